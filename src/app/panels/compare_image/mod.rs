//! File > Compare with image… (and `barylab --compare-image IMAGE`): an image from a
//! student's rasterizer, or a screenshot, against barylab's render of the canvas's scene, in
//! the GPU view's compare modes (`other_image`): coverage by alpha, or by the scene's
//! background colour when the image is opaque (as `barylab compare`), the summary, the worst
//! and first mismatched pixels, and for the pinned pixel the reason from [`crate::compare`].
//!
//! The comparison (a render, the comparison with its hypotheses' renders, the difference
//! image: about 0.2 s at 1920x1080 with the fast path's renders, `compare::render_for_comparison`)
//! runs in a background thread, as the Benchmark
//! window's runs do ([`crate::app::panels::bench_panel`]): the window keeps showing the last result, with
//! a "comparing…" note, until the new one arrives; a result for a scene that has changed
//! since is dropped.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, TryRecvError, channel};
use std::time::Duration;

use crate::app::panels::gpu_view::{GpuResult, GpuView};
use crate::app::services::render::CanvasOutput;
use crate::compare::reason::Reason;
use crate::compare::{self, Comparison, CoverageBy, Image, Reference, Rendered};
use crate::files::shown;
use crate::i18n::Lang;
use crate::raster::{Interpolation, NO_TRIANGLE, Texture};

mod strip;
pub use strip::{strip_ui, summary};

/// Reads an image through the library's checked reader ([`compare::read_image`]); the error
/// is one line naming the file and the problem.
pub fn read_image(path: &Path, lang: Lang) -> Result<Image, String> {
    compare::read_image(path, lang, |_, _| Ok(()))
}

/// Why a pinned pixel differs, or the probe's or the renderer's message when that cannot be
/// found.
pub type PinReason = Result<Reason, String>;

/// An image being compared with the canvas's render.
pub struct ImageCompare {
    /// The file it was read from.
    pub path: PathBuf,
    image: Arc<Image>,
    /// The display (barylab's image, this image, the difference image), as the GPU view's.
    pub view: GpuView,
    /// The last comparison (`None` while the sizes differ).
    pub comparison: Option<Comparison>,
    /// The canvas's image size when it is not the image's.
    pub size_mismatch: Option<[u32; 2]>,
    /// Why the comparison failed (the renderer's or the probe's message).
    pub error: Option<String>,
    /// What the last comparison was made of (`None`: compare on the next update).
    key: Option<Inputs>,
    /// What the pinned pixel's reason needs.
    reference: Option<Held>,
    /// The pinned pixel and why it differs (`None`: it agrees; `Err`: the probe's or the
    /// renderer's message). Worded in the UI's language when shown.
    pub pin_reason: Option<([u32; 2], Option<PinReason>)>,
    /// The image's background colour, chosen (`--compare-background`, the strip's colour
    /// button): covered is any other colour, even where the image has alpha. `None`: alpha
    /// when the image has transparency, else the scene's background colour.
    pub background: Option<[u8; 3]>,
    /// The scene changed during a drag: compared when it ends.
    pub deferred: bool,
    /// The comparison going on in the background, if any.
    running: Option<Running>,
    /// The last comparison's number (each started comparison gets the next one).
    job: u64,
    /// The background thread ended without a result (it panicked).
    pub lost: bool,
    comparisons: u64,
}

/// How often a frame looks for the background result when nothing else repaints (the
/// thread asks for a repaint when it is done; this is a fallback).
const POLL: Duration = Duration::from_millis(100);

/// A comparison going on in a background thread.
struct Running {
    /// Its number: a message with another number is for an outdated scene.
    job: u64,
    messages: Receiver<(u64, Result<Made, String>)>,
    /// Set when the comparison is no longer wanted (checked between its steps).
    stop: Arc<AtomicBool>,
}

impl Drop for Running {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
    }
}

/// What the background thread makes: the comparison, the display and the pinned pixel's
/// needs.
struct Made {
    comparison: Comparison,
    result: GpuResult,
    held: Held,
}

/// What a comparison is made of: the canvas's scene as rendered (with the render's
/// generation, which saves comparing scenes while it has not changed), the mode and the
/// texture. A new render of the same scene (another compare view, another rasterizer) does
/// not compare again.
struct Inputs {
    generation: u64,
    scene: crate::scene::Scene,
    mode: Interpolation,
    texture: Arc<Texture>,
}

impl Inputs {
    /// Whether `output` in `mode` with `texture` is what was compared (the texture is
    /// checked only when given).
    fn same(
        &self,
        output: &CanvasOutput,
        mode: Interpolation,
        texture: Option<&Arc<Texture>>,
    ) -> bool {
        self.mode == mode
            && texture.is_none_or(|t| Arc::ptr_eq(t, &self.texture))
            && (self.generation == output.generation || self.scene == output.scene)
    }
}

/// The scene as compared, kept for the pinned pixel's reason.
struct Held {
    scene: crate::scene::Scene,
    mesh: crate::raster::ClipMesh,
    texture: Arc<Texture>,
    settings: crate::raster::RenderSettings,
    render: crate::raster::render::Render,
    by: CoverageBy,
}

impl ImageCompare {
    /// A comparison of `image` (read from `path`), made on the next [`ImageCompare::update`].
    pub fn new(path: PathBuf, image: Image, print_summary: bool) -> Self {
        let name = path
            .file_name()
            .map_or_else(|| shown(&path), |n| n.to_string_lossy().into_owned());
        let mut view = GpuView::new(print_summary);
        view.other_name = Some(name);
        Self {
            path,
            image: Arc::new(image),
            view,
            comparison: None,
            size_mismatch: None,
            error: None,
            key: None,
            reference: None,
            pin_reason: None,
            background: None,
            deferred: false,
            running: None,
            job: 0,
            lost: false,
            comparisons: 0,
        }
    }

    /// Sets the image's background colour; compares again on the next update.
    pub fn set_background(&mut self, color: [u8; 3]) {
        if self.background != Some(color) {
            self.background = Some(color);
            self.key = None;
        }
    }

    /// The image's size.
    pub fn size(&self) -> [u32; 2] {
        [self.image.width, self.image.height]
    }

    /// Whether the comparison is made (and done) for the canvas's current render.
    pub fn settled(&self, output: Option<&CanvasOutput>, mode: Interpolation) -> bool {
        self.running.is_none()
            && output.is_some_and(|o| self.key.as_ref().is_some_and(|k| k.same(o, mode, None)))
    }

    /// Whether a comparison is going on in the background (the last result, if any, is
    /// shown meanwhile).
    pub fn is_comparing(&self) -> bool {
        self.running.is_some()
    }

    /// How many comparisons were started.
    pub fn comparisons(&self) -> u64 {
        self.comparisons
    }

    /// Once per frame: compares again when what is compared changed (the canvas's scene, the
    /// mode, the texture, the background colour; not merely a new render of the same scene,
    /// e.g. for another compare view), and finds the pinned pixel's reason when the pin
    /// moved. While a pointer button is held (`held`: a drag, which renders every frame) a
    /// changed scene is not compared: the canvas shows barylab's render until the drag
    /// ends, then compares once.
    ///
    /// The comparison runs in a background thread: this frame starts it and returns; a later
    /// frame takes the result (`ctx` is asked to repaint when it is ready). Meanwhile the
    /// last result stays shown. Returns whether anything changed.
    pub fn update(
        &mut self,
        ctx: &egui::Context,
        output: Option<&CanvasOutput>,
        mode: Interpolation,
        texture: &Arc<Texture>,
        pinned: Option<[u32; 2]>,
        held: bool,
    ) -> bool {
        let mut changed = self.poll();
        if let Some(out) = output {
            match &mut self.key {
                Some(k) if k.same(out, mode, Some(texture)) => k.generation = out.generation,
                Some(_) if held => {
                    if !self.deferred {
                        self.running = None;
                        self.clear();
                        self.deferred = true;
                        changed = true;
                    }
                }
                _ => {
                    self.deferred = false;
                    self.key = Some(Inputs {
                        generation: out.generation,
                        scene: out.scene.clone(),
                        mode,
                        texture: Arc::clone(texture),
                    });
                    self.compare(ctx, out, mode, texture);
                    changed = true;
                }
            }
        }
        if self.running.is_some() {
            ctx.request_repaint_after(POLL);
        }
        if self.pin_reason.as_ref().map(|p| p.0) != pinned {
            self.pin_reason = pinned.map(|p| (p, self.reason_at(p)));
            changed = true;
        }
        changed
    }

    /// Forgets the last comparison (the canvas shows barylab's render).
    fn clear(&mut self) {
        self.view.result = None;
        self.comparison = None;
        self.reference = None;
        self.error = None;
        self.lost = false;
        self.pin_reason = None;
        self.view.generation += 1;
    }

    /// Takes the background thread's result, when it has come. Returns whether anything
    /// changed.
    fn poll(&mut self) -> bool {
        let Some(running) = &self.running else {
            return false;
        };
        let job = running.job;
        match running.messages.try_recv() {
            Err(TryRecvError::Empty) => false,
            Err(TryRecvError::Disconnected) => {
                self.running = None;
                self.clear();
                self.lost = true;
                true
            }
            // A result for an outdated scene (not kept: a new comparison replaces the
            // receiver, but checked all the same).
            Ok((n, _)) if n != job => false,
            Ok((_, made)) => {
                self.running = None;
                self.clear();
                match made {
                    Ok(m) => self.show(m),
                    Err(e) => self.error = Some(format!("{}: {e}", shown(&self.path))),
                }
                true
            }
        }
    }

    /// Shows a comparison made in the background.
    fn show(&mut self, made: Made) {
        if self.view.print_summary {
            println!("image compare: {}", summary(&made.comparison, Lang::En));
        }
        self.view.result = Some(made.result);
        self.comparison = Some(made.comparison);
        self.reference = Some(made.held);
    }

    /// Starts comparing the image with `out`'s scene in `mode` in a background thread (a
    /// comparison going on is dropped). A wrong size is said at once.
    fn compare(
        &mut self,
        ctx: &egui::Context,
        out: &CanvasOutput,
        mode: Interpolation,
        texture: &Arc<Texture>,
    ) {
        self.running = None;
        self.comparisons += 1;
        let mut settings = out.scene.settings();
        settings.mode = mode;
        if [settings.width, settings.height] != self.size() {
            self.clear();
            self.size_mismatch = Some([settings.width, settings.height]);
            return;
        }
        self.size_mismatch = None;
        if self.view.result.is_none() {
            // Nothing to keep showing (the last one failed, or there was none).
            self.clear();
        }
        let by = if let Some(c) = self.background {
            CoverageBy::Background(c)
        } else if self.image.has_transparency() {
            CoverageBy::Alpha
        } else {
            let b = settings.background;
            CoverageBy::Background([b[0], b[1], b[2]])
        };
        self.job += 1;
        let job = self.job;
        let stop = Arc::new(AtomicBool::new(false));
        let (tx, rx) = channel();
        let work = Work {
            scene: out.scene.clone(),
            texture: Arc::clone(texture),
            image: Arc::clone(&self.image),
            settings,
            by,
            stop: Arc::clone(&stop),
        };
        let ctx = ctx.clone();
        let spawned = std::thread::Builder::new()
            .name("barylab-compare-image".into())
            .spawn(move || {
                if let Some(made) = work.run() {
                    // The receiver is gone when a newer comparison replaced this one.
                    if tx.send((job, made)).is_ok() {
                        ctx.request_repaint();
                    }
                }
            });
        match spawned {
            Ok(_) => {
                self.running = Some(Running {
                    job,
                    messages: rx,
                    stop,
                });
            }
            Err(e) => {
                self.clear();
                self.error = Some(format!("{}: {e}", shown(&self.path)));
            }
        }
    }

    /// Why pixel `p` differs (`None` when it agrees or the reason cannot be found).
    fn reason_at(&self, p: [u32; 2]) -> Option<PinReason> {
        let (c, h) = (self.comparison.as_ref()?, self.reference.as_ref()?);
        if let Some(listed) = c.first.iter().find(|d| d.pixel == p) {
            return Some(Ok(listed.reason.clone()));
        }
        let k = (p[1] as usize) * (c.width as usize) + p[0] as usize;
        let theirs = *self.image.pixels.get(k)?;
        let frame = &h.render.frame;
        let rendered = Rendered {
            color: frame.color.clone(),
            covered: frame.triangle.iter().map(|&t| t != NO_TRIANGLE).collect(),
        };
        let d = compare::classify(theirs, &rendered, k, h.by, c.tolerance)?;
        let best = c
            .hypotheses
            .iter()
            .filter(|t| t.differing * 2 < c.differing())
            .min_by_key(|t| t.differing);
        if let Some(t) = best.filter(|t| !t.differs_at(k)) {
            return Some(Ok(t.pixel_reason(k, frame, &h.texture)));
        }
        let reference = Reference {
            scene: &h.scene,
            mesh: &h.mesh,
            texture: &h.texture,
            settings: h.settings,
        };
        let context = compare::diagnose::Context::new(&reference, &h.render, h.by, c.tolerance);
        Some(context.and_then(|cx| cx.reason(p, d, theirs)))
    }
}

/// One comparison's inputs, owned by the background thread.
struct Work {
    scene: crate::scene::Scene,
    texture: Arc<Texture>,
    image: Arc<Image>,
    settings: crate::raster::RenderSettings,
    by: CoverageBy,
    stop: Arc<AtomicBool>,
}

impl Work {
    /// Renders, compares and makes the difference image; `None` when stopped on the way
    /// (a newer comparison is wanted).
    fn run(self) -> Option<Result<Made, String>> {
        let stopped = || self.stop.load(Ordering::Relaxed);
        let mesh = self.scene.to_mesh();
        if stopped() {
            return None;
        }
        let tol = compare::DEFAULT_TOLERANCE;
        // One render for the comparison, the difference image and the pinned reasons.
        let render = match compare::render_for_comparison(&mesh, &self.texture, &self.settings) {
            Ok(r) => r,
            Err(e) => return Some(Err(e)),
        };
        if stopped() {
            return None;
        }
        let reference = Reference {
            scene: &self.scene,
            mesh: &mesh,
            texture: &self.texture,
            settings: self.settings,
        };
        let c = match compare::compare_rendered(&self.image, &reference, &render, self.by, tol) {
            Ok(c) => c,
            Err(e) => return Some(Err(e)),
        };
        if stopped() {
            return None;
        }
        let diff = compare::difference_image_of(&self.image, &render.frame, self.by, tol);
        let first = c.first.first().map(|p| p.pixel);
        let worst = c.max_color_at.filter(|_| c.color_differing > 0).or(first);
        let image_diff = crate::gpu::view::ImageDiff {
            width: c.width,
            height: c.height,
            pixels: c.pixels,
            covered: c.covered,
            only_gpu: c.only_theirs,
            only_barylab: c.only_ours,
            triangle_mismatches: 0,
            color_differing: c.color_differing,
            max_color_difference: c.max_color_difference,
            worst,
            image: diff.pixels().map(|p| p.0).collect(),
        };
        let result = GpuResult {
            ours: render.frame.color.clone(),
            gpu: self.image.pixels.clone(),
            diff: image_diff,
            notes: Vec::new(),
            samples: None,
            #[cfg(feature = "gpu")]
            lod: None,
        };
        let held = Held {
            scene: self.scene,
            mesh,
            texture: self.texture,
            settings: self.settings,
            render,
            by: self.by,
        };
        Some(Ok(Made {
            comparison: c,
            result,
            held,
        }))
    }
}

/// The other image the canvas shows: the compared image's, else the GPU's when the GPU view
/// is on (`gpu_on`).
pub(in crate::app) fn other_view<'a>(
    image: Option<&'a ImageCompare>,
    gpu_on: bool,
    gpu: &'a GpuView,
) -> Option<&'a GpuView> {
    match image {
        Some(ic) => Some(&ic.view),
        None => gpu_on.then_some(gpu),
    }
}

impl crate::app::BaryApp {
    /// Reads `path` and compares it with the canvas's render from the next frame on (the GPU
    /// view goes off); a bad file leaves a one-line error naming it.
    pub(in crate::app) fn open_compare_image(&mut self, path: &Path) {
        match read_image(path, self.lang) {
            Ok(image) => {
                let print = self.gpu_view.print_summary;
                self.compare_image = Some(ImageCompare::new(path.to_path_buf(), image, print));
                self.state.view.gpu = false;
                if self.message.as_ref().is_some_and(|m| m.error) {
                    self.message = None;
                }
            }
            Err(e) => self.message = Some(crate::app::panels::status::Message::error(e, None)),
        }
    }

    /// The image comparison, when an image is being compared.
    pub fn compare_image(&self) -> Option<&ImageCompare> {
        self.compare_image.as_ref()
    }

    /// Once per frame: the comparison for the current render. Returns whether it changed.
    /// `held`: a pointer button is down (a drag may be going on).
    pub(in crate::app) fn compare_image_frame(
        &mut self,
        ctx: &egui::Context,
        texture: &Arc<Texture>,
        held: bool,
    ) -> bool {
        let (mode, pinned) = (self.state.options().mode, self.state.view.pinned);
        let out = self.canvas.output.as_ref();
        self.compare_image
            .as_mut()
            .is_some_and(|ic| ic.update(ctx, out, mode, texture, pinned, held))
    }
}
