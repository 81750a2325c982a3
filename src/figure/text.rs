//! Text of the overlays: the font (egui's own proportional font, so the exported figure and the
//! screen use the same letters), its measurements, and where a label box goes. The screen
//! painter measures with egui and the figure export with this font; both place the box with
//! [`place_label`].

use std::sync::OnceLock;

use ab_glyph::{Font, FontRef, GlyphId, OutlineCurve, ScaleFont};

use super::overlay::Anchor;

/// The font of the overlays: egui's default proportional font (Ubuntu Light).
pub const FONT_BYTES: &[u8] = epaint_default_fonts::UBUNTU_LIGHT;
/// The font's family name, as SVG viewers and `fontdb` know it.
pub const FONT_FAMILY: &str = "Ubuntu";
/// Its CSS weight (Light).
pub const FONT_WEIGHT: u16 = 300;

/// Points of padding around label text that has a background box (x, y).
pub const LABEL_PAD: [f32; 2] = [6.0, 3.0];
/// Points: corner radius of a label's background box.
pub const LABEL_ROUNDING: f32 = 4.0;
/// Points: a label pushed inside its view keeps this far from the view's clip edge.
pub const LABEL_INSET: f32 = 2.0;

fn font() -> Option<&'static FontRef<'static>> {
    static FONT: OnceLock<Option<FontRef<'static>>> = OnceLock::new();
    FONT.get_or_init(|| FontRef::try_from_slice(FONT_BYTES).ok())
        .as_ref()
}

/// The bundled symbols font ([`crate::i18n::SYMBOLS_FONT`]), for the symbols the overlay font
/// lacks (floor brackets, arrows), as the app falls back to it.
fn symbols() -> Option<&'static FontRef<'static>> {
    static FONT: OnceLock<Option<FontRef<'static>>> = OnceLock::new();
    FONT.get_or_init(|| FontRef::try_from_slice(crate::i18n::SYMBOLS_FONT).ok())
        .as_ref()
}

/// The system's CJK font ([`crate::i18n::cjk_font`]), for the characters the overlay and
/// symbols fonts lack (Chinese labels); SVG renderers fall back the same way.
fn cjk() -> Option<&'static FontRef<'static>> {
    static FONT: OnceLock<Option<FontRef<'static>>> = OnceLock::new();
    FONT.get_or_init(|| {
        let f = crate::i18n::cjk_font()?;
        FontRef::try_from_slice_and_index(f.data.as_slice(), f.index).ok()
    })
    .as_ref()
}

/// Which font a glyph comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum GlyphFont {
    /// The overlay font ([`FONT_BYTES`]).
    Overlay,
    /// The bundled symbols font ([`crate::i18n::SYMBOLS_FONT`]), for the symbols the overlay
    /// font lacks.
    Symbols,
    /// The system's CJK font ([`crate::i18n::cjk_font`]), for what the overlay font lacks.
    Cjk,
}

impl GlyphFont {
    fn font(self) -> Option<&'static FontRef<'static>> {
        match self {
            GlyphFont::Overlay => font(),
            GlyphFont::Symbols => symbols(),
            GlyphFont::Cjk => cjk(),
        }
    }
}

/// One glyph of a laid-out line: its font and glyph id, where the pen is (points from the
/// line's start) and the points per font unit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GlyphAt {
    /// The font the glyph comes from.
    pub font: GlyphFont,
    /// The glyph's id in that font.
    pub id: u16,
    /// Points from the line's start to the glyph's origin.
    pub x: f32,
    /// Points per font unit (the text size over the font's units per em).
    pub per_unit: f32,
}

/// `text` laid out on one line at font size `size` (points, the em size): each character's
/// glyph from the overlay font (with kerning), or when the overlay font lacks it from the symbols
/// font, else from the CJK font; and the line's advance width.
fn layout(text: &str, size: f32) -> Option<(Vec<GlyphAt>, f32)> {
    let font = font()?;
    // ab_glyph scales by the line height: this scale makes one em `size` points.
    let scaled_of = |f: &'static FontRef<'static>| {
        let units = f.units_per_em().unwrap_or(1000.0);
        (
            f.as_scaled(size * f.height_unscaled() / units),
            size / units,
        )
    };
    let (scaled, per_unit) = scaled_of(font);
    let mut glyphs = Vec::with_capacity(text.len());
    let mut x = 0.0;
    let mut previous = None;
    for c in text.chars() {
        let id = scaled.glyph_id(c);
        let fallback = [GlyphFont::Symbols, GlyphFont::Cjk]
            .into_iter()
            .find_map(|k| {
                k.font()
                    .map(|f| (k, f))
                    .filter(|(_, f)| f.glyph_id(c).0 != 0)
            });
        if id.0 == 0
            && let Some((kind, other)) = fallback
        {
            let (s, per) = scaled_of(other);
            let cid = other.glyph_id(c);
            glyphs.push(GlyphAt {
                font: kind,
                id: cid.0,
                x,
                per_unit: per,
            });
            x += s.h_advance(cid);
            previous = None;
            continue;
        }
        if let Some(p) = previous {
            x += scaled.kern(p, id);
        }
        glyphs.push(GlyphAt {
            font: GlyphFont::Overlay,
            id: id.0,
            x,
            per_unit,
        });
        x += scaled.h_advance(id);
        previous = Some(id);
    }
    Some((glyphs, x))
}

/// The glyphs of `text` at font size `size`, placed as [`measure`] measures it. The figures
/// draw labels with their outlines ([`glyph_outline`]), so a label looks the same in every
/// SVG viewer whatever fonts it has, and its box, sized by [`measure`], holds it.
pub fn glyphs(text: &str, size: f32) -> Vec<GlyphAt> {
    layout(text, size).map(|(g, _)| g).unwrap_or_default()
}

/// A piece of a glyph outline: a line, a quadratic or a cubic Bézier curve through its
/// points (the first is where it starts).
#[derive(Clone, Debug, PartialEq)]
pub enum Curve {
    /// A straight line from the first point to the second.
    Line([[f32; 2]; 2]),
    /// A quadratic curve: start, control, end.
    Quad([[f32; 2]; 3]),
    /// A cubic curve: start, two controls, end.
    Cubic([[f32; 2]; 4]),
}

impl Curve {
    /// The first point.
    pub fn start(&self) -> [f32; 2] {
        match self {
            Curve::Line(p) => p[0],
            Curve::Quad(p) => p[0],
            Curve::Cubic(p) => p[0],
        }
    }

    /// The last point.
    pub fn end(&self) -> [f32; 2] {
        match self {
            Curve::Line(p) => p[1],
            Curve::Quad(p) => p[2],
            Curve::Cubic(p) => p[3],
        }
    }
}

/// The outline of glyph `id` of `font` in font units, y up, from the glyph's origin (empty
/// for a glyph without one, such as the space).
pub fn glyph_outline(font: GlyphFont, id: u16) -> Vec<Curve> {
    let Some(o) = font.font().and_then(|f| f.outline(GlyphId(id))) else {
        return Vec::new();
    };
    let p = |q: ab_glyph::Point| [q.x, q.y];
    o.curves
        .into_iter()
        .map(|c| match c {
            OutlineCurve::Line(a, b) => Curve::Line([p(a), p(b)]),
            OutlineCurve::Quad(a, b, c) => Curve::Quad([p(a), p(b), p(c)]),
            OutlineCurve::Cubic(a, b, c, d) => Curve::Cubic([p(a), p(b), p(c), p(d)]),
        })
        .collect()
}

/// Size of one line of text at font size `size` (points, the em size as in egui and SVG):
/// width = sum of the glyph advances (with kerning), height = ascent - descent + line gap.
/// Also returns the ascent (the baseline's distance below the top).
///
/// ```
/// use barylab::figure::text::measure;
/// let (a, _) = measure("A", 20.0);
/// let (aa, asc) = measure("AA", 20.0);
/// assert!(aa[0] > 1.9 * a[0] && aa[0] <= 2.0 * a[0] + 0.5);
/// assert!(asc > 10.0 && asc < aa[1]);
/// ```
pub fn measure(text: &str, size: f32) -> ([f32; 2], f32) {
    let (Some(font), Some((_, width))) = (font(), layout(text, size)) else {
        // The bundled font always parses; a rough estimate keeps boxes sensible otherwise.
        return ([0.5 * size * text.chars().count() as f32, 1.2 * size], size);
    };
    let units = font.units_per_em().unwrap_or(1000.0);
    let scaled = font.as_scaled(size * font.height_unscaled() / units);
    let height = scaled.ascent() - scaled.descent() + scaled.line_gap();
    ([width, height], scaled.ascent())
}

/// An axis-aligned box in points: `[min_x, min_y, max_x, max_y]`.
pub type Box2 = [f32; 4];

impl Anchor {
    /// Fractions (0, 1/2, 1) of the box's width and height at which the anchor point sits.
    pub fn fractions(self) -> [f32; 2] {
        match self {
            Anchor::LeftTop => [0.0, 0.0],
            Anchor::LeftBottom => [0.0, 1.0],
            Anchor::RightBottom => [1.0, 1.0],
            Anchor::LeftCenter => [0.0, 0.5],
            Anchor::CenterTop => [0.5, 0.0],
            Anchor::CenterBottom => [0.5, 1.0],
            Anchor::Center => [0.5, 0.5],
            Anchor::RightTop => [1.0, 0.0],
            Anchor::RightCenter => [1.0, 0.5],
        }
    }

    fn from_fractions(f: [f32; 2]) -> Self {
        let [x, y] = f.map(|v| (v * 2.0).round() as i32);
        match (x, y) {
            (0, 0) => Anchor::LeftTop,
            (0, 2) => Anchor::LeftBottom,
            (2, 2) => Anchor::RightBottom,
            (0, _) => Anchor::LeftCenter,
            (1, 0) => Anchor::CenterTop,
            (1, 2) => Anchor::CenterBottom,
            (1, _) => Anchor::Center,
            (_, 0) => Anchor::RightTop,
            (_, 2) => Anchor::RightBottom,
            _ => Anchor::RightCenter,
        }
    }

    /// Left and right swapped.
    pub fn flipped_x(self) -> Self {
        let [x, y] = self.fractions();
        Self::from_fractions([1.0 - x, y])
    }

    /// Top and bottom swapped.
    pub fn flipped_y(self) -> Self {
        let [x, y] = self.fractions();
        Self::from_fractions([x, 1.0 - y])
    }

    /// The box of `size` whose anchor point is at `pos`.
    pub fn box_at(self, pos: [f32; 2], size: [f32; 2]) -> Box2 {
        let [fx, fy] = self.fractions();
        let min = [pos[0] - fx * size[0], pos[1] - fy * size[1]];
        [min[0], min[1], min[0] + size[0], min[1] + size[1]]
    }
}

/// Where a label box of `size` goes: at `base + offset` by its `anchor`; a box that would stick
/// out of `clip` on one side is mirrored to the other side of `base` (if it fits there), then
/// moved as little as needed to lie [`LABEL_INSET`] inside `clip` (if it fits at all).
///
/// ```
/// use barylab::figure::overlay::Anchor;
/// use barylab::figure::text::place_label;
/// let clip = [0.0, 0.0, 100.0, 100.0];
/// // Fits: stays right of and below its point.
/// assert_eq!(place_label([10.0, 10.0], [5.0, 5.0], Anchor::LeftTop, [20.0, 10.0], clip),
///            [15.0, 15.0, 35.0, 25.0]);
/// // Would stick out on the right: mirrored to the left of its point.
/// assert_eq!(place_label([90.0, 10.0], [5.0, 5.0], Anchor::LeftTop, [20.0, 10.0], clip),
///            [65.0, 15.0, 85.0, 25.0]);
/// ```
pub fn place_label(
    base: [f32; 2],
    offset: [f32; 2],
    anchor: Anchor,
    size: [f32; 2],
    clip: Box2,
) -> Box2 {
    let sticks_x = |b: Box2| b[0] < clip[0] || b[2] > clip[2];
    let sticks_y = |b: Box2| b[1] < clip[1] || b[3] > clip[3];
    let mut anchor = anchor;
    let mut pos = [base[0] + offset[0], base[1] + offset[1]];
    if sticks_x(anchor.box_at(pos, size)) {
        let (a, p) = (anchor.flipped_x(), [base[0] - offset[0], pos[1]]);
        if !sticks_x(a.box_at(p, size)) {
            (anchor, pos) = (a, p);
        }
    }
    if sticks_y(anchor.box_at(pos, size)) {
        let (a, p) = (anchor.flipped_y(), [pos[0], base[1] - offset[1]]);
        if !sticks_y(a.box_at(p, size)) {
            (anchor, pos) = (a, p);
        }
    }
    push_inside(anchor.box_at(pos, size), clip)
}

/// Where two labels of outer sizes `sizes` go side by side about `base` (the point between
/// them, their bottom edges at `base.y`), `gap` apart: the left one ends `gap / 2` left of
/// `base.x`, the right one starts `gap / 2` right of it, then both move together, as little
/// as needed, to lie [`LABEL_INSET`] inside `clip`. They never overlap. Returns the boxes and
/// whether they fit side by side (when not, the caller shrinks the text by [`pair_fit`] and
/// places them again; until then they start at the clip's left edge).
///
/// ```
/// use barylab::figure::text::place_pair;
/// let clip = [0.0, 0.0, 200.0, 100.0];
/// // In the middle: straddling the point.
/// let ([l, r], fits) = place_pair([100.0, 50.0], 10.0, [[40.0, 20.0], [60.0, 20.0]], clip);
/// assert!(fits);
/// assert_eq!((l, r), ([55.0, 30.0, 95.0, 50.0], [105.0, 30.0, 165.0, 50.0]));
/// // At the right edge: both move left, the left one stays left of the right one.
/// let ([l, r], _) = place_pair([200.0, 50.0], 10.0, [[40.0, 20.0], [60.0, 20.0]], clip);
/// assert_eq!((l[0], r[2]), (88.0, 198.0));
/// assert!(l[2] < r[0]);
/// ```
pub fn place_pair(base: [f32; 2], gap: f32, sizes: [[f32; 2]; 2], clip: Box2) -> ([Box2; 2], bool) {
    let [ls, rs] = sizes;
    let (lo, hi) = (clip[0] + LABEL_INSET, clip[2] - LABEL_INSET);
    // The shift of the pair that puts its left end at `lo`, and its right end at `hi`.
    let min_shift = lo - (base[0] - gap / 2.0 - ls[0]);
    let max_shift = hi - (base[0] + gap / 2.0 + rs[0]);
    let fits = min_shift <= max_shift;
    let shift = if fits {
        0.0f32.clamp(min_shift, max_shift)
    } else {
        min_shift
    };
    let x = base[0] + shift;
    let left = Anchor::RightBottom.box_at([x - gap / 2.0, base[1]], ls);
    let right = Anchor::LeftBottom.box_at([x + gap / 2.0, base[1]], rs);
    let push_y = |b: Box2| {
        let moved = push_inside(
            b,
            [b[0] - LABEL_INSET, clip[1], b[2] + LABEL_INSET, clip[3]],
        );
        [b[0], moved[1], b[2], moved[3]]
    };
    ([push_y(left), push_y(right)], fits)
}

/// The factor (at most 1) by which two labels of text widths `text_widths` (without their
/// padding) must shrink to fit side by side in `clip` with `gap` between their boxes and
/// `padding` points of box around each text on both sides; 1 when they fit. The text size is
/// multiplied by it (advances scale with the size); a little is kept spare for rounding.
///
/// ```
/// use barylab::figure::text::pair_fit;
/// assert_eq!(pair_fit([50.0, 50.0], 0.0, 10.0, [0.0, 0.0, 500.0, 10.0]), 1.0);
/// // 100 points of room for 200 points of text: about half the size.
/// let f = pair_fit([100.0, 100.0], 6.0, 20.0, [0.0, 0.0, 148.0, 10.0]);
/// assert!(f < 0.5 && f > 0.45);
/// ```
pub fn pair_fit(text_widths: [f32; 2], padding: f32, gap: f32, clip: Box2) -> f32 {
    fit(text_widths[0] + text_widths[1], gap + 4.0 * padding, clip)
}

/// The factor (at most 1, at least [`PAIR_MIN_FIT`]) by which text `text_width` points wide
/// must shrink so that it and `fixed` points more (padding, gaps) fit across `clip` (less
/// [`LABEL_INSET`] on each side); 1 when it fits.
///
/// ```
/// use barylab::figure::text::fit;
/// assert_eq!(fit(50.0, 12.0, [0.0, 0.0, 100.0, 10.0]), 1.0);
/// assert!((fit(200.0, 12.0, [0.0, 0.0, 116.0, 10.0]) - 0.49).abs() < 1e-6);
/// ```
pub fn fit(text_width: f32, fixed: f32, clip: Box2) -> f32 {
    let room = clip[2] - clip[0] - 2.0 * LABEL_INSET - fixed;
    if text_width <= 0.0 || room >= text_width {
        1.0
    } else {
        (0.98 * room.max(0.0) / text_width).max(PAIR_MIN_FIT)
    }
}

/// The smallest factor [`fit`] shrinks a label by: small enough that labels on the smallest
/// views still fit (never overlapping, never leaving their view); text that small is only
/// there to be readable when zoomed in.
pub const PAIR_MIN_FIT: f32 = 0.02;

/// [`place_label`], but clear of the labels already placed (`placed`) and of what must stay
/// visible (`keep_clear`: the handles, colour bars, cards): of the box at its own side of `base`
/// (pushed inside `clip`, else as [`place_label`] places it) and the boxes mirrored left-right,
/// up-down and both, the first that overlaps none of them; when all four do, the nearest free
/// place found by moving them (up to [`AVOID_STEPS`] half-heights or half-widths); else the
/// place overlapping them least, an overlap with `keep_clear` counting [`KEEP_CLEAR_COST`]
/// times its area (a label covering another label is better than one hiding a handle).
/// Neighbouring corners' labels on a small image go to different sides instead of on top of
/// each other.
///
/// ```
/// use barylab::figure::overlay::Anchor;
/// use barylab::figure::text::{place_label, place_label_avoiding};
/// let clip = [0.0, 0.0, 100.0, 100.0];
/// let first = place_label([50.0, 50.0], [2.0, 2.0], Anchor::LeftTop, [20.0, 10.0], clip);
/// let second = place_label_avoiding([52.0, 52.0], [2.0, 2.0], Anchor::LeftTop, [20.0, 10.0],
///                                   clip, &[first], &[]);
/// assert_eq!(second, [30.0, 54.0, 50.0, 64.0]); // mirrored to the left of its point
/// // Boxed in on every side within reach: it covers a label rather than a handle.
/// let handle = [0.0, 0.0, 100.0, 50.0];
/// let label = [0.0, 50.0, 100.0, 100.0];
/// let b = place_label_avoiding([50.0, 50.0], [2.0, 2.0], Anchor::LeftTop, [20.0, 10.0],
///                              clip, &[label], &[handle]);
/// assert!(b[1] >= 50.0);
/// ```
pub fn place_label_avoiding(
    base: [f32; 2],
    offset: [f32; 2],
    anchor: Anchor,
    size: [f32; 2],
    clip: Box2,
    placed: &[Box2],
    keep_clear: &[Box2],
) -> Box2 {
    let overlap = |b: Box2| overlap_area(b, placed) + KEEP_CLEAR_COST * overlap_area(b, keep_clear);
    let candidates = [
        (anchor, offset),
        (anchor.flipped_x(), [-offset[0], offset[1]]),
        (anchor.flipped_y(), [offset[0], -offset[1]]),
        (anchor.flipped_x().flipped_y(), [-offset[0], -offset[1]]),
    ];
    // Each side's box pushed inside the clip as it is, then as `place_label` puts it (mirrored
    // when it sticks out): a label near the edge keeps its side when there is room.
    let boxes: Vec<Box2> = candidates
        .iter()
        .flat_map(|&(a, o)| {
            [
                push_inside(a.box_at([base[0] + o[0], base[1] + o[1]], size), clip),
                place_label(base, o, a, size, clip),
            ]
        })
        .collect();
    let mut best: Option<(f32, Box2)> = None;
    let mut consider = |b: Box2| {
        let cost = overlap(b);
        if best.is_none_or(|(c, _)| cost < c) {
            best = Some((cost, b));
        }
        cost == 0.0
    };
    for &b in &boxes {
        if consider(b) {
            return b;
        }
    }
    // All four sides taken: the nearest free place, moving a side's box up or down (then
    // left or right) in steps of half its height (width), kept inside the clip.
    let step = [size[0] / 2.0, size[1] / 2.0];
    for k in 1..=AVOID_STEPS {
        for axis in [1, 0] {
            for sign in [-1.0, 1.0] {
                for &b in &boxes {
                    let d = sign * k as f32 * step[axis];
                    let mut moved = b;
                    moved[axis] += d;
                    moved[axis + 2] += d;
                    let moved = push_inside(moved, clip);
                    if consider(moved) {
                        return moved;
                    }
                }
            }
        }
    }
    best.map_or(boxes[1], |(_, b)| b)
}

/// The area box `b` shares with `boxes`, summed over them (a point under two of them counts
/// twice).
///
/// ```
/// use barylab::figure::text::overlap_area;
/// let b = [0.0, 0.0, 10.0, 10.0];
/// assert_eq!(overlap_area(b, &[[5.0, 5.0, 20.0, 20.0], [20.0, 0.0, 30.0, 10.0]]), 25.0);
/// ```
pub fn overlap_area(b: Box2, boxes: &[Box2]) -> f32 {
    boxes
        .iter()
        .map(|p| {
            let w = (b[2].min(p[2]) - b[0].max(p[0])).max(0.0);
            let h = (b[3].min(p[3]) - b[1].max(p[1])).max(0.0);
            w * h
        })
        .sum()
}

/// How much worse [`place_label_avoiding`] counts covering a point of what must stay visible
/// (a handle) than covering a point of another label.
pub const KEEP_CLEAR_COST: f32 = 1000.0;

/// The part of a handle of radius `radius` at `centre` that labels keep clear of: the square
/// inside its circle (a label placed diagonally next to its own handle touches only the
/// circle's rim, outside this square).
pub fn handle_obstacle(centre: [f32; 2], radius: f32) -> Box2 {
    let h = HANDLE_OBSTACLE * radius;
    [centre[0] - h, centre[1] - h, centre[0] + h, centre[1] + h]
}

/// Half the side of [`handle_obstacle`]'s square, in radii (a little less than 1/sqrt(2)).
pub const HANDLE_OBSTACLE: f32 = 0.7;

/// How far [`place_label_avoiding`] moves a label looking for a free place: this many half
/// heights up or down, or half widths left or right.
pub const AVOID_STEPS: usize = 8;

/// `b` moved as little as needed to lie [`LABEL_INSET`] inside `bounds`, if it fits.
pub fn push_inside(b: Box2, bounds: Box2) -> Box2 {
    let inner = [
        bounds[0] + LABEL_INSET,
        bounds[1] + LABEL_INSET,
        bounds[2] - LABEL_INSET,
        bounds[3] - LABEL_INSET,
    ];
    let fits = inner.iter().all(|v| v.is_finite())
        && b[2] - b[0] <= inner[2] - inner[0]
        && b[3] - b[1] <= inner[3] - inner[1];
    if !fits {
        return b;
    }
    let dx = (inner[0] - b[0]).max(0.0) + (inner[2] - b[2]).min(0.0);
    let dy = (inner[1] - b[1]).max(0.0) + (inner[3] - b[3]).min(0.0);
    [b[0] + dx, b[1] + dy, b[2] + dx, b[3] + dy]
}

/// The outer size of a label: the text's size plus [`LABEL_PAD`] (times `k`, the overlay
/// scale) on each side if it has a background.
pub fn padded(text_size: [f32; 2], background: bool, k: f32) -> [f32; 2] {
    if background {
        [
            text_size[0] + 2.0 * LABEL_PAD[0] * k,
            text_size[1] + 2.0 * LABEL_PAD[1] * k,
        ]
    } else {
        text_size
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flips_are_involutions_and_mirror_the_side() {
        for a in [
            Anchor::LeftTop,
            Anchor::LeftBottom,
            Anchor::RightBottom,
            Anchor::LeftCenter,
            Anchor::CenterTop,
            Anchor::CenterBottom,
            Anchor::Center,
            Anchor::RightTop,
            Anchor::RightCenter,
        ] {
            assert_eq!(a.flipped_x().flipped_x(), a);
            assert_eq!(a.flipped_y().flipped_y(), a);
        }
        assert_eq!(Anchor::LeftTop.flipped_x(), Anchor::RightTop);
        assert_eq!(Anchor::LeftTop.flipped_y(), Anchor::LeftBottom);
        assert_eq!(Anchor::Center.flipped_y(), Anchor::Center);
    }

    #[test]
    fn a_label_near_the_bottom_goes_above_its_point_and_one_too_wide_stays() {
        let clip = [0.0, 0.0, 100.0, 100.0];
        let b = place_label(
            [50.0, 95.0],
            [0.0, 4.0],
            Anchor::CenterTop,
            [20.0, 10.0],
            clip,
        );
        assert_eq!(b, [40.0, 81.0, 60.0, 91.0]);
        // Wider than the clip: left where it is.
        let b = place_label(
            [50.0, 50.0],
            [0.0, 0.0],
            Anchor::Center,
            [200.0, 10.0],
            clip,
        );
        assert_eq!(b, [-50.0, 45.0, 150.0, 55.0]);
    }
}
