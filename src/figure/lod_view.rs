//! The level-of-detail view: every covered pixel coloured by the mipmap level its texture
//! lookup starts from (`floor(lambda)`, clamped to the last level; with anisotropic filtering
//! the probes' level), magnification (`lambda <= 0`) in its own colour, with a legend of the
//! level numbers beside the image. It shows where magnification ends and minification begins,
//! and how far each level reaches.

use super::FigureError;
use super::raster_svg::{Raster, RasterSvg};
use super::svg::escape;
use crate::i18n::Lang;
use crate::raster::interpolate::{self, Derivatives};
use crate::raster::render::{self, RenderSettings};
use crate::raster::setup::sample_point;
use crate::raster::texture::{Anisotropic, Texture, lod};
use crate::scene::Scene;

/// The colour of magnified pixels (`lambda <= 0`).
pub const MAGNIFIED: [u8; 3] = [255, 255, 255];

/// One colour per level, 0 upwards (repeated past the tenth).
pub const LEVEL_COLOURS: [[u8; 3]; 10] = [
    [78, 121, 167],
    [242, 142, 43],
    [225, 87, 89],
    [118, 183, 178],
    [89, 161, 79],
    [237, 201, 72],
    [176, 122, 161],
    [255, 157, 167],
    [156, 117, 95],
    [186, 176, 172],
];

/// The colour of level of detail `lambda`: [`MAGNIFIED`] at or below 0, else level
/// `min(floor(lambda), last)`'s.
///
/// ```
/// use barylab::figure::lod_view::{LEVEL_COLOURS, MAGNIFIED, level_colour};
/// assert_eq!(level_colour(-0.5, 8), MAGNIFIED);
/// assert_eq!(level_colour(2.7, 8), LEVEL_COLOURS[2]);
/// assert_eq!(level_colour(20.0, 3), LEVEL_COLOURS[3]);
/// ```
pub fn level_colour(lambda: f32, last: u32) -> [u8; 3] {
    if lambda.is_nan() || lambda <= 0.0 {
        return MAGNIFIED;
    }
    LEVEL_COLOURS[level_of(lambda, last) as usize % LEVEL_COLOURS.len()]
}

/// The mipmap level a pixel of level of detail `lambda` is shown as: floor(lambda), at
/// least 0 (magnified) and at most `last`, the texture's last level.
///
/// ```
/// use barylab::figure::lod_view::level_of;
/// assert_eq!(level_of(-0.5, 8), 0);
/// assert_eq!(level_of(2.7, 8), 2);
/// assert_eq!(level_of(20.0, 3), 3);
/// ```
pub fn level_of(lambda: f32, last: u32) -> u32 {
    if lambda <= 0.0 {
        return 0;
    }
    (lambda.floor() as u32).min(last)
}

/// Every pixel's level of detail as the renderer computes it (coarse derivatives, the
/// rendered mode), for the triangle that wrote it; NaN where no triangle did.
pub fn lod_per_pixel(
    scene: &Scene,
    texture: &Texture,
    settings: &RenderSettings,
) -> Result<Vec<f32>, FigureError> {
    lod_per_pixel_of_mesh(&scene.to_mesh(), texture, settings)
}

/// [`lod_per_pixel`] for a clip-space mesh (the GPU check's, rounded to f32).
pub fn lod_per_pixel_of_mesh(
    mesh: &crate::raster::ClipMesh,
    texture: &Texture,
    settings: &RenderSettings,
) -> Result<Vec<f32>, FigureError> {
    let frame = render::render(mesh, texture, settings)
        .map_err(|e| FigureError::Draw(e.to_string()))?
        .frame;
    let triangles =
        render::prepare_triangles(mesh, settings).map_err(|e| FigureError::Draw(e.to_string()))?;
    let size = (texture.width(), texture.height());
    let (w, h) = (frame.width, frame.height);
    let mut out = Vec::new();
    crate::budget::try_resize(&mut out, w as usize * h as usize, f32::NAN, || {
        format!("the {w}x{h} level-of-detail image")
    })?;
    for tri in &triangles {
        for s in &tri.setups {
            let b = s.bounds;
            for y in b.y0..=b.y1.min(frame.height.saturating_sub(1)) {
                for x in b.x0..=b.x1.min(frame.width.saturating_sub(1)) {
                    let i = frame.index(x, y);
                    if frame.triangle[i] != tri.source
                        || !s.covers(&s.edge_values(sample_point(x, y)))
                    {
                        continue;
                    }
                    out[i] = pixel_lambda(s, (x, y), settings, size);
                }
            }
        }
    }
    Ok(out)
}

/// The legend's rows for `lambdas` (a texture of `levels` levels), words in `lang`: the
/// magnified colour if any pixel is magnified, then each level some pixel reads, in order.
pub fn legend(lambdas: &[f32], levels: u32, lang: Lang) -> Vec<([u8; 3], String)> {
    let last = levels.saturating_sub(1);
    let mut v = Vec::new();
    if lambdas.iter().any(|&l| !l.is_nan() && l <= 0.0) {
        v.push((MAGNIFIED, lang.tr("figure.lod.magnified")));
    }
    for lv in 0..=last {
        if lambdas.iter().any(|&l| l > 0.0 && level_of(l, last) == lv) {
            let label = lang.tr_with("figure.lod.level", &[("level", &lv)]);
            v.push((LEVEL_COLOURS[lv as usize % LEVEL_COLOURS.len()], label));
        }
    }
    v
}

/// The level-of-detail image: one pixel per image pixel, coloured by [`level_colour`], dark
/// grey where no triangle wrote.
pub fn lod_image(lambdas: &[f32], (width, height): (u32, u32), levels: u32) -> image::RgbaImage {
    let last = levels.saturating_sub(1);
    image::RgbaImage::from_fn(width, height, |x, y| {
        let l = lambdas[(y * width + x) as usize];
        if l.is_nan() {
            image::Rgba([40, 40, 40, 255])
        } else {
            let c = level_colour(l, last);
            image::Rgba([c[0], c[1], c[2], 255])
        }
    })
}

/// The level of detail of pixel `(x, y)` of set-up triangle `s` as the renderer computes it:
/// coarse derivatives of the quad in `settings.mode`, `lod` (or the anisotropic level when
/// `settings.max_anisotropy` is on) for a texture of `size`; 0 where the quad has no uv.
fn pixel_lambda(
    s: &crate::raster::setup::TriangleSetup,
    (x, y): (u32, u32),
    settings: &RenderSettings,
    size: (u32, u32),
) -> f32 {
    match interpolate::quad_derivatives(s, (x, y), settings.mode, Derivatives::Coarse) {
        None => 0.0,
        Some([dx, dy]) if settings.max_anisotropy.is_on() => {
            Anisotropic::of(dx, dy, size, settings.max_anisotropy).lambda
        }
        Some([dx, dy]) => lod(dx, dy, size.0, size.1),
    }
}

/// Column `x` of [`lod_per_pixel`]'s image: `[row, lambda]` for every row a triangle wrote,
/// top to bottom, and `[row, level]` with the mipmap level read there (0 when magnified,
/// else `floor(lambda)` clamped to the texture's last level).
pub fn lod_column(
    scene: &Scene,
    texture: &Texture,
    settings: &RenderSettings,
    x: u32,
) -> Result<[Vec<[f64; 2]>; 2], FigureError> {
    let lambdas = lod_per_pixel(scene, texture, settings)?;
    let (w, h) = scene.size();
    let last = texture.levels().saturating_sub(1);
    let mut lambda = Vec::new();
    let mut level = Vec::new();
    for y in (0..h).filter(|_| x < w) {
        let l = lambdas[y as usize * w as usize + x as usize];
        if l.is_nan() {
            continue;
        }
        let lv = level_of(l, last);
        lambda.push([f64::from(y), f64::from(l)]);
        level.push([f64::from(y), f64::from(lv)]);
    }
    Ok([lambda, level])
}

/// The level-of-detail view: the image coloured by level (`scale` points per pixel) and the
/// legend to its right, words in `lang`.
pub fn lod_picture(
    lambdas: &[f32],
    (width, height): (u32, u32),
    levels: u32,
    scale: f64,
    lang: Lang,
) -> RasterSvg {
    let img = lod_image(lambdas, (width, height), levels);
    let (iw, ih) = (f64::from(width) * scale, f64::from(height) * scale);
    let margin = 16.0;
    let legend_w = 220.0;
    let entries = legend(lambdas, levels, lang);
    let rows = entries.len();
    let title_h = 30.0;
    let w = margin * 3.0 + iw + legend_w;
    let h = (title_h + ih + margin).max(title_h + 24.0 + 22.0 * rows as f64 + margin);
    let mut s = String::new();
    s.push_str(&format!(
        r#"<text x="{margin}" y="20" font-size="15">{}</text>"#,
        escape(&lang.tr("figure.lod.title"))
    ));
    let lx = margin * 2.0 + iw;
    let mut y = title_h + 4.0;
    s.push_str(&format!(
        r#"<text x="{lx}" y="{:.1}">{}</text>"#,
        y + 10.0,
        escape(&lang.tr("figure.lod.legend"))
    ));
    y += 22.0;
    let mut swatch = |s: &mut String, c: [u8; 3], label: String| {
        s.push_str(&format!(
            r##"<rect x="{lx}" y="{y:.1}" width="18" height="14" fill="rgb({},{},{})" stroke="#404040"/><text x="{:.1}" y="{:.1}">{}</text>"##,
            c[0],
            c[1],
            c[2],
            lx + 26.0,
            y + 12.0,
            escape(&label)
        ));
        y += 22.0;
    };
    for (c, label) in entries {
        swatch(&mut s, c, label);
    }
    RasterSvg {
        size: [w, h],
        rasters: vec![Raster {
            image: img,
            rect: [margin, title_h, iw, ih],
        }],
        marks: s,
        lang,
    }
}
