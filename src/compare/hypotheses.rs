//! Whole-image explanations of a difference: barylab's image made the way a common mistake
//! (or another convention) would make it, compared with the other image again. The one that
//! leaves far fewer pixels differing is what the other image "looks like".

use serde::Serialize;

use super::{CoverageBy, Image, Reference, Rendered, classify};
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

/// A tried explanation and how many pixels still differ under it.
#[derive(Clone, Debug, Serialize)]
pub struct Tried {
    /// Which explanation.
    pub kind: Kind,
    /// What barylab's image was turned into, e.g. "barylab's image flipped upside down".
    pub description: String,
    /// Pixels that differ from it.
    pub differing: usize,
    /// Per pixel: whether it differs from this explanation.
    #[serde(skip)]
    mask: Vec<bool>,
    /// The mode of the other-mode render.
    #[serde(skip)]
    other_mode: Interpolation,
}

impl Tried {
    /// Whether pixel `k` differs from this explanation too.
    pub fn differs_at(&self, k: usize) -> bool {
        self.mask.get(k).copied().unwrap_or(true)
    }

    /// The verdict line, e.g. "looks like y flipped: ...".
    pub fn verdict(&self) -> String {
        let what = match self.kind {
            Kind::YFlipped => {
                "looks like y flipped (image row 0 written at the bottom)".to_string()
            }
            Kind::Rotated180 => "looks rotated by 180 degrees (x and y flipped): a projection \
                                 whose w has the wrong sign, e.g. a near plane at z = +n for a \
                                 camera looking down -z"
                .to_string(),
            Kind::OtherMode => format!("looks like {} interpolation", mode_words(self.other_mode)),
            Kind::OtherTieRule => {
                "looks like the other tie rule for centres exactly on an edge".to_string()
            }
            Kind::IntegerCentresYDown | Kind::IntegerCentresYUp => {
                "looks like pixel centres at integer coordinates (x, y) instead of \
                 (x + 0.5, y + 0.5)"
                    .to_string()
            }
        };
        format!(
            "{what}: {} leaves {} pixels differing",
            self.description, self.differing
        )
    }

    /// The reason for one pixel this explanation accounts for.
    pub fn pixel_reason(&self, k: usize, frame: &Framebuffer, texture: &Texture) -> String {
        match self.kind {
            Kind::OtherMode => {
                let (p, a) = (frame.uv_perspective[k], frame.uv_affine[k]);
                let texels = ((p[0] - a[0]).abs() * texture.width() as f32)
                    .max((p[1] - a[1]).abs() * texture.height() as f32);
                format!(
                    "uv differs by {texels:.1} texels between perspective-correct and affine \
                     here, and this colour is barylab's {} one: looks like {} interpolation",
                    mode_words(self.other_mode),
                    mode_words(self.other_mode)
                )
            }
            _ => format!("agrees with {}: {}", self.description, self.verdict_short()),
        }
    }

    fn verdict_short(&self) -> &'static str {
        match self.kind {
            Kind::YFlipped => "looks like y flipped",
            Kind::Rotated180 => "looks rotated by 180 degrees (w of the wrong sign)",
            Kind::OtherMode => "looks like the other interpolation mode",
            Kind::OtherTieRule => "looks like the other tie rule",
            Kind::IntegerCentresYDown | Kind::IntegerCentresYUp => {
                "looks like pixel centres at integer coordinates"
            }
        }
    }
}

fn mode_words(m: Interpolation) -> &'static str {
    match m {
        Interpolation::Affine => "affine (screen-space)",
        Interpolation::Perspective => "perspective-correct",
    }
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
        crate::raster::render(mesh, reference.texture, &settings)
            .map(|r| Rendered::of(&r.frame))
            .map_err(|e| e.to_string())
    };
    let mut tried = Vec::new();
    let mut add = |kind, description: String, image: Rendered| {
        let mask: Vec<bool> = theirs
            .pixels
            .iter()
            .enumerate()
            .map(|(k, &p)| classify(p, &image, k, by, tolerance).is_some())
            .collect();
        tried.push(Tried {
            kind,
            description,
            differing: mask.iter().filter(|&&d| d).count(),
            mask,
            other_mode,
        });
    };
    add(
        Kind::YFlipped,
        "barylab's image flipped upside down".into(),
        remap(&|x, y| (h - 1 - y) * w + x),
    );
    add(
        Kind::Rotated180,
        "barylab's image rotated by 180 degrees".into(),
        remap(&|x, y| (h - 1 - y) * w + (w - 1 - x)),
    );
    add(
        Kind::OtherMode,
        format!("barylab's {} render", mode_words(other_mode)),
        render(reference.mesh, other_mode)?,
    );
    let other_rule = match s.tie_rule {
        TieRule::Llvmpipe => TieRule::TopLeft,
        TieRule::TopLeft => TieRule::Llvmpipe,
    };
    let with_rule = crate::raster::RenderSettings {
        tie_rule: other_rule,
        ..*s
    };
    add(
        Kind::OtherTieRule,
        format!("barylab's render under {}", other_rule.describe()),
        crate::raster::render(reference.mesh, reference.texture, &with_rule)
            .map(|r| Rendered::of(&r.frame))
            .map_err(|e| e.to_string())?,
    );
    // Sampling at (x, y) instead of (x + 0.5, y + 0.5) is the same as moving the geometry by
    // half a pixel the other way.
    add(
        Kind::IntegerCentresYDown,
        "barylab's render sampled at integer coordinates (y down)".into(),
        render(
            &shifted(reference.mesh, s.width, s.height, 0.5, 0.5),
            s.mode,
        )?,
    );
    add(
        Kind::IntegerCentresYUp,
        "barylab's render sampled at integer coordinates (y up)".into(),
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
