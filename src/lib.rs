//! barylab: a conformant CPU rasterizer that shows how a GPU interpolates across a triangle.
//!
//! - [`raster`]: the pipeline stages (no GUI).
//! - [`scene`]: scene files (world, raw clip-space and OBJ model forms).
//! - [`model`]: OBJ models.
//! - [`probe`](mod@probe): every number behind one pixel, and its derivation as text.
//! - [`bench`](mod@bench): timing the rasterizers (`barylab bench`, the app's benchmark panel).
//! - [`compare`]: another rasterizer's image (a student's, a screenshot) against barylab's,
//!   pixel by pixel, with a reason for each difference.
//! - [`animate`]: moving figures (GIF, APNG, WebP, MP4) of a sweep, a drag or the
//!   rasterizer's visiting order, every frame a figure.
//! - [`aov`]: float32 OpenEXR export of the per-pixel buffers.
//! - [`figure`]: annotated figures (PNG, SVG) of what the canvas shows, for lecture notes.
//! - [`lesson`]: lessons, a guided walk through the maths in steps that set the scene and the
//!   view, with figures and a printable handout.
//! - [`files`]: reading only regular files with size caps, atomic writes, paths in messages.
//! - [`budget`]: the memory budget checked before large allocations.
//! - `gpu` (feature `gpu`, on by default): the same scene drawn by OpenGL through headless EGL,
//!   compared with barylab's pixels (`barylab gpu-check`).
//! - [`i18n`]: languages (English, Simplified Chinese), the string catalogues in `locales/`,
//!   and finding a CJK font.
//! - [`app`]: the classroom app (egui); the modules above never use egui.
//!
//! # Start here
//!
//! The names most callers need are re-exported at the top: a [`Scene`] becomes a clip-space
//! [`ClipMesh`], [`render`](fn@render) draws it into a [`Framebuffer`], and
//! [`probe`](fn@probe) traces one pixel through the same stages, so its numbers are the ones
//! that made the pixel.
//!
//! ```
//! use std::path::Path;
//! use barylab::{Interpolation, Scene, probe, render};
//!
//! let scene = Scene::default_scene();
//! let texture = scene.load_texture(Path::new(".")).expect("built-in texture");
//! let mut settings = scene.settings();
//! settings.mode = Interpolation::Perspective;
//! let image = render(&scene.to_mesh(), &texture, &settings).expect("render");
//! let (w, h) = scene.size();
//! assert_eq!((image.frame.width, image.frame.height), (w, h));
//!
//! // The probe's colour is the rendered pixel's colour.
//! let (x, y) = (w / 2, h / 2);
//! let trace = probe(&scene, &texture, &settings, (x, y)).expect("probe");
//! assert_eq!(trace.color, image.frame.color[(y * w + x) as usize]);
//! ```

#![warn(missing_docs)]

pub mod animate;
pub mod aov;
pub mod app;
pub mod bench;
pub mod budget;
pub mod compare;
pub mod edit;
pub mod figure;
pub mod files;
#[cfg(feature = "gpu")]
pub mod gpu;
pub mod grade;
/// Without the `gpu` feature: only the GPU view's comparison of two images (no OpenGL), which
/// the app's GPU view needs to compile (it then says the feature is missing).
#[cfg(not(feature = "gpu"))]
pub mod gpu {
    #[path = "view.rs"]
    pub mod view;
}
pub mod i18n;
pub mod lesson;
pub mod model;
pub mod probe;
pub mod progress;
pub mod raster;
pub mod scene;

pub use figure::{Compare, Figure, FigureOptions};
pub use i18n::Lang;
pub use probe::{PixelTrace, ProbeError, Prober, probe};
pub use raster::{
    Buffers, ClipMesh, Filter, Framebuffer, Interpolation, MeshVertex, RenderSettings, Shading,
    Texture, Wrap, render, render_into,
};
pub use scene::{Scene, SceneError, open_input};

// The string catalogues `locales/*.yml`, compiled in (see `i18n`).
rust_i18n::i18n!("locales", fallback = "en");
