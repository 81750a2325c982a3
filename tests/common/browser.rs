//! Headless Chromium for screenshots of the HTML outputs (slide decks, grade reports).

use std::path::Path;
use std::process::Command;

/// The installed Chromium's command, or `None` (the test says it skipped) when none is
/// installed, except under `CI=true`, where a missing browser fails the test (`.ci/run`
/// installs `chromium`).
pub fn chromium() -> Option<&'static str> {
    let found = ["chromium", "chromium-browser", "google-chrome"]
        .into_iter()
        .find(|b| Command::new(b).arg("--version").output().is_ok());
    if found.is_none() {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "headless Chromium is required on CI (apt package chromium)"
        );
        println!("SKIPPED the screenshot: no headless Chromium installed");
    }
    found
}

/// Opens `url` in headless `browser` at `width` x `height` and writes a PNG to `shot`;
/// returns the browser's stderr when it fails.
pub fn screenshot(
    browser: &str,
    url: &str,
    [width, height]: [u32; 2],
    shot: &Path,
) -> Result<(), String> {
    let run = Command::new(browser)
        .args([
            "--headless",
            "--disable-gpu",
            "--no-sandbox",
            "--hide-scrollbars",
            &format!("--window-size={width},{height}"),
        ])
        .arg(format!("--screenshot={}", shot.display()))
        .arg(url)
        .output()
        .map_err(|e| e.to_string())?;
    if run.status.success() && shot.exists() {
        Ok(())
    } else {
        Err(String::from_utf8_lossy(&run.stderr).into_owned())
    }
}
