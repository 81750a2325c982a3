//! A triangle as the lanes draw it: its edges, edge planes, bounds and the per-triangle
//! constants of the interpolation ([`LaneTriangle`]).

use glam::{DVec2, I64Vec2};

use super::*;
use crate::raster::mesh::MeshVertex;
use crate::raster::project::Viewport;
use crate::raster::setup::{TieRule, geometry_into};

/// Interpolated channels the lanes carry: a colour (or weights, or a normal) in 0..3, and the
/// normal in 3..6 for [`LaneColor::Lambert`].
pub(super) const CHANNELS: usize = 6;

/// The source weights of a triangle's own vertices (a triangle the clipper left whole).
const ONE_HOT: [[f32; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// A vertex attribute the channels may hold.
#[derive(Clone, Copy)]
enum Attribute {
    /// The vertex colour.
    Color,
    /// The source triangle's weights.
    Source,
    /// The normal.
    Normal,
}

/// Per-triangle constants of the interpolation, as [`interpolate::fragment`] uses them.
///
/// [`interpolate::fragment`]: super::interpolate::fragment
#[derive(Clone, Copy, Debug)]
pub(super) struct Constants {
    pub(super) weights: WeightPlanes,
    pub(super) inv_w: [f64; 3],
    pub(super) depth: [f64; 3],
    pub(super) u: [f64; 3],
    pub(super) v: [f64; 3],
    /// The planes of `1/w`, the depth and both uv sets ([`Planes`]), as the full render
    /// evaluates them: the edge-function lanes interpolate with these; the scanline lanes
    /// step the weights' sums above.
    pub(super) attrs: Planes,
    /// Whether the target wants uv of both attribute sets, `[u_affine, v_affine, u_smooth,
    /// v_smooth]` ([`Planes::uv_affine`], [`Planes::uv_over_w`]).
    pub(super) both_uv: bool,
    /// `channels[c][k]`: channel `c` of vertex `k`: the vertex colour, the source weights or
    /// the normal in 0..3, and the normal in 3..6 for Lambert shading.
    pub(super) channels: [[f64; 3]; CHANNELS],
    /// How many of `channels` the shading reads (none for texture and depth, 6 for Lambert,
    /// else 3).
    pub(super) used_channels: usize,
    pub(super) wire: Option<Wire>,
}

/// The wireframe test of [`shade`](super::shade::shade): a sample is on a line when, for a
/// source-triangle vertex `i` whose weight changes on screen (`len_i > 0`), its affine
/// weight (as `f32`) over `len_i` is below [`WIRE_WIDTH_PX`].
#[derive(Clone, Copy, Debug)]
pub(super) struct Wire {
    /// `bary[i][k]`: source weight `i` at rasterized vertex `k`.
    pub(super) bary: [[f64; 3]; 3],
    /// `|grad l_i|`, per pixel.
    pub(super) len: [f64; 3],
}

/// What the lanes interpolate of a triangle's three vertices: `1/w`, the window depth and
/// both attribute sets.
#[derive(Clone, Copy, Debug)]
pub struct LaneVertices {
    /// `1 / w_clip` per vertex.
    pub inv_w: [f64; 3],
    /// Window depth per vertex.
    pub depth: [f64; 3],
    /// The attributes for `smooth` (perspective-correct) interpolation.
    pub smooth: [Varyings; 3],
    /// The attributes for `noperspective` (affine) interpolation, when they differ from
    /// `smooth` (only where the clipper made a vertex).
    pub noperspective: Option<[Varyings; 3]>,
}

impl LaneVertices {
    /// A set-up triangle's vertices.
    pub fn of(setup: &TriangleSetup) -> Self {
        Self {
            inv_w: setup.v.map(|v| v.inv_w),
            depth: setup.v.map(|v| v.depth),
            smooth: setup.v.map(|v| v.varyings),
            noperspective: Some(setup.v.map(|v| v.noperspective)),
        }
    }
}

impl Constants {
    /// Constants of no triangle, to be [`set`](Constants::set).
    pub(super) const EMPTY: Self = Self {
        weights: WeightPlanes::EMPTY,
        inv_w: [0.0; 3],
        depth: [0.0; 3],
        u: [0.0; 3],
        v: [0.0; 3],
        attrs: Planes::ZERO,
        both_uv: false,
        channels: [[0.0; 3]; CHANNELS],
        used_channels: 0,
        wire: None,
    };

    /// Sets every field for a triangle, in place (the lanes set one up per triangle and
    /// band: a dense mesh sets up hundreds of thousands a frame). `mode` picks the vertices'
    /// attribute set: `smooth` (perspective-correct) or `noperspective` (affine). The
    /// wireframe uses the `smooth` source weights with screen weights, as
    /// [`Fragment::edge_weights`](super::interpolate::Fragment::edge_weights).
    #[inline(always)]
    pub(super) fn set(
        &mut self,
        weights: &WeightPlanes,
        verts: &LaneVertices,
        mode: Interpolation,
        wireframe: bool,
        color: LaneColor,
    ) {
        let vary = |k: usize| match (mode, &verts.noperspective) {
            (Interpolation::Affine, Some(n)) => &n[k],
            _ => &verts.smooth[k],
        };
        self.weights = *weights;
        self.inv_w = verts.inv_w;
        self.depth = verts.depth;
        self.set_uv([0, 1, 2].map(|k| vary(k).uv()));
        self.set_channels(color, |k, a| match a {
            Attribute::Color => vary(k).color().to_array(),
            Attribute::Source => vary(k).bary(),
            Attribute::Normal => vary(k).normal().to_array(),
        });
        self.set_wire(wireframe, verts.smooth.map(|v| v.bary()));
        let uv_of = |v: &Varyings| {
            let uv = v.uv();
            [f64::from(uv.x), f64::from(uv.y)]
        };
        let smooth = verts.smooth.map(|v| uv_of(&v));
        let affine = verts.noperspective.map_or(smooth, |n| n.map(|v| uv_of(&v)));
        self.attrs = Planes::new(weights, (verts.inv_w, verts.depth), smooth, affine);
        self.both_uv = false;
    }

    /// The planes of the mode's uv: `u/w`, `v/w` (perspective-correct, divided by `1/w` per
    /// sample) or `u`, `v` (affine).
    #[inline(always)]
    pub(super) fn uv_planes(&self, mode: Interpolation) -> &[ScreenPlane; 2] {
        match mode {
            Interpolation::Perspective => &self.attrs.uv_over_w,
            Interpolation::Affine => &self.attrs.uv_affine,
        }
    }

    /// The planes texture shading reads, in the order the lanes keep them: `1/w`, the depth,
    /// and the mode's u and v ([`Constants::uv_planes`]).
    #[inline(always)]
    pub(super) fn texture_planes(&self, mode: Interpolation) -> [ScreenPlane; 4] {
        let uv = self.uv_planes(mode);
        [self.attrs.inv_w, self.attrs.depth, uv[0], uv[1]]
    }

    /// Whether the shading or the wireframe reads the screen weights (texture and depth
    /// shading without the wireframe read only the planes). Read by the AVX2 lanes.
    #[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
    #[inline(always)]
    pub(super) fn reads_weights(&self) -> bool {
        self.used_channels > 0 || self.wire.is_some()
    }

    /// [`Constants::set`] for a triangle the clipper left whole, straight from its mesh
    /// vertices (the values `set` gives it, without building [`Varyings`]): both attribute
    /// sets are the vertices' own, and the source weights are one-hot. `uv`: also
    /// [`Constants::both_uv`]. The weight planes are already set (in place, by
    /// [`LaneTriangle::set_whole`]).
    #[inline(always)]
    pub(super) fn set_whole(
        &mut self,
        inv_w: [f64; 3],
        depth: [f64; 3],
        verts: [&MeshVertex; 3],
        wireframe: bool,
        color: LaneColor,
        uv: bool,
    ) {
        self.inv_w = inv_w;
        self.depth = depth;
        self.set_uv(verts.map(|v| v.uv));
        self.set_channels(color, |k, a| match a {
            Attribute::Color => verts[k].color.to_array(),
            Attribute::Source => ONE_HOT[k],
            Attribute::Normal => verts[k].normal.to_array(),
        });
        self.set_wire(wireframe, ONE_HOT);
        // Both attribute sets are the same: the vertices' own uv.
        let uv_k = |k: usize| [self.u[k], self.v[k]];
        let both = [uv_k(0), uv_k(1), uv_k(2)];
        self.attrs = Planes::new(&self.weights, (inv_w, depth), both, both);
        self.both_uv = uv;
    }

    /// The three vertices' uv.
    #[inline(always)]
    fn set_uv(&mut self, uv: [glam::Vec2; 3]) {
        for k in 0..3 {
            self.u[k] = f64::from(uv[k].x);
            self.v[k] = f64::from(uv[k].y);
        }
    }

    /// The channels `color` reads, from `attribute(vertex, which)`.
    #[inline(always)]
    fn set_channels(&mut self, color: LaneColor, attribute: impl Fn(usize, Attribute) -> [f32; 3]) {
        // Channel values per vertex, as f64 (a plain array, so the match below inlines).
        // Loops, not `array::map`: that was left as a call in some builds (once per triangle).
        let of = |a: Attribute| {
            let mut out = [[0.0; 3]; 3];
            for (k, o) in out.iter_mut().enumerate() {
                let x = attribute(k, a);
                for c in 0..3 {
                    o[c] = f64::from(x[c]);
                }
            }
            out
        };
        let put = |channels: &mut [[f64; 3]; CHANNELS], first: usize, at: [[f64; 3]; 3]| {
            for (k, at) in at.iter().enumerate() {
                for c in 0..3 {
                    channels[first + c][k] = at[c];
                }
            }
        };
        let first = match color {
            LaneColor::VertexColor | LaneColor::Lambert => of(Attribute::Color),
            LaneColor::Barycentric => of(Attribute::Source),
            LaneColor::Normal => of(Attribute::Normal),
            LaneColor::Texture | LaneColor::Depth(..) => [[0.0; 3]; 3],
        };
        put(&mut self.channels, 0, first);
        self.used_channels = match color {
            LaneColor::Lambert => {
                put(&mut self.channels, 3, of(Attribute::Normal));
                CHANNELS
            }
            LaneColor::Texture | LaneColor::Depth(..) => 0,
            _ => 3,
        };
    }

    /// The wireframe's constants from the vertices' `smooth` source weights `b` and the weight
    /// planes (set before), or none.
    #[inline(always)]
    fn set_wire(&mut self, wireframe: bool, b: [[f32; 3]; 3]) {
        let weights = &self.weights;
        self.wire = wireframe.then(|| Wire {
            bary: [0, 1, 2].map(|i| [0, 1, 2].map(|k| f64::from(b[k][i]))),
            len: source_weight_gradients(weights, b).map(|g| g.length()),
        });
    }
}

/// A triangle as the lanes draw it (edge functions or scanline): its edges, edge planes, bounds and interpolation
/// constants, from a [`TriangleSetup`] ([`LaneTriangle::of`]) or from its parts
/// ([`LaneTriangle::new`], the fast path's shared vertices): the same values either way.
#[derive(Clone, Copy, Debug)]
pub struct LaneTriangle {
    pub(super) edges: [Edge; 3],
    pub(super) planes: EdgePlanes,
    pub(super) bounds: PixelBounds,
    pub(super) consts: Constants,
}

impl LaneTriangle {
    /// A triangle covering nothing, to be [`set`](LaneTriangle::set).
    pub const EMPTY: Self = Self {
        edges: [Edge::EMPTY; 3],
        planes: EdgePlanes {
            a: [0; 3],
            b: [0; 3],
            c: [-1; 3],
            t: [0; 3],
        },
        bounds: PixelBounds::EMPTY,
        consts: Constants::EMPTY,
    };

    /// From the triangle's edges, bounds and weight planes (see
    /// [`triangle_geometry`](crate::raster::setup::triangle_geometry)) and its vertices, for drawing
    /// with `shading` (`None`: coverage only, for the caller's per-pixel shading); `uv` when
    /// the target needs both uvs (it keeps the uv buffers or the texel difference).
    pub fn new(
        edges: &[Edge; 3],
        bounds: PixelBounds,
        weights: &WeightPlanes,
        verts: &LaneVertices,
        shading: Option<LaneShading>,
        uv: bool,
    ) -> Self {
        let mut tri = Self::EMPTY;
        tri.set(edges, bounds, weights, verts, shading, uv);
        tri
    }

    /// [`LaneTriangle::new`] in place, so that a loop over many triangles reuses one.
    #[inline(always)]
    pub fn set(
        &mut self,
        edges: &[Edge; 3],
        bounds: PixelBounds,
        weights: &WeightPlanes,
        verts: &LaneVertices,
        shading: Option<LaneShading>,
        uv: bool,
    ) {
        let color = shading.map_or(LaneColor::Texture, |s| s.color);
        let mode = shading.map_or(Interpolation::Perspective, |s| s.mode);
        let wire = shading.is_some_and(|s| s.wireframe);
        self.consts.set(weights, verts, mode, wire, color);
        self.consts.both_uv = uv;
        self.planes = EdgePlanes::from_edges(edges);
        self.edges = *edges;
        self.bounds = bounds;
    }

    /// [`LaneTriangle::set`] for a triangle the clipper left whole, from the snapped (`fixed`)
    /// and unsnapped (`window`) positions, `1/w` and window depth of its mesh vertices (the
    /// fast path's shared vertices): the same values as `set` with the triangle's
    /// [`triangle_geometry`](crate::raster::setup::triangle_geometry), their [`Varyings`],
    /// one-hot source weights and no `noperspective` set. The edges, weight planes and bounds
    /// are set up in place ([`geometry_into`]). `false` (and the triangle unusable) when it
    /// has no set-up.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub fn set_whole(
        &mut self,
        (fixed, window): ([I64Vec2; 3], [DVec2; 3]),
        viewport: Viewport,
        rule: TieRule,
        inv_w: [f64; 3],
        depth: [f64; 3],
        verts: [&MeshVertex; 3],
        shading: LaneShading,
        uv: bool,
    ) -> bool {
        let c = &mut self.consts;
        if geometry_into(
            fixed,
            window,
            viewport,
            rule,
            &mut self.edges,
            &mut c.weights,
            &mut self.bounds,
        )
        .is_none()
        {
            return false;
        }
        c.set_whole(inv_w, depth, verts, shading.wireframe, shading.color, uv);
        self.planes = EdgePlanes::from_edges(&self.edges);
        true
    }

    /// From a set-up triangle.
    pub fn of(setup: &TriangleSetup, shading: Option<LaneShading>, uv: bool) -> Self {
        let verts = LaneVertices::of(setup);
        Self::new(
            &setup.edges,
            setup.bounds,
            &setup.weights,
            &verts,
            shading,
            uv,
        )
    }

    /// Pixels whose centres can be covered.
    pub fn bounds(&self) -> PixelBounds {
        self.bounds
    }

    /// Whether the lanes can draw it: edge values exact in `f64` over its bounds (otherwise,
    /// near the guard band, the per-pixel path does).
    pub fn exact(&self) -> bool {
        // Cheap and sufficient (nearly every triangle): every vertex within 2^24 subpixels
        // (65,536 pixels) of the origin. Then |dir| < 2^25 and, for any sample the lanes visit
        // (columns and rows below 2^14 + LANES, so below 2^22 subpixels), |P - S| < 2^25, and
        // |E| = |dir_x (P_y - S_y) - dir_y (P_x - S_x)| < 2^51, below the exactness limit.
        // Otherwise the edge values at the corners of the bounds are checked.
        const NEAR: i64 = 1 << 24;
        let near = |e: &Edge| e.start.x.abs() < NEAR && e.start.y.abs() < NEAR;
        self.edges.iter().all(near) || self.planes.exact_over(&self.bounds)
    }
}
