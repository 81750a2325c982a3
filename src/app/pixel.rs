//! What the app knows about one pixel: the numbers the inspector shows and the triangle the
//! overlay marks. (Until the probe lands this reads the renderer's framebuffer.)

use glam::DVec2;

use super::canvas::CanvasOutput;
use super::overlay::{PixelMark, TriangleMark};
use crate::raster::{Interpolation, NO_TRIANGLE};

/// The derivation of one pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelReport {
    pub pixel: [u32; 2],
    pub triangle: Option<TriangleMark>,
    pub source_triangle: Option<u32>,
    pub weights_screen: Option<[f32; 3]>,
    pub weights_perspective: Option<[f32; 3]>,
    pub uv_affine: Option<[f32; 2]>,
    pub uv_perspective: Option<[f32; 2]>,
    pub inv_w: Option<f32>,
    pub depth: Option<f32>,
    pub color: [u8; 4],
}

impl PixelReport {
    /// The report of `pixel` in the render of `mode`.
    pub fn new(output: &CanvasOutput, mode: Interpolation, pixel: [u32; 2]) -> Option<Self> {
        let render = output.render(mode)?;
        let f = &render.frame;
        if pixel[0] >= f.width || pixel[1] >= f.height {
            return None;
        }
        let i = f.index(pixel[0], pixel[1]);
        let tri = f.triangle[i];
        let covered = tri != NO_TRIANGLE;
        let triangle = covered
            .then(|| {
                let prepared = render.triangles.get(tri as usize)?;
                let setup = prepared.setups.first()?;
                if prepared.setups.len() != 1 || !prepared.polygon?.unclipped() {
                    return None;
                }
                // Not `to_mesh()`: a model may have many thousand vertices.
                let m = output.scene.triangle(tri as usize)?;
                let ws = f.weights_screen[i];
                Some(TriangleMark {
                    vertices: setup.v.map(|v| DVec2::new(v.window.x, v.window.y)),
                    mesh_indices: m.map(|k| k as usize),
                    weights: ws.map(f64::from),
                })
            })
            .flatten();
        Some(Self {
            pixel,
            triangle,
            source_triangle: covered.then_some(tri),
            weights_screen: covered.then_some(f.weights_screen[i]),
            weights_perspective: covered.then_some(f.weights_perspective[i]),
            uv_affine: covered.then_some(f.uv_affine[i]),
            uv_perspective: covered.then_some(f.uv_perspective[i]),
            inv_w: covered.then_some(f.inv_w[i]),
            depth: covered.then_some(f.depth[i]),
            color: f.color[i],
        })
    }

    pub fn mark(&self) -> PixelMark {
        PixelMark {
            pixel: self.pixel,
            triangle: self.triangle,
        }
    }
}
