//! `barylab figure --view texture|lod`: the pinned pixel's lookup in texture space, or every
//! pixel's mipmap level, as SVG or PNG.

use anyhow::{Context, Result};
use barylab::figure::{lod_view, texture_view};
use barylab::i18n::Lang;
use barylab::raster::{Interpolation, RenderSettings, Texture};
use barylab::scene::Scene;

use super::{FigureArgs, FigureViewArg};
use crate::output::print;

/// Writes the texture or level-of-detail view of `scene` to `args.output`.
pub(super) fn write(
    args: &FigureArgs,
    scene: &Scene,
    texture: &Texture,
    settings: &RenderSettings,
    lang: Lang,
) -> Result<()> {
    let shown = || barylab::files::shown(&args.input.scene);
    let picture = match args.view {
        FigureViewArg::Texture => {
            let Some((x, y)) = args.pixel else {
                anyhow::bail!("--view texture needs --pixel X,Y: the pixel whose lookup it shows");
            };
            let trace =
                barylab::probe::probe(scene, texture, settings, (x, y)).with_context(shown)?;
            let Some(a) = trace.detail.as_ref().and_then(|d| d.attribute.as_ref()) else {
                anyhow::bail!("pixel ({x}, {y}) has no texture lookup: no triangle covers it");
            };
            let view = texture_view::TextureView::of(
                texture,
                (settings.filter, settings.wrap),
                a,
                settings.mode == Interpolation::Perspective,
                [x, y],
            );
            view.picture(lang)
        }
        _ => {
            let lambdas = lod_view::lod_per_pixel(scene, texture, settings).with_context(shown)?;
            let scale = f64::from(args.pixel_size);
            lod_view::lod_picture(&lambdas, scene.size(), texture.levels(), scale, lang)
        }
    };
    write_picture(args, &picture)
}

/// Writes a raster picture (the texture, level-of-detail and per-sample buffers views) to
/// `args.output`: SVG or PNG by its extension, at `--scale`.
pub(super) fn write_picture(
    args: &FigureArgs,
    picture: &barylab::figure::raster_svg::RasterSvg,
) -> Result<()> {
    let svg_out = args
        .output
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
    let bytes = if svg_out {
        picture.to_svg()?.into_bytes()
    } else {
        picture.to_png(args.scale as f32)?
    };
    barylab::files::write_bytes(&args.output, &bytes)?;
    print(&format!(
        "figure -> {}\n",
        barylab::files::shown(&args.output)
    ))
}
