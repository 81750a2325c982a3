//! What an overlay is built from: the handles, the marked pixels with their triangles, and
//! the view's settings ([`OverlayInput`]).

use glam::DVec2;

use crate::raster::Interpolation;

/// A vertex handle as the overlay shows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HandleMark {
    /// The mesh vertex's index (its name and colour).
    pub index: usize,
    /// Window position, or `None` when the vertex is behind the camera.
    pub window: Option<DVec2>,
    /// The vertex's clip w, shown in its label.
    pub w: f64,
    /// Hovered or dragged: drawn larger.
    pub active: bool,
}

/// The three vertices (unsnapped window positions, in triangle order) and mesh indices of the
/// triangle a marked pixel's weights refer to, with the weights. A vertex the clipper made has
/// no mesh index.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleMark {
    /// Unsnapped window positions of the three corners, in triangle order.
    pub vertices: [DVec2; 3],
    /// Each corner's mesh vertex (`None` for a point the clipper made).
    pub mesh_indices: [Option<usize>; 3],
    /// Screen-space weights of the three vertices at the pixel centre.
    pub weights: [f64; 3],
}

/// A marked (hovered or pinned) pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelMark {
    /// The pixel (column, row).
    pub pixel: [u32; 2],
    /// The triangle its weights refer to, if any.
    pub triangle: Option<TriangleMark>,
    /// The 2x2 quad its texture derivatives come from (trilinear and anisotropic filtering).
    pub quad: Option<QuadMark>,
}

/// The 2x2 pixel quad a pixel's texture derivatives are differences in, with each pixel's uv.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadMark {
    /// Its top-left pixel `(x0, y0)`; the others are `(x0 + 1, y0)`, `(x0, y0 + 1)`,
    /// `(x0 + 1, y0 + 1)`, the order of [`QuadMark::uvs`] and [`QuadMark::inside`].
    pub origin: [u32; 2],
    /// Each pixel's uv (extrapolated from the triangle's plane outside it; `None` where the
    /// plane gives none).
    pub uvs: [Option<[f32; 2]>; 4],
    /// Whether the triangle covers each pixel's centre (else a helper pixel).
    pub inside: [bool; 4],
}

/// The polygon the clipper left of a marked pixel's triangle: its corners in order, with
/// their names (a source letter, or K1, K2, ... for a point the clipper made) and unsnapped
/// window positions, and the fan triangle the pixel lies in.
#[derive(Clone, Debug, PartialEq)]
pub struct ClipMark {
    /// The corners: name, window position, whether the clipper made it.
    pub corners: Vec<(String, DVec2, bool)>,
    /// Polygon indices of the fan triangle the pixel's weights refer to.
    pub fan: [usize; 3],
}

/// What the overlay of one view shows.
#[derive(Clone, Debug, PartialEq)]
pub struct OverlayInput {
    /// Rendered image size in pixels.
    pub size: [u32; 2],
    /// Display pixels per rendered pixel.
    pub pixel_size: u32,
    /// Display pixels per point (sizes in points are this many display pixels).
    pub pixels_per_point: f32,
    /// The mode this view shows (`None` for the difference view).
    pub mode: Option<Interpolation>,
    /// Draw the pixel grid (from [`GRID_FROM_PIXEL_SIZE`](super::GRID_FROM_PIXEL_SIZE)).
    pub show_grid: bool,
    /// The vertex handles.
    pub handles: Vec<HandleMark>,
    /// The hovered pixel (marker with crosshair).
    pub hover: Option<PixelMark>,
    /// The pinned pixel (marker, triangle, sub-triangles).
    pub pin: Option<PixelMark>,
    /// The clipped polygon of the marked pixel's triangle (the pinned one's, else the
    /// hovered one's), when the clipper cut it.
    pub clipped: Option<ClipMark>,
    /// Draw the marked pixel's sub-triangles.
    pub sub_areas: bool,
    /// Fill the sub-triangles (tinted); off, they are outlines only, so a texture under them
    /// keeps its colours.
    pub sub_area_fill: bool,
    /// Wipe line x in canvas pixels, with the modes left and right of it.
    pub wipe: Option<(f64, Interpolation, Interpolation)>,
    /// Colour bar top value in texels (difference view).
    pub color_bar: Option<f32>,
}
