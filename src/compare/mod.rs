//! `barylab compare`: an image from someone else's rasterizer (a student's homework, a
//! screenshot) against barylab's render of the same scene, pixel by pixel.
//!
//! Coverage of the other image comes from its alpha (at least half opaque is covered) or from
//! a background colour (anything else is covered). Each differing pixel gets a one-line
//! reason ([`reason::Reason`]) from the probe ([`diagnose`]); whole-image explanations (y flipped, rotated, affine
//! interpolation, pixel centres at integer coordinates; against a multisampled reference: black
//! edges, no anti-aliasing, differences only on edges) are tried by rendering or
//! transforming barylab's image that way and counting what still differs ([`hypotheses`]).
//! The differing pixels are grouped into connected regions ([`regions`]), each with the
//! reason that explains most of it; an explanation that fits exactly or nearly names a bug
//! ([`bugs`]: its code, explanation and fix).

pub mod bugs;
pub mod diagnose;
mod file;
pub mod hypotheses;
pub mod reason;
pub mod regions;
pub mod sampling;
pub mod verdict;

pub use file::read_image;

use serde::Serialize;

use crate::i18n::Lang;
use crate::raster::{ClipMesh, Interpolation, NO_TRIANGLE, RenderSettings, Texture};
use crate::scene::Scene;

/// Differing pixels listed with their reasons (all are counted).
pub const LISTED: usize = 12;

/// barylab's render of a mesh for a comparison: colour, the triangle and both uvs per pixel,
/// everything a comparison reads, drawn by the fast path ([`Buffers::ColorDepthUv`]: the same
/// values as the full render, `tests/fast_path.rs`), several times faster than the full
/// render with every buffer. The render keeps no per-triangle record (the reasons probe the
/// scene themselves).
///
/// [`Buffers::ColorDepthUv`]: crate::raster::Buffers::ColorDepthUv
pub fn render_for_comparison(
    mesh: &ClipMesh,
    texture: &Texture,
    settings: &RenderSettings,
) -> Result<crate::raster::render::Render, String> {
    let mut frame = crate::raster::Framebuffer::empty();
    let buffers = crate::raster::Buffers::ColorDepthUv;
    crate::raster::render_into(&mut frame, mesh, texture, settings, buffers)
        .map_err(|e| e.to_string())?;
    Ok(crate::raster::render::Render {
        frame,
        triangles: Vec::new(),
    })
}

/// Default tolerance: 8-bit levels one channel may differ by and still agree (two rasterizers
/// that follow the same rules still round and filter a little differently: llvmpipe and
/// barylab differ by up to 2 with bilinear filtering).
pub const DEFAULT_TOLERANCE: u8 = 2;

/// How the other image says which pixels are covered.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case", tag = "by", content = "color")]
pub enum CoverageBy {
    /// Alpha of at least 128.
    Alpha,
    /// Any colour other than this one (within the tolerance).
    Background([u8; 3]),
}

/// An image to compare: RGBA8, row 0 at the top.
#[derive(Clone, Debug)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// RGBA8, `width * height`, row by row from the top.
    pub pixels: Vec<[u8; 4]>,
}

impl Image {
    /// Whether some pixel is not fully opaque.
    pub fn has_transparency(&self) -> bool {
        self.pixels.iter().any(|p| p[3] < 255)
    }
}

/// What is compared: the scene and barylab's settings for it.
pub struct Reference<'a> {
    /// The scene (the probe traces its pixels).
    pub scene: &'a Scene,
    /// The scene's clip-space mesh ([`Scene::to_mesh`]).
    pub mesh: &'a ClipMesh,
    /// The scene's texture.
    pub texture: &'a Texture,
    /// barylab's settings; their size must be the other image's.
    pub settings: RenderSettings,
}

/// How a pixel differs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Difference {
    /// The other image covers it, barylab does not.
    OnlyTheirs,
    /// barylab covers it, the other image does not.
    OnlyOurs,
    /// Both cover it, with colours more than the tolerance apart.
    Color,
}

/// One differing pixel with its reason. In JSON the reason is `reason` (in English) and
/// `why` (the structured [`reason::Reason`], its `kind` a stable code).
#[derive(Clone, Debug)]
pub struct PixelDifference {
    /// `[x, y]`, row 0 at the top.
    pub pixel: [u32; 2],
    /// Coverage on one side only, or colour.
    pub difference: Difference,
    /// The other image's RGBA.
    pub theirs: [u8; 4],
    /// barylab's RGBA.
    pub ours: [u8; 4],
    /// The source triangle barylab drew there.
    pub triangle: Option<u32>,
    /// Why they differ, from the probe or a whole-image explanation
    /// ([`reason::Reason::text`] words it).
    pub reason: reason::Reason,
}

impl PixelDifference {
    /// The pixel in one line with its colours and reason, in `lang` (indented as a sample
    /// under its region).
    pub fn text(&self, lang: Lang) -> String {
        let what = lang.tr(match self.difference {
            Difference::OnlyTheirs => "compare.report.only_image",
            Difference::OnlyOurs => "compare.report.only_barylab",
            Difference::Color => "compare.report.colour_kind",
        });
        let rgb = |c: [u8; 4]| format!("{},{},{}", c[0], c[1], c[2]);
        lang.tr_with(
            "compare.report.sample",
            &[
                ("x", &self.pixel[0]),
                ("y", &self.pixel[1]),
                ("what", &what),
                ("image", &rgb(self.theirs)),
                ("barylab", &rgb(self.ours)),
                ("reason", &self.reason.text(lang)),
            ],
        )
    }
}

impl Serialize for PixelDifference {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut s = serializer.serialize_struct("PixelDifference", 7)?;
        s.serialize_field("pixel", &self.pixel)?;
        s.serialize_field("difference", &self.difference)?;
        s.serialize_field("theirs", &self.theirs)?;
        s.serialize_field("ours", &self.ours)?;
        s.serialize_field("triangle", &self.triangle)?;
        s.serialize_field("reason", &self.reason.text(Lang::En))?;
        s.serialize_field("why", &self.reason)?;
        s.end()
    }
}

/// `looks_like` in JSON: the verdict in English, and its kind as `looks_like_kind`.
fn looks_like_json<S: serde::Serializer>(
    verdict: &Option<verdict::Verdict>,
    serializer: S,
) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeMap;
    let mut m = serializer.serialize_map(Some(2))?;
    m.serialize_entry("looks_like", &verdict.map(|v| v.text(Lang::En)))?;
    m.serialize_entry("looks_like_kind", &verdict.map(|v| v.kind))?;
    m.end()
}

/// The result of a comparison.
#[derive(Clone, Debug, Serialize)]
pub struct Comparison {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// barylab's interpolation mode.
    pub mode: Interpolation,
    /// How the other image's coverage was read.
    pub coverage_by: CoverageBy,
    /// 8-bit levels a channel may differ by and still agree.
    pub tolerance: u8,
    /// Pixels compared, `width * height`.
    pub pixels: usize,
    /// Pixels barylab covers.
    pub covered: usize,
    /// Pixels the other image covers and barylab does not.
    pub only_theirs: usize,
    /// Pixels barylab covers and the other image does not.
    pub only_ours: usize,
    /// Pixels both cover whose colours differ by more than the tolerance.
    pub color_differing: usize,
    /// Over the pixels both cover: the largest difference of one channel (RGB).
    pub max_color_difference: u8,
    /// `[x, y]` of the first pixel (in row order) with `max_color_difference`; `None` when
    /// it is 0.
    pub max_color_at: Option<[u32; 2]>,
    /// The whole-image explanations tried, best first, with what each leaves differing.
    pub hypotheses: Vec<hypotheses::Tried>,
    /// The explanation that fits much better than barylab's own image, if any
    /// ([`verdict::Verdict::text`] words it). In JSON: `looks_like` (in English) and
    /// `looks_like_kind`.
    #[serde(flatten, serialize_with = "looks_like_json")]
    pub looks_like: Option<verdict::Verdict>,
    /// The first differing pixels in row order.
    pub first: Vec<PixelDifference>,
    /// The named bugs ([`bugs::named`]): empty when none fits exactly or nearly.
    pub bugs: Vec<bugs::Bug>,
    /// Connected regions of differing pixels.
    pub region_count: usize,
    /// The largest [`regions::REGIONS_LISTED`] regions, largest first, with reasons.
    pub regions: Vec<regions::Region>,
}

impl Comparison {
    /// Pixels that differ in coverage or colour.
    pub fn differing(&self) -> usize {
        self.only_theirs + self.only_ours + self.color_differing
    }

    /// Whether the images agree: same coverage, colours within the tolerance.
    pub fn agrees(&self) -> bool {
        self.differing() == 0
    }
}

/// How an image's coverage is read when nothing else is said: by `background` when given,
/// else by alpha when the image has a transparent pixel, else by the scene's background
/// colour (`barylab compare` and `barylab grade` read it alike).
pub fn coverage_for(
    image: &Image,
    settings: &RenderSettings,
    background: Option<[u8; 3]>,
) -> CoverageBy {
    match background {
        Some(c) => CoverageBy::Background(c),
        None if image.has_transparency() => CoverageBy::Alpha,
        None => {
            let b = settings.background;
            CoverageBy::Background([b[0], b[1], b[2]])
        }
    }
}

/// Largest difference of the R, G, B channels.
pub fn rgb_difference(a: [u8; 4], b: [u8; 4]) -> u8 {
    (0..3).map(|i| a[i].abs_diff(b[i])).max().unwrap_or(0)
}

/// Whether the other image covers a pixel.
pub fn covered_by(p: [u8; 4], by: CoverageBy, tolerance: u8) -> bool {
    match by {
        CoverageBy::Alpha => p[3] >= 128,
        CoverageBy::Background(bg) => rgb_difference(p, [bg[0], bg[1], bg[2], 255]) > tolerance,
    }
}

/// A rendered image in the terms of the comparison: colour and coverage per pixel.
#[derive(Clone, Debug)]
pub struct Rendered {
    /// RGBA8 per pixel, row 0 at the top.
    pub color: Vec<[u8; 4]>,
    /// Whether a triangle covers the pixel.
    pub covered: Vec<bool>,
}

impl Rendered {
    /// A frame's colours and coverage.
    pub fn of(frame: &crate::raster::Framebuffer) -> Self {
        Self {
            color: frame.color.clone(),
            covered: frame.triangle.iter().map(|&t| t != NO_TRIANGLE).collect(),
        }
    }

    /// The colours as an image `width` pixels wide (row 0 at the top); `None` when the
    /// pixel count is not a multiple of `width`.
    pub fn to_image(&self, width: u32) -> Option<image::RgbaImage> {
        let w = width.max(1) as usize;
        if !self.color.len().is_multiple_of(w) {
            return None;
        }
        let h = (self.color.len() / w) as u32;
        let bytes: Vec<u8> = self.color.iter().flatten().copied().collect();
        image::RgbaImage::from_raw(width, h, bytes)
    }
}

/// How pixel `k` of the other image differs from `reference` (`None`: they agree).
pub fn classify(
    theirs: [u8; 4],
    reference: &Rendered,
    k: usize,
    by: CoverageBy,
    tolerance: u8,
) -> Option<Difference> {
    let ours = reference.color[k];
    let (t, o) = (covered_by(theirs, by, tolerance), reference.covered[k]);
    match (t, o) {
        (false, false) => None,
        (true, false) => {
            // Against a background colour, the other image's pixel counts as covered only if
            // it differs from barylab's too (barylab's background may be another colour).
            let same = matches!(by, CoverageBy::Background(_))
                && rgb_difference(theirs, ours) <= tolerance;
            (!same).then_some(Difference::OnlyTheirs)
        }
        (false, true) => {
            // A covered pixel whose colour is the background's cannot be told apart.
            let same = matches!(by, CoverageBy::Background(_)) && !covered_by(ours, by, tolerance);
            (!same).then_some(Difference::OnlyOurs)
        }
        (true, true) => (rgb_difference(theirs, ours) > tolerance).then_some(Difference::Color),
    }
}

/// Compares `theirs` with barylab's render of `reference`. The sizes must match (checked by
/// the caller, who names the files).
pub fn compare(
    theirs: &Image,
    reference: &Reference,
    by: CoverageBy,
    tolerance: u8,
) -> Result<Comparison, String> {
    let s = &reference.settings;
    if (theirs.width, theirs.height) != (s.width, s.height) {
        return Err(format!(
            "the image is {}x{}, the scene renders {}x{}",
            theirs.width, theirs.height, s.width, s.height
        ));
    }
    let render = render_for_comparison(reference.mesh, reference.texture, s)?;
    compare_rendered(theirs, reference, &render, by, tolerance)
}

/// [`compare`] with barylab's render of `reference` already made (by
/// [`render_for_comparison`], or with all its buffers by [`crate::raster::render()`]), so that a caller who also needs the render or the
/// [`difference_image_of`] renders once. The sizes must match.
pub fn compare_rendered(
    theirs: &Image,
    reference: &Reference,
    render: &crate::raster::render::Render,
    by: CoverageBy,
    tolerance: u8,
) -> Result<Comparison, String> {
    compare_with(theirs, reference, render, None, by, tolerance)
}

/// [`compare_rendered`] with the whole-image explanations already made
/// ([`hypotheses::Candidates`], for the same reference and render; `None` makes them when
/// the images differ): `barylab grade` makes them once per scene for a whole class.
pub fn compare_with(
    theirs: &Image,
    reference: &Reference,
    render: &crate::raster::render::Render,
    candidates: Option<&hypotheses::Candidates>,
    by: CoverageBy,
    tolerance: u8,
) -> Result<Comparison, String> {
    let s = &reference.settings;
    let f = &render.frame;
    if (theirs.width, theirs.height) != (f.width, f.height) || theirs.pixels.len() != f.color.len()
    {
        return Err(format!(
            "the image is {}x{}, the render {}x{}",
            theirs.width, theirs.height, f.width, f.height
        ));
    }
    let ours = Rendered::of(&render.frame);
    let width = s.width;
    let mut c = Comparison {
        width,
        height: s.height,
        mode: s.mode,
        coverage_by: by,
        tolerance,
        pixels: ours.color.len(),
        covered: ours.covered.iter().filter(|&&c| c).count(),
        only_theirs: 0,
        only_ours: 0,
        color_differing: 0,
        max_color_difference: 0,
        max_color_at: None,
        hypotheses: Vec::new(),
        looks_like: None,
        first: Vec::new(),
        bugs: Vec::new(),
        region_count: 0,
        regions: Vec::new(),
    };
    let mut differs = vec![None; ours.color.len()];
    for (k, &p) in theirs.pixels.iter().enumerate() {
        if ours.covered[k] && covered_by(p, by, tolerance) {
            let d = rgb_difference(p, ours.color[k]);
            if d > c.max_color_difference {
                c.max_color_difference = d;
                c.max_color_at = Some([(k as u32) % width, (k as u32) / width]);
            }
        }
        let Some(d) = classify(p, &ours, k, by, tolerance) else {
            continue;
        };
        match d {
            Difference::OnlyTheirs => c.only_theirs += 1,
            Difference::OnlyOurs => c.only_ours += 1,
            Difference::Color => c.color_differing += 1,
        }
        differs[k] = Some(d);
    }
    if c.agrees() {
        return Ok(c);
    }
    let made;
    let candidates = match candidates {
        Some(made) => made,
        None => {
            made = hypotheses::Candidates::new(reference, &render.frame)?;
            &made
        }
    };
    let tried = candidates.try_against(theirs, by, tolerance);
    let best = tried
        .iter()
        .filter(|h| h.differing * 2 < c.differing())
        .min_by_key(|h| h.differing);
    c.looks_like = best.map(|h| h.verdict());
    c.bugs = bugs::named(c.differing(), &tried);
    let context = diagnose::Context::new(reference, render, by, tolerance)?;
    let pixel = |k: usize, d: Difference| -> Result<PixelDifference, String> {
        let xy = [(k as u32) % width, (k as u32) / width];
        let explained = best.filter(|h| !h.differs_at(k));
        let reason = match explained {
            Some(h) => h.pixel_reason(k, &render.frame, reference.texture),
            None => context.reason(xy, d, theirs.pixels[k])?,
        };
        let t = render.frame.triangle[k];
        Ok(PixelDifference {
            pixel: xy,
            difference: d,
            theirs: theirs.pixels[k],
            ours: ours.color[k],
            triangle: (t != NO_TRIANGLE).then_some(t),
            reason,
        })
    };
    for (k, d) in differs.iter().enumerate() {
        if c.first.len() == LISTED {
            break;
        }
        if let Some(d) = d {
            c.first.push(pixel(k, *d)?);
        }
    }
    let components = regions::components(&differs, width as usize);
    c.region_count = components.len();
    for comp in components.iter().take(regions::REGIONS_LISTED) {
        let count = |want: Difference| {
            comp.indices
                .iter()
                .filter(|&&k| differs[k] == Some(want))
                .count()
        };
        let explained = best.map_or(0, |h| {
            comp.indices.iter().filter(|&&k| !h.differs_at(k)).count()
        });
        let mut samples = Vec::new();
        for k in comp.samples() {
            if let Some(d) = differs[k] {
                samples.push(pixel(k, d)?);
            }
        }
        let reason = match best {
            Some(h) if explained * 2 > comp.indices.len() => {
                Some(h.pixel_reason(comp.indices[0], &render.frame, reference.texture))
            }
            _ => commonest_reason(&samples),
        };
        c.regions.push(regions::Region {
            bbox: comp.bbox,
            pixels: comp.indices.len(),
            only_theirs: count(Difference::OnlyTheirs),
            only_ours: count(Difference::OnlyOurs),
            color: count(Difference::Color),
            explained,
            reason,
            samples,
        });
    }
    c.hypotheses = tried;
    Ok(c)
}

/// The reason of the commonest kind among `samples` (the first of that kind; among equally
/// common kinds, the one met first).
fn commonest_reason(samples: &[PixelDifference]) -> Option<reason::Reason> {
    let count = |kind: &str| samples.iter().filter(|p| p.reason.kind() == kind).count();
    samples
        .iter()
        .max_by(|a, b| {
            count(a.reason.kind())
                .cmp(&count(b.reason.kind()))
                // max_by keeps the last of equals: prefer the earlier sample.
                .then(std::cmp::Ordering::Greater)
        })
        .map(|p| p.reason.clone())
}

/// The difference image: barylab's image in dim grey where the two agree, red to yellow by
/// how much a colour differs, magenta where only the other image covers a pixel and cyan
/// where only barylab does.
pub fn difference_image(
    theirs: &Image,
    reference: &Reference,
    by: CoverageBy,
    tolerance: u8,
) -> Result<image::RgbaImage, String> {
    let render = render_for_comparison(reference.mesh, reference.texture, &reference.settings)?;
    Ok(difference_image_of(theirs, &render.frame, by, tolerance))
}

/// [`difference_image`] of barylab's frame already rendered (the sizes must match: pixels
/// past the shorter of the two are left black).
pub fn difference_image_of(
    theirs: &Image,
    frame: &crate::raster::Framebuffer,
    by: CoverageBy,
    tolerance: u8,
) -> image::RgbaImage {
    let ours = Rendered::of(frame);
    let mut out = image::RgbaImage::new(theirs.width, theirs.height);
    let n = ours.color.len();
    for (k, (px, &p)) in out.pixels_mut().zip(&theirs.pixels).take(n).enumerate() {
        let o = ours.color[k];
        let grey = ((u32::from(o[0]) * 3 + u32::from(o[1]) * 6 + u32::from(o[2])) / 10 / 3) as u8;
        px.0 = match classify(p, &ours, k, by, tolerance) {
            None => [grey, grey, grey, 255],
            Some(Difference::OnlyTheirs) => [255, 0, 255, 255],
            Some(Difference::OnlyOurs) => [0, 255, 255, 255],
            Some(Difference::Color) => {
                let d = rgb_difference(p, o);
                [255, d.saturating_mul(2), 0, 255]
            }
        };
    }
    out
}

/// How far apart the affine and the perspective-correct uv of pixel `k` are, in texels: the
/// heatmap's and the inspector's measure ([`texel_difference`](crate::figure::heatmap::texel_difference),
/// the length of the offset).
fn uv_gap_texels(frame: &crate::raster::Framebuffer, k: usize, texture: &Texture) -> f32 {
    crate::figure::heatmap::texel_difference(
        frame.uv_affine[k],
        frame.uv_perspective[k],
        (texture.width(), texture.height()),
    )
}
