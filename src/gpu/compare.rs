//! barylab's images and values against the GPU's, pixel by pixel.

use std::path::Path;

use super::{GlScene, Gpu, MODES, Output, mesh_at_f32};
use crate::raster::{ClipMesh, Filter, Interpolation, Shading, Texture};
use crate::scene::Scene;

/// How barylab's image of a scene compares with llvmpipe's.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Comparison {
    /// Pixels compared, `width * height`.
    pub pixels: usize,
    /// Pixels covered in one image and not in the other.
    pub coverage_mismatch: Vec<(u32, u32)>,
    /// Pixels covered by different source triangles.
    pub triangle_mismatch: Vec<(u32, u32)>,
    /// Covered pixels whose colour differs in any channel.
    pub color_differing: usize,
    /// The largest difference of one channel.
    pub max_channel_diff: u8,
    /// Where that largest difference is (x, y).
    pub max_at: Option<(u32, u32)>,
    /// For nearest filtering (when barylab's uv is given): the largest distance, in texels,
    /// from a differing pixel's sample point to the nearest texel boundary along u or v.
    /// Near 0 means every difference is a tie that rounding decides either way.
    pub max_boundary_distance: f32,
}

/// Distance, in texels, from texel coordinate `s = u * size` to the nearest texel boundary
/// (an integer): `|s - round(s)|`.
pub fn boundary_distance(s: f32) -> f32 {
    (s - s.round()).abs()
}

/// Compares barylab's triangle ids and colours with llvmpipe's (`gl_ids`: `TriangleId`
/// output; `gl_colors`: the colour output), pixel by pixel.
/// `nearest_uv`: barylab's uv per pixel and the texture size, for nearest filtering.
pub fn compare(
    width: u32,
    ours_triangle: &[u32],
    ours_color: &[[u8; 4]],
    gl_ids: &[[u8; 4]],
    gl_colors: &[[u8; 4]],
    nearest_uv: Option<(&[[f32; 2]], u32, u32)>,
) -> Comparison {
    let mut c = Comparison {
        pixels: ours_color.len(),
        ..Comparison::default()
    };
    for (k, (((&tri, ours), id), theirs)) in ours_triangle
        .iter()
        .zip(ours_color)
        .zip(gl_ids)
        .zip(gl_colors)
        .enumerate()
    {
        let xy = ((k as u32) % width, (k as u32) / width);
        let gl_id = u32::from_le_bytes(*id);
        let ours_covered = tri != crate::raster::NO_TRIANGLE;
        if ours_covered != (gl_id != 0) {
            c.coverage_mismatch.push(xy);
            continue;
        }
        if !ours_covered {
            continue;
        }
        if gl_id != tri + 1 {
            c.triangle_mismatch.push(xy);
        }
        let diff = (0..4)
            .map(|i| ours[i].abs_diff(theirs[i]))
            .max()
            .unwrap_or(0);
        if diff > 0 {
            c.color_differing += 1;
            if let Some((uv, tw, th)) = nearest_uv {
                let [u, v] = uv[k];
                let d = boundary_distance(u * tw as f32).min(boundary_distance(v * th as f32));
                c.max_boundary_distance = c.max_boundary_distance.max(d);
            }
        }
        if diff > c.max_channel_diff {
            c.max_channel_diff = diff;
            c.max_at = Some(xy);
        }
    }
    c
}

/// Loads a scene (optionally resized) as the GPU gets it, with its render settings.
pub fn load(path: &Path, size: Option<(u32, u32)>) -> Result<(GlScene, Scene, Texture), String> {
    let (mut scene, base) =
        crate::scene::open_input(path).map_err(|e| format!("{}: {e}", path.display()))?;
    if let Some((w, h)) = size {
        scene.set_size(w, h);
    }
    let texture = scene
        .load_texture(&base)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let s = scene.settings();
    let mesh = mesh_at_f32(&scene.to_mesh());
    Ok((
        GlScene::new(&mesh, &texture, s.width, s.height, s.wrap, s.background),
        scene,
        texture,
    ))
}

/// One image of a scene drawn by both ([`compare_mesh`]): what was drawn, and how it compares.
pub struct SceneComparison {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// What the colours show: the texture or the vertex colour.
    pub output: Output,
    /// The texture filter (nearest for vertex colours).
    pub filter: Filter,
    /// Affine or perspective-correct interpolation.
    pub mode: Interpolation,
    /// The pixel-by-pixel comparison.
    pub result: Comparison,
}

/// Texture (nearest, bilinear) and vertex colour, affine and perspective.
pub fn compare_scene(
    lp: &mut Gpu,
    path: &Path,
    size: Option<(u32, u32)>,
) -> Result<Vec<SceneComparison>, String> {
    let (_, scene, texture) = load(path, size)?;
    compare_mesh(lp, &scene.to_mesh(), &texture, &scene.settings())
}

/// Draws `mesh` (its clip coordinates rounded to f32) with both, with the texture (nearest,
/// bilinear) and with the vertex colours, affine and perspective, and compares the images.
/// `base` gives the size, wrap and background.
pub fn compare_mesh(
    lp: &mut Gpu,
    mesh: &ClipMesh,
    texture: &Texture,
    base: &crate::raster::RenderSettings,
) -> Result<Vec<SceneComparison>, String> {
    let mesh = mesh_at_f32(mesh);
    lp.load_mesh(&mesh, texture, base)?;
    let mut out = Vec::new();
    for (output, shading, filters) in [
        (
            Output::Texture,
            Shading::Texture,
            &[Filter::Nearest, Filter::Bilinear][..],
        ),
        (
            Output::VertexColor,
            Shading::VertexColor,
            &[Filter::Nearest][..],
        ),
    ] {
        for &filter in filters {
            for mode in [Interpolation::Affine, Interpolation::Perspective] {
                let settings = crate::raster::RenderSettings {
                    filter,
                    mode,
                    shading,
                    wireframe: false,
                    ..*base
                };
                let ours =
                    crate::raster::render(&mesh, texture, &settings).map_err(|e| e.to_string())?;
                let ids = lp.render(Output::TriangleId, filter, mode)?;
                let colors = lp.render(output, filter, mode)?;
                let uv = match mode {
                    Interpolation::Affine => &ours.frame.uv_affine,
                    Interpolation::Perspective => &ours.frame.uv_perspective,
                };
                let nearest_uv = (output == Output::Texture && filter == Filter::Nearest)
                    .then_some((&uv[..], texture.width(), texture.height()));
                out.push(SceneComparison {
                    width: settings.width,
                    height: settings.height,
                    output,
                    filter,
                    mode,
                    result: compare(
                        settings.width,
                        &ours.frame.triangle,
                        &ours.frame.color,
                        &ids,
                        &colors,
                        nearest_uv,
                    ),
                });
            }
        }
    }
    Ok(out)
}

/// A pixel (x, y) with barylab's and llvmpipe's uv there.
pub type UvAt = ((u32, u32), [f32; 2], [f32; 2]);

/// How far barylab's interpolated values are from llvmpipe's, over the pixels both cover.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ValueComparison {
    /// The interpolation mode of both renders.
    pub mode: Interpolation,
    /// Pixels compared.
    pub pixels: usize,
    /// Largest |u - u_gl| or |v - v_gl|.
    pub uv: f64,
    /// Where it is, with both uv there.
    pub uv_at: Option<UvAt>,
    /// Largest |depth - depth_gl| (window depth).
    pub depth: f64,
    /// Largest |1/w - (1/w)_gl| relative to |(1/w)_gl|.
    pub inv_w_relative: f64,
}

/// Draws `mesh` (its clip coordinates rounded to f32) with both and compares uv, window depth
/// and 1/w, affine and perspective, over the pixels both cover.
pub fn compare_values(
    lp: &mut Gpu,
    mesh: &ClipMesh,
    texture: &Texture,
    base: &crate::raster::RenderSettings,
) -> Result<Vec<ValueComparison>, String> {
    let mesh = mesh_at_f32(mesh);
    lp.load_mesh(&mesh, texture, base)?;
    let mut out = Vec::new();
    for mode in MODES {
        let settings = crate::raster::RenderSettings { mode, ..*base };
        let ours = crate::raster::render(&mesh, texture, &settings).map_err(|e| e.to_string())?;
        let gl = lp.read_values(mode)?;
        let f = &ours.frame;
        let uv = match mode {
            Interpolation::Affine => &f.uv_affine,
            Interpolation::Perspective => &f.uv_perspective,
        };
        let mut c = ValueComparison {
            mode,
            ..ValueComparison::default()
        };
        for (k, g) in gl.iter().enumerate() {
            if f.triangle[k] == crate::raster::NO_TRIANGLE || g[3] <= 0.0 {
                continue;
            }
            c.pixels += 1;
            let d = |a: f32, b: f32| (f64::from(a) - f64::from(b)).abs();
            let duv = d(uv[k][0], g[0]).max(d(uv[k][1], g[1]));
            if duv > c.uv {
                c.uv = duv;
                let xy = ((k as u32) % settings.width, (k as u32) / settings.width);
                c.uv_at = Some((xy, uv[k], [g[0], g[1]]));
            }
            c.depth = c.depth.max(d(f.depth[k], g[2]));
            c.inv_w_relative = c.inv_w_relative.max(d(f.inv_w[k], g[3]) / f64::from(g[3]));
        }
        out.push(c);
    }
    Ok(out)
}
