//! The scanline lanes with AVX2 intrinsics (see the parent module); the chunks of gathered
//! short spans are in `scanline/spans.rs`.

use super::*;

mod spans;

use spans::draw_spans;

/// The scanline body of both entries (`avx2::draw` and `avx512::draw`), inlined into each
/// (so compiled for each one's instruction set). It walks the rows' spans; every intrinsic is
/// in the AVX2 functions it calls (which inline into an AVX-512 caller too).
///
/// # Safety
/// The CPU has AVX2, and AVX-512 F, BW, VL and DQ when `WIDE`.
#[inline(always)]
pub(super) unsafe fn scanline_triangle_body<const WIDE: bool>(
    tri: &LaneTriangle,
    (y_start, y_end): (u32, u32),
    sampler: Option<&VecSampler<'_>>,
    shading: &LaneShading,
    target: &mut Target<'_>,
) {
    let (mode, color) = (shading.mode, shading.color);
    let sampler = match sampler {
        Some(s) if color == LaneColor::Texture => Some(s),
        // Texture shading always has a sampler here (see `Lanes::draw`).
        _ if color == LaneColor::Texture => return,
        _ => None,
    };
    let consts = &tri.consts;
    // The increments along a row, made when a span of more than one pixel needs them (a
    // dense mesh's rows are often one pixel).
    let mut step = None;
    let mut lookups = Lookups::new(sampler, WIDE);
    let mut gathered = sparse::SpanGathered::new();
    // SAFETY: here and in the calls below: the function's condition (AVX2, and AVX-512 when
    // `WIDE`) is what these functions need; the spans are the rows' exact spans, inside the
    // triangle's bounds and so inside the image.
    let mut spans = unsafe { RowSpans::new(tri, y_start) };
    // A narrow triangle's spans (at most eight pixels) are all gathered.
    let narrow = spans.narrow.is_some();
    for y in y_start..=y_end {
        // SAFETY: as above.
        let Some((x0, x1)) = (unsafe { spans.next(y) }) else {
            continue;
        };
        if x1 > x0 && step.is_none() {
            step = Some(Stepped::row_step(consts, mode));
        }
        if narrow || x1 - x0 < sparse::MAX_LANES {
            // SAFETY: as above.
            unsafe { gathered.add(x0, x1, y) };
            if gathered.full() {
                // An opaque reference: the constants are loaded when a chunk is drawn,
                // not before the loop for every triangle (see `narrow_rows`).
                let consts = std::hint::black_box(consts);
                let step = step.as_ref().unwrap_or(&ZERO_STEP);
                let drawn = (consts, step);
                // SAFETY: as above.
                unsafe {
                    draw_spans::<11, WIDE>(
                        &mut gathered,
                        drawn,
                        shading,
                        sampler,
                        &mut lookups,
                        target,
                    )
                };
            }
            continue;
        }
        let step = step.unwrap_or_default();
        let start = Stepped::span_start(consts, mode, x0, y);
        let span = ((y - target.y0) as usize * target.width as usize, x0, x1);
        match sampler {
            // SAFETY: as above.
            None => unsafe { colour_span::<WIDE>(&start, &step, span, consts, shading, target) },
            // SAFETY: as above.
            Some(sampler) => unsafe {
                texture_span::<WIDE>(&start, &step, span, mode, sampler, &mut lookups, target)
            },
        }
    }
    // At most seven pixels are left (a chunk is drawn whenever eight wait): one chunk.
    if !gathered.is_empty() {
        let step = step.as_ref().unwrap_or(&ZERO_STEP);
        // SAFETY: as above.
        unsafe {
            draw_spans::<12, WIDE>(
                &mut gathered,
                (consts, step),
                shading,
                sampler,
                &mut lookups,
                target,
            )
        };
        debug_assert!(gathered.is_empty());
    }
    // SAFETY: as above.
    unsafe { lookups.flush(sampler, target) };
}

/// The chunks of one span of texture shading longer than [`sparse::MAX_LANES`] pixels: its
/// columns `x0..=x1` of the band row whose first pixel is buffer index `row`. Lane k holds
/// pixel `x0 + k`, reached by k single steps from `start`; then eight steps per chunk (with
/// AVX-512, sixteen pixels at a time, `avx512::wide_span`).
///
/// # Safety
/// The CPU has AVX2 (this function's feature), and AVX-512 F, BW, VL and DQ when `WIDE`;
/// the span is inside the image.
#[inline]
#[target_feature(enable = "avx2")]
unsafe fn texture_span<const WIDE: bool>(
    start: &Stepped,
    step: &Stepped,
    (row, x0, x1): (usize, u32, u32),
    mode: Interpolation,
    sampler: &VecSampler<'_>,
    lookups: &mut Lookups,
    target: &mut Target<'_>,
) {
    let lanes = Stepped::lanes(*start, step);
    if WIDE {
        // SAFETY: the function's condition: AVX-512 when `WIDE`, the span inside the image.
        unsafe { super::avx512::wide_span(&lanes, step, (row, x0, x1), mode, sampler, target) };
        return;
    }
    let load = |f: fn(&Stepped) -> f64, h: usize| {
        _mm256_setr_pd(
            f(&lanes[4 * h]),
            f(&lanes[4 * h + 1]),
            f(&lanes[4 * h + 2]),
            f(&lanes[4 * h + 3]),
        )
    };
    // [u, v, 1/w, depth] x [lanes 0..4, lanes 4..8] (written out: `array::map` was
    // left as a call).
    let half = |h: usize| {
        [
            load(|s| s.u, h),
            load(|s| s.v, h),
            load(|s| s.inv_w, h),
            load(|s| s.depth, h),
        ]
    };
    let mut vals = [half(0), half(1)];
    let n = _mm256_set1_pd(LANES as f64);
    let step8 = [
        _mm256_mul_pd(_mm256_set1_pd(step.u), n),
        _mm256_mul_pd(_mm256_set1_pd(step.v), n),
        _mm256_mul_pd(_mm256_set1_pd(step.inv_w), n),
        _mm256_mul_pd(_mm256_set1_pd(step.depth), n),
    ];
    let mut x = x0;
    while x <= x1 {
        let lanes_in = (x1 - x + 1).min(LANES as u32);
        let at = Where::Row(row + x as usize);
        push_stepped::<10, WIDE>(
            &vals,
            (1i32 << lanes_in) - 1,
            at,
            mode,
            sampler,
            lookups,
            target,
        );
        for half in vals.iter_mut() {
            for (q, s) in half.iter_mut().zip(&step8) {
                *q = _mm256_add_pd(*q, *s);
            }
        }
        x += LANES as u32;
    }
}

/// No increments (the row step of a triangle whose spans are single pixels: never read).
const ZERO_STEP: Stepped = Stepped {
    u: 0.0,
    v: 0.0,
    inv_w: 0.0,
    depth: 0.0,
    ch: [0.0; CHANNELS],
};

/// The covered span of each row in turn, as [`row_span_of`] finds it. For a triangle at most
/// [`LANES`] columns wide (a dense mesh's) it is read from the exact edge values of the
/// row's eight pixels instead ([`NarrowRows`]): the same columns (the covered samples of a row
/// are one run, and both tests are exact), without `row_span_of`'s three integer divisions
/// per row.
struct RowSpans<'t> {
    tri: &'t LaneTriangle,
    narrow: Option<NarrowRows>,
}

impl<'t> RowSpans<'t> {
    /// Spans from row `y` on.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn new(tri: &'t LaneTriangle, y: u32) -> Self {
        let narrow = tri.bounds.x1 - tri.bounds.x0 < LANES as u32 && tri.exact();
        Self {
            tri,
            narrow: narrow.then(|| NarrowRows::new(tri, y)),
        }
    }

    /// The covered columns `[x0, x1]` of row `y`, the row after the last one asked for (or
    /// the first row).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn next(&mut self, y: u32) -> Option<(u32, u32)> {
        match self.narrow.as_mut() {
            Some(rows) => {
                let covered = rows.next_row();
                // An `if`, not `bool::then`: that was left as a call, once per row.
                if covered == 0 {
                    return None;
                }
                // One run of lanes (a convex triangle's samples on a row).
                debug_assert_eq!(
                    covered.count_ones(),
                    32 - covered.leading_zeros() - covered.trailing_zeros()
                );
                let x0 = self.tri.bounds.x0;
                Some((
                    x0 + covered.trailing_zeros(),
                    x0 + 31 - covered.leading_zeros(),
                ))
            }
            None => row_span_of(&self.tri.edges, self.tri.bounds, y),
        }
    }
}

/// The chunks of one span with a non-texture colour (vertex colour, weights, depth, normal,
/// Lambert): the channels are stepped like uv (divided by w when perspective-correct, then
/// multiplied by `1 / (1/w)`), as the scalar scanline lanes do. Spans of more than
/// [`sparse::MAX_LANES`] pixels come here (shorter ones are gathered, `spans.rs`).
#[inline]
#[target_feature(enable = "avx2")]
fn colour_span<const WIDE: bool>(
    start: &Stepped,
    step: &Stepped,
    (row, x0, x1): (usize, u32, u32),
    consts: &Constants,
    shading: &LaneShading,
    target: &mut Target<'_>,
) {
    const H: usize = 2;
    let used = consts.used_channels;
    // Lane k is the span's start after k single steps, as `Stepped::lanes` makes it (only
    // the values this colour reads, only the pixels of the span).
    let lanes = (x1 - x0 + 1).min(4 * H as u32) as usize;
    let load = |s: f64, d: f64| {
        let mut a = [s; LANES];
        for k in 1..lanes {
            a[k] = a[k - 1] + d;
        }
        let mut v = [_mm256_setzero_pd(); H];
        for (h, v) in v.iter_mut().enumerate() {
            *v = _mm256_setr_pd(a[4 * h], a[4 * h + 1], a[4 * h + 2], a[4 * h + 3]);
        }
        v
    };
    let n = LANES as f64;
    let mut inv_w = load(start.inv_w, step.inv_w);
    let mut depth = load(start.depth, step.depth);
    let mut ch = [[_mm256_setzero_pd(); CHANNELS]; H];
    for j in 0..used {
        for (h, v) in load(start.ch[j], step.ch[j]).into_iter().enumerate() {
            ch[h][j] = v;
        }
    }
    let mut x = x0;
    while x <= x1 {
        let lanes_in = (x1 - x + 1).min(LANES as u32);
        let mut ok = (1i32 << lanes_in) - 1;
        for h in 0..H {
            let valid = _mm256_and_pd(
                _mm256_cmp_pd::<_CMP_GT_OQ>(inv_w[h], _mm256_setzero_pd()),
                _mm256_cmp_pd::<_CMP_LT_OQ>(inv_w[h], _mm256_set1_pd(f64::INFINITY)),
            );
            ok &= !((!_mm256_movemask_pd(valid) & 0xf) << (4 * h));
        }
        if ok != 0 {
            let mut channels = [[_mm256_setzero_pd(); CHANNELS]; H];
            for (h, f) in channels.iter_mut().enumerate() {
                let w = match shading.mode {
                    Interpolation::Perspective => {
                        Some(_mm256_div_pd(_mm256_set1_pd(1.0), inv_w[h]))
                    }
                    Interpolation::Affine => None,
                };
                for j in 0..used {
                    f[j] = match w {
                        Some(w) => _mm256_mul_pd(ch[h][j], w),
                        None => ch[h][j],
                    };
                }
            }
            let channel = |j: usize| to_f32(channels[0][j], channels[H - 1][j]);
            let depths = [depth[0], depth[H - 1]];
            let rgba = channel_colors::<13, WIDE>(depths, channel, shading.color);
            let chunk = Pending {
                u: _mm256_setzero_ps(),
                v: _mm256_setzero_ps(),
                depth: to_f32(depth[0], depth[H - 1]),
                valid: mask_from_bits(ok),
                wire: 0,
                halo: 0,
                index: row + x as usize,
                lanes: None,
            };
            // SAFETY: this function runs with AVX2 (and AVX-512 F, BW, VL and DQ when `WIDE`,
            // the callers' condition); the valid lanes are columns of the row's span
            // `x0..=x1`, inside the image (`finish`'s conditions).
            unsafe { finish::<WIDE>(target, &chunk, rgba, None) };
        }
        x += LANES as u32;
        if x > x1 {
            break;
        }
        // Only a span of more than eight pixels gets here.
        let (inv_w8, depth8) = (
            _mm256_set1_pd(step.inv_w * n),
            _mm256_set1_pd(step.depth * n),
        );
        for h in 0..H {
            inv_w[h] = _mm256_add_pd(inv_w[h], inv_w8);
            depth[h] = _mm256_add_pd(depth[h], depth8);
            for j in 0..used {
                ch[h][j] = _mm256_add_pd(ch[h][j], _mm256_set1_pd(step.ch[j] * n));
            }
        }
    }
}

/// uv, depth and the lanes to write of one chunk of the scanline lanes from its stepped
/// values (`[lanes 0..4, lanes 4..8]` of `[u, v, 1/w, depth]`): the lanes of `ok` whose
/// `1/w` is positive and finite; uv is `(u/w) * (1 / (1/w))` when perspective-correct.
#[inline]
#[target_feature(enable = "avx2")]
fn stepped_chunk(
    vals: &[[__m256d; 4]; 2],
    mut ok: i32,
    mode: Interpolation,
) -> (__m256, __m256, __m256, i32) {
    let mut uv = [[_mm256_setzero_pd(); 2]; 2];
    for (h, v) in vals.iter().enumerate() {
        let valid = _mm256_and_pd(
            _mm256_cmp_pd::<_CMP_GT_OQ>(v[2], _mm256_setzero_pd()),
            _mm256_cmp_pd::<_CMP_LT_OQ>(v[2], _mm256_set1_pd(f64::INFINITY)),
        );
        if _mm256_movemask_pd(valid) != 0xf {
            ok &= !((!_mm256_movemask_pd(valid) & 0xf) << (4 * h));
        }
        uv[h] = match mode {
            Interpolation::Perspective => {
                let w = _mm256_div_pd(_mm256_set1_pd(1.0), v[2]);
                [_mm256_mul_pd(v[0], w), _mm256_mul_pd(v[1], w)]
            }
            Interpolation::Affine => [v[0], v[1]],
        };
    }
    (
        to_f32(uv[0][0], uv[1][0]),
        to_f32(uv[0][1], uv[1][1]),
        to_f32(vals[0][3], vals[1][3]),
        ok,
    )
}

/// Hands one chunk of the scanline lanes, from its stepped values, to the texture lookups
/// (which write it).
#[allow(clippy::too_many_arguments)]
#[inline]
#[target_feature(enable = "avx2")]
fn push_stepped<const SITE: u8, const WIDE: bool>(
    vals: &[[__m256d; 4]; 2],
    ok: i32,
    at: Where,
    mode: Interpolation,
    sampler: &VecSampler<'_>,
    lookups: &mut Lookups,
    target: &mut Target<'_>,
) {
    let (u, v, depth, ok) = stepped_chunk(vals, ok, mode);
    if ok != 0 {
        let (index, lanes) = at.parts();
        let chunk = Pending {
            u,
            v,
            depth,
            valid: mask_from_bits(ok),
            wire: 0,
            halo: 0,
            index,
            lanes,
        };
        lookups.push::<SITE, WIDE>(sampler, target, chunk, None);
    }
}
