//! Level of detail: the 2x2 quad, the uv derivatives, the footprint, rho, lambda, the mipmap
//! levels and their taps, and for anisotropic filtering the probes.

use super::*;
use crate::probe::{LevelChoice, LodTrace};
use crate::raster::interpolate::Derivatives;

/// The name of quad pixel `(i, j)` (0 or 1 each): `uv_ij`.
fn quad_sym(i: u32, j: u32) -> M {
    sym(format!("uv_{i}{j}"))
}

/// `P = |(du W, dv H)| = |(a, b)| = p`.
fn axis_line(name: &str, axis: &str, duv: [f32; 2], size: [u32; 2], p: f32) -> Vec<M> {
    let (w, h) = (f64::from(size[0]), f64::from(size[1]));
    vec![
        sym(name),
        EQ,
        M::Abs(vec![M::Tuple(vec![
            vec![sym(format!("du/d{axis}")), MUL, sym("W")],
            vec![sym(format!("dv/d{axis}")), MUL, sym("H")],
        ])]),
        EQ,
        M::Abs(vec![tup(&[f64::from(duv[0]) * w, f64::from(duv[1]) * h])]),
        EQ,
        num(f64::from(p)),
    ]
}

/// Which levels a lookup at `lambda` reads, in words and numbers.
fn levels_para(b: &mut Builder, c: &LevelChoice, last: u32) {
    let text = match c.next {
        _ if c.lambda <= 0.0 || !c.lambda.is_finite() => tr!(b, "probe.lod.magnified"),
        Some((next, f)) => tr!(
            b,
            "probe.lod.two_levels",
            d = c.level,
            e = next,
            wd = fmt_number(1.0 - f64::from(f)),
            we = fmt_number(f64::from(f))
        ),
        None if c.level >= last && c.lambda > last as f32 => {
            tr!(b, "probe.lod.last_level", d = c.level)
        }
        None => tr!(b, "probe.lod.one_level", d = c.level),
    };
    b.text(text);
}

/// `sum weight (i, j, level) -> colour`.
fn taps_sum(taps: &[TapTrace], color: [u8; 4]) -> Vec<M> {
    let mut l = Vec::new();
    for (k, tp) in taps.iter().enumerate() {
        if k > 0 {
            l.push(PLUS);
        }
        l.extend([
            num(f64::from(tp.weight)),
            MUL,
            M::Tuple(vec![
                vec![int(tp.i.into())],
                vec![int(tp.j.into())],
                vec![int(tp.level.into())],
            ]),
        ]);
    }
    l.extend([TO, txt(rgba(color))]);
    l
}

pub(super) fn lod_section(b: &mut Builder, trace: &PixelTrace, lt: &LodTrace) {
    let [x, y] = trace.pixel;
    let (x0, y0) = (x & !1, y & !1);
    b.section(tr!(b, "probe.lod.title"));
    let kind = match lt.derivatives {
        Derivatives::Coarse => tr!(b, "probe.lod.coarse"),
        Derivatives::Fine => tr!(b, "probe.lod.fine"),
    };
    b.text(tr!(
        b,
        "probe.lod.intro",
        x0 = x0,
        y0 = y0,
        x1 = x0 + 1,
        y1 = y0 + 1,
        mode = mode_name(b.lang, lt.mode),
        kind = kind
    ));
    b.eq(listing(lt.quad.iter().map(|q| {
        let sym = quad_sym(q.pixel[0] - x0, q.pixel[1] - y0);
        match q.uv {
            Some(uv) => vec![sym, EQ, tup32(&uv)],
            None => vec![sym, EQ, txt("-")],
        }
    })));
    let outside: Vec<String> = lt
        .quad
        .iter()
        .filter(|q| !q.inside)
        .map(|q| format!("({}, {})", q.pixel[0], q.pixel[1]))
        .collect();
    if !outside.is_empty() {
        b.text(tr!(b, "probe.lod.helpers", pixels = outside.join(", ")));
    }
    let (row, column) = match lt.derivatives {
        Derivatives::Coarse => (0, 0),
        Derivatives::Fine => (y - y0, x - x0),
    };
    b.eq(vec![
        M::Tuple(vec![vec![sym("du/dx")], vec![sym("dv/dx")]]),
        EQ,
        quad_sym(1, row),
        MINUS,
        quad_sym(0, row),
        EQ,
        tup32(&lt.duv_dx),
    ]);
    b.eq(vec![
        M::Tuple(vec![vec![sym("du/dy")], vec![sym("dv/dy")]]),
        EQ,
        quad_sym(column, 1),
        MINUS,
        quad_sym(column, 0),
        EQ,
        tup32(&lt.duv_dy),
    ]);
    let [w, h] = lt.texture_size;
    b.text(tr!(b, "probe.lod.footprint", w = w, h = h));
    b.eq(axis_line("P_x", "x", lt.duv_dx, lt.texture_size, lt.px));
    b.eq(axis_line("P_y", "y", lt.duv_dy, lt.texture_size, lt.py));
    b.eq(listing([
        vec![
            sym("rho"),
            EQ,
            sym("max"),
            M::Tuple(vec![vec![sym("P_x")], vec![sym("P_y")]]),
            EQ,
            num(f64::from(lt.rho)),
        ],
        vec![
            sym("lambda"),
            EQ,
            sym("log_2"),
            grp(sym("rho")),
            EQ,
            num(f64::from(lt.trilinear.lambda)),
        ],
    ]));
    let last = lt.levels.saturating_sub(1);
    let Some(a) = &lt.anisotropic else {
        b.text(tr!(b, "probe.lod.levels", levels = lt.levels, last = last));
        levels_para(b, &lt.trilinear, last);
        b.eq(taps_sum(&lt.taps, lt.color));
        return;
    };
    b.text(tr!(b, "probe.lod.anisotropic", max = a.max));
    let axis = if a.major_y { "y" } else { "x" };
    b.eq(listing([
        vec![sym("P_max"), EQ, num(f64::from(a.p_max))],
        vec![sym("P_min"), EQ, num(f64::from(a.p_min))],
    ]));
    b.eq(vec![
        sym("N"),
        EQ,
        sym("min"),
        M::Tuple(vec![
            vec![sym("ceil"), grp(frac(sym("P_max"), sym("P_min")))],
            vec![int(a.max.into())],
        ]),
        EQ,
        sym("min"),
        M::Tuple(vec![
            vec![sym("ceil"), grp(num(f64::from(a.p_max / a.p_min)))],
            vec![int(a.max.into())],
        ]),
        EQ,
        int(a.n.into()),
    ]);
    b.eq(vec![
        sym("lambda_aniso"),
        EQ,
        sym("log_2"),
        grp(frac(sym("P_max"), sym("N"))),
        EQ,
        num(f64::from(a.levels.lambda)),
    ]);
    b.text(tr!(b, "probe.lod.levels", levels = lt.levels, last = last));
    levels_para(b, &a.levels, last);
    b.text(tr!(b, "probe.lod.probes", n = a.n, axis = axis));
    for (k, p) in a.probes.iter().enumerate() {
        b.eq(vec![
            sym(format!("uv_{}", k + 1)),
            EQ,
            sym("uv"),
            PLUS,
            num(f64::from(p.offset)),
            MUL,
            M::Tuple(vec![
                vec![sym(format!("du/d{axis}"))],
                vec![sym(format!("dv/d{axis}"))],
            ]),
            EQ,
            tup32(&p.uv),
            TO,
            txt(rgba(p.color)),
        ]);
    }
    b.eq(vec![
        sym("colour"),
        EQ,
        frac(int(1), sym("N")),
        MUL,
        grp(vec![
            sym("colour_1"),
            PLUS,
            txt("..."),
            PLUS,
            sym("colour_N"),
        ]),
        TO,
        txt(rgba(lt.color)),
    ]);
}
