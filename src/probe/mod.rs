//! The pixel probe: every number behind one pixel, computed by the stages that drew it.
//!
//! [`probe`] (or [`Prober::pixel`] for many pixels of one scene) traces the pixel centre
//! `(x + 0.5, y + 0.5)` through the same functions the renderer runs: it prepares every
//! source triangle with [`render::prepare_triangle`], evaluates the edge functions at
//! [`setup::sample_point`] with [`TriangleSetup::edge_values`] and
//! [`TriangleSetup::covers`], interpolates with [`interpolate::fragment`], resolves the depth
//! test as the renderer does (source triangles in order, `less than`, buffer cleared to 1)
//! and shades with [`shade::shade`]. So [`PixelTrace::color`] is the rendered pixel.
//!
//! Beside those numbers the trace holds the same quantities computed the ways textbooks
//! teach them ([`weights`]): screen-space weights by the explicit formula (GAMES101), by
//! cross-product areas and by the OpenGL area form; the 1/w correction in the
//! r, s, t / W_P notation; the 4x4 system (Umetani's Applied Computer Graphics notes); and the 3D point where the ray through
//! the pixel centre meets the triangle's plane. [`format`](mod@format) writes the trace as a worked
//! example (text, Markdown, LaTeX); the trace itself serializes to JSON with the field names
//! documented in `docs/probe.md`.
//!
//! Vertices are named by letter: the quad corners A, B, C, D in a world scene, the vertex
//! index as a letter (0 = A, 1 = B, ..., then V26, V27, ...) in clip-space and model scenes. Points the clipper made are
//! named K1, K2, ... in polygon order. P is the sample, X the 3D point it sees.

pub mod format;
pub mod weights;

use glam::{DMat4, DVec2, DVec3, DVec4, Vec2};
use serde::Serialize;

use crate::raster::camera::{Camera, Projection};
use crate::raster::clip::PlaneName;
use crate::raster::interpolate::{self, Fragment, Interpolation};
use crate::raster::project::{self, MAX_IMAGE_SIZE, SUBPIXEL, Viewport};
use crate::raster::render::TriangleStatus;
use crate::raster::render::{self, ClipMesh, PreparedTriangle, RenderError, RenderSettings};
use crate::raster::setup::{self, EdgeKind, Facing, TriangleSetup};
use crate::raster::shade::{self, ShadeParams, Shading};
use crate::raster::texture::{Filter, Texture, Wrap};
use crate::scene::Scene;

use weights::{AreaWeights, ExplicitFormula, HomogeneousSystem, RayHit, WpCorrection};

/// Errors of the probe.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ProbeError {
    #[error(
        "pixel ({x}, {y}) is outside the {width}x{height} image (x must be 0..={}, y 0..={})",
        .width.saturating_sub(1),
        .height.saturating_sub(1)
    )]
    PixelOutside {
        x: u32,
        y: u32,
        width: u32,
        height: u32,
    },
    #[error(transparent)]
    Render(#[from] RenderError),
}

/// Everything behind one pixel. Serializes to the JSON documented in `docs/probe.md`.
#[derive(Clone, Debug, Serialize)]
pub struct PixelTrace {
    /// `[x, y]`, row 0 at the top.
    pub pixel: [u32; 2],
    /// `[width, height]` of the image.
    pub image_size: [u32; 2],
    pub settings: TraceSettings,
    pub scene_form: SceneForm,
    /// The world scene's matrices; `None` for a clip-space scene.
    pub matrices: Option<Matrices>,
    pub sample: Sample,
    /// The source triangles in drawing order, with coverage and depth test at the sample:
    /// all of them in a mesh of at most [`LIST_ALL_TRIANGLES`] triangles, else those whose
    /// pixel bounds contain the pixel (a model can have thousands).
    pub triangles: Vec<TriangleCoverage>,
    /// How many source triangles the mesh has.
    pub triangle_count: usize,
    /// The source triangle whose fragment the framebuffer kept, if any.
    pub written_by: Option<u32>,
    /// The full derivation for the triangle that wrote the pixel or, for an uncovered pixel,
    /// the nearest drawn triangle (largest smallest weight). `None` if nothing was drawn.
    pub detail: Option<TriangleTrace>,
    /// The final RGBA colour in the framebuffer: equal to the rendered image's pixel.
    pub color: [u8; 4],
}

/// The render settings the trace was made with.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct TraceSettings {
    pub mode: Interpolation,
    pub shading: Shading,
    pub filter: Filter,
    pub wrap: Wrap,
    pub wireframe: bool,
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

/// The matrices of a world scene, each row by row.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Matrices {
    pub world_from_object: [[f64; 4]; 4],
    pub view_from_world: [[f64; 4]; 4],
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
}

/// One source triangle at the sample.
#[derive(Clone, Debug, Serialize)]
pub struct TriangleCoverage {
    /// Index of the source triangle.
    pub source: u32,
    /// Names of its three vertices.
    pub vertices: [String; 3],
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
    pub position: Position,
    /// Whether the fill rule covers the sample.
    pub covered: bool,
    /// The tie rule that decides a sample exactly on an edge.
    pub tie_rule: setup::TieRule,
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
    pub attribute: Option<AttributeTrace>,
    pub depth: Option<DepthTrace>,
    pub shade: Option<ShadeTrace>,
}

/// One source vertex in every space.
#[derive(Clone, Debug, Serialize)]
pub struct VertexTrace {
    pub name: String,
    /// Index into the mesh's vertices.
    pub index: u32,
    /// Object space (world scenes).
    pub object: Option<[f64; 3]>,
    /// World space (world scenes).
    pub world: Option<[f64; 3]>,
    /// View (camera) space (world scenes).
    pub view: Option<[f64; 3]>,
    /// Clip space `(x, y, z, w)`.
    pub clip: [f64; 4],
    /// `(x/w, y/w, z/w)`; `None` if `w <= 0`.
    pub ndc: Option<[f64; 3]>,
    /// Window `(x, y, depth)` before snapping; `None` if `w <= 0`.
    pub window: Option<[f64; 3]>,
    /// Window `(x, y)` snapped to 1/256 pixel; `None` if `w <= 0`.
    pub window_snapped: Option<[f64; 2]>,
    /// `1/w`; `None` if `w <= 0`.
    pub inv_w: Option<f64>,
    pub uv: [f32; 2],
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
    pub name: String,
    /// Which source vertex it is (0, 1, 2), or `None` for a point the clipper made.
    pub source_vertex: Option<usize>,
    pub clip: [f64; 4],
    /// Its weights with respect to the source triangle, carried as a varying.
    pub source_weights: [f32; 3],
}

/// A vertex of the rasterized triangle, as the rasterizer holds it.
#[derive(Clone, Debug, Serialize)]
pub struct RasterVertex {
    pub name: String,
    pub source_vertex: Option<usize>,
    pub clip: [f64; 4],
    pub ndc: [f64; 3],
    /// Window position in pixels before snapping: the interpolation weights come from it.
    pub window: [f64; 2],
    /// Window position snapped to 1/256 pixel, in pixels (`fixed / 256`): coverage.
    pub window_snapped: [f64; 2],
    /// Snapped window position in 1/256 pixel.
    pub fixed: [i64; 2],
    /// Window depth `(z_ndc + 1) / 2`.
    pub depth: f64,
    /// `1 / w`.
    pub inv_w: f64,
    /// Weights of the source triangle's vertices (one-hot at a source vertex), the `smooth`
    /// attribute: at a vertex the clipper made, interpolated in clip space.
    pub source_weights: [f32; 3],
    /// The same as a `noperspective` attribute: at a vertex the clipper made, the source
    /// triangle's screen-linear weights there (OpenGL 4.6, section 13.7.1).
    pub source_weights_affine: [f32; 3],
    pub uv: [f32; 2],
    pub color: [f32; 3],
    /// View-space position (world scenes), from the clip position.
    pub view: Option<[f64; 3]>,
}

/// The set-up triangle.
#[derive(Clone, Debug, Serialize)]
pub struct RasterTriangle {
    pub vertices: [RasterVertex; 3],
    /// Twice the area, in 1/65536 pixel^2.
    pub area2: i64,
    pub facing: Facing,
}

/// Screen-space weights `[r, s, t]` of the rasterized triangle's vertices.
#[derive(Clone, Debug, Serialize)]
pub struct ScreenWeights {
    /// The rasterizer's: `E_i / (2 area)` from exact fixed-point edge values.
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
    pub correction: WpCorrection,
    /// GAMES101's `w_reciprocal = 1 / (alpha/w_A + beta/w_B + gamma/w_C)` (it is W_P).
    pub games101_w_reciprocal: f64,
    /// The renderer's perspective-correct weights ([`interpolate::fragment`]).
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
}

/// The source triangle's weights at the sample as interpolated by the rasterizer (its
/// barycentric varyings, f32), as written to the weight buffers.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct SourceWeights {
    pub screen: [f32; 3],
    pub perspective: [f32; 3],
}

/// The point on the source triangle's plane that the pixel centre sees.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct SeenPoint {
    /// World scenes: the ray through the pixel centre in view space.
    pub ray: Option<ViewRay>,
    /// World scenes: the ray's hit on the plane, in view space, with its weights.
    pub hit: Option<RayHit>,
    pub view: Option<[f64; 3]>,
    pub world: Option<[f64; 3]>,
    /// The point in clip space.
    pub clip: [f64; 4],
    /// Its window depth `(z/w + 1) / 2`.
    pub depth: f64,
    /// Its barycentric weights with respect to the source triangle (from the ray hit in a
    /// world scene, from the 4x4 system's solution in a clip-space scene).
    pub weights: [f64; 3],
}

/// A ray in view space.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct ViewRay {
    pub origin: [f64; 3],
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
    /// `uv * size` for each way.
    pub texel_affine: [f64; 2],
    pub texel_perspective: [f64; 2],
    /// `texel_affine - texel_perspective`, and its length.
    pub texel_difference: [f64; 2],
    pub texel_distance: f64,
    /// Trilinear filtering only: the levels of detail each way.
    pub trilinear: Option<Trilinear>,
    /// The texels the filter reads, each way.
    pub taps_affine: Vec<TapTrace>,
    pub taps_perspective: Vec<TapTrace>,
    /// The filtered texture colour each way, as 8-bit RGBA.
    pub color_affine: [u8; 4],
    pub color_perspective: [u8; 4],
    /// Vertex colours of the rasterized vertices, and the colour interpolated each way.
    pub vertex_colors: [[f32; 3]; 3],
    pub vertex_color_affine: [f32; 3],
    pub vertex_color_perspective: [f32; 3],
}

/// Mipmapping for trilinear filtering.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Trilinear {
    /// Number of mipmap levels (level 0 is the full texture).
    pub levels: u32,
    /// The level of detail from the uv differences across the pixel's 2x2 quad
    /// ([`interpolate::quad_lod`]), with affine and with perspective-correct uv.
    pub lod_affine: f32,
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
    pub weight: f32,
    pub texel: [u8; 4],
}

/// What the pixel's distance measure is in [`DepthTrace`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DistanceKind {
    /// `-z_view`, the distance in front of the camera (world scenes).
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
    pub shading: Shading,
    pub mode: Interpolation,
    /// Distance to the nearest source edge in pixels (with the wireframe on).
    pub edge_distance_px: Option<f64>,
    /// Whether the wireframe overlay coloured the pixel.
    pub wire: bool,
    /// The colour the fragment shades to.
    pub color: [u8; 4],
}

/// World-scene data the mesh does not keep.
#[derive(Clone, Debug)]
struct WorldSpaces {
    object: Vec<DVec3>,
    world_from_object: DMat4,
    view_from_world: DMat4,
    clip_from_view: DMat4,
    view_from_clip: DMat4,
    perspective: bool,
}

impl WorldSpaces {
    fn matrices(&self) -> Matrices {
        let rows = |m: DMat4| m.transpose().to_cols_array_2d();
        Matrices {
            world_from_object: rows(self.world_from_object),
            view_from_world: rows(self.view_from_world),
            clip_from_view: rows(self.clip_from_view),
            perspective: self.perspective,
        }
    }

    /// View-space position of a clip-space point: `view_from_clip * clip`, divided by its w.
    fn view_from_clip_point(&self, clip: DVec4) -> DVec3 {
        let v = self.view_from_clip * clip;
        v.truncate() / v.w
    }
}

/// Meshes with at most this many triangles list every one in [`PixelTrace::triangles`].
pub const LIST_ALL_TRIANGLES: usize = 16;

/// Probes many pixels of one scene: prepares the triangles once.
#[derive(Clone, Debug)]
pub struct Prober<'a> {
    mesh: ClipMesh,
    form: SceneForm,
    spaces: Option<WorldSpaces>,
    names: Vec<String>,
    texture: TextureRef<'a>,
    settings: RenderSettings,
    triangles: Vec<PreparedTriangle>,
    params: ShadeParams,
}

/// The name of mesh vertex `i`: A, B, C, ... then `V26`, `V27`, ...
fn vertex_name(i: usize) -> String {
    if i < 26 {
        char::from(b'A' + i as u8).to_string()
    } else {
        format!("V{i}")
    }
}

/// The texture a [`Prober`] samples: borrowed, or shared so the prober can be kept (the app
/// keeps one per render, so moving the pointer does not clip and set up every triangle again).
#[derive(Clone, Debug)]
enum TextureRef<'a> {
    Borrowed(&'a Texture),
    Shared(std::sync::Arc<Texture>),
}

impl std::ops::Deref for TextureRef<'_> {
    type Target = Texture;
    fn deref(&self) -> &Texture {
        match self {
            TextureRef::Borrowed(t) => t,
            TextureRef::Shared(t) => t,
        }
    }
}

impl Prober<'static> {
    /// Like [`Prober::new`], holding a shared texture, so the prober can be kept.
    pub fn shared(
        scene: &Scene,
        texture: std::sync::Arc<Texture>,
        settings: &RenderSettings,
    ) -> Result<Self, ProbeError> {
        Self::build(scene, TextureRef::Shared(texture), settings)
    }
}

impl<'a> Prober<'a> {
    /// Prepares the scene's triangles as [`render::render`] does.
    pub fn new(
        scene: &Scene,
        texture: &'a Texture,
        settings: &RenderSettings,
    ) -> Result<Self, ProbeError> {
        Self::build(scene, TextureRef::Borrowed(texture), settings)
    }

    /// The settings the prober traces with.
    pub fn settings(&self) -> &RenderSettings {
        &self.settings
    }

    fn build(
        scene: &Scene,
        texture: TextureRef<'a>,
        settings: &RenderSettings,
    ) -> Result<Self, ProbeError> {
        let (w, h) = (settings.width, settings.height);
        if w == 0 || h == 0 || w > MAX_IMAGE_SIZE || h > MAX_IMAGE_SIZE {
            return Err(RenderError::BadSize {
                width: w,
                height: h,
            }
            .into());
        }
        let mesh = scene.to_mesh();
        let spaces = |camera: Camera, object: Vec<DVec3>| {
            let (w, h) = scene.size();
            let clip_from_view = camera.clip_from_view(f64::from(w) / f64::from(h));
            Some(WorldSpaces {
                object,
                world_from_object: scene.world_from_object(),
                view_from_world: camera.view_from_world(),
                clip_from_view,
                view_from_clip: clip_from_view.inverse(),
                perspective: matches!(camera.projection, Projection::Perspective { .. }),
            })
        };
        let spaces = match scene {
            Scene::World(s) => spaces(s.camera, s.quad.iter().map(|c| c.position).collect()),
            Scene::Model(s) => spaces(s.camera(), s.mesh.positions.clone()),
            Scene::Clip(_) => None,
        };
        let names = (0..mesh.vertices.len()).map(vertex_name).collect();
        let viewport = settings.viewport();
        let triangles: Vec<PreparedTriangle> = (0..mesh.triangles.len() as u32)
            .map(|i| render::prepare_triangle_with(&mesh, i, viewport, settings.tie_rule))
            .collect();
        let params = render::shade_params(settings, &triangles);
        let form = match scene {
            Scene::World(_) => SceneForm::World,
            Scene::Clip(_) => SceneForm::Clip,
            Scene::Model(_) => SceneForm::Model,
        };
        Ok(Self {
            mesh,
            form,
            spaces,
            names,
            texture,
            settings: *settings,
            triangles,
            params,
        })
    }

    fn viewport(&self) -> Viewport {
        self.settings.viewport()
    }

    /// The names of source triangle `t`'s vertices.
    fn triangle_names(&self, t: usize) -> [String; 3] {
        match self.mesh.triangles.get(t) {
            Some(tri) => tri.map(|i| {
                self.names
                    .get(i as usize)
                    .cloned()
                    .unwrap_or_else(|| format!("V{i}"))
            }),
            None => [String::new(), String::new(), String::new()],
        }
    }

    /// The texture level of detail the renderer gives a fragment at (x, y): from its 2x2
    /// quad with trilinear filtering ([`interpolate::quad_lod`]), else 0.
    fn lod(&self, s: &TriangleSetup, x: u32, y: u32, mode: Interpolation) -> f32 {
        if self.params.filter == Filter::Trilinear {
            interpolate::quad_lod(s, x, y, mode, self.texture.width(), self.texture.height())
        } else {
            0.0
        }
    }

    fn wire_gradients(&self, s: &TriangleSetup) -> [DVec2; 3] {
        if self.params.wireframe {
            s.source_weight_gradients()
        } else {
            [DVec2::ZERO; 3]
        }
    }

    /// Traces pixel `(x, y)` (row 0 at the top).
    pub fn pixel(&self, x: u32, y: u32) -> Result<PixelTrace, ProbeError> {
        let (width, height) = (self.settings.width, self.settings.height);
        if x >= width || y >= height {
            return Err(ProbeError::PixelOutside {
                x,
                y,
                width,
                height,
            });
        }
        let sp = setup::sample_point(x, y);
        let window = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
        let ndc = ndc_of_window(window, self.viewport());

        // The depth test, exactly as `render` runs it.
        let mut buffer: f32 = 1.0;
        let mut winner: Option<(usize, usize, Fragment)> = None;
        let mut coverage = Vec::with_capacity(self.triangles.len());
        for (ti, tri) in self.triangles.iter().enumerate() {
            let mut depth_test = None;
            let mut covering = None;
            for (si, s) in tri.setups.iter().enumerate() {
                let e = s.edge_values(sp);
                if !s.covers(&e) {
                    continue;
                }
                covering.get_or_insert(si);
                let l = s.weights.at_pixel(x, y);
                let Some(mut frag) = interpolate::fragment_from_weights(s, e, l) else {
                    continue;
                };
                frag.lod = self.lod(s, x, y, self.settings.mode);
                let depth = frag.depth as f32;
                let passed = depth < buffer;
                depth_test = Some(DepthTest {
                    depth,
                    buffer_before: buffer,
                    passed,
                });
                if passed {
                    buffer = depth;
                    winner = Some((ti, si, frag));
                }
            }
            let listed = self.triangles.len() <= LIST_ALL_TRIANGLES
                || tri.setups.iter().any(|s| {
                    let b = s.bounds;
                    (b.x0..=b.x1).contains(&x) && (b.y0..=b.y1).contains(&y)
                });
            if !listed {
                continue;
            }
            let chosen = covering.or_else(|| nearest_setup(tri, x, y).map(|(si, _)| si));
            coverage.push(TriangleCoverage {
                source: tri.source,
                vertices: self.triangle_names(ti),
                status: tri.status,
                clipped: tri.polygon.is_some_and(|p| !p.unclipped()),
                test: chosen.map(|si| self.coverage_test(ti, si, sp)),
                depth_test,
            });
        }

        let color = match &winner {
            Some((ti, si, frag)) => {
                let s = &self.triangles[*ti].setups[*si];
                shade::shade(frag, &self.texture, &self.params, &self.wire_gradients(s))
            }
            None => self.settings.background,
        };

        // The triangle to explain: the winner, else the nearest drawn one.
        let shown = match &winner {
            Some((ti, si, _)) => Some((*ti, *si, true)),
            None => self
                .triangles
                .iter()
                .enumerate()
                .filter_map(|(ti, t)| nearest_setup(t, x, y).map(|(si, m)| (ti, si, m)))
                .fold(None, |best: Option<(usize, usize, f64)>, c| match best {
                    Some(b) if b.2 >= c.2 => Some(b),
                    _ => Some(c),
                })
                .map(|(ti, si, _)| (ti, si, false)),
        };
        let detail = shown.map(|(ti, si, writes)| self.detail(ti, si, writes, (x, y), window, ndc));

        Ok(PixelTrace {
            pixel: [x, y],
            image_size: [width, height],
            settings: TraceSettings {
                mode: self.settings.mode,
                shading: self.settings.shading,
                filter: self.settings.filter,
                wrap: self.settings.wrap,
                wireframe: self.settings.wireframe,
                background: self.settings.background,
            },
            scene_form: self.form,
            matrices: self.spaces.as_ref().map(WorldSpaces::matrices),
            sample: Sample {
                window: window.to_array(),
                fixed: sp.to_array(),
                ndc: ndc.to_array(),
            },
            triangles: coverage,
            triangle_count: self.triangles.len(),
            written_by: winner.map(|(ti, _, _)| self.triangles[ti].source),
            detail,
            color,
        })
    }

    /// The clipped polygon's vertices, named by the source name where a vertex is a source
    /// vertex (kept bit-exactly by the clipper), else K1, K2, ...
    fn polygon(&self, ti: usize) -> Vec<PolygonVertex> {
        let tri = &self.triangles[ti];
        let names = self.triangle_names(ti);
        let source = render::source_vertices(&self.mesh, tri.source);
        let Some(poly) = &tri.polygon else {
            return Vec::new();
        };
        let mut made = 0;
        poly.vertices()
            .iter()
            .map(|v| {
                let src = source
                    .as_ref()
                    .and_then(|s| s.iter().position(|sv| sv.clip == v.clip));
                PolygonVertex {
                    name: match src {
                        Some(i) => names[i].clone(),
                        None => {
                            made += 1;
                            format!("K{made}")
                        }
                    },
                    source_vertex: src,
                    clip: v.clip.to_array(),
                    source_weights: v.varyings.bary(),
                }
            })
            .collect()
    }

    /// The polygon indices of set-up triangle `si` of triangle `ti`.
    fn fan_indices(&self, ti: usize, si: usize, polygon: &[PolygonVertex]) -> [usize; 3] {
        let s = &self.triangles[ti].setups[si];
        s.v.map(|v| {
            polygon
                .iter()
                .position(|p| p.clip == v.clip.to_array())
                .unwrap_or(0)
        })
    }

    fn raster_names(&self, ti: usize, si: usize) -> [String; 3] {
        let polygon = self.polygon(ti);
        self.fan_indices(ti, si, &polygon)
            .map(|k| polygon.get(k).map(|p| p.name.clone()).unwrap_or_default())
    }

    fn coverage_test(&self, ti: usize, si: usize, sp: glam::I64Vec2) -> CoverageTest {
        let s = &self.triangles[ti].setups[si];
        let names = self.raster_names(ti, si);
        let e = s.edge_values(sp);
        let edges: [EdgeTest; 3] = std::array::from_fn(|i| EdgeTest {
            name: format!("{}{}", names[(i + 1) % 3], names[(i + 2) % 3]),
            kind: s.edges[i].kind,
            value: e[i],
            passes: s.edges[i].passes(e[i]),
        });
        let position = if e.iter().any(|&v| v < 0) {
            Position::Outside
        } else if e.contains(&0) {
            Position::OnEdge
        } else {
            Position::Inside
        };
        CoverageTest {
            sub_triangle: si,
            vertices: names,
            edges,
            position,
            covered: s.covers(&e),
            tie_rule: self.settings.tie_rule,
        }
    }

    fn vertex_trace(&self, ti: usize, k: usize) -> VertexTrace {
        let index = self.mesh.triangles[ti][k];
        let v = self.mesh.vertices[index as usize];
        let viewport = self.viewport();
        let clip = v.clip;
        let projected = (clip.w > 0.0).then(|| {
            let ndc = project::ndc_from_clip(clip);
            let win = project::window_from_ndc(ndc, viewport);
            let snapped = project::snap(win.truncate()).as_dvec2() / SUBPIXEL as f64;
            (ndc, win, snapped)
        });
        let (object, world, view) = match &self.spaces {
            Some(sp) => {
                let object = sp.object.get(index as usize).copied().unwrap_or_default();
                let world = sp.world_from_object.transform_point3(object);
                let view = sp.view_from_world.transform_point3(world);
                (
                    Some(object.to_array()),
                    Some(world.to_array()),
                    Some(view.to_array()),
                )
            }
            None => (None, None, None),
        };
        VertexTrace {
            name: self.triangle_names(ti)[k].clone(),
            index,
            object,
            world,
            view,
            clip: clip.to_array(),
            ndc: projected.map(|p| p.0.to_array()),
            window: projected.map(|p| p.1.to_array()),
            window_snapped: projected.map(|p| p.2.to_array()),
            inv_w: projected.map(|_| 1.0 / clip.w),
            uv: v.uv.to_array(),
            color: v.color.to_array(),
        }
    }

    fn detail(
        &self,
        ti: usize,
        si: usize,
        writes_pixel: bool,
        (x, y): (u32, u32),
        window: DVec2,
        ndc: DVec2,
    ) -> TriangleTrace {
        let sp = setup::sample_point(x, y);
        let tri = &self.triangles[ti];
        let s = &tri.setups[si];
        let viewport = self.viewport();
        let vertices: [VertexTrace; 3] = std::array::from_fn(|k| self.vertex_trace(ti, k));
        let behind = vertices.iter().any(|v| v.clip[3] <= 0.0);
        let clipped = tri.polygon.is_some_and(|p| !p.unclipped());
        let polygon = self.polygon(ti);
        let fan = self.fan_indices(ti, si, &polygon);
        let clipping = clipped.then(|| ClipTrace {
            planes: tri
                .polygon
                .map(|p| p.cut_by(viewport.guard_band_ndc()))
                .unwrap_or_default(),
            polygon: polygon.clone(),
            fan_triangle: fan,
        });
        let raster_vertices: [RasterVertex; 3] = std::array::from_fn(|i| {
            let v = &s.v[i];
            let p = polygon.get(fan[i]);
            RasterVertex {
                name: p.map(|p| p.name.clone()).unwrap_or_default(),
                source_vertex: p.and_then(|p| p.source_vertex),
                clip: v.clip.to_array(),
                ndc: v.ndc.to_array(),
                window: v.window.to_array(),
                window_snapped: v.window_snapped().to_array(),
                fixed: v.fixed.to_array(),
                depth: v.depth,
                inv_w: v.inv_w,
                source_weights: v.varyings.bary(),
                source_weights_affine: v.noperspective.bary(),
                uv: v.varyings.uv().to_array(),
                color: v.varyings.color().to_array(),
                view: self
                    .spaces
                    .as_ref()
                    .map(|w| w.view_from_clip_point(v.clip).to_array()),
            }
        });
        let raster = RasterTriangle {
            vertices: raster_vertices,
            area2: s.area2,
            facing: s.facing,
        };
        let coverage = self.coverage_test(ti, si, sp);
        let e = s.edge_values(sp);
        let rasterizer = s.weights.at_pixel(x, y);
        let frag = interpolate::fragment_from_weights(s, e, rasterizer).map(|mut f| {
            f.lod = self.lod(s, x, y, self.settings.mode);
            f
        });

        // The 4x4 system on the source triangle.
        let system = self.system(ti, ndc);

        // Screen weights, four ways plus the rasterizer's.
        let pos = s.v.map(|v| v.window);
        let explicit = weights::explicit_formula(window, pos);
        let cross_product = weights::cross_product_weights(window, pos);
        let gl_area = weights::gl_area_weights(window, pos);
        let from_system = match (&system, clipped) {
            (Some(sys), false) => {
                let b = sys.system.solution;
                Some([0, 1, 2].map(|i| b[i] * s.v[i].clip.w / b[3]))
            }
            _ => None,
        };
        let mut max_difference: f64 = 0.0;
        let others = [
            explicit.map(|f| f.weights),
            cross_product.map(|a| a.weights),
            gl_area.map(|a| a.weights),
            from_system,
        ];
        for m in others.iter().flatten() {
            for i in 0..3 {
                max_difference = max_difference.max((m[i] - rasterizer[i]).abs());
            }
        }
        let screen = ScreenWeights {
            rasterizer,
            explicit,
            cross_product,
            gl_area,
            from_system,
            max_difference,
        };

        let w = s.v.map(|v| v.clip.w);
        let perspective = frag.as_ref().and_then(|f| {
            let correction = weights::w_p_correction(f.screen, w)?;
            Some(PerspectiveTrace {
                w,
                correction,
                games101_w_reciprocal: 1.0
                    / (f.screen[0] / w[0] + f.screen[1] / w[1] + f.screen[2] / w[2]),
                renderer_weights: f.perspective,
                renderer_inv_w: f.inv_w,
            })
        });

        let seen_point = self.seen_point(ti, ndc, system.as_ref());
        let source_weights = frag.as_ref().map(|f| SourceWeights {
            screen: f.affine.bary(),
            perspective: f.correct.bary(),
        });
        let attribute = frag.as_ref().map(|f| self.attribute(s, f, (x, y)));
        let depth = frag.as_ref().map(|f| {
            let (kind, distances) = match &self.spaces {
                Some(_) => (
                    DistanceKind::ViewDepth,
                    raster
                        .vertices
                        .clone()
                        .map(|v| -v.view.map_or(0.0, |p| p[2])),
                ),
                None => (DistanceKind::ClipW, w),
            };
            let dot =
                |l: &[f64; 3]| l[0] * distances[0] + l[1] * distances[1] + l[2] * distances[2];
            DepthTrace {
                window_depths: s.v.map(|v| v.depth),
                depth: f.depth,
                distance_kind: kind,
                distances,
                distance_affine: dot(&f.screen),
                distance_corrected: dot(&f.perspective),
                distance_true: seen_point.map(|p| match (kind, p.view) {
                    (DistanceKind::ViewDepth, Some(v)) => -v[2],
                    _ => p.clip[3],
                }),
                depth_of_point: seen_point.map(|p| p.depth),
            }
        });
        let shade = frag.as_ref().map(|f| {
            let wire = self.wire_gradients(s);
            ShadeTrace {
                shading: self.settings.shading,
                mode: self.settings.mode,
                edge_distance_px: self
                    .params
                    .wireframe
                    .then(|| shade::edge_distance_px(f.edge_weights, &wire)),
                wire: self.params.wireframe
                    && shade::edge_distance_px(f.edge_weights, &wire) < shade::WIRE_WIDTH_PX,
                color: shade::shade(f, &self.texture, &self.params, &wire),
            }
        });

        TriangleTrace {
            source: tri.source,
            writes_pixel,
            vertices,
            vertex_behind_camera: behind,
            clipping,
            raster,
            coverage,
            screen,
            perspective,
            system,
            source_weights,
            seen_point,
            attribute,
            depth,
            shade,
        }
    }

    /// The 4x4 system for source triangle `ti`, on its raw clip coordinates: it reaches the
    /// exact answer on its own, independently of clipping, projection and the rasterizer.
    fn system(&self, ti: usize, ndc: DVec2) -> Option<SystemTrace> {
        let source = render::source_vertices(&self.mesh, self.triangles[ti].source)?;
        let system = weights::solve_homogeneous_system(source.map(|v| v.clip), ndc)?;
        Some(SystemTrace {
            system,
            s: ndc.to_array(),
        })
    }

    fn seen_point(&self, ti: usize, ndc: DVec2, system: Option<&SystemTrace>) -> Option<SeenPoint> {
        match &self.spaces {
            Some(sp) => {
                let unproject = |z: f64| {
                    let v = sp.view_from_clip * DVec4::new(ndc.x, ndc.y, z, 1.0);
                    v.truncate() / v.w
                };
                let (near, far) = (unproject(-1.0), unproject(1.0));
                let (origin, direction) = if sp.perspective {
                    (DVec3::ZERO, near)
                } else {
                    (near, far - near)
                };
                let tri: [DVec3; 3] = std::array::from_fn(|k| {
                    let i = self.mesh.triangles[ti][k] as usize;
                    let object = sp.object.get(i).copied().unwrap_or_default();
                    sp.view_from_world
                        .transform_point3(sp.world_from_object.transform_point3(object))
                });
                let hit = weights::ray_triangle(origin, direction, tri)?;
                let view = DVec3::from_array(hit.point);
                let clip = sp.clip_from_view * view.extend(1.0);
                Some(SeenPoint {
                    ray: Some(ViewRay {
                        origin: origin.to_array(),
                        direction: direction.to_array(),
                    }),
                    hit: Some(hit),
                    view: Some(hit.point),
                    world: Some(
                        sp.view_from_world
                            .inverse()
                            .transform_point3(view)
                            .to_array(),
                    ),
                    clip: clip.to_array(),
                    depth: (clip.z / clip.w + 1.0) / 2.0,
                    weights: hit.weights,
                })
            }
            None => {
                let sys = system?;
                let b = sys.system.solution;
                let source = render::source_vertices(&self.mesh, self.triangles[ti].source)?;
                let clip = source[0].clip * b[0] + source[1].clip * b[1] + source[2].clip * b[2];
                Some(SeenPoint {
                    ray: None,
                    hit: None,
                    view: None,
                    world: None,
                    clip: clip.to_array(),
                    depth: (clip.z / clip.w + 1.0) / 2.0,
                    weights: [b[0], b[1], b[2]],
                })
            }
        }
    }

    fn attribute(&self, s: &TriangleSetup, f: &Fragment, (x, y): (u32, u32)) -> AttributeTrace {
        let t = &*self.texture;
        let size = DVec2::new(f64::from(t.width()), f64::from(t.height()));
        let uv_a = f.affine.uv();
        let uv_p = f.correct.uv();
        let uvs = s.v.map(|v| v.varyings.uv());
        let w_p = 1.0 / f.inv_w;
        let g = |k: usize| {
            (0..3)
                .map(|i| f.screen[i] * f64::from(uvs[i][k]) * s.v[i].inv_w)
                .sum::<f64>()
                * w_p
        };
        // As `Texture::taps` computes them: `u W` in f32.
        let texel = |uv: Vec2| {
            [
                f64::from(uv.x * t.width() as f32),
                f64::from(uv.y * t.height() as f32),
            ]
        };
        let (filter, wrap) = (self.settings.filter, self.settings.wrap);
        let lod_affine = self.lod(s, x, y, Interpolation::Affine);
        let lod_perspective = self.lod(s, x, y, Interpolation::Perspective);
        let taps = |uv: Vec2, lod: f32| {
            t.taps_lod(uv, filter, wrap, lod)
                .iter()
                .map(|tap| TapTrace {
                    level: tap.level,
                    i: tap.i,
                    j: tap.j,
                    unwrapped: (filter == Filter::Nearest)
                        .then(|| t.nearest_unwrapped(uv, tap.level)),
                    weight: tap.weight,
                    texel: t.texel_at(tap.level, tap.i, tap.j),
                })
                .collect()
        };
        let sample = |uv: Vec2, lod: f32| t.sample_rgba8(uv, filter, wrap, lod);
        let diff = (uv_a.as_dvec2() - uv_p.as_dvec2()) * size;
        AttributeTrace {
            uv_vertices: uvs.map(|u| u.to_array()),
            uv_vertices_affine: s.v.map(|v| v.noperspective.uv().to_array()),
            uv_affine: uv_a.to_array(),
            uv_perspective: uv_p.to_array(),
            uv_games101: [g(0), g(1)],
            texture_size: [t.width(), t.height()],
            texel_affine: texel(uv_a),
            texel_perspective: texel(uv_p),
            texel_difference: diff.to_array(),
            texel_distance: diff.length(),
            trilinear: (filter == Filter::Trilinear).then_some(Trilinear {
                levels: t.levels(),
                lod_affine,
                lod_perspective,
            }),
            taps_affine: taps(uv_a, lod_affine),
            taps_perspective: taps(uv_p, lod_perspective),
            color_affine: sample(uv_a, lod_affine),
            color_perspective: sample(uv_p, lod_perspective),
            vertex_colors: s.v.map(|v| v.varyings.color().to_array()),
            vertex_color_affine: f.affine.color().to_array(),
            vertex_color_perspective: f.correct.color().to_array(),
        }
    }
}

/// The set-up triangle of `tri` nearest to the centre of pixel (x, y): the largest smallest
/// screen weight, with that weight.
fn nearest_setup(tri: &PreparedTriangle, x: u32, y: u32) -> Option<(usize, f64)> {
    let mut best: Option<(usize, f64)> = None;
    for (si, s) in tri.setups.iter().enumerate() {
        let m = s
            .weights
            .at_pixel(x, y)
            .into_iter()
            .fold(f64::INFINITY, f64::min);
        if best.is_none_or(|b| m > b.1) {
            best = Some((si, m));
        }
    }
    best
}

/// NDC of a window position: `(2 x / W - 1, 1 - 2 y / H)`.
///
/// ```
/// use barylab::probe::ndc_of_window;
/// use barylab::raster::project::Viewport;
/// use glam::DVec2;
/// let n = ndc_of_window(DVec2::new(4.5, 6.5), Viewport { width: 8, height: 8 });
/// assert_eq!(n, DVec2::new(0.125, -0.625));
/// ```
pub fn ndc_of_window(window: DVec2, viewport: Viewport) -> DVec2 {
    DVec2::new(
        2.0 * window.x / f64::from(viewport.width) - 1.0,
        1.0 - 2.0 * window.y / f64::from(viewport.height),
    )
}

/// Traces one pixel of a scene rendered with `settings` (see [`Prober`] for many pixels).
///
/// ```
/// use barylab::probe::probe;
/// use barylab::scene::Scene;
/// use barylab::raster::Texture;
/// let scene = Scene::default_scene();
/// let texture = Texture::builtin(barylab::raster::BuiltinTexture::UvGrid);
/// let trace = probe(&scene, &texture, &scene.settings(), (400, 420)).unwrap();
/// assert_eq!(trace.written_by, Some(0));
/// let d = trace.detail.unwrap();
/// assert!(d.screen.max_difference < 1e-12);
/// ```
pub fn probe(
    scene: &Scene,
    texture: &Texture,
    settings: &RenderSettings,
    pixel: (u32, u32),
) -> Result<PixelTrace, ProbeError> {
    Prober::new(scene, texture, settings)?.pixel(pixel.0, pixel.1)
}
