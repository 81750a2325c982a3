//! `barylab compare` against a multisampled reference, two more whole-image verdicts:
//! supersampling against an MSAA reference (and MSAA against a supersampled one), and a wrong
//! sample pattern (the 2x2 grid against the standard positions, and back). The images are
//! written here by barylab itself at the other setting (what a student's renderer with that
//! mistake produces), and the verdict is named in both languages.

use std::path::Path;
use std::process::{Command, Output};

const SIZE: &str = "96x72";

fn barylab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_barylab"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(args)
        .output()
        .expect("run barylab")
}

/// Renders `scene` with `settings` into `out` (the "student's" image).
fn render(scene: &str, settings: &[&str], out: &Path) {
    let o = out.to_str().expect("utf-8");
    let r = barylab(&[&["render", scene, "--size", SIZE, "-o", o], settings].concat());
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
}

/// Compares `image` with `scene` under the reference `settings`: the JSON verdict's kind
/// and how many pixels it leaves differing, and the text report in Chinese.
fn compare(scene: &str, image: &Path, settings: &[&str]) -> (String, u64, String) {
    let i = image.to_str().expect("utf-8");
    let base = [&["compare", scene, i, "--size", SIZE], settings].concat();
    let json = barylab(&[&base[..], &["--json"]].concat());
    assert_eq!(json.status.code(), Some(1), "the images differ");
    let report: serde_json::Value = serde_json::from_slice(&json.stdout).expect("JSON");
    let kind = report["looks_like_kind"]
        .as_str()
        .unwrap_or("none")
        .to_string();
    let text = report["looks_like"].as_str().unwrap_or("").to_string();
    let left: u64 = text
        .rsplit("leaves ")
        .next()
        .and_then(|t| t.split(' ').next())
        .and_then(|n| n.parse().ok())
        .expect("the verdict says how many pixels it leaves");
    let zh = barylab(&[&base[..], &["--lang", "zh"]].concat());
    (kind, left, String::from_utf8_lossy(&zh.stdout).into_owned())
}

fn temp(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("barylab-verdicts-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("folder");
    dir.join(name)
}

#[test]
fn supersampling_against_msaa_and_the_reverse() {
    // A textured scene: supersampling samples the texture at every sample, MSAA once per
    // pixel, so the two differ inside the triangles too, not only on edges.
    let scene = "assets/scenes/default.json";
    let ssaa = temp("ssaa.png");
    render(scene, &["--samples", "4", "--shading-rate", "ssaa"], &ssaa);
    let (kind, left, zh) = compare(scene, &ssaa, &["--samples", "4"]);
    assert_eq!((kind.as_str(), left), ("other_shading_rate", 0));
    assert!(zh.contains("超采样与多重采样抗锯齿之别"), "{zh}");
    let msaa = temp("msaa.png");
    render(scene, &["--samples", "4"], &msaa);
    let (kind, left, _) = compare(scene, &msaa, &["--samples", "4", "--shading-rate", "ssaa"]);
    assert_eq!((kind.as_str(), left), ("other_shading_rate", 0));
}

#[test]
fn a_grid_against_the_standard_pattern_and_the_reverse() {
    let scene = "assets/scenes/games101-a2.json";
    let grid = temp("grid.png");
    render(
        scene,
        &["--samples", "4", "--sample-pattern", "grid"],
        &grid,
    );
    let (kind, left, zh) = compare(scene, &grid, &["--samples", "4"]);
    assert_eq!((kind.as_str(), left), ("other_sample_pattern", 0));
    assert!(zh.contains("采样模式不对"), "{zh}");
    let standard = temp("standard.png");
    render(scene, &["--samples", "4"], &standard);
    let (kind, left, _) = compare(
        scene,
        &standard,
        &["--samples", "4", "--sample-pattern", "grid"],
    );
    assert_eq!((kind.as_str(), left), ("other_sample_pattern", 0));
}
