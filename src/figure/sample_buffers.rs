//! The per-sample buffers view: what each sample buffer of a multisampled render holds. The
//! coverage count per pixel (how many of its `N` samples a triangle wrote, `0..=N`, as a
//! heatmap with a legend), the colour and the depth one sample index `k` holds in every pixel,
//! and the resolve (each pixel the average of its samples, [`resolve`]). The pixels are the
//! core's own samples ([`render_samples`]'s [`SampleBuffer`]); nothing is drawn again here.
//!
//! The "black edges" of GAMES101's assignment 2 ([`black_edge_samples`]): colour kept per
//! pixel while coverage is per sample. Where the samples of one pixel belong to two or more
//! triangles, the pixel keeps only the triangle with the most samples (on a tie the higher
//! index, the one drawn last) and the other triangles' samples keep the background; resolved,
//! such an edge pixel is darker than both triangles. `barylab compare`'s tests write the bug
//! with it, and the app's black-edge toggle shows it.

use super::FigureError;
use super::raster_svg::{Raster, RasterSvg};
use super::svg::escape;
use crate::i18n::Lang;
use crate::raster::multisample::{SampleBuffer, SampleValue};
use crate::raster::render::{RenderSettings, render_samples};
use crate::raster::sample::resolve;
use crate::raster::shade::depth_grey;
use crate::raster::{NO_TRIANGLE, Texture};
use crate::scene::Scene;

/// Which buffer the view shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SampleBufferKind {
    /// Each pixel the average of its samples' colours (the usual image).
    #[default]
    Resolve,
    /// How many of each pixel's samples a triangle wrote, `0..=N`.
    Coverage,
    /// The colour sample `k` holds.
    Color,
    /// The depth sample `k` holds (near dark, far light; cleared samples blue).
    Depth,
}

impl SampleBufferKind {
    /// Every kind, in the order the app offers them.
    pub const ALL: [SampleBufferKind; 4] = [
        SampleBufferKind::Resolve,
        SampleBufferKind::Coverage,
        SampleBufferKind::Color,
        SampleBufferKind::Depth,
    ];

    /// The catalogue key of its name (`figure.samples.*`).
    pub fn key(self) -> &'static str {
        match self {
            SampleBufferKind::Resolve => "figure.samples.resolve",
            SampleBufferKind::Coverage => "figure.samples.coverage",
            SampleBufferKind::Color => "figure.samples.color",
            SampleBufferKind::Depth => "figure.samples.depth",
        }
    }

    /// The catalogue key of the buffer's short title (a narrow view's).
    pub fn short_key(self) -> &'static str {
        match self {
            SampleBufferKind::Resolve => "figure.samples.short.resolve",
            SampleBufferKind::Coverage => "figure.samples.short.coverage",
            SampleBufferKind::Color => "figure.samples.short.color",
            SampleBufferKind::Depth => "figure.samples.short.depth",
        }
    }
}

/// What the per-sample buffers view shows: a buffer, the sample index, and whether with the
/// black-edge bug. The default (the resolve, no bug) is the usual image.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SampleView {
    /// The buffer shown.
    pub kind: SampleBufferKind,
    /// The sample index whose colour or depth is shown (clamped to the last sample).
    pub index: u32,
    /// The buffers with GAMES101 A2's black-edge bug.
    pub black_edges: bool,
}

impl SampleView {
    /// Whether it shows something other than the usual resolved image.
    pub fn is_on(&self) -> bool {
        self.kind != SampleBufferKind::Resolve || self.black_edges
    }
}

/// The colour of a depth sample no triangle wrote (still the cleared 1).
pub const CLEARED_DEPTH: [u8; 4] = [70, 110, 170, 255];

/// The samples of `buffer` with the black-edge bug (see the module): in every pixel whose
/// samples belong to two or more triangles, the samples of all but the triangle with the
/// most samples (the higher index on a tie) are cleared to `background` (depth 1, no
/// triangle). Returns the buffer and how many pixels changed.
pub fn black_edge_samples(buffer: &SampleBuffer, background: [u8; 4]) -> (SampleBuffer, usize) {
    let mut out = buffer.clone();
    let n = buffer.offsets.len().max(1);
    let mut changed = 0;
    for pixel in out.samples.chunks_exact_mut(n) {
        let mut tris: smallvec::SmallVec<[u32; 16]> = pixel
            .iter()
            .map(|v| v.triangle)
            .filter(|&t| t != NO_TRIANGLE)
            .collect();
        tris.sort_unstable();
        tris.dedup();
        if tris.len() < 2 {
            continue;
        }
        let count = |t: u32| pixel.iter().filter(|v| v.triangle == t).count();
        let Some(keep) = tris.iter().copied().max_by_key(|&t| count(t)) else {
            continue;
        };
        for v in pixel.iter_mut().filter(|v| v.triangle != keep) {
            *v = SampleValue::clear(background);
        }
        changed += 1;
    }
    (out, changed)
}

/// Each pixel's resolve: the average of its samples' colours ([`resolve`]).
pub fn resolved(buffer: &SampleBuffer) -> Vec<[u8; 4]> {
    let n = buffer.offsets.len().max(1);
    buffer
        .samples
        .chunks_exact(n)
        .map(|p| {
            let colors: smallvec::SmallVec<[[u8; 4]; 16]> = p.iter().map(|s| s.color).collect();
            resolve(&colors)
        })
        .collect()
}

/// Each pixel's coverage count: how many of its samples hold a triangle.
pub fn coverage_counts(buffer: &SampleBuffer) -> Vec<u8> {
    let n = buffer.offsets.len().max(1);
    buffer
        .samples
        .chunks_exact(n)
        .map(|p| p.iter().filter(|s| s.triangle != NO_TRIANGLE).count() as u8)
        .collect()
}

/// The colour of coverage count `count` of `n` samples: the heatmap's colour at `count / n`
/// (0 black, `n` light yellow).
///
/// ```
/// use barylab::figure::heatmap::heat_color;
/// use barylab::figure::sample_buffers::coverage_colour;
/// assert_eq!(coverage_colour(0, 4), heat_color(0.0, 4.0));
/// assert_eq!(coverage_colour(4, 4), heat_color(1.0, 1.0));
/// ```
pub fn coverage_colour(count: u8, n: usize) -> [u8; 4] {
    super::heatmap::heat_color(f32::from(count), n as f32)
}

/// The range of the depths sample `k` holds where a triangle wrote it (`None`: none did).
pub fn depth_range(buffer: &SampleBuffer, k: usize) -> Option<(f64, f64)> {
    let n = buffer.offsets.len().max(1);
    buffer
        .samples
        .iter()
        .skip(k)
        .step_by(n)
        .filter(|s| s.triangle != NO_TRIANGLE)
        .map(|s| f64::from(s.depth))
        .fold(None, |r, d| match r {
            None => Some((d, d)),
            Some((lo, hi)) => Some((d.min(lo), d.max(hi))),
        })
}

/// The image of `kind` (sample index `k` for the colour and the depth, clamped to the last
/// sample): one RGBA per pixel, row by row.
///
/// The depth of a written sample is [`depth_grey`] over [`depth_range`] (the nearest black,
/// the farthest white); a cleared one is [`CLEARED_DEPTH`].
pub fn image(buffer: &SampleBuffer, kind: SampleBufferKind, k: usize) -> Vec<[u8; 4]> {
    let n = buffer.offsets.len().max(1);
    let k = k.min(n - 1);
    let at_k = || buffer.samples.iter().skip(k).step_by(n);
    match kind {
        SampleBufferKind::Resolve => resolved(buffer),
        SampleBufferKind::Coverage => coverage_counts(buffer)
            .into_iter()
            .map(|c| coverage_colour(c, n))
            .collect(),
        SampleBufferKind::Color => at_k().map(|s| s.color).collect(),
        SampleBufferKind::Depth => {
            let range = depth_range(buffer, k).unwrap_or((0.0, 1.0));
            at_k()
                .map(|s| {
                    if s.triangle == NO_TRIANGLE {
                        CLEARED_DEPTH
                    } else {
                        let g = depth_grey(f64::from(s.depth), range);
                        [g, g, g, 255]
                    }
                })
                .collect()
        }
    }
}

/// The samples of a scene as the core draws them ([`render_samples`]), with the black-edge
/// bug applied when `black_edges` is set.
pub fn samples_of(
    scene: &Scene,
    texture: &Texture,
    settings: &RenderSettings,
    black_edges: bool,
) -> Result<SampleBuffer, FigureError> {
    let (_, buffer) = render_samples(&scene.to_mesh(), texture, settings)
        .map_err(|e| FigureError::Draw(e.to_string()))?;
    Ok(if black_edges {
        black_edge_samples(&buffer, settings.background).0
    } else {
        buffer
    })
}

/// The title of `kind`'s image in `lang` (`k` the sample index, `n` the sample count).
pub fn title(kind: SampleBufferKind, k: usize, n: usize, black_edges: bool, lang: Lang) -> String {
    let [full, ..] = titles(kind, k, n, black_edges, lang);
    full
}

/// [`title`] and two shorter forms, longest first, for a view too narrow for the whole title
/// at full size: the buffer's short name with the bug's mark ("Resolve (black-edge bug)"),
/// then the short name alone ("Resolve", "Sample 1: colour").
pub fn titles(
    kind: SampleBufferKind,
    k: usize,
    n: usize,
    black_edges: bool,
    lang: Lang,
) -> [String; 3] {
    let k = k.min(n.max(1) - 1).to_string();
    let n = n.to_string();
    let args: [(&str, &dyn std::fmt::Display); 2] = [("k", &k), ("n", &n)];
    let base = lang.tr_with(kind.key(), &args);
    let short = lang.tr_with(kind.short_key(), &args);
    let bug = |view: &str| lang.tr_with("figure.samples.with_bug", &[("view", &view)]);
    if black_edges {
        [bug(&base), bug(&short), short]
    } else {
        [base, short.clone(), short]
    }
}

/// The per-sample buffers figure: the coverage count with its legend, the resolve, and
/// sample `k`'s colour and depth, two by two, each image `scale` points per pixel, words in
/// `lang` (`black_edges`: the buffers with the bug).
pub fn picture(
    buffer: &SampleBuffer,
    k: usize,
    scale: f64,
    black_edges: bool,
    lang: Lang,
) -> RasterSvg {
    let n = buffer.offsets.len().max(1);
    let (w, h) = (buffer.width, buffer.height);
    let (iw, ih) = (f64::from(w) * scale, f64::from(h) * scale);
    let (margin, title_h, legend_w) = (16.0, 26.0, 130.0);
    let order = [
        SampleBufferKind::Coverage,
        SampleBufferKind::Resolve,
        SampleBufferKind::Color,
        SampleBufferKind::Depth,
    ];
    let titles = order.map(|kind| title(kind, k, n, black_edges, lang));
    // A title's width: the bundled font's measure, or a full em per wide (CJK) character.
    let width_of = |t: &str| {
        let wide = t.chars().filter(|c| !c.is_ascii()).count() as f64 * 15.0;
        f64::from(super::text::measure(t, 15.0).0[0]).max(wide)
    };
    let column = |c: usize| {
        (iw + legend_w)
            .max(width_of(&titles[c]))
            .max(width_of(&titles[c + 2]))
            + margin
    };
    let columns = [column(0), column(1)];
    // A row is as tall as its image or its legend (the coverage count's n + 1 swatches, the
    // taller), so a small image's legend never runs into the row below.
    let legend_h = (n + 1) as f64 * 20.0;
    let cell_h = title_h + ih.max(legend_h) + margin;
    let mut rasters = Vec::new();
    let mut marks = String::new();
    for (i, kind) in order.into_iter().enumerate() {
        let row = (i / 2) as f64;
        let x = margin + if i % 2 == 1 { columns[0] } else { 0.0 };
        let y = margin + row * cell_h;
        let pixels = image(buffer, kind, k);
        let raw: Vec<u8> = pixels.iter().flatten().copied().collect();
        if let Some(img) = image::RgbaImage::from_raw(w, h, raw) {
            rasters.push(Raster {
                image: img,
                rect: [x, y + title_h, iw, ih],
            });
        }
        marks.push_str(&format!(
            r#"<text x="{x}" y="{:.1}" font-size="15">{}</text>"#,
            y + 18.0,
            escape(&titles[i])
        ));
        let lx = x + iw + 10.0;
        let mut ly = y + title_h;
        let mut swatch = |s: &mut String, c: [u8; 4], label: &str| {
            s.push_str(&format!(
                r##"<rect x="{lx:.1}" y="{ly:.1}" width="18" height="14" fill="rgb({},{},{})" stroke="#404040"/><text x="{:.1}" y="{:.1}">{}</text>"##,
                c[0],
                c[1],
                c[2],
                lx + 24.0,
                ly + 12.0,
                escape(label)
            ));
            ly += 20.0;
        };
        match kind {
            SampleBufferKind::Coverage => {
                for c in 0..=n as u8 {
                    let label = lang.tr_with("figure.samples.count", &[("count", &c)]);
                    swatch(&mut marks, coverage_colour(c, n), &label);
                }
            }
            SampleBufferKind::Depth => {
                if let Some((lo, hi)) = depth_range(buffer, k.min(n - 1)) {
                    swatch(&mut marks, [0, 0, 0, 255], &format!("{lo:.4}"));
                    swatch(&mut marks, [255, 255, 255, 255], &format!("{hi:.4}"));
                }
                swatch(
                    &mut marks,
                    CLEARED_DEPTH,
                    &lang.tr("figure.samples.cleared"),
                );
            }
            _ => {}
        }
    }
    RasterSvg {
        size: [margin + columns[0] + columns[1], margin + 2.0 * cell_h],
        rasters,
        marks,
        lang,
    }
}
