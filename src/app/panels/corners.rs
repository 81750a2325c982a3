//! Where presentation mode puts a box over the picture (the card, the plot, the magnifier):
//! the corner of the canvas that hides least of the scene.

use crate::app::BaryApp;
use crate::app::panels::canvas::View;
use crate::figure::ViewContent;

/// Points: the box around a handle where its letter and w label go.
const LABELLED_HANDLE: egui::Vec2 = egui::vec2(150.0, 80.0);
/// Points: the box at the image's bottom left where the note naming the corners behind the
/// camera goes.
const BEHIND_NOTE: egui::Vec2 = egui::vec2(420.0, 50.0);
/// A corner over a handle's label, a title or the colour bar counts as this many covered
/// samples.
const MARK_PENALTY: u32 = 40;
/// Points around a card over the picture that the pointer keeps it away from (a handle's
/// disc and a little more).
const POINTER_CLEARANCE: f32 = 24.0;
/// Samples per side of the grid that measures how much of the picture a card would hide.
const CORNER_SAMPLES: usize = 12;
/// A corner over the pinned pixel counts as this many covered samples (more than a whole
/// grid: it is never chosen while another corner is free of the pin).
const PIN_PENALTY: u32 = 1000;

impl BaryApp {
    /// The corner of the canvas `area` where a card of `size` hides least of the picture:
    /// fewest covered pixels under it (sampled on a grid), never over the pinned pixel, in
    /// the order top right, top left, bottom right, bottom left on a tie. It depends on the
    /// render and the pin only (not on the hovered pixel), so the card does not jump about.
    ///
    /// Except that it keeps out from under the `pointer`: the emptiest corner whose box, grown
    /// by [`POINTER_CLEARANCE`], does not hold it. On a picture with a handle in every
    /// corner (the default scene presented at 1024x768) the card lay over a handle, which the
    /// presenter could then neither see nor find to drag; now the card moves away when the
    /// pointer comes to it.
    pub(in crate::app) fn emptiest_corner(
        &self,
        area: egui::Rect,
        size: egui::Vec2,
        pointer: Option<egui::Pos2>,
    ) -> egui::Rect {
        let corners = self.corners_by_emptiness(area, size, &self.canvas.views);
        let clear =
            |c: &egui::Rect| pointer.is_none_or(|p| !c.expand(POINTER_CLEARANCE).contains(p));
        corners
            .iter()
            .find(|(_, c)| clear(c))
            .unwrap_or(&corners[0])
            .1
    }

    /// The four corners for a box of `size` in the canvas `area` with how much each hides
    /// (covered samples plus penalties) of the canvas's `views` (as drawn, or as a layout
    /// being considered would draw them), the emptiest first (see [`Self::emptiest_corner`]).
    fn corners_by_emptiness(
        &self,
        area: egui::Rect,
        size: egui::Vec2,
        views: &[View],
    ) -> Vec<(u32, egui::Rect)> {
        let corners = [
            egui::Rect::from_min_size(egui::pos2(area.max.x - size.x, area.min.y), size),
            egui::Rect::from_min_size(area.min, size),
            egui::Rect::from_min_size(area.max - size, size),
            egui::Rect::from_min_size(egui::pos2(area.min.x, area.max.y - size.y), size),
        ];
        let Some(output) = &self.canvas.output else {
            return corners.iter().map(|c| (0, *c)).collect();
        };
        let pinned = self.state.view.pinned;
        let (marks, behind) = self.corner_marks(output);
        let marks = &marks;
        let score = |card: &egui::Rect| -> u32 {
            let mut covered = 0;
            for view in views {
                // The handles with their w labels, the title strip and the colour bar count
                // as picture too.
                for v in marks.iter() {
                    let at = view.transform.to_screen(*v);
                    let label = egui::Rect::from_center_size(at, LABELLED_HANDLE);
                    if label.intersects(*card) {
                        covered += MARK_PENALTY;
                    }
                }
                // The note naming the corners behind the camera, at the image's bottom left.
                let note = egui::Rect::from_min_max(
                    egui::pos2(view.rect.min.x, view.rect.max.y - BEHIND_NOTE.y),
                    egui::pos2(view.rect.min.x + BEHIND_NOTE.x, view.rect.max.y),
                );
                if behind && note.intersects(*card) {
                    covered += MARK_PENALTY;
                }
                let title = egui::Rect::from_min_max(
                    egui::pos2(view.rect.min.x, view.area.min.y),
                    egui::pos2(view.rect.max.x, view.rect.min.y),
                );
                if title.height() > 1.0 && title.intersects(*card) {
                    covered += MARK_PENALTY;
                }
                if view.content == ViewContent::Difference {
                    let bar = egui::Rect::from_min_max(
                        egui::pos2(view.rect.max.x, view.rect.min.y),
                        egui::pos2(
                            view.rect.max.x + crate::figure::overlay::COLOR_BAR_ROOM,
                            view.rect.max.y,
                        ),
                    );
                    if bar.intersects(*card) {
                        covered += 2 * MARK_PENALTY;
                    }
                }
                let mode = match view.content {
                    ViewContent::Mode(m) => m,
                    _ => self.state.options().mode,
                };
                let Some(render) = output.render(mode) else {
                    continue;
                };
                let frame = &render.frame;
                let part = card.intersect(view.rect);
                if !part.is_positive() {
                    continue;
                }
                if let Some([px, py]) = pinned {
                    let centre = view
                        .transform
                        .to_screen(glam::DVec2::new(f64::from(px) + 0.5, f64::from(py) + 0.5));
                    if part.expand(8.0).contains(centre) {
                        covered += PIN_PENALTY;
                    }
                }
                let steps = CORNER_SAMPLES as f32;
                for j in 0..CORNER_SAMPLES {
                    for i in 0..CORNER_SAMPLES {
                        let p = part.min
                            + egui::vec2(
                                (i as f32 + 0.5) / steps * part.width(),
                                (j as f32 + 0.5) / steps * part.height(),
                            );
                        let c = view.transform.to_canvas(p);
                        let (x, y) = (c.x.floor(), c.y.floor());
                        if x < 0.0 || y < 0.0 {
                            continue;
                        }
                        let (x, y) = (x as usize, y as usize);
                        let width = frame.width as usize;
                        if x < width && frame.depth.get(y * width + x).is_some_and(|d| *d < 1.0) {
                            covered += 1;
                        }
                    }
                }
            }
            covered
        };
        // A stable sort: on a tie the order above.
        let mut scored: Vec<(u32, egui::Rect)> = corners.iter().map(|c| (score(c), *c)).collect();
        scored.sort_by_key(|(s, _)| *s);
        scored
    }
}

impl BaryApp {
    /// A corner for a box of `size` in the canvas `area` that overlaps none of `taken` and
    /// hides no mark and at most a few samples of the picture ([`FREE_CORNER`]), if there is
    /// one: for boxes the lecture can do without (the magnifier).
    pub(in crate::app) fn free_corner(
        &self,
        area: egui::Rect,
        size: egui::Vec2,
        taken: &[egui::Rect],
    ) -> Option<egui::Rect> {
        self.free_corner_in(area, size, taken, &self.canvas.views, FREE_CORNER)
    }

    /// A corner for a box of `size` in the canvas `area` clear of `taken` that hides no mark
    /// and at most `most` samples of the `views` (as a layout being considered draws them).
    pub(in crate::app) fn free_corner_in(
        &self,
        area: egui::Rect,
        size: egui::Vec2,
        taken: &[egui::Rect],
        views: &[View],
        most: u32,
    ) -> Option<egui::Rect> {
        self.corners_by_emptiness(area, size, views)
            .into_iter()
            .find(|(_, c)| !taken.iter().any(|t| c.intersects(*t)))
            .filter(|(score, _)| *score <= most)
            .map(|(_, c)| c)
    }
}

/// The most a box the lecture can do without may hide: this many covered samples of the
/// [`CORNER_SAMPLES`]² grid (a tenth), and no mark.
const FREE_CORNER: u32 = 14;
/// The most the card over the picture may hide of the [`CORNER_SAMPLES`]² grid (a fifth,
/// where the scene's empty corner is not quite the card's shape) and no mark; else the
/// picture makes room for the card beside it.
pub(in crate::app) const FREE_CARD: u32 = 29;

/// The drawn handles' points in the render's pixels, and whether a vertex is behind the
/// camera: kept for the render and the handles they were found for (every vertex of the scene
/// is projected to find them, up to three times a frame otherwise).
#[derive(Default)]
pub(in crate::app) struct MarkCache {
    key: Option<(u64, Vec<usize>)>,
    handles: Vec<glam::DVec2>,
    behind: bool,
}

impl BaryApp {
    /// The points a box over the picture must not hide (the drawn handles, the clipper's
    /// labelled corners K1, K2, ... from the pinned pixel's trace) in the render's pixels, and
    /// whether a vertex is behind the camera.
    fn corner_marks(
        &self,
        output: &crate::app::services::render::CanvasOutput,
    ) -> (Vec<glam::DVec2>, bool) {
        let key = (output.generation, self.canvas.handles.clone());
        let mut cache = self.corner_marks.borrow_mut();
        if cache.key.as_ref() != Some(&key) {
            let viewport = output.viewport();
            let vertices = crate::figure::vertices_on_screen(&output.scene, viewport);
            let image = glam::DVec2::new(f64::from(viewport.width), f64::from(viewport.height));
            *cache = MarkCache {
                handles: key
                    .1
                    .iter()
                    .filter_map(|&k| vertices.get(k)?.window)
                    .map(|w| crate::figure::overlay::handle_position(w, image))
                    .collect(),
                behind: vertices.iter().any(|v| v.window.is_none()),
                key: Some(key),
            };
        }
        let clip = self
            .reports
            .pin
            .as_ref()
            .and_then(|r| crate::figure::clip_mark(&r.trace));
        let marks = cache
            .handles
            .iter()
            .copied()
            .chain(
                clip.iter()
                    .flat_map(|c| c.corners.iter().filter(|k| k.2).map(|k| k.1)),
            )
            .collect();
        (marks, cache.behind)
    }
}
