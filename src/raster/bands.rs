//! Bands of image rows for parallel rasterization: mutable views of a band's rows of every
//! framebuffer buffer ([`RowBand`]), and which set-up triangles reach each band
//! ([`bin_by_band`]). Each band is one rayon task in [`render`](super::render).

use super::framebuffer::{Framebuffer, NO_TRIANGLE};
use super::render::PreparedTriangle;
use super::setup::Facing;

/// The set-up triangles that reach each band of `rows_per_band` rows, in submission order, as
/// `(triangle, setup)` indices: each band then visits only its own triangles (a dense mesh
/// has hundreds of thousands, each in one or two bands).
pub(super) fn bin_by_band(
    triangles: &[PreparedTriangle],
    height: u32,
    rows_per_band: u32,
) -> Vec<Vec<(u32, u32)>> {
    let bands = height.div_ceil(rows_per_band).max(1) as usize;
    let mut bins: Vec<Vec<(u32, u32)>> = vec![Vec::new(); bands];
    for (ti, tri) in triangles.iter().enumerate() {
        for (si, setup) in tri.setups.iter().enumerate() {
            let first = (setup.bounds.y0 / rows_per_band) as usize;
            let last = ((setup.bounds.y1 / rows_per_band) as usize).min(bands - 1);
            for bin in bins.iter_mut().take(last + 1).skip(first) {
                bin.push((ti as u32, si as u32));
            }
        }
    }
    bins
}

/// Mutable views of rows `y0..y0 + rows` of every framebuffer buffer.
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

    /// Whether every per-pixel buffer is present ([`Buffers::All`](super::framebuffer::Buffers::All)).
    pub(super) fn has_aovs(&self) -> bool {
        self.weights_screen.len() == self.color.len()
    }

    /// Clears every buffer of the band: colour to `background`, depth to 1 (the far plane).
    pub(super) fn clear(&mut self, background: [u8; 4]) {
        self.color.fill(background);
        self.depth.fill(1.0);
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
