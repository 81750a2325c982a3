//! The 4x4 system (Umetani's notes) on the source triangle's clip coordinates.

use super::*;

pub(super) fn system_section(b: &mut Builder, d: &TriangleTrace) {
    b.section("The 4x4 linear system (Umetani, Applied Computer Graphics)");
    let src: Vec<String> = d.vertices.iter().map(|v| v.name.clone()).collect();
    let Some(sys) = &d.system else {
        b.text(
            "The system is singular here (the triangle is seen edge-on): the sample's ray does \
             not meet its plane in one point.",
        );
        return;
    };
    b.text(format!(
        "Unknowns: the weights b of {} on the triangle in space, and w, the sample's clip w. \
         The clip-space point b_{} q_{} + b_{} q_{} + b_{} q_{} must be (s_x w, s_y w, z, w) with s \
         the sample in NDC, and the weights sum to 1.{}",
        src.join(", "),
        src[0],
        src[0],
        src[1],
        src[1],
        src[2],
        src[2],
        " The source triangle's own clip coordinates are used: the system never divides by \
         w, so it works even with a vertex behind the camera, and it reaches the exact answer \
         independently of the rasterizer."
    ));
    let s = &sys.system;
    b.push(Item::Matrix {
        lhs: Vec::new(),
        rows: rows4(&s.matrix),
        unknowns: vec![
            sym(format!("b_{}", src[0])),
            sym(format!("b_{}", src[1])),
            sym(format!("b_{}", src[2])),
            sym("w"),
        ],
        rhs: s.rhs.to_vec(),
    });
    b.eq(vec![
        tup_m(vec![
            sym(format!("b_{}", src[0])),
            sym(format!("b_{}", src[1])),
            sym(format!("b_{}", src[2])),
            sym("w"),
        ]),
        EQ,
        tup(&s.solution),
    ]);
    if s.solution[3].is_nan() || s.solution[3] <= 0.0 {
        b.text(
            "w <= 0: the line through the eye and the pixel meets the triangle's plane behind \
             the camera, so the pixel sees no point of the plane.",
        );
        return;
    }
    let Some(diff) = sys.max_difference else {
        return;
    };
    if d.clipping.is_none() {
        if d.perspective.is_some() {
            b.para(vec![
                t("These are a, b, c and W_P from the 1/w method (largest difference "),
                m1(num(diff)),
                t(")."),
            ]);
        }
    } else if let Some(sw) = &d.source_weights {
        b.para(vec![
            t("These are the source weights the rasterizer interpolated, "),
            m1(tup32(&sw.perspective)),
            t(" (largest difference "),
            m1(num(diff)),
            t(", from the f32 varyings)."),
        ]);
    }
}
