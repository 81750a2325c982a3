//! Writing a [`PixelTrace`] as a worked example: plain text, Markdown, LaTeX, or JSON.
//!
//! The derivation is built once, by [`document`], as a [`Document`]: sections of prose and
//! equations whose formulas are small expression trees ([`M`]). Each output format renders
//! that same document, so the three agree line by line. Numbers show 4 significant digits
//! ([`fmt_number`]); JSON keeps full precision.
//!
//! Layout: `numbers` formats numbers, `model` is the document model, `text`,
//! `markdown` and `latex` render it, and `sections/` builds the derivation, one file per
//! step; all user-facing words of the derivation are there. The formatter computes nothing:
//! every number it prints is a field of the trace. The words come from the catalogues
//! `locales/*.yml` ([`crate::i18n`]): [`document_in`] and [`write_in`] take the language.

mod latex;
mod markdown;
mod model;
mod numbers;
mod sections;
#[cfg(test)]
mod tests;
mod text;

pub use model::{Document, Inline, Item, M, Op, Section};
pub use numbers::{OPERAND_DIGITS, SIGNIFICANT_DIGITS, fmt_column, fmt_digits, fmt_number};
pub use sections::{document, document_in, filter_name, mode_name, shading_name, wrap_name};

use super::PixelTrace;
use crate::i18n::Lang;

/// Output formats of `barylab probe`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// A worked example in plain text (UTF-8), one formula per line.
    Text,
    /// The same with `$...$` math, for lecture notes.
    Markdown,
    /// A LaTeX fragment (`align*` environments) for a document with amsmath.
    Latex,
    /// Every value of the trace, full precision (see `docs/probe.md`).
    Json,
}

/// Writes a trace in the given format, in English.
pub fn write(trace: &PixelTrace, format: Format) -> String {
    write_in(trace, format, Lang::En)
}

/// Writes a trace in the given format with the prose in `lang` (text and Markdown; LaTeX is
/// always English, for a plain pdflatex document, and JSON has no prose).
pub fn write_in(trace: &PixelTrace, format: Format, lang: Lang) -> String {
    match format {
        Format::Text => document_in(trace, lang).to_text(),
        Format::Markdown => document_in(trace, lang).to_markdown(),
        Format::Latex => document(trace).to_latex(),
        Format::Json => to_json(trace),
    }
}

/// The trace as pretty-printed JSON.
pub fn to_json(trace: &PixelTrace) -> String {
    let mut s =
        serde_json::to_string_pretty(trace).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"));
    s.push('\n');
    s
}
