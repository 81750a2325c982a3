//! Perspective correction with 1/w: the corrected weights a, b, c and W_P.

use super::*;

pub(super) fn perspective_section(b: &mut Builder, trace: &PixelTrace, d: &TriangleTrace) {
    let n = raster_names(d);
    b.section("Perspective correction with 1/w (OpenGL 4.6, eq. 14.9)");
    let Some(p) = &d.perspective else {
        b.text(
            "The interpolated 1/w is not positive here: extended beyond its edges, the \
             triangle's plane lies behind the camera at this pixel, so there are no \
             perspective-correct weights.",
        );
        return;
    };
    let s004 = &p.correction;
    let r = d.screen.rasterizer;
    b.text(format!(
        "W is each vertex's clip-space w; with a perspective camera it is the depth in front of \
         the eye. 1/W is linear on the screen, W itself is not. With the screen weights r, s, t \
         of {}:{}",
        names3(&n),
        if p.w.iter().all(|&w| w == p.w[0]) {
            " (all W are equal here, as with an orthographic camera, so a, b, c are r, s, t)"
        } else {
            ""
        }
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
    b.eq_note(l, "linear on screen");
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
        t("GAMES101's code (Assignment 2, rasterize_triangle) writes the same with its screen weights alpha, beta, gamma: "),
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
        t(". Despite its name it is W_P itself, the reciprocal of the interpolated 1/w."),
    ]);
    b.para(vec![
        t("The renderer (interpolate::fragment) computed "),
        m(vec![
            tup_m(CORRECT.iter().map(|c| sym(*c)).collect()),
            EQ,
            tup(&p.renderer_weights),
        ]),
        t(" and "),
        m(vec![frac(int(1), sym("W_P")), EQ, num(p.renderer_inv_w)]),
        t("."),
    ]);
    if trace.settings.mode == Interpolation::Affine {
        b.text(
            "The mode is affine: the shader uses r, s, t directly; a, b, c are shown for \
             comparison.",
        );
    }
    if let (Some(_), Some(sw)) = (&d.clipping, &d.source_weights) {
        let src: Vec<&str> = d.vertices.iter().map(|v| v.name.as_str()).collect();
        let rv = &d.raster.vertices;
        let lam = tup_m(src.iter().map(|s| sym(format!("lambda_{s}"))).collect());
        b.para(vec![t(format!(
            "The weights lambda of the source triangle {} at the pixel are an attribute like \
             any other: each vertex of the rasterized triangle carries its lambda, and the \
             pixel interpolates them. Perspective-correct, with a, b, c and the smooth lambda \
             (at a vertex the clipper made: interpolated in clip space):",
            src.join(", ")
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
            "as written to the weight buffers",
        );
        b.text(
            "Affine, with r, s, t and the noperspective lambda: OpenGL keeps a noperspective \
             attribute linear on the screen, so at a vertex the clipper made it is the source \
             triangle's screen-linear lambda there, not the smooth value:",
        );
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
