//! What a render is asked for: the image size, interpolation, texture, shading, rasterizer,
//! tie rule and samples ([`RenderSettings`]), and the errors that stop a render as a whole
//! ([`RenderError`]). Every stage's driver reads these; they depend on no driver.

use super::interpolate::Interpolation;
use super::project::{MAX_IMAGE_SIZE, Viewport};
use super::sample::SampleSettings;
use super::setup::TieRule;
use super::shade::Shading;
use super::texture::{Filter, MaxAnisotropy, Wrap};

/// Which rasterizer visits the covered pixels. Both give the same coverage and values equal
/// up to floating-point rounding.
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, Hash, Default, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum Rasterizer {
    /// Every pixel centre in the bounding box is tested against the three edge functions and
    /// interpolated from its own weights.
    #[default]
    EdgeFunction,
    /// Spans per row, attributes stepped per pixel (the incremental scanline).
    Scanline,
}

/// How to draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderSettings {
    /// Image width in pixels (1 to [`MAX_IMAGE_SIZE`]).
    pub width: u32,
    /// Image height in pixels (1 to [`MAX_IMAGE_SIZE`]).
    pub height: u32,
    /// Affine (`noperspective`) or perspective-correct (`smooth`) interpolation.
    pub mode: Interpolation,
    /// Texture filter: nearest, bilinear or trilinear.
    pub filter: Filter,
    /// Texture wrap mode outside [0, 1].
    pub wrap: Wrap,
    /// The sampler's largest anisotropy: 1 (off, the default) to 16; above 1, trilinear
    /// filtering becomes anisotropic.
    pub max_anisotropy: MaxAnisotropy,
    /// What a fragment's colour is made from.
    pub shading: Shading,
    /// Overlay the source triangles' edges.
    pub wireframe: bool,
    /// RGBA of pixels no triangle covers.
    pub background: [u8; 4],
    /// Which pixel-coverage algorithm draws: edge functions or the scanline.
    pub rasterizer: Rasterizer,
    /// Which triangle owns a pixel centre exactly on a shared edge.
    pub tie_rule: TieRule,
    /// Samples per pixel, their pattern, the shading rate and the interpolation qualifiers
    /// (the default: one sample at the centre, as GL without multisampling).
    pub samples: SampleSettings,
}

/// The default background: a dark slate grey, opaque.
pub const DEFAULT_BACKGROUND: [u8; 4] = [36, 38, 46, 255];

impl Default for RenderSettings {
    fn default() -> Self {
        Self {
            width: 800,
            height: 600,
            mode: Interpolation::Perspective,
            filter: Filter::Bilinear,
            wrap: Wrap::Repeat,
            max_anisotropy: MaxAnisotropy::default(),
            shading: Shading::Texture,
            wireframe: false,
            background: DEFAULT_BACKGROUND,
            rasterizer: Rasterizer::EdgeFunction,
            tie_rule: TieRule::Llvmpipe,
            samples: SampleSettings::default(),
        }
    }
}

impl RenderSettings {
    /// Refuses an image size outside 1 to [`MAX_IMAGE_SIZE`] pixels per side
    /// ([`RenderError::BadSize`]).
    pub fn check_size(&self) -> Result<(), RenderError> {
        let (w, h) = (self.width, self.height);
        if (1..=MAX_IMAGE_SIZE).contains(&w) && (1..=MAX_IMAGE_SIZE).contains(&h) {
            Ok(())
        } else {
            Err(RenderError::BadSize {
                width: w,
                height: h,
            })
        }
    }

    /// The viewport (0, 0, width, height).
    pub fn viewport(&self) -> Viewport {
        Viewport {
            width: self.width,
            height: self.height,
        }
    }
}

/// Errors that stop a render as a whole.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RenderError {
    /// Width or height is 0 or above [`MAX_IMAGE_SIZE`].
    #[error("image size {width}x{height} is outside 1..={max} pixels per side", max = MAX_IMAGE_SIZE)]
    BadSize {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
    },
    /// The sample settings have no positions (the grid pattern with 8 samples).
    #[error("{0}")]
    BadSamples(String),
    /// The buffers would need more memory than the budget allows.
    #[error(transparent)]
    Memory(#[from] crate::budget::MemoryError),
}
