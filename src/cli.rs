//! Command-line parsing and the headless commands.

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Result;
use barylab::probe::format::Format;
use barylab::raster::sample::SampleCount;
use barylab::raster::{self, Filter, Interpolation, Shading};
use barylab::scene::Scene;
use clap::{Parser, Subcommand, ValueEnum};

use crate::output::{self, note, print};
use crate::progress_line::ProgressLine;

mod animate;
mod args;
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

use args::*;
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
