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
//! opposite directions, so every sample on it belongs to exactly one of them. That is
//! llvmpipe's rule under OpenGL ([`TieRule::Llvmpipe`], the default); [`TieRule::TopLeft`] is
//! the top-left rule as Direct3D states it (and most Vulkan drivers follow) in y-down
//! coordinates (left and top edges own their samples). Vulkan itself only requires that
//! exactly one of two triangles sharing an edge covers a sample on it.
//!
//! The interpolation weights are set up separately, in `f64` from the unsnapped window
//! positions ([`WeightPlanes`]), as llvmpipe sets up its interpolation from the float
//! positions: coverage follows the 1/256 grid, values follow the triangle itself. A sample
//! the snapped edges cover can therefore get a weight of about -1e-6 (a GPU gives it the
//! same).

use glam::{DVec2, I64Vec2};

use super::project::{SUBPIXEL, Viewport, WindowVertex};

mod bounds;
mod plane;

use bounds::pixel_bounds;
pub use bounds::{
    PixelBounds, TINY_TRIANGLE_PIXELS, covers_no_sample, sample_pixel_bounds, setup_bounds,
};
pub use plane::ScreenPlane;

/// Whether the triangle is seen from its front (counter-clockwise on screen, as OpenGL's
/// default `glFrontFace(GL_CCW)`) or its back. Both are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Facing {
    /// Counter-clockwise as displayed (negative [`signed_area2`] in image coordinates).
    Front,
    /// Clockwise as displayed (positive [`signed_area2`]).
    Back,
}

/// Which kind of edge an edge is under the fill rule.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum EdgeKind {
    /// The interior is to its right on screen (oriented direction going up, `dir.y < 0`).
    Left,
    /// The interior is to its left on screen (`dir.y > 0`).
    Right,
    /// Horizontal, the interior below it on screen (y down).
    Top,
    /// Horizontal, the interior above it on screen.
    Bottom,
}

impl EdgeKind {
    /// Samples exactly on left and bottom edges are covered (the default tie rule,
    /// [`TieRule::Llvmpipe`]).
    pub fn inclusive(self) -> bool {
        TieRule::Llvmpipe.inclusive(self)
    }
}

/// Which edges own the samples exactly on them: the tie rule (a "fill rule" in OpenGL's and
/// Direct3D's words). Both give every sample on an edge shared by two triangles to exactly
/// one of them.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum TieRule {
    /// As Mesa's llvmpipe under OpenGL: in image rows (y down), left and bottom edges. (It is
    /// the top-left rule applied to OpenGL's window coordinates, whose y points up.)
    #[default]
    Llvmpipe,
    /// The top-left rule as Direct3D states it (and most Vulkan drivers follow) in y-down
    /// framebuffer coordinates: left edges, and top edges (horizontal, interior below).
    TopLeft,
    /// No fill rule: every edge owns the samples exactly on it, so a sample on an edge two
    /// triangles share is drawn by both (a common homework mistake, `>= 0` on all three
    /// edges; `barylab compare` renders it to name the mistake, scene files cannot ask
    /// for it).
    #[serde(skip)]
    AllEdges,
    /// No fill rule the other way: no edge owns the samples exactly on it, so a sample on an
    /// edge two triangles share is missed by both (`> 0` on all three edges; as
    /// [`TieRule::AllEdges`], only for `barylab compare`).
    #[serde(skip)]
    NoEdges,
}

impl TieRule {
    /// Whether samples exactly on an edge of this kind are covered under this rule.
    pub fn inclusive(self, kind: EdgeKind) -> bool {
        match self {
            TieRule::Llvmpipe => matches!(kind, EdgeKind::Left | EdgeKind::Bottom),
            TieRule::TopLeft => matches!(kind, EdgeKind::Left | EdgeKind::Top),
            TieRule::AllEdges => true,
            TieRule::NoEdges => false,
        }
    }

    /// The name in scene files and on the command line: `llvmpipe` or `top_left`.
    pub fn name(self) -> &'static str {
        match self {
            TieRule::Llvmpipe => "llvmpipe",
            TieRule::TopLeft => "top_left",
            TieRule::AllEdges => "all_edges",
            TieRule::NoEdges => "no_edges",
        }
    }

    /// The rule in words, e.g. for the probe's coverage section.
    pub fn describe(self) -> &'static str {
        match self {
            TieRule::Llvmpipe => {
                "the llvmpipe rule (OpenGL on Mesa): centres on left and bottom edges are covered"
            }
            TieRule::TopLeft => {
                "the top-left rule (Direct3D, and most Vulkan drivers): centres on left and top edges are covered"
            }
            TieRule::AllEdges => "no fill rule: centres on every edge are covered",
            TieRule::NoEdges => "no fill rule: centres on an edge are never covered",
        }
    }

    /// Whether this is the default rule (scene files leave it out).
    pub fn is_default(&self) -> bool {
        *self == TieRule::default()
    }
}

/// One oriented edge: `value(P) = dir x (P - start) >= 0` inside the triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Edge {
    /// The edge's start vertex, snapped window position in 1/256 pixel.
    pub start: I64Vec2,
    /// Edge direction, oriented so that the interior is on the non-negative side.
    pub dir: I64Vec2,
    /// Left, right, top or bottom, from `dir` (y down).
    pub kind: EdgeKind,
    /// Whether samples exactly on the edge are covered (the tie rule for `kind`).
    pub inclusive: bool,
}

impl Edge {
    /// An edge no sample passes (a placeholder before a triangle is set).
    pub const EMPTY: Self = Self {
        start: I64Vec2::ZERO,
        dir: I64Vec2::ZERO,
        kind: EdgeKind::Top,
        inclusive: false,
    };

    /// Builds the edge S->E oriented for a triangle of the given sign of area.
    ///
    /// Classification (y down): interior side normal is `(-dir_y, dir_x)`. `dir_y < 0`: left edge;
    /// `dir_y > 0`: right edge; `dir_y = 0` and `dir_x < 0`: interior above, bottom edge;
    /// `dir_y = 0` and `dir_x > 0`: top edge.
    pub fn new(start: I64Vec2, end: I64Vec2, positive_area: bool) -> Self {
        Self::with_rule(start, end, positive_area, TieRule::Llvmpipe)
    }

    /// Like [`Edge::new`], with samples on the edge decided by `rule`.
    pub fn with_rule(start: I64Vec2, end: I64Vec2, positive_area: bool, rule: TieRule) -> Self {
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
        Self {
            start,
            dir,
            kind,
            inclusive: rule.inclusive(kind),
        }
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

    /// The smallest edge value that passes under the fill rule: 0 on an inclusive edge (left
    /// or bottom under the default rule), 1 otherwise (edge values are integers). The lanes
    /// and the scanline rasterizer test `value >= min_value()`.
    pub fn min_value(&self) -> i64 {
        if self.inclusive { 0 } else { 1 }
    }

    /// Whether a sample with this edge value passes the edge under the fill rule.
    pub fn passes(&self, value: i64) -> bool {
        value >= self.min_value()
    }
}

/// The screen-space weights `l_0, l_1, l_2` of a triangle as functions of the window
/// position, from the vertices' unsnapped window positions `V_0, V_1, V_2` (pixels):
///
/// `l_i(P) = ((V_{i+2} - V_{i+1}) x (P - V_{i+1})) / ((V_1 - V_0) x (V_2 - V_0))`,
///
/// the signed area of (edge i, P) over the triangle's, computed in `f64` in exactly this
/// order: `(d_x (P_y - S_y) - d_y (P_x - S_x)) * (1 / area2)` with `S = V_{i+1}`,
/// `d = V_{i+2} - V_{i+1}`. The lane paths repeat these operations bit for bit.
///
/// ```
/// use barylab::raster::setup::WeightPlanes;
/// use glam::DVec2;
/// let w = WeightPlanes::new([DVec2::new(0.0, 0.0), DVec2::new(4.0, 0.0), DVec2::new(0.0, 2.0)])
///     .unwrap();
/// // The centre of pixel (0, 0): P = (0.5, 0.5); l_1 = 0.5 / 4, l_2 = 0.5 / 2.
/// assert_eq!(w.at_pixel(0, 0), [0.625, 0.125, 0.25]);
/// // A vertex has weight 1 at itself, and the weights step by -d_y / area2 along a row.
/// assert_eq!(w.at(DVec2::new(4.0, 0.0)), [0.0, 1.0, 0.0]);
/// assert_eq!(w.step_x(), [-0.25, 0.25, 0.0]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WeightPlanes {
    /// Start of edge `i`: `V_{i+1}`.
    pub start: [DVec2; 3],
    /// Direction of edge `i`: `V_{i+2} - V_{i+1}`.
    pub dir: [DVec2; 3],
    /// Twice the signed area, `(V_1 - V_0) x (V_2 - V_0)`, in pixel^2.
    pub area2: f64,
    /// `1 / area2`.
    pub inv_area2: f64,
}

impl WeightPlanes {
    /// Planes of no triangle (a placeholder before a triangle is set).
    pub const EMPTY: Self = Self {
        start: [DVec2::ZERO; 3],
        dir: [DVec2::ZERO; 3],
        area2: 0.0,
        inv_area2: 0.0,
    };

    /// `None` when the three positions have no finite, non-zero area.
    pub fn new(v: [DVec2; 3]) -> Option<Self> {
        let area2 = (v[1] - v[0]).perp_dot(v[2] - v[0]);
        let inv_area2 = 1.0 / area2;
        if area2 == 0.0 || !inv_area2.is_finite() || !area2.is_finite() {
            return None;
        }
        let start = [v[1], v[2], v[0]];
        let end = [v[2], v[0], v[1]];
        Some(Self {
            start,
            dir: [0, 1, 2].map(|i| end[i] - start[i]),
            area2,
            inv_area2,
        })
    }

    /// The part of `l_i`'s numerator that depends on the row: `d_x (P_y - S_y)`.
    #[inline(always)]
    pub fn row_term(&self, i: usize, y: f64) -> f64 {
        self.dir[i].x * (y - self.start[i].y)
    }

    /// The part of `l_i`'s numerator that depends on the column: `d_y (P_x - S_x)`.
    #[inline(always)]
    pub fn column_term(&self, i: usize, x: f64) -> f64 {
        self.dir[i].y * (x - self.start[i].x)
    }

    /// `l_i` from its row and column terms: `(row_term - column_term) * (1 / area2)`.
    #[inline(always)]
    pub fn weight_of_terms(&self, row_term: f64, column_term: f64) -> f64 {
        (row_term - column_term) * self.inv_area2
    }

    /// `l_i` from its row term at window x: `(row_term - d_y (P_x - S_x)) * (1 / area2)`.
    #[inline(always)]
    pub fn weight(&self, i: usize, row_term: f64, x: f64) -> f64 {
        self.weight_of_terms(row_term, self.column_term(i, x))
    }

    /// The three weights at a window position.
    #[inline]
    pub fn at(&self, p: DVec2) -> [f64; 3] {
        // Written out: `[0, 1, 2].map` was left as a call (the scanline lanes call this per row).
        let l = |i: usize| self.weight(i, self.row_term(i, p.y), p.x);
        [l(0), l(1), l(2)]
    }

    /// The three weights at the centre of pixel (col, row): `P = (col + 0.5, row + 0.5)`.
    pub fn at_pixel(&self, col: u32, row: u32) -> [f64; 3] {
        self.at(pixel_centre(col, row))
    }

    /// How much each weight changes from one pixel to the next along a row: `-d_y / area2`.
    pub fn step_x(&self) -> [f64; 3] {
        self.dir.map(|d| -d.y * self.inv_area2)
    }

    /// The gradient of `l_i` per pixel: `(-d_y, d_x) / area2`.
    pub fn gradients(&self) -> [DVec2; 3] {
        self.dir.map(|d| DVec2::new(-d.y, d.x) * self.inv_area2)
    }
}

/// The centre of pixel (col, row) in window coordinates (pixels): `(col + 0.5, row + 0.5)`.
pub fn pixel_centre(col: u32, row: u32) -> DVec2 {
    DVec2::new(f64::from(col) + 0.5, f64::from(row) + 0.5)
}

/// A triangle ready for rasterization.
#[derive(Clone, Copy, Debug)]
pub struct TriangleSetup {
    /// The vertices, in their original order.
    pub v: [WindowVertex; 3],
    /// Edge `i` is opposite vertex `i` (from vertex i+1 to vertex i+2).
    pub edges: [Edge; 3],
    /// Twice the snapped triangle's area, in 1/65536 pixel^2, always positive.
    pub area2: i64,
    /// The interpolation weights, from the unsnapped positions (see [`WeightPlanes`]); from
    /// the snapped ones in the rare sliver whose unsnapped area is zero or of the other sign
    /// than the snapped one (a triangle the grid made, whose weights the float positions
    /// cannot give).
    pub weights: WeightPlanes,
    /// Front (counter-clockwise on screen) or back.
    pub facing: Facing,
    /// Inclusive pixel bounds `[x0, x1] x [y0, y1]` of candidate samples, within the viewport.
    pub bounds: PixelBounds,
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

/// Sets up a triangle under the default tie rule. Returns `None` for a zero-area triangle or
/// one whose bounds miss the viewport.
pub fn setup_triangle(v: [WindowVertex; 3], viewport: Viewport) -> Option<TriangleSetup> {
    setup_triangle_with(v, viewport, TieRule::default())
}

/// Like [`setup_triangle`], with samples exactly on an edge decided by `rule`.
pub fn setup_triangle_with(
    v: [WindowVertex; 3],
    viewport: Viewport,
    rule: TieRule,
) -> Option<TriangleSetup> {
    setup_triangle_samples(v, viewport, rule, false)
}

/// Like [`setup_triangle_with`]; with `multisample`, a triangle too thin to hold a pixel
/// centre is kept when its [`sample_pixel_bounds`] reach the viewport (with empty
/// [`TriangleSetup::bounds`]: it covers no centre, but it may cover other samples).
pub fn setup_triangle_samples(
    v: [WindowVertex; 3],
    viewport: Viewport,
    rule: TieRule,
    multisample: bool,
) -> Option<TriangleSetup> {
    let g = geometry_samples(
        ([v[0].fixed, v[1].fixed, v[2].fixed], v.map(|v| v.window)),
        (viewport, rule, multisample),
    )?;
    Some(TriangleSetup {
        v,
        edges: g.edges,
        area2: g.area2,
        weights: g.weights,
        facing: g.facing,
        bounds: g.bounds,
    })
}

/// Everything of a [`TriangleSetup`] but its vertices: what decides coverage and the
/// screen weights.
#[derive(Clone, Copy, Debug)]
pub struct Geometry {
    /// Edge `i` is opposite vertex `i`.
    pub edges: [Edge; 3],
    /// Twice the snapped area, in 1/65536 pixel^2, positive.
    pub area2: i64,
    /// The interpolation weights.
    pub weights: WeightPlanes,
    /// Front or back.
    pub facing: Facing,
    /// Pixels whose centres can be covered.
    pub bounds: PixelBounds,
}

/// The set-up of a triangle from its snapped (`fixed`, 1/256 pixel) and unsnapped (`window`,
/// pixels) positions: exactly what [`setup_triangle_with`] gives it, without the vertices
/// (the fast path sets triangles up from shared projected vertices). `None` exactly when
/// [`setup_triangle_with`] gives `None`.
pub fn triangle_geometry(
    p: [I64Vec2; 3],
    window: [DVec2; 3],
    viewport: Viewport,
    rule: TieRule,
) -> Option<Geometry> {
    geometry_samples((p, window), (viewport, rule, false))
}

/// [`triangle_geometry`], keeping a triangle between pixel centres with `multisample` (see
/// [`setup_triangle_samples`]).
fn geometry_samples(
    (p, window): ([I64Vec2; 3], [DVec2; 3]),
    (viewport, rule, multisample): (Viewport, TieRule, bool),
) -> Option<Geometry> {
    let mut g = Geometry {
        edges: [Edge::EMPTY; 3],
        area2: 0,
        weights: WeightPlanes::EMPTY,
        facing: Facing::Front,
        bounds: PixelBounds::EMPTY,
    };
    let (area2, facing) = geometry_into_samples(
        (p, window),
        (viewport, rule, multisample),
        &mut g.edges,
        &mut g.weights,
        &mut g.bounds,
    )?;
    Some(Geometry { area2, facing, ..g })
}

/// [`triangle_geometry`] written where the caller keeps its edges, weight planes and bounds
/// (the fast path sets hundreds of thousands of triangles up per frame, in place), returning
/// the twice-area and the facing. On `None` the three may hold anything.
pub fn geometry_into(
    p: [I64Vec2; 3],
    window: [DVec2; 3],
    viewport: Viewport,
    rule: TieRule,
    edges: &mut [Edge; 3],
    weights: &mut WeightPlanes,
    bounds: &mut PixelBounds,
) -> Option<(i64, Facing)> {
    geometry_into_samples((p, window), (viewport, rule, false), edges, weights, bounds)
}

/// [`geometry_into`], keeping a triangle between pixel centres with `multisample` (see
/// [`setup_triangle_samples`]).
fn geometry_into_samples(
    (p, window): ([I64Vec2; 3], [DVec2; 3]),
    (viewport, rule, multisample): (Viewport, TieRule, bool),
    edges: &mut [Edge; 3],
    weights: &mut WeightPlanes,
    bounds: &mut PixelBounds,
) -> Option<(i64, Facing)> {
    let (signed, b, w) = geometry(p, window, viewport, multisample)?;
    let positive = signed > 0;
    *edges = edges_of(p, positive, rule);
    *weights = w;
    *bounds = b;
    // Positive area in image coordinates (y down) means clockwise as displayed, which
    // OpenGL calls the back face.
    let facing = if positive {
        Facing::Back
    } else {
        Facing::Front
    };
    Some((signed.abs(), facing))
}

/// The edges V1->V2, V2->V0, V0->V1 of a triangle with these snapped positions, oriented for
/// the sign of its area.
fn edges_of(p: [I64Vec2; 3], positive: bool, rule: TieRule) -> [Edge; 3] {
    [
        Edge::with_rule(p[1], p[2], positive, rule),
        Edge::with_rule(p[2], p[0], positive, rule),
        Edge::with_rule(p[0], p[1], positive, rule),
    ]
}

/// The signed snapped area, the bounds and the weight planes; `None` for zero snapped area,
/// bounds outside the viewport, or no usable weight planes.
fn geometry(
    p: [I64Vec2; 3],
    window: [DVec2; 3],
    viewport: Viewport,
    multisample: bool,
) -> Option<(i64, PixelBounds, WeightPlanes)> {
    let signed = signed_area2(p[0], p[1], p[2]);
    if signed == 0 {
        return None;
    }
    let positive = signed > 0;
    let bounds = pixel_bounds(&p, viewport).or_else(|| {
        (multisample && sample_pixel_bounds(&p, viewport).is_some()).then_some(PixelBounds::EMPTY)
    })?;
    let weights = WeightPlanes::new(window)
        .filter(|w| (w.area2 > 0.0) == positive)
        .or_else(|| WeightPlanes::new(p.map(|f| f.as_dvec2() / SUBPIXEL as f64)))?;
    Some((signed, bounds, weights))
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

    /// Screen gradient (per pixel) of each *source-triangle* weight across this triangle
    /// ([`source_weight_gradients`] of its weights and vertices' barycentric attributes).
    pub fn source_weight_gradients(&self) -> [DVec2; 3] {
        source_weight_gradients(&self.weights, self.v.map(|v| v.varyings.bary()))
    }

    /// Whether the sample with these edge values is covered under the fill rule.
    pub fn covers(&self, e: &[i64; 3]) -> bool {
        self.edges[0].passes(e[0]) && self.edges[1].passes(e[1]) && self.edges[2].passes(e[2])
    }
}

/// Screen gradient (per pixel) of each *source-triangle* weight across a rasterized triangle
/// whose vertex `k` has source weights `bary[k]`, with the weights taken as screen-linear:
/// `grad f_i = sum_k bary[k][i] grad l_k`, with `grad l_k` from [`WeightPlanes::gradients`].
pub fn source_weight_gradients(weights: &WeightPlanes, bary: [[f32; 3]; 3]) -> [DVec2; 3] {
    let grad_l = weights.gradients();
    let mut out = [DVec2::ZERO; 3];
    for (i, g) in out.iter_mut().enumerate() {
        for (k, gl) in grad_l.iter().enumerate() {
            *g += *gl * f64::from(bary[k][i]);
        }
    }
    out
}
