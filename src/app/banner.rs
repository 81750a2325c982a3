//! The banner under the top bar: what opening a file did, or why it did not open.

use std::time::{Duration, Instant};

use egui::{Color32, RichText, Ui};

use super::files::{FileCommand, Opened, OpenedFile};

/// User-facing strings of the banner.
pub mod text {
    pub const OPENED: &str = "opened";
    pub const TEXTURE_SET: &str = "is now the texture";
    pub const NOT_OPENED: &str = "not opened; the scene is unchanged";
    pub const NOTE: &str = "note";
    pub const DISMISS: &str = "Dismiss";
}

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
}

/// A success without notes leaves the canvas area after this; errors and notes stay until
/// dismissed.
pub const BANNER_HIDE_AFTER: Duration = Duration::from_secs(6);

impl Banner {
    /// The banner for a file that opened.
    pub fn opened(file: &OpenedFile) -> Self {
        let text = match file.what {
            Opened::Scene { .. } => format!("{} {}", text::OPENED, file.path.display()),
            Opened::Texture { .. } => format!("{} {}", file.path.display(), text::TEXTURE_SET),
        };
        Self {
            text,
            notes: file.notes.clone(),
            error: false,
            shown: Instant::now(),
        }
    }

    /// The banner for a file that did not open (`error` names the file and the problem).
    pub fn failed(error: String) -> Self {
        Self {
            text: format!("{error} — {}", text::NOT_OPENED),
            notes: Vec::new(),
            error: true,
            shown: Instant::now(),
        }
    }

    /// Everything the banner says, one line each (for tests and the status line).
    pub fn lines(&self) -> Vec<String> {
        std::iter::once(self.text.clone())
            .chain(self.notes.iter().map(|n| format!("{}: {n}", text::NOTE)))
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
                if ui.button(text::DISMISS).clicked() {
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
                                RichText::new(format!("{}: {n}", text::NOTE))
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
