//! Opening files in the app: the File menu (native dialog, a typed path, recent files),
//! drag-and-drop, the banner that reports what opening a file did.
//!
//! Every way of opening goes through [`open`], which loads and checks everything (scene, model,
//! texture) before anything changes; the app then applies the result with one command. So a bad
//! file leaves the current scene exactly as it was.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::mpsc::{Receiver, TryRecvError};
use std::time::{Duration, Instant};

use egui::{Color32, RichText, Ui};
use serde::{Deserialize, Serialize};

use super::state::Command;
use crate::raster::Texture;
use crate::scene::{IMAGE_EXTENSIONS, InputKind, Scene, open_input};

/// User-facing strings of the File menu and the banner.
pub mod text {
    pub const FILE: &str = "File";
    pub const OPEN: &str = "Open…";
    pub const OPEN_TIP: &str = "Open a scene (.json), a model (.obj) or an image \
        (PNG, JPEG, BMP, TGA, WebP: it becomes the texture). You can also drop files on the \
        window. Key: Ctrl+O";
    pub const TYPE_PATH: &str = "Type a path…";
    pub const TYPE_PATH_TIP: &str = "Open a file by typing its path.";
    pub const RECENT: &str = "Recent files";
    pub const NO_RECENT: &str = "(none yet)";
    pub const MISSING: &str = "missing";
    pub const CLEAR_RECENT: &str = "Clear the list";
    pub const PATH_WINDOW: &str = "Open a file";
    pub const PATH_HINT: &str = "/path/to/photo.jpg, model.obj or scene.json";
    pub const OPEN_BUTTON: &str = "Open";
    pub const BROWSE: &str = "Browse…";
    pub const DIALOG_TITLE: &str = "Open a scene, model or image";
    pub const FILTER_ALL: &str = "Scenes, models and images";
    pub const FILTER_SCENE: &str = "Scene (JSON)";
    pub const FILTER_MODEL: &str = "Model (OBJ)";
    pub const FILTER_IMAGE: &str = "Image";
    pub const DIALOG_FAILED: &str = "The file dialog did not open (no desktop portal and no \
        zenity found). Type the path of the file instead:";
    pub const DIALOG_WAITING: &str = "waiting for the file dialog…";
    pub const OPENED: &str = "opened";
    pub const TEXTURE_SET: &str = "is now the texture";
    pub const NOT_OPENED: &str = "not opened; the scene is unchanged";
    pub const NOTE: &str = "note";
    pub const DISMISS: &str = "Dismiss";
    pub const NO_UV_TEXTURE: &str = "the model has no texture coordinates, so the image shows \
        as one colour; it is shaded by vertex colour";
}

/// Recent files shown in the menu.
pub const MAX_RECENT: usize = 10;

/// If the native dialog returns nothing sooner than this, it most likely could not open (no
/// portal, no zenity); nobody picks or cancels that fast, so the typed-path window is offered.
pub const DIALOG_FAILED_WITHIN: Duration = Duration::from_millis(700);

/// What opening a file changes.
#[derive(Clone, Debug)]
pub enum Opened {
    /// A scene file or a model: replaces the scene.
    Scene { scene: Box<Scene>, dir: PathBuf },
    /// An image: becomes the current scene's texture (its absolute path).
    Texture { path: String },
}

/// A file that loaded, with everything checked.
#[derive(Clone, Debug)]
pub struct OpenedFile {
    /// The path as opened (absolute when it could be made so).
    pub path: PathBuf,
    pub what: Opened,
    /// The texture the result shows, already loaded (so the app does not decode it twice).
    pub texture: Arc<Texture>,
    /// Things that did not stop loading (downscaled image, no uvs, missing MTL ...).
    pub notes: Vec<String>,
}

impl OpenedFile {
    /// The command that applies this file to the current scene.
    pub fn command(&self) -> Command {
        match &self.what {
            Opened::Scene { scene, dir } => Command::OpenScene(scene.clone(), Some(dir.clone())),
            Opened::Texture { path } => Command::SetTexture(path.clone()),
        }
    }
}

/// Loads and checks a file named by the user (by dialog, drop, typed path, recent list or the
/// command line): a scene, a model with its texture, or an image. Nothing is changed; the
/// error names the file and the problem.
pub fn open(path: &Path, current: &Scene) -> Result<OpenedFile, String> {
    // Absolute, so the scene saved between runs still finds its model and texture.
    let path = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    let shown = path.display().to_string();
    // A model's texture error names the texture; say which file was being opened too.
    let named = |e: String| {
        if e.contains(&shown) {
            e
        } else {
            format!("{shown}: {e}")
        }
    };
    match InputKind::of(&path) {
        Some(InputKind::Image) => {
            let (texture, note) = Texture::load_noted(&path).map_err(|e| named(e.to_string()))?;
            let mut notes: Vec<String> = note.into_iter().collect();
            if let Scene::Model(m) = current
                && !m.mesh.has_uv
            {
                notes.push(text::NO_UV_TEXTURE.to_string());
            }
            Ok(OpenedFile {
                what: Opened::Texture { path: shown },
                path,
                texture: Arc::new(texture),
                notes,
            })
        }
        _ => {
            let (scene, dir) = open_input(&path).map_err(|e| named(e.to_string()))?;
            let (texture, texture_notes) = scene
                .load_texture_noted(&dir)
                .map_err(|e| named(e.to_string()))?;
            let mut notes = scene.notes();
            notes.extend(texture_notes);
            Ok(OpenedFile {
                what: Opened::Scene {
                    scene: Box::new(scene),
                    dir,
                },
                path,
                texture: Arc::new(texture),
                notes,
            })
        }
    }
}

/// The recently opened files, newest first, saved between runs.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct RecentFiles(pub Vec<PathBuf>);

impl RecentFiles {
    /// Puts `path` first (once), keeping at most [`MAX_RECENT`].
    pub fn push(&mut self, path: &Path) {
        self.0.retain(|p| p != path);
        self.0.insert(0, path.to_path_buf());
        self.0.truncate(MAX_RECENT);
    }
}

/// The message shown under the top bar after opening a file.
#[derive(Clone, Debug, PartialEq)]
pub struct Banner {
    /// One line naming the file and what happened (or the problem).
    pub text: String,
    /// Notes (downscaled image, no uvs, missing MTL ...), one line each.
    pub notes: Vec<String>,
    pub error: bool,
    /// When it appeared (a plain success hides itself after [`BANNER_HIDE_AFTER`]).
    pub shown: Instant,
}

/// A success without notes leaves the canvas area after this; errors and notes stay until
/// dismissed.
pub const BANNER_HIDE_AFTER: Duration = Duration::from_secs(6);

impl Banner {
    /// The banner for a file that opened.
    pub fn opened(file: &OpenedFile) -> Self {
        let text = match file.what {
            Opened::Scene { .. } => format!("{} {}", text::OPENED, file.path.display()),
            Opened::Texture { .. } => format!("{} {}", file.path.display(), text::TEXTURE_SET),
        };
        Self {
            text,
            notes: file.notes.clone(),
            error: false,
            shown: Instant::now(),
        }
    }

    /// The banner for a file that did not open (`error` names the file and the problem).
    pub fn failed(error: String) -> Self {
        Self {
            text: format!("{error} — {}", text::NOT_OPENED),
            notes: Vec::new(),
            error: true,
            shown: Instant::now(),
        }
    }

    /// Everything the banner says, one line each (for tests and the status line).
    pub fn lines(&self) -> Vec<String> {
        std::iter::once(self.text.clone())
            .chain(self.notes.iter().map(|n| format!("{}: {n}", text::NOTE)))
            .collect()
    }
}

/// A native file dialog running on its own thread (it blocks), and the typed-path window.
#[derive(Default)]
pub struct FilePicker {
    dialog: Option<(Receiver<Option<PathBuf>>, Instant)>,
    /// Whether the typed-path window is open.
    pub path_window: bool,
    /// Shown in the typed-path window when the native dialog failed.
    pub dialog_failed: bool,
    /// The text of the path field.
    pub typed: String,
    /// Give the path field the keyboard focus (the window just opened).
    focus_field: bool,
}

impl FilePicker {
    /// Opens the native dialog (once at a time).
    pub fn open_dialog(&mut self, ctx: &egui::Context) {
        if self.dialog.is_some() {
            return;
        }
        let (tx, rx) = std::sync::mpsc::channel();
        let repaint = ctx.clone();
        let mut all: Vec<&str> = vec!["json", "obj"];
        all.extend(IMAGE_EXTENSIONS);
        let spawned = std::thread::Builder::new()
            .name("file dialog".into())
            .spawn(move || {
                let picked = rfd::FileDialog::new()
                    .set_title(text::DIALOG_TITLE)
                    .add_filter(text::FILTER_ALL, &all)
                    .add_filter(text::FILTER_SCENE, &["json"])
                    .add_filter(text::FILTER_MODEL, &["obj"])
                    .add_filter(text::FILTER_IMAGE, &IMAGE_EXTENSIONS)
                    .pick_file();
                let _ = tx.send(picked);
                repaint.request_repaint();
            });
        match spawned {
            Ok(_) => self.dialog = Some((rx, Instant::now())),
            Err(_) => self.show_path_window(true),
        }
    }

    /// Opens the typed-path window; `dialog_failed` says why it is offered.
    pub fn show_path_window(&mut self, dialog_failed: bool) {
        self.dialog_failed = dialog_failed;
        self.path_window = true;
        self.focus_field = true;
        // Start empty: typing must not append to the last path.
        self.typed.clear();
    }

    /// Whether the native dialog is open.
    pub fn waiting(&self) -> bool {
        self.dialog.is_some()
    }

    /// The file picked in the dialog, once it closed with one.
    pub fn poll(&mut self) -> Option<PathBuf> {
        let (rx, started) = self.dialog.as_ref()?;
        match rx.try_recv() {
            Err(TryRecvError::Empty) => None,
            Ok(Some(path)) => {
                self.dialog = None;
                Some(path)
            }
            Ok(None) | Err(TryRecvError::Disconnected) => {
                if started.elapsed() < DIALOG_FAILED_WITHIN {
                    self.show_path_window(true);
                }
                self.dialog = None;
                None
            }
        }
    }
}

/// The File menu: open (dialog), type a path, recent files. Pushes the paths to open.
pub fn file_menu_ui(
    ui: &mut Ui,
    picker: &mut FilePicker,
    recent: &mut RecentFiles,
    open: &mut Vec<PathBuf>,
) {
    ui.menu_button(text::FILE, |ui| {
        if ui
            .button(text::OPEN)
            .on_hover_text(text::OPEN_TIP)
            .clicked()
        {
            picker.open_dialog(ui.ctx());
            ui.close();
        }
        if ui
            .button(text::TYPE_PATH)
            .on_hover_text(text::TYPE_PATH_TIP)
            .clicked()
        {
            picker.show_path_window(false);
            ui.close();
        }
        ui.separator();
        ui.label(RichText::new(text::RECENT).weak());
        if recent.0.is_empty() {
            ui.label(RichText::new(text::NO_RECENT).weak());
        }
        for p in &recent.0 {
            let name = p
                .file_name()
                .map_or_else(|| p.display().to_string(), |n| n.to_string_lossy().into());
            let exists = p.exists();
            let label = if exists {
                name
            } else {
                format!("{name} ({})", text::MISSING)
            };
            let r = ui
                .add_enabled(exists, egui::Button::new(label))
                .on_hover_text(p.display().to_string())
                .on_disabled_hover_text(p.display().to_string());
            if r.clicked() {
                open.push(p.clone());
                ui.close();
            }
        }
        if !recent.0.is_empty() && ui.button(text::CLEAR_RECENT).clicked() {
            recent.0.clear();
        }
    });
    if picker.waiting() {
        ui.label(RichText::new(text::DIALOG_WAITING).weak());
    }
}

/// The typed-path window.
pub fn path_window_ui(ctx: &egui::Context, picker: &mut FilePicker, open: &mut Vec<PathBuf>) {
    if !picker.path_window {
        return;
    }
    let mut window_open = true;
    let mut submit = false;
    egui::Window::new(text::PATH_WINDOW)
        .open(&mut window_open)
        .collapsible(false)
        .default_width(560.0)
        .anchor(egui::Align2::CENTER_TOP, [0.0, 100.0])
        .show(ctx, |ui| {
            if picker.dialog_failed {
                ui.label(RichText::new(text::DIALOG_FAILED).color(Color32::from_rgb(255, 200, 90)));
            }
            let field = ui.add(
                egui::TextEdit::singleline(&mut picker.typed)
                    .hint_text(text::PATH_HINT)
                    .desired_width(f32::INFINITY),
            );
            if std::mem::take(&mut picker.focus_field) {
                field.request_focus();
            }
            if field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) {
                submit = true;
            }
            ui.horizontal(|ui| {
                if ui.button(text::OPEN_BUTTON).clicked() {
                    submit = true;
                }
                if !picker.dialog_failed && ui.button(text::BROWSE).clicked() {
                    picker.open_dialog(ui.ctx());
                }
            });
        });
    let typed = picker.typed.trim();
    if submit && !typed.is_empty() {
        open.push(PathBuf::from(typed));
        window_open = false;
    }
    picker.path_window = window_open;
}

/// Hides a plain success banner once it is [`BANNER_HIDE_AFTER`] old.
pub fn expire_banner(ctx: &egui::Context, banner: &mut Option<Banner>) {
    if let Some(b) = banner
        && !b.error
        && b.notes.is_empty()
    {
        let age = b.shown.elapsed();
        if age >= BANNER_HIDE_AFTER {
            *banner = None;
        } else {
            ctx.request_repaint_after(BANNER_HIDE_AFTER - age);
        }
    }
}

/// The banner under the top bar (nothing when there is none).
pub fn banner_ui(ui: &mut Ui, banner: &mut Option<Banner>) {
    let Some(b) = banner else {
        return;
    };

    let (fill, stroke) = if b.error {
        (
            Color32::from_rgb(90, 25, 25),
            Color32::from_rgb(255, 120, 120),
        )
    } else {
        (
            Color32::from_rgb(25, 60, 35),
            Color32::from_rgb(120, 220, 140),
        )
    };
    let mut dismiss = false;
    egui::Frame::new()
        .fill(fill)
        .stroke(egui::Stroke::new(1.0, stroke))
        .inner_margin(egui::Margin::symmetric(10, 6))
        .corner_radius(4.0)
        .show(ui, |ui| {
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Min), |ui| {
                if ui.button(text::DISMISS).clicked() {
                    dismiss = true;
                }
                ui.vertical(|ui| {
                    ui.add(
                        egui::Label::new(RichText::new(&b.text).color(Color32::WHITE).strong())
                            .wrap(),
                    );
                    for n in &b.notes {
                        ui.add(
                            egui::Label::new(
                                RichText::new(format!("{}: {n}", text::NOTE))
                                    .color(Color32::from_rgb(255, 215, 120)),
                            )
                            .wrap(),
                        );
                    }
                });
            });
        });
    if dismiss {
        *banner = None;
    }
}
