//! A line plot for printed notes, drawn without egui: the lesson handout's row plot (the same
//! lines the app's plot shows, `lesson::plot::row_lines`), as an SVG document and as a PNG
//! rasterized by resvg with the figures' fonts. The legend and the axes sit outside the
//! plotting area, so no line is hidden.

use super::svg::escape;
use resvg::tiny_skia::{self, Transform};
use resvg::usvg;

use super::FigureError;
use super::png::svg_options_in;
use crate::i18n::Lang;

/// Size of a plot in points (one PNG pixel per point at scale 1).
pub const PLOT_SIZE: [f32; 2] = [640.0, 360.0];

/// Margins of the plotting area inside [`PLOT_SIZE`]: left, top, right, bottom (points). The
/// bottom holds the x ticks, the axis label and the legend.
const MARGIN: [f32; 4] = [56.0, 34.0, 20.0, 84.0];

/// Colours of the lines, in order (distinct in print and for colour-blind readers).
const COLOURS: [&str; 4] = ["#0072b2", "#d55e00", "#009e73", "#cc79a7"];

/// What a plot shows: a title, the x axis's name, named lines of `(x, y)` points, and an
/// optional marked column (the pinned pixel's).
#[derive(Clone, Debug, PartialEq)]
pub struct LinePlot {
    /// Drawn above the plot.
    pub title: String,
    /// The x axis's name.
    pub x_label: String,
    /// The lines: a name for the legend and the points, in x order.
    pub lines: Vec<(String, Vec<[f64; 2]>)>,
    /// A column marked with a vertical dashed line and its value.
    pub marker: Option<f64>,
}

/// A "nice" tick step for a range: 1, 2 or 5 times a power of ten, about five ticks.
///
/// ```
/// use barylab::figure::plot::tick_step;
/// assert_eq!(tick_step(1.0), 0.2);
/// assert_eq!(tick_step(640.0), 100.0);
/// assert_eq!(tick_step(0.0), 1.0);
/// ```
pub fn tick_step(range: f64) -> f64 {
    if !(range.is_finite() && range > 0.0) {
        return 1.0;
    }
    let raw = range / 5.0;
    let p = 10f64.powf(raw.log10().floor());
    let m = raw / p;
    let nice = if m < 1.5 {
        1.0
    } else if m < 3.5 {
        2.0
    } else if m < 7.5 {
        5.0
    } else {
        10.0
    };
    nice * p
}

/// `[min, max]` of the finite values, or `[0, 1]` when there are none; a flat range is widened
/// by one on each side.
fn extent(values: impl Iterator<Item = f64>) -> [f64; 2] {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if lo > hi {
        [0.0, 1.0]
    } else if lo == hi {
        [lo - 1.0, hi + 1.0]
    } else {
        [lo, hi]
    }
}

/// A tick's label: no more decimals than the step needs.
fn tick_label(v: f64, step: f64) -> String {
    let decimals = (-step.log10().floor()).max(0.0) as usize;
    let s = format!("{v:.decimals$}");
    if s.starts_with('-') && s.trim_start_matches(['-', '0', '.']).is_empty() {
        s[1..].to_string()
    } else {
        s
    }
}

impl LinePlot {
    /// The plot as an SVG document of [`PLOT_SIZE`] points, text in `lang`'s fonts.
    pub fn to_svg(&self, lang: Lang) -> String {
        let [w, h] = PLOT_SIZE;
        let [ml, mt, mr, mb] = MARGIN;
        let (x0, y0, x1, y1) = (ml, mt, w - mr, h - mb);
        let points = || self.lines.iter().flat_map(|(_, p)| p.iter());
        let xr = extent(points().map(|p| p[0]).chain(self.marker));
        let yr = extent(points().map(|p| p[1]));
        let sx = |x: f64| x0 as f64 + (x - xr[0]) / (xr[1] - xr[0]) * f64::from(x1 - x0);
        let sy = |y: f64| y1 as f64 - (y - yr[0]) / (yr[1] - yr[0]) * f64::from(y1 - y0);
        let fonts = super::svg::font_families(lang);
        let mut s = format!(
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="{fonts}" font-size="13">"#
        );
        s.push_str(&format!(
            r##"<rect width="{w}" height="{h}" fill="#ffffff"/><text x="{}" y="22" font-size="15" text-anchor="middle">{}</text>"##,
            w / 2.0,
            escape(&self.title)
        ));
        // Grid and ticks.
        for (axis, r) in [(0, xr), (1, yr)] {
            let step = tick_step(r[1] - r[0]);
            let mut v = (r[0] / step).ceil() * step;
            while v <= r[1] + step * 1e-9 {
                let label = tick_label(v, step);
                if axis == 0 {
                    let x = sx(v);
                    s.push_str(&format!(
                        r##"<line x1="{x:.2}" y1="{y0}" x2="{x:.2}" y2="{y1}" stroke="#e0e0e0"/><text x="{x:.2}" y="{}" text-anchor="middle">{label}</text>"##,
                        y1 + 16.0
                    ));
                } else {
                    let y = sy(v);
                    s.push_str(&format!(
                        r##"<line x1="{x0}" y1="{y:.2}" x2="{x1}" y2="{y:.2}" stroke="#e0e0e0"/><text x="{}" y="{:.2}" text-anchor="end">{label}</text>"##,
                        x0 - 6.0,
                        y + 4.0
                    ));
                }
                v += step;
            }
        }
        s.push_str(&format!(
            r##"<rect x="{x0}" y="{y0}" width="{}" height="{}" fill="none" stroke="#404040"/><text x="{}" y="{}" text-anchor="middle">{}</text>"##,
            x1 - x0,
            y1 - y0,
            (x0 + x1) / 2.0,
            y1 + 34.0,
            escape(&self.x_label)
        ));
        if let Some(m) = self.marker {
            let x = sx(m);
            s.push_str(&format!(
                r##"<line x1="{x:.2}" y1="{y0}" x2="{x:.2}" y2="{y1}" stroke="#202020" stroke-dasharray="4 3"/><text x="{:.2}" y="{}" font-size="12">x = {}</text>"##,
                x + 4.0,
                y0 + 14.0,
                crate::probe::format::fmt_number(m)
            ));
        }
        for (k, (_, line)) in self.lines.iter().enumerate() {
            let pts: Vec<String> = line
                .iter()
                .filter(|p| p[1].is_finite())
                .map(|p| format!("{:.2},{:.2}", sx(p[0]), sy(p[1])))
                .collect();
            s.push_str(&format!(
                r#"<polyline points="{}" fill="none" stroke="{}" stroke-width="2"/>"#,
                pts.join(" "),
                COLOURS[k % COLOURS.len()]
            ));
        }
        // The legend, in a row under the axis label.
        let mut lx = x0;
        let ly = h - 18.0;
        for (k, (name, _)) in self.lines.iter().enumerate() {
            let (size, _) = super::text::measure(name, 13.0);
            s.push_str(&format!(
                r#"<line x1="{lx}" y1="{}" x2="{}" y2="{}" stroke="{}" stroke-width="3"/><text x="{}" y="{ly}">{}</text>"#,
                ly - 4.0,
                lx + 20.0,
                ly - 4.0,
                COLOURS[k % COLOURS.len()],
                lx + 26.0,
                escape(name)
            ));
            lx += 26.0 + size[0] + 24.0;
        }
        s.push_str("</svg>");
        s
    }

    /// The plot as PNG file bytes, `scale` pixels per point.
    pub fn to_png(&self, lang: Lang, scale: f32) -> Result<Vec<u8>, FigureError> {
        let svg = self.to_svg(lang);
        let tree = usvg::Tree::from_str(&svg, &svg_options_in(lang))
            .map_err(|e| FigureError::Draw(format!("plot SVG: {e}")))?;
        let [w, h] = PLOT_SIZE.map(|v| (v * scale).round() as u32);
        let mut pixmap = super::png::canvas(w, h, "plot canvas")?;
        pixmap.fill(tiny_skia::Color::WHITE);
        resvg::render(
            &tree,
            Transform::from_scale(scale, scale),
            &mut pixmap.as_mut(),
        );
        super::png::encode(&super::png::image_of(&pixmap)?)
    }
}
