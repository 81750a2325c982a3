//! The probe's level-of-detail derivation: its numbers follow from each other as the formulas
//! say (checked here from the quad's uvs), its colour is the rendered pixel's (trilinear and
//! anisotropic), helper pixels are named, fine derivatives use the pixel's own row and column,
//! and every format and both languages carry it.

use std::path::Path;

use barylab::i18n::Lang;
use barylab::probe::format::{Format, write_in};
use barylab::probe::{LodTrace, PixelTrace, Prober};
use barylab::raster::interpolate::Derivatives;
use barylab::raster::texture::MaxAnisotropy;
use barylab::raster::{Filter, Texture, Wrap, render};
use barylab::scene::Scene;
use glam::Vec2;

fn far_checker() -> (Scene, Texture) {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/assets/scenes/far-checker.json"
    );
    let scene = Scene::load(Path::new(path)).expect("far-checker scene");
    let tex = scene.load_texture(Path::new(".")).expect("texture");
    (scene, tex)
}

fn lod_of(trace: &PixelTrace) -> &LodTrace {
    trace
        .detail
        .as_ref()
        .and_then(|d| d.attribute.as_ref())
        .and_then(|a| a.lod.as_ref())
        .expect("a level-of-detail derivation")
}

fn uv(q: Option<[f32; 2]>) -> Vec2 {
    Vec2::from_array(q.expect("uv at a quad pixel"))
}

/// Checks the derivation's arithmetic from the quad's uvs, with the formulas written out.
fn check_numbers(lt: &LodTrace, tex: &Texture, max: u32) {
    let q: Vec<Vec2> = lt.quad.iter().map(|p| uv(p.uv)).collect();
    // Coarse: d/dx from the first row, d/dy from the first column.
    assert_eq!(Vec2::from_array(lt.duv_dx), q[1] - q[0]);
    assert_eq!(Vec2::from_array(lt.duv_dy), q[2] - q[0]);
    let (w, h) = (tex.width() as f32, tex.height() as f32);
    let len = |d: [f32; 2]| ((d[0] * w).powi(2) + (d[1] * h).powi(2)).sqrt();
    assert!((lt.px - len(lt.duv_dx)).abs() <= 1e-5 * lt.px.max(1.0));
    assert!((lt.py - len(lt.duv_dy)).abs() <= 1e-5 * lt.py.max(1.0));
    assert_eq!(lt.rho, lt.px.max(lt.py));
    assert!((lt.trilinear.lambda - lt.rho.log2()).abs() < 1e-6);
    let Some(a) = &lt.anisotropic else {
        assert_eq!(max, 1);
        return;
    };
    let n = ((a.p_max / a.p_min).ceil() as u32).min(max);
    assert_eq!(a.n, n);
    assert!((a.levels.lambda - (a.p_max / n as f32).log2()).abs() < 1e-6);
    let major = if a.major_y { lt.duv_dy } else { lt.duv_dx };
    for (i, p) in a.probes.iter().enumerate() {
        let t = (i + 1) as f32 / (n + 1) as f32 - 0.5;
        assert_eq!(p.offset, t);
        let want = Vec2::from_array(lt.uv) + Vec2::from_array(major) * t;
        assert!((Vec2::from_array(p.uv) - want).length() < 1e-6, "probe {i}");
        let c = tex.sample_rgba8(want, Filter::Trilinear, Wrap::Repeat, a.levels.lambda);
        assert_eq!(p.color, c, "probe {i}");
    }
}

#[test]
fn the_derivation_adds_up_and_gives_the_rendered_colour() {
    let (scene, tex) = far_checker();
    for max in [1, 4, 16] {
        let mut settings = scene.settings();
        settings.max_anisotropy = MaxAnisotropy::new(max).expect("anisotropy");
        let frame = render(&scene.to_mesh(), &tex, &settings)
            .expect("render")
            .frame;
        let prober = Prober::new(&scene, &tex, &settings).expect("prober");
        let mut checked = 0;
        for y in (150..300).step_by(7) {
            for x in (0..480).step_by(23) {
                let trace = prober.pixel(x, y).expect("probe");
                if !frame.covered(x, y) {
                    continue;
                }
                let lt = lod_of(&trace);
                check_numbers(lt, &tex, max);
                assert_eq!(
                    lt.color,
                    frame.color[frame.index(x, y)],
                    "({x}, {y}), max {max}"
                );
                assert_eq!(trace.color, lt.color, "({x}, {y}), max {max}");
                checked += 1;
            }
        }
        assert!(checked > 100, "{checked} pixels checked");
    }
}

#[test]
fn helper_pixels_outside_the_triangle_are_named() {
    let (scene, tex) = far_checker();
    let settings = scene.settings();
    let frame = render(&scene.to_mesh(), &tex, &settings)
        .expect("render")
        .frame;
    let prober = Prober::new(&scene, &tex, &settings).expect("prober");
    // The horizon: a column whose first covered row is odd, so the quad's upper row is
    // above the floor, outside the triangle.
    let first = |x: u32| {
        (0..frame.height)
            .find(|&y| frame.covered(x, y))
            .expect("horizon")
    };
    let x = (100..380)
        .find(|&x| first(x) % 2 == 1)
        .expect("an odd horizon row");
    let y = first(x);
    let trace = prober.pixel(x, y).expect("probe");
    let lt = lod_of(&trace);
    let outside: Vec<[u32; 2]> = lt
        .quad
        .iter()
        .filter(|q| !q.inside)
        .map(|q| q.pixel)
        .collect();
    assert!(
        outside.contains(&[x & !1, y - 1]),
        "({x}, {y}): {outside:?}"
    );
    assert!(
        lt.quad[0].uv.is_some(),
        "the helper pixel's uv is extrapolated"
    );
    let text = write_in(&trace, Format::Text, Lang::En);
    assert!(text.contains("helper pixels"), "{text}");
    assert!(text.contains(&format!("({}, {})", outside[0][0], outside[0][1])));
    let zh = write_in(&trace, Format::Text, Lang::Zh);
    assert!(zh.contains("辅助像素"), "{zh}");
}

#[test]
fn fine_derivatives_use_the_pixels_own_row_and_column() {
    let (scene, tex) = far_checker();
    let settings = scene.settings();
    let mut prober = Prober::new(&scene, &tex, &settings).expect("prober");
    prober.set_derivatives(Derivatives::Fine);
    // The quad's bottom-right pixel: its own row is the quad's second, its column the second.
    let trace = prober.pixel(241, 201).expect("probe");
    let lt = lod_of(&trace);
    assert_eq!(lt.derivatives, Derivatives::Fine);
    let q: Vec<Vec2> = lt.quad.iter().map(|p| uv(p.uv)).collect();
    assert_eq!(Vec2::from_array(lt.duv_dx), q[3] - q[2]);
    assert_eq!(Vec2::from_array(lt.duv_dy), q[3] - q[1]);
    // Perspective makes the rows differ: fine is not coarse here.
    assert_ne!(Vec2::from_array(lt.duv_dx), q[1] - q[0]);
    let text = write_in(&trace, Format::Text, Lang::En);
    assert!(text.contains("(du/dx, dv/dx) = uv_11 - uv_01"), "{text}");
}

#[test]
fn every_format_and_both_languages_carry_the_derivation() {
    let (scene, tex) = far_checker();
    let mut settings = scene.settings();
    settings.max_anisotropy = MaxAnisotropy::new(16).expect("anisotropy");
    let trace = Prober::new(&scene, &tex, &settings)
        .expect("prober")
        .pixel(240, 160)
        .expect("probe");
    let n = lod_of(&trace).anisotropic.as_ref().expect("anisotropic").n;
    let text = write_in(&trace, Format::Text, Lang::En);
    assert!(text.contains("Level of detail: from uv to texel"));
    assert!(text.contains("P_x = |(du/dx·W, dv/dx·H)|"));
    assert!(text.contains(&format!("uv_{n} = uv + ")), "the last probe");
    let md = write_in(&trace, Format::Markdown, Lang::En);
    assert!(
        md.contains("Level of detail") && md.contains("P_{\\mathrm{max}}"),
        "{md}"
    );
    let tex_out = write_in(&trace, Format::Latex, Lang::En);
    assert!(tex_out.contains("\\lambda_{\\mathrm{aniso}}"), "{tex_out}");
    let json: serde_json::Value =
        serde_json::from_str(&write_in(&trace, Format::Json, Lang::En)).expect("JSON");
    let lod = &json["detail"]["attribute"]["lod"];
    assert_eq!(lod["anisotropic"]["n"], n);
    assert_eq!(lod["derivatives"], "coarse");
    let zh = write_in(&trace, Format::Text, Lang::Zh);
    for word in [
        "细节层次",
        "多级渐远纹理",
        "各向异性过滤",
        "纹素",
        "双线性插值",
    ] {
        assert!(zh.contains(word), "{word}");
    }
}
