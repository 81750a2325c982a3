//! The texture views beside the canvas, the same pictures `barylab figure --view texture|lod`
//! makes: the hovered, else pinned, pixel's lookup in texture space (`figure::texture_view`:
//! level 0 with the footprint, the levels read with their taps and weights, the anisotropic
//! probes), or every pixel coloured by its mipmap level (`figure::lod_view`) with the legend.
//! Under each picture the numbers that made the pixel, from the probe's trace, as text.

use std::sync::Arc;

use egui::{Color32, RichText, Sense, Stroke, TextureHandle, TextureOptions, Ui};

use crate::app::document::state::StateCommand;
use crate::app::services::pixel::PixelReport;
use crate::app::services::render::CanvasOutput;
use crate::figure::TexelView;
use crate::figure::lod_view;
use crate::figure::texture_view::TextureView;
use crate::i18n::Lang;
use crate::raster::texture::Filter;
use crate::raster::{Interpolation, Texture};

mod lines;

pub use lines::{lod_line, texture_lines};
use lines::{n, rgba};

/// Pixels per point the pictures are drawn at before egui scales them to the column.
const PICTURE_SCALE: f32 = 2.0;
/// Narrowest a texture panel is laid out, points (narrower columns show one per row).
const MIN_PANEL: f32 = 220.0;
/// The texture view's share of the window's width in presentation mode.
pub const PRESENT_SHARE: f32 = 0.46;

/// How the pixels of the pictures are shown: crisp (they are texels or image pixels).
const PICTURE_TEXTURE: TextureOptions = TextureOptions::NEAREST;

/// What the drawn pictures belong to: the view, the render's generation, the pixel with its
/// report's generation, the language.
type PictureKey = (TexelView, u64, Option<([u32; 2], u64)>, Lang);

/// The views' state: the pictures drawn for the last key, and the level of detail of every
/// pixel of the last render.
#[derive(Default)]
pub struct TexelViewPanel {
    pictures: Option<(PictureKey, Vec<TextureHandle>)>,
    lambdas: Option<(u64, Arc<Vec<f32>>)>,
    /// The lambda-down-a-column plot's lines: the render's generation, the mode, the column.
    column: Option<((u64, Interpolation, u32), crate::lesson::plot::PlotLines)>,
}

/// The Controls panel's choices of the texture views (beside the 3D view's toggle): a second
/// click on the one shown turns it off.
pub fn toggle_ui(ui: &mut Ui, current: TexelView) -> Vec<StateCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut out = Vec::new();
    for (kind, name, tip) in [
        (
            TexelView::Texture,
            "texel_view.texture",
            "texel_view.texture_tip",
        ),
        (TexelView::Lod, "texel_view.lod", "texel_view.lod_tip"),
    ] {
        if ui
            .selectable_label(current == kind, lang.tr(name))
            .on_hover_text(lang.tr(tip))
            .clicked()
        {
            let next = if current == kind {
                TexelView::Off
            } else {
                kind
            };
            out.push(StateCommand::SetTexelView(next));
        }
    }
    out
}

impl TexelViewPanel {
    /// The lines of the lambda plot down column `x` of `output`'s scene drawn with `settings`
    /// ([`crate::lesson::plot::lambda_column`]; computed again only for a new render, mode or
    /// column).
    pub(in crate::app) fn lambda_column(
        &mut self,
        output: &CanvasOutput,
        texture: &Texture,
        settings: &crate::raster::RenderSettings,
        x: u32,
    ) -> Option<crate::lesson::plot::PlotLines> {
        let key = (output.generation, settings.mode, x);
        if self.column.as_ref().is_none_or(|(k, _)| *k != key) {
            let lines =
                crate::lesson::plot::lambda_column(&output.scene, texture, settings, x).ok()?;
            self.column = Some((key, lines));
        }
        self.column.as_ref().map(|(_, l)| l.clone())
    }

    /// Every pixel's level of detail for `output` (computed again only for a new render).
    fn lambdas(&mut self, output: &CanvasOutput, texture: &Texture) -> Option<Arc<Vec<f32>>> {
        if self
            .lambdas
            .as_ref()
            .is_none_or(|(g, _)| *g != output.generation)
        {
            let settings = output.scene.settings();
            let l = lod_view::lod_per_pixel(&output.scene, texture, &settings).ok()?;
            self.lambdas = Some((output.generation, Arc::new(l)));
        }
        self.lambdas.as_ref().map(|(_, l)| Arc::clone(l))
    }

    /// The view `kind` for the canvas's `output` and the pixel `report` traced (hovered,
    /// else pinned): its title, the picture fitted to the column, the numbers under it.
    pub fn ui(
        &mut self,
        ui: &mut Ui,
        kind: TexelView,
        output: Option<&CanvasOutput>,
        report: Option<&PixelReport>,
        texture: &Texture,
        fit: bool,
    ) {
        let lang = crate::app::services::locale::lang(ui.ctx());
        let title = match kind {
            TexelView::Lod => "texel_view.lod_title",
            _ => "texel_view.texture_title",
        };
        ui.label(RichText::new(lang.tr(title)).strong());
        // Presentation mode: the height under the title, which all of the view must fit.
        let fit = fit.then(|| ui.available_height());
        let Some(output) = output else {
            return;
        };
        egui::ScrollArea::vertical()
            .id_salt("texel-view")
            .auto_shrink([false, false])
            .show(ui, |ui| match kind {
                TexelView::Lod => self.lod_ui(ui, lang, output, report, texture),
                _ => self.texture_ui(ui, lang, output, report, texture, fit),
            });
    }

    /// The texture-space view of the report's pixel. With `fit` (presentation mode: the
    /// panel's height below its title) all of it fits that height at the presentation text
    /// size: the numbers in the proportional font, the anisotropic probes as a row of colour
    /// swatches, the tap lines (more than one tap) and the caption as the pictures' hover text (the
    /// pictures print each tap's weight), and the pictures as large as the
    /// room left between the numbers over and under them allows (at least [`MIN_PICTURE`]).
    fn texture_ui(
        &mut self,
        ui: &mut Ui,
        lang: Lang,
        output: &CanvasOutput,
        report: Option<&PixelReport>,
        texture: &Texture,
        fit: Option<f32>,
    ) {
        let Some(report) = report else {
            ui.label(lang.tr("texel_view.no_pixel"));
            return;
        };
        let Some(a) = report
            .trace
            .detail
            .as_ref()
            .and_then(|d| d.attribute.as_ref())
            .filter(|_| report.trace.written_by.is_some())
        else {
            ui.label(lang.tr("texel_view.no_lookup"));
            return;
        };
        let settings = PixelReport::settings(output, report.mode);
        let perspective = report.mode == Interpolation::Perspective;
        let view = TextureView::of(
            texture,
            (settings.filter, settings.wrap),
            a,
            perspective,
            report.pixel,
        );
        let key = (
            TexelView::Texture,
            output.generation,
            Some((report.pixel, report.generation)),
            lang,
        );
        let (uv, taps, color) = if perspective {
            (a.uv_perspective, &a.taps_perspective, a.color_perspective)
        } else {
            (a.uv_affine, &a.taps_affine, a.color_affine)
        };
        let lod = a
            .lod
            .as_ref()
            .filter(|_| settings.filter == Filter::Trilinear);
        let [over, mut under] = texture_lines(lang, report.pixel, uv, taps, lod, color);
        if fit.is_some() {
            // Lines closer together: the pictures get the room.
            ui.spacing_mut().item_spacing.y = FIT_SPACING;
        }
        // Beside the canvas, the pixel's line over the pictures and its other numbers under
        // them: in a short panel (a projector's 1024x768 with the Lessons panel open) the
        // derivatives' lines filled it and the pictures were out of sight.
        let (over, after): (Vec<String>, Vec<String>) = if fit.is_some() {
            (over, Vec::new())
        } else {
            let mut over = over;
            let after = over.split_off(over.len().min(1));
            (over, after)
        };
        for line in over {
            // Presenting, the numbers in the strong (brightest) text colour: a projector loses
            // the contrast of the default grey.
            ui.label(if fit.is_some() {
                RichText::new(line).strong()
            } else {
                RichText::new(line).monospace()
            });
        }
        if self.pictures.as_ref().is_none_or(|(k, _)| *k != key) {
            let handles = view
                .panel_pictures(lang)
                .iter()
                .enumerate()
                .filter_map(|(i, p)| {
                    let img = p.to_image(PICTURE_SCALE).ok()?;
                    Some(upload(ui.ctx(), &format!("texel-view-{i}"), &img))
                })
                .collect();
            self.pictures = Some((key, handles));
        }
        let captions = view.caption(lang);
        let probes = lod
            .and_then(|l| l.anisotropic.as_ref())
            .filter(|_| fit.is_some());
        let mut hover = captions.join("\n");
        if probes.is_some() {
            // The probes' lines (all but the colour's) become a row of swatches.
            under.drain(..under.len().saturating_sub(1));
        } else if fit.is_some() && under.len() > 2 {
            // Bilinear's four taps, trilinear's eight: the pictures print each tap's weight
            // in its texel, so presenting, their lines (all but the colour's) are the
            // pictures' hover text and the pictures get the room.
            let taps: Vec<String> = under.drain(..under.len().saturating_sub(1)).collect();
            hover = format!("{hover}\n{}", taps.join("\n"));
        }
        let Some((_, handles)) = &self.pictures else {
            return;
        };
        let Some(height) = fit else {
            show_grid(ui, handles, f32::INFINITY, None);
            for line in &captions {
                ui.label(RichText::new(line).weak());
            }
            ui.add_space(4.0);
            for line in after.iter().chain(&under) {
                ui.label(RichText::new(line).monospace());
            }
            return;
        };
        // The room the numbers over the pictures (drawn) and under them (measured here as
        // their labels will lay them out) leave for the pictures; the caption is the
        // pictures' hover text.
        let width = ui.available_width();
        let spacing = ui.spacing().item_spacing;
        let font = egui::TextStyle::Body.resolve(ui.style());
        let layout = |t: &str| {
            ui.painter()
                .layout(t.to_string(), font.clone(), Color32::WHITE, width)
                .size()
        };
        let lines: f32 = under.iter().map(|t| layout(t).y + spacing.y).sum();
        let probes_line = probes.map(|_| lang.tr("texel_view.probes_compact"));
        let swatch_rows = probes.zip(probes_line.as_ref()).map_or(0.0, |(a, line)| {
            let row = layout(line).x + spacing.x + a.probes.len() as f32 * (SWATCH + SWATCH_GAP);
            (row / width).ceil() * (layout(line).y.max(SWATCH) + spacing.y)
        });
        let used = ui.cursor().top() - ui.max_rect().top();
        let room = height - used - lines - swatch_rows - spacing.y;
        show_grid(ui, handles, room.max(MIN_PICTURE), Some(&hover));
        if let (Some(a), Some(line)) = (probes, probes_line) {
            swatches(ui, lang, a, line);
        }
        for line in &under {
            ui.label(RichText::new(line.as_str()).strong());
        }
    }

    /// The level-of-detail view of the render, the report's pixel outlined.
    fn lod_ui(
        &mut self,
        ui: &mut Ui,
        lang: Lang,
        output: &CanvasOutput,
        report: Option<&PixelReport>,
        texture: &Texture,
    ) {
        let Some(lambdas) = self.lambdas(output, texture) else {
            return;
        };
        let (w, h) = output.scene.size();
        if lambdas.len() != w as usize * h as usize {
            return;
        }
        let levels = texture.levels();
        let key = (TexelView::Lod, output.generation, None, lang);
        if self.pictures.as_ref().is_none_or(|(k, _)| *k != key) {
            let img = lod_view::lod_image(&lambdas, (w, h), levels);
            self.pictures = Some((key, vec![upload(ui.ctx(), "texel-view-lod", &img)]));
        }
        if output.scene.settings().filter != Filter::Trilinear {
            ui.label(RichText::new(lang.tr("texel_view.lod_not_mipmapped")).weak());
        }
        if let Some((_, handles)) = &self.pictures
            && let Some(t) = handles.first()
        {
            let side = ui.available_width();
            let size = egui::vec2(side, side * h as f32 / w.max(1) as f32);
            let (rect, _) = ui.allocate_exact_size(size, Sense::hover());
            let uv = egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0));
            ui.painter().image(t.id(), rect, uv, Color32::WHITE);
            if let Some(r) = report {
                let k = rect.width() / w.max(1) as f32;
                let min = rect.min + egui::vec2(r.pixel[0] as f32 * k, r.pixel[1] as f32 * k);
                let px = egui::Rect::from_min_size(min, egui::vec2(k, k)).expand(2.0);
                ui.painter().rect_stroke(
                    px,
                    0.0,
                    Stroke::new(2.0, Color32::BLACK),
                    egui::StrokeKind::Outside,
                );
            }
        }
        ui.label(RichText::new(lang.tr("figure.lod.legend")).strong());
        ui.horizontal_wrapped(|ui| {
            for (c, label) in lod_view::legend(&lambdas, levels, lang) {
                // The swatch (a square glyph in the level's colour) and its label as one
                // text that never breaks: an entry wraps as a whole, never a swatch apart
                // from its level.
                let font = egui::TextStyle::Body.resolve(ui.style());
                let mut job = egui::text::LayoutJob::default();
                let swatch = Color32::from_rgb(c[0], c[1], c[2]);
                job.append(
                    "\u{25A0} ",
                    0.0,
                    egui::TextFormat::simple(font.clone(), swatch),
                );
                let text = ui.visuals().text_color();
                job.append(&label, 0.0, egui::TextFormat::simple(font, text));
                ui.add(egui::Label::new(job).wrap_mode(egui::TextWrapMode::Extend));
                ui.add_space(6.0);
            }
        });
        if let Some(r) = report {
            let i = (r.pixel[1] as usize) * w as usize + r.pixel[0] as usize;
            if let Some(&l) = lambdas.get(i) {
                ui.label(RichText::new(lod_line(lang, r.pixel, l, levels)).monospace());
            }
        }
    }
}

/// Uploads a picture as an egui texture.
fn upload(ctx: &egui::Context, name: &str, img: &image::RgbaImage) -> TextureHandle {
    let size = [img.width() as usize, img.height() as usize];
    let image = egui::ColorImage::from_rgba_unmultiplied(size, img.as_raw());
    ctx.load_texture(name, image, PICTURE_TEXTURE)
}

/// The panels' pictures in rows as wide as the column, as many to a row as fit
/// [`MIN_PANEL`] points each (with `hover` as their hover text); when that is taller than
/// `room` points, the number of columns
/// that gives the largest pictures within `room` (the presentation panel's pictures scale to
/// the space the numbers leave). Three pictures that would leave a row half empty (level 0
/// and the two levels read) are laid out as the first beside the other two stacked, when
/// that makes the first larger and the others no smaller.
fn show_grid(ui: &mut Ui, handles: &[TextureHandle], room: f32, hover: Option<&str>) {
    let width = ui.available_width();
    let gap = ui.spacing().item_spacing;
    // The tallest picture's height per point of width.
    let aspect = handles
        .iter()
        .map(|t| {
            let [tw, th] = t.size().map(|v| v as f32);
            th / tw.max(1.0)
        })
        .fold(0.0f32, f32::max);
    let count = handles.len().max(1);
    // Side (width) of the pictures in `c` columns, limited by `room`.
    let side_in = |c: usize| {
        let rows = count.div_ceil(c) as f32;
        let by_width = width / c as f32 - gap.x;
        let by_height = (room - rows * gap.y) / rows / aspect.max(1e-3);
        by_width.min(by_height).max(0.0)
    };
    let preferred = ((width / MIN_PANEL).floor() as usize).clamp(1, count);
    let columns = if side_in(preferred) >= width / preferred as f32 - gap.x {
        preferred
    } else {
        (1..=count)
            .max_by(|&a, &b| side_in(a).total_cmp(&side_in(b)))
            .unwrap_or(1)
    };
    let side = side_in(columns);
    let picture = |ui: &mut Ui, t: &TextureHandle, side: f32| {
        let [tw, th] = t.size().map(|v| v as f32);
        let size = egui::vec2(side, side * th / tw.max(1.0));
        let r = ui.add(egui::Image::new((t.id(), size)));
        if let Some(text) = hover {
            r.on_hover_text(text);
        }
    };
    if let [first, rest @ ..] = handles
        && let Some([large, small]) = first_beside_two(width, room, gap, aspect, count, side)
    {
        ui.horizontal_top(|ui| {
            picture(ui, first, large);
            ui.vertical(|ui| {
                for t in rest {
                    picture(ui, t, small);
                }
            });
        });
        return;
    }
    for row in handles.chunks(columns) {
        ui.horizontal(|ui| {
            for t in row {
                picture(ui, t, side);
            }
        });
    }
}

/// Sides (widths, points) of the first of three pictures and of the other two stacked beside
/// it in `width` x `room` points (`aspect`: height per point of width; `gap` between them),
/// when that gives the first more than `side` (the grid's side) and the others at least
/// `side`; else `None` (not three pictures, no height limit, or no gain).
fn first_beside_two(
    width: f32,
    room: f32,
    gap: egui::Vec2,
    aspect: f32,
    count: usize,
    side: f32,
) -> Option<[f32; 2]> {
    if count != 3 || !room.is_finite() {
        return None;
    }
    let aspect = aspect.max(1e-3);
    // The stacked two as large as half the room allows, the first the rest of the width.
    let small = (room / 2.0 - gap.y) / aspect;
    let small = small.min((width - 2.0 * gap.x) / 2.0).max(0.0);
    let large = ((room - gap.y) / aspect).min(width - small - 2.0 * gap.x);
    (small >= side - 0.5 && large > (1.0 + LARGER) * side).then_some([large, small])
}

/// How much larger (a fraction) the first picture must get for the first-beside-two layout.
const LARGER: f32 = 0.1;

/// Points: the smallest room the presentation panel gives its pictures (a smaller window
/// scrolls).
const MIN_PICTURE: f32 = 80.0;

/// Points between the presentation panel's lines.
const FIT_SPACING: f32 = 1.0;

/// Points: the side of a probe's colour swatch.
const SWATCH: f32 = 14.0;
/// Points between two swatches.
const SWATCH_GAP: f32 = 2.0;

/// The anisotropic probes' colours as a row of swatches after `line` (each swatch named,
/// with its line, on hover), wrapped to the column.
fn swatches(ui: &mut Ui, lang: Lang, a: &crate::probe::AnisotropicTrace, line: String) {
    ui.horizontal_wrapped(|ui| {
        ui.label(line);
        ui.spacing_mut().item_spacing.x = SWATCH_GAP;
        for (i, p) in a.probes.iter().enumerate() {
            let c = p.color;
            let (rect, response) =
                ui.allocate_exact_size(egui::vec2(SWATCH, SWATCH), Sense::hover());
            ui.painter().rect(
                rect,
                2.0,
                Color32::from_rgba_unmultiplied(c[0], c[1], c[2], c[3]),
                Stroke::new(1.0, Color32::from_gray(160)),
                egui::StrokeKind::Inside,
            );
            response.on_hover_text(lang.tr_with(
                "texel_view.probe",
                &[
                    ("i", &(i + 1)),
                    ("u", &n(p.uv[0])),
                    ("v", &n(p.uv[1])),
                    ("color", &rgba(c)),
                ],
            ));
        }
    });
}

impl crate::app::BaryApp {
    /// Presentation mode, when a texture view is on: a column right of the picture
    /// ([`PRESENT_SHARE`] of the window). In a window narrower than
    /// [`space_view::PRESENT_MIN_ASPECT`](super::space_view::PRESENT_MIN_ASPECT) (a 4:3
    /// projector) the view's numbers stand in for the card, and the picture takes the rest
    /// alone (returns true: the caller draws the canvas only); in a wider one the rest is laid
    /// out as before.
    pub(in crate::app) fn texel_panel_presenting(
        &mut self,
        ui: &mut Ui,
        texture: &Texture,
    ) -> bool {
        let kind = self.state.view.texel;
        if kind == TexelView::Off {
            return false;
        }
        let window = ui.ctx().content_rect();
        let narrow = window.width() < super::space_view::PRESENT_MIN_ASPECT * window.height();
        let report = self.reports.hover.as_ref().or(self.reports.pin.as_ref());
        let output = self.canvas.output.as_ref();
        let view = &mut self.texel_view;
        egui::Panel::right("texel-view-present")
            .frame(
                egui::Frame::new()
                    .fill(crate::app::panels::present::CARD_FILL)
                    .inner_margin(egui::Margin::same(10)),
            )
            .resizable(false)
            .exact_size((PRESENT_SHARE * window.width()).round())
            .show(ui, |ui| view.ui(ui, kind, output, report, texture, true));
        narrow
    }

    /// The texture view as a resizable panel right of the canvas (when one is on).
    pub(in crate::app) fn texel_panel(&mut self, ui: &mut Ui, texture: &Texture) {
        let kind = self.state.view.texel;
        if kind == TexelView::Off {
            return;
        }
        let width = ui.available_width();
        let report = self.reports.hover.as_ref().or(self.reports.pin.as_ref());
        let output = self.canvas.output.as_ref();
        let view = &mut self.texel_view;
        egui::Panel::right("texel-view")
            .resizable(true)
            .default_size(0.4 * width)
            .size_range((0.25 * width)..=(0.7 * width))
            .show(ui, |ui| view.ui(ui, kind, output, report, texture, false));
    }
}
