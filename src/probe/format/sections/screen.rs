//! Screen-space weights r, s, t, four ways (explicit formula, cross products, OpenGL area form, 4x4 system) and the rasterizer's.

use super::*;

pub(super) fn screen_section(b: &mut Builder, trace: &PixelTrace, d: &TriangleTrace) {
    let n = raster_names(d);
    let rv = &d.raster.vertices;
    let sw = &d.screen;
    let p = trace.sample.window;
    b.section(tr!(b, "probe.screen.title", names = names3(&n)));
    b.text(tr!(b, "probe.screen.intro", names = names3(&n)));
    let mut pos = Vec::new();
    for (k, v) in rv.iter().enumerate() {
        if k > 0 {
            pos.push(SEP);
        }
        pos.extend([sym(n[k].clone()), EQ, tup(&v.window)]);
    }
    pos.extend([SEP, sym("P"), EQ, tup(&p)]);
    // The inputs of the arithmetic below: shown with an operand's digits.
    pos.iter_mut().for_each(mark_all);
    b.eq(pos);
    let xs = |k: usize| sym(format!("x_{}", n[k]));
    let ys = |k: usize| sym(format!("y_{}", n[k]));

    // 1. Explicit formula.
    if let Some(f) = &sw.explicit {
        b.text(tr!(
            b,
            "probe.screen.explicit",
            a = n[0].clone(),
            ca = format!("{}{}", n[2], n[0]),
            ab = format!("{}{}", n[0], n[1])
        ));
        // (y_P - y_A)(x_C - x_A) - (x_P - x_A)(y_C - y_A)
        let form = |u: usize| {
            vec![
                grp(vec![sym("y_P"), MINUS, ys(0)]),
                grp(vec![xs(u), MINUS, xs(0)]),
                MINUS,
                grp(vec![sym("x_P"), MINUS, xs(0)]),
                grp(vec![ys(u), MINUS, ys(0)]),
            ]
        };
        let vals = |f: [f64; 4]| vec![num(f[0]), MUL, num(f[1]), MINUS, num(f[2]), MUL, num(f[3])];
        let dform = |u: usize, v: usize| {
            vec![
                grp(vec![ys(u), MINUS, ys(0)]),
                grp(vec![xs(v), MINUS, xs(0)]),
                MINUS,
                grp(vec![xs(u), MINUS, xs(0)]),
                grp(vec![ys(v), MINUS, ys(0)]),
            ]
        };
        let mut l = vec![sym("N_beta"), EQ];
        l.extend(form(2));
        l.push(EQ);
        l.extend(vals(f.beta_numerator_factors));
        l.extend([EQ, num(f.beta_numerator)]);
        b.eq(l);
        let mut l = vec![sym("D_beta"), EQ];
        l.extend(dform(1, 2));
        l.push(EQ);
        l.extend(vals(f.beta_denominator_factors));
        l.extend([EQ, num(f.beta_denominator)]);
        b.eq(l);
        b.eq(vec![
            sym("s"),
            EQ,
            sym("beta"),
            EQ,
            frac(sym("N_beta"), sym("D_beta")),
            EQ,
            frac(num(f.beta_numerator), num(f.beta_denominator)),
            EQ,
            num(f.weights[1]),
        ]);
        let mut l = vec![sym("N_gamma"), EQ];
        l.extend(form(1));
        l.push(EQ);
        l.extend(vals(f.gamma_numerator_factors));
        l.extend([EQ, num(f.gamma_numerator)]);
        b.eq(l);
        let mut l = vec![sym("D_gamma"), EQ];
        l.extend(dform(2, 1));
        l.push(EQ);
        l.extend(vals(f.gamma_denominator_factors));
        l.extend([EQ, num(f.gamma_denominator)]);
        b.eq(l);
        b.eq(vec![
            sym("t"),
            EQ,
            sym("gamma"),
            EQ,
            frac(sym("N_gamma"), sym("D_gamma")),
            EQ,
            frac(num(f.gamma_numerator), num(f.gamma_denominator)),
            EQ,
            num(f.weights[2]),
        ]);
        b.eq(vec![
            sym("r"),
            EQ,
            sym("alpha"),
            EQ,
            int(1),
            MINUS,
            sym("beta"),
            MINUS,
            sym("gamma"),
            EQ,
            int(1),
            MINUS,
            num(f.weights[1]),
            MINUS,
            num(f.weights[2]),
            EQ,
            num(f.weights[0]),
        ]);
        // GAMES101's slides: alpha from the edge BC, beta from the edge CA, each
        // -(x_Q - x_U)(y_V - y_U) + (y_Q - y_U)(x_V - x_U) at Q = P over the same at Q = the
        // opposite corner.
        b.text(tr!(
            b,
            "probe.screen.slides",
            bc = format!("{}{}", n[1], n[2]),
            ca = format!("{}{}", n[2], n[0])
        ));
        let line = |q: Option<usize>, u: usize, v: usize| {
            let (qx, qy) = match q {
                Some(k) => (xs(k), ys(k)),
                None => (sym("x_P"), sym("y_P")),
            };
            vec![
                MINUS,
                grp(vec![qx, MINUS, xs(u)]),
                grp(vec![ys(v), MINUS, ys(u)]),
                PLUS,
                grp(vec![qy, MINUS, ys(u)]),
                grp(vec![xs(v), MINUS, xs(u)]),
            ]
        };
        for (k, u, v, name) in [(0, 1, 2, "alpha"), (1, 2, 0, "beta")] {
            b.eq(vec![
                sym(name),
                EQ,
                frac(line(None, u, v), line(Some(k), u, v)),
                EQ,
                num(f.slides[k]),
            ]);
        }
        b.eq(vec![
            sym("gamma"),
            EQ,
            int(1),
            MINUS,
            sym("alpha"),
            MINUS,
            sym("beta"),
            EQ,
            num(f.slides[2]),
        ]);
    }

    // 2. Cross products.
    if let Some(c) = &sw.cross_product {
        b.para(vec![
            t(tr!(b, "probe.screen.cross_before")),
            m(vec![
                sym("u"),
                CROSS,
                sym("v"),
                EQ,
                sym("u_x"),
                MUL,
                sym("v_y"),
                MINUS,
                sym("u_y"),
                MUL,
                sym("v_x"),
            ]),
            t(tr!(b, "probe.screen.cross_after")),
        ]);
        // The vectors (u, v) of S, S_A, S_B, S_C.
        let vectors = c.vectors.unwrap_or_default();
        let cross_line = |lhs: M, a: &str, bb: &str, c_: &str, [u, w]: [[f64; 2]; 2], val: f64| {
            // lhs = 1/2 (ab x ac) = 1/2 (u_x w_y - u_y w_x) = val
            vec![
                lhs,
                EQ,
                sym("half"),
                grp(vec![
                    sym(format!("{a}{bb}")),
                    CROSS,
                    sym(format!("{a}{c_}")),
                ]),
                EQ,
                sym("half"),
                grp(vec![
                    num(u[0]),
                    MUL,
                    num(w[1]),
                    MINUS,
                    num(u[1]),
                    MUL,
                    num(w[0]),
                ]),
                EQ,
                num(val),
            ]
        };
        b.eq_note(
            cross_line(sym("S"), &n[1], &n[2], &n[0], vectors[0], c.area),
            if c.area < 0.0 {
                tr!(b, "probe.screen.area_negative")
            } else {
                tr!(b, "probe.screen.area_positive")
            },
        );
        let subs = [(1usize, 2usize), (2, 0), (0, 1)];
        for (k, (i, j)) in subs.iter().enumerate() {
            let mut l = cross_line(
                sym(format!("S_{}", n[k])),
                &n[*i],
                &n[*j],
                "P",
                vectors[k + 1],
                c.sub_areas[k],
            );
            l.extend([
                SEP,
                sym(SCREEN[k]),
                EQ,
                frac(sym(format!("S_{}", n[k])), sym("S")),
                EQ,
                num(c.weights[k]),
            ]);
            if c.weights[k] < 0.0 {
                b.eq_note(
                    l,
                    tr!(
                        b,
                        "probe.screen.far_side",
                        edge = format!("{}{}", n[*i], n[*j])
                    ),
                );
            } else {
                b.eq(l);
            }
        }
        b.eq(vec![
            sym(format!("S_{}", n[0])),
            PLUS,
            sym(format!("S_{}", n[1])),
            PLUS,
            sym(format!("S_{}", n[2])),
            EQ,
            num(c.sub_area_sum),
            EQ,
            sym("S"),
        ]);
    }

    // 3. OpenGL area form.
    if let Some(g) = &sw.gl_area {
        b.para(vec![
            t(tr!(b, "probe.screen.gl_before")),
            m(vec![
                sym("area"),
                M::Tuple(vec![vec![sym("p_1")], vec![sym("p_2")], vec![sym("p_3")]]),
                EQ,
                sym("half"),
                sym("sum_i"),
                grp(vec![
                    sym("x_i"),
                    MUL,
                    sym("y_i+1"),
                    MINUS,
                    sym("x_i+1"),
                    MUL,
                    sym("y_i"),
                ]),
            ]),
            t(tr!(b, "probe.colon")),
        ]);
        let area_of = |pts: [&str; 3]| {
            vec![
                sym("area"),
                M::Tuple(pts.iter().map(|s| vec![sym(*s)]).collect()),
            ]
        };
        let all = [n[0].as_str(), n[1].as_str(), n[2].as_str()];
        let mut l = area_of(all);
        l.extend([EQ, num(g.area)]);
        b.eq(l);
        for k in 0..3 {
            let mut with_p = all;
            with_p[k] = "P";
            let mut l = vec![sym(SCREEN[k]), EQ];
            l.push(frac(area_of(with_p), area_of(all)));
            l.extend([
                EQ,
                frac(num(g.sub_areas[k]), num(g.area)),
                EQ,
                num(g.weights[k]),
            ]);
            b.eq(l);
        }
    }

    // 4. From the system.
    match (&sw.from_system, &d.system) {
        (Some(r), Some(sys)) => {
            let sol = sys.system.solution;
            b.text(tr!(b, "probe.screen.system"));
            for k in 0..3 {
                b.eq(vec![
                    sym(SCREEN[k]),
                    EQ,
                    frac(
                        vec![sym(format!("b_{}", n[k])), MUL, sym(format!("W_{}", n[k]))],
                        sym("w"),
                    ),
                    EQ,
                    frac(vec![num(sol[k]), MUL, num(rv[k].clip[3])], num(sol[3])),
                    EQ,
                    num(r[k]),
                ]);
            }
        }
        _ => b.text(tr!(b, "probe.screen.system_clipped")),
    }

    // The rasterizer.
    b.para(vec![
        t(tr!(b, "probe.screen.rasterizer_before")),
        m(vec![
            tup_m(SCREEN.iter().map(|c| sym(*c)).collect()),
            EQ,
            tup(&sw.rasterizer),
        ]),
        t(tr!(b, "probe.screen.rasterizer_after")),
    ]);
    if !d.coverage.covered {
        for (k, e) in d.coverage.edges.iter().enumerate() {
            if sw.rasterizer[k] < 0.0 {
                b.eq_note(
                    vec![sym(SCREEN[k]), EQ, num(sw.rasterizer[k])],
                    tr!(b, "probe.screen.outside", edge = e.name),
                );
            }
        }
    }
    if d.coverage.covered && sw.rasterizer.iter().any(|&w| w < 0.0) {
        b.text(tr!(
            b,
            "probe.screen.slightly_negative",
            subpixel = trace.sample.subpixel
        ));
    }
    b.para(vec![
        t(tr!(b, "probe.screen.agree")),
        m1(num(sw.max_difference)),
        t(tr!(b, "probe.period")),
    ]);
}
