//! The document model: a derivation as sections of prose and formulas, each formula a small
//! expression tree of [`M`] tokens, and the helpers the sections build formulas with. The
//! renderers ([`text`](super::text), [`markdown`](super::markdown), [`latex`](super::latex))
//! turn one [`Document`] into each output format.

use super::numbers::{OPERAND_DIGITS, SIGNIFICANT_DIGITS};

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
    /// An operator or separator.
    Op(Op),
    /// Words inside a formula.
    Text(String),
    /// A fraction, numerator over denominator.
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
    /// `+`.
    Plus,
    /// `-`.
    Minus,
    /// Multiplication, `·`.
    Mul,
    /// Cross product, `×`.
    Cross,
    /// `=`.
    Eq,
    /// `≈`.
    Approx,
    /// `<`.
    Lt,
    /// `≤`.
    Le,
    /// `>`.
    Gt,
    /// `≥`.
    Ge,
    /// An arrow, `→`: a step in a chain (object → world → view), or what a value becomes
    /// (snapped, wrapped, the taps' colour).
    To,
    /// Separates two formulas on one line.
    Sep,
}

/// Inline content of a paragraph.
#[derive(Clone, Debug, PartialEq)]
pub enum Inline {
    /// Words.
    T(String),
    /// Inline math.
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
        /// The matrix's name, written before ` = ` (e.g. `M_view`); empty for a system.
        lhs: Vec<M>,
        /// The matrix, row by row.
        rows: Vec<Vec<f64>>,
        /// The unknowns column of a system `M x = rhs`; empty for a plain matrix.
        unknowns: Vec<M>,
        /// The right-hand side of a system; empty for a plain matrix.
        rhs: Vec<f64>,
    },
}

/// A titled section.
#[derive(Clone, Debug, PartialEq)]
pub struct Section {
    /// The section's heading with its number, e.g. `3. Which triangle covers it`.
    pub title: String,
    /// Its prose and formulas, in order.
    pub items: Vec<Item>,
}

/// A worked example.
#[derive(Clone, Debug, PartialEq)]
pub struct Document {
    /// The heading of the whole derivation (for the probe: the pixel and the image size).
    pub title: String,
    /// The steps, in order.
    pub sections: Vec<Section>,
}

pub(super) const EQ: M = M::Op(Op::Eq);

pub(super) const PLUS: M = M::Op(Op::Plus);

pub(super) const MINUS: M = M::Op(Op::Minus);

pub(super) const MUL: M = M::Op(Op::Mul);

pub(super) const CROSS: M = M::Op(Op::Cross);

pub(super) const SEP: M = M::Op(Op::Sep);

pub(super) const TO: M = M::Op(Op::To);

pub(super) fn num(x: f64) -> M {
    M::Num(x)
}

pub(super) fn int(i: i64) -> M {
    M::Int(i)
}

pub(super) fn sym(s: impl Into<String>) -> M {
    M::Sym(s.into())
}

pub(super) fn txt(s: impl Into<String>) -> M {
    M::Text(s.into())
}

/// Things that can be the parts of a fraction or group.
pub(super) trait IntoMath {
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

pub(super) fn frac(a: impl IntoMath, b: impl IntoMath) -> M {
    M::Frac(a.into_math(), b.into_math())
}

pub(super) fn grp(a: impl IntoMath) -> M {
    M::Group(a.into_math())
}

/// Components this much smaller than a tuple's largest are rounding noise of an exact zero
/// (e.g. `-2.2e-16` for a point on the plane y = 0); they are shown as 0. Display only.
pub(super) const TUPLE_NOISE: f64 = 1e-12;

pub(super) fn tup(xs: &[f64]) -> M {
    let big = xs.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    M::Tuple(
        xs.iter()
            .map(|&x| vec![num(if x.abs() < TUPLE_NOISE * big { 0.0 } else { x })])
            .collect(),
    )
}

pub(super) fn tup32(xs: &[f32]) -> M {
    M::Tuple(xs.iter().map(|&x| vec![num(f64::from(x))]).collect())
}

pub(super) fn tup_m(xs: Vec<M>) -> M {
    M::Tuple(xs.into_iter().map(|x| vec![x]).collect())
}

/// `w_0 x_0 + w_1 x_1 + ...` with numbers for the weights.
pub(super) fn weighted(ws: &[f64], xs: Vec<M>) -> Vec<M> {
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
pub(super) fn weighted_sym(ws: &[&str], xs: &[String]) -> Vec<M> {
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
pub(super) fn listing(items: impl IntoIterator<Item = Vec<M>>) -> Vec<M> {
    let mut out = Vec::new();
    for (k, item) in items.into_iter().enumerate() {
        if k > 0 {
            out.push(SEP);
        }
        out.extend(item);
    }
    out
}

pub(super) fn t(s: impl Into<String>) -> Inline {
    Inline::T(s.into())
}

pub(super) fn m(v: Vec<M>) -> Inline {
    Inline::M(v)
}

pub(super) fn m1(x: M) -> Inline {
    Inline::M(vec![x])
}

/// The significant digits a number token is shown with.
pub(super) fn digits_of(x: &M) -> i32 {
    match x {
        M::Operand(_) => OPERAND_DIGITS,
        _ => SIGNIFICANT_DIGITS,
    }
}

/// Marks the numbers an equation computes with: in each formula of a line (formulas are
/// separated by [`Op::Sep`]), every number left of the last `=` becomes an [`M::Operand`];
/// the result, right of it, stays an [`M::Num`].
pub(super) fn mark_operands(ms: &mut [M]) {
    for formula in ms.split_mut(|x| matches!(x, M::Op(Op::Sep))) {
        let last_eq = formula
            .iter()
            .rposition(|x| matches!(x, M::Op(Op::Eq | Op::Approx)));
        if let Some(i) = last_eq {
            formula[..i].iter_mut().for_each(mark_all);
        }
    }
}

pub(super) fn mark_all(x: &mut M) {
    match x {
        M::Num(v) => *x = M::Operand(*v),
        M::Frac(a, b) => a.iter_mut().chain(b.iter_mut()).for_each(mark_all),
        M::Group(a) | M::Abs(a) => a.iter_mut().for_each(mark_all),
        M::Tuple(parts) => parts.iter_mut().flatten().for_each(mark_all),
        _ => {}
    }
}
