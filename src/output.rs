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
        let _ = writeln!(std::io::stderr().lock(), $($arg)*);
    }};
}
pub(crate) use note;

/// Writes `text` to standard output. A closed pipe becomes [`BrokenPipe`]; other failures
/// (a full disk behind `>`) an error that says so.
pub fn print(text: &str) -> Result<()> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Err(BrokenPipe.into()),
        Err(e) => bail!("cannot write to standard output: {e}"),
    }
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
