//! The labels of the 3D view: their size as drawn ([`Measure`], [`svg_measure`],
//! [`text_width`]) and [`spread_labels`], which moves a label off the ones placed before it
//! and draws a leader back to its point when it moved far.

use super::shape::{Anchor2, Colour, Shape, ShapeKind};

/// A label's width and row height in points, given its text and text size, as a renderer
/// draws it.
pub type Measure<'a> = &'a dyn Fn(&str, f32) -> [f32; 2];

/// A label's size in the SVG figures: [`text_width`] wide, its row from 0.8 of the text size
/// above the baseline to a quarter below.
pub fn svg_measure(text: &str, size: f32) -> [f32; 2] {
    [text_width(text, size), 1.05 * size]
}

/// Moves labels that would overlap an earlier one: below it, above it, then to the other
/// side of its anchor point, then further up or down (up to [`SPREAD_STEPS`] lines), each kept
/// inside `rect`; the first position that overlaps nothing placed (nor comes nearer one side by
/// side than [`LABEL_GAP`]) wins, else the one that overlaps the placed labels least (a crowded
/// corner of a small view stays readable).
/// `measure` gives a label's width and row height as drawn: a label covers from a quarter size
/// below its baseline up by its row, and moves by lines a twentieth of a size taller.
pub(super) fn spread_labels(shapes: &mut Vec<Shape>, rect: [f32; 4], measure: Measure<'_>) {
    let mut placed: Vec<[f32; 4]> = Vec::new();
    let mut leaders = Vec::new();
    for s in shapes.iter_mut() {
        let depth = s.depth;
        let ShapeKind::Text {
            at,
            text,
            size,
            anchor,
            colour,
        } = &mut s.kind
        else {
            continue;
        };
        let [w, row] = measure(text, *size);
        let bounds = |at: [f32; 2], anchor: Anchor2| {
            let x0 = match anchor {
                Anchor2::Start => at[0],
                Anchor2::Middle => at[0] - w / 2.0,
                Anchor2::End => at[0] - w,
            };
            let bottom = at[1] + 0.25 * *size;
            [x0, bottom - row, x0 + w, bottom]
        };
        // The position moved as little as needed to lie inside `rect`.
        let inside = |mut pos: [f32; 2], anchor: Anchor2| {
            let b = bounds(pos, anchor);
            let pad = 2.0;
            pos[0] += (rect[0] + pad - b[0]).max(0.0) - (b[2] - rect[2] + pad).max(0.0);
            pos[1] += (rect[1] + pad - b[1]).max(0.0) - (b[3] - rect[3] + pad).max(0.0);
            pos
        };
        let flipped = match anchor {
            Anchor2::Start => Anchor2::End,
            Anchor2::End => Anchor2::Start,
            Anchor2::Middle => Anchor2::Middle,
        };
        let h = row + 0.05 * *size;
        // Lines up and down in the order 0, +1, -1, +2, -2, ...; each with both anchors.
        let shifts = (0..=2 * SPREAD_STEPS).map(|i| {
            let n = i.div_ceil(2) as f32;
            if i % 2 == 1 { n * h } else { -n * h }
        });
        let mut best: Option<(f32, [f32; 2], Anchor2)> = None;
        'search: for dy in shifts {
            for a in [*anchor, flipped] {
                let pos = inside([at[0], at[1] + dy], a);
                let [x0, y0, x1, y1] = bounds(pos, a);
                let gap = LABEL_GAP * *size;
                let padded = [x0 - gap, y0, x1 + gap, y1];
                let cost = crate::figure::text::overlap_area(padded, &placed);
                if best.is_none_or(|(c, _, _)| cost < c) {
                    best = Some((cost, pos, a));
                }
                if cost == 0.0 {
                    break 'search;
                }
            }
        }
        let (_, pos, anc) = best.unwrap_or((0.0, inside(*at, *anchor), *anchor));
        let home = bounds(*at, *anchor);
        let moved = bounds(pos, anc);
        // A label moved clear away from its place: a thin line leads back.
        if crate::figure::label_place::box_distance(home, moved) > LEADER_AFTER * h {
            let centre = |b: [f32; 4]| [(b[0] + b[2]) / 2.0, (b[1] + b[3]) / 2.0];
            let target = centre(home);
            let from = nearest_on_box(moved, target);
            let [r, g, b, _] = colour.0;
            leaders.push(Shape {
                kind: ShapeKind::Line {
                    from,
                    to: target,
                    colour: Colour([r, g, b, 150]),
                    width: 1.0,
                    dashed: true,
                },
                depth,
            });
        }
        *at = pos;
        *anchor = anc;
        placed.push(moved);
    }
    // Under the labels, so that a line crossing another label does not strike it through.
    let first_text = shapes
        .iter()
        .position(|s| matches!(s.kind, ShapeKind::Text { .. }))
        .unwrap_or(shapes.len());
    shapes.splice(first_text..first_text, leaders);
}

/// The gap, in lines, between where [`spread_labels`] put a label and where it belonged over
/// which it draws a line back: a label moved two lines (a gap of about one) no longer reads as
/// its point's; one moved a line, or to the other side of its point, still touches its place.
const LEADER_AFTER: f32 = 0.5;

/// The point of the box `b` nearest to `p`.
fn nearest_on_box(b: [f32; 4], p: [f32; 2]) -> [f32; 2] {
    [p[0].clamp(b[0], b[2]), p[1].clamp(b[1], b[3])]
}

/// How many lines up or down [`spread_labels`] moves a label looking for a free place.
const SPREAD_STEPS: usize = 4;
/// The space [`spread_labels`] keeps between labels side by side, in text sizes: labels that
/// touched read as one ("z/w=0view depth").
const LABEL_GAP: f32 = 0.3;

/// The width of `s` at `size` points: the overlay font's for most characters, one em for
/// CJK ideographs and punctuation (which the overlay font lacks).
pub fn text_width(s: &str, size: f32) -> f32 {
    let (cjk, rest): (String, String) = s.chars().partition(|c| *c >= '\u{2E80}');
    crate::figure::text::measure(&rest, size).0[0] + size * cjk.chars().count() as f32
}
