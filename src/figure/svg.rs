//! A figure as an SVG document: each view's raster embedded as a PNG, its overlay as vector
//! shapes and real text (editable in Inkscape, scalable in a LaTeX/Beamer deck).
//!
//! Coordinates: the document's user units are figure points (`viewBox`), its `width` and
//! `height` the PNG pixels at the figure's scale. A canvas position `p` (rendered pixels) of a
//! view lies at `origin + pixel_size * p` points. Line widths, radii, text sizes and offsets
//! of the overlay are already in points.

use std::fmt::Write;

use base64::Engine;
use glam::DVec2;

use super::overlay::{Anchor, LABEL_BG, LABEL_TEXT, Overlay, Rgba, Shape, Stroke};
use super::text::{self, Box2, FONT_FAMILY, LABEL_PAD, LABEL_ROUNDING};
use super::{Background, Figure, FigureError, FigureView};

/// Dash and gap lengths of dashed lines, in points (as on screen).
pub const DASH: (f32, f32) = (6.0, 4.0);
/// Points (times the overlay scale): circles at least this large are handles, which labels
/// keep clear of.
pub const MIN_OBSTACLE_RADIUS: f32 = 8.0;
/// Points: corner radius of the colour bar's background.
const COLOR_BAR_ROUNDING: f32 = 6.0;
/// Points: the colour bar's background reaches this far left/above and right/below the bar
/// (room for its title above and its labels to the right).
const COLOR_BAR_BACK_MIN: [f32; 2] = [12.0, 40.0];
const COLOR_BAR_BACK_MAX: [f32; 2] = [56.0, 12.0];
/// Points: the colour bar's text size.
const COLOR_BAR_TEXT: f32 = 16.0;
/// Points: length of a tick of the colour bar, and the gap between the bar and its labels.
const COLOR_BAR_TICK: f32 = 5.0;
const COLOR_BAR_LABEL_GAP: f32 = 8.0;

/// Which parts of the figure the document holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layers {
    /// The background fill and the views' rasters.
    pub images: bool,
    /// The overlays.
    pub overlays: bool,
}

impl Layers {
    /// The whole figure.
    pub const ALL: Layers = Layers {
        images: true,
        overlays: true,
    };
    /// The overlays only (the PNG draws them over its own rasters).
    pub const OVERLAYS: Layers = Layers {
        images: false,
        overlays: true,
    };
}

/// The whole figure as an SVG document.
pub fn to_svg(figure: &Figure) -> Result<String, FigureError> {
    document(figure, Layers::ALL)
}

/// A `font-family` list for SVG text in `lang`: the overlay font, then (for Chinese) the CJK
/// families a viewer may have ([`crate::i18n::CJK_FAMILIES`]), then `sans-serif`. (The
/// figures themselves draw their labels as glyph outlines and need no font.)
pub fn font_families(lang: crate::i18n::Lang) -> String {
    let mut families = vec![FONT_FAMILY.to_string()];
    if lang != crate::i18n::Lang::En {
        if let Some(found) = crate::i18n::cjk_font() {
            families.push(format!("'{}'", found.family));
        }
        for f in crate::i18n::CJK_FAMILIES {
            let quoted = format!("'{f}'");
            if !families.contains(&quoted) {
                families.push(quoted);
            }
        }
    }
    families.push("sans-serif".to_string());
    families.join(", ")
}

/// The figure's SVG document with the chosen layers.
pub fn document(figure: &Figure, layers: Layers) -> Result<String, FigureError> {
    let [w, h] = figure.size;
    let [pw, ph] = figure.pixel_dimensions();
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" width="{pw}" height="{ph}" viewBox="0 0 {w} {h}">"#
    );
    let _ = writeln!(
        s,
        "<desc>barylab figure: {}x{} rendered pixels, {} point(s) per pixel, scale {}</desc>",
        figure.canvas_size[0], figure.canvas_size[1], figure.pixel_size, figure.scale
    );
    s.push_str("<defs>\n");
    for (i, v) in figure.views.iter().enumerate() {
        let [x0, y0, x1, y1] = v.clip;
        let _ = writeln!(
            s,
            r#"<clipPath id="view{i}"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath>"#,
            n(x0),
            n(y0),
            n(x1 - x0),
            n(y1 - y0)
        );
        let [iw, ih] = figure.canvas_size.map(|v| v * figure.pixel_size);
        let _ = writeln!(
            s,
            r#"<clipPath id="image{i}"><rect x="{}" y="{}" width="{iw}" height="{ih}"/></clipPath>"#,
            v.origin[0], v.origin[1]
        );
    }
    let mut head = std::mem::take(&mut s);
    let mut glyphs = Glyphs::default();
    if layers.images && figure.background == Background::White {
        let _ = writeln!(s, r##"<rect width="{w}" height="{h}" fill="#ffffff"/>"##);
    }
    for (i, v) in figure.views.iter().enumerate() {
        if layers.images {
            image_element(&mut s, figure, v)?;
        }
        if layers.overlays {
            let _ = writeln!(s, r#"<g clip-path="url(#view{i})">"#);
            let t = Transform {
                origin: [f64::from(v.origin[0]), f64::from(v.origin[1])],
                scale: f64::from(figure.pixel_size),
            };
            overlay(
                &mut s,
                &mut glyphs,
                &super::bounds::bounded(&v.overlay, figure.canvas_size),
                t,
                v.clip,
                &format!("image{i}"),
                figure.overlay_scale,
            );
            s.push_str("</g>\n");
        }
    }
    if layers.overlays
        && let Some(c) = &figure.caption
    {
        for (i, line) in c.lines.iter().enumerate() {
            label(
                &mut s,
                &mut glyphs,
                c.line_box(i),
                Label::new(line, c.size, super::caption::CAPTION_INK, None),
                figure.overlay_scale,
            );
        }
    }
    s.push_str("</svg>\n");
    glyphs.defs(&mut head);
    head.push_str("</defs>\n");
    head.push_str(&s);
    Ok(head)
}

fn image_element(s: &mut String, figure: &Figure, v: &FigureView) -> Result<(), FigureError> {
    let mut png = Vec::new();
    v.raster
        .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .map_err(|e| FigureError::Draw(e.to_string()))?;
    let data = base64::engine::general_purpose::STANDARD.encode(&png);
    let (iw, ih) = (
        v.raster.width() / figure.scale,
        v.raster.height() / figure.scale,
    );
    let _ = writeln!(
        s,
        r#"<image x="{}" y="{}" width="{iw}" height="{ih}" preserveAspectRatio="none" image-rendering="optimizeSpeed" style="image-rendering:pixelated" xlink:href="data:image/png;base64,{data}"/>"#,
        v.origin[0], v.origin[1]
    );
    Ok(())
}

/// Canvas coordinates (rendered pixels) to figure points.
#[derive(Clone, Copy, Debug)]
struct Transform {
    origin: [f64; 2],
    scale: f64,
}

impl Transform {
    fn point(&self, p: DVec2) -> [f32; 2] {
        [
            (self.origin[0] + p.x * self.scale) as f32,
            (self.origin[1] + p.y * self.scale) as f32,
        ]
    }
}

/// A number for SVG: at most three decimals, no trailing zeros.
fn n(v: f32) -> String {
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}

fn hex(c: Rgba) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

/// `fill="..."` with its opacity, or `fill="none"`.
fn fill(c: Rgba) -> String {
    if c[3] == 0 {
        r#"fill="none""#.into()
    } else if c[3] == 255 {
        format!(r#"fill="{}""#, hex(c))
    } else {
        format!(
            r#"fill="{}" fill-opacity="{}""#,
            hex(c),
            n(f32::from(c[3]) / 255.0)
        )
    }
}

/// Stroke attributes; dashes are [`DASH`] overlay points long, times `k`.
fn stroke(st: Option<Stroke>, dashed: bool, k: f32) -> String {
    let Some(st) = st else {
        return String::new();
    };
    let mut out = format!(
        r#" stroke="{}" stroke-width="{}" stroke-linejoin="round""#,
        hex(st.color),
        n(st.width)
    );
    if st.color[3] != 255 {
        let _ = write!(
            out,
            r#" stroke-opacity="{}""#,
            n(f32::from(st.color[3]) / 255.0)
        );
    }
    if dashed {
        let _ = write!(
            out,
            r#" stroke-dasharray="{} {}""#,
            n(DASH.0 * k),
            n(DASH.1 * k)
        );
    }
    out
}

fn points(pts: &[[f32; 2]]) -> String {
    pts.iter()
        .map(|p| format!("{},{}", n(p[0]), n(p[1])))
        .collect::<Vec<_>>()
        .join(" ")
}

fn escape(t: &str) -> String {
    let mut out = String::with_capacity(t.len());
    for c in t.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            c => out.push(c),
        }
    }
    out
}

fn rect(s: &mut String, b: Box2, rounding: f32, attrs: &str) {
    let _ = writeln!(
        s,
        r#"<rect x="{}" y="{}" width="{}" height="{}"{} {attrs}/>"#,
        n(b[0]),
        n(b[1]),
        n(b[2] - b[0]),
        n(b[3] - b[1]),
        if rounding > 0.0 {
            format!(r#" rx="{}""#, n(rounding))
        } else {
            String::new()
        }
    );
}

/// What a label shows: its text at a size in a colour, on a box of a colour or none.
#[derive(Clone, Copy)]
struct Label<'a> {
    text: &'a str,
    size: f32,
    color: Rgba,
    background: Option<Rgba>,
}

impl<'a> Label<'a> {
    fn new(text: &'a str, size: f32, color: Rgba, background: Option<Rgba>) -> Self {
        Self {
            text,
            size,
            color,
            background,
        }
    }
}

/// A label: its background box (if any) and its text, in the box `b`. The text is drawn as
/// the overlay font's glyph outlines ([`text::glyph_outline`]), so it looks the same, and fits the
/// box measured with the same font ([`text::measure`]), in every viewer (browsers, Inkscape,
/// librsvg, resvg) whatever fonts it has. The group carries the text as its `aria-label`
/// and `<title>` (for search and screen readers), its size as `font-size` and its box as
/// `data-box` (x y width height).
fn label(s: &mut String, glyphs: &mut Glyphs, b: Box2, l: Label<'_>, k: f32) {
    let Label {
        text,
        size,
        color,
        background,
    } = l;
    let pad = if background.is_some() {
        LABEL_PAD.map(|v| v * k)
    } else {
        [0.0, 0.0]
    };
    let t = escape(text);
    let _ = writeln!(
        s,
        r#"<g class="label" aria-label="{t}" font-size="{}" data-box="{} {} {} {}"><title>{t}</title>"#,
        fine(size),
        n(b[0]),
        n(b[1]),
        n(b[2] - b[0]),
        n(b[3] - b[1]),
    );
    if let Some(bg) = background {
        rect(s, b, LABEL_ROUNDING * k, &fill(bg));
    }
    let (_, ascent) = text::measure(text, size);
    let origin = [b[0] + pad[0], b[1] + pad[1] + ascent];
    let placed = text::glyphs(text, size);
    if !placed.is_empty() {
        let _ = writeln!(s, "<g {}>", fill(color));
        for g in placed {
            if let Some(id) = glyphs.id(g.font, g.id) {
                let _ = writeln!(
                    s,
                    r##"<use xlink:href="#{id}" transform="matrix({} 0 0 -{} {} {})"/>"##,
                    fine(g.per_unit),
                    fine(g.per_unit),
                    n(origin[0] + g.x),
                    n(origin[1])
                );
            }
        }
        s.push_str("</g>\n");
    }
    s.push_str("</g>\n");
}

/// The glyph outlines a document uses, each defined once (in font units, y up) and drawn
/// with `<use>` wherever a label has it.
#[derive(Default)]
struct Glyphs {
    /// Glyph and its outline's path data (`None`: no outline, nothing to draw).
    used: std::collections::BTreeMap<(text::GlyphFont, u16), Option<String>>,
}

impl Glyphs {
    /// The element id of a glyph's outline, or `None` for a glyph without one (a space).
    fn id(&mut self, font: text::GlyphFont, glyph: u16) -> Option<String> {
        let d = self.used.entry((font, glyph)).or_insert_with(|| {
            Some(glyph_path(&text::glyph_outline(font, glyph))).filter(|d| !d.is_empty())
        });
        d.as_ref().map(|_| glyph_id(font, glyph))
    }

    /// The `<path>` definitions of the glyphs used, for the document's `<defs>`.
    fn defs(&self, s: &mut String) {
        for ((font, glyph), d) in &self.used {
            if let Some(d) = d {
                let _ = writeln!(s, r#"<path id="{}" d="{d}"/>"#, glyph_id(*font, *glyph));
            }
        }
    }
}

/// The element id of a glyph's outline: `g0-N` for glyph N of the overlay font, `g1-N` of
/// the CJK font.
fn glyph_id(font: text::GlyphFont, glyph: u16) -> String {
    let f = match font {
        text::GlyphFont::Overlay => 0,
        text::GlyphFont::Cjk => 1,
    };
    format!("g{f}-{glyph}")
}

/// A scale factor for SVG: six decimals, no trailing zeros (a glyph's points per font unit
/// is about 0.02; three decimals would lose a few percent of its size).
fn fine(v: f32) -> String {
    let s = format!("{v:.6}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// SVG path data of a glyph outline: a new subpath wherever a curve does not start where the
/// previous one ended.
fn glyph_path(curves: &[text::Curve]) -> String {
    let p = |q: [f32; 2]| format!("{} {}", n(q[0]), n(q[1]));
    let mut d = String::new();
    let mut at: Option<[f32; 2]> = None;
    for c in curves {
        if at != Some(c.start()) {
            if at.is_some() {
                d.push('Z');
            }
            let _ = write!(d, "M{}", p(c.start()));
        }
        let _ = match c {
            text::Curve::Line([_, b]) => write!(d, "L{}", p(*b)),
            text::Curve::Quad([_, b, c]) => write!(d, "Q{} {}", p(*b), p(*c)),
            text::Curve::Cubic([_, b, c, e]) => write!(d, "C{} {} {}", p(*b), p(*c), p(*e)),
        };
        at = Some(c.end());
    }
    if at.is_some() {
        d.push('Z');
    }
    d
}

/// The overlay's shapes as SVG elements.
/// The overlay's shapes (sizes already scaled) as SVG elements; `k` scales the fixed sizes
/// of the drawing itself (label padding, dashes, the colour bar's frame and text).
fn overlay(
    s: &mut String,
    glyphs: &mut Glyphs,
    overlay: &Overlay,
    t: Transform,
    clip: Box2,
    image_clip: &str,
    k: f32,
) {
    // Lines and areas stay on the image (a clipped triangle's outline can reach far off it);
    // handles and labels may use the margin around it. Consecutive shapes on the image share
    // one clipped group, so the painting order is kept.
    let mut in_image_group = false;
    // The label boxes placed so far: a label goes where it covers none of them if it can.
    // The handles are there from the start.
    let mut placed: Vec<Box2> = overlay
        .shapes
        .iter()
        .filter_map(|shape| match shape {
            Shape::Circle { centre, radius, .. } if *radius >= MIN_OBSTACLE_RADIUS * k => {
                Some(text::handle_obstacle(t.point(*centre), *radius))
            }
            Shape::ColorBar {
                at, offset, size, ..
            } => {
                let p = t.point(*at);
                let min = [p[0] + offset[0], p[1] + offset[1]];
                Some(color_bar_back(
                    [min[0], min[1], min[0] + size[0], min[1] + size[1]],
                    k,
                ))
            }
            _ => None,
        })
        .collect();
    for shape in &overlay.shapes {
        let on_image = matches!(
            shape,
            Shape::Polygon { .. }
                | Shape::Line { .. }
                | Shape::Rect { .. }
                | Shape::PixelGrid { .. }
        );
        if on_image != in_image_group {
            if on_image {
                let _ = writeln!(s, r#"<g clip-path="url(#{image_clip})">"#);
            } else {
                s.push_str("</g>\n");
            }
            in_image_group = on_image;
        }
        match shape {
            Shape::Polygon {
                points: pts,
                fill: f,
                stroke: st,
                dashed,
            } => {
                let p: Vec<[f32; 2]> = pts.iter().map(|p| t.point(*p)).collect();
                let _ = writeln!(
                    s,
                    r#"<polygon points="{}" {}{}/>"#,
                    points(&p),
                    fill(*f),
                    stroke(*st, *dashed, k)
                );
            }
            Shape::Line {
                points: pts,
                stroke: st,
                dashed,
            } => {
                let p: Vec<[f32; 2]> = pts.iter().map(|p| t.point(*p)).collect();
                let _ = writeln!(
                    s,
                    r#"<polyline points="{}" fill="none"{}/>"#,
                    points(&p),
                    stroke(Some(*st), *dashed, k)
                );
            }
            Shape::Rect {
                min,
                max,
                fill: f,
                stroke: st,
            } => {
                let (a, b) = (t.point(*min), t.point(*max));
                if f[3] > 0 {
                    rect(s, [a[0], a[1], b[0], b[1]], 0.0, &fill(*f));
                }
                if let Some(st) = st {
                    // The stroke lies outside the rectangle, as on screen.
                    let e = st.width / 2.0;
                    rect(
                        s,
                        [a[0] - e, a[1] - e, b[0] + e, b[1] + e],
                        0.0,
                        &format!(r#"fill="none"{}"#, stroke(Some(*st), false, k)),
                    );
                }
            }
            Shape::Circle {
                centre,
                radius,
                fill: f,
                stroke: st,
            } => {
                let c = t.point(*centre);
                let _ = writeln!(
                    s,
                    r#"<circle cx="{}" cy="{}" r="{}" {}{}/>"#,
                    n(c[0]),
                    n(c[1]),
                    n(*radius),
                    fill(*f),
                    stroke(*st, false, k)
                );
            }
            Shape::Text {
                at,
                offset,
                anchor,
                text: txt,
                size,
                color,
                background,
            } => {
                // A label wider than its view shrinks to fit it.
                let pad = if background.is_some() {
                    LABEL_PAD[0] * k
                } else {
                    0.0
                };
                let width = text::measure(txt, *size).0[0];
                let size = &(size * text::fit(width, 2.0 * pad, clip));
                let (text_size, _) = text::measure(txt, *size);
                let outer = text::padded(text_size, background.is_some(), k);
                // A label with a box keeps clear of the others; a bare letter (a handle's
                // name) stays where it is.
                let b = if background.is_some() {
                    text::place_label_avoiding(t.point(*at), *offset, *anchor, outer, clip, &placed)
                } else {
                    text::place_label(t.point(*at), *offset, *anchor, outer, clip)
                };
                if background.is_some() {
                    placed.push(b);
                }
                label(s, glyphs, b, Label::new(txt, *size, *color, *background), k);
            }
            Shape::LabelPair {
                at,
                offset_y,
                gap,
                texts,
                size,
                color,
                background,
            } => {
                let p = t.point(*at);
                let has_box = background.is_some();
                let widths = texts.each_ref().map(|x| text::measure(x, *size).0[0]);
                let pad = if has_box { LABEL_PAD[0] * k } else { 0.0 };
                let size = size * text::pair_fit(widths, pad, *gap, clip);
                let outer = texts
                    .each_ref()
                    .map(|x| text::padded(text::measure(x, size).0, has_box, k));
                let (boxes, _) = text::place_pair([p[0], p[1] + offset_y], *gap, outer, clip);
                for (b, txt) in boxes.iter().zip(texts) {
                    label(s, glyphs, *b, Label::new(txt, size, *color, *background), k);
                }
                placed.extend(boxes);
            }
            Shape::PixelGrid {
                width,
                height,
                line,
                dots,
            } => grid(s, t, clip, [*width, *height], *line, *dots),
            Shape::ColorBar {
                at,
                offset,
                size,
                colors,
                labels,
                title,
            } => {
                let p = t.point(*at);
                let min = [p[0] + offset[0], p[1] + offset[1]];
                color_bar(
                    s,
                    glyphs,
                    [min[0], min[1], min[0] + size[0], min[1] + size[1]],
                    colors,
                    labels,
                    title,
                    k,
                );
            }
        }
    }
    if in_image_group {
        s.push_str("</g>\n");
    }
}

fn grid(
    s: &mut String,
    t: Transform,
    clip: Box2,
    [width, height]: [u32; 2],
    line: Stroke,
    dots: Option<(f32, Rgba)>,
) {
    let (w, h) = (f64::from(width), f64::from(height));
    let mut d = String::new();
    for x in 0..=width {
        let a = t.point(DVec2::new(f64::from(x), 0.0));
        let b = t.point(DVec2::new(f64::from(x), h));
        let _ = write!(d, "M{} {}V{}", n(a[0]), n(a[1]), n(b[1]));
    }
    for y in 0..=height {
        let a = t.point(DVec2::new(0.0, f64::from(y)));
        let b = t.point(DVec2::new(w, f64::from(y)));
        let _ = write!(d, "M{} {}H{}", n(a[0]), n(a[1]), n(b[0]));
    }
    let _ = writeln!(
        s,
        r#"<path d="{d}" fill="none"{}/>"#,
        stroke(Some(line), false, 1.0).replace(r#" stroke-linejoin="round""#, "")
    );
    if let Some((r, c)) = dots {
        let mut d = String::new();
        for y in 0..height {
            for x in 0..width {
                let p = t.point(DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5));
                if p[0] >= clip[0] && p[0] <= clip[2] && p[1] >= clip[1] && p[1] <= clip[3] {
                    let _ = write!(
                        d,
                        "M{} {}h{}v{}h-{}z",
                        n(p[0] - r),
                        n(p[1] - r),
                        n(2.0 * r),
                        n(2.0 * r),
                        n(2.0 * r)
                    );
                }
            }
        }
        let _ = writeln!(s, r#"<path d="{d}" {}/>"#, fill(c));
    }
}

/// The colour bar's background box for the bar `r` (its title above, its labels right).
pub fn color_bar_back(r: Box2, k: f32) -> Box2 {
    [
        r[0] - COLOR_BAR_BACK_MIN[0] * k,
        r[1] - COLOR_BAR_BACK_MIN[1] * k,
        r[2] + COLOR_BAR_BACK_MAX[0] * k,
        r[3] + COLOR_BAR_BACK_MAX[1] * k,
    ]
}

/// The colour bar as the screen draws it: a rounded background, the gradient from the first
/// colour at the bottom to the last at the top, a white frame, ticks with labels, a title.
fn color_bar(
    s: &mut String,
    glyphs: &mut Glyphs,
    r: Box2,
    colors: &[Rgba],
    labels: &[(f32, String)],
    title: &str,
    k: f32,
) {
    let back = color_bar_back(r, k);
    rect(s, back, COLOR_BAR_ROUNDING * k, &fill(LABEL_BG));
    // One gradient through all the colours, evenly spaced from bottom to top (the screen
    // draws the same as one band per pair of neighbouring colours).
    let last = colors.len().saturating_sub(1).max(1);
    let height = r[3] - r[1];
    let id = format!("bar-{}-{}", r[0].round(), r[1].round());
    let _ = write!(
        s,
        r#"<linearGradient id="{id}" x1="0" y1="1" x2="0" y2="0">"#
    );
    for (i, c) in colors.iter().enumerate() {
        let _ = write!(
            s,
            r#"<stop offset="{}" stop-color="{}"/>"#,
            n(i as f32 / last as f32),
            hex(*c)
        );
    }
    s.push_str("</linearGradient>\n");
    rect(s, r, 0.0, &format!(r#"fill="url(#{id})""#));
    // A white frame of one point, outside the bar.
    let e = k / 2.0;
    rect(
        s,
        [r[0] - e, r[1] - e, r[2] + e, r[3] + e],
        0.0,
        &format!(r##"fill="none" stroke="#ffffff" stroke-width="{}""##, n(k)),
    );
    let size = COLOR_BAR_TEXT * k;
    for (f, l) in labels {
        let y = r[3] - height * f;
        let _ = writeln!(
            s,
            r#"<line x1="{}" y1="{}" x2="{}" y2="{}"{}/>"#,
            n(r[2]),
            n(y),
            n(r[2] + COLOR_BAR_TICK * k),
            n(y),
            stroke(Some(Stroke::new(k, LABEL_TEXT)), false, k)
        );
        let (extent, _) = text::measure(l, size);
        let b = Anchor::LeftCenter.box_at([r[2] + COLOR_BAR_LABEL_GAP * k, y], extent);
        label(s, glyphs, b, Label::new(l, size, LABEL_TEXT, None), k);
    }
    let (extent, _) = text::measure(title, size);
    let b = Anchor::CenterBottom.box_at(
        [(r[0] + r[2]) / 2.0, r[1] - COLOR_BAR_LABEL_GAP * k],
        extent,
    );
    label(s, glyphs, b, Label::new(title, size, LABEL_TEXT, None), k);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_and_text_is_escaped() {
        assert_eq!(n(1.5), "1.5");
        assert_eq!(n(2.0), "2");
        assert_eq!(n(-0.0001), "0");
        assert_eq!(n(0.12345), "0.123");
        assert_eq!(escape("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
        assert_eq!(fill([255, 0, 16, 255]), r##"fill="#ff0010""##);
        assert_eq!(fill([0, 0, 0, 0]), r#"fill="none""#);
    }
}
