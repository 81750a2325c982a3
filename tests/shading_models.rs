//! Normal and Lambert shading, and how models are framed: the colours against the normal
//! computed independently (the plane's tilt, a ray hitting the sphere, the file's `vn`).

use std::path::Path;

use barylab::model::ModelMesh;
use barylab::raster::camera::ModelView;
use barylab::raster::shade::AMBIENT;
use barylab::raster::{NO_TRIANGLE, Shading, render};
use barylab::scene::{ModelScene, Scene};
use glam::{DMat4, DVec3, DVec4};

fn front_quad(yaw_deg: f64, shading: Shading) -> Scene {
    let text = format!(
        r#"{{
  "width": 200, "height": 200,
  "camera": {{ "eye": [0, 0, 3], "target": [0, 0, 0],
    "projection": {{ "kind": "perspective", "fov_y_deg": 50, "near": 0.1, "far": 100 }} }},
  "quad": [
    {{ "position": [-1, -1, 0], "uv": [0, 0] }}, {{ "position": [1, -1, 0], "uv": [1, 0] }},
    {{ "position": [1, 1, 0], "uv": [1, 1] }}, {{ "position": [-1, 1, 0], "uv": [0, 1] }}
  ],
  "tilt": {{ "yaw_deg": {yaw_deg}, "pitch_deg": 0 }},
  "shading": "{}"
}}"#,
        serde_json::to_value(shading)
            .expect("shading name")
            .as_str()
            .expect("a string")
    );
    Scene::from_json(&text, "quad.json").expect("scene")
}

fn draw(scene: &Scene) -> barylab::raster::Framebuffer {
    let tex = scene.load_texture(Path::new(".")).expect("texture");
    render(&scene.to_mesh(), &tex, &scene.settings())
        .expect("render")
        .frame
}

fn unorm8(x: f64) -> u8 {
    (x.clamp(0.0, 1.0) * 255.0).round() as u8
}

#[test]
fn a_plane_facing_the_camera_is_lilac_blue_and_a_tilted_one_is_lit_by_its_cosine() {
    let f = draw(&front_quad(0.0, Shading::Normal));
    let covered: Vec<_> = (0..f.color.len())
        .filter(|&i| f.triangle[i] != NO_TRIANGLE)
        .collect();
    assert!(covered.len() > 5000);
    for &i in &covered {
        assert_eq!(f.color[i], [128, 128, 255, 255], "pixel {i}");
    }
    for yaw in [0.0f64, 30.0, 60.0, 75.0] {
        let f = draw(&front_quad(yaw, Shading::Lambert));
        // The camera looks down -z and the quad turned by `yaw` about y: n = (sin, 0, cos)
        // in view space, n . l = cos(yaw); the corners are white.
        let k = f64::from(AMBIENT) + (1.0 - f64::from(AMBIENT)) * yaw.to_radians().cos();
        let g = unorm8(k);
        let mut n = 0;
        for i in 0..f.color.len() {
            if f.triangle[i] != NO_TRIANGLE {
                let c = f.color[i];
                assert!(
                    c[..3].iter().all(|&x| x.abs_diff(g) <= 1),
                    "yaw {yaw}: {c:?} vs {g}"
                );
                n += 1;
            }
        }
        assert!(n > 1000, "yaw {yaw}: {n} pixels");
    }
}

#[test]
fn the_sphere_shows_its_true_normals() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/models");
    let mut model = ModelScene::for_model(&dir.join("sphere.obj"), 240, 180).expect("sphere");
    model.shading = Some(Shading::Normal);
    let cam = model.camera();
    let scene = Scene::Model(model);
    let f = draw(&scene);
    let clip_from_world = cam.clip_from_world(240.0 / 180.0);
    let world_from_clip = clip_from_world.inverse();
    let view_from_world: DMat4 = cam.view_from_world();
    let mut checked = 0;
    let mut worst = 0u8;
    for y in 0..f.height {
        for x in 0..f.width {
            let i = (y * f.width + x) as usize;
            if f.triangle[i] == NO_TRIANGLE {
                continue;
            }
            // The ray through the pixel centre, from the near to the far plane.
            let ndc = (
                2.0 * (f64::from(x) + 0.5) / 240.0 - 1.0,
                1.0 - 2.0 * (f64::from(y) + 0.5) / 180.0,
            );
            let at = |z: f64| {
                let p = world_from_clip * DVec4::new(ndc.0, ndc.1, z, 1.0);
                p.truncate() / p.w
            };
            let (o, d) = (at(-1.0), (at(1.0) - at(-1.0)).normalize());
            // |o + t d| = 1: the nearer root.
            let (b, c) = (o.dot(d), o.length_squared() - 1.0);
            let disc = b * b - c;
            if disc < 0.05 {
                continue; // at the silhouette the tessellation and the sphere differ most
            }
            let hit = o + d * (-b - disc.sqrt());
            let n_view = view_from_world.transform_vector3(hit).normalize();
            let expected = (n_view + DVec3::ONE) * 0.5;
            for k in 0..3 {
                let diff = f.color[i][k].abs_diff(unorm8(expected[k]));
                worst = worst.max(diff);
            }
            checked += 1;
        }
    }
    assert!(checked > 5000, "{checked} pixels checked");
    // 32 x 16 facets: interpolated vertex normals stay within a few degrees of the sphere's.
    assert!(worst <= 10, "largest channel difference {worst}");
}

#[test]
fn the_files_normals_are_used_and_missing_ones_computed() {
    let dir = tempfile::tempdir().expect("temp dir");
    // A square in z = 0 whose `vn` all lean to +x: the file's normals, not the face's.
    let with_vn = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvn 0.6 0 0.8\n\
                   f 1//1 2//1 3//1\nf 1//1 3//1 4//1\n";
    let path = dir.path().join("leaning.obj");
    std::fs::write(&path, with_vn).expect("write");
    let mesh = ModelMesh::load(&path).expect("load");
    assert!(
        mesh.normals
            .iter()
            .all(|n| (*n - DVec3::new(0.6, 0.0, 0.8)).length() < 1e-6)
    );
    // Without `vn`: the face normal, +z for counter-clockwise faces.
    let plain = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n";
    let path = dir.path().join("plain.obj");
    std::fs::write(&path, plain).expect("write");
    let model = ModelScene::for_model(&path, 100, 100).expect("load");
    assert!(model.mesh.normals.iter().all(|n| *n == DVec3::Z));
    // No uvs: the model is lit (Lambert), not a flat silhouette.
    let scene = Scene::Model(model);
    assert_eq!(scene.settings().shading, Shading::Lambert);
    let f = draw(&scene);
    let greys: std::collections::BTreeSet<u8> = (0..f.color.len())
        .filter(|&i| f.triangle[i] != NO_TRIANGLE)
        .map(|i| f.color[i][0])
        .collect();
    // Seen from the course's view the eye is behind the +z-facing square: the view-space
    // normal's z is the eye direction's z, negative, so only the ambient light is left.
    let (eye, _) = ModelView::Course.eye_direction();
    let k = f64::from(AMBIENT) + (1.0 - f64::from(AMBIENT)) * eye.z.max(0.0);
    assert_eq!(greys.into_iter().collect::<Vec<_>>(), vec![unorm8(k)]);
}

#[test]
fn models_are_framed_from_the_courses_view_and_the_named_views() {
    // GAMES101 assignment 3 turns its models by 140 degrees about y and looks from +z: the
    // eye sits at -z (and -x) of the model, where spot's face is.
    let (eye, up) = ModelView::Course.eye_direction();
    assert!(eye.z < -0.6 && eye.x < -0.5 && eye.y > 0.0, "{eye}");
    assert!((eye.length() - 1.0).abs() < 1e-12 && up == DVec3::Y);
    for v in ModelView::ALL {
        let (e, u) = v.eye_direction();
        assert!((e.length() - 1.0).abs() < 1e-12, "{v:?}");
        assert!(e.cross(u).length() > 0.5, "{v:?}: up parallel to the view");
    }
}

#[test]
fn the_apps_view_buttons_frame_the_model_from_each_side_and_home_goes_back() {
    use barylab::app::document::state::{AppState, StateCommand};
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/models");
    let model = ModelScene::for_model(&dir.join("torus.obj"), 160, 120).expect("torus");
    let (centre, _) = model.mesh.bounding_sphere();
    let mut state = AppState {
        scene: Scene::Model(model),
        ..AppState::default()
    };
    let eye = |s: &AppState| match &s.scene {
        Scene::Model(m) => (m.camera().eye - centre).normalize(),
        _ => panic!("a model scene"),
    };
    let course = eye(&state);
    for view in ModelView::ALL {
        state.apply(StateCommand::ModelView(view)).expect("view");
        let (expected, _) = view.eye_direction();
        assert!((eye(&state) - expected).length() < 1e-9, "{view:?}");
        // The model stays framed: it draws, touching no border.
        let f = draw(&state.scene);
        assert!(f.triangle.iter().any(|&t| t != NO_TRIANGLE), "{view:?}");
        assert!(
            (0..f.width).all(|x| !f.covered(x, 0) && !f.covered(x, f.height - 1)),
            "{view:?}"
        );
    }
    state.apply(StateCommand::ResetCamera).expect("home");
    assert!((eye(&state) - course).length() < 1e-12);
}
