//! The lane paths written with AVX2 intrinsics: the same operations in the same order as
//! the portable lane code in the parent module (and so as the per-pixel renderer), eight
//! pixels per instruction. Chosen at run time when the CPU has AVX2 and the texture's wrap
//! is a mask or a clamp on both axes; tests check the two agree bit for bit.
//! The texture lookups are in `avx2/texture.rs`.

use std::arch::x86_64::*;

use super::{
    BLOCK_ROWS, Block, CHANNELS, Constants, LANES, LaneColor, LaneShading, LaneTriangle, LaneWrap,
    Stepped, Target, classify,
};
use crate::raster::interpolate::Interpolation;
use crate::raster::scanline::row_span_of;
use crate::raster::setup::WeightPlanes;
use crate::raster::shade::{
    AMBIENT, MIN_NORMAL_LENGTH, WIRE_COLOR, WIRE_HALO_COLOR, WIRE_HALO_PX, WIRE_WIDTH_PX,
};
use crate::raster::texture::{Filter, MAX_TEXEL_COORD, Texture};

mod texture;

use texture::sample;
pub(super) use texture::{VecSampler, VecWrap};

/// A chunk of eight pixels whose colours are still to be looked up.
struct Pending {
    u: __m256,
    v: __m256,
    depth: __m256,
    /// Lanes to write.
    valid: __m256i,
    /// Lanes on a wireframe line.
    wire: i32,
    /// Lanes in the wireframe's halo (the line wins where both are set).
    halo: i32,
    /// Buffer index of lane 0.
    index: usize,
    /// Buffer index of lane 4: `index + 4` for eight pixels of one row, or the start of the
    /// next row for the small-triangle path's two rows of four.
    index_hi: usize,
    /// `[u_affine, v_affine, u_smooth, v_smooth]` for a target with uv buffers.
    both_uv: Option<[__m256; 4]>,
}

/// Texture lookups of chunks: one at a time with AVX2, or two at a time with AVX-512.
struct Lookups<'s, 'a> {
    sampler: &'s VecSampler<'a>,
    wide: bool,
    pending: Option<Pending>,
}

impl<'s, 'a> Lookups<'s, 'a> {
    fn new(sampler: &'s VecSampler<'a>, wide: bool) -> Self {
        Self {
            sampler,
            // Measured: pairs pay for bilinear filtering (four lookups), not for nearest.
            wide: wide && sampler.filter != Filter::Nearest,
            pending: None,
        }
    }

    /// Shades and writes `chunk`, now or together with the next one.
    #[target_feature(enable = "avx2")]
    fn push(&mut self, target: &mut Target<'_>, chunk: Pending) {
        if !self.wide {
            let rgba = sample(self.sampler, chunk.u, chunk.v);
            finish(target, &chunk, rgba);
            return;
        }
        match self.pending.take() {
            None => self.pending = Some(chunk),
            Some(first) => {
                // SAFETY: `wide` is set only when the CPU has AVX-512 F and BW (`wide_path`).
                let (a, b) = unsafe {
                    super::avx512::sample16(self.sampler, (first.u, first.v), (chunk.u, chunk.v))
                };
                finish(target, &first, a);
                finish(target, &chunk, b);
            }
        }
    }

    /// Shades and writes a chunk still waiting for a partner.
    #[target_feature(enable = "avx2")]
    fn flush(&mut self, target: &mut Target<'_>) {
        if let Some(chunk) = self.pending.take() {
            let rgba = sample(self.sampler, chunk.u, chunk.v);
            finish(target, &chunk, rgba);
        }
    }
}

/// Paints the wireframe over a chunk's colours and writes it.
#[inline]
#[target_feature(enable = "avx2")]
fn finish(target: &mut Target<'_>, chunk: &Pending, mut rgba: __m256i) {
    if chunk.halo != 0 {
        rgba = _mm256_blendv_epi8(
            rgba,
            _mm256_set1_epi32(i32::from_le_bytes(WIRE_HALO_COLOR)),
            mask_from_bits(chunk.halo),
        );
    }
    if chunk.wire != 0 {
        rgba = _mm256_blendv_epi8(
            rgba,
            _mm256_set1_epi32(i32::from_le_bytes(WIRE_COLOR)),
            mask_from_bits(chunk.wire),
        );
    }
    let at = [chunk.index, chunk.index_hi];
    let pass = write(target, at, chunk.valid, chunk.depth, rgba);
    if let (Some(uv), Some(both)) = (target.uv.as_mut(), &chunk.both_uv) {
        store_uv(uv, at, pass, both);
    }
}

/// Writes the source triangle and both uvs of the lanes in `pass` (lanes 0-3 from buffer
/// index `at[0]` of the band, lanes 4-7 from `at[1]`): the uv pairs are interleaved in
/// registers and stored with masks, as `write` stores the colour.
#[inline]
#[target_feature(enable = "avx2")]
fn store_uv(uv: &mut super::UvTarget<'_>, at: [usize; 2], pass: __m256i, both: &[__m256; 4]) {
    debug_assert!(
        uv.triangle.len() == uv.uv_affine.len() && uv.triangle.len() == uv.uv_perspective.len()
    );
    // Lane k's mask for both halves of its pair: (m0 m0 m1 m1 m2 m2 m3 m3), (m4 m4 ... m7 m7).
    let m_lo = _mm256_unpacklo_epi32(pass, pass);
    let m_hi = _mm256_unpackhi_epi32(pass, pass);
    let masks = [
        _mm256_permute2x128_si256::<0x20>(m_lo, m_hi),
        _mm256_permute2x128_si256::<0x31>(m_lo, m_hi),
    ];
    // (u0 v0 u1 v1 u2 v2 u3 v3), (u4 v4 ... u7 v7).
    let pairs = |u: __m256, v: __m256| {
        let lo = _mm256_unpacklo_ps(u, v);
        let hi = _mm256_unpackhi_ps(u, v);
        [
            _mm256_permute2f128_ps::<0x20>(lo, hi),
            _mm256_permute2f128_ps::<0x31>(lo, hi),
        ]
    };
    let affine = pairs(both[0], both[1]);
    let perspective = pairs(both[2], both[3]);
    let source = _mm_set1_epi32(uv.source as i32);
    let bits = _mm256_movemask_ps(_mm256_castsi256_ps(pass));
    for h in 0..2 {
        // A half with no lane to write is skipped: its index may lie past the band.
        if (bits >> (4 * h)) & 0xf == 0 {
            continue;
        }
        let index = at[h];
        debug_assert!(index < uv.triangle.len());
        let half_mask = if h == 0 {
            _mm256_castsi256_si128(pass)
        } else {
            _mm256_extracti128_si256::<1>(pass)
        };
        // SAFETY: as in `write`: `pass` enables only lanes of pixels inside the band's rows,
        // so every element written (`index + k` of this half, its two floats) is inside the
        // three buffers, which have the colour buffer's length; masked stores touch no other
        // element, and a half without enabled lanes is not addressed at all.
        unsafe {
            _mm_maskstore_epi32(
                uv.triangle.as_mut_ptr().add(index).cast::<i32>(),
                half_mask,
                source,
            );
            let a = uv.uv_affine.as_mut_ptr().add(index).cast::<f32>();
            let p = uv.uv_perspective.as_mut_ptr().add(index).cast::<f32>();
            _mm256_maskstore_ps(a, masks[h], affine[h]);
            _mm256_maskstore_ps(p, masks[h], perspective[h]);
        }
    }
}

/// Depth-tests and writes eight pixels, lanes 0-3 from buffer index `at[0]` of the band and
/// lanes 4-7 from `at[1]` (`at[0] + 4` for eight pixels of one row); lanes outside `ok` are
/// neither read nor written. Returns the lanes that passed.
#[inline]
#[target_feature(enable = "avx2")]
fn write(
    target: &mut Target<'_>,
    at: [usize; 2],
    ok: __m256i,
    depth: __m256,
    rgba: __m256i,
) -> __m256i {
    debug_assert!(target.depth.len() == target.color.len());
    if at[1] == at[0] + 4 {
        let index = at[0];
        debug_assert!(index < target.depth.len());
        // SAFETY: the caller's `ok` enables only lanes of pixels inside the band's row
        // (columns up to the triangle's last column, which is inside the image), so every
        // accessed element `index + k` is in both slices; masked loads and stores touch no
        // other lane.
        unsafe {
            let dp = target.depth.as_mut_ptr().add(index);
            let cp = target.color.as_mut_ptr().add(index).cast::<i32>();
            let old = _mm256_maskload_ps(dp, ok);
            // `framebuffer::depth_passes`, mirrored: an ordered less-than (NaN fails).
            let pass = _mm256_and_si256(
                ok,
                _mm256_castps_si256(_mm256_cmp_ps::<_CMP_LT_OQ>(depth, old)),
            );
            _mm256_maskstore_ps(dp, pass, depth);
            _mm256_maskstore_epi32(cp, pass, rgba);
            return pass;
        }
    }
    // Two runs of four: each half tested and written at its own index, the same operations.
    let bits = _mm256_movemask_ps(_mm256_castsi256_ps(ok));
    let halves = [
        (
            _mm256_castsi256_si128(ok),
            _mm256_castps256_ps128(depth),
            _mm256_castsi256_si128(rgba),
        ),
        (
            _mm256_extracti128_si256::<1>(ok),
            _mm256_extractf128_ps::<1>(depth),
            _mm256_extracti128_si256::<1>(rgba),
        ),
    ];
    let mut pass = [_mm_setzero_si128(); 2];
    for (h, &(ok, depth, rgba)) in halves.iter().enumerate() {
        // A half with no lane to write is skipped: its index may lie past the band.
        if (bits >> (4 * h)) & 0xf == 0 {
            continue;
        }
        let index = at[h];
        debug_assert!(index < target.depth.len());
        // SAFETY: as above, for the four pixels of this half (`ok` enables only pixels inside
        // the band's rows); a half without enabled lanes is not addressed at all.
        unsafe {
            let dp = target.depth.as_mut_ptr().add(index);
            let cp = target.color.as_mut_ptr().add(index).cast::<i32>();
            let old = _mm_maskload_ps(dp, ok);
            let p = _mm_and_si128(ok, _mm_castps_si128(_mm_cmp_ps::<_CMP_LT_OQ>(depth, old)));
            _mm_maskstore_ps(dp, p, depth);
            _mm_maskstore_epi32(cp, p, rgba);
            pass[h] = p;
        }
    }
    _mm256_set_m128i(pass[1], pass[0])
}

/// An eight-lane mask from the low eight bits of `bits`.
#[inline]
#[target_feature(enable = "avx2")]
fn mask_from_bits(bits: i32) -> __m256i {
    let b = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(bits), b), b)
}

/// Two halves of four `f64` lanes converted to eight `f32` lanes.
#[inline]
#[target_feature(enable = "avx2")]
fn to_f32(lo: __m256d, hi: __m256d) -> __m256 {
    _mm256_set_m128(_mm256_cvtpd_ps(hi), _mm256_cvtpd_ps(lo))
}

/// `sum_i w_i x_i`, left to right, as the scalar code adds.
#[inline]
#[target_feature(enable = "avx2")]
fn dot3(w: &[__m256d; 3], x: [f64; 3]) -> __m256d {
    let t = _mm256_add_pd(
        _mm256_mul_pd(w[0], _mm256_set1_pd(x[0])),
        _mm256_mul_pd(w[1], _mm256_set1_pd(x[1])),
    );
    _mm256_add_pd(t, _mm256_mul_pd(w[2], _mm256_set1_pd(x[2])))
}

/// The screen weights at four window x (`px`, pixel centres) of one row, from the row terms
/// `row[i]`: [`WeightPlanes::weight`]'s operations, `(row - d_y (x - S_x)) * (1 / area2)`.
#[inline]
#[target_feature(enable = "avx2")]
fn weights4(w: &WeightPlanes, row: &[f64; 3], px: __m256d) -> [__m256d; 3] {
    // Written out, not with a closure (which would not take the target features, so its
    // vector arguments would go through memory).
    [
        weight4(w, row, px, 0),
        weight4(w, row, px, 1),
        weight4(w, row, px, 2),
    ]
}

/// Weight `i` of [`weights4`].
#[inline]
#[target_feature(enable = "avx2")]
fn weight4(w: &WeightPlanes, row: &[f64; 3], px: __m256d, i: usize) -> __m256d {
    let dx = _mm256_sub_pd(px, _mm256_set1_pd(w.start[i].x));
    let t = _mm256_sub_pd(
        _mm256_set1_pd(row[i]),
        _mm256_mul_pd(_mm256_set1_pd(w.dir[i].y), dx),
    );
    _mm256_mul_pd(t, _mm256_set1_pd(w.inv_area2))
}

/// uv, depth (f64 lanes) and the validity bits of four samples from their screen weights, as
/// `interpolate::fragment`.
#[inline]
#[target_feature(enable = "avx2")]
fn from_weights4(l: [__m256d; 3], c: &Constants, mode: Interpolation, color: LaneColor) -> Four {
    let q = [
        _mm256_mul_pd(l[0], _mm256_set1_pd(c.inv_w[0])),
        _mm256_mul_pd(l[1], _mm256_set1_pd(c.inv_w[1])),
        _mm256_mul_pd(l[2], _mm256_set1_pd(c.inv_w[2])),
    ];
    let sum = _mm256_add_pd(_mm256_add_pd(q[0], q[1]), q[2]);
    let ok = _mm256_and_pd(
        _mm256_cmp_pd::<_CMP_GT_OQ>(sum, _mm256_setzero_pd()),
        _mm256_cmp_pd::<_CMP_LT_OQ>(sum, _mm256_set1_pd(f64::INFINITY)),
    );
    let inv = _mm256_div_pd(_mm256_set1_pd(1.0), sum);
    let p = [
        _mm256_mul_pd(q[0], inv),
        _mm256_mul_pd(q[1], inv),
        _mm256_mul_pd(q[2], inv),
    ];
    let w = match mode {
        Interpolation::Perspective => p,
        Interpolation::Affine => l,
    };
    // uv both ways for the heatmap's buffers, as the lane code computes them.
    let both_uv = c.both_uv.map(|b| {
        [
            dot3(&l, b[0]),
            dot3(&l, b[1]),
            dot3(&p, b[2]),
            dot3(&p, b[3]),
        ]
    });
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
    let mut channels = [_mm256_setzero_pd(); CHANNELS];
    if !matches!(color, LaneColor::Texture | LaneColor::Depth(..)) {
        for ch in 0..c.used_channels {
            channels[ch] = dot3(&w, c.channels[ch]);
        }
    }
    Four {
        u: dot3(&w, c.u),
        v: dot3(&w, c.v),
        depth: dot3(&l, c.depth),
        ok: _mm256_movemask_pd(ok),
        wire,
        halo,
        channels,
        both_uv,
    }
}

/// What [`from_weights4`] finds for four samples.
struct Four {
    u: __m256d,
    v: __m256d,
    depth: __m256d,
    /// Validity and wireframe bits, lane k in bit k.
    ok: i32,
    wire: i32,
    /// Wireframe halo bits, lane k in bit k.
    halo: i32,
    /// The interpolated channels of [`Constants`] (zero for texture and depth shading).
    channels: [__m256d; CHANNELS],
    /// `[u_affine, v_affine, u_smooth, v_smooth]` when [`Constants`] asks for them.
    both_uv: Option<[__m256d; 4]>,
}

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

/// The colours of the non-texture shadings for eight samples, as `shade` makes them.
#[inline]
#[target_feature(enable = "avx2")]
fn channel_colors(lo: &Four, hi: &Four, color: LaneColor) -> __m256i {
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
                unorm8(to_f32(scale(lo.depth), scale(hi.depth)))
            } else {
                _mm256_setzero_si256()
            };
            pack_opaque(grey, grey, grey)
        }
        LaneColor::Normal | LaneColor::Lambert => {
            let ch = |c: usize| to_f32(lo.channels[c], hi.channels[c]);
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
        _ => {
            let ch = |c: usize| unorm8(to_f32(lo.channels[c], hi.channels[c]));
            pack_opaque(ch(0), ch(1), ch(2))
        }
    }
}

/// The edge-function lane path (see the parent module): every [`LaneColor`], with the
/// wireframe. A triangle at most four pixels wide (most triangles of a dense mesh) is drawn
/// two rows at a time, four pixels of each row in one register ([`narrow_triangle`]); every
/// pixel's value is computed by the same operations either way.
#[target_feature(enable = "avx2")]
pub(super) fn edge_triangle(
    tri: &LaneTriangle,
    (y_start, y_end): (u32, u32),
    sampler: Option<&VecSampler<'_>>,
    wide: bool,
    shading: &LaneShading,
    target: &mut Target<'_>,
) {
    let mut lookups = sampler.map(|s| Lookups::new(s, wide));
    let (x0, x1) = (tri.bounds.x0, tri.bounds.x1);
    if x1 - x0 < NARROW && y_end > y_start {
        narrow_triangle(tri, (y_start, y_end), shading, &mut lookups, target);
    } else {
        block_triangle(tri, (y_start, y_end), shading, &mut lookups, target);
    }
    if let Some(l) = lookups.as_mut() {
        l.flush(target);
    }
}

/// Triangles narrower than this many pixels take [`narrow_triangle`].
const NARROW: u32 = 4;

/// The lanes' column offsets 0..3 and 4..7.
#[inline]
#[target_feature(enable = "avx2")]
fn lane_offsets() -> [__m256d; 2] {
    [
        _mm256_setr_pd(0.0, 1.0, 2.0, 3.0),
        _mm256_setr_pd(4.0, 5.0, 6.0, 7.0),
    ]
}

/// Edge values at four pixels of row `row` from column `col`, exact integers in `f64`
/// lanes: `E(row, col) + a k`.
#[inline]
#[target_feature(enable = "avx2")]
fn edge_values(tri: &LaneTriangle, row: u32, col: u32, offset: __m256d) -> [__m256d; 3] {
    // No closures here: a closure does not take the function's target features, and a call
    // with vector arguments per row costs more than the arithmetic.
    let base = tri.planes.at(i64::from(row), i64::from(col));
    let a = &tri.planes.a;
    let value = |i: usize| (base[i] as f64, a[i] as f64);
    let (b0, a0) = value(0);
    let (b1, a1) = value(1);
    let (b2, a2) = value(2);
    [
        _mm256_add_pd(_mm256_set1_pd(b0), _mm256_mul_pd(_mm256_set1_pd(a0), offset)),
        _mm256_add_pd(_mm256_set1_pd(b1), _mm256_mul_pd(_mm256_set1_pd(a1), offset)),
        _mm256_add_pd(_mm256_set1_pd(b2), _mm256_mul_pd(_mm256_set1_pd(a2), offset)),
    ]
}

/// The lanes (bit k for lane k) of four edge values that pass every edge.
#[inline]
#[target_feature(enable = "avx2")]
fn inside_bits(tri: &LaneTriangle, e: &[__m256d; 3]) -> i32 {
    let t = &tri.planes.t;
    let t = [
        _mm256_set1_pd(t[0] as f64),
        _mm256_set1_pd(t[1] as f64),
        _mm256_set1_pd(t[2] as f64),
    ];
    let m = _mm256_and_pd(
        _mm256_and_pd(
            _mm256_cmp_pd::<_CMP_GE_OQ>(e[0], t[0]),
            _mm256_cmp_pd::<_CMP_GE_OQ>(e[1], t[1]),
        ),
        _mm256_cmp_pd::<_CMP_GE_OQ>(e[2], t[2]),
    );
    _mm256_movemask_pd(m)
}

/// The bounding box in blocks of [`LANES`] x [`BLOCK_ROWS`] pixels, each rejected or accepted
/// whole by its corners, then eight pixels of a row at a time.
#[inline]
#[target_feature(enable = "avx2")]
fn block_triangle(
    tri: &LaneTriangle,
    (y_start, y_end): (u32, u32),
    shading: &LaneShading,
    lookups: &mut Option<Lookups<'_, '_>>,
    target: &mut Target<'_>,
) {
    let (x0, x1) = (tri.bounds.x0, tri.bounds.x1);
    let [lane_lo, lane_hi] = lane_offsets();
    let mut by = y_start;
    while by <= y_end {
        let by_end = (by + BLOCK_ROWS - 1).min(y_end);
        let mut bx = x0;
        while bx <= x1 {
            let bx_end = bx + LANES as u32 - 1;
            let block = classify(
                &tri.planes,
                (i64::from(bx), i64::from(bx_end)),
                (i64::from(by), i64::from(by_end)),
            );
            if block != Block::Outside {
                let lanes_in = (x1 - bx + 1).min(LANES as u32);
                let in_row = (1i32 << lanes_in) - 1;
                for y in by..=by_end {
                    let covered = if block == Block::Inside {
                        in_row
                    } else {
                        let lo = edge_values(tri, y, bx, lane_lo);
                        let hi = edge_values(tri, y, bx, lane_hi);
                        (inside_bits(tri, &lo) | (inside_bits(tri, &hi) << 4)) & in_row
                    };
                    if covered != 0 {
                        shade_chunk(tri, covered, [(y, bx), (y, bx + 4)], shading, lookups, target);
                    }
                }
            }
            bx += LANES as u32;
        }
        by = by_end + 1;
    }
}

/// A triangle less than [`NARROW`] pixels wide: rows `y` and `y + 1` together, the four
/// columns from the bounds' first in lanes 0-3 (row `y`) and 4-7 (row `y + 1`). No block
/// test: the pixels are tested one by one.
#[inline]
#[target_feature(enable = "avx2")]
fn narrow_triangle(
    tri: &LaneTriangle,
    (y_start, y_end): (u32, u32),
    shading: &LaneShading,
    lookups: &mut Option<Lookups<'_, '_>>,
    target: &mut Target<'_>,
) {
    let (x0, x1) = (tri.bounds.x0, tri.bounds.x1);
    let [lane_lo, _] = lane_offsets();
    let in_half = (1i32 << (x1 - x0 + 1)) - 1;
    let mut y = y_start;
    while y <= y_end {
        let second = y < y_end;
        let mut covered = inside_bits(tri, &edge_values(tri, y, x0, lane_lo)) & in_half;
        if second {
            covered |= (inside_bits(tri, &edge_values(tri, y + 1, x0, lane_lo)) & in_half) << 4;
        }
        if covered != 0 {
            shade_chunk(tri, covered, [(y, x0), (y + 1, x0)], shading, lookups, target);
        }
        y += 2;
    }
}

/// [`WeightPlanes::row_term`] of the three weights at the centres of row `y`.
#[inline(always)]
fn row_terms(w: &WeightPlanes, y: u32) -> [f64; 3] {
    let py = f64::from(y) + 0.5;
    [w.row_term(0, py), w.row_term(1, py), w.row_term(2, py)]
}

/// Interpolates, shades and writes the `covered` lanes of one chunk: lanes 0-3 are the four
/// pixels of row `at[0].0` from column `at[0].1`, lanes 4-7 those of row `at[1].0` from
/// column `at[1].1` (eight pixels of one row, or four of two rows).
#[inline]
#[target_feature(enable = "avx2")]
fn shade_chunk(
    tri: &LaneTriangle,
    covered: i32,
    at: [(u32, u32); 2],
    shading: &LaneShading,
    lookups: &mut Option<Lookups<'_, '_>>,
    target: &mut Target<'_>,
) {
    let (mode, color) = (shading.mode, shading.color);
    let consts = &tri.consts;
    let [lane_lo, _] = lane_offsets();
    let row_lo = row_terms(&consts.weights, at[0].0);
    let row_hi = if at[1].0 == at[0].0 {
        row_lo
    } else {
        row_terms(&consts.weights, at[1].0)
    };
    let px_lo = _mm256_add_pd(_mm256_set1_pd(f64::from(at[0].1) + 0.5), lane_lo);
    let px_hi = _mm256_add_pd(_mm256_set1_pd(f64::from(at[1].1) + 0.5), lane_lo);
    let lo = from_weights4(weights4(&consts.weights, &row_lo, px_lo), consts, mode, color);
    let hi = from_weights4(weights4(&consts.weights, &row_hi, px_hi), consts, mode, color);
    let ok = covered & (lo.ok | (hi.ok << 4));
    if ok == 0 {
        return;
    }
    let row_start = |y: u32| (y - target.y0) as usize * target.width as usize;
    let chunk = Pending {
        u: to_f32(lo.u, hi.u),
        v: to_f32(lo.v, hi.v),
        depth: to_f32(lo.depth, hi.depth),
        valid: mask_from_bits(ok),
        wire: lo.wire | (hi.wire << 4),
        halo: lo.halo | (hi.halo << 4),
        index: row_start(at[0].0) + at[0].1 as usize,
        index_hi: row_start(at[1].0) + at[1].1 as usize,
        both_uv: lo
            .both_uv
            .zip(hi.both_uv)
            .map(|(l, h)| [0, 1, 2, 3].map(|j| to_f32(l[j], h[j]))),
    };
    match lookups.as_mut() {
        Some(l) if color == LaneColor::Texture => l.push(target, chunk),
        _ => finish(target, &chunk, channel_colors(&lo, &hi, color)),
    }
}

/// The scanline lane path (see the parent module).
#[target_feature(enable = "avx2")]
pub(super) fn scanline_triangle(
    tri: &LaneTriangle,
    (y_start, y_end): (u32, u32),
    sampler: &VecSampler<'_>,
    wide: bool,
    mode: Interpolation,
    target: &mut Target<'_>,
) {
    let mut lookups = Lookups::new(sampler, wide);
    let consts = &tri.consts;
    let step = Stepped::row_step(consts, mode);
    let n = LANES as f64;
    let step8 = [step.u * n, step.v * n, step.inv_w * n, step.depth * n].map(|x| _mm256_set1_pd(x));
    for y in y_start..=y_end {
        let Some((x0, x1)) = row_span_of(&tri.edges, tri.bounds, y) else {
            continue;
        };
        let start = Stepped::span_start(consts, mode, x0, y);
        // Lane k holds pixel x0 + k, reached by k single steps; then eight steps per chunk.
        let lanes = Stepped::lanes(start, &step);
        let load = |f: fn(&Stepped) -> f64, h: usize| {
            _mm256_setr_pd(
                f(&lanes[4 * h]),
                f(&lanes[4 * h + 1]),
                f(&lanes[4 * h + 2]),
                f(&lanes[4 * h + 3]),
            )
        };
        // [u, v, 1/w, depth] x [lanes 0..4, lanes 4..8]
        let mut vals = [0, 1].map(|h| {
            [
                load(|s| s.u, h),
                load(|s| s.v, h),
                load(|s| s.inv_w, h),
                load(|s| s.depth, h),
            ]
        });
        let row = (y - target.y0) as usize * target.width as usize;
        let mut x = x0;
        while x <= x1 {
            let lanes_in = (x1 - x + 1).min(LANES as u32);
            let mut ok = (1i32 << lanes_in) - 1;
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
            if ok != 0 {
                let u = to_f32(uv[0][0], uv[1][0]);
                let v = to_f32(uv[0][1], uv[1][1]);
                let chunk = Pending {
                    u,
                    v,
                    depth: to_f32(vals[0][3], vals[1][3]),
                    valid: mask_from_bits(ok),
                    wire: 0,
                    halo: 0,
                    index: row + x as usize,
                    index_hi: row + x as usize + 4,
                    both_uv: None,
                };
                lookups.push(target, chunk);
            }
            for half in vals.iter_mut() {
                for (q, s) in half.iter_mut().zip(&step8) {
                    *q = _mm256_add_pd(*q, *s);
                }
            }
            x += LANES as u32;
        }
    }
    lookups.flush(target);
}
