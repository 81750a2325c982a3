//! The difference heatmap: how far apart, in texels, the affine and the perspective-correct
//! texture coordinates of each pixel are. Reads the framebuffer (which holds both); no GUI code.

use crate::budget::MemoryError;
use crate::raster::Framebuffer;

use crate::raster::texture::square_texel_difference as square_difference;
pub use crate::raster::texture::texel_difference;

/// A rendered heatmap and its scale.
#[derive(Clone, Debug, PartialEq, Default)]
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
    heat_table()[heat_index(d, scale_max)]
}

/// The step of the colour scale for a difference `d` on a scale from 0 to `scale_max`: `d`
/// over the scale, clamped to [0, 1] (a NaN counts as 0), times the last step, rounded to the
/// nearest step.
#[inline(always)]
fn heat_index(d: f32, scale_max: f32) -> usize {
    let t = if scale_max > 0.0 { d / scale_max } else { 0.0 };
    // `max` and `min` written as compares: a NaN fails both and is replaced by 0.
    let t = if t > 0.0 { t } else { 0.0 };
    let t = if t < 1.0 { t } else { 1.0 };
    // t >= 0, so adding a half and truncating rounds. The value is in [0.5, 1023.5]: the
    // conversion needs no saturation (which would keep the loops from being vectorized).
    let x = t * (HEAT_STEPS - 1) as f32 + 0.5;
    debug_assert!((0.0..HEAT_STEPS as f32).contains(&x));
    // SAFETY: `x` is finite and within [0.5, 1023.5] (t is clamped to [0, 1] above), so its
    // truncation is representable as an i32.
    let i = unsafe { x.to_int_unchecked::<i32>() };
    i as usize
}

/// [`heat_index`] of each difference in `d` into `steps` ([`NOT_DRAWN`] for a NaN: no triangle
/// there), written without branches so that the compiler vectorizes it (a frame of the
/// difference view runs it for every pixel).
// `clamp` would keep a NaN, whose truncation below is undefined: `max` then `min` on purpose.
#[allow(clippy::manual_clamp)]
#[inline(always)]
fn heat_steps(d: &[f32], scale_max: f32, steps: &mut [u32]) {
    // `heat_index`, with the scale's test taken out of the loop: `max` and `min` give the
    // same clamp for every number, and the NaN is told apart by the select below.
    let scale = if scale_max > 0.0 {
        scale_max
    } else {
        f32::INFINITY
    };
    let last = (HEAT_STEPS - 1) as f32;
    for (s, &d) in steps.iter_mut().zip(d) {
        let t = (d / scale).max(0.0).min(1.0);
        // SAFETY: `t` is in [0, 1] (`max` returns 0 for a NaN), so the value is within
        // [0.5, 1023.5] and its truncation is representable as an i32.
        let i = unsafe { (t * last + 0.5).to_int_unchecked::<i32>() } as u32;
        *s = if d.is_nan() { NOT_DRAWN } else { i };
    }
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
/// rayon's current pool); an error naming the heatmap's size when its memory is refused.
pub fn heatmap(frame: &Framebuffer, texture_size: (u32, u32)) -> Result<Heatmap, MemoryError> {
    let mut out = Heatmap::default();
    heatmap_into(frame, texture_size, &mut out)?;
    Ok(out)
}

/// Makes `out` hold `n` pixels, asking for the memory fallibly (an error naming the
/// `width`x`height` heatmap when the system refuses it).
fn size_pixels(
    out: &mut Heatmap,
    n: usize,
    (width, height): (u32, u32),
) -> Result<(), MemoryError> {
    crate::budget::try_resize(&mut out.pixels, n, [0; 4], || {
        format!("the {width}x{height} difference heatmap")
    })
}

/// [`heatmap`] into `out`, reusing its pixel memory (a view redrawn every frame then takes no
/// fresh pages from the system). Two passes over the uv buffers and no buffer of its own: the
/// largest difference first (it sets the scale), then each pixel's difference again, coloured
/// on that scale. Both passes run over plain slices so the compiler vectorizes them; the
/// largest difference is found among the squares (the square root is monotonic, so
/// `sqrt(max d^2)` is exactly `max d`).
pub fn heatmap_into(
    frame: &Framebuffer,
    texture_size: (u32, u32),
    out: &mut Heatmap,
) -> Result<(), MemoryError> {
    use rayon::prelude::*;
    let n = frame.color.len();
    let covered =
        frame.triangle.len() == n && frame.uv_affine.len() == n && frame.uv_perspective.len() == n;
    let size = [texture_size.0 as f32, texture_size.1 as f32];
    if frame.texel_difference.len() == n {
        // The render kept the difference itself (`Buffers::DepthDifference`).
        size_pixels(out, n, (frame.width, frame.height))?;
        from_differences(frame, out);
        return Ok(());
    }
    let max = if covered {
        frame
            .triangle
            .par_chunks(HEATMAP_CHUNK)
            .zip(frame.uv_affine.par_chunks(HEATMAP_CHUNK))
            .zip(frame.uv_perspective.par_chunks(HEATMAP_CHUNK))
            .map(|((t, a), p)| largest_square(t, a, p, size))
            .reduce(|| 0.0f32, |x, y| if y > x { y } else { x })
            .sqrt()
    } else {
        0.0
    };
    let scale_max = nice_ceiling(max);
    size_pixels(out, n, (frame.width, frame.height))?;
    if covered {
        out.pixels
            .par_chunks_mut(HEATMAP_CHUNK)
            .zip(frame.color.par_chunks(HEATMAP_CHUNK))
            .zip(frame.triangle.par_chunks(HEATMAP_CHUNK))
            .zip(frame.uv_affine.par_chunks(HEATMAP_CHUNK))
            .zip(frame.uv_perspective.par_chunks(HEATMAP_CHUNK))
            .for_each(|((((o, c), t), a), p)| color_run(o, c, t, a, p, size, scale_max));
    } else {
        out.pixels
            .par_chunks_mut(HEATMAP_CHUNK)
            .zip(frame.color.par_chunks(HEATMAP_CHUNK))
            .for_each(|(o, c)| o.iter_mut().zip(c).for_each(|(o, c)| *o = dim(*c)));
    }
    out.width = frame.width;
    out.height = frame.height;
    out.max = max;
    out.scale_max = scale_max;
    Ok(())
}

/// Colours a run of pixels: [`heat_color`] of the difference where a triangle is drawn, the
/// framebuffer's colour dimmed elsewhere. One table, slices of one length (no bounds checks in
/// the loop).
fn color_run(
    out: &mut [[u8; 4]],
    color: &[[u8; 4]],
    triangle: &[u32],
    affine: &[[f32; 2]],
    perspective: &[[f32; 2]],
    size: [f32; 2],
    scale_max: f32,
) {
    // Steps of RUN pixels: first every step index (arithmetic only, which the compiler
    // vectorizes), then the table lookups.
    const RUN: usize = 64;
    let table = heat_table();
    let n = out.len();
    let (color, triangle) = (&color[..n], &triangle[..n]);
    let (affine, perspective) = (&affine[..n], &perspective[..n]);
    let mut step = [0u32; RUN];
    let mut first = 0;
    while first < n {
        let m = RUN.min(n - first);
        let (t, a, p) = (
            &triangle[first..first + m],
            &affine[first..first + m],
            &perspective[first..first + m],
        );
        for k in 0..m {
            let d = square_difference(a[k], p[k], size).sqrt();
            let drawn = t[k] != crate::raster::NO_TRIANGLE && !d.is_nan();
            step[k] = if drawn {
                heat_index(d, scale_max) as u32
            } else {
                NOT_DRAWN
            };
        }
        let run = first..first + m;
        for ((o, c), &s) in out[run.clone()].iter_mut().zip(&color[run]).zip(&step) {
            *o = match s {
                NOT_DRAWN => dim(*c),
                s => table[s as usize],
            };
        }
        first += m;
    }
}

/// The largest [`square_difference`] over the covered pixels of a run of pixels (0 when none;
/// a NaN is passed over), in eight independent lanes so that it vectorizes.
fn largest_square(
    triangle: &[u32],
    affine: &[[f32; 2]],
    perspective: &[[f32; 2]],
    size: [f32; 2],
) -> f32 {
    const W: usize = 8;
    let mut lanes = [0.0f32; W];
    let n = triangle.len().min(affine.len()).min(perspective.len());
    let (t, a, p) = (&triangle[..n], &affine[..n], &perspective[..n]);
    for ((t, a), p) in t.chunks(W).zip(a.chunks(W)).zip(p.chunks(W)) {
        for k in 0..t.len() {
            let d = square_difference(a[k], p[k], size);
            // `>` is false for a NaN, so a NaN never becomes the largest.
            if t[k] != crate::raster::NO_TRIANGLE && d > lanes[k] {
                lanes[k] = d;
            }
        }
    }
    lanes
        .into_iter()
        .fold(0.0, |x, y| if y > x { y } else { x })
}

/// [`heatmap_into`] of a framebuffer that keeps the texel difference per pixel (NaN where
/// nothing is drawn): the same two passes over 4 bytes a pixel instead of 20.
fn from_differences(frame: &Framebuffer, out: &mut Heatmap) {
    use rayon::prelude::*;
    let d = &frame.texel_difference;
    let max = d
        .par_chunks(HEATMAP_CHUNK)
        .map(largest)
        .reduce(|| 0.0f32, |x, y| if y > x { y } else { x });
    let scale_max = nice_ceiling(max);
    let table = heat_table();
    out.pixels
        .par_chunks_mut(HEATMAP_CHUNK)
        .zip(frame.color.par_chunks(HEATMAP_CHUNK))
        .zip(d.par_chunks(HEATMAP_CHUNK))
        .for_each(|((o, c), d)| {
            // Runs of RUN pixels: the steps first (arithmetic only, which vectorizes), then
            // the table lookups.
            const RUN: usize = 64;
            let mut step = [0u32; RUN];
            for ((o, c), d) in o.chunks_mut(RUN).zip(c.chunks(RUN)).zip(d.chunks(RUN)) {
                heat_steps(d, scale_max, &mut step);
                for ((o, c), &s) in o.iter_mut().zip(c).zip(&step) {
                    *o = match s {
                        NOT_DRAWN => dim(*c),
                        s => table[s as usize],
                    };
                }
            }
        });
    out.width = frame.width;
    out.height = frame.height;
    out.max = max;
    out.scale_max = scale_max;
}

/// The largest of some differences (0 when none; NaN, where nothing is drawn, is passed
/// over), in eight independent lanes so that it vectorizes.
fn largest(d: &[f32]) -> f32 {
    const W: usize = 8;
    let mut lanes = [0.0f32; W];
    let chunks = d.chunks_exact(W);
    let rest = chunks.remainder();
    for chunk in chunks {
        for (l, &x) in lanes.iter_mut().zip(chunk) {
            // `>` is false for a NaN.
            if x > *l {
                *l = x;
            }
        }
    }
    for (l, &x) in lanes.iter_mut().zip(rest) {
        if x > *l {
            *l = x;
        }
    }
    lanes
        .into_iter()
        .fold(0.0, |x, y| if y > x { y } else { x })
}

/// A colour at half its brightness, alpha kept: `[r / 2, g / 2, b / 2, a]`, on the four bytes
/// as one word (the same bytes).
#[inline(always)]
fn dim(c: [u8; 4]) -> [u8; 4] {
    let w = u32::from_le_bytes(c);
    (((w >> 1) & 0x007f_7f7f) | (w & 0xff00_0000)).to_le_bytes()
}

/// A colour step that marks a pixel where nothing is drawn.
const NOT_DRAWN: u32 = u32::MAX;

/// Pixels one parallel task of [`heatmap`] handles at least.
const HEATMAP_CHUNK: usize = 16 * 1024;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::document::presets::Preset;
    use crate::raster::{Texture, render};

    #[test]
    fn front_facing_quad_has_no_difference_and_the_floor_has_some() {
        let texture = Texture::builtin(crate::raster::BuiltinTexture::UvGrid);
        let size = (texture.width(), texture.height());
        let mut scene = Preset::FrontFacing.scene();
        scene.set_size(160, 120);
        let out = render(&scene.to_mesh(), &texture, &scene.settings()).expect("render");
        let h = heatmap(&out.frame, size).expect("a small heatmap");
        // Equal w everywhere: the weights agree up to float rounding.
        assert!(h.max < 1e-3, "max {}", h.max);
        let mut floor = Preset::Floor.scene();
        floor.set_size(160, 120);
        let out = render(&floor.to_mesh(), &texture, &floor.settings()).expect("render");
        let h = heatmap(&out.frame, size).expect("a small heatmap");
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

    /// Every pixel against a plain per-pixel evaluation of the definitions, and a reused
    /// heatmap (of another size) gives the same as a new one.
    #[test]
    fn every_pixel_is_its_difference_on_the_scale() {
        let texture = Texture::builtin(crate::raster::BuiltinTexture::UvGrid);
        let size = (texture.width(), texture.height());
        let mut floor = Preset::Floor.scene();
        floor.set_size(203, 117);
        let out = render(&floor.to_mesh(), &texture, &floor.settings()).expect("render");
        let f = &out.frame;
        let drawn = |i: usize| f.triangle[i] != crate::raster::NO_TRIANGLE;
        let d = |i: usize| texel_difference(f.uv_affine[i], f.uv_perspective[i], size);
        let max = (0..f.color.len())
            .filter(|&i| drawn(i))
            .map(d)
            .fold(0.0f32, f32::max);
        let mut reused = heatmap(f, (7, 3)).expect("a small heatmap");
        assert_eq!(reused.pixels.len(), f.color.len());
        heatmap_into(f, size, &mut reused).expect("a small heatmap");
        let h = heatmap(f, size).expect("a small heatmap");
        assert_eq!(reused, h);
        assert_eq!(h.max, max);
        assert_eq!(h.scale_max, nice_ceiling(max));
        for i in 0..f.color.len() {
            let c = f.color[i];
            let expected = if drawn(i) {
                heat_color(d(i), h.scale_max)
            } else {
                [c[0] / 2, c[1] / 2, c[2] / 2, c[3]]
            };
            assert_eq!(h.pixels[i], expected, "pixel {i}");
        }
        // A render that keeps only the texel difference gives the same heatmap.
        let mut fast = crate::raster::Framebuffer::empty();
        let buffers = crate::raster::Buffers::DepthDifference;
        let mesh = floor.to_mesh();
        crate::raster::render_into(&mut fast, &mesh, &texture, &floor.settings(), buffers)
            .expect("render");
        assert_eq!(fast.buffers(), buffers);
        assert_eq!(heatmap(&fast, size).expect("a small heatmap"), h);
        // Some pixels of each kind, and more than one colour.
        assert!((0..f.color.len()).any(drawn) && !(0..f.color.len()).all(drawn));
        assert!(h.pixels.iter().any(|p| *p != h.pixels[0]));
    }
}

#[cfg(test)]
mod dim_tests {
    /// The word form halves each colour byte and keeps alpha, for every byte value.
    #[test]
    fn dim_halves_every_channel() {
        for v in 0..=255u8 {
            let c = [v, 255 - v, v / 3, v.wrapping_mul(7)];
            assert_eq!(super::dim(c), [c[0] / 2, c[1] / 2, c[2] / 2, c[3]]);
        }
    }
}
