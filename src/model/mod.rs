//! OBJ models: triangulated meshes with uvs and the MTL diffuse colour/texture.
//!
//! `obj.rs` reads an OBJ file line by line and builds the mesh directly (a 1,000,000-triangle
//! model loads in a fraction of the memory a whole-file parser takes); MTL libraries are read
//! with `tobj`. `reference.rs` is the `tobj`-based loader it replaced, kept for the tests.

use std::io::{BufRead, BufReader, Seek, SeekFrom};
use std::path::{Path, PathBuf};

use glam::{DVec3, Vec2, Vec3};

use crate::budget::{self, MemoryError};
use crate::files::{self, FileKind, ReadError};

mod count;
mod obj;
mod reference;

#[doc(hidden)]
pub use reference::from_obj_tobj;

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
        /// 1-based, as OBJ counts: the vertex of the file's `index`-th `v` line.
        index: usize,
        /// "not a finite number" or "larger than 1e6 in magnitude".
        what: String,
    },
}

/// What a part's material gives it, whichever reader read it: its diffuse colour (`Kd`, white
/// without one), and the model's texture if none was found before (the first material's
/// `map_Kd`, resolved against the OBJ's folder `dir`).
fn material_look(
    material: Option<&tobj::Material>,
    dir: &Path,
    texture: &mut Option<PathBuf>,
) -> Vec3 {
    if texture.is_none()
        && let Some(tex) = material.and_then(|mat| mat.diffuse_texture.as_ref())
    {
        *texture = Some(dir.join(tex));
    }
    material
        .and_then(|mat| mat.diffuse)
        .map(Vec3::from)
        .unwrap_or(Vec3::ONE)
}

/// The last step of reading a model, whichever reader read it: whether it has uvs, normals
/// computed from the positions where the file gives none for every vertex, and the note for
/// a model without uvs (`shown` names it).
fn finish(out: &mut ModelMesh, all_have_uv: bool, all_have_normals: bool, shown: &str) {
    out.has_uv = all_have_uv;
    if !all_have_normals {
        out.normals = vertex_normals(&out.positions, &out.triangles);
    }
    if !all_have_uv {
        // What this means depends on the shading chosen later: see `Scene::notes_for`.
        out.notes.push(format!("{shown} {NO_UV}"));
    }
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
        E::FaceColorOutOfBounds => {
            "a face uses a vertex beyond the vertices given a colour (`v x y z r g b`)".into()
        }
        E::ScalingByZeroError => "a `v` line has a w of 0 (`v x y z w` divides by w)".into(),
        E::ColorParseError => {
            "a `v` line has too many or too few numbers (x y z, x y z w or x y z r g b)".into()
        }
        E::InvalidPolygon => "an `f` (face) line has no vertices".into(),
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
    // One slot per distinct position (bit pattern), so split copies share their normal.
    let slots = position_slots(positions);
    // Each slot's sum is kept in the entry of its first vertex (a slot is numbered by its
    // first vertex, never after any of its vertices), and written out from the last vertex
    // back: no second array.
    let mut normals = vec![DVec3::ZERO; positions.len()];
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
            if let Some(&s) = slots.get(i as usize) {
                normals[s as usize] += face;
            }
        }
    }
    for i in (0..positions.len()).rev() {
        // Vertices past the last a `u32` triangle index reaches have no face.
        normals[i] = match slots.get(i) {
            Some(&s) => normals[s as usize].normalize_or_zero(),
            None => DVec3::ZERO,
        };
    }
    normals
}

/// For each vertex (up to the last a `u32` index reaches), its slot: the index of the first
/// vertex with the same position (bit pattern). An open-addressing table of vertex indices
/// (4 bytes a slot, at most half full) with a randomly keyed hash: a few bytes per vertex
/// where a `HashMap` of positions took about 70, and no file can make it slow.
fn position_slots(positions: &[DVec3]) -> Vec<u32> {
    use std::hash::BuildHasher;
    const EMPTY: u32 = u32::MAX;
    let n = positions.len().min(EMPTY as usize);
    let bits = |i: usize| positions[i].to_array().map(f64::to_bits);
    let hasher = std::collections::hash_map::RandomState::new();
    let mask = (2 * n).next_power_of_two().max(16) - 1;
    let mut table = vec![EMPTY; mask + 1];
    let mut slots: Vec<u32> = Vec::with_capacity(n);
    for i in 0..n {
        let key = bits(i);
        let mut h = hasher.hash_one(key) as usize & mask;
        loop {
            let first = table[h];
            if first == EMPTY {
                table[h] = i as u32;
                slots.push(i as u32);
                break;
            }
            if bits(first as usize) == key {
                slots.push(first);
                break;
            }
            h = (h + 1) & mask;
        }
    }
    slots
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
    /// Reads an OBJ file line by line, triangulating polygons (never holding its whole
    /// text). Only regular files are read (the OBJ, its MTL), each up to its size cap; the
    /// memory it will need is checked first. Errors name the file, and the line where one is
    /// known.
    pub fn load(path: &Path) -> Result<Self, ModelError> {
        let shown = files::shown(path);
        // The memory the model will take, before it is read.
        if let Ok(meta) = std::fs::metadata(path)
            && meta.is_file()
        {
            budget::check(
                || format!("model {shown} ({})", files::bytes(meta.len())),
                meta.len().saturating_mul(budget::MODEL_BYTES_PER_FILE_BYTE),
            )?;
        }
        let (file, _) = files::open_regular(path, FileKind::Model)?;
        let io = |e| ModelError::File(ReadError::io(path, FileKind::Model, e));
        let cap = FileKind::Model.cap();
        // Two passes over the file: the first counts its lines, so the arrays are reserved
        // once (see `obj::count`).
        let mut input = BufReader::with_capacity(1 << 16, file);
        if input.fill_buf().map_err(io)?.is_empty() {
            return Err(ModelError::EmptyFile { path: shown });
        }
        let counts = count::count(&mut input, cap).map_err(io)?;
        let mut file = input.into_inner();
        file.get_mut().seek(SeekFrom::Start(0)).map_err(io)?;
        file.set_limit(cap + 1);
        let input = BufReader::with_capacity(1 << 16, file);
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        obj::read(input, &shown, &dir, cap, counts).map_err(|stop| match stop {
            obj::Stop::Model(e) => e,
            obj::Stop::Io(e) => io(e),
            obj::Stop::TooLarge => ReadError::grew(path, FileKind::Model).into(),
        })
    }

    /// Parses OBJ text (the same reader as [`ModelMesh::load`]); `shown` names it in
    /// messages, and its MTL and texture paths are relative to `dir`.
    pub fn from_obj(bytes: &[u8], shown: &str, dir: &Path) -> Result<Self, ModelError> {
        let counts = count::count(bytes, u64::MAX).unwrap_or_default();
        obj::read(bytes, shown, dir, u64::MAX, counts).map_err(|stop| match stop {
            obj::Stop::Model(e) => e,
            obj::Stop::Io(e) => ModelError::Parse {
                path: shown.to_string(),
                reason: format!("it cannot be read ({e})"),
            },
            obj::Stop::TooLarge => ModelError::Parse {
                path: shown.to_string(),
                reason: "it is too large".into(),
            },
        })
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

/// The first line of an MTL library that tobj cannot read (its number from 1, and the line),
/// found by bisection: a prefix of the text that fails to load fails with every line after it.
pub(crate) fn first_bad_mtl_line(text: &[u8]) -> Option<(usize, &str)> {
    let text = std::str::from_utf8(text).ok()?;
    let ends: Vec<usize> = text
        .match_indices('\n')
        .map(|(i, _)| i + 1)
        .chain(std::iter::once(text.len()))
        .collect();
    let fails =
        |lines: usize| tobj::load_mtl_buf(&mut &text.as_bytes()[..ends[lines - 1]]).is_err();
    // The smallest number of lines whose prefix fails (the whole text fails).
    let (mut good, mut bad) = (0, ends.len());
    if !fails(bad) {
        return None;
    }
    while bad - good > 1 {
        let mid = (good + bad) / 2;
        if fails(mid) { bad = mid } else { good = mid }
    }
    let start = if bad == 1 { 0 } else { ends[bad - 2] };
    Some((bad, text[start..ends[bad - 1]].trim_end()))
}
