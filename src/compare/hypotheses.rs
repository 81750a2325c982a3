//! Whole-image explanations of a difference: barylab's image made the way a common mistake
//! (or another convention) would make it, compared with the other image again. The one that
//! leaves far fewer pixels differing is what the other image "looks like".

use serde::Serialize;

use super::reason::Reason;
use super::sampling::Sampled;
use super::verdict::{Kind, Verdict};
use super::{CoverageBy, Image, Reference, Rendered, classify, uv_gap_texels};
use crate::i18n::Lang;
use crate::raster::sample::{SampleCount, SamplePattern, SampleSettings, ShadingRate};
use crate::raster::setup::TieRule;
use crate::raster::{Framebuffer, Interpolation, Texture};

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
    let mut push = |kind, mask: Vec<bool>| {
        tried.push(Tried {
            kind,
            differing: mask.iter().filter(|&&d| d).count(),
            mask,
            other_mode,
            other_rule,
        });
    };
    let mut add = |kind, image: Rendered| {
        let mask = theirs
            .pixels
            .iter()
            .enumerate()
            .map(|(k, &p)| classify(p, &image, k, by, tolerance).is_some())
            .collect();
        push(kind, mask);
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
    if s.samples.count != SampleCount::One {
        let one = crate::raster::RenderSettings {
            samples: crate::raster::sample::SampleSettings {
                count: SampleCount::One,
                ..s.samples
            },
            ..*s
        };
        let single = super::render_for_comparison(reference.mesh, reference.texture, &one)
            .map(|r| Rendered::of(&r.frame))?;
        // Supersampling for MSAA and back; the other pattern where both have positions.
        let rate = match s.samples.rate {
            ShadingRate::Msaa => ShadingRate::Ssaa,
            ShadingRate::Ssaa => ShadingRate::Msaa,
        };
        let pattern = match s.samples.pattern {
            SamplePattern::Standard => SamplePattern::Grid,
            SamplePattern::Grid => SamplePattern::Standard,
        };
        for (kind, samples) in [
            (Kind::OtherShadingRate, SampleSettings { rate, ..s.samples }),
            (
                Kind::OtherSamplePattern,
                SampleSettings {
                    pattern,
                    ..s.samples
                },
            ),
        ] {
            if samples.check().is_err() {
                continue;
            }
            let other = crate::raster::RenderSettings { samples, ..*s };
            add(
                kind,
                super::render_for_comparison(reference.mesh, reference.texture, &other)
                    .map(|r| Rendered::of(&r.frame))?,
            );
        }
        let sampled = Sampled {
            ours: &ours,
            single: &single,
            width: w,
        };
        // Added after the others and in this order: among equal counts the first one wins,
        // and "all differences on edges" is the least specific.
        for kind in [Kind::BlackEdges, Kind::NoAntiAliasing, Kind::EdgesOnly] {
            push(kind, sampled.mask(kind, theirs, by, tolerance));
        }
    }
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
