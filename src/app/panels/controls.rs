//! The controls panel: mode, comparison, shading, pixel size, presets, camera and vertices.

use egui::{Color32, DragValue, RichText, Slider, Ui};
use glam::{DVec3, DVec4, Vec2};

use crate::app::document::presets::Preset;
use crate::app::document::state::{AppState, PIXEL_SIZE_RANGE, StateCommand, UI_SCALE_RANGE};
use crate::app::panels::paint::color;
use crate::edit::{self, FOV_RANGE_DEG};
use crate::figure::Compare;
use crate::figure::overlay::{vertex_color, vertex_name};
use crate::i18n::Lang;
use crate::raster::camera::ModelView;
use crate::raster::{Filter, Interpolation, Shading};
use crate::scene::{Scene, Tilt};

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

/// Width of numeric fields, in points.
const FIELD_WIDTH: f32 = 64.0;

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
        for (c, label, tip) in [
            (
                Compare::Single,
                &lang.tr("app.controls.single"),
                &lang.tr("app.controls.tip.single"),
            ),
            (
                Compare::SideBySide,
                &lang.tr("app.controls.side_by_side"),
                &lang.tr("app.controls.tip.side_by_side"),
            ),
            (
                Compare::Wipe,
                &lang.tr("app.controls.wipe"),
                &lang.tr("app.controls.tip.wipe"),
            ),
            (
                Compare::Difference,
                &lang.tr("app.controls.difference"),
                &lang.tr("app.controls.tip.difference"),
            ),
        ] {
            if ui
                .selectable_label(view.compare == c, label)
                .on_hover_text(tip)
                .clicked()
            {
                out.push(StateCommand::SetCompare(c));
            }
        }
        out.extend(crate::app::panels::gpu_view::toggle_ui(ui, view.gpu));
        out.extend(crate::app::panels::space_view::toggle_ui(ui, view.space));
        out.extend(crate::app::panels::texel_view::toggle_ui(ui, view.texel));
    });

    section(ui, &lang.tr("app.controls.shading"));
    ui.horizontal_wrapped(|ui| {
        for (s, label, tip) in [
            (
                Shading::Texture,
                &lang.tr("app.controls.texture"),
                &lang.tr("app.controls.tip.texture"),
            ),
            (
                Shading::VertexColor,
                &lang.tr("app.controls.vertex_color"),
                &lang.tr("app.controls.tip.vertex_color"),
            ),
            (
                Shading::Barycentric,
                &lang.tr("app.controls.barycentric"),
                &lang.tr("app.controls.tip.barycentric"),
            ),
            (
                Shading::Depth,
                &lang.tr("app.controls.depth"),
                &lang.tr("app.controls.tip.depth"),
            ),
            (
                Shading::Normal,
                &lang.tr("app.controls.normal"),
                &lang.tr("app.controls.tip.normal"),
            ),
            (
                Shading::Lambert,
                &lang.tr("app.controls.lambert"),
                &lang.tr("app.controls.tip.lambert"),
            ),
        ] {
            if ui
                .selectable_label(options.shading == s, label)
                .on_hover_text(tip)
                .clicked()
            {
                out.push(StateCommand::SetShading(s));
            }
        }
    });
    ui.horizontal_wrapped(|ui| {
        ui.label(lang.tr("app.controls.filter"));
        for (f, label, tip) in [
            (
                Filter::Nearest,
                &lang.tr("app.controls.nearest"),
                &lang.tr("app.controls.tip.nearest"),
            ),
            (
                Filter::Bilinear,
                &lang.tr("app.controls.bilinear"),
                &lang.tr("app.controls.tip.bilinear"),
            ),
            (
                Filter::Trilinear,
                &lang.tr("app.controls.trilinear"),
                &lang.tr("app.controls.tip.trilinear"),
            ),
        ] {
            if ui
                .selectable_label(options.filter == f, label)
                .on_hover_text(tip)
                .clicked()
            {
                out.push(StateCommand::SetFilter(f));
            }
        }
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
        for (r, label, tip) in [
            (
                Rasterizer::EdgeFunction,
                &lang.tr("app.controls.edge_functions"),
                &lang.tr("app.controls.tip.edge_functions"),
            ),
            (
                Rasterizer::Scanline,
                &lang.tr("app.controls.scanline"),
                &lang.tr("app.controls.tip.scanline"),
            ),
        ] {
            if ui
                .selectable_label(view.rasterizer == r, label)
                .on_hover_text(tip)
                .clicked()
            {
                out.push(StateCommand::SetRasterizer(r));
            }
        }
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
        view.show_grid,
        &lang.tr("app.controls.grid"),
        &lang.tr("app.controls.tip.grid"),
        &mut out,
        StateCommand::SetShowGrid,
    );
    checkbox(
        ui,
        view.show_handles,
        &lang.tr("app.controls.handles"),
        &lang.tr("app.controls.tip.handles"),
        &mut out,
        StateCommand::SetShowHandles,
    );
    checkbox(
        ui,
        view.show_sub_areas,
        &lang.tr("app.controls.sub_areas"),
        &lang.tr("app.controls.tip.sub_areas"),
        &mut out,
        StateCommand::SetShowSubAreas,
    );
    checkbox(
        ui,
        view.show_magnifier,
        &lang.tr("app.controls.magnifier"),
        &lang.tr("app.controls.tip.magnifier"),
        &mut out,
        StateCommand::SetShowMagnifier,
    );
    checkbox(
        ui,
        view.show_card,
        &lang.tr("app.controls.card"),
        &lang.tr("app.controls.tip.card"),
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
    camera_ui(ui, &state.scene, &mut out);

    ui.add_space(6.0);
    egui::CollapsingHeader::new(RichText::new(lang.tr("app.controls.vertices")).strong())
        .default_open(true)
        .show(ui, |ui| vertices_ui(ui, &state.scene, &mut out));
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

fn checkbox(
    ui: &mut Ui,
    value: bool,
    label: &str,
    tip: &str,
    out: &mut Vec<StateCommand>,
    make: fn(bool) -> StateCommand,
) {
    let mut v = value;
    if ui.checkbox(&mut v, label).on_hover_text(tip).changed() {
        out.push(make(v));
    }
}

fn camera_ui(ui: &mut Ui, scene: &Scene, out: &mut Vec<StateCommand>) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    if let Scene::Model(_) = scene {
        model_camera_ui(ui, scene, out);
        return;
    }
    let Scene::World(s) = scene else {
        ui.label(lang.tr("app.controls.no_tilt_clip"));
        return;
    };
    let mut tilt = s.tilt;
    let mut changed = false;
    changed |= ui
        .add(
            Slider::new(&mut tilt.pitch_deg, -90.0..=90.0)
                .suffix("°")
                .text(lang.tr("app.controls.pitch")),
        )
        .on_hover_text(lang.tr("app.controls.tip.pitch"))
        .changed();
    changed |= ui
        .add(
            Slider::new(&mut tilt.yaw_deg, -90.0..=90.0)
                .suffix("°")
                .text(lang.tr("app.controls.yaw")),
        )
        .on_hover_text(lang.tr("app.controls.tip.yaw"))
        .changed();
    if changed {
        out.push(StateCommand::SetTilt(Tilt {
            pitch_deg: tilt.pitch_deg,
            yaw_deg: tilt.yaw_deg,
        }));
    }
    if let Some(mut fov) = edit::fov_deg(scene)
        && ui
            .add(
                Slider::new(&mut fov, FOV_RANGE_DEG.0..=FOV_RANGE_DEG.1)
                    .suffix("°")
                    .text(lang.tr("app.controls.fov")),
            )
            .on_hover_text(lang.tr("app.controls.tip.fov"))
            .changed()
    {
        out.push(StateCommand::SetFov(fov));
    }
}

/// Model scenes: how to move the camera, the field of view, reset.
fn model_camera_ui(ui: &mut Ui, scene: &Scene, out: &mut Vec<StateCommand>) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    ui.label(RichText::new(lang.tr("app.controls.model_camera_hint")).weak());
    if let Some(mut fov) = edit::fov_deg(scene)
        && ui
            .add(
                Slider::new(&mut fov, FOV_RANGE_DEG.0..=FOV_RANGE_DEG.1)
                    .suffix("°")
                    .text(lang.tr("app.controls.fov")),
            )
            .on_hover_text(lang.tr("app.controls.tip.fov"))
            .changed()
    {
        out.push(StateCommand::SetFov(fov));
    }
    ui.horizontal_wrapped(|ui| {
        ui.label(lang.tr("app.controls.view"));
        for v in ModelView::ALL {
            if ui
                .button(model_view_name(v, lang))
                .on_hover_text(lang.tr("app.controls.tip.view"))
                .clicked()
            {
                out.push(StateCommand::ModelView(v));
            }
        }
    });
    if ui
        .button(lang.tr("app.controls.reset_view"))
        .on_hover_text(lang.tr("app.controls.tip.reset_view"))
        .clicked()
    {
        out.push(StateCommand::ResetCamera);
    }
}

/// The name of a model view, for its button.
fn model_view_name(v: ModelView, lang: Lang) -> String {
    lang.tr(match v {
        ModelView::Course => "app.controls.views.course",
        ModelView::Front => "app.controls.views.front",
        ModelView::Back => "app.controls.views.back",
        ModelView::Left => "app.controls.views.left",
        ModelView::Right => "app.controls.views.right",
        ModelView::Top => "app.controls.views.top",
    })
}

fn vertex_label(ui: &mut Ui, k: usize) {
    ui.label(
        RichText::new(vertex_name(k))
            .strong()
            .color(color(vertex_color(k))),
    );
}

fn field(ui: &mut Ui, v: &mut f64, speed: f64, tip: &str) -> bool {
    ui.add_sized(
        [FIELD_WIDTH, ui.spacing().interact_size.y],
        DragValue::new(v).speed(speed).max_decimals(3),
    )
    .on_hover_text(tip)
    .changed()
}

/// A grid row with a vertex's uv as two numeric fields; sets `changed` when edited.
fn uv_row(ui: &mut Ui, uv: Vec2, changed: &mut bool) -> Vec2 {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut uv = uv.as_dvec2();
    ui.label(RichText::new(lang.tr("app.controls.uv")).weak());
    ui.horizontal(|ui| {
        *changed |= field(ui, &mut uv.x, 0.01, &lang.tr("app.controls.tip.uv"));
        *changed |= field(ui, &mut uv.y, 0.01, &lang.tr("app.controls.tip.uv"));
    });
    ui.end_row();
    uv.as_vec2()
}

fn vertices_ui(ui: &mut Ui, scene: &Scene, out: &mut Vec<StateCommand>) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    match scene {
        Scene::World(s) => {
            egui::Grid::new("corners")
                .num_columns(2)
                .spacing([6.0, 6.0])
                .show(ui, |ui| {
                    for (k, c) in s.quad.iter().enumerate() {
                        vertex_label(ui, k);
                        let mut p = c.position;
                        let mut changed = false;
                        ui.horizontal(|ui| {
                            changed |=
                                field(ui, &mut p.x, 0.01, &lang.tr("app.controls.tip.position"));
                            changed |=
                                field(ui, &mut p.y, 0.01, &lang.tr("app.controls.tip.position"));
                            changed |=
                                field(ui, &mut p.z, 0.01, &lang.tr("app.controls.tip.position"));
                        });
                        ui.end_row();
                        let uv = uv_row(ui, c.uv, &mut changed);
                        if changed {
                            out.push(StateCommand::SetCorner {
                                index: k,
                                position: DVec3::new(p.x, p.y, p.z),
                                uv,
                                color: c.color,
                            });
                        }
                    }
                });
            ui.label(
                RichText::new(format!("{}: x, y, z", &lang.tr("app.controls.position"))).weak(),
            );
        }
        Scene::Clip(s) => {
            egui::Grid::new("clip-vertices")
                .num_columns(2)
                .spacing([6.0, 6.0])
                .show(ui, |ui| {
                    for (k, v) in s.vertices.iter().enumerate() {
                        vertex_label(ui, k);
                        let mut c = v.clip;
                        let mut changed = false;
                        ui.horizontal(|ui| {
                            changed |= field(ui, &mut c.x, 0.01, &lang.tr("app.controls.tip.clip"));
                            changed |= field(ui, &mut c.y, 0.01, &lang.tr("app.controls.tip.clip"));
                            changed |= field(ui, &mut c.z, 0.01, &lang.tr("app.controls.tip.clip"));
                            changed |= field(ui, &mut c.w, 0.01, &lang.tr("app.controls.tip.clip"));
                        });
                        ui.end_row();
                        let uv = uv_row(ui, v.uv, &mut changed);
                        if changed {
                            out.push(StateCommand::SetClipVertex {
                                index: k,
                                clip: DVec4::new(c.x, c.y, c.z, c.w),
                                uv,
                            });
                        }
                    }
                });
            ui.label(
                RichText::new(format!("{}: x, y, z, w", &lang.tr("app.controls.clip"))).weak(),
            );
        }
        Scene::Model(m) => {
            ui.label(format!(
                "{} {} ({} {}, {} {})",
                &lang.tr("app.controls.model"),
                m.model,
                m.mesh.positions.len(),
                &lang.tr("app.controls.model_vertices"),
                m.mesh.triangles.len(),
                &lang.tr("app.controls.model_triangles")
            ));
        }
    }
}
