//! The space view's own camera (not the scene's): it orbits the scene's bounding sphere,
//! and projects 3D points to the 2D drawing area.

use glam::DVec3;

/// The orbit camera's angles and zoom. Yaw turns about the vertical (y) axis, from behind
/// the scene camera (yaw 0: looking down -z like it) towards its right; pitch raises it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orbit {
    /// Degrees about the y axis.
    pub yaw_deg: f64,
    /// Degrees above the horizontal, within [`PITCH_LIMIT`].
    pub pitch_deg: f64,
    /// Magnification of the drawing, within [`ZOOM_RANGE`] (1: the scene just fits).
    pub zoom: f64,
}

/// The pitch is kept within `-PITCH_LIMIT..=PITCH_LIMIT` degrees (the up vector stays defined).
pub const PITCH_LIMIT: f64 = 85.0;

/// The zoom's range.
pub const ZOOM_RANGE: (f64, f64) = (0.25, 8.0);

/// The orbit camera's vertical field of view, degrees.
const ORBIT_FOV_DEG: f64 = 40.0;

impl Default for Orbit {
    /// From the right of the scene camera and above: the eye, the frustum and the quad all
    /// show, the ray seen from its side.
    fn default() -> Self {
        Self {
            yaw_deg: 40.0,
            pitch_deg: 28.0,
            zoom: 1.0,
        }
    }
}

impl Orbit {
    /// Turned by `d_yaw` and `d_pitch` degrees (the pitch clamped).
    pub fn turned(self, d_yaw: f64, d_pitch: f64) -> Self {
        Self {
            yaw_deg: (self.yaw_deg + d_yaw).rem_euclid(360.0),
            pitch_deg: (self.pitch_deg + d_pitch).clamp(-PITCH_LIMIT, PITCH_LIMIT),
            ..self
        }
    }

    /// Zoomed by the factor `f` (clamped to [`ZOOM_RANGE`]).
    pub fn zoomed(self, f: f64) -> Self {
        let z = self.zoom * f;
        Self {
            zoom: if z.is_finite() {
                z.clamp(ZOOM_RANGE.0, ZOOM_RANGE.1)
            } else {
                self.zoom
            },
            ..self
        }
    }
}

/// Projects 3D points to a 2D rectangle for one orbit and one scene.
///
/// The camera sits at `centre + dist (cos p sin y, sin p, cos p cos y)`, looking at the centre
/// of the points' bounding sphere (radius `R`), with `dist = 1.05 R / sin(fov / 2)`, so every
/// point of the sphere is in front of it; a point `q` relative to the camera, in its basis
/// (right, up, forward), lands at `centre_2d + focal zoom (x / z, -y / z)`,
/// `focal = min(width, height) / (2 tan(fov / 2))`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projector {
    eye: DVec3,
    right: DVec3,
    up: DVec3,
    forward: DVec3,
    centre_2d: [f64; 2],
    focal: f64,
    rect: [f32; 4],
}

impl Projector {
    /// The projector of `orbit` for `points` (the scene's), drawing into `rect`
    /// (`[min_x, min_y, max_x, max_y]`, y down).
    pub fn new(orbit: Orbit, points: &[DVec3], rect: [f32; 4]) -> Self {
        let finite = || points.iter().filter(|p| p.is_finite());
        let (lo, hi) = finite().fold(
            (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
            |(lo, hi), p| (lo.min(*p), hi.max(*p)),
        );
        let (centre, radius) = if lo.x <= hi.x {
            ((lo + hi) / 2.0, ((hi - lo).length() / 2.0).max(1e-9))
        } else {
            (DVec3::ZERO, 1.0)
        };
        let half_fov = (ORBIT_FOV_DEG / 2.0).to_radians();
        let (yaw, pitch) = (
            orbit.yaw_deg.to_radians(),
            orbit
                .pitch_deg
                .clamp(-PITCH_LIMIT, PITCH_LIMIT)
                .to_radians(),
        );
        let towards_eye = DVec3::new(
            pitch.cos() * yaw.sin(),
            pitch.sin(),
            pitch.cos() * yaw.cos(),
        );
        let eye = centre + towards_eye * (1.05 * radius / half_fov.sin());
        let forward = -towards_eye;
        let right = forward.cross(DVec3::Y).normalize();
        let up = right.cross(forward);
        let [x0, y0, x1, y1] = rect.map(f64::from);
        let focal = orbit.zoom * (x1 - x0).min(y1 - y0) / (2.0 * half_fov.tan());
        Self {
            eye,
            right,
            up,
            forward,
            centre_2d: [(x0 + x1) / 2.0, (y0 + y1) / 2.0],
            focal,
            rect,
        }
    }

    /// The drawing area, `[min_x, min_y, max_x, max_y]`.
    pub fn rect(&self) -> [f32; 4] {
        self.rect
    }

    /// Where `p` is drawn, and its distance along the orbit camera's forward axis (larger is
    /// farther; the painter's order). Points at or behind the orbit camera are put just in
    /// front of it.
    pub fn project(&self, p: DVec3) -> ([f32; 2], f64) {
        let q = p - self.eye;
        let z = q.dot(self.forward).max(1e-9);
        let (x, y) = (q.dot(self.right), q.dot(self.up));
        (
            [
                (self.centre_2d[0] + self.focal * x / z) as f32,
                (self.centre_2d[1] - self.focal * y / z) as f32,
            ],
            z,
        )
    }
}
