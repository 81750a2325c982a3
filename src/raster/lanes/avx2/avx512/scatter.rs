//! The AVX-512 writes of a gathered chunk (`avx2/sparse.rs`): the stored depths gathered, the
//! passing lanes scattered.

use std::arch::x86_64::*;

use super::super::super::Target;
use super::super::sparse;

/// [`sparse::write`] with AVX-512: the stored depths of the `ok` lanes gathered, compared with
/// [`depth_passes`](crate::raster::framebuffer::depth_passes)'s test (`<`, false for NaN), and the passing lanes' depth and colour
/// scattered. The lanes of a gathered chunk are distinct pixels of one triangle, so the
/// order of the writes does not matter and the result is [`sparse::write`]'s. A chunk with a lane
/// outside the band's buffers (never expected) goes to [`sparse::write`], which checks each one.
/// For CPUs with AVX-512 F and VL (the `WIDE` builds).
#[inline]
#[target_feature(enable = "avx2,avx512f,avx512vl")]
pub(in crate::raster::lanes) fn write_scatter(
    target: &mut Target<'_>,
    at: __m256i,
    ok: __m256i,
    depth: __m256,
    rgba: __m256i,
) -> __m256i {
    debug_assert!(target.uv.is_none() && target.difference.is_none());
    // Both buffers hold the band's pixels; a band is far below 2^31 pixels.
    let len = target
        .depth
        .len()
        .min(target.color.len())
        .min(i32::MAX as usize) as i32;
    let lanes = _mm256_cmplt_epi32_mask(ok, _mm256_setzero_si256());
    let inside = _mm256_mask_cmplt_epu32_mask(lanes, at, _mm256_set1_epi32(len));
    if inside != lanes {
        return sparse::write(target, at, ok, depth, rgba);
    }
    // SAFETY: every lane in `lanes` indexes both buffers (checked just above), and only
    // those lanes are read or written.
    unsafe {
        let old =
            _mm256_mmask_i32gather_ps::<4>(_mm256_setzero_ps(), lanes, at, target.depth.as_ptr());
        let pass = _mm256_mask_cmp_ps_mask::<_CMP_LT_OQ>(lanes, depth, old);
        _mm256_mask_i32scatter_ps::<4>(target.depth.as_mut_ptr(), pass, at, depth);
        _mm256_mask_i32scatter_epi32::<4>(target.color.as_mut_ptr().cast(), pass, at, rgba);
        _mm256_maskz_mov_epi32(pass, _mm256_set1_epi32(-1))
    }
}
