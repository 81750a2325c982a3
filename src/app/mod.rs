//! The classroom app: drag the quad, flip affine/perspective, hover a pixel to read its
//! derivation.
//!
//! One panel per file, each with a `*_ui` function and its strings in one place: [`canvas`],
//! [`controls`], [`inspector`], [`status`], [`help`], [`bench_panel`],
//! [`export`]. Panels read the [`state::AppState`] and
//! push [`state::Command`]s, applied once per frame. The overlays are described as plain data
//! in canvas coordinates ([`overlay`]) and painted by [`paint`]. The scene edits ([`edit`]),
//! presets ([`presets`]) and the difference heatmap ([`heatmap`]) do not depend on egui.

pub mod bench_panel;
pub mod canvas;
pub mod controls;
pub mod edit;
pub mod export;
pub mod files;
pub mod help;
pub mod inspector;
pub mod paint;
pub mod pixel;
pub mod presets;
pub mod state;
pub mod status;

/// The overlay description and the heatmap live in [`crate::figure`] (no egui there).
pub use crate::figure::{heatmap, overlay};

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use egui::{Key, Modifiers};

use self::canvas::{CanvasInput, CanvasState};
use self::pixel::PixelReport;
use self::state::{AppState, Command, Compare, STORAGE_KEY, SavedState};
use self::status::{FrameTiming, Message};
use crate::raster::{BuiltinTexture, Texture};
use crate::scene::Scene;

/// User-facing strings of the app frame (window title, messages).
mod text {
    pub const TITLE: &str = "barylab — how a GPU interpolates across a triangle";
    pub const RESTORE_FAILED: &str = "could not restore the saved scene, using the default";
    pub const TEXTURE_FALLBACK: &str = "texture not loaded, showing the uv-grid instead";
    pub const SCREENSHOT_TIMEOUT: &str = "no screenshot arrived in time";
    pub const HELP: &str = "Help";
    pub const CONTROLS: &str = "Controls";
    pub const INSPECTOR: &str = "Inspector";
    pub const CONTROLS_TIP: &str = "Show or hide the controls panel.";
    pub const INSPECTOR_TIP: &str = "Show or hide the pixel inspector.";
    pub const HELP_TIP: &str = "Mouse and keyboard shortcuts. Key: F1";
}

/// How the app is started.
#[derive(Clone, Debug, Default)]
pub struct AppOptions {
    /// A scene to open instead of the saved one, with the folder its texture paths are
    /// relative to.
    pub scene: Option<(Scene, PathBuf)>,
    /// Save a screenshot of the first fully rendered frame to this PNG and exit.
    pub screenshot: Option<PathBuf>,
    /// A file opened on the command line ([`files::open`]), applied on start as if it had
    /// been dropped on the window (an image becomes the restored scene's texture).
    pub opened: Option<files::OpenedFile>,
    /// Restore state on start and save it on exit.
    pub persist: bool,
    /// Initial window size in points.
    pub window_size: Option<[f32; 2]>,
}

/// Errors that stop the app.
#[derive(Debug, thiserror::Error)]
pub enum AppError {
    #[error("cannot open the window: {0}")]
    Window(String),
    #[error("screenshot {path}: {message}")]
    Screenshot { path: String, message: String },
}

/// Frames to draw before taking the screenshot, so fonts, layout and the canvas texture have
/// settled.
const SCREENSHOT_AFTER_FRAMES: u32 = 5;
/// Give up on the screenshot after this long.
const SCREENSHOT_TIMEOUT: Duration = Duration::from_secs(30);
/// Side panel widths in points. Fixed, so that nothing in them (a number growing a digit)
/// can move the canvas under a dragged corner.
const CONTROLS_WIDTH: f32 = 400.0;
const INSPECTOR_WIDTH: f32 = 460.0;
/// Default window size in points.
const WINDOW_SIZE: [f32; 2] = [1500.0, 950.0];

/// Where the screenshot callback reports: `None` until the image was written (or not).
type ScreenshotResult = Arc<Mutex<Option<Result<(), String>>>>;

struct ScreenshotJob {
    path: PathBuf,
    frames: u32,
    requested: bool,
    started: Instant,
    result: ScreenshotResult,
}

/// The textures scenes name, loaded once.
#[derive(Default)]
struct TextureCache {
    key: Option<(String, Option<PathBuf>)>,
    texture: Option<Arc<Texture>>,
    /// A texture already loaded while opening a file, used for the next new key.
    pending: Option<Arc<Texture>>,
}

impl TextureCache {
    /// The scene's texture; on failure the uv-grid and the error.
    fn get(&mut self, scene: &Scene, dir: Option<&Path>) -> (Arc<Texture>, Option<String>) {
        let key = (scene.texture_name().to_string(), dir.map(Path::to_path_buf));
        if self.key.as_ref() == Some(&key)
            && let Some(t) = &self.texture
        {
            return (t.clone(), None);
        }
        if let Some(t) = self.pending.take() {
            self.key = Some(key);
            self.texture = Some(t.clone());
            return (t, None);
        }
        let (texture, error) = match scene.load_texture(dir.unwrap_or(Path::new(""))) {
            Ok(t) => (t, None),
            Err(e) => (
                Texture::builtin(BuiltinTexture::UvGrid),
                Some(format!("{e}; {}", text::TEXTURE_FALLBACK)),
            ),
        };
        let texture = Arc::new(texture);
        self.key = Some(key);
        self.texture = Some(texture.clone());
        (texture, error)
    }
}

/// The app.
pub struct BaryApp {
    state: AppState,
    canvas: CanvasState,
    commands: Vec<Command>,
    textures: TextureCache,
    help_open: bool,
    message: Option<Message>,
    timing: FrameTiming,
    persist: bool,
    screenshot: Option<ScreenshotJob>,
    hover_report: Option<PixelReport>,
    pin_report: Option<PixelReport>,
    applied_zoom: Option<f32>,
    styled: bool,
    picker: files::FilePicker,
    recent: files::RecentFiles,
    banner: Option<files::Banner>,
    /// Files to open at the start of the next frame (menu, typed path).
    to_open: Vec<PathBuf>,
    /// The prober of the current render and mode (see `pixel_reports`).
    prober: Option<(
        (u64, crate::raster::Interpolation),
        crate::probe::Prober<'static>,
    )>,
    /// How many probers were made (tests check that hovering reuses one).
    probers_built: u64,
    bench: bench_panel::BenchPanel,
    export: export::ExportPanel,
}

/// Text sizes in points, large enough for a projector at zoom 1.
fn apply_style(ctx: &egui::Context) {
    use egui::{FontFamily, FontId, TextStyle};
    ctx.all_styles_mut(|style| {
        style.text_styles = [
            (
                TextStyle::Heading,
                FontId::new(26.0, FontFamily::Proportional),
            ),
            (TextStyle::Body, FontId::new(18.0, FontFamily::Proportional)),
            (
                TextStyle::Button,
                FontId::new(18.0, FontFamily::Proportional),
            ),
            (
                TextStyle::Monospace,
                FontId::new(17.0, FontFamily::Monospace),
            ),
            (
                TextStyle::Small,
                FontId::new(14.0, FontFamily::Proportional),
            ),
        ]
        .into();
        style.spacing.item_spacing = egui::vec2(8.0, 6.0);
        style.spacing.button_padding = egui::vec2(8.0, 4.0);
        style.spacing.interact_size.y = 26.0;
        style.spacing.slider_width = 180.0;
    });
    ctx.set_visuals(egui::Visuals::dark());
}

impl BaryApp {
    /// Creates the app: restores the saved state (if `options.persist`), then opens
    /// `options.scene` if given.
    pub fn new(storage: Option<&dyn eframe::Storage>, options: AppOptions) -> Self {
        let mut message = None;
        let mut state = AppState::default();
        let mut recent = files::RecentFiles::default();
        let mut export_settings = export::ExportSettings::default();
        if options.persist
            && let Some(saved) =
                storage.and_then(|s| eframe::get_value::<SavedState>(s, STORAGE_KEY))
        {
            recent = saved.recent.clone();
            export_settings = saved.export.clone();
            let (restored, error) = AppState::from_saved(saved);
            state = restored;
            if let Some(e) = error {
                message = Some(Message {
                    text: format!("{}: {e}", text::RESTORE_FAILED),
                    error: true,
                });
            }
        }
        if let Some((scene, dir)) = options.scene {
            state.scene = scene;
            state.scene_dir = Some(dir);
            state.view.pinned = None;
        }
        let screenshot = options.screenshot.map(|path| ScreenshotJob {
            path,
            frames: 0,
            requested: false,
            started: Instant::now(),
            result: Arc::new(Mutex::new(None)),
        });
        let mut app = Self {
            state,
            canvas: CanvasState::default(),
            commands: Vec::new(),
            textures: TextureCache::default(),
            help_open: false,
            message,
            timing: FrameTiming::default(),
            persist: options.persist,
            screenshot,
            hover_report: None,
            pin_report: None,
            applied_zoom: None,
            styled: false,
            picker: files::FilePicker::default(),
            recent,
            banner: None,
            to_open: Vec::new(),
            prober: None,
            probers_built: 0,
            bench: bench_panel::BenchPanel::default(),
            export: export::ExportPanel::new(export_settings),
        };
        if let Some(opened) = options.opened {
            app.opened(opened);
        }
        app
    }

    /// Applies a file that loaded.
    fn opened(&mut self, opened: files::OpenedFile) {
        self.commands.push(opened.command());
        self.textures.pending = Some(opened.texture.clone());
        self.recent.push(&opened.path);
        self.banner = Some(files::Banner::opened(&opened));
        self.message = None;
    }

    /// Opens a scene (.json), a model (.obj) or an image (it becomes the texture), as the File
    /// menu and drag-and-drop do. Everything is loaded and checked first: on failure the
    /// current scene stays exactly as it was and the banner names the file and the problem.
    pub fn open_file(&mut self, path: &Path) {
        match files::open(path, &self.state.scene) {
            Ok(opened) => self.opened(opened),
            Err(e) => self.banner = Some(files::Banner::failed(e)),
        }
    }

    /// The banner's lines (what the last opened file did, or why it did not open).
    pub fn banner(&self) -> Option<Vec<String>> {
        self.banner.as_ref().map(files::Banner::lines)
    }

    /// The recent files, newest first.
    pub fn recent_files(&self) -> &[PathBuf] {
        &self.recent.0
    }

    /// The files a dialog, the typed-path window, the recent list, drag-and-drop or the
    /// command line asked to open.
    fn open_requested(&mut self, ctx: &egui::Context) {
        let dropped: Vec<PathBuf> = ctx.input(|i| {
            i.raw
                .dropped_files
                .iter()
                .map(|f| f.path().to_path_buf())
                .collect()
        });
        self.to_open.extend(dropped);
        self.to_open.extend(self.picker.poll());
        for p in std::mem::take(&mut self.to_open) {
            self.open_file(&p);
        }
    }

    /// The Export panel (settings, last outcome).
    pub fn export_panel(&self) -> &export::ExportPanel {
        &self.export
    }

    /// Queues an Export panel command, as its widgets do.
    pub fn push_export(&mut self, command: export::ExportCommand) {
        self.export.push(command);
    }

    /// The current state (scene and view).
    pub fn state(&self) -> &AppState {
        &self.state
    }

    /// The canvas: views, renders, hovered pixel.
    /// How many probers the inspector has made (one per render and mode it traced).
    pub fn probers_built(&self) -> u64 {
        self.probers_built
    }

    pub fn canvas(&self) -> &CanvasState {
        &self.canvas
    }

    /// The report of the hovered pixel shown in the inspector.
    pub fn hover_report(&self) -> Option<&PixelReport> {
        self.hover_report.as_ref()
    }

    /// The report of the pinned pixel.
    pub fn pin_report(&self) -> Option<&PixelReport> {
        self.pin_report.as_ref()
    }

    /// Queues a command, as a panel would.
    pub fn push(&mut self, command: Command) {
        self.commands.push(command);
    }

    /// The benchmark window's state.
    pub fn bench(&self) -> &bench_panel::BenchPanel {
        &self.bench
    }

    /// The benchmark window's state, to change.
    pub fn bench_mut(&mut self) -> &mut bench_panel::BenchPanel {
        &mut self.bench
    }

    /// The message on the status line.
    pub fn message(&self) -> Option<&str> {
        self.message.as_ref().map(|m| m.text.as_str())
    }

    /// Opens a file (see [`BaryApp::open_file`]).
    pub fn open_scene(&mut self, path: &Path) {
        self.open_file(path);
    }

    fn shortcuts(&mut self, ctx: &egui::Context) {
        if ctx.egui_wants_keyboard_input() {
            return;
        }
        let none = Modifiers::NONE;
        let size = self.canvas.output.as_ref().map(|o| o.size);
        let mut cmds = Vec::new();
        let mut help = false;
        let mut open = false;
        let mut export = false;
        ctx.input_mut(|i| {
            let mut key = |k| i.consume_key(none, k);
            if key(Key::P) {
                cmds.push(Command::ToggleMode);
            }
            for (k, c) in [
                (Key::Num1, Compare::Single),
                (Key::Num2, Compare::SideBySide),
                (Key::Num3, Compare::Wipe),
                (Key::Num4, Compare::Difference),
            ] {
                if key(k) {
                    cmds.push(Command::SetCompare(c));
                }
            }
            let options = self.state.options();
            let view = &self.state.view;
            if key(Key::W) {
                cmds.push(Command::SetWireframe(!options.wireframe));
            }
            if key(Key::G) {
                cmds.push(Command::SetShowGrid(!view.show_grid));
            }
            if key(Key::H) {
                cmds.push(Command::SetShowHandles(!view.show_handles));
            }
            if key(Key::OpenBracket) {
                cmds.push(Command::SetPixelSize(smaller_pixel(view.pixel_size)));
            }
            if key(Key::CloseBracket) {
                cmds.push(Command::SetPixelSize(larger_pixel(view.pixel_size)));
            }
            if key(Key::Escape) {
                if self.help_open {
                    help = true;
                } else {
                    cmds.push(Command::Pin(None));
                }
            }
            if key(Key::Home) {
                cmds.push(Command::ResetCamera);
            }
            if key(Key::F1) {
                help = true;
            }
            if let Some(size) = size
                && view.pinned.is_some()
            {
                for (k, dx, dy) in [
                    (Key::ArrowLeft, -1, 0),
                    (Key::ArrowRight, 1, 0),
                    (Key::ArrowUp, 0, -1),
                    (Key::ArrowDown, 0, 1),
                ] {
                    if key(k) {
                        cmds.push(Command::MovePin { dx, dy, size });
                    }
                }
            }
            if i.consume_key(Modifiers::COMMAND, Key::R) {
                cmds.push(Command::ResetScene);
            }
            if i.consume_key(Modifiers::COMMAND, Key::O) {
                open = true;
            }
            if i.consume_key(Modifiers::COMMAND, Key::S) {
                export = true;
            }
        });
        if export {
            // The first Ctrl+S opens the Export window, the next one exports.
            self.export.push(if self.export.open {
                export::ExportCommand::Export
            } else {
                export::ExportCommand::Open
            });
        }
        if help {
            self.help_open = !self.help_open;
        }
        if open {
            self.picker.open_dialog(ctx);
        }
        self.commands.extend(cmds);
    }

    fn apply_commands(&mut self, ctx: &egui::Context) {
        if self.commands.is_empty() {
            return;
        }
        let before = self.state.clone();
        for c in std::mem::take(&mut self.commands) {
            if let Err(e) = self.state.apply(c) {
                self.message = Some(Message {
                    text: e.to_string(),
                    error: true,
                });
            }
        }
        if self.state != before {
            ctx.request_repaint();
        }
    }

    fn sync_zoom(&mut self, ctx: &egui::Context) {
        let z = ctx.zoom_factor();
        if let Some(applied) = self.applied_zoom
            && (z - applied).abs() > f32::EPSILON
        {
            // Changed with Ctrl +/-: keep it.
            self.state.view.ui_scale = z;
        }
        if (self.state.view.ui_scale - z).abs() > f32::EPSILON {
            ctx.set_zoom_factor(self.state.view.ui_scale);
        }
        self.applied_zoom = Some(self.state.view.ui_scale);
    }

    /// Probes the hovered and the pinned pixel (again only if the pixel or the render changed).
    fn pixel_reports(&mut self, texture: &Arc<Texture>) {
        let mode = self.state.options().mode;
        let Some(out) = self.canvas.output.as_ref() else {
            self.hover_report = None;
            self.pin_report = None;
            self.prober = None;
            return;
        };
        let mut error = None;
        let prober = &mut self.prober;
        let built = &mut self.probers_built;
        let mut update = |slot: &mut Option<PixelReport>, pixel: Option<[u32; 2]>| {
            let Some(p) = pixel else {
                *slot = None;
                return;
            };
            if slot.as_ref().is_some_and(|r| r.is_for(out, mode, p)) {
                return;
            }
            // One prober per render and mode: it clips and sets up every triangle once.
            let tag = (out.generation, mode);
            if prober.as_ref().is_none_or(|(t, _)| *t != tag) {
                let settings = PixelReport::settings(out, mode);
                *prober = match crate::probe::Prober::shared(&out.scene, texture.clone(), &settings)
                {
                    Ok(pr) => {
                        *built += 1;
                        Some((tag, pr))
                    }
                    Err(e) => {
                        error = Some(e.to_string());
                        *slot = None;
                        return;
                    }
                };
            }
            let Some((_, pr)) = prober.as_ref() else {
                return;
            };
            *slot = match PixelReport::with_prober(out, pr, p) {
                Ok(r) => Some(r),
                Err(e) => {
                    error = Some(e.to_string());
                    None
                }
            };
        };
        update(&mut self.hover_report, self.canvas.hover);
        update(&mut self.pin_report, self.state.view.pinned);
        if let Some(e) = error {
            self.message = Some(Message {
                text: e,
                error: true,
            });
        }
    }

    /// The whole UI, inside the given `Ui` (eframe's root `Ui`, or a test harness's).
    pub fn show(&mut self, ui: &mut egui::Ui) {
        let start = Instant::now();
        let ctx = ui.ctx().clone();
        if !self.styled {
            apply_style(&ctx);
            self.styled = true;
        }
        self.sync_zoom(&ctx);
        self.shortcuts(&ctx);
        self.open_requested(&ctx);

        let (texture, texture_error) = self
            .textures
            .get(&self.state.scene, self.state.scene_dir.as_deref());
        if let Some(e) = texture_error {
            self.message = Some(Message {
                text: e,
                error: true,
            });
        }
        let texture_key = (
            self.state.scene.texture_name().to_string(),
            self.state.scene_dir.clone(),
        );

        let hover_before = self.canvas.hover;
        egui::Panel::top("top").show(ui, |ui| self.top_bar_ui(ui));
        files::expire_banner(&ctx, &mut self.banner);
        if self.banner.is_some() {
            egui::Panel::top("banner").show(ui, |ui| files::banner_ui(ui, &mut self.banner));
        }
        files::path_window_ui(&ctx, &mut self.picker, &mut self.to_open);
        export::export_ui(&ctx, &mut self.export);
        egui::Panel::bottom("status").show(ui, |ui| {
            status::status_ui(
                ui,
                &self.state,
                &self.canvas,
                self.timing,
                self.message.as_ref(),
            );
        });
        if self.state.view.show_controls {
            egui::Panel::left("controls")
                .resizable(false)
                .exact_size(CONTROLS_WIDTH)
                .show(ui, |ui| {
                    egui::ScrollArea::vertical()
                        .auto_shrink([false, false])
                        .show(ui, |ui| {
                            controls::controls_ui(ui, &self.state, &mut self.commands);
                        });
                });
        }
        if self.state.view.show_inspector {
            egui::Panel::right("inspector")
                .resizable(false)
                .exact_size(INSPECTOR_WIDTH)
                .show(ui, |ui| {
                    // Content never widens the panel: a wide line scrolls instead. (A panel
                    // that grew with the hovered pixel's text would move the canvas under
                    // the pointer, change the hovered pixel, and so on.)
                    let width = ui.available_width();
                    egui::ScrollArea::both()
                        .auto_shrink([false, false])
                        .show(ui, |ui| {
                            ui.set_max_width(width);
                            inspector::inspector_ui(
                                ui,
                                self.hover_report.as_ref(),
                                self.pin_report.as_ref(),
                            );
                        });
                });
        }
        egui::CentralPanel::default().show(ui, |ui| {
            canvas::canvas_ui(
                ui,
                &mut self.canvas,
                CanvasInput {
                    state: &self.state,
                    texture: &texture,
                    texture_key,
                    hover_report: self.hover_report.as_ref(),
                    pin_report: self.pin_report.as_ref(),
                },
                &mut self.commands,
            );
        });
        let mut help_open = self.help_open;
        egui::Window::new(text::HELP)
            .open(&mut help_open)
            .default_width(620.0)
            .show(&ctx, help::help_ui);
        self.help_open = help_open;
        let rendered = self.canvas.output.as_ref().map(|o| (&o.scene, &texture));
        bench_panel::bench_ui(&ctx, &mut self.bench, rendered);

        let key = |r: &Option<PixelReport>| r.as_ref().map(|r| (r.pixel, r.mode, r.generation));
        let reports_before = (key(&self.hover_report), key(&self.pin_report));
        self.pixel_reports(&texture);
        if self.canvas.hover != hover_before
            || reports_before != (key(&self.hover_report), key(&self.pin_report))
        {
            // The inspector and overlay drew last frame's pixel; draw again with this one.
            ctx.request_repaint();
        }
        let outcome_before = self.export.outcome.clone();
        self.export.apply(
            &ctx,
            &export::ExportContext {
                state: &self.state,
                texture: &texture,
                size: self.canvas.output.as_ref().map(|o| o.size),
                hovered: self.canvas.hover,
                pixels_per_point: ctx.pixels_per_point(),
            },
        );
        if self.export.outcome != outcome_before
            && let Some(o) = &self.export.outcome
        {
            self.message = Some(Message {
                text: o.summary.clone(),
                error: o.error,
            });
            ctx.request_repaint();
        }
        self.apply_commands(&ctx);
        self.timing.ui_ms = start.elapsed().as_secs_f64() * 1e3;
        self.screenshot_step(&ctx);
    }

    fn top_bar_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.label(egui::RichText::new("barylab").strong());
            ui.separator();
            files::file_menu_ui(ui, &mut self.picker, &mut self.recent, &mut self.to_open);
            ui.separator();
            let view = &self.state.view;
            if ui
                .selectable_label(view.show_controls, text::CONTROLS)
                .on_hover_text(text::CONTROLS_TIP)
                .clicked()
            {
                self.commands
                    .push(Command::SetShowControls(!view.show_controls));
            }
            if ui
                .selectable_label(view.show_inspector, text::INSPECTOR)
                .on_hover_text(text::INSPECTOR_TIP)
                .clicked()
            {
                self.commands
                    .push(Command::SetShowInspector(!view.show_inspector));
            }
            if ui
                .selectable_label(self.export.open, export::text::BUTTON)
                .on_hover_text(export::text::BUTTON_TIP)
                .clicked()
            {
                self.export.push(if self.export.open {
                    export::ExportCommand::Close
                } else {
                    export::ExportCommand::Open
                });
            }
            if ui
                .selectable_label(self.help_open, text::HELP)
                .on_hover_text(text::HELP_TIP)
                .clicked()
            {
                self.help_open = !self.help_open;
            }
            bench_panel::toggle_ui(ui, &mut self.bench);
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                controls::reset_ui(ui, &self.state, &mut self.commands);
            });
        });
    }

    fn screenshot_step(&mut self, ctx: &egui::Context) {
        let Some(job) = &mut self.screenshot else {
            return;
        };
        ctx.request_repaint();
        let done = job.result.lock().map(|r| r.is_some()).unwrap_or(true);
        if done {
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
            return;
        }
        if job.started.elapsed() > SCREENSHOT_TIMEOUT {
            if let Ok(mut r) = job.result.lock() {
                *r = Some(Err(text::SCREENSHOT_TIMEOUT.to_string()));
            }
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
            return;
        }
        if self.canvas.output.is_some() {
            job.frames += 1;
        }
        if job.frames >= SCREENSHOT_AFTER_FRAMES && !job.requested {
            job.requested = true;
            let path = job.path.clone();
            let result = job.result.clone();
            let repaint = ctx.clone();
            ctx.request_screenshot(move |image| {
                let r = save_color_image(&image, &path);
                if let Ok(mut slot) = result.lock() {
                    *slot = Some(r);
                }
                repaint.request_repaint();
            });
        }
    }
}

fn smaller_pixel(p: u32) -> u32 {
    (p / 2).max(state::PIXEL_SIZE_RANGE.0)
}

fn larger_pixel(p: u32) -> u32 {
    (p * 2).min(state::PIXEL_SIZE_RANGE.1)
}

/// Writes an egui image as PNG.
fn save_color_image(image: &egui::ColorImage, path: &Path) -> Result<(), String> {
    let [w, h] = image.size;
    let mut out = image::RgbaImage::new(w as u32, h as u32);
    for (px, c) in out.pixels_mut().zip(&image.pixels) {
        px.0 = c.to_srgba_unmultiplied();
    }
    crate::files::write_atomic(path, |w| {
        out.write_to(w, image::ImageFormat::Png)
            .map_err(std::io::Error::other)
    })
    .map_err(|e| e.to_string())
}

/// Loads a scene file and checks that its texture loads; returns the scene and its folder.
pub fn load_scene(path: &Path) -> Result<(Scene, PathBuf), String> {
    let scene = Scene::load(path).map_err(|e| e.to_string())?;
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    scene.load_texture(&dir).map_err(|e| e.to_string())?;
    Ok((scene, dir))
}

impl eframe::App for BaryApp {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        self.timing.frame_ms = frame.info().cpu_usage.map(|s| s * 1e3);
        self.show(ui);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        if self.persist {
            let mut saved = self.state.to_saved();
            saved.recent = self.recent.clone();
            saved.export = self.export.settings.clone();
            eframe::set_value(storage, STORAGE_KEY, &saved);
        }
    }

    fn persist_egui_memory(&self) -> bool {
        self.persist
    }
}

/// Opens the window and runs the app until it is closed.
pub fn run(options: AppOptions) -> Result<(), AppError> {
    let size = options.window_size.unwrap_or(WINDOW_SIZE);
    let native = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title(text::TITLE)
            .with_app_id("barylab")
            .with_inner_size(size)
            .with_min_inner_size([800.0, 500.0]),
        persist_window: options.persist,
        // Dithering would add noise to the canvas; its pixels must show exactly.
        dithering: false,
        ..Default::default()
    };
    let screenshot = options.screenshot.clone();
    let result_slot: Arc<Mutex<Option<ScreenshotResult>>> = Arc::new(Mutex::new(None));
    let slot = result_slot.clone();
    eframe::run_native(
        "barylab",
        native,
        Box::new(move |cc| {
            let app = BaryApp::new(cc.storage, options);
            if let (Some(job), Ok(mut s)) = (&app.screenshot, slot.lock()) {
                *s = Some(job.result.clone());
            }
            Ok(Box::new(app))
        }),
    )
    .map_err(|e| AppError::Window(e.to_string()))?;
    if let Some(path) = screenshot {
        let outcome = result_slot
            .lock()
            .ok()
            .and_then(|s| s.clone())
            .and_then(|r| r.lock().ok().and_then(|r| r.clone()));
        match outcome {
            Some(Ok(())) => {}
            Some(Err(message)) => {
                return Err(AppError::Screenshot {
                    path: path.display().to_string(),
                    message,
                });
            }
            None => {
                return Err(AppError::Screenshot {
                    path: path.display().to_string(),
                    message: "the window closed before the screenshot was taken".into(),
                });
            }
        }
    }
    Ok(())
}
