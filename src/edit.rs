//! Scene edits the app makes (the app's document and the animations use them): moving a vertex under the cursor, pushing it along its view ray,
//! the render options stored in a scene. No GUI code here.

use glam::{DMat4, DVec2, DVec3, DVec4};

use crate::i18n::Lang;
use crate::raster::camera::{Camera, CameraChain, Projection};
use crate::raster::project::Viewport;
use crate::raster::{Filter, Interpolation, Shading};
use crate::scene::{Scene, Tilt};

use crate::figure::MIN_HANDLE_W;

/// Range a single push may scale a vertex's distance by, so one scroll event cannot send a
/// vertex to infinity or onto the camera.
pub const PUSH_FACTOR_RANGE: (f64, f64) = (0.5, 2.0);

use crate::figure::vertices_on_screen;

/// Why an edit could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EditError {
    #[error("vertex {0} does not exist")]
    /// No vertex has this index.
    NoVertex(usize),
    #[error("vertex {0} is behind the camera; edit its numbers instead")]
    /// The vertex is behind the camera (w at most the handle minimum), so it cannot follow the pointer.
    BehindCamera(usize),
    #[error("the edit would give a position that is not a finite number")]
    /// The edit would give a position that is not finite.
    NotFinite,
    #[error("a model (OBJ) scene's vertices cannot be moved here; edit the OBJ file")]
    /// A model (OBJ) scene: its vertices cannot be moved or pushed in the app.
    Model,
}

impl EditError {
    /// The message in `lang`, for the status line.
    pub fn message(&self, lang: Lang) -> String {
        match self {
            EditError::NoVertex(k) => lang.tr_with("app.edit.no_vertex", &[("n", k)]),
            EditError::BehindCamera(k) => lang.tr_with("app.edit.behind_camera", &[("n", k)]),
            EditError::NotFinite => lang.tr("app.edit.not_finite"),
            EditError::Model => lang.tr("app.edit.model"),
        }
    }
}

pub use crate::raster::project::ndc_from_window;

/// Replaces a world scene's corners by their tilted positions and sets the tilt to zero, so a
/// corner can be moved without the pivot (the corners' centre) moving the others.
pub fn bake_tilt(scene: &mut Scene) {
    let world_from_object = scene.world_from_object();
    if let Scene::World(s) = scene {
        if s.tilt == Tilt::default() {
            return;
        }
        for c in &mut s.quad {
            c.position = world_from_object.transform_point3(c.position);
        }
        s.tilt = Tilt::default();
    }
}

/// Moves vertex `index` so that it lands on `target` (window pixels) while keeping its depth:
/// in the plane parallel to the screen through the vertex (world form), or keeping clip z and
/// w (clip form, `x_c = x_ndc w`, `y_c = y_ndc w`). A world scene's tilt is baked in first.
pub fn move_vertex_to(
    scene: &mut Scene,
    index: usize,
    target: DVec2,
    viewport: Viewport,
) -> Result<(), EditError> {
    let ndc = ndc_from_window(target, viewport);
    let aspect = viewport.aspect();
    let clip_w = vertex_clip(scene, index, viewport)?.w;
    if clip_w <= MIN_HANDLE_W {
        return Err(EditError::BehindCamera(index));
    }
    bake_tilt(scene);
    match scene {
        Scene::World(s) => {
            let corner = s.quad.get_mut(index).ok_or(EditError::NoVertex(index))?;
            let chain = CameraChain::new(&s.camera, DMat4::IDENTITY, aspect);
            let view = chain.view_from_world.transform_point3(corner.position);
            // The view ray through the target: unproject the NDC point at the near and far
            // planes, then intersect with the plane z_view = const through the vertex.
            let (near, far) = (chain.unproject(ndc, -1.0), chain.unproject(ndc, 1.0));
            let t = (view.z - near.z) / (far.z - near.z);
            let moved_view = near + t * (far - near);
            let world = chain.world_from_view_point(moved_view);
            if !world.is_finite() {
                return Err(EditError::NotFinite);
            }
            corner.position = world;
        }
        Scene::Clip(s) => {
            let v = s
                .vertices
                .get_mut(index)
                .ok_or(EditError::NoVertex(index))?;
            let moved = DVec4::new(ndc.x * v.clip.w, ndc.y * v.clip.w, v.clip.z, v.clip.w);
            if !moved.is_finite() {
                return Err(EditError::NotFinite);
            }
            v.clip = moved;
        }
        Scene::Model(_) => return Err(EditError::Model),
    }
    Ok(())
}

/// Pushes vertex `index` away (factor > 1) or pulls it closer (factor < 1) along its view ray,
/// so it stays at the same place on screen while its w is multiplied by `factor`: the view
/// position is scaled about the eye (perspective; orthographic: only its depth), the clip
/// position is scaled as a whole (clip form). The factor is clamped to [`PUSH_FACTOR_RANGE`].
pub fn push_vertex(
    scene: &mut Scene,
    index: usize,
    factor: f64,
    viewport: Viewport,
) -> Result<(), EditError> {
    let k = factor.clamp(PUSH_FACTOR_RANGE.0, PUSH_FACTOR_RANGE.1);
    if !k.is_finite() {
        return Err(EditError::NotFinite);
    }
    let clip_w = vertex_clip(scene, index, viewport)?.w;
    bake_tilt(scene);
    match scene {
        Scene::World(s) => {
            let corner = s.quad.get_mut(index).ok_or(EditError::NoVertex(index))?;
            let view_from_world = s.camera.view_from_world();
            let view = view_from_world.transform_point3(corner.position);
            let pushed = match s.camera.projection {
                Projection::Perspective { .. } => {
                    if clip_w <= MIN_HANDLE_W {
                        return Err(EditError::BehindCamera(index));
                    }
                    view * k
                }
                Projection::Orthographic { .. } => DVec3::new(view.x, view.y, view.z * k),
            };
            let world = view_from_world.inverse().transform_point3(pushed);
            if !world.is_finite() {
                return Err(EditError::NotFinite);
            }
            corner.position = world;
        }
        Scene::Clip(s) => {
            let v = s
                .vertices
                .get_mut(index)
                .ok_or(EditError::NoVertex(index))?;
            if v.clip.w <= MIN_HANDLE_W {
                return Err(EditError::BehindCamera(index));
            }
            v.clip *= k;
        }
        Scene::Model(_) => return Err(EditError::Model),
    }
    Ok(())
}

fn vertex_clip(scene: &Scene, index: usize, viewport: Viewport) -> Result<DVec4, EditError> {
    vertices_on_screen(scene, viewport)
        .get(index)
        .map(|v| v.clip)
        .ok_or(EditError::NoVertex(index))
}

/// The render options a scene stores, as one value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SceneOptions {
    /// Affine or perspective-correct interpolation.
    pub mode: Interpolation,
    /// What the pixels show (colour, texture, ...).
    pub shading: Shading,
    /// How the texture is sampled.
    pub filter: Filter,
    /// Whether triangle edges are drawn over the image.
    pub wireframe: bool,
}

/// Reads a scene's render options.
pub fn options(scene: &Scene) -> SceneOptions {
    let s = scene.settings();
    SceneOptions {
        mode: s.mode,
        shading: s.shading,
        filter: s.filter,
        wireframe: s.wireframe,
    }
}

/// Writes a scene's render options.
pub fn set_options(scene: &mut Scene, o: SceneOptions) {
    match scene {
        Scene::World(s) => {
            (s.mode, s.shading, s.filter, s.wireframe) = (o.mode, o.shading, o.filter, o.wireframe);
        }
        Scene::Clip(s) => {
            (s.mode, s.shading, s.filter, s.wireframe) = (o.mode, o.shading, o.filter, o.wireframe);
        }
        Scene::Model(s) => {
            (s.mode, s.shading, s.filter, s.wireframe) =
                (o.mode, Some(o.shading), o.filter, o.wireframe);
        }
    }
}

/// The vertical field of view of a world scene's perspective camera, in degrees.
pub fn fov_deg(scene: &Scene) -> Option<f64> {
    match scene {
        Scene::World(s) => match s.camera.projection {
            Projection::Perspective { fov_y_deg, .. } => Some(fov_y_deg),
            Projection::Orthographic { .. } => None,
        },
        Scene::Model(s) => match s.camera().projection {
            Projection::Perspective { fov_y_deg, .. } => Some(fov_y_deg),
            Projection::Orthographic { .. } => None,
        },
        Scene::Clip(_) => None,
    }
}

/// Sets the field of view of a world or model scene's perspective camera (ignored otherwise).
pub fn set_fov_deg(scene: &mut Scene, fov: f64) {
    if let Scene::Model(s) = scene
        && fov.is_finite()
    {
        let mut cam = s.camera();
        if let Projection::Perspective { fov_y_deg, .. } = &mut cam.projection {
            *fov_y_deg = fov.clamp(FOV_RANGE_DEG.0, FOV_RANGE_DEG.1);
            s.camera = Some(cam);
        }
        return;
    }
    if let Scene::World(s) = scene
        && let Projection::Perspective { fov_y_deg, .. } = &mut s.camera.projection
        && fov.is_finite()
    {
        *fov_y_deg = fov.clamp(FOV_RANGE_DEG.0, FOV_RANGE_DEG.1);
    }
}

/// Makes an image (absolute path) or a built-in texture the scene's texture, and shades by it
/// where there are uvs (a model without uvs keeps its colour shading).
pub fn set_texture(scene: &mut Scene, name: String) {
    match scene {
        Scene::World(s) => (s.texture, s.shading) = (name, Shading::Texture),
        Scene::Clip(s) => (s.texture, s.shading) = (name, Shading::Texture),
        Scene::Model(s) => {
            s.texture = Some(name);
            if s.mesh.has_uv {
                s.shading = Some(Shading::Texture);
            }
        }
    }
}

/// Highest camera elevation above (or below) the target's horizon when orbiting, in degrees:
/// at 90 the view direction would be parallel to the up vector and the camera's roll undefined.
pub const MAX_ORBIT_ELEVATION_DEG: f64 = 85.0;

/// Closest and farthest camera distance when zooming, in model radii: closer than this the
/// near plane would cut away almost everything; farther the model is a dot.
pub const ZOOM_DISTANCE_RANGE: (f64, f64) = (0.05, 200.0);

/// A model scene's camera after `change`, with near and far planes fitted to the model again
/// (`near = max(d - 2r, d / 1000)`, `far = d + 2r`, d the distance to the model's centre, r its
/// radius, as [`crate::raster::camera::Camera::framing`] does). Other scenes are unchanged.
fn change_model_camera(scene: &mut Scene, change: impl FnOnce(&mut Camera, f64)) {
    let Scene::Model(s) = scene else {
        return;
    };
    let (centre, radius) = s.mesh.bounding_sphere();
    let radius = radius.max(f64::MIN_POSITIVE);
    let mut cam = s.camera();
    change(&mut cam, radius);
    let d = cam.eye.distance(centre);
    let (near, far) = ((d - 2.0 * radius).max(d / 1000.0), d + 2.0 * radius);
    match &mut cam.projection {
        Projection::Perspective {
            near: n, far: f, ..
        } => (*n, *f) = (near, far),
        Projection::Orthographic {
            near: n, far: f, ..
        } => (*n, *f) = (near, far),
    }
    if cam.validate().is_ok() {
        s.camera = Some(cam);
    }
}

/// Orbits a model scene's camera about its target: `yaw_deg` about the up vector, then
/// `pitch_deg` up (elevation), the elevation kept within ±[`MAX_ORBIT_ELEVATION_DEG`]. The
/// distance to the target stays.
pub fn orbit_camera(scene: &mut Scene, yaw_deg: f64, pitch_deg: f64) {
    if !(yaw_deg.is_finite() && pitch_deg.is_finite()) {
        return;
    }
    change_model_camera(scene, |cam, _| {
        let up = cam.up.normalize_or(DVec3::Y);
        let offset = cam.eye - cam.target;
        let d = offset.length();
        let along = offset.dot(up);
        let horizontal = offset - up * along;
        let h = horizontal
            .try_normalize()
            .unwrap_or_else(|| up.any_orthonormal_vector());
        let elevation = along.atan2(horizontal.length());
        let max = MAX_ORBIT_ELEVATION_DEG.to_radians();
        let elevation = (elevation + pitch_deg.to_radians()).clamp(-max, max);
        let h = glam::DQuat::from_axis_angle(up, yaw_deg.to_radians()) * h;
        cam.eye = cam.target + d * (elevation.cos() * h + elevation.sin() * up);
    });
}

/// Moves a model scene's camera and target parallel to the screen so that the point at the
/// target's depth moves by `pixels` (right, down) in the image: world units per pixel are
/// `2 d tan(fov/2) / H` (perspective) or `height / H` (orthographic).
pub fn pan_camera(scene: &mut Scene, pixels: DVec2, viewport: Viewport) {
    if !pixels.is_finite() || viewport.height == 0 {
        return;
    }
    change_model_camera(scene, |cam, _| {
        let forward = (cam.target - cam.eye).normalize_or_zero();
        let right = forward.cross(cam.up).normalize_or_zero();
        let screen_up = right.cross(forward);
        let d = cam.eye.distance(cam.target);
        let view_height = match cam.projection {
            Projection::Perspective { fov_y_deg, .. } => {
                2.0 * d * (fov_y_deg.to_radians() / 2.0).tan()
            }
            Projection::Orthographic { height, .. } => height,
        };
        let per_pixel = view_height / f64::from(viewport.height);
        // The model follows the pointer, so the camera moves the other way.
        let shift = (-pixels.x * right + pixels.y * screen_up) * per_pixel;
        cam.eye += shift;
        cam.target += shift;
    });
}

/// Zooms a model scene's camera: the distance to the target (orthographic: the view height)
/// is multiplied by `factor` (limited to [`PUSH_FACTOR_RANGE`] per call), the distance kept
/// within [`ZOOM_DISTANCE_RANGE`] model radii.
pub fn zoom_camera(scene: &mut Scene, factor: f64) {
    if !(factor.is_finite() && factor > 0.0) {
        return;
    }
    let factor = factor.clamp(PUSH_FACTOR_RANGE.0, PUSH_FACTOR_RANGE.1);
    change_model_camera(scene, |cam, radius| {
        if let Projection::Orthographic { height, .. } = &mut cam.projection {
            *height *= factor;
            return;
        }
        let offset = cam.eye - cam.target;
        let d = (offset.length() * factor).clamp(
            ZOOM_DISTANCE_RANGE.0 * radius,
            ZOOM_DISTANCE_RANGE.1 * radius,
        );
        cam.eye = cam.target + offset.normalize_or(DVec3::Z) * d;
    });
}

/// Field-of-view range the app offers, in degrees (the camera accepts (0, 180)).
pub const FOV_RANGE_DEG: (f64, f64) = (5.0, 150.0);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::project::{ndc_from_clip, window_from_ndc};

    fn vp() -> Viewport {
        Viewport {
            width: 800,
            height: 600,
        }
    }

    #[test]
    fn moved_vertex_lands_on_the_target_at_the_same_w() {
        for tilt in [
            Tilt::default(),
            Tilt {
                pitch_deg: 20.0,
                yaw_deg: -35.0,
            },
        ] {
            let mut scene = Scene::default_scene();
            if let Scene::World(s) = &mut scene {
                s.tilt = tilt;
            }
            let before = vertices_on_screen(&scene, vp());
            let target = DVec2::new(123.25, 456.5);
            move_vertex_to(&mut scene, 0, target, vp()).expect("move");
            let after = vertices_on_screen(&scene, vp());
            let moved = after[0].window.expect("in front");
            assert!((moved - target).length() < 1e-9, "{moved} vs {target}");
            assert!((after[0].w() - before[0].w()).abs() < 1e-9);
            for k in 1..4 {
                let (a, b) = (after[k].window.expect("a"), before[k].window.expect("b"));
                assert!((a - b).length() < 1e-9, "vertex {k} moved: {a} vs {b}");
            }
        }
    }

    #[test]
    fn pushed_vertex_stays_put_on_screen_and_its_w_scales() {
        let mut scene = Scene::default_scene();
        let before = vertices_on_screen(&scene, vp());
        push_vertex(&mut scene, 2, 1.5, vp()).expect("push");
        let after = vertices_on_screen(&scene, vp());
        let (a, b) = (after[2].window.expect("a"), before[2].window.expect("b"));
        assert!((a - b).length() < 1e-9);
        assert!((after[2].w() / before[2].w() - 1.5).abs() < 1e-12);
    }

    #[test]
    fn clip_form_edits_keep_w() {
        let mut scene = Scene::from_json(
            include_str!("../assets/scenes/clip-two-triangles.json"),
            "clip-two-triangles.json",
        )
        .expect("scene");
        let vp = Viewport {
            width: 64,
            height: 48,
        };
        move_vertex_to(&mut scene, 2, DVec2::new(10.0, 20.0), vp).expect("move");
        let v = vertices_on_screen(&scene, vp)[2];
        assert_eq!(v.w(), 3.0);
        assert!((v.window.expect("front") - DVec2::new(10.0, 20.0)).length() < 1e-12);
    }

    #[test]
    fn a_vertex_behind_the_camera_cannot_be_dragged() {
        let mut scene = Scene::from_json(
            include_str!("../assets/scenes/corner-behind.json"),
            "corner-behind.json",
        )
        .expect("scene");
        let behind = vertices_on_screen(&scene, vp())
            .iter()
            .position(|v| v.window.is_none())
            .expect("a corner is behind");
        let err = move_vertex_to(&mut scene, behind, DVec2::new(1.0, 1.0), vp());
        assert_eq!(err, Err(EditError::BehindCamera(behind)));
    }

    fn torus() -> Scene {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/models/torus.obj");
        Scene::Model(crate::scene::ModelScene::for_model(&path, 800, 600).expect("torus"))
    }

    fn camera(scene: &Scene) -> Camera {
        match scene {
            Scene::Model(s) => s.camera(),
            _ => unreachable!(),
        }
    }

    #[test]
    fn orbiting_keeps_the_distance_and_stops_short_of_the_pole() {
        let mut scene = torus();
        let before = camera(&scene);
        let d = before.eye.distance(before.target);
        orbit_camera(&mut scene, 30.0, 500.0);
        let c = camera(&scene);
        assert!((c.eye.distance(c.target) - d).abs() < 1e-9 * d);
        let elevation = ((c.eye - c.target).normalize().dot(DVec3::Y))
            .asin()
            .to_degrees();
        assert!(
            (elevation - MAX_ORBIT_ELEVATION_DEG).abs() < 1e-9,
            "{elevation}"
        );
        // Near and far still enclose the whole model.
        let (centre, r) = match &scene {
            Scene::Model(s) => s.mesh.bounding_sphere(),
            _ => unreachable!(),
        };
        let Projection::Perspective { near, far, .. } = c.projection else {
            panic!("perspective")
        };
        let dc = c.eye.distance(centre);
        assert!(near <= dc - r && far >= dc + r, "{near} {far} {dc} {r}");
    }

    #[test]
    fn panning_moves_the_target_point_by_the_given_pixels() {
        let mut scene = torus();
        let before = camera(&scene);
        pan_camera(&mut scene, DVec2::new(40.0, -25.0), vp());
        let after = camera(&scene);
        let clip = after.clip_from_world(vp().aspect()) * before.target.extend(1.0);
        let window = window_from_ndc(ndc_from_clip(clip), vp()).truncate();
        let expected = DVec2::new(400.0 + 40.0, 300.0 - 25.0);
        assert!(
            (window - expected).length() < 1e-6,
            "{window} vs {expected}"
        );
    }

    #[test]
    fn zooming_scales_the_distance_within_its_limits() {
        let mut scene = torus();
        let before = camera(&scene);
        let d = before.eye.distance(before.target);
        zoom_camera(&mut scene, 0.8);
        let c = camera(&scene);
        assert!((c.eye.distance(c.target) - 0.8 * d).abs() < 1e-9 * d);
        for _ in 0..100 {
            zoom_camera(&mut scene, 0.5);
        }
        let c = camera(&scene);
        let r = match &scene {
            Scene::Model(s) => s.mesh.bounding_sphere().1,
            _ => unreachable!(),
        };
        assert!((c.eye.distance(c.target) - ZOOM_DISTANCE_RANGE.0 * r).abs() < 1e-9 * r);
        assert!(c.validate().is_ok());
    }
}
