//! The pipeline driver: clip-space mesh in, framebuffer out.
//!
//! Per source triangle: clip (`clip`), divide and snap (`project`), fan the clipped polygon
//! into triangles and set them up (`setup`). Then, in submission order, every covered pixel
//! centre is interpolated (`interpolate`), depth-tested (less-than) and shaded (`shade`).
//! The probe calls [`prepare_triangle`] and
//! [`interpolate::fragment`](super::interpolate::fragment) exactly as done here.
//!
//! This module only drives: the settings are [`settings`](super::settings)'s, the preparation
//! `prepare.rs`'s, the per-pixel kernel and the lane glue `draw.rs`'s, the fast path's mesh
//! `fast.rs`'s, the bins `bands.rs`'s and the memory estimate
//! [`footprint`](super::footprint)'s; none of them calls back into it.

use crate::budget::MemoryError;

use super::bands::{RowsDrawn, bin_rows, stop_at};
use super::draw::rasterize;
use super::fast::FastMesh;
use super::footprint::check_render_samples;
use super::framebuffer::{Buffers, Framebuffer, RowBand};
use super::lanes::VectorLevel;
use super::msaa_band::{draw_frame_fast, fast_applies};
use super::multisample::{SampleBuffer, SampleContext, draw_frame};
use super::shade::{ShadeParams, Shading, depth_range};
use super::texture::Texture;

pub use super::mesh::{ClipMesh, MeshVertex, subdivided_triangle};
pub use super::prepare::{
    PreparedTriangle, TriangleStatus, prepare_all, prepare_all_with, prepare_triangle,
    prepare_triangle_with, prepare_triangles, source_vertices,
};
pub use super::settings::{DEFAULT_BACKGROUND, Rasterizer, RenderError, RenderSettings};

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
    if settings.samples.uses_sample_path() {
        return render_samples(mesh, texture, settings).map(|(render, _)| render);
    }
    check_budget(mesh, settings, Buffers::All)?;
    let triangles = prepare_triangles(mesh, settings)?;
    let params = shade_params(settings, &triangles);
    let mut frame = Framebuffer::empty();
    frame.resize(settings.width, settings.height, Buffers::All)?;
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

/// Renders with every buffer and keeps every sample: the resolved image (each pixel the
/// average of its samples; depth and the per-pixel buffers sample 0's) and the samples
/// themselves ([`multisample`](super::multisample)). [`render`] draws a multisampled scene
/// through here; with one sample it gives [`render`]'s single-sample image too.
pub fn render_samples(
    mesh: &ClipMesh,
    texture: &Texture,
    settings: &RenderSettings,
) -> Result<(Render, SampleBuffer), RenderError> {
    check_budget(mesh, settings, Buffers::All)?;
    let triangles = prepare_triangles(mesh, settings)?;
    let mut frame = Framebuffer::with_buffers(0, 0, settings.background, Buffers::All)?;
    frame.resize(settings.width, settings.height, Buffers::All)?;
    let samples = draw_samples(
        mesh,
        &triangles,
        texture,
        settings,
        &mut frame,
        ROWS_PER_BAND,
    )?;
    Ok((Render { frame, triangles }, samples))
}

/// The multisample drawing of prepared triangles into a sized `frame`, cleared first.
fn draw_samples(
    mesh: &ClipMesh,
    triangles: &[PreparedTriangle],
    texture: &Texture,
    settings: &RenderSettings,
    frame: &mut Framebuffer,
    rows_per_band: u32,
) -> Result<SampleBuffer, MemoryError> {
    let params = shade_params(settings, triangles);
    let offsets = settings.samples.offsets();
    let ctx = SampleContext {
        offsets: &offsets,
        samples: settings.samples,
        texture,
        params: &params,
    };
    frame.clear(settings.background);
    draw_frame(
        (mesh, triangles),
        &ctx,
        frame,
        rows_per_band,
        settings.background,
    )
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
    if settings.samples.uses_sample_path() {
        // Every row, then the one asked for (a multisampled row plot is rare and small).
        let (full, _) = render_samples(mesh, texture, settings)?;
        return one_row(&full.frame, y, settings.background);
    }
    let triangles = prepare_triangles(mesh, settings)?;
    let params = shade_params(settings, &triangles);
    let mut frame =
        Framebuffer::with_buffers(settings.width, 1, settings.background, Buffers::All)?;
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
                    (settings.rasterizer, VectorLevel::current()),
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
/// ([`lanes`](mod@super::lanes)) draws whatever it can, at the level
/// [`VectorLevel::for_frame`] picks for the mesh.
pub fn render_into(
    frame: &mut Framebuffer,
    mesh: &ClipMesh,
    texture: &Texture,
    settings: &RenderSettings,
    buffers: Buffers,
) -> Result<(), RenderError> {
    let pixels = u64::from(settings.width) * u64::from(settings.height);
    render_into_at(
        frame,
        mesh,
        texture,
        settings,
        buffers,
        VectorLevel::for_frame(mesh.triangles.len(), pixels),
    )
}

/// [`render_into`] with the lanes limited to the instruction sets of `vector` (each level
/// gives the same pixels; `tests/fast_path.rs` draws at every level and compares).
pub fn render_into_at(
    frame: &mut Framebuffer,
    mesh: &ClipMesh,
    texture: &Texture,
    settings: &RenderSettings,
    buffers: Buffers,
    vector: VectorLevel,
) -> Result<(), RenderError> {
    check_budget(mesh, settings, buffers)?;
    settings.check_size()?;
    if settings.samples.uses_sample_path() {
        // More than one sample per pixel: the multisample path, not the lanes.
        let triangles = prepare_triangles(mesh, settings)?;
        frame.resize(settings.width, settings.height, buffers)?;
        let params = shade_params(settings, &triangles);
        let offsets = settings.samples.offsets();
        let ctx = SampleContext {
            offsets: &offsets,
            samples: settings.samples,
            texture,
            params: &params,
        };
        if fast_applies(&ctx, frame) {
            // Colour and depth only: every pixel is written, no sample kept.
            draw_frame_fast(
                (mesh, &triangles),
                &ctx,
                frame,
                (FAST_ROWS_PER_BAND, vector),
                settings.background,
            )?;
        } else {
            draw_samples(
                mesh,
                &triangles,
                texture,
                settings,
                frame,
                FAST_ROWS_PER_BAND,
            )?;
        }
        return Ok(());
    }
    let prepared = FastMesh::prepare(mesh, settings.viewport(), settings.tie_rule);
    let mut params = shade_params(settings, &[]);
    // Only depth shading reads the range (a pass over every triangle).
    if settings.shading == Shading::Depth {
        params.depth_range = prepared.depth_range();
    }
    frame.resize(settings.width, settings.height, buffers)?;
    prepared.rasterize(
        texture,
        &params,
        (settings.rasterizer, vector),
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
    if settings.check_size().is_ok() {
        check_render_samples(
            (settings.width, settings.height),
            buffers,
            &settings.samples,
            mesh.vertices.len(),
            mesh.triangles.len(),
        )?;
    }
    settings.samples.check().map_err(RenderError::BadSamples)?;
    Ok(())
}

/// The shading parameters of a render: the settings plus the depth range of the drawn
/// triangles' vertices ([`depth_range`]; the renderer and the probe both call this).
pub fn shade_params(settings: &RenderSettings, triangles: &[PreparedTriangle]) -> ShadeParams {
    ShadeParams {
        shading: settings.shading,
        mode: settings.mode,
        filter: settings.filter,
        wrap: settings.wrap,
        wireframe: settings.wireframe,
        max_anisotropy: settings.max_anisotropy,
        depth_range: depth_range(
            triangles
                .iter()
                .flat_map(|t| &t.setups)
                .flat_map(|s| s.v.iter().map(|v| v.depth)),
        ),
    }
}

/// Row `y` of `frame` as a frame one row high with every buffer (clear outside the image).
fn one_row(frame: &Framebuffer, y: u32, background: [u8; 4]) -> Result<Framebuffer, RenderError> {
    let mut row = Framebuffer::with_buffers(frame.width, 1, background, Buffers::All)?;
    if y < frame.height {
        let r = frame.index(0, y)..frame.index(0, y) + frame.width as usize;
        row.color.copy_from_slice(&frame.color[r.clone()]);
        row.depth.copy_from_slice(&frame.depth[r.clone()]);
        row.triangle.copy_from_slice(&frame.triangle[r.clone()]);
        row.facing.copy_from_slice(&frame.facing[r.clone()]);
        row.weights_screen
            .copy_from_slice(&frame.weights_screen[r.clone()]);
        row.weights_perspective
            .copy_from_slice(&frame.weights_perspective[r.clone()]);
        row.uv_affine.copy_from_slice(&frame.uv_affine[r.clone()]);
        row.uv_perspective
            .copy_from_slice(&frame.uv_perspective[r.clone()]);
        row.inv_w.copy_from_slice(&frame.inv_w[r]);
    }
    Ok(row)
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
    let pixels = u64::from(frame.width) * u64::from(frame.height);
    let vector = VectorLevel::for_frame(triangles.len(), pixels);
    let mut bins = Vec::new();
    bin_rows(
        &mut bins,
        frame.height,
        rows_per_band,
        triangles.iter().enumerate().flat_map(|(ti, tri)| {
            tri.setups
                .iter()
                .enumerate()
                .map(move |(si, s)| (ti as u32, si as u32, s.bounds.y0, s.bounds.y1))
        }),
    );
    let progress = crate::progress::render_started(frame.height);
    let bands = RowBand::split(frame, rows_per_band);
    bands.into_par_iter().zip(bins).for_each(|(mut band, bin)| {
        let _drawn = RowsDrawn(&progress, band.rows);
        if let Some(background) = clear {
            band.clear(background);
        }
        for (j, (ti, si)) in bin.into_iter().enumerate() {
            if stop_at(&progress, j) {
                break;
            }
            let tri = &triangles[ti as usize];
            let setup = &tri.setups[si as usize];
            rasterize(
                setup,
                tri.source,
                texture,
                params,
                (rasterizer, vector),
                &mut band,
            );
        }
    });
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
            let mut frame = Framebuffer::new(203, 157, settings.background).expect("small frame");
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
