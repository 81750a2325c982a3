//! The marks the overlay draws from the scene and the probe: the vertex handles' screen
//! positions and a traced pixel's triangle with its weights.

use glam::{DVec2, DVec4};

use super::overlay::{ClipMark, PixelMark, TriangleMark};
use crate::probe::PixelTrace;
use crate::raster::project::{Viewport, ndc_from_clip, window_from_ndc};
use crate::scene::Scene;

/// Smallest clip w at which a vertex is drawn as a handle: at or behind the camera plane a
/// vertex has no position on screen.
pub const MIN_HANDLE_W: f64 = 1e-6;

/// A mesh vertex's clip and window position.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexOnScreen {
    /// Clip-space position.
    pub clip: DVec4,
    /// Window position in pixels (image coordinates, y down), unsnapped; `None` when the vertex
    /// is at or behind the camera (w <= [`MIN_HANDLE_W`]).
    pub window: Option<DVec2>,
}

impl VertexOnScreen {
    /// The vertex's clip w (its view-space distance for a perspective camera).
    pub fn w(&self) -> f64 {
        self.clip.w
    }
}

/// The mesh vertices' clip positions and window positions for a viewport (none for a model:
/// it has too many vertices for handles).
pub fn vertices_on_screen(scene: &Scene, viewport: Viewport) -> Vec<VertexOnScreen> {
    if let Scene::Model(_) = scene {
        return Vec::new();
    }
    let mut sized = scene.clone();
    sized.set_size(viewport.width, viewport.height);
    sized
        .to_mesh()
        .vertices
        .iter()
        .map(|v| VertexOnScreen {
            clip: v.clip,
            window: (v.clip.w > MIN_HANDLE_W && v.clip.is_finite())
                .then(|| window_from_ndc(ndc_from_clip(v.clip), viewport).truncate()),
        })
        .collect()
}

/// The triangle whose weights a trace shows (the one that wrote the pixel, or the nearest
/// one for an uncovered pixel), as rasterized: unsnapped window positions (the weights come
/// from them), mesh vertex of each
/// corner (`None` for a point the clipper made) and the screen weights.
pub fn triangle_mark(trace: &PixelTrace) -> Option<TriangleMark> {
    let d = trace.detail.as_ref()?;
    let v = &d.raster.vertices;
    Some(TriangleMark {
        vertices: [0, 1, 2].map(|k| DVec2::from(v[k].window)),
        mesh_indices: [0, 1, 2].map(|k| {
            v[k].source_vertex
                .and_then(|s| d.vertices.get(s))
                .map(|vt| vt.index as usize)
        }),
        weights: d.screen.rasterizer,
    })
}

/// The polygon the clipper left of the traced pixel's triangle, in window coordinates (the
/// viewport transform of each corner's clip position), when the clipper cut it.
pub fn clip_mark(trace: &PixelTrace) -> Option<ClipMark> {
    let c = trace.detail.as_ref()?.clipping.as_ref()?;
    let viewport = Viewport {
        width: trace.image_size[0],
        height: trace.image_size[1],
    };
    let corners = c
        .polygon
        .iter()
        .map(|v| {
            let window = window_from_ndc(ndc_from_clip(DVec4::from(v.clip)), viewport);
            (v.name.clone(), window.truncate(), v.source_vertex.is_none())
        })
        .collect();
    Some(ClipMark {
        corners,
        fan: c.fan_triangle,
    })
}

/// The overlay's mark of a traced pixel.
pub fn pixel_mark(trace: &PixelTrace) -> PixelMark {
    PixelMark {
        pixel: trace.pixel,
        triangle: triangle_mark(trace),
        quad: quad_mark(trace),
    }
}

/// The 2x2 quad of a traced pixel's level-of-detail derivation (trilinear and anisotropic
/// filtering), with its pixels' uvs.
pub fn quad_mark(trace: &PixelTrace) -> Option<super::overlay::QuadMark> {
    let lod = trace.detail.as_ref()?.attribute.as_ref()?.lod.as_ref()?;
    Some(super::overlay::QuadMark {
        origin: lod.quad[0].pixel,
        uvs: lod.quad.map(|q| q.uv),
        inside: lod.quad.map(|q| q.inside),
    })
}

/// The common w of `ws` when every one is the same (within [`FLAT_W_TOLERANCE`], relative):
/// a flat triangle or quad facing the camera, where affine and perspective-correct
/// interpolation agree. `None` for no values or differing ones.
///
/// ```
/// use barylab::figure::common_w;
/// assert_eq!(common_w([2.4, 2.4, 2.4]), Some(2.4));
/// assert_eq!(common_w([1.0, 6.0]), None);
/// assert_eq!(common_w([]), None);
/// ```
pub fn common_w(ws: impl IntoIterator<Item = f64>) -> Option<f64> {
    let mut ws = ws.into_iter();
    let first = ws.next()?;
    ws.all(|w| (w - first).abs() <= FLAT_W_TOLERANCE * first.abs())
        .then_some(first)
}

/// Relative difference of w below which corners count as at one distance: far below the
/// digits any label or card shows.
pub const FLAT_W_TOLERANCE: f64 = 1e-9;
