//! The Export panel's settings, saved between runs with the rest of the document.

use std::path::PathBuf;

use serde::{Deserialize, Serialize};

use crate::figure::Background;
use crate::figure::export::ExportSelection;

/// Export settings saved between runs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ExportSettings {
    /// The folder of the last export.
    pub folder: Option<PathBuf>,
    /// 1, 2 or 4.
    pub scale: u32,
    /// The figure's background.
    pub background: Background,
    /// Which files an export writes.
    pub selection: ExportSelection,
    /// A caption with the marked pixel's key numbers below the figure.
    pub caption: bool,
}

impl Default for ExportSettings {
    fn default() -> Self {
        Self {
            folder: None,
            scale: 2,
            background: Background::White,
            selection: ExportSelection::default(),
            caption: false,
        }
    }
}
