//! The samples of a probed pixel when the render has more than one per pixel (or `flat`
//! attributes): each sample's position, coverage, triangle, depth and uv, and for each
//! triangle covering some of them where its MSAA shading was evaluated and why. It runs the
//! renderer's own per-pixel kernel ([`multisample::draw_pixel`]) over the triangles in
//! drawing order, so the samples and the resolved colour are the rendered ones.

use serde::Serialize;

use super::Prober;
use crate::raster::NO_TRIANGLE;
use crate::raster::multisample::{self, SampleContext, SampleValue};
use crate::raster::sample::{self, Location, ShadingRate};
use crate::raster::setup::sample_point;

/// One sample of the pixel after every triangle was drawn.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SampleTrace {
    /// The sample index, as the GL numbers them.
    pub index: usize,
    /// Its position in window coordinates (pixels, y down, pixel corners at integers).
    pub position: [f64; 2],
    /// Whether a triangle covers it.
    pub covered: bool,
    /// The source triangle whose fragment it kept, if any.
    pub triangle: Option<u32>,
    /// Its depth (that triangle's z/w at the sample), if covered.
    pub depth: Option<f32>,
    /// The uv the fragment shader saw for it (the same for every covered sample of a triangle
    /// under centre or centroid MSAA), if covered.
    pub uv: Option<[f32; 2]>,
}

/// Where one triangle covering some of the pixel's samples was shaded.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TriangleSamples {
    /// The source triangle.
    pub triangle: u32,
    /// The indices of the samples it covers (before the depth test).
    pub covered: Vec<usize>,
    /// Whether the pixel centre is inside it (by its edge functions and tie rule).
    pub centre_inside: bool,
    /// Where its values were evaluated (window coordinates), when shaded once for the pixel
    /// (MSAA at the centre or centroid); `None` when every sample is shaded on its own.
    pub evaluated_at: Option<[f64; 2]>,
    /// The sample index the centroid chose, when it is a sample rather than the centre.
    pub centroid_sample: Option<usize>,
}

/// What decided a probed pixel's samples.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SampleShading {
    /// Shading rate: `msaa` or `ssaa`.
    pub shading_rate: ShadingRate,
    /// Where MSAA evaluates values.
    pub location: Location,
    /// Whether every attribute is `flat`.
    pub flat: bool,
    /// Every triangle covering at least one sample, in drawing order.
    pub triangles: Vec<TriangleSamples>,
    /// The resolved colour: the average of the samples' colours.
    pub resolved: [u8; 4],
}

impl Prober<'_> {
    /// The samples of pixel (x, y) after every triangle was drawn, or `None` when the render
    /// has one sample at the centre and no `flat` attributes.
    pub fn pixel_samples(&self, x: u32, y: u32) -> Option<Vec<SampleTrace>> {
        self.samples(x, y).map(|(samples, _)| samples)
    }

    /// The samples of pixel (x, y), or `None` when the render has one sample at the centre
    /// and no `flat` attributes (the single-sample trace says everything then).
    pub(super) fn samples(&self, x: u32, y: u32) -> Option<(Vec<SampleTrace>, SampleShading)> {
        let settings = self.settings.samples;
        if !settings.uses_sample_path() {
            return None;
        }
        let offsets = settings.offsets();
        let ctx = SampleContext {
            offsets: &offsets,
            samples: settings,
            texture: &self.texture,
            params: &self.params,
        };
        let mut pixel = vec![SampleValue::clear(self.settings.background); offsets.len()];
        let mut triangles = Vec::new();
        let window = |p| sample::window_position(p).to_array();
        for tri in &self.triangles {
            let flat = multisample::flat_varyings(&self.mesh, tri.source, &settings);
            for s in &tri.setups {
                let mask = multisample::coverage(s, x, y, &offsets);
                if mask != 0 {
                    let shared = !settings.per_sample_shading();
                    let chosen = sample::centroid_sample(settings.location, mask, offsets.len());
                    triangles.push(TriangleSamples {
                        triangle: tri.source,
                        covered: (0..offsets.len()).filter(|k| mask & 1 << k != 0).collect(),
                        centre_inside: s.covers(&s.edge_values(sample_point(x, y))),
                        evaluated_at: shared
                            .then(|| window(multisample::shading_point(x, y, mask, &ctx))),
                        centroid_sample: chosen.filter(|_| shared),
                    });
                }
                let wire = self.wire_gradients(s);
                multisample::draw_pixel(
                    (s, tri.source, flat.as_ref()),
                    (x, y),
                    &ctx,
                    &wire,
                    &mut pixel,
                );
            }
        }
        let colors: Vec<[u8; 4]> = pixel.iter().map(|v| v.color).collect();
        let samples = pixel
            .iter()
            .zip(&offsets)
            .enumerate()
            .map(|(index, (v, &o))| {
                let covered = v.triangle != NO_TRIANGLE;
                SampleTrace {
                    index,
                    position: window(sample::sample_at(x, y, o)),
                    covered,
                    triangle: covered.then_some(v.triangle),
                    depth: covered.then_some(v.depth),
                    uv: covered.then_some(v.uv),
                }
            })
            .collect();
        let shading = SampleShading {
            shading_rate: settings.rate,
            location: settings.location,
            flat: settings.flat,
            triangles,
            resolved: sample::resolve(&colors),
        };
        Some((samples, shading))
    }
}
