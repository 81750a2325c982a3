//! The classroom app: drag the quad, flip affine/perspective, hover a pixel to read its
//! derivation.
//!
//! How it fits together: panels read the state and return commands; [`BaryApp::show`] lays the
//! panels out and then applies every command of the frame in one place, in order.
//!
//! - [`document`]: the scene and the view settings ([`document::state`], changed by
//!   [`document::state::StateCommand`]), their edits and presets (no egui), the undo history
//!   and what is saved between runs ([`document::persist`]); [`AppOptions`] (the command line's
//!   choices).
//! - [`command::AppCommand`]: one enum for every panel's requests; each part has its own
//!   `*Command` enum (`StateCommand`, `FileCommand`, `ExportCommand`, `BenchCommand`,
//!   `LessonCommand`) that converts into it.
//! - [`panels`]: one per file, each a `*_ui` function that takes what it shows and returns
//!   commands (the top bar, File menu, typed-path window, banner, controls, canvas, inspector,
//!   presentation card and magnifier, status line, help, export, export animation, benchmark,
//!   lessons, row plot,
//!   GPU view, image compare, 3D view, samples and tie-rule controls).
//! - [`services`]: behind the panels: the canvas's renders and their cache, the scene's
//!   texture, the pixel reports (one prober per render), opening files (all checked first),
//!   native dialogs, window screenshots, text sizes, the language the panels show, and the
//!   recorder (a drag's states) with the animation export's thread.
//! - Here: `window` (eframe), `apply` (the frame's commands carried out), `layout` (side
//!   panels, canvas, presentation; `side_panels` is the arithmetic), `shortcuts` (the keyboard)
//!   and `access` (what tests read).
//!
//! The overlays and the difference heatmap are described in [`crate::figure`], which the
//! exported figures share.

pub mod document;
pub mod panels;
pub mod services;

pub(crate) mod access;
mod apply;
pub mod command;
mod options;
pub use options::AppOptions;
pub(crate) mod language;
pub(crate) mod layout;
pub(crate) mod shortcuts;
pub(crate) mod side_panels;
mod window;

pub use window::run;

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

use self::command::AppCommand;
use self::command::FileCommand;
use self::document::persist::RecentFiles;
use self::document::persist::{STORAGE_KEY, SavedState};
use self::document::state::AppState;
use self::panels::banner::Banner;
use self::panels::bench_panel::BenchPanel;
use self::panels::canvas::CanvasState;
use self::panels::export::ExportPanel;
use self::panels::file_menu::FilePicker;
use self::panels::status::{Cause, FrameTiming, Message};
use self::services::files::OpenedFile;
use self::services::reports::PixelReports;
use self::services::screenshot::StartupShot;
use self::services::textures::{TextureCache, texture_key};
use self::side_panels::Side;
use crate::i18n::Lang;
use crate::raster::Texture;

/// For the terminal, in English like every command-line message.
const SAVE_STATE_FAILED: &str = "could not save the app's state";

/// Errors that stop the app.
#[derive(Debug, thiserror::Error)]
pub enum AppError {
    /// eframe could not open the window: its message.
    #[error("cannot open the window: {0}")]
    Window(String),
    /// The startup screenshot (`--screenshot`) could not be taken or written.
    #[error("screenshot {path}: {message}")]
    Screenshot {
        /// The PNG file asked for.
        path: String,
        /// What went wrong.
        message: String,
    },
}

/// The app.
pub struct BaryApp {
    state: AppState,
    canvas: CanvasState,
    /// This frame's commands, applied at its end ([`BaryApp::apply_commands`]).
    commands: Vec<AppCommand>,
    textures: TextureCache,
    help_open: bool,
    message: Option<Message>,
    timing: FrameTiming,
    persist: bool,
    /// Where the state is kept atomically besides eframe's storage (the real app only).
    state_file: Option<PathBuf>,
    screenshot: Option<StartupShot>,
    reports: PixelReports,
    applied_zoom: Option<f32>,
    styled: bool,
    picker: FilePicker,
    recent: RecentFiles,
    banner: Option<Banner>,
    bench: BenchPanel,
    export: ExportPanel,
    /// File > Export animation… and the recorder.
    animation: panels::export_animation::AnimationPanel,
    /// Presentation mode: panels hidden, the pixel card in large print.
    presenting: bool,
    /// Presentation mode shows the 3D view in the picture's place (V; narrow windows only).
    space_full: bool,
    /// This frame's presentation layout offers V (the 3D view is on, the window narrow).
    space_toggle_offered: bool,
    /// The preset loaded last (Page Down / Page Up step on from it).
    last_preset: Option<document::presets::Preset>,
    /// What presentation mode's boxes must not hide, for the render shown.
    corner_marks: std::cell::RefCell<panels::corners::MarkCache>,
    /// The side panel asked for last: it gets the room when both do not fit.
    panel_first: Side,
    /// The side panel the user opened, which opens even where the canvas's share leaves no
    /// room (the canvas gives way), until it is folded again.
    panel_forced: Option<Side>,
    history: document::history::History,
    /// The scene file the scene came from or was saved to last (File > Save writes it).
    scene_file: Option<PathBuf>,
    /// The language chosen (English when Chinese was asked for but no CJK font is installed).
    lang: Lang,
    /// Whether egui has a font with Chinese glyphs.
    fonts: services::locale::Fonts,
    /// The open lesson (with the user's own state set aside) and the lesson file dialog.
    lessons: panels::lessons::Lessons,
    /// The GPU view's context, GL objects and last comparison.
    gpu_view: panels::gpu_view::GpuView,
    /// The image compared with the canvas's render (File > Compare with image…).
    compare_image: Option<panels::compare_image::ImageCompare>,
    /// The 3D view's orbit and scene.
    space_view: panels::space_view::SpaceView,
    /// Where the magnifier's column beside the canvas was laid out last, if it was.
    magnifier_rect: Option<egui::Rect>,
    /// The texture views' pictures (texture space, level of detail).
    texel_view: panels::texel_view::TexelViewPanel,
    /// The quiz on the pinned pixel, if one is going on.
    quiz: panels::quiz::Quiz,
}

impl BaryApp {
    /// Creates the app: restores the saved state (if `options.persist`), then opens
    /// `options.scene` if given.
    pub fn new(storage: Option<&dyn eframe::Storage>, options: AppOptions) -> Self {
        Self::new_with_state_file(storage, options, None)
    }

    /// [`BaryApp::new`] that also keeps its state in `state_file` (see
    /// [`document::persist::state_file`]): read first on start, written atomically on save.
    pub fn new_with_state_file(
        storage: Option<&dyn eframe::Storage>,
        options: AppOptions,
        state_file: Option<PathBuf>,
    ) -> Self {
        let mut message = None;
        let mut lang = options.system_lang;
        let mut state = AppState::default();
        let mut recent = RecentFiles::default();
        let mut export_settings = document::export_settings::ExportSettings::default();
        let state_file = state_file.filter(|_| options.persist);
        let from_file = state_file
            .as_deref()
            .and_then(document::persist::read_state_file);
        if options.persist
            && let Some(saved) = from_file
                .or_else(|| storage.and_then(|s| eframe::get_value::<SavedState>(s, STORAGE_KEY)))
        {
            let restored = saved.restore();
            (state, recent, export_settings) = (restored.state, restored.recent, restored.export);
            lang = restored.lang.unwrap_or(lang);
            if let Some(e) = restored.error {
                message = Some(Message::error(
                    lang.tr_with("app.restore_failed", &[("error", &e)]),
                    None,
                ));
            }
        }
        let lang = options.lang.unwrap_or(lang);
        if let Some(size) = options.text_size {
            state.view.ui_scale = size;
        }
        if let Some((compare, gpu)) = options.compare {
            (state.view.compare, state.view.gpu) = (compare, gpu);
        }
        if options.space_view {
            state.view.space = true;
        }
        if let Some((scene, dir)) = options.scene {
            state.scene = scene;
            state.scene_dir = Some(dir);
            state.view.pinned = None;
        }
        let mut app = Self {
            state,
            canvas: CanvasState::default(),
            commands: Vec::new(),
            textures: TextureCache::default(),
            help_open: false,
            message,
            timing: FrameTiming::default(),
            persist: options.persist,
            state_file,
            screenshot: options.screenshot.clone().map(StartupShot::new),
            reports: PixelReports::default(),
            applied_zoom: None,
            styled: false,
            picker: FilePicker::default(),
            recent,
            banner: None,
            bench: BenchPanel::default(),
            export: ExportPanel::new(export_settings),
            animation: Default::default(),
            presenting: options.present,
            space_full: false,
            space_toggle_offered: false,
            last_preset: None,
            corner_marks: Default::default(),
            panel_first: Side::default(),
            panel_forced: None,
            history: document::history::History::default(),
            scene_file: None,
            lang,
            fonts: services::locale::Fonts::new(options.no_cjk_font),
            lessons: panels::lessons::Lessons::default(),
            gpu_view: panels::gpu_view::GpuView::new(options.screenshot.is_some()),
            space_view: panels::space_view::SpaceView::default(),
            magnifier_rect: None,
            texel_view: Default::default(),
            compare_image: None,
            quiz: panels::quiz::Quiz::default(),
        };
        if let Some(path) = &options.compare_image {
            app.push(FileCommand::CompareImage(path.clone()));
            if let Some(c) = options.compare_background {
                app.push(FileCommand::SetCompareBackground(c));
            }
        }
        if let Some(opened) = options.opened {
            app.opened(opened);
        }
        if let Some((lesson, step)) = options.lesson {
            app.enter_lesson(lesson, step);
        }
        if let Some(kind) = options.animation_window {
            app.push(command::AnimationCommand::Open);
            app.push(command::AnimationCommand::SetKind(kind));
        }
        if let Some(p) = options.pin {
            app.push(document::state::StateCommand::Pin(Some(p)));
        }
        app.quiz.answers = options.quiz_answers;
        if let Some(e) = options.startup_error {
            app.set_error(e);
        }
        app
    }

    /// Saves the scene (at the size the canvas renders it) to `path`; the outcome goes to the
    /// status line.
    pub fn save_scene(&mut self, path: &Path) {
        let mut scene = self.state.scene.clone();
        if let Some(out) = &self.canvas.output {
            scene.set_size(out.size[0], out.size[1]);
        }
        match services::files::save(path, &scene, self.state.scene_dir.as_deref(), self.lang) {
            Ok(done) => {
                self.message = Some(Message::note(done));
                self.scene_file = Some(path.to_path_buf());
                self.recent.push(path);
            }
            Err(e) => self.set_error(e),
        }
    }

    /// Applies a file that loaded.
    fn opened(&mut self, opened: OpenedFile) {
        if matches!(opened.what, services::files::Opened::Scene { .. }) {
            // A model is not a scene file: Save asks where.
            self.scene_file = opened
                .path
                .extension()
                .is_some_and(|e| e == "json")
                .then(|| opened.path.clone());
        }
        self.commands.push(opened.command().into());
        self.textures.pending = Some(opened.texture.clone());
        self.recent.push(&opened.path);
        self.banner = Some(Banner::opened(&opened, self.lang));
        self.message = None;
    }

    /// Opens a scene (.json), a model (.obj) or an image (it becomes the texture), as the File
    /// menu and drag-and-drop do. Everything is loaded and checked first: on failure the
    /// current scene stays exactly as it was and the banner names the file and the problem.
    pub fn open_file(&mut self, path: &Path) {
        match services::files::open(path, &self.state.scene, self.lang) {
            Ok(opened) => self.opened(opened),
            Err(e) => self.banner = Some(Banner::failed(e, self.lang)),
        }
    }

    /// Opens a file (see [`BaryApp::open_file`]).
    pub fn open_scene(&mut self, path: &Path) {
        self.open_file(path);
    }

    fn set_error(&mut self, text: String) {
        self.message = Some(Message::error(text, None));
    }

    /// The whole UI, inside the given `Ui` (eframe's root `Ui`, or a test harness's).
    pub fn show(&mut self, ui: &mut egui::Ui) {
        let start = Instant::now();
        let ctx = ui.ctx().clone();
        if !self.styled {
            services::style::apply_style(&ctx);
            self.styled = true;
        }
        self.sync_lang(&ctx);
        services::style::sync_zoom(&ctx, &mut self.applied_zoom, &mut self.state.view.ui_scale);
        self.commands.extend(shortcuts::shortcuts(
            &ctx,
            &shortcuts::ShortcutInput {
                state: &self.state,
                canvas_size: self.canvas.output.as_ref().map(|o| o.size),
                help_open: self.help_open,
                export_open: self.export.open,
                presenting: self.presenting,
                last_preset: self.last_preset,
                lesson_open: self.lessons.session.is_some(),
            },
        ));
        // Files dropped on the window, or picked in the Open dialog.
        let dropped: Vec<PathBuf> = ctx.input(|i| {
            i.raw
                .dropped_files
                .iter()
                .map(|f| f.path().to_path_buf())
                .collect()
        });
        self.commands
            .extend(dropped.into_iter().map(|p| FileCommand::Open(p).into()));
        self.commands.extend(self.picker.poll().map(Into::into));
        self.commands.extend(self.lessons.poll().map(Into::into));

        let (texture, texture_error) = self.textures.get(
            &self.state.scene,
            self.state.scene_dir.as_deref(),
            self.lang,
        );
        let key = texture_key(&self.state.scene, self.state.scene_dir.as_deref());
        match texture_error {
            Some(e) => self.message = Some(Message::error(e, Some(Cause::Texture(key)))),
            None => panels::status::clear_if(
                &mut self.message,
                |c| matches!(c, Cause::Texture(k) if *k != key),
            ),
        }
        let hover_before = self.canvas.hover;
        self.quiz.sync(self.lesson_quiz(), self.state.view.pinned);
        panels::quiz::set_hidden_pixel(&ctx, self.quiz.hidden());
        self.panels(ui, &texture);
        let (gpu_on, mode) = (self.state.view.gpu, self.state.options().mode);
        if self
            .gpu_view
            .update(gpu_on, self.canvas.output.as_ref(), mode, &texture)
        {
            ctx.request_repaint();
        }
        let held = ctx.input(|i| i.pointer.any_down());
        if self.compare_image_frame(&ctx, &texture, held) {
            ctx.request_repaint();
        }

        let reports_before = self.reports.key();
        let error = self.reports.update(
            self.canvas.output.as_ref(),
            &texture,
            self.state.options().mode,
            [self.canvas.hover, self.state.view.pinned],
            self.lang,
        );
        match error {
            Some(e) => self.message = Some(Message::error(e, Some(Cause::Probe))),
            None => panels::status::clear_if(&mut self.message, |c| *c == Cause::Probe),
        }
        if self.canvas.hover != hover_before || reports_before != self.reports.key() {
            // The inspector and overlay drew last frame's pixel; draw again with this one.
            ctx.request_repaint();
        }
        let outcome_before = self.export.outcome.clone();
        let picked = self.export.frame(&ctx);
        self.export_message(&ctx, outcome_before);
        self.commands.splice(0..0, command::all(picked));
        // (Only a frame with commands can change the scene; a scene can be large.)
        let before =
            (!self.commands.is_empty()).then(|| document::history::Snapshot::of(&self.state));
        self.apply_commands(&ctx, &texture);
        self.animation_frame(&ctx, &texture);
        // A drag (a button held) is one undo step, taken when it is released.
        let held = ctx.input(|i| i.pointer.any_down());
        self.history.track(before, &self.state, held);
        self.timing.ui_ms = start.elapsed().as_secs_f64() * 1e3;
        if let Some(shot) = &mut self.screenshot {
            let gpu = self
                .gpu_view
                .settled(gpu_on, self.canvas.output.as_ref(), mode);
            let image = self
                .compare_image
                .as_ref()
                .is_none_or(|ic| ic.settled(self.canvas.output.as_ref(), mode));
            // Not while a render runs on: the picture shown is an older one. A render that
            // failed (over the memory budget) is shot with its message in the picture's place.
            let drawn = (self.canvas.output.is_some() || self.canvas.error.is_some())
                && self.canvas.underway().is_none();
            shot.step(&ctx, drawn && gpu && image);
        }
    }

    /// Lays out the panels and windows; collects their commands.
    fn panels(&mut self, ui: &mut egui::Ui, texture: &Arc<Texture>) {
        let lang = self.lang;
        let ctx = ui.ctx().clone();
        let mut out: Vec<AppCommand> = Vec::new();
        if self.presenting {
            self.lesson_strip(ui, &mut out);
            if self.quiz.session.is_some() {
                self.quiz_presenting(ui, texture, &mut out);
            } else if !self.space_panel_presenting(ui) {
                if self.texel_panel_presenting(ui, texture) {
                    self.present_plot_band(ui, texture, &mut out);
                    let framing =
                        panels::canvas_layout::Framing::presenting(self.state.view.compare);
                    self.canvas_panel(ui, texture, framing, &mut out);
                } else {
                    self.presentation(ui, texture, &mut out);
                }
            }
            self.commands.extend(out);
            return;
        }
        egui::Panel::top("top").show(ui, |ui| {
            out.extend(panels::top_bar::top_bar_ui(
                ui,
                &panels::top_bar::TopBarInput {
                    state: &self.state,
                    recent: &self.recent,
                    dialog_waiting: self.picker.waiting(),
                    export_open: self.export.open,
                    help_open: self.help_open,
                    bench_open: self.bench.open,
                    presenting: self.presenting,
                    cjk_font: self.fonts.cjk,
                    lesson_open: self.lessons.session.is_some(),
                    lang: self.lang,
                },
            ));
        });
        panels::banner::expire_banner(&ctx, &mut self.banner);
        if let Some(b) = &self.banner {
            egui::Panel::top("banner").show(ui, |ui| {
                out.extend(command::all(panels::banner::banner_ui(ui, b)));
            });
        }
        out.extend(command::all(panels::path_window::path_window_ui(
            &ctx,
            &self.picker.path_window,
        )));
        if let Some((view, folder_text)) = self.export.view() {
            out.extend(command::all(panels::export::export_ui(
                &ctx,
                &view,
                folder_text,
            )));
        }
        self.animation_window(&ctx, &mut out);
        egui::Panel::bottom("status").show(ui, |ui| {
            panels::status::status_ui(
                ui,
                &self.state,
                &self.canvas,
                self.timing,
                self.message.as_ref(),
            );
        });
        self.lesson_panel(ui, texture, &mut out);
        self.side_panels_ui(ui, &mut out);
        self.quiz_docked(ui, &mut out);
        self.magnifier_docked(ui);
        self.canvas.avoid.clear();
        // The 3D view shows the pinned pixel's a, b, c: not during a quiz before Reveal.
        let quiz_hides = self.quiz.hidden().is_some();
        if quiz_hides || !self.space_enlarged(ui, &mut out) {
            if !quiz_hides {
                self.space_panel(ui, &mut out);
                self.texel_panel(ui, texture);
            }
            self.canvas_panel(
                ui,
                texture,
                panels::canvas_layout::Framing::NORMAL,
                &mut out,
            );
        }
        self.plot_window(&ctx, texture, &mut out);
        self.quiz_window(&ctx, &mut out);
        let mut help_open = self.help_open;
        egui::Window::new(lang.tr("app.help.title"))
            .id(egui::Id::unique("help-window"))
            .open(&mut help_open)
            .default_width(620.0)
            .show(&ctx, panels::help::help_ui);
        if help_open != self.help_open {
            out.push(AppCommand::SetHelpOpen(help_open));
        }
        self.bench.frame(&ctx);
        out.extend(command::all(panels::bench_panel::bench_ui(
            &ctx,
            &self.bench,
        )));
        self.commands.extend(out);
    }
}
