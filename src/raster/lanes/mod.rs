//! The fast path: eight pixels of a row at a time, colour and depth only.
//!
//! (Longer than the project's ~600 lines: the portable lane code and the types the AVX2 and
//! AVX-512 files mirror are kept together, so a reader sees every step of the arithmetic that
//! must stay bit-identical in one place.)
//!
//! Both rasterizers have a lane form here, used when a render asks for colour and depth only
//! (the app's canvas, `barylab bench`). The edge-function lanes draw texture shading with
//! nearest or bilinear filtering, vertex colour, barycentric and depth shading, and the
//! wireframe overlay; the scanline lanes draw texture shading without the wireframe. Other
//! cases (trilinear filtering, the scanline rasterizer's other shadings) go through
//! [`render`](mod@super::render)'s per-pixel code (after the block rejection of the
//! edge-function path).
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
//!   per-pixel renderer and to what the probe reports.
//! - **Scanline** ([`scanline_triangle`]): exact integer spans per row
//!   ([`row_span`]); along a span `u/w`, `v/w`, `1/w` and the depth are stepped by their
//!   per-pixel increments (eight lanes advance by eight increments), and the
//!   perspective-correct uv is `(u/w) * (1 / (1/w))`, one division per pixel. Coverage is
//!   identical to the edge-function path; values agree up to floating-point rounding.
//!
//! Three builds of the same arithmetic, chosen at run time ([`VectorLevel`]): AVX2 intrinsics
//! (`avx2.rs`), with bilinear texture lookups of two chunks (sixteen pixels) at once in
//! AVX-512 when the CPU has it (`avx512.rs`), and portable lane code (plain arrays,
//! compiled with AVX2 enabled where available). No fused multiply-add is used anywhere, so
//! every build rounds identically; `tests/fast_path.rs` compares them all with the full
//! render.

// Lane code indexes several parallel arrays by the lane number; iterators would hide that.
#![allow(clippy::needless_range_loop)]

use std::sync::atomic::{AtomicU8, Ordering};

use super::framebuffer::depth_passes;
use super::interpolate::Interpolation;
use super::project::SUBPIXEL;
use super::scanline::row_span;
use super::setup::{PixelBounds, TriangleSetup, WeightPlanes};
use super::shade::{WIRE_COLOR, WIRE_HALO_COLOR, depth_grey, on_wire_edge, on_wire_halo, unorm8};
use super::texture::{
    self, Filter, Texture, Wrap, bilinear_fraction, bilinear_weights, byte_from_sum, wrap_coord,
};

#[cfg(target_arch = "x86_64")]
mod avx2;
#[cfg(target_arch = "x86_64")]
mod avx512;

/// The instruction sets the lane paths may use (each also needs the CPU to have it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum VectorLevel {
    /// The portable lane code only.
    Portable = 0,
    /// AVX2 intrinsics.
    Avx2 = 1,
    /// AVX2, with texture lookups of sixteen pixels at once in AVX-512.
    Avx512 = 2,
}

/// The highest [`VectorLevel`] allowed (the default: all).
static VECTOR_LEVEL: AtomicU8 = AtomicU8::new(VectorLevel::Avx512 as u8);

/// Limits the instruction sets the lane paths use. Every level gives the same pixels; tests
/// switch levels to compare them.
pub fn set_vector_level(level: VectorLevel) {
    VECTOR_LEVEL.store(level as u8, Ordering::Relaxed);
}

/// Whether the AVX2 intrinsics path is allowed and the CPU has AVX2.
#[cfg(target_arch = "x86_64")]
fn vector_path() -> bool {
    VECTOR_LEVEL.load(Ordering::Relaxed) >= VectorLevel::Avx2 as u8
        && std::arch::is_x86_feature_detected!("avx2")
}

/// Whether the AVX-512 texture lookups are allowed and the CPU has AVX-512 F and BW.
#[cfg(target_arch = "x86_64")]
fn wide_path() -> bool {
    VECTOR_LEVEL.load(Ordering::Relaxed) >= VectorLevel::Avx512 as u8
        && std::arch::is_x86_feature_detected!("avx512f")
        && std::arch::is_x86_feature_detected!("avx512bw")
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
/// optionally the triangle and uv both ways ([`Buffers::ColorDepthUv`]).
///
/// [`Buffers::ColorDepthUv`]: super::framebuffer::Buffers::ColorDepthUv
pub struct Target<'a> {
    pub y0: u32,
    pub width: u32,
    pub color: &'a mut [[u8; 4]],
    pub depth: &'a mut [f32],
    pub uv: Option<UvTarget<'a>>,
}

/// The triangle and uv buffers of a band, for the difference heatmap: where a fragment passes
/// the depth test, its source triangle, its `noperspective` uv and its `smooth` uv, as
/// [`interpolate::fragment`](super::interpolate::fragment) computes them (bit for bit).
pub struct UvTarget<'a> {
    /// The source triangle being drawn.
    pub source: u32,
    pub triangle: &'a mut [u32],
    pub uv_affine: &'a mut [[f32; 2]],
    pub uv_perspective: &'a mut [[f32; 2]],
}

/// What the lanes shade: texture (nearest or bilinear), vertex colour, barycentric weights or
/// depth ([`LaneColor`]), with the wireframe overlay on the edge-function path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LaneShading {
    pub mode: Interpolation,
    /// What the colour shows.
    pub color: LaneColor,
    /// The texture filter and wrap (used by [`LaneColor::Texture`]).
    pub filter: Filter,
    pub wrap: Wrap,
    /// Draw the source triangles' edges (see [`on_wire_edge`]).
    pub wireframe: bool,
}

/// The shadings of [`Shading`](super::shade::Shading) the lanes draw (texture lookups with
/// nearest or bilinear filtering only).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LaneColor {
    Texture,
    VertexColor,
    Barycentric,
    /// Grey from the window depth, black at `.0` and white at `.1`.
    Depth(f64, f64),
}

/// The edge functions of a triangle as planes over pixel indices:
/// `E_i(col, row) = a_i col + b_i row + c_i`, the value at the pixel centre
/// `(256 col + 128, 256 row + 128)` (1/256 pixel units). A pixel passes edge `i` when
/// `E_i >= t_i`, with `t_i = 0` on an inclusive (left or bottom) edge and 1 otherwise.
///
/// ```
/// use barylab::raster::clip::ClipVertex;
/// use barylab::raster::lanes::EdgePlanes;
/// use barylab::raster::project::{project_vertex, Viewport};
/// use barylab::raster::setup::{sample_point, setup_triangle};
/// use barylab::raster::varying::Varyings;
/// use glam::DVec4;
/// let vp = Viewport { width: 8, height: 8 };
/// let at = |x: f64, y: f64| project_vertex(&ClipVertex::new(
///     DVec4::new(x / 4.0 - 1.0, 1.0 - y / 4.0, 0.0, 1.0), Varyings::default()), vp);
/// let s = setup_triangle([at(0.0, 0.0), at(8.0, 0.0), at(0.0, 8.0)], vp).unwrap();
/// let planes = EdgePlanes::new(&s);
/// // The planes give the setup's own edge values at every pixel centre.
/// assert_eq!(planes.at(2, 3), s.edge_values(sample_point(3, 2)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EdgePlanes {
    pub a: [i64; 3],
    pub b: [i64; 3],
    pub c: [i64; 3],
    pub t: [i64; 3],
}

impl EdgePlanes {
    /// From `E(P) = dir_x (P_y - S_y) - dir_y (P_x - S_x)` with `P = (256 col + 128, 256 row + 128)`.
    pub fn new(setup: &TriangleSetup) -> Self {
        let half = SUBPIXEL / 2;
        let mut out = Self {
            a: [0; 3],
            b: [0; 3],
            c: [0; 3],
            t: [0; 3],
        };
        for (i, e) in setup.edges.iter().enumerate() {
            out.a[i] = -e.dir.y * SUBPIXEL;
            out.b[i] = e.dir.x * SUBPIXEL;
            out.c[i] = e.dir.x * (half - e.start.y) - e.dir.y * (half - e.start.x);
            out.t[i] = e.min_value();
        }
        out
    }

    /// The three edge values at pixel (col, row).
    pub fn at(&self, row: i64, col: i64) -> [i64; 3] {
        [0, 1, 2].map(|i| self.a[i] * col + self.b[i] * row + self.c[i])
    }

    /// Whether every edge value over the columns `x0..=x1 + LANES` and rows `y0..=y1` is
    /// exact in `f64` (an edge function is linear, so its extremes are at the corners).
    fn exact_over(&self, b: &PixelBounds) -> bool {
        let (x0, x1) = (i64::from(b.x0), i64::from(b.x1) + LANES as i64);
        let (y0, y1) = (i64::from(b.y0), i64::from(b.y1));
        [(y0, x0), (y0, x1), (y1, x0), (y1, x1)]
            .iter()
            .all(|&(r, c)| self.at(r, c).iter().all(|v| v.abs() < EXACT_EDGE_LIMIT))
    }
}

/// How a block relates to the triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Block {
    /// Outside one edge at all four corners: no pixel is covered.
    Outside,
    /// Inside every edge at all four corners: every pixel is covered.
    Inside,
    /// Pixels need testing one by one.
    Partial,
}

fn classify(planes: &EdgePlanes, cols: (i64, i64), rows: (i64, i64)) -> Block {
    let corners = [
        planes.at(rows.0, cols.0),
        planes.at(rows.0, cols.1),
        planes.at(rows.1, cols.0),
        planes.at(rows.1, cols.1),
    ];
    let mut inside = true;
    for i in 0..3 {
        let lo = corners.iter().map(|e| e[i]).min().unwrap_or(0);
        let hi = corners.iter().map(|e| e[i]).max().unwrap_or(0);
        if hi < planes.t[i] {
            return Block::Outside;
        }
        inside &= lo >= planes.t[i];
    }
    if inside {
        Block::Inside
    } else {
        Block::Partial
    }
}

/// Per-triangle constants of the interpolation, as [`interpolate::fragment`] uses them.
///
/// [`interpolate::fragment`]: super::interpolate::fragment
#[derive(Clone, Copy, Debug)]
struct Constants {
    weights: WeightPlanes,
    inv_w: [f64; 3],
    depth: [f64; 3],
    u: [f64; 3],
    v: [f64; 3],
    /// uv of both attribute sets, `[u_affine, v_affine, u_smooth, v_smooth]` per vertex, when
    /// the target wants them.
    both_uv: Option<[[f64; 3]; 4]>,
    /// `channels[c][k]`: channel `c` of vertex `k` for vertex-colour or barycentric shading.
    channels: [[f64; 3]; 3],
    wire: Option<Wire>,
}

/// The wireframe test of [`shade`](super::shade::shade): a sample is on a line when, for a
/// source-triangle vertex `i` whose weight changes on screen (`len_i > 0`), its affine
/// weight (as `f32`) over `len_i` is below [`WIRE_WIDTH_PX`].
#[derive(Clone, Copy, Debug)]
struct Wire {
    /// `bary[i][k]`: source weight `i` at rasterized vertex `k`.
    bary: [[f64; 3]; 3],
    /// `|grad l_i|`, per pixel.
    len: [f64; 3],
}

impl Constants {
    /// `mode` picks the vertices' attribute set: `smooth` (perspective-correct) or
    /// `noperspective` (affine). The wireframe uses the `smooth` source weights with screen
    /// weights, as [`Fragment::edge_weights`](super::interpolate::Fragment::edge_weights).
    fn new(setup: &TriangleSetup, mode: Interpolation, wireframe: bool, color: LaneColor) -> Self {
        let vary = |k: usize| match mode {
            Interpolation::Perspective => &setup.v[k].varyings,
            Interpolation::Affine => &setup.v[k].noperspective,
        };
        let uv = [0, 1, 2].map(|k| vary(k).uv());
        let per_vertex = |f: &dyn Fn(usize) -> [f32; 3]| {
            let at = [f(0), f(1), f(2)];
            [0, 1, 2].map(|c| [0, 1, 2].map(|k| f64::from(at[k][c])))
        };
        let channels = match color {
            LaneColor::VertexColor => per_vertex(&|k| vary(k).color().to_array()),
            LaneColor::Barycentric => per_vertex(&|k| vary(k).bary()),
            LaneColor::Texture | LaneColor::Depth(..) => [[0.0; 3]; 3],
        };
        let wire = wireframe.then(|| {
            let b = setup.v.map(|v| v.varyings.bary());
            Wire {
                bary: [0, 1, 2].map(|i| [0, 1, 2].map(|k| f64::from(b[k][i]))),
                len: setup.source_weight_gradients().map(|g| g.length()),
            }
        });
        Self {
            weights: setup.weights,
            inv_w: setup.v.map(|v| v.inv_w),
            depth: setup.v.map(|v| v.depth),
            u: uv.map(|t| f64::from(t.x)),
            v: uv.map(|t| f64::from(t.y)),
            both_uv: None,
            channels,
            wire,
        }
    }
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
    channels: [F32s; 3],
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
            channels: [[0.0; LANES]; 3],
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
            _ => [
                unorm8(s.channels[0][k]),
                unorm8(s.channels[1][k]),
                unorm8(s.channels[2][k]),
                255,
            ],
        };
    }
}

/// The vertices' uv of both attribute sets, `[u_affine, v_affine, u_smooth, v_smooth]`
/// (the `noperspective` set, then the `smooth` one), for [`Constants::both_uv`].
fn both_uv(setup: &TriangleSetup) -> [[f64; 3]; 4] {
    let uv = |k: usize, smooth: bool| {
        let v = if smooth {
            &setup.v[k].varyings
        } else {
            &setup.v[k].noperspective
        };
        v.uv().as_dvec2()
    };
    [
        [0, 1, 2].map(|k| uv(k, false).x),
        [0, 1, 2].map(|k| uv(k, false).y),
        [0, 1, 2].map(|k| uv(k, true).x),
        [0, 1, 2].map(|k| uv(k, true).y),
    ]
}

/// The screen weights of the eight pixels `x, x + 1, ...` of row `y`, as
/// [`WeightPlanes::at_pixel`] computes them.
#[inline(always)]
fn row_weights(w: &WeightPlanes, x: u32, y: u32) -> [F64s; 3] {
    let py = f64::from(y) + 0.5;
    let mut l = [[0.0; LANES]; 3];
    for i in 0..3 {
        let row = w.row_term(i, py);
        for k in 0..LANES {
            l[i][k] = w.weight(i, row, (f64::from(x) + OFFSETS[k]) + 0.5);
        }
    }
    l
}

/// From screen weights, exactly as `interpolate::fragment` computes them:
/// `q_i = l_i / w_i`, `p_i = q_i / sum q`, `uv = sum w_i uv_i` with the mode's weights,
/// `depth = sum l_i d_i`; a sample is valid when `sum q` is positive and finite.
#[inline(always)]
fn from_weights(lw: &[F64s; 3], c: &Constants, mode: Interpolation) -> Samples {
    let mut out = Samples::new();
    for k in 0..LANES {
        let l = [lw[0][k], lw[1][k], lw[2][k]];
        let q = [l[0] * c.inv_w[0], l[1] * c.inv_w[1], l[2] * c.inv_w[2]];
        let sum = q[0] + q[1] + q[2];
        out.ok[k] = sum > 0.0 && sum < f64::INFINITY;
        let inv = 1.0 / sum;
        if let Some(b) = &c.both_uv {
            let p = [q[0] * inv, q[1] * inv, q[2] * inv];
            for (j, x) in b.iter().enumerate() {
                let w = if j < 2 { &l } else { &p };
                out.both_uv[j][k] = (w[0] * x[0] + w[1] * x[1] + w[2] * x[2]) as f32;
            }
        }
        let w = match mode {
            Interpolation::Perspective => [q[0] * inv, q[1] * inv, q[2] * inv],
            Interpolation::Affine => l,
        };
        out.u[k] = (w[0] * c.u[0] + w[1] * c.u[1] + w[2] * c.u[2]) as f32;
        out.v[k] = (w[0] * c.v[0] + w[1] * c.v[1] + w[2] * c.v[2]) as f32;
        out.depth64[k] = l[0] * c.depth[0] + l[1] * c.depth[1] + l[2] * c.depth[2];
        out.depth[k] = out.depth64[k] as f32;
        for ch in 0..3 {
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

/// The texture module's `texel_floor` as an `i32` (it clamps to +-1e9, which fits).
#[inline(always)]
fn texel_floor(x: f32) -> i32 {
    texture::texel_floor(x) as i32
}

/// A wrap mode applied to lanes of texel coordinates along one axis of `size` texels.
#[derive(Clone, Copy)]
enum LaneWrap {
    /// Repeat on a power-of-two size: a mask (two's complement makes it `rem_euclid`).
    Mask(i32),
    /// Clamp to edge: `clamp(0, size - 1)`.
    Clamp(i32),
    /// Anything else: the texture module's `wrap_coord` outside the texture.
    General(u32, Wrap),
}

impl LaneWrap {
    fn new(size: u32, wrap: Wrap) -> Self {
        match wrap {
            Wrap::Repeat if size.is_power_of_two() => LaneWrap::Mask(size as i32 - 1),
            Wrap::ClampToEdge => LaneWrap::Clamp(size as i32 - 1),
            _ => LaneWrap::General(size, wrap),
        }
    }

    #[inline(always)]
    fn apply(self, i: i32) -> usize {
        match self {
            LaneWrap::Mask(m) => (i & m) as usize,
            LaneWrap::Clamp(hi) => i.clamp(0, hi) as usize,
            LaneWrap::General(size, wrap) => {
                if (0..size as i32).contains(&i) {
                    i as usize
                } else {
                    wrap_coord(i64::from(i), size, wrap) as usize
                }
            }
        }
    }
}

/// The base level of a texture, ready for lane lookups.
struct Sampler<'a> {
    texels: &'a [[u8; 4]],
    width: usize,
    size: (f32, f32),
    wrap: (LaneWrap, LaneWrap),
    filter: Filter,
}

impl<'a> Sampler<'a> {
    fn new(texture: &'a Texture, filter: Filter, wrap: Wrap) -> Self {
        let (w, h) = (texture.width(), texture.height());
        Self {
            texels: texture.base_texels(),
            width: w as usize,
            size: (w as f32, h as f32),
            wrap: (LaneWrap::new(w, wrap), LaneWrap::new(h, wrap)),
            filter,
        }
    }

    #[inline(always)]
    fn texel(&self, i: usize, j: usize) -> [u8; 4] {
        self.texels[j * self.width + i]
    }

    /// The colours at eight uv, as [`Texture::sample_rgba8`] computes them.
    #[inline(always)]
    fn sample(&self, u: &F32s, v: &F32s, out: &mut [[u8; 4]; LANES]) {
        match self.filter {
            // One texel of weight 1: `round(0 + 1 * c)` is exactly `c`, so the texel is the
            // colour.
            Filter::Nearest => {
                for k in 0..LANES {
                    let i = self.wrap.0.apply(texel_floor(u[k] * self.size.0));
                    let j = self.wrap.1.apply(texel_floor(v[k] * self.size.1));
                    out[k] = self.texel(i, j);
                }
            }
            _ => {
                for k in 0..LANES {
                    let x = u[k] * self.size.0 - 0.5;
                    let y = v[k] * self.size.1 - 0.5;
                    let (i0, j0) = (texel_floor(x), texel_floor(y));
                    let (a, b) = (bilinear_fraction(x), bilinear_fraction(y));
                    let (ia, ib) = (self.wrap.0.apply(i0), self.wrap.0.apply(i0 + 1));
                    let (ja, jb) = (self.wrap.1.apply(j0), self.wrap.1.apply(j0 + 1));
                    let weights = bilinear_weights(a, b);
                    let texels = [
                        self.texel(ia, ja),
                        self.texel(ib, ja),
                        self.texel(ia, jb),
                        self.texel(ib, jb),
                    ];
                    let mut sum = [0.0f32; 4];
                    for (wt, t) in weights.iter().zip(&texels) {
                        for ch in 0..4 {
                            sum[ch] += wt * f32::from(t[ch]);
                        }
                    }
                    out[k] = sum.map(byte_from_sum);
                }
            }
        }
    }
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
            target.color[i] = colors[k];
            if let Some(uv) = target.uv.as_mut() {
                let b = &s.both_uv;
                uv.triangle[i] = uv.source;
                uv.uv_affine[i] = [b[0][k], b[1][k]];
                uv.uv_perspective[i] = [b[2][k], b[3][k]];
            }
        }
    }
}

/// Whether the lane path can draw this triangle: edge values exact in `f64` over its bounds.
pub fn edge_lanes_apply(setup: &TriangleSetup) -> bool {
    EdgePlanes::new(setup).exact_over(&setup.bounds)
}

/// The edge-function rasterizer's lane path for rows `rows` (within the target band).
/// With `shading` `None`, covered samples go to `fallback(x, y, edges)` instead (the caller's
/// per-pixel shading), still with block rejection.
pub fn edge_triangle(
    setup: &TriangleSetup,
    rows: (u32, u32),
    texture: &Texture,
    shading: Option<LaneShading>,
    target: &mut Target<'_>,
    fallback: &mut dyn FnMut(u32, u32, [i64; 3]),
) {
    #[cfg(target_arch = "x86_64")]
    {
        if vector_path() {
            if let Some(sh) = shading {
                let sampler = avx2::VecSampler::new(texture, &sh);
                if sh.color != LaneColor::Texture || sampler.is_some() {
                    // SAFETY: the CPU supports AVX2, checked by `vector_path`.
                    unsafe {
                        avx2::edge_triangle(setup, rows, sampler.as_ref(), wide_path(), &sh, target)
                    };
                    return;
                }
            }
            // SAFETY: as above.
            unsafe { edge_triangle_avx2(setup, rows, texture, shading, target, fallback) };
            return;
        }
    }
    edge_triangle_impl(setup, rows, texture, shading, target, fallback);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn edge_triangle_avx2(
    setup: &TriangleSetup,
    rows: (u32, u32),
    texture: &Texture,
    shading: Option<LaneShading>,
    target: &mut Target<'_>,
    fallback: &mut dyn FnMut(u32, u32, [i64; 3]),
) {
    edge_triangle_impl(setup, rows, texture, shading, target, fallback);
}

#[inline(always)]
fn edge_triangle_impl(
    setup: &TriangleSetup,
    (y_start, y_end): (u32, u32),
    texture: &Texture,
    shading: Option<LaneShading>,
    target: &mut Target<'_>,
    fallback: &mut dyn FnMut(u32, u32, [i64; 3]),
) {
    let planes = EdgePlanes::new(setup);
    let color = shading.map_or(LaneColor::Texture, |s| s.color);
    let mode = shading.map_or(Interpolation::Perspective, |s| s.mode);
    let mut consts = Constants::new(setup, mode, shading.is_some_and(|s| s.wireframe), color);
    if target.uv.is_some() {
        consts.both_uv = Some(both_uv(setup));
    }
    let sampler = shading.map(|s| Sampler::new(texture, s.filter, s.wrap));
    let (x0, x1) = (setup.bounds.x0, setup.bounds.x1);
    let a = planes.a.map(|v| v as f64);
    let t = planes.t.map(|v| v as f64);
    let mut colors = [[0u8; 4]; LANES];
    let mut by = y_start;
    while by <= y_end {
        let by_end = (by + BLOCK_ROWS - 1).min(y_end);
        let mut bx = x0;
        while bx <= x1 {
            let bx_end = bx + LANES as u32 - 1;
            let block = classify(
                &planes,
                (i64::from(bx), i64::from(bx_end)),
                (i64::from(by), i64::from(by_end)),
            );
            if block != Block::Outside {
                let lanes_in = (x1 - bx + 1).min(LANES as u32) as usize;
                for y in by..=by_end {
                    let base = planes.at(i64::from(y), i64::from(bx));
                    let mut e = [[0.0; LANES]; 3];
                    for i in 0..3 {
                        for k in 0..LANES {
                            e[i][k] = base[i] as f64 + a[i] * OFFSETS[k];
                        }
                    }
                    let mut covered = [false; LANES];
                    for k in 0..lanes_in {
                        covered[k] = block == Block::Inside
                            || (e[0][k] >= t[0] && e[1][k] >= t[1] && e[2][k] >= t[2]);
                    }
                    if !covered.iter().any(|&c| c) {
                        continue;
                    }
                    match &sampler {
                        Some(sampler) => {
                            let l = row_weights(&consts.weights, bx, y);
                            let mut s = from_weights(&l, &consts, mode);
                            for k in 0..LANES {
                                s.ok[k] &= covered[k];
                            }
                            match color {
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
            bx += LANES as u32;
        }
        by = by_end + 1;
    }
}

/// The scanline rasterizer's lane path for rows `rows` (within the target band).
pub fn scanline_triangle(
    setup: &TriangleSetup,
    rows: (u32, u32),
    texture: &Texture,
    shading: LaneShading,
    target: &mut Target<'_>,
) {
    #[cfg(target_arch = "x86_64")]
    {
        if vector_path() {
            if let Some(sampler) = avx2::VecSampler::new(texture, &shading) {
                // SAFETY: the CPU supports AVX2, checked by `vector_path`.
                unsafe {
                    avx2::scanline_triangle(
                        setup,
                        rows,
                        &sampler,
                        wide_path(),
                        shading.mode,
                        target,
                    )
                };
                return;
            }
            // SAFETY: as above.
            unsafe { scanline_triangle_avx2(setup, rows, texture, shading, target) };
            return;
        }
    }
    scanline_triangle_impl(setup, rows, texture, shading, target);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn scanline_triangle_avx2(
    setup: &TriangleSetup,
    rows: (u32, u32),
    texture: &Texture,
    shading: LaneShading,
    target: &mut Target<'_>,
) {
    scanline_triangle_impl(setup, rows, texture, shading, target);
}

/// What the scanline lanes step: `u`, `v` (divided by w when perspective-correct), `1/w`
/// and depth, each linear along a row.
#[derive(Clone, Copy, Default)]
struct Stepped {
    u: f64,
    v: f64,
    inv_w: f64,
    depth: f64,
}

impl Stepped {
    /// The stepped quantities for screen weights `l` (a point's weights, or their per-pixel
    /// increments: the map is linear).
    fn from_weights(l: [f64; 3], c: &Constants, mode: Interpolation) -> Self {
        let mut s = Self::default();
        for k in 0..3 {
            let scale = match mode {
                Interpolation::Perspective => l[k] * c.inv_w[k],
                Interpolation::Affine => l[k],
            };
            s.u += scale * c.u[k];
            s.v += scale * c.v[k];
            s.inv_w += l[k] * c.inv_w[k];
            s.depth += l[k] * c.depth[k];
        }
        s
    }

    /// The increments per pixel along a row: the map applied to the screen weights'
    /// increments [`WeightPlanes::step_x`] (as the per-pixel scanline rasterizer steps them).
    fn row_step(c: &Constants, mode: Interpolation) -> Self {
        Self::from_weights(c.weights.step_x(), c, mode)
    }

    /// The values at the first pixel `x0` of a span of row `y`.
    fn span_start(c: &Constants, mode: Interpolation, x0: u32, y: u32) -> Self {
        Self::from_weights(c.weights.at_pixel(x0, y), c, mode)
    }

    /// The values of a row's first eight pixels: lane k is `start` after k single steps.
    fn lanes(start: Self, step: &Self) -> [Self; LANES] {
        let mut lanes = [start; LANES];
        for k in 1..LANES {
            let p = lanes[k - 1];
            lanes[k] = Self {
                u: p.u + step.u,
                v: p.v + step.v,
                inv_w: p.inv_w + step.inv_w,
                depth: p.depth + step.depth,
            };
        }
        lanes
    }
}

#[inline(always)]
fn scanline_triangle_impl(
    setup: &TriangleSetup,
    (y_start, y_end): (u32, u32),
    texture: &Texture,
    shading: LaneShading,
    target: &mut Target<'_>,
) {
    // The scanline lanes draw no wireframe (the caller sends that case to the per-pixel
    // scanline code).
    let mode = shading.mode;
    let consts = Constants::new(setup, mode, false, LaneColor::Texture);
    let sampler = Sampler::new(texture, shading.filter, shading.wrap);
    let step = Stepped::row_step(&consts, mode);
    let mut colors = [[0u8; 4]; LANES];
    for y in y_start..=y_end {
        let Some((x0, x1)) = row_span(setup, y) else {
            continue;
        };
        let start = Stepped::span_start(&consts, mode, x0, y);
        // Lane k holds pixel x0 + k; each chunk advances every lane by eight increments.
        let mut lanes = Stepped::lanes(start, &step);
        let n = LANES as f64;
        let (su, sv, sw, sd) = (step.u * n, step.v * n, step.inv_w * n, step.depth * n);
        let mut x = x0;
        while x <= x1 {
            let lanes_in = (x1 - x + 1).min(LANES as u32) as usize;
            let mut s = Samples::new();
            for k in 0..LANES {
                let l = &lanes[k];
                s.ok[k] = k < lanes_in && l.inv_w > 0.0 && l.inv_w < f64::INFINITY;
                let (u, v) = match mode {
                    Interpolation::Perspective => {
                        let w = 1.0 / l.inv_w;
                        (l.u * w, l.v * w)
                    }
                    Interpolation::Affine => (l.u, l.v),
                };
                s.u[k] = u as f32;
                s.v[k] = v as f32;
                s.depth[k] = l.depth as f32;
            }
            sampler.sample(&s.u, &s.v, &mut colors);
            write(target, x, y, &s, &colors);
            for l in lanes.iter_mut() {
                l.u += su;
                l.v += sv;
                l.inv_w += sw;
                l.depth += sd;
            }
            x += LANES as u32;
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::raster::texture::byte_from_sum;

    /// The nearest path writes the texel itself: `byte_from_sum(0 + 1 * c) == c`.
    #[test]
    fn a_byte_survives_the_weighted_sum() {
        for c in 0..=255u8 {
            assert_eq!(byte_from_sum(0.0 + 1.0 * f32::from(c)), c);
        }
    }
}
