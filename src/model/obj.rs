//! The streaming OBJ reader: reads an OBJ file line by line (never the whole text) and builds
//! the [`ModelMesh`] directly, the same mesh `tobj` 4's `load_obj_buf` with
//! `GPU_LOAD_OPTIONS` and barylab's builder give ([`super::reference`], compared in the tests).
//!
//! What it keeps while reading: the file's positions, texture coordinates and normals as f32
//! (as tobj parses them), the (v, vt, vn) indices of every output vertex (12 bytes), the
//! triangles, and for the model being read the output vertex of each position it used first
//! (4 bytes per position). A face corner is an output vertex seen before in the same model
//! when its (v, vt, vn) is the same (tobj's single-index dedup, per model): found through the
//! position's first vertex, and a hash map only for the other vertices at one position (uv or
//! normal seams); faces that give only `v` never need the map.
//!
//! tobj's rules it follows: polygons are fans from their first corner; a face with one or two
//! corners (a point, a line; `l` lines too) is dropped; negative indices count back from the
//! last vertex defined so far; a face may use vertices defined later in the same model, and
//! indices are checked when the model ends (an `o` or `g` line after faces, a `usemtl` naming
//! another material after faces, the end of the file), vertex, texture coordinate, normal and
//! vertex colour in turn, in the order vertices appear; `vt` and `vn` indices mean nothing in a
//! file without `vt` or `vn` lines; `v x y z w` divides by w; `mtllib` loads its library when
//! the line is read, so `usemtl` finds only materials loaded before it.

use std::collections::HashMap;
use std::io::{self, BufRead};
use std::path::Path;

use glam::{DVec3, Vec2};
use tobj::LoadError as E;

use super::count::{Counts, reserve};
use super::{MAX_MODEL_COORD, ModelError, ModelMesh, explain, finish, material_look};
use crate::files::{self, FileKind};

/// An index a face corner does not give: an empty field, `0`, or a relative index one before
/// the first (tobj's `MISSING_INDEX`).
const MISSING: u32 = u32::MAX;
/// An index no file can reach: relative past the start, or 2^32 - 2 and more.
const BEYOND: u32 = u32::MAX - 1;
/// No output vertex at this position yet in the model being read.
const NONE: u32 = u32::MAX;

/// A face corner: its position, texture coordinate and normal index (0-based, [`MISSING`]).
type Key = [u32; 3];

/// Why reading stopped.
pub(super) enum Stop {
    /// The file is not a valid OBJ (or has no triangles, or a bad coordinate).
    Model(ModelError),
    /// Reading the input failed.
    Io(io::Error),
    /// More bytes came than the limit given to [`read`].
    TooLarge,
}

impl From<ModelError> for Stop {
    fn from(e: ModelError) -> Self {
        Stop::Model(e)
    }
}

/// One model as tobj makes them: a run of faces with one material, its output vertices
/// `start..end`.
struct Model {
    start: usize,
    end: usize,
    material: Option<usize>,
    /// Every vertex has a texture coordinate (and the file has `vt` lines).
    has_uv: bool,
    /// Every vertex has a normal (and the file has `vn` lines).
    has_normals: bool,
}

/// The reader's state.
struct Obj<'a> {
    shown: &'a str,
    dir: &'a Path,
    /// The 1-based number of the line being read.
    line: u64,
    positions: Vec<[f32; 3]>,
    texcoords: Vec<[f32; 2]>,
    normals: Vec<[f32; 3]>,
    /// Vertex colour numbers read (`v x y z r g b`): unused, but tobj checks faces against them.
    color_floats: usize,
    /// The corners of every output vertex, in order.
    keys: Vec<Key>,
    triangles: Vec<[u32; 3]>,
    models: Vec<Model>,
    /// The model being read: its first output vertex, whether it has faces (points and lines
    /// count, as in tobj), its material.
    start: usize,
    has_faces: bool,
    material: Option<usize>,
    /// Per position: the first output vertex of this model at it, or [`NONE`].
    first_at: Vec<u32>,
    /// This model's other output vertices (a position with several uvs or normals, or one
    /// used before its `v` line).
    others: HashMap<Key, u32>,
    /// This model's output vertices whose indices were out of range when their face was read,
    /// with the face's line (for the message, if they still are when the model ends).
    suspects: Vec<(u32, u64)>,
    /// This model's first face without corners: its line, and the output vertices before it.
    empty_face: Option<(u64, usize)>,
    /// Scratch: the corners of the face being read, and their output vertices.
    corners: Vec<Key>,
    indices: Vec<u32>,
    materials: Vec<tobj::Material>,
    material_ids: HashMap<String, usize>,
    /// The last material library that failed, and why when it could not be read.
    mtl_failure: Option<E>,
    mtl_reason: Option<String>,
}

/// Reads an OBJ text from `input` line by line and builds its mesh; `shown` names it in
/// messages, its MTL and texture paths are relative to `dir`, and more than `max_bytes` of
/// input is [`Stop::TooLarge`]. `counts` ([`super::count::count`]) sizes the arrays. A UTF-8
/// byte order mark at the start is skipped.
pub(super) fn read(
    mut input: impl BufRead,
    shown: &str,
    dir: &Path,
    max_bytes: u64,
    counts: Counts,
) -> Result<ModelMesh, Stop> {
    let mut obj = Obj::new(shown, dir);
    reserve(&mut obj.positions, counts.positions);
    reserve(&mut obj.first_at, counts.positions);
    reserve(&mut obj.texcoords, counts.texcoords);
    reserve(&mut obj.normals, counts.normals);
    reserve(&mut obj.triangles, counts.triangles);
    // As many output vertices as positions: exact for a file whose faces give only `v` (one
    // model), a start for the others.
    reserve(&mut obj.keys, counts.positions);
    let mut buf = Vec::new();
    let mut total = 0u64;
    loop {
        buf.clear();
        let n = input.read_until(b'\n', &mut buf).map_err(Stop::Io)?;
        if n == 0 {
            break;
        }
        total += n as u64;
        if total > max_bytes {
            return Err(Stop::TooLarge);
        }
        obj.line += 1;
        // As `BufRead::lines` (what tobj reads): without the `\n` or `\r\n` at the end.
        if buf.last() == Some(&b'\n') {
            buf.pop();
            if buf.last() == Some(&b'\r') {
                buf.pop();
            }
        }
        let Ok(mut text) = std::str::from_utf8(&buf) else {
            return Err(obj.parse_error(format!(
                "it is not a readable text OBJ file (binary data or invalid UTF-8 at line {})",
                obj.line
            )));
        };
        if obj.line == 1 {
            text = text.strip_prefix('\u{feff}').unwrap_or(text);
        }
        obj.read_line(text)?;
    }
    obj.end_model()?;
    obj.finish()
}

/// The first `N` words as f32 numbers (tobj's `parse_floatn`: more words are ignored).
fn floats<const N: usize>(words: &mut std::str::SplitWhitespace) -> Option<[f32; N]> {
    let mut out = [0.0; N];
    for x in &mut out {
        *x = words.next()?.parse().ok()?;
    }
    Some(out)
}

/// One index of a face corner as tobj reads it: negative counts back from the `count`
/// defined so far, else 1-based; the result taken as an unsigned number (so `0` and `-(count
/// + 1)` are [`MISSING`], and anything out of reach is [`BEYOND`]).
fn resolve(x: isize, count: usize) -> u32 {
    let (x, count) = (x as i128, count as i128);
    let r = if x < 0 { count + x } else { x - 1 };
    if r == -1 {
        MISSING
    } else if r < 0 || r >= i128::from(BEYOND) {
        BEYOND
    } else {
        r as u32
    }
}

/// A face corner `v`, `v/vt`, `v//vn` or `v/vt/vn` (tobj's `VertexIndices::parse`: empty
/// fields are missing, a fourth field must be empty), with the numbers of positions,
/// texture coordinates and normals defined so far. `None` when it is malformed.
fn corner(word: &str, counts: [usize; 3]) -> Option<Key> {
    let mut key = [MISSING; 3];
    for (i, part) in word.split('/').enumerate() {
        if part.is_empty() {
            continue;
        }
        let x: isize = part.parse().ok()?;
        *key.get_mut(i)? = resolve(x, *counts.get(i)?);
    }
    Some(key)
}

impl<'a> Obj<'a> {
    fn new(shown: &'a str, dir: &'a Path) -> Self {
        Obj {
            shown,
            dir,
            line: 0,
            positions: Vec::new(),
            texcoords: Vec::new(),
            normals: Vec::new(),
            color_floats: 0,
            keys: Vec::new(),
            triangles: Vec::new(),
            models: Vec::new(),
            start: 0,
            has_faces: false,
            material: None,
            first_at: Vec::new(),
            others: HashMap::new(),
            suspects: Vec::new(),
            empty_face: None,
            corners: Vec::new(),
            indices: Vec::new(),
            materials: Vec::new(),
            material_ids: HashMap::new(),
            mtl_failure: None,
            mtl_reason: None,
        }
    }

    /// A parse error with `reason`.
    fn parse_error(&self, reason: String) -> Stop {
        Stop::Model(ModelError::Parse {
            path: self.shown.to_string(),
            reason,
        })
    }

    /// tobj's error `e`, at `line` when known.
    fn error_at(&self, line: Option<u64>, e: E, detail: &str) -> Stop {
        let what = explain(&e);
        self.parse_error(match line {
            Some(n) => format!("line {n}: {what}{detail}"),
            None => format!("{what}{detail}"),
        })
    }

    /// tobj's error `e` at the line being read.
    fn error(&self, e: E) -> Stop {
        self.error_at(Some(self.line), e, "")
    }

    /// Reads one line (without its line break).
    fn read_line(&mut self, line: &str) -> Result<(), Stop> {
        let mut words = line.split_whitespace();
        match words.next() {
            None | Some("#") => {}
            Some("v") => self.position(words)?,
            Some("vt") => {
                let t = floats::<2>(&mut words).ok_or_else(|| self.error(E::TexcoordParseError))?;
                self.texcoords.push(t);
            }
            Some("vn") => {
                let n = floats::<3>(&mut words).ok_or_else(|| self.error(E::NormalParseError))?;
                self.normals.push(n);
            }
            Some("f") | Some("l") => self.face(words)?,
            Some("o") | Some("g") => {
                if self.has_faces {
                    self.end_model()?;
                }
            }
            Some("mtllib") => {
                // As tobj: everything after the first space is the name (it may hold spaces).
                let name = line.split_once(' ').unwrap_or_default().1.trim();
                self.load_mtl(Path::new(name));
            }
            Some("usemtl") => {
                let name = line.split_once(' ').unwrap_or_default().1.trim();
                if name.is_empty() {
                    return Err(self.parse_error(format!(
                        "line {}: a `usemtl` line names no material",
                        self.line
                    )));
                }
                let id = self.material_ids.get(name).copied();
                if self.material != id && self.has_faces {
                    self.end_model()?;
                }
                self.material = id;
            }
            Some(_) => {}
        }
        Ok(())
    }

    /// A `v` line: x y z, then nothing, a w that divides them, or an r g b colour.
    fn position(&mut self, mut words: std::str::SplitWhitespace) -> Result<(), Stop> {
        let mut p = floats::<3>(&mut words).ok_or_else(|| self.error(E::PositionParseError))?;
        if let Some(first) = words.next() {
            match (words.next(), words.next()) {
                (None, _) => {
                    let w: f32 = first
                        .parse()
                        .map_err(|_| self.error(E::PositionParseError))?;
                    if w == 0.0 {
                        return Err(self.error(E::ScalingByZeroError));
                    }
                    for c in &mut p {
                        *c /= w;
                    }
                }
                (Some(_), None) => return Err(self.error(E::ColorParseError)),
                (Some(second), Some(third)) => {
                    if words.next().is_some() {
                        return Err(self.error(E::ColorParseError));
                    }
                    // tobj keeps the numbers up to the first bad one.
                    for c in [first, second, third] {
                        if c.parse::<f32>().is_err() {
                            break;
                        }
                        self.color_floats += 1;
                    }
                }
            }
        }
        if self.positions.len() >= BEYOND as usize {
            return Err(self.parse_error(format!(
                "line {}: more vertices than barylab can index ({BEYOND})",
                self.line
            )));
        }
        self.positions.push(p);
        self.first_at.push(NONE);
        Ok(())
    }

    /// An `f` (or `l`) line: its corners, and the fan of triangles from its first corner.
    fn face(&mut self, words: std::str::SplitWhitespace) -> Result<(), Stop> {
        let counts = [
            self.positions.len(),
            self.texcoords.len(),
            self.normals.len(),
        ];
        self.corners.clear();
        for word in words {
            let key = corner(word, counts).ok_or_else(|| self.error(E::FaceParseError))?;
            self.corners.push(key);
        }
        self.has_faces = true;
        match self.corners.len() {
            // tobj fails on it when the model ends (after the faces before it).
            0 => {
                if self.empty_face.is_none() {
                    self.empty_face = Some((self.line, self.keys.len()));
                }
            }
            // A point or a line: dropped, unchecked.
            1 | 2 => {}
            n => {
                self.indices.clear();
                for k in 0..n {
                    let i = self.vertex(self.corners[k])?;
                    self.indices.push(i);
                }
                let first = self.indices[0];
                for k in 2..n {
                    self.triangles
                        .push([first, self.indices[k - 1], self.indices[k]]);
                }
            }
        }
        Ok(())
    }

    /// The output vertex of a corner in this model: the one made for the same (v, vt, vn)
    /// before, or a new one.
    fn vertex(&mut self, key: Key) -> Result<u32, Stop> {
        let v = key[0] as usize;
        let first = self.first_at.get(v).copied();
        if let Some(i) = first
            && i != NONE
            && self.keys[i as usize] == key
        {
            return Ok(i);
        }
        if !self.others.is_empty()
            && let Some(&i) = self.others.get(&key)
        {
            return Ok(i);
        }
        if self.keys.len() >= BEYOND as usize {
            return Err(self.parse_error(format!(
                "line {}: more vertices than barylab can index ({BEYOND})",
                self.line
            )));
        }
        let i = self.keys.len() as u32;
        self.keys.push(key);
        if first == Some(NONE) {
            self.first_at[v] = i;
        } else {
            self.others.insert(key, i);
        }
        if self.problem(key).is_some() {
            self.suspects.push((i, self.line));
        }
        Ok(i)
    }

    /// What is wrong with a corner's indices now, in tobj's order (vertex, texture
    /// coordinate, normal, vertex colour), with the numbers defined.
    fn problem(&self, [v, vt, vn]: Key) -> Option<(E, String)> {
        let (p, t, n) = (
            self.positions.len(),
            self.texcoords.len(),
            self.normals.len(),
        );
        if v as usize >= p {
            Some((E::FaceVertexOutOfBounds, format!(" ({p} defined)")))
        } else if t > 0 && vt != MISSING && vt as usize >= t {
            Some((E::FaceTexCoordOutOfBounds, format!(" ({t} defined)")))
        } else if n > 0 && vn != MISSING && vn as usize >= n {
            Some((E::FaceNormalOutOfBounds, format!(" ({n} defined)")))
        } else if self.color_floats > 0 && 3 * v as usize + 2 >= self.color_floats {
            Some((E::FaceColorOutOfBounds, String::new()))
        } else {
            None
        }
    }

    /// Ends the model being read: checks its vertices' indices (tobj's export), and starts a
    /// new one.
    fn end_model(&mut self) -> Result<(), Stop> {
        let end = self.keys.len();
        let checked = self.empty_face.map_or(end, |(_, before)| before);
        let mut has_uv = !self.texcoords.is_empty();
        let mut has_normals = !self.normals.is_empty();
        for i in self.start..checked {
            let key = self.keys[i];
            if let Some((e, detail)) = self.problem(key) {
                let line = self
                    .suspects
                    .binary_search_by_key(&(i as u32), |s| s.0)
                    .ok()
                    .map(|k| self.suspects[k].1);
                return Err(self.error_at(line, e, &detail));
            }
            has_uv &= key[1] != MISSING;
            has_normals &= key[2] != MISSING;
        }
        if let Some((line, _)) = self.empty_face {
            return Err(self.error_at(Some(line), E::InvalidPolygon, ""));
        }
        // A model without vertices (only points and lines, or an `o`, `g` or `usemtl` line
        // after the last face) adds nothing.
        if end > self.start {
            self.models.push(Model {
                start: self.start,
                end,
                material: self.material,
                has_uv,
                has_normals,
            });
        }
        for key in &self.keys[self.start..end] {
            if let Some(slot) = self.first_at.get_mut(key[0] as usize) {
                *slot = NONE;
            }
        }
        if !self.others.is_empty() {
            self.others = HashMap::new();
        }
        self.suspects.clear();
        self.has_faces = false;
        self.start = end;
        Ok(())
    }

    /// An `mtllib` line: reads the library (a regular file beside the OBJ, at most its cap)
    /// with tobj, its materials after those loaded before (a later name wins).
    fn load_mtl(&mut self, name: &Path) {
        let path = self.dir.join(name);
        let loaded = match files::read_regular(&path, FileKind::Material) {
            Ok(text) => {
                let text = files::strip_bom(&text);
                let loaded = tobj::load_mtl_buf(&mut &text[..]);
                if loaded.is_err()
                    && let Some((n, line)) = super::first_bad_mtl_line(text)
                {
                    self.mtl_reason = Some(format!(
                        "{} line {n}: `{}` cannot be read",
                        files::shown(&path),
                        files::text(line.trim())
                    ));
                }
                loaded
            }
            Err(e) => {
                self.mtl_reason = Some(e.to_string());
                Err(E::OpenFileFailed)
            }
        };
        match loaded {
            Ok((mut materials, ids)) => {
                let offset = self.materials.len();
                self.materials.append(&mut materials);
                for (name, id) in ids {
                    self.material_ids.insert(name, id + offset);
                }
            }
            Err(e) => self.mtl_failure = Some(e),
        }
    }

    /// Builds the mesh from the models read: f64 positions (each checked), uvs and normals
    /// where every vertex has them, colours from each model's material.
    fn finish(mut self) -> Result<ModelMesh, Stop> {
        let shown = self.shown.to_string();
        let mut out = ModelMesh::default();
        if self.triangles.is_empty() {
            return Err(ModelError::NoTriangles { path: shown }.into());
        }
        // As tobj: a library that failed matters only when none gave materials.
        if self.materials.is_empty()
            && let Some(e) = self.mtl_failure
        {
            let why = self.mtl_reason.take().unwrap_or_else(|| explain(&e));
            out.notes.push(format!(
                "the material library (mtllib) of {shown} could not be loaded ({why}); \
                 drawing without materials"
            ));
        }
        let all_have_uv = self.models.iter().all(|m| m.has_uv);
        let all_have_normals = self.models.iter().all(|m| m.has_normals);
        let n = self.keys.len();
        out.positions.reserve_exact(n);
        out.uvs.reserve_exact(n);
        out.colors.reserve_exact(n);
        if all_have_normals {
            out.normals.reserve_exact(n);
        }
        for m in &self.models {
            let material = m.material.and_then(|id| self.materials.get(id));
            let color = material_look(material, self.dir, &mut out.diffuse_texture);
            for &[v, vt, vn] in &self.keys[m.start..m.end] {
                // Checked when the model ended: every index here is in range.
                let p = DVec3::from(self.positions[v as usize].map(f64::from));
                if !p.is_finite() || p.abs().max_element() > MAX_MODEL_COORD {
                    return Err(ModelError::BadCoordinate {
                        path: shown,
                        index: v as usize + 1,
                        what: if p.is_finite() {
                            format!("larger than {MAX_MODEL_COORD:e} in magnitude")
                        } else {
                            "not a finite number".into()
                        },
                    }
                    .into());
                }
                out.positions.push(p);
                out.uvs.push(if m.has_uv {
                    Vec2::from(self.texcoords[vt as usize])
                } else {
                    Vec2::ZERO
                });
                out.colors.push(color);
                if all_have_normals {
                    let n = DVec3::from(self.normals[vn as usize].map(f64::from));
                    out.normals.push(n.normalize_or_zero());
                }
            }
        }
        // The file's arrays go before the normals are computed.
        out.triangles = std::mem::take(&mut self.triangles);
        drop(self);
        finish(&mut out, all_have_uv, all_have_normals, &shown);
        Ok(out)
    }
}
