//! Never over an input: every file read through [`super::open_regular`] is remembered by its
//! identity (device and inode, so every name of it, links included, is the same file), and
//! every output ([`super::stage`], through which all files are written) is refused when it is
//! one of them. Recording starts with [`guard_inputs`]: the command line turns it on for its
//! commands (and for the app's `--screenshot` run); the interactive app leaves it off, since
//! saving a scene over the file it was opened from is what "Save" means.

use std::fs::Metadata;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering};

use super::{FileKind, WriteError, shown};

/// Whether files read are remembered ([`guard_inputs`]).
static GUARDED: AtomicBool = AtomicBool::new(false);

/// A file read: its identity, what it was read as and the name it was read by.
struct Read {
    id: FileId,
    kind: FileKind,
    path: PathBuf,
}

/// Every file read since [`guard_inputs`].
static READ: Mutex<Vec<Read>> = Mutex::new(Vec::new());

/// A file's identity: the device it is on and its inode number (the same for every name of
/// the file). Elsewhere than on Unix, its canonical path.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FileId(#[cfg(unix)] (u64, u64), #[cfg(not(unix))] PathBuf);

impl FileId {
    /// The identity of the file `meta` describes (`path` is its name).
    pub fn of(meta: &Metadata, path: &Path) -> Option<Self> {
        #[cfg(unix)]
        {
            use std::os::unix::fs::MetadataExt;
            let _ = path;
            Some(FileId((meta.dev(), meta.ino())))
        }
        #[cfg(not(unix))]
        {
            let _ = meta;
            std::fs::canonicalize(path).ok().map(FileId)
        }
    }

    /// The identity of the file at `path` (links followed), if there is one.
    pub fn at(path: &Path) -> Option<Self> {
        Self::of(&std::fs::metadata(path).ok()?, path)
    }
}

/// From now on, remembers every file read, and refuses every output that is one of them
/// ([`check_not_input`], which [`super::stage`] calls for every file written).
pub fn guard_inputs() {
    GUARDED.store(true, Ordering::Relaxed);
}

/// Remembers a file just opened for reading (when [`guard_inputs`] was called).
pub(super) fn remember(meta: &Metadata, path: &Path, kind: FileKind) {
    if !GUARDED.load(Ordering::Relaxed) {
        return;
    }
    let Some(id) = FileId::of(meta, path) else {
        return;
    };
    let mut read = READ
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    if !read.iter().any(|r| r.id == id) {
        read.push(Read {
            id,
            kind,
            path: path.to_path_buf(),
        });
    }
}

/// Refuses an output `path` that is a file this run has read (by any name: the same device
/// and inode), naming the input. Nothing to check when `path` does not exist yet.
pub fn check_not_input(path: &Path) -> Result<(), WriteError> {
    if !GUARDED.load(Ordering::Relaxed) {
        return Ok(());
    }
    let Some(id) = FileId::at(path) else {
        return Ok(());
    };
    let read = READ
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    match read.iter().find(|r| r.id == id) {
        Some(r) => Err(WriteError::Refused {
            path: shown(path),
            problem: format!(
                "it is an input of this command (the {} {}); choose another output file",
                r.kind.name(),
                shown(&r.path)
            ),
        }),
        None => Ok(()),
    }
}
