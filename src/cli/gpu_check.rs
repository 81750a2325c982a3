//! `barylab gpu-check`: barylab beside this computer's OpenGL, scene by scene.

use anyhow::Result;
use barylab::gpu::{self, Gpu, check};
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
        print(&text(&report))?;
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
    Err(Differs(format!(
        "coverage differs from {} in {} of {} scenes: {}",
        report.renderer,
        differing.len(),
        report.scenes.len(),
        differing.join(", ")
    ))
    .into())
}

fn pixels(list: &[[u32; 2]], total: usize) -> String {
    let shown: Vec<String> = list.iter().map(|[x, y]| format!("({x}, {y})")).collect();
    let more = if total > list.len() { ", ..." } else { "" };
    format!("{}{more}", shown.join(", "))
}

fn text(r: &Report) -> String {
    let mut out = format!("OpenGL: {} ({}; {})\n", r.renderer, r.vendor, r.version);
    let t = &r.ties;
    out.push_str(&match t.follows {
        Some(rule) => format!(
            "ties: the GPU follows {} ({} of the tie lattice's pixels would differ under the other rule)\n",
            rule.describe(),
            t.rules_differ_on
        ),
        None => format!(
            "ties: the GPU follows neither rule: {} lattice pixels differ from the llvmpipe rule, {} from the top-left rule\n",
            t.differing_llvmpipe, t.differing_top_left
        ),
    });
    for s in &r.scenes {
        out.push_str(&format!(
            "\n{} {}x{}, {}, {} filter, {}:\n",
            s.scene,
            s.width,
            s.height,
            s.mode,
            s.filter,
            s.output.replace('_', " ")
        ));
        for n in &s.notes {
            out.push_str(&format!("  note: {n}\n"));
        }
        out.push_str(&format!(
            "  coverage: {} of {} pixels covered by barylab; {} mismatches{}\n",
            s.covered,
            s.pixels,
            s.coverage_mismatches,
            if s.coverage_mismatches > 0 {
                format!(
                    " at {}",
                    pixels(&s.coverage_mismatch_pixels, s.coverage_mismatches)
                )
            } else {
                String::new()
            }
        ));
        out.push_str(&format!(
            "  owning triangle: {} mismatches{}\n",
            s.triangle_mismatches,
            if s.triangle_mismatches > 0 {
                format!(
                    " at {}",
                    pixels(&s.triangle_mismatch_pixels, s.triangle_mismatches)
                )
            } else {
                String::new()
            }
        ));
        let at = s
            .max_color_at
            .map(|[x, y]| format!(" at ({x}, {y})"))
            .unwrap_or_default();
        out.push_str(&format!(
            "  colour: {} differing; largest difference {} levels{at}, 99.9% within {}\n",
            s.color_differing, s.max_color_difference, s.p999_color_difference
        ));
        let at = s
            .max_uv_at
            .map(|[x, y]| format!(" at ({x}, {y})"))
            .unwrap_or_default();
        out.push_str(&format!(
            "  uv: largest difference {:.1e}{at}\n",
            s.max_uv_difference
        ));
    }
    out
}
