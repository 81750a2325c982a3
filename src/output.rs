//! What the command line writes: standard output and error that never panic (a closed pipe
//! ends the program quietly), one-line error messages, and output files checked before any
//! long work and never one of the inputs.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{Result, bail};
use barylab::files::{self, shown};

/// Exit code after standard output was closed early (`barylab probe ... | head -1`): what a
/// shell reports for a program ended by SIGPIPE (128 + 13).
pub const BROKEN_PIPE_EXIT: u8 = 141;

/// Longest error message printed, in characters; longer ones are cut (a message quotes paths
/// and values, which are shortened already; this bounds everything else).
pub const MAX_MESSAGE_CHARS: usize = 2000;

/// Standard output was closed by the reader: not worth a message.
#[derive(Debug, thiserror::Error)]
#[error("standard output was closed")]
pub struct BrokenPipe;

/// A check that ran to the end and found differences (`gpu-check`, `compare`): its report is
/// printed; the program ends with exit code 1 after this line on standard error.
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
pub struct Differs(pub String);

/// Prints a line to standard error; a closed or full standard error is ignored (there is
/// nowhere left to report it).
macro_rules! note {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        $crate::progress_line::clear();
        let _ = writeln!(std::io::stderr().lock(), $($arg)*);
    }};
}
pub(crate) use note;

/// Writes `text` to standard output. A closed pipe becomes [`BrokenPipe`]; other failures
/// (a full disk behind `>`) an error that says so.
pub fn print(text: &str) -> Result<()> {
    crate::progress_line::clear();
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Err(BrokenPipe.into()),
        Err(e) => bail!("cannot write to standard output: {e}"),
    }
}

/// Fails when standard output was closed (`barylab probe ... >&-`): what a command prints
/// would be lost without a word. The standard library reopens a closed standard output on
/// /dev/null for reading and writing before `main`; a shell's `> /dev/null` opens it for
/// writing only, so the two are told apart by the access mode.
pub fn stdout_open() -> Result<()> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let rdev = |p: &str| std::fs::metadata(p).map(|m| m.rdev()).ok();
        // SAFETY: F_GETFL only reads descriptor 1's flags (-1 when it is not open).
        let flags = unsafe { libc::fcntl(libc::STDOUT_FILENO, libc::F_GETFL) };
        if flags == -1 {
            bail!("standard output is closed: nothing could be printed");
        }
        let mode = flags & libc::O_ACCMODE;
        let (rdev, null) = (rdev("/dev/stdout"), rdev("/dev/null"));
        if rdev.is_some() && rdev == null && mode == libc::O_RDWR {
            bail!(
                "standard output is closed (the command was run with >&-): nothing could be \
                 printed; send it to a file, or to /dev/null to discard it"
            );
        }
    }
    Ok(())
}

/// The exit code for an error, after printing it as one line (unless it is [`BrokenPipe`]).
pub fn report(e: &anyhow::Error) -> ExitCode {
    if e.downcast_ref::<BrokenPipe>().is_some() {
        return ExitCode::from(BROKEN_PIPE_EXIT);
    }
    if let Some(d) = e.downcast_ref::<Differs>() {
        note!("{}", one_line(&d.0));
        return ExitCode::FAILURE;
    }
    note!("error: {}", one_line(&format!("{e:#}")));
    ExitCode::FAILURE
}

/// A message on one line: line breaks and other control characters escaped, at most
/// [`MAX_MESSAGE_CHARS`].
pub fn one_line(message: &str) -> String {
    let escaped = files::escape_controls(message.trim_end());
    if escaped.chars().count() <= MAX_MESSAGE_CHARS {
        return escaped;
    }
    let cut: String = escaped.chars().take(MAX_MESSAGE_CHARS).collect();
    format!("{cut}…")
}

/// Checks an output file before any work: extension, folder, not a device (see
/// [`files::check_output`]).
pub fn check_output(path: &Path, extensions: &[&str]) -> Result<()> {
    files::check_output(path, extensions)?;
    Ok(())
}

/// Refuses to write `output` when it is a file this command read ([`files::check_not_input`])
/// or one of `inputs` it will read (the same file, by any name).
pub fn not_an_input(output: &Path, inputs: &[PathBuf]) -> Result<()> {
    // Every file read so far (the same check runs again for every file written) ...
    files::check_not_input(output)?;
    // ... and those named that are read later.
    if let Some(input) = inputs.iter().find(|i| files::same_file(output, i)) {
        bail!(
            "cannot write {}: it is an input of this command ({}); choose another output file",
            shown(output),
            shown(input)
        );
    }
    Ok(())
}

/// A window system's error in plain words: the source file and line it quotes (`at
/// /root/.cargo/.../mod.rs:765:`) removed, and a missing display said as such, with what to do.
pub fn window_error(message: &str) -> String {
    let mut out = String::with_capacity(message.len());
    let mut rest = message;
    // " at PATH.rs:LINE:" (or ":LINE:COLUMN:") is a location in the library's source.
    while let Some(i) = rest.find(" at ") {
        let after = &rest[i + 4..];
        let end = after.find(' ').unwrap_or(after.len());
        let word = &after[..end];
        out.push_str(&rest[..i]);
        if word.contains(".rs:") {
            if word.ends_with(':') {
                out.push(':');
            }
            rest = &after[end..];
        } else {
            out.push_str(" at ");
            rest = after;
        }
    }
    out.push_str(rest);
    if message.contains("DISPLAY") && message.contains("neither") {
        out.push_str(
            " (no display to open a window on: run barylab in a desktop session, or use its \
             commands, such as barylab render, figure or probe; see barylab --help)",
        );
    }
    out
}
