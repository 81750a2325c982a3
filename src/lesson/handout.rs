//! A lesson as a printable handout: one Markdown file (ready for pandoc) with each step's
//! title, text and "try this", its figure, its row plot (when the step has one: the app's
//! plot, drawn by [`crate::figure::plot`]) and the pinned pixel's derivation from the probe,
//! the figures and plots as PNG files beside it. A step that draws the same figure as an
//! earlier one shows that file again instead of a copy. A lesson with quiz steps also gets
//! a quiz sheet and its answer key ([`super::quiz_sheet`]). Nothing is written here: [`handout`] returns the files
//! and the command line writes them (all or nothing, never over an existing file).

use std::path::Path;

pub use super::sheet::HandoutError;
use super::sheet::{derivation, front_matter};
use super::{Lesson, StepState, text};
use crate::figure::{Figure, png};
use crate::i18n::{Lang, tr};
use crate::probe;
use crate::raster::Texture;

/// One file of a handout: its name in the handout's folder and its bytes.
#[derive(Clone, Debug, PartialEq)]
pub struct HandoutFile {
    /// The file name (no folder).
    pub name: String,
    /// What goes in it.
    pub bytes: Vec<u8>,
}

/// The name of the handout's Markdown file.
pub const MARKDOWN_NAME: &str = "handout.md";

/// The figure file of step `number` (from 1): `step-01.png`, ...
pub fn figure_name(number: usize) -> String {
    format!("step-{number:02}.png")
}

/// The row plot file of step `number` (from 1): `step-01-plot.png`, ...
pub fn plot_name(number: usize) -> String {
    format!("step-{number:02}-plot.png")
}

/// The texture a step's scene draws with.
pub fn texture_of(state: &StepState, step: usize) -> Result<Texture, HandoutError> {
    let dir = state.scene_dir.as_deref().unwrap_or(Path::new(""));
    state
        .scene
        .load_texture(dir)
        .map_err(|error| HandoutError::Scene { step, error })
}

/// The state step `number` (from 1) sets, or [`HandoutError::NoStep`].
pub fn step_state(lesson: &Lesson, number: usize) -> Result<StepState, HandoutError> {
    let count = lesson.steps.len();
    number
        .checked_sub(1)
        .and_then(|i| lesson.state(i))
        .ok_or(HandoutError::NoStep {
            step: number,
            count,
        })
}

/// Step `number`'s figure (from 1), as `barylab figure` draws the same scene and options
/// ([`StepState::figure_options`] with `options` applied), labels in `lang`.
pub fn step_figure(
    lesson: &Lesson,
    number: usize,
    lang: Lang,
    options: impl FnOnce(&mut crate::figure::FigureOptions),
) -> Result<Figure, HandoutError> {
    let state = step_state(lesson, number)?;
    let texture = texture_of(&state, number)?;
    let mut o = state.figure_options();
    options(&mut o);
    Figure::compose_in(&state.scene, &texture, &o, lang).map_err(|error| HandoutError::Figure {
        step: number,
        error,
    })
}

/// A step's pictures as PNG files: its figure and, when it has one, its row plot (with the
/// plot's title). The handout and the slide deck both show these.
pub struct StepPictures {
    /// The step's figure ([`StepState::figure_options`]).
    pub figure: Vec<u8>,
    /// The row plot's title and PNG at [`PLOT_SCALE`].
    pub plot: Option<(String, Vec<u8>)>,
}

/// The pictures of step `number` (from 1) in `state` with `texture`, labels in `lang`.
pub fn step_pictures(
    state: &StepState,
    texture: &Texture,
    number: usize,
    lang: Lang,
) -> Result<StepPictures, HandoutError> {
    let figure_error = |error| HandoutError::Figure {
        step: number,
        error,
    };
    let figure = Figure::compose_in(&state.scene, texture, &state.figure_options(), lang)
        .map_err(figure_error)?;
    let figure = png::to_png(&figure).map_err(figure_error)?;
    let plot = match (state.plot, state.pin) {
        (Some(plot), Some(pin)) => {
            let lines = super::plot::row_plot(&state.scene, texture, pin, plot, lang).map_err(
                |source| HandoutError::Plot {
                    step: number,
                    source,
                },
            )?;
            let bytes = lines.to_png(lang, PLOT_SCALE).map_err(figure_error)?;
            Some((lines.title, bytes))
        }
        _ => None,
    };
    Ok(StepPictures { figure, plot })
}

/// PNG pixels per point of a handout's row plot (sharp in print).
pub const PLOT_SCALE: f32 = 2.0;

/// The handout of `lesson` in `lang`: [`MARKDOWN_NAME`] first, then the figures (one per
/// distinct picture, named after the first step that draws it) and the row plots.
pub fn handout(lesson: &Lesson, lang: Lang) -> Result<Vec<HandoutFile>, HandoutError> {
    let mut md = front_matter(lesson.title.get(lang), lang);
    let mut files = Vec::new();
    // The quiz steps, with their texture and figure, for the quiz sheet and its key.
    let mut quizzes: Vec<(usize, StepState, Texture, String)> = Vec::new();
    for number in 1..=lesson.steps.len() {
        let step = &lesson.steps[number - 1];
        let state = step_state(lesson, number)?;
        let texture = texture_of(&state, number)?;
        let pictures = step_pictures(&state, &texture, number, lang)?;
        let bytes = pictures.figure;
        let name = match files.iter().find(|f: &&HandoutFile| f.bytes == bytes) {
            Some(earlier) => earlier.name.clone(),
            None => {
                let name = figure_name(number);
                files.push(HandoutFile {
                    name: name.clone(),
                    bytes,
                });
                name
            }
        };
        let title = step.title.get(lang);
        md.push_str(&format!(
            "## {number}. {}\n\n",
            text::markdown(title).trim()
        ));
        if let Some(summary) = &step.summary {
            md.push_str(&format!(
                "> {}\n\n",
                text::markdown(summary.get(lang)).trim()
            ));
        }
        md.push_str(&text::markdown(step.text.get(lang)));
        md.push_str(&format!(
            "\n![{}]({name})\n\n",
            text::plain(title).replace(['[', ']'], "")
        ));
        if let Some((title, bytes)) = pictures.plot {
            let name = plot_name(number);
            md.push_str(&format!("![{}]({name})\n\n", title.replace(['[', ']'], "")));
            files.push(HandoutFile { name, bytes });
        }
        md.push_str(&format!(
            "**{}** {}\n",
            tr(lang, "lesson.try_this"),
            text::markdown(step.try_this.get(lang)).trim()
        ));
        if let Some([x, y]) = state.pin {
            let settings = state.scene.settings();
            let trace =
                probe::probe(&state.scene, &texture, &settings, (x, y)).map_err(|error| {
                    HandoutError::Probe {
                        step: number,
                        error,
                    }
                })?;
            md.push_str(&format!(
                "\n### {}\n\n{}\n",
                rust_i18n::t!("lesson.handout_pixel", locale = lang.code(), x = x, y = y),
                derivation(&trace, &state, lang)
            ));
        }
        md.push('\n');
        if state.quiz.is_some() {
            quizzes.push((number, state, texture, name));
        }
    }
    let steps: Vec<super::quiz_sheet::QuizStep<'_>> = quizzes
        .iter()
        .map(
            |(number, state, texture, figure)| super::quiz_sheet::QuizStep {
                number: *number,
                state,
                texture,
                figure,
            },
        )
        .collect();
    if let Some((sheet, key)) = super::quiz_sheet::sheets(lesson, &steps, lang)? {
        files.push(HandoutFile {
            name: super::quiz_sheet::SHEET_NAME.to_string(),
            bytes: sheet.into_bytes(),
        });
        files.push(HandoutFile {
            name: super::quiz_sheet::KEY_NAME.to_string(),
            bytes: key.into_bytes(),
        });
    }
    files.insert(
        0,
        HandoutFile {
            name: MARKDOWN_NAME.to_string(),
            bytes: md.into_bytes(),
        },
    );
    Ok(files)
}
