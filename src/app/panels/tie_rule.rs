//! The tie rule chooser in the controls: which triangle owns a pixel centre exactly on a
//! shared edge, llvmpipe's rule or top-left. The rule is part of the scene (saved with it,
//! undone like any edit); the inspector's coverage section names the rule that decided a tie.

use egui::Ui;

use crate::app::document::state::StateCommand;

/// The tie rule (which triangle owns a pixel centre exactly on a shared edge): llvmpipe's
/// (OpenGL on Mesa, the default) or top-left (Direct3D, and most Vulkan drivers). Saved in the scene.
pub fn tie_rule_ui(ui: &mut Ui, rule: crate::raster::setup::TieRule) -> Vec<StateCommand> {
    use crate::raster::setup::TieRule;
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut out = Vec::new();
    ui.horizontal_wrapped(|ui| {
        ui.label(lang.tr("gpu_view.tie_rule"))
            .on_hover_text(lang.tr("gpu_view.tie_rule_tip"));
        for (r, label, tip) in [
            (
                TieRule::Llvmpipe,
                "gpu_view.tie_llvmpipe",
                "gpu_view.tie_llvmpipe_tip",
            ),
            (
                TieRule::TopLeft,
                "gpu_view.tie_top_left",
                "gpu_view.tie_top_left_tip",
            ),
        ] {
            if ui
                .selectable_label(rule == r, lang.tr(label))
                .on_hover_text(lang.tr(tip))
                .clicked()
                && rule != r
            {
                out.push(StateCommand::SetTieRule(r));
            }
        }
    });
    out
}
