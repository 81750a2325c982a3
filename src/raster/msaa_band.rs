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
    /// Per pixel: [`CLEAR`], [`EXPANDED`], or `t + 1` for uniform from triangle `t`.
    owner: Vec<u32>,
    /// A uniform pixel's colour.
    color: Vec<[u8; 4]>,
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
/// against the clear depth 1. The depth `sum l_i d_i` is affine in the window position, so
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
        let d = interpolate::depth_at(setup, &l);
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
/// [`multisample::draw_band`](super::multisample) gives the band.
pub(super) fn draw_band(
    triangles: &[Drawn<'_>],
    bin: &[(u32, u32)],
    ctx: &SampleContext<'_>,
    (vector, background): (VectorLevel, [u8; 4]),
    band: &mut RowBand<'_>,
) {
    SCRATCH.with_borrow_mut(|s| {
        let pixels = band.color.len();
        let n = ctx.offsets.len();
        s.lane_color.resize(pixels, [0; 4]);
        s.lane_depth.resize(pixels, f32::INFINITY);
        s.owner.clear();
        s.owner.resize(pixels, CLEAR);
        s.color.resize(pixels, [0; 4]);
        s.sample_color.resize(pixels * n, [0; 4]);
        s.sample_depth.resize(pixels * n, 1.0);
        s.sample_writer.resize(pixels * n, 0);
        let lanes = lane_shading(ctx.params).map(|sh| Lanes::new(ctx.texture, sh, vector));
        for &(t, _) in bin {
            draw_triangle(triangles, t, ctx, lanes.as_ref(), (s, band), background);
        }
        resolve_band(triangles, ctx, s, band, background);
    });
}

/// Draws triangle `t` of `triangles` into the band's samples.
fn draw_triangle(
    triangles: &[Drawn<'_>],
    t: u32,
    ctx: &SampleContext<'_>,
    lanes: Option<&Lanes<'_>>,
    (s, band): (&mut Scratch, &RowBand<'_>),
    background: [u8; 4],
) {
    let (setup, _, ref flat, bounds) = triangles[t as usize];
    let flat = flat.as_ref();
    let Some((y_start, y_end)) = band.rows_of(&bounds) else {
        return;
    };
    let width = band.width as usize;
    let row_index = |y: u32| (y - band.y0) as usize * width;
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
    let all = if n >= 32 { u32::MAX } else { (1u32 << n) - 1 };
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
        let (full_lo, full_hi) = (full_lo.max(any_lo), full_hi.min(any_hi));
        if uniform && full_lo <= full_hi {
            // Every sample covered and passing, in a clear pixel the lanes shaded: one
            // colour, the lanes' at the centre (the other pixels are drawn below).
            let (a, b) = (r + full_lo as usize, r + full_hi as usize + 1);
            let pixels = s.owner[a..b]
                .iter_mut()
                .zip(&mut s.color[a..b])
                .zip(s.lane_color[a..b].iter().zip(&s.lane_depth[a..b]));
            for ((owner, color), (lane_color, lane_depth)) in pixels {
                if *owner == CLEAR && *lane_depth != f32::INFINITY {
                    *owner = t + 1;
                    *color = *lane_color;
                }
            }
        }
        for x in any_lo..=any_hi {
            let i = r + x as usize;
            let full = full_lo <= x && x <= full_hi;
            if full && uniform && s.owner[i] == t + 1 {
                continue;
            }
            let mask = if full {
                all
            } else {
                runs[..n]
                    .iter()
                    .enumerate()
                    .filter(|(_, run)| run.0 <= x && x <= run.1)
                    .fold(0, |m, (k, _)| m | 1 << k)
            };
            if mask == 0 {
                continue;
            }
            let (x, yy) = (x as u32, y);
            let centre = mask == all || ctx.samples.location == Location::Center;
            let color = if centre && s.lane_depth[i] != f32::INFINITY {
                s.lane_color[i]
            } else {
                match shared_shading((setup, flat), (x, yy), mask, ctx, &wire) {
                    Some((_, c)) => c,
                    None => continue,
                }
            };
            if mask == all && uniform && s.owner[i] == CLEAR {
                s.owner[i] = t + 1;
                s.color[i] = color;
                continue;
            }
            expand(n, s, i, background);
            for (k, &o) in ctx.offsets.iter().enumerate() {
                if mask & 1 << k == 0 {
                    continue;
                }
                let j = i * n + k;
                let depth = sample_depth(setup, x, yy, o);
                if depth_passes(depth, known_depth(triangles, ctx, s, (j, x, yy, k))) {
                    s.sample_color[j] = color;
                    s.sample_depth[j] = depth;
                }
            }
        }
    }
}

/// Makes pixel `i` keep each of its `n` samples: a clear pixel's samples are the background
/// at depth 1, a uniform pixel's its colour, their depths still to be computed.
fn expand(n: usize, s: &mut Scratch, i: usize, background: [u8; 4]) {
    let owner = s.owner[i];
    if owner == EXPANDED {
        return;
    }
    let (color, writer) = match owner {
        CLEAR => (background, 0),
        t => (s.color[i], t),
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

/// Each pixel's colour, the [`resolve`] of its samples, and depth, sample 0's.
fn resolve_band(
    triangles: &[Drawn<'_>],
    ctx: &SampleContext<'_>,
    s: &mut Scratch,
    band: &mut RowBand<'_>,
    background: [u8; 4],
) {
    let n = ctx.offsets.len();
    let width = band.width as usize;
    let o = ctx.offsets[0];
    for row in 0..band.rows as usize {
        let y = band.y0 + row as u32;
        // Sample 0's window y, and the row terms of the last uniform pixel's triangle.
        let py = window_position(sample_at(0, y, o)).y;
        let mut rows_of: Option<(u32, [f64; 3])> = None;
        for x in 0..width {
            let i = row * width + x;
            let (color, depth) = match s.owner[i] {
                CLEAR => (background, 1.0),
                EXPANDED => (
                    resolve(&s.sample_color[i * n..(i + 1) * n]),
                    known_depth(triangles, ctx, s, (i * n, x as u32, y, 0)),
                ),
                t => {
                    let setup = triangles[t as usize - 1].0;
                    let w = &setup.weights;
                    let terms = match rows_of {
                        Some((u, terms)) if u == t => terms,
                        _ => {
                            let terms = [w.row_term(0, py), w.row_term(1, py), w.row_term(2, py)];
                            rows_of = Some((t, terms));
                            terms
                        }
                    };
                    // `sample_depth` with the row terms kept: the same operations.
                    let px = window_position(sample_at(x as u32, y, o)).x;
                    // Written out: `[0, 1, 2].map` was left as a call.
                    let l = [
                        w.weight(0, terms[0], px),
                        w.weight(1, terms[1], px),
                        w.weight(2, terms[2], px),
                    ];
                    (s.color[i], interpolate::depth_at(setup, &l) as f32)
                }
            };
            band.color[i] = color;
            band.depth[i] = depth;
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
/// colour and depth are [`draw_frame`](super::multisample)'s; no sample is kept.
pub(super) fn draw_frame_fast(
    prepared: (&ClipMesh, &[PreparedTriangle]),
    ctx: &SampleContext<'_>,
    frame: &mut Framebuffer,
    (rows_per_band, vector): (u32, VectorLevel),
    background: [u8; 4],
) {
    use rayon::prelude::*;
    let (drawn, bins) = drawn_and_bins(prepared, ctx, (frame.width, frame.height), rows_per_band);
    let progress = crate::progress::render_started(frame.height);
    RowBand::split(frame, rows_per_band)
        .into_par_iter()
        .zip(bins)
        .for_each(|(mut band, bin)| {
            let _drawn = super::bands::RowsDrawn(&progress, band.rows);
            if !progress.cancelled() {
                draw_band(&drawn, &bin, ctx, (vector, background), &mut band);
            }
        });
}
