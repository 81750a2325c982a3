//! The pixel probe: every number behind one pixel, computed by the stages that drew it.
//!
//! [`probe`] (or [`Prober::pixel`] for many pixels of one scene) traces the pixel centre
//! `(x + 0.5, y + 0.5)` through the same functions the renderer runs: it prepares every
//! source triangle with [`render::prepare_triangles`], evaluates the edge functions at
//! [`setup::sample_point`] with [`TriangleSetup::edge_values`] and
//! [`TriangleSetup::covers`], interpolates with [`interpolate::fragment`], resolves the depth
//! test as the renderer does (source triangles in order, `less than`, buffer cleared to 1)
//! and shades with [`shade::shade`]. So [`PixelTrace::color`] is the rendered pixel.
//!
//! Beside those numbers the trace holds the same quantities computed the ways textbooks
//! teach them ([`weights`]): screen-space weights by the explicit formula (from corner A, and
//! as GAMES101's slides write it, from B and C), by cross-product areas and by the OpenGL area form; the 1/w correction in the
//! r, s, t / W_P notation; the 4x4 system (Umetani's Applied Computer Graphics notes); and the 3D point where the ray through
//! the pixel centre meets the triangle's plane. [`format`](mod@format) writes the trace as a worked
//! example (text, Markdown, LaTeX); the trace itself serializes to JSON with the field names
//! documented in `docs/probe.md`.
//!
//! Vertices are named by letter: the quad corners A, B, C, D in a world scene, the vertex
//! index as a letter (0 = A, 1 = B, ..., then V26, V27, ...) in clip-space and model scenes. Points the clipper made are
//! named K1, K2, ... in polygon order. P is the sample, X the 3D point it sees.
//!
//! Files: this one holds [`Prober`] (preparing the scene, [`Prober::pixel`]: coverage and the
//! depth test at the sample); `detail.rs` the derivation for one triangle; `trace.rs` the
//! trace types (re-exported here); [`weights`] the textbook forms; [`format`](mod@format) the
//! worked example.

mod detail;
pub mod format;
mod lod;
pub mod quiz;
mod samples;
mod trace;
pub mod weights;

pub use lod::{AnisotropicTrace, LevelChoice, LodTrace, ProbeTrace, QuadPixel};
pub use samples::{SampleShading, SampleTrace, TriangleSamples};
pub use trace::*;

use glam::{DMat4, DVec2, DVec3};

use crate::raster::camera::{Camera, CameraChain};
use crate::raster::framebuffer;
use crate::raster::interpolate::{self, Derivatives, Fragment};
use crate::raster::project::{self, SUBPIXEL, Viewport};
use crate::raster::render::{self, ClipMesh, PreparedTriangle, RenderError, RenderSettings};
use crate::raster::setup::{self, TriangleSetup, pixel_centre};
use crate::raster::shade::{self, ShadeParams};
use crate::raster::texture::Texture;
use crate::scene::{Scene, vertex_name};

/// Errors of the probe.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ProbeError {
    #[error(
        "pixel ({x}, {y}) is outside the {width}x{height} image (x must be 0..={}, y 0..={})",
        .width.saturating_sub(1),
        .height.saturating_sub(1)
    )]
    /// The pixel is not in the image.
    PixelOutside {
        /// Column asked for, from the left.
        x: u32,
        /// Row asked for, from the top.
        y: u32,
        /// Image width in pixels.
        width: u32,
        /// Image height in pixels.
        height: u32,
    },
    /// The scene cannot be rendered: a bad image size, or not enough memory.
    #[error(transparent)]
    Render(#[from] RenderError),
}

/// World- and model-scene data the mesh does not keep: the object-space positions and the
/// camera chain.
#[derive(Clone, Debug)]
struct WorldSpaces {
    object: Vec<DVec3>,
    chain: CameraChain,
}

impl WorldSpaces {
    fn matrices(&self) -> Matrices {
        let rows = |m: DMat4| m.transpose().to_cols_array_2d();
        Matrices {
            world_from_object: rows(self.chain.world_from_object),
            view_from_world: rows(self.chain.view_from_world),
            clip_from_view: rows(self.chain.clip_from_view),
            perspective: self.chain.perspective,
        }
    }
}

/// What the rasterizer computed for one fan triangle at the pixel: made once by
/// [`Prober::pixel`], reused by the derivation.
#[derive(Clone, Debug)]
struct Sampled {
    /// Source triangle (index into the prepared triangles) and fan triangle.
    ti: usize,
    si: usize,
    pixel: (u32, u32),
    /// The screen weights at the pixel centre ([`setup::WeightPlanes::at_pixel`]).
    weights: [f64; 3],
    /// The fragment there; `None` where the interpolated 1/w is not positive.
    frag: Option<Fragment>,
}

/// Meshes with at most this many triangles list every one in [`PixelTrace::triangles`].
pub const LIST_ALL_TRIANGLES: usize = 16;

/// Probes many pixels of one scene: prepares the triangles once.
#[derive(Clone, Debug)]
pub struct Prober<'a> {
    mesh: ClipMesh,
    form: SceneForm,
    spaces: Option<WorldSpaces>,
    names: Vec<String>,
    texture: TextureRef<'a>,
    settings: RenderSettings,
    triangles: Vec<PreparedTriangle>,
    params: ShadeParams,
    derivatives: Derivatives,
}

/// The texture a [`Prober`] samples: borrowed, or shared so the prober can be kept (the app
/// keeps one per render, so moving the pointer does not clip and set up every triangle again).
#[derive(Clone, Debug)]
enum TextureRef<'a> {
    Borrowed(&'a Texture),
    Shared(std::sync::Arc<Texture>),
}

impl std::ops::Deref for TextureRef<'_> {
    type Target = Texture;
    fn deref(&self) -> &Texture {
        match self {
            TextureRef::Borrowed(t) => t,
            TextureRef::Shared(t) => t,
        }
    }
}

impl Prober<'static> {
    /// Like [`Prober::new`], holding a shared texture, so the prober can be kept.
    pub fn shared(
        scene: &Scene,
        texture: std::sync::Arc<Texture>,
        settings: &RenderSettings,
    ) -> Result<Self, ProbeError> {
        Self::build(scene, TextureRef::Shared(texture), settings)
    }
}

impl<'a> Prober<'a> {
    /// Prepares the scene's triangles as [`render::render`] does.
    pub fn new(
        scene: &Scene,
        texture: &'a Texture,
        settings: &RenderSettings,
    ) -> Result<Self, ProbeError> {
        Self::build(scene, TextureRef::Borrowed(texture), settings)
    }

    /// Which derivatives the level-of-detail derivation uses ([`LodTrace`]): coarse (the
    /// default, what the renderer uses) or fine.
    pub fn set_derivatives(&mut self, kind: Derivatives) {
        self.derivatives = kind;
    }

    /// The settings the prober traces with.
    pub fn settings(&self) -> &RenderSettings {
        &self.settings
    }

    fn build(
        scene: &Scene,
        texture: TextureRef<'a>,
        settings: &RenderSettings,
    ) -> Result<Self, ProbeError> {
        let mesh = scene.to_mesh();
        let triangles = render::prepare_triangles(&mesh, settings)?;
        let spaces = |camera: Camera, object: Vec<DVec3>| {
            let (w, h) = scene.size();
            let aspect = f64::from(w) / f64::from(h);
            Some(WorldSpaces {
                object,
                chain: CameraChain::new(&camera, scene.world_from_object(), aspect),
            })
        };
        let spaces = match scene {
            Scene::World(s) => spaces(s.camera, s.quad.iter().map(|c| c.position).collect()),
            Scene::Model(s) => spaces(s.camera(), s.mesh.positions.clone()),
            Scene::Clip(_) => None,
        };
        let names = (0..mesh.vertices.len()).map(vertex_name).collect();
        let params = render::shade_params(settings, &triangles);
        let form = match scene {
            Scene::World(_) => SceneForm::World,
            Scene::Clip(_) => SceneForm::Clip,
            Scene::Model(_) => SceneForm::Model,
        };
        Ok(Self {
            mesh,
            form,
            spaces,
            names,
            texture,
            settings: *settings,
            triangles,
            params,
            derivatives: Derivatives::Coarse,
        })
    }

    fn viewport(&self) -> Viewport {
        self.settings.viewport()
    }

    /// The names of source triangle `t`'s vertices.
    fn triangle_names(&self, t: usize) -> [String; 3] {
        match self.mesh.triangles.get(t) {
            Some(tri) => tri.map(|i| {
                self.names
                    .get(i as usize)
                    .cloned()
                    .unwrap_or_else(|| format!("V{i}"))
            }),
            None => [String::new(), String::new(), String::new()],
        }
    }

    fn wire_gradients(&self, s: &TriangleSetup) -> [DVec2; 3] {
        if self.params.wireframe {
            s.source_weight_gradients()
        } else {
            [DVec2::ZERO; 3]
        }
    }

    /// Traces pixel `(x, y)` (row 0 at the top).
    pub fn pixel(&self, x: u32, y: u32) -> Result<PixelTrace, ProbeError> {
        let (width, height) = (self.settings.width, self.settings.height);
        if x >= width || y >= height {
            return Err(ProbeError::PixelOutside {
                x,
                y,
                width,
                height,
            });
        }
        let sp = setup::sample_point(x, y);
        let window = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
        let ndc = project::ndc_from_window(window, self.viewport());

        // The depth test, exactly as `render` runs it.
        let mut buffer: f32 = 1.0;
        let mut winner: Option<Sampled> = None;
        let mut coverage = Vec::with_capacity(self.triangles.len());
        for (ti, tri) in self.triangles.iter().enumerate() {
            let mut depth_test = None;
            let mut covering = None;
            for (si, s) in tri.setups.iter().enumerate() {
                let e = s.edge_values(sp);
                if !s.covers(&e) {
                    continue;
                }
                covering.get_or_insert(si);
                let sampled = self.sampled(ti, si, e, (x, y));
                let Some(frag) = &sampled.frag else {
                    continue;
                };
                let depth = frag.depth as f32;
                let passed = framebuffer::depth_passes(depth, buffer);
                depth_test = Some(DepthTest {
                    depth,
                    buffer_before: buffer,
                    passed,
                });
                if passed {
                    buffer = depth;
                    winner = Some(sampled);
                }
            }
            let listed = self.triangles.len() <= LIST_ALL_TRIANGLES
                || tri.setups.iter().any(|s| {
                    let b = s.bounds;
                    (b.x0..=b.x1).contains(&x) && (b.y0..=b.y1).contains(&y)
                });
            if !listed {
                continue;
            }
            let chosen = covering.or_else(|| nearest_setup(tri, x, y).map(|(si, _)| si));
            coverage.push(TriangleCoverage {
                source: tri.source,
                vertices: self.triangle_names(ti),
                status: tri.status,
                clipped: tri.is_clipped(),
                test: chosen.map(|si| self.coverage_test(ti, si, sp)),
                depth_test,
            });
        }

        let color = match &winner {
            Some(Sampled {
                ti,
                si,
                frag: Some(frag),
                ..
            }) => {
                let s = &self.triangles[*ti].setups[*si];
                shade::shade(frag, &self.texture, &self.params, &self.wire_gradients(s))
            }
            _ => self.settings.background,
        };

        // The triangle to explain: the winner, else the nearest drawn one.
        let written_by = winner.as_ref().map(|w| self.triangles[w.ti].source);
        let shown = match winner {
            Some(w) => Some((w, true)),
            None => self
                .triangles
                .iter()
                .enumerate()
                .filter_map(|(ti, t)| nearest_setup(t, x, y).map(|(si, m)| (ti, si, m)))
                .fold(None, |best: Option<(usize, usize, f64)>, c| match best {
                    Some(b) if b.2 >= c.2 => Some(b),
                    _ => Some(c),
                })
                .map(|(ti, si, _)| {
                    let e = self.triangles[ti].setups[si].edge_values(sp);
                    (self.sampled(ti, si, e, (x, y)), false)
                }),
        };
        let detail = shown.map(|(sampled, writes)| {
            // The coverage test of the shown fan triangle, when the list above has it.
            let source = self.triangles[sampled.ti].source;
            let listed = coverage
                .iter()
                .filter(|c| c.source == source)
                .find_map(|c| c.test.clone())
                .filter(|t| t.sub_triangle == sampled.si);
            let test = listed.unwrap_or_else(|| self.coverage_test(sampled.ti, sampled.si, sp));
            self.detail(&sampled, test, writes, window, ndc)
        });

        let (samples, sample_shading) = self.samples(x, y).unzip();
        // With samples, the pixel is their resolve.
        let color = sample_shading.as_ref().map_or(color, |s| s.resolved);
        Ok(PixelTrace {
            samples: samples.unwrap_or_default(),
            sample_shading,
            pixel: [x, y],
            image_size: [width, height],
            settings: TraceSettings {
                mode: self.settings.mode,
                shading: self.settings.shading,
                filter: self.settings.filter,
                wrap: self.settings.wrap,
                max_anisotropy: self.settings.max_anisotropy.get(),
                wireframe: self.settings.wireframe,
                background: self.settings.background,
            },
            scene_form: self.form,
            matrices: self.spaces.as_ref().map(WorldSpaces::matrices),
            sample: Sample {
                window: window.to_array(),
                fixed: sp.to_array(),
                ndc: ndc.to_array(),
                subpixel: SUBPIXEL,
                edge_function_unit: SUBPIXEL * SUBPIXEL,
            },
            triangles: coverage,
            triangle_count: self.triangles.len(),
            written_by,
            detail,
            color,
        })
    }

    /// What the rasterizer computes for fan triangle `si` of triangle `ti` at pixel (x, y),
    /// given its edge values `edges` there: the screen weights ([`setup::WeightPlanes`]) and
    /// the fragment ([`interpolate::fragment_at_window`], with the level of detail).
    fn sampled(&self, ti: usize, si: usize, edges: [i64; 3], (x, y): (u32, u32)) -> Sampled {
        let s = &self.triangles[ti].setups[si];
        let weights = s.weights.at_pixel(x, y);
        let frag = interpolate::fragment_at_window(s, edges, pixel_centre(x, y)).map(|mut f| {
            shade::texture_footprint(&mut f, s, (x, y), &self.params, &self.texture);
            f
        });
        Sampled {
            ti,
            si,
            pixel: (x, y),
            weights,
            frag,
        }
    }

    /// The clipped polygon's vertices, named by the source name where a vertex is a source
    /// vertex (kept bit-exactly by the clipper), else K1, K2, ...
    fn polygon(&self, ti: usize) -> Vec<PolygonVertex> {
        let tri = &self.triangles[ti];
        let names = self.triangle_names(ti);
        let source = render::source_vertices(&self.mesh, tri.source);
        let Some(poly) = tri.polygon(&self.mesh, self.viewport()) else {
            return Vec::new();
        };
        let mut made = 0;
        poly.vertices()
            .iter()
            .map(|v| {
                let src = source
                    .as_ref()
                    .and_then(|s| s.iter().position(|sv| sv.clip == v.clip));
                PolygonVertex {
                    name: match src {
                        Some(i) => names[i].clone(),
                        None => {
                            made += 1;
                            format!("K{made}")
                        }
                    },
                    source_vertex: src,
                    clip: v.clip.to_array(),
                    source_weights: v.varyings.bary(),
                }
            })
            .collect()
    }

    /// The polygon indices of set-up triangle `si` of triangle `ti`.
    fn fan_indices(&self, ti: usize, si: usize, polygon: &[PolygonVertex]) -> [usize; 3] {
        let s = &self.triangles[ti].setups[si];
        s.v.map(|v| {
            polygon
                .iter()
                .position(|p| p.clip == v.clip.to_array())
                .unwrap_or(0)
        })
    }

    fn raster_names(&self, ti: usize, si: usize) -> [String; 3] {
        let polygon = self.polygon(ti);
        self.fan_indices(ti, si, &polygon)
            .map(|k| polygon.get(k).map(|p| p.name.clone()).unwrap_or_default())
    }

    fn coverage_test(&self, ti: usize, si: usize, sp: glam::I64Vec2) -> CoverageTest {
        let s = &self.triangles[ti].setups[si];
        let names = self.raster_names(ti, si);
        let e = s.edge_values(sp);
        let edges: [EdgeTest; 3] = std::array::from_fn(|i| EdgeTest {
            name: format!("{}{}", names[(i + 1) % 3], names[(i + 2) % 3]),
            kind: s.edges[i].kind,
            value: e[i],
            passes: s.edges[i].passes(e[i]),
        });
        let position = if e.iter().any(|&v| v < 0) {
            Position::Outside
        } else if e.contains(&0) {
            Position::OnEdge
        } else {
            Position::Inside
        };
        CoverageTest {
            sub_triangle: si,
            vertices: names,
            edges,
            position,
            covered: s.covers(&e),
            tie_rule: self.settings.tie_rule,
        }
    }
}

/// The set-up triangle of `tri` nearest to the centre of pixel (x, y): the largest smallest
/// screen weight, with that weight.
fn nearest_setup(tri: &PreparedTriangle, x: u32, y: u32) -> Option<(usize, f64)> {
    let mut best: Option<(usize, f64)> = None;
    for (si, s) in tri.setups.iter().enumerate() {
        let m = s
            .weights
            .at_pixel(x, y)
            .into_iter()
            .fold(f64::INFINITY, f64::min);
        if best.is_none_or(|b| m > b.1) {
            best = Some((si, m));
        }
    }
    best
}

/// Traces one pixel of a scene rendered with `settings` (see [`Prober`] for many pixels).
///
/// ```
/// use barylab::probe::probe;
/// use barylab::scene::Scene;
/// use barylab::raster::Texture;
/// let scene = Scene::default_scene();
/// let texture = Texture::builtin(barylab::raster::BuiltinTexture::UvGrid);
/// let trace = probe(&scene, &texture, &scene.settings(), (400, 420)).unwrap();
/// assert_eq!(trace.written_by, Some(0));
/// let d = trace.detail.unwrap();
/// assert!(d.screen.max_difference < 1e-12);
/// ```
pub fn probe(
    scene: &Scene,
    texture: &Texture,
    settings: &RenderSettings,
    pixel: (u32, u32),
) -> Result<PixelTrace, ProbeError> {
    Prober::new(scene, texture, settings)?.pixel(pixel.0, pixel.1)
}
