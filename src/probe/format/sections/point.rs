//! The point the pixel sees: the view ray meeting the triangle's plane.

use super::*;

pub(super) fn point_section(b: &mut Builder, trace: &PixelTrace, d: &TriangleTrace) {
    b.section("The point on the triangle that the pixel sees");
    let src: Vec<String> = d.vertices.iter().map(|v| v.name.clone()).collect();
    let Some(sp) = &d.seen_point else {
        b.text(
            "The ray through the pixel centre is parallel to the triangle's plane: it sees no \
             point of it.",
        );
        return;
    };
    match (&sp.ray, &sp.hit) {
        (Some(ray), Some(hit)) => {
            let perspective = trace.matrices.is_some_and(|m| m.perspective);
            b.text(if perspective {
                "In view space the eye is at the origin; the ray goes through the pixel centre \
                 on the near plane:"
            } else {
                "Orthographic camera: the ray is parallel to -z, from the pixel centre on the \
                 near plane to the far plane:"
            });
            b.eq(vec![
                sym("O"),
                EQ,
                tup(&ray.origin),
                SEP,
                sym("dir"),
                EQ,
                tup(&ray.direction),
            ]);
            b.eq(vec![
                sym("n"),
                EQ,
                grp(vec![sym(src[1].clone()), MINUS, sym(src[0].clone())]),
                CROSS,
                grp(vec![sym(src[2].clone()), MINUS, sym(src[0].clone())]),
                EQ,
                tup(&hit.edges[0]),
                CROSS,
                tup(&hit.edges[1]),
                EQ,
                tup(&hit.normal),
            ]);
            b.eq(vec![
                sym("k"),
                EQ,
                frac(
                    vec![
                        sym("n"),
                        MUL,
                        grp(vec![sym(src[0].clone()), MINUS, sym("O")]),
                    ],
                    vec![sym("n"), MUL, sym("dir")],
                ),
                EQ,
                frac(num(hit.t_numerator), num(hit.t_denominator)),
                EQ,
                num(hit.t),
            ]);
            if hit.t.is_nan() || hit.t <= 0.0 {
                b.para(vec![
                    m(vec![sym("k"), M::Op(Op::Le), int(0)]),
                    t(": the line meets the plane behind the start of the ray, not in front of the camera; the pixel sees no point of it."),
                ]);
                return;
            }
            b.eq_note(
                vec![
                    sym("X"),
                    EQ,
                    sym("O"),
                    PLUS,
                    sym("k"),
                    MUL,
                    sym("dir"),
                    EQ,
                    tup(&hit.point),
                ],
                "the seen point, view space",
            );
            if let Some(wd) = sp.world {
                b.eq(vec![
                    sym("X_world"),
                    EQ,
                    M::Inverse("M_view".into()),
                    MUL,
                    sym("X"),
                    EQ,
                    tup(&wd),
                ]);
            }
            b.text(format!(
                "Its own weights lambda, as ratios of signed areas in 3D measured along n ({} \
                 in view space):",
                src.join(", ")
            ));
            let pairs = [(1usize, 2usize), (2, 0), (0, 1)];
            for (k, (i, j)) in pairs.iter().enumerate() {
                b.eq(vec![
                    sym(format!("lambda_{}", src[k])),
                    EQ,
                    frac(
                        vec![
                            sym("n"),
                            MUL,
                            grp(vec![
                                grp(vec![sym(src[*i].clone()), MINUS, sym("X")]),
                                CROSS,
                                grp(vec![sym(src[*j].clone()), MINUS, sym("X")]),
                            ]),
                        ],
                        vec![sym("n"), MUL, sym("n")],
                    ),
                    EQ,
                    num(hit.weights[k]),
                ]);
            }
        }
        _ => {
            b.text(
                "A clip-space scene has no camera, but the 4x4 system's solution is the point \
                 itself, in clip space:",
            );
            let mut l = vec![sym("X"), EQ];
            l.extend(weighted(
                &sp.weights,
                src.iter().map(|s| sym(format!("q_{s}"))).collect(),
            ));
            l.extend([EQ, tup(&sp.clip)]);
            b.eq(l);
            b.eq_note(
                vec![frac(sym("X_xyz"), sym("X_w")), EQ, tup(&sp.ndc)],
                "its x and y are the sample's NDC",
            );
        }
    }
    if let Some(diff) = sp.max_difference {
        b.para(vec![
            t(if d.clipping.is_none() {
                "These are the perspective-correct weights a, b, c (largest difference "
            } else {
                "These are the source weights the rasterizer interpolated (largest difference "
            }),
            m1(num(diff)),
            t(if trace.scene_form != SceneForm::Clip {
                "; the ray is computed from the camera, the rasterizer from clip space)."
            } else {
                ")."
            }),
        ]);
    }
}
