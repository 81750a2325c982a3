//! What a lesson's handout ([`super::handout`]) and its quiz sheets ([`super::quiz_sheet`])
//! share: their error, the pinned pixel's derivation in Markdown, pandoc's front matter.

use super::StepState;
use crate::figure::FigureError;
use crate::i18n::Lang;
use crate::probe::format::{Document, document_in};
use crate::probe::{self, PixelTrace};
use crate::scene::SceneError;

/// Why a handout or a step's figure could not be made.
#[derive(Debug, thiserror::Error)]
pub enum HandoutError {
    /// A step's scene's texture could not be read.
    #[error("step {step}: {error}")]
    Scene {
        /// The step, from 1.
        step: usize,
        /// What went wrong (its message is this error's; not a separate source, so a
        /// chain of messages does not print it twice).
        error: SceneError,
    },
    /// A step's figure could not be drawn.
    #[error("step {step}: {error}")]
    Figure {
        /// The step, from 1.
        step: usize,
        /// What went wrong (part of this error's message).
        error: FigureError,
    },
    /// A step's row plot could not be rendered.
    #[error("step {step}: {source}")]
    Plot {
        /// The step, from 1.
        step: usize,
        /// What went wrong.
        source: crate::figure::FigureError,
    },
    /// The pinned pixel could not be probed.
    #[error("step {step}: {error}")]
    Probe {
        /// The step, from 1.
        step: usize,
        /// What went wrong (part of this error's message).
        error: probe::ProbeError,
    },
    /// A step's animation could not be made.
    #[error("step {step}: animation: {error}")]
    Animation {
        /// The step, from 1.
        step: usize,
        /// What went wrong (part of this error's message).
        error: crate::animate::AnimateError,
    },
    /// There is no such step.
    #[error("there is no step {step}: the lesson has steps 1 to {count}")]
    NoStep {
        /// The step asked for, from 1.
        step: usize,
        /// How many steps the lesson has.
        count: usize,
    },
}

/// The pinned pixel's derivation, only the sections the step opens in the inspector (all
/// when it names none), with headings two levels down so they sit under the step's, and the
/// sections numbered from 1 (the probe numbers them in its full derivation).
pub(super) fn derivation(trace: &PixelTrace, state: &StepState, lang: Lang) -> String {
    let full = document_in(trace, lang);
    let detail = trace.detail.is_some();
    let clipped = trace.detail.as_ref().is_some_and(|d| d.clipping.is_some());
    let wanted: Vec<usize> = state
        .inspector
        .iter()
        .filter_map(|s| s.index(detail, clipped))
        .collect();
    let doc = Document {
        title: String::new(),
        sections: full
            .sections
            .into_iter()
            .enumerate()
            .filter(|(i, _)| wanted.is_empty() || wanted.contains(i))
            .map(|(_, s)| s)
            .collect(),
    };
    doc.to_markdown()
        .lines()
        .filter(|l| *l != "# ")
        .scan(0, |section, l| {
            Some(if let Some(heading) = l.strip_prefix("## ") {
                *section += 1;
                // "5. Screen-space weights" -> "1. Screen-space weights".
                let title = heading
                    .split_once(". ")
                    .filter(|(n, _)| n.chars().all(|c| c.is_ascii_digit()))
                    .map_or(heading, |(_, t)| t);
                format!("#### {section}. {title}")
            } else if l.starts_with('#') {
                format!("##{l}")
            } else {
                l.to_string()
            })
        })
        .collect::<Vec<_>>()
        .join("\n")
        .trim()
        .to_string()
}

/// The YAML front matter pandoc reads: the title and the language (`en`, `zh-CN`).
pub(super) fn front_matter(title: &str, lang: Lang) -> String {
    format!(
        "---\ntitle: \"{}\"\nlang: {}\n---\n\n",
        title.replace('"', "\\\""),
        match lang {
            Lang::En => "en",
            Lang::Zh => "zh-CN",
        }
    )
}
