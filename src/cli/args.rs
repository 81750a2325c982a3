//! The command line's arguments: one `clap` struct per subcommand, the scene and sample
//! options they share, and the value parsers of their options.

use std::path::PathBuf;

use barylab::raster;
use barylab::raster::sample::{
    Location, ProvokingVertex, SampleCount, SampleOverride, SamplePattern, SampleSettings,
    ShadingRate,
};
use clap::ValueEnum;

use super::values::*;

#[derive(clap::Args, Debug)]
pub(super) struct LessonArgs {
    /// The lesson file (JSON; see docs/lessons.md), or `builtin` for the built-in lesson.
    pub(super) lesson: PathBuf,
    /// One line per step (the default when nothing else is asked).
    #[arg(long)]
    pub(super) list: bool,
    /// The step (from 1): printed as text, or drawn with --figure.
    #[arg(long, value_name = "N")]
    pub(super) step: Option<usize>,
    /// Write the step's figure here (.png or .svg), as `barylab figure` and the app's Export
    /// draw it.
    #[arg(long, value_name = "OUT", requires = "step")]
    pub(super) figure: Option<PathBuf>,
    /// PNG pixels per figure point for --figure: 1, 2 or 4.
    #[arg(long, default_value_t = 1, value_parser = parse_scale)]
    pub(super) scale: u32,
    /// Write the lesson as a Markdown handout (handout.md, one PNG figure per step) into this
    /// folder; never overwrites a file.
    #[arg(long, value_name = "DIR", conflicts_with_all = ["figure", "list"])]
    pub(super) handout: Option<PathBuf>,
    /// Write the lesson as a slide deck: .html (one self-contained file, no network: the
    /// figures inline; arrow keys, Page Up/Down and space step through it) or .pdf (Beamer,
    /// through pandoc and LaTeX).
    #[arg(long, value_name = "OUT", conflicts_with_all = ["figure", "list", "handout", "step"])]
    pub(super) slides: Option<PathBuf>,
    /// Language of the texts, figure labels and derivations: en, zh (zh-CN), or auto.
    #[arg(long, default_value = "en", value_parser = parse_lang)]
    pub(super) lang: barylab::i18n::Lang,
}

#[derive(clap::Args, Debug)]
pub(super) struct CompareArgs {
    #[command(flatten)]
    pub(super) input: SceneOptions,
    /// The image to compare (PNG, JPEG, BMP, TGA or WebP), the size barylab renders the scene.
    pub(super) image: PathBuf,
    /// Write the difference image here (PNG): dim grey where they agree, red to yellow by
    /// colour difference, magenta where only the image covers a pixel, cyan where only
    /// barylab does.
    #[arg(short, long)]
    pub(super) output: Option<PathBuf>,
    /// The image's background colour (black, white, #rrggbb or R,G,B): other colours are
    /// covered pixels. Default: by alpha if the image has transparent pixels, else the
    /// scene's background colour.
    #[arg(long, value_parser = parse_color, value_name = "COLOR")]
    pub(super) background: Option<[u8; 3]>,
    /// 8-bit levels a channel may differ by and still agree.
    #[arg(long, default_value_t = barylab::compare::DEFAULT_TOLERANCE)]
    pub(super) tolerance: u8,
    /// Print the comparison as JSON.
    #[arg(long)]
    pub(super) json: bool,
    /// Language of the report and the reasons: en, zh (zh-CN), or auto (the system locale:
    /// LC_ALL, LC_MESSAGES, LANG). JSON keeps English texts and adds stable `kind` codes.
    #[arg(long, default_value = "en", value_parser = parse_lang)]
    pub(super) lang: barylab::i18n::Lang,
}

#[derive(clap::Args, Debug)]
pub(super) struct GradeArgs {
    /// The scene files the images are compared with (a student's file name, or the names of
    /// the images in a student's folder, contain the scene's file name when there are
    /// several).
    pub(super) scenes: Vec<PathBuf>,
    /// The folder of submissions: an image per student, or a folder per student.
    #[arg(long, value_name = "DIR")]
    pub(super) submissions: PathBuf,
    /// Write the HTML report here (.html; self-contained).
    #[arg(long, value_name = "OUT")]
    pub(super) report: PathBuf,
    /// Also write a CSV: student, scene, verdict, bug codes, pixels differing.
    #[arg(long, value_name = "FILE")]
    pub(super) csv: Option<PathBuf>,
    /// The roster `barylab assign` wrote: each student's image is compared with their own
    /// variant (instead of SCENE...).
    #[arg(long, value_name = "FILE", conflicts_with = "scenes")]
    pub(super) roster: Option<PathBuf>,
    /// 8-bit levels a channel may differ by and still agree.
    #[arg(long, default_value_t = barylab::compare::DEFAULT_TOLERANCE)]
    pub(super) tolerance: u8,
    /// Language of the report: en, zh (zh-CN), or auto.
    #[arg(long, default_value = "en", value_parser = parse_lang)]
    pub(super) lang: barylab::i18n::Lang,
}

#[derive(clap::Args, Debug)]
pub(super) struct AssignArgs {
    /// The roster: CSV with the student's id in the first column.
    #[arg(long, value_name = "FILE")]
    pub(super) students: PathBuf,
    /// The number that picks the variants: the same roster and number give the same
    /// variants.
    #[arg(long, alias = "seed", value_name = "N")]
    pub(super) number: u64,
    /// A new (or empty) folder for the variants: one folder per student and roster.csv.
    #[arg(long, value_name = "DIR")]
    pub(super) out: PathBuf,
    /// The base scene (world form: a camera and a quad); default: the built-in scene.
    #[arg(long, value_name = "BASE")]
    pub(super) scene: Option<PathBuf>,
}

/// Parses a colour: black, white, #rrggbb or R,G,B.
pub(super) fn parse_color(s: &str) -> Result<[u8; 3], String> {
    let bad = || format!("`{s}` is not a colour like black, white, #1e90ff or 30,144,255");
    let t = s.trim().to_ascii_lowercase();
    match t.as_str() {
        "black" => return Ok([0, 0, 0]),
        "white" => return Ok([255, 255, 255]),
        _ => {}
    }
    if let Some(hex) = t.strip_prefix('#') {
        if hex.len() != 6 || !hex.is_ascii() {
            return Err(bad());
        }
        let c = |i: usize| u8::from_str_radix(&hex[i..i + 2], 16).map_err(|_| bad());
        return Ok([c(0)?, c(2)?, c(4)?]);
    }
    let parts: Vec<&str> = t.split(',').collect();
    if parts.len() != 3 {
        return Err(bad());
    }
    let c = |i: usize| parts[i].trim().parse::<u8>().map_err(|_| bad());
    Ok([c(0)?, c(1)?, c(2)?])
}

#[cfg(feature = "gpu")]
#[derive(clap::Args, Debug)]
pub(super) struct GpuCheckArgs {
    /// Scene files (JSON), OBJ models or images, as for `render`.
    #[arg(required = true)]
    pub(super) scenes: Vec<PathBuf>,
    /// Interpolation mode (default: each scene's).
    #[arg(long)]
    pub(super) mode: Option<ModeArg>,
    /// Texture filter (default: each scene's; trilinear is compared as bilinear).
    #[arg(long)]
    pub(super) filter: Option<FilterArg>,
    /// Image size as WIDTHxHEIGHT (default: each scene's).
    #[arg(long, value_parser = parse_size, allow_hyphen_values = true)]
    pub(super) size: Option<(u32, u32)>,
    /// Use Mesa's software rasterizer (llvmpipe) instead of the GPU.
    #[arg(long)]
    pub(super) software: bool,
    #[command(flatten)]
    pub(super) sampling: SampleOptions,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub(super) json: bool,
    /// Language of the report: en, zh (zh-CN), or auto (the system locale: LC_ALL,
    /// LC_MESSAGES, LANG). JSON stays the same in every language.
    #[arg(long, default_value = "en", value_parser = parse_lang)]
    pub(super) lang: barylab::i18n::Lang,
}

#[derive(clap::Args, Debug)]
pub(super) struct RenderArgs {
    #[command(flatten)]
    pub(super) input: SceneOptions,
    /// Output PNG file.
    #[arg(short, long)]
    pub(super) output: PathBuf,
    /// Also write float32 OpenEXR buffers into this folder: uv.exr, weights_screen.exr,
    /// weights_perspective.exr, depth.exr, inv_w.exr.
    #[arg(long, value_name = "DIR")]
    pub(super) aov: Option<PathBuf>,
    /// Which rasterizer visits the pixels: per-pixel edge functions, or the classic scanline
    /// with per-pixel stepping (same pixels, same values).
    #[arg(long, default_value = "edge")]
    pub(super) rasterizer: RasterizerArg,
    /// Worker threads (default: one per core).
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=256))]
    pub(super) threads: Option<u16>,
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum RasterizerArg {
    Edge,
    Scanline,
}

impl From<RasterizerArg> for raster::render::Rasterizer {
    fn from(r: RasterizerArg) -> Self {
        match r {
            RasterizerArg::Edge => raster::render::Rasterizer::EdgeFunction,
            RasterizerArg::Scanline => raster::render::Rasterizer::Scanline,
        }
    }
}

#[derive(clap::Args, Debug)]
pub(super) struct FigureArgs {
    #[command(flatten)]
    pub(super) input: SceneOptions,
    /// Mark (pin) this pixel as X,Y: its marker, its triangle and the sub-triangles of its
    /// weights.
    #[arg(long, value_parser = parse_pixel, allow_hyphen_values = true)]
    pub(super) pixel: Option<(u32, u32)>,
    /// Also mark this pixel as hovered (marker with crosshair), as X,Y.
    #[arg(long, value_parser = parse_pixel, allow_hyphen_values = true)]
    pub(super) hover: Option<(u32, u32)>,
    /// Compare the modes: one view (default), side by side, a wipe line, or the difference
    /// heatmap.
    #[arg(long, default_value = "single")]
    pub(super) compare: CompareArg,
    /// Wipe line position as a fraction of the width (with --compare wipe).
    #[arg(long, default_value_t = 0.5, value_parser = parse_fraction)]
    pub(super) wipe: f32,
    /// PNG pixels per figure point: 1, 2 or 4 (the scene is rendered again at that
    /// resolution when the pixel size is 1).
    #[arg(long, default_value_t = 1, value_parser = parse_scale)]
    pub(super) scale: u32,
    /// Figure points per rendered pixel, as the app's pixel size (the grid shows from 6, the
    /// sample dots from 10).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=32))]
    pub(super) pixel_size: u32,
    /// Language of the labels: en, zh (zh-CN), or auto (the system locale). Chinese labels
    /// need a CJK font (Noto Sans CJK SC, Source Han Sans SC, WenQuanYi, ...); without one
    /// they stay English.
    #[arg(long, default_value = "en", value_parser = parse_lang)]
    pub(super) lang: barylab::i18n::Lang,
    /// Background around the image (title strip, margins).
    #[arg(long, default_value = "transparent")]
    pub(super) background: BackgroundArg,
    /// Figure points per overlay point: labels, lines, handles and margins this much larger,
    /// as in the app at that text size (the app's Export uses its screen's pixels per point).
    #[arg(long, default_value_t = 1.0, value_parser = parse_overlay_scale)]
    pub(super) overlay_scale: f32,
    /// Leave out the pixel grid.
    #[arg(long)]
    pub(super) no_grid: bool,
    /// Leave out the vertex handles and their w labels.
    #[arg(long)]
    pub(super) no_handles: bool,
    /// Leave out the sub-triangles of the marked pixel.
    #[arg(long)]
    pub(super) no_sub_areas: bool,
    /// Add a caption below the figure with the pinned (else hovered) pixel's key numbers:
    /// the screen weights r s t, the corrected weights a b c, W_P, and uv affine and
    /// perspective-correct, as its derivation gives them.
    #[arg(long)]
    pub(super) caption: bool,
    /// What the figure shows: the rendered image with its overlays (default; also `canvas`);
    /// `texture`: the pinned pixel's texture lookup in texture space (texels, taps and
    /// weights, footprint, mipmap levels, anisotropic probes; needs --pixel); `lod`: every
    /// pixel's mipmap level; `space`: the scene in 3D (eye, frustum, image plane, triangles)
    /// with the ray of the --pixel (else --hover) pixel meeting its triangle at P beside the
    /// affine guess Q, from the --yaw/--pitch/--zoom orbit; `depth`: window depth against
    /// view depth for the scene's near and far planes; `tetra`: the volume weights of a point
    /// inside a tetrahedron scene; `samples`: the per-sample buffers of a multisampled scene
    /// (coverage count, resolve, and sample --sample-index's colour and depth).
    #[arg(long, default_value = "image")]
    pub(super) view: FigureViewArg,
    /// With --view samples: the sample index whose colour and depth are shown (0 to N-1).
    #[arg(long, default_value_t = 0)]
    pub(super) sample_index: u32,
    /// With --view samples: the buffers with GAMES101 A2's black-edge bug (colour kept per
    /// pixel while coverage is per sample).
    #[arg(long)]
    pub(super) black_edges: bool,
    #[command(flatten)]
    pub(super) orbit: super::space::OrbitArgs,
    /// Output file: .png or .svg.
    #[arg(short, long)]
    pub(super) output: PathBuf,
}

/// What `barylab figure` draws.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum FigureViewArg {
    /// The rendered image with its overlays.
    #[value(alias = "canvas")]
    Image,
    /// The pinned pixel's texture lookup in texture space.
    Texture,
    /// Every pixel's mipmap level.
    Lod,
    /// The scene in 3D with the pixel's ray.
    Space,
    /// Window depth against view depth.
    Depth,
    /// The volume weights of a point in a tetrahedron.
    Tetra,
    /// The per-sample buffers of a multisampled scene.
    Samples,
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub(super) enum CompareArg {
    Single,
    Side,
    Wipe,
    Diff,
}

impl From<CompareArg> for barylab::figure::Compare {
    fn from(c: CompareArg) -> Self {
        use barylab::figure::Compare;
        match c {
            CompareArg::Single => Compare::Single,
            CompareArg::Side => Compare::SideBySide,
            CompareArg::Wipe => Compare::Wipe,
            CompareArg::Diff => Compare::Difference,
        }
    }
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub(super) enum BackgroundArg {
    Transparent,
    White,
}

impl From<BackgroundArg> for barylab::figure::Background {
    fn from(b: BackgroundArg) -> Self {
        match b {
            BackgroundArg::Transparent => Self::Transparent,
            BackgroundArg::White => Self::White,
        }
    }
}

/// Parses a fraction in [0, 1].
pub(super) fn parse_fraction(s: &str) -> Result<f32, String> {
    match s.trim().parse::<f32>() {
        Ok(v) if (0.0..=1.0).contains(&v) => Ok(v),
        _ => Err(format!("`{s}` is not a fraction from 0 to 1")),
    }
}

/// Parses an overlay scale within [`barylab::figure::OVERLAY_SCALE_RANGE`].
pub(super) fn parse_overlay_scale(s: &str) -> Result<f32, String> {
    let (lo, hi) = barylab::figure::OVERLAY_SCALE_RANGE;
    match s.trim().parse::<f32>() {
        Ok(v) if (lo..=hi).contains(&v) => Ok(v),
        _ => Err(format!(
            "overlay scale `{s}` is not a number from {lo} to {hi}"
        )),
    }
}

/// Parses a figure scale: 1, 2 or 4.
pub(super) fn parse_scale(s: &str) -> Result<u32, String> {
    match s.trim().parse::<u32>() {
        Ok(v) if barylab::figure::SCALES.contains(&v) => Ok(v),
        _ => Err(format!("scale `{s}` is not 1, 2 or 4")),
    }
}

#[derive(clap::Args, Debug)]
pub(super) struct BenchArgs {
    /// Scene (default: assets/scenes/bench-1080p.json if present, else the built-in default).
    pub(super) scene: Option<PathBuf>,
    /// Image size as WIDTHxHEIGHT (default: the scene's).
    #[arg(long, value_parser = parse_size, allow_hyphen_values = true)]
    pub(super) size: Option<(u32, u32)>,
    /// Frames rendered per configuration; the median is reported.
    #[arg(long, default_value_t = 9, value_parser = clap::value_parser!(u32).range(1..=10000))]
    pub(super) frames: u32,
    /// Print a JSON array of records instead of a table.
    #[arg(long)]
    pub(super) json: bool,
    /// What each frame draws, as the app's compare modes: one image, both modes (side by side
    /// or wiped), or both with the difference heatmap.
    #[arg(long, value_enum, default_value = "single")]
    pub(super) view: barylab::bench::View,
    /// Time only this rasterizer (default: both).
    #[arg(long, value_enum)]
    pub(super) rasterizer: Option<RasterizerArg>,
    /// Time only this filter (default: nearest and bilinear).
    #[arg(long, value_enum)]
    pub(super) filter: Option<FilterArg>,
    /// Time only this interpolation mode (default: both).
    #[arg(long, value_enum)]
    pub(super) mode: Option<ModeArg>,
    /// Time only this many worker threads (default: 1 and the number of cores).
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=256))]
    pub(super) threads: Option<u16>,
    /// The highest instruction set the lanes may use (default: the best the CPU has). Every
    /// level draws the same pixels.
    #[arg(long, value_enum)]
    pub(super) vector: Option<VectorArg>,
    #[command(flatten)]
    pub(super) sampling: SampleOptions,
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum VectorArg {
    /// The scalar lane code (the reference).
    Scalar,
    /// Portable SIMD lanes (SSE2/SSE4.1 on x86_64, NEON on aarch64).
    Portable,
    Avx2,
    Avx512,
}

impl From<VectorArg> for raster::lanes::VectorLevel {
    fn from(v: VectorArg) -> Self {
        match v {
            VectorArg::Scalar => raster::lanes::VectorLevel::Scalar,
            VectorArg::Portable => raster::lanes::VectorLevel::Portable,
            VectorArg::Avx2 => raster::lanes::VectorLevel::Avx2,
            VectorArg::Avx512 => raster::lanes::VectorLevel::Avx512,
        }
    }
}

#[derive(clap::Args, Debug)]
pub(super) struct ProbeArgs {
    #[command(flatten)]
    pub(super) input: SceneOptions,
    /// The pixel as X,Y: column from the left, row from the top, both from 0.
    #[arg(long, value_parser = parse_pixel, allow_hyphen_values = true)]
    pub(super) pixel: (u32, u32),
    /// Output format: a worked example as text, Markdown or a LaTeX fragment, or JSON.
    #[arg(long, default_value = "text")]
    pub(super) format: FormatArg,
    /// Language of the derivation's prose: en, zh (zh-CN), or auto (the system locale:
    /// LC_ALL, LC_MESSAGES, LANG). Formulas are the same in every language; LaTeX stays English.
    #[arg(long, default_value = "en", value_parser = parse_lang)]
    pub(super) lang: barylab::i18n::Lang,
    /// The derivatives the level-of-detail derivation uses (trilinear filtering): coarse (one
    /// pair per 2x2 quad, as the renderer and GPUs) or fine (the pixel's own row and column).
    #[arg(long, default_value = "coarse", value_parser = parse_named::<barylab::raster::interpolate::Derivatives>, value_name = "KIND")]
    pub(super) derivatives: barylab::raster::interpolate::Derivatives,
}

/// `--lang`: a language tag, or `auto` for the system locale.
pub(super) fn parse_lang(s: &str) -> Result<barylab::i18n::Lang, String> {
    if s.eq_ignore_ascii_case("auto") {
        Ok(barylab::i18n::Lang::detect())
    } else {
        s.parse()
    }
}

/// What to draw and how: shared by `render` and `probe`, so a probe describes exactly what
/// `render` draws with the same options.
#[derive(clap::Args, Debug)]
pub(super) struct SceneOptions {
    /// Scene file (JSON; see docs/scene-format.md), or an OBJ model, or an image (PNG, JPEG,
    /// BMP, TGA, WebP) shown on the default quad.
    pub(super) scene: PathBuf,
    /// Interpolation mode (default: the scene's).
    #[arg(long)]
    pub(super) mode: Option<ModeArg>,
    /// Image size as WIDTHxHEIGHT, e.g. 800x600 (default: the scene's).
    #[arg(long, value_parser = parse_size, allow_hyphen_values = true)]
    pub(super) size: Option<(u32, u32)>,
    /// Texture filter (default: the scene's); trilinear uses mipmaps.
    #[arg(long)]
    pub(super) filter: Option<FilterArg>,
    /// The largest anisotropy of trilinear filtering: 1 (off) to 16 (default: the scene's,
    /// else 1).
    #[arg(long, value_parser = parse_anisotropy, value_name = "N")]
    pub(super) anisotropy: Option<barylab::raster::texture::MaxAnisotropy>,
    /// What the colour shows (default: the scene's).
    #[arg(long)]
    pub(super) shading: Option<ShadingArg>,
    /// Overlay the triangles' edges (threshold on the smallest weight).
    #[arg(long)]
    pub(super) wireframe: bool,
    /// Which triangle owns a pixel centre exactly on a shared edge: llvmpipe's rule (left and
    /// bottom edges in image rows, as OpenGL on Mesa) or the top-left rule of Direct3D (and most
    /// Vulkan drivers) (default: the scene's, else llvmpipe).
    #[arg(long, value_name = "RULE")]
    pub(super) tie_rule: Option<TieRuleArg>,
    #[command(flatten)]
    pub(super) sampling: SampleOptions,
}

/// The samples and qualifiers: shared by render, probe, figure, compare, bench and gpu-check.
#[derive(clap::Args, Debug, Default, Clone, Copy)]
pub(super) struct SampleOptions {
    /// Samples per pixel: 1, 4, 8 or 16 (default: the scene's, else 1).
    #[arg(long, value_parser = parse_samples, value_name = "N")]
    pub(super) samples: Option<SampleCount>,
    /// Where the samples lie: standard (the GL's positions) or grid (GAMES101's 2x2, or 4x4)
    /// (default: the scene's, else standard).
    #[arg(long, value_parser = parse_named::<SamplePattern>, value_name = "PATTERN")]
    pub(super) sample_pattern: Option<SamplePattern>,
    /// msaa (one shading per pixel and triangle) or ssaa (every sample shaded) (default: the
    /// scene's, else msaa).
    #[arg(long, value_parser = parse_named::<ShadingRate>, value_name = "RATE")]
    pub(super) shading_rate: Option<ShadingRate>,
    /// Where MSAA evaluates values: center, centroid or sample (default: the scene's, else
    /// center).
    #[arg(long, value_parser = parse_named::<Location>, value_name = "LOCATION")]
    pub(super) location: Option<Location>,
    /// Every attribute flat: the provoking vertex's value.
    #[arg(long)]
    pub(super) flat: bool,
    /// The provoking vertex of --flat: last (OpenGL's default) or first (default: the
    /// scene's, else last).
    #[arg(long, value_parser = parse_named::<ProvokingVertex>, value_name = "VERTEX")]
    pub(super) provoking_vertex: Option<ProvokingVertex>,
}

impl SceneOptions {
    /// The scene's samples with these options applied.
    pub(super) fn samples(&self, scene: &SampleSettings) -> SampleSettings {
        self.sampling.apply(scene)
    }
}

impl SampleOptions {
    /// The options as changes to a scene's samples.
    pub(super) fn overrides(&self) -> SampleOverride {
        SampleOverride {
            count: self.samples,
            pattern: self.sample_pattern,
            rate: self.shading_rate,
            location: self.location,
            flat: self.flat,
            provoking: self.provoking_vertex,
        }
    }

    /// `scene`'s samples with these options applied.
    pub(super) fn apply(&self, scene: &SampleSettings) -> SampleSettings {
        self.overrides().apply(scene)
    }
}
