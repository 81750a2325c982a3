//! The app driven through egui_kittest: real clicks, hovers, drags and keys on the real UI.

mod common;

use barylab::app::document::state::StateCommand;
use barylab::app::{AppOptions, BaryApp};
use barylab::figure::vertices_on_screen;
use barylab::probe::format::fmt_number;
use barylab::raster::{BuiltinTexture, Interpolation, RenderSettings, Texture};
use barylab::scene::Scene;
use egui::Pos2;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use glam::DVec2;

/// Window size of the tests, in points.
const SIZE: egui::Vec2 = egui::vec2(1500.0, 950.0);

fn harness() -> Harness<'static, BaryApp> {
    common::app::harness(SIZE, AppOptions::default())
}

/// Screen position (points) of the centre of rendered pixel `p` in view 0.
fn pixel_centre(h: &Harness<'_, BaryApp>, p: [u32; 2]) -> Pos2 {
    let view = h.state().canvas().views[0];
    view.transform
        .to_screen(DVec2::new(f64::from(p[0]) + 0.5, f64::from(p[1]) + 0.5))
}

/// Window positions of the mesh vertices in the rendered canvas.
fn vertex_windows(h: &Harness<'_, BaryApp>) -> Vec<Option<DVec2>> {
    let out = h.state().canvas().output.as_ref().expect("rendered");
    vertices_on_screen(&h.state().state().scene, out.viewport())
        .iter()
        .map(|v| v.window)
        .collect()
}

fn colors(h: &Harness<'_, BaryApp>) -> Vec<[u8; 4]> {
    let out = h.state().canvas().output.as_ref().expect("rendered");
    out.renders[0].1.frame.color.clone()
}

#[test]
fn switching_the_mode_changes_the_rendered_canvas() {
    let mut h = harness();
    assert_eq!(h.state().state().options().mode, Interpolation::Perspective);
    let perspective = colors(&h);
    let uploads = h.state().canvas().timing.uploads;
    h.get_by_label("Affine").click();
    h.run();
    assert_eq!(h.state().state().options().mode, Interpolation::Affine);
    let affine = colors(&h);
    assert_eq!(affine.len(), perspective.len());
    let differing = affine
        .iter()
        .zip(&perspective)
        .filter(|(a, b)| a != b)
        .count();
    assert!(
        differing > affine.len() / 20,
        "only {differing} pixels changed"
    );
    assert!(
        h.state().canvas().timing.uploads > uploads,
        "texture not re-uploaded"
    );
    // The key P flips back, to the very same image.
    h.key_press(egui::Key::P);
    h.run();
    assert_eq!(h.state().state().options().mode, Interpolation::Perspective);
    assert!(colors(&h) == perspective);
}

#[test]
fn nothing_is_rendered_again_when_nothing_changed() {
    let mut h = harness();
    let renders = h.state().canvas().timing.renders;
    let uploads = h.state().canvas().timing.uploads;
    h.hover_at(pixel_centre(&h, [100, 100]));
    h.run();
    h.hover_at(pixel_centre(&h, [120, 110]));
    h.run();
    assert_eq!(h.state().canvas().timing.renders, renders);
    assert_eq!(h.state().canvas().timing.uploads, uploads);
}

/// The probe's trace of `pixel` of what the app rendered, computed here independently of the
/// app's inspector.
fn probe_of(h: &Harness<'_, BaryApp>, pixel: [u32; 2]) -> barylab::probe::PixelTrace {
    let out = h.state().canvas().output.as_ref().expect("rendered");
    let texture = Texture::builtin(BuiltinTexture::UvGrid);
    let settings = RenderSettings {
        mode: h.state().state().options().mode,
        ..out.scene.settings()
    };
    barylab::probe::probe(&out.scene, &texture, &settings, (pixel[0], pixel[1])).expect("probe")
}

fn shows(h: &Harness<'_, BaryApp>, text: &str) -> bool {
    h.query_all_by_label(text).next().is_some()
}

#[test]
fn hovering_a_pixel_shows_the_probes_weights_in_the_inspector() {
    let mut h = harness();
    let out = h.state().canvas().output.as_ref().expect("rendered");
    let [w, hgt] = out.size;
    let p = [w / 2, hgt * 2 / 3];
    let trace = probe_of(&h, p);
    assert_eq!(trace.written_by, Some(0), "a covered pixel of triangle ABC");
    let d = trace.detail.expect("detail");
    let persp = d.perspective.expect("1/w correction");
    h.hover_at(pixel_centre(&h, p));
    h.run();
    assert_eq!(h.state().canvas().hover, Some(p));
    assert!(shows(&h, &format!("Pixel ({}, {})", p[0], p[1])));
    for k in 0..3 {
        let r = fmt_number(d.screen.rasterizer[k]);
        let a = fmt_number(persp.correction.weights[k]);
        assert!(shows(&h, &r), "screen weight {r} not shown");
        assert!(shows(&h, &a), "corrected weight {a} not shown");
    }
    let w_p = format!("W_P = {}", fmt_number(persp.correction.w_p));
    assert!(shows(&h, &w_p), "{w_p} not shown");
    // The same pixel in the framebuffer: the probe explains what was drawn.
    let render = out_render(&h);
    let i = render.frame.index(p[0], p[1]);
    assert_eq!(render.frame.color[i], trace.color);
}

fn out_render(h: &Harness<'_, BaryApp>) -> barylab::raster::render::Render {
    let out = h.state().canvas().output.as_ref().expect("rendered");
    out.render(h.state().state().options().mode)
        .expect("render")
        .clone()
}

#[test]
fn hovering_outside_the_quad_still_shows_weights_and_why() {
    let mut h = harness();
    // The top-left pixel is background in the default scene.
    let p = [2, 2];
    let trace = probe_of(&h, p);
    assert_eq!(trace.written_by, None);
    let d = trace.detail.expect("nearest triangle");
    let negative = d
        .screen
        .rasterizer
        .iter()
        .find(|w| **w < 0.0)
        .copied()
        .expect("a negative weight outside");
    h.hover_at(pixel_centre(&h, p));
    h.run();
    assert!(shows(&h, "not covered"));
    assert!(
        h.query_all_by_label_contains("outside edge")
            .next()
            .is_some()
    );
    assert!(shows(&h, &fmt_number(negative)));
}

/// Drags from `start` by `delta` points in four moves, as a hand would.
fn drag_by(h: &mut Harness<'_, BaryApp>, start: Pos2, delta: egui::Vec2) {
    h.hover_at(start);
    h.run();
    h.drag_at(start);
    h.run();
    for k in 1..=4 {
        h.hover_at(start + delta * (k as f32 / 4.0));
        h.run();
    }
    h.drop_at(start + delta);
    h.run();
}

#[test]
fn dragging_handle_a_moves_vertex_a() {
    let mut h = harness();
    let before = vertex_windows(&h);
    let a = before[0].expect("A on screen");
    let view = h.state().canvas().views[0];
    let start = view.transform.to_screen(a);
    let delta = egui::vec2(60.0, -40.0);
    drag_by(&mut h, start, delta);
    let after = vertex_windows(&h);
    let moved = after[0].expect("A on screen");
    let expected =
        a + DVec2::new(f64::from(delta.x), f64::from(delta.y)) / f64::from(view.transform.scale);
    assert!(
        (moved - expected).length() < 0.01,
        "A at {moved}, expected {expected}"
    );
    for k in 1..4 {
        let (x, y) = (after[k].expect("on screen"), before[k].expect("on screen"));
        assert!((x - y).length() < 1e-9, "vertex {k} moved");
    }
    // Its depth did not change: same w.
    let out = h.state().canvas().output.as_ref().expect("rendered");
    let w_after = vertices_on_screen(&h.state().state().scene, out.viewport())[0].w();
    let w_before = vertices_on_screen(&Scene::default_scene(), out.viewport())[0].w();
    assert!((w_after - w_before).abs() < 1e-9);
}

/// A corner far off the picture (the receding floor's near corners) has its handle on the
/// image's edge; dragging that handle moves the corner by the pointer's motion.
#[test]
fn a_corner_off_the_image_is_dragged_by_its_handle_on_the_edge() {
    let path = std::path::PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/assets/scenes/far-checker.json"
    ));
    let scene = Scene::load(&path).expect("far-checker loads");
    let mut h = common::app::harness(
        SIZE,
        AppOptions {
            scene: Some((scene, path)),
            ..AppOptions::default()
        },
    );
    h.run();
    let before = vertex_windows(&h);
    let a = before[0].expect("A in front of the camera");
    let out = h.state().canvas().output.as_ref().expect("rendered");
    let size = DVec2::new(f64::from(out.size[0]), f64::from(out.size[1]));
    assert!(
        a.x < 0.0 && a.y > size.y,
        "A lies off the image's bottom left: {a}"
    );
    // Its handle: the image's bottom-left corner.
    let view = h.state().canvas().views[0];
    let start = view.transform.to_screen(DVec2::new(0.0, size.y));
    let delta = egui::vec2(30.0, -20.0);
    drag_by(&mut h, start, delta);
    let moved = vertex_windows(&h)[0].expect("A in front of the camera");
    let expected =
        a + DVec2::new(f64::from(delta.x), f64::from(delta.y)) / f64::from(view.transform.scale);
    assert!(
        (moved - expected).length() < 0.02,
        "A at {moved}, expected {expected}"
    );
}

#[test]
fn pressing_reset_restores_the_default_scene() {
    let mut h = harness();
    h.state_mut().push(StateCommand::Preset(
        barylab::app::document::presets::Preset::GrazingWall,
    ));
    h.run();
    assert_ne!(h.state().state().scene, Scene::default_scene());
    h.get_by_label("Reset scene").click();
    h.run();
    assert_eq!(h.state().state().scene, Scene::default_scene());
}

#[test]
fn clicking_pins_a_pixel_and_arrow_keys_move_it() {
    let mut h = harness();
    let out = h.state().canvas().output.as_ref().expect("rendered");
    let p = [out.size[0] / 2, out.size[1] / 2];
    let pos = pixel_centre(&h, p);
    h.hover_at(pos);
    h.run();
    h.event(egui::Event::PointerButton {
        pos,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: egui::Modifiers::NONE,
    });
    h.event(egui::Event::PointerButton {
        pos,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: egui::Modifiers::NONE,
    });
    h.run();
    assert_eq!(h.state().state().view.pinned, Some(p));
    h.key_press(egui::Key::ArrowRight);
    h.run();
    h.key_press(egui::Key::ArrowUp);
    h.run();
    assert_eq!(h.state().state().view.pinned, Some([p[0] + 1, p[1] - 1]));
    h.key_press(egui::Key::Escape);
    h.run();
    assert_eq!(h.state().state().view.pinned, None);
}

/// An in-memory eframe storage.
#[derive(Default)]
struct MemoryStorage(std::collections::HashMap<String, String>);

impl eframe::Storage for MemoryStorage {
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

#[test]
fn state_is_saved_on_exit_and_restored_on_start() {
    use eframe::App as _;
    let mut h = harness();
    h.get_by_label("Affine").click();
    h.run();
    h.get_by_label("Wipe").click();
    h.run();
    h.state_mut().push(StateCommand::Preset(
        barylab::app::document::presets::Preset::FarCorner,
    ));
    h.run();
    let before = h.state().state().clone();
    let mut storage = MemoryStorage::default();
    // The app saves through eframe's storage (only when persisting).
    let mut app = BaryApp::new(
        None,
        AppOptions {
            persist: true,
            ..AppOptions::default()
        },
    );
    for c in [
        StateCommand::SetMode(Interpolation::Affine),
        StateCommand::SetCompare(barylab::figure::Compare::Wipe),
        StateCommand::Preset(barylab::app::document::presets::Preset::FarCorner),
    ] {
        app.push(c);
    }
    let mut h2 = common::app::harness_of(app, SIZE);
    assert_eq!(h2.state().state(), &before);
    h2.state_mut().save(&mut storage);
    let restored = BaryApp::new(
        Some(&storage),
        AppOptions {
            persist: true,
            ..AppOptions::default()
        },
    );
    assert_eq!(restored.state(), &before);
    // Without persistence nothing is read.
    let fresh = BaryApp::new(Some(&storage), AppOptions::default());
    assert_eq!(fresh.state().scene, Scene::default_scene());
}

/// The real app keeps its state in a file of its own, written atomically (`files::write_bytes`,
/// whose failure cases tests/robust.rs covers): it is what the app restores first, a save
/// leaves no temporary file behind, and a damaged file falls back to eframe's storage.
#[test]
fn state_file_is_written_atomically_and_read_first() {
    use eframe::App as _;
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("data").join("barylab-state.json");
    let persist = || AppOptions {
        persist: true,
        ..AppOptions::default()
    };
    let mut app = BaryApp::new_with_state_file(None, persist(), Some(path.clone()));
    app.push(StateCommand::Preset(
        barylab::app::document::presets::Preset::FarCorner,
    ));
    let mut h = common::app::harness_of(app, SIZE);
    let saved = h.state().state().clone();
    assert_ne!(saved.scene, Scene::default_scene());
    let mut storage = MemoryStorage::default();
    h.state_mut().save(&mut storage);
    assert!(path.is_file(), "the state file was not written");
    let names: Vec<_> = std::fs::read_dir(path.parent().expect("folder"))
        .expect("folder")
        .map(|e| e.expect("entry").file_name())
        .collect();
    assert_eq!(
        names,
        ["barylab-state.json"],
        "a temporary file was left behind"
    );
    // Restored from the file alone, with an empty eframe storage.
    let restored = BaryApp::new_with_state_file(
        Some(&MemoryStorage::default()),
        persist(),
        Some(path.clone()),
    );
    assert_eq!(restored.state(), &saved);
    // A damaged file (a crash of some other writer, a full disk) is not trusted: eframe's copy
    // of the same save restores the scene.
    std::fs::write(&path, b"{\"scene_json\": \"{\\\"wid").expect("damage");
    let fallback = BaryApp::new_with_state_file(Some(&storage), persist(), Some(path.clone()));
    assert_eq!(fallback.state(), &saved);
    // Without persistence the file is neither read nor written.
    let fresh = BaryApp::new_with_state_file(None, AppOptions::default(), Some(path));
    assert_eq!(fresh.state().scene, Scene::default_scene());
}

#[test]
fn scrolling_on_a_handle_pushes_the_corner_away_along_its_ray() {
    let mut h = harness();
    let out = h.state().canvas().output.as_ref().expect("rendered");
    let before = vertices_on_screen(&h.state().state().scene, out.viewport());
    let c = before[2].window.expect("C on screen");
    let pos = h.state().canvas().views[0].transform.to_screen(c);
    h.hover_at(pos);
    h.run();
    h.event(egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Point,
        delta: egui::vec2(0.0, 60.0),
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Wheel,
        modifiers: egui::Modifiers::NONE,
    });
    h.run();
    let out = h.state().canvas().output.as_ref().expect("rendered");
    let after = vertices_on_screen(&h.state().state().scene, out.viewport());
    assert!(
        after[2].w() > before[2].w() * 1.1,
        "w {} -> {}",
        before[2].w(),
        after[2].w()
    );
    let moved = after[2].window.expect("C on screen");
    assert!(
        (moved - c).length() < 1e-6,
        "C moved on screen: {c} -> {moved}"
    );
    // The affine image only depends on screen positions: it is the same; the perspective
    // one changed.
    assert_eq!(after[0].w(), before[0].w());
}

#[test]
fn the_rasterizer_can_be_chosen_and_covers_the_same_pixels() {
    use barylab::raster::render::Rasterizer;
    let mut h = harness();
    let covered = |h: &Harness<'_, BaryApp>| {
        let out = h.state().canvas().output.as_ref().expect("rendered");
        let f = &out.renders[0].1.frame;
        (0..f.height)
            .flat_map(|y| (0..f.width).map(move |x| (x, y)))
            .map(|(x, y)| f.covered(x, y))
            .collect::<Vec<bool>>()
    };
    let (edge_colors, edge_covered) = (colors(&h), covered(&h));
    assert!(edge_covered.iter().filter(|&&c| c).count() > edge_covered.len() / 10);
    let renders = h.state().canvas().timing.renders;
    h.get_by_label("Scanline").click();
    h.run();
    assert_eq!(h.state().state().view.rasterizer, Rasterizer::Scanline);
    assert!(
        h.state().canvas().timing.renders > renders,
        "not rendered again"
    );
    assert!(covered(&h) == edge_covered, "coverage differs");
    let scan_colors = colors(&h);
    let differing = scan_colors
        .iter()
        .zip(&edge_colors)
        .filter(|(a, b)| a != b)
        .count();
    assert!(
        differing * 200 <= edge_colors.len(),
        "{differing} colours differ"
    );
    assert!(h.query_by_label_contains("render (scanline)").is_some());
    h.get_by_label("Edge functions").click();
    h.run();
    assert!(colors(&h) == edge_colors);
}

#[test]
fn hovering_reuses_one_prober_per_render() {
    let mut h = harness();
    h.hover_at(pixel_centre(&h, [300, 300]));
    h.run();
    let built = h.state().probers_built();
    assert!(built >= 1);
    for p in [[310, 305], [320, 310], [200, 250]] {
        h.hover_at(pixel_centre(&h, p));
        h.run();
    }
    assert_eq!(
        h.state().probers_built(),
        built,
        "a new prober for the same render"
    );
    // The inspector still follows the pointer, with the probe's numbers.
    let trace = probe_of(&h, [200, 250]);
    let shown = h.state().hover_report().map(|r| r.trace.pixel);
    assert_eq!(shown, Some(trace.pixel));
    // Another mode is another render: one more prober.
    h.key_press(egui::Key::P);
    h.run();
    assert_eq!(h.state().probers_built(), built + 1);
}
