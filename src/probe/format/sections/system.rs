//! The 4x4 system (Umetani's notes) on the source triangle's clip coordinates.

use super::*;

pub(super) fn system_section(b: &mut Builder, d: &TriangleTrace) {
    b.section(tr!(b, "probe.system.title"));
    let src: Vec<String> = d.vertices.iter().map(|v| v.name.clone()).collect();
    let Some(sys) = &d.system else {
        b.text(tr!(b, "probe.system.singular"));
        return;
    };
    b.text(tr!(
        b,
        "probe.system.intro",
        names = src.join(", "),
        v0 = src[0],
        v1 = src[1],
        v2 = src[2]
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
        b.text(tr!(b, "probe.system.behind"));
        return;
    }
    let Some(diff) = sys.max_difference else {
        return;
    };
    if d.clipping.is_none() {
        if d.perspective.is_some() {
            b.para(vec![
                t(tr!(b, "probe.system.same_before")),
                m1(num(diff)),
                t(tr!(b, "probe.system.same_after")),
            ]);
        }
    } else if let Some(sw) = &d.source_weights {
        b.para(vec![
            t(tr!(b, "probe.system.source_before")),
            m1(tup32(&sw.perspective)),
            t(tr!(b, "probe.system.source_mid")),
            m1(num(diff)),
            t(tr!(b, "probe.system.source_after")),
        ]);
    }
}
