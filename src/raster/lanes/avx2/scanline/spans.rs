//! The chunks of gathered short spans of the scanline lanes: each lane computes its span's
//! start values and its own number of single steps, with the row path's operations.

use super::*;

/// Interpolates, shades and writes the next (up to) eight gathered pixels of short spans.
/// Lane by lane, the operations of the row path: the start values of the lane's span
/// ([`Stepped::span_start`]: its screen weights at the span's first pixel, then
/// [`Stepped::from_weights`]), then `k` single steps (`step`), so the same values bit for bit.
#[inline]
#[target_feature(enable = "avx2")]
pub(super) fn draw_spans<const SITE: u8, const WIDE: bool>(
    g: &mut sparse::SpanGathered,
    (consts, step): (&Constants, &Stepped),
    shading: &LaneShading,
    sampler: Option<&VecSampler<'_>>,
    lookups: &mut Lookups,
    target: &mut Target<'_>,
) {
    let (x, y, k, bits) = g.take();
    let at = sparse::indices(target, x, y);
    let first = _mm256_sub_epi32(x, k);
    let lanes = |h: usize| {
        let half = |v: __m256i| {
            if h == 0 {
                _mm256_castsi256_si128(v)
            } else {
                _mm256_extracti128_si256::<1>(v)
            }
        };
        Four {
            first: half(first),
            y: half(y),
            k: half(k),
        }
    };
    let mode = shading.mode;
    // The high half only when a pixel waits there (most small triangles fill four lanes at
    // most); else its lanes copy the low half's, and are not written.
    let both = bits > 0xf;
    if let Some(sampler) = sampler {
        let q = |h| {
            let v = start_values::<0, true>(&lanes(h), consts, step, mode);
            [v.u, v.v, v.inv_w, v.depth]
        };
        let lo = q(0);
        let hi = if both { q(1) } else { lo };
        return push_stepped::<SITE, WIDE>(
            &[lo, hi],
            bits,
            Where::Lanes(at),
            mode,
            sampler,
            lookups,
            target,
        );
    }
    match consts.used_channels {
        0 => colour_spans::<SITE, WIDE, 0>(lanes, both, bits, at, (consts, step), shading, target),
        3 => colour_spans::<SITE, WIDE, 3>(lanes, both, bits, at, (consts, step), shading, target),
        _ => colour_spans::<SITE, WIDE, CHANNELS>(
            lanes,
            both,
            bits,
            at,
            (consts, step),
            shading,
            target,
        ),
    }
}

/// Four gathered pixels: their spans' first columns, their rows and their places `k` in
/// their spans.
struct Four {
    first: __m128i,
    y: __m128i,
    k: __m128i,
}

/// What [`start_values`] computes for four lanes (`u` and `v` only with `UV`, the first `N`
/// channels).
struct FourValues<const N: usize> {
    u: __m256d,
    v: __m256d,
    inv_w: __m256d,
    depth: __m256d,
    ch: [__m256d; N],
}

/// The values of four gathered pixels: [`Stepped::span_start`] and `k` single steps, lane
/// by lane, with the same operations.
#[inline]
#[target_feature(enable = "avx2")]
fn start_values<const N: usize, const UV: bool>(
    p: &Four,
    c: &Constants,
    step: &Stepped,
    mode: Interpolation,
) -> FourValues<N> {
    {
        let l = sparse::weights4(&c.weights, sparse::centres(p.first), sparse::centres(p.y));
        // `Stepped::from_weights`: sums from zero, vertex by vertex.
        let scale = match mode {
            Interpolation::Perspective => [
                _mm256_mul_pd(l[0], _mm256_set1_pd(c.inv_w[0])),
                _mm256_mul_pd(l[1], _mm256_set1_pd(c.inv_w[1])),
                _mm256_mul_pd(l[2], _mm256_set1_pd(c.inv_w[2])),
            ],
            Interpolation::Affine => l,
        };
        let sum = |w: &[__m256d; 3], a: &[f64; 3]| {
            let mut s = _mm256_setzero_pd();
            for i in 0..3 {
                s = _mm256_add_pd(s, _mm256_mul_pd(w[i], _mm256_set1_pd(a[i])));
            }
            s
        };
        let zero = _mm256_setzero_pd();
        let mut v = FourValues {
            u: if UV { sum(&scale, &c.u) } else { zero },
            v: if UV { sum(&scale, &c.v) } else { zero },
            inv_w: sum(&l, &c.inv_w),
            depth: sum(&l, &c.depth),
            ch: [zero; N],
        };
        for j in 0..N {
            v.ch[j] = sum(&scale, &c.channels[j]);
        }
        // Then `k` single steps: lane by lane, the steps while `k` is above their count.
        let k64 = _mm256_cvtepi32_epi64(p.k);
        for i in 0..LANES as i64 - 1 {
            let more = _mm256_cmpgt_epi64(k64, _mm256_set1_epi64x(i));
            if _mm256_testz_si256(more, more) != 0 {
                break;
            }
            let more = _mm256_castsi256_pd(more);
            let add =
                |x: __m256d, d: f64| _mm256_blendv_pd(x, _mm256_add_pd(x, _mm256_set1_pd(d)), more);
            if UV {
                v.u = add(v.u, step.u);
                v.v = add(v.v, step.v);
            }
            v.inv_w = add(v.inv_w, step.inv_w);
            v.depth = add(v.depth, step.depth);
            for j in 0..N {
                v.ch[j] = add(v.ch[j], step.ch[j]);
            }
        }
        v
    }
}

/// [`draw_spans`] for a non-texture colour reading `N` channels: as `colour_span`.
#[allow(clippy::too_many_arguments)]
#[inline]
#[target_feature(enable = "avx2")]
fn colour_spans<const SITE: u8, const WIDE: bool, const N: usize>(
    lanes: impl Fn(usize) -> Four,
    both: bool,
    bits: i32,
    at: __m256i,
    (consts, step): (&Constants, &Stepped),
    shading: &LaneShading,
    target: &mut Target<'_>,
) {
    let mode = shading.mode;
    let values = |h: usize| {
        let v = start_values::<N, false>(&lanes(h), consts, step, mode);
        let valid = _mm256_and_pd(
            _mm256_cmp_pd::<_CMP_GT_OQ>(v.inv_w, _mm256_setzero_pd()),
            _mm256_cmp_pd::<_CMP_LT_OQ>(v.inv_w, _mm256_set1_pd(f64::INFINITY)),
        );
        let mut ch = v.ch;
        if mode == Interpolation::Perspective {
            let w = _mm256_div_pd(_mm256_set1_pd(1.0), v.inv_w);
            for c in ch.iter_mut() {
                *c = _mm256_mul_pd(*c, w);
            }
        }
        (_mm256_movemask_pd(valid), v.depth, ch)
    };
    let lo = values(0);
    let hi = if both { values(1) } else { lo };
    let ok = bits & (lo.0 | (hi.0 << 4));
    if ok == 0 {
        return;
    }
    let channel = |j: usize| to_f32(lo.2[j], hi.2[j]);
    let rgba = channel_colors::<SITE, WIDE>([lo.1, hi.1], channel, shading.color);
    let chunk = Pending {
        u: _mm256_setzero_ps(),
        v: _mm256_setzero_ps(),
        depth: to_f32(lo.1, hi.1),
        valid: mask_from_bits(ok),
        wire: 0,
        halo: 0,
        index: 0,
        lanes: Some(at),
    };
    // SAFETY: this function runs with AVX2 (and AVX-512 F, BW, VL and DQ when `WIDE`, the
    // callers' condition); the valid lanes are gathered pixels of spans inside the image, at
    // their own buffer indices (`finish`'s conditions).
    unsafe { finish::<WIDE>(target, &chunk, rgba, None) }
}
