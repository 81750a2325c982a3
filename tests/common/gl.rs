//! Mesa's llvmpipe for the conformance tests, one test at a time.

use barylab::gpu as gl;

/// One test at a time talks to Mesa (the environment is set once, before EGL is loaded).
static MESA: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// llvmpipe with the lock that keeps other tests of this binary off Mesa meanwhile; `None`
/// (the test says it skipped) when Mesa's EGL is missing, except under `CI=true`, where that
/// fails the test.
pub fn llvmpipe() -> Option<(std::sync::MutexGuard<'static, ()>, gl::Gpu)> {
    let guard = MESA
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    static ENV: std::sync::Once = std::sync::Once::new();
    ENV.call_once(gl::force_llvmpipe_env);
    match gl::Gpu::new() {
        Ok(lp) => Some((guard, lp)),
        Err(e) if std::env::var("CI").as_deref() == Ok("true") => {
            panic!("llvmpipe is required on CI: {e}")
        }
        Err(e) => {
            eprintln!("skipped: {e}");
            None
        }
    }
}
