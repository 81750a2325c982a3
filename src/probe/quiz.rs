//! Quiz questions on one pixel's numbers: a class predicts the screen weights r, s, t, the
//! perspective-correct weights a, b, c, 1/W_P or the texture coordinate uv, and
//! [`Expected::check`] says whether the prediction is right within [`TOLERANCE`], by how much
//! each number is off, and which known mistake a wrong answer matches ([`Mistake`]).
//!
//! Every number comes from the probe: the answers are the trace's own values
//! ([`ScreenWeights::rasterizer`](super::ScreenWeights::rasterizer), the
//! [`WpCorrection`](super::weights::WpCorrection) of the perspective step, the renderer's uv),
//! and each mistake is the same probe function run with the mistake applied: r, s, t in place
//! of a, b, c; [`w_p_correction`] with every w = 1; the weights in another vertex order; the
//! screen weights by [`cross_product_weights`] at the pixel's corner `(x, y)` instead of its
//! centre `(x + 0.5, y + 0.5)`. No egui here; the app's quiz panel and the lesson handout
//! both use it.

use glam::DVec2;
use serde::{Deserialize, Serialize};

use super::PixelTrace;
use super::weights::{cross_product_weights, w_p_correction};
use crate::i18n::Lang;
use crate::raster::Interpolation;

/// How far a predicted number may be from the answer and still be right. A class writes two
/// decimals: rounding to two decimals is off by at most 0.005, and the answer shown is
/// rounded too, so 0.006 accepts every correctly rounded prediction and nothing a digit off.
pub const TOLERANCE: f64 = 0.006;

/// A mistake is named only when its numbers differ from the answer by more than this (twice
/// [`TOLERANCE`]): where every w is equal, r, s, t *are* a, b, c, and using one for the other
/// is no mistake.
const DISTINCT: f64 = 2.0 * TOLERANCE;

/// Two mistakes whose predictions are this close give the same numbers (they differ by
/// rounding only).
const SAME: f64 = 1e-9;

/// What a question asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    /// The screen-space weights r, s, t at the pixel centre.
    ScreenWeights,
    /// The perspective-correct weights a, b, c.
    Weights,
    /// `1/W_P = r/W_A + s/W_B + t/W_C`.
    InvW,
    /// The texture coordinate (u, v), interpolated in the scene's mode.
    Uv,
}

impl Quantity {
    /// Every quantity, in the order a question lists them.
    pub const ALL: [Quantity; 4] = [
        Quantity::ScreenWeights,
        Quantity::Weights,
        Quantity::InvW,
        Quantity::Uv,
    ];

    /// The symbols of its numbers, the same in every language.
    ///
    /// ```
    /// use barylab::probe::quiz::Quantity;
    /// assert_eq!(Quantity::Weights.symbols(), ["a", "b", "c"]);
    /// assert_eq!(Quantity::InvW.symbols().len(), 1);
    /// ```
    pub fn symbols(self) -> &'static [&'static str] {
        match self {
            Quantity::ScreenWeights => &["r", "s", "t"],
            Quantity::Weights => &["a", "b", "c"],
            Quantity::InvW => &["1/W_P"],
            Quantity::Uv => &["u", "v"],
        }
    }

    /// Its name as a lesson writes it (`screen_weights`, `weights`, `inv_w`, `uv`).
    pub fn code(self) -> &'static str {
        match self {
            Quantity::ScreenWeights => "screen_weights",
            Quantity::Weights => "weights",
            Quantity::InvW => "inv_w",
            Quantity::Uv => "uv",
        }
    }

    /// Its name in `lang` (`screen-space weights r, s, t`, ...).
    pub fn name(self, lang: Lang) -> String {
        lang.tr(&format!("quiz.quantity.{}", self.code()))
    }
}

/// A known mistake a wrong answer can match.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Mistake {
    /// The screen weights r, s, t used as the perspective weights a, b, c (or the other way
    /// round): right only when every w is equal.
    ScreenForPerspective,
    /// Every w taken as 1: 1/W_P = r + s + t = 1, uv interpolated affinely.
    WOne,
    /// The right weights assigned to the wrong vertices (a permutation).
    VertexOrder,
    /// The weights at the pixel's corner (x, y) instead of its centre (x + 0.5, y + 0.5).
    HalfPixel,
}

impl Mistake {
    /// Its code in the catalogues and in JSON.
    pub fn code(self) -> &'static str {
        match self {
            Mistake::ScreenForPerspective => "screen_for_perspective",
            Mistake::WOne => "w_one",
            Mistake::VertexOrder => "vertex_order",
            Mistake::HalfPixel => "half_pixel",
        }
    }

    /// Its short name in `lang`.
    pub fn name(self, lang: Lang) -> String {
        lang.tr(&format!("quiz.mistake.{}.name", self.code()))
    }

    /// What went wrong and how to get it right, in `lang`.
    pub fn explain(self, lang: Lang) -> String {
        lang.tr(&format!("quiz.mistake.{}.explain", self.code()))
    }
}

/// A question: a pixel and what is asked about it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Question {
    /// The pixel (column from the left, row from the top).
    pub pixel: [u32; 2],
    /// The quantities asked, in order, each once.
    pub ask: Vec<Quantity>,
}

/// Why a pixel cannot be asked about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum QuizError {
    /// No triangle is near the pixel: it has no weights.
    #[error("no triangle covers the pixel")]
    NoTriangle,
    /// No 1/w correction at the pixel (a vertex or the point behind the camera).
    #[error("the pixel has no perspective correction (a w is not positive)")]
    NoPerspective,
}

impl QuizError {
    /// The message in `lang`.
    pub fn message(self, lang: Lang) -> String {
        lang.tr(match self {
            QuizError::NoTriangle => "quiz.error.no_triangle",
            QuizError::NoPerspective => "quiz.error.no_perspective",
        })
    }
}

/// The answer to one quantity, and the numbers each known mistake gives.
#[derive(Clone, Debug, PartialEq)]
pub struct Expected {
    /// What is asked.
    pub quantity: Quantity,
    /// The probe's values.
    pub values: Vec<f64>,
    /// The values each mistake gives, in the order they are tried (a mistake may be listed
    /// several times, e.g. each wrong vertex order).
    pub mistakes: Vec<(Mistake, Vec<f64>)>,
}

/// The verdict on one predicted quantity.
#[derive(Clone, Debug, PartialEq)]
pub struct Verdict {
    /// What was asked.
    pub quantity: Quantity,
    /// The prediction.
    pub given: Vec<f64>,
    /// The answer.
    pub expected: Vec<f64>,
    /// `given - expected`, per number.
    pub differences: Vec<f64>,
    /// Every number within [`TOLERANCE`].
    pub correct: bool,
    /// The known mistake the prediction matches (within [`TOLERANCE`]), if wrong.
    pub diagnosis: Option<Mistake>,
}

/// The largest absolute difference of two lists of numbers (infinite for lists of different
/// lengths).
fn distance(a: &[f64], b: &[f64]) -> f64 {
    if a.len() != b.len() {
        return f64::INFINITY;
    }
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

impl Expected {
    /// The mistakes a wrong prediction can be diagnosed as: those whose numbers differ from
    /// the answer by more than twice [`TOLERANCE`].
    pub fn diagnosable(&self) -> impl Iterator<Item = &(Mistake, Vec<f64>)> {
        self.mistakes
            .iter()
            .filter(|(_, m)| distance(m, &self.values) > DISTINCT)
    }

    /// Checks a prediction: right when every number is within [`TOLERANCE`] of the answer;
    /// else the differences, and the closest known mistake that the prediction matches within
    /// [`TOLERANCE`] and that differs from the answer by more than twice that.
    ///
    /// ```
    /// use barylab::probe::quiz::{Expected, Mistake, Quantity};
    /// let e = Expected {
    ///     quantity: Quantity::InvW,
    ///     values: vec![0.5],
    ///     mistakes: vec![(Mistake::WOne, vec![1.0])],
    /// };
    /// assert!(e.check(&[0.503]).correct);
    /// let v = e.check(&[1.0]);
    /// assert!(!v.correct);
    /// assert_eq!(v.diagnosis, Some(Mistake::WOne));
    /// assert_eq!(v.differences, vec![0.5]);
    /// ```
    pub fn check(&self, given: &[f64]) -> Verdict {
        let differences: Vec<f64> = if given.len() == self.values.len() {
            given.iter().zip(&self.values).map(|(g, e)| g - e).collect()
        } else {
            Vec::new()
        };
        let correct = distance(given, &self.values) <= TOLERANCE;
        let diagnosis = if correct {
            None
        } else {
            self.diagnosable()
                .map(|(k, m)| (*k, distance(given, m)))
                .filter(|(_, d)| *d <= TOLERANCE)
                // The closest; of mistakes that give the same numbers (r, s, t used as a, b, c
                // and every w = 1 both give r, s, t), the one listed first.
                .fold(None, |best: Option<(Mistake, f64)>, c| match best {
                    Some(b) if b.1 <= c.1 + SAME => Some(b),
                    _ => Some(c),
                })
                .map(|(k, _)| k)
        };
        Verdict {
            quantity: self.quantity,
            given: given.to_vec(),
            expected: self.values.clone(),
            differences,
            correct,
            diagnosis,
        }
    }
}

/// The five other orders of three weights: the two-vertex swaps, then the rotations.
fn other_orders(w: [f64; 3]) -> [[f64; 3]; 5] {
    [
        [w[1], w[0], w[2]],
        [w[0], w[2], w[1]],
        [w[2], w[1], w[0]],
        [w[1], w[2], w[0]],
        [w[2], w[0], w[1]],
    ]
}

/// `w_0 q_0 + w_1 q_1 + w_2 q_2` for a 2-vector attribute `q` (uv) at the three vertices.
fn blend(w: [f64; 3], q: [[f32; 2]; 3]) -> Vec<f64> {
    (0..2)
        .map(|k| (0..3).map(|i| w[i] * f64::from(q[i][k])).sum())
        .collect()
}

/// The answers to `ask` at the pixel of `trace`, with the numbers of each mistake.
///
/// Fails for a pixel no triangle is near, and for a question on a b c, 1/W_P or uv where the
/// pixel has no 1/w correction.
pub fn key(trace: &PixelTrace, ask: &[Quantity]) -> Result<Vec<Expected>, QuizError> {
    let d = trace.detail.as_ref().ok_or(QuizError::NoTriangle)?;
    let screen = d.screen.rasterizer;
    let corners = d.raster.vertices.each_ref().map(|v| DVec2::from(v.window));
    let [x, y] = trace.pixel.map(f64::from);
    // The mistake of the forgotten half pixel: the same weights at the corner (x, y).
    let at_corner = cross_product_weights(DVec2::new(x, y), corners).map(|a| a.weights);
    let perspective = d.perspective.as_ref();
    let need = |q: Quantity| q != Quantity::ScreenWeights;
    if ask.iter().any(|&q| need(q)) && perspective.is_none() {
        return Err(QuizError::NoPerspective);
    }
    let mut out = Vec::with_capacity(ask.len());
    for &q in ask {
        let (values, mistakes) = match (q, perspective) {
            (Quantity::ScreenWeights, p) => {
                let mut m: Vec<(Mistake, Vec<f64>)> = Vec::new();
                if let Some(p) = p {
                    m.push((Mistake::ScreenForPerspective, p.correction.weights.to_vec()));
                }
                m.extend(other_orders(screen).map(|o| (Mistake::VertexOrder, o.to_vec())));
                m.extend(at_corner.map(|c| (Mistake::HalfPixel, c.to_vec())));
                (screen.to_vec(), m)
            }
            (_, None) => return Err(QuizError::NoPerspective),
            (Quantity::Weights, Some(p)) => {
                let abc = p.correction.weights;
                let mut m = vec![(Mistake::ScreenForPerspective, screen.to_vec())];
                if let Some(w1) = w_p_correction(screen, [1.0; 3]) {
                    m.push((Mistake::WOne, w1.weights.to_vec()));
                }
                m.extend(other_orders(abc).map(|o| (Mistake::VertexOrder, o.to_vec())));
                let corner = at_corner.and_then(|c| w_p_correction(c, p.w));
                m.extend(corner.map(|c| (Mistake::HalfPixel, c.weights.to_vec())));
                (abc.to_vec(), m)
            }
            (Quantity::InvW, Some(p)) => {
                let mut m = Vec::new();
                if let Some(w1) = w_p_correction(screen, [1.0; 3]) {
                    m.push((Mistake::WOne, vec![w1.inv_w_p]));
                }
                // r, s, t paired with the wrong vertices' w.
                m.extend(
                    other_orders(screen)
                        .iter()
                        .filter_map(|o| w_p_correction(*o, p.w))
                        .map(|c| (Mistake::VertexOrder, vec![c.inv_w_p])),
                );
                let corner = at_corner.and_then(|c| w_p_correction(c, p.w));
                m.extend(corner.map(|c| (Mistake::HalfPixel, vec![c.inv_w_p])));
                (vec![p.correction.inv_w_p], m)
            }
            (Quantity::Uv, Some(p)) => {
                let a = d.attribute.as_ref().ok_or(QuizError::NoPerspective)?;
                let affine = trace.settings.mode == Interpolation::Affine;
                // The weights and vertex uv of the scene's mode.
                let (weights, uvs, uv) = if affine {
                    (screen, a.uv_vertices_affine, a.uv_affine)
                } else {
                    (p.correction.weights, a.uv_vertices, a.uv_perspective)
                };
                let mut m = Vec::new();
                if !affine {
                    m.push((Mistake::WOne, a.uv_affine.map(f64::from).to_vec()));
                }
                m.extend(other_orders(weights).map(|o| (Mistake::VertexOrder, blend(o, uvs))));
                let corner = at_corner.and_then(|c| {
                    if affine {
                        Some(c)
                    } else {
                        w_p_correction(c, p.w).map(|c| c.weights)
                    }
                });
                m.extend(corner.map(|c| (Mistake::HalfPixel, blend(c, uvs))));
                (uv.map(f64::from).to_vec(), m)
            }
        };
        out.push(Expected {
            quantity: q,
            values,
            mistakes,
        });
    }
    Ok(out)
}

/// Reads a typed number: a decimal (`0.25`, `.25`, `0,25`) or a fraction (`1/4`, `-3/8`).
/// `None` for anything else.
///
/// ```
/// use barylab::probe::quiz::parse_number;
/// assert_eq!(parse_number(" 0.25 "), Some(0.25));
/// assert_eq!(parse_number("0,5"), Some(0.5));
/// assert_eq!(parse_number("3/8"), Some(0.375));
/// assert_eq!(parse_number("1/0"), None);
/// assert_eq!(parse_number("abc"), None);
/// ```
pub fn parse_number(text: &str) -> Option<f64> {
    let t = text.trim().replace(',', ".");
    let value = match t.split_once('/') {
        Some((n, d)) => n.trim().parse::<f64>().ok()? / d.trim().parse::<f64>().ok()?,
        None => t.parse::<f64>().ok()?,
    };
    value.is_finite().then_some(value)
}
