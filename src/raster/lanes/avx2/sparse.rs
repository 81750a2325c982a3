//! Sparse rows gathered into full chunks: a small triangle (a dense mesh's, a few pixels
//! each) covers one to three pixels of each row it crosses, so a row chunk of eight lanes
//! does mostly wasted work. Rows whose chunk covers at most [`MAX_LANES`] pixels give their
//! covered pixels to a [`Gathered`] list instead, and every eight of them are interpolated,
//! shaded and written as one chunk, each lane with its own row. Every lane still computes
//! the row path's operations on its own pixel centre (its own row term), so the values are
//! the same bit for bit; only the write differs: lane by lane, not eight pixels side by side.
//! The pixels of one triangle are distinct, so the order of their writes does not matter.

use std::arch::x86_64::*;

use super::super::{LANES, Target};
use crate::raster::framebuffer::depth_passes;
use crate::raster::setup::WeightPlanes;

/// A row chunk covering at most this many pixels goes to the gathered list.
pub(super) const MAX_LANES: u32 = 4;

/// Covered pixels waiting to be drawn as full chunks (at most `LANES - 1` left over from
/// the last chunk, plus one row's `MAX_LANES`).
pub(super) struct Gathered {
    x: [i32; 2 * LANES],
    y: [i32; 2 * LANES],
    len: usize,
}

impl Gathered {
    pub(super) fn new() -> Self {
        Self {
            x: [0; 2 * LANES],
            y: [0; 2 * LANES],
            len: 0,
        }
    }

    /// Adds the covered lanes (`bits`, lane k in bit k) of the chunk at column `x`, row `y`.
    #[inline]
    pub(super) fn add(&mut self, x: u32, y: u32, mut bits: i32) {
        while bits != 0 && self.len < 2 * LANES {
            let k = bits.trailing_zeros();
            self.x[self.len] = (x + k) as i32;
            self.y[self.len] = y as i32;
            self.len += 1;
            bits &= bits - 1;
        }
    }

    /// Whether a full chunk is waiting.
    #[inline]
    pub(super) fn full(&self) -> bool {
        self.len >= LANES
    }

    /// Whether nothing is waiting.
    #[inline]
    pub(super) fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Takes up to eight pixels: their columns and rows as lanes, and the lanes that hold
    /// one (lane k in bit k; the other lanes hold stale positions, whose values nobody
    /// writes). The rest (fewer than eight) moves to the front.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(super) fn take(&mut self) -> (__m256i, __m256i, i32) {
        let n = self.len.min(LANES);
        // SAFETY: unaligned loads and stores of the first and second eight elements of the
        // sixteen-element arrays.
        unsafe {
            let x = self.x.as_mut_ptr().cast::<__m256i>();
            let y = self.y.as_mut_ptr().cast::<__m256i>();
            let xs = _mm256_loadu_si256(x);
            let ys = _mm256_loadu_si256(y);
            _mm256_storeu_si256(x, _mm256_loadu_si256(x.add(1)));
            _mm256_storeu_si256(y, _mm256_loadu_si256(y.add(1)));
            self.len -= n;
            (xs, ys, (1 << n) - 1)
        }
    }
}

/// Pixels of short spans of the scanline lanes waiting to be drawn as full chunks: each
/// one's column, row and place `k` in its span (the pixel's values are its span's start
/// values after `k` single steps, as the row path's lane `k` holds them). The chunk computes
/// them lane by lane from these ([`scanline`](super::scanline)); nothing is stepped or
/// copied per pixel here.
pub(super) struct SpanGathered {
    x: [i32; 2 * LANES],
    y: [i32; 2 * LANES],
    k: [i32; 2 * LANES],
    len: usize,
}

impl SpanGathered {
    pub(super) fn new() -> Self {
        Self {
            x: [0; 2 * LANES],
            y: [0; 2 * LANES],
            k: [0; 2 * LANES],
            len: 0,
        }
    }

    /// Adds the span `x0..=x1` (at most [`LANES`] pixels) of row `y`. At most
    /// `LANES - 1` pixels may be waiting (a full chunk is drawn before the next add).
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(super) fn add(&mut self, x0: u32, x1: u32, y: u32) {
        debug_assert!(x1 >= x0 && x1 - x0 < LANES as u32 && self.len < LANES);
        let n = ((x1 - x0 + 1) as usize).min(LANES);
        let at = self.len.min(LANES);
        let k = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
        // SAFETY: unaligned stores of eight elements from `at <= LANES` in sixteen-element
        // arrays (lanes beyond the span are written but not counted).
        unsafe {
            let put = |a: &mut [i32; 2 * LANES], v: __m256i| {
                _mm256_storeu_si256(a.as_mut_ptr().add(at).cast(), v)
            };
            put(
                &mut self.x,
                _mm256_add_epi32(_mm256_set1_epi32(x0 as i32), k),
            );
            put(&mut self.y, _mm256_set1_epi32(y as i32));
            put(&mut self.k, k);
        }
        self.len = at + n;
    }

    /// Whether a full chunk is waiting.
    #[inline]
    pub(super) fn full(&self) -> bool {
        self.len >= LANES
    }

    /// Whether nothing is waiting.
    #[inline]
    pub(super) fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Takes up to eight pixels: their columns, rows and places in their spans as lanes,
    /// and the lanes that hold one (lane k in bit k; the other lanes hold stale pixels,
    /// which nobody writes). The rest (fewer than eight) moves to the front.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(super) fn take(&mut self) -> (__m256i, __m256i, __m256i, i32) {
        let n = self.len.min(LANES);
        // SAFETY: unaligned loads and stores of the first and second eight elements of the
        // sixteen-element arrays.
        let [x, y, k] = [&mut self.x, &mut self.y, &mut self.k].map(|a| unsafe {
            let p = a.as_mut_ptr().cast::<__m256i>();
            let v = _mm256_loadu_si256(p);
            _mm256_storeu_si256(p, _mm256_loadu_si256(p.add(1)));
            v
        });
        self.len -= n;
        (x, y, k, (1 << n) - 1)
    }
}

/// Pixel centres `i + 0.5` of four i32 lanes as `f64` (exact: the values are small integers
/// plus a half, as the row path's `f64::from(x) + 0.5`).
#[inline]
#[target_feature(enable = "avx2")]
pub(super) fn centres(v: __m128i) -> __m256d {
    _mm256_add_pd(_mm256_cvtepi32_pd(v), _mm256_set1_pd(0.5))
}

/// The weights' row and column terms at four pixel centres, each on its own row:
/// [`WeightPlanes::row_term`] and [`WeightPlanes::column_term`] per lane, the row path's
/// operations with the row term per lane.
#[inline]
#[target_feature(enable = "avx2")]
pub(super) fn terms4(w: &WeightPlanes, px: __m256d, py: __m256d) -> super::interp::Terms4 {
    let mut rows = [_mm256_setzero_pd(); 3];
    for (i, r) in rows.iter_mut().enumerate() {
        *r = _mm256_mul_pd(
            _mm256_set1_pd(w.dir[i].x),
            _mm256_sub_pd(py, _mm256_set1_pd(w.start[i].y)),
        );
    }
    super::interp::Terms4 {
        rows,
        columns: super::interp::column_terms4(w, px),
    }
}

/// The screen weights at four pixel centres, each on its own row: [`terms4`], then
/// [`WeightPlanes::weight_of_terms`] (the scanline lanes' span starts).
#[inline]
#[target_feature(enable = "avx2")]
pub(super) fn weights4(w: &WeightPlanes, px: __m256d, py: __m256d) -> [__m256d; 3] {
    super::interp::weights_of_terms4(w, &terms4(w, px, py))
}

/// Buffer indices of the band for columns `x` and image rows `y`.
#[inline]
#[target_feature(enable = "avx2")]
pub(super) fn indices(target: &Target<'_>, x: __m256i, y: __m256i) -> __m256i {
    let row = _mm256_sub_epi32(y, _mm256_set1_epi32(target.y0 as i32));
    _mm256_add_epi32(
        _mm256_mullo_epi32(row, _mm256_set1_epi32(target.width as i32)),
        x,
    )
}

/// Depth-tests and writes the lanes in `ok` of a gathered chunk, each at its own buffer
/// index (`at`), one by one with [`depth_passes`]. Returns the lanes that passed. A target
/// with uv or difference buffers never gets a gathered chunk.
#[inline]
#[target_feature(enable = "avx2")]
pub(in crate::raster::lanes) fn write(
    target: &mut Target<'_>,
    at: __m256i,
    ok: __m256i,
    depth: __m256,
    rgba: __m256i,
) -> __m256i {
    debug_assert!(target.uv.is_none() && target.difference.is_none());
    let (mut d, mut c, mut i) = ([0.0f32; LANES], [0i32; LANES], [0i32; LANES]);
    // SAFETY: unaligned stores into three eight-element arrays.
    unsafe {
        _mm256_storeu_ps(d.as_mut_ptr(), depth);
        _mm256_storeu_si256(c.as_mut_ptr().cast(), rgba);
        _mm256_storeu_si256(i.as_mut_ptr().cast(), at);
    }
    let mut bits = _mm256_movemask_ps(_mm256_castsi256_ps(ok));
    let mut pass = 0;
    while bits != 0 {
        let k = bits.trailing_zeros() as usize;
        bits &= bits - 1;
        let j = i[k] as usize;
        if let Some(old) = target.depth.get_mut(j)
            && depth_passes(d[k], *old)
        {
            *old = d[k];
            if let Some(px) = target.color.get_mut(j) {
                *px = c[k].to_le_bytes();
            }
            pass |= 1 << k;
        }
    }
    super::mask_from_bits(pass)
}
