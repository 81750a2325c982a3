//! The depth-precision plot: window depth `d = (z/w + 1) / 2` against view depth for the
//! scene's near and far planes, through the projection itself (the scene camera's matrix, or
//! a clip-space scene's fitted `z_c = alpha w_c + beta`), drawn by the figures' line plot.

use glam::DVec4;

use super::Lens;
use crate::figure::plot::LinePlot;
use crate::i18n::Lang;
use crate::probe::format::fmt_number;
use crate::raster::project;
use crate::scene::Scene;

/// Points along the view depth axis.
const SAMPLES: usize = 240;

impl Lens {
    /// The window depth of the point at view depth `depth` on the central axis: the
    /// projection of `(0, 0, -depth)` (camera scenes) or of `(0, 0, alpha depth + beta, depth)`
    /// (fitted clip-space scenes), divided by w, then [`project::window_depth`]. `None`
    /// without a fit.
    pub fn window_depth_at(&self, depth: f64) -> Option<f64> {
        let clip = match self {
            Lens::Camera { chain, .. } => chain.clip_from_view * DVec4::new(0.0, 0.0, -depth, 1.0),
            Lens::ClipW { fit: None } => return None,
            Lens::ClipW {
                fit: Some([alpha, beta]),
            } => DVec4::new(0.0, 0.0, alpha * depth + beta, depth),
        };
        Some(project::window_depth(project::ndc_from_clip(clip).z))
    }
}

/// The plot of window depth against view depth from the near to the far plane of `scene`;
/// an error when the scene's planes are unknown (a clip-space scene whose z is not affine
/// in w).
pub fn depth_plot(scene: &Scene, lang: Lang) -> Result<LinePlot, String> {
    let lens = Lens::of_scene(scene, &scene.to_mesh());
    let (Some(near), Some(far)) = lens.planes() else {
        return Err(lang.tr("space.no_planes"));
    };
    let points = (0..=SAMPLES)
        .filter_map(|i| {
            let d = near + (far - near) * i as f64 / SAMPLES as f64;
            lens.window_depth_at(d).map(|z| [d, z])
        })
        .collect();
    Ok(LinePlot {
        title: lang.tr_with(
            "space.depth_plot.title",
            &[("n", &fmt_number(near)), ("f", &fmt_number(far))],
        ),
        x_label: lang.tr("space.depth_plot.x"),
        lines: vec![(lang.tr("space.depth_plot.line"), points)],
        marker: None,
    })
}
