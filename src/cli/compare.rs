//! `barylab compare SCENE IMAGE`: another rasterizer's image against barylab's render.

use std::io::Cursor;
use std::path::Path;

use anyhow::Result;
use barylab::compare::{self, Comparison, CoverageBy, Difference, Image, Reference};
use barylab::files::{self, shown};

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
    let image = read_image(
        &args.image,
        (settings.width, settings.height),
        &args.input.scene,
    )?;
    let by = match args.background {
        Some(c) => CoverageBy::Background(c),
        None if image.has_transparency() => CoverageBy::Alpha,
        None => {
            let b = settings.background;
            CoverageBy::Background([b[0], b[1], b[2]])
        }
    };
    let mesh = scene.to_mesh();
    let reference = Reference {
        scene: &scene,
        mesh: &mesh,
        texture: &texture,
        settings,
    };
    let c = compare::compare(&image, &reference, by, args.tolerance)
        .map_err(|e| anyhow::anyhow!("{}: {e}", shown(&args.input.scene)))?;
    if let Some(o) = &args.output {
        let diff = compare::difference_image(&image, &reference, by, args.tolerance)
            .map_err(anyhow::Error::msg)?;
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
        ))?;
    }
    if c.agrees() {
        return Ok(());
    }
    Err(Differs(format!(
        "{} differs from barylab's render of {} on {} of {} pixels",
        shown(&args.image),
        shown(&args.input.scene),
        c.differing(),
        c.pixels
    ))
    .into())
}

/// Reads the image, checking its size against the scene's before decoding it.
fn read_image(path: &Path, size: (u32, u32), scene: &Path) -> Result<Image> {
    let name = shown(path);
    compare::read_image(path, |w, h| {
        if (w, h) == size {
            Ok(())
        } else {
            Err(format!(
                "image {name} is {w}x{h}, but {} renders {}x{}: compare images of the same size \
                 (or render the scene at {w}x{h} with --size {w}x{h})",
                shown(scene),
                size.0,
                size.1
            ))
        }
    })
    .map_err(anyhow::Error::msg)
}

fn text(c: &Comparison, image: &Path, scene: &Path, diff: Option<&Path>) -> String {
    let by = match c.coverage_by {
        CoverageBy::Alpha => "alpha of at least 128".to_string(),
        CoverageBy::Background([r, g, b]) => format!("any colour but the background {r},{g},{b}"),
    };
    let mut out = format!(
        "{} against barylab's render of {} ({}x{}, {}); covered: {by}; tolerance {} levels\n",
        shown(image),
        shown(scene),
        c.width,
        c.height,
        barylab::bench::mode_name(c.mode),
        c.tolerance
    );
    out.push_str(&format!(
        "coverage: {} pixels differ ({} covered only in the image, {} only by barylab, which covers {})\n",
        c.only_theirs + c.only_ours,
        c.only_theirs,
        c.only_ours,
        c.covered
    ));
    let at = c
        .max_color_at
        .map(|[x, y]| format!(" at ({x}, {y})"))
        .unwrap_or_default();
    out.push_str(&format!(
        "colour: {} pixels covered by both differ by more than {} levels; largest difference {}{at}\n",
        c.color_differing, c.tolerance, c.max_color_difference
    ));
    if c.agrees() {
        out.push_str("verdict: the images agree\n");
    } else {
        match &c.looks_like {
            Some(l) => out.push_str(&format!("verdict: {l}\n")),
            None => out.push_str(&format!("verdict: {} pixels differ\n", c.differing())),
        }
        out.push_str("first differing pixels:\n");
        for p in &c.first {
            let what = match p.difference {
                Difference::OnlyTheirs => "covered only in the image",
                Difference::OnlyOurs => "covered only by barylab",
                Difference::Color => "colour",
            };
            let rgb = |c: [u8; 4]| format!("{},{},{}", c[0], c[1], c[2]);
            out.push_str(&format!(
                "  ({}, {}) {what}: image {}, barylab {}: {}\n",
                p.pixel[0],
                p.pixel[1],
                rgb(p.theirs),
                rgb(p.ours),
                p.reason
            ));
        }
    }
    if let Some(d) = diff {
        out.push_str(&format!("difference image -> {}\n", shown(d)));
    }
    out
}
