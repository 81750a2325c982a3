//! The framebuffer: the colour image and, beside it, per-pixel float buffers that the GUI, the
//! inspector and the AOV export read.

use super::setup::Facing;

/// Marks a pixel no triangle covers in [`Framebuffer::triangle`].
pub const NO_TRIANGLE: u32 = u32::MAX;

/// The depth test: a fragment at window depth `depth` replaces the buffer's `stored` value
/// when it is nearer, `depth < stored` (OpenGL's `GL_LESS`; the buffer is cleared to 1, and a
/// NaN depth fails). The AVX2 lanes repeat it as an ordered less-than compare.
///
/// ```
/// use barylab::raster::framebuffer::depth_passes;
/// assert!(depth_passes(0.25, 1.0));
/// assert!(!depth_passes(0.5, 0.5));
/// assert!(!depth_passes(f32::NAN, 1.0));
/// ```
#[inline(always)]
pub fn depth_passes(depth: f32, stored: f32) -> bool {
    depth < stored
}

/// Which per-pixel buffers a render fills.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Buffers {
    /// Colour, depth and every per-pixel buffer the inspector, the heatmap and the AOV export
    /// read.
    #[default]
    All,
    /// Colour and depth only; the other buffers are left empty (the fast path for display
    /// and benchmarks).
    ColorDepth,
    /// Colour, depth, the triangle and uv both ways (what the GPU comparison reads). The
    /// edge-function lanes draw it (the weights, facing and 1/w buffers are left empty).
    ColorDepthUv,
    /// Depth and the texel difference of the two uvs per pixel: what the difference heatmap
    /// reads (4 bytes a pixel instead of the 20 of the triangle and two uv pairs). Nothing is
    /// shaded: the colour buffer keeps the background, which the heatmap shows dimmed where
    /// no triangle is drawn.
    DepthDifference,
}

/// Colour plus per-pixel data of the front-most fragment. Uncovered pixels hold the
/// background colour, depth 1, 0 in the other float buffers (never NaN) and [`NO_TRIANGLE`]
/// as their triangle. With
/// [`Buffers::ColorDepth`] only `color` and `depth` have a value per pixel; the other buffers
/// are empty.
#[derive(Clone, Debug, PartialEq)]
pub struct Framebuffer {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels; each filled buffer holds `width * height` values, row by row from the
    /// top.
    pub height: u32,
    /// RGBA8, row 0 at the top.
    pub color: Vec<[u8; 4]>,
    /// Window depth `(z/w + 1)/2` in [0, 1]; cleared to 1 (the far plane), less-than test.
    pub depth: Vec<f32>,
    /// Index of the source triangle that wrote the pixel, or `NO_TRIANGLE`.
    pub triangle: Vec<u32>,
    /// Facing of the triangle that wrote the pixel (meaningful where covered).
    pub facing: Vec<Facing>,
    /// Screen-space (affine) weights of the source triangle's vertices.
    pub weights_screen: Vec<[f32; 3]>,
    /// Perspective-correct weights of the source triangle's vertices.
    pub weights_perspective: Vec<[f32; 3]>,
    /// Texture coordinate interpolated with screen-space weights.
    pub uv_affine: Vec<[f32; 2]>,
    /// Texture coordinate interpolated perspective-correctly.
    pub uv_perspective: Vec<[f32; 2]>,
    /// 1/w interpolated linearly on screen.
    pub inv_w: Vec<f32>,
    /// How far apart the affine and the perspective-correct uv are, in texels of the texture
    /// drawn ([`texel_difference`](super::texture::texel_difference)); NaN where no triangle
    /// is drawn. Only with [`Buffers::DepthDifference`] (empty otherwise: the other
    /// buffer sets keep both uvs).
    pub texel_difference: Vec<f32>,
}

impl Framebuffer {
    /// A cleared framebuffer with every buffer.
    pub fn new(width: u32, height: u32, background: [u8; 4]) -> Self {
        Self::with_buffers(width, height, background, Buffers::All)
    }

    /// A cleared framebuffer with the given buffers.
    pub fn with_buffers(width: u32, height: u32, background: [u8; 4], buffers: Buffers) -> Self {
        let n = width as usize * height as usize;
        match buffers {
            Buffers::ColorDepth => {
                return Self {
                    width,
                    height,
                    color: vec![background; n],
                    depth: vec![1.0; n],
                    ..Self::new(0, 0, background)
                };
            }
            Buffers::ColorDepthUv => {
                return Self {
                    width,
                    height,
                    color: vec![background; n],
                    depth: vec![1.0; n],
                    triangle: vec![NO_TRIANGLE; n],
                    uv_affine: vec![[0.0; 2]; n],
                    uv_perspective: vec![[0.0; 2]; n],
                    ..Self::new(0, 0, background)
                };
            }
            Buffers::DepthDifference => {
                return Self {
                    width,
                    height,
                    color: vec![background; n],
                    depth: vec![1.0; n],
                    texel_difference: vec![f32::NAN; n],
                    ..Self::new(0, 0, background)
                };
            }
            Buffers::All => {}
        }
        Self {
            width,
            height,
            color: vec![background; n],
            depth: vec![1.0; n],
            triangle: vec![NO_TRIANGLE; n],
            facing: vec![Facing::Front; n],
            weights_screen: vec![[0.0; 3]; n],
            weights_perspective: vec![[0.0; 3]; n],
            uv_affine: vec![[0.0; 2]; n],
            uv_perspective: vec![[0.0; 2]; n],
            inv_w: vec![0.0; n],
            texel_difference: Vec::new(),
        }
    }

    /// Index of pixel (x, y) in the buffers.
    pub fn index(&self, x: u32, y: u32) -> usize {
        y as usize * self.width as usize + x as usize
    }

    /// Which buffers this framebuffer has.
    pub fn buffers(&self) -> Buffers {
        if self.weights_screen.len() == self.color.len() {
            Buffers::All
        } else if self.texel_difference.len() == self.color.len() && !self.color.is_empty() {
            Buffers::DepthDifference
        } else if self.uv_affine.len() == self.color.len() {
            Buffers::ColorDepthUv
        } else {
            Buffers::ColorDepth
        }
    }

    /// Whether a triangle covers pixel (x, y). Only the cleared depth (the far plane, which
    /// no fragment passes with the less-than test) tells uncovered pixels apart when the
    /// triangle buffer is absent.
    pub fn covered(&self, x: u32, y: u32) -> bool {
        let i = self.index(x, y);
        match self.triangle.get(i) {
            Some(&t) => t != NO_TRIANGLE,
            None => self.depth[i] < 1.0,
        }
    }

    /// The colour buffer as an image.
    pub fn to_image(&self) -> image::RgbaImage {
        let mut img = image::RgbaImage::new(self.width, self.height);
        for (px, c) in img.pixels_mut().zip(&self.color) {
            px.0 = *c;
        }
        img
    }
}
