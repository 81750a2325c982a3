//! Preparing source triangles for rasterization: each one clipped in clip space, projected
//! and set up (edge functions, bounds, weight planes), in parallel and in submission order.
//! What happened to each (drawn, clipped away, empty, unusable) is kept for the reports.

use smallvec::SmallVec;

use super::clip::{ClipPolygon, ClipVertex, clip_triangle, inside_every_plane};
use super::mesh::ClipMesh;
use super::project::{Viewport, project_vertex};
use super::settings::{RenderError, RenderSettings};
use super::setup::{Facing, TieRule, TriangleSetup, setup_triangle_samples};
use super::varying::Varyings;

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
    /// Whether it was drawn, or why it drew nothing.
    pub status: TriangleStatus,
    /// The clipped polygon, kept only where the clipper changed the triangle (`None` for an
    /// unclipped or unusable one): most triangles are not clipped, and a polygon is about 1 KB
    /// (see [`PreparedTriangle::polygon`] for every triangle's).
    pub clipped: Option<Box<ClipPolygon>>,
    /// The fan triangles of the clipped polygon that can cover pixels: one for an unclipped
    /// triangle (most of a mesh), kept inline so preparing a mesh allocates nothing per triangle.
    pub setups: SmallVec<[TriangleSetup; 1]>,
}

impl PreparedTriangle {
    /// The polygon the clipper made of this triangle of `mesh` (the triangle itself when the
    /// clipper left it whole): the kept one, or the same clipping done again. `None` if the
    /// input was unusable.
    pub fn polygon(&self, mesh: &ClipMesh, viewport: Viewport) -> Option<ClipPolygon> {
        match &self.clipped {
            Some(p) => Some(**p),
            None => {
                let verts = source_vertices(mesh, self.source)?;
                if !verts.iter().all(|v| v.clip.is_finite()) {
                    return None;
                }
                Some(clip_triangle(&verts, viewport.guard_band_ndc()))
            }
        }
    }

    /// Whether the clipper changed the triangle.
    pub fn is_clipped(&self) -> bool {
        self.clipped.is_some()
    }

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
        *o = ClipVertex::new(
            v.clip,
            Varyings::new(bary, v.uv, v.color).with_normal(v.normal),
        );
    }
    Some(out)
}

/// Clips, projects and sets up one source triangle (under the default tie rule).
pub fn prepare_triangle(mesh: &ClipMesh, index: u32, viewport: Viewport) -> PreparedTriangle {
    prepare_triangle_with(mesh, index, viewport, TieRule::default())
}

/// Like [`prepare_triangle`], with samples exactly on an edge decided by `rule`.
pub fn prepare_triangle_with(
    mesh: &ClipMesh,
    index: u32,
    viewport: Viewport,
    rule: TieRule,
) -> PreparedTriangle {
    prepare_triangle_samples(mesh, index, (viewport, rule), false)
}

/// Like [`prepare_triangle_with`]; with `multisample`, the set-up keeps triangles too thin
/// to hold a pixel centre ([`setup_triangle_samples`]): they may cover other samples.
pub fn prepare_triangle_samples(
    mesh: &ClipMesh,
    index: u32,
    (viewport, rule): (Viewport, TieRule),
    multisample: bool,
) -> PreparedTriangle {
    let mut out = PreparedTriangle {
        source: index,
        status: TriangleStatus::BadIndex,
        clipped: None,
        setups: SmallVec::new(),
    };
    let Some(verts) = source_vertices(mesh, index) else {
        return out;
    };
    if !verts.iter().all(|v| v.clip.is_finite()) {
        out.status = TriangleStatus::NotFinite;
        return out;
    }
    let guard = viewport.guard_band_ndc();
    if inside_every_plane(&verts, guard) {
        // Most triangles of a mesh: nothing to clip, one set-up triangle.
        let window = verts.map(|v| project_vertex(&v, viewport));
        out.setups
            .extend(setup_triangle_samples(window, viewport, rule, multisample));
    } else {
        let polygon = clip_triangle(&verts, guard);
        out.clipped = Some(Box::new(polygon));
        let pv = polygon.vertices();
        if pv.len() < 3 {
            out.status = TriangleStatus::ClippedAway;
            return out;
        }
        let window: Vec<_> = pv.iter().map(|v| project_vertex(v, viewport)).collect();
        for k in 1..window.len() - 1 {
            let fan = [window[0], window[k], window[k + 1]];
            if let Some(s) = setup_triangle_samples(fan, viewport, rule, multisample) {
                out.setups.push(s);
            }
        }
    }
    out.status = if out.setups.is_empty() {
        TriangleStatus::Empty
    } else {
        TriangleStatus::Drawn
    };
    out
}

/// Checks the image size ([`RenderSettings::check_size`]) and prepares every source
/// triangle of `mesh` with [`prepare_triangle`], in order: the first step of a render, and
/// what the probe traces.
pub fn prepare_triangles(
    mesh: &ClipMesh,
    settings: &RenderSettings,
) -> Result<Vec<PreparedTriangle>, RenderError> {
    settings.check_size()?;
    let multisample = settings.samples.count.get() > 1;
    Ok(prepare_all_samples(
        mesh,
        (settings.viewport(), settings.tie_rule),
        multisample,
    ))
}

/// Clips, projects and sets up every source triangle, in parallel (rayon's current thread
/// pool), in submission order.
pub fn prepare_all(mesh: &ClipMesh, viewport: Viewport) -> Vec<PreparedTriangle> {
    prepare_all_with(mesh, viewport, TieRule::default())
}

/// Like [`prepare_all`], with samples exactly on an edge decided by `rule`.
pub fn prepare_all_with(
    mesh: &ClipMesh,
    viewport: Viewport,
    rule: TieRule,
) -> Vec<PreparedTriangle> {
    prepare_all_samples(mesh, (viewport, rule), false)
}

/// Like [`prepare_all_with`], each triangle prepared by [`prepare_triangle_samples`].
pub fn prepare_all_samples(
    mesh: &ClipMesh,
    (viewport, rule): (Viewport, TieRule),
    multisample: bool,
) -> Vec<PreparedTriangle> {
    use rayon::prelude::*;
    (0..mesh.triangles.len() as u32)
        .into_par_iter()
        .with_min_len(PREPARE_CHUNK)
        .map(|i| prepare_triangle_samples(mesh, i, (viewport, rule), multisample))
        .collect()
}

/// Triangles one parallel task prepares at least: small meshes (the quad) stay on one thread.
const PREPARE_CHUNK: usize = 256;
