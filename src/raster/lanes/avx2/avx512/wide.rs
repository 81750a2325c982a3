//! The edge-function lanes with the eight `f64` lanes of a chunk in one AVX-512 register:
//! the operations of `weights4` and `from_weights4!`, lane for lane, so the same values (tests
//! compare every vector build with the full render, bit for bit). Used for texture shading
//! without the wireframe or extra buffers, the common case, and for the difference view's
//! buffers, for row chunks
//! (gathered chunks keep the halves: measured slower on the dense meshes, more code for no
//! gain); the rest takes the two halves of four lanes.

use std::arch::x86_64::*;

use super::super::super::{Constants, LaneColor, Target};
use super::super::sampler::VecSampler;
use super::super::{Lookups, Pending, Where, finish, mask_from_bits};
use crate::raster::interpolate::Interpolation;
use crate::raster::setup::WeightPlanes;

/// Whether [`texture_chunk`] can draw a triangle's row chunks: texture shading without the
/// wireframe or any extra buffer, or the difference view's buffers (which shade nothing, so
/// neither colour nor wireframe matters there).
#[inline]
pub(in crate::raster::lanes) fn applies(
    consts: &Constants,
    color: LaneColor,
    sampler: Option<&VecSampler<'_>>,
    target: &Target<'_>,
) -> bool {
    target.uv.is_none()
        && match target.difference {
            Some(_) => consts.both_uv.is_some(),
            None => {
                color == LaneColor::Texture
                    && sampler.is_some()
                    && consts.wire.is_none()
                    && consts.both_uv.is_none()
            }
        }
}

/// `sum_i w_i x_i`, left to right, as `dot3`.
#[inline]
#[target_feature(enable = "avx512f")]
fn dot3(w: &[__m512d; 3], x: [f64; 3]) -> __m512d {
    let t = _mm512_add_pd(
        _mm512_mul_pd(w[0], _mm512_set1_pd(x[0])),
        _mm512_mul_pd(w[1], _mm512_set1_pd(x[1])),
    );
    _mm512_add_pd(t, _mm512_mul_pd(w[2], _mm512_set1_pd(x[2])))
}

/// The screen weights of the row chunk of eight pixels from window x `px` (pixel centres),
/// from the row terms `row`: `weights4`'s operations.
#[inline]
#[target_feature(enable = "avx512f")]
pub(in crate::raster::lanes) fn row_weights(
    w: &WeightPlanes,
    row: &[f64; 3],
    px: f64,
) -> [__m512d; 3] {
    let x = _mm512_add_pd(
        _mm512_set1_pd(px),
        _mm512_setr_pd(0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0),
    );
    // `(row - d_y (x - S_x)) * (1 / area2)`.
    [0, 1, 2].map(|i| {
        let dx = _mm512_sub_pd(x, _mm512_set1_pd(w.start[i].x));
        let t = _mm512_sub_pd(
            _mm512_set1_pd(row[i]),
            _mm512_mul_pd(_mm512_set1_pd(w.dir[i].y), dx),
        );
        _mm512_mul_pd(t, _mm512_set1_pd(w.inv_area2))
    })
}

/// Interpolates the `covered` ones of eight pixels from their screen weights `l` and hands
/// them to the texture lookups, which write them: `from_weights4!`'s operations. [`applies`]
/// must hold.
#[allow(clippy::too_many_arguments)]
#[inline]
#[target_feature(enable = "avx2,avx512f,avx512dq")]
pub(in crate::raster::lanes) fn texture_chunk<const SITE: u8, const WIDE: bool>(
    l: [__m512d; 3],
    consts: &Constants,
    covered: i32,
    at: Where,
    mode: Interpolation,
    sampler: Option<&VecSampler<'_>>,
    lookups: &mut Lookups,
    target: &mut Target<'_>,
) {
    // q_i = l_i / w_i, valid where their sum is positive and finite.
    let q = [0, 1, 2].map(|i| _mm512_mul_pd(l[i], _mm512_set1_pd(consts.inv_w[i])));
    let sum = _mm512_add_pd(_mm512_add_pd(q[0], q[1]), q[2]);
    let valid = _mm512_cmp_pd_mask::<_CMP_GT_OQ>(sum, _mm512_setzero_pd())
        & _mm512_cmp_pd_mask::<_CMP_LT_OQ>(sum, _mm512_set1_pd(f64::INFINITY));
    let ok = covered & i32::from(valid);
    if ok == 0 {
        return;
    }
    let (index, lanes) = at.parts();
    let mut chunk = Pending {
        u: _mm256_setzero_ps(),
        v: _mm256_setzero_ps(),
        depth: _mm512_cvtpd_ps(dot3(&l, consts.depth)),
        valid: mask_from_bits(ok),
        wire: 0,
        halo: 0,
        index,
        lanes,
    };
    let p = || {
        let inv = _mm512_div_pd(_mm512_set1_pd(1.0), sum);
        [0, 1, 2].map(|i| _mm512_mul_pd(q[i], inv))
    };
    if let (Some(b), Some(_)) = (&consts.both_uv, &target.difference) {
        // The difference view: both uvs, nothing shaded (see `DifferenceTarget`).
        let p = p();
        let both = [
            dot3(&l, b[0]),
            dot3(&l, b[1]),
            dot3(&p, b[2]),
            dot3(&p, b[3]),
        ]
        .map(|x| _mm512_cvtpd_ps(x));
        // SAFETY: this module runs with AVX2, and the chunk's valid lanes are pixels of the
        // band's row inside the image (`finish`'s conditions; every chunk is made so).
        unsafe { finish::<WIDE>(target, &chunk, _mm256_setzero_si256(), Some(&both)) };
        return;
    }
    let Some(sampler) = sampler else {
        return;
    };
    let weights = match mode {
        Interpolation::Perspective => p(),
        Interpolation::Affine => l,
    };
    chunk.u = _mm512_cvtpd_ps(dot3(&weights, consts.u));
    chunk.v = _mm512_cvtpd_ps(dot3(&weights, consts.v));
    lookups.push::<SITE, WIDE>(sampler, target, chunk, None);
}

/// Whether [`texture_pair`] can draw a triangle's rows: texture shading without the wireframe
/// or any extra buffer (not the difference view's).
#[inline]
pub(in crate::raster::lanes) fn pairs_apply(
    consts: &Constants,
    color: LaneColor,
    sampler: Option<&VecSampler<'_>>,
    target: &Target<'_>,
) -> bool {
    target.difference.is_none() && applies(consts, color, sampler, target)
}

/// The rows of a block inside the triangle (`in_row`: its columns within the bounds), from
/// column `bx`, in pairs ([`texture_pair`]); a last row without a partner is paired with
/// nothing (no lane of the second half enabled). [`pairs_apply`] must hold. Always inlined
/// into the edge-function lanes' block walk (a call there measured slower).
///
/// # Safety
/// The CPU has AVX2 and AVX-512 F, BW, VL and DQ.
#[inline(always)]
pub(in crate::raster::lanes) unsafe fn inside_block(
    consts: &Constants,
    (bx, in_row): (u32, i32),
    (by, by_end): (u32, u32),
    mode: Interpolation,
    sampler: &VecSampler<'_>,
    target: &mut Target<'_>,
) {
    let px = f64::from(bx) + 0.5;
    let w = &consts.weights;
    // (Written out: `array::map` of these closures was left as calls, a third slower.)
    let weights = |y: u32| {
        let py = f64::from(y) + 0.5;
        let row = [w.row_term(0, py), w.row_term(1, py), w.row_term(2, py)];
        // SAFETY: as the function's.
        unsafe { row_weights(w, &row, px) }
    };
    let (y0, width) = (target.y0, target.width as usize);
    let at = |y: u32| (y - y0) as usize * width + bx as usize;
    let mut y = by;
    while y <= by_end {
        let l = [weights(y), weights(y + 1)];
        let index = [at(y), at((y + 1).min(by_end))];
        let covered = [in_row, if y < by_end { in_row } else { 0 }];
        // SAFETY: as the function's.
        unsafe { texture_pair(l, consts, covered, index, mode, sampler, target) };
        y += 2;
    }
}

/// Two row chunks of eight pixels (rows `y` and `y + 1` of one block, screen weights `l[0]`
/// and `l[1]`, buffer indices `index`) drawn as one chunk of sixteen: each row gets
/// [`texture_chunk`]'s operations lane for lane, then one sixteen-lane texture lookup (the
/// lookup a pair of chunks gets in `Lookups`), and a masked depth test and write per row.
/// [`pairs_apply`] must hold.
#[inline]
#[target_feature(enable = "avx2,avx512f,avx512bw,avx512vl,avx512dq")]
pub(in crate::raster::lanes) fn texture_pair(
    l: [[__m512d; 3]; 2],
    consts: &Constants,
    covered: [i32; 2],
    index: [usize; 2],
    mode: Interpolation,
    sampler: &VecSampler<'_>,
    target: &mut Target<'_>,
) {
    let mut ok = 0u16;
    let mut u = [_mm256_setzero_ps(); 2];
    let mut v = [_mm256_setzero_ps(); 2];
    let mut depth = [_mm256_setzero_ps(); 2];
    for h in 0..2 {
        let l = &l[h];
        // q_i = l_i / w_i, valid where their sum is positive and finite.
        let q_i = |i: usize| _mm512_mul_pd(l[i], _mm512_set1_pd(consts.inv_w[i]));
        let q = [q_i(0), q_i(1), q_i(2)];
        let sum = _mm512_add_pd(_mm512_add_pd(q[0], q[1]), q[2]);
        let valid = _mm512_cmp_pd_mask::<_CMP_GT_OQ>(sum, _mm512_setzero_pd())
            & _mm512_cmp_pd_mask::<_CMP_LT_OQ>(sum, _mm512_set1_pd(f64::INFINITY));
        ok |= ((covered[h] as u16) & u16::from(valid) & 0xff) << (8 * h);
        depth[h] = _mm512_cvtpd_ps(dot3(l, consts.depth));
        let weights = match mode {
            Interpolation::Perspective => {
                let inv = _mm512_div_pd(_mm512_set1_pd(1.0), sum);
                [
                    _mm512_mul_pd(q[0], inv),
                    _mm512_mul_pd(q[1], inv),
                    _mm512_mul_pd(q[2], inv),
                ]
            }
            Interpolation::Affine => *l,
        };
        u[h] = _mm512_cvtpd_ps(dot3(&weights, consts.u));
        v[h] = _mm512_cvtpd_ps(dot3(&weights, consts.v));
    }
    if ok == 0 {
        return;
    }
    use super::{join, sample16_packed, write_rows};
    // SAFETY: this function is compiled with AVX-512 F and BW and AVX2.
    let rgba = unsafe { sample16_packed(sampler, join(u[0], u[1]), join(v[0], v[1])) };
    write_rows(target, index, ok, join(depth[0], depth[1]), rgba);
}
