//! A figure as an SVG document: each view's raster embedded as a PNG, its overlay as vector
//! shapes, its labels as the overlay font's glyph outlines (the same in every viewer,
//! scalable in a LaTeX/Beamer deck).
//!
//! - `markup.rs`: numbers, colours, strokes, escaping, the canvas-to-points transform.
//! - `labels.rs`: a label's box and glyphs, each glyph defined once per document.
//! - `shapes.rs`: the overlay's shapes, the label placement, the grid and the colour bar.
//!
//! Coordinates: the document's user units are figure points (`viewBox`), its `width` and
//! `height` the PNG pixels at the figure's scale. A canvas position `p` (rendered pixels) of a
//! view lies at `origin + pixel_size * p` points. Line widths, radii, text sizes and offsets
//! of the overlay are already in points.

mod labels;
mod markup;
pub use markup::escape;
mod shapes;

use std::fmt::Write;

use base64::Engine;

use self::labels::{Glyphs, Label, label};
use self::markup::{Transform, n};
pub use self::shapes::color_bar_back;
use super::text::FONT_FAMILY;
use super::{Background, Figure, FigureError, FigureView};

/// Dash and gap lengths of dashed lines, in points (as on screen).
pub const DASH: (f32, f32) = (6.0, 4.0);
/// Points (times the overlay scale): circles at least this large are handles, which labels
/// keep clear of.
pub const MIN_OBSTACLE_RADIUS: f32 = 8.0;

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

/// A `font-family` list for SVG text in `lang`: the overlay font, the symbols font
/// ([`crate::i18n::SYMBOLS_FAMILY`]), then (for Chinese) the CJK
/// families a viewer may have ([`crate::i18n::CJK_FAMILIES`]), then `sans-serif`. (The
/// figures themselves draw their labels as glyph outlines and need no font.)
pub fn font_families(lang: crate::i18n::Lang) -> String {
    let mut families = vec![
        FONT_FAMILY.to_string(),
        format!("'{}'", crate::i18n::SYMBOLS_FAMILY),
    ];
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
            shapes::overlay(
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
