//! The plot of a pinned pixel's row, as data: values read from the row rendered with every
//! per-pixel buffer (`raster::render_row`: the rasterizer's own numbers; nothing is
//! interpolated here). The app draws these lines with egui_plot, the handout as a
//! [`LinePlot`] image.
//!
//! - u and v along the row, affine beside perspective-correct (`uv_affine`, `uv_perspective`);
//! - 1/w (the `inv_w` buffer: a straight line on the screen) and w = 1/(1/w) (a curve);
//! - window depth z/w (the depth buffer: straight) and the view depth w (curved).
//!
//! The last two pairs have very different ranges, so each line is scaled to 0..1 over the row
//! (`(v - min)/(max - min)`): straight stays straight, and curved stays curved.

use super::LessonPlot;
use crate::figure::plot::LinePlot;
use crate::i18n::{Lang, tr};
use crate::raster::{Framebuffer, NO_TRIANGLE, Texture};
use crate::scene::Scene;

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
        // The level of detail is no per-pixel buffer: [`lambda_column`] computes it.
        LessonPlot::LambdaColumn => Vec::new(),
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
pub fn title_key(plot: LessonPlot) -> &'static str {
    match plot {
        LessonPlot::UvRow => "lesson.plot_uv",
        LessonPlot::WRow => "lesson.plot_w",
        LessonPlot::DepthRow => "lesson.plot_depth",
        LessonPlot::LambdaColumn => "lesson.plot_lambda",
    }
}

/// The catalogue key of a plot's x axis: the pixel column along a row, the pixel row down a
/// column ([`LessonPlot::LambdaColumn`]).
pub fn x_label_key(plot: LessonPlot) -> &'static str {
    match plot {
        LessonPlot::LambdaColumn => "lesson.plot_row",
        _ => X_LABEL_KEY,
    }
}

/// The lines of [`LessonPlot::LambdaColumn`] down column `x` of `scene` drawn with `settings`:
/// lambda and the mipmap level read ([`crate::figure::lod_view::lod_column`]).
pub fn lambda_column(
    scene: &Scene,
    texture: &Texture,
    settings: &crate::raster::RenderSettings,
    x: u32,
) -> Result<PlotLines, crate::figure::FigureError> {
    let [lambda, level] = crate::figure::lod_view::lod_column(scene, texture, settings, x)?;
    Ok(vec![
        ("lesson.plot_lambda_line", lambda),
        ("lesson.plot_level_line", level),
    ])
}

/// The catalogue key of the x axis's name (the pixel column).
pub const X_LABEL_KEY: &str = "lesson.plot_column";

/// `plot` along row `y` of `scene` (drawn with its own settings) with column `x` marked, as the
/// app's plot shows it, names in `lang`: the row rendered with every buffer
/// (`raster::render_row`), its [`row_lines`].
pub fn row_plot(
    scene: &Scene,
    texture: &Texture,
    [x, y]: [u32; 2],
    plot: LessonPlot,
    lang: Lang,
) -> Result<LinePlot, crate::figure::FigureError> {
    let (lines, marker) = if plot == LessonPlot::LambdaColumn {
        (lambda_column(scene, texture, &scene.settings(), x)?, y)
    } else {
        let row = crate::raster::render_row(&scene.to_mesh(), texture, &scene.settings(), y)?;
        (row_lines(&row, 0, plot), x)
    };
    Ok(LinePlot {
        title: tr(lang, title_key(plot)),
        x_label: tr(lang, x_label_key(plot)),
        lines: lines
            .into_iter()
            .map(|(key, points)| (tr(lang, key), points))
            .collect(),
        marker: Some(f64::from(marker)),
    })
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
