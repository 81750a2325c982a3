//! Drawing one set-up triangle into one band of rows: the per-pixel kernel ([`rasterize`]:
//! coverage by edge functions or the scanline, the depth test, shading and the per-pixel
//! buffers) and the glue to the SIMD lanes (which shadings they draw, where they write in a
//! band). The full render ([`render`](super::render)) and the fast path
//! ([`fast`](super::fast)) both draw every triangle through here.

use super::framebuffer::{RowBand, depth_passes};
use super::interpolate::{self, Fragment};
use super::lanes::{self, DifferenceTarget, LaneShading, Target, UvTarget, VectorLevel};
use super::settings::Rasterizer;
use super::setup::{TriangleSetup, pixel_centre, sample_point};
use super::shade::{ShadeParams, Shading, shade, texture_footprint};
use super::texture::{Filter, Texture, texel_difference};

/// What the lanes can draw of these shading parameters (into colour and depth, and into the
/// triangle and uv or the texel-difference buffers where a band has them): every shading but
/// trilinear texture lookups in the edge-function lanes (trilinear goes per pixel, after
/// block rejection); the scanline lanes draw the same without the wireframe, which goes per
/// pixel, into colour and depth only.
pub(super) fn lane_shading(params: &ShadeParams) -> Option<LaneShading> {
    let color = match params.shading {
        Shading::Texture => matches!(params.filter, Filter::Nearest | Filter::Bilinear)
            .then_some(lanes::LaneColor::Texture)?,
        Shading::VertexColor => lanes::LaneColor::VertexColor,
        Shading::Barycentric => lanes::LaneColor::Barycentric,
        Shading::Depth => lanes::LaneColor::Depth(params.depth_range.0, params.depth_range.1),
        Shading::Normal => lanes::LaneColor::Normal,
        Shading::Lambert => lanes::LaneColor::Lambert,
    };
    Some(LaneShading {
        mode: params.mode,
        color,
        filter: params.filter,
        wrap: params.wrap,
        wireframe: params.wireframe,
    })
}

/// Where the lanes write in a band: colour and depth, and the triangle and uv buffers or the
/// texel-difference buffer (of `texture`'s size) when the band has them.
fn lane_target<'b>(band: &'b mut RowBand<'_>, source: u32, texture: &Texture) -> Target<'b> {
    let uvs = !band.uv_affine.is_empty();
    let diffs = !band.texel_difference.is_empty();
    Target {
        y0: band.y0,
        width: band.width,
        color: band.color,
        depth: band.depth,
        uv: uvs.then_some(UvTarget {
            source,
            triangle: band.triangle,
            uv_affine: band.uv_affine,
            uv_perspective: band.uv_perspective,
        }),
        difference: diffs.then_some(DifferenceTarget {
            size: [texture.width() as f32, texture.height() as f32],
            out: band.texel_difference,
        }),
    }
}

/// Draws the rows of an [`exact`](lanes::LaneTriangle::exact) lane triangle (made for the
/// shading of `lanes`) that fall in a band without per-pixel buffers, with the
/// edge-function lanes.
pub(super) fn draw_lanes(
    tri: &lanes::LaneTriangle,
    source: u32,
    lanes: &lanes::Lanes<'_>,
    band: &mut RowBand<'_>,
) {
    let Some(rows) = band.rows_of(&tri.bounds()) else {
        return;
    };
    let mut target = lane_target(band, source, lanes.texture());
    // With a shading, the lanes colour every covered sample themselves.
    lanes.edge_triangle(tri, rows, &mut target);
}

/// Whether the scanline lanes draw with this shading into a band without uv or per-pixel
/// buffers (every colour without the wireframe; the wireframe goes per pixel).
pub(super) fn scanline_lanes_apply(shading: &LaneShading) -> bool {
    !shading.wireframe
}

/// Draws the rows of a lane triangle (made for the shading of `lanes`, without uv) that fall
/// in a band without uv or per-pixel buffers, with the scanline lanes.
pub(super) fn draw_scanline_lanes(
    tri: &lanes::LaneTriangle,
    lanes: &lanes::Lanes<'_>,
    band: &mut RowBand<'_>,
) {
    let Some(rows) = band.rows_of(&tri.bounds()) else {
        return;
    };
    let mut target = Target {
        y0: band.y0,
        width: band.width,
        color: band.color,
        depth: band.depth,
        uv: None,
        difference: None,
    };
    lanes.scanline_triangle(tri, rows, &mut target);
}

/// Writes a fragment that passed the depth test at index `i` of a band into the per-pixel
/// buffers the band has beyond colour and depth: the texel difference of its two uvs (for a
/// texture of `texels` texels), the triangle and both uvs, the facing, both weights and 1/w.
pub(super) fn write_buffers(
    band: &mut RowBand<'_>,
    i: usize,
    (setup, source): (&TriangleSetup, u32),
    frag: &Fragment,
    texels: (u32, u32),
) {
    if !band.texel_difference.is_empty() {
        band.texel_difference[i] = texel_difference(
            frag.affine.uv().to_array(),
            frag.correct.uv().to_array(),
            texels,
        );
    }
    if !band.uv_affine.is_empty() {
        band.triangle[i] = source;
        band.uv_affine[i] = frag.affine.uv().to_array();
        band.uv_perspective[i] = frag.correct.uv().to_array();
    }
    if band.has_aovs() {
        band.facing[i] = setup.facing;
        band.weights_screen[i] = frag.affine.bary();
        band.weights_perspective[i] = frag.correct.bary();
        band.inv_w[i] = frag.inv_w as f32;
    }
}

/// Visits every covered pixel centre of one set-up triangle within a band, depth-tests and
/// writes it; where the band has no per-pixel buffers beyond the uv or texel-difference ones,
/// the lanes draw at the vector level `vector`.
pub(super) fn rasterize(
    setup: &TriangleSetup,
    source: u32,
    texture: &Texture,
    params: &ShadeParams,
    (rasterizer, vector): (Rasterizer, VectorLevel),
    band: &mut RowBand<'_>,
) {
    let b = setup.bounds;
    let Some((y_start, y_end)) = band.rows_of(&b) else {
        return;
    };
    let wire = if params.wireframe {
        setup.source_weight_gradients()
    } else {
        [glam::DVec2::ZERO; 3]
    };
    let aovs = band.has_aovs();
    let uvs = !band.uv_affine.is_empty();
    let diffs = !band.texel_difference.is_empty();
    let texels = (texture.width(), texture.height());
    // Depth test, buffers and shading: the same for both rasterizers.
    let write = |band: &mut RowBand<'_>, x: u32, y: u32, frag: &Fragment| {
        let mut frag = *frag;
        texture_footprint(&mut frag, setup, (x, y), params, texture);
        let i = (y - band.y0) as usize * band.width as usize + x as usize;
        let depth = frag.depth as f32;
        if !depth_passes(depth, band.depth[i]) {
            return;
        }
        band.depth[i] = depth;
        // A difference render shades nothing (`Buffers::DepthDifference`).
        if !diffs {
            band.color[i] = shade(&frag, texture, params, &wire);
        }
        write_buffers(band, i, (setup, source), &frag, texels);
    };
    let lane_shading = lane_shading(params);
    if !aovs {
        match (rasterizer, lane_shading) {
            (Rasterizer::EdgeFunction, shading)
                if let Some(tri) = Some(lanes::LaneTriangle::of(setup, shading, uvs || diffs))
                    .filter(lanes::LaneTriangle::exact) =>
            {
                let mut per_pixel = Vec::new();
                let mut target = lane_target(band, source, texture);
                lanes::edge_triangle(
                    &tri,
                    (y_start, y_end),
                    texture,
                    (shading, vector),
                    &mut target,
                    &mut |x, y, e| per_pixel.push((x, y, e)),
                );
                let planes = interpolate::Planes::of(setup);
                for (x, y, e) in per_pixel {
                    let p = pixel_centre(x, y);
                    if let Some(frag) = interpolate::fragment_with_planes(setup, &planes, e, p) {
                        write(band, x, y, &frag);
                    }
                }
                return;
            }
            (Rasterizer::Scanline, Some(shading))
                if !uvs && !diffs && scanline_lanes_apply(&shading) =>
            {
                let tri = lanes::LaneTriangle::of(setup, Some(shading), false);
                draw_scanline_lanes(&tri, &lanes::Lanes::new(texture, shading, vector), band);
                return;
            }
            _ => {}
        }
    }
    match rasterizer {
        Rasterizer::EdgeFunction => {
            let planes = interpolate::Planes::of(setup);
            for y in y_start..=y_end {
                for x in b.x0..=b.x1 {
                    let e = setup.edge_values(sample_point(x, y));
                    if !setup.covers(&e) {
                        continue;
                    }
                    let p = pixel_centre(x, y);
                    if let Some(frag) = interpolate::fragment_with_planes(setup, &planes, e, p) {
                        write(band, x, y, &frag);
                    }
                }
            }
        }
        Rasterizer::Scanline => {
            super::scanline::rasterize_rows(
                setup,
                y_start..y_end + 1,
                &mut |x, y, frag: &Fragment| write(band, x, y, frag),
            );
        }
    }
}
