//! Float32 OpenEXR export of the per-pixel buffers ("arbitrary output variables").
//!
//! Each file is RGBA float32: covered pixels hold the value(s) in R, G, B and 1 in A;
//! uncovered pixels hold NaN in R, G, B and 0 in A.

use std::path::{Path, PathBuf};

use crate::files::{self, Staged, WriteError, shown};
use crate::raster::Framebuffer;
use crate::raster::interpolate::Interpolation;

/// Errors while writing AOV files.
#[derive(Debug, thiserror::Error)]
pub enum AovError {
    /// The folder cannot be created or written to, or is not a folder.
    #[error("cannot use AOV folder {path}: {problem}")]
    Folder {
        /// The folder, as shown in messages.
        path: String,
        /// What is wrong with it.
        problem: String,
    },
    /// Writing one of the files failed.
    #[error(transparent)]
    Write(#[from] WriteError),
}

/// The AOV file names, in the order they are written.
pub const AOV_FILES: [&str; 5] = [
    "uv.exr",
    "weights_screen.exr",
    "weights_perspective.exr",
    "depth.exr",
    "inv_w.exr",
];

/// Checks that `dir` can take the AOV files (creating it if missing), before a render.
pub fn check_folder(dir: &Path) -> Result<(), AovError> {
    let folder = |problem: String| AovError::Folder {
        path: shown(dir),
        problem,
    };
    if let Ok(meta) = std::fs::metadata(dir)
        && !meta.is_dir()
    {
        return Err(folder(format!("it is {}", files::describe(&meta))));
    }
    std::fs::create_dir_all(dir).map_err(|e| folder(e.to_string()))?;
    files::check_folder(dir).map_err(folder)
}

fn stage(
    path: &Path,
    frame: &Framebuffer,
    value: impl Fn(usize) -> [f32; 3] + Sync,
) -> Result<Staged, AovError> {
    use exr::prelude::{Image, SpecificChannels, Vec2, WritableImage};
    let w = frame.width as usize;
    let channels = SpecificChannels::rgba(|Vec2(x, y): Vec2<usize>| {
        let i = y * w + x;
        if frame.triangle[i] == crate::raster::NO_TRIANGLE {
            (f32::NAN, f32::NAN, f32::NAN, 0.0f32)
        } else {
            let v = value(i);
            (v[0], v[1], v[2], 1.0f32)
        }
    });
    let image = Image::from_channels((w, frame.height as usize), channels);
    Ok(files::stage(path, |out| {
        image
            .write()
            .to_buffered(out)
            .map_err(|e| std::io::Error::other(e.to_string()))
    })?)
}

/// Writes all AOV files into `dir` (created if missing), all or nothing: each is written to a
/// temporary file first and they are moved into place together once all were written, so a
/// failure leaves the folder as it was (no mix of new files and files of an earlier run).
/// `uv.exr` holds the uv of `mode`. Returns the paths written.
pub fn write_aovs(
    dir: &Path,
    frame: &Framebuffer,
    mode: Interpolation,
) -> Result<Vec<PathBuf>, AovError> {
    Ok(stage_aovs(dir, frame, mode)?
        .into_iter()
        .map(|s| {
            let path = s.path().to_path_buf();
            s.commit().map(|()| path)
        })
        .collect::<Result<_, _>>()?)
}

/// Writes the AOV files to temporary files in `dir` (created if missing), to be moved into
/// place with [`Staged::commit`] (after, for example, the image they go with was written).
pub fn stage_aovs(
    dir: &Path,
    frame: &Framebuffer,
    mode: Interpolation,
) -> Result<Vec<Staged>, AovError> {
    check_folder(dir)?;
    let paths: Vec<PathBuf> = AOV_FILES.iter().map(|f| dir.join(f)).collect();
    let uv = match mode {
        Interpolation::Affine => &frame.uv_affine,
        Interpolation::Perspective => &frame.uv_perspective,
    };
    Ok(vec![
        stage(&paths[0], frame, |i| [uv[i][0], uv[i][1], 0.0])?,
        stage(&paths[1], frame, |i| frame.weights_screen[i])?,
        stage(&paths[2], frame, |i| frame.weights_perspective[i])?,
        stage(&paths[3], frame, |i| [frame.depth[i]; 3])?,
        stage(&paths[4], frame, |i| [frame.inv_w[i]; 3])?,
    ])
}
