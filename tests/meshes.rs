//! Dense meshes: a clip scene's `subdivide` splits every triangle on its barycentric grid,
//! which draws the same surface with the same values; the benchmark meshes in assets/bench
//! load, and `Scene::triangle` agrees with the built mesh.

use std::path::Path;

use barylab::raster::{NO_TRIANGLE, render};
use barylab::scene::Scene;

fn bench_dir() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/bench")
}

/// The reference quad split into 2 x 50² triangles against the same quad as two triangles, at
/// a small size: the same pixels (but for centres within a sub-pixel of the outline, where the
/// split edges' own snapping decides) and the same uv to f32 precision.
#[test]
fn a_subdivided_quad_draws_the_same_image() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut quad = Scene::load(&dir.join("assets/scenes/bench-1080p.json")).expect("quad");
    let mut dense = Scene::load(&bench_dir().join("bench-mesh-5k.json")).expect("mesh");
    quad.set_size(240, 135);
    dense.set_size(240, 135);
    assert_eq!(dense.to_mesh().triangles.len(), 5000);
    let texture = quad.load_texture(dir).expect("texture");
    let a = render(&quad.to_mesh(), &texture, &quad.settings()).expect("render");
    let b = render(&dense.to_mesh(), &texture, &dense.settings()).expect("render");
    let (fa, fb) = (&a.frame, &b.frame);
    let (mut both, mut one) = (0, 0);
    let mut uv: f32 = 0.0;
    for i in 0..fa.triangle.len() {
        match (fa.triangle[i] != NO_TRIANGLE, fb.triangle[i] != NO_TRIANGLE) {
            (true, true) => {
                both += 1;
                // Perspective-correct only: affine uv is linear per triangle on screen, so
                // smaller triangles rightly give other affine values.
                let (p, q) = (fa.uv_perspective[i], fb.uv_perspective[i]);
                uv = uv.max((p[0] - q[0]).abs()).max((p[1] - q[1]).abs());
            }
            (false, false) => {}
            _ => one += 1,
        }
    }
    assert!(both > 20_000, "{both} pixels covered");
    assert!(one * 1000 <= both, "{one} pixels covered by one only");
    assert!(uv <= 2e-6, "perspective-correct uv differs by {uv}");
}

/// Every benchmark mesh loads with the triangle count its name says, and
/// `Scene::triangle(i)` is the built mesh's triangle `i`.
#[test]
fn benchmark_meshes_load() {
    for (name, count) in [
        ("bench-mesh-5k.json", 5_000),
        ("bench-mesh-75k.json", 75_272),
        ("bench-mesh-460k.json", 460_800),
    ] {
        let scene = Scene::load(&bench_dir().join(name)).expect(name);
        let mesh = scene.to_mesh();
        assert_eq!(mesh.triangles.len(), count, "{name}");
        let n = mesh.vertices.len() as u32;
        assert!(mesh.triangles.iter().flatten().all(|&i| i < n), "{name}");
        for i in (0..=count).step_by(997).chain([count - 1, count]) {
            assert_eq!(
                scene.triangle(i),
                mesh.triangles.get(i).copied(),
                "{name} {i}"
            );
        }
    }
}

/// A subdivision that would make too many triangles is refused at load, naming the field.
#[test]
fn a_huge_subdivision_is_refused() {
    let json = r#"{"width": 8, "height": 8,
        "vertices": [{"clip": [0, 0, 0, 1]}, {"clip": [1, 0, 0, 1]}, {"clip": [0, 1, 0, 1]}],
        "triangles": [[0, 1, 2]], "subdivide": 100000}"#;
    let e = Scene::from_json(json, "big.json").expect_err("too many");
    let msg = e.to_string();
    assert!(
        msg.contains("subdivide") && msg.contains("big.json"),
        "{msg}"
    );
}
