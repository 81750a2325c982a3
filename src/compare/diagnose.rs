//! One line per differing pixel, from the probe's trace of barylab's pixel: a centre exactly
//! on an edge (the tie rule), a centre a hair from an edge (snapping), the other interpolation
//! mode's colour, two triangles at one centre (the depth test), an edge pixel with a blended
//! colour (anti-aliasing).

use super::reason::Reason;
use super::{CoverageBy, Difference, Reference, rgb_difference, uv_gap_texels};
use crate::probe::{PixelTrace, Position, Prober, TriangleCoverage};
use crate::raster::render::Render;
use crate::raster::{Interpolation, NO_TRIANGLE, RenderSettings};

/// What the reasons need: a prober of the scene, barylab's render and the other mode's.
pub struct Context<'a> {
    prober: Prober<'a>,
    render: &'a Render,
    other: Render,
    other_mode: Interpolation,
    reference: &'a Reference<'a>,
    tolerance: u8,
}

impl<'a> Context<'a> {
    /// Prepares a prober of `reference`'s scene and renders it in the other interpolation
    /// mode; `render` is barylab's render of it, `tolerance` the comparison's (the coverage
    /// rule is not used). Fails with the probe's or the renderer's message.
    pub fn new(
        reference: &'a Reference<'a>,
        render: &'a Render,
        _by: CoverageBy,
        tolerance: u8,
    ) -> Result<Self, String> {
        let prober = Prober::new(reference.scene, reference.texture, &reference.settings)
            .map_err(|e| e.to_string())?;
        let mode = match reference.settings.mode {
            Interpolation::Affine => Interpolation::Perspective,
            Interpolation::Perspective => Interpolation::Affine,
        };
        let settings = RenderSettings {
            mode,
            ..reference.settings
        };
        let other = super::render_for_comparison(reference.mesh, reference.texture, &settings)?;
        Ok(Self {
            prober,
            render,
            other,
            other_mode: mode,
            reference,
            tolerance,
        })
    }

    /// Why pixel `(x, y)` differs as `d`, the other image's colour there being `theirs`.
    pub fn reason(
        &self,
        [x, y]: [u32; 2],
        d: Difference,
        theirs: [u8; 4],
    ) -> Result<Reason, String> {
        let trace = self.prober.pixel(x, y).map_err(|e| e.to_string())?;
        Ok(match d {
            Difference::OnlyTheirs | Difference::OnlyOurs => self.coverage_reason(&trace, d),
            Difference::Color => self.colour_reason(&trace, theirs),
        })
    }

    fn name(t: &TriangleCoverage) -> String {
        t.vertices.concat()
    }

    /// The distance in pixels from the sample to edge `i` of the set-up triangle tested.
    fn edge_distance(&self, t: &TriangleCoverage, i: usize) -> Option<f64> {
        let test = t.test.as_ref()?;
        let setup = self
            .render
            .triangles
            .get(t.source as usize)?
            .setups
            .get(test.sub_triangle)?;
        let len = setup.edges[i].dir.as_dvec2().length();
        (len > 0.0)
            .then(|| test.edges[i].value as f64 / len / crate::raster::project::SUBPIXEL as f64)
    }

    fn coverage_reason(&self, trace: &PixelTrace, d: Difference) -> Reason {
        let by_name = |source: u32| {
            trace
                .triangles
                .iter()
                .find(|t| t.source == source)
                .map(Self::name)
                .unwrap_or_else(|| source.to_string())
        };
        for t in &trace.triangles {
            let Some(test) = &t.test else { continue };
            if test.position != Position::OnEdge {
                continue;
            }
            let Some(e) = test.edges.iter().find(|e| e.value == 0) else {
                continue;
            };
            return Reason::OnEdge {
                edge: e.name.clone(),
                edge_kind: e.kind,
                triangle: Self::name(t),
                rule: self.reference.settings.tie_rule,
                owner: trace.written_by.map(by_name),
            };
        }
        match (d, trace.written_by) {
            (Difference::OnlyOurs, Some(w)) => {
                let Some(t) = trace.triangles.iter().find(|t| t.source == w) else {
                    return Reason::Covered {
                        triangle: w.to_string(),
                    };
                };
                let nearest = (0..3)
                    .filter_map(|i| Some((i, self.edge_distance(t, i)?)))
                    .min_by(|a, b| a.1.total_cmp(&b.1));
                match (nearest, &t.test) {
                    (Some((i, dist)), Some(test)) => Reason::Inside {
                        distance: dist,
                        edge: test.edges[i].name.clone(),
                        triangle: Self::name(t),
                    },
                    _ => Reason::Covered {
                        triangle: Self::name(t),
                    },
                }
            }
            _ => {
                // The triangle whose outside the centre is least far into.
                let nearest = trace
                    .triangles
                    .iter()
                    .filter_map(|t| {
                        let out = (0..3)
                            .filter_map(|i| self.edge_distance(t, i).map(|d| (i, d)))
                            .filter(|&(_, d)| d < 0.0)
                            .min_by(|a, b| a.1.total_cmp(&b.1))?;
                        Some((t, out))
                    })
                    .min_by(|a, b| b.1.1.total_cmp(&a.1.1));
                match nearest {
                    Some((t, (i, dist))) => Reason::Outside {
                        distance: -dist,
                        edge: t
                            .test
                            .as_ref()
                            .map_or_else(|| "?".to_string(), |s| s.edges[i].name.clone()),
                        triangle: Self::name(t),
                    },
                    None => Reason::NothingNear,
                }
            }
        }
    }

    fn colour_reason(&self, trace: &PixelTrace, theirs: [u8; 4]) -> Reason {
        let [x, y] = trace.pixel;
        let f = &self.render.frame;
        let k = (y * f.width + x) as usize;
        let ours = f.color[k];
        let other = self.other.frame.color[k];
        let diff = rgb_difference(theirs, ours);
        if rgb_difference(theirs, other) <= self.tolerance {
            return Reason::OtherMode {
                texels: uv_gap_texels(f, k, self.reference.texture),
                looks_like: self.other_mode,
            };
        }
        let covering: Vec<&TriangleCoverage> = trace
            .triangles
            .iter()
            .filter(|t| t.depth_test.is_some())
            .collect();
        if let (Some(w), true) = (trace.written_by, covering.len() > 1) {
            let front = covering.iter().find(|t| t.source == w);
            let behind = covering.iter().find(|t| t.source != w);
            if let (Some(front), Some(behind)) = (front, behind) {
                let depth = |t: &TriangleCoverage| t.depth_test.map_or(f32::NAN, |d| d.depth);
                return Reason::Depth {
                    front: Self::name(front),
                    behind: Self::name(behind),
                    front_depth: depth(front),
                    behind_depth: depth(behind),
                };
            }
        }
        if let Some(n) = self.blended_with_neighbour(x, y, theirs) {
            return Reason::AntiAliased {
                neighbour: [n.0, n.1],
            };
        }
        let uv = match self.reference.settings.mode {
            Interpolation::Affine => f.uv_affine[k],
            Interpolation::Perspective => f.uv_perspective[k],
        };
        let tri = f.triangle[k];
        Reason::Colour {
            levels: diff,
            triangle: (tri != NO_TRIANGLE).then_some(tri),
            uv,
            colour: [ours[0], ours[1], ours[2]],
        }
    }

    /// A 4-neighbour with another triangle (or none) whose colour, with barylab's, brackets
    /// `theirs` in every channel.
    fn blended_with_neighbour(&self, x: u32, y: u32, theirs: [u8; 4]) -> Option<(u32, u32)> {
        let f = &self.render.frame;
        let k = (y * f.width + x) as usize;
        let ours = f.color[k];
        let tol = i32::from(self.tolerance);
        let neighbours = [(-1i64, 0i64), (1, 0), (0, -1), (0, 1)];
        neighbours.iter().find_map(|&(dx, dy)| {
            let (nx, ny) = (i64::from(x) + dx, i64::from(y) + dy);
            if nx < 0 || ny < 0 || nx >= i64::from(f.width) || ny >= i64::from(f.height) {
                return None;
            }
            let j = (ny as u32 * f.width + nx as u32) as usize;
            if f.triangle[j] == f.triangle[k] {
                return None;
            }
            let other = f.color[j];
            let between = (0..3).all(|c| {
                let (a, b, t) = (
                    i32::from(ours[c]),
                    i32::from(other[c]),
                    i32::from(theirs[c]),
                );
                t >= a.min(b) - tol && t <= a.max(b) + tol
            });
            (between && rgb_difference(theirs, other) > self.tolerance)
                .then_some((nx as u32, ny as u32))
        })
    }
}
