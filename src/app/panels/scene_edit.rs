//! The scene's camera and vertices in the controls panel: the tilt of a world scene or a model's
//! camera, and each vertex's position, w and uv as numeric fields.

use egui::{DragValue, RichText, Slider, Ui};
use glam::{DVec3, DVec4, Vec2};

use crate::app::document::state::StateCommand;
use crate::app::panels::paint::color;
use crate::edit::{self, FOV_RANGE_DEG};
use crate::figure::overlay::{vertex_color, vertex_name};
use crate::i18n::Lang;
use crate::raster::camera::ModelView;
use crate::scene::{Scene, Tilt};

/// Width of numeric fields, in points.
const FIELD_WIDTH: f32 = 64.0;

/// The camera: a world scene's tilt sliders, a model scene's camera controls, or a note for a
/// clip-space scene.
pub(super) fn camera_ui(ui: &mut Ui, scene: &Scene, out: &mut Vec<StateCommand>) {
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
    fov_ui(ui, lang, scene, out);
}

/// The field-of-view slider, for a scene with a perspective camera.
fn fov_ui(ui: &mut Ui, lang: Lang, scene: &Scene, out: &mut Vec<StateCommand>) {
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
    fov_ui(ui, lang, scene, out);
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

pub(super) fn vertices_ui(ui: &mut Ui, scene: &Scene, out: &mut Vec<StateCommand>) {
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
