//! Shading: turns an interpolated fragment into a colour.

use serde::{Deserialize, Serialize};

use super::interpolate::{Fragment, Interpolation};
use super::texture::{Filter, Texture, Wrap};

/// What the colour of a covered pixel shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Shading {
    /// The texture sampled at the interpolated uv.
    #[default]
    Texture,
    /// The interpolated vertex colour (red/green/blue corners).
    VertexColor,
    /// The source triangle's three weights as red, green, blue.
    Barycentric,
    /// Window depth z/w as grey: black at the nearest, white at the farthest drawn vertex.
    Depth,
}

/// Line colour of the wireframe overlay.
pub const WIRE_COLOR: [u8; 4] = [16, 16, 24, 255];

/// Wireframe line width inside each triangle, in pixels. The overlay thresholds the smallest
/// weight; the threshold for weight i is this width times the weight's screen
/// gradient, so lines keep one width on screen however close the triangle is.
pub const WIRE_WIDTH_PX: f64 = 1.0;

/// Distance in pixels from the sample to the nearest edge of the source triangle:
/// `min_i l_i / |grad l_i|`, with `l` the screen-linear source weights.
///
/// ```
/// use barylab::raster::shade::edge_distance_px;
/// use glam::DVec2;
/// // Weight 0.25 changing by 0.125 per pixel: 2 pixels from that edge; the weight 0.5
/// // changing by 0.0625 per pixel is 8 pixels from its edge; a zero gradient is ignored.
/// let g = [DVec2::new(0.125, 0.0), DVec2::new(0.0, 0.0625), DVec2::ZERO];
/// assert_eq!(edge_distance_px([0.25, 0.5, 0.25], &g), 2.0);
/// ```
pub fn edge_distance_px(weights: [f32; 3], gradients: &[glam::DVec2; 3]) -> f64 {
    let mut d = f64::INFINITY;
    for (w, g) in weights.iter().zip(gradients) {
        let len = g.length();
        if len > 0.0 {
            d = d.min(f64::from(*w) / len);
        }
    }
    d
}

/// Everything shading needs besides the fragment.
#[derive(Clone, Copy, Debug)]
pub struct ShadeParams {
    pub shading: Shading,
    pub mode: Interpolation,
    pub filter: Filter,
    pub wrap: Wrap,
    /// Draw the source triangles' edges (see [`WIRE_WIDTH_PX`]).
    pub wireframe: bool,
    /// Window depths mapped to black and white in [`Shading::Depth`].
    pub depth_range: (f64, f64),
}

/// Converts a [0, 1] channel to 8 bits, rounding to nearest (unorm8 conversion).
///
/// ```
/// use barylab::raster::shade::unorm8;
/// assert_eq!(unorm8(0.5), 128);
/// assert_eq!(unorm8(1.7), 255);
/// assert_eq!(unorm8(f32::NAN), 0);
/// ```
pub fn unorm8(x: f32) -> u8 {
    if x.is_nan() {
        return 0;
    }
    (x.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// The colour of one fragment. `wire_gradients` are the triangle's
/// [`TriangleSetup::source_weight_gradients`](super::setup::TriangleSetup::source_weight_gradients),
/// needed only when the wireframe is on.
pub fn shade(
    frag: &Fragment,
    texture: &Texture,
    p: &ShadeParams,
    wire_gradients: &[glam::DVec2; 3],
) -> [u8; 4] {
    if p.wireframe && edge_distance_px(frag.edge_weights, wire_gradients) < WIRE_WIDTH_PX {
        return WIRE_COLOR;
    }
    let v = frag.varyings(p.mode);
    let bary = v.bary();
    match p.shading {
        Shading::Texture => texture.sample_rgba8(v.uv(), p.filter, p.wrap, frag.lod),
        Shading::VertexColor => {
            let c = v.color();
            [unorm8(c.x), unorm8(c.y), unorm8(c.z), 255]
        }
        Shading::Barycentric => [unorm8(bary[0]), unorm8(bary[1]), unorm8(bary[2]), 255],
        Shading::Depth => {
            let (lo, hi) = p.depth_range;
            let g = if hi > lo {
                ((frag.depth - lo) / (hi - lo)) as f32
            } else {
                0.0
            };
            let g = unorm8(g);
            [g, g, g, 255]
        }
    }
}
