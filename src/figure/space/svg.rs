//! The space view as a figure: the 3D drawing on the left, the pixel's numbers on the right,
//! as an SVG document (real text in the figures' fonts) and as a PNG rasterized from it by
//! resvg, as the line plots are.

use std::fmt::Write as _;

use resvg::tiny_skia::{self, Transform};
use resvg::usvg;

use super::draw::{self, Anchor2, Colour, Shape, ShapeKind};
use super::{Orbit, SpaceScene};
use crate::figure::FigureError;
use crate::figure::png::svg_options_in;
use crate::figure::svg::escape;
use crate::i18n::Lang;
use crate::probe::format::fmt_number;

/// The figure's size in points (one PNG pixel per point at scale 1).
pub const FIGURE_SIZE: [f32; 2] = [1200.0, 720.0];

/// Width of the numbers' column on the right, points.
const PANEL_WIDTH: f32 = 380.0;

/// The labels' font size in the figure, points.
pub(super) const LABEL_SIZE: f32 = 16.0;

/// The space view as a figure.
#[derive(Clone, Debug)]
pub struct SpaceFigure<'a> {
    /// The scene in 3D.
    pub space: &'a SpaceScene,
    /// The orbit camera.
    pub orbit: Orbit,
    /// The labels' language.
    pub lang: Lang,
}

/// `fill="rgb(...)" fill-opacity="..."` (or stroke) of a colour.
fn paint(what: &str, c: Colour) -> String {
    let [r, g, b, a] = c.0;
    format!(
        "{what}=\"rgb({r},{g},{b})\" {what}-opacity=\"{:.3}\"",
        f32::from(a) / 255.0
    )
}

/// `text` broken into lines no wider than `width` at `size` points: at spaces, and between
/// any two CJK characters.
pub fn wrap_line(text: &str, size: f32, width: f32) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    let mut word = String::new();
    let flush_word = |line: &mut String, word: &mut String, lines: &mut Vec<String>| {
        let joined = format!("{line}{word}");
        if !line.trim().is_empty() && draw::text_width(joined.trim_end(), size) > width {
            lines.push(line.trim_end().to_string());
            *line = word.trim_start().to_string();
        } else {
            *line = joined;
        }
        word.clear();
    };
    for c in text.chars() {
        if c == ' ' || c >= '\u{2E80}' {
            if c >= '\u{2E80}' {
                word.push(c);
                flush_word(&mut line, &mut word, &mut lines);
            } else {
                flush_word(&mut line, &mut word, &mut lines);
                word.push(c);
            }
        } else {
            word.push(c);
        }
    }
    flush_word(&mut line, &mut word, &mut lines);
    if !line.trim().is_empty() {
        lines.push(line.trim_end().to_string());
    }
    lines
}

/// The numbers beside the drawing, each a line and its colour: the weights of P (the
/// probe's `a b c`) and of Q (`r s t`), `W_P`, the window depth, the gap and the notes.
pub fn panel_lines(space: &SpaceScene, lang: Lang) -> Vec<(String, Colour)> {
    use draw::INK;
    let tr = |k: &str| lang.tr(&format!("space.{k}"));
    let n = |v: f64| fmt_number(v);
    let mut out = Vec::new();
    if matches!(space.lens, super::Lens::ClipW { .. }) {
        out.push((tr("clip_scene"), INK));
        if space.near.is_none() {
            out.push((tr("no_planes"), INK));
        }
    }
    match space.ray.as_ref().map(|r| r.seen.as_ref()) {
        None => out.push((tr("no_pixel"), INK)),
        Some(None) => out.push((tr("no_seen"), INK)),
        Some(Some(s)) => {
            out.push((tr("ray"), draw::RAY_COLOUR));
            let names = s.names.join(" ");
            out.push((
                lang.tr_with("space.weights_heading", &[("names", &names)]),
                INK,
            ));
            let [a, b, c] = s.abc.map(n);
            out.push((
                lang.tr_with("space.abc", &[("a", &a), ("b", &b), ("c", &c)]),
                draw::P_COLOUR,
            ));
            let [r, s_, t] = s.rst.map(n);
            out.push((
                lang.tr_with("space.rst", &[("r", &r), ("s", &s_), ("t", &t)]),
                draw::Q_COLOUR,
            ));
            let key = if space.lens.perspective() {
                "space.w_p"
            } else {
                "space.w_p_ortho"
            };
            out.push((lang.tr_with(key, &[("w", &n(s.w_p))]), draw::P_COLOUR));
            out.push((lang.tr_with("space.depth", &[("d", &n(s.depth))]), INK));
            out.push((
                lang.tr_with("space.gap", &[("d", &n((s.p - s.q).length()))]),
                draw::Q_COLOUR,
            ));
            if !s.covered {
                out.push((tr("not_covered"), INK));
            }
            if let Some(cut) = &s.cut {
                let names: Vec<&str> = cut.polygon.iter().map(|(n, _)| n.as_str()).collect();
                out.push((
                    lang.tr_with("space.cut", &[("names", &names.join(" "))]),
                    INK,
                ));
            }
        }
    }
    let [w, h] = space.image_size;
    let grid = lang.tr_with(
        "space.grid",
        &[
            ("w", &w.to_string()),
            ("h", &h.to_string()),
            ("step", &space.grid_step.to_string()),
        ],
    );
    out.push((format!("{}: {grid}", tr("image_plane")), INK));
    if let (Some(f), false) = (space.far, space.far_is_shown()) {
        out.push((lang.tr_with("space.far_beyond", &[("d", &n(f))]), INK));
    }
    out.push((tr("p"), draw::P_COLOUR));
    out.push((tr("q"), draw::Q_COLOUR));
    out.push((tr("axis"), INK));
    out
}

/// SVG markup of one shape.
pub(super) fn shape_svg(s: &Shape, out: &mut String) {
    let pts = |p: &[[f32; 2]]| {
        p.iter()
            .map(|q| format!("{:.2},{:.2}", q[0], q[1]))
            .collect::<Vec<_>>()
            .join(" ")
    };
    let stroke = |st: &Option<(Colour, f32)>| match st {
        Some((c, w)) => format!(" {} stroke-width=\"{w:.2}\"", paint("stroke", *c)),
        None => String::new(),
    };
    let _ = match &s.kind {
        ShapeKind::Polygon {
            points,
            fill,
            stroke: st,
        } => writeln!(
            out,
            "<polygon points=\"{}\" {}{} stroke-linejoin=\"round\"/>",
            pts(points),
            paint("fill", *fill),
            stroke(st)
        ),
        ShapeKind::Line {
            from,
            to,
            colour,
            width,
            dashed,
        } => writeln!(
            out,
            "<line x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" {} stroke-width=\"{width:.2}\"{} stroke-linecap=\"round\"/>",
            from[0],
            from[1],
            to[0],
            to[1],
            paint("stroke", *colour),
            if *dashed {
                format!(
                    " stroke-dasharray=\"{:.1} {:.1}\"",
                    3.0 * width,
                    3.0 * width
                )
            } else {
                String::new()
            }
        ),
        ShapeKind::Dot {
            centre,
            radius,
            fill,
            stroke: st,
        } => writeln!(
            out,
            "<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"{radius:.2}\" {}{}/>",
            centre[0],
            centre[1],
            paint("fill", *fill),
            stroke(st)
        ),
        ShapeKind::Text {
            at,
            text,
            size,
            colour,
            anchor,
        } => writeln!(
            out,
            "<text x=\"{:.2}\" y=\"{:.2}\" font-size=\"{size:.1}\" text-anchor=\"{}\" {} stroke=\"white\" stroke-width=\"{:.1}\" stroke-opacity=\"0.85\" paint-order=\"stroke\" stroke-linejoin=\"round\">{}</text>",
            at[0],
            at[1],
            match anchor {
                Anchor2::Start => "start",
                Anchor2::Middle => "middle",
                Anchor2::End => "end",
            },
            paint("fill", *colour),
            size / 4.0,
            escape(text)
        ),
    };
}

/// The drawing area of a 3D figure, `[min_x, min_y, max_x, max_y]`: left of the numbers.
pub fn drawing_rect() -> [f32; 4] {
    let [w, h] = FIGURE_SIZE;
    [0.0, 48.0, w - PANEL_WIDTH, h]
}

/// A 3D figure's SVG document of [`FIGURE_SIZE`] points on white: the title, the drawing's
/// shapes, and the numbers' column on the right (its lines wrapped to fit).
pub(super) fn document(
    title: &str,
    shapes: &[Shape],
    panel: &[(String, Colour)],
    lang: Lang,
) -> String {
    let [w, h] = FIGURE_SIZE;
    let fonts = crate::figure::svg::font_families(lang);
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" font-family=\"{fonts}\" font-size=\"{LABEL_SIZE}\">\n<rect width=\"{w}\" height=\"{h}\" fill=\"#ffffff\"/>\n"
    );
    let _ = writeln!(
        s,
        "<text x=\"20\" y=\"32\" font-size=\"22\">{}</text>",
        escape(title)
    );
    let [x0, y0, x1, y1] = drawing_rect();
    let _ = writeln!(
        s,
        "<clipPath id=\"drawing\"><rect x=\"{x0}\" y=\"{y0}\" width=\"{}\" height=\"{}\"/></clipPath>\n<g clip-path=\"url(#drawing)\">",
        x1 - x0,
        y1 - y0
    );
    for shape in shapes {
        shape_svg(shape, &mut s);
    }
    s.push_str("</g>\n");
    let x = w - PANEL_WIDTH + 10.0;
    let _ = writeln!(
        s,
        "<rect x=\"{}\" y=\"48\" width=\"{}\" height=\"{}\" fill=\"#f6f6f6\" stroke=\"#d0d0d0\"/>",
        x - 10.0,
        PANEL_WIDTH - 10.0,
        h - 58.0
    );
    let mut y = 76.0;
    let size = LABEL_SIZE;
    for (line, colour) in panel {
        for part in wrap_line(line, size, PANEL_WIDTH - 36.0) {
            let _ = writeln!(
                s,
                "<text x=\"{x:.1}\" y=\"{y:.1}\" font-size=\"{size}\" {}>{}</text>",
                paint("fill", *colour),
                escape(&part)
            );
            y += size * 1.3;
        }
        y += size * 0.5;
    }
    s.push_str("</svg>\n");
    s
}

/// An SVG document of [`FIGURE_SIZE`] points rasterized on white, `scale` pixels per point,
/// with the figures' fonts for `lang`.
pub(super) fn rasterize_svg(
    svg: &str,
    lang: Lang,
    scale: f32,
) -> Result<image::RgbaImage, FigureError> {
    let tree = usvg::Tree::from_str(svg, &svg_options_in(lang))
        .map_err(|e| FigureError::Draw(format!("space view SVG: {e}")))?;
    let [w, h] = FIGURE_SIZE.map(|v| (v * scale).round() as u32);
    let mut pixmap = crate::figure::png::canvas(w, h, "space view canvas")?;
    pixmap.fill(tiny_skia::Color::WHITE);
    resvg::render(
        &tree,
        Transform::from_scale(scale, scale),
        &mut pixmap.as_mut(),
    );
    crate::figure::png::image_of(&pixmap)
}

impl SpaceFigure<'_> {
    /// The shapes of the 3D drawing, as the figure places them.
    pub fn shapes(&self) -> Vec<Shape> {
        let projector = self.space.projector(self.orbit, drawing_rect());
        draw::shapes(
            self.space,
            &projector,
            self.lang,
            LABEL_SIZE,
            &draw::svg_measure,
        )
    }

    /// The figure as an SVG document of [`FIGURE_SIZE`] points, on white.
    pub fn to_svg(&self) -> String {
        let title = if self.space.ray.is_some() {
            "space.title"
        } else {
            "space.title_no_pixel"
        };
        document(
            &self.lang.tr(title),
            &self.shapes(),
            &panel_lines(self.space, self.lang),
            self.lang,
        )
    }

    /// The figure as an RGBA image, `scale` pixels per point.
    pub fn rasterize(&self, scale: f32) -> Result<image::RgbaImage, FigureError> {
        rasterize_svg(&self.to_svg(), self.lang, scale)
    }

    /// The figure as PNG file bytes, `scale` pixels per point.
    pub fn to_png(&self, scale: f32) -> Result<Vec<u8>, FigureError> {
        crate::figure::png::encode(&self.rasterize(scale)?)
    }
}
