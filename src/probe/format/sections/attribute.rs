//! Texture coordinate and colour both ways: uv, texels, the filter's taps, vertex colour.

use super::*;

/// How a wrap mode maps a texel index into `0..size` (in words, for the nearest line).
fn wrap_rule(b: &Builder, wrap: Wrap, a: &AttributeTrace) -> String {
    let [w, h] = a.texture_size;
    let [last_i, last_j] = a.last_texel;
    match wrap {
        Wrap::Repeat => tr!(b, "probe.attribute.wrap_repeat", w = w, h = h),
        Wrap::MirroredRepeat => tr!(b, "probe.attribute.wrap_mirrored", w = w, h = h),
        Wrap::ClampToEdge => tr!(b, "probe.attribute.wrap_clamp", i = last_i, j = last_j),
    }
}

/// One way's texture lookup: uv, the texels read (`rule` says how the wrap mode maps an
/// index), the colour.
#[allow(clippy::too_many_arguments)]
fn taps_line(
    b: &Builder,
    label: &str,
    uv: [f32; 2],
    texel: [f64; 2],
    taps: &[TapTrace],
    color: [u8; 4],
    filter: Filter,
    rule: &str,
) -> Vec<M> {
    let mut l = vec![txt(label.to_string()), tup32(&uv), TO];
    match filter {
        Filter::Nearest => {
            l.extend([
                txt(tr!(b, "probe.attribute.texel")),
                M::Tuple(vec![
                    vec![sym("floor"), grp(num(texel[0]))],
                    vec![sym("floor"), grp(num(texel[1]))],
                ]),
            ]);
            if let Some(tp) = taps.first() {
                let wrapped = M::Tuple(vec![vec![int(tp.i.into())], vec![int(tp.j.into())]]);
                match tp.unwrapped {
                    Some([i, j]) if [i, j] != [i64::from(tp.i), i64::from(tp.j)] => {
                        l.extend([
                            EQ,
                            M::Tuple(vec![vec![int(i)], vec![int(j)]]),
                            TO,
                            txt(format!("{rule}: ")),
                            wrapped,
                        ]);
                    }
                    _ => l.extend([EQ, wrapped]),
                }
            }
        }
        Filter::Bilinear | Filter::Trilinear => {
            let mut ts = Vec::new();
            for (k, tp) in taps.iter().enumerate() {
                if k > 0 {
                    ts.push(PLUS);
                }
                let mut ij = vec![vec![int(tp.i.into())], vec![int(tp.j.into())]];
                if filter == Filter::Trilinear {
                    ij.push(vec![int(tp.level.into())]);
                }
                ts.extend([num(f64::from(tp.weight)), MUL, M::Tuple(ij)]);
            }
            l.extend(ts);
        }
    }
    l.extend([TO, txt(rgba(color))]);
    l
}

pub(super) fn attribute_section(b: &mut Builder, trace: &PixelTrace, d: &TriangleTrace) {
    let Some(a) = &d.attribute else {
        return;
    };
    let n = raster_names(d);
    let r = d.screen.rasterizer;
    b.section(tr!(b, "probe.attribute.title"));
    b.eq(listing((0..3).map(|k| {
        vec![sym(format!("uv_{}", n[k])), EQ, tup32(&a.uv_vertices[k])]
    })));
    if a.uv_vertices_affine != a.uv_vertices {
        b.eq_note(
            listing((0..3).map(|k| {
                vec![
                    sym(format!("uv_{}", n[k])),
                    EQ,
                    tup32(&a.uv_vertices_affine[k]),
                ]
            })),
            tr!(b, "probe.attribute.noperspective"),
        );
    }
    let uvs: Vec<String> = n.iter().map(|x| format!("uv_{x}")).collect();
    let mut l = vec![sym("uv_affine"), EQ];
    l.extend(weighted_sym(&SCREEN, &uvs));
    l.push(EQ);
    l.extend(weighted(
        &r,
        a.uv_vertices_affine.iter().map(|u| tup32(u)).collect(),
    ));
    l.extend([EQ, tup32(&a.uv_affine)]);
    b.eq_note(l, tr!(b, "probe.attribute.wrong"));
    if let Some(p) = &d.perspective {
        let mut l = vec![sym("uv_persp"), EQ];
        l.extend(weighted_sym(&CORRECT, &uvs));
        l.push(EQ);
        l.extend(weighted(
            &p.correction.weights,
            a.uv_vertices.iter().map(|u| tup32(u)).collect(),
        ));
        l.extend([EQ, tup32(&a.uv_perspective)]);
        b.eq_note(l, tr!(b, "probe.attribute.correct"));
        let mut inner = Vec::new();
        for k in 0..3 {
            if k > 0 {
                inner.push(PLUS);
            }
            inner.push(frac(
                vec![sym(SCREEN[k]), MUL, sym(uvs[k].clone())],
                sym(format!("W_{}", n[k])),
            ));
        }
        b.para(vec![t(tr!(b, "probe.attribute.games101"))]);
        b.eq(vec![
            sym("uv_persp"),
            EQ,
            grp(inner),
            MUL,
            sym("W_P"),
            EQ,
            tup(&a.uv_games101),
        ]);
    }
    let [tw, th] = a.texture_size;
    b.para(vec![t(tr!(b, "probe.attribute.texels", w = tw, h = th))]);
    let (affine, perspective) = (
        tr!(b, "probe.attribute.affine"),
        tr!(b, "probe.attribute.perspective"),
    );
    b.eq(vec![
        txt(affine.clone()),
        tup(&a.texel_affine),
        SEP,
        txt(perspective.clone()),
        tup(&a.texel_perspective),
        SEP,
        sym("Delta"),
        EQ,
        tup(&a.texel_difference),
        SEP,
        M::Abs(vec![sym("Delta")]),
        EQ,
        num(a.texel_distance),
        txt(tr!(b, "probe.attribute.texels_unit")),
    ]);
    if let Some(tri) = &a.trilinear {
        b.para(vec![
            t(tr!(b, "probe.attribute.trilinear", levels = tri.levels)),
            m(vec![
                sym("lambda"),
                EQ,
                sym("log_2"),
                grp(vec![
                    sym("max"),
                    M::Tuple(vec![
                        vec![M::Abs(vec![sym("d(uv)/dx")])],
                        vec![M::Abs(vec![sym("d(uv)/dy")])],
                    ]),
                ]),
            ]),
            t(tr!(b, "probe.period")),
        ]);
        b.eq(vec![
            sym("lambda_affine"),
            EQ,
            num(f64::from(tri.lod_affine)),
            SEP,
            sym("lambda_persp"),
            EQ,
            num(f64::from(tri.lod_perspective)),
        ]);
    }
    let anisotropic = a.lod.as_ref().and_then(|l| l.anisotropic.as_ref());
    if let Some(an) = anisotropic {
        b.text(tr!(b, "probe.attribute.reads_anisotropic", max = an.max));
        for (label, uv, color) in [
            (&affine, a.uv_affine, a.color_affine),
            (&perspective, a.uv_perspective, a.color_perspective),
        ] {
            b.eq(vec![txt(label.clone()), tup32(&uv), TO, txt(rgba(color))]);
        }
    } else {
        filter_lines(b, trace, a, (&affine, &perspective));
    }
    vertex_colour_lines(b, a, &n, perspective);
}

/// The filter's texels and weights for both uvs.
fn filter_lines(
    b: &mut Builder,
    trace: &PixelTrace,
    a: &AttributeTrace,
    (affine, perspective): (&str, &str),
) {
    let filter = trace.settings.filter;
    let what = match filter {
        Filter::Nearest => tr!(b, "probe.attribute.reads_nearest"),
        Filter::Bilinear => tr!(b, "probe.attribute.reads_bilinear"),
        Filter::Trilinear => tr!(b, "probe.attribute.reads_trilinear"),
    };
    b.text(tr!(
        b,
        "probe.attribute.filter_reads",
        filter = filter_name(b.lang, filter),
        what = what
    ));
    let rule = wrap_rule(b, trace.settings.wrap, a);
    b.eq(taps_line(
        b,
        affine,
        a.uv_affine,
        a.texel_affine,
        &a.taps_affine,
        a.color_affine,
        filter,
        &rule,
    ));
    b.eq(taps_line(
        b,
        perspective,
        a.uv_perspective,
        a.texel_perspective,
        &a.taps_perspective,
        a.color_perspective,
        filter,
        &rule,
    ));
}

/// The vertex colours and the colour interpolated both ways.
fn vertex_colour_lines(b: &mut Builder, a: &AttributeTrace, n: &[String; 3], perspective: String) {
    b.eq(listing((0..3).map(|k| {
        vec![
            sym(format!("colour_{}", n[k])),
            EQ,
            tup32(&a.vertex_colors[k]),
        ]
    })));
    b.eq(vec![
        txt(tr!(b, "probe.attribute.vertex_colour")),
        tup32(&a.vertex_color_affine),
        SEP,
        txt(perspective),
        tup32(&a.vertex_color_perspective),
    ]);
}
