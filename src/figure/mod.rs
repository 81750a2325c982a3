//! Figures for lecture notes: the canvas as the app shows it (one view, side by side, wipe or
//! difference heatmap) with its overlays, re-rendered by the CPU rasterizer at 1x, 2x or 4x,
//! as SVG (raster embedded, overlays as vector shapes and real text) or PNG. No egui here: the
//! app's Export and `barylab figure` both call [`Figure::compose`] and [`export`].
//!
//! - [`Compare`] and the views it needs (`compare.rs`); [`FigureOptions`], the background and
//!   the layout sizes (`options.rs`); the marks taken from the scene and the probe (`marks.rs`);
//!   [`Figure::compose`], which renders and lays out the views (`compose.rs`).
//! - [`overlay`]: the single plain-data description of everything drawn over the image (the
//!   app paints it with egui, [`svg`] writes it as SVG).
//! - [`text`]: the overlay font, text measurement and label placement (shared with the app).
//! - [`svg`], [`png`]: the figure as an SVG document, and that document rasterized by resvg.
//! - [`texture_view`], [`lod_view`]: the pinned pixel's lookup in texture space (texels,
//!   taps and weights, footprint, anisotropic probes) and every pixel's mipmap level.
//! - [`sample_buffers`]: what each sample buffer of a multisampled render holds (coverage
//!   count, a sample's colour and depth, the resolve; the black-edge bug).
//! - [`plot`]: a line plot (the handout's row plot) as SVG and PNG, without egui.
//! - [`caption`]: the optional caption with the marked pixel's key numbers.
//! - [`space`]: the space view, the scene in 3D with the pixel's ray (`barylab figure --view
//!   space`).
//! - [`heatmap`]: the difference view's colours.
//! - [`export`]: writing a figure's files (PNG, SVG, derivation, scene) under fresh names.
//!
//! Sizes: a figure is laid out in points; at scale 1 one point is one PNG pixel. A view shows
//! the `W x H` rendered image with `pixel_size` points per rendered pixel, as on screen at
//! that pixel size. At scale `s` the PNG has `s` pixels per point: with pixel size 1 the scene
//! is rendered again at `sW x sH` (sharper, same picture); with a larger pixel size the
//! rendered pixels are the subject, so they stay the scene's pixels, drawn as
//! `s * pixel_size` square PNG pixels each.

pub mod bounds;
pub mod caption;
mod compare;
mod compose;
pub mod export;
pub mod heatmap;
pub mod label_place;
pub mod lod_view;
mod marks;
mod options;
pub mod overlay;
pub mod plot;
pub mod png;
pub mod raster_svg;
pub mod sample_buffers;
pub mod space;
pub mod svg;
pub mod text;
pub mod texture_view;

pub use compare::{Compare, ViewContent, modes_for, view_contents, wipe_column, wipe_pixels};
pub use compose::{Figure, FigureError, FigureView};
pub use marks::{
    FLAT_W_TOLERANCE, MIN_HANDLE_W, VertexOnScreen, clip_mark, common_w, pixel_mark, triangle_mark,
    vertices_on_screen,
};
pub use options::{
    Background, FIGURE_MARGIN, FigureOptions, MAX_FIGURE_SIZE, OVERLAY_SCALE_RANGE, SCALES,
    SIDE_BY_SIDE_GAP, image_background, layout_points,
};
pub use texture_view::TexelView;
