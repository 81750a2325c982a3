//! The framebuffer: the colour image and, beside it, per-pixel float buffers that the GUI, the
//! inspector and the AOV export read.

use super::fill::fill_words;
use super::setup::Facing;
use crate::budget::{self, MemoryError};

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

/// One buffer of a [`Framebuffer`] (a field of the same name).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Buffer {
    /// [`Framebuffer::color`].
    Color,
    /// [`Framebuffer::depth`].
    Depth,
    /// [`Framebuffer::triangle`].
    Triangle,
    /// [`Framebuffer::facing`].
    Facing,
    /// [`Framebuffer::weights_screen`].
    WeightsScreen,
    /// [`Framebuffer::weights_perspective`].
    WeightsPerspective,
    /// [`Framebuffer::uv_affine`].
    UvAffine,
    /// [`Framebuffer::uv_perspective`].
    UvPerspective,
    /// [`Framebuffer::inv_w`].
    InvW,
    /// [`Framebuffer::texel_difference`].
    TexelDifference,
}

impl Buffer {
    /// Every buffer, in field order.
    pub const ALL: [Buffer; 10] = [
        Buffer::Color,
        Buffer::Depth,
        Buffer::Triangle,
        Buffer::Facing,
        Buffer::WeightsScreen,
        Buffer::WeightsPerspective,
        Buffer::UvAffine,
        Buffer::UvPerspective,
        Buffer::InvW,
        Buffer::TexelDifference,
    ];

    /// The buffer's name in messages ("colour buffer").
    pub const fn name(self) -> &'static str {
        match self {
            Buffer::Color => "colour buffer",
            Buffer::Depth => "depth buffer",
            Buffer::Triangle => "triangle id buffer",
            Buffer::Facing => "facing buffer",
            Buffer::WeightsScreen => "screen weights buffer",
            Buffer::WeightsPerspective => "perspective weights buffer",
            Buffer::UvAffine => "affine uv buffer",
            Buffer::UvPerspective => "perspective uv buffer",
            Buffer::InvW => "1/w buffer",
            Buffer::TexelDifference => "texel difference buffer",
        }
    }

    /// Bytes one pixel of this buffer takes (the size of its element type).
    pub const fn bytes_per_pixel(self) -> u64 {
        (match self {
            Buffer::Color => size_of::<[u8; 4]>(),
            Buffer::Depth | Buffer::InvW | Buffer::TexelDifference => size_of::<f32>(),
            Buffer::Triangle => size_of::<u32>(),
            Buffer::Facing => size_of::<Facing>(),
            Buffer::WeightsScreen | Buffer::WeightsPerspective => size_of::<[f32; 3]>(),
            Buffer::UvAffine | Buffer::UvPerspective => size_of::<[f32; 2]>(),
        }) as u64
    }
}

impl Buffers {
    /// The buffer layout, the one table of which buffer each set has: colour and depth
    /// always; [`Buffers::All`] every other one but the texel difference;
    /// [`Buffers::ColorDepthUv`] the triangle and both uvs; [`Buffers::DepthDifference`] the
    /// texel difference. [`Framebuffer::resize`], the band views and the memory estimate of a
    /// render read it.
    ///
    /// ```
    /// use barylab::raster::framebuffer::{Buffer, Buffers};
    /// assert!(Buffers::ColorDepthUv.has(Buffer::UvAffine));
    /// assert!(!Buffers::All.has(Buffer::TexelDifference));
    /// ```
    pub const fn has(self, buffer: Buffer) -> bool {
        use Buffer as B;
        match (self, buffer) {
            (_, B::Color | B::Depth) => true,
            (Buffers::All, B::TexelDifference) => false,
            (Buffers::All, _) => true,
            (Buffers::ColorDepthUv, B::Triangle | B::UvAffine | B::UvPerspective) => true,
            (Buffers::DepthDifference, B::TexelDifference) => true,
            _ => false,
        }
    }

    /// Bytes per pixel of a framebuffer with these buffers: the sum of
    /// [`Buffer::bytes_per_pixel`] over the buffers it [has](Buffers::has).
    ///
    /// ```
    /// use barylab::raster::framebuffer::Buffers;
    /// assert_eq!(Buffers::ColorDepth.bytes_per_pixel(), 8);
    /// assert_eq!(Buffers::DepthDifference.bytes_per_pixel(), 12);
    /// ```
    pub fn bytes_per_pixel(self) -> u64 {
        Buffer::ALL
            .iter()
            .filter(|&&b| self.has(b))
            .map(|b| b.bytes_per_pixel())
            .sum()
    }
}

/// Colour plus per-pixel data of the front-most fragment. Uncovered pixels hold the
/// background colour, depth 1, 0 in the weight, uv and 1/w buffers, NaN in the texel
/// difference and [`NO_TRIANGLE`] as their triangle. Which buffers have a value per pixel is
/// [`Buffers::has`]'s table (with [`Buffers::ColorDepth`] only `color` and `depth`); the
/// others are empty.
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
    /// A framebuffer of no pixels (nothing allocated): what [`render_into`] resizes.
    ///
    /// [`render_into`]: super::render::render_into
    pub fn empty() -> Self {
        Self {
            width: 0,
            height: 0,
            color: Vec::new(),
            depth: Vec::new(),
            triangle: Vec::new(),
            facing: Vec::new(),
            weights_screen: Vec::new(),
            weights_perspective: Vec::new(),
            uv_affine: Vec::new(),
            uv_perspective: Vec::new(),
            inv_w: Vec::new(),
            texel_difference: Vec::new(),
        }
    }

    /// A cleared framebuffer with every buffer, or the error of a buffer the system refuses
    /// ([`Framebuffer::resize`]).
    pub fn new(width: u32, height: u32, background: [u8; 4]) -> Result<Self, MemoryError> {
        Self::with_buffers(width, height, background, Buffers::All)
    }

    /// A cleared framebuffer with the given buffers, or the error of a buffer the system
    /// refuses ([`Framebuffer::resize`]).
    pub fn with_buffers(
        width: u32,
        height: u32,
        background: [u8; 4],
        buffers: Buffers,
    ) -> Result<Self, MemoryError> {
        let mut frame = Self::empty();
        frame.resize(width, height, buffers)?;
        frame.clear(background);
        Ok(frame)
    }

    /// Gives the framebuffer `width` x `height` pixels of the buffers `buffers` has
    /// ([`Buffers::has`]) and empties the others, reusing the memory it holds. The pixels'
    /// contents are not cleared: renders clear them band by band ([`Framebuffer::clear`]
    /// clears the whole frame). Every buffer's memory is asked for fallibly: a buffer the
    /// system refuses is an error naming it and its size ("cannot allocate 1.0 GiB for the
    /// 16384x16384 colour buffer"), never an abort; the frame then has no pixels.
    pub fn resize(&mut self, width: u32, height: u32, buffers: Buffers) -> Result<(), MemoryError> {
        let done = self.resize_buffers(width, height, buffers);
        if done.is_err() {
            *self = Self::empty();
        }
        done
    }

    /// [`Framebuffer::resize`]'s work, stopping at the first buffer refused.
    fn resize_buffers(
        &mut self,
        width: u32,
        height: u32,
        buffers: Buffers,
    ) -> Result<(), MemoryError> {
        let n = width as usize * height as usize;
        let len = |b: Buffer| if buffers.has(b) { n } else { 0 };
        let what = |b: Buffer| move || format!("the {width}x{height} {}", b.name());
        use budget::try_resize as fit;
        self.width = width;
        self.height = height;
        fit(
            &mut self.color,
            len(Buffer::Color),
            [0; 4],
            what(Buffer::Color),
        )?;
        fit(
            &mut self.depth,
            len(Buffer::Depth),
            1.0,
            what(Buffer::Depth),
        )?;
        let triangle = len(Buffer::Triangle);
        fit(
            &mut self.triangle,
            triangle,
            NO_TRIANGLE,
            what(Buffer::Triangle),
        )?;
        let facing = len(Buffer::Facing);
        fit(
            &mut self.facing,
            facing,
            Facing::Front,
            what(Buffer::Facing),
        )?;
        let (ws, wp) = (len(Buffer::WeightsScreen), len(Buffer::WeightsPerspective));
        fit(
            &mut self.weights_screen,
            ws,
            [0.0; 3],
            what(Buffer::WeightsScreen),
        )?;
        fit(
            &mut self.weights_perspective,
            wp,
            [0.0; 3],
            what(Buffer::WeightsPerspective),
        )?;
        let (ua, up) = (len(Buffer::UvAffine), len(Buffer::UvPerspective));
        fit(&mut self.uv_affine, ua, [0.0; 2], what(Buffer::UvAffine))?;
        fit(
            &mut self.uv_perspective,
            up,
            [0.0; 2],
            what(Buffer::UvPerspective),
        )?;
        fit(&mut self.inv_w, len(Buffer::InvW), 0.0, what(Buffer::InvW))?;
        let td = len(Buffer::TexelDifference);
        fit(
            &mut self.texel_difference,
            td,
            f32::NAN,
            what(Buffer::TexelDifference),
        )
    }

    /// Clears every pixel of every buffer: colour to `background`, depth to 1 (the far
    /// plane), the rest to the values of an uncovered pixel.
    pub fn clear(&mut self, background: [u8; 4]) {
        let height = self.height.max(1);
        for mut band in RowBand::split(self, height) {
            band.clear(background);
        }
    }

    /// Index of pixel (x, y) in the buffers.
    pub fn index(&self, x: u32, y: u32) -> usize {
        y as usize * self.width as usize + x as usize
    }

    /// Which buffers this framebuffer has: the first of [`Buffers::All`],
    /// [`Buffers::DepthDifference`], [`Buffers::ColorDepthUv`] and [`Buffers::ColorDepth`]
    /// whose every buffer ([`Buffers::has`]) holds a value per pixel.
    pub fn buffers(&self) -> Buffers {
        let n = self.color.len();
        [
            Buffers::All,
            Buffers::DepthDifference,
            Buffers::ColorDepthUv,
        ]
        .into_iter()
        .find(|&set| {
            Buffer::ALL
                .into_iter()
                .all(|b| !set.has(b) || self.buffer_len(b) == n)
        })
        .unwrap_or(Buffers::ColorDepth)
    }

    /// How many values `buffer` holds (`width * height`, or 0 where it is absent).
    pub fn buffer_len(&self, buffer: Buffer) -> usize {
        match buffer {
            Buffer::Color => self.color.len(),
            Buffer::Depth => self.depth.len(),
            Buffer::Triangle => self.triangle.len(),
            Buffer::Facing => self.facing.len(),
            Buffer::WeightsScreen => self.weights_screen.len(),
            Buffer::WeightsPerspective => self.weights_perspective.len(),
            Buffer::UvAffine => self.uv_affine.len(),
            Buffer::UvPerspective => self.uv_perspective.len(),
            Buffer::InvW => self.inv_w.len(),
            Buffer::TexelDifference => self.texel_difference.len(),
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

    /// The colour buffer as an image (its memory asked for fallibly: an error naming the
    /// image when the system refuses it).
    pub fn to_image(&self) -> Result<image::RgbaImage, MemoryError> {
        let (w, h) = (self.width, self.height);
        let mut img = budget::try_image(w, h, [0; 4], || format!("the {w}x{h} output image"))?;
        for (px, c) in img.pixels_mut().zip(&self.color) {
            px.0 = *c;
        }
        Ok(img)
    }
}

/// Mutable views of rows `y0..y0 + rows` of every framebuffer buffer: what one parallel task
/// of a render draws into (an absent buffer is empty in every band).
pub(super) struct RowBand<'a> {
    pub(super) y0: u32,
    pub(super) rows: u32,
    pub(super) width: u32,
    pub(super) color: &'a mut [[u8; 4]],
    pub(super) depth: &'a mut [f32],
    pub(super) triangle: &'a mut [u32],
    pub(super) facing: &'a mut [Facing],
    pub(super) weights_screen: &'a mut [[f32; 3]],
    pub(super) weights_perspective: &'a mut [[f32; 3]],
    pub(super) uv_affine: &'a mut [[f32; 2]],
    pub(super) uv_perspective: &'a mut [[f32; 2]],
    pub(super) inv_w: &'a mut [f32],
    pub(super) texel_difference: &'a mut [f32],
}

impl<'a> RowBand<'a> {
    /// Cuts the framebuffer into bands of `rows_per_band` rows (the last may be shorter).
    pub(super) fn split(frame: &'a mut Framebuffer, rows_per_band: u32) -> Vec<RowBand<'a>> {
        let width = frame.width;
        let mut rest = RowBand {
            y0: 0,
            rows: frame.height,
            width,
            color: &mut frame.color,
            depth: &mut frame.depth,
            triangle: &mut frame.triangle,
            facing: &mut frame.facing,
            weights_screen: &mut frame.weights_screen,
            weights_perspective: &mut frame.weights_perspective,
            uv_affine: &mut frame.uv_affine,
            uv_perspective: &mut frame.uv_perspective,
            inv_w: &mut frame.inv_w,
            texel_difference: &mut frame.texel_difference,
        };
        let mut out = Vec::new();
        while rest.rows > rows_per_band {
            let (head, tail) = rest.split_at(rows_per_band);
            out.push(head);
            rest = tail;
        }
        out.push(rest);
        out
    }

    /// The first and last row of `bounds` inside this band, if any.
    pub(super) fn rows_of(&self, bounds: &super::setup::PixelBounds) -> Option<(u32, u32)> {
        let last = (self.y0 + self.rows).checked_sub(1)?;
        let (start, end) = (bounds.y0.max(self.y0), bounds.y1.min(last));
        (self.rows > 0 && start <= end).then_some((start, end))
    }

    /// Whether every per-pixel buffer is present ([`Buffers::All`]).
    pub(super) fn has_aovs(&self) -> bool {
        self.weights_screen.len() == self.color.len()
    }

    /// Clears every buffer of the band: colour to `background`, depth to 1 (the far plane).
    pub(super) fn clear(&mut self, background: [u8; 4]) {
        fill_words(self.color, background);
        fill_words(self.depth, 1.0);
        self.triangle.fill(NO_TRIANGLE);
        self.facing.fill(Facing::Front);
        self.weights_screen.fill([0.0; 3]);
        self.weights_perspective.fill([0.0; 3]);
        self.uv_affine.fill([0.0; 2]);
        self.uv_perspective.fill([0.0; 2]);
        self.inv_w.fill(0.0);
        self.texel_difference.fill(f32::NAN);
    }

    /// The first `rows` rows and the remainder.
    fn split_at(self, rows: u32) -> (RowBand<'a>, RowBand<'a>) {
        let n = rows as usize * self.width as usize;
        // Absent buffers (`Buffers::ColorDepth`) are empty and stay empty in both halves.
        fn cut<T>(s: &mut [T], n: usize) -> (&mut [T], &mut [T]) {
            let n = n.min(s.len());
            s.split_at_mut(n)
        }
        let (color, color_t) = self.color.split_at_mut(n);
        let (depth, depth_t) = self.depth.split_at_mut(n);
        let (triangle, triangle_t) = cut(self.triangle, n);
        let (facing, facing_t) = cut(self.facing, n);
        let (ws, ws_t) = cut(self.weights_screen, n);
        let (wp, wp_t) = cut(self.weights_perspective, n);
        let (ua, ua_t) = cut(self.uv_affine, n);
        let (up, up_t) = cut(self.uv_perspective, n);
        let (iw, iw_t) = cut(self.inv_w, n);
        let (td, td_t) = cut(self.texel_difference, n);
        (
            RowBand {
                y0: self.y0,
                rows,
                width: self.width,
                color,
                depth,
                triangle,
                facing,
                weights_screen: ws,
                weights_perspective: wp,
                uv_affine: ua,
                uv_perspective: up,
                inv_w: iw,
                texel_difference: td,
            },
            RowBand {
                y0: self.y0 + rows,
                rows: self.rows - rows,
                width: self.width,
                color: color_t,
                depth: depth_t,
                triangle: triangle_t,
                facing: facing_t,
                weights_screen: ws_t,
                weights_perspective: wp_t,
                uv_affine: ua_t,
                uv_perspective: up_t,
                inv_w: iw_t,
                texel_difference: td_t,
            },
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every buffer set's framebuffer has exactly the buffers of the layout table, each
    /// `width * height` long, cleared; resizing to another set follows the table too; and the
    /// bytes per pixel are the element sizes of those buffers.
    #[test]
    fn the_layout_table_decides_every_buffer() {
        let sets = [
            Buffers::All,
            Buffers::ColorDepth,
            Buffers::ColorDepthUv,
            Buffers::DepthDifference,
        ];
        for set in sets {
            let mut frame = Framebuffer::with_buffers(3, 2, [9; 4], set).expect("6 pixels");
            assert_eq!(frame.buffers(), set);
            for b in Buffer::ALL {
                let want = if set.has(b) { 6 } else { 0 };
                assert_eq!(frame.buffer_len(b), want, "{set:?} {b:?}");
            }
            assert!(frame.color.iter().all(|&c| c == [9; 4]));
            assert!(frame.texel_difference.iter().all(|d| d.is_nan()));
            for other in sets {
                frame.resize(5, 1, other).expect("5 pixels");
                assert_eq!(frame.buffers(), other, "{set:?} -> {other:?}");
            }
        }
        assert_eq!(
            Buffers::All.bytes_per_pixel(),
            4 + 4 + 4 + 1 + 12 + 12 + 8 + 8 + 4
        );
        assert_eq!(Buffers::ColorDepthUv.bytes_per_pixel(), 4 + 4 + 4 + 8 + 8);
    }
}
