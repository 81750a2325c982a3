//! The canvas's layout: the views of a comparison, the render size and the points per
//! rendered pixel, for a fixed image size or one that follows the window.

use egui::{Pos2, Rect};

use super::canvas::{SIDE_BY_SIDE_GAP, WHOLE_PIXELS_FROM};
use super::state::PIXEL_SIZE_RANGE;
use crate::figure::overlay;
use crate::figure::{Compare, ViewContent};
use crate::raster::Interpolation;

/// How the rendered image's size is chosen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Sizing {
    /// A fixed size (the scene's), drawn as large as the view allows: whole screen pixels per
    /// rendered pixel when magnified, so every pixel is the same square.
    Fixed([u32; 2]),
    /// Follow the window: `pixel_size` screen pixels per rendered pixel, the aspect ratio
    /// (width / height) of the scene.
    Fit {
        /// The scene's width / height.
        aspect: f32,
        /// Screen pixels per rendered pixel.
        pixel_size: u32,
    },
}

/// The canvas's views, the render size and the points per rendered pixel.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Layout {
    /// Each view's screen rectangle (points) and what it shows.
    pub views: Vec<(Rect, ViewContent)>,
    /// The render size: width and height in rendered pixels.
    pub size: [u32; 2],
    /// Points per rendered pixel.
    pub scale: f32,
}

impl Layout {
    /// Screen pixels per rendered pixel, as a whole number for the overlay's grid and the
    /// figure's pixel size (at least 1, at most the largest pixel size).
    pub(crate) fn pixel_size(&self, pixels_per_point: f32) -> u32 {
        let px = (self.scale * pixels_per_point).round();
        (px as u32).clamp(PIXEL_SIZE_RANGE.0, PIXEL_SIZE_RANGE.1)
    }
}

/// Splits the available rectangle into the views of a comparison, each the largest rectangle
/// of the image's aspect ratio that fits, and fixes the render size and the scale.
pub(crate) fn layout(
    available: Rect,
    compare: Compare,
    sizing: Sizing,
    pixels_per_point: f32,
) -> Layout {
    let aspect = match sizing {
        Sizing::Fixed([w, h]) => w.max(1) as f32 / h.max(1) as f32,
        Sizing::Fit { aspect, .. } => aspect,
    };
    let aspect = if aspect.is_finite() && aspect > 0.0 {
        aspect
    } else {
        1.0
    };
    let areas: Vec<(Rect, ViewContent)> = match compare {
        Compare::SideBySide => {
            // Side by side or one above the other, whichever gives larger views.
            let w = ((available.width() - SIDE_BY_SIDE_GAP) / 2.0).max(1.0);
            let h = ((available.height() - SIDE_BY_SIDE_GAP) / 2.0).max(1.0);
            let fit = |w: f32, h: f32| w.min(h * aspect.max(f32::MIN_POSITIVE));
            let (first, second) = if fit(w, available.height()) >= fit(available.width(), h) {
                (
                    Rect::from_min_size(available.min, egui::vec2(w, available.height())),
                    Rect::from_min_size(
                        Pos2::new(available.max.x - w, available.min.y),
                        egui::vec2(w, available.height()),
                    ),
                )
            } else {
                (
                    Rect::from_min_size(available.min, egui::vec2(available.width(), h)),
                    Rect::from_min_size(
                        Pos2::new(available.min.x, available.max.y - h),
                        egui::vec2(available.width(), h),
                    ),
                )
            };
            vec![
                (first, ViewContent::Mode(Interpolation::Affine)),
                (second, ViewContent::Mode(Interpolation::Perspective)),
            ]
        }
        Compare::Single => vec![(available, ViewContent::Mode(Interpolation::Perspective))],
        Compare::Wipe => vec![(available, ViewContent::Wipe)],
        Compare::Difference => vec![(available, ViewContent::Difference)],
    };
    let first = Rect::from_min_max(
        areas[0].0.min + egui::vec2(0.0, overlay::TITLE_STRIP),
        areas[0].0.max,
    );
    let ppp = pixels_per_point.max(0.01);
    let max = crate::raster::project::MAX_IMAGE_SIZE;
    let (size, scale) = match sizing {
        Sizing::Fit { pixel_size, .. } => {
            let scale = pixel_size as f32 / ppp;
            let fit_w = first.width().min(first.height() * aspect).max(1.0);
            let fit_h = (fit_w / aspect).max(1.0);
            let w = ((fit_w / scale).floor() as u32).clamp(1, max);
            let h = ((fit_h / scale).floor() as u32).clamp(1, max);
            ([w, h], scale)
        }
        Sizing::Fixed([w, h]) => {
            let (w, h) = (w.clamp(1, max), h.clamp(1, max));
            let fit = (first.width().max(1.0) / w as f32).min(first.height().max(1.0) / h as f32);
            // Screen pixels per rendered pixel: whole from WHOLE_PIXELS_FROM on, so every
            // magnified pixel is the same crisp square; below that a pixel is too small to
            // see on its own and the image fills the canvas.
            let px = fit * ppp;
            let px = if px >= WHOLE_PIXELS_FROM {
                px.floor()
            } else {
                px
            };
            ([w, h], px / ppp)
        }
    };
    let views = areas
        .into_iter()
        .map(|(area, content)| {
            let area =
                Rect::from_min_max(area.min + egui::vec2(0.0, overlay::TITLE_STRIP), area.max);
            let shown = egui::vec2(size[0] as f32 * scale, size[1] as f32 * scale);
            let min = area.center() - shown / 2.0;
            // Snap to whole physical pixels so nearest magnification is crisp.
            let min = Pos2::new((min.x * ppp).round() / ppp, (min.y * ppp).round() / ppp);
            (Rect::from_min_size(min, shown), content)
        })
        .collect();
    Layout { views, size, scale }
}
