//! Settings: interpolation mode, shading, filter, wrap.

use super::*;

/// Section 1: the render settings.
pub(super) fn settings_section(b: &mut Builder, trace: &PixelTrace) {
    let st = &trace.settings;
    let lang = b.lang;
    b.section(tr!(b, "probe.settings.title"));
    b.text(tr!(
        b,
        "probe.settings.interpolation",
        mode = mode_name(lang, st.mode)
    ));
    let wire = if st.wireframe {
        tr!(b, "probe.settings.wireframe_on")
    } else {
        String::new()
    };
    b.text(tr!(
        b,
        "probe.settings.shading",
        shading = shading_name(lang, st.shading),
        filter = sampler_name(lang, st.filter, st.max_anisotropy),
        wrap = wrap_name(lang, st.wrap),
        wire = wire
    ));
}
