//! Float32 OpenEXR export of the per-pixel buffers ("arbitrary output variables").
//!
//! Each file is RGBA float32: covered pixels hold the value(s) in R, G, B and 1 in A;
//! uncovered pixels hold NaN in R, G, B and 0 in A.

use std::path::{Path, PathBuf};

use crate::raster::Framebuffer;
use crate::raster::interpolate::Interpolation;

/// Errors while writing AOV files.
#[derive(Debug, thiserror::Error)]
pub enum AovError {
    #[error("cannot create AOV folder {path}: {cause}")]
    Folder { path: String, cause: std::io::Error },
    #[error("cannot write {path}: {cause}")]
    Write {
        path: String,
        cause: exr::error::Error,
    },
}

/// The AOV file names, in the order they are written.
pub const AOV_FILES: [&str; 5] = [
    "uv.exr",
    "weights_screen.exr",
    "weights_perspective.exr",
    "depth.exr",
    "inv_w.exr",
];

fn write(
    path: &Path,
    frame: &Framebuffer,
    value: impl Fn(usize) -> [f32; 3] + Sync,
) -> Result<(), AovError> {
    let w = frame.width as usize;
    exr::prelude::write_rgba_file(path, w, frame.height as usize, |x, y| {
        let i = y * w + x;
        if frame.triangle[i] == crate::raster::NO_TRIANGLE {
            (f32::NAN, f32::NAN, f32::NAN, 0.0f32)
        } else {
            let v = value(i);
            (v[0], v[1], v[2], 1.0f32)
        }
    })
    .map_err(|cause| AovError::Write {
        path: path.display().to_string(),
        cause,
    })
}

/// Writes all AOV files into `dir` (created if missing). `uv.exr` holds the uv of `mode`.
/// Returns the paths written.
pub fn write_aovs(
    dir: &Path,
    frame: &Framebuffer,
    mode: Interpolation,
) -> Result<Vec<PathBuf>, AovError> {
    std::fs::create_dir_all(dir).map_err(|cause| AovError::Folder {
        path: dir.display().to_string(),
        cause,
    })?;
    let paths: Vec<PathBuf> = AOV_FILES.iter().map(|f| dir.join(f)).collect();
    let uv = match mode {
        Interpolation::Affine => &frame.uv_affine,
        Interpolation::Perspective => &frame.uv_perspective,
    };
    write(&paths[0], frame, |i| [uv[i][0], uv[i][1], 0.0])?;
    write(&paths[1], frame, |i| frame.weights_screen[i])?;
    write(&paths[2], frame, |i| frame.weights_perspective[i])?;
    write(&paths[3], frame, |i| [frame.depth[i]; 3])?;
    write(&paths[4], frame, |i| [frame.inv_w[i]; 3])?;
    Ok(paths)
}
