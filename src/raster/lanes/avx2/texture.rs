//! Texture lookups of eight lanes with AVX2: wrap, gather, bilinear weights, bytes.

use std::arch::x86_64::*;

use super::*;

/// Texture lookups of chunks: one at a time with AVX2, or two at a time with AVX-512. The
/// sampler is passed to each call, not kept: a reference parameter tells the compiler that
/// the pixel writes do not change it, so its filter and wrap are decided once per loop.
pub(in crate::raster::lanes) struct Lookups {
    wide: bool,
    pending: Option<Pending>,
}

impl Lookups {
    pub(in crate::raster::lanes) fn new(sampler: Option<&VecSampler<'_>>, wide: bool) -> Self {
        Self {
            // Measured: pairs pay for bilinear filtering (four lookups), not for nearest.
            wide: wide && sampler.is_some_and(|s| s.filter != Filter::Nearest),
            pending: None,
        }
    }

    /// Shades and writes `chunk`, now or together with the next one; with `both`
    /// (`[u_affine, v_affine, u_smooth, v_smooth]` for uv or difference buffers) always now,
    /// on its own (a chunk waiting for a partner carries no uvs).
    ///
    /// `SITE` makes each caller its own copy: a function with one call site is inlined
    /// whatever its size, and the texture lookups of a hot loop must be inlined into it
    /// (a call boundary between its gathers costs up to half the speed).
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(in crate::raster::lanes) fn push<const SITE: u8, const WIDE: bool>(
        &mut self,
        sampler: &VecSampler<'_>,
        target: &mut Target<'_>,
        chunk: Pending,
        both: Option<&[__m256; 4]>,
    ) {
        if !(WIDE && self.wide) || both.is_some() {
            let rgba = sample::<SITE, WIDE>(sampler, chunk.u, chunk.v);
            // SAFETY: this module runs with AVX2, and the chunk's valid lanes are pixels of the
            // band's row inside the image (`finish`'s conditions; every chunk is made so).
            unsafe { finish::<WIDE>(target, &chunk, rgba, both) };
            return;
        }
        match self.pending.take() {
            None => self.pending = Some(chunk),
            Some(first) => {
                // SAFETY: `wide` is set only when the CPU has AVX-512 F, BW, VL and DQ
                // (`VectorLevel::avx512`).
                let (a, b) = unsafe {
                    super::avx512::sample16(sampler, (first.u, first.v), (chunk.u, chunk.v))
                };
                // SAFETY: this module runs with AVX2, and the chunk's valid lanes are pixels of the
                // band's row inside the image (`finish`'s conditions; every chunk is made so).
                unsafe { finish::<WIDE>(target, &first, a, None) };
                // SAFETY: this module runs with AVX2, and the chunk's valid lanes are pixels of the
                // band's row inside the image (`finish`'s conditions; every chunk is made so).
                unsafe { finish::<WIDE>(target, &chunk, b, None) };
            }
        }
    }

    /// Shades and writes a chunk still waiting for a partner.
    #[target_feature(enable = "avx2")]
    pub(in crate::raster::lanes) fn flush(
        &mut self,
        sampler: Option<&VecSampler<'_>>,
        target: &mut Target<'_>,
    ) {
        if let (Some(chunk), Some(sampler)) = (self.pending.take(), sampler) {
            let rgba = sample::<{ u8::MAX }, false>(sampler, chunk.u, chunk.v);
            // SAFETY: this module runs with AVX2, and the chunk's valid lanes are pixels of the
            // band's row inside the image (`finish`'s conditions; every chunk is made so).
            unsafe { finish::<false>(target, &chunk, rgba, None) };
        }
    }
}
