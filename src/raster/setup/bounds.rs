//! Pixel bounds of a set-up triangle: the pixels whose centres it can cover
//! ([`setup_bounds`]), the pixels whose samples anywhere in the pixel it can cover under
//! multisampling ([`sample_pixel_bounds`]), and the early test of a tiny triangle's few
//! centres ([`covers_no_sample`]), all from the snapped positions (1/256 pixel).

use glam::I64Vec2;

use super::{TieRule, edges_of, sample_point, signed_area2};
use crate::raster::project::{SUBPIXEL, Viewport};

/// Inclusive pixel rectangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelBounds {
    /// First column, from the left.
    pub x0: u32,
    /// First row, from the top.
    pub y0: u32,
    /// Last column (included).
    pub x1: u32,
    /// Last row (included).
    pub y1: u32,
}

impl PixelBounds {
    /// No pixel (a placeholder before a triangle is set).
    pub const EMPTY: Self = Self {
        x0: 1,
        y0: 1,
        x1: 0,
        y1: 0,
    };
}

/// The pixel bounds [`setup_triangle_with`](super::setup_triangle_with) gives a triangle with these snapped (`fixed`,
/// 1/256 pixel) positions, and `None` exactly when it gives `None`: what the fast path keeps
/// of a triangle before it draws it. (The weight planes never refuse a triangle whose snapped
/// area is not zero: their fallback, the snapped positions, has that area, at least
/// 1/65536 pixel^2, so they are not needed here.)
#[inline]
pub fn setup_bounds(fixed: [I64Vec2; 3], viewport: Viewport) -> Option<PixelBounds> {
    if signed_area2(fixed[0], fixed[1], fixed[2]) == 0 {
        return None;
    }
    pixel_bounds(&fixed, viewport)
}

/// Pixels a triangle's bounds may hold for [`covers_no_sample`] to test them one by one.
pub const TINY_TRIANGLE_PIXELS: u32 = 4;

/// Whether a triangle with these snapped positions and (non-empty) pixel bounds covers no
/// pixel centre in rows `rows` (inclusive), by its exact edge functions under `rule`: the
/// test [`setup_triangle_with`](super::setup_triangle_with)'s set-up triangle would make at each of those pixels, done
/// before the set-up. `None` when more than [`TINY_TRIANGLE_PIXELS`] pixels would need
/// testing. A dense model drawn small has many triangles between pixel centres; they need
/// no set-up at all.
///
/// ```
/// use barylab::raster::setup::{covers_no_sample, PixelBounds, TieRule};
/// use glam::I64Vec2;
/// // A sliver between the centres of pixels (0, 0) and (1, 0) (x from 130 to 250 of 256).
/// let p = [I64Vec2::new(130, 0), I64Vec2::new(250, 0), I64Vec2::new(190, 250)];
/// let b = PixelBounds { x0: 0, y0: 0, x1: 0, y1: 0 };
/// assert_eq!(covers_no_sample(p, b, (0, 0), TieRule::default()), Some(true));
/// // Moved left by 40/256 pixel it covers the centre (128, 128) of pixel (0, 0).
/// let q = p.map(|v| v - I64Vec2::new(40, 0));
/// assert_eq!(covers_no_sample(q, b, (0, 0), TieRule::default()), Some(false));
/// ```
pub fn covers_no_sample(
    p: [I64Vec2; 3],
    b: PixelBounds,
    (first, last): (u32, u32),
    rule: TieRule,
) -> Option<bool> {
    let (y0, y1) = (b.y0.max(first), b.y1.min(last));
    if y0 > y1 {
        return Some(true);
    }
    let pixels = u64::from(b.x1 - b.x0 + 1) * u64::from(y1 - y0 + 1);
    if pixels > u64::from(TINY_TRIANGLE_PIXELS) {
        return None;
    }
    let edges = edges_of(p, signed_area2(p[0], p[1], p[2]) > 0, rule);
    for y in y0..=y1 {
        for x in b.x0..=b.x1 {
            let s = sample_point(x, y);
            if edges.iter().all(|e| e.passes(e.value(s))) {
                return Some(false);
            }
        }
    }
    Some(true)
}

/// Pixels whose centres can lie inside the triangle: centre `256 c + 128` within
/// `[min, max]` of the vertices, clamped to the viewport.
pub(super) fn pixel_bounds(p: &[I64Vec2; 3], viewport: Viewport) -> Option<PixelBounds> {
    let min = p[0].min(p[1]).min(p[2]);
    let max = p[0].max(p[1]).max(p[2]);
    let half = SUBPIXEL / 2;
    // Smallest c with 256c + 128 >= min, largest c with 256c + 128 <= max.
    let lo = |m: i64| (m - half + SUBPIXEL - 1).div_euclid(SUBPIXEL);
    let hi = |m: i64| (m - half).div_euclid(SUBPIXEL);
    let x0 = lo(min.x).max(0);
    let y0 = lo(min.y).max(0);
    let x1 = hi(max.x).min(i64::from(viewport.width) - 1);
    let y1 = hi(max.y).min(i64::from(viewport.height) - 1);
    if x0 > x1 || y0 > y1 {
        return None;
    }
    Some(PixelBounds {
        x0: x0 as u32,
        y0: y0 as u32,
        x1: x1 as u32,
        y1: y1 as u32,
    })
}

/// The pixels whose samples (anywhere in the pixel, its edges included) a triangle with
/// these snapped positions can cover: their bounding box widened by a pixel up and left,
/// `[floor(min / 256) - 1, floor(max / 256)]`, within the viewport.
pub fn sample_pixel_bounds(p: &[I64Vec2; 3], viewport: Viewport) -> Option<PixelBounds> {
    let (min, max) = (p[0].min(p[1]).min(p[2]), p[0].max(p[1]).max(p[2]));
    let lo = |m: i64| (m.div_euclid(SUBPIXEL) - 1).max(0);
    let x1 = max
        .x
        .div_euclid(SUBPIXEL)
        .min(i64::from(viewport.width) - 1);
    let y1 = max
        .y
        .div_euclid(SUBPIXEL)
        .min(i64::from(viewport.height) - 1);
    let (x0, y0) = (lo(min.x), lo(min.y));
    (x0 <= x1 && y0 <= y1).then_some(PixelBounds {
        x0: x0 as u32,
        y0: y0 as u32,
        x1: x1 as u32,
        y1: y1 as u32,
    })
}
