//! The Export animation window's widgets ([`super::export_animation`] has its state): they
//! return commands, like every panel.

use egui::{Color32, RichText, Ui};

use crate::animate::{Format, Sweep};
use crate::app::command::{AnimationCommand, AnimationKind, AppCommand, ExportCommand};
use crate::app::panels::export::Outcome;
use crate::app::services::recorder::{RECORD_FPS, Recorder};
use crate::figure::{Background, SCALES};
use crate::i18n::Lang;

/// Frames of a sweep the slider offers (the command line goes to 1000).
const SWEEP_FRAMES: (u32, u32) = (2, 240);

/// Frames per second the slider offers.
pub(super) const FPS_RANGE: (u32, u32) = (1, 50);

/// The catalogue key of a sweep's label.
fn sweep_key(sweep: Sweep) -> String {
    format!("animate.sweep.{}", sweep.name().replace('-', "_"))
}

/// What the window shows (the Export animation panel's state, as of this frame).
pub(crate) struct WindowView<'a> {
    /// A sweep or the recording.
    pub kind: AnimationKind,
    /// The sweep.
    pub sweep: Sweep,
    /// The corner the depth and clip sweeps move.
    pub vertex: usize,
    /// Frames of a sweep.
    pub frames: u32,
    /// Frames per second.
    pub fps: u32,
    /// The file format.
    pub format: Format,
    /// The label language (`None`: the app's).
    pub lang: Option<Lang>,
    /// Whether ffmpeg runs.
    pub ffmpeg: bool,
    /// The recording.
    pub recorder: &'a Recorder,
    /// The export going on: frames drawn, frames to draw.
    pub progress: Option<(usize, usize)>,
    /// What the last export did.
    pub outcome: Option<&'a Outcome>,
    /// The Export window's settings (scale, background, caption, folder).
    pub settings: &'a crate::app::document::export_settings::ExportSettings,
    /// The pinned pixel.
    pub pinned: Option<[u32; 2]>,
    /// The canvas's render size.
    pub size: Option<[u32; 2]>,
    /// Whether a CJK font is installed.
    pub cjk: bool,
}

/// The corners the depth and clip sweeps offer.
const CORNERS: usize = 4;

/// The window's contents.
pub(crate) fn contents(
    ui: &mut Ui,
    view: &WindowView<'_>,
    folder_text: &mut String,
    out: &mut Vec<AppCommand>,
) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let panel = view;
    egui::Grid::new("animation-grid")
        .num_columns(2)
        .spacing([12.0, 6.0])
        .show(ui, |ui| {
            ui.label(lang.tr("animate.app.what"));
            ui.horizontal_wrapped(|ui| {
                for (k, key) in [
                    (AnimationKind::Sweep, "animate.app.kind_sweep"),
                    (AnimationKind::Recording, "animate.app.kind_recording"),
                ] {
                    if ui.selectable_label(panel.kind == k, lang.tr(key)).clicked() {
                        out.push(AnimationCommand::SetKind(k).into());
                    }
                }
            });
            ui.end_row();
            match panel.kind {
                AnimationKind::Sweep => sweep_rows(ui, view, lang, out),
                AnimationKind::Recording => recording_rows(ui, view, lang, out),
            }
            let mut fps = panel.fps;
            let label = ui.label(lang.tr("animate.app.fps"));
            if slider(ui, &mut fps, FPS_RANGE.0..=FPS_RANGE.1, label.id) {
                out.push(AnimationCommand::SetFps(fps).into());
            }
            ui.end_row();

            ui.label(lang.tr("animate.app.format"));
            ui.horizontal_wrapped(|ui| {
                let ffmpeg = panel.ffmpeg;
                for f in [Format::Gif, Format::Apng, Format::WebP, Format::Mp4] {
                    let enabled = f != Format::Mp4 || ffmpeg;
                    let r = ui
                        .add_enabled(
                            enabled,
                            egui::Button::selectable(panel.format == f, f.name()),
                        )
                        .on_disabled_hover_text(lang.tr("animate.app.no_ffmpeg"));
                    if r.clicked() {
                        out.push(AnimationCommand::SetFormat(f).into());
                    }
                }
            });
            ui.end_row();

            ui.label(lang.tr("app.export.scale"))
                .on_hover_text(lang.tr("app.export.scale_tip"));
            ui.horizontal(|ui| {
                for k in SCALES {
                    if ui
                        .selectable_label(view.settings.scale == k, format!("{k}x"))
                        .clicked()
                    {
                        out.push(ExportCommand::SetScale(k).into());
                    }
                }
                if let Some([w, h]) = view.size {
                    ui.label(
                        RichText::new(lang.tr_with("animate.app.image", &[("w", &w), ("h", &h)]))
                            .weak(),
                    );
                }
            });
            ui.end_row();

            ui.label(lang.tr("app.export.background"));
            ui.horizontal_wrapped(|ui| {
                for (b, key) in [
                    (Background::White, "app.export.white"),
                    (Background::Transparent, "app.export.transparent"),
                ] {
                    if ui
                        .selectable_label(view.settings.background == b, lang.tr(key))
                        .clicked()
                    {
                        out.push(ExportCommand::SetBackground(b).into());
                    }
                }
            });
            ui.end_row();

            ui.label(lang.tr("animate.app.labels"));
            ui.horizontal_wrapped(|ui| {
                let choices = [
                    (None, lang.tr("animate.app.labels_app")),
                    (Some(Lang::En), "English".to_string()),
                    (Some(Lang::Zh), "中文".to_string()),
                ];
                for (l, label) in choices {
                    let enabled = l != Some(Lang::Zh) || view.cjk;
                    let r =
                        ui.add_enabled(enabled, egui::Button::selectable(panel.lang == l, label));
                    if r.clicked() {
                        out.push(AnimationCommand::SetLang(l).into());
                    }
                }
            });
            ui.end_row();

            ui.label(lang.tr("animate.app.pinned"));
            ui.label(match view.pinned {
                Some([x, y]) => format!("({x}, {y})"),
                None => lang.tr("animate.app.no_pin"),
            });
            ui.end_row();

            let mut folder = Vec::new();
            super::export::folder_row(ui, folder_text, 180.0, &mut folder);
            out.extend(folder.into_iter().map(AppCommand::from));
        });
    let mut caption = view.settings.caption;
    ui.checkbox(&mut caption, lang.tr("figure.caption.option"))
        .on_hover_text(lang.tr("figure.caption.option_tip"));
    if caption != view.settings.caption {
        out.push(ExportCommand::SetCaption(caption).into());
    }
}

/// Export (or the progress bar and Cancel) and what the last export did: above the settings,
/// so that they stay in view when the settings scroll.
pub(crate) fn actions(ui: &mut Ui, view: &WindowView<'_>, out: &mut Vec<AppCommand>) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    buttons(ui, view, lang, out);
    if let Some(o) = &view.outcome {
        super::export::outcome_lines(ui, o);
    }
    ui.separator();
}

/// Export, or the progress bar and Cancel while exporting.
fn buttons(ui: &mut Ui, view: &WindowView<'_>, lang: Lang, out: &mut Vec<AppCommand>) {
    let panel = view;
    match panel.progress {
        Some((done, total)) => {
            ui.horizontal(|ui| {
                let f = done as f32 / total.max(1) as f32;
                ui.add(
                    egui::ProgressBar::new(f).desired_width(200.0).text(
                        lang.tr_with("animate.app.progress", &[("done", &done), ("n", &total)]),
                    ),
                );
                if ui.button(lang.tr("animate.app.cancel")).clicked() {
                    out.push(AnimationCommand::Cancel.into());
                }
            });
        }
        None => {
            let ready = !panel.recorder.recording();
            if ui
                .add_enabled(
                    ready,
                    egui::Button::new(RichText::new(lang.tr("animate.app.export")).strong()),
                )
                .on_hover_text(lang.tr("animate.app.export_tip"))
                .clicked()
            {
                out.push(AnimationCommand::Export.into());
            }
        }
    }
}

/// The sweep, its corner and its frames.
fn sweep_rows(ui: &mut Ui, view: &WindowView<'_>, lang: Lang, out: &mut Vec<AppCommand>) {
    let panel = view;
    let label = ui.label(lang.tr("animate.app.sweep"));
    egui::ComboBox::from_id_salt("animation-sweep")
        .selected_text(lang.tr(&sweep_key(panel.sweep)))
        .width(220.0)
        .show_ui(ui, |ui| {
            for s in Sweep::ALL {
                if ui
                    .selectable_label(panel.sweep == s, lang.tr(&sweep_key(s)))
                    .on_hover_text(s.name())
                    .clicked()
                {
                    out.push(AnimationCommand::SetSweep(s).into());
                }
            }
        })
        .response
        .labelled_by(label.id);
    ui.end_row();
    if panel.sweep.moves_vertex() {
        ui.label(lang.tr("animate.app.corner"));
        ui.horizontal(|ui| {
            for v in 0..CORNERS {
                let name = crate::scene::vertex_name(v);
                if ui.selectable_label(panel.vertex == v, name).clicked() {
                    out.push(AnimationCommand::SetVertex(v).into());
                }
            }
        });
        ui.end_row();
    }
    let mut frames = panel.frames;
    let label = ui.label(lang.tr("animate.app.frames"));
    if slider(ui, &mut frames, SWEEP_FRAMES.0..=SWEEP_FRAMES.1, label.id) {
        out.push(AnimationCommand::SetFrames(frames).into());
    }
    ui.end_row();
}

/// Record / Stop, what is recorded, and the trim.
fn recording_rows(ui: &mut Ui, view: &WindowView<'_>, lang: Lang, out: &mut Vec<AppCommand>) {
    let r = view.recorder;
    let seconds = |n: usize| format!("{:.1}", n as f64 / RECORD_FPS);
    ui.label(lang.tr("animate.app.recording"));
    ui.horizontal_wrapped(|ui| {
        let (key, color) = if r.recording() {
            ("animate.app.stop", Color32::from_rgb(255, 120, 110))
        } else {
            ("animate.app.record", Color32::from_rgb(230, 80, 70))
        };
        if ui
            .button(RichText::new(lang.tr(key)).color(color).strong())
            .on_hover_text(lang.tr("animate.app.record_tip"))
            .clicked()
        {
            out.push(AnimationCommand::ToggleRecord.into());
        }
        let n = r.len();
        let status = if r.recording() {
            lang.tr_with(
                "animate.app.recording_now",
                &[("n", &n), ("seconds", &seconds(n))],
            )
        } else if r.is_empty() {
            lang.tr("animate.app.nothing_recorded")
        } else {
            lang.tr_with(
                "animate.app.recorded",
                &[("n", &n), ("seconds", &seconds(n))],
            )
        };
        ui.label(status);
    });
    ui.end_row();
    if r.recording() || r.len() < 2 {
        return;
    }
    let last = r.len() - 1;
    let (mut a, mut b) = r.trim;
    let label = ui.label(lang.tr("animate.app.first"));
    let first = slider(ui, &mut a, 0..=last, label.id);
    ui.end_row();
    let label = ui.label(lang.tr("animate.app.last"));
    let second = slider(ui, &mut b, 0..=last, label.id);
    ui.end_row();
    if first || second {
        out.push(AnimationCommand::SetTrim(a.min(b), b.max(a)).into());
    }
    let kept = b.saturating_sub(a) + 1;
    let playing = format!("{:.1}", kept as f64 / f64::from(view.fps.max(1)));
    ui.label("");
    ui.label(
        RichText::new(lang.tr_with("animate.app.kept", &[("n", &kept), ("seconds", &playing)]))
            .weak(),
    );
    ui.end_row();
}

/// A slider named by the grid's `label`, its value beside it; whether it changed.
fn slider<T: egui::emath::Numeric + std::fmt::Display>(
    ui: &mut Ui,
    value: &mut T,
    range: std::ops::RangeInclusive<T>,
    label: egui::Id,
) -> bool {
    ui.horizontal(|ui| {
        let r = ui
            .add(egui::Slider::new(value, range).show_value(false))
            .labelled_by(label);
        ui.label(value.to_string());
        r.changed()
    })
    .inner
}
