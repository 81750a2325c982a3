//! The colours of the non-texture shadings for eight lanes, as `shade` makes them.

use super::*;

/// `unorm8(x)`: `round(clamp(x, 0, 1) * 255)`, half away from zero (NaN gives 0).
#[inline]
#[target_feature(enable = "avx2")]
fn unorm8(x: __m256) -> __m256i {
    let y = _mm256_mul_ps(
        _mm256_min_ps(_mm256_max_ps(x, _mm256_setzero_ps()), _mm256_set1_ps(1.0)),
        _mm256_set1_ps(255.0),
    );
    let t = _mm256_round_ps::<{ _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC }>(y);
    let up = _mm256_cmp_ps::<_CMP_GE_OQ>(_mm256_sub_ps(y, t), _mm256_set1_ps(0.5));
    _mm256_cvttps_epi32(_mm256_add_ps(t, _mm256_and_ps(up, _mm256_set1_ps(1.0))))
}

/// Red, green, blue bytes and an opaque alpha packed into eight RGBA8 lanes.
#[inline]
#[target_feature(enable = "avx2")]
fn pack_opaque(r: __m256i, g: __m256i, b: __m256i) -> __m256i {
    _mm256_or_si256(
        _mm256_or_si256(r, _mm256_slli_epi32::<8>(g)),
        _mm256_or_si256(
            _mm256_slli_epi32::<16>(b),
            _mm256_set1_epi32(0xff00_0000_u32 as i32),
        ),
    )
}

/// `shade::unit_normal` of eight normals, operation for operation:
/// `len = sqrt(x x + y y + z z)`, `n / len` when `len` is finite and at least
/// [`MIN_NORMAL_LENGTH`], else `(0, 0, 1)`.
#[inline]
#[target_feature(enable = "avx2")]
fn unit_normal(n: [__m256; 3]) -> [__m256; 3] {
    let sq = |x: __m256| _mm256_mul_ps(x, x);
    let len = _mm256_sqrt_ps(_mm256_add_ps(_mm256_add_ps(sq(n[0]), sq(n[1])), sq(n[2])));
    let ok = _mm256_and_ps(
        _mm256_cmp_ps::<_CMP_LT_OQ>(len, _mm256_set1_ps(f32::INFINITY)),
        _mm256_cmp_ps::<_CMP_GE_OQ>(len, _mm256_set1_ps(MIN_NORMAL_LENGTH)),
    );
    let unit = |x: __m256, otherwise: f32| {
        _mm256_blendv_ps(_mm256_set1_ps(otherwise), _mm256_div_ps(x, len), ok)
    };
    [unit(n[0], 0.0), unit(n[1], 0.0), unit(n[2], 1.0)]
}

/// The colours of the non-texture shadings for eight samples, as `shade` makes them, from
/// their depths (`f64`, lanes 0..4 and 4..8) and `ch(c)`, channel `c` of [`Constants`]
/// interpolated, as `f32` (called only for the channels the shading reads). `SITE` and
/// `WIDE`: one copy per caller, see `Lookups::push`.
#[inline]
#[target_feature(enable = "avx2")]
pub(super) fn channel_colors<const SITE: u8, const WIDE: bool>(
    [lo_depth, hi_depth]: [__m256d; 2],
    ch: impl Fn(usize) -> __m256,
    color: LaneColor,
) -> __m256i {
    match color {
        LaneColor::Depth(near, far) => {
            // `shade::depth_grey`, mirrored.
            let grey = if far > near {
                let scale = |d: __m256d| {
                    _mm256_div_pd(
                        _mm256_sub_pd(d, _mm256_set1_pd(near)),
                        _mm256_set1_pd(far - near),
                    )
                };
                unorm8(to_f32(scale(lo_depth), scale(hi_depth)))
            } else {
                _mm256_setzero_si256()
            };
            pack_opaque(grey, grey, grey)
        }
        LaneColor::Normal | LaneColor::Lambert => {
            if color == LaneColor::Normal {
                let n = unit_normal([ch(0), ch(1), ch(2)]);
                // `shade::normal_rgba8`: unorm8((n̂ + 1) * 0.5) per channel.
                let c = |x: __m256| {
                    unorm8(_mm256_mul_ps(
                        _mm256_add_ps(x, _mm256_set1_ps(1.0)),
                        _mm256_set1_ps(0.5),
                    ))
                };
                return pack_opaque(c(n[0]), c(n[1]), c(n[2]));
            }
            // The normal is in channels 3..6, the albedo (vertex colour) in 0..3.
            let n = unit_normal([ch(3), ch(4), ch(5)]);
            // `shade::lambert_factor`: AMBIENT + (1 - AMBIENT) max(0, n̂.z).
            let f = _mm256_add_ps(
                _mm256_set1_ps(AMBIENT),
                _mm256_mul_ps(
                    _mm256_set1_ps(1.0 - AMBIENT),
                    _mm256_max_ps(n[2], _mm256_setzero_ps()),
                ),
            );
            let c = |a: __m256| unorm8(_mm256_mul_ps(a, f));
            pack_opaque(c(ch(0)), c(ch(1)), c(ch(2)))
        }
        _ => pack_opaque(unorm8(ch(0)), unorm8(ch(1)), unorm8(ch(2))),
    }
}
