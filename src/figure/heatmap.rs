//! The difference heatmap: how far apart, in texels, the affine and the perspective-correct
//! texture coordinates of each pixel are. Reads the framebuffer (which holds both); no GUI code.

use crate::raster::Framebuffer;
use crate::raster::texture::texel_offset;

/// One pixel's difference in texels: the length of [`texel_offset`],
/// `|((u_a - u_p) W, (v_a - v_p) H)|` for a W x H texture, in `f32`.
///
/// ```
/// use barylab::figure::heatmap::texel_difference;
/// // 0.03 of a 100-texel-wide texture across, 0.04 of a 100-texel-high one down: 5 texels.
/// let d = texel_difference([0.53, 0.54], [0.5, 0.5], (100, 100));
/// assert!((d - 5.0).abs() < 1e-4);
/// ```
pub fn texel_difference(uv_affine: [f32; 2], uv_perspective: [f32; 2], size: (u32, u32)) -> f32 {
    let [du, dv] = texel_offset(uv_affine, uv_perspective, [size.0 as f32, size.1 as f32]);
    (du * du + dv * dv).sqrt()
}

/// A rendered heatmap and its scale.
#[derive(Clone, Debug, PartialEq)]
pub struct Heatmap {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// RGBA8, row 0 at the top; uncovered pixels keep the framebuffer's colour dimmed.
    pub pixels: Vec<[u8; 4]>,
    /// The largest difference over the covered pixels, in texels.
    pub max: f32,
    /// The difference the top of the colour scale stands for: `max` rounded up by
    /// [`nice_ceiling`].
    pub scale_max: f32,
}

/// Steps of the colour scale: the magma map sampled once at `i / (HEAT_STEPS - 1)`, then looked
/// up per pixel (evaluating the spline for every pixel cost more than drawing the two images).
/// 1024 steps are finer than the 8-bit colours can show.
const HEAT_STEPS: usize = 1024;

/// The colour of a difference `d` on a scale from 0 to `scale_max` (the magma colour map, in
/// 1024 steps).
///
/// ```
/// use barylab::figure::heatmap::heat_color;
/// assert_eq!(heat_color(0.0, 4.0), heat_color(-1.0, 4.0)); // below the scale: its bottom
/// assert_eq!(heat_color(4.0, 4.0), heat_color(9.0, 4.0)); // above: its top
/// assert_ne!(heat_color(1.0, 4.0), heat_color(3.0, 4.0));
/// ```
pub fn heat_color(d: f32, scale_max: f32) -> [u8; 4] {
    let table = heat_table();
    let t = if scale_max > 0.0 {
        (d / scale_max).clamp(0.0, 1.0)
    } else {
        0.0
    };
    // Rounded to the nearest step (t >= 0, so adding a half and truncating rounds); a NaN
    // stays NaN through the clamp and converts to index 0.
    let i = (t * (HEAT_STEPS - 1) as f32 + 0.5) as usize;
    table[i.min(HEAT_STEPS - 1)]
}

/// The colour scale's [`HEAT_STEPS`] colours, computed once.
fn heat_table() -> &'static [[u8; 4]] {
    static TABLE: std::sync::OnceLock<Vec<[u8; 4]>> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        (0..HEAT_STEPS)
            .map(|i| {
                let c = colorous::MAGMA.eval_continuous(i as f64 / (HEAT_STEPS - 1) as f64);
                [c.r, c.g, c.b, 255]
            })
            .collect()
    })
}

/// The smallest of 1, 1.5, 2, 3, 4, 5, 6, 8 times a power of ten that is at least `x` (at
/// least 0.01), so the scale's top is at most a third above the largest value.
///
/// ```
/// use barylab::figure::heatmap::nice_ceiling;
/// assert_eq!(nice_ceiling(0.0), 0.01);
/// assert_eq!(nice_ceiling(3.2), 4.0);
/// assert_eq!(nice_ceiling(20.0), 20.0);
/// assert_eq!(nice_ceiling(251.0), 300.0);
/// assert_eq!(nice_ceiling(81.0), 100.0);
/// ```
pub fn nice_ceiling(x: f32) -> f32 {
    const FLOOR: f32 = 0.01;
    if x.is_nan() || x <= FLOOR {
        return FLOOR;
    }
    let p = 10f32.powf(x.log10().floor());
    for m in [1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0] {
        // Tolerance for x being a power of ten times m up to rounding in powf/log10.
        if x <= m * p * (1.0 + 1e-6) {
            return m * p;
        }
    }
    10.0 * p
}

/// The heatmap of a framebuffer for a texture of `texture_size` texels (rows in parallel, on
/// rayon's current pool).
pub fn heatmap(frame: &Framebuffer, texture_size: (u32, u32)) -> Heatmap {
    use rayon::prelude::*;
    let n = frame.color.len();
    let covered = frame.triangle.len() == n && frame.uv_affine.len() == n;
    // The difference per pixel (NaN where nothing is drawn), then the colours on its scale.
    let mut diff = vec![f32::NAN; n];
    if covered {
        diff.par_chunks_mut(HEATMAP_CHUNK)
            .enumerate()
            .for_each(|(c, chunk)| {
                let first = c * HEATMAP_CHUNK;
                let rows = first..first + chunk.len();
                let triangle = &frame.triangle[rows.clone()];
                let affine = &frame.uv_affine[rows.clone()];
                let perspective = &frame.uv_perspective[rows];
                for (k, d) in chunk.iter_mut().enumerate() {
                    if triangle[k] != crate::raster::NO_TRIANGLE {
                        *d = texel_difference(affine[k], perspective[k], texture_size);
                    }
                }
            });
    }
    let max = diff
        .par_chunks(HEATMAP_CHUNK)
        .map(|c| c.iter().copied().fold(0.0f32, f32::max))
        .reduce(|| 0.0f32, f32::max);
    let scale_max = nice_ceiling(max);
    let mut pixels = vec![[0u8; 4]; n];
    pixels
        .par_chunks_mut(HEATMAP_CHUNK)
        .zip(diff.par_chunks(HEATMAP_CHUNK))
        .zip(frame.color.par_chunks(HEATMAP_CHUNK))
        .for_each(|((out, diff), color)| {
            for ((o, &d), c) in out.iter_mut().zip(diff).zip(color) {
                *o = if d.is_nan() {
                    [c[0] / 2, c[1] / 2, c[2] / 2, c[3]]
                } else {
                    heat_color(d, scale_max)
                };
            }
        });
    Heatmap {
        width: frame.width,
        height: frame.height,
        pixels,
        max,
        scale_max,
    }
}

/// Pixels one parallel task of [`heatmap`] handles at least.
const HEATMAP_CHUNK: usize = 16 * 1024;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::presets::Preset;
    use crate::raster::{Texture, render};

    #[test]
    fn front_facing_quad_has_no_difference_and_the_floor_has_some() {
        let texture = Texture::builtin(crate::raster::BuiltinTexture::UvGrid);
        let size = (texture.width(), texture.height());
        let mut scene = Preset::FrontFacing.scene();
        scene.set_size(160, 120);
        let out = render(&scene.to_mesh(), &texture, &scene.settings()).expect("render");
        let h = heatmap(&out.frame, size);
        // Equal w everywhere: the weights agree up to float rounding.
        assert!(h.max < 1e-3, "max {}", h.max);
        let mut floor = Preset::Floor.scene();
        floor.set_size(160, 120);
        let out = render(&floor.to_mesh(), &texture, &floor.settings()).expect("render");
        let h = heatmap(&out.frame, size);
        assert!(h.max > 10.0, "max {}", h.max);
        assert!(h.scale_max >= h.max);
        // The hottest pixel gets the top colour of the scale, up to the map's quantisation.
        let i = (0..out.frame.color.len())
            .filter(|&i| out.frame.covered(i as u32 % 160, i as u32 / 160))
            .max_by(|&a, &b| {
                let d = |i: usize| {
                    texel_difference(out.frame.uv_affine[i], out.frame.uv_perspective[i], size)
                };
                d(a).total_cmp(&d(b))
            })
            .expect("covered pixel");
        assert_eq!(h.pixels[i], heat_color(h.max, h.scale_max));
    }
}
