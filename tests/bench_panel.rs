//! The benchmark window driven through egui_kittest: open it from the top bar, run a tiny
//! benchmark (coarse pixels, 1 frame per configuration) and see the results.

use std::time::{Duration, Instant};

use barylab::app::document::state::StateCommand;
use barylab::app::{AppOptions, BaryApp};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

/// A run of 16 tiny configurations takes well under a second; this only bounds a hang.
const RUN_TIMEOUT: Duration = Duration::from_secs(60);

#[test]
fn the_benchmark_window_measures_the_canvas_and_shows_the_table() {
    let app = BaryApp::new(None, AppOptions::default());
    let mut h = Harness::builder()
        .with_size(egui::vec2(1500.0, 950.0))
        .with_max_steps(30)
        .build_ui_state(|ui, app: &mut BaryApp| app.show(ui), app);
    // Coarse pixels: a small canvas to render.
    h.state_mut().push(StateCommand::SetImageSize(None));
    h.state_mut().push(StateCommand::SetPixelSize(16));
    h.run();
    let size = h.state().canvas().output.as_ref().expect("rendered").size;
    assert!(size[0] < 100 && size[1] < 100, "canvas {size:?}");

    assert!(!h.state().bench().open);
    h.get_by_label("Benchmark").click();
    h.run();
    assert!(
        h.state().bench().open,
        "the top-bar button opens the window"
    );
    assert!(h.query_by_label("Press Run to measure.").is_some());

    h.state_mut().bench_mut().frames = 1;
    h.get_by_label("Run").click();
    h.run();
    let start = Instant::now();
    while h.state().bench().is_running() {
        assert!(start.elapsed() < RUN_TIMEOUT, "benchmark did not finish");
        std::thread::sleep(Duration::from_millis(20));
        h.run();
    }
    h.run();
    let bench = h.state().bench();
    assert_eq!(bench.error(), None);
    let records = bench.records();
    let expected = barylab::bench::matrix(barylab::bench::available_cores());
    assert_eq!(records.len(), expected.len());
    for (r, c) in records.iter().zip(&expected) {
        assert_eq!([r.width, r.height], size, "measured at the canvas size");
        assert_eq!(r.threads, c.threads);
        assert!(r.median_ms > 0.0);
    }
    // The table, the ratio next to the seed's claim, and the measured scene are shown.
    assert!(h.query_by_label("edge / scanline").is_some());
    assert!(
        h.query_by_label_contains("Measured here: edge functions take")
            .is_some()
    );
    assert!(
        h.query_by_label_contains(&format!("current scene, {} x {}", size[0], size[1]))
            .is_some()
    );
    assert!(h.query_by_label_contains("1.40 ms vs 0.73 ms").is_some());
    assert!(h.query_by_label("Press Run to measure.").is_none());
}
