//! The app's GPU view and tie rule: without a glow context (egui_kittest) the view says why
//! and the canvas keeps working; the tie rule is chosen in the controls, saved in the scene
//! and named by the inspector; under Xvfb the real window draws every sample scene with
//! Mesa's llvmpipe and finds the same coverage as barylab.

use std::path::PathBuf;
use std::process::Command;

mod common;
use common::xvfb::{start_xvfb, xvfb_or_skip};

use barylab::app::document::state::StateCommand as AppCmd;
use barylab::app::panels::gpu_view::Unavailable;
use barylab::app::{AppOptions, BaryApp};
use barylab::figure::Compare;
use barylab::gpu::check::tie_lattice;
use barylab::raster::setup::TieRule;
use barylab::raster::{BuiltinTexture, RenderSettings, Texture, render};
use barylab::scene::Scene;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

const SIZE: egui::Vec2 = egui::vec2(1280.0, 1024.0);

fn harness(options: AppOptions) -> Harness<'static, BaryApp> {
    common::app::harness(SIZE, options)
}

#[test]
fn without_a_glow_context_the_gpu_view_says_why_and_the_canvas_keeps_working() {
    let mut h = harness(AppOptions::default());
    assert!(!h.state().state().view.gpu);
    h.get_by_label("GPU").click();
    h.run();
    assert!(h.state().state().view.gpu);
    assert_eq!(
        h.state().gpu_view().unavailable,
        Some(Unavailable::NoContext)
    );
    assert!(h.state().gpu_view().result.is_none());
    // The reason, in one line, where the summary would be.
    h.get_by_label(
        "GPU view unavailable: this window has no OpenGL context (another renderer, or a test \
         harness)",
    );
    for (label, compare, views) in [
        ("Side by side", Compare::SideBySide, 2),
        ("Wipe", Compare::Wipe, 1),
        ("Difference", Compare::Difference, 1),
        ("Single", Compare::Single, 1),
    ] {
        h.get_by_label(label).click();
        h.run();
        let app = h.state();
        assert_eq!(app.state().view.compare, compare);
        assert_eq!(app.canvas().views.len(), views, "{label}");
        let out = app.canvas().output.as_ref().expect("barylab still renders");
        // Only the scene's mode is rendered while the GPU view is on.
        assert_eq!(out.renders.len(), 1, "{label}");
        assert!(app.canvas().error.is_none());
    }
    // Off again: no reason left, and the mode comparison renders both modes again.
    h.get_by_label("GPU").click();
    h.get_by_label("Side by side").click();
    h.run();
    assert!(!h.state().state().view.gpu);
    assert_eq!(h.state().gpu_view().unavailable, None);
    assert!(h.query_by_label_contains("GPU view unavailable").is_none());
    let out = h.state().canvas().output.as_ref().expect("rendered");
    assert_eq!(out.renders.len(), 2);
}

/// The tie lattice (vertices on pixel centres: many centres exactly on shared edges) as a
/// clip-space scene.
fn lattice_scene() -> Scene {
    Scene::from_json(&common::lattice_scene(""), "lattice.json").expect("lattice scene")
}

/// A pixel whose owner differs between the two rules (a centre exactly on a shared edge).
fn tie_pixel() -> [u32; 2] {
    let (mesh, settings) = tie_lattice();
    let owners = |rule| {
        let s = RenderSettings {
            tie_rule: rule,
            ..settings
        };
        render(&mesh, &Texture::builtin(BuiltinTexture::Checker), &s)
            .expect("render")
            .frame
            .triangle
    };
    let (lp, tl) = (owners(TieRule::Llvmpipe), owners(TieRule::TopLeft));
    let k = lp
        .iter()
        .zip(&tl)
        .position(|(a, b)| a != b)
        .expect("a tie pixel") as u32;
    [k % settings.width, k / settings.width]
}

fn pinned_text(h: &Harness<'_, BaryApp>) -> String {
    h.state()
        .pin_report()
        .expect("pinned report")
        .document
        .to_text()
}

#[test]
fn the_tie_rule_is_chosen_in_the_controls_saved_in_the_scene_and_named_by_the_inspector() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut h = harness(AppOptions {
        scene: Some((lattice_scene(), dir.path().to_path_buf())),
        ..AppOptions::default()
    });
    assert_eq!(
        h.state().state().scene.settings().tie_rule,
        TieRule::Llvmpipe
    );
    let p = tie_pixel();
    h.state_mut().push(AppCmd::Pin(Some(p)));
    h.run();
    let text = pinned_text(&h);
    assert!(
        text.contains("The tie rule (llvmpipe's, as OpenGL on Mesa)"),
        "{text}"
    );
    h.get_by_label("top-left").click();
    h.run();
    let scene = &h.state().state().scene;
    assert_eq!(scene.settings().tie_rule, TieRule::TopLeft);
    assert!(scene.to_json().contains("\"tie_rule\": \"top_left\""));
    let text = pinned_text(&h);
    assert!(
        text.contains(
            "The tie rule (top-left, as Direct3D states it and most Vulkan drivers follow)"
        ),
        "{text}"
    );
    // A scene edit like any other: undo brings llvmpipe's rule back.
    h.state_mut().push(barylab::app::command::AppCommand::Undo);
    h.run();
    assert_eq!(
        h.state().state().scene.settings().tie_rule,
        TieRule::Llvmpipe
    );
    // Saved with the scene, and read back.
    let file = dir.path().join("saved.json");
    h.get_by_label("top-left").click();
    h.run();
    h.state_mut().save_scene(&file);
    let saved = std::fs::read_to_string(&file).expect("saved scene");
    let back = Scene::from_json(&saved, "saved.json").expect("scene");
    assert_eq!(back.settings().tie_rule, TieRule::TopLeft);
}

// The real window under Xvfb.

/// Runs the app; returns (success, stdout, stderr).
fn run_app(display: &str, args: &[&str]) -> (bool, String, String) {
    common::xvfb::run_app(display, args, &[])
}

/// The last "gpu view: coverage identical on N of M pixels; ..." line: (N, M, K).
fn summary(stdout: &str) -> Option<(usize, usize, u32)> {
    let line = stdout
        .lines()
        .rev()
        .find_map(|l| l.strip_prefix("gpu view: coverage identical on "))?;
    let words: Vec<&str> = line.split([' ', ';']).collect();
    Some((
        words.first()?.parse().ok()?,
        words.get(2)?.parse().ok()?,
        words.get(8)?.parse().ok()?,
    ))
}

#[test]
fn under_xvfb_the_gpu_view_shows_llvmpipe_agreeing_on_coverage_on_every_sample_scene() {
    let Some(xvfb) = xvfb_or_skip("gpu_view") else {
        return;
    };
    let x = start_xvfb(&xvfb);
    let dir = tempfile::tempdir().expect("tempdir");
    let mut scenes: Vec<PathBuf> = std::fs::read_dir("assets/scenes")
        .expect("assets/scenes")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    scenes.sort();
    assert!(scenes.len() >= 5, "{scenes:?}");
    for (k, scene) in scenes.iter().enumerate() {
        let shot = dir.path().join(format!("gpu-{k}.png"));
        let compare = ["gpu", "gpu-difference", "gpu-wipe"][k % 3];
        let (ok, out, err) = run_app(
            &x.display,
            &[
                "--fresh",
                "--screenshot",
                shot.to_str().expect("utf-8"),
                "--window",
                "1280x800",
                "--compare",
                compare,
                scene.to_str().expect("utf-8"),
            ],
        );
        assert!(ok, "{}: {err}", scene.display());
        let (same, total, max) = summary(&out)
            .unwrap_or_else(|| panic!("{}: no GPU summary in {out:?} ({err})", scene.display()));
        assert!(total > 0);
        assert_eq!(
            same,
            total,
            "{}: coverage differs from llvmpipe: {out}",
            scene.display()
        );
        // Colours are bounded only for the default scene (bilinear): with nearest filtering a
        // sample exactly on a texel boundary may take either texel (clip-two-triangles.json
        // has one such pixel, 195 levels apart, as `barylab gpu-check` reports too).
        if scene.ends_with("default.json") {
            assert!(max <= 2, "{}: {out}", scene.display());
        }
        let img = image::open(&shot).expect("screenshot").to_rgba8();
        assert_eq!(img.dimensions(), (1280, 800), "{}", scene.display());
    }
}

#[test]
fn the_compare_flag_names_its_views_when_given_a_bad_one() {
    let out = Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args([
            "--compare",
            "gpu-sideways",
            "--screenshot",
            "/nonexistent/x.png",
        ])
        .output()
        .expect("run barylab");
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("unknown view 'gpu-sideways'"), "{err}");
    for view in ["single", "side", "wipe", "difference", "gpu", "gpu-wipe"] {
        assert!(err.contains(view), "{view}: {err}");
    }
}
