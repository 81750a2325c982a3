//! MSAA into colour and depth only (`render_into` with `Buffers::ColorDepth`: the coverage
//! intervals, the lanes' centre colours and the uniform pixels of `raster::msaa_band`)
//! against the straightforward per-sample kernel (`render_samples`, which keeps every
//! sample): colour and depth bit for bit, on random overlapping scenes and the sample scenes,
//! with every pattern, count, location and shading, at every vector level.

mod common;

use barylab::raster::lanes::VectorLevel;
use barylab::raster::render::{ClipMesh, RenderSettings, render_into_at, render_samples};
use barylab::raster::sample::{Location, SampleCount, SamplePattern, SampleSettings};
use barylab::raster::setup::TieRule;
use barylab::raster::{Buffers, BuiltinTexture, Filter, Framebuffer, Interpolation, Shading};
use barylab::raster::{Texture, Wrap};
use common::four_triangles;
use proptest::prelude::*;

/// The fast path's colour and depth equal the per-sample kernel's, bit for bit, at every
/// vector level, in a fresh frame and in one reused from another render.
fn assert_same(mesh: &ClipMesh, tex: &Texture, s: &RenderSettings, what: &str) {
    let (reference, _) = render_samples(mesh, tex, s).expect("reference render");
    let want = &reference.frame;
    let mut reused = Framebuffer::empty();
    for vector in [
        VectorLevel::Scalar,
        VectorLevel::Portable,
        VectorLevel::current(),
    ] {
        let mut fresh = Framebuffer::empty();
        render_into_at(&mut fresh, mesh, tex, s, Buffers::ColorDepth, vector).expect("render");
        render_into_at(&mut reused, mesh, tex, s, Buffers::ColorDepth, vector).expect("render");
        for frame in [&fresh, &reused] {
            let colours = (frame.color.iter().zip(&want.color))
                .filter(|(a, b)| a != b)
                .count();
            let depths = (frame.depth.iter().zip(&want.depth))
                .filter(|(a, b)| a.to_bits() != b.to_bits())
                .count();
            assert_eq!(
                (colours, depths),
                (0, 0),
                "{what}, {vector:?}: colours and depths that differ"
            );
        }
    }
}

fn samples(count: SampleCount, pattern: SamplePattern, location: Location) -> SampleSettings {
    SampleSettings {
        count,
        pattern,
        location,
        ..SampleSettings::default()
    }
}

/// Every count and pattern with a location.
fn sample_settings() -> Vec<SampleSettings> {
    use SampleCount::*;
    use SamplePattern::*;
    let mut out = Vec::new();
    for location in [Location::Center, Location::Centroid] {
        for (c, p) in [
            (Four, Standard),
            (Four, Grid),
            (Eight, Standard),
            (Sixteen, Standard),
            (Sixteen, Grid),
        ] {
            out.push(samples(c, p, location));
        }
    }
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Random triangles (overlapping, so depth decides; both windings; some partly off
    /// screen; slivers; w from 0.3 to 12) with each texture filter, wrap and shading.
    #[test]
    fn msaa_fast_path_is_the_per_sample_kernel_on_random_scenes(
        pts in proptest::collection::vec((-30.0f64..110.0, -30.0f64..80.0, 0.3f64..12.0), 6),
        uv_scale in 0.5f32..6.0,
        persp in any::<bool>(),
        filter in 0usize..3,
        wrap in 0usize..3,
        wireframe in any::<bool>(),
        shading in 0usize..6,
        top_left in any::<bool>(),
        which in 0usize..10,
    ) {
        let (w, h) = (83, 61);
        let mesh = four_triangles(&pts, uv_scale, w, h);
        let tex = Texture::builtin(BuiltinTexture::Noise);
        let s = RenderSettings {
            width: w,
            height: h,
            mode: if persp { Interpolation::Perspective } else { Interpolation::Affine },
            filter: [Filter::Nearest, Filter::Bilinear, Filter::Trilinear][filter],
            wrap: [Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat][wrap],
            wireframe,
            shading: Shading::ALL[shading],
            tie_rule: if top_left { TieRule::TopLeft } else { TieRule::Llvmpipe },
            samples: sample_settings()[which],
            ..RenderSettings::default()
        };
        assert_same(&mesh, &tex, &s, "random scene");
    }
}

/// Every sample scene, at most 320x240, 4 standard and 4 grid samples, each location.
#[test]
fn msaa_fast_path_is_the_per_sample_kernel_on_the_sample_scenes() {
    let scenes = common::sample_scenes();
    assert!(scenes.len() >= 8);
    for (path, mut scene) in scenes {
        let dir = path.parent().expect("the scenes' folder");
        let (w, h) = scene.size();
        let k = (w / 320).max(h / 240).max(1);
        scene.set_size(w / k, h / k);
        let tex = scene.load_texture(dir).expect("texture");
        let mesh = scene.to_mesh();
        for pattern in [SamplePattern::Standard, SamplePattern::Grid] {
            for location in [Location::Center, Location::Centroid] {
                let s = RenderSettings {
                    samples: samples(SampleCount::Four, pattern, location),
                    ..scene.settings()
                };
                let what = format!("{} {pattern:?} {location:?}", path.display());
                assert_same(&mesh, &tex, &s, &what);
            }
        }
    }
}
