//! Edge planes and the rejection or acceptance of a whole block of pixels.

use super::*;

/// The edge functions of a triangle as planes over pixel indices:
/// `E_i(col, row) = a_i col + b_i row + c_i`, the value at the pixel centre
/// `(256 col + 128, 256 row + 128)` (1/256 pixel units). A pixel passes edge `i` when
/// `E_i >= t_i`, with `t_i = 0` on an inclusive edge (left or bottom under the default rule)
/// and 1 otherwise.
///
/// ```
/// use barylab::raster::clip::ClipVertex;
/// use barylab::raster::lanes::EdgePlanes;
/// use barylab::raster::project::{project_vertex, Viewport};
/// use barylab::raster::setup::{sample_point, setup_triangle};
/// use barylab::raster::varying::Varyings;
/// use glam::DVec4;
/// let vp = Viewport { width: 8, height: 8 };
/// let at = |x: f64, y: f64| project_vertex(&ClipVertex::new(
///     DVec4::new(x / 4.0 - 1.0, 1.0 - y / 4.0, 0.0, 1.0), Varyings::default()), vp);
/// let s = setup_triangle([at(0.0, 0.0), at(8.0, 0.0), at(0.0, 8.0)], vp).unwrap();
/// let planes = EdgePlanes::new(&s);
/// // The planes give the setup's own edge values at every pixel centre.
/// assert_eq!(planes.at(2, 3), s.edge_values(sample_point(3, 2)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EdgePlanes {
    /// Step of `E_i` per column, `-dir_y · 256`, in 1/65536 px².
    pub a: [i64; 3],
    /// Step of `E_i` per row, `dir_x · 256`, in 1/65536 px².
    pub b: [i64; 3],
    /// `E_i` at pixel (0, 0)'s centre, in 1/65536 px².
    pub c: [i64; 3],
    /// The smallest passing value of `E_i`
    /// ([`Edge::min_value`](crate::raster::setup::Edge::min_value)): 0 or 1.
    pub t: [i64; 3],
}

impl EdgePlanes {
    /// From `E(P) = dir_x (P_y - S_y) - dir_y (P_x - S_x)` with `P = (256 col + 128, 256 row + 128)`.
    pub fn new(setup: &TriangleSetup) -> Self {
        Self::from_edges(&setup.edges)
    }

    /// The planes of these three edges (as [`EdgePlanes::new`]).
    pub fn from_edges(edges: &[Edge; 3]) -> Self {
        let half = SUBPIXEL / 2;
        let mut out = Self {
            a: [0; 3],
            b: [0; 3],
            c: [0; 3],
            t: [0; 3],
        };
        for (i, e) in edges.iter().enumerate() {
            out.a[i] = -e.dir.y * SUBPIXEL;
            out.b[i] = e.dir.x * SUBPIXEL;
            out.c[i] = e.dir.x * (half - e.start.y) - e.dir.y * (half - e.start.x);
            out.t[i] = e.min_value();
        }
        out
    }

    /// The three edge values at pixel (col, row).
    #[inline]
    pub fn at(&self, row: i64, col: i64) -> [i64; 3] {
        // Written out: `[0, 1, 2].map` was left as a call in some builds.
        let e = |i: usize| self.a[i] * col + self.b[i] * row + self.c[i];
        [e(0), e(1), e(2)]
    }

    /// Whether every edge value over the columns `x0..=x1 + LANES` and rows `y0..=y1` is
    /// exact in `f64` (an edge function is linear, so its extremes are at the corners).
    pub(super) fn exact_over(&self, b: &PixelBounds) -> bool {
        let (x0, x1) = (i64::from(b.x0), i64::from(b.x1) + LANES as i64);
        let (y0, y1) = (i64::from(b.y0), i64::from(b.y1));
        [(y0, x0), (y0, x1), (y1, x0), (y1, x1)]
            .iter()
            .all(|&(r, c)| self.at(r, c).iter().all(|v| v.abs() < EXACT_EDGE_LIMIT))
    }
}

/// How a block relates to the triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Block {
    /// Outside one edge at all four corners: no pixel is covered.
    Outside,
    /// Inside every edge at all four corners: every pixel is covered.
    Inside,
    /// Pixels need testing one by one.
    Partial,
}

#[inline]
pub(super) fn classify(planes: &EdgePlanes, cols: (i64, i64), rows: (i64, i64)) -> Block {
    let corners = [
        planes.at(rows.0, cols.0),
        planes.at(rows.0, cols.1),
        planes.at(rows.1, cols.0),
        planes.at(rows.1, cols.1),
    ];
    let mut inside = true;
    for i in 0..3 {
        let lo = corners.iter().map(|e| e[i]).min().unwrap_or(0);
        let hi = corners.iter().map(|e| e[i]).max().unwrap_or(0);
        if hi < planes.t[i] {
            return Block::Outside;
        }
        inside &= lo >= planes.t[i];
    }
    if inside {
        Block::Inside
    } else {
        Block::Partial
    }
}

/// One block of the edge-function walk ([`Blocks`]): columns `x..x + LANES` (of which the
/// first `lanes_in` are inside the bounding box) by rows `rows.0..=rows.1`.
#[derive(Clone, Copy, Debug)]
pub(super) struct BlockAt {
    /// The block's first column.
    pub(super) x: u32,
    /// Its first and last row.
    pub(super) rows: (u32, u32),
    /// The columns from `x` inside the bounding box (1 to [`LANES`]).
    pub(super) lanes_in: usize,
    /// [`Block::Inside`] or [`Block::Partial`] (outside blocks are skipped).
    pub(super) kind: Block,
}

/// The block walk of the scalar and portable edge-function lanes (the AVX2 lanes write the
/// same loops out in `avx2::block_rows`, where this measured slower): the bounding box's columns
/// `x0..=x1` in blocks of [`LANES`], rows `y_start..=y_end` in blocks of [`BLOCK_ROWS`],
/// row of blocks by row of blocks, each block [`classify`]'d by its corners and yielded
/// unless it is outside. (An iterator, not a function taking the loop body: a closure was
/// left as a call, compiled without the caller's SSE4.1.)
pub(super) struct Blocks<'p> {
    planes: &'p EdgePlanes,
    cols: (u32, u32),
    y_end: u32,
    /// The current block's column and rows.
    x: u32,
    rows: (u32, u32),
}

impl<'p> Blocks<'p> {
    /// The blocks of columns `cols` (`x0..=x1`) over rows `y_start..=y_end`.
    #[inline(always)]
    pub(super) fn new(
        planes: &'p EdgePlanes,
        cols: (u32, u32),
        (y_start, y_end): (u32, u32),
    ) -> Self {
        Self {
            planes,
            cols,
            y_end,
            x: cols.0,
            rows: (y_start, (y_start + BLOCK_ROWS - 1).min(y_end)),
        }
    }
}

impl Iterator for Blocks<'_> {
    type Item = BlockAt;

    #[inline(always)]
    fn next(&mut self) -> Option<BlockAt> {
        loop {
            if self.x > self.cols.1 {
                let by = self.rows.1 + 1;
                self.rows = (by, (by + BLOCK_ROWS - 1).min(self.y_end));
                self.x = self.cols.0;
            }
            if self.rows.0 > self.y_end {
                return None;
            }
            let (bx, (by, by_end)) = (self.x, self.rows);
            self.x += LANES as u32;
            let kind = classify(
                self.planes,
                (i64::from(bx), i64::from(bx + LANES as u32 - 1)),
                (i64::from(by), i64::from(by_end)),
            );
            if kind != Block::Outside {
                return Some(BlockAt {
                    x: bx,
                    rows: (by, by_end),
                    lanes_in: (self.cols.1 - bx + 1).min(LANES as u32) as usize,
                    kind,
                });
            }
        }
    }
}

/// The row parts of four planes ([`ScreenPlane::part`] of the weights' row terms) for the
/// rows of one row of blocks, each made when first asked for.
pub(super) struct RowParts {
    pub(super) first: u32,
    made: u32,
    parts: [[f64; 4]; BLOCK_ROWS as usize],
}

impl RowParts {
    /// For the row of blocks from row `first`.
    #[inline(always)]
    pub(super) fn new(first: u32) -> Self {
        Self {
            first,
            made: 0,
            parts: [[0.0; 4]; BLOCK_ROWS as usize],
        }
    }

    /// The row parts of `planes` at row `y` (pixel centres: `y + 0.5`).
    #[inline(always)]
    pub(super) fn at(&mut self, y: u32, planes: &[ScreenPlane; 4], w: &WeightPlanes) -> [f64; 4] {
        let r = (y - self.first) as usize;
        if self.made & (1 << r) == 0 {
            self.made |= 1 << r;
            let rows = w.row_terms(f64::from(y) + 0.5);
            let part = |j: usize| planes[j].part(&rows);
            self.parts[r] = [part(0), part(1), part(2), part(3)];
        }
        self.parts[r]
    }
}
