//! The level of detail the GL used against barylab's, pixel by pixel, for trilinear and
//! anisotropic filtering: the GL's from a level-coloured pyramid ([`Gpu::read_levels`]),
//! barylab's from the renderer's own per-pixel lambda
//! ([`crate::figure::lod_view::lod_per_pixel_of_mesh`]), both as the level position read:
//! lambda clamped to `[0, last level]`.

use serde::Serialize;

use super::Gpu;
use crate::raster::{ClipMesh, NO_TRIANGLE, RenderSettings, Texture};

/// Pixels whose level positions differ by at most this much "agree": their colours are then
/// compared ([`LodCheck::agreeing_max_color`]).
pub const AGREE: f32 = 1.0 / 16.0;

/// How the GL's level of detail compares with barylab's over the pixels both cover.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct LodCheck {
    /// The largest anisotropy both drew with (1: trilinear).
    pub anisotropy: u32,
    /// Pixels compared.
    pub pixels: usize,
    /// The largest `|level_gl - level_barylab|`, in levels.
    pub max_difference: f32,
    /// The first pixel (in row order) with it, (x, y) in image rows.
    pub max_at: Option<[u32; 2]>,
    /// The mean `|level_gl - level_barylab|`.
    pub mean_difference: f32,
    /// The mean `level_gl - level_barylab` (positive: the GL reads coarser levels).
    pub mean_signed: f32,
    /// Pixels within one level.
    pub within_one: usize,
    /// Pixels within a tenth of a level.
    pub within_tenth: usize,
    /// Pixels within [`AGREE`].
    pub agreeing: usize,
    /// Over the agreeing pixels: the largest difference of one 8-bit colour channel.
    pub agreeing_max_color: u8,
}

impl LodCheck {
    /// The share of the compared pixels within one level, 0 to 1 (1 when none were compared).
    pub fn share_within_one(&self) -> f64 {
        share(self.within_one, self.pixels)
    }

    /// The share within a tenth of a level.
    pub fn share_within_tenth(&self) -> f64 {
        share(self.within_tenth, self.pixels)
    }
}

fn share(n: usize, total: usize) -> f64 {
    if total == 0 {
        1.0
    } else {
        n as f64 / total as f64
    }
}

/// The level position a lookup at `lambda` reads in a texture whose last level is `last`:
/// `clamp(lambda, 0, last)` (0 when magnified).
///
/// ```
/// use barylab::gpu::lod_check::level_position;
/// assert_eq!(level_position(-1.5, 8), 0.0);
/// assert_eq!(level_position(4.25, 8), 4.25);
/// assert_eq!(level_position(11.0, 8), 8.0);
/// ```
pub fn level_position(lambda: f32, last: u32) -> f32 {
    if lambda.is_nan() {
        return 0.0;
    }
    lambda.clamp(0.0, last as f32)
}

/// Compares the level of detail of the scene the GPU has loaded (`mesh`, drawn with
/// `settings`, trilinear) with barylab's, and the colours (`ours`: barylab's owning triangle
/// and colour per pixel; `gl_colors`: the GL's colour image) where the levels agree.
pub fn check_lod(
    gpu: &Gpu,
    mesh: &ClipMesh,
    texture: &Texture,
    settings: &RenderSettings,
    ours: (&[u32], &[[u8; 4]]),
    gl_colors: &[[u8; 4]],
) -> Result<LodCheck, String> {
    let gl = gpu.read_levels(settings.mode)?;
    let lambdas = crate::figure::lod_view::lod_per_pixel_of_mesh(mesh, texture, settings)
        .map_err(|e| e.to_string())?;
    let last = texture.levels().saturating_sub(1);
    let width = settings.width.max(1);
    let mut c = LodCheck {
        anisotropy: settings.max_anisotropy.get(),
        ..LodCheck::default()
    };
    let (mut sum, mut signed) = (0.0f64, 0.0f64);
    for (k, (&tri, &lambda)) in ours.0.iter().zip(&lambdas).enumerate() {
        if tri == NO_TRIANGLE || lambda.is_nan() || k >= gl.len() {
            continue;
        }
        let d = gl[k] - level_position(lambda, last);
        let a = d.abs();
        c.pixels += 1;
        sum += f64::from(a);
        signed += f64::from(d);
        c.within_one += usize::from(a <= 1.0);
        c.within_tenth += usize::from(a <= 0.1);
        if a > c.max_difference {
            c.max_difference = a;
            c.max_at = Some([(k as u32) % width, (k as u32) / width]);
        }
        if a <= AGREE {
            c.agreeing += 1;
            let diff = (0..4)
                .map(|i| ours.1[k][i].abs_diff(gl_colors[k][i]))
                .max()
                .unwrap_or(0);
            c.agreeing_max_color = c.agreeing_max_color.max(diff);
        }
    }
    if c.pixels > 0 {
        c.mean_difference = (sum / c.pixels as f64) as f32;
        c.mean_signed = (signed / c.pixels as f64) as f32;
    }
    Ok(c)
}

impl LodCheck {
    /// The report's lines in `lang`: the numbers, then why they differ, naming the renderer
    /// (`renderer`: GL_RENDERER) rather than calling either side wrong.
    pub fn lines(&self, renderer: &str, lang: crate::i18n::Lang) -> Vec<String> {
        let pct = |x: f64| format!("{:.1}", 100.0 * x);
        let at = self
            .max_at
            .map(|[x, y]| lang.tr_with("compare.report.at", &[("x", &x), ("y", &y)]))
            .unwrap_or_default();
        let what = if self.anisotropy > 1 {
            lang.tr_with(
                "compare.gpu_check.lod_anisotropic",
                &[("n", &self.anisotropy)],
            )
        } else {
            lang.tr("probe.filter.trilinear")
        };
        let llvmpipe = renderer.contains("llvmpipe");
        let why = match (llvmpipe, self.anisotropy > 1) {
            (true, false) => "compare.gpu_check.lod_why_llvmpipe",
            (true, true) => "compare.gpu_check.lod_why_llvmpipe_anisotropic",
            (false, _) => "compare.gpu_check.lod_why_other",
        };
        vec![
            lang.tr_with(
                "compare.gpu_check.lod",
                &[
                    ("what", &what),
                    ("max", &format!("{:.3}", self.max_difference)),
                    ("at", &at),
                    ("mean", &format!("{:.3}", self.mean_difference)),
                    ("signed", &format!("{:+.3}", self.mean_signed)),
                    ("n", &self.pixels),
                    ("one", &pct(self.share_within_one())),
                    ("tenth", &pct(self.share_within_tenth())),
                ],
            ),
            lang.tr_with(
                "compare.gpu_check.lod_colour",
                &[
                    ("n", &self.agreeing),
                    ("max", &lang.levels(self.agreeing_max_color)),
                ],
            ),
            lang.tr_with("compare.gpu_check.note", &[("note", &lang.tr(why))]),
        ]
    }
}
