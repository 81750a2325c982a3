//! Scene files (JSON), in three forms; see `docs/scene-format.md`.
//!
//! 1. World form: a camera and a quad's four corners A, B, C, D in world space (drawn as the
//!    triangles A B C and A C D, diagonal A-C).
//! 2. Raw clip-space form: vertices given directly in clip space and any triangles over them,
//!    with viewport (0, 0, width, height), NDC y = +1 at image row 0, depth range [0, 1].
//! 3. Model form: an OBJ model seen by a camera (by default one that frames it).
//!
//! An OBJ model or an image can also stand in for a scene file ([`open_input`]).
//!
//! Unknown fields are errors. Errors name the file, the line and column, and the field.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use glam::{DMat3, DMat4, DVec3, DVec4, Vec2, Vec3};
use serde::{Deserialize, Serialize};

use crate::budget::{self, MemoryError};
use crate::files::{self, FileKind, ReadError, shown};
use crate::model::{ModelError, ModelMesh, vertex_normals};
use crate::raster::camera::{Camera, CameraError, Projection};
use crate::raster::project::MAX_IMAGE_SIZE;
use crate::raster::render::{ClipMesh, DEFAULT_BACKGROUND, MeshVertex, RenderSettings};
use crate::raster::setup::TieRule;
use crate::raster::texture::{BuiltinTexture, Filter, Texture, TextureError, Wrap};
use crate::raster::{Interpolation, Shading};
use json::{parse_error, strict};

mod forms;
pub(crate) mod json;
mod mesh;
mod samples;

use forms::default_texture;
pub use forms::{ClipScene, ClipSceneVertex, Corner, ModelScene, Tilt, WorldScene};
pub use mesh::view_normal;

/// Errors while reading or checking a scene.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The file could not be read (missing, not a regular file, too large).
    #[error(transparent)]
    File(#[from] ReadError),
    /// The scene would need more memory than the budget allows.
    #[error(transparent)]
    Memory(#[from] MemoryError),
    /// The JSON does not parse, or a field has the wrong type or an unknown name.
    #[error("{path}:{line}:{column}: {field}{message}")]
    Parse {
        /// The scene file, as shown in messages.
        path: String,
        /// Line of the error, from 1.
        line: usize,
        /// Column of the error, from 1.
        column: usize,
        /// The JSON path of the offending field followed by ": ", or empty at the top level.
        field: String,
        /// What is wrong.
        message: String,
    },
    /// The scene parses but a value is out of range (image size, camera, indices, ...).
    #[error("{path}: {message}")]
    Invalid {
        /// The scene file, as shown in messages.
        path: String,
        /// What is wrong, naming the field.
        message: String,
    },
    /// The texture could not be loaded.
    #[error(transparent)]
    Texture(#[from] TextureError),
    /// The OBJ model could not be loaded.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// The file's extension is none of `.json`, `.obj` or an image's.
    #[error(
        "{path}: unknown kind of file (expected a .json scene, an .obj model, or an image: {})",
        IMAGE_EXTENSIONS.join(", ")
    )]
    UnknownKind {
        /// The file, as shown in messages.
        path: String,
    },
}

/// Most triangles a clip scene's `subdivide` may make: well beyond the dense-mesh
/// benchmarks (460,800), and a bound on the memory a small scene file can ask for.
pub const MAX_SUBDIVIDED_TRIANGLES: u64 = 4_000_000;

/// Image file extensions accepted in place of a scene (lower case).
pub const IMAGE_EXTENSIONS: [&str; 6] = ["png", "jpg", "jpeg", "bmp", "tga", "webp"];

/// The name of mesh vertex `index`, the same in the derivation, the figures and the app: A, B,
/// C, ..., Z, then `V26`, `V27`, ... (a world quad's corners are A, B, C, D).
///
/// ```
/// use barylab::scene::vertex_name;
/// assert_eq!(vertex_name(0), "A");
/// assert_eq!(vertex_name(6), "G");
/// assert_eq!(vertex_name(25), "Z");
/// assert_eq!(vertex_name(26), "V26");
/// ```
pub fn vertex_name(index: usize) -> String {
    match u8::try_from(index) {
        Ok(i) if i < 26 => char::from(b'A' + i).to_string(),
        _ => format!("V{index}"),
    }
}

/// What a file given in place of a scene is, by its extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InputKind {
    /// A JSON scene file.
    Scene,
    /// An OBJ model.
    Model,
    /// An image (PNG, JPEG, BMP, TGA, WebP).
    Image,
}

impl InputKind {
    /// The kind of `path` by its extension (case-insensitive), or `None` if unknown.
    ///
    /// ```
    /// use barylab::scene::InputKind;
    /// use std::path::Path;
    /// assert_eq!(InputKind::of(Path::new("a/Photo.JPG")), Some(InputKind::Image));
    /// assert_eq!(InputKind::of(Path::new("torus.obj")), Some(InputKind::Model));
    /// assert_eq!(InputKind::of(Path::new("notes.txt")), None);
    /// ```
    pub fn of(path: &Path) -> Option<Self> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)?;
        match ext.as_str() {
            "json" => Some(Self::Scene),
            "obj" => Some(Self::Model),
            e if IMAGE_EXTENSIONS.contains(&e) => Some(Self::Image),
            _ => None,
        }
    }
}

/// Loads what the user named in place of a scene: a scene file, an OBJ model (framed by a
/// default camera), or an image (on the default quad). Returns the scene and the folder its
/// relative paths are resolved against. The CLI and the app both open files through this.
pub fn open_input(path: &Path) -> Result<(Scene, PathBuf), SceneError> {
    match InputKind::of(path) {
        Some(InputKind::Model) => {
            let (w, h) = Scene::default_scene().size();
            let model = ModelScene::for_model(path, w, h)?;
            // The model path is used as given, so relative paths resolve from here.
            Ok((Scene::Model(model), PathBuf::new()))
        }
        Some(InputKind::Image) => Ok((Scene::for_image(path), PathBuf::new())),
        Some(InputKind::Scene) => Ok((
            Scene::load(path)?,
            path.parent().map(Path::to_path_buf).unwrap_or_default(),
        )),
        None => Err(SceneError::UnknownKind { path: shown(path) }),
    }
}

/// A scene in any of its forms.
// One scene exists at a time; boxing the larger variant would buy nothing.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Scene {
    /// A camera and a quad in world space.
    World(WorldScene),
    /// Vertices given in clip space, and triangles over them.
    Clip(ClipScene),
    /// A camera and an OBJ model.
    Model(ModelScene),
}

/// Decides the form before the strict parse, so errors name the right fields.
#[derive(Deserialize)]
#[serde(expecting = "a scene: a JSON object with `quad`, `vertices` or `model`")]
struct FormProbe {
    #[serde(default)]
    quad: Option<serde::de::IgnoredAny>,
    #[serde(default)]
    vertices: Option<serde::de::IgnoredAny>,
    #[serde(default)]
    model: Option<serde::de::IgnoredAny>,
}

impl Scene {
    /// Parses a scene from JSON text; `path` names it in errors, and a model path in the scene
    /// is relative to its folder.
    pub fn from_json(text: &str, path: &str) -> Result<Self, SceneError> {
        Self::parse(
            text,
            path,
            Path::new(path).parent().unwrap_or(Path::new("")),
        )
    }

    /// Parses a scene from JSON text (a leading byte order mark is ignored); `path` names it
    /// in errors; a model path is relative to `dir`.
    fn parse(text: &str, path: &str, dir: &Path) -> Result<Self, SceneError> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        if let Some(held) = not_an_object(text) {
            return Err(invalid(
                path,
                &format!(
                    "is not a scene: a scene is a JSON object ({{ ... }}), this file holds {held}"
                ),
            ));
        }
        let probe: FormProbe =
            serde_json::from_str(text).map_err(|e| parse_error(path, e, String::new()))?;
        let forms = [
            probe.quad.is_some(),
            probe.vertices.is_some(),
            probe.model.is_some(),
        ];
        let scene = match forms {
            [true, false, false] => Scene::World(strict(text, path)?),
            [false, true, false] => Scene::Clip(strict(text, path)?),
            [false, false, true] => {
                let mut s: ModelScene = strict(text, path)?;
                s.mesh = Arc::new(ModelMesh::load(&resolve(dir, &s.model))?);
                Scene::Model(s)
            }
            [false, false, false] => {
                return Err(invalid(
                    path,
                    "has none of `quad` (world form), `vertices` (clip-space form) or `model` (OBJ form)",
                ));
            }
            _ => {
                return Err(invalid(
                    path,
                    "mixes the forms: use exactly one of `quad`, `vertices` and `model`",
                ));
            }
        };
        scene.validate(path)?;
        Ok(scene)
    }

    /// Reads and parses a scene file.
    pub fn load(path: &Path) -> Result<Self, SceneError> {
        let bytes = files::read_regular(path, FileKind::Scene)?;
        let name = shown(path);
        budget::check(
            || format!("scene {name} ({})", files::bytes(bytes.len() as u64)),
            bytes.len() as u64 * budget::SCENE_BYTES_PER_FILE_BYTE,
        )?;
        let text = std::str::from_utf8(&bytes).map_err(|e| {
            invalid(
                &name,
                &format!("is not UTF-8 text (bad byte at offset {})", e.valid_up_to()),
            )
        })?;
        // The directory the model path resolves against is the file's, not the shown name's.
        Self::parse(text, &name, path.parent().unwrap_or(Path::new("")))
    }

    /// The scene as pretty JSON (the form it was read in).
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    /// The built-in default scene: a UV-grid quad lying like a floor, leaning away from the
    /// camera, so that affine and perspective-correct interpolation differ at once.
    pub fn default_scene() -> Self {
        let corner = |x, y, z, u, v, c: [f32; 3]| Corner {
            position: DVec3::new(x, y, z),
            uv: Vec2::new(u, v),
            color: Vec3::from(c),
        };
        Scene::World(WorldScene {
            width: 800,
            height: 600,
            camera: Camera {
                eye: DVec3::new(0.0, 1.5, 1.2),
                target: DVec3::new(0.0, -0.1, -2.0),
                up: DVec3::Y,
                projection: Projection::Perspective {
                    fov_y_deg: 60.0,
                    near: 0.1,
                    far: 100.0,
                },
            },
            quad: [
                corner(-1.2, 0.0, 0.0, 0.0, 0.0, [1.0, 0.0, 0.0]),
                corner(1.2, 0.0, 0.0, 1.0, 0.0, [0.0, 1.0, 0.0]),
                corner(1.2, 0.0, -4.8, 1.0, 1.0, [0.0, 0.0, 1.0]),
                corner(-1.2, 0.0, -4.8, 0.0, 1.0, [1.0, 1.0, 0.0]),
            ],
            tilt: Tilt::default(),
            texture: default_texture(),
            filter: Filter::Bilinear,
            wrap: Wrap::Repeat,
            max_anisotropy: Default::default(),
            mode: Interpolation::Perspective,
            shading: Shading::Texture,
            wireframe: false,
            background: DEFAULT_BACKGROUND,
            tie_rule: TieRule::default(),
            samples: Default::default(),
            sample_pattern: Default::default(),
            shading_rate: Default::default(),
            location: Default::default(),
            flat: false,
            provoking_vertex: Default::default(),
        })
    }

    /// Image width and height.
    pub fn size(&self) -> (u32, u32) {
        match self {
            Scene::World(s) => (s.width, s.height),
            Scene::Clip(s) => (s.width, s.height),
            Scene::Model(s) => (s.width, s.height),
        }
    }

    /// Sets the image size (the clip form's NDC is unchanged; the world form keeps its camera
    /// and adapts the aspect ratio).
    pub fn set_size(&mut self, width: u32, height: u32) {
        match self {
            Scene::World(s) => (s.width, s.height) = (width, height),
            Scene::Clip(s) => (s.width, s.height) = (width, height),
            Scene::Model(s) => (s.width, s.height) = (width, height),
        }
    }

    /// The texture field: a built-in name or a path relative to the scene file (for a model
    /// without one: its MTL diffuse texture, else `uv-grid`).
    pub fn texture_name(&self) -> &str {
        match self {
            Scene::World(s) => &s.texture,
            Scene::Clip(s) => &s.texture,
            Scene::Model(s) => match (&s.texture, &s.mesh.diffuse_texture) {
                (Some(t), _) => t,
                (None, Some(p)) => p.to_str().unwrap_or("uv-grid"),
                (None, None) => BuiltinTexture::UvGrid.name(),
            },
        }
    }

    /// The scene with its texture and model paths made absolute against `base_dir` (the
    /// folder they are relative to), so a copy saved anywhere loads the same files. Built-in
    /// texture names stay as they are.
    pub fn with_absolute_paths(&self, base_dir: &Path) -> Scene {
        let absolute = |name: &str| {
            let p = resolve(base_dir, name);
            std::path::absolute(&p).unwrap_or(p).display().to_string()
        };
        let texture = |name: &str| match BuiltinTexture::from_name(name) {
            Some(_) => name.to_string(),
            None => absolute(name),
        };
        let mut scene = self.clone();
        match &mut scene {
            Scene::World(s) => s.texture = texture(&s.texture),
            Scene::Clip(s) => s.texture = texture(&s.texture),
            Scene::Model(s) => {
                s.model = absolute(&s.model);
                s.texture = s.texture.as_deref().map(texture);
            }
        }
        scene
    }

    /// The files the scene reads besides the scene file itself: its texture image (unless
    /// built in) and its model, resolved against `base_dir`.
    pub fn input_files(&self, base_dir: &Path) -> Vec<PathBuf> {
        let mut files = Vec::new();
        if let Scene::Model(s) = self {
            files.push(resolve(base_dir, &s.model));
        }
        let texture = self.texture_name();
        if BuiltinTexture::from_name(texture).is_none() {
            files.push(resolve(base_dir, texture));
        }
        files
    }

    /// Things the user should be told about the scene that did not stop it loading, for the
    /// scene's own shading.
    pub fn notes(&self) -> Vec<String> {
        self.notes_for(self.settings().shading)
    }

    /// Like [`Scene::notes`], for the shading it is drawn with (the command line may choose
    /// another): a model without texture coordinates says what that shading shows.
    pub fn notes_for(&self, shading: Shading) -> Vec<String> {
        let Scene::Model(s) = self else {
            return Vec::new();
        };
        s.mesh
            .notes
            .iter()
            .map(|n| {
                if !n.ends_with(crate::model::NO_UV) {
                    return n.clone();
                }
                let meaning = match shading {
                    Shading::Texture => {
                        "; the texture shows as one colour (every vertex has uv (0, 0))"
                    }
                    Shading::VertexColor => "; shading by vertex colour",
                    Shading::Lambert => "; lit by a headlight (Lambert shading) to show its shape",
                    Shading::Barycentric | Shading::Depth | Shading::Normal => "",
                };
                format!("{n}{meaning}")
            })
            .collect()
    }

    /// The default quad showing an image file as its texture.
    pub fn for_image(image_path: &Path) -> Self {
        let mut scene = Self::default_scene();
        if let Scene::World(s) = &mut scene {
            s.texture = image_path.display().to_string();
        }
        scene
    }

    /// Sets which triangle owns a pixel centre exactly on a shared edge.
    pub fn set_tie_rule(&mut self, rule: TieRule) {
        match self {
            Scene::World(s) => s.tie_rule = rule,
            Scene::Clip(s) => s.tie_rule = rule,
            Scene::Model(s) => s.tie_rule = rule,
        }
    }

    /// The render settings the scene asks for.
    pub fn settings(&self) -> RenderSettings {
        let (width, height) = self.size();
        let (mode, filter, wrap, shading, wireframe, background) = match self {
            Scene::World(s) => (
                s.mode,
                s.filter,
                s.wrap,
                s.shading,
                s.wireframe,
                s.background,
            ),
            Scene::Clip(s) => (
                s.mode,
                s.filter,
                s.wrap,
                s.shading,
                s.wireframe,
                s.background,
            ),
            Scene::Model(s) => {
                // Without uvs a texture would be one colour: light the shape instead.
                let shading = s.shading.unwrap_or(if s.mesh.has_uv {
                    Shading::Texture
                } else {
                    Shading::Lambert
                });
                (s.mode, s.filter, s.wrap, shading, s.wireframe, s.background)
            }
        };
        let tie_rule = match self {
            Scene::World(s) => s.tie_rule,
            Scene::Clip(s) => s.tie_rule,
            Scene::Model(s) => s.tie_rule,
        };
        RenderSettings {
            rasterizer: Default::default(),
            max_anisotropy: self.max_anisotropy(),
            samples: self.samples(),
            tie_rule,
            width,
            height,
            mode,
            filter,
            wrap,
            shading,
            wireframe,
            background,
        }
    }

    /// Loads the scene's texture: a built-in by name, else a file relative to `base_dir`.
    pub fn load_texture(&self, base_dir: &Path) -> Result<Texture, SceneError> {
        Ok(self.load_texture_noted(base_dir)?.0)
    }

    /// Like [`Scene::load_texture`], also returning notes (e.g. that a huge image was
    /// downscaled).
    pub fn load_texture_noted(
        &self,
        base_dir: &Path,
    ) -> Result<(Texture, Vec<String>), SceneError> {
        let name = self.texture_name();
        match BuiltinTexture::from_name(name) {
            Some(b) => Ok((Texture::builtin(b), Vec::new())),
            None => {
                let (tex, note) = Texture::load_noted(&resolve(base_dir, name))?;
                Ok((tex, note.into_iter().collect()))
            }
        }
    }
}

/// What JSON text holds when it is not an object ("a JSON array", "nothing", ...), from its
/// first character; `None` for an object (or text serde will name the problem of).
fn not_an_object(text: &str) -> Option<&'static str> {
    match text.trim_start().chars().next() {
        None => Some("nothing (it is empty)"),
        Some('{') => None,
        Some('[') => Some("a JSON array ([ ... ])"),
        Some('"') => Some("a JSON string"),
        Some('-' | '0'..='9') => Some("a number"),
        Some('t' | 'f') => Some("true or false"),
        Some('n') => Some("null"),
        Some(_) => None,
    }
}

fn invalid(path: &str, message: &str) -> SceneError {
    SceneError::Invalid {
        path: path.to_string(),
        message: message.to_string(),
    }
}

/// A texture path as written in a scene, relative to the scene file's folder.
pub fn resolve(base_dir: &Path, name: &str) -> PathBuf {
    let p = Path::new(name);
    if p.is_absolute() {
        p.to_path_buf()
    } else {
        base_dir.join(p)
    }
}
