//! Figures for lecture notes: the canvas as the app shows it (one view, side by side, wipe or
//! difference heatmap) with its overlays, re-rendered by the CPU rasterizer at 1x, 2x or 4x,
//! as SVG (raster embedded, overlays as vector shapes and real text) or PNG. No egui here: the
//! app's Export and `barylab figure` both call [`Figure::compose`] and [`export`].
//!
//! - [`overlay`]: the single plain-data description of everything drawn over the image (the
//!   app paints it with egui, [`svg`] writes it as SVG).
//! - [`text`]: the overlay font, text measurement and label placement (shared with the app).
//! - [`svg`], [`png`]: the figure as an SVG document, and that document rasterized by resvg.
//! - [`heatmap`]: the difference view's colours.
//! - [`export`]: writing a figure's files (PNG, SVG, derivation, scene) under fresh names.
//!
//! Sizes: a figure is laid out in points; at scale 1 one point is one PNG pixel. A view shows
//! the `W x H` rendered image with `pixel_size` points per rendered pixel, as on screen at
//! that pixel size. At scale `s` the PNG has `s` pixels per point: with pixel size 1 the scene
//! is rendered again at `sW x sH` (sharper, same picture); with a larger pixel size the
//! rendered pixels are the subject, so they stay the scene's pixels, drawn as
//! `s * pixel_size` square PNG pixels each.

pub mod bounds;
pub mod export;
pub mod heatmap;
pub mod overlay;
pub mod png;
pub mod svg;
pub mod text;

use crate::i18n::Lang;
use glam::{DVec2, DVec4};
use serde::{Deserialize, Serialize};

use self::overlay::{HandleMark, Overlay, OverlayInput, PixelMark, TriangleMark};
use crate::probe::{PixelTrace, ProbeError, Prober};
use crate::raster::project::{Viewport, ndc_from_clip, window_from_ndc};
use crate::raster::render::Render;
use crate::raster::render::RenderError;
use crate::raster::{Interpolation, RenderSettings, Texture};
use crate::scene::Scene;

/// How the canvas compares the two interpolation modes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Compare {
    /// One view in the scene's mode.
    #[default]
    Single,
    /// Affine on the left, perspective-correct on the right, same view.
    SideBySide,
    /// One view split by a draggable line: affine left of it, perspective-correct right.
    Wipe,
    /// |uv affine - uv perspective| in texels as a heatmap.
    Difference,
}

impl Compare {
    pub const ALL: [Compare; 4] = [
        Compare::Single,
        Compare::SideBySide,
        Compare::Wipe,
        Compare::Difference,
    ];
}

/// What one view of the canvas shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ViewContent {
    Mode(Interpolation),
    Wipe,
    Difference,
}

/// The views a comparison shows, left to right; `mode` is the scene's mode.
pub fn view_contents(compare: Compare, mode: Interpolation) -> Vec<ViewContent> {
    match compare {
        Compare::Single => vec![ViewContent::Mode(mode)],
        Compare::SideBySide => vec![
            ViewContent::Mode(Interpolation::Affine),
            ViewContent::Mode(Interpolation::Perspective),
        ],
        Compare::Wipe => vec![ViewContent::Wipe],
        Compare::Difference => vec![ViewContent::Difference],
    }
}

/// The modes a comparison needs rendered (`mode`: the scene's).
pub fn modes_for(compare: Compare, mode: Interpolation) -> Vec<Interpolation> {
    match compare {
        Compare::Single | Compare::Difference => vec![mode],
        Compare::SideBySide | Compare::Wipe => {
            vec![Interpolation::Affine, Interpolation::Perspective]
        }
    }
}

/// The wipe line's column: affine left of it, perspective-correct from it on.
///
/// `column = round(wipe * width)`.
///
/// ```
/// assert_eq!(barylab::figure::wipe_column(0.5, 801), 401);
/// ```
pub fn wipe_column(wipe: f32, width: u32) -> u32 {
    (wipe.clamp(0.0, 1.0) * width as f32).round() as u32
}

/// The wipe view's pixels: the affine image left of `column`, the perspective-correct one from
/// it on (both `width` pixels wide, row by row).
pub fn wipe_pixels(
    affine: &[[u8; 4]],
    perspective: &[[u8; 4]],
    width: u32,
    column: u32,
) -> Vec<[u8; 4]> {
    let row = width as usize;
    affine
        .iter()
        .zip(perspective)
        .enumerate()
        .map(|(k, (ca, cp))| {
            if ((k % row) as u32) < column {
                *ca
            } else {
                *cp
            }
        })
        .collect()
}

/// Smallest clip w at which a vertex is drawn as a handle: at or behind the camera plane a
/// vertex has no position on screen.
pub const MIN_HANDLE_W: f64 = 1e-6;

/// A mesh vertex's clip and window position.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexOnScreen {
    /// Clip-space position.
    pub clip: DVec4,
    /// Window position in pixels (image coordinates, y down), unsnapped; `None` when the vertex
    /// is at or behind the camera (w <= [`MIN_HANDLE_W`]).
    pub window: Option<DVec2>,
}

impl VertexOnScreen {
    /// The vertex's clip w (its view-space distance for a perspective camera).
    pub fn w(&self) -> f64 {
        self.clip.w
    }
}

/// The mesh vertices' clip positions and window positions for a viewport (none for a model:
/// it has too many vertices for handles).
pub fn vertices_on_screen(scene: &Scene, viewport: Viewport) -> Vec<VertexOnScreen> {
    if let Scene::Model(_) = scene {
        return Vec::new();
    }
    let mut sized = scene.clone();
    sized.set_size(viewport.width, viewport.height);
    sized
        .to_mesh()
        .vertices
        .iter()
        .map(|v| VertexOnScreen {
            clip: v.clip,
            window: (v.clip.w > MIN_HANDLE_W && v.clip.is_finite())
                .then(|| window_from_ndc(ndc_from_clip(v.clip), viewport).truncate()),
        })
        .collect()
}

/// The triangle whose weights a trace shows (the one that wrote the pixel, or the nearest
/// one for an uncovered pixel), as rasterized: unsnapped window positions (the weights come
/// from them), mesh vertex of each
/// corner (`None` for a point the clipper made) and the screen weights.
pub fn triangle_mark(trace: &PixelTrace) -> Option<TriangleMark> {
    let d = trace.detail.as_ref()?;
    let v = &d.raster.vertices;
    Some(TriangleMark {
        vertices: [0, 1, 2].map(|k| DVec2::from(v[k].window)),
        mesh_indices: [0, 1, 2].map(|k| {
            v[k].source_vertex
                .and_then(|s| d.vertices.get(s))
                .map(|vt| vt.index as usize)
        }),
        weights: d.screen.rasterizer,
    })
}

/// The overlay's mark of a traced pixel.
pub fn pixel_mark(trace: &PixelTrace) -> PixelMark {
    PixelMark {
        pixel: trace.pixel,
        triangle: triangle_mark(trace),
    }
}

/// The image's background on a white figure.
const WHITE: [u8; 4] = [255, 255, 255, 255];

/// The figure's background outside the image (title strip, margins, gap); a white figure
/// (for print) draws the image on white too.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Background {
    #[default]
    Transparent,
    White,
}

/// Scales a figure can be exported at.
pub const SCALES: [u32; 3] = [1, 2, 4];

/// What a figure shows, as the canvas does: the view settings and the marked pixels.
#[derive(Clone, Debug, PartialEq)]
pub struct FigureOptions {
    pub compare: Compare,
    /// Figure points per rendered pixel (the canvas's pixel size).
    pub pixel_size: u32,
    /// Wipe line position as a fraction of the image width.
    pub wipe: f32,
    pub show_grid: bool,
    pub show_handles: bool,
    pub show_sub_areas: bool,
    /// The pinned pixel (marker, triangle and sub-triangles; its derivation is exported).
    pub pinned: Option<[u32; 2]>,
    /// The hovered pixel (marker with crosshair).
    pub hovered: Option<[u32; 2]>,
    /// PNG pixels per figure point: 1, 2 or 4.
    pub scale: u32,
    pub background: Background,
    /// Figure points per overlay point: the screen's pixels per point (the app's text size
    /// times the display's scale). Labels, lines, handles, the title strip and the margins
    /// are this much larger, so the figure looks as the canvas did on screen.
    pub overlay_scale: f32,
}

impl Default for FigureOptions {
    fn default() -> Self {
        Self {
            compare: Compare::Single,
            pixel_size: 1,
            wipe: 0.5,
            show_grid: true,
            show_handles: true,
            show_sub_areas: true,
            pinned: None,
            hovered: None,
            scale: 1,
            background: Background::Transparent,
            overlay_scale: 1.0,
        }
    }
}

impl FigureOptions {
    /// The `barylab figure` options that make this figure (after the scene file; before
    /// `-o`). Defaults are left out.
    ///
    /// ```
    /// use barylab::figure::{Background, Compare, FigureOptions};
    /// let o = FigureOptions {
    ///     compare: Compare::SideBySide,
    ///     pinned: Some([3, 4]),
    ///     scale: 2,
    ///     background: Background::White,
    ///     show_grid: false,
    ///     ..FigureOptions::default()
    /// };
    /// assert_eq!(o.cli_args().join(" "),
    ///            "--pixel 3,4 --compare side --scale 2 --background white --no-grid");
    /// ```
    pub fn cli_args(&self) -> Vec<String> {
        let mut a: Vec<String> = Vec::new();
        let mut push = |k: &str, v: String| {
            a.push(k.to_string());
            a.push(v);
        };
        if let Some([x, y]) = self.pinned {
            push("--pixel", format!("{x},{y}"));
        }
        if let Some([x, y]) = self.hovered {
            push("--hover", format!("{x},{y}"));
        }
        let compare = match self.compare {
            Compare::Single => None,
            Compare::SideBySide => Some("side"),
            Compare::Wipe => Some("wipe"),
            Compare::Difference => Some("diff"),
        };
        if let Some(c) = compare {
            push("--compare", c.to_string());
        }
        if self.compare == Compare::Wipe && self.wipe != 0.5 {
            push("--wipe", format!("{}", self.wipe));
        }
        if self.scale != 1 {
            push("--scale", self.scale.to_string());
        }
        if self.pixel_size != 1 {
            push("--pixel-size", self.pixel_size.to_string());
        }
        if self.overlay_scale != 1.0 {
            push("--overlay-scale", format!("{}", self.overlay_scale));
        }
        if self.background == Background::White {
            push("--background", "white".to_string());
        }
        for (shown, flag) in [
            (self.show_grid, "--no-grid"),
            (self.show_handles, "--no-handles"),
            (self.show_sub_areas, "--no-sub-areas"),
        ] {
            if !shown {
                a.push(flag.to_string());
            }
        }
        a
    }
}

/// Overlay points of margin around each view: a handle on the image's edge (radius
/// [`overlay::HANDLE_RADIUS`] + its outline) is drawn whole.
pub const FIGURE_MARGIN: u32 = 16;
/// Overlay points between the two views of the side-by-side comparison (as on screen).
pub const SIDE_BY_SIDE_GAP: u32 = 10;
/// Range of [`FigureOptions::overlay_scale`] (the app's text size range times a HiDPI
/// display's 2).
pub const OVERLAY_SCALE_RANGE: (f32, f32) = (0.5, 5.0);

/// The figure's margin, side-by-side gap and title strip in figure points for an overlay
/// scale `k`: `round(k * points)` each.
///
/// ```
/// assert_eq!(barylab::figure::layout_points(1.5), [24, 15, 66]);
/// ```
pub fn layout_points(k: f32) -> [u32; 3] {
    [
        FIGURE_MARGIN as f32,
        SIDE_BY_SIDE_GAP as f32,
        overlay::TITLE_STRIP,
    ]
    .map(|v| (v * k).round() as u32)
}
/// Largest figure side in PNG pixels.
pub const MAX_FIGURE_SIZE: u32 = 16384;

/// Why a figure cannot be made.
#[derive(Debug, thiserror::Error)]
pub enum FigureError {
    #[error("scale {0} is not one of 1, 2, 4")]
    Scale(u32),
    #[error("pixel size {0} is outside 1..=32")]
    PixelSize(u32),
    #[error("overlay scale {0} is outside 0.5..=5")]
    OverlayScale(f32),
    #[error(
        "the figure would be {width}x{height} PNG pixels (at most {MAX_FIGURE_SIZE} per side): \
         use a smaller scale, pixel size or image size"
    )]
    TooLarge { width: u64, height: u64 },
    #[error(transparent)]
    Probe(#[from] ProbeError),
    #[error(transparent)]
    Render(#[from] RenderError),
    #[error(transparent)]
    Memory(#[from] crate::budget::MemoryError),
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
    use crate::budget::{FIGURE_BYTES_PER_PIXEL, check, render_need};
    use crate::raster::Buffers;
    let (v, t) = (mesh.vertices.len(), mesh.triangles.len());
    let need = renders as u64 * render_need(size[0], size[1], Buffers::All, v, t)
        + render_need(0, 0, Buffers::All, v, t)
        + pixels[0] * pixels[1] * FIGURE_BYTES_PER_PIXEL;
    check(|| format!("a {}x{} figure", pixels[0], pixels[1]), need)
}

/// One view of a figure.
#[derive(Clone, Debug)]
pub struct FigureView {
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
    pub background: Background,
    pub views: Vec<FigureView>,
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
        let total_w = 2 * m + u64::from(n) * view_w + u64::from(n - 1) * gap;
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

        // On a white figure (for print) the image's background is white too: no dark block
        // around the quad on paper.
        let base = hi.settings();
        let image_background = match o.background {
            Background::White => WHITE,
            Background::Transparent => base.background,
        };
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
            .flatten();

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
                sub_areas: o.show_sub_areas,
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
            let clip = [
                (u64::from(origin[0]) - m) as f32,
                (u64::from(origin[1]) - strip - m) as f32,
                (u64::from(origin[0]) + view_w + m) as f32,
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
    Ok(image::RgbaImage::from_fn(w * f, h * f, |x, y| {
        image::Rgba(pixels[((y / f) * w + x / f) as usize])
    }))
}
