//! `barylab compare SCENE IMAGE`: another rasterizer's image against barylab's render.

use std::io::Cursor;
use std::path::Path;

use anyhow::Result;
use barylab::compare::reason::mode_short;
use barylab::compare::{self, Comparison, CoverageBy, Image, Reference};
use barylab::files::{self, shown};
use barylab::i18n::Lang;

use super::CompareArgs;
use super::commands::{inputs, prepare};
use crate::output::{self, Differs, print};

pub(super) fn run(args: &CompareArgs) -> Result<()> {
    if let Some(o) = &args.output {
        output::check_output(o, &["png"])?;
    }
    let (scene, texture, settings) = prepare(&args.input)?;
    let mut read = inputs(&args.input.scene, &scene);
    read.push(args.image.clone());
    if let Some(o) = &args.output {
        output::not_an_input(o, &read)?;
    }
    let lang = args.lang;
    let image = read_image(
        &args.image,
        (settings.width, settings.height),
        &args.input.scene,
        lang,
    )?;
    let by = compare::coverage_for(&image, &settings, args.background);
    let mesh = scene.to_mesh();
    let reference = Reference {
        scene: &scene,
        mesh: &mesh,
        texture: &texture,
        settings,
    };
    let failed = |e: String| anyhow::anyhow!("{}: {e}", shown(&args.input.scene));
    let render = compare::render_for_comparison(&mesh, &texture, &settings).map_err(failed)?;
    let c = compare::compare_rendered(&image, &reference, &render, by, args.tolerance)
        .map_err(failed)?;
    if let Some(o) = &args.output {
        let diff = compare::difference_image_of(&image, &render.frame, by, args.tolerance);
        let mut png = Vec::new();
        diff.write_to(&mut Cursor::new(&mut png), image::ImageFormat::Png)?;
        files::write_bytes(o, &png)?;
    }
    if args.json {
        print(&format!("{}\n", serde_json::to_string_pretty(&c)?))?;
    } else {
        print(&text(
            &c,
            &args.image,
            &args.input.scene,
            args.output.as_deref(),
            lang,
        ))?;
    }
    if c.agrees() {
        return Ok(());
    }
    Err(Differs(lang.tr_with(
        "compare.report.differs",
        &[
            ("image", &shown(&args.image)),
            ("scene", &shown(&args.input.scene)),
            ("n", &c.differing()),
            ("total", &c.pixels),
        ],
    ))
    .into())
}

/// Reads the image, checking its size against the scene's before decoding it.
fn read_image(path: &Path, size: (u32, u32), scene: &Path, lang: Lang) -> Result<Image> {
    let name = shown(path);
    compare::read_image(path, lang, |w, h| {
        if (w, h) == size {
            Ok(())
        } else {
            Err(lang.tr_with(
                "compare.report.wrong_size",
                &[
                    ("image", &name),
                    ("w", &w),
                    ("h", &h),
                    ("scene", &shown(scene)),
                    ("sw", &size.0),
                    ("sh", &size.1),
                ],
            ))
        }
    })
    .map_err(anyhow::Error::msg)
}

/// The report, in `lang`: the verdict first (underlined), the named bugs with their fixes,
/// what was compared, coverage, colour, then the regions of differing pixels, each with its
/// reason and a few sample pixels.
fn text(c: &Comparison, image: &Path, scene: &Path, diff: Option<&Path>, lang: Lang) -> String {
    let by = match c.coverage_by {
        CoverageBy::Alpha => lang.tr("compare.report.by_alpha"),
        CoverageBy::Background([r, g, b]) => lang.tr_with(
            "compare.report.by_background",
            &[("color", &format!("{r},{g},{b}"))],
        ),
    };
    let verdict = if c.agrees() {
        lang.tr("compare.report.agree")
    } else {
        match &c.looks_like {
            Some(v) => lang.tr_with("compare.report.verdict", &[("verdict", &v.text(lang))]),
            None => lang.tr_with("compare.report.differ", &[("n", &c.differing())]),
        }
    };
    let rule = "=".repeat(verdict.chars().count().min(100));
    let mut lines = vec![verdict, rule];
    for b in &c.bugs {
        lines.push(lang.tr_with(
            "compare.report.bug",
            &[
                ("code", &b.code()),
                ("title", &b.title(lang)),
                ("explanation", &b.explanation(lang)),
                ("fix", &b.fix(lang)),
            ],
        ));
    }
    lines.push(lang.tr_with(
        "compare.report.header",
        &[
            ("image", &shown(image)),
            ("scene", &shown(scene)),
            ("w", &c.width),
            ("h", &c.height),
            ("mode", &mode_short(c.mode, lang)),
            ("by", &by),
            ("tolerance", &lang.levels(c.tolerance)),
        ],
    ));
    lines.push(lang.tr_with(
        "compare.report.coverage",
        &[
            ("n", &(c.only_theirs + c.only_ours)),
            ("only_image", &c.only_theirs),
            ("only_barylab", &c.only_ours),
            ("covered", &c.covered),
        ],
    ));
    let at = c
        .max_color_at
        .map(|[x, y]| lang.tr_with("compare.report.at", &[("x", &x), ("y", &y)]))
        .unwrap_or_default();
    lines.push(lang.tr_with(
        "compare.report.colour",
        &[
            ("n", &c.color_differing),
            ("tolerance", &lang.levels(c.tolerance)),
            ("max", &c.max_color_difference),
            ("at", &at),
        ],
    ));
    if !c.agrees() {
        lines.push(lang.tr_with("compare.report.regions", &[("n", &c.region_count)]));
        for (i, r) in c.regions.iter().enumerate() {
            lines.push(r.text(i + 1, lang));
            lines.extend(r.samples.iter().map(|p| p.text(lang)));
        }
        if c.region_count > c.regions.len() {
            lines.push(lang.tr_with(
                "compare.report.regions_more",
                &[("n", &(c.region_count - c.regions.len()))],
            ));
        }
    }
    if let Some(d) = diff {
        lines.push(lang.tr_with("compare.report.difference_image", &[("file", &shown(d))]));
    }
    let mut out = lines.join("\n");
    out.push('\n');
    out
}
