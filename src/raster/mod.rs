//! The rasterizer core, one module per pipeline stage, data flowing one way:
//! `camera` -> `clip` -> `project` -> `setup` -> `interpolate` -> `shade` (with `texture`) ->
//! `framebuffer`, driven by `render`. Nothing here depends on the GUI.

mod bands;
pub mod camera;
pub mod clip;
mod draw;
pub(crate) mod fast;
mod fill;
pub mod footprint;
pub mod framebuffer;
pub mod interpolate;
pub mod lanes;
pub mod mesh;
mod msaa_band;
pub mod multisample;
mod prepare;
pub mod project;
pub mod render;
pub mod sample;
pub mod scanline;
pub mod settings;
pub mod setup;
pub mod shade;
pub mod texture;
pub mod varying;

pub use framebuffer::{Buffers, Framebuffer, NO_TRIANGLE};
pub use interpolate::Interpolation;
pub use mesh::{ClipMesh, MeshVertex};
pub use render::{render, render_into, render_into_at, render_row};
pub use settings::RenderSettings;
pub use shade::Shading;
pub use texture::{BuiltinTexture, Filter, Texture, Wrap};
