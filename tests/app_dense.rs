//! Dense scenes in the app: vertex handles and labels only for a few vertices, else only for
//! the pinned and hovered triangles' corners (issue 30; every handle cost a widget and a text
//! layout each frame, and bench-mesh-5k took 42 s to its first frame).

mod common;

use barylab::app::document::state::StateCommand;
use barylab::app::{AppOptions, BaryApp};
use egui_kittest::Harness;

const SIZE: egui::Vec2 = egui::vec2(1500.0, 950.0);

fn open(path: &str) -> Harness<'static, BaryApp> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(path);
    let opened = barylab::scene::open_input(&path).expect("the scene opens");
    common::app::harness(
        SIZE,
        AppOptions {
            scene: Some(opened),
            ..AppOptions::default()
        },
    )
}

#[test]
fn a_few_vertices_all_have_handles() {
    let h = open("assets/scenes/default.json");
    assert_eq!(h.state().canvas().handles, [0, 1, 2, 3]);
}

#[test]
fn a_dense_mesh_shows_only_the_pinned_triangles_handles() {
    let mut h = open("assets/bench/bench-mesh-5k.json");
    assert!(h.state().canvas().output.is_some(), "rendered");
    assert_eq!(h.state().canvas().handles, Vec::<usize>::new());
    h.state_mut().push(StateCommand::Pin(Some([500, 500])));
    h.run();
    let mark = h.state().pin_report().expect("pinned").mark();
    let corners: Vec<usize> = mark
        .triangle
        .expect("the pixel is covered")
        .mesh_indices
        .into_iter()
        .flatten()
        .collect();
    assert_eq!(corners.len(), 3);
    // Drawn the frame after the pin's report exists.
    h.run();
    assert_eq!(h.state().canvas().handles, corners);
    assert!(
        corners.iter().all(|&k| k > 3),
        "inner vertices: {corners:?}"
    );
}
