//! Criterion benchmarks of the pixel probe: what the app pays per hovered pixel per frame.

use std::hint::black_box;
use std::path::Path;

use barylab::probe::format::{self, Format};
use barylab::probe::{Prober, probe};
use barylab::scene::Scene;
use criterion::{Criterion, criterion_group, criterion_main};

fn scenes_dir() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/scenes"))
}

fn bench_probe(c: &mut Criterion) {
    let mut group = c.benchmark_group("probe");
    for (name, pixel) in [
        ("default.json", (400, 420)),
        ("corner-behind.json", (100, 400)),
    ] {
        let scene = Scene::load(&scenes_dir().join(name)).expect("scene");
        let texture = scene.load_texture(scenes_dir()).expect("texture");
        let settings = scene.settings();
        // One call from scratch: prepare the triangles, then trace the pixel.
        group.bench_function(format!("{name}/probe"), |b| {
            b.iter(|| probe(&scene, &texture, &settings, black_box(pixel)).expect("probe"))
        });
        // The triangles prepared once, one pixel traced.
        let prober = Prober::new(&scene, &texture, &settings).expect("prober");
        group.bench_function(format!("{name}/pixel"), |b| {
            b.iter(|| {
                prober
                    .pixel(black_box(pixel.0), black_box(pixel.1))
                    .expect("pixel")
            })
        });
        let trace = prober.pixel(pixel.0, pixel.1).expect("pixel");
        group.bench_function(format!("{name}/text"), |b| {
            b.iter(|| format::write(black_box(&trace), Format::Text))
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30);
    targets = bench_probe
}
criterion_main!(benches);
