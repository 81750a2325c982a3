//! Where the frame's commands change the app: [`BaryApp::apply_commands`] takes every panel's
//! [`AppCommand`] of the frame, in order, and [`BaryApp::apply`] carries out each one.

use std::collections::VecDeque;
use std::sync::Arc;

use super::BaryApp;
use super::command::{AppCommand, FileCommand};
use super::document;
use super::panels;
use super::panels::export::ExportContext;
use super::panels::status::{Cause, Message};
use super::side_panels::Side;
use crate::raster::Texture;

impl BaryApp {
    /// Applies this frame's commands, in order: the one place where panels' requests change
    /// the app.
    pub(super) fn apply_commands(&mut self, ctx: &egui::Context, texture: &Arc<Texture>) {
        if self.commands.is_empty() {
            return;
        }
        let before = self.state.clone();
        let space_full = self.space_full;
        let mut others = false;
        let mut queue: VecDeque<AppCommand> = std::mem::take(&mut self.commands).into();
        while let Some(c) = queue.pop_front() {
            others |= !matches!(c, AppCommand::State(_));
            self.apply(ctx, c, texture);
            // What a command queued (opening a file queues the command that applies it) is
            // applied right after it.
            for (k, c) in std::mem::take(&mut self.commands).into_iter().enumerate() {
                queue.insert(k, c);
            }
        }
        if others || self.state != before || self.space_full != space_full {
            // The panels show the change next frame.
            ctx.request_repaint();
        }
    }

    fn apply(&mut self, ctx: &egui::Context, command: AppCommand, texture: &Arc<Texture>) {
        match command {
            AppCommand::State(c) => {
                // The picture comes back for any change (the 3D view is drawn from its render).
                self.space_full = false;
                match c {
                    document::state::StateCommand::Preset(p) => self.last_preset = Some(p),
                    document::state::StateCommand::SetShowControls(true) => {
                        self.panel_first = Side::Controls;
                        self.panel_forced = Some(Side::Controls);
                    }
                    document::state::StateCommand::SetShowInspector(true) => {
                        self.panel_first = Side::Inspector;
                        self.panel_forced = Some(Side::Inspector);
                    }
                    document::state::StateCommand::SetShowControls(false)
                        if self.panel_forced == Some(Side::Controls) =>
                    {
                        self.panel_forced = None;
                    }
                    document::state::StateCommand::SetShowInspector(false)
                        if self.panel_forced == Some(Side::Inspector) =>
                    {
                        self.panel_forced = None;
                    }
                    document::state::StateCommand::SetGpuView(true) => self.compare_image = None,
                    _ => {}
                }
                // A new scene leaves every error about the old one behind.
                let fresh = matches!(
                    c,
                    document::state::StateCommand::Preset(_)
                        | document::state::StateCommand::ResetScene
                        | document::state::StateCommand::ResetAll
                        | document::state::StateCommand::OpenScene(..)
                );
                match self.state.apply(c) {
                    Err(e) => {
                        self.message =
                            Some(Message::error(e.message(self.lang), Some(Cause::Edit)));
                    }
                    Ok(()) if fresh => {
                        if self.message.as_ref().is_some_and(|m| m.error) {
                            self.message = None;
                        }
                    }
                    Ok(()) => panels::status::clear_if(&mut self.message, |c| *c == Cause::Edit),
                }
            }
            AppCommand::Export(c) => {
                let app = ExportContext {
                    state: &self.state,
                    texture,
                    size: self.canvas.output.as_ref().map(|o| o.size),
                    pixel_size: self.canvas.pixel_size,
                    hovered: self.canvas.hover,
                    pixels_per_point: ctx.pixels_per_point(),
                };
                let before = self.export.outcome.clone();
                self.export.apply(ctx, c, &app);
                self.export_message(ctx, before);
            }
            AppCommand::Bench(c) => {
                let rendered = self.canvas.output.as_ref().map(|o| (&o.scene, texture));
                self.bench.apply(ctx, c, rendered);
            }
            AppCommand::Animation(c) => self.apply_animation(ctx, c, texture),
            AppCommand::File(FileCommand::ExportAnimation) => self.animation.open = true,
            AppCommand::File(FileCommand::Open(path)) => self.open_file(&path),
            AppCommand::File(FileCommand::ClearRecent) => self.recent.0.clear(),
            AppCommand::File(FileCommand::DismissBanner) => self.banner = None,
            AppCommand::File(FileCommand::Save) => match self.scene_file.clone() {
                Some(path) => self.save_scene(&path),
                None => self.picker.apply(ctx, &FileCommand::SaveAsDialog),
            },
            AppCommand::File(FileCommand::SaveTo(path)) => self.save_scene(&path),
            AppCommand::File(FileCommand::CompareImage(path)) => self.open_compare_image(&path),
            AppCommand::File(FileCommand::CloseCompareImage) => self.compare_image = None,
            AppCommand::File(FileCommand::SetCompareBackground(c)) => {
                if let Some(ic) = &mut self.compare_image {
                    ic.set_background(c);
                }
            }
            AppCommand::File(c) => self.picker.apply(ctx, &c),
            AppCommand::SetHelpOpen(open) => self.help_open = open,
            AppCommand::ToggleSpanStepping => self.canvas.span_play = !self.canvas.span_play,
            AppCommand::ToggleSpaceFull => self.space_full = !self.space_full,
            AppCommand::SetPresenting(on) => self.presenting = on,
            AppCommand::SetLang(lang) => self.set_lang(lang),
            AppCommand::Undo => {
                self.history.undo(&mut self.state);
            }
            AppCommand::Redo => {
                self.history.redo(&mut self.state);
            }
            AppCommand::Lesson(c) => {
                self.space_full = false;
                self.apply_lesson(ctx, c);
            }
            AppCommand::Quiz(c) => {
                // A quiz is on the picture: it comes back, and stays after the quiz.
                self.space_full = false;
                let step = self.lesson_step();
                self.quiz.apply(c, self.state.view.pinned, step);
            }
        }
    }

    /// The open lesson's step and its quiz, for [`panels::quiz::Quiz::sync`].
    pub(super) fn lesson_quiz(&self) -> Option<(usize, Option<crate::probe::quiz::Question>)> {
        let s = self.lessons.session.as_ref()?;
        let step = s.lesson.steps.get(s.step)?;
        let quiz = step.quiz.as_ref().and_then(|q| {
            Some(crate::probe::quiz::Question {
                pixel: step.quiz_pixel()?,
                ask: q.ask.clone(),
            })
        });
        Some((s.step, quiz))
    }

    /// Puts a new outcome of the Export panel on the status line.
    pub(super) fn export_message(
        &mut self,
        ctx: &egui::Context,
        before: Option<panels::export::Outcome>,
    ) {
        if self.export.outcome != before
            && let Some(o) = &self.export.outcome
        {
            self.message = Some(Message {
                text: o.summary.clone(),
                error: o.error,
                cause: None,
            });
            ctx.request_repaint();
        }
    }
}
