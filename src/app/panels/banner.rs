//! The banner under the top bar: what opening a file did, or why it did not open.

use std::time::{Duration, Instant};

use egui::{Color32, RichText, Ui};

use crate::app::command::FileCommand;
use crate::app::services::files::{Opened, OpenedFile};
use crate::i18n::Lang;

/// The message shown under the top bar after opening a file.
#[derive(Clone, Debug, PartialEq)]
pub struct Banner {
    /// One line naming the file and what happened (or the problem).
    pub text: String,
    /// Notes (downscaled image, no uvs, missing MTL ...), one line each.
    pub notes: Vec<String>,
    pub error: bool,
    /// When it appeared (a plain success hides itself after [`BANNER_HIDE_AFTER`]).
    pub shown: Instant,
    /// The language it was written in (its notes' label follows it).
    pub lang: Lang,
}

/// A success without notes leaves the canvas area after this; errors and notes stay until
/// dismissed.
pub const BANNER_HIDE_AFTER: Duration = Duration::from_secs(6);

impl Banner {
    /// The banner for a file that opened.
    pub fn opened(file: &OpenedFile, lang: Lang) -> Self {
        let key = match file.what {
            Opened::Scene { .. } => "app.banner.opened",
            Opened::Texture { .. } => "app.banner.texture_set",
        };
        Self {
            text: lang.tr_with(key, &[("path", &file.path.display())]),
            notes: file.notes.clone(),
            error: false,
            shown: Instant::now(),
            lang,
        }
    }

    /// The banner for a file that did not open (`error` names the file and the problem).
    pub fn failed(error: String, lang: Lang) -> Self {
        Self {
            text: lang.tr_with("app.banner.not_opened", &[("error", &error)]),
            notes: Vec::new(),
            error: true,
            shown: Instant::now(),
            lang,
        }
    }

    /// A notice that is not about a file (such as the missing Chinese font): stays until
    /// dismissed.
    pub fn notice(text: String, lang: Lang) -> Self {
        Self {
            text,
            notes: Vec::new(),
            error: true,
            shown: Instant::now(),
            lang,
        }
    }

    /// Everything the banner says, one line each (for tests and the status line).
    pub fn lines(&self) -> Vec<String> {
        std::iter::once(self.text.clone())
            .chain(
                self.notes
                    .iter()
                    .map(|n| self.lang.tr_with("app.banner.note", &[("note", n)])),
            )
            .collect()
    }
}

/// Hides a plain success banner once it is [`BANNER_HIDE_AFTER`] old.
pub fn expire_banner(ctx: &egui::Context, banner: &mut Option<Banner>) {
    if let Some(b) = banner
        && !b.error
        && b.notes.is_empty()
    {
        let age = b.shown.elapsed();
        if age >= BANNER_HIDE_AFTER {
            *banner = None;
        } else {
            ctx.request_repaint_after(BANNER_HIDE_AFTER - age);
        }
    }
}

/// The banner under the top bar.
pub fn banner_ui(ui: &mut Ui, b: &Banner) -> Vec<FileCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let (fill, stroke) = if b.error {
        (
            Color32::from_rgb(90, 25, 25),
            Color32::from_rgb(255, 120, 120),
        )
    } else {
        (
            Color32::from_rgb(25, 60, 35),
            Color32::from_rgb(120, 220, 140),
        )
    };
    let mut out = Vec::new();
    egui::Frame::new()
        .fill(fill)
        .stroke(egui::Stroke::new(1.0, stroke))
        .inner_margin(egui::Margin::symmetric(10, 6))
        .corner_radius(4.0)
        .show(ui, |ui| {
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Min), |ui| {
                if ui.button(lang.tr("app.banner.dismiss")).clicked() {
                    out.push(FileCommand::DismissBanner);
                }
                ui.vertical(|ui| {
                    ui.add(
                        egui::Label::new(RichText::new(&b.text).color(Color32::WHITE).strong())
                            .wrap(),
                    );
                    for n in &b.notes {
                        ui.add(
                            egui::Label::new(
                                RichText::new(lang.tr_with("app.banner.note", &[("note", n)]))
                                    .color(Color32::from_rgb(255, 215, 120)),
                            )
                            .wrap(),
                        );
                    }
                });
            });
        });
    out
}
