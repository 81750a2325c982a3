//! How the space view places a scene's clip-space points in 3D: through the scene camera's
//! inverse projection (world and model scenes), or, for a clip-space scene (no camera), with
//! clip w as the depth.
//!
//! A clip-space scene is drawn in the space `(x_c, y_c, -w_c)`: as if its projection were
//! `x_c = x_v`, `y_c = y_v`, `w_c = -z_v` (a square 90 degree frustum, `|x| <= w`). That map is
//! linear, so triangles stay flat, the eye is the origin and the ray through NDC `(n_x, n_y)` is
//! `d (n_x, n_y, -1)`: the point it meets has the perspective-correct weights, as in a camera
//! scene. Its near and far planes are where `z_c = -w_c` and `z_c = w_c`; they are drawn when the
//! vertices' `z_c` is an affine function of `w_c` (what every OpenGL perspective projection
//! makes: `z_c = alpha w_c + beta`), found by least squares over the vertices.

use glam::{DVec2, DVec3, DVec4};

use crate::raster::camera::{Camera, CameraChain, Projection};
use crate::raster::mesh::ClipMesh;
use crate::scene::Scene;

/// How clip-space points become the space view's 3D points (view space, or clip w as depth).
#[derive(Clone, Debug, PartialEq)]
pub enum Lens {
    /// A world or model scene: its camera chain (view space, eye at the origin looking down -z).
    Camera {
        /// The scene camera's chain (its `view_from_clip` maps points back).
        chain: Box<CameraChain>,
        /// The near plane's distance in front of the eye.
        near: f64,
        /// The far plane's distance.
        far: f64,
    },
    /// A clip-space scene, drawn as `(x_c, y_c, -w_c)`.
    ClipW {
        /// `z_c = alpha w_c + beta` fitted to the vertices, when they fit it.
        fit: Option<[f64; 2]>,
    },
}

/// Largest residual of the `z_c = alpha w_c + beta` fit, relative to the largest `|w_c|`,
/// for a clip-space scene's near and far planes to be drawn (the bundled scenes round their
/// coordinates to five decimals).
pub const FIT_TOLERANCE: f64 = 1e-3;

impl Lens {
    /// The lens of `scene`: its camera's (world and model scenes), else [`Lens::clip_w`] of
    /// `mesh` (the scene's clip-space mesh).
    pub fn of_scene(scene: &Scene, mesh: &ClipMesh) -> Self {
        let (w, h) = scene.size();
        let aspect = f64::from(w) / f64::from(h);
        match scene {
            Scene::World(s) => Lens::camera(&s.camera, scene.world_from_object(), aspect),
            Scene::Model(s) => Lens::camera(&s.camera(), scene.world_from_object(), aspect),
            Scene::Clip(_) => Lens::clip_w(mesh),
        }
    }

    /// The lens of a camera scene for an image of `aspect` = width / height.
    pub fn camera(camera: &Camera, world_from_object: glam::DMat4, aspect: f64) -> Self {
        let (near, far) = match camera.projection {
            Projection::Perspective { near, far, .. }
            | Projection::Orthographic { near, far, .. } => (near, far),
        };
        Lens::Camera {
            chain: Box::new(CameraChain::new(camera, world_from_object, aspect)),
            near,
            far,
        }
    }

    /// The lens of a clip-space mesh: `z_c = alpha w_c + beta` by least squares over the
    /// vertices in front of the eye (`w > 0`), kept when every residual is within
    /// [`FIT_TOLERANCE`] of the largest `w` and the planes it gives satisfy `0 < near < far`.
    pub fn clip_w(mesh: &ClipMesh) -> Self {
        let points: Vec<(f64, f64)> = mesh
            .vertices
            .iter()
            .map(|v| (v.clip.w, v.clip.z))
            .filter(|(w, z)| *w > 0.0 && w.is_finite() && z.is_finite())
            .collect();
        let n = points.len() as f64;
        let (sw, sz) = points
            .iter()
            .fold((0.0, 0.0), |(a, b), (w, z)| (a + w, b + z));
        let (mw, mz) = (sw / n, sz / n);
        let (sww, swz) = points.iter().fold((0.0, 0.0), |(a, b), (w, z)| {
            (a + (w - mw) * (w - mw), b + (w - mw) * (z - mz))
        });
        let fit = (points.len() >= 2 && sww > 0.0).then(|| {
            let alpha = swz / sww;
            [alpha, mz - alpha * mw]
        });
        let max_w = points.iter().fold(0.0f64, |m, (w, _)| m.max(w.abs()));
        let fit = fit.filter(|[alpha, beta]| {
            let fits = points
                .iter()
                .all(|(w, z)| (alpha * w + beta - z).abs() <= FIT_TOLERANCE * max_w);
            let lens = Lens::ClipW {
                fit: Some([*alpha, *beta]),
            };
            fits && matches!(lens.planes(), (Some(n), f) if n > 0.0 && f.is_none_or(|f| f > n))
        });
        Lens::ClipW { fit }
    }

    /// Whether rays leave one eye point (else they are parallel: an orthographic camera).
    pub fn perspective(&self) -> bool {
        match self {
            Lens::Camera { chain, .. } => chain.perspective,
            Lens::ClipW { .. } => true,
        }
    }

    /// The 3D point of a clip-space position: `view_from_clip clip` divided by its w (camera
    /// scenes), `(x_c, y_c, -w_c)` (clip-space scenes).
    pub fn point(&self, clip: DVec4) -> DVec3 {
        match self {
            Lens::Camera { chain, .. } => chain.view_from_clip_point(clip),
            Lens::ClipW { .. } => DVec3::new(clip.x, clip.y, -clip.w),
        }
    }

    /// The point at view depth `depth` (distance in front of the eye, `-z`) on the ray
    /// through NDC `ndc`: between the ray's near- and far-plane points, linearly in depth
    /// (camera scenes; exact for both projections, the depth being linear along the ray),
    /// `depth (n_x, n_y, -1)` (clip-space scenes).
    pub fn at_depth(&self, ndc: DVec2, depth: f64) -> DVec3 {
        match self {
            Lens::Camera { chain, .. } => {
                let (a, b) = (chain.unproject(ndc, -1.0), chain.unproject(ndc, 1.0));
                a + (b - a) * ((depth + a.z) / (a.z - b.z))
            }
            Lens::ClipW { .. } => DVec3::new(ndc.x * depth, ndc.y * depth, -depth),
        }
    }

    /// The near and far planes' view depths: the camera's, or a clip-space scene's from its
    /// fit (`w_near = -beta / (alpha + 1)` where `z_c = -w_c`, `w_far = beta / (1 - alpha)`
    /// where `z_c = w_c`; no far plane when `alpha >= 1`). `(None, None)` without a fit.
    pub fn planes(&self) -> (Option<f64>, Option<f64>) {
        match self {
            Lens::Camera { near, far, .. } => (Some(*near), Some(*far)),
            Lens::ClipW { fit: None } => (None, None),
            Lens::ClipW {
                fit: Some([alpha, beta]),
            } => (
                Some(-beta / (alpha + 1.0)),
                (*alpha < 1.0).then(|| beta / (1.0 - alpha)),
            ),
        }
    }

    /// The view depth on the central axis where NDC depth `z/w` is `z_ndc`: the inverse of
    /// the projection's depth (camera scenes), `w = beta / (z_ndc - alpha)` (fitted clip-space
    /// scenes). `None` where no point has that depth.
    pub fn depth_at_z_ndc(&self, z_ndc: f64) -> Option<f64> {
        let d = match self {
            Lens::Camera { chain, .. } => -chain.unproject(DVec2::ZERO, z_ndc).z,
            Lens::ClipW { fit: None } => return None,
            Lens::ClipW {
                fit: Some([alpha, beta]),
            } => beta / (z_ndc - alpha),
        };
        (d.is_finite() && d > 0.0).then_some(d)
    }
}
