//! The pipeline driver: clip-space mesh in, framebuffer out.
//!
//! Per source triangle: clip (`clip`), divide and snap (`project`), fan the clipped polygon
//! into triangles and set them up (`setup`). Then, in submission order, every covered pixel
//! centre is interpolated (`interpolate`), depth-tested (less-than) and shaded (`shade`).
//! The probe calls [`prepare_triangle`] and [`interpolate::fragment`] exactly as done here.

use super::framebuffer::{Buffers, Framebuffer, NO_TRIANGLE};
use super::interpolate::{self, Fragment, Interpolation};
use super::lanes::{self, DifferenceTarget, LaneShading, Target, UvTarget};
use super::project::{MAX_IMAGE_SIZE, Viewport};
use super::setup::{Facing, TieRule, TriangleSetup, sample_point};
use super::shade::{ShadeParams, Shading, shade};
use super::texture::{Filter, Texture, Wrap};

use super::bands::{RowBand, bin_by_band};
use super::fast::FastMesh;
pub use super::mesh::{ClipMesh, MeshVertex, subdivided_triangle};
pub use super::prepare::{
    PreparedTriangle, TriangleStatus, prepare_all, prepare_all_with, prepare_triangle,
    prepare_triangle_with, prepare_triangles, source_vertices,
};

/// Which rasterizer visits the covered pixels. Both give the same coverage and values equal
/// up to floating-point rounding.
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, Hash, Default, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum Rasterizer {
    /// Every pixel centre in the bounding box is tested against the three edge functions and
    /// interpolated from its own weights.
    #[default]
    EdgeFunction,
    /// Spans per row, attributes stepped per pixel (the incremental scanline).
    Scanline,
}

/// How to draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderSettings {
    /// Image width in pixels (1 to [`MAX_IMAGE_SIZE`]).
    pub width: u32,
    /// Image height in pixels (1 to [`MAX_IMAGE_SIZE`]).
    pub height: u32,
    /// Affine (`noperspective`) or perspective-correct (`smooth`) interpolation.
    pub mode: Interpolation,
    /// Texture filter: nearest, bilinear or trilinear.
    pub filter: Filter,
    /// Texture wrap mode outside [0, 1].
    pub wrap: Wrap,
    /// What a fragment's colour is made from.
    pub shading: Shading,
    /// Overlay the source triangles' edges.
    pub wireframe: bool,
    /// RGBA of pixels no triangle covers.
    pub background: [u8; 4],
    /// Which pixel-coverage algorithm draws: edge functions or the scanline.
    pub rasterizer: Rasterizer,
    /// Which triangle owns a pixel centre exactly on a shared edge.
    pub tie_rule: TieRule,
}

/// The default background: a dark slate grey, opaque.
pub const DEFAULT_BACKGROUND: [u8; 4] = [36, 38, 46, 255];

impl Default for RenderSettings {
    fn default() -> Self {
        Self {
            width: 800,
            height: 600,
            mode: Interpolation::Perspective,
            filter: Filter::Bilinear,
            wrap: Wrap::Repeat,
            shading: Shading::Texture,
            wireframe: false,
            background: DEFAULT_BACKGROUND,
            rasterizer: Rasterizer::EdgeFunction,
            tie_rule: TieRule::Llvmpipe,
        }
    }
}

impl RenderSettings {
    /// The viewport (0, 0, width, height).
    pub fn viewport(&self) -> Viewport {
        Viewport {
            width: self.width,
            height: self.height,
        }
    }
}

/// Errors that stop a render as a whole.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RenderError {
    /// Width or height is 0 or above [`MAX_IMAGE_SIZE`].
    #[error("image size {width}x{height} is outside 1..={max} pixels per side", max = MAX_IMAGE_SIZE)]
    BadSize {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
    },
    /// The buffers would need more memory than the budget allows.
    #[error(transparent)]
    Memory(#[from] crate::budget::MemoryError),
}

/// The result of a render: the framebuffer and what happened to each source triangle.
#[derive(Clone, Debug)]
pub struct Render {
    /// The image and the per-pixel buffers.
    pub frame: Framebuffer,
    /// Every source triangle as prepared, in mesh order ([`render`]; empty where a caller
    /// built a `Render` around an image from [`render_into`], which keeps no per-triangle record).
    pub triangles: Vec<PreparedTriangle>,
}

/// Renders a clip-space mesh into a new framebuffer with every buffer.
pub fn render(
    mesh: &ClipMesh,
    texture: &Texture,
    settings: &RenderSettings,
) -> Result<Render, RenderError> {
    let mut frame = Framebuffer::with_buffers(0, 0, settings.background, Buffers::All);
    check_budget(mesh, settings, Buffers::All)?;
    let triangles = prepare_triangles(mesh, settings)?;
    let params = shade_params(settings, &triangles);
    resize(&mut frame, settings.width, settings.height, Buffers::All);
    rasterize_bands(
        &triangles,
        texture,
        &params,
        settings.rasterizer,
        &mut frame,
        ROWS_PER_BAND,
        Some(settings.background),
    );
    Ok(Render { frame, triangles })
}

/// Row `y` of [`render`]'s image, every buffer, as a framebuffer one row high: the same
/// values (the same triangles in the same order, the same per-pixel code), for a plot of one
/// row (the app's row plot) without rendering the other rows. A row outside the image is
/// left clear.
pub fn render_row(
    mesh: &ClipMesh,
    texture: &Texture,
    settings: &RenderSettings,
    y: u32,
) -> Result<Framebuffer, RenderError> {
    let row_settings = RenderSettings {
        height: 1,
        ..*settings
    };
    check_budget(mesh, &row_settings, Buffers::All)?;
    let triangles = prepare_triangles(mesh, settings)?;
    let params = shade_params(settings, &triangles);
    let mut frame = Framebuffer::with_buffers(settings.width, 1, settings.background, Buffers::All);
    let mut bands = RowBand::split(&mut frame, 1);
    if let Some(band) = bands.first_mut() {
        band.clear(settings.background);
        band.y0 = y;
        for tri in &triangles {
            for setup in &tri.setups {
                rasterize(
                    setup,
                    tri.source,
                    texture,
                    &params,
                    settings.rasterizer,
                    band,
                );
            }
        }
    }
    Ok(frame)
}

/// Renders a clip-space mesh into `frame`, reusing its memory: the frame is resized to the
/// settings' size, given `buffers`, cleared to the background and drawn, with the same pixels
/// as [`render`]. It keeps no per-triangle record: every vertex is projected once and each
/// triangle's set-up is rebuilt where it is drawn (module `fast`), so dense meshes need little
/// memory. With [`Buffers::ColorDepth`], [`Buffers::ColorDepthUv`] or
/// [`Buffers::DepthDifference`] the lane path
/// ([`lanes`](mod@super::lanes)) draws whatever it can.
pub fn render_into(
    frame: &mut Framebuffer,
    mesh: &ClipMesh,
    texture: &Texture,
    settings: &RenderSettings,
    buffers: Buffers,
) -> Result<(), RenderError> {
    check_budget(mesh, settings, buffers)?;
    let (w, h) = (settings.width, settings.height);
    if w == 0 || h == 0 || w > MAX_IMAGE_SIZE || h > MAX_IMAGE_SIZE {
        return Err(RenderError::BadSize {
            width: w,
            height: h,
        });
    }
    let prepared = FastMesh::prepare(mesh, settings.viewport(), settings.tie_rule);
    let mut params = shade_params(settings, &[]);
    // Only depth shading reads the range (a pass over every triangle).
    if settings.shading == Shading::Depth {
        params.depth_range = prepared.depth_range();
    }
    resize(frame, w, h, buffers);
    prepared.rasterize(
        texture,
        &params,
        settings.rasterizer,
        frame,
        FAST_ROWS_PER_BAND,
        settings.background,
    );
    Ok(())
}

/// Refuses a render the memory limit cannot hold (image sizes out of range are refused
/// after, with [`RenderError::BadSize`]).
fn check_budget(
    mesh: &ClipMesh,
    settings: &RenderSettings,
    buffers: Buffers,
) -> Result<(), RenderError> {
    let (w, h) = (settings.width, settings.height);
    if (1..=MAX_IMAGE_SIZE).contains(&w) && (1..=MAX_IMAGE_SIZE).contains(&h) {
        crate::budget::check_render(w, h, buffers, mesh.vertices.len(), mesh.triangles.len())?;
    }
    Ok(())
}

/// Gives `frame` the size and buffers asked for (contents are cleared later, per band).
fn resize(frame: &mut Framebuffer, width: u32, height: u32, buffers: Buffers) {
    let n = width as usize * height as usize;
    frame.width = width;
    frame.height = height;
    frame.color.resize(n, [0; 4]);
    frame.depth.resize(n, 1.0);
    let aov = if buffers == Buffers::All { n } else { 0 };
    let uv = match buffers {
        Buffers::All | Buffers::ColorDepthUv => n,
        Buffers::ColorDepth | Buffers::DepthDifference => 0,
    };
    frame.triangle.resize(uv, NO_TRIANGLE);
    frame.facing.resize(aov, Facing::Front);
    frame.weights_screen.resize(aov, [0.0; 3]);
    frame.weights_perspective.resize(aov, [0.0; 3]);
    frame.uv_affine.resize(uv, [0.0; 2]);
    frame.uv_perspective.resize(uv, [0.0; 2]);
    frame.inv_w.resize(aov, 0.0);
    let diff = if buffers == Buffers::DepthDifference {
        n
    } else {
        0
    };
    frame.texel_difference.resize(diff, f32::NAN);
}

/// The shading parameters of a render: the settings plus the depth range of the drawn
/// triangles (the renderer and the probe both call this).
pub fn shade_params(settings: &RenderSettings, triangles: &[PreparedTriangle]) -> ShadeParams {
    ShadeParams {
        shading: settings.shading,
        mode: settings.mode,
        filter: settings.filter,
        wrap: settings.wrap,
        wireframe: settings.wireframe,
        depth_range: depth_range(triangles),
    }
}

/// Smallest and largest window depth over the drawn vertices.
pub fn depth_range(triangles: &[PreparedTriangle]) -> (f64, f64) {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for s in triangles.iter().flat_map(|t| &t.setups) {
        for v in &s.v {
            lo = lo.min(v.depth);
            hi = hi.max(v.depth);
        }
    }
    if lo <= hi { (lo, hi) } else { (0.0, 1.0) }
}

/// Rows of the image each parallel task rasterizes. Every band draws the triangles that reach
/// it in submission order, so each pixel sees the same fragments in the same order as a
/// serial render and the output does not depend on the band size or the number of threads.
pub const ROWS_PER_BAND: u32 = 16;

/// Rows of a band of the fast path ([`render_into`]). Twice [`ROWS_PER_BAND`]: the fast path
/// sets a triangle up again in every band it reaches, and a dense mesh's triangles, a few rows
/// tall, reach two bands of 16 rows about twice as often as two of 32. A band of a 1920-pixel
/// image is then about 0.5 MB of colour and depth, still within a core's L2 cache. (Any band
/// size gives the same pixels.)
pub const FAST_ROWS_PER_BAND: u32 = 32;

/// Rasterizes all set-up triangles into `frame`, in parallel over bands of `rows_per_band`
/// image rows (rayon's current thread pool). With `clear`, each band first clears its rows
/// to that background (depth to 1, the other buffers to their empty values).
pub fn rasterize_bands(
    triangles: &[PreparedTriangle],
    texture: &Texture,
    params: &ShadeParams,
    rasterizer: Rasterizer,
    frame: &mut Framebuffer,
    rows_per_band: u32,
    clear: Option<[u8; 4]>,
) {
    use rayon::prelude::*;
    let rows_per_band = rows_per_band.max(1);
    let bins = bin_by_band(triangles, frame.height, rows_per_band);
    let bands = RowBand::split(frame, rows_per_band);
    bands.into_par_iter().zip(bins).for_each(|(mut band, bin)| {
        if let Some(background) = clear {
            band.clear(background);
        }
        for (ti, si) in bin {
            let tri = &triangles[ti as usize];
            let setup = &tri.setups[si as usize];
            rasterize(setup, tri.source, texture, params, rasterizer, &mut band);
        }
    });
}

/// What the lanes can draw of these shading parameters (colour and depth only): every shading
/// but trilinear texture lookups in the edge-function lanes (trilinear goes per pixel, after
/// block rejection); the scanline lanes draw the same without the wireframe, which goes per
/// pixel.
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

/// Visits every covered pixel centre of one set-up triangle within a band, depth-tests and
/// writes it.
pub(super) fn rasterize(
    setup: &TriangleSetup,
    source: u32,
    texture: &Texture,
    params: &ShadeParams,
    rasterizer: Rasterizer,
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
        if params.filter == Filter::Trilinear {
            frag.lod =
                interpolate::quad_lod(setup, x, y, params.mode, texture.width(), texture.height());
        }
        let i = (y - band.y0) as usize * band.width as usize + x as usize;
        let depth = frag.depth as f32;
        if !super::framebuffer::depth_passes(depth, band.depth[i]) {
            return;
        }
        band.depth[i] = depth;
        // A difference render shades nothing (`Buffers::DepthDifference`).
        if !diffs {
            band.color[i] = shade(&frag, texture, params, &wire);
        }
        if diffs {
            band.texel_difference[i] = super::texture::texel_difference(
                frag.affine.uv().to_array(),
                frag.correct.uv().to_array(),
                texels,
            );
        }
        if uvs {
            band.triangle[i] = source;
            band.uv_affine[i] = frag.affine.uv().to_array();
            band.uv_perspective[i] = frag.correct.uv().to_array();
        }
        if aovs {
            band.facing[i] = setup.facing;
            band.weights_screen[i] = frag.affine.bary();
            band.weights_perspective[i] = frag.correct.bary();
            band.inv_w[i] = frag.inv_w as f32;
        }
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
                    shading,
                    &mut target,
                    &mut |x, y, e| per_pixel.push((x, y, e)),
                );
                for (x, y, e) in per_pixel {
                    let l = setup.weights.at_pixel(x, y);
                    if let Some(frag) = interpolate::fragment_from_weights(setup, e, l) {
                        write(band, x, y, &frag);
                    }
                }
                return;
            }
            (Rasterizer::Scanline, Some(shading))
                if !uvs && !diffs && scanline_lanes_apply(&shading) =>
            {
                let tri = lanes::LaneTriangle::of(setup, Some(shading), false);
                draw_scanline_lanes(&tri, &lanes::Lanes::new(texture, shading), band);
                return;
            }
            _ => {}
        }
    }
    match rasterizer {
        Rasterizer::EdgeFunction => {
            for y in y_start..=y_end {
                for x in b.x0..=b.x1 {
                    let e = setup.edge_values(sample_point(x, y));
                    if !setup.covers(&e) {
                        continue;
                    }
                    let l = setup.weights.at_pixel(x, y);
                    if let Some(frag) = interpolate::fragment_from_weights(setup, e, l) {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Scene;

    /// One band (a serial render) and many small bands on several threads give the same
    /// framebuffer, bit for bit.
    #[test]
    fn bands_and_threads_do_not_change_the_output() {
        let mut scene = Scene::default_scene();
        scene.set_size(203, 157);
        let mesh = scene.to_mesh();
        let texture = Texture::builtin(super::super::BuiltinTexture::UvGrid);
        let mut settings = scene.settings();
        settings.wireframe = true;
        let viewport = settings.viewport();
        let triangles: Vec<PreparedTriangle> = (0..mesh.triangles.len() as u32)
            .map(|i| prepare_triangle(&mesh, i, viewport))
            .collect();
        let params = shade_params(&settings, &triangles);
        let draw = |rows: u32, threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("thread pool");
            let mut frame = Framebuffer::new(203, 157, settings.background);
            pool.install(|| {
                rasterize_bands(
                    &triangles,
                    &texture,
                    &params,
                    Rasterizer::EdgeFunction,
                    &mut frame,
                    rows,
                    None,
                )
            });
            frame
        };
        let serial = draw(157, 1);
        assert!(
            serial
                .triangle
                .iter()
                .any(|&t| t != crate::raster::NO_TRIANGLE)
        );
        for (rows, threads) in [(1, 4), (7, 3), (16, 2), (1000, 2)] {
            assert!(
                draw(rows, threads) == serial,
                "{rows} rows per band, {threads} threads"
            );
        }
    }
}
