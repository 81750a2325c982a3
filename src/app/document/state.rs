//! The app's document: the scene and the view settings, and the [`StateCommand`]s that change them.
//! Panels read the state and return commands; the app applies them once per frame
//! ([`AppState::apply`]). What of it is saved between runs: [`crate::app::document::persist`].

use std::path::PathBuf;

use glam::{DVec2, DVec4, Vec2, Vec3};
use serde::{Deserialize, Serialize};

use crate::app::document::presets::Preset;
use crate::edit::{self, EditError, SceneOptions};
use crate::raster::camera::{Camera, ModelView};
use crate::raster::project::Viewport;
use crate::raster::{Filter, Interpolation, Shading};
use crate::scene::{Scene, Tilt};

use crate::figure::Compare;

/// Smallest and largest pixel size (display pixels per rendered pixel).
pub const PIXEL_SIZE_RANGE: (u32, u32) = (1, 32);
/// Range of the UI zoom factor.
pub const UI_SCALE_RANGE: (f32, f32) = (0.75, 2.5);

/// View settings saved between runs (the scene is saved beside them).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ViewSettings {
    /// Screen pixels per rendered pixel when the image follows the window ([`PIXEL_SIZE_RANGE`]).
    pub pixel_size: u32,
    /// One view, side by side, wipe or difference.
    pub compare: Compare,
    /// Wipe line position as a fraction of the canvas width.
    pub wipe: f32,
    /// Draw the pixel grid over a magnified image.
    pub show_grid: bool,
    /// Draw the vertex handles (and let them be dragged).
    pub show_handles: bool,
    /// Draw the hovered or pinned pixel's sub-triangles (its barycentric areas).
    pub show_sub_areas: bool,
    /// In presentation mode, show the pinned pixel and its neighbours enlarged.
    pub show_magnifier: bool,
    /// In presentation mode, show the card of the pixel's numbers (off: the picture alone, as
    /// large as the window allows).
    pub show_card: bool,
    /// Show the Controls side panel.
    pub show_controls: bool,
    /// Show the Inspector side panel.
    pub show_inspector: bool,
    /// The pinned pixel (image pixels, x right, y down), whose derivation the inspector keeps.
    pub pinned: Option<[u32; 2]>,
    /// UI zoom factor (text and widgets), for projectors.
    pub ui_scale: f32,
    /// Which rasterizer draws the canvas (both give the same coverage; the inspector follows
    /// the edge-function derivation).
    pub rasterizer: crate::raster::render::Rasterizer,
    /// The rendered image follows the window (`pixel_size` screen pixels per rendered pixel)
    /// instead of keeping the scene's own size. Off by default: a fixed size keeps every
    /// pixel, and so a pin, where it is through any layout change.
    pub fit_window: bool,
    /// The plot of the pinned pixel's row shown (a lesson step's, or the user's choice).
    pub plot: Option<crate::lesson::LessonPlot>,
    /// The GPU view: the comparison shows barylab beside this computer's OpenGL
    /// ([`crate::app::panels::gpu_view`]) instead of affine beside perspective-correct.
    pub gpu: bool,
    /// The 3D view beside the canvas (the space view, `figure::space`).
    pub space: bool,
    /// The per-sample buffers view of a multisampled scene (coverage count, a sample's
    /// colour or depth; the black-edge bug), [`crate::figure::sample_buffers`].
    pub samples_view: crate::figure::sample_buffers::SampleView,
    /// The texture-space or level-of-detail view beside the canvas
    /// (the app's `panels::texel_view`).
    pub texel: crate::figure::TexelView,
}

impl Default for ViewSettings {
    fn default() -> Self {
        Self {
            pixel_size: 1,
            compare: Compare::Single,
            wipe: 0.5,
            show_grid: true,
            show_handles: true,
            show_sub_areas: false,
            show_magnifier: true,
            show_card: true,
            show_controls: true,
            show_inspector: true,
            pinned: None,
            ui_scale: 1.0,
            rasterizer: Default::default(),
            fit_window: false,
            plot: None,
            gpu: false,
            space: false,
            samples_view: Default::default(),
            texel: crate::figure::TexelView::Off,
        }
    }
}

/// The live document: the scene and the view.
#[derive(Clone, Debug, PartialEq)]
pub struct AppState {
    /// The scene shown and edited.
    pub scene: Scene,
    /// The folder the scene's relative texture paths are resolved against.
    pub scene_dir: Option<PathBuf>,
    /// The view settings.
    pub view: ViewSettings,
}

impl Default for AppState {
    fn default() -> Self {
        Self {
            scene: Scene::default_scene(),
            scene_dir: None,
            view: ViewSettings::default(),
        }
    }
}

impl AppState {
    /// The scene's render options (mode, shading, filter, wireframe).
    pub fn options(&self) -> SceneOptions {
        edit::options(&self.scene)
    }
}

/// A small change to the state, pushed by a panel and applied once per frame.
#[derive(Clone, Debug, PartialEq)]
pub enum StateCommand {
    /// Replace the scene (a file was opened); keeps the view.
    OpenScene(Box<Scene>, Option<PathBuf>),
    /// An image became the texture (an absolute path or a built-in name); shading switches to
    /// the texture where the mesh has uvs.
    SetTexture(String),
    /// Model scenes: turn the camera about its target (drag), in degrees.
    OrbitCamera {
        /// Turn about the vertical axis, in degrees.
        yaw_deg: f64,
        /// Turn up or down, in degrees.
        pitch_deg: f64,
    },
    /// Model scenes: move camera and target parallel to the screen by this many rendered
    /// pixels (right, down), so the model follows the pointer.
    PanCamera {
        /// Rendered pixels to the right.
        dx: f64,
        /// Rendered pixels down.
        dy: f64,
        /// The rendered image's size the pixels are counted in.
        viewport: Viewport,
    },
    /// Model scenes: multiply the distance to the target (scroll).
    ZoomCamera(f64),
    /// Model scenes: back to the camera that frames the model.
    ResetCamera,
    /// Frame a model from one side ([`ModelView`]); Home ([`StateCommand::ResetCamera`]) goes back
    /// to the course's view.
    ModelView(ModelView),
    /// Load a preset's geometry and camera, keeping the render options and texture.
    Preset(Preset),
    /// Back to the built-in default scene (view settings kept).
    ResetScene,
    /// Back to the default scene and the default view settings.
    ResetAll,
    /// Interpolate affinely or perspective-correctly.
    SetMode(Interpolation),
    /// Switch between affine and perspective-correct interpolation.
    ToggleMode,
    /// Shade by this (colour, texture, ...).
    SetShading(Shading),
    /// Sample the texture with this filter.
    SetFilter(Filter),
    /// Draw the triangle edges over the image, or not.
    SetWireframe(bool),
    /// Draw the canvas with this rasterizer.
    SetRasterizer(crate::raster::render::Rasterizer),
    /// Show one view, side by side, the wipe or the difference (the pin is kept).
    SetCompare(Compare),
    /// The GPU view on or off.
    SetGpuView(bool),
    /// The 3D view beside the canvas on or off.
    SetSpaceView(bool),
    /// The per-sample buffers view: which buffer, sample index, black-edge bug.
    SetSamplesView(crate::figure::sample_buffers::SampleView),
    /// Which texture view shows beside the canvas (texture space, level of detail, none).
    SetTexelView(crate::figure::TexelView),
    /// Which triangle owns a pixel centre exactly on a shared edge (saved in the scene).
    SetTieRule(crate::raster::setup::TieRule),
    /// Samples per pixel, their pattern, the shading rate and the location (saved in the scene).
    SetSamples(crate::raster::sample::SampleSettings),
    /// Put the wipe line at this fraction of the width (clamped to 0..1).
    SetWipe(f32),
    /// Screen pixels per rendered pixel when following the window (clamped; unpins if it changes).
    SetPixelSize(u32),
    /// Render at this fixed size (the scene's size, so exports carry it), or `None`: follow
    /// the window.
    SetImageSize(Option<[u32; 2]>),
    /// Draw the pixel grid, or not.
    SetShowGrid(bool),
    /// Draw the vertex handles, or not.
    SetShowHandles(bool),
    /// Draw the sub-triangles of the hovered or pinned pixel, or not.
    SetShowSubAreas(bool),
    /// Show the magnifier in presentation mode, or not.
    SetShowMagnifier(bool),
    /// Show the card in presentation mode, or not.
    SetShowCard(bool),
    /// Show the Controls panel, or not.
    SetShowControls(bool),
    /// Show the Inspector panel, or not.
    SetShowInspector(bool),
    /// Set the UI zoom factor (clamped to [`UI_SCALE_RANGE`]).
    SetUiScale(f32),
    /// Drag: move a vertex so it lands on this window position, at its depth.
    MoveVertex {
        /// The vertex's index in the scene.
        index: usize,
        /// Where it goes, in window pixels of the rendered image (y down).
        to: DVec2,
        /// The rendered image's size.
        viewport: Viewport,
    },
    /// Scroll / Shift+drag: multiply a vertex's w, keeping its place on screen.
    PushVertex {
        /// The vertex's index in the scene.
        index: usize,
        /// Multiplies w (clamped to [`edit::PUSH_FACTOR_RANGE`]).
        factor: f64,
        /// The rendered image's size.
        viewport: Viewport,
    },
    /// Numeric edit of a world-form corner (object-space position, uv).
    SetCorner {
        /// The corner's index.
        index: usize,
        /// Object-space position.
        position: glam::DVec3,
        /// Texture coordinates.
        uv: Vec2,
        /// Vertex colour, RGB in [0, 1].
        color: Vec3,
    },
    /// Numeric edit of a clip-form vertex.
    SetClipVertex {
        /// The vertex's index.
        index: usize,
        /// Clip-space position (x, y, z, w).
        clip: DVec4,
        /// Texture coordinates.
        uv: Vec2,
    },
    /// World scenes: tilt the quad about its centre (ignored unless finite).
    SetTilt(Tilt),
    /// Set the perspective camera's vertical field of view, in degrees (clamped).
    SetFov(f64),
    /// Pin a pixel (or unpin).
    Pin(Option<[u32; 2]>),
    /// Show a plot of the pinned pixel's row, or none.
    SetPlot(Option<crate::lesson::LessonPlot>),
    /// Move the pin by whole pixels, staying inside the image.
    MovePin {
        /// Pixels to the right (negative: left).
        dx: i32,
        /// Pixels down (negative: up).
        dy: i32,
        /// The image's size, in pixels, that the pin stays inside.
        size: [u32; 2],
    },
}

impl AppState {
    /// Applies one command. Returns a message for the status line when it could not be done.
    pub fn apply(&mut self, command: StateCommand) -> Result<(), EditError> {
        let mut options = self.options();
        match command {
            StateCommand::OpenScene(scene, dir) => {
                self.scene = *scene;
                self.scene_dir = dir;
                self.view.pinned = None;
            }
            StateCommand::SetTexture(name) => edit::set_texture(&mut self.scene, name),
            StateCommand::OrbitCamera { yaw_deg, pitch_deg } => {
                edit::orbit_camera(&mut self.scene, yaw_deg, pitch_deg)
            }
            StateCommand::PanCamera { dx, dy, viewport } => {
                edit::pan_camera(&mut self.scene, DVec2::new(dx, dy), viewport)
            }
            StateCommand::ZoomCamera(factor) => edit::zoom_camera(&mut self.scene, factor),
            StateCommand::ResetCamera => {
                if let Scene::Model(s) = &mut self.scene {
                    s.camera = None;
                }
            }
            StateCommand::ModelView(view) => {
                if let Scene::Model(s) = &mut self.scene {
                    let (centre, radius) = s.mesh.bounding_sphere();
                    s.camera = Some(Camera::framing_from(centre, radius, view));
                }
            }
            StateCommand::Preset(p) => {
                let texture = self.scene.texture_name().to_string();
                let (w, h) = self.scene.size();
                let mut scene = p.scene();
                edit::set_options(&mut scene, options);
                // The image size is the teacher's choice, not the preset's.
                scene.set_size(w, h);
                if let Scene::World(s) = &mut scene {
                    s.texture = texture;
                } else {
                    self.scene_dir = None;
                }
                // The pin stays (the image size is kept): stepping through the presets shows
                // the same pixel in each situation.
                self.scene = scene;
            }
            StateCommand::ResetScene => {
                let (w, h) = self.scene.size();
                self.scene = Scene::default_scene();
                self.scene.set_size(w, h);
                self.scene_dir = None;
                self.view.pinned = None;
            }
            StateCommand::ResetAll => *self = AppState::default(),
            StateCommand::SetMode(m) => {
                options.mode = m;
                edit::set_options(&mut self.scene, options);
            }
            StateCommand::ToggleMode => {
                options.mode = match options.mode {
                    Interpolation::Affine => Interpolation::Perspective,
                    Interpolation::Perspective => Interpolation::Affine,
                };
                edit::set_options(&mut self.scene, options);
            }
            StateCommand::SetShading(s) => {
                options.shading = s;
                edit::set_options(&mut self.scene, options);
            }
            StateCommand::SetFilter(f) => {
                options.filter = f;
                edit::set_options(&mut self.scene, options);
            }
            StateCommand::SetWireframe(w) => {
                options.wireframe = w;
                edit::set_options(&mut self.scene, options);
            }
            StateCommand::SetRasterizer(r) => self.view.rasterizer = r,
            StateCommand::SetCompare(c) => {
                // The wipe line starts on the quad, not at the middle of the image.
                if c == Compare::Wipe
                    && self.view.compare != Compare::Wipe
                    && let Some(x) = quad_centre(&self.scene)
                {
                    self.view.wipe = x;
                }
                self.view.compare = c;
            }
            StateCommand::SetGpuView(on) => self.view.gpu = on,
            StateCommand::SetSpaceView(on) => self.view.space = on,
            StateCommand::SetSamplesView(v) => self.view.samples_view = v,
            StateCommand::SetTexelView(t) => self.view.texel = t,
            StateCommand::SetTieRule(rule) => self.scene.set_tie_rule(rule),
            StateCommand::SetSamples(samples) => self.scene.set_samples(samples),
            StateCommand::SetWipe(x) => self.view.wipe = x.clamp(0.0, 1.0),
            StateCommand::SetPixelSize(p) => {
                let p = p.clamp(PIXEL_SIZE_RANGE.0, PIXEL_SIZE_RANGE.1);
                if p != self.view.pixel_size {
                    self.view.pixel_size = p;
                    // The pixel grid changes, so a pinned pixel would point elsewhere.
                    self.view.pinned = None;
                }
            }
            StateCommand::SetImageSize(None) => self.view.fit_window = true,
            StateCommand::SetImageSize(Some([w, h])) => {
                let max = crate::raster::project::MAX_IMAGE_SIZE;
                let (w, h) = (w.clamp(1, max), h.clamp(1, max));
                if self.view.fit_window || self.scene.size() != (w, h) {
                    // Another image: a pinned pixel would point at another surface point.
                    self.view.pinned = None;
                }
                self.scene.set_size(w, h);
                self.view.fit_window = false;
            }
            StateCommand::SetShowGrid(b) => self.view.show_grid = b,
            StateCommand::SetShowHandles(b) => self.view.show_handles = b,
            StateCommand::SetShowSubAreas(b) => self.view.show_sub_areas = b,
            StateCommand::SetShowMagnifier(b) => self.view.show_magnifier = b,
            StateCommand::SetShowCard(b) => self.view.show_card = b,
            StateCommand::SetShowControls(b) => self.view.show_controls = b,
            StateCommand::SetShowInspector(b) => self.view.show_inspector = b,
            StateCommand::SetUiScale(s) => {
                self.view.ui_scale = s.clamp(UI_SCALE_RANGE.0, UI_SCALE_RANGE.1)
            }
            StateCommand::MoveVertex {
                index,
                to,
                viewport,
            } => edit::move_vertex_to(&mut self.scene, index, to, viewport)?,
            StateCommand::PushVertex {
                index,
                factor,
                viewport,
            } => edit::push_vertex(&mut self.scene, index, factor, viewport)?,
            StateCommand::SetCorner {
                index,
                position,
                uv,
                color,
            } => {
                if let Scene::World(s) = &mut self.scene {
                    if !(position.is_finite() && uv.is_finite()) {
                        return Err(EditError::NotFinite);
                    }
                    let c = s.quad.get_mut(index).ok_or(EditError::NoVertex(index))?;
                    (c.position, c.uv, c.color) = (position, uv, color);
                }
            }
            StateCommand::SetClipVertex { index, clip, uv } => {
                if let Scene::Clip(s) = &mut self.scene {
                    if !(clip.is_finite() && uv.is_finite()) {
                        return Err(EditError::NotFinite);
                    }
                    let v = s
                        .vertices
                        .get_mut(index)
                        .ok_or(EditError::NoVertex(index))?;
                    (v.clip, v.uv) = (clip, uv);
                }
            }
            StateCommand::SetTilt(t) => {
                if let Scene::World(s) = &mut self.scene
                    && t.pitch_deg.is_finite()
                    && t.yaw_deg.is_finite()
                {
                    s.tilt = t;
                }
            }
            StateCommand::SetFov(f) => edit::set_fov_deg(&mut self.scene, f),
            StateCommand::Pin(p) => self.view.pinned = p,
            StateCommand::SetPlot(p) => self.view.plot = p,
            StateCommand::MovePin { dx, dy, size } => {
                if let Some([x, y]) = self.view.pinned {
                    let nx = (i64::from(x) + i64::from(dx)).clamp(0, i64::from(size[0]) - 1);
                    let ny = (i64::from(y) + i64::from(dy)).clamp(0, i64::from(size[1]) - 1);
                    self.view.pinned = Some([nx as u32, ny as u32]);
                }
            }
        }
        Ok(())
    }
}

/// The horizontal middle of the scene's vertices on screen (those in front of the camera),
/// as a fraction of the image width, kept off the very edges.
fn quad_centre(scene: &Scene) -> Option<f32> {
    let (w, h) = scene.size();
    let viewport = Viewport {
        width: w,
        height: h,
    };
    let xs: Vec<f64> = crate::figure::vertices_on_screen(scene, viewport)
        .iter()
        .filter_map(|v| v.window.map(|p| p.x))
        .collect();
    if xs.is_empty() || w == 0 {
        return None;
    }
    let (lo, hi) = xs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
            (lo.min(x), hi.max(x))
        });
    let x = ((lo + hi) / 2.0 / f64::from(w)).clamp(WIPE_EDGE, 1.0 - WIPE_EDGE);
    x.is_finite().then_some(x as f32)
}

/// The wipe line starts at least this fraction of the width from either edge.
const WIPE_EDGE: f64 = 0.1;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn toggling_the_mode_and_moving_the_pin() {
        let mut s = AppState::default();
        assert_eq!(s.options().mode, Interpolation::Perspective);
        s.apply(StateCommand::ToggleMode).expect("toggle");
        assert_eq!(s.options().mode, Interpolation::Affine);
        s.apply(StateCommand::Pin(Some([0, 5]))).expect("pin");
        s.apply(StateCommand::MovePin {
            dx: -1,
            dy: 1,
            size: [10, 10],
        })
        .expect("move");
        assert_eq!(s.view.pinned, Some([0, 6]));
    }

    #[test]
    fn the_wipe_line_starts_on_the_quad() {
        let mut s = AppState::default();
        // The floor moved to the right.
        if let Scene::World(w) = &mut s.scene {
            for c in &mut w.quad {
                c.position.x += 1.0;
            }
        }
        let x = quad_centre(&s.scene).expect("corners on screen");
        s.apply(StateCommand::SetCompare(Compare::Wipe))
            .expect("wipe");
        assert_eq!(s.view.wipe, x);
        assert!(x > 0.6, "{x}");
    }
}
