//! What each sweep changes between its first and last frame, as a function of the frame's
//! time `t` in `[0, 1]` (`t = i / (N - 1)` for frame `i` of `N`). A frame is a scene and the
//! figure options it is drawn with; the drawing is [`crate::figure`]'s.

use crate::edit::{self, PUSH_FACTOR_RANGE};
use crate::figure::{Compare, FigureOptions};
use crate::raster::camera::Projection;
use crate::raster::project::Viewport;
use crate::scene::Scene;

use super::AnimateError;

/// What an animation sweeps.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sweep {
    /// The wipe line across the image, affine left of it, perspective-correct right:
    /// `wipe = 1 - t` (the first frame all affine, the last all perspective-correct).
    AffinePerspective,
    /// A corner pushed away along its view ray (it stays on the screen): its w multiplied by
    /// `1 + 7 t`, from 1x to 8x.
    Depth,
    /// The quad tilting about its centre (the view of a camera tilting the other way): its
    /// pitch from the scene's to the scene's + [`TILT_DEGREES`].
    Tilt,
    /// The pinned pixel walking along its row across the covered columns, with the caption's
    /// weights and uv.
    Row,
    /// The edge-function rasterizer filling the triangles pixel by pixel in its block order.
    FillEdge,
    /// The scanline rasterizer filling the triangles row by row, span by span.
    FillScanline,
    /// A corner moved along the view depth through the eye: its view z (clip z and w)
    /// multiplied by `1 - 2 t`, so it crosses the near plane on the way (behind the camera at
    /// the end).
    Clip,
}

/// How far the `tilt` sweep tilts the quad, in degrees.
pub const TILT_DEGREES: f64 = 60.0;

/// The largest w factor of the `depth` sweep.
pub const DEPTH_FACTOR: f64 = 8.0;

impl Sweep {
    /// Every sweep, in the order `--help` lists them.
    pub const ALL: [Sweep; 7] = [
        Sweep::AffinePerspective,
        Sweep::Depth,
        Sweep::Tilt,
        Sweep::Row,
        Sweep::FillEdge,
        Sweep::FillScanline,
        Sweep::Clip,
    ];

    /// The sweep's name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Sweep::AffinePerspective => "affine-perspective",
            Sweep::Depth => "depth",
            Sweep::Tilt => "tilt",
            Sweep::Row => "row",
            Sweep::FillEdge => "fill-edge",
            Sweep::FillScanline => "fill-scanline",
            Sweep::Clip => "clip",
        }
    }

    /// The sweep called `name`, if any.
    ///
    /// ```
    /// use barylab::animate::Sweep;
    /// assert_eq!(Sweep::from_name("fill-edge"), Some(Sweep::FillEdge));
    /// assert_eq!(Sweep::from_name("spin"), None);
    /// ```
    pub fn from_name(name: &str) -> Option<Sweep> {
        Sweep::ALL.into_iter().find(|s| s.name() == name)
    }

    /// Whether the sweep moves a corner (`--vertex`).
    pub fn moves_vertex(self) -> bool {
        matches!(self, Sweep::Depth | Sweep::Clip)
    }
}

/// `scene` and `options` at time `t` of `sweep` (the fill and row sweeps' per-frame parts
/// are in [`super::frame_states`]).
pub(super) fn at(
    sweep: Sweep,
    scene: &Scene,
    options: &FigureOptions,
    vertex: usize,
    t: f64,
) -> Result<(Scene, FigureOptions), AnimateError> {
    let mut s = scene.clone();
    let mut o = options.clone();
    let (w, h) = scene.size();
    let viewport = Viewport {
        width: w,
        height: h,
    };
    match sweep {
        Sweep::AffinePerspective => {
            o.compare = Compare::Wipe;
            o.wipe = (1.0 - t) as f32;
        }
        Sweep::Depth => push_by(&mut s, vertex, 1.0 + (DEPTH_FACTOR - 1.0) * t, viewport)?,
        Sweep::Tilt => match &mut s {
            Scene::World(q) => q.tilt.pitch_deg += TILT_DEGREES * t,
            _ => return Err(AnimateError::NeedsQuad(sweep.name())),
        },
        Sweep::Clip => through_eye(&mut s, vertex, 1.0 - 2.0 * t)?,
        Sweep::Row | Sweep::FillEdge | Sweep::FillScanline => {}
    }
    Ok((s, o))
}

/// Pushes `vertex` away by `factor` (its w multiplied by it) in steps the app's push allows
/// ([`PUSH_FACTOR_RANGE`]).
fn push_by(
    scene: &mut Scene,
    vertex: usize,
    factor: f64,
    viewport: Viewport,
) -> Result<(), AnimateError> {
    let mut left = factor;
    while (left - 1.0).abs() > 1e-12 {
        let step = left.clamp(PUSH_FACTOR_RANGE.0, PUSH_FACTOR_RANGE.1);
        edit::push_vertex(scene, vertex, step, viewport).map_err(AnimateError::Edit)?;
        left /= step;
    }
    Ok(())
}

/// Multiplies `vertex`'s view depth by `k` (world form: its view z; clip form: its clip z and
/// w), keeping its other view (clip) coordinates: with `k` from 1 to -1 it moves through the
/// near plane and the eye's plane to behind the camera.
fn through_eye(scene: &mut Scene, vertex: usize, k: f64) -> Result<(), AnimateError> {
    edit::bake_tilt(scene);
    match scene {
        Scene::World(q) => {
            let corner = q
                .quad
                .get_mut(vertex)
                .ok_or(AnimateError::Edit(edit::EditError::NoVertex(vertex)))?;
            if matches!(q.camera.projection, Projection::Orthographic { .. }) {
                return Err(AnimateError::NeedsPerspective);
            }
            let view_from_world = q.camera.view_from_world();
            let mut view = view_from_world.transform_point3(corner.position);
            view.z *= k;
            corner.position = view_from_world.inverse().transform_point3(view);
        }
        Scene::Clip(c) => {
            let v = c
                .vertices
                .get_mut(vertex)
                .ok_or(AnimateError::Edit(edit::EditError::NoVertex(vertex)))?;
            v.clip.z *= k;
            v.clip.w *= k;
        }
        Scene::Model(_) => return Err(AnimateError::Edit(edit::EditError::Model)),
    }
    Ok(())
}
