//! Composing a figure: the renders (again at the scale), the traces of the marked pixels, each
//! view's raster and overlay laid out in points.

use crate::i18n::Lang;

use super::caption::{self, Caption};
use super::overlay::{self, HandleMark, Overlay, OverlayInput};
use super::{
    Background, Compare, FigureOptions, MAX_FIGURE_SIZE, OVERLAY_SCALE_RANGE, SCALES, ViewContent,
    clip_mark, heatmap, layout_points, modes_for, pixel_mark, text, vertices_on_screen,
    view_contents, wipe_column, wipe_pixels,
};
use crate::probe::{PixelTrace, ProbeError, Prober};
use crate::raster::project::Viewport;
use crate::raster::render::{Render, RenderError};
use crate::raster::{Interpolation, RenderSettings, Texture};
use crate::scene::Scene;

/// Why a figure cannot be made.
#[derive(Debug, thiserror::Error)]
pub enum FigureError {
    /// A scale other than 1, 2 or 4.
    #[error("scale {0} is not one of 1, 2, 4")]
    Scale(u32),
    /// A pixel size outside 1..=32.
    #[error("pixel size {0} is outside 1..=32")]
    PixelSize(u32),
    /// An overlay scale outside [`OVERLAY_SCALE_RANGE`].
    #[error("overlay scale {0} is outside 0.5..=5")]
    OverlayScale(f32),
    /// The figure would be larger than [`MAX_FIGURE_SIZE`] PNG pixels on a side.
    #[error(
        "the figure would be {width}x{height} PNG pixels (at most {MAX_FIGURE_SIZE} per side): \
         use a smaller scale, pixel size or image size"
    )]
    TooLarge {
        /// PNG pixels across.
        width: u64,
        /// PNG pixels down.
        height: u64,
    },
    /// The marked pixel could not be probed.
    #[error(transparent)]
    Probe(#[from] ProbeError),
    /// The scene could not be rendered.
    #[error(transparent)]
    Render(#[from] RenderError),
    /// The figure would not fit the memory budget.
    #[error(transparent)]
    Memory(#[from] crate::budget::MemoryError),
    /// Drawing or encoding failed.
    #[error("cannot draw the figure: {0}")]
    Draw(String),
}

/// Checks the memory a figure needs before it is made: `renders` renders of `size` pixels
/// with every buffer, the probe's set-up triangles, and the figure's `pixels` (the canvas,
/// each view's raster, the overlay, the output image).
fn figure_fits(
    mesh: &crate::raster::ClipMesh,
    size: [u32; 2],
    renders: usize,
    pixels: [u64; 2],
) -> Result<(), crate::budget::MemoryError> {
    use crate::budget::{FIGURE_BYTES_PER_PIXEL, check};
    use crate::raster::Buffers;
    use crate::raster::footprint::render_need;
    let (v, t) = (mesh.vertices.len(), mesh.triangles.len());
    let need = renders as u64 * render_need(size[0], size[1], Buffers::All, v, t)
        + render_need(0, 0, Buffers::All, v, t)
        + pixels[0] * pixels[1] * FIGURE_BYTES_PER_PIXEL;
    check(|| format!("a {}x{} figure", pixels[0], pixels[1]), need)
}

/// One view of a figure.
#[derive(Clone, Debug)]
pub struct FigureView {
    /// What the view shows.
    pub content: ViewContent,
    /// Figure points of the image's top-left corner.
    pub origin: [u32; 2],
    /// The view's image at PNG resolution (`scale * pixel_size` pixels per rendered pixel).
    pub raster: image::RgbaImage,
    /// The overlays, in canvas coordinates (rendered pixels of the `W x H` image).
    pub overlay: Overlay,
    /// Labels and shapes are clipped to this box (points).
    pub clip: text::Box2,
}

/// A composed figure: views laid out in points, each with its raster and overlay.
#[derive(Clone, Debug)]
pub struct Figure {
    /// Figure size in points.
    pub size: [u32; 2],
    /// PNG pixels per point.
    pub scale: u32,
    /// Figure points per overlay point ([`FigureOptions::overlay_scale`]).
    pub overlay_scale: f32,
    /// Points per rendered pixel.
    pub pixel_size: u32,
    /// The rendered image size `W x H` the overlays refer to.
    pub canvas_size: [u32; 2],
    /// The background outside the image (and of the image on white).
    pub background: Background,
    /// The views, left to right.
    pub views: Vec<FigureView>,
    /// The caption below the views ([`FigureOptions::caption`]), when a pixel is marked.
    pub caption: Option<Caption>,
    /// The pinned pixel's trace (its derivation), made in the scene's mode.
    pub pinned: Option<PixelTrace>,
    /// The hovered pixel's trace.
    pub hovered: Option<PixelTrace>,
    /// The labels' language (English when Chinese was asked for but no CJK font is installed).
    pub lang: Lang,
}

impl Figure {
    /// PNG size in pixels: the point size times the scale.
    pub fn pixel_dimensions(&self) -> [u32; 2] {
        self.size.map(|v| v * self.scale)
    }

    /// Renders `scene` (at its size, in its mode) as the canvas would show it with `options`,
    /// probing the marked pixels with the same stages.
    pub fn compose(
        scene: &Scene,
        texture: &Texture,
        options: &FigureOptions,
    ) -> Result<Figure, FigureError> {
        Figure::compose_in(scene, texture, options, Lang::En)
    }

    /// [`Figure::compose`] with the labels in `lang`. Chinese labels need a system CJK font
    /// ([`crate::i18n::cjk_font`]); without one the labels stay English (never boxes), and
    /// [`Figure::lang`] says which language was used.
    pub fn compose_in(
        scene: &Scene,
        texture: &Texture,
        options: &FigureOptions,
        lang: Lang,
    ) -> Result<Figure, FigureError> {
        let lang = match lang {
            Lang::Zh if crate::i18n::cjk_font().is_none() => Lang::En,
            l => l,
        };
        let o = options;
        if !SCALES.contains(&o.scale) {
            return Err(FigureError::Scale(o.scale));
        }
        if !(1..=32).contains(&o.pixel_size) {
            return Err(FigureError::PixelSize(o.pixel_size));
        }
        let k = o.overlay_scale;
        if !(OVERLAY_SCALE_RANGE.0..=OVERLAY_SCALE_RANGE.1).contains(&k) {
            return Err(FigureError::OverlayScale(k));
        }
        let (w, h) = scene.size();
        let settings = scene.settings();
        let mode = settings.mode;
        let contents = view_contents(o.compare, mode);
        let n = contents.len() as u32;

        // Layout in points.
        let (view_w, view_h) = (
            u64::from(w) * u64::from(o.pixel_size),
            u64::from(h) * u64::from(o.pixel_size),
        );
        let [m, gap, strip] = layout_points(k).map(u64::from);
        // A difference view keeps room right of its image for the colour bar.
        let bar = if contents.contains(&ViewContent::Difference) {
            (overlay::COLOR_BAR_ROOM * k).ceil() as u64
        } else {
            0
        };
        let total_w = 2 * m + u64::from(n) * view_w + u64::from(n - 1) * gap + bar;
        let total_h = 2 * m + strip + view_h;
        let (px_w, px_h) = (total_w * u64::from(o.scale), total_h * u64::from(o.scale));
        if px_w > u64::from(MAX_FIGURE_SIZE) || px_h > u64::from(MAX_FIGURE_SIZE) {
            return Err(FigureError::TooLarge {
                width: px_w,
                height: px_h,
            });
        }

        // The renders, again at the scale when the pixel size is 1.
        let multiple = if o.pixel_size == 1 { o.scale } else { 1 };
        let upscale = o.pixel_size * o.scale / multiple;
        let mut hi = scene.clone();
        hi.set_size(w * multiple, h * multiple);
        let mesh = hi.to_mesh();
        let modes = modes_for(o.compare, mode);
        figure_fits(
            &mesh,
            [w * multiple, h * multiple],
            modes.len(),
            [px_w, px_h],
        )?;

        // The traces, on the scene at its own size, in its mode (as the inspector shows them).
        let prober = Prober::new(scene, texture, &settings)?;
        let trace = |p: Option<[u32; 2]>| p.map(|[x, y]| prober.pixel(x, y)).transpose();
        let pinned = trace(o.pinned)?;
        let hovered = trace(o.hovered)?;

        // The caption below the views (and their bottom margin), as wide as the views.
        let caption = o
            .caption
            .then(|| pinned.as_ref().or(hovered.as_ref()))
            .flatten()
            .map(|t| {
                caption::layout(
                    t,
                    [w, h],
                    lang,
                    [m as f32, total_h as f32],
                    (total_w - 2 * m) as f32,
                    k,
                )
            });
        let total_h = match &caption {
            Some(c) => total_h + c.height().ceil() as u64 + m,
            None => total_h,
        };
        if total_h * u64::from(o.scale) > u64::from(MAX_FIGURE_SIZE) {
            return Err(FigureError::TooLarge {
                width: px_w,
                height: total_h * u64::from(o.scale),
            });
        }

        // On a white figure (for print) the image's background is white too: no dark block
        // around the quad on paper.
        let base = hi.settings();
        let image_background = super::image_background(o.background, base.background);
        let mut renders: Vec<(Interpolation, Render)> = Vec::new();
        for m in modes {
            let s = RenderSettings {
                mode: m,
                background: image_background,
                ..base
            };
            renders.push((m, crate::raster::render(&mesh, texture, &s)?));
        }
        let render_of = |m: Interpolation| {
            renders
                .iter()
                .find(|(k, _)| *k == m)
                .or(renders.first())
                .map(|(_, r)| r)
        };
        let heat = (o.compare == Compare::Difference)
            .then(|| {
                render_of(mode)
                    .map(|r| heatmap::heatmap(&r.frame, (texture.width(), texture.height())))
            })
            .flatten()
            .transpose()?;

        let handles: Vec<HandleMark> = if o.show_handles {
            vertices_on_screen(
                scene,
                Viewport {
                    width: w,
                    height: h,
                },
            )
            .iter()
            .enumerate()
            .map(|(k, v)| HandleMark {
                index: k,
                window: v.window,
                w: v.w(),
                active: false,
            })
            .collect()
        } else {
            Vec::new()
        };

        let wipe_px = wipe_column(o.wipe, w) * multiple;
        let mut views = Vec::new();
        for (i, content) in contents.into_iter().enumerate() {
            let pixels: Vec<[u8; 4]> = match content {
                ViewContent::Mode(m) => render_of(m)
                    .map(|r| r.frame.color.clone())
                    .unwrap_or_default(),
                ViewContent::Difference => {
                    heat.as_ref().map(|h| h.pixels.clone()).unwrap_or_default()
                }
                ViewContent::Wipe => match (
                    render_of(Interpolation::Affine),
                    render_of(Interpolation::Perspective),
                ) {
                    (Some(a), Some(p)) => {
                        wipe_pixels(&a.frame.color, &p.frame.color, w * multiple, wipe_px)
                    }
                    _ => Vec::new(),
                },
            };
            let raster = upscaled(&pixels, [w * multiple, h * multiple], upscale)?;
            let input = OverlayInput {
                size: [w, h],
                pixel_size: o.pixel_size,
                pixels_per_point: k,
                mode: match content {
                    ViewContent::Mode(m) => Some(m),
                    _ => None,
                },
                show_grid: o.show_grid,
                handles: handles.clone(),
                hover: hovered.as_ref().map(pixel_mark),
                pin: pinned.as_ref().map(pixel_mark),
                clipped: pinned.as_ref().or(hovered.as_ref()).and_then(clip_mark),
                sub_areas: o.show_sub_areas,
                sub_area_fill: settings.shading != crate::raster::Shading::Texture,
                wipe: (content == ViewContent::Wipe).then_some((
                    f64::from(o.wipe) * f64::from(w),
                    Interpolation::Affine,
                    Interpolation::Perspective,
                )),
                color_bar: match content {
                    ViewContent::Difference => heat.as_ref().map(|h| h.scale_max),
                    _ => None,
                },
            };
            let origin = [(m + i as u64 * (view_w + gap)) as u32, (m + strip) as u32];
            // The margin around the view, but between two views only half the gap each: one
            // view's labels never reach over the other's.
            let (left, right) = (
                if i == 0 { m as f32 } else { gap as f32 / 2.0 },
                if i + 1 == n as usize {
                    (m + bar) as f32
                } else {
                    gap as f32 / 2.0
                },
            );
            let clip = [
                origin[0] as f32 - left,
                (u64::from(origin[1]) - strip - m) as f32,
                (u64::from(origin[0]) + view_w) as f32 + right,
                (u64::from(origin[1]) + view_h + m) as f32,
            ];
            views.push(FigureView {
                content,
                origin,
                raster,
                overlay: overlay::build_in(&input, lang).scaled(k),
                clip,
            });
        }
        Ok(Figure {
            size: [total_w as u32, total_h as u32],
            scale: o.scale,
            overlay_scale: k,
            pixel_size: o.pixel_size,
            canvas_size: [w, h],
            background: o.background,
            views,
            caption,
            pinned,
            hovered,
            lang,
        })
    }
}

/// A `size` RGBA image with every pixel repeated `factor` x `factor` times.
fn upscaled(
    pixels: &[[u8; 4]],
    size: [u32; 2],
    factor: u32,
) -> Result<image::RgbaImage, FigureError> {
    let [w, h] = size;
    if pixels.len() != (w as usize) * (h as usize) {
        return Err(FigureError::Draw(format!(
            "an image of {} pixels is not {w}x{h}",
            pixels.len()
        )));
    }
    let f = factor.max(1);
    let (uw, uh) = (w * f, h * f);
    let mut out = crate::budget::try_image(uw, uh, [0; 4], || format!("the {uw}x{uh} view image"))?;
    for (x, y, px) in out.enumerate_pixels_mut() {
        *px = image::Rgba(pixels[((y / f) * w + x / f) as usize]);
    }
    Ok(out)
}
