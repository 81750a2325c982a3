//! Perspective correction with 1/w: the corrected weights a, b, c and W_P.

use super::*;

pub(super) fn perspective_section(b: &mut Builder, trace: &PixelTrace, d: &TriangleTrace) {
    let n = raster_names(d);
    b.section(tr!(b, "probe.perspective.title"));
    let Some(p) = &d.perspective else {
        b.text(tr!(b, "probe.perspective.none"));
        return;
    };
    let s004 = &p.correction;
    let r = d.screen.rasterizer;
    let equal = if p.w.iter().all(|&w| w == p.w[0]) {
        tr!(b, "probe.perspective.all_equal")
    } else {
        String::new()
    };
    b.text(tr!(
        b,
        "probe.perspective.intro",
        names = names3(&n),
        equal = equal
    ));
    b.eq(listing((0..3).map(|k| {
        vec![
            frac(int(1), sym(format!("W_{}", n[k]))),
            EQ,
            frac(int(1), num(p.w[k])),
            EQ,
            num(s004.inv_w[k]),
        ]
    })));
    let mut l = vec![frac(int(1), sym("W_P")), EQ];
    for k in 0..3 {
        if k > 0 {
            l.push(PLUS);
        }
        l.push(frac(sym(SCREEN[k]), sym(format!("W_{}", n[k]))));
    }
    l.push(EQ);
    l.extend(weighted(&r, s004.inv_w.iter().map(|&x| num(x)).collect()));
    l.extend([EQ, num(s004.inv_w_p)]);
    b.eq_note(l, tr!(b, "probe.perspective.linear"));
    b.eq(vec![
        sym("W_P"),
        EQ,
        frac(int(1), num(s004.inv_w_p)),
        EQ,
        num(s004.w_p),
    ]);
    for k in 0..3 {
        b.eq(vec![
            sym(CORRECT[k]),
            EQ,
            frac(
                vec![sym(SCREEN[k]), MUL, sym("W_P")],
                sym(format!("W_{}", n[k])),
            ),
            EQ,
            frac(vec![num(r[k]), MUL, num(s004.w_p)], num(p.w[k])),
            EQ,
            num(s004.weights[k]),
        ]);
    }
    b.eq(vec![
        sym("a"),
        PLUS,
        sym("b"),
        PLUS,
        sym("c"),
        EQ,
        num(s004.sum),
    ]);
    b.para(vec![
        t(tr!(b, "probe.perspective.games101_before")),
        m(vec![
            sym("w_reciprocal"),
            EQ,
            frac(
                int(1),
                vec![
                    frac(sym("alpha"), sym(format!("w_{}", n[0]))),
                    PLUS,
                    frac(sym("beta"), sym(format!("w_{}", n[1]))),
                    PLUS,
                    frac(sym("gamma"), sym(format!("w_{}", n[2]))),
                ],
            ),
            EQ,
            num(p.games101_w_reciprocal),
        ]),
        t(tr!(b, "probe.perspective.games101_after")),
    ]);
    b.para(vec![
        t(tr!(b, "probe.perspective.renderer_before")),
        m(vec![
            tup_m(CORRECT.iter().map(|c| sym(*c)).collect()),
            EQ,
            tup(&p.renderer_weights),
        ]),
        t(tr!(b, "probe.perspective.and")),
        m(vec![frac(int(1), sym("W_P")), EQ, num(p.renderer_inv_w)]),
        t(tr!(b, "probe.period")),
    ]);
    if trace.settings.mode == Interpolation::Affine {
        b.text(tr!(b, "probe.perspective.affine_mode"));
    }
    if let (Some(_), Some(sw)) = (&d.clipping, &d.source_weights) {
        let src: Vec<&str> = d.vertices.iter().map(|v| v.name.as_str()).collect();
        let rv = &d.raster.vertices;
        let lam = tup_m(src.iter().map(|s| sym(format!("lambda_{s}"))).collect());
        b.para(vec![t(tr!(
            b,
            "probe.perspective.lambda_intro",
            src = src.join(", ")
        ))]);
        let per_vertex = |f: fn(&RasterVertex) -> [f32; 3]| {
            listing((0..3).map(|k| vec![sym(format!("lambda({})", n[k])), EQ, tup32(&f(&rv[k]))]))
        };
        b.eq(per_vertex(|v| v.source_weights));
        b.eq_note(
            [
                vec![lam.clone(), EQ],
                weighted(
                    &p.renderer_weights,
                    (0..3).map(|k| tup32(&rv[k].source_weights)).collect(),
                ),
                vec![EQ, tup32(&sw.perspective)],
            ]
            .concat(),
            tr!(b, "probe.perspective.buffers"),
        );
        b.text(tr!(b, "probe.perspective.lambda_affine"));
        b.eq(per_vertex(|v| v.source_weights_affine));
        b.eq([
            vec![lam, EQ],
            weighted(
                &d.screen.rasterizer,
                (0..3)
                    .map(|k| tup32(&rv[k].source_weights_affine))
                    .collect(),
            ),
            vec![EQ, tup32(&sw.screen)],
        ]
        .concat());
    }
}
