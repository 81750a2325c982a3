//! Mipmaps: each level half the previous one, texels averaged 2x2 (odd sizes clamp).

use super::Level;

/// The next mipmap level, as glGenerateMipmap: size `max(1, floor(n / 2))`, each texel the
/// rounded mean of the 2x2 texels it covers (clamped at odd edges).
pub(super) fn half_level(w: u32, h: u32, texels: &[[u8; 4]]) -> Level {
    let (nw, nh) = half_size(w, h);
    half_level_into(w, h, texels, Vec::with_capacity(nw as usize * nh as usize))
}

/// The size of the level after a `w` x `h` one: `max(1, floor(n / 2))` each way.
fn half_size(w: u32, h: u32) -> (u32, u32) {
    ((w / 2).max(1), (h / 2).max(1))
}

/// [`half_level`] into `out` (empty, its room reserved by the caller).
fn half_level_into(w: u32, h: u32, texels: &[[u8; 4]], mut out: Vec<[u8; 4]>) -> Level {
    let (nw, nh) = half_size(w, h);
    let at = |i: u32, j: u32| texels[(j.min(h - 1) * w + i.min(w - 1)) as usize];
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

/// [`mip_chain`] with each level's memory asked for fallibly: a refusal is an error naming
/// the level ("the 4096x4096 texture's 2048x2048 mipmap level") and its size, never an abort.
pub(super) fn try_mip_chain(
    w: u32,
    h: u32,
    texels: &[[u8; 4]],
) -> Result<Vec<Level>, crate::budget::MemoryError> {
    let mut mips: Vec<Level> = Vec::new();
    let (mut cw, mut ch) = (w, h);
    while cw > 1 || ch > 1 {
        let (nw, nh) = half_size(cw, ch);
        let room = crate::budget::try_vec(
            nw as usize * nh as usize,
            &format!("the {w}x{h} texture's {nw}x{nh} mipmap level"),
        )?;
        let next = match mips.last() {
            Some(l) => half_level_into(cw, ch, &l.texels, room),
            None => half_level_into(cw, ch, texels, room),
        };
        (cw, ch) = (next.width, next.height);
        mips.push(next);
    }
    Ok(mips)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fallible chain is the same chain: level sizes 5x3 -> 2x1 -> 1x1, each texel the
    /// rounded mean of its 2x2 (clamped) block.
    #[test]
    fn the_fallible_chain_equals_the_chain() {
        let texels: Vec<[u8; 4]> = (0..15u8).map(|i| [i * 17, 255 - i * 9, i, 255]).collect();
        let chain = mip_chain(5, 3, &texels);
        let sizes: Vec<(u32, u32)> = chain.iter().map(|l| (l.width, l.height)).collect();
        assert_eq!(sizes, [(2, 1), (1, 1)]);
        // Level 1's first texel: the mean of texels 0, 1, 5, 6 (row 0 and row 1, columns 0-1).
        let mean = |k: usize| {
            let sum: u32 = [0, 1, 5, 6].iter().map(|&i| u32::from(texels[i][k])).sum();
            ((sum + 2) / 4) as u8
        };
        assert_eq!(chain[0].texels[0], [mean(0), mean(1), mean(2), mean(3)]);
        assert_eq!(try_mip_chain(5, 3, &texels).expect("a few bytes"), chain);
    }
}
