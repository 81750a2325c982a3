//! The canvas's renders: what a render depends on, the few renders kept for reuse, and the
//! images of the views (one per mode, the wipe, the difference heatmap). No widgets here.

use std::sync::Arc;
use std::sync::mpsc::{Receiver, RecvTimeoutError, TryRecvError};
use std::time::{Duration, Instant};

use egui::Color32;

use crate::app::document::state::AppState;
use crate::edit;
use crate::figure::heatmap::{self, Heatmap};
use crate::figure::{Compare, ViewContent, modes_for, wipe_pixels};
use crate::progress::{self, Job};
use crate::raster::project::Viewport;
use crate::raster::render::{Rasterizer, Render};
use crate::raster::{Buffers, Framebuffer, Interpolation, RenderSettings, Texture};
use crate::scene::Scene;

/// A texture's name and the folder it is resolved against.
pub type TextureKey = (String, Option<std::path::PathBuf>);

/// Everything a render depends on; a new render happens only when this changes.
#[derive(Clone, Debug, PartialEq)]
struct RenderKey {
    scene: Scene,
    modes: Vec<Interpolation>,
    rasterizer: Rasterizer,
    texture: TextureKey,
    /// The difference heatmap is made (the difference comparison).
    heat: bool,
}

/// The rendered frames of the current state.
pub struct CanvasOutput {
    /// The scene as rendered (its size set to the render size).
    pub scene: Scene,
    pub size: [u32; 2],
    /// One render per mode shown.
    pub renders: Vec<(Interpolation, Arc<Render>)>,
    pub heatmap: Option<Heatmap>,
    /// Increments with every render.
    pub generation: u64,
}

impl CanvasOutput {
    /// The render in `mode`, or the first one.
    pub fn render(&self, mode: Interpolation) -> Option<&Render> {
        self.renders
            .iter()
            .find(|(m, _)| *m == mode)
            .or(self.renders.first())
            .map(|(_, r)| r.as_ref())
    }

    pub fn viewport(&self) -> Viewport {
        Viewport {
            width: self.size[0],
            height: self.size[1],
        }
    }
}

/// What one cached render depends on: the sized scene, the mode, the texture, the buffers,
/// the rasterizer.
type RenderCacheKey = (Scene, Interpolation, TextureKey, Buffers, Rasterizer);

/// Renders kept for reuse, so flipping the mode back and forth or switching comparisons does
/// not render again.
const RENDER_CACHE: usize = 4;

/// How long [`RenderCache::update`] waits for a render that is not quick (small enough to be a
/// few tens of milliseconds) before it lets the frame go on without it (the previous picture
/// stays, with a progress bar and Cancel).
pub const FRAME_BUDGET: Duration = Duration::from_millis(100);

/// Pixels (all the modes' renders together) up to which a render is quick whatever the time
/// it takes: a full-HD image side by side (a canvas fitting a large window).
const QUICK_PIXELS: u64 = 2 * 1920 * 1080;

/// Triangles up to which a render is quick.
const QUICK_TRIANGLES: usize = 100_000;

/// Whether drawing `triangles` triangles into `pixels` pixels is quick enough to wait for
/// always (a few tens of milliseconds): the app then renders as if on its own thread, the
/// picture there the frame after any change (dragging stays immediate). Longer work is waited
/// for up to [`FRAME_BUDGET`] only.
fn quick(pixels: u64, triangles: usize) -> bool {
    pixels <= QUICK_PIXELS && triangles <= QUICK_TRIANGLES
}

/// One mode's new framebuffer, with the key it is kept under.
type Drawn = (RenderCacheKey, Framebuffer);

/// What one output is made of: its key, comparison and size, and each mode's render's key.
struct Request {
    key: RenderKey,
    compare: Compare,
    size: [u32; 2],
    wanted: Vec<(Interpolation, RenderCacheKey)>,
}

/// A render running on a thread of its own.
struct Running {
    request: Request,
    job: Arc<Job>,
    started: Instant,
    done: Receiver<Result<Vec<Drawn>, RenderFailure>>,
}

/// The last render's key and the renders kept for reuse.
#[derive(Default)]
pub struct RenderCache {
    key: Option<RenderKey>,
    cache: Vec<(RenderCacheKey, Arc<Render>)>,
    /// A framebuffer of a render that left the cache, reused by the next render.
    spare: Option<Framebuffer>,
    /// The heatmap of an output no longer shown, whose memory the next heatmap reuses.
    spare_heat: Option<Heatmap>,
    /// The render under way, when it takes longer than a frame.
    running: Option<Running>,
    /// What a cancelled render was to draw: not started again until something changes.
    cancelled: Option<RenderKey>,
}

/// Why a render gave no picture.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderFailure {
    /// The render needs more memory than barylab may use or the system gives it.
    pub memory: bool,
    /// The message, naming the problem.
    pub text: String,
}

impl RenderFailure {
    fn other(text: String) -> RenderFailure {
        RenderFailure {
            memory: false,
            text,
        }
    }
}

impl From<crate::raster::settings::RenderError> for RenderFailure {
    fn from(e: crate::raster::settings::RenderError) -> RenderFailure {
        RenderFailure {
            memory: matches!(e, crate::raster::settings::RenderError::Memory(_)),
            text: e.to_string(),
        }
    }
}

/// A new output of [`RenderCache::update`].
pub struct Rendered {
    pub output: CanvasOutput,
    /// How long rendering took, if anything was rendered (not all from the cache).
    pub render_ms: Option<f64>,
}

/// A render under way, for the progress bar.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Underway {
    /// The share drawn, in [0, 1].
    pub fraction: f64,
    /// The image size being drawn.
    pub size: [u32; 2],
    /// Seconds since it started.
    pub seconds: f64,
}

impl RenderCache {
    /// Takes back an output that is no longer shown, keeping its heatmap's memory for the next
    /// one.
    pub fn recycle(&mut self, old: CanvasOutput) {
        if old.heatmap.is_some() {
            self.spare_heat = old.heatmap;
        }
    }

    /// The render under way on its own thread, if any.
    pub fn underway(&self) -> Option<Underway> {
        self.running.as_ref().map(|r| Underway {
            fraction: r.job.fraction(),
            size: r.request.size,
            seconds: r.started.elapsed().as_secs_f64(),
        })
    }

    /// Stops the render under way (it stops at its next band): the picture shown stays, and
    /// the same request is not rendered again until something it depends on changes. Returns
    /// the size it was drawing, if one was under way.
    pub fn cancel(&mut self) -> Option<[u32; 2]> {
        let running = self.running.take()?;
        running.job.cancel();
        self.cancelled = Some(running.request.key);
        Some(running.request.size)
    }

    /// Renders `state` at `size` for the comparison `compare` if anything the image depends
    /// on changed: `Ok(None)` when nothing did, or while the render runs on (a render that is
    /// not quick and takes longer than [`FRAME_BUDGET`] goes on on its own thread; a later
    /// call takes its result, see [`RenderCache::underway`]). `generation` numbers the new
    /// output.
    pub fn update(
        &mut self,
        state: &AppState,
        compare: Compare,
        size: [u32; 2],
        texture: &Arc<Texture>,
        texture_key: TextureKey,
        generation: u64,
    ) -> Result<Option<Rendered>, RenderFailure> {
        let mut scene = state.scene.clone();
        scene.set_size(size[0], size[1]);
        let modes = modes_for(compare, state.options().mode);
        // The mode is in `modes`; the scene's own mode field must not make keys differ.
        let mut options = edit::options(&scene);
        options.mode = Interpolation::Perspective;
        edit::set_options(&mut scene, options);
        let key = RenderKey {
            scene,
            modes,
            rasterizer: state.view.rasterizer,
            texture: texture_key,
            heat: compare == Compare::Difference,
        };
        if self.running.as_ref().is_some_and(|r| r.request.key == key) {
            return self.take_running(texture, generation, None);
        }
        if let Some(old) = self.running.take() {
            // Something changed while it ran: its picture would be stale.
            old.job.cancel();
        }
        if self.key.as_ref() == Some(&key) || self.cancelled.as_ref() == Some(&key) {
            return Ok(None);
        }
        self.cancelled = None;
        let mesh = key.scene.to_mesh();
        let base = key.scene.settings();
        // Only the difference heatmap reads more than colour: the texel difference of the two
        // uvs per pixel (which the edge-function lanes also draw). Both are bit-identical to
        // the full render.
        let buffers = if compare == Compare::Difference {
            Buffers::DepthDifference
        } else {
            Buffers::ColorDepth
        };
        let wanted: Vec<(Interpolation, RenderCacheKey)> = key
            .modes
            .iter()
            .map(|&mode| {
                let one = (
                    key.scene.clone(),
                    mode,
                    key.texture.clone(),
                    buffers,
                    key.rasterizer,
                );
                (mode, one)
            })
            .collect();
        let missing: Vec<(RenderCacheKey, RenderSettings)> = wanted
            .iter()
            .filter(|(_, one)| !self.cache.iter().any(|(k, _)| k == one))
            .map(|(mode, one)| {
                let settings = RenderSettings {
                    mode: *mode,
                    rasterizer: key.rasterizer,
                    ..base
                };
                (one.clone(), settings)
            })
            .collect();
        let request = Request {
            key,
            compare,
            size,
            wanted,
        };
        if missing.is_empty() {
            return self
                .finish(request, Vec::new(), texture, generation, 0.0)
                .map(Some);
        }
        let pixels = u64::from(size[0]) * u64::from(size[1]) * missing.len() as u64;
        // A quick render is waited for whatever it takes (`None`); a longer one a frame at most.
        let wait = (!quick(pixels, mesh.triangles.len())).then_some(FRAME_BUDGET);
        let job = Job::new(u64::from(size[1]) * missing.len() as u64);
        let (send, done) = std::sync::mpsc::channel();
        let mut spare = self.spare.take();
        let thread_job = job.clone();
        let thread_texture = Arc::clone(texture);
        let work = move || {
            let drawn = progress::with_job(&thread_job, || {
                missing
                    .into_iter()
                    .map(|(one, settings)| {
                        let mut frame = spare.take().unwrap_or_else(Framebuffer::empty);
                        let texture = &thread_texture;
                        crate::raster::render_into(&mut frame, &mesh, texture, &settings, buffers)
                            .map(|()| (one, frame))
                            .map_err(RenderFailure::from)
                    })
                    .collect::<Result<Vec<Drawn>, RenderFailure>>()
            });
            // The receiver is gone when the render was given up: nothing to do then.
            let _ = send.send(drawn);
        };
        std::thread::Builder::new()
            .name("canvas render".into())
            .spawn(work)
            .map_err(|e| RenderFailure::other(format!("cannot start a render thread: {e}")))?;
        self.running = Some(Running {
            request,
            job,
            started: Instant::now(),
            done,
        });
        self.take_running(texture, generation, Some(wait))
    }

    /// The output of the render under way if it is done (waiting for it up to `wait`:
    /// `Some(None)` without limit; `None` not at all), else `Ok(None)` and it runs on.
    fn take_running(
        &mut self,
        texture: &Texture,
        generation: u64,
        wait: Option<Option<Duration>>,
    ) -> Result<Option<Rendered>, RenderFailure> {
        let Some(running) = &self.running else {
            return Ok(None);
        };
        let result = match wait {
            Some(None) => running
                .done
                .recv()
                .map_err(|_| RecvTimeoutError::Disconnected),
            Some(Some(budget)) => running.done.recv_timeout(budget),
            None => running.done.try_recv().map_err(|e| match e {
                TryRecvError::Empty => RecvTimeoutError::Timeout,
                TryRecvError::Disconnected => RecvTimeoutError::Disconnected,
            }),
        };
        let drawn = match result {
            Err(RecvTimeoutError::Timeout) => return Ok(None),
            Err(RecvTimeoutError::Disconnected) => {
                self.running = None;
                return Err(RenderFailure::other(
                    "the render thread stopped without a picture".into(),
                ));
            }
            Ok(drawn) => drawn,
        };
        let Some(running) = self.running.take() else {
            return Ok(None);
        };
        let render_ms = running.started.elapsed().as_secs_f64() * 1e3;
        self.finish(running.request, drawn?, texture, generation, render_ms)
            .map(Some)
    }

    /// Puts the new frames in the cache and makes the output of `request`.
    fn finish(
        &mut self,
        request: Request,
        drawn: Vec<Drawn>,
        texture: &Texture,
        generation: u64,
        render_ms: f64,
    ) -> Result<Rendered, RenderFailure> {
        let rendered = !drawn.is_empty();
        for (one, frame) in drawn {
            // The canvas keeps the image only: the inspector probes the scene itself.
            let r = Arc::new(Render {
                frame,
                triangles: Vec::new(),
            });
            self.cache.push((one, r));
        }
        let renders: Vec<(Interpolation, Arc<Render>)> = request
            .wanted
            .iter()
            .filter_map(|(mode, one)| {
                let (_, r) = self.cache.iter().rev().find(|(k, _)| k == one)?;
                Some((*mode, r.clone()))
            })
            .collect();
        if self.cache.len() > RENDER_CACHE {
            for (_, old) in self.cache.drain(..self.cache.len() - RENDER_CACHE) {
                // Keep the memory of a render nobody else holds for the next one.
                if let Ok(r) = Arc::try_unwrap(old) {
                    self.spare = Some(r.frame);
                }
            }
        }
        let heat = match renders.first() {
            Some((_, r)) if request.compare == Compare::Difference => {
                let mut h = self.spare_heat.take().unwrap_or_default();
                heatmap::heatmap_into(&r.frame, (texture.width(), texture.height()), &mut h)
                    .map_err(|e| RenderFailure {
                        memory: true,
                        text: e.to_string(),
                    })?;
                Some(h)
            }
            _ => None,
        };
        let key = request.key;
        let output = CanvasOutput {
            scene: key.scene.clone(),
            size: request.size,
            renders,
            heatmap: heat,
            generation,
        };
        self.key = Some(key);
        Ok(Rendered {
            output,
            render_ms: rendered.then_some(render_ms),
        })
    }
}

/// The image a view shows; `wipe_col` is the wipe line's column.
pub fn view_image(out: &CanvasOutput, content: ViewContent, wipe_col: u32) -> egui::ColorImage {
    let size = [out.size[0] as usize, out.size[1] as usize];
    let pixels: Vec<Color32> = match content {
        ViewContent::Mode(m) => out
            .render(m)
            .map(|r| to_color32(&r.frame.color))
            .unwrap_or_default(),
        ViewContent::Difference => out
            .heatmap
            .as_ref()
            .map(|h| to_color32(&h.pixels))
            .unwrap_or_default(),
        ViewContent::Wipe => wipe_image(out, wipe_col),
    };
    if pixels.len() == size[0] * size[1] {
        egui::ColorImage::new(size, pixels)
    } else {
        egui::ColorImage::filled(size, Color32::BLACK)
    }
}

fn to_color32(pixels: &[[u8; 4]]) -> Vec<Color32> {
    pixels
        .iter()
        .map(|c| Color32::from_rgba_unmultiplied(c[0], c[1], c[2], c[3]))
        .collect()
}

/// Affine columns left of `column`, perspective-correct from it on.
fn wipe_image(out: &CanvasOutput, column: u32) -> Vec<Color32> {
    match (
        out.render(Interpolation::Affine),
        out.render(Interpolation::Perspective),
    ) {
        (Some(a), Some(p)) => to_color32(&wipe_pixels(
            &a.frame.color,
            &p.frame.color,
            out.size[0],
            column,
        )),
        _ => Vec::new(),
    }
}
