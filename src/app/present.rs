//! Presentation mode's card: the pinned (else hovered) pixel's key numbers, large and high
//! contrast, for the back of a lecture hall. Every number is the probe trace's (the same
//! trace the inspector shows); nothing is computed here.

use egui::{Color32, RichText, Ui};

use super::pixel::PixelReport;
use crate::probe::format::fmt_digits;
use crate::raster::Interpolation;

/// Text size of the card's numbers in points (times the text size setting), for a window
/// `height` points high: 26 at 768, larger on a larger screen.
pub fn card_text(height: f32) -> f32 {
    (height / 29.5).clamp(CARD_TEXT_RANGE.0, CARD_TEXT_RANGE.1)
}

/// The card's text size for a card `width` points wide under a canvas in a window `height`
/// points high: [`card_text`], smaller if the card would take more than [`CARD_MAX_SHARE`] of
/// the height (a large text size on a small window would leave the canvas a strip).
pub fn card_text_below(width: f32, height: f32, spacing: f32) -> f32 {
    let room = CARD_MAX_SHARE * height - PANEL_MARGINS;
    let mut size = card_text(height);
    // Down in half points to the largest size that fits (a smaller text may put the table
    // beside the lines, which needs fewer rows, so the height is not monotonic in the size).
    while size > CARD_SMALLEST && card_height(width, spacing, size) > room {
        size -= 0.5;
    }
    size.max(CARD_SMALLEST)
}

/// The smallest text size the card shrinks to, in points.
const CARD_SMALLEST: f32 = 10.0;

/// The largest share of the window's height a card below the canvas takes.
pub const CARD_MAX_SHARE: f32 = 0.45;
/// Points the card's panel adds around it (its frame's margins).
pub const PANEL_MARGINS: f32 = 24.0;

/// Smallest and largest card text size, in points.
const CARD_TEXT_RANGE: (f32, f32) = (26.0, 44.0);

/// The card's height in points for a card `width` points wide with text `size`: always the
/// same for a window, whatever pixel it shows (a card that grew with its content would move
/// the canvas under the pointer, change the hovered pixel, and so on).
pub fn card_height(width: f32, spacing: f32, size: f32) -> f32 {
    // The title, then the table (a header and three vertices) beside four lines, or above
    // them (and then the title may take two lines).
    let rows = if width >= SIDE_BY_SIDE_EMS * size {
        5.0
    } else {
        10.0
    };
    // A little to spare below the line of keys at the card's foot.
    rows * (ROW * size + spacing) + ROW * hint_text(size) + spacing + 0.1 * size
}

/// Text size of the card's line of keys (F5 / Esc, Page Down / Up) for card text `size`: on
/// its own line at the card's foot, large enough to read from the back of the room, smaller
/// than the numbers so it does not compete with them.
pub fn hint_text(size: f32) -> f32 {
    HINT_SHARE * size
}

/// The line of keys' size, as a share of the card's text size (at 1024x768 about 16 points, a
/// quarter larger than the body text).
const HINT_SHARE: f32 = 0.6;

/// A row's height, in text heights.
const ROW: f32 = 1.3;
/// The card puts the weights table and the other lines side by side from this many text
/// heights of width (the table and the longest line, uv perspective with two numbers, whole).
const SIDE_BY_SIDE_EMS: f32 = 36.0;
/// Characters of a number column.
const NUMBER_EMS: f32 = 7.0;
/// Significant digits on the card: enough to see the difference, few enough to read.
const DIGITS: i32 = 4;
/// The card's colours: white on near-black.
pub const CARD_FILL: Color32 = Color32::from_rgb(8, 10, 16);
const INK: Color32 = Color32::WHITE;
const DIM: Color32 = Color32::from_rgb(170, 180, 200);
const ACCENT: Color32 = Color32::from_rgb(255, 214, 90);

fn big(s: impl Into<String>, size: f32) -> RichText {
    RichText::new(s).monospace().size(size).color(INK)
}

fn label(s: &str, size: f32) -> RichText {
    RichText::new(s).monospace().size(size).color(DIM)
}

fn num(x: f64) -> String {
    fmt_digits(x, DIGITS)
}

fn pair(uv: [f32; 2]) -> String {
    format!(
        "({}, {})",
        fmt_digits(f64::from(uv[0]), DIGITS),
        fmt_digits(f64::from(uv[1]), DIGITS)
    )
}

/// The card, for the pinned pixel's report if any, else the hovered one's. `keys_hint`
/// replaces the line of keys (a lesson's Page Down / Page Up step through it).
pub fn card_ui(
    ui: &mut Ui,
    hovered: Option<&PixelReport>,
    pinned: Option<&PixelReport>,
    size: f32,
    keys_hint: Option<&str>,
) {
    let lang = super::locale::lang(ui.ctx());
    // The line of keys at the card's foot, the card's numbers above it.
    let hint = keys_hint.map_or_else(|| lang.tr("app.present.leave"), str::to_string);
    ui.with_layout(egui::Layout::bottom_up(egui::Align::Min), |ui| {
        ui.add(
            egui::Label::new(RichText::new(hint).size(hint_text(size)).color(DIM))
                .wrap_mode(egui::TextWrapMode::Truncate),
        );
        ui.with_layout(egui::Layout::top_down(egui::Align::Min), |ui| {
            card_body(ui, hovered, pinned, size, lang);
        });
    });
}

/// The card above its line of keys: the pixel, its weights table and its numbers.
fn card_body(
    ui: &mut Ui,
    hovered: Option<&PixelReport>,
    pinned: Option<&PixelReport>,
    size: f32,
    lang: crate::i18n::Lang,
) {
    let big = |s: String| big(s, size);
    let label = |s: &str| label(s, size);
    let focus = pinned
        .map(|r| (r, lang.tr("app.present.pinned")))
        .or(hovered.map(|r| (r, lang.tr("app.present.hovered"))));
    ui.horizontal_wrapped(|ui| match &focus {
        Some((r, how)) => {
            let mode = match r.mode {
                Interpolation::Affine => lang.tr("app.present.affine"),
                Interpolation::Perspective => lang.tr("app.present.perspective"),
            };
            ui.label(
                big(format!(
                    "{} {}, {} ({how}) · {mode}",
                    &lang.tr("app.present.pixel"),
                    r.pixel[0],
                    r.pixel[1]
                ))
                .color(ACCENT)
                .strong(),
            );
        }
        None => {
            ui.label(big(lang.tr("app.present.no_pixel")).color(ACCENT));
        }
    });
    let Some((r, _)) = focus else {
        return;
    };
    let Some(d) = &r.trace.detail else {
        ui.label(big(lang.tr("app.present.not_covered")));
        return;
    };
    let correction = d.perspective.map(|p| p.correction);
    // A table of fixed-width cells (monospace numbers line up; no measured layout that could
    // change from frame to frame).
    let grid = |ui: &mut Ui| {
        let cell = |ui: &mut Ui, t: RichText, ems: f32| {
            ui.add_sized(
                [ems * size * 0.62, size * ROW],
                egui::Label::new(t).wrap_mode(egui::TextWrapMode::Extend),
            );
        };
        ui.horizontal(|ui| {
            cell(ui, label(""), 1.5);
            for h in [
                &lang.tr("app.present.screen"),
                &lang.tr("app.present.inv_w"),
                &lang.tr("app.present.corrected"),
            ] {
                cell(ui, label(h), NUMBER_EMS);
            }
        });
        for (k, v) in d.raster.vertices.iter().enumerate() {
            ui.horizontal(|ui| {
                cell(ui, big(v.name.clone()).color(ACCENT).strong(), 1.5);
                cell(ui, big(num(d.screen.rasterizer[k])), NUMBER_EMS);
                cell(ui, big(num(v.inv_w)), NUMBER_EMS);
                let c = correction.map_or("–".into(), |c| num(c.weights[k]));
                cell(ui, big(c), NUMBER_EMS);
            });
        }
    };
    let lines = |ui: &mut Ui| {
        if let Some(c) = correction {
            ui.label(big(format!(
                "{} = {}",
                &lang.tr("app.present.inv_w_p"),
                num(c.inv_w_p)
            )));
            ui.label(big(format!(
                "{} = {}",
                &lang.tr("app.present.w_p"),
                num(c.w_p)
            )));
        }
        if let Some(a) = &d.attribute {
            let strong = |t: RichText, on: bool| if on { t.color(ACCENT) } else { t };
            ui.label(strong(
                big(format!(
                    "{} {}",
                    &lang.tr("app.present.uv_affine"),
                    pair(a.uv_affine)
                )),
                r.mode == Interpolation::Affine,
            ));
            ui.label(strong(
                big(format!(
                    "{} {}",
                    &lang.tr("app.present.uv_perspective"),
                    pair(a.uv_perspective)
                )),
                r.mode == Interpolation::Perspective,
            ));
        }
    };
    // Side by side when the card is wide enough, else one above the other (decided from the
    // width alone, so the layout cannot flip back and forth).
    if ui.available_width() >= SIDE_BY_SIDE_EMS * size {
        ui.horizontal_top(|ui| {
            ui.vertical(grid);
            ui.add_space(size);
            ui.vertical(lines);
        });
    } else {
        grid(ui);
        lines(ui);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_card_under_the_canvas_leaves_it_over_half_the_window() {
        // 1024x768 at text sizes 1, 1.5 and 2 (the window in points), and 1920x1080.
        for [w, h] in [
            [1024.0, 768.0],
            [682.7, 512.0],
            [512.0, 384.0],
            [1280.0, 720.0],
        ] {
            let size = card_text_below(w - PANEL_MARGINS, h, 8.0);
            let card = card_height(w - PANEL_MARGINS, 8.0, size) + PANEL_MARGINS;
            assert!(
                card <= CARD_MAX_SHARE * h + 0.5,
                "{w}x{h}: {card} for {size}"
            );
        }
        // At 1024x768 the numbers keep their full size.
        assert_eq!(card_text_below(1000.0, 768.0, 8.0), card_text(768.0));
    }
}
