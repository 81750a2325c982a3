//! Textures: RGBA8 texel storage, wrap modes and filters (OpenGL 4.6, section 8.14).
//!
//! Texel row 0 is the *bottom* row of the picture, so v = 0 is the bottom edge and a picture
//! appears upright on a quad whose uv (0,0) is its lower-left corner. Images loaded from files
//! are flipped on load accordingly.

use std::path::Path;

use ab_glyph::{Font, FontRef, PxScale, ScaleFont};
use glam::Vec2;
use serde::{Deserialize, Serialize};

/// Texture minification/magnification filter.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Filter {
    /// GL_NEAREST: the texel containing the sample.
    Nearest,
    /// GL_LINEAR: the 2x2 texels around the sample, weighted by distance.
    #[default]
    Bilinear,
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
    /// The 2x2 texture of seed 001: red, white / green, blue.
    Rgbw2x2,
}

impl BuiltinTexture {
    /// All built-ins, for listings.
    pub const ALL: [BuiltinTexture; 3] = [
        BuiltinTexture::UvGrid,
        BuiltinTexture::Checker,
        BuiltinTexture::Rgbw2x2,
    ];

    /// The name used in scene files.
    pub fn name(self) -> &'static str {
        match self {
            BuiltinTexture::UvGrid => "uv-grid",
            BuiltinTexture::Checker => "checker",
            BuiltinTexture::Rgbw2x2 => "rgbw-2x2",
        }
    }

    /// Looks a built-in up by its scene-file name.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|b| b.name() == name)
    }
}

/// Errors while loading a texture from a file.
#[derive(Debug, thiserror::Error)]
pub enum TextureError {
    #[error("cannot read texture {path}: {source}")]
    Read {
        path: String,
        source: std::io::Error,
    },
    #[error("cannot decode texture {path}: {source}")]
    Decode {
        path: String,
        source: image::ImageError,
    },
    #[error("texture {path} is empty (0 x 0 pixels)")]
    Empty { path: String },
}

/// An RGBA8 texture; texel row 0 is the bottom row (v = 0).
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    width: u32,
    height: u32,
    texels: Vec<[u8; 4]>,
}

/// One texel fetch with its weight, as used by the filters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tap {
    /// Texel column after wrapping.
    pub i: u32,
    /// Texel row after wrapping (0 = bottom).
    pub j: u32,
    pub weight: f32,
}

/// Applies a wrap mode to an integer texel coordinate (OpenGL 4.6, section 8.14.2).
///
/// ```
/// use barylab::raster::texture::{wrap_coord, Wrap};
/// assert_eq!(wrap_coord(-1, 4, Wrap::Repeat), 3);
/// assert_eq!(wrap_coord(5, 4, Wrap::ClampToEdge), 3);
/// // Mirrored repeat of size 4: ... 4 -> 3, 5 -> 2, -1 -> 0, -2 -> 1.
/// assert_eq!(wrap_coord(4, 4, Wrap::MirroredRepeat), 3);
/// assert_eq!(wrap_coord(5, 4, Wrap::MirroredRepeat), 2);
/// assert_eq!(wrap_coord(-1, 4, Wrap::MirroredRepeat), 0);
/// assert_eq!(wrap_coord(-2, 4, Wrap::MirroredRepeat), 1);
/// ```
pub fn wrap_coord(i: i64, size: u32, wrap: Wrap) -> u32 {
    let s = i64::from(size);
    let r = match wrap {
        Wrap::Repeat => i.rem_euclid(s),
        Wrap::ClampToEdge => i.clamp(0, s - 1),
        Wrap::MirroredRepeat => {
            let m = i.rem_euclid(2 * s) - s;
            let mirror = if m >= 0 { m } else { -(1 + m) };
            (s - 1) - mirror
        }
    };
    r as u32
}

/// Largest |texel coordinate| used for wrapping: far beyond any texture size, keeps the
/// `f32 -> i64` conversion of huge or infinite uv well defined.
const MAX_TEXEL_COORD: f32 = 1e9;

fn texel_floor(x: f32) -> i64 {
    if x.is_nan() {
        return 0;
    }
    x.clamp(-MAX_TEXEL_COORD, MAX_TEXEL_COORD).floor() as i64
}

impl Texture {
    /// A texture from texels given bottom row first. Returns `None` if the size does not match
    /// or is zero.
    pub fn from_texels(width: u32, height: u32, texels: Vec<[u8; 4]>) -> Option<Self> {
        if width == 0 || height == 0 || texels.len() != width as usize * height as usize {
            return None;
        }
        Some(Self {
            width,
            height,
            texels,
        })
    }

    /// A texture from an image whose row 0 is the top (as image files store it).
    pub fn from_image(img: &image::RgbaImage) -> Option<Self> {
        let (w, h) = img.dimensions();
        let mut texels = Vec::with_capacity(w as usize * h as usize);
        for row in (0..h).rev() {
            for col in 0..w {
                texels.push(img.get_pixel(col, row).0);
            }
        }
        Self::from_texels(w, h, texels)
    }

    /// Loads PNG, JPEG, BMP, TGA or WebP from a file, converting to RGBA8.
    pub fn load(path: &Path) -> Result<Self, TextureError> {
        let shown = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|source| TextureError::Read {
            path: shown.clone(),
            source,
        })?;
        let img = image::load_from_memory(&bytes).map_err(|source| TextureError::Decode {
            path: shown.clone(),
            source,
        })?;
        Self::from_image(&img.to_rgba8()).ok_or(TextureError::Empty { path: shown })
    }

    /// The texels as an image with row 0 at the top, for display and export.
    pub fn to_image(&self) -> image::RgbaImage {
        image::RgbaImage::from_fn(self.width, self.height, |x, y| {
            image::Rgba(self.texel(x, self.height - 1 - y))
        })
    }

    pub fn width(&self) -> u32 {
        self.width
    }

    pub fn height(&self) -> u32 {
        self.height
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
    pub fn taps(&self, uv: Vec2, filter: Filter, wrap: Wrap) -> Vec<Tap> {
        let (w, h) = (self.width, self.height);
        let su = uv.x * w as f32;
        let sv = uv.y * h as f32;
        match filter {
            Filter::Nearest => vec![Tap {
                i: wrap_coord(texel_floor(su), w, wrap),
                j: wrap_coord(texel_floor(sv), h, wrap),
                weight: 1.0,
            }],
            Filter::Bilinear => {
                let (x, y) = (su - 0.5, sv - 0.5);
                let (i0, j0) = (texel_floor(x), texel_floor(y));
                let a = if x.is_finite() { x - x.floor() } else { 0.0 };
                let b = if y.is_finite() { y - y.floor() } else { 0.0 };
                let (a, b) = (a.clamp(0.0, 1.0), b.clamp(0.0, 1.0));
                let (ia, ib) = (wrap_coord(i0, w, wrap), wrap_coord(i0 + 1, w, wrap));
                let (ja, jb) = (wrap_coord(j0, h, wrap), wrap_coord(j0 + 1, h, wrap));
                vec![
                    Tap {
                        i: ia,
                        j: ja,
                        weight: (1.0 - a) * (1.0 - b),
                    },
                    Tap {
                        i: ib,
                        j: ja,
                        weight: a * (1.0 - b),
                    },
                    Tap {
                        i: ia,
                        j: jb,
                        weight: (1.0 - a) * b,
                    },
                    Tap {
                        i: ib,
                        j: jb,
                        weight: a * b,
                    },
                ]
            }
        }
    }

    /// Samples the texture: the filtered colour with each channel in [0, 1].
    pub fn sample(&self, uv: Vec2, filter: Filter, wrap: Wrap) -> [f32; 4] {
        let mut out = [0.0f32; 4];
        for tap in self.taps(uv, filter, wrap) {
            let t = self.texel(tap.i, tap.j);
            for (o, c) in out.iter_mut().zip(t) {
                *o += tap.weight * f32::from(c) / 255.0;
            }
        }
        out
    }

    /// A built-in procedural texture.
    pub fn builtin(which: BuiltinTexture) -> Self {
        match which {
            BuiltinTexture::UvGrid => uv_grid(),
            BuiltinTexture::Checker => checker(),
            BuiltinTexture::Rgbw2x2 => rgbw_2x2(),
        }
    }
}

fn checker() -> Texture {
    const SIZE: u32 = 256;
    const CELLS: u32 = 8;
    let cell = SIZE / CELLS;
    let mut texels = Vec::with_capacity((SIZE * SIZE) as usize);
    for j in 0..SIZE {
        for i in 0..SIZE {
            let dark = (i / cell + j / cell).is_multiple_of(2);
            texels.push(if dark {
                [40, 40, 40, 255]
            } else {
                [235, 235, 235, 255]
            });
        }
    }
    Texture {
        width: SIZE,
        height: SIZE,
        texels,
    }
}

fn rgbw_2x2() -> Texture {
    // Seed 001's picture[x][y]: (0,0) red, (0,1) white, (1,0) green, (1,1) blue, with y = v.
    Texture {
        width: 2,
        height: 2,
        texels: vec![
            [255, 0, 0, 255],
            [0, 255, 0, 255],
            [255, 255, 255, 255],
            [0, 0, 255, 255],
        ],
    }
}

/// 8x8 cells of 64 texels. Cell (c, r) (c along u, r along v) is tinted by its position and
/// labelled "c,r"; thin dark lines separate the cells and a thicker line marks the borders.
fn uv_grid() -> Texture {
    const SIZE: u32 = 512;
    const CELLS: u32 = 8;
    let cell = SIZE / CELLS;
    // Draw top-down in an image, then flip into texel order.
    let mut img = image::RgbaImage::new(SIZE, SIZE);
    for (x, y, px) in img.enumerate_pixels_mut() {
        let c = x / cell;
        let r = CELLS - 1 - y / cell;
        let (fu, fv) = (c as f32 / (CELLS - 1) as f32, r as f32 / (CELLS - 1) as f32);
        let light = (c + r).is_multiple_of(2);
        let base = if light { 0.92 } else { 0.78 };
        let rgb = [
            base - 0.35 * (1.0 - fu) * fv,
            base - 0.30 * fu * (1.0 - fv),
            base - 0.35 * (1.0 - fu) * (1.0 - fv) - 0.2 * fu * fv,
        ];
        let (lx, ly) = (x % cell, y % cell);
        let line = lx == 0 || ly == 0 || lx == cell - 1 || ly == cell - 1;
        let border = x < 3 || y < 3 || x >= SIZE - 3 || y >= SIZE - 3;
        *px = if border {
            image::Rgba([20, 20, 30, 255])
        } else if line {
            image::Rgba([70, 70, 90, 255])
        } else {
            image::Rgba([
                (rgb[0] * 255.0) as u8,
                (rgb[1] * 255.0) as u8,
                (rgb[2] * 255.0) as u8,
                255,
            ])
        };
    }
    if let Ok(font) = FontRef::try_from_slice(epaint_default_fonts::HACK_REGULAR) {
        for r in 0..CELLS {
            for c in 0..CELLS {
                let label = format!("{c},{r}");
                let x0 = c * cell;
                let y0 = (CELLS - 1 - r) * cell;
                draw_text_centered(&mut img, &font, &label, x0, y0, cell, [25, 25, 40]);
            }
        }
    }
    Texture::from_image(&img).unwrap_or_else(checker)
}

/// Draws `text` centred in the square cell at (x0, y0) of side `cell`.
fn draw_text_centered(
    img: &mut image::RgbaImage,
    font: &FontRef<'_>,
    text: &str,
    x0: u32,
    y0: u32,
    cell: u32,
    rgb: [u8; 3],
) {
    let scale = PxScale::from(cell as f32 * 0.42);
    let scaled = font.as_scaled(scale);
    let width: f32 = text
        .chars()
        .map(|ch| scaled.h_advance(font.glyph_id(ch)))
        .sum();
    let mut pen_x = x0 as f32 + (cell as f32 - width) / 2.0;
    let baseline = y0 as f32 + (cell as f32 + scaled.ascent() + scaled.descent()) / 2.0;
    for ch in text.chars() {
        let id = font.glyph_id(ch);
        let glyph = id.with_scale_and_position(scale, ab_glyph::point(pen_x, baseline));
        pen_x += scaled.h_advance(id);
        if let Some(outlined) = font.outline_glyph(glyph) {
            let b = outlined.px_bounds();
            outlined.draw(|gx, gy, coverage| {
                let px = b.min.x as i64 + i64::from(gx);
                let py = b.min.y as i64 + i64::from(gy);
                if px < 0 || py < 0 || px >= img.width() as i64 || py >= img.height() as i64 {
                    return;
                }
                let p = img.get_pixel_mut(px as u32, py as u32);
                for (ch, fg) in p.0.iter_mut().zip(rgb) {
                    let bg = f32::from(*ch);
                    *ch = (bg + (f32::from(fg) - bg) * coverage.clamp(0.0, 1.0)) as u8;
                }
            });
        }
    }
}
