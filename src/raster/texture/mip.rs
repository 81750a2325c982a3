//! Mipmaps: each level half the previous one, texels averaged 2x2 (odd sizes clamp).

use super::Level;

/// The next mipmap level, as glGenerateMipmap: size `max(1, floor(n / 2))`, each texel the
/// rounded mean of the 2x2 texels it covers (clamped at odd edges).
pub(super) fn half_level(w: u32, h: u32, texels: &[[u8; 4]]) -> Level {
    let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
    let at = |i: u32, j: u32| texels[(j.min(h - 1) * w + i.min(w - 1)) as usize];
    let mut out = Vec::with_capacity((nw * nh) as usize);
    for j in 0..nh {
        for i in 0..nw {
            let q = [
                at(2 * i, 2 * j),
                at(2 * i + 1, 2 * j),
                at(2 * i, 2 * j + 1),
                at(2 * i + 1, 2 * j + 1),
            ];
            let mut c = [0u8; 4];
            for (k, ch) in c.iter_mut().enumerate() {
                let sum: u32 = q.iter().map(|t| u32::from(t[k])).sum();
                *ch = ((sum + 2) / 4) as u8;
            }
            out.push(c);
        }
    }
    Level {
        width: nw,
        height: nh,
        texels: out,
    }
}

pub(super) fn mip_chain(w: u32, h: u32, texels: &[[u8; 4]]) -> Vec<Level> {
    let mut mips: Vec<Level> = Vec::new();
    let (mut cw, mut ch) = (w, h);
    while cw > 1 || ch > 1 {
        let next = match mips.last() {
            Some(l) => half_level(cw, ch, &l.texels),
            None => half_level(cw, ch, texels),
        };
        (cw, ch) = (next.width, next.height);
        mips.push(next);
    }
    mips
}
