//! Files that look regular but are not: the kernel's pseudo file systems (`/proc`, `/sys`,
//! debugfs, ...) report a size of 0 or 4096 whatever a read returns, and some of their files
//! (`/proc/kmsg`) block a read forever. They are recognised by the file system they are on
//! (its `statfs` magic number) and refused before they are opened.

use std::path::Path;

/// Linux file system magic numbers (`linux/magic.h`) of the kernel's pseudo file systems, with
/// the name used in messages. Their files' sizes are not what a read returns.
#[cfg(target_os = "linux")]
const PSEUDO_FILE_SYSTEMS: [(i64, &str); 14] = [
    (0x9fa0, "a file of the kernel's /proc file system"),
    (0x6265_6572, "a file of the kernel's /sys file system"),
    (
        0x6462_6720,
        "a file of the kernel's debug file system (debugfs)",
    ),
    (
        0x7472_6163,
        "a file of the kernel's trace file system (tracefs)",
    ),
    (
        0x7363_6673,
        "a file of the kernel's security file system (securityfs)",
    ),
    (0x0027_e0eb, "a file of the kernel's cgroup file system"),
    (0x6367_7270, "a file of the kernel's cgroup file system"),
    (0x6265_6570, "a file of the kernel's configfs file system"),
    (0xcafe_4a11, "a file of the kernel's BPF file system"),
    (0x6165_676c, "a file of the kernel's pstore file system"),
    (
        0xde5e_81e4,
        "a file of the kernel's EFI variables file system",
    ),
    (
        0x6573_5543,
        "a file of the kernel's FUSE control file system",
    ),
    (
        0x4249_4e4d,
        "a file of the kernel's binfmt_misc file system",
    ),
    (0x1980_0202, "a POSIX message queue"),
];

/// What the file system `path` is on makes of it, when that is a kernel pseudo file system
/// ([`PSEUDO_FILE_SYSTEMS`]): "a file of the kernel's /proc file system", ... `None` for
/// ordinary file systems and when the file system cannot be asked.
#[cfg(target_os = "linux")]
pub fn pseudo_path(path: &Path) -> Option<&'static str> {
    use std::os::unix::ffi::OsStrExt;
    let c = std::ffi::CString::new(path.as_os_str().as_bytes()).ok()?;
    let mut stat = std::mem::MaybeUninit::<libc::statfs>::uninit();
    // SAFETY: `c` is a NUL-terminated path and `stat` has room for one `statfs` record,
    // which the call fills on success (checked before it is read).
    let ok = unsafe { libc::statfs(c.as_ptr(), stat.as_mut_ptr()) } == 0;
    // SAFETY: the call succeeded, so it initialised the record.
    ok.then(|| pseudo_magic(&unsafe { stat.assume_init() }))?
}

/// Like [`pseudo_path`], for a file already open.
#[cfg(target_os = "linux")]
pub fn pseudo_file(file: &std::fs::File) -> Option<&'static str> {
    use std::os::fd::AsRawFd;
    let mut stat = std::mem::MaybeUninit::<libc::statfs>::uninit();
    // SAFETY: the descriptor is open (borrowed from `file`) and `stat` has room for one
    // `statfs` record, which the call fills on success (checked before it is read).
    let ok = unsafe { libc::fstatfs(file.as_raw_fd(), stat.as_mut_ptr()) } == 0;
    // SAFETY: the call succeeded, so it initialised the record.
    ok.then(|| pseudo_magic(&unsafe { stat.assume_init() }))?
}

/// The description of the pseudo file system a `statfs` record describes
/// ([`PSEUDO_FILE_SYSTEMS`]).
#[cfg(target_os = "linux")]
fn pseudo_magic(stat: &libc::statfs) -> Option<&'static str> {
    // `f_type` is an i64 on 64-bit Linux, an i32 or u32 elsewhere.
    #[allow(clippy::useless_conversion)]
    let magic = i64::from(stat.f_type);
    PSEUDO_FILE_SYSTEMS
        .iter()
        .find(|(m, _)| *m == magic)
        .map(|(_, what)| *what)
}

/// Other systems: no pseudo file systems are known.
#[cfg(not(target_os = "linux"))]
pub fn pseudo_path(_path: &Path) -> Option<&'static str> {
    None
}

/// Other systems: no pseudo file systems are known.
#[cfg(not(target_os = "linux"))]
pub fn pseudo_file(_file: &std::fs::File) -> Option<&'static str> {
    None
}
