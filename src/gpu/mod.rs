//! Drawing a barylab clip-space mesh with OpenGL 3.3 core on a headless EGL context
//! (surfaceless platform): Mesa's llvmpipe, or this computer's GPU. Times it and reads its
//! image back.
//!
//! Used by `barylab gpu-check`, the `llvmpipe` benchmark (benches/llvmpipe/main.rs) and the
//! conformance test (tests/llvmpipe.rs). Behind the default cargo feature `gpu`.

pub mod check;
mod compare;
mod context;
pub mod lod_check;
mod mipmaps;
pub mod multisample;
pub mod sample_check;
mod scene;
mod shaders;
pub mod status;
pub mod view;

pub use compare::*;
pub use context::force_llvmpipe_env;
pub use mipmaps::GlLevel;
pub use scene::{GlScene, mesh_at_f32};
use shaders::{FRAGMENT_SHADER, VERTEX_SHADER};

use std::sync::Arc;
use std::time::Instant;

use crate::raster::{Filter, Interpolation, Wrap};
use glow::HasContext;
use khronos_egl as egl;

/// What the fragment shader outputs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Output {
    /// The texture at the interpolated uv.
    Texture,
    /// The interpolated vertex colour.
    VertexColor,
    /// `gl_PrimitiveID + 1` as little-endian RGBA bytes (0 = no triangle).
    TriangleId,
    /// The interpolated values as floats, into an RGBA32F framebuffer:
    /// `(u, v, window depth, 1/w)` (`gl_FragCoord.z`, `gl_FragCoord.w`); see
    /// [`Gpu::read_values`].
    Values,
}

/// An OpenGL 3.3 context (llvmpipe or a GPU) with one scene loaded: a headless one through
/// EGL ([`Gpu::open`]), or a context someone else owns, such as the app's ([`Gpu::on_context`]).
pub struct Gpu {
    /// The EGL display and context when this owns them (headless).
    egl: Option<EglContext>,
    gl: Arc<glow::Context>,
    vendor: String,
    renderer: String,
    version: String,
    /// Programs indexed by [`program_index`], compiled on the first load and kept until the
    /// `Gpu` is dropped (a scene changing every frame, as in the app, does not recompile).
    programs: Vec<glow::Program>,
    objects: Option<Objects>,
    /// GL_MAX_TEXTURE_MAX_ANISOTROPY when the context offers anisotropic filtering.
    max_anisotropy: Option<f32>,
}

/// A headless EGL display and the context made current on it.
struct EglContext {
    egl: egl::DynamicInstance<egl::EGL1_4>,
    display: egl::Display,
    context: egl::Context,
}

struct Objects {
    width: u32,
    height: u32,
    index_count: i32,
    background: [u8; 4],
    vao: glow::VertexArray,
    buffers: [glow::Buffer; 2],
    texture: glow::Texture,
    /// Each mipmap level's size, level 0 first.
    level_sizes: Vec<(u32, u32)>,
    /// The texture's GL wrap mode.
    wrap: i32,
    /// The scene's largest anisotropy (1 = off), used with trilinear filtering.
    anisotropy: u32,
    fbo: glow::Framebuffer,
    renderbuffers: [glow::Renderbuffer; 2],
    /// The RGBA32F framebuffer of [`Output::Values`].
    values_fbo: glow::Framebuffer,
    values_renderbuffers: [glow::Renderbuffer; 2],
}

const OUTPUTS: [Output; 4] = [
    Output::Texture,
    Output::VertexColor,
    Output::TriangleId,
    Output::Values,
];
const MODES: [Interpolation; 2] = [Interpolation::Affine, Interpolation::Perspective];

fn program_index(output: Output, mode: Interpolation) -> usize {
    let o = OUTPUTS.iter().position(|&x| x == output).unwrap_or(0);
    let m = MODES.iter().position(|&x| x == mode).unwrap_or(0);
    o * MODES.len() + m
}

impl Gpu {
    fn compile(&self, output: Output, mode: Interpolation) -> Result<glow::Program, String> {
        let qualifier = match mode {
            Interpolation::Affine => "noperspective",
            Interpolation::Perspective => "smooth",
        };
        let out = OUTPUTS.iter().position(|&x| x == output).unwrap_or(0);
        let vs_src = VERTEX_SHADER.replace("QUALIFIER", qualifier);
        let fs_src = FRAGMENT_SHADER.replace("QUALIFIER", qualifier).replacen(
            "\n",
            &format!("\n#define OUTPUT {out}\n"),
            1,
        );
        self.link(&[
            (glow::VERTEX_SHADER, vs_src),
            (glow::FRAGMENT_SHADER, fs_src),
        ])
    }

    /// Uploads `mesh` (its clip coordinates rounded to f32) with `texture`, at the settings'
    /// size, wrap and background: see [`Gpu::load`].
    pub fn load_mesh(
        &mut self,
        mesh: &crate::raster::ClipMesh,
        texture: &crate::raster::Texture,
        settings: &crate::raster::RenderSettings,
    ) -> Result<(), String> {
        self.load(
            &GlScene::new(
                &mesh_at_f32(mesh),
                texture,
                settings.width,
                settings.height,
                settings.wrap,
                settings.background,
            )
            .with_anisotropy(settings.max_anisotropy.get()),
        )
    }

    /// Uploads a scene: vertex and index buffers, the texture (RGBA8, with barylab's mipmap
    /// levels), and a
    /// `width x height` RGBA8 framebuffer with a 32-bit float depth buffer.
    pub fn load(&mut self, scene: &GlScene) -> Result<(), String> {
        self.unload();
        if self.programs.is_empty() {
            let mut programs = Vec::new();
            for output in OUTPUTS {
                for mode in MODES {
                    programs.push(self.compile(output, mode)?);
                }
            }
            self.programs = programs;
        }
        let gl = &self.gl;
        // SAFETY: plain GL calls on the current context; the slices outlive the calls.
        unsafe {
            let vao = gl.create_vertex_array()?;
            gl.bind_vertex_array(Some(vao));
            let vbo = gl.create_buffer()?;
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
            let bytes: Vec<u8> = scene
                .vertices
                .iter()
                .flatten()
                .flat_map(|f| f.to_ne_bytes())
                .collect();
            gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &bytes, glow::STATIC_DRAW);
            let stride = 9 * 4;
            gl.enable_vertex_attrib_array(0);
            gl.vertex_attrib_pointer_f32(0, 4, glow::FLOAT, false, stride, 0);
            gl.enable_vertex_attrib_array(1);
            gl.vertex_attrib_pointer_f32(1, 2, glow::FLOAT, false, stride, 16);
            gl.enable_vertex_attrib_array(2);
            gl.vertex_attrib_pointer_f32(2, 3, glow::FLOAT, false, stride, 24);
            let ibo = gl.create_buffer()?;
            gl.bind_buffer(glow::ELEMENT_ARRAY_BUFFER, Some(ibo));
            let idx: Vec<u8> = scene.indices.iter().flat_map(|i| i.to_ne_bytes()).collect();
            gl.buffer_data_u8_slice(glow::ELEMENT_ARRAY_BUFFER, &idx, glow::STATIC_DRAW);

            let texture = gl.create_texture()?;
            gl.active_texture(glow::TEXTURE0);
            gl.bind_texture(glow::TEXTURE_2D, Some(texture));
            gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
            gl.tex_image_2d(
                glow::TEXTURE_2D,
                0,
                glow::RGBA8 as i32,
                scene.texture_width as i32,
                scene.texture_height as i32,
                0,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                glow::PixelUnpackData::Slice(Some(&scene.texels)),
            );
            mipmaps::upload_levels(gl, &scene.levels);
            let wrap = match scene.wrap {
                Wrap::Repeat => glow::REPEAT,
                Wrap::ClampToEdge => glow::CLAMP_TO_EDGE,
                Wrap::MirroredRepeat => glow::MIRRORED_REPEAT,
            } as i32;
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_WRAP_S, wrap);
            gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_WRAP_T, wrap);

            let (w, h) = (scene.width as i32, scene.height as i32);
            let (values_fbo, values_renderbuffers) = Self::framebuffer(gl, glow::RGBA32F, w, h)?;
            let (fbo, [color, depth]) = Self::framebuffer(gl, glow::RGBA8, w, h)?;
            gl.viewport(0, 0, w, h);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(glow::LESS);
            gl.disable(glow::CULL_FACE);
            gl.disable(glow::BLEND);
            gl.disable(glow::DITHER);
            for &p in &self.programs {
                gl.use_program(Some(p));
                if let Some(loc) = gl.get_uniform_location(p, "tex") {
                    gl.uniform_1_i32(Some(&loc), 0);
                }
            }
            self.objects = Some(Objects {
                width: scene.width,
                height: scene.height,
                index_count: scene.indices.len() as i32,
                background: scene.background,
                vao,
                buffers: [vbo, ibo],
                texture,
                level_sizes: std::iter::once((scene.texture_width, scene.texture_height))
                    .chain(scene.levels.iter().map(|l| (l.width, l.height)))
                    .collect(),
                wrap,
                anisotropy: scene.max_anisotropy,
                fbo,
                renderbuffers: [color, depth],
                values_fbo,
                values_renderbuffers,
            });
        }
        Ok(())
    }

    /// A `width x height` framebuffer with a colour buffer of `format` and a 32-bit float
    /// depth buffer, left bound.
    ///
    /// # Safety
    /// Plain GL calls: `gl` must be the current context.
    unsafe fn framebuffer(
        gl: &glow::Context,
        format: u32,
        w: i32,
        h: i32,
    ) -> Result<(glow::Framebuffer, [glow::Renderbuffer; 2]), String> {
        // SAFETY: the caller's context is current; the objects are created here.
        unsafe {
            let fbo = gl.create_framebuffer()?;
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
            let color = gl.create_renderbuffer()?;
            gl.bind_renderbuffer(glow::RENDERBUFFER, Some(color));
            gl.renderbuffer_storage(glow::RENDERBUFFER, format, w, h);
            gl.framebuffer_renderbuffer(
                glow::FRAMEBUFFER,
                glow::COLOR_ATTACHMENT0,
                glow::RENDERBUFFER,
                Some(color),
            );
            let depth = gl.create_renderbuffer()?;
            gl.bind_renderbuffer(glow::RENDERBUFFER, Some(depth));
            gl.renderbuffer_storage(glow::RENDERBUFFER, glow::DEPTH_COMPONENT32F, w, h);
            gl.framebuffer_renderbuffer(
                glow::FRAMEBUFFER,
                glow::DEPTH_ATTACHMENT,
                glow::RENDERBUFFER,
                Some(depth),
            );
            let gl_error = gl.get_error();
            let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
            if status != glow::FRAMEBUFFER_COMPLETE {
                let max_size = gl.get_parameter_i32(glow::MAX_RENDERBUFFER_SIZE).max(0) as u32;
                gl.bind_framebuffer(glow::FRAMEBUFFER, None);
                gl.delete_framebuffer(fbo);
                gl.delete_renderbuffer(color);
                gl.delete_renderbuffer(depth);
                let (name, bytes) = if format == glow::RGBA32F {
                    ("RGBA32F", 16)
                } else {
                    ("RGBA8", 4)
                };
                return Err(status::incomplete(
                    status,
                    w.max(0) as u32,
                    h.max(0) as u32,
                    name,
                    bytes,
                    max_size,
                    gl_error,
                ));
            }
            Ok((fbo, [color, depth]))
        }
    }

    fn unload(&mut self) {
        let Some(o) = self.objects.take() else {
            return;
        };
        let gl = &self.gl;
        // SAFETY: deleting objects created on this context.
        unsafe {
            gl.delete_vertex_array(o.vao);
            for b in o.buffers {
                gl.delete_buffer(b);
            }
            gl.delete_texture(o.texture);
            gl.delete_framebuffer(o.fbo);
            gl.delete_framebuffer(o.values_fbo);
            for r in o.renderbuffers.into_iter().chain(o.values_renderbuffers) {
                gl.delete_renderbuffer(r);
            }
        }
    }

    /// Clears and draws the loaded scene once (not waiting for it).
    pub fn draw(&self, output: Output, filter: Filter, mode: Interpolation) -> Result<(), String> {
        self.clear(output, filter, mode)?;
        self.draw_elements()
    }

    /// Draws the loaded scene's triangles with the state [`Gpu::clear`] set.
    pub fn draw_elements(&self) -> Result<(), String> {
        let o = self.objects.as_ref().ok_or("no scene loaded")?;
        // SAFETY: the loaded index buffer holds `index_count` indices.
        unsafe {
            self.gl
                .draw_elements(glow::TRIANGLES, o.index_count, glow::UNSIGNED_INT, 0);
        }
        Ok(())
    }

    /// Selects the program and filter and clears colour and depth (not waiting for it).
    pub fn clear(&self, output: Output, filter: Filter, mode: Interpolation) -> Result<(), String> {
        let o = self.objects.as_ref().ok_or("no scene loaded")?;
        let gl = &self.gl;
        let bg = if matches!(output, Output::TriangleId | Output::Values) {
            [0.0; 4]
        } else {
            o.background.map(|c| f32::from(c) / 255.0)
        };
        let fbo = if output == Output::Values {
            o.values_fbo
        } else {
            o.fbo
        };
        // SAFETY: plain GL calls on the current context with the loaded objects.
        unsafe {
            // All the state a draw needs, set each time: a shared context (the app's) has
            // been used by someone else since.
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
            gl.viewport(0, 0, o.width as i32, o.height as i32);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(glow::LESS);
            gl.depth_mask(true);
            gl.color_mask(true, true, true, true);
            gl.disable(glow::CULL_FACE);
            gl.disable(glow::BLEND);
            gl.disable(glow::DITHER);
            gl.disable(glow::SCISSOR_TEST);
            gl.bind_vertex_array(Some(o.vao));
            gl.active_texture(glow::TEXTURE0);
            gl.bind_texture(glow::TEXTURE_2D, Some(o.texture));
            self.set_filter(filter, o.anisotropy);
            gl.use_program(Some(self.programs[program_index(output, mode)]));
            gl.clear_color(bg[0], bg[1], bg[2], bg[3]);
            gl.clear_depth_f64(1.0);
            gl.clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT);
        }
        Ok(())
    }

    /// Waits until everything drawn so far is finished (glFinish).
    pub fn finish(&self) {
        // SAFETY: a current context.
        unsafe { self.gl.finish() }
    }

    /// Median milliseconds of drawing the scene, draw only, into the colour buffer alone (no
    /// depth test, as the reference figures: the reference scene's triangles do not
    /// overlap): per frame, clear + glFinish untimed, then draw + glFinish timed. One untimed
    /// frame first (llvmpipe compiles the shader variant on first use).
    pub fn time(&self, filter: Filter, mode: Interpolation, frames: u32) -> Result<f64, String> {
        self.time_with(filter, mode, frames, false)
    }

    /// [`Gpu::time`], with the depth test on or off (`depth_test`): on, as barylab always
    /// draws, for meshes whose triangles may overlap.
    pub fn time_with(
        &self,
        filter: Filter,
        mode: Interpolation,
        frames: u32,
        depth_test: bool,
    ) -> Result<f64, String> {
        let result = self.time_frames(filter, mode, frames, depth_test);
        // SAFETY: a current context.
        unsafe { self.gl.enable(glow::DEPTH_TEST) };
        result
    }

    fn time_frames(
        &self,
        filter: Filter,
        mode: Interpolation,
        frames: u32,
        depth_test: bool,
    ) -> Result<f64, String> {
        // `clear` turns the depth test on; switched off after it when not wanted.
        let depth = |on: bool| {
            // SAFETY: a current context.
            unsafe {
                if on {
                    self.gl.enable(glow::DEPTH_TEST)
                } else {
                    self.gl.disable(glow::DEPTH_TEST)
                }
            }
        };
        self.clear(Output::Texture, filter, mode)?;
        depth(depth_test);
        self.draw_elements()?;
        self.finish();
        let mut times = Vec::with_capacity(frames as usize);
        for _ in 0..frames {
            self.clear(Output::Texture, filter, mode)?;
            depth(depth_test);
            self.finish();
            let start = Instant::now();
            self.draw_elements()?;
            self.finish();
            times.push(start.elapsed().as_secs_f64() * 1e3);
        }
        crate::bench::median(&times).ok_or_else(|| "no frames".to_string())
    }

    /// Reads the framebuffer back as RGBA8, image row 0 (the top) first.
    pub fn read(&self) -> Result<Vec<[u8; 4]>, String> {
        let o = self.objects.as_ref().ok_or("no scene loaded")?;
        let (w, h) = (o.width as usize, o.height as usize);
        let mut bytes = readback_buffer(w * h * 4, || {
            format!("reading back the GPU's {w}x{h} image")
        })?;
        // SAFETY: the buffer holds exactly width * height RGBA8 pixels.
        unsafe {
            self.gl.bind_framebuffer(glow::FRAMEBUFFER, Some(o.fbo));
            self.gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            self.gl.read_pixels(
                0,
                0,
                o.width as i32,
                o.height as i32,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                glow::PixelPackData::Slice(Some(&mut bytes)),
            );
        }
        top_row_first(&bytes, w, h, |c| [c[0], c[1], c[2], c[3]])
    }

    /// Draws [`Output::Values`] once and reads the floats back, image row 0 (the top) first:
    /// per pixel `[u, v, window depth, 1/w]`, all 0 where nothing was drawn (1/w > 0 where
    /// something was).
    pub fn read_values(&self, mode: Interpolation) -> Result<Vec<[f32; 4]>, String> {
        self.draw(Output::Values, Filter::Nearest, mode)?;
        self.finish();
        let o = self.objects.as_ref().ok_or("no scene loaded")?;
        let (w, h) = (o.width as usize, o.height as usize);
        let mut bytes = readback_buffer(w * h * 16, || {
            format!("reading back the GPU's {w}x{h} values")
        })?;
        // SAFETY: the buffer holds exactly width * height RGBA32F pixels.
        unsafe {
            self.gl
                .bind_framebuffer(glow::FRAMEBUFFER, Some(o.values_fbo));
            self.gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
            self.gl.read_pixels(
                0,
                0,
                o.width as i32,
                o.height as i32,
                glow::RGBA,
                glow::FLOAT,
                glow::PixelPackData::Slice(Some(&mut bytes)),
            );
        }
        self.release_state();
        top_row_first(&bytes, w, h, rgba32f)
    }

    /// Draws once and reads back.
    pub fn render(
        &self,
        output: Output,
        filter: Filter,
        mode: Interpolation,
    ) -> Result<Vec<[u8; 4]>, String> {
        self.draw(output, filter, mode)?;
        self.finish();
        let pixels = self.read();
        self.release_state();
        pixels
    }

    /// Leaves the context as a window's painter expects it: the default framebuffer bound,
    /// no depth test, no vertex array, program or texture of ours bound.
    fn release_state(&self) {
        // SAFETY: plain GL calls on the current context.
        unsafe {
            self.gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            self.gl.disable(glow::DEPTH_TEST);
            self.gl.bind_vertex_array(None);
            self.gl.use_program(None);
            self.gl.bind_texture(glow::TEXTURE_2D, None);
        }
    }
}

impl Drop for Gpu {
    fn drop(&mut self) {
        self.unload();
        // SAFETY: deleting programs created on this context, which is current.
        unsafe {
            for p in self.programs.drain(..) {
                self.gl.delete_program(p);
            }
        }
        if let Some(e) = &self.egl {
            let _ = e.egl.make_current(e.display, None, None, None);
            let _ = e.egl.destroy_context(e.display, e.context);
            let _ = e.egl.terminate(e.display);
        }
    }
}

/// A zeroed buffer of `n` bytes for a readback, allocated fallibly: when the system refuses
/// the memory, a message naming `what` and the size instead of an abort.
pub(crate) fn readback_buffer(n: usize, what: impl FnOnce() -> String) -> Result<Vec<u8>, String> {
    let mut bytes = Vec::new();
    crate::budget::try_resize(&mut bytes, n, 0u8, what).map_err(|e| e.to_string())?;
    Ok(bytes)
}

/// One RGBA32F pixel's 16 bytes (native order, as GL wrote them) as four floats.
pub(crate) fn rgba32f(p: &[u8]) -> [f32; 4] {
    [0, 4, 8, 12].map(|k| f32::from_ne_bytes([p[k], p[k + 1], p[k + 2], p[k + 3]]))
}

/// Pixels read back from GL (row 0 at the bottom), each decoded from its bytes by `pixel`,
/// in image order, row 0 at the top; the output is allocated fallibly.
fn top_row_first<T>(
    bottom_first: &[u8],
    width: usize,
    height: usize,
    pixel: impl Fn(&[u8]) -> T,
) -> Result<Vec<T>, String> {
    let size = bottom_first.len() / (width * height).max(1);
    let mut out = crate::budget::try_vec(width * height, "the GPU's pixels in image order")
        .map_err(|e| e.to_string())?;
    for row in (0..height).rev() {
        let bytes = &bottom_first[row * width * size..(row + 1) * width * size];
        out.extend(bytes.chunks_exact(size).map(&pixel));
    }
    Ok(out)
}
