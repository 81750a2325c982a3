//! The texture-space view of a pixel: the texels around its uv in level 0 and in the mipmap
//! levels the lookup reads, with the filter's taps and their weights, the pixel's footprint
//! parallelogram (its sides are the uv derivatives in texels) and, for anisotropic filtering,
//! the probes along the footprint's long side: a [`RasterSvg`] (the texels as rasters, the
//! marks as vector shapes and text).

use glam::DVec2;

use super::raster_svg::{Raster, RasterSvg};
use super::svg::escape;
use crate::i18n::Lang;
use crate::probe::format::fmt_number;
use crate::probe::{AttributeTrace, LodTrace};
use crate::raster::texture::{Filter, Texture, Wrap, wrap_coord};

/// Side of one level's panel, in points.
const PANEL: f64 = 300.0;
/// Narrowest view, in points.
const MIN_WIDTH: f64 = 640.0;
/// Space around and between the panels, in points.
const GAP: f64 = 24.0;
/// Space left and right of a panel drawn alone ([`TextureView::panel_pictures`]), in points.
const PANEL_MARGIN: f64 = 4.0;
/// Height of the title strip above the panels and of the caption below, in points.
const TITLE: f64 = 44.0;
/// Space between the panels and the caption's first line, in points.
const CAPTION: f64 = 14.0;

/// Colours of the marks (distinct in print and for colour-blind readers).
const TAP: &str = "#d55e00";
const FOOTPRINT: &str = "#0072b2";
const PROBE: &str = "#009e73";

/// Which texture picture shows beside the canvas (the app) or a lesson step selects: none,
/// the pixel's lookup in texture space ([`TextureView`]), or every pixel's mipmap level
/// ([`super::lod_view`]).
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum TexelView {
    /// Neither.
    #[default]
    Off,
    /// The texture beside the image with the pixel's footprint, taps and weights.
    Texture,
    /// Every pixel coloured by its mipmap level, with a legend.
    Lod,
}

/// What the view shows for one pixel.
#[derive(Clone, Debug)]
pub struct TextureView<'a> {
    /// The texture.
    pub texture: &'a Texture,
    /// The filter and the wrap mode of the lookup.
    pub filter: Filter,
    /// The wrap mode.
    pub wrap: Wrap,
    /// The pixel's uv (the rendered mode's).
    pub uv: [f32; 2],
    /// The taps of the lookup at `uv` (nearest or bilinear: level 0).
    pub taps: Vec<(u32, f32)>,
    /// The level-of-detail derivation (trilinear and anisotropic filtering).
    pub lod: Option<&'a LodTrace>,
    /// The pixel, for the title.
    pub pixel: [u32; 2],
}

impl<'a> TextureView<'a> {
    /// The view of a probed pixel's texture lookup with the `perspective` (else affine) uv.
    pub fn of(
        texture: &'a Texture,
        (filter, wrap): (Filter, Wrap),
        a: &'a AttributeTrace,
        perspective: bool,
        pixel: [u32; 2],
    ) -> Self {
        let (uv, taps) = if perspective {
            (a.uv_perspective, &a.taps_perspective)
        } else {
            (a.uv_affine, &a.taps_affine)
        };
        Self {
            texture,
            filter,
            wrap,
            uv,
            taps: taps.iter().map(|t| (t.level, t.weight)).collect(),
            lod: a.lod.as_ref(),
            pixel,
        }
    }

    /// The panels: level and its share of the colour (`None`: the footprint overview).
    fn panels(&self) -> Vec<(u32, Option<f32>)> {
        let Some(lt) = self.lod else {
            return vec![(0, Some(1.0))];
        };
        let c = lt.anisotropic.as_ref().map_or(&lt.trilinear, |a| &a.levels);
        let mut v = vec![(0, None)];
        match c.next {
            Some((next, f)) => v.extend([(c.level, Some(1.0 - f)), (next, Some(f))]),
            None => v.push((c.level, Some(1.0))),
        }
        v
    }

    /// Half the side of the window shown, in level-0 texels: the footprint with room around
    /// it, at least 2 texels (five texels across: large enough for the taps' weights to be
    /// read from the back of a lecture hall).
    fn window_radius(&self) -> f64 {
        let p = self.lod.map_or(0.0, |l| f64::from(l.rho));
        (0.9 * p).clamp(2.0, 48.0)
    }

    /// The view, words in `lang`: SVG with [`RasterSvg::to_svg`], PNG with
    /// [`RasterSvg::to_png`].
    pub fn picture(&self, lang: Lang) -> RasterSvg {
        let panels = self.panels();
        // Room for the title and the caption beside a single panel too.
        let w = (GAP + panels.len() as f64 * (PANEL + GAP)).max(MIN_WIDTH);
        let caption: Vec<String> = self
            .caption(lang)
            .iter()
            .flat_map(|c| wrap(c, w - 2.0 * GAP))
            .collect();
        let h = TITLE + PANEL + CAPTION + 18.0 * caption.len() as f64;
        let mut s = String::new();
        let mut rasters = Vec::new();
        let title = lang.tr_with(
            "figure.texture.title",
            &[
                ("x", &self.pixel[0]),
                ("y", &self.pixel[1]),
                ("u", &fmt_number(f64::from(self.uv[0]))),
                ("v", &fmt_number(f64::from(self.uv[1]))),
            ],
        );
        s.push_str(&format!(
            r#"<text x="{}" y="20" font-size="15" text-anchor="middle">{}</text>"#,
            w / 2.0,
            escape(&title)
        ));
        for (k, &(level, share)) in panels.iter().enumerate() {
            let x0 = GAP + k as f64 * (PANEL + GAP);
            rasters.push(self.panel(&mut s, lang, [x0, TITLE], level, share));
        }
        for (k, line) in caption.iter().enumerate() {
            s.push_str(&format!(
                r#"<text x="{GAP}" y="{:.1}">{}</text>"#,
                TITLE + PANEL + CAPTION + 14.0 + 18.0 * k as f64,
                escape(line)
            ));
        }
        RasterSvg {
            size: [w, h],
            rasters,
            marks: s,
            lang,
        }
    }

    /// Each level's panel as a picture of its own with its title (the app lays them out to
    /// fit its column); the caption ([`TextureView::caption`]) is left to the caller.
    pub fn panel_pictures(&self, lang: Lang) -> Vec<RasterSvg> {
        self.panels()
            .into_iter()
            .map(|(level, share)| {
                let mut s = String::new();
                let raster = self.panel(&mut s, lang, [PANEL_MARGIN, TITLE / 2.0], level, share);
                RasterSvg {
                    size: [
                        PANEL + 2.0 * PANEL_MARGIN,
                        TITLE / 2.0 + PANEL + PANEL_MARGIN,
                    ],
                    rasters: vec![raster],
                    marks: s,
                    lang,
                }
            })
            .collect()
    }

    /// The caption's lines: the footprint and the level of detail.
    pub fn caption(&self, lang: Lang) -> Vec<String> {
        let Some(lt) = self.lod else {
            return vec![lang.tr("figure.texture.caption_level0")];
        };
        let n = |x: f32| fmt_number(f64::from(x));
        let mut v = vec![lang.tr_with(
            "figure.texture.caption_lod",
            &[
                ("px", &n(lt.px)),
                ("py", &n(lt.py)),
                ("lambda", &n(lt.trilinear.lambda)),
            ],
        )];
        if let Some(a) = &lt.anisotropic {
            v.push(lang.tr_with(
                "figure.texture.caption_aniso",
                &[
                    ("n", &a.n),
                    ("max", &a.max),
                    ("lambda", &n(a.levels.lambda)),
                ],
            ));
        }
        v
    }

    /// One level's panel at `origin` (its top-left corner): the texels around the uv (the
    /// raster returned), the texel grid, the footprint, the taps with their weights or the
    /// probes (marks added to `s`).
    fn panel(
        &self,
        s: &mut String,
        lang: Lang,
        origin: [f64; 2],
        level: u32,
        share: Option<f32>,
    ) -> Raster {
        let t = self.texture;
        let (lw, lh) = t.level_size(level);
        let scale = f64::from(1u32 << level.min(31));
        let centre = DVec2::new(
            f64::from(self.uv[0]) * f64::from(lw),
            f64::from(self.uv[1]) * f64::from(lh),
        );
        // At least 2 texels each side, so the 2x2 taps show.
        let r = (self.window_radius() / scale).max(2.0);
        let (i0, j0) = ((centre.x - r).floor() as i64, (centre.y - r).floor() as i64);
        let k = ((2.0 * r).ceil() as i64 + 1).max(1);
        let texel_pt = PANEL / k as f64;
        // Texel (i, j) (unwrapped) to its panel corner; row j grows upwards.
        let to_pt = |p: DVec2| {
            [
                origin[0] + (p.x - i0 as f64) * texel_pt,
                origin[1] + PANEL - (p.y - j0 as f64) * texel_pt,
            ]
        };
        let mut img = image::RgbaImage::new(k as u32, k as u32);
        for (x, y, px) in img.enumerate_pixels_mut() {
            let (i, j) = (i0 + i64::from(x), j0 + k - 1 - i64::from(y));
            let texel = t.texel_at(
                level,
                wrap_coord(i, lw, self.wrap),
                wrap_coord(j, lh, self.wrap),
            );
            *px = image::Rgba(texel);
        }
        // The texel grid, where texels are large enough to see.
        if texel_pt >= 8.0 {
            for n in 0..=k {
                let a = n as f64 * texel_pt;
                s.push_str(&format!(
                    r##"<line x1="{x:.2}" y1="{y0}" x2="{x:.2}" y2="{y1}" stroke="#808080" stroke-width="0.5"/><line x1="{x0}" y1="{y:.2}" x2="{x1}" y2="{y:.2}" stroke="#808080" stroke-width="0.5"/>"##,
                    x = origin[0] + a,
                    y = origin[1] + a,
                    x0 = origin[0],
                    x1 = origin[0] + PANEL,
                    y0 = origin[1],
                    y1 = origin[1] + PANEL,
                ));
            }
        }
        s.push_str(&format!(
            r##"<rect x="{}" y="{}" width="{PANEL}" height="{PANEL}" fill="none" stroke="#404040"/>"##,
            origin[0], origin[1]
        ));
        let title = match share {
            None => lang.tr_with("figure.texture.footprint_panel", &[("level", &level)]),
            Some(f) => lang.tr_with(
                "figure.texture.level_panel",
                &[("level", &level), ("share", &fmt_number(f64::from(f)))],
            ),
        };
        s.push_str(&format!(
            r#"<text x="{}" y="{}" text-anchor="middle">{}</text>"#,
            origin[0] + PANEL / 2.0,
            origin[1] - 6.0,
            escape(&title)
        ));
        let level_size = DVec2::new(f64::from(lw), f64::from(lh));
        let in_level = |uv: [f32; 2]| DVec2::new(f64::from(uv[0]), f64::from(uv[1])) * level_size;
        // The footprint parallelogram: centre +- duv/dx / 2 +- duv/dy / 2, in this level.
        if let Some(lt) = self.lod {
            let dx = in_level(lt.duv_dx);
            let dy = in_level(lt.duv_dy);
            let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
                .map(|(a, b)| to_pt(centre + dx * (0.5 * a) + dy * (0.5 * b)));
            let pts: Vec<String> = corners
                .iter()
                .map(|p| format!("{:.2},{:.2}", p[0], p[1]))
                .collect();
            s.push_str(&format!(
                r#"<polygon points="{}" fill="{FOOTPRINT}" fill-opacity="0.15" stroke="{FOOTPRINT}" stroke-width="2"/>"#,
                pts.join(" ")
            ));
            if let Some(a) = &lt.anisotropic {
                for p in &a.probes {
                    let q = to_pt(in_level(p.uv));
                    s.push_str(&format!(
                        r##"<circle cx="{:.2}" cy="{:.2}" r="3.5" fill="{PROBE}" stroke="#ffffff"/>"##,
                        q[0], q[1]
                    ));
                }
            }
        }
        if share.is_some() && self.lod.is_none_or(|l| l.anisotropic.is_none()) {
            self.taps_marks(s, level, centre, texel_pt, &to_pt);
        }
        let c = to_pt(centre);
        s.push_str(&format!(
            r##"<circle cx="{:.2}" cy="{:.2}" r="4" fill="#ffffff" stroke="#000000" stroke-width="1.5"/>"##,
            c[0], c[1]
        ));
        Raster {
            image: img,
            rect: [origin[0], origin[1], PANEL, PANEL],
        }
    }

    /// The taps of `level`: each texel outlined with its weight.
    fn taps_marks(
        &self,
        s: &mut String,
        level: u32,
        centre: DVec2,
        texel_pt: f64,
        to_pt: &dyn Fn(DVec2) -> [f64; 2],
    ) {
        let weights: Vec<f32> = match self.lod {
            Some(lt) => lt
                .taps
                .iter()
                .filter(|t| t.level == level)
                .map(|t| t.weight)
                .collect(),
            None => self
                .taps
                .iter()
                .filter(|t| t.0 == level)
                .map(|t| t.1)
                .collect(),
        };
        // Unwrapped texel corners in the order the filters list their taps.
        let corners: Vec<DVec2> = if self.filter == Filter::Nearest {
            vec![centre.floor()]
        } else {
            let b = (centre - DVec2::splat(0.5)).floor();
            vec![b, b + DVec2::X, b + DVec2::Y, b + DVec2::ONE]
        };
        let font = tap_label_size(texel_pt);
        for (corner, w) in corners.iter().zip(weights) {
            let [x, y] = to_pt(*corner + DVec2::Y);
            s.push_str(&format!(
                r#"<rect x="{x:.2}" y="{y:.2}" width="{texel_pt:.2}" height="{texel_pt:.2}" fill="none" stroke="{TAP}" stroke-width="2.5"/>"#
            ));
            // Three decimals: four labels fit their texels from the smallest window. The
            // label sits in the half of its texel away from the uv's dot (in texel rows),
            // so the dot never covers it.
            let label = format!("{w:.3}");
            let towards_dot_up = centre.y > corner.y + 0.5;
            let shift = if towards_dot_up { 0.22 } else { -0.22 } * texel_pt;
            s.push_str(&format!(
                r##"<text x="{:.2}" y="{:.2}" text-anchor="middle" font-size="{font:.1}" fill="#000000" stroke="#ffffff" stroke-width="3" paint-order="stroke">{label}</text>"##,
                x + texel_pt / 2.0,
                y + texel_pt / 2.0 + font / 3.0 + shift
            ));
        }
    }
}

/// The font size, in points, of a tap's weight in a texel `texel_pt` points wide: a
/// three-decimal weight ("0.838", about 2.8 font sizes wide) fills at most 70% of the texel
/// (`texel_pt / 4`), between 12 and 22 points.
///
/// ```
/// # use barylab::figure::texture_view::tap_label_size;
/// assert_eq!(tap_label_size(30.0), 12.0);
/// assert_eq!(tap_label_size(60.0), 15.0);
/// assert_eq!(tap_label_size(100.0), 22.0);
/// ```
pub fn tap_label_size(texel_pt: f64) -> f64 {
    (texel_pt / 4.0).clamp(12.0, 22.0)
}

/// `text` in lines no wider than `width` points at the caption's 13-point size: broken at
/// spaces, or anywhere in a run without spaces (Chinese).
fn wrap(text: &str, width: f64) -> Vec<String> {
    let fits = |s: &str| f64::from(super::text::measure(s, 13.0).0[0]) <= width;
    let mut lines = Vec::new();
    let mut line = String::new();
    for c in text.chars() {
        line.push(c);
        if fits(&line) {
            continue;
        }
        // Break at the last space if there is one, else before this character.
        let cut = line
            .rfind(' ')
            .filter(|&i| i > 0)
            .unwrap_or(line.len() - c.len_utf8());
        let rest = line.split_off(cut);
        lines.push(std::mem::take(&mut line));
        line = rest.trim_start().to_string();
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}
