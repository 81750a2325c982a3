//! The canvas panel: the CPU-rendered image (one or two views), the overlays, the vertex
//! handles, hovering and pinning pixels. The renders themselves: `crate::app::services::render`.

use std::sync::Arc;

use egui::{Color32, CursorIcon, Id, Pos2, Rect, Sense, Ui};
use glam::DVec2;

use crate::app::document::state::{AppState, StateCommand};
use crate::app::panels::canvas_layout::{Sizing, layout};
use crate::app::panels::canvas_progress;
use crate::app::panels::gpu_view::GpuView;
use crate::app::panels::other_image;
use crate::app::panels::paint::{self, CanvasTransform};
use crate::app::services::pixel::PixelReport;
use crate::app::services::render::TextureKey;
use crate::figure::overlay::{self, HandleMark, OverlayInput};
use crate::figure::{Compare, VertexOnScreen, ViewContent, vertices_on_screen};
use crate::raster::project::Viewport;
use crate::raster::{Interpolation, Texture};
use crate::scene::Scene;

/// Points: extra grab radius around a handle.
const HANDLE_GRAB_SLACK: f32 = 6.0;
/// Points: the side of the square around the pinned pixel's marker that labels keep clear of.
const PIN_CLEARANCE: f32 = 24.0;
/// Seconds per pixel while stepping along the scanline span.
const SPAN_STEP_SECONDS: f64 = 0.12;
/// Steps the stepping rests on the span's last pixel before it starts again.
const SPAN_PAUSE_STEPS: u32 = 8;
/// Points: half-width of the wipe line's grab area.
const WIPE_GRAB: f32 = 10.0;
/// w factor per point of vertical Shift+drag: 100 points up doubles w roughly (e^0.7).
const PUSH_PER_POINT: f64 = 0.007;
/// w factor per point of scrolling.
const PUSH_PER_SCROLL_POINT: f64 = 0.004;
/// Model scenes: degrees the camera orbits per point dragged (a 450-point drag turns 180°).
const ORBIT_DEG_PER_POINT: f64 = 0.4;
/// Model scenes: the camera distance is multiplied by e^(-this) per point scrolled up.
const ZOOM_PER_SCROLL_POINT: f64 = 0.004;

mod state;
use state::DragKind;
pub use state::{CanvasState, CanvasTiming, View};

/// Inputs the canvas needs besides its own state.
pub(crate) struct CanvasInput<'a> {
    /// The document the canvas renders and edits.
    pub state: &'a AppState,
    /// The scene's texture, loaded.
    pub texture: &'a Arc<Texture>,
    /// Identifies the texture, so a new one triggers a new render.
    pub texture_key: TextureKey,
    /// Derivations of the hovered and pinned pixels from the last frame (for the overlay).
    pub hover_report: Option<&'a PixelReport>,
    /// The pinned pixel's derivation from the last frame (for the overlay).
    pub pin_report: Option<&'a PixelReport>,
    /// The GPU view, when it is on.
    pub gpu: Option<&'a GpuView>,
    /// How the images are framed (presentation mode: larger, a single view without title).
    pub framing: crate::app::panels::canvas_layout::Framing,
    /// The size of the overlay's marks (handles, labels, markers) relative to the usual:
    /// larger in presentation mode, for the back of the room.
    pub mark_scale: f32,
}

/// Most vertices whose handles and labels the canvas draws. A denser scene shows only the
/// corners of the pinned and the hovered pixel's triangles: a label on every vertex of a mesh
/// is unreadable, and each handle costs a widget and a text layout every frame (a 5,000
/// triangle mesh took 42 s to its first frame with one for each).
pub(crate) const MAX_HANDLES: usize = 32;

/// The vertices whose handles are drawn: all `count` when there are at most [`MAX_HANDLES`],
/// else the mesh corners of the triangles of `marks` (the pinned and hovered pixels), in
/// order, each once.
fn handle_indices(count: usize, marks: [Option<overlay::PixelMark>; 2]) -> Vec<usize> {
    if count <= MAX_HANDLES {
        return (0..count).collect();
    }
    let mut shown: Vec<usize> = Vec::new();
    for k in marks
        .iter()
        .flatten()
        .filter_map(|m| m.triangle)
        .flat_map(|t| t.mesh_indices)
        .flatten()
    {
        if k < count && !shown.contains(&k) {
            shown.push(k);
        }
    }
    shown
}

/// How the canvas sizes its image: to fit the window at the chosen pixel size, or the
/// scene's own size.
pub(crate) fn sizing(state: &AppState) -> Sizing {
    let (w, h) = state.scene.size();
    if state.view.fit_window {
        Sizing::Fit {
            aspect: w as f32 / h as f32,
            pixel_size: state.view.pixel_size,
        }
    } else {
        Sizing::Fixed([w, h])
    }
}

/// The views of a canvas `lay`out, their transforms mapping pixels of an image `image_width`
/// pixels wide (the render shown, which may be of another size than the layout's) to the
/// screen; what each shows as the canvas draws it (`gpu`: the GPU view is on).
pub(crate) fn views_of(
    lay: &crate::app::panels::canvas_layout::Layout,
    state: &AppState,
    gpu: bool,
    image_width: u32,
) -> Vec<View> {
    let compare = state.view.compare;
    lay.views
        .iter()
        .zip(&lay.areas)
        .map(|(&(rect, content), &area)| View {
            rect,
            area,
            transform: CanvasTransform {
                origin: rect.min,
                scale: lay.scale * lay.size[0] as f32 / image_width.max(1) as f32,
            },
            content: match content {
                ViewContent::Mode(_) if compare == Compare::Single || gpu => {
                    ViewContent::Mode(state.options().mode)
                }
                c => c,
            },
        })
        .collect()
}

/// The canvas panel. It renders and uploads what changed, and keeps its own widget state
/// (views, hovered pixel, drag) in `canvas`; every change to the app is a returned command.
pub(crate) fn canvas_ui(
    ui: &mut Ui,
    canvas: &mut CanvasState,
    input: CanvasInput<'_>,
) -> Vec<StateCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut out = Vec::new();
    let state = input.state;
    let view_settings = &state.view;
    let ppp = ui.ctx().pixels_per_point();
    let available = ui.available_rect_before_wrap();
    canvas.area = Some(available);
    let lay = layout(
        available,
        view_settings.compare,
        sizing(state),
        ppp,
        input.framing,
    );
    let size = lay.size;
    let compare = other_image::render_compare(input.gpu, view_settings.compare);
    canvas.update(
        state,
        compare,
        size,
        input.texture,
        input.texture_key.clone(),
    );
    // While a larger render is drawn (or after one was cancelled) the picture shown is an
    // older one of another size: it is laid out at its own size, so the pixel under the
    // pointer (and the probe's numbers) are its pixels.
    let lay = match &canvas.output {
        Some(o) if o.size != size => layout(
            available,
            view_settings.compare,
            Sizing::Fixed(o.size),
            ppp,
            input.framing,
        ),
        _ => lay,
    };
    canvas.pixel_size = lay.pixel_size(ppp);
    canvas.views = views_of(&lay, state, input.gpu.is_some(), lay.size[0]);
    if let Some(o) = &canvas.output {
        let rasterizer = view_settings.rasterizer;
        let view = view_settings.samples_view;
        canvas.samples.update(o, input.texture, view, rasterizer);
    }
    let (compare, wipe) = (view_settings.compare, view_settings.wipe);
    canvas.upload(
        ui.ctx(),
        (compare, wipe),
        input.gpu,
        view_settings.samples_view,
    );
    if let Some(e) = &canvas.error {
        // In the picture's place: an older picture (or the handles of a scene it cannot
        // draw over it) would not belong to what the controls show.
        canvas_progress::failure_ui(ui, e, lang);
        canvas.handles.clear();
        return out;
    }
    if canvas_progress::underway_ui(ui, available, canvas.underway(), canvas.cancelled, lang) {
        canvas.cancel_render();
    }
    let Some(output) = &canvas.output else {
        return out;
    };
    let viewport = output.viewport();
    let vertices = vertices_on_screen(&state.scene, viewport);
    let marks = [input.pin_report, input.hover_report].map(|r| r.map(PixelReport::mark));
    let shown = if view_settings.show_handles {
        handle_indices(vertices.len(), marks)
    } else {
        Vec::new()
    };
    canvas.handles.clone_from(&shown);
    let painter = ui.painter().clone();
    let base_id = Id::unique("canvas");
    let mut hover = None;
    let mut active_handle = None;

    for (vi, view) in canvas.views.iter().enumerate() {
        if let Some(tex) = canvas.textures.get(vi) {
            painter.image(
                tex.id(),
                view.rect,
                Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)),
                Color32::WHITE,
            );
        }
        let t = view.transform;
        let is_model = matches!(state.scene, Scene::Model(_));
        let sense = if is_model {
            Sense::click_and_drag()
        } else {
            Sense::click()
        };
        let view_resp = ui.interact(view.rect, base_id.with(("view", vi)), sense);
        if is_model {
            model_camera_input(ui, &view_resp, t.scale, viewport, &mut out);
        }
        let pointer_pixel = |p: Pos2| -> Option<[u32; 2]> {
            let c = t.to_canvas(p);
            (c.x >= 0.0 && c.y >= 0.0 && c.x < f64::from(size[0]) && c.y < f64::from(size[1]))
                .then(|| [c.x.floor() as u32, c.y.floor() as u32])
        };
        if ui.rect_contains_pointer(view.rect)
            && let Some(p) = ui.ctx().pointer_hover_pos()
        {
            hover = pointer_pixel(p);
        }
        if view_resp.clicked()
            && let Some(p) = view_resp.interact_pointer_pos().and_then(pointer_pixel)
        {
            let same = view_settings.pinned == Some(p);
            out.push(StateCommand::Pin(if same { None } else { Some(p) }));
        }
        if view_resp.hovered() {
            ui.ctx().set_cursor_icon(CursorIcon::Crosshair);
        }

        // The wipe line.
        if view.content == ViewContent::Wipe {
            let x = view.rect.left() + view_settings.wipe * view.rect.width();
            let grab =
                Rect::from_x_y_ranges((x - WIPE_GRAB)..=(x + WIPE_GRAB), view.rect.y_range());
            let r = ui.interact(grab, base_id.with(("wipe", vi)), Sense::drag());
            if r.hovered() || r.dragged() {
                ui.ctx().set_cursor_icon(CursorIcon::ResizeHorizontal);
            }
            if r.drag_started() {
                canvas.drag = Some(DragKind::Wipe);
            }
            if r.dragged()
                && let Some(p) = r.interact_pointer_pos()
            {
                out.push(StateCommand::SetWipe(
                    (p.x - view.rect.left()) / view.rect.width(),
                ));
            }
            // No tooltip while dragging: it would cover what the drag changes.
            if !r.dragged() {
                r.on_hover_text(lang.tr("app.canvas.wipe_line"));
            }
        }

        // Handles.
        {
            for &k in &shown {
                let Some(win) = vertices.get(k).and_then(|v| v.window) else {
                    continue;
                };
                // Where the handle is drawn: a corner off the image has it on the edge (the
                // drag moves the corner by the pointer's motion, from wherever it is).
                let image = glam::DVec2::new(f64::from(viewport.width), f64::from(viewport.height));
                let centre = t.to_screen(overlay::handle_position(win, image));
                let grab = Rect::from_center_size(
                    centre,
                    egui::Vec2::splat(2.0 * (overlay::HANDLE_RADIUS + HANDLE_GRAB_SLACK)),
                );
                if !view.rect.expand(overlay::HANDLE_RADIUS).intersects(grab) {
                    continue;
                }
                let r = ui.interact(grab, base_id.with(("handle", vi, k)), Sense::drag());
                if r.hovered() || r.dragged() {
                    active_handle = Some(k);
                    ui.ctx().set_cursor_icon(if r.dragged() {
                        CursorIcon::Grabbing
                    } else {
                        CursorIcon::Grab
                    });
                }
                // Grab offset from where the button went down, not from where the drag was
                // recognised (a few points later), so the corner follows the pointer exactly.
                if r.drag_started()
                    && let Some(p) = ui
                        .input(|i| i.pointer.press_origin())
                        .or(r.interact_pointer_pos())
                {
                    canvas.drag = Some(DragKind::Handle {
                        index: k,
                        grab: t.to_canvas(p) - win,
                    });
                }
                if r.dragged()
                    && let Some(DragKind::Handle { index, grab }) = canvas.drag
                    && index == k
                {
                    let shift = ui.input(|i| i.modifiers.shift);
                    if shift {
                        let dy = f64::from(r.drag_delta().y);
                        if dy != 0.0 {
                            out.push(StateCommand::PushVertex {
                                index: k,
                                factor: (-dy * PUSH_PER_POINT).exp(),
                                viewport,
                            });
                        }
                    } else if r.drag_delta() != egui::Vec2::ZERO
                        && let Some(p) = r.interact_pointer_pos()
                    {
                        out.push(StateCommand::MoveVertex {
                            index: k,
                            to: t.to_canvas(p) - grab,
                            viewport,
                        });
                    }
                }
                if r.hovered() {
                    let scroll = ui.input(|i| i.smooth_scroll_delta.y);
                    if scroll != 0.0 {
                        out.push(StateCommand::PushVertex {
                            index: k,
                            factor: (f64::from(scroll) * PUSH_PER_SCROLL_POINT).exp(),
                            viewport,
                        });
                    }
                }
                if !r.dragged() {
                    r.on_hover_text(lang.tr("app.canvas.handle_tip"));
                }
            }
        }
    }
    if !ui.input(|i| i.pointer.any_down()) {
        canvas.drag = None;
    }
    canvas.hover = hover;

    // Overlays.
    let handles: Vec<HandleMark> = shown
        .iter()
        .filter_map(|&k| Some((k, vertices.get(k)?)))
        .map(|(k, v): (usize, &VertexOnScreen)| HandleMark {
            index: k,
            window: v.window,
            w: v.w(),
            active: active_handle == Some(k),
        })
        .collect();
    // The GPU view: Some(whether it has a GPU image).
    let gpu = input.gpu.map(|g| g.result.is_some());
    // Steps taken along the scanline span since the stepping started (S).
    let span_elapsed = if canvas.span_play
        && view_settings.rasterizer == crate::raster::render::Rasterizer::Scanline
        && view_settings.pinned.is_some()
    {
        let now = ui.input(|i| i.time);
        let start = *canvas.span_started.get_or_insert(now);
        ui.ctx()
            .request_repaint_after(std::time::Duration::from_secs_f64(SPAN_STEP_SECONDS));
        Some(((now - start) / SPAN_STEP_SECONDS).max(0.0) as u32)
    } else {
        canvas.span_started = None;
        None
    };
    for (vi, view) in canvas.views.iter().enumerate() {
        let input_overlay = OverlayInput {
            size,
            pixel_size: canvas.pixel_size,
            pixels_per_point: ppp,
            mode: match view.content {
                _ if gpu.is_some() => Some(other_image::badge_mode(gpu, compare, vi, state)),
                ViewContent::Mode(m) => Some(m),
                _ => None,
            },
            show_grid: view_settings.show_grid,
            handles: handles.clone(),
            hover: input.hover_report.map(PixelReport::mark),
            pin: input.pin_report.map(PixelReport::mark),
            clipped: input
                .pin_report
                .or(input.hover_report)
                .and_then(|r| crate::figure::clip_mark(&r.trace)),
            sub_areas: view_settings.show_sub_areas,
            sub_area_fill: state.options().shading != crate::raster::Shading::Texture,
            wipe: (view.content == ViewContent::Wipe && gpu != Some(false)).then_some((
                f64::from(view_settings.wipe) * f64::from(size[0]),
                Interpolation::Affine,
                Interpolation::Perspective,
            )),
            color_bar: match view.content {
                ViewContent::Difference if gpu.is_none() => {
                    output.heatmap.as_ref().map(|h| h.scale_max)
                }
                _ => None,
            },
        };
        // Overlays stay in their view's share of the canvas (the image, its title strip and
        // the margins where handles and their labels go), never over the panels.
        let clip = view.area.intersect(available);
        let mut shapes = overlay::build_in(&input_overlay, lang);
        if let Some(g) = input.gpu.filter(|_| gpu == Some(true)) {
            other_image::relabel(&mut shapes, lang, view_settings.compare, g);
        }
        if input.framing.title_strip == 0.0 {
            paint::drop_titles(&mut shapes);
        } else if let Some(w) = crate::figure::common_w(vertices.iter().map(VertexOnScreen::w))
            && compare == Compare::Single
            && gpu.is_none()
        {
            // Every corner at one w: both modes draw the same picture; the title says so
            // instead of naming one (a lesson's flat steps are about screen space). Where the
            // whole sentence would be shrunk (a quiz column beside the canvas at a projector),
            // a shorter form at full size: "SCREEN SPACE (w = 1.00)", else "SCREEN SPACE".
            let w = format!("{w:.2}");
            let titles = ["figure.flat", "figure.flat_short", "figure.flat_shortest"]
                .map(|key| lang.tr_with(key, &[("w", &w)]));
            paint::retitle(
                &mut shapes,
                paint::first_fitting(ui.painter(), &titles, clip),
            );
        }
        // The sample view's buffer (the GPU view shows the GL's image instead).
        // Where its whole title would be shrunk, a shorter form at full size (the samples
        // lesson's black-edge step beside the enlarged pixel at a projector).
        let buffer_title = gpu
            .is_none()
            .then(|| {
                canvas
                    .samples
                    .titles(view.content, view_settings.samples_view, lang)
            })
            .flatten();
        if let Some(titles) = &buffer_title {
            paint::retitle(
                &mut shapes,
                paint::first_fitting(ui.painter(), titles, clip),
            );
        }
        // A mode's title too wide for its view (side by side at a projector) in its short
        // form: shrunk to fit, it was smaller than its neighbour's and hard to read.
        if let Some(title) = paint::title(&shapes)
            && let Some(short) = overlay::short_mode_label(title, lang)
        {
            let titles = [title.to_string(), short];
            paint::retitle(
                &mut shapes,
                paint::first_fitting(ui.painter(), &titles, clip),
            );
        }
        // With the wireframe on, the triangle's outline would lie right over the wireframe's
        // line (the thing to see): the line shows the triangle already. A sample buffer's
        // thing to see is its edge pixels too (the black-edge bug's dark line, a sample's
        // coverage): the outline would cover them.
        if state.options().wireframe || buffer_title.is_some() {
            shapes.shapes.retain(|s| !overlay::is_triangle_outline(s));
        }
        // The scanline rasterizer: the pinned pixel's row, where it crosses two edges, and the
        // span between (values stepped along the edges, then along the span).
        if view_settings.rasterizer == crate::raster::render::Rasterizer::Scanline
            && let Some(pin) = input.pin_report.map(PixelReport::mark)
            && let Some(t) = pin.triangle
            && let Some(span) = overlay::span_shapes(&t, pin.pixel[1])
        {
            // Over the triangle's outline, under the pixel marker and the handles.
            let at = shapes
                .shapes
                .iter()
                .rposition(|s| matches!(s, overlay::Shape::Polygon { .. }))
                .map_or(0, |i| i + 1);
            shapes.shapes.splice(at..at, span);
            // Stepping: one pixel of the span after another, as the rasterizer visits them;
            // after the last pixel a pause, then from the start again.
            if let Some(elapsed) = span_elapsed
                && let Some((_, count)) = overlay::span_step_shapes(&t, pin.pixel[1], 0)
                && let Some((trail, _)) = overlay::span_step_shapes(
                    &t,
                    pin.pixel[1],
                    elapsed % (count + SPAN_PAUSE_STEPS),
                )
            {
                shapes.shapes.splice(at..at, trail);
            }
        }
        paint::scale_marks(&mut shapes, input.mark_scale);
        let image = Rect::from_min_max(
            view.rect.min - egui::vec2(2.0, overlay::TITLE_STRIP),
            view.rect.max + egui::vec2(2.0, 2.0),
        );
        // Labels keep clear of the pinned pixel's marker too (the pixel the lesson talks
        // about).
        let mut avoid = canvas.avoid.clone();
        if let Some([px, py]) = view_settings.pinned {
            let at = view
                .transform
                .to_screen(DVec2::new(f64::from(px) + 0.5, f64::from(py) + 0.5));
            avoid.push(Rect::from_center_size(at, egui::Vec2::splat(PIN_CLEARANCE)));
        }
        paint::paint(&painter, clip, image, view.transform, &shapes, &avoid);
    }
    out
}

/// Model scenes: drag orbits the camera about its target, Shift+drag or a right/middle drag
/// pans, scrolling zooms. `scale` is points per rendered pixel.
fn model_camera_input(
    ui: &Ui,
    resp: &egui::Response,
    scale: f32,
    viewport: Viewport,
    out: &mut Vec<StateCommand>,
) {
    use egui::PointerButton as B;
    let d = resp.drag_delta();
    if d != egui::Vec2::ZERO {
        let shift = ui.input(|i| i.modifiers.shift);
        let pan = resp.dragged_by(B::Secondary)
            || resp.dragged_by(B::Middle)
            || (shift && resp.dragged_by(B::Primary));
        if pan {
            let per_point = 1.0 / f64::from(scale.max(f32::MIN_POSITIVE));
            out.push(StateCommand::PanCamera {
                dx: f64::from(d.x) * per_point,
                dy: f64::from(d.y) * per_point,
                viewport,
            });
        } else if resp.dragged_by(B::Primary) {
            // Grab-and-turn: dragging right turns the model's front to the right.
            out.push(StateCommand::OrbitCamera {
                yaw_deg: -f64::from(d.x) * ORBIT_DEG_PER_POINT,
                pitch_deg: f64::from(d.y) * ORBIT_DEG_PER_POINT,
            });
        }
    }
    if resp.dragged() {
        ui.ctx().set_cursor_icon(CursorIcon::Grabbing);
    }
    if resp.hovered() {
        let scroll = ui.input(|i| i.smooth_scroll_delta.y);
        if scroll != 0.0 {
            out.push(StateCommand::ZoomCamera(
                (-f64::from(scroll) * ZOOM_PER_SCROLL_POINT).exp(),
            ));
        }
    }
}
