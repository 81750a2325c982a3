//! Tests of the pixel probe: it agrees with the renderer pixel for pixel, its independent
//! weight computations agree with each other, a hand-worked example, the output formats and
//! the command line.

use std::path::{Path, PathBuf};
use std::process::Command;

use barylab::probe::format::{self, Format};
use barylab::probe::{Position, ProbeError, Prober, probe};
use barylab::raster::setup::{EdgeKind, Facing};
use barylab::raster::{self, Interpolation, NO_TRIANGLE};
use barylab::scene::{ModelScene, Scene};
use proptest::prelude::*;

fn scenes_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes")
}

fn sample_scenes() -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(scenes_dir())
        .expect("assets/scenes")
        .map(|e| e.expect("dir entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    v.sort();
    assert!(v.len() >= 5, "sample scenes: {v:?}");
    v
}

/// Renders a sample scene in one mode and probes every pixel: the probe's colour, triangle
/// and weights are the framebuffer's.
fn probe_matches_render(path: &Path, mode: Interpolation) {
    let mut scene = Scene::load(path).expect("scene loads");
    // A model has thousands of triangles to test per pixel: a quarter of the size is as
    // thorough a check, in a sixteenth of the time.
    if scene.to_mesh().triangles.len() > 1000 {
        let (w, h) = scene.size();
        scene.set_size(w / 4, h / 4);
    }
    // A multisampled scene's per-pixel buffers are sample 0's, not the centre's the probe
    // traces (its samples are checked in tests/samples.rs): its single-sample render here.
    scene.set_samples(Default::default());
    scene_matches_render(&scene, &scenes_dir(), path, mode);
}

fn scene_matches_render(scene: &Scene, base_dir: &Path, path: &Path, mode: Interpolation) {
    let texture = scene.load_texture(base_dir).expect("texture");
    let mut settings = scene.settings();
    settings.mode = mode;
    let out = raster::render(&scene.to_mesh(), &texture, &settings).expect("render");
    let f = &out.frame;
    let prober = Prober::new(scene, &texture, &settings).expect("prober");
    let mut covered = 0;
    for y in 0..f.height {
        for x in 0..f.width {
            let i = f.index(x, y);
            let t = prober.pixel(x, y).expect("probe");
            assert_eq!(
                t.color,
                f.color[i],
                "{} {mode:?} pixel ({x}, {y})",
                path.display()
            );
            let tri = f.triangle[i];
            assert_eq!(t.written_by, (tri != NO_TRIANGLE).then_some(tri));
            if tri == NO_TRIANGLE {
                continue;
            }
            covered += 1;
            let d = t.detail.as_ref().expect("detail of a covered pixel");
            assert!(d.writes_pixel && d.coverage.covered);
            let sw = d.source_weights.expect("source weights");
            assert_eq!(sw.screen, f.weights_screen[i]);
            assert_eq!(sw.perspective, f.weights_perspective[i]);
            let depth = d.depth.expect("depth");
            assert_eq!(depth.depth as f32, f.depth[i]);
        }
    }
    assert!(covered > 0, "{} covers no pixel", path.display());
}

macro_rules! scene_tests {
    ($($name:ident: $file:literal,)*) => {
        mod every_pixel {
            use super::*;
            $(
                #[test]
                fn $name() {
                    let path = scenes_dir().join($file);
                    probe_matches_render(&path, Interpolation::Affine);
                    probe_matches_render(&path, Interpolation::Perspective);
                }
            )*

            /// Every sample scene has a test above.
            #[test]
            fn all_sample_scenes_are_listed() {
                let listed = [$($file),*];
                for p in sample_scenes() {
                    let name = p.file_name().and_then(|n| n.to_str()).unwrap_or_default().to_string();
                    assert!(listed.contains(&name.as_str()), "{name} has no probe test");
                }
            }
        }
    };
}

scene_tests! {
    bench_1080p: "bench-1080p.json",
    clip_two_triangles: "clip-two-triangles.json",
    corner_behind: "corner-behind.json",
    default: "default.json",
    far_checker: "far-checker.json",
    far_checker_anisotropic: "far-checker-anisotropic.json",
    checker_closeup: "checker-closeup.json",
    receding_wall: "receding-wall.json",
    front: "front.json",
    games101_a2: "games101-a2.json",
    games101_a2_ssaa: "games101-a2-ssaa.json",
    games101_a2_clip: "games101-a2-clip.json",
    games101_a2_clip_ssaa: "games101-a2-clip-ssaa.json",
    games101_a3_spot: "games101-a3-spot.json",
    games101_pitfall: "games101-pitfall.json",
    near_cut: "near-cut.json",
    orthographic: "orthographic.json",
    seed001_2x2: "rgbw-2x2.json",
    rgb_triangle: "rgb-triangle.json",
    tetrahedron: "tetrahedron.json",
    vertex_colors: "vertex-colors.json",
}

/// A model (12 triangles, some hidden by the depth test): every pixel matches too.
#[test]
fn every_pixel_of_a_model() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/models/cube.obj");
    let model = ModelScene::for_model(&path, 160, 120).expect("cube.obj");
    let scene = Scene::Model(model);
    for mode in [Interpolation::Affine, Interpolation::Perspective] {
        scene_matches_render(&scene, Path::new(""), &path, mode);
    }
    // Some pixel sees a fragment fail the depth test.
    let texture = scene.load_texture(Path::new("")).expect("texture");
    let prober = Prober::new(&scene, &texture, &scene.settings()).expect("prober");
    let hidden = (0..120)
        .flat_map(|y| (0..160).map(move |x| (x, y)))
        .filter_map(|(x, y)| prober.pixel(x, y).ok())
        .filter(|t| {
            t.triangles
                .iter()
                .any(|c| c.depth_test.is_some_and(|d| !d.passed))
        })
        .count();
    assert!(hidden > 0);
}

/// The hand-worked scene: an 8x8 image, one triangle in clip space with window positions
/// A = (0, 8), B = (8, 8), C = (0, 0) and w = 1, 2, 4, the 2x2 texture (red, white / green, blue) with
/// nearest filtering.
const HAND_SCENE: &str = r#"{
  "width": 8, "height": 8,
  "vertices": [
    { "clip": [-1.0, -1.0, -0.5, 1.0], "uv": [0.0, 0.0] },
    { "clip": [2.0, -2.0, 0.0, 2.0], "uv": [1.0, 0.0] },
    { "clip": [-4.0, 4.0, 2.0, 4.0], "uv": [0.0, 1.0] }
  ],
  "triangles": [[0, 1, 2]],
  "texture": "rgbw-2x2",
  "filter": "nearest",
  "wrap": "clamp_to_edge"
}"#;

fn hand_scene() -> Scene {
    Scene::from_json(HAND_SCENE, "hand.json").expect("hand scene")
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * (1.0 + b.abs())
}

/// Pixel (4, 6), worked on paper.
///
/// Centre P = (4.5, 6.5), NDC (2*4.5/8 - 1, 1 - 2*6.5/8) = (0.125, -0.625).
/// With A = (0, 8), B = (8, 8), C = (0, 0): P = A + s (B - A) + t (C - A) gives s = x/8 =
/// 9/16, t = (8 - y)/8 = 3/16, r = 1 - s - t = 1/4.
/// Fixed point: 2A = 2048^2 = 4194304; E_BC = r 2A = 1048576, E_CA = 2359296, E_AB = 786432.
/// 1/W_P = (1/4)/1 + (9/16)/2 + (3/16)/4 = 16/64 + 18/64 + 3/64 = 37/64, W_P = 64/37,
/// a = (1/4)(64/37)/1 = 16/37, b = (9/16)(64/37)/2 = 18/37, c = (3/16)(64/37)/4 = 3/37.
/// Depth: d = (z/w + 1)/2 = 1/4, 1/2, 3/4; d_P = 1/16 + 9/32 + 9/64 = 31/64 = 0.484375.
/// uv: affine (s, t) = (9/16, 3/16), perspective (b, c) = (18/37, 3/37).
/// Texels (u*2, v*2): affine (1.125, 0.375) -> texel (1, 0) = green; perspective
/// (0.973, 0.162) -> texel (0, 0) = red.
/// The seen point in clip space: (16 q_A + 18 q_B + 3 q_C)/37 = (8, -40, -2, 64)/37, whose
/// z/w = -1/32 gives depth (1 - 1/32)/2 = 31/64 again.
#[test]
fn hand_worked_example() {
    let scene = hand_scene();
    let texture = scene.load_texture(Path::new(".")).expect("texture");
    let settings = scene.settings();
    let t = probe(&scene, &texture, &settings, (4, 6)).expect("probe");

    assert_eq!(t.sample.window, [4.5, 6.5]);
    assert_eq!(t.sample.ndc, [0.125, -0.625]);
    assert_eq!(t.sample.fixed, [1152, 1664]);
    assert_eq!(t.written_by, Some(0));
    let d = t.detail.expect("detail");
    assert!(d.clipping.is_none());
    assert_eq!(d.raster.area2, 4194304);
    assert_eq!(d.raster.facing, Facing::Front);
    let e: Vec<i64> = d.coverage.edges.iter().map(|e| e.value).collect();
    assert_eq!(e, [1048576, 2359296, 786432]);
    assert_eq!(d.coverage.position, Position::Inside);
    let names: Vec<&str> = d.coverage.edges.iter().map(|e| e.name.as_str()).collect();
    assert_eq!(names, ["BC", "CA", "AB"]);
    let kinds: Vec<EdgeKind> = d.coverage.edges.iter().map(|e| e.kind).collect();
    assert_eq!(kinds, [EdgeKind::Right, EdgeKind::Left, EdgeKind::Bottom]);

    // Screen weights, every way, exactly (all inputs are dyadic).
    let rst = [0.25, 0.5625, 0.1875];
    assert_eq!(d.screen.rasterizer, rst);
    assert_eq!(d.screen.explicit.expect("explicit").weights, rst);
    assert_eq!(d.screen.cross_product.expect("cross").weights, rst);
    assert_eq!(d.screen.gl_area.expect("gl").weights, rst);
    let from_system = d.screen.from_system.expect("from system");
    assert!((0..3).all(|k| close(from_system[k], rst[k])));

    // The 1/w correction.
    let p = d.perspective.expect("perspective");
    assert_eq!(p.w, [1.0, 2.0, 4.0]);
    assert_eq!(p.correction.inv_w, [1.0, 0.5, 0.25]);
    assert_eq!(p.correction.inv_w_p, 37.0 / 64.0);
    assert!(close(p.correction.w_p, 64.0 / 37.0));
    assert!(close(p.games101_w_reciprocal, 64.0 / 37.0));
    let abc = [16.0 / 37.0, 18.0 / 37.0, 3.0 / 37.0];
    for (k, expect) in abc.iter().enumerate() {
        assert!(close(p.correction.weights[k], *expect));
        assert!(close(p.renderer_weights[k], *expect));
    }

    // The 4x4 system, on the raw clip coordinates.
    let sys = d.system.expect("system");
    assert_eq!(
        sys.system.matrix,
        [
            [-1.0, 2.0, -4.0, -0.125],
            [-1.0, -2.0, 4.0, 0.625],
            [1.0, 1.0, 1.0, 0.0],
            [1.0, 2.0, 4.0, -1.0],
        ]
    );
    let sol = sys.system.solution;
    assert!((0..3).all(|k| close(sol[k], abc[k])));
    assert!(close(sol[3], 64.0 / 37.0));

    // The seen point, in clip space.
    let seen = d.seen_point.expect("seen point");
    let clip = [8.0 / 37.0, -40.0 / 37.0, -2.0 / 37.0, 64.0 / 37.0];
    assert!(
        (0..4).all(|k| close(seen.clip[k], clip[k])),
        "{:?}",
        seen.clip
    );
    assert!(close(seen.depth, 31.0 / 64.0));

    // Depth.
    let depth = d.depth.expect("depth");
    assert_eq!(depth.window_depths, [0.25, 0.5, 0.75]);
    assert_eq!(depth.depth, 31.0 / 64.0);
    assert!(close(depth.distance_corrected, 64.0 / 37.0));
    assert_eq!(depth.distance_affine, 0.25 + 0.5625 * 2.0 + 0.1875 * 4.0);

    // uv and the texels.
    let a = d.attribute.expect("attribute");
    assert_eq!(a.uv_affine, [0.5625, 0.1875]);
    assert!((a.uv_perspective[0] - 18.0 / 37.0).abs() < 1e-7);
    assert!((a.uv_perspective[1] - 3.0 / 37.0).abs() < 1e-7);
    assert_eq!((a.taps_affine[0].i, a.taps_affine[0].j), (1, 0));
    assert_eq!((a.taps_perspective[0].i, a.taps_perspective[0].j), (0, 0));
    assert_eq!(a.color_affine, [0, 255, 0, 255]);
    assert_eq!(a.color_perspective, [255, 0, 0, 255]);
    assert_eq!(t.color, [255, 0, 0, 255]);

    // In affine mode the same pixel is green.
    let mut affine = settings;
    affine.mode = Interpolation::Affine;
    let t = probe(&scene, &texture, &affine, (4, 6)).expect("probe");
    assert_eq!(t.color, [0, 255, 0, 255]);

    // The worked example reads these numbers.
    let text = format::write(
        &probe(&scene, &texture, &settings, (4, 6)).expect("probe"),
        Format::Text,
    );
    for needle in [
        "E_BC = 1048576",
        "(r, s, t) = (0.25, 0.5625, 0.1875)",
        "1/W_P = r/W_A + s/W_B + t/W_C = 0.25·1 + 0.5625·0.5 + 0.1875·0.25 = 0.5781",
        "W_P = 1/0.578125 = 1.73",
        "a = r·W_P/W_A = 0.25·1.72973/1 = 0.4324",
        "d_P = r·d_A + s·d_B + t·d_C = 0.25·0.25 + 0.5625·0.5 + 0.1875·0.75 = 0.4844",
        "framebuffer(4, 6) = rgba(255, 0, 0, 255) = #ff0000",
    ] {
        assert!(text.contains(needle), "missing `{needle}` in\n{text}");
    }
}

/// Pixel (3, 3) of the hand scene: its centre (3.5, 3.5) lies exactly on edge BC (the line
/// y = x), a right edge, so the fill rule leaves it to a neighbour.
#[test]
fn sample_on_a_right_edge_is_not_covered_and_says_why() {
    let scene = hand_scene();
    let texture = scene.load_texture(Path::new(".")).expect("texture");
    let t = probe(&scene, &texture, &scene.settings(), (3, 3)).expect("probe");
    assert_eq!(t.written_by, None);
    assert_eq!(t.color, scene.settings().background);
    let d = t.detail.as_ref().expect("the nearest triangle");
    assert!(!d.writes_pixel);
    assert_eq!(d.coverage.position, Position::OnEdge);
    assert_eq!(d.coverage.edges[0].value, 0);
    assert_eq!(d.coverage.edges[0].kind, EdgeKind::Right);
    assert_eq!(d.screen.rasterizer, [0.0, 0.4375, 0.5625]);
    let text = format::write(&t, Format::Text);
    assert!(
        text.contains("E_BC = 0: on edge BC, a right edge"),
        "{text}"
    );
    assert!(text.contains("not covered"), "{text}");
}

/// Pixel (6, 1) is outside edge BC: the nearest triangle's weights, with the negative one
/// marked.
#[test]
fn uncovered_pixel_shows_negative_weights() {
    let scene = hand_scene();
    let texture = scene.load_texture(Path::new(".")).expect("texture");
    let t = probe(&scene, &texture, &scene.settings(), (6, 1)).expect("probe");
    assert_eq!(t.written_by, None);
    let d = t.detail.as_ref().expect("the nearest triangle");
    assert_eq!(d.coverage.position, Position::Outside);
    // P = (6.5, 1.5): s = 6.5/8, t = 6.5/8, r = 1 - 13/8 = -5/8.
    assert_eq!(d.screen.rasterizer, [-0.625, 0.8125, 0.8125]);
    let text = format::write(&t, Format::Text);
    assert!(
        text.contains("E_BC < 0: the sample is outside edge BC"),
        "{text}"
    );
    assert!(text.contains("(negative: P is outside edge BC)"), "{text}");
    assert!(text.contains("No triangle covers the pixel"), "{text}");
}

#[test]
fn pixel_outside_the_image_is_an_error() {
    let scene = hand_scene();
    let texture = scene.load_texture(Path::new(".")).expect("texture");
    let e = probe(&scene, &texture, &scene.settings(), (8, 0)).expect_err("outside");
    assert_eq!(
        e,
        ProbeError::PixelOutside {
            x: 8,
            y: 0,
            width: 8,
            height: 8
        }
    );
    assert_eq!(
        e.to_string(),
        "pixel (8, 0) is outside the 8x8 image (x must be 0..=7, y 0..=7)"
    );
}

/// A vertex behind the camera: the trace says so, uses the fan triangle, and the source
/// weights from the 4x4 system and the 3D ray agree with the interpolated varyings.
#[test]
fn clipped_triangle_is_explained_with_source_weights() {
    let path = scenes_dir().join("corner-behind.json");
    let scene = Scene::load(&path).expect("scene");
    let texture = scene.load_texture(&scenes_dir()).expect("texture");
    let prober = Prober::new(&scene, &texture, &scene.settings()).expect("prober");
    let (w, h) = scene.size();
    let mut checked = 0;
    for y in (0..h).step_by(7) {
        for x in (0..w).step_by(7) {
            let t = prober.pixel(x, y).expect("probe");
            let Some(d) = t.detail.filter(|d| d.writes_pixel) else {
                continue;
            };
            if d.clipping.is_none() {
                continue;
            }
            assert!(d.vertex_behind_camera);
            assert!(d.screen.from_system.is_none());
            let sw = d.source_weights.expect("source weights");
            let sys = d.system.expect("system on the source triangle");
            let seen = d.seen_point.expect("seen point");
            for k in 0..3 {
                let v = f64::from(sw.perspective[k]);
                assert!(
                    (sys.system.solution[k] - v).abs() < 1e-4,
                    "system vs varyings at ({x}, {y})"
                );
                assert!(
                    (seen.weights[k] - v).abs() < 1e-4,
                    "ray vs varyings at ({x}, {y})"
                );
            }
            checked += 1;
        }
    }
    assert!(checked > 100, "only {checked} clipped pixels");
    // The text says what happened.
    let t = prober.pixel(100, 400).expect("probe");
    let text = format::write(&t, Format::Text);
    assert!(
        text.contains("is at or behind the plane of the eye"),
        "{text}"
    );
    assert!(text.contains("the near plane"), "{text}");
    assert!(text.contains("do not exist"), "{text}");
}

/// A clip-space scene whose vertices are at window positions `(x, y)` with clip `w`.
fn clip_scene(v: &[(f64, f64, f64)], width: u32, height: u32) -> Scene {
    let vertices: Vec<String> = v
        .iter()
        .enumerate()
        .map(|(k, &(x, y, w))| {
            let nx = 2.0 * x / f64::from(width) - 1.0;
            let ny = 1.0 - 2.0 * y / f64::from(height);
            format!(
                r#"{{ "clip": [{}, {}, {}, {}], "uv": [{}, {}] }}"#,
                nx * w,
                ny * w,
                0.1 * k as f64 * w,
                w,
                k % 2,
                k / 2
            )
        })
        .collect();
    let json = format!(
        r#"{{ "width": {width}, "height": {height}, "vertices": [{}], "triangles": [[0, 1, 2]], "texture": "checker" }}"#,
        vertices.join(",")
    );
    Scene::from_json(&json, "random.json").expect("random scene")
}

/// A window coordinate on the 1/256 grid, with a margin around a `max`-pixel viewport.
fn grid_coord(max: u32) -> impl Strategy<Value = f64> {
    let lo = -8 * 256i64;
    let hi = (i64::from(max) + 8) * 256;
    (lo..hi).prop_map(|k| k as f64 / 256.0)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// The explicit formula, the cross-product areas, the OpenGL area form, the 4x4 system
    /// and the rasterizer's fixed-point edge functions give the same screen weights, inside
    /// the triangle or out; the system's b and w are the 1/w method's a, b, c and W_P.
    #[test]
    fn four_weight_methods_agree(
        a in (grid_coord(64), grid_coord(48), 0.2f64..20.0),
        b in (grid_coord(64), grid_coord(48), 0.2f64..20.0),
        c in (grid_coord(64), grid_coord(48), 0.2f64..20.0),
        px in 0u32..64, py in 0u32..48,
    ) {
        let scene = clip_scene(&[a, b, c], 64, 48);
        let texture = scene.load_texture(Path::new(".")).expect("texture");
        let t = probe(&scene, &texture, &scene.settings(), (px, py)).expect("probe");
        let Some(d) = t.detail else { return Ok(()); };
        prop_assert!(d.clipping.is_none());
        let r = d.screen.rasterizer;
        let scale = 1.0 + r.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let methods = [
            d.screen.explicit.map(|f| f.weights),
            d.screen.cross_product.map(|f| f.weights),
            d.screen.gl_area.map(|f| f.weights),
        ];
        for m in methods {
            let m = m.expect("a drawn triangle is not degenerate");
            for k in 0..3 {
                prop_assert!((m[k] - r[k]).abs() < 1e-9 * scale, "{:?} vs {:?}", m, r);
            }
        }
        prop_assert!(d.screen.max_difference < 1e-9 * scale);
        if let (Some(p), Some(sys)) = (d.perspective, d.system) {
            let s = sys.system.solution;
            let from = d.screen.from_system.expect("unclipped: screen weights from the system");
            let pscale = 1.0 + p.correction.weights.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            for k in 0..3 {
                prop_assert!((from[k] - r[k]).abs() < 1e-7 * scale, "{:?} vs {:?}", from, r);
                prop_assert!((s[k] - p.correction.weights[k]).abs() < 1e-7 * pscale);
                prop_assert!((p.correction.weights[k] - p.renderer_weights[k]).abs() < 1e-12 * pscale);
            }
            prop_assert!((s[3] - p.correction.w_p).abs() < 1e-7 * p.correction.w_p.abs().max(1.0));
            prop_assert!((p.games101_w_reciprocal - p.correction.w_p).abs() < 1e-12 * p.correction.w_p);
        }
    }

    /// In a world scene, the perspective-correct weights at every covered pixel are the
    /// weights of the 3D point where the ray through the pixel centre meets the triangle's
    /// plane (up to the rasterizer's snapping of the vertices to 1/256 pixel).
    #[test]
    fn corrected_weights_are_the_seen_points_weights(
        corners in proptest::collection::vec((-2.0f64..2.0, -1.5f64..1.5, -9.0f64..-1.5), 4),
        fov in 35.0f64..90.0,
        pitch in -60.0f64..60.0,
    ) {
        let quad: Vec<String> = corners
            .iter()
            .enumerate()
            .map(|(k, (x, y, z))| format!(
                r#"{{ "position": [{x}, {y}, {z}], "uv": [{}, {}] }}"#, k % 2, k / 2
            ))
            .collect();
        let json = format!(
            r#"{{ "width": 64, "height": 48,
                 "camera": {{ "eye": [0, 0, 0], "target": [0, 0, -1],
                   "projection": {{ "kind": "perspective", "fov_y_deg": {fov}, "near": 0.1, "far": 100 }} }},
                 "tilt": {{ "pitch_deg": {pitch}, "yaw_deg": 0 }},
                 "quad": [{}] }}"#,
            quad.join(",")
        );
        let scene = Scene::from_json(&json, "random.json").expect("scene");
        let texture = scene.load_texture(Path::new(".")).expect("texture");
        let prober = Prober::new(&scene, &texture, &scene.settings()).expect("prober");
        for y in 0..48 {
            for x in 0..64 {
                let t = prober.pixel(x, y).expect("probe");
                let Some(d) = t.detail.filter(|d| d.writes_pixel) else { continue; };
                let Some(seen) = d.seen_point else { continue; };
                let expect: [f64; 3] = match (&d.clipping, d.perspective) {
                    (None, Some(p)) => p.correction.weights,
                    _ => d.source_weights.expect("weights").perspective.map(f64::from),
                };
                // The snapping error relative to the triangle's size on screen.
                let tol = 1e-4 + 2.0 / (d.raster.area2 as f64 / 65536.0);
                for k in 0..3 {
                    prop_assert!((seen.weights[k] - expect[k]).abs() < tol,
                        "pixel ({}, {}): seen {:?} vs corrected {:?}", x, y, seen.weights, expect);
                }
                let depth = d.depth.expect("depth");
                prop_assert!((seen.depth - depth.depth).abs() < 1e-3);
            }
        }
    }
}

#[test]
fn json_has_the_documented_fields() {
    let path = scenes_dir().join("default.json");
    let scene = Scene::load(&path).expect("scene");
    let texture = scene.load_texture(&scenes_dir()).expect("texture");
    let t = probe(&scene, &texture, &scene.settings(), (400, 420)).expect("probe");
    let v: serde_json::Value =
        serde_json::from_str(&format::write(&t, Format::Json)).expect("valid JSON");
    for pointer in [
        "/pixel/0",
        "/image_size/1",
        "/settings/mode",
        "/scene_form",
        "/matrices/clip_from_view/3/2",
        "/sample/window/0",
        "/sample/fixed/1",
        "/sample/ndc/0",
        "/triangles/0/test/edges/0/value",
        "/triangles/0/depth_test/passed",
        "/written_by",
        "/color/3",
        "/detail/vertices/2/view/2",
        "/detail/raster/area2",
        "/detail/screen/explicit/beta_numerator",
        "/detail/screen/cross_product/sub_areas/0",
        "/detail/screen/gl_area/area",
        "/detail/screen/from_system/2",
        "/detail/perspective/correction/inv_w_p",
        "/detail/perspective/games101_w_reciprocal",
        "/detail/system/system/matrix/3/3",
        "/detail/system/system/solution/3",
        "/detail/seen_point/hit/weights/0",
        "/detail/attribute/uv_perspective/1",
        "/detail/attribute/taps_perspective/0/texel",
        "/detail/depth/distance_corrected",
        "/detail/shade/color",
        // Added for the formatter, which prints only trace fields:
        "/sample/subpixel",
        "/sample/edge_function_unit",
        "/detail/vertices/0/window_fixed/1",
        "/detail/screen/explicit/beta_numerator_factors/3",
        "/detail/screen/explicit/gamma_denominator_factors/0",
        "/detail/screen/cross_product/sub_area_sum",
        "/detail/screen/cross_product/vectors/3/1/0",
        "/detail/system/max_difference",
        "/detail/seen_point/ndc/2",
        "/detail/seen_point/max_difference",
        "/detail/seen_point/hit/edges/1/2",
        "/detail/seen_point/hit/t_numerator",
        "/detail/seen_point/hit/t_denominator",
        "/detail/attribute/last_texel/1",
        "/detail/shade/wire_width_px",
    ] {
        assert!(v.pointer(pointer).is_some(), "missing {pointer}");
    }
    assert_eq!(v["settings"]["mode"], "perspective");
    assert_eq!(v["written_by"], 0);
    // Full precision: the JSON number is the f64 itself.
    let p = t.detail.expect("detail").perspective.expect("perspective");
    assert_eq!(
        v["detail"]["perspective"]["correction"]["w_p"].as_f64(),
        Some(p.correction.w_p)
    );
}

/// The Markdown uses `$...$` math and the LaTeX compiles (with `pdflatex`, when it is
/// installed; otherwise its structure is checked).
#[test]
fn markdown_and_latex_formats() {
    let mut traces = Vec::new();
    for (file, pixel) in [
        ("default.json", (400, 420)),
        ("default.json", (10, 10)),
        ("corner-behind.json", (100, 400)),
        ("clip-two-triangles.json", (20, 20)),
        ("orthographic.json", (300, 300)),
    ] {
        let scene = Scene::load(&scenes_dir().join(file)).expect("scene");
        let texture = scene.load_texture(&scenes_dir()).expect("texture");
        traces.push(probe(&scene, &texture, &scene.settings(), pixel).expect("probe"));
    }
    let md = format::write(&traces[0], Format::Markdown);
    assert!(md.starts_with("# barylab probe: pixel (400, 420)"));
    assert!(
        md.contains("- $\\frac{1}{W_{P}} = \\frac{r}{W_{A}}"),
        "{md}"
    );
    assert!(md.contains("\\begin{bmatrix}"));
    assert_eq!(md.matches('$').count() % 2, 0, "unbalanced $ in markdown");

    let dir = tempfile::tempdir().expect("temp dir");
    let mut body = String::new();
    for (k, t) in traces.iter().enumerate() {
        let tex = format::write(t, Format::Latex);
        assert!(tex.is_ascii(), "LaTeX output must be ASCII for pdflatex");
        assert_eq!(
            tex.matches("\\begin{align*}").count(),
            tex.matches("\\end{align*}").count()
        );
        assert_eq!(tex.matches('{').count(), tex.matches('}').count());
        assert_eq!(tex.matches('$').count() % 2, 0);
        let name = format!("probe{k}.tex");
        std::fs::write(dir.path().join(&name), &tex).expect("write fragment");
        body.push_str(&format!("\\input{{{name}}}\n\\clearpage\n"));
    }
    let doc = format!(
        "\\documentclass{{article}}\n\\usepackage{{amsmath}}\n\\begin{{document}}\n{body}\\end{{document}}\n"
    );
    std::fs::write(dir.path().join("doc.tex"), doc).expect("write document");
    match Command::new("pdflatex")
        .args(["-interaction=nonstopmode", "-halt-on-error", "doc.tex"])
        .current_dir(dir.path())
        .output()
    {
        Ok(out) => {
            let log = String::from_utf8_lossy(&out.stdout);
            assert!(out.status.success(), "pdflatex failed:\n{log}");
            assert!(dir.path().join("doc.pdf").exists());
        }
        // CI installs pdflatex (.ci/run), so there it must run; elsewhere it is optional.
        Err(e) if std::env::var("CI").is_ok_and(|v| v == "true") => {
            panic!("pdflatex is required when CI=true: {e}")
        }
        Err(e) => eprintln!("pdflatex not available ({e}); checked the structure only"),
    }
}

fn barylab(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("run barylab")
}

#[test]
fn cli_bad_pixels_give_one_line_errors() {
    for (pixel, expect) in [
        (
            "800,10",
            "pixel (800, 10) is outside the 800x600 image (x must be 0..=799, y 0..=599)",
        ),
        (
            "5,600",
            "pixel (5, 600) is outside the 800x600 image (x must be 0..=799, y 0..=599)",
        ),
        ("abc", "`abc` is not a pixel like 400,300"),
        ("-1,5", "`-1,5` is not a pixel like 400,300"),
        ("1.5,2", "`1.5,2` is not a pixel like 400,300"),
        ("12", "`12` is not a pixel like 400,300"),
    ] {
        let out = barylab(&["probe", "assets/scenes/default.json", "--pixel", pixel]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{pixel} succeeded");
        assert!(err.contains(expect), "--pixel {pixel}: {err}");
        assert!(!err.contains("panicked"), "{err}");
        if pixel.contains(',') && !pixel.contains('.') && !pixel.starts_with('-') {
            assert_eq!(err.trim().lines().count(), 1, "one line: {err}");
            assert!(
                err.contains("assets/scenes/default.json"),
                "names the file: {err}"
            );
        }
    }
}

#[test]
fn cli_probe_json_matches_the_rendered_png() {
    let dir = tempfile::tempdir().expect("temp dir");
    let png = dir.path().join("out.png");
    let png_s = png.to_str().expect("utf-8 path");
    let out = barylab(&[
        "render",
        "assets/scenes/corner-behind.json",
        "--mode",
        "affine",
        "-o",
        png_s,
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let img = image::open(&png).expect("png").to_rgba8();
    for (x, y) in [(100u32, 400u32), (320, 240), (5, 5), (600, 100)] {
        let pixel = format!("{x},{y}");
        let out = barylab(&[
            "probe",
            "assets/scenes/corner-behind.json",
            "--pixel",
            &pixel,
            "--mode",
            "affine",
            "--format",
            "json",
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
        let color: Vec<u8> = v["color"]
            .as_array()
            .expect("color")
            .iter()
            .map(|c| c.as_u64().expect("u8") as u8)
            .collect();
        assert_eq!(color, img.get_pixel(x, y).0.to_vec(), "pixel ({x}, {y})");
        assert_eq!(v["settings"]["mode"], "affine");
    }
    for format in ["text", "markdown", "latex"] {
        let out = barylab(&[
            "probe",
            "assets/scenes/default.json",
            "--pixel",
            "400,420",
            "--format",
            format,
        ]);
        assert!(out.status.success());
        assert!(String::from_utf8_lossy(&out.stdout).contains("400, 420"));
    }
}

/// The example in docs/probe.md is what the CLI prints today.
#[test]
fn docs_example_is_current() {
    let doc = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/probe.md"))
        .expect("docs/probe.md");
    let begin = "<!-- probe-example:begin -->\n```text\n";
    let start = doc.find(begin).expect("example begin marker") + begin.len();
    let end = doc[start..]
        .find("```\n<!-- probe-example:end -->")
        .expect("end marker")
        + start;
    let out = barylab(&["probe", "assets/scenes/default.json", "--pixel", "400,420"]);
    assert!(out.status.success());
    assert!(
        doc[start..end] == *String::from_utf8_lossy(&out.stdout),
        "docs/probe.md's example is out of date: paste the output of \
         `barylab probe assets/scenes/default.json --pixel 400,420`"
    );
}
