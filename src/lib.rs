//! barylab: a conformant CPU rasterizer that shows how a GPU interpolates across a triangle.
//!
//! - [`raster`]: the pipeline stages (no GUI).
//! - [`scene`]: scene files (world, raw clip-space and OBJ model forms).
//! - [`model`]: OBJ models.
//! - [`probe`]: every number behind one pixel, and its derivation as text.
//! - [`bench`](mod@bench): timing the rasterizers (`barylab bench`, the app's benchmark panel).
//! - [`compare`]: another rasterizer's image (a student's, a screenshot) against barylab's,
//!   pixel by pixel, with a reason for each difference.
//! - [`aov`]: float32 OpenEXR export of the per-pixel buffers.
//! - [`figure`]: annotated figures (PNG, SVG) of what the canvas shows, for lecture notes.
//! - [`files`]: reading only regular files with size caps, atomic writes, paths in messages.
//! - [`budget`]: the memory budget checked before large allocations.
//! - `gpu` (feature `gpu`, on by default): the same scene drawn by OpenGL through headless EGL,
//!   compared with barylab's pixels (`barylab gpu-check`).
//! - [`app`]: the classroom app (egui); the modules above never use egui.

pub mod aov;
pub mod app;
pub mod bench;
pub mod budget;
pub mod compare;
pub mod figure;
pub mod files;
#[cfg(feature = "gpu")]
pub mod gpu;
pub mod model;
pub mod probe;
pub mod raster;
pub mod scene;
