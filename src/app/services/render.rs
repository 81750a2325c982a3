//! The canvas's renders: what a render depends on, the few renders kept for reuse, and the
//! images of the views (one per mode, the wipe, the difference heatmap). No widgets here.

use std::sync::Arc;
use std::time::Instant;

use egui::Color32;

use crate::app::document::edit;
use crate::app::document::state::AppState;
use crate::figure::heatmap::{self, Heatmap};
use crate::figure::{Compare, ViewContent, modes_for, wipe_pixels};
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

/// The last render's key and the renders kept for reuse.
#[derive(Default)]
pub struct RenderCache {
    key: Option<RenderKey>,
    cache: Vec<(RenderCacheKey, Arc<Render>)>,
    /// A framebuffer of a render that left the cache, reused by the next render.
    spare: Option<Framebuffer>,
    /// The heatmap of an output no longer shown, whose memory the next heatmap reuses.
    spare_heat: Option<Heatmap>,
}

/// A new output of [`RenderCache::update`].
pub struct Rendered {
    pub output: CanvasOutput,
    /// How long rendering took, if anything was rendered (not all from the cache).
    pub render_ms: Option<f64>,
}

impl RenderCache {
    /// Takes back an output that is no longer shown, keeping its heatmap's memory for the next
    /// one.
    pub fn recycle(&mut self, old: CanvasOutput) {
        if old.heatmap.is_some() {
            self.spare_heat = old.heatmap;
        }
    }

    /// Renders `state` at `size` for the comparison `compare` if anything the image depends
    /// on changed: `Ok(None)` when nothing did. `generation` numbers the new output.
    pub fn update(
        &mut self,
        state: &AppState,
        compare: Compare,
        size: [u32; 2],
        texture: &Texture,
        texture_key: TextureKey,
        generation: u64,
    ) -> Result<Option<Rendered>, String> {
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
        if self.key.as_ref() == Some(&key) {
            return Ok(None);
        }
        let start = Instant::now();
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
        let mut renders = Vec::new();
        let mut rendered = false;
        for &mode in &key.modes {
            let one = (
                key.scene.clone(),
                mode,
                key.texture.clone(),
                buffers,
                key.rasterizer,
            );
            if let Some((_, r)) = self.cache.iter().find(|(k, _)| *k == one) {
                renders.push((mode, r.clone()));
                continue;
            }
            let settings = RenderSettings {
                mode,
                rasterizer: key.rasterizer,
                ..base
            };
            let mut frame = self.spare.take().unwrap_or_else(Framebuffer::empty);
            crate::raster::render_into(&mut frame, &mesh, texture, &settings, buffers)
                .map_err(|e| e.to_string())?;
            // The canvas keeps the image only: the inspector probes the scene itself.
            let r = Arc::new(Render {
                frame,
                triangles: Vec::new(),
            });
            self.cache.push((one, r.clone()));
            renders.push((mode, r));
            rendered = true;
        }
        if self.cache.len() > RENDER_CACHE {
            for (_, old) in self.cache.drain(..self.cache.len() - RENDER_CACHE) {
                // Keep the memory of a render nobody else holds for the next one.
                if let Ok(r) = Arc::try_unwrap(old) {
                    self.spare = Some(r.frame);
                }
            }
        }
        let heat = match renders.first() {
            Some((_, r)) if compare == Compare::Difference => {
                let mut h = self.spare_heat.take().unwrap_or_default();
                heatmap::heatmap_into(&r.frame, (texture.width(), texture.height()), &mut h);
                Some(h)
            }
            _ => None,
        };
        let output = CanvasOutput {
            scene: key.scene.clone(),
            size,
            renders,
            heatmap: heat,
            generation,
        };
        self.key = Some(key);
        Ok(Some(Rendered {
            output,
            render_ms: rendered.then(|| start.elapsed().as_secs_f64() * 1e3),
        }))
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
