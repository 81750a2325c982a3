//! Checking a scene and turning it into the clip-space mesh the rasterizer draws.

use super::*;

impl Scene {
    /// Checks everything a parse cannot: sizes, indices, the camera, finite numbers.
    pub fn validate(&self, path: &str) -> Result<(), SceneError> {
        let (w, h) = self.size();
        if w == 0 || h == 0 || w > MAX_IMAGE_SIZE || h > MAX_IMAGE_SIZE {
            return Err(invalid(
                path,
                &format!("image size {w}x{h} is outside 1..={MAX_IMAGE_SIZE} pixels per side"),
            ));
        }
        self.check_samples(path)?;
        if self.texture_name().trim().is_empty() {
            let builtins: Vec<&str> = crate::raster::texture::BuiltinTexture::ALL
                .iter()
                .map(|b| b.name())
                .collect();
            return Err(invalid(
                path,
                &format!(
                    "field `texture` is empty: name an image file (relative to the scene file) \
                     or a built-in texture ({})",
                    builtins.join(", ")
                ),
            ));
        }
        match self {
            Scene::World(s) => {
                s.camera
                    .validate()
                    .map_err(|e: CameraError| invalid(path, &format!("field `camera`: {e}")))?;
                for (k, c) in s.quad.iter().enumerate() {
                    if !c.position.is_finite() || !c.uv.is_finite() || !c.color.is_finite() {
                        return Err(invalid(
                            path,
                            &format!("field `quad[{k}]` has a number that is not finite"),
                        ));
                    }
                }
                if !(s.tilt.pitch_deg.is_finite() && s.tilt.yaw_deg.is_finite()) {
                    return Err(invalid(path, "field `tilt` is not finite"));
                }
            }
            Scene::Model(s) => {
                if let Some(cam) = &s.camera {
                    cam.validate()
                        .map_err(|e| invalid(path, &format!("field `camera`: {e}")))?;
                }
            }
            Scene::Clip(s) => {
                if let Some(k) = s.subdivide {
                    let total = s.triangles.len() as u64 * u64::from(k) * u64::from(k);
                    if k == 0 || total > MAX_SUBDIVIDED_TRIANGLES {
                        return Err(invalid(
                            path,
                            &format!(
                                "field `subdivide` is {k}: it must be at least 1 and give at most \
                                 {MAX_SUBDIVIDED_TRIANGLES} triangles ({} triangles x {k}^2 = {total})",
                                s.triangles.len()
                            ),
                        ));
                    }
                }
                let n = s.vertices.len();
                for (t, tri) in s.triangles.iter().enumerate() {
                    if let Some(&bad) = tri.iter().find(|&&i| i as usize >= n) {
                        return Err(invalid(
                            path,
                            &format!(
                                "field `triangles[{t}]` uses vertex {bad}, but there are only {n} vertices"
                            ),
                        ));
                    }
                }
            }
        }
        Ok(())
    }

    /// The matrix object -> world: rotation about the quad's centre (pitch about x, then yaw
    /// about y). Identity for the clip form.
    pub fn world_from_object(&self) -> DMat4 {
        match self {
            Scene::World(s) => {
                let centre = s.quad.iter().map(|c| c.position).sum::<DVec3>() / 4.0;
                DMat4::from_translation(centre)
                    * DMat4::from_rotation_y(s.tilt.yaw_deg.to_radians())
                    * DMat4::from_rotation_x(s.tilt.pitch_deg.to_radians())
                    * DMat4::from_translation(-centre)
            }
            Scene::Clip(_) | Scene::Model(_) => DMat4::IDENTITY,
        }
    }

    /// The mesh vertex indices of source triangle `i` (as in [`Scene::to_mesh`]), without
    /// building the mesh.
    pub fn triangle(&self, i: usize) -> Option<[u32; 3]> {
        match self {
            Scene::World(_) => [[0, 1, 2], [0, 2, 3]].get(i).copied(),
            Scene::Clip(s) => match s.subdivide {
                Some(n) if n > 1 => {
                    let per_source = n as usize * n as usize;
                    s.triangles.get(i / per_source)?;
                    let base = (i / per_source) * ((n as usize + 1) * (n as usize + 2) / 2);
                    Some(crate::raster::render::subdivided_triangle(
                        n,
                        base as u32,
                        (i % per_source) as u32,
                    ))
                }
                _ => s.triangles.get(i).copied(),
            },
            Scene::Model(s) => s.mesh.triangles.get(i).copied(),
        }
    }

    /// The number of vertices and triangles of [`Scene::to_mesh`], without building it.
    pub fn mesh_size(&self) -> (usize, usize) {
        match self {
            Scene::World(_) => (4, 2),
            Scene::Clip(s) => (s.vertices.len(), s.triangles.len()),
            Scene::Model(s) => (s.mesh.positions.len(), s.mesh.triangles.len()),
        }
    }

    /// The mesh the rasterizer draws: vertices in clip space.
    pub fn to_mesh(&self) -> ClipMesh {
        match self {
            Scene::World(s) => {
                let aspect = f64::from(s.width) / f64::from(s.height);
                let clip_from_object = s.camera.clip_from_world(aspect) * self.world_from_object();
                let view_from_object = s.camera.view_from_world() * self.world_from_object();
                let triangles = vec![[0, 1, 2], [0, 2, 3]];
                let positions = s.quad.map(|c| c.position);
                let normals = vertex_normals(&positions, &triangles);
                ClipMesh {
                    vertices: s
                        .quad
                        .iter()
                        .zip(&normals)
                        .map(|(c, n)| MeshVertex {
                            clip: clip_from_object * c.position.extend(1.0),
                            uv: c.uv,
                            color: c.color,
                            normal: view_normal(&view_from_object, *n),
                        })
                        .collect(),
                    triangles,
                }
            }
            Scene::Clip(s) => {
                let mesh = ClipMesh {
                    vertices: s
                        .vertices
                        .iter()
                        .map(|v| MeshVertex {
                            clip: v.clip,
                            uv: v.uv,
                            color: v.color,
                            // No view space: read as facing the viewer.
                            normal: Vec3::ZERO,
                        })
                        .collect(),
                    triangles: s.triangles.clone(),
                };
                match s.subdivide {
                    Some(n) if n > 1 => mesh.subdivided(n),
                    _ => mesh,
                }
            }
            Scene::Model(s) => {
                let aspect = f64::from(s.width) / f64::from(s.height);
                let clip_from_world = s.camera().clip_from_world(aspect);
                let view_from_world = s.camera().view_from_world();
                let m = &s.mesh;
                ClipMesh {
                    vertices: (0..m.positions.len())
                        .map(|i| MeshVertex {
                            clip: clip_from_world * m.positions[i].extend(1.0),
                            uv: m.uvs[i],
                            color: m.colors[i],
                            normal: view_normal(&view_from_world, m.normals[i]),
                        })
                        .collect(),
                    triangles: m.triangles.clone(),
                }
            }
        }
    }
}

/// An object-space normal in view space: `N n` normalized, with the normal matrix
/// `N = (M^-1)^T` of the upper-left 3x3 of `view_from_object` (normals stay perpendicular to
/// the surface under non-uniform scaling). Zero for a zero normal or a singular matrix.
///
/// ```
/// use barylab::scene::view_normal;
/// use glam::{DMat4, DVec3, Vec3};
/// // Scaling x by 2 turns the 45-degree normal (1, 1, 0) towards y: (1/2, 1, 0) normalized.
/// let n = view_normal(&DMat4::from_scale(DVec3::new(2.0, 1.0, 1.0)), DVec3::new(1.0, 1.0, 0.0));
/// let expected = DVec3::new(0.5, 1.0, 0.0).normalize().as_vec3();
/// assert!((n - expected).length() < 1e-6);
/// ```
pub fn view_normal(view_from_object: &DMat4, n: DVec3) -> Vec3 {
    let m = DMat3::from_mat4(*view_from_object);
    if m.determinant().abs() < f64::MIN_POSITIVE {
        return Vec3::ZERO;
    }
    (m.inverse().transpose() * n).normalize_or_zero().as_vec3()
}
