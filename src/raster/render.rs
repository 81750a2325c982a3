//! The pipeline driver: clip-space mesh in, framebuffer out.
//!
//! Per source triangle: clip (`clip`), divide and snap (`project`), fan the clipped polygon
//! into triangles and set them up (`setup`). Then, in submission order, every covered pixel
//! centre is interpolated (`interpolate`), depth-tested (less-than) and shaded (`shade`).
//! The probe calls [`prepare_triangle`] and [`interpolate::fragment`] exactly as done here.

use glam::{DVec4, Vec2, Vec3};

use super::clip::{ClipPolygon, ClipVertex, clip_triangle};
use super::framebuffer::Framebuffer;
use super::interpolate::{self, Interpolation};
use super::project::{MAX_IMAGE_SIZE, Viewport, project_vertex};
use super::setup::{Facing, TriangleSetup, sample_point, setup_triangle};
use super::shade::{ShadeParams, Shading, shade};
use super::texture::{Filter, Texture, Wrap};
use super::varying::Varyings;

/// One vertex of a mesh, already in clip space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshVertex {
    pub clip: DVec4,
    pub uv: Vec2,
    pub color: Vec3,
}

/// Triangles over clip-space vertices: what the rasterizer draws.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct ClipMesh {
    pub vertices: Vec<MeshVertex>,
    pub triangles: Vec<[u32; 3]>,
}

/// How to draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderSettings {
    pub width: u32,
    pub height: u32,
    pub mode: Interpolation,
    pub filter: Filter,
    pub wrap: Wrap,
    pub shading: Shading,
    pub wireframe: bool,
    pub background: [u8; 4],
}

/// The default background: a dark slate grey, opaque.
pub const DEFAULT_BACKGROUND: [u8; 4] = [36, 38, 46, 255];

impl Default for RenderSettings {
    fn default() -> Self {
        Self {
            width: 800,
            height: 600,
            mode: Interpolation::Perspective,
            filter: Filter::Bilinear,
            wrap: Wrap::Repeat,
            shading: Shading::Texture,
            wireframe: false,
            background: DEFAULT_BACKGROUND,
        }
    }
}

impl RenderSettings {
    pub fn viewport(&self) -> Viewport {
        Viewport {
            width: self.width,
            height: self.height,
        }
    }
}

/// Errors that stop a render as a whole.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RenderError {
    #[error("image size {width}x{height} is outside 1..={max} pixels per side", max = MAX_IMAGE_SIZE)]
    BadSize { width: u32, height: u32 },
}

/// Why a source triangle drew nothing, or that it was drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TriangleStatus {
    /// Set up and rasterized (it may still cover no pixel centre).
    Drawn,
    /// A vertex index is out of range.
    BadIndex,
    /// A vertex has a NaN or infinite clip coordinate.
    NotFinite,
    /// Clipping left nothing: the triangle is outside the view volume.
    ClippedAway,
    /// Zero area on screen after snapping, or bounds outside the viewport.
    Empty,
}

impl TriangleStatus {
    /// A short explanation for people.
    pub fn describe(self) -> &'static str {
        match self {
            TriangleStatus::Drawn => "drawn",
            TriangleStatus::BadIndex => "a vertex index is out of range",
            TriangleStatus::NotFinite => "a vertex coordinate is NaN or infinite",
            TriangleStatus::ClippedAway => "clipped away: it lies outside the view volume",
            TriangleStatus::Empty => "zero area on screen, or outside the image",
        }
    }
}

/// A source triangle after clipping, projection and setup.
#[derive(Clone, Debug)]
pub struct PreparedTriangle {
    /// Index into [`ClipMesh::triangles`].
    pub source: u32,
    pub status: TriangleStatus,
    /// The clipped polygon (`None` if the input was unusable).
    pub polygon: Option<ClipPolygon>,
    /// The fan triangles of the clipped polygon that can cover pixels.
    pub setups: Vec<TriangleSetup>,
}

impl PreparedTriangle {
    /// The facing of the drawn triangle, if any part of it was set up.
    pub fn facing(&self) -> Option<Facing> {
        self.setups.first().map(|s| s.facing)
    }
}

/// The three clip-space vertices of a source triangle, with one-hot barycentric varyings.
/// `None` if an index is out of range.
pub fn source_vertices(mesh: &ClipMesh, index: u32) -> Option<[ClipVertex; 3]> {
    let tri = mesh.triangles.get(index as usize)?;
    let mut out = [ClipVertex::default(); 3];
    for (k, (o, &vi)) in out.iter_mut().zip(tri).enumerate() {
        let v = mesh.vertices.get(vi as usize)?;
        let mut bary = [0.0; 3];
        bary[k] = 1.0;
        *o = ClipVertex {
            clip: v.clip,
            varyings: Varyings::new(bary, v.uv, v.color),
        };
    }
    Some(out)
}

/// Clips, projects and sets up one source triangle.
pub fn prepare_triangle(mesh: &ClipMesh, index: u32, viewport: Viewport) -> PreparedTriangle {
    let mut out = PreparedTriangle {
        source: index,
        status: TriangleStatus::BadIndex,
        polygon: None,
        setups: Vec::new(),
    };
    let Some(verts) = source_vertices(mesh, index) else {
        return out;
    };
    if !verts.iter().all(|v| v.clip.is_finite()) {
        out.status = TriangleStatus::NotFinite;
        return out;
    }
    let polygon = clip_triangle(&verts, viewport.guard_band_ndc());
    out.polygon = Some(polygon);
    let pv = polygon.vertices();
    if pv.len() < 3 {
        out.status = TriangleStatus::ClippedAway;
        return out;
    }
    let window: Vec<_> = pv.iter().map(|v| project_vertex(v, viewport)).collect();
    for k in 1..window.len() - 1 {
        if let Some(s) = setup_triangle([window[0], window[k], window[k + 1]], viewport) {
            out.setups.push(s);
        }
    }
    out.status = if out.setups.is_empty() {
        TriangleStatus::Empty
    } else {
        TriangleStatus::Drawn
    };
    out
}

/// The result of a render: the framebuffer and what happened to each source triangle.
#[derive(Clone, Debug)]
pub struct Render {
    pub frame: Framebuffer,
    pub triangles: Vec<PreparedTriangle>,
}

/// Renders a clip-space mesh.
pub fn render(
    mesh: &ClipMesh,
    texture: &Texture,
    settings: &RenderSettings,
) -> Result<Render, RenderError> {
    let (w, h) = (settings.width, settings.height);
    if w == 0 || h == 0 || w > MAX_IMAGE_SIZE || h > MAX_IMAGE_SIZE {
        return Err(RenderError::BadSize {
            width: w,
            height: h,
        });
    }
    let viewport = settings.viewport();
    let triangles: Vec<PreparedTriangle> = (0..mesh.triangles.len() as u32)
        .map(|i| prepare_triangle(mesh, i, viewport))
        .collect();
    let params = shade_params(settings, &triangles);
    let mut frame = Framebuffer::new(w, h, settings.background);
    for tri in &triangles {
        for setup in &tri.setups {
            rasterize(setup, tri.source, texture, &params, &mut frame);
        }
    }
    Ok(Render { frame, triangles })
}

/// The shading parameters of a render: the settings plus the depth range of the drawn
/// triangles (the renderer and the probe both call this).
pub fn shade_params(settings: &RenderSettings, triangles: &[PreparedTriangle]) -> ShadeParams {
    ShadeParams {
        shading: settings.shading,
        mode: settings.mode,
        filter: settings.filter,
        wrap: settings.wrap,
        wireframe: settings.wireframe,
        depth_range: depth_range(triangles),
    }
}

/// Smallest and largest window depth over the drawn vertices.
pub fn depth_range(triangles: &[PreparedTriangle]) -> (f64, f64) {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for s in triangles.iter().flat_map(|t| &t.setups) {
        for v in &s.v {
            lo = lo.min(v.depth);
            hi = hi.max(v.depth);
        }
    }
    if lo <= hi { (lo, hi) } else { (0.0, 1.0) }
}

/// Visits every covered pixel centre of one set-up triangle, depth-tests and writes it.
fn rasterize(
    setup: &TriangleSetup,
    source: u32,
    texture: &Texture,
    params: &ShadeParams,
    frame: &mut Framebuffer,
) {
    let b = setup.bounds;
    let wire = if params.wireframe {
        setup.source_weight_gradients()
    } else {
        [glam::DVec2::ZERO; 3]
    };
    for y in b.y0..=b.y1 {
        for x in b.x0..=b.x1 {
            let e = setup.edge_values(sample_point(x, y));
            if !setup.covers(&e) {
                continue;
            }
            let Some(mut frag) = interpolate::fragment(setup, e) else {
                continue;
            };
            if params.filter == Filter::Trilinear {
                frag.lod = interpolate::quad_lod(
                    setup,
                    x,
                    y,
                    params.mode,
                    texture.width(),
                    texture.height(),
                );
            }
            let i = frame.index(x, y);
            let depth = frag.depth as f32;
            // Less-than depth test (a NaN depth never passes).
            if depth.is_nan() || depth >= frame.depth[i] {
                continue;
            }
            frame.depth[i] = depth;
            frame.triangle[i] = source;
            frame.facing[i] = setup.facing;
            frame.weights_screen[i] = frag.affine.bary();
            frame.weights_perspective[i] = frag.correct.bary();
            frame.uv_affine[i] = frag.affine.uv().to_array();
            frame.uv_perspective[i] = frag.correct.uv().to_array();
            frame.inv_w[i] = frag.inv_w as f32;
            frame.color[i] = shade(&frag, texture, params, &wire);
        }
    }
}
