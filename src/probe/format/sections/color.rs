//! The colour written: the shading mode, the wireframe test, the framebuffer's RGBA.

use super::*;

pub(super) fn color_section(b: &mut Builder, trace: &PixelTrace) {
    b.section("The colour written");
    let st = &trace.settings;
    let Some(d) = &trace.detail else {
        b.eq_note(
            vec![txt(format!(
                "pixel ({}, {}) = {}",
                trace.pixel[0],
                trace.pixel[1],
                rgba(trace.color)
            ))],
            "background",
        );
        return;
    };
    if let Some(sh) = &d.shade {
        if let (Some(dist), Some(width)) = (sh.edge_distance_px, sh.wire_width_px) {
            b.para(vec![
                t("Wireframe: distance to the nearest source edge, smallest weight over its screen gradient: "),
                m1(num(dist)),
                t(format!(
                    " px; lines are drawn below {} px{}.",
                    fmt_number(width),
                    if sh.wire { ", so this is a line pixel" } else { "" }
                )),
            ]);
        }
        let how = match st.shading {
            Shading::Texture => format!(
                "the texture sampled at uv_{} with the {} filter, times 255, rounded",
                if st.mode == Interpolation::Affine {
                    "affine"
                } else {
                    "persp"
                },
                filter_name(st.filter)
            ),
            Shading::VertexColor => format!(
                "the vertex colour interpolated {}, times 255, rounded",
                if st.mode == Interpolation::Affine {
                    "affinely"
                } else {
                    "perspective-correctly"
                }
            ),
            Shading::Barycentric => format!(
                "the source triangle's weights ({}) as red, green, blue, times 255, rounded",
                if st.mode == Interpolation::Affine {
                    "screen"
                } else {
                    "perspective-correct"
                }
            ),
            Shading::Depth => "d_P as grey between the nearest (black) and farthest (white) \
                               drawn vertex depth"
                .to_string(),
        };
        if d.writes_pixel {
            b.text(format!("Shading: {how}."));
        } else {
            b.text(format!(
                "If the triangle covered the pixel, the shading ({how}) would give {}.",
                rgba(sh.color)
            ));
        }
    }
    b.eq_note(
        vec![txt(format!(
            "framebuffer({}, {}) = {}",
            trace.pixel[0],
            trace.pixel[1],
            rgba(trace.color)
        ))],
        if trace.written_by.is_some() {
            "the rendered pixel"
        } else {
            "background: no triangle covers it"
        },
    );
}
