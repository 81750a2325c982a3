//! The inspector's two pixels, the hovered and the pinned one, probed again only when the
//! pixel, the render or the mode changed, with one [`Prober`] per render and mode between them
//! (it clips and sets up every triangle once, not on every pointer move).

use std::sync::Arc;

use crate::app::services::pixel::PixelReport;
use crate::app::services::render::CanvasOutput;
use crate::i18n::Lang;
use crate::probe::Prober;
use crate::raster::{Interpolation, Texture};

/// The reports of the hovered and the pinned pixel, and the prober they share.
#[derive(Default)]
pub struct PixelReports {
    pub hover: Option<PixelReport>,
    pub pin: Option<PixelReport>,
    /// The prober of the current render and mode, tagged with both.
    prober: Option<((u64, Interpolation), Prober<'static>)>,
    /// How many probers were made (tests check that hovering reuses one).
    pub probers_built: u64,
}

/// Which pixels, renders, modes and languages the reports are for (to see that they changed).
pub type ReportsKey = [Option<([u32; 2], Interpolation, u64, Lang)>; 2];

impl PixelReports {
    /// Which pixels, renders and modes the reports are for.
    pub fn key(&self) -> ReportsKey {
        let key =
            |r: &Option<PixelReport>| r.as_ref().map(|r| (r.pixel, r.mode, r.generation, r.lang));
        [key(&self.hover), key(&self.pin)]
    }

    /// Probes the `hover`ed and the `pinned` pixel of `output` in `mode` (again only if the
    /// pixel, the render or the language changed), their derivations in `lang`. Returns the
    /// error of a probe that failed.
    pub fn update(
        &mut self,
        output: Option<&CanvasOutput>,
        texture: &Arc<Texture>,
        mode: Interpolation,
        [hover, pinned]: [Option<[u32; 2]>; 2],
        lang: Lang,
    ) -> Option<String> {
        let Some(out) = output else {
            self.hover = None;
            self.pin = None;
            self.prober = None;
            return None;
        };
        let mut error = None;
        let prober = &mut self.prober;
        let built = &mut self.probers_built;
        let mut update =
            |slot: &mut Option<PixelReport>, pixel: Option<[u32; 2]>, magnify: bool| {
                let Some(p) = pixel else {
                    *slot = None;
                    return;
                };
                if slot.as_ref().is_some_and(|r| r.is_for(out, mode, p, lang)) {
                    return;
                }
                // One prober per render and mode: it clips and sets up every triangle once.
                let tag = (out.generation, mode);
                if prober.as_ref().is_none_or(|(t, _)| *t != tag) {
                    let settings = PixelReport::settings(out, mode);
                    *prober = match Prober::shared(&out.scene, texture.clone(), &settings) {
                        Ok(pr) => {
                            *built += 1;
                            Some((tag, pr))
                        }
                        Err(e) => {
                            error = Some(e.to_string());
                            *slot = None;
                            return;
                        }
                    };
                }
                let Some((_, pr)) = prober.as_ref() else {
                    return;
                };
                *slot = match PixelReport::with_prober(out, pr, p, lang) {
                    Ok(mut r) => {
                        if magnify {
                            r.magnify(pr);
                        }
                        Some(r)
                    }
                    Err(e) => {
                        error = Some(e.to_string());
                        None
                    }
                };
            };
        update(&mut self.hover, hover, false);
        // The pinned pixel's magnifier shows every sample around it.
        update(&mut self.pin, pinned, true);
        error
    }
}
