//! Per-vertex attributes ("varyings"), interpolated by one code path.
//!
//! Every attribute is a slot in a small fixed-size `f32` array, so clipping and interpolation
//! treat them all alike. The first three slots hold the vertex's barycentric coordinates with
//! respect to the *source* triangle (one-hot at the original vertices); they survive clipping
//! and so give the weights of the original triangle A, B, C at every pixel.

use glam::{Vec2, Vec3};

/// Number of `f32` attribute slots carried by every vertex.
pub const NUM_VARYINGS: usize = 11;
/// First slot of the barycentric coordinates with respect to the source triangle (3 slots).
pub const SLOT_BARY: usize = 0;
/// First slot of the texture coordinate (u, v).
pub const SLOT_UV: usize = 3;
/// First slot of the RGB vertex colour, each channel in [0, 1].
pub const SLOT_COLOR: usize = 5;
/// First slot of the view-space vertex normal (x right, y up, z towards the viewer; unit
/// length at the vertices, zero when the scene has none).
pub const SLOT_NORMAL: usize = 8;

/// The attribute slots of one vertex or one fragment.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Varyings(pub [f32; NUM_VARYINGS]);

impl Varyings {
    /// Packs the named attributes into slots.
    pub fn new(bary: [f32; 3], uv: Vec2, color: Vec3) -> Self {
        let mut s = [0.0; NUM_VARYINGS];
        s[SLOT_BARY..SLOT_BARY + 3].copy_from_slice(&bary);
        s[SLOT_UV] = uv.x;
        s[SLOT_UV + 1] = uv.y;
        s[SLOT_COLOR..SLOT_COLOR + 3].copy_from_slice(&color.to_array());
        Self(s)
    }

    /// The same attributes with the view-space `normal` in its slots.
    ///
    /// ```
    /// use barylab::raster::varying::Varyings;
    /// use glam::{Vec2, Vec3};
    /// let v = Varyings::new([1.0, 0.0, 0.0], Vec2::ZERO, Vec3::ONE).with_normal(Vec3::Z);
    /// assert_eq!(v.normal(), Vec3::Z);
    /// assert_eq!(v.color(), Vec3::ONE);
    /// ```
    pub fn with_normal(mut self, normal: Vec3) -> Self {
        self.0[SLOT_NORMAL..SLOT_NORMAL + 3].copy_from_slice(&normal.to_array());
        self
    }

    /// The same attributes with `uv` in its slots (the fragment's uv comes from its planes,
    /// [`Planes`](super::interpolate::Planes)).
    pub fn with_uv(mut self, uv: Vec2) -> Self {
        self.0[SLOT_UV] = uv.x;
        self.0[SLOT_UV + 1] = uv.y;
        self
    }

    /// The interpolated view-space normal (not renormalized: interpolation shortens it).
    pub fn normal(&self) -> Vec3 {
        Vec3::new(
            self.0[SLOT_NORMAL],
            self.0[SLOT_NORMAL + 1],
            self.0[SLOT_NORMAL + 2],
        )
    }

    /// Barycentric coordinates with respect to the source triangle.
    pub fn bary(&self) -> [f32; 3] {
        [
            self.0[SLOT_BARY],
            self.0[SLOT_BARY + 1],
            self.0[SLOT_BARY + 2],
        ]
    }

    /// Texture coordinate.
    pub fn uv(&self) -> Vec2 {
        Vec2::new(self.0[SLOT_UV], self.0[SLOT_UV + 1])
    }

    /// RGB colour in [0, 1].
    pub fn color(&self) -> Vec3 {
        Vec3::new(
            self.0[SLOT_COLOR],
            self.0[SLOT_COLOR + 1],
            self.0[SLOT_COLOR + 2],
        )
    }

    /// Linear interpolation on a segment: `a + t (b - a)` in every slot.
    ///
    /// ```
    /// use barylab::raster::varying::Varyings;
    /// use glam::{Vec2, Vec3};
    /// let a = Varyings::new([1.0, 0.0, 0.0], Vec2::new(0.0, 0.0), Vec3::ZERO);
    /// let b = Varyings::new([0.0, 1.0, 0.0], Vec2::new(1.0, 2.0), Vec3::ONE);
    /// let m = Varyings::lerp(&a, &b, 0.25);
    /// assert_eq!(m.uv(), Vec2::new(0.25, 0.5));
    /// assert_eq!(m.bary(), [0.75, 0.25, 0.0]);
    /// ```
    pub fn lerp(a: &Self, b: &Self, t: f64) -> Self {
        let mut s = [0.0; NUM_VARYINGS];
        for (i, out) in s.iter_mut().enumerate() {
            let (x, y) = (f64::from(a.0[i]), f64::from(b.0[i]));
            *out = (x + t * (y - x)) as f32;
        }
        Self(s)
    }

    /// Weighted sum `w0 v0 + w1 v1 + w2 v2` in every slot (the weights are expected to sum to 1).
    ///
    /// ```
    /// use barylab::raster::varying::Varyings;
    /// use glam::{Vec2, Vec3};
    /// let v = [
    ///     Varyings::new([1.0, 0.0, 0.0], Vec2::new(0.0, 0.0), Vec3::X),
    ///     Varyings::new([0.0, 1.0, 0.0], Vec2::new(1.0, 0.0), Vec3::Y),
    ///     Varyings::new([0.0, 0.0, 1.0], Vec2::new(0.0, 1.0), Vec3::Z),
    /// ];
    /// let f = Varyings::weighted(&[0.5, 0.25, 0.25], &v);
    /// assert_eq!(f.uv(), Vec2::new(0.25, 0.25));
    /// assert_eq!(f.color(), Vec3::new(0.5, 0.25, 0.25));
    /// ```
    pub fn weighted(w: &[f64; 3], v: &[Varyings; 3]) -> Self {
        let mut s = [0.0; NUM_VARYINGS];
        for (i, out) in s.iter_mut().enumerate() {
            *out = (w[0] * f64::from(v[0].0[i])
                + w[1] * f64::from(v[1].0[i])
                + w[2] * f64::from(v[2].0[i])) as f32;
        }
        Self(s)
    }
}
