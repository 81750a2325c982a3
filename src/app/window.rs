//! The native window: eframe runs the app in it until it is closed; a `--screenshot` run
//! reports whether its screenshot was saved.

use std::sync::{Arc, Mutex};

use crate::app::document::persist::{self, STORAGE_KEY, SavedState};
use crate::app::services::screenshot::{self, ShotSlot};
use crate::app::{AppError, AppOptions, BaryApp, SAVE_STATE_FAILED};

/// Default window size in points.
const WINDOW_SIZE: [f32; 2] = [1500.0, 950.0];

/// Opens the window and runs the app until it is closed.
pub fn run(options: AppOptions) -> Result<(), AppError> {
    // The title follows the language once the app runs ([`BaryApp::sync_lang`]).
    let lang = options.lang.unwrap_or(options.system_lang);
    let size = options.window_size.unwrap_or(WINDOW_SIZE);
    let native = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title(lang.tr("app.title"))
            .with_app_id("barylab")
            .with_inner_size(size)
            .with_min_inner_size([800.0, 500.0]),
        persist_window: options.persist,
        // Dithering would add noise to the canvas; its pixels must show exactly.
        dithering: false,
        ..Default::default()
    };
    let screenshot = options.screenshot.clone();
    // Where the app's `--screenshot` reports, read once the window has closed.
    let result_slot: Arc<Mutex<Option<ShotSlot>>> = Arc::new(Mutex::new(None));
    let slot = result_slot.clone();
    eframe::run_native(
        "barylab",
        native,
        Box::new(move |cc| {
            let app = BaryApp::new_with_state_file(cc.storage, options, persist::state_file());
            if let (Some(shot), Ok(mut s)) = (&app.screenshot, slot.lock()) {
                *s = Some(shot.slot());
            }
            Ok(Box::new(app))
        }),
    )
    .map_err(|e| AppError::Window(e.to_string()))?;
    if let Some(path) = screenshot {
        let shot = result_slot.lock().ok().and_then(|s| s.clone());
        screenshot::result_of(shot.as_ref()).map_err(|message| AppError::Screenshot {
            path: path.display().to_string(),
            message,
        })?;
    }
    Ok(())
}

impl eframe::App for BaryApp {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        self.timing.frame_ms = frame.info().cpu_usage.map(|s| s * 1e3);
        self.gpu_view.set_context(frame.gl());
        self.show(ui);
    }

    fn on_exit(&mut self, _gl: Option<&eframe::glow::Context>) {
        // The GL objects go while eframe's context is still current.
        self.gpu_view.release();
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        if self.persist {
            // In a lesson, the user's own state is what is kept.
            let state = self.lessons.user_state().unwrap_or(&self.state);
            let saved = SavedState::capture(state, &self.recent, &self.export.settings, self.lang);
            if let Some(path) = &self.state_file
                && let Err(e) = persist::write_state_file(path, &saved)
            {
                eprintln!("barylab: {SAVE_STATE_FAILED}: {e}");
            }
            eframe::set_value(storage, STORAGE_KEY, &saved);
        }
    }

    fn persist_egui_memory(&self) -> bool {
        self.persist
    }
}
