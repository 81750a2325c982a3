//! The OBJ reader's first pass: how many positions, texture coordinates, normals and
//! triangles a file has, so the second pass ([`super::obj`]) reserves its arrays once.

use std::io::{self, BufRead};

/// How many lines of each kind an OBJ text has (about: whitespace as ASCII), so the reader
/// reserves its arrays once instead of growing them (a growing array holds up to twice its
/// size, and leaves the smaller copies behind in the allocator).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Counts {
    /// `v` lines.
    pub positions: usize,
    /// `vt` lines.
    pub texcoords: usize,
    /// `vn` lines.
    pub normals: usize,
    /// Triangles the faces make (corners - 2 for each `f` or `l` line).
    pub triangles: usize,
}

/// Counts the lines of an OBJ text read from `input` (a first, quick pass: no numbers are
/// parsed). Stops after `max_bytes` bytes.
pub(super) fn count(mut input: impl BufRead, max_bytes: u64) -> io::Result<Counts> {
    let mut counts = Counts::default();
    let mut buf = Vec::new();
    let mut total = 0u64;
    loop {
        buf.clear();
        let n = input.read_until(b'\n', &mut buf)?;
        total += n as u64;
        if n == 0 || total > max_bytes {
            return Ok(counts);
        }
        let mut words = buf.split(u8::is_ascii_whitespace).filter(|w| !w.is_empty());
        match words.next() {
            Some(b"v") => counts.positions += 1,
            Some(b"vt") => counts.texcoords += 1,
            Some(b"vn") => counts.normals += 1,
            Some(b"f" | b"l") => counts.triangles += words.count().saturating_sub(2),
            _ => {}
        }
    }
}

/// Reserves room for `n` more items when the allocator has it (else the array grows as it
/// fills).
pub(super) fn reserve<T>(v: &mut Vec<T>, n: usize) {
    let _ = v.try_reserve_exact(n);
}
