//! How wide the side panels may be: the canvas keeps at least half of the window's area, so a
//! panel that does not fit collapses to a strip instead of crushing the canvas. Pure
//! arithmetic in points (so text size is included); the panels themselves are laid out in
//! [`crate::app::BaryApp`].

/// The canvas's least share of the window's area.
pub const CANVAS_SHARE: f32 = 0.5;
/// Points: the narrowest an open side panel gets.
pub const PANEL_MIN: f32 = 220.0;
/// Points: the default widths.
pub const CONTROLS_DEFAULT: f32 = 300.0;
pub const INSPECTOR_DEFAULT: f32 = 380.0;
/// The inspector's least share of the panels' room when both are open (its numbers need it
/// more than the controls do).
pub const INSPECTOR_SHARE: f32 = 0.55;
/// Points a side panel takes beyond its width (its separator line and resize margin).
pub const PANEL_SLACK: f32 = 10.0;
/// Points: the central panel's margin around the canvas.
pub const CANVAS_MARGIN: f32 = 8.0;
/// Points: the width of a collapsed panel's strip.
pub const STRIP: f32 = 30.0;
/// Points: the narrowest the canvas gets when the user opens a panel that the canvas's share
/// leaves no room for (a projector at a large text size): the canvas gives way down to this
/// width rather than the panel staying shut.
pub const CANVAS_MIN_WIDTH: f32 = 200.0;
/// Points: the least width the canvas keeps beside a column that a pinned pixel's quiz or
/// magnifier takes at its right (outside presentation mode); with less, the column is not
/// laid out (the quiz becomes a window, the magnifier is left out).
pub const CANVAS_BESIDE_COLUMN: f32 = 300.0;

/// Which side panel gets the room first when both do not fit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Side {
    Controls,
    #[default]
    Inspector,
}

/// How one side panel is shown.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Fit {
    /// Not wanted.
    Hidden,
    /// Wanted, but there is no room: a strip with a button that opens it.
    Strip,
    /// Open, resizable up to `max` points wide.
    Open { max: f32 },
}

/// The two panels' fits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fits {
    pub controls: Fit,
    pub inspector: Fit,
}

/// Points of width the side panels may take together, for a window of `window` points whose
/// canvas row (between the top and bottom bars) is `row_height` points high. The canvas is
/// what is inside the central panel's margins.
pub fn budget(window: [f32; 2], row_height: f32) -> f32 {
    let [w, h] = window;
    let m = 2.0 * CANVAS_MARGIN;
    let min_canvas = CANVAS_SHARE * w * h / (row_height - m).max(1.0) + m;
    (w - min_canvas - 2.0 * PANEL_SLACK).max(0.0)
}

/// Points of width a panel the user opened may take when [`budget`] leaves it no room: the
/// window less the canvas's narrowest width.
pub fn room(window_width: f32) -> f32 {
    (window_width - CANVAS_MIN_WIDTH - 2.0 * CANVAS_MARGIN - 2.0 * PANEL_SLACK).max(0.0)
}

/// Which panels open in `budget` points, the `first` one first. A panel the user opened
/// (`forced`) that `budget` leaves shut opens all the same in `room` points (the canvas gives
/// way), the other one then a strip.
pub fn fits_forced(
    budget: f32,
    room: f32,
    controls: bool,
    inspector: bool,
    first: Side,
    forced: Option<Side>,
) -> Fits {
    let mut f = fits(budget, controls, inspector, first);
    let strips = if controls && inspector { STRIP } else { 0.0 };
    let open = Fit::Open { max: room - strips };
    if room - strips >= PANEL_MIN {
        match forced {
            Some(Side::Controls) if controls && f.controls == Fit::Strip => {
                f.controls = open;
                if inspector {
                    f.inspector = Fit::Strip;
                }
            }
            Some(Side::Inspector) if inspector && f.inspector == Fit::Strip => {
                f.inspector = open;
                if controls {
                    f.controls = Fit::Strip;
                }
            }
            _ => {}
        }
    }
    f
}

/// Which panels open in `budget` points, the `first` one first.
pub fn fits(budget: f32, controls: bool, inspector: bool, first: Side) -> Fits {
    let wanted = usize::from(controls) + usize::from(inspector);
    let (mut c, mut i) = (
        if controls { Fit::Strip } else { Fit::Hidden },
        if inspector { Fit::Strip } else { Fit::Hidden },
    );
    if wanted == 2 && budget >= 2.0 * PANEL_MIN {
        // The controls (laid out first) leave the inspector its default width or a fair
        // share; the inspector may then take the rest.
        let reserve = INSPECTOR_DEFAULT
            .min(budget * INSPECTOR_SHARE)
            .max(PANEL_MIN);
        c = Fit::Open {
            max: (budget - reserve).max(PANEL_MIN),
        };
        i = Fit::Open {
            max: budget - PANEL_MIN,
        };
    } else if wanted > 0 {
        let strips = if wanted == 2 { STRIP } else { 0.0 };
        if budget - strips >= PANEL_MIN {
            let open = Fit::Open {
                max: budget - strips,
            };
            match (controls, inspector, first) {
                (true, true, Side::Controls) | (true, false, _) => c = open,
                _ => i = open,
            }
        }
    }
    Fits {
        controls: c,
        inspector: i,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_projector_keeps_half_the_window_for_the_canvas() {
        // 1024x768 with about 60 points of bars: room for one panel beside half the window.
        let b = budget([1024.0, 768.0], 708.0);
        assert!(b > PANEL_MIN + STRIP && b < 2.0 * PANEL_MIN, "{b}");
        let f = fits(b, true, true, Side::Inspector);
        assert_eq!(f.controls, Fit::Strip);
        assert!(matches!(f.inspector, Fit::Open { max } if max + STRIP <= b));
        // 1920x1080: both, each able to grow while the other keeps its narrowest.
        let b = budget([1920.0, 1080.0], 1020.0);
        let f = fits(b, true, true, Side::Inspector);
        assert!(matches!(f.controls, Fit::Open { max } if max + PANEL_MIN <= b));
        assert!(matches!(f.inspector, Fit::Open { max } if max + PANEL_MIN <= b));
        // Text size 2 halves the window in points: no room for either panel.
        let b = budget([512.0, 384.0], 324.0);
        let f = fits(b, true, true, Side::Inspector);
        assert_eq!((f.controls, f.inspector), (Fit::Strip, Fit::Strip));
        // Room for one: the one asked for last opens, the other is a strip.
        let f = fits(PANEL_MIN + STRIP + 10.0, true, true, Side::Controls);
        assert_eq!(f.inspector, Fit::Strip);
        assert!(matches!(f.controls, Fit::Open { .. }));
        // Text size 1.5 at 1024x768: the canvas's share leaves no room, but a panel the user
        // opens opens (the canvas gives way, keeping CANVAS_MIN_WIDTH), the other a strip.
        let (w, b) = (1024.0 / 1.5, budget([1024.0 / 1.5, 768.0 / 1.5], 440.0));
        assert_eq!(fits(b, true, true, Side::Inspector).inspector, Fit::Strip);
        for side in [Side::Controls, Side::Inspector] {
            let f = fits_forced(b, room(w), true, true, side, Some(side));
            let (open, other) = match side {
                Side::Controls => (f.controls, f.inspector),
                Side::Inspector => (f.inspector, f.controls),
            };
            assert!(
                matches!(open, Fit::Open { max } if max >= PANEL_MIN),
                "{f:?}"
            );
            assert_eq!(other, Fit::Strip);
        }
        // Text size 2: still each panel opens on request.
        let f = fits_forced(
            0.0,
            room(512.0),
            true,
            true,
            Side::Controls,
            Some(Side::Controls),
        );
        assert!(matches!(f.controls, Fit::Open { .. }), "{f:?}");
        // Not asked for: the canvas keeps its share.
        let f = fits_forced(b, room(w), true, true, Side::Inspector, None);
        assert_eq!((f.controls, f.inspector), (Fit::Strip, Fit::Strip));
        // Nothing wanted, nothing shown.
        let f = fits(1000.0, false, false, Side::Controls);
        assert_eq!((f.controls, f.inspector), (Fit::Hidden, Fit::Hidden));
    }
}
