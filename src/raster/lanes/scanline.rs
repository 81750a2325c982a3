//! The scanline rasterizer's lanes: spans per row, values stepped by their per-pixel increments.

use super::*;

/// The scanline rasterizer's lane path for rows `rows` (within the target band); `tri` made
/// for this `shading` (any colour, no wireframe), without the uv buffers; at the vector level
/// `vector`.
pub fn scanline_triangle(
    tri: &LaneTriangle,
    rows: (u32, u32),
    texture: &Texture,
    (shading, vector): (LaneShading, VectorLevel),
    target: &mut Target<'_>,
) {
    Lanes::new(texture, shading, vector).scanline_triangle(tri, rows, target);
}

/// What the scanline lanes step: `u`, `v` and the shading's channels (divided by w when
/// perspective-correct), `1/w` and depth, each linear along a row.
#[derive(Clone, Copy, Default)]
pub(super) struct Stepped {
    pub(super) u: f64,
    pub(super) v: f64,
    pub(super) inv_w: f64,
    pub(super) depth: f64,
    /// The first [`Constants::used_channels`] channels (vertex colour, normal, weights).
    pub(super) ch: [f64; CHANNELS],
}

impl Stepped {
    /// The stepped quantities for screen weights `l` (a point's weights, or their per-pixel
    /// increments: the map is linear).
    pub(super) fn from_weights(l: [f64; 3], c: &Constants, mode: Interpolation) -> Self {
        // Loops of a fixed length, unrolled: with `used_channels` as their bound they were
        // about 200 instructions a call (twice per triangle of a dense mesh, at least).
        match c.used_channels {
            0 => Self::from_weights_n::<0>(l, c, mode),
            3 => Self::from_weights_n::<3>(l, c, mode),
            n => {
                debug_assert_eq!(n, CHANNELS);
                Self::from_weights_n::<CHANNELS>(l, c, mode)
            }
        }
    }

    /// [`from_weights`](Self::from_weights) for a shading reading the first `N` channels.
    #[inline(always)]
    fn from_weights_n<const N: usize>(l: [f64; 3], c: &Constants, mode: Interpolation) -> Self {
        let scale = match mode {
            Interpolation::Perspective => [l[0] * c.inv_w[0], l[1] * c.inv_w[1], l[2] * c.inv_w[2]],
            Interpolation::Affine => l,
        };
        let mut s = Self::default();
        for k in 0..3 {
            s.u += scale[k] * c.u[k];
            s.v += scale[k] * c.v[k];
            s.inv_w += l[k] * c.inv_w[k];
            s.depth += l[k] * c.depth[k];
            for j in 0..N {
                s.ch[j] += scale[k] * c.channels[j][k];
            }
        }
        s
    }

    /// The increments per pixel along a row: the map applied to the screen weights'
    /// increments [`WeightPlanes::step_x`] (as the per-pixel scanline rasterizer steps them).
    pub(super) fn row_step(c: &Constants, mode: Interpolation) -> Self {
        Self::from_weights(c.weights.step_x(), c, mode)
    }

    /// The values at the first pixel `x0` of a span of row `y`.
    pub(super) fn span_start(c: &Constants, mode: Interpolation, x0: u32, y: u32) -> Self {
        Self::from_weights(c.weights.at_pixel(x0, y), c, mode)
    }

    /// The values of a row's first eight pixels: lane k is `start` after k single steps.
    pub(super) fn lanes(start: Self, step: &Self) -> [Self; LANES] {
        let mut lanes = [start; LANES];
        for k in 1..LANES {
            lanes[k] = lanes[k - 1].next(step);
        }
        lanes
    }

    /// The values one pixel further along the row: one single step.
    #[inline(always)]
    pub(super) fn next(&self, step: &Self) -> Self {
        // A loop, not `array::map`: that was left as a call, once per pixel of a short span.
        let mut ch = self.ch;
        for (c, d) in ch.iter_mut().zip(&step.ch) {
            *c += d;
        }
        Self {
            u: self.u + step.u,
            v: self.v + step.v,
            inv_w: self.inv_w + step.inv_w,
            depth: self.depth + step.depth,
            ch,
        }
    }
}

#[inline(always)]
pub(super) fn scanline_triangle_impl(
    tri: &LaneTriangle,
    (y_start, y_end): (u32, u32),
    texture: &Texture,
    shading: LaneShading,
    target: &mut Target<'_>,
) {
    // The scanline lanes draw no wireframe (the caller sends that case to the per-pixel
    // scanline code).
    let (mode, color) = (shading.mode, shading.color);
    let consts = &tri.consts;
    let used = consts.used_channels;
    let sampler = Sampler::new(texture, shading.filter, shading.wrap);
    let step = Stepped::row_step(consts, mode);
    let mut colors = [[0u8; 4]; LANES];
    for y in y_start..=y_end {
        let Some((x0, x1)) = row_span_of(&tri.edges, tri.bounds, y) else {
            continue;
        };
        let start = Stepped::span_start(consts, mode, x0, y);
        // Lane k holds pixel x0 + k; each chunk advances every lane by eight increments.
        let mut lanes = Stepped::lanes(start, &step);
        let n = LANES as f64;
        let (su, sv, sw, sd) = (step.u * n, step.v * n, step.inv_w * n, step.depth * n);
        let sch = step.ch.map(|x| x * n);
        let mut x = x0;
        while x <= x1 {
            let lanes_in = (x1 - x + 1).min(LANES as u32) as usize;
            let mut s = Samples::new();
            for k in 0..LANES {
                let l = &lanes[k];
                s.ok[k] = k < lanes_in && l.inv_w > 0.0 && l.inv_w < f64::INFINITY;
                let (u, v) = match mode {
                    Interpolation::Perspective => {
                        let w = 1.0 / l.inv_w;
                        for j in 0..used {
                            s.channels[j][k] = (l.ch[j] * w) as f32;
                        }
                        (l.u * w, l.v * w)
                    }
                    Interpolation::Affine => {
                        for j in 0..used {
                            s.channels[j][k] = l.ch[j] as f32;
                        }
                        (l.u, l.v)
                    }
                };
                s.u[k] = u as f32;
                s.v[k] = v as f32;
                s.depth64[k] = l.depth;
                s.depth[k] = l.depth as f32;
            }
            match color {
                LaneColor::Texture => sampler.sample(&s.u, &s.v, &mut colors),
                _ => channel_colors(&s, color, &mut colors),
            }
            write(target, x, y, &s, &colors);
            for l in lanes.iter_mut() {
                l.u += su;
                l.v += sv;
                l.inv_w += sw;
                l.depth += sd;
                for j in 0..used {
                    l.ch[j] += sch[j];
                }
            }
            x += LANES as u32;
        }
    }
}
