//! Rendering a [`Document`] as a LaTeX fragment (`\\subsection*` per section, formulas in
//! `align*`; needs only amsmath), and the LaTeX of a formula, which Markdown's math uses too.

use std::fmt::Write as _;

use super::model::*;
use super::numbers::{SIGNIFICANT_DIGITS, split_number};
use super::text::{Lead, binds_tightly, layout};

pub(super) fn greek_latex(base: &str) -> Option<&'static str> {
    Some(match base {
        "alpha" => "\\alpha",
        "beta" => "\\beta",
        "gamma" => "\\gamma",
        "Delta" => "\\Delta",
        "lambda" => "\\lambda",
        "half" => "\\tfrac{1}{2}",
        "sum" => "\\sum",
        _ => return None,
    })
}

pub(super) fn op_latex(op: Op) -> &'static str {
    match op {
        Op::Plus => "+",
        Op::Minus => "-",
        Op::Mul => "\\cdot",
        Op::Cross => "\\times",
        Op::Eq => "=",
        Op::Approx => "\\approx",
        Op::Lt => "<",
        Op::Le => "\\le",
        Op::Gt => ">",
        Op::Ge => "\\ge",
        Op::To => "\\;\\to\\;",
        Op::Sep => ",\\quad",
    }
}

pub(super) fn latex_escape(s: &str) -> String {
    let mut out = String::new();
    for ch in s.chars() {
        match ch {
            '\\' => out.push_str("\\textbackslash{}"),
            '&' | '%' | '$' | '#' | '_' | '{' | '}' => {
                out.push('\\');
                out.push(ch);
            }
            '~' => out.push_str("\\textasciitilde{}"),
            '^' => out.push_str("\\textasciicircum{}"),
            '<' => out.push_str("\\textless{}"),
            '>' => out.push_str("\\textgreater{}"),
            _ => out.push(ch),
        }
    }
    out
}

pub(super) fn num_latex(v: f64, digits: i32) -> String {
    let (mantissa, exponent) = split_number(v, digits);
    match exponent {
        Some(e) => format!("{mantissa}\\times 10^{{{e}}}"),
        None => mantissa,
    }
}

pub(super) fn sym_latex(name: &str) -> String {
    let (base, sub) = match name.split_once('_') {
        Some((b, sub)) => (b, Some(sub)),
        None => (name, None),
    };
    let mut s = match greek_latex(base) {
        Some(g) => g.to_string(),
        None if base.chars().count() > 1 => format!("\\mathrm{{{}}}", latex_escape(base)),
        None => latex_escape(base),
    };
    if let Some(g) = sub.and_then(greek_latex) {
        let _ = write!(s, "_{{{g}}}");
    } else if let Some(sub) = sub {
        let plain = sub.chars().filter(char::is_ascii_lowercase).count() < 2;
        if plain {
            let _ = write!(s, "_{{{}}}", latex_escape(sub));
        } else {
            let _ = write!(s, "_{{\\mathrm{{{}}}}}", latex_escape(sub));
        }
    }
    s
}

pub(super) fn latex_of(ms: &[M]) -> String {
    let mut parts: Vec<String> = Vec::new();
    let mut prev: Option<&M> = None;
    for x in ms {
        let s = match x {
            M::Num(v) | M::Operand(v) => {
                let n = num_latex(*v, digits_of(x));
                if *v < 0.0 && binds_tightly(prev) {
                    format!("({n})")
                } else {
                    n
                }
            }
            M::Int(i) => {
                if *i < 0 && binds_tightly(prev) {
                    format!("({i})")
                } else {
                    format!("{i}")
                }
            }
            M::Sym(name) => sym_latex(name),
            M::Op(op) => op_latex(*op).to_string(),
            M::Text(w) => format!("\\text{{{}}}", latex_escape(w)),
            M::Frac(a, b) => format!("\\frac{{{}}}{{{}}}", latex_of(a), latex_of(b)),
            M::Group(g) => format!("\\left({}\\right)", latex_of(g)),
            M::Tuple(xs) => {
                let inner: Vec<String> = xs.iter().map(|x| latex_of(x)).collect();
                format!("\\left({}\\right)", inner.join(",\\ "))
            }
            M::Abs(g) => format!("\\left\\lvert {}\\right\\rvert", latex_of(g)),
            M::Inverse(name) => format!("{}^{{-1}}", sym_latex(name)),
        };
        parts.push(s);
        prev = Some(x);
    }
    parts.join(" ")
}

/// Longest formula (counted as text) kept on one line of an `align*`: typeset math is wider
/// than the text form, and this keeps lines within an `article` text width.
pub(super) const LATEX_LINE_WIDTH: usize = 58;

/// Longest note kept beside its formula in an `align*`; longer ones follow as a paragraph.
pub(super) const LATEX_NOTE_WIDTH: usize = 30;

/// One `align*` row (or several, one per `=` step for a long chain), aligned at the first `=`.
pub(super) fn align_latex(ms: &[M], note: Option<&str>) -> String {
    let width = LATEX_LINE_WIDTH.saturating_sub(note.map_or(0, |n| n.chars().count() + 3));
    let note = note
        .map(|n| format!(" && \\text{{({})}}", latex_escape(n)))
        .unwrap_or_default();
    let rows: Vec<String> = layout(ms, width)
        .iter()
        .map(|row| {
            let steps: String = row
                .steps
                .iter()
                .map(|p| format!(" = {}", latex_of(p)))
                .collect();
            match row.lead {
                Lead::First if row.steps.is_empty() => format!("  & {}", latex_of(row.lhs)),
                Lead::First => format!("  {} &{}", latex_of(row.lhs), steps.trim_start()),
                Lead::Continue => format!("  &{}", steps.trim_start()),
                Lead::Arrow => format!("  & \\quad\\to\\; {}{steps}", latex_of(row.lhs)),
                Lead::Plus => format!("  & \\qquad + {}{steps}", latex_of(row.lhs)),
            }
        })
        .collect();
    format!("{}{note}", rows.join(" \\\\\n"))
}

pub(super) fn matrix_latex(lhs: &[M], rows: &[Vec<f64>], unknowns: &[M], rhs: &[f64]) -> String {
    let body: Vec<String> = rows
        .iter()
        .map(|r| {
            r.iter()
                .map(|&x| num_latex(x, SIGNIFICANT_DIGITS))
                .collect::<Vec<_>>()
                .join(" & ")
        })
        .collect();
    let mut s = format!(
        "{} \\begin{{bmatrix}} {} \\end{{bmatrix}}",
        latex_of(lhs),
        body.join(" \\\\ ")
    );
    if !unknowns.is_empty() {
        let u: Vec<String> = unknowns
            .iter()
            .map(|x| latex_of(std::slice::from_ref(x)))
            .collect();
        let r: Vec<String> = rhs
            .iter()
            .map(|&x| num_latex(x, SIGNIFICANT_DIGITS))
            .collect();
        let _ = write!(
            s,
            " \\begin{{bmatrix}} {} \\end{{bmatrix}} = \\begin{{bmatrix}} {} \\end{{bmatrix}}",
            u.join(" \\\\ "),
            r.join(" \\\\ ")
        );
    }
    s
}

pub(super) fn inline_latex(parts: &[Inline]) -> String {
    inline_with(parts, latex_escape)
}

/// Prose with inline math: text through `escape`, each formula as `$...$` in LaTeX (what both
/// LaTeX and Markdown with MathJax/KaTeX read).
pub(super) fn inline_with(parts: &[Inline], escape: fn(&str) -> String) -> String {
    parts
        .iter()
        .map(|p| match p {
            Inline::T(s) => escape(s),
            Inline::M(ms) => format!("${}$", latex_of(ms)),
        })
        .collect()
}

impl Document {
    /// A LaTeX fragment: `\subsection*` per section, prose paragraphs, formulas in `align*`.
    /// Needs only `amsmath`; the text is ASCII.
    pub fn to_latex(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "% Generated by barylab probe. Needs \\usepackage{{amsmath}}.\n\\section*{{{}}}",
            latex_escape(&self.title)
        );
        for sec in &self.sections {
            let _ = writeln!(out, "\n\\subsection*{{{}}}", latex_escape(&sec.title));
            let mut open = false;
            for item in &sec.items {
                match item {
                    Item::Para(p) => {
                        if open {
                            out.push_str("\n\\end{align*}\n");
                            open = false;
                        }
                        let _ = writeln!(out, "{}\n", inline_latex(p));
                    }
                    Item::Eq(ms, note) => {
                        if open {
                            out.push_str(" \\\\\n");
                        } else {
                            out.push_str("\\begin{align*}\n");
                            open = true;
                        }
                        match note {
                            Some(n) if n.chars().count() > LATEX_NOTE_WIDTH => {
                                out.push_str(&align_latex(ms, None));
                                out.push_str("\n\\end{align*}\n");
                                open = false;
                                let _ = writeln!(out, "({})\n", latex_escape(n));
                            }
                            _ => out.push_str(&align_latex(ms, note.as_deref())),
                        }
                    }
                    Item::Matrix {
                        lhs,
                        rows,
                        unknowns,
                        rhs,
                    } => {
                        if open {
                            out.push_str(" \\\\\n");
                        } else {
                            out.push_str("\\begin{align*}\n");
                            open = true;
                        }
                        out.push_str("  &");
                        out.push_str(&matrix_latex(lhs, rows, unknowns, rhs));
                    }
                }
            }
            if open {
                out.push_str("\n\\end{align*}\n");
            }
        }
        out
    }
}
