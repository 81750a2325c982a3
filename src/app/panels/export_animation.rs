//! File > Export animation…: a sweep of the scene (the sweeps of `barylab animate`) or a
//! recorded drag, as GIF, APNG, WebP or MP4. Frames are figures of the canvas (the Export
//! window's scale, background and caption), rendered by [`crate::animate`] on a thread of
//! their own ([`AnimationJob`]) with a progress bar and Cancel; the file goes into the
//! figures' folder under a fresh name.
//!
//! Recording ([`Recorder`], key R): while on, the canvas's scene and figure options are taken
//! at [`RECORD_FPS`] from egui's clock; after Stop, two sliders trim it, and Export draws each
//! kept state again as a figure at the export scale.

use super::export_animation_ui::{FPS_RANGE, WindowView};
use crate::animate::{Animation, Format, FrameState, Sweep};
use crate::app::BaryApp;
use crate::app::command::{AnimationCommand, AnimationKind};
use crate::app::document::export_settings::ExportSettings;
use crate::app::panels::export::{ExportContext, Outcome, figure_options, figure_scene};
use crate::app::services::recorder::{
    AnimationJob, AnimationSource, RECORD_FPS, RECORD_MAX_FRAMES, Recorder, fresh_path,
};
use crate::i18n::Lang;
use crate::raster::Texture;

/// How often a running export repaints (its progress bar).
const POLL: std::time::Duration = std::time::Duration::from_millis(100);

/// The Export animation window's state and the recorder.
pub struct AnimationPanel {
    /// Whether the window is shown.
    pub open: bool,
    /// A sweep or the recording.
    pub kind: AnimationKind,
    /// The sweep.
    pub sweep: Sweep,
    /// The corner the depth and clip sweeps move.
    pub vertex: usize,
    /// Frames of a sweep.
    pub frames: u32,
    /// Frames per second of the file.
    pub fps: u32,
    /// The file format.
    pub format: Format,
    /// The label language (`None`: the app's).
    pub lang: Option<Lang>,
    /// The recording.
    pub recorder: Recorder,
    /// The export going on.
    job: Option<AnimationJob>,
    /// What the last export did.
    pub outcome: Option<Outcome>,
    /// Whether ffmpeg runs (asked once, when the window first shows).
    pub(crate) ffmpeg: Option<bool>,
}

impl Default for AnimationPanel {
    fn default() -> Self {
        Self {
            open: false,
            kind: AnimationKind::Sweep,
            sweep: Sweep::AffinePerspective,
            vertex: 2,
            frames: 48,
            fps: RECORD_FPS as u32,
            format: Format::Gif,
            lang: None,
            recorder: Recorder::default(),
            job: None,
            outcome: None,
            ffmpeg: None,
        }
    }
}

impl AnimationPanel {
    /// Whether an export is going on.
    pub fn exporting(&self) -> bool {
        self.job.is_some()
    }

    /// The export going on: frames drawn and frames to draw.
    pub fn progress(&self) -> Option<(usize, usize)> {
        self.job.as_ref().map(|j| (j.done(), j.total))
    }
}

/// The figure options a recorded or swept frame starts from: the canvas's, with the export
/// settings, and without the hovered pixel (the pointer is not part of the picture).
fn frame_options(
    app: &ExportContext<'_>,
    settings: &ExportSettings,
) -> crate::figure::FigureOptions {
    crate::figure::FigureOptions {
        hovered: None,
        ..figure_options(app, settings)
    }
}

/// The export context of the canvas as it is now.
fn animation_context<'a>(
    state: &'a crate::app::document::state::AppState,
    canvas: &crate::app::panels::canvas::CanvasState,
    ctx: &egui::Context,
    texture: &'a Texture,
) -> ExportContext<'a> {
    ExportContext {
        state,
        texture,
        size: canvas.output.as_ref().map(|o| o.size),
        pixel_size: canvas.pixel_size,
        hovered: None,
        pixels_per_point: ctx.pixels_per_point(),
    }
}

impl BaryApp {
    /// Once per frame, after the commands: records the ticks due, and takes a finished export.
    pub(crate) fn animation_frame(&mut self, ctx: &egui::Context, texture: &Texture) {
        let lang = self.lang;
        if self.animation.recorder.recording() {
            let now = ctx.input(|i| i.time);
            let app = animation_context(&self.state, &self.canvas, ctx, texture);
            let settings = &self.export.settings;
            let state = || FrameState {
                scene: app.size.map_or_else(
                    || app.state.scene.clone(),
                    |size| figure_scene(app.state, size),
                ),
                options: frame_options(&app, settings),
                filled: None,
            };
            let capped = app.size.is_some() && self.animation.recorder.capture(now, state);
            if capped {
                let seconds = RECORD_MAX_FRAMES as f64 / RECORD_FPS;
                let o = Outcome::failed(lang.tr_with(
                    "animate.app.capped",
                    &[("n", &RECORD_MAX_FRAMES), ("seconds", &seconds)],
                ));
                self.message = Some(crate::app::panels::status::Message::error(
                    o.summary.clone(),
                    None,
                ));
                self.animation.outcome = Some(o);
            }
            ctx.request_repaint_after(std::time::Duration::from_secs_f64(1.0 / RECORD_FPS));
        }
        let Some(job) = &self.animation.job else {
            return;
        };
        match job.finished() {
            None => ctx.request_repaint_after(POLL),
            Some(result) => {
                let o = match result {
                    Ok(w) => Outcome::done(lang.tr_with(
                        "animate.app.wrote",
                        &[
                            ("path", &w.path.display()),
                            ("n", &w.frames),
                            ("w", &w.size.0),
                            ("h", &w.size.1),
                            ("size", &crate::files::bytes(w.bytes as u64)),
                        ],
                    )),
                    Err(e) => Outcome::failed(e),
                };
                self.message = Some(crate::app::panels::status::Message {
                    text: o.summary.clone(),
                    error: o.error,
                    cause: None,
                });
                self.animation.outcome = Some(o);
                self.animation.job = None;
                ctx.request_repaint();
            }
        }
    }

    /// Applies a command of the window or the R key.
    pub(crate) fn apply_animation(
        &mut self,
        ctx: &egui::Context,
        command: AnimationCommand,
        texture: &std::sync::Arc<Texture>,
    ) {
        let panel = &mut self.animation;
        match command {
            AnimationCommand::Open => panel.open = true,
            AnimationCommand::Close => panel.open = false,
            AnimationCommand::SetKind(k) => panel.kind = k,
            AnimationCommand::SetSweep(s) => panel.sweep = s,
            AnimationCommand::SetVertex(v) => panel.vertex = v,
            AnimationCommand::SetFrames(n) => {
                panel.frames =
                    n.clamp(crate::animate::FRAME_RANGE.0, crate::animate::FRAME_RANGE.1);
            }
            AnimationCommand::SetFps(f) => panel.fps = f.clamp(FPS_RANGE.0, FPS_RANGE.1),
            AnimationCommand::SetFormat(f) => panel.format = f,
            AnimationCommand::SetLang(l) => panel.lang = l,
            AnimationCommand::SetTrim(a, b) => panel.recorder.set_trim(a, b),
            AnimationCommand::ToggleRecord => {
                if panel.recorder.recording() {
                    panel.recorder.stop();
                } else {
                    panel.recorder.start(ctx.input(|i| i.time));
                    panel.open = true;
                    panel.kind = AnimationKind::Recording;
                    panel.outcome = None;
                }
            }
            AnimationCommand::Cancel => {
                if let Some(job) = &panel.job {
                    job.cancel();
                }
            }
            AnimationCommand::Export => {
                let outcome = self
                    .start_animation(ctx, texture)
                    .err()
                    .map(Outcome::failed);
                if let Some(o) = &outcome {
                    self.message = Some(crate::app::panels::status::Message::error(
                        o.summary.clone(),
                        None,
                    ));
                }
                self.animation.outcome = outcome;
            }
        }
    }

    /// Starts the export of the sweep or the trimmed recording.
    fn start_animation(
        &mut self,
        ctx: &egui::Context,
        texture: &std::sync::Arc<Texture>,
    ) -> Result<(), String> {
        let lang = self.lang;
        let panel = &self.animation;
        if panel.job.is_some() || panel.recorder.recording() {
            return Err(lang.tr("animate.app.busy"));
        }
        let folder = self
            .export
            .settings
            .folder
            .clone()
            .ok_or_else(|| lang.tr("app.export.no_folder"))?;
        if panel.format == Format::Mp4 && !crate::animate::encode::has_ffmpeg() {
            return Err(crate::animate::AnimateError::NoFfmpeg.to_string());
        }
        let app = animation_context(&self.state, &self.canvas, ctx, texture);
        let size = app.size.ok_or_else(|| lang.tr("app.export.no_canvas"))?;
        let settings = &self.export.settings;
        let source = match panel.kind {
            AnimationKind::Sweep => AnimationSource::Sweep {
                scene: Box::new(figure_scene(app.state, size)),
                animation: Animation {
                    sweep: panel.sweep,
                    frames: panel.frames,
                    vertex: panel.vertex,
                    options: frame_options(&app, settings),
                },
            },
            AnimationKind::Recording => {
                let mut states = panel.recorder.trimmed();
                if states.len() < 2 {
                    return Err(lang.tr("animate.app.too_short"));
                }
                // Drawn at the export's scale, background and caption.
                for s in &mut states {
                    s.options.scale = settings.scale;
                    s.options.background = settings.background;
                    s.options.caption = settings.caption;
                }
                AnimationSource::Recording(states)
            }
        };
        let path = fresh_path(&folder, panel.format)?;
        let repaint = ctx.clone();
        let job = AnimationJob::start(
            source,
            std::sync::Arc::clone(texture),
            panel.lang.unwrap_or(lang),
            (f64::from(panel.fps), panel.format),
            path,
            move || repaint.request_repaint(),
        );
        self.animation.job = Some(job);
        ctx.request_repaint_after(POLL);
        Ok(())
    }

    /// The Export animation window, when open.
    pub(crate) fn animation_window(
        &mut self,
        ctx: &egui::Context,
        out: &mut Vec<crate::app::command::AppCommand>,
    ) {
        if !self.animation.open {
            return;
        }
        if self.animation.ffmpeg.is_none() {
            self.animation.ffmpeg = Some(crate::animate::encode::has_ffmpeg());
        }
        let lang = crate::app::services::locale::lang(ctx);
        let mut open = true;
        let mut cmds: Vec<crate::app::command::AppCommand> = Vec::new();
        let panel = &self.animation;
        let view = WindowView {
            kind: panel.kind,
            sweep: panel.sweep,
            vertex: panel.vertex,
            frames: panel.frames,
            fps: panel.fps,
            format: panel.format,
            lang: panel.lang,
            ffmpeg: panel.ffmpeg.unwrap_or(false),
            recorder: &panel.recorder,
            progress: panel.progress(),
            outcome: panel.outcome.as_ref(),
            settings: &self.export.settings,
            pinned: self.state.view.pinned,
            size: self.canvas.output.as_ref().map(|o| o.size),
            cjk: self.fonts.cjk,
        };
        let folder_text = &mut self.export.folder_text;
        egui::Window::new(lang.tr("animate.app.window"))
            .id(egui::Id::unique("animation-window"))
            .open(&mut open)
            .collapsible(false)
            .resizable(false)
            .pivot(egui::Align2::RIGHT_TOP)
            .default_pos(ctx.content_rect().right_top() + egui::vec2(-20.0, 60.0))
            .show(ctx, |ui| {
                super::export_animation_ui::actions(ui, &view, &mut cmds);
                egui::ScrollArea::vertical().show(ui, |ui| {
                    super::export_animation_ui::contents(ui, &view, folder_text, &mut cmds);
                });
            });
        if !open {
            cmds.push(AnimationCommand::Close.into());
        }
        out.extend(cmds);
    }
}
