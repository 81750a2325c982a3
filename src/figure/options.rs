//! What a figure shows and how large it is drawn: [`FigureOptions`], the background, the
//! scales, and the layout sizes (margin, gap, title strip) in points.

use serde::{Deserialize, Serialize};

use super::Compare;
use super::overlay;

/// The image's background on a white figure.
pub(super) const WHITE: [u8; 4] = [255, 255, 255, 255];

/// The figure's background outside the image (title strip, margins, gap); a white figure
/// (for print) draws the image on white too.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Background {
    #[default]
    /// Nothing around the image (and the image keeps the scene's background).
    Transparent,
    /// White around the image and behind it, for print.
    White,
}

/// The image's own background in a figure: white on a white figure (no dark block around
/// the quad on paper), else the scene's `scene_background`.
pub fn image_background(background: Background, scene_background: [u8; 4]) -> [u8; 4] {
    match background {
        Background::White => WHITE,
        Background::Transparent => scene_background,
    }
}

/// Scales a figure can be exported at.
pub const SCALES: [u32; 3] = [1, 2, 4];

/// What a figure shows, as the canvas does: the view settings and the marked pixels.
#[derive(Clone, Debug, PartialEq)]
pub struct FigureOptions {
    /// One view, side by side, wipe or difference.
    pub compare: Compare,
    /// Figure points per rendered pixel (the canvas's pixel size).
    pub pixel_size: u32,
    /// Wipe line position as a fraction of the image width.
    pub wipe: f32,
    /// Draw the pixel grid (from pixel size [`overlay::GRID_FROM_PIXEL_SIZE`]).
    pub show_grid: bool,
    /// Draw the vertex handles with their w.
    pub show_handles: bool,
    /// Draw the marked pixel's sub-triangles.
    pub show_sub_areas: bool,
    /// The pinned pixel (marker, triangle and sub-triangles; its derivation is exported).
    pub pinned: Option<[u32; 2]>,
    /// The hovered pixel (marker with crosshair).
    pub hovered: Option<[u32; 2]>,
    /// PNG pixels per figure point: 1, 2 or 4.
    pub scale: u32,
    /// The background around (and on a white figure behind) the image.
    pub background: Background,
    /// Figure points per overlay point: the screen's pixels per point (the app's text size
    /// times the display's scale). Labels, lines, handles, the title strip and the margins
    /// are this much larger, so the figure looks as the canvas did on screen.
    pub overlay_scale: f32,
    /// A caption below the views with the pinned (else hovered) pixel's key numbers
    /// ([`super::caption`]); none when no pixel is marked.
    pub caption: bool,
}

impl Default for FigureOptions {
    fn default() -> Self {
        Self {
            compare: Compare::Single,
            pixel_size: 1,
            wipe: 0.5,
            show_grid: true,
            show_handles: true,
            show_sub_areas: true,
            pinned: None,
            hovered: None,
            scale: 1,
            background: Background::Transparent,
            overlay_scale: 1.0,
            caption: false,
        }
    }
}

impl FigureOptions {
    /// The `barylab figure` options that make this figure (after the scene file; before
    /// `-o`). Defaults are left out.
    ///
    /// ```
    /// use barylab::figure::{Background, Compare, FigureOptions};
    /// let o = FigureOptions {
    ///     compare: Compare::SideBySide,
    ///     pinned: Some([3, 4]),
    ///     scale: 2,
    ///     background: Background::White,
    ///     show_grid: false,
    ///     ..FigureOptions::default()
    /// };
    /// assert_eq!(o.cli_args().join(" "),
    ///            "--pixel 3,4 --compare side --scale 2 --background white --no-grid");
    /// ```
    pub fn cli_args(&self) -> Vec<String> {
        let mut a: Vec<String> = Vec::new();
        let mut push = |k: &str, v: String| {
            a.push(k.to_string());
            a.push(v);
        };
        if let Some([x, y]) = self.pinned {
            push("--pixel", format!("{x},{y}"));
        }
        if let Some([x, y]) = self.hovered {
            push("--hover", format!("{x},{y}"));
        }
        let compare = match self.compare {
            Compare::Single => None,
            Compare::SideBySide => Some("side"),
            Compare::Wipe => Some("wipe"),
            Compare::Difference => Some("diff"),
        };
        if let Some(c) = compare {
            push("--compare", c.to_string());
        }
        if self.compare == Compare::Wipe && self.wipe != 0.5 {
            push("--wipe", format!("{}", self.wipe));
        }
        if self.scale != 1 {
            push("--scale", self.scale.to_string());
        }
        if self.pixel_size != 1 {
            push("--pixel-size", self.pixel_size.to_string());
        }
        if self.overlay_scale != 1.0 {
            push("--overlay-scale", format!("{}", self.overlay_scale));
        }
        if self.background == Background::White {
            push("--background", "white".to_string());
        }
        if self.caption {
            a.push("--caption".to_string());
        }
        for (shown, flag) in [
            (self.show_grid, "--no-grid"),
            (self.show_handles, "--no-handles"),
            (self.show_sub_areas, "--no-sub-areas"),
        ] {
            if !shown {
                a.push(flag.to_string());
            }
        }
        a
    }
}

/// Overlay points of margin around each view: a handle on the image's edge (radius
/// [`overlay::HANDLE_RADIUS`] + its outline) is drawn whole.
pub const FIGURE_MARGIN: u32 = 16;
/// Overlay points between the two views of the side-by-side comparison (as on screen).
pub const SIDE_BY_SIDE_GAP: u32 = 10;
/// Range of [`FigureOptions::overlay_scale`] (the app's text size range times a HiDPI
/// display's 2).
pub const OVERLAY_SCALE_RANGE: (f32, f32) = (0.5, 5.0);

/// The figure's margin, side-by-side gap and title strip in figure points for an overlay
/// scale `k`: `round(k * points)` each.
///
/// ```
/// assert_eq!(barylab::figure::layout_points(1.5), [24, 15, 66]);
/// ```
pub fn layout_points(k: f32) -> [u32; 3] {
    [
        FIGURE_MARGIN as f32,
        SIDE_BY_SIDE_GAP as f32,
        overlay::TITLE_STRIP,
    ]
    .map(|v| (v * k).round() as u32)
}
/// Largest figure side in PNG pixels.
pub const MAX_FIGURE_SIZE: u32 = 16384;
