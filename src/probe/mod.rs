//! The pixel probe: every number behind one pixel, computed by the stages that drew it.
//!
//! [`probe`] (or [`Prober::pixel`] for many pixels of one scene) traces the pixel centre
//! `(x + 0.5, y + 0.5)` through the same functions the renderer runs: it prepares every
//! source triangle with [`render::prepare_triangle`], evaluates the edge functions at
//! [`setup::sample_point`] with [`TriangleSetup::edge_values`] and
//! [`TriangleSetup::covers`], interpolates with [`interpolate::fragment`], resolves the depth
//! test as the renderer does (source triangles in order, `less than`, buffer cleared to 1)
//! and shades with [`shade::shade`]. So [`PixelTrace::color`] is the rendered pixel.
//!
//! Beside those numbers the trace holds the same quantities computed the ways textbooks
//! teach them ([`weights`]): screen-space weights by the explicit formula (GAMES101), by
//! cross-product areas and by the OpenGL area form; the 1/w correction in the
//! r, s, t / W_P notation; the 4x4 system (Umetani's Applied Computer Graphics notes); and the 3D point where the ray through
//! the pixel centre meets the triangle's plane. [`format`](mod@format) writes the trace as a worked
//! example (text, Markdown, LaTeX); the trace itself serializes to JSON with the field names
//! documented in `docs/probe.md`.
//!
//! Vertices are named by letter: the quad corners A, B, C, D in a world scene, the vertex
//! index as a letter (0 = A, 1 = B, ..., then V26, V27, ...) in clip-space and model scenes. Points the clipper made are
//! named K1, K2, ... in polygon order. P is the sample, X the 3D point it sees.

pub mod format;
mod trace;
pub mod weights;

pub use trace::*;

use glam::{DMat4, DVec2, DVec3, Vec2};

use crate::raster::camera::{Camera, CameraChain};
use crate::raster::framebuffer;
use crate::raster::interpolate::{self, Fragment, Interpolation};
use crate::raster::project::{self, SUBPIXEL, Viewport};
use crate::raster::render::{self, ClipMesh, PreparedTriangle, RenderError, RenderSettings};
use crate::raster::setup::{self, TriangleSetup};
use crate::raster::shade::{self, ShadeParams};
use crate::raster::texture::{self, Filter, Texture};
use crate::scene::{Scene, vertex_name};

/// Errors of the probe.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ProbeError {
    #[error(
        "pixel ({x}, {y}) is outside the {width}x{height} image (x must be 0..={}, y 0..={})",
        .width.saturating_sub(1),
        .height.saturating_sub(1)
    )]
    PixelOutside {
        x: u32,
        y: u32,
        width: u32,
        height: u32,
    },
    #[error(transparent)]
    Render(#[from] RenderError),
}

/// World-scene data the mesh does not keep: the object-space positions and the camera chain.
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

    /// The texture level of detail the renderer gives a fragment at (x, y): from its 2x2
    /// quad with trilinear filtering ([`interpolate::quad_lod`]), else 0.
    fn lod(&self, s: &TriangleSetup, x: u32, y: u32, mode: Interpolation) -> f32 {
        if self.params.filter == Filter::Trilinear {
            interpolate::quad_lod(s, x, y, mode, self.texture.width(), self.texture.height())
        } else {
            0.0
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
                clipped: tri.polygon.is_some_and(|p| !p.unclipped()),
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

        Ok(PixelTrace {
            pixel: [x, y],
            image_size: [width, height],
            settings: TraceSettings {
                mode: self.settings.mode,
                shading: self.settings.shading,
                filter: self.settings.filter,
                wrap: self.settings.wrap,
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
    /// the fragment ([`interpolate::fragment_from_weights`], with the level of detail).
    fn sampled(&self, ti: usize, si: usize, edges: [i64; 3], (x, y): (u32, u32)) -> Sampled {
        let s = &self.triangles[ti].setups[si];
        let weights = s.weights.at_pixel(x, y);
        let frag = interpolate::fragment_from_weights(s, edges, weights).map(|mut f| {
            f.lod = self.lod(s, x, y, self.settings.mode);
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
        let Some(poly) = &tri.polygon else {
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
        }
    }

    fn vertex_trace(&self, ti: usize, k: usize) -> VertexTrace {
        let index = self.mesh.triangles[ti][k];
        let v = self.mesh.vertices[index as usize];
        let viewport = self.viewport();
        let clip = v.clip;
        let projected = (clip.w > 0.0).then(|| {
            let ndc = project::ndc_from_clip(clip);
            let win = project::window_from_ndc(ndc, viewport);
            let fixed = project::snap(win.truncate());
            (ndc, win, fixed.as_dvec2() / SUBPIXEL as f64, fixed)
        });
        let (object, world, view) = match &self.spaces {
            Some(sp) => {
                let object = sp.object.get(index as usize).copied().unwrap_or_default();
                let (world, view) = sp.chain.world_and_view(object);
                (
                    Some(object.to_array()),
                    Some(world.to_array()),
                    Some(view.to_array()),
                )
            }
            None => (None, None, None),
        };
        VertexTrace {
            name: self.triangle_names(ti)[k].clone(),
            index,
            object,
            world,
            view,
            clip: clip.to_array(),
            ndc: projected.map(|p| p.0.to_array()),
            window: projected.map(|p| p.1.to_array()),
            window_snapped: projected.map(|p| p.2.to_array()),
            window_fixed: projected.map(|p| p.3.to_array()),
            inv_w: projected.map(|_| 1.0 / clip.w),
            uv: v.uv.to_array(),
            color: v.color.to_array(),
        }
    }

    /// The derivation for the fan triangle `sampled` (its coverage test `coverage`), reusing
    /// the edge values, weights and fragment [`Prober::pixel`] computed.
    fn detail(
        &self,
        sampled: &Sampled,
        coverage: CoverageTest,
        writes_pixel: bool,
        window: DVec2,
        ndc: DVec2,
    ) -> TriangleTrace {
        let (ti, si, (x, y)) = (sampled.ti, sampled.si, sampled.pixel);
        let tri = &self.triangles[ti];
        let s = &tri.setups[si];
        let viewport = self.viewport();
        let vertices: [VertexTrace; 3] = std::array::from_fn(|k| self.vertex_trace(ti, k));
        let behind = vertices.iter().any(|v| v.clip[3] <= 0.0);
        let clipped = tri.polygon.is_some_and(|p| !p.unclipped());
        let polygon = self.polygon(ti);
        let fan = self.fan_indices(ti, si, &polygon);
        let clipping = clipped.then(|| ClipTrace {
            planes: tri
                .polygon
                .map(|p| p.cut_by(viewport.guard_band_ndc()))
                .unwrap_or_default(),
            polygon: polygon.clone(),
            fan_triangle: fan,
        });
        let raster_vertices: [RasterVertex; 3] = std::array::from_fn(|i| {
            let v = &s.v[i];
            let p = polygon.get(fan[i]);
            RasterVertex {
                name: p.map(|p| p.name.clone()).unwrap_or_default(),
                source_vertex: p.and_then(|p| p.source_vertex),
                clip: v.clip.to_array(),
                ndc: v.ndc.to_array(),
                window: v.window.to_array(),
                window_snapped: v.window_snapped().to_array(),
                fixed: v.fixed.to_array(),
                depth: v.depth,
                inv_w: v.inv_w,
                source_weights: v.varyings.bary(),
                source_weights_affine: v.noperspective.bary(),
                uv: v.varyings.uv().to_array(),
                color: v.varyings.color().to_array(),
                view: self
                    .spaces
                    .as_ref()
                    .map(|w| w.chain.view_from_clip_point(v.clip).to_array()),
            }
        });
        let raster = RasterTriangle {
            vertices: raster_vertices,
            area2: s.area2,
            facing: s.facing,
        };
        let rasterizer = sampled.weights;
        let frag = sampled.frag.as_ref();

        // The 4x4 system on the source triangle.
        let system = self.system(ti, ndc);

        // Screen weights, four ways plus the rasterizer's.
        let pos = s.v.map(|v| v.window);
        let explicit = weights::explicit_formula(window, pos);
        let cross_product = weights::cross_product_weights(window, pos);
        let gl_area = weights::gl_area_weights(window, pos);
        let from_system = match (&system, clipped) {
            (Some(sys), false) => {
                let b = sys.system.solution;
                Some([0, 1, 2].map(|i| b[i] * s.v[i].clip.w / b[3]))
            }
            _ => None,
        };
        let mut max_difference: f64 = 0.0;
        let others = [
            explicit.map(|f| f.weights),
            cross_product.map(|a| a.weights),
            gl_area.map(|a| a.weights),
            from_system,
        ];
        for m in others.iter().flatten() {
            for i in 0..3 {
                max_difference = max_difference.max((m[i] - rasterizer[i]).abs());
            }
        }
        let screen = ScreenWeights {
            rasterizer,
            explicit,
            cross_product,
            gl_area,
            from_system,
            max_difference,
        };

        let w = s.v.map(|v| v.clip.w);
        let perspective = frag.and_then(|f| {
            let correction = weights::w_p_correction(f.screen, w)?;
            Some(PerspectiveTrace {
                w,
                correction,
                games101_w_reciprocal: 1.0
                    / (f.screen[0] / w[0] + f.screen[1] / w[1] + f.screen[2] / w[2]),
                renderer_weights: f.perspective,
                renderer_inv_w: f.inv_w,
            })
        });

        let source_weights = frag.map(|f| SourceWeights {
            screen: f.affine.bary(),
            perspective: f.correct.bary(),
        });
        // The system and the seen point against the rasterizer: (a, b, c) and W_P of the 1/w
        // method for an unclipped triangle, the interpolated source weights for a clipped one.
        let largest = |d: [f64; 3], r: [f64; 3], start: f64| {
            (0..3).map(|k| (d[k] - r[k]).abs()).fold(start, f64::max)
        };
        let reference = if clipped {
            source_weights.map(|w| (w.perspective.map(f64::from), None))
        } else {
            perspective.map(|p| (p.correction.weights, Some(p.correction.w_p)))
        };
        let system = system.map(|mut sys| {
            let b = sys.system.solution;
            sys.max_difference = reference.map(|(r, w_p)| {
                let start = w_p.map_or(0.0, |w_p| (b[3] - w_p).abs());
                largest([b[0], b[1], b[2]], r, start)
            });
            sys
        });
        let seen_point = self.seen_point(ti, ndc, system.as_ref()).map(|mut p| {
            p.max_difference = reference.map(|(r, _)| largest(p.weights, r, 0.0));
            p
        });
        let attribute = frag.map(|f| self.attribute(s, f, (x, y)));
        let depth = frag.map(|f| {
            let (kind, distances) = match &self.spaces {
                Some(_) => (
                    DistanceKind::ViewDepth,
                    raster
                        .vertices
                        .clone()
                        .map(|v| -v.view.map_or(0.0, |p| p[2])),
                ),
                None => (DistanceKind::ClipW, w),
            };
            let dot =
                |l: &[f64; 3]| l[0] * distances[0] + l[1] * distances[1] + l[2] * distances[2];
            DepthTrace {
                window_depths: s.v.map(|v| v.depth),
                depth: f.depth,
                distance_kind: kind,
                distances,
                distance_affine: dot(&f.screen),
                distance_corrected: dot(&f.perspective),
                distance_true: seen_point.map(|p| match (kind, p.view) {
                    (DistanceKind::ViewDepth, Some(v)) => -v[2],
                    _ => p.clip[3],
                }),
                depth_of_point: seen_point.map(|p| p.depth),
            }
        });
        let shade = frag.map(|f| {
            let wire = self.wire_gradients(s);
            ShadeTrace {
                shading: self.settings.shading,
                mode: self.settings.mode,
                edge_distance_px: self
                    .params
                    .wireframe
                    .then(|| shade::edge_distance_px(f.edge_weights, &wire)),
                wire: self.params.wireframe
                    && (0..3).any(|i| shade::on_wire_edge(f.edge_weights[i], wire[i].length())),
                color: shade::shade(f, &self.texture, &self.params, &wire),
                wire_width_px: self.params.wireframe.then_some(shade::WIRE_WIDTH_PX),
            }
        });

        TriangleTrace {
            source: tri.source,
            writes_pixel,
            vertices,
            vertex_behind_camera: behind,
            clipping,
            raster,
            coverage,
            screen,
            perspective,
            system,
            source_weights,
            seen_point,
            attribute,
            depth,
            shade,
        }
    }

    /// The 4x4 system for source triangle `ti`, on its raw clip coordinates: it reaches the
    /// exact answer on its own, independently of clipping, projection and the rasterizer.
    fn system(&self, ti: usize, ndc: DVec2) -> Option<SystemTrace> {
        let source = render::source_vertices(&self.mesh, self.triangles[ti].source)?;
        let system = weights::solve_homogeneous_system(source.map(|v| v.clip), ndc)?;
        Some(SystemTrace {
            system,
            s: ndc.to_array(),
            max_difference: None,
        })
    }

    fn seen_point(&self, ti: usize, ndc: DVec2, system: Option<&SystemTrace>) -> Option<SeenPoint> {
        match &self.spaces {
            Some(sp) => {
                let (origin, direction) = sp.chain.view_ray(ndc);
                let tri: [DVec3; 3] = std::array::from_fn(|k| {
                    let i = self.mesh.triangles[ti][k] as usize;
                    let object = sp.object.get(i).copied().unwrap_or_default();
                    sp.chain.world_and_view(object).1
                });
                let hit = weights::ray_triangle(origin, direction, tri)?;
                let view = DVec3::from_array(hit.point);
                let clip = sp.chain.clip_from_view * view.extend(1.0);
                let ndc = project::ndc_from_clip(clip);
                Some(SeenPoint {
                    ray: Some(ViewRay {
                        origin: origin.to_array(),
                        direction: direction.to_array(),
                    }),
                    hit: Some(hit),
                    view: Some(hit.point),
                    world: Some(sp.chain.world_from_view_point(view).to_array()),
                    clip: clip.to_array(),
                    ndc: ndc.to_array(),
                    depth: project::window_depth(ndc.z),
                    weights: hit.weights,
                    max_difference: None,
                })
            }
            None => {
                let sys = system?;
                let b = sys.system.solution;
                let source = render::source_vertices(&self.mesh, self.triangles[ti].source)?;
                let clip = source[0].clip * b[0] + source[1].clip * b[1] + source[2].clip * b[2];
                let ndc = project::ndc_from_clip(clip);
                Some(SeenPoint {
                    ray: None,
                    hit: None,
                    view: None,
                    world: None,
                    clip: clip.to_array(),
                    ndc: ndc.to_array(),
                    depth: project::window_depth(ndc.z),
                    weights: [b[0], b[1], b[2]],
                    max_difference: None,
                })
            }
        }
    }

    fn attribute(&self, s: &TriangleSetup, f: &Fragment, (x, y): (u32, u32)) -> AttributeTrace {
        let t = &*self.texture;
        let size = DVec2::new(f64::from(t.width()), f64::from(t.height()));
        let uv_a = f.affine.uv();
        let uv_p = f.correct.uv();
        let uvs = s.v.map(|v| v.varyings.uv());
        let w_p = 1.0 / f.inv_w;
        let g = |k: usize| {
            (0..3)
                .map(|i| f.screen[i] * f64::from(uvs[i][k]) * s.v[i].inv_w)
                .sum::<f64>()
                * w_p
        };
        // As the filters compute them: `u W` in f32.
        let texel = |uv: Vec2| t.texel_coords(uv, 0).map(f64::from);
        let (filter, wrap) = (self.settings.filter, self.settings.wrap);
        let lod_affine = self.lod(s, x, y, Interpolation::Affine);
        let lod_perspective = self.lod(s, x, y, Interpolation::Perspective);
        let taps = |uv: Vec2, lod: f32| {
            t.taps_lod(uv, filter, wrap, lod)
                .iter()
                .map(|tap| TapTrace {
                    level: tap.level,
                    i: tap.i,
                    j: tap.j,
                    unwrapped: (filter == Filter::Nearest)
                        .then(|| t.nearest_unwrapped(uv, tap.level)),
                    weight: tap.weight,
                    texel: t.texel_at(tap.level, tap.i, tap.j),
                })
                .collect()
        };
        let sample = |uv: Vec2, lod: f32| t.sample_rgba8(uv, filter, wrap, lod);
        let diff = DVec2::from_array(texture::texel_offset(
            uv_a.as_dvec2().to_array(),
            uv_p.as_dvec2().to_array(),
            size.to_array(),
        ));
        AttributeTrace {
            uv_vertices: uvs.map(|u| u.to_array()),
            uv_vertices_affine: s.v.map(|v| v.noperspective.uv().to_array()),
            uv_affine: uv_a.to_array(),
            uv_perspective: uv_p.to_array(),
            uv_games101: [g(0), g(1)],
            texture_size: [t.width(), t.height()],
            last_texel: [t.width().saturating_sub(1), t.height().saturating_sub(1)],
            texel_affine: texel(uv_a),
            texel_perspective: texel(uv_p),
            texel_difference: diff.to_array(),
            texel_distance: diff.length(),
            trilinear: (filter == Filter::Trilinear).then_some(Trilinear {
                levels: t.levels(),
                lod_affine,
                lod_perspective,
            }),
            taps_affine: taps(uv_a, lod_affine),
            taps_perspective: taps(uv_p, lod_perspective),
            color_affine: sample(uv_a, lod_affine),
            color_perspective: sample(uv_p, lod_perspective),
            vertex_colors: s.v.map(|v| v.varyings.color().to_array()),
            vertex_color_affine: f.affine.color().to_array(),
            vertex_color_perspective: f.correct.color().to_array(),
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

/// NDC of a window position: [`project::ndc_from_window`], under the probe's older name.
pub use crate::raster::project::ndc_from_window as ndc_of_window;

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
