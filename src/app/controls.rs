//! The controls panel: mode, comparison, shading, pixel size, presets, camera and vertices.

use egui::{Color32, DragValue, RichText, Slider, Ui};
use glam::{DVec3, DVec4, Vec2};

use super::edit::{self, FOV_RANGE_DEG};
use super::paint::color;
use super::presets::Preset;
use super::state::{AppState, Command, PIXEL_SIZE_RANGE, UI_SCALE_RANGE};
use crate::figure::Compare;
use crate::figure::overlay::{vertex_color, vertex_name};
use crate::raster::{Filter, Interpolation, Shading};
use crate::scene::{Scene, Tilt};

/// User-facing strings of the controls panel.
pub mod text {
    pub const INTERPOLATION: &str = "Interpolation";
    pub const AFFINE: &str = "Affine";
    pub const PERSPECTIVE: &str = "Perspective-correct";
    pub const COMPARE: &str = "Compare";
    pub const SINGLE: &str = "Single";
    pub const SIDE_BY_SIDE: &str = "Side by side";
    pub const WIPE: &str = "Wipe";
    pub const DIFFERENCE: &str = "Difference";
    pub const SHADING: &str = "Shading";
    pub const TEXTURE: &str = "Texture";
    pub const VERTEX_COLOR: &str = "Vertex colour";
    pub const BARYCENTRIC: &str = "Barycentric";
    pub const DEPTH: &str = "Depth";
    pub const FILTER: &str = "Filter";
    pub const NEAREST: &str = "Nearest";
    pub const BILINEAR: &str = "Bilinear";
    pub const TRILINEAR: &str = "Trilinear";
    pub const WIREFRAME: &str = "Wireframe (edges + diagonal)";
    pub const RASTERIZER: &str = "Rasterizer";
    pub const EDGE_FUNCTIONS: &str = "Edge functions";
    pub const SCANLINE: &str = "Scanline";
    pub const PIXELS: &str = "Pixels";
    pub const PIXEL_SIZE: &str = "Pixel size";
    pub const GRID: &str = "Pixel grid and sample points";
    pub const HANDLES: &str = "Corner handles";
    pub const SUB_AREAS: &str = "Sub-triangle areas";
    pub const PRESETS: &str = "Presets";
    pub const CAMERA: &str = "Tilt and camera";
    pub const PITCH: &str = "Pitch";
    pub const YAW: &str = "Yaw";
    pub const FOV: &str = "Field of view";
    pub const VERTICES: &str = "Corners";
    pub const POSITION: &str = "position";
    pub const CLIP: &str = "clip";
    pub const UV: &str = "uv";
    pub const RESET_SCENE: &str = "Reset scene";
    pub const RESET_ALL: &str = "Reset everything";
    pub const TEXT_SIZE: &str = "Text size";
    pub const NO_TILT_CLIP: &str = "Clip-space and model scenes have no tilt.";
    pub const MODEL: &str = "Model";
    pub const MODEL_VERTICES: &str = "vertices";
    pub const MODEL_TRIANGLES: &str = "triangles";
    pub const MODEL_CAMERA_HINT: &str =
        "Drag: orbit · Shift+drag or right drag: pan · scroll: zoom";
    pub const RESET_VIEW: &str = "Reset view";

    pub fn preset(p: super::Preset) -> &'static str {
        use super::Preset::*;
        match p {
            FrontFacing => "Front-facing",
            Floor => "Floor (default)",
            GrazingWall => "Wall at a grazing angle",
            FarCorner => "One corner far away",
            CornerBehind => "A corner behind the camera",
        }
    }
}

/// Tooltips of the controls (and of canvas items).
pub mod tips {
    pub const AFFINE: &str = "Interpolate with screen-space weights, as if the triangle were flat \
        on the screen (GLSL `noperspective`). Key: P";
    pub const PERSPECTIVE: &str = "Divide by w before interpolating and multiply back \
        (GLSL `smooth`, what GPUs do by default). Key: P";
    pub const SINGLE: &str = "One view in the chosen interpolation mode. Key: 1";
    pub const SIDE_BY_SIDE: &str =
        "Affine on the left, perspective-correct on the right, same view. Key: 2";
    pub const WIPE: &str = "One view split by a line you can drag: affine on the left, \
        perspective-correct on the right. Key: 3";
    pub const DIFFERENCE: &str = "How far apart the two modes' texture coordinates are, in texels, \
        as a heatmap with a colour bar. Key: 4";
    pub const TEXTURE: &str = "Sample the texture at the interpolated uv.";
    pub const VERTEX_COLOR: &str = "Interpolate the corners' colours.";
    pub const BARYCENTRIC: &str =
        "Show the three weights of the pixel's triangle as red, green, blue.";
    pub const DEPTH: &str =
        "Window depth z/w as grey (near black, far white): it is linear on screen.";
    pub const NEAREST: &str = "GL_NEAREST: the texel containing the sample.";
    pub const BILINEAR: &str = "GL_LINEAR: the four texels around the sample, weighted.";
    pub const TRILINEAR: &str = "GL_LINEAR_MIPMAP_LINEAR: bilinear in the two mipmap levels \
        around the level of detail (from the uv change across the 2x2 pixel quad), blended. \
        Compare with bilinear on a far-away checkerboard: the moiré goes away.";
    pub const EDGE_FUNCTIONS: &str = "Every pixel of the triangle's bounding box (in 8x8 blocks, \
        whole blocks rejected or accepted at once) is tested against the three edge functions \
        and interpolated from its own weights. The inspector shows exactly these numbers.";
    pub const SCANLINE: &str = "Per row, the covered span is found from the edges, and u/w, v/w, \
        1/w are stepped by one addition per pixel (the classic incremental scanline). Same pixels covered; \
        values equal up to rounding. The inspector still shows the edge-function derivation.";
    pub const WIREFRAME: &str = "Draw the triangles' edges (and so the quad's diagonal A-C) by \
        thresholding the smallest weight. Key: W";
    pub const PIXEL_SIZE: &str = "With \"Fit window\": render at a lower resolution and \
        magnify, so each rendered pixel is this many screen pixels wide. Keys: [ and ]";
    pub const GRID: &str = "At large pixel sizes, draw the pixel grid and the pixel centres \
        where the samples are taken. Key: G";
    pub const HANDLES: &str = "Show the draggable corner handles with their w. Key: H";
    pub const SUB_AREAS: &str = "Shade the three sub-triangles of the hovered pixel: each one's \
        signed area over the whole is the weight of the opposite corner.";
    pub const PRESET: &str = "Load this situation (keeps mode, shading and texture).";
    pub const PITCH: &str = "Rotate the quad about its centre around the horizontal axis.";
    pub const YAW: &str = "Rotate the quad about its centre around the vertical axis.";
    pub const FOV: &str = "The camera's vertical field of view. Wider means stronger perspective.";
    pub const POSITION: &str = "Object-space position (before the tilt). Drag to change, \
        double-click to type.";
    pub const CLIP: &str = "Clip-space position (x, y, z, w).";
    pub const UV: &str = "Texture coordinate of this corner.";
    pub const RESET_SCENE: &str = "Back to the built-in floor scene; view settings stay.";
    pub const RESET_ALL: &str = "Back to the default scene and all default settings.";
    pub const TEXT_SIZE: &str = "Zoom the whole interface, for a projector. Keys: Ctrl + / Ctrl -";
    pub const RESET_VIEW: &str = "Back to the camera that frames the whole model. Key: Home";
}

/// Width of numeric fields, in points.
const FIELD_WIDTH: f32 = 64.0;

/// The controls panel.
pub fn controls_ui(ui: &mut Ui, state: &AppState) -> Vec<Command> {
    let mut out = Vec::new();
    let options = state.options();
    let view = &state.view;

    section(ui, text::INTERPOLATION);
    ui.horizontal_wrapped(|ui| {
        for (mode, label, tip, c) in [
            (
                Interpolation::Affine,
                text::AFFINE,
                tips::AFFINE,
                Color32::from_rgb(230, 140, 60),
            ),
            (
                Interpolation::Perspective,
                text::PERSPECTIVE,
                tips::PERSPECTIVE,
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
                out.push(Command::SetMode(mode));
            }
        }
    });

    section(ui, text::COMPARE);
    ui.horizontal_wrapped(|ui| {
        for (c, label, tip) in [
            (Compare::Single, text::SINGLE, tips::SINGLE),
            (Compare::SideBySide, text::SIDE_BY_SIDE, tips::SIDE_BY_SIDE),
            (Compare::Wipe, text::WIPE, tips::WIPE),
            (Compare::Difference, text::DIFFERENCE, tips::DIFFERENCE),
        ] {
            if ui
                .selectable_label(view.compare == c, label)
                .on_hover_text(tip)
                .clicked()
            {
                out.push(Command::SetCompare(c));
            }
        }
    });

    section(ui, text::SHADING);
    ui.horizontal_wrapped(|ui| {
        for (s, label, tip) in [
            (Shading::Texture, text::TEXTURE, tips::TEXTURE),
            (Shading::VertexColor, text::VERTEX_COLOR, tips::VERTEX_COLOR),
            (Shading::Barycentric, text::BARYCENTRIC, tips::BARYCENTRIC),
            (Shading::Depth, text::DEPTH, tips::DEPTH),
        ] {
            if ui
                .selectable_label(options.shading == s, label)
                .on_hover_text(tip)
                .clicked()
            {
                out.push(Command::SetShading(s));
            }
        }
    });
    ui.horizontal_wrapped(|ui| {
        ui.label(text::FILTER);
        for (f, label, tip) in [
            (Filter::Nearest, text::NEAREST, tips::NEAREST),
            (Filter::Bilinear, text::BILINEAR, tips::BILINEAR),
            (Filter::Trilinear, text::TRILINEAR, tips::TRILINEAR),
        ] {
            if ui
                .selectable_label(options.filter == f, label)
                .on_hover_text(tip)
                .clicked()
            {
                out.push(Command::SetFilter(f));
            }
        }
    });
    let mut wire = options.wireframe;
    if ui
        .checkbox(&mut wire, text::WIREFRAME)
        .on_hover_text(tips::WIREFRAME)
        .changed()
    {
        out.push(Command::SetWireframe(wire));
    }
    ui.horizontal_wrapped(|ui| {
        use crate::raster::render::Rasterizer;
        ui.label(text::RASTERIZER);
        for (r, label, tip) in [
            (
                Rasterizer::EdgeFunction,
                text::EDGE_FUNCTIONS,
                tips::EDGE_FUNCTIONS,
            ),
            (Rasterizer::Scanline, text::SCANLINE, tips::SCANLINE),
        ] {
            if ui
                .selectable_label(view.rasterizer == r, label)
                .on_hover_text(tip)
                .clicked()
            {
                out.push(Command::SetRasterizer(r));
            }
        }
    });

    section(ui, text::PIXELS);
    out.extend(super::image_size::image_size_ui(ui, state));
    let mut px = view.pixel_size;
    if ui
        .add_enabled(
            view.fit_window,
            Slider::new(&mut px, PIXEL_SIZE_RANGE.0..=PIXEL_SIZE_RANGE.1)
                .logarithmic(true)
                .suffix("×")
                .text(text::PIXEL_SIZE),
        )
        .on_hover_text(tips::PIXEL_SIZE)
        .changed()
    {
        out.push(Command::SetPixelSize(px));
    }
    checkbox(
        ui,
        view.show_grid,
        text::GRID,
        tips::GRID,
        &mut out,
        Command::SetShowGrid,
    );
    checkbox(
        ui,
        view.show_handles,
        text::HANDLES,
        tips::HANDLES,
        &mut out,
        Command::SetShowHandles,
    );
    checkbox(
        ui,
        view.show_sub_areas,
        text::SUB_AREAS,
        tips::SUB_AREAS,
        &mut out,
        Command::SetShowSubAreas,
    );

    section(ui, text::PRESETS);
    ui.horizontal_wrapped(|ui| {
        for p in Preset::ALL {
            if ui
                .button(text::preset(p))
                .on_hover_text(tips::PRESET)
                .clicked()
            {
                out.push(Command::Preset(p));
            }
        }
    });

    section(ui, text::CAMERA);
    camera_ui(ui, &state.scene, &mut out);

    ui.add_space(6.0);
    egui::CollapsingHeader::new(RichText::new(text::VERTICES).strong())
        .default_open(true)
        .show(ui, |ui| vertices_ui(ui, &state.scene, &mut out));
    out
}

/// The reset buttons and the text size, for the top bar.
pub fn reset_ui(ui: &mut Ui, state: &AppState) -> Vec<Command> {
    let mut out = Vec::new();
    if ui
        .button(text::RESET_SCENE)
        .on_hover_text(tips::RESET_SCENE)
        .clicked()
    {
        out.push(Command::ResetScene);
    }
    if ui
        .button(text::RESET_ALL)
        .on_hover_text(tips::RESET_ALL)
        .clicked()
    {
        out.push(Command::ResetAll);
    }
    ui.separator();
    let mut scale = state.view.ui_scale;
    if ui
        .add(
            Slider::new(&mut scale, UI_SCALE_RANGE.0..=UI_SCALE_RANGE.1)
                .step_by(0.05)
                .text(text::TEXT_SIZE),
        )
        .on_hover_text(tips::TEXT_SIZE)
        .changed()
    {
        out.push(Command::SetUiScale(scale));
    }
    out
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
    out: &mut Vec<Command>,
    make: fn(bool) -> Command,
) {
    let mut v = value;
    if ui.checkbox(&mut v, label).on_hover_text(tip).changed() {
        out.push(make(v));
    }
}

fn camera_ui(ui: &mut Ui, scene: &Scene, out: &mut Vec<Command>) {
    if let Scene::Model(_) = scene {
        model_camera_ui(ui, scene, out);
        return;
    }
    let Scene::World(s) = scene else {
        ui.label(text::NO_TILT_CLIP);
        return;
    };
    let mut tilt = s.tilt;
    let mut changed = false;
    changed |= ui
        .add(
            Slider::new(&mut tilt.pitch_deg, -90.0..=90.0)
                .suffix("°")
                .text(text::PITCH),
        )
        .on_hover_text(tips::PITCH)
        .changed();
    changed |= ui
        .add(
            Slider::new(&mut tilt.yaw_deg, -90.0..=90.0)
                .suffix("°")
                .text(text::YAW),
        )
        .on_hover_text(tips::YAW)
        .changed();
    if changed {
        out.push(Command::SetTilt(Tilt {
            pitch_deg: tilt.pitch_deg,
            yaw_deg: tilt.yaw_deg,
        }));
    }
    if let Some(mut fov) = edit::fov_deg(scene)
        && ui
            .add(
                Slider::new(&mut fov, FOV_RANGE_DEG.0..=FOV_RANGE_DEG.1)
                    .suffix("°")
                    .text(text::FOV),
            )
            .on_hover_text(tips::FOV)
            .changed()
    {
        out.push(Command::SetFov(fov));
    }
}

/// Model scenes: how to move the camera, the field of view, reset.
fn model_camera_ui(ui: &mut Ui, scene: &Scene, out: &mut Vec<Command>) {
    ui.label(RichText::new(text::MODEL_CAMERA_HINT).weak());
    if let Some(mut fov) = edit::fov_deg(scene)
        && ui
            .add(
                Slider::new(&mut fov, FOV_RANGE_DEG.0..=FOV_RANGE_DEG.1)
                    .suffix("°")
                    .text(text::FOV),
            )
            .on_hover_text(tips::FOV)
            .changed()
    {
        out.push(Command::SetFov(fov));
    }
    if ui
        .button(text::RESET_VIEW)
        .on_hover_text(tips::RESET_VIEW)
        .clicked()
    {
        out.push(Command::ResetCamera);
    }
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
    let mut uv = uv.as_dvec2();
    ui.label(RichText::new(text::UV).weak());
    ui.horizontal(|ui| {
        *changed |= field(ui, &mut uv.x, 0.01, tips::UV);
        *changed |= field(ui, &mut uv.y, 0.01, tips::UV);
    });
    ui.end_row();
    uv.as_vec2()
}

fn vertices_ui(ui: &mut Ui, scene: &Scene, out: &mut Vec<Command>) {
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
                            changed |= field(ui, &mut p.x, 0.01, tips::POSITION);
                            changed |= field(ui, &mut p.y, 0.01, tips::POSITION);
                            changed |= field(ui, &mut p.z, 0.01, tips::POSITION);
                        });
                        ui.end_row();
                        let uv = uv_row(ui, c.uv, &mut changed);
                        if changed {
                            out.push(Command::SetCorner {
                                index: k,
                                position: DVec3::new(p.x, p.y, p.z),
                                uv,
                                color: c.color,
                            });
                        }
                    }
                });
            ui.label(RichText::new(format!("{}: x, y, z", text::POSITION)).weak());
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
                            changed |= field(ui, &mut c.x, 0.01, tips::CLIP);
                            changed |= field(ui, &mut c.y, 0.01, tips::CLIP);
                            changed |= field(ui, &mut c.z, 0.01, tips::CLIP);
                            changed |= field(ui, &mut c.w, 0.01, tips::CLIP);
                        });
                        ui.end_row();
                        let uv = uv_row(ui, v.uv, &mut changed);
                        if changed {
                            out.push(Command::SetClipVertex {
                                index: k,
                                clip: DVec4::new(c.x, c.y, c.z, c.w),
                                uv,
                            });
                        }
                    }
                });
            ui.label(RichText::new(format!("{}: x, y, z, w", text::CLIP)).weak());
        }
        Scene::Model(m) => {
            ui.label(format!(
                "{} {} ({} {}, {} {})",
                text::MODEL,
                m.model,
                m.mesh.positions.len(),
                text::MODEL_VERTICES,
                m.mesh.triangles.len(),
                text::MODEL_TRIANGLES
            ));
        }
    }
}
