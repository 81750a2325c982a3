//! Shading: turns an interpolated fragment into a colour.

use glam::Vec3;
use serde::{Deserialize, Serialize};

use super::interpolate::{self, Derivatives, Fragment, Interpolation};
use super::setup::TriangleSetup;
use super::texture::{Filter, MaxAnisotropy, Texture, Wrap, lod};

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
    /// The interpolated view-space normal as colour, `(n̂ + 1) / 2` per channel (x red, y
    /// green, z blue): the first shader of GAMES101's assignment 3.
    Normal,
    /// A headlight Lambert shade: the vertex colour times
    /// `AMBIENT + (1 - AMBIENT) max(0, n̂ · l)`, with the light `l = (0, 0, 1)` in view space
    /// (at the eye, shining where the camera looks). See [`lambert_factor`].
    Lambert,
}

impl Shading {
    /// Every shading, in menu order.
    pub const ALL: [Shading; 6] = [
        Shading::Texture,
        Shading::VertexColor,
        Shading::Barycentric,
        Shading::Depth,
        Shading::Normal,
        Shading::Lambert,
    ];
}

/// The light a [`Shading::Lambert`] surface gets however it faces (so back-facing and grazing
/// parts stay visible as a dark silhouette instead of black).
pub const AMBIENT: f32 = 0.15;

/// An interpolated normal shorter than this is not a direction: the vertex normals cancel (a
/// fold) or the scene has none (clip-space scenes carry zero normals). It is read as facing
/// the viewer. Interpolated unit normals are at least `cos(θ/2)` long for an angle `θ`
/// between them, so only near-opposite normals come this close to zero.
pub const MIN_NORMAL_LENGTH: f32 = 1e-6;

/// The interpolated normal scaled to unit length, `n / |n|`; `(0, 0, 1)` (facing the viewer)
/// when it is shorter than [`MIN_NORMAL_LENGTH`] or not finite.
///
/// ```
/// use barylab::raster::shade::unit_normal;
/// use glam::Vec3;
/// assert_eq!(unit_normal(Vec3::new(0.0, 3.0, 4.0)), Vec3::new(0.0, 0.6, 0.8));
/// assert_eq!(unit_normal(Vec3::ZERO), Vec3::Z);
/// ```
pub fn unit_normal(n: Vec3) -> Vec3 {
    let len = n.length();
    if len.is_finite() && len >= MIN_NORMAL_LENGTH {
        n / len
    } else {
        Vec3::Z
    }
}

/// The normal as a colour before conversion to 8 bits: `(n̂ + 1) / 2` per channel, for a unit
/// normal `n̂` ([`unit_normal`]), each channel in [0, 1].
///
/// ```
/// use barylab::raster::shade::normal_colour;
/// use glam::Vec3;
/// assert_eq!(normal_colour(Vec3::Z), Vec3::new(0.5, 0.5, 1.0));
/// ```
pub fn normal_colour(unit: Vec3) -> Vec3 {
    (unit + Vec3::ONE) * 0.5
}

/// The colour of [`Shading::Normal`]: `unorm8((n̂ + 1) / 2)` per channel, opaque.
///
/// ```
/// use barylab::raster::shade::normal_rgba8;
/// use glam::Vec3;
/// // Facing the viewer: (0, 0, 1) -> (0.5, 0.5, 1), the familiar lilac-blue.
/// assert_eq!(normal_rgba8(Vec3::Z), [128, 128, 255, 255]);
/// ```
pub fn normal_rgba8(n: Vec3) -> [u8; 4] {
    let c = normal_colour(unit_normal(n));
    [unorm8(c.x), unorm8(c.y), unorm8(c.z), 255]
}

/// The brightness of [`Shading::Lambert`]: `AMBIENT + (1 - AMBIENT) max(0, n̂ · l)` with the
/// headlight `l = (0, 0, 1)`, so `n̂ · l = n̂.z`.
///
/// ```
/// use barylab::raster::shade::{AMBIENT, lambert_factor};
/// use glam::Vec3;
/// assert_eq!(lambert_factor(Vec3::Z), 1.0);
/// assert_eq!(lambert_factor(Vec3::NEG_Z), AMBIENT);
/// // Tilted 60 degrees away from the light: cos 60 = 0.5.
/// let f = lambert_factor(Vec3::new(60f32.to_radians().sin(), 0.0, 0.5));
/// assert!((f - (AMBIENT + (1.0 - AMBIENT) * 0.5)).abs() < 1e-6);
/// ```
pub fn lambert_factor(n: Vec3) -> f32 {
    AMBIENT + (1.0 - AMBIENT) * unit_normal(n).z.max(0.0)
}

/// The colour of [`Shading::Lambert`]: `unorm8(albedo * lambert_factor(n))`, opaque.
pub fn lambert_rgba8(albedo: Vec3, n: Vec3) -> [u8; 4] {
    let c = albedo * lambert_factor(n);
    [unorm8(c.x), unorm8(c.y), unorm8(c.z), 255]
}

/// Line colour of the wireframe overlay: light, so it shows on dark textures and backgrounds.
pub const WIRE_COLOR: [u8; 4] = [250, 250, 250, 255];
/// Colour of the wireframe's halo, the dark border along the inner side of each line, so the
/// line also shows on light textures.
pub const WIRE_HALO_COLOR: [u8; 4] = [16, 16, 24, 255];

/// Wireframe line width inside each triangle, in pixels. The overlay thresholds the smallest
/// weight; the threshold for weight i is this width times the weight's screen
/// gradient, so lines keep one width on screen however close the triangle is.
pub const WIRE_WIDTH_PX: f64 = 1.0;

/// Width of the halo in pixels, beyond the line: samples from [`WIRE_WIDTH_PX`] up to
/// `WIRE_WIDTH_PX + WIRE_HALO_PX` from an edge take [`WIRE_HALO_COLOR`]. Only the colour of
/// covered pixels changes: coverage, depth and every interpolated value stay as they are.
pub const WIRE_HALO_PX: f64 = 1.0;

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

/// The wireframe test for one source-triangle weight: the sample is on the line when the
/// weight changes on screen (`len = |grad l| > 0`, per pixel) and `weight / len`, its distance
/// in pixels from that edge, is below [`WIRE_WIDTH_PX`]. The weight is the `f32` the varyings
/// hold. (The AVX2 lanes repeat this test; `tests/fast_path.rs` compares them bit for bit.)
///
/// ```
/// use barylab::raster::shade::on_wire_edge;
/// assert!(on_wire_edge(0.05, 0.1)); // half a pixel from the edge
/// assert!(!on_wire_edge(0.5, 0.1)); // five pixels away
/// assert!(!on_wire_edge(0.0, 0.0)); // a weight that does not change has no edge here
/// ```
#[inline(always)]
pub fn on_wire_edge(weight: f32, len: f64) -> bool {
    len > 0.0 && f64::from(weight) / len < WIRE_WIDTH_PX
}

/// The halo test, as [`on_wire_edge`] with the line widened by [`WIRE_HALO_PX`]: the sample
/// is on the line or its halo. (The AVX2 lanes repeat it; `tests/fast_path.rs` compares them
/// bit for bit.)
///
/// ```
/// use barylab::raster::shade::on_wire_halo;
/// assert!(on_wire_halo(0.15, 0.1)); // 1.5 pixels from the edge: in the halo
/// assert!(!on_wire_halo(0.25, 0.1)); // 2.5 pixels away
/// ```
#[inline(always)]
pub fn on_wire_halo(weight: f32, len: f64) -> bool {
    len > 0.0 && f64::from(weight) / len < WIRE_WIDTH_PX + WIRE_HALO_PX
}

/// What the wireframe paints at a sample.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum WirePaint {
    /// Nothing: the shading's own colour.
    None,
    /// The line ([`WIRE_COLOR`]).
    Line,
    /// The halo along the line ([`WIRE_HALO_COLOR`]).
    Halo,
}

impl WirePaint {
    /// The paint for a sample with source weights `weights` (the `f32`s the varyings hold)
    /// whose screen gradients have lengths `lens`: the line when [`on_wire_edge`] holds for
    /// one weight, else the halo when [`on_wire_halo`] does.
    ///
    /// ```
    /// use barylab::raster::shade::WirePaint;
    /// let lens = [0.1, 0.1, 0.1];
    /// assert_eq!(WirePaint::of([0.05, 0.5, 0.45], lens), WirePaint::Line);
    /// assert_eq!(WirePaint::of([0.15, 0.5, 0.35], lens), WirePaint::Halo);
    /// assert_eq!(WirePaint::of([0.3, 0.4, 0.3], lens), WirePaint::None);
    /// ```
    pub fn of(weights: [f32; 3], lens: [f64; 3]) -> Self {
        if (0..3).any(|i| on_wire_edge(weights[i], lens[i])) {
            WirePaint::Line
        } else if (0..3).any(|i| on_wire_halo(weights[i], lens[i])) {
            WirePaint::Halo
        } else {
            WirePaint::None
        }
    }

    /// The colour painted over the shading, if any.
    pub fn color(self) -> Option<[u8; 4]> {
        match self {
            WirePaint::None => None,
            WirePaint::Line => Some(WIRE_COLOR),
            WirePaint::Halo => Some(WIRE_HALO_COLOR),
        }
    }
}

/// The grey of [`Shading::Depth`]: window depth `d` mapped from `range = (black, white)` to
/// 8 bits, `unorm8((d - black) / (white - black))`; black when the range is empty. (The AVX2
/// lanes repeat it; compared bit for bit by `tests/fast_path.rs`.)
///
/// ```
/// use barylab::raster::shade::depth_grey;
/// assert_eq!(depth_grey(0.75, (0.5, 1.0)), 128);
/// assert_eq!(depth_grey(0.75, (1.0, 1.0)), 0);
/// ```
#[inline(always)]
pub fn depth_grey(depth: f64, (black, white): (f64, f64)) -> u8 {
    let g = if white > black {
        ((depth - black) / (white - black)) as f32
    } else {
        0.0
    };
    unorm8(g)
}

/// Everything shading needs besides the fragment.
#[derive(Clone, Copy, Debug)]
pub struct ShadeParams {
    /// What the colour is made from.
    pub shading: Shading,
    /// Which of the fragment's interpolated values are used: affine or perspective-correct.
    pub mode: Interpolation,
    /// Texture filter.
    pub filter: Filter,
    /// Texture wrap mode.
    pub wrap: Wrap,
    /// Draw the source triangles' edges (see [`WIRE_WIDTH_PX`]).
    pub wireframe: bool,
    /// Window depths mapped to black and white in [`Shading::Depth`].
    pub depth_range: (f64, f64),
    /// The sampler's largest anisotropy (anisotropic filtering when above 1 with trilinear).
    pub max_anisotropy: MaxAnisotropy,
}

impl ShadeParams {
    /// The largest anisotropy when texture lookups filter anisotropically: trilinear
    /// filtering with `max_anisotropy` above 1.
    pub fn anisotropy(&self) -> Option<MaxAnisotropy> {
        (self.filter == Filter::Trilinear && self.max_anisotropy.is_on())
            .then_some(self.max_anisotropy)
    }
}

/// The texture's colour at `uv` for fragment `frag` (its level of detail and derivatives,
/// [`texture_footprint`]): anisotropic when [`ShadeParams::anisotropy`] says so, else the
/// filter's lookup.
pub fn texture_color(
    texture: &Texture,
    uv: glam::Vec2,
    frag: &Fragment,
    p: &ShadeParams,
) -> [u8; 4] {
    match p.anisotropy() {
        Some(max) => texture.sample_anisotropic_rgba8(uv, p.wrap, frag.duv, max),
        None => texture.sample_rgba8(uv, p.filter, p.wrap, frag.lod),
    }
}

/// Sets what a texture lookup at pixel (x, y) needs beyond the uv: with trilinear filtering
/// the level of detail of its 2x2 quad ([`interpolate::quad_lod`]'s, from coarse
/// derivatives), and with anisotropic filtering the derivatives too. The renderer (one sample
/// or many) and the probe call this.
pub fn texture_footprint(
    frag: &mut Fragment,
    setup: &TriangleSetup,
    (x, y): (u32, u32),
    p: &ShadeParams,
    texture: &Texture,
) {
    if p.filter != Filter::Trilinear {
        return;
    }
    let (w, h) = (texture.width(), texture.height());
    let duv = interpolate::quad_derivatives(setup, (x, y), p.mode, Derivatives::Coarse);
    frag.duv = duv.unwrap_or([glam::Vec2::ZERO; 2]);
    frag.lod = duv.map_or(0.0, |[dx, dy]| lod(dx, dy, w, h));
}

/// The depth range [`Shading::Depth`] maps to black and white: the smallest and largest of
/// `depths` (the window depths of the drawn triangles' vertices), or (0, 1) when there are
/// none. The full render and the fast path both pass their drawn vertices here.
///
/// ```
/// use barylab::raster::shade::depth_range;
/// assert_eq!(depth_range([0.5, 0.25, 0.75]), (0.25, 0.75));
/// assert_eq!(depth_range([]), (0.0, 1.0));
/// ```
pub fn depth_range(depths: impl IntoIterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = depths
        .into_iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), d| {
            (lo.min(d), hi.max(d))
        });
    if lo <= hi { (lo, hi) } else { (0.0, 1.0) }
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
    crate::raster::texture::round_byte(x.clamp(0.0, 1.0) * 255.0)
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
    if p.wireframe
        && let Some(c) =
            WirePaint::of(frag.edge_weights, wire_gradients.map(|g| g.length())).color()
    {
        return c;
    }
    let v = frag.varyings(p.mode);
    let bary = v.bary();
    match p.shading {
        Shading::Texture => texture_color(texture, v.uv(), frag, p),
        Shading::VertexColor => {
            let c = v.color();
            [unorm8(c.x), unorm8(c.y), unorm8(c.z), 255]
        }
        Shading::Barycentric => [unorm8(bary[0]), unorm8(bary[1]), unorm8(bary[2]), 255],
        Shading::Depth => {
            let g = depth_grey(frag.depth, p.depth_range);
            [g, g, g, 255]
        }
        Shading::Normal => normal_rgba8(v.normal()),
        Shading::Lambert => lambert_rgba8(v.color(), v.normal()),
    }
}
