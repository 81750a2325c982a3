//! Tests of the AVX-512 lanes' helpers against the scalar code and the gather.

use std::arch::x86_64::*;

use crate::raster::texture::byte_from_sum;

/// The floats from 0 to 255.001 (the range of a bilinear sum) that `round` rounds
/// differently from the scalar code (at most ten), sixteen at a time.
fn wrong_roundings(round: impl Fn(&[f32; 16]) -> [i32; 16]) -> Vec<(f32, i32)> {
    let last = 255.001f32.to_bits();
    let mut wrong = Vec::new();
    let mut bits = 0u32;
    while bits <= last && wrong.len() < 10 {
        let xs: [f32; 16] = std::array::from_fn(|k| f32::from_bits((bits + k as u32).min(last)));
        for (x, got) in xs.iter().zip(round(&xs)) {
            if got != i32::from(byte_from_sum(*x)) {
                wrong.push((*x, got));
            }
        }
        bits += 16;
    }
    wrong
}

/// Every float from 0 to 255.001 rounds to the byte the scalar code gives, in the AVX-512
/// lanes (also scaled by 256 and 65536, as a channel in place) and in the AVX2 lanes (each
/// checked where the CPU has it).
#[test]
fn every_bilinear_sum_rounds_as_the_scalar_code() {
    if is_x86_feature_detected!("avx512f") {
        let wrong = wrong_roundings(|xs| {
            let mut out = [0i32; 16];
            // SAFETY: the CPU has AVX-512 F (checked above); 16 lanes in and out.
            unsafe {
                let v = super::byte_from_sum(_mm512_loadu_ps(xs.as_ptr()));
                _mm512_storeu_si512(out.as_mut_ptr().cast(), v);
            }
            out
        });
        assert!(wrong.is_empty(), "AVX-512 rounded differently: {wrong:?}");
    }
    if is_x86_feature_detected!("avx512f") {
        // Scaled by 256 and 65536 (green and blue in place), the bits from 8 and 16 on.
        for c in [1, 2] {
            let wrong = wrong_roundings(|xs| {
                let mut out = [0i32; 16];
                let scale = (1 << (8 * c)) as f32;
                // SAFETY: the CPU has AVX-512 F (checked above); 16 lanes in and out.
                unsafe {
                    let y = _mm512_mul_ps(_mm512_loadu_ps(xs.as_ptr()), _mm512_set1_ps(scale));
                    let v = if c == 1 {
                        super::round_in_place::<1>(y)
                    } else {
                        super::round_in_place::<2>(y)
                    };
                    _mm512_storeu_si512(out.as_mut_ptr().cast(), v);
                }
                out.map(|t| t >> (8 * c))
            });
            assert!(
                wrong.is_empty(),
                "AVX-512 in place ({c}) rounded differently: {wrong:?}"
            );
        }
    }
    if is_x86_feature_detected!("avx2") {
        let wrong = wrong_roundings(|xs| {
            let mut out = [0i32; 16];
            for h in 0..2 {
                // SAFETY: the CPU has AVX2 (checked above); 8 lanes in and out.
                unsafe {
                    let x = _mm256_loadu_ps(xs[8 * h..].as_ptr());
                    let v = super::super::sampler::byte_from_sum(x);
                    _mm256_storeu_si256(out[8 * h..].as_mut_ptr().cast(), v);
                }
            }
            out
        });
        assert!(wrong.is_empty(), "AVX2 rounded differently: {wrong:?}");
    }
}

/// `row_block` picks the texels the gather reads, wherever it applies: spans of one row
/// and pairs of rows of eight, near the texture's last texel too (where it declines), on
/// a power-of-two and an odd width; and it applies to a magnified span.
#[test]
fn row_blocks_of_nearest_pick_the_gathered_texels() {
    use super::super::sampler::{VecSampler, VecWrap};
    use crate::raster::texture::Filter;
    if !is_x86_feature_detected!("avx512f") {
        return;
    }
    let mut random = crate::raster::lanes::xorshift(0x2545_f491_4f6c_dd1d);
    let mut next = move |n: u32| (random() % u64::from(n)) as i32;
    for (w, h) in [(64u32, 8u32), (37, 5)] {
        let texels: Vec<[u8; 4]> = (0..w * h)
            .map(|k| (k.wrapping_mul(2_654_435_761)).to_le_bytes())
            .collect();
        let s = VecSampler {
            texels: &texels,
            width: w as i32,
            width_shift: w.is_power_of_two().then_some(w.trailing_zeros() as i32),
            size: (w as f32, h as f32),
            wrap: (VecWrap::Clamp(w as i32 - 1), VecWrap::Clamp(h as i32 - 1)),
            filter: Filter::Nearest,
            opaque: false,
        };
        let (mut picked, mut declined) = (0, 0);
        for case in 0..4000 {
            let (j0, j1) = (next(h), if case % 2 == 0 { next(h) } else { -1 });
            let spread = [4, 16, 32, 40][case % 4];
            let i0 = next(w);
            let i: [i32; 16] = std::array::from_fn(|_| (i0 + next(spread)).min(w as i32 - 1));
            let j: [i32; 16] = std::array::from_fn(|k| if k >= 8 && j1 >= 0 { j1 } else { j0 });
            // SAFETY: the CPU has AVX-512 F (checked above); the arrays are 64 bytes.
            let (got, want) = unsafe {
                let iv = _mm512_loadu_si512(i.as_ptr().cast());
                let jv = _mm512_loadu_si512(j.as_ptr().cast());
                (super::row_block(&s, iv, jv), super::gather(&s, iv, jv))
            };
            let Some(got) = got else {
                declined += 1;
                continue;
            };
            picked += 1;
            let (mut a, mut b) = ([0i32; 16], [0i32; 16]);
            // SAFETY: as above.
            unsafe {
                _mm512_storeu_si512(a.as_mut_ptr().cast(), got);
                _mm512_storeu_si512(b.as_mut_ptr().cast(), want);
            }
            assert_eq!(a, b, "width {w}, i {i:?}, j {j:?}");
        }
        assert!(
            picked > 1000 && declined > 100,
            "{picked} picked, {declined} declined"
        );
    }
    // A magnified span: sixteen pixels over a few texels of one row qualify.
    let texels = vec![[1u8, 2, 3, 4]; 64 * 64];
    let s = VecSampler {
        texels: &texels,
        width: 64,
        width_shift: Some(6),
        size: (64.0, 64.0),
        wrap: (VecWrap::Mask(63), VecWrap::Mask(63)),
        filter: Filter::Nearest,
        opaque: true,
    };
    // SAFETY: the CPU has AVX-512 F (checked above).
    let got = unsafe {
        let i = _mm512_setr_epi32(3, 3, 3, 4, 4, 4, 5, 5, 5, 6, 6, 6, 7, 7, 7, 8);
        super::row_block(&s, i, _mm512_set1_epi32(9))
    };
    assert!(got.is_some());
}

/// Random floats for the helpers' tests: every exponent (so huge, tiny and subnormal values),
/// both signs, the infinities and NaN, and coordinates of a texture (within a few thousand).
fn test_floats(count: usize) -> Vec<f32> {
    let mut next = crate::raster::lanes::xorshift(0x9e37_79b9_7f4a_7c15);
    let mut xs = vec![
        0.0,
        -0.0,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        super::MAX_TEXEL_COORD,
        -super::MAX_TEXEL_COORD,
        super::MAX_TEXEL_COORD.next_up(),
        (-super::MAX_TEXEL_COORD).next_down(),
        -f32::MIN_POSITIVE / 2.0,
        f32::MIN_POSITIVE / 2.0,
        -0.5,
        -1.0,
        -1.0f32.next_up(),
        -1.0f32.next_down(),
    ];
    while xs.len() < count {
        let r = next();
        xs.push(match r % 3 {
            0 => f32::from_bits((r as u32).rotate_right(1)),
            1 => (r >> 8) as u32 as f32 / (1u64 << 32) as f32 * 8192.0 - 4096.0,
            _ => f32::from_bits((r >> 40) as u32) - 0.5,
        });
    }
    xs
}

/// The short paths of `floor_and_fraction` (and of the nearest lookup's `floor_index`) give
/// the index and fraction of the general one (`floor_coord` and `fraction`) on every lane,
/// sixteen lanes of random floats at a time, whether all sixteen are in range (the short
/// path) or not; in the AVX-512 lanes and, eight lanes at a time and also with the signs
/// cleared (the AVX2 lanes' path for coordinates at least 0), in the AVX2 lanes (each where
/// the CPU has it).
#[test]
fn floor_and_fraction_matches_the_clamped_floor() {
    use super::super::sampler as avx2;
    if !is_x86_feature_detected!("avx512f") {
        return;
    }
    let xs = test_floats(64_000);
    let (mut short, mut long) = (0, 0);
    for (n, lanes) in xs.chunks_exact(16).enumerate() {
        // Every fourth group with a lane out of range, to exercise the general path too.
        let mut lanes: [f32; 16] = lanes.try_into().expect("sixteen lanes");
        if n % 4 != 0 {
            for x in &mut lanes {
                if x.is_nan() || x.abs() > super::MAX_TEXEL_COORD {
                    *x = 0.25;
                }
            }
            short += 1;
        } else {
            long += 1;
        }
        let (mut i, mut a, mut i_ref, mut a_ref) = ([0i32; 16], [0f32; 16], [0i32; 16], [0f32; 16]);
        let mut nearest = [0i32; 16];
        // SAFETY: the CPU has AVX-512 F (checked above); 16 lanes in and out.
        unsafe {
            let x = _mm512_loadu_ps(lanes.as_ptr());
            let (gi, ga) = super::floor_and_fraction(x);
            let (ri, rf) = super::floor_coord(x);
            let ni = super::floor_index(x);
            _mm512_storeu_si512(i.as_mut_ptr().cast(), gi);
            _mm512_storeu_si512(nearest.as_mut_ptr().cast(), ni);
            _mm512_storeu_ps(a.as_mut_ptr(), ga);
            _mm512_storeu_si512(i_ref.as_mut_ptr().cast(), ri);
            _mm512_storeu_ps(a_ref.as_mut_ptr(), super::fraction(x, rf));
        }
        assert_eq!(i, i_ref, "{lanes:?}");
        assert_eq!(nearest, i_ref, "nearest, {lanes:?}");
        assert_eq!(a.map(f32::to_bits), a_ref.map(f32::to_bits), "{lanes:?}");
        // Eight at a time as they are, and with every sign cleared (the AVX2 lanes' path for
        // coordinates at least 0, which the random signs rarely give all eight of).
        let cleared = lanes.map(|x| f32::from_bits(x.to_bits() & 0x7fff_ffff));
        for half in lanes.chunks_exact(8).chain(cleared.chunks_exact(8)) {
            let (mut i, mut a, mut i_ref, mut a_ref) = ([0i32; 8], [0f32; 8], [0i32; 8], [0f32; 8]);
            let mut nearest = [0i32; 8];
            // SAFETY: the CPU has AVX-512 F, so AVX2 (checked above); 8 lanes in and out.
            unsafe {
                let x = _mm256_loadu_ps(half.as_ptr());
                let (gi, ga) = avx2::floor_and_fraction(x);
                let (ri, rf) = avx2::floor_coord(x);
                _mm256_storeu_si256(i.as_mut_ptr().cast(), gi);
                _mm256_storeu_si256(nearest.as_mut_ptr().cast(), avx2::floor_index(x));
                _mm256_storeu_ps(a.as_mut_ptr(), ga);
                _mm256_storeu_si256(i_ref.as_mut_ptr().cast(), ri);
                _mm256_storeu_ps(a_ref.as_mut_ptr(), avx2::fraction(x, rf));
            }
            assert_eq!(i, i_ref, "AVX2, {half:?}");
            assert_eq!(nearest, i_ref, "AVX2 nearest, {half:?}");
            assert_eq!(
                a.map(f32::to_bits),
                a_ref.map(f32::to_bits),
                "AVX2, {half:?}"
            );
        }
    }
    assert!(short > 2000 && long > 900, "{short} short, {long} long");
}

/// `weighted_in_place` and `pack_in_place` give the colours of `weighted` and the shifts, on
/// random texels and on the weights of random fractions (`texture::bilinear_weights`), and on
/// the extremes (texels of 0 and 255, a weight of 1).
#[test]
fn channels_in_place_give_the_shifted_bytes() {
    if !is_x86_feature_detected!("avx512bw") {
        return;
    }
    let fractions = test_floats(40_000)
        .into_iter()
        .map(|x| crate::raster::texture::bilinear_fraction(x * 0.001))
        .collect::<Vec<_>>();
    let mut random = crate::raster::lanes::xorshift(0x2545_f491_4f6c_dd1d);
    let mut texel = move || {
        let r = random();
        match r % 8 {
            0 => 0,
            1 => u32::MAX,
            _ => r as u32,
        }
    };
    for (n, ab) in fractions.chunks_exact(32).enumerate() {
        let texels: [[u32; 16]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| texel()));
        let (mut got, mut want) = ([0u32; 16], [0u32; 16]);
        // SAFETY: the CPU has AVX-512 F and BW (checked above); 16 lanes in and out.
        unsafe {
            let a = _mm512_loadu_ps(ab.as_ptr());
            let b = if n % 5 == 0 {
                _mm512_set1_ps(1.0)
            } else {
                _mm512_loadu_ps(ab[16..].as_ptr())
            };
            let weights = super::bilinear_weights(a, b);
            let t = texels.map(|t| _mm512_loadu_si512(t.as_ptr().cast()));
            let alpha = super::weighted::<3>(&weights, &t);
            let packed = super::pack_in_place(
                super::weighted_in_place::<0>(&weights, &t),
                super::weighted_in_place::<1>(&weights, &t),
                super::weighted_in_place::<2>(&weights, &t),
                alpha,
            );
            let shifted = _mm512_or_si512(
                _mm512_or_si512(
                    super::weighted::<0>(&weights, &t),
                    _mm512_slli_epi32::<8>(super::weighted::<1>(&weights, &t)),
                ),
                _mm512_or_si512(
                    _mm512_slli_epi32::<16>(super::weighted::<2>(&weights, &t)),
                    _mm512_slli_epi32::<24>(alpha),
                ),
            );
            _mm512_storeu_si512(got.as_mut_ptr().cast(), packed);
            _mm512_storeu_si512(want.as_mut_ptr().cast(), shifted);
        }
        assert_eq!(got, want, "fractions {ab:?}, texels {texels:?}");
    }
}

/// `all_beside` says whether every lane's `wrap(i + 1)` is `wrap(i) + 1`, as wrapping both and
/// comparing does, for masks and clamps near the edges of the texture (and far outside), and
/// `wrap_one` wraps as each lane of `wrap` does.
#[test]
fn all_beside_matches_wrapping_the_neighbour() {
    use super::super::sampler::VecWrap;
    if !is_x86_feature_detected!("avx512f") {
        return;
    }
    let mut random = crate::raster::lanes::xorshift(0x9e37_79b9_7f4a_7c15);
    let mut next = move |n: i64| (random() % n as u64) as i64;
    let (mut yes, mut no) = (0, 0);
    for case in 0..20_000 {
        let size = [1, 2, 8, 64, 37][case % 5];
        let wrap = if case % 2 == 0 && (size as u32).is_power_of_two() {
            VecWrap::Mask(size - 1)
        } else {
            VecWrap::Clamp(size - 1)
        };
        // Columns near 0 and near the size, mostly all beside, sometimes one at an edge.
        let base = next(4 * i64::from(size)) - 2 * i64::from(size);
        let i: [i32; 16] = std::array::from_fn(|_| {
            let d = if next(40) == 0 {
                next(1 << 31) - (1 << 30)
            } else {
                next(3)
            };
            (base + d) as i32
        });
        // SAFETY: the CPU has AVX-512 F (checked above); 16 lanes in and out.
        let (got, want, wrapped) = unsafe {
            let iv = _mm512_loadu_si512(i.as_ptr().cast());
            let ia = super::wrap(iv, wrap);
            let ib = super::wrap(_mm512_add_epi32(iv, _mm512_set1_epi32(1)), wrap);
            let mut out = [0i32; 16];
            _mm512_storeu_si512(out.as_mut_ptr().cast(), ia);
            (
                super::all_beside(iv, ia, wrap),
                _mm512_cmpeq_epi32_mask(ib, _mm512_add_epi32(ia, _mm512_set1_epi32(1))) == 0xffff,
                out,
            )
        };
        assert_eq!(got, want, "size {size}, i {i:?}");
        assert_eq!(wrapped, i.map(|i| super::wrap_one(i, wrap)), "size {size}");
        if got { yes += 1 } else { no += 1 }
    }
    assert!(yes > 1000 && no > 1000, "{yes} beside, {no} not");
}

/// `column_offsets` gives the smallest column and every lane's offset from it whenever all
/// lie within the window (whichever of its tries applies: columns growing along the lanes,
/// shrinking, or in any order), and declines otherwise.
#[test]
fn column_offsets_are_from_the_smallest_column() {
    if !is_x86_feature_detected!("avx512f") {
        return;
    }
    let mut random = crate::raster::lanes::xorshift(0x9e37_79b9_7f4a_7c15);
    let mut next = move |n: i32| (random() % n as u64) as i32;
    let mut found = [0; 3];
    for case in 0..30_000 {
        let base = next(4000);
        let spread = [8, 30, 31, 40][case % 4];
        let mut i: [i32; 16] = std::array::from_fn(|_| base + next(spread));
        match case % 3 {
            0 => i.sort_unstable(),
            1 => i.sort_unstable_by(|a, b| b.cmp(a)),
            _ => {}
        }
        let (lo, hi) = (i.iter().min().copied(), i.iter().max().copied());
        let (Some(lo), Some(hi)) = (lo, hi) else {
            unreachable!("sixteen lanes")
        };
        // SAFETY: the CPU has AVX-512 F (checked above); the arrays are 64 bytes.
        let got = unsafe {
            super::column_offsets(_mm512_loadu_si512(i.as_ptr().cast()), 30).map(|(i0, d)| {
                let mut offsets = [0i32; 16];
                _mm512_storeu_si512(offsets.as_mut_ptr().cast(), d);
                (i0, offsets)
            })
        };
        if hi - lo <= 30 {
            assert_eq!(got, Some((lo, i.map(|x| x - lo))), "{i:?}");
            found[case % 3] += 1;
        } else {
            assert_eq!(got, None, "{i:?}");
        }
    }
    assert!(found.iter().all(|&n| n > 2000), "{found:?}");
}
