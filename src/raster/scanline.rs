//! The scanline rasterizer (the classic incremental form): per row, the covered span is found
//! from the edges; along the span every attribute is stepped by a constant increment per pixel.
//!
//! - Span ends are exact: along a row (sample y fixed) an edge function is
//!   `E(px) = a px + K` with `a = -dir_y` (positions in 1/256 pixel), so the samples
//!   `px = 256 c + 128` that pass it form a half-line found by one integer division, with the
//!   same fill rule as [`TriangleSetup::covers`]. Coverage is therefore identical to the
//!   edge-function rasterizer, pixel for pixel. `K` itself steps by `dir_x * 256` per row.
//! - Along a span, screen-space quantities are linear: the screen weights `l_i` (set up from
//!   the unsnapped positions, [`WeightPlanes`](super::setup::WeightPlanes)), the depth,
//!   `1/w`, every `noperspective` attribute, and also `attribute / w` for `smooth` ones. Each
//!   is stepped by its per-pixel increment; the perspective-correct value is recovered per
//!   pixel as `(attribute / w) / (1 / w)`, as the Vulkan specification's note describes.
//!   Values equal the edge-function rasterizer's up to floating-point rounding.

use super::interpolate::Fragment;
use super::project::SUBPIXEL;
use super::setup::{Edge, PixelBounds, TriangleSetup, sample_point};
use super::varying::{NUM_VARYINGS, Varyings};

/// `floor(n / d)` for `d > 0`.
fn floor_div(n: i64, d: i64) -> i64 {
    n.div_euclid(d)
}

/// `ceil(n / d)` for `d > 0`.
fn ceil_div(n: i64, d: i64) -> i64 {
    -(-n).div_euclid(d)
}

/// The columns `c` (as an inclusive range, possibly empty) whose sample `256 c + 128` passes
/// one edge on the row whose sample y is `py` (1/256 pixel).
fn edge_columns(edge: &Edge, py: i64) -> (i64, i64) {
    let a = -edge.dir.y;
    let k = edge.dir.x * (py - edge.start.y) + edge.dir.y * edge.start.x;
    // Passing means E >= t (the fill rule's smallest passing value).
    let t = edge.min_value();
    let half = SUBPIXEL / 2;
    if a == 0 {
        return if k >= t { (i64::MIN, i64::MAX) } else { (1, 0) };
    }
    if a > 0 {
        // a px + k >= t  <=>  px >= ceil((t - k) / a)
        let px_min = ceil_div(t - k, a);
        (ceil_div(px_min - half, SUBPIXEL), i64::MAX)
    } else {
        // a px + k >= t  <=>  px <= floor((k - t) / -a)
        let px_max = floor_div(k - t, -a);
        (i64::MIN, floor_div(px_max - half, SUBPIXEL))
    }
}

/// The covered columns `[x0, x1]` of image row `row`, within the triangle's bounds, or `None`.
///
/// ```
/// use barylab::raster::clip::ClipVertex;
/// use barylab::raster::project::{project_vertex, Viewport};
/// use barylab::raster::scanline::row_span;
/// use barylab::raster::setup::setup_triangle;
/// use barylab::raster::varying::Varyings;
/// use glam::DVec4;
/// // Window (0,0), (8,0), (0,8) in an 8x8 viewport: row 2 (y = 2.5) covers x + y < 8,
/// // centres 0.5 .. 4.5 -> columns 0..=4 (the centre 5.5 is outside).
/// let vp = Viewport { width: 8, height: 8 };
/// let at = |x: f64, y: f64| project_vertex(&ClipVertex::new(
///     DVec4::new(x / 4.0 - 1.0, 1.0 - y / 4.0, 0.0, 1.0), Varyings::default()), vp);
/// let s = setup_triangle([at(0.0, 0.0), at(8.0, 0.0), at(0.0, 8.0)], vp).unwrap();
/// assert_eq!(row_span(&s, 2), Some((0, 4)));
/// ```
pub fn row_span(setup: &TriangleSetup, row: u32) -> Option<(u32, u32)> {
    row_span_of(&setup.edges, setup.bounds, row)
}

/// [`row_span`] of a triangle given by its edges and bounds.
pub fn row_span_of(edges: &[Edge; 3], b: PixelBounds, row: u32) -> Option<(u32, u32)> {
    if row < b.y0 || row > b.y1 {
        return None;
    }
    let py = sample_point(0, row).y;
    let mut lo = i64::from(b.x0);
    let mut hi = i64::from(b.x1);
    for edge in edges {
        let (l, h) = edge_columns(edge, py);
        lo = lo.max(l);
        hi = hi.min(h);
    }
    (lo <= hi).then_some((lo as u32, hi as u32))
}

/// The stepped quantities at one pixel.
#[derive(Clone, Copy)]
struct Values {
    screen: [f64; 3],
    depth: f64,
    inv_w: f64,
    affine: [f64; NUM_VARYINGS],
    over_w: [f64; NUM_VARYINGS],
}

impl Values {
    /// All stepped quantities from screen weights `l`.
    fn from_weights(setup: &TriangleSetup, l: [f64; 3]) -> Self {
        let v = &setup.v;
        let mut affine = [0.0; NUM_VARYINGS];
        let mut over_w = [0.0; NUM_VARYINGS];
        for s in 0..NUM_VARYINGS {
            for k in 0..3 {
                let a = f64::from(v[k].varyings.0[s]);
                affine[s] += l[k] * f64::from(v[k].noperspective.0[s]);
                over_w[s] += l[k] * a * v[k].inv_w;
            }
        }
        Self {
            screen: l,
            depth: l[0] * v[0].depth + l[1] * v[1].depth + l[2] * v[2].depth,
            inv_w: l[0] * v[0].inv_w + l[1] * v[1].inv_w + l[2] * v[2].inv_w,
            affine,
            over_w,
        }
    }

    fn step(&mut self, d: &Values) {
        for k in 0..3 {
            self.screen[k] += d.screen[k];
        }
        self.depth += d.depth;
        self.inv_w += d.inv_w;
        for s in 0..NUM_VARYINGS {
            self.affine[s] += d.affine[s];
            self.over_w[s] += d.over_w[s];
        }
    }

    /// The fragment: perspective-correct attributes are `(attribute / w) / (1 / w)`.
    fn fragment(&self, setup: &TriangleSetup, edges: [i64; 3]) -> Option<Fragment> {
        if !(self.inv_w > 0.0 && self.inv_w.is_finite()) {
            return None;
        }
        let inv_w = [setup.v[0].inv_w, setup.v[1].inv_w, setup.v[2].inv_w];
        let q = [
            self.screen[0] * inv_w[0] / self.inv_w,
            self.screen[1] * inv_w[1] / self.inv_w,
            self.screen[2] * inv_w[2] / self.inv_w,
        ];
        let mut affine = Varyings::default();
        let mut correct = Varyings::default();
        for s in 0..NUM_VARYINGS {
            affine.0[s] = self.affine[s] as f32;
            correct.0[s] = (self.over_w[s] / self.inv_w) as f32;
        }
        Some(Fragment {
            edge_weights: super::interpolate::edge_weights(setup, &self.screen),
            edges,
            screen: self.screen,
            perspective: q,
            depth: self.depth,
            inv_w: self.inv_w,
            affine,
            correct,
            lod: 0.0,
            duv: [glam::Vec2::ZERO; 2],
        })
    }
}

/// Visits the covered pixels of rows `rows` in order, stepping attributes along each span.
/// `visit(x, y, fragment)`.
pub fn rasterize_rows(
    setup: &TriangleSetup,
    rows: std::ops::Range<u32>,
    mut visit: impl FnMut(u32, u32, &Fragment),
) {
    // Per pixel along x, the screen weight l_i changes by -d_y,i / area2.
    let dl = setup.weights.step_x();
    // Everything stepped is linear in the screen weights, so its increments are the same
    // map applied to the weight increments.
    let steps = Values::from_weights(setup, dl);
    let de: [i64; 3] = setup.edges.map(|e| -e.dir.y * SUBPIXEL);
    for y in rows {
        let Some((x0, x1)) = row_span(setup, y) else {
            continue;
        };
        // Exact values at the span's first pixel, then stepping.
        let mut e = setup.edge_values(sample_point(x0, y));
        let mut vals = Values::from_weights(setup, setup.weights.at_pixel(x0, y));
        for x in x0..=x1 {
            if let Some(frag) = vals.fragment(setup, e) {
                visit(x, y, &frag);
            }
            vals.step(&steps);
            for k in 0..3 {
                e[k] += de[k];
            }
        }
    }
}
