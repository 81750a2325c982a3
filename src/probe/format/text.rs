//! Rendering a [`Document`] as plain text (UTF-8): one formula per line, long formulas
//! laid out over several lines ([`layout`], shared with the LaTeX renderer).

use std::fmt::Write as _;

use super::model::*;
use super::numbers::{fmt_digits, fmt_number};

pub(super) fn greek_text(base: &str) -> Option<&'static str> {
    Some(match base {
        "alpha" => "α",
        "beta" => "β",
        "gamma" => "γ",
        "Delta" => "Δ",
        "lambda" => "λ",
        "half" => "½",
        "sum" => "Σ",
        _ => return None,
    })
}

pub(super) fn op_text(op: Op) -> &'static str {
    match op {
        Op::Plus => " + ",
        Op::Minus => " - ",
        Op::Mul => "·",
        Op::Cross => " × ",
        Op::Eq => " = ",
        Op::Approx => " ≈ ",
        Op::Lt => " < ",
        Op::Le => " ≤ ",
        Op::Gt => " > ",
        Op::Ge => " ≥ ",
        Op::To => " → ",
        Op::Sep => ",   ",
    }
}

/// Whether a negative number after this token needs parentheses.
pub(super) fn binds_tightly(prev: Option<&M>) -> bool {
    matches!(
        prev,
        Some(M::Op(Op::Plus | Op::Minus | Op::Mul | Op::Cross))
    )
}

/// Whether a fraction part needs parentheses in text, read left to right: a numerator if it
/// is a sum, a denominator if it is anything but a single factor.
pub(super) fn needs_parens(part: &[M], denominator: bool) -> bool {
    let sum = part
        .iter()
        .any(|x| matches!(x, M::Op(Op::Plus | Op::Minus | Op::Cross)));
    let product = part
        .iter()
        .any(|x| matches!(x, M::Op(Op::Mul) | M::Frac(..)));
    sum || (denominator && (product || matches!(part, [M::Num(x) | M::Operand(x)] if *x < 0.0)))
}

pub(super) fn text_of(ms: &[M]) -> String {
    let mut s = String::new();
    let mut prev: Option<&M> = None;
    for x in ms {
        match x {
            M::Num(v) | M::Operand(v) => {
                let n = fmt_digits(*v, digits_of(x));
                if *v < 0.0 && binds_tightly(prev) {
                    let _ = write!(s, "({n})");
                } else {
                    s.push_str(&n);
                }
            }
            M::Int(i) => {
                if *i < 0 && binds_tightly(prev) {
                    let _ = write!(s, "({i})");
                } else {
                    let _ = write!(s, "{i}");
                }
            }
            M::Sym(name) => {
                let (base, sub) = match name.split_once('_') {
                    Some((b, sub)) => (b, Some(sub)),
                    None => (name.as_str(), None),
                };
                s.push_str(greek_text(base).unwrap_or(base));
                if let Some(sub) = sub {
                    s.push('_');
                    s.push_str(greek_text(sub).unwrap_or(sub));
                }
            }
            M::Op(op) => s.push_str(op_text(*op)),
            M::Text(w) => s.push_str(w),
            M::Frac(a, b) => {
                let (ta, tb) = (text_of(a), text_of(b));
                let ta = if needs_parens(a, false) {
                    format!("({ta})")
                } else {
                    ta
                };
                let tb = if needs_parens(b, true) {
                    format!("({tb})")
                } else {
                    tb
                };
                if needs_parens(a, false) || needs_parens(b, true) {
                    let _ = write!(s, "{ta} / {tb}");
                } else {
                    let _ = write!(s, "{ta}/{tb}");
                }
            }
            M::Group(g) => {
                let _ = write!(s, "({})", text_of(g));
            }
            M::Tuple(xs) => {
                let parts: Vec<String> = xs.iter().map(|x| text_of(x)).collect();
                let _ = write!(s, "({})", parts.join(", "));
            }
            M::Abs(g) => {
                let _ = write!(s, "|{}|", text_of(g));
            }
            M::Inverse(name) => {
                s.push_str(&text_of(&[sym(name.clone())]));
                s.push_str("^-1");
            }
        }
        prev = Some(x);
    }
    s
}

pub(super) fn inline_text(parts: &[Inline]) -> String {
    parts
        .iter()
        .map(|p| match p {
            Inline::T(s) => s.clone(),
            Inline::M(ms) => text_of(ms),
        })
        .collect()
}

/// Longest formula line in text before its `=` steps go on lines of their own.
pub(super) const TEXT_LINE_WIDTH: usize = 100;

/// Splits a chain at its top-level `=` signs: `[lhs, step1, step2, ...]`.
pub(super) fn split_chain(ms: &[M]) -> Vec<&[M]> {
    ms.split(|x| matches!(x, M::Op(Op::Eq))).collect()
}

/// How an output line of a formula starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Lead {
    /// `lhs = step = ...`
    First,
    /// `    = step`, aligned under the `=` of the line before.
    Continue,
    /// `-> piece`: the part after an [`Op::To`].
    Arrow,
    /// `+ terms`: more terms of a sum too long for one line.
    Plus,
}

/// One output line of a formula.
pub(super) struct Row<'a> {
    pub(super) lead: Lead,
    pub(super) lhs: &'a [M],
    pub(super) steps: Vec<&'a [M]>,
}

/// Lays a formula out in lines of at most `width` characters (as text): a line too long is
/// split into the formulas separated by [`Op::Sep`]; one still too long at its arrows
/// ([`Op::To`]) or else at its `=` steps; a piece without `=` still too long at its `+`.
pub(super) fn layout(ms: &[M], width: usize) -> Vec<Row<'_>> {
    let fits = |p: &[M]| text_of(p).chars().count() <= width;
    fn whole(p: &[M], lead: Lead) -> Row<'_> {
        let parts = split_chain(p);
        Row {
            lead,
            lhs: parts[0],
            steps: parts[1..].to_vec(),
        }
    }
    /// A piece without `=`, wrapped at its top-level `+` signs: each line takes the most
    /// whole terms that fit, at least one.
    fn wrapped<'a>(p: &'a [M], lead: Lead, width: usize, rows: &mut Vec<Row<'a>>) {
        let plus: Vec<usize> = p
            .iter()
            .enumerate()
            .filter(|(_, x)| matches!(x, M::Op(Op::Plus)))
            .map(|(i, _)| i)
            .collect();
        let mut start = 0;
        let mut lead = lead;
        loop {
            let mut end = p.len();
            if text_of(&p[start..]).chars().count() > width {
                let mut best = None;
                for &b in plus.iter().filter(|&&b| b > start) {
                    if best.is_none() || text_of(&p[start..b]).chars().count() <= width {
                        best = Some(b);
                    } else {
                        break;
                    }
                }
                if let Some(b) = best {
                    end = b;
                }
            }
            rows.push(Row {
                lead,
                lhs: &p[start..end],
                steps: Vec::new(),
            });
            if end == p.len() {
                break;
            }
            start = end + 1;
            lead = Lead::Plus;
        }
    }
    if fits(ms) {
        return vec![whole(ms, Lead::First)];
    }
    let mut rows = Vec::new();
    for piece in ms.split(|x| matches!(x, M::Op(Op::Sep))) {
        if fits(piece) {
            rows.push(whole(piece, Lead::First));
        } else if piece.contains(&M::Op(Op::To)) {
            for (k, seg) in piece.split(|x| matches!(x, M::Op(Op::To))).enumerate() {
                let lead = if k > 0 { Lead::Arrow } else { Lead::First };
                if fits(seg) || seg.contains(&M::Op(Op::Eq)) {
                    rows.push(whole(seg, lead));
                } else {
                    wrapped(seg, lead, width, &mut rows);
                }
            }
        } else if piece.contains(&M::Op(Op::Eq)) {
            let parts = split_chain(piece);
            for (k, p) in parts.iter().enumerate().skip(1) {
                rows.push(Row {
                    lead: if k > 1 { Lead::Continue } else { Lead::First },
                    lhs: parts[0],
                    steps: vec![p],
                });
            }
        } else {
            wrapped(piece, Lead::First, width, &mut rows);
        }
    }
    rows
}

pub(super) fn matrix_text(
    indent: &str,
    lhs: &[M],
    rows: &[Vec<f64>],
    unknowns: &[M],
    rhs: &[f64],
) -> String {
    let cells: Vec<Vec<String>> = rows
        .iter()
        .map(|r| r.iter().map(|&x| fmt_number(x)).collect())
        .collect();
    let ncols = cells.iter().map(Vec::len).max().unwrap_or(0);
    let widths: Vec<usize> = (0..ncols)
        .map(|c| {
            cells
                .iter()
                .map(|r| r.get(c).map_or(0, |s| s.chars().count()))
                .max()
                .unwrap_or(0)
        })
        .collect();
    let unk: Vec<String> = unknowns
        .iter()
        .map(|u| text_of(std::slice::from_ref(u)))
        .collect();
    let uw = unk.iter().map(|s| s.chars().count()).max().unwrap_or(0);
    let rhs_s: Vec<String> = rhs.iter().map(|&x| fmt_number(x)).collect();
    let rw = rhs_s.iter().map(|s| s.chars().count()).max().unwrap_or(0);
    let lhs_s = text_of(lhs);
    let lw = lhs_s.chars().count();
    let mid = rows.len().saturating_sub(1) / 2;
    let mut out = String::new();
    for (i, r) in cells.iter().enumerate() {
        let row: Vec<String> = r
            .iter()
            .enumerate()
            .map(|(c, s)| format!("{s:>w$}", w = widths[c]))
            .collect();
        let mut line = format!(
            "{indent}{}[ {} ]",
            if i == mid {
                format!("{lhs_s}{}", if lw > 0 { " " } else { "" })
            } else {
                " ".repeat(lw + usize::from(lw > 0))
            },
            row.join("  ")
        );
        if !unk.is_empty() {
            let u = unk.get(i).map_or(String::new(), Clone::clone);
            let r = rhs_s.get(i).map_or(String::new(), Clone::clone);
            let (times, eq) = if i == mid {
                (" · ", " = ")
            } else {
                ("   ", "   ")
            };
            let _ = write!(line, "{times}[ {u:<uw$} ]{eq}[ {r:>rw$} ]");
        }
        out.push_str(line.trim_end());
        out.push('\n');
    }
    out
}

impl Section {
    /// The section's items as plain text, as [`Document::to_text`] writes them (without the
    /// section title), for showing one section at a time (the app's inspector).
    pub fn to_text(&self) -> String {
        let mut out = String::new();
        items_to_text(&self.items, &mut out);
        out
    }
}

/// Writes items as plain text, one formula per line.
pub(super) fn items_to_text(items: &[Item], out: &mut String) {
    for item in items {
        match item {
            Item::Para(p) => {
                let _ = writeln!(out, "  {}", inline_text(p));
            }
            Item::Eq(ms, note) => {
                let note = note
                    .as_ref()
                    .map(|n| format!("    ({n})"))
                    .unwrap_or_default();
                let width = TEXT_LINE_WIDTH.saturating_sub(note.chars().count());
                let rows = layout(ms, width);
                let last = rows.len().saturating_sub(1);
                for (k, row) in rows.iter().enumerate() {
                    let lhs = text_of(row.lhs);
                    let head = match row.lead {
                        Lead::First => lhs,
                        Lead::Continue => " ".repeat(lhs.chars().count()),
                        Lead::Arrow => format!("    → {lhs}"),
                        Lead::Plus => format!("      + {lhs}"),
                    };
                    let steps: Vec<String> = row.steps.iter().map(|p| text_of(p)).collect();
                    let tail = if k == last { note.as_str() } else { "" };
                    if steps.is_empty() {
                        let _ = writeln!(out, "    {head}{tail}");
                    } else {
                        let _ = writeln!(out, "    {head} = {}{tail}", steps.join(" = "));
                    }
                }
            }
            Item::Matrix {
                lhs,
                rows,
                unknowns,
                rhs,
            } => {
                out.push_str(&matrix_text("    ", lhs, rows, unknowns, rhs));
            }
        }
    }
}

impl Document {
    /// Plain text: numbered sections, one formula per line.
    pub fn to_text(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(out, "{}", self.title);
        let _ = writeln!(out, "{}", "=".repeat(self.title.chars().count()));
        for sec in &self.sections {
            let _ = writeln!(out, "\n{}", sec.title);
            let _ = writeln!(out, "{}", "-".repeat(sec.title.chars().count()));
            items_to_text(&sec.items, &mut out);
        }
        out
    }
}
