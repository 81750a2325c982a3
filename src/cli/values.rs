//! The command line's value types (modes, filters, shadings, ...) and parsers for sizes,
//! pixels, fractions and views.

use super::*;
use barylab::raster::texture::{MAX_ANISOTROPY, MaxAnisotropy};

#[derive(ValueEnum, Clone, Copy, Debug)]
pub(super) enum TieRuleArg {
    Llvmpipe,
    #[value(name = "top-left", alias = "top_left")]
    TopLeft,
}

impl From<TieRuleArg> for raster::setup::TieRule {
    fn from(r: TieRuleArg) -> Self {
        match r {
            TieRuleArg::Llvmpipe => Self::Llvmpipe,
            TieRuleArg::TopLeft => Self::TopLeft,
        }
    }
}

/// `--samples N`: 1, 4, 8 or 16.
pub(super) fn parse_samples(s: &str) -> Result<SampleCount, String> {
    let n: u32 = s
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a number of samples: expected 1, 4, 8 or 16"))?;
    SampleCount::try_from(n)
}

/// `--anisotropy N`: the largest anisotropy, 1 (off) to 16.
pub(super) fn parse_anisotropy(s: &str) -> Result<MaxAnisotropy, String> {
    let n: u32 = s.trim().parse().map_err(|_| {
        format!(
            "`{s}` is not a number: expected the largest anisotropy, 1 (off) to {MAX_ANISOTROPY}"
        )
    })?;
    MaxAnisotropy::new(n)
}

/// A value named as in scene files (`grid`, `ssaa`, `centroid`, `first`, ...), through the
/// type's own serde names, so the command line and the scene file accept the same words.
pub(super) fn parse_named<T: serde::de::DeserializeOwned>(s: &str) -> Result<T, String> {
    serde_json::from_value(serde_json::Value::String(s.trim().to_string()))
        .map_err(|e| e.to_string())
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub(super) enum FormatArg {
    Text,
    Markdown,
    Latex,
    Json,
}

impl From<FormatArg> for Format {
    fn from(f: FormatArg) -> Self {
        match f {
            FormatArg::Text => Format::Text,
            FormatArg::Markdown => Format::Markdown,
            FormatArg::Latex => Format::Latex,
            FormatArg::Json => Format::Json,
        }
    }
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub(super) enum ModeArg {
    Affine,
    Perspective,
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub(super) enum FilterArg {
    Nearest,
    Bilinear,
    Trilinear,
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub(super) enum ShadingArg {
    Texture,
    VertexColor,
    Barycentric,
    Depth,
    /// The interpolated view-space normal as colour, (n̂ + 1) / 2.
    Normal,
    /// A headlight Lambert shade of the vertex colour.
    Lambert,
}

impl From<ModeArg> for Interpolation {
    fn from(m: ModeArg) -> Self {
        match m {
            ModeArg::Affine => Interpolation::Affine,
            ModeArg::Perspective => Interpolation::Perspective,
        }
    }
}

impl From<FilterArg> for Filter {
    fn from(f: FilterArg) -> Self {
        match f {
            FilterArg::Nearest => Filter::Nearest,
            FilterArg::Bilinear => Filter::Bilinear,
            FilterArg::Trilinear => Filter::Trilinear,
        }
    }
}

impl From<ShadingArg> for Shading {
    fn from(s: ShadingArg) -> Self {
        match s {
            ShadingArg::Texture => Shading::Texture,
            ShadingArg::VertexColor => Shading::VertexColor,
            ShadingArg::Barycentric => Shading::Barycentric,
            ShadingArg::Depth => Shading::Depth,
            ShadingArg::Normal => Shading::Normal,
            ShadingArg::Lambert => Shading::Lambert,
        }
    }
}

/// Parses "WIDTHxHEIGHT".
pub(super) fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let bad = || format!("`{s}` is not a size like 800x600 (whole numbers from 1)");
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let w: u32 = w.trim().parse().map_err(|_| bad())?;
    let h: u32 = h.trim().parse().map_err(|_| bad())?;
    let max = raster::project::MAX_IMAGE_SIZE;
    if w == 0 || h == 0 || w > max || h > max {
        return Err(format!("size {w}x{h} is outside 1..={max} pixels per side"));
    }
    Ok((w, h))
}

/// Parses "X,Y" (whole numbers from 0).
pub(super) fn parse_pixel(s: &str) -> Result<(u32, u32), String> {
    let bad = || format!("`{s}` is not a pixel like 400,300 (column,row, whole numbers from 0)");
    let (x, y) = s.split_once(',').ok_or_else(bad)?;
    let x: u32 = x.trim().parse().map_err(|_| bad())?;
    let y: u32 = y.trim().parse().map_err(|_| bad())?;
    Ok((x, y))
}

/// Parses the app's text size (its zoom factor).
pub(super) fn parse_compare(s: &str) -> Result<(barylab::figure::Compare, bool), String> {
    use barylab::figure::Compare;
    let (gpu, view) = match s.strip_prefix("gpu") {
        Some("") => (true, "side"),
        Some(rest) => (true, rest.trim_start_matches('-')),
        None => (false, s),
    };
    let compare = match view {
        "single" => Compare::Single,
        "side" => Compare::SideBySide,
        "wipe" => Compare::Wipe,
        "difference" | "diff" => Compare::Difference,
        _ => {
            return Err(format!(
                "unknown view '{s}' (single, side, wipe, difference, gpu, gpu-single, \
                 gpu-wipe, gpu-difference)"
            ));
        }
    };
    Ok((compare, gpu))
}

pub(super) fn parse_text_size(s: &str) -> Result<f32, String> {
    let (lo, hi) = barylab::app::document::state::UI_SCALE_RANGE;
    match s.trim().parse::<f32>() {
        Ok(v) if (lo..=hi).contains(&v) => Ok(v),
        _ => Err(format!("text size `{s}`: a number from {lo} to {hi}")),
    }
}

/// Parses a window size "WIDTHxHEIGHT" in points.
pub(super) fn parse_window_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = parse_size(s)?;
    if w < 200 || h < 200 {
        return Err(format!(
            "window size {w}x{h} is too small (at least 200x200)"
        ));
    }
    Ok((w, h))
}
