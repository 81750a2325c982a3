//! Depth: window depth, view depth both ways, and the seen point's depth.

use super::*;

pub(super) fn depth_section(b: &mut Builder, trace: &PixelTrace, d: &TriangleTrace) {
    let Some(dt) = &d.depth else {
        return;
    };
    let n = raster_names(d);
    let r = d.screen.rasterizer;
    b.section("Depth");
    b.text(
        "The depth buffer stores window depth d = (z/w + 1)/2. z/w is linear on the screen, \
         so the screen weights interpolate it exactly, with no correction:",
    );
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
        DistanceKind::ViewDepth => (
            "view depth z = -z_view (the distance in front of the camera)",
            "z",
        ),
        DistanceKind::ClipW => ("clip w (for a perspective projection, the view depth)", "w"),
    };
    if trace.matrices.is_some_and(|m| !m.perspective) {
        b.text(format!(
            "The {label}: with an orthographic camera every w is 1 and it is linear on the \
             screen too, so both ways agree:"
        ));
    } else {
        b.text(format!("The {label} is not linear on the screen:"));
    }
    b.eq(listing((0..3).map(|k| {
        vec![sym(format!("{sname}_{}", n[k])), EQ, num(dt.distances[k])]
    })));
    let zs: Vec<M> = dt.distances.iter().map(|&x| num(x)).collect();
    let mut l = vec![sym(format!("{sname}_affine")), EQ];
    l.extend(weighted(&r, zs.clone()));
    l.extend([EQ, num(dt.distance_affine)]);
    b.eq_note(l, "screen weights: wrong");
    if let Some(p) = &d.perspective {
        let mut l = vec![sym(format!("{sname}_corrected")), EQ];
        l.extend(weighted(&p.correction.weights, zs));
        l.extend([EQ, num(dt.distance_corrected)]);
        let note = if dt.distance_kind == DistanceKind::ViewDepth
            && trace.matrices.is_some_and(|m| m.perspective)
        {
            "perspective-correct weights: right; it is W_P, as w = -z_view for this camera"
        } else {
            "perspective-correct weights: right"
        };
        b.eq_note(l, note);
    }
    if let Some(tz) = dt.distance_true {
        b.eq_note(
            vec![sym(format!("{sname}_true")), EQ, num(tz)],
            "of the seen point X",
        );
    }
    if let Some(dp) = dt.depth_of_point {
        b.eq_note(
            vec![sym("d_X"), EQ, num(dp)],
            "window depth of the seen point: the same as d_P",
        );
    }
}
