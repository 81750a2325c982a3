//! A recorded drag as an animation, without the GUI: a list of states (one per frame, as the
//! app's recorder takes them) drawn by `animate::render_states`, encoded as GIF and APNG and
//! decoded again: frame count, size, frames that change exactly where the scene changed, and
//! frame k equal to the still figure of state k. The recorder's ticks, trim and cap.

use std::path::Path;
use std::sync::atomic::Ordering;

use barylab::animate::{self, AnimateError, Control, Format, FrameState};
use barylab::app::services::recorder::{RECORD_FPS, RECORD_MAX_FRAMES, Recorder};
use barylab::edit::move_vertex_to;
use barylab::figure::{Background, Figure, FigureOptions, png};
use barylab::i18n::Lang;
use barylab::raster::Texture;
use barylab::raster::project::Viewport;
use barylab::scene::Scene;
use glam::DVec2;
use image::{AnimationDecoder, RgbaImage};

const SIZE: (u32, u32) = (160, 120);

fn scene_and_texture() -> (Scene, Texture) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let json = std::fs::read_to_string(root.join("default.json")).expect("the default scene");
    let mut scene = Scene::from_json(&json, "default.json").expect("a scene");
    scene.set_size(SIZE.0, SIZE.1);
    let texture = scene.load_texture(&root).expect("its texture");
    (scene, texture)
}

/// A drag of corner C: two frames still, then four steps of 6 pixels right and 4 up.
fn recorded_drag(scene: &Scene) -> Vec<FrameState> {
    let options = FigureOptions {
        pinned: Some([80, 60]),
        background: Background::White,
        ..FigureOptions::default()
    };
    let viewport = Viewport {
        width: SIZE.0,
        height: SIZE.1,
    };
    let start = DVec2::new(120.0, 40.0);
    let mut states = Vec::new();
    for k in [0.0, 0.0, 1.0, 2.0, 3.0, 4.0] {
        let mut s = scene.clone();
        move_vertex_to(&mut s, 2, start + DVec2::new(6.0 * k, -4.0 * k), viewport)
            .expect("C moves");
        states.push(FrameState {
            scene: s,
            options: options.clone(),
            filled: None,
        });
    }
    states
}

/// The still figure of a state, drawn as `barylab figure` draws it.
fn still(state: &FrameState, texture: &Texture) -> RgbaImage {
    let fig = Figure::compose_in(&state.scene, texture, &state.options, Lang::En).expect("figure");
    png::rasterize(&fig).expect("rasterized")
}

fn decode(bytes: &[u8], format: Format) -> Vec<RgbaImage> {
    let cursor = std::io::Cursor::new(bytes);
    let frames = match format {
        Format::Gif => image::codecs::gif::GifDecoder::new(cursor)
            .expect("a GIF")
            .into_frames()
            .collect_frames(),
        _ => image::codecs::png::PngDecoder::new(cursor)
            .expect("a PNG")
            .apng()
            .expect("an APNG")
            .into_frames()
            .collect_frames(),
    }
    .expect("the frames decode");
    frames.into_iter().map(|f| f.into_buffer()).collect()
}

#[test]
fn a_recorded_drag_plays_frame_by_frame_as_the_still_figures_of_its_states() {
    let (scene, texture) = scene_and_texture();
    let states = recorded_drag(&scene);
    let frames =
        animate::render_states(&states, &texture, Lang::En, &Control::default()).expect("rendered");
    let stills: Vec<RgbaImage> = states.iter().map(|s| still(s, &texture)).collect();
    let dims = stills[0].dimensions();
    assert!(
        dims.0 >= SIZE.0 && dims.1 >= SIZE.1,
        "a figure of the image"
    );

    let apng = decode(
        &animate::encode(&frames, RECORD_FPS, Format::Apng).expect("APNG"),
        Format::Apng,
    );
    assert_eq!(apng.len(), states.len(), "APNG frame count");
    for (k, (f, s)) in apng.iter().zip(&stills).enumerate() {
        assert_eq!(f.dimensions(), dims, "APNG frame {k} size");
        assert!(
            f == s,
            "APNG frame {k} is not the still figure of state {k}"
        );
    }

    let gif = decode(
        &animate::encode(&frames, RECORD_FPS, Format::Gif).expect("GIF"),
        Format::Gif,
    );
    assert_eq!(gif.len(), states.len(), "GIF frame count");
    for f in &gif {
        assert_eq!(f.dimensions(), dims, "GIF frame size");
    }
    // The first two states are one scene: the same picture; then C moves every frame.
    assert!(gif[0] == gif[1], "an unchanged state changed the picture");
    for k in 1..gif.len() - 1 {
        assert!(
            gif[k] != gif[k + 1],
            "frames {k} and {} are the same",
            k + 1
        );
    }
    // The GIF's one palette keeps the flat white margins exact.
    for (f, s) in gif.iter().zip(&stills) {
        for (p, q) in f.pixels().zip(s.pixels()) {
            if q.0 == [255, 255, 255, 255] {
                assert_eq!(p.0, q.0, "a white pixel changed colour");
            }
        }
    }
}

#[test]
fn a_recording_needs_two_frames_and_stops_when_cancelled() {
    let (scene, texture) = scene_and_texture();
    let states = recorded_drag(&scene);
    let err = animate::render_states(&states[..1], &texture, Lang::En, &Control::default())
        .expect_err("one frame is no animation");
    assert!(matches!(err, AnimateError::Frames(1)), "{err}");
    assert!(err.to_string().contains("2 to 1000 frames"), "{err}");

    let control = Control::default();
    control.cancel.store(true, Ordering::Relaxed);
    let err = animate::render_states(&states, &texture, Lang::En, &control).expect_err("cancelled");
    assert!(matches!(err, AnimateError::Cancelled), "{err}");
    assert_eq!(control.done.load(Ordering::Relaxed), 0);

    let control = Control::default();
    animate::render_states(&states, &texture, Lang::En, &control).expect("rendered");
    assert_eq!(control.done.load(Ordering::Relaxed), states.len());
}

/// A state told apart by its pinned pixel's x.
fn state(scene: &Scene, x: u32) -> FrameState {
    FrameState {
        scene: scene.clone(),
        options: FigureOptions {
            pinned: Some([x, 0]),
            ..FigureOptions::default()
        },
        filled: None,
    }
}

fn pinned_xs(r: &Recorder) -> Vec<u32> {
    r.trimmed()
        .iter()
        .map(|s| s.options.pinned.expect("pinned")[0])
        .collect()
}

#[test]
fn the_recorder_takes_one_state_per_tick_of_egui_time_and_stops_at_its_cap() {
    let (scene, _) = scene_and_texture();
    let mut r = Recorder::default();
    assert!(!r.capture(0.0, || state(&scene, 9)), "not recording");
    assert!(r.is_empty());

    r.start(10.0);
    assert!(r.recording());
    r.capture(10.0, || state(&scene, 1)); // tick 0
    r.capture(10.03, || panic!("no tick is due before 10.04"));
    // A frame 0.1 s later fills ticks 1 and 2 (10.04, 10.08) with its state.
    r.capture(10.1, || state(&scene, 2));
    r.capture(10.125, || state(&scene, 3)); // tick 3 (10.12)
    r.stop();
    assert!(!r.recording());
    assert_eq!(r.len(), 4);
    assert_eq!(pinned_xs(&r), [1, 2, 2, 3]);
    assert_eq!(r.trim, (0, 3));
    r.set_trim(1, 2);
    assert_eq!(pinned_xs(&r), [2, 2]);
    r.set_trim(3, 99);
    assert_eq!(r.trim, (3, 3), "kept inside the frames");

    // A long recording stops at the cap, with the frames it has.
    r.start(0.0);
    r.capture(0.0, || state(&scene, 1));
    let seconds = RECORD_MAX_FRAMES as f64 / RECORD_FPS;
    assert!(!r.capture(seconds - 0.5, || state(&scene, 2)));
    assert!(r.capture(seconds + 60.0, || state(&scene, 3)), "capped now");
    assert!(r.capped && !r.recording());
    assert_eq!(r.len(), RECORD_MAX_FRAMES);
}
