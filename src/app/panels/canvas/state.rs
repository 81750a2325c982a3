//! The canvas's state between frames: the renders and their textures, the views drawn last
//! frame, the pointer's pixel and the drag under way.

use std::sync::Arc;
use std::time::Instant;

use egui::{Rect, TextureHandle, TextureOptions};
use glam::DVec2;

use crate::app::document::state::AppState;
use crate::app::panels::gpu_view::GpuView;
use crate::app::panels::other_image;
use crate::app::panels::paint::CanvasTransform;
use crate::app::services::render::{
    CanvasOutput, RenderCache, RenderFailure, TextureKey, view_image,
};
use crate::figure::{Compare, ViewContent};
use crate::raster::Texture;

/// Magnified pixels stay crisp squares; a large image shrunk into a small canvas is averaged
/// rather than decimated.
const VIEW_TEXTURE: TextureOptions = TextureOptions {
    magnification: egui::TextureFilter::Nearest,
    minification: egui::TextureFilter::Linear,
    ..TextureOptions::NEAREST
};

/// One view on screen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// Screen rectangle of the image, in points.
    pub rect: Rect,
    /// The view's share of the canvas (its image, title strip and margins), in points.
    pub area: Rect,
    /// Maps rendered-image pixels to screen points for this view.
    pub transform: CanvasTransform,
    /// What the view shows (a mode, the wipe, the difference heatmap).
    pub content: ViewContent,
}

/// Timings of the last render, for the status line.
#[derive(Clone, Copy, Debug, Default)]
pub struct CanvasTiming {
    /// Time the last render took, in milliseconds.
    pub render_ms: f64,
    /// Time the last texture upload to egui took, in milliseconds.
    pub upload_ms: f64,
    /// Renders made since start.
    pub renders: u64,
    /// Texture uploads made since start.
    pub uploads: u64,
}

#[derive(Clone, Copy, Debug)]
pub(super) enum DragKind {
    Handle { index: usize, grab: DVec2 },
    Wipe,
}

/// The canvas's state between frames (not saved).
#[derive(Default)]
pub struct CanvasState {
    renders: RenderCache,
    /// The last successful render (`None` until the first; kept when a later one fails).
    pub output: Option<CanvasOutput>,
    pub(super) textures: Vec<TextureHandle>,
    uploaded: Option<(u64, Compare, u32, Option<u64>, u64)>,
    /// The per-sample buffers the sample view shows (made only while it is on).
    pub samples: crate::app::services::sample_images::SampleImages,
    /// How many views the last upload took from the per-sample buffers.
    pub samples_shown: usize,
    pub(super) drag: Option<DragKind>,
    /// The views drawn last frame, left to right.
    pub views: Vec<View>,
    /// The pixel under the pointer, if it is over a view.
    pub hover: Option<[u32; 2]>,
    /// Timings of the last render and upload.
    pub timing: CanvasTiming,
    /// Why the last render failed, for the canvas to show in the picture's place.
    pub error: Option<RenderFailure>,
    /// The size of a render that was cancelled: the picture shown is an older one.
    pub cancelled: Option<[u32; 2]>,
    /// Screen pixels per rendered pixel as drawn (whole, 1 to 32): the overlay's grid and
    /// the exported figure's pixel size.
    pub pixel_size: u32,
    /// The canvas's whole area on screen (points), the views inside it (`None` before the
    /// first frame).
    pub area: Option<Rect>,
    /// What lies over the canvas (presentation mode's card, as placed last frame): labels
    /// keep clear of it where they can.
    pub avoid: Vec<Rect>,
    /// The vertices whose handles were drawn last frame (every one of a scene of at most 32,
    /// else only the pinned and hovered triangles' corners).
    pub handles: Vec<usize>,
    /// The scanline rasterizer steps along the pinned row's span (S starts and stops it).
    pub span_play: bool,
    /// When the stepping along the span started (egui's clock, seconds).
    pub(super) span_started: Option<f64>,
}

impl CanvasState {
    /// The texture and image size of the view that shows `content`, else of the first view
    /// (the magnifier enlarges what the canvas shows).
    pub fn view_texture(&self, content: ViewContent) -> Option<(egui::TextureId, [u32; 2])> {
        let out = self.output.as_ref()?;
        let i = self
            .views
            .iter()
            .position(|v| v.content == content)
            .unwrap_or(0);
        self.textures.get(i).map(|t| (t.id(), out.size))
    }

    /// A render under way on its own thread (it took longer than a frame), if any.
    pub fn underway(&self) -> Option<crate::app::services::render::Underway> {
        self.renders.underway()
    }

    /// Cancels the render under way (its render cache cancels it); the picture shown stays.
    pub fn cancel_render(&mut self) {
        if let Some(size) = self.renders.cancel() {
            self.cancelled = Some(size);
        }
    }

    /// Renders if anything the image depends on changed. Returns whether a new picture came.
    pub fn update(
        &mut self,
        state: &AppState,
        compare: Compare,
        size: [u32; 2],
        texture: &Arc<Texture>,
        texture_key: TextureKey,
    ) -> bool {
        let generation = self.output.as_ref().map_or(0, |o| o.generation + 1);
        match self
            .renders
            .update(state, compare, size, texture, texture_key, generation)
        {
            Ok(None) => false,
            Ok(Some(r)) => {
                if let Some(ms) = r.render_ms {
                    self.timing.render_ms = ms;
                    self.timing.renders += 1;
                }
                if let Some(old) = self.output.replace(r.output) {
                    self.renders.recycle(old);
                }
                self.error = None;
                self.cancelled = None;
                true
            }
            Err(e) => {
                // Also on stderr, once per new message: a terminal (or a test) sees why the
                // picture is missing.
                if self.error.as_ref().map(|old| &old.text) != Some(&e.text) {
                    eprintln!("barylab: {}", e.text);
                }
                self.error = Some(e);
                false
            }
        }
    }

    /// Builds the view images and uploads them, only if the render, the GPU view's images or
    /// the wipe moved.
    pub(super) fn upload(
        &mut self,
        ctx: &egui::Context,
        (compare, wipe): (Compare, f32),
        gpu: Option<&GpuView>,
        samples_view: crate::figure::sample_buffers::SampleView,
    ) {
        let Some(out) = &self.output else {
            return;
        };
        let wipe_col = crate::figure::wipe_column(wipe, out.size[0]);
        let tag = (
            out.generation,
            compare,
            wipe_col,
            gpu.map(|g| g.generation),
            // The sample view's image changes with its kind and index too.
            self.samples.generation
                ^ (u64::from(samples_view.index) << 40)
                ^ ((samples_view.kind as u64) << 56),
        );
        if self.uploaded == Some(tag) && self.textures.len() == self.views.len() {
            return;
        }
        let start = Instant::now();
        self.samples_shown = 0;
        let images: Vec<egui::ColorImage> = self
            .views
            .iter()
            .enumerate()
            .map(|(i, v)| match gpu {
                Some(g) => other_image::view_image(g, compare, i, wipe_col)
                    .unwrap_or_else(|| view_image(out, g.fallback(), wipe_col)),
                None => match v.content {
                    ViewContent::Mode(m) => self.samples.image(m, samples_view),
                    _ => None,
                }
                .inspect(|_| self.samples_shown += 1)
                .unwrap_or_else(|| view_image(out, v.content, wipe_col)),
            })
            .collect();
        self.textures.truncate(images.len());
        for (i, image) in images.into_iter().enumerate() {
            match self.textures.get_mut(i) {
                Some(t) => t.set(image, VIEW_TEXTURE),
                None => {
                    self.textures
                        .push(ctx.load_texture(format!("canvas-{i}"), image, VIEW_TEXTURE))
                }
            }
        }
        self.uploaded = Some(tag);
        self.timing.upload_ms = start.elapsed().as_secs_f64() * 1e3;
        self.timing.uploads += 1;
    }
}
