//! Texture lookups for eight lanes: wrap, nearest and bilinear, as `Texture::sample_rgba8` does them.

use super::*;

/// The texture module's `texel_floor` as an `i32` (it clamps to +-1e9, which fits).
#[inline(always)]
pub(super) fn texel_floor(x: f32) -> i32 {
    texture::texel_floor(x) as i32
}

/// A wrap mode applied to lanes of texel coordinates along one axis of `size` texels.
#[derive(Clone, Copy)]
pub(super) enum LaneWrap {
    /// Repeat on a power-of-two size: a mask (two's complement makes it `rem_euclid`).
    Mask(i32),
    /// Clamp to edge: `clamp(0, size - 1)`.
    Clamp(i32),
    /// Anything else: the texture module's `wrap_coord` outside the texture.
    General(u32, Wrap),
}

impl LaneWrap {
    pub(super) fn new(size: u32, wrap: Wrap) -> Self {
        match wrap {
            Wrap::Repeat if size.is_power_of_two() => LaneWrap::Mask(size as i32 - 1),
            Wrap::ClampToEdge => LaneWrap::Clamp(size as i32 - 1),
            _ => LaneWrap::General(size, wrap),
        }
    }

    #[inline(always)]
    pub(super) fn apply(self, i: i32) -> usize {
        match self {
            LaneWrap::Mask(m) => (i & m) as usize,
            LaneWrap::Clamp(hi) => i.clamp(0, hi) as usize,
            LaneWrap::General(size, wrap) => {
                if (0..size as i32).contains(&i) {
                    i as usize
                } else {
                    wrap_coord(i64::from(i), size, wrap) as usize
                }
            }
        }
    }
}

/// Just below 1/2 (`0.5 - 2^-25`, the largest `f32` below it): for a bilinear sum `y` (never
/// NaN, in [0, 255.001]) `trunc(y + HALF_DOWN)` is `texture::byte_from_sum(y)`, `round(y)`
/// half away from zero, in two vector operations (the portable and AVX2 samplers). Adding
/// exactly 1/2 would be wrong below 1/2: `0.5 - 2^-25 + 0.5` rounds to 1. Adding `HALF_DOWN`
/// to a tie `n + 1/2` gives `n + 1 - 2^-25`, which rounds up to `n + 1` for every `n` (its
/// spacing there is at least `2^-24`), and anything below `n + 1/2` stays below `n + 1`.
/// Tests check both samplers on every float of [0, 255.001].
pub(super) const HALF_DOWN: f32 = 0.499_999_97;

/// The base level of a texture, ready for lane lookups. Made only by [`Sampler::new`], from
/// one texture: `texels` holds `width * height` texels and the wraps are for that width and
/// height, so a wrapped coordinate pair always indexes a texel (the portable lanes read
/// texels unchecked at such indices, as the AVX2 gathers do).
pub(super) struct Sampler<'a> {
    pub(super) texels: &'a [[u8; 4]],
    pub(super) width: usize,
    /// `log2(width)` when the width is a power of two (the portable lanes' row offsets by a
    /// shift, as the AVX2 sampler's).
    pub(super) width_shift: Option<u32>,
    pub(super) size: (f32, f32),
    pub(super) wrap: (LaneWrap, LaneWrap),
    pub(super) filter: Filter,
    /// Every texel's alpha is 255 ([`Texture::is_opaque`]; read by the portable lanes,
    /// which then skip the alpha sum of bilinear filtering, whose result is 255).
    pub(super) opaque: bool,
}

impl<'a> Sampler<'a> {
    pub(super) fn new(texture: &'a Texture, filter: Filter, wrap: Wrap) -> Self {
        let (w, h) = (texture.width(), texture.height());
        Self {
            texels: texture.base_texels(),
            width: w as usize,
            width_shift: w.is_power_of_two().then_some(w.trailing_zeros()),
            size: (w as f32, h as f32),
            wrap: (LaneWrap::new(w, wrap), LaneWrap::new(h, wrap)),
            filter,
            opaque: texture.is_opaque(),
        }
    }

    #[inline(always)]
    pub(super) fn texel(&self, i: usize, j: usize) -> [u8; 4] {
        self.texels[j * self.width + i]
    }

    /// The colours at eight uv, as [`Texture::sample_rgba8`] computes them.
    #[inline(always)]
    pub(super) fn sample(&self, u: &F32s, v: &F32s, out: &mut [[u8; 4]; LANES]) {
        match self.filter {
            // One texel of weight 1: `round(0 + 1 * c)` is exactly `c`, so the texel is the
            // colour.
            Filter::Nearest => {
                for k in 0..LANES {
                    let i = self.wrap.0.apply(texel_floor(u[k] * self.size.0));
                    let j = self.wrap.1.apply(texel_floor(v[k] * self.size.1));
                    out[k] = self.texel(i, j);
                }
            }
            _ => {
                for k in 0..LANES {
                    let x = u[k] * self.size.0 - 0.5;
                    let y = v[k] * self.size.1 - 0.5;
                    let (i0, j0) = (texel_floor(x), texel_floor(y));
                    let (a, b) = (bilinear_fraction(x), bilinear_fraction(y));
                    let (ia, ib) = (self.wrap.0.apply(i0), self.wrap.0.apply(i0 + 1));
                    let (ja, jb) = (self.wrap.1.apply(j0), self.wrap.1.apply(j0 + 1));
                    let weights = bilinear_weights(a, b);
                    let texels = [
                        self.texel(ia, ja),
                        self.texel(ib, ja),
                        self.texel(ia, jb),
                        self.texel(ib, jb),
                    ];
                    let mut sum = [0.0f32; 4];
                    for (wt, t) in weights.iter().zip(&texels) {
                        for ch in 0..4 {
                            sum[ch] += wt * f32::from(t[ch]);
                        }
                    }
                    out[k] = sum.map(byte_from_sum);
                }
            }
        }
    }
}
