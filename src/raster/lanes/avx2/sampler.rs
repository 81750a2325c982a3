//! The texture sampler of the x86 lanes: wrap, gather, bilinear weights and bytes of eight
//! lanes with AVX2 ([`VecSampler`], [`sample`]). The AVX2 lanes (`avx2/`) look up one chunk
//! of eight pixels at a time with it, the AVX-512 lanes (`avx512/`) two; it needs AVX2 only,
//! and uses neither of them.

use std::arch::x86_64::*;

use super::super::LaneShading;
use super::super::sampler::{HALF_DOWN, LaneWrap};
use crate::raster::texture::{Filter, MAX_TEXEL_COORD, Texture};

/// A wrap mode the vector path can apply: `Mask(size - 1)` or `Clamp(size - 1)`.
#[derive(Clone, Copy)]
pub(in crate::raster::lanes) enum VecWrap {
    Mask(i32),
    Clamp(i32),
}

impl VecWrap {
    pub(in crate::raster::lanes) fn new(w: LaneWrap) -> Option<Self> {
        match w {
            LaneWrap::Mask(m) => Some(VecWrap::Mask(m)),
            LaneWrap::Clamp(hi) => Some(VecWrap::Clamp(hi)),
            LaneWrap::General(..) => None,
        }
    }
}

/// The texture's base level for vector lookups.
pub(in crate::raster::lanes) struct VecSampler<'a> {
    pub(in crate::raster::lanes) texels: &'a [[u8; 4]],
    pub(in crate::raster::lanes) width: i32,
    /// `log2(width)` when the width is a power of two (row offsets by a shift).
    pub(in crate::raster::lanes) width_shift: Option<i32>,
    pub(in crate::raster::lanes) size: (f32, f32),
    pub(in crate::raster::lanes) wrap: (VecWrap, VecWrap),
    pub(in crate::raster::lanes) filter: Filter,
    /// Every texel's alpha is 255 ([`Texture::is_opaque`]): bilinear filtering then skips
    /// the alpha sum, whose result is 255.
    pub(in crate::raster::lanes) opaque: bool,
}

impl<'a> VecSampler<'a> {
    /// `None` when a wrap mode needs the general (per-lane) path.
    pub(in crate::raster::lanes) fn new(
        texture: &'a Texture,
        shading: &LaneShading,
    ) -> Option<Self> {
        let (w, h) = (texture.width(), texture.height());
        Some(Self {
            texels: texture.base_texels(),
            width: w as i32,
            width_shift: w.is_power_of_two().then_some(w.trailing_zeros() as i32),
            size: (w as f32, h as f32),
            wrap: (
                VecWrap::new(LaneWrap::new(w, shading.wrap))?,
                VecWrap::new(LaneWrap::new(h, shading.wrap))?,
            ),
            filter: shading.filter,
            opaque: texture.is_opaque(),
        })
    }
}

/// `(floor(clamp(x)) as i32, floor(clamp(x)))` with NaN giving index 0, as `texel_floor`.
#[inline]
#[target_feature(enable = "avx2")]
pub(in crate::raster::lanes) fn floor_coord(x: __m256) -> (__m256i, __m256) {
    let ordered = _mm256_cmp_ps::<_CMP_ORD_Q>(x, x);
    let xc = _mm256_min_ps(
        _mm256_max_ps(x, _mm256_set1_ps(-MAX_TEXEL_COORD)),
        _mm256_set1_ps(MAX_TEXEL_COORD),
    );
    let f = _mm256_round_ps::<{ _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC }>(xc);
    let i = _mm256_and_si256(_mm256_cvttps_epi32(f), _mm256_castps_si256(ordered));
    (i, f)
}

/// `texture::bilinear_fraction`, mirrored: `clamp(x - floor, 0, 1)` where x is finite, else 0.
#[inline]
#[target_feature(enable = "avx2")]
pub(in crate::raster::lanes) fn fraction(x: __m256, floor: __m256) -> __m256 {
    let finite = _mm256_cmp_ps::<_CMP_EQ_OQ>(_mm256_sub_ps(x, x), _mm256_setzero_ps());
    let t = _mm256_min_ps(
        _mm256_max_ps(_mm256_sub_ps(x, floor), _mm256_setzero_ps()),
        _mm256_set1_ps(1.0),
    );
    _mm256_and_ps(t, finite)
}

/// Whether every lane of `x` is at least 0 and at most `MAX_TEXEL_COORD` (NaN is not): then
/// its floor is its truncation, an `i32`, so the index is one conversion of `x`, not of its
/// floor. The texel reads wait for the index, and the lookup's chain of dependent
/// instructions (coordinate, index, read, blend) is what bounds the lanes: the index no
/// longer waits for the floor instruction, which only the fraction needs (as in the portable
/// lanes' `index_fraction`).
#[inline]
#[target_feature(enable = "avx2")]
fn non_negative(x: __m256) -> bool {
    let at_least_zero = _mm256_cmp_ps::<_CMP_GE_OQ>(x, _mm256_setzero_ps());
    let at_most_max = _mm256_cmp_ps::<_CMP_LE_OQ>(x, _mm256_set1_ps(MAX_TEXEL_COORD));
    _mm256_movemask_ps(_mm256_and_ps(at_least_zero, at_most_max)) == 0xff
}

/// [`floor_coord`]'s index of eight coordinates: one conversion when they are
/// [`non_negative`], else [`floor_coord`].
#[inline]
#[target_feature(enable = "avx2")]
pub(in crate::raster::lanes) fn floor_index(x: __m256) -> __m256i {
    if non_negative(x) {
        _mm256_cvttps_epi32(x)
    } else {
        floor_coord(x).0
    }
}

/// [`floor_coord`]'s index and [`fraction`] of eight coordinates, the short way when every
/// lane is ordered and within +-`MAX_TEXEL_COORD`: then the clamps change nothing and
/// `x - floor(x)`, whose exact value is in [0, 1), rounds into [0, 1] (as the AVX-512 lanes'
/// `floor_and_fraction`, which has the argument): the floor, its conversion and a subtraction
/// where the general path takes thirteen operations; when they are also [`non_negative`], the
/// index from `x` itself. `tests` compare the short ways with the general one.
#[inline]
#[target_feature(enable = "avx2")]
pub(in crate::raster::lanes) fn floor_and_fraction(x: __m256) -> (__m256i, __m256) {
    if non_negative(x) {
        let f = _mm256_round_ps::<{ _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC }>(x);
        return (_mm256_cvttps_epi32(x), _mm256_sub_ps(x, f));
    }
    let magnitude = _mm256_andnot_ps(_mm256_set1_ps(-0.0), x);
    let inside = _mm256_cmp_ps::<_CMP_LE_OQ>(magnitude, _mm256_set1_ps(MAX_TEXEL_COORD));
    if _mm256_movemask_ps(inside) == 0xff {
        let f = _mm256_round_ps::<{ _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC }>(x);
        (_mm256_cvttps_epi32(f), _mm256_sub_ps(x, f))
    } else {
        let (i, f) = floor_coord(x);
        (i, fraction(x, f))
    }
}

#[inline]
#[target_feature(enable = "avx2")]
pub(in crate::raster::lanes) fn wrap(i: __m256i, w: VecWrap) -> __m256i {
    match w {
        VecWrap::Mask(m) => _mm256_and_si256(i, _mm256_set1_epi32(m)),
        VecWrap::Clamp(hi) => _mm256_min_epi32(
            _mm256_max_epi32(i, _mm256_setzero_si256()),
            _mm256_set1_epi32(hi),
        ),
    }
}

/// The texel index `j * width + i` of each lane (a shift when the width is a power of two).
#[inline]
#[target_feature(enable = "avx2")]
fn texel_index(s: &VecSampler<'_>, i: __m256i, j: __m256i) -> __m256i {
    let row = match s.width_shift {
        Some(k) => _mm256_sll_epi32(j, _mm_cvtsi32_si128(k)),
        None => _mm256_mullo_epi32(j, _mm256_set1_epi32(s.width)),
    };
    _mm256_add_epi32(row, i)
}

/// Eight texels at wrapped indices (each within the texture, so every read is in bounds).
#[inline]
#[target_feature(enable = "avx2")]
pub(in crate::raster::lanes) fn gather(s: &VecSampler<'_>, i: __m256i, j: __m256i) -> __m256i {
    let index = texel_index(s, i, j);
    debug_assert!(s.texels.len() <= i32::MAX as usize);
    // SAFETY: `wrap` put i in 0..width and j in 0..height, so every index is below
    // width * height = texels.len(); a texel is 4 bytes, read as one i32.
    unsafe { _mm256_i32gather_epi32::<4>(s.texels.as_ptr().cast::<i32>(), index) }
}

/// The texels at `(i, j)` and `(i + 1, j)` of eight lanes, each pair read as one 64-bit
/// element; every `i + 1` must be inside the row (a wrapped neighbour is not beside it).
#[inline]
#[target_feature(enable = "avx2")]
pub(in crate::raster::lanes) fn gather_pairs(
    s: &VecSampler<'_>,
    i: __m256i,
    j: __m256i,
) -> (__m256i, __m256i) {
    let index = texel_index(s, i, j);
    // SAFETY: i + 1 and j are inside the texture, so both texels of every pair are in
    // `texels` (one row, side by side); the 8 bytes are read unaligned as one i64.
    let (lo, hi) = unsafe {
        let p = s.texels.as_ptr().cast::<i64>();
        (
            _mm256_i32gather_epi64::<4>(p, _mm256_castsi256_si128(index)),
            _mm256_i32gather_epi64::<4>(p, _mm256_extracti128_si256::<1>(index)),
        )
    };
    // lo = (a0 b0 a1 b1 | a2 b2 a3 b3), hi = (a4 b4 a5 b5 | a6 b6 a7 b7).
    let (lo, hi) = (_mm256_castsi256_ps(lo), _mm256_castsi256_ps(hi));
    let a = _mm256_shuffle_ps::<0b10_00_10_00>(lo, hi); // a0 a1 a4 a5 | a2 a3 a6 a7
    let b = _mm256_shuffle_ps::<0b11_01_11_01>(lo, hi);
    (
        _mm256_permute4x64_epi64::<0b11_01_10_00>(_mm256_castps_si256(a)),
        _mm256_permute4x64_epi64::<0b11_01_10_00>(_mm256_castps_si256(b)),
    )
}

/// Channel `C` (0 = red) of eight packed texels, as f32 in 0..255: one byte shuffle moves
/// byte `C` of every texel to the bottom of its lane and zeroes the rest.
#[inline]
#[target_feature(enable = "avx2")]
pub(in crate::raster::lanes) fn channel<const C: i32>(t: __m256i) -> __m256 {
    let pick = |n: i32| (4 * n + C) | 0x8080_8000_u32 as i32;
    let mask = _mm256_setr_epi32(
        pick(0),
        pick(1),
        pick(2),
        pick(3),
        pick(0),
        pick(1),
        pick(2),
        pick(3),
    );
    _mm256_cvtepi32_ps(_mm256_shuffle_epi8(t, mask))
}

/// `byte_from_sum(x)` for a bilinear sum: `round(x)`, half away from zero. The clamp of the
/// scalar code changes nothing here: every weight is in [0, 1] and they add up to 1 (within
/// a few ulps), so the sum is in [0, 255.001] and never NaN. Two operations: the truncation
/// of `x + HALF_DOWN`, as the portable lanes round (`lanes::sampler::HALF_DOWN` has the
/// argument).
#[inline]
#[target_feature(enable = "avx2")]
pub(in crate::raster::lanes) fn byte_from_sum(y: __m256) -> __m256i {
    _mm256_cvttps_epi32(_mm256_add_ps(y, _mm256_set1_ps(HALF_DOWN)))
}

/// `sum_k weight_k * channel_k`, left to right.
#[inline]
#[target_feature(enable = "avx2")]
pub(in crate::raster::lanes) fn weighted<const C: i32>(
    weights: &[__m256; 4],
    texels: &[__m256i; 4],
) -> __m256i {
    let mut sum = _mm256_mul_ps(weights[0], channel::<C>(texels[0]));
    for k in 1..4 {
        sum = _mm256_add_ps(sum, _mm256_mul_ps(weights[k], channel::<C>(texels[k])));
    }
    byte_from_sum(sum)
}

/// The packed RGBA8 colours at eight uv, as `Texture::sample_rgba8` (`SITE`: one copy per
/// caller, see `Lookups::push`).
#[inline]
#[target_feature(enable = "avx2")]
pub(in crate::raster::lanes) fn sample<const SITE: u8, const WIDE: bool>(
    s: &VecSampler<'_>,
    u: __m256,
    v: __m256,
) -> __m256i {
    let (w, h) = (_mm256_set1_ps(s.size.0), _mm256_set1_ps(s.size.1));
    match s.filter {
        Filter::Nearest => {
            // One texel of weight 1: the colour is the texel (see the parent module).
            let i = wrap(floor_index(_mm256_mul_ps(u, w)), s.wrap.0);
            let j = wrap(floor_index(_mm256_mul_ps(v, h)), s.wrap.1);
            gather(s, i, j)
        }
        _ => {
            let half = _mm256_set1_ps(0.5);
            let x = _mm256_sub_ps(_mm256_mul_ps(u, w), half);
            let y = _mm256_sub_ps(_mm256_mul_ps(v, h), half);
            let (i0, a) = floor_and_fraction(x);
            let (j0, b) = floor_and_fraction(y);
            let one = _mm256_set1_epi32(1);
            let (ia, ib) = (
                wrap(i0, s.wrap.0),
                wrap(_mm256_add_epi32(i0, one), s.wrap.0),
            );
            let (ja, jb) = (
                wrap(j0, s.wrap.1),
                wrap(_mm256_add_epi32(j0, one), s.wrap.1),
            );
            let side_by_side = _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(
                ib,
                _mm256_add_epi32(ia, one),
            ))) == 0xff;
            let texels = if side_by_side {
                let (t00, t10) = gather_pairs(s, ia, ja);
                let (t01, t11) = gather_pairs(s, ia, jb);
                [t00, t10, t01, t11]
            } else {
                [
                    gather(s, ia, ja),
                    gather(s, ib, ja),
                    gather(s, ia, jb),
                    gather(s, ib, jb),
                ]
            };
            // `texture::bilinear_weights`, mirrored.
            let ones = _mm256_set1_ps(1.0);
            let (oa, ob) = (_mm256_sub_ps(ones, a), _mm256_sub_ps(ones, b));
            let weights = [
                _mm256_mul_ps(oa, ob),
                _mm256_mul_ps(a, ob),
                _mm256_mul_ps(oa, b),
                _mm256_mul_ps(a, b),
            ];
            let r = weighted::<0>(&weights, &texels);
            let g = weighted::<1>(&weights, &texels);
            let b = weighted::<2>(&weights, &texels);
            let a = if s.opaque {
                _mm256_set1_epi32(0xff)
            } else {
                weighted::<3>(&weights, &texels)
            };
            _mm256_or_si256(
                _mm256_or_si256(r, _mm256_slli_epi32::<8>(g)),
                _mm256_or_si256(_mm256_slli_epi32::<16>(b), _mm256_slli_epi32::<24>(a)),
            )
        }
    }
}
