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

use egui::{Color32, RichText, Ui};

use crate::bench::{self, BenchRecord};
use crate::raster::{ClipMesh, RenderSettings, Texture};
use crate::scene::Scene;

/// User-facing strings of the benchmark window.
pub mod text {
    pub const TITLE: &str = "Benchmark";
    pub const OPEN: &str = "Benchmark";
    pub const OPEN_TIP: &str = "Time the two rasterizers (edge functions, scanline) on this \
        scene: every filter x mode x thread count, median ms per frame. Compare with a published \
        measurement and with Mesa's llvmpipe.";
    pub const RUN: &str = "Run";
    pub const RUN_TIP: &str = "Render every configuration the given number of times in the \
        background and keep the median. The app stays usable; timings are noisier while you \
        interact.";
    pub const STOP: &str = "Stop";
    pub const FRAMES: &str = "Frames per configuration";
    pub const FRAMES_TIP: &str = "Each configuration is rendered this many times; the median \
        time is shown.";
    pub const SOURCE_CANVAS: &str = "Current scene at canvas size";
    pub const SOURCE_REFERENCE: &str = "Reference scene (1920 x 1080)";
    pub const SOURCE_REFERENCE_TIP: &str = "assets/scenes/bench-1080p.json: a full-screen quad, \
        w from 1 to 4, 1024 x 1024 noise texture. llvmpipe's reference figures are for this \
        scene.";
    pub const NOTHING_TO_MEASURE: &str = "Nothing rendered yet to measure.";
    pub const RUNNING: &str = "measuring";
    pub const STOPPED: &str = "stopped";
    pub const NO_RESULTS: &str = "Press Run to measure.";
    pub const MEASURED: &str = "Measured";
    pub const FILTER: &str = "filter";
    pub const MODE: &str = "mode";
    pub const THREADS: &str = "threads";
    pub const EDGE: &str = "edge functions";
    pub const SCANLINE: &str = "scanline";
    pub const RATIO: &str = "edge / scanline";
    pub const LLVMPIPE_REF: &str = "llvmpipe (reference)";
    pub const MS: &str = "ms";
    pub const MPIX: &str = "Mpix/s";
    pub const CHART_Y: &str = "ms per frame";
    pub const CHART_CAPTION: &str = "Median ms per frame, lower is faster.";
    pub const SEED_CLAIM: &str = "A rasterizer tutorial measured per-pixel barycentric evaluation about 2x \
        slower than the scanline with increments: 1.40 ms vs 0.73 ms (= 1.9x).";
    pub const MEASURED_RATIO: &str = "Measured here: edge functions take";
    pub const MEASURED_RATIO_END: &str = "the scanline's time (median over the cells above).";
    pub const REFERENCE_HEADING: &str = "llvmpipe reference figures";
    pub const REFERENCE_NOTE: &str = "Mesa's llvmpipe (OpenGL on the CPU) drawing the reference \
        scene, perspective-correct, draw only; measured on this project's 2-core machine, \
        quoted from the performance issue (not measured by this window). \
        `cargo bench --bench llvmpipe` measures them again.";
    pub const THREAD_1: &str = "1 thread";
    pub const THREADS_N: &str = "threads";
}

/// Which scene the benchmark draws.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BenchSource {
    /// The scene on the canvas, at the canvas's render size.
    #[default]
    Canvas,
    /// `assets/scenes/bench-1080p.json` (built in), 1920 x 1080.
    Reference,
}

/// The reference scene, built in so that the app finds it wherever it runs.
const REFERENCE_SCENE: &str = include_str!("../../assets/scenes/bench-1080p.json");

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
pub struct BenchJob {
    pub mesh: ClipMesh,
    pub texture: Arc<Texture>,
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
    pub fn start(&mut self, ctx: &egui::Context, job: BenchJob) {
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

/// The top-bar toggle that opens and closes the window.
pub fn toggle_ui(ui: &mut Ui, panel: &mut BenchPanel) {
    if ui
        .selectable_label(panel.open, text::OPEN)
        .on_hover_text(text::OPEN_TIP)
        .clicked()
    {
        panel.open = !panel.open;
    }
}

/// The benchmark window. `current` is the scene as the canvas renders it (sized) and its
/// texture, if anything is rendered.
pub fn bench_ui(
    ctx: &egui::Context,
    panel: &mut BenchPanel,
    current: Option<(&Scene, &Arc<Texture>)>,
) {
    panel.poll();
    if panel.is_running() {
        ctx.request_repaint_after(POLL);
    }
    let mut open = panel.open;
    egui::Window::new(text::TITLE)
        .open(&mut open)
        .default_pos([360.0, 50.0])
        .default_size([900.0, 860.0])
        .vscroll(true)
        .show(ctx, |ui| window_contents(ui, panel, current));
    panel.open = open;
}

fn window_contents(ui: &mut Ui, panel: &mut BenchPanel, current: Option<(&Scene, &Arc<Texture>)>) {
    ui.horizontal(|ui| {
        ui.radio_value(&mut panel.source, BenchSource::Canvas, text::SOURCE_CANVAS);
        ui.radio_value(
            &mut panel.source,
            BenchSource::Reference,
            text::SOURCE_REFERENCE,
        )
        .on_hover_text(text::SOURCE_REFERENCE_TIP);
    });
    ui.horizontal(|ui| {
        if panel.is_running() {
            if ui.button(text::STOP).clicked() {
                panel.stop();
                panel.error = Some(text::STOPPED.into());
            }
        } else if ui.button(text::RUN).on_hover_text(text::RUN_TIP).clicked() {
            let job = match panel.source {
                BenchSource::Canvas => current
                    .map(|(scene, texture)| {
                        let (w, h) = scene.size();
                        BenchJob::from_scene(
                            scene,
                            texture.clone(),
                            format!("current scene, {w} x {h}"),
                        )
                    })
                    .ok_or_else(|| text::NOTHING_TO_MEASURE.to_string()),
                BenchSource::Reference => BenchJob::reference(),
            };
            match job {
                Ok(job) => panel.start(ui.ctx(), job),
                Err(e) => panel.error = Some(e),
            }
        }
        let label = ui.label(text::FRAMES).on_hover_text(text::FRAMES_TIP);
        ui.add(egui::DragValue::new(&mut panel.frames).range(FRAMES_RANGE.0..=FRAMES_RANGE.1))
            .labelled_by(label.id);
    });
    if panel.total > 0 && (panel.is_running() || panel.records.len() < panel.total) {
        let done = panel.records.len();
        let label = if panel.is_running() {
            text::RUNNING
        } else {
            text::STOPPED
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
        ui.label(text::NO_RESULTS);
    } else {
        if let Some(m) = &panel.measured {
            ui.label(RichText::new(format!("{}: {m}", text::MEASURED)).strong());
        }
        let reference = panel.measured_reference;
        table_ui(ui, &panel.records, reference);
        ui.add_space(6.0);
        ratio_ui(ui, &panel.records);
        ui.add_space(6.0);
        ui.label(RichText::new(text::CHART_CAPTION).small());
        chart_ui(ui, &panel.records, reference);
    }
    ui.separator();
    reference_ui(ui);
}

/// llvmpipe's reference median for one cell (perspective only), if quoted.
fn llvmpipe_reference(filter: &str, mode: &str, threads: usize) -> Option<f64> {
    if mode != "perspective" {
        return None;
    }
    bench::LLVMPIPE_REFERENCE_1080P
        .iter()
        .find(|(t, f, _)| *t == threads && *f == filter)
        .map(|(_, _, ms)| *ms)
}

/// The filter x mode x threads cells in table order.
fn cells(records: &[BenchRecord]) -> Vec<(String, String, usize)> {
    let mut out: Vec<(String, String, usize)> = Vec::new();
    for r in records {
        let cell = (r.filter.clone(), r.mode.clone(), r.threads);
        if !out.contains(&cell) {
            out.push(cell);
        }
    }
    out
}

fn table_ui(ui: &mut Ui, records: &[BenchRecord], reference: bool) {
    let ms =
        |r: Option<&BenchRecord>| r.map_or("…".to_string(), |r| format!("{:.1}", r.median_ms));
    egui::Grid::new("bench_table")
        .striped(true)
        .spacing([18.0, 4.0])
        .show(ui, |ui| {
            for h in [text::FILTER, text::MODE, text::THREADS] {
                ui.label(RichText::new(h).strong());
            }
            ui.label(
                RichText::new(format!("{} {}", text::EDGE, text::MS))
                    .strong()
                    .color(EDGE_COLOR),
            );
            ui.label(
                RichText::new(format!("{} {}", text::SCANLINE, text::MS))
                    .strong()
                    .color(SCANLINE_COLOR),
            );
            ui.label(RichText::new(text::RATIO).strong());
            ui.label(RichText::new(format!("{} {}", text::EDGE, text::MPIX)).strong());
            if reference {
                ui.label(
                    RichText::new(format!("{} {}", text::LLVMPIPE_REF, text::MS))
                        .strong()
                        .color(LLVMPIPE_COLOR),
                );
            }
            ui.end_row();
            for (filter, mode, threads) in cells(records) {
                let edge = bench::find(records, "edge", &filter, &mode, threads);
                let scan = bench::find(records, "scanline", &filter, &mode, threads);
                ui.label(&filter);
                ui.label(&mode);
                ui.label(threads.to_string());
                ui.monospace(ms(edge));
                ui.monospace(ms(scan));
                ui.monospace(
                    bench::edge_over_scanline(records, &filter, &mode, threads)
                        .map_or("…".to_string(), |x| format!("{x:.2}x")),
                );
                ui.monospace(edge.map_or("…".to_string(), |r| format!("{:.1}", r.mpix_per_s)));
                if reference {
                    ui.monospace(
                        llvmpipe_reference(&filter, &mode, threads)
                            .map_or("-".to_string(), |ms| format!("{ms:.1}")),
                    );
                }
                ui.end_row();
            }
        });
}

/// The median over the measured cells of edge / scanline.
fn median_ratio(records: &[BenchRecord]) -> Option<f64> {
    let ratios: Vec<f64> = cells(records)
        .iter()
        .filter_map(|(f, m, t)| bench::edge_over_scanline(records, f, m, *t))
        .collect();
    bench::median(&ratios)
}

fn ratio_ui(ui: &mut Ui, records: &[BenchRecord]) {
    ui.label(text::SEED_CLAIM);
    if let Some(r) = median_ratio(records) {
        ui.label(
            RichText::new(format!(
                "{} {r:.2}x {}",
                text::MEASURED_RATIO,
                text::MEASURED_RATIO_END
            ))
            .strong(),
        );
    }
}

const EDGE_COLOR: Color32 = Color32::from_rgb(90, 160, 240);
const SCANLINE_COLOR: Color32 = Color32::from_rgb(240, 160, 60);
const LLVMPIPE_COLOR: Color32 = Color32::from_rgb(150, 150, 150);
/// The y range reaches this multiple of the tallest bar, leaving room for the legend.
const LEGEND_HEADROOM: f64 = 1.3;
/// Cell labels under the chart, in points (three short lines fit a cell's width).
const TICK_LABEL_SIZE: f32 = 15.0;
/// Bar width and offsets within a cell (cells are 1 apart on the x axis).
const BAR_WIDTH: f64 = 0.26;

fn chart_ui(ui: &mut Ui, records: &[BenchRecord], reference: bool) {
    use egui_plot::{AxisHints, Bar, BarChart, Corner, GridMark, Legend, Plot};
    let cells = cells(records);
    let series = |name: &str,
                  offset: f64,
                  color: Color32,
                  value: &dyn Fn(&str, &str, usize) -> Option<f64>| {
        let bars: Vec<Bar> = cells
            .iter()
            .enumerate()
            .filter_map(|(i, (f, m, t))| {
                value(f, m, *t).map(|ms| {
                    Bar::new(i as f64 + offset, ms)
                        .width(BAR_WIDTH)
                        .name(format!("{f} {m} {t}"))
                })
            })
            .collect();
        BarChart::new(name, bars).color(color)
    };
    let ms_of = |name: &'static str| {
        move |f: &str, m: &str, t: usize| bench::find(records, name, f, m, t).map(|r| r.median_ms)
    };
    let edge = series(text::EDGE, -BAR_WIDTH, EDGE_COLOR, &ms_of("edge"));
    let scan = series(text::SCANLINE, 0.0, SCANLINE_COLOR, &ms_of("scanline"));
    let llvm = reference.then(|| {
        series(text::LLVMPIPE_REF, BAR_WIDTH, LLVMPIPE_COLOR, &|f, m, t| {
            llvmpipe_reference(f, m, t)
        })
    });
    let labels: Vec<String> = cells
        .iter()
        .map(|(f, m, t)| {
            let threads = if *t == 1 {
                text::THREAD_1.to_string()
            } else {
                format!("{t} {}", text::THREADS_N)
            };
            format!("{f}\n{m}\n{threads}")
        })
        .collect();
    let n = cells.len();
    let tallest = records.iter().map(|r| r.median_ms).fold(0.0, f64::max);
    Plot::new("bench_chart")
        .height(280.0)
        .legend(Legend::default().position(Corner::LeftTop))
        .y_axis_label(text::CHART_Y)
        .include_y(0.0)
        .include_y(tallest * LEGEND_HEADROOM)
        .include_x(-0.6)
        .include_x(n as f64 - 0.4)
        .allow_zoom(false)
        .allow_drag(false)
        .allow_scroll(false)
        .allow_boxed_zoom(false)
        .show_x(false)
        .x_grid_spacer(move |_| {
            (0..n)
                .map(|i| GridMark {
                    value: i as f64,
                    step_size: 1.0,
                })
                .collect()
        })
        .custom_x_axes(vec![
            AxisHints::new_x()
                .min_thickness(60.0)
                .tick_label_font(egui::FontId::proportional(TICK_LABEL_SIZE))
                .formatter(move |mark, _| {
                    let i = mark.value.round();
                    if (mark.value - i).abs() < 1e-6 && i >= 0.0 {
                        labels.get(i as usize).cloned().unwrap_or_default()
                    } else {
                        String::new()
                    }
                }),
        ])
        .show(ui, |plot| {
            plot.bar_chart(edge);
            plot.bar_chart(scan);
            if let Some(l) = llvm {
                plot.bar_chart(l);
            }
        });
}

fn reference_ui(ui: &mut Ui) {
    ui.label(RichText::new(text::REFERENCE_HEADING).strong());
    egui::Grid::new("llvmpipe_reference")
        .spacing([18.0, 2.0])
        .show(ui, |ui| {
            ui.label("");
            ui.label(RichText::new("nearest").strong());
            ui.label(RichText::new("bilinear").strong());
            ui.end_row();
            for threads in [1usize, 2] {
                ui.label(if threads == 1 {
                    text::THREAD_1.to_string()
                } else {
                    format!("{threads} {}", text::THREADS_N)
                });
                for filter in ["nearest", "bilinear"] {
                    let ms = llvmpipe_reference(filter, "perspective", threads);
                    ui.monospace(ms.map_or("-".into(), |ms| {
                        format!(
                            "{ms:.1} {} ({:.0} {})",
                            text::MS,
                            bench::mpix_per_s(1920, 1080, ms),
                            text::MPIX
                        )
                    }));
                }
                ui.end_row();
            }
        });
    ui.label(RichText::new(text::REFERENCE_NOTE).small());
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

    #[test]
    fn llvmpipe_reference_figures_are_for_perspective_only() {
        assert_eq!(llvmpipe_reference("bilinear", "perspective", 1), Some(11.8));
        assert_eq!(llvmpipe_reference("nearest", "perspective", 2), Some(2.5));
        assert_eq!(llvmpipe_reference("nearest", "affine", 2), None);
        assert_eq!(llvmpipe_reference("nearest", "perspective", 4), None);
    }
}
