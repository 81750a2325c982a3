//! What the canvas compares: one view, side by side, the wipe or the difference heatmap, the
//! views and renders each needs, and the wipe line's pixels.

use serde::{Deserialize, Serialize};

use crate::raster::Interpolation;

/// How the canvas compares the two interpolation modes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Compare {
    /// One view in the scene's mode.
    #[default]
    Single,
    /// Affine on the left, perspective-correct on the right, same view.
    SideBySide,
    /// One view split by a draggable line: affine left of it, perspective-correct right.
    Wipe,
    /// |uv affine - uv perspective| in texels as a heatmap.
    Difference,
}

impl Compare {
    /// Every comparison, in the order the app offers them.
    pub const ALL: [Compare; 4] = [
        Compare::Single,
        Compare::SideBySide,
        Compare::Wipe,
        Compare::Difference,
    ];
}

/// What one view of the canvas shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ViewContent {
    /// The render in one interpolation mode.
    Mode(Interpolation),
    /// The wipe: affine left of the line, perspective-correct right of it.
    Wipe,
    /// The difference heatmap in texels.
    Difference,
}

/// The views a comparison shows, left to right; `mode` is the scene's mode.
pub fn view_contents(compare: Compare, mode: Interpolation) -> Vec<ViewContent> {
    match compare {
        Compare::Single => vec![ViewContent::Mode(mode)],
        Compare::SideBySide => vec![
            ViewContent::Mode(Interpolation::Affine),
            ViewContent::Mode(Interpolation::Perspective),
        ],
        Compare::Wipe => vec![ViewContent::Wipe],
        Compare::Difference => vec![ViewContent::Difference],
    }
}

/// The modes a comparison needs rendered (`mode`: the scene's).
pub fn modes_for(compare: Compare, mode: Interpolation) -> Vec<Interpolation> {
    match compare {
        Compare::Single | Compare::Difference => vec![mode],
        Compare::SideBySide | Compare::Wipe => {
            vec![Interpolation::Affine, Interpolation::Perspective]
        }
    }
}

/// The wipe line's column: affine left of it, perspective-correct from it on.
///
/// `column = round(wipe * width)`.
///
/// ```
/// assert_eq!(barylab::figure::wipe_column(0.5, 801), 401);
/// ```
pub fn wipe_column(wipe: f32, width: u32) -> u32 {
    (wipe.clamp(0.0, 1.0) * width as f32).round() as u32
}

/// The wipe view's pixels: the affine image left of `column`, the perspective-correct one from
/// it on (both `width` pixels wide, row by row).
pub fn wipe_pixels(
    affine: &[[u8; 4]],
    perspective: &[[u8; 4]],
    width: u32,
    column: u32,
) -> Vec<[u8; 4]> {
    let row = width as usize;
    affine
        .iter()
        .zip(perspective)
        .enumerate()
        .map(|(k, (ca, cp))| {
            if ((k % row) as u32) < column {
                *ca
            } else {
                *cp
            }
        })
        .collect()
}
