//! The framebuffer: the colour image and, beside it, per-pixel float buffers that the GUI, the
//! inspector and the AOV export read.

use super::setup::Facing;

/// Marks a pixel no triangle covers in [`Framebuffer::triangle`].
pub const NO_TRIANGLE: u32 = u32::MAX;

/// Colour plus per-pixel data of the front-most fragment. Uncovered pixels hold 0 in every
/// float buffer (never NaN) and `NO_TRIANGLE` as their triangle.
#[derive(Clone, Debug, PartialEq)]
pub struct Framebuffer {
    pub width: u32,
    pub height: u32,
    /// RGBA8, row 0 at the top.
    pub color: Vec<[u8; 4]>,
    /// Window depth z/w in [0, 1]; cleared to 1 (the far plane), less-than test.
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
}

impl Framebuffer {
    /// A cleared framebuffer.
    pub fn new(width: u32, height: u32, background: [u8; 4]) -> Self {
        let n = width as usize * height as usize;
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
        }
    }

    /// Index of pixel (x, y) in the buffers.
    pub fn index(&self, x: u32, y: u32) -> usize {
        y as usize * self.width as usize + x as usize
    }

    /// Whether a triangle covers pixel (x, y).
    pub fn covered(&self, x: u32, y: u32) -> bool {
        self.triangle[self.index(x, y)] != NO_TRIANGLE
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
