//! The overlay's shapes as plain data ([`Shape`], [`Overlay`]), in canvas coordinates with
//! sizes in points, and [`Overlay::scaled`].

use glam::DVec2;

use super::Rgba;

/// A line style.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stroke {
    /// Points.
    pub width: f32,
    /// Colour.
    pub color: Rgba,
}

impl Stroke {
    /// A stroke `width` points wide in `color`.
    pub const fn new(width: f32, color: Rgba) -> Self {
        Self { width, color }
    }
}

/// Which point of a text box sits at its position.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchor {
    /// The top-left corner.
    LeftTop,
    /// The bottom-left corner.
    LeftBottom,
    /// The bottom-right corner.
    RightBottom,
    /// The middle of the left side.
    LeftCenter,
    /// The middle of the top.
    CenterTop,
    /// The middle of the bottom.
    CenterBottom,
    /// The centre.
    Center,
    /// The top-right corner.
    RightTop,
    /// The middle of the right side.
    RightCenter,
}

/// One thing drawn over the image.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// A closed polygon.
    Polygon {
        /// Corners in canvas coordinates.
        points: Vec<DVec2>,
        /// Fill colour (alpha 0: none).
        fill: Rgba,
        /// Outline, if any.
        stroke: Option<Stroke>,
        /// Dashed outline ([`DASH`](crate::figure::svg::DASH)).
        dashed: bool,
    },
    /// An open polyline.
    Line {
        /// Points in canvas coordinates.
        points: Vec<DVec2>,
        /// Line style.
        stroke: Stroke,
        /// Dashed ([`DASH`](crate::figure::svg::DASH)).
        dashed: bool,
    },
    /// An axis-aligned rectangle in canvas coordinates.
    Rect {
        /// Top-left corner.
        min: DVec2,
        /// Bottom-right corner.
        max: DVec2,
        /// Fill colour (alpha 0: none).
        fill: Rgba,
        /// Outline, drawn outside the rectangle, if any.
        stroke: Option<Stroke>,
    },
    /// A circle of a fixed on-screen radius.
    Circle {
        /// Centre in canvas coordinates.
        centre: DVec2,
        /// Radius in points.
        radius: f32,
        /// Fill colour.
        fill: Rgba,
        /// Outline, if any.
        stroke: Option<Stroke>,
    },
    /// Text at a canvas position, moved by `offset` points.
    Text {
        /// The point the label belongs to, in canvas coordinates.
        at: DVec2,
        /// Points from `at` to the anchor point.
        offset: [f32; 2],
        /// Which point of the label's box sits there.
        anchor: Anchor,
        /// The text.
        text: String,
        /// Text size in points.
        size: f32,
        /// Text colour.
        color: Rgba,
        /// Box colour; a label with a box keeps clear of the others.
        background: Option<Rgba>,
    },
    /// A vertex handle's label, placed beside its own handle (centre `at`, radius `reach`
    /// points) by [`place_handle_label`](crate::figure::label_place::place_handle_label):
    /// first on the diagonal `outward`, never nearer another handle (every other
    /// `HandleLabel`'s `at`) than its own.
    HandleLabel {
        /// The handle's centre in canvas coordinates.
        at: DVec2,
        /// Points: the handle's radius.
        reach: f32,
        /// The preferred diagonal: signs of x and y (-1: left / up).
        outward: [f32; 2],
        /// The text.
        text: String,
        /// Text size in points.
        size: f32,
        /// Text colour.
        color: Rgba,
        /// Box colour.
        background: Rgba,
    },
    /// The 2x2 quad's four uv labels as one block laid out as the pixels are, placed by
    /// [`place_quad_block`](crate::figure::label_place::place_quad_block) (a leader line to
    /// the quad when the block ends up far from it).
    QuadLabels(QuadLabels),
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
        /// Image width in pixels.
        width: u32,
        /// Image height in pixels.
        height: u32,
        /// Grid line style.
        line: Stroke,
        /// Radius in points and colour of the pixel-centre dots, if shown.
        dots: Option<(f32, Rgba)>,
    },
    /// A vertical colour bar at canvas position `at` moved by `offset` points, `size` points
    /// large, from `colors[0]` at the bottom to the last colour at the top, with labels.
    ColorBar {
        /// Canvas position the bar is placed from.
        at: DVec2,
        /// Points from `at` to the bar's top-left corner.
        offset: [f32; 2],
        /// Width and height in points.
        size: [f32; 2],
        /// Colours from the bottom to the top.
        colors: Vec<Rgba>,
        /// Labels at fractions of the height (0 at the bottom).
        labels: Vec<(f32, String)>,
        /// The title above the bar.
        title: String,
    },
}

/// The 2x2 quad's four uv labels as one block laid out as the pixels are ([`Shape::QuadLabels`]).
#[derive(Clone, Debug, PartialEq)]
pub struct QuadLabels {
    /// The quad's top-left corner in canvas coordinates.
    pub min: DVec2,
    /// The quad's bottom-right corner in canvas coordinates.
    pub max: DVec2,
    /// Label `i + 2 j` (pixel `(x0 + i, y0 + j)`): its text and colour.
    pub texts: [Option<(String, Rgba)>; 4],
    /// Text size in points.
    pub size: f32,
    /// Points: between the labels, and between the block and the quad's outline.
    pub gaps: [f32; 2],
    /// Points the quad's outline reaches outside the quad.
    pub outline: f32,
    /// Prefer the block above the quad (else below it).
    pub above: bool,
    /// Box colour.
    pub background: Rgba,
    /// The leader line's style.
    pub leader: Stroke,
}

impl QuadLabels {
    /// Its marks `k` times their size: the text, the gaps, the outline's reach and the
    /// leader's width (the quad stays where it is).
    pub fn scale(&mut self, k: f32) {
        self.size *= k;
        self.gaps = self.gaps.map(|g| g * k);
        self.outline *= k;
        self.leader.width *= k;
    }
}

/// Everything drawn over one view of the canvas.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Overlay {
    /// The shapes, in painting order.
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
                Shape::HandleLabel {
                    at,
                    reach,
                    outward,
                    text,
                    size,
                    color,
                    background,
                } => Shape::HandleLabel {
                    at,
                    reach: reach * k,
                    outward,
                    text,
                    size: size * k,
                    color,
                    background,
                },
                Shape::QuadLabels(mut q) => {
                    q.scale(k);
                    Shape::QuadLabels(q)
                }
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
