//! The Lessons panel: the steps of a lesson ([`crate::lesson`]), the step's text and "try
//! this", Previous / Next, "reset this step" and leaving; the presentation strip; the top
//! bar's Lessons menu. Panels take what they show and return [`LessonCommand`]s; the app
//! applies them (`BaryApp::apply_lesson`).
//!
//! Opening a lesson sets the user's own scene, settings, undo history and scene file aside;
//! leaving brings them back exactly. Step changes are not edits: they never enter the undo
//! history (undo inside a lesson undoes the user's own edits on the step, and "reset this
//! step" puts the whole step back).

use std::path::PathBuf;

use egui::{RichText, Ui};

use crate::app::BaryApp;
use crate::app::command::AppCommand;
use crate::app::command::LessonCommand;
use crate::app::document::history::History;
use crate::app::document::state::{AppState, StateCommand};
use crate::app::panels::banner::Banner;
use crate::app::panels::plots::{PlotLines, plot_ui};
use crate::app::services::dialog::{DialogOutcome, NativeDialog};
use crate::i18n::{Lang, tr};
use crate::lesson::text::{self, Block, blocks};
use crate::lesson::{InspectorSection, Lesson, LessonPlot, StepState};

mod formula;

/// What the user had before the lesson, put back on leaving.
#[derive(Debug)]
struct SetAside {
    state: AppState,
    history: History,
    scene_file: Option<PathBuf>,
    last_preset: Option<crate::app::document::presets::Preset>,
}

/// An open lesson.
#[derive(Debug)]
pub struct Session {
    /// The lesson.
    pub lesson: Lesson,
    /// The current step (0-based).
    pub step: usize,
    user: SetAside,
}

/// The app's lesson part: the open lesson, if any, and the lesson file dialog.
#[derive(Default)]
pub struct Lessons {
    /// The open lesson.
    pub session: Option<Session>,
    dialog: NativeDialog,
    /// The inspector sections the step opens, until the inspector has shown them.
    pub open_sections: Option<Vec<InspectorSection>>,
    /// The plot row rendered with every buffer (`crate::app::panels::plots`).
    pub row_render: crate::app::panels::plots::RowRender,
    /// The plot column hovered this frame.
    pub plot_hover: Option<u32>,
    /// The window height (points) the Lessons panel was last shown in and its share of it:
    /// the panel keeps its share when the window or the text size changes.
    panel_share: Option<(f32, f32)>,
    /// Where the Lessons panel was laid out last.
    pub(in crate::app) panel_rect: Option<egui::Rect>,
}

impl Lessons {
    /// The user's own state while a lesson is open (what is saved between runs).
    pub fn user_state(&self) -> Option<&AppState> {
        self.session.as_ref().map(|s| &s.user.state)
    }

    /// What the picked lesson file asks for, once the dialog has closed.
    pub fn poll(&mut self) -> Option<LessonCommand> {
        match self.dialog.poll()? {
            DialogOutcome::Picked(path) => Some(LessonCommand::OpenFile(path)),
            DialogOutcome::Cancelled | DialogOutcome::Failed => None,
        }
    }
}

/// Sets what a step sets: the scene (at the step's size, with its mode, shading, filter and
/// wireframe), the comparison, rasterizer, overlays, pixel size, pin, plot, the 3D view and the texture view. The image keeps
/// the step's size (not the window's), so the pin is the step's pixel.
pub fn apply_step(state: &mut AppState, step: &StepState) {
    state.scene = step.scene.clone();
    state.scene_dir = step.scene_dir.clone();
    let v = &mut state.view;
    v.compare = step.compare;
    v.wipe = 0.5;
    v.rasterizer = step.rasterizer;
    v.show_grid = step.overlays.grid;
    v.show_handles = step.overlays.handles;
    v.show_sub_areas = step.overlays.sub_areas;
    v.pixel_size = step.pixel_size;
    v.fit_window = false;
    v.pinned = step.pin;
    v.plot = step.plot;
    v.space = step.space_view;
    v.samples_view = step.samples_view;
    v.texel = step.texture_view;
}

impl BaryApp {
    /// Applies a lesson command.
    pub(in crate::app) fn apply_lesson(&mut self, ctx: &egui::Context, command: LessonCommand) {
        let lang = self.lang();
        let opened = match command {
            LessonCommand::SectionsShown => {
                self.lessons.open_sections = None;
                None
            }
            LessonCommand::OpenBuiltin => Some(Lesson::builtin()),
            LessonCommand::OpenFile(ref path) => Some(Lesson::open(path)),
            LessonCommand::OpenDialog => {
                let title = tr(lang, "lesson.open_file");
                let started = self.lessons.dialog.open(ctx, "lesson dialog", move || {
                    rfd::FileDialog::new()
                        .set_title(title)
                        .add_filter("JSON", &["json"])
                        .pick_file()
                });
                if let Err(e) = started {
                    self.banner = Some(Banner::failed(
                        format!("{}: {e}", tr(lang, "lesson.failed")),
                        lang,
                    ));
                }
                None
            }
            _ => None,
        };
        if let Some(result) = opened {
            match result {
                Ok(lesson) => self.enter_lesson(lesson, 0),
                Err(e) => self.banner = Some(Banner::failed(e.to_string(), lang)),
            }
            return;
        }
        let Some(session) = &self.lessons.session else {
            return;
        };
        let (step, last) = (session.step, session.lesson.steps.len().saturating_sub(1));
        match command {
            LessonCommand::Go(n) => self.go_to_step(n.min(last)),
            LessonCommand::Next => self.go_to_step((step + 1).min(last)),
            LessonCommand::Previous => self.go_to_step(step.saturating_sub(1)),
            LessonCommand::Reset => self.go_to_step(step),
            LessonCommand::Leave => self.leave_lesson(),
            _ => {}
        }
    }

    /// Opens `lesson` at step `step` (0-based), setting the user's own state aside (a lesson
    /// already open keeps what it set aside).
    pub fn enter_lesson(&mut self, lesson: Lesson, step: usize) {
        let user = match self.lessons.session.take() {
            Some(s) => s.user,
            None => SetAside {
                state: self.state.clone(),
                history: std::mem::take(&mut self.history),
                scene_file: self.scene_file.take(),
                last_preset: self.last_preset,
            },
        };
        self.lessons.session = Some(Session { lesson, step, user });
        self.go_to_step(step);
    }

    /// Sets step `n`'s state; the undo history starts afresh for the step.
    fn go_to_step(&mut self, n: usize) {
        let Some(session) = &mut self.lessons.session else {
            return;
        };
        let Some(state) = session.lesson.state(n) else {
            return;
        };
        session.step = n;
        apply_step(&mut self.state, &state);
        self.lessons.open_sections = Some(state.inspector.clone());
        self.history = History::default();
        self.history.skip_frame();
    }

    /// Leaves the lesson: the user's scene, settings, undo history and scene file come back.
    pub fn leave_lesson(&mut self) {
        if let Some(s) = self.lessons.session.take() {
            self.state = s.user.state;
            self.history = s.user.history;
            self.history.skip_frame();
            self.scene_file = s.user.scene_file;
            self.last_preset = s.user.last_preset;
            self.lessons.open_sections = None;
        }
    }
}

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
pub fn lesson_panel_ui(
    ui: &mut Ui,
    session: &Session,
    lang: Lang,
    plot: PanelPlot,
    hovered_column: &mut Option<u32>,
) -> Vec<AppCommand> {
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
                                        plot_ui(ui, p, lines, lang, hovered_column, false)
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
                        plot_ui(ui, p, lines, lang, hovered_column, false)
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

/// The top bar's Lessons menu: the built-in lesson, a lesson file, leaving the open one, and
/// showing or hiding the plot of the pinned pixel's row (`plot`: the one shown).
pub fn lessons_menu_ui(
    ui: &mut Ui,
    open: bool,
    plot: Option<LessonPlot>,
    lang: Lang,
) -> Vec<AppCommand> {
    let mut out: Vec<LessonCommand> = Vec::new();
    let mut plot_out: Vec<AppCommand> = Vec::new();
    ui.menu_button(tr(lang, "lesson.menu"), |ui| {
        if ui.button(tr(lang, "lesson.open_builtin")).clicked() {
            out.push(LessonCommand::OpenBuiltin);
            ui.close();
        }
        // The other built-in lessons of the registry, by name.
        for b in crate::lesson::builtin::LESSONS.iter().skip(1) {
            if ui
                .button(tr(lang, &format!("lesson.open_{}", b.name)))
                .clicked()
            {
                out.push(LessonCommand::OpenFile(b.name.into()));
                ui.close();
            }
        }
        if ui.button(tr(lang, "lesson.open_file")).clicked() {
            out.push(LessonCommand::OpenDialog);
            ui.close();
        }
        if open && ui.button(tr(lang, "lesson.leave")).clicked() {
            out.push(LessonCommand::Leave);
            ui.close();
        }
        ui.separator();
        let label = if plot.is_some() {
            "lesson.plot_hide"
        } else {
            "lesson.plot_show"
        };
        if ui.button(tr(lang, label)).clicked() {
            let next = match plot {
                Some(_) => None,
                None => Some(LessonPlot::UvRow),
            };
            plot_out.push(StateCommand::SetPlot(next).into());
            ui.close();
        }
    });
    let mut all: Vec<AppCommand> = out.into_iter().map(Into::into).collect();
    all.extend(plot_out);
    all
}

impl BaryApp {
    /// The Lessons panel under the canvas, when a lesson is open.
    pub(in crate::app) fn lesson_panel(
        &mut self,
        ui: &mut Ui,
        texture: &crate::raster::Texture,
        out: &mut Vec<AppCommand>,
    ) {
        let lang = self.lang();
        self.lessons.panel_rect = None;
        if self.lessons.session.is_none() {
            return;
        }
        let plot = self.state.view.plot.map(|p| (p, self.row_plot(texture)));
        let Some(session) = &self.lessons.session else {
            return;
        };
        let height = ui.ctx().content_rect().height();
        let mut hovered = None;
        let panel = egui::Panel::bottom("lesson")
            .resizable(true)
            .default_size(height * PANEL_SHARE)
            .size_range(PANEL_MIN..=height * PANEL_MAX_SHARE);
        // egui keeps a panel's size in points: after a new window or text size the panel
        // would keep the points it had (half the window once the text is larger), so it gets
        // its share of the new height back.
        let panel = match self.lessons.panel_share {
            Some((h, share)) if (h - height).abs() > 0.5 => {
                panel.exact_size((height * share).clamp(PANEL_MIN, height * PANEL_MAX_SHARE))
            }
            _ => panel,
        };
        let shown = panel.show(ui, |ui| {
            out.extend(lesson_panel_ui(ui, session, lang, plot, &mut hovered));
        });
        self.lessons.panel_share = Some((height, shown.response.rect.height() / height.max(1.0)));
        self.lessons.panel_rect = Some(shown.response.rect);
        self.lessons.plot_hover = hovered;
    }

    /// Presentation mode's lesson strip under the canvas, when a lesson is open.
    pub(in crate::app) fn lesson_strip(&mut self, ui: &mut Ui, out: &mut Vec<AppCommand>) {
        let lang = self.lang();
        let Some(session) = &self.lessons.session else {
            return;
        };
        let size = crate::app::panels::present::strip_text(ui.ctx().content_rect().height());
        egui::Panel::bottom("lesson-strip")
            .frame(
                egui::Frame::new()
                    .fill(crate::app::panels::present::CARD_FILL)
                    .inner_margin(egui::Margin::symmetric(10, 6)),
            )
            .resizable(false)
            .show(ui, |ui| {
                out.extend(crate::app::command::all(lesson_strip_ui(
                    ui, session, lang, size,
                )));
            });
    }
}

/// The Lessons panel's share of the window height at first, and at most.
const PANEL_SHARE: f32 = 0.3;
const PANEL_MAX_SHARE: f32 = 0.5;
/// The Lessons panel's smallest height in points.
const PANEL_MIN: f32 = 120.0;

impl BaryApp {
    /// The open lesson's current step (0-based), if a lesson is open.
    pub fn lesson_step(&self) -> Option<usize> {
        self.lessons.session.as_ref().map(|s| s.step)
    }
}
