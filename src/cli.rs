//! Command-line parsing and the headless commands.

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Result;
use barylab::probe::format::Format;
use barylab::raster::sample::{
    Location, ProvokingVertex, SampleCount, SampleOverride, SamplePattern, SampleSettings,
    ShadingRate,
};
use barylab::raster::{self, Filter, Interpolation, Shading};
use barylab::scene::Scene;
use clap::{Parser, Subcommand, ValueEnum};

use crate::output::{self, note, print};
use crate::progress_line::ProgressLine;

mod animate;
mod assign;
mod commands;
mod compare;
#[cfg(feature = "gpu")]
mod gpu_check;
mod grade;
mod lesson;
mod samples_figure;
mod slides;
mod space;
mod texture_figure;
mod values;
mod work;

use values::*;

const EXAMPLES: &str = "\
Examples:
  barylab                                   open the app (last state, or the built-in default scene)
  barylab assets/scenes/front.json          open the app on a scene file
  barylab assets/models/torus.obj           open the app on a model (drag to orbit)
  barylab photo.jpg                         open the app with a photo as the texture
  barylab render photo.jpg -o out.png       the photo on the default quad
  barylab render assets/models/torus.obj -o out.png
  barylab --screenshot shot.png             open the app, save a screenshot, exit
  barylab --screenshot s.png --window 1024x768 --present   the same, as on a projector
  barylab --compare gpu                     open the app with barylab beside this computer's GPU
  barylab render assets/scenes/default.json -o out.png
  barylab render assets/scenes/default.json --mode affine --size 400x300 -o affine.png
  barylab render assets/scenes/clip-two-triangles.json --filter nearest --aov aov/ -o out.png
  barylab probe assets/scenes/default.json --pixel 400,420
  barylab probe assets/scenes/default.json --pixel 400,420 --mode affine --format markdown > notes.md
  barylab figure assets/scenes/default.json --pixel 400,420 -o fig.svg
  barylab figure assets/scenes/default.json --size 400x300 --compare side --scale 2 -o fig.png
  barylab compare assets/scenes/games101-a2.json output.png --background black -o diff.png
  barylab grade assets/scenes/games101-a2.json --submissions homework/ --report report.html --csv grades.csv
  barylab assign --students roster.csv --number 2026 --out variants/
  barylab gpu-check assets/scenes/*.json
  barylab lesson builtin --list             the built-in lesson's steps
  barylab lesson builtin --step 9 --figure step9.png
  barylab lesson builtin --handout handout/ --lang zh
  barylab animate assets/scenes/default.json --sweep depth -o depth.gif
  barylab --lesson builtin --step 9         open the app on a lesson step
  barylab --compare-image out.png scene.json   open the app comparing out.png with the scene";

/// barylab: see how a GPU interpolates across a triangle, pixel by pixel.
#[derive(Parser, Debug)]
#[command(name = "barylab", version, about, after_help = EXAMPLES, args_conflicts_with_subcommands = true)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    /// Scene file (.json), OBJ model or image to open in the app (default: the scene saved last
    /// time, or the built-in one). An image becomes the texture of the scene.
    scene: Option<PathBuf>,
    /// Open the app, save a screenshot of the first rendered frame to this PNG, and exit.
    #[arg(long, value_name = "FILE")]
    screenshot: Option<PathBuf>,
    /// Start from the built-in defaults instead of the state saved last time (and do not save).
    #[arg(long)]
    fresh: bool,
    /// Window size in points, e.g. 1024x768 (also `--window`).
    #[arg(long, alias = "window", value_parser = parse_window_size, value_name = "WxH")]
    window_size: Option<(u32, u32)>,
    /// Start in presentation mode (panels hidden, the pixel card shown); F5 or Esc leaves it.
    #[arg(long)]
    present: bool,
    /// Start with this pixel of the image pinned (e.g. for a --screenshot).
    #[arg(long, value_parser = parse_pixel, value_name = "X,Y")]
    pin: Option<(u32, u32)>,
    /// Language of the app: en, zh (zh-CN), or auto (the system locale: LC_ALL, LC_MESSAGES,
    /// LANG). Default: the language chosen last time, else the system locale's.
    #[arg(long, value_parser = parse_lang, value_name = "LANG")]
    lang: Option<barylab::i18n::Lang>,
    /// Text size of the app (its zoom), 0.75 to 2.5, e.g. 1.5 for a projector.
    #[arg(long, value_parser = parse_text_size, value_name = "SIZE")]
    text_size: Option<f32>,
    /// Open the app on a lesson: a lesson file (JSON, see docs/lessons.md) or `builtin`.
    #[arg(long, value_name = "FILE")]
    lesson: Option<PathBuf>,
    /// With --lesson: start at this step (from 1).
    #[arg(long, value_name = "N", requires = "lesson")]
    step: Option<usize>,
    /// Start in this comparison: single, side, wipe, difference (affine beside
    /// perspective-correct), or gpu (barylab beside this computer's OpenGL), gpu-single,
    /// gpu-wipe, gpu-difference.
    #[arg(long, value_parser = parse_compare, value_name = "VIEW")]
    compare: Option<(barylab::figure::Compare, bool)>,
    /// Start with the 3D view beside the canvas: the eye, the frustum, the triangles and the
    /// pinned or hovered pixel's ray.
    #[arg(long)]
    space_view: bool,
    /// Start with File > Export animation… open, on a sweep or a recording (screenshots of the
    /// window).
    #[arg(long, hide = true, value_name = "sweep|recording", value_parser = ["sweep", "recording"])]
    animation_window: Option<String>,
    /// Start comparing this image (a student's rasterizer output, a screenshot) with barylab's
    /// render of the scene, as File > Compare with image… does.
    #[arg(long, value_name = "IMAGE")]
    compare_image: Option<PathBuf>,
    /// With --compare-image: the image's background colour (black, white, #rrggbb or R,G,B);
    /// other colours are covered (default: alpha if the image has transparency, else the
    /// scene's background colour).
    #[arg(long, value_parser = parse_color, value_name = "COLOR", requires = "compare_image")]
    compare_background: Option<[u8; 3]>,
    /// Type these predictions into the quiz of the --lesson step (or of the pinned pixel)
    /// and press Reveal, e.g. for a --screenshot of a verdict: the numbers in the quiz's
    /// order, separated by spaces or semicolons ("0.25 0.56 0.19").
    #[arg(long, value_name = "NUMBERS")]
    quiz_answers: Option<String>,
    /// Memory a render, figure, scene or model may use, e.g. 2G or 512M (default: the
    /// environment variable BARYLAB_MEMORY_LIMIT if set, else 75% of the available memory).
    #[arg(long, global = true, value_parser = parse_memory, value_name = "SIZE")]
    memory_limit: Option<u64>,
}

/// Parses a memory size such as 2G, 512M or 1000000.
fn parse_memory(s: &str) -> Result<u64, String> {
    barylab::budget::parse_size(s)
        .ok_or_else(|| format!("`{s}` is not a memory size like 2G, 512M or 1000000"))
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Render a scene file to a PNG image (and optionally float32 EXR buffers).
    #[command(after_help = EXAMPLES)]
    Render(RenderArgs),
    /// Print every number behind one pixel: coverage, weights four ways, the 1/w
    /// derivation, the 4x4 system, uv, texel, depth and the final colour.
    #[command(after_help = EXAMPLES)]
    Probe(ProbeArgs),
    /// Write the annotated figure the app shows (overlays, labels, marked pixel, comparison)
    /// as PNG or SVG, through the same code as the app's Export.
    #[command(after_help = EXAMPLES)]
    Figure(FigureArgs),
    /// Time the rasterizers: every rasterizer x filter x mode x thread count, median ms per
    /// frame and Mpixel/s.
    #[command(
        after_help = "Examples:\n  barylab bench\n  barylab bench assets/scenes/default.json --frames 20 --json"
    )]
    Bench(BenchArgs),
    /// Compare an image from another rasterizer (a student's, a screenshot) with barylab's
    /// render of the same scene: coverage, colours, a difference image, and the first
    /// differing pixels each with a reason. Exits 0 when they agree, 1 when they differ.
    #[command(
        after_help = "Examples:\n  barylab compare assets/scenes/games101-a2.json output.png --background black\n  barylab compare assets/scenes/default.json shot.png -o diff.png --json"
    )]
    Compare(CompareArgs),
    /// Grade a class: every student's image in a folder against barylab's renders of the
    /// scenes, in parallel; an HTML report (verdicts, named bugs, difference thumbnails,
    /// regions and reasons per student) and a CSV.
    #[command(
        after_help = "Examples:\n  barylab grade assets/scenes/games101-a2.json --submissions homework/ --report report.html --csv grades.csv\n  barylab grade --roster variants/roster.csv --submissions homework/ --report report.html"
    )]
    Grade(GradeArgs),
    /// Make a variant of a course scene per student (corners, uv, colours and camera moved
    /// within limits that keep the task well-posed): scene file, task sheet and answer key.
    #[command(
        after_help = "Examples:\n  barylab assign --students roster.csv --number 2026 --out variants/\n  barylab grade --roster variants/roster.csv --submissions homework/ --report report.html"
    )]
    Assign(AssignArgs),
    /// A lesson (a file, or `builtin`): list its steps, print one, write a step's figure, or
    /// write the whole lesson as a Markdown handout with its figures or as a slide deck.
    #[command(
        after_help = "Examples:\n  barylab lesson builtin --list\n  barylab lesson builtin --step 9\n  barylab lesson builtin --step 9 --figure step9.svg\n  barylab lesson my-lesson.json --handout handout/ --lang zh\n  barylab lesson builtin --slides deck.html\n  pandoc handout/handout.md -o handout.html"
    )]
    Lesson(LessonArgs),
    /// A sweep of a scene as an animation for slides (GIF, APNG, WebP, MP4): the wipe from
    /// affine to perspective-correct, a corner pushed away, a tilt, the pinned pixel walking
    /// its row, the rasterizers filling the triangles, a corner crossing the near plane. Every
    /// frame is the figure `barylab figure` draws.
    #[command(
        after_help = "Examples:\n  barylab animate assets/scenes/default.json --sweep affine-perspective -o wipe.gif\n  barylab animate assets/scenes/default.json --sweep depth --frames 60 -o depth.apng\n  barylab animate assets/scenes/default.json --sweep fill-scanline --size 40x30 --pixel-size 12 -o fill.gif\n  barylab animate assets/scenes/default.json --sweep row --pixel 400,300 --lang zh -o row.webp"
    )]
    Animate(animate::AnimateArgs),
    /// Draw scenes with barylab and with this computer's OpenGL (headless EGL; Mesa's
    /// llvmpipe with --software) and compare them pixel by pixel: coverage, the owning
    /// triangle, colours, uv, and which tie rule the GPU follows. Exits non-zero when
    /// coverage differs.
    #[cfg(feature = "gpu")]
    #[command(
        name = "gpu-check",
        after_help = "Examples:\n  barylab gpu-check assets/scenes/*.json\n  barylab gpu-check assets/scenes/default.json --mode affine --filter nearest --json"
    )]
    GpuCheck(GpuCheckArgs),
}

#[derive(clap::Args, Debug)]
struct LessonArgs {
    /// The lesson file (JSON; see docs/lessons.md), or `builtin` for the built-in lesson.
    lesson: PathBuf,
    /// One line per step (the default when nothing else is asked).
    #[arg(long)]
    list: bool,
    /// The step (from 1): printed as text, or drawn with --figure.
    #[arg(long, value_name = "N")]
    step: Option<usize>,
    /// Write the step's figure here (.png or .svg), as `barylab figure` and the app's Export
    /// draw it.
    #[arg(long, value_name = "OUT", requires = "step")]
    figure: Option<PathBuf>,
    /// PNG pixels per figure point for --figure: 1, 2 or 4.
    #[arg(long, default_value_t = 1, value_parser = parse_scale)]
    scale: u32,
    /// Write the lesson as a Markdown handout (handout.md, one PNG figure per step) into this
    /// folder; never overwrites a file.
    #[arg(long, value_name = "DIR", conflicts_with_all = ["figure", "list"])]
    handout: Option<PathBuf>,
    /// Write the lesson as a slide deck: .html (one self-contained file, no network: the
    /// figures inline; arrow keys, Page Up/Down and space step through it) or .pdf (Beamer,
    /// through pandoc and LaTeX).
    #[arg(long, value_name = "OUT", conflicts_with_all = ["figure", "list", "handout", "step"])]
    slides: Option<PathBuf>,
    /// Language of the texts, figure labels and derivations: en, zh (zh-CN), or auto.
    #[arg(long, default_value = "en", value_parser = parse_lang)]
    lang: barylab::i18n::Lang,
}

#[derive(clap::Args, Debug)]
struct CompareArgs {
    #[command(flatten)]
    input: SceneOptions,
    /// The image to compare (PNG, JPEG, BMP, TGA or WebP), the size barylab renders the scene.
    image: PathBuf,
    /// Write the difference image here (PNG): dim grey where they agree, red to yellow by
    /// colour difference, magenta where only the image covers a pixel, cyan where only
    /// barylab does.
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// The image's background colour (black, white, #rrggbb or R,G,B): other colours are
    /// covered pixels. Default: by alpha if the image has transparent pixels, else the
    /// scene's background colour.
    #[arg(long, value_parser = parse_color, value_name = "COLOR")]
    background: Option<[u8; 3]>,
    /// 8-bit levels a channel may differ by and still agree.
    #[arg(long, default_value_t = barylab::compare::DEFAULT_TOLERANCE)]
    tolerance: u8,
    /// Print the comparison as JSON.
    #[arg(long)]
    json: bool,
    /// Language of the report and the reasons: en, zh (zh-CN), or auto (the system locale:
    /// LC_ALL, LC_MESSAGES, LANG). JSON keeps English texts and adds stable `kind` codes.
    #[arg(long, default_value = "en", value_parser = parse_lang)]
    lang: barylab::i18n::Lang,
}

#[derive(clap::Args, Debug)]
struct GradeArgs {
    /// The scene files the images are compared with (a student's file name, or the names of
    /// the images in a student's folder, contain the scene's file name when there are
    /// several).
    scenes: Vec<PathBuf>,
    /// The folder of submissions: an image per student, or a folder per student.
    #[arg(long, value_name = "DIR")]
    submissions: PathBuf,
    /// Write the HTML report here (.html; self-contained).
    #[arg(long, value_name = "OUT")]
    report: PathBuf,
    /// Also write a CSV: student, scene, verdict, bug codes, pixels differing.
    #[arg(long, value_name = "FILE")]
    csv: Option<PathBuf>,
    /// The roster `barylab assign` wrote: each student's image is compared with their own
    /// variant (instead of SCENE...).
    #[arg(long, value_name = "FILE", conflicts_with = "scenes")]
    roster: Option<PathBuf>,
    /// 8-bit levels a channel may differ by and still agree.
    #[arg(long, default_value_t = barylab::compare::DEFAULT_TOLERANCE)]
    tolerance: u8,
    /// Language of the report: en, zh (zh-CN), or auto.
    #[arg(long, default_value = "en", value_parser = parse_lang)]
    lang: barylab::i18n::Lang,
}

#[derive(clap::Args, Debug)]
struct AssignArgs {
    /// The roster: CSV with the student's id in the first column.
    #[arg(long, value_name = "FILE")]
    students: PathBuf,
    /// The number that picks the variants: the same roster and number give the same
    /// variants.
    #[arg(long, alias = "seed", value_name = "N")]
    number: u64,
    /// A new (or empty) folder for the variants: one folder per student and roster.csv.
    #[arg(long, value_name = "DIR")]
    out: PathBuf,
    /// The base scene (world form: a camera and a quad); default: the built-in scene.
    #[arg(long, value_name = "BASE")]
    scene: Option<PathBuf>,
}

/// Parses a colour: black, white, #rrggbb or R,G,B.
fn parse_color(s: &str) -> Result<[u8; 3], String> {
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
struct GpuCheckArgs {
    /// Scene files (JSON), OBJ models or images, as for `render`.
    #[arg(required = true)]
    scenes: Vec<PathBuf>,
    /// Interpolation mode (default: each scene's).
    #[arg(long)]
    mode: Option<ModeArg>,
    /// Texture filter (default: each scene's; trilinear is compared as bilinear).
    #[arg(long)]
    filter: Option<FilterArg>,
    /// Image size as WIDTHxHEIGHT (default: each scene's).
    #[arg(long, value_parser = parse_size, allow_hyphen_values = true)]
    size: Option<(u32, u32)>,
    /// Use Mesa's software rasterizer (llvmpipe) instead of the GPU.
    #[arg(long)]
    software: bool,
    #[command(flatten)]
    sampling: SampleOptions,
    /// Print one JSON object instead of text.
    #[arg(long)]
    json: bool,
    /// Language of the report: en, zh (zh-CN), or auto (the system locale: LC_ALL,
    /// LC_MESSAGES, LANG). JSON stays the same in every language.
    #[arg(long, default_value = "en", value_parser = parse_lang)]
    lang: barylab::i18n::Lang,
}

#[derive(clap::Args, Debug)]
struct RenderArgs {
    #[command(flatten)]
    input: SceneOptions,
    /// Output PNG file.
    #[arg(short, long)]
    output: PathBuf,
    /// Also write float32 OpenEXR buffers into this folder: uv.exr, weights_screen.exr,
    /// weights_perspective.exr, depth.exr, inv_w.exr.
    #[arg(long, value_name = "DIR")]
    aov: Option<PathBuf>,
    /// Which rasterizer visits the pixels: per-pixel edge functions, or the classic scanline
    /// with per-pixel stepping (same pixels, same values).
    #[arg(long, default_value = "edge")]
    rasterizer: RasterizerArg,
    /// Worker threads (default: one per core).
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=256))]
    threads: Option<u16>,
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
enum RasterizerArg {
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
struct FigureArgs {
    #[command(flatten)]
    input: SceneOptions,
    /// Mark (pin) this pixel as X,Y: its marker, its triangle and the sub-triangles of its
    /// weights.
    #[arg(long, value_parser = parse_pixel, allow_hyphen_values = true)]
    pixel: Option<(u32, u32)>,
    /// Also mark this pixel as hovered (marker with crosshair), as X,Y.
    #[arg(long, value_parser = parse_pixel, allow_hyphen_values = true)]
    hover: Option<(u32, u32)>,
    /// Compare the modes: one view (default), side by side, a wipe line, or the difference
    /// heatmap.
    #[arg(long, default_value = "single")]
    compare: CompareArg,
    /// Wipe line position as a fraction of the width (with --compare wipe).
    #[arg(long, default_value_t = 0.5, value_parser = parse_fraction)]
    wipe: f32,
    /// PNG pixels per figure point: 1, 2 or 4 (the scene is rendered again at that
    /// resolution when the pixel size is 1).
    #[arg(long, default_value_t = 1, value_parser = parse_scale)]
    scale: u32,
    /// Figure points per rendered pixel, as the app's pixel size (the grid shows from 6, the
    /// sample dots from 10).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=32))]
    pixel_size: u32,
    /// Language of the labels: en, zh (zh-CN), or auto (the system locale). Chinese labels
    /// need a CJK font (Noto Sans CJK SC, Source Han Sans SC, WenQuanYi, ...); without one
    /// they stay English.
    #[arg(long, default_value = "en", value_parser = parse_lang)]
    lang: barylab::i18n::Lang,
    /// Background around the image (title strip, margins).
    #[arg(long, default_value = "transparent")]
    background: BackgroundArg,
    /// Figure points per overlay point: labels, lines, handles and margins this much larger,
    /// as in the app at that text size (the app's Export uses its screen's pixels per point).
    #[arg(long, default_value_t = 1.0, value_parser = parse_overlay_scale)]
    overlay_scale: f32,
    /// Leave out the pixel grid.
    #[arg(long)]
    no_grid: bool,
    /// Leave out the vertex handles and their w labels.
    #[arg(long)]
    no_handles: bool,
    /// Leave out the sub-triangles of the marked pixel.
    #[arg(long)]
    no_sub_areas: bool,
    /// Add a caption below the figure with the pinned (else hovered) pixel's key numbers:
    /// the screen weights r s t, the corrected weights a b c, W_P, and uv affine and
    /// perspective-correct, as its derivation gives them.
    #[arg(long)]
    caption: bool,
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
    view: FigureViewArg,
    /// With --view samples: the sample index whose colour and depth are shown (0 to N-1).
    #[arg(long, default_value_t = 0)]
    sample_index: u32,
    /// With --view samples: the buffers with GAMES101 A2's black-edge bug (colour kept per
    /// pixel while coverage is per sample).
    #[arg(long)]
    black_edges: bool,
    #[command(flatten)]
    orbit: space::OrbitArgs,
    /// Output file: .png or .svg.
    #[arg(short, long)]
    output: PathBuf,
}

/// What `barylab figure` draws.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
enum FigureViewArg {
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
enum CompareArg {
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
enum BackgroundArg {
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
fn parse_fraction(s: &str) -> Result<f32, String> {
    match s.trim().parse::<f32>() {
        Ok(v) if (0.0..=1.0).contains(&v) => Ok(v),
        _ => Err(format!("`{s}` is not a fraction from 0 to 1")),
    }
}

/// Parses an overlay scale within [`barylab::figure::OVERLAY_SCALE_RANGE`].
fn parse_overlay_scale(s: &str) -> Result<f32, String> {
    let (lo, hi) = barylab::figure::OVERLAY_SCALE_RANGE;
    match s.trim().parse::<f32>() {
        Ok(v) if (lo..=hi).contains(&v) => Ok(v),
        _ => Err(format!(
            "overlay scale `{s}` is not a number from {lo} to {hi}"
        )),
    }
}

/// Parses a figure scale: 1, 2 or 4.
fn parse_scale(s: &str) -> Result<u32, String> {
    match s.trim().parse::<u32>() {
        Ok(v) if barylab::figure::SCALES.contains(&v) => Ok(v),
        _ => Err(format!("scale `{s}` is not 1, 2 or 4")),
    }
}

#[derive(clap::Args, Debug)]
struct BenchArgs {
    /// Scene (default: assets/scenes/bench-1080p.json if present, else the built-in default).
    scene: Option<PathBuf>,
    /// Image size as WIDTHxHEIGHT (default: the scene's).
    #[arg(long, value_parser = parse_size, allow_hyphen_values = true)]
    size: Option<(u32, u32)>,
    /// Frames rendered per configuration; the median is reported.
    #[arg(long, default_value_t = 9, value_parser = clap::value_parser!(u32).range(1..=10000))]
    frames: u32,
    /// Print a JSON array of records instead of a table.
    #[arg(long)]
    json: bool,
    /// What each frame draws, as the app's compare modes: one image, both modes (side by side
    /// or wiped), or both with the difference heatmap.
    #[arg(long, value_enum, default_value = "single")]
    view: barylab::bench::View,
    /// Time only this rasterizer (default: both).
    #[arg(long, value_enum)]
    rasterizer: Option<RasterizerArg>,
    /// Time only this filter (default: nearest and bilinear).
    #[arg(long, value_enum)]
    filter: Option<FilterArg>,
    /// Time only this interpolation mode (default: both).
    #[arg(long, value_enum)]
    mode: Option<ModeArg>,
    /// Time only this many worker threads (default: 1 and the number of cores).
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=256))]
    threads: Option<u16>,
    /// The highest instruction set the lanes may use (default: the best the CPU has). Every
    /// level draws the same pixels.
    #[arg(long, value_enum)]
    vector: Option<VectorArg>,
    #[command(flatten)]
    sampling: SampleOptions,
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
enum VectorArg {
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
struct ProbeArgs {
    #[command(flatten)]
    input: SceneOptions,
    /// The pixel as X,Y: column from the left, row from the top, both from 0.
    #[arg(long, value_parser = parse_pixel, allow_hyphen_values = true)]
    pixel: (u32, u32),
    /// Output format: a worked example as text, Markdown or a LaTeX fragment, or JSON.
    #[arg(long, default_value = "text")]
    format: FormatArg,
    /// Language of the derivation's prose: en, zh (zh-CN), or auto (the system locale:
    /// LC_ALL, LC_MESSAGES, LANG). Formulas are the same in every language; LaTeX stays English.
    #[arg(long, default_value = "en", value_parser = parse_lang)]
    lang: barylab::i18n::Lang,
    /// The derivatives the level-of-detail derivation uses (trilinear filtering): coarse (one
    /// pair per 2x2 quad, as the renderer and GPUs) or fine (the pixel's own row and column).
    #[arg(long, default_value = "coarse", value_parser = parse_named::<barylab::raster::interpolate::Derivatives>, value_name = "KIND")]
    derivatives: barylab::raster::interpolate::Derivatives,
}

/// `--lang`: a language tag, or `auto` for the system locale.
fn parse_lang(s: &str) -> Result<barylab::i18n::Lang, String> {
    if s.eq_ignore_ascii_case("auto") {
        Ok(barylab::i18n::Lang::detect())
    } else {
        s.parse()
    }
}

/// What to draw and how: shared by `render` and `probe`, so a probe describes exactly what
/// `render` draws with the same options.
#[derive(clap::Args, Debug)]
struct SceneOptions {
    /// Scene file (JSON; see docs/scene-format.md), or an OBJ model, or an image (PNG, JPEG,
    /// BMP, TGA, WebP) shown on the default quad.
    scene: PathBuf,
    /// Interpolation mode (default: the scene's).
    #[arg(long)]
    mode: Option<ModeArg>,
    /// Image size as WIDTHxHEIGHT, e.g. 800x600 (default: the scene's).
    #[arg(long, value_parser = parse_size, allow_hyphen_values = true)]
    size: Option<(u32, u32)>,
    /// Texture filter (default: the scene's); trilinear uses mipmaps.
    #[arg(long)]
    filter: Option<FilterArg>,
    /// The largest anisotropy of trilinear filtering: 1 (off) to 16 (default: the scene's,
    /// else 1).
    #[arg(long, value_parser = parse_anisotropy, value_name = "N")]
    anisotropy: Option<barylab::raster::texture::MaxAnisotropy>,
    /// What the colour shows (default: the scene's).
    #[arg(long)]
    shading: Option<ShadingArg>,
    /// Overlay the triangles' edges (threshold on the smallest weight).
    #[arg(long)]
    wireframe: bool,
    /// Which triangle owns a pixel centre exactly on a shared edge: llvmpipe's rule (left and
    /// bottom edges in image rows, as OpenGL on Mesa) or the top-left rule of Direct3D (and most
    /// Vulkan drivers) (default: the scene's, else llvmpipe).
    #[arg(long, value_name = "RULE")]
    tie_rule: Option<TieRuleArg>,
    #[command(flatten)]
    sampling: SampleOptions,
}

/// The samples and qualifiers: shared by render, probe, figure, compare, bench and gpu-check.
#[derive(clap::Args, Debug, Default, Clone, Copy)]
struct SampleOptions {
    /// Samples per pixel: 1, 4, 8 or 16 (default: the scene's, else 1).
    #[arg(long, value_parser = parse_samples, value_name = "N")]
    samples: Option<SampleCount>,
    /// Where the samples lie: standard (the GL's positions) or grid (GAMES101's 2x2, or 4x4)
    /// (default: the scene's, else standard).
    #[arg(long, value_parser = parse_named::<SamplePattern>, value_name = "PATTERN")]
    sample_pattern: Option<SamplePattern>,
    /// msaa (one shading per pixel and triangle) or ssaa (every sample shaded) (default: the
    /// scene's, else msaa).
    #[arg(long, value_parser = parse_named::<ShadingRate>, value_name = "RATE")]
    shading_rate: Option<ShadingRate>,
    /// Where MSAA evaluates values: center, centroid or sample (default: the scene's, else
    /// center).
    #[arg(long, value_parser = parse_named::<Location>, value_name = "LOCATION")]
    location: Option<Location>,
    /// Every attribute flat: the provoking vertex's value.
    #[arg(long)]
    flat: bool,
    /// The provoking vertex of --flat: last (OpenGL's default) or first (default: the
    /// scene's, else last).
    #[arg(long, value_parser = parse_named::<ProvokingVertex>, value_name = "VERTEX")]
    provoking_vertex: Option<ProvokingVertex>,
}

impl SceneOptions {
    /// The scene's samples with these options applied.
    fn samples(&self, scene: &SampleSettings) -> SampleSettings {
        self.sampling.apply(scene)
    }
}

impl SampleOptions {
    /// The options as changes to a scene's samples.
    fn overrides(&self) -> SampleOverride {
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
    fn apply(&self, scene: &SampleSettings) -> SampleSettings {
        self.overrides().apply(scene)
    }
}

/// Parses the arguments; usage errors are reported on one line (clap's first line).
fn parse_args() -> Result<Cli, ExitCode> {
    Cli::try_parse().map_err(|e| {
        use clap::error::ErrorKind;
        if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion)
            || e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
        {
            return match print(&e.render().to_string()) {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => output::report(&e),
            };
        }
        // Clap's message is the paragraph before the first blank line; join it into one line.
        let text = e.render().to_string();
        let first: Vec<&str> = text
            .lines()
            .take_while(|l| !l.trim().is_empty())
            .map(str::trim)
            .collect();
        note!("{}", output::one_line(&first.join(" ")));
        ExitCode::from(2)
    })
}

pub fn main() -> ExitCode {
    // First, before any thread starts: an interrupted run removes its temporary files.
    if let Err(e) = barylab::files::remove_temps_on_signals() {
        note!("warning: cannot catch Ctrl+C to remove temporary files: {e}");
    }
    let cli = match parse_args() {
        Ok(cli) => cli,
        Err(code) => return code,
    };
    if cli.command.is_some()
        && let Err(e) = output::stdout_open()
    {
        return output::report(&e);
    }
    // No output of a command replaces a file it read (the interactive app saves scenes over
    // the files they came from, as Save does; its screenshot run is a command).
    if cli.command.is_some() || cli.screenshot.is_some() {
        barylab::files::guard_inputs();
    }
    if let Some(bytes) = cli.memory_limit {
        barylab::budget::set_limit(bytes);
    }
    // Long work shows a progress line on a terminal's standard error.
    let progress = match &cli.command {
        Some(Command::Render(_)) => ProgressLine::start("render"),
        Some(Command::Bench(_)) => ProgressLine::start("bench"),
        Some(Command::Figure(_)) => ProgressLine::start("figure"),
        Some(Command::Compare(_)) => ProgressLine::start("compare"),
        Some(Command::Grade(_)) => ProgressLine::start("grade"),
        Some(Command::Lesson(_)) => ProgressLine::start("lesson"),
        Some(Command::Animate(_)) => ProgressLine::start("animate"),
        _ => None,
    };
    let result = match cli.command {
        None => app(&cli),
        Some(Command::Render(args)) => commands::render(&args),
        Some(Command::Probe(args)) => commands::probe(&args),
        Some(Command::Bench(args)) => commands::bench(&args),
        Some(Command::Figure(args)) => commands::figure(&args),
        Some(Command::Compare(args)) => compare::run(&args),
        Some(Command::Grade(args)) => grade::run(&args),
        Some(Command::Assign(args)) => assign::run(&args),
        Some(Command::Lesson(args)) => lesson::run(&args),
        Some(Command::Animate(args)) => animate::run(&args),
        #[cfg(feature = "gpu")]
        Some(Command::GpuCheck(args)) => gpu_check::run(&args),
    };
    drop(progress);
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => output::report(&e),
    }
}

/// The lesson of `--lesson` at `--step` (1-based; the first step without it), 0-based.
fn open_lesson(
    path: &std::path::Path,
    step: Option<usize>,
) -> Result<(barylab::lesson::Lesson, usize)> {
    let lesson = barylab::lesson::Lesson::open(path)?;
    let count = lesson.steps.len();
    let step = step.unwrap_or(1);
    if step == 0 || step > count {
        anyhow::bail!(
            "{}: --step {step}: the lesson has steps 1 to {count}",
            lesson.shown_path()
        );
    }
    Ok((lesson, step - 1))
}

/// Opens the app.
fn app(cli: &Cli) -> Result<()> {
    if let Some(shot) = &cli.screenshot {
        output::check_output(shot, &["png"])?;
    }
    let system_lang = barylab::i18n::Lang::detect();
    let lang = cli.lang.unwrap_or(system_lang);
    // A file that cannot be opened stops a screenshot run (it must show what was asked for);
    // the window starts on the default scene with the message instead, printed here too (a
    // teacher who started the app from a file manager sees it in the window).
    let mut startup_errors: Vec<String> = Vec::new();
    let mut started = |e: anyhow::Error| -> Result<()> {
        if cli.screenshot.is_some() {
            return Err(e);
        }
        note!("error: {}", output::one_line(&format!("{e:#}")));
        startup_errors.push(format!("{e:#}"));
        Ok(())
    };
    let opened = match &cli.scene {
        Some(path) => {
            match barylab::app::services::files::open(path, &Scene::default_scene(), lang) {
                Ok(opened) => {
                    for n in &opened.notes {
                        note!("note: {n}");
                    }
                    Some(opened)
                }
                Err(e) => {
                    started(anyhow::Error::msg(e))?;
                    None
                }
            }
        }
        None => None,
    };
    let lesson = match &cli.lesson {
        Some(path) => match open_lesson(path, cli.step) {
            Ok(lesson) => Some(lesson),
            Err(e) => {
                started(e)?;
                None
            }
        },
        None => None,
    };
    if let Some(path) = &cli.compare_image
        && let Err(e) = barylab::app::panels::compare_image::read_image(path, lang)
    {
        // The window shows it when it reads the image.
        note!("error: {}", output::one_line(&e));
    }
    let options = barylab::app::AppOptions {
        opened,
        scene: None,
        screenshot: cli.screenshot.clone(),
        // A screenshot run is reproducible: it neither reads nor writes saved state.
        persist: !cli.fresh && cli.screenshot.is_none(),
        window_size: cli.window_size.map(|(w, h)| [w as f32, h as f32]),
        present: cli.present,
        pin: cli.pin.map(|(x, y)| [x, y]),
        lang: cli.lang,
        system_lang,
        no_cjk_font: false,
        text_size: cli.text_size,
        lesson,
        startup_error: (!startup_errors.is_empty()).then(|| startup_errors.join("; ")),
        compare: cli.compare,
        space_view: cli.space_view,
        animation_window: cli.animation_window.as_deref().map(|k| {
            if k == "recording" {
                barylab::app::command::AnimationKind::Recording
            } else {
                barylab::app::command::AnimationKind::Sweep
            }
        }),
        compare_image: cli.compare_image.clone(),
        compare_background: cli.compare_background,
        quiz_answers: cli.quiz_answers.as_ref().map(|a| {
            a.split([' ', ';'])
                .filter(|t| !t.is_empty())
                .map(str::to_string)
                .collect()
        }),
    };
    if let Some(shot) = &cli.screenshot {
        // The scene, its texture or model and the lesson were read by now; the image to
        // compare is read by the window.
        output::not_an_input(shot, cli.compare_image.as_slice())?;
    }
    barylab::app::run(options).map_err(|e| anyhow::anyhow!(output::window_error(&e.to_string())))
}
