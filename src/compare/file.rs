//! Reading the image to compare: a regular file under the image size cap, its size checked
//! before it is decoded, decoded as RGBA8.

use std::io::Cursor;
use std::path::Path;

use super::Image;
use crate::files::{FileKind, read_regular, shown};

/// Reads the image at `path` as RGBA8. `check` sees the width and height before the pixels
/// are decoded and may refuse them with a message; sizes outside 1 to
/// [`MAX_IMAGE_SIZE`](crate::raster::project::MAX_IMAGE_SIZE) are refused first. The error is
/// one line naming the file and the problem.
pub fn read_image(
    path: &Path,
    check: impl FnOnce(u32, u32) -> Result<(), String>,
) -> Result<Image, String> {
    let bytes = read_regular(path, FileKind::Image).map_err(|e| e.to_string())?;
    let name = shown(path);
    let fail = |e: &dyn std::fmt::Display| format!("cannot read image {name}: {e}");
    let reader = || {
        image::ImageReader::new(Cursor::new(&bytes))
            .with_guessed_format()
            .map_err(|e| fail(&e))
    };
    let first = reader()?;
    if first.format().is_none() {
        return Err(fail(&"it is not a PNG, JPEG, BMP, TGA or WebP image"));
    }
    let (w, h) = reader()?.into_dimensions().map_err(|e| fail(&e))?;
    let max = crate::raster::project::MAX_IMAGE_SIZE;
    if w == 0 || h == 0 || w > max || h > max {
        return Err(fail(&format!(
            "it is {w}x{h}; barylab renders 1x1 to {max}x{max}"
        )));
    }
    check(w, h)?;
    let decoded = first.decode().map_err(|e| fail(&e))?.to_rgba8();
    Ok(Image {
        width: w,
        height: h,
        pixels: decoded.pixels().map(|p| p.0).collect(),
    })
}
