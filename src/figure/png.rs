//! A figure as a PNG: the background, each view's raster copied pixel for pixel, then the
//! figure's SVG overlay layer ([`super::svg::document`]) rasterized on top by resvg with the
//! overlay font. The PNG's overlays are therefore exactly the SVG's.

use std::sync::{Arc, OnceLock};

use resvg::tiny_skia::{self, Pixmap, PixmapPaint, Transform};
use resvg::usvg;

use super::svg::{self, Layers};
use super::text::FONT_BYTES;
use super::{Background, Figure, FigureError};
use crate::i18n::Lang;

/// The fonts resvg may use: only the overlay font and the bundled symbols font
/// ([`crate::i18n::SYMBOLS_FONT`]; no system fonts are scanned), and for Chinese labels the
/// system's CJK font ([`crate::i18n::cjk_font`]) as well.
fn fonts(lang: Lang) -> Arc<usvg::fontdb::Database> {
    static DB: OnceLock<Arc<usvg::fontdb::Database>> = OnceLock::new();
    static CJK: OnceLock<Arc<usvg::fontdb::Database>> = OnceLock::new();
    let overlay_only = || {
        let mut db = usvg::fontdb::Database::new();
        db.load_font_data(FONT_BYTES.to_vec());
        db.load_font_data(crate::i18n::SYMBOLS_FONT.to_vec());
        db.set_sans_serif_family(super::text::FONT_FAMILY);
        db
    };
    match (lang, crate::i18n::cjk_font()) {
        (Lang::Zh, Some(cjk)) => CJK
            .get_or_init(|| {
                let mut db = overlay_only();
                db.load_font_data(cjk.data.as_ref().clone());
                Arc::new(db)
            })
            .clone(),
        _ => DB.get_or_init(|| Arc::new(overlay_only())).clone(),
    }
}

/// Options for parsing the figure's SVG with the overlay font.
pub fn svg_options() -> usvg::Options<'static> {
    svg_options_in(Lang::En)
}

/// Options for parsing the figure's SVG with the overlay font and, for `lang` Chinese, the
/// CJK font as the fallback for the characters the overlay font lacks.
pub fn svg_options_in(lang: Lang) -> usvg::Options<'static> {
    usvg::Options {
        fontdb: fonts(lang),
        font_family: super::text::FONT_FAMILY.to_string(),
        ..usvg::Options::default()
    }
}

/// The figure as an RGBA image of [`Figure::pixel_dimensions`].
pub fn rasterize(figure: &Figure) -> Result<image::RgbaImage, FigureError> {
    let [w, h] = figure.pixel_dimensions();
    let mut pixmap = canvas(w, h, "figure canvas")?;
    if figure.background == Background::White {
        pixmap.fill(tiny_skia::Color::WHITE);
    }
    for v in &figure.views {
        let raster = pixmap_of(&v.raster)?;
        pixmap.draw_pixmap(
            (v.origin[0] * figure.scale) as i32,
            (v.origin[1] * figure.scale) as i32,
            raster.as_ref(),
            &PixmapPaint::default(),
            Transform::identity(),
            None,
        );
    }
    let overlay = svg::document(figure, Layers::OVERLAYS)?;
    let tree = usvg::Tree::from_str(&overlay, &svg_options_in(figure.lang))
        .map_err(|e| FigureError::Draw(format!("overlay SVG: {e}")))?;
    // The document's width and height are the PNG's pixels and its viewBox the points: usvg
    // already maps points to pixels.
    resvg::render(&tree, Transform::identity(), &mut pixmap.as_mut());
    image_of(&pixmap)
}

/// A transparent `w` x `h` pixmap, its memory asked for fallibly: an error naming the
/// `what` ("figure canvas") and its size when the system refuses it, never an abort.
pub(super) fn canvas(w: u32, h: u32, what: &str) -> Result<Pixmap, FigureError> {
    let no_image = || FigureError::Draw(format!("no {w}x{h} image"));
    let size = tiny_skia::IntSize::from_wh(w, h).ok_or_else(no_image)?;
    let n = (w as usize).saturating_mul(h as usize).saturating_mul(4);
    let mut data = crate::budget::try_vec::<u8>(n, &format!("the {w}x{h} {what}"))?;
    data.resize(n, 0);
    Pixmap::from_vec(data, size).ok_or_else(no_image)
}

/// A straight-alpha RGBA copy of a (premultiplied) pixmap (its memory asked for fallibly).
pub(super) fn image_of(pixmap: &Pixmap) -> Result<image::RgbaImage, FigureError> {
    let (w, h) = (pixmap.width(), pixmap.height());
    let mut out = crate::budget::try_image(w, h, [0; 4], || format!("the {w}x{h} figure image"))?;
    for (px, c) in out.pixels_mut().zip(pixmap.pixels()) {
        let c = c.demultiply();
        px.0 = [c.red(), c.green(), c.blue(), c.alpha()];
    }
    Ok(out)
}

/// The figure as PNG file bytes.
pub fn to_png(figure: &Figure) -> Result<Vec<u8>, FigureError> {
    encode(&rasterize(figure)?)
}

/// An image as PNG file bytes.
pub(super) fn encode(image: &image::RgbaImage) -> Result<Vec<u8>, FigureError> {
    let mut bytes = Vec::new();
    image
        .write_to(
            &mut std::io::Cursor::new(&mut bytes),
            image::ImageFormat::Png,
        )
        .map_err(|e| FigureError::Draw(e.to_string()))?;
    Ok(bytes)
}

/// A premultiplied copy of a straight-alpha RGBA image.
pub(super) fn pixmap_of(image: &image::RgbaImage) -> Result<Pixmap, FigureError> {
    let (w, h) = image.dimensions();
    let mut p = canvas(w, h, "view image")?;
    for (dst, src) in p.pixels_mut().iter_mut().zip(image.pixels()) {
        let [r, g, b, a] = src.0;
        *dst = tiny_skia::ColorU8::from_rgba(r, g, b, a).premultiply();
    }
    Ok(p)
}
