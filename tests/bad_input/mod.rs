//! Helpers of the bad-input tests (`tests/robust.rs`, `tests/messages.rs`): the real binary
//! with a fixed memory limit, and checks that a failure is one line without a panic.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

pub fn bin() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_barylab"));
    // A fixed limit, so the tests do not depend on the machine's memory.
    c.env("BARYLAB_MEMORY_LIMIT", "4G");
    c
}

pub fn run(args: &[&str]) -> Output {
    bin().args(args).output().expect("run barylab")
}

pub fn scene(name: &str) -> String {
    format!("{}/assets/scenes/{name}", env!("CARGO_MANIFEST_DIR"))
}

pub fn data(name: &str) -> String {
    format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"))
}

pub fn s(p: &Path) -> &str {
    p.to_str().expect("utf-8 path")
}

pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Runs a command that must fail with exit code 1 (2 for a bad option) and a one-line error
/// (no panic, no blank line); returns the error.
pub fn fails(args: &[&str]) -> String {
    fails_with(&mut bin(), args)
}

pub fn fails_with(cmd: &mut Command, args: &[&str]) -> String {
    let out = cmd.args(args).output().expect("run barylab");
    let err = stderr(&out);
    // 1 for bad input, 2 for a bad option (clap's usage errors); never a signal.
    assert!(
        matches!(out.status.code(), Some(1 | 2)),
        "{args:?}: {:?} {err}",
        out.status
    );
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    assert_eq!(
        err.matches('\n').count(),
        1,
        "{args:?}: not one line:\n{err}"
    );
    assert!(err.starts_with("error: ") && err.ends_with('\n'), "{err}");
    err
}

/// Runs a command that must succeed; returns its standard error (notes).
pub fn succeeds(args: &[&str]) -> String {
    let out = run(args);
    assert!(out.status.success(), "{args:?}: {}", stderr(&out));
    stderr(&out)
}

/// Whether a command-line tool is there. Under CI (`CI=true`) a missing tool fails the test
/// instead of skipping it.
pub fn tool(name: &str) -> bool {
    let found = Command::new(name)
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok();
    if !found {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "{name} is needed by this test under CI"
        );
        eprintln!("skipped: {name} is not installed");
    }
    found
}

pub fn mkfifo(path: &Path) {
    let ok = Command::new("mkfifo")
        .arg(path)
        .status()
        .expect("mkfifo")
        .success();
    assert!(ok, "mkfifo {}", path.display());
}

/// Files in `dir` whose name starts with the temporary prefix.
pub fn temporary_files(dir: &Path) -> Vec<PathBuf> {
    std::fs::read_dir(dir)
        .expect("read dir")
        .map(|e| e.expect("entry").path())
        .filter(|p| {
            p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with(".barylab-"))
        })
        .collect()
}

/// Writes a lesson of one step showing the scene file `scene` (relative to the lesson) to
/// `path`, with the same text in both languages.
pub fn write_one_step_lesson(path: &Path, scene: &str) {
    let both = |t: &str| serde_json::json!({"en": t, "zh": t});
    let lesson = serde_json::json!({
        "title": both("t"),
        "steps": [{"title": both("one"), "text": both("x"), "try": both("y"), "scene": scene}]
    });
    std::fs::write(path, lesson.to_string()).expect("write lesson");
}
