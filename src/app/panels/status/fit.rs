//! Which parts of the status line fit its width. The line never wraps (the timings change
//! every frame, and a status line that changed height would move the canvas and re-render
//! it), so at narrow widths it drops or shortens its less important parts first: the
//! render/upload/ui timings (kept in the frame time's tooltip), then the F1 hint, then the
//! canvas's long form. The mode, the canvas size with its pixel scale and the frame time stay.

/// The status line's texts, long and short forms; widths come from a `measure` function so
/// the choice is pure arithmetic (in points).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct StatusTexts {
    /// The GPU view's badge, when it is on.
    pub gpu: Option<String>,
    /// The mode or the comparison.
    pub mode: String,
    /// The canvas's size and pixel scale: long and short form.
    pub canvas: Option<[String; 2]>,
    /// All the timings, and the frame time alone.
    pub timings: [String; 2],
    /// A message (it is elided to what is left, but keeps at least [`MESSAGE_MIN`]).
    pub message: Option<String>,
    /// The F1 hint at the right end.
    pub help: String,
}

/// What the status line shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Shown {
    /// All the timings (else the frame time alone, the others in its tooltip).
    pub all_timings: bool,
    /// The F1 hint.
    pub help: bool,
    /// The canvas's long form.
    pub long_canvas: bool,
}

/// Points a message keeps at the least (the rest of it is elided, and shown on hover).
pub(crate) const MESSAGE_MIN: f32 = 120.0;

/// Points of room kept spare, for rounding and the frame time's digits changing.
const SLACK: f32 = 12.0;

impl StatusTexts {
    /// The richest form that fits in `width` points: `gap` is the space between two items,
    /// `separator` what a separator takes besides its gaps.
    pub(crate) fn fit(
        &self,
        width: f32,
        gap: f32,
        separator: f32,
        measure: impl Fn(&str) -> f32,
    ) -> Shown {
        let forms = [
            Shown {
                all_timings: true,
                help: true,
                long_canvas: true,
            },
            Shown {
                all_timings: false,
                help: true,
                long_canvas: true,
            },
            Shown {
                all_timings: false,
                help: false,
                long_canvas: true,
            },
        ];
        let leanest = Shown {
            all_timings: false,
            help: false,
            long_canvas: false,
        };
        forms
            .into_iter()
            .find(|s| self.width(*s, gap, separator, &measure) + SLACK <= width)
            .unwrap_or(leanest)
    }

    /// Points the line takes in form `s`.
    pub(crate) fn width(
        &self,
        s: Shown,
        gap: f32,
        separator: f32,
        measure: impl Fn(&str) -> f32,
    ) -> f32 {
        let mut items: Vec<f32> = Vec::new();
        let mut separators = 0;
        if let Some(g) = &self.gpu {
            items.push(measure(g));
        }
        items.push(measure(&self.mode));
        separators += 1;
        if let Some([long, short]) = &self.canvas {
            items.push(measure(if s.long_canvas { long } else { short }));
            separators += 1;
        }
        items.push(measure(&self.timings[usize::from(!s.all_timings)]));
        if let Some(m) = &self.message {
            separators += 1;
            items.push(measure(m).min(MESSAGE_MIN));
        }
        if s.help {
            items.push(measure(&self.help));
        }
        let n = items.len() + separators;
        items.iter().sum::<f32>() + separators as f32 * separator + n.saturating_sub(1) as f32 * gap
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn texts(message: Option<&str>) -> StatusTexts {
        StatusTexts {
            gpu: None,
            mode: "PERSPECTIVE-CORRECT".into(),
            canvas: Some(["canvas 800×600 at 0.97×".into(), "800×600 @ 0.97×".into()]),
            timings: [
                "render (edge functions) 1.6 ms · upload 0.3 ms · ui 1.2 ms · frame 4.0 ms".into(),
                "frame 4.0 ms".into(),
            ],
            message: message.map(str::to_string),
            help: "F1: help".into(),
        }
    }

    /// Eight points a character: a rough but monotone measure.
    fn measure(s: &str) -> f32 {
        8.0 * s.chars().count() as f32
    }

    #[test]
    fn the_less_important_parts_go_first() {
        let t = texts(None);
        let full = t.width(t.fit(10_000.0, 8.0, 7.0, measure), 8.0, 7.0, measure);
        assert!(t.fit(10_000.0, 8.0, 7.0, measure).all_timings);
        // A bit narrower: the timings go to the tooltip, the rest stays.
        let s = t.fit(full - 1.0, 8.0, 7.0, measure);
        assert!(!s.all_timings && s.help && s.long_canvas, "{s:?}");
        // Narrower still: the F1 hint goes, then the canvas's long form.
        let no_help = t.width(
            Shown {
                all_timings: false,
                help: false,
                long_canvas: true,
            },
            8.0,
            7.0,
            measure,
        );
        let s = t.fit(no_help + SLACK, 8.0, 7.0, measure);
        assert!(!s.help && s.long_canvas, "{s:?}");
        let s = t.fit(no_help + SLACK - 1.0, 8.0, 7.0, measure);
        assert!(!s.help && !s.long_canvas, "{s:?}");
    }

    #[test]
    fn a_long_message_counts_only_what_it_keeps() {
        let short = texts(None);
        let long = texts(Some(&"x".repeat(500)));
        let w = 600.0;
        let a = short.fit(w, 8.0, 7.0, measure);
        let b = long.fit(w + MESSAGE_MIN + 15.0, 8.0, 7.0, measure);
        assert_eq!(a, b);
    }
}
