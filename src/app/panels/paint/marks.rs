//! What presentation mode changes in an overlay before it is painted: its marks scaled up,
//! the views' titles left out or renamed.

use crate::figure::overlay::{Overlay, Shape, Stroke};

/// Draws the overlay's marks `k` times their usual size: handles, markers and lines (their
/// radii and stroke widths) and labels (their text and offsets). Positions stay where they
/// are; the pixel grid and the colour bar keep their sizes. Presentation mode uses it so the
/// back of the room sees the corners, their labels and the pinned pixel.
pub fn scale_marks(overlay: &mut Overlay, k: f32) {
    if (k - 1.0).abs() < f32::EPSILON {
        return;
    }
    let widen = |s: &mut Stroke| s.width *= k;
    for shape in &mut overlay.shapes {
        let title = is_title(shape);
        match shape {
            Shape::Polygon { stroke, .. } | Shape::Rect { stroke, .. } => {
                stroke.as_mut().map(widen);
            }
            Shape::Line { stroke, .. } => widen(stroke),
            Shape::Circle { radius, stroke, .. } => {
                *radius *= k;
                stroke.as_mut().map(widen);
            }
            // A title keeps its size: it lives in the title strip above the image.
            Shape::Text { offset, size, .. } if !title => {
                *size *= k;
                *offset = offset.map(|o| o * k);
            }
            Shape::Text { .. } => {}
            Shape::HandleLabel { reach, size, .. } => {
                *reach *= k;
                *size *= k;
            }
            Shape::QuadLabels(q) => q.scale(k),
            Shape::LabelPair {
                offset_y,
                gap,
                size,
                ..
            } => {
                *size *= k;
                *offset_y *= k;
                *gap *= k;
            }
            Shape::PixelGrid { .. } | Shape::ColorBar { .. } => {}
        }
    }
}

/// Leaves out the views' titles (presentation mode's single view, whose card names the mode).
pub fn drop_titles(overlay: &mut Overlay) {
    overlay.shapes.retain(|s| !is_title(s));
}

/// Replaces the view's title text with `title`.
pub fn retitle(overlay: &mut Overlay, title: &str) {
    for shape in &mut overlay.shapes {
        if is_title(shape)
            && let Shape::Text { text, .. } = shape
        {
            *text = title.to_string();
        }
    }
}

/// The view's title text, if it has one.
pub fn title(overlay: &Overlay) -> Option<&str> {
    overlay.shapes.iter().find_map(|s| match s {
        Shape::Text { text, .. } if is_title(s) => Some(text.as_str()),
        _ => None,
    })
}

/// Whether `shape` is a view's title: a boxed text above the image's top-left corner.
pub(super) fn is_title(shape: &Shape) -> bool {
    crate::figure::overlay::is_title(shape)
}
