//! SVG markup: numbers, colours, strokes, escaped text, rectangles, and the map from canvas
//! coordinates to figure points.

use std::fmt::Write;

use glam::DVec2;

use super::DASH;
use crate::figure::overlay::{Rgba, Stroke};
use crate::figure::text::Box2;

/// Canvas coordinates (rendered pixels) to figure points.
#[derive(Clone, Copy, Debug)]
pub(super) struct Transform {
    /// Figure points of canvas (0, 0).
    pub(super) origin: [f64; 2],
    /// Points per rendered pixel.
    pub(super) scale: f64,
}

impl Transform {
    pub(super) fn point(&self, p: DVec2) -> [f32; 2] {
        [
            (self.origin[0] + p.x * self.scale) as f32,
            (self.origin[1] + p.y * self.scale) as f32,
        ]
    }
}

/// A number for SVG: at most three decimals, no trailing zeros.
pub(super) fn n(v: f32) -> String {
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}

pub(super) fn hex(c: Rgba) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

/// `fill="..."` with its opacity, or `fill="none"`.
pub(super) fn fill(c: Rgba) -> String {
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
pub(super) fn stroke(st: Option<Stroke>, dashed: bool, k: f32) -> String {
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

pub(super) fn points(pts: &[[f32; 2]]) -> String {
    pts.iter()
        .map(|p| format!("{},{}", n(p[0]), n(p[1])))
        .collect::<Vec<_>>()
        .join(" ")
}

/// `t` with `&`, `<`, `>` and `"` escaped for XML and HTML text and attributes.
///
/// ```
/// assert_eq!(barylab::figure::svg::escape("a < b & \"c\""), "a &lt; b &amp; &quot;c&quot;");
/// ```
pub fn escape(t: &str) -> String {
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

pub(super) fn rect(s: &mut String, b: Box2, rounding: f32, attrs: &str) {
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
