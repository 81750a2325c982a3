//! What a whole-image explanation of a difference is ([`Kind`]) and its verdict in words
//! ([`Verdict`]): the [`hypotheses`](super::hypotheses) find it, the per-pixel
//! [`Reason`](super::reason::Reason)s and the report word it.

use serde::Serialize;

use crate::i18n::Lang;
use crate::raster::Interpolation;
use crate::raster::setup::TieRule;

/// One convention or mistake tried.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    /// Rows in the opposite order (image row 0 at the bottom).
    YFlipped,
    /// Rows and columns reversed: the projection's w has the wrong sign (x/w and y/w both
    /// change sign).
    Rotated180,
    /// The other interpolation mode (affine for a perspective-correct scene, and back).
    OtherMode,
    /// Samples at integer pixel coordinates `(x, y)` in image rows (y down) instead of the
    /// centres `(x + 0.5, y + 0.5)`.
    IntegerCentresYDown,
    /// The other tie rule (top-left for a llvmpipe scene, and back): differs only on centres
    /// exactly on an edge.
    OtherTieRule,
    /// Samples at integer pixel coordinates in y-up rows (row 0 at the bottom, then written
    /// out top row first, as a framework with y up does).
    IntegerCentresYUp,
    /// Against a multisampled reference: edge pixels between triangles darker than the
    /// triangles on both sides (GAMES101 A2's supersampling bug: colour or depth kept per
    /// pixel while coverage is per sample), the rest agreeing.
    BlackEdges,
    /// Against a multisampled reference: the image is barylab's single-sample render.
    NoAntiAliasing,
    /// Against a multisampled reference: every difference sits on a triangle edge.
    EdgesOnly,
    /// Against a multisampled reference: the image is barylab's render at the other shading
    /// rate (supersampling for an MSAA reference, MSAA for a supersampled one).
    OtherShadingRate,
    /// Against a multisampled reference: the image is barylab's render with the other
    /// sample pattern (the grid for a standard-pattern reference, and back).
    OtherSamplePattern,
    /// Rows and columns exchanged: pixel `(x, y)` written at `(y, x)` (square images only).
    XySwapped,
    /// Red and blue exchanged (the colour written as BGR).
    Bgr,
    /// The colour encoded with gamma 2.2 once more: `255 (c / 255)^(1 / 2.2)`.
    Gamma,
    /// The depth test reversed (greater wins), or the sign of z flipped.
    DepthReversed,
    /// No depth test: the triangles drawn in the scene's order, the last one on top.
    NoDepthTest,
    /// No depth test and the triangles drawn in the reverse order: the first one on top.
    ReverseOrder,
    /// No fill rule: samples exactly on an edge covered by every triangle that has the edge.
    EveryEdgeOwns,
    /// No fill rule: samples exactly on an edge covered by no triangle.
    NoEdgeOwns,
    /// Against a single-sample reference: barylab's render supersampled at 2x2 grid
    /// positions (GAMES101 A2's SSAA), where none was asked for.
    Supersampled,
}

/// A whole-image explanation as a verdict: which one, what it leaves differing, and what it
/// is in this comparison (the other mode, the other tie rule); worded by [`Verdict::text`].
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Verdict {
    /// Which explanation.
    pub kind: Kind,
    /// Pixels that still differ under it.
    pub differing: usize,
    /// The other interpolation mode (the one [`Kind::OtherMode`] renders in).
    pub other_mode: Interpolation,
    /// The other tie rule (the one [`Kind::OtherTieRule`] renders under).
    pub other_rule: TieRule,
}

impl Verdict {
    /// What barylab's image was turned into, e.g. "barylab's image flipped upside down".
    pub fn description(&self, lang: Lang) -> String {
        match self.kind {
            Kind::YFlipped => lang.tr("compare.describe.y_flipped"),
            Kind::Rotated180 => lang.tr("compare.describe.rotated180"),
            Kind::OtherMode => lang.tr_with(
                "compare.describe.other_mode",
                &[("mode", &mode_words(self.other_mode, lang))],
            ),
            Kind::OtherTieRule => lang.tr_with(
                "compare.describe.other_tie_rule",
                &[("rule", &rule_words(self.other_rule, lang))],
            ),
            Kind::IntegerCentresYDown => lang.tr("compare.describe.integer_y_down"),
            Kind::IntegerCentresYUp => lang.tr("compare.describe.integer_y_up"),
            Kind::BlackEdges => lang.tr("compare.describe.black_edges"),
            Kind::NoAntiAliasing => lang.tr("compare.describe.no_anti_aliasing"),
            Kind::EdgesOnly => lang.tr("compare.describe.edges_only"),
            Kind::OtherShadingRate => lang.tr("compare.describe.other_shading_rate"),
            Kind::OtherSamplePattern => lang.tr("compare.describe.other_sample_pattern"),
            Kind::XySwapped => lang.tr("compare.describe.xy_swapped"),
            Kind::Bgr => lang.tr("compare.describe.bgr"),
            Kind::Gamma => lang.tr("compare.describe.gamma"),
            Kind::DepthReversed => lang.tr("compare.describe.depth_reversed"),
            Kind::NoDepthTest => lang.tr("compare.describe.no_depth_test"),
            Kind::ReverseOrder => lang.tr("compare.describe.reverse_order"),
            Kind::EveryEdgeOwns => lang.tr("compare.describe.every_edge_owns"),
            Kind::NoEdgeOwns => lang.tr("compare.describe.no_edge_owns"),
            Kind::Supersampled => lang.tr("compare.describe.supersampled"),
        }
    }

    /// What the other image looks like, e.g. "looks like y flipped (image row 0 written at
    /// the bottom)".
    pub fn looks(&self, lang: Lang) -> String {
        match self.kind {
            Kind::YFlipped => lang.tr("compare.looks.y_flipped"),
            Kind::Rotated180 => lang.tr("compare.looks.rotated180"),
            Kind::OtherMode => lang.tr_with(
                "compare.looks.other_mode",
                &[("mode", &mode_words(self.other_mode, lang))],
            ),
            Kind::OtherTieRule => lang.tr("compare.looks.other_tie_rule"),
            Kind::IntegerCentresYDown | Kind::IntegerCentresYUp => {
                lang.tr("compare.looks.integer_centres")
            }
            Kind::BlackEdges => lang.tr("compare.looks.black_edges"),
            Kind::NoAntiAliasing => lang.tr("compare.looks.no_anti_aliasing"),
            Kind::EdgesOnly => lang.tr("compare.looks.edges_only"),
            Kind::OtherShadingRate => lang.tr("compare.looks.other_shading_rate"),
            Kind::OtherSamplePattern => lang.tr("compare.looks.other_sample_pattern"),
            Kind::XySwapped => lang.tr("compare.looks.xy_swapped"),
            Kind::Bgr => lang.tr("compare.looks.bgr"),
            Kind::Gamma => lang.tr("compare.looks.gamma"),
            Kind::DepthReversed => lang.tr("compare.looks.depth_reversed"),
            Kind::NoDepthTest => lang.tr("compare.looks.no_depth_test"),
            Kind::ReverseOrder => lang.tr("compare.looks.reverse_order"),
            Kind::EveryEdgeOwns | Kind::NoEdgeOwns => lang.tr("compare.looks.no_fill_rule"),
            Kind::Supersampled => lang.tr("compare.looks.supersampled"),
        }
    }

    /// The verdict line, e.g. "looks like y flipped (…): barylab's image flipped upside down
    /// leaves 0 pixels differing".
    pub fn text(&self, lang: Lang) -> String {
        lang.tr_with(
            "compare.looks.verdict",
            &[
                ("looks", &self.looks(lang)),
                ("description", &self.description(lang)),
                ("n", &self.differing),
            ],
        )
    }

    /// The verdict in a few words, e.g. "looks like y flipped".
    pub fn short(&self, lang: Lang) -> String {
        lang.tr(match self.kind {
            Kind::YFlipped => "compare.short.y_flipped",
            Kind::Rotated180 => "compare.short.rotated180",
            Kind::OtherMode => "compare.short.other_mode",
            Kind::OtherTieRule => "compare.short.other_tie_rule",
            Kind::IntegerCentresYDown | Kind::IntegerCentresYUp => "compare.short.integer_centres",
            Kind::BlackEdges => "compare.short.black_edges",
            Kind::NoAntiAliasing => "compare.short.no_anti_aliasing",
            Kind::EdgesOnly => "compare.short.edges_only",
            Kind::OtherShadingRate => "compare.short.other_shading_rate",
            Kind::OtherSamplePattern => "compare.short.other_sample_pattern",
            Kind::XySwapped => "compare.short.xy_swapped",
            Kind::Bgr => "compare.short.bgr",
            Kind::Gamma => "compare.short.gamma",
            Kind::DepthReversed => "compare.short.depth_reversed",
            Kind::NoDepthTest => "compare.short.no_depth_test",
            Kind::ReverseOrder => "compare.short.reverse_order",
            Kind::EveryEdgeOwns | Kind::NoEdgeOwns => "compare.short.no_fill_rule",
            Kind::Supersampled => "compare.short.supersampled",
        })
    }
}

/// The mode in a verdict, in `lang`: "affine (screen-space)" or "perspective-correct".
fn mode_words(m: Interpolation, lang: Lang) -> String {
    lang.tr(match m {
        Interpolation::Affine => "compare.mode.affine",
        Interpolation::Perspective => "compare.mode.perspective",
    })
}

/// A tie rule in words, in `lang`.
pub fn rule_words(rule: TieRule, lang: Lang) -> String {
    lang.tr(match rule {
        TieRule::Llvmpipe => "compare.rule.llvmpipe",
        TieRule::TopLeft => "compare.rule.top_left",
        TieRule::AllEdges => "compare.rule.all_edges",
        TieRule::NoEdges => "compare.rule.no_edges",
    })
}
