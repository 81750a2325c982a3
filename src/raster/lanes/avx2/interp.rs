//! The interpolation of four samples with AVX2: the planes' values (`R - C`, as
//! [`ScreenPlane`] evaluates them) and, for the shadings that read them, the screen weights;
//! then [`from_planes4!`] makes uv, depth, validity and the wireframe bits of
//! `interpolate::fragment_at_window`, lane for lane.

use std::arch::x86_64::*;

use super::super::Constants;
use super::dot3;
use crate::raster::interpolate::Interpolation;
use crate::raster::setup::{ScreenPlane, WeightPlanes};

/// The weights' row terms `d_x (P_y - S_y)` and column terms `d_y (P_x - S_x)` of four
/// samples, per weight.
#[derive(Clone, Copy)]
pub(super) struct Terms4 {
    pub(super) rows: [__m256d; 3],
    pub(super) columns: [__m256d; 3],
}

/// The column terms at four window x: [`WeightPlanes::column_term`]'s operations.
#[inline]
#[target_feature(enable = "avx2")]
pub(super) fn column_terms4(w: &WeightPlanes, px: __m256d) -> [__m256d; 3] {
    [0, 1, 2].map(|i| {
        let dx = _mm256_sub_pd(px, _mm256_set1_pd(w.start[i].x));
        _mm256_mul_pd(_mm256_set1_pd(w.dir[i].y), dx)
    })
}

/// The screen weights from the terms: [`WeightPlanes::weight_of_terms`],
/// `(row - column) * (1 / area2)`.
#[inline]
#[target_feature(enable = "avx2")]
pub(super) fn weights_of_terms4(w: &WeightPlanes, t: &Terms4) -> [__m256d; 3] {
    [0, 1, 2].map(|i| {
        _mm256_mul_pd(
            _mm256_sub_pd(t.rows[i], t.columns[i]),
            _mm256_set1_pd(w.inv_area2),
        )
    })
}

/// A plane's value from the terms: [`ScreenPlane::part`] of the rows minus that of the
/// columns.
#[inline]
#[target_feature(enable = "avx2")]
pub(super) fn plane4(plane: &ScreenPlane, t: &Terms4) -> __m256d {
    _mm256_sub_pd(dot3(&t.rows, plane.k), dot3(&t.columns, plane.k))
}

/// What the interpolation of four samples starts from.
#[derive(Clone, Copy)]
pub(super) struct At4 {
    /// The values of the planes `1/w`, depth, and the mode's u and v
    /// ([`Constants::uv_planes`]).
    pub(super) values: [__m256d; 4],
    /// The screen weights, where [`Constants::reads_weights`] (else zero).
    pub(super) l: [__m256d; 3],
    /// The other attribute set's u and v planes, where the target wants both uvs (else
    /// zero): `u`, `v` when the mode is perspective-correct, `u/w`, `v/w` when affine.
    pub(super) other: [__m256d; 2],
}

impl At4 {
    /// Everything from the weights' terms of each lane (`uv`: the target may want both uvs).
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(super) fn of_terms(c: &Constants, mode: Interpolation, t: &Terms4, uv: bool) -> Self {
        let planes = c.uv_planes(mode);
        let zero = _mm256_setzero_pd();
        let other = if uv && c.both_uv {
            let o = match mode {
                Interpolation::Perspective => &c.attrs.uv_affine,
                Interpolation::Affine => &c.attrs.uv_over_w,
            };
            [plane4(&o[0], t), plane4(&o[1], t)]
        } else {
            [zero; 2]
        };
        Self {
            values: [
                plane4(&c.attrs.inv_w, t),
                plane4(&c.attrs.depth, t),
                plane4(&planes[0], t),
                plane4(&planes[1], t),
            ],
            l: if c.reads_weights() {
                weights_of_terms4(&c.weights, t)
            } else {
                [zero; 3]
            },
            other,
        }
    }
}

/// A block's eight columns, in two halves of four: the weights' column terms and the
/// column parts of the planes `1/w`, depth and the mode's u and v.
pub(super) struct BlockColumns {
    terms: [[__m256d; 3]; 2],
    parts: [[__m256d; 4]; 2],
}

impl BlockColumns {
    /// The columns from `bx` (pixel centres `bx + 0.5 + k`).
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(super) fn new(w: &WeightPlanes, bx: u32, planes: &[ScreenPlane; 4]) -> Self {
        let px = _mm256_set1_pd(f64::from(bx) + 0.5);
        let terms = [
            column_terms4(w, _mm256_add_pd(px, _mm256_setr_pd(0.0, 1.0, 2.0, 3.0))),
            column_terms4(w, _mm256_add_pd(px, _mm256_setr_pd(4.0, 5.0, 6.0, 7.0))),
        ];
        let mut parts = [[_mm256_setzero_pd(); 4]; 2];
        for h in 0..2 {
            for j in 0..4 {
                parts[h][j] = dot3(&terms[h], planes[j].k);
            }
        }
        Self { terms, parts }
    }

    /// The planes' values in a row with row parts `row`: `R - C`.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(super) fn values(&self, row: &[f64; 4]) -> [At4; 2] {
        let zero = _mm256_setzero_pd();
        let half = |h: usize| {
            let mut values = [zero; 4];
            for j in 0..4 {
                values[j] = _mm256_sub_pd(_mm256_set1_pd(row[j]), self.parts[h][j]);
            }
            At4 {
                values,
                l: [zero; 3],
                other: [zero; 2],
            }
        };
        [half(0), half(1)]
    }

    /// Everything in a row with the weights' row terms `row` ([`At4::of_terms`]).
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(super) fn of_terms(&self, c: &Constants, mode: Interpolation, row: &[f64; 3]) -> [At4; 2] {
        let rows = [
            _mm256_set1_pd(row[0]),
            _mm256_set1_pd(row[1]),
            _mm256_set1_pd(row[2]),
        ];
        let half = |h: usize| {
            let terms = Terms4 {
                rows,
                columns: self.terms[h],
            };
            At4::of_terms(c, mode, &terms, true)
        };
        [half(0), half(1)]
    }
}

/// What `from_planes4!` finds for four samples.
pub(super) struct Four {
    pub(super) u: __m256d,
    pub(super) v: __m256d,
    pub(super) depth: __m256d,
    /// Validity and wireframe bits, lane k in bit k.
    pub(super) ok: i32,
    pub(super) wire: i32,
    /// Wireframe halo bits, lane k in bit k.
    pub(super) halo: i32,
    /// The screen weights (zero unless [`Constants::reads_weights`]).
    pub(super) l: [__m256d; 3],
    /// `1 / (1/w)` (zero when affine without both uvs).
    pub(super) inv: __m256d,
    /// `[u_affine, v_affine, u_smooth, v_smooth]` when [`Constants`] asks for them.
    pub(super) both_uv: Option<[__m256d; 4]>,
}

impl Four {
    /// The weights of the interpolation: perspective-correct `p_i = (l_i / w_i) * inv`, or
    /// the screen weights (the channels of [`Constants`] are `dot3(w, channel)`).
    #[inline]
    #[target_feature(enable = "avx2")]
    pub(super) fn weights(&self, c: &Constants, mode: Interpolation) -> [__m256d; 3] {
        match mode {
            Interpolation::Perspective => [0, 1, 2].map(|i| {
                _mm256_mul_pd(
                    _mm256_mul_pd(self.l[i], _mm256_set1_pd(c.inv_w[i])),
                    self.inv,
                )
            }),
            Interpolation::Affine => self.l,
        }
    }
}

/// uv, depth (f64 lanes) and the validity bits of four samples from [`At4`], as
/// `interpolate::fragment_at_window`: valid where `1/w` is positive and finite, `inv =
/// 1 / (1/w)`, perspective-correct uv `(u/w) * inv`, and the wireframe from the weights.
/// `uv`: whether the target may keep uvs (then [`Constants::both_uv`] is read; a constant
/// `false` takes that code out).
/// (A macro, not a function: it is expanded into each caller, so its vectors stay in
/// registers; a call returns [`Four`](super::Four) through memory. Use it in functions
/// compiled with AVX2.)
macro_rules! from_planes4 {
    ($at:expr, $c:expr, $mode:expr, $uv:expr) => {{
        let (at, c, mode): (interp::At4, &Constants, Interpolation) = ($at, $c, $mode);
        let both = $uv && c.both_uv;
        let [one_over_w, depth, u, v] = at.values;
        let ok = _mm256_and_pd(
            _mm256_cmp_pd::<_CMP_GT_OQ>(one_over_w, _mm256_setzero_pd()),
            _mm256_cmp_pd::<_CMP_LT_OQ>(one_over_w, _mm256_set1_pd(f64::INFINITY)),
        );
        let perspective = mode == Interpolation::Perspective;
        // `1 / (1/w)`, unless nothing reads it (affine, without the heatmap's buffers or the
        // channels): a division saved.
        let inv = if perspective || both {
            _mm256_div_pd(_mm256_set1_pd(1.0), one_over_w)
        } else {
            _mm256_setzero_pd()
        };
        let (u, v) = if perspective {
            (_mm256_mul_pd(u, inv), _mm256_mul_pd(v, inv))
        } else {
            (u, v)
        };
        // uv both ways for the heatmap's buffers, as the lane code computes them.
        let both_uv = both.then(|| {
            let [o0, o1] = at.other;
            if perspective {
                [o0, o1, u, v]
            } else {
                [u, v, _mm256_mul_pd(o0, inv), _mm256_mul_pd(o1, inv)]
            }
        });
        let l = at.l;
        let (mut wire, mut halo) = (0, 0);
        if let Some(wire_consts) = &c.wire {
            for i in 0..3 {
                if wire_consts.len[i] > 0.0 {
                    // `shade::on_wire_edge`, mirrored: the weight as f32, as the varyings hold
                    // it, then over the gradient length.
                    let weight = _mm256_cvtps_pd(_mm256_cvtpd_ps(dot3(&l, wire_consts.bary[i])));
                    let d = _mm256_div_pd(weight, _mm256_set1_pd(wire_consts.len[i]));
                    wire |= _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_LT_OQ>(
                        d,
                        _mm256_set1_pd(WIRE_WIDTH_PX),
                    ));
                    // `shade::on_wire_halo`, mirrored the same way.
                    halo |= _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_LT_OQ>(
                        d,
                        _mm256_set1_pd(WIRE_WIDTH_PX + WIRE_HALO_PX),
                    ));
                }
            }
        }
        Four {
            u,
            v,
            depth,
            ok: _mm256_movemask_pd(ok),
            wire,
            halo,
            l,
            inv,
            both_uv,
        }
    }};
}
