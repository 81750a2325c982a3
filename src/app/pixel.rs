//! What the app shows about one pixel: the probe's trace (every number, computed by the
//! stages that drew the pixel), its worked-example document, and the triangle the overlay
//! marks. Nothing here re-does the math.

use super::render::CanvasOutput;
use crate::figure::overlay::{PixelMark, TriangleMark};
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
        })
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
