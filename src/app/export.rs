//! The Export panel: figures of the canvas for lecture notes. Writes the annotated PNG, the
//! SVG, the marked pixel's derivation (Markdown, LaTeX) and the scene file into a folder,
//! under fresh names; copies the figure to the clipboard; saves a screenshot of the window.
//! The figure is made by [`crate::figure`], the same code as `barylab figure`.

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use egui::{Color32, RichText, Ui};
use serde::{Deserialize, Serialize};

use super::dialog::{DialogOutcome, NativeDialog};
use super::screenshot::{self, ShotSlot};
use super::state::AppState;
use crate::figure::export::{self, ExportError, ExportRequest, ExportSelection};
use crate::figure::{Background, Figure, FigureError, FigureOptions, SCALES, png};
use crate::raster::Texture;
use crate::scene::Scene;

/// User-facing strings of the Export panel.
pub mod text {
    pub const WINDOW: &str = "Export figure";
    pub const BUTTON: &str = "Export…";
    pub const BUTTON_TIP: &str = "Figures for slides and notes: PNG, SVG, the pixel's \
        derivation and the scene file. Key: Ctrl+S";
    pub const FOLDER: &str = "Folder";
    pub const FOLDER_HINT: &str = "folder to write the files into";
    pub const BROWSE: &str = "Browse…";
    pub const SCALE: &str = "Scale";
    pub const SCALE_TIP: &str = "PNG pixels per screen pixel: the scene is rendered again at \
        that resolution (at pixel size 1), labels and lines are drawn sharper, not larger.";
    pub const BACKGROUND: &str = "Background";
    pub const TRANSPARENT: &str = "Transparent";
    pub const WHITE: &str = "White";
    pub const PNG: &str = "PNG (annotated)";
    pub const SVG: &str = "SVG (vector overlays, real text)";
    pub const DERIVATION: &str = "Derivation (.md, .tex)";
    pub const DERIVATION_TIP: &str = "The pinned pixel's worked example (or the hovered one's); \
        skipped when no pixel is marked.";
    pub const SCENE: &str = "Scene file (.json)";
    pub const SCENE_TIP: &str = "Reproduces the figure: barylab figure FILE.json …";
    pub const EXPORT: &str = "Export";
    pub const COPY: &str = "Copy figure";
    pub const COPY_TIP: &str = "Copy the annotated figure (PNG) to the clipboard.";
    pub const SCREENSHOT: &str = "Screenshot window";
    pub const SCREENSHOT_TIP: &str = "Save the whole window as a PNG into the folder.";
    pub const NO_FOLDER: &str = "choose a folder first";
    pub const NOTHING_SELECTED: &str = "nothing to export: tick at least one kind of file";
    pub const NO_CANVAS: &str = "nothing rendered yet";
    pub const WROTE: &str = "wrote";
    pub const MORE_FILES: &str = "more files";
    pub const AGAIN: &str = "the same figure from the command line:";
    pub const COPIED: &str = "figure copied to the clipboard";
    pub const CLIPBOARD_FAILED: &str = "cannot copy to the clipboard";
    pub const SCREENSHOT_FAILED: &str = "screenshot failed";
    pub const FOLDER_DIALOG: &str = "Folder for figures";
    pub const FOLDER_DIALOG_FAILED: &str = "no folder dialog available: type the folder";
}

/// Export settings saved between runs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ExportSettings {
    /// The folder of the last export.
    pub folder: Option<PathBuf>,
    /// 1, 2 or 4.
    pub scale: u32,
    pub background: Background,
    pub selection: ExportSelection,
    /// A caption with the marked pixel's key numbers below the figure.
    pub caption: bool,
}

impl Default for ExportSettings {
    fn default() -> Self {
        Self {
            folder: None,
            scale: 2,
            background: Background::White,
            selection: ExportSelection::default(),
            caption: false,
        }
    }
}

/// A change or an action of the Export panel, applied once per frame.
#[derive(Clone, Debug, PartialEq)]
pub enum ExportCommand {
    Open,
    Close,
    /// Show the native folder dialog.
    BrowseFolder,
    SetFolder(PathBuf),
    SetScale(u32),
    SetBackground(Background),
    SetSelection(ExportSelection),
    /// Add (or leave out) the figure's caption.
    SetCaption(bool),
    /// Write the selected files into the folder.
    Export,
    /// Put the figure's PNG on the clipboard.
    Copy,
    /// Save the whole window as a PNG into the folder.
    Screenshot,
}

/// What the last action did, shown in the panel (and on the status line).
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    pub error: bool,
    pub lines: Vec<String>,
    /// One line for the status line.
    pub summary: String,
}

impl Outcome {
    fn failed(message: impl Into<String>) -> Self {
        let message = message.into();
        Self {
            error: true,
            lines: vec![message.clone()],
            summary: message,
        }
    }

    fn done(message: impl Into<String>) -> Self {
        let message = message.into();
        Self {
            error: false,
            lines: vec![message.clone()],
            summary: message,
        }
    }
}

/// Give up waiting for a window screenshot after this long (a backend without screenshots
/// never calls back).
const SCREENSHOT_TIMEOUT: std::time::Duration = std::time::Duration::from_secs(10);

/// The Export panel's state.
#[derive(Default)]
pub struct ExportPanel {
    pub settings: ExportSettings,
    pub open: bool,
    /// The text of the folder field.
    pub folder_text: String,
    pub outcome: Option<Outcome>,
    dialog: NativeDialog,
    screenshot: Option<(PathBuf, ShotSlot, std::time::Instant)>,
    /// A window screenshot to take next frame, when the panel is not drawn.
    screenshot_due: Option<PathBuf>,
    clipboard: Option<arboard::Clipboard>,
}

/// Everything an export needs from the app.
pub struct ExportContext<'a> {
    pub state: &'a AppState,
    pub texture: &'a Texture,
    /// The canvas's rendered size.
    pub size: Option<[u32; 2]>,
    /// Screen pixels per rendered pixel as the canvas draws them (the figure's pixel size).
    pub pixel_size: u32,
    /// The hovered pixel (marked like on screen).
    pub hovered: Option<[u32; 2]>,
    /// Screen pixels per point: overlays are drawn this much larger, as on screen.
    pub pixels_per_point: f32,
}

impl ExportPanel {
    pub fn new(settings: ExportSettings) -> Self {
        let folder_text = settings
            .folder
            .as_ref()
            .map(|f| f.display().to_string())
            .unwrap_or_default();
        Self {
            settings,
            folder_text,
            ..Self::default()
        }
    }

    /// Once per frame: what the folder dialog and a window screenshot came back with; takes a
    /// due screenshot. Returns the folder picked, as a command.
    pub fn frame(&mut self, ctx: &egui::Context) -> Vec<ExportCommand> {
        let picked = self.poll_dialog();
        self.poll_screenshot();
        self.take_due_screenshot(ctx);
        picked.into_iter().collect()
    }

    /// Applies a command; runs the actions.
    pub fn apply(&mut self, ctx: &egui::Context, command: ExportCommand, app: &ExportContext<'_>) {
        match command {
            ExportCommand::Open => self.open = true,
            ExportCommand::Close => self.open = false,
            ExportCommand::BrowseFolder => self.open_folder_dialog(ctx),
            ExportCommand::SetFolder(f) => {
                self.folder_text = f.display().to_string();
                self.settings.folder = Some(f);
            }
            ExportCommand::SetScale(s) if SCALES.contains(&s) => self.settings.scale = s,
            ExportCommand::SetScale(_) => {}
            ExportCommand::SetBackground(b) => self.settings.background = b,
            ExportCommand::SetCaption(c) => self.settings.caption = c,
            ExportCommand::SetSelection(s) => self.settings.selection = s,
            ExportCommand::Export => {
                self.outcome = Some(match self.export(app) {
                    Ok(files) => {
                        let summary = match files.first() {
                            Some(f) if files.len() > 1 => format!(
                                "{} {} (+{} {})",
                                text::WROTE,
                                f.display(),
                                files.len() - 1,
                                text::MORE_FILES
                            ),
                            Some(f) => format!("{} {}", text::WROTE, f.display()),
                            None => String::new(),
                        };
                        let mut lines: Vec<String> = files
                            .iter()
                            .map(|f| format!("{} {}", text::WROTE, f.display()))
                            .collect();
                        if let Some(json) = files
                            .iter()
                            .find(|f| f.extension().is_some_and(|e| e == "json"))
                        {
                            lines.push(text::AGAIN.to_string());
                            lines.push(self.command(app, json));
                        }
                        Outcome {
                            error: false,
                            lines,
                            summary,
                        }
                    }
                    Err(e) => Outcome::failed(e),
                });
            }
            ExportCommand::Copy => {
                self.outcome = Some(match self.copy(app) {
                    Ok(()) => Outcome::done(text::COPIED),
                    Err(e) => Outcome::failed(e),
                });
            }
            ExportCommand::Screenshot => self.screenshot(ctx),
        }
    }

    fn folder(&self) -> Result<PathBuf, String> {
        self.settings
            .folder
            .clone()
            .ok_or_else(|| text::NO_FOLDER.to_string())
    }

    /// The figure of the canvas as it is now.
    fn figure(&self, app: &ExportContext<'_>) -> Result<(Scene, Figure), String> {
        let size = app.size.ok_or_else(|| text::NO_CANVAS.to_string())?;
        let scene = figure_scene(app.state, size);
        let options = figure_options(app, &self.settings);
        let figure = Figure::compose(&scene, app.texture, &options)
            .map_err(|e: FigureError| e.to_string())?;
        Ok((scene, figure))
    }

    /// The `barylab figure` command that makes the exported PNG again from the exported scene
    /// file `json`.
    pub fn command(&self, app: &ExportContext<'_>, json: &Path) -> String {
        let options = figure_options(app, &self.settings);
        let quote = |p: &Path| {
            let s = p.display().to_string();
            if s.contains([' ', '\'', '"']) {
                format!("'{}'", s.replace('\'', "'\\''"))
            } else {
                s
            }
        };
        format!(
            "barylab figure {} {} -o {}",
            quote(json),
            options.cli_args().join(" "),
            quote(&json.with_extension("png"))
        )
    }

    /// Writes the selected files; returns them.
    pub fn export(&self, app: &ExportContext<'_>) -> Result<Vec<PathBuf>, String> {
        let folder = self.folder()?;
        let sel = self.settings.selection;
        if !(sel.png || sel.svg || sel.derivation || sel.scene) {
            return Err(text::NOTHING_SELECTED.to_string());
        }
        let (scene, figure) = self.figure(app)?;
        export::export(&ExportRequest {
            folder: &folder,
            stem: "figure",
            figure: &figure,
            scene: &scene,
            scene_dir: app.state.scene_dir.as_deref(),
            selection: sel,
        })
        .map_err(|e: ExportError| e.to_string())
    }

    fn copy(&mut self, app: &ExportContext<'_>) -> Result<(), String> {
        let (_, figure) = self.figure(app)?;
        let image = png::rasterize(&figure).map_err(|e| e.to_string())?;
        let (width, height) = image.dimensions();
        let fail = |e: arboard::Error| format!("{}: {e}", text::CLIPBOARD_FAILED);
        // Kept open: on X11 without a clipboard manager the image is served by this process
        // and would be gone the moment the clipboard was dropped.
        let clipboard = match &mut self.clipboard {
            Some(c) => c,
            None => self
                .clipboard
                .insert(arboard::Clipboard::new().map_err(fail)?),
        };
        clipboard
            .set_image(arboard::ImageData {
                width: width as usize,
                height: height as usize,
                bytes: image.into_raw().into(),
            })
            .map_err(fail)
    }

    /// Picks the screenshot's file; the shot itself is taken next frame, with this panel
    /// hidden ([`ExportPanel::take_due_screenshot`]).
    fn screenshot(&mut self, ctx: &egui::Context) {
        let path = self.folder().and_then(|folder| {
            export::prepare_folder(&folder).map_err(|e| e.to_string())?;
            let stem =
                export::fresh_stem(&folder, "window", &["png"]).map_err(|e| e.to_string())?;
            Ok(folder.join(format!("{stem}.png")))
        });
        match path {
            Ok(p) => {
                self.screenshot_due = Some(p);
                ctx.request_repaint();
            }
            Err(e) => self.outcome = Some(Outcome::failed(e)),
        }
    }

    /// Whether the panel is hidden for a window screenshot.
    pub fn hidden_for_screenshot(&self) -> bool {
        self.screenshot_due.is_some() || self.screenshot.is_some()
    }

    /// Requests the due screenshot of this frame (drawn without the panel).
    fn take_due_screenshot(&mut self, ctx: &egui::Context) {
        let Some(path) = self.screenshot_due.take() else {
            return;
        };
        let slot: ShotSlot = Arc::new(Mutex::new(None));
        let target = path.clone();
        screenshot::request(ctx, &slot, move |image| write_color_image(image, &target));
        self.screenshot = Some((path, slot, std::time::Instant::now()));
    }

    fn poll_screenshot(&mut self) {
        let Some((path, slot, started)) = &self.screenshot else {
            return;
        };
        if let Some(r) = screenshot::outcome(slot, *started, SCREENSHOT_TIMEOUT) {
            self.outcome = Some(match r {
                Ok(()) => Outcome::done(format!("{} {}", text::WROTE, path.display())),
                Err(e) => Outcome::failed(format!("{}: {e}", text::SCREENSHOT_FAILED)),
            });
            self.screenshot = None;
        }
    }

    fn open_folder_dialog(&mut self, ctx: &egui::Context) {
        let start = self.settings.folder.clone();
        let opened = self.dialog.open(ctx, "folder dialog", move || {
            let mut d = rfd::FileDialog::new().set_title(text::FOLDER_DIALOG);
            if let Some(f) = start {
                d = d.set_directory(f);
            }
            d.pick_folder()
        });
        if opened.is_err() {
            self.outcome = Some(Outcome::failed(text::FOLDER_DIALOG_FAILED));
        }
    }

    /// The folder picked in the dialog, once it closed with one.
    fn poll_dialog(&mut self) -> Option<ExportCommand> {
        match self.dialog.poll()? {
            DialogOutcome::Picked(folder) => Some(ExportCommand::SetFolder(folder)),
            DialogOutcome::Failed => {
                self.outcome = Some(Outcome::failed(text::FOLDER_DIALOG_FAILED));
                None
            }
            DialogOutcome::Cancelled => None,
        }
    }
}

/// The scene a figure of the canvas shows: the current scene at the canvas's render size.
pub fn figure_scene(state: &AppState, size: [u32; 2]) -> Scene {
    let mut scene = state.scene.clone();
    scene.set_size(size[0], size[1]);
    scene
}

/// The figure options of the canvas as shown, with the export's scale and background;
/// the pixel size and the overlay scale are the screen's.
pub fn figure_options(app: &ExportContext<'_>, settings: &ExportSettings) -> FigureOptions {
    let (v, hovered, pixels_per_point) = (&app.state.view, app.hovered, app.pixels_per_point);
    FigureOptions {
        compare: v.compare,
        pixel_size: app.pixel_size,
        wipe: v.wipe,
        show_grid: v.show_grid,
        show_handles: v.show_handles,
        show_sub_areas: v.show_sub_areas,
        pinned: v.pinned,
        hovered,
        scale: settings.scale,
        background: settings.background,
        overlay_scale: pixels_per_point,
        caption: settings.caption,
    }
}

/// Writes an egui image as a new PNG file (never over an existing one).
fn write_color_image(image: &egui::ColorImage, path: &Path) -> Result<(), String> {
    let bytes = screenshot::png_bytes(image)?;
    export::write_new(path, &bytes).map_err(|e| e.to_string())
}

/// What the Export window shows ([`ExportPanel::view`]).
pub struct ExportView<'a> {
    pub settings: &'a ExportSettings,
    pub outcome: Option<&'a Outcome>,
}

impl ExportPanel {
    /// What the window shows, and the folder field's text (the one thing the window edits
    /// itself); `None` when the window is not shown.
    pub fn view(&mut self) -> Option<(ExportView<'_>, &mut String)> {
        if !self.open || self.hidden_for_screenshot() {
            return None;
        }
        let view = ExportView {
            settings: &self.settings,
            outcome: self.outcome.as_ref(),
        };
        Some((view, &mut self.folder_text))
    }
}

/// The Export window.
pub fn export_ui(
    ctx: &egui::Context,
    panel: &ExportView<'_>,
    folder_text: &mut String,
) -> Vec<ExportCommand> {
    let mut open = true;
    let mut out = Vec::new();
    egui::Window::new(text::WINDOW)
        .open(&mut open)
        .collapsible(false)
        .resizable(false)
        .default_width(560.0)
        // Low on the right, over the inspector: the canvas being exported stays in view.
        .pivot(egui::Align2::RIGHT_BOTTOM)
        .default_pos(ctx.content_rect().right_bottom() - egui::vec2(20.0, 60.0))
        .show(ctx, |ui| window_contents(ui, panel, folder_text, &mut out));
    if !open {
        out.push(ExportCommand::Close);
    }
    out
}

fn window_contents(
    ui: &mut Ui,
    panel: &ExportView<'_>,
    folder_text: &mut String,
    out: &mut Vec<ExportCommand>,
) {
    let s = panel.settings.clone();
    egui::Grid::new("export-grid")
        .num_columns(2)
        .spacing([12.0, 8.0])
        .show(ui, |ui| {
            ui.label(text::FOLDER);
            ui.horizontal(|ui| {
                let field = ui.add(
                    egui::TextEdit::singleline(folder_text)
                        .hint_text(text::FOLDER_HINT)
                        .desired_width(340.0),
                );
                if field.changed() {
                    let t = folder_text.trim();
                    if !t.is_empty() {
                        out.push(ExportCommand::SetFolder(PathBuf::from(t)));
                    }
                }
                if ui.button(text::BROWSE).clicked() {
                    out.push(ExportCommand::BrowseFolder);
                }
            });
            ui.end_row();

            ui.label(text::SCALE).on_hover_text(text::SCALE_TIP);
            ui.horizontal(|ui| {
                for k in SCALES {
                    if ui
                        .selectable_label(s.scale == k, format!("{k}x"))
                        .on_hover_text(text::SCALE_TIP)
                        .clicked()
                    {
                        out.push(ExportCommand::SetScale(k));
                    }
                }
            });
            ui.end_row();

            ui.label(text::BACKGROUND);
            ui.horizontal(|ui| {
                for (b, label) in [
                    (Background::White, text::WHITE),
                    (Background::Transparent, text::TRANSPARENT),
                ] {
                    if ui.selectable_label(s.background == b, label).clicked() {
                        out.push(ExportCommand::SetBackground(b));
                    }
                }
            });
            ui.end_row();
        });
    // A figure option, under the scale and background; the catalogue's words (English
    // until the app has a language setting).
    let lang = crate::i18n::Lang::En;
    let mut caption = s.caption;
    ui.checkbox(&mut caption, crate::i18n::tr(lang, "figure.caption.option"))
        .on_hover_text(crate::i18n::tr(lang, "figure.caption.option_tip"));
    if caption != s.caption {
        out.push(ExportCommand::SetCaption(caption));
    }
    ui.add_space(4.0);
    let mut sel = s.selection;
    ui.checkbox(&mut sel.png, text::PNG);
    ui.checkbox(&mut sel.svg, text::SVG);
    ui.checkbox(&mut sel.derivation, text::DERIVATION)
        .on_hover_text(text::DERIVATION_TIP);
    ui.checkbox(&mut sel.scene, text::SCENE)
        .on_hover_text(text::SCENE_TIP);
    if sel != s.selection {
        out.push(ExportCommand::SetSelection(sel));
    }
    ui.add_space(4.0);
    ui.horizontal(|ui| {
        if ui
            .button(RichText::new(text::EXPORT).strong())
            .on_hover_text(text::BUTTON_TIP)
            .clicked()
        {
            out.push(ExportCommand::Export);
        }
        if ui
            .button(text::COPY)
            .on_hover_text(text::COPY_TIP)
            .clicked()
        {
            out.push(ExportCommand::Copy);
        }
        if ui
            .button(text::SCREENSHOT)
            .on_hover_text(text::SCREENSHOT_TIP)
            .clicked()
        {
            out.push(ExportCommand::Screenshot);
        }
    });
    if let Some(o) = panel.outcome {
        ui.separator();
        let color = if o.error {
            Color32::from_rgb(255, 120, 110)
        } else {
            Color32::from_rgb(140, 220, 140)
        };
        for line in &o.lines {
            ui.label(RichText::new(line).color(color));
        }
    }
}
