//! barylab: a conformant CPU rasterizer that shows how a GPU interpolates across a triangle.
//!
//! - [`raster`]: the pipeline stages (no GUI).
//! - [`scene`]: scene files (world form and raw clip-space form).
//! - [`probe`]: every number behind one pixel, and its derivation as text.
//! - [`aov`]: float32 OpenEXR export of the per-pixel buffers.
//! - [`app`]: the classroom app (egui); the modules above never use egui.

pub mod aov;
pub mod app;
pub mod model;
pub mod probe;
pub mod raster;
pub mod scene;
