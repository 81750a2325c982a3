//! Opening files in the app (issue 7), driven through egui_kittest: files dropped on the window,
//! typed into the File menu's path window, the recent list; bad files from `tests/data/` give a
//! banner naming the file and the problem and leave the scene exactly as it was; model scenes
//! orbit, pan, zoom and are hovered like the quad.

mod common;

use std::path::{Path, PathBuf};
use std::sync::Arc;

use barylab::app::document::state::StateCommand;
use barylab::app::{AppOptions, BaryApp};
use barylab::raster::Interpolation;
use barylab::scene::Scene;
use egui::Pos2;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use glam::DVec2;

const SIZE: egui::Vec2 = egui::vec2(1500.0, 950.0);

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn asset(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(name)
}

fn harness() -> Harness<'static, BaryApp> {
    common::app::harness(SIZE, AppOptions::default())
}

/// A file dropped on the window, as winit hands it to egui.
#[derive(Debug)]
struct Dropped(PathBuf);

impl egui::DroppedFile for Dropped {
    fn path(&self) -> &Path {
        &self.0
    }
    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

fn drop_file(h: &mut Harness<'_, BaryApp>, path: &Path) {
    h.input_mut()
        .dropped_files
        .push(Arc::new(Dropped(path.to_path_buf())));
    h.run();
}

fn colors(h: &Harness<'_, BaryApp>) -> Vec<[u8; 4]> {
    let out = h.state().canvas().output.as_ref().expect("rendered");
    out.renders[0].1.frame.color.clone()
}

fn banner(h: &Harness<'_, BaryApp>) -> String {
    h.state().banner().expect("a banner").join("\n")
}

/// Screen position (points) of the centre of rendered pixel `p` in view 0.
fn pixel_centre(h: &Harness<'_, BaryApp>, p: [u32; 2]) -> Pos2 {
    let view = h.state().canvas().views[0];
    view.transform
        .to_screen(DVec2::new(f64::from(p[0]) + 0.5, f64::from(p[1]) + 0.5))
}

#[test]
fn every_bad_file_gets_a_banner_naming_it_and_the_scene_stays() {
    let dir = tempfile::tempdir().expect("temp dir");
    let unknown = dir.path().join("notes.txt");
    std::fs::write(&unknown, "hello").expect("write");
    let cases: Vec<(PathBuf, &str)> = vec![
        (data("empty.obj"), "empty (0 bytes)"),
        (data("garbage.obj"), "not a readable text OBJ"),
        (data("out_of_range.obj"), "vertex index beyond"),
        (data("nan.obj"), "not a finite number"),
        (data("huge.obj"), "larger than"),
        (data("missing_texture.obj"), "nothere.png"),
        (data("broken_texture.obj"), "cannot decode texture"),
        (data("broken_image.png"), "cannot decode texture"),
        (data("empty.png"), "is empty"),
        (data("does-not-exist.obj"), "cannot read model"),
        (data("does-not-exist.json"), "cannot read scene"),
        (unknown.clone(), "unknown kind of file"),
    ];
    let mut h = harness();
    // Start from something that is not the default: a model with a photo-like texture.
    drop_file(&mut h, &data("textured.obj"));
    assert!(matches!(h.state().state().scene, Scene::Model(_)));
    for (path, needle) in cases {
        let scene = h.state().state().clone();
        let pixels = colors(&h);
        let renders = h.state().canvas().timing.renders;
        drop_file(&mut h, &path);
        let text = banner(&h);
        let name = path
            .file_name()
            .expect("name")
            .to_string_lossy()
            .to_string();
        assert!(text.contains(&name), "{name}: banner `{text}`");
        assert!(
            text.contains(needle),
            "{name}: banner `{text}` lacks `{needle}`"
        );
        assert!(text.contains("the scene is unchanged"), "{text}");
        assert_eq!(text.lines().count(), 1, "one line: {text}");
        assert_eq!(h.state().state(), &scene, "{name} changed the scene");
        assert_eq!(colors(&h), pixels, "{name} changed the picture");
        assert_eq!(
            h.state().canvas().timing.renders,
            renders,
            "{name} re-rendered"
        );
        // The banner is shown in the UI.
        assert!(
            h.query_by_label_contains(&name).is_some(),
            "{name} not on screen"
        );
    }
    // Bad files do not enter the recent list.
    assert_eq!(h.state().recent_files().len(), 1);
}

#[test]
fn notes_are_shown_and_the_file_opens() {
    let mut h = harness();
    drop_file(&mut h, &data("no_uv.obj"));
    let text = banner(&h);
    assert!(
        text.contains("opened") && text.contains("no_uv.obj"),
        "{text}"
    );
    assert!(
        text.contains("note: ") && text.contains("no texture coordinates"),
        "{text}"
    );
    assert!(matches!(h.state().state().scene, Scene::Model(_)));
    assert_eq!(
        h.state().state().options().shading,
        barylab::raster::Shading::Lambert
    );

    drop_file(&mut h, &data("missing_mtl.obj"));
    let text = banner(&h);
    assert!(text.contains("material library"), "{text}");

    // A huge image is downscaled, with a note.
    let dir = tempfile::tempdir().expect("temp dir");
    let big = dir.path().join("wide.png");
    image::RgbaImage::from_pixel(5000, 10, image::Rgba([9, 99, 199, 255]))
        .save(&big)
        .expect("write image");
    drop_file(&mut h, &big);
    let text = banner(&h);
    assert!(
        text.contains("wide.png is now the texture") && text.contains("4096x8"),
        "{text}"
    );
    assert!(!text.contains("no texture coordinates"), "{text}");
    // An image on a model without uvs: it is set, and the banner says it shows as one colour.
    drop_file(&mut h, &data("no_uv.obj"));
    drop_file(&mut h, &data("rgbw.png"));
    let text = banner(&h);
    assert!(
        text.contains("rgbw.png is now the texture") && text.contains("no texture coordinates"),
        "{text}"
    );
    assert_eq!(
        h.state().state().options().shading,
        barylab::raster::Shading::Lambert
    );
}

#[test]
fn an_image_becomes_the_texture_of_the_current_scene() {
    let mut h = harness();
    h.state_mut().push(StateCommand::SetShading(
        barylab::raster::Shading::Barycentric,
    ));
    h.run();
    let geometry_before = h.state().state().scene.to_mesh();
    let rgbw = data("rgbw.png");
    drop_file(&mut h, &rgbw);
    let state = h.state().state();
    assert_eq!(state.scene.texture_name(), rgbw.display().to_string());
    assert_eq!(
        state.options().shading,
        barylab::raster::Shading::Texture,
        "dropping an image shows it"
    );
    assert_eq!(state.scene.to_mesh(), geometry_before, "the quad stays");
    // The picture shows the image's four colours (nearest lookups of the 2x2 image).
    h.state_mut()
        .push(StateCommand::SetFilter(barylab::raster::Filter::Nearest));
    h.run();
    let px = colors(&h);
    for c in [
        [255, 0, 0, 255],
        [0, 255, 0, 255],
        [0, 0, 255, 255],
        [255, 255, 255, 255],
    ] {
        assert!(px.contains(&c), "colour {c:?} missing");
    }
    assert!(banner(&h).contains("rgbw.png is now the texture"));
}

#[test]
fn a_path_typed_in_the_file_menu_opens_and_joins_the_recent_list() {
    let mut h = harness();
    h.get_by_label("File").click();
    h.run();
    h.get_by_label("Type a path…").click();
    h.run();
    let torus = asset("assets/models/torus.obj");
    let field = h.get_by_role(egui::accesskit::Role::TextInput);
    field.focus();
    field.type_text(&torus.display().to_string());
    h.run();
    h.get_by_label("Open").click();
    h.run();
    let Scene::Model(m) = &h.state().state().scene else {
        panic!("not a model scene: {}", banner(&h));
    };
    assert_eq!(m.mesh.triangles.len(), 1024);
    assert_eq!(h.state().recent_files(), std::slice::from_ref(&torus));

    // Recent files: newest first, once each, and a missing one is shown disabled.
    let dir = tempfile::tempdir().expect("temp dir");
    let copy = dir.path().join("cube-copy.obj");
    std::fs::copy(asset("assets/models/cube.obj"), &copy).expect("copy");
    drop_file(&mut h, &copy);
    drop_file(&mut h, &torus);
    assert_eq!(h.state().recent_files(), [torus.clone(), copy.clone()]);
    std::fs::remove_file(&copy).expect("remove");
    h.get_by_label("File").click();
    h.run();
    let missing = h.get_by_label("cube-copy.obj (missing)");
    assert!(missing.accesskit_node().is_disabled());
    let present = h.get_by_label("torus.obj");
    assert!(!present.accesskit_node().is_disabled());
}

#[test]
fn recent_files_are_saved_and_restored() {
    use eframe::App as _;
    #[derive(Default)]
    struct Memory(std::collections::HashMap<String, String>);
    impl eframe::Storage for Memory {
        fn get_string(&self, key: &str) -> Option<String> {
            self.0.get(key).cloned()
        }
        fn set_string(&mut self, key: &str, value: String) {
            self.0.insert(key.to_string(), value);
        }
        fn remove_string(&mut self, key: &str) {
            self.0.remove(key);
        }
        fn flush(&mut self) {}
    }
    let options = || AppOptions {
        persist: true,
        ..AppOptions::default()
    };
    let mut app = BaryApp::new(None, options());
    for f in ["assets/models/cube.obj", "assets/models/sphere.obj"] {
        app.open_file(&asset(f));
    }
    let mut storage = Memory::default();
    app.save(&mut storage);
    let restored = BaryApp::new(Some(&storage), options());
    assert_eq!(
        restored.recent_files(),
        [
            asset("assets/models/sphere.obj"),
            asset("assets/models/cube.obj")
        ]
    );
}

fn model_harness() -> Harness<'static, BaryApp> {
    let opened = barylab::app::services::files::open(
        &asset("assets/models/torus.obj"),
        &Scene::default_scene(),
        barylab::i18n::Lang::En,
    )
    .expect("torus");
    let app = BaryApp::new(
        None,
        AppOptions {
            opened: Some(opened),
            ..AppOptions::default()
        },
    );
    common::app::harness_of(app, SIZE)
}

fn camera(h: &Harness<'_, BaryApp>) -> barylab::raster::camera::Camera {
    match &h.state().state().scene {
        Scene::Model(m) => m.camera(),
        _ => panic!("not a model scene"),
    }
}

#[test]
fn a_model_orbits_pans_zooms_and_resets() {
    let mut h = model_harness();
    let framing = camera(&h);
    let d0 = framing.eye.distance(framing.target);
    let view = h.state().canvas().views[0].rect;
    let start = view.center();

    // Drag right: the camera turns about the target at the same distance.
    h.drag_at(start);
    h.run();
    h.hover_at(start + egui::vec2(100.0, 0.0));
    h.run();
    h.drop_at(start + egui::vec2(100.0, 0.0));
    h.run();
    let c = camera(&h);
    assert_eq!(c.target, framing.target);
    assert!((c.eye.distance(c.target) - d0).abs() < 1e-9 * d0);
    let turned = (c.eye - c.target)
        .normalize()
        .angle_between((framing.eye - framing.target).normalize())
        .to_degrees();
    assert!(turned > 10.0, "turned {turned}°");
    assert!(
        (c.eye.y - framing.eye.y).abs() < 1e-9,
        "a horizontal drag keeps the height"
    );
    assert_eq!(h.state().state().view.pinned, None, "a drag does not pin");

    // Scroll up: closer, by e^(-0.004 per point).
    h.hover_at(start);
    h.run();
    h.event(egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Point,
        delta: egui::vec2(0.0, 50.0),
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Wheel,
        modifiers: egui::Modifiers::NONE,
    });
    h.run();
    let z = camera(&h);
    let ratio = z.eye.distance(z.target) / d0;
    assert!((ratio - (-0.2f64).exp()).abs() < 1e-6, "zoom ratio {ratio}");

    // Shift+drag pans: target and eye move together, parallel to the screen.
    h.event(egui::Event::ModifiersChanged(egui::Modifiers::SHIFT));
    h.drag_at(start);
    h.run();
    h.hover_at(start + egui::vec2(0.0, 40.0));
    h.run();
    h.drop_at(start + egui::vec2(0.0, 40.0));
    h.event(egui::Event::ModifiersChanged(egui::Modifiers::NONE));
    h.run();
    let p = camera(&h);
    let moved = p.target - z.target;
    assert!(moved.length() > 0.0, "no pan");
    assert!(((p.eye - z.eye) - moved).length() < 1e-9);
    let forward = (z.target - z.eye).normalize();
    assert!(moved.dot(forward).abs() < 1e-9 * moved.length().max(1.0));

    // Reset view: the framing camera again (the button may be below the panel's fold).
    h.get_by_label("Reset view").scroll_to_me();
    h.run();
    h.get_by_label("Reset view").click();
    h.run();
    assert_eq!(camera(&h), framing);
}

#[test]
fn every_pixel_of_a_model_is_hovered_like_the_quad_and_agrees_with_the_probe() {
    let mut h = model_harness();
    let out = h.state().canvas().output.as_ref().expect("rendered");
    let size = out.size;
    let render = out.render(Interpolation::Perspective).expect("render");
    // Pixels covered by the model, a few spread over it.
    let covered: Vec<[u32; 2]> = (0..size[1])
        .step_by(37)
        .flat_map(|y| (0..size[0]).step_by(41).map(move |x| [x, y]))
        .filter(|&[x, y]| render.frame.covered(x, y))
        .collect();
    assert!(covered.len() > 20, "{} covered samples", covered.len());
    let scene = out.scene.clone();
    let texture = barylab::scene::Scene::load_texture(&scene, Path::new("")).expect("texture");
    let settings = scene.settings();
    for p in covered {
        h.hover_at(pixel_centre(&h, p));
        h.run();
        let report = h.state().hover_report().expect("hover report").clone();
        assert_eq!(report.pixel, p);
        let trace =
            barylab::probe::probe(&scene, &texture, &settings, (p[0], p[1])).expect("probe");
        assert_eq!(report.trace.written_by, trace.written_by, "pixel {p:?}");
        assert_eq!(report.trace.color, trace.color, "pixel {p:?}");
        assert!(report.triangle().is_some(), "pixel {p:?}: triangle marked");
    }
}
