//! How a lesson's formula block fits the panel: a little too wide, it is set a little smaller;
//! much too wide, its lines wrap at full size.

use egui::{RichText, Ui};

/// The smallest share of its size a formula is set at to fit the panel.
const FORMULA_MIN_SCALE: f32 = 0.85;

/// The width in points of a formula's lines set in monospace at `size`.
pub(super) fn width(ui: &Ui, text: &str, size: f32) -> f32 {
    egui::WidgetText::from(RichText::new(text).monospace().size(size))
        .into_galley(
            ui,
            Some(egui::TextWrapMode::Extend),
            f32::INFINITY,
            egui::TextStyle::Monospace,
        )
        .size()
        .x
}

/// The size a formula `width` points wide at `size` is set at to fit `available` points:
/// `size` when it fits, else scaled down with the width; `None` when that would be below
/// [`FORMULA_MIN_SCALE`] of `size` (its lines wrap instead).
pub(super) fn fitted_size(size: f32, width: f32, available: f32) -> Option<f32> {
    if width <= available || width <= 0.0 {
        return Some(size);
    }
    let scaled = size * available / width;
    (scaled >= size * FORMULA_MIN_SCALE).then_some(scaled)
}

#[cfg(test)]
mod tests {
    use super::{FORMULA_MIN_SCALE, fitted_size};

    #[test]
    fn a_formula_a_little_too_wide_is_set_smaller_and_a_much_wider_one_wraps() {
        assert_eq!(fitted_size(20.0, 300.0, 400.0), Some(20.0));
        assert_eq!(fitted_size(20.0, 440.0, 400.0), Some(20.0 * 400.0 / 440.0));
        // Far too wide (it would be set at 0.4 of its size): not tiny, but wrapped.
        assert_eq!(fitted_size(20.0, 1000.0, 400.0), None);
        // Just at the floor it is still set smaller.
        let at_floor = 400.0 / FORMULA_MIN_SCALE;
        assert!(fitted_size(20.0, at_floor - 1.0, 400.0).is_some());
    }
}
