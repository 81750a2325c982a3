//! The derivation for one triangle at the pixel ([`TriangleTrace`]): its vertices in every
//! space, the clipping, the screen weights four ways, the 1/w correction, the 4x4 system, the
//! point the pixel sees, the texture lookup, the depth and the shading. Everything the
//! rasterizer computed at the pixel comes from [`Prober::pixel`] ([`Sampled`]); the rest is
//! computed here, by the stage functions and the textbook forms of [`weights`].

use glam::{DVec2, DVec3, Vec2};

use super::lod;
use super::weights;
use super::*;
use crate::raster::clip::ClipVertex;
use crate::raster::interpolate::{Fragment, Interpolation};
use crate::raster::project;
use crate::raster::render;
use crate::raster::setup::TriangleSetup;
use crate::raster::shade::{self, ShadeParams, Shading};
use crate::raster::texture::{self, Filter};
use crate::raster::varying::Varyings;

impl Prober<'_> {
    fn vertex_trace(&self, ti: usize, k: usize) -> VertexTrace {
        let index = self.mesh.triangles[ti][k];
        let v = self.mesh.vertices[index as usize];
        let viewport = self.viewport();
        let clip = v.clip;
        // The renderer's own projection of the vertex (its varyings are not traced here).
        let projected = (clip.w > 0.0).then(|| {
            let vertex = ClipVertex::new(clip, Varyings::default());
            project::project_vertex(&vertex, viewport)
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
            ndc: projected.map(|p| p.ndc.to_array()),
            window: projected.map(|p| p.window.extend(p.depth).to_array()),
            window_snapped: projected.map(|p| p.window_snapped().to_array()),
            window_fixed: projected.map(|p| p.fixed.to_array()),
            inv_w: projected.map(|p| p.inv_w),
            uv: v.uv.to_array(),
            color: v.color.to_array(),
        }
    }

    /// The derivation for the fan triangle `sampled` (its coverage test `coverage`), reusing
    /// the edge values, weights and fragment [`Prober::pixel`] computed.
    pub(super) fn detail(
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
        let frag = sampled.frag.as_ref();
        let vertices: [VertexTrace; 3] = std::array::from_fn(|k| self.vertex_trace(ti, k));
        let clipped = tri.is_clipped();
        let (clipping, raster) = self.clipping_and_raster(ti, si, clipped);

        let system = self.system(ti, ndc);
        let screen = screen_weights(s, window, sampled.weights, system.as_ref(), clipped);
        let perspective = frag.and_then(|f| perspective_trace(s, f));
        let source_weights = frag.map(|f| SourceWeights {
            screen: f.affine.bary(),
            perspective: f.correct.bary(),
        });

        // The system and the seen point against the rasterizer: (a, b, c) and W_P of the 1/w
        // method for an unclipped triangle, the interpolated source weights for a clipped one.
        let reference = if clipped {
            source_weights.map(|w| (w.perspective.map(f64::from), None))
        } else {
            perspective.map(|p| (p.correction.weights, Some(p.correction.w_p)))
        };
        let system = system.map(|mut sys| {
            let b = sys.system.solution;
            sys.max_difference = reference.map(|(r, w_p)| {
                let start = w_p.map_or(0.0, |w_p| (b[3] - w_p).abs());
                largest_difference([b[0], b[1], b[2]], r, start)
            });
            sys
        });
        let seen_point = self.seen_point(ti, ndc, system.as_ref()).map(|mut p| {
            p.max_difference = reference.map(|(r, _)| largest_difference(p.weights, r, 0.0));
            p
        });

        TriangleTrace {
            source: tri.source,
            writes_pixel,
            vertex_behind_camera: vertices.iter().any(|v| v.clip[3] <= 0.0),
            vertices,
            clipping,
            coverage,
            screen,
            perspective,
            system,
            source_weights,
            seen_point,
            attribute: frag.map(|f| self.attribute(s, f, (x, y))),
            depth: frag.map(|f| self.depth_trace(s, f, &raster, seen_point.as_ref())),
            shade: frag.map(|f| self.shade_trace(s, f)),
            raster,
        }
    }

    /// What the clipper did to source triangle `ti` (when it cut it) and the rasterized fan
    /// triangle `si`, its vertices named after the polygon's.
    fn clipping_and_raster(
        &self,
        ti: usize,
        si: usize,
        clipped: bool,
    ) -> (Option<ClipTrace>, RasterTriangle) {
        let tri = &self.triangles[ti];
        let s = &tri.setups[si];
        let polygon = self.polygon(ti);
        let fan = self.fan_indices(ti, si, &polygon);
        let vertices: [RasterVertex; 3] = std::array::from_fn(|i| {
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
            vertices,
            area2: s.area2,
            facing: s.facing,
        };
        let clipping = clipped.then(|| ClipTrace {
            planes: tri
                .clipped
                .as_ref()
                .map(|p| p.cut_by(self.viewport().guard_band_ndc()))
                .unwrap_or_default(),
            polygon,
            fan_triangle: fan,
        });
        (clipping, raster)
    }

    /// Depth at the fragment: window depth as tested, and the distance (view depth, or clip
    /// w in a clip-space scene) interpolated both ways and at the seen point.
    fn depth_trace(
        &self,
        s: &TriangleSetup,
        f: &Fragment,
        raster: &RasterTriangle,
        seen_point: Option<&SeenPoint>,
    ) -> DepthTrace {
        let (kind, distances) = match &self.spaces {
            Some(_) => (
                DistanceKind::ViewDepth,
                raster
                    .vertices
                    .clone()
                    .map(|v| -v.view.map_or(0.0, |p| p[2])),
            ),
            None => (DistanceKind::ClipW, s.v.map(|v| v.clip.w)),
        };
        let dot = |l: &[f64; 3]| l[0] * distances[0] + l[1] * distances[1] + l[2] * distances[2];
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
    }

    /// How the fragment shades: [`shade::shade`], and the wireframe test
    /// ([`shade::WirePaint::of`]: the line or its halo) when the wireframe is on.
    fn shade_trace(&self, s: &TriangleSetup, f: &Fragment) -> ShadeTrace {
        let wire = self.wire_gradients(s);
        let on = self.params.wireframe;
        let paint = shade::WirePaint::of(f.edge_weights, wire.map(|g| g.length()));
        ShadeTrace {
            shading: self.settings.shading,
            mode: self.settings.mode,
            edge_distance_px: on.then(|| shade::edge_distance_px(f.edge_weights, &wire)),
            wire: on && paint == shade::WirePaint::Line,
            halo: on && paint == shade::WirePaint::Halo,
            color: shade::shade(f, &self.texture, &self.params, &wire),
            wire_width_px: on.then_some(shade::WIRE_WIDTH_PX),
            wire_halo_px: on.then_some(shade::WIRE_WIDTH_PX + shade::WIRE_HALO_PX),
            normal: matches!(self.settings.shading, Shading::Normal | Shading::Lambert).then(
                || {
                    let v = f.varyings(self.settings.mode);
                    let n = v.normal();
                    NormalTrace {
                        interpolated: n.to_array(),
                        length: n.length(),
                        unit: shade::unit_normal(n).to_array(),
                        lambert: shade::lambert_factor(n),
                        ambient: shade::AMBIENT,
                        albedo: v.color().to_array(),
                    }
                },
            ),
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
        // The fragment as the renderer shades it in each mode: its level of detail (and
        // derivatives) from that mode's uv.
        let footprint = |mode| {
            let params = ShadeParams {
                mode,
                ..self.params
            };
            let mut f = *f;
            shade::texture_footprint(&mut f, s, (x, y), &params, t);
            (f, params)
        };
        let (frag_affine, params_affine) = footprint(Interpolation::Affine);
        let (frag_perspective, params_perspective) = footprint(Interpolation::Perspective);
        let (lod_affine, lod_perspective) = (frag_affine.lod, frag_perspective.lod);
        let taps = |uv: Vec2, lod: f32| {
            let mut taps = lod::tap_traces(t, &t.taps_lod(uv, filter, wrap, lod));
            if filter == Filter::Nearest {
                for tap in &mut taps {
                    tap.unwrapped = Some(t.nearest_unwrapped(uv, tap.level));
                }
            }
            taps
        };
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
            color_affine: shade::texture_color(t, uv_a, &frag_affine, &params_affine),
            color_perspective: shade::texture_color(
                t,
                uv_p,
                &frag_perspective,
                &params_perspective,
            ),
            lod: self.lod_trace(s, (x, y)),
            vertex_colors: s.v.map(|v| v.varyings.color().to_array()),
            vertex_color_affine: f.affine.color().to_array(),
            vertex_color_perspective: f.correct.color().to_array(),
        }
    }
}

/// Screen weights of set-up triangle `s` at `window`: the rasterizer's (`rasterizer`), and
/// the explicit formula, cross products, OpenGL area form and (unclipped) the 4x4 system's
/// `b_i W_i / w`, with the largest difference from the rasterizer's.
fn screen_weights(
    s: &TriangleSetup,
    window: DVec2,
    rasterizer: [f64; 3],
    system: Option<&SystemTrace>,
    clipped: bool,
) -> ScreenWeights {
    let pos = s.v.map(|v| v.window);
    let explicit = weights::explicit_formula(window, pos);
    let cross_product = weights::cross_product_weights(window, pos);
    let gl_area = weights::gl_area_weights(window, pos);
    let from_system = match (system, clipped) {
        (Some(sys), false) => {
            let b = sys.system.solution;
            Some([0, 1, 2].map(|i| b[i] * s.v[i].clip.w / b[3]))
        }
        _ => None,
    };
    let mut max_difference: f64 = 0.0;
    let others = [
        explicit.map(|f| f.weights),
        explicit.map(|f| f.slides),
        cross_product.map(|a| a.weights),
        gl_area.map(|a| a.weights),
        from_system,
    ];
    for m in others.iter().flatten() {
        for i in 0..3 {
            max_difference = max_difference.max((m[i] - rasterizer[i]).abs());
        }
    }
    ScreenWeights {
        rasterizer,
        explicit,
        cross_product,
        gl_area,
        from_system,
        max_difference,
    }
}

/// The 1/w correction of fragment `f` in the r, s, t / W_P notation
/// ([`weights::w_p_correction`]), GAMES101's `1 / (r/W_A + s/W_B + t/W_C)` and the
/// renderer's values; `None` where the interpolated 1/w is not positive.
fn perspective_trace(s: &TriangleSetup, f: &Fragment) -> Option<PerspectiveTrace> {
    let w = s.v.map(|v| v.clip.w);
    let correction = weights::w_p_correction(f.screen, w)?;
    Some(PerspectiveTrace {
        w,
        correction,
        games101_w_reciprocal: 1.0 / (f.screen[0] / w[0] + f.screen[1] / w[1] + f.screen[2] / w[2]),
        renderer_weights: f.perspective,
        renderer_inv_w: f.inv_w,
    })
}

/// `max(start, max_k |d_k - r_k|)`.
fn largest_difference(d: [f64; 3], r: [f64; 3], start: f64) -> f64 {
    (0..3).map(|k| (d[k] - r[k]).abs()).fold(start, f64::max)
}
