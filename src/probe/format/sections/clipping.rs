//! Clipping: the planes that cut the triangle, the clipped polygon and the fan triangle.

use super::*;

pub(super) fn clipping_section(b: &mut Builder, d: &TriangleTrace) {
    let Some(c) = &d.clipping else {
        return;
    };
    b.section("Clipping");
    let planes: Vec<&str> = c.planes.iter().map(|p| plane_name(*p)).collect();
    b.text(format!(
        "The triangle crosses {}, so the clipper (Sutherland-Hodgman, in clip space) cut it \
         into a polygon of {} vertices, drawn as a fan of triangles. A new vertex on edge UV \
         is U + k (V - U) with the same k for every attribute, including its weights lambda \
         with respect to the source triangle.",
        planes.join(" and "),
        c.polygon.len()
    ));
    let src: Vec<&str> = d.vertices.iter().map(|v| v.name.as_str()).collect();
    for p in &c.polygon {
        match p.source_vertex {
            Some(_) => b.eq_note(
                vec![sym(p.name.clone()), EQ, tup(&p.clip)],
                "a source vertex, kept",
            ),
            None => b.eq_note(
                vec![
                    sym(p.name.clone()),
                    EQ,
                    tup(&p.clip),
                    SEP,
                    tup_m(src.iter().map(|s| sym(format!("lambda_{s}"))).collect()),
                    EQ,
                    tup32(&p.source_weights),
                ],
                "made by the clipper",
            ),
        }
    }
    let fan: Vec<&str> = c
        .fan_triangle
        .iter()
        .map(|&k| c.polygon.get(k).map_or("?", |p| p.name.as_str()))
        .collect();
    b.text(format!(
        "The pixel is in fan triangle ({}). Each of its vertices carries its weights with \
         respect to the source triangle {} as a varying; interpolating them gives the weights \
         of {} at the pixel. The screen-space formulas below apply to the fan triangle{}.",
        fan.join(", "),
        src.join(", "),
        src.join(", "),
        if d.vertex_behind_camera {
            ": the source triangle has a vertex with w <= 0, which has no position on the \
             screen, so its own screen-space weights do not exist"
        } else {
            ""
        }
    ));
}
