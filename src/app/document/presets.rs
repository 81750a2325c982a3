//! Named starting scenes for the classroom, each showing one situation. No GUI code here.

use glam::{DVec3, Vec2, Vec3};

use crate::raster::camera::{Camera, Projection};
use crate::scene::{Corner, Scene, Tilt};

/// The presets the app offers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Preset {
    /// The quad faces the camera: all w equal, affine and perspective agree.
    FrontFacing,
    /// The built-in default: a floor leaning away.
    Floor,
    /// A wall seen at a grazing angle: w changes a lot across the quad.
    GrazingWall,
    /// The front-facing quad with corner C pushed far away along its view ray: the same
    /// picture in affine mode, a very different one in perspective mode.
    FarCorner,
    /// Corner A behind the camera: the near plane clips the quad.
    CornerBehind,
}

impl Preset {
    /// Every preset, in menu order.
    pub const ALL: [Preset; 5] = [
        Preset::FrontFacing,
        Preset::Floor,
        Preset::GrazingWall,
        Preset::FarCorner,
        Preset::CornerBehind,
    ];

    /// The preset's geometry and camera; render options are the default scene's.
    pub fn scene(self) -> Scene {
        let mut scene = Scene::default_scene();
        let Scene::World(s) = &mut scene else {
            return scene;
        };
        s.tilt = Tilt::default();
        let corner = |p: [f64; 3], uv: [f32; 2], c: [f32; 3]| Corner {
            position: DVec3::from(p),
            uv: Vec2::from(uv),
            color: Vec3::from(c),
        };
        let (red, green, blue, yellow) = (
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [1.0, 1.0, 0.0],
        );
        let perspective = |fov_y_deg| Projection::Perspective {
            fov_y_deg,
            near: 0.1,
            far: 100.0,
        };
        let front_camera = Camera {
            eye: DVec3::new(0.0, 0.0, 3.0),
            target: DVec3::ZERO,
            up: DVec3::Y,
            projection: perspective(50.0),
        };
        let front_quad = [
            corner([-1.0, -1.0, 0.0], [0.0, 0.0], red),
            corner([1.0, -1.0, 0.0], [1.0, 0.0], green),
            corner([1.0, 1.0, 0.0], [1.0, 1.0], blue),
            corner([-1.0, 1.0, 0.0], [0.0, 1.0], yellow),
        ];
        match self {
            Preset::Floor => {}
            Preset::FrontFacing => {
                s.camera = front_camera;
                s.quad = front_quad;
            }
            Preset::GrazingWall => {
                s.camera = Camera {
                    eye: DVec3::new(0.0, 0.0, 2.0),
                    target: DVec3::new(0.0, 0.0, -1.0),
                    up: DVec3::Y,
                    projection: perspective(60.0),
                };
                // Seen from the left, so u runs from the far end (A, D) to the near end (B, C)
                // and the texture reads the right way round.
                s.quad = [
                    corner([0.6, -0.5, -9.0], [0.0, 0.0], red),
                    corner([0.6, -0.5, 0.8], [1.0, 0.0], green),
                    corner([0.6, 0.5, 0.8], [1.0, 1.0], blue),
                    corner([0.6, 0.5, -9.0], [0.0, 1.0], yellow),
                ];
            }
            Preset::FarCorner => {
                s.camera = front_camera;
                s.quad = front_quad;
                // Five times as far from the eye along the same ray: same screen position,
                // w = 15 instead of 3.
                let eye = front_camera.eye;
                let c = &mut s.quad[2].position;
                *c = eye + 5.0 * (*c - eye);
            }
            Preset::CornerBehind => {
                s.camera = Camera {
                    eye: DVec3::ZERO,
                    target: DVec3::NEG_Z,
                    up: DVec3::Y,
                    projection: perspective(70.0),
                };
                // A flat parallelogram (its centre, half-diagonals to A and B),
                // tilted so that A alone passes behind the camera: the near plane cuts a
                // plane, as clipping does on a GPU, and nothing folds.
                let c = DVec3::new(0.3, 0.1, -3.0);
                let (a, b) = (DVec3::new(-1.2, -0.9, 3.3), DVec3::new(1.5, -0.8, -0.6));
                let at = |p: DVec3| [p.x, p.y, p.z];
                s.quad = [
                    corner(at(c + a), [0.0, 0.0], red),
                    corner(at(c + b), [1.0, 0.0], green),
                    corner(at(c - a), [1.0, 1.0], blue),
                    corner(at(c - b), [0.0, 1.0], yellow),
                ];
            }
        }
        scene
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure::vertices_on_screen;
    use crate::raster::project::Viewport;

    #[test]
    fn presets_are_valid_and_show_what_they_say() {
        let vp = Viewport {
            width: 800,
            height: 600,
        };
        for p in Preset::ALL {
            p.scene().validate(&format!("{p:?}")).expect("valid");
        }
        assert_eq!(Preset::Floor.scene(), Scene::default_scene());
        let front = vertices_on_screen(&Preset::FrontFacing.scene(), vp);
        assert!(front.iter().all(|v| (v.w() - 3.0).abs() < 1e-12));
        let far = vertices_on_screen(&Preset::FarCorner.scene(), vp);
        assert!((far[2].w() - 15.0).abs() < 1e-9);
        let (a, b) = (far[2].window.expect("far"), front[2].window.expect("front"));
        assert!((a - b).length() < 1e-9);
        let wall = vertices_on_screen(&Preset::GrazingWall.scene(), vp);
        assert!(wall.iter().all(|v| {
            v.window
                .is_some_and(|p| p.x > 0.0 && p.y > 0.0 && p.x < 800.0 && p.y < 600.0)
        }));
        assert!(wall[0].w() / wall[1].w() > 5.0);
        let behind = vertices_on_screen(&Preset::CornerBehind.scene(), vp);
        assert!(behind[0].window.is_none() && behind[1..].iter().all(|v| v.window.is_some()));
        // Planar: D - A = C - B (a parallelogram), so the two triangles share one plane.
        let Scene::World(w) = Preset::CornerBehind.scene() else {
            panic!("world scene")
        };
        let q = w.quad.map(|c| c.position);
        assert!(((q[3] - q[0]) - (q[2] - q[1])).length() < 1e-12);
        let normal = (q[1] - q[0]).cross(q[3] - q[0]);
        assert!(normal.dot(q[2] - q[0]).abs() < 1e-12);
    }
}
