//! The native window: eframe runs the app in it until it is closed; a `--screenshot` run
//! reports whether its screenshot was saved.

use std::sync::{Arc, Mutex};

use super::screenshot::{self, ShotSlot};
use super::{AppError, AppOptions, BaryApp, persist};

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
