//! The space view's 2D shapes ([`Shape`], [`ShapeKind`]), their colours and the named colours
//! of its marks, shared by the drawing (`draw.rs`), its labels (`labels.rs`) and the figures.

/// A straight-alpha RGBA colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Colour(pub [u8; 4]);

/// Where a text's anchor point is along its width.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchor2 {
    /// The text starts at the point.
    Start,
    /// The text is centred on the point.
    Middle,
    /// The text ends at the point.
    End,
}

/// What a shape is.
#[derive(Clone, Debug, PartialEq)]
pub enum ShapeKind {
    /// A filled polygon, with an optional outline (colour, width).
    Polygon {
        /// Its corners.
        points: Vec<[f32; 2]>,
        /// The fill.
        fill: Colour,
        /// The outline.
        stroke: Option<(Colour, f32)>,
    },
    /// A line segment.
    Line {
        /// Start.
        from: [f32; 2],
        /// End.
        to: [f32; 2],
        /// Colour.
        colour: Colour,
        /// Width in points.
        width: f32,
        /// Drawn dashed (hidden or construction lines).
        dashed: bool,
    },
    /// A disc, with an optional outline.
    Dot {
        /// Centre.
        centre: [f32; 2],
        /// Radius in points.
        radius: f32,
        /// The fill (transparent for a ring).
        fill: Colour,
        /// The outline.
        stroke: Option<(Colour, f32)>,
    },
    /// One line of text; its baseline's anchor point at `at`.
    Text {
        /// The anchor point.
        at: [f32; 2],
        /// The text.
        text: String,
        /// Font size in points.
        size: f32,
        /// Colour.
        colour: Colour,
        /// Which point of the text `at` is.
        anchor: Anchor2,
    },
}

/// A shape and its distance from the orbit camera (for the painter's order).
#[derive(Clone, Debug, PartialEq)]
pub struct Shape {
    /// What to draw.
    pub kind: ShapeKind,
    /// Mean distance from the orbit camera; marks and labels come after every 3D shape.
    pub depth: f64,
}

/// P's mark: a filled disc of this colour (tests find it in the PNG by it).
pub const P_COLOUR: Colour = Colour([200, 0, 200, 255]);
/// Q's mark: a ring of this colour.
pub const Q_COLOUR: Colour = Colour([0, 140, 150, 255]);
/// The ray.
pub const RAY_COLOUR: Colour = Colour([215, 40, 30, 255]);
/// Text and outlines.
pub const INK: Colour = Colour([30, 30, 30, 255]);
