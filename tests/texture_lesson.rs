//! The built-in texture lesson: at least 12 steps in both languages, opened by name, every
//! step's scene renders and pins a covered pixel, and the numbers its text quotes are the
//! probe's (the level-of-detail derivation of the pinned pixel).

mod common;

use std::path::Path;

use barylab::figure::TexelView;
use barylab::lesson::Lesson;
use barylab::probe::PixelTrace;
use barylab::probe::format::fmt_number;
use barylab::raster::Filter;

fn lesson() -> Lesson {
    Lesson::open(Path::new("texture")).expect("the texture lesson")
}

/// The probe of step `n`'s pinned pixel (with trilinear filtering when `trilinear`, so the
/// level of detail is derived whatever the step's filter).
fn probe_step(lesson: &Lesson, n: usize, trilinear: bool) -> PixelTrace {
    let state = lesson.state(n - 1).expect("state");
    let texture = state.scene.load_texture(Path::new("")).expect("texture");
    let [x, y] = state.pin.expect("pinned");
    let mut settings = state.scene.settings();
    if trilinear {
        settings.filter = Filter::Trilinear;
    }
    barylab::probe::probe(&state.scene, &texture, &settings, (x, y)).expect("probe")
}

/// What step `n`'s text lacks of `v` (as the probe prints it), in each language.
fn missing(lesson: &Lesson, n: usize, v: f64) -> Vec<String> {
    let t = fmt_number(v).replace('-', "−");
    let step = &lesson.steps[n - 1];
    [("en", &step.text.en), ("zh", &step.text.zh)]
        .into_iter()
        .filter(|(_, text)| !text.contains(&t))
        .map(|(lang, _)| format!("step {n} ({lang}) does not quote {t}"))
        .collect()
}

#[test]
fn the_texture_lesson_has_12_steps_in_both_languages_and_opens_by_name() {
    let l = lesson();
    assert!(l.steps.len() >= 12, "{} steps", l.steps.len());
    assert_eq!(l.builtin, Some("texture"));
    assert_eq!(l.shown_path(), "texture");
    for (i, s) in l.steps.iter().enumerate() {
        for text in [&s.title, &s.text, &s.try_this] {
            assert!(
                !text.en.trim().is_empty() && !text.zh.trim().is_empty(),
                "step {}",
                i + 1
            );
        }
        assert!(!s.text.en.to_lowercase().contains("seed"), "step {}", i + 1);
    }
    // `builtin` stays the interpolation lesson's name.
    let b = Lesson::open(Path::new("builtin")).expect("builtin");
    let i = Lesson::open(Path::new("interpolation")).expect("interpolation");
    assert_eq!(b.title, i.title);
    assert_ne!(b.title, l.title);
}

#[test]
fn every_step_pins_a_covered_pixel() {
    let l = lesson();
    for n in 1..=l.steps.len() {
        let t = probe_step(&l, n, false);
        assert!(
            t.written_by.is_some(),
            "step {n}: the pinned pixel is not covered"
        );
    }
}

#[test]
fn numbers_quoted_in_the_texture_lesson_are_the_probes() {
    let l = lesson();
    let problems = std::cell::RefCell::new(Vec::new());
    let q = |n: usize, v: f64| problems.borrow_mut().extend(missing(&l, n, v));
    // 1: uv and texel coordinates; nearest reads texel (0, 0).
    let t = probe_step(&l, 1, false);
    let a = t
        .detail
        .as_ref()
        .and_then(|d| d.attribute.clone())
        .expect("attribute");
    for v in a
        .uv_perspective
        .into_iter()
        .map(f64::from)
        .chain(a.texel_perspective)
    {
        q(1, v);
    }
    assert_eq!((a.taps_perspective[0].i, a.taps_perspective[0].j), (0, 0));
    // 2: the half-texel offset and the weights by row; the colour.
    let t = probe_step(&l, 2, false);
    let a = t
        .detail
        .as_ref()
        .and_then(|d| d.attribute.clone())
        .expect("attribute");
    q(2, a.texel_perspective[0] - 0.5);
    q(2, a.texel_perspective[1] - 0.5);
    let row = |j: u32| {
        a.taps_perspective
            .iter()
            .filter(|t| t.j == j)
            .map(|t| f64::from(t.weight))
            .sum::<f64>()
    };
    q(2, row(0));
    q(2, row(1));
    assert!(l.steps[1].text.en.contains(&format!(
        "rgba({}, {}, {})",
        t.color[0], t.color[1], t.color[2]
    )));
    // 3: magnification.
    let lt = common::lod_of(&probe_step(&l, 3, false)).clone();
    q(3, f64::from(lt.duv_dx[0]));
    q(3, f64::from(lt.px));
    q(3, f64::from(lt.trilinear.lambda));
    assert!(lt.trilinear.lambda < 0.0);
    // 4: the footprint's long side, measured with the level of detail's derivatives.
    q(4, f64::from(common::lod_of(&probe_step(&l, 4, true)).py));
    // 5: the quad's uvs and the derivatives.
    let lt = common::lod_of(&probe_step(&l, 5, false)).clone();
    for p in &lt.quad[..3] {
        for c in p.uv.expect("uv") {
            q(5, f64::from(c));
        }
    }
    for v in lt.duv_dx.into_iter().chain(lt.duv_dy) {
        q(5, f64::from(v));
    }
    // 6: the footprint, rho, lambda.
    let lt = common::lod_of(&probe_step(&l, 6, false)).clone();
    for v in [lt.px, lt.py, lt.rho, lt.trilinear.lambda] {
        q(6, f64::from(v));
    }
    // 7: the number of levels and lambda lower on the floor.
    let lt = common::lod_of(&probe_step(&l, 7, false)).clone();
    q(7, f64::from(lt.levels));
    q(7, f64::from(lt.trilinear.lambda));
    assert_eq!(lt.trilinear.level, 2);
    // 8: trilinear's two levels and weights; the colour.
    let t = probe_step(&l, 8, false);
    let lt = common::lod_of(&t).clone();
    let (next, f) = lt.trilinear.next.expect("two levels");
    assert_eq!((lt.trilinear.level, next), (4, 5));
    q(8, f64::from(lt.trilinear.lambda));
    q(8, 1.0 - f64::from(f));
    q(8, f64::from(f));
    assert!(
        l.steps[7]
            .text
            .en
            .contains(&format!("rgba({0}, {0}, {0})", t.color[0]))
    );
    // 9: magnified near the camera.
    let lt = common::lod_of(&probe_step(&l, 9, false)).clone();
    for v in [lt.px, lt.py, lt.trilinear.lambda] {
        q(9, f64::from(v));
    }
    assert!(lt.trilinear.lambda < 0.0);
    // 10: the footprint's sides and their ratio.
    let lt = common::lod_of(&probe_step(&l, 10, false)).clone();
    q(10, f64::from(lt.py));
    q(10, f64::from(lt.px));
    q(10, f64::from(lt.py / lt.px));
    // 11: anisotropic: N, lambda, the colour.
    let t = probe_step(&l, 11, false);
    let lt = common::lod_of(&t).clone();
    let an = lt.anisotropic.as_ref().expect("anisotropic");
    q(11, f64::from(an.p_max));
    q(11, f64::from(an.p_min));
    q(11, f64::from(an.n));
    q(11, f64::from(an.levels.lambda));
    assert!(
        l.steps[10]
            .text
            .en
            .contains(&format!("rgba({0}, {0}, {0})", t.color[0]))
    );
    // 12: affine uv: its lambda and footprint against the perspective-correct ones.
    let t = probe_step(&l, 12, false);
    let a = t
        .detail
        .as_ref()
        .and_then(|d| d.attribute.clone())
        .expect("attribute");
    let lt = a.lod.clone().expect("lod");
    let tri = a.trilinear.expect("trilinear");
    q(12, f64::from(tri.lod_affine));
    q(12, f64::from(tri.lod_perspective));
    q(12, f64::from(lt.py));
    for v in a.uv_affine {
        q(12, f64::from(v));
    }
    let problems = problems.into_inner();
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// The view a step's words name, in one language: the texture-space view, the
/// level-of-detail view, or none.
fn named_view(text: &str, texture: &str, lod: &str) -> Option<TexelView> {
    match (text.contains(texture), text.contains(lod)) {
        (true, false) => Some(TexelView::Texture),
        (false, true) => Some(TexelView::Lod),
        _ => None,
    }
}

#[test]
fn steps_that_talk_about_a_texture_view_select_it_in_both_languages() {
    let l = lesson();
    let mut named = 0;
    for (i, s) in l.steps.iter().enumerate() {
        let en = format!("{} {}", s.text.en, s.try_this.en);
        let zh = format!("{} {}", s.text.zh, s.try_this.zh);
        let by_en = named_view(&en, "texture-space view", "level-of-detail view");
        let by_zh = named_view(&zh, "纹理空间视图", "细节层次视图");
        assert_eq!(
            by_en,
            by_zh,
            "step {}: the languages name different views",
            i + 1
        );
        if let Some(v) = by_en {
            named += 1;
            assert_eq!(s.texture_view, v, "step {} names {v:?}", i + 1);
            let state = l.state(i).expect("state");
            assert_eq!(state.texture_view, v, "step {}'s state", i + 1);
        }
    }
    // The footprint, the mipmap pyramid, magnification's end and the probes.
    assert_eq!(named, 4);
    let views: Vec<TexelView> = l.steps.iter().map(|s| s.texture_view).collect();
    assert_eq!(views[6], TexelView::Lod, "step 7 (the mipmap pyramid)");
    assert_eq!(views[10], TexelView::Texture, "step 11 (anisotropic)");
    assert_eq!(
        views[0],
        TexelView::Off,
        "step 1 is plain nearest filtering"
    );
}

#[test]
fn the_step_where_lambda_grows_towards_the_horizon_plots_it_down_the_column() {
    let l = lesson();
    let n = 1 + l
        .steps
        .iter()
        .position(|s| s.text.en.contains("lambda grows towards the horizon"))
        .expect("a step says it");
    assert!(l.steps[n - 1].text.zh.contains("越靠近地平线越大"));
    let state = l.state(n - 1).expect("state");
    assert_eq!(state.plot, Some(barylab::lesson::LessonPlot::LambdaColumn));
    let texture = state.scene.load_texture(Path::new("")).expect("texture");
    let [x, y] = state.pin.expect("pinned");
    let plot = barylab::lesson::plot::row_plot(
        &state.scene,
        &texture,
        [x, y],
        barylab::lesson::LessonPlot::LambdaColumn,
        barylab::i18n::Lang::En,
    )
    .expect("plot");
    assert_eq!(plot.marker, Some(f64::from(y)));
    let lambda = &plot.lines[0].1;
    // At the pinned row, the probe's lambda.
    let at_pin = lambda
        .iter()
        .find(|p| p[0] == f64::from(y))
        .expect("the pinned row is covered")[1];
    let probed = common::lod_of(&probe_step(&l, n, true)).trilinear.lambda;
    assert_eq!(at_pin, f64::from(probed));
    // Up the column (rows decreasing) lambda never falls, from magnified to past level 4.
    for w in lambda.windows(2) {
        assert!(w[0][0] < w[1][0]);
        assert!(w[0][1] >= w[1][1] - 1e-6, "lambda falls going up at {w:?}");
    }
    assert!(lambda.last().expect("rows")[1] < 0.0);
    assert!(lambda[0][1] > 4.0);
    // The level line: floor(lambda), 0 when magnified.
    for (p, q) in lambda.iter().zip(&plot.lines[1].1) {
        assert_eq!(q[1], p[1].max(0.0).floor().min(8.0), "row {}", p[0]);
    }
}

/// Step 3 says the squares' edges look soft under magnification: its picture must hold both
/// colours of the checkerboard (40 and 235) and, where they meet, the bilinear blend between
/// them over several pixels (a close-up inside one square would show one flat colour).
#[test]
fn the_magnification_step_shows_soft_edges_between_squares() {
    let lesson = lesson();
    let state = lesson.state(2).expect("state");
    let texture = state.scene.load_texture(Path::new("")).expect("texture");
    let settings = state.scene.settings();
    let r = barylab::raster::render(&state.scene.to_mesh(), &texture, &settings).expect("render");
    let covered: Vec<u8> = r
        .frame
        .color
        .iter()
        .zip(&r.frame.triangle)
        .filter(|(_, t)| **t != barylab::raster::NO_TRIANGLE)
        .map(|(c, _)| c[0])
        .collect();
    assert!(covered.len() > 200 * 200, "the quad fills the picture");
    let count = |lo: u8, hi: u8| covered.iter().filter(|&&v| v >= lo && v <= hi).count();
    let (dark, light) = (count(40, 40), count(235, 235));
    let blended = count(60, 215);
    assert!(
        dark > 10_000 && light > 10_000,
        "dark {dark}, light {light}"
    );
    // Each edge between squares blends over about 1 / 0.1386 = 7 pixels, across the picture.
    assert!(blended > 1_000, "only {blended} blended pixels");
}

/// The `(x, y, font size)` of each `<text>` of `svg` whose content is a three-decimal weight.
fn weight_labels(svg: &str) -> Vec<(f64, f64, f64)> {
    let attr = |el: &str, name: &str| -> f64 {
        let key = format!(" {name}=\"");
        let start = el.find(&key).expect("attribute") + key.len();
        let end = start + el[start..].find('"').expect("closing quote");
        el[start..end].parse().expect("number")
    };
    svg.split("<text")
        .skip(1)
        .filter_map(|el| {
            let body = &el[el.find('>')? + 1..el.find("</text>")?];
            let is_weight = body.len() == 5 && body.starts_with("0.") || body == "1.000";
            is_weight.then(|| (attr(el, "x"), attr(el, "y"), attr(el, "font-size")))
        })
        .collect()
}

/// Step 2 (bilinear, magnified): the four taps' weights are printed large enough for a room
/// and none of them lies under the white dot that marks the pixel's uv.
#[test]
fn the_bilinear_step_prints_readable_weights_clear_of_the_uv_dot() {
    let lesson = lesson();
    let trace = probe_step(&lesson, 2, false);
    let state = lesson.state(1).expect("state");
    let texture = state.scene.load_texture(Path::new("")).expect("texture");
    let settings = state.scene.settings();
    assert_eq!(
        settings.filter,
        Filter::Bilinear,
        "step 2 filters bilinearly"
    );
    let a = trace
        .detail
        .as_ref()
        .and_then(|d| d.attribute.as_ref())
        .expect("a texture lookup");
    let view = barylab::figure::texture_view::TextureView::of(
        &texture,
        (settings.filter, settings.wrap),
        a,
        true,
        trace.pixel,
    );
    let svg = view.picture(barylab::i18n::Lang::En).to_svg().expect("svg");
    let labels = weight_labels(&svg);
    assert_eq!(labels.len(), 4, "four bilinear taps: {labels:?}");
    // The uv's dot: the white circle of radius 4.
    let dot = svg
        .split("<circle")
        .skip(1)
        .find(|el| el.contains("r=\"4\"") && el.contains("fill=\"#ffffff\""))
        .expect("the uv dot");
    let coord = |name: &str| -> f64 {
        let key = format!(" {name}=\"");
        let start = dot.find(&key).expect("attribute") + key.len();
        let end = start + dot[start..].find('"').expect("quote");
        dot[start..end].parse().expect("number")
    };
    let (cx, cy) = (coord("cx"), coord("cy"));
    for (x, y, size) in labels {
        assert!(
            size >= 15.0,
            "a weight at {size} points is too small to read"
        );
        // The label's box: five digits about 0.56 font sizes each, centred on x; baseline y.
        let half_width = 5.0 * 0.56 * size / 2.0;
        let clear_x = (cx - x).abs() > half_width + 4.0;
        let clear_y = cy < y - size - 4.0 || cy > y + 0.25 * size + 4.0;
        assert!(
            clear_x || clear_y,
            "the weight at ({x}, {y}), {size} pt, lies under the uv dot at ({cx}, {cy})"
        );
    }
}
