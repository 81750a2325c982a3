//! A self-contained picture of rasters (images in pixels, each stretched over a rectangle,
//! pixelated) under vector marks, written as SVG (the rasters embedded as PNG) or as PNG (the
//! rasters drawn pixel for pixel, then the marks rasterized on top by resvg, as
//! [`super::png`] does for figures). The texture and level-of-detail views use it.

use base64::Engine;
use resvg::tiny_skia::{Color, FilterQuality, PixmapPaint, Transform};

use super::FigureError;
use super::png::svg_options_in;
use crate::i18n::Lang;

/// An image stretched over the rectangle `[x, y, width, height]` (points).
#[derive(Clone, Debug)]
pub struct Raster {
    /// The pixels, row 0 at the top.
    pub image: image::RgbaImage,
    /// Where it is drawn: `[x, y, width, height]` in points.
    pub rect: [f64; 4],
}

/// A white picture of `size` points: rasters below, then SVG elements (`marks`) on top.
#[derive(Clone, Debug)]
pub struct RasterSvg {
    /// Width and height in points.
    pub size: [f64; 2],
    /// Drawn first, in order.
    pub rasters: Vec<Raster>,
    /// SVG elements drawn over the rasters.
    pub marks: String,
    /// The language of the text (its fonts).
    pub lang: Lang,
}

impl RasterSvg {
    fn head(&self) -> String {
        let [w, h] = self.size;
        let fonts = super::svg::font_families(self.lang);
        format!(
            r#"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="{fonts}" font-size="13">"#
        )
    }

    /// The picture as an SVG document, the rasters embedded as PNG.
    pub fn to_svg(&self) -> Result<String, FigureError> {
        let [w, h] = self.size;
        let mut s = self.head();
        s.push_str(&format!(
            r##"<rect width="{w}" height="{h}" fill="#ffffff"/>"##
        ));
        for r in &self.rasters {
            let png = super::png::encode(&r.image)?;
            let data = base64::engine::general_purpose::STANDARD.encode(&png);
            let [x, y, rw, rh] = r.rect;
            s.push_str(&format!(
                r#"<image x="{x}" y="{y}" width="{rw}" height="{rh}" preserveAspectRatio="none" style="image-rendering:pixelated" image-rendering="optimizeSpeed" xlink:href="data:image/png;base64,{data}"/>"#
            ));
        }
        s.push_str(&self.marks);
        s.push_str("</svg>");
        Ok(s)
    }

    /// The picture as PNG file bytes, `scale` pixels per point.
    pub fn to_png(&self, scale: f32) -> Result<Vec<u8>, FigureError> {
        super::png::encode(&self.to_image(scale)?)
    }

    /// The picture as an image, `scale` pixels per point (what [`RasterSvg::to_png`] encodes;
    /// the app shows it).
    pub fn to_image(&self, scale: f32) -> Result<image::RgbaImage, FigureError> {
        let [w, h] = self.size.map(|v| (v * f64::from(scale)).round() as u32);
        let mut pixmap = super::png::canvas(w, h, "picture canvas")?;
        pixmap.fill(Color::WHITE);
        let k = f64::from(scale);
        for r in &self.rasters {
            let (iw, ih) = r.image.dimensions();
            if iw == 0 || ih == 0 {
                continue;
            }
            let src = super::png::pixmap_of(&r.image)?;
            let [x, y, rw, rh] = r.rect;
            let t = Transform::from_row(
                (rw * k / f64::from(iw)) as f32,
                0.0,
                0.0,
                (rh * k / f64::from(ih)) as f32,
                (x * k) as f32,
                (y * k) as f32,
            );
            let paint = PixmapPaint {
                quality: FilterQuality::Nearest,
                ..PixmapPaint::default()
            };
            pixmap.draw_pixmap(0, 0, src.as_ref(), &paint, t, None);
        }
        let marks = format!("{}{}</svg>", self.head(), self.marks);
        let tree = resvg::usvg::Tree::from_str(&marks, &svg_options_in(self.lang))
            .map_err(|e| FigureError::Draw(format!("picture SVG: {e}")))?;
        resvg::render(
            &tree,
            Transform::from_scale(scale, scale),
            &mut pixmap.as_mut(),
        );
        super::png::image_of(&pixmap)
    }
}
