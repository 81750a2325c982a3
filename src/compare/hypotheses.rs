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
    Ok(Candidates::new(reference, frame)?.try_against(theirs, by, tolerance))
}

/// barylab's image of one scene made every way [`try_all`] tries, made once and compared
/// with any number of images ([`Candidates::try_against`]; `barylab grade` compares a whole
/// class with one set). An explanation whose image is barylab's own is left out: the scene
/// cannot show that mistake.
pub struct Candidates {
    /// barylab's render as the reference settings ask.
    ours: Rendered,
    /// Image width in pixels.
    width: usize,
    /// The other interpolation mode.
    other_mode: Interpolation,
    /// The other tie rule.
    other_rule: TieRule,
    /// Each explanation's image, in the order tried.
    images: Vec<(Kind, Rendered)>,
    /// With a multisampled reference: barylab's single-sample render.
    single: Option<Rendered>,
}

impl Candidates {
    /// Renders (or transforms) barylab's image of `reference` every way; `frame` is its render
    /// as asked. Fails with the renderer's message.
    pub fn new(reference: &Reference, frame: &Framebuffer) -> Result<Self, String> {
        let (w, h) = (frame.width as usize, frame.height as usize);
        let ours = Rendered::of(frame);
        let s = &reference.settings;
        let other_mode = match s.mode {
            Interpolation::Affine => Interpolation::Perspective,
            Interpolation::Perspective => Interpolation::Affine,
        };
        let other_rule = match s.tie_rule {
            TieRule::Llvmpipe => TieRule::TopLeft,
            _ => TieRule::Llvmpipe,
        };
        let render = |mesh: &crate::raster::ClipMesh, settings: crate::raster::RenderSettings| {
            super::render_for_comparison(mesh, reference.texture, &settings)
                .map(|r| Rendered::of(&r.frame))
        };
        let remap = |f: &dyn Fn(usize, usize) -> usize| Rendered {
            color: (0..w * h).map(|k| ours.color[f(k % w, k / w)]).collect(),
            covered: (0..w * h).map(|k| ours.covered[f(k % w, k / w)]).collect(),
        };
        let recolour = |f: &dyn Fn([u8; 4]) -> [u8; 4]| Rendered {
            color: ours.color.iter().map(|&c| f(c)).collect(),
            covered: ours.covered.clone(),
        };
        let mesh = reference.mesh;
        let mut images = vec![
            (Kind::YFlipped, remap(&|x, y| (h - 1 - y) * w + x)),
            (
                Kind::Rotated180,
                remap(&|x, y| (h - 1 - y) * w + (w - 1 - x)),
            ),
        ];
        if w == h {
            images.push((Kind::XySwapped, remap(&|x, y| x * w + y)));
        }
        images.push((
            Kind::OtherMode,
            render(
                mesh,
                crate::raster::RenderSettings {
                    mode: other_mode,
                    ..*s
                },
            )?,
        ));
        for (kind, tie_rule) in [
            (Kind::OtherTieRule, other_rule),
            (Kind::EveryEdgeOwns, TieRule::AllEdges),
            (Kind::NoEdgeOwns, TieRule::NoEdges),
        ] {
            let settings = crate::raster::RenderSettings { tie_rule, ..*s };
            images.push((kind, render(mesh, settings)?));
        }
        // Sampling at (x, y) instead of (x + 0.5, y + 0.5) is the same as moving the geometry
        // by half a pixel the other way.
        for (kind, dy) in [
            (Kind::IntegerCentresYDown, 0.5),
            (Kind::IntegerCentresYUp, -0.5),
        ] {
            let moved = shifted(mesh, s.width, s.height, 0.5, dy);
            images.push((kind, render(&moved, *s)?));
        }
        images.push((Kind::DepthReversed, render(&depth_reversed(mesh), *s)?));
        images.push((Kind::NoDepthTest, render(&drawn_in_order(mesh, true), *s)?));
        images.push((
            Kind::ReverseOrder,
            render(&drawn_in_order(mesh, false), *s)?,
        ));
        images.push((Kind::Bgr, recolour(&|c| [c[2], c[1], c[0], c[3]])));
        images.push((Kind::Gamma, recolour(&gamma_encoded)));
        let mut single = None;
        if s.samples.count == SampleCount::One {
            let samples = SampleSettings {
                count: SampleCount::Four,
                pattern: SamplePattern::Grid,
                rate: ShadingRate::Ssaa,
                ..s.samples
            };
            if samples.check().is_ok() {
                let settings = crate::raster::RenderSettings { samples, ..*s };
                images.push((Kind::Supersampled, render(mesh, settings)?));
            }
        } else {
            let one = crate::raster::RenderSettings {
                samples: SampleSettings {
                    count: SampleCount::One,
                    ..s.samples
                },
                ..*s
            };
            single = Some(render(mesh, one)?);
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
                images.push((kind, render(mesh, other)?));
            }
        }
        images.retain(|(_, r)| r.color != ours.color || r.covered != ours.covered);
        Ok(Self {
            ours,
            width: w,
            other_mode,
            other_rule,
            images,
            single,
        })
    }

    /// barylab's image made the way `kind` says (`None`: not tried for this scene, or
    /// barylab's own image, or a kind found by its pattern rather than an image:
    /// [`Kind::BlackEdges`], [`Kind::EdgesOnly`]).
    pub fn image(&self, kind: Kind) -> Option<&Rendered> {
        if kind == Kind::NoAntiAliasing {
            return self.single.as_ref();
        }
        self.images.iter().find(|(k, _)| *k == kind).map(|(_, r)| r)
    }

    /// The kinds with an image ([`Candidates::image`]), in the order tried.
    pub fn kinds(&self) -> impl Iterator<Item = Kind> + '_ {
        self.images
            .iter()
            .map(|(k, _)| *k)
            .chain(self.single.as_ref().map(|_| Kind::NoAntiAliasing))
    }

    /// Every explanation against `theirs`; best (fewest differing) first, among equal counts
    /// the first tried.
    pub fn try_against(&self, theirs: &Image, by: CoverageBy, tolerance: u8) -> Vec<Tried> {
        let (other_mode, other_rule) = (self.other_mode, self.other_rule);
        let tried_with = |kind, mask: Vec<bool>| Tried {
            kind,
            differing: mask.iter().filter(|&&d| d).count(),
            mask,
            other_mode,
            other_rule,
        };
        let against = |image: &Rendered| -> Vec<bool> {
            theirs
                .pixels
                .iter()
                .enumerate()
                .map(|(k, &p)| classify(p, image, k, by, tolerance).is_some())
                .collect()
        };
        let mut tried: Vec<Tried> = self
            .images
            .iter()
            .map(|(kind, image)| tried_with(*kind, against(image)))
            .collect();
        if let Some(single) = &self.single {
            let sampled = Sampled {
                ours: &self.ours,
                single,
                width: self.width,
            };
            // Added after the others and in this order: among equal counts the first one
            // wins, and "all differences on edges" is the least specific.
            for kind in [Kind::BlackEdges, Kind::NoAntiAliasing, Kind::EdgesOnly] {
                tried.push(tried_with(kind, sampled.mask(kind, theirs, by, tolerance)));
            }
        }
        tried.sort_by_key(|t| t.differing);
        tried
    }
}

/// `255 (c / 255)^(1 / 2.2)` per colour channel (alpha kept): gamma 2.2 encoding applied to
/// a colour that already was.
pub fn gamma_encoded(c: [u8; 4]) -> [u8; 4] {
    let g = |v: u8| ((f64::from(v) / 255.0).powf(1.0 / 2.2) * 255.0).round() as u8;
    [g(c[0]), g(c[1]), g(c[2]), c[3]]
}

/// The mesh with z negated in clip space: window depth `d` becomes `1 - d`, so the
/// less-than test keeps the farther fragment (a reversed depth test, or z of the wrong sign;
/// clipping against `-w <= z <= w` is unchanged).
pub fn depth_reversed(mesh: &crate::raster::ClipMesh) -> crate::raster::ClipMesh {
    let mut m = mesh.clone();
    for v in &mut m.vertices {
        v.clip.z = -v.clip.z;
    }
    m
}

/// The mesh drawn as without a depth test: every triangle gets its own vertices at a
/// constant depth `z / w` in (-0.9, 0.9), decreasing with its place in the list when
/// `last_on_top` (the last triangle drawn wins, as with no depth test) and increasing
/// otherwise (the first wins: the triangles drawn in the reverse order). Coverage and values
/// are unchanged (they come from x, y and w).
pub fn drawn_in_order(
    mesh: &crate::raster::ClipMesh,
    last_on_top: bool,
) -> crate::raster::ClipMesh {
    let n = mesh.triangles.len().max(1) as f64;
    let mut vertices = Vec::with_capacity(mesh.triangles.len() * 3);
    let mut triangles = Vec::with_capacity(mesh.triangles.len());
    for (i, t) in mesh.triangles.iter().enumerate() {
        let rank = if last_on_top {
            mesh.triangles.len() - 1 - i
        } else {
            i
        };
        let depth = -0.9 + 1.8 * (rank as f64 + 0.5) / n;
        let base = vertices.len() as u32;
        for &index in t {
            let Some(v) = mesh.vertices.get(index as usize) else {
                continue;
            };
            let mut v = *v;
            v.clip.z = depth * v.clip.w;
            vertices.push(v);
        }
        if vertices.len() as u32 == base + 3 {
            triangles.push([base, base + 1, base + 2]);
        }
    }
    crate::raster::ClipMesh {
        vertices,
        triangles,
    }
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
