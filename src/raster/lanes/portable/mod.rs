//! The portable SIMD lanes: texture shading (nearest or bilinear) of both rasterizers into
//! colour and depth, written once in plain Rust over fixed arrays of eight lanes, one
//! operation at a time over all lanes ([`each`]), so that the compiler maps each operation to
//! vector instructions: SSE2 on any x86_64 (SSE4.1 where the CPU has it: the same source
//! compiled a second time, `draw_sse41`), NEON on aarch64. No intrinsics, no
//! dependency; `unsafe` only for one conversion (`sampler::trunc`, whose range is checked
//! first) and the texel reads at wrapped indices (`sampler::Sampler::fetch`).
//!
//! The operations and their order are the scalar lane code's (the parent module), so the
//! pixels are the same bit for bit (`tests/fast_path.rs` runs every test at this level too);
//! the AVX2 intrinsics (`avx2/`) mirror the same code. Other cases (other shadings, the
//! wireframe, the uv and difference buffers) go to the scalar lane code.

use super::*;

mod sampler;

type I32s = [i32; LANES];
/// Packed RGBA8 colours of eight lanes, red in the low byte.
type Rgba = [u32; LANES];
/// A condition per lane from `f64` lanes as an integer mask: all ones where it holds, else
/// zero (what a vector comparison gives; `[bool; 8]` needed packing and unpacking).
type Mask64 = [i64; LANES];
/// The same per `f32` lane.
type Mask32 = [i32; LANES];

/// Infinity, opaque to the optimizer (made once per triangle, [`Inf::new`]): compared with
/// the constant, `x > 0 && x < inf` and `is_finite` became scalar bit tests lane by lane
/// (LLVM's floating-point class tests); compared with this value they stay vector compares.
#[derive(Clone, Copy)]
struct Inf(f64);

impl Inf {
    #[inline(always)]
    fn new() -> Self {
        Self(std::hint::black_box(f64::INFINITY))
    }
}

/// Whether the build has a vector floor instruction (SSE4.1's `roundps`, NEON's `frintm`),
/// so that `f32::floor` is one instruction per register; without it (SSE2) `floor` is a call
/// per lane, and the sampler floors by truncation instead (`sampler::floor_coord`). A constant
/// in each build of [`draw_body`].
#[derive(Clone, Copy)]
struct VectorFloor(bool);

/// `cond` as a lane mask: all ones or zero.
#[inline(always)]
fn mask64(cond: bool) -> i64 {
    -i64::from(cond)
}

/// `cond` as a lane mask: all ones or zero.
#[inline(always)]
fn mask32(cond: bool) -> i32 {
    -i32::from(cond)
}

/// `[f(0), f(1), ..., f(7)]`: one operation over the eight lanes. (A loop, not
/// `array::from_fn`: that was left as a call, compiled without the caller's SSE4.1.)
#[inline(always)]
fn each<T: Copy + Default>(f: impl FnMut(usize) -> T) -> [T; LANES] {
    each_n(f)
}

/// `[f(0), f(1), ..., f(N - 1)]`: [`each`] over `N` lanes.
#[inline(always)]
fn each_n<T: Copy + Default, const N: usize>(mut f: impl FnMut(usize) -> T) -> [T; N] {
    let mut out = [T::default(); N];
    for (k, o) in out.iter_mut().enumerate() {
        *o = f(k);
    }
    out
}

/// `[f(0), f(1), f(2)]`: one operation per edge or vertex (written out: `[0, 1, 2].map` was
/// left as calls).
#[inline(always)]
fn three<T>(mut f: impl FnMut(usize) -> T) -> [T; 3] {
    [f(0), f(1), f(2)]
}

/// Whether the portable lanes draw a triangle made for `shading` into `target`: texture
/// shading without the wireframe, into colour and depth only, from a texture of fewer than
/// 2^31 texels (the sampler's indices are 32-bit).
pub(super) fn applies(shading: &LaneShading, texture: &Texture, target: &Target<'_>) -> bool {
    shading.color == LaneColor::Texture
        && texture.base_texels().len() < 1 << 31
        && !shading.wireframe
        && target.uv.is_none()
        && target.difference.is_none()
}

/// Proof that the CPU has SSE4.1 (made only by [`Sse41::detect`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Sse41(());

impl Sse41 {
    /// `Some` when the CPU has SSE4.1 (never off x86_64).
    pub(super) fn detect() -> Option<Self> {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("sse4.1") {
            return Some(Self(()));
        }
        None
    }
}

/// Draws rows `rows` (within the target band) of `tri` with texture shading ([`applies`]
/// must hold) with the lanes of `rasterizer`: the edge functions of
/// [`edge_triangle_impl`](super::edge_triangle_impl) or the spans of
/// [`scanline_triangle_impl`](super::scanline::scanline_triangle_impl). Compiled with
/// SSE4.1 (rounding, blends, 32-bit minimum and maximum) when `sse41` is given, else for the
/// baseline of the target (SSE2 on x86_64, NEON on aarch64).
pub(super) fn draw(
    rasterizer: Rasterizer,
    sse41: Option<Sse41>,
    tri: &LaneTriangle,
    rows: (u32, u32),
    sampler: &Sampler<'_>,
    mode: Interpolation,
    target: &mut Target<'_>,
) {
    #[cfg(target_arch = "x86_64")]
    if sse41.is_some() {
        // SAFETY: the CPU has SSE4.1 (an `Sse41` is made only when it is detected).
        unsafe { draw_sse41(rasterizer, tri, rows, sampler, mode, target) };
        return;
    }
    let _ = sse41;
    let floor = VectorFloor(cfg!(target_arch = "aarch64"));
    draw_body(rasterizer, tri, rows, sampler, mode, target, floor);
}

/// [`draw`] compiled with SSE4.1.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "sse4.1")]
fn draw_sse41(
    rasterizer: Rasterizer,
    tri: &LaneTriangle,
    rows: (u32, u32),
    sampler: &Sampler<'_>,
    mode: Interpolation,
    target: &mut Target<'_>,
) {
    draw_body(
        rasterizer,
        tri,
        rows,
        sampler,
        mode,
        target,
        VectorFloor(true),
    );
}

/// Both rasterizers' lanes, inlined into each build of [`draw`].
#[inline(always)]
fn draw_body(
    rasterizer: Rasterizer,
    tri: &LaneTriangle,
    rows: (u32, u32),
    sampler: &Sampler<'_>,
    mode: Interpolation,
    target: &mut Target<'_>,
    floor: VectorFloor,
) {
    match rasterizer {
        Rasterizer::EdgeFunction => edge_body(tri, rows, sampler, mode, target, floor),
        Rasterizer::Scanline => scanline_body(tri, rows, sampler, mode, target, floor),
    }
}

/// The edge-function lanes: blocks rejected, accepted or tested as in the scalar lane code,
/// then per row chunk the scalar code's operations, lane by lane: the edge values, then
/// `interpolate::fragment_at_window`'s `1/w`, depth and uv from their planes (`R - C`: the
/// column parts made once per block, the row parts once per row), the texture lookup, the
/// depth test and the write.
#[inline(always)]
fn edge_body(
    tri: &LaneTriangle,
    (y_start, y_end): (u32, u32),
    sampler: &Sampler<'_>,
    mode: Interpolation,
    target: &mut Target<'_>,
    floor: VectorFloor,
) {
    let planes = &tri.planes;
    let consts = &tri.consts;
    let weights = &consts.weights;
    let attrs = consts.texture_planes(mode);
    let (x0, x1) = (tri.bounds.x0, tri.bounds.x1);
    let a = three(|i| planes.a[i] as f64);
    let t = three(|i| planes.t[i] as f64);
    let inf = Inf::new();
    // The planes' row parts of the current row of blocks, each made once for all its
    // blocks.
    let mut row_parts = RowParts::new(y_start);
    for block in Blocks::new(planes, (x0, x1), (y_start, y_end)) {
        let (bx, lanes_in) = (block.x, block.lanes_in);
        if row_parts.first != block.rows.0 {
            row_parts = RowParts::new(block.rows.0);
        }
        let in_row: Mask64 = each(|k| mask64(k < lanes_in));
        // Each plane's column part at the block's columns: the same in all its rows.
        let px: F64s = each(|k| (f64::from(bx) + OFFSETS[k]) + 0.5);
        let terms: [F64s; 3] = three(|i| each(|k| weights.column_term(i, px[k])));
        let column = |j: usize| -> F64s {
            let k = &attrs[j].k;
            each(|l| terms[0][l] * k[0] + terms[1][l] * k[1] + terms[2][l] * k[2])
        };
        let columns = [column(0), column(1), column(2), column(3)];
        // A row is looked up and written one pass later, after the next row's values are
        // made, so that the two overlap (the division of one with the texture lookup of the
        // other); the last pass only draws the row before it.
        let mut pending = NO_ROW;
        for y in block.rows.0..=block.rows.1 + 1 {
            let mut made = NO_ROW;
            if y <= block.rows.1 {
                let covered: Mask64 = if block.kind == Block::Inside {
                    in_row
                } else {
                    let base = planes.at(i64::from(y), i64::from(bx));
                    let e = three(|i| each(|k| base[i] as f64 + a[i] * OFFSETS[k]));
                    let pass = |i: usize| each(|k| mask64(e[i][k] >= t[i]));
                    let (p0, p1, p2) = (pass(0), pass(1), pass(2));
                    each(|k| in_row[k] & p0[k] & p1[k] & p2[k])
                };
                // (A block inside the triangle covers a lane of every row.)
                if block.kind == Block::Inside || covered.iter().fold(0, |m, &c| m | c) != 0 {
                    let rows = row_parts.at(y, &attrs, weights);
                    let (u, v, depth, valid) = interpolate(&columns, rows, mode, inf);
                    let ok: Mask32 = each(|k| (valid[k] & covered[k]) as i32);
                    made = (true, y, ok, u, v, depth);
                }
            }
            let (drawn, py, ok, u, v, depth) = pending;
            if drawn {
                let rgba = sampler.sample_packed(&u, &v, inf, floor);
                write(target, bx, py, &ok, &depth, &rgba);
            }
            pending = made;
        }
    }
}

/// A row chunk of the edge-function lanes made and waiting to be drawn: whether there is one,
/// its row, its lanes, uv and depth.
type RowChunk = (bool, u32, Mask32, F32s, F32s, F32s);

/// No row chunk.
const NO_ROW: RowChunk = (
    false,
    0,
    [0; LANES],
    [0.0; LANES],
    [0.0; LANES],
    [0.0; LANES],
);

/// uv, depth and validity of eight samples from the column parts of the planes `1/w`, depth,
/// u and v (`u/w`, `v/w` when perspective-correct) and their row parts, as
/// [`super::from_terms`] computes them for texture shading: each value `R - C`; valid where
/// `1/w` is positive and finite; perspective-correct uv `(u/w) * (1 / (1/w))`.
#[inline(always)]
fn interpolate(
    columns: &[F64s; 4],
    rows: [f64; 4],
    mode: Interpolation,
    inf: Inf,
) -> (F32s, F32s, F32s, Mask64) {
    let at = |j: usize| -> F64s { each(|k| rows[j] - columns[j][k]) };
    let one_over_w = at(0);
    let ok = positive_finite(&one_over_w, inf);
    let depth: F32s = {
        let d = at(1);
        each(|k| d[k] as f32)
    };
    let (u, v) = (at(2), at(3));
    match mode {
        Interpolation::Affine => (each(|k| u[k] as f32), each(|k| v[k] as f32), depth, ok),
        Interpolation::Perspective => {
            let inv: F64s = each(|k| 1.0 / one_over_w[k]);
            (
                each(|k| (u[k] * inv[k]) as f32),
                each(|k| (v[k] * inv[k]) as f32),
                depth,
                ok,
            )
        }
    }
}

/// The scanline lanes: the scalar code's spans, start values and single steps (the same
/// [`Stepped`] values), carried as eight lanes per quantity, advanced by eight increments per
/// chunk.
#[inline(always)]
fn scanline_body(
    tri: &LaneTriangle,
    (y_start, y_end): (u32, u32),
    sampler: &Sampler<'_>,
    mode: Interpolation,
    target: &mut Target<'_>,
    floor: VectorFloor,
) {
    let consts = &tri.consts;
    let step = Stepped::row_step(consts, mode);
    let n = LANES as f64;
    let (su, sv, sw, sd) = (step.u * n, step.v * n, step.inv_w * n, step.depth * n);
    let inf = Inf::new();
    for y in y_start..=y_end {
        let Some((x0, x1)) = row_span_of(&tri.edges, tri.bounds, y) else {
            continue;
        };
        let lanes = Stepped::lanes(Stepped::span_start(consts, mode, x0, y), &step);
        let mut u: F64s = each(|k| lanes[k].u);
        let mut v: F64s = each(|k| lanes[k].v);
        let mut inv_w: F64s = each(|k| lanes[k].inv_w);
        let mut depth: F64s = each(|k| lanes[k].depth);
        let mut x = x0;
        // A chunk's uv, depth and validity from the stepped values.
        let chunk = |u: &F64s, v: &F64s, inv_w: &F64s, depth: &F64s| {
            let valid = positive_finite(inv_w, inf);
            let (uf, vf) = match mode {
                Interpolation::Perspective => {
                    let w: F64s = each(|k| 1.0 / inv_w[k]);
                    (
                        each(|k| (u[k] * w[k]) as f32),
                        each(|k| (v[k] * w[k]) as f32),
                    )
                }
                Interpolation::Affine => (each(|k| u[k] as f32), each(|k| v[k] as f32)),
            };
            let d: F32s = each(|k| depth[k] as f32);
            (uf, vf, d, valid)
        };
        let mut next = chunk(&u, &v, &inv_w, &depth);
        while x <= x1 {
            let lanes_in = (x1 - x + 1).min(LANES as u32) as usize;
            let (uf, vf, d, valid) = next;
            u = each(|k| u[k] + su);
            v = each(|k| v[k] + sv);
            inv_w = each(|k| inv_w[k] + sw);
            depth = each(|k| depth[k] + sd);
            // The next chunk's division before this chunk's lookup, so the two overlap.
            if x1 - x >= LANES as u32 {
                next = chunk(&u, &v, &inv_w, &depth);
            }
            let ok: Mask32 = each(|k| (mask64(k < lanes_in) & valid[k]) as i32);
            let rgba = sampler.sample_packed(&uf, &vf, inf, floor);
            write(target, x, y, &ok, &d, &rgba);
            x += LANES as u32;
        }
    }
}

/// The lanes of `x` that are positive and finite (`x > 0 && x < inf`: NaN fails).
#[inline(always)]
fn positive_finite<const N: usize>(x: &[f64; N], inf: Inf) -> [i64; N] {
    let above: [i64; N] = each_n(|k| mask64(x[k] > 0.0));
    let below: [i64; N] = each_n(|k| mask64(x[k] < inf.0));
    each_n(|k| above[k] & below[k])
}

/// Depth-tests and writes the lanes of `ok` of one row chunk from column `x` of row `y`
/// ([`depth_passes`]: an ordered less-than), as the scalar [`write`](super::write) does
/// for colour and depth. Eight lanes inside the band are read and written whole, with the
/// lanes not in `ok` or failing the test keeping their values (the band's rows belong to
/// this thread only; lanes past the row's end are pixels of the next row, rewritten as they
/// were); only a chunk running past the band's end is written lane by lane.
#[inline(always)]
fn write(target: &mut Target<'_>, x: u32, y: u32, ok: &Mask32, depth: &F32s, rgba: &Rgba) {
    let i = (y - target.y0) as usize * target.width as usize + x as usize;
    if let Some((d, _)) = target
        .depth
        .get_mut(i..)
        .and_then(|s| s.split_first_chunk_mut::<LANES>())
        && let Some((c, _)) = target
            .color
            .get_mut(i..)
            .and_then(|s| s.split_first_chunk_mut::<LANES>())
    {
        let pass: Mask32 = each(|k| ok[k] & mask32(depth_passes(depth[k], d[k])));
        let old: [u32; LANES] = each(|k| d[k].to_bits());
        *d = each(|k| f32::from_bits(select(pass[k], depth[k].to_bits(), old[k])));
        let old: Rgba = each(|k| u32::from_le_bytes(c[k]));
        let new: Rgba = each(|k| select(pass[k], rgba[k], old[k]));
        *c = each(|k| new[k].to_le_bytes());
        return;
    }
    for k in 0..LANES {
        if ok[k] != 0 && depth_passes(depth[k], target.depth[i + k]) {
            target.depth[i + k] = depth[k];
            target.color[i + k] = rgba[k].to_le_bytes();
        }
    }
}

/// `a` where the lane mask `m` is set, else `b` (bitwise: and, and-not, or).
#[inline(always)]
fn select(m: i32, a: u32, b: u32) -> u32 {
    let m = m as u32;
    (a & m) | (b & !m)
}
