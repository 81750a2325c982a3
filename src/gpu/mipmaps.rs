//! Mipmapped filtering on the GL side: barylab's own mipmap pyramid uploaded level by level
//! (the same texels barylab's trilinear filter reads, not glGenerateMipmap's), the min filter
//! GL_LINEAR_MIPMAP_LINEAR for trilinear, GL_TEXTURE_MAX_ANISOTROPY where the context offers
//! EXT_texture_filter_anisotropic / ARB_texture_filter_anisotropic, and the readback of the
//! level of detail the GL used (a "level-coloured" pyramid: an R32F texture whose level k
//! holds the value k everywhere, so trilinear filtering returns `d + f = lambda`, clamped to
//! the levels).

use glow::HasContext;

use super::{Gpu, Output, program_index, readback_buffer, rgba32f, top_row_first};
use crate::raster::{Filter, Interpolation, Texture};

/// One mipmap level as the GL gets it.
#[derive(Clone, Debug, PartialEq)]
pub struct GlLevel {
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// RGBA8, row 0 first (texel row 0, v = 0).
    pub texels: Vec<u8>,
}

/// The RGBA8 bytes of `texture`'s mipmap `level`, row 0 first.
pub(super) fn level_bytes(texture: &Texture, level: u32) -> GlLevel {
    let (w, h) = texture.level_size(level);
    let mut texels = Vec::with_capacity(w as usize * h as usize * 4);
    for j in 0..h {
        for i in 0..w {
            texels.extend_from_slice(&texture.texel_at(level, i, j));
        }
    }
    GlLevel {
        width: w,
        height: h,
        texels,
    }
}

/// The GL's min and mag filters for barylab's filter: GL_NEAREST, GL_LINEAR, or
/// GL_LINEAR_MIPMAP_LINEAR (mag GL_LINEAR) for trilinear.
pub(super) fn gl_filters(filter: Filter) -> (i32, i32) {
    let (min, mag) = match filter {
        Filter::Nearest => (glow::NEAREST, glow::NEAREST),
        Filter::Bilinear => (glow::LINEAR, glow::LINEAR),
        Filter::Trilinear => (glow::LINEAR_MIPMAP_LINEAR, glow::LINEAR),
    };
    (min as i32, mag as i32)
}

/// GL_MAX_TEXTURE_MAX_ANISOTROPY when the context offers anisotropic filtering
/// (GL_EXT_texture_filter_anisotropic, GL_ARB_texture_filter_anisotropic or OpenGL 4.6).
pub(super) fn query_max_anisotropy(gl: &glow::Context) -> Option<f32> {
    let ext = gl.supported_extensions();
    let v = gl.version();
    let offered = ext.contains("GL_EXT_texture_filter_anisotropic")
        || ext.contains("GL_ARB_texture_filter_anisotropic")
        || (!v.is_embedded && (v.major, v.minor) >= (4, 6));
    if !offered {
        return None;
    }
    // SAFETY: a plain query on the current context.
    let max = unsafe { gl.get_parameter_f32(glow::MAX_TEXTURE_MAX_ANISOTROPY) };
    (max >= 1.0).then_some(max)
}

/// Uploads mipmap levels 1, 2, ... of the bound 2D texture and sets its last level.
///
/// # Safety
/// Plain GL calls: `gl` must be the current context, the texture bound to TEXTURE_2D.
pub(super) unsafe fn upload_levels(gl: &glow::Context, levels: &[GlLevel]) {
    // SAFETY: the caller's context is current; each slice holds width * height RGBA8 texels.
    unsafe {
        for (k, l) in levels.iter().enumerate() {
            gl.tex_image_2d(
                glow::TEXTURE_2D,
                k as i32 + 1,
                glow::RGBA8 as i32,
                l.width as i32,
                l.height as i32,
                0,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                glow::PixelUnpackData::Slice(Some(&l.texels)),
            );
        }
        gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_BASE_LEVEL, 0);
        gl.tex_parameter_i32(
            glow::TEXTURE_2D,
            glow::TEXTURE_MAX_LEVEL,
            levels.len() as i32,
        );
    }
}

impl Gpu {
    /// GL_MAX_TEXTURE_MAX_ANISOTROPY when the context offers anisotropic filtering, else
    /// `None` (anisotropic scenes are then drawn trilinear by the GL).
    pub fn max_anisotropy(&self) -> Option<f32> {
        self.max_anisotropy
    }

    /// Sets the bound texture's filters for `filter`, and its GL_TEXTURE_MAX_ANISOTROPY: the
    /// loaded scene's for trilinear, 1 otherwise (where the GL offers it).
    ///
    /// # Safety
    /// Plain GL calls: the context must be current, the texture bound to TEXTURE_2D.
    pub(super) unsafe fn set_filter(&self, filter: Filter, anisotropy: u32) {
        let (min, mag) = gl_filters(filter);
        // SAFETY: the caller's context is current with a texture bound.
        unsafe {
            self.gl
                .tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MIN_FILTER, min);
            self.gl
                .tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAG_FILTER, mag);
            if let Some(max) = self.max_anisotropy {
                let n = if filter == Filter::Trilinear {
                    (anisotropy as f32).min(max)
                } else {
                    1.0
                };
                self.gl
                    .tex_parameter_f32(glow::TEXTURE_2D, glow::TEXTURE_MAX_ANISOTROPY, n);
            }
        }
    }

    /// The level of detail the GL used at every pixel, image row 0 first: the loaded scene
    /// drawn with trilinear filtering (and its anisotropy) from a texture of the loaded
    /// texture's level sizes whose level k is the value k everywhere. Trilinear filtering
    /// reads levels `d` and `d + 1` blended by `f`, so each pixel gets `d + f`: lambda
    /// clamped to `[0, last level]` (0 where magnified); an anisotropic filter gets its
    /// weighted mean of the levels it read. 0 where nothing was drawn.
    pub fn read_levels(&self, mode: Interpolation) -> Result<Vec<f32>, String> {
        let o = self.objects.as_ref().ok_or("no scene loaded")?;
        let (w, h) = (o.width as usize, o.height as usize);
        let mut bytes = readback_buffer(w * h * 16, || {
            format!("reading back the GPU's {w}x{h} levels of detail")
        })?;
        self.clear(Output::Values, Filter::Trilinear, mode)?;
        let gl = &self.gl;
        // SAFETY: plain GL calls on the current context; each level's data holds width *
        // height f32 texels; the readback buffer holds width * height RGBA32F pixels.
        let result = unsafe {
            let texture = gl.create_texture()?;
            gl.active_texture(glow::TEXTURE0);
            gl.bind_texture(glow::TEXTURE_2D, Some(texture));
            gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 4);
            for (k, &(lw, lh)) in o.level_sizes.iter().enumerate() {
                let data: Vec<u8> = std::iter::repeat_n(k as f32, lw as usize * lh as usize)
                    .flat_map(f32::to_ne_bytes)
                    .collect();
                gl.tex_image_2d(
                    glow::TEXTURE_2D,
                    k as i32,
                    glow::R32F as i32,
                    lw as i32,
                    lh as i32,
                    0,
                    glow::RED,
                    glow::FLOAT,
                    glow::PixelUnpackData::Slice(Some(&data)),
                );
            }
            gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
            let last = o.level_sizes.len().saturating_sub(1) as i32;
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_BASE_LEVEL, 0);
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAX_LEVEL, last);
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_WRAP_S, o.wrap);
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_WRAP_T, o.wrap);
            self.set_filter(Filter::Trilinear, o.anisotropy);
            gl.use_program(Some(self.programs[program_index(Output::Texture, mode)]));
            gl.draw_elements(glow::TRIANGLES, o.index_count, glow::UNSIGNED_INT, 0);
            gl.finish();
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
            gl.read_pixels(
                0,
                0,
                o.width as i32,
                o.height as i32,
                glow::RGBA,
                glow::FLOAT,
                glow::PixelPackData::Slice(Some(&mut bytes)),
            );
            gl.bind_texture(glow::TEXTURE_2D, Some(o.texture));
            gl.delete_texture(texture);
            Ok::<(), String>(())
        };
        self.release_state();
        result?;
        top_row_first(&bytes, w, h, |p| rgba32f(p)[0])
    }
}
