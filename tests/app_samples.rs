//! Samples in the app: the samples control's command changes the scene's samples, the canvas
//! renders them, and the pinned pixel's magnifier gets every sample of the 7 x 7 pixels around
//! it (filled by triangle where covered), none with one sample per pixel.

mod common;

use barylab::app::document::state::StateCommand;
use barylab::app::{AppOptions, BaryApp};
use barylab::figure::overlay::{MAGNIFIER_RADIUS_SAMPLES, magnifier_radius};
use barylab::raster::sample::{SampleCount, SampleSettings};
use egui_kittest::Harness;

fn open() -> Harness<'static, BaryApp> {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/games101-a2.json");
    let opened = barylab::scene::open_input(&path).expect("the scene opens");
    let mut h = common::app::harness(
        egui::vec2(1500.0, 950.0),
        AppOptions {
            scene: Some(opened),
            ..AppOptions::default()
        },
    );
    h.state_mut()
        .push(StateCommand::SetImageSize(Some([120, 120])));
    h.run();
    h
}

#[test]
fn the_pinned_pixels_magnifier_gets_every_sample_around_it() {
    let mut h = open();
    h.state_mut().push(StateCommand::Pin(Some([70, 55])));
    h.run();
    let report = h.state().pin_report().expect("pinned");
    assert!(
        report.sample_marks.is_empty(),
        "one sample: the centres only"
    );

    h.state_mut().push(StateCommand::SetSamples(SampleSettings {
        count: SampleCount::Four,
        ..SampleSettings::default()
    }));
    h.run();
    assert_eq!(h.state().state().scene.samples().count, SampleCount::Four);
    let report = h.state().pin_report().expect("pinned");
    let side = (2 * magnifier_radius(true) + 1) as usize;
    assert_eq!(side, 2 * MAGNIFIER_RADIUS_SAMPLES as usize + 1);
    assert_eq!(report.sample_marks.len(), side * side * 4);
    // The pinned pixel lies inside the front triangle: its four samples are that triangle's.
    let own: Vec<_> = report
        .sample_marks
        .iter()
        .filter(|m| m.position.x.floor() == 70.0 && m.position.y.floor() == 55.0)
        .collect();
    assert_eq!(own.len(), 4);
    let triangle = report.trace.written_by;
    assert!(triangle.is_some(), "covered");
    assert!(own.iter().all(|m| m.triangle == triangle), "{own:?}");
    // The same samples as the inspector's list (the probe's trace of the pinned pixel).
    let listed: Vec<_> = report
        .trace
        .samples
        .iter()
        .map(|s| (s.position, s.triangle))
        .collect();
    let marked: Vec<_> = own
        .iter()
        .map(|m| (m.position.to_array(), m.triangle))
        .collect();
    assert_eq!(listed, marked);
    // Every mark lies in the magnified square.
    assert!(report.sample_marks.iter().all(|m| {
        (m.position.x - 70.5).abs() <= f64::from(MAGNIFIER_RADIUS_SAMPLES) + 0.5
            && (m.position.y - 55.5).abs() <= f64::from(MAGNIFIER_RADIUS_SAMPLES) + 0.5
    }));
}
