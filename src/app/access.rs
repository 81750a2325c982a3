//! What tests and the binary read of the app, and how they queue commands as the panels do.

use std::path::PathBuf;

use crate::app::BaryApp;
use crate::app::command::AppCommand;
use crate::app::command::ExportCommand;
use crate::app::document::history;
use crate::app::document::state::AppState;
use crate::app::panels::banner::Banner;
use crate::app::panels::bench_panel::BenchPanel;
use crate::app::panels::canvas::CanvasState;
use crate::app::panels::export::ExportPanel;
use crate::app::services::pixel::PixelReport;

impl BaryApp {
    /// The banner's lines (what the last opened file did, or why it did not open).
    pub fn banner(&self) -> Option<Vec<String>> {
        self.banner.as_ref().map(Banner::lines)
    }

    /// The recent files, newest first.
    pub fn recent_files(&self) -> &[PathBuf] {
        &self.recent.0
    }

    /// The Export panel (settings, last outcome).
    pub fn export_panel(&self) -> &ExportPanel {
        &self.export
    }

    /// The Export animation window and the recorder.
    pub fn animation_panel(&self) -> &crate::app::panels::export_animation::AnimationPanel {
        &self.animation
    }

    /// Queues an Export panel command, as its widgets do.
    pub fn push_export(&mut self, command: ExportCommand) {
        self.push(command);
    }

    /// Where the 3D view's panel beside the canvas was laid out last, if it was shown.
    pub fn space_panel_rect(&self) -> Option<egui::Rect> {
        self.space_view.panel_rect
    }

    /// Where the 3D view's drawing was laid out last, if it was drawn.
    pub fn space_drawing_rect(&self) -> Option<egui::Rect> {
        self.space_view.drawing_rect
    }

    /// Where the Lessons panel was laid out last, if it was shown.
    pub fn lesson_panel_rect(&self) -> Option<egui::Rect> {
        self.lessons.panel_rect
    }

    /// Where the magnifier's column beside the canvas was laid out last (outside
    /// presentation mode, for a pinned pixel of several samples).
    pub fn magnifier_rect(&self) -> Option<egui::Rect> {
        self.magnifier_rect
    }

    /// Where the quiz's column was laid out last, while a quiz was going on.
    pub fn quiz_rect(&self) -> Option<egui::Rect> {
        self.quiz.session.as_ref().and(self.quiz.column)
    }

    /// Where the pinned row's plot was drawn last in this context, if one was drawn (in the
    /// Lessons panel or its window).
    pub fn plot_rect(ctx: &egui::Context) -> Option<egui::Rect> {
        crate::app::panels::plots::last_plot_rect(ctx)
    }

    /// The current state (scene and view).
    pub fn state(&self) -> &AppState {
        &self.state
    }

    /// The canvas: views, renders, hovered pixel.
    pub fn canvas(&self) -> &CanvasState {
        &self.canvas
    }

    /// How many probers the inspector has made (one per render and mode it traced).
    pub fn probers_built(&self) -> u64 {
        self.reports.probers_built
    }

    /// The report of the hovered pixel shown in the inspector.
    pub fn hover_report(&self) -> Option<&PixelReport> {
        self.reports.hover.as_ref()
    }

    /// The report of the pinned pixel.
    pub fn pin_report(&self) -> Option<&PixelReport> {
        self.reports.pin.as_ref()
    }

    /// Queues a command, as a panel would; it is applied at the end of the next frame.
    pub fn push(&mut self, command: impl Into<AppCommand>) {
        self.commands.push(command.into());
    }

    /// The benchmark window's state.
    pub fn bench(&self) -> &BenchPanel {
        &self.bench
    }

    /// The benchmark window's state, to change.
    pub fn bench_mut(&mut self) -> &mut BenchPanel {
        &mut self.bench
    }

    /// The undo history.
    pub fn history(&self) -> &history::History {
        &self.history
    }

    /// Whether the app is in presentation mode.
    pub fn presenting(&self) -> bool {
        self.presenting
    }

    /// The message on the status line.
    pub fn message(&self) -> Option<&str> {
        self.message.as_ref().map(|m| m.text.as_str())
    }

    /// The GPU view (its last comparison, or why there is none).
    pub fn gpu_view(&self) -> &crate::app::panels::gpu_view::GpuView {
        &self.gpu_view
    }
}
