//! The colour written: the shading mode, the wireframe test, the framebuffer's RGBA.

use super::*;
use crate::probe::NormalTrace;

pub(super) fn color_section(b: &mut Builder, trace: &PixelTrace) {
    b.section(tr!(b, "probe.color.title"));
    let st = &trace.settings;
    let lang = b.lang;
    let Some(d) = &trace.detail else {
        b.eq_note(
            vec![txt(tr!(
                b,
                "probe.color.pixel",
                x = trace.pixel[0],
                y = trace.pixel[1],
                rgba = rgba(trace.color)
            ))],
            tr!(b, "probe.color.background"),
        );
        return;
    };
    if let Some(sh) = &d.shade {
        if let (Some(dist), Some(width), Some(halo)) =
            (sh.edge_distance_px, sh.wire_width_px, sh.wire_halo_px)
        {
            b.para(vec![
                t(tr!(b, "probe.color.wireframe_before")),
                // An operand's digits, so that a distance just under the width does not
                // print as the width itself.
                m1(M::Operand(dist)),
                t(tr!(
                    b,
                    "probe.color.wireframe_after",
                    width = fmt_number(width),
                    halo = fmt_number(halo),
                    line = if sh.wire {
                        tr!(b, "probe.color.line_pixel", width = fmt_number(width))
                    } else if sh.halo {
                        tr!(b, "probe.color.halo_pixel")
                    } else {
                        String::new()
                    }
                )),
            ]);
        }
        let how = match st.shading {
            Shading::Texture => tr!(
                b,
                "probe.color.texture",
                uv = if st.mode == Interpolation::Affine {
                    "affine"
                } else {
                    "persp"
                },
                filter = sampler_name(lang, st.filter, st.max_anisotropy)
            ),
            Shading::VertexColor => tr!(
                b,
                "probe.color.vertex",
                how = if st.mode == Interpolation::Affine {
                    tr!(b, "probe.color.affinely")
                } else {
                    tr!(b, "probe.color.perspective_correctly")
                }
            ),
            Shading::Barycentric => tr!(
                b,
                "probe.color.barycentric",
                which = if st.mode == Interpolation::Affine {
                    tr!(b, "probe.color.screen")
                } else {
                    tr!(b, "probe.color.perspective_correct")
                }
            ),
            Shading::Depth => tr!(b, "probe.color.depth"),
            Shading::Normal => tr!(b, "probe.color.normal", how = interpolated_how(b, st.mode)),
            Shading::Lambert => tr!(b, "probe.color.lambert", how = interpolated_how(b, st.mode)),
        };
        if d.writes_pixel {
            b.text(tr!(b, "probe.color.shading", how = how));
        } else {
            b.text(tr!(
                b,
                "probe.color.would",
                how = how,
                rgba = rgba(sh.color)
            ));
        }
    }
    if let Some(n) = d.shade.as_ref().and_then(|sh| sh.normal.as_ref()) {
        normal_lines(b, st.shading, n);
    }
    b.eq_note(
        vec![txt(tr!(
            b,
            "probe.color.framebuffer",
            x = trace.pixel[0],
            y = trace.pixel[1],
            rgba = rgba(trace.color)
        ))],
        if trace.written_by.is_some() {
            tr!(b, "probe.color.rendered")
        } else {
            tr!(b, "probe.color.uncovered")
        },
    );
}

/// "affinely" or "perspective-correctly".
fn interpolated_how(b: &Builder, mode: Interpolation) -> String {
    if mode == Interpolation::Affine {
        tr!(b, "probe.color.affinely")
    } else {
        tr!(b, "probe.color.perspective_correctly")
    }
}

/// The normal's arithmetic: `n`, `|n|`, `n̂`, and the normal colour or the Lambert brightness.
fn normal_lines(b: &mut Builder, shading: Shading, n: &NormalTrace) {
    b.eq(vec![
        sym("n"),
        EQ,
        tup32(&n.interpolated),
        SEP,
        M::Abs(vec![sym("n")]),
        EQ,
        num(f64::from(n.length)),
        SEP,
        sym("n̂"),
        EQ,
        frac(sym("n"), M::Abs(vec![sym("n")])),
        EQ,
        tup32(&n.unit),
    ]);
    match shading {
        Shading::Normal => {
            let c = crate::raster::shade::normal_colour(glam::Vec3::from_array(n.unit)).to_array();
            b.eq_note(
                vec![
                    frac(grp(vec![sym("n̂"), PLUS, M::Int(1)]), M::Int(2)),
                    EQ,
                    tup32(&c),
                ],
                tr!(b, "probe.color.normal_note"),
            );
        }
        _ => {
            let dot = n.unit[2];
            b.eq_note(
                vec![
                    sym("n̂ · l"),
                    EQ,
                    sym("n̂_z"),
                    EQ,
                    num(f64::from(dot)),
                    SEP,
                    sym("k"),
                    EQ,
                    num(f64::from(n.ambient)),
                    PLUS,
                    num(f64::from(1.0 - n.ambient)),
                    MUL,
                    sym("max"),
                    M::Tuple(vec![vec![M::Int(0)], vec![sym("n̂ · l")]]),
                    EQ,
                    num(f64::from(n.lambert)),
                ],
                tr!(b, "probe.color.lambert_note"),
            );
            b.eq(vec![
                sym("albedo"),
                MUL,
                sym("k"),
                EQ,
                tup32(&n.albedo),
                MUL,
                num(f64::from(n.lambert)),
                EQ,
                tup32(&n.albedo.map(|a| a * n.lambert)),
            ]);
        }
    }
}
