//! How far the process's renders have got, for a progress display (the command line's
//! progress line): the renders started so far and the image rows the latest one has drawn of
//! its total. Plain counters the raster driver advances band by band; reading them costs
//! nothing, and nothing waits on them. Renders running at the same time share them (the
//! display is approximate then). A [`Job`] counts one caller's renders alone and can cancel
//! them.

use std::cell::RefCell;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

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

/// A render of `rows` image rows starts (on this thread, in this thread's [`Job`] if any).
pub fn render_started(rows: u32) -> RenderProgress {
    RENDERS.fetch_add(1, Ordering::Relaxed);
    ROWS_DONE.store(0, Ordering::Relaxed);
    ROWS_TOTAL.store(u64::from(rows), Ordering::Relaxed);
    RenderProgress {
        job: CURRENT.with(|c| c.borrow().clone()),
    }
}

/// The counters now.
pub fn now() -> Progress {
    Progress {
        renders: RENDERS.load(Ordering::Relaxed),
        rows_done: ROWS_DONE.load(Ordering::Relaxed),
        rows_total: ROWS_TOTAL.load(Ordering::Relaxed),
    }
}

/// One render job's progress and its cancel flag, shared by the thread that renders and the
/// one that shows it (the app's canvas renders long work on a thread of its own). The raster
/// driver finds the job of the thread that starts a render ([`with_job`]) and checks its flag
/// band by band: a cancelled render stops drawing at its next band (or after a few hundred
/// triangles of a band) and its picture is to be thrown away.
#[derive(Debug, Default)]
pub struct Job {
    cancelled: AtomicBool,
    rows_done: AtomicU64,
    rows_total: AtomicU64,
}

impl Job {
    /// A job that expects to draw `rows_total` image rows in all (every render it makes).
    pub fn new(rows_total: u64) -> Arc<Job> {
        Arc::new(Job {
            rows_total: AtomicU64::new(rows_total),
            ..Job::default()
        })
    }

    /// Asks the job's renders to stop.
    pub fn cancel(&self) {
        self.cancelled.store(true, Ordering::Relaxed);
    }

    /// Whether [`Job::cancel`] was called.
    pub fn is_cancelled(&self) -> bool {
        self.cancelled.load(Ordering::Relaxed)
    }

    /// The share of the expected rows drawn, `rows_done / rows_total` in [0, 1].
    ///
    /// ```
    /// use barylab::progress::Job;
    /// let job = Job::new(200);
    /// barylab::progress::with_job(&job, || {
    ///     let render = barylab::progress::render_started(200);
    ///     render.rows_drawn(50);
    /// });
    /// assert_eq!(job.fraction(), 0.25);
    /// ```
    pub fn fraction(&self) -> f64 {
        Progress {
            renders: 0,
            rows_done: self.rows_done.load(Ordering::Relaxed),
            rows_total: self.rows_total.load(Ordering::Relaxed),
        }
        .fraction()
    }
}

thread_local! {
    /// The job of the renders this thread starts.
    static CURRENT: RefCell<Option<Arc<Job>>> = const { RefCell::new(None) };
}

/// Runs `f` with `job` as the job of every render it starts on this thread.
pub fn with_job<R>(job: &Arc<Job>, f: impl FnOnce() -> R) -> R {
    let before = CURRENT.with(|c| c.replace(Some(job.clone())));
    let result = f();
    CURRENT.with(|c| *c.borrow_mut() = before);
    result
}

/// One render's progress as the raster driver keeps it: the process's counters and the job
/// (if any) of the thread that started the render. Shared by the render's bands.
#[derive(Debug)]
pub struct RenderProgress {
    job: Option<Arc<Job>>,
}

impl RenderProgress {
    /// `rows` more rows of this render are drawn.
    pub fn rows_drawn(&self, rows: u32) {
        ROWS_DONE.fetch_add(u64::from(rows), Ordering::Relaxed);
        if let Some(job) = &self.job {
            job.rows_done.fetch_add(u64::from(rows), Ordering::Relaxed);
        }
    }

    /// Whether the render's job was cancelled (never for a render without a job).
    pub fn cancelled(&self) -> bool {
        self.job.as_ref().is_some_and(|j| j.is_cancelled())
    }
}
