//! The memory budget: what a render, a figure, a scene or a model needs is estimated before
//! anything is allocated, and a request past the budget is refused with a message giving the
//! need and the limit (instead of the process being killed for want of memory). The limit,
//! the error and the generic checks live here; each estimate lives with what it sizes (a
//! render's in [`raster::footprint`](crate::raster::footprint)).
//!
//! The limit is, in order: [`set_limit`] (the command line's `--memory-limit`), the
//! environment variable [`LIMIT_ENV`], or [`AVAILABLE_SHARE`] of the memory the system reports
//! available (`MemAvailable` in `/proc/meminfo`) or, when smaller, of the room the process's
//! own limits leave (`ulimit -v`, `ulimit -d`, a cgroup's memory.max), else
//! [`FALLBACK_LIMIT`].

use std::sync::OnceLock;
use std::sync::atomic::{AtomicU64, Ordering};

use crate::files::bytes;

/// Environment variable that sets the limit, e.g. `BARYLAB_MEMORY_LIMIT=2G`.
pub const LIMIT_ENV: &str = "BARYLAB_MEMORY_LIMIT";

/// Share of the available memory a request may use by default: the rest stays for the
/// system, the other programs, and estimates that come out low.
pub const AVAILABLE_SHARE: f64 = 0.75;

/// The limit when the system does not say how much memory is available (no `/proc/meminfo`).
pub const FALLBACK_LIMIT: u64 = 4 << 30;

/// Bytes of memory per byte of OBJ text while it is read and turned into a mesh. The streaming
/// reader (`model/obj.rs`) never holds the text: the file's f32 positions, uvs and normals, 12
/// bytes of indices per output vertex and the mesh (68 bytes a vertex, 12 a triangle), then the
/// normals' position table. Measured 1.8 for a 1,002,000-triangle model of `v` and `f a b c`
/// lines (38 MB of text) and 1.0 for a 1,000,000-triangle grid with `vt` and `vn` (71 MB); 3
/// leaves room. (With tobj, which kept the text and a 104-byte record per face, it was 8.)
pub const MODEL_BYTES_PER_FILE_BYTE: u64 = 3;

/// Bytes of memory per byte of scene JSON while it is parsed (the text, the parsed vertices
/// and triangles, and the checking pass).
pub const SCENE_BYTES_PER_FILE_BYTE: u64 = 4;

/// Bytes per pixel of a figure's PNG beyond its renders: the canvas, the overlay layer, the
/// output image and the encoded PNG (4 bytes each).
pub const FIGURE_BYTES_PER_PIXEL: u64 = 16;

/// Bytes per pixel of decoding an image file (a texture, an image to compare): the decoded
/// image in the file's own format (up to 8 bytes, RGBA at 16 bits), its RGBA8 copy and the
/// texture or comparison image made from it (4 bytes each).
pub const IMAGE_DECODE_BYTES_PER_PIXEL: u64 = 16;

/// What decoding a `width` x `height` image file needs
/// (`width * height *` [`IMAGE_DECODE_BYTES_PER_PIXEL`]).
pub fn image_decode_need(width: u32, height: u32) -> u64 {
    u64::from(width) * u64::from(height) * IMAGE_DECODE_BYTES_PER_PIXEL
}

/// Set by `--memory-limit`; 0 means not set.
static OVERRIDE: AtomicU64 = AtomicU64::new(0);

/// A request that does not fit, or a limit that cannot be understood.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MemoryError {
    /// The estimated need is above the limit.
    #[error(
        "{what} needs about {need} of memory, more than the limit of {limit} ({origin}); \
         see --memory-limit"
    )]
    TooLarge {
        /// What needs the memory ("a 800x600 render of 2 triangles", "model torus.obj (1.2 MiB)",
        /// ...).
        what: String,
        /// The estimate, for people ([`bytes`]).
        need: String,
        /// The limit, for people.
        limit: String,
        /// Where the limit came from ([`Limit::source`]).
        origin: String,
    },
    /// [`LIMIT_ENV`] is set to something [`parse_size`] does not read.
    #[error("{LIMIT_ENV}={value} is not a memory size like 2G, 512M or 1000000")]
    BadEnv {
        /// The variable's value, as shown in messages.
        value: String,
    },
    /// The allocator refused the memory although the estimate was within the limit (the
    /// system's own limits, `ulimit -v`, or the memory free now).
    #[error(
        "cannot allocate {need} for {what}: the system refused the memory; \
         draw it smaller, or free memory and try again"
    )]
    Allocation {
        /// What the memory was for.
        what: String,
        /// How much was asked for, for people.
        need: String,
    },
}

/// The memory limit and where it came from (for messages).
#[derive(Clone, Debug, PartialEq)]
pub struct Limit {
    /// The limit in bytes.
    pub bytes: u64,
    /// Where it came from: `--memory-limit`, [`LIMIT_ENV`], or a share of the available
    /// memory (or the fallback).
    pub source: String,
}

/// Sets the limit for the rest of the run (the command line's `--memory-limit`).
pub fn set_limit(bytes: u64) {
    OVERRIDE.store(bytes.max(1), Ordering::Relaxed);
}

/// Parses a memory size: a whole number of bytes, optionally followed by K, M, G or T (powers
/// of 1024, an optional "i" and "B" allowed: `512M`, `2GiB`, `1.5G`).
pub fn parse_size(s: &str) -> Option<u64> {
    let t = s.trim();
    let digits = t
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(t.len());
    let (number, unit) = t.split_at(digits);
    let number: f64 = number.parse().ok()?;
    let unit = unit.trim().to_ascii_lowercase();
    let unit = unit.trim_end_matches('b').trim_end_matches('i');
    let scale: u64 = match unit {
        "" => 1,
        "k" => 1 << 10,
        "m" => 1 << 20,
        "g" => 1 << 30,
        "t" => 1 << 40,
        _ => return None,
    };
    let v = number * scale as f64;
    (v.is_finite() && v >= 1.0 && v < u64::MAX as f64).then_some(v as u64)
}

/// The available memory the system reports, in bytes.
fn available() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    kib_field(&text, "MemAvailable:")
}

/// A `NAME:  1234 kB` line of a /proc file, in bytes.
fn kib_field(text: &str, name: &str) -> Option<u64> {
    let line = text.lines().find(|l| l.starts_with(name))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb.saturating_mul(1024))
}

/// What bounds the memory of this process besides the machine's available memory, and the
/// room it leaves, in bytes: the address-space limit (`ulimit -v`, RLIMIT_AS) less the
/// process's virtual size now, the data limit (RLIMIT_DATA) less its data now, and the
/// memory.max of its cgroup and each parent (containers, shared lab machines) less what the
/// cgroup uses. The smallest room, with its name for messages; `None` when nothing is set.
fn process_room() -> Option<(u64, &'static str)> {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    let mut rooms: Vec<(u64, &'static str)> = Vec::new();
    #[cfg(unix)]
    for (resource, used, name) in [
        (
            libc::RLIMIT_AS,
            "VmSize:",
            "the address space limit (ulimit -v)",
        ),
        (
            libc::RLIMIT_DATA,
            "VmData:",
            "the data size limit (ulimit -d)",
        ),
    ] {
        let mut lim = libc::rlimit {
            rlim_cur: 0,
            rlim_max: 0,
        };
        // SAFETY: `lim` is a valid place for one `rlimit` record; the result is checked.
        let ok = unsafe { libc::getrlimit(resource, &mut lim) } == 0;
        if ok && lim.rlim_cur != libc::RLIM_INFINITY {
            let used = kib_field(&status, used).unwrap_or(0);
            // `rlim_t` is a u64 on Linux, maybe narrower elsewhere.
            #[allow(clippy::useless_conversion)]
            let cur = u64::from(lim.rlim_cur);
            rooms.push((cur.saturating_sub(used), name));
        }
    }
    if let Some(room) = cgroup_room() {
        rooms.push((room, "the memory.max of its cgroup"));
    }
    rooms.into_iter().min_by_key(|(room, _)| *room)
}

/// The smallest `memory.max - memory.current` of this process's cgroup (v2) and its
/// parents, or v1's `memory.limit_in_bytes - memory.usage_in_bytes`.
fn cgroup_room() -> Option<u64> {
    let read = |p: &std::path::Path| {
        std::fs::read_to_string(p)
            .ok()
            .and_then(|t| t.trim().parse::<u64>().ok())
    };
    let own = std::fs::read_to_string("/proc/self/cgroup").ok()?;
    let mut best: Option<u64> = None;
    let mut keep = |room: u64| best = Some(best.map_or(room, |b| b.min(room)));
    if let Some(path) = own.lines().find_map(|l| l.strip_prefix("0::")) {
        let mut dir = std::path::Path::new("/sys/fs/cgroup").join(path.trim_start_matches('/'));
        loop {
            // "max" (no limit) does not parse as a number.
            if let Some(max) = read(&dir.join("memory.max")) {
                keep(max.saturating_sub(read(&dir.join("memory.current")).unwrap_or(0)));
            }
            if dir.as_os_str().len() <= "/sys/fs/cgroup".len() || !dir.pop() {
                break;
            }
        }
    }
    let v1 = std::path::Path::new("/sys/fs/cgroup/memory");
    /// v1 writes a number near 2^63 for "no limit".
    const V1_UNLIMITED: u64 = 1 << 60;
    if let Some(max) = read(&v1.join("memory.limit_in_bytes")).filter(|&m| m < V1_UNLIMITED) {
        keep(max.saturating_sub(read(&v1.join("memory.usage_in_bytes")).unwrap_or(0)));
    }
    best
}

/// The default limit: [`AVAILABLE_SHARE`] of the smaller of the available memory and the
/// room the process's own limits leave ([`process_room`]), else [`FALLBACK_LIMIT`] (or the
/// room, when smaller).
fn default_limit() -> Limit {
    let share = |b: u64| (b as f64 * AVAILABLE_SHARE) as u64;
    let percent = AVAILABLE_SHARE * 100.0;
    match (available(), process_room()) {
        (Some(a), Some((room, name))) if room < a => Limit {
            bytes: share(room),
            source: format!("{percent:.0}% of what {name} leaves this process"),
        },
        (None, Some((room, name))) if share(room) < FALLBACK_LIMIT => Limit {
            bytes: share(room),
            source: format!("{percent:.0}% of what {name} leaves this process"),
        },
        (Some(a), _) => Limit {
            bytes: share(a),
            source: format!("{percent:.0}% of the available memory"),
        },
        (None, _) => Limit {
            bytes: FALLBACK_LIMIT,
            source: "the default when available memory is unknown".into(),
        },
    }
}

/// The current limit.
pub fn limit() -> Result<Limit, MemoryError> {
    let set = OVERRIDE.load(Ordering::Relaxed);
    if set > 0 {
        return Ok(Limit {
            bytes: set,
            source: "--memory-limit".into(),
        });
    }
    if let Some(value) = std::env::var_os(LIMIT_ENV) {
        let value = value.to_string_lossy().into_owned();
        return match parse_size(&value) {
            Some(b) => Ok(Limit {
                bytes: b,
                source: LIMIT_ENV.into(),
            }),
            None => Err(MemoryError::BadEnv {
                value: crate::files::text(&value),
            }),
        };
    }
    // Read once: the share of what was available when the program started.
    static DEFAULT: OnceLock<Limit> = OnceLock::new();
    Ok(DEFAULT.get_or_init(default_limit).clone())
}

/// Refuses `need` bytes for `what` ("a 16384x16384 render") past the limit.
pub fn check(what: impl FnOnce() -> String, need: u64) -> Result<(), MemoryError> {
    let limit = limit()?;
    if need <= limit.bytes {
        return Ok(());
    }
    Err(MemoryError::TooLarge {
        what: what(),
        need: bytes(need),
        limit: bytes(limit.bytes),
        origin: limit.source,
    })
}

/// A vector of `n` elements' capacity, or an error naming `what` when the memory cannot be had.
pub fn try_vec<T>(n: usize, what: &str) -> Result<Vec<T>, MemoryError> {
    let mut v = Vec::new();
    reserve(&mut v, n, || what.to_string())?;
    Ok(v)
}

/// Makes `v` hold `n` elements, the new ones `value`, asking for the memory it lacks
/// fallibly: when the system refuses it, an error naming `what` ("the 1024x768 colour
/// buffer") and the size, never an abort. Shrinking keeps the memory for reuse.
pub fn try_resize<T: Clone>(
    v: &mut Vec<T>,
    n: usize,
    value: T,
    what: impl FnOnce() -> String,
) -> Result<(), MemoryError> {
    reserve(v, n.saturating_sub(v.len()), what)?;
    v.resize(n, value);
    Ok(())
}

/// A `width` x `height` RGBA image of `background`, its pixels allocated fallibly (an error
/// naming `what` when the system refuses them).
pub fn try_image(
    width: u32,
    height: u32,
    background: [u8; 4],
    what: impl FnOnce() -> String,
) -> Result<image::RgbaImage, MemoryError> {
    let n = (width as usize)
        .saturating_mul(height as usize)
        .saturating_mul(4);
    let mut data = Vec::new();
    reserve(&mut data, n, what)?;
    data.resize(n, 0);
    for px in data.chunks_exact_mut(4) {
        px.copy_from_slice(&background);
    }
    image::RgbaImage::from_raw(width, height, data).ok_or_else(|| MemoryError::Allocation {
        what: format!("a {width}x{height} image"),
        need: bytes(n as u64),
    })
}

/// Reserves room for `extra` more elements in `v`, or the [`MemoryError::Allocation`] of
/// `what`.
fn reserve<T>(
    v: &mut Vec<T>,
    extra: usize,
    what: impl FnOnce() -> String,
) -> Result<(), MemoryError> {
    v.try_reserve_exact(extra)
        .map_err(|_| MemoryError::Allocation {
            what: what(),
            need: bytes(
                (v.len().saturating_add(extra) as u64).saturating_mul(size_of::<T>() as u64),
            ),
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_parse_with_units() {
        assert_eq!(parse_size("1000"), Some(1000));
        assert_eq!(parse_size("512M"), Some(512 << 20));
        assert_eq!(parse_size("2GiB"), Some(2 << 30));
        assert_eq!(parse_size("1.5g"), Some(3 << 29));
        assert_eq!(parse_size("-5"), None);
        assert_eq!(parse_size("lots"), None);
        assert_eq!(parse_size("0"), None);
    }

    #[test]
    fn a_refused_allocation_names_what_and_how_much() {
        let mut v = vec![1u64; 3];
        let e = try_resize(&mut v, usize::MAX / 16, 0, || "the test buffer".into())
            .expect_err("no room for 2^60 elements");
        assert_eq!(
            e,
            MemoryError::Allocation {
                what: "the test buffer".into(),
                need: bytes((usize::MAX / 16) as u64 * 8),
            }
        );
        assert_eq!(v, [1, 1, 1], "the vector is left as it was");
        try_resize(&mut v, 5, 7, || "the test buffer".into()).expect("5 elements");
        assert_eq!(v, [1, 1, 1, 7, 7]);
        let img = try_image(2, 1, [1, 2, 3, 4], || "an image".into()).expect("2 pixels");
        assert_eq!(img.as_raw(), &[1, 2, 3, 4, 1, 2, 3, 4]);
    }
}
