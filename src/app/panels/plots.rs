//! The plot of the pinned pixel's row, for a lesson step's [`LessonPlot`] (in the Lessons
//! panel) or the user's choice (a window): the lines of [`crate::lesson::plot::row_lines`],
//! read from the row rendered with every per-pixel buffer, drawn with egui_plot. (The
//! handout draws the same lines without egui: [`crate::lesson::plot::row_plot`].)

use std::sync::Arc;

use egui::RichText;
use egui_plot::{Line, Plot, VLine};

use crate::app::BaryApp;
use crate::app::command::AppCommand;
use crate::app::document::state::StateCommand;
use crate::i18n::{Lang, tr};
use crate::lesson::LessonPlot;
use crate::raster::{Framebuffer, Interpolation, Texture};

pub use crate::lesson::plot::{PlotLines, row_lines, title_key};

/// The smallest share of the text size the presentation band's one-row legend is set in to
/// fit its row (smaller would not be read from the back of a room; the entries wrap instead).
const LEGEND_MIN_SCALE: f32 = 0.8;

/// The plot window's contents: a choice of plot, then the plot with the pinned column marked.
/// `one_row`: only the legend above the plot, no choice (a short band: presentation mode).
/// `most`: the most height in points all of it may take (the Lessons panel's largest size
/// leaves its plot column this much; `f32::INFINITY` in a window or the band).
pub fn plot_ui(
    ui: &mut egui::Ui,
    plot: LessonPlot,
    lines: Option<(u32, PlotLines)>,
    lang: Lang,
    hovered_column: &mut Option<u32>,
    one_row: bool,
    most: f32,
) -> Vec<StateCommand> {
    let mut out = Vec::new();
    let top = ui.cursor().top();
    // Never wider than the room given (a long legend must not widen the plot past it).
    let width = ui.available_width().max(120.0);
    ui.set_max_width(width);
    // A short room (the plot beside a step's text in the Lessons panel on a projector): the
    // legend is the lines' names in their colours, in one row if it fits (set smaller as in
    // the band), and the plot keeps a readable height (the panel grows to hold it). With the
    // "Plot:" and legend rows each on a line of their own, the curve had a strip of 15 points.
    let short = !one_row && ui.available_height() < SHORT_BELOW_HEIGHT;
    let fit = one_row || short;
    let legend = |ui: &mut egui::Ui, lines: &PlotLines| {
        // Each entry (the line's colour and its name) wraps as one piece, never inside a name:
        // an entry that would not fit the rest of the row starts the next one (the wrapped
        // layout cannot move a group it has already placed, which then ran past the edge).
        // In one row (the presentation band, whose plot a second legend row would squash),
        // the names are set smaller, down to LEGEND_MIN_SCALE of the text size, to fit it.
        let body = egui::TextStyle::Body.resolve(ui.style());
        let gap = ui.spacing().item_spacing.x;
        let entry_width = |ui: &egui::Ui, text: String, font: &egui::FontId| {
            let w = |t: String| {
                ui.painter()
                    .layout_no_wrap(t, font.clone(), egui::Color32::WHITE)
                    .size()
                    .x
            };
            if short {
                w(text)
            } else {
                w("━━".to_owned()) + gap + w(text)
            }
        };
        let total: f32 = lines
            .iter()
            .map(|(key, _)| entry_width(ui, tr(lang, key), &body) + gap + 8.0)
            .sum();
        let room = ui.available_size_before_wrap().x;
        let scale = if fit && total > room {
            (room / total).max(LEGEND_MIN_SCALE)
        } else {
            1.0
        };
        let font = egui::FontId::new(body.size * scale, body.family.clone());
        for (k, (key, _)) in lines.iter().enumerate() {
            let entry = entry_width(ui, tr(lang, key), &font);
            if k > 0 && entry > ui.available_size_before_wrap().x {
                ui.end_row();
            }
            ui.horizontal(|ui| {
                let mut name = RichText::new(tr(lang, key)).font(font.clone());
                if short {
                    name = name.color(line_color(k, ui.visuals().dark_mode)).strong();
                } else {
                    ui.label(
                        RichText::new("━━")
                            .font(font.clone())
                            .color(line_color(k, ui.visuals().dark_mode))
                            .strong(),
                    );
                }
                ui.add(egui::Label::new(name).wrap_mode(egui::TextWrapMode::Extend));
            });
            ui.add_space(8.0);
        }
    };
    if one_row {
        // One row (a band under the picture): the legend (it names the lines), no choice.
        ui.horizontal_wrapped(|ui| match &lines {
            Some((_, lines)) => legend(ui, lines),
            None => {
                ui.label(RichText::new(tr(lang, title_key(plot))).strong());
            }
        });
    } else {
        // "Plot:" and the chosen plot's name in one row, the name cut short to the room left
        // (the whole name is the hover text and in the list). Wrapped to three lines in a
        // narrow column, it pushed the plot past the Lessons panel; in a wrapping row, the
        // button took a row of its own.
        ui.horizontal(|ui| {
            let label = ui.label(tr(lang, "lesson.plot_kind"));
            egui::ComboBox::from_id_salt("row-plot-kind")
                .selected_text(tr(lang, title_key(plot)))
                .truncate()
                .width(COMBO_MIN_WIDTH)
                .show_ui(ui, |ui| {
                    for p in [
                        LessonPlot::UvRow,
                        LessonPlot::WRow,
                        LessonPlot::DepthRow,
                        LessonPlot::LambdaColumn,
                    ] {
                        if ui
                            .selectable_label(p == plot, tr(lang, title_key(p)))
                            .clicked()
                            && p != plot
                        {
                            out.push(StateCommand::SetPlot(Some(p)));
                        }
                    }
                })
                .response
                .labelled_by(label.id)
                .on_hover_text(tr(lang, title_key(plot)));
        });
    }
    let Some((pin_x, lines)) = lines else {
        ui.label(tr(lang, "lesson.plot_none"));
        return out;
    };
    // The legend above the plot, in the lines' colours (egui_plot's legend lies over the
    // lines it names).
    if !one_row {
        ui.horizontal_wrapped(|ui| legend(ui, &lines));
    }
    // Readable if the room allows, but never more than the room left (a plot taller than its
    // panel's largest size pushed the panel's first row, Previous and Next, out of sight).
    let left = most - (ui.cursor().top() - top) - 8.0;
    let least = if one_row {
        PLOT_MIN_HEIGHT
    } else {
        PLOT_READABLE_HEIGHT.min(left).max(PLOT_MIN_HEIGHT)
    };
    let dark = ui.visuals().dark_mode;
    let shown = Plot::new(("row-plot", plot as u8))
        .x_axis_label(tr(lang, crate::lesson::plot::x_label_key(plot)))
        .show_axes([true, true])
        // Never taller than the room left (a plot that overflowed its panel would push the
        // panel's first row, the lesson's Previous / Next, out of sight).
        .height((ui.available_height() - 8.0).max(least))
        .width(width)
        .show(ui, |p| {
            for (k, (key, points)) in lines.into_iter().enumerate() {
                p.line(
                    Line::new(tr(lang, key), points)
                        .color(line_color(k, dark))
                        .width(2.5),
                );
            }
            p.vline(VLine::new("", f64::from(pin_x)));
            p.pointer_coordinate()
        });
    ui.ctx()
        .data_mut(|d| d.insert_temp(egui::Id::unique(PLOT_RECT_ID), shown.response.rect));
    // Hovering the plot marks that column of the pinned row on the canvas.
    if shown.response.hovered()
        && let Some(at) = shown.inner
        && at.x >= 0.0
    {
        *hovered_column = Some(at.x.round() as u32);
    }
    out
}

/// Points: the least width of the button choosing the plot.
const COMBO_MIN_WIDTH: f32 = 80.0;

/// Points of height below which the room for a plot is short: its legend keeps to one row.
const SHORT_BELOW_HEIGHT: f32 = 260.0;

/// Where the row plot drawn last lies: egui's temporary data under this id.
const PLOT_RECT_ID: &str = "row-plot-rect";

/// Where the row plot (its axes and lines) was drawn last, if one was drawn.
pub(crate) fn last_plot_rect(ctx: &egui::Context) -> Option<egui::Rect> {
    ctx.data(|d| d.get_temp(egui::Id::unique(PLOT_RECT_ID)))
}

/// Points: the least height of the plot outside the presentation band, where its room allows
/// ([`plot_ui`]'s `most`): about 35 go to the axes, and the curve needs the rest to be read
/// from the back of a room.
const PLOT_READABLE_HEIGHT: f32 = 100.0;

/// Points: the least height of the plot area.
const PLOT_MIN_HEIGHT: f32 = 48.0;

/// The colour of a plot's `k`th line and of its name in the legend, on the dark theme
/// (`dark`) or the light one: distinct, and not the vertex colours (the lines are no
/// vertices). Each has at least the 4.5:1 contrast of readable text against the theme's
/// backgrounds; the dark theme's light colours had 1.6-2.8:1 on the light theme's white.
fn line_color(k: usize, dark: bool) -> egui::Color32 {
    const ON_DARK: [egui::Color32; 4] = [
        egui::Color32::from_rgb(255, 140, 60),
        egui::Color32::from_rgb(90, 170, 255),
        egui::Color32::from_rgb(240, 90, 200),
        egui::Color32::from_rgb(120, 220, 140),
    ];
    const ON_LIGHT: [egui::Color32; 4] = [
        egui::Color32::from_rgb(176, 80, 0),
        egui::Color32::from_rgb(20, 100, 200),
        egui::Color32::from_rgb(170, 40, 140),
        egui::Color32::from_rgb(20, 125, 50),
    ];
    let colors = if dark { ON_DARK } else { ON_LIGHT };
    colors[k % colors.len()]
}

/// The last row rendered with every buffer (one row high), by the canvas render it repeats,
/// the mode and the row.
pub type RowRender = Option<((u64, Interpolation, u32), Arc<Framebuffer>)>;

impl BaryApp {
    /// The chosen plot's lines along the pinned row, from that row rendered with every buffer
    /// (`raster::render_row`: the full render's values, made once per canvas render, mode and
    /// row; the canvas itself renders colour and depth only).
    pub(in crate::app) fn row_plot(&mut self, texture: &Texture) -> Option<(u32, PlotLines)> {
        let plot = self.state.view.plot?;
        let [x, y] = self.state.view.pinned?;
        let output = self.canvas.output.as_ref()?;
        let mode = self.state.options().mode;
        let mut settings = output.scene.settings();
        if y >= settings.height || x >= settings.width {
            return None;
        }
        if plot == LessonPlot::LambdaColumn {
            settings.mode = mode;
            let lines = self
                .texel_view
                .lambda_column(output, texture, &settings, x)?;
            return Some((y, lines));
        }
        let key = (output.generation, mode, y);
        let row = match &self.lessons.row_render {
            Some((k, r)) if *k == key => r.clone(),
            _ => {
                settings.mode = mode;
                let mesh = output.scene.to_mesh();
                let r = Arc::new(crate::raster::render_row(&mesh, texture, &settings, y).ok()?);
                self.lessons.row_render = Some((key, r.clone()));
                r
            }
        };
        Some((x, row_lines(&row, 0, plot)))
    }

    /// The plot window, when a plot is chosen outside a lesson (a lesson shows it in its
    /// panel); closing it clears the choice.
    pub(in crate::app) fn plot_window(
        &mut self,
        ctx: &egui::Context,
        texture: &Texture,
        out: &mut Vec<AppCommand>,
    ) {
        self.plot_hover_to_canvas();
        let Some(plot) = self.state.view.plot else {
            return;
        };
        if self.lessons.session.is_some() {
            return;
        }
        let lang = self.lang();
        let lines = self.row_plot(texture);
        let mut open = true;
        let size = ctx.content_rect().size();
        egui::Window::new(tr(lang, "lesson.plot_title"))
            .open(&mut open)
            .default_size([size.x * 0.4, size.y * 0.35])
            .default_pos([size.x * 0.55, size.y * 0.1])
            .show(ctx, |ui| {
                let mut column = None;
                out.extend(
                    plot_ui(ui, plot, lines, lang, &mut column, false, f32::INFINITY)
                        .into_iter()
                        .map(Into::into),
                );
                self.lessons.plot_hover = column;
            });
        if !open {
            out.push(StateCommand::SetPlot(None).into());
        }
        self.plot_hover_to_canvas();
    }

    /// The column hovered in the plot (this frame's, from the Lessons panel or the window)
    /// becomes the canvas's hovered pixel on the pinned row while the pointer is off the
    /// canvas, so the inspector and the overlay show it.
    fn plot_hover_to_canvas(&mut self) {
        let Some(x) = self.lessons.plot_hover.take() else {
            return;
        };
        let size = self.canvas.output.as_ref().map(|o| o.size);
        // Along the pinned column for the column plot (its axis counts rows).
        let column = self.state.view.plot == Some(LessonPlot::LambdaColumn);
        if let (None, Some([px, py]), Some([w, h])) =
            (self.canvas.hover, self.state.view.pinned, size)
            && x < if column { h } else { w }
        {
            self.canvas.hover = Some(if column { [px, x] } else { [x, py] });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// WCAG's contrast ratio of two colours (relative luminance of the sRGB values).
    fn contrast(a: egui::Color32, b: egui::Color32) -> f32 {
        let luminance = |c: egui::Color32| {
            let lin = |v: u8| {
                let v = f32::from(v) / 255.0;
                if v <= 0.04045 {
                    v / 12.92
                } else {
                    ((v + 0.055) / 1.055).powf(2.4)
                }
            };
            0.2126 * lin(c.r()) + 0.7152 * lin(c.g()) + 0.0722 * lin(c.b())
        };
        let (x, y) = (luminance(a) + 0.05, luminance(b) + 0.05);
        x.max(y) / x.min(y)
    }

    /// Every line and legend colour reads as text (4.5:1) on its theme's panel and on the
    /// plot's background; the dark colours on the light theme did not (green 1.6:1).
    #[test]
    fn the_lines_read_on_both_themes() {
        for (dark, visuals) in [
            (true, egui::Visuals::dark()),
            (false, egui::Visuals::light()),
        ] {
            for k in 0..4 {
                for background in [visuals.panel_fill, visuals.extreme_bg_color] {
                    let c = contrast(line_color(k, dark), background);
                    assert!(
                        c >= 4.5,
                        "line {k}, dark {dark}: {c:.2}:1 on {background:?}"
                    );
                }
            }
        }
        assert!(contrast(line_color(3, true), egui::Visuals::light().panel_fill) < 4.5);
    }
}
