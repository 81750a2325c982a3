//! The animation formats: GIF (one palette, [`super::palette`]), APNG (lossless RGBA),
//! animated WebP (lossless, `webp.rs`) and MP4 (H.264 through an installed `ffmpeg`).
//! Each returns the file's bytes; the caller writes them atomically.

use std::io::Write;
use std::path::Path;
use std::process::{Command, Stdio};

use rayon::prelude::*;

use super::AnimateError;
use super::palette::Palette;

/// An animation file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// GIF with one palette for all frames.
    Gif,
    /// Animated PNG, lossless (`.apng`, or `.png`: browsers play both).
    Apng,
    /// Animated WebP, lossless.
    WebP,
    /// H.264 in MP4, through ffmpeg.
    Mp4,
}

/// The output extensions `barylab animate` accepts.
pub const EXTENSIONS: [&str; 5] = ["gif", "apng", "png", "webp", "mp4"];

impl Format {
    /// The format of `path` by its extension (any case), if it is one of [`EXTENSIONS`].
    ///
    /// ```
    /// use barylab::animate::Format;
    /// use std::path::Path;
    /// assert_eq!(Format::of(Path::new("a.GIF")), Some(Format::Gif));
    /// assert_eq!(Format::of(Path::new("a.png")), Some(Format::Apng));
    /// assert_eq!(Format::of(Path::new("a.svg")), None);
    /// ```
    pub fn of(path: &Path) -> Option<Format> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "gif" => Some(Format::Gif),
            "apng" | "png" => Some(Format::Apng),
            "webp" => Some(Format::WebP),
            "mp4" => Some(Format::Mp4),
            _ => None,
        }
    }

    /// The format's name in reports.
    pub fn name(self) -> &'static str {
        match self {
            Format::Gif => "GIF",
            Format::Apng => "APNG",
            Format::WebP => "WebP",
            Format::Mp4 => "MP4",
        }
    }
}

/// A GIF frame's delay in hundredths of a second at `fps`: `round(100 / fps)`, at least 2
/// (browsers show shorter delays as 10).
///
/// ```
/// assert_eq!(barylab::animate::encode::gif_delay(25.0), 4);
/// assert_eq!(barylab::animate::encode::gif_delay(30.0), 3);
/// assert_eq!(barylab::animate::encode::gif_delay(100.0), 2);
/// ```
pub fn gif_delay(fps: f64) -> u16 {
    (100.0 / fps).round().clamp(2.0, f64::from(u16::MAX)) as u16
}

/// The frames played at `fps` as a file of `format`.
pub fn encode(
    frames: &[image::RgbaImage],
    fps: f64,
    format: Format,
) -> Result<Vec<u8>, AnimateError> {
    if frames.is_empty() {
        return Err(AnimateError::Frames(0));
    }
    match format {
        Format::Gif => gif(frames, fps),
        Format::Apng => apng(frames, fps),
        Format::WebP => super::webp::encode(frames, fps),
        Format::Mp4 => mp4(frames, fps),
    }
}

fn encode_error(e: impl std::fmt::Display) -> AnimateError {
    AnimateError::Encode(e.to_string())
}

/// The smallest rectangle `(left, top, width, height)` holding every index that differs
/// between `a` and `b` (rows of `w`), or a single pixel when none does.
fn changed_rect(a: &[u8], b: &[u8], w: usize) -> (usize, usize, usize, usize) {
    let (mut x0, mut y0, mut x1, mut y1) = (usize::MAX, usize::MAX, 0, 0);
    for (i, _) in a.iter().zip(b).enumerate().filter(|(_, (p, q))| p != q) {
        let (x, y) = (i % w, i / w);
        x0 = x0.min(x);
        y0 = y0.min(y);
        x1 = x1.max(x);
        y1 = y1.max(y);
    }
    if x0 == usize::MAX {
        return (0, 0, 1, 1);
    }
    (x0, y0, x1 - x0 + 1, y1 - y0 + 1)
}

/// GIF: one global palette, looping forever. Without transparency a frame after the first
/// holds only the rectangle that changed (drawn over the previous frame); with it every
/// frame is whole and cleared after it is shown.
fn gif(frames: &[image::RgbaImage], fps: f64) -> Result<Vec<u8>, AnimateError> {
    let (w, h) = frames[0].dimensions();
    let too_large =
        || AnimateError::Encode(format!("a GIF is at most 65535 pixels a side, not {w}x{h}"));
    let (gw, gh) = (
        u16::try_from(w).map_err(|_| too_large())?,
        u16::try_from(h).map_err(|_| too_large())?,
    );
    let palette = Palette::of(frames);
    let indices: Vec<Vec<u8>> = frames.par_iter().map(|f| palette.indices(f)).collect();
    let mut bytes = Vec::new();
    {
        let mut enc =
            gif::Encoder::new(&mut bytes, gw, gh, &palette.rgb_bytes()).map_err(encode_error)?;
        enc.set_repeat(gif::Repeat::Infinite)
            .map_err(encode_error)?;
        let delay = gif_delay(fps);
        for (i, idx) in indices.iter().enumerate() {
            let whole = i == 0 || palette.transparent.is_some();
            let (left, top, fw, fh) = if whole {
                (0, 0, w as usize, h as usize)
            } else {
                changed_rect(&indices[i - 1], idx, w as usize)
            };
            let buffer: Vec<u8> = (top..top + fh)
                .flat_map(|y| &idx[y * w as usize + left..y * w as usize + left + fw])
                .copied()
                .collect();
            let frame = gif::Frame {
                delay,
                dispose: if palette.transparent.is_some() {
                    gif::DisposalMethod::Background
                } else {
                    gif::DisposalMethod::Keep
                },
                transparent: palette.transparent,
                left: left as u16,
                top: top as u16,
                width: fw as u16,
                height: fh as u16,
                buffer: buffer.into(),
                ..gif::Frame::default()
            };
            enc.write_frame(&frame).map_err(encode_error)?;
        }
    }
    Ok(bytes)
}

/// An APNG frame's delay as a fraction of a second: `100 / round(100 fps)`.
fn apng_delay(fps: f64) -> (u16, u16) {
    (
        100,
        (100.0 * fps).round().clamp(1.0, f64::from(u16::MAX)) as u16,
    )
}

/// APNG: lossless RGBA frames, looping forever.
fn apng(frames: &[image::RgbaImage], fps: f64) -> Result<Vec<u8>, AnimateError> {
    let (w, h) = frames[0].dimensions();
    let mut bytes = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut bytes, w, h);
        enc.set_color(png::ColorType::Rgba);
        enc.set_depth(png::BitDepth::Eight);
        enc.set_compression(png::Compression::Balanced);
        enc.set_animated(frames.len() as u32, 0)
            .map_err(encode_error)?;
        let (num, den) = apng_delay(fps);
        enc.set_frame_delay(num, den).map_err(encode_error)?;
        let mut writer = enc.write_header().map_err(encode_error)?;
        for f in frames {
            writer.write_image_data(f.as_raw()).map_err(encode_error)?;
        }
        writer.finish().map_err(encode_error)?;
    }
    Ok(bytes)
}

/// Whether `ffmpeg` runs.
pub fn has_ffmpeg() -> bool {
    Command::new("ffmpeg")
        .arg("-version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

/// MP4 (H.264, yuv420p) through ffmpeg: the frames over white (MP4 has no transparency),
/// padded to even sizes.
fn mp4(frames: &[image::RgbaImage], fps: f64) -> Result<Vec<u8>, AnimateError> {
    if !has_ffmpeg() {
        return Err(AnimateError::NoFfmpeg);
    }
    let (w, h) = frames[0].dimensions();
    let dir = tempfile::tempdir().map_err(encode_error)?;
    let out = dir.path().join("animation.mp4");
    let mut child = Command::new("ffmpeg")
        .args(["-nostdin", "-y", "-loglevel", "error", "-f", "rawvideo"])
        .args(["-pix_fmt", "rgb24", "-s", &format!("{w}x{h}")])
        .args(["-r", &format!("{fps}"), "-i", "-"])
        .args(["-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white"])
        .args([
            "-c:v",
            "libx264",
            "-pix_fmt",
            "yuv420p",
            "-movflags",
            "+faststart",
        ])
        .arg(&out)
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|_| AnimateError::NoFfmpeg)?;
    if let Some(mut stdin) = child.stdin.take() {
        for f in frames {
            let rgb: Vec<u8> = f
                .pixels()
                .flat_map(|p| {
                    let a = u32::from(p[3]);
                    [0, 1, 2].map(|c| ((u32::from(p[c]) * a + 255 * (255 - a) + 127) / 255) as u8)
                })
                .collect();
            if stdin.write_all(&rgb).is_err() {
                break;
            }
        }
    }
    let result = child.wait_with_output().map_err(encode_error)?;
    if !result.status.success() {
        let msg = String::from_utf8_lossy(&result.stderr);
        return Err(AnimateError::Encode(format!(
            "ffmpeg failed: {}",
            msg.lines().next().unwrap_or("no message")
        )));
    }
    std::fs::read(&out).map_err(encode_error)
}
