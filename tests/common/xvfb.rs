//! A private X server (Xvfb) for the tests that open the real window.

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// How long Xvfb may take to create its socket.
const XVFB_TIMEOUT: Duration = Duration::from_secs(15);

/// `program`'s path on PATH, if it is there.
pub fn on_path(program: &str) -> Option<PathBuf> {
    std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .map(|d| d.join(program))
            .find(|p| p.is_file())
    })
}

/// Xvfb's path; `None` (the test says it skipped) when it is not installed, except under
/// CI=true, where a missing Xvfb fails the test.
pub fn xvfb_or_skip(test: &str) -> Option<PathBuf> {
    match on_path("Xvfb") {
        Some(p) => Some(p),
        None if std::env::var("CI").as_deref() == Ok("true") => {
            panic!("Xvfb is not installed but CI=true: install the xvfb package")
        }
        None => {
            println!("SKIPPED {test}: Xvfb is not on PATH (apt-get install xvfb)");
            None
        }
    }
}

/// A display number nobody is using, not one of `failed`: no lock file, or a stale one (an X server that died
/// without cleaning up, e.g. killed by a timeout), whose lock and socket are removed here.
fn free_display(failed: &[u32]) -> u32 {
    (90..250)
        .filter(|n| !failed.contains(n))
        .find(|n| {
            let lock = PathBuf::from(format!("/tmp/.X{n}-lock"));
            let socket = PathBuf::from(format!("/tmp/.X11-unix/X{n}"));
            let alive = std::fs::read_to_string(&lock)
                .ok()
                .and_then(|t| t.trim().parse::<u32>().ok())
                .is_some_and(|pid| Path::new(&format!("/proc/{pid}")).exists());
            if alive {
                return false;
            }
            if lock.exists() || socket.exists() {
                let _ = std::fs::remove_file(&lock);
                let _ = std::fs::remove_file(&socket);
            }
            !lock.exists() && !socket.exists()
        })
        .expect("a free X display number between 90 and 250")
}

/// Xvfb on a free display, killed when dropped.
pub struct Xvfb {
    child: Child,
    /// The `DISPLAY` value, e.g. `:91`.
    pub display: String,
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Held while an Xvfb starts, so tests running in parallel do not pick the same display.
static STARTING: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// Starts Xvfb (1920x1080, 24 bits) on a free display and waits for its socket. An Xvfb that
/// exits or gives no socket within [`XVFB_TIMEOUT`] is killed and the next free display tried,
/// up to [`XVFB_TRIES`] times (once, under a full CI machine, one never made its socket).
pub fn start_xvfb(xvfb: &Path) -> Xvfb {
    let _starting = STARTING.lock().unwrap_or_else(|e| e.into_inner());
    let mut failed = Vec::new();
    for _ in 0..XVFB_TRIES {
        let n = free_display(&failed);
        let child = Command::new(xvfb)
            .args([
                &format!(":{n}"),
                "-screen",
                "0",
                "1920x1080x24",
                "-nolisten",
                "tcp",
            ])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("start Xvfb");
        let mut x = Xvfb {
            child,
            display: format!(":{n}"),
        };
        let socket = PathBuf::from(format!("/tmp/.X11-unix/X{n}"));
        let start = Instant::now();
        loop {
            if socket.exists() {
                return x;
            }
            let exited = matches!(x.child.try_wait(), Ok(Some(_)));
            if exited || start.elapsed() >= XVFB_TIMEOUT {
                break;
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        drop(x);
        failed.push(n);
    }
    panic!("Xvfb did not start on displays {failed:?}");
}

/// How many displays [`start_xvfb`] tries.
const XVFB_TRIES: usize = 3;

/// How long the app may take to open, draw, save its screenshot and exit.
const APP_TIMEOUT: Duration = Duration::from_secs(120);

/// Runs the barylab binary on `display` with `args` and these environment variables (Mesa's
/// software OpenGL); returns (success, stdout, stderr). Fails the test after [`APP_TIMEOUT`].
pub fn run_app(display: &str, args: &[&str], env: &[(&str, &str)]) -> (bool, String, String) {
    let mut c = app_command(display, args);
    c.envs(env.iter().copied());
    let (status, out, err) = run_to_end(c);
    (status.success(), out, err)
}

/// The barylab binary on `display` with `args`, Mesa's software OpenGL, its output piped.
pub fn app_command(display: &str, args: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_barylab"));
    c.args(args)
        .env("DISPLAY", display)
        .env_remove("WAYLAND_DISPLAY")
        .env("LIBGL_ALWAYS_SOFTWARE", "1")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    c
}

/// Runs `c` to its end, reading its output while it runs; (status, stdout, stderr). Fails
/// the test after [`APP_TIMEOUT`].
pub fn run_to_end(mut c: Command) -> (std::process::ExitStatus, String, String) {
    let mut child = c.spawn().expect("start barylab");
    let reader = |r: Option<Box<dyn std::io::Read + Send>>| {
        std::thread::spawn(move || {
            let mut s = String::new();
            if let Some(mut r) = r {
                let _ = r.read_to_string(&mut s);
            }
            s
        })
    };
    let out = reader(
        child
            .stdout
            .take()
            .map(|r| Box::new(r) as Box<dyn std::io::Read + Send>),
    );
    let err = reader(
        child
            .stderr
            .take()
            .map(|r| Box::new(r) as Box<dyn std::io::Read + Send>),
    );
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait") {
            break s;
        }
        if start.elapsed() > APP_TIMEOUT {
            let _ = child.kill();
            panic!("barylab did not exit within {APP_TIMEOUT:?}");
        }
        std::thread::sleep(Duration::from_millis(100));
    };
    let join = |h: std::thread::JoinHandle<String>| h.join().unwrap_or_default();
    (status, join(out), join(err))
}
