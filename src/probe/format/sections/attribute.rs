//! Texture coordinate and colour both ways: uv, texels, the filter's taps, vertex colour.

use super::*;

/// How a wrap mode maps a texel index into `0..size` (in words, for the nearest line).
fn wrap_rule(wrap: Wrap, a: &AttributeTrace) -> String {
    let [w, h] = a.texture_size;
    let [last_i, last_j] = a.last_texel;
    match wrap {
        Wrap::Repeat => format!("repeat, i mod {w}, j mod {h}"),
        Wrap::MirroredRepeat => format!("mirrored repeat over {w}x{h}"),
        Wrap::ClampToEdge => format!("clamp to 0..{last_i}, 0..{last_j}"),
    }
}

/// One way's texture lookup: uv, the texels read (`rule` says how the wrap mode maps an
/// index), the colour.
fn taps_line(
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
                txt("texel "),
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
    b.section("Texture coordinate and colour, both ways");
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
            "for noperspective: at a vertex the clipper made, OpenGL interpolates along the \
             cut edge with the screen-space fraction, so affine uv stays linear on screen",
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
    b.eq_note(l, "screen weights: wrong under perspective");
    if let Some(p) = &d.perspective {
        let mut l = vec![sym("uv_persp"), EQ];
        l.extend(weighted_sym(&CORRECT, &uvs));
        l.push(EQ);
        l.extend(weighted(
            &p.correction.weights,
            a.uv_vertices.iter().map(|u| tup32(u)).collect(),
        ));
        l.extend([EQ, tup32(&a.uv_perspective)]);
        b.eq_note(l, "perspective-correct");
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
        b.para(vec![t(
            "The same by the OpenGL / GAMES101 form, interpolating uv/W and 1/W linearly and \
             dividing:",
        )]);
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
    b.para(vec![
        t(format!("Texel coordinates: uv times the texture size {tw} x {th} (texel row 0 is the bottom, v = 0):")),
    ]);
    b.eq(vec![
        txt("affine "),
        tup(&a.texel_affine),
        SEP,
        txt("perspective "),
        tup(&a.texel_perspective),
        SEP,
        sym("Delta"),
        EQ,
        tup(&a.texel_difference),
        SEP,
        M::Abs(vec![sym("Delta")]),
        EQ,
        num(a.texel_distance),
        txt(" texels"),
    ]);
    let filter = trace.settings.filter;
    if let Some(tri) = &a.trilinear {
        b.para(vec![
            t(format!(
                "Trilinear filtering: the level of detail comes from the uv differences across \
                 the pixel's 2x2 quad (as GPUs compute derivatives), in texels of level 0, and \
                 the texture has {} mipmap levels: ",
                tri.levels
            )),
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
            t("."),
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
    b.text(format!(
        "The {} filter reads{}:",
        filter_name(filter),
        match filter {
            Filter::Nearest => " the texel (floor(u W), floor(v H))",
            Filter::Bilinear => {
                " the 2x2 texels (i, j) around (u W - 1/2, v H - 1/2), weighted by the fractions; \
                 the colour is the weighted sum"
            }
            Filter::Trilinear => {
                " 2x2 texels (i, j, level) bilinearly in levels floor(lambda) and \
                 floor(lambda) + 1 (level 0 alone when lambda <= 0), blended by frac(lambda)"
            }
        }
    ));
    let rule = wrap_rule(trace.settings.wrap, a);
    b.eq(taps_line(
        "affine ",
        a.uv_affine,
        a.texel_affine,
        &a.taps_affine,
        a.color_affine,
        filter,
        &rule,
    ));
    b.eq(taps_line(
        "perspective ",
        a.uv_perspective,
        a.texel_perspective,
        &a.taps_perspective,
        a.color_perspective,
        filter,
        &rule,
    ));
    b.eq(listing((0..3).map(|k| {
        vec![
            sym(format!("colour_{}", n[k])),
            EQ,
            tup32(&a.vertex_colors[k]),
        ]
    })));
    b.eq(vec![
        txt("vertex colour: affine "),
        tup32(&a.vertex_color_affine),
        SEP,
        txt("perspective "),
        tup32(&a.vertex_color_perspective),
    ]);
}
