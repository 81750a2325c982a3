//! The overlay's colours and sizes: vertex colours, marker colours, label colours, text
//! sizes and the title strip, in display points.

/// sRGB colour with straight (unmultiplied) alpha.
pub type Rgba = [u8; 4];

/// Colours of the vertex letters A, B, C, D, ... used everywhere (handles, weights, sub-areas).
pub const VERTEX_COLORS: [Rgba; 6] = [
    [255, 80, 80, 255],
    [70, 210, 90, 255],
    [80, 150, 255, 255],
    [255, 200, 40, 255],
    [230, 110, 255, 255],
    [60, 220, 220, 255],
];

/// Colour of a point the clipper made (it is no mesh vertex).
pub const CLIP_POINT: Rgba = [200, 200, 200, 255];
/// Colour of negative numbers and of "outside" markings.
pub const NEGATIVE: Rgba = [255, 90, 90, 255];
/// Colour of the hovered pixel's marker.
pub const HOVER: Rgba = [255, 255, 255, 255];
/// Colour of the pinned pixel's marker.
pub const PIN: Rgba = [255, 150, 30, 255];
/// Dark outline behind light marks, so they read on any texture.
pub const SHADOW: Rgba = [0, 0, 0, 200];
/// Pixel grid lines.
pub const GRID: Rgba = [0, 0, 0, 110];
/// Pixel-centre sample dots.
pub const SAMPLE_DOT: Rgba = [255, 255, 255, 170];
/// Label backgrounds.
pub const LABEL_BG: Rgba = [20, 22, 28, 215];
/// Label text.
pub const LABEL_TEXT: Rgba = [240, 240, 240, 255];

/// Alpha of a sub-triangle's fill (positive area; negative areas use half of it).
pub(super) const SUB_AREA_ALPHA: u8 = 90;
/// Points: radius of a vertex handle.
pub const HANDLE_RADIUS: f32 = 11.0;
/// Points: the text size of labels (a handle's w, the note on vertices behind the camera).
pub const TEXT_LABEL: f32 = 20.0;
/// Points: the mode titles' text size.
pub const TEXT_BADGE: f32 = 24.0;
/// Points: the handles' letters and the colour bar's text size.
pub const TEXT_SMALL: f32 = 16.0;

/// Points: titles (the mode, the heatmap's meaning) sit this far above the image, in the
/// strip of [`TITLE_STRIP`] points the canvas keeps free there.
pub const TITLE_GAP: f32 = 6.0;
/// Points: the strip above the image kept for titles.
pub const TITLE_STRIP: f32 = 44.0;

/// Points between the wipe line's two mode labels.
pub const WIPE_LABEL_GAP: f32 = 20.0;

/// Pixel size (display pixels per rendered pixel) from which the grid shows.
pub const GRID_FROM_PIXEL_SIZE: u32 = 6;
/// Pixel size (display pixels per rendered pixel) from which the sample dots show.
pub const DOTS_FROM_PIXEL_SIZE: u32 = 10;

/// The colour of mesh vertex `index`.
pub fn vertex_color(index: usize) -> Rgba {
    VERTEX_COLORS[index % VERTEX_COLORS.len()]
}
