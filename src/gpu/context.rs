//! Opening the headless EGL display and an OpenGL 3.3 core context; the renderer's strings.

use super::*;
use khronos_egl as egl;

/// `EGL_PLATFORM_SURFACELESS_MESA` (EGL_MESA_platform_surfaceless).
const PLATFORM_SURFACELESS_MESA: egl::Enum = 0x31DD;

/// The environment that makes Mesa pick its software rasterizer, headless. Set before EGL is
/// loaded (Mesa reads it at start-up, as it reads `LP_NUM_THREADS`).
pub fn force_llvmpipe_env() {
    // SAFETY: called at the start of the process (or of a test), before any thread that
    // reads the environment is started by us.
    unsafe {
        std::env::set_var("LIBGL_ALWAYS_SOFTWARE", "1");
        std::env::set_var("GALLIUM_DRIVER", "llvmpipe");
        std::env::set_var("EGL_PLATFORM", "surfaceless");
    }
}

impl Gpu {
    /// Mesa's llvmpipe: loads libEGL, opens the surfaceless display and makes a GL 3.3 core
    /// context current on this thread. Fails with a one-line reason when EGL, the platform or
    /// llvmpipe is missing. Call [`force_llvmpipe_env`] first.
    pub fn new() -> Result<Self, String> {
        let gpu = Self::open()?;
        if !gpu.renderer.contains("llvmpipe") {
            return Err(format!(
                "the OpenGL renderer is `{}`, not llvmpipe",
                gpu.renderer
            ));
        }
        Ok(gpu)
    }

    /// Whatever OpenGL 3.3 core the headless EGL display gives: this computer's GPU, or
    /// llvmpipe after [`force_llvmpipe_env`]. Fails with a one-line reason when EGL, the
    /// platform or OpenGL 3.3 is missing.
    pub fn open() -> Result<Self, String> {
        // SAFETY: libEGL is the system's EGL library, which implements the EGL 1.4 API.
        let egl = unsafe { egl::DynamicInstance::<egl::EGL1_4>::load_required() }
            .map_err(|e| format!("cannot load libEGL.so.1 (install libegl1 libegl-mesa0): {e}"))?;
        let display = Self::display(&egl)?;
        egl.initialize(display)
            .map_err(|e| format!("eglInitialize failed: {e}"))?;
        egl.bind_api(egl::OPENGL_API)
            .map_err(|e| format!("eglBindAPI(OpenGL) failed: {e}"))?;
        let config = egl
            .choose_first_config(
                display,
                // The default surface type is a window, which a surfaceless display lacks.
                &[
                    egl::SURFACE_TYPE,
                    egl::PBUFFER_BIT,
                    egl::RENDERABLE_TYPE,
                    egl::OPENGL_BIT,
                    egl::NONE,
                ],
            )
            .map_err(|e| format!("eglChooseConfig failed: {e}"))?
            .ok_or("no EGL config renders OpenGL (install libgl1-mesa-dri)")?;
        let context = egl
            .create_context(
                display,
                config,
                None,
                &[
                    egl::CONTEXT_MAJOR_VERSION,
                    3,
                    egl::CONTEXT_MINOR_VERSION,
                    3,
                    egl::CONTEXT_OPENGL_PROFILE_MASK,
                    egl::CONTEXT_OPENGL_CORE_PROFILE_BIT,
                    egl::NONE,
                ],
            )
            .map_err(|e| format!("cannot create an OpenGL 3.3 core context: {e}"))?;
        egl.make_current(display, None, None, Some(context))
            .map_err(|e| format!("eglMakeCurrent (surfaceless) failed: {e}"))?;
        // SAFETY: the context is current on this thread; the loader returns its entry points.
        let gl = unsafe {
            glow::Context::from_loader_function(|name| {
                egl.get_proc_address(name)
                    .map_or(std::ptr::null(), |f| f as *const _)
            })
        };
        let owned = EglContext {
            egl,
            display,
            context,
        };
        Self::with_context(Arc::new(gl), Some(owned))
    }

    /// Draws on an OpenGL context someone else made current on this thread, such as the app
    /// window's (eframe's glow context): the GPU view beside barylab's canvas. Fails with a
    /// one-line reason when the context is older than OpenGL 3.3 or is OpenGL ES. Every call
    /// must come from the thread the context is current on; [`Gpu::draw`] and the reads leave
    /// the default framebuffer bound and the depth test off.
    pub fn on_context(gl: Arc<glow::Context>) -> Result<Self, String> {
        Self::with_context(gl, None)
    }

    fn with_context(gl: Arc<glow::Context>, egl: Option<EglContext>) -> Result<Self, String> {
        // SAFETY: a current context.
        let [vendor, renderer, version] = [glow::VENDOR, glow::RENDERER, glow::VERSION]
            .map(|p| unsafe { gl.get_parameter_string(p) });
        let v = gl.version();
        if v.is_embedded || (v.major, v.minor) < (3, 3) {
            return Err(format!(
                "the OpenGL context is {version}; the GPU view needs OpenGL 3.3 (not OpenGL ES)"
            ));
        }
        let max_anisotropy = mipmaps::query_max_anisotropy(&gl);
        Ok(Self {
            egl,
            max_anisotropy,
            gl,
            vendor,
            renderer,
            version,
            programs: Vec::new(),
            objects: None,
        })
    }

    fn display(egl: &egl::DynamicInstance<egl::EGL1_4>) -> Result<egl::Display, String> {
        if let Some(egl15) = egl.upcast::<egl::EGL1_5>() {
            // SAFETY: the surfaceless platform takes no native display.
            if let Ok(d) = unsafe {
                egl15.get_platform_display(
                    PLATFORM_SURFACELESS_MESA,
                    egl::DEFAULT_DISPLAY,
                    &[egl::ATTRIB_NONE],
                )
            } {
                return Ok(d);
            }
        }
        // SAFETY: EGL_PLATFORM=surfaceless makes the default display the surfaceless one.
        unsafe { egl.get_display(egl::DEFAULT_DISPLAY) }
            .ok_or_else(|| "no EGL display (surfaceless platform unavailable)".to_string())
    }

    /// The GL_RENDERER string, e.g. `llvmpipe (LLVM 15.0.6, 256 bits)`.
    pub fn renderer(&self) -> &str {
        &self.renderer
    }

    /// The GL_VENDOR string, e.g. `Mesa`.
    pub fn vendor(&self) -> &str {
        &self.vendor
    }

    /// The GL_VERSION string, e.g. `4.5 (Core Profile) Mesa 22.3.6`.
    pub fn version(&self) -> &str {
        &self.version
    }
}
