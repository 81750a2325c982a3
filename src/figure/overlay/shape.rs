//! The overlay's shapes as plain data ([`Shape`], [`Overlay`]), in canvas coordinates with
//! sizes in points, and [`Overlay::scaled`].

use glam::DVec2;

use super::Rgba;

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
    /// Two labels side by side (the wipe line's modes): `texts[0]` left of canvas x `at.x`,
    /// `texts[1]` right of it, `gap` points apart, their bottoms `offset_y` points below
    /// `at.y`. Placed with [`place_pair`](crate::figure::text::place_pair): they never overlap,
    /// move together to stay inside the view's clip, and shrink together when they do not
    /// fit side by side at `size`.
    LabelPair {
        /// Canvas position of the point between the labels.
        at: DVec2,
        /// Points from `at.y` to the labels' bottom edge (negative: above).
        offset_y: f32,
        /// Points between the two boxes.
        gap: f32,
        /// The left and the right label.
        texts: [String; 2],
        /// Text size in points.
        size: f32,
        /// Text colour.
        color: Rgba,
        /// Box colour.
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
                Shape::LabelPair {
                    at,
                    offset_y,
                    gap,
                    texts,
                    size,
                    color,
                    background,
                } => Shape::LabelPair {
                    at,
                    offset_y: offset_y * k,
                    gap: gap * k,
                    texts,
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
