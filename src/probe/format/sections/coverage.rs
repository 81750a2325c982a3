//! Which triangle covers the sample: the edge functions, the fill rule and the depth test.

use super::*;

fn edge_values_eq(test: &CoverageTest) -> Vec<M> {
    let mut v = Vec::new();
    for (i, e) in test.edges.iter().enumerate() {
        if i > 0 {
            v.push(SEP);
        }
        v.extend([sym(format!("E_{}", e.name)), EQ, int(e.value)]);
    }
    v
}

fn coverage_reason(test: &CoverageTest) -> String {
    let neg: Vec<&EdgeTest> = test.edges.iter().filter(|e| e.value < 0).collect();
    let zero: Vec<&EdgeTest> = test.edges.iter().filter(|e| e.value == 0).collect();
    match test.position {
        Position::Inside => "All three are positive: the sample is inside, covered.".into(),
        Position::Outside => {
            let list: Vec<String> = neg.iter().map(|e| format!("E_{} < 0", e.name)).collect();
            let edges: Vec<String> = neg.iter().map(|e| e.name.clone()).collect();
            format!(
                "{}: the sample is outside edge{} {}, not covered.",
                list.join(" and "),
                if neg.len() > 1 { "s" } else { "" },
                edges.join(" and ")
            )
        }
        Position::OnEdge => {
            let parts: Vec<String> = zero
                .iter()
                .map(|e| {
                    format!(
                        "E_{} = 0: on edge {}, {}",
                        e.name,
                        e.name,
                        edge_kind_name(e.kind)
                    )
                })
                .collect();
            let (covering, leaving) = match test.tie_rule {
                TieRule::Llvmpipe => ("left and bottom", "top and right"),
                TieRule::TopLeft => ("left and top", "bottom and right"),
            };
            let rule = match test.tie_rule {
                TieRule::Llvmpipe => "The tie rule (llvmpipe's, as OpenGL on Mesa)",
                TieRule::TopLeft => "The tie rule (top-left, as Direct3D and Vulkan state it)",
            };
            if test.covered {
                format!(
                    "{}. {rule} covers samples on {covering} edges: covered.",
                    parts.join("; ")
                )
            } else {
                format!(
                    "{}. {rule} leaves samples on {leaving} edges to the triangle \
                     on the other side: not covered here.",
                    parts.join("; ")
                )
            }
        }
    }
}

pub(super) fn coverage_section(b: &mut Builder, trace: &PixelTrace) {
    b.section("Which triangle covers it");
    b.para(vec![
        t("The edge function of edge UV at P, "),
        m(vec![
            sym("E_UV"),
            EQ,
            grp(vec![sym("V"), MINUS, sym("U")]),
            CROSS,
            grp(vec![sym("P"), MINUS, sym("U")]),
        ]),
        t(format!(
            ", is twice the signed area of U, V, P, in exact integers of 1/{} px^2, signed \
             so that it is positive inside. Triangles are drawn in order; a fragment is kept if \
             its depth is less than the depth buffer's value (cleared to 1).",
            trace.sample.edge_function_unit
        )),
    ]);
    if trace.triangles.len() < trace.triangle_count {
        b.text(format!(
            "The mesh has {} triangles; listed are the {} whose bounding box contains the pixel.",
            trace.triangle_count,
            trace.triangles.len()
        ));
    }
    for c in &trace.triangles {
        coverage_entry(b, c);
    }
    match (trace.written_by, &trace.detail) {
        (Some(k), _) => b.text(format!("The pixel shows triangle {k}.")),
        (None, Some(d)) => b.text(format!(
            "No triangle covers the pixel: it keeps the background colour. The steps below \
             use the nearest triangle, {} ({}), with its weights extended outside it; negative \
             weights are marked.",
            d.source,
            names3(&d.coverage.vertices)
        )),
        (None, None) => b.text(
            "No triangle covers the pixel, and no triangle was drawn at all: it keeps the \
             background colour.",
        ),
    }
}

fn coverage_entry(b: &mut Builder, c: &TriangleCoverage) {
    let head = format!("Triangle {} ({})", c.source, names3(&c.vertices));
    let Some(test) = &c.test else {
        b.text(format!("{head}: {}.", status_text(c.status)));
        return;
    };
    if c.clipped {
        b.text(format!(
            "{head}, clipped; the sample is tested against fan triangle {} ({}):",
            test.sub_triangle,
            names3(&test.vertices)
        ));
    } else {
        b.text(format!("{head}:"));
    }
    b.eq(edge_values_eq(test));
    b.text(coverage_reason(test));
    if let Some(d) = &c.depth_test {
        let (op, verdict) = if d.passed {
            (
                Op::Lt,
                "less than the depth buffer's value: the test passes, the fragment is written",
            )
        } else {
            (
                Op::Ge,
                "not less than the depth buffer's value: the test fails, the fragment is hidden",
            )
        };
        b.eq_note(
            vec![
                sym("d_P"),
                EQ,
                num(f64::from(d.depth)),
                M::Op(op),
                num(f64::from(d.buffer_before)),
            ],
            verdict,
        );
    }
}
