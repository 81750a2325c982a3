//! The lane code that needs AVX-512 (F, BW, VL and DQ; used when the CPU has them): the
//! entry that compiles the `avx2/` bodies for AVX-512 ([`draw`]), the texture lookup of sixteen pixels
//! at once (two eight-pixel chunks) with the same operations in the same order as
//! `avx2::sample`, so the same bytes; the scanline lanes' long spans of texture shading
//! sixteen pixels at a time ([`span::span16`]), the edge-function lanes' row pairs' writes
//! ([`span::write_rows`]), the row chunks of `wide.rs` and the scattered writes of `scatter.rs`.

use std::arch::x86_64::*;

pub(super) mod scatter;
mod span;
pub(super) mod wide;

pub(in crate::raster::lanes) use span::wide_span;
use span::write_rows;

use super as avx2;
use super::super::{LaneShading, LaneTriangle, Target};
use super::sampler::{VecSampler, VecWrap};
use crate::raster::settings::Rasterizer;
use crate::raster::texture::{Filter, MAX_TEXEL_COORD};

/// The lanes of `avx2/` ([`avx2::draw`]) compiled for AVX-512: 32 vector registers, mask
/// registers; the edge functions' row chunks in one 512-bit register ([`wide`]), lookups of
/// sixteen pixels, the scanline lanes' long texture spans sixteen pixels at a time
/// ([`span::span16`]).
#[target_feature(enable = "avx2,avx512f,avx512bw,avx512vl,avx512dq")]
pub(in crate::raster::lanes) fn draw(
    rasterizer: Rasterizer,
    tri: &LaneTriangle,
    rows: (u32, u32),
    sampler: Option<&VecSampler<'_>>,
    shading: &LaneShading,
    target: &mut Target<'_>,
) {
    // SAFETY: this function is compiled with AVX2 and AVX-512 F, BW, VL and DQ (so the CPU
    // has them): the bodies' condition with `WIDE`.
    unsafe { avx2::draw_body::<true>(rasterizer, tri, rows, sampler, shading, target) }
}

/// `(floor(clamp(x)) as i32, floor(clamp(x)))` with NaN giving index 0, as `texel_floor`.
#[inline]
#[target_feature(enable = "avx512f")]
fn floor_coord(x: __m512) -> (__m512i, __m512) {
    let ordered = _mm512_cmp_ps_mask::<_CMP_ORD_Q>(x, x);
    let xc = _mm512_min_ps(
        _mm512_max_ps(x, _mm512_set1_ps(-MAX_TEXEL_COORD)),
        _mm512_set1_ps(MAX_TEXEL_COORD),
    );
    let f = _mm512_roundscale_ps::<{ _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC }>(xc);
    (_mm512_maskz_cvttps_epi32(ordered, f), f)
}

/// `texture::bilinear_fraction`, mirrored: `clamp(x - floor, 0, 1)` where x is finite, else 0.
#[inline]
#[target_feature(enable = "avx512f")]
fn fraction(x: __m512, floor: __m512) -> __m512 {
    let finite = _mm512_cmp_ps_mask::<_CMP_EQ_OQ>(_mm512_sub_ps(x, x), _mm512_setzero_ps());
    let t = _mm512_min_ps(
        _mm512_max_ps(_mm512_sub_ps(x, floor), _mm512_setzero_ps()),
        _mm512_set1_ps(1.0),
    );
    _mm512_maskz_mov_ps(finite, t)
}

/// Whether every lane of `x` is ordered and within +-`MAX_TEXEL_COORD` (one comparison of the
/// magnitudes, which fails for NaN): where [`floor_coord`]'s clamps change nothing.
#[inline]
#[target_feature(enable = "avx512f")]
fn all_in_range(x: __m512) -> bool {
    _mm512_cmp_ps_mask::<_CMP_LE_OQ>(_mm512_abs_ps(x), _mm512_set1_ps(MAX_TEXEL_COORD)) == 0xffff
}

/// [`floor_coord`]'s index and [`fraction`] of sixteen coordinates, the short way when every
/// lane is ordered and within +-`MAX_TEXEL_COORD` (a span's lanes almost always are): then the
/// clamps change nothing, `floor(x)` converts to and from `i32` exactly, and `x - floor(x)`,
/// whose exact value is in [0, 1), rounds into [0, 1], so its clamp changes nothing either:
/// three operations where the general path takes eleven, with the same results (`tests`
/// compare the two on random and edge-case floats).
#[inline]
#[target_feature(enable = "avx512f")]
fn floor_and_fraction(x: __m512) -> (__m512i, __m512) {
    if all_in_range(x) {
        let i = _mm512_cvt_roundps_epi32::<{ _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC }>(x);
        (i, _mm512_sub_ps(x, _mm512_cvtepi32_ps(i)))
    } else {
        let (i, f) = floor_coord(x);
        (i, fraction(x, f))
    }
}

/// [`floor_coord`]'s index of sixteen coordinates, the short way (one conversion rounding
/// down) when every lane is ordered and within +-`MAX_TEXEL_COORD`, as in
/// [`floor_and_fraction`].
#[inline]
#[target_feature(enable = "avx512f")]
fn floor_index(x: __m512) -> __m512i {
    if all_in_range(x) {
        _mm512_cvt_roundps_epi32::<{ _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC }>(x)
    } else {
        floor_coord(x).0
    }
}

#[inline]
#[target_feature(enable = "avx512f")]
fn wrap(i: __m512i, w: VecWrap) -> __m512i {
    match w {
        VecWrap::Mask(m) => _mm512_and_si512(i, _mm512_set1_epi32(m)),
        VecWrap::Clamp(hi) => _mm512_min_epi32(
            _mm512_max_epi32(i, _mm512_setzero_si512()),
            _mm512_set1_epi32(hi),
        ),
    }
}

/// [`wrap`] of one coordinate (the same mode, the same value as each lane of [`wrap`]).
#[inline]
fn wrap_one(i: i32, w: VecWrap) -> i32 {
    match w {
        VecWrap::Mask(m) => i & m,
        VecWrap::Clamp(hi) => i.clamp(0, hi),
    }
}

/// Whether `wrap(i + 1) = wrap(i) + 1` in every lane (each column's right neighbour beside it
/// in the row, not wrapped to its start nor clamped), from `i` and `ia = wrap(i)`: with a mask
/// `m`, where `i & m` is not `m` (there `(i + 1) & m` is `(i & m) + 1`, and at `m` it is 0);
/// clamped to `0..=hi`, where `0 <= i < hi` (below, both clamp to 0; from `hi` on, both to
/// `hi`). One comparison where wrapping `i + 1` and comparing take four.
#[inline]
#[target_feature(enable = "avx512f")]
fn all_beside(i: __m512i, ia: __m512i, w: VecWrap) -> bool {
    match w {
        VecWrap::Mask(m) => _mm512_cmpeq_epi32_mask(ia, _mm512_set1_epi32(m)) == 0,
        VecWrap::Clamp(hi) => _mm512_cmplt_epu32_mask(i, _mm512_set1_epi32(hi)) == 0xffff,
    }
}

/// The texel index `j * width + i` of each lane (a shift when the width is a power of two).
#[inline]
#[target_feature(enable = "avx512f")]
fn texel_index(s: &VecSampler<'_>, i: __m512i, j: __m512i) -> __m512i {
    let row = match s.width_shift {
        Some(k) => _mm512_sll_epi32(j, _mm_cvtsi32_si128(k)),
        None => _mm512_mullo_epi32(j, _mm512_set1_epi32(s.width)),
    };
    _mm512_add_epi32(row, i)
}

/// Sixteen texels at wrapped indices (each within the texture, so every read is in bounds).
#[inline]
#[target_feature(enable = "avx512f")]
fn gather(s: &VecSampler<'_>, i: __m512i, j: __m512i) -> __m512i {
    let index = texel_index(s, i, j);
    // SAFETY: `wrap` put i in 0..width and j in 0..height, so every index is below
    // width * height = texels.len(); a texel is 4 bytes, read as one i32.
    unsafe { _mm512_i32gather_epi32::<4>(index, s.texels.as_ptr().cast::<i32>()) }
}

/// The texels at `(i, j)` and `(i + 1, j)` of sixteen lanes, each pair read as one 64-bit
/// element (`avx2::gather_pairs`); every `i + 1` must be inside the row.
#[inline]
#[target_feature(enable = "avx512f")]
fn gather_pairs(s: &VecSampler<'_>, i: __m512i, j: __m512i) -> (__m512i, __m512i) {
    let index = texel_index(s, i, j);
    // SAFETY: i + 1 and j are inside the texture, so both texels of every pair are in
    // `texels` (one row, side by side); the 8 bytes are read unaligned as one i64.
    let (lo, hi) = unsafe {
        let p = s.texels.as_ptr().cast::<i64>();
        (
            _mm512_i32gather_epi64::<4>(_mm512_castsi512_si256(index), p),
            _mm512_i32gather_epi64::<4>(_mm512_extracti64x4_epi64::<1>(index), p),
        )
    };
    // lo = (a0 b0 a1 b1 ... a7 b7), hi = (a8 b8 ... a15 b15).
    let even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
    let odd = _mm512_add_epi32(even, _mm512_set1_epi32(1));
    (
        _mm512_permutex2var_epi32(lo, even, hi),
        _mm512_permutex2var_epi32(lo, odd, hi),
    )
}

/// The columns `i` of sixteen lanes as offsets from the smallest, `(i0, i - i0)`, when every
/// offset is at most `max` (the lanes read within a window of texels of one row); `None`
/// otherwise.
#[inline]
#[target_feature(enable = "avx512f")]
fn column_offsets(i: __m512i, max: i32) -> Option<(i32, __m512i)> {
    let max = _mm512_set1_epi32(max);
    // First the first lane: the smallest wherever the columns grow along the lanes, as along
    // most spans, and two operations sooner than the next try (the reads wait for the
    // window's start: alternating A/B, the AVX-512 scanline bilinear quad 1.5-2% faster).
    // Any lane below it gives an offset that is huge unsigned, so the check declines rather
    // than misleads.
    let d = _mm512_sub_epi32(i, _mm512_broadcastd_epi32(_mm512_castsi512_si128(i)));
    if _mm512_cmpgt_epu32_mask(d, max) == 0 {
        return Some((lane0(i), d));
    }
    // Then the smaller of the first and last lanes (three operations; the smallest lane
    // wherever the columns run one way along the lanes, as along a span).
    let ends = _mm512_min_epi32(i, _mm512_alignr_epi32::<15>(i, i));
    let d = _mm512_sub_epi32(i, _mm512_broadcastd_epi32(_mm512_castsi512_si128(ends)));
    if _mm512_cmpgt_epu32_mask(d, max) == 0 {
        return Some((lane0(ends), d));
    }
    let i0 = _mm512_reduce_min_epi32(i);
    let d = _mm512_sub_epi32(i, _mm512_set1_epi32(i0));
    (_mm512_cmpgt_epu32_mask(d, max) == 0).then_some((i0, d))
}

/// The 32 texels from texel `(i0, j)` on (row-major), in two registers; `None` when they would
/// run past the texture's end. `i0` and `j` must be wrapped (inside the texture).
#[inline]
#[target_feature(enable = "avx512f")]
fn texel_window(s: &VecSampler<'_>, i0: i32, j: i32) -> Option<(__m512i, __m512i)> {
    // Wrapped indices: not negative.
    let at = j as usize * s.width as usize + i0 as usize;
    if at + 32 > s.texels.len() {
        return None;
    }
    // SAFETY: texels at..at + 32 are inside `texels` (checked just above); a texel is 4
    // bytes, read as one i32.
    Some(unsafe {
        let p = s.texels.as_ptr().cast::<i32>().add(at);
        (
            _mm512_loadu_si512(p.cast()),
            _mm512_loadu_si512(p.add(16).cast()),
        )
    })
}

/// The first lane of `v`.
#[inline]
#[target_feature(enable = "avx512f")]
fn lane0(v: __m512i) -> i32 {
    _mm_cvtsi128_si32(_mm512_castsi512_si128(v))
}

/// The texels `(i, ja)`, `(i + 1, ja)`, `(i, jb)` and `(i + 1, jb)` of sixteen lanes whose
/// row `j` (before wrapping; `ja` and `jb` are the wraps of `j` and `j + 1`, made here) is the
/// same in every lane and whose columns `i` (wrapped) lie within 30 of
/// the smallest (a row of a magnified or mildly minified texture): picked from 32
/// consecutive texels of each row, read with two plain loads, instead of gathered. `None`
/// when the lanes do not qualify (or the 32 texels would run past the texture's end). Every
/// `i + 1` must be inside the row, as for [`gather_pairs`]; then the picked texels are the
/// gathered ones.
#[inline]
#[target_feature(enable = "avx512f")]
fn row_blocks(s: &VecSampler<'_>, i: __m512i, j: __m512i) -> Option<[__m512i; 4]> {
    // One row `j` in every lane (before wrapping) makes its wraps `ja` and `jb` one row each,
    // wrapped once.
    if _mm512_cmpneq_epi32_mask(j, _mm512_broadcastd_epi32(_mm512_castsi512_si128(j))) != 0 {
        return None;
    }
    // A floor within +-MAX_TEXEL_COORD: `j + 1` does not overflow.
    let j = lane0(j);
    let (j0, j1) = (wrap_one(j, s.wrap.1), wrap_one(j + 1, s.wrap.1));
    let (i0, d) = column_offsets(i, 30)?;
    let (a_lo, a_hi) = texel_window(s, i0, j0)?;
    let (b_lo, b_hi) = texel_window(s, i0, j1)?;
    let d1 = _mm512_add_epi32(d, _mm512_set1_epi32(1));
    Some([
        _mm512_permutex2var_epi32(a_lo, d, a_hi),
        _mm512_permutex2var_epi32(a_lo, d1, a_hi),
        _mm512_permutex2var_epi32(b_lo, d, b_hi),
        _mm512_permutex2var_epi32(b_lo, d1, b_hi),
    ])
}

/// The texels `(i, j)` of sixteen lanes whose row `j` is the same in lanes 0..8 and the same
/// in lanes 8..16 (a span's sixteen pixels, or two rows of eight, of a magnified or mildly
/// minified texture) and whose columns `i` lie within 31 of the smallest: picked from 32
/// consecutive texels of each of the (one or two) rows, read with plain loads, instead of
/// gathered (as [`row_blocks`] does for bilinear). `None` when the lanes do not qualify (or
/// the 32 texels would run past the texture's end). Every index must be wrapped (inside the
/// texture); then the picked texels are the gathered ones.
#[inline]
#[target_feature(enable = "avx512f")]
fn row_block(s: &VecSampler<'_>, i: __m512i, j: __m512i) -> Option<__m512i> {
    /// Lanes 8..16.
    const HIGH: __mmask16 = 0xff00;
    let (j0, j1) = (
        lane0(j),
        _mm_cvtsi128_si32(_mm512_extracti32x4_epi32::<2>(j)),
    );
    let rows = _mm512_mask_set1_epi32(_mm512_set1_epi32(j0), HIGH, j1);
    if _mm512_cmpneq_epi32_mask(j, rows) != 0 {
        return None;
    }
    let (i0, d) = column_offsets(i, 31)?;
    let (lo, hi) = texel_window(s, i0, j0)?;
    let first = _mm512_permutex2var_epi32(lo, d, hi);
    if j0 == j1 {
        return Some(first);
    }
    let (lo, hi) = texel_window(s, i0, j1)?;
    let second = _mm512_permutex2var_epi32(lo, d, hi);
    Some(_mm512_mask_blend_epi32(HIGH, first, second))
}

/// Channel `C` (0 = red) of sixteen packed texels, as f32 in 0..255.
#[inline]
#[target_feature(enable = "avx512f,avx512bw")]
fn channel<const C: i32>(t: __m512i) -> __m512 {
    let pick = |n: i32| (4 * n + C) | 0x8080_8000_u32 as i32;
    let mask = _mm512_setr_epi32(
        pick(0),
        pick(1),
        pick(2),
        pick(3),
        pick(0),
        pick(1),
        pick(2),
        pick(3),
        pick(0),
        pick(1),
        pick(2),
        pick(3),
        pick(0),
        pick(1),
        pick(2),
        pick(3),
    );
    _mm512_cvtepi32_ps(_mm512_shuffle_epi8(t, mask))
}

/// `round(x)` half away from zero for a bilinear sum in [0, 255.001] (see `avx2`), as
/// `floor(x + 1/2)` with the addition rounded toward zero (AVX-512's embedded rounding): two
/// operations where `avx2` needs six.
///
/// Exact for every `x` in [0, 2^22): where `x >= 1/2`, 1/2 is a whole number of `x`'s ulps, so
/// `x + 1/2` is exact unless it reaches the next power of two `p`; then the true sum is in
/// [p, p + 1/2) and rounding toward zero keeps it there, so the floor is `p`, which is also
/// `round(x)` for `x` in [p - 1/2, p). Where `x < 1/2`, `x + 1/2 < 1` rounds toward zero to
/// below 1 and the floor is 0 (rounding to nearest would give 1 for the largest two floats below
/// 1/2). A tie `k + 1/2` gives `k + 1` exactly, away from zero. `tests` check every float in
/// [0, 255.001] against `texture::byte_from_sum`.
#[inline]
#[target_feature(enable = "avx512f")]
fn byte_from_sum(y: __m512) -> __m512i {
    round_in_place::<0>(y)
}

/// `texture::bilinear_weights`, mirrored: `[(1 - a)(1 - b), a (1 - b), (1 - a) b, a b]` of
/// sixteen lanes' fractions `a` (across) and `b` (down).
#[inline]
#[target_feature(enable = "avx512f")]
fn bilinear_weights(a: __m512, b: __m512) -> [__m512; 4] {
    let ones = _mm512_set1_ps(1.0);
    let (oa, ob) = (_mm512_sub_ps(ones, a), _mm512_sub_ps(ones, b));
    [
        _mm512_mul_ps(oa, ob),
        _mm512_mul_ps(a, ob),
        _mm512_mul_ps(oa, b),
        _mm512_mul_ps(a, b),
    ]
}

/// `sum_k weight_k * channel_k`, left to right, rounded to a byte.
#[inline]
#[target_feature(enable = "avx512f,avx512bw")]
fn weighted<const C: i32>(weights: &[__m512; 4], texels: &[__m512i; 4]) -> __m512i {
    let mut sum = _mm512_mul_ps(weights[0], channel::<C>(texels[0]));
    for k in 1..4 {
        sum = _mm512_add_ps(sum, _mm512_mul_ps(weights[k], channel::<C>(texels[k])));
    }
    byte_from_sum(sum)
}

/// [`weighted`] for channel `C` of 0, 1 or 2 computed on the channel's bits where they lie,
/// `2^(8C)` times the byte (an `and` per texel where [`channel`] takes a shuffle, which only one
/// port runs, and no shift to pack): the result's bits `8C..8C + 8` are the rounded byte, the
/// bits above are zero and the bits below arbitrary.
///
/// The same byte: a channel in place is `2^(8C) c` exactly (below 2^24), and every product, sum
/// and the addition of `2^(8C) / 2` is `2^(8C)` times [`weighted`]'s, exactly, since scaling by a
/// power of two commutes with rounding (toward nearest or zero) for normal floats far from the
/// largest (a bilinear fraction of a coordinate `u w - 1/2` is 0 or at least 2^-26, so the
/// values are 0 or at least about 2^-52, and at most 2^24). So the floor is
/// `floor(2^(8C) t)` for [`weighted`]'s `t`, whose bits from `8C` on are `floor(t)`, the byte
/// (`t` in [1/2, 256)). `tests` compare the packed colours of the two on random texels and
/// weights.
#[inline]
#[target_feature(enable = "avx512f")]
fn weighted_in_place<const C: i32>(weights: &[__m512; 4], texels: &[__m512i; 4]) -> __m512i {
    let bits = _mm512_set1_epi32(0xff << (8 * C));
    let channel = |t: __m512i| _mm512_cvtepi32_ps(_mm512_and_si512(t, bits));
    let mut sum = _mm512_mul_ps(weights[0], channel(texels[0]));
    for k in 1..4 {
        sum = _mm512_add_ps(sum, _mm512_mul_ps(weights[k], channel(texels[k])));
    }
    round_in_place::<C>(sum)
}

/// [`byte_from_sum`] of `2^(8C)` times a sum: `floor(y + 2^(8C) / 2)` with the addition
/// rounded toward zero, `2^(8C)` times [`byte_from_sum`]'s `t` exactly, so its bits from `8C`
/// on are the byte (`tests` check every float of [0, 255.001], scaled).
#[inline]
#[target_feature(enable = "avx512f")]
fn round_in_place<const C: i32>(y: __m512) -> __m512i {
    let half = _mm512_set1_ps(0.5 * (1 << (8 * C)) as f32);
    let t = _mm512_add_round_ps::<{ _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC }>(y, half);
    _mm512_cvt_roundps_epi32::<{ _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC }>(t)
}

/// The packed colour of [`weighted_in_place`]'s red, green and blue and the bytes `alpha`:
/// bitwise selections keep each channel's own bits.
#[inline]
#[target_feature(enable = "avx512f")]
fn pack_in_place(r: __m512i, g: __m512i, b: __m512i, alpha: __m512i) -> __m512i {
    /// `ternarylogic` table of `a ? b : c` (bitwise).
    const SELECT: i32 = 0xca;
    let gb = _mm512_ternarylogic_epi32::<SELECT>(_mm512_set1_epi32(0xffff_0000_u32 as i32), b, g);
    let rgb = _mm512_ternarylogic_epi32::<SELECT>(_mm512_set1_epi32(0xff), r, gb);
    _mm512_or_si512(rgb, _mm512_slli_epi32::<24>(alpha))
}

/// Two halves of eight `f32` lanes as one register of sixteen (`lo` in lanes 0..8).
#[inline]
#[target_feature(enable = "avx512f")]
pub(super) fn join(lo: __m256, hi: __m256) -> __m512 {
    _mm512_castsi512_ps(_mm512_inserti64x4::<1>(
        _mm512_castsi256_si512(_mm256_castps_si256(lo)),
        _mm256_castps_si256(hi),
    ))
}

/// The packed RGBA8 colours at sixteen uv (lanes 0..8 from `first`, 8..16 from `second`),
/// as `avx2::sample` gives them for each half.
#[target_feature(enable = "avx512f,avx512bw,avx2")]
pub(super) fn sample16(
    s: &VecSampler<'_>,
    (u0, v0): (__m256, __m256),
    (u1, v1): (__m256, __m256),
) -> (__m256i, __m256i) {
    // SAFETY: this function is compiled with AVX-512 F and BW and AVX2.
    let packed = unsafe { sample16_packed(s, join(u0, u1), join(v0, v1)) };
    (
        _mm512_castsi512_si256(packed),
        _mm512_extracti64x4_epi64::<1>(packed),
    )
}

/// The packed RGBA8 colours at sixteen uv, as `avx2::sample` gives them for each half.
///
/// Always inlined, without a target feature of its own, so the nearest lookup (a few
/// operations and one gather) is part of its caller: as a call, its vectors went through
/// memory both ways. The bilinear lookup stays a call ([`sample16_bilinear`]).
///
/// # Safety
/// The CPU has AVX-512 F and BW, and AVX2.
#[inline(always)]
pub(super) unsafe fn sample16_packed(s: &VecSampler<'_>, u: __m512, v: __m512) -> __m512i {
    // SAFETY: the function's condition is what these need.
    unsafe {
        match s.filter {
            Filter::Nearest => {
                let (w, h) = (_mm512_set1_ps(s.size.0), _mm512_set1_ps(s.size.1));
                let i = wrap(floor_index(_mm512_mul_ps(u, w)), s.wrap.0);
                let j = wrap(floor_index(_mm512_mul_ps(v, h)), s.wrap.1);
                match row_block(s, i, j) {
                    Some(t) => t,
                    None => gather(s, i, j),
                }
            }
            _ => sample16_bilinear(s, u, v),
        }
    }
}

/// [`sample16_packed`] for the bilinear filter (any filter but nearest).
///
/// Always inlined, without a target feature of its own, as [`sample16_packed`]: as a call,
/// its result went back through memory (the return measured a tenth of the function's time
/// in the scanline quad).
///
/// # Safety
/// The CPU has AVX-512 F and BW, and AVX2.
#[inline(always)]
unsafe fn sample16_bilinear(s: &VecSampler<'_>, u: __m512, v: __m512) -> __m512i {
    // SAFETY: the function's condition is what these need.
    unsafe {
        let (w, h) = (_mm512_set1_ps(s.size.0), _mm512_set1_ps(s.size.1));
        let half = _mm512_set1_ps(0.5);
        let x = _mm512_sub_ps(_mm512_mul_ps(u, w), half);
        let y = _mm512_sub_ps(_mm512_mul_ps(v, h), half);
        let (i0, a) = floor_and_fraction(x);
        let (j0, b) = floor_and_fraction(y);
        let ia = wrap(i0, s.wrap.0);
        let side_by_side = all_beside(i0, ia, s.wrap.0);
        let blocks = if side_by_side {
            row_blocks(s, ia, j0)
        } else {
            None
        };
        let texels = match blocks {
            Some(t) => t,
            None => {
                let one = _mm512_set1_epi32(1);
                let ib = wrap(_mm512_add_epi32(i0, one), s.wrap.0);
                let (ja, jb) = (
                    wrap(j0, s.wrap.1),
                    wrap(_mm512_add_epi32(j0, one), s.wrap.1),
                );
                if side_by_side {
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
                }
            }
        };
        let weights = bilinear_weights(a, b);
        let r = weighted_in_place::<0>(&weights, &texels);
        let g = weighted_in_place::<1>(&weights, &texels);
        let b = weighted_in_place::<2>(&weights, &texels);
        let a = if s.opaque {
            _mm512_set1_epi32(0xff)
        } else {
            weighted::<3>(&weights, &texels)
        };
        pack_in_place(r, g, b, a)
    }
}

#[cfg(test)]
mod tests;
