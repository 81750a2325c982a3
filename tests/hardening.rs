//! Hardening, round 2 (issue 30): no read of a /proc or /sys file (some block forever), no
//! output over any file the command read, and no temporary file left by an interrupted run.

mod bad_input;
mod common;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

use bad_input::{bin, data, fails, s, scene, stderr, temporary_files};

/// Longest a refused request may take: it must fail before reading anything.
const QUICK: Duration = Duration::from_secs(30);

/// Runs `cmd`, killing it (and failing the test) if it has not ended after [`QUICK`].
fn within_deadline(cmd: &mut Command) -> Output {
    let mut child = cmd
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("start barylab");
    let start = Instant::now();
    while child.try_wait().expect("wait").is_none() {
        if start.elapsed() > QUICK {
            let _ = child.kill();
            panic!("{cmd:?} still runs after {QUICK:?} (it hangs)");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().expect("output")
}

/// The default scene with `texture`, written to `dir/name`.
fn scene_with_texture(dir: &Path, name: &str, texture: &str) -> PathBuf {
    let text = std::fs::read_to_string(scene("default.json")).expect("default scene");
    let path = dir.join(name);
    let quoted = serde_json::to_string(texture).expect("json string");
    std::fs::write(&path, text.replace("\"uv-grid\"", &quoted)).expect("write scene");
    path
}

#[test]
fn files_of_proc_and_sys_are_refused_before_they_are_read() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = |n: &str| dir.path().join(n);
    let out = d("out.png");
    // /proc/kmsg blocks a read forever once the kernel's messages were read (as root); a
    // sysfs file reports 4096 bytes whatever it holds.
    let cases: Vec<(PathBuf, &str)> = vec![
        (
            scene_with_texture(dir.path(), "k.json", "/proc/kmsg"),
            "/proc",
        ),
        (
            scene_with_texture(dir.path(), "c.json", "/sys/devices/system/cpu/online"),
            "/sys",
        ),
    ];
    std::os::unix::fs::symlink("/proc/kmsg", d("kmsg.json")).expect("link");
    std::os::unix::fs::symlink("/proc/self/status", d("status.png")).expect("link");
    std::fs::write(
        d("m.obj"),
        "mtllib /proc/kmsg\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    )
    .expect("write");
    let mut cases = cases;
    cases.push((d("kmsg.json"), "/proc"));
    cases.push((d("status.png"), "/proc"));
    for (input, fs) in &cases {
        let o = within_deadline(bin().args(["render", s(input), "-o", s(&out)]));
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{input:?}: {err}");
        assert!(
            err.contains(&format!(
                "a file of the kernel's {fs} file system, not a regular file"
            )),
            "{input:?}: {err}"
        );
    }
    // A model's material library: the model is drawn without it, and the note says why.
    let o = within_deadline(bin().args(["render", s(&d("m.obj")), "-o", s(&out)]));
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("/proc/kmsg: it is a file of the kernel's /proc file system"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn no_output_replaces_a_file_the_command_read() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = |n: &str| dir.path().join(n);
    std::fs::copy(data("rgbw.png"), d("photo.png")).expect("copy");
    let photo = std::fs::read(d("photo.png")).expect("read");
    let is_input = |e: &str, input: &str| {
        assert!(
            e.contains("is an input of this command") && e.contains(input),
            "{e}"
        );
    };
    // The app's screenshot over the picture it opens, refused before the window opens.
    is_input(
        &fails(&["--screenshot", s(&d("photo.png")), s(&d("photo.png"))]),
        "photo.png",
    );
    // ... over the scene's texture, and over the image to compare.
    let sc = scene_with_texture(dir.path(), "s.json", "photo.png");
    is_input(
        &fails(&["--screenshot", s(&d("photo.png")), s(&sc)]),
        "photo.png",
    );
    is_input(
        &fails(&[
            "--screenshot",
            s(&d("photo.png")),
            "--compare-image",
            s(&d("photo.png")),
        ]),
        "photo.png",
    );
    // `render --aov DIR` over a texture in DIR (a PNG named uv.exr, read by its content).
    std::fs::create_dir(d("aov")).expect("mkdir");
    std::fs::copy(data("rgbw.png"), d("aov/uv.exr")).expect("copy");
    let sc = scene_with_texture(&d("aov"), "s.json", "uv.exr");
    is_input(
        &fails(&[
            "render",
            s(&sc),
            "--aov",
            s(&d("aov")),
            "-o",
            s(&d("o.png")),
        ]),
        "uv.exr",
    );
    assert_eq!(std::fs::read(d("aov/uv.exr")).expect("read"), photo);
    assert!(!d("o.png").exists(), "the PNG is not written either");
    // A lesson step's figure over the step scene's texture.
    scene_with_texture(dir.path(), "l.json", "photo.png");
    bad_input::write_one_step_lesson(&d("lesson.json"), "l.json");
    is_input(
        &fails(&[
            "lesson",
            s(&d("lesson.json")),
            "--step",
            "1",
            "--figure",
            s(&d("photo.png")),
        ]),
        "photo.png",
    );
    assert_eq!(std::fs::read(d("photo.png")).expect("read"), photo);
    assert_eq!(temporary_files(dir.path()), Vec::<PathBuf>::new());
}

#[test]
fn an_interrupted_write_leaves_no_temporary_file() {
    let dir = tempfile::tempdir().expect("tempdir");
    for signal in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP] {
        let aov = dir.path().join(format!("aov-{signal}"));
        let out = dir.path().join(format!("out-{signal}.png"));
        // Five float images of 9 million pixels after the PNG: seconds of writing.
        let mut child = bin()
            .args(["render", &scene("default.json"), "--size", "3000x3000"])
            .args(["--aov", s(&aov), "-o", s(&out)])
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .expect("start");
        // Wait for a temporary file with content (the folder check's empty one comes and
        // goes at the start).
        let start = Instant::now();
        let writing = |folder: &Path| {
            temporary_files(folder)
                .iter()
                .any(|p| std::fs::metadata(p).is_ok_and(|m| m.len() > 0))
        };
        while !(writing(dir.path()) || aov.exists() && writing(&aov)) {
            assert!(
                child.try_wait().expect("wait").is_none(),
                "the render ended before anything was seen written"
            );
            assert!(start.elapsed() < Duration::from_secs(120), "no write began");
            std::thread::sleep(Duration::from_millis(1));
        }
        let pid = i32::try_from(child.id()).expect("pid");
        // SAFETY: `pid` is our child, still running (not yet waited for).
        assert_eq!(unsafe { libc::kill(pid, signal) }, 0);
        let status = child.wait().expect("wait");
        assert_eq!(status.code(), Some(128 + signal), "signal {signal}");
        assert_eq!(temporary_files(dir.path()), Vec::<PathBuf>::new());
        assert_eq!(temporary_files(&aov), Vec::<PathBuf>::new());
        assert!(!out.exists(), "no output after the signal");
    }
}

/// The binary without the tests' fixed memory limit, under an address-space limit (`ulimit
/// -v`) of `bytes`.
fn under_address_limit(bytes: u64) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_barylab"));
    c.env_remove("BARYLAB_MEMORY_LIMIT");
    common::limit_address_space(&mut c, bytes);
    c
}

#[test]
fn the_default_memory_limit_respects_the_address_space_limit() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("o.png");
    const LIMIT: u64 = 3 << 30;
    // An 8192x8192 render needs about 3.8 GiB: more than the process may have, whatever the
    // machine's free memory. Refused with a message (it aborted in the allocator before).
    let o = within_deadline(under_address_limit(LIMIT).args([
        "render",
        &scene("default.json"),
        "--size",
        "8192x8192",
        "-o",
        s(&out),
    ]));
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.starts_with("error: a 8192x8192 render of 2 triangles needs about 3.8 GiB")
            && err.contains("of what the address space limit (ulimit -v) leaves this process"),
        "{err}"
    );
    // The limit is 75% of what is left: below 75% of 3 GiB.
    let limit = err
        .split("more than the limit of ")
        .nth(1)
        .and_then(|t| t.split(" GiB").next())
        .and_then(|t| t.parse::<f64>().ok())
        .expect("the limit in GiB");
    assert!(limit > 0.5 && limit < 2.25, "{err}");
    // A request within it is drawn.
    let o = within_deadline(under_address_limit(LIMIT).args([
        "render",
        &scene("default.json"),
        "-o",
        s(&out),
    ]));
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn a_refused_allocation_is_a_message_not_an_abort() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("o.png");
    // The limit set by hand lets the 15 GiB render past the estimate; the system's 2 GiB
    // address space refuses its first 1 GiB buffer past what the process holds. It aborted
    // (exit 134, "memory allocation of ... failed") before.
    let o = within_deadline(under_address_limit(2 << 30).args([
        "render",
        &scene("default.json"),
        "--size",
        "16384x16384",
        "-o",
        s(&out),
        "--memory-limit",
        "64G",
    ]));
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.starts_with("error: cannot allocate 1.0 GiB for the 16384x16384 ")
            && err.contains("buffer: the system refused the memory"),
        "{err}"
    );
    assert!(!out.exists());
}

#[test]
fn a_refused_sample_buffer_is_a_message_naming_it() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("o.png");
    // The frame's buffers (about 1 GiB) fit in the 3 GiB address space; the 16 samples of
    // each of its 16.8 million pixels (20 bytes each, 5.0 GiB) do not. The limit set by hand
    // lets it past the estimate, so the allocation itself is refused: it aborted before.
    let o = within_deadline(under_address_limit(3 << 30).args([
        "render",
        &scene("default.json"),
        "--size",
        "4096x4096",
        "--samples",
        "16",
        "-o",
        s(&out),
        "--memory-limit",
        "64G",
    ]));
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.starts_with(
            "error: cannot allocate 5.0 GiB for the 4096x4096 sample buffer (16 samples a pixel)"
        ) && err.contains("the system refused the memory"),
        "{err}"
    );
    assert!(!out.exists());
    // Under a small --memory-limit the estimate, which counts the samples, refuses it first.
    let e = fails(&[
        "render",
        &scene("default.json"),
        "--size",
        "1024x1024",
        "--samples",
        "16",
        "-o",
        s(&out),
        "--memory-limit",
        "200M",
    ]);
    assert!(
        e.starts_with(
            "error: a 1024x1024 render of 2 triangles with 16 samples a pixel needs about"
        ) && e.contains("more than the limit of 200.0 MiB (--memory-limit)"),
        "{e}"
    );
    assert!(!out.exists());
}

/// A render long enough for the progress line (past half a second: 16 million pixels of
/// every buffer), into `out`.
fn long_render(out: &Path) -> Vec<String> {
    [
        "render",
        &scene("default.json"),
        "--size",
        "4096x4096",
        "-o",
        s(out),
    ]
    .map(String::from)
    .to_vec()
}

#[test]
fn the_progress_line_is_for_a_terminal_only() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("o.png");
    // Standard error piped (a log, a script): not a byte of progress.
    let o = within_deadline(bin().args(long_render(&out)));
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stderr(&o), "");
    // On a terminal (script(1) gives the command one), the line is drawn in place, a few
    // times a second at most, and cleared before the result is printed.
    let Ok(script) = which("script") else {
        return;
    };
    let command = format!(
        "BARYLAB_MEMORY_LIMIT=4G {} {}",
        env!("CARGO_BIN_EXE_barylab"),
        long_render(&out).join(" ")
    );
    let start = Instant::now();
    let o = within_deadline(Command::new(script).args(["-qec", &command, "/dev/null"]));
    let seconds = start.elapsed().as_secs_f64();
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(o.status.success(), "{text}");
    let updates = text.matches("\r\x1b[2Kbarylab render: ").count();
    assert!(updates >= 1, "{text:?}");
    assert!(
        updates as f64 <= seconds * 4.0 + 1.0,
        "{updates} in {seconds} s"
    );
    assert!(text.contains("\r\x1b[2Krendered 4096x4096"), "{text:?}");
}

/// The path of a program on `PATH`.
fn which(name: &str) -> Result<PathBuf, ()> {
    std::env::var_os("PATH")
        .and_then(|paths| {
            std::env::split_paths(&paths)
                .map(|d| d.join(name))
                .find(|p| p.is_file())
        })
        .ok_or(())
}
