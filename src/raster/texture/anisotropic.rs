//! Anisotropic filtering, as EXT_texture_filter_anisotropic and OpenGL 4.6 (section 8.14.3,
//! "Anisotropic texture filtering") describe it.
//!
//! A pixel's footprint in the texture is the parallelogram spanned by its uv derivatives in
//! texels, `(du/dx W, dv/dx H)` and `(du/dy W, dv/dy H)`, with side lengths
//! `Px = |(du/dx W, dv/dx H)|` and `Py = |(du/dy W, dv/dy H)|` ([`footprint_axes`]). Trilinear
//! filtering picks the level from the longer side, `lambda = log2(max(Px, Py))`, and so blurs
//! across the shorter one. Anisotropic filtering takes
//!
//! - `Pmax = max(Px, Py)`, `Pmin = min(Px, Py)`,
//! - `N = min(ceil(Pmax / Pmin), max_anisotropy)` probes,
//! - `lambda' = log2(Pmax / N)` (so the level follows the shorter side as long as `N` may grow),
//! - probe `i` (1..=N) at `uv + (i / (N + 1) - 1/2) duv`, `duv` the derivative along the major
//!   axis (`d/dx` when `Px > Py`, else `d/dy`), each a trilinear lookup at `lambda'`,
//!
//! and averages the N colours. With `N = 1` this is trilinear filtering exactly.

use glam::Vec2;
use serde::{Deserialize, Serialize};

use super::{Filter, Taps, Texture, Wrap, byte_from_sum};

/// Largest `max_anisotropy` (what GPUs offer: `GL_MAX_TEXTURE_MAX_ANISOTROPY` is 16 on
/// llvmpipe and on most hardware).
pub const MAX_ANISOTROPY: u32 = 16;

/// The sampler's `GL_TEXTURE_MAX_ANISOTROPY`: 1 (off, the default) to [`MAX_ANISOTROPY`].
/// Anisotropic filtering applies to trilinear (mipmapped) filtering only.
///
/// ```
/// use barylab::raster::texture::MaxAnisotropy;
/// assert_eq!(MaxAnisotropy::new(16).map(MaxAnisotropy::get), Ok(16));
/// assert!(MaxAnisotropy::new(0).is_err());
/// assert!(!MaxAnisotropy::default().is_on());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(try_from = "u32", into = "u32")]
pub struct MaxAnisotropy(u8);

impl Default for MaxAnisotropy {
    fn default() -> Self {
        Self(1)
    }
}

impl MaxAnisotropy {
    /// `n` if it is 1 to [`MAX_ANISOTROPY`], else a message saying the range.
    pub fn new(n: u32) -> Result<Self, String> {
        match u8::try_from(n) {
            Ok(k) if (1..=MAX_ANISOTROPY).contains(&n) => Ok(Self(k)),
            _ => Err(format!(
                "the largest anisotropy must be a whole number from 1 (off) to {MAX_ANISOTROPY}, not {n}"
            )),
        }
    }

    /// The number, 1 to [`MAX_ANISOTROPY`].
    pub fn get(self) -> u32 {
        u32::from(self.0)
    }

    /// Whether anisotropic filtering is on (more than 1 probe allowed).
    pub fn is_on(self) -> bool {
        self.0 > 1
    }
}

impl TryFrom<u32> for MaxAnisotropy {
    type Error = String;
    fn try_from(n: u32) -> Result<Self, String> {
        Self::new(n)
    }
}

impl From<MaxAnisotropy> for u32 {
    fn from(m: MaxAnisotropy) -> u32 {
        m.get()
    }
}

/// The side lengths of a pixel's footprint in texels of a `width` x `height` texture:
/// `[Px, Py] = [|(du/dx W, dv/dx H)|, |(du/dy W, dv/dy H)|]`, in `f32`. The level of detail
/// ([`lod`](super::lod)) is `log2(max(Px, Py))`.
///
/// ```
/// use barylab::raster::texture::footprint_axes;
/// use glam::Vec2;
/// // 3 texels across and 4 down along x, 0.5 along y, on a 256 x 128 texture.
/// let [px, py] = footprint_axes(Vec2::new(3.0 / 256.0, 4.0 / 128.0), Vec2::new(0.0, 0.5 / 128.0), 256, 128);
/// assert_eq!((px, py), (5.0, 0.5));
/// ```
pub fn footprint_axes(duv_dx: Vec2, duv_dy: Vec2, width: u32, height: u32) -> [f32; 2] {
    let size = Vec2::new(width as f32, height as f32);
    [(duv_dx * size).length(), (duv_dy * size).length()]
}

/// The anisotropic lookup of one pixel: its footprint, the number of probes, the level of
/// detail and the step between probes (see the module documentation for the formulas).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Anisotropic {
    /// The footprint's side along x in texels, `Px`.
    pub px: f32,
    /// The footprint's side along y in texels, `Py`.
    pub py: f32,
    /// Number of probes: `min(ceil(Pmax / Pmin), max_anisotropy)`; 1 when the footprint is
    /// empty or not finite.
    pub n: u32,
    /// Level of detail of every probe: `log2(Pmax / N)` (`-inf` for an empty footprint, which
    /// reads the base level).
    pub lambda: f32,
    /// Whether the major axis is y (`Py > Px`); else x.
    pub major_y: bool,
    /// The uv derivative along the major axis (`duv/dx` or `duv/dy`).
    pub major: Vec2,
}

impl Anisotropic {
    /// The lookup for uv derivatives `duv_dx`, `duv_dy` on a `width` x `height` texture with
    /// at most `max` probes.
    ///
    /// ```
    /// use barylab::raster::texture::{Anisotropic, MaxAnisotropy};
    /// use glam::Vec2;
    /// let max = MaxAnisotropy::new(16).unwrap();
    /// // 8 texels along x, 1 along y: 8 probes at level log2(8 / 8) = 0.
    /// let a = Anisotropic::of(Vec2::new(8.0 / 64.0, 0.0), Vec2::new(0.0, 1.0 / 64.0), (64, 64), max);
    /// assert_eq!((a.n, a.lambda, a.major_y), (8, 0.0, false));
    /// ```
    pub fn of(duv_dx: Vec2, duv_dy: Vec2, (width, height): (u32, u32), max: MaxAnisotropy) -> Self {
        let [px, py] = footprint_axes(duv_dx, duv_dy, width, height);
        let major_y = py > px;
        let (p_max, p_min) = if major_y { (py, px) } else { (px, py) };
        let ratio = p_max / p_min;
        let n = if ratio.is_nan() || !p_max.is_finite() {
            1
        } else {
            ratio.ceil().clamp(1.0, max.get() as f32) as u32
        };
        Self {
            px,
            py,
            n,
            lambda: (p_max / n as f32).log2(),
            major_y,
            major: if major_y { duv_dy } else { duv_dx },
        }
    }

    /// Where probe `i` (0-based, below `n`) reads around `uv`:
    /// `uv + ((i + 1) / (N + 1) - 1/2) duv_major`.
    ///
    /// ```
    /// use barylab::raster::texture::{Anisotropic, MaxAnisotropy};
    /// use glam::Vec2;
    /// let max = MaxAnisotropy::new(4).unwrap();
    /// let a = Anisotropic::of(Vec2::new(0.0, 0.3), Vec2::new(0.1, 0.0), (1, 1), max);
    /// // Pmax / Pmin = 3: probes at -1/4, 0 and +1/4 of duv/dx.
    /// assert_eq!(a.n, 3);
    /// assert_eq!(a.probe_uv(Vec2::new(0.5, 0.5), 0), Vec2::new(0.5, 0.5 - 0.075));
    /// ```
    pub fn probe_uv(&self, uv: Vec2, i: u32) -> Vec2 {
        let t = (i + 1) as f32 / (self.n + 1) as f32 - 0.5;
        uv + self.major * t
    }

    /// Every probe's uv, in order.
    pub fn probes(&self, uv: Vec2) -> impl Iterator<Item = Vec2> + '_ {
        (0..self.n).map(move |i| self.probe_uv(uv, i))
    }
}

impl Texture {
    /// The anisotropic colour in the texels' 0..255 scale: the sum of the N probes'
    /// trilinear sums ([`Texture::sample_rgba8`]'s) times `1 / N`.
    fn anisotropic_sum(&self, uv: Vec2, wrap: Wrap, a: &Anisotropic) -> [f32; 4] {
        let mut sum = [0.0f32; 4];
        for p in a.probes(uv) {
            let one = self.filtered_sum(p, Filter::Trilinear, wrap, a.lambda);
            for (s, c) in sum.iter_mut().zip(one) {
                *s += c;
            }
        }
        let share = 1.0 / a.n as f32;
        sum.map(|s| s * share)
    }

    /// The taps of one anisotropic probe at `uv`: a trilinear lookup at the lookup's level.
    pub fn anisotropic_probe_taps(&self, uv: Vec2, wrap: Wrap, a: &Anisotropic) -> Taps {
        self.taps_lod(uv, Filter::Trilinear, wrap, a.lambda)
    }

    /// The 8-bit colour of anisotropic filtering at `uv` with derivatives `duv = [duv/dx,
    /// duv/dy]`: each channel `round(clamp(sum, 0, 255))` of the averaged probes. With one
    /// probe it is [`Texture::sample_rgba8`]'s trilinear colour at `log2(max(Px, Py))`.
    ///
    /// ```
    /// use barylab::raster::texture::{Filter, MaxAnisotropy, Texture, Wrap, lod};
    /// use glam::Vec2;
    /// let t = Texture::builtin(barylab::raster::BuiltinTexture::Checker);
    /// let (dx, dy) = (Vec2::new(0.01, 0.0), Vec2::new(0.0, 0.01));
    /// let uv = Vec2::new(0.3, 0.6);
    /// let max = MaxAnisotropy::new(16).unwrap();
    /// let trilinear = t.sample_rgba8(uv, Filter::Trilinear, Wrap::Repeat, lod(dx, dy, 256, 256));
    /// assert_eq!(t.sample_anisotropic_rgba8(uv, Wrap::Repeat, [dx, dy], max), trilinear);
    /// ```
    pub fn sample_anisotropic_rgba8(
        &self,
        uv: Vec2,
        wrap: Wrap,
        duv: [Vec2; 2],
        max: MaxAnisotropy,
    ) -> [u8; 4] {
        let a = Anisotropic::of(duv[0], duv[1], (self.width, self.height), max);
        self.anisotropic_sum(uv, wrap, &a).map(byte_from_sum)
    }
}
