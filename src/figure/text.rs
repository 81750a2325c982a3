//! Text of the overlays: the font (egui's own proportional font, so the exported figure and the
//! screen use the same letters), its measurements, and where a label box goes. The screen
//! painter measures with egui and the figure export with this font; both place the box with
//! [`place_label`].

use std::sync::OnceLock;

use ab_glyph::{Font, FontRef, ScaleFont};

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

/// The system's CJK font ([`crate::i18n::cjk_font`]), for the characters the overlay font
/// lacks (Chinese labels); SVG renderers fall back the same way.
fn cjk() -> Option<&'static FontRef<'static>> {
    static FONT: OnceLock<Option<FontRef<'static>>> = OnceLock::new();
    FONT.get_or_init(|| {
        let f = crate::i18n::cjk_font()?;
        FontRef::try_from_slice_and_index(f.data.as_slice(), f.index).ok()
    })
    .as_ref()
}

/// The advance of `c` at font size `size` in the CJK font, when the overlay font has no glyph
/// for it and a CJK font is installed.
fn cjk_advance(c: char, size: f32) -> Option<f32> {
    let font = cjk()?;
    let id = font.glyph_id(c);
    if id.0 == 0 {
        return None;
    }
    // ab_glyph scales by the line height: this scale makes one em `size` points, as for the
    // overlay font.
    let units = font.units_per_em().unwrap_or(1000.0);
    Some(
        font.as_scaled(size * font.height_unscaled() / units)
            .h_advance(id),
    )
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
    let Some(font) = font() else {
        // The bundled font always parses; a rough estimate keeps boxes sensible otherwise.
        return ([0.5 * size * text.chars().count() as f32, 1.2 * size], size);
    };
    let units = font.units_per_em().unwrap_or(1000.0);
    let scaled = font.as_scaled(size * font.height_unscaled() / units);
    let mut width = 0.0;
    let mut previous = None;
    for c in text.chars() {
        let id = scaled.glyph_id(c);
        if id.0 == 0
            && let Some(advance) = cjk_advance(c, size)
        {
            width += advance;
            previous = None;
            continue;
        }
        if let Some(p) = previous {
            width += scaled.kern(p, id);
        }
        width += scaled.h_advance(id);
        previous = Some(id);
    }
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
