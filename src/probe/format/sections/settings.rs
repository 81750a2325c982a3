//! Settings: interpolation mode, shading, filter, wrap.

use super::*;

/// Section 1: the render settings.
pub(super) fn settings_section(b: &mut Builder, trace: &PixelTrace) {
    let st = &trace.settings;
    b.section("Settings");
    b.text(format!("Interpolation: {}.", mode_name(st.mode)));
    b.text(format!(
        "Shading: {}; texture filter {}, wrap {}{}.",
        shading_name(st.shading),
        filter_name(st.filter),
        wrap_name(st.wrap),
        if st.wireframe { "; wireframe on" } else { "" }
    ));
}
