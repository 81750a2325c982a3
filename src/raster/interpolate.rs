//! Interpolation at a sample: screen-space weights, perspective-correct weights, attributes.

use glam::{DVec2, Vec2};

use super::setup::{ScreenPlane, TriangleSetup, WeightPlanes, pixel_centre, sample_point};
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

/// Perspective-correct weights from screen weights `l`, the vertices' 1/w and 1/w at the
/// sample (`sum l_i / w_i`, which the fragment takes from its plane, [`ScreenPlane`]):
/// `p_i = (l_i / w_i) * (1 / (1/w))`. `None` unless that 1/w is positive and finite.
///
/// ```
/// use barylab::raster::interpolate::perspective_weights;
/// // Halfway on screen between a vertex at w = 1 and one at w = 3: 1/w_P = (1 + 1/3) / 2,
/// // so w_P = 1.5 and the near vertex gets weight (0.5 / 1) * 1.5 = 0.75.
/// let inv_w = [1.0, 1.0 / 3.0, 1.0];
/// let p = perspective_weights(&[0.5, 0.5, 0.0], &inv_w, (1.0 + 1.0 / 3.0) / 2.0).unwrap();
/// assert!((p[0] - 0.75).abs() < 1e-15 && (p[1] - 0.25).abs() < 1e-15 && p[2] == 0.0);
/// ```
pub fn perspective_weights(l: &[f64; 3], inv_w: &[f64; 3], one_over_w: f64) -> Option<[f64; 3]> {
    perspective_divisor(one_over_w).map(|inv| weights_times(l, inv_w, inv))
}

/// [`perspective_weights`] with `1 / (1/w)` already divided: `(l_i * inv_w_i) * inv` (the
/// scalar lanes call it too).
#[inline(always)]
pub(crate) fn weights_times(l: &[f64; 3], inv_w: &[f64; 3], inv: f64) -> [f64; 3] {
    [
        l[0] * inv_w[0] * inv,
        l[1] * inv_w[1] * inv,
        l[2] * inv_w[2] * inv,
    ]
}

/// `1 / (1/w)`, the one division of a perspective-correct sample, when 1/w is positive and
/// finite (it is at every sample inside a clipped triangle: all its w > 0).
#[inline(always)]
pub fn perspective_divisor(one_over_w: f64) -> Option<f64> {
    (one_over_w > 0.0 && one_over_w < f64::INFINITY).then(|| 1.0 / one_over_w)
}

/// The planes a triangle interpolates by ([`ScreenPlane`]): `1/w`, the window depth, and
/// uv of both attribute sets: `u/w`, `v/w` of the `smooth` uv (divided by w: perspective
/// correct) and `u`, `v` of the `noperspective` uv.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Planes {
    /// `1/w`: vertex values `1 / w_i`.
    pub inv_w: ScreenPlane,
    /// Window depth z/w: vertex values `d_i`.
    pub depth: ScreenPlane,
    /// `u/w` and `v/w`: vertex values `u_i * (1 / w_i)` of the `smooth` uv.
    pub uv_over_w: [ScreenPlane; 2],
    /// `u` and `v` of the `noperspective` uv.
    pub uv_affine: [ScreenPlane; 2],
}

impl Planes {
    /// The planes of no triangle (a placeholder before a triangle is set).
    pub const ZERO: Self = Self {
        inv_w: ScreenPlane::ZERO,
        depth: ScreenPlane::ZERO,
        uv_over_w: [ScreenPlane::ZERO; 2],
        uv_affine: [ScreenPlane::ZERO; 2],
    };

    /// The planes of a set-up triangle.
    pub fn of(setup: &TriangleSetup) -> Self {
        let w = &setup.weights;
        let inv_w = setup.v.map(|v| v.inv_w);
        let smooth = setup.v.map(|v| v.varyings.uv());
        let affine = setup.v.map(|v| v.noperspective.uv());
        Self::new(
            w,
            (inv_w, setup.v.map(|v| v.depth)),
            smooth.map(|uv| [f64::from(uv.x), f64::from(uv.y)]),
            affine.map(|uv| [f64::from(uv.x), f64::from(uv.y)]),
        )
    }

    /// The planes from the weights, each vertex's 1/w and depth, and both uv sets per vertex.
    #[inline(always)]
    pub fn new(
        w: &WeightPlanes,
        (inv_w, depth): ([f64; 3], [f64; 3]),
        smooth: [[f64; 2]; 3],
        affine: [[f64; 2]; 3],
    ) -> Self {
        let over_w = |c: usize| {
            w.plane([
                smooth[0][c] * inv_w[0],
                smooth[1][c] * inv_w[1],
                smooth[2][c] * inv_w[2],
            ])
        };
        let plain = |c: usize| w.plane([affine[0][c], affine[1][c], affine[2][c]]);
        Self {
            inv_w: w.plane(inv_w),
            depth: w.plane(depth),
            uv_over_w: [over_w(0), over_w(1)],
            uv_affine: [plain(0), plain(1)],
        }
    }
}

/// Everything interpolated at one covered sample of one (clipped) triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fragment {
    /// The three edge values at the sample (snapped, exact: they decided coverage).
    pub edges: [i64; 3],
    /// Screen-space weights of the rasterized triangle's vertices, from the unsnapped
    /// positions ([`WeightPlanes`]).
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
/// call this): [`fragment_at_window`] at `(x + 0.5, y + 0.5)`. Returns `None` if 1/w is not
/// positive there, which cannot happen for a sample inside a clipped triangle (all w > 0).
pub fn fragment(setup: &TriangleSetup, x: u32, y: u32) -> Option<Fragment> {
    let edges = setup.edge_values(sample_point(x, y));
    fragment_at_window(setup, edges, pixel_centre(x, y))
}

/// Everything at a sample from its edge values and its window position `p` (pixels), with
/// the weights' row terms at `p_y` and column terms at `p_x` ([`WeightPlanes`]):
/// the screen weights `l_i`; `1/w`, the depth and uv from their planes ([`Planes`]): `1/w`,
/// `depth`, `noperspective` uv `u`, `v`, and `smooth` uv `(u/w) * (1 / (1/w))`; the
/// perspective weights `p_i = (l_i / w_i) * (1 / (1/w))` ([`perspective_weights`]); the
/// other attributes `sum l_i f_i` (`noperspective`) and `sum p_i f_i` (`smooth`).
pub fn fragment_at_window(setup: &TriangleSetup, edges: [i64; 3], p: DVec2) -> Option<Fragment> {
    fragment_with_planes(setup, &Planes::of(setup), edges, p)
}

/// [`fragment_at_window`] with the triangle's planes made once by the caller
/// (`Planes::of(setup)`), for a loop over many samples of one triangle.
pub fn fragment_with_planes(
    setup: &TriangleSetup,
    planes: &Planes,
    edges: [i64; 3],
    p: DVec2,
) -> Option<Fragment> {
    let w = &setup.weights;
    let (rows, columns) = (w.row_terms(p.y), w.column_terms(p.x));
    let l = [0, 1, 2].map(|i| w.weight_of_terms(rows[i], columns[i]));
    let at = |plane: &ScreenPlane| plane.part(&rows) - plane.part(&columns);
    let one_over_w = at(&planes.inv_w);
    let inv = perspective_divisor(one_over_w)?;
    let inv_w = [setup.v[0].inv_w, setup.v[1].inv_w, setup.v[2].inv_w];
    let p = weights_times(&l, &inv_w, inv);
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
    let [u_w, v_w] = planes.uv_over_w.map(|plane| (at(&plane) * inv) as f32);
    let [u, v] = planes.uv_affine.map(|plane| at(&plane) as f32);
    Some(Fragment {
        edges,
        screen: l,
        perspective: p,
        depth: at(&planes.depth),
        inv_w: one_over_w,
        affine: Varyings::weighted(&l, &noperspective).with_uv(Vec2::new(u, v)),
        edge_weights: edge_weights(setup, &l),
        correct: Varyings::weighted(&p, &vars).with_uv(Vec2::new(u_w, v_w)),
        lod: 0.0,
        duv: [Vec2::ZERO; 2],
    })
}

/// Window depth z/w at window position `p`, linear on screen, from its plane
/// ([`Planes::depth`]): the depth of a fragment, and of each sample under multisampling.
#[inline]
pub fn depth_at(setup: &TriangleSetup, p: DVec2) -> f64 {
    let depth = setup.weights.plane(setup.v.map(|v| v.depth));
    setup.weights.value(&depth, p)
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
