//! The per-sample buffers behind the canvas's sample view: the core's samples of the canvas's
//! render ([`crate::figure::sample_buffers::samples_of`]), one per mode shown, made again only
//! when the render or the view's black-edge bug changes. No widgets here.

use crate::app::services::render::CanvasOutput;
use crate::figure::sample_buffers::{self, SampleView};
use crate::raster::multisample::SampleBuffer;
use crate::raster::{Interpolation, RenderSettings, Texture};

/// The samples of the canvas's last render, per mode.
#[derive(Default)]
pub struct SampleImages {
    /// The render's generation and the bug they were made for.
    key: Option<(u64, bool)>,
    /// One buffer per mode of the render.
    buffers: Vec<(Interpolation, SampleBuffer)>,
    /// Why the samples could not be made (the renderer's message).
    pub error: Option<String>,
    /// Increments whenever the buffers change (the canvas uploads again).
    pub generation: u64,
}

impl SampleImages {
    /// Makes the samples of `out`'s renders when `view` shows them and they are not made yet;
    /// drops them when the view is off. `rasterizer` is the canvas's.
    pub fn update(
        &mut self,
        out: &CanvasOutput,
        texture: &Texture,
        view: SampleView,
        rasterizer: crate::raster::render::Rasterizer,
    ) {
        let multisampled = out.scene.samples().count.get() > 1;
        if !view.is_on() || !multisampled {
            if self.key.take().is_some() {
                self.buffers.clear();
                self.generation += 1;
            }
            self.error = None;
            return;
        }
        let key = (out.generation, view.black_edges);
        if self.key == Some(key) {
            return;
        }
        self.key = Some(key);
        self.generation += 1;
        self.error = None;
        self.buffers.clear();
        let base = out.scene.settings();
        for (mode, _) in &out.renders {
            let settings = RenderSettings {
                mode: *mode,
                rasterizer,
                ..base
            };
            match sample_buffers::samples_of(&out.scene, texture, &settings, view.black_edges) {
                Ok(b) => self.buffers.push((*mode, b)),
                Err(e) => self.error = Some(e.to_string()),
            }
        }
    }

    /// The samples drawn in `mode` (else the first mode's), if made.
    pub fn buffer(&self, mode: Interpolation) -> Option<&SampleBuffer> {
        self.buffers
            .iter()
            .find(|(m, _)| *m == mode)
            .or(self.buffers.first())
            .map(|(_, b)| b)
    }

    /// The image `view` shows of the samples drawn in `mode`, if they are made.
    pub fn image(&self, mode: Interpolation, view: SampleView) -> Option<egui::ColorImage> {
        let b = self.buffer(mode)?;
        let pixels = sample_buffers::image(b, view.kind, view.index as usize);
        let size = [b.width as usize, b.height as usize];
        (pixels.len() == size[0] * size[1]).then(|| {
            egui::ColorImage::new(
                size,
                pixels
                    .iter()
                    .map(|c| egui::Color32::from_rgba_unmultiplied(c[0], c[1], c[2], c[3]))
                    .collect(),
            )
        })
    }

    /// The titles of a view showing `content` under `view`, when it shows a sample buffer:
    /// the whole title, then shorter forms for a narrow view
    /// ([`sample_buffers::titles`]).
    pub fn titles(
        &self,
        content: crate::figure::ViewContent,
        view: SampleView,
        lang: crate::i18n::Lang,
    ) -> Option<[String; 3]> {
        let crate::figure::ViewContent::Mode(m) = content else {
            return None;
        };
        let n = self.buffer(m)?.offsets.len();
        let titles =
            sample_buffers::titles(view.kind, view.index as usize, n, view.black_edges, lang);
        Some(if self.buffers.len() > 1 {
            // The whole title with the mode's whole name, the shorter ones with its short name.
            let mode = crate::figure::overlay::mode_label_in(m, lang);
            let short = crate::figure::overlay::short_mode_label(&mode, lang);
            let [full, a, b] = titles;
            [
                format!("{full} ({mode})"),
                format!("{a} ({})", short.as_deref().unwrap_or(&mode)),
                format!("{b} ({})", short.as_deref().unwrap_or(&mode)),
            ]
        } else {
            titles
        })
    }
}
