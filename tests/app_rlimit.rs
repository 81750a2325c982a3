//! The app under an address-space limit (`ulimit -v`, issue 30): a picture too large for
//! what the process may have is a message in the window (and on stderr), never an abort in
//! the allocator (exit 134).

mod common;

use common::xvfb::{start_xvfb, xvfb_or_skip};

/// The address space the app may have: enough for the window and Mesa, not for a
/// 16384x16384 picture (its colour buffer alone is 1 GiB, the render about 3 GiB).
const ADDRESS_LIMIT: u64 = 3_000_000 * 1024;

/// Runs the app on `display` under [`ADDRESS_LIMIT`] without the tests' memory limit;
/// returns (exit code, stderr).
fn run_limited(display: &str, args: &[&str]) -> (Option<i32>, String) {
    let mut c = common::xvfb::app_command(display, args);
    c.env_remove("BARYLAB_MEMORY_LIMIT");
    common::limit_address_space(&mut c, ADDRESS_LIMIT);
    let (status, _, err) = common::xvfb::run_to_end(c);
    (status.code(), err)
}

#[test]
fn a_picture_past_the_address_space_limit_is_a_message_in_the_window() {
    let Some(xvfb) = xvfb_or_skip("app_rlimit") else {
        return;
    };
    let x = start_xvfb(&xvfb);
    let dir = tempfile::tempdir().expect("tempdir");
    let mut scene: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/assets/scenes/default.json"
        ))
        .expect("default scene"),
    )
    .expect("scene JSON");
    scene["width"] = 16384.into();
    scene["height"] = 16384.into();
    let scene_path = dir.path().join("huge.json");
    std::fs::write(&scene_path, scene.to_string()).expect("write scene");
    let scene_arg = scene_path.to_str().expect("utf-8 path");
    let shot = dir.path().join("shot.png");
    let shot_arg = shot.to_str().expect("utf-8 path");
    let common = [
        "--fresh",
        "--window-size",
        "1024x768",
        "--screenshot",
        shot_arg,
    ];

    // The default budget follows the address-space limit: the render is refused by its
    // estimate, and the message says where the limit came from.
    let (code, err) = run_limited(&x.display, &[&common[..], &[scene_arg]].concat());
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.contains("a 16384x16384 render of 2 triangles needs about")
            && err.contains("address space limit (ulimit -v)"),
        "{err}"
    );
    assert!(shot.is_file(), "the window was saved: {err}");

    // A limit set by hand lets the estimate pass; the system then refuses the colour
    // buffer, and that too is a message, not an abort.
    std::fs::remove_file(&shot).expect("remove shot");
    let (code, err) = run_limited(
        &x.display,
        &[&common[..], &["--memory-limit", "64G", scene_arg]].concat(),
    );
    assert_eq!(code, Some(0), "exit 134 is the allocator's abort: {err}");
    assert!(
        err.contains("cannot allocate") && err.contains("the system refused the memory"),
        "{err}"
    );
    assert!(shot.is_file(), "the window was saved: {err}");
}
