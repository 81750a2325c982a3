//! Behind the panels: renders and their cache, textures, pixel reports, files, dialogs, screenshots, text sizes and the language.

pub(crate) mod dialog;
pub mod files;
pub(crate) mod locale;
pub(crate) mod pixel;
pub mod recorder;
pub(crate) mod render;
pub(crate) mod reports;
pub(crate) mod sample_images;
pub(crate) mod screenshot;
pub(crate) mod style;
pub(crate) mod textures;
