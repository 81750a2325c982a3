//! Perspective divide and viewport transform: clip -> NDC -> window coordinates.
//!
//! Window coordinates here are image coordinates: x to the right from the left edge, y down
//! from the top row (NDC y = +1 is image row 0), in pixels; depth z in [0, 1]. Each vertex
//! keeps two positions, as llvmpipe does: the float position, from which the interpolation
//! weights are set up (so interpolated values equal the exact answer), and the position
//! snapped to 1/256 pixel, the sub-pixel precision that decides coverage.

use glam::{DVec2, DVec3, DVec4, I64Vec2};

use super::clip::ClipVertex;
use super::varying::Varyings;

/// Sub-pixel bits of snapped window positions.
pub const SUBPIXEL_BITS: u32 = 8;
/// Sub-pixel steps per pixel (256).
pub const SUBPIXEL: i64 = 1 << SUBPIXEL_BITS;

/// Largest accepted image width or height in pixels.
pub const MAX_IMAGE_SIZE: u32 = 16384;

/// Largest |window coordinate| in pixels that the guard band lets through: 2^20 pixels, i.e.
/// 2^28 sub-pixel units, so edge-function products stay below 2^58 in an `i64`.
pub const GUARD_BAND_PIXELS: f64 = (1u64 << 20) as f64;

/// The viewport (0, 0, width, height) with depth range [0, 1].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Viewport {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
}

impl Viewport {
    /// Guard band half-size in NDC units: the NDC |x|, |y| at which window coordinates reach
    /// `GUARD_BAND_PIXELS` from the viewport's far side.
    pub fn guard_band_ndc(&self) -> f64 {
        let size = f64::from(self.width.max(self.height));
        2.0 * GUARD_BAND_PIXELS / size - 1.0
    }

    /// `width / height`.
    pub fn aspect(&self) -> f64 {
        f64::from(self.width) / f64::from(self.height)
    }
}

/// A vertex after the perspective divide and viewport transform.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WindowVertex {
    /// The clip-space position it came from.
    pub clip: DVec4,
    /// Normalized device coordinates (x/w, y/w, z/w).
    pub ndc: DVec3,
    /// Snapped window position in 1/256-pixel units: decides coverage.
    pub fixed: I64Vec2,
    /// Window position in pixels before snapping: the interpolation weights come from it.
    pub window: DVec2,
    /// Window depth `z_ndc / 2 + 1/2`, in [0, 1].
    pub depth: f64,
    /// 1 / w_clip, kept for perspective-correct interpolation.
    pub inv_w: f64,
    /// The attributes for `smooth` (perspective-correct) interpolation.
    pub varyings: Varyings,
    /// The attributes for `noperspective` (affine) interpolation (see [`ClipVertex`]).
    pub noperspective: Varyings,
}

/// Perspective divide: NDC = (x/w, y/w, z/w).
///
/// ```
/// use barylab::raster::project::ndc_from_clip;
/// use glam::{DVec3, DVec4};
/// assert_eq!(ndc_from_clip(DVec4::new(1.0, -2.0, 3.0, 4.0)), DVec3::new(0.25, -0.5, 0.75));
/// ```
pub fn ndc_from_clip(clip: DVec4) -> DVec3 {
    clip.truncate() / clip.w
}

/// Viewport transform to image-space window coordinates:
/// `x = (x_ndc + 1) W / 2`, `y = (1 - y_ndc) H / 2`, `z = (z_ndc + 1) / 2`.
///
/// ```
/// use barylab::raster::project::{window_from_ndc, Viewport};
/// use glam::DVec3;
/// let vp = Viewport { width: 8, height: 4 };
/// // The top-left corner of NDC is image (0, 0); the centre is (4, 2); near plane depth 0.
/// assert_eq!(window_from_ndc(DVec3::new(-1.0, 1.0, -1.0), vp), DVec3::new(0.0, 0.0, 0.0));
/// assert_eq!(window_from_ndc(DVec3::new(0.0, 0.0, 1.0), vp), DVec3::new(4.0, 2.0, 1.0));
/// ```
pub fn window_from_ndc(ndc: DVec3, viewport: Viewport) -> DVec3 {
    DVec3::new(
        (ndc.x + 1.0) * f64::from(viewport.width) / 2.0,
        (1.0 - ndc.y) * f64::from(viewport.height) / 2.0,
        window_depth(ndc.z),
    )
}

/// Window depth of an NDC depth (the depth range [0, 1]): `d = (z_ndc + 1) / 2`.
///
/// ```
/// use barylab::raster::project::window_depth;
/// assert_eq!(window_depth(-1.0), 0.0);
/// assert_eq!(window_depth(0.5), 0.75);
/// ```
pub fn window_depth(z_ndc: f64) -> f64 {
    (z_ndc + 1.0) / 2.0
}

/// NDC (x, y) of a window position, the inverse of [`window_from_ndc`]:
/// `x_ndc = 2 x / W - 1`, `y_ndc = 1 - 2 y / H`.
///
/// ```
/// use barylab::raster::project::{ndc_from_window, Viewport};
/// use glam::DVec2;
/// let n = ndc_from_window(DVec2::new(4.5, 6.5), Viewport { width: 8, height: 8 });
/// assert_eq!(n, DVec2::new(0.125, -0.625));
/// let vp = Viewport { width: 8, height: 4 };
/// assert_eq!(ndc_from_window(DVec2::new(4.0, 0.0), vp), DVec2::new(0.0, 1.0));
/// ```
pub fn ndc_from_window(window: DVec2, viewport: Viewport) -> DVec2 {
    DVec2::new(
        2.0 * window.x / f64::from(viewport.width) - 1.0,
        1.0 - 2.0 * window.y / f64::from(viewport.height),
    )
}

/// Snaps a window position to the 1/256-pixel grid: `round(256 x)`.
///
/// ```
/// use barylab::raster::project::snap;
/// use glam::{DVec2, I64Vec2};
/// assert_eq!(snap(DVec2::new(1.5, 0.001)), I64Vec2::new(384, 0));
/// assert_eq!(snap(DVec2::new(0.5 / 256.0 + 1e-9, -0.75)), I64Vec2::new(1, -192));
/// ```
pub fn snap(window: DVec2) -> I64Vec2 {
    let s = SUBPIXEL as f64;
    I64Vec2::new((window.x * s).round() as i64, (window.y * s).round() as i64)
}

impl WindowVertex {
    /// The snapped window position in pixels: `fixed / 256`.
    pub fn window_snapped(&self) -> DVec2 {
        self.fixed.as_dvec2() / SUBPIXEL as f64
    }
}

/// Divides, maps to the viewport and snaps one clipped vertex.
pub fn project_vertex(v: &ClipVertex, viewport: Viewport) -> WindowVertex {
    let ndc = ndc_from_clip(v.clip);
    let win = window_from_ndc(ndc, viewport);
    let fixed = snap(win.truncate());
    WindowVertex {
        clip: v.clip,
        ndc,
        fixed,
        window: win.truncate(),
        depth: win.z,
        inv_w: 1.0 / v.clip.w,
        varyings: v.varyings,
        noperspective: v.noperspective,
    }
}
