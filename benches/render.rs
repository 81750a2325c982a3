//! Criterion benchmarks of whole-frame rendering on the sample scenes.

use std::path::Path;

use barylab::raster::{Filter, Interpolation, render};
use barylab::scene::Scene;
use criterion::{Criterion, criterion_group, criterion_main};

fn scenes_dir() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/scenes"))
}

fn bench_default_scene(c: &mut Criterion) {
    let scene = Scene::default_scene();
    let texture = scene.load_texture(scenes_dir()).expect("texture");
    let mesh = scene.to_mesh();
    let mut group = c.benchmark_group("default-800x600");
    for mode in [Interpolation::Affine, Interpolation::Perspective] {
        for filter in [Filter::Nearest, Filter::Bilinear] {
            let mut settings = scene.settings();
            settings.mode = mode;
            settings.filter = filter;
            group.bench_function(format!("{mode:?}-{filter:?}"), |b| {
                b.iter(|| render(&mesh, &texture, &settings).expect("render"))
            });
        }
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20);
    targets = bench_default_scene
}
criterion_main!(benches);
