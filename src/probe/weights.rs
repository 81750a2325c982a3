//! The weight formulas the probe shows side by side, each in the form a textbook or course writes it.
//!
//! All work in `f64` on positions given in pixels (window coordinates, y down) or in clip or
//! view space. The rasterizer ([`crate::raster::setup`]) decides coverage with exact
//! fixed-point edge functions and takes its weights from f64 weight planes on the unsnapped
//! positions; these independent forms are what a student would write, and the probe shows
//! that they agree with it.

use glam::{DMat4, DVec2, DVec3, DVec4};
use serde::Serialize;

/// 2D cross product `u x v = u_x v_y - u_y v_x`: twice the signed area of the triangle
/// spanned by `u` and `v`.
///
/// ```
/// use barylab::probe::weights::cross2;
/// use glam::DVec2;
/// assert_eq!(cross2(DVec2::new(2.0, 0.0), DVec2::new(0.0, 3.0)), 6.0);
/// assert_eq!(cross2(DVec2::new(0.0, 3.0), DVec2::new(2.0, 0.0)), -6.0);
/// ```
pub fn cross2(u: DVec2, v: DVec2) -> f64 {
    u.x * v.y - u.y * v.x
}

/// The explicit formula written from corner A (beta and gamma; alpha = 1 - beta - gamma), with
/// its numerators and denominators, and GAMES101's form of the slides (alpha and beta from B
/// and C).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ExplicitFormula {
    /// `N_beta = (y_P - y_A)(x_C - x_A) - (x_P - x_A)(y_C - y_A)`, in px².
    pub beta_numerator: f64,
    /// `D_beta = (y_B - y_A)(x_C - x_A) - (x_B - x_A)(y_C - y_A)`, in px².
    pub beta_denominator: f64,
    /// `N_gamma = (y_P - y_A)(x_B - x_A) - (x_P - x_A)(y_B - y_A)`, in px².
    pub gamma_numerator: f64,
    /// `D_gamma = (y_C - y_A)(x_B - x_A) - (x_C - x_A)(y_B - y_A)`, in px².
    pub gamma_denominator: f64,
    /// `[alpha, beta, gamma]`.
    pub weights: [f64; 3],
    /// The four differences of `N_beta = f_0 f_1 - f_2 f_3`:
    /// `[y_P - y_A, x_C - x_A, x_P - x_A, y_C - y_A]`.
    pub beta_numerator_factors: [f64; 4],
    /// Of `D_beta`: `[y_B - y_A, x_C - x_A, x_B - x_A, y_C - y_A]`.
    pub beta_denominator_factors: [f64; 4],
    /// Of `N_gamma`: `[y_P - y_A, x_B - x_A, x_P - x_A, y_B - y_A]`.
    pub gamma_numerator_factors: [f64; 4],
    /// Of `D_gamma`: `[y_C - y_A, x_B - x_A, x_C - x_A, y_B - y_A]`.
    pub gamma_denominator_factors: [f64; 4],
    /// `[alpha, beta, gamma]` by GAMES101's slides (lecture 9), from B and C:
    /// `alpha = (-(x - x_B)(y_C - y_B) + (y - y_B)(x_C - x_B)) / (-(x_A - x_B)(y_C - y_B) + (y_A - y_B)(x_C - x_B))`,
    /// `beta = (-(x - x_C)(y_A - y_C) + (y - y_C)(x_A - x_C)) / (-(x_B - x_C)(y_A - y_C) + (y_B - y_C)(x_A - x_C))`,
    /// `gamma = 1 - alpha - beta`.
    pub slides: [f64; 3],
}

/// Barycentric weights of `p` in the triangle `v = [A, B, C]` by the explicit formula written
/// from corner A:
///
/// `beta = ((y - y_A)(x_C - x_A) - (x - x_A)(y_C - y_A)) / ((y_B - y_A)(x_C - x_A) - (x_B - x_A)(y_C - y_A))`,
/// `gamma = ((y - y_A)(x_B - x_A) - (x - x_A)(y_B - y_A)) / ((y_C - y_A)(x_B - x_A) - (x_C - x_A)(y_B - y_A))`,
/// `alpha = 1 - beta - gamma`; and by GAMES101's slides ([`ExplicitFormula::slides`]), whose
/// numerators are the 2D cross products `(C - B) x (P - B)` and `(A - C) x (P - C)`. `None`
/// for a degenerate triangle.
///
/// ```
/// use barylab::probe::weights::explicit_formula;
/// use glam::DVec2;
/// // A = (0, 8), B = (8, 8), C = (0, 0), P = (4.5, 6.5): beta = 36 / 64, gamma = -12 / -64.
/// let v = [DVec2::new(0.0, 8.0), DVec2::new(8.0, 8.0), DVec2::new(0.0, 0.0)];
/// let f = explicit_formula(DVec2::new(4.5, 6.5), v).unwrap();
/// assert_eq!((f.beta_numerator, f.beta_denominator), (36.0, 64.0));
/// assert_eq!((f.gamma_numerator, f.gamma_denominator), (-12.0, -64.0));
/// assert_eq!(f.weights, [0.25, 0.5625, 0.1875]);
/// // The slides, from B and C: alpha = -16 / -64, beta = -36 / -64.
/// assert_eq!(f.slides, [0.25, 0.5625, 0.1875]);
/// ```
pub fn explicit_formula(p: DVec2, v: [DVec2; 3]) -> Option<ExplicitFormula> {
    let [a, b, c] = v;
    // `[y_Q - y_A, x_U - x_A, x_Q - x_A, y_U - y_A]`, the factors of
    // `(y_Q - y_A)(x_U - x_A) - (x_Q - x_A)(y_U - y_A)`.
    let factors = |q: DVec2, u: DVec2| [q.y - a.y, u.x - a.x, q.x - a.x, u.y - a.y];
    let value = |f: [f64; 4]| f[0] * f[1] - f[2] * f[3];
    let beta_numerator_factors = factors(p, c);
    let beta_denominator_factors = factors(b, c);
    let gamma_numerator_factors = factors(p, b);
    let gamma_denominator_factors = factors(c, b);
    let beta_numerator = value(beta_numerator_factors);
    let beta_denominator = value(beta_denominator_factors);
    let gamma_numerator = value(gamma_numerator_factors);
    let gamma_denominator = value(gamma_denominator_factors);
    if beta_denominator == 0.0 || gamma_denominator == 0.0 {
        return None;
    }
    let beta = beta_numerator / beta_denominator;
    let gamma = gamma_numerator / gamma_denominator;
    let slides_alpha = cross2(c - b, p - b) / cross2(c - b, a - b);
    let slides_beta = cross2(a - c, p - c) / cross2(a - c, b - c);
    Some(ExplicitFormula {
        beta_numerator,
        beta_denominator,
        gamma_numerator,
        gamma_denominator,
        weights: [1.0 - beta - gamma, beta, gamma],
        beta_numerator_factors,
        beta_denominator_factors,
        gamma_numerator_factors,
        gamma_denominator_factors,
        slides: [slides_alpha, slides_beta, 1.0 - slides_alpha - slides_beta],
    })
}

/// Weights as ratios of signed areas.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct AreaWeights {
    /// The signed sub-areas opposite each vertex, in pixels^2: `[S_A, S_B, S_C]`.
    pub sub_areas: [f64; 3],
    /// The signed area of the whole triangle, `S`.
    pub area: f64,
    /// `[S_A / S, S_B / S, S_C / S]`.
    pub weights: [f64; 3],
    /// `S_A + S_B + S_C` (equal to `S` up to rounding).
    pub sub_area_sum: f64,
    /// The cross-product form only: the vectors `(u, v)` of `S = ½ u x v`, `S_A`, `S_B`,
    /// `S_C` in that order: `(BC, BA)`, `(BC, BP)`, `(CA, CP)`, `(AB, AP)`.
    pub vectors: Option<[[[f64; 2]; 2]; 4]>,
}

/// Weights as ratios of signed areas from 2D cross products:
/// `S_A = (BC x BP) / 2`, `S_B = (CA x CP) / 2`, `S_C = (AB x AP) / 2`, `S = (BC x BA) / 2`,
/// weights `S_A / S`, `S_B / S`, `S_C / S`. A weight is negative when P is on the far side
/// of the opposite edge. `None` for a degenerate triangle.
///
/// ```
/// use barylab::probe::weights::cross_product_weights;
/// use glam::DVec2;
/// let v = [DVec2::new(0.0, 8.0), DVec2::new(8.0, 8.0), DVec2::new(0.0, 0.0)];
/// let w = cross_product_weights(DVec2::new(4.5, 6.5), v).unwrap();
/// // BC = (-8, -8), BA = (-8, 0): S = ((-8)(0) - (-8)(-8)) / 2 = -32.
/// assert_eq!(w.area, -32.0);
/// // BP = (-3.5, -1.5): S_A = ((-8)(-1.5) - (-8)(-3.5)) / 2 = -8, weight 0.25.
/// assert_eq!(w.sub_areas, [-8.0, -18.0, -6.0]);
/// assert_eq!(w.weights, [0.25, 0.5625, 0.1875]);
/// // Outside edge BC: a negative weight.
/// let out = cross_product_weights(DVec2::new(6.0, 2.0), v).unwrap();
/// assert!(out.weights[0] < 0.0);
/// ```
pub fn cross_product_weights(p: DVec2, v: [DVec2; 3]) -> Option<AreaWeights> {
    let [a, b, c] = v;
    // (u, v) of S, S_A, S_B, S_C: (BC, BA), (BC, BP), (CA, CP), (AB, AP).
    let vectors = [
        (c - b, a - b),
        (c - b, p - b),
        (a - c, p - c),
        (b - a, p - a),
    ];
    let [area, sub_areas @ ..] = vectors.map(|(u, w)| cross2(u, w) / 2.0);
    if area == 0.0 {
        return None;
    }
    Some(AreaWeights {
        sub_areas,
        area,
        weights: sub_areas.map(|s| s / area),
        sub_area_sum: sub_areas[0] + sub_areas[1] + sub_areas[2],
        vectors: Some(vectors.map(|(u, w)| [u.to_array(), w.to_array()])),
    })
}

/// The signed area of a triangle by the shoelace formula of the OpenGL specification
/// (eq. 14.8 uses it): `A = 1/2 sum_i (x_i y_(i+1) - x_(i+1) y_i)`, indices mod 3.
///
/// ```
/// use barylab::probe::weights::shoelace_area;
/// use glam::DVec2;
/// let t = [DVec2::new(0.0, 0.0), DVec2::new(4.0, 0.0), DVec2::new(0.0, 2.0)];
/// assert_eq!(shoelace_area(t), 4.0);
/// ```
pub fn shoelace_area(t: [DVec2; 3]) -> f64 {
    let mut s = 0.0;
    for i in 0..3 {
        let (p, q) = (t[i], t[(i + 1) % 3]);
        s += p.x * q.y - q.x * p.y;
    }
    s / 2.0
}

/// Weights by the OpenGL area form (OpenGL 4.6, eq. 14.8):
/// `a = A(P, B, C) / A(A, B, C)`, `b = A(A, P, C) / A(A, B, C)`, `c = A(A, B, P) / A(A, B, C)`,
/// with `A` the [`shoelace_area`]. `None` for a degenerate triangle.
///
/// ```
/// use barylab::probe::weights::gl_area_weights;
/// use glam::DVec2;
/// let v = [DVec2::new(0.0, 8.0), DVec2::new(8.0, 8.0), DVec2::new(0.0, 0.0)];
/// let w = gl_area_weights(DVec2::new(4.5, 6.5), v).unwrap();
/// assert_eq!(w.area, -32.0);
/// assert_eq!(w.weights, [0.25, 0.5625, 0.1875]);
/// ```
pub fn gl_area_weights(p: DVec2, v: [DVec2; 3]) -> Option<AreaWeights> {
    let [a, b, c] = v;
    let area = shoelace_area([a, b, c]);
    if area == 0.0 {
        return None;
    }
    let sub_areas = [
        shoelace_area([p, b, c]),
        shoelace_area([a, p, c]),
        shoelace_area([a, b, p]),
    ];
    Some(AreaWeights {
        sub_areas,
        area,
        weights: sub_areas.map(|s| s / area),
        sub_area_sum: sub_areas[0] + sub_areas[1] + sub_areas[2],
        vectors: None,
    })
}

/// The perspective correction in the r, s, t / W_P notation (a derivation straight from homogeneous coordinates).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct WpCorrection {
    /// `[1/W_A, 1/W_B, 1/W_C]`.
    pub inv_w: [f64; 3],
    /// `1/W_P = r/W_A + s/W_B + t/W_C`, linear on screen.
    pub inv_w_p: f64,
    /// `W_P = 1 / (1/W_P)`.
    pub w_p: f64,
    /// `[a, b, c] = [r W_P / W_A, s W_P / W_B, t W_P / W_C]`.
    pub weights: [f64; 3],
    /// `a + b + c`.
    pub sum: f64,
}

/// Perspective-correct weights from screen weights `[r, s, t]` and clip `w` of the vertices
/// : `1/W_P = r/W_A + s/W_B + t/W_C`, `W_P = 1 / (1/W_P)`, `a = r W_P / W_A`,
/// `b = s W_P / W_B`, `c = t W_P / W_C`. `None` if some `w` is not positive or `1/W_P` is not
/// positive (the sample's ray meets the triangle's plane behind the camera).
///
/// ```
/// use barylab::probe::weights::w_p_correction;
/// // r, s, t = 1/4, 9/16, 3/16 and W = 1, 2, 4: 1/W_P = 1/4 + 9/32 + 3/64 = 37/64.
/// let p = w_p_correction([0.25, 0.5625, 0.1875], [1.0, 2.0, 4.0]).unwrap();
/// assert_eq!(p.inv_w_p, 37.0 / 64.0);
/// assert!((p.w_p - 64.0 / 37.0).abs() < 1e-15);
/// let expect = [16.0 / 37.0, 18.0 / 37.0, 3.0 / 37.0];
/// assert!((0..3).all(|i| (p.weights[i] - expect[i]).abs() < 1e-15));
/// ```
pub fn w_p_correction(screen: [f64; 3], w: [f64; 3]) -> Option<WpCorrection> {
    if !w.iter().all(|&w| w > 0.0) {
        return None;
    }
    let inv_w = w.map(|w| 1.0 / w);
    let inv_w_p = screen[0] * inv_w[0] + screen[1] * inv_w[1] + screen[2] * inv_w[2];
    if !(inv_w_p > 0.0 && inv_w_p.is_finite()) {
        return None;
    }
    let w_p = 1.0 / inv_w_p;
    let weights = [
        screen[0] * w_p / w[0],
        screen[1] * w_p / w[1],
        screen[2] * w_p / w[2],
    ];
    Some(WpCorrection {
        inv_w,
        inv_w_p,
        w_p,
        weights,
        sum: weights[0] + weights[1] + weights[2],
    })
}

/// Smallest accepted `|det M| / (|row_0| |row_1| |row_2| |row_3|)` of the 4x4 system. By
/// Hadamard's inequality the ratio is at most 1; near 0 the rows are nearly dependent (the
/// triangle is seen edge-on), and the f64 solution would keep fewer than about four correct
/// digits below this bound.
pub const MIN_RELATIVE_DET: f64 = 1e-12;

/// The 4x4 linear system (Umetani's Applied Computer Graphics notes) with its solution.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct HomogeneousSystem {
    /// The matrix, row by row.
    pub matrix: [[f64; 4]; 4],
    /// The right-hand side `(0, 0, 1, 0)`.
    pub rhs: [f64; 4],
    /// `(b_A, b_B, b_C, w)`.
    pub solution: [f64; 4],
    /// Largest `|M x - rhs|` component of the computed solution.
    pub residual: f64,
}

/// Solves the 4x4 system for the weights on the 3D triangle and the sample's clip w:
///
/// ```text
/// [ q_Ax  q_Bx  q_Cx  -s_x ]   [ b_A ]   [ 0 ]
/// [ q_Ay  q_By  q_Cy  -s_y ] . [ b_B ] = [ 0 ]
/// [ 1     1     1      0   ]   [ b_C ]   [ 1 ]
/// [ q_Aw  q_Bw  q_Cw  -1   ]   [ w   ]   [ 0 ]
/// ```
///
/// `q` are the vertices in clip space (only x, y and w are used), `s` is the sample in NDC.
/// Rows 1, 2 and 4 say that `sum b q` is the clip-space point `(s_x w, s_y w, _, w)` seen at
/// the sample; row 3 that the weights sum to 1. `None` if the system is (nearly) singular
/// (see [`MIN_RELATIVE_DET`]).
///
/// ```
/// use barylab::probe::weights::solve_homogeneous_system;
/// use glam::{DVec2, DVec4};
/// let q = [
///     DVec4::new(-1.0, -1.0, 0.0, 1.0),
///     DVec4::new(2.0, -2.0, 0.0, 2.0),
///     DVec4::new(-4.0, 4.0, 0.0, 4.0),
/// ];
/// let s = solve_homogeneous_system(q, DVec2::new(0.125, -0.625)).unwrap();
/// let expect = [16.0 / 37.0, 18.0 / 37.0, 3.0 / 37.0, 64.0 / 37.0];
/// assert!((0..4).all(|i| (s.solution[i] - expect[i]).abs() < 1e-14));
/// ```
pub fn solve_homogeneous_system(q: [DVec4; 3], s: DVec2) -> Option<HomogeneousSystem> {
    let matrix = [
        [q[0].x, q[1].x, q[2].x, -s.x],
        [q[0].y, q[1].y, q[2].y, -s.y],
        [1.0, 1.0, 1.0, 0.0],
        [q[0].w, q[1].w, q[2].w, -1.0],
    ];
    let rhs = [0.0, 0.0, 1.0, 0.0];
    if !matrix.iter().flatten().all(|x| x.is_finite()) {
        return None;
    }
    // glam stores columns; the rows above are the columns of the transpose.
    let m = DMat4::from_cols_array_2d(&matrix).transpose();
    let det = m.determinant();
    let hadamard: f64 = matrix
        .iter()
        .map(|r| DVec4::from_array(*r).length())
        .product();
    // Also rejects a NaN determinant.
    if det.is_nan() || det.abs() <= MIN_RELATIVE_DET * hadamard {
        return None;
    }
    let x = m.inverse() * DVec4::from_array(rhs);
    let residual = (m * x - DVec4::from_array(rhs)).abs().max_element();
    Some(HomogeneousSystem {
        matrix,
        rhs,
        solution: x.to_array(),
        residual,
    })
}

/// Smallest accepted `|n . d| / (|n| |d|)` for a ray to hit a triangle's plane: below this
/// the ray grazes the plane (the triangle is seen edge-on) and the hit point is not
/// determined to useful precision.
pub const MIN_RAY_PLANE_COSINE: f64 = 1e-9;

/// Where a ray meets a triangle's plane, with the point's barycentric weights.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct RayHit {
    /// The plane normal `n = (B - A) x (C - A)`.
    pub normal: [f64; 3],
    /// `[B - A, C - A]`.
    pub edges: [[f64; 3]; 2],
    /// `n.(A - O)`, the numerator of `t`.
    pub t_numerator: f64,
    /// `n.d`, the denominator of `t`.
    pub t_denominator: f64,
    /// The ray parameter of the hit, `t = n.(A - O) / n.d`.
    pub t: f64,
    /// The point `O + t d`.
    pub point: [f64; 3],
    /// `[n.((B-P)x(C-P)), n.((C-P)x(A-P)), n.((A-P)x(B-P))] / n.n`.
    pub weights: [f64; 3],
}

/// Intersects the ray `O + t d` with the plane of triangle `[A, B, C]` and returns the hit
/// point's barycentric weights, as ratios of signed sub-areas in 3D:
/// `n = (B - A) x (C - A)`, `t = n.(A - O) / n.d`, `P = O + t d`,
/// `alpha = n.((B - P) x (C - P)) / n.n` and likewise. `None` if the ray is parallel to the
/// plane (see [`MIN_RAY_PLANE_COSINE`]) or the triangle is degenerate.
///
/// ```
/// use barylab::probe::weights::ray_triangle;
/// use glam::DVec3;
/// // The triangle (0,0,-2), (2,0,-2), (0,2,-2); the ray from the origin towards (0.5, 0.5, -1)
/// // meets z = -2 at t = 2, point (1, 1, -2): weights (0, 1/2, 1/2).
/// let tri = [DVec3::new(0.0, 0.0, -2.0), DVec3::new(2.0, 0.0, -2.0), DVec3::new(0.0, 2.0, -2.0)];
/// let hit = ray_triangle(DVec3::ZERO, DVec3::new(0.5, 0.5, -1.0), tri).unwrap();
/// assert_eq!(hit.t, 2.0);
/// assert_eq!(hit.point, [1.0, 1.0, -2.0]);
/// assert_eq!(hit.weights, [0.0, 0.5, 0.5]);
/// ```
pub fn ray_triangle(origin: DVec3, dir: DVec3, tri: [DVec3; 3]) -> Option<RayHit> {
    let [a, b, c] = tri;
    let n = (b - a).cross(c - a);
    let nn = n.dot(n);
    let nd = n.dot(dir);
    let grazing = nd.abs() <= MIN_RAY_PLANE_COSINE * nn.sqrt() * dir.length();
    if nn.is_nan() || nn <= 0.0 || nd.is_nan() || grazing {
        return None;
    }
    let t_numerator = n.dot(a - origin);
    let t = t_numerator / nd;
    let p = origin + dir * t;
    let weights = [
        n.dot((b - p).cross(c - p)) / nn,
        n.dot((c - p).cross(a - p)) / nn,
        n.dot((a - p).cross(b - p)) / nn,
    ];
    Some(RayHit {
        normal: n.to_array(),
        edges: [(b - a).to_array(), (c - a).to_array()],
        t_numerator,
        t_denominator: nd,
        t,
        point: p.to_array(),
        weights,
    })
}
