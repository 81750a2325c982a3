//! The three forms of a scene file: a world quad, raw clip-space vertices, an OBJ model.

use super::*;
use crate::raster::sample::{Location, ProvokingVertex, SampleCount, SamplePattern, ShadingRate};
use crate::raster::texture::MaxAnisotropy;

/// Whether a field holds its default (scene files leave such fields out).
fn is_default<T: Default + PartialEq>(v: &T) -> bool {
    *v == T::default()
}

/// Corner of the quad in the world form.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Corner {
    /// Position in object space (world space when the tilt is zero).
    pub position: DVec3,
    /// Texture coordinate (v = 0 is the texture's bottom row).
    pub uv: Vec2,
    /// RGB in [0, 1]; white when omitted.
    #[serde(default = "white")]
    pub color: Vec3,
}

fn white() -> Vec3 {
    Vec3::ONE
}

/// A rotation of the whole quad about its centre: pitch about the x axis, then yaw about y.
#[derive(Clone, Copy, Debug, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Tilt {
    /// Rotation about the x axis through the quad's centre, in degrees (applied first).
    pub pitch_deg: f64,
    /// Then rotation about the y axis through the centre, in degrees.
    pub yaw_deg: f64,
}

pub(super) fn default_texture() -> String {
    BuiltinTexture::UvGrid.name().to_string()
}

fn default_background() -> [u8; 4] {
    DEFAULT_BACKGROUND
}

/// Defines a scene form: the doc and attributes, its own fields, then the look fields every
/// form has, written here once (serde's `flatten` cannot be combined with
/// `deny_unknown_fields`, and rejecting unknown fields matters more: a typo must not pass
/// silently). `texture` and `shading` differ between forms and are given with their
/// attributes; fields after the look fields follow `then`.
macro_rules! scene_form {
    (
        $(#[$meta:meta])*
        pub struct $name:ident {
            $( $(#[$own_meta:meta])* pub $own:ident: $own_ty:ty, )*
        }
        texture: $(#[$texture_meta:meta])* $texture_ty:ty,
        shading: $(#[$shading_meta:meta])* $shading_ty:ty,
        then { $( $(#[$then_meta:meta])* pub $then:ident: $then_ty:ty, )* }
    ) => {
        $(#[$meta])*
        pub struct $name {
            $( $(#[$own_meta])* pub $own: $own_ty, )*
            $(#[$texture_meta])*
            pub texture: $texture_ty,
            /// Texture filter (default bilinear).
            #[serde(default)]
            pub filter: Filter,
            /// Texture wrap mode outside [0, 1] (default repeat).
            #[serde(default)]
            pub wrap: Wrap,
            /// The largest anisotropy of texture lookups: 1 (off, the default) to 16; above 1,
            /// trilinear filtering becomes anisotropic.
            #[serde(default, skip_serializing_if = "is_default")]
            pub max_anisotropy: MaxAnisotropy,
            /// Interpolation: perspective-correct (default) or affine.
            #[serde(default)]
            pub mode: Interpolation,
            $(#[$shading_meta])*
            pub shading: $shading_ty,
            /// Overlay the triangles' edges.
            #[serde(default)]
            pub wireframe: bool,
            /// Colour of uncovered pixels, RGBA 0..=255.
            #[serde(default = "default_background")]
            pub background: [u8; 4],
            /// Which triangle owns a pixel centre exactly on a shared edge (default: llvmpipe's).
            #[serde(default, skip_serializing_if = "TieRule::is_default")]
            pub tie_rule: TieRule,
            /// Samples per pixel: 1 (the default), 4, 8 or 16.
            #[serde(default, skip_serializing_if = "is_default")]
            pub samples: SampleCount,
            /// Where the samples lie: `standard` (the GL's, the default) or `grid`.
            #[serde(default, skip_serializing_if = "is_default")]
            pub sample_pattern: SamplePattern,
            /// `msaa` (one shading per pixel and triangle, the default) or `ssaa` (every sample).
            #[serde(default, skip_serializing_if = "is_default")]
            pub shading_rate: ShadingRate,
            /// Where MSAA evaluates values: `center` (the default), `centroid` or `sample`.
            #[serde(default, skip_serializing_if = "is_default")]
            pub location: Location,
            /// Every attribute `flat`: the provoking vertex's value (default false).
            #[serde(default, skip_serializing_if = "is_default")]
            pub flat: bool,
            /// The provoking vertex of `flat`: `last` (OpenGL's default) or `first`.
            #[serde(default, skip_serializing_if = "is_default")]
            pub provoking_vertex: ProvokingVertex,
            $( $(#[$then_meta])* pub $then: $then_ty, )*
        }
    };
}

scene_form! {
    /// The world form.
    #[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields)]
    pub struct WorldScene {
        /// Image width in pixels (1..=16384).
        pub width: u32,
        /// Image height in pixels (1..=16384).
        pub height: u32,
        /// The camera (look-at and projection); default: at the origin looking down -z, 60°
        /// perspective.
        #[serde(default)]
        pub camera: Camera,
        /// Corners A, B, C, D.
        pub quad: [Corner; 4],
        /// Rotation of the quad about its centre (`world_from_object`).
        #[serde(default)]
        pub tilt: Tilt,
    }
    texture:
        /// A built-in texture name (`uv-grid`, `checker`, `rgbw-2x2`, `noise`) or an image path
        /// relative to the scene file.
        #[serde(default = "default_texture")]
        String,
    shading:
        /// What the colour shows (default the texture).
        #[serde(default)]
        Shading,
    then {
    }
}

/// A vertex of the raw clip-space form.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClipSceneVertex {
    /// Position in clip space `(x, y, z, w)`; window `x = (x/w + 1) width/2`, `y = (1 - y/w)
    /// height/2`, depth `(z/w + 1)/2`.
    pub clip: DVec4,
    /// Texture coordinate; `[0, 0]` when omitted.
    #[serde(default)]
    pub uv: Vec2,
    /// RGB in [0, 1]; white when omitted.
    #[serde(default = "white")]
    pub color: Vec3,
}

scene_form! {
    /// The raw clip-space form (its look fields, `texture` on, are [`WorldScene`]'s: one
    /// definition, `scene_form!`).
    #[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields)]
    pub struct ClipScene {
        /// Image width in pixels (1..=16384).
        pub width: u32,
        /// Image height in pixels (1..=16384).
        pub height: u32,
        /// The vertices, any number.
        pub vertices: Vec<ClipSceneVertex>,
        /// Index triples into `vertices`, drawn in order.
        pub triangles: Vec<[u32; 3]>,
        /// Split every triangle into `n x n` smaller ones on its barycentric grid
        /// ([`ClipMesh::subdivided`]): the same surface, the same image, more triangles (the
        /// dense-mesh benchmarks). 1 or absent: as given.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub subdivide: Option<u32>,
    }
    texture:
        /// A built-in texture name or an image path relative to the scene file.
        #[serde(default = "default_texture")]
        String,
    shading:
        /// What the colour shows (default the texture).
        #[serde(default)]
        Shading,
    then {
    }
}

scene_form! {
    /// The model form: an OBJ file seen by a camera.
    #[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields)]
    pub struct ModelScene {
        /// Image width in pixels (1..=16384).
        pub width: u32,
        /// Image height in pixels (1..=16384).
        pub height: u32,
        /// When omitted, a camera that frames the model ([`Camera::framing`]).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub camera: Option<Camera>,
        /// The OBJ file, relative to the scene file.
        pub model: String,
    }
    texture:
        /// A built-in texture or image path; when omitted, the model's MTL diffuse texture, else
        /// `uv-grid`.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        Option<String>,
    shading:
        /// When omitted: the texture if the model has uvs, else the vertex (material) colour.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        Option<Shading>,
    then {
        /// The loaded model (filled when the scene is loaded).
        #[serde(skip)]
        pub mesh: Arc<ModelMesh>,
    }
}

impl ModelScene {
    /// A scene showing an OBJ file with the default framing camera.
    pub fn for_model(model_path: &Path, width: u32, height: u32) -> Result<Self, SceneError> {
        Ok(Self {
            width,
            height,
            camera: None,
            model: model_path.display().to_string(),
            texture: None,
            filter: Filter::default(),
            wrap: Wrap::default(),
            max_anisotropy: MaxAnisotropy::default(),
            mode: Interpolation::default(),
            shading: None,
            wireframe: false,
            background: DEFAULT_BACKGROUND,
            tie_rule: TieRule::default(),
            samples: SampleCount::default(),
            sample_pattern: SamplePattern::default(),
            shading_rate: ShadingRate::default(),
            location: Location::default(),
            flat: false,
            provoking_vertex: ProvokingVertex::default(),
            mesh: Arc::new(ModelMesh::load(model_path)?),
        })
    }

    /// The camera: the given one, or one framing the model.
    pub fn camera(&self) -> Camera {
        self.camera.unwrap_or_else(|| {
            let (centre, radius) = self.mesh.bounding_sphere();
            Camera::framing(centre, radius)
        })
    }
}
