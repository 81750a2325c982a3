//! The benchmark window: times the two rasterizers (edge functions and the classic scanline)
//! over filter x mode x threads, in a background thread, on the current scene at the canvas
//! size or on the 1080p reference scene; shows a table, a bar chart, the measured edge /
//! scanline ratio next to a published measurement, and llvmpipe's reference figures.
//!
//! The measuring is [`crate::bench`], the same as `barylab bench`.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, TryRecvError, channel};
use std::time::Duration;

use egui::{RichText, Ui};

use crate::app::command::{BenchCommand, BenchSource};
use crate::app::panels::bench_chart;
use crate::bench::{self, BenchRecord};
use crate::raster::{ClipMesh, RenderSettings, Texture};
use crate::scene::Scene;

/// The reference scene, built in so that the app finds it wherever it runs.
const REFERENCE_SCENE: &str = include_str!("../../../assets/scenes/bench-1080p.json");

/// Frames per configuration: default and range.
const FRAMES_DEFAULT: u32 = 5;
const FRAMES_RANGE: (u32, u32) = (1, 200);
/// How often the window polls a running benchmark when nothing else repaints.
const POLL: Duration = Duration::from_millis(100);

enum Message {
    Record(BenchRecord),
    Failed(String),
    Done,
}

struct Running {
    messages: Receiver<Message>,
    stop: Arc<AtomicBool>,
}

/// The benchmark window's state.
pub struct BenchPanel {
    /// Whether the window is shown.
    pub open: bool,
    /// Frames per configuration.
    pub frames: u32,
    /// Which scene a run measures.
    pub source: BenchSource,
    records: Vec<BenchRecord>,
    /// Configurations in the current (or last) run.
    total: usize,
    running: Option<Running>,
    error: Option<String>,
    /// What the shown records measured, e.g. "current scene, 640 x 480".
    measured: Option<String>,
    /// Whether they are of the reference scene (llvmpipe's figures apply).
    measured_reference: bool,
}

impl Default for BenchPanel {
    fn default() -> Self {
        Self {
            open: false,
            frames: FRAMES_DEFAULT,
            source: BenchSource::Canvas,
            records: Vec::new(),
            total: 0,
            running: None,
            error: None,
            measured: None,
            measured_reference: false,
        }
    }
}

impl Drop for BenchPanel {
    fn drop(&mut self) {
        self.stop();
    }
}

/// What one run draws.
pub(crate) struct BenchJob {
    /// The scene's triangles in clip space, as the renderer takes them.
    pub mesh: ClipMesh,
    /// The texture the scene samples.
    pub texture: Arc<Texture>,
    /// The scene's render settings, which each measured configuration varies.
    pub base: RenderSettings,
    /// Shown above the results.
    pub description: String,
    /// The reference scene, whose llvmpipe figures are shown next to the results.
    pub reference: bool,
}

impl BenchJob {
    /// The scene as it is rendered (already sized) with its texture.
    pub fn from_scene(scene: &Scene, texture: Arc<Texture>, description: String) -> Self {
        Self {
            mesh: scene.to_mesh(),
            texture,
            base: scene.settings(),
            description,
            reference: false,
        }
    }

    /// The built-in reference scene, 1920 x 1080.
    pub fn reference() -> Result<Self, String> {
        let scene =
            Scene::from_json(REFERENCE_SCENE, "bench-1080p.json").map_err(|e| e.to_string())?;
        let texture = scene
            .load_texture(std::path::Path::new(""))
            .map_err(|e| e.to_string())?;
        let (w, h) = scene.size();
        Ok(Self {
            reference: true,
            ..Self::from_scene(&scene, Arc::new(texture), format!("bench-1080p, {w} x {h}"))
        })
    }
}

impl BenchPanel {
    /// The records measured so far (in the current or the last run), in matrix order.
    pub fn records(&self) -> &[BenchRecord] {
        &self.records
    }

    /// Whether a run is going on.
    pub fn is_running(&self) -> bool {
        self.running.is_some()
    }

    /// The last error (a configuration that could not be measured).
    pub fn error(&self) -> Option<&str> {
        self.error.as_deref()
    }

    /// Starts measuring `job` in a background thread (stopping any run going on); `ctx` is
    /// asked to repaint after each configuration.
    pub(crate) fn start(&mut self, ctx: &egui::Context, job: BenchJob) {
        self.stop();
        let configs = bench::matrix(bench::available_cores());
        self.total = configs.len();
        self.records.clear();
        self.error = None;
        self.measured = Some(job.description.clone());
        self.measured_reference = job.reference;
        let (tx, rx) = channel();
        let stop = Arc::new(AtomicBool::new(false));
        let stop_flag = stop.clone();
        let frames = self.frames;
        let ctx = ctx.clone();
        let spawned = std::thread::Builder::new()
            .name("barylab-bench".into())
            .spawn(move || {
                for config in configs {
                    if stop_flag.load(Ordering::Relaxed) {
                        break;
                    }
                    let msg =
                        match bench::run_config(&job.mesh, &job.texture, &job.base, config, frames)
                        {
                            Ok(r) => Message::Record(r),
                            Err(e) => Message::Failed(e.to_string()),
                        };
                    let failed = matches!(msg, Message::Failed(_));
                    if tx.send(msg).is_err() || failed {
                        break;
                    }
                    ctx.request_repaint();
                }
                let _ = tx.send(Message::Done);
                ctx.request_repaint();
            });
        match spawned {
            Ok(_) => {
                self.running = Some(Running { messages: rx, stop });
            }
            Err(e) => self.error = Some(e.to_string()),
        }
    }

    /// Asks a run to stop after the configuration it is measuring.
    pub fn stop(&mut self) {
        if let Some(r) = self.running.take() {
            r.stop.store(true, Ordering::Relaxed);
        }
    }

    /// Takes what the background thread reported.
    pub fn poll(&mut self) {
        let Some(running) = &self.running else {
            return;
        };
        let mut finished = false;
        loop {
            match running.messages.try_recv() {
                Ok(Message::Record(r)) => self.records.push(r),
                Ok(Message::Failed(e)) => self.error = Some(e),
                Ok(Message::Done) | Err(TryRecvError::Disconnected) => {
                    finished = true;
                    break;
                }
                Err(TryRecvError::Empty) => break,
            }
        }
        if finished {
            self.running = None;
        }
    }
}

impl BenchPanel {
    /// Applies a command; `current` is the scene as the canvas renders it (sized) and its
    /// texture, if anything is rendered.
    pub fn apply(
        &mut self,
        ctx: &egui::Context,
        command: BenchCommand,
        current: Option<(&Scene, &Arc<Texture>)>,
    ) {
        let lang = crate::app::services::locale::lang(ctx);
        match command {
            BenchCommand::SetOpen(open) => self.open = open,
            BenchCommand::SetSource(source) => self.source = source,
            BenchCommand::SetFrames(frames) => {
                self.frames = frames.clamp(FRAMES_RANGE.0, FRAMES_RANGE.1);
            }
            BenchCommand::Run => {
                let job = match self.source {
                    BenchSource::Canvas => current
                        .map(|(scene, texture)| {
                            let (w, h) = scene.size();
                            BenchJob::from_scene(
                                scene,
                                texture.clone(),
                                lang.tr_with(
                                    "app.bench_panel.current_scene",
                                    &[("w", &w), ("h", &h)],
                                ),
                            )
                        })
                        .ok_or_else(|| lang.tr("app.bench_panel.nothing_to_measure")),
                    BenchSource::Reference => BenchJob::reference(),
                };
                match job {
                    Ok(job) => self.start(ctx, job),
                    Err(e) => self.error = Some(e),
                }
            }
            BenchCommand::Stop => {
                self.stop();
                self.error = Some(lang.tr("app.bench_panel.stopped"));
            }
        }
    }

    /// Once per frame, before the window is drawn: takes what the run reported, and asks for
    /// the next frame while it goes on.
    pub fn frame(&mut self, ctx: &egui::Context) {
        self.poll();
        if self.is_running() {
            ctx.request_repaint_after(POLL);
        }
    }
}

/// The benchmark window (when open).
pub fn bench_ui(ctx: &egui::Context, panel: &BenchPanel) -> Vec<BenchCommand> {
    let lang = crate::app::services::locale::lang(ctx);
    let mut out = Vec::new();
    let mut open = panel.open;
    egui::Window::new(lang.tr("app.bench_panel.title"))
        .id(egui::Id::unique("bench-window"))
        .open(&mut open)
        .default_pos([360.0, 50.0])
        .default_size([900.0, 860.0])
        .vscroll(true)
        .show(ctx, |ui| window_contents(ui, panel, &mut out));
    if open != panel.open {
        out.push(BenchCommand::SetOpen(open));
    }
    out
}

fn window_contents(ui: &mut Ui, panel: &BenchPanel, out: &mut Vec<BenchCommand>) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut source = panel.source;
    ui.horizontal(|ui| {
        ui.radio_value(
            &mut source,
            BenchSource::Canvas,
            lang.tr("app.bench_panel.source_canvas"),
        );
        ui.radio_value(
            &mut source,
            BenchSource::Reference,
            lang.tr("app.bench_panel.source_reference"),
        )
        .on_hover_text(lang.tr("app.bench_panel.source_reference_tip"));
    });
    if source != panel.source {
        out.push(BenchCommand::SetSource(source));
    }
    ui.horizontal(|ui| {
        if panel.is_running() {
            if ui.button(lang.tr("app.bench_panel.stop")).clicked() {
                out.push(BenchCommand::Stop);
            }
        } else if ui
            .button(lang.tr("app.bench_panel.run"))
            .on_hover_text(lang.tr("app.bench_panel.run_tip"))
            .clicked()
        {
            out.push(BenchCommand::Run);
        }
        let label = ui
            .label(lang.tr("app.bench_panel.frames"))
            .on_hover_text(lang.tr("app.bench_panel.frames_tip"));
        let mut frames = panel.frames;
        ui.add(egui::DragValue::new(&mut frames).range(FRAMES_RANGE.0..=FRAMES_RANGE.1))
            .labelled_by(label.id);
        if frames != panel.frames {
            out.push(BenchCommand::SetFrames(frames));
        }
    });
    if panel.total > 0 && (panel.is_running() || panel.records.len() < panel.total) {
        let done = panel.records.len();
        let label = if panel.is_running() {
            &lang.tr("app.bench_panel.running")
        } else {
            &lang.tr("app.bench_panel.stopped")
        };
        ui.add(
            egui::ProgressBar::new(done as f32 / panel.total as f32)
                .text(format!("{label}: {done} / {}", panel.total)),
        );
    }
    if let Some(e) = &panel.error {
        ui.colored_label(ui.visuals().warn_fg_color, e);
    }
    ui.separator();
    if panel.records.is_empty() {
        ui.label(lang.tr("app.bench_panel.no_results"));
    } else {
        if let Some(m) = &panel.measured {
            ui.label(
                RichText::new(format!("{}: {m}", &lang.tr("app.bench_panel.measured"))).strong(),
            );
        }
        let reference = panel.measured_reference;
        bench_chart::table_ui(ui, &panel.records, reference);
        ui.add_space(6.0);
        bench_chart::ratio_ui(ui, &panel.records);
        ui.add_space(6.0);
        ui.label(RichText::new(lang.tr("app.bench_panel.chart_caption")).small());
        bench_chart::chart_ui(ui, &panel.records, reference);
    }
    ui.separator();
    bench_chart::reference_ui(ui);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reference_job_is_the_1080p_scene_with_its_noise_texture() {
        let job = BenchJob::reference().expect("built-in reference scene");
        assert!(job.reference);
        assert_eq!((job.base.width, job.base.height), (1920, 1080));
        assert_eq!((job.texture.width(), job.texture.height()), (1024, 1024));
        assert_eq!(job.mesh.triangles.len(), 2);
        assert_eq!(
            job.mesh.vertices[2].clip,
            glam::DVec4::new(4.0, 4.0, 0.0, 4.0)
        );
    }
}
