//! Presentation mode's layout: the canvas as large as the window allows, the row plot in a
//! band under it, and the card (and the magnifier) beside, under or over the picture.

use crate::app::BaryApp;
use crate::app::command::{self, AppCommand};
use crate::app::panels::canvas_layout::Framing;
use crate::app::panels::{compare_image, magnifier, present};
use crate::app::side_panels;
use crate::figure::ViewContent;
use crate::raster::Texture;
use std::sync::Arc;

impl BaryApp {
    /// Presentation mode: the canvas as large as the window allows; the row plot (if any) in a
    /// band under it; the card beside it where a column is to spare (wide screens), under two
    /// images side by side, over the picture in a corner that hides none of it, else in a
    /// narrow column the picture makes room for.
    pub(in crate::app) fn presentation(
        &mut self,
        ui: &mut egui::Ui,
        texture: &Arc<Texture>,
        out: &mut Vec<AppCommand>,
    ) {
        let spacing = ui.spacing().item_spacing.y;
        // The card's lines of keys: two when V offers the 3D view.
        let key_lines = 1 + usize::from(self.space_toggle_offered);
        let full = self.reports.hover.is_some() || self.reports.pin.is_some();
        let compare = self.state.view.compare;
        let framing = Framing::presenting(compare);
        let (w, h) = self.state.scene.size();
        let aspect = w.max(1) as f32 / h.max(1) as f32;
        self.present_plot_band(ui, texture, out);
        let rect = ui.available_rect_before_wrap();
        let window = ui.ctx().content_rect();
        // C hides the card: the picture alone, as large as the window allows.
        if !self.state.view.show_card {
            self.canvas.avoid.clear();
            self.canvas_panel(ui, texture, framing, out);
            return;
        }
        if let Some(width) = beside_width(rect, aspect, compare, framing, window) {
            let size = present::card_text_for_width(width);
            self.card_column(ui, width, size, false, texture, framing, out);
            return;
        }
        if let Some(height) = below_height(rect, aspect, compare, framing, spacing, key_lines) {
            let size = present::card_text_for_width(rect.width() / 2.0)
                .min(below_text(height, spacing, key_lines));
            self.canvas.avoid.clear();
            let input = self.card_input(size, false);
            egui::Panel::bottom("present-card-below")
                .frame(
                    egui::Frame::new()
                        .fill(present::CARD_FILL)
                        .inner_margin(egui::Margin::same(12)),
                )
                .resizable(false)
                .exact_size(height)
                .show(ui, |ui| present::card_ui(ui, &input));
            self.canvas_panel(ui, texture, framing, out);
            if let Some(m) = self.magnifier_input(size) {
                let area = self.canvas.area.unwrap_or(rect);
                self.magnifier_over(ui, area, &[], m);
            }
            return;
        }
        // Over the picture, in a corner where it hides no mark and little of the scene, as
        // the picture would be drawn at its largest (not as it is drawn now: the choice must
        // not depend on itself); without a pin, in the emptiest corner.
        let over_area = rect.shrink(side_panels::CANVAS_MARGIN);
        let size = over_text(over_area.width());
        let width = present::card_width_for_text(size).min(over_area.width());
        let card = egui::vec2(width, present::card_height(size, full, spacing, key_lines));
        // The layout follows the pin only: a hovered pixel fills the card where it is (a
        // picture that made room when the pointer entered it would move under the pointer).
        let corner = if self.state.view.pinned.is_some() {
            let views = self.views_at_largest(over_area, framing, ui.ctx().pixels_per_point());
            self.free_corner_in(
                over_area,
                card,
                &[],
                &views,
                crate::app::panels::corners::FREE_CARD,
            )
        } else {
            let pointer = ui.ctx().pointer_hover_pos();
            Some(self.emptiest_corner(self.canvas.area.unwrap_or(over_area), card, pointer))
        };
        let Some(corner) = corner else {
            let size = narrow_text(rect, spacing, key_lines);
            let width = present::card_width_narrow(size);
            self.card_column(ui, width, size, true, texture, framing, out);
            return;
        };
        self.canvas_panel(ui, texture, framing, out);
        self.canvas.avoid = vec![corner];
        let area = self.canvas.area.unwrap_or(over_area);
        if let Some(m) = self.magnifier_input(size) {
            let taken: Vec<egui::Rect> = self.canvas.avoid.clone();
            self.magnifier_over(ui, area, &taken, m);
        }
        let input = self.card_input(size, false);
        egui::Area::new(egui::Id::unique("present-card-over"))
            .order(egui::Order::Foreground)
            .fixed_pos(corner.min)
            .interactable(false)
            .show(ui.ctx(), |ui| {
                egui::Frame::new()
                    .fill(present::CARD_FILL_OVER)
                    .corner_radius(6)
                    .inner_margin(egui::Margin::same(12))
                    .show(ui, |ui| {
                        ui.set_width(width - present::PANEL_MARGINS);
                        present::card_ui(ui, &input);
                    });
            });
    }

    /// Presentation mode's plot of the pinned pixel's row (or column): a band as wide as the
    /// room left under the picture (over it or in the card's column it would hide the picture
    /// or be too small to read).
    pub(in crate::app) fn present_plot_band(
        &mut self,
        ui: &mut egui::Ui,
        texture: &Arc<Texture>,
        out: &mut Vec<AppCommand>,
    ) {
        let lang = self.lang();
        if let Some(p) = self.state.view.plot.zip(self.state.view.pinned) {
            let lines = self.row_plot(texture);
            let band = (PLOT_BAND_SHARE * ui.available_rect_before_wrap().height()).round();
            let mut plot_hover = None;
            egui::Panel::bottom("present-plot-below")
                .frame(
                    egui::Frame::new()
                        .fill(present::CARD_FILL)
                        .inner_margin(egui::Margin::same(10)),
                )
                .resizable(false)
                .exact_size(band)
                .show(ui, |ui| {
                    out.extend(present_plot(ui, (p.0, lines), lang, &mut plot_hover));
                });
            self.lessons.plot_hover = plot_hover;
        } else {
            self.lessons.plot_hover = None;
        }
    }

    /// The card in a column `width` points wide right of the canvas (text `size`, `narrow`:
    /// the narrow card), the magnifier under it where there is room.
    #[allow(clippy::too_many_arguments)]
    fn card_column(
        &mut self,
        ui: &mut egui::Ui,
        width: f32,
        size: f32,
        narrow: bool,
        texture: &Arc<Texture>,
        framing: Framing,
        out: &mut Vec<AppCommand>,
    ) {
        self.canvas.avoid.clear();
        let input = self.card_input(size, narrow);
        let magnifier = self.magnifier_input(size);
        egui::Panel::right("present-card")
            .frame(
                egui::Frame::new()
                    .fill(present::CARD_FILL)
                    .inner_margin(egui::Margin::same(12)),
            )
            .resizable(false)
            .exact_size(width)
            .show(ui, |ui| {
                present::card_ui(ui, &input);
                if let Some(m) = &magnifier {
                    ui.add_space(12.0);
                    let side = ui
                        .available_width()
                        .min(ui.available_height() - magnifier::title_height(m.text_size));
                    if side >= magnifier::MIN_SIDE {
                        magnifier::magnifier_ui(ui, side, m);
                    }
                }
            });
        self.canvas_panel(ui, texture, framing, out);
    }

    /// The canvas's views as it would draw them in `area` at their largest (presentation
    /// mode's card over the picture), mapping the pixels of the render shown now.
    fn views_at_largest(
        &self,
        area: egui::Rect,
        framing: Framing,
        pixels_per_point: f32,
    ) -> Vec<crate::app::panels::canvas::View> {
        let Some(output) = &self.canvas.output else {
            return Vec::new();
        };
        let view = &self.state.view;
        let sizing = crate::app::panels::canvas::sizing(&self.state);
        let lay = crate::app::panels::canvas_layout::layout(
            area,
            view.compare,
            sizing,
            pixels_per_point,
            framing,
        );
        let gpu = compare_image::other_view(self.compare_image.as_ref(), view.gpu, &self.gpu_view);
        crate::app::panels::canvas::views_of(&lay, &self.state, gpu.is_some(), output.size[0])
    }

    /// The magnifier's contents, when it is on and a pixel is pinned; its title `text_size`
    /// points.
    pub(in crate::app) fn magnifier_input(
        &self,
        text_size: f32,
    ) -> Option<magnifier::MagnifierInput> {
        if !self.state.view.show_magnifier {
            return None;
        }
        let pin = self.reports.pin.as_ref()?;
        let content = ViewContent::Mode(self.state.options().mode);
        Some(magnifier::MagnifierInput {
            texture: self.canvas.view_texture(content)?,
            pixel: pin.pixel,
            triangle: pin.triangle(),
            samples: pin.sample_marks.clone(),
            lang: self.lang(),
            text_size,
        })
    }

    /// The magnifier over the picture, in a free corner of the canvas `area` clear of the
    /// boxes `taken` (the card, the plot); left out when no corner is free (it would hide a
    /// mark or much of the picture).
    fn magnifier_over(
        &mut self,
        ui: &egui::Ui,
        area: egui::Rect,
        taken: &[egui::Rect],
        m: magnifier::MagnifierInput,
    ) {
        let side =
            (magnifier::OVER_SHARE * area.width().min(area.height())).max(magnifier::MIN_SIDE);
        let margin = 10.0;
        let size = egui::vec2(side, side + magnifier::title_height(m.text_size))
            + egui::Vec2::splat(2.0 * margin);
        let Some(at) = self.free_corner(area, size, taken) else {
            return;
        };
        self.canvas.avoid.push(at);
        egui::Area::new(egui::Id::unique("present-magnifier"))
            .order(egui::Order::Foreground)
            .fixed_pos(at.min)
            .interactable(false)
            .show(ui.ctx(), |ui| {
                egui::Frame::new()
                    .fill(present::CARD_FILL_OVER)
                    .corner_radius(6)
                    .inner_margin(egui::Margin::same(margin as i8))
                    .show(ui, |ui| magnifier::magnifier_ui(ui, side, &m));
            });
    }

    /// The card's contents at text `size`.
    fn card_input(&self, size: f32, narrow: bool) -> present::CardInput<'_> {
        present::CardInput {
            narrow,
            compare: self.state.view.compare != crate::figure::Compare::Single,
            hovered: self.reports.hover.as_ref(),
            pinned: self.reports.pin.as_ref(),
            context: self.present_context(),
            keys_hint: {
                let lang = self.lang();
                // A lesson's keys (else the card's own line), and V where it is offered.
                let keys = self
                    .lessons
                    .session
                    .is_some()
                    .then(|| crate::i18n::tr(lang, "lesson.present_hint"));
                if self.space_toggle_offered {
                    let keys = keys.unwrap_or_else(|| lang.tr("app.present.leave"));
                    Some(format!(
                        "{keys}\n{}",
                        crate::i18n::tr(lang, "lesson.present_hint_space")
                    ))
                } else {
                    keys
                }
            },
            size,
        }
    }

    /// What the canvas shows, for the card's first line: the preset last loaded. None during
    /// a lesson: its strip under the picture names the step in the lesson's large text (the
    /// card's small line repeated it, cut short, too small for a room).
    fn present_context(&self) -> Option<String> {
        if self.lessons.session.is_some() {
            return None;
        }
        let lang = self.lang();
        self.last_preset
            .map(|p| crate::app::panels::controls::preset_name(p, lang))
    }
}

/// Presentation mode's row plot (beside or over the picture), its commands.
fn present_plot(
    ui: &mut egui::Ui,
    (plot, lines): (
        crate::lesson::LessonPlot,
        Option<(u32, crate::app::panels::plots::PlotLines)>,
    ),
    lang: crate::i18n::Lang,
    hovered_column: &mut Option<u32>,
) -> Vec<AppCommand> {
    command::all(crate::app::panels::plots::plot_ui(
        ui,
        plot,
        lines,
        lang,
        hovered_column,
        true,
        f32::INFINITY,
    ))
    .collect()
}

/// The share of the canvas's height the row plot's band under the picture takes.
const PLOT_BAND_SHARE: f32 = 0.34;
/// Points: the largest text of a card over the picture (on a large screen a larger card would
/// hide more of it than the room needs to read it).
const OVER_MAX_TEXT: f32 = 26.0;

/// The card over the picture takes this share of the canvas's width.
const OVER_CARD_SHARE: f32 = 0.42;
/// The smallest text size (points) of a card beside the picture, unless a card over the
/// picture would have smaller text still ([`over_text`]): narrower than that, the card goes
/// over the picture instead.
const BESIDE_MIN_TEXT: f32 = 16.0;

/// The text size of the card over a canvas `width` points wide: a share of the width, within
/// the card's range.
fn over_text(width: f32) -> f32 {
    present::card_text_for_width(
        (OVER_CARD_SHARE * width).max(present::card_width_for_text(present::CARD_TEXT_RANGE.0)),
    )
    .min(OVER_MAX_TEXT)
}
/// The largest share of the window's width a card beside the picture takes.
const BESIDE_MAX_SHARE: f32 = 0.36;

/// The height of a wide card under two images side by side: the band the images at their
/// largest leave free, or up to [`BELOW_MAX_SHARE`] of the canvas `rect` (the images give way),
/// if a card at least [`BELOW_MIN_TEXT`] large fits there. A single image takes a column
/// beside it or the card over it instead.
fn below_height(
    rect: egui::Rect,
    aspect: f32,
    compare: crate::figure::Compare,
    framing: Framing,
    spacing: f32,
    key_lines: usize,
) -> Option<f32> {
    if compare != crate::figure::Compare::SideBySide {
        return None;
    }
    let margin = side_panels::CANVAS_MARGIN + crate::app::panels::canvas_layout::HANDLE_MARGIN;
    let each =
        (rect.width() - 2.0 * margin - crate::app::panels::canvas_layout::SIDE_BY_SIDE_GAP) / 2.0;
    let used = each.max(0.0) / aspect.max(0.01)
        + framing.title_strip
        + 2.0 * side_panels::CANVAS_MARGIN
        + crate::app::panels::canvas_layout::HANDLE_MARGIN;
    let room = (rect.height() - used).max(BELOW_MAX_SHARE * rect.height());
    let least = present::card_height_wide(BELOW_MIN_TEXT, spacing, key_lines);
    (room >= least).then(|| room.min(present::card_height_wide(OVER_MAX_TEXT, spacing, key_lines)))
}

/// The largest share of the canvas's height a card under two images takes from them.
const BELOW_MAX_SHARE: f32 = 0.38;
/// The smallest text size (points) of a card under two images.
const BELOW_MIN_TEXT: f32 = 13.0;

/// The narrow card's column takes this share of the canvas's width.
const NARROW_SHARE: f32 = 0.32;
/// The smallest text size (points) of the narrow card.
const NARROW_MIN_TEXT: f32 = 12.0;

/// The text size of the narrow card beside the picture in the canvas `rect`: its column a
/// share of the width, its height within the canvas's.
fn narrow_text(rect: egui::Rect, spacing: f32, key_lines: usize) -> f32 {
    let for_width = (NARROW_SHARE * rect.width() - present::PANEL_MARGINS)
        / (present::card_width_narrow(1.0) - present::PANEL_MARGINS);
    let mut size = for_width.clamp(NARROW_MIN_TEXT, OVER_MAX_TEXT);
    while size > NARROW_MIN_TEXT
        && present::card_height_narrow(size, spacing, key_lines) > rect.height()
    {
        size -= 0.5;
    }
    size
}

/// The largest text size whose wide card fits `height` points.
fn below_text(height: f32, spacing: f32, key_lines: usize) -> f32 {
    let mut size = OVER_MAX_TEXT;
    while size > BELOW_MIN_TEXT && present::card_height_wide(size, spacing, key_lines) > height {
        size -= 0.5;
    }
    size
}

/// The width of the card beside the picture, if the canvas `rect` (points) leaves a column
/// for it next to the largest picture of `aspect` (width / height) it can hold.
fn beside_width(
    rect: egui::Rect,
    aspect: f32,
    compare: crate::figure::Compare,
    framing: Framing,
    window: egui::Rect,
) -> Option<f32> {
    let views = if compare == crate::figure::Compare::SideBySide {
        2.0
    } else {
        1.0
    };
    let margin = side_panels::CANVAS_MARGIN + crate::app::panels::canvas_layout::HANDLE_MARGIN;
    let height = rect.height()
        - 2.0 * side_panels::CANVAS_MARGIN
        - framing.title_strip
        - crate::app::panels::canvas_layout::HANDLE_MARGIN;
    let image = views * height.max(0.0) * aspect + 2.0 * margin;
    let free = rect.width() - image;
    // Beside is better than over whenever its text is no smaller than the card over the
    // picture would have (a square picture leaves columns at both sides).
    let least = present::card_width_for_text(BESIDE_MIN_TEXT.min(over_text(rect.width())));
    if free >= least {
        return Some(free.min(BESIDE_MAX_SHARE * rect.width()).max(least));
    }
    // Not quite: the picture may narrow to make the column, if it keeps BESIDE_KEEP of the
    // window (a wide screen: the card beside hides nothing).
    let width = (rect.width() - least - 2.0 * margin) / views;
    let shown = views * width.max(0.0) * (width.max(0.0) / aspect).min(height.max(0.0));
    // Or a narrow picture (a square one on a 4:3 projector) that keeps most of its size: the
    // card beside it hides nothing, over it the card would hide a good part of it.
    let full = height.max(0.0) * aspect;
    let keeps = width.max(0.0).min(full) >= BESIDE_SHRINK * full;
    (shown >= BESIDE_KEEP * window.area() || keeps).then_some(least)
}

/// The share of the window the picture keeps when it narrows for the card beside it.
const BESIDE_KEEP: f32 = 0.5;
/// Or the share of its own width a picture keeps when it narrows for the card beside it.
const BESIDE_SHRINK: f32 = 0.8;
