//! The edge-function lanes with the eight `f64` lanes of a chunk in one AVX-512 register:
//! the operations of `interp` and `from_planes4!`, lane for lane, so the same values (tests
//! compare every vector build with the full render, bit for bit). Used for texture shading
//! without the wireframe or extra buffers, the common case, and for the difference view's
//! buffers, for row chunks
//! (gathered chunks keep the halves: measured slower on the dense meshes, more code for no
//! gain); the rest takes the two halves of four lanes.

use std::arch::x86_64::*;

use super::super::super::{Constants, LaneColor, RowParts, Target};
use super::super::sampler::VecSampler;
use super::super::{Lookups, Pending, Where, finish, mask_from_bits};
use crate::raster::interpolate::Interpolation;
use crate::raster::setup::{ScreenPlane, WeightPlanes};

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
            Some(_) => consts.both_uv,
            None => {
                color == LaneColor::Texture
                    && sampler.is_some()
                    && consts.wire.is_none()
                    && !consts.both_uv
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

/// The weights' column terms of the row chunk of eight pixels from window x `px` (pixel
/// centres): `column_terms4`'s operations.
#[inline]
#[target_feature(enable = "avx512f")]
fn column_terms(w: &WeightPlanes, px: f64) -> [__m512d; 3] {
    let x = _mm512_add_pd(
        _mm512_set1_pd(px),
        _mm512_setr_pd(0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0),
    );
    // `d_y (x - S_x)`.
    [0, 1, 2].map(|i| {
        let dx = _mm512_sub_pd(x, _mm512_set1_pd(w.start[i].x));
        _mm512_mul_pd(_mm512_set1_pd(w.dir[i].y), dx)
    })
}

/// A plane's value from its row part and the column terms: `R - C` (`plane4`'s operations).
#[inline]
#[target_feature(enable = "avx512f")]
fn value(plane: &ScreenPlane, row: &[f64; 3], columns: &[__m512d; 3]) -> __m512d {
    _mm512_sub_pd(_mm512_set1_pd(plane.part(row)), dot3(columns, plane.k))
}

/// The lanes where `1/w` is positive and finite (valid).
#[inline]
#[target_feature(enable = "avx512f")]
fn valid(one_over_w: __m512d) -> u8 {
    _mm512_cmp_pd_mask::<_CMP_GT_OQ>(one_over_w, _mm512_setzero_pd())
        & _mm512_cmp_pd_mask::<_CMP_LT_OQ>(one_over_w, _mm512_set1_pd(f64::INFINITY))
}

/// `1 / (1/w)`.
#[inline]
#[target_feature(enable = "avx512f")]
fn inverse(one_over_w: __m512d) -> __m512d {
    _mm512_div_pd(_mm512_set1_pd(1.0), one_over_w)
}

/// Interpolates the `covered` ones of eight pixels of a row (its weights' row terms `row`,
/// the first pixel centre at window x `px`) and hands them to the texture lookups, which
/// write them: `from_planes4!`'s operations. [`applies`] must hold.
#[allow(clippy::too_many_arguments)]
#[inline]
#[target_feature(enable = "avx2,avx512f,avx512dq")]
pub(in crate::raster::lanes) fn texture_chunk<const SITE: u8, const WIDE: bool>(
    (row, px): (&[f64; 3], f64),
    consts: &Constants,
    covered: i32,
    at: Where,
    mode: Interpolation,
    sampler: Option<&VecSampler<'_>>,
    lookups: &mut Lookups,
    target: &mut Target<'_>,
) {
    let columns = column_terms(&consts.weights, px);
    let attrs = &consts.attrs;
    let one_over_w = value(&attrs.inv_w, row, &columns);
    let ok = covered & i32::from(valid(one_over_w));
    if ok == 0 {
        return;
    }
    let (index, lanes) = at.parts();
    let mut chunk = Pending {
        u: _mm256_setzero_ps(),
        v: _mm256_setzero_ps(),
        depth: _mm512_cvtpd_ps(value(&attrs.depth, row, &columns)),
        valid: mask_from_bits(ok),
        wire: 0,
        halo: 0,
        index,
        lanes,
    };
    if let (true, Some(_)) = (consts.both_uv, &target.difference) {
        // The difference view: both uvs, nothing shaded (see `DifferenceTarget`).
        let [ua, va] = attrs.uv_affine;
        let [us, vs] = attrs.uv_over_w;
        let inv = inverse(one_over_w);
        let smooth = |p: &ScreenPlane| _mm512_mul_pd(value(p, row, &columns), inv);
        let both = [
            value(&ua, row, &columns),
            value(&va, row, &columns),
            smooth(&us),
            smooth(&vs),
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
    let uv = consts.uv_planes(mode);
    let (u, v) = (value(&uv[0], row, &columns), value(&uv[1], row, &columns));
    let (u, v) = match mode {
        Interpolation::Perspective => {
            let inv = inverse(one_over_w);
            (_mm512_mul_pd(u, inv), _mm512_mul_pd(v, inv))
        }
        Interpolation::Affine => (u, v),
    };
    chunk.u = _mm512_cvtpd_ps(u);
    chunk.v = _mm512_cvtpd_ps(v);
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
    row_parts: &mut RowParts,
) {
    let w = &consts.weights;
    let attrs = consts.texture_planes(mode);
    // Each plane's column part: the same in all the block's rows.
    // SAFETY: as the function's.
    let parts = unsafe { column_parts(w, bx, &attrs) };
    let (y0, width) = (target.y0, target.width as usize);
    let at = |y: u32| (y - y0) as usize * width + bx as usize;
    let mut y = by;
    while y <= by_end {
        // A last row without a partner pairs with itself, none of its lanes enabled.
        let y1 = (y + 1).min(by_end);
        let rows = [row_parts.at(y, &attrs, w), row_parts.at(y1, &attrs, w)];
        let index = [at(y), at(y1)];
        let covered = [in_row, if y < by_end { in_row } else { 0 }];
        // SAFETY: as the function's.
        unsafe { texture_pair((&rows, &parts), covered, index, mode, sampler, target) };
        y += 2;
    }
}

/// The column parts of four planes at the eight columns from `bx` (pixel centres).
#[inline]
#[target_feature(enable = "avx512f")]
fn column_parts(w: &WeightPlanes, bx: u32, planes: &[ScreenPlane; 4]) -> [__m512d; 4] {
    let columns = column_terms(w, f64::from(bx) + 0.5);
    let mut parts = [_mm512_setzero_pd(); 4];
    for j in 0..4 {
        parts[j] = dot3(&columns, planes[j].k);
    }
    parts
}

/// Two row chunks of eight pixels (rows `y` and `y + 1` of one block: the row parts of the
/// planes `1/w`, depth and the mode's u and v in `rows`, their column parts in `columns`,
/// each value `R - C`; buffer indices `index`) drawn as
/// one chunk of sixteen: each row gets [`texture_chunk`]'s operations lane for lane, then
/// one sixteen-lane texture lookup (the lookup a pair of chunks gets in `Lookups`), and a
/// masked depth test and write per row. [`pairs_apply`] must hold.
#[inline]
#[target_feature(enable = "avx2,avx512f,avx512bw,avx512vl,avx512dq")]
pub(in crate::raster::lanes) fn texture_pair(
    (rows, columns): (&[[f64; 4]; 2], &[__m512d; 4]),
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
        let value = |j: usize| _mm512_sub_pd(_mm512_set1_pd(rows[h][j]), columns[j]);
        let [one_over_w, d, uh, vh] = [value(0), value(1), value(2), value(3)];
        ok |= ((covered[h] as u16) & u16::from(valid(one_over_w)) & 0xff) << (8 * h);
        depth[h] = _mm512_cvtpd_ps(d);
        let (uh, vh) = match mode {
            Interpolation::Perspective => {
                let inv = inverse(one_over_w);
                (_mm512_mul_pd(uh, inv), _mm512_mul_pd(vh, inv))
            }
            Interpolation::Affine => (uh, vh),
        };
        u[h] = _mm512_cvtpd_ps(uh);
        v[h] = _mm512_cvtpd_ps(vh);
    }
    if ok == 0 {
        return;
    }
    use super::{join, sample16_packed, write_rows};
    // SAFETY: this function is compiled with AVX-512 F and BW and AVX2.
    let rgba = unsafe { sample16_packed(sampler, join(u[0], u[1]), join(v[0], v[1])) };
    write_rows(target, index, ok, join(depth[0], depth[1]), rgba);
}
