//! `gpu-check` under multisampling: barylab's samples ([`render_samples`]) against the GL's
//! ([`Gpu::read_samples`]), sample by sample: coverage, the owning triangle, uv, depth and
//! colour, and the resolved image against the GL's resolve.
//!
//! One GL difference is named rather than counted as an error: for `smooth` values at the
//! centroid or a sample (or under supersampling), llvmpipe divides `f/w` interpolated at that
//! location by `1/w` interpolated at the pixel centre, `g = N(p) / D(c)` with
//! `N(p) = sum l_i(p) f_i / w_i` and `D(q) = sum l_i(q) / w_i`; the exact value there is
//! `N(p) / D(p) = g D(c) / D(p)`. barylab computes the exact value, so the uv compared is the
//! GL's multiplied by `D(c) / D(p)` ([`UvFormula::SampleOverCentre`]), and the raw
//! difference is reported as the size of the GL's formula's own error.

use serde::Serialize;

use super::multisample::GlSamples;
use super::{Gpu, Output};
use crate::raster::multisample::{SampleBuffer, coverage, fragment_at};
use crate::raster::render::{Render, render_samples};
use crate::raster::sample::{
    Location, ProvokingVertex, SampleSettings, ShadingRate, centroid_sample, sample_at,
};
use crate::raster::setup::sample_point;
use crate::raster::{ClipMesh, Filter, Interpolation, NO_TRIANGLE, RenderSettings, Texture};

/// Samples listed in a report (all are counted).
pub const LISTED: usize = 10;

/// How the GL's uv relates to the exact value at the location it used.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum UvFormula {
    /// The exact value there (`noperspective`, `flat`, `smooth` at the centre).
    Exact,
    /// `smooth` at the centroid or a sample: `f/w` at the location divided by `1/w` at the
    /// pixel centre (llvmpipe's), compared after multiplying by `D(c) / D(p)`.
    SampleOverCentre,
}

/// The GL's uv formula for these settings, as measured on llvmpipe (Mesa 22.3).
pub fn uv_formula(mode: Interpolation, samples: &SampleSettings) -> UvFormula {
    let off_centre = samples.rate == ShadingRate::Ssaa || samples.location != Location::Center;
    if mode == Interpolation::Perspective && !samples.flat && off_centre {
        UvFormula::SampleOverCentre
    } else {
        UvFormula::Exact
    }
}

/// One scene's samples drawn by both, compared.
#[derive(Clone, Debug, Default, Serialize)]
pub struct SampleCheck {
    /// Samples per pixel.
    pub per_pixel: usize,
    /// Samples compared, `width * height * per_pixel`.
    pub samples: usize,
    /// Samples barylab covers.
    pub covered: usize,
    /// Samples covered by one and not the other.
    pub coverage_mismatches: usize,
    /// The first of them, `[x, y, sample]`.
    pub coverage_mismatch_at: Vec<[u32; 3]>,
    /// Samples both cover, with different source triangles.
    pub triangle_mismatches: usize,
    /// The first of them, `[x, y, sample]`.
    pub triangle_mismatch_at: Vec<[u32; 3]>,
    /// How the GL's uv was turned into the exact value before comparing (`None` in a
    /// default check that compared nothing).
    pub uv_formula: Option<UvFormula>,
    /// Over the samples both give to the same triangle: the largest |uv - uv_gl| per
    /// component, with barylab's exact value at the location the GL used, taken through the
    /// GL's [`SampleCheck::uv_formula`].
    pub max_uv_difference: f64,
    /// `[x, y, sample]` of the first sample with it.
    pub max_uv_at: Option<[u32; 3]>,
    /// The largest |uv - uv_gl| with both values as they are (barylab's at its own
    /// location): where [`UvFormula::SampleOverCentre`] applies or the GL chose another
    /// location, the size of that difference.
    pub max_uv_formula_difference: f64,
    /// `[x, y, sample]` of the first sample with it.
    pub max_uv_formula_at: Option<[u32; 3]>,
    /// Covered samples whose GL value was evaluated somewhere else than barylab's location
    /// rule says (found among the centre and the covered samples; llvmpipe's `centroid` in
    /// some fully covered pixels takes a sample's position instead of the centre).
    pub location_differs: usize,
    /// The first of them, `[x, y, sample]`.
    pub location_differs_at: Vec<[u32; 3]>,
    /// The largest |depth - depth_gl| over the samples both cover (window depth).
    pub max_depth_difference: f64,
    /// The largest difference of one 8-bit channel of a sample's colour, same triangle.
    pub max_sample_color_difference: u8,
    /// The largest difference of one channel between barylab's resolve and the GL's.
    pub max_resolve_difference: u8,
    /// Pixels whose resolved colours differ at all.
    pub resolve_differing: usize,
}

impl SampleCheck {
    /// Whether every sample has the same coverage and owning triangle in both.
    pub fn coverage_agrees(&self) -> bool {
        self.coverage_mismatches == 0 && self.triangle_mismatches == 0
    }
}

/// `mesh` as the GL gets it for `samples`: with `flat` and the first-vertex convention,
/// every triangle's indices rotated so that its first vertex comes last (the GL's default
/// provoking vertex); coverage, winding and the smooth values are the same triangle's.
pub fn gl_mesh(mesh: &ClipMesh, samples: &SampleSettings) -> ClipMesh {
    let mut m = mesh.clone();
    if samples.flat && samples.provoking == ProvokingVertex::First {
        for t in &mut m.triangles {
            *t = [t[1], t[2], t[0]];
        }
    }
    m
}

/// Draws `mesh` (clip coordinates already at f32, see [`super::mesh_at_f32`]) with both, the
/// settings' samples included, and compares every sample. The GL draws its own sample
/// positions, so the settings' must be them: a different pattern (the grid) is refused.
pub fn check_samples(
    gpu: &mut Gpu,
    mesh: &ClipMesh,
    texture: &Texture,
    settings: &RenderSettings,
    output: Output,
) -> Result<(SampleCheck, Render, SampleBuffer, GlSamples), String> {
    settings.samples.check()?;
    gpu.load_mesh(&gl_mesh(mesh, &settings.samples), texture, settings)?;
    let filter = match settings.filter {
        Filter::Trilinear => Filter::Bilinear,
        f => f,
    };
    let gl = gpu.read_samples(output, filter, settings.mode, &settings.samples)?;
    let offsets = settings.samples.offsets();
    let gl_offsets: Vec<[i64; 2]> = gl
        .positions
        .iter()
        .map(|&[x, y]| {
            let s = crate::raster::project::SUBPIXEL as f32;
            [(x * s).round() as i64, (s - y * s).round() as i64]
        })
        .collect();
    let ours_offsets: Vec<[i64; 2]> = offsets.iter().map(|o| [o.x, o.y]).collect();
    if gl_offsets != ours_offsets {
        return Err(format!(
            "the GL puts its {} samples at {gl_offsets:?} (1/256 pixel from the top-left corner), \
             barylab's {} pattern at {ours_offsets:?}: only the GL's own positions can be compared",
            offsets.len(),
            match settings.samples.pattern {
                crate::raster::sample::SamplePattern::Standard => "standard",
                crate::raster::sample::SamplePattern::Grid => "grid",
            }
        ));
    }
    let (render, ours) = render_samples(mesh, texture, settings).map_err(|e| e.to_string())?;
    let check = compare_samples(&render, &ours, &gl, settings);
    Ok((check, render, ours, gl))
}

/// Compares barylab's samples with the GL's (same size and positions).
pub fn compare_samples(
    render: &Render,
    ours: &SampleBuffer,
    gl: &GlSamples,
    settings: &RenderSettings,
) -> SampleCheck {
    let n = ours.offsets.len();
    let formula = uv_formula(settings.mode, &settings.samples);
    let mut c = SampleCheck {
        per_pixel: n,
        samples: ours.samples.len(),
        uv_formula: Some(formula),
        ..SampleCheck::default()
    };
    let width = ours.width as usize;
    let d = |a: f32, b: f64| (f64::from(a) - b).abs();
    for (i, (s, g)) in ours.samples.iter().zip(&gl.samples).enumerate() {
        let (pixel, k) = (i / n, i % n);
        let (x, y) = ((pixel % width) as u32, (pixel / width) as u32);
        let at = [x, y, k as u32];
        let covered = s.triangle != NO_TRIANGLE;
        c.covered += usize::from(covered);
        if covered != (g.id != 0) {
            c.coverage_mismatches += 1;
            push_listed(&mut c.coverage_mismatch_at, at);
            continue;
        }
        if !covered {
            continue;
        }
        if g.id != s.triangle + 1 {
            c.triangle_mismatches += 1;
            push_listed(&mut c.triangle_mismatch_at, at);
            continue;
        }
        let raw = d(s.uv[0], f64::from(g.uv[0])).max(d(s.uv[1], f64::from(g.uv[1])));
        if raw > c.max_uv_formula_difference {
            c.max_uv_formula_difference = raw;
            c.max_uv_formula_at = Some(at);
        }
        let found = if settings.samples.flat {
            Some(GlLocation {
                difference: raw,
                barylab_rule: true,
            })
        } else {
            gl_location(render, ours, settings, s.triangle, (x, y), k, g.uv)
        };
        if let Some(f) = found {
            if !f.barylab_rule {
                c.location_differs += 1;
                push_listed(&mut c.location_differs_at, at);
            }
            if f.difference > c.max_uv_difference {
                c.max_uv_difference = f.difference;
                c.max_uv_at = Some(at);
            }
        }
        c.max_depth_difference = c.max_depth_difference.max(d(s.depth, f64::from(g.depth)));
        let diff = (0..4).map(|j| s.color[j].abs_diff(g.color[j])).max();
        c.max_sample_color_difference = c.max_sample_color_difference.max(diff.unwrap_or(0));
    }
    for (a, b) in render.frame.color.iter().zip(&gl.resolved) {
        let diff = (0..4).map(|j| a[j].abs_diff(b[j])).max().unwrap_or(0);
        c.resolve_differing += usize::from(diff > 0);
        c.max_resolve_difference = c.max_resolve_difference.max(diff);
    }
    c
}

/// Where the GL evaluated a sample's value, as [`gl_location`] finds it.
struct GlLocation {
    /// |uv - uv_gl| per component there (the GL's value through its formula).
    difference: f64,
    /// Whether that is the location barylab's rule gives ([`centroid_sample`]).
    barylab_rule: bool,
}

fn push_listed(list: &mut Vec<[u32; 3]>, at: [u32; 3]) {
    if list.len() < LISTED {
        list.push(at);
    }
}

/// The location the GL evaluated sample `k` of pixel (x, y) at, for source triangle
/// `triangle`: of the candidates (the pixel centre and each sample of the pixel the triangle
/// covers; only the sample itself when every sample is shaded), the one whose value, as the
/// GL computes it ([`UvFormula`]: `N(p) / D(c)` for `smooth` off the centre), is nearest
/// `gl_uv`. Ties go to barylab's rule's location. The values come from the clipped piece
/// that covers the sample ([`fragment_at`], extrapolated at a centre outside it).
fn gl_location(
    render: &Render,
    ours: &SampleBuffer,
    settings: &RenderSettings,
    triangle: u32,
    (x, y): (u32, u32),
    k: usize,
    gl_uv: [f32; 2],
) -> Option<GlLocation> {
    let samples = &settings.samples;
    let offsets = &ours.offsets;
    let prepared = match render.triangles.get(triangle as usize) {
        Some(t) if t.source == triangle => t,
        _ => render.triangles.iter().find(|t| t.source == triangle)?,
    };
    let setup = prepared
        .setups
        .iter()
        .find(|s| coverage(s, x, y, offsets) & 1 << k != 0)?;
    let mask = coverage(setup, x, y, offsets);
    let rule = if samples.per_sample_shading() {
        Some(k)
    } else {
        centroid_sample(samples.location, mask, offsets.len())
    };
    let position =
        |at: Option<usize>| at.map_or(sample_point(x, y), |j| sample_at(x, y, offsets[j]));
    let centre = fragment_at(setup, sample_point(x, y), None)?;
    let off_centre = uv_formula(settings.mode, samples) == UvFormula::SampleOverCentre;
    let difference = |at: Option<usize>| -> Option<f64> {
        let f = fragment_at(setup, position(at), None)?;
        let uv = f.varyings(settings.mode).uv();
        // The GL's value is N(p) / D(c) = exact(p) D(p) / D(c) for smooth off the centre.
        let scale = if off_centre {
            f.inv_w / centre.inv_w
        } else {
            1.0
        };
        let gl = [f64::from(gl_uv[0]), f64::from(gl_uv[1])];
        Some(
            (f64::from(uv.x) * scale - gl[0])
                .abs()
                .max((f64::from(uv.y) * scale - gl[1]).abs()),
        )
    };
    let mut best = GlLocation {
        difference: difference(rule)?,
        barylab_rule: true,
    };
    let candidates = if samples.per_sample_shading() {
        Vec::new()
    } else {
        std::iter::once(None)
            .chain((0..offsets.len()).filter(|j| mask & 1 << j != 0).map(Some))
            .collect()
    };
    for at in candidates {
        if let Some(e) = difference(at)
            && e < best.difference
        {
            best = GlLocation {
                difference: e,
                barylab_rule: false,
            };
        }
    }
    Some(best)
}
