//! Writing a [`PixelTrace`] as a worked example: plain text, Markdown, LaTeX, or JSON.
//!
//! The derivation is built once, by [`document`], as a [`Document`]: sections of prose and
//! equations whose formulas are small expression trees ([`M`]). Each output format renders
//! that same document, so the three agree line by line. Numbers show 4 significant digits
//! ([`fmt_number`]); JSON keeps full precision.
//!
//! All user-facing words of the derivation are in this file.

use std::fmt::Write as _;

use super::{
    CoverageTest, DistanceKind, EdgeTest, PixelTrace, Position, RasterVertex, SceneForm, TapTrace,
    TriangleCoverage, TriangleTrace,
};
use crate::raster::clip::PlaneName;
use crate::raster::interpolate::Interpolation;
use crate::raster::render::TriangleStatus;
use crate::raster::setup::{EdgeKind, TieRule};
use crate::raster::shade::{Shading, WIRE_WIDTH_PX};
use crate::raster::texture::{Filter, Wrap};

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

// ---------------------------------------------------------------------------------------------
// Numbers

/// Significant digits of a result shown in text, Markdown and LaTeX.
pub const SIGNIFICANT_DIGITS: i32 = 4;

/// Significant digits of an operand: a number left of an equation's last `=`. Two more than a
/// result's, so that the arithmetic on the page checks at the precision shown
/// (`W_P = 1/10.4047 = 0.09611`, not `1/10.4 = 0.09611`).
pub const OPERAND_DIGITS: i32 = 6;

/// A number with [`SIGNIFICANT_DIGITS`] significant digits, trailing zeros dropped; plain
/// decimals from 1e-4 up to 1e6, else scientific (`1.234e-7`).
///
/// ```
/// use barylab::probe::format::fmt_number;
/// assert_eq!(fmt_number(0.0), "0");
/// assert_eq!(fmt_number(0.25), "0.25");
/// assert_eq!(fmt_number(2.0 / 3.0), "0.6667");
/// assert_eq!(fmt_number(-1234.5678), "-1235");
/// assert_eq!(fmt_number(400.5), "400.5");
/// assert_eq!(fmt_number(0.99999), "1");
/// assert_eq!(fmt_number(1.25e-9), "1.25e-9");
/// assert_eq!(fmt_number(-3.0e7), "-3e7");
/// ```
pub fn fmt_number(x: f64) -> String {
    fmt_digits(x, SIGNIFICANT_DIGITS)
}

/// [`fmt_number`] with `digits` significant digits.
///
/// ```
/// use barylab::probe::format::fmt_digits;
/// assert_eq!(fmt_digits(10.404_712, 6), "10.4047");
/// assert_eq!(fmt_digits(1.0 / 10.404_712, 4), "0.09611");
/// ```
pub fn fmt_digits(x: f64, digits: i32) -> String {
    let (mantissa, exponent) = split_number(x, digits);
    match exponent {
        Some(e) => format!("{mantissa}e{e}"),
        None => mantissa,
    }
}

/// Mantissa and (for scientific notation) exponent of [`fmt_digits`].
fn split_number(x: f64, digits: i32) -> (String, Option<i32>) {
    if x == 0.0 {
        return ("0".into(), None);
    }
    if !x.is_finite() {
        return (format!("{x}"), None);
    }
    let e = x.abs().log10().floor() as i32;
    if (-4..6).contains(&e) {
        let decimals = (digits - 1 - e).max(0) as usize;
        (trim_zeros(format!("{x:.decimals$}")), None)
    } else {
        let s = format!("{:.*e}", (digits - 1) as usize, x);
        match s.split_once('e') {
            Some((m, e)) => (trim_zeros(m.to_string()), e.parse().ok()),
            None => (s, None),
        }
    }
}

fn trim_zeros(s: String) -> String {
    if !s.contains('.') {
        return s;
    }
    let t = s.trim_end_matches('0').trim_end_matches('.');
    if t == "-0" { "0".into() } else { t.into() }
}

// ---------------------------------------------------------------------------------------------
// The document model

/// A token of a formula.
#[derive(Clone, Debug, PartialEq)]
pub enum M {
    /// A number, shown with [`SIGNIFICANT_DIGITS`].
    Num(f64),
    /// A number that an equation computes with, shown with [`OPERAND_DIGITS`] (the builder
    /// marks them: see `mark_operands`).
    Operand(f64),
    /// An exact integer.
    Int(i64),
    /// A symbol: `base` or `base_sub`; greek names (`alpha`, `beta`, `gamma`, `Delta`) and
    /// `half` are written as such.
    Sym(String),
    Op(Op),
    /// Words inside a formula.
    Text(String),
    Frac(Vec<M>, Vec<M>),
    /// A parenthesised group.
    Group(Vec<M>),
    /// `(x, y, ...)`.
    Tuple(Vec<Vec<M>>),
    /// `|x|`.
    Abs(Vec<M>),
    /// The inverse of a matrix symbol, `M^-1`.
    Inverse(String),
}

/// Operators and separators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    Plus,
    Minus,
    Mul,
    Cross,
    Eq,
    Approx,
    Lt,
    Le,
    Gt,
    Ge,
    To,
    /// Separates two formulas on one line.
    Sep,
}

/// Inline content of a paragraph.
#[derive(Clone, Debug, PartialEq)]
pub enum Inline {
    T(String),
    M(Vec<M>),
}

/// One item of a section.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// Prose with inline math.
    Para(Vec<Inline>),
    /// A displayed formula (a chain `lhs = ... = ...`), with an optional note.
    Eq(Vec<M>, Option<String>),
    /// A displayed matrix `lhs M` or a system `M x = rhs`.
    Matrix {
        lhs: Vec<M>,
        rows: Vec<Vec<f64>>,
        unknowns: Vec<M>,
        rhs: Vec<f64>,
    },
}

/// A titled section.
#[derive(Clone, Debug, PartialEq)]
pub struct Section {
    pub title: String,
    pub items: Vec<Item>,
}

/// A worked example.
#[derive(Clone, Debug, PartialEq)]
pub struct Document {
    pub title: String,
    pub sections: Vec<Section>,
}

const EQ: M = M::Op(Op::Eq);
const PLUS: M = M::Op(Op::Plus);
const MINUS: M = M::Op(Op::Minus);
const MUL: M = M::Op(Op::Mul);
const CROSS: M = M::Op(Op::Cross);
const SEP: M = M::Op(Op::Sep);
const TO: M = M::Op(Op::To);

fn num(x: f64) -> M {
    M::Num(x)
}

fn int(i: i64) -> M {
    M::Int(i)
}

fn sym(s: impl Into<String>) -> M {
    M::Sym(s.into())
}

fn txt(s: impl Into<String>) -> M {
    M::Text(s.into())
}

/// Things that can be the parts of a fraction or group.
trait IntoMath {
    fn into_math(self) -> Vec<M>;
}

impl IntoMath for M {
    fn into_math(self) -> Vec<M> {
        vec![self]
    }
}

impl IntoMath for Vec<M> {
    fn into_math(self) -> Vec<M> {
        self
    }
}

fn frac(a: impl IntoMath, b: impl IntoMath) -> M {
    M::Frac(a.into_math(), b.into_math())
}

fn grp(a: impl IntoMath) -> M {
    M::Group(a.into_math())
}

/// Components this much smaller than a tuple's largest are rounding noise of an exact zero
/// (e.g. `-2.2e-16` for a point on the plane y = 0); they are shown as 0. Display only.
const TUPLE_NOISE: f64 = 1e-12;

fn tup(xs: &[f64]) -> M {
    let big = xs.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    M::Tuple(
        xs.iter()
            .map(|&x| vec![num(if x.abs() < TUPLE_NOISE * big { 0.0 } else { x })])
            .collect(),
    )
}

fn tup32(xs: &[f32]) -> M {
    M::Tuple(xs.iter().map(|&x| vec![num(f64::from(x))]).collect())
}

fn tup_m(xs: Vec<M>) -> M {
    M::Tuple(xs.into_iter().map(|x| vec![x]).collect())
}

/// `w_0 x_0 + w_1 x_1 + ...` with numbers for the weights.
fn weighted(ws: &[f64], xs: Vec<M>) -> Vec<M> {
    let mut out = Vec::new();
    for (k, (w, x)) in ws.iter().zip(xs).enumerate() {
        if k > 0 {
            out.push(PLUS);
        }
        out.extend([num(*w), MUL, x]);
    }
    out
}

/// `a x + b y + c z` with symbols.
fn weighted_sym(ws: &[&str], xs: &[String]) -> Vec<M> {
    let mut out = Vec::new();
    for (k, (w, x)) in ws.iter().zip(xs).enumerate() {
        if k > 0 {
            out.push(PLUS);
        }
        out.extend([sym(*w), MUL, sym(x.clone())]);
    }
    out
}

/// Formulas side by side on one line, separated by [`Op::Sep`].
fn listing(items: impl IntoIterator<Item = Vec<M>>) -> Vec<M> {
    let mut out = Vec::new();
    for (k, item) in items.into_iter().enumerate() {
        if k > 0 {
            out.push(SEP);
        }
        out.extend(item);
    }
    out
}

fn t(s: impl Into<String>) -> Inline {
    Inline::T(s.into())
}

fn m(v: Vec<M>) -> Inline {
    Inline::M(v)
}

fn m1(x: M) -> Inline {
    Inline::M(vec![x])
}

// ---------------------------------------------------------------------------------------------
// Rendering: plain text

fn greek_text(base: &str) -> Option<&'static str> {
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

fn greek_latex(base: &str) -> Option<&'static str> {
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

fn op_text(op: Op) -> &'static str {
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

fn op_latex(op: Op) -> &'static str {
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

/// Whether a negative number after this token needs parentheses.
fn binds_tightly(prev: Option<&M>) -> bool {
    matches!(
        prev,
        Some(M::Op(Op::Plus | Op::Minus | Op::Mul | Op::Cross))
    )
}

/// Whether a fraction part needs parentheses in text, read left to right: a numerator if it
/// is a sum, a denominator if it is anything but a single factor.
fn needs_parens(part: &[M], denominator: bool) -> bool {
    let sum = part
        .iter()
        .any(|x| matches!(x, M::Op(Op::Plus | Op::Minus | Op::Cross)));
    let product = part
        .iter()
        .any(|x| matches!(x, M::Op(Op::Mul) | M::Frac(..)));
    sum || (denominator && (product || matches!(part, [M::Num(x) | M::Operand(x)] if *x < 0.0)))
}

/// The significant digits a number token is shown with.
fn digits_of(x: &M) -> i32 {
    match x {
        M::Operand(_) => OPERAND_DIGITS,
        _ => SIGNIFICANT_DIGITS,
    }
}

/// Marks the numbers an equation computes with: in each formula of a line (formulas are
/// separated by [`Op::Sep`]), every number left of the last `=` becomes an [`M::Operand`];
/// the result, right of it, stays an [`M::Num`].
fn mark_operands(ms: &mut [M]) {
    for formula in ms.split_mut(|x| matches!(x, M::Op(Op::Sep))) {
        let last_eq = formula
            .iter()
            .rposition(|x| matches!(x, M::Op(Op::Eq | Op::Approx)));
        if let Some(i) = last_eq {
            formula[..i].iter_mut().for_each(mark_all);
        }
    }
}

fn mark_all(x: &mut M) {
    match x {
        M::Num(v) => *x = M::Operand(*v),
        M::Frac(a, b) => a.iter_mut().chain(b.iter_mut()).for_each(mark_all),
        M::Group(a) | M::Abs(a) => a.iter_mut().for_each(mark_all),
        M::Tuple(parts) => parts.iter_mut().flatten().for_each(mark_all),
        _ => {}
    }
}

fn text_of(ms: &[M]) -> String {
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

fn inline_text(parts: &[Inline]) -> String {
    parts
        .iter()
        .map(|p| match p {
            Inline::T(s) => s.clone(),
            Inline::M(ms) => text_of(ms),
        })
        .collect()
}

/// Longest formula line in text before its `=` steps go on lines of their own.
const TEXT_LINE_WIDTH: usize = 100;

/// Splits a chain at its top-level `=` signs: `[lhs, step1, step2, ...]`.
fn split_chain(ms: &[M]) -> Vec<&[M]> {
    ms.split(|x| matches!(x, M::Op(Op::Eq))).collect()
}

/// How an output line of a formula starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Lead {
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
struct Row<'a> {
    lead: Lead,
    lhs: &'a [M],
    steps: Vec<&'a [M]>,
}

/// Lays a formula out in lines of at most `width` characters (as text): a line too long is
/// split into the formulas separated by [`Op::Sep`]; one still too long at its arrows
/// ([`Op::To`]) or else at its `=` steps; a piece without `=` still too long at its `+`.
fn layout(ms: &[M], width: usize) -> Vec<Row<'_>> {
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

fn matrix_text(indent: &str, lhs: &[M], rows: &[Vec<f64>], unknowns: &[M], rhs: &[f64]) -> String {
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
fn items_to_text(items: &[Item], out: &mut String) {
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

// ---------------------------------------------------------------------------------------------
// Rendering: LaTeX (also the math of Markdown)

fn latex_escape(s: &str) -> String {
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

fn markdown_escape(s: &str) -> String {
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

fn num_latex(v: f64, digits: i32) -> String {
    let (mantissa, exponent) = split_number(v, digits);
    match exponent {
        Some(e) => format!("{mantissa}\\times 10^{{{e}}}"),
        None => mantissa,
    }
}

fn sym_latex(name: &str) -> String {
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

fn latex_of(ms: &[M]) -> String {
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
const LATEX_LINE_WIDTH: usize = 58;

/// Longest note kept beside its formula in an `align*`; longer ones follow as a paragraph.
const LATEX_NOTE_WIDTH: usize = 30;

/// One `align*` row (or several, one per `=` step for a long chain), aligned at the first `=`.
fn align_latex(ms: &[M], note: Option<&str>) -> String {
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

fn matrix_latex(lhs: &[M], rows: &[Vec<f64>], unknowns: &[M], rhs: &[f64]) -> String {
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

fn inline_latex(parts: &[Inline]) -> String {
    parts
        .iter()
        .map(|p| match p {
            Inline::T(s) => latex_escape(s),
            Inline::M(ms) => format!("${}$", latex_of(ms)),
        })
        .collect()
}

fn inline_markdown(parts: &[Inline]) -> String {
    parts
        .iter()
        .map(|p| match p {
            Inline::T(s) => markdown_escape(s),
            Inline::M(ms) => format!("${}$", latex_of(ms)),
        })
        .collect()
}

// ---------------------------------------------------------------------------------------------
// Building the derivation

struct Builder {
    doc: Document,
}

impl Builder {
    fn section(&mut self, title: impl Into<String>) {
        let n = self.doc.sections.len() + 1;
        self.doc.sections.push(Section {
            title: format!("{n}. {}", title.into()),
            items: Vec::new(),
        });
    }

    fn push(&mut self, item: Item) {
        if self.doc.sections.is_empty() {
            self.section("");
        }
        if let Some(s) = self.doc.sections.last_mut() {
            s.items.push(item);
        }
    }

    fn para(&mut self, mut parts: Vec<Inline>) {
        for p in &mut parts {
            if let Inline::M(ms) = p {
                mark_operands(ms);
            }
        }
        self.push(Item::Para(parts));
    }

    fn text(&mut self, s: impl Into<String>) {
        self.para(vec![t(s)]);
    }

    fn eq(&mut self, mut ms: Vec<M>) {
        mark_operands(&mut ms);
        self.push(Item::Eq(ms, None));
    }

    fn eq_note(&mut self, mut ms: Vec<M>, note: impl Into<String>) {
        mark_operands(&mut ms);
        self.push(Item::Eq(ms, Some(note.into())));
    }

    fn matrix(&mut self, lhs: Vec<M>, rows: Vec<Vec<f64>>) {
        self.push(Item::Matrix {
            lhs,
            rows,
            unknowns: Vec::new(),
            rhs: Vec::new(),
        });
    }
}

/// Screen weights of the rasterized triangle's vertices, in the r, s, t / W_P notation.
const SCREEN: [&str; 3] = ["r", "s", "t"];
/// Perspective-correct weights, in the r, s, t / W_P notation.
const CORRECT: [&str; 3] = ["a", "b", "c"];

fn mode_name(mode: Interpolation) -> &'static str {
    match mode {
        Interpolation::Affine => "affine (screen-space, like GLSL noperspective)",
        Interpolation::Perspective => "perspective-correct (GLSL smooth)",
    }
}

fn shading_name(s: Shading) -> &'static str {
    match s {
        Shading::Texture => "texture",
        Shading::VertexColor => "vertex colour",
        Shading::Barycentric => "barycentric weights as colour",
        Shading::Depth => "depth as grey",
    }
}

fn filter_name(f: Filter) -> &'static str {
    match f {
        Filter::Nearest => "nearest",
        Filter::Bilinear => "bilinear",
        Filter::Trilinear => "trilinear",
    }
}

fn wrap_name(w: Wrap) -> &'static str {
    match w {
        Wrap::Repeat => "repeat",
        Wrap::ClampToEdge => "clamp to edge",
        Wrap::MirroredRepeat => "mirrored repeat",
    }
}

fn edge_kind_name(k: EdgeKind) -> &'static str {
    match k {
        EdgeKind::Left => "a left edge",
        EdgeKind::Right => "a right edge",
        EdgeKind::Top => "a top edge (horizontal, interior below it)",
        EdgeKind::Bottom => "a bottom edge (horizontal, interior above it)",
    }
}

fn plane_name(p: PlaneName) -> &'static str {
    match p {
        PlaneName::Near => "the near plane (z >= -w)",
        PlaneName::Far => "the far plane (z <= w)",
        PlaneName::PositiveW => "the plane w > 0",
        PlaneName::GuardLeft => "the left guard band",
        PlaneName::GuardRight => "the right guard band",
        PlaneName::GuardBottom => "the bottom guard band",
        PlaneName::GuardTop => "the top guard band",
    }
}

fn status_text(s: TriangleStatus) -> String {
    match s {
        TriangleStatus::Drawn => s.describe().to_string(),
        _ => format!("not drawn: {}", s.describe()),
    }
}

fn rgba(c: [u8; 4]) -> String {
    format!(
        "rgba({}, {}, {}, {}) = #{:02x}{:02x}{:02x}",
        c[0], c[1], c[2], c[3], c[0], c[1], c[2]
    )
}

fn names3(n: &[String; 3]) -> String {
    n.join(", ")
}

/// The derivation for a trace.
pub fn document(trace: &PixelTrace) -> Document {
    let [x, y] = trace.pixel;
    let [w, h] = trace.image_size;
    let mut b = Builder {
        doc: Document {
            title: format!("barylab probe: pixel ({x}, {y}) of the {w}x{h} image"),
            sections: Vec::new(),
        },
    };
    let st = &trace.settings;
    b.section("Settings");
    b.text(format!("Interpolation: {}.", mode_name(st.mode)));
    b.text(format!(
        "Shading: {}; texture filter {}, wrap {}{}.",
        shading_name(st.shading),
        filter_name(st.filter),
        wrap_name(st.wrap),
        if st.wireframe { "; wireframe on" } else { "" }
    ));
    sample_section(&mut b, trace);
    coverage_section(&mut b, trace);
    if let Some(d) = &trace.detail {
        vertices_section(&mut b, trace, d);
        if d.clipping.is_some() {
            clipping_section(&mut b, d);
        }
        screen_section(&mut b, trace, d);
        perspective_section(&mut b, trace, d);
        system_section(&mut b, d);
        point_section(&mut b, trace, d);
        attribute_section(&mut b, trace, d);
        depth_section(&mut b, trace, d);
    }
    color_section(&mut b, trace);
    b.doc
}

fn sample_section(b: &mut Builder, trace: &PixelTrace) {
    let [x, y] = trace.pixel;
    let [w, h] = trace.image_size;
    let s = &trace.sample;
    b.section("The sample point");
    b.text(
        "A pixel is sampled at its centre. Window coordinates are in pixels, x to the right, \
         y down from the top row:",
    );
    b.eq(vec![
        sym("x_P"),
        EQ,
        int(x.into()),
        PLUS,
        num(0.5),
        EQ,
        num(s.window[0]),
        SEP,
        sym("y_P"),
        EQ,
        int(y.into()),
        PLUS,
        num(0.5),
        EQ,
        num(s.window[1]),
    ]);
    b.text("In normalized device coordinates (NDC y = +1 is the top row):");
    b.eq(vec![
        sym("x_ndc"),
        EQ,
        frac(vec![int(2), MUL, num(s.window[0])], int(w.into())),
        MINUS,
        int(1),
        EQ,
        num(s.ndc[0]),
        SEP,
        sym("y_ndc"),
        EQ,
        int(1),
        MINUS,
        frac(vec![int(2), MUL, num(s.window[1])], int(h.into())),
        EQ,
        num(s.ndc[1]),
    ]);
    b.para(vec![
        t("The rasterizer works in exact integers of 1/256 pixel: "),
        m(vec![
            sym("P"),
            EQ,
            M::Tuple(vec![vec![int(s.fixed[0])], vec![int(s.fixed[1])]]),
        ]),
        t("."),
    ]);
}

fn edge_values_eq(test: &CoverageTest) -> Vec<M> {
    let mut v = Vec::new();
    for (i, e) in test.edges.iter().enumerate() {
        if i > 0 {
            v.push(SEP);
        }
        v.extend([sym(format!("E_{}", e.name)), EQ, int(e.value)]);
    }
    v
}

fn coverage_reason(test: &CoverageTest) -> String {
    let neg: Vec<&EdgeTest> = test.edges.iter().filter(|e| e.value < 0).collect();
    let zero: Vec<&EdgeTest> = test.edges.iter().filter(|e| e.value == 0).collect();
    match test.position {
        Position::Inside => "All three are positive: the sample is inside, covered.".into(),
        Position::Outside => {
            let list: Vec<String> = neg.iter().map(|e| format!("E_{} < 0", e.name)).collect();
            let edges: Vec<String> = neg.iter().map(|e| e.name.clone()).collect();
            format!(
                "{}: the sample is outside edge{} {}, not covered.",
                list.join(" and "),
                if neg.len() > 1 { "s" } else { "" },
                edges.join(" and ")
            )
        }
        Position::OnEdge => {
            let parts: Vec<String> = zero
                .iter()
                .map(|e| {
                    format!(
                        "E_{} = 0: on edge {}, {}",
                        e.name,
                        e.name,
                        edge_kind_name(e.kind)
                    )
                })
                .collect();
            let (covering, leaving) = match test.tie_rule {
                TieRule::Llvmpipe => ("left and bottom", "top and right"),
                TieRule::TopLeft => ("left and top", "bottom and right"),
            };
            let rule = match test.tie_rule {
                TieRule::Llvmpipe => "The tie rule (llvmpipe's, as OpenGL on Mesa)",
                TieRule::TopLeft => "The tie rule (top-left, as Direct3D and Vulkan state it)",
            };
            if test.covered {
                format!(
                    "{}. {rule} covers samples on {covering} edges: covered.",
                    parts.join("; ")
                )
            } else {
                format!(
                    "{}. {rule} leaves samples on {leaving} edges to the triangle \
                     on the other side: not covered here.",
                    parts.join("; ")
                )
            }
        }
    }
}

fn coverage_section(b: &mut Builder, trace: &PixelTrace) {
    b.section("Which triangle covers it");
    b.para(vec![
        t("The edge function of edge UV at P, "),
        m(vec![
            sym("E_UV"),
            EQ,
            grp(vec![sym("V"), MINUS, sym("U")]),
            CROSS,
            grp(vec![sym("P"), MINUS, sym("U")]),
        ]),
        t(
            ", is twice the signed area of U, V, P, in exact integers of 1/65536 px^2, signed \
             so that it is positive inside. Triangles are drawn in order; a fragment is kept if \
             its depth is less than the depth buffer's value (cleared to 1).",
        ),
    ]);
    if trace.triangles.len() < trace.triangle_count {
        b.text(format!(
            "The mesh has {} triangles; listed are the {} whose bounding box contains the pixel.",
            trace.triangle_count,
            trace.triangles.len()
        ));
    }
    for c in &trace.triangles {
        coverage_entry(b, c);
    }
    match (trace.written_by, &trace.detail) {
        (Some(k), _) => b.text(format!("The pixel shows triangle {k}.")),
        (None, Some(d)) => b.text(format!(
            "No triangle covers the pixel: it keeps the background colour. The steps below \
             use the nearest triangle, {} ({}), with its weights extended outside it; negative \
             weights are marked.",
            d.source,
            names3(&d.coverage.vertices)
        )),
        (None, None) => b.text(
            "No triangle covers the pixel, and no triangle was drawn at all: it keeps the \
             background colour.",
        ),
    }
}

fn coverage_entry(b: &mut Builder, c: &TriangleCoverage) {
    let head = format!("Triangle {} ({})", c.source, names3(&c.vertices));
    let Some(test) = &c.test else {
        b.text(format!("{head}: {}.", status_text(c.status)));
        return;
    };
    if c.clipped {
        b.text(format!(
            "{head}, clipped; the sample is tested against fan triangle {} ({}):",
            test.sub_triangle,
            names3(&test.vertices)
        ));
    } else {
        b.text(format!("{head}:"));
    }
    b.eq(edge_values_eq(test));
    b.text(coverage_reason(test));
    if let Some(d) = &c.depth_test {
        let (op, verdict) = if d.passed {
            (
                Op::Lt,
                "less than the depth buffer's value: the test passes, the fragment is written",
            )
        } else {
            (
                Op::Ge,
                "not less than the depth buffer's value: the test fails, the fragment is hidden",
            )
        };
        b.eq_note(
            vec![
                sym("d_P"),
                EQ,
                num(f64::from(d.depth)),
                M::Op(op),
                num(f64::from(d.buffer_before)),
            ],
            verdict,
        );
    }
}

fn vertices_section(b: &mut Builder, trace: &PixelTrace, d: &TriangleTrace) {
    b.section(format!(
        "The vertices of triangle {} in every space",
        d.source
    ));
    let [w, h] = trace.image_size;
    if let Some(mats) = &trace.matrices {
        let tilted = mats.world_from_object != glam::DMat4::IDENTITY.to_cols_array_2d();
        b.para(vec![
            t("Object"),
            m1(TO),
            t("world"),
            m1(TO),
            t("view (the camera, looking down -z)"),
            m1(TO),
            t("clip (the projection), then divide by w"),
            m1(TO),
            t("NDC"),
            m1(TO),
            t("window."),
        ]);
        if tilted {
            b.matrix(vec![sym("M_world"), EQ], rows4(&mats.world_from_object));
        }
        b.matrix(vec![sym("M_view"), EQ], rows4(&mats.view_from_world));
        b.matrix(vec![sym("M_proj"), EQ], rows4(&mats.clip_from_view));
    } else {
        b.text("A clip-space scene: the vertices are given in clip space.");
    }
    for v in &d.vertices {
        let n = &v.name;
        b.para(vec![t(format!("Vertex {n} (mesh vertex {}):", v.index))]);
        if let (Some(o), Some(wd), Some(vw)) = (v.object, v.world, v.view) {
            if o != wd {
                b.eq(vec![
                    sym(format!("world_{n}")),
                    EQ,
                    sym("M_world"),
                    MUL,
                    tup(&o),
                    EQ,
                    tup(&wd),
                ]);
            } else {
                b.eq(vec![sym(format!("world_{n}")), EQ, tup(&wd)]);
            }
            b.eq(vec![
                sym(format!("view_{n}")),
                EQ,
                sym("M_view"),
                MUL,
                sym(format!("world_{n}")),
                EQ,
                tup(&vw),
            ]);
            b.eq(vec![
                sym(format!("clip_{n}")),
                EQ,
                sym("M_proj"),
                MUL,
                sym(format!("view_{n}")),
                EQ,
                tup(&v.clip),
            ]);
        } else {
            b.eq(vec![sym(format!("clip_{n}")), EQ, tup(&v.clip)]);
        }
        match (v.ndc, v.window, v.window_snapped, v.inv_w) {
            (Some(ndc), Some(win), Some(snap), Some(inv_w)) => {
                b.eq(vec![
                    sym(format!("ndc_{n}")),
                    EQ,
                    frac(tup(&v.clip[..3]), num(v.clip[3])),
                    EQ,
                    tup(&ndc),
                ]);
                b.eq(vec![
                    sym(format!("window_{n}")),
                    EQ,
                    M::Tuple(vec![
                        vec![
                            grp(vec![num(ndc[0]), PLUS, int(1)]),
                            MUL,
                            frac(int(w.into()), int(2)),
                        ],
                        vec![
                            grp(vec![int(1), MINUS, num(ndc[1])]),
                            MUL,
                            frac(int(h.into()), int(2)),
                        ],
                    ]),
                    EQ,
                    tup(&win[..2]),
                    TO,
                    txt("snapped: "),
                    frac(
                        M::Tuple(
                            snap.iter()
                                .map(|&c| vec![int((c * 256.0).round() as i64)])
                                .collect(),
                        ),
                        int(256),
                    ),
                ]);
                b.eq(vec![
                    sym(format!("d_{n}")),
                    EQ,
                    frac(vec![num(ndc[2]), PLUS, int(1)], int(2)),
                    EQ,
                    num(win[2]),
                    SEP,
                    frac(int(1), sym(format!("W_{n}"))),
                    EQ,
                    frac(int(1), num(v.clip[3])),
                    EQ,
                    num(inv_w),
                ]);
            }
            _ => {
                b.para(vec![
                    m(vec![
                        sym(format!("W_{n}")),
                        EQ,
                        num(v.clip[3]),
                        M::Op(Op::Le),
                        int(0),
                    ]),
                    t(format!(
                        ": {n} is at or behind the plane of the eye. It has no NDC or window \
                         position (dividing by w <= 0 would mirror it through the eye), so the \
                         clipper cuts the triangle in clip space before the divide."
                    )),
                ]);
            }
        }
        b.eq(vec![
            sym(format!("uv_{n}")),
            EQ,
            tup32(&v.uv),
            SEP,
            sym(format!("colour_{n}")),
            EQ,
            tup32(&v.color),
        ]);
    }
}

fn rows4(m: &[[f64; 4]; 4]) -> Vec<Vec<f64>> {
    m.iter().map(|r| r.to_vec()).collect()
}

fn clipping_section(b: &mut Builder, d: &TriangleTrace) {
    let Some(c) = &d.clipping else {
        return;
    };
    b.section("Clipping");
    let planes: Vec<&str> = c.planes.iter().map(|p| plane_name(*p)).collect();
    b.text(format!(
        "The triangle crosses {}, so the clipper (Sutherland-Hodgman, in clip space) cut it \
         into a polygon of {} vertices, drawn as a fan of triangles. A new vertex on edge UV \
         is U + k (V - U) with the same k for every attribute, including its weights lambda \
         with respect to the source triangle.",
        planes.join(" and "),
        c.polygon.len()
    ));
    let src: Vec<&str> = d.vertices.iter().map(|v| v.name.as_str()).collect();
    for p in &c.polygon {
        match p.source_vertex {
            Some(_) => b.eq_note(
                vec![sym(p.name.clone()), EQ, tup(&p.clip)],
                "a source vertex, kept",
            ),
            None => b.eq_note(
                vec![
                    sym(p.name.clone()),
                    EQ,
                    tup(&p.clip),
                    SEP,
                    tup_m(src.iter().map(|s| sym(format!("lambda_{s}"))).collect()),
                    EQ,
                    tup32(&p.source_weights),
                ],
                "made by the clipper",
            ),
        }
    }
    let fan: Vec<&str> = c
        .fan_triangle
        .iter()
        .map(|&k| c.polygon.get(k).map_or("?", |p| p.name.as_str()))
        .collect();
    b.text(format!(
        "The pixel is in fan triangle ({}). Each of its vertices carries its weights with \
         respect to the source triangle {} as a varying; interpolating them gives the weights \
         of {} at the pixel. The screen-space formulas below apply to the fan triangle{}.",
        fan.join(", "),
        src.join(", "),
        src.join(", "),
        if d.vertex_behind_camera {
            ": the source triangle has a vertex with w <= 0, which has no position on the \
             screen, so its own screen-space weights do not exist"
        } else {
            ""
        }
    ));
}

fn raster_names(d: &TriangleTrace) -> [String; 3] {
    d.raster.vertices.clone().map(|v| v.name)
}

fn screen_section(b: &mut Builder, trace: &PixelTrace, d: &TriangleTrace) {
    let n = raster_names(d);
    let rv = &d.raster.vertices;
    let sw = &d.screen;
    let p = trace.sample.window;
    b.section(format!(
        "Screen-space weights r, s, t of {}, four ways",
        names3(&n)
    ));
    b.text(format!(
        "r, s, t weigh {} in the 2D triangle on screen (GAMES101 calls them alpha, beta, gamma). \
         Window positions (unsnapped, as the interpolation uses them):",
        names3(&n)
    ));
    let mut pos = Vec::new();
    for (k, v) in rv.iter().enumerate() {
        if k > 0 {
            pos.push(SEP);
        }
        pos.extend([sym(n[k].clone()), EQ, tup(&v.window)]);
    }
    pos.extend([SEP, sym("P"), EQ, tup(&p)]);
    // The inputs of the arithmetic below: shown with an operand's digits.
    pos.iter_mut().for_each(mark_all);
    b.eq(pos);
    let wx = |k: usize| rv[k].window[0];
    let wy = |k: usize| rv[k].window[1];
    let xs = |k: usize| sym(format!("x_{}", n[k]));
    let ys = |k: usize| sym(format!("y_{}", n[k]));
    let (px, py) = (p[0], p[1]);

    // 1. Explicit formula.
    if let Some(f) = &sw.explicit {
        b.text("1. The explicit formula (as in GAMES101):");
        // (y_P - y_A)(x_C - x_A) - (x_P - x_A)(y_C - y_A)
        let form = |u: usize| {
            vec![
                grp(vec![sym("y_P"), MINUS, ys(0)]),
                grp(vec![xs(u), MINUS, xs(0)]),
                MINUS,
                grp(vec![sym("x_P"), MINUS, xs(0)]),
                grp(vec![ys(u), MINUS, ys(0)]),
            ]
        };
        let vals = |py_: f64, px_: f64, u: usize| {
            vec![
                num(py_ - wy(0)),
                MUL,
                num(wx(u) - wx(0)),
                MINUS,
                num(px_ - wx(0)),
                MUL,
                num(wy(u) - wy(0)),
            ]
        };
        let dform = |u: usize, v: usize| {
            vec![
                grp(vec![ys(u), MINUS, ys(0)]),
                grp(vec![xs(v), MINUS, xs(0)]),
                MINUS,
                grp(vec![xs(u), MINUS, xs(0)]),
                grp(vec![ys(v), MINUS, ys(0)]),
            ]
        };
        let mut l = vec![sym("N_beta"), EQ];
        l.extend(form(2));
        l.push(EQ);
        l.extend(vals(py, px, 2));
        l.extend([EQ, num(f.beta_numerator)]);
        b.eq(l);
        let mut l = vec![sym("D_beta"), EQ];
        l.extend(dform(1, 2));
        l.push(EQ);
        l.extend(vals(wy(1), wx(1), 2));
        l.extend([EQ, num(f.beta_denominator)]);
        b.eq(l);
        b.eq(vec![
            sym("s"),
            EQ,
            sym("beta"),
            EQ,
            frac(sym("N_beta"), sym("D_beta")),
            EQ,
            frac(num(f.beta_numerator), num(f.beta_denominator)),
            EQ,
            num(f.weights[1]),
        ]);
        let mut l = vec![sym("N_gamma"), EQ];
        l.extend(form(1));
        l.push(EQ);
        l.extend(vals(py, px, 1));
        l.extend([EQ, num(f.gamma_numerator)]);
        b.eq(l);
        let mut l = vec![sym("D_gamma"), EQ];
        l.extend(dform(2, 1));
        l.push(EQ);
        l.extend(vals(wy(2), wx(2), 1));
        l.extend([EQ, num(f.gamma_denominator)]);
        b.eq(l);
        b.eq(vec![
            sym("t"),
            EQ,
            sym("gamma"),
            EQ,
            frac(sym("N_gamma"), sym("D_gamma")),
            EQ,
            frac(num(f.gamma_numerator), num(f.gamma_denominator)),
            EQ,
            num(f.weights[2]),
        ]);
        b.eq(vec![
            sym("r"),
            EQ,
            sym("alpha"),
            EQ,
            int(1),
            MINUS,
            sym("beta"),
            MINUS,
            sym("gamma"),
            EQ,
            int(1),
            MINUS,
            num(f.weights[1]),
            MINUS,
            num(f.weights[2]),
            EQ,
            num(f.weights[0]),
        ]);
    }

    // 2. Cross products.
    if let Some(c) = &sw.cross_product {
        b.para(vec![
            t("2. Ratios of signed areas from 2D cross products, with "),
            m(vec![
                sym("u"),
                CROSS,
                sym("v"),
                EQ,
                sym("u_x"),
                MUL,
                sym("v_y"),
                MINUS,
                sym("u_y"),
                MUL,
                sym("v_x"),
            ]),
            t(". Each sub-area is the triangle of P with the edge opposite a vertex:"),
        ]);
        let v2 = |k: usize| glam::DVec2::from_array(rv[k].window);
        let pp = glam::DVec2::from_array(p);
        let cross_line =
            |lhs: M, a: &str, bb: &str, c_: &str, u: glam::DVec2, w: glam::DVec2, val: f64| {
                // lhs = 1/2 (ab x ac) = 1/2 (u_x w_y - u_y w_x) = val
                vec![
                    lhs,
                    EQ,
                    sym("half"),
                    grp(vec![
                        sym(format!("{a}{bb}")),
                        CROSS,
                        sym(format!("{a}{c_}")),
                    ]),
                    EQ,
                    sym("half"),
                    grp(vec![
                        num(u.x),
                        MUL,
                        num(w.y),
                        MINUS,
                        num(u.y),
                        MUL,
                        num(w.x),
                    ]),
                    EQ,
                    num(val),
                ]
            };
        b.eq_note(
            cross_line(
                sym("S"),
                &n[1],
                &n[2],
                &n[0],
                v2(2) - v2(1),
                v2(0) - v2(1),
                c.area,
            ),
            if c.area < 0.0 {
                "negative: with y down, this order runs counter-clockwise on screen; the signs cancel in the ratios"
            } else {
                "positive: with y down, this order runs clockwise on screen"
            },
        );
        let subs = [(1usize, 2usize), (2, 0), (0, 1)];
        for (k, (i, j)) in subs.iter().enumerate() {
            let mut l = cross_line(
                sym(format!("S_{}", n[k])),
                &n[*i],
                &n[*j],
                "P",
                v2(*j) - v2(*i),
                pp - v2(*i),
                c.sub_areas[k],
            );
            l.extend([
                SEP,
                sym(SCREEN[k]),
                EQ,
                frac(sym(format!("S_{}", n[k])), sym("S")),
                EQ,
                num(c.weights[k]),
            ]);
            if c.weights[k] < 0.0 {
                b.eq_note(
                    l,
                    format!("negative: P is on the far side of edge {}{}", n[*i], n[*j]),
                );
            } else {
                b.eq(l);
            }
        }
        b.eq(vec![
            sym(format!("S_{}", n[0])),
            PLUS,
            sym(format!("S_{}", n[1])),
            PLUS,
            sym(format!("S_{}", n[2])),
            EQ,
            num(c.sub_areas[0] + c.sub_areas[1] + c.sub_areas[2]),
            EQ,
            sym("S"),
        ]);
    }

    // 3. OpenGL area form.
    if let Some(g) = &sw.gl_area {
        b.para(vec![
            t("3. The OpenGL area form (OpenGL 4.6, eq. 14.8), with the shoelace area "),
            m(vec![
                sym("area"),
                M::Tuple(vec![vec![sym("p_1")], vec![sym("p_2")], vec![sym("p_3")]]),
                EQ,
                sym("half"),
                sym("sum_i"),
                grp(vec![
                    sym("x_i"),
                    MUL,
                    sym("y_i+1"),
                    MINUS,
                    sym("x_i+1"),
                    MUL,
                    sym("y_i"),
                ]),
            ]),
            t(":"),
        ]);
        let area_of = |pts: [&str; 3]| {
            vec![
                sym("area"),
                M::Tuple(pts.iter().map(|s| vec![sym(*s)]).collect()),
            ]
        };
        let all = [n[0].as_str(), n[1].as_str(), n[2].as_str()];
        let mut l = area_of(all);
        l.extend([EQ, num(g.area)]);
        b.eq(l);
        for k in 0..3 {
            let mut with_p = all;
            with_p[k] = "P";
            let mut l = vec![sym(SCREEN[k]), EQ];
            l.push(frac(area_of(with_p), area_of(all)));
            l.extend([
                EQ,
                frac(num(g.sub_areas[k]), num(g.area)),
                EQ,
                num(g.weights[k]),
            ]);
            b.eq(l);
        }
    }

    // 4. From the system.
    match (&sw.from_system, &d.system) {
        (Some(r), Some(sys)) => {
            let sol = sys.system.solution;
            b.text(
                "4. From the 4x4 system (section below), which gives the weights \
                 b on the triangle in space and the sample's w; projecting back to the screen:",
            );
            for k in 0..3 {
                b.eq(vec![
                    sym(SCREEN[k]),
                    EQ,
                    frac(
                        vec![sym(format!("b_{}", n[k])), MUL, sym(format!("W_{}", n[k]))],
                        sym("w"),
                    ),
                    EQ,
                    frac(vec![num(sol[k]), MUL, num(rv[k].clip[3])], num(sol[3])),
                    EQ,
                    num(r[k]),
                ]);
            }
        }
        _ => b.text(
            "4. The 4x4 system is solved on the source triangle (section below); \
             since the rasterized triangle is a piece of the clipped triangle, its screen \
             weights do not come out of it.",
        ),
    }

    // The rasterizer.
    b.para(vec![
        t(
            "The rasterizer (setup::WeightPlanes) evaluates the same signed-area ratios in f64 \
           from the unsnapped window positions, as llvmpipe sets up its interpolation: ",
        ),
        m(vec![
            tup_m(SCREEN.iter().map(|c| sym(*c)).collect()),
            EQ,
            tup(&sw.rasterizer),
        ]),
        t(
            ". The exact integer edge values of the snapped positions (the coverage section) \
           only decide whether the pixel is covered.",
        ),
    ]);
    if !d.coverage.covered {
        for (k, e) in d.coverage.edges.iter().enumerate() {
            if sw.rasterizer[k] < 0.0 {
                b.eq_note(
                    vec![sym(SCREEN[k]), EQ, num(sw.rasterizer[k])],
                    format!("negative: P is outside edge {}", e.name),
                );
            }
        }
    }
    if d.coverage.covered && sw.rasterizer.iter().any(|&w| w < 0.0) {
        b.text(
            "A weight is slightly negative although the pixel is covered: the snapped edges \
             (1/256 px) cover the centre, the unsnapped triangle misses it by a hair. A GPU \
             interpolates with the same negative weight.",
        );
    }
    b.para(vec![
        t("All ways agree: the largest difference from the rasterizer's values is "),
        m1(num(sw.max_difference)),
        t("."),
    ]);
}

fn perspective_section(b: &mut Builder, trace: &PixelTrace, d: &TriangleTrace) {
    let n = raster_names(d);
    b.section("Perspective correction with 1/w (OpenGL 4.6, eq. 14.9)");
    let Some(p) = &d.perspective else {
        b.text(
            "The interpolated 1/w is not positive here: extended beyond its edges, the \
             triangle's plane lies behind the camera at this pixel, so there are no \
             perspective-correct weights.",
        );
        return;
    };
    let s004 = &p.correction;
    let r = d.screen.rasterizer;
    b.text(format!(
        "W is each vertex's clip-space w; with a perspective camera it is the depth in front of \
         the eye. 1/W is linear on the screen, W itself is not. With the screen weights r, s, t \
         of {}:{}",
        names3(&n),
        if p.w.iter().all(|&w| w == p.w[0]) {
            " (all W are equal here, as with an orthographic camera, so a, b, c are r, s, t)"
        } else {
            ""
        }
    ));
    b.eq(listing((0..3).map(|k| {
        vec![
            frac(int(1), sym(format!("W_{}", n[k]))),
            EQ,
            frac(int(1), num(p.w[k])),
            EQ,
            num(s004.inv_w[k]),
        ]
    })));
    let mut l = vec![frac(int(1), sym("W_P")), EQ];
    for k in 0..3 {
        if k > 0 {
            l.push(PLUS);
        }
        l.push(frac(sym(SCREEN[k]), sym(format!("W_{}", n[k]))));
    }
    l.push(EQ);
    l.extend(weighted(&r, s004.inv_w.iter().map(|&x| num(x)).collect()));
    l.extend([EQ, num(s004.inv_w_p)]);
    b.eq_note(l, "linear on screen");
    b.eq(vec![
        sym("W_P"),
        EQ,
        frac(int(1), num(s004.inv_w_p)),
        EQ,
        num(s004.w_p),
    ]);
    for k in 0..3 {
        b.eq(vec![
            sym(CORRECT[k]),
            EQ,
            frac(
                vec![sym(SCREEN[k]), MUL, sym("W_P")],
                sym(format!("W_{}", n[k])),
            ),
            EQ,
            frac(vec![num(r[k]), MUL, num(s004.w_p)], num(p.w[k])),
            EQ,
            num(s004.weights[k]),
        ]);
    }
    b.eq(vec![
        sym("a"),
        PLUS,
        sym("b"),
        PLUS,
        sym("c"),
        EQ,
        num(s004.sum),
    ]);
    b.para(vec![
        t("GAMES101's code (Assignment 2, rasterize_triangle) writes the same with its screen weights alpha, beta, gamma: "),
        m(vec![
            sym("w_reciprocal"),
            EQ,
            frac(
                int(1),
                vec![
                    frac(sym("alpha"), sym(format!("w_{}", n[0]))),
                    PLUS,
                    frac(sym("beta"), sym(format!("w_{}", n[1]))),
                    PLUS,
                    frac(sym("gamma"), sym(format!("w_{}", n[2]))),
                ],
            ),
            EQ,
            num(p.games101_w_reciprocal),
        ]),
        t(". Despite its name it is W_P itself, the reciprocal of the interpolated 1/w."),
    ]);
    b.para(vec![
        t("The renderer (interpolate::fragment) computed "),
        m(vec![
            tup_m(CORRECT.iter().map(|c| sym(*c)).collect()),
            EQ,
            tup(&p.renderer_weights),
        ]),
        t(" and "),
        m(vec![frac(int(1), sym("W_P")), EQ, num(p.renderer_inv_w)]),
        t("."),
    ]);
    if trace.settings.mode == Interpolation::Affine {
        b.text(
            "The mode is affine: the shader uses r, s, t directly; a, b, c are shown for \
             comparison.",
        );
    }
    if let (Some(_), Some(sw)) = (&d.clipping, &d.source_weights) {
        let src: Vec<&str> = d.vertices.iter().map(|v| v.name.as_str()).collect();
        let rv = &d.raster.vertices;
        let lam = tup_m(src.iter().map(|s| sym(format!("lambda_{s}"))).collect());
        b.para(vec![t(format!(
            "The weights lambda of the source triangle {} at the pixel are an attribute like \
             any other: each vertex of the rasterized triangle carries its lambda, and the \
             pixel interpolates them. Perspective-correct, with a, b, c and the smooth lambda \
             (at a vertex the clipper made: interpolated in clip space):",
            src.join(", ")
        ))]);
        let per_vertex = |f: fn(&RasterVertex) -> [f32; 3]| {
            listing((0..3).map(|k| vec![sym(format!("lambda({})", n[k])), EQ, tup32(&f(&rv[k]))]))
        };
        b.eq(per_vertex(|v| v.source_weights));
        b.eq_note(
            [
                vec![lam.clone(), EQ],
                weighted(
                    &p.renderer_weights,
                    (0..3).map(|k| tup32(&rv[k].source_weights)).collect(),
                ),
                vec![EQ, tup32(&sw.perspective)],
            ]
            .concat(),
            "as written to the weight buffers",
        );
        b.text(
            "Affine, with r, s, t and the noperspective lambda: OpenGL keeps a noperspective \
             attribute linear on the screen, so at a vertex the clipper made it is the source \
             triangle's screen-linear lambda there, not the smooth value:",
        );
        b.eq(per_vertex(|v| v.source_weights_affine));
        b.eq([
            vec![lam, EQ],
            weighted(
                &d.screen.rasterizer,
                (0..3)
                    .map(|k| tup32(&rv[k].source_weights_affine))
                    .collect(),
            ),
            vec![EQ, tup32(&sw.screen)],
        ]
        .concat());
    }
}

fn system_section(b: &mut Builder, d: &TriangleTrace) {
    b.section("The 4x4 linear system (Umetani, Applied Computer Graphics)");
    let src: Vec<String> = d.vertices.iter().map(|v| v.name.clone()).collect();
    let Some(sys) = &d.system else {
        b.text(
            "The system is singular here (the triangle is seen edge-on): the sample's ray does \
             not meet its plane in one point.",
        );
        return;
    };
    b.text(format!(
        "Unknowns: the weights b of {} on the triangle in space, and w, the sample's clip w. \
         The clip-space point b_{} q_{} + b_{} q_{} + b_{} q_{} must be (s_x w, s_y w, z, w) with s \
         the sample in NDC, and the weights sum to 1.{}",
        src.join(", "),
        src[0],
        src[0],
        src[1],
        src[1],
        src[2],
        src[2],
        " The source triangle's own clip coordinates are used: the system never divides by \
         w, so it works even with a vertex behind the camera, and it reaches the exact answer \
         independently of the rasterizer."
    ));
    let s = &sys.system;
    b.push(Item::Matrix {
        lhs: Vec::new(),
        rows: rows4(&s.matrix),
        unknowns: vec![
            sym(format!("b_{}", src[0])),
            sym(format!("b_{}", src[1])),
            sym(format!("b_{}", src[2])),
            sym("w"),
        ],
        rhs: s.rhs.to_vec(),
    });
    b.eq(vec![
        tup_m(vec![
            sym(format!("b_{}", src[0])),
            sym(format!("b_{}", src[1])),
            sym(format!("b_{}", src[2])),
            sym("w"),
        ]),
        EQ,
        tup(&s.solution),
    ]);
    let b3 = [s.solution[0], s.solution[1], s.solution[2]];
    if s.solution[3].is_nan() || s.solution[3] <= 0.0 {
        b.text(
            "w <= 0: the line through the eye and the pixel meets the triangle's plane behind \
             the camera, so the pixel sees no point of the plane.",
        );
        return;
    }
    if d.clipping.is_none() {
        if let Some(p) = &d.perspective {
            let diff = (0..3)
                .map(|k| (b3[k] - p.correction.weights[k]).abs())
                .fold((s.solution[3] - p.correction.w_p).abs(), f64::max);
            b.para(vec![
                t("These are a, b, c and W_P from the 1/w method (largest difference "),
                m1(num(diff)),
                t(")."),
            ]);
        }
    } else if let Some(sw) = &d.source_weights {
        let diff = (0..3)
            .map(|k| (b3[k] - f64::from(sw.perspective[k])).abs())
            .fold(0.0, f64::max);
        b.para(vec![
            t("These are the source weights the rasterizer interpolated, "),
            m1(tup32(&sw.perspective)),
            t(" (largest difference "),
            m1(num(diff)),
            t(", from the f32 varyings)."),
        ]);
    }
}

fn point_section(b: &mut Builder, trace: &PixelTrace, d: &TriangleTrace) {
    b.section("The point on the triangle that the pixel sees");
    let src: Vec<String> = d.vertices.iter().map(|v| v.name.clone()).collect();
    let Some(sp) = &d.seen_point else {
        b.text(
            "The ray through the pixel centre is parallel to the triangle's plane: it sees no \
             point of it.",
        );
        return;
    };
    let reference: Option<[f64; 3]> = if d.clipping.is_none() {
        d.perspective.map(|p| p.correction.weights)
    } else {
        d.source_weights.map(|w| w.perspective.map(f64::from))
    };
    match (&sp.ray, &sp.hit) {
        (Some(ray), Some(hit)) => {
            let perspective = trace.matrices.is_some_and(|m| m.perspective);
            b.text(if perspective {
                "In view space the eye is at the origin; the ray goes through the pixel centre \
                 on the near plane:"
            } else {
                "Orthographic camera: the ray is parallel to -z, from the pixel centre on the \
                 near plane to the far plane:"
            });
            b.eq(vec![
                sym("O"),
                EQ,
                tup(&ray.origin),
                SEP,
                sym("dir"),
                EQ,
                tup(&ray.direction),
            ]);
            let views: Vec<[f64; 3]> = d
                .vertices
                .iter()
                .map(|v| v.view.unwrap_or_default())
                .collect();
            let vv = |k: usize| glam::DVec3::from_array(views[k]);
            let nn = glam::DVec3::from_array(hit.normal);
            b.eq(vec![
                sym("n"),
                EQ,
                grp(vec![sym(src[1].clone()), MINUS, sym(src[0].clone())]),
                CROSS,
                grp(vec![sym(src[2].clone()), MINUS, sym(src[0].clone())]),
                EQ,
                tup(&(vv(1) - vv(0)).to_array()),
                CROSS,
                tup(&(vv(2) - vv(0)).to_array()),
                EQ,
                tup(&hit.normal),
            ]);
            let o = glam::DVec3::from_array(ray.origin);
            let dir = glam::DVec3::from_array(ray.direction);
            b.eq(vec![
                sym("k"),
                EQ,
                frac(
                    vec![
                        sym("n"),
                        MUL,
                        grp(vec![sym(src[0].clone()), MINUS, sym("O")]),
                    ],
                    vec![sym("n"), MUL, sym("dir")],
                ),
                EQ,
                frac(num(nn.dot(vv(0) - o)), num(nn.dot(dir))),
                EQ,
                num(hit.t),
            ]);
            if hit.t.is_nan() || hit.t <= 0.0 {
                b.para(vec![
                    m(vec![sym("k"), M::Op(Op::Le), int(0)]),
                    t(": the line meets the plane behind the start of the ray, not in front of the camera; the pixel sees no point of it."),
                ]);
                return;
            }
            b.eq_note(
                vec![
                    sym("X"),
                    EQ,
                    sym("O"),
                    PLUS,
                    sym("k"),
                    MUL,
                    sym("dir"),
                    EQ,
                    tup(&hit.point),
                ],
                "the seen point, view space",
            );
            if let Some(wd) = sp.world {
                b.eq(vec![
                    sym("X_world"),
                    EQ,
                    M::Inverse("M_view".into()),
                    MUL,
                    sym("X"),
                    EQ,
                    tup(&wd),
                ]);
            }
            b.text(format!(
                "Its own weights lambda, as ratios of signed areas in 3D measured along n ({} \
                 in view space):",
                src.join(", ")
            ));
            let pairs = [(1usize, 2usize), (2, 0), (0, 1)];
            for (k, (i, j)) in pairs.iter().enumerate() {
                b.eq(vec![
                    sym(format!("lambda_{}", src[k])),
                    EQ,
                    frac(
                        vec![
                            sym("n"),
                            MUL,
                            grp(vec![
                                grp(vec![sym(src[*i].clone()), MINUS, sym("X")]),
                                CROSS,
                                grp(vec![sym(src[*j].clone()), MINUS, sym("X")]),
                            ]),
                        ],
                        vec![sym("n"), MUL, sym("n")],
                    ),
                    EQ,
                    num(hit.weights[k]),
                ]);
            }
        }
        _ => {
            b.text(
                "A clip-space scene has no camera, but the 4x4 system's solution is the point \
                 itself, in clip space:",
            );
            let mut l = vec![sym("X"), EQ];
            l.extend(weighted(
                &sp.weights,
                src.iter().map(|s| sym(format!("q_{s}"))).collect(),
            ));
            l.extend([EQ, tup(&sp.clip)]);
            b.eq(l);
            b.eq_note(
                vec![
                    frac(sym("X_xyz"), sym("X_w")),
                    EQ,
                    tup(&[
                        sp.clip[0] / sp.clip[3],
                        sp.clip[1] / sp.clip[3],
                        sp.clip[2] / sp.clip[3],
                    ]),
                ],
                "its x and y are the sample's NDC",
            );
        }
    }
    if let Some(r) = reference {
        let diff = (0..3)
            .map(|k| (sp.weights[k] - r[k]).abs())
            .fold(0.0, f64::max);
        b.para(vec![
            t(if d.clipping.is_none() {
                "These are the perspective-correct weights a, b, c (largest difference "
            } else {
                "These are the source weights the rasterizer interpolated (largest difference "
            }),
            m1(num(diff)),
            t(if trace.scene_form != SceneForm::Clip {
                "; the ray is computed from the camera, the rasterizer from clip space)."
            } else {
                ")."
            }),
        ]);
    }
}

/// How a wrap mode maps a texel index into `0..size` (in words, for the nearest line).
fn wrap_rule(wrap: Wrap, size: [u32; 2]) -> String {
    let [w, h] = size;
    match wrap {
        Wrap::Repeat => format!("repeat, i mod {w}, j mod {h}"),
        Wrap::MirroredRepeat => format!("mirrored repeat over {w}x{h}"),
        Wrap::ClampToEdge => format!(
            "clamp to 0..{}, 0..{}",
            w.saturating_sub(1),
            h.saturating_sub(1)
        ),
    }
}

#[allow(clippy::too_many_arguments)]
fn taps_line(
    label: &str,
    uv: [f32; 2],
    texel: [f64; 2],
    taps: &[TapTrace],
    color: [u8; 4],
    filter: Filter,
    wrap: Wrap,
    size: [u32; 2],
) -> Vec<M> {
    let mut l = vec![txt(label.to_string()), tup32(&uv), TO];
    match filter {
        Filter::Nearest => {
            l.extend([
                txt("texel "),
                M::Tuple(vec![
                    vec![sym("floor"), grp(num(texel[0]))],
                    vec![sym("floor"), grp(num(texel[1]))],
                ]),
            ]);
            if let Some(tp) = taps.first() {
                let wrapped = M::Tuple(vec![vec![int(tp.i.into())], vec![int(tp.j.into())]]);
                match tp.unwrapped {
                    Some([i, j]) if [i, j] != [i64::from(tp.i), i64::from(tp.j)] => {
                        l.extend([
                            EQ,
                            M::Tuple(vec![vec![int(i)], vec![int(j)]]),
                            TO,
                            txt(format!("{}: ", wrap_rule(wrap, size))),
                            wrapped,
                        ]);
                    }
                    _ => l.extend([EQ, wrapped]),
                }
            }
        }
        Filter::Bilinear | Filter::Trilinear => {
            let mut ts = Vec::new();
            for (k, tp) in taps.iter().enumerate() {
                if k > 0 {
                    ts.push(PLUS);
                }
                let mut ij = vec![vec![int(tp.i.into())], vec![int(tp.j.into())]];
                if filter == Filter::Trilinear {
                    ij.push(vec![int(tp.level.into())]);
                }
                ts.extend([num(f64::from(tp.weight)), MUL, M::Tuple(ij)]);
            }
            l.extend(ts);
        }
    }
    l.extend([TO, txt(rgba(color))]);
    l
}

fn attribute_section(b: &mut Builder, trace: &PixelTrace, d: &TriangleTrace) {
    let Some(a) = &d.attribute else {
        return;
    };
    let n = raster_names(d);
    let r = d.screen.rasterizer;
    b.section("Texture coordinate and colour, both ways");
    b.eq(listing((0..3).map(|k| {
        vec![sym(format!("uv_{}", n[k])), EQ, tup32(&a.uv_vertices[k])]
    })));
    if a.uv_vertices_affine != a.uv_vertices {
        b.eq_note(
            listing((0..3).map(|k| {
                vec![
                    sym(format!("uv_{}", n[k])),
                    EQ,
                    tup32(&a.uv_vertices_affine[k]),
                ]
            })),
            "for noperspective: at a vertex the clipper made, OpenGL interpolates along the \
             cut edge with the screen-space fraction, so affine uv stays linear on screen",
        );
    }
    let uvs: Vec<String> = n.iter().map(|x| format!("uv_{x}")).collect();
    let mut l = vec![sym("uv_affine"), EQ];
    l.extend(weighted_sym(&SCREEN, &uvs));
    l.push(EQ);
    l.extend(weighted(
        &r,
        a.uv_vertices_affine.iter().map(|u| tup32(u)).collect(),
    ));
    l.extend([EQ, tup32(&a.uv_affine)]);
    b.eq_note(l, "screen weights: wrong under perspective");
    if let Some(p) = &d.perspective {
        let mut l = vec![sym("uv_persp"), EQ];
        l.extend(weighted_sym(&CORRECT, &uvs));
        l.push(EQ);
        l.extend(weighted(
            &p.correction.weights,
            a.uv_vertices.iter().map(|u| tup32(u)).collect(),
        ));
        l.extend([EQ, tup32(&a.uv_perspective)]);
        b.eq_note(l, "perspective-correct");
        let mut inner = Vec::new();
        for k in 0..3 {
            if k > 0 {
                inner.push(PLUS);
            }
            inner.push(frac(
                vec![sym(SCREEN[k]), MUL, sym(uvs[k].clone())],
                sym(format!("W_{}", n[k])),
            ));
        }
        b.para(vec![t(
            "The same by the OpenGL / GAMES101 form, interpolating uv/W and 1/W linearly and \
             dividing:",
        )]);
        b.eq(vec![
            sym("uv_persp"),
            EQ,
            grp(inner),
            MUL,
            sym("W_P"),
            EQ,
            tup(&a.uv_games101),
        ]);
    }
    let [tw, th] = a.texture_size;
    b.para(vec![
        t(format!("Texel coordinates: uv times the texture size {tw} x {th} (texel row 0 is the bottom, v = 0):")),
    ]);
    b.eq(vec![
        txt("affine "),
        tup(&a.texel_affine),
        SEP,
        txt("perspective "),
        tup(&a.texel_perspective),
        SEP,
        sym("Delta"),
        EQ,
        tup(&a.texel_difference),
        SEP,
        M::Abs(vec![sym("Delta")]),
        EQ,
        num(a.texel_distance),
        txt(" texels"),
    ]);
    let filter = trace.settings.filter;
    if let Some(tri) = &a.trilinear {
        b.para(vec![
            t(format!(
                "Trilinear filtering: the level of detail comes from the uv differences across \
                 the pixel's 2x2 quad (as GPUs compute derivatives), in texels of level 0, and \
                 the texture has {} mipmap levels: ",
                tri.levels
            )),
            m(vec![
                sym("lambda"),
                EQ,
                sym("log_2"),
                grp(vec![
                    sym("max"),
                    M::Tuple(vec![
                        vec![M::Abs(vec![sym("d(uv)/dx")])],
                        vec![M::Abs(vec![sym("d(uv)/dy")])],
                    ]),
                ]),
            ]),
            t("."),
        ]);
        b.eq(vec![
            sym("lambda_affine"),
            EQ,
            num(f64::from(tri.lod_affine)),
            SEP,
            sym("lambda_persp"),
            EQ,
            num(f64::from(tri.lod_perspective)),
        ]);
    }
    b.text(format!(
        "The {} filter reads{}:",
        filter_name(filter),
        match filter {
            Filter::Nearest => " the texel (floor(u W), floor(v H))",
            Filter::Bilinear => {
                " the 2x2 texels (i, j) around (u W - 1/2, v H - 1/2), weighted by the fractions; \
                 the colour is the weighted sum"
            }
            Filter::Trilinear => {
                " 2x2 texels (i, j, level) bilinearly in levels floor(lambda) and \
                 floor(lambda) + 1 (level 0 alone when lambda <= 0), blended by frac(lambda)"
            }
        }
    ));
    b.eq(taps_line(
        "affine ",
        a.uv_affine,
        a.texel_affine,
        &a.taps_affine,
        a.color_affine,
        filter,
        trace.settings.wrap,
        a.texture_size,
    ));
    b.eq(taps_line(
        "perspective ",
        a.uv_perspective,
        a.texel_perspective,
        &a.taps_perspective,
        a.color_perspective,
        filter,
        trace.settings.wrap,
        a.texture_size,
    ));
    b.eq(listing((0..3).map(|k| {
        vec![
            sym(format!("colour_{}", n[k])),
            EQ,
            tup32(&a.vertex_colors[k]),
        ]
    })));
    b.eq(vec![
        txt("vertex colour: affine "),
        tup32(&a.vertex_color_affine),
        SEP,
        txt("perspective "),
        tup32(&a.vertex_color_perspective),
    ]);
}

fn depth_section(b: &mut Builder, trace: &PixelTrace, d: &TriangleTrace) {
    let Some(dt) = &d.depth else {
        return;
    };
    let n = raster_names(d);
    let r = d.screen.rasterizer;
    b.section("Depth");
    b.text(
        "The depth buffer stores window depth d = (z/w + 1)/2. z/w is linear on the screen, \
         so the screen weights interpolate it exactly, with no correction:",
    );
    let mut l = vec![sym("d_P"), EQ];
    l.extend(weighted_sym(&SCREEN, &n.clone().map(|x| format!("d_{x}"))));
    l.push(EQ);
    l.extend(weighted(
        &r,
        dt.window_depths.iter().map(|&x| num(x)).collect(),
    ));
    l.extend([EQ, num(dt.depth)]);
    b.eq(l);
    let (label, sname) = match dt.distance_kind {
        DistanceKind::ViewDepth => (
            "view depth z = -z_view (the distance in front of the camera)",
            "z",
        ),
        DistanceKind::ClipW => ("clip w (for a perspective projection, the view depth)", "w"),
    };
    if trace.matrices.is_some_and(|m| !m.perspective) {
        b.text(format!(
            "The {label}: with an orthographic camera every w is 1 and it is linear on the \
             screen too, so both ways agree:"
        ));
    } else {
        b.text(format!("The {label} is not linear on the screen:"));
    }
    b.eq(listing((0..3).map(|k| {
        vec![sym(format!("{sname}_{}", n[k])), EQ, num(dt.distances[k])]
    })));
    let zs: Vec<M> = dt.distances.iter().map(|&x| num(x)).collect();
    let mut l = vec![sym(format!("{sname}_affine")), EQ];
    l.extend(weighted(&r, zs.clone()));
    l.extend([EQ, num(dt.distance_affine)]);
    b.eq_note(l, "screen weights: wrong");
    if let Some(p) = &d.perspective {
        let mut l = vec![sym(format!("{sname}_corrected")), EQ];
        l.extend(weighted(&p.correction.weights, zs));
        l.extend([EQ, num(dt.distance_corrected)]);
        let note = if dt.distance_kind == DistanceKind::ViewDepth
            && trace.matrices.is_some_and(|m| m.perspective)
        {
            "perspective-correct weights: right; it is W_P, as w = -z_view for this camera"
        } else {
            "perspective-correct weights: right"
        };
        b.eq_note(l, note);
    }
    if let Some(tz) = dt.distance_true {
        b.eq_note(
            vec![sym(format!("{sname}_true")), EQ, num(tz)],
            "of the seen point X",
        );
    }
    if let Some(dp) = dt.depth_of_point {
        b.eq_note(
            vec![sym("d_X"), EQ, num(dp)],
            "window depth of the seen point: the same as d_P",
        );
    }
}

fn color_section(b: &mut Builder, trace: &PixelTrace) {
    b.section("The colour written");
    let st = &trace.settings;
    let Some(d) = &trace.detail else {
        b.eq_note(
            vec![txt(format!(
                "pixel ({}, {}) = {}",
                trace.pixel[0],
                trace.pixel[1],
                rgba(trace.color)
            ))],
            "background",
        );
        return;
    };
    if let Some(sh) = &d.shade {
        if let Some(dist) = sh.edge_distance_px {
            b.para(vec![
                t("Wireframe: distance to the nearest source edge, smallest weight over its screen gradient: "),
                m1(num(dist)),
                t(format!(
                    " px; lines are drawn below {} px{}.",
                    fmt_number(WIRE_WIDTH_PX),
                    if sh.wire { ", so this is a line pixel" } else { "" }
                )),
            ]);
        }
        let how = match st.shading {
            Shading::Texture => format!(
                "the texture sampled at uv_{} with the {} filter, times 255, rounded",
                if st.mode == Interpolation::Affine {
                    "affine"
                } else {
                    "persp"
                },
                filter_name(st.filter)
            ),
            Shading::VertexColor => format!(
                "the vertex colour interpolated {}, times 255, rounded",
                if st.mode == Interpolation::Affine {
                    "affinely"
                } else {
                    "perspective-correctly"
                }
            ),
            Shading::Barycentric => format!(
                "the source triangle's weights ({}) as red, green, blue, times 255, rounded",
                if st.mode == Interpolation::Affine {
                    "screen"
                } else {
                    "perspective-correct"
                }
            ),
            Shading::Depth => "d_P as grey between the nearest (black) and farthest (white) \
                               drawn vertex depth"
                .to_string(),
        };
        if d.writes_pixel {
            b.text(format!("Shading: {how}."));
        } else {
            b.text(format!(
                "If the triangle covered the pixel, the shading ({how}) would give {}.",
                rgba(sh.color)
            ));
        }
    }
    b.eq_note(
        vec![txt(format!(
            "framebuffer({}, {}) = {}",
            trace.pixel[0],
            trace.pixel[1],
            rgba(trace.color)
        ))],
        if trace.written_by.is_some() {
            "the rendered pixel"
        } else {
            "background: no triangle covers it"
        },
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn negative_numbers_after_operators_get_parentheses() {
        let e = vec![num(0.5), MUL, num(-2.0), MINUS, num(-1.5), EQ, num(-2.5)];
        assert_eq!(text_of(&e), "0.5·(-2) - (-1.5) = -2.5");
        assert_eq!(latex_of(&e), "0.5 \\cdot (-2) - (-1.5) = -2.5");
    }

    #[test]
    fn fractions_are_parenthesised_only_where_needed() {
        assert_eq!(
            text_of(&[frac(vec![sym("r"), MUL, sym("W_P")], sym("W_A"))]),
            "r·W_P/W_A"
        );
        assert_eq!(
            text_of(&[frac(vec![num(1.0), PLUS, sym("x")], int(2))]),
            "(1 + x) / 2"
        );
        assert_eq!(
            text_of(&[frac(int(1), vec![sym("a"), MUL, sym("b")])]),
            "1 / (a·b)"
        );
        assert_eq!(text_of(&[frac(num(3.0), num(-4.0))]), "3 / (-4)");
        assert_eq!(
            latex_of(&[frac(sym("alpha"), sym("w_A"))]),
            "\\frac{\\alpha}{w_{A}}"
        );
    }

    #[test]
    fn symbols_in_latex() {
        assert_eq!(sym_latex("W_P"), "W_{P}");
        assert_eq!(sym_latex("x_ndc"), "x_{\\mathrm{ndc}}");
        assert_eq!(sym_latex("N_beta"), "N_{\\beta}");
        assert_eq!(sym_latex("uv_affine"), "\\mathrm{uv}_{\\mathrm{affine}}");
        assert_eq!(sym_latex("E_CP1"), "E_{CP1}");
    }

    #[test]
    fn long_chains_break_at_separators_then_at_equals() {
        let mut e = vec![sym("x"), EQ];
        for k in 0..30 {
            if k > 0 {
                e.push(PLUS);
            }
            e.push(num(f64::from(k) + 0.125));
        }
        e.extend([EQ, num(1.0), SEP, sym("y"), EQ, num(2.0)]);
        let rows = layout(&e, 60);
        assert_eq!(rows.len(), 3);
        assert_eq!(rows[0].lead, Lead::First);
        assert_eq!(rows[1].lead, Lead::Continue);
        assert_eq!(text_of(rows[1].steps[0]), "1");
        assert_eq!(text_of(rows[2].lhs), "y");
        // Short formulas stay on one line.
        assert_eq!(layout(&[sym("y"), EQ, num(2.0)], 60).len(), 1);
    }

    #[test]
    fn long_sums_wrap_at_plus() {
        let mut e = Vec::new();
        for k in 0..20 {
            if k > 0 {
                e.push(PLUS);
            }
            e.extend([num(0.125), MUL, tup(&[f64::from(k), 1.0])]);
        }
        let rows = layout(&e, 50);
        assert!(rows.len() > 2);
        assert!(rows.iter().skip(1).all(|r| r.lead == Lead::Plus));
        assert!(rows.iter().all(|r| text_of(r.lhs).chars().count() <= 50));
        let joined: Vec<String> = rows.iter().map(|r| text_of(r.lhs)).collect();
        assert_eq!(joined.join(" + "), text_of(&e));
    }

    #[test]
    fn tuple_noise_is_shown_as_zero() {
        assert_eq!(text_of(&[tup(&[0.5, -2.2e-16, 3.0])]), "(0.5, 0, 3)");
        // A small value in a small tuple is not noise.
        assert_eq!(text_of(&[tup(&[1e-9, 2e-9])]), "(1e-9, 2e-9)");
    }
}
