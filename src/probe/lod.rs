//! The level of detail of a trilinear (or anisotropic) lookup, derived step by step: the
//! pixel's 2x2 quad and its uvs, the derivatives, the footprint in texels, rho, lambda, the
//! mipmap levels and their blend, the taps, and for anisotropic filtering the probes.

use serde::Serialize;

use super::{Prober, TapTrace};
use crate::raster::interpolate::{self, Derivatives, Interpolation};
use crate::raster::setup::{TriangleSetup, sample_point};
use crate::raster::texture::{Anisotropic, Filter, Taps, Texture, footprint_axes, lod};

/// One pixel of the 2x2 quad the derivatives come from.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct QuadPixel {
    /// The pixel (row 0 at the top).
    pub pixel: [u32; 2],
    /// uv from the triangle's plane at its centre (extrapolated outside the triangle);
    /// `None` where the plane gives none.
    pub uv: Option<[f32; 2]>,
    /// Whether the triangle covers its centre (else the GPU runs it as a helper pixel, only
    /// for the differences).
    pub inside: bool,
}

/// Which mipmap levels a lookup at `lambda` reads.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct LevelChoice {
    /// The level of detail the levels come from.
    pub lambda: f32,
    /// The first level read: 0 when `lambda <= 0` (magnification), else `floor(lambda)`
    /// clamped to the last level.
    pub level: u32,
    /// The second level, `level + 1`, with its weight `frac(lambda)`; `None` when one level
    /// alone is read.
    pub next: Option<(u32, f32)>,
}

/// One probe of an anisotropic lookup.
#[derive(Clone, Debug, Serialize)]
pub struct ProbeTrace {
    /// `i / (N + 1) - 1/2` (i = 1..N): where along the major axis's derivative it reads.
    pub offset: f32,
    /// The probe's uv, `uv + offset duv_major`.
    pub uv: [f32; 2],
    /// Its trilinear taps.
    pub taps: Vec<TapTrace>,
    /// Its trilinear colour.
    pub color: [u8; 4],
}

/// Anisotropic filtering's numbers (EXT_texture_filter_anisotropic).
#[derive(Clone, Debug, Serialize)]
pub struct AnisotropicTrace {
    /// The sampler's largest anisotropy.
    pub max: u32,
    /// `max(Px, Py)` and `min(Px, Py)`, in texels.
    pub p_max: f32,
    /// `min(Px, Py)`, in texels.
    pub p_min: f32,
    /// `N = min(ceil(Pmax / Pmin), max)`.
    pub n: u32,
    /// Whether the probes lie along y (`Py > Px`); else along x.
    pub major_y: bool,
    /// `log2(Pmax / N)` and the levels it reads.
    pub levels: LevelChoice,
    /// The probes, in order.
    pub probes: Vec<ProbeTrace>,
}

/// The level of detail derived for the pixel, with the uv of one interpolation mode.
#[derive(Clone, Debug, Serialize)]
pub struct LodTrace {
    /// Whose uv: the scene's interpolation mode.
    pub mode: Interpolation,
    /// Coarse (what the renderer and GPUs use) or fine derivatives.
    pub derivatives: Derivatives,
    /// The quad's pixels: (x0, y0), (x0 + 1, y0), (x0, y0 + 1), (x0 + 1, y0 + 1).
    pub quad: [QuadPixel; 4],
    /// The pixel's uv.
    pub uv: [f32; 2],
    /// `(du/dx, dv/dx)`: the difference of two horizontal neighbours of the quad.
    pub duv_dx: [f32; 2],
    /// `(du/dy, dv/dy)`: the difference of two vertical neighbours (y grows down the image).
    pub duv_dy: [f32; 2],
    /// `[W, H]` of level 0.
    pub texture_size: [u32; 2],
    /// Number of mipmap levels (level 0 is the texture).
    pub levels: u32,
    /// `Px = |(du/dx W, dv/dx H)|`, in texels.
    pub px: f32,
    /// `Py = |(du/dy W, dv/dy H)|`, in texels.
    pub py: f32,
    /// `rho = max(Px, Py)`.
    pub rho: f32,
    /// `lambda = log2(rho)` and the levels trilinear filtering reads.
    pub trilinear: LevelChoice,
    /// The trilinear taps at the pixel's uv.
    pub taps: Vec<TapTrace>,
    /// With anisotropic filtering: its numbers and probes.
    pub anisotropic: Option<AnisotropicTrace>,
    /// The colour these numbers give (the rendered one with coarse derivatives).
    pub color: [u8; 4],
}

/// The taps of one lookup as the trace lists them.
pub(super) fn tap_traces(t: &Texture, taps: &Taps) -> Vec<TapTrace> {
    taps.iter()
        .map(|tap| TapTrace {
            level: tap.level,
            i: tap.i,
            j: tap.j,
            unwrapped: None,
            weight: tap.weight,
            texel: t.texel_at(tap.level, tap.i, tap.j),
        })
        .collect()
}

fn level_choice(t: &Texture, lambda: f32) -> LevelChoice {
    let (level, next) = t.trilinear_levels(lambda);
    LevelChoice {
        lambda,
        level,
        next: next.map(|f| (level + 1, f)),
    }
}

impl Prober<'_> {
    /// The level-of-detail derivation at pixel (x, y) of set-up triangle `s` with the scene's
    /// interpolation mode; `None` unless the filter is trilinear, or where the quad has no uv.
    pub(super) fn lod_trace(&self, s: &TriangleSetup, (x, y): (u32, u32)) -> Option<LodTrace> {
        if self.settings.filter != Filter::Trilinear {
            return None;
        }
        let t = &*self.texture;
        let mode = self.settings.mode;
        let wrap = self.settings.wrap;
        let [dx, dy] = interpolate::quad_derivatives(s, (x, y), mode, self.derivatives)?;
        let uv = interpolate::uv_at(s, x, y, mode)?;
        let (x0, y0) = (x & !1, y & !1);
        let quad =
            [(x0, y0), (x0 + 1, y0), (x0, y0 + 1), (x0 + 1, y0 + 1)].map(|(qx, qy)| QuadPixel {
                pixel: [qx, qy],
                uv: interpolate::uv_at(s, qx, qy, mode).map(|u| u.to_array()),
                inside: qx < self.settings.width
                    && qy < self.settings.height
                    && s.covers(&s.edge_values(sample_point(qx, qy))),
            });
        let (w, h) = (t.width(), t.height());
        let [px, py] = footprint_axes(dx, dy, w, h);
        let lambda = lod(dx, dy, w, h);
        let anisotropic = self.params.anisotropy().map(|max| {
            let a = Anisotropic::of(dx, dy, (w, h), max);
            let probes = (0..a.n)
                .map(|i| {
                    let p = a.probe_uv(uv, i);
                    ProbeTrace {
                        offset: (i + 1) as f32 / (a.n + 1) as f32 - 0.5,
                        uv: p.to_array(),
                        taps: tap_traces(t, &t.anisotropic_probe_taps(p, wrap, &a)),
                        color: t.sample_rgba8(p, Filter::Trilinear, wrap, a.lambda),
                    }
                })
                .collect();
            AnisotropicTrace {
                max: max.get(),
                p_max: px.max(py),
                p_min: px.min(py),
                n: a.n,
                major_y: a.major_y,
                levels: level_choice(t, a.lambda),
                probes,
            }
        });
        let color = match self.params.anisotropy() {
            Some(max) => t.sample_anisotropic_rgba8(uv, wrap, [dx, dy], max),
            None => t.sample_rgba8(uv, Filter::Trilinear, wrap, lambda),
        };
        Some(LodTrace {
            mode,
            derivatives: self.derivatives,
            quad,
            uv: uv.to_array(),
            duv_dx: dx.to_array(),
            duv_dy: dy.to_array(),
            texture_size: [w, h],
            levels: t.levels(),
            px,
            py,
            rho: px.max(py),
            trilinear: level_choice(t, lambda),
            taps: tap_traces(t, &t.taps_lod(uv, Filter::Trilinear, wrap, lambda)),
            anisotropic,
            color,
        })
    }
}
