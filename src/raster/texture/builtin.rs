//! The built-in textures: a labelled uv grid, a checkerboard, deterministic noise and the tiny
//! 2x2 red/white/green/blue texture of the classic tutorials.

use ab_glyph::{Font, FontRef, PxScale, ScaleFont};

use super::Texture;

pub(super) fn checker() -> Texture {
    const SIZE: u32 = 256;
    const CELLS: u32 = 8;
    let cell = SIZE / CELLS;
    let mut texels = Vec::with_capacity((SIZE * SIZE) as usize);
    for j in 0..SIZE {
        for i in 0..SIZE {
            let dark = (i / cell + j / cell).is_multiple_of(2);
            texels.push(if dark {
                [40, 40, 40, 255]
            } else {
                [235, 235, 235, 255]
            });
        }
    }
    Texture::new_with_mips(SIZE, SIZE, texels)
}

/// SplitMix64-style integer hash: a fixed, platform-independent pseudo-random texel.
fn hash(mut x: u64) -> u64 {
    x = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    x = (x ^ (x >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    x ^ (x >> 31)
}

pub(super) fn noise() -> Texture {
    const SIZE: u32 = 1024;
    let texels = (0..u64::from(SIZE * SIZE))
        .map(|i| {
            let h = hash(i).to_le_bytes();
            [h[0], h[1], h[2], 255]
        })
        .collect();
    Texture::new_with_mips(SIZE, SIZE, texels)
}

pub(super) fn rgbw_2x2() -> Texture {
    // The picture[x][y]: (0,0) red, (0,1) white, (1,0) green, (1,1) blue, with y = v.
    Texture::new_with_mips(
        2,
        2,
        vec![
            [255, 0, 0, 255],
            [0, 255, 0, 255],
            [255, 255, 255, 255],
            [0, 0, 255, 255],
        ],
    )
}

/// 8x8 cells of 64 texels. Cell (c, r) (c along u, r along v) is tinted by its position and
/// labelled "c,r"; thin dark lines separate the cells and a thicker line marks the borders.
pub(super) fn uv_grid() -> Texture {
    const SIZE: u32 = 512;
    const CELLS: u32 = 8;
    let cell = SIZE / CELLS;
    // Draw top-down in an image, then flip into texel order.
    let mut img = image::RgbaImage::new(SIZE, SIZE);
    for (x, y, px) in img.enumerate_pixels_mut() {
        let c = x / cell;
        let r = CELLS - 1 - y / cell;
        let (fu, fv) = (c as f32 / (CELLS - 1) as f32, r as f32 / (CELLS - 1) as f32);
        let light = (c + r).is_multiple_of(2);
        let base = if light { 0.92 } else { 0.78 };
        let rgb = [
            base - 0.35 * (1.0 - fu) * fv,
            base - 0.30 * fu * (1.0 - fv),
            base - 0.35 * (1.0 - fu) * (1.0 - fv) - 0.2 * fu * fv,
        ];
        let (lx, ly) = (x % cell, y % cell);
        let line = lx == 0 || ly == 0 || lx == cell - 1 || ly == cell - 1;
        let border = x < 3 || y < 3 || x >= SIZE - 3 || y >= SIZE - 3;
        *px = if border {
            image::Rgba([20, 20, 30, 255])
        } else if line {
            image::Rgba([70, 70, 90, 255])
        } else {
            image::Rgba([
                (rgb[0] * 255.0) as u8,
                (rgb[1] * 255.0) as u8,
                (rgb[2] * 255.0) as u8,
                255,
            ])
        };
    }
    if let Ok(font) = FontRef::try_from_slice(epaint_default_fonts::HACK_REGULAR) {
        for r in 0..CELLS {
            for c in 0..CELLS {
                let label = format!("{c},{r}");
                let x0 = c * cell;
                let y0 = (CELLS - 1 - r) * cell;
                draw_text_centered(&mut img, &font, &label, x0, y0, cell, [25, 25, 40]);
            }
        }
    }
    Texture::from_image(&img).unwrap_or_else(checker)
}

/// Draws `text` centred in the square cell at (x0, y0) of side `cell`.
fn draw_text_centered(
    img: &mut image::RgbaImage,
    font: &FontRef<'_>,
    text: &str,
    x0: u32,
    y0: u32,
    cell: u32,
    rgb: [u8; 3],
) {
    let scale = PxScale::from(cell as f32 * 0.42);
    let scaled = font.as_scaled(scale);
    let width: f32 = text
        .chars()
        .map(|ch| scaled.h_advance(font.glyph_id(ch)))
        .sum();
    let mut pen_x = x0 as f32 + (cell as f32 - width) / 2.0;
    let baseline = y0 as f32 + (cell as f32 + scaled.ascent() + scaled.descent()) / 2.0;
    for ch in text.chars() {
        let id = font.glyph_id(ch);
        let glyph = id.with_scale_and_position(scale, ab_glyph::point(pen_x, baseline));
        pen_x += scaled.h_advance(id);
        if let Some(outlined) = font.outline_glyph(glyph) {
            let b = outlined.px_bounds();
            outlined.draw(|gx, gy, coverage| {
                let px = b.min.x as i64 + i64::from(gx);
                let py = b.min.y as i64 + i64::from(gy);
                if px < 0 || py < 0 || px >= img.width() as i64 || py >= img.height() as i64 {
                    return;
                }
                let p = img.get_pixel_mut(px as u32, py as u32);
                for (channel, ink) in p.0.iter_mut().zip(rgb) {
                    let bg = f32::from(*channel);
                    *channel = (bg + (f32::from(ink) - bg) * coverage.clamp(0.0, 1.0)) as u8;
                }
            });
        }
    }
}
