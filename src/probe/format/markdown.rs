//! Rendering a [`Document`] as Markdown: `##` sections, prose with `$...$` math (the LaTeX
//! of [`latex_of`]), each formula a list item, matrices as `$$` blocks.

use std::fmt::Write as _;

use super::latex::{latex_of, matrix_latex};
use super::model::{Document, Inline, Item};

pub(super) fn markdown_escape(s: &str) -> String {
    let mut out = String::new();
    for ch in s.chars() {
        if matches!(
            ch,
            '*' | '_' | '`' | '$' | '[' | ']' | '<' | '>' | '#' | '|'
        ) {
            out.push('\\');
        }
        out.push(ch);
    }
    out
}

pub(super) fn inline_markdown(parts: &[Inline]) -> String {
    super::latex::inline_with(parts, markdown_escape)
}

impl Document {
    /// Markdown: `##` sections, prose with `$...$`, each formula a list item.
    pub fn to_markdown(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(out, "# {}", markdown_escape(&self.title));
        for sec in &self.sections {
            let _ = writeln!(out, "\n## {}\n", markdown_escape(&sec.title));
            let mut in_list = false;
            for item in &sec.items {
                match item {
                    Item::Para(p) => {
                        if in_list {
                            out.push('\n');
                            in_list = false;
                        }
                        let _ = writeln!(out, "{}\n", inline_markdown(p));
                    }
                    Item::Eq(ms, note) => {
                        let note = note
                            .as_ref()
                            .map(|n| format!(" ({})", markdown_escape(n)))
                            .unwrap_or_default();
                        let _ = writeln!(out, "- ${}${note}", latex_of(ms));
                        in_list = true;
                    }
                    Item::Matrix {
                        lhs,
                        rows,
                        unknowns,
                        rhs,
                    } => {
                        if in_list {
                            out.push('\n');
                            in_list = false;
                        }
                        let _ =
                            writeln!(out, "$$\n{}\n$$\n", matrix_latex(lhs, rows, unknowns, rhs));
                    }
                }
            }
            if in_list {
                out.push('\n');
            }
        }
        while out.contains("\n\n\n") {
            out = out.replace("\n\n\n", "\n\n");
        }
        while out.ends_with("\n\n") {
            out.pop();
        }
        out
    }
}
