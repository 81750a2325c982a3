//! The canvas's layout: the views of a comparison, the render size and the points per
//! rendered pixel, for a fixed image size or one that follows the window.

use egui::{Pos2, Rect};

use crate::app::document::state::PIXEL_SIZE_RANGE;
use crate::figure::overlay;
use crate::figure::{Compare, ViewContent};
use crate::raster::Interpolation;

/// Points between the two views of the side-by-side comparison.
pub(crate) const SIDE_BY_SIDE_GAP: f32 = crate::figure::SIDE_BY_SIDE_GAP as f32;
/// Screen pixels per rendered pixel from which a fixed-size image is magnified by a whole
/// number.
pub const WHOLE_PIXELS_FROM: f32 = 2.0;

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

/// How the canvas frames its images: the title strip above each and how a magnified image is
/// scaled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Framing {
    /// Points above each image kept for its title (the mode, the heatmap's meaning).
    pub title_strip: f32,
    /// Magnified pixels are whole screen pixels, so every pixel is the same crisp square; off,
    /// the image fills its view (presentation mode: the largest picture for the room).
    pub whole_pixels: bool,
}

impl Framing {
    /// The app's usual framing: titles above the images, whole screen pixels.
    pub(crate) const NORMAL: Framing = Framing {
        title_strip: overlay::TITLE_STRIP,
        whole_pixels: true,
    };

    /// Presentation mode's framing for `compare`: the image fills its view; a single view has
    /// no title strip (the card names the mode), the comparisons keep theirs (they say which
    /// side is which).
    pub(crate) fn presenting(compare: Compare) -> Framing {
        Framing {
            title_strip: if compare == Compare::Single {
                0.0
            } else {
                overlay::TITLE_STRIP
            },
            whole_pixels: false,
        }
    }
}

/// The canvas's views, the render size and the points per rendered pixel.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Layout {
    /// Each view's screen rectangle (points) and what it shows.
    pub views: Vec<(Rect, ViewContent)>,
    /// Each view's share of the canvas (points): its image, the title strip above it and the
    /// margins around it, where the overlay's handles and labels may go.
    pub areas: Vec<Rect>,
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
    framing: Framing,
) -> Layout {
    let strip = framing.title_strip;
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
            // Side by side or one above the other, whichever gives larger images (each area
            // less its title strip and margins).
            let w = ((available.width() - SIDE_BY_SIDE_GAP) / 2.0).max(1.0);
            let h = ((available.height() - SIDE_BY_SIDE_GAP) / 2.0).max(1.0);
            if side_by_side_is_larger(available.size(), aspect, strip) {
                vec![
                    Rect::from_min_size(available.min, egui::vec2(w, available.height())),
                    Rect::from_min_size(
                        Pos2::new(available.max.x - w, available.min.y),
                        egui::vec2(w, available.height()),
                    ),
                ]
            } else {
                vec![
                    Rect::from_min_size(available.min, egui::vec2(available.width(), h)),
                    Rect::from_min_size(
                        Pos2::new(available.min.x, available.max.y - h),
                        egui::vec2(available.width(), h),
                    ),
                ]
            }
            .into_iter()
            .zip([
                ViewContent::Mode(Interpolation::Affine),
                ViewContent::Mode(Interpolation::Perspective),
            ])
            .collect()
        }
        Compare::Single => vec![(available, ViewContent::Mode(Interpolation::Perspective))],
        Compare::Wipe => vec![(available, ViewContent::Wipe)],
        Compare::Difference => vec![(available, ViewContent::Difference)],
    };
    // A difference view keeps room right of its image for the colour bar.
    let bar = if compare == Compare::Difference {
        overlay::COLOR_BAR_ROOM
    } else {
        0.0
    };
    let image_room = |area: Rect| {
        let mut r = image_area(area, strip);
        r.max.x = (r.max.x - bar).max(r.min.x + 1.0);
        r
    };
    let first = image_room(areas[0].0);
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
            let px = if framing.whole_pixels && px >= WHOLE_PIXELS_FROM {
                px.floor()
            } else {
                px
            };
            ([w, h], px / ppp)
        }
    };
    let views = areas
        .iter()
        .map(|&(area, content)| {
            let area = image_room(area);
            let shown = egui::vec2(size[0] as f32 * scale, size[1] as f32 * scale);
            let min = area.center() - shown / 2.0;
            // Snap to whole physical pixels so nearest magnification is crisp.
            let min = Pos2::new((min.x * ppp).round() / ppp, (min.y * ppp).round() / ppp);
            (Rect::from_min_size(min, shown), content)
        })
        .collect();
    Layout {
        views,
        areas: areas.into_iter().map(|(a, _)| a).collect(),
        size,
        scale,
    }
}

/// Points kept free left, right and below a view's image: a vertex handle at the image's edge
/// (its circle, grown when active, and its stroke) shows whole there.
pub(crate) const HANDLE_MARGIN: f32 = overlay::HANDLE_RADIUS + 6.0;

/// Where a view's image may go in its `area`: below the title strip (`title_strip` points),
/// inside the handles' margins (when the area is large enough to spare them).
pub(crate) fn image_area(area: Rect, title_strip: f32) -> Rect {
    let m = if area.width() > 8.0 * HANDLE_MARGIN && area.height() > 8.0 * HANDLE_MARGIN {
        HANDLE_MARGIN
    } else {
        0.0
    };
    Rect::from_min_max(
        area.min + egui::vec2(m, title_strip),
        area.max - egui::vec2(m, m),
    )
}

/// Whether two views of images `aspect` wide (width / height) go side by side in `available`
/// points rather than one above the other: unless stacking gives each image (less its title
/// strip and margins) [`STACK_ADVANTAGE`] times the width. Two images at the same height are
/// the easier comparison, and a few per cent are not worth it.
pub(crate) fn side_by_side_is_larger(available: egui::Vec2, aspect: f32, title_strip: f32) -> bool {
    let aspect = aspect.max(f32::MIN_POSITIVE);
    let image_width = |w: f32, h: f32| {
        let inner = image_area(
            Rect::from_min_size(Pos2::ZERO, egui::vec2(w, h)),
            title_strip,
        );
        inner.width().min(inner.height() * aspect).max(0.0)
    };
    let half_w = ((available.x - SIDE_BY_SIDE_GAP) / 2.0).max(1.0);
    let half_h = ((available.y - SIDE_BY_SIDE_GAP) / 2.0).max(1.0);
    image_width(half_w, available.y) * STACK_ADVANTAGE >= image_width(available.x, half_h)
}

/// How much larger stacked images must be for the side-by-side comparison to stack them.
const STACK_ADVANTAGE: f32 = 1.05;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presenting_a_small_image_fills_the_view_instead_of_whole_pixels() {
        // A 320x240 step image in a 700x500 canvas at 1.5 pixels per point: 2.9 screen pixels
        // per pixel fit. Normally that is floored to 2 (crisp squares); presenting, it fills.
        let available = Rect::from_min_size(Pos2::ZERO, egui::vec2(700.0, 500.0));
        let sizing = Sizing::Fixed([320, 240]);
        let normal = layout(available, Compare::Single, sizing, 1.5, Framing::NORMAL);
        assert_eq!(normal.scale * 1.5, 2.0);
        let present = layout(
            available,
            Compare::Single,
            sizing,
            1.5,
            Framing::presenting(Compare::Single),
        );
        let r = present.views[0].0;
        // No title strip: the image is as tall as the canvas less the handles' margin below.
        assert!((r.height() - (500.0 - HANDLE_MARGIN)).abs() < 1.0, "{r:?}");
        assert!(
            r.width() * r.height() > 1.9 * normal.views[0].0.area(),
            "{r:?}"
        );
        // The comparisons keep their titles.
        assert_eq!(
            Framing::presenting(Compare::SideBySide).title_strip,
            overlay::TITLE_STRIP
        );
    }

    #[test]
    fn side_by_side_when_the_title_strips_make_stacked_views_smaller() {
        // The canvas at 1920x1080 with text size 1.5 and both panels open: 4:3 views. Without
        // the title strips stacked views looked larger (min(756, 323 * 4/3) = 431 > 373); with
        // them and the handles' margins the two are within a few per cent (339 and 350 points
        // wide), and side by side wins.
        let available = egui::vec2(756.0, 657.0);
        let strip = overlay::TITLE_STRIP;
        assert!(side_by_side_is_larger(available, 4.0 / 3.0, strip));
        let lay = layout(
            Rect::from_min_size(Pos2::ZERO, available),
            Compare::SideBySide,
            Sizing::Fixed([800, 600]),
            1.5,
            Framing::NORMAL,
        );
        let [a, b] = [lay.views[0].0, lay.views[1].0];
        assert!(a.right() <= b.left(), "{a:?} {b:?}");
        // And a wide short canvas stacks nothing.
        assert!(side_by_side_is_larger(
            egui::vec2(1200.0, 400.0),
            4.0 / 3.0,
            strip
        ));
        // A tall narrow one stacks.
        assert!(!side_by_side_is_larger(
            egui::vec2(500.0, 900.0),
            4.0 / 3.0,
            strip
        ));
    }

    #[test]
    fn a_handle_at_an_image_corner_stays_inside_its_views_area() {
        for compare in [Compare::Single, Compare::SideBySide] {
            for available in [egui::vec2(700.0, 500.0), egui::vec2(1200.0, 650.0)] {
                let lay = layout(
                    Rect::from_min_size(Pos2::new(10.0, 20.0), available),
                    compare,
                    Sizing::Fixed([800, 600]),
                    1.0,
                    Framing::NORMAL,
                );
                for (&(image, _), area) in lay.views.iter().zip(&lay.areas) {
                    let r = overlay::HANDLE_RADIUS + 4.0;
                    for corner in [image.left_bottom(), image.right_bottom()] {
                        let handle = Rect::from_center_size(corner, egui::Vec2::splat(2.0 * r));
                        assert!(area.contains_rect(handle), "{handle:?} in {area:?}");
                    }
                }
            }
        }
    }
}
