//! The other image of the GPU view and of the image comparison ([`crate::app::panels::compare_image`]):
//! which image each view of the canvas shows, the views' title badges, and the other image's
//! colour in the inspector.

use egui::{Color32, Ui};

use crate::app::document::state::AppState;
use crate::app::panels::gpu_view::GpuView;
use crate::app::services::style::swatch;
use crate::figure::Compare;
use crate::figure::overlay::{Overlay, Shape, mode_label_in};
use crate::i18n::Lang;
use crate::raster::Interpolation;

/// What one view of the canvas shows in the GPU view.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GpuContent {
    /// barylab's image.
    Ours,
    /// The other image (the GPU's, or the loaded file's).
    Gpu,
    /// barylab's image left of the wipe line, the other right of it.
    Wipe,
    /// The difference image of the two.
    Difference,
}

/// The canvas's views in the GPU view, by the comparison chosen: Single shows the GPU's
/// image, side by side barylab | GPU, the wipe barylab | GPU, the difference image.
pub fn content(compare: Compare, index: usize) -> GpuContent {
    match (compare, index) {
        (Compare::Single, _) => GpuContent::Gpu,
        (Compare::SideBySide, 0) => GpuContent::Ours,
        (Compare::SideBySide, _) => GpuContent::Gpu,
        (Compare::Wipe, _) => GpuContent::Wipe,
        (Compare::Difference, _) => GpuContent::Difference,
    }
}

/// The image of view `index`, or `None` when there is no GPU image (the canvas then shows
/// barylab's).
pub fn view_image(
    view: &GpuView,
    compare: Compare,
    index: usize,
    wipe_col: u32,
) -> Option<egui::ColorImage> {
    let r = view.result.as_ref()?;
    let d = &r.diff;
    let pixels = match content(compare, index) {
        GpuContent::Ours => r.ours.clone(),
        GpuContent::Gpu => r.gpu.clone(),
        GpuContent::Wipe => crate::gpu::view::wipe(&r.ours, &r.gpu, d.width, wipe_col),
        GpuContent::Difference => d.image.clone(),
    };
    let size = [d.width as usize, d.height as usize];
    (pixels.len() == size[0] * size[1] && !pixels.is_empty()).then(|| {
        egui::ColorImage::new(
            size,
            pixels
                .iter()
                .map(|c| Color32::from_rgba_unmultiplied(c[0], c[1], c[2], c[3]))
                .collect(),
        )
    })
}

/// The other image's title: the GPU with its renderer, or the image file's name.
pub fn other_title(view: &GpuView, lang: Lang) -> String {
    match (&view.other_name, &view.info) {
        (Some(name), _) => lang.tr_with("compare_image.image_named", &[("name", &short(name))]),
        (None, Some(i)) => lang.tr_with("gpu_view.gpu_named", &[("renderer", &short(&i.renderer))]),
        (None, None) => lang.tr("gpu_view.gpu"),
    }
}

/// The overlay's title badges for the GPU view: the canvas builds the overlay as for the
/// mode comparison (affine badge on the left view or wipe side, perspective on the right)
/// and this names them barylab and the GPU instead.
pub fn relabel(overlay: &mut Overlay, lang: Lang, compare: Compare, view: &GpuView) {
    let gpu = other_title(view, lang);
    let right = match compare {
        Compare::Difference if view.other_name.is_some() => {
            lang.tr("compare_image.difference_title")
        }
        Compare::Difference => lang.tr("gpu_view.difference_title"),
        _ => gpu,
    };
    let (affine, perspective) = (
        mode_label_in(Interpolation::Affine, lang),
        mode_label_in(Interpolation::Perspective, lang),
    );
    for shape in &mut overlay.shapes {
        if let Shape::Text { text, .. } = shape {
            if *text == affine {
                *text = lang.tr("gpu_view.barylab");
            } else if *text == perspective {
                *text = right.clone();
            }
        }
    }
}

/// The mode badge of view `index` in the GPU view (`gpu`: whether there is a GPU image):
/// the one [`relabel`] turns into the view's title, or the scene's mode when the views show
/// barylab's image alone.
pub fn badge_mode(
    gpu: Option<bool>,
    compare: Compare,
    index: usize,
    state: &AppState,
) -> Interpolation {
    match (gpu, content(compare, index)) {
        (Some(true), GpuContent::Ours) => Interpolation::Affine,
        (Some(true), _) => Interpolation::Perspective,
        _ => state.options().mode,
    }
}

/// The comparison the canvas renders for: the GPU view needs barylab in the scene's mode
/// only.
pub fn render_compare(gpu: Option<&GpuView>, compare: Compare) -> Compare {
    match gpu {
        Some(_) => Compare::Single,
        None => compare,
    }
}

/// A renderer string up to its first parenthesis ("llvmpipe (LLVM 15, 256 bits)" ->
/// "llvmpipe"), at most 32 characters.
pub(in crate::app) fn short(renderer: &str) -> String {
    let s = renderer.split(" (").next().unwrap_or(renderer).trim();
    if s.chars().count() > 32 {
        let cut: String = s.chars().take(31).collect();
        format!("{cut}…")
    } else {
        s.to_string()
    }
}

fn hex(c: [u8; 4]) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

/// barylab's colour and the other image's at `pixel`, for the inspector (nothing without a GPU
/// image).
pub fn pixel_colours_ui(ui: &mut Ui, view: &GpuView, [x, y]: [u32; 2]) {
    let Some(r) = &view.result else {
        return;
    };
    let k = (y as usize) * (r.diff.width as usize) + x as usize;
    if let (Some(&ours), Some(&gpu)) = (r.ours.get(k), r.gpu.get(k)) {
        let lang = crate::app::services::locale::lang(ui.ctx());
        ui.horizontal(|ui| {
            swatch(ui, ours);
            ui.monospace(format!("{} barylab", hex(ours)));
        });
        ui.horizontal_wrapped(|ui| {
            swatch(ui, gpu);
            let name = view.other_name.as_deref().unwrap_or("GPU");
            ui.monospace(format!("{} {}", hex(gpu), short(name)));
            let d = (0..4).map(|i| ours[i].abs_diff(gpu[i])).max().unwrap_or(0);
            if d > 0 {
                ui.label(lang.tr_with("gpu_view.pixel_difference", &[("levels", &lang.levels(d))]));
            }
        });
    }
}
