//! Times Mesa's llvmpipe drawing the same scene as `barylab bench`, and prints the same JSON
//! records (`"rasterizer": "llvmpipe"`), or one Markdown table of barylab and llvmpipe side
//! by side, or how llvmpipe's images compare with barylab's. See docs/performance.md.
//!
//! ```text
//! cargo bench --bench llvmpipe                                  # JSON records, 1 and N threads
//! cargo bench --bench llvmpipe -- --markdown                    # + barylab bench, one table
//! cargo bench --bench llvmpipe -- --conformance                 # image comparison table
//! cargo bench --bench llvmpipe -- SCENE --size 960x540 --frames 30
//! cargo bench --bench llvmpipe -- assets/bench/bench-mesh-75k.json --depth-test --markdown
//! ```
//!
//! llvmpipe reads `LP_NUM_THREADS` when it starts, so each thread count runs in a child
//! process of this program (`--child`) with the variable set.

use barylab::gpu as gl;

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

use barylab::bench::{BenchRecord, filter_name, mode_name};
use barylab::raster::{Filter, Interpolation};
use clap::Parser;

const DEFAULT_SCENE: &str = "assets/scenes/bench-1080p.json";

/// Scenes compared by `--conformance` (the same list as tests/llvmpipe.rs).
const CONFORMANCE_SCENES: [(&str, Option<(u32, u32)>); 6] = [
    ("assets/scenes/bench-1080p.json", Some((480, 270))),
    ("assets/scenes/clip-two-triangles.json", None),
    ("assets/scenes/default.json", None),
    ("assets/scenes/front.json", None),
    ("assets/scenes/corner-behind.json", None),
    ("assets/scenes/vertex-colors.json", None),
];

#[derive(Parser, Debug)]
#[command(about = "llvmpipe reference timings and image comparison for barylab")]
struct Args {
    /// Scene (default: assets/scenes/bench-1080p.json).
    scene: Option<PathBuf>,
    /// Image size as WIDTHxHEIGHT (default: the scene's).
    #[arg(long, value_parser = parse_size)]
    size: Option<(u32, u32)>,
    /// Frames per configuration; the median is reported.
    #[arg(long, default_value_t = 21)]
    frames: u32,
    /// Also run `barylab bench --json` and print one Markdown table side by side.
    #[arg(long)]
    markdown: bool,
    /// Time llvmpipe with the depth test on (less-than, cleared to 1), as barylab always
    /// draws: for meshes whose triangles may overlap. Off by default, as the reference
    /// figures for the quad were measured.
    #[arg(long)]
    depth_test: bool,
    /// Measure everything this many times, barylab and llvmpipe in turn, and keep each
    /// configuration's best median: on a shared machine the load changes from minute to
    /// minute, and interleaved rounds give both renderers the same chances.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..=100))]
    rounds: u32,
    /// With `--markdown`: the lanes' vector levels to time barylab at, each in every round and
    /// in a table of its own (`--vector scalar,portable,avx2,avx512`); default: the best.
    #[arg(long, value_delimiter = ',')]
    vector: Vec<String>,
    /// Compare llvmpipe's images with barylab's on several scenes; print a Markdown table.
    #[arg(long)]
    conformance: bool,
    /// Internal: measure in this process with LP_NUM_THREADS already set.
    #[arg(long, hide = true)]
    child: Option<usize>,
    /// Passed by `cargo bench`; ignored.
    #[arg(long, hide = true)]
    bench: bool,
}

fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let bad = || format!("`{s}` is not a size like 800x600");
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let (w, h): (u32, u32) = (
        w.trim().parse().map_err(|_| bad())?,
        h.trim().parse().map_err(|_| bad())?,
    );
    if w == 0 || h == 0 || w > 8192 || h > 8192 {
        return Err(format!("size {w}x{h} is outside 1..=8192"));
    }
    Ok((w, h))
}

fn main() -> ExitCode {
    let args = Args::parse();
    gl::force_llvmpipe_env();
    let result = if args.conformance {
        conformance()
    } else if let Some(threads) = args.child {
        child(&args, threads)
    } else {
        parent(&args)
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("llvmpipe: {e}");
            ExitCode::FAILURE
        }
    }
}

fn scene_path(args: &Args) -> PathBuf {
    args.scene
        .clone()
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join(DEFAULT_SCENE))
}

/// Measures every filter x mode with the thread count llvmpipe was started with.
fn child(args: &Args, threads: usize) -> Result<(), String> {
    let (scene, _, _) = gl::load(&scene_path(args), args.size)?;
    let mut lp = gl::Gpu::new()?;
    lp.load(&scene)?;
    let mut records = Vec::new();
    for filter in [Filter::Nearest, Filter::Bilinear] {
        for mode in [Interpolation::Affine, Interpolation::Perspective] {
            let ms = lp.time_with(filter, mode, args.frames.max(1), args.depth_test)?;
            records.push(BenchRecord {
                rasterizer: "llvmpipe".into(),
                filter: filter_name(filter).into(),
                mode: mode_name(mode).into(),
                view: barylab::bench::view_name(barylab::bench::View::Single).to_string(),
                threads,
                width: scene.width,
                height: scene.height,
                median_ms: ms,
                mpix_per_s: barylab::bench::mpix_per_s(scene.width, scene.height, ms),
            });
        }
    }
    println!(
        "{}",
        serde_json::to_string(&records).map_err(|e| e.to_string())?
    );
    Ok(())
}

/// Runs a child per thread count (and `barylab bench` for `--markdown`), prints the result.
fn parent(args: &Args) -> Result<(), String> {
    let exe = std::env::current_exe().map_err(|e| format!("cannot find myself: {e}"))?;
    let path = scene_path(args);
    let mut records: Vec<BenchRecord> = Vec::new();
    let mut renderer = String::new();
    {
        // Check once, in this process, that llvmpipe is there (one clear message if not).
        let lp = gl::Gpu::new()?;
        renderer.push_str(lp.renderer());
    }
    // barylab's records per vector level (`None`: the default level).
    let levels: Vec<Option<&str>> = if args.vector.is_empty() {
        vec![None]
    } else {
        args.vector.iter().map(|v| Some(v.as_str())).collect()
    };
    let mut barylab: Vec<Vec<BenchRecord>> = vec![Vec::new(); levels.len()];
    for _ in 0..args.rounds {
        let mut round = Vec::new();
        for threads in barylab::bench::thread_counts(barylab::bench::available_cores()) {
            let mut cmd = Command::new(&exe);
            cmd.arg(&path)
                .arg("--frames")
                .arg(args.frames.to_string())
                .arg("--child")
                .arg(threads.to_string())
                .env("LP_NUM_THREADS", threads.to_string());
            if args.depth_test {
                cmd.arg("--depth-test");
            }
            if let Some((w, h)) = args.size {
                cmd.arg("--size").arg(format!("{w}x{h}"));
            }
            round.extend(run_json(&mut cmd, "llvmpipe child")?);
        }
        keep_best(&mut records, round);
        if args.markdown {
            for (level, best) in levels.iter().zip(barylab.iter_mut()) {
                let mut cmd = Command::new(env!("CARGO_BIN_EXE_barylab"));
                cmd.arg("bench")
                    .arg(&path)
                    .arg("--frames")
                    .arg(args.frames.to_string())
                    .arg("--json");
                if let Some((w, h)) = args.size {
                    cmd.arg("--size").arg(format!("{w}x{h}"));
                }
                if let Some(level) = level {
                    cmd.arg("--vector").arg(level);
                }
                keep_best(best, run_json(&mut cmd, "barylab bench")?);
            }
        }
    }
    if !args.markdown {
        println!(
            "{}",
            serde_json::to_string_pretty(&records).map_err(|e| e.to_string())?
        );
        return Ok(());
    }
    for (level, best) in levels.iter().zip(barylab) {
        if let Some(level) = level {
            println!("Vector level `{level}`:\n");
        }
        let mut all = records.clone();
        all.extend(best);
        print!(
            "{}",
            markdown(&all, &path, &renderer, args.frames, args.rounds)
        );
        println!();
    }
    Ok(())
}

/// Adds a round's records to `best`, keeping the lower median of each configuration.
fn keep_best(best: &mut Vec<BenchRecord>, round: Vec<BenchRecord>) {
    for r in round {
        let same = |b: &&mut BenchRecord| {
            (&b.rasterizer, &b.filter, &b.mode, &b.view, b.threads)
                == (&r.rasterizer, &r.filter, &r.mode, &r.view, r.threads)
        };
        match best.iter_mut().find(same) {
            Some(b) if r.median_ms < b.median_ms => *b = r,
            Some(_) => {}
            None => best.push(r),
        }
    }
}

fn run_json(cmd: &mut Command, what: &str) -> Result<Vec<BenchRecord>, String> {
    let out = cmd
        .output()
        .map_err(|e| format!("cannot run {what}: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "{what} failed: {}",
            String::from_utf8_lossy(&out.stderr).trim()
        ));
    }
    serde_json::from_slice(&out.stdout).map_err(|e| format!("{what} printed no JSON records: {e}"))
}

/// One row per filter x mode x threads: barylab's two rasterizers and llvmpipe, in ms.
fn markdown(
    records: &[BenchRecord],
    scene: &Path,
    renderer: &str,
    frames: u32,
    rounds: u32,
) -> String {
    let size = records
        .first()
        .map(|r| format!("{}x{}", r.width, r.height))
        .unwrap_or_default();
    let mut out = format!(
        "Scene `{}`, {size}, best of {rounds} interleaved rounds of the median of {frames} frames, \
         {renderer}.\n\n\
         | filter | mode | threads | edge ms | scanline ms | llvmpipe ms | edge / llvmpipe | scanline / llvmpipe |\n\
         |---|---|---|---|---|---|---|---|\n",
        scene
            .strip_prefix(env!("CARGO_MANIFEST_DIR"))
            .unwrap_or(scene)
            .display()
            .to_string()
            .trim_start_matches('/')
    );
    let ms = |r: Option<&BenchRecord>| r.map_or("-".to_string(), |r| format!("{:.1}", r.median_ms));
    for filter in ["nearest", "bilinear"] {
        for mode in ["affine", "perspective"] {
            for threads in barylab::bench::thread_counts(barylab::bench::available_cores()) {
                let find = |name| barylab::bench::find(records, name, filter, mode, threads);
                let ratio = |name| match (find(name), find("llvmpipe")) {
                    (Some(e), Some(l)) if l.median_ms > 0.0 => {
                        format!("{:.2}x", e.median_ms / l.median_ms)
                    }
                    _ => "-".into(),
                };
                let (edge_ratio, scan_ratio) = (ratio("edge"), ratio("scanline"));
                out.push_str(&format!(
                    "| {filter} | {mode} | {threads} | {} | {} | {} | {edge_ratio} | {scan_ratio} |\n",
                    ms(find("edge")),
                    ms(find("scanline")),
                    ms(find("llvmpipe")),
                ));
            }
        }
    }
    out
}

/// Renders each conformance scene with both and prints how they compare.
fn conformance() -> Result<(), String> {
    let mut lp = gl::Gpu::new()?;
    println!("Compared with {}.\n", lp.renderer());
    println!(
        "| scene | size | output | filter | mode | coverage mismatches | triangle mismatches | pixels differing | max channel diff | nearest: max texels from a texel edge |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for (name, size) in CONFORMANCE_SCENES {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(name);
        for c in gl::compare_scene(&mut lp, &path, size)? {
            println!(
                "| {name} | {}x{} | {:?} | {} | {} | {} | {} | {} of {} | {} | {} |",
                c.width,
                c.height,
                c.output,
                filter_name(c.filter),
                mode_name(c.mode),
                c.result.coverage_mismatch.len(),
                c.result.triangle_mismatch.len(),
                c.result.color_differing,
                c.result.pixels,
                c.result.max_channel_diff,
                if c.output == gl::Output::Texture && c.filter == Filter::Nearest {
                    format!("{:.2e}", c.result.max_boundary_distance)
                } else {
                    "-".into()
                }
            );
        }
    }
    println!("\nInterpolated values, barylab against llvmpipe, over the pixels both cover:\n");
    println!(
        "| scene | size | mode | pixels | max uv difference | max depth difference | max 1/w difference (relative) |"
    );
    println!("|---|---|---|---|---|---|---|");
    for (name, size) in CONFORMANCE_SCENES {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(name);
        let (_, scene, texture) = gl::load(&path, size)?;
        let s = scene.settings();
        for c in gl::compare_values(&mut lp, &scene.to_mesh(), &texture, &s)? {
            println!(
                "| {name} | {}x{} | {} | {} | {:.1e} | {:.1e} | {:.1e} |",
                s.width,
                s.height,
                mode_name(c.mode),
                c.pixels,
                c.uv,
                c.depth,
                c.inv_w_relative
            );
        }
    }
    Ok(())
}
