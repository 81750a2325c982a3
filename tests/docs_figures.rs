//! The figures in docs/ are what the CLI renders today: re-render each one listed in
//! docs/figures/list.txt with the real binary (`barylab render`, or `barylab figure` when the
//! arguments start with `figure`) and compare pixels with the committed file.

use std::path::Path;
use std::process::Command;

#[test]
fn committed_figures_match_the_cli() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let list = std::fs::read_to_string(root.join("docs/figures/list.txt")).expect("list.txt");
    let dir = tempfile::tempdir().expect("tempdir");
    let mut checked = 0;
    for line in list.lines().map(str::trim) {
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let mut words = line.split_whitespace().peekable();
        let name = words.next().expect("figure name");
        let out = dir.path().join(name);
        let command = if words.next_if_eq(&"figure").is_some() {
            "figure"
        } else {
            "render"
        };
        let status = Command::new(env!("CARGO_BIN_EXE_barylab"))
            .current_dir(root)
            .arg(command)
            .args(words)
            .arg("-o")
            .arg(&out)
            .output()
            .expect("run barylab");
        assert!(
            status.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&status.stderr)
        );
        let fresh = image::open(&out).expect("fresh figure").to_rgba8();
        let committed = image::open(root.join("docs/figures").join(name))
            .unwrap_or_else(|e| panic!("docs/figures/{name}: {e} (run docs/make-figures.sh)"))
            .to_rgba8();
        assert!(
            fresh == committed,
            "docs/figures/{name} is out of date: run docs/make-figures.sh"
        );
        checked += 1;
    }
    assert!(checked >= 5, "only {checked} figures listed");
}
