//! `barylab lesson`: list a lesson's steps, print one, write a step's figure, or write the
//! whole lesson as a Markdown handout with its figures.

use std::path::Path;

use anyhow::{Context, Result, bail};
use barylab::files::shown;
use barylab::i18n::Lang;
use barylab::lesson::handout::{self, HandoutFile};
use barylab::lesson::{Lesson, text};

use super::LessonArgs;
use crate::output::{self, print};

/// Runs `barylab lesson`.
pub(super) fn run(args: &LessonArgs) -> Result<()> {
    if let Some(out) = &args.figure {
        output::check_output(out, &["png", "svg"])?;
    }
    if let Some(out) = &args.slides {
        output::check_output(out, &["html", "htm", "pdf"])?;
    }
    let lang = check_font(
        args.lang,
        args.figure.is_some() || args.handout.is_some() || args.slides.is_some(),
    );
    let lesson = Lesson::open(&args.lesson)?;
    let count = lesson.steps.len();
    let step = match args.step {
        Some(n) if n == 0 || n > count => bail!(
            "{}: --step {n}: the lesson has steps 1 to {count}",
            lesson.shown_path()
        ),
        s => s,
    };
    if let Some(dir) = &args.handout {
        return write_handout(&lesson, dir, lang);
    }
    if let Some(out) = &args.slides {
        return super::slides::write(&lesson, out, lang);
    }
    match (step, &args.figure) {
        (Some(n), Some(out)) => write_figure(&lesson, n, out, lang, args.scale),
        (None, Some(_)) => bail!("--figure needs --step N (which step's figure)"),
        (Some(n), None) if !args.list => print(&step_text(&lesson, n, lang)),
        _ => print(&lesson.list(lang)),
    }
}

/// The language asked for; for figures, English when Chinese labels have no font.
pub(super) fn check_font(lang: Lang, figures: bool) -> Lang {
    if figures && lang != Lang::En && barylab::i18n::cjk_font().is_none() {
        eprintln!(
            "warning: no font with Chinese glyphs found (looked for {}); the figures' labels are \
             in English",
            barylab::i18n::CJK_FAMILIES.join(", ")
        );
    }
    lang
}

/// One step as plain text: its title, text and "try this".
fn step_text(lesson: &Lesson, n: usize, lang: Lang) -> String {
    let step = &lesson.steps[n - 1];
    format!(
        "{n}. {}\n\n{}\n\n{} {}\n",
        step.title.get(lang),
        text::plain(step.text.get(lang)),
        barylab::i18n::tr(lang, "lesson.try_this"),
        text::plain(step.try_this.get(lang))
    )
}

/// Writes step `n`'s figure (PNG or SVG by the extension), as `barylab figure` draws it.
fn write_figure(lesson: &Lesson, n: usize, out: &Path, lang: Lang, scale: u32) -> Result<()> {
    use barylab::figure::{png, svg};
    if let Some(barylab::lesson::SceneSource::File(p)) = lesson.scene_of(n - 1).map(|s| &s.source) {
        output::not_an_input(out, std::slice::from_ref(p))?;
    }
    if let Some(p) = &lesson.path {
        output::not_an_input(out, std::slice::from_ref(p))?;
    }
    let fig = handout::step_figure(lesson, n, lang, |o| o.scale = scale)
        .with_context(|| lesson.shown_path())?;
    let svg_out = out
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
    let bytes = if svg_out {
        svg::to_svg(&fig)?.into_bytes()
    } else {
        png::to_png(&fig)?
    };
    barylab::files::write_bytes(out, &bytes)?;
    let [w, h] = fig.pixel_dimensions();
    print(&format!("step {n}: figure {w}x{h} -> {}\n", shown(out)))
}

/// Writes the handout into `dir` (created if needed): every file is made first, then each is
/// moved into place; nothing is written if any of the names is taken.
fn write_handout(lesson: &Lesson, dir: &Path, lang: Lang) -> Result<()> {
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create folder {}", shown(dir)))?;
    barylab::files::check_folder(dir).map_err(anyhow::Error::msg)?;
    let files: Vec<HandoutFile> =
        handout::handout(lesson, lang).with_context(|| lesson.shown_path())?;
    for f in &files {
        let path = dir.join(&f.name);
        if std::fs::symlink_metadata(&path).is_ok() {
            bail!(
                "{} already exists: the handout never overwrites a file (choose an empty folder)",
                shown(&path)
            );
        }
    }
    let staged = files
        .iter()
        .map(|f| barylab::files::stage_bytes(&dir.join(&f.name), &f.bytes))
        .collect::<Result<Vec<_>, _>>()?;
    for s in staged {
        s.commit_new()?;
    }
    print(&format!(
        "handout: {} and {} figures and plots -> {}\n",
        handout::MARKDOWN_NAME,
        files.len() - 1,
        shown(dir)
    ))
}
