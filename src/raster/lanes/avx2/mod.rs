//! The lane paths written with AVX2 intrinsics: the same operations in the same order as
//! the scalar lane code in the parent module (and so as the per-pixel renderer), eight
//! pixels per instruction. Chosen at run time when the CPU has AVX2 and the texture's wrap
//! is a mask or a clamp on both axes; tests check the two agree bit for bit. The bodies are
//! generic over `WIDE`: the subfolder `avx512/` (code that needs AVX-512 as well) compiles them
//! again for AVX-512.
//! The interpolation of a chunk (the planes' values, `from_planes4!`) is in `interp.rs`, the
//! texture lookups in `texture.rs` (through the sampler of `sampler.rs`), the writes of a
//! chunk in `write.rs`, the non-texture colours in `shade.rs`, the gathering of sparse rows in
//! `sparse.rs` and the scanline lanes in `scanline.rs`.

use std::arch::x86_64::*;

use super::blocks::{RowParts, classify};
use super::{
    BLOCK_ROWS, Block, CHANNELS, Constants, LANES, LaneColor, LaneShading, LaneTriangle, Stepped,
    Target,
};
use crate::raster::interpolate::Interpolation;
use crate::raster::scanline::row_span_of;
use crate::raster::settings::Rasterizer;
use crate::raster::shade::{
    AMBIENT, MIN_NORMAL_LENGTH, WIRE_COLOR, WIRE_HALO_COLOR, WIRE_HALO_PX, WIRE_WIDTH_PX,
};
use crate::raster::texture::Filter;

#[macro_use]
mod interp;
pub(in crate::raster::lanes) mod avx512;
pub(super) mod sampler;
mod scanline;
mod shade;
pub(in crate::raster::lanes) mod sparse;
mod texture;
mod write;

use scanline::scanline_triangle_body;
use shade::channel_colors;
pub(in crate::raster::lanes) use texture::Lookups;
pub(in crate::raster::lanes) use write::{finish, mask_from_bits};

use avx512::wide;
use interp::{At4, BlockColumns, Four};
use sampler::{VecSampler, sample};

/// A chunk of eight pixels whose colours are still to be looked up.
pub(in crate::raster::lanes) struct Pending {
    pub(in crate::raster::lanes) u: __m256,
    pub(in crate::raster::lanes) v: __m256,
    pub(in crate::raster::lanes) depth: __m256,
    /// Lanes to write.
    pub(in crate::raster::lanes) valid: __m256i,
    /// Lanes on a wireframe line.
    pub(in crate::raster::lanes) wire: i32,
    /// Lanes in the wireframe's halo (the line wins where both are set).
    pub(in crate::raster::lanes) halo: i32,
    /// Buffer index of lane 0 (a row chunk: eight pixels side by side).
    pub(in crate::raster::lanes) index: usize,
    /// Buffer index of each lane instead, for a chunk gathered from several rows
    /// ([`sparse`]).
    pub(in crate::raster::lanes) lanes: Option<__m256i>,
}

/// Two halves of four `f64` lanes converted to eight `f32` lanes.
#[inline]
#[target_feature(enable = "avx2")]
fn to_f32(lo: __m256d, hi: __m256d) -> __m256 {
    _mm256_set_m128(_mm256_cvtpd_ps(hi), _mm256_cvtpd_ps(lo))
}

/// `sum_i w_i x_i`, left to right, as the scalar code adds.
#[inline]
#[target_feature(enable = "avx2")]
fn dot3(w: &[__m256d; 3], x: [f64; 3]) -> __m256d {
    let t = _mm256_add_pd(
        _mm256_mul_pd(w[0], _mm256_set1_pd(x[0])),
        _mm256_mul_pd(w[1], _mm256_set1_pd(x[1])),
    );
    _mm256_add_pd(t, _mm256_mul_pd(w[2], _mm256_set1_pd(x[2])))
}

/// Draws rows `rows` of `tri` with the lanes of `rasterizer` (see the parent module): every
/// [`LaneColor`], with the wireframe on the edge-function path. The same bodies are compiled
/// for AVX-512 in `avx512/` ([`draw_body`]).
#[target_feature(enable = "avx2")]
pub(super) fn draw(
    rasterizer: Rasterizer,
    tri: &LaneTriangle,
    rows: (u32, u32),
    sampler: Option<&VecSampler<'_>>,
    shading: &LaneShading,
    target: &mut Target<'_>,
) {
    // SAFETY: this function is compiled with AVX2 (so the CPU has it), and `WIDE` is false:
    // the bodies' condition.
    unsafe { draw_body::<false>(rasterizer, tri, rows, sampler, shading, target) }
}

/// The body of `rasterizer` ([`edge_triangle_body`] or [`scanline_triangle_body`]), inlined
/// into both entries ([`draw`] and `avx512::draw`).
///
/// # Safety
/// The CPU has AVX2, and AVX-512 F, BW, VL and DQ when `WIDE`.
#[inline(always)]
pub(in crate::raster::lanes) unsafe fn draw_body<const WIDE: bool>(
    rasterizer: Rasterizer,
    tri: &LaneTriangle,
    rows: (u32, u32),
    sampler: Option<&VecSampler<'_>>,
    shading: &LaneShading,
    target: &mut Target<'_>,
) {
    // SAFETY: the function's condition is the bodies'.
    unsafe {
        match rasterizer {
            Rasterizer::EdgeFunction => {
                edge_triangle_body::<WIDE>(tri, rows, sampler, shading, target)
            }
            Rasterizer::Scanline => {
                scanline_triangle_body::<WIDE>(tri, rows, sampler, shading, target)
            }
        }
    }
}

/// The edge-function body of both entries ([`draw`] and `avx512::draw`), inlined into each
/// (so compiled for each one's instruction set). It only chooses the walk: every intrinsic is
/// in the AVX2 functions it calls (which inline into an AVX-512 caller too).
///
/// # Safety
/// The CPU has AVX2, and AVX-512 F, BW, VL and DQ when `WIDE`.
#[inline(always)]
unsafe fn edge_triangle_body<const WIDE: bool>(
    tri: &LaneTriangle,
    (y_start, y_end): (u32, u32),
    sampler: Option<&VecSampler<'_>>,
    shading: &LaneShading,
    target: &mut Target<'_>,
) {
    let (mode, color) = (shading.mode, shading.color);
    let mut lookups = Lookups::new(sampler, WIDE);
    // Sparse rows are gathered only where pixels are written one by one (no uv or
    // difference buffers).
    let mut gathered =
        (target.uv.is_none() && target.difference.is_none()).then(sparse::Gathered::new);
    let consts = &tri.consts;
    let rows = (y_start, y_end);
    match gathered.as_mut() {
        // A narrow triangle (a dense mesh's): every covered pixel is gathered.
        // SAFETY: here and in the calls below: the function's condition (AVX2, and AVX-512
        // when `WIDE`) is what these functions need.
        Some(g) if tri.bounds.x1 - tri.bounds.x0 < LANES as u32 => unsafe {
            narrow_rows::<WIDE>(tri, rows, g, mode, color, sampler, &mut lookups, target)
        },
        // SAFETY: as above.
        _ => unsafe {
            block_rows::<WIDE>(
                tri,
                rows,
                gathered.as_mut(),
                mode,
                color,
                sampler,
                &mut lookups,
                target,
            )
        },
    }
    // At most seven pixels are left (a chunk is drawn whenever eight wait): one chunk.
    if let Some(g) = gathered.as_mut()
        && !g.is_empty()
    {
        // SAFETY: as above.
        unsafe { draw_gathered::<3, WIDE>(g, consts, mode, color, sampler, &mut lookups, target) };
        debug_assert!(g.is_empty());
    }
    // SAFETY: as above.
    unsafe { lookups.flush(sampler, target) };
}

/// The edge-function lanes over the triangle's blocks of [`LANES`] columns by
/// [`BLOCK_ROWS`](super::BLOCK_ROWS)
/// rows: each block rejected, accepted or tested whole, then row by row; a row covering at
/// most [`sparse::MAX_LANES`] pixels goes to `gathered` when there is one.
///
/// Always inlined, without a target feature of its own: compiled into each entry with that
/// entry's instruction set, so the AVX-512 entry's sixteen-lane functions (`wide`) inline
/// here. (As an AVX2 function it was a call of its own in the AVX-512 entry, and every
/// sixteen-lane call from it passed its vectors through memory: the nearest quad measured
/// about 25% slower than when this walk was inlined.)
///
/// # Safety
/// The CPU has AVX2, and AVX-512 F, BW, VL and DQ when `WIDE`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
unsafe fn block_rows<const WIDE: bool>(
    tri: &LaneTriangle,
    (y_start, y_end): (u32, u32),
    mut gathered: Option<&mut sparse::Gathered>,
    mode: Interpolation,
    color: LaneColor,
    sampler: Option<&VecSampler<'_>>,
    lookups: &mut Lookups,
    target: &mut Target<'_>,
) {
    // SAFETY: the function's condition: AVX2 for the AVX2 functions called, AVX-512 F, BW, VL
    // and DQ for the sixteen-lane ones (called only when `WIDE`); the writes' indices are
    // pixels of the band inside the image, as each call's comment says.
    unsafe {
        let planes = &tri.planes;
        let consts = &tri.consts;
        let (x0, x1) = (tri.bounds.x0, tri.bounds.x1);
        let lane_lo = _mm256_setr_pd(0.0, 1.0, 2.0, 3.0);
        let lane_hi = _mm256_setr_pd(4.0, 5.0, 6.0, 7.0);
        let a = planes.a.map(|v| _mm256_set1_pd(v as f64));
        let t = planes.t.map(|v| _mm256_set1_pd(v as f64));
        // The planes texture shading reads: `1/w`, the depth, the mode's u and v; with the
        // weights (other shadings, the wireframe) or both uvs, every value comes from the
        // terms (`At4::of_terms`), the same values.
        let attrs = consts.texture_planes(mode);
        let slow = consts.reads_weights() || consts.both_uv;
        // Row chunks in one AVX-512 register each (see `wide`).
        let wide_rows = WIDE && wide::applies(consts, color, sampler, target);
        // Rows of a block inside the triangle in pairs of sixteen lanes (see `wide::texture_pair`).
        let pairs = match sampler {
            Some(s) if WIDE && wide::pairs_apply(consts, color, sampler, target) => Some(s),
            _ => None,
        };
        // The walk of `blocks::Blocks`, written out: the iterator measured about 5% more
        // instructions here on the 75k mesh (its triangles are a few blocks each).
        let mut by = y_start;
        while by <= y_end {
            let by_end = (by + BLOCK_ROWS - 1).min(y_end);
            // The planes' row parts of this row of blocks, each made once for all its blocks
            // when a row chunk first needs it.
            let mut row_parts = RowParts::new(by);
            let mut bx = x0;
            while bx <= x1 {
                let block = classify(
                    planes,
                    (i64::from(bx), i64::from(bx + LANES as u32 - 1)),
                    (i64::from(by), i64::from(by_end)),
                );
                if block == Block::Outside {
                    bx += LANES as u32;
                    continue;
                }
                let lanes_in = (x1 - bx + 1).min(LANES as u32);
                let in_row = (1i32 << lanes_in) - 1;
                // The block's columns: their terms and each plane's column part, the same in
                // all its rows, made when a row chunk first needs them.
                let mut block_columns = None;
                if let Some(sampler) = pairs
                    && block == Block::Inside
                    && (gathered.is_none() || lanes_in > sparse::MAX_LANES)
                {
                    // `pairs` is set only when `WIDE`, which is set only when the CPU has AVX-512
                    // F, BW, VL and DQ.
                    wide::inside_block(
                        consts,
                        (bx, in_row),
                        (by, by_end),
                        mode,
                        sampler,
                        target,
                        &mut row_parts,
                    );
                    bx += LANES as u32;
                    continue;
                }
                for y in by..=by_end {
                    let base = planes.at(i64::from(y), i64::from(bx));
                    let mut lo = [_mm256_setzero_pd(); 3];
                    let mut hi = [_mm256_setzero_pd(); 3];
                    for i in 0..3 {
                        let b = _mm256_set1_pd(base[i] as f64);
                        lo[i] = _mm256_add_pd(b, _mm256_mul_pd(a[i], lane_lo));
                        hi[i] = _mm256_add_pd(b, _mm256_mul_pd(a[i], lane_hi));
                    }
                    let covered = if block == Block::Inside {
                        in_row
                    } else {
                        (passing(&lo, &t) | (passing(&hi, &t) << 4)) & in_row
                    };
                    if covered == 0 {
                        continue;
                    }
                    if let Some(g) = gathered.as_deref_mut()
                        && covered.count_ones() <= sparse::MAX_LANES
                    {
                        g.add(bx, y, covered);
                        if g.full() {
                            draw_gathered::<2, WIDE>(
                                g, consts, mode, color, sampler, lookups, target,
                            );
                        }
                        continue;
                    }
                    let py = f64::from(y) + 0.5;
                    let row = consts.weights.row_terms(py);
                    let index = (y - target.y0) as usize * target.width as usize + bx as usize;
                    if WIDE && wide_rows {
                        // `WIDE` is set only when the CPU has AVX-512 F, BW, VL and DQ; the row
                        // chunk's covered lanes are pixels of the band's row inside the image.
                        wide::texture_chunk::<4, WIDE>(
                            (&row, f64::from(bx) + 0.5),
                            consts,
                            covered,
                            Where::Row(index),
                            mode,
                            sampler,
                            lookups,
                            target,
                        );
                        continue;
                    }
                    if block_columns.is_none() {
                        block_columns = Some(BlockColumns::new(&consts.weights, bx, &attrs));
                    }
                    let Some(columns) = &block_columns else {
                        continue;
                    };
                    let at4 = if slow {
                        columns.of_terms(consts, mode, &row)
                    } else {
                        columns.values(&row_parts.at(y, &attrs, &consts.weights))
                    };
                    let at = Where::Row(index);
                    shade_chunk::<0, WIDE, true>(
                        at4, covered, at, consts, mode, color, sampler, lookups, target,
                    );
                }
                bx += LANES as u32;
            }
            by = by_end + 1;
        }
    }
}

/// The edge-function lanes over a triangle at most [`LANES`] columns wide: the edge values of
/// one row of eight lanes, stepped row by row (exact integer additions: the triangle is
/// [`exact`](LaneTriangle::exact)), and every covered pixel gathered, without blocks.
#[allow(clippy::too_many_arguments)]
#[inline]
#[target_feature(enable = "avx2")]
fn narrow_rows<const WIDE: bool>(
    tri: &LaneTriangle,
    (y_start, y_end): (u32, u32),
    g: &mut sparse::Gathered,
    mode: Interpolation,
    color: LaneColor,
    sampler: Option<&VecSampler<'_>>,
    lookups: &mut Lookups,
    target: &mut Target<'_>,
) {
    let x0 = tri.bounds.x0;
    let mut rows = NarrowRows::new(tri, y_start);
    for y in y_start..=y_end {
        let covered = rows.next_row();
        if covered != 0 {
            g.add(x0, y, covered);
            if g.full() {
                // Only triangles of more than eight pixels get here. An opaque reference keeps
                // the compiler from loading and broadcasting every constant before the loop
                // (and spilling them) for every triangle: about 200 instructions each.
                let consts = std::hint::black_box(&tri.consts);
                draw_gathered::<1, WIDE>(g, consts, mode, color, sampler, lookups, target);
            }
        }
    }
}

/// The coverage of a triangle at most [`LANES`] columns wide, row after row: the edge
/// values of the eight lanes from its first column, stepped by exact integer additions (the
/// triangle must be [`exact`](LaneTriangle::exact)).
struct NarrowRows {
    lo: [__m256d; 3],
    hi: [__m256d; 3],
    step: [__m256d; 3],
    t: [__m256d; 3],
    /// The lanes within the bounds.
    in_row: i32,
}

impl NarrowRows {
    /// Starting at row `y`.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn new(tri: &LaneTriangle, y: u32) -> Self {
        let planes = &tri.planes;
        let x0 = tri.bounds.x0;
        let lanes_in = (tri.bounds.x1 - x0 + 1).min(LANES as u32);
        let base = planes.at(i64::from(y), i64::from(x0));
        let lane_lo = _mm256_setr_pd(0.0, 1.0, 2.0, 3.0);
        let lane_hi = _mm256_setr_pd(4.0, 5.0, 6.0, 7.0);
        let a = planes.a.map(|v| _mm256_set1_pd(v as f64));
        let b = base.map(|v| _mm256_set1_pd(v as f64));
        Self {
            lo: [0, 1, 2].map(|i| _mm256_add_pd(b[i], _mm256_mul_pd(a[i], lane_lo))),
            hi: [0, 1, 2].map(|i| _mm256_add_pd(b[i], _mm256_mul_pd(a[i], lane_hi))),
            step: planes.b.map(|v| _mm256_set1_pd(v as f64)),
            t: planes.t.map(|v| _mm256_set1_pd(v as f64)),
            in_row: (1i32 << lanes_in) - 1,
        }
    }

    /// The covered lanes of the current row (lane k in bit k: column `x0 + k`), then a step
    /// to the next row.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn next_row(&mut self) -> i32 {
        let covered =
            (passing(&self.lo, &self.t) | (passing(&self.hi, &self.t) << 4)) & self.in_row;
        for i in 0..3 {
            self.lo[i] = _mm256_add_pd(self.lo[i], self.step[i]);
            self.hi[i] = _mm256_add_pd(self.hi[i], self.step[i]);
        }
        covered
    }
}

/// The lanes (bits 0..4) whose three edge values `e` reach their thresholds `t`.
#[inline]
#[target_feature(enable = "avx2")]
fn passing(e: &[__m256d; 3], t: &[__m256d; 3]) -> i32 {
    let m = _mm256_and_pd(
        _mm256_and_pd(
            _mm256_cmp_pd::<_CMP_GE_OQ>(e[0], t[0]),
            _mm256_cmp_pd::<_CMP_GE_OQ>(e[1], t[1]),
        ),
        _mm256_cmp_pd::<_CMP_GE_OQ>(e[2], t[2]),
    );
    _mm256_movemask_pd(m)
}

/// Where a chunk's lanes are in the band's buffers.
#[derive(Clone, Copy)]
pub(in crate::raster::lanes) enum Where {
    /// Eight pixels side by side from this buffer index.
    Row(usize),
    /// Each lane at its own buffer index ([`sparse`]).
    Lanes(__m256i),
}

impl Where {
    /// [`Pending::index`] and [`Pending::lanes`].
    #[inline]
    pub(in crate::raster::lanes) fn parts(self) -> (usize, Option<__m256i>) {
        match self {
            Where::Row(i) => (i, None),
            Where::Lanes(l) => (0, Some(l)),
        }
    }
}

/// Interpolates, shades and writes the next (up to) eight gathered pixels. (The AVX-512
/// chunk of `wide` was measured slower here, on the dense meshes: more code, no gain.)
#[inline]
#[target_feature(enable = "avx2")]
fn draw_gathered<const SITE: u8, const WIDE: bool>(
    g: &mut sparse::Gathered,
    consts: &Constants,
    mode: Interpolation,
    color: LaneColor,
    sampler: Option<&VecSampler<'_>>,
    lookups: &mut Lookups,
    target: &mut Target<'_>,
) {
    debug_assert!(target.uv.is_none() && target.difference.is_none());
    let (x, y, bits) = g.take();
    let x_lo = sparse::centres(_mm256_castsi256_si128(x));
    let x_hi = sparse::centres(_mm256_extracti128_si256::<1>(x));
    let y_lo = sparse::centres(_mm256_castsi256_si128(y));
    let y_hi = sparse::centres(_mm256_extracti128_si256::<1>(y));
    let lo = At4::of_terms(
        consts,
        mode,
        &sparse::terms4(&consts.weights, x_lo, y_lo),
        false,
    );
    let hi = At4::of_terms(
        consts,
        mode,
        &sparse::terms4(&consts.weights, x_hi, y_hi),
        false,
    );
    let at = Where::Lanes(sparse::indices(target, x, y));
    // Pixels are gathered only for targets without uv or difference buffers.
    shade_chunk::<SITE, WIDE, false>(
        [lo, hi],
        bits,
        at,
        consts,
        mode,
        color,
        sampler,
        lookups,
        target,
    );
}

/// Interpolates eight samples from their planes' values and weights (`[lanes 0..4, lanes
/// 4..8]`, [`At4`]), shades
/// the `covered` ones and writes them (or hands them to the texture lookups, which write them).
/// `UV`: the target may have uv or difference buffers (gathered chunks never do).
#[allow(clippy::too_many_arguments)]
#[inline]
#[target_feature(enable = "avx2")]
fn shade_chunk<const SITE: u8, const WIDE: bool, const UV: bool>(
    [lo, hi]: [At4; 2],
    covered: i32,
    at: Where,
    consts: &Constants,
    mode: Interpolation,
    color: LaneColor,
    sampler: Option<&VecSampler<'_>>,
    lookups: &mut Lookups,
    target: &mut Target<'_>,
) {
    let lo = from_planes4!(lo, consts, mode, UV);
    let hi = from_planes4!(hi, consts, mode, UV);
    let ok = covered & (lo.ok | (hi.ok << 4));
    if ok == 0 {
        return;
    }
    let (index, lanes) = at.parts();
    let chunk = Pending {
        u: to_f32(lo.u, hi.u),
        v: to_f32(lo.v, hi.v),
        depth: to_f32(lo.depth, hi.depth),
        valid: mask_from_bits(ok),
        wire: lo.wire | (hi.wire << 4),
        halo: lo.halo | (hi.halo << 4),
        index,
        lanes,
    };
    let both = match (&lo.both_uv, &hi.both_uv) {
        (Some(l), Some(h)) => Some([
            to_f32(l[0], h[0]),
            to_f32(l[1], h[1]),
            to_f32(l[2], h[2]),
            to_f32(l[3], h[3]),
        ]),
        _ => None,
    };
    let rgba = match sampler {
        // A difference target is not shaded (see `DifferenceTarget`).
        _ if target.difference.is_some() => _mm256_setzero_si256(),
        Some(sampler) if color == LaneColor::Texture => {
            return lookups.push::<SITE, WIDE>(sampler, target, chunk, both.as_ref());
        }
        _ => {
            let (lo_w, hi_w) = (lo.weights(consts, mode), hi.weights(consts, mode));
            let channel = |ch: usize| {
                to_f32(
                    dot3(&lo_w, consts.channels[ch]),
                    dot3(&hi_w, consts.channels[ch]),
                )
            };
            channel_colors::<SITE, WIDE>([lo.depth, hi.depth], channel, color)
        }
    };
    // SAFETY: this module runs with AVX2, and the chunk's valid lanes are pixels of the
    // band's row inside the image (`finish`'s conditions; every chunk is made so).
    unsafe { finish::<WIDE>(target, &chunk, rgba, both.as_ref()) }
}
