//! Drawing with more than one sample per pixel: coverage, depth and colour per sample, then
//! the resolve. The positions, the location rule and the resolve formula are
//! [`sample`](super::sample)'s; coverage uses the triangle's own snapped edge functions and
//! tie rule at each sample, values the same interpolation functions as a single sample
//! ([`interpolate::fragment_at_window`], [`interpolate::depth_at`]).
//!
//! Per pixel and triangle ([`draw_pixel`]): the samples the triangle covers; under MSAA one
//! fragment at the centre or the centroid ([`centroid_sample`]), shaded once, its colour
//! written to every covered sample that passes the depth test, each with its own depth
//! from the depth's plane at the sample; under supersampling, or at the `sample` location, every
//! covered sample interpolated and shaded at its own position. The render driver
//! ([`render`](mod@super::render)) sends a multisampled render here and a single-sample one to
//! the usual path, which stays as it was.

use glam::{DVec2, I64Vec2};

use crate::budget::{MemoryError, try_resize};

use super::draw::write_buffers;
use super::framebuffer::{Framebuffer, NO_TRIANGLE, RowBand, depth_passes};
use super::interpolate::{self, Fragment};
use super::mesh::ClipMesh;
use super::prepare::{PreparedTriangle, source_vertices};
use super::project::Viewport;
use super::sample::{SampleSettings, centroid_sample, resolve, sample_at, window_position};
use super::setup::{PixelBounds, TriangleSetup, sample_pixel_bounds, sample_point};
use super::shade::{ShadeParams, shade, texture_footprint};
use super::texture::Texture;
use super::varying::Varyings;

/// What one sample holds: the colour, the depth, the source triangle that wrote it and the
/// uv its fragment shader saw (the render's interpolation mode).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampleValue {
    /// RGBA of the fragment written here, or the background.
    pub color: [u8; 4],
    /// Window depth z/w at this sample of the triangle that wrote it; 1 when none did.
    pub depth: f32,
    /// The source triangle, or [`NO_TRIANGLE`].
    pub triangle: u32,
    /// The uv the shading of this sample used (the centre's or the centroid's under MSAA).
    pub uv: [f32; 2],
}

impl SampleValue {
    /// A cleared sample: the background, depth 1, no triangle.
    pub fn clear(background: [u8; 4]) -> Self {
        Self {
            color: background,
            depth: 1.0,
            triangle: NO_TRIANGLE,
            uv: [0.0; 2],
        }
    }
}

/// Every sample of an image: `count` per pixel, pixel by pixel, row by row.
#[derive(Clone, Debug, PartialEq)]
pub struct SampleBuffer {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The sample offsets in a pixel (1/256 pixel from its top-left corner, y down).
    pub offsets: Vec<I64Vec2>,
    /// `width * height * offsets.len()` samples.
    pub samples: Vec<SampleValue>,
}

impl SampleBuffer {
    /// The samples of pixel (x, y).
    pub fn pixel(&self, x: u32, y: u32) -> &[SampleValue] {
        let n = self.offsets.len();
        let i = (y as usize * self.width as usize + x as usize) * n;
        &self.samples[i..i + n]
    }
}

/// What the kernel needs beyond one triangle: the positions, the qualifiers, the texture
/// and the shading parameters.
#[derive(Clone, Copy)]
pub struct SampleContext<'a> {
    /// Sample offsets in a pixel.
    pub offsets: &'a [I64Vec2],
    /// Rate, location, flat.
    pub samples: SampleSettings,
    /// The texture.
    pub texture: &'a Texture,
    /// The shading parameters.
    pub params: &'a ShadeParams,
}

/// The samples of pixel (x, y) a triangle covers, bit `k` for sample `k`: the edge values at
/// each sample position ([`sample_at`]) passed through the triangle's fill rule.
pub fn coverage(setup: &TriangleSetup, x: u32, y: u32, offsets: &[I64Vec2]) -> u32 {
    offsets.iter().enumerate().fold(0, |mask, (k, &o)| {
        let e = setup.edge_values(sample_at(x, y, o));
        if setup.covers(&e) {
            mask | 1 << k
        } else {
            mask
        }
    })
}

/// Everything interpolated at a position `p` (1/256 pixel; inside the triangle or not):
/// the edge values there and [`interpolate::fragment_at_window`] at `p / 256`; with `flat`,
/// the provoking vertex's attributes.
pub fn fragment_at(setup: &TriangleSetup, p: I64Vec2, flat: Option<&Varyings>) -> Option<Fragment> {
    let frag = interpolate::fragment_at_window(setup, setup.edge_values(p), window_position(p))?;
    Some(match flat {
        Some(v) => frag.flat(v),
        None => frag,
    })
}

/// The attributes of a source triangle's provoking vertex, when every attribute is `flat`.
pub fn flat_varyings(mesh: &ClipMesh, source: u32, samples: &SampleSettings) -> Option<Varyings> {
    if !samples.flat {
        return None;
    }
    source_vertices(mesh, source).map(|v| v[samples.provoking.index()].varyings)
}

/// Where the shared MSAA fragment of a pixel is evaluated: its centre, or the sample
/// [`centroid_sample`] names (1/256 pixel).
pub fn shading_point(x: u32, y: u32, mask: u32, ctx: &SampleContext<'_>) -> I64Vec2 {
    match centroid_sample(ctx.samples.location, mask, ctx.offsets.len()) {
        Some(k) => sample_at(x, y, ctx.offsets[k]),
        None => sample_point(x, y),
    }
}

/// The fragment pixel (x, y) of a triangle shades at `p` (1/256 pixel): [`fragment_at`] with
/// the texture footprint of the pixel.
fn shading_fragment(
    (setup, flat): (&TriangleSetup, Option<&Varyings>),
    (x, y): (u32, u32),
    p: I64Vec2,
    ctx: &SampleContext<'_>,
) -> Option<Fragment> {
    let mut frag = fragment_at(setup, p, flat)?;
    texture_footprint(&mut frag, setup, (x, y), ctx.params, ctx.texture);
    Some(frag)
}

/// MSAA's one shading of pixel (x, y) for a triangle covering the samples `mask`: the
/// fragment at the [`shading_point`] and its colour; `None` when there is no fragment there.
pub(super) fn shared_shading(
    (setup, flat): (&TriangleSetup, Option<&Varyings>),
    (x, y): (u32, u32),
    mask: u32,
    ctx: &SampleContext<'_>,
    wire: &[DVec2; 3],
) -> Option<(Fragment, [u8; 4])> {
    let frag = shading_fragment((setup, flat), (x, y), shading_point(x, y, mask, ctx), ctx)?;
    Some((frag, shade(&frag, ctx.texture, ctx.params, wire)))
}

/// The window depth of the sample at `offset` in pixel (x, y) under a triangle:
/// its plane at the sample ([`interpolate::depth_at`]), as `f32`.
pub(super) fn sample_depth(setup: &TriangleSetup, x: u32, y: u32, offset: I64Vec2) -> f32 {
    interpolate::depth_at(setup, window_position(sample_at(x, y, offset))) as f32
}

/// Draws one triangle (source triangle `source`, with its `flat` attributes if any) into the
/// samples of pixel (x, y): coverage, the depth test per sample (less-than), shading once
/// (MSAA at the centre or centroid) or per sample, and the sample's colour, depth, triangle
/// and uv. Returns the fragment written to sample 0, if one was.
pub fn draw_pixel(
    (setup, source, flat): (&TriangleSetup, u32, Option<&Varyings>),
    (x, y): (u32, u32),
    ctx: &SampleContext<'_>,
    wire: &[DVec2; 3],
    pixel: &mut [SampleValue],
) -> Option<Fragment> {
    let mask = coverage(setup, x, y, ctx.offsets);
    if mask == 0 {
        return None;
    }
    let params = ctx.params;
    let texture = ctx.texture;
    let fragment = |p: I64Vec2| shading_fragment((setup, flat), (x, y), p, ctx);
    let shared = if ctx.samples.per_sample_shading() {
        None
    } else {
        Some(shared_shading((setup, flat), (x, y), mask, ctx, wire)?)
    };
    let mut first = None;
    for (k, (&o, out)) in ctx.offsets.iter().zip(pixel.iter_mut()).enumerate() {
        if mask & 1 << k == 0 {
            continue;
        }
        let (frag, depth) = match &shared {
            Some((frag, _)) => (*frag, sample_depth(setup, x, y, o)),
            None => {
                let Some(frag) = fragment(sample_at(x, y, o)) else {
                    continue;
                };
                (frag, frag.depth as f32)
            }
        };
        if !depth_passes(depth, out.depth) {
            continue;
        }
        let color = match &shared {
            Some((_, c)) => *c,
            None => shade(&frag, texture, params, wire),
        };
        *out = SampleValue {
            color,
            depth,
            triangle: source,
            uv: frag.varyings(params.mode).uv().to_array(),
        };
        if k == 0 {
            first = Some(frag);
        }
    }
    first
}

/// The pixels whose samples a triangle can cover ([`sample_pixel_bounds`] of its snapped
/// corners).
pub fn sample_bounds(setup: &TriangleSetup, viewport: Viewport) -> Option<PixelBounds> {
    sample_pixel_bounds(&setup.v.map(|v| v.fixed), viewport)
}

/// Draws `triangles` (with their bounds and `flat` attributes, in submission order) into
/// one band of the frame and its samples (`samples`: the band's pixels times the sample
/// count), then resolves: each pixel's colour is the [`resolve`] of its samples (unless the
/// band only keeps the texel difference), its depth and per-pixel buffers sample 0's.
pub(super) fn draw_band<'t>(
    triangles: impl Iterator<Item = (&'t TriangleSetup, u32, Option<&'t Varyings>, PixelBounds)>,
    ctx: &SampleContext<'_>,
    band: &mut RowBand<'_>,
    samples: &mut [SampleValue],
) {
    let n = ctx.offsets.len();
    let texels = (ctx.texture.width(), ctx.texture.height());
    for (setup, source, flat, bounds) in triangles {
        let Some((y_start, y_end)) = band.rows_of(&bounds) else {
            continue;
        };
        let wire = if ctx.params.wireframe {
            setup.source_weight_gradients()
        } else {
            [DVec2::ZERO; 3]
        };
        for y in y_start..=y_end {
            for x in bounds.x0..=bounds.x1 {
                let i = (y - band.y0) as usize * band.width as usize + x as usize;
                let pixel = &mut samples[i * n..(i + 1) * n];
                if let Some(frag) = draw_pixel((setup, source, flat), (x, y), ctx, &wire, pixel) {
                    write_buffers(band, i, (setup, source), &frag, texels);
                }
            }
        }
    }
    let shaded = band.texel_difference.is_empty();
    for (i, pixel) in samples.chunks_exact(n).enumerate() {
        if shaded {
            let colors: smallvec::SmallVec<[[u8; 4]; 16]> = pixel.iter().map(|s| s.color).collect();
            band.color[i] = resolve(&colors);
        }
        band.depth[i] = pixel[0].depth;
    }
}

/// One triangle a band draws: its set-up, source triangle, `flat` attributes and
/// [`sample_bounds`].
pub(super) type Drawn<'a> = (&'a TriangleSetup, u32, Option<Varyings>, PixelBounds);

/// The set-up triangles of a multisampled frame with their source, `flat` attributes and
/// [`sample_bounds`], in submission order, and the bins of the bands of `rows_per_band` rows.
pub(super) fn drawn_and_bins<'t>(
    (mesh, triangles): (&ClipMesh, &'t [PreparedTriangle]),
    ctx: &SampleContext<'_>,
    (width, height): (u32, u32),
    rows_per_band: u32,
) -> (Vec<Drawn<'t>>, Vec<Vec<(u32, u32)>>) {
    let viewport = Viewport { width, height };
    let drawn: Vec<Drawn<'_>> = triangles
        .iter()
        .map(|t| (t, flat_varyings(mesh, t.source, &ctx.samples)))
        .flat_map(|(t, flat)| {
            t.setups
                .iter()
                .filter_map(move |s| Some((s, t.source, flat, sample_bounds(s, viewport)?)))
        })
        .collect();
    let mut bins = Vec::new();
    super::bands::bin_rows(
        &mut bins,
        height,
        rows_per_band,
        drawn
            .iter()
            .enumerate()
            .map(|(i, d)| (i as u32, 0, d.3.y0, d.3.y1)),
    );
    (drawn, bins)
}

/// Draws every prepared triangle into `frame` (already sized and cleared to `background`)
/// and into a new sample buffer, in parallel over bands of `rows_per_band` rows, each band
/// drawing its triangles in submission order; returns the samples. The sample buffer's
/// memory is asked for fallibly: refused, it is an error naming the buffer and its size
/// (`width x height x n` samples of [`SampleValue`]'s size), never an abort.
pub(super) fn draw_frame(
    prepared: (&ClipMesh, &[PreparedTriangle]),
    ctx: &SampleContext<'_>,
    frame: &mut Framebuffer,
    rows_per_band: u32,
    background: [u8; 4],
) -> Result<SampleBuffer, MemoryError> {
    use rayon::prelude::*;
    let n = ctx.offsets.len();
    let (width, height) = (frame.width, frame.height);
    let mut samples = Vec::new();
    try_resize(
        &mut samples,
        (width as usize * height as usize).saturating_mul(n),
        SampleValue::clear(background),
        || format!("the {width}x{height} sample buffer ({n} samples a pixel)"),
    )?;
    let mut buffer = SampleBuffer {
        width,
        height,
        offsets: ctx.offsets.to_vec(),
        samples,
    };
    let (drawn, bins) = drawn_and_bins(prepared, ctx, (width, height), rows_per_band);
    let progress = crate::progress::render_started(height);
    let bands = RowBand::split(frame, rows_per_band);
    let chunk = (rows_per_band as usize * width as usize * n).max(1);
    bands
        .into_par_iter()
        .zip(buffer.samples.par_chunks_mut(chunk))
        .zip(bins)
        .for_each(|((mut band, samples), bin)| {
            let _drawn = super::bands::RowsDrawn(&progress, band.rows);
            if progress.cancelled() {
                return;
            }
            let triangles = bin.iter().map(|&(i, _)| {
                let (s, source, flat, bounds) = &drawn[i as usize];
                (*s, *source, flat.as_ref(), *bounds)
            });
            draw_band(triangles, ctx, &mut band, samples);
        });
    Ok(buffer)
}
