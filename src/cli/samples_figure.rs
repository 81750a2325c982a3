//! `barylab figure --view samples`: the per-sample buffers of a multisampled scene (coverage
//! count, resolve, a sample's colour and depth), as SVG or PNG.

use anyhow::{Context, Result};
use barylab::figure::sample_buffers;
use barylab::i18n::Lang;
use barylab::raster::{RenderSettings, Texture};
use barylab::scene::Scene;

use super::FigureArgs;

/// Writes the per-sample buffers view of `scene` to `args.output`.
pub(super) fn write(
    args: &FigureArgs,
    scene: &Scene,
    texture: &Texture,
    settings: &RenderSettings,
    lang: Lang,
) -> Result<()> {
    let n = settings.samples.count.get();
    if n < 2 {
        anyhow::bail!(
            "--view samples needs a multisampled scene: {} has 1 sample per pixel (add --samples 4)",
            barylab::files::shown(&args.input.scene)
        );
    }
    let k = args.sample_index as usize;
    if k >= n {
        anyhow::bail!(
            "--sample-index {k} is not a sample of this scene: it has {n} samples, 0 to {}",
            n - 1
        );
    }
    let buffer = sample_buffers::samples_of(scene, texture, settings, args.black_edges)
        .with_context(|| barylab::files::shown(&args.input.scene))?;
    let picture = sample_buffers::picture(
        &buffer,
        k,
        f64::from(args.pixel_size),
        args.black_edges,
        lang,
    );
    super::texture_figure::write_picture(args, &picture)
}
