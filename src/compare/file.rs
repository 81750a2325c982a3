//! Reading the image to compare: a regular file under the image size cap, its size checked
//! before it is decoded, decoded as RGBA8.

use std::path::Path;

use super::Image;
use crate::files::{FileKind, read_regular, shown};
use crate::i18n::Lang;

/// Reads the image at `path` as RGBA8. `check` sees the width and height before the pixels
/// are decoded and may refuse them with a message; sizes outside 1 to
/// [`MAX_IMAGE_SIZE`](crate::raster::project::MAX_IMAGE_SIZE) are refused first. The error is
/// one line naming the file and the problem, in `lang` (the decoder's and the file system's
/// own messages stay as they are).
pub fn read_image(
    path: &Path,
    lang: Lang,
    check: impl FnOnce(u32, u32) -> Result<(), String>,
) -> Result<Image, String> {
    let bytes = read_regular(path, FileKind::Image).map_err(|e| e.to_string())?;
    let name = shown(path);
    let fail = |e: &dyn std::fmt::Display| {
        lang.tr_with(
            "compare.file.cannot_read",
            &[("file", &name), ("error", &e.to_string())],
        )
    };
    // The same reading as a texture's: TGA by its extension, truncated PNG and JPEG files
    // found, the size from the header.
    let opened = crate::raster::texture::open_image(&bytes, path).map_err(|p| match p {
        crate::raster::texture::ImageProblem::NotAnImage(_) => {
            fail(&lang.tr("compare.file.not_an_image"))
        }
        other => fail(&other),
    })?;
    let (w, h) = opened.size;
    let max = crate::raster::project::MAX_IMAGE_SIZE;
    if w == 0 || h == 0 || w > max || h > max {
        return Err(fail(&lang.tr_with(
            "compare.file.size",
            &[("w", &w), ("h", &h), ("max", &max)],
        )));
    }
    check(w, h)?;
    crate::budget::check(
        || format!("image {name} ({w}x{h})"),
        crate::budget::image_decode_need(w, h),
    )
    .map_err(|e| e.to_string())?;
    let decoded = opened.decode().map_err(|e| fail(&e))?;
    Ok(Image {
        width: w,
        height: h,
        pixels: decoded.pixels().map(|p| p.0).collect(),
    })
}
