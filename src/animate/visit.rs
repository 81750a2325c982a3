//! The order in which each rasterizer visits the pixels it covers, for the `fill-edge` and
//! `fill-scanline` sweeps. Both take the triangles as [`prepare_triangles`] sets them up (the
//! renderer's own set-up, fill rule and tie rule), in mesh order, and within one triangle:
//!
//! - **scanline**: rows top to bottom over the triangle's bounds; on each row the exact span
//!   of [`row_span`] (the scanline rasterizer's own span ends), left to right;
//! - **edge functions**: the bounding box walked in blocks of [`LANES`] columns by
//!   [`BLOCK_ROWS`] rows (rows of blocks top to bottom, blocks left to right, then the block's
//!   rows), as `lanes::edge_triangle` walks it; in a block, the pixels whose sample passes
//!   the three edge functions ([`TriangleSetup::covers`]), left to right.
//!
//! A pixel a later triangle draws again appears again. Both orders visit the same pixels
//! (coverage is identical); only the order differs.

use crate::raster::lanes::{BLOCK_ROWS, LANES};
use crate::raster::render::{RenderError, prepare_triangles};
use crate::raster::scanline::row_span;
use crate::raster::settings::Rasterizer;
use crate::raster::setup::{TriangleSetup, sample_point};
use crate::raster::{ClipMesh, RenderSettings};

/// The pixels `[column, row]` each rasterizer visits, in its order (see the module's text).
pub fn visit_order(
    mesh: &ClipMesh,
    settings: &RenderSettings,
    rasterizer: Rasterizer,
) -> Result<Vec<[u32; 2]>, RenderError> {
    let triangles = prepare_triangles(mesh, settings)?;
    let mut out = Vec::new();
    for setup in triangles.iter().flat_map(|t| t.setups.iter()) {
        match rasterizer {
            Rasterizer::Scanline => scanline_order(setup, &mut out),
            Rasterizer::EdgeFunction => edge_order(setup, &mut out),
        }
    }
    Ok(out)
}

/// One triangle's pixels in the scanline rasterizer's order.
fn scanline_order(setup: &TriangleSetup, out: &mut Vec<[u32; 2]>) {
    let b = setup.bounds;
    if b.y0 > b.y1 {
        return;
    }
    for row in b.y0..=b.y1 {
        if let Some((lo, hi)) = row_span(setup, row) {
            out.extend((lo..=hi).map(|x| [x, row]));
        }
    }
}

/// One triangle's pixels in the edge-function rasterizer's block order.
fn edge_order(setup: &TriangleSetup, out: &mut Vec<[u32; 2]>) {
    let b = setup.bounds;
    if b.y0 > b.y1 || b.x0 > b.x1 {
        return;
    }
    let lanes = LANES as u32;
    let mut by = b.y0;
    while by <= b.y1 {
        let by_end = (by + BLOCK_ROWS - 1).min(b.y1);
        let mut bx = b.x0;
        while bx <= b.x1 {
            let bx_end = (bx + lanes - 1).min(b.x1);
            for y in by..=by_end {
                for x in bx..=bx_end {
                    if setup.covers(&setup.edge_values(sample_point(x, y))) {
                        out.push([x, y]);
                    }
                }
            }
            bx += lanes;
        }
        by = by_end + 1;
    }
}
