//! The work a render takes, estimated before it starts: the pixels its triangles cover,
//! overlaps counted (its fragments). A request whose work is absurd (millions of copies of
//! one large triangle) is refused with the estimate and what to change, instead of running
//! for hours.

use anyhow::{Result, bail};
use barylab::raster::ClipMesh;

/// Fragments (pixels covered by a triangle, each overlap counted again) past which a command
/// is refused: at the few hundred million fragments a second of a laptop, about a minute.
pub const MAX_FRAGMENTS: f64 = 1e10;

/// The fragments of drawing `mesh` at `width` x `height`: for each triangle its screen area
/// `|cross(B - A, C - A)| / 2` in pixels (after the divide by w), at most its bounding box
/// within the image; a triangle with a vertex at or behind the eye (w <= 0, clipped) or not
/// finite counts as the whole image.
pub fn fragments(mesh: &ClipMesh, width: u32, height: u32) -> f64 {
    let (w, h) = (f64::from(width), f64::from(height));
    let image = w * h;
    let screen = |i: u32| {
        let c = mesh.vertices.get(i as usize)?.clip;
        (c.w > 0.0 && c.is_finite())
            .then(|| ((c.x / c.w + 1.0) * 0.5 * w, (c.y / c.w + 1.0) * 0.5 * h))
    };
    mesh.triangles
        .iter()
        .map(|t| match (screen(t[0]), screen(t[1]), screen(t[2])) {
            (Some(a), Some(b), Some(c)) => {
                let area = ((b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)).abs() / 2.0;
                let span = |lo: f64, hi: f64, size: f64| (hi.min(size) - lo.max(0.0)).max(0.0);
                let bx = span(a.0.min(b.0).min(c.0), a.0.max(b.0).max(c.0), w);
                let by = span(a.1.min(b.1).min(c.1), a.1.max(b.1).max(c.1), h);
                area.min(bx * by)
            }
            _ => image,
        })
        .sum()
}

/// Refuses drawing `mesh` at `width` x `height` when its [`fragments`] pass
/// [`MAX_FRAGMENTS`]; `what` names the input.
pub fn check(what: &str, mesh: &ClipMesh, width: u32, height: u32) -> Result<()> {
    let f = fragments(mesh, width, height);
    if f <= MAX_FRAGMENTS {
        return Ok(());
    }
    bail!(
        "{what}: drawing its {} triangles at {width}x{height} covers about {f:.1e} pixels \
         (overlaps counted), more than the {MAX_FRAGMENTS:.0e} barylab draws in one command \
         (it would take many minutes); draw it smaller (--size), or use fewer or smaller \
         triangles",
        mesh.triangles.len()
    )
}
