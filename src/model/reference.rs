//! The `tobj`-based OBJ loader barylab used before its streaming reader ([`super::obj`]):
//! kept as the independent reference the tests compare the streaming reader with. It holds
//! the whole text and every face in memory (tobj keeps each face as a 104-byte enum), so the
//! app does not use it.

use std::path::Path;

use glam::{DVec3, Vec2};

use super::{MAX_MODEL_COORD, ModelError, ModelMesh, explain, finish, material_look};
use crate::files::{self, FileKind};

/// Parses OBJ text with `tobj` (polygons triangulated, one index per vertex) and builds the
/// [`ModelMesh`] from its models, as barylab did before its streaming reader: the reference
/// for [`ModelMesh::from_obj`], which must give the same mesh for every file tobj accepts.
/// `shown` names the file in messages; its MTL and texture paths are relative to `dir`.
#[doc(hidden)]
pub fn from_obj_tobj(bytes: &[u8], shown: &str, dir: &Path) -> Result<ModelMesh, ModelError> {
    let parsed = parse_obj(files::strip_bom(bytes), shown, dir)?;
    from_parsed(parsed, shown.to_string(), dir)
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

/// Builds the mesh from tobj's models: their vertices one after the other, colours from each
/// model's material, uvs and normals where every vertex of every model has them.
fn from_parsed(parsed: ParsedObj, shown: String, dir: &Path) -> Result<ModelMesh, ModelError> {
    let ParsedObj {
        models,
        materials,
        mtl_error,
    } = parsed;
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
    for m in &models {
        let mesh = &m.mesh;
        let base = out.positions.len() as u32;
        let n = mesh.positions.len() / 3;
        // A model without vertices (only points and lines, or an `o`, `g` or `usemtl` line
        // after the last face) adds nothing: no uvs to lack, no texture.
        if n == 0 {
            continue;
        }
        let has_uv = mesh.texcoords.len() / 2 == n;
        all_have_uv &= has_uv;
        let has_normals = mesh.normals.len() / 3 == n;
        all_have_normals &= has_normals;
        let material = mesh.material_id.and_then(|id| materials.get(id));
        let color = material_look(material, dir, &mut out.diffuse_texture);
        for k in 0..n {
            let p = DVec3::new(
                f64::from(mesh.positions[3 * k]),
                f64::from(mesh.positions[3 * k + 1]),
                f64::from(mesh.positions[3 * k + 2]),
            );
            if !p.is_finite() || p.abs().max_element() > MAX_MODEL_COORD {
                // The streaming reader names the `v` line's number, which tobj does not keep.
                return Err(ModelError::BadCoordinate {
                    path: shown,
                    index: out.positions.len() + 1,
                    what: if p.is_finite() {
                        format!("larger than {MAX_MODEL_COORD:e} in magnitude")
                    } else {
                        "not a finite number".into()
                    },
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
            out.triangles.push([base + t[0], base + t[1], base + t[2]]);
        }
    }
    if out.triangles.is_empty() {
        return Err(ModelError::NoTriangles { path: shown });
    }
    finish(&mut out, all_have_uv, all_have_normals, &shown);
    Ok(out)
}
