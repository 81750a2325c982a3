//! The trace of one pixel: the data [`Prober::pixel`](super::Prober::pixel) returns.
//!
//! Every type here serializes to the JSON documented in `docs/probe.md` (field names are the
//! Rust names); the formatter ([`format`](super::format)) prints only fields of these types.

use serde::Serialize;

use super::weights::{AreaWeights, ExplicitFormula, HomogeneousSystem, RayHit, WpCorrection};
use crate::raster::clip::PlaneName;
use crate::raster::interpolate::Interpolation;
use crate::raster::render::TriangleStatus;
use crate::raster::setup::{EdgeKind, Facing, TieRule};
use crate::raster::shade::Shading;
use crate::raster::texture::{Filter, Wrap};

/// Everything behind one pixel. Serializes to the JSON documented in `docs/probe.md`.
#[derive(Clone, Debug, Serialize)]
pub struct PixelTrace {
    /// `[x, y]`, row 0 at the top.
    pub pixel: [u32; 2],
    /// `[width, height]` of the image.
    pub image_size: [u32; 2],
    /// The render settings the trace was made with.
    pub settings: TraceSettings,
    /// Which form the scene file had: world, clip or model.
    pub scene_form: SceneForm,
    /// The matrices of a world or model scene; `None` for a clip-space scene.
    pub matrices: Option<Matrices>,
    /// The pixel centre in window, fixed-point and NDC coordinates.
    pub sample: Sample,
    /// The source triangles in drawing order, with coverage and depth test at the sample:
    /// all of them in a mesh of at most [`LIST_ALL_TRIANGLES`](super::LIST_ALL_TRIANGLES) triangles, else those whose
    /// pixel bounds contain the pixel (a model can have thousands).
    pub triangles: Vec<TriangleCoverage>,
    /// How many source triangles the mesh has.
    pub triangle_count: usize,
    /// The source triangle whose fragment the framebuffer kept, if any.
    pub written_by: Option<u32>,
    /// The full derivation for the triangle that wrote the pixel or, for an uncovered pixel,
    /// the nearest drawn triangle (largest smallest weight). `None` if nothing was drawn.
    pub detail: Option<TriangleTrace>,
    /// The final RGBA colour in the framebuffer: equal to the rendered image's pixel (with
    /// samples, their resolve).
    pub color: [u8; 4],
    /// The pixel's samples in index order, when the render has more than one per pixel or
    /// `flat` attributes (empty, and absent from the JSON, otherwise).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub samples: Vec<super::SampleTrace>,
    /// What decided the samples: the rate, the location, where each triangle was shaded,
    /// the resolve (absent without samples).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sample_shading: Option<super::SampleShading>,
}

/// The render settings the trace was made with.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct TraceSettings {
    /// Interpolation mode: affine (`noperspective`) or perspective-correct (`smooth`).
    pub mode: Interpolation,
    /// What the fragment's colour is made from.
    pub shading: Shading,
    /// Texture filter: nearest, bilinear or trilinear.
    pub filter: Filter,
    /// Texture wrap mode.
    pub wrap: Wrap,
    /// The largest anisotropy (above 1 with trilinear: anisotropic filtering).
    pub max_anisotropy: u32,
    /// Whether the source triangles' edges are drawn as lines.
    pub wireframe: bool,
    /// Background RGBA, the colour of pixels no triangle covers.
    pub background: [u8; 4],
}

/// Which form the scene file had.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SceneForm {
    /// A camera and a quad.
    World,
    /// Vertices given in clip space.
    Clip,
    /// A camera and an OBJ model.
    Model,
}

/// The matrices of a world or model scene, each row by row.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Matrices {
    /// Object -> world: the quad's tilt about its centre (world scenes); the identity for a model.
    pub world_from_object: [[f64; 4]; 4],
    /// The camera's look-at matrix: world -> view.
    pub view_from_world: [[f64; 4]; 4],
    /// The camera's projection: view -> clip.
    pub clip_from_view: [[f64; 4]; 4],
    /// Whether the camera projection is a perspective one (else orthographic).
    pub perspective: bool,
}

/// The sample point of the pixel.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Sample {
    /// `(x + 0.5, y + 0.5)` in window coordinates (pixels, y down).
    pub window: [f64; 2],
    /// The same in the rasterizer's 1/256-pixel units.
    pub fixed: [i64; 2],
    /// In normalized device coordinates: `(2 x_w / W - 1, 1 - 2 y_w / H)`.
    pub ndc: [f64; 2],
    /// Sub-pixel steps per pixel of the fixed-point positions:
    /// [`SUBPIXEL`](crate::raster::project::SUBPIXEL), 256.
    pub subpixel: i64,
    /// Edge functions count in units of `1 / edge_function_unit` px²: `subpixel²`, 65536.
    pub edge_function_unit: i64,
}

/// One source triangle at the sample.
#[derive(Clone, Debug, Serialize)]
pub struct TriangleCoverage {
    /// Index of the source triangle.
    pub source: u32,
    /// Names of its three vertices.
    pub vertices: [String; 3],
    /// Whether it was drawn, or why it drew nothing.
    pub status: TriangleStatus,
    /// Whether the clipper cut it.
    pub clipped: bool,
    /// The edge test of the set-up triangle that covers the sample or, if none does, the one
    /// nearest to it. `None` if nothing of the triangle was set up.
    pub test: Option<CoverageTest>,
    /// The depth test, if the triangle covers the sample.
    pub depth_test: Option<DepthTest>,
}

/// The edge functions of one set-up triangle at the sample.
#[derive(Clone, Debug, Serialize)]
pub struct CoverageTest {
    /// Which triangle of the clipped polygon's fan (0 when the triangle was not clipped).
    pub sub_triangle: usize,
    /// Names of the set-up triangle's vertices.
    pub vertices: [String; 3],
    /// Edge `i` is opposite vertex `i`.
    pub edges: [EdgeTest; 3],
    /// Inside, on an edge, or outside, from the signs of the edge values.
    pub position: Position,
    /// Whether the fill rule covers the sample.
    pub covered: bool,
    /// The tie rule that decides a sample exactly on an edge.
    pub tie_rule: TieRule,
}

/// Where the sample lies relative to a triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Position {
    /// Every edge value is positive.
    Inside,
    /// No edge value is negative, at least one is zero.
    OnEdge,
    /// Some edge value is negative.
    Outside,
}

/// One edge function at the sample.
#[derive(Clone, Debug, Serialize)]
pub struct EdgeTest {
    /// The edge's two vertex names, e.g. "BC".
    pub name: String,
    /// Left, right, top or bottom, for the tie rule.
    pub kind: EdgeKind,
    /// `E(P)`, twice the signed area of (edge, P) in 1/65536 pixel^2; positive inside.
    pub value: i64,
    /// Whether the sample passes this edge under the fill rule.
    pub passes: bool,
}

/// The depth test of a covering fragment.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct DepthTest {
    /// The fragment's window depth as stored (f32).
    pub depth: f32,
    /// The depth buffer before the test.
    pub buffer_before: f32,
    /// `depth < buffer_before`.
    pub passed: bool,
}

/// The derivation for one triangle at the sample.
#[derive(Clone, Debug, Serialize)]
pub struct TriangleTrace {
    /// Index of the source triangle.
    pub source: u32,
    /// Whether this triangle's fragment is what the pixel shows (false: the nearest triangle
    /// of an uncovered pixel, with weights extended outside it).
    pub writes_pixel: bool,
    /// The source triangle's vertices in every space.
    pub vertices: [VertexTrace; 3],
    /// Whether some source vertex has `w <= 0` (at or behind the camera's plane).
    pub vertex_behind_camera: bool,
    /// The clipping, if the clipper cut the triangle.
    pub clipping: Option<ClipTrace>,
    /// The triangle the rasterizer set up: the source triangle itself, or one triangle of the
    /// clipped polygon's fan.
    pub raster: RasterTriangle,
    /// The coverage test of the rasterized triangle.
    pub coverage: CoverageTest,
    /// Screen-space weights of the rasterized triangle's vertices, several ways.
    pub screen: ScreenWeights,
    /// The 1/w correction; `None` if the interpolated 1/w is not positive.
    pub perspective: Option<PerspectiveTrace>,
    /// The 4x4 system on the source triangle; `None` if singular.
    pub system: Option<SystemTrace>,
    /// The source triangle's weights as the rasterizer interpolated them (the varyings).
    pub source_weights: Option<SourceWeights>,
    /// The 3D point the pixel sees on the triangle's plane.
    pub seen_point: Option<SeenPoint>,
    /// The texture coordinate, texels and vertex colour, both ways; `None` where the fragment
    /// cannot be interpolated.
    pub attribute: Option<AttributeTrace>,
    /// Window depth and view depth, interpolated both ways; `None` where the fragment cannot be
    /// interpolated.
    pub depth: Option<DepthTrace>,
    /// How the shading mode turned the fragment into a colour; `None` where the fragment cannot be
    /// interpolated.
    pub shade: Option<ShadeTrace>,
}

/// One source vertex in every space.
#[derive(Clone, Debug, Serialize)]
pub struct VertexTrace {
    /// The vertex's name, from its mesh index: A, B, C, ... (`V26`, `V27`, ... after Z).
    pub name: String,
    /// Index into the mesh's vertices.
    pub index: u32,
    /// Object space (world and model scenes).
    pub object: Option<[f64; 3]>,
    /// World space (world and model scenes).
    pub world: Option<[f64; 3]>,
    /// View (camera) space (world and model scenes).
    pub view: Option<[f64; 3]>,
    /// Clip space `(x, y, z, w)`.
    pub clip: [f64; 4],
    /// `(x/w, y/w, z/w)`; `None` if `w <= 0`.
    pub ndc: Option<[f64; 3]>,
    /// Window `(x, y, depth)` before snapping; `None` if `w <= 0`.
    pub window: Option<[f64; 3]>,
    /// Window `(x, y)` snapped to 1/256 pixel; `None` if `w <= 0`.
    pub window_snapped: Option<[f64; 2]>,
    /// The snapped position in 1/256-pixel units, `window_snapped · 256`; `None` if `w <= 0`.
    pub window_fixed: Option<[i64; 2]>,
    /// `1/w`, w the clip-space w (the view depth for a perspective camera); `None` if `w <= 0`.
    pub inv_w: Option<f64>,
    /// Texture coordinate.
    pub uv: [f32; 2],
    /// Vertex colour, RGB in [0, 1].
    pub color: [f32; 3],
}

/// What the clipper did to the source triangle.
#[derive(Clone, Debug, Serialize)]
pub struct ClipTrace {
    /// The planes that cut it.
    pub planes: Vec<PlaneName>,
    /// The clipped polygon, in order.
    pub polygon: Vec<PolygonVertex>,
    /// The polygon indices of the fan triangle that was rasterized for this pixel.
    pub fan_triangle: [usize; 3],
}

/// A vertex of the clipped polygon.
#[derive(Clone, Debug, Serialize)]
pub struct PolygonVertex {
    /// The vertex's name: a source vertex's letter, or K1, K2, ... for a point the clipper made.
    pub name: String,
    /// Which source vertex it is (0, 1, 2), or `None` for a point the clipper made.
    pub source_vertex: Option<usize>,
    /// Clip-space position `(x, y, z, w)`.
    pub clip: [f64; 4],
    /// Its weights with respect to the source triangle, carried as a varying.
    pub source_weights: [f32; 3],
}

/// A vertex of the rasterized triangle, as the rasterizer holds it.
#[derive(Clone, Debug, Serialize)]
pub struct RasterVertex {
    /// The vertex's name, as in the clipped polygon (a source letter, or K1, K2, ...).
    pub name: String,
    /// Which source vertex it is (0, 1, 2), or `None` for a point the clipper made.
    pub source_vertex: Option<usize>,
    /// Clip-space position `(x, y, z, w)`.
    pub clip: [f64; 4],
    /// NDC `(x/w, y/w, z/w)`.
    pub ndc: [f64; 3],
    /// Window position in pixels before snapping: the interpolation weights come from it.
    pub window: [f64; 2],
    /// Window position snapped to 1/256 pixel, in pixels (`fixed / 256`): coverage.
    pub window_snapped: [f64; 2],
    /// Snapped window position in 1/256 pixel.
    pub fixed: [i64; 2],
    /// Window depth `(z_ndc + 1) / 2`.
    pub depth: f64,
    /// `1/w`, w the clip-space w (the view depth for a perspective camera).
    pub inv_w: f64,
    /// Weights of the source triangle's vertices (one-hot at a source vertex), the `smooth`
    /// attribute: at a vertex the clipper made, interpolated in clip space.
    pub source_weights: [f32; 3],
    /// The same as a `noperspective` attribute: at a vertex the clipper made, the source
    /// triangle's screen-linear weights there (OpenGL 4.6, section 13.7.1).
    pub source_weights_affine: [f32; 3],
    /// Texture coordinate (the `smooth` varying).
    pub uv: [f32; 2],
    /// Vertex colour, RGB in [0, 1] (the `smooth` varying).
    pub color: [f32; 3],
    /// View-space position (world and model scenes), from the clip position.
    pub view: Option<[f64; 3]>,
}

/// The set-up triangle.
#[derive(Clone, Debug, Serialize)]
pub struct RasterTriangle {
    /// The three vertices, in the order the edge functions use.
    pub vertices: [RasterVertex; 3],
    /// Twice the area, in 1/65536 pixel^2.
    pub area2: i64,
    /// Front or back, from the sign of the area on screen.
    pub facing: Facing,
}

/// Screen-space weights `[r, s, t]` of the rasterized triangle's vertices.
#[derive(Clone, Debug, Serialize)]
pub struct ScreenWeights {
    /// The rasterizer's ([`WeightPlanes`](crate::raster::setup::WeightPlanes)): the signed-area
    /// ratios in f64 from the unsnapped window positions (not the snapped edge values).
    pub rasterizer: [f64; 3],
    /// The explicit formula on the unsnapped window positions.
    pub explicit: Option<ExplicitFormula>,
    /// Signed areas from 2D cross products.
    pub cross_product: Option<AreaWeights>,
    /// The OpenGL area form (eq. 14.8).
    pub gl_area: Option<AreaWeights>,
    /// From the 4x4 system's solution, `r = b_A W_A / w` (only when the rasterized triangle is the
    /// source triangle).
    pub from_system: Option<[f64; 3]>,
    /// Largest difference of any method from `rasterizer`.
    pub max_difference: f64,
}

/// The 1/w correction with the renderer's own values beside it.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct PerspectiveTrace {
    /// `[W_A, W_B, W_C]`: clip w of the rasterized vertices.
    pub w: [f64; 3],
    /// The correction in the r, s, t / W_P notation: `1/W_P = r/W_A + s/W_B + t/W_C`, `a = r W_P /
    /// W_A`, ...
    pub correction: WpCorrection,
    /// GAMES101's `w_reciprocal = 1 / (alpha/w_A + beta/w_B + gamma/w_C)` (it is W_P).
    pub games101_w_reciprocal: f64,
    /// The renderer's perspective-correct weights ([`interpolate::fragment`](crate::raster::interpolate::fragment)).
    pub renderer_weights: [f64; 3],
    /// The renderer's interpolated 1/w.
    pub renderer_inv_w: f64,
}

/// The 4x4 system on the source triangle.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct SystemTrace {
    /// The system on the source triangle's clip coordinates `q`.
    pub system: HomogeneousSystem,
    /// The sample in NDC, `s`.
    pub s: [f64; 2],
    /// The largest difference between the solution and the rasterizer's weights: with
    /// `(a, b, c, W_P)` of the 1/w method for an unclipped triangle, with the interpolated
    /// source weights (f32) for a clipped one; `None` where those do not exist.
    pub max_difference: Option<f64>,
}

/// The source triangle's weights at the sample as interpolated by the rasterizer (its
/// barycentric varyings, f32), as written to the weight buffers.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct SourceWeights {
    /// Interpolated with the screen weights r, s, t (`noperspective`).
    pub screen: [f32; 3],
    /// Interpolated with the perspective-correct weights a, b, c (`smooth`).
    pub perspective: [f32; 3],
}

/// The point on the source triangle's plane that the pixel centre sees.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct SeenPoint {
    /// World and model scenes: the ray through the pixel centre in view space.
    pub ray: Option<ViewRay>,
    /// World and model scenes: the ray's hit on the plane, in view space, with its weights.
    pub hit: Option<RayHit>,
    /// The point in view space (world and model scenes).
    pub view: Option<[f64; 3]>,
    /// The point in world space (world and model scenes).
    pub world: Option<[f64; 3]>,
    /// The point in clip space.
    pub clip: [f64; 4],
    /// The point in NDC, `clip.xyz / clip.w`.
    pub ndc: [f64; 3],
    /// Its window depth `(z/w + 1) / 2`.
    pub depth: f64,
    /// Its barycentric weights with respect to the source triangle (from the ray hit in a
    /// world or model scene, from the 4x4 system's solution in a clip-space scene).
    pub weights: [f64; 3],
    /// The largest difference between `weights` and the rasterizer's: the perspective-correct
    /// weights for an unclipped triangle, the interpolated source weights (f32) for a clipped
    /// one; `None` where those do not exist.
    pub max_difference: Option<f64>,
}

/// A ray in view space.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct ViewRay {
    /// Where the ray starts, in view space: the eye (the origin) for a perspective camera, the
    /// point on the near plane for an orthographic one.
    pub origin: [f64; 3],
    /// The ray's direction in view space (not normalized): to the pixel centre's point on the near
    /// plane (perspective), from near to far plane along -z (orthographic).
    pub direction: [f64; 3],
}

/// The texture coordinate and vertex colour both ways.
#[derive(Clone, Debug, Serialize)]
pub struct AttributeTrace {
    /// uv of the rasterized vertices (for `smooth`, perspective-correct interpolation).
    pub uv_vertices: [[f32; 2]; 3],
    /// uv of the rasterized vertices for `noperspective` (affine) interpolation: the same as
    /// `uv_vertices` except at a vertex the clipper made, where OpenGL interpolates
    /// `noperspective` attributes with the screen-space fraction along the cut edge.
    pub uv_vertices_affine: [[f32; 2]; 3],
    /// `r uv_A + s uv_B + t uv_C` (the renderer's, f32).
    pub uv_affine: [f32; 2],
    /// `a uv_A + b uv_B + c uv_C` (the renderer's, f32).
    pub uv_perspective: [f32; 2],
    /// GAMES101's form `(r uv_A/W_A + s uv_B/W_B + t uv_C/W_C) W_P`, in f64.
    pub uv_games101: [f64; 2],
    /// `[width, height]` of the texture in texels.
    pub texture_size: [u32; 2],
    /// The last texel index per axis, `[width - 1, height - 1]` (what clamp-to-edge clamps to).
    pub last_texel: [u32; 2],
    /// `uv * size` for each way.
    pub texel_affine: [f64; 2],
    /// `uv_perspective * size`, in texels.
    pub texel_perspective: [f64; 2],
    /// `texel_affine - texel_perspective`, and its length.
    pub texel_difference: [f64; 2],
    /// Length of `texel_difference`, in texels.
    pub texel_distance: f64,
    /// Trilinear filtering only: the levels of detail each way.
    pub trilinear: Option<Trilinear>,
    /// The texels the filter reads, each way.
    pub taps_affine: Vec<TapTrace>,
    /// The texels the filter reads with the perspective-correct uv.
    pub taps_perspective: Vec<TapTrace>,
    /// The filtered texture colour each way, as 8-bit RGBA.
    pub color_affine: [u8; 4],
    /// The filtered texture colour with the perspective-correct uv, 8-bit RGBA.
    pub color_perspective: [u8; 4],
    /// Trilinear filtering only: the level of detail derived step by step with the scene's
    /// mode's uv (and the anisotropic probes).
    pub lod: Option<super::LodTrace>,
    /// Vertex colours of the rasterized vertices, and the colour interpolated each way.
    pub vertex_colors: [[f32; 3]; 3],
    /// Vertex colour interpolated with the screen weights r, s, t (the renderer's, f32).
    pub vertex_color_affine: [f32; 3],
    /// Vertex colour interpolated with the perspective-correct weights a, b, c (the renderer's,
    /// f32).
    pub vertex_color_perspective: [f32; 3],
}

/// Mipmapping for trilinear filtering.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Trilinear {
    /// Number of mipmap levels (level 0 is the full texture).
    pub levels: u32,
    /// The level of detail from the uv differences across the pixel's 2x2 quad
    /// ([`interpolate::quad_lod`](crate::raster::interpolate::quad_lod)), with affine and with perspective-correct uv.
    pub lod_affine: f32,
    /// The level of detail with the perspective-correct uv.
    pub lod_perspective: f32,
}

/// One texel read by the filter.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct TapTrace {
    /// Mipmap level (0 = the full texture).
    pub level: u32,
    /// Column after wrapping.
    pub i: u32,
    /// Row after wrapping (0 = bottom, v = 0).
    pub j: u32,
    /// Nearest filtering: the texel `(floor(u W), floor(v H))` before the wrap mode applied.
    pub unwrapped: Option<[i64; 2]>,
    /// The filter's weight for this texel (the weights of one way sum to 1).
    pub weight: f32,
    /// The texel's RGBA.
    pub texel: [u8; 4],
}

/// What the pixel's distance measure is in [`DepthTrace`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DistanceKind {
    /// `-z_view`, the distance in front of the camera (world and model scenes).
    ViewDepth,
    /// Clip w (clip-space scenes: for a perspective projection, the view depth).
    ClipW,
}

/// Depth: window z/w versus view depth both ways.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct DepthTrace {
    /// `[d_A, d_B, d_C]`, window depths of the rasterized vertices.
    pub window_depths: [f64; 3],
    /// `r d_A + s d_B + t d_C`, the value the depth test compares (the renderer's).
    pub depth: f64,
    /// What `distances` measure: view depth (world and model scenes) or clip w (clip-space scenes).
    pub distance_kind: DistanceKind,
    /// The distance at the rasterized vertices.
    pub distances: [f64; 3],
    /// Interpolated with screen weights: wrong under perspective.
    pub distance_affine: f64,
    /// Interpolated with perspective-correct weights: right.
    pub distance_corrected: f64,
    /// The distance of the seen 3D point, for comparison.
    pub distance_true: Option<f64>,
    /// The window depth of the seen 3D point: equals `depth` (z/w is linear on screen).
    pub depth_of_point: Option<f64>,
}

/// How the colour came about.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct ShadeTrace {
    /// The shading mode.
    pub shading: Shading,
    /// The interpolation mode.
    pub mode: Interpolation,
    /// Distance to the nearest source edge in pixels (with the wireframe on).
    pub edge_distance_px: Option<f64>,
    /// Whether the pixel is on a wireframe line (painted [`WIRE_COLOR`](crate::raster::shade::WIRE_COLOR)).
    pub wire: bool,
    /// Whether the pixel is in a line's dark halo (painted
    /// [`WIRE_HALO_COLOR`](crate::raster::shade::WIRE_HALO_COLOR)).
    pub halo: bool,
    /// The distance from an edge below which a pixel is on a line, in pixels,
    /// [`WIRE_WIDTH_PX`](crate::raster::shade::WIRE_WIDTH_PX) (wireframe on).
    pub wire_width_px: Option<f64>,
    /// The distance in pixels below which a pixel not on a line is in its halo,
    /// `WIRE_WIDTH_PX + WIRE_HALO_PX` (wireframe on).
    pub wire_halo_px: Option<f64>,
    /// The colour the fragment shades to.
    pub color: [u8; 4],
    /// The normal behind a normal or Lambert shade (those shadings only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub normal: Option<NormalTrace>,
}

/// The normal of a [`Shading::Normal`] or [`Shading::Lambert`] fragment, in view space (x
/// right, y up, z towards the viewer).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct NormalTrace {
    /// The vertex normals interpolated in the trace's mode (shorter than 1 between vertices).
    pub interpolated: [f32; 3],
    /// Its length `|n|`.
    pub length: f32,
    /// `n̂ = n / |n|` ([`shade::unit_normal`](crate::raster::shade::unit_normal)).
    pub unit: [f32; 3],
    /// The Lambert brightness `AMBIENT + (1 - AMBIENT) max(0, n̂ · l)`, `l = (0, 0, 1)`
    /// ([`shade::lambert_factor`](crate::raster::shade::lambert_factor)).
    pub lambert: f32,
    /// [`shade::AMBIENT`](crate::raster::shade::AMBIENT).
    pub ambient: f32,
    /// The interpolated vertex colour, the Lambert shade's albedo.
    pub albedo: [f32; 3],
}
