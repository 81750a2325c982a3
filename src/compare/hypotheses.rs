//! Whole-image explanations of a difference: barylab's image made the way a common mistake
//! (or another convention) would make it, compared with the other image again. The one that
//! leaves far fewer pixels differing is what the other image "looks like".

use serde::Serialize;

use super::reasons::Reason;
use super::{CoverageBy, Image, Reference, Rendered, classify};
use crate::i18n::Lang;
use crate::raster::setup::TieRule;
use crate::raster::{Framebuffer, Interpolation, Texture};

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
        })
    }
}

/// A tried explanation and how many pixels still differ under it. In JSON: `kind`,
/// `description` (English) and `differing`.
#[derive(Clone, Debug)]
pub struct Tried {
    /// Which explanation.
    pub kind: Kind,
    /// Pixels that differ from it.
    pub differing: usize,
    /// Per pixel: whether it differs from this explanation.
    mask: Vec<bool>,
    /// The mode of the other-mode render.
    other_mode: Interpolation,
    /// The rule of the other-tie-rule render.
    other_rule: TieRule,
}

impl Serialize for Tried {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut s = serializer.serialize_struct("Tried", 3)?;
        s.serialize_field("kind", &self.kind)?;
        s.serialize_field("description", &self.verdict().description(Lang::En))?;
        s.serialize_field("differing", &self.differing)?;
        s.end()
    }
}

impl Tried {
    /// Whether pixel `k` differs from this explanation too.
    pub fn differs_at(&self, k: usize) -> bool {
        self.mask.get(k).copied().unwrap_or(true)
    }

    /// This explanation as a verdict.
    pub fn verdict(&self) -> Verdict {
        Verdict {
            kind: self.kind,
            differing: self.differing,
            other_mode: self.other_mode,
            other_rule: self.other_rule,
        }
    }

    /// The reason for one pixel this explanation accounts for.
    pub fn pixel_reason(&self, k: usize, frame: &Framebuffer, texture: &Texture) -> Reason {
        match self.kind {
            Kind::OtherMode => Reason::OtherMode {
                texels: uv_gap_texels(frame, k, texture),
                looks_like: self.other_mode,
            },
            _ => Reason::Explained {
                verdict: self.verdict(),
            },
        }
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
    })
}

/// Tries every explanation; best (fewest differing) first.
pub fn try_all(
    theirs: &Image,
    reference: &Reference,
    frame: &Framebuffer,
    by: CoverageBy,
    tolerance: u8,
) -> Result<Vec<Tried>, String> {
    let (w, h) = (frame.width as usize, frame.height as usize);
    let ours = Rendered::of(frame);
    let remap = |f: &dyn Fn(usize, usize) -> usize| Rendered {
        color: (0..w * h).map(|k| ours.color[f(k % w, k / w)]).collect(),
        covered: (0..w * h).map(|k| ours.covered[f(k % w, k / w)]).collect(),
    };
    let s = &reference.settings;
    let other_mode = match s.mode {
        Interpolation::Affine => Interpolation::Perspective,
        Interpolation::Perspective => Interpolation::Affine,
    };
    let render = |mesh: &crate::raster::ClipMesh, mode| {
        let settings = crate::raster::RenderSettings { mode, ..*s };
        super::render_for_comparison(mesh, reference.texture, &settings)
            .map(|r| Rendered::of(&r.frame))
    };
    let other_rule = match s.tie_rule {
        TieRule::Llvmpipe => TieRule::TopLeft,
        TieRule::TopLeft => TieRule::Llvmpipe,
    };
    let mut tried = Vec::new();
    let mut add = |kind, image: Rendered| {
        let mask: Vec<bool> = theirs
            .pixels
            .iter()
            .enumerate()
            .map(|(k, &p)| classify(p, &image, k, by, tolerance).is_some())
            .collect();
        tried.push(Tried {
            kind,
            differing: mask.iter().filter(|&&d| d).count(),
            mask,
            other_mode,
            other_rule,
        });
    };
    add(Kind::YFlipped, remap(&|x, y| (h - 1 - y) * w + x));
    add(
        Kind::Rotated180,
        remap(&|x, y| (h - 1 - y) * w + (w - 1 - x)),
    );
    add(Kind::OtherMode, render(reference.mesh, other_mode)?);
    let with_rule = crate::raster::RenderSettings {
        tie_rule: other_rule,
        ..*s
    };
    add(
        Kind::OtherTieRule,
        super::render_for_comparison(reference.mesh, reference.texture, &with_rule)
            .map(|r| Rendered::of(&r.frame))?,
    );
    // Sampling at (x, y) instead of (x + 0.5, y + 0.5) is the same as moving the geometry by
    // half a pixel the other way.
    add(
        Kind::IntegerCentresYDown,
        render(
            &shifted(reference.mesh, s.width, s.height, 0.5, 0.5),
            s.mode,
        )?,
    );
    add(
        Kind::IntegerCentresYUp,
        render(
            &shifted(reference.mesh, s.width, s.height, 0.5, -0.5),
            s.mode,
        )?,
    );
    tried.sort_by_key(|t| t.differing);
    Ok(tried)
}

/// The mesh moved by `(dx, dy)` pixels in image rows (x right, y down): in clip space,
/// `x += 2 dx / W * w`, `y -= 2 dy / H * w`.
pub fn shifted(
    mesh: &crate::raster::ClipMesh,
    width: u32,
    height: u32,
    dx: f64,
    dy: f64,
) -> crate::raster::ClipMesh {
    let mut m = mesh.clone();
    for v in &mut m.vertices {
        v.clip.x += 2.0 * dx / f64::from(width) * v.clip.w;
        v.clip.y -= 2.0 * dy / f64::from(height) * v.clip.w;
    }
    m
}

/// How far apart the affine and the perspective-correct uv of pixel `k` are, in texels: the
/// heatmap's and the inspector's measure ([`texel_difference`](crate::figure::heatmap::texel_difference),
/// the length of the offset).
pub(super) fn uv_gap_texels(frame: &Framebuffer, k: usize, texture: &Texture) -> f32 {
    crate::figure::heatmap::texel_difference(
        frame.uv_affine[k],
        frame.uv_perspective[k],
        (texture.width(), texture.height()),
    )
}
