//! Clipping: the planes that cut the triangle, the clipped polygon and the fan triangle.

use super::*;

pub(super) fn clipping_section(b: &mut Builder, d: &TriangleTrace) {
    let Some(c) = &d.clipping else {
        return;
    };
    b.section(tr!(b, "probe.clipping.title"));
    let planes: Vec<String> = c.planes.iter().map(|p| plane_name(b, *p)).collect();
    b.text(tr!(
        b,
        "probe.clipping.intro",
        planes = planes.join(&tr!(b, "probe.clipping.and")),
        count = c.polygon.len()
    ));
    let src: Vec<&str> = d.vertices.iter().map(|v| v.name.as_str()).collect();
    for p in &c.polygon {
        match p.source_vertex {
            Some(_) => b.eq_note(
                vec![sym(p.name.clone()), EQ, tup(&p.clip)],
                tr!(b, "probe.clipping.kept"),
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
                tr!(b, "probe.clipping.made"),
            ),
        }
    }
    let fan: Vec<&str> = c
        .fan_triangle
        .iter()
        .map(|&k| c.polygon.get(k).map_or("?", |p| p.name.as_str()))
        .collect();
    let behind = if d.vertex_behind_camera {
        tr!(b, "probe.clipping.behind")
    } else {
        String::new()
    };
    b.text(tr!(
        b,
        "probe.clipping.fan",
        fan = fan.join(", "),
        src = src.join(", "),
        behind = behind
    ));
}
