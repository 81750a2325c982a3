//! `barylab figure --view space|depth|tetra`: the scene in 3D with the pixel's ray, the
//! depth-precision plot and the tetrahedron's volume weights.

use anyhow::{Context, Result};
use barylab::figure::space::{Orbit, SpaceFigure, SpaceScene};
use barylab::i18n::Lang;
use barylab::raster::{RenderSettings, Texture};
use barylab::scene::Scene;

use super::{FigureArgs, FigureViewArg as ViewArg};
use crate::output::print;

/// The orbit of `--view space`.
#[derive(clap::Args, Debug)]
pub(super) struct OrbitArgs {
    /// With --view space: the orbit camera's turn about the vertical, degrees (0: from behind
    /// the scene's eye; default 40, from its right).
    #[arg(long, allow_hyphen_values = true)]
    yaw: Option<f64>,
    /// With --view space: the orbit camera's height, degrees above the horizontal (-85 to 85;
    /// default 28).
    #[arg(long, allow_hyphen_values = true, value_parser = parse_pitch)]
    pitch: Option<f64>,
    /// With --view space: magnification (0.25 to 8; default 1, the scene just fits).
    #[arg(long, value_parser = parse_zoom)]
    zoom: Option<f64>,
}

fn parse_pitch(s: &str) -> Result<f64, String> {
    let l = barylab::figure::space::PITCH_LIMIT;
    match s.trim().parse::<f64>() {
        Ok(v) if (-l..=l).contains(&v) => Ok(v),
        _ => Err(format!("pitch `{s}` is not a number from -{l} to {l}")),
    }
}

fn parse_zoom(s: &str) -> Result<f64, String> {
    let (lo, hi) = barylab::figure::space::ZOOM_RANGE;
    match s.trim().parse::<f64>() {
        Ok(v) if (lo..=hi).contains(&v) => Ok(v),
        _ => Err(format!("zoom `{s}` is not a number from {lo} to {hi}")),
    }
}

impl OrbitArgs {
    fn orbit(&self) -> Orbit {
        let d = Orbit::default();
        Orbit {
            yaw_deg: self.yaw.filter(|v| v.is_finite()).unwrap_or(d.yaw_deg),
            pitch_deg: self.pitch.unwrap_or(d.pitch_deg),
            zoom: self.zoom.unwrap_or(d.zoom),
        }
    }
}

/// Writes the figure `args.view` asks for (not the canvas).
pub(super) fn figure(
    args: &FigureArgs,
    scene: &Scene,
    texture: &Texture,
    settings: &RenderSettings,
    lang: Lang,
    svg_out: bool,
) -> Result<()> {
    let shown = barylab::files::shown(&args.input.scene);
    let scale = args.scale as f32;
    let (bytes, what) = match args.view {
        ViewArg::Space | ViewArg::Image | ViewArg::Texture | ViewArg::Lod | ViewArg::Samples => {
            let trace = pixel_trace(args, scene, texture, settings)?;
            let space = SpaceScene::build(scene, settings, trace.as_ref())
                .with_context(|| shown.clone())?;
            let fig = SpaceFigure {
                space: &space,
                orbit: args.orbit.orbit(),
                lang,
            };
            let bytes = if svg_out {
                fig.to_svg().into_bytes()
            } else {
                fig.to_png(scale)?
            };
            (bytes, "space view")
        }
        ViewArg::Depth => {
            let plot = barylab::figure::space::depth_plot(scene, lang)
                .map_err(anyhow::Error::msg)
                .with_context(|| shown.clone())?;
            let bytes = if svg_out {
                plot.to_svg(lang).into_bytes()
            } else {
                plot.to_png(lang, scale)?
            };
            (bytes, "depth plot")
        }
        ViewArg::Tetra => {
            let trace = pixel_trace(args, scene, texture, settings)?;
            let space = SpaceScene::build(scene, settings, trace.as_ref())
                .with_context(|| shown.clone())?;
            let fig = barylab::figure::space::TetraFigure::new(&space, args.orbit.orbit(), lang)
                .map_err(anyhow::Error::msg)
                .with_context(|| shown.clone())?;
            let bytes = if svg_out {
                fig.to_svg().into_bytes()
            } else {
                fig.to_png(scale)?
            };
            (bytes, "tetrahedron")
        }
    };
    barylab::files::write_bytes(&args.output, &bytes)?;
    print(&format!(
        "{what} -> {}\n",
        barylab::files::shown(&args.output)
    ))
}

/// The probe of the pixel `--pixel` (else `--hover`) names, when one is given.
fn pixel_trace(
    args: &FigureArgs,
    scene: &Scene,
    texture: &Texture,
    settings: &RenderSettings,
) -> Result<Option<barylab::probe::PixelTrace>> {
    match args.pixel.or(args.hover) {
        Some(p) => Ok(Some(
            barylab::probe::probe(scene, texture, settings, p)
                .with_context(|| barylab::files::shown(&args.input.scene))?,
        )),
        None => Ok(None),
    }
}
