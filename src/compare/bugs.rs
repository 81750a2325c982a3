//! Named bugs: the mistakes of rasterizer homework that `barylab compare` and `barylab
//! grade` name, each with a stable code, a title, a short explanation and the fix in both
//! languages (the catalogues' `compare.bug` section).
//!
//! A bug is found the way every whole-image explanation is
//! ([`hypotheses`](super::hypotheses)): barylab's image of the scene made with the bug (one
//! or more [`Kind`]s show it) is compared with the other image. It is *named* when it
//! explains the difference exactly or nearly: it leaves at most [`NAMED_FRACTION`] of the
//! differing pixels differing. Several bugs are named together when their images leave the
//! same count (a scene in which they look alike).

use serde::Serialize;

use super::hypotheses::{Candidates, Tried};
use super::verdict::Kind;
use crate::i18n::Lang;

/// A bug is named when its image leaves at most this fraction of the pixels that differ from
/// barylab's own image differing (near-exact: a student's gamma curve or rounding may differ
/// a little from barylab's).
pub const NAMED_FRACTION: f64 = 0.05;

/// One named mistake; in JSON and CSV its [`Bug::code`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Bug {
    /// Image row 0 written at the bottom.
    YFlipped,
    /// Pixel `(x, y)` written at `(y, x)`.
    XySwapped,
    /// Samples at integer coordinates instead of the pixel centres (a half-pixel offset).
    HalfPixel,
    /// The top-left rule where the scene follows llvmpipe's, or the reverse.
    TieRule,
    /// No fill rule: shared-edge centres drawn twice or missed.
    NoFillRule,
    /// Affine (screen-space) interpolation instead of perspective-correct (or the reverse).
    Affine,
    /// The depth test reversed (or z of the wrong sign), or missing.
    DepthTest,
    /// No depth test and the triangles drawn in the reverse order.
    TriangleOrder,
    /// Red and blue exchanged.
    Bgr,
    /// Gamma 2.2 encoding applied to colours that already were.
    Gamma,
    /// Supersampled where one sample was asked for, one sample where several were, or
    /// another sample pattern or shading rate.
    AntiAliasing,
    /// Supersampling with colour or depth per pixel: edge pixels darker than both sides.
    BlackEdges,
}

impl Bug {
    /// Every bug, in the order reports list them.
    pub const ALL: [Bug; 12] = [
        Bug::YFlipped,
        Bug::XySwapped,
        Bug::HalfPixel,
        Bug::TieRule,
        Bug::NoFillRule,
        Bug::Affine,
        Bug::DepthTest,
        Bug::TriangleOrder,
        Bug::Bgr,
        Bug::Gamma,
        Bug::AntiAliasing,
        Bug::BlackEdges,
    ];

    /// The stable code: `y_flipped`, `xy_swapped`, `half_pixel`, `tie_rule`,
    /// `no_fill_rule`, `affine`, `depth_test`, `triangle_order`, `bgr`, `gamma`,
    /// `anti_aliasing`, `black_edges`.
    pub fn code(self) -> &'static str {
        match self {
            Bug::YFlipped => "y_flipped",
            Bug::XySwapped => "xy_swapped",
            Bug::HalfPixel => "half_pixel",
            Bug::TieRule => "tie_rule",
            Bug::NoFillRule => "no_fill_rule",
            Bug::Affine => "affine",
            Bug::DepthTest => "depth_test",
            Bug::TriangleOrder => "triangle_order",
            Bug::Bgr => "bgr",
            Bug::Gamma => "gamma",
            Bug::AntiAliasing => "anti_aliasing",
            Bug::BlackEdges => "black_edges",
        }
    }

    /// The bug with this code.
    pub fn from_code(code: &str) -> Option<Bug> {
        Bug::ALL.into_iter().find(|b| b.code() == code)
    }

    /// The whole-image explanations that show this bug, the one to render first.
    pub fn kinds(self) -> &'static [Kind] {
        match self {
            Bug::YFlipped => &[Kind::YFlipped],
            Bug::XySwapped => &[Kind::XySwapped],
            Bug::HalfPixel => &[Kind::IntegerCentresYDown, Kind::IntegerCentresYUp],
            Bug::TieRule => &[Kind::OtherTieRule],
            Bug::NoFillRule => &[Kind::NoEdgeOwns, Kind::EveryEdgeOwns],
            Bug::Affine => &[Kind::OtherMode],
            Bug::DepthTest => &[Kind::DepthReversed, Kind::NoDepthTest],
            Bug::TriangleOrder => &[Kind::ReverseOrder],
            Bug::Bgr => &[Kind::Bgr],
            Bug::Gamma => &[Kind::Gamma],
            Bug::AntiAliasing => &[
                Kind::Supersampled,
                Kind::NoAntiAliasing,
                Kind::OtherShadingRate,
                Kind::OtherSamplePattern,
            ],
            Bug::BlackEdges => &[Kind::BlackEdges],
        }
    }

    /// The bug an explanation shows, if it is one (a 180-degree turn and "only the edges
    /// differ" are not named bugs).
    pub fn of(kind: Kind) -> Option<Bug> {
        Bug::ALL.into_iter().find(|b| b.kinds().contains(&kind))
    }

    /// The bug's title, e.g. "Y flipped".
    pub fn title(self, lang: Lang) -> String {
        lang.tr(&format!("compare.bug.{}.title", self.code()))
    }

    /// What the mistake is and what it looks like, in a sentence or two.
    pub fn explanation(self, lang: Lang) -> String {
        lang.tr(&format!("compare.bug.{}.explain", self.code()))
    }

    /// How to fix it.
    pub fn fix(self, lang: Lang) -> String {
        lang.tr(&format!("compare.bug.{}.fix", self.code()))
    }

    /// barylab's image of the scene with this bug, as `candidates` made it (`None`: the
    /// scene cannot show it, or the bug is found by its pattern only: black edges).
    pub fn image(self, candidates: &Candidates) -> Option<&super::Rendered> {
        self.kinds().iter().find_map(|&k| candidates.image(k))
    }
}

/// The bugs named for an image that differs from barylab's on `differing` pixels, from the
/// explanations tried (best first): those whose best explanation leaves the fewest pixels,
/// at most [`NAMED_FRACTION`] of `differing`. Empty when nothing fits that well.
pub fn named(differing: usize, tried: &[Tried]) -> Vec<Bug> {
    let Some(best) = tried.iter().map(|t| t.differing).min() else {
        return Vec::new();
    };
    if differing == 0 || best as f64 > differing as f64 * NAMED_FRACTION {
        return Vec::new();
    }
    let mut bugs: Vec<Bug> = tried
        .iter()
        .filter(|t| t.differing == best)
        .filter_map(|t| Bug::of(t.kind))
        .collect();
    bugs.sort();
    bugs.dedup();
    bugs
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_bug_has_a_code_title_explanation_and_fix_in_both_languages() {
        for b in Bug::ALL {
            assert_eq!(Bug::from_code(b.code()), Some(b));
            assert_eq!(
                serde_json::to_value(b).expect("json"),
                serde_json::json!(b.code())
            );
            for lang in [Lang::En, Lang::Zh] {
                for text in [b.title(lang), b.explanation(lang), b.fix(lang)] {
                    assert!(!text.is_empty() && !text.starts_with("compare."), "{text}");
                }
            }
            assert_ne!(b.title(Lang::En), b.title(Lang::Zh));
            assert!(!b.kinds().is_empty());
            for &k in b.kinds() {
                assert_eq!(Bug::of(k), Some(b), "{k:?}");
            }
        }
        assert_eq!(Bug::of(Kind::Rotated180), None);
        assert_eq!(Bug::of(Kind::EdgesOnly), None);
    }
}
