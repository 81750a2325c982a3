//! The app's GPU view under MSAA, in the real window under Xvfb (Mesa's llvmpipe): a scene
//! with 4 samples at the GL's standard positions is drawn by the GL with those samples, and
//! the per-sample comparison the view shows agrees with barylab at every sample (coverage,
//! owning triangle, uv within 5e-5; the smooth centroid difference named). Skipped without
//! Xvfb, except under CI=true.

mod common;
use common::xvfb::{run_app, start_xvfb, xvfb_or_skip};

/// The default scene (a textured quad in perspective) at 160 x 120, 4 samples at the
/// standard positions, MSAA at `location`.
fn scene(location: &str) -> String {
    let text = barylab::lesson::builtin::scene("default").expect("built in");
    let mut json: serde_json::Value = serde_json::from_str(text).expect("json");
    json["width"] = 160.into();
    json["height"] = 120.into();
    json["samples"] = 4.into();
    json["location"] = location.into();
    json.to_string()
}

/// The "gpu view samples: ..." line the app prints for a --screenshot run.
fn samples_line(stdout: &str) -> Option<String> {
    stdout
        .lines()
        .rev()
        .find_map(|l| l.strip_prefix("gpu view samples: "))
        .map(str::to_string)
}

#[test]
fn the_gpu_view_draws_every_sample_and_agrees_with_barylab() {
    let Some(xvfb) = xvfb_or_skip("llvmpipe_gpu_view_samples") else {
        return;
    };
    let x = start_xvfb(&xvfb);
    let dir = tempfile::tempdir().expect("tempdir");
    for location in ["center", "centroid"] {
        let file = dir.path().join(format!("a2-{location}.json"));
        std::fs::write(&file, scene(location)).expect("scene written");
        let shot = dir.path().join(format!("{location}.png"));
        let (ok, out, err) = run_app(
            &x.display,
            &[
                "--fresh",
                "--screenshot",
                shot.to_str().expect("utf-8"),
                "--window",
                "1280x800",
                "--compare",
                "gpu",
                file.to_str().expect("utf-8"),
            ],
            &[],
        );
        assert!(ok, "{location}: {err}");
        let line = samples_line(&out)
            .unwrap_or_else(|| panic!("{location}: no per-sample summary in {out:?} ({err})"));
        assert!(
            line.contains(
                "Every sample (4 per pixel, 76800 in all): coverage and owning triangle identical."
            ),
            "{location}: {line}"
        );
        // uv within the tolerance: the printed maximum is at most 5e-5.
        let max: f64 = line
            .split("within ")
            .nth(1)
            .and_then(|s| s.split_whitespace().next())
            .and_then(|s| s.parse().ok())
            .unwrap_or_else(|| panic!("{location}: no uv maximum in {line}"));
        assert!(max <= 5e-5, "{location}: {line}");
        // smooth at the centroid: the GL's N(p) / D(c) is named, not counted.
        assert_eq!(
            line.contains("N(p) / D(c)"),
            location == "centroid",
            "{location}: {line}"
        );
        assert!(
            line.contains("Resolve: the GL's within"),
            "{location}: {line}"
        );
    }
}
