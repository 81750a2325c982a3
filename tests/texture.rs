//! Texture sampling against hand-computed texel rules (OpenGL 4.6, 8.14).

use barylab::raster::texture::{
    BuiltinTexture, Filter, Texture, Wrap, bilinear_weights, byte_from_sum,
};
use glam::Vec2;
use proptest::prelude::*;

fn seed_2x2() -> Texture {
    Texture::builtin(BuiltinTexture::Rgbw2x2)
}

fn rgb(c: [f32; 4]) -> [u8; 3] {
    [c[0], c[1], c[2]].map(barylab::raster::shade::unorm8)
}

#[test]
fn seed_001_texture_layout() {
    // Seed 001: (0,0) red, (0,1) white, (1,0) green, (1,1) blue, second index = v.
    let t = seed_2x2();
    let at = |u, v| rgb(t.sample(Vec2::new(u, v), Filter::Nearest, Wrap::ClampToEdge));
    assert_eq!(at(0.25, 0.25), [255, 0, 0]);
    assert_eq!(at(0.25, 0.75), [255, 255, 255]);
    assert_eq!(at(0.75, 0.25), [0, 255, 0]);
    assert_eq!(at(0.75, 0.75), [0, 0, 255]);
}

#[test]
fn bilinear_blends_the_four_nearest_texels() {
    let t = seed_2x2();
    // The texture centre: a quarter of each of red, white, green, blue.
    let c = t.sample(Vec2::new(0.5, 0.5), Filter::Bilinear, Wrap::ClampToEdge);
    let expect = [
        (255.0 + 255.0) / 4.0,
        (255.0 + 255.0) / 4.0,
        (255.0 + 255.0) / 4.0,
    ];
    for k in 0..3 {
        assert!(
            (c[k] * 255.0 - expect[k]).abs() < 1e-3,
            "channel {k}: {}",
            c[k] * 255.0
        );
    }
    // At a texel centre bilinear equals nearest.
    let red = t.sample(Vec2::new(0.25, 0.25), Filter::Bilinear, Wrap::Repeat);
    assert_eq!(rgb(red), [255, 0, 0]);
    // Halfway between red (0,0) and green (1,0) along u, on row 0, with clamp: 50/50.
    let c = t.sample(Vec2::new(0.5, 0.25), Filter::Bilinear, Wrap::ClampToEdge);
    assert_eq!(rgb(c), [128, 128, 0]);
}

#[test]
fn wrap_modes_outside_the_unit_square() {
    let t = seed_2x2();
    let at = |u, w| rgb(t.sample(Vec2::new(u, 0.25), Filter::Nearest, w));
    // u = 1.25 -> texel 2: repeat -> 0 (red); clamp -> 1 (green); mirrored -> 1 (green).
    assert_eq!(at(1.25, Wrap::Repeat), [255, 0, 0]);
    assert_eq!(at(1.25, Wrap::ClampToEdge), [0, 255, 0]);
    assert_eq!(at(1.25, Wrap::MirroredRepeat), [0, 255, 0]);
    // u = -0.25 -> texel -1: repeat -> 1 (green); clamp -> 0 (red); mirrored -> 0 (red).
    assert_eq!(at(-0.25, Wrap::Repeat), [0, 255, 0]);
    assert_eq!(at(-0.25, Wrap::ClampToEdge), [255, 0, 0]);
    assert_eq!(at(-0.25, Wrap::MirroredRepeat), [255, 0, 0]);
    // Bilinear with repeat at u = 0 blends the last and first columns.
    let c = t.sample(Vec2::new(0.0, 0.25), Filter::Bilinear, Wrap::Repeat);
    assert_eq!(rgb(c), [128, 128, 0]);
}

#[test]
fn huge_and_nan_texture_coordinates_do_not_panic() {
    let t = Texture::builtin(BuiltinTexture::Checker);
    for uv in [
        Vec2::new(1e30, -1e30),
        Vec2::new(f32::NAN, 0.5),
        Vec2::new(f32::INFINITY, f32::NEG_INFINITY),
    ] {
        for f in [Filter::Nearest, Filter::Bilinear] {
            for w in [Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat] {
                let c = t.sample(uv, f, w);
                assert!(c.iter().all(|x| x.is_finite()));
            }
        }
    }
}

#[test]
fn uv_grid_cells_differ_and_carry_labels() {
    let t = Texture::builtin(BuiltinTexture::UvGrid);
    assert_eq!((t.width(), t.height()), (512, 512));
    // Two diagonal cells have different tints (the grid shows where uv goes).
    assert_ne!(t.texel(8, 8), t.texel(8 + 64 * 7, 8 + 64 * 7));
    // Each cell's interior holds label text: dark texels near its centre.
    let dark = (0..64u32)
        .flat_map(|y| (0..64u32).map(move |x| (x, y)))
        .filter(|&(x, y)| t.texel(x, y)[0] < 90 && x > 4 && y > 4 && x < 60 && y < 60)
        .count();
    assert!(dark > 30, "only {dark} dark texels in cell (0,0)");
}

#[test]
fn mip_chain_halves_down_to_one_texel_with_box_averages() {
    let t = Texture::builtin(BuiltinTexture::Checker);
    // 256 -> 128 -> ... -> 1: 9 levels.
    assert_eq!(t.levels(), 9);
    assert_eq!(t.level_size(3), (32, 32));
    assert_eq!(t.level_size(8), (1, 1));
    // The 1x1 level is the mean of the checker: (40 + 235) / 2 = 137.5, box-rounded per level.
    let last = t.texel_at(8, 0, 0);
    assert!((i32::from(last[0]) - 138).abs() <= 1, "{last:?}");
    // Level 1 of the seed-001 2x2 texture: the rounded mean of red, green, white, blue.
    let s = seed_2x2();
    assert_eq!(s.levels(), 2);
    assert_eq!(s.texel_at(1, 0, 0), [128, 128, 128, 255]);
    // Odd sizes: 3x1 -> 1x1 (floor(3/2) = 1), averaging texels 0 and 1.
    let odd = Texture::from_texels(
        3,
        1,
        vec![[0, 0, 0, 255], [200, 0, 0, 255], [100, 0, 0, 255]],
    )
    .expect("3x1");
    assert_eq!(odd.levels(), 2);
    assert_eq!(odd.texel_at(1, 0, 0), [100, 0, 0, 255]);
}

#[test]
fn trilinear_blends_two_levels_by_the_fraction_of_lambda() {
    let s = seed_2x2();
    let uv = Vec2::new(0.25, 0.25);
    // lambda <= 0: bilinear on level 0 (texel centre: pure red).
    assert_eq!(
        rgb(s.sample_lod(uv, Filter::Trilinear, Wrap::Repeat, -1.0)),
        [255, 0, 0]
    );
    // lambda = 1 (the last level): the 1x1 grey.
    assert_eq!(
        rgb(s.sample_lod(uv, Filter::Trilinear, Wrap::Repeat, 1.0)),
        [128, 128, 128]
    );
    // lambda = 0.25: 3/4 red + 1/4 grey (128): (0.75 * 255 + 0.25 * 128, 0.25 * 128, ...).
    let c = s.sample_lod(uv, Filter::Trilinear, Wrap::Repeat, 0.25);
    assert_eq!(rgb(c), [223, 32, 32]);
}

proptest::proptest! {
    /// The renderer's direct lookup equals summing the taps the probe shows, bit for bit.
    #[test]
    fn direct_sampling_equals_the_listed_taps(
        u in -3.0f32..3.0, v in -3.0f32..3.0, lambda in -2.0f32..12.0,
        filter in 0usize..3, wrap in 0usize..3, which in 0usize..3,
    ) {
        let tex = [BuiltinTexture::Rgbw2x2, BuiltinTexture::Checker, BuiltinTexture::UvGrid][which];
        let t = Texture::builtin(tex);
        let filter = [Filter::Nearest, Filter::Bilinear, Filter::Trilinear][filter];
        let wrap = [Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat][wrap];
        let uv = Vec2::new(u, v);
        let mut sum = [0.0f32; 4];
        for tap in &t.taps_lod(uv, filter, wrap, lambda) {
            let c = t.texel_at(tap.level, tap.i, tap.j);
            for k in 0..4 {
                sum[k] += tap.weight * f32::from(c[k]);
            }
        }
        proptest::prop_assert_eq!(t.sample_lod(uv, filter, wrap, lambda), sum.map(|c| c / 255.0));
    }
}

proptest! {
    /// Four equal texel values `c` blended with any bilinear weights round back to `c` (the
    /// sum's rounding error is about `c * 1e-6`): the vector lanes skip the alpha sum of an
    /// opaque texture on this ground.
    #[test]
    fn bilinear_sum_of_equal_texels_rounds_to_the_texel(
        a in 0.0f32..=1.0,
        b in 0.0f32..=1.0,
        c in 0u8..=255,
    ) {
        let w = bilinear_weights(a, b);
        let x = f32::from(c);
        let sum = ((w[0] * x + w[1] * x) + w[2] * x) + w[3] * x;
        prop_assert_eq!(byte_from_sum(sum), c);
    }
}

#[test]
fn bilinear_alpha_of_an_opaque_texture_is_255() {
    let t = Texture::builtin(BuiltinTexture::Noise);
    assert!(t.is_opaque());
    for k in 0..2000 {
        let uv = Vec2::new(k as f32 * 0.000_731, k as f32 * 0.001_377 - 0.7);
        let c = t.sample_rgba8(uv, Filter::Bilinear, Wrap::Repeat, 0.0);
        assert_eq!(c[3], 255, "uv {uv}");
    }
    let clear = Texture::from_texels(1, 1, vec![[1, 2, 3, 254]]).expect("texture");
    assert!(!clear.is_opaque());
}
