//! Over the memory budget in the app (issue 30): the canvas says so, in the picture's place,
//! instead of an older picture with the new scene's handles crammed over it.

mod common;

use barylab::app::AppOptions;
use barylab::app::document::state::StateCommand;
use egui_kittest::kittest::Queryable;

#[test]
fn a_picture_over_the_memory_budget_is_a_message_in_the_window() {
    // The whole test binary runs under this limit: 800x600 fits, 4096x4096 does not.
    barylab::budget::set_limit(64 << 20);
    let mut h = common::app::harness(egui::vec2(1500.0, 950.0), AppOptions::default());
    h.state_mut()
        .push(StateCommand::SetImageSize(Some([800, 600])));
    h.run();
    assert!(h.state().canvas().error.is_none());
    assert_eq!(h.state().canvas().handles, [0, 1, 2, 3]);
    h.state_mut()
        .push(StateCommand::SetImageSize(Some([4096, 4096])));
    h.run();
    let e = h.state().canvas().error.clone().expect("refused");
    assert!(e.memory, "{e:?}");
    assert!(
        e.text
            .starts_with("a 4096x4096 render of 2 triangles needs about")
            && e.text
                .contains("more than the limit of 64.0 MiB (--memory-limit)"),
        "{e:?}"
    );
    h.get_by_label_contains(
        "This picture does not fit in the memory barylab may use: a 4096x4096 render",
    );
    h.get_by_label_contains("Choose a smaller image size");
    assert_eq!(
        h.state().canvas().handles,
        Vec::<usize>::new(),
        "no handles over nothing"
    );
    // A size that fits is drawn again.
    h.state_mut()
        .push(StateCommand::SetImageSize(Some([320, 240])));
    h.run();
    assert!(h.state().canvas().error.is_none());
    assert_eq!(
        h.state().canvas().output.as_ref().expect("drawn").size,
        [320, 240]
    );
    assert!(h.query_by_label_contains("does not fit").is_none());
}
