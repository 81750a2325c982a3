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

use egui::Ui;

use crate::app::BaryApp;
use crate::app::command::AppCommand;
use crate::app::command::LessonCommand;
use crate::app::document::history::History;
use crate::app::document::state::{AppState, StateCommand};
use crate::app::panels::banner::Banner;
use crate::app::services::dialog::{DialogOutcome, NativeDialog};
use crate::i18n::{Lang, tr};
use crate::lesson::{InspectorSection, Lesson, LessonPlot, StepState};

mod formula;
mod panel;

pub use panel::{PanelPlot, first_sentence, lesson_panel_ui, lesson_strip_ui};

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
            let most = height * PLOT_ROOM_SHARE;
            out.extend(lesson_panel_ui(ui, session, lang, plot, &mut hovered, most));
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
/// The most of the window's height the Lessons panel grows to for its plot (a little under its
/// largest share): the canvas and the 3D view beside it keep room for their labels (at
/// 1024x768, text size 1.5, the 3D view's corner labels otherwise crowded each other).
const PLOT_ROOM_SHARE: f32 = 0.46;
/// The Lessons panel's smallest height in points.
const PANEL_MIN: f32 = 120.0;

impl BaryApp {
    /// The open lesson's current step (0-based), if a lesson is open.
    pub fn lesson_step(&self) -> Option<usize> {
        self.lessons.session.as_ref().map(|s| s.step)
    }
}
