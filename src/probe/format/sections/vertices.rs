//! The vertices in every space: object, world, view, clip, NDC, window.

use super::*;

pub(super) fn vertices_section(b: &mut Builder, trace: &PixelTrace, d: &TriangleTrace) {
    b.section(format!(
        "The vertices of triangle {} in every space",
        d.source
    ));
    let [w, h] = trace.image_size;
    if let Some(mats) = &trace.matrices {
        let tilted = mats.world_from_object != glam::DMat4::IDENTITY.to_cols_array_2d();
        b.para(vec![
            t("Object"),
            m1(TO),
            t("world"),
            m1(TO),
            t("view (the camera, looking down -z)"),
            m1(TO),
            t("clip (the projection), then divide by w"),
            m1(TO),
            t("NDC"),
            m1(TO),
            t("window."),
        ]);
        if tilted {
            b.matrix(vec![sym("M_world"), EQ], rows4(&mats.world_from_object));
        }
        b.matrix(vec![sym("M_view"), EQ], rows4(&mats.view_from_world));
        b.matrix(vec![sym("M_proj"), EQ], rows4(&mats.clip_from_view));
    } else {
        b.text("A clip-space scene: the vertices are given in clip space.");
    }
    for v in &d.vertices {
        let n = &v.name;
        b.para(vec![t(format!("Vertex {n} (mesh vertex {}):", v.index))]);
        if let (Some(o), Some(wd), Some(vw)) = (v.object, v.world, v.view) {
            if o != wd {
                b.eq(vec![
                    sym(format!("world_{n}")),
                    EQ,
                    sym("M_world"),
                    MUL,
                    tup(&o),
                    EQ,
                    tup(&wd),
                ]);
            } else {
                b.eq(vec![sym(format!("world_{n}")), EQ, tup(&wd)]);
            }
            b.eq(vec![
                sym(format!("view_{n}")),
                EQ,
                sym("M_view"),
                MUL,
                sym(format!("world_{n}")),
                EQ,
                tup(&vw),
            ]);
            b.eq(vec![
                sym(format!("clip_{n}")),
                EQ,
                sym("M_proj"),
                MUL,
                sym(format!("view_{n}")),
                EQ,
                tup(&v.clip),
            ]);
        } else {
            b.eq(vec![sym(format!("clip_{n}")), EQ, tup(&v.clip)]);
        }
        match (v.ndc, v.window, v.window_fixed, v.inv_w) {
            (Some(ndc), Some(win), Some(fixed), Some(inv_w)) => {
                b.eq(vec![
                    sym(format!("ndc_{n}")),
                    EQ,
                    frac(tup(&v.clip[..3]), num(v.clip[3])),
                    EQ,
                    tup(&ndc),
                ]);
                b.eq(vec![
                    sym(format!("window_{n}")),
                    EQ,
                    M::Tuple(vec![
                        vec![
                            grp(vec![num(ndc[0]), PLUS, int(1)]),
                            MUL,
                            frac(int(w.into()), int(2)),
                        ],
                        vec![
                            grp(vec![int(1), MINUS, num(ndc[1])]),
                            MUL,
                            frac(int(h.into()), int(2)),
                        ],
                    ]),
                    EQ,
                    tup(&win[..2]),
                    TO,
                    txt("snapped: "),
                    frac(
                        M::Tuple(fixed.iter().map(|&c| vec![int(c)]).collect()),
                        int(trace.sample.subpixel),
                    ),
                ]);
                b.eq(vec![
                    sym(format!("d_{n}")),
                    EQ,
                    frac(vec![num(ndc[2]), PLUS, int(1)], int(2)),
                    EQ,
                    num(win[2]),
                    SEP,
                    frac(int(1), sym(format!("W_{n}"))),
                    EQ,
                    frac(int(1), num(v.clip[3])),
                    EQ,
                    num(inv_w),
                ]);
            }
            _ => {
                b.para(vec![
                    m(vec![
                        sym(format!("W_{n}")),
                        EQ,
                        num(v.clip[3]),
                        M::Op(Op::Le),
                        int(0),
                    ]),
                    t(format!(
                        ": {n} is at or behind the plane of the eye. It has no NDC or window \
                         position (dividing by w <= 0 would mirror it through the eye), so the \
                         clipper cuts the triangle in clip space before the divide."
                    )),
                ]);
            }
        }
        b.eq(vec![
            sym(format!("uv_{n}")),
            EQ,
            tup32(&v.uv),
            SEP,
            sym(format!("colour_{n}")),
            EQ,
            tup32(&v.color),
        ]);
    }
}
