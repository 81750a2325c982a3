//! Render benchmarks: the default scene at the app's 1x canvas size.

use barylab::raster::{BuiltinTexture, Interpolation, Texture, render};
use barylab::scene::Scene;
use criterion::{Criterion, criterion_group, criterion_main};

fn bench_render(c: &mut Criterion) {
    let texture = Texture::builtin(BuiltinTexture::UvGrid);
    let mut scene = Scene::default_scene();
    scene.set_size(800, 600);
    let mesh = scene.to_mesh();
    for mode in [Interpolation::Perspective, Interpolation::Affine] {
        let settings = barylab::raster::RenderSettings {
            mode,
            ..scene.settings()
        };
        c.bench_function(&format!("default scene 800x600 {mode:?}"), |b| {
            b.iter(|| render(&mesh, &texture, &settings).expect("render"))
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20);
    targets = bench_render
}
criterion_main!(benches);
