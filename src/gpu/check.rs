//! `barylab gpu-check`: a scene drawn by barylab and by OpenGL (this computer's GPU, or
//! llvmpipe), compared pixel by pixel: coverage, the owning triangle, colours and uv.

use std::path::Path;

use glam::{Vec2, Vec3};
use serde::Serialize;

use super::{Gpu, Output, mesh_at_f32};
use crate::bench::{filter_name, mode_name};
use crate::raster::sample::{SampleCount, SampleOverride, SamplePattern, SampleSettings};
use crate::raster::setup::TieRule;
use crate::raster::{
    BuiltinTexture, ClipMesh, Filter, Interpolation, MeshVertex, NO_TRIANGLE, RenderSettings,
    Shading, Texture, texture::MaxAnisotropy,
};

/// Mismatched pixels listed in a report (all are counted).
pub const LISTED: usize = 10;

/// What `gpu-check` changes of a scene's own settings.
#[derive(Clone, Copy, Debug, Default)]
pub struct CheckOptions {
    /// The interpolation mode instead of the scene's.
    pub mode: Option<Interpolation>,
    /// The texture filter instead of the scene's.
    pub filter: Option<Filter>,
    /// The image size `(width, height)` in pixels instead of the scene's.
    pub size: Option<(u32, u32)>,
    /// Changes to the scene's samples and qualifiers.
    pub samples: SampleOverride,
}

/// One scene drawn by both, compared.
#[derive(Clone, Debug, Serialize)]
pub struct SceneCheck {
    /// The scene's path or name, as shown in messages.
    pub scene: String,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// `affine` or `perspective`.
    pub mode: &'static str,
    /// The filter compared: `nearest`, `bilinear` or `trilinear`.
    pub filter: &'static str,
    /// What the colours show: `texture` or `vertex_color`.
    pub output: &'static str,
    /// Pixels compared, `width * height`.
    pub pixels: usize,
    /// Pixels barylab covers.
    pub covered: usize,
    /// Pixels covered by one and not the other.
    pub coverage_mismatches: usize,
    /// The first of them, (x, y) in image rows.
    pub coverage_mismatch_pixels: Vec<[u32; 2]>,
    /// Pixels both cover, with different source triangles.
    pub triangle_mismatches: usize,
    /// The first of them (at most [`LISTED`]), (x, y) in image rows.
    pub triangle_mismatch_pixels: Vec<[u32; 2]>,
    /// Over the pixels both cover: the largest difference of one 8-bit channel.
    pub max_color_difference: u8,
    /// `[x, y]` of the first pixel (in row order) with `max_color_difference`; `None` when
    /// it is 0.
    pub max_color_at: Option<[u32; 2]>,
    /// 99.9% of the pixels both cover differ by at most this much.
    pub p999_color_difference: u8,
    /// Pixels whose colour differs at all.
    pub color_differing: usize,
    /// Over the pixels both cover: the largest |u - u_gpu| or |v - v_gpu| (floats read back).
    pub max_uv_difference: f64,
    /// `[x, y]` of the first pixel (in row order) with `max_uv_difference`; `None` when it
    /// is 0.
    pub max_uv_at: Option<[u32; 2]>,
    /// With trilinear (or anisotropic) filtering of the texture: the level of detail the GL
    /// used against barylab's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lod: Option<super::lod_check::LodCheck>,
    /// The multisampled draw, sample by sample, when the settings ask for more than one
    /// sample or for `flat` (the pixel fields above then compare one sample at the centre).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub samples: Option<super::sample_check::SampleCheck>,
    /// What was changed to draw it on the GPU (shading, filter, wireframe); in JSON as
    /// English sentences.
    #[serde(serialize_with = "notes_json")]
    pub notes: Vec<Note>,
}

/// A setting of the scene the GPU check changed to draw it on the GPU.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Note {
    /// A shading the GPU check does not draw: vertex colours are compared instead.
    Shading(Shading),
    /// Anisotropic filtering the GL does not offer (no EXT_texture_filter_anisotropic):
    /// trilinear compared.
    NoAnisotropy,
    /// The wireframe overlay, left out.
    Wireframe,
    /// A sample pattern the GL cannot place (the grid): the samples are not compared.
    SamplePattern,
}

impl Note {
    /// The note in one line, in `lang`.
    pub fn text(self, lang: crate::i18n::Lang) -> String {
        match self {
            Note::Shading(s) => lang.tr_with(
                "compare.gpu_check.note_shading",
                &[("shading", &crate::probe::format::shading_name(lang, s))],
            ),
            Note::NoAnisotropy => lang.tr("compare.gpu_check.note_no_anisotropy"),
            Note::Wireframe => lang.tr("compare.gpu_check.note_wireframe"),
            Note::SamplePattern => lang.tr("compare.gpu_check.note_sample_pattern"),
        }
    }
}

/// The notes as English sentences (JSON stays the same in every language).
fn notes_json<S: serde::Serializer>(notes: &[Note], serializer: S) -> Result<S::Ok, S::Error> {
    serializer.collect_seq(notes.iter().map(|n| n.text(crate::i18n::Lang::En)))
}

impl SceneCheck {
    /// Whether the same pixels are covered (the owning triangle may still differ: see
    /// [`SceneCheck::triangle_mismatches`]).
    pub fn coverage_agrees(&self) -> bool {
        self.coverage_mismatches == 0
            && self
                .samples
                .as_ref()
                .is_none_or(|s| s.coverage_mismatches == 0)
    }
}

/// Loads a scene file (or model, or image) and compares it: see [`check_mesh`].
pub fn check_scene(
    gpu: &mut Gpu,
    path: &Path,
    options: CheckOptions,
) -> Result<SceneCheck, String> {
    let shown = crate::files::shown(path);
    let (mut scene, base) = crate::scene::open_input(path).map_err(|e| e.to_string())?;
    if let Some((w, h)) = options.size {
        scene.set_size(w, h);
    }
    let texture = scene.load_texture(&base).map_err(|e| e.to_string())?;
    let mut settings = scene.settings();
    if let Some(m) = options.mode {
        settings.mode = m;
    }
    if let Some(f) = options.filter {
        settings.filter = f;
    }
    settings.samples = options.samples.apply(&settings.samples);
    check_mesh(gpu, &shown, &scene.to_mesh(), &texture, settings)
        .map_err(|e| format!("{shown}: {e}"))
}

/// Draws `mesh` (its clip coordinates rounded to f32, as the GPU gets them) with both, in the
/// settings' mode and filter, and compares coverage, triangles, colours and uv.
pub fn check_mesh(
    gpu: &mut Gpu,
    name: &str,
    mesh: &ClipMesh,
    texture: &Texture,
    mut settings: RenderSettings,
) -> Result<SceneCheck, String> {
    let mut notes = Vec::new();
    let output = match settings.shading {
        Shading::Texture => Output::Texture,
        Shading::VertexColor => Output::VertexColor,
        other => {
            notes.push(Note::Shading(other));
            settings.shading = Shading::VertexColor;
            Output::VertexColor
        }
    };
    let mipmapped = settings.filter == Filter::Trilinear && output == Output::Texture;
    if mipmapped && settings.max_anisotropy.is_on() {
        match gpu.max_anisotropy() {
            None => {
                notes.push(Note::NoAnisotropy);
                settings.max_anisotropy = MaxAnisotropy::default();
            }
            Some(max) => {
                let n = settings.max_anisotropy.get().min(max as u32).max(1);
                settings.max_anisotropy = MaxAnisotropy::new(n).unwrap_or_default();
            }
        }
    }
    if settings.wireframe {
        notes.push(Note::Wireframe);
        settings.wireframe = false;
    }
    let mesh = mesh_at_f32(mesh);
    if settings.samples.pattern == SamplePattern::Grid && settings.samples.count != SampleCount::One
    {
        notes.push(Note::SamplePattern);
    }
    let samples = if settings.samples.uses_sample_path() && !notes.contains(&Note::SamplePattern) {
        let check = super::sample_check::check_samples(gpu, &mesh, texture, &settings, output)?;
        Some(check.0)
    } else {
        None
    };
    // The pixel comparison: one sample at the centre.
    settings.samples = SampleSettings::default();
    gpu.load_mesh(&mesh, texture, &settings)?;
    let ours = crate::raster::render(&mesh, texture, &settings).map_err(|e| e.to_string())?;
    let ids = gpu.render(Output::TriangleId, settings.filter, settings.mode)?;
    let colors = gpu.render(output, settings.filter, settings.mode)?;
    let values = gpu.read_values(settings.mode)?;
    let f = &ours.frame;
    let uv = match settings.mode {
        Interpolation::Affine => &f.uv_affine,
        Interpolation::Perspective => &f.uv_perspective,
    };
    let width = settings.width;
    let mut c = SceneCheck {
        scene: name.to_string(),
        width,
        height: settings.height,
        mode: mode_name(settings.mode),
        filter: filter_name(settings.filter),
        output: match output {
            Output::Texture => "texture",
            _ => "vertex_color",
        },
        pixels: f.triangle.len(),
        covered: 0,
        coverage_mismatches: 0,
        coverage_mismatch_pixels: Vec::new(),
        triangle_mismatches: 0,
        triangle_mismatch_pixels: Vec::new(),
        max_color_difference: 0,
        max_color_at: None,
        p999_color_difference: 0,
        color_differing: 0,
        max_uv_difference: 0.0,
        max_uv_at: None,
        lod: None,
        samples,
        notes,
    };
    let mut histogram = [0usize; 256];
    let mut both = 0usize;
    for (k, &tri) in f.triangle.iter().enumerate() {
        let xy = [(k as u32) % width, (k as u32) / width];
        let gl_id = u32::from_le_bytes(ids[k]);
        let ours_covered = tri != NO_TRIANGLE;
        c.covered += usize::from(ours_covered);
        if ours_covered != (gl_id != 0) {
            c.coverage_mismatches += 1;
            if c.coverage_mismatch_pixels.len() < LISTED {
                c.coverage_mismatch_pixels.push(xy);
            }
            continue;
        }
        if !ours_covered {
            continue;
        }
        if gl_id != tri + 1 {
            c.triangle_mismatches += 1;
            if c.triangle_mismatch_pixels.len() < LISTED {
                c.triangle_mismatch_pixels.push(xy);
            }
        }
        both += 1;
        let diff = (0..4)
            .map(|i| f.color[k][i].abs_diff(colors[k][i]))
            .max()
            .unwrap_or(0);
        histogram[usize::from(diff)] += 1;
        if diff > 0 {
            c.color_differing += 1;
        }
        if diff > c.max_color_difference {
            c.max_color_difference = diff;
            c.max_color_at = Some(xy);
        }
        let g = values[k];
        if g[3] > 0.0 {
            let d = |a: f32, b: f32| (f64::from(a) - f64::from(b)).abs();
            let duv = d(uv[k][0], g[0]).max(d(uv[k][1], g[1]));
            if duv > c.max_uv_difference {
                c.max_uv_difference = duv;
                c.max_uv_at = Some(xy);
            }
        }
    }
    c.p999_color_difference = percentile(&histogram, both, 0.999);
    if mipmapped {
        let lod = super::lod_check::check_lod(
            gpu,
            &mesh,
            texture,
            &settings,
            (&f.triangle, &f.color),
            &colors,
        )?;
        c.lod = Some(lod);
    }
    Ok(c)
}

/// The smallest difference `d` such that at least `fraction` of `total` values are `<= d`.
fn percentile(histogram: &[usize; 256], total: usize, fraction: f64) -> u8 {
    let needed = (fraction * total as f64).ceil() as usize;
    let mut seen = 0;
    for (d, &n) in histogram.iter().enumerate() {
        seen += n;
        if seen >= needed {
            return d as u8;
        }
    }
    255
}

/// A 64x48 mesh made for ties: a 7x5 lattice of triangles whose vertices sit exactly on pixel
/// centres (cells split along alternating diagonals) and a fan of 12 triangles around one
/// pixel centre, spokes at slopes that hit pixel centres. Many pixel centres lie exactly on
/// shared horizontal, vertical and diagonal edges, so the tie rule decides them.
pub fn tie_lattice() -> (ClipMesh, RenderSettings) {
    let (w, h) = (64u32, 48u32);
    // Window position (x right, y down) to clip space with w = 1.
    let viewport = crate::raster::project::Viewport {
        width: w,
        height: h,
    };
    let vertex = |x: f64, y: f64, k: usize| MeshVertex {
        clip: crate::raster::project::ndc_from_window(glam::DVec2::new(x, y), viewport)
            .extend(0.0)
            .extend(1.0),
        uv: Vec2::new((x / f64::from(w)) as f32, (y / f64::from(h)) as f32),
        color: Vec3::new(
            (k % 3) as f32 / 2.0,
            (k % 5) as f32 / 4.0,
            (k % 7) as f32 / 6.0,
        ),
        normal: Vec3::ZERO,
    };
    let mut mesh = ClipMesh::default();
    let (nx, ny, step, origin) = (7usize, 5usize, 6.0, (4.5, 5.5));
    for j in 0..ny {
        for i in 0..nx {
            let k = mesh.vertices.len();
            mesh.vertices.push(vertex(
                origin.0 + step * i as f64,
                origin.1 + step * j as f64,
                k,
            ));
        }
    }
    let at = |i: usize, j: usize| (j * nx + i) as u32;
    for j in 0..ny - 1 {
        for i in 0..nx - 1 {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            if (i + j) % 2 == 0 {
                mesh.triangles.extend([[a, b, c], [a, c, d]]);
            } else {
                mesh.triangles.extend([[a, b, d], [b, c, d]]);
            }
        }
    }
    let centre = mesh.vertices.len() as u32;
    mesh.vertices.push(vertex(52.5, 30.5, 0));
    let spokes: [(i32, i32); 12] = [
        (8, 0),
        (8, 4),
        (8, 8),
        (4, 8),
        (0, 8),
        (-4, 8),
        (-8, 8),
        (-8, 0),
        (-8, -8),
        (0, -8),
        (4, -8),
        (8, -8),
    ];
    let first = mesh.vertices.len() as u32;
    for (k, (dx, dy)) in spokes.iter().enumerate() {
        mesh.vertices
            .push(vertex(52.5 + f64::from(*dx), 30.5 + f64::from(*dy), k + 1));
    }
    let n = spokes.len() as u32;
    for k in 0..n {
        mesh.triangles
            .push([centre, first + k, first + (k + 1) % n]);
    }
    let settings = RenderSettings {
        width: w,
        height: h,
        ..RenderSettings::default()
    };
    (mesh, settings)
}

/// Which tie rule the GPU's ties follow, from the [`tie_lattice`].
#[derive(Clone, Debug, Serialize)]
pub struct TieCheck {
    /// The rule under which barylab gives every lattice pixel the GPU's triangle, if one does.
    pub follows: Option<TieRule>,
    /// Lattice pixels whose owner (or coverage) differs from the GPU's under barylab's
    /// llvmpipe rule.
    pub differing_llvmpipe: usize,
    /// The same under the top-left rule.
    pub differing_top_left: usize,
    /// Lattice pixels where the two rules themselves differ (centres exactly on an edge
    /// whose owner depends on the rule).
    pub rules_differ_on: usize,
}

/// Draws the [`tie_lattice`] with the GPU and with barylab under each tie rule, and says which
/// rule the GPU's owners match.
pub fn tie_rule(gpu: &mut Gpu) -> Result<TieCheck, String> {
    let (mesh, settings) = tie_lattice();
    let mesh = mesh_at_f32(&mesh);
    let texture = Texture::builtin(BuiltinTexture::Checker);
    gpu.load_mesh(&mesh, &texture, &settings)?;
    let ids = gpu.render(
        Output::TriangleId,
        Filter::Nearest,
        Interpolation::Perspective,
    )?;
    let owners = |tie_rule| -> Result<Vec<u32>, String> {
        let s = RenderSettings {
            tie_rule,
            ..settings
        };
        let r = crate::raster::render(&mesh, &texture, &s).map_err(|e| e.to_string())?;
        Ok(r.frame
            .triangle
            .iter()
            .map(|&t| if t == NO_TRIANGLE { 0 } else { t + 1 })
            .collect())
    };
    let (lp, tl) = (owners(TieRule::Llvmpipe)?, owners(TieRule::TopLeft)?);
    let gl: Vec<u32> = ids.iter().map(|b| u32::from_le_bytes(*b)).collect();
    let differing = |ours: &[u32]| ours.iter().zip(&gl).filter(|(a, b)| a != b).count();
    let (differing_llvmpipe, differing_top_left) = (differing(&lp), differing(&tl));
    let follows = if differing_llvmpipe == 0 {
        Some(TieRule::Llvmpipe)
    } else if differing_top_left == 0 {
        Some(TieRule::TopLeft)
    } else {
        None
    };
    Ok(TieCheck {
        follows,
        differing_llvmpipe,
        differing_top_left,
        rules_differ_on: lp.iter().zip(&tl).filter(|(a, b)| a != b).count(),
    })
}
