//! Opening files in the app: a scene (.json), a model (.obj) or an image (it becomes the
//! texture), from the File menu (`crate::app::panels::file_menu`), drag-and-drop, the recent list or the
//! command line; the banner (`crate::app::panels::banner`) reports what happened.
//!
//! Every way of opening goes through [`open`], which loads and checks everything (scene, model,
//! texture) before anything changes; the app then applies the result with one command. So a bad
//! file leaves the current scene exactly as it was.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::app::document::state::StateCommand;
use crate::i18n::Lang;
use crate::raster::Texture;
use crate::scene::{InputKind, Scene, open_input};

/// What opening a file changes.
#[derive(Clone, Debug)]
pub enum Opened {
    /// A scene file or a model: replaces the scene.
    Scene {
        /// The scene loaded.
        scene: Box<Scene>,
        /// The folder its relative texture paths are resolved against.
        dir: PathBuf,
    },
    /// An image: becomes the current scene's texture (its absolute path).
    Texture {
        /// The image's absolute path, as the scene names its texture.
        path: String,
    },
}

/// A file that loaded, with everything checked.
#[derive(Clone, Debug)]
pub struct OpenedFile {
    /// The path as opened (absolute when it could be made so).
    pub path: PathBuf,
    /// What the file changes: the scene or the texture.
    pub what: Opened,
    /// The texture the result shows, already loaded (so the app does not decode it twice).
    pub texture: Arc<Texture>,
    /// Things that did not stop loading (downscaled image, no uvs, missing MTL ...).
    pub notes: Vec<String>,
}

impl OpenedFile {
    /// The command that applies this file to the current scene.
    pub fn command(&self) -> StateCommand {
        match &self.what {
            Opened::Scene { scene, dir } => {
                StateCommand::OpenScene(scene.clone(), Some(dir.clone()))
            }
            Opened::Texture { path } => StateCommand::SetTexture(path.clone()),
        }
    }
}

/// Loads and checks a file named by the user (by dialog, drop, typed path, recent list or the
/// command line): a scene, a model with its texture, or an image. Nothing is changed; the
/// error names the file and the problem.
pub fn open(path: &Path, current: &Scene, lang: Lang) -> Result<OpenedFile, String> {
    // Absolute, so the scene saved between runs still finds its model and texture.
    let path = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    let shown = path.display().to_string();
    // A model's texture error names the texture; say which file was being opened too.
    let named = |e: String| {
        if e.contains(&shown) {
            e
        } else {
            format!("{shown}: {e}")
        }
    };
    match InputKind::of(&path) {
        Some(InputKind::Image) => {
            let (texture, note) = Texture::load_noted(&path).map_err(|e| named(e.to_string()))?;
            let mut notes: Vec<String> = note.into_iter().collect();
            if let Scene::Model(m) = current
                && !m.mesh.has_uv
            {
                notes.push(lang.tr("app.files.no_uv_texture"));
            }
            Ok(OpenedFile {
                what: Opened::Texture { path: shown },
                path,
                texture: Arc::new(texture),
                notes,
            })
        }
        _ => {
            let (scene, dir) = open_input(&path).map_err(|e| named(e.to_string()))?;
            let (texture, texture_notes) = scene
                .load_texture_noted(&dir)
                .map_err(|e| named(e.to_string()))?;
            let mut notes = scene.notes();
            notes.extend(texture_notes);
            Ok(OpenedFile {
                what: Opened::Scene {
                    scene: Box::new(scene),
                    dir,
                },
                path,
                texture: Arc::new(texture),
                notes,
            })
        }
    }
}

/// Loads a scene file and checks that its texture loads; returns the scene and its folder.
pub fn load_scene(path: &Path) -> Result<(Scene, PathBuf), String> {
    let scene = Scene::load(path).map_err(|e| e.to_string())?;
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    scene.load_texture(&dir).map_err(|e| e.to_string())?;
    Ok((scene, dir))
}

/// Writes `scene` as the JSON that `barylab render`, `probe` and `figure` read, its texture and
/// model paths made absolute against `scene_dir` (so it loads from anywhere), atomically: the
/// file is whole or as it was.
pub fn save(
    path: &Path,
    scene: &Scene,
    scene_dir: Option<&Path>,
    lang: Lang,
) -> Result<String, String> {
    let json = crate::figure::export::scene_json(scene, scene_dir);
    crate::files::write_bytes(path, json.as_bytes()).map_err(|e| e.to_string())?;
    Ok(lang.tr_with("app.files.saved", &[("path", &path.display())]))
}
