//! What the app saves between runs, in eframe's storage under [`STORAGE_KEY`], and how it comes
//! back: the scene, the view settings, the recent files, the Export panel's settings and the
//! language.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::app::document::export_settings::ExportSettings;
use crate::app::document::state::{AppState, PIXEL_SIZE_RANGE, UI_SCALE_RANGE, ViewSettings};
use crate::i18n::Lang;
use crate::scene::Scene;

/// Recent files shown in the menu.
pub const MAX_RECENT: usize = 10;

/// The recently opened files, newest first, saved between runs.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct RecentFiles(pub Vec<PathBuf>);

impl RecentFiles {
    /// Puts `path` first (once), keeping at most [`MAX_RECENT`].
    pub fn push(&mut self, path: &Path) {
        self.0.retain(|p| p != path);
        self.0.insert(0, path.to_path_buf());
        self.0.truncate(MAX_RECENT);
    }
}

/// Key under which eframe stores [`SavedState`].
pub const STORAGE_KEY: &str = "barylab_state";

/// Everything saved between runs. Every field has a default, so older or partial saved states
/// still load.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SavedState {
    /// The scene as JSON (parsed with [`Scene::from_json`] on restore).
    pub scene_json: String,
    /// Folder relative texture paths of the scene are resolved against.
    pub scene_dir: Option<PathBuf>,
    /// The view settings.
    pub view: ViewSettings,
    /// Recently opened files, newest first.
    pub recent: RecentFiles,
    /// The Export panel's folder, scale, background and file choice.
    pub export: ExportSettings,
    /// The language chosen (none saved yet: the system locale's).
    pub lang: Option<Lang>,
}

/// A saved state, restored.
#[derive(Clone, Debug, PartialEq)]
pub struct Restored {
    /// The document: the scene (or the default one) and the view settings.
    pub state: AppState,
    /// Recently opened files, newest first.
    pub recent: RecentFiles,
    /// The Export panel's settings.
    pub export: ExportSettings,
    /// The language saved, if any.
    pub lang: Option<Lang>,
    /// Why the saved scene could not be used (the default scene is used instead).
    pub error: Option<String>,
}

impl SavedState {
    /// What is saved of the app now.
    pub fn capture(
        state: &AppState,
        recent: &RecentFiles,
        export: &ExportSettings,
        lang: Lang,
    ) -> Self {
        Self {
            scene_json: state.scene.to_json(),
            scene_dir: state.scene_dir.clone(),
            view: state.view.clone(),
            recent: recent.clone(),
            export: export.clone(),
            lang: Some(lang),
        }
    }

    /// Restores a saved state: settings out of range get their defaults, and a scene that no
    /// longer parses is replaced by the default scene (the error is returned beside it).
    pub fn restore(self) -> Restored {
        let mut state = AppState {
            view: self.view,
            ..AppState::default()
        };
        state.view.pixel_size = state
            .view
            .pixel_size
            .clamp(PIXEL_SIZE_RANGE.0, PIXEL_SIZE_RANGE.1);
        if !(state.view.ui_scale >= UI_SCALE_RANGE.0 && state.view.ui_scale <= UI_SCALE_RANGE.1) {
            state.view.ui_scale = ViewSettings::default().ui_scale;
        }
        let mut error = None;
        if !self.scene_json.is_empty() {
            // Model scenes name their OBJ relative to the scene file's folder.
            let name = self.scene_dir.as_ref().map_or_else(
                || "saved scene".to_string(),
                |d| d.join("saved scene").display().to_string(),
            );
            match Scene::from_json(&self.scene_json, &name) {
                Ok(scene) => {
                    state.scene = scene;
                    state.scene_dir = self.scene_dir;
                }
                Err(e) => error = Some(e.to_string()),
            }
        }
        Restored {
            state,
            recent: self.recent,
            export: self.export,
            lang: self.lang,
            error,
        }
    }
}

/// The file the app keeps its saved state in: `barylab-state.json` in eframe's storage folder
/// for the app (`~/.local/share/barylab` on Linux). eframe's own storage file is rewritten in
/// place, so a full disk or a crash while saving could lose it; this one is written to a
/// temporary file and renamed ([`write_state_file`]), so the last good state always survives.
pub fn state_file() -> Option<PathBuf> {
    eframe::storage_dir("barylab").map(|d| d.join("barylab-state.json"))
}

/// The saved state in `path`, if it is there and reads as one.
pub fn read_state_file(path: &std::path::Path) -> Option<SavedState> {
    let bytes = crate::files::read_regular(path, crate::files::FileKind::Scene).ok()?;
    serde_json::from_slice(&bytes).ok()
}

/// Writes the saved state to `path` atomically (temporary file in the same folder, then
/// rename), creating the folder if needed.
pub fn write_state_file(path: &std::path::Path, saved: &SavedState) -> Result<(), String> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    }
    let json = serde_json::to_vec_pretty(saved).map_err(|e| e.to_string())?;
    crate::files::write_bytes(path, &json).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::document::presets::Preset;
    use crate::app::document::state::StateCommand;
    use crate::raster::Interpolation;

    #[test]
    fn saved_state_round_trips_and_bad_scenes_fall_back_to_the_default() {
        let mut s = AppState::default();
        s.apply(StateCommand::Preset(Preset::GrazingWall))
            .expect("preset");
        s.apply(StateCommand::SetMode(Interpolation::Affine))
            .expect("mode");
        s.apply(StateCommand::SetPixelSize(8)).expect("size");
        let mut recent = RecentFiles::default();
        recent.push(std::path::Path::new("/tmp/a.json"));
        let export = ExportSettings {
            scale: 4,
            ..ExportSettings::default()
        };
        let saved = SavedState::capture(&s, &recent, &export, Lang::Zh);
        let json = serde_json::to_string(&saved).expect("json");
        let back: SavedState = serde_json::from_str(&json).expect("parse");
        let restored = back.restore();
        assert_eq!(restored.error, None);
        assert_eq!(restored.state, s);
        assert_eq!((restored.recent, restored.export), (recent, export));
        assert_eq!(restored.lang, Some(Lang::Zh));

        let broken = SavedState {
            scene_json: "{\"quad\": 3}".into(),
            ..SavedState::default()
        };
        let restored = broken.restore();
        assert!(restored.error.expect("error").starts_with("saved scene:"));
        assert_eq!(restored.state.scene, Scene::default_scene());
        // Old or partial saved states still load (serde default).
        let partial: SavedState =
            serde_json::from_str("{\"view\": {\"pixel_size\": 4}}").expect("partial state");
        assert_eq!(partial.view.pixel_size, 4);
        assert!(partial.view.show_handles);
    }
}
