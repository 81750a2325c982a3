//! Clipping in homogeneous clip space (OpenGL 4.6, section 13.7).
//!
//! A triangle is clipped against the near plane (z >= -w), the far plane (z <= w), a tiny
//! positive-w plane (keeps the perspective divide finite) and a guard band far outside the
//! viewport in x and y (keeps window coordinates within the fixed-point range of the edge
//! functions). The guard band lies outside the viewport, so it never changes which pixels are
//! covered. A new vertex on the segment from an inside vertex P to an outside vertex Q is
//! `P + t (Q - P)` with `t = d_P / (d_P - d_Q)`, where `d` is the signed distance to the plane;
//! `smooth` attributes are interpolated with that clip-space `t`. `noperspective` attributes
//! must stay linear on screen (OpenGL 4.6, section 13.7.1), so theirs are interpolated with
//! the screen-space fraction `t'` of the new vertex between the projected ends, as Mesa's
//! clipper does: `t' = (V_ndc - P_ndc) / (Q_ndc - P_ndc)` in x (or in y when the ends have the
//! same clip x), falling back to `t` when that is undefined.
//!
//! Intersections are always computed from the inside vertex towards the outside one, so a
//! segment shared by two triangles is cut at bit-identical points in both (no cracks).

use glam::DVec4;

use super::varying::Varyings;

/// Smallest clip w kept after clipping. With -w <= z <= w every kept point already has w >= 0;
/// this keeps 1/w finite for the one point (w = 0) those planes allow.
pub const MIN_CLIP_W: f64 = 1e-9;

/// Largest number of vertices a clipped triangle can have: 3 plus one per plane.
pub const MAX_POLYGON: usize = 3 + NUM_PLANES;

const NUM_PLANES: usize = 7;

/// One vertex in clip space with its attributes.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct ClipVertex {
    /// Homogeneous clip coordinates (x, y, z, w).
    pub clip: DVec4,
    /// The attributes as `smooth` (perspective-correct) interpolation uses them.
    pub varyings: Varyings,
    /// The attributes as `noperspective` (affine) interpolation uses them: the same as
    /// `varyings` at the mesh's own vertices; different at vertices the clipper made.
    pub noperspective: Varyings,
}

impl ClipVertex {
    /// A mesh vertex: both attribute sets equal.
    pub fn new(clip: DVec4, varyings: Varyings) -> Self {
        Self {
            clip,
            varyings,
            noperspective: varyings,
        }
    }
}

/// A clipping plane: the kept half-space is `dot(normal, clip) + offset >= 0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipPlane {
    /// Which plane it is.
    pub name: PlaneName,
    /// The plane's coefficients on clip-space `(x, y, z, w)`.
    pub normal: DVec4,
    /// The constant term (`-`[`MIN_CLIP_W`] for the positive-w plane, else 0).
    pub offset: f64,
}

/// Which plane cut a triangle, for explanations.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PlaneName {
    /// `z + w >= 0`: NDC z >= -1.
    Near,
    /// `w - z >= 0`: NDC z <= 1.
    Far,
    /// `w >= `[`MIN_CLIP_W`]: keeps 1/w finite at the one point (w = 0) near and far allow.
    PositiveW,
    /// `x + g w >= 0`: the guard band's left side, NDC x >= -g.
    GuardLeft,
    /// `g w - x >= 0`: the guard band's right side, NDC x <= g.
    GuardRight,
    /// `y + g w >= 0`: the guard band's bottom side, NDC y >= -g (y up in NDC).
    GuardBottom,
    /// `g w - y >= 0`: the guard band's top side, NDC y <= g.
    GuardTop,
}

impl ClipPlane {
    /// Signed distance of a clip-space point: positive or zero inside.
    ///
    /// ```
    /// use barylab::raster::clip::{planes, PlaneName};
    /// use glam::DVec4;
    /// let near = planes(1000.0)[0];
    /// assert_eq!(near.name, PlaneName::Near);
    /// // Near plane: z + w >= 0.
    /// assert_eq!(near.distance(DVec4::new(0.0, 0.0, -0.5, 1.0)), 0.5);
    /// assert_eq!(near.distance(DVec4::new(0.0, 0.0, -2.0, 1.0)), -1.0);
    /// ```
    pub fn distance(&self, clip: DVec4) -> f64 {
        self.normal.dot(clip) + self.offset
    }
}

/// The planes a triangle is clipped against, given the guard band half-size in NDC units.
pub fn planes(guard_band_ndc: f64) -> [ClipPlane; NUM_PLANES] {
    let g = guard_band_ndc;
    let p = |name, x, y, z, w, offset| ClipPlane {
        name,
        normal: DVec4::new(x, y, z, w),
        offset,
    };
    [
        p(PlaneName::Near, 0.0, 0.0, 1.0, 1.0, 0.0),
        p(PlaneName::Far, 0.0, 0.0, -1.0, 1.0, 0.0),
        p(PlaneName::PositiveW, 0.0, 0.0, 0.0, 1.0, -MIN_CLIP_W),
        p(PlaneName::GuardLeft, 1.0, 0.0, 0.0, g, 0.0),
        p(PlaneName::GuardRight, -1.0, 0.0, 0.0, g, 0.0),
        p(PlaneName::GuardBottom, 0.0, 1.0, 0.0, g, 0.0),
        p(PlaneName::GuardTop, 0.0, -1.0, 0.0, g, 0.0),
    ]
}

/// A convex polygon in clip space (the clipped triangle), stored without allocation.
#[derive(Clone, Copy, Debug)]
pub struct ClipPolygon {
    verts: [ClipVertex; MAX_POLYGON],
    len: usize,
    /// The planes that actually cut the triangle, as a bit set over `planes()` order.
    cut_by: u8,
}

impl ClipPolygon {
    /// The polygon's vertices, in the triangle's winding order.
    pub fn vertices(&self) -> &[ClipVertex] {
        &self.verts[..self.len]
    }

    /// True when the whole triangle was inside every plane.
    pub fn unclipped(&self) -> bool {
        self.cut_by == 0
    }

    /// The planes that cut the triangle.
    pub fn cut_by(&self, guard_band_ndc: f64) -> Vec<PlaneName> {
        planes(guard_band_ndc)
            .iter()
            .enumerate()
            .filter(|(i, _)| self.cut_by & (1 << i) != 0)
            .map(|(_, p)| p.name)
            .collect()
    }

    fn push(&mut self, v: ClipVertex) {
        if self.len < MAX_POLYGON {
            self.verts[self.len] = v;
            self.len += 1;
        }
    }
}

/// The point where segment P->Q crosses a plane, from P (inside) towards Q (outside):
/// `t = d_P / (d_P - d_Q)`, position and attributes `P + t (Q - P)`.
///
/// ```
/// use barylab::raster::clip::{intersect, ClipVertex};
/// use barylab::raster::varying::Varyings;
/// use glam::{DVec4, Vec2, Vec3};
/// let p = ClipVertex::new(DVec4::new(0.0, 0.0, 0.0, 1.0),
///     Varyings::new([1.0, 0.0, 0.0], Vec2::new(0.0, 0.0), Vec3::ZERO));
/// let q = ClipVertex::new(DVec4::new(0.0, 0.0, -3.0, -1.0),
///     Varyings::new([0.0, 1.0, 0.0], Vec2::new(1.0, 1.0), Vec3::ONE));
/// // Near plane z + w >= 0: d_P = 1, d_Q = -4, t = 1 / 5.
/// let (m, t) = intersect(&p, &q, 1.0, -4.0);
/// assert_eq!(t, 0.2);
/// assert!((m.clip - DVec4::new(0.0, 0.0, -0.6, 0.6)).abs().max_element() < 1e-15);
/// assert_eq!(m.varyings.uv(), Vec2::new(0.2, 0.2));
/// ```
pub fn intersect(p: &ClipVertex, q: &ClipVertex, d_p: f64, d_q: f64) -> (ClipVertex, f64) {
    let t = d_p / (d_p - d_q);
    let clip = p.clip + (q.clip - p.clip) * t;
    let t_screen = screen_fraction(p.clip, q.clip, clip).unwrap_or(t);
    let v = ClipVertex {
        clip,
        varyings: Varyings::lerp(&p.varyings, &q.varyings, t),
        noperspective: Varyings::lerp(&p.noperspective, &q.noperspective, t_screen),
    };
    (v, t)
}

/// The fraction `t'` of the projected point `v` between the projected ends `p` and `q`:
/// `(v_k/v_w - p_k/p_w) / (q_k/q_w - p_k/p_w)`, along the screen axis `k` (x or y) in which
/// the projected ends are further apart (Mesa takes x unless the ends share their clip x; the
/// longer axis gives the same fraction, better conditioned). `None` when the projected ends
/// coincide or the fraction is not finite (an end at w = 0).
///
/// ```
/// use barylab::raster::clip::screen_fraction;
/// use glam::DVec4;
/// // p at NDC x = 0 (w = 1), q at NDC x = 1 (x = 3, w = 3); the point halfway in clip space,
/// // (1.5, w = 2), is at NDC x = 0.75: three quarters of the way on screen.
/// let (p, q) = (DVec4::new(0.0, 0.0, 0.0, 1.0), DVec4::new(3.0, 0.0, 0.0, 3.0));
/// assert_eq!(screen_fraction(p, q, (p + q) * 0.5), Some(0.75));
/// ```
pub fn screen_fraction(p: DVec4, q: DVec4, v: DVec4) -> Option<f64> {
    let (pn, qn, vn) = (
        p.truncate().truncate() / p.w,
        q.truncate().truncate() / q.w,
        v.truncate().truncate() / v.w,
    );
    let d = qn - pn;
    let k = if d.x.abs() >= d.y.abs() { 0 } else { 1 };
    let t = (vn[k] - pn[k]) / d[k];
    t.is_finite().then_some(t)
}

/// Whether every vertex is inside every clipping plane: then [`clip_triangle`] returns the
/// triangle unchanged (its `unclipped()` is true), and the renderer skips building the polygon.
pub fn inside_every_plane(tri: &[ClipVertex; 3], guard_band_ndc: f64) -> bool {
    planes(guard_band_ndc)
        .iter()
        .all(|p| tri.iter().all(|v| p.distance(v.clip) >= 0.0))
}

/// Clips a triangle against all planes (Sutherland-Hodgman in clip space).
///
/// Returns the clipped convex polygon, which may be empty (fewer than 3 vertices) when the
/// triangle lies wholly outside. Vertices must be finite.
pub fn clip_triangle(tri: &[ClipVertex; 3], guard_band_ndc: f64) -> ClipPolygon {
    let all = planes(guard_band_ndc);
    let mut poly = ClipPolygon {
        verts: [ClipVertex::default(); MAX_POLYGON],
        len: 0,
        cut_by: 0,
    };
    for v in tri {
        poly.push(*v);
    }
    for (index, plane) in all.iter().enumerate() {
        if poly.len == 0 {
            break;
        }
        let inside_all = poly
            .vertices()
            .iter()
            .all(|v| plane.distance(v.clip) >= 0.0);
        if inside_all {
            continue;
        }
        poly.cut_by |= 1 << index;
        let input = poly;
        poly.len = 0;
        let n = input.len;
        for i in 0..n {
            let cur = input.verts[i];
            let next = input.verts[(i + 1) % n];
            let d_cur = plane.distance(cur.clip);
            let d_next = plane.distance(next.clip);
            if d_cur >= 0.0 {
                poly.push(cur);
                if d_next < 0.0 {
                    poly.push(intersect(&cur, &next, d_cur, d_next).0);
                }
            } else if d_next >= 0.0 {
                poly.push(intersect(&next, &cur, d_next, d_cur).0);
            }
        }
    }
    if poly.len < 3 {
        poly.len = 0;
    }
    if poly.cut_by != 0
        && let Some(screen) = ScreenLinear::new(tri)
    {
        for v in &mut poly.verts[..poly.len] {
            if tri.iter().all(|t| t.clip != v.clip)
                && let Some(np) = screen.at(v.clip)
            {
                v.noperspective = np;
            }
        }
    }
    poly
}

/// The `noperspective` attributes of a triangle as a function of the screen position: the
/// values at its corners interpolated with 2D barycentric weights over its projected corners
/// `(x/w, y/w)` (a corner behind the camera projects through its negative w, as in OpenGL).
/// This is what "linear on screen" means, and what clipping must preserve (OpenGL 4.6,
/// section 13.7.1); evaluating it directly at the vertices the clipper made gives the same
/// values as interpolating along each cut edge with the screen-space fraction
/// ([`screen_fraction`]), without the chain of interpolations, which breaks down at points
/// near w = 0 (projected to infinity).
struct ScreenLinear {
    corners: [glam::DVec2; 3],
    area: f64,
    values: [Varyings; 3],
}

/// A projected triangle this much smaller than its extent squared has no usable screen
/// barycentrics (its corners are nearly collinear on screen).
const MIN_SCREEN_AREA: f64 = 1e-12;

impl ScreenLinear {
    fn new(tri: &[ClipVertex; 3]) -> Option<Self> {
        let corners = tri.map(|v| glam::DVec2::new(v.clip.x / v.clip.w, v.clip.y / v.clip.w));
        let area = (corners[1] - corners[0]).perp_dot(corners[2] - corners[0]);
        let extent = corners
            .iter()
            .map(|c| c.abs().max_element())
            .fold(0.0, f64::max);
        (area.is_finite() && area.abs() > MIN_SCREEN_AREA * extent * extent).then_some(Self {
            corners,
            area,
            values: tri.map(|v| v.noperspective),
        })
    }

    /// The attributes at the screen position of clip-space point `clip`; `None` where it has
    /// no finite screen position.
    fn at(&self, clip: DVec4) -> Option<Varyings> {
        let p = glam::DVec2::new(clip.x / clip.w, clip.y / clip.w);
        let c = &self.corners;
        let weights = [
            (c[1] - p).perp_dot(c[2] - p) / self.area,
            (c[2] - p).perp_dot(c[0] - p) / self.area,
            (c[0] - p).perp_dot(c[1] - p) / self.area,
        ];
        weights
            .iter()
            .all(|w| w.is_finite())
            .then(|| Varyings::weighted(&weights, &self.values))
    }
}
