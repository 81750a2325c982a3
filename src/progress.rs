//! How far the process's renders have got, for a progress display (the command line's
//! progress line): the renders started so far and the image rows the latest one has drawn of
//! its total. Plain counters the raster driver advances band by band; reading them costs
//! nothing, and nothing waits on them. Renders running at the same time share them (the
//! display is approximate then).

use std::sync::atomic::{AtomicU64, Ordering};

/// Renders started in this process.
static RENDERS: AtomicU64 = AtomicU64::new(0);
/// Rows of the latest render drawn so far.
static ROWS_DONE: AtomicU64 = AtomicU64::new(0);
/// Rows of the latest render.
static ROWS_TOTAL: AtomicU64 = AtomicU64::new(0);

/// A snapshot of the counters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Progress {
    /// Renders started so far.
    pub renders: u64,
    /// Rows of the latest render drawn so far.
    pub rows_done: u64,
    /// Rows of the latest render.
    pub rows_total: u64,
}

impl Progress {
    /// The share of the latest render drawn, `rows_done / rows_total` in [0, 1] (0 before
    /// any render).
    ///
    /// ```
    /// use barylab::progress::Progress;
    /// let p = Progress { renders: 1, rows_done: 30, rows_total: 120 };
    /// assert_eq!(p.fraction(), 0.25);
    /// ```
    pub fn fraction(&self) -> f64 {
        if self.rows_total == 0 {
            0.0
        } else {
            (self.rows_done as f64 / self.rows_total as f64).min(1.0)
        }
    }
}

/// A render of `rows` image rows starts.
pub fn render_started(rows: u32) {
    RENDERS.fetch_add(1, Ordering::Relaxed);
    ROWS_DONE.store(0, Ordering::Relaxed);
    ROWS_TOTAL.store(u64::from(rows), Ordering::Relaxed);
}

/// `rows` more rows of the latest render are drawn.
pub fn rows_drawn(rows: u32) {
    ROWS_DONE.fetch_add(u64::from(rows), Ordering::Relaxed);
}

/// The counters now.
pub fn now() -> Progress {
    Progress {
        renders: RENDERS.load(Ordering::Relaxed),
        rows_done: ROWS_DONE.load(Ordering::Relaxed),
        rows_total: ROWS_TOTAL.load(Ordering::Relaxed),
    }
}
