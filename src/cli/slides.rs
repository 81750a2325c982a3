//! `barylab lesson FILE --slides OUT`: the lesson as a self-contained HTML slide deck, or as a
//! Beamer PDF through pandoc and LaTeX.

use std::path::Path;
use std::process::Command;

use anyhow::{Context, Result, bail};
use barylab::files::shown;
use barylab::i18n::Lang;
use barylab::lesson::{Lesson, slides};

use crate::output::{self, print};

/// Writes the deck: HTML, or PDF by the extension.
pub(super) fn write(lesson: &Lesson, out: &Path, lang: Lang) -> Result<()> {
    if let Some(p) = &lesson.path {
        output::not_an_input(out, std::slice::from_ref(p))?;
    }
    let pdf = out
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("pdf"));
    if pdf {
        return write_pdf(lesson, out, lang);
    }
    let html = slides::html(lesson, lang).with_context(|| lesson.shown_path())?;
    barylab::files::write_bytes(out, html.as_bytes())?;
    print(&format!(
        "slides: {} steps, {:.1} MiB of HTML (figures inline) -> {}\n",
        lesson.steps.len(),
        html.len() as f64 / (1024.0 * 1024.0),
        shown(out)
    ))
}

/// Whether `program` runs (`program --version`).
fn runs(program: &str) -> bool {
    Command::new(program)
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// Whether LaTeX finds `file` (`kpsewhich`).
fn latex_has(file: &str) -> bool {
    Command::new("kpsewhich")
        .arg(file)
        .output()
        .is_ok_and(|o| o.status.success() && !o.stdout.is_empty())
}

/// The Beamer PDF: the deck's Markdown and pictures in a temporary folder, `pandoc -t beamer`
/// with pdflatex (Chinese: xelatex with ctex), the PDF copied into place.
fn write_pdf(lesson: &Lesson, out: &Path, lang: Lang) -> Result<()> {
    let engine = match lang {
        Lang::En => "pdflatex",
        Lang::Zh => "xelatex",
    };
    if !runs("pandoc") {
        bail!(
            "{}: a PDF deck needs pandoc, which is not installed (install pandoc, or write \
             --slides deck.html)",
            shown(out)
        );
    }
    if !runs(engine) || !latex_has("beamer.cls") || (lang == Lang::Zh && !latex_has("ctex.sty")) {
        let what = match lang {
            Lang::En => "pdflatex and LaTeX's beamer class (Debian: texlive-latex-recommended)",
            Lang::Zh => {
                "xelatex, LaTeX's beamer class and ctex (Debian: texlive-xetex, \
                 texlive-latex-recommended, texlive-lang-chinese)"
            }
        };
        bail!(
            "{}: a PDF deck needs {what}, which is not installed; write --slides deck.html \
             instead",
            shown(out)
        );
    }
    let files = slides::beamer(lesson, lang).with_context(|| lesson.shown_path())?;
    let dir = tempfile::tempdir().context("cannot make a temporary folder")?;
    for f in &files {
        std::fs::write(dir.path().join(&f.name), &f.bytes)
            .with_context(|| format!("cannot write {} in a temporary folder", f.name))?;
    }
    let mut cmd = Command::new("pandoc");
    cmd.current_dir(dir.path())
        .args([slides::BEAMER_MARKDOWN, "-t", "beamer", "--slide-level=2"])
        .args(["--pdf-engine", engine, "-o", "slides.pdf"]);
    if lang == Lang::Zh {
        cmd.args(["-V", "documentclass=ctexbeamer"]);
    }
    let result = cmd.output().context("cannot run pandoc")?;
    if !result.status.success() {
        let msg = String::from_utf8_lossy(&result.stderr);
        bail!(
            "{}: pandoc could not make the PDF: {}",
            shown(out),
            msg.lines()
                .find(|l| !l.trim().is_empty())
                .unwrap_or("no message")
        );
    }
    let pdf = std::fs::read(dir.path().join("slides.pdf")).context("pandoc wrote no PDF")?;
    barylab::files::write_bytes(out, &pdf)?;
    print(&format!(
        "slides: {} steps, Beamer PDF ({:.1} MiB) -> {}\n",
        lesson.steps.len(),
        pdf.len() as f64 / (1024.0 * 1024.0),
        shown(out)
    ))
}
