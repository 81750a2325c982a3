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
//! every number it prints is a field of the trace.

mod latex;
mod markdown;
mod model;
mod numbers;
mod sections;
#[cfg(test)]
mod tests;
mod text;

pub use model::{Document, Inline, Item, M, Op, Section};
pub use numbers::{OPERAND_DIGITS, SIGNIFICANT_DIGITS, fmt_digits, fmt_number};
pub use sections::document;

use super::PixelTrace;

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

/// Writes a trace in the given format.
pub fn write(trace: &PixelTrace, format: Format) -> String {
    match format {
        Format::Text => document(trace).to_text(),
        Format::Markdown => document(trace).to_markdown(),
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
