//! Presentation mode's card: the pinned (else hovered) pixel's key numbers, large and high
//! contrast, for the back of a lecture hall, with what is shown (the lesson step or the
//! preset). Every number is the probe trace's (the same trace the inspector shows); nothing is
//! computed here.
//!
//! The card goes beside the picture where the window has a column to spare (wide screens),
//! else over the picture, in the corner the scene leaves most empty (see
//! [`crate::app::layout`]). Its size follows from its width: the widest line must fit.

use egui::{Color32, RichText, Ui};

use crate::app::services::pixel::PixelReport;
use crate::figure::overlay::{CLIP_POINT, vertex_color};
use crate::probe::format::{fmt_column, fmt_digits};
use crate::raster::Interpolation;

/// What the card shows.
pub struct CardInput<'a> {
    /// The hovered pixel's report.
    pub hovered: Option<&'a PixelReport>,
    /// The pinned pixel's report (shown rather than the hovered one).
    pub pinned: Option<&'a PixelReport>,
    /// What is on the canvas: the lesson step, or the preset's name.
    pub context: Option<String>,
    /// Replaces the line of keys (a lesson's Page Down / Page Up step through it).
    pub keys_hint: Option<String>,
    /// Text size of the numbers, in points.
    pub size: f32,
    /// The narrow card of a column beside the picture ([`card_width_narrow`]): the lines
    /// broken where the full card has them side by side.
    pub narrow: bool,
    /// The canvas compares the two modes (side by side, wipe, difference): the card names
    /// no mode, unless every w is equal (then the two agree and it says so).
    pub compare: bool,
}

/// Characters (monospace) of the card's widest line: the weights table, `1/W_P = … W_P = …`
/// and `uv perspective (…, …)` (with a number of seven characters, such as 0.03510).
const CARD_EMS: f32 = 32.0;
/// Width of a monospace character, in text heights.
const MONO_ADVANCE: f32 = 0.62;
/// The smallest and largest text size of the card's numbers, in points.
pub const CARD_TEXT_RANGE: (f32, f32) = (10.0, 40.0);
/// Points the card's frame adds around its contents (its margins, both sides).
pub const PANEL_MARGINS: f32 = 24.0;
/// A row's height, in text heights.
const ROW: f32 = 1.3;
/// Rows of a card with a pixel: the pixel, the context, the mode, the table's header and
/// three rows, 1/W_P and W_P, depth, uv both ways.
const FULL_ROWS: f32 = 11.0;
/// Characters (monospace) of the narrow card's widest line: the weights table.
const NARROW_EMS: f32 = 25.5;
/// Rows of a narrow card with a pixel: the pixel, the mode, the table's header and three
/// rows, 1/W_P, W_P, depth, and uv both ways with its name on a line of its own.
const NARROW_ROWS: f32 = 13.0;
/// Rows of a card without a pixel: the context and the invitation to hover.
const COMPACT_ROWS: f32 = 2.0;
/// The context line's and the line of keys' size, as a share of the numbers' size.
const SMALL_SHARE: f32 = 0.7;
/// Characters of a number column.
const NUMBER_EMS: f32 = 7.5;
/// Characters of the vertex-name column.
const NAME_EMS: f32 = 2.5;
/// Significant digits on the card: enough to see the difference, few enough to read.
const DIGITS: i32 = 4;

/// The card's colours: white on near-black.
pub const CARD_FILL: Color32 = Color32::from_rgb(8, 10, 16);
/// The card's fill when it lies over the picture: the picture shows faintly through.
pub const CARD_FILL_OVER: Color32 = Color32::from_rgba_premultiplied(8, 10, 16, 236);
const INK: Color32 = Color32::WHITE;
pub const DIM: Color32 = Color32::from_rgb(170, 180, 200);
const ACCENT: Color32 = Color32::from_rgb(255, 214, 90);

/// The text size at which the card's widest line fills a card `width` points wide:
/// `(width - PANEL_MARGINS) / (CARD_EMS * MONO_ADVANCE)` within [`CARD_TEXT_RANGE`] (32
/// characters of 0.62 text heights: 20 points of text need 32 x 0.62 x 20 + 24 = 420.8 points
/// of card; the unit test below checks it both ways).
pub fn card_text_for_width(width: f32) -> f32 {
    ((width - PANEL_MARGINS) / (CARD_EMS * MONO_ADVANCE))
        .clamp(CARD_TEXT_RANGE.0, CARD_TEXT_RANGE.1)
}

/// The card's width for text `size` (the inverse of [`card_text_for_width`]).
pub fn card_width_for_text(size: f32) -> f32 {
    size * CARD_EMS * MONO_ADVANCE + PANEL_MARGINS
}

/// The width of a narrow card (a column beside the picture) at text `size`.
pub fn card_width_narrow(size: f32) -> f32 {
    size * NARROW_EMS * MONO_ADVANCE + PANEL_MARGINS
}

/// The height in points of a narrow card with a pixel at text `size`, with `key_lines` lines
/// of keys (two when V offers the 3D view).
pub fn card_height_narrow(size: f32, spacing: f32, key_lines: usize) -> f32 {
    let spacing = card_spacing(spacing, size);
    NARROW_ROWS * (ROW * size + spacing)
        + small_rows(key_lines) * (ROW * SMALL_SHARE * size + spacing)
        + PANEL_MARGINS
}

/// The small rows of a card: the context line and `key_lines` lines of keys (at least one).
fn small_rows(key_lines: usize) -> f32 {
    1.0 + key_lines.max(1) as f32
}

/// The card's height in points at text `size`, with a pixel to show (`full`) or without,
/// and `key_lines` lines of keys under it (two when V offers the 3D view). Used to place the
/// card before it is drawn; the card is never taller.
pub fn card_height(size: f32, full: bool, spacing: f32, key_lines: usize) -> f32 {
    let spacing = card_spacing(spacing, size);
    let rows = if full { FULL_ROWS } else { COMPACT_ROWS };
    rows * (ROW * size + spacing)
        + key_lines.max(1) as f32 * (ROW * SMALL_SHARE * size + spacing)
        + PANEL_MARGINS
}

/// The height in points of a wide card (two columns: the table beside the other lines) at
/// text `size`, with `key_lines` lines of keys.
pub fn card_height_wide(size: f32, spacing: f32, key_lines: usize) -> f32 {
    let spacing = card_spacing(spacing, size);
    WIDE_ROWS * (ROW * size + spacing)
        + small_rows(key_lines) * (ROW * SMALL_SHARE * size + spacing)
        + PANEL_MARGINS
}

/// The card's space between rows for the style's `spacing` and text `size`: at most a
/// seventh of the text (the rows' own height already leaves room).
fn card_spacing(spacing: f32, size: f32) -> f32 {
    spacing.min(0.15 * size)
}

/// Rows of a wide card: the pixel with the mode, the table's header and three rows.
const WIDE_ROWS: f32 = 5.0;

/// Text size of presentation mode's other large print (the lesson strip's title) for a
/// window `height` points high: 20 at 768, larger on a larger screen.
pub fn strip_text(height: f32) -> f32 {
    (height / 38.0).clamp(18.0, 34.0)
}

fn big(s: impl Into<String>, size: f32) -> RichText {
    RichText::new(s).monospace().size(size).color(INK)
}

fn num(x: f64) -> String {
    fmt_column(x, DIGITS)
}

fn pair(uv: [f32; 2]) -> String {
    format!(
        "({}, {})",
        fmt_column(f64::from(uv[0]), DIGITS),
        fmt_column(f64::from(uv[1]), DIGITS)
    )
}

/// The card: the context line, the pixel's numbers, the line of keys at its foot.
pub fn card_ui(ui: &mut Ui, input: &CardInput<'_>) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let size = input.size;
    let small = SMALL_SHARE * size;
    let hint = input
        .keys_hint
        .clone()
        .unwrap_or_else(|| lang.tr("app.present.leave"));
    ui.spacing_mut().item_spacing.y = card_spacing(ui.spacing().item_spacing.y, size);
    let focus = input
        .pinned
        .map(|r| (r, lang.tr("app.present.pinned")))
        .or(input.hovered.map(|r| (r, lang.tr("app.present.hovered"))));
    if let Some(c) = &input.context {
        ui.add(
            egui::Label::new(RichText::new(c).size(small).color(DIM))
                .wrap_mode(egui::TextWrapMode::Truncate),
        );
    }
    match &focus {
        Some((r, how)) => pixel_ui(ui, r, how, input, lang),
        None => {
            ui.add(
                egui::Label::new(big(lang.tr("app.present.no_pixel"), size).color(ACCENT)).wrap(),
            );
        }
    }
    // One line per key group (a narrow card would cut a long line short).
    for line in hint.lines() {
        ui.add(
            egui::Label::new(RichText::new(line).size(small).color(DIM))
                .wrap_mode(egui::TextWrapMode::Truncate),
        );
    }
}

/// The pixel's lines: which pixel and mode, the weights table (rows in the vertex colours),
/// 1/W_P and W_P, the depth, uv both ways.
fn pixel_ui(
    ui: &mut Ui,
    r: &PixelReport,
    how: &str,
    input: &CardInput<'_>,
    lang: crate::i18n::Lang,
) {
    let size = input.size;
    // Every w equal (a flat triangle facing the camera): both modes agree, and the card says
    // so instead of naming one. A comparison shows both modes: no name.
    let flat = r
        .trace
        .detail
        .as_ref()
        .and_then(|d| crate::figure::common_w(d.raster.vertices.iter().map(|v| 1.0 / v.inv_w)));
    let mode = match (flat, r.mode) {
        (Some(w), _) => Some(lang.tr_with("app.present.flat", &[("w", &fmt_digits(w, DIGITS))])),
        _ if input.compare => None,
        (None, Interpolation::Affine) => Some(lang.tr("app.present.affine")),
        (None, Interpolation::Perspective) => Some(lang.tr("app.present.perspective")),
    };
    // Two columns (the table, then the other lines) where the card is wide enough, else one.
    let wide = !input.narrow && ui.available_width() >= 2.0 * CARD_EMS * MONO_ADVANCE * size + size;
    let pixel = format!(
        "{} {}, {} ({how})",
        &lang.tr("app.present.pixel"),
        r.pixel[0],
        r.pixel[1]
    );
    let line = |ui: &mut Ui, text: String, strong: bool| {
        let t = big(text, size).color(ACCENT);
        ui.add(
            egui::Label::new(if strong { t.strong() } else { t })
                .wrap_mode(egui::TextWrapMode::Truncate),
        );
    };
    match mode {
        Some(m) if wide => line(ui, format!("{pixel} · {m}"), true),
        Some(m) => {
            line(ui, pixel, true);
            line(ui, m, false);
        }
        None => line(ui, pixel, true),
    }
    let Some(d) = &r.trace.detail else {
        ui.add(egui::Label::new(big(lang.tr("app.present.not_covered"), size)).wrap());
        return;
    };
    if wide {
        ui.horizontal_top(|ui| {
            ui.vertical(|ui| table_ui(ui, r, d, size, lang));
            ui.add_space(size);
            ui.vertical(|ui| lines_ui(ui, r, d, size, false, lang));
        });
    } else {
        table_ui(ui, r, d, size, lang);
        lines_ui(ui, r, d, size, input.narrow, lang);
    }
}

/// The weights table: a row per vertex in its colour, r s t, 1/W, a b c.
fn table_ui(
    ui: &mut Ui,
    r: &PixelReport,
    d: &crate::probe::TriangleTrace,
    size: f32,
    lang: crate::i18n::Lang,
) {
    let correction = d.perspective.map(|p| p.correction);
    let mesh_indices = r.mark().triangle.map(|t| t.mesh_indices);
    // A table of fixed-width cells (monospace numbers line up; no measured layout that could
    // change from frame to frame).
    let cell = |ui: &mut Ui, t: RichText, ems: f32| {
        ui.add_sized(
            [ems * size * MONO_ADVANCE, size * ROW],
            egui::Label::new(t).wrap_mode(egui::TextWrapMode::Extend),
        );
    };
    ui.horizontal(|ui| {
        ui.spacing_mut().item_spacing.x = 0.0;
        cell(ui, big("", size), NAME_EMS);
        for h in [
            &lang.tr("app.present.screen"),
            &lang.tr("app.present.inv_w"),
            &lang.tr("app.present.corrected"),
        ] {
            cell(ui, big(h.as_str(), size).color(DIM), NUMBER_EMS);
        }
    });
    for (k, v) in d.raster.vertices.iter().enumerate() {
        let rgba = match mesh_indices.and_then(|m| m[k]) {
            Some(i) => vertex_color(i),
            None => CLIP_POINT,
        };
        let c = Color32::from_rgb(rgba[0], rgba[1], rgba[2]);
        ui.horizontal(|ui| {
            ui.spacing_mut().item_spacing.x = 0.0;
            cell(ui, big(v.name.clone(), size).color(c).strong(), NAME_EMS);
            cell(
                ui,
                big(num(d.screen.rasterizer[k]), size).color(c),
                NUMBER_EMS,
            );
            cell(ui, big(num(v.inv_w), size).color(c), NUMBER_EMS);
            let w = correction.map_or("–".into(), |cr| num(cr.weights[k]));
            cell(ui, big(w, size).color(c), NUMBER_EMS);
        });
    }
}

/// 1/W_P and W_P, the depth, uv both ways (the mode's in the accent colour) when the picture
/// is textured; `narrow`: a line each, and uv's name on a line of its own.
fn lines_ui(
    ui: &mut Ui,
    r: &PixelReport,
    d: &crate::probe::TriangleTrace,
    size: f32,
    narrow: bool,
    lang: crate::i18n::Lang,
) {
    let correction = d.perspective.map(|p| p.correction);
    if let Some(c) = correction {
        let inv = format!("{} = {}", &lang.tr("app.present.inv_w_p"), num(c.inv_w_p));
        let w = format!("{} = {}", &lang.tr("app.present.w_p"), num(c.w_p));
        if narrow {
            ui.label(big(inv, size));
            ui.label(big(w, size));
        } else {
            ui.label(big(format!("{inv}  {w}"), size));
        }
    }
    if let Some(depth) = &d.depth {
        ui.label(big(
            format!("{} = {}", &lang.tr("app.present.depth"), num(depth.depth)),
            size,
        ));
    }
    // uv only where a texture shows it (a vertex-colour or weights picture has none to read).
    let textured = r.trace.settings.shading == crate::raster::Shading::Texture;
    if let Some(a) = d.attribute.as_ref().filter(|_| textured) {
        let strong = |t: RichText, on: bool| if on { t.color(ACCENT) } else { t };
        // Trilinear or anisotropic filtering: the mode's uv and its level of detail, in the
        // rows the two uvs take otherwise (the card's height does not change).
        if let Some(lod) = &a.lod {
            let uv = match r.mode {
                Interpolation::Affine => ("app.present.uv_affine", a.uv_affine),
                Interpolation::Perspective => ("app.present.uv_perspective", a.uv_perspective),
            };
            let [rho, levels] = lod_lines(lod, lang);
            if narrow {
                ui.label(big(lang.tr(uv.0), size).color(ACCENT));
                ui.label(big(format!("  {}", pair(uv.1)), size).color(ACCENT));
                ui.label(big(rho, size));
                ui.label(big(levels, size));
            } else {
                ui.label(big(format!("{} {}", &lang.tr(uv.0), pair(uv.1)), size).color(ACCENT));
                ui.label(big(format!("{rho}  {levels}"), size));
            }
            return;
        }
        for (name, uv, mode) in [
            ("app.present.uv_affine", a.uv_affine, Interpolation::Affine),
            (
                "app.present.uv_perspective",
                a.uv_perspective,
                Interpolation::Perspective,
            ),
        ] {
            let on = r.mode == mode;
            if narrow {
                ui.label(strong(big(lang.tr(name), size), on));
                ui.label(strong(big(format!("  {}", pair(uv)), size), on));
            } else {
                ui.label(strong(
                    big(format!("{} {}", &lang.tr(name), pair(uv)), size),
                    on,
                ));
            }
        }
    }
}

/// The card's level-of-detail lines: `rho = ...  lambda = ...` (anisotropic: `N = ...
/// lambda' = ...`, the level from the long side over N) and the mipmap levels read.
pub fn lod_lines(lod: &crate::probe::LodTrace, lang: crate::i18n::Lang) -> [String; 2] {
    let n = |x: f32| fmt_digits(f64::from(x), DIGITS);
    let (first, choice) = match &lod.anisotropic {
        Some(a) => (
            lang.tr_with(
                "app.present.lod_aniso",
                &[("n", &a.n), ("lambda", &n(a.levels.lambda))],
            ),
            &a.levels,
        ),
        None => (
            lang.tr_with(
                "app.present.lod",
                &[("rho", &n(lod.rho)), ("lambda", &n(lod.trilinear.lambda))],
            ),
            &lod.trilinear,
        ),
    };
    let levels = match choice.next {
        Some((e, _)) => lang.tr_with("app.present.levels_two", &[("d", &choice.level), ("e", &e)]),
        None => lang.tr_with("app.present.level_one", &[("d", &choice.level)]),
    };
    [first, levels]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_card_text_fills_the_width_it_is_given_within_its_range() {
        for size in [12.0, 20.0, 31.5] {
            let w = card_width_for_text(size);
            assert!((card_text_for_width(w) - size).abs() < 1e-3, "{size}");
        }
        // Too narrow or too wide: the range's ends.
        assert_eq!(card_text_for_width(10.0), CARD_TEXT_RANGE.0);
        assert_eq!(card_text_for_width(5000.0), CARD_TEXT_RANGE.1);
        // A card without a pixel is far smaller than one with.
        assert!(card_height(20.0, false, 4.0, 1) < 0.4 * card_height(20.0, true, 4.0, 1));
        // The V line: one small row more.
        let row = ROW * SMALL_SHARE * 20.0 + card_spacing(4.0, 20.0);
        let two = card_height(20.0, true, 4.0, 2);
        assert!(
            (two - card_height(20.0, true, 4.0, 1) - row).abs() < 1e-3,
            "{two}"
        );
    }
}
