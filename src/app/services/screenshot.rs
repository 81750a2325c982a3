//! Screenshots of the window: `barylab --screenshot FILE` (the first settled frame, then the
//! app exits) and the Export panel's "Screenshot window". One way to ask egui for the image
//! and wait for it, one PNG encoder.

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// User-facing strings of screenshots.
mod text {
    pub const TIMEOUT: &str = "no screenshot arrived in time";
    pub const NEVER_TAKEN: &str = "the window closed before the screenshot was taken";
}

/// Where a screenshot's callback reports: `None` until the image was written (or not).
pub type ShotSlot = Arc<Mutex<Option<Result<(), String>>>>;

/// Asks egui for a screenshot of this frame; `write` stores the image, its result lands in
/// `slot`, and the app repaints to see it.
pub fn request(
    ctx: &egui::Context,
    slot: &ShotSlot,
    write: impl FnOnce(&egui::ColorImage) -> Result<(), String> + Send + 'static,
) {
    let (report, repaint) = (slot.clone(), ctx.clone());
    ctx.request_screenshot(move |image| {
        let r = write(&image);
        if let Ok(mut s) = report.lock() {
            *s = Some(r);
        }
        repaint.request_repaint();
    });
}

/// The result in `slot`; an error once `started` is more than `timeout` ago without one (a
/// backend without screenshots never calls back).
pub fn outcome(slot: &ShotSlot, started: Instant, timeout: Duration) -> Option<Result<(), String>> {
    let done = slot.lock().ok().and_then(|s| s.clone());
    if done.is_none() && started.elapsed() > timeout {
        return Some(Err(text::TIMEOUT.to_string()));
    }
    done
}

/// A screenshot as PNG bytes.
pub fn png_bytes(image: &egui::ColorImage) -> Result<Vec<u8>, String> {
    let [w, h] = image.size;
    let mut out = image::RgbaImage::new(w as u32, h as u32);
    for (px, c) in out.pixels_mut().zip(&image.pixels) {
        px.0 = c.to_srgba_unmultiplied();
    }
    let mut bytes = Vec::new();
    out.write_to(
        &mut std::io::Cursor::new(&mut bytes),
        image::ImageFormat::Png,
    )
    .map_err(|e| e.to_string())?;
    Ok(bytes)
}

/// Frames to draw before taking the `--screenshot`, so fonts, layout and the canvas texture
/// have settled.
const STARTUP_AFTER_FRAMES: u32 = 5;
/// Give up on the `--screenshot` after this long.
const STARTUP_TIMEOUT: Duration = Duration::from_secs(30);

/// The `--screenshot` run: waits for a few rendered frames, saves the window as PNG (over an
/// existing file), then closes the window.
pub struct StartupShot {
    path: PathBuf,
    frames: u32,
    requested: bool,
    started: Instant,
    result: ShotSlot,
}

impl StartupShot {
    pub fn new(path: PathBuf) -> Self {
        Self {
            path,
            frames: 0,
            requested: false,
            started: Instant::now(),
            result: Arc::new(Mutex::new(None)),
        }
    }

    /// Where the result lands (read by [`result_of`] after the window closed).
    pub fn slot(&self) -> ShotSlot {
        self.result.clone()
    }

    /// Once per frame, at its end: counts frames with a rendered canvas, asks for the shot,
    /// closes the window once it is written (or failed, or timed out).
    pub fn step(&mut self, ctx: &egui::Context, rendered: bool) {
        ctx.request_repaint();
        if let Some(r) = outcome(&self.result, self.started, STARTUP_TIMEOUT) {
            if let Ok(mut slot) = self.result.lock() {
                *slot = Some(r);
            }
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
            return;
        }
        if rendered {
            self.frames += 1;
        }
        if self.frames >= STARTUP_AFTER_FRAMES && !self.requested {
            self.requested = true;
            let path = self.path.clone();
            request(ctx, &self.result, move |image| save(image, &path));
        }
    }
}

/// Writes a screenshot as PNG, replacing the file.
fn save(image: &egui::ColorImage, path: &Path) -> Result<(), String> {
    let bytes = png_bytes(image)?;
    crate::files::write_bytes(path, &bytes).map_err(|e| e.to_string())
}

/// What became of a `--screenshot` once the window has closed.
pub fn result_of(slot: Option<&ShotSlot>) -> Result<(), String> {
    match slot.and_then(|s| s.lock().ok().and_then(|r| r.clone())) {
        Some(r) => r,
        None => Err(text::NEVER_TAKEN.into()),
    }
}
