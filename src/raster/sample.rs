//! Samples inside a pixel: how many, where, where a value is interpolated, and the resolve.
//!
//! Positions are offsets from the pixel's top-left corner in 1/256 pixel (image rows, y
//! down), so a sample of pixel (col, row) sits at `(256 col + o_x, 256 row + o_y)`, on the
//! same grid as the snapped vertices: the edge functions stay exact at every sample.
//!
//! The standard patterns are the positions the GL reports as `GL_SAMPLE_POSITION` (from the
//! pixel's bottom-left corner, y up, in sixteenths of a pixel): llvmpipe's four, and for 8
//! and 16 samples the tables Mesa's radeonsi reports (the same as Direct3D's standard
//! patterns). In image rows, y down, a GL position `(x, y)` is the offset `(x, 1 - y)`:
//! llvmpipe's sample 0 at GL (0.375, 0.125) lies at (0.375, 0.875). The grid pattern is
//! GAMES101's: `k x k` samples at `((i + 0.5) / k, (j + 0.5) / k)`, numbered row by row from
//! the top left.
//!
//! A pixel's colour is the average of its samples' colours ([`resolve`]), the box filter
//! OpenGL's multisample resolve applies.

use glam::{DVec2, I64Vec2};

use super::project::SUBPIXEL;
use super::setup::sample_point;

/// Samples per pixel: 1 (one sample at the centre, the default), 4, 8 or 16.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(try_from = "u32", into = "u32")]
pub enum SampleCount {
    /// One sample, at the pixel centre (no anti-aliasing).
    #[default]
    One,
    /// Four samples.
    Four,
    /// Eight samples.
    Eight,
    /// Sixteen samples.
    Sixteen,
}

impl SampleCount {
    /// The number of samples.
    pub fn get(self) -> usize {
        match self {
            SampleCount::One => 1,
            SampleCount::Four => 4,
            SampleCount::Eight => 8,
            SampleCount::Sixteen => 16,
        }
    }

    /// The count for `n` samples, or `None` unless `n` is 1, 4, 8 or 16.
    pub fn from_number(n: u32) -> Option<Self> {
        match n {
            1 => Some(SampleCount::One),
            4 => Some(SampleCount::Four),
            8 => Some(SampleCount::Eight),
            16 => Some(SampleCount::Sixteen),
            _ => None,
        }
    }
}

impl TryFrom<u32> for SampleCount {
    type Error = String;
    fn try_from(n: u32) -> Result<Self, String> {
        Self::from_number(n).ok_or_else(|| format!("{n} samples: expected 1, 4, 8 or 16"))
    }
}

impl From<SampleCount> for u32 {
    fn from(c: SampleCount) -> u32 {
        c.get() as u32
    }
}

/// Where the samples of a pixel lie.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum SamplePattern {
    /// The GL's standard positions (llvmpipe's for 4 samples).
    #[default]
    Standard,
    /// A regular `k x k` grid (GAMES101's 2x2 for 4 samples); 4 or 16 samples.
    Grid,
}

/// How often the fragment shader runs under multisampling.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum ShadingRate {
    /// Multisample anti-aliasing: one shading per pixel and triangle, its colour written to
    /// every sample the triangle covers (depth is still per sample).
    #[default]
    Msaa,
    /// Supersampling: every covered sample shaded at its own position.
    Ssaa,
}

/// Where a `smooth` or `noperspective` value is evaluated under MSAA (GLSL's auxiliary
/// storage qualifiers).
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum Location {
    /// The pixel centre, even where it lies outside the triangle (extrapolated values).
    #[default]
    Center,
    /// The lowest-index covered sample, or the centre when every sample is covered
    /// ([`centroid_sample`]).
    Centroid,
    /// Each sample's own position (the shader runs per sample).
    Sample,
}

/// Which vertex gives a `flat` attribute its value.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum ProvokingVertex {
    /// The triangle's last vertex (OpenGL's default).
    #[default]
    Last,
    /// The triangle's first vertex (`glProvokingVertex(GL_FIRST_VERTEX_CONVENTION)`).
    First,
}

impl ProvokingVertex {
    /// The index (0, 1 or 2) of the provoking vertex within a source triangle.
    pub fn index(self) -> usize {
        match self {
            ProvokingVertex::Last => 2,
            ProvokingVertex::First => 0,
        }
    }
}

/// What a render asks of the samples and of the interpolation qualifiers. The default is one
/// sample at the pixel centre, smooth/noperspective values, as before any of this existed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct SampleSettings {
    /// Samples per pixel.
    pub count: SampleCount,
    /// Where they lie.
    pub pattern: SamplePattern,
    /// MSAA or supersampling.
    pub rate: ShadingRate,
    /// Where MSAA evaluates the values.
    pub location: Location,
    /// Every attribute `flat`: the provoking vertex's value.
    pub flat: bool,
    /// Which vertex provokes.
    pub provoking: ProvokingVertex,
}

impl SampleSettings {
    /// Whether the sample path draws: more than one sample per pixel, or `flat` attributes
    /// (which the single-sample path, and its SIMD lanes, do not have). One sample at the
    /// centre without `flat` is the single-sample path, unchanged.
    pub fn uses_sample_path(&self) -> bool {
        self.count != SampleCount::One || self.flat
    }

    /// Refuses a combination without positions: the grid needs a square count (1, 4 or 16).
    pub fn check(&self) -> Result<(), String> {
        if self.pattern == SamplePattern::Grid && self.count == SampleCount::Eight {
            return Err("the grid sample pattern needs 1, 4 or 16 samples, not 8".into());
        }
        Ok(())
    }

    /// The sample offsets of this count and pattern ([`offsets`]).
    pub fn offsets(&self) -> Vec<I64Vec2> {
        offsets(self.count, self.pattern)
    }

    /// Whether each covered sample is shaded at its own position: supersampling, or the
    /// `sample` location.
    pub fn per_sample_shading(&self) -> bool {
        self.rate == ShadingRate::Ssaa || self.location == Location::Sample
    }
}

/// Changes to a scene's [`SampleSettings`] asked for on a command line: each field that is
/// set replaces the scene's (`flat` turns flat on; it never turns it off).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SampleOverride {
    /// Samples per pixel.
    pub count: Option<SampleCount>,
    /// Where they lie.
    pub pattern: Option<SamplePattern>,
    /// MSAA or supersampling.
    pub rate: Option<ShadingRate>,
    /// Where MSAA evaluates the values.
    pub location: Option<Location>,
    /// Every attribute `flat`.
    pub flat: bool,
    /// Which vertex provokes.
    pub provoking: Option<ProvokingVertex>,
}

impl SampleOverride {
    /// `scene`'s samples with these changes applied.
    pub fn apply(&self, scene: &SampleSettings) -> SampleSettings {
        SampleSettings {
            count: self.count.unwrap_or(scene.count),
            pattern: self.pattern.unwrap_or(scene.pattern),
            rate: self.rate.unwrap_or(scene.rate),
            location: self.location.unwrap_or(scene.location),
            flat: self.flat || scene.flat,
            provoking: self.provoking.unwrap_or(scene.provoking),
        }
    }
}

/// The GL's standard positions in sixteenths of a pixel from the bottom-left corner, y up,
/// for 4, 8 and 16 samples, in the GL's sample order.
const STANDARD_4: [[i64; 2]; 4] = [[6, 2], [14, 6], [2, 10], [10, 14]];
const STANDARD_8: [[i64; 2]; 8] = [
    [9, 5],
    [7, 11],
    [13, 9],
    [5, 3],
    [3, 13],
    [1, 7],
    [11, 15],
    [15, 1],
];
const STANDARD_16: [[i64; 2]; 16] = [
    [9, 9],
    [7, 5],
    [5, 10],
    [12, 7],
    [3, 6],
    [10, 13],
    [13, 11],
    [11, 3],
    [6, 14],
    [8, 1],
    [4, 2],
    [2, 12],
    [0, 8],
    [15, 4],
    [14, 15],
    [1, 0],
];

/// The offsets of each sample from the pixel's top-left corner, in 1/256 pixel, y down, in
/// sample order. Standard: a GL position `(x, y)` in sixteenths, y up, becomes
/// `(16 x, 256 - 16 y)`; grid `k x k`: `(256 (i + 1/2) / k, 256 (j + 1/2) / k)` for sample
/// `j k + i`. One sample is the centre `(128, 128)` in both.
///
/// ```
/// use barylab::raster::sample::{offsets, SampleCount, SamplePattern};
/// use glam::I64Vec2;
/// // llvmpipe's sample 0, GL (0.375, 0.125) from the bottom left: x = 96/256, y = 224/256.
/// let s = offsets(SampleCount::Four, SamplePattern::Standard);
/// assert_eq!(s[0], I64Vec2::new(96, 224));
/// assert_eq!(s[3], I64Vec2::new(160, 32));
/// // GAMES101's grid: 0.25 and 0.75 of a pixel, row by row.
/// let g = offsets(SampleCount::Four, SamplePattern::Grid);
/// assert_eq!(g, [I64Vec2::new(64, 64), I64Vec2::new(192, 64), I64Vec2::new(64, 192), I64Vec2::new(192, 192)]);
/// assert_eq!(offsets(SampleCount::One, SamplePattern::Standard), [I64Vec2::new(128, 128)]);
/// ```
pub fn offsets(count: SampleCount, pattern: SamplePattern) -> Vec<I64Vec2> {
    let sixteenth = SUBPIXEL / 16;
    let gl = |t: &[[i64; 2]]| -> Vec<I64Vec2> {
        t.iter()
            .map(|&[x, y]| I64Vec2::new(x * sixteenth, SUBPIXEL - y * sixteenth))
            .collect()
    };
    let grid = |k: i64| -> Vec<I64Vec2> {
        (0..k * k)
            .map(|s| {
                let (i, j) = (s % k, s / k);
                I64Vec2::new(
                    SUBPIXEL * (2 * i + 1) / (2 * k),
                    SUBPIXEL * (2 * j + 1) / (2 * k),
                )
            })
            .collect()
    };
    match (count, pattern) {
        (SampleCount::One, _) => grid(1),
        (SampleCount::Four, SamplePattern::Standard) => gl(&STANDARD_4),
        (SampleCount::Eight, _) => gl(&STANDARD_8),
        (SampleCount::Sixteen, SamplePattern::Standard) => gl(&STANDARD_16),
        (SampleCount::Four, SamplePattern::Grid) => grid(2),
        (SampleCount::Sixteen, SamplePattern::Grid) => grid(4),
    }
}

/// The position of the sample at `offset` in pixel (col, row), in 1/256 pixel:
/// `(256 col + o_x, 256 row + o_y)` ([`sample_point`], the centre, moved by `offset - 128`).
///
/// ```
/// use barylab::raster::sample::sample_at;
/// use glam::I64Vec2;
/// assert_eq!(sample_at(2, 1, I64Vec2::new(96, 224)), I64Vec2::new(608, 480));
/// ```
pub fn sample_at(col: u32, row: u32, offset: I64Vec2) -> I64Vec2 {
    sample_point(col, row) + offset - I64Vec2::splat(SUBPIXEL / 2)
}

/// A position in 1/256 pixel as window coordinates in pixels, `p / 256` (exact in `f64`).
///
/// ```
/// use barylab::raster::sample::window_position;
/// use glam::{DVec2, I64Vec2};
/// assert_eq!(window_position(I64Vec2::new(608, 480)), DVec2::new(2.375, 1.875));
/// ```
pub fn window_position(p: I64Vec2) -> DVec2 {
    p.as_dvec2() / SUBPIXEL as f64
}

/// Where a triangle's MSAA shading is evaluated for a pixel whose samples it covers in
/// `mask` (bit k: sample k) out of `n`: `None` means the pixel centre, `Some(k)` sample `k`.
/// `center`: always the centre; `centroid`: the centre when every sample is covered, else the
/// lowest-index covered sample (llvmpipe's choice); `sample` shades each sample on its own,
/// so this is its lowest covered sample.
///
/// ```
/// use barylab::raster::sample::{centroid_sample, Location};
/// assert_eq!(centroid_sample(Location::Centroid, 0b0110, 4), Some(1));
/// assert_eq!(centroid_sample(Location::Centroid, 0b1111, 4), None);
/// assert_eq!(centroid_sample(Location::Center, 0b0100, 4), None);
/// ```
pub fn centroid_sample(location: Location, mask: u32, n: usize) -> Option<usize> {
    let all = if n >= 32 { u32::MAX } else { (1 << n) - 1 };
    match location {
        Location::Center => None,
        Location::Centroid if mask & all == all => None,
        Location::Centroid | Location::Sample => {
            (mask != 0).then_some(mask.trailing_zeros() as usize)
        }
    }
}

/// The resolved colour of a pixel: the average of its samples' colours per channel,
/// rounded to the nearest level, `(sum c_k + n / 2) / n` in integers (the box filter).
///
/// ```
/// use barylab::raster::sample::resolve;
/// // Two samples white, two background black: half grey, 510 / 4 = 127.5 rounds up.
/// let c = resolve(&[[255, 255, 255, 255], [255, 255, 255, 255], [0, 0, 0, 255], [0, 0, 0, 255]]);
/// assert_eq!(c, [128, 128, 128, 255]);
/// assert_eq!(resolve(&[[10, 20, 30, 40]]), [10, 20, 30, 40]);
/// ```
pub fn resolve(colors: &[[u8; 4]]) -> [u8; 4] {
    let n = colors.len().max(1) as u32;
    let mut sum = [0u32; 4];
    for c in colors {
        for (s, &v) in sum.iter_mut().zip(c) {
            *s += u32::from(v);
        }
    }
    sum.map(|s| ((s + n / 2) / n) as u8)
}
