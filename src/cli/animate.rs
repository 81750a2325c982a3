//! `barylab animate`: a sweep of a scene as an animation (GIF, APNG, WebP, MP4), every frame
//! drawn as `barylab figure` draws it.

use std::path::PathBuf;
use std::time::Instant;

use anyhow::{Context, Result, bail};
use barylab::animate::{self, Animation, Format, Sweep};
use barylab::files::shown;

use super::values::*;
use super::{BackgroundArg, SceneOptions, parse_lang, parse_overlay_scale, parse_scale};
use crate::output::{self, print};

/// Parses a sweep by its name.
fn parse_sweep(s: &str) -> Result<Sweep, String> {
    Sweep::from_name(s.trim()).ok_or_else(|| {
        let names: Vec<&str> = Sweep::ALL.iter().map(|k| k.name()).collect();
        format!("`{s}` is not a sweep: one of {}", names.join(", "))
    })
}

/// Parses frames per second: 1 to 100.
fn parse_fps(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(v) if (1.0..=100.0).contains(&v) => Ok(v),
        _ => Err(format!("`{s}` is not a frame rate from 1 to 100")),
    }
}

/// Parses a vertex by its name (A, B, C, ...) or index from 0.
fn parse_vertex(s: &str) -> Result<usize, String> {
    let t = s.trim();
    if let Ok(i) = t.parse::<usize>() {
        return Ok(i);
    }
    animate::vertex_by_name(t)
        .ok_or_else(|| format!("`{s}` is not a vertex: a name A, B, C, ... or an index from 0"))
}

#[derive(clap::Args, Debug)]
pub(super) struct AnimateArgs {
    #[command(flatten)]
    input: SceneOptions,
    /// What moves: affine-perspective (the wipe from affine to perspective-correct), depth (a
    /// corner pushed away, w 1x to 8x), tilt (the quad tilting 60 degrees), row (the pinned
    /// pixel walking its row, weights and uv in the caption), fill-edge and fill-scanline (each
    /// rasterizer filling the triangles in its order), clip (a corner crossing the near plane).
    #[arg(long, value_name = "KIND", value_parser = parse_sweep)]
    sweep: Sweep,
    /// Frames, 2 to 1000.
    #[arg(long, default_value_t = 48, value_parser = clap::value_parser!(u32).range(2..=1000))]
    frames: u32,
    /// Frames per second, 1 to 100 (a GIF plays in hundredths of a second: 25 or 50 exactly).
    #[arg(long, default_value_t = 25.0, value_parser = parse_fps)]
    fps: f64,
    /// The corner the depth and clip sweeps move: A, B, C, ... (default C).
    #[arg(long, default_value = "C", value_parser = parse_vertex)]
    vertex: usize,
    /// Pin this pixel as X,Y (its marker and sub-triangles); the row sweep walks its row.
    #[arg(long, value_parser = parse_pixel, allow_hyphen_values = true)]
    pixel: Option<(u32, u32)>,
    /// PNG pixels per figure point: 1, 2 or 4.
    #[arg(long, default_value_t = 1, value_parser = parse_scale)]
    scale: u32,
    /// Figure points per rendered pixel (the fill sweeps read best from 8 on, with a small
    /// --size such as 40x30).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=32))]
    pixel_size: u32,
    /// Language of the labels: en, zh (zh-CN), or auto.
    #[arg(long, default_value = "en", value_parser = parse_lang)]
    lang: barylab::i18n::Lang,
    /// Background around and (white) behind the image.
    #[arg(long, default_value = "white")]
    background: BackgroundArg,
    /// Figure points per overlay point (labels, lines, handles larger).
    #[arg(long, default_value_t = 1.0, value_parser = parse_overlay_scale)]
    overlay_scale: f32,
    /// A caption with the pinned pixel's numbers (always on for the row sweep).
    #[arg(long)]
    caption: bool,
    /// Leave out the pixel grid.
    #[arg(long)]
    no_grid: bool,
    /// Leave out the vertex handles and their w labels.
    #[arg(long)]
    no_handles: bool,
    /// Output file: .gif, .apng (or .png), .webp or .mp4 (needs ffmpeg).
    #[arg(short, long)]
    output: PathBuf,
}

/// Runs `barylab animate`.
pub(super) fn run(args: &AnimateArgs) -> Result<()> {
    use barylab::figure::FigureOptions;
    output::check_output(&args.output, &animate::encode::EXTENSIONS)?;
    let format = Format::of(&args.output).context("unknown output format")?;
    if format == Format::Mp4 && !animate::encode::has_ffmpeg() {
        bail!(
            "{}: {}",
            shown(&args.output),
            animate::AnimateError::NoFfmpeg
        );
    }
    let (mut scene, texture, settings) = super::commands::prepare(&args.input)?;
    output::not_an_input(
        &args.output,
        &super::commands::inputs(&args.input.scene, &scene),
    )?;
    super::commands::inside("--pixel", args.pixel, &args.input, &scene)?;
    super::commands::own_options(&mut scene, &settings);
    scene.set_max_anisotropy(settings.max_anisotropy);
    let lang = super::lesson::check_font(args.lang, true);
    let sweep = args.sweep;
    let anim = Animation {
        sweep,
        frames: args.frames,
        vertex: args.vertex,
        options: FigureOptions {
            pixel_size: args.pixel_size,
            show_grid: !args.no_grid,
            show_handles: !args.no_handles,
            pinned: args.pixel.map(|(x, y)| [x, y]),
            scale: args.scale,
            background: args.background.into(),
            overlay_scale: args.overlay_scale,
            caption: args.caption,
            ..FigureOptions::default()
        },
    };
    let shown_scene = shown(&args.input.scene);
    let start = Instant::now();
    let frames = animate::render_frames(&scene, &texture, &anim, lang)
        .with_context(|| format!("{shown_scene}: --sweep {}", sweep.name()))?;
    let rendered = start.elapsed().as_secs_f64();
    let bytes = animate::encode(&frames, args.fps, format)
        .with_context(|| format!("{}: {}", shown(&args.output), format.name()))?;
    let total = start.elapsed().as_secs_f64();
    barylab::files::write_bytes(&args.output, &bytes)?;
    let (w, h) = frames[0].dimensions();
    print(&format!(
        "{} {}: {} frames {w}x{h} at {} fps, {} in {:.2} s ({:.2} s rendering) -> {}\n",
        format.name(),
        sweep.name(),
        frames.len(),
        args.fps,
        barylab::files::bytes(bytes.len() as u64),
        total,
        rendered,
        shown(&args.output)
    ))
}
