//! Which lane code draws: chosen once for many triangles ([`Lanes`]), not per triangle.

use super::*;

/// The build of the lane code that runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Build {
    /// The scalar lane code.
    Scalar,
    /// The portable SIMD lanes (`portable/`) where they apply, else the scalar lane code;
    /// `sse41`: their build compiled with SSE4.1 (x86_64 CPUs that have it).
    Portable { sse41: Option<portable::Sse41> },
    /// The scalar lane code compiled with AVX2 (a texture wrap the vector sampler lacks).
    #[cfg(target_arch = "x86_64")]
    Avx2Scalar,
    /// The AVX2 intrinsics.
    #[cfg(target_arch = "x86_64")]
    Avx2,
}

/// The lane paths for drawing many triangles with one texture and shading (a band of the fast
/// path): the instruction set and the texture sampler are chosen once, when it is made.
pub struct Lanes<'t> {
    texture: &'t Texture,
    shading: LaneShading,
    build: Build,
    #[cfg(target_arch = "x86_64")]
    sampler: Option<avx2::sampler::VecSampler<'t>>,
    /// AVX-512 texture lookups allowed and present.
    #[cfg(target_arch = "x86_64")]
    wide: bool,
}

impl<'t> Lanes<'t> {
    /// The best lane code this CPU and the level `vector` allow for `shading`.
    pub fn new(texture: &'t Texture, shading: LaneShading, vector: VectorLevel) -> Self {
        #[cfg(target_arch = "x86_64")]
        {
            if vector.avx2() {
                let sampler = avx2::sampler::VecSampler::new(texture, &shading);
                let build = if shading.color != LaneColor::Texture || sampler.is_some() {
                    Build::Avx2
                } else {
                    Build::Avx2Scalar
                };
                return Self {
                    texture,
                    shading,
                    build,
                    sampler,
                    wide: vector.avx512(),
                };
            }
        }
        let build = if vector >= VectorLevel::Portable {
            Build::Portable {
                sse41: portable::Sse41::detect(),
            }
        } else {
            Build::Scalar
        };
        Self {
            texture,
            shading,
            build,
            #[cfg(target_arch = "x86_64")]
            sampler: None,
            #[cfg(target_arch = "x86_64")]
            wide: false,
        }
    }

    /// The shading it draws.
    pub fn shading(&self) -> LaneShading {
        self.shading
    }

    /// The texture it samples.
    pub fn texture(&self) -> &'t Texture {
        self.texture
    }

    /// Draws rows `rows` (within the target band) of `tri`, made for this shading, with the
    /// edge-function lanes (see [`edge_triangle`]). `tri` must be
    /// [`exact`](LaneTriangle::exact).
    pub fn edge_triangle(&self, tri: &LaneTriangle, rows: (u32, u32), target: &mut Target<'_>) {
        self.draw(Rasterizer::EdgeFunction, tri, rows, target);
    }

    /// Draws rows `rows` of `tri`, made for this shading (without the wireframe), with the
    /// scanline lanes (see [`scanline_triangle`]).
    pub fn scanline_triangle(&self, tri: &LaneTriangle, rows: (u32, u32), target: &mut Target<'_>) {
        self.draw(Rasterizer::Scanline, tri, rows, target);
    }

    /// Draws rows `rows` of `tri` with the lanes of `rasterizer` in the build chosen when this
    /// was made.
    fn draw(
        &self,
        rasterizer: Rasterizer,
        tri: &LaneTriangle,
        rows: (u32, u32),
        target: &mut Target<'_>,
    ) {
        let (texture, shading) = (self.texture, self.shading);
        match self.build {
            Build::Portable { sse41 } if portable::applies(&shading, texture, target) => {
                let sampler = Sampler::new(texture, shading.filter, shading.wrap);
                portable::draw(rasterizer, sse41, tri, rows, &sampler, shading.mode, target);
            }
            #[cfg(target_arch = "x86_64")]
            Build::Avx2 => {
                let sampler = self.sampler.as_ref();
                if self.wide {
                    // SAFETY: the CPU has AVX2 and AVX-512 F, BW, VL and DQ (`wide` is set
                    // only by `VectorLevel::avx512`).
                    unsafe { avx2::avx512::draw(rasterizer, tri, rows, sampler, &shading, target) }
                } else {
                    // SAFETY: the CPU has AVX2 (`VectorLevel::avx2` chose this build).
                    unsafe { avx2::draw(rasterizer, tri, rows, sampler, &shading, target) }
                }
            }
            #[cfg(target_arch = "x86_64")]
            // SAFETY: the CPU has AVX2 (`VectorLevel::avx2` chose this build).
            Build::Avx2Scalar => unsafe {
                scalar_avx2(rasterizer, tri, rows, texture, shading, target)
            },
            _ => scalar(rasterizer, tri, rows, texture, shading, target),
        }
    }
}

/// The scalar lane code of `rasterizer` (the reference build).
#[inline(always)]
fn scalar(
    rasterizer: Rasterizer,
    tri: &LaneTriangle,
    rows: (u32, u32),
    texture: &Texture,
    shading: LaneShading,
    target: &mut Target<'_>,
) {
    match rasterizer {
        Rasterizer::EdgeFunction => {
            edge_triangle_impl(tri, rows, texture, Some(shading), target, &mut |_, _, _| {})
        }
        Rasterizer::Scanline => {
            scanline::scanline_triangle_impl(tri, rows, texture, shading, target)
        }
    }
}

/// [`scalar`] compiled with AVX2 (a texture wrap the vector sampler lacks).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn scalar_avx2(
    rasterizer: Rasterizer,
    tri: &LaneTriangle,
    rows: (u32, u32),
    texture: &Texture,
    shading: LaneShading,
    target: &mut Target<'_>,
) {
    scalar(rasterizer, tri, rows, texture, shading, target);
}
