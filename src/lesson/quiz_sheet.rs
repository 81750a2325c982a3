//! A lesson's printable quiz: the sheet (each quiz step's question, its figure with the pixel
//! marked, blank answer lines) and the answer key (the answers, the derivation sections they
//! come from, and what each known mistake gives), as two Markdown files beside the handout
//! ([`SHEET_NAME`], [`KEY_NAME`]). Every number is the probe's ([`crate::probe::quiz::key`]).

use super::sheet::{HandoutError, derivation, front_matter};
use super::{InspectorSection, Lesson, StepState, text};
use crate::i18n::Lang;
use crate::probe::quiz::{self, Quantity, TOLERANCE};
use crate::probe::{self as probe_mod, PixelTrace};
use crate::raster::Texture;

/// The quiz sheet's file name.
pub const SHEET_NAME: &str = "quiz.md";
/// The answer key's file name.
pub const KEY_NAME: &str = "quiz-key.md";

/// One quiz step as the handout made it: its number (from 1), state, texture and figure file.
pub struct QuizStep<'a> {
    /// The step, from 1.
    pub number: usize,
    /// What it sets (with its quiz).
    pub state: &'a StepState,
    /// Its scene's texture.
    pub texture: &'a Texture,
    /// The figure file the handout shows for it.
    pub figure: &'a str,
}

/// The derivation sections an answer comes from.
fn sections(q: Quantity) -> &'static [InspectorSection] {
    match q {
        Quantity::ScreenWeights => &[InspectorSection::ScreenWeights],
        Quantity::Weights | Quantity::InvW => &[InspectorSection::Perspective],
        Quantity::Uv => &[InspectorSection::Attribute],
    }
}

/// `r = 0.2500, s = 0.5625, t = 0.1875`.
fn values(q: Quantity, v: &[f64]) -> String {
    q.symbols()
        .iter()
        .zip(v)
        .map(|(s, v)| format!("{s} = {v:.4}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The sheet and the key of `lesson`'s quiz steps in `lang`: `(sheet, key)` Markdown, or
/// `None` when no step has a quiz.
pub fn sheets(
    lesson: &Lesson,
    steps: &[QuizStep<'_>],
    lang: Lang,
) -> Result<Option<(String, String)>, HandoutError> {
    if steps.is_empty() {
        return Ok(None);
    }
    let title = format!(
        "{}: {}",
        lang.tr("quiz.sheet_title"),
        lesson.title.get(lang)
    );
    let mut sheet = front_matter(&title, lang);
    sheet.push_str(&format!("{}\n\n", lang.tr("quiz.sheet_intro")));
    let key_title = format!("{}: {}", lang.tr("quiz.key_title"), lesson.title.get(lang));
    let mut key = front_matter(&key_title, lang);
    let tol = TOLERANCE.to_string();
    key.push_str(&format!(
        "{}\n\n",
        lang.tr_with("quiz.key_intro", &[("tol", &tol)])
    ));
    for (i, s) in steps.iter().enumerate() {
        let Some(q) = &s.state.quiz else { continue };
        let [x, y] = q.pixel;
        let step_title = text::plain(lesson.steps[s.number - 1].title.get(lang));
        let heading = format!(
            "## {}. {}\n\n",
            i + 1,
            lang.tr_with(
                "quiz.sheet_question",
                &[
                    ("n", &s.number),
                    ("title", &step_title),
                    ("x", &x),
                    ("y", &y)
                ]
            )
        );
        sheet.push_str(&heading);
        sheet.push_str(&format!(
            "![{}]({})\n\n",
            step_title.replace(['[', ']'], ""),
            s.figure
        ));
        for a in &q.ask {
            sheet.push_str(&format!("- {}: ", a.name(lang)));
            let blanks: Vec<String> = a
                .symbols()
                .iter()
                .map(|s| format!("{s} = \\_\\_\\_\\_\\_\\_\\_\\_"))
                .collect();
            sheet.push_str(&format!("{}\n", blanks.join(" &nbsp; ")));
        }
        sheet.push('\n');

        let trace: PixelTrace =
            probe_mod::probe(&s.state.scene, s.texture, &s.state.scene.settings(), (x, y))
                .map_err(|error| HandoutError::Probe {
                    step: s.number,
                    error,
                })?;
        key.push_str(&heading);
        match quiz::key(&trace, &q.ask) {
            Err(e) => key.push_str(&format!("{}\n\n", e.message(lang))),
            Ok(expected) => {
                for e in &expected {
                    key.push_str(&format!(
                        "### {}\n\n**{}**\n\n",
                        e.quantity.name(lang),
                        values(e.quantity, &e.values)
                    ));
                    let mut shown: Vec<String> = Vec::new();
                    for (m, v) in e.diagnosable() {
                        let line = lang.tr_with(
                            "quiz.key_mistake",
                            &[("name", &m.name(lang)), ("values", &values(e.quantity, v))],
                        );
                        if !shown.contains(&line) {
                            shown.push(line);
                        }
                    }
                    for line in shown {
                        key.push_str(&format!("- {line}\n"));
                    }
                    key.push('\n');
                }
                let mut state = s.state.clone();
                state.inspector = q.ask.iter().flat_map(|a| sections(*a)).copied().collect();
                state.inspector.dedup();
                key.push_str(&derivation(&trace, &state, lang));
                key.push_str("\n\n");
            }
        }
    }
    Ok(Some((sheet, key)))
}
