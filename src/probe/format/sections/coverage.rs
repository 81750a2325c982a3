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

fn coverage_reason(b: &Builder, test: &CoverageTest) -> String {
    let neg: Vec<&EdgeTest> = test.edges.iter().filter(|e| e.value < 0).collect();
    let zero: Vec<&EdgeTest> = test.edges.iter().filter(|e| e.value == 0).collect();
    match test.position {
        Position::Inside => tr!(b, "probe.coverage.inside"),
        Position::Outside => {
            let list: Vec<String> = neg.iter().map(|e| format!("E_{} < 0", e.name)).collect();
            let edges: Vec<String> = neg.iter().map(|e| e.name.clone()).collect();
            let list = list.join(&tr!(b, "probe.coverage.and_conditions"));
            let edges = edges.join(&tr!(b, "probe.coverage.and_edges"));
            if neg.len() > 1 {
                tr!(b, "probe.coverage.outside_many", list = list, edges = edges)
            } else {
                tr!(b, "probe.coverage.outside_one", list = list, edges = edges)
            }
        }
        Position::OnEdge => {
            let parts: Vec<String> = zero
                .iter()
                .map(|e| {
                    tr!(
                        b,
                        "probe.coverage.on_edge",
                        edge = e.name,
                        kind = edge_kind_name(b, e.kind)
                    )
                })
                .collect();
            let parts = parts.join(&tr!(b, "probe.coverage.parts_sep"));
            let (rule, covering, leaving) = match test.tie_rule {
                TieRule::Llvmpipe => (
                    tr!(b, "probe.coverage.rule_llvmpipe"),
                    tr!(b, "probe.coverage.edges_left_bottom"),
                    tr!(b, "probe.coverage.edges_top_right"),
                ),
                TieRule::TopLeft => (
                    tr!(b, "probe.coverage.rule_top_left"),
                    tr!(b, "probe.coverage.edges_left_top"),
                    tr!(b, "probe.coverage.edges_bottom_right"),
                ),
                TieRule::AllEdges => (
                    tr!(b, "probe.coverage.rule_all_edges"),
                    tr!(b, "probe.coverage.edges_all"),
                    tr!(b, "probe.coverage.edges_none"),
                ),
                TieRule::NoEdges => (
                    tr!(b, "probe.coverage.rule_no_edges"),
                    tr!(b, "probe.coverage.edges_none"),
                    tr!(b, "probe.coverage.edges_all"),
                ),
            };
            if test.covered {
                tr!(
                    b,
                    "probe.coverage.fill_covered",
                    parts = parts,
                    rule = rule,
                    edges = covering
                )
            } else {
                tr!(
                    b,
                    "probe.coverage.fill_not_covered",
                    parts = parts,
                    rule = rule,
                    edges = leaving
                )
            }
        }
    }
}

pub(super) fn coverage_section(b: &mut Builder, trace: &PixelTrace) {
    b.section(tr!(b, "probe.coverage.title"));
    b.para(vec![
        t(tr!(b, "probe.coverage.intro_before")),
        m(vec![
            sym("E_UV"),
            EQ,
            grp(vec![sym("V"), MINUS, sym("U")]),
            CROSS,
            grp(vec![sym("P"), MINUS, sym("U")]),
        ]),
        t(tr!(
            b,
            "probe.coverage.intro_after",
            unit = trace.sample.edge_function_unit
        )),
    ]);
    if trace.triangles.len() < trace.triangle_count {
        b.text(tr!(
            b,
            "probe.coverage.listed",
            count = trace.triangle_count,
            listed = trace.triangles.len()
        ));
    }
    for c in &trace.triangles {
        coverage_entry(b, c);
    }
    match (trace.written_by, &trace.detail) {
        (Some(k), _) => b.text(tr!(b, "probe.coverage.shows", k = k)),
        (None, Some(d)) => b.text(tr!(
            b,
            "probe.coverage.nearest",
            source = d.source,
            names = names3(&d.coverage.vertices)
        )),
        (None, None) => b.text(tr!(b, "probe.coverage.none")),
    }
}

fn coverage_entry(b: &mut Builder, c: &TriangleCoverage) {
    let head = tr!(
        b,
        "probe.coverage.head",
        k = c.source,
        names = names3(&c.vertices)
    );
    let Some(test) = &c.test else {
        let status = status_text(b, c.status);
        b.text(tr!(
            b,
            "probe.coverage.status",
            head = head,
            status = status
        ));
        return;
    };
    if c.clipped {
        b.text(tr!(
            b,
            "probe.coverage.clipped",
            head = head,
            fan = test.sub_triangle,
            names = names3(&test.vertices)
        ));
    } else {
        b.text(tr!(b, "probe.coverage.entry", head = head));
    }
    b.eq(edge_values_eq(test));
    let reason = coverage_reason(b, test);
    b.text(reason);
    if let Some(d) = &c.depth_test {
        let (op, verdict) = if d.passed {
            (Op::Lt, tr!(b, "probe.coverage.depth_pass"))
        } else {
            (Op::Ge, tr!(b, "probe.coverage.depth_fail"))
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
