//! The document: the scene and view settings, their edits, undo history, presets and what is saved between runs (no egui).

pub mod export_settings;
pub(crate) mod history;
pub mod persist;
pub mod presets;
pub mod state;
