//! Writing a chunk of eight lanes: the depth test, colour, and the uv or difference buffers.

use super::*;

/// Paints the wireframe over a chunk's colours and writes it, with `both_uv`
/// (`[u_affine, v_affine, u_smooth, v_smooth]`) into a target with uv or difference buffers
/// (The uvs are not part of [`Pending`]: a chunk waiting for its partner is moved, and
/// the smaller the better.) Always inlined: it runs once or twice per chunk, and a call
/// costs the dense meshes several percent.
///
/// # Safety
/// The CPU has AVX2, and AVX-512 F, BW, VL and DQ when `WIDE` (gathered chunks are then
/// written with scatters, `avx512::scatter::write_scatter`). Every lane of `chunk.valid` is a pixel
/// of the target band's row inside the image: for a row chunk, buffer indices
/// `chunk.index + k` below the length of the colour and depth buffers (and of the uv or
/// difference buffers the target has), as [`write`], [`store_uv`] and [`store_difference`]
/// require.
#[inline(always)]
pub(in crate::raster::lanes) unsafe fn finish<const WIDE: bool>(
    target: &mut Target<'_>,
    chunk: &Pending,
    rgba: __m256i,
    both_uv: Option<&[__m256; 4]>,
) {
    // SAFETY: here and below, the function's conditions: the CPU has AVX2 (and AVX-512 F,
    // BW, VL and DQ when `WIDE`), and `chunk.valid` enables only pixels inside the buffers
    // (so do `pass`'s lanes, a subset of them), as the writes require.
    let rgba = unsafe { paint_wire(chunk, rgba) };
    let pass = match chunk.lanes {
        // SAFETY: as above (`WIDE`: AVX-512).
        Some(at) if WIDE => unsafe {
            super::avx512::scatter::write_scatter(target, at, chunk.valid, chunk.depth, rgba)
        },
        // SAFETY: as above.
        Some(at) => unsafe { sparse::write(target, at, chunk.valid, chunk.depth, rgba) },
        // SAFETY: as above.
        None => unsafe { write(target, chunk.index, chunk.valid, chunk.depth, rgba) },
    };
    if let (Some(uv), Some(both)) = (target.uv.as_mut(), both_uv) {
        // SAFETY: as above.
        unsafe { store_uv(uv, chunk.index, pass, both) };
    }
    if let (Some(d), Some(both)) = (target.difference.as_mut(), both_uv) {
        // SAFETY: as above.
        unsafe { store_difference(d, chunk.index, pass, both) };
    }
}

/// A chunk's colours with the wireframe's halo, then its line, painted over them.
#[inline]
#[target_feature(enable = "avx2")]
fn paint_wire(chunk: &Pending, mut rgba: __m256i) -> __m256i {
    if chunk.halo != 0 {
        rgba = _mm256_blendv_epi8(
            rgba,
            _mm256_set1_epi32(i32::from_le_bytes(WIRE_HALO_COLOR)),
            mask_from_bits(chunk.halo),
        );
    }
    if chunk.wire != 0 {
        rgba = _mm256_blendv_epi8(
            rgba,
            _mm256_set1_epi32(i32::from_le_bytes(WIRE_COLOR)),
            mask_from_bits(chunk.wire),
        );
    }
    rgba
}

/// Writes the texel difference of the lanes in `pass` (eight pixels from buffer index
/// `index` of the band): `texture::square_texel_difference`'s operations, mirrored, then the
/// square root (IEEE `f32` operations, so bit for bit the scalar values).
///
/// # Safety
/// The CPU has AVX2. Every lane `k` enabled in `pass` has `index + k < d.out.len()` (the
/// masked store writes those elements and no other; checked, a panic otherwise).
#[inline]
#[target_feature(enable = "avx2")]
unsafe fn store_difference(
    d: &mut super::super::DifferenceTarget<'_>,
    index: usize,
    pass: __m256i,
    both: &[__m256; 4],
) {
    assert!(
        lanes_end(index, pass) <= d.out.len(),
        "difference lanes past the band"
    );
    let du = _mm256_mul_ps(_mm256_sub_ps(both[0], both[2]), _mm256_set1_ps(d.size[0]));
    let dv = _mm256_mul_ps(_mm256_sub_ps(both[1], both[3]), _mm256_set1_ps(d.size[1]));
    let len = _mm256_sqrt_ps(_mm256_add_ps(_mm256_mul_ps(du, du), _mm256_mul_ps(dv, dv)));
    // SAFETY: the function's condition: `pass` enables only lanes whose element is in
    // `d.out`; masked stores touch no other element.
    unsafe { _mm256_maskstore_ps(d.out.as_mut_ptr().add(index), pass, len) };
}

/// Writes the source triangle and both uvs of the lanes in `pass` (eight pixels from buffer
/// index `index` of the band): the uv pairs are interleaved in registers and stored with masks,
/// as `write` stores the colour.
///
/// # Safety
/// The CPU has AVX2. Every lane `k` enabled in `pass` has `index + k` below the length of
/// `uv.triangle`, `uv.uv_affine` and `uv.uv_perspective` (the masked stores write those
/// elements and no other; checked, a panic otherwise).
#[inline]
#[target_feature(enable = "avx2")]
unsafe fn store_uv(
    uv: &mut super::super::UvTarget<'_>,
    index: usize,
    pass: __m256i,
    both: &[__m256; 4],
) {
    assert!(
        lanes_end(index, pass) <= uv.triangle.len()
            && uv.triangle.len() == uv.uv_affine.len()
            && uv.triangle.len() == uv.uv_perspective.len(),
        "uv lanes past the band"
    );
    // Lane k's mask for both halves of its pair: (m0 m0 m1 m1 m2 m2 m3 m3), (m4 m4 ... m7 m7).
    let m_lo = _mm256_unpacklo_epi32(pass, pass);
    let m_hi = _mm256_unpackhi_epi32(pass, pass);
    let masks = [
        _mm256_permute2x128_si256::<0x20>(m_lo, m_hi),
        _mm256_permute2x128_si256::<0x31>(m_lo, m_hi),
    ];
    // (u0 v0 u1 v1 u2 v2 u3 v3), (u4 v4 ... u7 v7).
    let pairs = |u: __m256, v: __m256| {
        let lo = _mm256_unpacklo_ps(u, v);
        let hi = _mm256_unpackhi_ps(u, v);
        [
            _mm256_permute2f128_ps::<0x20>(lo, hi),
            _mm256_permute2f128_ps::<0x31>(lo, hi),
        ]
    };
    let affine = pairs(both[0], both[1]);
    let perspective = pairs(both[2], both[3]);
    // SAFETY: the function's condition: `pass` enables only lanes whose element
    // (`index + k`, its two floats) is inside the three buffers; masked stores touch no
    // other element.
    unsafe {
        _mm256_maskstore_epi32(
            uv.triangle.as_mut_ptr().add(index).cast::<i32>(),
            pass,
            _mm256_set1_epi32(uv.source as i32),
        );
        let a = uv.uv_affine.as_mut_ptr().add(index).cast::<f32>();
        let p = uv.uv_perspective.as_mut_ptr().add(index).cast::<f32>();
        for h in 0..2 {
            _mm256_maskstore_ps(a.add(8 * h), masks[h], affine[h]);
            _mm256_maskstore_ps(p.add(8 * h), masks[h], perspective[h]);
        }
    }
}

/// Depth-tests and writes eight pixels starting at buffer index `index` of the band; lanes
/// outside `ok` are neither read nor written. Returns the lanes that passed.
///
/// # Safety
/// The CPU has AVX2. Every lane `k` enabled in `ok` has `index + k` below the length of
/// `target.depth` and `target.color`; when all eight are enabled, all eight elements are read
/// and written (checked, a panic otherwise).
#[inline]
#[target_feature(enable = "avx2")]
unsafe fn write(
    target: &mut Target<'_>,
    index: usize,
    ok: __m256i,
    depth: __m256,
    rgba: __m256i,
) -> __m256i {
    assert!(
        lanes_end(index, ok) <= target.depth.len() && target.depth.len() == target.color.len(),
        "colour lanes past the band"
    );
    let dp = target.depth.as_mut_ptr().wrapping_add(index);
    let cp = target.color.as_mut_ptr().wrapping_add(index).cast::<i32>();
    if _mm256_movemask_ps(_mm256_castsi256_ps(ok)) == 0xff {
        // Every lane is a pixel of the band's row, which only this thread draws: plain
        // loads and stores of blended values (masked stores are slow on some CPUs).
        // SAFETY: here and in this branch's other loads and stores: all eight lanes are
        // enabled, so elements `index..index + 8` are in both slices (asserted above).
        let old = unsafe { _mm256_loadu_ps(dp) };
        let pass = _mm256_castps_si256(_mm256_cmp_ps::<_CMP_LT_OQ>(depth, old));
        let new = _mm256_blendv_ps(old, depth, _mm256_castsi256_ps(pass));
        // SAFETY: as above.
        unsafe { _mm256_storeu_ps(dp, new) };
        if target.difference.is_none() {
            // The old colours are read only when some lane keeps its own.
            let colour = if _mm256_movemask_ps(_mm256_castsi256_ps(pass)) == 0xff {
                rgba
            } else {
                // SAFETY: as above.
                _mm256_blendv_epi8(unsafe { _mm256_loadu_si256(cp.cast()) }, rgba, pass)
            };
            // SAFETY: as above.
            unsafe { _mm256_storeu_si256(cp.cast(), colour) };
        }
        return pass;
    }
    // SAFETY: here and in the masked stores below: every lane enabled in `ok` indexes both
    // slices (asserted above), and `pass` is a subset of `ok`; masked loads and stores touch
    // no other lane.
    let old = unsafe { _mm256_maskload_ps(dp, ok) };
    // `framebuffer::depth_passes`, mirrored: an ordered less-than (NaN fails).
    let pass = _mm256_and_si256(
        ok,
        _mm256_castps_si256(_mm256_cmp_ps::<_CMP_LT_OQ>(depth, old)),
    );
    // SAFETY: as above.
    unsafe { _mm256_maskstore_ps(dp, pass, depth) };
    // A difference target keeps the background colour (see `DifferenceTarget`).
    if target.difference.is_none() {
        // SAFETY: as above.
        unsafe { _mm256_maskstore_epi32(cp, pass, rgba) };
    }
    pass
}

/// One past the last buffer index the lanes enabled in `mask` touch, from buffer index
/// `index` (`index` itself when none is): the bound the masked stores are checked against.
#[inline]
#[target_feature(enable = "avx2")]
fn lanes_end(index: usize, mask: __m256i) -> usize {
    let bits = _mm256_movemask_ps(_mm256_castsi256_ps(mask)) as u32;
    index + (u32::BITS - bits.leading_zeros()) as usize
}

/// An eight-lane mask from the low eight bits of `bits`.
#[inline]
#[target_feature(enable = "avx2")]
pub(in crate::raster::lanes) fn mask_from_bits(bits: i32) -> __m256i {
    let b = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(bits), b), b)
}
