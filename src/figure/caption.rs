//! The figure's optional caption for print: the marked pixel's key numbers (the pixel, the
//! screen weights r s t, the corrected weights a b c, W_P, uv affine and perspective-correct)
//! in lines below the views. Every number is a field of the pixel's trace, written as its
//! derivation writes it ([`fmt_number`]), so the caption, the exported derivation and
//! `barylab probe` on the exported scene agree digit for digit.

use crate::i18n::Lang;
use crate::probe::PixelTrace;
use crate::probe::format::fmt_number;
use crate::raster::Interpolation;

use super::overlay::Rgba;
use super::text;

/// Points: the caption's text size (times the overlay scale).
pub const CAPTION_TEXT: f32 = 16.0;
/// The caption's text colour: near-black, for paper.
pub const CAPTION_INK: Rgba = [24, 24, 28, 255];
/// Between the parts of one caption line.
pub const SEPARATOR: &str = " · ";
/// The smallest caption text size in points, before the overlay scale: a word wider than the
/// figure shrinks the caption down to this, not below.
pub const MIN_CAPTION_TEXT: f32 = 8.0;

/// A caption laid out in figure points.
#[derive(Clone, Debug, PartialEq)]
pub struct Caption {
    /// The lines, top to bottom.
    pub lines: Vec<String>,
    /// Text size in points.
    pub size: f32,
    /// Points from one line's top to the next one's.
    pub line_height: f32,
    /// Figure points of the first line's top-left corner.
    pub origin: [f32; 2],
}

impl Caption {
    /// The caption's height in points.
    pub fn height(&self) -> f32 {
        self.lines.len() as f32 * self.line_height
    }

    /// The box of line `i` (as wide as its text), in figure points.
    pub fn line_box(&self, i: usize) -> text::Box2 {
        let ([w, _], _) = text::measure(&self.lines[i], self.size);
        let y = self.origin[1] + i as f32 * self.line_height;
        [self.origin[0], y, self.origin[0] + w, y + self.line_height]
    }
}

fn t(lang: Lang, key: &str, args: &[(&str, String)]) -> String {
    let mut s = crate::i18n::tr(lang, key);
    for (name, value) in args {
        s = s.replace(&format!("%{{{name}}}"), value);
    }
    s
}

/// The caption's groups for `trace` (a pixel of an image `size` pixels large) in `lang`:
/// each group starts a new line and its parts are joined by [`SEPARATOR`].
pub fn groups(trace: &PixelTrace, size: [u32; 2], lang: Lang) -> Vec<Vec<String>> {
    let [x, y] = trace.pixel.map(|v| v.to_string());
    let mut head = vec![t(
        lang,
        "figure.caption.pixel",
        &[
            ("x", x),
            ("y", y),
            ("width", size[0].to_string()),
            ("height", size[1].to_string()),
        ],
    )];
    let Some(d) = &trace.detail else {
        head.push(t(lang, "figure.caption.not_covered", &[]));
        return vec![head];
    };
    head.push(t(
        lang,
        match trace.settings.mode {
            Interpolation::Affine => "figure.caption.mode_affine",
            Interpolation::Perspective => "figure.caption.mode_perspective",
        },
        &[],
    ));
    let mut out = vec![head];
    let [r, s, tt] = d.screen.rasterizer.map(fmt_number);
    out.push(vec![t(
        lang,
        "figure.caption.screen",
        &[("r", r), ("s", s), ("t", tt)],
    )]);
    if let Some(p) = &d.perspective {
        let c = p.correction;
        let [a, b, cc] = c.weights.map(fmt_number);
        out.push(vec![
            t(
                lang,
                "figure.caption.corrected",
                &[("a", a), ("b", b), ("c", cc)],
            ),
            t(lang, "figure.caption.w_p", &[("w_p", fmt_number(c.w_p))]),
        ]);
    }
    if let Some(a) = &d.attribute {
        let uv = |key: &str, v: [f32; 2]| {
            let [u, v] = v.map(|x| fmt_number(f64::from(x)));
            t(lang, key, &[("u", u), ("v", v)])
        };
        out.push(vec![
            uv("figure.caption.uv_affine", a.uv_affine),
            uv("figure.caption.uv_perspective", a.uv_perspective),
        ]);
    }
    out
}

/// `groups` set in lines at most `width` points wide at text size `size`: each group starts a
/// line and its parts follow joined by [`SEPARATOR`]; a part that does not fit on the line
/// starts the next one, and a part wider than `width` on its own is wrapped between its
/// [`words`] (at every space when an equation does not fit even at `min_size`). When one word
/// is wider than `width` the size shrinks until it fits (not below `min_size`).
/// Returns the lines and the size used.
///
/// ```
/// use barylab::figure::caption::wrap;
/// let groups = vec![vec!["a b".to_string(), "c".to_string()], vec!["d".to_string()]];
/// let (lines, size) = wrap(&groups, 1000.0, 16.0, 8.0);
/// assert_eq!((lines, size), (vec!["a b · c".to_string(), "d".to_string()], 16.0));
/// let (narrow, _) = wrap(&groups, 1.0, 16.0, 8.0);
/// assert_eq!(narrow, ["a", "b", "c", "d"]);
/// ```
pub fn wrap(groups: &[Vec<String>], width: f32, size: f32, min_size: f32) -> (Vec<String>, f32) {
    // Equations kept whole when they fit (at a smaller size if need be, not below
    // `min_size`), else split at every space.
    let split = |glued: bool| {
        move |p: &String| -> Vec<String> {
            if glued {
                words(p)
            } else {
                p.split(' ').map(str::to_string).collect()
            }
        }
    };
    let size_for = |glued: bool| {
        let widest = groups
            .iter()
            .flatten()
            .flat_map(split(glued))
            .map(|w| text::measure(&w, size).0[0])
            .fold(0.0f32, f32::max);
        if widest > width && widest > 0.0 {
            size * width / widest
        } else {
            size
        }
    };
    let glued = size_for(true) >= min_size;
    let size = if glued {
        size_for(true)
    } else {
        size_for(false).max(min_size)
    };
    let words = split(glued);
    let fits = |s: &str| text::measure(s, size).0[0] <= width;
    let mut lines = Vec::new();
    for g in groups {
        let mut line = String::new();
        for part in g {
            let joined = format!("{line}{SEPARATOR}{part}");
            if !line.is_empty() && fits(&joined) {
                line = joined;
                continue;
            }
            if !line.is_empty() {
                lines.push(std::mem::take(&mut line));
            }
            // The part starts a line; wrapped at spaces if it is too wide on its own.
            for word in words(part) {
                let candidate = if line.is_empty() {
                    word.to_string()
                } else {
                    format!("{line} {word}")
                };
                if !line.is_empty() && !fits(&candidate) {
                    lines.push(std::mem::take(&mut line));
                    line = word.to_string();
                } else {
                    line = candidate;
                }
            }
        }
        lines.push(line);
    }
    (lines, size)
}

/// The words a caption part may wrap between: split at spaces, except after a comma and
/// around `=`, so an equation such as `r, s, t = 0.4961, 0.3491, 0.1548` stays on one line.
///
/// ```
/// use barylab::figure::caption::words;
/// assert_eq!(words("screen weights r, s, t = 0.1, 0.2, 0.7"),
///            ["screen", "weights", "r, s, t = 0.1, 0.2, 0.7"]);
/// ```
pub fn words(part: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut glue = false;
    for w in part.split(' ') {
        match out.last_mut() {
            Some(last) if glue || last.ends_with(',') || w == "=" => {
                last.push(' ');
                last.push_str(w);
            }
            _ => out.push(w.to_string()),
        }
        glue = w == "=";
    }
    out
}

/// The caption of `trace` laid out from `origin` (figure points, top-left), at most `width`
/// points wide, for overlay scale `k`.
pub fn layout(
    trace: &PixelTrace,
    image_size: [u32; 2],
    lang: Lang,
    origin: [f32; 2],
    width: f32,
    k: f32,
) -> Caption {
    let (lines, size) = wrap(
        &groups(trace, image_size, lang),
        width,
        CAPTION_TEXT * k,
        MIN_CAPTION_TEXT * k,
    );
    let ([_, h], _) = text::measure("Ag", size);
    Caption {
        lines,
        size,
        line_height: h.ceil(),
        origin,
    }
}
