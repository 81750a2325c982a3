//! Moving figures: a sweep ([`Sweep`]) of a scene as an animation (GIF, APNG, animated WebP,
//! MP4 through ffmpeg) for lecture slides (`barylab animate`, `docs/animation.md`).
//!
//! Every frame is a figure: [`Figure::compose_in`] of the scene as the sweep has changed it,
//! rasterized by [`figure::png::rasterize`], so a frame has the figure's overlays, labels,
//! caption and language, and the first and last frames are the still figures of the sweep's
//! end states. The fill sweeps hide the pixels the rasterizer has not visited yet (they show
//! the image's background) and outline the one it is at ([`visit`]); nothing else is drawn
//! here. Frames are rendered in parallel (rayon), then encoded ([`mod@encode`]).
//!
//! - [`sweep`]: what each sweep changes, as a function of the frame's time `t = i / (N - 1)`.
//! - [`visit`]: the order each rasterizer visits the pixels.
//! - [`mod@encode`]: the formats; [`palette`]: one GIF palette for the whole animation.

pub mod encode;
pub mod palette;
pub mod sweep;
pub mod visit;
mod webp;

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use rayon::prelude::*;

use crate::edit::EditError;
use crate::figure::overlay::{PIN, SHADOW, Shape, Stroke};
use crate::figure::{self, Background, Figure, FigureError, FigureOptions};
use crate::i18n::Lang;
use crate::raster::Texture;
use crate::raster::render::RenderError;
use crate::raster::settings::Rasterizer;
use crate::scene::Scene;

pub use encode::{Format, encode};
pub use sweep::Sweep;

/// The fewest and most frames of an animation.
pub const FRAME_RANGE: (u32, u32) = (2, 1000);

/// Why an animation cannot be made.
#[derive(Debug, thiserror::Error)]
pub enum AnimateError {
    /// The sweep changes a world scene's quad.
    #[error("the {0} sweep tilts a quad: it needs a scene in the world form (`quad`)")]
    NeedsQuad(&'static str),
    /// The clip sweep moves a corner through the eye of a perspective camera.
    #[error(
        "the clip sweep needs a perspective camera (an orthographic one has no near plane to cross)"
    )]
    NeedsPerspective,
    /// The corner cannot be moved.
    #[error("--vertex: {0}")]
    Edit(EditError),
    /// A frame count outside [`FRAME_RANGE`].
    #[error("--frames {0}: an animation has 2 to 1000 frames")]
    Frames(u32),
    /// The row sweep's row crosses no triangle.
    #[error("row {0} covers no pixel of a triangle: choose another --pixel X,Y")]
    EmptyRow(u32),
    /// The fill sweeps' scene covers no pixel.
    #[error("the scene covers no pixel: there is nothing to fill")]
    NothingCovered,
    /// A frame could not be drawn.
    #[error("frame {frame}: {error}")]
    Figure {
        /// The frame, from 1.
        frame: usize,
        /// Why (part of this message).
        error: FigureError,
    },
    /// The visiting order could not be found.
    #[error(transparent)]
    Render(#[from] RenderError),
    /// The frames would not fit the memory budget.
    #[error(transparent)]
    Memory(#[from] crate::budget::MemoryError),
    /// Encoding failed.
    #[error("cannot encode the animation: {0}")]
    Encode(String),
    /// MP4 needs ffmpeg, which is not installed.
    #[error(
        "writing MP4 needs ffmpeg, which is not installed (or not on PATH): install it (e.g. \
         `apt install ffmpeg`), or write .gif, .apng or .webp"
    )]
    NoFfmpeg,
    /// The rendering was cancelled ([`Control::cancel`]).
    #[error("cancelled")]
    Cancelled,
}

/// What to animate: the sweep, the number of frames, the corner the depth and clip sweeps
/// move, and the figure options every frame is drawn with (the row sweep pins its pixel
/// and turns the caption on; the wipe sweep sets the comparison).
#[derive(Clone, Debug, PartialEq)]
pub struct Animation {
    /// What changes.
    pub sweep: Sweep,
    /// Frames, [`FRAME_RANGE`].
    pub frames: u32,
    /// The corner (mesh vertex index) the depth and clip sweeps move.
    pub vertex: usize,
    /// The figure options of every frame; the pinned pixel's row is the row sweep's.
    pub options: FigureOptions,
}

/// One frame before it is drawn: the scene and options, and for a fill sweep how many
/// pixels of the visiting order are drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameState {
    /// The scene as the sweep has changed it.
    pub scene: Scene,
    /// The figure options.
    pub options: FigureOptions,
    /// Fill sweeps: the first this many pixels of the order are shown.
    pub filled: Option<usize>,
}

/// The corner named `name` (A, B, C, ...; any case), as a mesh vertex index.
///
/// ```
/// assert_eq!(barylab::animate::vertex_by_name(" c"), Some(2));
/// assert_eq!(barylab::animate::vertex_by_name("AB"), None);
/// ```
pub fn vertex_by_name(name: &str) -> Option<usize> {
    (0..26).find(|&i| crate::scene::vertex_name(i).eq_ignore_ascii_case(name.trim()))
}

/// Frame `i`'s time `t = i / (n - 1)`.
fn time(i: u32, n: u32) -> f64 {
    f64::from(i) / f64::from(n.max(2) - 1)
}

/// The visiting order of the fill sweeps (`None` for the others).
fn order_of(scene: &Scene, sweep: Sweep) -> Result<Option<Vec<[u32; 2]>>, AnimateError> {
    let rasterizer = match sweep {
        Sweep::FillEdge => Rasterizer::EdgeFunction,
        Sweep::FillScanline | Sweep::Row => Rasterizer::Scanline,
        _ => return Ok(None),
    };
    let order = visit::visit_order(&scene.to_mesh(), &scene.settings(), rasterizer)?;
    if order.is_empty() {
        return Err(AnimateError::NothingCovered);
    }
    Ok(Some(order))
}

/// Every frame's scene and options. The row sweep walks from the first to the last covered
/// column of the pinned pixel's row (else the middle row), `x = lo + round(t (hi - lo))`;
/// a fill sweep shows `round(t n)` of the order's `n` pixels.
pub fn frame_states(scene: &Scene, anim: &Animation) -> Result<Vec<FrameState>, AnimateError> {
    let n = anim.frames;
    if !(FRAME_RANGE.0..=FRAME_RANGE.1).contains(&n) {
        return Err(AnimateError::Frames(n));
    }
    let order = order_of(scene, anim.sweep)?;
    let row = anim.options.pinned.map_or(scene.size().1 / 2, |[_, y]| y);
    let span = match (anim.sweep, &order) {
        (Sweep::Row, Some(order)) => {
            let xs = order.iter().filter(|p| p[1] == row).map(|p| p[0]);
            let lo = xs.clone().min().ok_or(AnimateError::EmptyRow(row))?;
            Some((lo, xs.max().unwrap_or(lo)))
        }
        _ => None,
    };
    (0..n)
        .map(|i| {
            let t = time(i, n);
            let (scene, mut options) = sweep::at(anim.sweep, scene, &anim.options, anim.vertex, t)?;
            if let Some((lo, hi)) = span {
                let x = lo + (t * f64::from(hi - lo)).round() as u32;
                options.pinned = Some([x, row]);
                options.caption = true;
            }
            let filled = match (anim.sweep, &order) {
                (Sweep::FillEdge | Sweep::FillScanline, Some(o)) => {
                    Some((t * o.len() as f64).round() as usize)
                }
                _ => None,
            };
            Ok(FrameState {
                scene,
                options,
                filled,
            })
        })
        .collect()
}

/// The image's colour where nothing is drawn, as [`Figure::compose_in`] renders it.
fn unvisited_color(scene: &Scene, options: &FigureOptions) -> [u8; 4] {
    figure::image_background(options.background, scene.settings().background)
}

/// Hides the pixels not among the first `filled` of `order` and outlines the last one shown
/// (none when all are shown, so the last frame is the still figure).
fn show_filled(fig: &mut Figure, order: &[[u32; 2]], filled: usize, color: [u8; 4]) {
    let [w, h] = fig.canvas_size;
    let mut shown = vec![false; w as usize * h as usize];
    for &[x, y] in &order[..filled.min(order.len())] {
        if x < w && y < h {
            shown[(y * w + x) as usize] = true;
        }
    }
    let k = fig.overlay_scale;
    for view in &mut fig.views {
        let (rw, rh) = view.raster.dimensions();
        for (px, py, c) in view.raster.enumerate_pixels_mut() {
            let x = (u64::from(px) * u64::from(w) / u64::from(rw)) as u32;
            let y = (u64::from(py) * u64::from(h) / u64::from(rh)) as u32;
            if !shown[(y * w + x) as usize] {
                c.0 = color;
            }
        }
        if let Some(&[x, y]) = order
            .get(filled.wrapping_sub(1))
            .filter(|_| filled < order.len())
        {
            let (x0, y0) = (f64::from(x), f64::from(y));
            let square = vec![
                glam::DVec2::new(x0, y0),
                glam::DVec2::new(x0 + 1.0, y0),
                glam::DVec2::new(x0 + 1.0, y0 + 1.0),
                glam::DVec2::new(x0, y0 + 1.0),
            ];
            for stroke in [Stroke::new(6.0 * k, SHADOW), Stroke::new(3.0 * k, PIN)] {
                view.overlay.shapes.push(Shape::Polygon {
                    points: square.clone(),
                    fill: [0, 0, 0, 0],
                    stroke: Some(stroke),
                    dashed: false,
                });
            }
        }
    }
}

/// Frame `index`'s image.
fn draw(
    state: &FrameState,
    index: usize,
    texture: &Texture,
    order: Option<&[[u32; 2]]>,
    lang: Lang,
) -> Result<image::RgbaImage, AnimateError> {
    let err = |error| AnimateError::Figure {
        frame: index + 1,
        error,
    };
    let mut fig = Figure::compose_in(&state.scene, texture, &state.options, lang).map_err(err)?;
    if let (Some(order), Some(filled)) = (order, state.filled) {
        let color = unvisited_color(&state.scene, &state.options);
        show_filled(&mut fig, order, filled, color);
    }
    figure::png::rasterize(&fig).map_err(err)
}

/// Every frame of `anim` on `scene`, labels in `lang`, rendered in parallel on the current
/// rayon pool ([`render_frames_with`] without progress or cancelling).
pub fn render_frames(
    scene: &Scene,
    texture: &Texture,
    anim: &Animation,
    lang: Lang,
) -> Result<Vec<image::RgbaImage>, AnimateError> {
    render_frames_with(scene, texture, anim, lang, &Control::default())
}

/// [`render_frames`], counting the frames drawn in `control` and stopping with
/// [`AnimateError::Cancelled`] once it is cancelled.
pub fn render_frames_with(
    scene: &Scene,
    texture: &Texture,
    anim: &Animation,
    lang: Lang,
    control: &Control,
) -> Result<Vec<image::RgbaImage>, AnimateError> {
    let states = frame_states(scene, anim)?;
    let order = order_of(scene, anim.sweep)?;
    let order = order.as_deref().filter(|_| anim.sweep != Sweep::Row);
    render_all(&states, texture, order, lang, control)
}

/// A recorded list of states (a drag in the app, one state per frame at a fixed frame rate),
/// each drawn as the still figure of its scene and options: frame `k` is
/// `figure::png::rasterize(Figure::compose_in(states[k]))`, padded like [`render_frames`].
/// The fill sweeps' `filled` is ignored (a recording has no visiting order).
pub fn render_states(
    states: &[FrameState],
    texture: &Texture,
    lang: Lang,
    control: &Control,
) -> Result<Vec<image::RgbaImage>, AnimateError> {
    let n = u32::try_from(states.len()).unwrap_or(u32::MAX);
    if !(FRAME_RANGE.0..=FRAME_RANGE.1).contains(&n) {
        return Err(AnimateError::Frames(n));
    }
    render_all(states, texture, None, lang, control)
}

/// How far a rendering has got, and a way to stop it from another thread (the app's Export
/// animation window).
#[derive(Debug, Default)]
pub struct Control {
    /// Frames drawn so far.
    pub done: AtomicUsize,
    /// Set to stop: the frames not yet started are not drawn.
    pub cancel: AtomicBool,
}

/// Draws `states` in parallel (the first alone: its size bounds the memory), padding frames
/// of different sizes (a caption that wraps differently) to the largest at the top left with
/// the figure's background.
fn render_all(
    states: &[FrameState],
    texture: &Texture,
    order: Option<&[[u32; 2]]>,
    lang: Lang,
    control: &Control,
) -> Result<Vec<image::RgbaImage>, AnimateError> {
    let Some(first_state) = states.first() else {
        return Err(AnimateError::Frames(0));
    };
    let draw_one = |i: usize, s: &FrameState| {
        if control.cancel.load(Ordering::Relaxed) {
            return Err(AnimateError::Cancelled);
        }
        let frame = draw(s, i, texture, order, lang)?;
        control.done.fetch_add(1, Ordering::Relaxed);
        Ok(frame)
    };
    let first = draw_one(0, first_state)?;
    let (w, h) = first.dimensions();
    crate::budget::check(
        || format!("{} frames of {w}x{h}", states.len()),
        u64::from(w) * u64::from(h) * 4 * 2 * states.len() as u64,
    )?;
    let rest: Vec<image::RgbaImage> = states[1..]
        .par_iter()
        .enumerate()
        .map(|(i, s)| draw_one(i + 1, s))
        .collect::<Result<_, _>>()?;
    let mut frames = vec![first];
    frames.extend(rest);
    let (mw, mh) = frames
        .iter()
        .fold((0, 0), |(a, b), f| (a.max(f.width()), b.max(f.height())));
    let fill = match first_state.options.background {
        Background::White => image::Rgba([255, 255, 255, 255]),
        Background::Transparent => image::Rgba([0, 0, 0, 0]),
    };
    for f in &mut frames {
        if f.dimensions() != (mw, mh) {
            let mut padded = image::RgbaImage::from_pixel(mw, mh, fill);
            image::imageops::replace(&mut padded, f, 0, 0);
            *f = padded;
        }
    }
    Ok(frames)
}
