//! The controls panel: mode, comparison, shading, pixel size, presets, camera and vertices.

use egui::{Color32, RichText, Slider, Ui};

use crate::app::document::presets::Preset;
use crate::app::document::state::{AppState, PIXEL_SIZE_RANGE, StateCommand, UI_SCALE_RANGE};
use crate::app::panels::scene_edit;
use crate::figure::Compare;
use crate::i18n::Lang;
use crate::raster::{Filter, Interpolation, Shading};

/// The name of a preset, for its button (and the lessons).
pub fn preset_name(p: Preset, lang: Lang) -> String {
    lang.tr(match p {
        Preset::FrontFacing => "app.controls.preset.front_facing",
        Preset::Floor => "app.controls.preset.floor",
        Preset::GrazingWall => "app.controls.preset.grazing_wall",
        Preset::FarCorner => "app.controls.preset.far_corner",
        Preset::CornerBehind => "app.controls.preset.corner_behind",
    })
}

/// The controls panel.
pub fn controls_ui(ui: &mut Ui, state: &AppState) -> Vec<StateCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut out = Vec::new();
    let options = state.options();
    let view = &state.view;
    fit_sliders(
        ui,
        &[
            "app.controls.pixel_size",
            "app.controls.pitch",
            "app.controls.yaw",
            "app.controls.fov",
        ]
        .map(|k| lang.tr(k)),
    );

    section(ui, &lang.tr("app.controls.interpolation"));
    ui.horizontal_wrapped(|ui| {
        for (mode, label, tip, c) in [
            (
                Interpolation::Affine,
                &lang.tr("app.controls.affine"),
                &lang.tr("app.controls.tip.affine"),
                Color32::from_rgb(230, 140, 60),
            ),
            (
                Interpolation::Perspective,
                &lang.tr("app.controls.perspective"),
                &lang.tr("app.controls.tip.perspective"),
                Color32::from_rgb(80, 170, 255),
            ),
        ] {
            let on = options.mode == mode;
            let rich = RichText::new(label)
                .size(ui.style().text_styles[&egui::TextStyle::Button].size * 1.1);
            let rich = if on {
                rich.strong().color(Color32::BLACK)
            } else {
                rich
            };
            let mut button = egui::Button::new(rich).selected(on);
            if on {
                button = button.fill(c);
            }
            if ui.add(button).on_hover_text(tip).clicked() {
                out.push(StateCommand::SetMode(mode));
            }
        }
    });

    section(ui, &lang.tr("app.controls.compare"));
    ui.horizontal_wrapped(|ui| {
        choices(
            ui,
            lang,
            view.compare,
            &[
                (
                    Compare::Single,
                    "app.controls.single",
                    "app.controls.tip.single",
                ),
                (
                    Compare::SideBySide,
                    "app.controls.side_by_side",
                    "app.controls.tip.side_by_side",
                ),
                (Compare::Wipe, "app.controls.wipe", "app.controls.tip.wipe"),
                (
                    Compare::Difference,
                    "app.controls.difference",
                    "app.controls.tip.difference",
                ),
            ],
            &mut out,
            StateCommand::SetCompare,
        );
        out.extend(crate::app::panels::gpu_view::toggle_ui(ui, view.gpu));
        out.extend(crate::app::panels::space_view::toggle_ui(ui, view.space));
        out.extend(crate::app::panels::texel_view::toggle_ui(ui, view.texel));
    });

    section(ui, &lang.tr("app.controls.shading"));
    ui.horizontal_wrapped(|ui| {
        choices(
            ui,
            lang,
            options.shading,
            &[
                (
                    Shading::Texture,
                    "app.controls.texture",
                    "app.controls.tip.texture",
                ),
                (
                    Shading::VertexColor,
                    "app.controls.vertex_color",
                    "app.controls.tip.vertex_color",
                ),
                (
                    Shading::Barycentric,
                    "app.controls.barycentric",
                    "app.controls.tip.barycentric",
                ),
                (
                    Shading::Depth,
                    "app.controls.depth",
                    "app.controls.tip.depth",
                ),
                (
                    Shading::Normal,
                    "app.controls.normal",
                    "app.controls.tip.normal",
                ),
                (
                    Shading::Lambert,
                    "app.controls.lambert",
                    "app.controls.tip.lambert",
                ),
            ],
            &mut out,
            StateCommand::SetShading,
        );
    });
    ui.horizontal_wrapped(|ui| {
        ui.label(lang.tr("app.controls.filter"));
        choices(
            ui,
            lang,
            options.filter,
            &[
                (
                    Filter::Nearest,
                    "app.controls.nearest",
                    "app.controls.tip.nearest",
                ),
                (
                    Filter::Bilinear,
                    "app.controls.bilinear",
                    "app.controls.tip.bilinear",
                ),
                (
                    Filter::Trilinear,
                    "app.controls.trilinear",
                    "app.controls.tip.trilinear",
                ),
            ],
            &mut out,
            StateCommand::SetFilter,
        );
    });
    let mut wire = options.wireframe;
    if ui
        .checkbox(&mut wire, lang.tr("app.controls.wireframe"))
        .on_hover_text(lang.tr("app.controls.tip.wireframe"))
        .changed()
    {
        out.push(StateCommand::SetWireframe(wire));
    }
    ui.horizontal_wrapped(|ui| {
        use crate::raster::render::Rasterizer;
        ui.label(lang.tr("app.controls.rasterizer"));
        choices(
            ui,
            lang,
            view.rasterizer,
            &[
                (
                    Rasterizer::EdgeFunction,
                    "app.controls.edge_functions",
                    "app.controls.tip.edge_functions",
                ),
                (
                    Rasterizer::Scanline,
                    "app.controls.scanline",
                    "app.controls.tip.scanline",
                ),
            ],
            &mut out,
            StateCommand::SetRasterizer,
        );
    });
    out.extend(crate::app::panels::tie_rule::tie_rule_ui(
        ui,
        state.scene.settings().tie_rule,
    ));
    section(ui, &lang.tr("app.samples.title"));
    out.extend(crate::app::panels::samples_control::samples_ui(
        ui,
        state.scene.samples(),
    ));
    out.extend(crate::app::panels::sample_buffers::buffers_ui(
        ui,
        view.samples_view,
        state.scene.samples().count.get(),
    ));

    section(ui, &lang.tr("app.controls.pixels"));
    out.extend(crate::app::panels::image_size::image_size_ui(ui, state));
    let mut px = view.pixel_size;
    if ui
        .add_enabled(
            view.fit_window,
            Slider::new(&mut px, PIXEL_SIZE_RANGE.0..=PIXEL_SIZE_RANGE.1)
                .logarithmic(true)
                .suffix("×")
                .text(lang.tr("app.controls.pixel_size")),
        )
        .on_hover_text(lang.tr("app.controls.tip.pixel_size"))
        .changed()
    {
        out.push(StateCommand::SetPixelSize(px));
    }
    checkbox(
        ui,
        lang,
        view.show_grid,
        ["app.controls.grid", "app.controls.tip.grid"],
        &mut out,
        StateCommand::SetShowGrid,
    );
    checkbox(
        ui,
        lang,
        view.show_handles,
        ["app.controls.handles", "app.controls.tip.handles"],
        &mut out,
        StateCommand::SetShowHandles,
    );
    checkbox(
        ui,
        lang,
        view.show_sub_areas,
        ["app.controls.sub_areas", "app.controls.tip.sub_areas"],
        &mut out,
        StateCommand::SetShowSubAreas,
    );
    checkbox(
        ui,
        lang,
        view.show_magnifier,
        ["app.controls.magnifier", "app.controls.tip.magnifier"],
        &mut out,
        StateCommand::SetShowMagnifier,
    );
    checkbox(
        ui,
        lang,
        view.show_card,
        ["app.controls.card", "app.controls.tip.card"],
        &mut out,
        StateCommand::SetShowCard,
    );

    section(ui, &lang.tr("app.controls.presets"));
    ui.horizontal_wrapped(|ui| {
        for p in Preset::ALL {
            if ui
                .button(preset_name(p, lang))
                .on_hover_text(lang.tr("app.controls.tip.preset"))
                .clicked()
            {
                out.push(StateCommand::Preset(p));
            }
        }
    });

    section(ui, &lang.tr("app.controls.camera"));
    scene_edit::camera_ui(ui, &state.scene, &mut out);

    ui.add_space(6.0);
    egui::CollapsingHeader::new(RichText::new(lang.tr("app.controls.vertices")).strong())
        .default_open(true)
        .show(ui, |ui| scene_edit::vertices_ui(ui, &state.scene, &mut out));
    out
}

/// The reset buttons and the text size, for the top bar.
pub fn reset_ui(ui: &mut Ui, state: &AppState) -> Vec<StateCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut out = Vec::new();
    if ui
        .button(lang.tr("app.controls.reset_scene"))
        .on_hover_text(lang.tr("app.controls.tip.reset_scene"))
        .clicked()
    {
        out.push(StateCommand::ResetScene);
    }
    if ui
        .button(lang.tr("app.controls.reset_all"))
        .on_hover_text(lang.tr("app.controls.tip.reset_all"))
        .clicked()
    {
        out.push(StateCommand::ResetAll);
    }
    ui.separator();
    let mut scale = state.view.ui_scale;
    if ui
        .add(
            Slider::new(&mut scale, UI_SCALE_RANGE.0..=UI_SCALE_RANGE.1)
                .step_by(0.05)
                .text(lang.tr("app.controls.text_size")),
        )
        .on_hover_text(lang.tr("app.controls.tip.text_size"))
        .changed()
    {
        out.push(StateCommand::SetUiScale(scale));
    }
    out
}

/// Room for a slider's value field (with its unit), in points.
const SLIDER_VALUE: f32 = 64.0;

/// Narrows this panel's sliders so that the longest of their `labels` fits beside them in
/// either language, at any text size (a slider's label is drawn to its right and would be cut
/// at the panel's edge).
fn fit_sliders(ui: &mut Ui, labels: &[String]) {
    let font = egui::TextStyle::Body.resolve(ui.style());
    let widest = labels
        .iter()
        .map(|l| {
            ui.painter()
                .layout_no_wrap(l.clone(), font.clone(), Color32::WHITE)
                .size()
                .x
        })
        .fold(0.0, f32::max);
    let room = ui.available_width() - widest - SLIDER_VALUE - 2.0 * ui.spacing().item_spacing.x;
    ui.spacing_mut().slider_width = room.clamp(60.0, 180.0);
}

fn section(ui: &mut Ui, title: &str) {
    ui.add_space(8.0);
    ui.label(
        RichText::new(title)
            .strong()
            .size(ui.style().text_styles[&egui::TextStyle::Heading].size * 0.8),
    );
}

/// A checkbox with its label's and tip's catalogue keys; a change pushes `make(new value)`.
fn checkbox(
    ui: &mut Ui,
    lang: Lang,
    value: bool,
    [label, tip]: [&str; 2],
    out: &mut Vec<StateCommand>,
    make: fn(bool) -> StateCommand,
) {
    let mut v = value;
    let (label, tip) = (lang.tr(label), lang.tr(tip));
    if ui.checkbox(&mut v, label).on_hover_text(tip).changed() {
        out.push(make(v));
    }
}

/// One selectable label per `(value, label key, tip key)`: `current` shown selected, a click
/// pushes `make(value)`.
fn choices<T: Copy + PartialEq>(
    ui: &mut Ui,
    lang: Lang,
    current: T,
    items: &[(T, &str, &str)],
    out: &mut Vec<StateCommand>,
    make: fn(T) -> StateCommand,
) {
    for &(value, label, tip) in items {
        let (label, tip) = (lang.tr(label), lang.tr(tip));
        if ui
            .selectable_label(current == value, label)
            .on_hover_text(tip)
            .clicked()
        {
            out.push(make(value));
        }
    }
}
