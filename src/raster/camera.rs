//! Camera: the look-at view matrix and OpenGL projection matrices.
//!
//! Matrices are named by what they map: `view_from_world` takes world coordinates to the
//! camera's view space (right-handed, looking down -z), `clip_from_view` takes view space to
//! OpenGL clip space (-w <= x, y, z <= w inside the frustum).

use glam::dcamera::rh::proj::opengl;
use glam::dcamera::rh::view;
use glam::{DMat4, DVec2, DVec3, DVec4};
use serde::{Deserialize, Serialize};

use crate::files::number;

/// Errors for cameras that cannot form a valid projection.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CameraError {
    /// `eye == target`: no viewing direction.
    #[error("the camera's eye and target are the same point")]
    EyeIsTarget,
    /// `up` is zero or parallel to `target - eye`: the roll is undetermined.
    #[error("the camera's up vector is zero or parallel to the viewing direction")]
    BadUp,
    /// The vertical field of view, in degrees, is not in (0, 180).
    #[error("field of view {} degrees is outside (0, 180)", number(*.0))]
    BadFov(f64),
    /// The clip planes do not satisfy `0 < near < far`.
    #[error("near plane {} and far plane {} must satisfy 0 < near < far", number(*near), number(*far))]
    BadPlanes {
        /// Distance of the near plane in front of the eye, view units.
        near: f64,
        /// Distance of the far plane in front of the eye, view units.
        far: f64,
    },
    /// The orthographic view volume's height is not positive.
    #[error("orthographic height {} must be positive", number(*.0))]
    BadHeight(f64),
    /// Some camera value is NaN or infinite.
    #[error("camera value is not a finite number")]
    NotFinite,
    /// A value exceeds [`MAX_CAMERA_VALUE`] in magnitude.
    #[error(
        "camera {what} is {}, larger than {} in magnitude",
        number(*value),
        number(MAX_CAMERA_VALUE)
    )]
    TooLarge {
        /// Which value ("eye", "far plane", "orthographic height", ...).
        what: &'static str,
        /// The value given.
        value: f64,
    },
}

/// Largest accepted magnitude of a camera coordinate, near or far plane, or orthographic
/// height. Far beyond any classroom scene; past it the view and projection matrices square
/// or multiply values that overflow f64 or leave f32 depth without precision.
pub const MAX_CAMERA_VALUE: f64 = 1e12;

/// Where a camera framing a model looks from (the model's object axes: x right, y up, z
/// towards the front, as OBJ files are usually written).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ModelView {
    /// The view of GAMES101's assignment 3 (the model turned 140 degrees about y, seen from
    /// +z), from a little above: its models (spot, the bunny) face the viewer.
    #[default]
    Course,
    /// From +z.
    Front,
    /// From -z.
    Back,
    /// From -x.
    Left,
    /// From +x.
    Right,
    /// From +y, looking down (-z at the top of the image).
    Top,
}

impl ModelView {
    /// Every view, in menu order.
    pub const ALL: [ModelView; 6] = [
        ModelView::Course,
        ModelView::Front,
        ModelView::Back,
        ModelView::Left,
        ModelView::Right,
        ModelView::Top,
    ];

    /// The unit direction from the model's centre to the eye, and the camera's up vector.
    ///
    /// [`ModelView::Course`]: GAMES101 turns the model by `R_y(140 deg)` and looks from +z,
    /// which is looking from `R_y(-140 deg) (0, 0, 1) = (sin(-140 deg), 0, cos(-140 deg))` in
    /// the model's own axes; raised by [`COURSE_VIEW_ELEVATION`] so the top shows.
    pub fn eye_direction(self) -> (DVec3, DVec3) {
        let course = || {
            let a = (-140f64).to_radians();
            let h = DVec3::new(a.sin(), 0.0, a.cos());
            let e = COURSE_VIEW_ELEVATION.to_radians();
            h * e.cos() + DVec3::Y * e.sin()
        };
        match self {
            ModelView::Course => (course(), DVec3::Y),
            ModelView::Front => (DVec3::Z, DVec3::Y),
            ModelView::Back => (DVec3::NEG_Z, DVec3::Y),
            ModelView::Left => (DVec3::NEG_X, DVec3::Y),
            ModelView::Right => (DVec3::X, DVec3::Y),
            ModelView::Top => (DVec3::Y, DVec3::NEG_Z),
        }
    }
}

/// How far above the horizon [`ModelView::Course`] looks from, in degrees: enough to see a
/// model's top and depth, little enough to keep GAMES101's framing.
pub const COURSE_VIEW_ELEVATION: f64 = 20.0;

/// How view space is projected to clip space.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Projection {
    /// OpenGL perspective projection: clip w equals the view-space distance -z_view.
    Perspective {
        /// Vertical field of view in degrees.
        fov_y_deg: f64,
        /// Distance of the near plane in front of the eye (> 0), view units.
        near: f64,
        /// Distance of the far plane in front of the eye (> near), view units.
        far: f64,
    },
    /// Orthographic projection: clip w = 1 everywhere, so affine and perspective-correct agree.
    Orthographic {
        /// Height of the view volume in world units.
        height: f64,
        /// Distance of the near plane in front of the eye (> 0), view units.
        near: f64,
        /// Distance of the far plane in front of the eye (> near), view units.
        far: f64,
    },
}

/// A look-at camera.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Camera {
    /// The eye position, world space.
    pub eye: DVec3,
    /// The point looked at, world space: the view direction is `target - eye`.
    pub target: DVec3,
    /// The world direction that is up on screen; `[0, 1, 0]` when omitted.
    #[serde(default = "default_up")]
    pub up: DVec3,
    /// View -> clip.
    pub projection: Projection,
}

fn default_up() -> DVec3 {
    DVec3::Y
}

/// Smallest accepted |forward x up| relative to their lengths: below this the up vector
/// does not determine the camera's roll.
const MIN_UP_SINE: f64 = 1e-9;

impl Default for Camera {
    fn default() -> Self {
        Self {
            eye: DVec3::ZERO,
            target: DVec3::NEG_Z,
            up: DVec3::Y,
            projection: Projection::Perspective {
                fov_y_deg: 60.0,
                near: 0.1,
                far: 100.0,
            },
        }
    }
}

impl Camera {
    /// Checks that the camera forms a valid, invertible projection.
    pub fn validate(&self) -> Result<(), CameraError> {
        let finite = self.eye.is_finite() && self.target.is_finite() && self.up.is_finite();
        if !finite {
            return Err(CameraError::NotFinite);
        }
        let large = |what, v: DVec3| -> Result<(), CameraError> {
            match v
                .to_array()
                .into_iter()
                .find(|c| c.abs() > MAX_CAMERA_VALUE)
            {
                Some(value) => Err(CameraError::TooLarge { what, value }),
                None => Ok(()),
            }
        };
        large("eye", self.eye)?;
        large("target", self.target)?;
        large("up", self.up)?;
        let forward = self.target - self.eye;
        if forward.length_squared() == 0.0 {
            return Err(CameraError::EyeIsTarget);
        }
        let sine = forward.cross(self.up).length() / (forward.length() * self.up.length());
        // Also rejects NaN (a zero-length vector).
        if sine.is_nan() || sine <= MIN_UP_SINE {
            return Err(CameraError::BadUp);
        }
        let (near, far) = match self.projection {
            Projection::Perspective {
                fov_y_deg,
                near,
                far,
            } => {
                if !(fov_y_deg > 0.0 && fov_y_deg < 180.0) {
                    return Err(CameraError::BadFov(fov_y_deg));
                }
                (near, far)
            }
            Projection::Orthographic { height, near, far } => {
                if !(height > 0.0 && height.is_finite()) {
                    return Err(CameraError::BadHeight(height));
                }
                if height > MAX_CAMERA_VALUE {
                    return Err(CameraError::TooLarge {
                        what: "orthographic height",
                        value: height,
                    });
                }
                (near, far)
            }
        };
        if !(near > 0.0 && far > near && far.is_finite()) {
            return Err(CameraError::BadPlanes { near, far });
        }
        if far > MAX_CAMERA_VALUE {
            return Err(CameraError::TooLarge {
                what: "far plane",
                value: far,
            });
        }
        Ok(())
    }

    /// A perspective camera that frames a sphere (centre, radius `r`) from the course's view
    /// ([`ModelView::Course`]), at the distance where the sphere fits a 45 degree field of view
    /// with a 15% margin: `d = 1.15 r / sin(22.5 deg)`; near = `max(d - 2r, d / 1000)`,
    /// far = `d + 2r`.
    ///
    /// ```
    /// use barylab::raster::camera::{Camera, Projection};
    /// use glam::DVec3;
    /// let cam = Camera::framing(DVec3::ZERO, 2.0);
    /// assert_eq!(cam.target, DVec3::ZERO);
    /// let d = (cam.eye - cam.target).length();
    /// assert!((d - 1.15 * 2.0 / 22.5f64.to_radians().sin()).abs() < 1e-12);
    /// assert!(cam.validate().is_ok());
    /// ```
    pub fn framing(centre: DVec3, radius: f64) -> Self {
        Self::framing_from(centre, radius, ModelView::Course)
    }

    /// [`Camera::framing`] looking from `view`'s direction.
    ///
    /// ```
    /// use barylab::raster::camera::{Camera, ModelView};
    /// use glam::DVec3;
    /// // From the front the eye is on the +z axis, looking down -z.
    /// let cam = Camera::framing_from(DVec3::ZERO, 1.0, ModelView::Front);
    /// assert!(cam.eye.x.abs() < 1e-12 && cam.eye.y.abs() < 1e-12 && cam.eye.z > 0.0);
    /// ```
    pub fn framing_from(centre: DVec3, radius: f64, view: ModelView) -> Self {
        const FOV_DEG: f64 = 45.0;
        /// Radius used for a model of zero size (a single point), so the camera stays valid.
        const MIN_RADIUS: f64 = 1e-3;
        let r = radius.max(MIN_RADIUS);
        let d = 1.15 * r / (FOV_DEG / 2.0).to_radians().sin();
        let (dir, up) = view.eye_direction();
        Self {
            eye: centre + dir * d,
            target: centre,
            up,
            projection: Projection::Perspective {
                fov_y_deg: FOV_DEG,
                near: (d - 2.0 * r).max(d / 1000.0),
                far: d + 2.0 * r,
            },
        }
    }

    /// The view matrix: world -> view space (right-handed, camera looking down -z).
    pub fn view_from_world(&self) -> DMat4 {
        view::look_at_mat4(self.eye, self.target, self.up)
    }

    /// The projection matrix: view space -> OpenGL clip space, for `aspect` = width / height.
    ///
    /// Perspective: `x_c = x_v / (aspect tan(fov/2))`, `y_c = y_v / tan(fov/2)`,
    /// `z_c = ((f + n) z_v + 2 f n) / (n - f)`, `w_c = -z_v`.
    ///
    /// ```
    /// use barylab::raster::camera::{Camera, Projection};
    /// use glam::{DVec3, DVec4};
    /// let cam = Camera {
    ///     eye: DVec3::ZERO, target: DVec3::NEG_Z, up: DVec3::Y,
    ///     projection: Projection::Perspective { fov_y_deg: 90.0, near: 1.0, far: 3.0 },
    /// };
    /// // A point on the near plane maps to z/w = -1; its w is its distance, 1.
    /// let c = cam.clip_from_view(1.0) * DVec4::new(1.0, 0.5, -1.0, 1.0);
    /// assert!((c - DVec4::new(1.0, 0.5, -1.0, 1.0)).abs().max_element() < 1e-12);
    /// // On the far plane: z/w = +1 and w = 3.
    /// let c = cam.clip_from_view(1.0) * DVec4::new(0.0, 0.0, -3.0, 1.0);
    /// assert!((c.z / c.w - 1.0).abs() < 1e-12 && (c.w - 3.0).abs() < 1e-12);
    /// ```
    pub fn clip_from_view(&self, aspect: f64) -> DMat4 {
        match self.projection {
            Projection::Perspective {
                fov_y_deg,
                near,
                far,
            } => opengl::perspective(fov_y_deg.to_radians(), aspect, near, far),
            Projection::Orthographic { height, near, far } => {
                let h = height / 2.0;
                let w = h * aspect;
                opengl::orthographic(-w, w, -h, h, near, far)
            }
        }
    }

    /// The full matrix world -> clip space: `clip_from_view * view_from_world`.
    pub fn clip_from_world(&self, aspect: f64) -> DMat4 {
        self.clip_from_view(aspect) * self.view_from_world()
    }
}

/// A scene's camera chain: object -> world -> view -> clip, each matrix named by what it maps,
/// and the way back from clip space and NDC to view space. The probe follows vertices and the
/// pixel's view ray through it; the app moves vertices along it.
///
/// ```
/// use barylab::raster::camera::{Camera, CameraChain, Projection};
/// use glam::{DMat4, DVec2, DVec3};
/// let cam = Camera {
///     eye: DVec3::ZERO, target: DVec3::NEG_Z, up: DVec3::Y,
///     projection: Projection::Perspective { fov_y_deg: 90.0, near: 1.0, far: 3.0 },
/// };
/// let chain = CameraChain::new(&cam, DMat4::IDENTITY, 1.0);
/// // The centre of the screen looks straight down -z, from the eye.
/// let (origin, dir) = chain.view_ray(DVec2::ZERO);
/// assert_eq!(origin, DVec3::ZERO);
/// assert!((dir - DVec3::new(0.0, 0.0, -1.0)).length() < 1e-12);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraChain {
    /// Object -> world: the world quad's tilt, the identity for models.
    pub world_from_object: DMat4,
    /// World -> view: the look-at matrix.
    pub view_from_world: DMat4,
    /// View -> clip: the OpenGL projection for the image's aspect.
    pub clip_from_view: DMat4,
    /// `clip_from_view^-1`.
    pub view_from_clip: DMat4,
    /// Whether the projection is a perspective one (else orthographic).
    pub perspective: bool,
}

impl CameraChain {
    /// The chain of `camera` for an image of `aspect` = width / height, with the object's
    /// placement `world_from_object`.
    pub fn new(camera: &Camera, world_from_object: DMat4, aspect: f64) -> Self {
        let clip_from_view = camera.clip_from_view(aspect);
        Self {
            world_from_object,
            view_from_world: camera.view_from_world(),
            clip_from_view,
            view_from_clip: clip_from_view.inverse(),
            perspective: matches!(camera.projection, Projection::Perspective { .. }),
        }
    }

    /// World and view position of an object-space point: `world = world_from_object object`,
    /// `view = view_from_world world`.
    pub fn world_and_view(&self, object: DVec3) -> (DVec3, DVec3) {
        let world = self.world_from_object.transform_point3(object);
        (world, self.view_from_world.transform_point3(world))
    }

    /// World position of a view-space point: `view_from_world^-1 view`.
    pub fn world_from_view_point(&self, view: DVec3) -> DVec3 {
        self.view_from_world.inverse().transform_point3(view)
    }

    /// View-space position of a clip-space point: `view_from_clip clip`, divided by its w.
    pub fn view_from_clip_point(&self, clip: DVec4) -> DVec3 {
        let v = self.view_from_clip * clip;
        v.truncate() / v.w
    }

    /// The view-space point at NDC `(x, y, z_ndc)`: [`CameraChain::view_from_clip_point`] of
    /// `(x, y, z_ndc, 1)` (z_ndc = -1 is the near plane, +1 the far plane).
    pub fn unproject(&self, ndc: DVec2, z_ndc: f64) -> DVec3 {
        self.view_from_clip_point(DVec4::new(ndc.x, ndc.y, z_ndc, 1.0))
    }

    /// The view ray through NDC `(x, y)`, as `(origin, direction)` in view space: from the eye
    /// at the origin through the point on the near plane (perspective), or from the near-plane
    /// point to the far-plane point, parallel to -z (orthographic).
    pub fn view_ray(&self, ndc: DVec2) -> (DVec3, DVec3) {
        let (near, far) = (self.unproject(ndc, -1.0), self.unproject(ndc, 1.0));
        if self.perspective {
            (DVec3::ZERO, near)
        } else {
            (near, far - near)
        }
    }
}
