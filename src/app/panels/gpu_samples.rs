//! The GPU view under multisampling: the canvas's scene drawn by the GL with the scene's
//! samples (a multisample framebuffer, every sample read back, `gpu::sample_check`), the
//! GL's resolve beside barylab's, and the per-sample comparison's summary: coverage and the
//! owning triangle at every sample, uv against barylab's exact value, and the GL difference
//! named for `smooth` at the centroid or a sample (the GL's `N(p) / D(c)`).

use egui::{Color32, RichText, Ui};

use crate::i18n::Lang;

/// The per-sample comparison's numbers the view shows (`gpu::sample_check::SampleCheck`'s).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SamplesSummary {
    /// Samples per pixel.
    pub per_pixel: usize,
    /// Samples compared.
    pub samples: usize,
    /// Samples covered by one side only.
    pub coverage_mismatches: usize,
    /// Samples both cover, owned by different triangles.
    pub triangle_mismatches: usize,
    /// The largest |uv - uv_gl| with the GL's value taken through its formula.
    pub max_uv_difference: f64,
    /// The GL's `smooth` value at the centroid or a sample is `N(p) / D(c)`.
    pub sample_over_centre: bool,
    /// The largest |uv - uv_gl| with both values as they are.
    pub max_uv_formula_difference: f64,
    /// Samples the GL evaluated at another location than barylab's rule.
    pub location_differs: usize,
    /// The largest channel difference of the two resolves.
    pub max_resolve_difference: u8,
}

/// The uv tolerance of the per-sample comparison (issue 31's, `tests/llvmpipe_samples.rs`).
pub const UV_TOLERANCE: f64 = 5e-5;

impl SamplesSummary {
    /// Whether coverage and the owning triangle agree at every sample and uv within
    /// [`UV_TOLERANCE`].
    pub fn agrees(&self) -> bool {
        self.coverage_mismatches == 0
            && self.triangle_mismatches == 0
            && self.max_uv_difference <= UV_TOLERANCE
    }
}

#[cfg(feature = "gpu")]
impl From<&crate::gpu::sample_check::SampleCheck> for SamplesSummary {
    fn from(c: &crate::gpu::sample_check::SampleCheck) -> Self {
        Self {
            per_pixel: c.per_pixel,
            samples: c.samples,
            coverage_mismatches: c.coverage_mismatches,
            triangle_mismatches: c.triangle_mismatches,
            max_uv_difference: c.max_uv_difference,
            sample_over_centre: c.uv_formula
                == Some(crate::gpu::sample_check::UvFormula::SampleOverCentre),
            max_uv_formula_difference: c.max_uv_formula_difference,
            location_differs: c.location_differs,
            max_resolve_difference: c.max_resolve_difference,
        }
    }
}

/// What [`draw`] gives: barylab's resolve, the GL's, their per-pixel comparison and the
/// per-sample summary.
#[cfg(feature = "gpu")]
pub(crate) type Drawn = (
    Vec<[u8; 4]>,
    Vec<[u8; 4]>,
    crate::gpu::view::ImageDiff,
    SamplesSummary,
);

/// Draws `mesh` with the GL and barylab at the settings' samples and compares every sample:
/// barylab's resolve and the GL's, the per-pixel comparison by sample 0's owner (the frame's
/// per-pixel buffers are sample 0's), and the per-sample summary.
#[cfg(feature = "gpu")]
pub(crate) fn draw(
    gpu: &mut crate::gpu::Gpu,
    mesh: &crate::raster::ClipMesh,
    texture: &crate::raster::Texture,
    settings: &crate::raster::RenderSettings,
    output: crate::gpu::Output,
) -> Result<Drawn, String> {
    let (check, render, _ours, gl) =
        crate::gpu::sample_check::check_samples(gpu, mesh, texture, settings, output)?;
    let n = gl.count.max(1);
    let ids: Vec<[u8; 4]> = gl
        .samples
        .chunks_exact(n)
        .map(|p| p[0].id.to_le_bytes())
        .collect();
    let f = render.frame;
    let diff =
        crate::gpu::view::image_diff(settings.width, &f.triangle, &f.color, &ids, &gl.resolved);
    Ok((f.color, gl.resolved, diff, SamplesSummary::from(&check)))
}

/// The summary's lines, in `lang`.
pub fn summary_lines(s: &SamplesSummary, lang: Lang) -> Vec<(String, bool)> {
    let uv = format!("{:.1e}", s.max_uv_difference);
    let mut lines = vec![
        if s.coverage_mismatches == 0 && s.triangle_mismatches == 0 {
            (
                lang.tr_with(
                    "gpu_view.samples_identical",
                    &[("n", &s.per_pixel), ("samples", &s.samples)],
                ),
                true,
            )
        } else {
            (
                lang.tr_with(
                    "gpu_view.samples_differ",
                    &[
                        ("coverage", &s.coverage_mismatches),
                        ("triangles", &s.triangle_mismatches),
                    ],
                ),
                false,
            )
        },
        (
            lang.tr_with("gpu_view.samples_uv", &[("max", &uv)]),
            s.max_uv_difference <= UV_TOLERANCE,
        ),
    ];
    if s.sample_over_centre {
        let off = format!("{:.3}", s.max_uv_formula_difference);
        lines.push((
            lang.tr_with("gpu_view.samples_formula", &[("max", &off)]),
            true,
        ));
    }
    if s.location_differs > 0 {
        lines.push((
            lang.tr_with(
                "gpu_view.samples_location",
                &[("count", &s.location_differs)],
            ),
            true,
        ));
    }
    lines.push((
        lang.tr_with(
            "gpu_view.samples_resolve",
            &[("max", &lang.levels(s.max_resolve_difference))],
        ),
        // Different uv (the GL's formula) may read other texels: then the resolve differs.
        s.max_resolve_difference <= 1 || s.sample_over_centre,
    ));
    lines
}

/// The summary under the GPU view's strip.
pub fn summary_ui(ui: &mut Ui, s: &SamplesSummary) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    for (line, good) in summary_lines(s, lang) {
        let color = if good {
            Color32::LIGHT_GREEN
        } else {
            Color32::from_rgb(255, 120, 255)
        };
        ui.add(egui::Label::new(RichText::new(line).color(color)).wrap());
    }
}
