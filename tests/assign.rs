//! `barylab assign`: a variant of the course scene per student (distinct, the same again for
//! the same roster and number), each with its scene file, a task sheet in both languages and
//! an answer key; `barylab grade --roster` compares each student's image with their own
//! variant, so a student's own render passes and a classmate's copied image fails.

use std::path::Path;
use std::process::Command;

fn barylab(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args(args)
        .output()
        .expect("run barylab")
}

fn s(p: &Path) -> &str {
    p.to_str().expect("utf-8 path")
}

fn assign(roster: &Path, number: &str, out: &Path) {
    let o = barylab(&[
        "assign",
        "--students",
        s(roster),
        "--number",
        number,
        "--out",
        s(out),
    ]);
    assert!(
        o.status.success(),
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

#[test]
fn variants_are_distinct_and_grade_matches_each_student_with_their_own() {
    let dir = tempfile::tempdir().expect("tempdir");
    let roster = dir.path().join("roster.csv");
    std::fs::write(
        &roster,
        "student,name\nalice,Alice A\nbob,Bob B\ncarol,Carol C\n",
    )
    .expect("roster");
    let out = dir.path().join("variants");
    assign(&roster, "7", &out);
    let students = ["alice", "bob", "carol"];
    let mut scenes = Vec::new();
    for st in students {
        let d = out.join(st);
        for f in ["scene.json", "task.md", "answer.png", "answer.md"] {
            assert!(d.join(f).is_file(), "{st}/{f}");
        }
        let task = read(&d.join("task.md"));
        assert!(task.contains(&format!("## Task for {st}")), "{task}");
        assert!(task.contains(&format!("## {st} 的作业")), "{task}");
        let key = read(&d.join("answer.md"));
        // Three marked pixels, each a table row with r s t, a b c, 1/W_P, W_P and uv, in
        // both languages.
        assert_eq!(
            key.lines().filter(|l| l.starts_with("| (")).count(),
            6,
            "{key}"
        );
        assert!(
            key.contains("参考答案") && key.contains("Answer key"),
            "{key}"
        );
        let scene = read(&d.join("scene.json"));
        let png = image::open(d.join("answer.png")).expect("png");
        assert_eq!((png.width(), png.height()), (800, 600));
        scenes.push(scene);
    }
    assert!(scenes[0] != scenes[1] && scenes[1] != scenes[2] && scenes[0] != scenes[2]);
    // The same roster and number give the same variants; another number others.
    let again = dir.path().join("again");
    assign(&roster, "7", &again);
    assert_eq!(read(&again.join("alice/scene.json")), scenes[0]);
    let other = dir.path().join("other");
    assign(&roster, "8", &other);
    assert_ne!(read(&other.join("alice/scene.json")), scenes[0]);
    // An existing, non-empty folder is refused.
    let o = barylab(&[
        "assign",
        "--students",
        s(&roster),
        "--number",
        "7",
        "--out",
        s(&out),
    ]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("not empty"));

    // alice hands in her own answer, bob copies alice's, carol hands in nothing.
    let subs = dir.path().join("homework");
    std::fs::create_dir(&subs).expect("folder");
    std::fs::copy(out.join("alice/answer.png"), subs.join("alice.png")).expect("copy");
    std::fs::copy(out.join("alice/answer.png"), subs.join("bob.png")).expect("copy");
    let csv = dir.path().join("grades.csv");
    let o = barylab(&[
        "grade",
        "--roster",
        s(&out.join("roster.csv")),
        "--submissions",
        s(&subs),
        "--report",
        s(&dir.path().join("report.html")),
        "--csv",
        s(&csv),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = read(&csv);
    let row = |st: &str| {
        text.lines()
            .find(|l| l.starts_with(&format!("\"{st}\",")))
            .unwrap_or_else(|| panic!("no row for {st}: {text}"))
            .to_string()
    };
    assert!(
        row("alice").starts_with("\"alice\",\"alice\",\"pass\","),
        "{text}"
    );
    assert!(
        row("bob").starts_with("\"bob\",\"bob\",\"fail\","),
        "{text}"
    );
    assert!(
        row("carol").starts_with("\"carol\",\"carol\",\"bad\","),
        "{text}"
    );
    assert!(row("carol").contains("no image"), "{text}");
}

#[test]
fn a_roster_line_that_cannot_name_a_folder_is_refused() {
    let dir = tempfile::tempdir().expect("tempdir");
    let roster = dir.path().join("roster.csv");
    std::fs::write(&roster, "alice\n../evil\n").expect("roster");
    let o = barylab(&[
        "assign",
        "--students",
        s(&roster),
        "--number",
        "1",
        "--out",
        s(&dir.path().join("v")),
    ]);
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("line 2") && err.contains("cannot name a folder"),
        "{err}"
    );
    assert!(!dir.path().join("v").exists());
}
