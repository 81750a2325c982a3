//! The wireframe: a light line with a dark halo along it, so it shows on any texture. It is a
//! colour only: coverage, depth and every interpolated value are those of the render without
//! it, and the probe's colour is the rendered pixel's.

use std::path::Path;

use barylab::figure::vertices_on_screen;
use barylab::raster::project::Viewport;
use barylab::raster::shade::{WIRE_COLOR, WIRE_HALO_COLOR, WIRE_HALO_PX, WIRE_WIDTH_PX};
use barylab::raster::{self, Interpolation};
use barylab::scene::Scene;
use glam::DVec2;

fn default_scene(size: [u32; 2]) -> (Scene, raster::Texture) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut scene = Scene::load(&root.join("assets/scenes/default.json")).expect("scene");
    scene.set_size(size[0], size[1]);
    let texture = scene
        .load_texture(&root.join("assets/scenes"))
        .expect("texture");
    (scene, texture)
}

/// Distance from `p` to the line through `a` and `b`.
fn distance(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let d = b - a;
    (d.perp_dot(p - a)).abs() / d.length()
}

#[test]
fn the_line_is_light_its_halo_dark_and_nothing_else_changes() {
    let size = [160, 120];
    let (scene, texture) = default_scene(size);
    let mesh = scene.to_mesh();
    let windows: Vec<DVec2> = vertices_on_screen(
        &scene,
        Viewport {
            width: size[0],
            height: size[1],
        },
    )
    .iter()
    .map(|v| v.window.expect("in front of the camera"))
    .collect();
    for mode in [Interpolation::Perspective, Interpolation::Affine] {
        let mut plain = scene.settings();
        plain.mode = mode;
        let wired = raster::RenderSettings {
            wireframe: true,
            ..plain
        };
        let a = raster::render(&mesh, &texture, &plain)
            .expect("render")
            .frame;
        let b = raster::render(&mesh, &texture, &wired)
            .expect("render")
            .frame;
        // Only the colour may change.
        assert_eq!(a.triangle, b.triangle);
        assert_eq!(a.depth, b.depth);
        assert_eq!(a.weights_screen, b.weights_screen);
        assert_eq!(a.weights_perspective, b.weights_perspective);
        assert_eq!(a.uv_affine, b.uv_affine);
        assert_eq!(a.uv_perspective, b.uv_perspective);
        assert_eq!(a.inv_w, b.inv_w);
        let (mut lines, mut halos) = (0, 0);
        for y in 0..size[1] {
            for x in 0..size[0] {
                let i = (y * size[0] + x) as usize;
                let t = b.triangle[i];
                if t == raster::NO_TRIANGLE {
                    assert_eq!(a.color[i], b.color[i]);
                    continue;
                }
                // The distance to the nearest edge of the pixel's triangle, from the corners'
                // window positions (the quad is not clipped: the weights are screen-linear).
                let tri = mesh.triangles[t as usize].map(|k| windows[k as usize]);
                let c = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
                let d = (0..3)
                    .map(|e| distance(c, tri[(e + 1) % 3], tri[(e + 2) % 3]))
                    .fold(f64::INFINITY, f64::min);
                let near = |edge: f64| (d - edge).abs() < 1e-3;
                if near(WIRE_WIDTH_PX) || near(WIRE_WIDTH_PX + WIRE_HALO_PX) {
                    continue;
                }
                let expected = if d < WIRE_WIDTH_PX {
                    lines += 1;
                    WIRE_COLOR
                } else if d < WIRE_WIDTH_PX + WIRE_HALO_PX {
                    halos += 1;
                    WIRE_HALO_COLOR
                } else {
                    a.color[i]
                };
                assert_eq!(b.color[i], expected, "pixel ({x}, {y}) at {d} px, {mode:?}");
            }
        }
        assert!(
            lines > 200 && halos > 200,
            "{lines} line, {halos} halo pixels"
        );
    }
    // Light on dark, dark on light.
    let lum =
        |c: [u8; 4]| 0.2126 * f64::from(c[0]) + 0.7152 * f64::from(c[1]) + 0.0722 * f64::from(c[2]);
    assert!(lum(WIRE_COLOR) > 200.0 && lum(WIRE_HALO_COLOR) < 40.0);
}

#[test]
fn the_probe_shows_the_line_and_the_halo_as_drawn() {
    let size = [160, 120];
    let (scene, texture) = default_scene(size);
    let mut settings = scene.settings();
    settings.wireframe = true;
    let r = raster::render(&scene.to_mesh(), &texture, &settings).expect("render");
    let prober = barylab::probe::Prober::new(&scene, &texture, &settings).expect("prober");
    let (mut lines, mut halos) = (0, 0);
    for y in (0..size[1]).step_by(3) {
        for x in 0..size[0] {
            let t = prober.pixel(x, y).expect("trace");
            let i = (y * size[0] + x) as usize;
            assert_eq!(t.color, r.frame.color[i], "pixel ({x}, {y})");
            if let Some(sh) = t.detail.as_ref().and_then(|d| d.shade) {
                if r.frame.triangle[i] == raster::NO_TRIANGLE {
                    continue;
                }
                assert_eq!(sh.wire, t.color == WIRE_COLOR, "({x}, {y})");
                assert_eq!(sh.halo, t.color == WIRE_HALO_COLOR, "({x}, {y})");
                lines += usize::from(sh.wire);
                halos += usize::from(sh.halo);
            }
        }
    }
    assert!(lines > 20 && halos > 20, "{lines} {halos}");
}
