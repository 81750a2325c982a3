//! One GIF palette for a whole animation, built from every frame's pixels, and the frames as
//! indices into it. No dithering anywhere: a flat colour stays one flat colour.
//!
//! - A pixel with alpha below [`ALPHA_CUTOFF`] is the transparent index (one entry, only when
//!   some pixel is transparent); other pixels are their RGB.
//! - When the animation has at most as many colours as the palette has entries (figures of
//!   vertex colours, barycentric shading, the fill sweeps on a flat texture), the palette is
//!   those colours: every frame is exact.
//! - Otherwise the frequent colours (each at least [`RESERVED_SHARE`] of all pixels; at most
//!   half the palette: backgrounds, labels, overlay lines, flat texture cells) get an exact
//!   entry each, and NeuQuant (`color_quant`) learns the rest of the palette from a sample of
//!   the other pixels of every frame; a pixel takes the nearest entry NeuQuant gives.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

use color_quant::NeuQuant;
use rayon::prelude::*;

/// Pixels with alpha below this are transparent in a GIF.
pub const ALPHA_CUTOFF: u8 = 128;

/// The share of all pixels a colour needs to get an exact entry of its own.
pub const RESERVED_SHARE: f64 = 1e-3;

/// Pixels NeuQuant learns from, at most (every frame's pixels, sampled evenly).
const SAMPLE_PIXELS: usize = 300_000;

/// NeuQuant's sampling factor (1 best and slowest, 30 fastest).
const SAMPLE_FACTOR: i32 = 10;

/// A hasher for `0xRRGGBB` keys: one multiplication (Fibonacci hashing), far cheaper than
/// the default SipHash over the millions of pixels of an animation.
#[derive(Default)]
struct ColorHasher(u64);

impl Hasher for ColorHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0 << 8 | u64::from(b)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        }
    }
    fn write_u32(&mut self, k: u32) {
        self.0 = u64::from(k).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    }
}

/// A map keyed by `0xRRGGBB`.
type ColorMap<V> = HashMap<u32, V, BuildHasherDefault<ColorHasher>>;

/// A palette of at most 256 entries for every frame of one animation.
pub struct Palette {
    /// The RGB entries, in index order.
    pub colors: Vec<[u8; 3]>,
    /// The transparent entry, when some pixel is transparent.
    pub transparent: Option<u8>,
    /// The exact entries by colour (`0xRRGGBB`).
    exact: ColorMap<u8>,
    /// The learned entries (after the exact ones), when the colours did not all fit.
    learned: Option<NeuQuant>,
}

/// `0xRRGGBB` of a pixel.
fn key(p: &image::Rgba<u8>) -> u32 {
    u32::from(p[0]) << 16 | u32::from(p[1]) << 8 | u32::from(p[2])
}

/// The RGB of a key.
fn rgb(k: u32) -> [u8; 3] {
    [(k >> 16) as u8, (k >> 8) as u8, k as u8]
}

/// How often each opaque colour occurs in `frame`, and whether a pixel is transparent.
fn histogram(frame: &image::RgbaImage) -> (ColorMap<u64>, bool) {
    let mut counts: ColorMap<u64> = ColorMap::default();
    let mut transparent = false;
    // Runs of one colour (flat areas) are counted at once.
    let mut run: Option<(u32, u64)> = None;
    for p in frame.pixels() {
        if p[3] < ALPHA_CUTOFF {
            transparent = true;
            continue;
        }
        let k = key(p);
        match &mut run {
            Some((c, n)) if *c == k => *n += 1,
            _ => {
                if let Some((c, n)) = run.replace((k, 1)) {
                    *counts.entry(c).or_insert(0) += n;
                }
            }
        }
    }
    if let Some((c, n)) = run {
        *counts.entry(c).or_insert(0) += n;
    }
    (counts, transparent)
}

impl Palette {
    /// The palette of all `frames` (see the module's text).
    pub fn of(frames: &[image::RgbaImage]) -> Palette {
        let (counts, transparent) = frames.par_iter().map(histogram).reduce(
            || (ColorMap::default(), false),
            |(mut a, ta), (b, tb)| {
                for (k, n) in b {
                    *a.entry(k).or_insert(0) += n;
                }
                (a, ta || tb)
            },
        );
        let slots = 256 - usize::from(transparent);
        // Most frequent first; equal counts by colour, so the palette is the same every run.
        let mut by_count: Vec<(u32, u64)> = counts.into_iter().collect();
        by_count.sort_unstable_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
        let total: u64 = by_count.iter().map(|c| c.1).sum();
        let reserved: Vec<u32> = if by_count.len() <= slots {
            by_count.iter().map(|c| c.0).collect()
        } else {
            by_count
                .iter()
                .take(slots / 2)
                .take_while(|c| c.1 as f64 >= RESERVED_SHARE * total as f64)
                .map(|c| c.0)
                .collect()
        };
        let exact: ColorMap<u8> = reserved
            .iter()
            .enumerate()
            .map(|(i, &k)| (k, i as u8))
            .collect();
        let mut colors: Vec<[u8; 3]> = reserved.iter().map(|&k| rgb(k)).collect();
        let learned = (by_count.len() > slots).then(|| {
            let sample = sample_rest(frames, &exact);
            let nq = NeuQuant::new(SAMPLE_FACTOR, slots - colors.len(), &sample);
            colors.extend(
                nq.color_map_rgb()
                    .chunks_exact(3)
                    .map(|c| [c[0], c[1], c[2]]),
            );
            nq
        });
        let transparent = transparent.then(|| {
            colors.push([0, 0, 0]);
            (colors.len() - 1) as u8
        });
        Palette {
            colors,
            transparent,
            exact,
            learned,
        }
    }

    /// The palette as `r g b r g b ...` (a GIF's global colour table).
    pub fn rgb_bytes(&self) -> Vec<u8> {
        self.colors.iter().flatten().copied().collect()
    }

    /// `frame` as palette indices, row by row.
    pub fn indices(&self, frame: &image::RgbaImage) -> Vec<u8> {
        let offset = self.exact.len();
        let mut nearest: ColorMap<u8> = ColorMap::default();
        // The last opaque colour and its index: flat areas look up once per run.
        let mut last: Option<(u32, u8)> = None;
        frame
            .pixels()
            .map(|p| {
                if p[3] < ALPHA_CUTOFF {
                    return self.transparent.unwrap_or(0);
                }
                let k = key(p);
                match last {
                    Some((c, i)) if c == k => return i,
                    _ => {}
                }
                let i = match self.exact.get(&k) {
                    Some(&i) => i,
                    None => *nearest.entry(k).or_insert_with(|| match &self.learned {
                        Some(nq) => (offset + nq.index_of(&[p[0], p[1], p[2], 255])) as u8,
                        None => 0,
                    }),
                };
                last = Some((k, i));
                i
            })
            .collect()
    }
}

/// RGBA bytes of up to [`SAMPLE_PIXELS`] opaque pixels of `frames` without an exact entry,
/// taken at an even stride across all frames.
fn sample_rest(frames: &[image::RgbaImage], exact: &ColorMap<u8>) -> Vec<u8> {
    let all: usize = frames.iter().map(|f| f.pixels().len()).sum();
    let stride = all.div_ceil(SAMPLE_PIXELS).max(1);
    let mut sample = Vec::with_capacity(4 * SAMPLE_PIXELS.min(all));
    for p in frames
        .iter()
        .flat_map(|f| f.pixels())
        .step_by(stride)
        .filter(|p| p[3] >= ALPHA_CUTOFF && !exact.contains_key(&key(p)))
    {
        sample.extend_from_slice(&[p[0], p[1], p[2], 255]);
    }
    if sample.is_empty() {
        sample.extend_from_slice(&[0, 0, 0, 255]);
    }
    sample
}
