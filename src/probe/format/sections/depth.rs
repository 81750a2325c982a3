//! Depth: window depth, view depth both ways, and the seen point's depth.

use super::*;

pub(super) fn depth_section(b: &mut Builder, trace: &PixelTrace, d: &TriangleTrace) {
    let Some(dt) = &d.depth else {
        return;
    };
    let n = raster_names(d);
    let r = d.screen.rasterizer;
    b.section(tr!(b, "probe.depth.title"));
    b.text(tr!(b, "probe.depth.intro"));
    let mut l = vec![sym("d_P"), EQ];
    l.extend(weighted_sym(&SCREEN, &n.clone().map(|x| format!("d_{x}"))));
    l.push(EQ);
    l.extend(weighted(
        &r,
        dt.window_depths.iter().map(|&x| num(x)).collect(),
    ));
    l.extend([EQ, num(dt.depth)]);
    b.eq(l);
    let (label, sname) = match dt.distance_kind {
        DistanceKind::ViewDepth => (tr!(b, "probe.depth.view_label"), "z"),
        DistanceKind::ClipW => (tr!(b, "probe.depth.clip_label"), "w"),
    };
    if trace.matrices.is_some_and(|m| !m.perspective) {
        b.text(tr!(b, "probe.depth.orthographic", label = label));
    } else {
        b.text(tr!(b, "probe.depth.not_linear", label = label));
    }
    b.eq(listing((0..3).map(|k| {
        vec![sym(format!("{sname}_{}", n[k])), EQ, num(dt.distances[k])]
    })));
    let zs: Vec<M> = dt.distances.iter().map(|&x| num(x)).collect();
    let mut l = vec![sym(format!("{sname}_affine")), EQ];
    l.extend(weighted(&r, zs.clone()));
    l.extend([EQ, num(dt.distance_affine)]);
    b.eq_note(l, tr!(b, "probe.depth.wrong"));
    if let Some(p) = &d.perspective {
        let mut l = vec![sym(format!("{sname}_corrected")), EQ];
        l.extend(weighted(&p.correction.weights, zs));
        l.extend([EQ, num(dt.distance_corrected)]);
        let note = if dt.distance_kind == DistanceKind::ViewDepth
            && trace.matrices.is_some_and(|m| m.perspective)
        {
            tr!(b, "probe.depth.right_w_p")
        } else {
            tr!(b, "probe.depth.right")
        };
        b.eq_note(l, note);
    }
    if let Some(tz) = dt.distance_true {
        b.eq_note(
            vec![sym(format!("{sname}_true")), EQ, num(tz)],
            tr!(b, "probe.depth.seen_true"),
        );
    }
    if let Some(dp) = dt.depth_of_point {
        b.eq_note(
            vec![sym("d_X"), EQ, num(dp)],
            tr!(b, "probe.depth.of_point"),
        );
    }
}
