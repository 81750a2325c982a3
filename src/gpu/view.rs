//! The app's GPU view, without GL: barylab's image beside the GPU's, the wipe between them,
//! and the difference image (coverage mismatches in strong colours, colour differences as a
//! heatmap), with the numbers of its one-line summary.

use crate::raster::NO_TRIANGLE;

/// Where only the GPU covers a pixel (the colour `barylab compare` uses for "only the image").
pub const ONLY_GPU: [u8; 4] = [255, 0, 255, 255];
/// Where only barylab covers a pixel.
pub const ONLY_BARYLAB: [u8; 4] = [0, 255, 255, 255];
/// The heatmap's top is at least this many levels, so that a 1-level difference is a dim
/// colour, not the brightest.
pub const MIN_SCALE: u8 = 4;

/// barylab's image and the GPU's, compared pixel by pixel for the GPU view.
#[derive(Clone, Debug, PartialEq)]
pub struct ImageDiff {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Pixels compared, `width * height`.
    pub pixels: usize,
    /// Pixels covered by barylab.
    pub covered: usize,
    /// Pixels covered by the GPU and not by barylab.
    pub only_gpu: usize,
    /// Pixels covered by barylab and not by the GPU.
    pub only_barylab: usize,
    /// Pixels both cover whose owning triangle differs.
    pub triangle_mismatches: usize,
    /// Pixels both cover whose colour differs in some channel.
    pub color_differing: usize,
    /// The largest difference of one 8-bit channel over the pixels both cover.
    pub max_color_difference: u8,
    /// The pixel to look at first, (x, y) in image rows: the first coverage mismatch, else
    /// the first owning-triangle mismatch, else the first pixel with the largest colour
    /// difference; `None` when the images are identical.
    pub worst: Option<[u32; 2]>,
    /// The difference image, RGBA8, row 0 at the top: barylab's colour dimmed to grey where
    /// the two agree, [`ONLY_GPU`] and [`ONLY_BARYLAB`] where coverage differs, and the
    /// colour difference as a heatmap (see [`heat_top`]) where it is not 0.
    pub image: Vec<[u8; 4]>,
}

impl ImageDiff {
    /// Pixels whose coverage is the same in both (covered by both or by neither).
    pub fn coverage_same(&self) -> usize {
        self.pixels - self.only_gpu - self.only_barylab
    }

    /// Whether both cover exactly the same pixels.
    pub fn coverage_identical(&self) -> bool {
        self.only_gpu == 0 && self.only_barylab == 0
    }

    /// The summary in English, as the app prints it for a `--screenshot` run: "coverage
    /// identical on N of M pixels; largest colour difference K levels".
    pub fn summary_en(&self) -> String {
        format!(
            "coverage identical on {} of {} pixels; largest colour difference {}",
            self.coverage_same(),
            self.pixels,
            crate::i18n::Lang::En.levels(self.max_color_difference)
        )
    }
}

/// The heatmap's top value in levels for a largest difference `max`: `max`, at least
/// [`MIN_SCALE`].
pub fn heat_top(max: u8) -> u8 {
    max.max(MIN_SCALE)
}

/// Compares barylab's render (`ours_triangle`: the owning triangle per pixel, [`NO_TRIANGLE`]
/// where none; `ours_color`) with the GPU's (`gl_ids`: the `Output::TriangleId`
/// image, `gl_colors`: its colour image), all `width` pixels wide in image row order.
///
/// ```
/// use barylab::gpu::view::{ONLY_GPU, image_diff};
/// use barylab::raster::NO_TRIANGLE;
/// let bg = [0, 0, 0, 255];
/// let red = [200, 0, 0, 255];
/// // Two pixels: barylab covers the first with triangle 0, the GPU covers both.
/// let d = image_diff(2, &[0, NO_TRIANGLE], &[red, bg], &[[1, 0, 0, 0]; 2], &[red, red]);
/// assert_eq!((d.only_gpu, d.only_barylab, d.coverage_same()), (1, 0, 1));
/// assert_eq!(d.worst, Some([1, 0]));
/// assert_eq!(d.image[1], ONLY_GPU);
/// ```
pub fn image_diff(
    width: u32,
    ours_triangle: &[u32],
    ours_color: &[[u8; 4]],
    gl_ids: &[[u8; 4]],
    gl_colors: &[[u8; 4]],
) -> ImageDiff {
    let n = ours_color
        .len()
        .min(ours_triangle.len())
        .min(gl_ids.len())
        .min(gl_colors.len());
    let width = width.max(1);
    let xy = |k: usize| [(k as u32) % width, (k as u32) / width];
    let mut d = ImageDiff {
        width,
        height: (n as u32).div_ceil(width),
        pixels: n,
        covered: 0,
        only_gpu: 0,
        only_barylab: 0,
        triangle_mismatches: 0,
        color_differing: 0,
        max_color_difference: 0,
        worst: None,
        image: Vec::with_capacity(n),
    };
    let mut diffs = vec![0u8; n];
    let (mut first_coverage, mut first_triangle, mut first_max) = (None, None, None);
    for k in 0..n {
        let ours = ours_triangle[k] != NO_TRIANGLE;
        let gl_id = u32::from_le_bytes(gl_ids[k]);
        let theirs = gl_id != 0;
        d.covered += usize::from(ours);
        if ours != theirs {
            if ours {
                d.only_barylab += 1;
            } else {
                d.only_gpu += 1;
            }
            first_coverage.get_or_insert(k);
            continue;
        }
        if !ours {
            continue;
        }
        if gl_id != ours_triangle[k].wrapping_add(1) {
            d.triangle_mismatches += 1;
            first_triangle.get_or_insert(k);
        }
        let diff = (0..4)
            .map(|i| ours_color[k][i].abs_diff(gl_colors[k][i]))
            .max()
            .unwrap_or(0);
        diffs[k] = diff;
        if diff > 0 {
            d.color_differing += 1;
        }
        if diff > d.max_color_difference {
            d.max_color_difference = diff;
            first_max = Some(k);
        }
    }
    d.worst = first_coverage.or(first_triangle).or(first_max).map(xy);
    let top = f32::from(heat_top(d.max_color_difference));
    for k in 0..n {
        let ours = ours_triangle[k] != NO_TRIANGLE;
        let theirs = u32::from_le_bytes(gl_ids[k]) != 0;
        d.image.push(match (ours, theirs) {
            (false, true) => ONLY_GPU,
            (true, false) => ONLY_BARYLAB,
            _ if diffs[k] > 0 => crate::figure::heatmap::heat_color(f32::from(diffs[k]), top),
            _ => dimmed(ours_color[k]),
        });
    }
    d
}

/// A colour as a dim grey (a third of its luma), for pixels where the two images agree.
pub fn dimmed(c: [u8; 4]) -> [u8; 4] {
    let luma = (299 * u32::from(c[0]) + 587 * u32::from(c[1]) + 114 * u32::from(c[2])) / 1000;
    let g = (24 + luma / 3) as u8;
    [g, g, g, 255]
}

/// The wipe between barylab's image (left of `column`) and the GPU's (from it on).
pub fn wipe(ours: &[[u8; 4]], gpu: &[[u8; 4]], width: u32, column: u32) -> Vec<[u8; 4]> {
    crate::figure::wipe_pixels(ours, gpu, width, column)
}

#[cfg(test)]
mod tests {
    use super::*;

    const BG: [u8; 4] = [10, 10, 10, 255];

    /// A 4x2 image: barylab covers x < 2 with triangle 0 (x = 0) and 1 (x = 1) in both rows.
    fn ours() -> (Vec<u32>, Vec<[u8; 4]>) {
        let tri = vec![
            0,
            1,
            NO_TRIANGLE,
            NO_TRIANGLE,
            0,
            1,
            NO_TRIANGLE,
            NO_TRIANGLE,
        ];
        let col = tri
            .iter()
            .map(|&t| {
                if t == NO_TRIANGLE {
                    BG
                } else {
                    [100, 150, 200, 255]
                }
            })
            .collect();
        (tri, col)
    }

    fn ids(tri: &[u32]) -> Vec<[u8; 4]> {
        tri.iter()
            .map(|&t| t.wrapping_add(1).to_le_bytes())
            .collect()
    }

    #[test]
    fn identical_images_agree_everywhere() {
        let (tri, col) = ours();
        let d = image_diff(4, &tri, &col, &ids(&tri), &col);
        assert!(d.coverage_identical());
        assert_eq!((d.coverage_same(), d.pixels, d.covered), (8, 8, 4));
        assert_eq!((d.max_color_difference, d.color_differing), (0, 0));
        assert_eq!(d.worst, None);
        assert_eq!(d.height, 2);
        assert!(d.image.iter().zip(&col).all(|(a, &b)| *a == dimmed(b)));
        assert_eq!(
            d.summary_en(),
            "coverage identical on 8 of 8 pixels; largest colour difference 0 levels"
        );
        // One level apart at one pixel (llvmpipe's usual rounding): the unit in the singular.
        let mut gl_col = col.clone();
        gl_col[1][0] ^= 1;
        let d = image_diff(4, &tri, &col, &ids(&tri), &gl_col);
        assert_eq!(d.max_color_difference, 1);
        assert_eq!(
            d.summary_en(),
            "coverage identical on 8 of 8 pixels; largest colour difference 1 level"
        );
    }

    #[test]
    fn coverage_mismatches_are_marked_and_come_first() {
        let (tri, col) = ours();
        let mut gl_tri = tri.clone();
        gl_tri[2] = 1; // (2, 0): only the GPU
        gl_tri[4] = NO_TRIANGLE; // (0, 1): only barylab
        gl_tri[5] = 0; // (1, 1): another triangle
        let mut gl_col = col.clone();
        gl_col[1] = [100, 150, 203, 255]; // (1, 0): 3 levels
        let d = image_diff(4, &tri, &col, &ids(&gl_tri), &gl_col);
        assert_eq!((d.only_gpu, d.only_barylab), (1, 1));
        assert_eq!(d.coverage_same(), 6);
        assert_eq!(d.triangle_mismatches, 1);
        assert_eq!((d.max_color_difference, d.color_differing), (3, 1));
        assert_eq!(d.worst, Some([2, 0]));
        assert_eq!(d.image[2], ONLY_GPU);
        assert_eq!(d.image[4], ONLY_BARYLAB);
        let heat = crate::figure::heatmap::heat_color(3.0, 4.0);
        assert_eq!(d.image[1], heat);
        assert_ne!(heat, dimmed(col[1]));
    }

    #[test]
    fn without_coverage_mismatches_the_worst_is_the_largest_colour_difference() {
        let (tri, col) = ours();
        let mut gl_col = col.clone();
        gl_col[0] = [101, 150, 200, 255];
        gl_col[4] = [100, 170, 200, 255];
        gl_col[5] = [100, 170, 200, 255];
        let d = image_diff(4, &tri, &col, &ids(&tri), &gl_col);
        assert_eq!(d.max_color_difference, 20);
        assert_eq!(d.worst, Some([0, 1]));
        assert_eq!(heat_top(1), MIN_SCALE);
        assert_eq!(heat_top(20), 20);
    }
}
