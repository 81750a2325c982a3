//! Textures from image files: decoding (with the format guessed from the bytes, TGA by its
//! extension), truncated files as errors, flipped so that texel row 0 is the bottom.

use std::path::Path;

use super::{MAX_TEXTURE_SIZE, Texture};

/// Errors while loading a texture from a file.
#[derive(Debug, thiserror::Error)]
pub enum TextureError {
    /// The file could not be read.
    #[error(transparent)]
    File(#[from] crate::files::ReadError),
    /// The bytes are not an image the decoder reads (or are truncated).
    #[error("cannot decode texture {path}: {message}")]
    Decode {
        /// The file, as shown in messages.
        path: String,
        /// The decoder's message, on one line.
        message: String,
    },
    /// The file has 0 bytes, or the image has no pixels.
    #[error("texture {path} is empty (no pixels or 0 bytes)")]
    Empty {
        /// The file, as shown in messages.
        path: String,
    },
}

/// A decoder's message on one line, without trailing blank lines.
pub(super) fn one_line(message: &str) -> String {
    message
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join(" ")
}

/// Why an image file of `format` is cut short, if it is: decoders fill a truncated JPEG with
/// grey and may accept a PNG without its end, so the file's end marker is checked here.
fn truncated(format: image::ImageFormat, bytes: &[u8]) -> Option<&'static str> {
    match format {
        image::ImageFormat::Jpeg => {
            // The picture's data starts at its last start-of-scan marker (an embedded
            // thumbnail comes before it) and ends with the end-of-image marker; neither
            // byte pair occurs inside the entropy-coded data.
            let last = |marker: [u8; 2]| bytes.windows(2).rposition(|w| w == marker);
            match (last([0xFF, 0xDA]), last([0xFF, 0xD9])) {
                (Some(sos), Some(eoi)) if eoi > sos => None,
                _ => Some("the JPEG file is truncated (no end-of-image marker after its data)"),
            }
        }
        image::ImageFormat::Png => {
            // The last chunk: length 0, type IEND, its CRC.
            let iend = b"\0\0\0\0IEND\xAE\x42\x60\x82";
            (!bytes.windows(iend.len()).any(|w| w == iend))
                .then_some("the PNG file is truncated (no IEND chunk)")
        }
        _ => None,
    }
}

impl Texture {
    /// Loads PNG, JPEG, BMP, TGA or WebP from a file, converting to RGBA8.
    pub fn load(path: &Path) -> Result<Self, TextureError> {
        Ok(Self::load_noted(path)?.0)
    }

    /// Like [`Texture::load`]; images larger than [`MAX_TEXTURE_SIZE`] on a side are
    /// downscaled (keeping the aspect ratio), and the note says so.
    pub fn load_noted(path: &Path) -> Result<(Self, Option<String>), TextureError> {
        let img = Self::decode(path)?;
        let (w, h) = img.dimensions();
        if w.max(h) <= MAX_TEXTURE_SIZE {
            let tex = Self::from_image(&img).ok_or(TextureError::Empty {
                path: crate::files::shown(path),
            })?;
            return Ok((tex, None));
        }
        let scale = f64::from(MAX_TEXTURE_SIZE) / f64::from(w.max(h));
        let nw = ((f64::from(w) * scale).round() as u32).max(1);
        let nh = ((f64::from(h) * scale).round() as u32).max(1);
        let small = image::imageops::resize(&img, nw, nh, image::imageops::FilterType::Triangle);
        let tex = Self::from_image(&small).ok_or(TextureError::Empty {
            path: crate::files::shown(path),
        })?;
        let note = format!(
            "texture {} is {w}x{h}; downscaled to {nw}x{nh} for speed",
            crate::files::shown(path)
        );
        Ok((tex, Some(note)))
    }

    fn decode(path: &Path) -> Result<image::RgbaImage, TextureError> {
        use crate::files::{FileKind, read_regular, shown};
        let bytes = read_regular(path, FileKind::Texture)?;
        if bytes.is_empty() {
            return Err(TextureError::Empty { path: shown(path) });
        }
        let decode_error = |message: String| TextureError::Decode {
            path: shown(path),
            message: one_line(&message),
        };
        let mut reader = image::ImageReader::new(std::io::Cursor::new(&bytes[..]))
            .with_guessed_format()
            .map_err(|e| decode_error(e.to_string()))?;
        // TGA has no signature to sniff: fall back on the file's extension.
        if reader.format().is_none() {
            reader.set_format(
                image::ImageFormat::from_path(path).map_err(|e| decode_error(e.to_string()))?,
            );
        }
        if let Some(problem) = reader.format().and_then(|f| truncated(f, &bytes)) {
            return Err(decode_error(problem.to_string()));
        }
        let img = reader.decode().map_err(|e| decode_error(e.to_string()))?;
        Ok(img.to_rgba8())
    }
}
