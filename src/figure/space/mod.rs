//! The space view: the scene in 3D beside the screen. The eye, the view frustum with its near
//! and far planes, the image plane with a coarse pixel grid, the triangles with their vertex
//! names and clip w, and for one pixel the ray from the eye through its centre meeting the
//! triangle at P, with the affine guess Q beside it.
//!
//! Nothing here computes a weight: P's weights are the probe's perspective-correct `a b c`
//! ([`crate::probe::TriangleTrace::perspective`]), Q's the rasterizer's screen weights `r s t`
//! ([`crate::probe::ScreenWeights::rasterizer`]), both applied to the rasterized triangle's
//! vertices in 3D: `P = a V_0 + b V_1 + c V_2`, `Q = r V_0 + s V_1 + t V_2`. Clipping is the
//! renderer's ([`render::prepare_triangles`]); points come back to 3D through the scene
//! camera's inverse projection ([`Lens`]).
//!
//! Files: this one builds [`SpaceScene`] (the 3D primitives); `lens.rs` maps clip space to
//! 3D; `orbit.rs` is the view's own camera; `draw.rs` turns the scene into painter-ordered 2D
//! [`Shape`]s, which `svg.rs` writes as an SVG figure (and PNG) and the app paints with egui;
//! `tetra.rs` is the tetrahedron's volume weights figure, `depth.rs` the depth-precision plot.

mod depth;
mod draw;
mod labels;
mod lens;
mod orbit;
mod shape;
mod svg;
mod tetra;

pub use depth::depth_plot;
pub use draw::{
    Anchor2, Colour, INK, P_COLOUR, Q_COLOUR, RAY_COLOUR, Shape, ShapeKind, shapes, text_width,
};
pub use lens::{FIT_TOLERANCE, Lens};
pub use orbit::{Orbit, PITCH_LIMIT, Projector, ZOOM_RANGE};
pub use svg::{FIGURE_SIZE, SpaceFigure, drawing_rect, panel_lines, wrap_line};
pub use tetra::{
    POINT_WEIGHTS, RayThrough, TetraFigure, is_tetrahedron, segment_inside, signed_volume,
    volume_weights,
};

use glam::{DVec2, DVec3};

use crate::probe::PixelTrace;
use crate::raster::render::{self, RenderError, RenderSettings};
use crate::scene::{Scene, vertex_name};

/// Meshes with more triangles are drawn as the pixel's triangle only (a model's thousands of
/// triangles would bury the frustum and the ray).
pub const MAX_SPACE_TRIANGLES: usize = 2000;

/// The pixel grid drawn on the image plane has about this many cells across.
const GRID_CELLS: u32 = 8;

/// One vertex of the mesh in 3D.
#[derive(Clone, Debug, PartialEq)]
pub struct SpaceVertex {
    /// Its name, as on the canvas and in the derivation (A, B, C, ...).
    pub name: String,
    /// Its 3D position ([`Lens::point`] of its clip position).
    pub point: DVec3,
    /// Its clip w (the view depth for a perspective camera).
    pub w: f64,
}

/// One source triangle in 3D.
#[derive(Clone, Debug, PartialEq)]
pub struct SpaceTriangle {
    /// Index of the source triangle.
    pub source: u32,
    /// Its vertices (indices into [`SpaceScene::vertices`]).
    pub corners: [usize; 3],
    /// The part the clipper kept, in 3D, when it cut the triangle (the renderer's polygon).
    pub kept: Option<Vec<DVec3>>,
}

/// The near plane's cut of the pixel's triangle: the clipped polygon with the probe's names
/// (source letters, K1, K2, ...) and its fan.
#[derive(Clone, Debug, PartialEq)]
pub struct NearCut {
    /// The polygon's vertices in order: name and 3D point.
    pub polygon: Vec<(String, DVec3)>,
    /// The fan triangle the pixel was rasterized in (polygon indices).
    pub fan_triangle: [usize; 3],
}

/// The pixel's ray and the two points on its triangle.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelRay {
    /// The pixel, `[x, y]`, row 0 at the top.
    pub pixel: [u32; 2],
    /// The pixel centre in NDC.
    pub ndc: DVec2,
    /// Where the ray starts: the eye, or for an orthographic camera its point at depth 0.
    pub origin: DVec3,
    /// The pixel centre on the image plane.
    pub on_image: DVec3,
    /// The far end drawn (at [`SpaceScene::shown_far`]).
    pub end: DVec3,
    /// What the ray meets; `None` when no triangle is near the pixel or its 1/w is not
    /// positive.
    pub seen: Option<Seen>,
}

/// The point P the pixel sees and the affine guess Q on the rasterized triangle.
#[derive(Clone, Debug, PartialEq)]
pub struct Seen {
    /// Index of the source triangle.
    pub source: u32,
    /// Whether that triangle's fragment is the pixel's (false: the nearest triangle of an
    /// uncovered pixel, the weights extended outside it).
    pub covered: bool,
    /// The rasterized triangle's vertex names (source letters, or K1, K2 when clipped).
    pub names: [String; 3],
    /// Its vertices in 3D.
    pub corners: [DVec3; 3],
    /// The probe's perspective-correct weights `a b c`.
    pub abc: [f64; 3],
    /// The rasterizer's screen weights `r s t`.
    pub rst: [f64; 3],
    /// `W_P`, the interpolated w (the view depth of P for a perspective camera).
    pub w_p: f64,
    /// The fragment's window depth `d = (z/w + 1) / 2`, what the depth buffer stores (linear
    /// on the screen).
    pub depth: f64,
    /// `P = a V_0 + b V_1 + c V_2`.
    pub p: DVec3,
    /// `Q = r V_0 + s V_1 + t V_2`.
    pub q: DVec3,
    /// The near plane's cut, when the clipper cut the triangle.
    pub cut: Option<NearCut>,
}

/// What the space view draws, in 3D (view space, or clip w as depth).
#[derive(Clone, Debug, PartialEq)]
pub struct SpaceScene {
    /// How clip space maps to 3D.
    pub lens: Lens,
    /// The image size in pixels.
    pub image_size: [u32; 2],
    /// The near plane's view depth, when known.
    pub near: Option<f64>,
    /// The far plane's view depth, when known.
    pub far: Option<f64>,
    /// Where the drawn frustum ends: the far plane, or nearer when the far plane is far
    /// beyond the scene (then the end face is not the far plane).
    pub shown_far: f64,
    /// The image plane's depth: the near plane, unless that is tiny next to the scene.
    pub image_depth: f64,
    /// The image plane's corners, image order (top left, top right, bottom right, bottom
    /// left).
    pub image_corners: [DVec3; 4],
    /// Grid lines on the image plane, every `grid_step` pixels.
    pub grid: Vec<[DVec3; 2]>,
    /// Pixels per grid cell.
    pub grid_step: u32,
    /// The near plane's corners (when known).
    pub near_corners: Option<[DVec3; 4]>,
    /// The end face's corners at [`SpaceScene::shown_far`].
    pub far_corners: [DVec3; 4],
    /// The mesh vertices.
    pub vertices: Vec<SpaceVertex>,
    /// The source triangles drawn.
    pub triangles: Vec<SpaceTriangle>,
    /// The pixel's ray, when a pixel is given.
    pub ray: Option<PixelRay>,
}

/// The four NDC corners in image order: top left, top right, bottom right, bottom left.
const NDC_CORNERS: [[f64; 2]; 4] = [[-1.0, 1.0], [1.0, 1.0], [1.0, -1.0], [-1.0, -1.0]];

impl SpaceScene {
    /// The scene in 3D, with the ray of the pixel `trace` traced (from [`crate::probe()`],
    /// with the same `settings`).
    pub fn build(
        scene: &Scene,
        settings: &RenderSettings,
        trace: Option<&PixelTrace>,
    ) -> Result<Self, RenderError> {
        let mesh = scene.to_mesh();
        let (w, h) = scene.size();
        let lens = Lens::of_scene(scene, &mesh);
        let vertices: Vec<SpaceVertex> = mesh
            .vertices
            .iter()
            .enumerate()
            .map(|(i, v)| SpaceVertex {
                name: vertex_name(i),
                point: lens.point(v.clip),
                w: v.clip.w,
            })
            .collect();
        let pixel_source = trace.and_then(|t| t.detail.as_ref()).map(|d| d.source);
        let prepared = render::prepare_triangles(&mesh, settings)?;
        let triangles = prepared
            .iter()
            .filter(|t| prepared.len() <= MAX_SPACE_TRIANGLES || Some(t.source) == pixel_source)
            .filter_map(|t| {
                let corners = mesh.triangles.get(t.source as usize)?.map(|i| i as usize);
                let kept = t
                    .clipped
                    .as_ref()
                    .map(|p| p.vertices().iter().map(|v| lens.point(v.clip)).collect());
                Some(SpaceTriangle {
                    source: t.source,
                    corners,
                    kept,
                })
            })
            .collect();

        let (near, far) = lens.planes();
        let deepest = vertices
            .iter()
            .map(|v| -v.point.z)
            .filter(|d| d.is_finite())
            .fold(0.0f64, f64::max);
        let nearest = vertices
            .iter()
            .map(|v| -v.point.z)
            .filter(|d| d.is_finite() && *d > 0.0)
            .fold(f64::INFINITY, f64::min);
        let scene_depth = if deepest > 0.0 { deepest } else { 1.0 };
        let image_depth = match near {
            Some(n) if n >= 0.3 * nearest.min(scene_depth) => n,
            _ => 0.5 * nearest.min(scene_depth),
        };
        let shown_far = match far {
            Some(f) if f <= 1.3 * scene_depth => f,
            _ => 1.3 * scene_depth,
        }
        .max(1.5 * image_depth);
        let face = |depth: f64| NDC_CORNERS.map(|c| lens.at_depth(DVec2::from_array(c), depth));
        let image_corners = face(image_depth);
        let grid_step = (w.max(h) / GRID_CELLS).max(1);
        let ndc_x = |x: u32| 2.0 * f64::from(x) / f64::from(w) - 1.0;
        let ndc_y = |y: u32| 1.0 - 2.0 * f64::from(y) / f64::from(h);
        let at = |x: f64, y: f64| lens.at_depth(DVec2::new(x, y), image_depth);
        let grid = (0..=w)
            .step_by(grid_step as usize)
            .map(|x| [at(ndc_x(x), 1.0), at(ndc_x(x), -1.0)])
            .chain(
                (0..=h)
                    .step_by(grid_step as usize)
                    .map(|y| [at(-1.0, ndc_y(y)), at(1.0, ndc_y(y))]),
            )
            .collect();
        let ray = trace.map(|t| pixel_ray(&lens, t, image_depth, shown_far));
        let (near_corners, far_corners) = (near.map(face), face(shown_far));
        Ok(SpaceScene {
            lens,
            image_size: [w, h],
            near,
            far,
            shown_far,
            image_depth,
            image_corners,
            grid,
            grid_step,
            near_corners,
            far_corners,
            vertices,
            triangles,
            ray,
        })
    }

    /// Whether the drawn end face is the far plane (else the frustum goes on beyond it).
    pub fn far_is_shown(&self) -> bool {
        self.far.is_some_and(|f| f <= self.shown_far)
    }
}

/// The ray of the traced pixel and, from its derivation, P and Q.
fn pixel_ray(lens: &Lens, trace: &PixelTrace, image_depth: f64, shown_far: f64) -> PixelRay {
    let ndc = DVec2::from_array(trace.sample.ndc);
    let seen = trace.detail.as_ref().and_then(|d| {
        let p = d.perspective.as_ref()?;
        let corners = d
            .raster
            .vertices
            .clone()
            .map(|v| lens.point(glam::DVec4::from_array(v.clip)));
        let combine = |l: [f64; 3]| corners[0] * l[0] + corners[1] * l[1] + corners[2] * l[2];
        let abc = p.correction.weights;
        let rst = d.screen.rasterizer;
        let depth = d.depth.map_or(f64::NAN, |t| t.depth);
        let cut = d.clipping.as_ref().map(|c| NearCut {
            polygon: c
                .polygon
                .iter()
                .map(|v| (v.name.clone(), lens.point(glam::DVec4::from_array(v.clip))))
                .collect(),
            fan_triangle: c.fan_triangle,
        });
        Some(Seen {
            source: d.source,
            covered: d.writes_pixel,
            names: d.raster.vertices.clone().map(|v| v.name),
            corners,
            abc,
            rst,
            w_p: p.correction.w_p,
            depth,
            p: combine(abc),
            q: combine(rst),
            cut,
        })
    });
    PixelRay {
        pixel: trace.pixel,
        ndc,
        origin: lens.at_depth(ndc, 0.0),
        on_image: lens.at_depth(ndc, image_depth),
        end: lens.at_depth(ndc, shown_far),
        seen,
    }
}
