//! What the app shows about one pixel: the probe's trace (every number, computed by the
//! stages that drew the pixel), its worked-example document, and the triangle the overlay
//! marks. Nothing here re-does the math.

use crate::app::services::render::CanvasOutput;
use crate::figure::overlay::{PixelMark, SampleMark, TriangleMark, magnifier_radius};
use crate::i18n::Lang;
use crate::probe::format::{self, Document};
use crate::probe::{PixelTrace, ProbeError, Prober};
use crate::raster::{Interpolation, RenderSettings, Texture};

/// One pixel's trace and derivation.
#[derive(Clone, Debug)]
pub struct PixelReport {
    pub pixel: [u32; 2],
    /// The mode the trace was made in.
    pub mode: Interpolation,
    pub trace: PixelTrace,
    pub document: Document,
    /// The language of `document`.
    pub lang: Lang,
    /// Which render it belongs to ([`CanvasOutput::generation`]).
    pub generation: u64,
    /// Every sample of the pixels the magnifier shows around this one, when the render has
    /// several per pixel (filled by [`PixelReport::magnify`]; empty otherwise).
    pub sample_marks: Vec<SampleMark>,
}

impl PartialEq for PixelReport {
    fn eq(&self, other: &Self) -> bool {
        self.pixel == other.pixel
            && self.mode == other.mode
            && self.generation == other.generation
            && self.lang == other.lang
    }
}

impl PixelReport {
    /// Probes `pixel` of the rendered scene in `mode`; the derivation is written in `lang`.
    pub fn new(
        output: &CanvasOutput,
        texture: &Texture,
        mode: Interpolation,
        pixel: [u32; 2],
        lang: Lang,
    ) -> Result<Self, ProbeError> {
        let settings = Self::settings(output, mode);
        Self::with_prober(
            output,
            &Prober::new(&output.scene, texture, &settings)?,
            pixel,
            lang,
        )
    }

    /// The settings a probe of `output` in `mode` traces with.
    pub fn settings(output: &CanvasOutput, mode: Interpolation) -> RenderSettings {
        RenderSettings {
            mode,
            ..output.scene.settings()
        }
    }

    /// Probes `pixel` with a prober made for `output` (kept by the app for the render it
    /// belongs to, so moving the pointer does not prepare every triangle again).
    pub fn with_prober(
        output: &CanvasOutput,
        prober: &Prober<'_>,
        pixel: [u32; 2],
        lang: Lang,
    ) -> Result<Self, ProbeError> {
        let mode = prober.settings().mode;
        let trace = prober.pixel(pixel[0], pixel[1])?;
        let document = format::document_in(&trace, lang);
        Ok(Self {
            pixel,
            mode,
            trace,
            document,
            lang,
            generation: output.generation,
            sample_marks: Vec::new(),
        })
    }

    /// Fills [`PixelReport::sample_marks`]: the samples of every pixel within the magnifier's
    /// radius, from `prober` (the renderer's own per-pixel kernel); nothing for a
    /// single-sample render.
    pub fn magnify(&mut self, prober: &Prober<'_>) {
        let settings = prober.settings();
        let [px, py] = self.pixel;
        let r = magnifier_radius(settings.samples.count.get() > 1);
        let mut marks = Vec::new();
        for y in py.saturating_sub(r)..=(py + r).min(settings.height.saturating_sub(1)) {
            for x in px.saturating_sub(r)..=(px + r).min(settings.width.saturating_sub(1)) {
                let Some(samples) = prober.pixel_samples(x, y) else {
                    return;
                };
                marks.extend(samples.iter().map(|s| SampleMark {
                    position: glam::DVec2::from_array(s.position),
                    triangle: s.triangle,
                }));
            }
        }
        self.sample_marks = marks;
    }

    /// Whether this report is for this pixel of this render in this mode, in this language.
    pub fn is_for(
        &self,
        output: &CanvasOutput,
        mode: Interpolation,
        pixel: [u32; 2],
        lang: Lang,
    ) -> bool {
        self.pixel == pixel
            && self.mode == mode
            && self.generation == output.generation
            && self.lang == lang
    }

    /// The triangle whose weights the trace shows ([`crate::figure::triangle_mark`]).
    pub fn triangle(&self) -> Option<TriangleMark> {
        crate::figure::triangle_mark(&self.trace)
    }

    /// The overlay's mark of this pixel ([`crate::figure::pixel_mark`]).
    pub fn mark(&self) -> PixelMark {
        crate::figure::pixel_mark(&self.trace)
    }
}
