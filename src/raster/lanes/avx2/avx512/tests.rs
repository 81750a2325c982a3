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
/// and in the AVX2 lanes (each checked where the CPU has it).
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
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = move |n: u32| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % u64::from(n)) as i32
    };
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
