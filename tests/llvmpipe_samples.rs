//! Multisampling against llvmpipe: random scenes drawn with 4 samples per pixel (the GL's
//! standard positions) by barylab and by Mesa's llvmpipe, every sample read back from a
//! multisample texture (`texelFetch` per sample). Every sample's coverage and owning
//! triangle must be identical; every covered sample's uv the GL's (for `noperspective` at
//! every location, `smooth` at the centre) or the exact value at the GL's location (for
//! `smooth` centroid/sample, whose GL value is `f/w` at the location over `1/w` at the
//! centre, see `barylab::gpu::sample_check`); `flat` exactly; the resolve within one level of
//! the GL's.
//!
//! Runs when Mesa's EGL is present; with `CI=true` a missing llvmpipe is a failure.

#![cfg(feature = "gpu")]

mod common;

use barylab::gpu as gl;
use barylab::gpu::sample_check::{UvFormula, check_samples};
use barylab::raster::render::{ClipMesh, MeshVertex, RenderSettings};
use barylab::raster::sample::{
    Location, ProvokingVertex, SampleCount, SamplePattern, SampleSettings, ShadingRate,
};
use barylab::raster::{Filter, Interpolation, Shading, Texture};
use common::gl::llvmpipe;
use glam::{DVec4, Vec2, Vec3};

const W: u32 = 40;
const H: u32 = 30;

/// The GL's uv against the exact value (after its formula is undone): llvmpipe's f32 plane
/// equations, and for `smooth` off the centre the f32 quotient it divides by.
const UV_TOLERANCE: f64 = 5e-5;

/// Window depth at a sample: llvmpipe evaluates its f32 depth plane at the sample offset
/// (measured at most 2.3e-6 on these scenes; barylab's is exact to f32 rounding).
const DEPTH_TOLERANCE: f64 = 1e-5;

/// A small xorshift generator: the same scenes on every run.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

/// Eight triangles with corners anywhere in the image, w from 0.5 to
/// 4 (strong perspective), uv and colours at random.
fn random_scene(rng: &mut Rng) -> ClipMesh {
    let mut mesh = ClipMesh::default();
    let mut t = 0u32;
    while t < 8 {
        // Each triangle in a depth band of its own, the bands in a random order: triangles
        // overlap but never cross in depth, so a sample's owner is decided by coverage and
        // the depth order, never by f32 against f64 depths along an intersection line.
        let band = -0.9 + 0.2 * f64::from((t * 5 + (rng.next() * 2.0) as u32) % 9);
        let corners: Vec<(f64, f64)> = (0..3)
            .map(|_| (rng.range(0.0, f64::from(W)), rng.range(0.0, f64::from(H))))
            .collect();
        let (a, b, c) = (corners[0], corners[1], corners[2]);
        let area2 = ((b.0 - a.0) * (c.1 - a.1) - (c.0 - a.0) * (b.1 - a.1)).abs();
        // Random slivers narrower than a pixel are left out (their values at far samples
        // are ill-conditioned); one thin triangle is added below.
        let longest = [(a, b), (b, c), (c, a)]
            .iter()
            .map(|(p, q)| (p.0 - q.0).hypot(p.1 - q.1))
            .fold(0.0, f64::max);
        if area2 / longest < 2.0 {
            continue;
        }
        for (x, y) in corners {
            let w = rng.range(0.5, 4.0);
            let z = (band + rng.range(0.0, 0.1)) * w;
            let ndc = (2.0 * x / f64::from(W) - 1.0, 1.0 - 2.0 * y / f64::from(H));
            mesh.vertices.push(MeshVertex {
                clip: DVec4::new(ndc.0 * w, ndc.1 * w, z, w),
                uv: Vec2::new(rng.next() as f32, rng.next() as f32),
                color: Vec3::new(rng.next() as f32, rng.next() as f32, rng.next() as f32),
                normal: Vec3::ZERO,
            });
        }
        mesh.triangles.push([3 * t, 3 * t + 1, 3 * t + 2]);
        t += 1;
    }
    // And in front of them, one triangle too thin to hold a pixel centre: rows r + 0.55 to
    // r + 0.95 of a 20-pixel run, covering samples 0 and 1 of some pixels and no centre.
    let (x, r) = (
        rng.range(0.0, f64::from(W) - 24.0),
        f64::from((rng.next() * f64::from(H - 2)) as u32),
    );
    for (dx, dy) in [(0.0, 0.55), (20.0, 0.6), (10.0, 0.95)] {
        let ndc = (
            2.0 * (x + dx) / f64::from(W) - 1.0,
            1.0 - 2.0 * (r + dy) / f64::from(H),
        );
        mesh.vertices.push(MeshVertex {
            clip: DVec4::new(ndc.0, ndc.1, -0.99, 1.0),
            uv: Vec2::new(rng.next() as f32, rng.next() as f32),
            color: Vec3::new(rng.next() as f32, rng.next() as f32, rng.next() as f32),
            normal: Vec3::ZERO,
        });
    }
    mesh.triangles.push([3 * t, 3 * t + 1, 3 * t + 2]);
    mesh
}

fn settings(mode: Interpolation, samples: SampleSettings) -> RenderSettings {
    RenderSettings {
        width: W,
        height: H,
        mode,
        filter: Filter::Nearest,
        shading: Shading::VertexColor,
        background: [0, 0, 0, 255],
        samples,
        ..RenderSettings::default()
    }
}

fn four(rate: ShadingRate, location: Location) -> SampleSettings {
    SampleSettings {
        count: SampleCount::Four,
        pattern: SamplePattern::Standard,
        rate,
        location,
        ..SampleSettings::default()
    }
}

#[test]
fn every_sample_matches_llvmpipe_on_random_scenes() {
    let Some((_mesa, mut lp)) = llvmpipe() else {
        return;
    };
    let texture = Texture::from_texels(1, 1, vec![[255; 4]]).expect("1x1 texture");
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut configurations = Vec::new();
    for mode in [Interpolation::Affine, Interpolation::Perspective] {
        for location in [Location::Center, Location::Centroid, Location::Sample] {
            configurations.push((mode, four(ShadingRate::Msaa, location)));
        }
        configurations.push((mode, four(ShadingRate::Ssaa, Location::Center)));
    }
    for provoking in [ProvokingVertex::Last, ProvokingVertex::First] {
        let flat = SampleSettings {
            flat: true,
            provoking,
            ..four(ShadingRate::Msaa, Location::Center)
        };
        configurations.push((Interpolation::Perspective, flat));
    }
    let mut off_centre_formula = 0.0f64;
    let mut covered = 0;
    let mut locations_differ = 0;
    for scene in 0..6 {
        let mesh = gl::mesh_at_f32(&random_scene(&mut rng));
        for &(mode, samples) in &configurations {
            let s = settings(mode, samples);
            let (c, ..) = check_samples(&mut lp, &mesh, &texture, &s, gl::Output::VertexColor)
                .expect("check");
            let what = format!("scene {scene} {mode:?} {samples:?}: {c:?}");
            eprintln!("{what}");
            covered += c.covered;
            assert_eq!(c.samples, (W * H * 4) as usize, "{what}");
            assert_eq!(c.coverage_mismatches, 0, "coverage differs: {what}");
            assert_eq!(c.triangle_mismatches, 0, "owning triangle differs: {what}");
            if samples.flat {
                assert_eq!(c.max_uv_difference, 0.0, "flat is exact: {what}");
            }
            assert!(c.max_uv_difference <= UV_TOLERANCE, "uv differs: {what}");
            assert!(
                c.max_depth_difference <= DEPTH_TOLERANCE,
                "depth differs: {what}"
            );
            locations_differ += c.location_differs;
            match c.uv_formula {
                Some(UvFormula::Exact) if c.location_differs == 0 => {
                    assert!(c.max_resolve_difference <= 1, "resolve differs: {what}");
                    assert!(c.max_sample_color_difference <= 1, "colour differs: {what}");
                }
                Some(UvFormula::SampleOverCentre) => {
                    off_centre_formula = off_centre_formula.max(c.max_uv_formula_difference);
                }
                Some(UvFormula::Exact) => {}
                None => panic!("nothing compared: {what}"),
            }
        }
    }
    assert!(covered > 10_000, "the scenes cover too little: {covered}");
    // The GL's smooth centroid/sample values are not the exact ones (that is what the
    // formula accounts for): measured well above the tolerance on these scenes.
    eprintln!("llvmpipe's smooth off-centre formula: up to {off_centre_formula} in uv");
    eprintln!("samples evaluated elsewhere than barylab's centroid rule: {locations_differ}");
    assert!(off_centre_formula > 100.0 * UV_TOLERANCE);
}

/// The GL's sample positions are barylab's standard ones; the grid is refused by name.
#[test]
fn the_gl_positions_are_the_standard_pattern_and_the_grid_is_refused() {
    let Some((_mesa, mut lp)) = llvmpipe() else {
        return;
    };
    let texture = Texture::from_texels(1, 1, vec![[255; 4]]).expect("1x1 texture");
    let mesh = gl::mesh_at_f32(&random_scene(&mut Rng(7)));
    let s = settings(
        Interpolation::Perspective,
        four(ShadingRate::Msaa, Location::Center),
    );
    let (_, _, _, samples) =
        check_samples(&mut lp, &mesh, &texture, &s, gl::Output::VertexColor).expect("check");
    assert_eq!(
        samples.positions,
        [
            [0.375, 0.125],
            [0.875, 0.375],
            [0.125, 0.625],
            [0.625, 0.875]
        ]
    );
    let grid = settings(
        Interpolation::Perspective,
        SampleSettings {
            pattern: SamplePattern::Grid,
            ..four(ShadingRate::Msaa, Location::Center)
        },
    );
    let e = check_samples(&mut lp, &mesh, &texture, &grid, gl::Output::VertexColor)
        .map(|_| ())
        .expect_err("the grid cannot be drawn by the GL");
    assert!(e.contains("only the GL's own positions"), "{e}");
}

/// `barylab gpu-check --samples 4`: the samples section in JSON (coverage identical on a
/// sample scene, the GL's smooth centroid formula named) and in the text report.
#[test]
fn gpu_check_reports_the_samples() {
    let Some((mesa, lp)) = llvmpipe() else {
        return;
    };
    drop(lp);
    let run = |extra: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_barylab"))
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .args(["gpu-check", "--software", "assets/scenes/default.json"])
            .args([
                "--size",
                "96x72",
                "--samples",
                "4",
                "--location",
                "centroid",
            ])
            .args(extra)
            .output()
            .expect("run barylab")
    };
    let out = run(&["--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let s = &report["scenes"][0]["samples"];
    assert_eq!(s["per_pixel"], 4, "{report}");
    assert_eq!(s["samples"], 96 * 72 * 4, "{report}");
    assert_eq!(s["coverage_mismatches"], 0, "{report}");
    assert_eq!(s["triangle_mismatches"], 0, "{report}");
    assert_eq!(s["uv_formula"], "sample_over_centre", "{report}");
    let uv = s["max_uv_difference"].as_f64().expect("a number");
    assert!(uv <= UV_TOLERANCE, "{report}");
    let text = String::from_utf8_lossy(&run(&[]).stdout).into_owned();
    assert!(
        text.contains("f/w at the sample divided by 1/w at the pixel centre"),
        "{text}"
    );
    let zh = String::from_utf8_lossy(&run(&["--lang", "zh"]).stdout).into_owned();
    assert!(zh.contains("像素中心处的 1/w"), "{zh}");
    drop(mesa);
}
