//! Quantities linear on screen, each evaluated as one plane ([`ScreenPlane`]).

use glam::DVec2;

use super::WeightPlanes;

/// A quantity linear in window x and y, `f(P) = l_0(P) f_0 + l_1(P) f_1 + l_2(P) f_2`, with
/// its vertex values `f_i` folded into the weights' planes ([`WeightPlanes`]), the way a GPU
/// sets up an attribute once per triangle and then evaluates a plane per pixel (llvmpipe
/// does; GAMES101 lecture 9 and the OpenGL 4.6 spec, section 14.6.1, state it as
/// interpolation with the weights). With `k_i = f_i * (1 / area2)`,
///
/// `f(P) = R(P_y) - C(P_x)`, `R(y) = sum_i d_x,i (y - S_y,i) k_i`,
/// `C(x) = sum_i d_y,i (x - S_x,i) k_i`,
///
/// the row part `R` and the column part `C` each summed left to right from the weights' row
/// and column terms ([`WeightPlanes::row_term`], [`WeightPlanes::column_term`]). A row of
/// pixels shares `R`, a column shares `C`, so a pixel costs one subtraction per quantity:
/// the fast path evaluates `1/w`, the depth and `u/w`, `v/w` this way, and the full render
/// and the probe call the same functions, so their values are the fast path's bit for bit.
///
/// ```
/// use barylab::raster::setup::WeightPlanes;
/// use glam::DVec2;
/// let w = WeightPlanes::new([DVec2::new(0.0, 0.0), DVec2::new(4.0, 0.0), DVec2::new(0.0, 2.0)])
///     .unwrap();
/// // Depth 0.2 at (0, 0), 0.6 at (4, 0), 1.0 at (0, 2): at (1, 1), l = (0.25, 0.25, 0.5)
/// // and the depth is 0.05 + 0.15 + 0.5 = 0.7.
/// let depth = w.plane([0.2, 0.6, 1.0]);
/// assert!((w.value(&depth, DVec2::new(1.0, 1.0)) - 0.7).abs() < 1e-15);
/// // The same value from its parts: the row's and the column's.
/// let (row, column) = (depth.part(&w.row_terms(1.0)), depth.part(&w.column_terms(1.0)));
/// assert_eq!(row - column, w.value(&depth, DVec2::new(1.0, 1.0)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct ScreenPlane {
    /// `k_i = f_i * (1 / area2)`.
    pub k: [f64; 3],
}

impl ScreenPlane {
    /// The plane of no quantity (a placeholder before a triangle is set).
    pub const ZERO: Self = Self { k: [0.0; 3] };

    /// A row or column part from the weights' three row (or column) terms `t_i`:
    /// `(t_0 k_0 + t_1 k_1) + t_2 k_2`.
    #[inline(always)]
    pub fn part(&self, t: &[f64; 3]) -> f64 {
        t[0] * self.k[0] + t[1] * self.k[1] + t[2] * self.k[2]
    }
}

impl WeightPlanes {
    /// The plane of the quantity with vertex values `f`: `k_i = f_i * (1 / area2)`.
    #[inline(always)]
    pub fn plane(&self, f: [f64; 3]) -> ScreenPlane {
        ScreenPlane {
            k: [
                f[0] * self.inv_area2,
                f[1] * self.inv_area2,
                f[2] * self.inv_area2,
            ],
        }
    }

    /// The three row terms at window y ([`WeightPlanes::row_term`]).
    #[inline(always)]
    pub fn row_terms(&self, y: f64) -> [f64; 3] {
        [
            self.row_term(0, y),
            self.row_term(1, y),
            self.row_term(2, y),
        ]
    }

    /// The three column terms at window x ([`WeightPlanes::column_term`]).
    #[inline(always)]
    pub fn column_terms(&self, x: f64) -> [f64; 3] {
        [
            self.column_term(0, x),
            self.column_term(1, x),
            self.column_term(2, x),
        ]
    }

    /// A plane's value at window position `p`: `R(p_y) - C(p_x)` (see [`ScreenPlane`]).
    #[inline]
    pub fn value(&self, plane: &ScreenPlane, p: DVec2) -> f64 {
        plane.part(&self.row_terms(p.y)) - plane.part(&self.column_terms(p.x))
    }
}
