//! The GL under multisampling: the loaded scene drawn into a multisample framebuffer
//! (`GL_TEXTURE_2D_MULTISAMPLE` colour, values and depth), every sample read back by a second
//! pass that fetches it with `texelFetch(sampler2DMS, p, i)` and writes it to a
//! single-sample float framebuffer, the GL's own resolve (a blit), and the sample positions
//! the GL uses (`gl_SamplePosition`, measured by a per-sample draw).
//!
//! The qualifiers are GLSL's: `smooth`, `noperspective` or `flat` for the interpolation, and
//! nothing (the pixel centre), `centroid` or `sample` for the location; supersampling is the
//! `sample` qualifier (every covered sample shaded at its own position). `flat` takes the
//! last vertex (OpenGL's default convention); the caller rotates a triangle's indices for the
//! first-vertex convention (see [`super::check`]). Needs OpenGL 4.0 (`sample` and
//! `gl_SamplePosition`).

use glow::HasContext;

use super::{Gpu, Output};
use crate::raster::sample::{Location, SampleSettings, ShadingRate};
use crate::raster::{Filter, Interpolation};

/// What one GL sample holds, as read back.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GlSample {
    /// The colour written to it (RGBA8), or the background.
    pub color: [u8; 4],
    /// The uv the fragment shader saw for it.
    pub uv: [f32; 2],
    /// `gl_PrimitiveID + 1` of the triangle that wrote it; 0 when none did.
    pub id: u32,
    /// The depth buffer's value at this sample (1 when nothing was drawn).
    pub depth: f32,
}

/// Every sample of the GL's image, its resolve and its sample positions.
#[derive(Clone, Debug, PartialEq)]
pub struct GlSamples {
    /// Samples per pixel.
    pub count: usize,
    /// `width * height * count` samples, pixel by pixel, image row 0 (the top) first.
    pub samples: Vec<GlSample>,
    /// The GL's resolve (`glBlitFramebuffer` of the multisample colour), row 0 at the top.
    pub resolved: Vec<[u8; 4]>,
    /// Each sample's position in a pixel as `gl_SamplePosition` gives it (from the
    /// bottom-left corner, y up, in pixels).
    pub positions: Vec<[f32; 2]>,
}

/// Colour to attachment 0, `(u, v, gl_PrimitiveID + 1, 0)` to attachment 1.
const FRAGMENT_SHADER: &str = "#version 400 core
QUALIFIER in vec2 v_uv;
QUALIFIER in vec3 v_color;
uniform sampler2D tex;
layout(location = 0) out vec4 out_color;
layout(location = 1) out vec4 out_values;
void main() {
#if OUTPUT == 0
    out_color = texture(tex, v_uv);
#else
    out_color = vec4(v_color, 1.0);
#endif
    out_values = vec4(v_uv, float(gl_PrimitiveID + 1), 0.0);
}
";

/// A triangle over the whole viewport from `gl_VertexID` (no attributes).
const FULL_SCREEN: &str = "#version 400 core
void main() {
    vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID & 2) * 2 - 1));
    gl_Position = vec4(p, 0.0, 1.0);
}
";

/// The second pass: sample `index` of the multisample texture, written out as floats.
const FETCH_SHADER: &str = "#version 400 core
uniform sampler2DMS samples;
uniform int index;
out vec4 out_value;
void main() {
    out_value = texelFetch(samples, ivec2(gl_FragCoord.xy), index);
}
";

/// The sample positions: a per-sample draw writing `gl_SamplePosition` and `gl_SampleID`.
const POSITION_SHADER: &str = "#version 400 core
layout(location = 0) out vec4 out_color;
layout(location = 1) out vec4 out_values;
void main() {
    out_color = vec4(0.0);
    out_values = vec4(gl_SamplePosition, float(gl_SampleID), 1.0);
}
";

/// The GLSL qualifiers of the settings: interpolation (`smooth`, `noperspective`, `flat`)
/// then location (none, `centroid`, `sample`; supersampling is `sample`).
pub fn qualifiers(mode: Interpolation, samples: &SampleSettings) -> String {
    let interpolation = if samples.flat {
        "flat"
    } else {
        match mode {
            Interpolation::Affine => "noperspective",
            Interpolation::Perspective => "smooth",
        }
    };
    let location = match (samples.rate, samples.location) {
        _ if samples.flat => "",
        (ShadingRate::Ssaa, _) | (_, Location::Sample) => " sample",
        (_, Location::Centroid) => " centroid",
        (_, Location::Center) => "",
    };
    format!("{interpolation}{location}")
}

/// The multisample objects of one readback, deleted when it is done.
struct MsObjects {
    fbo: glow::Framebuffer,
    textures: [glow::Texture; 3],
    programs: Vec<glow::Program>,
}

impl Gpu {
    /// Draws the loaded scene with `samples` per pixel (the GL's own sample positions) in the
    /// given mode, qualifiers and output, and reads every sample back (see [`GlSamples`]).
    pub fn read_samples(
        &self,
        output: Output,
        filter: Filter,
        mode: Interpolation,
        samples: &SampleSettings,
    ) -> Result<GlSamples, String> {
        let v = self.gl.version();
        if (v.major, v.minor) < (4, 0) {
            return Err(format!(
                "the OpenGL context is {}; reading samples needs OpenGL 4.0",
                self.version
            ));
        }
        let count = samples.count.get();
        // SAFETY: a current context.
        let max = unsafe { self.gl.get_parameter_i32(glow::MAX_SAMPLES) }.max(0) as usize;
        if count > max {
            return Err(format!(
                "{count} samples per pixel: this OpenGL offers at most {max}"
            ));
        }
        let objects = self.ms_objects(output, mode, samples)?;
        let result = self.read_ms(&objects, output, filter, count);
        // SAFETY: deleting objects created on this context.
        unsafe {
            self.gl.delete_framebuffer(objects.fbo);
            for t in objects.textures {
                self.gl.delete_texture(t);
            }
            for p in objects.programs {
                self.gl.delete_program(p);
            }
        }
        self.release_state();
        result
    }

    /// The multisample framebuffer (RGBA8 colour, RGBA32F values, 32-bit float depth, all
    /// multisample textures) and the three programs: the scene's, the fetch, the positions.
    fn ms_objects(
        &self,
        output: Output,
        mode: Interpolation,
        samples: &SampleSettings,
    ) -> Result<MsObjects, String> {
        let o = self.objects.as_ref().ok_or("no scene loaded")?;
        let q = qualifiers(mode, samples);
        let out = i32::from(output != Output::Texture);
        let scene = self.link(&[
            (
                glow::VERTEX_SHADER,
                super::VERTEX_SHADER
                    .replace("#version 330 core", "#version 400 core")
                    .replace("QUALIFIER", &q),
            ),
            (
                glow::FRAGMENT_SHADER,
                FRAGMENT_SHADER.replace("QUALIFIER", &q).replacen(
                    "\n",
                    &format!("\n#define OUTPUT {out}\n"),
                    1,
                ),
            ),
        ])?;
        let fetch = self.link(&[
            (glow::VERTEX_SHADER, FULL_SCREEN.into()),
            (glow::FRAGMENT_SHADER, FETCH_SHADER.into()),
        ])?;
        let positions = self.link(&[
            (glow::VERTEX_SHADER, FULL_SCREEN.into()),
            (glow::FRAGMENT_SHADER, POSITION_SHADER.into()),
        ])?;
        let n = samples.count.get() as i32;
        let (w, h) = (o.width as i32, o.height as i32);
        let gl = &self.gl;
        // SAFETY: plain GL calls on the current context; the objects are created here.
        unsafe {
            let fbo = gl.create_framebuffer()?;
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
            let mut textures = Vec::new();
            for (format, attachment) in [
                (glow::RGBA8, glow::COLOR_ATTACHMENT0),
                (glow::RGBA32F, glow::COLOR_ATTACHMENT1),
                (glow::DEPTH_COMPONENT32F, glow::DEPTH_ATTACHMENT),
            ] {
                let t = gl.create_texture()?;
                gl.bind_texture(glow::TEXTURE_2D_MULTISAMPLE, Some(t));
                gl.tex_image_2d_multisample(
                    glow::TEXTURE_2D_MULTISAMPLE,
                    n,
                    format as i32,
                    w,
                    h,
                    true,
                );
                gl.framebuffer_texture_2d(
                    glow::FRAMEBUFFER,
                    attachment,
                    glow::TEXTURE_2D_MULTISAMPLE,
                    Some(t),
                    0,
                );
                textures.push(t);
            }
            gl.bind_texture(glow::TEXTURE_2D_MULTISAMPLE, None);
            let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
            let objects = MsObjects {
                fbo,
                textures: [textures[0], textures[1], textures[2]],
                programs: vec![scene, fetch, positions],
            };
            if status != glow::FRAMEBUFFER_COMPLETE {
                gl.delete_framebuffer(fbo);
                for t in objects.textures {
                    gl.delete_texture(t);
                }
                return Err(format!(
                    "the {w}x{h} framebuffer with {n} samples per pixel is incomplete (status {status:#x})"
                ));
            }
            Ok(objects)
        }
    }

    /// Compiles and links one program from its shaders.
    pub(super) fn link(&self, shaders: &[(u32, String)]) -> Result<glow::Program, String> {
        let gl = &self.gl;
        // SAFETY: plain GL calls on the current context.
        unsafe {
            let program = gl.create_program()?;
            for (kind, src) in shaders {
                let shader = gl.create_shader(*kind)?;
                gl.shader_source(shader, src);
                gl.compile_shader(shader);
                if !gl.get_shader_compile_status(shader) {
                    let log = gl.get_shader_info_log(shader);
                    gl.delete_shader(shader);
                    gl.delete_program(program);
                    return Err(format!("shader compile error: {log}"));
                }
                gl.attach_shader(program, shader);
                gl.delete_shader(shader);
            }
            gl.link_program(program);
            if !gl.get_program_link_status(program) {
                let log = gl.get_program_info_log(program);
                gl.delete_program(program);
                return Err(format!("program link error: {log}"));
            }
            Ok(program)
        }
    }

    /// The draws and readbacks of [`Gpu::read_samples`].
    fn read_ms(
        &self,
        ms: &MsObjects,
        output: Output,
        filter: Filter,
        count: usize,
    ) -> Result<GlSamples, String> {
        let o = self.objects.as_ref().ok_or("no scene loaded")?;
        let (w, h) = (o.width as i32, o.height as i32);
        let f = match filter {
            Filter::Nearest => glow::NEAREST,
            _ => glow::LINEAR,
        } as i32;
        let bg = if output == Output::Texture || output == Output::VertexColor {
            o.background.map(|c| f32::from(c) / 255.0)
        } else {
            [0.0; 4]
        };
        let gl = &self.gl;
        let [scene, fetch, positions] = [ms.programs[0], ms.programs[1], ms.programs[2]];
        // SAFETY: plain GL calls on the current context with the loaded objects.
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(ms.fbo));
            gl.draw_buffers(&[glow::COLOR_ATTACHMENT0, glow::COLOR_ATTACHMENT1]);
            gl.viewport(0, 0, w, h);
            gl.enable(glow::MULTISAMPLE);
            gl.disable(glow::CULL_FACE);
            gl.disable(glow::BLEND);
            gl.disable(glow::DITHER);
            gl.disable(glow::SCISSOR_TEST);
            gl.color_mask(true, true, true, true);
            gl.depth_mask(true);
            gl.bind_vertex_array(Some(o.vao));

            // The sample positions: every sample of every pixel runs the shader.
            gl.disable(glow::DEPTH_TEST);
            gl.clear_buffer_f32_slice(glow::COLOR, 1, &[0.0; 4]);
            gl.use_program(Some(positions));
            gl.draw_arrays(glow::TRIANGLES, 0, 3);
            let measured = self.fetch_all(ms.textures[1], fetch, count)?;
            // Every pixel has the same positions: the top-left pixel's.
            let positions: Vec<[f32; 2]> = measured[..count].iter().map(|p| [p[0], p[1]]).collect();

            // The scene.
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(ms.fbo));
            gl.draw_buffers(&[glow::COLOR_ATTACHMENT0, glow::COLOR_ATTACHMENT1]);
            gl.viewport(0, 0, w, h);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(glow::LESS);
            gl.clear_buffer_f32_slice(glow::COLOR, 0, &bg);
            gl.clear_buffer_f32_slice(glow::COLOR, 1, &[0.0; 4]);
            gl.clear_depth_f64(1.0);
            gl.clear(glow::DEPTH_BUFFER_BIT);
            gl.active_texture(glow::TEXTURE0);
            gl.bind_texture(glow::TEXTURE_2D, Some(o.texture));
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MIN_FILTER, f);
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAG_FILTER, f);
            gl.use_program(Some(scene));
            if let Some(loc) = gl.get_uniform_location(scene, "tex") {
                gl.uniform_1_i32(Some(&loc), 0);
            }
            gl.draw_elements(glow::TRIANGLES, o.index_count, glow::UNSIGNED_INT, 0);
            gl.disable(glow::DEPTH_TEST);

            // The GL's resolve: a blit of the colour into the single-sample RGBA8 framebuffer.
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(ms.fbo));
            gl.read_buffer(glow::COLOR_ATTACHMENT0);
            gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, Some(o.fbo));
            gl.blit_framebuffer(
                0,
                0,
                w,
                h,
                0,
                0,
                w,
                h,
                glow::COLOR_BUFFER_BIT,
                glow::NEAREST,
            );
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            let resolved = self.read()?;

            let colors = self.fetch_all(ms.textures[0], fetch, count)?;
            let values = self.fetch_all(ms.textures[1], fetch, count)?;
            let depths = self.fetch_all(ms.textures[2], fetch, count)?;
            let level = |x: f32| (x.clamp(0.0, 1.0) * 255.0).round() as u8;
            let samples = colors
                .iter()
                .zip(&values)
                .zip(&depths)
                .map(|((c, v), d)| GlSample {
                    color: c.map(level),
                    uv: [v[0], v[1]],
                    id: v[2].max(0.0) as u32,
                    depth: d[0],
                })
                .collect();
            Ok(GlSamples {
                count,
                samples,
                resolved,
                positions,
            })
        }
    }

    /// The second pass: every sample of the multisample `texture` fetched into the
    /// single-sample RGBA32F framebuffer, one draw and readback per sample index; the
    /// values pixel by pixel (all samples of a pixel together), image row 0 first.
    ///
    /// # Safety
    /// Plain GL calls: the context must be current and a scene loaded.
    unsafe fn fetch_all(
        &self,
        texture: glow::Texture,
        program: glow::Program,
        count: usize,
    ) -> Result<Vec<[f32; 4]>, String> {
        let o = self.objects.as_ref().ok_or("no scene loaded")?;
        let (w, h) = (o.width as usize, o.height as usize);
        let n = w * h * count;
        let mut out = Vec::new();
        crate::budget::try_resize(&mut out, n, [0.0f32; 4], || {
            format!("the GPU's {count} samples of a {w}x{h} image")
        })
        .map_err(|e| e.to_string())?;
        let mut bytes = super::readback_buffer(w * h * 16, || {
            format!("reading back one sample of the GPU's {w}x{h} image")
        })?;
        let gl = &self.gl;
        // SAFETY: the caller's context is current; the buffer holds w * h RGBA32F pixels.
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(o.values_fbo));
            gl.viewport(0, 0, w as i32, h as i32);
            gl.disable(glow::DEPTH_TEST);
            gl.use_program(Some(program));
            gl.active_texture(glow::TEXTURE1);
            gl.bind_texture(glow::TEXTURE_2D_MULTISAMPLE, Some(texture));
            if let Some(loc) = gl.get_uniform_location(program, "samples") {
                gl.uniform_1_i32(Some(&loc), 1);
            }
            let index = gl.get_uniform_location(program, "index");
            for k in 0..count {
                gl.uniform_1_i32(index.as_ref(), k as i32);
                gl.draw_arrays(glow::TRIANGLES, 0, 3);
                gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
                gl.read_pixels(
                    0,
                    0,
                    w as i32,
                    h as i32,
                    glow::RGBA,
                    glow::FLOAT,
                    glow::PixelPackData::Slice(Some(&mut bytes)),
                );
                for (i, p) in bytes.chunks_exact(16).enumerate() {
                    // GL row 0 is the bottom.
                    let (x, gl_row) = (i % w, i / w);
                    let pixel = (h - 1 - gl_row) * w + x;
                    out[pixel * count + k] = super::rgba32f(p);
                }
            }
            gl.bind_texture(glow::TEXTURE_2D_MULTISAMPLE, None);
            gl.active_texture(glow::TEXTURE0);
        }
        Ok(out)
    }
}
