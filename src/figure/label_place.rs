//! Where the overlay's labels that belong to one thing go, the same for the app's canvas and
//! for exported figures (SVG, and PNG through it): a vertex handle's label beside its own
//! handle ([`place_handle_label`]), and the 2x2 quad's four uv labels as one block laid out
//! as the quad's pixels are ([`place_quad_block`]). Boxes are `[x0, y0, x1, y1]` in points
//! (screen or figure coordinates), y down.

use glam::DVec2;

use crate::figure::overlay::Shape;
use crate::figure::text::{Box2, KEEP_CLEAR_COST, LABEL_INSET, fit, overlap_area, push_inside};

/// Distance from the point `p` to the box `b` (0 inside it):
/// `sqrt(dx^2 + dy^2)` with `dx = max(b0 - x, 0, x - b2)` and `dy` likewise.
///
/// ```
/// use barylab::figure::label_place::point_distance;
/// assert_eq!(point_distance([0.0, 0.0, 10.0, 10.0], [13.0, 14.0]), 5.0);
/// assert_eq!(point_distance([0.0, 0.0, 10.0, 10.0], [5.0, 5.0]), 0.0);
/// ```
pub fn point_distance(b: Box2, p: [f32; 2]) -> f32 {
    let dx = (b[0] - p[0]).max(p[0] - b[2]).max(0.0);
    let dy = (b[1] - p[1]).max(p[1] - b[3]).max(0.0);
    dx.hypot(dy)
}

/// The gap between the boxes `a` and `b` (0 when they touch or overlap): the distance
/// between their nearest points, per axis `max(a0 - b1, b0 - a1, 0)`.
///
/// ```
/// use barylab::figure::label_place::box_distance;
/// assert_eq!(box_distance([0.0, 0.0, 10.0, 10.0], [13.0, 14.0, 20.0, 20.0]), 5.0);
/// assert_eq!(box_distance([0.0, 0.0, 10.0, 10.0], [5.0, 12.0, 20.0, 20.0]), 2.0);
/// ```
pub fn box_distance(a: Box2, b: Box2) -> f32 {
    let dx = (a[0] - b[2]).max(b[0] - a[2]).max(0.0);
    let dy = (a[1] - b[3]).max(b[1] - a[3]).max(0.0);
    dx.hypot(dy)
}

/// The box of a quad from `min` to `max` (points) with its outline reaching `outline`
/// points outside it: what the quad's labels and the handles' labels keep clear of.
///
/// ```
/// use barylab::figure::label_place::quad_box;
/// assert_eq!(quad_box([10.0, 20.0], [14.0, 24.0], 5.0), [5.0, 15.0, 19.0, 29.0]);
/// ```
pub fn quad_box(min: [f32; 2], max: [f32; 2], outline: f32) -> Box2 {
    [
        min[0] - outline,
        min[1] - outline,
        max[0] + outline,
        max[1] + outline,
    ]
}

/// The centres of the overlay's handles (the points their [`Shape::HandleLabel`]s belong
/// to), mapped by `to_points` from canvas coordinates.
pub fn handle_centres(shapes: &[Shape], to_points: impl Fn(DVec2) -> [f32; 2]) -> Vec<[f32; 2]> {
    shapes
        .iter()
        .filter_map(|s| match s {
            Shape::HandleLabel { at, .. } => Some(to_points(*at)),
            _ => None,
        })
        .collect()
}

/// The handles of `handles` other than the one at `own`.
pub fn others(handles: &[[f32; 2]], own: [f32; 2]) -> Vec<[f32; 2]> {
    handles.iter().copied().filter(|&h| h != own).collect()
}

/// Whether `b` lies [`LABEL_INSET`] inside `clip`.
fn inside(b: Box2, clip: Box2) -> bool {
    b[0] >= clip[0] + LABEL_INSET - 1e-3
        && b[1] >= clip[1] + LABEL_INSET - 1e-3
        && b[2] <= clip[2] - LABEL_INSET + 1e-3
        && b[3] <= clip[3] - LABEL_INSET + 1e-3
}

/// What covering costs: the area over labels already placed, plus [`KEEP_CLEAR_COST`] times
/// the area over what must stay visible.
fn cost(b: Box2, placed: &[Box2], keep_clear: &[Box2]) -> f32 {
    overlap_area(b, placed) + KEEP_CLEAR_COST * overlap_area(b, keep_clear)
}

/// How many rings of candidates [`place_handle_label`] tries around a handle, each half a
/// label height further out than the one before.
pub const HANDLE_RINGS: usize = 4;

/// The box of a handle's label, `size` points large, beside its handle at `centre` of radius
/// `radius`. Candidates, in order: the diagonal `outward` (signs: -1 left/up, +1 right/down;
/// away from the handles' centroid), the other three diagonals, right, left, above and
/// below, each touching the handle's rim, then the same [`HANDLE_RINGS`] - 1 times further
/// out by half the label's height; each pushed inside `clip`. A candidate counts only if it
/// is nearer its own handle than any handle of `others` (box-to-centre distance,
/// [`point_distance`]): a label never sits at another corner. Of those, the first that
/// covers nothing placed nor kept clear, else the one covering least (a kept-clear point
/// costing [`KEEP_CLEAR_COST`] times a label's); when no candidate is nearer its own handle,
/// the first diagonal (it may cover the image, never stand for another corner).
///
/// ```
/// use barylab::figure::label_place::{place_handle_label, point_distance};
/// let clip = [0.0, 0.0, 400.0, 300.0];
/// // Two handles 60 points apart on a row; B's label wants to go left (towards A): it goes
/// // elsewhere, nearer B than A.
/// let (a, b) = ([100.0, 150.0], [160.0, 150.0]);
/// let l = place_handle_label(b, 10.0, [-1.0, -1.0], &[a], [80.0, 20.0], clip, &[], &[]);
/// assert!(point_distance(l, b) < point_distance(l, a));
/// ```
#[allow(clippy::too_many_arguments)]
pub fn place_handle_label(
    centre: [f32; 2],
    radius: f32,
    outward: [f32; 2],
    others: &[[f32; 2]],
    size: [f32; 2],
    clip: Box2,
    placed: &[Box2],
    keep_clear: &[Box2],
) -> Box2 {
    let [w, h] = size;
    let sx = if outward[0] < 0.0 { -1.0 } else { 1.0 };
    let sy = if outward[1] < 0.0 { -1.0 } else { 1.0 };
    // Directions: the four diagonals (the outward one first), then the four sides.
    let dirs: [[f32; 2]; 8] = [
        [sx, sy],
        [-sx, sy],
        [sx, -sy],
        [-sx, -sy],
        [1.0, 0.0],
        [-1.0, 0.0],
        [0.0, -1.0],
        [0.0, 1.0],
    ];
    // The box whose near corner (diagonals) or near side's middle (sides) lies `reach` from
    // the centre along `d`.
    let box_at = |d: [f32; 2], reach: f32| -> Box2 {
        let diagonal = d[0] != 0.0 && d[1] != 0.0;
        let r = if diagonal { 0.75 * reach } else { reach + 2.0 };
        let p = [centre[0] + d[0] * r, centre[1] + d[1] * r];
        let x0 = match d[0] {
            x if x > 0.0 => p[0],
            x if x < 0.0 => p[0] - w,
            _ => p[0] - w / 2.0,
        };
        let y0 = match d[1] {
            y if y > 0.0 => p[1],
            y if y < 0.0 => p[1] - h,
            _ => p[1] - h / 2.0,
        };
        push_inside([x0, y0, x0 + w, y0 + h], clip)
    };
    let own = |b: Box2| {
        let d = point_distance(b, centre);
        others.iter().all(|&o| d < point_distance(b, o))
    };
    let mut best: Option<(f32, Box2)> = None;
    for ring in 0..HANDLE_RINGS {
        let reach = radius + ring as f32 * h / 2.0;
        for d in dirs {
            let b = box_at(d, reach);
            if !own(b) {
                continue;
            }
            let c = cost(b, placed, keep_clear);
            if c == 0.0 {
                return b;
            }
            if best.is_none_or(|(bc, _)| c < bc) {
                best = Some((c, b));
            }
        }
    }
    best.map_or_else(|| box_at(dirs[0], radius), |(_, b)| b)
}

/// The text scales [`place_handle_label_fitting`] tries, largest first: a label shrinks to
/// a little under two thirds of its size at most (still readable where it is shown), and
/// only where the full size covers another label or a handle.
pub const HANDLE_LABEL_SCALES: [f32; 3] = [1.0, 0.8, 0.64];

/// [`place_handle_label`] at the largest of [`HANDLE_LABEL_SCALES`] whose box covers nothing
/// placed nor kept clear, `size_at(scale)` giving the label's box size with its text at that
/// scale; where every scale's box covers something, the one covering least (the larger on a
/// tie). Returns the box and the scale. On a small picture two neighbouring corners' labels
/// then sit side by side, smaller, instead of one over the other.
///
/// ```
/// use barylab::figure::label_place::{place_handle_label_fitting, HANDLE_LABEL_SCALES};
/// use barylab::figure::text::overlap_area;
/// // A picture 100 points wide whose left 45 points hold a label already: a label 60 points
/// // wide covers part of it wherever it goes; at 80% (48 points) it fits right of it.
/// let clip = [0.0, 0.0, 100.0, 20.0];
/// let placed = [[0.0, 0.0, 45.0, 20.0]];
/// let size_at = |s: f32| [60.0 * s, 10.0 * s];
/// let (b, scale) = place_handle_label_fitting([75.0, 10.0], 2.0, [1.0, -1.0], &[], size_at,
///                                             clip, &placed, &[]);
/// assert_eq!(scale, HANDLE_LABEL_SCALES[1]);
/// assert_eq!(overlap_area(b, &placed), 0.0);
/// ```
#[allow(clippy::too_many_arguments)]
pub fn place_handle_label_fitting(
    centre: [f32; 2],
    radius: f32,
    outward: [f32; 2],
    others: &[[f32; 2]],
    size_at: impl Fn(f32) -> [f32; 2],
    clip: Box2,
    placed: &[Box2],
    keep_clear: &[Box2],
) -> (Box2, f32) {
    at_fitting_scale(|scale| {
        let b = place_handle_label(
            centre,
            radius,
            outward,
            others,
            size_at(scale),
            clip,
            placed,
            keep_clear,
        );
        (b, cost(b, placed, keep_clear))
    })
}

/// `place(scale)` (a placement and what it covers, [`cost`]) at the largest of
/// [`HANDLE_LABEL_SCALES`] that covers nothing, else at the one covering least (the larger on
/// a tie); returns the placement and its scale.
fn at_fitting_scale<T>(place: impl Fn(f32) -> (T, f32)) -> (T, f32) {
    let [first, rest @ ..] = HANDLE_LABEL_SCALES;
    let ((mut best, mut best_cost), mut best_scale) = (place(first), first);
    for scale in rest {
        if best_cost == 0.0 {
            break;
        }
        let (t, c) = place(scale);
        if c < best_cost {
            (best, best_cost, best_scale) = (t, c, scale);
        }
    }
    (best, best_scale)
}

/// The four uv labels of a 2x2 quad, placed as one block by [`place_quad_block`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadBlock {
    /// The box of label `i + 2 j` (pixel `(x0 + i, y0 + j)`), if it has one.
    pub boxes: [Option<Box2>; 4],
    /// The whole block.
    pub block: Box2,
    /// A leader line from the block to the quad (block end first) when the block ended up
    /// farther than [`LEADER_FROM`] from the quad.
    pub leader: Option<[[f32; 2]; 2]>,
}

/// Points: a block farther than this from its quad gets a leader line.
pub const LEADER_FROM: f32 = 24.0;

/// [`place_quad_block`] at the largest of [`HANDLE_LABEL_SCALES`] whose boxes cover nothing
/// placed nor kept clear, `sizes_at(scale)` giving the labels' box sizes with their text at
/// that scale; where every scale's block covers something, the one covering least (the
/// larger on a tie). Returns the block and the scale. On a small picture the block then
/// stays off the corners' labels, smaller, instead of lying over them.
///
/// ```
/// use barylab::figure::label_place::{place_quad_block_fitting, HANDLE_LABEL_SCALES};
/// let clip = [0.0, 0.0, 400.0, 300.0];
/// let quad = [196.0, 146.0, 204.0, 154.0];
/// let sizes_at = |s: f32| [Some([60.0 * s, 20.0 * s]); 4];
/// // Room for the block at full size: it keeps it.
/// let (_, scale) = place_quad_block_fitting(quad, sizes_at, 2.0, 8.0, true, clip, &[], &[]);
/// assert_eq!(scale, HANDLE_LABEL_SCALES[0]);
/// ```
#[allow(clippy::too_many_arguments)]
pub fn place_quad_block_fitting(
    quad: Box2,
    sizes_at: impl Fn(f32) -> [Option<[f32; 2]>; 4],
    gap: f32,
    margin: f32,
    above: bool,
    clip: Box2,
    placed: &[Box2],
    keep_clear: &[Box2],
) -> (QuadBlock, f32) {
    at_fitting_scale(|scale| {
        let q = place_quad_block(
            quad,
            sizes_at(scale),
            gap,
            margin,
            above,
            clip,
            placed,
            keep_clear,
        );
        let c = q
            .boxes
            .iter()
            .flatten()
            .map(|&b| cost(b, placed, keep_clear))
            .sum();
        (q, c)
    })
}

/// The boxes of a block laid out from its top-left corner `at`: two columns (`gap` apart)
/// as wide as their widest label, the left one's labels flush right and the right one's
/// flush left, two rows (`gap` apart) as high as their highest; label `i + 2 j` in column
/// `i`, row `j`. Returns the labels' boxes and the block's size.
fn layout(at: [f32; 2], sizes: &[Option<[f32; 2]>; 4], gap: f32) -> ([Option<Box2>; 4], [f32; 2]) {
    let dim = |k: usize, axis: usize| sizes[k].map_or(0.0, |s| s[axis]);
    let cols = [dim(0, 0).max(dim(2, 0)), dim(1, 0).max(dim(3, 0))];
    let rows = [dim(0, 1).max(dim(1, 1)), dim(2, 1).max(dim(3, 1))];
    let boxes = std::array::from_fn(|k| {
        let [w, h] = sizes[k]?;
        let (i, j) = (k % 2, k / 2);
        let x = if i == 0 {
            at[0] + cols[0] - w
        } else {
            at[0] + cols[0] + gap
        };
        let y = if j == 0 { at[1] } else { at[1] + rows[0] + gap };
        Some([x, y, x + w, y + h])
    });
    (boxes, [cols[0] + gap + cols[1], rows[0] + gap + rows[1]])
}

/// The four uv labels of the 2x2 quad `quad` (its outline's box, in points) as ONE block,
/// laid out as the pixels are: label `i + 2 j` belongs to pixel `(x0 + i, y0 + j)` (image
/// rows down), so `uv_00 uv_10` is the upper row and `uv_01 uv_11` the lower, each row's two
/// labels side by side (`sizes[k]`: label `k`'s outer size; `None`: no label there). Its
/// place: the nearest to the quad (gap between boxes, [`box_distance`]) at least `margin`
/// from it, lying inside `clip`, covering neither a label already `placed` nor what is kept
/// clear (`keep_clear`: handles, and the quad with its pixel, which the margin keeps clear);
/// of equally near places the one nearest the preferred place, centred over the quad
/// (`above`) or under it. Searched on a grid of steps of at most 4 points (more on a very
/// large clip); when every place covers something, the one covering least. A block farther
/// than [`LEADER_FROM`] gets a leader line.
///
/// ```
/// use barylab::figure::label_place::place_quad_block;
/// let clip = [0.0, 0.0, 400.0, 300.0];
/// let quad = [196.0, 146.0, 204.0, 154.0];
/// let s = Some([60.0, 20.0]);
/// let q = place_quad_block(quad, [s; 4], 2.0, 8.0, true, clip, &[], &[]);
/// let [b00, b10, b01, b11] = q.boxes.map(|b| b.expect("a label"));
/// // Two rows of two, above the quad, centred on it.
/// assert!(b00[2] < b10[0] && b01[2] < b11[0]);
/// assert!(b00[3] < b01[1] && b10[3] < b11[1]);
/// assert_eq!(b01[3], quad[1] - 8.0);
/// assert_eq!(b00[2] + 1.0, 200.0);
/// assert_eq!(q.leader, None);
/// ```
#[allow(clippy::too_many_arguments)]
pub fn place_quad_block(
    quad: Box2,
    sizes: [Option<[f32; 2]>; 4],
    gap: f32,
    margin: f32,
    above: bool,
    clip: Box2,
    placed: &[Box2],
    keep_clear: &[Box2],
) -> QuadBlock {
    let (_, [bw, bh]) = layout([0.0, 0.0], &sizes, gap);
    let left_col = sizes[0]
        .map_or(0.0, |s| s[0])
        .max(sizes[2].map_or(0.0, |s| s[0]));
    let centre_x = (quad[0] + quad[2]) / 2.0;
    // The preferred place: the gap between the columns over the quad's centre.
    let pref = [
        centre_x - left_col - gap / 2.0,
        if above {
            quad[1] - margin - bh
        } else {
            quad[3] + margin
        },
    ];
    let clear = [
        quad[0] - margin,
        quad[1] - margin,
        quad[2] + margin,
        quad[3] + margin,
    ];
    let step = ((clip[2] - clip[0]).max(clip[3] - clip[1]) / 160.0).max(4.0);
    let range = |lo: f32, hi: f32, p: f32| {
        let a = ((lo - p) / step).floor() as i64;
        let b = ((hi - p) / step).ceil() as i64;
        a..=b
    };
    // (free?, cost, distance, displacement) of the best place so far, and the place.
    let mut best: Option<((f32, f32, f32), [f32; 2])> = None;
    let mut consider = |at: [f32; 2]| {
        let b = [at[0], at[1], at[0] + bw, at[1] + bh];
        if !inside(b, clip) {
            return;
        }
        let d = box_distance(b, quad);
        if d < margin - 1e-3 {
            return;
        }
        let c = cost(b, placed, keep_clear) + KEEP_CLEAR_COST * overlap_area(b, &[clear]);
        let moved = (at[0] - pref[0]).hypot(at[1] - pref[1]);
        let key = (c, (d / step).round(), moved);
        if best.is_none_or(|(k, _)| key < k) {
            best = Some((key, at));
        }
    };
    for i in range(clip[0], clip[2] - bw, pref[0]) {
        for j in range(clip[1], clip[3] - bh, pref[1]) {
            consider([pref[0] + i as f32 * step, pref[1] + j as f32 * step]);
        }
    }
    // A block larger than the clip: the preferred place pushed inside as far as it goes.
    let at = best.map_or_else(
        || {
            let b = push_inside([pref[0], pref[1], pref[0] + bw, pref[1] + bh], clip);
            [b[0], b[1]]
        },
        |(_, at)| at,
    );
    let (boxes, _) = layout(at, &sizes, gap);
    let block = [at[0], at[1], at[0] + bw, at[1] + bh];
    let leader = (box_distance(block, quad) > LEADER_FROM).then(|| nearest_points(block, quad));
    QuadBlock {
        boxes,
        block,
        leader,
    }
}

/// The factor (at most 1) by which the quad's labels of text widths `text_widths` (without
/// their padding of `padding` points on each side; `None`: no label) must shrink so that
/// their block, two columns `gap` apart, fits across `clip`: [`fit`] of the widest left and
/// the widest right label.
///
/// ```
/// use barylab::figure::label_place::block_fit;
/// let clip = [0.0, 0.0, 500.0, 100.0];
/// assert_eq!(block_fit([Some(100.0), Some(120.0), Some(90.0), None], 6.0, 2.0, clip), 1.0);
/// assert!(block_fit([Some(300.0), Some(300.0), None, None], 6.0, 2.0, clip) < 0.8);
/// ```
pub fn block_fit(text_widths: [Option<f32>; 4], padding: f32, gap: f32, clip: Box2) -> f32 {
    let w = |k: usize| text_widths[k].unwrap_or(0.0);
    fit(w(0).max(w(2)) + w(1).max(w(3)), 4.0 * padding + gap, clip)
}

/// The nearest points of the boxes `a` and `b` (a's first): per axis, the middle of their
/// overlap where they overlap, else their facing sides.
///
/// ```
/// use barylab::figure::label_place::nearest_points;
/// let p = nearest_points([0.0, 0.0, 10.0, 10.0], [20.0, 4.0, 30.0, 30.0]);
/// assert_eq!(p, [[10.0, 7.0], [20.0, 7.0]]);
/// ```
pub fn nearest_points(a: Box2, b: Box2) -> [[f32; 2]; 2] {
    let axis = |k: usize| {
        let (lo, hi) = (a[k].max(b[k]), a[k + 2].min(b[k + 2]));
        if lo <= hi {
            let m = (lo + hi) / 2.0;
            (m, m)
        } else if a[k + 2] < b[k] {
            (a[k + 2], b[k])
        } else {
            (a[k], b[k + 2])
        }
    };
    let ((ax, bx), (ay, by)) = (axis(0), axis(1));
    [[ax, ay], [bx, by]]
}
