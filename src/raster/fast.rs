//! The fast path's preparation of a mesh (colour and depth, optionally the uv buffers): what
//! [`render_into`](super::render::render_into) draws without keeping every buffer. It draws
//! each triangle with [`draw`](super::draw)'s kernel and lane glue, as the full render does.
//!
//! The full render keeps a [`PreparedTriangle`] per source triangle (its three window
//! vertices with both attribute sets, edges, weight planes: about 900 bytes) because the
//! probe and the inspector read them. Drawing needs none of that kept: here
//!
//! 1. every mesh vertex is projected **once** ([`ProjectedVertex`]: window position, snapped
//!    position, depth, 1/w, and whether it is inside every clipping plane), shared by the
//!    triangles that use it;
//! 2. a triangle whose three vertices are inside every plane (most of a mesh) becomes a
//!    [`Slot::Whole`] of 20 bytes: its corners and the rows it can reach; the rare triangle the
//!    clipper cuts is prepared as the full render prepares it ([`Slot::Clipped`]);
//! 3. each band of rows rebuilds the set-up triangle of a whole triangle where it draws it,
//!    with the same functions ([`project_vertex`]'s values, [`setup_triangle_with`]), so the
//!    pixels are the full render's bit for bit (`tests/fast_path.rs`).
//!
//! A mesh of a million triangles then needs about 40 MB for this, not about 1 GB.

use glam::{DVec2, I64Vec2, IVec2 as I32Vec2};

use super::bands::{RowsDrawn, bin_rows, stop_at};
use super::clip::{ClipPlane, planes};
use super::draw::{draw_lanes, draw_scanline_lanes, lane_shading, rasterize, scanline_lanes_apply};
use super::framebuffer::{Framebuffer, RowBand};
use super::lanes::{LaneShading, LaneTriangle, Lanes, VectorLevel};
use super::mesh::ClipMesh;
use super::prepare::{PreparedTriangle, prepare_triangle_with};
use super::project::{SUBPIXEL, Viewport, WindowVertex, ndc_from_clip, project_vertex};
use super::settings::Rasterizer;
use super::setup::{TieRule, TriangleSetup, covers_no_sample, setup_bounds, setup_triangle_with};
use super::shade::{ShadeParams, depth_range};
use super::texture::Texture;
use super::varying::Varyings;

/// A mesh vertex after the perspective divide and viewport transform, as
/// [`project_vertex`] computes it (without the attributes, which stay in the mesh).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProjectedVertex {
    /// Window position in pixels before snapping.
    pub window: DVec2,
    /// Snapped window position in 1/256 pixel, in 32 bits: inside the guard band
    /// ([`GUARD_BAND_PIXELS`](super::project::GUARD_BAND_PIXELS) = 2^20 pixels) it is below
    /// 2^28 in magnitude. (Only vertices inside every plane are read as snapped positions;
    /// others are saturated.) Use [`ProjectedVertex::fixed`].
    fixed32: I32Vec2,
    /// Window depth in [0, 1].
    pub depth: f64,
    /// `1 / w_clip`.
    pub inv_w: f64,
    /// Finite and inside every clipping plane: a triangle of three such vertices is drawn
    /// unclipped.
    pub inside: bool,
}

impl ProjectedVertex {
    /// The snapped window position in 1/256 pixel, as [`project_vertex`] gives it (for a
    /// vertex inside every plane).
    #[inline(always)]
    pub fn fixed(&self) -> I64Vec2 {
        self.fixed32.as_i64vec2()
    }

    /// Projects one clip-space position (the values of [`project_vertex`]).
    fn new(clip: glam::DVec4, viewport: Viewport, planes: &[ClipPlane]) -> Self {
        let w = project_vertex(
            &super::clip::ClipVertex::new(clip, Varyings::default()),
            viewport,
        );
        Self {
            window: w.window,
            fixed32: w
                .fixed
                .clamp(
                    I64Vec2::splat(i32::MIN.into()),
                    I64Vec2::splat(i32::MAX.into()),
                )
                .as_ivec2(),
            depth: w.depth,
            inv_w: w.inv_w,
            inside: clip.is_finite() && planes.iter().all(|p| p.distance(clip) >= 0.0),
        }
    }
}

/// What the fast path keeps of one source triangle (20 bytes).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Slot {
    /// Nothing to draw: a bad index, a NaN or infinite coordinate, zero area, off screen, or
    /// clipped away.
    Skip,
    /// Inside every clipping plane: the corners (indices into the mesh's vertices) and the
    /// first and last image row its pixels can lie on (for binning); the set-up triangle,
    /// with its bounds, is rebuilt where it is drawn.
    Whole {
        /// The source triangle's vertex indices.
        corners: [u32; 3],
        /// First and last row of its pixel bounds (rows fit in 16 bits: images are at most
        /// [`MAX_IMAGE_SIZE`](super::project::MAX_IMAGE_SIZE) high).
        rows: [u16; 2],
    },
    /// Cut by the clipper: prepared as the full render prepares it, kept in
    /// [`FastMesh::clipped`] at this index.
    Clipped(u32),
}

/// A mesh prepared for the fast path: the projected vertices and one [`Slot`] per source
/// triangle, in submission order.
pub struct FastMesh<'m> {
    mesh: &'m ClipMesh,
    viewport: Viewport,
    rule: TieRule,
    /// One per mesh vertex.
    pub vertices: Vec<ProjectedVertex>,
    /// One per source triangle.
    pub slots: Vec<Slot>,
    /// The triangles the clipper cut (few), as [`Slot::Clipped`] indexes them.
    pub clipped: Vec<PreparedTriangle>,
}

/// Vertices or triangles one parallel task handles at least (small meshes stay on one
/// thread).
const CHUNK: usize = 512;

impl<'m> FastMesh<'m> {
    /// Projects every vertex once and reduces every source triangle to its [`Slot`], in
    /// parallel (rayon's current pool).
    pub fn prepare(mesh: &'m ClipMesh, viewport: Viewport, rule: TieRule) -> Self {
        use rayon::prelude::*;
        let planes = planes(viewport.guard_band_ndc());
        let (mut vertices, mut slots) = {
            let mut s = scratch();
            (
                std::mem::take(&mut s.vertices),
                std::mem::take(&mut s.slots),
            )
        };
        // A much larger mesh drawn before gives its memory back.
        if vertices.capacity() > 4 * mesh.vertices.len().max(KEEP_AT_LEAST) {
            vertices = Vec::new();
        }
        if slots.capacity() > 4 * mesh.triangles.len().max(KEEP_AT_LEAST) {
            slots = Vec::new();
        }
        mesh.vertices
            .par_iter()
            .with_min_len(CHUNK)
            .map(|v| ProjectedVertex::new(v.clip, viewport, &planes))
            .collect_into_vec(&mut vertices);
        let mut out = Self {
            mesh,
            viewport,
            rule,
            vertices,
            slots: Vec::new(),
            clipped: Vec::new(),
        };
        // First pass: whole triangles get their slot; the few the clipper cuts are marked
        // and prepared after, in order.
        (0..mesh.triangles.len() as u32)
            .into_par_iter()
            .with_min_len(CHUNK)
            .map(|i| out.slot(i))
            .collect_into_vec(&mut slots);
        let cut: Vec<u32> = slots
            .iter()
            .enumerate()
            .filter(|(_, s)| **s == CUT)
            .map(|(i, _)| i as u32)
            .collect();
        let prepared: Vec<PreparedTriangle> = cut
            .par_iter()
            .map(|&i| prepare_triangle_with(mesh, i, viewport, rule))
            .collect();
        for (i, p) in cut.into_iter().zip(prepared) {
            slots[i as usize] = if p.setups.is_empty() {
                Slot::Skip
            } else {
                out.clipped.push(p);
                Slot::Clipped(out.clipped.len() as u32 - 1)
            };
        }
        out.slots = slots;
        out
    }

    /// The slot of a triangle inside every plane, [`Slot::Skip`], or [`CUT`] for one the
    /// clipper must cut.
    fn slot(&self, index: u32) -> Slot {
        let Some(corners) = self.mesh.triangles.get(index as usize).copied() else {
            return Slot::Skip;
        };
        let Some(p) = self.projected(corners) else {
            return Slot::Skip;
        };
        if p.iter().all(|v| v.inside) {
            return match setup_bounds(p.map(|v| v.fixed()), self.viewport) {
                Some(b) => Slot::Whole {
                    corners,
                    // The bounds lie inside the image, at most MAX_IMAGE_SIZE rows.
                    rows: [b.y0 as u16, b.y1 as u16],
                },
                None => Slot::Skip,
            };
        }
        CUT
    }

    fn projected(&self, corners: [u32; 3]) -> Option<[&ProjectedVertex; 3]> {
        let v = |k: usize| self.vertices.get(corners[k] as usize);
        Some([v(0)?, v(1)?, v(2)?])
    }

    /// The set-up triangle of a whole triangle, exactly as
    /// [`prepare_triangle_with`] sets it up: the window vertices of
    /// [`source_vertices`](super::prepare::source_vertices) projected, then
    /// [`setup_triangle_with`].
    pub fn setup(&self, corners: [u32; 3]) -> Option<TriangleSetup> {
        let mut window = [None; 3];
        for (k, w) in window.iter_mut().enumerate() {
            let i = corners[k] as usize;
            let (m, p) = (self.mesh.vertices.get(i)?, self.vertices.get(i)?);
            let mut bary = [0.0; 3];
            bary[k] = 1.0;
            let varyings = Varyings::new(bary, m.uv, m.color).with_normal(m.normal);
            *w = Some(WindowVertex {
                clip: m.clip,
                ndc: ndc_from_clip(m.clip),
                fixed: p.fixed(),
                window: p.window,
                depth: p.depth,
                inv_w: p.inv_w,
                varyings,
                noperspective: varyings,
            });
        }
        let [a, b, c] = window;
        setup_triangle_with([a?, b?, c?], self.viewport, self.rule)
    }

    /// Sets `tri` to a whole triangle as the edge-function lanes draw it, set up in place from
    /// the shared projected vertices ([`LaneTriangle::set_whole`]: the values of
    /// [`triangle_geometry`](super::setup::triangle_geometry) and [`FastMesh::setup`]);
    /// `false` when it has no set-up. The lanes draw it when it is
    /// [`exact`](LaneTriangle::exact).
    #[inline(always)]
    fn set_lane_triangle(
        &self,
        tri: &mut LaneTriangle,
        corners: [u32; 3],
        shading: LaneShading,
        uv: bool,
    ) -> bool {
        let Some([a, b, c]) = self.projected(corners) else {
            return false;
        };
        let m = |k: usize| self.mesh.vertices.get(corners[k] as usize);
        let (Some(ma), Some(mb), Some(mc)) = (m(0), m(1), m(2)) else {
            return false;
        };
        tri.set_whole(
            (
                [a.fixed(), b.fixed(), c.fixed()],
                [a.window, b.window, c.window],
            ),
            self.viewport,
            self.rule,
            [a.inv_w, b.inv_w, c.inv_w],
            [a.depth, b.depth, c.depth],
            [ma, mb, mc],
            shading,
            uv,
        )
    }

    /// Whether a whole triangle less than two pixels across is known to cover no pixel
    /// centre of the band ([`covers_no_sample`]): then it is not set up.
    #[inline(always)]
    fn covers_nothing(&self, corners: [u32; 3], rows: [u16; 2], band: &RowBand<'_>) -> bool {
        if rows[1] - rows[0] > 1 {
            return false;
        }
        let Some(p) = self.projected(corners) else {
            return false;
        };
        let fixed = p.map(|v| v.fixed());
        // Cheaply first: less than two pixels across each way, so at most 2x2 pixel centres.
        let (lo, hi) = (
            fixed[0].min(fixed[1]).min(fixed[2]),
            fixed[0].max(fixed[1]).max(fixed[2]),
        );
        let span = hi - lo;
        if span.x >= 2 * SUBPIXEL || span.y >= 2 * SUBPIXEL {
            return false;
        }
        let (Some(bounds), Some(last)) = (
            setup_bounds(fixed, self.viewport),
            (band.y0 + band.rows).checked_sub(1),
        ) else {
            return false;
        };
        covers_no_sample(fixed, bounds, (band.y0, last), self.rule) == Some(true)
    }

    /// The smallest and largest window depth of the drawn triangles' vertices
    /// ([`depth_range`], as the full render's
    /// [`shade_params`](super::render::shade_params) takes it of its triangles).
    pub fn depth_range(&self) -> (f64, f64) {
        let whole = self.slots.iter().flat_map(|slot| match slot {
            Slot::Whole { corners, .. } => corners.as_slice(),
            Slot::Skip | Slot::Clipped(_) => &[],
        });
        let clipped = self.clipped.iter().flat_map(|t| &t.setups);
        depth_range(
            whole
                .filter_map(|&c| self.vertices.get(c as usize))
                .map(|v| v.depth)
                .chain(clipped.flat_map(|s| s.v.iter().map(|v| v.depth))),
        )
    }

    /// The set-up triangles that reach each band of `rows_per_band` rows, in submission
    /// order, as `(source triangle, set-up index)` ([`bin_rows`]; the vectors are kept from
    /// frame to frame).
    fn bins(&self, height: u32, rows_per_band: u32) -> Vec<Vec<(u32, u32)>> {
        let mut bins = std::mem::take(&mut scratch().bins);
        let spans = self.slots.iter().enumerate().flat_map(|(ti, slot)| {
            let ti = ti as u32;
            let whole = match slot {
                Slot::Whole { rows, .. } => Some((ti, 0, rows[0].into(), rows[1].into())),
                Slot::Skip | Slot::Clipped(_) => None,
            };
            let clipped = match slot {
                Slot::Clipped(c) => self
                    .clipped
                    .get(*c as usize)
                    .map_or(&[][..], |t| t.setups.as_slice()),
                Slot::Skip | Slot::Whole { .. } => &[],
            };
            whole.into_iter().chain(
                clipped
                    .iter()
                    .enumerate()
                    .map(move |(si, s)| (ti, si as u32, s.bounds.y0, s.bounds.y1)),
            )
        });
        bin_rows(&mut bins, height, rows_per_band, spans);
        bins
    }

    /// Draws every prepared triangle into `frame` (already sized), band by band in parallel,
    /// clearing each band to `background` first, the lanes at the vector level `vector`.
    pub fn rasterize(
        &self,
        texture: &Texture,
        params: &ShadeParams,
        (rasterizer, vector): (Rasterizer, VectorLevel),
        frame: &mut Framebuffer,
        rows_per_band: u32,
        background: [u8; 4],
    ) {
        use rayon::prelude::*;
        let rows_per_band = rows_per_band.max(1);
        let bins = self.bins(frame.height, rows_per_band);
        let progress = crate::progress::render_started(frame.height);
        let bands = RowBand::split(frame, rows_per_band);
        // Whole triangles go straight to the lanes when they can draw them.
        let shading = lane_shading(params);
        bands
            .into_par_iter()
            .zip(&bins)
            .for_each(|(mut band, bin)| {
                let _drawn = RowsDrawn(&progress, band.rows);
                if progress.cancelled() {
                    return;
                }
                band.clear(background);
                // Both uvs, for the uv buffers or the texel difference.
                let uvs = !band.uv_affine.is_empty() || !band.texel_difference.is_empty();
                let lanes = shading.filter(|s| {
                    !band.has_aovs()
                        && match rasterizer {
                            Rasterizer::EdgeFunction => true,
                            Rasterizer::Scanline => !uvs && scanline_lanes_apply(s),
                        }
                });
                let drawer = lanes.map(|s| Lanes::new(texture, s, vector));
                let mut tri = LaneTriangle::EMPTY;
                for (j, &(ti, si)) in bin.iter().enumerate() {
                    if stop_at(&progress, j) {
                        break;
                    }
                    // The triangles a band visits are scattered over the mesh: ask for the memory
                    // of the ones a few steps ahead while this one draws.
                    if let Some(&(ahead, _)) = bin.get(j + PREFETCH_SLOTS) {
                        prefetch(self.slots.get(ahead as usize));
                    }
                    if let Some(&(ahead, _)) = bin.get(j + PREFETCH_VERTICES)
                        && let Some(Slot::Whole { corners, .. }) = self.slots.get(ahead as usize)
                    {
                        for &c in corners {
                            prefetch(self.vertices.get(c as usize));
                            prefetch(self.mesh.vertices.get(c as usize));
                        }
                    }
                    match &self.slots[ti as usize] {
                        Slot::Skip => {}
                        Slot::Whole { corners, rows } => {
                            if self.covers_nothing(*corners, *rows, &band) {
                                continue;
                            }
                            let drawn = match &drawer {
                                Some(d)
                                    if self.set_lane_triangle(
                                        &mut tri,
                                        *corners,
                                        d.shading(),
                                        uvs,
                                    ) =>
                                {
                                    match rasterizer {
                                        Rasterizer::Scanline => {
                                            draw_scanline_lanes(&tri, d, &mut band);
                                            true
                                        }
                                        Rasterizer::EdgeFunction if tri.exact() => {
                                            draw_lanes(&tri, ti, d, &mut band);
                                            true
                                        }
                                        Rasterizer::EdgeFunction => false,
                                    }
                                }
                                _ => false,
                            };
                            if !drawn && let Some(setup) = self.setup(*corners) {
                                rasterize(
                                    &setup,
                                    ti,
                                    texture,
                                    params,
                                    (rasterizer, vector),
                                    &mut band,
                                );
                            }
                        }
                        Slot::Clipped(c) => {
                            if let Some(setup) = self
                                .clipped
                                .get(*c as usize)
                                .and_then(|t| t.setups.get(si as usize))
                            {
                                rasterize(
                                    setup,
                                    ti,
                                    texture,
                                    params,
                                    (rasterizer, vector),
                                    &mut band,
                                );
                            }
                        }
                    }
                }
            });
        scratch().bins = bins;
    }
}

impl Drop for FastMesh<'_> {
    /// Gives the vectors back for the next frame's [`FastMesh::prepare`] on this thread.
    fn drop(&mut self) {
        let mut slots = std::mem::take(&mut self.slots);
        slots.clear();
        let vertices = std::mem::take(&mut self.vertices);
        let mut s = scratch();
        s.vertices = vertices;
        s.slots = slots;
    }
}

/// Vertices and triangles the kept vectors may hold whatever the mesh.
const KEEP_AT_LEAST: usize = 1 << 16;

/// The fast path's vectors, kept from one frame to the next: a dense mesh's tens of megabytes
/// are then not taken from the system (and zeroed by it) again every frame. One set for the
/// process, not one per thread: whichever thread renders next takes it (a render running
/// at the same time as another finds it empty and allocates its own).
#[derive(Default)]
struct Scratch {
    vertices: Vec<ProjectedVertex>,
    slots: Vec<Slot>,
    bins: Vec<Vec<(u32, u32)>>,
}

static SCRATCH: std::sync::Mutex<Scratch> = std::sync::Mutex::new(Scratch {
    vertices: Vec::new(),
    slots: Vec::new(),
    bins: Vec::new(),
});

/// The kept vectors (a poisoned lock only means a render panicked; its vectors are still
/// vectors).
fn scratch() -> std::sync::MutexGuard<'static, Scratch> {
    SCRATCH
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// A slot's marker, during [`FastMesh::prepare`], for a triangle the clipper must cut.
const CUT: Slot = Slot::Clipped(u32::MAX);

/// How many triangles ahead in a band's list the slot is prefetched.
const PREFETCH_SLOTS: usize = 8;
/// How many triangles ahead the vertices are prefetched (their slot is in cache by then).
const PREFETCH_VERTICES: usize = 4;

/// Asks the CPU to bring the cache line of `value` closer (a hint; nothing on other CPUs).
#[inline(always)]
fn prefetch<T>(value: Option<&T>) {
    #[cfg(target_arch = "x86_64")]
    if let Some(v) = value {
        // SAFETY: prefetching is a hint that never faults, and `v` is a valid reference.
        unsafe {
            std::arch::x86_64::_mm_prefetch::<{ std::arch::x86_64::_MM_HINT_T0 }>(
                (v as *const T).cast::<i8>(),
            )
        };
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = value;
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The per-triangle record stays compact (a million triangles: 20 MB).
    #[test]
    fn a_slot_is_twenty_bytes() {
        assert_eq!(size_of::<Slot>(), 20);
    }

    /// A projected vertex stays compact (a million vertices: 48 MB).
    #[test]
    fn a_projected_vertex_is_forty_eight_bytes() {
        assert_eq!(size_of::<ProjectedVertex>(), 48);
    }

    /// The 32-bit snapped position holds every position inside the guard band exactly.
    #[test]
    fn snapped_positions_inside_the_guard_band_fit_32_bits() {
        let viewport = Viewport {
            width: 64,
            height: 64,
        };
        let planes = planes(viewport.guard_band_ndc());
        let g = viewport.guard_band_ndc();
        for clip in [
            glam::DVec4::new(g, -g, 0.0, 1.0),
            glam::DVec4::new(-g, g, 0.5, 1.0),
            glam::DVec4::new(0.25, -0.5, 0.0, 1.0),
        ] {
            let v = ProjectedVertex::new(clip, viewport, &planes);
            let full = project_vertex(
                &super::super::clip::ClipVertex::new(clip, Varyings::default()),
                viewport,
            );
            assert!(v.inside, "{clip}");
            assert_eq!(v.fixed(), full.fixed, "{clip}");
        }
    }
}
