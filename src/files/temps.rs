//! Temporary files removed when the program is interrupted: every temporary file written
//! ([`super::stage`]) is registered while it exists, and [`remove_temps_on_signals`] starts a
//! thread that, on SIGINT (Ctrl+C), SIGTERM or SIGHUP (the terminal closed), removes the
//! registered files and ends the program with exit code 128 + the signal's number, as a shell
//! reports a program ended by that signal.

use std::path::PathBuf;
use std::sync::Mutex;

/// The temporary files that exist now (written, not yet renamed into place or removed).
static IN_FLIGHT: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Exit code offset of a program ended by a signal (the shell's convention: 128 + signal).
pub const SIGNAL_EXIT_BASE: i32 = 128;

/// A temporary file's place in the registry; dropping it takes the file off the list (after
/// the file was renamed into place or removed).
#[derive(Debug)]
pub(super) struct Registered(PathBuf);

/// Creates a temporary file through `make` and registers it until the returned guard is
/// dropped. The file is made while the registry is held, so a signal never finds a file that
/// exists but is not yet on the list (the signal thread holds the registry from the removal
/// until the program ends, so no file is made after the removal either).
pub(super) fn create(
    make: impl FnOnce() -> std::io::Result<tempfile::NamedTempFile>,
) -> std::io::Result<(tempfile::NamedTempFile, Registered)> {
    let mut list = lock();
    let file = make()?;
    let path = file.path().to_path_buf();
    list.push(path.clone());
    Ok((file, Registered(path)))
}

impl Drop for Registered {
    fn drop(&mut self) {
        let mut list = lock();
        if let Some(i) = list.iter().position(|p| *p == self.0) {
            list.swap_remove(i);
        }
    }
}

/// The registry, also after a thread panicked while holding it (a list of paths stays valid).
fn lock() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    IN_FLIGHT
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// Removes every registered temporary file and ends the program with `code`, holding the
/// registry to the end: a thread that is about to make a temporary file waits (for ever) in
/// [`create`] instead of leaving one behind.
fn remove_all_and_exit(code: i32) -> ! {
    let list = lock();
    for path in list.iter() {
        let _ = std::fs::remove_file(path);
    }
    std::process::exit(code)
}

/// Makes SIGINT, SIGTERM and SIGHUP remove the temporary files being written before the
/// program ends (exit code 128 + signal). Call it first in `main`, before any other thread
/// starts: the three signals are blocked in the calling thread, which every later thread
/// inherits, and one thread waits for them. Programs started later get the usual signal
/// handling (the standard library resets the mask of a child process).
#[cfg(unix)]
pub fn remove_temps_on_signals() -> std::io::Result<()> {
    let mut set = std::mem::MaybeUninit::<libc::sigset_t>::uninit();
    // SAFETY: `set` is initialised by `sigemptyset` before the signals are added to it, and
    // every call gets a valid pointer to it; the return values are checked.
    let set = unsafe {
        if libc::sigemptyset(set.as_mut_ptr()) != 0 {
            return Err(std::io::Error::last_os_error());
        }
        for signal in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP] {
            libc::sigaddset(set.as_mut_ptr(), signal);
        }
        set.assume_init()
    };
    // SAFETY: `set` is a valid signal set; the old mask is not wanted (null).
    let blocked = unsafe { libc::pthread_sigmask(libc::SIG_BLOCK, &set, std::ptr::null_mut()) };
    if blocked != 0 {
        return Err(std::io::Error::from_raw_os_error(blocked));
    }
    std::thread::Builder::new()
        .name("barylab-signals".into())
        .spawn(move || {
            loop {
                let mut signal: libc::c_int = 0;
                // SAFETY: `set` is a valid signal set, blocked in every thread, and `signal`
                // is a valid place for the number of the signal received.
                if unsafe { libc::sigwait(&set, &mut signal) } == 0 {
                    remove_all_and_exit(SIGNAL_EXIT_BASE + signal);
                }
            }
        })?;
    Ok(())
}

/// Elsewhere than on Unix the default handling stays (the temporary files may be left).
#[cfg(not(unix))]
pub fn remove_temps_on_signals() -> std::io::Result<()> {
    Ok(())
}
