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

use crate::i18n::{Lang, tr};
use crate::raster::Interpolation;

mod inputs;
mod magnifier;
mod marks;
mod shape;
mod style;

pub use inputs::{ClipMark, HandleMark, OverlayInput, PixelMark, QuadMark, TriangleMark};
pub use magnifier::{
    MAGNIFIER_RADIUS, MAGNIFIER_RADIUS_SAMPLES, SAMPLE_MARK_RADIUS, SampleMark, magnified_rect,
    magnifier, magnifier_radius, sample_color,
};
pub use marks::{
    SCIENTIFIC_W, behind_camera_note, format_w, handle_position, is_triangle_outline, span_shapes,
    span_step_shapes,
};
use marks::{behind_note, clip_shapes, handle_shapes, pixel_marker, quad_shapes, triangle_shapes};
pub use shape::{Anchor, Overlay, QuadLabels, Shape, Stroke};
pub use style::*;

/// Vertex names, shared with the derivation: A, B, C, ..., Z, then V26, ...
pub use crate::scene::vertex_name;

/// User-facing strings of the overlay, in English: the same as the catalogues' `figure.*`
/// entries, which [`build_in`] uses for other languages (`tests/i18n.rs` checks that the
/// English entries and these agree, through [`mode_label`] and [`build`]).
mod text {
    pub const AFFINE: &str = "AFFINE (screen-space)";
    pub const PERSPECTIVE: &str = "PERSPECTIVE-CORRECT";
    pub const DIFFERENCE: &str = "|uv affine − uv perspective| in texels";
    pub const BEHIND: &str = "behind the camera";
}

/// The mode's badge text.
pub fn mode_label(mode: Interpolation) -> &'static str {
    match mode {
        Interpolation::Affine => text::AFFINE,
        Interpolation::Perspective => text::PERSPECTIVE,
    }
}

/// The mode's badge text in `lang`.
pub fn mode_label_in(mode: Interpolation, lang: Lang) -> String {
    match (lang, mode) {
        (Lang::En, _) => mode_label(mode).to_string(),
        (_, Interpolation::Affine) => tr(lang, "figure.affine"),
        (_, Interpolation::Perspective) => tr(lang, "figure.perspective"),
    }
}

/// The short form of a mode's badge text (`text`, as [`mode_label_in`] words it in `lang`):
/// "AFFINE", "PERSPECTIVE"; `None` for any other title. A view too narrow for the whole
/// title shows this, at the size of its neighbour's title, rather than the whole one shrunk.
pub fn short_mode_label(text: &str, lang: Lang) -> Option<String> {
    [
        (Interpolation::Affine, "figure.affine_short"),
        (Interpolation::Perspective, "figure.perspective_short"),
    ]
    .into_iter()
    .find(|(mode, _)| mode_label_in(*mode, lang) == text)
    .map(|(_, key)| tr(lang, key))
}

/// [`short_mode_label`] of `text` in whichever language words it (a rendered figure knows
/// its titles, not their language).
pub fn short_title(text: &str) -> Option<String> {
    [Lang::En, Lang::Zh]
        .into_iter()
        .find_map(|lang| short_mode_label(text, lang))
}

/// Whether `shape` is a view's title: a boxed text above the image's top-left corner.
pub fn is_title(shape: &Shape) -> bool {
    matches!(shape, Shape::Text { at, offset, background: Some(_), .. }
        if *at == DVec2::ZERO && *offset == [0.0, -TITLE_GAP])
}

/// The overlay's other words in `lang`: the difference view's title, the colour bar's unit,
/// "behind the camera".
fn words(lang: Lang) -> [String; 3] {
    match lang {
        Lang::En => [text::DIFFERENCE, "texels", text::BEHIND].map(str::to_string),
        _ => ["figure.difference", "figure.texels", "figure.behind"].map(|k| tr(lang, k)),
    }
}

pub(super) fn with_alpha(c: Rgba, a: u8) -> Rgba {
    [c[0], c[1], c[2], a]
}

pub(super) fn centre_of(pixel: [u32; 2]) -> DVec2 {
    DVec2::new(f64::from(pixel[0]) + 0.5, f64::from(pixel[1]) + 0.5)
}

/// Builds the overlay of one view, with English labels.
pub fn build(input: &OverlayInput) -> Overlay {
    build_in(input, Lang::En)
}

/// Builds the overlay of one view with its labels in `lang` (the caller makes sure a font
/// with the language's glyphs is there: see [`crate::i18n::cjk_font`]).
pub fn build_in(input: &OverlayInput, lang: Lang) -> Overlay {
    let [difference, texels, behind] = words(lang);
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
        shapes.push(Shape::LabelPair {
            at: DVec2::new(x, 0.0),
            offset_y: -TITLE_GAP,
            gap: WIPE_LABEL_GAP,
            texts: [mode_label_in(left, lang), mode_label_in(right, lang)],
            size: TEXT_BADGE,
            color: LABEL_TEXT,
            background: Some(LABEL_BG),
        });
    } else if let Some(mode) = input.mode {
        shapes.push(Shape::Text {
            at: DVec2::ZERO,
            offset: [0.0, -TITLE_GAP],
            anchor: Anchor::LeftBottom,
            text: mode_label_in(mode, lang),
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
            text: difference,
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
            offset: [COLOR_BAR_GAP, COLOR_BAR_TOP],
            size: [
                26.0,
                color_bar_height(
                    hf * f64::from(input.pixel_size) / f64::from(input.pixels_per_point.max(0.1)),
                ),
            ],
            colors,
            labels,
            title: texels,
        });
    }

    // One set of triangle marks at a time: the pinned pixel's, else the hovered one's.
    if let Some(mark) = input.pin.or(input.hover)
        && let Some(t) = mark.triangle
    {
        let sub_areas = input.sub_areas.then_some(input.sub_area_fill);
        triangle_shapes(&mut shapes, &t, centre_of(mark.pixel), sub_areas);
    }
    if let Some(c) = &input.clipped {
        clip_shapes(&mut shapes, c, wf, hf);
    }
    // The quad's labels go last: placed clear of the handles and their labels.
    let mut quad_labels = None;
    if let Some(pin) = input.pin {
        if let Some(q) = pin.quad {
            quad_labels = Some(quad_shapes(&mut shapes, &q, DVec2::new(wf, hf), lang));
        }
        pixel_marker(&mut shapes, pin.pixel, PIN, wf, hf, false);
    }
    if let Some(hover) = input.hover {
        pixel_marker(&mut shapes, hover.pixel, HOVER, wf, hf, true);
    }

    let size = DVec2::new(wf, hf);
    let on_screen: Vec<DVec2> = input
        .handles
        .iter()
        .filter_map(|h| h.window)
        .map(|w| marks::handle_position(w, size))
        .collect();
    let centre = if on_screen.is_empty() {
        DVec2::new(wf / 2.0, hf / 2.0)
    } else {
        on_screen.iter().sum::<DVec2>() / on_screen.len() as f64
    };
    for handle in &input.handles {
        handle_shapes(&mut shapes, handle, centre, size);
    }
    if let Some(note) = behind_note(&input.handles, &behind) {
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
    shapes.extend(quad_labels);
    Overlay { shapes }
}

/// Points: the colour bar's top lies this far below the image's top.
const COLOR_BAR_TOP: f32 = 60.0;
/// Points between the image's right edge and the colour bar: the bar sits outside the image,
/// in the room the canvas keeps there ([`COLOR_BAR_ROOM`]).
const COLOR_BAR_GAP: f32 = 12.0;
/// Points the canvas (and a figure) keeps right of a difference image for its colour bar and
/// the bar's labels.
pub const COLOR_BAR_ROOM: f32 = 96.0;
/// Points: the colour bar's largest height, and the room kept below it (its background and
/// a margin).
const COLOR_BAR_HEIGHT: f32 = 260.0;
const COLOR_BAR_BELOW: f32 = 40.0;

/// The colour bar's height in points for an image `view_height` points high: at most 260
/// (`COLOR_BAR_HEIGHT`), less on a small image so it stays inside (at least 60). (The app
/// asks again with the height the image is shown at, which is smaller than its pixels
/// where the canvas shrinks it.)
pub fn color_bar_height(view_height: f64) -> f32 {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The short titles are shorter forms of the mode's own title, in each language; other
    /// titles (the difference view's, a sample buffer's) have none.
    #[test]
    fn a_modes_short_title_is_a_shorter_form_of_its_title() {
        for lang in [Lang::En, Lang::Zh] {
            for mode in [Interpolation::Affine, Interpolation::Perspective] {
                let long = mode_label_in(mode, lang);
                let short = short_mode_label(&long, lang).expect("a short form");
                assert!(
                    short.chars().count() < long.chars().count(),
                    "{short} / {long}"
                );
                let stem: String = short.chars().take(2).collect();
                assert!(long.starts_with(&stem), "{short} / {long}");
            }
            assert_eq!(short_mode_label(&words(lang)[0], lang), None);
        }
        assert_eq!(
            short_mode_label(&mode_label_in(Interpolation::Affine, Lang::Zh), Lang::En),
            None
        );
    }

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
            clipped: None,
            sub_areas: true,
            sub_area_fill: true,
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
                Shape::Text { text, .. } | Shape::HandleLabel { text, .. } => Some(text.as_str()),
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
            quad: None,
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
