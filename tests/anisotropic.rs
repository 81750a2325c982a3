//! Anisotropic and trilinear filtering against a computation written here in f64 (mipmaps,
//! bilinear, trilinear, the probes), on hand-worked footprints; anisotropy 1 is trilinear bit
//! for bit; scene and command-line errors name the file and the field.

use barylab::raster::texture::{Anisotropic, MaxAnisotropy, footprint_axes, lod};
use barylab::raster::{Filter, Texture, Wrap, render};
use barylab::scene::Scene;
use glam::Vec2;

const SIZE: u32 = 8;

/// An 8x8 texture whose texels all differ: channel values from the column and row.
fn texels() -> Vec<[u8; 4]> {
    (0..SIZE * SIZE)
        .map(|k| {
            let (i, j) = (k % SIZE, k / SIZE);
            [
                ((i * 37 + j * 11) % 256) as u8,
                ((i * 13 + j * 71) % 256) as u8,
                ((i * j * 29 + 5) % 256) as u8,
                255,
            ]
        })
        .collect()
}

/// The mipmap pyramid in f64, recomputed: each level's texel the rounded mean
/// `(sum + 2) / 4` of the 2x2 it covers (a 2^k square texture has no odd edge).
fn pyramid() -> Vec<(u32, Vec<[f64; 4]>)> {
    let mut levels = vec![(SIZE, texels().iter().map(|t| t.map(f64::from)).collect())];
    while levels.last().expect("a level").0 > 1 {
        let (w, prev): &(u32, Vec<[f64; 4]>) = levels.last().expect("a level");
        let n = w / 2;
        let at = |i: u32, j: u32| prev[(j * w + i) as usize];
        let next = (0..n * n)
            .map(|k| {
                let (i, j) = (k % n, k / n);
                let q = [
                    at(2 * i, 2 * j),
                    at(2 * i + 1, 2 * j),
                    at(2 * i, 2 * j + 1),
                    at(2 * i + 1, 2 * j + 1),
                ];
                [0, 1, 2, 3].map(|c| ((q.iter().map(|t| t[c]).sum::<f64>() + 2.0) / 4.0).floor())
            })
            .collect();
        levels.push((n, next));
    }
    levels
}

/// GL_LINEAR in one level with GL_REPEAT, in f64.
fn bilinear(levels: &[(u32, Vec<[f64; 4]>)], level: usize, uv: [f64; 2]) -> [f64; 4] {
    let (w, t) = &levels[level];
    let w = f64::from(*w);
    let (x, y) = (uv[0] * w - 0.5, uv[1] * w - 0.5);
    let (i0, j0) = (x.floor(), y.floor());
    let (a, b) = (x - i0, y - j0);
    let texel = |i: f64, j: f64| {
        let (i, j) = (i.rem_euclid(w) as usize, j.rem_euclid(w) as usize);
        t[j * w as usize + i]
    };
    [0, 1, 2, 3].map(|c| {
        (1.0 - a) * (1.0 - b) * texel(i0, j0)[c]
            + a * (1.0 - b) * texel(i0 + 1.0, j0)[c]
            + (1.0 - a) * b * texel(i0, j0 + 1.0)[c]
            + a * b * texel(i0 + 1.0, j0 + 1.0)[c]
    })
}

/// GL_LINEAR_MIPMAP_LINEAR at `lambda`, in f64.
fn trilinear(levels: &[(u32, Vec<[f64; 4]>)], uv: [f64; 2], lambda: f64) -> [f64; 4] {
    let last = (levels.len() - 1) as f64;
    if lambda <= 0.0 {
        return bilinear(levels, 0, uv);
    }
    let lambda = lambda.min(last);
    let d = lambda.floor();
    let f = lambda - d;
    let lo = bilinear(levels, d as usize, uv);
    if f == 0.0 {
        return lo;
    }
    let hi = bilinear(levels, d as usize + 1, uv);
    [0, 1, 2, 3].map(|c| (1.0 - f) * lo[c] + f * hi[c])
}

/// EXT_texture_filter_anisotropic in f64: the probes along the major axis, averaged.
/// Returns the colour, N and lambda.
fn anisotropic(
    levels: &[(u32, Vec<[f64; 4]>)],
    uv: [f64; 2],
    [dx, dy]: [[f64; 2]; 2],
    max: u32,
) -> ([f64; 4], u32, f64) {
    let s = f64::from(SIZE);
    let px = (dx[0] * s).hypot(dx[1] * s);
    let py = (dy[0] * s).hypot(dy[1] * s);
    let (p_max, p_min, major) = if py > px { (py, px, dy) } else { (px, py, dx) };
    let n = ((p_max / p_min).ceil() as u32).min(max);
    let lambda = (p_max / f64::from(n)).log2();
    let mut sum = [0.0; 4];
    for i in 1..=n {
        let t = f64::from(i) / f64::from(n + 1) - 0.5;
        let c = trilinear(levels, [uv[0] + t * major[0], uv[1] + t * major[1]], lambda);
        for k in 0..4 {
            sum[k] += c[k] / f64::from(n);
        }
    }
    (sum, n, lambda)
}

fn texture() -> Texture {
    Texture::from_texels(SIZE, SIZE, texels()).expect("8x8 texture")
}

fn v2(a: [f64; 2]) -> Vec2 {
    Vec2::new(a[0] as f32, a[1] as f32)
}

/// Each channel of `got` is the f64 colour rounded (within the f32 sum's error).
fn assert_rounds_to(got: [u8; 4], want: [f64; 4], what: &str) {
    for k in 0..4 {
        let d = (f64::from(got[k]) - want[k]).abs();
        assert!(d <= 0.5 + 1e-3, "{what}: channel {k}: {got:?} vs {want:?}");
    }
}

/// Hand-worked footprints on the 8x8 texture: derivatives, the largest anisotropy, and the
/// N and lambda they must give.
const FOOTPRINTS: [([[f64; 2]; 2], u32, u32, f64); 4] = [
    // Px = 0.5 * 8 = 4 texels, Py = 1: N = 4, lambda = log2(4 / 4) = 0 (the base level).
    ([[0.5, 0.0], [0.0, 0.125]], 16, 4, 0.0),
    // Px = 6, Py = 1, at most 4 probes: N = 4, lambda = log2(6 / 4) = 0.585.
    ([[0.75, 0.0], [0.0, 0.125]], 4, 4, 0.584_962_500_721_156_2),
    // Py = |(3, 4)| = 5 along y, Px = 0: N = the largest, 2; lambda = log2(5 / 2).
    ([[0.0, 0.0], [0.375, 0.5]], 2, 2, 1.321_928_094_887_362_3),
    // Px = Py = 2 (a square footprint, turned): N = 1, lambda = 1, trilinear.
    ([[0.25, 0.0], [0.0, 0.25]], 16, 1, 1.0),
];

const UVS: [[f64; 2]; 3] = [[0.37, 0.61], [0.02, 0.97], [0.5, 0.5]];

#[test]
fn anisotropic_colours_match_the_probes_computed_here() {
    let t = texture();
    let levels = pyramid();
    for (duv, max, n, lambda) in FOOTPRINTS {
        let m = MaxAnisotropy::new(max).expect("anisotropy");
        let a = Anisotropic::of(v2(duv[0]), v2(duv[1]), (SIZE, SIZE), m);
        assert_eq!(a.n, n, "{duv:?}: N");
        assert!(
            (f64::from(a.lambda) - lambda).abs() < 1e-6,
            "{duv:?}: lambda {}",
            a.lambda
        );
        for uv in UVS {
            let (want, n_here, lambda_here) = anisotropic(&levels, uv, duv, max);
            assert_eq!((n_here, (lambda_here - lambda).abs() < 1e-12), (n, true));
            let got = t.sample_anisotropic_rgba8(v2(uv), Wrap::Repeat, duv.map(v2), m);
            assert_rounds_to(got, want, &format!("uv {uv:?}, footprint {duv:?}"));
        }
    }
}

#[test]
fn trilinear_colours_match_the_levels_computed_here() {
    let t = texture();
    let levels = pyramid();
    // Px = 3, Py = 1: lambda = log2(3) = 1.585, 0.415 of level 1 and 0.585 of level 2;
    // Px = 1.5: lambda 0.585; Px = 16: past the last level (3), the 1x1 level alone.
    for (dx, lambda) in [(0.375, 3f64.log2()), (0.1875, 1.5f64.log2()), (2.0, 4.0)] {
        let l = lod(Vec2::new(dx as f32, 0.0), Vec2::new(0.0, 0.125), SIZE, SIZE);
        assert!(
            (f64::from(l) - lambda).abs() < 1e-6,
            "lambda {l} vs {lambda}"
        );
        for uv in UVS {
            let got = t.sample_rgba8(v2(uv), Filter::Trilinear, Wrap::Repeat, l);
            let want = trilinear(&levels, uv, f64::from(l));
            assert_rounds_to(got, want, &format!("uv {uv:?}, lambda {l}"));
        }
    }
}

proptest::proptest! {
    /// A square footprint (the derivatives turned by 90 degrees: Px = Py exactly) gives one
    /// probe, and the colour is trilinear's at log2(Px), bit for bit, whatever the largest
    /// anisotropy.
    #[test]
    fn one_probe_is_trilinear_bit_for_bit(
        u in -2.0f32..2.0, v in -2.0f32..2.0, a in -0.5f32..0.5, b in -0.5f32..0.5,
        max in 1u32..=16,
    ) {
        let t = Texture::builtin(barylab::raster::BuiltinTexture::UvGrid);
        let (dx, dy) = (Vec2::new(a, b), Vec2::new(-b, a));
        let [px, py] = footprint_axes(dx, dy, t.width(), t.height());
        proptest::prop_assume!(px > 0.0);
        proptest::prop_assert_eq!(px, py);
        let m = MaxAnisotropy::new(max).expect("anisotropy");
        let uv = Vec2::new(u, v);
        let lambda = lod(dx, dy, t.width(), t.height());
        proptest::prop_assert_eq!(
            t.sample_anisotropic_rgba8(uv, Wrap::Repeat, [dx, dy], m),
            t.sample_rgba8(uv, Filter::Trilinear, Wrap::Repeat, lambda)
        );
    }
}

fn far_checker() -> Scene {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/assets/scenes/far-checker.json"
    );
    Scene::load(std::path::Path::new(path)).expect("far-checker scene")
}

#[test]
fn anisotropy_1_renders_todays_trilinear_and_16_sharpens_the_horizon() {
    let scene = far_checker();
    let tex = scene
        .load_texture(std::path::Path::new("."))
        .expect("texture");
    let mesh = scene.to_mesh();
    let base = scene.settings();
    assert_eq!(base.max_anisotropy, MaxAnisotropy::default());
    let with = |n| {
        let mut s = base;
        s.max_anisotropy = MaxAnisotropy::new(n).expect("anisotropy");
        render(&mesh, &tex, &s).expect("render").frame
    };
    let trilinear = render(&mesh, &tex, &base).expect("render").frame;
    assert!(
        with(1).color == trilinear.color,
        "anisotropy 1 is not trilinear"
    );
    // Contrast of the band of rows just below the horizon: the mean distance of the grey
    // levels from their mean. Trilinear blurs the far squares to grey; 16 probes keep them.
    let contrast = |f: &barylab::raster::Framebuffer| {
        let first = (0..f.height)
            .find(|&y| f.covered(f.width / 2, y))
            .expect("horizon");
        let greys: Vec<f64> = (first + 4..first + 14)
            .flat_map(|y| (0..f.width).map(move |x| (x, y)))
            .map(|(x, y)| f64::from(f.color[f.index(x, y)][0]))
            .collect();
        let mean = greys.iter().sum::<f64>() / greys.len() as f64;
        greys.iter().map(|g| (g - mean).abs()).sum::<f64>() / greys.len() as f64
    };
    let (c1, c16) = (contrast(&trilinear), contrast(&with(16)));
    assert!(
        c16 > 2.0 * c1,
        "contrast below the horizon: anisotropic {c16} vs trilinear {c1}"
    );
}

#[test]
fn a_bad_max_anisotropy_names_the_file_and_the_field() {
    let text = |v: &str| {
        format!(
            r#"{{"width": 8, "height": 8, "quad": [
            {{"position": [0, 0, -1], "uv": [0, 0]}}, {{"position": [1, 0, -1], "uv": [1, 0]}},
            {{"position": [1, 1, -1], "uv": [1, 1]}}, {{"position": [0, 1, -1], "uv": [0, 1]}}],
            "filter": "trilinear", "max_anisotropy": {v}}}"#
        )
    };
    for (v, says) in [
        ("0", "from 1 (off) to 16, not 0"),
        ("17", "from 1 (off) to 16, not 17"),
        ("2.5", "expected a whole number"),
        ("\"x\"", "expected a whole number"),
    ] {
        let e = Scene::from_json(&text(v), "floor.json")
            .expect_err(v)
            .to_string();
        assert!(e.starts_with("floor.json:"), "{e}");
        assert!(
            e.contains("field `max_anisotropy`") && e.contains(says),
            "{v}: {e}"
        );
    }
    let ok = Scene::from_json(&text("8"), "floor.json").expect("8 is fine");
    assert_eq!(ok.settings().max_anisotropy.get(), 8);
    // Written back only when not the default.
    assert!(ok.to_json().contains("\"max_anisotropy\": 8"));
    assert!(!far_checker().to_json().contains("max_anisotropy"));
}
