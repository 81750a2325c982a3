//! Texture lookups of the portable lanes: the scalar [`Sampler`]'s operations, one operation
//! at a time over all eight lanes (so the compiler turns each into vector instructions), in
//! the AVX2 sampler's order (`avx2/sampler.rs`): `floor` by truncation, a bilinear sum
//! rounded to a byte as `trunc(sum + HALF_DOWN)`, the texels read unchecked at wrapped
//! indices.

use super::super::sampler::{HALF_DOWN, LaneWrap, Sampler};
use super::super::texture::Filter;
use super::{F32s, I32s, Inf, LANES, Rgba, VectorFloor, each, mask32};

/// Texel indices of eight lanes (`j * width + i`).
type Indices = [u32; LANES];
use crate::raster::texture::MAX_TEXEL_COORD;

/// `x as i32` for an `x` that is not NaN and within +-[`MAX_TEXEL_COORD`]: the truncation.
/// (`as i32` saturates and maps NaN to 0, which the compiler does lane by lane; this is one
/// vector conversion. The callers replace NaN and clamp first.)
#[inline(always)]
fn trunc(x: f32) -> i32 {
    debug_assert!(x.abs() <= MAX_TEXEL_COORD);
    // SAFETY: `x` is finite and within +-1e9 (clamped by the caller, NaN replaced), so its
    // truncation fits an `i32`.
    unsafe { x.to_int_unchecked::<i32>() }
}

/// `(floor(clamp(x)) as i32, floor(clamp(x)))` per lane, as `texture::texel_floor` and the
/// floor inside `texture::bilinear_fraction`: the coordinate clamped to
/// +-[`MAX_TEXEL_COORD`] (NaN as 0, which `texel_floor` gives), truncated, one less where the
/// truncation is above it (a negative non-integer, so below 2^23 in magnitude: `t - 1` is
/// exact in `f32`), and the index converted back: exact, since an index beyond 2^24 is the
/// coordinate itself (an `f32` that large is an integer). One conversion each way, where
/// `fast_floor` then `as i32` take two to the integer. With a vector floor instruction
/// ([`VectorFloor`]) the floor is that instruction and its truncation (the same values: the
/// floor of a clamped coordinate is an integer within +-1e9, exact both ways; a coordinate of
/// -0 keeps its sign as the floor, which only `fraction` reads, where a bilinear coordinate
/// `u w - 1/2` is never -0).
#[inline(always)]
fn floor_coord(x: &F32s, floor: VectorFloor) -> (I32s, F32s) {
    let xc: F32s = each(|k| {
        let c = x[k].clamp(-MAX_TEXEL_COORD, MAX_TEXEL_COORD);
        if c.is_nan() { 0.0 } else { c }
    });
    if floor.0 {
        let f: F32s = each(|k| xc[k].floor());
        return (each(|k| trunc(f[k])), f);
    }
    let t: I32s = each(|k| trunc(xc[k]));
    let i: I32s = each(|k| t[k] + mask32(t[k] as f32 > xc[k]));
    (i, each(|k| i[k] as f32))
}

/// `texture::bilinear_fraction` per lane: `clamp(x - floor, 0, 1)` where `x` is finite,
/// else 0.
#[inline(always)]
fn fraction(x: &F32s, floor: &F32s, inf: Inf) -> F32s {
    let inf = inf.0 as f32;
    each(|k| {
        let t = (x[k] - floor[k]).clamp(0.0, 1.0);
        if x[k].abs() < inf { t } else { 0.0 }
    })
}

/// Coordinates below this in magnitude are "tame" ([`tame`]).
const TAME: f32 = (1 << 22) as f32;

/// Whether every lane of `x` is below 2^22 in magnitude (so not NaN, not infinite): then
/// [`floor_fraction`] gives [`floor_coord`]'s index and [`fraction`]'s value.
#[inline(always)]
fn tame(x: &F32s) -> bool {
    let inside: I32s = each(|k| mask32(x[k].abs() < TAME));
    inside.iter().fold(-1, |m, &i| m & i) != 0
}

/// `(floor(x) as i32, x - floor(x))` per lane for [`tame`] coordinates, with the vector
/// floor ([`VectorFloor`]): [`floor_coord`] and [`fraction`] without their clamps and NaN
/// tests, which change nothing there: the clamp to +-[`MAX_TEXEL_COORD`] keeps `x`, the floor
/// is an integer below 2^22 in magnitude (its truncation is exact), and `x - floor(x)` is
/// `x`'s fractional part, exact (its bits are among `x`'s) and in [0, 1), so the clamp to
/// [0, 1] keeps it. Five vector operations per register fewer for each coordinate of a
/// bilinear lookup.
#[inline(always)]
fn floor_fraction(x: &F32s) -> (I32s, F32s) {
    let f: F32s = each(|k| x[k].floor());
    (each(|k| trunc(f[k])), each(|k| x[k] - f[k]))
}

/// Whether every lane of `x` is [`tame`] and not negative (`0 <= x < 2^22`; NaN fails): then
/// the floor of each is its truncation ([`index_fraction`]).
#[inline(always)]
fn tame_non_negative(x: &F32s) -> bool {
    let inside: I32s = each(|k| mask32(x[k] >= 0.0) & mask32(x[k] < TAME));
    inside.iter().fold(-1, |m, &i| m & i) != 0
}

/// `floor(x) as i32` per lane for [`tame_non_negative`] coordinates: the truncation (the
/// floor of a number at least 0, exact as an `i32` below 2^22), one conversion where
/// [`floor_tame`] first waits for the floor instruction (eight cycles on x86), so that the
/// texel reads, which wait for the index, start sooner: the lookup's longest chain of
/// dependent instructions (coordinate, index, read, blend) is what bounds these lanes, and
/// this shortened it by about a tenth (docs/performance.md).
#[inline(always)]
fn index_non_negative(x: &F32s) -> I32s {
    each(|k| trunc(x[k]))
}

/// [`floor_fraction`] for [`tame_non_negative`] coordinates: the index by
/// [`index_non_negative`], so not behind the floor, which only the fraction `x - floor(x)`
/// waits for (with [`VectorFloor`] the floor instruction, else the truncation converted
/// back: both the floor there, an integer below 2^22, exact).
#[inline(always)]
fn index_fraction(x: &F32s, floor: VectorFloor) -> (I32s, F32s) {
    let i = index_non_negative(x);
    let f: F32s = if floor.0 {
        each(|k| x[k].floor())
    } else {
        each(|k| i[k] as f32)
    };
    (i, each(|k| x[k] - f[k]))
}

/// `floor(x) as i32` per lane for [`tame`] coordinates: [`floor_coord`]'s index without its
/// clamp and NaN replacement, which change nothing there (the clamp keeps `x`, there is no
/// NaN, and the floor is an integer below 2^22 in magnitude, exact as an `i32`). With the
/// vector floor, that floor truncated; without, the truncation, one less where it is above
/// `x`. About a third of a nearest lookup's operations fewer.
#[inline(always)]
fn floor_tame(x: &F32s, floor: VectorFloor) -> I32s {
    if floor.0 {
        return each(|k| trunc(x[k].floor()));
    }
    let t: I32s = each(|k| trunc(x[k]));
    each(|k| t[k] + mask32(t[k] as f32 > x[k]))
}

/// A wrap mode applied to eight texel indices along one axis ([`LaneWrap::apply`]): the mode
/// is matched once, then applied to every lane. Each result is in `0..size`.
#[inline(always)]
fn wrap(i: &I32s, w: LaneWrap) -> I32s {
    match w {
        LaneWrap::Mask(m) => each(|k| i[k] & m),
        LaneWrap::Clamp(hi) => each(|k| i[k].clamp(0, hi)),
        LaneWrap::General(..) => each(|k| w.apply(i[k]) as i32),
    }
}

/// Channel `c` (0 = red) of eight packed texels, as `f32` in 0..255.
#[inline(always)]
fn channel(t: &Rgba, c: u32) -> F32s {
    each(|k| ((t[k] >> (8 * c)) & 0xff) as f32)
}

/// `texture::byte_from_sum` for a bilinear sum, which is never NaN and lies in [0, 255.001]
/// (four non-negative weights adding up to 1 within a few `f32` roundings, times bytes): the
/// clamps and the NaN test change nothing there, and the rounding is `trunc(y + HALF_DOWN)`
/// ([`HALF_DOWN`] has the argument), two vector operations where the truncation, comparison of
/// the rest and correction take five. Checked against the scalar rounding on every float of
/// [0, 255.001] by the test below.
#[inline(always)]
fn bilinear_byte(y: &F32s) -> I32s {
    debug_assert!(y.iter().all(|y| (0.0..=255.001).contains(y)), "{y:?}");
    round_in_place(y, 0)
}

/// `texture::bilinear_weights` per lane: `[(1 - a)(1 - b), a (1 - b), (1 - a) b, a b]` of the
/// fractions `a` (across) and `b` (down).
#[inline(always)]
fn bilinear_weights(a: &F32s, b: &F32s) -> [F32s; 4] {
    let (oa, ob) = (each(|k| 1.0 - a[k]), each(|k| 1.0 - b[k]));
    [
        each(|k| oa[k] * ob[k]),
        each(|k| a[k] * ob[k]),
        each(|k| oa[k] * b[k]),
        each(|k| a[k] * b[k]),
    ]
}

/// `sum_k weight_k * channel_k`, left to right, rounded to a byte.
#[inline(always)]
fn weighted(w: &[F32s; 4], t: &[Rgba; 4], c: u32) -> I32s {
    let mut sum = each(|k| w[0][k] * channel(&t[0], c)[k]);
    for n in 1..4 {
        let ch = channel(&t[n], c);
        sum = each(|k| sum[k] + w[n][k] * ch[k]);
    }
    bilinear_byte(&sum)
}

/// [`weighted`] for channel `c` of 0, 1 or 2 computed on the channel's bits where they lie,
/// `2^(8c)` times the byte (an `and` per texel where [`channel`] also shifts, and no shift to
/// pack): the result's bits from `8c` on are the rounded byte, the bits below arbitrary.
///
/// The same byte: a channel in place is `2^(8c)` times the byte exactly (below 2^24), and every
/// product and sum, and the addition of `2^(8c)` [`HALF_DOWN`], is `2^(8c)` times
/// [`weighted`]'s exactly, since scaling by a power of two commutes with rounding for normal
/// floats (a bilinear fraction of a coordinate `u w - 1/2` is 0 or at least 2^-26, so the
/// values are 0 or at least about 2^-52, and at most 2^24); the truncation of `2^(8c) t` for
/// [`weighted`]'s `t >= 0` has the truncation of `t`, the byte, in its bits from `8c` on. The
/// test below compares the packed colours with [`weighted`]'s.
#[inline(always)]
fn weighted_in_place(w: &[F32s; 4], t: &[Rgba; 4], c: u32) -> I32s {
    let bits = 0xff << (8 * c);
    let channel = |t: &Rgba| each(|k| (t[k] & bits) as i32 as f32);
    let mut sum = each(|k| w[0][k] * channel(&t[0])[k]);
    for n in 1..4 {
        let ch = channel(&t[n]);
        sum = each(|k| sum[k] + w[n][k] * ch[k]);
    }
    round_in_place(&sum, c)
}

/// [`bilinear_byte`] of `2^(8c)` times a sum: `trunc(y + 2^(8c) HALF_DOWN)`, `2^(8c)` times
/// [`bilinear_byte`]'s rounded sum exactly, so its bits from `8c` on are the byte (the test
/// below checks every float of [0, 255.001], scaled).
#[inline(always)]
fn round_in_place(y: &F32s, c: u32) -> I32s {
    let half = HALF_DOWN * (1 << (8 * c)) as f32;
    each(|k| trunc(y[k] + half))
}

/// The packed colour of [`weighted_in_place`]'s red, green and blue and the bytes `alpha`.
#[inline(always)]
fn pack_in_place(r: &I32s, g: &I32s, b: &I32s, alpha: &I32s) -> Rgba {
    each(|k| (r[k] & 0xff | g[k] & 0xff00 | b[k] & 0xff_0000 | alpha[k] << 24) as u32)
}

impl Sampler<'_> {
    /// The index `j * width + i` in `texels` of eight wrapped texel coordinates (each in
    /// `0..width` and `0..height`), as [`Sampler::texel`] reads it: below the number of
    /// texels, which is below 2^31 where these lanes draw ([`super::applies`]), so 32-bit
    /// products (one vector multiplication, or a shift when the width is a power of two).
    #[inline(always)]
    fn index(&self, i: &I32s, j: &I32s) -> Indices {
        if let Some(shift) = self.width_shift {
            return each(|k| ((j[k] as u32) << shift) + i[k] as u32);
        }
        let width = self.width as u32;
        each(|k| j[k] as u32 * width + i[k] as u32)
    }

    /// The packed texels (red in the low byte) at indices `at`, each a texel index: made by
    /// [`Sampler::index`] from wrapped coordinates ([`wrap`] puts each in `0..width` and
    /// `0..height`, so `j * width + i <= width * height - 1`), as the AVX2 gathers read them.
    #[inline(always)]
    fn fetch(&self, at: &Indices) -> Rgba {
        debug_assert!(at.iter().all(|&a| (a as usize) < self.texels.len()));
        // SAFETY: every index is below `width * height = texels.len()` (above).
        each(|k| u32::from_le_bytes(unsafe { *self.texels.get_unchecked(at[k] as usize) }))
    }

    /// The packed texels at indices `at` and beside them, `at + 1` (the texels `(i, j)` and
    /// `(i + 1, j)` where `i + 1` is inside the row, which the caller checks: then `at + 1` is
    /// the texel index of `(i + 1, j)`): two 4-byte reads per lane at one address (read as one
    /// 8-byte value they were split lane by lane, in scalar registers).
    #[inline(always)]
    fn fetch_pairs(&self, at: &Indices) -> (Rgba, Rgba) {
        debug_assert!(at.iter().all(|&a| (a as usize) + 1 < self.texels.len()));
        let base = self.texels.as_ptr();
        // SAFETY: `at + 1` is the index of a texel of the same row for every lane (above), so
        // both reads are below `texels.len()`.
        let read = |k: usize, d: usize| unsafe { *base.add(at[k] as usize + d) };
        (
            each(|k| u32::from_le_bytes(read(k, 0))),
            each(|k| u32::from_le_bytes(read(k, 1))),
        )
    }

    /// The packed RGBA8 colours (red in the low byte) at eight uv, as [`Sampler::sample`]
    /// gives them.
    #[inline(always)]
    pub(super) fn sample_packed(&self, u: &F32s, v: &F32s, inf: Inf, floor: VectorFloor) -> Rgba {
        let (w, h) = self.size;
        match self.filter {
            // One texel of weight 1: the colour is the texel (see the parent module).
            Filter::Nearest => {
                let x = each(|k| u[k] * w);
                let y = each(|k| v[k] * h);
                let (i, j) = if tame_non_negative(&x) && tame_non_negative(&y) {
                    (index_non_negative(&x), index_non_negative(&y))
                } else if tame(&x) && tame(&y) {
                    (floor_tame(&x, floor), floor_tame(&y, floor))
                } else {
                    (floor_coord(&x, floor).0, floor_coord(&y, floor).0)
                };
                let (i, j) = (wrap(&i, self.wrap.0), wrap(&j, self.wrap.1));
                self.fetch(&self.index(&i, &j))
            }
            _ => {
                let x = each(|k| u[k] * w - 0.5);
                let y = each(|k| v[k] * h - 0.5);
                let ((i0, a), (j0, b)) = if tame_non_negative(&x) && tame_non_negative(&y) {
                    (index_fraction(&x, floor), index_fraction(&y, floor))
                } else if floor.0 && tame(&x) && tame(&y) {
                    (floor_fraction(&x), floor_fraction(&y))
                } else {
                    let (i0, fx) = floor_coord(&x, floor);
                    let (j0, fy) = floor_coord(&y, floor);
                    ((i0, fraction(&x, &fx, inf)), (j0, fraction(&y, &fy, inf)))
                };
                let (ia, ib) = (
                    wrap(&i0, self.wrap.0),
                    wrap(&each(|k| i0[k] + 1), self.wrap.0),
                );
                let (ja, jb) = (
                    wrap(&j0, self.wrap.1),
                    wrap(&each(|k| j0[k] + 1), self.wrap.1),
                );
                let (at_a, at_b) = (self.index(&ia, &ja), self.index(&ia, &jb));
                // Where every right neighbour is beside its texel (not wrapped to the row's
                // start), each row's two texels are one read.
                let beside = each(|k| mask32(ib[k] == ia[k] + 1));
                let texels = if beside.iter().fold(-1, |m, &b| m & b) != 0 {
                    let (t00, t10) = self.fetch_pairs(&at_a);
                    let (t01, t11) = self.fetch_pairs(&at_b);
                    [t00, t10, t01, t11]
                } else {
                    [
                        self.fetch(&at_a),
                        self.fetch(&self.index(&ib, &ja)),
                        self.fetch(&at_b),
                        self.fetch(&self.index(&ib, &jb)),
                    ]
                };
                let weights = bilinear_weights(&a, &b);
                let r = weighted_in_place(&weights, &texels, 0);
                let g = weighted_in_place(&weights, &texels, 1);
                let b = weighted_in_place(&weights, &texels, 2);
                // An opaque texture's alpha sum is 255 (see `VecSampler::opaque`).
                let a = if self.opaque {
                    [255; LANES]
                } else {
                    weighted(&weights, &texels, 3)
                };
                pack_in_place(&r, &g, &b, &a)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::raster::texture::byte_from_sum;

    /// Every float from 0 to 255.001 (the range of a bilinear sum) rounds to the byte the
    /// scalar code gives, also scaled by 256 and 65536 (a channel in place).
    #[test]
    fn every_bilinear_sum_rounds_as_the_scalar_code() {
        let last = 255.001f32.to_bits();
        let mut wrong = Vec::new();
        let mut bits = 0u32;
        while bits <= last && wrong.len() < 10 {
            let xs: super::F32s =
                std::array::from_fn(|k| f32::from_bits((bits + k as u32).min(last)));
            for (x, got) in xs.iter().zip(super::bilinear_byte(&xs)) {
                if got != i32::from(byte_from_sum(*x)) {
                    wrong.push((*x, got));
                }
            }
            // Scaled by 256 and 65536 (green and blue in place): the bits from 8 and 16 on.
            for c in [1, 2] {
                let scaled = xs.map(|x| x * (1 << (8 * c)) as f32);
                for (x, got) in xs.iter().zip(super::round_in_place(&scaled, c)) {
                    if got >> (8 * c) != i32::from(byte_from_sum(*x)) {
                        wrong.push((*x, got));
                    }
                }
            }
            bits += super::LANES as u32;
        }
        assert!(wrong.is_empty(), "rounded differently: {wrong:?}");
    }

    /// `weighted_in_place` and `pack_in_place` give the colour `weighted` and the shifts give,
    /// on random texels (with many bytes of 0 and 255) and the weights of random bilinear
    /// fractions, and with a weight of 1.
    #[test]
    fn channels_in_place_give_the_shifted_bytes() {
        use super::{F32s, LANES, Rgba, each, pack_in_place, weighted, weighted_in_place};
        use crate::raster::texture::bilinear_fraction;
        let mut next = crate::raster::lanes::xorshift(0x2545_f491_4f6c_dd1d);
        for n in 0..20_000 {
            let mut fraction = || bilinear_fraction((next() % 200_000) as f32 / 64.0 - 1000.5);
            let a: F32s = each(|_| fraction());
            let b: F32s = if n % 5 == 0 {
                [1.0; LANES]
            } else {
                each(|_| fraction())
            };
            let texels: [Rgba; 4] = std::array::from_fn(|_| {
                each(|_| match next() % 8 {
                    0 => 0,
                    1 => u32::MAX,
                    r => (next() >> r) as u32,
                })
            });
            let w = super::bilinear_weights(&a, &b);
            let alpha = weighted(&w, &texels, 3);
            let got = pack_in_place(
                &weighted_in_place(&w, &texels, 0),
                &weighted_in_place(&w, &texels, 1),
                &weighted_in_place(&w, &texels, 2),
                &alpha,
            );
            let (r, g, b) = (
                weighted(&w, &texels, 0),
                weighted(&w, &texels, 1),
                weighted(&w, &texels, 2),
            );
            let want: Rgba = each(|k| (r[k] | g[k] << 8 | b[k] << 16 | alpha[k] << 24) as u32);
            assert_eq!(got, want, "a {a:?}, b {b:?}, texels {texels:?}");
        }
    }

    /// For tame coordinates the short floor and fraction (and the nearest lookup's short floor,
    /// with and without the vector floor), and for tame coordinates not negative the index by
    /// truncation, give the general code's index and fraction bit for bit: multiples of 1/8
    /// around zero, both signs of zero, tiny values, fractions just below and above integers,
    /// and the largest tame magnitudes.
    #[test]
    fn tame_coordinates_floor_as_the_general_code() {
        use super::{
            Inf, LANES, VectorFloor, floor_coord, floor_fraction, floor_tame, fraction,
            index_fraction, index_non_negative, tame, tame_non_negative,
        };
        let below = |x: f32| f32::from_bits(x.to_bits() - 1);
        let mut xs: Vec<f32> = (-4096..4096).map(|k| k as f32 / 8.0).collect();
        xs.extend([
            0.0,
            -0.0,
            1e-30,
            -1e-30,
            below(1.0),
            -below(1.0),
            1.0 + f32::EPSILON,
        ]);
        xs.extend([
            below(4194304.0),
            -below(4194304.0),
            4194303.5,
            -4194303.5,
            -2.5e6 - 0.25,
        ]);
        for chunk in xs.chunks(LANES) {
            let mut x = [0.5f32; LANES];
            x[..chunk.len()].copy_from_slice(chunk);
            assert!(tame(&x), "{x:?}");
            let (i, f) = floor_coord(&x, VectorFloor(true));
            let a = fraction(&x, &f, Inf::new());
            let (i_tame, a_tame) = floor_fraction(&x);
            assert_eq!(i, i_tame, "{x:?}");
            assert_eq!(a.map(f32::to_bits), a_tame.map(f32::to_bits), "{x:?}");
            for vector_floor in [true, false] {
                let floor = VectorFloor(vector_floor);
                assert_eq!(floor_tame(&x, floor), floor_coord(&x, floor).0, "{x:?}");
                assert_eq!(floor_tame(&x, floor), i, "{x:?}");
            }
        }
        // Not negative: the index by truncation, the fraction as the general code gives it
        // (both floors; a coordinate of -0, which a bilinear coordinate never is, gives the
        // general code's -0 or 0 too).
        let non_negative: Vec<f32> = xs.iter().copied().filter(|&x| x >= 0.0).collect();
        assert!(non_negative.len() > 4000);
        for chunk in non_negative.chunks(LANES) {
            let mut x = [0.5f32; LANES];
            x[..chunk.len()].copy_from_slice(chunk);
            assert!(tame_non_negative(&x), "{x:?}");
            for vector_floor in [true, false] {
                let floor = VectorFloor(vector_floor);
                let (i, f) = floor_coord(&x, floor);
                let a = fraction(&x, &f, Inf::new());
                let (i_short, a_short) = index_fraction(&x, floor);
                assert_eq!(i, i_short, "{x:?}");
                assert_eq!(i, index_non_negative(&x), "{x:?}");
                assert_eq!(a.map(f32::to_bits), a_short.map(f32::to_bits), "{x:?}");
            }
        }
        let lanes = |last: f32| std::array::from_fn(|k| if k == LANES - 1 { last } else { 0.5 });
        for x in [-1e-30, -0.25, 4194304.0, f32::NAN, f32::INFINITY] {
            assert!(!tame_non_negative(&lanes(x)), "{x}");
        }
        assert!(tame_non_negative(&lanes(below(4194304.0))));
        assert!(!tame(&[4194304.0; LANES]));
        assert!(!tame(&[0.5, f32::NAN, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5]));
        assert!(!tame(&[
            0.5,
            0.5,
            0.5,
            0.5,
            0.5,
            0.5,
            0.5,
            f32::NEG_INFINITY
        ]));
    }
}
