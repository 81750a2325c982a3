//! `barylab gpu-check`: barylab beside this computer's OpenGL, scene by scene.

use anyhow::Result;
use barylab::compare::reason::mode_short;
use barylab::compare::verdict::rule_words;
use barylab::gpu::sample_check::{SampleCheck, UvFormula};
use barylab::gpu::{self, Gpu, check};
use barylab::i18n::Lang;
use barylab::raster::Interpolation;
use serde::Serialize;

use super::GpuCheckArgs;
use crate::output::{Differs, print};

/// Everything `--json` prints.
#[derive(Serialize)]
struct Report {
    vendor: String,
    renderer: String,
    version: String,
    /// Which tie rule the GPU's ties follow.
    ties: check::TieCheck,
    scenes: Vec<check::SceneCheck>,
}

pub(super) fn run(args: &GpuCheckArgs) -> Result<()> {
    if args.software {
        gpu::force_llvmpipe_env();
    }
    if std::env::var_os("EGL_LOG_LEVEL").is_none() {
        // SAFETY: the command's only thread so far; set before libEGL is loaded. Mesa's own
        // warnings would otherwise come before our one-line reason.
        unsafe { std::env::set_var("EGL_LOG_LEVEL", "fatal") };
    }
    let mut gl =
        Gpu::open().map_err(|e| anyhow::anyhow!("gpu-check: no OpenGL to compare with: {e}"))?;
    let options = check::CheckOptions {
        mode: args.mode.map(Into::into),
        filter: args.filter.map(Into::into),
        size: args.size,
        samples: args.sampling.overrides(),
    };
    let ties = check::tie_rule(&mut gl).map_err(|e| anyhow::anyhow!("gpu-check: {e}"))?;
    let mut scenes = Vec::new();
    for path in &args.scenes {
        scenes.push(check::check_scene(&mut gl, path, options).map_err(anyhow::Error::msg)?);
    }
    let report = Report {
        vendor: gl.vendor().to_string(),
        renderer: gl.renderer().to_string(),
        version: gl.version().to_string(),
        ties,
        scenes,
    };
    if args.json {
        print(&format!("{}\n", serde_json::to_string_pretty(&report)?))?;
    } else {
        print(&text(&report, args.lang))?;
    }
    let differing: Vec<&str> = report
        .scenes
        .iter()
        .filter(|s| !s.coverage_agrees())
        .map(|s| s.scene.as_str())
        .collect();
    if differing.is_empty() {
        return Ok(());
    }
    Err(Differs(args.lang.tr_with(
        "compare.gpu_check.differs",
        &[
            ("renderer", &report.renderer),
            ("n", &differing.len()),
            ("total", &report.scenes.len()),
            ("list", &differing.join(", ")),
        ],
    ))
    .into())
}

/// The samples section of a scene's report.
fn sample_lines(c: &SampleCheck, lang: Lang) -> Vec<String> {
    let list = |l: &[[u32; 3]], total: usize| {
        if total == 0 {
            return String::new();
        }
        let shown: Vec<String> = l
            .iter()
            .map(|[x, y, k]| format!("({x}, {y}) #{k}"))
            .collect();
        let more = if total > l.len() { ", ..." } else { "" };
        lang.tr_with(
            "compare.gpu_check.at",
            &[("list", &format!("{}{more}", shown.join(", ")))],
        )
    };
    let at = |p: Option<[u32; 3]>| p.map(|a| list(&[a], 1)).unwrap_or_default();
    let mut lines = vec![lang.tr_with(
        "compare.gpu_check.samples",
        &[
            ("n", &c.per_pixel),
            ("covered", &c.covered),
            ("total", &c.samples),
            ("coverage", &c.coverage_mismatches),
            ("cat", &list(&c.coverage_mismatch_at, c.coverage_mismatches)),
            ("triangles", &c.triangle_mismatches),
            ("tat", &list(&c.triangle_mismatch_at, c.triangle_mismatches)),
        ],
    )];
    let max = format!("{:.1e}", c.max_uv_difference);
    lines.push(match c.uv_formula {
        Some(UvFormula::SampleOverCentre) => lang.tr_with(
            "compare.gpu_check.samples_uv_formula",
            &[
                ("raw", &format!("{:.2}", c.max_uv_formula_difference)),
                ("max", &max),
                ("at", &at(c.max_uv_at)),
            ],
        ),
        _ => lang.tr_with(
            "compare.gpu_check.samples_uv_exact",
            &[("max", &max), ("at", &at(c.max_uv_at))],
        ),
    });
    if c.location_differs > 0 {
        lines.push(lang.tr_with(
            "compare.gpu_check.samples_location",
            &[
                ("n", &c.location_differs),
                ("at", &list(&c.location_differs_at, c.location_differs)),
            ],
        ));
    }
    lines.push(lang.tr_with(
        "compare.gpu_check.samples_resolve",
        &[
            ("depth", &format!("{:.1e}", c.max_depth_difference)),
            ("n", &c.resolve_differing),
            ("max", &lang.levels(c.max_resolve_difference)),
        ],
    ));
    lines
}

fn pixels(list: &[[u32; 2]], total: usize) -> String {
    let shown: Vec<String> = list.iter().map(|[x, y]| format!("({x}, {y})")).collect();
    let more = if total > list.len() { ", ..." } else { "" };
    format!("{}{more}", shown.join(", "))
}

/// " at (x, y), ..." for the listed pixels, or nothing when there are none.
fn at_list(list: &[[u32; 2]], total: usize, lang: Lang) -> String {
    if total == 0 {
        return String::new();
    }
    lang.tr_with("compare.gpu_check.at", &[("list", &pixels(list, total))])
}

/// The report in `lang`.
fn text(r: &Report, lang: Lang) -> String {
    let mut out = lang.tr_with(
        "compare.gpu_check.opengl",
        &[
            ("renderer", &r.renderer),
            ("vendor", &r.vendor),
            ("version", &r.version),
        ],
    );
    out.push('\n');
    let t = &r.ties;
    out.push_str(&match t.follows {
        Some(rule) => lang.tr_with(
            "compare.gpu_check.ties_follow",
            &[("rule", &rule_words(rule, lang)), ("n", &t.rules_differ_on)],
        ),
        None => lang.tr_with(
            "compare.gpu_check.ties_neither",
            &[
                ("llvmpipe", &t.differing_llvmpipe),
                ("top_left", &t.differing_top_left),
            ],
        ),
    });
    out.push('\n');
    for s in &r.scenes {
        let mode = match s.mode {
            "affine" => mode_short(Interpolation::Affine, lang),
            _ => mode_short(Interpolation::Perspective, lang),
        };
        let filter = lang.tr(&format!("probe.filter.{}", s.filter));
        let output = lang.tr(&format!("probe.shading.{}", s.output));
        let mut lines = vec![
            String::new(),
            lang.tr_with(
                "compare.gpu_check.scene",
                &[
                    ("scene", &s.scene),
                    ("w", &s.width),
                    ("h", &s.height),
                    ("mode", &mode),
                    ("filter", &filter),
                    ("output", &output),
                ],
            ),
        ];
        for n in &s.notes {
            lines.push(lang.tr_with("compare.gpu_check.note", &[("note", &n.text(lang))]));
        }
        lines.push(lang.tr_with(
            "compare.gpu_check.coverage",
            &[
                ("covered", &s.covered),
                ("total", &s.pixels),
                ("n", &s.coverage_mismatches),
                (
                    "at",
                    &at_list(&s.coverage_mismatch_pixels, s.coverage_mismatches, lang),
                ),
            ],
        ));
        lines.push(lang.tr_with(
            "compare.gpu_check.triangles",
            &[
                ("n", &s.triangle_mismatches),
                (
                    "at",
                    &at_list(&s.triangle_mismatch_pixels, s.triangle_mismatches, lang),
                ),
            ],
        ));
        let at = |p: Option<[u32; 2]>| {
            p.map(|[x, y]| lang.tr_with("compare.report.at", &[("x", &x), ("y", &y)]))
                .unwrap_or_default()
        };
        lines.push(lang.tr_with(
            "compare.gpu_check.colour",
            &[
                ("n", &s.color_differing),
                ("max", &lang.levels(s.max_color_difference)),
                ("at", &at(s.max_color_at)),
                ("p999", &s.p999_color_difference),
            ],
        ));
        lines.push(lang.tr_with(
            "compare.gpu_check.uv",
            &[
                ("max", &format!("{:.1e}", s.max_uv_difference)),
                ("at", &at(s.max_uv_at)),
            ],
        ));
        if let Some(l) = &s.lod {
            lines.extend(l.lines(&r.renderer, lang));
        }
        if let Some(c) = &s.samples {
            lines.extend(sample_lines(c, lang));
        }
        for l in lines {
            out.push_str(&l);
            out.push('\n');
        }
    }
    out
}
