//! The GPU view: the canvas's scene drawn by OpenGL through the app's own glow context (the
//! same clip-space vertices, texture bytes, filter, wrap, `smooth` or `noperspective` uv and
//! depth test), read back and compared with barylab's render of the same settings: barylab
//! beside the GPU, a wipe between them, or the difference image ([`crate::gpu::view`]).
//!
//! GL runs only on the UI thread, inside the frame (where eframe's context is current): the
//! app hands the frame's context to [`GpuView::set_context`] and calls [`GpuView::update`]
//! once per frame; a new draw happens only when the canvas rendered anew or the mode changed.
//! The GL objects are dropped when the view is switched off, when the context changes, and
//! on exit ([`GpuView::release`]). Without a glow context (egui_kittest, another renderer),
//! with OpenGL older than 3.3, or without the `gpu` feature, the view says why in one line.

use std::sync::Arc;

use egui::{Color32, RichText, Ui};

use crate::app::services::style::swatch;

use crate::app::document::state::StateCommand;
use crate::app::services::render::CanvasOutput;
use crate::figure::Compare;
use crate::i18n::Lang;
use crate::raster::{Interpolation, Shading, Texture};

/// Why the GPU view shows no GPU image.
#[derive(Clone, Debug, PartialEq)]
pub enum Unavailable {
    /// No glow context in this frame (egui_kittest, or another renderer).
    NoContext,
    /// barylab was built without the `gpu` feature.
    NotBuilt,
    /// The window's context is older than OpenGL 3.3, or OpenGL ES: its GL_VERSION.
    TooOld(String),
    /// The context cannot do it (too old, OpenGL ES), or a draw failed: the one-line reason.
    Gl(String),
}

/// What the GPU drew differently from the scene's own settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Note {
    /// A shading the GPU shader lacks, compared as vertex colours.
    Shading(Shading),
    /// Anisotropic filtering the GL does not offer: both drawn trilinear.
    NoAnisotropy,
    /// The wireframe overlay left out.
    Wireframe,
    /// GAMES101's sample grid (the GL places only its own positions): both sides drawn with
    /// one sample at the centre.
    Samples,
}

/// One comparison: both images at the canvas's size and how they differ.
pub struct GpuResult {
    /// barylab's image with the settings the GPU drew (see [`GpuResult::notes`]).
    pub ours: Vec<[u8; 4]>,
    /// The GPU's image, row 0 at the top.
    pub gpu: Vec<[u8; 4]>,
    /// The comparison and the difference image.
    pub diff: crate::gpu::view::ImageDiff,
    /// What was drawn differently from the scene's settings.
    pub notes: Vec<Note>,
    /// With several samples per pixel: the per-sample comparison
    /// ([`crate::app::panels::gpu_samples`]).
    pub samples: Option<crate::app::panels::gpu_samples::SamplesSummary>,
    /// With trilinear (or anisotropic) filtering: the GL's level of detail against
    /// barylab's.
    #[cfg(feature = "gpu")]
    pub lod: Option<crate::gpu::lod_check::LodCheck>,
}

/// OpenGL's strings: GL_VENDOR, GL_RENDERER, GL_VERSION.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GlInfo {
    /// GL_VENDOR: who made the driver.
    pub vendor: String,
    /// GL_RENDERER: the GPU (or software renderer) that draws.
    pub renderer: String,
    /// GL_VERSION: the OpenGL version and driver version.
    pub version: String,
}

/// The GPU view's state between frames (not saved).
#[derive(Default)]
pub struct GpuView {
    /// This frame's glow context (`None` under egui_kittest).
    gl: Option<Arc<eframe::glow::Context>>,
    #[cfg(feature = "gpu")]
    gpu: Option<crate::gpu::Gpu>,
    /// What the last draw was made of: the canvas's render generation and the mode.
    key: Option<(u64, Interpolation)>,
    /// The context's OpenGL strings, once read.
    pub info: Option<GlInfo>,
    /// The last comparison of barylab's image with the GPU's.
    pub result: Option<GpuResult>,
    /// Why there is no GPU image, when there is none.
    pub unavailable: Option<Unavailable>,
    /// Increments with every new result (the canvas uploads the images again).
    pub generation: u64,
    /// How long the last comparison took (both renders, read-back, comparison), ms.
    pub draw_ms: f64,
    /// The scene's mode: what the canvas shows where there is no GPU image.
    pub fallback_mode: Interpolation,
    /// Print each new result's summary on standard output (`--screenshot` runs, for tests).
    pub print_summary: bool,
    /// The other image's file name when it is an image file, not the GPU's
    /// ([`crate::app::panels::compare_image`]).
    pub other_name: Option<String>,
}

impl GpuView {
    /// What the canvas shows where there is no GPU image: barylab's in the scene's mode.
    pub fn fallback(&self) -> crate::figure::ViewContent {
        crate::figure::ViewContent::Mode(self.fallback_mode)
    }

    /// A view with nothing drawn; `print_summary` prints each result on standard output.
    pub fn new(print_summary: bool) -> Self {
        Self {
            print_summary,
            ..Self::default()
        }
    }

    /// The frame's glow context (eframe's `frame.gl()`); a different context than before
    /// drops the GL objects made on the old one.
    pub fn set_context(&mut self, gl: Option<&Arc<eframe::glow::Context>>) {
        let same = match (&self.gl, gl) {
            (Some(a), Some(b)) => Arc::ptr_eq(a, b),
            (None, None) => true,
            _ => false,
        };
        if !same {
            self.release();
            self.gl = gl.cloned();
        }
    }

    /// Drops every GL object (the context must be current: call it inside a frame or in
    /// `on_exit`) and forgets the last draw.
    pub fn release(&mut self) {
        #[cfg(feature = "gpu")]
        {
            self.gpu = None;
        }
        self.key = None;
        self.result = None;
        self.info = None;
    }

    /// Whether the view has what the canvas's render needs: a result or a reason for the
    /// current render (always, when the view is off).
    pub fn settled(&self, on: bool, output: Option<&CanvasOutput>, mode: Interpolation) -> bool {
        !on || self.unavailable.is_some()
            || output.is_some_and(|o| self.key == Some((o.generation, mode)))
    }

    /// Once per frame, on the UI thread: draws the canvas's scene with OpenGL when it changed.
    /// Returns whether there is a new result (or a new reason).
    pub fn update(
        &mut self,
        on: bool,
        output: Option<&CanvasOutput>,
        mode: Interpolation,
        texture: &Texture,
    ) -> bool {
        self.fallback_mode = mode;
        if !on {
            let had = self.key.is_some() || self.unavailable.is_some();
            self.release();
            self.unavailable = None;
            return had;
        }
        let Some(out) = output else {
            return false;
        };
        let key = (out.generation, mode);
        if self.key == Some(key) {
            return false;
        }
        self.key = Some(key);
        let before = self.unavailable.clone();
        let start = std::time::Instant::now();
        let drawn = self.draw(out, mode, texture);
        self.draw_ms = start.elapsed().as_secs_f64() * 1e3;
        match drawn {
            Ok(result) => {
                if self.print_summary {
                    println!("gpu view: {}", result.diff.summary_en());
                    #[cfg(feature = "gpu")]
                    if let Some(l) = &result.lod {
                        let renderer = self.info.as_ref().map_or("", |i| i.renderer.as_str());
                        let text: Vec<String> = l.lines(renderer, Lang::En);
                        println!("gpu view lod: {}", text.join(" "));
                    }
                    if let Some(samples) = &result.samples {
                        let lines =
                            crate::app::panels::gpu_samples::summary_lines(samples, Lang::En);
                        let text: Vec<String> = lines.into_iter().map(|(l, _)| l).collect();
                        println!("gpu view samples: {}", text.join(" "));
                    }
                }
                self.result = Some(result);
                self.unavailable = None;
                self.generation += 1;
                true
            }
            Err(why) => {
                self.result = None;
                let changed = before.as_ref() != Some(&why);
                if self.print_summary {
                    println!("gpu view unavailable: {}", reason(&why, Lang::En));
                }
                self.unavailable = Some(why);
                self.generation += 1;
                changed
            }
        }
    }

    #[cfg(not(feature = "gpu"))]
    fn draw(
        &mut self,
        _out: &CanvasOutput,
        _mode: Interpolation,
        _texture: &Texture,
    ) -> Result<GpuResult, Unavailable> {
        Err(Unavailable::NotBuilt)
    }

    #[cfg(feature = "gpu")]
    fn draw(
        &mut self,
        out: &CanvasOutput,
        mode: Interpolation,
        texture: &Texture,
    ) -> Result<GpuResult, Unavailable> {
        use crate::gpu::{Gpu, Output, mesh_at_f32};
        let gl = self.gl.clone().ok_or(Unavailable::NoContext)?;
        if self.gpu.is_none() {
            use eframe::glow::HasContext;
            let v = gl.version();
            if v.is_embedded || (v.major, v.minor) < (3, 3) {
                // SAFETY: a plain query on the frame's context, which is current.
                let version = unsafe { gl.get_parameter_string(eframe::glow::VERSION) };
                return Err(Unavailable::TooOld(version));
            }
            let gpu = Gpu::on_context(gl).map_err(Unavailable::Gl)?;
            self.info = Some(GlInfo {
                vendor: gpu.vendor().to_string(),
                renderer: gpu.renderer().to_string(),
                version: gpu.version().to_string(),
            });
            self.gpu = Some(gpu);
        }
        let gpu = self.gpu.as_mut().ok_or(Unavailable::NoContext)?;
        let (mut settings, output, mut notes) = gpu_settings(out.scene.settings(), mode);
        let mipmapped =
            output == Output::Texture && settings.filter == crate::raster::Filter::Trilinear;
        if mipmapped && settings.max_anisotropy.is_on() && gpu.max_anisotropy().is_none() {
            notes.push(Note::NoAnisotropy);
            settings.max_anisotropy = Default::default();
        }
        let mesh = mesh_at_f32(&out.scene.to_mesh());
        if settings.samples.uses_sample_path() {
            let (ours, gpu_image, diff, summary) =
                crate::app::panels::gpu_samples::draw(gpu, &mesh, texture, &settings, output)
                    .map_err(Unavailable::Gl)?;
            return Ok(GpuResult {
                ours,
                gpu: gpu_image,
                diff,
                notes,
                samples: Some(summary),
                lod: None,
            });
        }
        // Colour, depth and the owning triangle (the fast path draws them).
        let mut f = crate::raster::Framebuffer::empty();
        let buffers = crate::raster::Buffers::ColorDepthUv;
        crate::raster::render_into(&mut f, &mesh, texture, &settings, buffers)
            .map_err(|e| Unavailable::Gl(e.to_string()))?;
        let gl_err = Unavailable::Gl;
        gpu.load_mesh(&mesh, texture, &settings).map_err(gl_err)?;
        let ids = gpu
            .render(Output::TriangleId, settings.filter, mode)
            .map_err(gl_err)?;
        let colors = gpu.render(output, settings.filter, mode).map_err(gl_err)?;
        let diff =
            crate::gpu::view::image_diff(settings.width, &f.triangle, &f.color, &ids, &colors);
        let lod = if mipmapped {
            let ours = (&f.triangle[..], &f.color[..]);
            let l = crate::gpu::lod_check::check_lod(gpu, &mesh, texture, &settings, ours, &colors);
            Some(l.map_err(gl_err)?)
        } else {
            None
        };
        Ok(GpuResult {
            ours: f.color,
            gpu: colors,
            diff,
            notes,
            samples: None,
            lod,
        })
    }
}

/// The settings the GPU draws with, its shader output, and what differs from the scene's
/// own settings: shadings other than texture and vertex colour become vertex colour,
/// no wireframe (as `gpu::check` does).
#[cfg(feature = "gpu")]
fn gpu_settings(
    mut s: crate::raster::RenderSettings,
    mode: Interpolation,
) -> (crate::raster::RenderSettings, crate::gpu::Output, Vec<Note>) {
    use crate::gpu::Output;
    use crate::raster::Filter;
    let mut notes = Vec::new();
    s.mode = mode;
    let output = match s.shading {
        Shading::Texture => Output::Texture,
        Shading::VertexColor => Output::VertexColor,
        other => {
            notes.push(Note::Shading(other));
            s.shading = Shading::VertexColor;
            Output::VertexColor
        }
    };
    if output == Output::VertexColor {
        s.filter = Filter::Nearest;
    }
    if s.wireframe {
        notes.push(Note::Wireframe);
        s.wireframe = false;
    }
    // The GL places its own samples only: GAMES101's grid is drawn with one sample.
    if s.samples.uses_sample_path()
        && s.samples.pattern == crate::raster::sample::SamplePattern::Grid
    {
        notes.push(Note::Samples);
        s.samples = Default::default();
    }
    (s, output, notes)
}

/// The one-line reason, in `lang`.
pub fn reason(why: &Unavailable, lang: Lang) -> String {
    let r = match why {
        Unavailable::NoContext => lang.tr("gpu_view.no_context"),
        Unavailable::NotBuilt => lang.tr("gpu_view.not_built"),
        Unavailable::TooOld(v) => lang.tr_with("gpu_view.too_old", &[("version", v)]),
        Unavailable::Gl(e) => e.clone(),
    };
    lang.tr_with("gpu_view.unavailable", &[("reason", &r)])
}

/// The summary line: "coverage identical on N of M pixels; largest colour difference K
/// levels".
pub fn summary(d: &crate::gpu::view::ImageDiff, lang: Lang) -> String {
    lang.tr_with(
        "gpu_view.summary",
        &[
            ("same", &d.coverage_same()),
            ("total", &d.pixels),
            ("max", &lang.levels(d.max_color_difference)),
        ],
    )
}

fn note_text(note: Note, lang: Lang) -> String {
    match note {
        Note::Shading(s) => {
            let key = match s {
                Shading::Barycentric => "app.controls.barycentric",
                Shading::Depth => "app.controls.depth",
                Shading::Normal => "app.controls.normal",
                Shading::Lambert => "app.controls.lambert",
                Shading::Texture => "app.controls.texture",
                Shading::VertexColor => "app.controls.vertex_color",
            };
            lang.tr_with("gpu_view.note_shading", &[("shading", &lang.tr(key))])
        }
        Note::NoAnisotropy => lang.tr("gpu_view.note_no_anisotropy"),
        Note::Wireframe => lang.tr("gpu_view.note_wireframe"),
        Note::Samples => lang.tr("gpu_view.note_samples"),
    }
}

/// The strip above the canvas in the GPU view: the OpenGL strings, the summary, the worst
/// pixel button, the difference image's legend, or the reason there is no GPU image.
pub fn strip_ui(ui: &mut Ui, view: &GpuView, compare: Compare) -> Vec<StateCommand> {
    // At most this share of the canvas panel (large text on a projector): the rest scrolls.
    let body = ui.text_style_height(&egui::TextStyle::Body);
    let max = (ui.available_height() * STRIP_SHARE).max(body * 2.5);
    ui.scope(|ui| {
        // A solid scroll bar, so that a strip that scrolls shows it does.
        ui.spacing_mut().scroll = egui::style::ScrollStyle::solid();
        egui::ScrollArea::vertical()
            .id_salt("gpu-strip")
            .max_height(max)
            .auto_shrink([false, true])
            .show(ui, |ui| strip_contents(ui, view, compare))
            .inner
    })
    .inner
}

/// The largest share of the canvas panel's height the strip takes.
const STRIP_SHARE: f32 = 0.22;

fn strip_contents(ui: &mut Ui, view: &GpuView, compare: Compare) -> Vec<StateCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut out = Vec::new();
    if let Some(why) = &view.unavailable {
        ui.add(egui::Label::new(RichText::new(reason(why, lang)).color(Color32::LIGHT_RED)).wrap());
        return out;
    }
    let Some(r) = &view.result else {
        ui.label(lang.tr("gpu_view.drawing"));
        return out;
    };
    let d = &r.diff;
    ui.horizontal_wrapped(|ui| {
        let color = if d.coverage_identical() {
            Color32::LIGHT_GREEN
        } else {
            Color32::from_rgb(255, 120, 255)
        };
        out.extend(worst_button(ui, d, lang));
        ui.label(RichText::new(summary(d, lang)).strong().color(color));
        if !d.coverage_identical() {
            ui.label(lang.tr_with(
                "gpu_view.mismatches",
                &[("only_gpu", &d.only_gpu), ("only_barylab", &d.only_barylab)],
            ));
        }
        if d.triangle_mismatches > 0 {
            ui.label(lang.tr_with("gpu_view.triangles", &[("count", &d.triangle_mismatches)]));
        }
    });
    if let Some(s) = &r.samples {
        crate::app::panels::gpu_samples::summary_ui(ui, s);
    }
    #[cfg(feature = "gpu")]
    if let Some(l) = &r.lod {
        let renderer = view.info.as_ref().map_or("", |i| i.renderer.as_str());
        for line in l.lines(renderer, lang) {
            ui.add(egui::Label::new(RichText::new(line.trim_start()).small()).wrap());
        }
    }
    if let Some(info) = &view.info {
        ui.add(
            egui::Label::new(
                RichText::new(lang.tr_with(
                    "gpu_view.renderer",
                    &[
                        ("renderer", &info.renderer),
                        ("vendor", &info.vendor),
                        ("version", &info.version),
                        ("ms", &format!("{:.1}", view.draw_ms)),
                    ],
                ))
                .small(),
            )
            .wrap(),
        );
    }
    if compare == Compare::Difference {
        ui.horizontal_wrapped(|ui| {
            for (c, key) in [
                (crate::gpu::view::ONLY_GPU, "gpu_view.legend_only_gpu"),
                (
                    crate::gpu::view::ONLY_BARYLAB,
                    "gpu_view.legend_only_barylab",
                ),
            ] {
                swatch(ui, c);
                ui.label(RichText::new(lang.tr(key)).small());
            }
            let top = crate::gpu::view::heat_top(d.max_color_difference);
            swatch(
                ui,
                crate::figure::heatmap::heat_color(f32::from(top), f32::from(top)),
            );
            ui.label(RichText::new(lang.tr_with("gpu_view.legend_heat", &[("top", &top)])).small());
        });
    }
    for n in &r.notes {
        ui.add(egui::Label::new(RichText::new(note_text(*n, lang)).small().italics()).wrap());
    }
    out
}

/// "Jump to worst pixel": pins the pixel that differs most.
fn worst_button(ui: &mut Ui, d: &crate::gpu::view::ImageDiff, lang: Lang) -> Option<StateCommand> {
    let button = ui
        .add_enabled(
            d.worst.is_some(),
            egui::Button::new(lang.tr("gpu_view.worst")),
        )
        .on_hover_text(lang.tr("gpu_view.worst_tip"))
        .on_disabled_hover_text(lang.tr("gpu_view.identical"));
    button
        .clicked()
        .then_some(d.worst)
        .flatten()
        .map(|p| StateCommand::Pin(Some(p)))
}

/// The GPU toggle beside the comparison buttons.
pub fn toggle_ui(ui: &mut Ui, on: bool) -> Vec<StateCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut out = Vec::new();
    let rich = RichText::new(lang.tr("gpu_view.toggle"));
    let rich = if on {
        rich.strong().color(Color32::BLACK)
    } else {
        rich
    };
    let mut button = egui::Button::new(rich).selected(on);
    if on {
        button = button.fill(Color32::from_rgb(120, 200, 120));
    }
    if ui
        .add(button)
        .on_hover_text(lang.tr("gpu_view.toggle_tip"))
        .clicked()
    {
        out.push(StateCommand::SetGpuView(!on));
    }
    out
}
