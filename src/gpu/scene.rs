//! A barylab mesh as OpenGL gets it: clip coordinates rounded to f32, the texture's bytes.

use crate::raster::{ClipMesh, Texture, Wrap};

/// What to draw: clip-space positions and uv/colour per vertex, the triangles, the texture.
pub struct GlScene {
    /// Image width in pixels (the viewport).
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Per vertex: clip x, y, z, w, u, v, r, g, b (f32, as the GPU gets them).
    pub vertices: Vec<[f32; 9]>,
    /// Three vertex indices per triangle, in the mesh's order.
    pub indices: Vec<u32>,
    /// Texture width in texels.
    pub texture_width: u32,
    /// Texture height in texels.
    pub texture_height: u32,
    /// RGBA8, row 0 first (t = 0, barylab's texel row 0).
    pub texels: Vec<u8>,
    /// Mipmap levels 1, 2, ... down to 1x1: barylab's own (the texels its trilinear filter
    /// reads).
    pub levels: Vec<super::GlLevel>,
    /// The largest anisotropy for trilinear filtering (1 = off).
    pub max_anisotropy: u32,
    /// Texture wrap mode.
    pub wrap: Wrap,
    /// Clear colour, RGBA8.
    pub background: [u8; 4],
}

impl GlScene {
    /// The mesh as the GPU gets it: clip coordinates rounded to f32.
    pub fn new(
        mesh: &ClipMesh,
        texture: &Texture,
        width: u32,
        height: u32,
        wrap: Wrap,
        background: [u8; 4],
    ) -> Self {
        let vertices = mesh
            .vertices
            .iter()
            .map(|v| {
                [
                    v.clip.x as f32,
                    v.clip.y as f32,
                    v.clip.z as f32,
                    v.clip.w as f32,
                    v.uv.x,
                    v.uv.y,
                    v.color.x,
                    v.color.y,
                    v.color.z,
                ]
            })
            .collect();
        let texels = super::mipmaps::level_bytes(texture, 0).texels;
        let levels = (1..texture.levels())
            .map(|k| super::mipmaps::level_bytes(texture, k))
            .collect();
        Self {
            width,
            height,
            vertices,
            indices: mesh.triangles.iter().flatten().copied().collect(),
            texture_width: texture.width(),
            texture_height: texture.height(),
            texels,
            levels,
            max_anisotropy: 1,
            wrap,
            background,
        }
    }

    /// The scene with anisotropic filtering up to `n` (1 = off) for trilinear lookups.
    pub fn with_anisotropy(self, n: u32) -> Self {
        Self {
            max_anisotropy: n,
            ..self
        }
    }
}

/// A copy of `mesh` whose clip coordinates are rounded to f32, so that barylab draws exactly
/// the coordinates OpenGL gets.
pub fn mesh_at_f32(mesh: &ClipMesh) -> ClipMesh {
    let mut m = mesh.clone();
    for v in &mut m.vertices {
        v.clip = v.clip.as_vec4().as_dvec4();
    }
    m
}
