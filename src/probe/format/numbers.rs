//! Numbers as the derivation prints them: [`SIGNIFICANT_DIGITS`] for a result,
//! [`OPERAND_DIGITS`] for an operand, trailing zeros dropped, scientific notation outside
//! `[1e-4, 1e6)`.

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

/// [`fmt_digits`] for a column of numbers: trailing zeros kept, so the digits line up
/// (`0.2080` beside `0.3333`), except that a whole number stays whole (`1`, not `1.000`).
///
/// ```
/// use barylab::probe::format::fmt_column;
/// assert_eq!(fmt_column(0.208, 4), "0.2080");
/// assert_eq!(fmt_column(0.015, 4), "0.01500");
/// assert_eq!(fmt_column(1.0, 4), "1");
/// assert_eq!(fmt_column(10.0, 4), "10");
/// assert_eq!(fmt_column(-0.5, 4), "-0.5000");
/// assert_eq!(fmt_column(0.0, 4), "0");
/// assert_eq!(fmt_column(1.25e-9, 4), "1.25e-9");
/// ```
pub fn fmt_column(x: f64, digits: i32) -> String {
    if x == 0.0 || !x.is_finite() {
        return fmt_digits(x, digits);
    }
    let e = x.abs().log10().floor() as i32;
    if !(-4..6).contains(&e) {
        return fmt_digits(x, digits);
    }
    let decimals = (digits - 1 - e).max(0) as usize;
    let s = format!("{x:.decimals$}");
    match s.split_once('.') {
        Some((whole, fraction)) if fraction.bytes().all(|b| b == b'0') => {
            if whole == "-0" {
                "0".into()
            } else {
                whole.into()
            }
        }
        _ => s,
    }
}

/// Mantissa and (for scientific notation) exponent of [`fmt_digits`].
pub(super) fn split_number(x: f64, digits: i32) -> (String, Option<i32>) {
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
