//! The fast path: eight pixels of a row at a time (sixteen in the AVX-512 spans and lookups).
//!
//! Both rasterizers have a lane form here, used when a render asks for fewer buffers than all
//! ([`render_into`](super::render::render_into): the app's canvas, `barylab bench`). The
//! edge-function lanes write colour and depth, and the triangle and both uvs
//! (`Buffers::ColorDepthUv`) or the texel difference (`Buffers::DepthDifference`) where the
//! band has them; they draw texture shading with nearest or bilinear filtering, vertex colour,
//! barycentric, depth, normal and Lambert shading, and the wireframe overlay. The scanline
//! lanes draw the same shadings without the wireframe, into colour and depth only. Other cases
//! (trilinear filtering, the scanline rasterizer's wireframe or uv buffers) go through the
//! per-pixel kernel (`raster/draw.rs`, after the block rejection of the edge-function
//! path).
//!
//! - **Edge functions** ([`edge_triangle`]): the bounding box is walked in blocks of
//!   [`LANES`] columns by [`BLOCK_ROWS`] rows. The three edge functions at a block's corners
//!   reject it whole (all four corners outside one edge) or accept it whole (all inside every
//!   edge: no per-pixel test). Per row, the edge values of the eight pixels are exact integers
//!   carried in `f64` lanes (checked to stay below 2^52) and decide coverage; the screen
//!   weights are computed per lane with the operations of
//!   [`WeightPlanes::weight`](super::setup::WeightPlanes::weight), and every later step
//!   repeats the operations of [`interpolate::fragment`](super::interpolate::fragment) and
//!   [`Texture::sample_rgba8`] in the same order, so the result is **bit-identical** to the
//!   per-pixel renderer and to what the probe reports. In the AVX2 build, a triangle at most
//!   eight columns wide skips the blocks (its edge values are stepped row by row), and its
//!   covered pixels, like those of any row chunk covering at most four, are gathered from
//!   several rows into chunks of eight (`avx2/sparse.rs`): each lane does the same operations
//!   at its own pixel centre.
//! - **Scanline** ([`scanline_triangle`]): exact integer spans per row
//!   ([`row_span`](super::scanline::row_span); in the AVX2 build, for a triangle at most eight
//!   columns wide, the same columns read from its exact edge values); along a span `u/w`, `v/w`, `1/w`, the depth
//!   and the shading's channels (`c/w`) are stepped by their per-pixel increments (eight lanes
//!   advance by eight increments), and the perspective-correct uv is `(u/w) * (1 / (1/w))`,
//!   one division per pixel. Coverage is
//!   identical to the edge-function path; values agree up to floating-point rounding. Spans of
//!   at most four pixels are gathered into chunks of eight in the AVX2 build, with the values
//!   the row's lanes would hold.
//!
//! Four builds of the same arithmetic, chosen at run time ([`VectorLevel`]) once per band of
//! triangles ([`Lanes`]): the scalar lane code here (plain loops, lane by lane: the reference
//! the others mirror); the portable SIMD lanes (`portable/`: the same operations over fixed
//! arrays of eight lanes, which the compiler turns into SSE2 or SSE4.1 on x86_64 and NEON on
//! aarch64, for texture shading into colour and depth); and, in folders named for the
//! instructions they need, AVX2 intrinsics (`avx2/`: the lane paths, the AVX2 texture sampler
//! `avx2/sampler.rs`) and, in its subfolder (AVX-512 code needs AVX2 too, and uses the AVX2
//! code: a child, so the two import one way), the same code compiled a second time for AVX-512
//! when the CPU has it (`avx2/avx512/`: the entries, 32 registers and mask registers; row chunks of texture shading in
//! one 512-bit register, `avx2/avx512/wide.rs`; bilinear texture lookups of two chunks, sixteen
//! pixels, at once, the scanline lanes' long texture spans sixteen pixels at a time, the
//! scattered writes of gathered chunks, `avx2/avx512/scatter.rs`). No fused multiply-add is used
//! anywhere, so every build rounds identically; `tests/fast_path.rs` compares them all with
//! the full render.

// Lane code indexes several parallel arrays by the lane number; iterators would hide that.
#![allow(clippy::needless_range_loop)]

use std::sync::atomic::{AtomicBool, AtomicU8, Ordering};

use glam::Vec3;

use super::framebuffer::depth_passes;
use super::interpolate::{Interpolation, Planes};
use super::project::SUBPIXEL;
use super::scanline::row_span_of;
use super::settings::Rasterizer;
use super::setup::{
    Edge, PixelBounds, ScreenPlane, TriangleSetup, WeightPlanes, source_weight_gradients,
};
use super::shade::{
    WIRE_COLOR, WIRE_HALO_COLOR, depth_grey, lambert_rgba8, normal_rgba8, on_wire_edge,
    on_wire_halo, unorm8,
};
use super::texture::{
    self, Filter, Texture, Wrap, bilinear_fraction, bilinear_weights, byte_from_sum, wrap_coord,
};
use super::varying::Varyings;

mod blocks;
mod paths;
mod portable;
mod sampler;
mod scanline;
mod triangle;

pub use blocks::EdgePlanes;
use blocks::{Block, Blocks, RowParts};
pub use paths::Lanes;
use sampler::Sampler;
use scanline::Stepped;
pub use scanline::scanline_triangle;
use triangle::{CHANNELS, Constants};
pub use triangle::{LaneTriangle, LaneVertices};

#[cfg(target_arch = "x86_64")]
mod avx2;

/// The instruction sets the lane paths may use (each also needs the CPU to have it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum VectorLevel {
    /// The scalar lane code only: the reference the other levels mirror, lane by lane.
    Scalar = 0,
    /// The portable SIMD lanes (`portable/`: SSE2 or SSE4.1 on x86_64, NEON on aarch64) for
    /// texture shading into colour and depth; the scalar lane code for the rest.
    Portable = 1,
    /// AVX2 intrinsics (`avx2/`), for every shading the lanes draw.
    Avx2 = 2,
    /// The AVX2 code compiled again for AVX-512 F, BW, VL and DQ (`avx2/avx512/`): 32
    /// registers and mask registers, row chunks in one 512-bit register, texture lookups and
    /// long scanline spans sixteen pixels at a time, scattered writes of gathered chunks.
    Avx512 = 3,
}

/// The level [`render_into`](super::render::render_into) draws at: all by default (AVX2 for
/// dense meshes, [`VectorLevel::for_frame`]); the command line's `--vector` sets it for the
/// run ([`set_vector_level`]).
static VECTOR_LEVEL: AtomicU8 = AtomicU8::new(VectorLevel::Avx512 as u8);

/// Sets the level [`render_into`](super::render::render_into) draws at for the rest of the
/// run (`barylab bench --vector`). Every level gives the same pixels; tests pass the level to
/// [`render_into_at`](super::render::render_into_at) instead of setting it here.
pub fn set_vector_level(level: VectorLevel) {
    VECTOR_LEVEL.store(level as u8, Ordering::Relaxed);
    VECTOR_LEVEL_CHOSEN.store(true, Ordering::Relaxed);
}

/// Whether the run chose its level ([`set_vector_level`]): then every frame draws at it; by
/// default a dense mesh draws with AVX2 rather than AVX-512 ([`VectorLevel::for_frame`]).
static VECTOR_LEVEL_CHOSEN: AtomicBool = AtomicBool::new(false);

/// Image pixels per triangle below which a frame draws with the AVX2 lanes rather than the
/// AVX-512 ones by default. Measured on an Intel Xeon (one thread, alternating the levels):
/// a mesh of 75k triangles at 1920x1080 (28 pixels a triangle) took 33.6 ms with AVX2 and 38.0
/// with AVX-512, one of 460k triangles 88 against 107 ms; one of 5k triangles (415 pixels a
/// triangle) 16.2 against 15.6 ms, and the two-triangle quad a third less time with AVX-512.
/// Small triangles fill few of sixteen lanes, and code that is the same at both levels (the
/// mesh's set-up, the clear) took about as much longer beside the 512-bit arithmetic, as when
/// a processor lowers its clock for it.
pub const DENSE_PIXELS_PER_TRIANGLE: u64 = 128;

impl VectorLevel {
    /// Every level, from the scalar reference up.
    pub const ALL: [VectorLevel; 4] = [
        VectorLevel::Scalar,
        VectorLevel::Portable,
        VectorLevel::Avx2,
        VectorLevel::Avx512,
    ];

    /// The level [`render_into`](super::render::render_into) draws at (see
    /// [`set_vector_level`]).
    pub fn current() -> Self {
        match VECTOR_LEVEL.load(Ordering::Relaxed) {
            0 => VectorLevel::Scalar,
            1 => VectorLevel::Portable,
            2 => VectorLevel::Avx2,
            _ => VectorLevel::Avx512,
        }
    }

    /// The level [`render_into`](super::render::render_into) and
    /// [`rasterize_bands`](super::render::rasterize_bands) draw a frame of `triangles`
    /// triangles over an image of `pixels` pixels at: [`VectorLevel::current`], but AVX2 for
    /// AVX-512 when the run did not choose its level and the triangles average fewer than
    /// [`DENSE_PIXELS_PER_TRIANGLE`] pixels of the image (the same pixels either way).
    pub fn for_frame(triangles: usize, pixels: u64) -> Self {
        Self::frame_level(
            Self::current(),
            VECTOR_LEVEL_CHOSEN.load(Ordering::Relaxed),
            triangles,
            pixels,
        )
    }

    /// [`VectorLevel::for_frame`] from the run's level and whether it was chosen.
    fn frame_level(level: Self, chosen: bool, triangles: usize, pixels: u64) -> Self {
        let dense = pixels < DENSE_PIXELS_PER_TRIANGLE.saturating_mul(triangles as u64);
        if level == VectorLevel::Avx512 && !chosen && dense {
            VectorLevel::Avx2
        } else {
            level
        }
    }

    /// Whether the AVX2 intrinsics path is allowed at this level and the CPU has AVX2.
    #[cfg(target_arch = "x86_64")]
    fn avx2(self) -> bool {
        self >= VectorLevel::Avx2 && std::arch::is_x86_feature_detected!("avx2")
    }

    /// Whether the AVX-512 texture lookups are allowed at this level and the CPU has AVX-512
    /// F, BW, VL and DQ.
    #[cfg(target_arch = "x86_64")]
    fn avx512(self) -> bool {
        self >= VectorLevel::Avx512
            && std::arch::is_x86_feature_detected!("avx512f")
            && std::arch::is_x86_feature_detected!("avx512bw")
            && std::arch::is_x86_feature_detected!("avx512vl")
            && std::arch::is_x86_feature_detected!("avx512dq")
    }
}

/// Pixels processed together along a row.
pub const LANES: usize = 8;

/// Rows of one block of the edge-function path (blocks are [`LANES`] columns wide).
pub const BLOCK_ROWS: u32 = 8;

/// Edge values are carried in `f64` lanes only while every value over the bounding box stays
/// below this magnitude: integers up to 2^53 are exact in `f64`, and 2^52 leaves room for the
/// per-lane offset. Larger triangles (near the guard band) use the per-pixel path.
const EXACT_EDGE_LIMIT: i64 = 1 << 52;

type F64s = [f64; LANES];
type F32s = [f32; LANES];
type Mask = [bool; LANES];

/// Lane offsets 0, 1, ..., 7 as `f64`.
const OFFSETS: F64s = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0];

/// Where the lanes write: the colour and depth rows `y0..` of one band of the framebuffer, and
/// optionally the triangle and uv both ways ([`Buffers::ColorDepthUv`]) or their texel
/// difference ([`DifferenceTarget`]).
///
/// [`Buffers::ColorDepthUv`]: super::framebuffer::Buffers::ColorDepthUv
pub struct Target<'a> {
    /// The band's first image row (row 0 at the top).
    pub y0: u32,
    /// Image width in pixels: the length of a row in the slices.
    pub width: u32,
    /// RGBA8 of the band's rows, row by row from `y0`.
    pub color: &'a mut [[u8; 4]],
    /// Window depth `(z/w + 1)/2` of the band's rows, tested less-than.
    pub depth: &'a mut [f32],
    /// The triangle and uv buffers, when the render keeps them.
    pub uv: Option<UvTarget<'a>>,
    /// The texel-difference buffer, when the render keeps it.
    pub difference: Option<DifferenceTarget<'a>>,
}

/// The texel-difference buffer of a band ([`Buffers::DepthDifference`]): where a
/// fragment passes the depth test,
/// [`texel_difference`](super::texture::texel_difference) of its `noperspective` and
/// `smooth` uv, with the same `f32` operations. A target with it is not shaded: depth and
/// the difference are written, the colour buffer is left as it is.
///
/// [`Buffers::DepthDifference`]: super::framebuffer::Buffers::DepthDifference
pub struct DifferenceTarget<'a> {
    /// The texture's width and height in texels.
    pub size: [f32; 2],
    /// One value per pixel, as `color`.
    pub out: &'a mut [f32],
}

/// The triangle and uv buffers of a band, for the difference heatmap: where a fragment passes
/// the depth test, its source triangle, its `noperspective` uv and its `smooth` uv, as
/// [`interpolate::fragment`](super::interpolate::fragment) computes them (bit for bit).
pub struct UvTarget<'a> {
    /// The source triangle being drawn.
    pub source: u32,
    /// The source triangle of the front-most fragment per pixel, as `color`.
    pub triangle: &'a mut [u32],
    /// uv interpolated with the screen weights (`noperspective`), as `color`.
    pub uv_affine: &'a mut [[f32; 2]],
    /// uv interpolated perspective-correctly (`smooth`), as `color`.
    pub uv_perspective: &'a mut [[f32; 2]],
}

/// What the lanes shade ([`LaneColor`]): texture (nearest or bilinear), vertex colour,
/// barycentric weights, depth, the normal as colour or Lambert, with the wireframe overlay on
/// the edge-function path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LaneShading {
    /// Affine or perspective-correct interpolation.
    pub mode: Interpolation,
    /// What the colour shows.
    pub color: LaneColor,
    /// The texture filter and wrap (used by [`LaneColor::Texture`]).
    pub filter: Filter,
    /// The texture wrap mode (used by [`LaneColor::Texture`]).
    pub wrap: Wrap,
    /// Draw the source triangles' edges (see [`on_wire_edge`]).
    pub wireframe: bool,
}

/// The shadings of [`Shading`](super::shade::Shading) the lanes draw (texture lookups with
/// nearest or bilinear filtering only).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LaneColor {
    /// The texture at the interpolated uv ([`Shading::Texture`](super::shade::Shading::Texture)).
    Texture,
    /// The interpolated vertex colour.
    VertexColor,
    /// The source triangle's three weights as red, green and blue.
    Barycentric,
    /// Grey from the window depth, black at `.0` and white at `.1`.
    Depth(f64, f64),
    /// The interpolated view-space normal as colour ([`normal_rgba8`]).
    Normal,
    /// The vertex colour lit by a headlight ([`lambert_rgba8`]).
    Lambert,
}

/// uv, depth, validity and wireframe hits of eight samples (and the interpolated channels
/// and the `f64` depth for the shadings that show them).
struct Samples {
    u: F32s,
    v: F32s,
    depth: F32s,
    ok: Mask,
    wire: Mask,
    /// Lanes in the wireframe's halo (the line wins where both are set).
    halo: Mask,
    channels: [F32s; CHANNELS],
    depth64: F64s,
    /// `[u_affine, v_affine, u_smooth, v_smooth]` (when [`Constants::both_uv`] is set).
    both_uv: [F32s; 4],
}

impl Samples {
    fn new() -> Self {
        Self {
            u: [0.0; LANES],
            v: [0.0; LANES],
            depth: [0.0; LANES],
            ok: [false; LANES],
            wire: [false; LANES],
            halo: [false; LANES],
            channels: [[0.0; LANES]; CHANNELS],
            depth64: [0.0; LANES],
            both_uv: [[0.0; LANES]; 4],
        }
    }
}

/// The colours of the non-texture shadings, as [`shade`](super::shade::shade) makes them.
#[inline(always)]
fn channel_colors(s: &Samples, color: LaneColor, out: &mut [[u8; 4]; LANES]) {
    for k in 0..LANES {
        out[k] = match color {
            LaneColor::Depth(lo, hi) => {
                let g = depth_grey(s.depth64[k], (lo, hi));
                [g, g, g, 255]
            }
            LaneColor::Normal => normal_rgba8(channel3(s, 0, k)),
            LaneColor::Lambert => lambert_rgba8(channel3(s, 0, k), channel3(s, 3, k)),
            _ => [
                unorm8(s.channels[0][k]),
                unorm8(s.channels[1][k]),
                unorm8(s.channels[2][k]),
                255,
            ],
        };
    }
}

/// Channels `first..first + 3` of lane `k` as a vector.
#[inline(always)]
fn channel3(s: &Samples, first: usize, k: usize) -> Vec3 {
    Vec3::new(
        s.channels[first][k],
        s.channels[first + 1][k],
        s.channels[first + 2][k],
    )
}

/// The weights' row terms of row `y` and column terms of the eight pixels `x, x + 1, ...`
/// ([`WeightPlanes::row_terms`], [`WeightPlanes::column_terms`], at pixel centres).
#[inline(always)]
fn row_terms(w: &WeightPlanes, x: u32, y: u32) -> ([f64; 3], [[f64; 3]; LANES]) {
    let rows = w.row_terms(f64::from(y) + 0.5);
    let mut columns = [[0.0; 3]; LANES];
    for (k, c) in columns.iter_mut().enumerate() {
        *c = w.column_terms((f64::from(x) + OFFSETS[k]) + 0.5);
    }
    (rows, columns)
}

/// Everything of eight samples from the weights' terms, exactly as
/// [`interpolate::fragment_at_window`](super::interpolate::fragment_at_window) computes it:
/// `1/w`, the depth and uv from their planes (`R - C`), valid where `1/w` is positive and
/// finite; the screen weights `l_i = (row_i - column_i) / area2`, the perspective weights
/// `p_i = (l_i / w_i) * (1 / (1/w))` and the channels and wireframe from them.
#[inline(always)]
fn from_terms(
    rows: &[f64; 3],
    columns: &[[f64; 3]; LANES],
    c: &Constants,
    mode: Interpolation,
) -> Samples {
    let mut out = Samples::new();
    let planes = &c.attrs;
    let uv = c.uv_planes(mode);
    for k in 0..LANES {
        let col = &columns[k];
        let at = |plane: &ScreenPlane| plane.part(rows) - plane.part(col);
        let l_i = |i: usize| c.weights.weight_of_terms(rows[i], col[i]);
        let l = [l_i(0), l_i(1), l_i(2)];
        let one_over_w = at(&planes.inv_w);
        out.ok[k] = one_over_w > 0.0 && one_over_w < f64::INFINITY;
        let inv = 1.0 / one_over_w;
        if c.both_uv {
            let [ua, va] = planes.uv_affine.map(|p| at(&p) as f32);
            let [us, vs] = planes.uv_over_w.map(|p| (at(&p) * inv) as f32);
            for (j, x) in [ua, va, us, vs].into_iter().enumerate() {
                out.both_uv[j][k] = x;
            }
        }
        let (u, v) = (at(&uv[0]), at(&uv[1]));
        (out.u[k], out.v[k]) = match mode {
            Interpolation::Perspective => ((u * inv) as f32, (v * inv) as f32),
            Interpolation::Affine => (u as f32, v as f32),
        };
        out.depth64[k] = at(&planes.depth);
        out.depth[k] = out.depth64[k] as f32;
        let w = match mode {
            Interpolation::Perspective => super::interpolate::weights_times(&l, &c.inv_w, inv),
            Interpolation::Affine => l,
        };
        for ch in 0..c.used_channels {
            let x = &c.channels[ch];
            out.channels[ch][k] = (w[0] * x[0] + w[1] * x[1] + w[2] * x[2]) as f32;
        }
        if let Some(wire) = &c.wire {
            for i in 0..3 {
                let b = &wire.bary[i];
                let weight = (l[0] * b[0] + l[1] * b[1] + l[2] * b[2]) as f32;
                out.wire[k] |= on_wire_edge(weight, wire.len[i]);
                out.halo[k] |= on_wire_halo(weight, wire.len[i]);
            }
        }
    }
    out
}

/// Depth-tests and writes the valid lanes of one row chunk starting at column `x`.
#[inline(always)]
fn write(target: &mut Target<'_>, x: u32, y: u32, s: &Samples, colors: &[[u8; 4]; LANES]) {
    let row = (y - target.y0) as usize * target.width as usize;
    for k in 0..LANES {
        if !s.ok[k] {
            continue;
        }
        let i = row + x as usize + k;
        if depth_passes(s.depth[k], target.depth[i]) {
            target.depth[i] = s.depth[k];
            if target.difference.is_none() {
                target.color[i] = colors[k];
            }
            if let Some(d) = target.difference.as_mut() {
                let b = &s.both_uv;
                d.out[i] = crate::raster::texture::square_texel_difference(
                    [b[0][k], b[1][k]],
                    [b[2][k], b[3][k]],
                    d.size,
                )
                .sqrt();
            }
            if let Some(uv) = target.uv.as_mut() {
                let b = &s.both_uv;
                uv.triangle[i] = uv.source;
                uv.uv_affine[i] = [b[0][k], b[1][k]];
                uv.uv_perspective[i] = [b[2][k], b[3][k]];
            }
        }
    }
}

/// The edge-function rasterizer's lane path for rows `rows` (within the target band), with
/// the `shading` `tri` was made for, at the vector level `vector`. With `shading` `None`, covered samples go to
/// `fallback(x, y, edges)` instead (the caller's per-pixel shading), still with block
/// rejection. `tri` must be [`exact`](LaneTriangle::exact).
pub fn edge_triangle(
    tri: &LaneTriangle,
    rows: (u32, u32),
    texture: &Texture,
    (shading, vector): (Option<LaneShading>, VectorLevel),
    target: &mut Target<'_>,
    fallback: &mut dyn FnMut(u32, u32, [i64; 3]),
) {
    if let Some(sh) = shading {
        return Lanes::new(texture, sh, vector).edge_triangle(tri, rows, target);
    }
    #[cfg(target_arch = "x86_64")]
    {
        if vector.avx2() {
            // SAFETY: the CPU supports AVX2, checked by `VectorLevel::avx2`.
            unsafe { edge_triangle_avx2(tri, rows, texture, shading, target, fallback) };
            return;
        }
    }
    edge_triangle_impl(tri, rows, texture, shading, target, fallback);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn edge_triangle_avx2(
    tri: &LaneTriangle,
    rows: (u32, u32),
    texture: &Texture,
    shading: Option<LaneShading>,
    target: &mut Target<'_>,
    fallback: &mut dyn FnMut(u32, u32, [i64; 3]),
) {
    edge_triangle_impl(tri, rows, texture, shading, target, fallback);
}

#[inline(always)]
fn edge_triangle_impl(
    tri: &LaneTriangle,
    (y_start, y_end): (u32, u32),
    texture: &Texture,
    shading: Option<LaneShading>,
    target: &mut Target<'_>,
    fallback: &mut dyn FnMut(u32, u32, [i64; 3]),
) {
    let planes = &tri.planes;
    let consts = &tri.consts;
    let color = shading.map_or(LaneColor::Texture, |s| s.color);
    let mode = shading.map_or(Interpolation::Perspective, |s| s.mode);
    let sampler = shading.map(|s| Sampler::new(texture, s.filter, s.wrap));
    let (x0, x1) = (tri.bounds.x0, tri.bounds.x1);
    let a = planes.a.map(|v| v as f64);
    let t = planes.t.map(|v| v as f64);
    let mut colors = [[0u8; 4]; LANES];
    for block in Blocks::new(planes, (x0, x1), (y_start, y_end)) {
        let bx = block.x;
        for y in block.rows.0..=block.rows.1 {
            let base = planes.at(i64::from(y), i64::from(bx));
            let mut e = [[0.0; LANES]; 3];
            for i in 0..3 {
                for k in 0..LANES {
                    e[i][k] = base[i] as f64 + a[i] * OFFSETS[k];
                }
            }
            let mut covered = [false; LANES];
            for k in 0..block.lanes_in {
                covered[k] = block.kind == Block::Inside
                    || (e[0][k] >= t[0] && e[1][k] >= t[1] && e[2][k] >= t[2]);
            }
            if !covered.iter().any(|&c| c) {
                continue;
            }
            match &sampler {
                Some(sampler) => {
                    let (rows, columns) = row_terms(&consts.weights, bx, y);
                    let mut s = from_terms(&rows, &columns, consts, mode);
                    for k in 0..LANES {
                        s.ok[k] &= covered[k];
                    }
                    // A difference target is not shaded (see `DifferenceTarget`).
                    match color {
                        _ if target.difference.is_some() => {}
                        LaneColor::Texture => sampler.sample(&s.u, &s.v, &mut colors),
                        _ => channel_colors(&s, color, &mut colors),
                    }
                    for k in 0..LANES {
                        if s.wire[k] {
                            colors[k] = WIRE_COLOR;
                        } else if s.halo[k] {
                            colors[k] = WIRE_HALO_COLOR;
                        }
                    }
                    write(target, bx, y, &s, &colors);
                }
                None => {
                    for k in 0..LANES {
                        if covered[k] {
                            let edges = [e[0][k] as i64, e[1][k] as i64, e[2][k] as i64];
                            fallback(bx + k as u32, y, edges);
                        }
                    }
                }
            }
        }
    }
}

/// The lanes' tests' random numbers: a xorshift64 generator from `seed` (not 0), the same
/// sequence every run.
#[cfg(test)]
fn xorshift(mut state: u64) -> impl FnMut() -> u64 {
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    }
}

#[cfg(test)]
mod tests {
    use crate::raster::texture::byte_from_sum;

    /// By default a frame of dense triangles draws with AVX2 instead of AVX-512 (the quad
    /// and a mesh of 5k triangles at 1080p keep AVX-512, meshes of 75k and 460k do not); a
    /// chosen level, and any level below AVX-512, is kept.
    #[test]
    fn dense_meshes_draw_with_avx2_by_default() {
        use super::VectorLevel::{self, *};
        let hd = 1920 * 1080;
        let level =
            |level, chosen, triangles| VectorLevel::frame_level(level, chosen, triangles, hd);
        assert_eq!(level(Avx512, false, 2), Avx512);
        assert_eq!(level(Avx512, false, 5_000), Avx512);
        assert_eq!(level(Avx512, false, 75_272), Avx2);
        assert_eq!(level(Avx512, false, 460_800), Avx2);
        assert_eq!(level(Avx512, true, 460_800), Avx512);
        for lower in [Scalar, Portable, Avx2] {
            assert_eq!(level(lower, false, 460_800), lower);
            assert_eq!(level(lower, false, 2), lower);
        }
        // At the boundary: 128 pixels a triangle keep AVX-512, fewer do not; no overflow.
        assert_eq!(VectorLevel::frame_level(Avx512, false, 10, 1280), Avx512);
        assert_eq!(VectorLevel::frame_level(Avx512, false, 10, 1279), Avx2);
        assert_eq!(
            VectorLevel::frame_level(Avx512, false, usize::MAX, hd),
            Avx2
        );
    }

    /// The nearest path writes the texel itself: `byte_from_sum(0 + 1 * c) == c`.
    #[test]
    fn a_byte_survives_the_weighted_sum() {
        for c in 0..=255u8 {
            assert_eq!(byte_from_sum(0.0 + 1.0 * f32::from(c)), c);
        }
    }

    /// `LaneTriangle::exact`'s cheap test is sufficient: triangles with every vertex at the
    /// edge of the near region (the extremes of the bound) have exact edge values over the
    /// largest image.
    #[test]
    fn vertices_near_the_origin_give_exact_edges_over_any_image() {
        use super::{EdgePlanes, PixelBounds};
        use crate::raster::setup::{Edge, TieRule};
        use glam::I64Vec2;
        let far = (1i64 << 24) - 1;
        let values = [-far, 0, far];
        let bounds = PixelBounds {
            x0: 0,
            y0: 0,
            x1: crate::raster::project::MAX_IMAGE_SIZE - 1,
            y1: crate::raster::project::MAX_IMAGE_SIZE - 1,
        };
        let mut checked = 0;
        for &ax in &values {
            for &ay in &values {
                for &bx in &values {
                    for &by in &values {
                        let p = [
                            I64Vec2::new(ax, ay),
                            I64Vec2::new(bx, by),
                            I64Vec2::new(-ax, -far),
                        ];
                        for positive in [false, true] {
                            let edge = |a: usize, b: usize| {
                                Edge::with_rule(p[a], p[b], positive, TieRule::Llvmpipe)
                            };
                            let edges = [edge(1, 2), edge(2, 0), edge(0, 1)];
                            assert!(EdgePlanes::from_edges(&edges).exact_over(&bounds), "{p:?}");
                            checked += 1;
                        }
                    }
                }
            }
        }
        assert_eq!(checked, 162);
        // Beyond the region the bound no longer holds: such a triangle takes the full check.
        let huge = 1i64 << 28;
        let p = [
            I64Vec2::new(-huge, -huge),
            I64Vec2::new(huge, -huge),
            I64Vec2::new(0, huge),
        ];
        let edge = |a: usize, b: usize| Edge::with_rule(p[a], p[b], true, TieRule::Llvmpipe);
        assert!(!EdgePlanes::from_edges(&[edge(1, 2), edge(2, 0), edge(0, 1)]).exact_over(&bounds));
    }
}
