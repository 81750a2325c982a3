//! The colour written: the shading mode, the wireframe test, the framebuffer's RGBA.

use super::*;

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
                m1(num(dist)),
                t(tr!(
                    b,
                    "probe.color.wireframe_after",
                    width = fmt_number(width),
                    halo = fmt_number(halo),
                    line = if sh.wire {
                        tr!(b, "probe.color.line_pixel")
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
                filter = filter_name(lang, st.filter)
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
