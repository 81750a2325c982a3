//! What is drawn over the rendered image, as plain data: shapes and text in canvas
//! coordinates. The app's canvas paints it with egui; the figure export writes the same list
//! as SVG (and rasterizes that SVG for PNG).
//!
//! Coordinates: canvas coordinates are the rasterizer's window coordinates of the rendered
//! image, in its pixels (x right, y down, pixel (c, r) covers [c, c+1] x [r, r+1], its sample at
//! (c + 1/2, r + 1/2)). Line widths, radii, text sizes and offsets are in display points, so
//! labels keep their size whatever the pixel size. Titles lie above the image (negative y
//! offsets), in a strip [`TITLE_STRIP`] points high.

use glam::DVec2;

use crate::raster::Interpolation;
/// Vertex names, shared with the derivation: A, B, C, ..., Z, then V26, ...
pub use crate::scene::vertex_name;

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
const SUB_AREA_ALPHA: u8 = 90;
/// Points: radius of a vertex handle.
pub const HANDLE_RADIUS: f32 = 11.0;
/// Points: text sizes.
pub const TEXT_LABEL: f32 = 20.0;
pub const TEXT_BADGE: f32 = 24.0;
pub const TEXT_SMALL: f32 = 16.0;

/// Points: titles (the mode, the heatmap's meaning) sit this far above the image, in the
/// strip of [`TITLE_STRIP`] points the canvas keeps free there.
pub const TITLE_GAP: f32 = 6.0;
pub const TITLE_STRIP: f32 = 44.0;

/// Pixel sizes (display pixels per rendered pixel) from which the grid and sample dots show.
pub const GRID_FROM_PIXEL_SIZE: u32 = 6;
pub const DOTS_FROM_PIXEL_SIZE: u32 = 10;

/// User-facing strings of the overlay.
mod text {
    pub const AFFINE: &str = "AFFINE (screen-space)";
    pub const PERSPECTIVE: &str = "PERSPECTIVE-CORRECT";
    pub const DIFFERENCE: &str = "|uv affine − uv perspective| in texels";
    pub const BEHIND: &str = "behind the camera";
}

/// The colour of mesh vertex `index`.
pub fn vertex_color(index: usize) -> Rgba {
    VERTEX_COLORS[index % VERTEX_COLORS.len()]
}

/// A line style.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stroke {
    /// Points.
    pub width: f32,
    pub color: Rgba,
}

impl Stroke {
    pub const fn new(width: f32, color: Rgba) -> Self {
        Self { width, color }
    }
}

/// Which point of a text box sits at its position.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchor {
    LeftTop,
    LeftBottom,
    RightBottom,
    LeftCenter,
    CenterTop,
    CenterBottom,
    Center,
    RightTop,
    RightCenter,
}

/// One thing drawn over the image.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// A closed polygon.
    Polygon {
        points: Vec<DVec2>,
        fill: Rgba,
        stroke: Option<Stroke>,
        dashed: bool,
    },
    /// An open polyline.
    Line {
        points: Vec<DVec2>,
        stroke: Stroke,
        dashed: bool,
    },
    /// An axis-aligned rectangle in canvas coordinates.
    Rect {
        min: DVec2,
        max: DVec2,
        fill: Rgba,
        stroke: Option<Stroke>,
    },
    /// A circle of a fixed on-screen radius.
    Circle {
        centre: DVec2,
        radius: f32,
        fill: Rgba,
        stroke: Option<Stroke>,
    },
    /// Text at a canvas position, moved by `offset` points.
    Text {
        at: DVec2,
        offset: [f32; 2],
        anchor: Anchor,
        text: String,
        size: f32,
        color: Rgba,
        background: Option<Rgba>,
    },
    /// The pixel grid of a `width` x `height` image, and optionally a dot at every pixel centre.
    PixelGrid {
        width: u32,
        height: u32,
        line: Stroke,
        dots: Option<(f32, Rgba)>,
    },
    /// A vertical colour bar at canvas position `at` moved by `offset` points, `size` points
    /// large, from `colors[0]` at the bottom to the last colour at the top, with labels.
    ColorBar {
        at: DVec2,
        offset: [f32; 2],
        size: [f32; 2],
        colors: Vec<Rgba>,
        labels: Vec<(f32, String)>,
        title: String,
    },
}

/// Everything drawn over one view of the canvas.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Overlay {
    pub shapes: Vec<Shape>,
}

impl Overlay {
    /// The overlay with every size in points (line widths, radii, text sizes, offsets, the
    /// colour bar) multiplied by `k`; positions on the canvas stay.
    pub fn scaled(&self, k: f32) -> Overlay {
        let st = |s: Stroke| Stroke::new(s.width * k, s.color);
        let shapes = self
            .shapes
            .iter()
            .cloned()
            .map(|shape| match shape {
                Shape::Polygon {
                    points,
                    fill,
                    stroke,
                    dashed,
                } => Shape::Polygon {
                    points,
                    fill,
                    stroke: stroke.map(st),
                    dashed,
                },
                Shape::Line {
                    points,
                    stroke,
                    dashed,
                } => Shape::Line {
                    points,
                    stroke: st(stroke),
                    dashed,
                },
                Shape::Rect {
                    min,
                    max,
                    fill,
                    stroke,
                } => Shape::Rect {
                    min,
                    max,
                    fill,
                    stroke: stroke.map(st),
                },
                Shape::Circle {
                    centre,
                    radius,
                    fill,
                    stroke,
                } => Shape::Circle {
                    centre,
                    radius: radius * k,
                    fill,
                    stroke: stroke.map(st),
                },
                Shape::Text {
                    at,
                    offset,
                    anchor,
                    text,
                    size,
                    color,
                    background,
                } => Shape::Text {
                    at,
                    offset: offset.map(|v| v * k),
                    anchor,
                    text,
                    size: size * k,
                    color,
                    background,
                },
                Shape::PixelGrid {
                    width,
                    height,
                    line,
                    dots,
                } => Shape::PixelGrid {
                    width,
                    height,
                    line: st(line),
                    dots: dots.map(|(r, c)| (r * k, c)),
                },
                Shape::ColorBar {
                    at,
                    offset,
                    size,
                    colors,
                    labels,
                    title,
                } => Shape::ColorBar {
                    at,
                    offset: offset.map(|v| v * k),
                    size: size.map(|v| v * k),
                    colors,
                    labels,
                    title,
                },
            })
            .collect();
        Overlay { shapes }
    }
}

/// A vertex handle as the overlay shows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HandleMark {
    pub index: usize,
    /// Window position, or `None` when the vertex is behind the camera.
    pub window: Option<DVec2>,
    pub w: f64,
    pub active: bool,
}

/// The three vertices (unsnapped window positions, in triangle order) and mesh indices of the
/// triangle a marked pixel's weights refer to, with the weights. A vertex the clipper made has
/// no mesh index.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleMark {
    pub vertices: [DVec2; 3],
    pub mesh_indices: [Option<usize>; 3],
    /// Screen-space weights of the three vertices at the pixel centre.
    pub weights: [f64; 3],
}

/// A marked (hovered or pinned) pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelMark {
    pub pixel: [u32; 2],
    pub triangle: Option<TriangleMark>,
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
    pub show_grid: bool,
    pub handles: Vec<HandleMark>,
    pub hover: Option<PixelMark>,
    pub pin: Option<PixelMark>,
    /// Draw the hovered pixel's sub-triangles.
    pub sub_areas: bool,
    /// Wipe line x in canvas pixels, with the modes left and right of it.
    pub wipe: Option<(f64, Interpolation, Interpolation)>,
    /// Colour bar top value in texels (difference view).
    pub color_bar: Option<f32>,
}

/// The mode's badge text.
pub fn mode_label(mode: Interpolation) -> &'static str {
    match mode {
        Interpolation::Affine => text::AFFINE,
        Interpolation::Perspective => text::PERSPECTIVE,
    }
}

fn with_alpha(c: Rgba, a: u8) -> Rgba {
    [c[0], c[1], c[2], a]
}

fn centre_of(pixel: [u32; 2]) -> DVec2 {
    DVec2::new(f64::from(pixel[0]) + 0.5, f64::from(pixel[1]) + 0.5)
}

/// Builds the overlay of one view.
pub fn build(input: &OverlayInput) -> Overlay {
    let mut shapes = Vec::new();
    let [w, h] = input.size;
    let (wf, hf) = (f64::from(w), f64::from(h));

    if input.show_grid && input.pixel_size >= GRID_FROM_PIXEL_SIZE {
        shapes.push(Shape::PixelGrid {
            width: w,
            height: h,
            line: Stroke::new(1.0, GRID),
            dots: (input.pixel_size >= DOTS_FROM_PIXEL_SIZE)
                .then_some(((input.pixel_size as f32 / 10.0).clamp(1.5, 3.0), SAMPLE_DOT)),
        });
    }

    if let Some((x, left, right)) = input.wipe {
        let line = vec![DVec2::new(x, 0.0), DVec2::new(x, hf)];
        shapes.push(Shape::Line {
            points: line.clone(),
            stroke: Stroke::new(5.0, SHADOW),
            dashed: false,
        });
        shapes.push(Shape::Line {
            points: line,
            stroke: Stroke::new(2.5, [255, 255, 255, 255]),
            dashed: false,
        });
        shapes.push(Shape::Circle {
            centre: DVec2::new(x, hf / 2.0),
            radius: 12.0,
            fill: [255, 255, 255, 255],
            stroke: Some(Stroke::new(2.0, SHADOW)),
        });
        for (mode, anchor, dx) in [
            (left, Anchor::RightBottom, -10.0),
            (right, Anchor::LeftBottom, 10.0),
        ] {
            shapes.push(Shape::Text {
                at: DVec2::new(x, 0.0),
                offset: [dx, -TITLE_GAP],
                anchor,
                text: mode_label(mode).to_string(),
                size: TEXT_BADGE,
                color: LABEL_TEXT,
                background: Some(LABEL_BG),
            });
        }
    } else if let Some(mode) = input.mode {
        shapes.push(Shape::Text {
            at: DVec2::ZERO,
            offset: [0.0, -TITLE_GAP],
            anchor: Anchor::LeftBottom,
            text: mode_label(mode).to_string(),
            size: TEXT_BADGE,
            color: LABEL_TEXT,
            background: Some(LABEL_BG),
        });
    }

    if let Some(top) = input.color_bar {
        shapes.push(Shape::Text {
            at: DVec2::ZERO,
            offset: [0.0, -TITLE_GAP],
            anchor: Anchor::LeftBottom,
            text: text::DIFFERENCE.to_string(),
            size: TEXT_BADGE,
            color: LABEL_TEXT,
            background: Some(LABEL_BG),
        });
        let colors = (0..=32)
            .map(|i| super::heatmap::heat_color(i as f32 / 32.0 * top, top))
            .collect();
        let labels = [0.0, 0.5, 1.0]
            .iter()
            .map(|&t| (t, format_scale(t * top)))
            .collect();
        shapes.push(Shape::ColorBar {
            at: DVec2::new(wf, 0.0),
            offset: [-90.0, COLOR_BAR_TOP],
            size: [
                26.0,
                color_bar_height(
                    hf * f64::from(input.pixel_size) / f64::from(input.pixels_per_point.max(0.1)),
                ),
            ],
            colors,
            labels,
            title: "texels".to_string(),
        });
    }

    for mark in [input.pin, input.hover].into_iter().flatten() {
        if let Some(t) = mark.triangle {
            triangle_shapes(&mut shapes, &t, centre_of(mark.pixel), input.sub_areas);
        }
    }
    if let Some(pin) = input.pin {
        pixel_marker(&mut shapes, pin.pixel, PIN, wf, hf, false);
    }
    if let Some(hover) = input.hover {
        pixel_marker(&mut shapes, hover.pixel, HOVER, wf, hf, true);
    }

    let on_screen: Vec<DVec2> = input.handles.iter().filter_map(|h| h.window).collect();
    let centre = if on_screen.is_empty() {
        DVec2::new(wf / 2.0, hf / 2.0)
    } else {
        on_screen.iter().sum::<DVec2>() / on_screen.len() as f64
    };
    for handle in &input.handles {
        handle_shapes(&mut shapes, handle, centre);
    }
    if let Some(note) = behind_camera_note(&input.handles) {
        shapes.push(Shape::Text {
            at: DVec2::new(0.0, hf),
            offset: [10.0, -10.0],
            anchor: Anchor::LeftBottom,
            text: note,
            size: TEXT_LABEL,
            color: NEGATIVE,
            background: Some(LABEL_BG),
        });
    }
    Overlay { shapes }
}

/// Points: the colour bar's top lies this far below the image's top.
const COLOR_BAR_TOP: f32 = 60.0;
/// Points: the colour bar's largest height, and the room kept below it (its background and
/// a margin).
const COLOR_BAR_HEIGHT: f32 = 260.0;
const COLOR_BAR_BELOW: f32 = 40.0;

/// The colour bar's height in points for an image `view_height` points high: at most
/// [`COLOR_BAR_HEIGHT`], less on a small image so it stays inside (at least 60).
fn color_bar_height(view_height: f64) -> f32 {
    (view_height as f32 - COLOR_BAR_TOP - COLOR_BAR_BELOW).clamp(60.0, COLOR_BAR_HEIGHT)
}

fn format_scale(v: f32) -> String {
    if v >= 10.0 || v == 0.0 {
        format!("{v:.0}")
    } else if v >= 1.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.2}")
    }
}

/// The triangle outline and, if asked, the three sub-triangles P V_{i+1} V_{i+2}, each in
/// the colour of the vertex V_i whose weight its signed area is (dashed when negative).
fn triangle_shapes(shapes: &mut Vec<Shape>, t: &TriangleMark, p: DVec2, sub_areas: bool) {
    if sub_areas {
        for i in 0..3 {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            let color = t.mesh_indices[i].map_or(CLIP_POINT, vertex_color);
            let negative = t.weights[i] < 0.0;
            shapes.push(Shape::Polygon {
                points: vec![p, t.vertices[j], t.vertices[k]],
                fill: with_alpha(
                    color,
                    if negative {
                        SUB_AREA_ALPHA / 2
                    } else {
                        SUB_AREA_ALPHA
                    },
                ),
                stroke: Some(Stroke::new(
                    if negative { 2.5 } else { 1.5 },
                    if negative { NEGATIVE } else { color },
                )),
                dashed: negative,
            });
        }
    }
    shapes.push(Shape::Polygon {
        points: t.vertices.to_vec(),
        fill: [0, 0, 0, 0],
        stroke: Some(Stroke::new(3.0, [255, 255, 255, 230])),
        dashed: false,
    });
}

/// A square around the pixel and a crosshair through its centre.
fn pixel_marker(
    shapes: &mut Vec<Shape>,
    pixel: [u32; 2],
    color: Rgba,
    w: f64,
    h: f64,
    cross: bool,
) {
    let (x, y) = (f64::from(pixel[0]), f64::from(pixel[1]));
    let c = centre_of(pixel);
    if cross {
        for points in [
            vec![DVec2::new(0.0, c.y), DVec2::new(x, c.y)],
            vec![DVec2::new(x + 1.0, c.y), DVec2::new(w, c.y)],
            vec![DVec2::new(c.x, 0.0), DVec2::new(c.x, y)],
            vec![DVec2::new(c.x, y + 1.0), DVec2::new(c.x, h)],
        ] {
            shapes.push(Shape::Line {
                points,
                stroke: Stroke::new(1.0, with_alpha(color, 150)),
                dashed: true,
            });
        }
    }
    for (width, col) in [(4.0, SHADOW), (2.0, color)] {
        shapes.push(Shape::Rect {
            min: DVec2::new(x, y),
            max: DVec2::new(x + 1.0, y + 1.0),
            fill: [0, 0, 0, 0],
            stroke: Some(Stroke::new(width, col)),
        });
    }
    shapes.push(Shape::Circle {
        centre: c,
        radius: 2.5,
        fill: color,
        stroke: Some(Stroke::new(1.0, SHADOW)),
    });
}

/// A handle and its label; the label goes on the side away from `centre` (the handles'
/// centroid), so labels of neighbouring corners do not cover each other.
fn handle_shapes(shapes: &mut Vec<Shape>, h: &HandleMark, centre: DVec2) {
    let color = vertex_color(h.index);
    let name = vertex_name(h.index);
    let Some(p) = h.window else {
        return;
    };
    shapes.push(Shape::Circle {
        centre: p,
        radius: if h.active {
            HANDLE_RADIUS + 3.0
        } else {
            HANDLE_RADIUS
        },
        fill: with_alpha(color, 200),
        stroke: Some(Stroke::new(
            if h.active { 3.5 } else { 2.5 },
            [255, 255, 255, 255],
        )),
    });
    shapes.push(Shape::Text {
        at: p,
        offset: [0.0, 0.0],
        anchor: Anchor::Center,
        text: name.clone(),
        size: TEXT_SMALL,
        color: [0, 0, 0, 255],
        background: None,
    });
    // Diagonally outward from the centroid: neighbouring corners' labels go different ways.
    let (left, up) = (p.x < centre.x, p.y < centre.y);
    let d = HANDLE_RADIUS * 0.75;
    shapes.push(Shape::Text {
        at: p,
        offset: [if left { -d } else { d }, if up { -d } else { d }],
        anchor: match (left, up) {
            (true, true) => Anchor::RightBottom,
            (true, false) => Anchor::RightTop,
            (false, true) => Anchor::LeftBottom,
            (false, false) => Anchor::LeftTop,
        },
        text: format!("{name}  w = {}", format_w(h.w)),
        size: TEXT_LABEL,
        color,
        background: Some(LABEL_BG),
    });
}

/// Magnitude of w from which labels use scientific notation: up to it, a label is at most
/// six digits.
pub const SCIENTIFIC_W: f64 = 1e6;

/// A w value for labels: three significant digits; scientific notation from
/// [`SCIENTIFIC_W`] on (a vertex near the eye plane has a w like 3.5e38).
pub fn format_w(w: f64) -> String {
    if w.abs() >= SCIENTIFIC_W {
        format!("{w:.2e}")
    } else if w.abs() >= 100.0 {
        format!("{w:.0}")
    } else if w.abs() >= 10.0 {
        format!("{w:.1}")
    } else {
        format!("{w:.2}")
    }
}

/// Labels for vertices behind the camera, listed in a corner of the view.
pub fn behind_camera_note(handles: &[HandleMark]) -> Option<String> {
    let names: Vec<String> = handles
        .iter()
        .filter(|h| h.window.is_none())
        .map(|h| format!("{} (w = {})", vertex_name(h.index), format_w(h.w)))
        .collect();
    (!names.is_empty()).then(|| format!("{}: {}", text::BEHIND, names.join(", ")))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input() -> OverlayInput {
        OverlayInput {
            size: [100, 80],
            pixel_size: 1,
            pixels_per_point: 1.0,
            mode: Some(Interpolation::Perspective),
            show_grid: true,
            handles: vec![HandleMark {
                index: 0,
                window: Some(DVec2::new(10.0, 10.0)),
                w: 2.5,
                active: false,
            }],
            hover: None,
            pin: None,
            sub_areas: true,
            wipe: None,
            color_bar: None,
        }
    }

    #[test]
    fn the_mode_badge_and_handle_labels_are_there() {
        let o = build(&input());
        let texts: Vec<&str> = o
            .shapes
            .iter()
            .filter_map(|s| match s {
                Shape::Text { text, .. } => Some(text.as_str()),
                _ => None,
            })
            .collect();
        assert!(texts.contains(&"PERSPECTIVE-CORRECT"));
        assert!(texts.contains(&"A  w = 2.50"));
        // No grid at pixel size 1.
        assert!(
            !o.shapes
                .iter()
                .any(|s| matches!(s, Shape::PixelGrid { .. }))
        );
    }

    #[test]
    fn a_vertex_behind_the_camera_has_no_handle_but_a_note_in_the_corner() {
        let mut i = input();
        i.handles.push(HandleMark {
            index: 1,
            window: None,
            w: -1.0,
            active: false,
        });
        let o = build(&i);
        let circles = o
            .shapes
            .iter()
            .filter(|s| matches!(s, Shape::Circle { .. }))
            .count();
        assert_eq!(circles, 1, "only A has a handle");
        let note = o.shapes.iter().find_map(|s| match s {
            Shape::Text {
                at, text, color, ..
            } if text.starts_with("behind") => Some((*at, text.clone(), *color)),
            _ => None,
        });
        assert_eq!(
            note,
            Some((
                DVec2::new(0.0, 80.0),
                "behind the camera: B (w = -1.00)".to_string(),
                NEGATIVE
            ))
        );
    }

    #[test]
    fn sub_triangles_are_coloured_by_the_opposite_vertex_and_dashed_when_negative() {
        let mut i = input();
        i.hover = Some(PixelMark {
            pixel: [5, 5],
            triangle: Some(TriangleMark {
                vertices: [DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(0.0, 4.0)],
                mesh_indices: [Some(0), Some(2), Some(3)],
                weights: [-1.75, 1.375, 1.375],
            }),
        });
        let o = build(&i);
        let polys: Vec<(Rgba, bool)> = o
            .shapes
            .iter()
            .filter_map(|s| match s {
                Shape::Polygon {
                    points,
                    fill,
                    dashed,
                    ..
                } if points.len() == 3 && fill[3] > 0 => Some((*fill, *dashed)),
                _ => None,
            })
            .collect();
        assert_eq!(polys.len(), 3);
        assert_eq!(
            polys[0],
            (with_alpha(vertex_color(0), SUB_AREA_ALPHA / 2), true)
        );
        assert_eq!(
            polys[1],
            (with_alpha(vertex_color(2), SUB_AREA_ALPHA), false)
        );
        assert_eq!(
            polys[2],
            (with_alpha(vertex_color(3), SUB_AREA_ALPHA), false)
        );
    }
}
