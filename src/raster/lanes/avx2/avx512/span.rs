//! The writes of sixteen pixels and the scanline lanes' long texture spans with AVX-512:
//! [`wide_span`] and [`span16`] (two eight-pixel chunks at a time, each pixel with the AVX2
//! scanline lanes' values), [`write16`] and the edge-function row pairs' [`write_rows`].

use std::arch::x86_64::*;

use super::super::super::{LANES, Stepped, Target};
use super::super::sampler::VecSampler;
use super::{join, sample16_packed};
use crate::raster::interpolate::Interpolation;

/// The chunks of one span of texture shading with AVX-512 (into a band without uv or
/// difference buffers, as every scanline band is): the `f64` values of the span's first eight
/// pixels in one register each, and their increments over eight pixels, for
/// [`span16`], which draws the span sixteen pixels at a
/// time with the operations of `avx2::scanline`'s `stepped_chunk`, lane for lane, so the same values.
///
/// # Safety
/// The CPU has AVX2 and AVX-512 F, BW, VL and DQ, and columns `x0..=x1` of the band row
/// whose first pixel is buffer index `row` are inside the target's buffers.
#[inline]
#[target_feature(enable = "avx2,avx512f,avx512dq")]
pub(in crate::raster::lanes) unsafe fn wide_span(
    lanes: &[Stepped; LANES],
    step: &Stepped,
    (row, x0, x1): (usize, u32, u32),
    mode: Interpolation,
    sampler: &VecSampler<'_>,
    target: &mut Target<'_>,
) {
    debug_assert!(target.uv.is_none() && target.difference.is_none());
    let load = |f: fn(&Stepped) -> f64| {
        _mm512_setr_pd(
            f(&lanes[0]),
            f(&lanes[1]),
            f(&lanes[2]),
            f(&lanes[3]),
            f(&lanes[4]),
            f(&lanes[5]),
            f(&lanes[6]),
            f(&lanes[7]),
        )
    };
    let vals = [
        load(|s| s.u),
        load(|s| s.v),
        load(|s| s.inv_w),
        load(|s| s.depth),
    ];
    let n = LANES as f64;
    let step8 = [step.u * n, step.v * n, step.inv_w * n, step.depth * n].map(|x| _mm512_set1_pd(x));
    // SAFETY: as the function's: the CPU features, and the span `x0..=x1` of the band's row
    // `row` lies inside the image (`span16`'s conditions).
    unsafe { span16(vals, step8, (row, x0, x1), mode, sampler, target) };
}

/// The chunks of one span of texture shading (nearest or bilinear) in the scanline lanes,
/// sixteen pixels at a time, into a band without uv or difference buffers.
///
/// `vals` holds `[u/w, v/w, 1/w, depth]` of the span's first eight pixels (lane k: the
/// start after k single steps) and `step8` eight increments of each. Lanes 0..8 of a pair
/// are one eight-pixel chunk of the AVX2 scanline lanes (`avx2::scanline::stepped_chunk`'s
/// operations, lane for lane) and lanes 8..16 the next one, reached by the same additions of
/// `step8` in the same order, so every pixel gets the same values, the same colour (the same
/// lookup as [`sample16`]) and the same depth test (`framebuffer::depth_passes`: an ordered
/// less-than), written with masks.
///
/// # Safety
/// The CPU has the features enabled here, and columns `x0..=x1` of the band row whose first
/// pixel is buffer index `row` are inside the target's colour and depth buffers (the writes,
/// `write16`, check this only in debug builds).
#[target_feature(enable = "avx2,avx512f,avx512bw,avx512dq,avx512vl")]
pub(super) unsafe fn span16(
    vals: [__m512d; 4],
    step8: [__m512d; 4],
    (row, x0, x1): (usize, u32, u32),
    mode: Interpolation,
    sampler: &VecSampler<'_>,
    target: &mut Target<'_>,
) {
    // The lanes with a positive, finite 1/w (`stepped_chunk`'s test).
    let valid = |inv_w: __m512d| {
        _mm512_cmp_pd_mask::<_CMP_GT_OQ>(inv_w, _mm512_setzero_pd())
            & _mm512_cmp_pd_mask::<_CMP_LT_OQ>(inv_w, _mm512_set1_pd(f64::INFINITY))
    };
    // uv of eight lanes: `(u/w) * (1 / (1/w))` when perspective-correct.
    let uv = |q: &[__m512d; 4]| match mode {
        Interpolation::Perspective => {
            let w = _mm512_div_pd(_mm512_set1_pd(1.0), q[2]);
            (
                _mm512_cvtpd_ps(_mm512_mul_pd(q[0], w)),
                _mm512_cvtpd_ps(_mm512_mul_pd(q[1], w)),
            )
        }
        Interpolation::Affine => (_mm512_cvtpd_ps(q[0]), _mm512_cvtpd_ps(q[1])),
    };
    let advance = |q: &[__m512d; 4]| {
        [
            _mm512_add_pd(q[0], step8[0]),
            _mm512_add_pd(q[1], step8[1]),
            _mm512_add_pd(q[2], step8[2]),
            _mm512_add_pd(q[3], step8[3]),
        ]
    };
    // A pair's uv, depth and valid lanes from its two chunks' values.
    let pair = |vals: &[__m512d; 4]| {
        let next = advance(vals);
        let (u0, v0) = uv(vals);
        let (u1, v1) = uv(&next);
        let depth = join(_mm512_cvtpd_ps(vals[3]), _mm512_cvtpd_ps(next[3]));
        let valid = u16::from(valid(vals[2])) | u16::from(valid(next[2])) << 8;
        ((join(u0, u1), join(v0, v1), depth, valid), advance(&next))
    };
    let mut x = x0;
    let (mut made, mut vals) = pair(&vals);
    while x <= x1 {
        let ((u, v, depth, valid), ahead) = (made, vals);
        // The next pair's values (its divisions) before this pair's lookup, so the two
        // overlap.
        if x1 - x >= 16 {
            (made, vals) = pair(&ahead);
        }
        let left = x1 - x + 1;
        let span = if left >= 16 {
            u16::MAX
        } else {
            ((1u32 << left) - 1) as u16
        };
        let ok = span & valid;
        if ok != 0 {
            // SAFETY: the function's condition includes AVX-512 F and BW and AVX2.
            let rgba = unsafe { sample16_packed(sampler, u, v) };
            // SAFETY: `ok` enables only columns x..=x1 of the span, which lie in the band's
            // row `row` (the function's condition), so each index is in both buffers.
            unsafe { write16(target, row + x as usize, ok, depth, rgba) };
        }
        x += 16;
    }
}

/// Depth-tests and writes the lanes of `ok` among sixteen pixels from buffer index `index` of
/// a band without uv or difference buffers; other lanes are neither read nor written.
///
/// # Safety
/// The CPU has AVX-512 F. Every lane `k` enabled in `ok` has `index + k` below the length of
/// `target.depth` and `target.color` (checked, a panic otherwise).
#[inline]
#[target_feature(enable = "avx512f")]
unsafe fn write16(target: &mut Target<'_>, index: usize, ok: u16, depth: __m512, rgba: __m512i) {
    debug_assert!(target.uv.is_none() && target.difference.is_none());
    let end = index + (16 - ok.leading_zeros()) as usize;
    assert!(
        end <= target.depth.len() && target.depth.len() == target.color.len(),
        "colour lanes past the band"
    );
    // SAFETY: the function's condition: every lane enabled in `ok` indexes both slices;
    // masked loads and stores touch no other lane.
    unsafe {
        let dp = target.depth.as_mut_ptr().add(index);
        let cp = target.color.as_mut_ptr().add(index).cast::<i32>();
        let old = _mm512_maskz_loadu_ps(ok, dp);
        let pass = _mm512_mask_cmp_ps_mask::<_CMP_LT_OQ>(ok, depth, old);
        _mm512_mask_storeu_ps(dp, pass, depth);
        _mm512_mask_storeu_epi32(cp, pass, rgba);
    }
}

/// [`write16`] for two rows of eight pixels: lanes 0..8 from buffer index `index[0]`, lanes
/// 8..16 from `index[1]` (the edge-function lanes' row pairs, `avx2::wide::texture_pair`).
#[inline]
#[target_feature(enable = "avx512f,avx512vl,avx512dq")]
pub(super) fn write_rows(
    target: &mut Target<'_>,
    index: [usize; 2],
    ok: u16,
    depth: __m512,
    rgba: __m512i,
) {
    debug_assert!(target.uv.is_none() && target.difference.is_none());
    let depths = [
        _mm512_castps512_ps256(depth),
        _mm512_extractf32x8_ps::<1>(depth),
    ];
    let colours = [
        _mm512_castsi512_si256(rgba),
        _mm512_extracti64x4_epi64::<1>(rgba),
    ];
    for h in 0..2 {
        let k = (ok >> (8 * h)) as u8;
        if k == 0 {
            continue;
        }
        let end = index[h] + (8 - k.leading_zeros()) as usize;
        assert!(
            end <= target.depth.len() && target.depth.len() == target.color.len(),
            "colour lanes past the band"
        );
        // SAFETY: the caller's `ok` enables only pixels of the row inside the band, so every
        // accessed element `index[h] + k` is in both slices; masked loads and stores touch no
        // other lane.
        unsafe {
            let dp = target.depth.as_mut_ptr().add(index[h]);
            let cp = target.color.as_mut_ptr().add(index[h]).cast::<i32>();
            if k == 0xff {
                let old = _mm256_loadu_ps(dp);
                let pass = _mm256_cmp_ps_mask::<_CMP_LT_OQ>(depths[h], old);
                _mm256_storeu_ps(dp, _mm256_mask_blend_ps(pass, old, depths[h]));
                let c = if pass == 0xff {
                    colours[h]
                } else {
                    _mm256_mask_blend_epi32(pass, _mm256_loadu_si256(cp.cast()), colours[h])
                };
                _mm256_storeu_si256(cp.cast(), c);
                continue;
            }
            let old = _mm256_maskz_loadu_ps(k, dp);
            let pass = _mm256_mask_cmp_ps_mask::<_CMP_LT_OQ>(k, depths[h], old);
            _mm256_mask_storeu_ps(dp, pass, depths[h]);
            _mm256_mask_storeu_epi32(cp, pass, colours[h]);
        }
    }
}
