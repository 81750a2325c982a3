//! The progress line of long commands: on standard error, only when it is a terminal
//! (`std::io::IsTerminal`), from half a second on, four times a second at most, rewritten in
//! place (`\r`) and cleared when the command ends, and before anything else is printed
//! ([`clear`], called by `output::print` and `note!`; the next update draws it again). Piped or
//! redirected, nothing is written.

use std::io::{IsTerminal, Write};
use std::sync::{Arc, Condvar, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// How long a command runs before the line appears (short commands show none).
const FIRST_AFTER: Duration = Duration::from_millis(500);
/// Time between updates.
const EVERY: Duration = Duration::from_millis(250);

/// Whether the line is on the screen now; held while it is written or cleared.
static SHOWN: Mutex<bool> = Mutex::new(false);

/// Clears the line if it is on the screen, so that a message or output starts on a clean
/// line.
pub fn clear() {
    if let Ok(mut shown) = SHOWN.lock()
        && *shown
    {
        let mut err = std::io::stderr().lock();
        // A line that cannot be cleared is not worth an error.
        let _ = write!(err, "\r\x1b[2K").and_then(|()| err.flush());
        *shown = false;
    }
}

/// The line of one command; dropping it stops the updates and clears the line.
pub struct ProgressLine {
    stop: Arc<(Mutex<bool>, Condvar)>,
    thread: Option<JoinHandle<()>>,
}

impl ProgressLine {
    /// Starts the line of the command `what` ("render"), or nothing when standard error is
    /// not a terminal.
    pub fn start(what: &'static str) -> Option<Self> {
        if !std::io::stderr().is_terminal() {
            return None;
        }
        let stop = Arc::new((Mutex::new(false), Condvar::new()));
        let stop_t = Arc::clone(&stop);
        let start = Instant::now();
        let first = barylab::progress::now().renders;
        let thread = std::thread::Builder::new()
            .name("progress".into())
            .spawn(move || {
                let (lock, wake) = &*stop_t;
                let mut wait = FIRST_AFTER;
                loop {
                    let Ok(guard) = lock.lock() else { return };
                    let Ok((stopped, _)) = wake.wait_timeout_while(guard, wait, |s| !*s) else {
                        return;
                    };
                    if *stopped {
                        return;
                    }
                    let line = text(what, barylab::progress::now(), first, start.elapsed());
                    let Ok(mut shown) = SHOWN.lock() else { return };
                    let mut err = std::io::stderr().lock();
                    // A line that cannot be written is not worth an error.
                    let _ = write!(err, "\r\x1b[2K{line}").and_then(|()| err.flush());
                    *shown = true;
                    wait = EVERY;
                }
            })
            .ok()?;
        Some(Self {
            stop,
            thread: Some(thread),
        })
    }
}

impl Drop for ProgressLine {
    fn drop(&mut self) {
        let (lock, wake) = &*self.stop;
        if let Ok(mut stopped) = lock.lock() {
            *stopped = true;
            wake.notify_all();
        }
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
        clear();
    }
}

/// The line's text: the command, the current render's share drawn (and which render, when
/// the command has made several) and the time so far, e.g. `barylab render: 42% · 3 s`.
fn text(what: &str, p: barylab::progress::Progress, first: u64, elapsed: Duration) -> String {
    let renders = p.renders.saturating_sub(first);
    let percent = (p.fraction() * 100.0).floor();
    let secs = elapsed.as_secs();
    match renders {
        0 => format!("barylab {what}: {secs} s"),
        1 => format!("barylab {what}: {percent:.0}% · {secs} s"),
        n => format!("barylab {what}: render {n}, {percent:.0}% · {secs} s"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use barylab::progress::Progress;

    #[test]
    fn the_line_names_the_share_and_the_time() {
        let p = |renders, rows_done| Progress {
            renders,
            rows_done,
            rows_total: 600,
        };
        let t = Duration::from_millis(3400);
        assert_eq!(text("render", p(2, 0), 2, t), "barylab render: 3 s");
        assert_eq!(text("render", p(3, 252), 2, t), "barylab render: 42% · 3 s");
        assert_eq!(
            text("bench", p(9, 600), 2, t),
            "barylab bench: render 7, 100% · 3 s"
        );
    }
}
