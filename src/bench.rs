//! Timing the rasterizers: the configuration matrix (rasterizer x filter x mode x threads),
//! one [`BenchRecord`] per configuration, median milliseconds per frame and Mpixel/s.
//!
//! Used by `barylab bench` and by the app's benchmark panel (which runs one configuration at
//! a time in a background thread to show progress). Every timed frame goes through
//! [`draw_frame`], the single place that calls the renderer. No egui here.

use std::time::Instant;

use crate::figure::heatmap;
use crate::raster::render::{Rasterizer, RenderError};
use crate::raster::{self, Buffers, ClipMesh, Filter, Interpolation, RenderSettings, Texture};

/// What a timed frame draws, as the app's compare modes do.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum View {
    /// One image in the configuration's mode (colour and depth).
    #[default]
    Single,
    /// Both modes, side by side (two colour-and-depth renders).
    Side,
    /// Both modes, one each side of the wipe line (two renders; composing them is a copy).
    Wipe,
    /// One image that keeps the triangle and the uv of both modes, then the texel-difference
    /// heatmap (as the app's difference view).
    Difference,
}

/// The short name of a view in records and tables.
pub fn view_name(v: View) -> &'static str {
    match v {
        View::Single => "single",
        View::Side => "side",
        View::Wipe => "wipe",
        View::Difference => "difference",
    }
}

/// One cell of the matrix: what to draw with and on how many worker threads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BenchConfig {
    /// Edge functions or the scanline.
    pub rasterizer: Rasterizer,
    /// Texture filter.
    pub filter: Filter,
    /// Affine or perspective-correct interpolation.
    pub mode: Interpolation,
    /// Worker threads of the pool the frames are drawn on.
    pub threads: usize,
}

/// The measured result of one configuration (the JSON of `barylab bench --json`).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct BenchRecord {
    /// `edge`, `scanline` (or `llvmpipe` for the OpenGL reference harness).
    pub rasterizer: String,
    /// `nearest` or `bilinear`.
    pub filter: String,
    /// `affine` or `perspective` (with a two-mode view: the mode of the single view it is
    /// compared with).
    pub mode: String,
    /// `single`, `side`, `wipe` or `difference` ([`View`]).
    #[serde(default = "single_view")]
    pub view: String,
    /// Worker threads the frames were drawn on.
    pub threads: usize,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Median wall-clock time of one frame.
    pub median_ms: f64,
    /// `width * height / median time`, in millions of pixels per second.
    pub mpix_per_s: f64,
}

/// Why a configuration could not be measured.
#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    /// The thread pool could not be built.
    #[error("cannot start {threads} worker threads: {reason}")]
    Threads {
        /// The threads asked for.
        threads: usize,
        /// The thread pool's error.
        reason: String,
    },
    /// The render failed (bad image size, not enough memory).
    #[error(transparent)]
    Render(#[from] RenderError),
    /// Zero frames were asked for.
    #[error("frames must be at least 1")]
    NoFrames,
    /// The view's renders together do not fit the memory limit.
    #[error(transparent)]
    Memory(#[from] crate::budget::MemoryError),
}

/// The short name of a rasterizer in records and tables.
pub fn rasterizer_name(r: Rasterizer) -> &'static str {
    match r {
        Rasterizer::EdgeFunction => "edge",
        Rasterizer::Scanline => "scanline",
    }
}

/// The short name of a filter in records and tables.
pub fn filter_name(f: Filter) -> &'static str {
    match f {
        Filter::Nearest => "nearest",
        Filter::Bilinear => "bilinear",
        Filter::Trilinear => "trilinear",
    }
}

/// The short name of an interpolation mode in records and tables.
pub fn mode_name(m: Interpolation) -> &'static str {
    match m {
        Interpolation::Affine => "affine",
        Interpolation::Perspective => "perspective",
    }
}

/// The thread counts measured on a machine with `cores` cores: 1, and `cores` if more.
pub fn thread_counts(cores: usize) -> Vec<usize> {
    if cores > 1 { vec![1, cores] } else { vec![1] }
}

/// The cores of this machine (1 if unknown).
pub fn available_cores() -> usize {
    std::thread::available_parallelism().map_or(1, usize::from)
}

/// Every configuration, in the order `barylab bench` prints them: rasterizer (edge, scanline)
/// x filter (nearest, bilinear) x mode (affine, perspective) x threads ([`thread_counts`]).
///
/// ```
/// let m = barylab::bench::matrix(2);
/// assert_eq!(m.len(), 2 * 2 * 2 * 2);
/// assert_eq!(m[0].threads, 1);
/// assert_eq!(m[1].threads, 2);
/// ```
pub fn matrix(cores: usize) -> Vec<BenchConfig> {
    let threads = thread_counts(cores);
    let mut out = Vec::new();
    for rasterizer in [Rasterizer::EdgeFunction, Rasterizer::Scanline] {
        for filter in [Filter::Nearest, Filter::Bilinear] {
            for mode in [Interpolation::Affine, Interpolation::Perspective] {
                for &threads in &threads {
                    out.push(BenchConfig {
                        rasterizer,
                        filter,
                        mode,
                        threads,
                    });
                }
            }
        }
    }
    out
}

/// Draws one frame for timing: colour and depth into `frame`, reused from frame to frame,
/// with the fast path the app's canvas uses (`raster::render_into`). This is the only call
/// of the renderer in the benchmark.
pub fn draw_frame(
    frame: &mut raster::Framebuffer,
    mesh: &ClipMesh,
    texture: &Texture,
    settings: &RenderSettings,
) -> Result<(), RenderError> {
    raster::render_into(frame, mesh, texture, settings, raster::Buffers::ColorDepth)
}

/// Median of the samples (the upper one of the middle two for an even count); `None` when
/// empty.
///
/// ```
/// assert_eq!(barylab::bench::median(&[3.0, 1.0, 2.0]), Some(2.0));
/// assert_eq!(barylab::bench::median(&[4.0, 1.0, 3.0, 2.0]), Some(3.0));
/// assert_eq!(barylab::bench::median(&[]), None);
/// ```
pub fn median(samples: &[f64]) -> Option<f64> {
    let mut s = samples.to_vec();
    s.sort_by(f64::total_cmp);
    s.get(s.len() / 2).copied()
}

/// Millions of pixels per second for a `width x height` frame drawn in `ms` milliseconds:
/// `width * height / (ms * 1000)`.
///
/// ```
/// assert_eq!(barylab::bench::mpix_per_s(1000, 1000, 10.0), 100.0);
/// ```
pub fn mpix_per_s(width: u32, height: u32, ms: f64) -> f64 {
    f64::from(width) * f64::from(height) / (ms * 1e3)
}

fn single_view() -> String {
    view_name(View::Single).to_string()
}

/// What [`draw_view`] draws into, kept from frame to frame as the app keeps it: one image per
/// mode and the difference view's heatmap.
pub struct ViewFrames {
    /// The affine and the perspective-correct image (the single view uses the first).
    pub images: [raster::Framebuffer; 2],
    /// The difference view's heatmap.
    pub heatmap: heatmap::Heatmap,
}

/// Draws one frame of `view` for timing, in the frames given (reused from frame to frame): [`draw_frame`] for each image, and for the difference view the heatmap
/// (`figure::heatmap`) of the uv buffers, as the app's canvas does.
pub fn draw_view(
    frames: &mut ViewFrames,
    mesh: &ClipMesh,
    texture: &Texture,
    settings: &RenderSettings,
    view: View,
) -> Result<(), RenderError> {
    let ViewFrames {
        images: [a, p],
        heatmap: heat,
    } = frames;
    let both = |a: &mut raster::Framebuffer, p: &mut raster::Framebuffer, buffers| {
        for (frame, mode) in [(a, Interpolation::Affine), (p, Interpolation::Perspective)] {
            let s = RenderSettings { mode, ..*settings };
            raster::render_into(frame, mesh, texture, &s, buffers)?;
        }
        Ok::<(), RenderError>(())
    };
    match view {
        View::Single => draw_frame(a, mesh, texture, settings),
        View::Side | View::Wipe => both(a, p, Buffers::ColorDepth),
        View::Difference => {
            // As the app's canvas: one render in the configuration's mode that keeps the
            // texel difference of the two uvs, then the heatmap.
            raster::render_into(a, mesh, texture, settings, Buffers::DepthDifference)?;
            heatmap::heatmap_into(a, (texture.width(), texture.height()), heat)?;
            std::hint::black_box(&heat.pixels);
            Ok(())
        }
    }
}

/// Refuses a view whose framebuffers, kept together from frame to frame, do not fit the
/// memory limit: side by side and wipe keep two images ([`draw_view`]), so they need twice
/// one render's memory.
fn check_view_memory(
    mesh: &ClipMesh,
    settings: &RenderSettings,
    view: View,
) -> Result<(), crate::budget::MemoryError> {
    let (renders, buffers) = match view {
        View::Single => (1, Buffers::ColorDepth),
        View::Side | View::Wipe => (2, Buffers::ColorDepth),
        View::Difference => (1, Buffers::DepthDifference),
    };
    let (w, h) = (settings.width, settings.height);
    let (vertices, triangles) = (mesh.vertices.len(), mesh.triangles.len());
    crate::budget::check(
        || {
            format!(
                "the {} view at {w}x{h} ({renders} render{} of {triangles} triangles)",
                view_name(view),
                if renders == 1 { "" } else { "s" }
            )
        },
        renders * crate::raster::footprint::render_need(w, h, buffers, vertices, triangles),
    )
}

/// Times `frames` frames of one configuration, `base` giving everything else (size, wrap,
/// shading, background), and returns the median.
pub fn run_config(
    mesh: &ClipMesh,
    texture: &Texture,
    base: &RenderSettings,
    config: BenchConfig,
    frames: u32,
) -> Result<BenchRecord, BenchError> {
    run_view(mesh, texture, base, config, frames, View::Single)
}

/// [`run_config`] drawing `view` in each frame ([`draw_view`]).
pub fn run_view(
    mesh: &ClipMesh,
    texture: &Texture,
    base: &RenderSettings,
    config: BenchConfig,
    frames: u32,
    view: View,
) -> Result<BenchRecord, BenchError> {
    if frames == 0 {
        return Err(BenchError::NoFrames);
    }
    let settings = RenderSettings {
        rasterizer: config.rasterizer,
        filter: config.filter,
        mode: config.mode,
        ..*base
    };
    let workers = rayon::ThreadPoolBuilder::new()
        .num_threads(config.threads)
        .build()
        .map_err(|e| BenchError::Threads {
            threads: config.threads,
            reason: e.to_string(),
        })?;
    check_view_memory(mesh, &settings, view)?;
    let mut times = Vec::with_capacity(frames as usize);
    let mut images = ViewFrames {
        images: [0, 1].map(|_| raster::Framebuffer::empty()),
        heatmap: heatmap::Heatmap::default(),
    };
    for _ in 0..frames {
        let start = Instant::now();
        workers.install(|| draw_view(&mut images, mesh, texture, &settings, view))?;
        times.push(start.elapsed().as_secs_f64() * 1e3);
    }
    let median_ms = median(&times).ok_or(BenchError::NoFrames)?;
    Ok(BenchRecord {
        rasterizer: rasterizer_name(config.rasterizer).to_string(),
        filter: filter_name(config.filter).to_string(),
        mode: mode_name(config.mode).to_string(),
        view: view_name(view).to_string(),
        threads: config.threads,
        width: settings.width,
        height: settings.height,
        median_ms,
        mpix_per_s: mpix_per_s(settings.width, settings.height, median_ms),
    })
}

/// The records as the plain-text table `barylab bench` prints (header line first).
pub fn text_table(records: &[BenchRecord]) -> String {
    let mut out = format!(
        "{:<10} {:<9} {:<12} {:<10} {:>7} {:>11} {:>11} {:>9}\n",
        "rasterizer", "filter", "mode", "view", "threads", "size", "median ms", "Mpix/s"
    );
    for r in records {
        out.push_str(&format!(
            "{:<10} {:<9} {:<12} {:<10} {:>7} {:>11} {:>11.2} {:>9.1}\n",
            r.rasterizer,
            r.filter,
            r.mode,
            r.view,
            r.threads,
            format!("{}x{}", r.width, r.height),
            r.median_ms,
            r.mpix_per_s
        ));
    }
    out
}

/// The record of `rasterizer` for one filter x mode x threads cell, if measured.
pub fn find<'a>(
    records: &'a [BenchRecord],
    rasterizer: &str,
    filter: &str,
    mode: &str,
    threads: usize,
) -> Option<&'a BenchRecord> {
    records.iter().find(|r| {
        r.rasterizer == rasterizer && r.filter == filter && r.mode == mode && r.threads == threads
    })
}

/// How many times longer the edge-function rasterizer took than the scanline one for one
/// filter x mode x threads cell: `edge median / scanline median` (a published tutorial measured 1.40 ms
/// / 0.73 ms, about 1.9). `None` unless both were measured.
///
/// ```
/// use barylab::bench::{BenchRecord, edge_over_scanline};
/// let rec = |r: &str, ms: f64| BenchRecord {
///     rasterizer: r.into(), filter: "nearest".into(), mode: "affine".into(),
///     view: "single".into(), threads: 1,
///     width: 10, height: 10, median_ms: ms, mpix_per_s: 0.0,
/// };
/// let records = [rec("edge", 3.0), rec("scanline", 2.0)];
/// assert_eq!(edge_over_scanline(&records, "nearest", "affine", 1), Some(1.5));
/// assert_eq!(edge_over_scanline(&records, "bilinear", "affine", 1), None);
/// ```
pub fn edge_over_scanline(
    records: &[BenchRecord],
    filter: &str,
    mode: &str,
    threads: usize,
) -> Option<f64> {
    let edge = find(records, "edge", filter, mode, threads)?;
    let scan = find(records, "scanline", filter, mode, threads)?;
    (scan.median_ms > 0.0).then(|| edge.median_ms / scan.median_ms)
}

/// A published tutorial's timing of its two release builds: per-pixel barycentric 1.40 ms, scanline
/// 0.73 ms.
pub const SEED_001_MS: (f64, f64) = (1.40, 0.73);

/// The llvmpipe figures quoted by the performance issue for `assets/scenes/bench-1080p.json`
/// (1920x1080, perspective-correct, draw only), measured on this project's 2-core machine:
/// (threads, filter, median ms).
pub const LLVMPIPE_REFERENCE_1080P: [(usize, &str, f64); 4] = [
    (1, "bilinear", 11.8),
    (1, "nearest", 7.3),
    (2, "bilinear", 5.4),
    (2, "nearest", 2.5),
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Scene;

    #[test]
    fn run_config_measures_the_asked_configuration() {
        let mut scene = Scene::default_scene();
        scene.set_size(32, 24);
        let texture = scene
            .load_texture(std::path::Path::new(""))
            .expect("builtin texture");
        let config = BenchConfig {
            rasterizer: Rasterizer::Scanline,
            filter: Filter::Nearest,
            mode: Interpolation::Affine,
            threads: 1,
        };
        let r =
            run_config(&scene.to_mesh(), &texture, &scene.settings(), config, 3).expect("bench");
        assert_eq!(
            (r.rasterizer.as_str(), r.filter.as_str(), r.mode.as_str()),
            ("scanline", "nearest", "affine")
        );
        assert_eq!((r.width, r.height, r.threads), (32, 24, 1));
        assert!(r.median_ms > 0.0);
        assert!((r.mpix_per_s - 32.0 * 24.0 / (r.median_ms * 1e3)).abs() < 1e-9);
        assert!(matches!(
            run_config(&scene.to_mesh(), &texture, &scene.settings(), config, 0),
            Err(BenchError::NoFrames)
        ));
    }

    #[test]
    fn matrix_covers_every_cell_once() {
        let m = matrix(4);
        let set: std::collections::HashSet<_> = m
            .iter()
            .map(|c| (c.rasterizer, c.filter, c.mode, c.threads))
            .collect();
        assert_eq!(set.len(), 16);
        assert_eq!(matrix(1).len(), 8);
    }
}
