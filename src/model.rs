//! OBJ models (via `tobj`): triangulated meshes with uvs and the MTL diffuse colour/texture.

use std::path::{Path, PathBuf};

use glam::{DVec3, Vec2, Vec3};

use crate::budget::{self, MemoryError};
use crate::files::{self, FileKind, ReadError};

/// Largest accepted |coordinate| in a model file. Beyond this the f32 positions of the file
/// have too little precision for a classroom-sized view, and framing the camera fails.
pub const MAX_MODEL_COORD: f64 = 1e6;

/// The note for a model without texture coordinates (after its name); the scene adds what
/// that means for its shading.
pub const NO_UV: &str = "has no texture coordinates (vt) on every face";

/// Errors while loading a model. Each names the file.
#[derive(Debug, thiserror::Error)]
pub enum ModelError {
    /// The file could not be read.
    #[error(transparent)]
    File(#[from] ReadError),
    /// Loading it would need more memory than the budget allows.
    #[error(transparent)]
    Memory(#[from] MemoryError),
    /// The file has 0 bytes.
    #[error("model {path} is empty (0 bytes)")]
    EmptyFile {
        /// The file, as shown in messages.
        path: String,
    },
    /// The OBJ text is malformed (or not text), or a face index is out of range.
    #[error("cannot load model {path}: {reason}")]
    Parse {
        /// The file, as shown in messages.
        path: String,
        /// What is wrong, for someone looking at the file.
        reason: String,
    },
    /// The file has no faces.
    #[error("model {path} contains no triangles")]
    NoTriangles {
        /// The file, as shown in messages.
        path: String,
    },
    /// A vertex position is NaN, infinite, or beyond [`MAX_MODEL_COORD`].
    #[error("model {path}: vertex {index} has a coordinate that is {what}")]
    BadCoordinate {
        /// The file, as shown in messages.
        path: String,
        /// 1-based, as OBJ counts.
        index: usize,
        /// "not a finite number" or "larger than 1e6 in magnitude".
        what: String,
    },
}

/// Says what a `tobj` error means for someone looking at the file.
fn explain(e: &tobj::LoadError) -> String {
    use tobj::LoadError as E;
    match e {
        E::OpenFileFailed => "the file cannot be opened".into(),
        E::ReadError => "it is not a readable text OBJ file (binary data or invalid UTF-8)".into(),
        E::PositionParseError => "a `v` (position) line has a missing or bad number".into(),
        E::TexcoordParseError => "a `vt` (texture coordinate) line has a bad number".into(),
        E::NormalParseError => "a `vn` (normal) line has a bad number".into(),
        E::FaceParseError => "an `f` (face) line is malformed".into(),
        E::FaceVertexOutOfBounds => "a face uses a vertex index beyond the vertices defined".into(),
        E::FaceTexCoordOutOfBounds => {
            "a face uses a texture coordinate index beyond those defined".into()
        }
        E::FaceNormalOutOfBounds => "a face uses a normal index beyond those defined".into(),
        other => other.to_string(),
    }
}

/// Unit vertex normals computed from the faces: at each position, the sum of the normals
/// `(b - a) × (c - a)` of the triangles around it (each as long as twice its area, so large
/// faces count more), scaled to unit length. Vertices at one position (an OBJ vertex split
/// at a uv seam) share the normal, so seams do not show. Zero where every face around a
/// position is degenerate; counter-clockwise faces (OBJ's convention) give outward normals.
///
/// ```
/// use barylab::model::vertex_normals;
/// use glam::DVec3;
/// // A square in the z = 0 plane, counter-clockwise seen from +z: every normal is +z.
/// let p = [DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
/// let n = vertex_normals(&p, &[[0, 1, 2], [0, 2, 3]]);
/// assert!(n.iter().all(|v| *v == DVec3::Z));
/// ```
pub fn vertex_normals(positions: &[DVec3], triangles: &[[u32; 3]]) -> Vec<DVec3> {
    use std::collections::HashMap;
    // One slot per distinct position (bit pattern), so split copies share their normal.
    let mut slot_of: HashMap<[u64; 3], usize> = HashMap::with_capacity(positions.len());
    let slots: Vec<usize> = positions
        .iter()
        .map(|p| {
            let key = p.to_array().map(f64::to_bits);
            let next = slot_of.len();
            *slot_of.entry(key).or_insert(next)
        })
        .collect();
    let mut sums = vec![DVec3::ZERO; slot_of.len()];
    for t in triangles {
        let [a, b, c] = t.map(|i| positions.get(i as usize).copied());
        let (Some(a), Some(b), Some(c)) = (a, b, c) else {
            continue;
        };
        let face = (b - a).cross(c - a);
        if !face.is_finite() {
            continue;
        }
        for &i in t {
            sums[slots[i as usize]] += face;
        }
    }
    slots.iter().map(|&s| sums[s].normalize_or_zero()).collect()
}

/// A triangle mesh in object space, ready to be transformed by a camera.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct ModelMesh {
    /// Vertex positions in object space (the file's units).
    pub positions: Vec<DVec3>,
    /// Unit vertex normals in object space: the file's `vn` where every face has them,
    /// else [`vertex_normals`] of the positions.
    pub normals: Vec<DVec3>,
    /// Texture coordinate per vertex; `[0, 0]` for a part of the file without `vt`.
    pub uvs: Vec<Vec2>,
    /// Colour per vertex: its material's diffuse colour (`Kd`), RGB in [0, 1]; white without one.
    pub colors: Vec<Vec3>,
    /// Index triples into `positions` (polygons triangulated), in file order.
    pub triangles: Vec<[u32; 3]>,
    /// Whether every vertex has a texture coordinate (`vt`).
    pub has_uv: bool,
    /// The first material's diffuse texture, resolved against the OBJ's folder.
    pub diffuse_texture: Option<PathBuf>,
    /// Things the user should know that did not stop loading (missing MTL, no uvs ...).
    pub notes: Vec<String>,
}

impl ModelMesh {
    /// Reads an OBJ file, triangulating polygons. Only regular files are read (the OBJ, its
    /// MTL), each up to its size cap; the memory it will need is checked first.
    pub fn load(path: &Path) -> Result<Self, ModelError> {
        let shown = files::shown(path);
        // The memory the model will take, before its text is read.
        if let Ok(meta) = std::fs::metadata(path)
            && meta.is_file()
        {
            budget::check(
                || format!("model {shown} ({})", files::bytes(meta.len())),
                meta.len().saturating_mul(budget::MODEL_BYTES_PER_FILE_BYTE),
            )?;
        }
        let bytes = files::read_regular(path, FileKind::Model)?;
        if bytes.is_empty() {
            return Err(ModelError::EmptyFile { path: shown });
        }
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        let parsed = parse_obj(files::strip_bom(&bytes), &shown, &dir)?;
        // The text is not needed any more: its memory is free before the mesh is built.
        drop(bytes);
        Self::from_parsed(parsed, shown, &dir)
    }

    /// Parses OBJ text; `shown` names it in messages, and its MTL and texture paths are
    /// relative to `dir`.
    pub fn from_obj(bytes: &[u8], shown: &str, dir: &Path) -> Result<Self, ModelError> {
        let parsed = parse_obj(bytes, shown, dir)?;
        Self::from_parsed(parsed, shown.to_string(), dir)
    }

    fn from_parsed(parsed: ParsedObj, shown: String, dir: &Path) -> Result<Self, ModelError> {
        let ParsedObj {
            models,
            materials,
            mtl_error,
        } = parsed;
        let dir = dir.to_path_buf();
        let mut out = ModelMesh::default();
        let materials = match materials {
            Ok(m) => m,
            Err(e) => {
                let why = mtl_error.unwrap_or_else(|| explain(&e));
                out.notes.push(format!(
                    "the material library (mtllib) of {shown} could not be loaded ({why}); \
                     drawing without materials"
                ));
                Vec::new()
            }
        };
        let mut all_have_uv = true;
        let mut all_have_normals = true;
        // Reserved once: growing by doubling would hold up to twice the memory.
        let vertices: usize = models.iter().map(|m| m.mesh.positions.len() / 3).sum();
        let triangles: usize = models.iter().map(|m| m.mesh.indices.len() / 3).sum();
        out.positions.reserve_exact(vertices);
        out.normals.reserve_exact(vertices);
        out.uvs.reserve_exact(vertices);
        out.colors.reserve_exact(vertices);
        out.triangles.reserve_exact(triangles);
        for m in &models {
            let mesh = &m.mesh;
            let base = out.positions.len() as u32;
            let n = mesh.positions.len() / 3;
            let has_uv = mesh.texcoords.len() / 2 == n && n > 0;
            all_have_uv &= has_uv;
            let has_normals = mesh.normals.len() / 3 == n && n > 0;
            all_have_normals &= has_normals;
            let material = mesh.material_id.and_then(|id| materials.get(id));
            let color = material
                .and_then(|mat| mat.diffuse)
                .map(Vec3::from)
                .unwrap_or(Vec3::ONE);
            if out.diffuse_texture.is_none()
                && let Some(tex) = material.and_then(|mat| mat.diffuse_texture.as_ref())
            {
                out.diffuse_texture = Some(dir.join(tex));
            }
            for k in 0..n {
                let p = DVec3::new(
                    f64::from(mesh.positions[3 * k]),
                    f64::from(mesh.positions[3 * k + 1]),
                    f64::from(mesh.positions[3 * k + 2]),
                );
                let index = out.positions.len() + 1;
                if !p.is_finite() {
                    return Err(ModelError::BadCoordinate {
                        path: shown,
                        index,
                        what: "not a finite number".into(),
                    });
                }
                if p.abs().max_element() > MAX_MODEL_COORD {
                    return Err(ModelError::BadCoordinate {
                        path: shown,
                        index,
                        what: format!("larger than {MAX_MODEL_COORD:e} in magnitude"),
                    });
                }
                out.positions.push(p);
                out.normals.push(if has_normals {
                    DVec3::new(
                        f64::from(mesh.normals[3 * k]),
                        f64::from(mesh.normals[3 * k + 1]),
                        f64::from(mesh.normals[3 * k + 2]),
                    )
                    .normalize_or_zero()
                } else {
                    DVec3::ZERO
                });
                out.uvs.push(if has_uv {
                    Vec2::new(mesh.texcoords[2 * k], mesh.texcoords[2 * k + 1])
                } else {
                    Vec2::ZERO
                });
                out.colors.push(color);
            }
            for t in mesh.indices.chunks_exact(3) {
                if t.iter().any(|&i| i as usize >= n) {
                    return Err(ModelError::Parse {
                        path: shown,
                        reason: explain(&tobj::LoadError::FaceVertexOutOfBounds),
                    });
                }
                out.triangles.push([base + t[0], base + t[1], base + t[2]]);
            }
        }
        drop(models);
        if out.triangles.is_empty() {
            return Err(ModelError::NoTriangles { path: shown });
        }
        out.has_uv = all_have_uv;
        if !all_have_normals {
            out.normals = vertex_normals(&out.positions, &out.triangles);
        }
        if !all_have_uv {
            // What this means depends on the shading chosen later: see `Scene::notes_for`.
            out.notes.push(format!("{shown} {NO_UV}"));
        }
        Ok(out)
    }

    /// A sphere containing every vertex: centred on the bounding box, radius the farthest
    /// vertex from there.
    pub fn bounding_sphere(&self) -> (DVec3, f64) {
        let (lo, hi) = self.bounds();
        let centre = (lo + hi) / 2.0;
        let r = self
            .positions
            .iter()
            .map(|p| p.distance(centre))
            .fold(0.0, f64::max);
        (centre, r)
    }

    /// Axis-aligned bounds (min, max) of the positions.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        let mut lo = DVec3::splat(f64::INFINITY);
        let mut hi = DVec3::splat(f64::NEG_INFINITY);
        for p in &self.positions {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
        (lo, hi)
    }
}

/// What tobj parsed of an OBJ file, before barylab builds its mesh.
struct ParsedObj {
    models: Vec<tobj::Model>,
    materials: Result<Vec<tobj::Material>, tobj::LoadError>,
    /// Why the MTL file could not be read, when that was the problem.
    mtl_error: Option<String>,
}

/// Parses OBJ text with tobj (polygons triangulated, one index per vertex); `shown` names it
/// in messages, and its MTL path is relative to `dir`.
fn parse_obj(bytes: &[u8], shown: &str, dir: &Path) -> Result<ParsedObj, ModelError> {
    // tobj's loader gives no reason for a failed MTL: keep ours for the note.
    let mtl_error = std::cell::RefCell::new(None::<String>);
    let load_mtl = |name: &Path| match files::read_regular(&dir.join(name), FileKind::Material) {
        Ok(text) => tobj::load_mtl_buf(&mut files::strip_bom(&text)),
        Err(e) => {
            mtl_error.replace(Some(e.to_string()));
            Err(tobj::LoadError::OpenFileFailed)
        }
    };
    let (models, materials) =
        tobj::load_obj_buf(&mut &bytes[..], &tobj::GPU_LOAD_OPTIONS, load_mtl).map_err(|e| {
            ModelError::Parse {
                path: shown.to_string(),
                reason: explain(&e),
            }
        })?;
    Ok(ParsedObj {
        models,
        materials,
        mtl_error: mtl_error.into_inner(),
    })
}
