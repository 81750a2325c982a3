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
    /// Decoding it needs more memory than the limit (from its header, before decoding).
    #[error(transparent)]
    Memory(#[from] crate::budget::MemoryError),
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
            let tex = Self::try_from_image(&img)?.ok_or(TextureError::Empty {
                path: crate::files::shown(path),
            })?;
            return Ok((tex, None));
        }
        let scale = f64::from(MAX_TEXTURE_SIZE) / f64::from(w.max(h));
        let nw = ((f64::from(w) * scale).round() as u32).max(1);
        let nh = ((f64::from(h) * scale).round() as u32).max(1);
        let small = image::imageops::resize(&img, nw, nh, image::imageops::FilterType::Triangle);
        let tex = Self::try_from_image(&small)?.ok_or(TextureError::Empty {
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
            message,
        };
        let opened = open_image(&bytes, path).map_err(|p| decode_error(p.to_string()))?;
        let (w, h) = opened.size;
        crate::budget::check(
            || format!("decoding texture {} ({w}x{h})", shown(path)),
            crate::budget::image_decode_need(w, h),
        )?;
        opened.decode().map_err(decode_error)
    }
}

/// Why image bytes could not be opened, in plain words.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ImageProblem {
    /// Neither the content nor (for TGA, which has no signature) the extension is of a format
    /// barylab reads.
    #[error("it is not an image: its content is {0}, not PNG, JPEG, BMP, TGA or WebP data")]
    NotAnImage(&'static str),
    /// The file is cut short or damaged, or its header cannot be read.
    #[error("{0}")]
    Damaged(String),
}

/// An image file whose format and size are known, not yet decoded ([`open_image`]).
pub struct OpenedImage<'a> {
    reader: image::ImageReader<std::io::Cursor<&'a [u8]>>,
    /// The file's format.
    pub format: image::ImageFormat,
    /// Width and height from the header.
    pub size: (u32, u32),
}

/// Opens the image in `bytes` (the file `path`): its format from its content, TGA by its
/// extension; a PNG or JPEG without its end is truncated; the size from its header, before
/// any pixel is decoded. Shared by textures and the images `compare` reads.
pub fn open_image<'a>(bytes: &'a [u8], path: &Path) -> Result<OpenedImage<'a>, ImageProblem> {
    let reader = || image::ImageReader::new(std::io::Cursor::new(bytes));
    let sniffed = reader().with_guessed_format().ok().and_then(|r| r.format());
    let format = match sniffed {
        Some(f) => f,
        // TGA has no signature to sniff: trust the extension for it alone.
        None if image::ImageFormat::from_path(path).ok() == Some(image::ImageFormat::Tga) => {
            image::ImageFormat::Tga
        }
        None => return Err(ImageProblem::NotAnImage(content_kind(bytes))),
    };
    if let Some(problem) = truncated(format, bytes) {
        return Err(ImageProblem::Damaged(problem.to_string()));
    }
    let mut header = reader();
    header.set_format(format);
    let size = header
        .into_dimensions()
        .map_err(|e| ImageProblem::Damaged(plain_error(&e, format)))?;
    let mut reader = reader();
    reader.set_format(format);
    Ok(OpenedImage {
        reader,
        format,
        size,
    })
}

impl OpenedImage<'_> {
    /// Decodes the pixels as RGBA8. The decoder may allocate up to the memory limit
    /// ([`crate::budget::limit`]; the caller checked the image against it); its error in
    /// plain words ([`plain_error`]).
    pub fn decode(self) -> Result<image::RgbaImage, String> {
        let format = self.format;
        let mut reader = self.reader;
        let mut limits = image::Limits::default();
        limits.max_alloc = crate::budget::limit().ok().map(|l| l.bytes);
        reader.limits(limits);
        let img = reader.decode().map_err(|e| plain_error(&e, format))?;
        rgba8(img).map_err(|e| e.to_string())
    }
}

/// The decoded image as RGBA8: itself when it is RGBA8 already, else a copy whose memory is
/// asked for fallibly (an error naming it when the system refuses it, never an abort).
fn rgba8(img: image::DynamicImage) -> Result<image::RgbaImage, crate::budget::MemoryError> {
    use image::GenericImageView;
    if let image::DynamicImage::ImageRgba8(rgba) = img {
        return Ok(rgba);
    }
    let (w, h) = img.dimensions();
    let mut out = crate::budget::try_image(w, h, [0; 4], || format!("the {w}x{h} decoded image"))?;
    for (x, y, px) in out.enumerate_pixels_mut() {
        *px = img.get_pixel(x, y);
    }
    Ok(out)
}

/// What bytes that are not an image hold, for the message: "text" or "binary data".
fn content_kind(bytes: &[u8]) -> &'static str {
    /// Bytes looked at.
    const SAMPLE: usize = 512;
    let sample = &bytes[..bytes.len().min(SAMPLE)];
    let text = std::str::from_utf8(sample).is_ok_and(|t| {
        t.chars()
            .all(|c| !c.is_control() || c.is_ascii_whitespace())
    });
    if text { "text" } else { "binary data" }
}

/// A decoder's error in plain words, on one line: a damaged file, a truncated one, a feature
/// the decoder lacks, or an image past its limits; never the decoder's internal records.
pub fn plain_error(e: &image::ImageError, format: image::ImageFormat) -> String {
    use image::ImageError as E;
    let name = format!("{format:?}").to_uppercase();
    match e {
        E::Decoding(d) => {
            let text = one_line(&d.to_string());
            // Drop the decoder's prefix ("Format error decoding Png:") and any record it
            // appends ("while decoding ChunkType { ... }").
            let text = text.split_once(": ").map_or(text.as_str(), |(_, t)| t);
            let text = text.split(" while decoding").next().unwrap_or(text).trim();
            if text.contains("CRC error") {
                format!(
                    "the {name} file is damaged: a chunk's checksum (CRC) does not match its data"
                )
            } else {
                format!("the {name} file is damaged ({text})")
            }
        }
        E::IoError(io) if io.kind() == std::io::ErrorKind::UnexpectedEof => {
            format!("the {name} file is truncated (it ends before its image data)")
        }
        E::Limits(_) => format!(
            "the {name} image needs more memory to decode than the limit allows (see \
             --memory-limit)"
        ),
        E::Unsupported(u) => format!(
            "the {name} file uses a feature the decoder does not support ({})",
            one_line(&u.to_string())
        ),
        other => one_line(&other.to_string()),
    }
}
