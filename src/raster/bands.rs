//! Binning for parallel rasterization: which set-up triangles reach each band of image rows
//! ([`bin_rows`]). Each band ([`RowBand`](super::framebuffer::RowBand)) is one rayon task of
//! the full render and of the fast path, and visits only the triangles of its bin, in
//! submission order. [`RowsDrawn`] counts a band's rows for the progress display;
//! [`stop_at`] stops a band of a cancelled render.

use crate::progress::RenderProgress;

/// The triangles that reach each band of `rows_per_band` rows of an image `height` rows high:
/// every `(triangle, setup, first row, last row)` of `spans`, in order, is added as
/// `(triangle, setup)` to the bin of every band from the one holding its first row to the
/// one holding its last (bands `first / rows_per_band ..= last / rows_per_band`, the last band
/// included at most). `bins` is reused: it ends with one bin per band, each refilled.
pub(super) fn bin_rows(
    bins: &mut Vec<Vec<(u32, u32)>>,
    height: u32,
    rows_per_band: u32,
    spans: impl Iterator<Item = (u32, u32, u32, u32)>,
) {
    let bands = height.div_ceil(rows_per_band).max(1) as usize;
    bins.resize_with(bands, Vec::new);
    bins.truncate(bands);
    bins.iter_mut().for_each(Vec::clear);
    for (ti, si, y0, y1) in spans {
        let first = (y0 / rows_per_band) as usize;
        let last = ((y1 / rows_per_band) as usize).min(bands - 1);
        for bin in bins.iter_mut().take(last + 1).skip(first) {
            bin.push((ti, si));
        }
    }
}

/// Counts a band's rows as drawn ([`crate::progress`]) when the band is done.
pub(super) struct RowsDrawn<'a>(pub(super) &'a RenderProgress, pub(super) u32);

impl Drop for RowsDrawn<'_> {
    fn drop(&mut self) {
        self.0.rows_drawn(self.1);
    }
}

/// How many triangles a band draws between two looks at its render's cancel flag.
pub(super) const CANCEL_CHECK_TRIANGLES: usize = 256;

/// Whether the band drawing its `j`th triangle stops there: its render was cancelled (looked
/// at every [`CANCEL_CHECK_TRIANGLES`] triangles).
pub(super) fn stop_at(progress: &RenderProgress, j: usize) -> bool {
    j.is_multiple_of(CANCEL_CHECK_TRIANGLES) && progress.cancelled()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A span lands in every band its rows reach, clamped to the last band, in order.
    #[test]
    fn spans_land_in_the_bands_their_rows_reach() {
        let mut bins = vec![vec![(9, 9)]; 5];
        bin_rows(
            &mut bins,
            40,
            16,
            [(0, 0, 0, 15), (1, 0, 15, 16), (2, 1, 30, 99)].into_iter(),
        );
        assert_eq!(
            bins,
            vec![vec![(0, 0), (1, 0)], vec![(1, 0), (2, 1)], vec![(2, 1)]]
        );
    }
}
