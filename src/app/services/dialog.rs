//! The native file dialogs (File > Open, the Export panel's folder): one at a time per owner,
//! on its own thread (the dialog blocks), polled once per frame.

use std::path::PathBuf;
use std::sync::mpsc::{Receiver, TryRecvError, channel};
use std::time::{Duration, Instant};

/// If the native dialog returns nothing sooner than this, it most likely could not open (no
/// portal, no zenity); nobody picks or cancels that fast.
pub const DIALOG_FAILED_WITHIN: Duration = Duration::from_millis(700);

/// How a dialog ended.
#[derive(Clone, Debug, PartialEq)]
pub enum DialogOutcome {
    /// The user picked this file or folder.
    Picked(PathBuf),
    /// Closed without a choice.
    Cancelled,
    /// It returned nothing at once: it could not open.
    Failed,
}

/// A native dialog that may be running.
#[derive(Default)]
pub struct NativeDialog {
    running: Option<(Receiver<Option<PathBuf>>, Instant)>,
}

impl NativeDialog {
    /// Runs `pick` (which shows the dialog and blocks until it closes) on a thread called
    /// `name`, unless this dialog is already open; `ctx` repaints when it closes. Fails when
    /// the thread cannot start.
    pub fn open(
        &mut self,
        ctx: &egui::Context,
        name: &str,
        pick: impl FnOnce() -> Option<PathBuf> + Send + 'static,
    ) -> std::io::Result<()> {
        if self.running.is_some() {
            return Ok(());
        }
        let (tx, rx) = channel();
        let repaint = ctx.clone();
        std::thread::Builder::new()
            .name(name.into())
            .spawn(move || {
                let _ = tx.send(pick());
                repaint.request_repaint();
            })?;
        self.running = Some((rx, Instant::now()));
        Ok(())
    }

    /// Whether the dialog is open.
    pub fn is_open(&self) -> bool {
        self.running.is_some()
    }

    /// How the dialog ended, once it has.
    pub fn poll(&mut self) -> Option<DialogOutcome> {
        let (rx, started) = self.running.as_ref()?;
        let outcome = match rx.try_recv() {
            Err(TryRecvError::Empty) => return None,
            Ok(Some(path)) => DialogOutcome::Picked(path),
            Ok(None) | Err(TryRecvError::Disconnected) => {
                if started.elapsed() < DIALOG_FAILED_WITHIN {
                    DialogOutcome::Failed
                } else {
                    DialogOutcome::Cancelled
                }
            }
        };
        self.running = None;
        Some(outcome)
    }
}
