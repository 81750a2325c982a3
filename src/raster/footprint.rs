//! The memory a render needs, estimated before anything is allocated (the limit and the check
//! are [`crate::budget`]'s): the framebuffer (bytes per pixel from the buffer layout,
//! [`Buffers::bytes_per_pixel`]), the output image, the mesh, and per source triangle what the
//! full render ([`PreparedTriangle`]) or the fast path (`Slot`, `ProjectedVertex`) keeps.

use super::fast::{ProjectedVertex, Slot};
use super::framebuffer::Buffers;
use super::mesh::MeshVertex;
use super::multisample::SampleValue;
use super::prepare::PreparedTriangle;
use super::sample::SampleSettings;
use super::setup::TriangleSetup;
use crate::budget;

/// What a render of `width` x `height` with `buffers` of a mesh with `vertices` and
/// `triangles` needs: the framebuffer, the output image (4 bytes a pixel), the mesh, and per
/// source triangle one set-up triangle (the full render, [`Buffers::All`]) or the fast path's
/// compact record and its place in a band's list (clipped triangles take more, found by
/// fallible allocation).
pub fn render_need(
    width: u32,
    height: u32,
    buffers: Buffers,
    vertices: usize,
    triangles: usize,
) -> u64 {
    let pixels = u64::from(width) * u64::from(height);
    let (per_triangle, per_vertex) = if buffers == Buffers::All {
        (
            size_of::<PreparedTriangle>() + size_of::<TriangleSetup>(),
            0,
        )
    } else {
        (
            size_of::<Slot>() + size_of::<(u32, u32)>() * 2,
            size_of::<ProjectedVertex>(),
        )
    };
    let (per_triangle, per_vertex) = (per_triangle as u64, per_vertex as u64);
    pixels * (buffers.bytes_per_pixel() + 4)
        + vertices as u64 * (size_of::<MeshVertex>() as u64 + per_vertex)
        + triangles as u64 * (per_triangle + size_of::<[u32; 3]>() as u64)
}

/// What the samples of a render add: `width * height * n` sample values ([`SampleValue`])
/// for `n` samples a pixel when the sample path draws; nothing otherwise (the single-sample
/// path keeps none).
pub fn sample_need(width: u32, height: u32, samples: &SampleSettings) -> u64 {
    if !samples.uses_sample_path() {
        return 0;
    }
    let n = samples.count.get() as u64;
    u64::from(width) * u64::from(height) * n * size_of::<SampleValue>() as u64
}

/// Checks a single-sample render before it starts; `what` is named in the message.
pub fn check_render(
    width: u32,
    height: u32,
    buffers: Buffers,
    vertices: usize,
    triangles: usize,
) -> Result<(), budget::MemoryError> {
    check_render_samples(
        (width, height),
        buffers,
        &SampleSettings::default(),
        vertices,
        triangles,
    )
}

/// Checks a render with these sample settings before it starts: [`render_need`] plus
/// [`sample_need`].
pub fn check_render_samples(
    (width, height): (u32, u32),
    buffers: Buffers,
    samples: &SampleSettings,
    vertices: usize,
    triangles: usize,
) -> Result<(), budget::MemoryError> {
    budget::check(
        || {
            let t = if triangles == 1 { "" } else { "s" };
            let n = samples.count.get();
            let s = if n == 1 {
                String::new()
            } else {
                format!(" with {n} samples a pixel")
            };
            format!("a {width}x{height} render of {triangles} triangle{t}{s}")
        },
        render_need(width, height, buffers, vertices, triangles)
            + sample_need(width, height, samples),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::files::bytes;

    #[test]
    fn a_full_size_render_needs_gigabytes() {
        let need = render_need(16384, 16384, Buffers::All, 4, 2);
        assert!(need > 14 << 30, "{}", bytes(need));
        let small = render_need(16384, 16384, Buffers::ColorDepth, 4, 2);
        assert!(small < need / 4, "{}", bytes(small));
    }

    #[test]
    fn ten_million_triangles_need_gigabytes_at_any_size() {
        let need = render_need(800, 600, Buffers::All, 10_000_000, 10_000_000);
        assert!(need > 5 << 30, "{}", bytes(need));
    }
}
