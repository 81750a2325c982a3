//! MSAA into colour and depth only ([`Buffers::ColorDepth`](super::framebuffer::Buffers),
//! what `render_into` draws for the app's canvas and `barylab bench`): the pixels of the
//! per-sample kernel of [`multisample`](super::multisample) (`tests/samples_fast.rs` compares
//! the two on random scenes), with less work per pixel.
//!
//! - Coverage: in a row, the pixels whose sample `k` a triangle covers form an interval. With
//!   `E_i(x) = A_i + b_i x`, `b_i = -256 dir_i.y`, the snapped edge function at sample `k` of
//!   pixel `x` (exact integers), edge `i` passes for `x >= ceil((m_i - A_i) / b_i)` when
//!   `b_i > 0` and `x <= floor((A_i - m_i) / -b_i)` when `b_i < 0` (`m_i` the tie rule's
//!   smallest passing value). A pixel's mask is which of the `n` intervals hold it; between
//!   the largest start and the smallest end every sample is covered.
//! - Shading: MSAA shades at the pixel centre wherever it is not the centroid of a partly
//!   covered pixel, and the fragment at the centre is the single-sample fragment: the SIMD
//!   lanes draw the triangle once, one sample per pixel, into a scratch band, and their colour
//!   is taken (a pixel the lanes left is shaded per pixel, [`shared_shading`]).
//! - Samples: a pixel no triangle has reached yet, all of whose samples a triangle covers, when
//!   every depth of the triangle over its bounds is below the clear depth 1 (so every sample
//!   passes the depth test), keeps one colour and the triangle ("uniform"). Its sample depths
//!   are computed only when needed: sample 0's at the resolve, and all of them when another
//!   triangle reaches the pixel, which then keeps every sample. The values are computed with
//!   the same operations as the per-sample kernel ([`sample_depth`]), so they are the same.

use std::cell::RefCell;

use glam::{DVec2, I64Vec2};

use crate::budget::{MemoryError, try_resize};

use super::draw::lane_shading;
use super::framebuffer::{Buffers, Framebuffer, RowBand, depth_passes};
use super::interpolate;
use super::lanes::{LaneTriangle, Lanes, Target, VectorLevel};
use super::mesh::ClipMesh;
use super::multisample::{Drawn, SampleContext, drawn_and_bins, sample_depth, shared_shading};
use super::prepare::PreparedTriangle;
use super::project::SUBPIXEL;
use super::sample::{Location, resolve, sample_at, window_position};
use super::setup::{PixelBounds, TriangleSetup};
use super::varying::Varyings;

/// A pixel no triangle has written: every sample the background at depth 1.
const CLEAR: u32 = 0;
/// A pixel that keeps each sample.
const EXPANDED: u32 = u32::MAX;

/// Whether the fast path draws these samples into a band of colour and depth: MSAA (one
/// shading per pixel) at the centre or the centroid, without `flat` attributes.
pub(super) fn applies(ctx: &SampleContext<'_>) -> bool {
    !ctx.samples.per_sample_shading()
        && !ctx.samples.flat
        && ctx.samples.location != Location::Sample
}

/// The memory of a band's drawing, kept per thread from frame to frame.
#[derive(Default)]
struct Scratch {
    /// The lanes' single-sample colour of the triangle being drawn.
    lane_color: Vec<[u8; 4]>,
    /// The lanes' depth: infinite where they wrote nothing.
    lane_depth: Vec<f32>,
    /// Per pixel: [`CLEAR`], [`EXPANDED`], or `t + 1` for uniform from triangle `t` (its
    /// colour then in the band's colour buffer).
    owner: Vec<u32>,
    /// An expanded pixel's sample colours.
    sample_color: Vec<[u8; 4]>,
    /// An expanded pixel's sample depths (where `sample_writer` is 0).
    sample_depth: Vec<f32>,
    /// 0 when the sample's depth is in `sample_depth`, else `t + 1`: triangle `t` wrote it and
    /// its depth is still to be computed.
    sample_writer: Vec<u32>,
}

thread_local! {
    static SCRATCH: RefCell<Scratch> = RefCell::default();
}

/// Whether every depth a triangle can give a sample within `bounds` passes the depth test
/// against the clear depth 1. The depth (`sum l_i d_i`, from its plane) is affine in the window position, so
/// its largest value over the bounds' rectangle is at a corner; the margin covers the
/// rounding of the `f64` evaluation (relative to the size of its terms) and of the `f32`
/// that is stored.
fn below_clear_depth(setup: &TriangleSetup, b: &PixelBounds) -> bool {
    let w = &setup.weights;
    let corners = [
        (b.x0, b.y0),
        (b.x1 + 1, b.y0),
        (b.x0, b.y1 + 1),
        (b.x1 + 1, b.y1 + 1),
    ];
    corners.iter().all(|&(x, y)| {
        let p = DVec2::new(f64::from(x), f64::from(y));
        let l = w.at(p);
        let d = interpolate::depth_at(setup, p);
        let size: f64 = (0..3)
            .map(|i| {
                let terms = (w.dir[i].x * (p.y - w.start[i].y)).abs()
                    + (w.dir[i].y * (p.x - w.start[i].x)).abs();
                (terms * w.inv_area2.abs() + l[i].abs()) * setup.v[i].depth.abs()
            })
            .sum();
        d + 1e-9 * (1.0 + size) < 1.0 - 1e-6
    })
}

/// The pixels `[lo, hi]` of row `y` (within `x0..=x1`) whose sample at `offset` the
/// triangle covers; `lo > hi` when none.
fn covered_run(setup: &TriangleSetup, y: u32, offset: I64Vec2, (x0, x1): (u32, u32)) -> (i64, i64) {
    let (mut lo, mut hi) = (i64::from(x0), i64::from(x1));
    // The sample of pixel x lies at (256 x + o_x, 256 y + o_y).
    let py = i64::from(y) * SUBPIXEL + offset.y;
    for e in &setup.edges {
        let a = e.dir.x * (py - e.start.y) - e.dir.y * (offset.x - e.start.x);
        let b = -e.dir.y * SUBPIXEL;
        let m = e.min_value();
        match b.signum() {
            0 if a < m => return (1, 0),
            0 => {}
            1 => lo = lo.max(-(a - m).div_euclid(b)),
            _ => hi = hi.min((a - m).div_euclid(-b)),
        }
    }
    (lo, hi)
}

/// Draws `triangles` (in submission order) into one band of colour and depth with the
/// samples of `ctx`, then resolves: the same colour and depth as
/// [`multisample::draw_band`](super::multisample) gives the band. The thread's scratch
/// memory is asked for fallibly: refused, it is an error naming it, never an abort.
pub(super) fn draw_band(
    triangles: &[Drawn<'_>],
    bin: &[(u32, u32)],
    ctx: &SampleContext<'_>,
    (vector, background): (VectorLevel, [u8; 4]),
    band: &mut RowBand<'_>,
) -> Result<(), MemoryError> {
    SCRATCH.with_borrow_mut(|s| {
        s.fit(band, ctx.offsets.len())?;
        let lanes = lane_shading(ctx.params).map(|sh| Lanes::new(ctx.texture, sh, vector));
        for &(t, _) in bin {
            draw_triangle(triangles, t, ctx, lanes.as_ref(), (s, band), background);
        }
        resolve_band(triangles, ctx, (s, vector), band, background);
        Ok(())
    })
}

impl Scratch {
    /// Sizes the scratch for a band (its pixels, `n` samples each) with every pixel clear.
    fn fit(&mut self, band: &RowBand<'_>, n: usize) -> Result<(), MemoryError> {
        let pixels = band.color.len();
        let (w, rows) = (band.width, band.rows);
        let what = |buffer: &'static str| {
            move || format!("the {w}x{rows} MSAA band's {buffer} ({n} samples a pixel)")
        };
        try_resize(&mut self.lane_color, pixels, [0; 4], what("centre colours"))?;
        try_resize(
            &mut self.lane_depth,
            pixels,
            f32::INFINITY,
            what("centre depths"),
        )?;
        self.owner.clear();
        try_resize(&mut self.owner, pixels, CLEAR, what("pixel owners"))?;
        let samples = pixels.saturating_mul(n);
        try_resize(
            &mut self.sample_color,
            samples,
            [0; 4],
            what("sample colours"),
        )?;
        try_resize(&mut self.sample_depth, samples, 1.0, what("sample depths"))?;
        try_resize(&mut self.sample_writer, samples, 0, what("sample writers"))
    }
}

/// Draws triangle `t` of `triangles` into the band's samples; a pixel it makes uniform gets
/// its colour in the band's colour buffer at once.
fn draw_triangle(
    triangles: &[Drawn<'_>],
    t: u32,
    ctx: &SampleContext<'_>,
    lanes: Option<&Lanes<'_>>,
    (s, band): (&mut Scratch, &mut RowBand<'_>),
    background: [u8; 4],
) {
    let (setup, _, ref flat, bounds) = triangles[t as usize];
    let flat = flat.as_ref();
    let Some((y_start, y_end)) = band.rows_of(&bounds) else {
        return;
    };
    let (width, y0) = (band.width as usize, band.y0);
    let row_index = |y: u32| (y - y0) as usize * width;
    // The lanes' single-sample colours of this triangle's rows, in the scratch band.
    for y in y_start..=y_end {
        let r = row_index(y);
        s.lane_depth[r + bounds.x0 as usize..=r + bounds.x1 as usize].fill(f32::INFINITY);
    }
    // A triangle between pixel centres (empty centre bounds) has nothing for the lanes.
    let centres = setup.bounds.x0 <= setup.bounds.x1 && setup.bounds.y0 <= setup.bounds.y1;
    if let Some(lanes) = lanes.filter(|_| centres) {
        let tri = LaneTriangle::of(setup, Some(lanes.shading()), false);
        if tri.exact()
            && let Some(rows) = band.rows_of(&tri.bounds())
        {
            let mut target = Target {
                y0: band.y0,
                width: band.width,
                color: &mut s.lane_color,
                depth: &mut s.lane_depth,
                uv: None,
                difference: None,
            };
            lanes.edge_triangle(&tri, rows, &mut target);
        }
    }
    let wire = if ctx.params.wireframe {
        setup.source_weight_gradients()
    } else {
        [DVec2::ZERO; 3]
    };
    let n = ctx.offsets.len();
    let uniform = below_clear_depth(setup, &bounds);
    let mut runs = [(0i64, 0i64); 16];
    for y in y_start..=y_end {
        let r = row_index(y);
        let (mut any_lo, mut any_hi) = (i64::MAX, i64::MIN);
        let (mut full_lo, mut full_hi) = (i64::MIN, i64::MAX);
        for (run, &o) in runs.iter_mut().zip(ctx.offsets) {
            *run = covered_run(setup, y, o, (bounds.x0, bounds.x1));
            if run.0 <= run.1 {
                any_lo = any_lo.min(run.0);
                any_hi = any_hi.max(run.1);
            }
            full_lo = full_lo.max(run.0);
            full_hi = full_hi.min(run.1);
        }
        let full = (full_lo.max(any_lo), full_hi.min(any_hi));
        let row = Row {
            y,
            r,
            runs: &runs[..n],
            full,
            uniform,
        };
        // The pixels each side of the full run, and the full run itself unless every pixel of
        // it became uniform here.
        let mut spans = [(any_lo, full.0 - 1), (full.1 + 1, any_hi), full];
        if full.0 > full.1 {
            spans = [(any_lo, any_hi), (1, 0), (1, 0)];
        } else if uniform && claim_run(t, (s, band), r, full) {
            spans[2] = (1, 0);
        }
        for (lo, hi) in spans {
            for x in lo..=hi {
                draw_pixel(
                    triangles,
                    t,
                    ctx,
                    (&row, x),
                    (s, band),
                    (flat, &wire, background),
                );
            }
        }
    }
}

/// One row of a triangle's pass: its image row `y`, the index `r` of the row's first pixel
/// in the band, each sample's covered run, the run where all are covered, and whether the
/// triangle's samples all pass the depth test against a clear pixel ([`below_clear_depth`]).
struct Row<'r> {
    y: u32,
    r: usize,
    runs: &'r [(i64, i64)],
    full: (i64, i64),
    uniform: bool,
}

/// Makes the clear pixels of the run `full` of the row at `r` that the lanes shaded uniform
/// from triangle `t`, with the lanes' colour; whether every pixel of the run is then
/// uniform from `t` (nothing more to draw there).
fn claim_run(
    t: u32,
    (s, band): (&mut Scratch, &mut RowBand<'_>),
    r: usize,
    full: (i64, i64),
) -> bool {
    let (a, b) = (r + full.0 as usize, r + full.1 as usize + 1);
    let (owner, color) = (&mut s.owner[a..b], &mut band.color[a..b]);
    let (lane_color, lane_depth) = (&s.lane_color[a..b], &s.lane_depth[a..b]);
    // Usually every pixel of the run is clear and shaded by the lanes: a fill and a copy.
    let fresh = (owner.iter().zip(lane_depth)).fold(true, |all, (&o, &d)| {
        all & (o == CLEAR) & (d != f32::INFINITY)
    });
    if fresh {
        owner.fill(t + 1);
        color.copy_from_slice(lane_color);
        return true;
    }
    let mut left = false;
    let lanes = lane_color.iter().zip(lane_depth);
    for ((owner, color), (lane_color, lane_depth)) in owner.iter_mut().zip(color).zip(lanes) {
        if *owner == CLEAR && *lane_depth != f32::INFINITY {
            *owner = t + 1;
            *color = *lane_color;
        }
        left |= *owner != t + 1;
    }
    !left
}

/// Draws the samples of pixel `x` of a row that triangle `t` covers (unless the pixel is
/// already uniform from `t`): its one shading (the lanes' centre colour when the shading is
/// at the centre and they drew it), then uniform if the pixel was clear and every sample is
/// covered and passes, else each covered sample's depth test and write.
fn draw_pixel(
    triangles: &[Drawn<'_>],
    t: u32,
    ctx: &SampleContext<'_>,
    (row, x): (&Row<'_>, i64),
    (s, band): (&mut Scratch, &mut RowBand<'_>),
    (flat, wire, background): (Option<&Varyings>, &[DVec2; 3], [u8; 4]),
) {
    let setup = triangles[t as usize].0;
    let n = ctx.offsets.len();
    let all = if n >= 32 { u32::MAX } else { (1u32 << n) - 1 };
    let i = row.r + x as usize;
    let full = row.full.0 <= x && x <= row.full.1;
    if full && row.uniform && s.owner[i] == t + 1 {
        return;
    }
    let mask = if full {
        all
    } else {
        (row.runs.iter().enumerate())
            .filter(|(_, run)| run.0 <= x && x <= run.1)
            .fold(0, |m, (k, _)| m | 1 << k)
    };
    if mask == 0 {
        return;
    }
    let (x, y) = (x as u32, row.y);
    let centre = mask == all || ctx.samples.location == Location::Center;
    let color = if centre && s.lane_depth[i] != f32::INFINITY {
        s.lane_color[i]
    } else {
        match shared_shading((setup, flat), (x, y), mask, ctx, wire) {
            Some((_, c)) => c,
            None => return,
        }
    };
    if mask == all && row.uniform && s.owner[i] == CLEAR {
        s.owner[i] = t + 1;
        band.color[i] = color;
        return;
    }
    expand(n, (s, band), i, background);
    for (k, &o) in ctx.offsets.iter().enumerate() {
        if mask & 1 << k == 0 {
            continue;
        }
        let j = i * n + k;
        let depth = sample_depth(setup, x, y, o);
        if depth_passes(depth, known_depth(triangles, ctx, s, (j, x, y, k))) {
            s.sample_color[j] = color;
            s.sample_depth[j] = depth;
        }
    }
}

/// Makes pixel `i` keep each of its `n` samples: a clear pixel's samples are the background
/// at depth 1, a uniform pixel's its colour, their depths still to be computed.
fn expand(n: usize, (s, band): (&mut Scratch, &RowBand<'_>), i: usize, background: [u8; 4]) {
    let owner = s.owner[i];
    if owner == EXPANDED {
        return;
    }
    let (color, writer) = match owner {
        CLEAR => (background, 0),
        t => (band.color[i], t),
    };
    s.sample_color[i * n..(i + 1) * n].fill(color);
    s.sample_depth[i * n..(i + 1) * n].fill(1.0);
    s.sample_writer[i * n..(i + 1) * n].fill(writer);
    s.owner[i] = EXPANDED;
}

/// The depth of sample `j` (sample `k` of pixel (x, y)) of an expanded pixel, computed now
/// if its writer left it to be computed.
fn known_depth(
    triangles: &[Drawn<'_>],
    ctx: &SampleContext<'_>,
    s: &mut Scratch,
    (j, x, y, k): (usize, u32, u32, usize),
) -> f32 {
    let writer = s.sample_writer[j];
    if writer != 0 {
        let setup = triangles[writer as usize - 1].0;
        s.sample_depth[j] = sample_depth(setup, x, y, ctx.offsets[k]);
        s.sample_writer[j] = 0;
    }
    s.sample_depth[j]
}

/// Each pixel's colour, the [`resolve`] of its samples, and depth, sample 0's, a run of
/// pixels with the same owner at a time: a clear run is the background at depth 1, a uniform
/// run keeps the colour its triangle wrote into the band and gets sample 0's depths from
/// [`DepthRow`], an expanded pixel resolves its samples.
fn resolve_band(
    triangles: &[Drawn<'_>],
    ctx: &SampleContext<'_>,
    (s, vector): (&mut Scratch, VectorLevel),
    band: &mut RowBand<'_>,
    background: [u8; 4],
) {
    let n = ctx.offsets.len();
    let width = band.width as usize;
    let o = ctx.offsets[0];
    for row in 0..band.rows as usize {
        let y = band.y0 + row as u32;
        let r = row * width;
        let mut x = 0;
        while x < width {
            let owner = s.owner[r + x];
            let end = x + same_run(&s.owner[r + x..r + width], owner);
            let (colors, depths) = (
                &mut band.color[r + x..r + end],
                &mut band.depth[r + x..r + end],
            );
            match owner {
                CLEAR => {
                    colors.fill(background);
                    depths.fill(1.0);
                }
                EXPANDED => {
                    for (i, (color, depth)) in (r + x..).zip(colors.iter_mut().zip(depths)) {
                        *color = resolve(&s.sample_color[i * n..(i + 1) * n]);
                        *depth = known_depth(triangles, ctx, s, (i * n, (i - r) as u32, y, 0));
                    }
                }
                t => {
                    let setup = triangles[t as usize - 1].0;
                    DepthRow::new(setup, y, o).write(x as u32, depths, vector);
                }
            }
            x = end;
        }
    }
}

/// How many values at the start of `owners` are `owner`: sixteen at a time while all are.
fn same_run(owners: &[u32], owner: u32) -> usize {
    let chunks = owners.chunks_exact(16);
    let whole = chunks
        .take_while(|c| c.iter().fold(true, |all, &w| all & (w == owner)))
        .count()
        * 16;
    whole
        + owners[whole..]
            .iter()
            .position(|&w| w != owner)
            .unwrap_or(owners.len() - whole)
}

/// [`sample_depth`] of one triangle along a row of pixels, for the sample at one offset:
/// the same `f64` operations, in the same order, several pixels at a time (so the same
/// depths, bit for bit). The sample of pixel `x` lies at window `p_x = x + o_x / 256`
/// (exact); the depth is its plane's ([`ScreenPlane`](super::setup::ScreenPlane)) row part
/// `R` at `p_y` minus its column part `(c_0 k_0 + c_1 k_1) + c_2 k_2` with the column terms
/// `c_i = d_y,i (p_x - S_x,i)`.
struct DepthRow {
    /// The depth plane's row part at the samples' `p_y`.
    row: f64,
    /// `d_y,i`.
    dir_y: [f64; 3],
    /// `S_x,i`.
    start_x: [f64; 3],
    /// The depth plane's `k_i = D_i * (1 / area2)`.
    k: [f64; 3],
    /// `o_x / 256`: the sample's x within its pixel.
    offset_x: f64,
}

impl DepthRow {
    /// The row of the samples at `offset` in pixel row `y` under `setup`.
    fn new(setup: &TriangleSetup, y: u32, offset: I64Vec2) -> Self {
        let w = &setup.weights;
        let p = window_position(sample_at(0, y, offset));
        let plane = w.plane(setup.v.map(|v| v.depth));
        Self {
            row: plane.part(&w.row_terms(p.y)),
            dir_y: w.dir.map(|d| d.y),
            start_x: w.start.map(|s| s.x),
            k: plane.k,
            offset_x: p.x,
        }
    }

    /// The depth, as `f32`, at the sample of pixel `x`.
    #[inline(always)]
    fn at(&self, x: f64) -> f32 {
        let px = x + self.offset_x;
        let c = |i: usize| self.dir_y[i] * (px - self.start_x[i]);
        (self.row - (c(0) * self.k[0] + c(1) * self.k[1] + c(2) * self.k[2])) as f32
    }

    /// Writes the depths of pixels `x0..x0 + out.len()` into `out`, with AVX2 when `vector`
    /// allows it and the CPU has it (the same operations on four pixels at once).
    fn write(&self, x0: u32, out: &mut [f32], vector: VectorLevel) {
        #[cfg(target_arch = "x86_64")]
        {
            if vector >= VectorLevel::Avx2 && std::arch::is_x86_feature_detected!("avx2") {
                // SAFETY: the CPU supports AVX2, checked just above.
                unsafe { self.write_avx2(x0, out) };
                return;
            }
        }
        let _ = vector;
        self.write_impl(x0, out);
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn write_avx2(&self, x0: u32, out: &mut [f32]) {
        self.write_impl(x0, out);
    }

    /// Four pixels at a time (`x` exact in `f64`: `x0 + 4 c + k`), which the compiler turns
    /// into vector operations; the same operations per pixel as [`DepthRow::at`].
    #[inline(always)]
    fn write_impl(&self, x0: u32, out: &mut [f32]) {
        const STEP: [f64; 4] = [0.0, 1.0, 2.0, 3.0];
        let mut x = f64::from(x0);
        let mut chunks = out.chunks_exact_mut(4);
        for chunk in &mut chunks {
            let d: [f32; 4] = std::array::from_fn(|k| self.at(x + STEP[k]));
            chunk.copy_from_slice(&d);
            x += 4.0;
        }
        for (k, d) in chunks.into_remainder().iter_mut().enumerate() {
            *d = self.at(x + STEP[k]);
        }
    }
}

/// Whether [`draw_frame_fast`] draws into `frame` with these samples: a frame of colour and
/// depth only, and samples [`applies`] to.
pub(super) fn fast_applies(ctx: &SampleContext<'_>, frame: &Framebuffer) -> bool {
    frame.buffers() == Buffers::ColorDepth && applies(ctx)
}

/// Draws every prepared triangle into `frame` (sized, with colour and depth only:
/// [`fast_applies`]) in parallel over bands of `rows_per_band` rows, each
/// band drawing its triangles in submission order with the lanes at level `vector`. The
/// colour and depth are [`draw_frame`](super::multisample)'s; no sample is kept. A band whose
/// scratch memory is refused makes the render an error naming it.
pub(super) fn draw_frame_fast(
    prepared: (&ClipMesh, &[PreparedTriangle]),
    ctx: &SampleContext<'_>,
    frame: &mut Framebuffer,
    (rows_per_band, vector): (u32, VectorLevel),
    background: [u8; 4],
) -> Result<(), MemoryError> {
    use rayon::prelude::*;
    let (drawn, bins) = drawn_and_bins(prepared, ctx, (frame.width, frame.height), rows_per_band);
    let progress = crate::progress::render_started(frame.height);
    RowBand::split(frame, rows_per_band)
        .into_par_iter()
        .zip(bins)
        .try_for_each(|(mut band, bin)| {
            let _drawn = super::bands::RowsDrawn(&progress, band.rows);
            if progress.cancelled() {
                return Ok(());
            }
            draw_band(&drawn, &bin, ctx, (vector, background), &mut band)
        })
}
