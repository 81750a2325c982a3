//! The strip above the canvas while an image is compared: the file, the summary, the worst and
//! first mismatch buttons, the pinned pixel's reason, the size message, and Close.

use egui::{Color32, RichText, Ui};

use super::ImageCompare;
use crate::app::command::AppCommand;
use crate::app::command::FileCommand;
use crate::app::document::state::StateCommand;
use crate::compare::{Comparison, CoverageBy};
use crate::figure::Compare;
use crate::files::shown;
use crate::i18n::Lang;

/// The summary: "N pixels differ in coverage, M in colour; largest colour difference K
/// levels", or that the images agree.
pub fn summary(c: &Comparison, lang: Lang) -> String {
    if c.agrees() {
        return lang.tr_with("compare_image.identical", &[("total", &c.pixels)]);
    }
    lang.tr_with(
        "compare_image.summary",
        &[
            ("coverage", &(c.only_theirs + c.only_ours)),
            ("colour", &c.color_differing),
            ("max", &lang.levels(c.max_color_difference)),
        ],
    )
}

/// The strip above the canvas while an image is compared: the file, the summary, the worst
/// and first mismatch buttons, the pinned pixel's reason, the size message, and Close.
pub fn strip_ui(ui: &mut Ui, ic: &ImageCompare, compare: Compare) -> Vec<AppCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut out = Vec::new();
    let body = ui.text_style_height(&egui::TextStyle::Body);
    let max = (ui.available_height() * 0.3).max(body * 4.0);
    // A solid scroll bar, so that a strip that scrolls shows it does.
    ui.spacing_mut().scroll = egui::style::ScrollStyle::solid();
    egui::ScrollArea::vertical()
        .id_salt("compare-image-strip")
        .max_height(max)
        .auto_shrink([false, true])
        .show(ui, |ui| {
            ui.horizontal_wrapped(|ui| {
                if ui
                    .button(lang.tr("compare_image.close"))
                    .on_hover_text(lang.tr("compare_image.close_tip"))
                    .clicked()
                {
                    out.push(FileCommand::CloseCompareImage.into());
                }
                ui.label(RichText::new(
                    lang.tr_with("compare_image.title", &[("file", &shown(&ic.path))]),
                ))
                .on_hover_text(ic.path.display().to_string());
            });
            if let Some(c) = &ic.comparison {
                ui.horizontal_wrapped(|ui| {
                    out.extend(buttons(ui, ic, c, lang));
                    let color = if c.agrees() {
                        Color32::LIGHT_GREEN
                    } else {
                        Color32::from_rgb(255, 120, 255)
                    };
                    ui.label(RichText::new(summary(c, lang)).strong().color(color));
                });
            }
            if let Some(([x, y], reason)) = &ic.pin_reason {
                let text = match reason {
                    Some(r) => {
                        let r = match r {
                            Ok(r) => r.text(lang),
                            Err(e) => e.clone(),
                        };
                        lang.tr_with(
                            "compare_image.pinned_reason",
                            &[("x", x), ("y", y), ("reason", &r)],
                        )
                    }
                    None => lang.tr_with("compare_image.pinned_agrees", &[("x", x), ("y", y)]),
                };
                ui.add(egui::Label::new(RichText::new(text).strong()).wrap());
            }
            let red = |s: String| egui::Label::new(RichText::new(s).color(Color32::LIGHT_RED));
            if let Some([w, h]) = ic.size_mismatch {
                let [iw, ih] = ic.size();
                ui.horizontal_wrapped(|ui| {
                    ui.add(red(lang.tr_with(
                        "compare_image.wrong_size",
                        &[
                            ("file", &shown(&ic.path)),
                            ("image", &format!("{iw}×{ih}")),
                            ("canvas", &format!("{w}×{h}")),
                        ],
                    )));
                    let set =
                        lang.tr_with("compare_image.set_size", &[("size", &format!("{iw}×{ih}"))]);
                    if ui.button(set).clicked() {
                        out.push(StateCommand::SetImageSize(Some([iw, ih])).into());
                    }
                });
            }
            if ic.deferred {
                ui.label(RichText::new(lang.tr("compare.after_drag")).italics());
            }
            if ic.is_comparing() {
                ui.label(RichText::new(lang.tr("compare_image.comparing")).italics());
            }
            if let Some(e) = &ic.error {
                ui.add(red(e.clone()).wrap());
            }
            if ic.lost {
                let e = lang.tr_with("compare_image.lost", &[("file", &shown(&ic.path))]);
                ui.add(red(e).wrap());
            }
            if let Some(c) = &ic.comparison {
                let by = match c.coverage_by {
                    CoverageBy::Alpha => lang.tr("compare_image.by_alpha"),
                    CoverageBy::Background([r, g, b]) => lang.tr_with(
                        "compare_image.by_background",
                        &[("color", &format!("#{r:02x}{g:02x}{b:02x}"))],
                    ),
                };
                ui.horizontal_wrapped(|ui| {
                    ui.label(RichText::new(by).small());
                    let mut c = match c.coverage_by {
                        CoverageBy::Background(c) => c,
                        CoverageBy::Alpha => [0, 0, 0],
                    };
                    let r = ui
                        .color_edit_button_srgb(&mut c)
                        .on_hover_text(lang.tr("compare_image.background_tip"));
                    if r.changed() {
                        out.push(FileCommand::SetCompareBackground(c).into());
                    }
                });
                if compare == Compare::Difference {
                    legend(ui, lang);
                }
                if let Some(l) = &c.looks_like {
                    ui.add(egui::Label::new(RichText::new(l.text(lang)).italics()).wrap());
                }
            }
        });
    out
}

/// The difference image's colours.
fn legend(ui: &mut Ui, lang: Lang) {
    ui.horizontal_wrapped(|ui| {
        for (c, key) in [
            ([255, 0, 255, 255], "compare_image.legend_only_image"),
            ([0, 255, 255, 255], "compare_image.legend_only_barylab"),
            ([255, 255, 0, 255], "compare_image.legend_colour"),
        ] {
            crate::app::services::style::swatch(ui, c);
            ui.label(RichText::new(lang.tr(key)).small());
        }
    });
}

/// "Worst pixel" and "First mismatch": each pins its pixel.
fn buttons(ui: &mut Ui, ic: &ImageCompare, c: &Comparison, lang: Lang) -> Vec<AppCommand> {
    let worst = ic.view.result.as_ref().and_then(|r| r.diff.worst);
    let first = c.first.first().map(|d| d.pixel);
    let mut out = Vec::new();
    for (p, key, tip) in [
        (worst, "gpu_view.worst", "gpu_view.worst_tip"),
        (first, "compare_image.first", "compare_image.first_tip"),
    ] {
        let r = ui
            .add_enabled(p.is_some(), egui::Button::new(lang.tr(key)))
            .on_hover_text(lang.tr(tip))
            .on_disabled_hover_text(lang.tr("compare_image.no_mismatch"));
        if r.clicked() {
            out.push(StateCommand::Pin(p).into());
        }
    }
    out
}
