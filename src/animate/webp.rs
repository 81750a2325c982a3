//! Animated WebP, lossless: each frame encoded as a lossless `VP8L` bitstream by `image-webp`
//! (which writes single images only), the frames put in the animated container of the WebP
//! specification: `RIFF` `WEBP`, a `VP8X` chunk (animation and alpha flags, the canvas size
//! minus one in 24 bits each), an `ANIM` chunk (background colour, loop count 0 = forever)
//! and one `ANMF` chunk per frame (position / 2, size minus one, duration in ms, 24 bits
//! each, then a flags byte: no blending, no disposal) holding the frame's `VP8L` chunk.

use rayon::prelude::*;

use super::AnimateError;

/// Appends a chunk: its four-character name, its size (little-endian u32), the data and a
/// zero byte when the size is odd.
fn chunk(out: &mut Vec<u8>, name: &[u8; 4], data: &[u8]) {
    out.extend_from_slice(name);
    out.extend_from_slice(&(data.len() as u32).to_le_bytes());
    out.extend_from_slice(data);
    if data.len() % 2 == 1 {
        out.push(0);
    }
}

/// The low three bytes of `v`, little-endian.
fn u24(v: u32) -> [u8; 3] {
    let b = v.to_le_bytes();
    [b[0], b[1], b[2]]
}

/// One frame's `VP8L` bitstream: the chunk of `image-webp`'s simple (no metadata) file.
fn vp8l(frame: &image::RgbaImage) -> Result<Vec<u8>, AnimateError> {
    let (w, h) = frame.dimensions();
    let mut file = Vec::new();
    image_webp::WebPEncoder::new(&mut file)
        .encode(frame.as_raw(), w, h, image_webp::ColorType::Rgba8)
        .map_err(|e| AnimateError::Encode(e.to_string()))?;
    // RIFF, size, WEBP, then the one chunk: VP8L, size, data.
    let size = file
        .get(16..20)
        .filter(|_| file.get(12..16) == Some(b"VP8L".as_slice()))
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as usize)
        .ok_or_else(|| AnimateError::Encode("unexpected WebP frame layout".to_string()))?;
    file.get(20..20 + size)
        .map(<[u8]>::to_vec)
        .ok_or_else(|| AnimateError::Encode("truncated WebP frame".to_string()))
}

/// The frames at `fps` as an animated lossless WebP file.
pub(super) fn encode(frames: &[image::RgbaImage], fps: f64) -> Result<Vec<u8>, AnimateError> {
    let (w, h) = frames[0].dimensions();
    if w > 1 << 24 || h > 1 << 24 {
        return Err(AnimateError::Encode(format!(
            "{w}x{h} is too large for WebP"
        )));
    }
    let bitstreams: Vec<Vec<u8>> = frames.par_iter().map(vp8l).collect::<Result<_, _>>()?;
    let duration = (1000.0 / fps).round().clamp(1.0, f64::from((1 << 24) - 1)) as u32;
    let mut body = b"WEBP".to_vec();
    let mut vp8x = vec![0x02 | 0x10, 0, 0, 0];
    vp8x.extend_from_slice(&u24(w - 1));
    vp8x.extend_from_slice(&u24(h - 1));
    chunk(&mut body, b"VP8X", &vp8x);
    chunk(&mut body, b"ANIM", &[255, 255, 255, 255, 0, 0]);
    for bits in &bitstreams {
        let mut anmf = Vec::with_capacity(bits.len() + 24);
        anmf.extend_from_slice(&u24(0));
        anmf.extend_from_slice(&u24(0));
        anmf.extend_from_slice(&u24(w - 1));
        anmf.extend_from_slice(&u24(h - 1));
        anmf.extend_from_slice(&u24(duration));
        // Bit 1: do not blend (the frame replaces the canvas); bit 0: no disposal.
        anmf.push(0x02);
        chunk(&mut anmf, b"VP8L", bits);
        chunk(&mut body, b"ANMF", &anmf);
    }
    let mut file = b"RIFF".to_vec();
    file.extend_from_slice(&(body.len() as u32).to_le_bytes());
    file.extend(body);
    Ok(file)
}
