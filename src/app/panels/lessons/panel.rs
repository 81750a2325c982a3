//! The Lessons panel's drawing: the step's text ([`text_ui`]), the stepper (Previous, the
//! step number's menu, Next), the panel itself ([`lesson_panel_ui`]) with its list of steps
//! and plot, and the presentation strip ([`lesson_strip_ui`]).

use egui::{RichText, Ui};

use super::Session;
use super::formula;
use crate::app::command::{AppCommand, LessonCommand};
use crate::app::panels::plots::{PlotLines, plot_ui};
use crate::i18n::{Lang, tr};
use crate::lesson::LessonPlot;
use crate::lesson::text::{self, Block, blocks};

/// The text size of a step's prose in the panel (points).
const TEXT_SIZE: f32 = 17.0;

/// A step's text as egui labels: paragraphs with bold spans, formula blocks in monospace.
fn text_ui(ui: &mut Ui, text: &str, size: f32) {
    for (k, block) in blocks(text).into_iter().enumerate() {
        match block {
            Block::Paragraph(spans) => {
                let mut job = egui::text::LayoutJob::default();
                let color = ui.visuals().strong_text_color();
                // Bold terms stand out by colour too (egui's strong text is only brighter).
                let term = if ui.visuals().dark_mode {
                    egui::Color32::from_rgb(250, 204, 92)
                } else {
                    egui::Color32::from_rgb(150, 80, 0)
                };
                for s in spans {
                    let mut t = RichText::new(s.text).size(size).color(color);
                    if s.bold {
                        t = t.strong().color(term);
                    }
                    t.append_to(
                        &mut job,
                        ui.style(),
                        egui::FontSelection::Default,
                        egui::Align::Min,
                    );
                }
                ui.add(egui::Label::new(job).wrap());
            }
            Block::Formula(lines) => {
                // A formula keeps its lines. A little wider than the panel, it is set a little
                // smaller (down to FORMULA_MIN_SCALE of its size); wider still, its lines wrap
                // at full size: a room reads a wrapped line, not a tiny or a cut one.
                let text = lines.join("\n");
                let natural = size - 2.0;
                let width = formula::width(ui, &text, natural);
                let label = match formula::fitted_size(natural, width, ui.available_width()) {
                    Some(fitted) => {
                        egui::Label::new(RichText::new(text).monospace().size(fitted)).extend()
                    }
                    None => egui::Label::new(RichText::new(text).monospace().size(natural)).wrap(),
                };
                ui.push_id(("formula", k), |ui| ui.add(label));
            }
        }
        ui.add_space(size * 0.4);
    }
}

/// Previous, "Step n of N" (a menu of every step), Next.
fn stepper_ui(ui: &mut Ui, session: &Session, lang: Lang, size: f32, out: &mut Vec<LessonCommand>) {
    let n = session.lesson.steps.len();
    if ui
        .add_enabled(
            session.step > 0,
            egui::Button::new(RichText::new(tr(lang, "lesson.previous")).size(size)),
        )
        .clicked()
    {
        out.push(LessonCommand::Previous);
    }
    let current = rust_i18n::t!(
        "lesson.step_of",
        locale = lang.code(),
        n = session.step + 1,
        total = n
    );
    // The step number opens the list of steps (the panel has no room for a list of its own
    // on a projector).
    let name = current.to_string();
    egui::ComboBox::from_id_salt("lesson-step-menu")
        .selected_text(RichText::new(current).size(size))
        .height(f32::INFINITY)
        .show_ui(ui, |ui| {
            for (i, s) in session.lesson.steps.iter().enumerate() {
                let label = format!("{}. {}", i + 1, s.title.get(lang));
                if ui.selectable_label(i == session.step, label).clicked() && i != session.step {
                    out.push(LessonCommand::Go(i));
                }
            }
        })
        .response
        .widget_info(|| egui::WidgetInfo::labeled(egui::Role::ComboBox, true, &name));
    if ui
        .add_enabled(
            session.step + 1 < n,
            egui::Button::new(RichText::new(tr(lang, "lesson.next")).size(size)),
        )
        .clicked()
    {
        out.push(LessonCommand::Next);
    }
}

/// A plot and its lines along the pinned row (none while nothing is pinned).
pub type PanelPlot = Option<(LessonPlot, Option<(u32, PlotLines)>)>;

/// Points of panel width from which the Lessons panel shows its list of steps on the left
/// (below that the step number's menu lists them).
const LIST_FROM_WIDTH: f32 = 980.0;
/// Points of panel width from which the plot goes beside the text (below that, under it).
const PLOT_BESIDE_FROM_WIDTH: f32 = 600.0;
/// Points: the plot's height when it goes under the text.
const PLOT_BELOW_HEIGHT: f32 = 230.0;
/// Points of panel width from which "Reset this step" and "Leave the lesson" are buttons in
/// the first row (below that, a menu).
const BUTTONS_FROM_WIDTH: f32 = 640.0;

/// The Lessons panel: first, always, one row with Previous, the step number (a menu of the
/// steps), Next, and Reset / Leave; under it the step's title, text and "try this", with the
/// step's plot beside or under the text, and on a wide window the list of steps on the left.
/// `most`: the panel's largest height in points, which the plot keeps within.
pub fn lesson_panel_ui(
    ui: &mut Ui,
    session: &Session,
    lang: Lang,
    plot: PanelPlot,
    hovered_column: &mut Option<u32>,
    most: f32,
) -> Vec<AppCommand> {
    let top = ui.max_rect().top();
    let mut out: Vec<LessonCommand> = Vec::new();
    let mut plot_out: Vec<AppCommand> = Vec::new();
    let lesson = &session.lesson;
    let step = &lesson.steps[session.step];
    let full_width = ui.available_width();
    ui.horizontal(|ui| {
        stepper_ui(ui, session, lang, 15.0, &mut out);
        ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
            let leave = |ui: &mut Ui, out: &mut Vec<LessonCommand>| {
                if ui
                    .button(tr(lang, "lesson.leave"))
                    .on_hover_text(tr(lang, "lesson.leave_hint"))
                    .clicked()
                {
                    out.push(LessonCommand::Leave);
                    ui.close();
                }
            };
            let reset = |ui: &mut Ui, out: &mut Vec<LessonCommand>| {
                if ui.button(tr(lang, "lesson.reset_step")).clicked() {
                    out.push(LessonCommand::Reset);
                    ui.close();
                }
            };
            if full_width >= BUTTONS_FROM_WIDTH {
                leave(ui, &mut out);
                reset(ui, &mut out);
            } else {
                ui.menu_button(tr(lang, "lesson.more"), |ui| {
                    reset(ui, &mut out);
                    leave(ui, &mut out);
                });
            }
            if full_width >= LIST_FROM_WIDTH {
                ui.add(egui::Label::new(RichText::new(lesson.title.get(lang)).weak()).truncate());
            }
        });
    });
    ui.separator();
    let height = ui.available_height();
    // What the panel at its largest leaves under the first row (the plot keeps within it).
    let room = most - (ui.cursor().top() - top);
    ui.horizontal_top(|ui| {
        if full_width >= LIST_FROM_WIDTH {
            let list_width = (full_width * 0.22).clamp(150.0, 300.0);
            steps_list_ui(ui, session, lang, [list_width, height], &mut out);
            ui.separator();
        }
        let beside = plot.is_some() && ui.available_width() >= PLOT_BESIDE_FROM_WIDTH;
        let plot_width = if beside {
            (ui.available_width() * 0.42).max(240.0)
        } else {
            0.0
        };
        let text_width = (ui.available_width() - plot_width).max(160.0);
        let mut plot = plot;
        let below = if beside { None } else { plot.take() };
        ui.allocate_ui_with_layout(
            egui::vec2(text_width, height),
            egui::Layout::top_down(egui::Align::Min),
            |ui| {
                egui::ScrollArea::vertical()
                    .id_salt(("lesson-text", session.step))
                    .auto_shrink([false, false])
                    .show(ui, |ui| {
                        // Keep the text clear of the scroll bar.
                        let bar =
                            ui.spacing().scroll.bar_width + ui.spacing().scroll.bar_outer_margin;
                        ui.set_max_width(ui.available_width() - bar - 4.0);
                        ui.label(
                            RichText::new(format!(
                                "{}. {}",
                                session.step + 1,
                                step.title.get(lang)
                            ))
                            .strong()
                            .size(TEXT_SIZE + 4.0),
                        );
                        ui.add_space(6.0);
                        text_ui(ui, step.text.get(lang), TEXT_SIZE);
                        egui::Frame::group(ui.style()).show(ui, |ui| {
                            ui.label(
                                RichText::new(tr(lang, "lesson.try_this"))
                                    .strong()
                                    .size(TEXT_SIZE),
                            );
                            text_ui(ui, step.try_this.get(lang), TEXT_SIZE);
                        });
                        if let Some((p, lines)) = below {
                            ui.add_space(8.0);
                            ui.label(RichText::new(tr(lang, "lesson.plot_title")).strong());
                            ui.allocate_ui(
                                egui::vec2(ui.available_width(), PLOT_BELOW_HEIGHT),
                                |ui| {
                                    plot_out.extend(
                                        plot_ui(ui, p, lines, lang, hovered_column, false, room)
                                            .into_iter()
                                            .map(Into::into),
                                    );
                                },
                            );
                        }
                    });
            },
        );
        if let Some((p, lines)) = plot {
            ui.separator();
            ui.allocate_ui_with_layout(
                egui::vec2(ui.available_width(), height),
                egui::Layout::top_down(egui::Align::Min),
                |ui| {
                    ui.set_max_width(ui.available_width() - 8.0);
                    ui.set_max_height(height);
                    plot_out.extend(
                        plot_ui(ui, p, lines, lang, hovered_column, false, room)
                            .into_iter()
                            .map(Into::into),
                    );
                },
            );
        }
    });
    let mut all: Vec<AppCommand> = out.into_iter().map(Into::into).collect();
    all.extend(plot_out);
    all
}

/// The list of steps (on a wide window), the current one scrolled into view once.
fn steps_list_ui(
    ui: &mut Ui,
    session: &Session,
    lang: Lang,
    [width, height]: [f32; 2],
    out: &mut Vec<LessonCommand>,
) {
    ui.allocate_ui_with_layout(
        egui::vec2(width, height),
        egui::Layout::top_down(egui::Align::Min),
        |ui| {
            egui::ScrollArea::vertical()
                .id_salt("lesson-steps")
                .auto_shrink([false, false])
                .show(ui, |ui| {
                    for (i, s) in session.lesson.steps.iter().enumerate() {
                        let label = format!("{}. {}", i + 1, s.title.get(lang));
                        let r = ui.selectable_label(i == session.step, label);
                        if r.clicked() && i != session.step {
                            out.push(LessonCommand::Go(i));
                        }
                        // Scroll the current step into view once when it changes (the
                        // list's own scratch memory), so the user can still scroll it.
                        let id = ui.make_persistent_id("lesson-steps-scrolled");
                        if i == session.step && ui.data(|d| d.get_temp::<usize>(id)) != Some(i) {
                            r.scroll_to_me(Some(egui::Align::Center));
                            ui.data_mut(|d| d.insert_temp(id, i));
                        }
                    }
                });
        },
    );
}

/// Presentation mode's strip: "n / N", the step's title in large print and its first
/// paragraph, with Previous and Next (a clicker's Page Up / Page Down do the same).
pub fn lesson_strip_ui(
    ui: &mut Ui,
    session: &Session,
    lang: Lang,
    size: f32,
) -> Vec<LessonCommand> {
    let mut out = Vec::new();
    let step = &session.lesson.steps[session.step];
    ui.horizontal(|ui| {
        stepper_ui(ui, session, lang, size * 0.8, &mut out);
        ui.separator();
        // The title wraps rather than run off the window.
        ui.add(
            egui::Label::new(
                RichText::new(step.title.get(lang))
                    .strong()
                    .size(size)
                    .color(egui::Color32::WHITE),
            )
            .wrap(),
        );
    });
    let short = match &step.summary {
        Some(s) => Some(text::plain(s.get(lang))),
        None => match blocks(step.text.get(lang)).into_iter().next() {
            Some(Block::Paragraph(spans)) => {
                let p: String = spans.into_iter().map(|s| s.text).collect();
                Some(first_sentence(&p).to_string())
            }
            _ => None,
        },
    };
    if let Some(first) = short {
        ui.add(
            egui::Label::new(
                RichText::new(first)
                    .size(size * 0.8)
                    .color(egui::Color32::LIGHT_GRAY),
            )
            .wrap(),
        );
    }
    out
}

/// The first sentence of a paragraph (up to ". " or "。"), for the presentation strip.
///
/// ```
/// use barylab::app::panels::lessons::first_sentence;
/// assert_eq!(first_sentence("One w. Two."), "One w.");
/// assert_eq!(first_sentence("一句。两句。"), "一句。");
/// ```
pub fn first_sentence(p: &str) -> &str {
    let en = p.find(". ").map(|i| i + 1);
    let zh = p.find('。').map(|i| i + '。'.len_utf8());
    match (en, zh) {
        (Some(a), Some(b)) => &p[..a.min(b)],
        (Some(a), None) | (None, Some(a)) => &p[..a],
        (None, None) => p,
    }
}
