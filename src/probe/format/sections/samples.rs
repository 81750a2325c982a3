//! The samples of a multisampled pixel: each sample's coverage, depth and uv, where each
//! triangle was shaded (centre, centroid or every sample) and why, and the resolve.

use super::*;
use crate::probe::{SampleShading, TriangleSamples};
use crate::raster::sample::{Location, ShadingRate};

/// A position or uv pair; positions are exact multiples of 1/256, so 9 digits show them whole.
fn point(p: [f64; 2]) -> String {
    let f = |v: f64| crate::probe::format::fmt_digits(v, 9);
    format!("({}, {})", f(p[0]), f(p[1]))
}

pub(super) fn samples_section(b: &mut Builder, trace: &PixelTrace) {
    let Some(shading) = &trace.sample_shading else {
        return;
    };
    b.section(tr!(b, "probe.samples.title"));
    let rate = match shading.shading_rate {
        ShadingRate::Msaa => tr!(b, "probe.samples.msaa"),
        ShadingRate::Ssaa => tr!(b, "probe.samples.ssaa"),
    };
    b.text(tr!(
        b,
        "probe.samples.intro",
        n = trace.samples.len(),
        rate = rate
    ));
    for s in &trace.samples {
        let at = point(s.position);
        let line = match (s.triangle, s.depth, s.uv) {
            (Some(t), Some(d), Some(uv)) => tr!(
                b,
                "probe.samples.covered",
                k = s.index,
                at = at,
                t = t,
                depth = fmt_number(f64::from(d)),
                uv = point(uv.map(f64::from))
            ),
            _ => tr!(b, "probe.samples.uncovered", k = s.index, at = at),
        };
        b.text(line);
    }
    for t in &shading.triangles {
        triangle_samples(b, shading, t);
    }
    if shading.flat {
        b.text(tr!(b, "probe.samples.flat"));
    }
    b.text(tr!(
        b,
        "probe.samples.resolve",
        n = trace.samples.len(),
        rgba = rgba(shading.resolved)
    ));
}

/// Which samples one triangle covers and where it was shaded, in words.
fn triangle_samples(b: &mut Builder, shading: &SampleShading, t: &TriangleSamples) {
    let list: Vec<String> = t.covered.iter().map(ToString::to_string).collect();
    let covers = tr!(
        b,
        "probe.samples.triangle_covers",
        t = t.triangle,
        list = list.join(", ")
    );
    let why = match (t.evaluated_at, t.centroid_sample) {
        (None, _) => tr!(b, "probe.samples.per_sample"),
        (Some(p), Some(k)) => tr!(b, "probe.samples.centroid_sample", k = k, at = point(p)),
        (Some(p), None) => {
            let at = point(p);
            let mut s = if shading.location == Location::Centroid {
                tr!(b, "probe.samples.centroid_centre", at = at)
            } else {
                tr!(b, "probe.samples.centre", at = at)
            };
            if !t.centre_inside {
                s.push(' ');
                s.push_str(&tr!(b, "probe.samples.extrapolated"));
            }
            s
        }
    };
    b.text(format!("{covers} {why}"));
}
