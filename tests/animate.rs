//! `barylab animate`: the written GIF, APNG and WebP decoded again (frame count, size, frames
//! that change), the end frames against the still figures `barylab figure` draws of the
//! sweep's end states, the rasterizers' visiting orders, the palette, and the messages.

use std::path::{Path, PathBuf};
use std::process::Command;

use barylab::animate::palette::Palette;
use barylab::animate::visit::visit_order;
use barylab::raster::settings::Rasterizer;
use barylab::scene::Scene;
use image::{AnimationDecoder, RgbaImage};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn barylab(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_barylab"))
        .current_dir(root())
        .args(args)
        .output()
        .expect("run barylab")
}

/// Runs barylab, expecting success.
fn ok(args: &[&str]) -> String {
    let out = barylab(args);
    assert!(
        out.status.success(),
        "barylab {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// Runs barylab, expecting failure; its message.
fn fails(args: &[&str]) -> String {
    let out = barylab(args);
    assert!(!out.status.success(), "barylab {args:?} should fail");
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn path_str(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

fn read(path: &Path) -> std::io::BufReader<std::fs::File> {
    std::io::BufReader::new(std::fs::File::open(path).expect("open the animation"))
}

/// Every frame of an animation, composited, as the image library plays it.
fn frames(path: &Path) -> Vec<RgbaImage> {
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
    let frames = match ext {
        "gif" => image::codecs::gif::GifDecoder::new(read(path))
            .expect("a GIF")
            .into_frames()
            .collect_frames(),
        "webp" => image::codecs::webp::WebPDecoder::new(read(path))
            .expect("a WebP")
            .into_frames()
            .collect_frames(),
        _ => image::codecs::png::PngDecoder::new(read(path))
            .expect("a PNG")
            .apng()
            .expect("an APNG")
            .into_frames()
            .collect_frames(),
    }
    .expect("decode the frames");
    frames.into_iter().map(|f| f.into_buffer()).collect()
}

/// The still figure `barylab figure SCENE ARGS` draws, on white.
fn still(dir: &Path, name: &str, scene: &str, args: &[&str]) -> RgbaImage {
    let out = dir.join(format!("{name}.png"));
    let mut all = vec!["figure", scene, "--background", "white"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["-o", path_str(&out)]);
    ok(&all);
    image::open(&out).expect("the still").to_rgba8()
}

/// Count, size, and that every frame differs from the one before.
fn check_frames(frames: &[RgbaImage], count: usize) {
    assert_eq!(frames.len(), count, "frame count");
    let dims = frames[0].dimensions();
    for (i, f) in frames.iter().enumerate() {
        assert_eq!(f.dimensions(), dims, "frame {i} size");
    }
    for (i, pair) in frames.windows(2).enumerate() {
        assert_ne!(pair[0], pair[1], "frames {i} and {} are the same", i + 1);
    }
}

/// The mean absolute channel difference of two images of one size.
fn mean_difference(a: &RgbaImage, b: &RgbaImage) -> f64 {
    assert_eq!(a.dimensions(), b.dimensions(), "sizes");
    let sum: u64 = a
        .as_raw()
        .iter()
        .zip(b.as_raw())
        .map(|(x, y)| u64::from(x.abs_diff(*y)))
        .sum();
    sum as f64 / a.as_raw().len() as f64
}

/// A GIF frame against the still it should show: every white pixel of the still (the
/// margins, the white image background: flat colours) exactly white, the rest close.
fn gif_matches(frame: &RgbaImage, still: &RgbaImage) {
    for (p, q) in frame.pixels().zip(still.pixels()) {
        if q.0 == [255, 255, 255, 255] {
            assert_eq!(p.0, q.0, "a flat white pixel changed");
        }
    }
    let d = mean_difference(frame, still);
    assert!(d < 4.0, "mean difference {d} levels");
}

const SCENE: &str = "assets/scenes/default.json";

#[test]
fn the_wipe_from_affine_to_perspective_plays_and_its_ends_are_the_still_figures() {
    let dir = tempfile::tempdir().expect("tempdir");
    let small = ["--size", "160x120"];
    let affine = still(
        dir.path(),
        "affine",
        SCENE,
        &[&small[..], &["--compare", "wipe", "--wipe", "1"]].concat(),
    );
    let perspective = still(
        dir.path(),
        "persp",
        SCENE,
        &[&small[..], &["--compare", "wipe", "--wipe", "0"]].concat(),
    );
    for ext in ["apng", "gif"] {
        let out = dir.path().join(format!("wipe.{ext}"));
        let report = ok(&[
            "animate",
            SCENE,
            "--size",
            "160x120",
            "--sweep",
            "affine-perspective",
            "--frames",
            "6",
            "-o",
            path_str(&out),
        ]);
        assert!(report.contains("6 frames"), "{report}");
        let bytes = std::fs::metadata(&out).expect("written").len();
        assert!(
            report.contains("KiB") || report.contains("bytes"),
            "size reported: {report}"
        );
        assert!(bytes > 0);
        let f = frames(&out);
        check_frames(&f, 6);
        if ext == "apng" {
            // Lossless: pixel for pixel the still figures.
            assert!(f[0] == affine, "first frame = the affine still");
            assert!(
                f[5] == perspective,
                "last frame = the perspective-correct still"
            );
        } else {
            gif_matches(&f[0], &affine);
            gif_matches(&f[5], &perspective);
        }
    }
}

/// The default scene with corner C at `eye + 8 (C - eye)`: pushed along its view ray, its w
/// eight times larger (the camera's eye is (0, 1.5, 1.2), C is (1.2, 0, -4.8)).
fn pushed_scene(dir: &Path) -> PathBuf {
    let text = std::fs::read_to_string(root().join(SCENE)).expect("scene");
    let pushed = text.replace(
        "\"position\": [1.2, 0.0, -4.8]",
        "\"position\": [9.6, -10.5, -46.8]",
    );
    assert_ne!(pushed, text, "corner C replaced");
    let path = dir.join("pushed.json");
    std::fs::write(&path, pushed).expect("write scene");
    path
}

#[test]
fn the_depth_push_plays_and_ends_at_w_times_eight() {
    let dir = tempfile::tempdir().expect("tempdir");
    let start = still(dir.path(), "start", SCENE, &["--size", "160x120"]);
    let pushed = pushed_scene(dir.path());
    let end = still(dir.path(), "end", path_str(&pushed), &["--size", "160x120"]);
    for ext in ["apng", "gif"] {
        let out = dir.path().join(format!("depth.{ext}"));
        ok(&[
            "animate",
            SCENE,
            "--size",
            "160x120",
            "--sweep",
            "depth",
            "--frames",
            "5",
            "-o",
            path_str(&out),
        ]);
        let f = frames(&out);
        check_frames(&f, 5);
        if ext == "apng" {
            assert!(f[0] == start, "first frame = the scene's still");
            // The push is made in steps of at most 2x through the view transform: allow the
            // last bit of a few pixels' colour.
            let d = mean_difference(&f[4], &end);
            assert!(
                d < 0.01,
                "last frame = the still with C pushed 8x (mean difference {d})"
            );
        } else {
            gif_matches(&f[0], &start);
            gif_matches(&f[4], &end);
        }
    }
}

#[test]
fn the_fill_sweeps_end_on_the_still_figure_and_start_empty() {
    let dir = tempfile::tempdir().expect("tempdir");
    let args = ["--size", "24x18", "--pixel-size", "8", "--no-handles"];
    let full = still(dir.path(), "full", SCENE, &args);
    for sweep in ["fill-edge", "fill-scanline"] {
        let out = dir.path().join(format!("{sweep}.webp"));
        let mut all = vec!["animate", SCENE, "--sweep", sweep, "--frames", "8"];
        all.extend_from_slice(&args);
        all.extend_from_slice(&["-o", path_str(&out)]);
        ok(&all);
        let f = frames(&out);
        check_frames(&f, 8);
        assert!(f[7] == full, "{sweep}: the last frame is the still figure");
        // The first frame has drawn nothing yet: it differs from the still, and a later
        // frame differs from it by more (more pixels drawn).
        let first = &f[0];
        let drawn = |g: &RgbaImage| {
            g.pixels()
                .zip(first.pixels())
                .filter(|(p, q)| p != q)
                .count()
        };
        assert!(0 < drawn(&f[3]) && drawn(&f[3]) < drawn(&f[7]));
    }
}

#[test]
fn both_rasterizers_visit_the_covered_pixels_each_in_its_own_order() {
    let mut scene = Scene::load(&root().join(SCENE)).expect("scene");
    scene.set_size(40, 30);
    let mesh = scene.to_mesh();
    let settings = scene.settings();
    let edge = visit_order(&mesh, &settings, Rasterizer::EdgeFunction).expect("edge order");
    let scan = visit_order(&mesh, &settings, Rasterizer::Scanline).expect("scanline order");
    // The same pixels: the ones the render covers.
    let texture = scene
        .load_texture(&root().join("assets/scenes"))
        .expect("texture");
    let render = barylab::raster::render(&mesh, &texture, &settings).expect("render");
    let mut covered: Vec<[u32; 2]> = (0..30)
        .flat_map(|y| (0..40).map(move |x| [x, y]))
        .filter(|&[x, y]| {
            render.frame.triangle[(y * 40 + x) as usize] != barylab::raster::NO_TRIANGLE
        })
        .collect();
    covered.sort_unstable();
    for order in [&edge, &scan] {
        let mut set = order.clone();
        set.sort_unstable();
        set.dedup();
        assert_eq!(set, covered);
    }
    assert_ne!(edge, scan, "the orders differ");
    // Each order again from the render: triangle by triangle (mesh order) the pixels it owns,
    // sorted row by row (scanline) or by 8x8 block from the bounds' corner, then row by row
    // (edge functions).
    let prepared = barylab::raster::render::prepare_triangles(&mesh, &settings).expect("set-up");
    let (mut want_edge, mut want_scan) = (Vec::new(), Vec::new());
    for t in &prepared {
        for setup in &t.setups {
            let b = setup.bounds;
            let mut own: Vec<[u32; 2]> = covered
                .iter()
                .copied()
                .filter(|&[x, y]| render.frame.triangle[(y * 40 + x) as usize] == t.source)
                .collect();
            own.sort_unstable_by_key(|&[x, y]| (y, x));
            want_scan.extend(own.iter().copied());
            own.sort_unstable_by_key(|&[x, y]| ((y - b.y0) / 8, (x - b.x0) / 8, y, x));
            want_edge.extend(own);
        }
    }
    assert_eq!(scan, want_scan);
    assert_eq!(edge, want_edge);
}

#[test]
fn a_palette_of_few_colours_is_exact_and_flat_colours_stay_exact_with_many() {
    // Few colours: exact.
    let mut a = RgbaImage::from_pixel(8, 8, image::Rgba([10, 20, 30, 255]));
    a.put_pixel(3, 3, image::Rgba([200, 100, 0, 255]));
    let b = RgbaImage::from_pixel(8, 8, image::Rgba([0, 0, 0, 0]));
    let p = Palette::of(&[a.clone(), b.clone()]);
    assert_eq!(p.colors.len(), 3, "two colours and the transparent entry");
    let t = p.transparent.expect("a transparent entry");
    let ia = p.indices(&a);
    assert_eq!(p.colors[usize::from(ia[0])], [10, 20, 30]);
    assert_eq!(p.colors[usize::from(ia[3 * 8 + 3])], [200, 100, 0]);
    assert!(p.indices(&b).iter().all(|&i| i == t));
    // Many colours (a 64x64 ramp, 4096 of them) beside a flat half: the flat colour exact.
    let ramp = RgbaImage::from_fn(128, 64, |x, y| {
        if x < 64 {
            image::Rgba([(x * 4) as u8, (y * 4) as u8, 128, 255])
        } else {
            image::Rgba([255, 255, 255, 255])
        }
    });
    let p = Palette::of(std::slice::from_ref(&ramp));
    assert!(p.colors.len() <= 256);
    assert_eq!(p.transparent, None);
    let idx = p.indices(&ramp);
    assert_eq!(p.colors[usize::from(idx[100])], [255, 255, 255]);
    // And the ramp close: within a few levels on average.
    let err: u32 = ramp
        .pixels()
        .zip(&idx)
        .map(|(q, &i)| {
            let c = p.colors[usize::from(i)];
            (0..3).map(|k| u32::from(c[k].abs_diff(q[k]))).sum::<u32>()
        })
        .sum();
    assert!(f64::from(err) / (128.0 * 64.0 * 3.0) < 6.0);
}

#[test]
fn the_row_sweep_walks_the_pinned_row_with_its_caption() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("row.gif");
    ok(&[
        "animate",
        SCENE,
        "--size",
        "160x120",
        "--sweep",
        "row",
        "--pixel",
        "80,80",
        "--frames",
        "4",
        "-o",
        path_str(&out),
    ]);
    let f = frames(&out);
    check_frames(&f, 4);
    // The caption makes the frames taller than the figure without it.
    let plain = still(dir.path(), "plain", SCENE, &["--size", "160x120"]);
    assert!(f[0].height() > plain.height());
}

#[test]
fn bad_arguments_get_clear_messages() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("a.gif");
    let o = path_str(&out);
    let msg = fails(&["animate", SCENE, "--sweep", "spin", "-o", o]);
    assert!(
        msg.contains("spin") && msg.contains("fill-scanline"),
        "{msg}"
    );
    let msg = fails(&[
        "animate",
        SCENE,
        "--sweep",
        "depth",
        "-o",
        "/nonexistent-dir/a.gif",
    ]);
    assert!(msg.contains("/nonexistent-dir"), "{msg}");
    let msg = fails(&[
        "animate",
        SCENE,
        "--sweep",
        "depth",
        "-o",
        &format!("{o}.svg"),
    ]);
    assert!(msg.contains(".svg") || msg.contains("gif"), "{msg}");
    // An image opened as the scene is never overwritten by the animation.
    let tex = dir.path().join("tex.png");
    image::RgbaImage::from_pixel(4, 4, image::Rgba([1, 2, 3, 255]))
        .save(&tex)
        .expect("image");
    let before = std::fs::read(&tex).expect("read");
    let msg = fails(&[
        "animate",
        path_str(&tex),
        "--sweep",
        "depth",
        "--frames",
        "2",
        "-o",
        path_str(&tex),
    ]);
    assert!(msg.contains("input"), "{msg}");
    assert_eq!(
        std::fs::read(&tex).expect("read"),
        before,
        "input unchanged"
    );
    let msg = fails(&[
        "animate", SCENE, "--sweep", "tilt", "--frames", "1", "-o", o,
    ]);
    assert!(msg.contains("--frames"), "{msg}");
    let msg = fails(&[
        "animate",
        "assets/scenes/rgb-triangle.json",
        "--sweep",
        "tilt",
        "-o",
        o,
    ]);
    assert!(msg.contains("tilt") && msg.contains("quad"), "{msg}");
    // MP4 without ffmpeg says what to install; with it, a file is written.
    let mp4 = dir.path().join("a.mp4");
    let has_ffmpeg = Command::new("ffmpeg").arg("-version").output().is_ok();
    let args = [
        "animate",
        SCENE,
        "--size",
        "64x48",
        "--sweep",
        "depth",
        "--frames",
        "3",
        "-o",
        path_str(&mp4),
    ];
    if has_ffmpeg {
        ok(&args);
        assert!(std::fs::metadata(&mp4).expect("mp4").len() > 0);
    } else {
        let msg = fails(&args);
        assert!(msg.contains("ffmpeg"), "{msg}");
        assert!(!mp4.exists());
    }
    assert!(!out.exists(), "no output after a failure");
}
