//! Triangle setup: edge functions in exact fixed point, facing, fill rule and bounds.
//!
//! For an edge from S to E, the edge function at a point P is the 2D cross product
//! `E(P) = (E - S) x (P - S) = (E_x - S_x)(P_y - S_y) - (E_y - S_y)(P_x - S_x)`,
//! twice the signed area of the triangle S, E, P. Edge `i` is the edge opposite vertex `i`,
//! so its value at a point divided by twice the triangle's area is the point's screen-space
//! weight of vertex `i`. Positions are integers in 1/256 pixel, so every value is exact.
//!
//! Fill rule (image rows, row 0 at the top): a sample exactly on an edge is covered when the
//! edge is a *left* edge (interior to its right) or a *bottom* edge (horizontal, interior
//! above); it is not covered on a top or right edge. Two triangles sharing an edge see it in
//! opposite directions, so every sample on it belongs to exactly one of them.

use glam::{DVec2, I64Vec2};

use super::project::{SUBPIXEL, Viewport, WindowVertex};

/// Whether the triangle is seen from its front (counter-clockwise on screen, as OpenGL's
/// default `glFrontFace(GL_CCW)`) or its back. Both are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Facing {
    Front,
    Back,
}

/// Which kind of edge an edge is under the fill rule.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum EdgeKind {
    Left,
    Right,
    Top,
    Bottom,
}

impl EdgeKind {
    /// Samples exactly on left and bottom edges are covered.
    pub fn inclusive(self) -> bool {
        matches!(self, EdgeKind::Left | EdgeKind::Bottom)
    }
}

/// One oriented edge: `value(P) = dir x (P - start) >= 0` inside the triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Edge {
    pub start: I64Vec2,
    /// Edge direction, oriented so that the interior is on the non-negative side.
    pub dir: I64Vec2,
    pub kind: EdgeKind,
}

impl Edge {
    /// Builds the edge S->E oriented for a triangle of the given sign of area.
    ///
    /// Classification (y down): interior side normal is `(-dir_y, dir_x)`. `dir_y < 0`: left edge;
    /// `dir_y > 0`: right edge; `dir_y = 0` and `dir_x < 0`: interior above, bottom edge;
    /// `dir_y = 0` and `dir_x > 0`: top edge.
    pub fn new(start: I64Vec2, end: I64Vec2, positive_area: bool) -> Self {
        let d = end - start;
        let dir = if positive_area { d } else { -d };
        let kind = if dir.y < 0 {
            EdgeKind::Left
        } else if dir.y > 0 {
            EdgeKind::Right
        } else if dir.x < 0 {
            EdgeKind::Bottom
        } else {
            EdgeKind::Top
        };
        Self { start, dir, kind }
    }

    /// The edge function at a point in 1/256-pixel units (units of 1/65536 pixel^2).
    ///
    /// ```
    /// use barylab::raster::setup::Edge;
    /// use glam::{DVec2, I64Vec2};
    /// // Edge from (0,0) to (0,256) (pointing down the image): interior on the left side of
    /// // the image for a positive-area triangle, i.e. x < 0 gives positive values.
    /// let e = Edge::new(I64Vec2::new(0, 0), I64Vec2::new(0, 256), true);
    /// assert_eq!(e.value(I64Vec2::new(-128, 128)), 256 * 128);
    /// assert_eq!(e.value(I64Vec2::new(128, 128)), -256 * 128);
    /// ```
    pub fn value(&self, p: I64Vec2) -> i64 {
        let r = p - self.start;
        self.dir.x * r.y - self.dir.y * r.x
    }

    /// Whether a sample with this edge value passes the edge under the fill rule.
    pub fn passes(&self, value: i64) -> bool {
        value > 0 || (value == 0 && self.kind.inclusive())
    }
}

/// A triangle ready for rasterization.
#[derive(Clone, Copy, Debug)]
pub struct TriangleSetup {
    /// The vertices, in their original order.
    pub v: [WindowVertex; 3],
    /// Edge `i` is opposite vertex `i` (from vertex i+1 to vertex i+2).
    pub edges: [Edge; 3],
    /// Twice the triangle's area, in 1/65536 pixel^2, always positive.
    pub area2: i64,
    pub facing: Facing,
    /// Inclusive pixel bounds `[x0, x1] x [y0, y1]` of candidate samples, within the viewport.
    pub bounds: PixelBounds,
}

/// Inclusive pixel rectangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelBounds {
    pub x0: u32,
    pub y0: u32,
    pub x1: u32,
    pub y1: u32,
}

/// Signed twice-area of the triangle a, b, c in image coordinates: `(b - a) x (c - a)`.
/// Positive means clockwise as seen on screen (y down).
///
/// ```
/// use barylab::raster::setup::signed_area2;
/// use glam::{DVec2, I64Vec2};
/// let (a, b, c) = (I64Vec2::new(0, 0), I64Vec2::new(4, 0), I64Vec2::new(0, 2));
/// assert_eq!(signed_area2(a, b, c), 8);
/// assert_eq!(signed_area2(a, c, b), -8);
/// ```
pub fn signed_area2(a: I64Vec2, b: I64Vec2, c: I64Vec2) -> i64 {
    let (ab, ac) = (b - a, c - a);
    ab.x * ac.y - ab.y * ac.x
}

/// The sample position of pixel (col, row), its centre, in 1/256-pixel units:
/// `(256 col + 128, 256 row + 128)`.
pub fn sample_point(col: u32, row: u32) -> I64Vec2 {
    I64Vec2::new(
        i64::from(col) * SUBPIXEL + SUBPIXEL / 2,
        i64::from(row) * SUBPIXEL + SUBPIXEL / 2,
    )
}

/// Sets up a triangle. Returns `None` for a zero-area triangle or one whose bounds miss the
/// viewport.
pub fn setup_triangle(v: [WindowVertex; 3], viewport: Viewport) -> Option<TriangleSetup> {
    let p = [v[0].fixed, v[1].fixed, v[2].fixed];
    let signed = signed_area2(p[0], p[1], p[2]);
    if signed == 0 {
        return None;
    }
    let positive = signed > 0;
    let edges = [
        Edge::new(p[1], p[2], positive),
        Edge::new(p[2], p[0], positive),
        Edge::new(p[0], p[1], positive),
    ];
    let bounds = pixel_bounds(&p, viewport)?;
    Some(TriangleSetup {
        v,
        edges,
        area2: signed.abs(),
        // Clockwise in image coordinates (y down) is counter-clockwise... for y up; positive
        // area here means clockwise as displayed, which OpenGL calls the back face.
        facing: if positive {
            Facing::Back
        } else {
            Facing::Front
        },
        bounds,
    })
}

/// Pixels whose centres can lie inside the triangle: centre `256 c + 128` within
/// `[min, max]` of the vertices, clamped to the viewport.
fn pixel_bounds(p: &[I64Vec2; 3], viewport: Viewport) -> Option<PixelBounds> {
    let min = p[0].min(p[1]).min(p[2]);
    let max = p[0].max(p[1]).max(p[2]);
    let half = SUBPIXEL / 2;
    // Smallest c with 256c + 128 >= min, largest c with 256c + 128 <= max.
    let lo = |m: i64| (m - half + SUBPIXEL - 1).div_euclid(SUBPIXEL);
    let hi = |m: i64| (m - half).div_euclid(SUBPIXEL);
    let x0 = lo(min.x).max(0);
    let y0 = lo(min.y).max(0);
    let x1 = hi(max.x).min(i64::from(viewport.width) - 1);
    let y1 = hi(max.y).min(i64::from(viewport.height) - 1);
    if x0 > x1 || y0 > y1 {
        return None;
    }
    Some(PixelBounds {
        x0: x0 as u32,
        y0: y0 as u32,
        x1: x1 as u32,
        y1: y1 as u32,
    })
}

impl TriangleSetup {
    /// The three edge values at a sample point.
    pub fn edge_values(&self, p: I64Vec2) -> [i64; 3] {
        [
            self.edges[0].value(p),
            self.edges[1].value(p),
            self.edges[2].value(p),
        ]
    }

    /// Screen gradient (per pixel) of each *source-triangle* weight across this triangle, with
    /// the weights taken as screen-linear: `grad f = sum_k f_k grad l_k`, where
    /// `grad l_k = 256 (-dir_k.y, dir_k.x) / area2` for edge k (positions in 1/256 pixel).
    pub fn source_weight_gradients(&self) -> [DVec2; 3] {
        let s = SUBPIXEL as f64 / self.area2 as f64;
        let grad_l = self
            .edges
            .map(|e| DVec2::new(-e.dir.y as f64, e.dir.x as f64) * s);
        let mut out = [DVec2::ZERO; 3];
        for (i, g) in out.iter_mut().enumerate() {
            for (k, gl) in grad_l.iter().enumerate() {
                *g += *gl * f64::from(self.v[k].varyings.bary()[i]);
            }
        }
        out
    }

    /// Whether the sample with these edge values is covered under the fill rule.
    pub fn covers(&self, e: &[i64; 3]) -> bool {
        self.edges[0].passes(e[0]) && self.edges[1].passes(e[1]) && self.edges[2].passes(e[2])
    }
}
