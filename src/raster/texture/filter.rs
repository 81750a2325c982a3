//! The pieces of a filter lookup: the taps it reads ([`Tap`], [`Taps`]), the wrap of a texel
//! coordinate (OpenGL 4.6, section 8.14.2), the floor and fraction of a texel coordinate, the
//! bilinear weights and the rounding of a filtered channel to a byte. The lane paths repeat
//! these operations (compared bit for bit by `tests/fast_path.rs`).

use super::Wrap;

/// One texel fetch with its weight, as used by the filters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tap {
    /// Mipmap level (0 = the full-size texture).
    pub level: u32,
    /// Texel column after wrapping.
    pub i: u32,
    /// Texel row after wrapping (0 = bottom).
    pub j: u32,
    /// The texel's share of the filtered colour (a lookup's weights sum to 1).
    pub weight: f32,
}

/// The texels one filter lookup reads: 1 (nearest), 4 (bilinear, or trilinear within one
/// level) or 8 (trilinear between two levels), without allocation.
/// Derefs to a slice of [`Tap`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Taps {
    pub(super) taps: [Tap; 8],
    pub(super) len: usize,
}

impl std::ops::Deref for Taps {
    type Target = [Tap];
    fn deref(&self) -> &[Tap] {
        &self.taps[..self.len]
    }
}

impl<'a> IntoIterator for &'a Taps {
    type Item = &'a Tap;
    type IntoIter = std::slice::Iter<'a, Tap>;
    fn into_iter(self) -> Self::IntoIter {
        self.taps[..self.len].iter()
    }
}

/// Applies a wrap mode to an integer texel coordinate (OpenGL 4.6, section 8.14.2).
///
/// ```
/// use barylab::raster::texture::{wrap_coord, Wrap};
/// assert_eq!(wrap_coord(-1, 4, Wrap::Repeat), 3);
/// assert_eq!(wrap_coord(5, 4, Wrap::ClampToEdge), 3);
/// // Mirrored repeat of size 4: ... 4 -> 3, 5 -> 2, -1 -> 0, -2 -> 1.
/// assert_eq!(wrap_coord(4, 4, Wrap::MirroredRepeat), 3);
/// assert_eq!(wrap_coord(5, 4, Wrap::MirroredRepeat), 2);
/// assert_eq!(wrap_coord(-1, 4, Wrap::MirroredRepeat), 0);
/// assert_eq!(wrap_coord(-2, 4, Wrap::MirroredRepeat), 1);
/// ```
pub fn wrap_coord(i: i64, size: u32, wrap: Wrap) -> u32 {
    let s = i64::from(size);
    // Inside the texture every mode is the identity (the common case; no division).
    if (0..s).contains(&i) {
        return i as u32;
    }
    let r = match wrap {
        Wrap::Repeat => i.rem_euclid(s),
        Wrap::ClampToEdge => i.clamp(0, s - 1),
        Wrap::MirroredRepeat => {
            let m = i.rem_euclid(2 * s) - s;
            let mirror = if m >= 0 { m } else { -(1 + m) };
            (s - 1) - mirror
        }
    };
    r as u32
}

/// `out += weight * texel`, channel by channel, in the texel's 0..255 scale.
pub(super) fn add_texel(out: &mut [f32; 4], texel: [u8; 4], weight: f32) {
    for (o, c) in out.iter_mut().zip(texel) {
        *o += weight * f32::from(c);
    }
}

/// A filtered channel in the 0..255 scale to a byte: `round(clamp(sum, 0, 255))`, half away
/// from zero (NaN gives 0).
///
/// ```
/// use barylab::raster::texture::byte_from_sum;
/// assert_eq!(byte_from_sum(127.5), 128);
/// assert_eq!(byte_from_sum(127.49999), 127);
/// assert_eq!(byte_from_sum(300.0), 255);
/// assert_eq!(byte_from_sum(f32::NAN), 0);
/// ```
pub fn byte_from_sum(sum: f32) -> u8 {
    if sum.is_nan() {
        return 0;
    }
    round_byte(sum.clamp(0.0, 255.0))
}

/// `y.round() as u8` for `y` in [0, 255]: the truncation, plus one where the rest is at least
/// 1/2. Exact: `y - trunc(y)` has no rounding error (for `trunc(y) >= 1` the two are within a
/// factor of two; else it is `y`). Without the call to `roundf` that `f32::round` is on the
/// baseline x86-64 target (no rounding instruction before SSE4.1), a few percent of a
/// supersampled frame; the lanes round the same way (`lanes/portable/sampler.rs`). Every
/// float of [0, 255] is checked against `f32::round` by the test below.
#[inline]
pub(crate) fn round_byte(y: f32) -> u8 {
    debug_assert!((0.0..=255.0).contains(&y), "{y}");
    let t = y as u8;
    t + u8::from(y - f32::from(t) >= 0.5)
}

/// Largest |texel coordinate| used for wrapping: far beyond any texture size, keeps the
/// `f32 -> i64` conversion of huge or infinite uv well defined.
pub(crate) const MAX_TEXEL_COORD: f32 = 1e9;

/// `floor(x)` as a texel index: NaN gives 0, the coordinate is clamped to
/// +-[`MAX_TEXEL_COORD`] first (so it also fits an `i32`).
pub(crate) fn texel_floor(x: f32) -> i64 {
    if x.is_nan() {
        return 0;
    }
    fast_floor(x.clamp(-MAX_TEXEL_COORD, MAX_TEXEL_COORD)) as i64
}

/// The fraction of bilinear filtering along one axis at texel coordinate `x` (`u W - 1/2`):
/// `clamp(x - floor(x), 0, 1)` with `floor` of the clamped coordinate, as [`texel_floor`]
/// takes it; 0 for a non-finite `x`. The lane paths repeat it (AVX2, AVX-512: compared bit
/// for bit by `tests/fast_path.rs`).
pub(crate) fn bilinear_fraction(x: f32) -> f32 {
    if x.is_finite() {
        (x - fast_floor(x.clamp(-MAX_TEXEL_COORD, MAX_TEXEL_COORD))).clamp(0.0, 1.0)
    } else {
        0.0
    }
}

/// The weights of the four texels of bilinear filtering, `(i0, j0), (i0 + 1, j0), (i0, j0 + 1),
/// (i0 + 1, j0 + 1)`, from the fractions `a` (along u) and `b` (along v).
///
/// ```
/// use barylab::raster::texture::bilinear_weights;
/// assert_eq!(bilinear_weights(0.25, 0.5), [0.375, 0.125, 0.375, 0.125]);
/// ```
pub fn bilinear_weights(a: f32, b: f32) -> [f32; 4] {
    [(1.0 - a) * (1.0 - b), a * (1.0 - b), (1.0 - a) * b, a * b]
}

/// `floor(x)` for |x| <= 2^30 without a libm call: truncate towards zero, then step down
/// for negative non-integers. (The baseline x86-64 target has no rounding instruction, and
/// `f32::floor` becomes a function call in the per-pixel path.)
fn fast_floor(x: f32) -> f32 {
    let t = x as i32 as f32;
    if t > x { t - 1.0 } else { t }
}

#[cfg(test)]
mod tests {
    /// Every float from 0 to 255 rounds as `f32::round` rounds it.
    #[test]
    fn round_byte_is_round_on_every_float_of_the_byte_range() {
        let last = 255.0f32.to_bits();
        let wrong = (0..=last)
            .map(f32::from_bits)
            .filter(|&y| super::round_byte(y) != y.round() as u8)
            .take(10)
            .collect::<Vec<_>>();
        assert!(wrong.is_empty(), "rounded differently: {wrong:?}");
    }
}
