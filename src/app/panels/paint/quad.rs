//! Paints the 2x2 quad's uv labels ([`QuadLabels`]) with egui: measured with egui's
//! galleys and placed as one block by the figures' own function
//! ([`place_quad_block`](crate::figure::label_place::place_quad_block)), with its leader.

use egui::{FontId, Pos2, Rect};

use super::{CanvasTransform, color, draw_label, stroke, to_box, to_point, to_rect};
use crate::figure::label_place;
use crate::figure::overlay::QuadLabels;
use crate::figure::text::{self as figure_text, Box2, LABEL_PAD};

/// Paints the quad's labels `labels` clear of the labels `placed` so far and of
/// `keep_clear`, inside `clip`; returns the labels' boxes.
pub(super) fn quad_labels(
    painter: &egui::Painter,
    labels: &QuadLabels,
    t: CanvasTransform,
    clip: Rect,
    placed: &[Box2],
    keep_clear: &[Box2],
) -> Vec<Box2> {
    let QuadLabels {
        texts,
        size,
        gaps,
        leader,
        background,
        ..
    } = labels;
    let lay = |s: f32| {
        texts.each_ref().map(|x| {
            x.as_ref()
                .map(|(x, c)| painter.layout_no_wrap(x.clone(), FontId::proportional(s), color(*c)))
        })
    };
    // A block wider than its view shrinks to fit it.
    let widths = lay(*size).map(|g| g.map(|g| g.size().x));
    let size = size * label_place::block_fit(widths, LABEL_PAD[0], gaps[0], to_box(clip));
    let sizes_at = |scale: f32| {
        lay(size * scale)
            .map(|g| g.map(|g| figure_text::padded([g.size().x, g.size().y], true, 1.0)))
    };
    let quad = label_place::quad_box(
        to_point(t, labels.min),
        to_point(t, labels.max),
        labels.outline,
    );
    let (q, scale) = label_place::place_quad_block_fitting(
        quad,
        sizes_at,
        gaps[0],
        gaps[1],
        labels.above,
        to_box(clip),
        placed,
        keep_clear,
    );
    let galleys = lay(size * scale);
    if let Some([a, b]) = q.leader {
        painter.line_segment(
            [Pos2::new(a[0], a[1]), Pos2::new(b[0], b[1])],
            stroke(*leader),
        );
    }
    let mut boxes = Vec::new();
    for ((b, g), x) in q.boxes.into_iter().zip(galleys).zip(texts) {
        if let (Some(b), Some(g), Some((_, c))) = (b, g, x) {
            draw_label(painter, to_rect(b), g, *c, Some(*background));
            boxes.push(b);
        }
    }
    boxes
}
