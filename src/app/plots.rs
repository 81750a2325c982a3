//! The plot of the pinned pixel's row: values read from a render of the canvas's scene with
//! every per-pixel buffer (the rasterizer's own numbers; nothing is interpolated here), for a
//! lesson step's [`LessonPlot`] (in the Lessons panel) or the user's choice (a window).
//!
//! - u and v along the row, affine beside perspective-correct (`uv_affine`, `uv_perspective`);
//! - 1/w (the `inv_w` buffer: a straight line on the screen) and w = 1/(1/w) (a curve);
//! - window depth z/w (the depth buffer: straight) and the view depth w (curved).
//!
//! The last two pairs have very different ranges, so each line is scaled to 0..1 over the row
//! (`(v - min)/(max - min)`): straight stays straight, and curved stays curved.

use std::sync::Arc;

use egui::RichText;
use egui_plot::{Line, Plot, VLine};

use super::BaryApp;
use super::command::AppCommand;
use super::state::Command;
use crate::i18n::{Lang, tr};
use crate::lesson::LessonPlot;
use crate::raster::{Framebuffer, Interpolation, NO_TRIANGLE, Texture};

/// Named lines of one plot: (catalogue key of the name, points).
pub type PlotLines = Vec<(&'static str, Vec<[f64; 2]>)>;

/// The lines of `plot` along row `y` of `frame`, at the covered pixels only.
pub fn row_lines(frame: &Framebuffer, y: u32, plot: LessonPlot) -> PlotLines {
    let w = frame.width as usize;
    let row = y as usize * w;
    let covered: Vec<usize> = (0..w)
        .filter(|x| {
            frame
                .triangle
                .get(row + x)
                .is_some_and(|t| *t != NO_TRIANGLE)
        })
        .collect();
    let line = |f: &dyn Fn(usize) -> f64| -> Vec<[f64; 2]> {
        covered.iter().map(|x| [*x as f64, f(row + x)]).collect()
    };
    match plot {
        LessonPlot::UvRow => vec![
            (
                "lesson.plot_u_affine",
                line(&|k| f64::from(frame.uv_affine[k][0])),
            ),
            (
                "lesson.plot_v_affine",
                line(&|k| f64::from(frame.uv_affine[k][1])),
            ),
            (
                "lesson.plot_u_persp",
                line(&|k| f64::from(frame.uv_perspective[k][0])),
            ),
            (
                "lesson.plot_v_persp",
                line(&|k| f64::from(frame.uv_perspective[k][1])),
            ),
        ],
        LessonPlot::WRow => vec![
            (
                "lesson.plot_inv_w",
                unit(line(&|k| f64::from(frame.inv_w[k]))),
            ),
            (
                "lesson.plot_w_line",
                unit(line(&|k| 1.0 / f64::from(frame.inv_w[k]))),
            ),
        ],
        LessonPlot::DepthRow => vec![
            (
                "lesson.plot_depth_line",
                unit(line(&|k| f64::from(frame.depth[k]))),
            ),
            (
                "lesson.plot_view_depth",
                unit(line(&|k| 1.0 / f64::from(frame.inv_w[k]))),
            ),
        ],
    }
}

/// Scales the values to 0..1 over the line: `(v - min)/(max - min)` (0 when all are equal).
fn unit(points: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    let finite = points.iter().map(|p| p[1]).filter(|v| v.is_finite());
    let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    let span = hi - lo;
    points
        .into_iter()
        .map(|[x, v]| [x, if span > 0.0 { (v - lo) / span } else { 0.0 }])
        .collect()
}

/// The catalogue key of a plot's title.
fn title_key(plot: LessonPlot) -> &'static str {
    match plot {
        LessonPlot::UvRow => "lesson.plot_uv",
        LessonPlot::WRow => "lesson.plot_w",
        LessonPlot::DepthRow => "lesson.plot_depth",
    }
}

/// The plot window's contents: a choice of plot, then the plot with the pinned column marked.
pub fn plot_ui(
    ui: &mut egui::Ui,
    plot: LessonPlot,
    lines: Option<(u32, PlotLines)>,
    lang: Lang,
    hovered_column: &mut Option<u32>,
) -> Vec<Command> {
    let mut out = Vec::new();
    ui.horizontal(|ui| {
        let label = ui.label(tr(lang, "lesson.plot_kind"));
        egui::ComboBox::from_id_salt("row-plot-kind")
            .selected_text(tr(lang, title_key(plot)))
            .width(ui.available_width().clamp(80.0, 360.0))
            .show_ui(ui, |ui| {
                for p in [LessonPlot::UvRow, LessonPlot::WRow, LessonPlot::DepthRow] {
                    if ui
                        .selectable_label(p == plot, tr(lang, title_key(p)))
                        .clicked()
                        && p != plot
                    {
                        out.push(Command::SetPlot(Some(p)));
                    }
                }
            })
            .response
            .labelled_by(label.id);
    });
    let Some((pin_x, lines)) = lines else {
        ui.label(tr(lang, "lesson.plot_none"));
        return out;
    };
    // The legend above the plot, in the lines' colours (egui_plot's legend lies over the
    // lines it names).
    ui.horizontal_wrapped(|ui| {
        for (k, (key, _)) in lines.iter().enumerate() {
            ui.label(RichText::new("━━").color(line_color(k)).strong());
            ui.label(tr(lang, key));
            ui.add_space(8.0);
        }
    });
    let shown = Plot::new(("row-plot", plot as u8))
        .x_axis_label(tr(lang, "lesson.plot_column"))
        .show_axes([true, true])
        // Never taller than the room left (a plot that overflowed its panel would push the
        // panel's first row, the lesson's Previous / Next, out of sight).
        .height((ui.available_height() - 8.0).max(PLOT_MIN_HEIGHT))
        .width(ui.available_width().max(120.0))
        .show(ui, |p| {
            for (k, (key, points)) in lines.into_iter().enumerate() {
                p.line(
                    Line::new(tr(lang, key), points)
                        .color(line_color(k))
                        .width(2.5),
                );
            }
            p.vline(VLine::new("", f64::from(pin_x)));
            p.pointer_coordinate()
        });
    // Hovering the plot marks that column of the pinned row on the canvas.
    if shown.response.hovered()
        && let Some(at) = shown.inner
        && at.x >= 0.0
    {
        *hovered_column = Some(at.x.round() as u32);
    }
    out
}

/// Points: the least height of the plot area.
const PLOT_MIN_HEIGHT: f32 = 48.0;

/// The colour of a plot's `k`th line: distinct on the dark and the light theme, and not the
/// vertex colours (the lines are no vertices).
fn line_color(k: usize) -> egui::Color32 {
    const COLORS: [egui::Color32; 4] = [
        egui::Color32::from_rgb(255, 140, 60),
        egui::Color32::from_rgb(90, 170, 255),
        egui::Color32::from_rgb(240, 90, 200),
        egui::Color32::from_rgb(120, 220, 140),
    ];
    COLORS[k % COLORS.len()]
}

/// The last row rendered with every buffer (one row high), by the canvas render it repeats,
/// the mode and the row.
pub type RowRender = Option<((u64, Interpolation, u32), Arc<Framebuffer>)>;

impl BaryApp {
    /// The chosen plot's lines along the pinned row, from that row rendered with every buffer
    /// (`raster::render_row`: the full render's values, made once per canvas render, mode and
    /// row; the canvas itself renders colour and depth only).
    pub(super) fn row_plot(&mut self, texture: &Texture) -> Option<(u32, PlotLines)> {
        let plot = self.state.view.plot?;
        let [x, y] = self.state.view.pinned?;
        let output = self.canvas.output.as_ref()?;
        let mode = self.state.options().mode;
        let mut settings = output.scene.settings();
        if y >= settings.height || x >= settings.width {
            return None;
        }
        let key = (output.generation, mode, y);
        let row = match &self.lessons.row_render {
            Some((k, r)) if *k == key => r.clone(),
            _ => {
                settings.mode = mode;
                let mesh = output.scene.to_mesh();
                let r = Arc::new(crate::raster::render_row(&mesh, texture, &settings, y).ok()?);
                self.lessons.row_render = Some((key, r.clone()));
                r
            }
        };
        Some((x, row_lines(&row, 0, plot)))
    }

    /// The plot window, when a plot is chosen outside a lesson (a lesson shows it in its
    /// panel); closing it clears the choice.
    pub(super) fn plot_window(
        &mut self,
        ctx: &egui::Context,
        texture: &Texture,
        out: &mut Vec<AppCommand>,
    ) {
        self.plot_hover_to_canvas();
        let Some(plot) = self.state.view.plot else {
            return;
        };
        if self.lessons.session.is_some() {
            return;
        }
        let lang = self.lang();
        let lines = self.row_plot(texture);
        let mut open = true;
        let size = ctx.content_rect().size();
        egui::Window::new(tr(lang, "lesson.plot_title"))
            .open(&mut open)
            .default_size([size.x * 0.4, size.y * 0.35])
            .default_pos([size.x * 0.55, size.y * 0.1])
            .show(ctx, |ui| {
                let mut column = None;
                out.extend(
                    plot_ui(ui, plot, lines, lang, &mut column)
                        .into_iter()
                        .map(Into::into),
                );
                self.lessons.plot_hover = column;
            });
        if !open {
            out.push(Command::SetPlot(None).into());
        }
        self.plot_hover_to_canvas();
    }

    /// The column hovered in the plot (this frame's, from the Lessons panel or the window)
    /// becomes the canvas's hovered pixel on the pinned row while the pointer is off the
    /// canvas, so the inspector and the overlay show it.
    fn plot_hover_to_canvas(&mut self) {
        let Some(x) = self.lessons.plot_hover.take() else {
            return;
        };
        let size = self.canvas.output.as_ref().map(|o| o.size);
        if let (None, Some([_, y]), Some([w, _])) =
            (self.canvas.hover, self.state.view.pinned, size)
            && x < w
        {
            self.canvas.hover = Some([x, y]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Along row 420 of the default floor (where w is the same along a row) and of the
    /// receding wall: 1/w and z/w are straight lines on the screen, w is not.
    #[test]
    fn inverse_w_is_straight_along_the_row_and_w_is_not() {
        let scene = crate::scene::Scene::default_scene();
        let texture = scene
            .load_texture(std::path::Path::new(""))
            .expect("texture");
        let r =
            crate::raster::render(&scene.to_mesh(), &texture, &scene.settings()).expect("render");
        let lines = row_lines(&r.frame, 420, LessonPlot::WRow);
        let (inv_w, w) = (&lines[0].1, &lines[1].1);
        assert!(inv_w.len() > 300, "{} covered pixels", inv_w.len());
        // The largest distance from the chord between the ends, on the 0..1 scale.
        let bend = |l: &Vec<[f64; 2]>| {
            let (a, b) = (l[0], l[l.len() - 1]);
            l.iter()
                .map(|p| {
                    let t = (p[0] - a[0]) / (b[0] - a[0]);
                    (p[1] - (a[1] + t * (b[1] - a[1]))).abs()
                })
                .fold(0.0, f64::max)
        };
        assert!(bend(inv_w) < 1e-3, "1/w bends by {}", bend(inv_w));
        let depth = row_lines(&r.frame, 420, LessonPlot::DepthRow);
        assert!(
            bend(&depth[0].1) < 1e-3,
            "z/w bends by {}",
            bend(&depth[0].1)
        );
        let _ = w;
        let wall = crate::lesson::builtin::scene("receding-wall").expect("built in");
        let scene = crate::scene::Scene::from_json(wall, "receding-wall").expect("scene");
        let r =
            crate::raster::render(&scene.to_mesh(), &texture, &scene.settings()).expect("render");
        let lines = row_lines(&r.frame, 420, LessonPlot::WRow);
        let w = &lines[1].1;
        assert!(
            bend(&lines[0].1) < 1e-3,
            "1/w bends by {}",
            bend(&lines[0].1)
        );
        assert!(bend(w) > 0.01, "w bends by only {}", bend(w));
    }
}
