//! Textures: RGBA8 texel storage, wrap modes and filters (OpenGL 4.6, section 8.14).
//!
//! Texel row 0 is the *bottom* row of the picture, so v = 0 is the bottom edge and a picture
//! appears upright on a quad whose uv (0,0) is its lower-left corner. Images loaded from files
//! are flipped on load accordingly.

use glam::Vec2;
use serde::{Deserialize, Serialize};

mod anisotropic;
mod builtin;
mod filter;
mod load;
mod mip;

pub use anisotropic::{Anisotropic, MAX_ANISOTROPY, MaxAnisotropy, footprint_axes};
pub use load::{ImageProblem, OpenedImage, TextureError, open_image, plain_error};
use mip::{mip_chain, try_mip_chain};

use filter::add_texel;
pub(crate) use filter::{MAX_TEXEL_COORD, bilinear_fraction, round_byte, texel_floor};
pub use filter::{Tap, Taps, bilinear_weights, byte_from_sum, wrap_coord};

/// Texture minification/magnification filter.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Filter {
    /// GL_NEAREST: the texel containing the sample.
    Nearest,
    /// GL_LINEAR: the 2x2 texels around the sample, weighted by distance.
    #[default]
    Bilinear,
    /// GL_LINEAR_MIPMAP_LINEAR: bilinear in the two mipmap levels around the level of detail,
    /// blended by its fraction.
    Trilinear,
}

/// Texture wrap mode for coordinates outside [0, 1].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Wrap {
    /// GL_REPEAT: `i mod size`.
    #[default]
    Repeat,
    /// GL_CLAMP_TO_EDGE: `clamp(i, 0, size - 1)`.
    ClampToEdge,
    /// GL_MIRRORED_REPEAT: `(size - 1) - mirror((i mod 2 size) - size)`.
    MirroredRepeat,
}

/// The built-in textures.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum BuiltinTexture {
    /// An 8x8 grid of coloured squares, each labelled with its (column, row) so that
    /// distortion is visible; 512x512 texels.
    UvGrid,
    /// An 8x8 black-and-white checkerboard, 256x256 texels.
    Checker,
    /// The 2x2 texture of the classic tutorial: red, white / green, blue.
    Rgbw2x2,
    /// 1024x1024 texels of deterministic colour noise (the benchmark texture: every lookup
    /// touches fresh memory, as with a photo).
    Noise,
}

impl BuiltinTexture {
    /// All built-ins, for listings.
    pub const ALL: [BuiltinTexture; 4] = [
        BuiltinTexture::UvGrid,
        BuiltinTexture::Checker,
        BuiltinTexture::Rgbw2x2,
        BuiltinTexture::Noise,
    ];

    /// The name used in scene files.
    pub fn name(self) -> &'static str {
        match self {
            BuiltinTexture::UvGrid => "uv-grid",
            BuiltinTexture::Checker => "checker",
            BuiltinTexture::Rgbw2x2 => "rgbw-2x2",
            BuiltinTexture::Noise => "noise",
        }
    }

    /// Looks a built-in up by its scene-file name.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|b| b.name() == name)
    }
}

/// An RGBA8 texture; texel row 0 is the bottom row (v = 0).
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    width: u32,
    height: u32,
    texels: Vec<[u8; 4]>,
    /// Mipmap levels 1, 2, ... down to 1x1 (level 0 is the texture itself).
    mips: Vec<Level>,
    /// Every texel's alpha is 255.
    opaque: bool,
}

/// One mipmap level.
#[derive(Clone, Debug, PartialEq)]
struct Level {
    width: u32,
    height: u32,
    texels: Vec<[u8; 4]>,
}

/// Level of detail from the uv derivatives across a pixel (OpenGL 4.6 eq. 8.7 - 8.9):
/// `lambda = log2(rho)`, `rho = max(Px, Py)` with the footprint's sides
/// `Px = |(du/dx W, dv/dx H)|`, `Py = |(du/dy W, dv/dy H)|` ([`footprint_axes`]). Derivatives that are
/// not finite give 0 (the base level).
///
/// ```
/// use barylab::raster::texture::lod;
/// use glam::Vec2;
/// // One pixel steps 4 texels along u on a 256-wide texture: level 2.
/// assert_eq!(lod(Vec2::new(4.0 / 256.0, 0.0), Vec2::new(0.0, 1.0 / 256.0), 256, 256), 2.0);
/// // Magnified (half a texel per pixel): negative.
/// assert_eq!(lod(Vec2::new(0.5 / 256.0, 0.0), Vec2::ZERO, 256, 256), -1.0);
/// ```
pub fn lod(duv_dx: Vec2, duv_dy: Vec2, width: u32, height: u32) -> f32 {
    let [px, py] = footprint_axes(duv_dx, duv_dy, width, height);
    let l = px.max(py).log2();
    if l.is_finite() { l } else { 0.0 }
}

/// How far apart two texture coordinates are, in texels of a `size` = (W, H) texture, per
/// axis: `((u_1 - u_2) W, (v_1 - v_2) H)`; its length is the distance. In the precision of
/// the caller: the heatmap computes it in `f32`, the probe in `f64`.
///
/// ```
/// use barylab::raster::texture::texel_offset;
/// assert_eq!(texel_offset([0.75f64, 0.5], [0.5, 0.25], [8.0, 4.0]), [2.0, 1.0]);
/// ```
pub fn texel_offset<T>(uv_1: [T; 2], uv_2: [T; 2], size: [T; 2]) -> [T; 2]
where
    T: Copy + std::ops::Sub<Output = T> + std::ops::Mul<Output = T>,
{
    [(uv_1[0] - uv_2[0]) * size[0], (uv_1[1] - uv_2[1]) * size[1]]
}

/// One pixel's difference in texels: the length of [`texel_offset`],
/// `|((u_a - u_p) W, (v_a - v_p) H)|` for a W x H texture, in `f32`. The difference heatmap
/// shows it; the lanes compute it with the same operations.
///
/// ```
/// use barylab::raster::texture::texel_difference;
/// // 0.03 of a 100-texel-wide texture across, 0.04 of a 100-texel-high one down: 5 texels.
/// let d = texel_difference([0.53, 0.54], [0.5, 0.5], (100, 100));
/// assert!((d - 5.0).abs() < 1e-4);
/// ```
pub fn texel_difference(uv_affine: [f32; 2], uv_perspective: [f32; 2], size: (u32, u32)) -> f32 {
    square_texel_difference(uv_affine, uv_perspective, [size.0 as f32, size.1 as f32]).sqrt()
}

/// The square of [`texel_difference`] (the same operations before the square root), with
/// the texture size as `f32`.
#[inline(always)]
pub fn square_texel_difference(
    uv_affine: [f32; 2],
    uv_perspective: [f32; 2],
    size: [f32; 2],
) -> f32 {
    let [du, dv] = texel_offset(uv_affine, uv_perspective, size);
    du * du + dv * dv
}

/// Largest texture side kept as is; larger images are downscaled on load.
pub const MAX_TEXTURE_SIZE: u32 = 4096;

/// An image's pixels (row 0 at the top) as texels (row 0 at the bottom), appended to `texels`
/// (empty, its room reserved by the caller).
fn flipped_texels(img: &image::RgbaImage, mut texels: Vec<[u8; 4]>) -> Vec<[u8; 4]> {
    let w = img.width() as usize;
    texels.reserve_exact(img.pixels().len());
    for row in img.as_raw().chunks_exact(w.max(1) * 4).rev() {
        texels.extend(row.chunks_exact(4).map(|p| [p[0], p[1], p[2], p[3]]));
    }
    texels
}

impl Texture {
    fn new_with_mips(width: u32, height: u32, texels: Vec<[u8; 4]>) -> Self {
        let mips = mip_chain(width, height, &texels);
        let opaque = texels.iter().all(|t| t[3] == u8::MAX);
        Self {
            width,
            height,
            texels,
            mips,
            opaque,
        }
    }

    /// Number of mipmap levels, including level 0.
    pub fn levels(&self) -> u32 {
        self.mips.len() as u32 + 1
    }

    /// Width and height of a mipmap level (clamped to the last level).
    pub fn level_size(&self, level: u32) -> (u32, u32) {
        match level.checked_sub(1) {
            None => (self.width, self.height),
            Some(k) => {
                let l = &self.mips[(k as usize).min(self.mips.len().saturating_sub(1))];
                (l.width, l.height)
            }
        }
    }

    /// The texel at column `i`, row `j` of a mipmap level. Indices must be in range.
    pub fn texel_at(&self, level: u32, i: u32, j: u32) -> [u8; 4] {
        match level.checked_sub(1).and_then(|k| self.mips.get(k as usize)) {
            None => self.texel(i, j),
            Some(l) => l.texels[j as usize * l.width as usize + i as usize],
        }
    }

    /// A texture from texels given bottom row first. Returns `None` if the size does not match
    /// or is zero.
    pub fn from_texels(width: u32, height: u32, texels: Vec<[u8; 4]>) -> Option<Self> {
        if width == 0 || height == 0 || texels.len() != width as usize * height as usize {
            return None;
        }
        Some(Self::new_with_mips(width, height, texels))
    }

    /// A texture from an image whose row 0 is the top (as image files store it).
    pub fn from_image(img: &image::RgbaImage) -> Option<Self> {
        Self::from_texels(img.width(), img.height(), flipped_texels(img, Vec::new()))
    }

    /// [`Texture::from_image`] with the texels' and the mipmap levels' memory asked for
    /// fallibly (`None` for an image of no pixels).
    pub fn try_from_image(
        img: &image::RgbaImage,
    ) -> Result<Option<Self>, crate::budget::MemoryError> {
        let (w, h) = img.dimensions();
        if w == 0 || h == 0 {
            return Ok(None);
        }
        let room =
            crate::budget::try_vec(w as usize * h as usize, &format!("the {w}x{h} texture"))?;
        let texels = flipped_texels(img, room);
        let mips = try_mip_chain(w, h, &texels)?;
        let opaque = texels.iter().all(|t| t[3] == u8::MAX);
        Ok(Some(Self {
            width: w,
            height: h,
            texels,
            mips,
            opaque,
        }))
    }

    /// The texels as an image with row 0 at the top, for display and export.
    pub fn to_image(&self) -> image::RgbaImage {
        image::RgbaImage::from_fn(self.width, self.height, |x, y| {
            image::Rgba(self.texel(x, self.height - 1 - y))
        })
    }

    /// Width of the base level, in texels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height of the base level, in texels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The base level's texels, row `j` starting at `j * width` (bottom row first).
    pub fn base_texels(&self) -> &[[u8; 4]] {
        &self.texels
    }

    /// Whether every texel's alpha is 255 (then every filtered alpha is 255: a weighted sum
    /// of equal values `c` with weights adding up to 1 is within `c * 1e-6` of `c`, and
    /// rounds to it).
    pub fn is_opaque(&self) -> bool {
        self.opaque
    }

    /// The texel at column `i`, row `j` (row 0 at the bottom). Indices must be in range.
    pub fn texel(&self, i: u32, j: u32) -> [u8; 4] {
        self.texels[j as usize * self.width as usize + i as usize]
    }

    /// The texels a filter reads for texture coordinate `uv`, with their weights.
    ///
    /// Nearest: `i = floor(u W)`, `j = floor(v H)`, wrapped. Bilinear: `i0 = floor(u W - 1/2)`,
    /// `alpha = frac(u W - 1/2)`, likewise for j and beta; the four texels (i0, j0), (i0+1, j0),
    /// (i0, j0+1), (i0+1, j0+1), each wrapped, weigh (1-a)(1-b), a(1-b), (1-a)b, ab.
    ///
    /// ```
    /// use barylab::raster::texture::{Texture, Filter, Wrap};
    /// use glam::Vec2;
    /// let t = Texture::from_texels(2, 2, vec![[0; 4]; 4]).unwrap();
    /// // u W = 0.75 -> texel 0; v H = 1.5 -> row 1.
    /// let taps = t.taps(Vec2::new(0.375, 0.75), Filter::Nearest, Wrap::Repeat);
    /// assert_eq!((taps[0].i, taps[0].j, taps[0].weight), (0, 1, 1.0));
    /// // Bilinear at the centre of the texture: the 4 texels, a quarter each.
    /// let taps = t.taps(Vec2::new(0.5, 0.5), Filter::Bilinear, Wrap::Repeat);
    /// assert!(taps.iter().all(|t| t.weight == 0.25));
    /// ```
    pub fn taps(&self, uv: Vec2, filter: Filter, wrap: Wrap) -> Taps {
        self.taps_lod(uv, filter, wrap, 0.0)
    }

    /// Like [`Texture::taps`] at level of detail `lambda` (see [`lod`]), which only trilinear
    /// filtering uses: `lambda <= 0` reads level 0 bilinearly; otherwise levels
    /// `d = floor(lambda)` and `d + 1` (clamped to the last level) are read bilinearly and
    /// blended with weights `1 - frac(lambda)` and `frac(lambda)`.
    ///
    /// ```
    /// use barylab::raster::texture::{Texture, Filter, Wrap};
    /// use glam::Vec2;
    /// let t = Texture::from_texels(4, 4, vec![[0; 4]; 16]).unwrap();
    /// assert_eq!(t.levels(), 3);
    /// let taps = t.taps_lod(Vec2::new(0.5, 0.5), Filter::Trilinear, Wrap::Repeat, 1.25);
    /// let on = |l| taps.iter().filter(|t| t.level == l).map(|t| t.weight).sum::<f32>();
    /// assert_eq!((on(1), on(2)), (0.75, 0.25));
    /// ```
    pub fn taps_lod(&self, uv: Vec2, filter: Filter, wrap: Wrap, lambda: f32) -> Taps {
        match filter {
            Filter::Nearest | Filter::Bilinear => self.level_taps(uv, filter, wrap, 0),
            Filter::Trilinear => {
                let (d, blend) = self.trilinear_levels(lambda);
                let lo = self.level_taps(uv, Filter::Bilinear, wrap, d);
                let Some(f) = blend else {
                    return lo;
                };
                let hi = self.level_taps(uv, Filter::Bilinear, wrap, d + 1);
                let mut out = lo;
                for k in 0..4 {
                    out.taps[k].weight *= 1.0 - f;
                    out.taps[4 + k] = hi.taps[k];
                    out.taps[4 + k].weight *= f;
                }
                out.len = 8;
                out
            }
        }
    }

    /// The mipmap levels trilinear filtering reads at `lambda`: `(d, None)` for level `d`
    /// alone, `(d, Some(f))` for levels `d` and `d + 1` weighted `1 - f` and `f`. `lambda <= 0`
    /// (or not finite) gives level 0; it is clamped to the last level.
    ///
    /// ```
    /// use barylab::raster::texture::Texture;
    /// let t = Texture::from_texels(4, 4, vec![[0; 4]; 16]).unwrap();
    /// assert_eq!(t.trilinear_levels(-0.5), (0, None));
    /// assert_eq!(t.trilinear_levels(1.25), (1, Some(0.25)));
    /// assert_eq!(t.trilinear_levels(7.0), (2, None));
    /// ```
    pub fn trilinear_levels(&self, lambda: f32) -> (u32, Option<f32>) {
        let last = self.levels() - 1;
        let lambda = if lambda.is_finite() { lambda } else { 0.0 };
        if lambda <= 0.0 || last == 0 {
            return (0, None);
        }
        let lambda = lambda.min(last as f32);
        let d = lambda.floor() as u32;
        let f = lambda - d as f32;
        if f == 0.0 || d >= last {
            (d, None)
        } else {
            (d, Some(f))
        }
    }

    /// The texel nearest filtering reads in one level: `(floor(u W), floor(v H))`, wrapped.
    fn nearest_texel(&self, uv: Vec2, wrap: Wrap, level: u32) -> (u32, u32) {
        let (w, h) = self.level_size(level);
        let [i, j] = self.nearest_unwrapped(uv, level);
        (wrap_coord(i, w, wrap), wrap_coord(j, h, wrap))
    }

    /// The texel nearest filtering reads before the wrap mode applies:
    /// `(floor(u W), floor(v H))` (`u W` in `f32`, clamped to `MAX_TEXEL_COORD`).
    ///
    /// ```
    /// use barylab::raster::texture::Texture;
    /// use glam::Vec2;
    /// let t = Texture::from_texels(4, 4, vec![[0; 4]; 16]).unwrap();
    /// assert_eq!(t.nearest_unwrapped(Vec2::new(1.3, -0.1), 0), [5, -1]);
    /// ```
    pub fn nearest_unwrapped(&self, uv: Vec2, level: u32) -> [i64; 2] {
        let [x, y] = self.texel_coords(uv, level);
        [texel_floor(x), texel_floor(y)]
    }

    /// Texel coordinates of `uv` in mipmap `level` (W x H): `(u W, v H)`, in `f32` as the
    /// filters compute them (texel row 0 is v = 0).
    ///
    /// ```
    /// use barylab::raster::texture::Texture;
    /// use glam::Vec2;
    /// let t = Texture::from_texels(4, 2, vec![[0; 4]; 8]).unwrap();
    /// assert_eq!(t.texel_coords(Vec2::new(0.5, 0.25), 0), [2.0, 0.5]);
    /// ```
    pub fn texel_coords(&self, uv: Vec2, level: u32) -> [f32; 2] {
        let (w, h) = self.level_size(level);
        [uv.x * w as f32, uv.y * h as f32]
    }

    /// Nearest or bilinear taps in one mipmap level.
    fn level_taps(&self, uv: Vec2, filter: Filter, wrap: Wrap, level: u32) -> Taps {
        match filter {
            Filter::Nearest => {
                let (i, j) = self.nearest_texel(uv, wrap, level);
                let tap = Tap {
                    level,
                    i,
                    j,
                    weight: 1.0,
                };
                Taps {
                    taps: [tap; 8],
                    len: 1,
                }
            }
            Filter::Bilinear | Filter::Trilinear => {
                let ([ia, ib], [ja, jb], a, b) = self.bilinear_coords(uv, wrap, level);
                let tap = |i, j, weight| Tap {
                    level,
                    i,
                    j,
                    weight,
                };
                let wt = bilinear_weights(a, b);
                let four = [
                    tap(ia, ja, wt[0]),
                    tap(ib, ja, wt[1]),
                    tap(ia, jb, wt[2]),
                    tap(ib, jb, wt[3]),
                ];
                let mut taps = [four[0]; 8];
                taps[..4].copy_from_slice(&four);
                Taps { taps, len: 4 }
            }
        }
    }

    /// Samples the texture: the filtered colour with each channel in [0, 1].
    pub fn sample(&self, uv: Vec2, filter: Filter, wrap: Wrap) -> [f32; 4] {
        self.sample_lod(uv, filter, wrap, 0.0)
    }

    /// Samples at level of detail `lambda` (used by trilinear filtering only): each channel
    /// is the filtered sum of [`Texture::sample_rgba8`] divided by 255, in [0, 1].
    pub fn sample_lod(&self, uv: Vec2, filter: Filter, wrap: Wrap, lambda: f32) -> [f32; 4] {
        self.filtered_sum(uv, filter, wrap, lambda)
            .map(|c| c / 255.0)
    }

    /// The 8-bit colour the renderer writes for a texture lookup: each channel is
    /// `round(clamp(sum_k weight_k * texel_k, 0, 255))`, the weighted sum of the taps
    /// ([`Texture::taps_lod`]) taken in the texels' own 0..255 scale and rounded half away
    /// from zero.
    ///
    /// This is the renderer's path: it reads the same texels with the same weights, in the
    /// same order, as [`Texture::taps_lod`] lists them (so the sum is bit-identical to
    /// summing the taps), without building the list.
    ///
    /// ```
    /// use barylab::raster::texture::{Texture, Filter, Wrap};
    /// use glam::Vec2;
    /// // A 2x1 texture, black and white: halfway between the texel centres the bilinear sum
    /// // is 0.5 * 0 + 0.5 * 255 = 127.5, which rounds to 128.
    /// let t = Texture::from_texels(2, 1, vec![[0, 0, 0, 255], [255, 255, 255, 255]]).unwrap();
    /// let c = t.sample_rgba8(Vec2::new(0.5, 0.5), Filter::Bilinear, Wrap::ClampToEdge, 0.0);
    /// assert_eq!(c, [128, 128, 128, 255]);
    /// ```
    pub fn sample_rgba8(&self, uv: Vec2, filter: Filter, wrap: Wrap, lambda: f32) -> [u8; 4] {
        self.filtered_sum(uv, filter, wrap, lambda)
            .map(byte_from_sum)
    }

    /// The filtered colour in the texels' 0..255 scale.
    fn filtered_sum(&self, uv: Vec2, filter: Filter, wrap: Wrap, lambda: f32) -> [f32; 4] {
        let mut out = [0.0f32; 4];
        match filter {
            Filter::Nearest => {
                let (i, j) = self.nearest_texel(uv, wrap, 0);
                add_texel(&mut out, self.texel(i, j), 1.0);
            }
            Filter::Bilinear => self.add_bilinear(&mut out, uv, wrap, 0, None),
            Filter::Trilinear => match self.trilinear_levels(lambda) {
                (d, None) => self.add_bilinear(&mut out, uv, wrap, d, None),
                (d, Some(f)) => {
                    self.add_bilinear(&mut out, uv, wrap, d, Some(1.0 - f));
                    self.add_bilinear(&mut out, uv, wrap, d + 1, Some(f));
                }
            },
        }
        out
    }

    /// Texel columns (i0, i0 + 1), rows (j0, j0 + 1), both wrapped, and the fractions (a, b)
    /// of bilinear filtering in one mipmap level.
    fn bilinear_coords(&self, uv: Vec2, wrap: Wrap, level: u32) -> ([u32; 2], [u32; 2], f32, f32) {
        let (w, h) = self.level_size(level);
        let (x, y) = (uv.x * w as f32 - 0.5, uv.y * h as f32 - 0.5);
        let (i0, j0) = (texel_floor(x), texel_floor(y));
        (
            [wrap_coord(i0, w, wrap), wrap_coord(i0 + 1, w, wrap)],
            [wrap_coord(j0, h, wrap), wrap_coord(j0 + 1, h, wrap)],
            bilinear_fraction(x),
            bilinear_fraction(y),
        )
    }

    /// Adds the bilinear lookup in one level to `out`, its weights multiplied by `scale`
    /// (the trilinear blend) when given.
    fn add_bilinear(
        &self,
        out: &mut [f32; 4],
        uv: Vec2,
        wrap: Wrap,
        level: u32,
        scale: Option<f32>,
    ) {
        let ([ia, ib], [ja, jb], a, b) = self.bilinear_coords(uv, wrap, level);
        let weights = bilinear_weights(a, b);
        let texels = [(ia, ja), (ib, ja), (ia, jb), (ib, jb)];
        for (wt, (i, j)) in weights.into_iter().zip(texels) {
            let wt = match scale {
                Some(s) => wt * s,
                None => wt,
            };
            add_texel(out, self.texel_at(level, i, j), wt);
        }
    }

    /// A built-in procedural texture.
    pub fn builtin(which: BuiltinTexture) -> Self {
        match which {
            BuiltinTexture::UvGrid => builtin::uv_grid(),
            BuiltinTexture::Checker => builtin::checker(),
            BuiltinTexture::Rgbw2x2 => builtin::rgbw_2x2(),
            BuiltinTexture::Noise => builtin::noise(),
        }
    }
}
