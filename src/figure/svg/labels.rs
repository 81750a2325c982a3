//! Labels as SVG: a box and the text as the overlay font's glyph outlines, each glyph
//! defined once per document and drawn with `<use>`.

use std::fmt::Write;

use super::markup::{escape, fill, n, rect};
use crate::figure::overlay::Rgba;
use crate::figure::text::{self, Box2, LABEL_PAD, LABEL_ROUNDING};

/// What a label shows: its text at a size in a colour, on a box of a colour or none.
#[derive(Clone, Copy)]
pub(super) struct Label<'a> {
    text: &'a str,
    size: f32,
    color: Rgba,
    background: Option<Rgba>,
}

impl<'a> Label<'a> {
    pub(super) fn new(text: &'a str, size: f32, color: Rgba, background: Option<Rgba>) -> Self {
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
pub(super) fn label(s: &mut String, glyphs: &mut Glyphs, b: Box2, l: Label<'_>, k: f32) {
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
pub(super) struct Glyphs {
    /// Glyph and its outline's path data (`None`: no outline, nothing to draw).
    used: std::collections::BTreeMap<(text::GlyphFont, u16), Option<String>>,
}

impl Glyphs {
    /// The element id of a glyph's outline, or `None` for a glyph without one (a space).
    pub(super) fn id(&mut self, font: text::GlyphFont, glyph: u16) -> Option<String> {
        let d = self.used.entry((font, glyph)).or_insert_with(|| {
            Some(glyph_path(&text::glyph_outline(font, glyph))).filter(|d| !d.is_empty())
        });
        d.as_ref().map(|_| glyph_id(font, glyph))
    }

    /// The `<path>` definitions of the glyphs used, for the document's `<defs>`.
    pub(super) fn defs(&self, s: &mut String) {
        for ((font, glyph), d) in &self.used {
            if let Some(d) = d {
                let _ = writeln!(s, r#"<path id="{}" d="{d}"/>"#, glyph_id(*font, *glyph));
            }
        }
    }
}

/// The element id of a glyph's outline: `g0-N` for glyph N of the overlay font, `g1-N` of
/// the CJK font, `g2-N` of the symbols font.
fn glyph_id(font: text::GlyphFont, glyph: u16) -> String {
    let f = match font {
        text::GlyphFont::Overlay => 0,
        text::GlyphFont::Cjk => 1,
        text::GlyphFont::Symbols => 2,
    };
    format!("g{f}-{glyph}")
}

/// A scale factor for SVG: six decimals, no trailing zeros (a glyph's points per font unit
/// is about 0.02; three decimals would lose a few percent of its size).
pub(super) fn fine(v: f32) -> String {
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
