//! The tie rule as a teaching choice: llvmpipe's (the default, left and bottom edges in image
//! rows) and the top-left rule of Direct3D and Vulkan (left and top edges, y down). Both give
//! every centre on a shared edge to exactly one triangle; they differ only on such centres;
//! the top-left rule is llvmpipe's seen upside down. Scene files, the command line and the
//! probe name the rule; `compare` names a student image that used the other one.

use std::process::Command;

use barylab::gpu::check::tie_lattice;

mod common;
use barylab::raster::project::SUBPIXEL;
use barylab::raster::render::prepare_triangle_with;
use barylab::raster::setup::{TieRule, TriangleSetup, sample_point};
use barylab::raster::{BuiltinTexture, ClipMesh, NO_TRIANGLE, RenderSettings, Texture, render};
use barylab::scene::Scene;
use common::lattice_scene;

fn owners(mesh: &ClipMesh, settings: &RenderSettings, rule: TieRule) -> Vec<u32> {
    let s = RenderSettings {
        tie_rule: rule,
        ..*settings
    };
    render(mesh, &Texture::builtin(BuiltinTexture::Checker), &s)
        .expect("render")
        .frame
        .triangle
}

/// What a rule's owner image comes to: pixels covered, and the sum over covered pixels of
/// `(triangle + 1) * (pixel index + 1)` (changes when any pixel changes owner).
fn tally(owners: &[u32]) -> (usize, u64) {
    let covered: Vec<_> = owners
        .iter()
        .enumerate()
        .filter(|(_, t)| **t != NO_TRIANGLE)
        .collect();
    let sum = covered
        .iter()
        .map(|&(k, &t)| (u64::from(t) + 1) * (k as u64 + 1))
        .sum();
    (covered.len(), sum)
}

/// The tie lattice's owners under each rule (`tally`), recorded from the renderer whose
/// rules the tests below check (every interior centre once, top-left = llvmpipe upside down)
/// and tests/llvmpipe.rs compares with Mesa; the default render is llvmpipe's.
const LLVMPIPE_TALLY: (usize, u64) = (1120, 57429050);
const TOP_LEFT_TALLY: (usize, u64) = (1120, 54987364);

#[test]
fn the_default_rule_is_llvmpipe_and_unchanged() {
    let (mesh, settings) = tie_lattice();
    assert_eq!(settings.tie_rule, TieRule::Llvmpipe);
    assert_eq!(RenderSettings::default().tie_rule, TieRule::Llvmpipe);
    let texture = Texture::builtin(BuiltinTexture::Checker);
    let default = render(&mesh, &texture, &settings).expect("render");
    assert_eq!(tally(&default.frame.triangle), LLVMPIPE_TALLY);
    assert_eq!(
        tally(&owners(&mesh, &settings, TieRule::TopLeft)),
        TOP_LEFT_TALLY
    );
}

/// A centre the mesh surrounds: each point a quarter pixel away from it in x and y (diagonals
/// included) lies inside or on some triangle.
fn surrounded(setups: &[&TriangleSetup], p: glam::I64Vec2) -> bool {
    let q = SUBPIXEL / 4;
    [-q, 0, q].iter().all(|&dx| {
        [-q, 0, q].iter().all(|&dy| {
            let o = p + glam::I64Vec2::new(dx, dy);
            setups
                .iter()
                .any(|s| s.edge_values(o).iter().all(|&v| v >= 0))
        })
    })
}

/// Under each rule every lattice centre inside the mesh (the interior edges and vertices
/// included) is covered exactly once, and none outside it; the two rules differ only at
/// centres exactly on an edge.
#[test]
fn both_rules_cover_shared_edges_exactly_once() {
    let (mesh, settings) = tie_lattice();
    let viewport = settings.viewport();
    for rule in [TieRule::Llvmpipe, TieRule::TopLeft] {
        let prepared: Vec<_> = (0..mesh.triangles.len() as u32)
            .map(|i| prepare_triangle_with(&mesh, i, viewport, rule))
            .collect();
        let setups: Vec<&TriangleSetup> = prepared.iter().flat_map(|t| &t.setups).collect();
        let mut interior_ties = 0;
        for y in 0..settings.height {
            for x in 0..settings.width {
                let p = sample_point(x, y);
                let mut covering = 0;
                let mut on_edge = false;
                for s in &setups {
                    let e = s.edge_values(p);
                    if e.iter().all(|&v| v >= 0) && e.contains(&0) {
                        on_edge = true;
                    }
                    covering += usize::from(s.covers(&e));
                }
                if surrounded(&setups, p) {
                    assert_eq!(covering, 1, "{rule:?}: ({x}, {y}) covered {covering} times");
                    interior_ties += usize::from(on_edge);
                } else {
                    assert!(
                        covering <= 1,
                        "{rule:?}: ({x}, {y}) covered {covering} times"
                    );
                }
            }
        }
        assert!(
            interior_ties > 200,
            "{rule:?}: only {interior_ties} interior centres on edges"
        );
    }
    let (lp, tl) = (
        owners(&mesh, &settings, TieRule::Llvmpipe),
        owners(&mesh, &settings, TieRule::TopLeft),
    );
    let differ = lp.iter().zip(&tl).filter(|(a, b)| a != b).count();
    assert!(differ > 100, "the rules differ on {differ} pixels");
    // Away from the lattice's outer border the two cover the same pixels (only owners change).
    let covered = |o: &[u32]| o.iter().filter(|&&t| t != NO_TRIANGLE).count();
    assert!(covered(&lp).abs_diff(covered(&tl)) < differ);
}

/// The top-left rule is llvmpipe's upside down: drawing the mesh mirrored in y under one rule
/// and flipping the image back gives the other rule's owners.
#[test]
fn top_left_is_llvmpipe_upside_down() {
    let (mesh, settings) = tie_lattice();
    let mut mirrored = mesh.clone();
    for v in &mut mirrored.vertices {
        v.clip.y = -v.clip.y;
    }
    let (w, h) = (settings.width as usize, settings.height as usize);
    let flip =
        |o: Vec<u32>| -> Vec<u32> { (0..w * h).map(|k| o[(h - 1 - k / w) * w + k % w]).collect() };
    assert_eq!(
        flip(owners(&mirrored, &settings, TieRule::TopLeft)),
        owners(&mesh, &settings, TieRule::Llvmpipe)
    );
    assert_eq!(
        flip(owners(&mirrored, &settings, TieRule::Llvmpipe)),
        owners(&mesh, &settings, TieRule::TopLeft)
    );
}

#[test]
fn scene_files_choose_the_rule() {
    let top_left = Scene::from_json(&lattice_scene(", \"tie_rule\": \"top_left\""), "t.json")
        .expect("top_left scene");
    assert_eq!(top_left.settings().tie_rule, TieRule::TopLeft);
    assert!(top_left.to_json().contains("\"tie_rule\": \"top_left\""));
    let default = Scene::from_json(&lattice_scene(""), "d.json").expect("scene");
    assert_eq!(default.settings().tie_rule, TieRule::Llvmpipe);
    assert!(!default.to_json().contains("tie_rule"));
    let err = Scene::from_json(&lattice_scene(", \"tie_rule\": \"bottom_right\""), "b.json")
        .expect_err("unknown rule");
    assert!(err.to_string().contains("b.json"), "{err}");
    assert!(err.to_string().contains("tie_rule"), "{err}");
}

fn barylab(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args(args)
        .output()
        .expect("run barylab")
}

/// The command line's --tie-rule; the probe names the rule that decided a tie; compare names
/// a student image drawn under the other rule, and gives the tie as the reason.
#[test]
fn command_line_probe_and_compare_name_the_rule() {
    let dir = tempfile::tempdir().expect("tempdir");
    let scene = dir.path().join("lattice.json");
    std::fs::write(&scene, lattice_scene("")).expect("write");
    let scene = scene.to_str().expect("utf-8");
    let (mesh, settings) = tie_lattice();
    let (lp, tl) = (
        owners(&mesh, &settings, TieRule::Llvmpipe),
        owners(&mesh, &settings, TieRule::TopLeft),
    );
    let k = lp
        .iter()
        .zip(&tl)
        .position(|(a, b)| a != b)
        .expect("a tie pixel");
    let (x, y) = (k as u32 % settings.width, k as u32 / settings.width);
    let pixel = format!("{x},{y}");
    for (rule, words) in [("llvmpipe", "llvmpipe's"), ("top-left", "top-left")] {
        let out = barylab(&["probe", scene, "--pixel", &pixel, "--tie-rule", rule]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(
            text.contains(&format!("The tie rule ({words}")),
            "{rule}: {text}"
        );
    }
    // A student's image drawn under the top-left rule.
    let student = dir.path().join("top-left.png");
    let out = barylab(&[
        "render",
        scene,
        "--tie-rule",
        "top-left",
        "-o",
        student.to_str().expect("utf-8"),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let out = barylab(&["compare", scene, student.to_str().expect("utf-8"), "--json"]);
    assert_eq!(out.status.code(), Some(1));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(json["hypotheses"][0]["kind"], "other_tie_rule", "{json}");
    assert_eq!(json["hypotheses"][0]["differing"], 0, "{json}");
    assert!(
        json["looks_like"]
            .as_str()
            .is_some_and(|l| l.contains("other tie rule")),
        "{json}"
    );
    // And the same image against the scene told to use the top-left rule agrees.
    let out = barylab(&[
        "compare",
        scene,
        student.to_str().expect("utf-8"),
        "--tie-rule",
        "top_left",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
}
