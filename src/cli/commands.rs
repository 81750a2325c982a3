//! The headless commands: `render`, `probe`, `figure` and `bench`.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context, Result};
use barylab::raster;
use barylab::scene::Scene;

use super::{BenchArgs, FigureArgs, ProbeArgs, RenderArgs, SceneOptions};
use crate::output::{self, note, print};

/// A thread pool of `n` workers (or rayon's default when `None`).
fn pool(threads: Option<u16>) -> Result<rayon::ThreadPool> {
    let mut b = rayon::ThreadPoolBuilder::new();
    if let Some(n) = threads {
        b = b.num_threads(usize::from(n));
    }
    b.build().context("cannot start worker threads")
}

/// Loads the input, its texture (printing any notes) and the settings with the options applied.
pub(super) fn prepare(
    o: &SceneOptions,
) -> Result<(Scene, raster::Texture, raster::RenderSettings)> {
    let (mut scene, base_dir) = load_input(&o.scene)?;
    if let Some((w, h)) = o.size {
        scene.set_size(w, h);
    }
    if let Some(rule) = o.tie_rule {
        scene.set_tie_rule(rule.into());
    }
    let samples = o.samples(&scene.samples());
    samples.check().map_err(anyhow::Error::msg)?;
    scene.set_samples(samples);
    // What drawing it takes (the probe and the figure set up every triangle too), before the
    // texture is read.
    let (w, h) = scene.size();
    let (vertices, triangles) = scene.mesh_size();
    barylab::raster::footprint::check_render_samples(
        (w, h),
        raster::Buffers::All,
        &samples,
        vertices,
        triangles,
    )?;
    let (texture, texture_notes) = scene.load_texture_noted(&base_dir)?;
    let mut settings = scene.settings();
    if let Some(m) = o.mode {
        settings.mode = m.into();
    }
    if let Some(f) = o.filter {
        settings.filter = f.into();
    }
    if let Some(a) = o.anisotropy {
        settings.max_anisotropy = a;
    }
    if let Some(s) = o.shading {
        settings.shading = s.into();
    }
    settings.wireframe |= o.wireframe;
    for note in scene
        .notes_for(settings.shading)
        .iter()
        .chain(&texture_notes)
    {
        note!("note: {note}");
    }
    Ok((scene, texture, settings))
}

/// Prints one note per reason for triangles that were not drawn, naming the first few.
fn report_skipped(triangles: &[raster::render::PreparedTriangle]) {
    use raster::render::TriangleStatus as S;
    const LISTED: usize = 8;
    for status in [S::BadIndex, S::NotFinite, S::ClippedAway, S::Empty] {
        let ids: Vec<String> = triangles
            .iter()
            .filter(|t| t.status == status)
            .map(|t| t.source.to_string())
            .collect();
        if ids.is_empty() {
            continue;
        }
        let more = if ids.len() > LISTED { ", ..." } else { "" };
        let shown = ids[..ids.len().min(LISTED)].join(", ");
        let noun = if ids.len() == 1 {
            "triangle"
        } else {
            "triangles"
        };
        note!(
            "note: {} {noun} not drawn ({shown}{more}): {}",
            ids.len(),
            status.describe()
        );
    }
}

pub(super) fn bench(args: &BenchArgs) -> Result<()> {
    let default_path = Path::new("assets/scenes/bench-1080p.json");
    let (mut scene, base_dir) = match &args.scene {
        Some(p) => load_input(p)?,
        None if default_path.exists() => load_input(default_path)?,
        None => (Scene::default_scene(), PathBuf::new()),
    };
    if let Some((w, h)) = args.size {
        scene.set_size(w, h);
    }
    let texture = scene.load_texture(&base_dir)?;
    let mesh = scene.to_mesh();
    let mut base = scene.settings();
    base.samples = args.sampling.apply(&base.samples);
    if let Some(v) = args.vector {
        barylab::raster::lanes::set_vector_level(v.into());
    }
    // The matrix, narrowed to what the options name (any filter, trilinear too, replaces
    // the matrix's two).
    let wanted = |c: &barylab::bench::BenchConfig| {
        args.rasterizer.is_none_or(|r| c.rasterizer == r.into())
            && args.mode.is_none_or(|m| c.mode == m.into())
            && args.threads.is_none_or(|t| c.threads == usize::from(t))
            && (args.filter.is_none() || c.filter == barylab::Filter::Nearest)
    };
    let cores = match args.threads {
        Some(t) => usize::from(t),
        None => barylab::bench::available_cores(),
    };
    let records = barylab::bench::matrix(cores)
        .into_iter()
        .filter(wanted)
        .map(|mut c| {
            if let Some(f) = args.filter {
                c.filter = f.into();
            }
            c
        })
        .map(|config| {
            barylab::bench::run_view(&mesh, &texture, &base, config, args.frames, args.view)
        })
        .collect::<Result<Vec<_>, _>>()?;
    if args.json {
        print(&format!("{}\n", serde_json::to_string_pretty(&records)?))
    } else {
        print(&barylab::bench::text_table(&records))
    }
}

/// Loads what the user named: a scene file, an OBJ model or an image
/// ([`barylab::scene::open_input`], shared with the app).
fn load_input(path: &Path) -> Result<(Scene, PathBuf)> {
    Ok(barylab::scene::open_input(path)?)
}

pub(super) fn render(args: &RenderArgs) -> Result<()> {
    // Every output is checked before the (possibly long) render.
    output::check_output(&args.output, &["png"])?;
    if let Some(dir) = &args.aov {
        barylab::aov::check_folder(dir)?;
    }
    let (scene, texture, mut settings) = prepare(&args.input)?;
    output::not_an_input(&args.output, &inputs(&args.input.scene, &scene))?;
    settings.rasterizer = args.rasterizer.into();
    let mesh = scene.to_mesh();
    let shown = barylab::files::shown(&args.input.scene);
    super::work::check(&shown, &mesh, settings.width, settings.height)?;
    let workers = pool(args.threads)?;
    let start = Instant::now();
    let out = workers.install(|| raster::render(&mesh, &texture, &settings))?;
    let ms = start.elapsed().as_secs_f64() * 1e3;
    // All files are written beside their places first and moved in together: a failure
    // leaves every earlier file as it was.
    let image = out.frame.to_image()?;
    let png = barylab::files::stage(&args.output, |w| {
        image
            .write_to(w, image::ImageFormat::Png)
            .map_err(std::io::Error::other)
    })?;
    let aovs = match &args.aov {
        Some(dir) => barylab::aov::stage_aovs(dir, &out.frame, settings.mode)?,
        None => Vec::new(),
    };
    for file in aovs {
        file.commit()?;
    }
    png.commit()?;
    report_skipped(&out.triangles);
    let drawn = out
        .triangles
        .iter()
        .filter(|t| t.status == raster::render::TriangleStatus::Drawn)
        .count();
    print(&format!(
        "rendered {}x{} ({:?}, {} of {} triangles drawn) in {:.2} ms -> {}\n",
        settings.width,
        settings.height,
        settings.mode,
        drawn,
        out.triangles.len(),
        ms,
        barylab::files::shown(&args.output)
    ))
}

/// Every file a command reads: the one named and those the scene reads.
pub(super) fn inputs(named: &Path, scene: &Scene) -> Vec<PathBuf> {
    let base_dir = match barylab::scene::InputKind::of(named) {
        Some(barylab::scene::InputKind::Scene) => named.parent().map(Path::to_path_buf),
        _ => None,
    };
    let mut files = scene.input_files(&base_dir.unwrap_or_default());
    files.push(named.to_path_buf());
    files
}

/// Refuses a pixel option (`--pixel`, `--hover`) outside the image, naming the option and the
/// scene file.
pub(super) fn inside(
    option: &str,
    pixel: Option<(u32, u32)>,
    o: &SceneOptions,
    scene: &Scene,
) -> Result<()> {
    let (w, h) = scene.size();
    match pixel {
        Some((x, y)) if x >= w || y >= h => anyhow::bail!(
            "{}: {option} {x},{y}: pixel ({x}, {y}) is outside the {w}x{h} image \
             (x must be 0..={}, y 0..={})",
            barylab::files::shown(&o.scene),
            w - 1,
            h - 1
        ),
        _ => Ok(()),
    }
}

pub(super) fn probe(args: &ProbeArgs) -> Result<()> {
    let (scene, texture, settings) = prepare(&args.input)?;
    inside("--pixel", Some(args.pixel), &args.input, &scene)?;
    let (x, y) = args.pixel;
    let trace = barylab::probe::Prober::new(&scene, &texture, &settings)
        .and_then(|mut p| {
            p.set_derivatives(args.derivatives);
            p.pixel(x, y)
        })
        .with_context(|| barylab::files::shown(&args.input.scene))?;
    let format = args.format.into();
    if format == barylab::probe::format::Format::Latex && args.lang != barylab::i18n::Lang::En {
        eprintln!(
            "note: the LaTeX fragment stays English (it compiles with plain pdflatex); for Chinese \
             use --format markdown, or see docs/probe.md for ctex/xeCJK"
        );
    }
    print(&barylab::probe::format::write_in(&trace, format, args.lang))
}

/// A figure draws the scene as it is: the render options (`--mode`, `--shading`, `--filter`,
/// `--wireframe`) become the scene's own.
pub(super) fn own_options(scene: &mut Scene, settings: &raster::RenderSettings) {
    barylab::edit::set_options(
        scene,
        barylab::edit::SceneOptions {
            mode: settings.mode,
            shading: settings.shading,
            filter: settings.filter,
            wireframe: settings.wireframe,
        },
    );
}

pub(super) fn figure(args: &FigureArgs) -> Result<()> {
    use barylab::figure::{Figure, FigureOptions, png, svg};
    output::check_output(&args.output, &["png", "svg"])?;
    let svg_out = args
        .output
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
    let (mut scene, texture, settings) = prepare(&args.input)?;
    output::not_an_input(&args.output, &inputs(&args.input.scene, &scene))?;
    inside("--pixel", args.pixel, &args.input, &scene)?;
    inside("--hover", args.hover, &args.input, &scene)?;
    let (w, h) = scene.size();
    super::work::check(
        &barylab::files::shown(&args.input.scene),
        &scene.to_mesh(),
        w,
        h,
    )?;
    own_options(&mut scene, &settings);
    let options = FigureOptions {
        compare: args.compare.into(),
        pixel_size: args.pixel_size,
        wipe: args.wipe,
        show_grid: !args.no_grid,
        show_handles: !args.no_handles,
        show_sub_areas: !args.no_sub_areas,
        pinned: args.pixel.map(|(x, y)| [x, y]),
        hovered: args.hover.map(|(x, y)| [x, y]),
        scale: args.scale,
        background: args.background.into(),
        overlay_scale: args.overlay_scale,
        caption: args.caption,
    };
    let mut lang = args.lang;
    if lang != barylab::i18n::Lang::En && barylab::i18n::cjk_font().is_none() {
        eprintln!(
            "warning: no font with Chinese glyphs found (looked for {}); the figure's labels \
             are in English",
            barylab::i18n::CJK_FAMILIES.join(", ")
        );
        lang = barylab::i18n::Lang::En;
    }
    scene.set_max_anisotropy(settings.max_anisotropy);
    use super::FigureViewArg as V;
    if matches!(args.view, V::Space | V::Depth | V::Tetra) {
        return super::space::figure(args, &scene, &texture, &settings, lang, svg_out);
    }
    if args.view == V::Samples {
        return super::samples_figure::write(args, &scene, &texture, &settings, lang);
    }
    if args.view != V::Image {
        return super::texture_figure::write(args, &scene, &texture, &settings, lang);
    }
    let fig = Figure::compose_in(&scene, &texture, &options, lang)
        .with_context(|| barylab::files::shown(&args.input.scene))?;
    let bytes = if svg_out {
        svg::to_svg(&fig)?.into_bytes()
    } else {
        png::to_png(&fig)?
    };
    barylab::files::write_bytes(&args.output, &bytes)?;
    let [w, h] = fig.pixel_dimensions();
    print(&format!(
        "figure {w}x{h} -> {}\n",
        barylab::files::shown(&args.output)
    ))
}
