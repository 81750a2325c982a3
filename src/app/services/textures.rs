//! The textures scenes name, loaded once: the canvas, the inspector, the benchmark and the
//! export all use the one loaded here.

use std::path::Path;
use std::sync::Arc;

use crate::app::services::render::TextureKey;
use crate::i18n::Lang;
use crate::raster::{BuiltinTexture, Texture};
use crate::scene::Scene;

/// The texture of the current scene, loaded once.
#[derive(Default)]
pub struct TextureCache {
    key: Option<TextureKey>,
    texture: Option<Arc<Texture>>,
    /// A texture already loaded while opening a file, used for the next new key.
    pub pending: Option<Arc<Texture>>,
}

/// The key of a scene's texture: its name and the folder it is resolved against.
pub fn texture_key(scene: &Scene, dir: Option<&Path>) -> TextureKey {
    (scene.texture_name().to_string(), dir.map(Path::to_path_buf))
}

impl TextureCache {
    /// The scene's texture; on failure the uv-grid and the error.
    pub fn get(
        &mut self,
        scene: &Scene,
        dir: Option<&Path>,
        lang: Lang,
    ) -> (Arc<Texture>, Option<String>) {
        let key = texture_key(scene, dir);
        if self.key.as_ref() == Some(&key)
            && let Some(t) = &self.texture
        {
            return (t.clone(), None);
        }
        if let Some(t) = self.pending.take() {
            self.key = Some(key);
            self.texture = Some(t.clone());
            return (t, None);
        }
        let (texture, error) = match scene.load_texture(dir.unwrap_or(Path::new(""))) {
            Ok(t) => (t, None),
            Err(e) => (
                Texture::builtin(BuiltinTexture::UvGrid),
                Some(lang.tr_with("app.textures.texture_fallback", &[("error", &e)])),
            ),
        };
        let texture = Arc::new(texture);
        self.key = Some(key);
        self.texture = Some(texture.clone());
        (texture, error)
    }
}
