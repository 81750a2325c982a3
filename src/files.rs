//! Reading and writing files safely, shared by the command line, the app and the loaders.
//!
//! - Reading: only regular files, each kind with a size cap ([`read_regular`]); a FIFO, a
//!   device or a folder is named as such instead of hanging or reading forever.
//! - Writing: every file goes to a temporary file in the same folder and is renamed into place
//!   ([`write_atomic`], [`stage`]): a full disk or a crash never leaves a half-written file, and
//!   the previous file stays as it was. [`check_output`] checks an output path before any
//!   long work starts.
//!   A file of the kernel's pseudo file systems (`/proc`, `/sys`, ...), whose size says
//!   nothing of what a read returns and whose read may block forever, is refused by the file
//!   system it is on, before it is opened.
//! - Never over an input: outputs are checked against every file read ([`check_not_input`]).
//! - Interrupted: the temporary files being written are removed on SIGINT, SIGTERM and SIGHUP
//!   ([`remove_temps_on_signals`]).
//! - Messages: [`shown`] escapes control characters and shortens very long paths.

use std::fs::{File, Metadata};
use std::io::{self, BufWriter, Read, Write};
use std::path::{Path, PathBuf};

mod inputs;
mod special;
mod temps;

pub use inputs::{FileId, check_not_input, guard_inputs};
pub use temps::{SIGNAL_EXIT_BASE, remove_temps_on_signals};

/// Largest scene file (JSON) read. Scenes written by hand or by the app are a few KB; 10
/// million triangles of the clip-space form take about 100 MB of text.
pub const MAX_SCENE_BYTES: u64 = 256 << 20;
/// Largest OBJ model read. Ten million faces with their vertices take a few hundred MB.
pub const MAX_MODEL_BYTES: u64 = 1 << 30;
/// Largest MTL material library read: materials are a few lines each.
pub const MAX_MATERIAL_BYTES: u64 = 16 << 20;
/// Largest image file read as a texture (compressed; the decoder limits the pixels).
pub const MAX_TEXTURE_BYTES: u64 = 256 << 20;
/// Largest lesson file read: a lesson of twenty steps in two languages is about 50 KB.
pub const MAX_LESSON_BYTES: u64 = 4 << 20;

/// Characters of a path kept in messages; longer paths keep their start and end around "…".
pub const MAX_SHOWN_CHARS: usize = 160;

/// What a file is read as: names it in messages and sets its size cap.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileKind {
    /// A JSON scene file ([`MAX_SCENE_BYTES`]).
    Scene,
    /// An OBJ model ([`MAX_MODEL_BYTES`]).
    Model,
    /// An MTL material library ([`MAX_MATERIAL_BYTES`]).
    Material,
    /// An image used as a texture ([`MAX_TEXTURE_BYTES`]).
    Texture,
    /// An image compared with barylab's render (`barylab compare`).
    Image,
    /// A lesson file (`barylab lesson`, the app's Lessons panel).
    Lesson,
}

impl FileKind {
    /// The name used in messages ("scene", "model", ...).
    pub fn name(self) -> &'static str {
        match self {
            FileKind::Scene => "scene",
            FileKind::Model => "model",
            FileKind::Material => "material library",
            FileKind::Texture => "texture",
            FileKind::Image => "image",
            FileKind::Lesson => "lesson",
        }
    }

    /// The largest file of this kind that is read.
    pub fn cap(self) -> u64 {
        match self {
            FileKind::Scene => MAX_SCENE_BYTES,
            FileKind::Model => MAX_MODEL_BYTES,
            FileKind::Material => MAX_MATERIAL_BYTES,
            FileKind::Texture | FileKind::Image => MAX_TEXTURE_BYTES,
            FileKind::Lesson => MAX_LESSON_BYTES,
        }
    }
}

/// Why a file could not be read. Each names the file.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    /// Opening or reading failed (missing file, no permission, ...).
    #[error("cannot read {kind} {path}: {cause}")]
    Io {
        /// What the file was read as ([`FileKind::name`]).
        kind: &'static str,
        /// The file, as shown in messages ([`shown`]).
        path: String,
        /// The operating system's error.
        cause: io::Error,
    },
    /// The path is a folder, FIFO, device or socket.
    #[error("cannot read {kind} {path}: it is {what}, not a regular file")]
    NotRegular {
        /// What the file was read as ([`FileKind::name`]).
        kind: &'static str,
        /// The file, as shown in messages ([`shown`]).
        path: String,
        /// What the entry is instead ([`describe`]: "a folder", "a FIFO", ...).
        what: &'static str,
    },
    /// The file is larger than its kind's cap ([`FileKind::cap`]).
    #[error("cannot read {kind} {path}: it is {size}, more than the {cap} allowed")]
    TooLarge {
        /// What the file was read as ([`FileKind::name`]).
        kind: &'static str,
        /// The file, as shown in messages ([`shown`]).
        path: String,
        /// Its size for people ([`bytes`]), or "more than ..." when it grew while read.
        size: String,
        /// The cap for people ([`bytes`]).
        cap: String,
    },
}

/// Why an output could not be written (or would not be safe to write).
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    /// Creating, writing or renaming the file failed.
    #[error("cannot write {path}: {cause}")]
    Io {
        /// The output, as shown in messages ([`shown`]).
        path: String,
        /// The operating system's error.
        cause: io::Error,
    },
    /// The output path is not usable: a wrong extension, a folder, device or FIFO, or a
    /// folder that is missing or not writable.
    #[error("cannot write {path}: {problem}")]
    Refused {
        /// The output, as shown in messages ([`shown`]).
        path: String,
        /// What is wrong with it.
        problem: String,
    },
}

/// What a file system entry is, for messages ("a FIFO", "a folder", ...).
pub fn describe(meta: &Metadata) -> &'static str {
    let t = meta.file_type();
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO (named pipe)";
        } else if t.is_char_device() {
            return "a character device";
        } else if t.is_block_device() {
            return "a block device";
        } else if t.is_socket() {
            return "a socket";
        }
    }
    if t.is_dir() {
        "a folder"
    } else if t.is_file() {
        "a regular file"
    } else {
        "not a regular file or folder"
    }
}

/// Opens a regular file of `kind` for reading, after the checks [`read_regular`] makes: a
/// FIFO, a device, a folder or a file larger than [`FileKind::cap`] is an error naming what it
/// is, found before the file is opened (so nothing blocks), and what was opened is checked
/// again. Returns the file, limited to one byte more than the cap (so a file that grew while
/// read shows as [`ReadError::grew`]), and its size when opened.
pub fn open_regular(path: &Path, kind: FileKind) -> Result<(io::Take<File>, u64), ReadError> {
    let io = |cause| ReadError::Io {
        kind: kind.name(),
        path: shown(path),
        cause,
    };
    let checked = |meta: &Metadata| -> Result<(), ReadError> {
        if !meta.is_file() {
            return Err(ReadError::NotRegular {
                kind: kind.name(),
                path: shown(path),
                what: describe(meta),
            });
        }
        if meta.len() > kind.cap() {
            return Err(ReadError::TooLarge {
                kind: kind.name(),
                path: shown(path),
                size: bytes(meta.len()),
                cap: bytes(kind.cap()),
            });
        }
        Ok(())
    };
    let pseudo = |what: Option<&'static str>| match what {
        Some(what) => Err(ReadError::NotRegular {
            kind: kind.name(),
            path: shown(path),
            what,
        }),
        None => Ok(()),
    };
    // `metadata` follows symbolic links and never opens the file: a FIFO is caught here, and
    // a file of /proc or /sys (`/proc/kmsg` blocks a read forever) by its file system.
    checked(&std::fs::metadata(path).map_err(io)?)?;
    pseudo(special::pseudo_path(path))?;
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        // A regular file ignores it; anything else that slipped through fails instead of
        // blocking the read.
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    let file = options.open(path).map_err(io)?;
    // The file may have been replaced between the two looks; check what was opened.
    let meta = file.metadata().map_err(io)?;
    checked(&meta)?;
    pseudo(special::pseudo_file(&file))?;
    inputs::remember(&meta, path, kind);
    // One byte more than the cap shows a file that grew while being read.
    Ok((file.take(kind.cap() + 1), meta.len()))
}

impl ReadError {
    /// The error for a file of `kind` that grew past its cap while it was read (more bytes
    /// came than [`FileKind::cap`]).
    pub fn grew(path: &Path, kind: FileKind) -> Self {
        ReadError::TooLarge {
            kind: kind.name(),
            path: shown(path),
            size: format!("more than {}", bytes(kind.cap())),
            cap: bytes(kind.cap()),
        }
    }

    /// The error for a failed read of a file of `kind` (the operating system's `cause`).
    pub fn io(path: &Path, kind: FileKind, cause: io::Error) -> Self {
        ReadError::Io {
            kind: kind.name(),
            path: shown(path),
            cause,
        }
    }
}

/// Reads a whole regular file of `kind`, at most its [`FileKind::cap`] bytes. Anything else (a
/// FIFO, a device, a folder, a file that is too large) is an error naming what it is, found
/// before the file is opened, so nothing blocks or reads forever ([`open_regular`]).
pub fn read_regular(path: &Path, kind: FileKind) -> Result<Vec<u8>, ReadError> {
    let io = |cause| ReadError::io(path, kind, cause);
    let (mut file, len) = open_regular(path, kind)?;
    let mut out = Vec::new();
    out.try_reserve_exact(len as usize)
        .map_err(|e| io(io::Error::new(io::ErrorKind::OutOfMemory, e.to_string())))?;
    file.read_to_end(&mut out).map_err(io)?;
    if out.len() as u64 > kind.cap() {
        return Err(ReadError::grew(path, kind));
    }
    Ok(out)
}

/// Removes a UTF-8 byte order mark at the start of a text file (some Windows editors write
/// one; it means nothing for JSON or OBJ).
pub fn strip_bom(bytes: &[u8]) -> &[u8] {
    bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes)
}

/// A byte count for people: "17 bytes", "12.0 KiB", "1.5 GiB".
pub fn bytes(n: u64) -> String {
    const UNITS: [&str; 5] = ["KiB", "MiB", "GiB", "TiB", "PiB"];
    if n < 1024 {
        return format!("{n} bytes");
    }
    let mut v = n as f64 / 1024.0;
    let mut unit = 0;
    while v >= 1024.0 && unit + 1 < UNITS.len() {
        v /= 1024.0;
        unit += 1;
    }
    format!("{v:.1} {}", UNITS[unit])
}

/// A path for a message: control characters escaped (`\n`, `\u{1b}`), and a path longer than
/// [`MAX_SHOWN_CHARS`] shortened to its start and end around "…".
pub fn shown(path: &Path) -> String {
    text(&path.display().to_string())
}

/// Any text from outside (a path, a name) made safe for a one-line message, as [`shown`].
pub fn text(s: &str) -> String {
    let escaped = escape_controls(s);
    let n = escaped.chars().count();
    if n <= MAX_SHOWN_CHARS {
        return escaped;
    }
    let keep = MAX_SHOWN_CHARS / 2;
    let head: String = escaped.chars().take(keep).collect();
    let tail: String = escaped.chars().skip(n - keep).collect();
    format!("{head}…{tail}")
}

/// Control characters (line breaks, escape sequences) written as Rust escapes (`\n`,
/// `\u{1b}`), so a message stays on one line and cannot drive the terminal.
pub fn escape_controls(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}

/// A number for a message: plain when moderate, else in scientific notation (`1e308`, not
/// 309 digits).
pub fn number(v: f64) -> String {
    /// Magnitudes from which numbers are written in scientific notation.
    const PLAIN_RANGE: (f64, f64) = (1e-4, 1e9);
    if v == 0.0 || !v.is_finite() || (PLAIN_RANGE.0..PLAIN_RANGE.1).contains(&v.abs()) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// Whether `a` and `b` are the same file (by any name: links are followed). False when
/// either does not exist.
pub fn same_file(a: &Path, b: &Path) -> bool {
    FileId::at(a).is_some_and(|x| Some(x) == FileId::at(b))
}

/// The folder a file is written in ("." for a bare file name).
fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// Checks an output path before any long work: its extension is one of `extensions` (lower
/// case, without the dot; empty accepts any), it is not a folder, device or FIFO, its folder
/// exists, and a file can be created there. Nothing is left behind.
pub fn check_output(path: &Path, extensions: &[&str]) -> Result<(), WriteError> {
    let refused = |problem: String| WriteError::Refused {
        path: shown(path),
        problem,
    };
    if !extensions.is_empty() {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        // ".png" is a hidden file's name with no extension, not an extension alone.
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if ext.is_none()
            && let Some(bare) = name.strip_prefix('.')
            && extensions.contains(&bare.to_ascii_lowercase().as_str())
        {
            return Err(refused(format!(
                "the file name is only the extension {name}: give it a name, e.g. out{name}"
            )));
        }
        if !ext.is_some_and(|e| extensions.contains(&e.as_str())) {
            let list: Vec<String> = extensions.iter().map(|e| format!(".{e}")).collect();
            return Err(refused(format!(
                "the output must be a {} file",
                list.join(" or ")
            )));
        }
    }
    if let Some(problem) = existing_problem(path) {
        return Err(refused(problem));
    }
    if path.as_os_str().as_encoded_bytes().ends_with(b"/") {
        return Err(refused("it names a folder (it ends with /)".into()));
    }
    check_folder(folder_of(path)).map_err(refused)
}

/// Why what is at an output path must not be replaced: a folder, a device, a FIFO, or a
/// read-only file (the rename would replace it although it cannot be written).
fn existing_problem(path: &Path) -> Option<String> {
    let meta = std::fs::metadata(path).ok()?;
    if !meta.is_file() {
        Some(format!("it is {}", describe(&meta)))
    } else if meta.permissions().readonly() {
        Some("it is read-only".into())
    } else {
        None
    }
}

/// Checks that files can be created in `folder`; the problem in words otherwise.
pub fn check_folder(folder: &Path) -> Result<(), String> {
    match std::fs::metadata(folder) {
        Ok(m) if !m.is_dir() => {
            return Err(format!(
                "{} is {}, not a folder",
                shown(folder),
                describe(&m)
            ));
        }
        Ok(_) => {}
        Err(e) if e.kind() == io::ErrorKind::NotFound => {
            return Err(format!("folder {} does not exist", shown(folder)));
        }
        Err(e) => return Err(format!("folder {}: {e}", shown(folder))),
    }
    // The file is removed before it leaves the registry (a tuple drops its first field first).
    temps::create(|| temp_in(folder, None))
        .map(drop)
        .map_err(|e| format!("cannot create files in {}: {e}", shown(folder)))
}

/// A new temporary file in `folder`, with the permissions `like` has (else the usual ones for
/// a new file).
fn temp_in(folder: &Path, like: Option<&Path>) -> io::Result<tempfile::NamedTempFile> {
    let mut builder = tempfile::Builder::new();
    builder.prefix(".barylab-").suffix(".part");
    let earlier = like
        .and_then(|p| std::fs::metadata(p).ok())
        .filter(Metadata::is_file)
        .map(|m| m.permissions());
    #[cfg(unix)]
    let earlier = earlier.or_else(|| {
        use std::os::unix::fs::PermissionsExt;
        /// Permissions of a new output file before the umask, as `File::create` uses
        /// (tempfile's own default, 0o600, would hide the output from other users).
        const NEW_FILE_MODE: u32 = 0o666;
        Some(std::fs::Permissions::from_mode(NEW_FILE_MODE))
    });
    if let Some(p) = earlier {
        builder.permissions(p);
    }
    builder.tempfile_in(folder)
}

/// A file written completely to a temporary file beside its destination, waiting to be moved
/// into place by [`Staged::commit`]. Dropped without a commit, it is deleted.
#[derive(Debug)]
pub struct Staged {
    file: tempfile::NamedTempFile,
    path: PathBuf,
    /// Keeps the temporary file on the list removed on a signal (dropped after `file`).
    _registered: temps::Registered,
}

/// Writes a file to a temporary file in `path`'s folder (through `write`, which may seek) and
/// flushes it to disk; nothing is at `path` yet. Several staged files can be committed
/// together once all were written.
pub fn stage(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>,
) -> Result<Staged, WriteError> {
    let io = |cause| WriteError::Io {
        path: shown(path),
        cause,
    };
    if let Some(problem) = existing_problem(path) {
        return Err(WriteError::Refused {
            path: shown(path),
            problem,
        });
    }
    check_not_input(path)?;
    // An output that is a link is written where the link points; the link stays.
    let target = match std::fs::symlink_metadata(path) {
        Ok(m) if m.file_type().is_symlink() => std::fs::canonicalize(path).map_err(io)?,
        _ => path.to_path_buf(),
    };
    let path = target.as_path();
    let (file, registered) = temps::create(|| temp_in(folder_of(path), Some(path))).map_err(io)?;
    let mut w = BufWriter::new(file.reopen().map_err(io)?);
    write(&mut w).map_err(io)?;
    let f = w.into_inner().map_err(|e| io(e.into_error()))?;
    f.sync_all().map_err(io)?;
    Ok(Staged {
        file,
        path: path.to_path_buf(),
        _registered: registered,
    })
}

/// Writes `bytes` to a temporary file; see [`stage`].
pub fn stage_bytes(path: &Path, bytes: &[u8]) -> Result<Staged, WriteError> {
    stage(path, |w| w.write_all(bytes))
}

impl Staged {
    /// Where the file goes.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Moves the file into place, replacing what was there in one step.
    pub fn commit(self) -> Result<(), WriteError> {
        let path = self.path;
        self.file.persist(&path).map_err(|e| WriteError::Io {
            path: shown(&path),
            cause: e.error,
        })?;
        Ok(())
    }

    /// Moves the file into place only if nothing is there yet (never overwrites).
    pub fn commit_new(self) -> Result<(), WriteError> {
        let path = self.path;
        self.file
            .persist_noclobber(&path)
            .map_err(|e| WriteError::Io {
                path: shown(&path),
                cause: e.error,
            })?;
        Ok(())
    }
}

/// Writes a file atomically: to a temporary file in the same folder, then renamed over
/// `path`. On any failure `path` is as it was.
pub fn write_atomic(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>,
) -> Result<(), WriteError> {
    stage(path, write)?.commit()
}

/// Writes `bytes` atomically; see [`write_atomic`].
pub fn write_bytes(path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
    stage_bytes(path, bytes)?.commit()
}

/// Writes `bytes` to a new file atomically; fails (never overwrites) if `path` exists.
pub fn write_new(path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
    stage_bytes(path, bytes)?.commit_new()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_in_messages_are_escaped_and_shortened() {
        assert_eq!(
            shown(Path::new("a\nb\u{1b}[31m.json")),
            "a\\nb\\u{1b}[31m.json"
        );
        let long = "x".repeat(10_000) + ".obj";
        let s = shown(Path::new(&long));
        assert_eq!(s.chars().count(), MAX_SHOWN_CHARS + 1);
        assert!(s.ends_with("x.obj") && s.contains('…'), "{s}");
    }

    #[test]
    fn numbers_and_sizes_read_well() {
        assert_eq!(number(1e308), "1e308");
        assert_eq!(number(100.0), "100");
        assert_eq!(number(-2.5e-7), "-2.5e-7");
        assert_eq!(bytes(17), "17 bytes");
        assert_eq!(bytes(3 << 30), "3.0 GiB");
    }

    #[test]
    fn a_bom_is_stripped_once() {
        assert_eq!(strip_bom(b"\xEF\xBB\xBF{}"), b"{}");
        assert_eq!(strip_bom(b"{}"), b"{}");
    }
}
