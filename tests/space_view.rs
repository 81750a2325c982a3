//! The space view: P's weights are the probe's a b c and P lies where an independent
//! ray–triangle intersection (written here) puts it; Q has the screen weights; the near-plane
//! cut is shown; the figure's P mark lands where P projects; the tetrahedron's volume weights
//! and the depth plot.

use barylab::figure::space::{
    Lens, Orbit, P_COLOUR, POINT_WEIGHTS, SpaceFigure, SpaceScene, TetraFigure, depth_plot,
    drawing_rect, volume_weights,
};
use barylab::i18n::Lang;
use barylab::probe::{PixelTrace, probe};
use barylab::raster::Texture;
use barylab::raster::camera::{Camera, Projection};
use barylab::scene::Scene;
use glam::{DVec2, DVec3};

fn load(name: &str) -> Scene {
    let path = format!("{}/assets/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    Scene::load(std::path::Path::new(&path)).expect("bundled scene loads")
}

fn traced(scene: &Scene, pixel: (u32, u32)) -> (SpaceScene, PixelTrace) {
    let texture = Texture::builtin(barylab::raster::BuiltinTexture::UvGrid);
    let settings = scene.settings();
    let trace = probe(scene, &texture, &settings, pixel).expect("probe");
    let space = SpaceScene::build(scene, &settings, Some(&trace)).expect("space scene");
    (space, trace)
}

/// A camera's view-space position of a world point, from its basis (not its matrices).
fn to_view(cam: &Camera, p: DVec3) -> DVec3 {
    let f = (cam.target - cam.eye).normalize();
    let r = f.cross(cam.up).normalize();
    let u = r.cross(f);
    let d = p - cam.eye;
    DVec3::new(d.dot(r), d.dot(u), -d.dot(f))
}

/// The view-space direction of the ray through the centre of pixel (x, y).
fn ray_dir(cam: &Camera, (w, h): (u32, u32), (x, y): (u32, u32)) -> DVec3 {
    let Projection::Perspective { fov_y_deg, .. } = cam.projection else {
        panic!("the test scenes are perspective");
    };
    let t = (fov_y_deg.to_radians() / 2.0).tan();
    let nx = 2.0 * (f64::from(x) + 0.5) / f64::from(w) - 1.0;
    let ny = 1.0 - 2.0 * (f64::from(y) + 0.5) / f64::from(h);
    DVec3::new(nx * t * f64::from(w) / f64::from(h), ny * t, -1.0)
}

/// Möller–Trumbore: the ray `t d` from the origin against triangle [a, b, c]: the point and
/// its weights `(1 - u - v, u, v)`.
fn intersect(d: DVec3, [a, b, c]: [DVec3; 3]) -> (DVec3, [f64; 3]) {
    let (e1, e2) = (b - a, c - a);
    let p = d.cross(e2);
    let det = e1.dot(p);
    let s = -a;
    let u = s.dot(p) / det;
    let q = s.cross(e1);
    let v = d.dot(q) / det;
    let t = e2.dot(q) / det;
    (d * t, [1.0 - u - v, u, v])
}

fn close(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() <= tol)
}

#[test]
fn p_has_the_probes_weights_and_lies_on_the_independent_ray() {
    let scene = Scene::default_scene();
    let Scene::World(world) = &scene else {
        panic!("the default scene is a world scene");
    };
    let pixel = (400, 420);
    let (space, trace) = traced(&scene, pixel);
    let detail = trace.detail.as_ref().expect("the pixel has a triangle");
    let abc = detail
        .perspective
        .as_ref()
        .expect("1/w is positive")
        .correction
        .weights;
    let ray = space.ray.as_ref().expect("a ray");
    let seen = ray.seen.as_ref().expect("the ray meets the quad");
    // Exactly the probe's numbers, not a recomputation.
    assert_eq!(seen.abc, abc);
    assert_eq!(seen.rst, detail.screen.rasterizer);
    assert_eq!(seen.names, ["A", "B", "C"].map(String::from));
    assert!(seen.covered);

    let corners = [0, 1, 2].map(|i| to_view(&world.camera, world.quad[i].position));
    let (hit, weights) = intersect(ray_dir(&world.camera, scene.size(), pixel), corners);
    assert!(
        close(seen.abc, weights, 1e-9),
        "{:?} vs {weights:?}",
        seen.abc
    );
    assert!((seen.p - hit).length() < 1e-9, "{} vs {hit}", seen.p);
    // W_P is P's view depth for a perspective camera.
    assert!((seen.w_p + hit.z).abs() < 1e-9);
    // Q has the screen weights and is off the ray by a visible gap.
    let q = corners[0] * seen.rst[0] + corners[1] * seen.rst[1] + corners[2] * seen.rst[2];
    assert!((seen.q - q).length() < 1e-9);
    assert!((seen.p - seen.q).length() > 0.5);
    // The ray starts at the eye and goes through the pixel centre on the image plane.
    assert!(ray.origin.length() < 1e-12);
    let dir = ray_dir(&world.camera, scene.size(), pixel);
    assert!(ray.on_image.cross(dir).length() < 1e-9 * ray.on_image.length());
    assert!((ray.on_image.z + space.image_depth).abs() < 1e-9);
}

#[test]
fn a_corner_behind_the_eye_shows_the_near_plane_cut() {
    let scene = load("near-cut.json");
    let Scene::World(world) = &scene else {
        panic!("near-cut is a world scene");
    };
    let pixel = (300, 330);
    let (space, _) = traced(&scene, pixel);
    let seen = space
        .ray
        .as_ref()
        .and_then(|r| r.seen.as_ref())
        .expect("the ray meets the floor");
    let cut = seen.cut.as_ref().expect("the triangle is clipped");
    let names: Vec<&str> = cut.polygon.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["K1", "C", "D", "K2"]);
    // K1 and K2 lie on the near plane, 1 in front of the eye.
    for (name, p) in &cut.polygon {
        if name.starts_with('K') {
            assert!((p.z + 1.0).abs() < 1e-9, "{name} at {p}");
        }
    }
    // A is behind the camera, and the clipped triangle's kept part is drawn.
    assert!(space.vertices[0].w < 0.0);
    assert!(space.triangles.iter().all(|t| t.kept.is_some()));
    // P is where the ray meets the source triangle A C D.
    let source = [0, 2, 3].map(|i| to_view(&world.camera, world.quad[i].position));
    let (hit, _) = intersect(ray_dir(&world.camera, scene.size(), pixel), source);
    assert!((seen.p - hit).length() < 1e-9, "{} vs {hit}", seen.p);
}

#[test]
fn a_clip_space_scene_is_drawn_with_w_as_depth() {
    let scene = load("tetrahedron.json");
    let (space, trace) = traced(&scene, (370, 290));
    // The vertices' z is affine in w (a camera made them): near and far planes exist.
    let Lens::ClipW { fit: Some(_) } = space.lens else {
        panic!("the tetrahedron's z fits an affine function of w");
    };
    let near = space.near.expect("a near plane");
    assert!(near > 0.0 && near < 1.0, "near {near}");
    let seen = space
        .ray
        .as_ref()
        .and_then(|r| r.seen.as_ref())
        .expect("the ray meets the front face");
    // P is on the ray through the pixel's NDC: (n_x d, n_y d, -d).
    let ndc = DVec2::from_array(trace.sample.ndc);
    let d = -seen.p.z;
    assert!((seen.p.x - ndc.x * d).abs() < 1e-9 && (seen.p.y - ndc.y * d).abs() < 1e-9);
    assert!((d - seen.w_p).abs() < 1e-9);
}

#[test]
fn the_figures_p_mark_lands_where_p_projects() {
    let scene = Scene::default_scene();
    let (space, _) = traced(&scene, (400, 420));
    let fig = SpaceFigure {
        space: &space,
        orbit: Orbit::default(),
        lang: Lang::En,
    };
    let p = space
        .ray
        .as_ref()
        .and_then(|r| r.seen.as_ref())
        .expect("P")
        .p;
    let [px, py] = space.projector(fig.orbit, drawing_rect()).project(p).0;
    let image = fig.rasterize(1.0).expect("rasterize");
    // The mark's fill colour within a few points of the projection, centred on it.
    let (mut n, mut sx, mut sy) = (0.0, 0.0, 0.0);
    for (x, y, c) in image.enumerate_pixels() {
        let (cx, cy) = (x as f32 + 0.5, y as f32 + 0.5);
        if c.0 == P_COLOUR.0 && (cx - px).hypot(cy - py) <= 8.0 {
            n += 1.0;
            sx += cx;
            sy += cy;
        }
    }
    assert!(n >= 40.0, "only {n} pixels of P's colour near ({px}, {py})");
    let (mx, my) = (sx / n, sy / n);
    assert!(
        (mx - px).hypot(my - py) < 1.0,
        "P's mark centred at ({mx}, {my}), P projects to ({px}, {py})"
    );
}

#[test]
fn the_tetrahedrons_volume_weights() {
    let t = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(2.0, 0.0, 0.0),
        DVec3::new(0.0, 3.0, 0.0),
        DVec3::new(0.0, 0.0, 4.0),
    ];
    // At a corner the weights are one-hot; at (0.5, 0.75, 1) they are (1/4 each) for this
    // right-angled tetrahedron: x/2 + y/3 + z/4 + λ_A = 1.
    assert_eq!(volume_weights(t, t[2]), Some([0.0, 0.0, 1.0, 0.0]));
    let w = volume_weights(t, DVec3::new(0.5, 0.75, 1.0)).expect("not flat");
    for v in w {
        assert!((v - 0.25).abs() < 1e-12, "{w:?}");
    }
    assert_eq!(volume_weights([t[0], t[1], t[2], t[0]], t[1]), None);

    let scene = load("tetrahedron.json");
    let space = SpaceScene::build(&scene, &scene.settings(), None).expect("space scene");
    let fig = TetraFigure::new(&space, Orbit::default(), Lang::En).expect("a tetrahedron");
    for (got, want) in fig.weights().iter().zip(POINT_WEIGHTS) {
        assert!((got - want).abs() < 1e-9, "{:?}", fig.weights());
    }
    assert!(fig.to_svg().contains("λ_A = 0.4"));
}

/// The pinned pixel's ray through the tetrahedron: where it enters (on the front face A B D)
/// the volume weights are the probe's perspective-correct a b c with C's weight 0, and X,
/// halfway to where it leaves, lies on the ray with four positive weights.
#[test]
fn the_tetrahedrons_point_follows_the_pixels_ray() {
    let scene = load("tetrahedron.json");
    let (space, trace) = traced(&scene, (370, 290));
    let fig = TetraFigure::new(&space, Orbit::default(), Lang::En).expect("a tetrahedron");
    let ray = fig.ray().expect("the ray crosses the tetrahedron");
    let detail = trace.detail.as_ref().expect("a triangle");
    let abc = detail
        .perspective
        .as_ref()
        .expect("1/w > 0")
        .correction
        .weights;
    // The face A B D is vertices 0, 1, 3; the entry's weights of A, B, D are a, b, c.
    let want = [abc[0], abc[1], 0.0, abc[2]];
    for (got, want) in ray.entry_weights.iter().zip(want) {
        assert!((got - want).abs() < 1e-9, "{:?} {abc:?}", ray.entry_weights);
    }
    assert_eq!(ray.entry_face_opposite(), 2);
    // X on the ray (the eye, the pixel centre and X in one line) and inside.
    let r = space.ray.as_ref().expect("a ray");
    let along = (r.on_image - r.origin).normalize();
    let off = (fig.point() - r.origin).cross(along).length();
    assert!(off < 1e-9 * fig.point().length(), "X is {off} off the ray");
    let w = fig.weights();
    assert!(w.iter().all(|&v| v > 0.0), "{w:?}");
    assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-12);
    // X is the volume weights' point: sum λ_i V_i.
    let x: DVec3 = (0..4).map(|i| space.vertices[i].point * w[i]).sum();
    assert!((x - fig.point()).length() < 1e-9 * x.length());
    let svg = fig.to_svg();
    assert!(svg.contains("(0.3675, 0.4099, 0, 0.2226)"), "{svg}");

    // A pixel beside the tetrahedron: the fixed point inside.
    let (space, _) = traced(&scene, (5, 5));
    let fig = TetraFigure::new(&space, Orbit::default(), Lang::En).expect("a tetrahedron");
    assert!(fig.ray().is_none());
    for (got, want) in fig.weights().iter().zip(POINT_WEIGHTS) {
        assert!((got - want).abs() < 1e-9, "{:?}", fig.weights());
    }
}

#[test]
fn the_depth_plot_runs_from_the_near_plane_to_the_far_plane() {
    let plot = depth_plot(&Scene::default_scene(), Lang::En).expect("planes");
    let line = &plot.lines[0].1;
    let (first, last) = (line[0], line[line.len() - 1]);
    assert_eq!((first[0], last[0]), (0.1, 100.0));
    assert!(first[1].abs() < 1e-9 && (last[1] - 1.0).abs() < 1e-9);
    // Most of the depth range is used up next to the near plane: d > 0.8 at view depth 0.52.
    let at = |d: f64| {
        line.iter()
            .min_by(|a, b| (a[0] - d).abs().total_cmp(&(b[0] - d).abs()))
            .expect("points")[1]
    };
    assert!(at(0.5) > 0.8, "{}", at(0.5));
    assert!(line.windows(2).all(|p| p[1][1] > p[0][1]));
}
