//! Unit tests of the document model and its renderers.

use super::latex::{latex_of, sym_latex};
use super::model::*;
use super::text::{Lead, layout, text_of};

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
