//! The Export panel: figures of the canvas for lecture notes. Writes the annotated PNG, the
//! SVG, the marked pixel's derivation (Markdown, LaTeX) and the scene file into a folder,
//! under fresh names; copies the figure to the clipboard; saves a screenshot of the window.
//! The figure is made by [`crate::figure`], the same code as `barylab figure`.

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use egui::{Color32, RichText, Ui};

use crate::app::command::ExportCommand;
use crate::app::document::export_settings::ExportSettings;
use crate::app::document::state::AppState;
use crate::app::services::dialog::{DialogOutcome, NativeDialog};
use crate::app::services::screenshot::{self, ShotSlot};
use crate::figure::export::{self, ExportError, ExportRequest};
use crate::figure::{Background, Figure, FigureError, FigureOptions, SCALES, png};
use crate::i18n::Lang;
use crate::raster::Texture;
use crate::scene::Scene;

/// What the last action did, shown in the panel (and on the status line).
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// Whether the action failed.
    pub error: bool,
    /// The lines the panel shows (written files, or the error).
    pub lines: Vec<String>,
    /// One line for the status line.
    pub summary: String,
}

impl Outcome {
    pub(crate) fn failed(message: impl Into<String>) -> Self {
        let message = message.into();
        Self {
            error: true,
            lines: vec![message.clone()],
            summary: message,
        }
    }

    pub(crate) fn done(message: impl Into<String>) -> Self {
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
    /// The settings, saved between runs.
    pub settings: ExportSettings,
    /// Whether the panel is shown.
    pub open: bool,
    /// The text of the folder field.
    pub folder_text: String,
    /// What the last action did (`None` before the first).
    pub outcome: Option<Outcome>,
    dialog: NativeDialog,
    screenshot: Option<(PathBuf, ShotSlot, std::time::Instant)>,
    /// A window screenshot to take next frame, when the panel is not drawn.
    screenshot_due: Option<PathBuf>,
    clipboard: Option<arboard::Clipboard>,
    /// The language of the outcome messages (the app's, as of this frame).
    lang: Lang,
}

/// Everything an export needs from the app.
pub(crate) struct ExportContext<'a> {
    /// The document the figure shows.
    pub state: &'a AppState,
    /// The scene's texture, loaded.
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
    /// A closed panel with these settings; the folder field shows their folder.
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
        self.lang = crate::app::services::locale::lang(ctx);
        let picked = self.poll_dialog();
        self.poll_screenshot();
        self.take_due_screenshot(ctx);
        picked.into_iter().collect()
    }

    /// Applies a command; runs the actions.
    pub(crate) fn apply(
        &mut self,
        ctx: &egui::Context,
        command: ExportCommand,
        app: &ExportContext<'_>,
    ) {
        self.lang = crate::app::services::locale::lang(ctx);
        let lang = self.lang;
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
                            Some(f) if files.len() > 1 => lang.tr_with(
                                "app.export.wrote_more",
                                &[("path", &f.display()), ("n", &(files.len() - 1))],
                            ),
                            Some(f) => lang.tr_with("app.export.wrote", &[("path", &f.display())]),
                            None => String::new(),
                        };
                        let mut lines: Vec<String> = files
                            .iter()
                            .map(|f| lang.tr_with("app.export.wrote", &[("path", &f.display())]))
                            .collect();
                        if let Some(json) = files
                            .iter()
                            .find(|f| f.extension().is_some_and(|e| e == "json"))
                        {
                            lines.push(lang.tr("app.export.again"));
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
                    Ok(()) => Outcome::done(lang.tr("app.export.copied")),
                    Err(e) => Outcome::failed(e),
                });
            }
            ExportCommand::Screenshot => self.screenshot(ctx),
        }
    }

    fn folder(&self) -> Result<PathBuf, String> {
        let lang = self.lang;
        self.settings
            .folder
            .clone()
            .ok_or_else(|| lang.tr("app.export.no_folder"))
    }

    /// The figure of the canvas as it is now.
    fn figure(&self, app: &ExportContext<'_>) -> Result<(Scene, Figure), String> {
        let lang = self.lang;
        let size = app.size.ok_or_else(|| lang.tr("app.export.no_canvas"))?;
        let scene = figure_scene(app.state, size);
        let options = figure_options(app, &self.settings);
        let figure = Figure::compose_in(&scene, app.texture, &options, self.lang)
            .map_err(|e: FigureError| e.to_string())?;
        Ok((scene, figure))
    }

    /// The `barylab figure` command that makes the exported PNG again from the exported scene
    /// file `json`.
    pub(crate) fn command(&self, app: &ExportContext<'_>, json: &Path) -> String {
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
    pub(crate) fn export(&self, app: &ExportContext<'_>) -> Result<Vec<PathBuf>, String> {
        let lang = self.lang;
        let folder = self.folder()?;
        let sel = self.settings.selection;
        if !(sel.png || sel.svg || sel.derivation || sel.scene) {
            return Err(lang.tr("app.export.nothing_selected"));
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
        let lang = self.lang;
        let (_, figure) = self.figure(app)?;
        let image = png::rasterize(&figure).map_err(|e| e.to_string())?;
        let (width, height) = image.dimensions();
        let fail = |e: arboard::Error| format!("{}: {e}", &lang.tr("app.export.clipboard_failed"));
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
        let lang = self.lang;
        let Some((path, slot, started)) = &self.screenshot else {
            return;
        };
        if let Some(r) = screenshot::outcome(slot, *started, SCREENSHOT_TIMEOUT) {
            self.outcome = Some(match r {
                Ok(()) => {
                    Outcome::done(lang.tr_with("app.export.wrote", &[("path", &path.display())]))
                }
                Err(e) => {
                    Outcome::failed(format!("{}: {e}", &lang.tr("app.export.screenshot_failed")))
                }
            });
            self.screenshot = None;
        }
    }

    fn open_folder_dialog(&mut self, ctx: &egui::Context) {
        let lang = crate::app::services::locale::lang(ctx);
        let start = self.settings.folder.clone();
        let opened = self.dialog.open(ctx, "folder dialog", move || {
            let mut d = rfd::FileDialog::new().set_title(lang.tr("app.export.folder_dialog"));
            if let Some(f) = start {
                d = d.set_directory(f);
            }
            d.pick_folder()
        });
        if opened.is_err() {
            self.outcome = Some(Outcome::failed(lang.tr("app.export.folder_dialog_failed")));
        }
    }

    /// The folder picked in the dialog, once it closed with one.
    fn poll_dialog(&mut self) -> Option<ExportCommand> {
        let lang = self.lang;
        match self.dialog.poll()? {
            DialogOutcome::Picked(folder) => Some(ExportCommand::SetFolder(folder)),
            DialogOutcome::Failed => {
                self.outcome = Some(Outcome::failed(lang.tr("app.export.folder_dialog_failed")));
                None
            }
            DialogOutcome::Cancelled => None,
        }
    }
}

/// The scene a figure of the canvas shows: the current scene at the canvas's render size.
pub(crate) fn figure_scene(state: &AppState, size: [u32; 2]) -> Scene {
    let mut scene = state.scene.clone();
    scene.set_size(size[0], size[1]);
    scene
}

/// The figure options of the canvas as shown, with the export's scale and background;
/// the pixel size and the overlay scale are the screen's.
pub(crate) fn figure_options(app: &ExportContext<'_>, settings: &ExportSettings) -> FigureOptions {
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
pub(crate) struct ExportView<'a> {
    /// The settings the panel shows.
    pub settings: &'a ExportSettings,
    /// What the last action did, if anything.
    pub outcome: Option<&'a Outcome>,
}

impl ExportPanel {
    /// What the window shows, and the folder field's text (the one thing the window edits
    /// itself); `None` when the window is not shown.
    pub(crate) fn view(&mut self) -> Option<(ExportView<'_>, &mut String)> {
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
pub(crate) fn export_ui(
    ctx: &egui::Context,
    panel: &ExportView<'_>,
    folder_text: &mut String,
) -> Vec<ExportCommand> {
    let lang = crate::app::services::locale::lang(ctx);
    let mut open = true;
    let mut out = Vec::new();
    egui::Window::new(lang.tr("app.export.window"))
        .id(egui::Id::unique("export-window"))
        .open(&mut open)
        .collapsible(false)
        .resizable(false)
        .default_width(560.0)
        // High on the right, over the inspector: the canvas being exported stays in view, and
        // so does an open lesson's bar at the bottom.
        .pivot(egui::Align2::RIGHT_TOP)
        .default_pos(ctx.content_rect().right_top() + egui::vec2(-20.0, 60.0))
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
    let lang = crate::app::services::locale::lang(ui.ctx());
    let s = panel.settings.clone();
    egui::Grid::new("export-grid")
        .num_columns(2)
        .spacing([12.0, 8.0])
        .show(ui, |ui| {
            folder_row(ui, folder_text, 340.0, out);

            ui.label(lang.tr("app.export.scale"))
                .on_hover_text(lang.tr("app.export.scale_tip"));
            ui.horizontal(|ui| {
                for k in SCALES {
                    if ui
                        .selectable_label(s.scale == k, format!("{k}x"))
                        .on_hover_text(lang.tr("app.export.scale_tip"))
                        .clicked()
                    {
                        out.push(ExportCommand::SetScale(k));
                    }
                }
            });
            ui.end_row();

            ui.label(lang.tr("app.export.background"));
            ui.horizontal(|ui| {
                for (b, label) in [
                    (Background::White, &lang.tr("app.export.white")),
                    (Background::Transparent, &lang.tr("app.export.transparent")),
                ] {
                    if ui.selectable_label(s.background == b, label).clicked() {
                        out.push(ExportCommand::SetBackground(b));
                    }
                }
            });
            ui.end_row();
        });
    // A figure option, under the scale and background.
    let mut caption = s.caption;
    ui.checkbox(&mut caption, lang.tr("figure.caption.option"))
        .on_hover_text(lang.tr("figure.caption.option_tip"));
    if caption != s.caption {
        out.push(ExportCommand::SetCaption(caption));
    }
    ui.add_space(4.0);
    let mut sel = s.selection;
    ui.checkbox(&mut sel.png, lang.tr("app.export.png"));
    ui.checkbox(&mut sel.svg, lang.tr("app.export.svg"));
    ui.checkbox(&mut sel.derivation, lang.tr("app.export.derivation"))
        .on_hover_text(lang.tr("app.export.derivation_tip"));
    ui.checkbox(&mut sel.scene, lang.tr("app.export.scene"))
        .on_hover_text(lang.tr("app.export.scene_tip"));
    if sel != s.selection {
        out.push(ExportCommand::SetSelection(sel));
    }
    ui.add_space(4.0);
    ui.horizontal(|ui| {
        if ui
            .button(RichText::new(lang.tr("app.export.export")).strong())
            .on_hover_text(lang.tr("app.export.button_tip"))
            .clicked()
        {
            out.push(ExportCommand::Export);
        }
        if ui
            .button(lang.tr("app.export.copy"))
            .on_hover_text(lang.tr("app.export.copy_tip"))
            .clicked()
        {
            out.push(ExportCommand::Copy);
        }
        if ui
            .button(lang.tr("app.export.screenshot"))
            .on_hover_text(lang.tr("app.export.screenshot_tip"))
            .clicked()
        {
            out.push(ExportCommand::Screenshot);
        }
    });
    if let Some(o) = panel.outcome {
        outcome_lines(ui, o);
    }
}

/// The grid row of the folder: its field (`width` points) and Browse….
pub(crate) fn folder_row(
    ui: &mut Ui,
    folder_text: &mut String,
    width: f32,
    out: &mut Vec<ExportCommand>,
) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    ui.label(lang.tr("app.export.folder"));
    ui.horizontal(|ui| {
        let field = ui.add(
            egui::TextEdit::singleline(folder_text)
                .hint_text(lang.tr("app.export.folder_hint"))
                .desired_width(width),
        );
        if field.changed() {
            let t = folder_text.trim();
            if !t.is_empty() {
                out.push(ExportCommand::SetFolder(PathBuf::from(t)));
            }
        }
        if ui.button(lang.tr("app.export.browse")).clicked() {
            out.push(ExportCommand::BrowseFolder);
        }
    });
    ui.end_row();
}

/// What the last action did, under a line: green, or red for an error.
pub(crate) fn outcome_lines(ui: &mut Ui, o: &Outcome) {
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
