//! Which lane code draws: chosen once for many triangles ([`Lanes`]), not per triangle.

use super::*;

/// The build of the lane code that runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Build {
    /// The scalar lane code.
    Scalar,
    /// The portable SIMD lanes (`portable/`) where they apply, else the scalar lane code;
    /// `sse41`: compiled with SSE4.1 (x86_64 CPUs that have it).
    Portable { sse41: bool },
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
        #[cfg(target_arch = "x86_64")]
        let sse41 = std::arch::is_x86_feature_detected!("sse4.1");
        #[cfg(not(target_arch = "x86_64"))]
        let sse41 = false;
        let build = if vector >= VectorLevel::Portable {
            Build::Portable { sse41 }
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
        let (texture, shading) = (self.texture, Some(self.shading));
        let fallback = &mut |_, _, _| {};
        let mode = self.shading.mode;
        match self.build {
            Build::Portable { sse41 } if portable::applies(&self.shading, target) => {
                let sampler = Sampler::new(texture, self.shading.filter, self.shading.wrap);
                #[cfg(target_arch = "x86_64")]
                if sse41 {
                    // SAFETY: the CPU has SSE4.1 (`sse41` is set only when it is detected).
                    unsafe { portable::edge_triangle_sse41(tri, rows, &sampler, mode, target) };
                    return;
                }
                let _ = sse41;
                portable::edge_triangle(tri, rows, &sampler, mode, target);
            }
            #[cfg(target_arch = "x86_64")]
            // SAFETY: the CPU supports AVX2 (`VectorLevel::avx2` chose this build), and AVX-512
            // F, BW, VL and DQ when `wide` (`VectorLevel::avx512`).
            Build::Avx2 => unsafe {
                let sampler = self.sampler.as_ref();
                if self.wide {
                    avx2::avx512::edge_triangle(tri, rows, sampler, &self.shading, target)
                } else {
                    avx2::edge_triangle(tri, rows, sampler, &self.shading, target)
                }
            },
            #[cfg(target_arch = "x86_64")]
            // SAFETY: as above.
            Build::Avx2Scalar => unsafe {
                edge_triangle_avx2(tri, rows, texture, shading, target, fallback)
            },
            _ => edge_triangle_impl(tri, rows, texture, shading, target, fallback),
        }
    }

    /// Draws rows `rows` of `tri`, made for this shading (without the wireframe), with the
    /// scanline lanes (see [`scanline_triangle`]).
    pub fn scanline_triangle(&self, tri: &LaneTriangle, rows: (u32, u32), target: &mut Target<'_>) {
        let (texture, shading) = (self.texture, self.shading);
        if let Build::Portable { sse41 } = self.build
            && portable::applies(&shading, target)
        {
            let sampler = Sampler::new(texture, shading.filter, shading.wrap);
            #[cfg(target_arch = "x86_64")]
            if sse41 {
                // SAFETY: the CPU has SSE4.1 (`sse41` is set only when it is detected).
                unsafe {
                    portable::scanline_triangle_sse41(tri, rows, &sampler, shading.mode, target)
                };
                return;
            }
            let _ = sse41;
            portable::scanline_triangle(tri, rows, &sampler, shading.mode, target);
            return;
        }
        #[cfg(target_arch = "x86_64")]
        match (self.build, &self.sampler) {
            // SAFETY: the CPU supports AVX2 (`VectorLevel::avx2` chose this build), and AVX-512
            // F, BW, VL and DQ when `wide` (`VectorLevel::avx512`).
            (Build::Avx2, sampler) if sampler.is_some() || shading.color != LaneColor::Texture => unsafe {
                if self.wide {
                    avx2::avx512::scanline_triangle(tri, rows, sampler.as_ref(), &shading, target)
                } else {
                    avx2::scanline_triangle(tri, rows, sampler.as_ref(), &shading, target)
                }
            },
            // SAFETY: as above.
            (Build::Avx2 | Build::Avx2Scalar, _) => unsafe {
                scanline::scanline_triangle_avx2(tri, rows, texture, shading, target)
            },
            _ => scanline::scanline_triangle_impl(tri, rows, texture, shading, target),
        }
        #[cfg(not(target_arch = "x86_64"))]
        scanline::scanline_triangle_impl(tri, rows, texture, shading, target);
    }
}
