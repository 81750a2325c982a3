//! Interpolation at a sample: screen-space weights, perspective-correct weights, attributes.

use glam::Vec2;

use super::setup::{TriangleSetup, sample_point};
use super::varying::Varyings;

/// How `smooth` attributes are interpolated.
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, Hash, Default, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum Interpolation {
    /// Screen-space (affine) weights, like GLSL `noperspective`.
    Affine,
    /// Perspective-correct weights (OpenGL 4.6 eq. 14.9), the default for GLSL `smooth`.
    #[default]
    Perspective,
}

/// Perspective-correct weights from screen weights `l` and the vertices' 1/w:
/// `a_i = (l_i / w_i) / (l_0 / w_0 + l_1 / w_1 + l_2 / w_2)`.
///
/// ```
/// use barylab::raster::interpolate::perspective_weights;
/// // Halfway on screen between a vertex at w = 1 and one at w = 3: 1/w_P = (1 + 1/3) / 2,
/// // so w_P = 1.5 and the near vertex gets weight (0.5 / 1) * 1.5 = 0.75.
/// let p = perspective_weights(&[0.5, 0.5, 0.0], &[1.0, 1.0 / 3.0, 1.0]).unwrap();
/// assert!((p[0] - 0.75).abs() < 1e-15 && (p[1] - 0.25).abs() < 1e-15 && p[2] == 0.0);
/// ```
pub fn perspective_weights(l: &[f64; 3], inv_w: &[f64; 3]) -> Option<[f64; 3]> {
    let q = [l[0] * inv_w[0], l[1] * inv_w[1], l[2] * inv_w[2]];
    let sum = q[0] + q[1] + q[2];
    if !(sum > 0.0 && sum.is_finite()) {
        return None;
    }
    let inv = 1.0 / sum;
    Some([q[0] * inv, q[1] * inv, q[2] * inv])
}

/// Everything interpolated at one covered sample of one (clipped) triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fragment {
    /// The three edge values at the sample (snapped, exact: they decided coverage).
    pub edges: [i64; 3],
    /// Screen-space weights of the rasterized triangle's vertices, from the unsnapped
    /// positions ([`WeightPlanes`](super::setup::WeightPlanes)).
    pub screen: [f64; 3],
    /// Perspective-correct weights of the rasterized triangle's vertices.
    pub perspective: [f64; 3],
    /// Window depth z/w, linear on screen: `sum l_i d_i`.
    pub depth: f64,
    /// 1/w, linear on screen: `sum l_i / w_i`.
    pub inv_w: f64,
    /// Attributes with screen-space weights (`noperspective`).
    pub affine: Varyings,
    /// Attributes with perspective-correct weights (`smooth`).
    pub correct: Varyings,
    /// The source triangle's weights at the rasterized vertices (their `smooth` values)
    /// interpolated with the screen weights: zero exactly along the source triangle's edges,
    /// in every clipped piece, so the wireframe draws those edges (see
    /// [`edge_distance_px`](super::shade::edge_distance_px)).
    pub edge_weights: [f32; 3],
    /// Texture level of detail (see [`quad_lod`]); 0 unless trilinear filtering asked for it.
    pub lod: f32,
    /// The uv derivatives `[duv/dx, duv/dy]` across the pixel's 2x2 quad
    /// ([`quad_derivatives`]); zero unless anisotropic filtering asked for them.
    pub duv: [Vec2; 2],
}

impl Fragment {
    /// The fragment with every attribute `flat`: both attribute sets take the provoking
    /// vertex's values, exactly (no interpolation; the wireframe's edge weights stay).
    pub fn flat(self, provoking: &Varyings) -> Self {
        Self {
            affine: *provoking,
            correct: *provoking,
            ..self
        }
    }

    /// The attributes the given mode uses.
    pub fn varyings(&self, mode: Interpolation) -> &Varyings {
        match mode {
            Interpolation::Affine => &self.affine,
            Interpolation::Perspective => &self.correct,
        }
    }
}

/// Interpolates everything at the centre of pixel (x, y) (the renderer and the probe both
/// call this): the screen weights from [`WeightPlanes::at_pixel`], then everything else from
/// them ([`fragment_from_weights`]). Returns `None` if the perspective denominator is not
/// positive, which cannot happen for a sample inside a clipped triangle (all w > 0).
///
/// [`WeightPlanes::at_pixel`]: super::setup::WeightPlanes::at_pixel
pub fn fragment(setup: &TriangleSetup, x: u32, y: u32) -> Option<Fragment> {
    let edges = setup.edge_values(sample_point(x, y));
    fragment_from_weights(setup, edges, setup.weights.at_pixel(x, y))
}

/// Everything at a sample from its edge values and screen weights `l`:
/// `p_i = (l_i / w_i) / sum_k (l_k / w_k)`, `1/w = sum l_i / w_i`, `depth = sum l_i d_i`,
/// `noperspective` attributes `sum l_i f_i`, `smooth` ones `sum p_i f_i`.
pub fn fragment_from_weights(
    setup: &TriangleSetup,
    edges: [i64; 3],
    l: [f64; 3],
) -> Option<Fragment> {
    let inv_w = [setup.v[0].inv_w, setup.v[1].inv_w, setup.v[2].inv_w];
    let p = perspective_weights(&l, &inv_w)?;
    let vars = [
        setup.v[0].varyings,
        setup.v[1].varyings,
        setup.v[2].varyings,
    ];
    let noperspective = [
        setup.v[0].noperspective,
        setup.v[1].noperspective,
        setup.v[2].noperspective,
    ];
    Some(Fragment {
        edges,
        screen: l,
        perspective: p,
        depth: depth_at(setup, &l),
        inv_w: l[0] * inv_w[0] + l[1] * inv_w[1] + l[2] * inv_w[2],
        affine: Varyings::weighted(&l, &noperspective),
        edge_weights: edge_weights(setup, &l),
        correct: Varyings::weighted(&p, &vars),
        lod: 0.0,
        duv: [Vec2::ZERO; 2],
    })
}

/// Window depth z/w at screen weights `l`, linear on screen: `sum l_i d_i` (the depth of a
/// fragment, and of each sample under multisampling).
#[inline]
pub fn depth_at(setup: &TriangleSetup, l: &[f64; 3]) -> f64 {
    l[0] * setup.v[0].depth + l[1] * setup.v[1].depth + l[2] * setup.v[2].depth
}

/// [`Fragment::edge_weights`]: `sum_k l_k b_k` with `b_k` the source weights (`smooth`) of
/// rasterized vertex `k`, per source vertex, as `f32`.
pub fn edge_weights(setup: &TriangleSetup, l: &[f64; 3]) -> [f32; 3] {
    let b = setup.v.map(|v| v.varyings.bary());
    [0, 1, 2].map(|i| {
        (l[0] * f64::from(b[0][i]) + l[1] * f64::from(b[1][i]) + l[2] * f64::from(b[2][i])) as f32
    })
}

/// The uv the triangle's plane gives at pixel centre (x, y), extrapolated beyond its edges
/// (as a GPU's helper invocations do), with the mode's weights.
pub fn uv_at(setup: &TriangleSetup, x: u32, y: u32, mode: Interpolation) -> Option<Vec2> {
    Some(fragment(setup, x, y)?.varyings(mode).uv())
}

/// Which pixels of the 2x2 quad the uv derivatives come from (GLSL `dFdxCoarse` /
/// `dFdxFine`).
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, Hash, Default, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum Derivatives {
    /// One pair for the whole quad, from its first row and first column (what GPUs use for
    /// implicit texture derivatives, llvmpipe included; the renderer's).
    #[default]
    Coarse,
    /// Each pixel's own row (for d/dx) and own column (for d/dy) of the quad.
    Fine,
}

/// The uv derivatives at pixel (x, y) from differences across its 2x2 quad with origin
/// (x0, y0) = (x & !1, y & !1), every uv from the triangle's plane (extrapolated beyond its
/// edges, as a GPU's helper invocations are):
/// coarse `duv/dx = uv(x0 + 1, y0) - uv(x0, y0)`, `duv/dy = uv(x0, y0 + 1) - uv(x0, y0)`;
/// fine `duv/dx = uv(x0 + 1, y) - uv(x0, y)`, `duv/dy = uv(x, y0 + 1) - uv(x, y0)`. `y` grows
/// down the image (so `dv/dy` has the opposite sign of GL's window y; the lengths agree).
/// `None` where the plane has no valid uv.
pub fn quad_derivatives(
    setup: &TriangleSetup,
    (x, y): (u32, u32),
    mode: Interpolation,
    kind: Derivatives,
) -> Option<[Vec2; 2]> {
    let (x0, y0) = (x & !1, y & !1);
    let (row, column) = match kind {
        Derivatives::Coarse => (y0, x0),
        Derivatives::Fine => (y, x),
    };
    let uv = |x, y| uv_at(setup, x, y, mode);
    let dx = uv(x0 + 1, row)? - uv(x0, row)?;
    let dy = uv(column, y0 + 1)? - uv(column, y0)?;
    Some([dx, dy])
}

/// Texture level of detail at pixel (x, y) from its coarse derivatives
/// ([`quad_derivatives`]) and [`texture::lod`](super::texture::lod); 0 where the plane has no
/// valid uv.
pub fn quad_lod(
    setup: &TriangleSetup,
    x: u32,
    y: u32,
    mode: Interpolation,
    width: u32,
    height: u32,
) -> f32 {
    match quad_derivatives(setup, (x, y), mode, Derivatives::Coarse) {
        Some([dx, dy]) => super::texture::lod(dx, dy, width, height),
        None => 0.0,
    }
}
