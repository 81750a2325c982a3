//! The per-sample buffers view (`figure::sample_buffers`, `barylab figure --view samples`):
//! on GAMES101 A2 supersampled with the 2x2 grid, the coverage count, a sample's colour and
//! depth and the resolve hold what the lesson's pixel (83, 42) holds (green covers samples 0,
//! 2 and 3, the blue triangle sample 1); the black-edge bug clears the blue sample; the built-in
//! clip-space copies of the A2 scenes draw the same image as the model scenes.

use std::path::{Path, PathBuf};
use std::process::Command;

use barylab::figure::sample_buffers::{
    CLEARED_DEPTH, SampleBufferKind, black_edge_samples, coverage_colour, image, resolved,
    samples_of,
};
use barylab::raster::sample::resolve;
use barylab::raster::{NO_TRIANGLE, RenderSettings, Texture, render};
use barylab::scene::Scene;

const GREEN: [u8; 4] = [217, 238, 185, 255];
const BLUE: [u8; 4] = [185, 217, 238, 255];
const BLACK: [u8; 4] = [0, 0, 0, 255];

fn asset(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(name)
}

/// A scene file at 120 x 120 pixels, with its texture and settings.
fn load(name: &str) -> (Scene, Texture, RenderSettings) {
    let path = asset(name);
    let mut scene = Scene::load(&path).expect("scene");
    scene.set_size(120, 120);
    let texture = scene
        .load_texture(path.parent().expect("folder"))
        .expect("texture");
    let settings = scene.settings();
    (scene, texture, settings)
}

fn at(pixels: &[[u8; 4]], x: usize, y: usize) -> [u8; 4] {
    pixels[y * 120 + x]
}

#[test]
fn the_buffers_hold_the_lessons_pixel() {
    let (scene, texture, settings) = load("assets/scenes/games101-a2-ssaa.json");
    let b = samples_of(&scene, &texture, &settings, false).expect("samples");
    assert_eq!(b.offsets.len(), 4);
    // The lesson's pixel: samples 0, 2, 3 green, 1 blue.
    let colors: Vec<[u8; 4]> = b.pixel(83, 42).iter().map(|s| s.color).collect();
    assert_eq!(colors, [GREEN, BLUE, GREEN, GREEN]);
    let coverage = image(&b, SampleBufferKind::Coverage, 0);
    assert_eq!(at(&coverage, 83, 42), coverage_colour(4, 4));
    assert_eq!(at(&coverage, 2, 2), coverage_colour(0, 4));
    assert_ne!(coverage_colour(3, 4), coverage_colour(4, 4));
    // Sample 1's colour is blue there, sample 0's green; the index past the last is the last.
    assert_eq!(at(&image(&b, SampleBufferKind::Color, 1), 83, 42), BLUE);
    assert_eq!(at(&image(&b, SampleBufferKind::Color, 0), 83, 42), GREEN);
    assert_eq!(
        image(&b, SampleBufferKind::Color, 9),
        image(&b, SampleBufferKind::Color, 3)
    );
    // The resolve is the renderer's own image (its bands resolve the same samples), and the
    // lesson's (209, 233, 198).
    let r = render(&scene.to_mesh(), &texture, &settings).expect("render");
    let res = image(&b, SampleBufferKind::Resolve, 0);
    assert_eq!(res, r.frame.color);
    assert_eq!(at(&res, 83, 42), [209, 233, 198, 255]);
    // Depth: the green (near, z = -2) sample darker than the blue (far) one, a pixel no
    // triangle covers the cleared colour.
    let d0 = at(&image(&b, SampleBufferKind::Depth, 0), 83, 42);
    let d1 = at(&image(&b, SampleBufferKind::Depth, 1), 83, 42);
    assert!(d0[0] < d1[0], "{d0:?} {d1:?}");
    assert_eq!(
        at(&image(&b, SampleBufferKind::Depth, 0), 2, 2),
        CLEARED_DEPTH
    );
}

#[test]
fn the_black_edge_bug_clears_the_minority_triangles_samples() {
    let (scene, texture, settings) = load("assets/scenes/games101-a2-ssaa.json");
    let b = samples_of(&scene, &texture, &settings, false).expect("samples");
    let (bug, changed) = black_edge_samples(&b, settings.background);
    let s = bug.pixel(83, 42);
    assert_eq!(s[1].color, BLACK);
    assert_eq!(s[1].triangle, NO_TRIANGLE);
    assert_eq!([s[0].color, s[2].color, s[3].color], [GREEN; 3]);
    let res = resolved(&bug);
    assert_eq!(at(&res, 83, 42), resolve(&[GREEN, BLACK, GREEN, GREEN]));
    assert_eq!(at(&res, 83, 42), [163, 179, 139, 255]);
    // Darker than both triangles.
    let sum = |c: [u8; 4]| u32::from(c[0]) + u32::from(c[1]) + u32::from(c[2]);
    assert!(sum(at(&res, 83, 42)) < sum(GREEN).min(sum(BLUE)));
    // Changed: exactly the pixels whose samples hold two triangles.
    let two = (0..120)
        .flat_map(|y| (0..120).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let p = b.pixel(x, y);
            let first = p.iter().map(|v| v.triangle).find(|&t| t != NO_TRIANGLE);
            p.iter()
                .any(|v| v.triangle != NO_TRIANGLE && Some(v.triangle) != first)
        })
        .count();
    assert!(two > 10, "{two}");
    assert_eq!(changed, two);
    // A pixel of one triangle only is untouched.
    assert_eq!(bug.pixel(70, 55), b.pixel(70, 55));
    assert_eq!(
        samples_of(&scene, &texture, &settings, true).expect("samples"),
        bug
    );
}

#[test]
fn the_builtin_a2_scenes_draw_the_model_scenes() {
    for (model, clip) in [
        ("games101-a2.json", "games101-a2-clip.json"),
        ("games101-a2-ssaa.json", "games101-a2-clip-ssaa.json"),
    ] {
        let (m, mt, ms) = load(&format!("assets/scenes/{model}"));
        let (c, ct, cs) = load(&format!("assets/scenes/{clip}"));
        let (mm, cm) = (m.to_mesh(), c.to_mesh());
        assert_eq!(mm.triangles, cm.triangles);
        // The JSON reader may round a clip coordinate's last bit differently.
        for (a, b) in mm.vertices.iter().zip(&cm.vertices) {
            assert!((a.clip - b.clip).abs().max_element() < 1e-14, "{clip}");
            assert_eq!((a.uv, a.color), (b.uv, b.color), "{clip}");
        }
        assert_eq!(ms.samples, cs.samples, "{clip}");
        let a = render(&mm, &mt, &ms).expect("render");
        let b = render(&cm, &ct, &cs).expect("render");
        assert_eq!(a.frame.color, b.frame.color, "{clip}");
        assert_eq!(a.frame.triangle, b.frame.triangle, "{clip}");
        // At the scene's own 700 x 700 too.
        let full = |s: &RenderSettings| RenderSettings {
            width: 700,
            height: 700,
            ..*s
        };
        let a = render(&mm, &mt, &full(&ms)).expect("render");
        let b = render(&cm, &ct, &full(&cs)).expect("render");
        assert_eq!(a.frame.color, b.frame.color, "{clip}");
        assert_eq!(
            barylab::lesson::builtin::scene(clip.trim_end_matches(".json")),
            Some(
                std::fs::read_to_string(asset(&format!("assets/scenes/{clip}")))
                    .expect("read")
                    .as_str()
            )
        );
    }
}

/// A small image's legend (five swatches of 20 points for 4 samples) must end above the next
/// row's title: at 16 x 16 pixels the image is shorter than the coverage legend.
#[test]
fn a_small_images_legend_stays_in_its_row() {
    let (mut scene, texture, _) = load("assets/scenes/games101-a2-ssaa.json");
    scene.set_size(16, 16);
    let settings = scene.settings();
    let b = samples_of(&scene, &texture, &settings, false).expect("samples");
    let picture =
        barylab::figure::sample_buffers::picture(&b, 0, 1.0, false, barylab::i18n::Lang::En);
    assert_eq!(picture.rasters.len(), 4);
    let coverage = picture.rasters[0].rect;
    // The swatches start at the image's top, one every 20 points, each 14 points tall.
    let legend_bottom = coverage[1] + 4.0 * 20.0 + 14.0;
    // The row below: its image's top less its title's height (26 points).
    let next_title_top = picture.rasters[2].rect[1] - 26.0;
    assert!(
        next_title_top >= legend_bottom,
        "legend ends at {legend_bottom}, the next title starts at {next_title_top}"
    );
    assert!(picture.size[1] >= picture.rasters[3].rect[1] + picture.rasters[3].rect[3]);
}

fn barylab(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args(args)
        .output()
        .expect("barylab runs")
}

#[test]
fn the_cli_draws_the_buffers_and_refuses_what_it_cannot() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("samples.png");
    let o = out.to_str().expect("path");
    let ssaa = asset("assets/scenes/games101-a2-ssaa.json");
    let one = asset("assets/scenes/games101-a2.json");
    // `barylab figure SCENE --size 120x120 --view samples --sample-index K -o OUT`.
    let figure = |scene: &Path, k: &str| {
        let s = scene.to_str().expect("path");
        let args = ["figure", s, "--size", "120x120", "--view", "samples"];
        barylab(&[&args[..], &["--sample-index", k, "-o", o]].concat())
    };
    let ok = figure(&ssaa, "1");
    assert!(
        ok.status.success(),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
    let png = image::open(&out).expect("png").to_rgba8();
    // Four images of 120 x 120 (each a 120 x 120 raster at pixel size 1) and their titles.
    let (w, h) = png.dimensions();
    assert!(w > 2 * 120 && h > 2 * 120, "{w}x{h}");
    for (scene, k, words) in [
        (&ssaa, "4", ["--sample-index 4", "0 to 3"]),
        (&one, "0", ["games101-a2.json", "--samples 4"]),
    ] {
        let bad = figure(scene, k);
        assert!(!bad.status.success());
        let err = String::from_utf8_lossy(&bad.stderr);
        assert!(words.iter().all(|w| err.contains(w)), "{err}");
    }
}

/// Prints the clip-space form of a model scene (run with `--ignored --nocapture` to write the
/// built-in copies).
#[test]
#[ignore]
fn print_clip_form() {
    for name in ["games101-a2.json", "games101-a2-ssaa.json"] {
        let path = asset(&format!("assets/scenes/{name}"));
        let scene = Scene::load(&path).expect("scene");
        let mesh = scene.to_mesh();
        println!("== {name}");
        for v in &mesh.vertices {
            println!(
                "    {{ \"clip\": [{:?}, {:?}, {:?}, {:?}], \"color\": [{:?}, {:?}, {:?}] }},",
                v.clip.x, v.clip.y, v.clip.z, v.clip.w, v.color.x, v.color.y, v.color.z
            );
        }
        println!("{:?}", mesh.triangles);
    }
}
