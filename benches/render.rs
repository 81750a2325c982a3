//! Criterion benchmarks of whole-frame rendering: every rasterizer x filter x mode on the
//! default scene (800x600) and on the bench-1080p reference scene scaled down, and a mesh of
//! many small triangles (where per-triangle setup dominates).

use std::path::Path;

use barylab::raster::render::{ClipMesh, MeshVertex, Rasterizer, RenderSettings};
use barylab::raster::{
    Buffers, BuiltinTexture, Filter, Framebuffer, Interpolation, Texture, render, render_into,
};
use barylab::scene::Scene;
use criterion::{Criterion, criterion_group, criterion_main};
use glam::{DVec4, Vec2, Vec3};

fn scenes_dir() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/scenes"))
}

fn matrix(c: &mut Criterion, name: &str, scene: &Scene) {
    let texture = scene.load_texture(scenes_dir()).expect("texture");
    let mesh = scene.to_mesh();
    let (w, h) = scene.size();
    let mut group = c.benchmark_group(format!("{name}-{w}x{h}"));
    for rasterizer in [Rasterizer::EdgeFunction, Rasterizer::Scanline] {
        for filter in [Filter::Nearest, Filter::Bilinear] {
            for mode in [Interpolation::Affine, Interpolation::Perspective] {
                let settings = RenderSettings {
                    rasterizer,
                    filter,
                    mode,
                    ..scene.settings()
                };
                // Colour and depth into a reused framebuffer: what the app and `barylab bench`
                // draw.
                let mut frame = Framebuffer::empty();
                group.bench_function(format!("{rasterizer:?}-{filter:?}-{mode:?}"), |b| {
                    b.iter(|| {
                        render_into(&mut frame, &mesh, &texture, &settings, Buffers::ColorDepth)
                            .expect("render")
                    })
                });
            }
        }
    }
    // Every per-pixel buffer (the inspector's, the heatmap's, the AOV export's), per pixel.
    let settings = scene.settings();
    group.bench_function("EdgeFunction-all-buffers", |b| {
        b.iter(|| render(&mesh, &texture, &settings).expect("render"))
    });
    group.finish();
}

fn bench_scenes(c: &mut Criterion) {
    matrix(c, "default", &Scene::default_scene());
    let mut bench = Scene::load(&scenes_dir().join("bench-1080p.json")).expect("bench scene");
    bench.set_size(960, 540);
    matrix(c, "bench-1080p-half", &bench);
}

/// A 64x48 grid of quads (6144 triangles, each a few pixels) in clip space, w varying.
fn small_triangles() -> ClipMesh {
    const NX: u32 = 64;
    const NY: u32 = 48;
    let mut vertices = Vec::new();
    for j in 0..=NY {
        for i in 0..=NX {
            let (u, v) = (i as f32 / NX as f32, j as f32 / NY as f32);
            let w = 1.0 + 3.0 * f64::from(v);
            let ndc = (f64::from(u) * 2.0 - 1.0, f64::from(v) * 2.0 - 1.0);
            vertices.push(MeshVertex {
                clip: DVec4::new(ndc.0 * w, ndc.1 * w, 0.0, w),
                uv: Vec2::new(u, v),
                color: Vec3::ONE,
                normal: Vec3::ZERO,
            });
        }
    }
    let at = |i: u32, j: u32| j * (NX + 1) + i;
    let mut triangles = Vec::new();
    for j in 0..NY {
        for i in 0..NX {
            triangles.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            triangles.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    ClipMesh {
        vertices,
        triangles,
    }
}

fn bench_small_triangles(c: &mut Criterion) {
    let (w, h) = (800, 600);
    let mesh = small_triangles();
    let texture = Texture::builtin(BuiltinTexture::UvGrid);
    let mut group = c.benchmark_group("small-triangles-6144-800x600");
    for rasterizer in [Rasterizer::EdgeFunction, Rasterizer::Scanline] {
        let settings = RenderSettings {
            width: w,
            height: h,
            rasterizer,
            ..RenderSettings::default()
        };
        let mut frame = Framebuffer::empty();
        group.bench_function(format!("{rasterizer:?}"), |b| {
            b.iter(|| {
                render_into(&mut frame, &mesh, &texture, &settings, Buffers::ColorDepth)
                    .expect("render")
            })
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench_scenes, bench_small_triangles
}
criterion_main!(benches);
