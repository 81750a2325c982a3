//! Whole-image explanations of a multisampled reference ([`Kind::BlackEdges`],
//! [`Kind::NoAntiAliasing`], [`Kind::EdgesOnly`]): which pixels each leaves differing.
//!
//! An edge pixel is one whose resolved colour differs from barylab's single-sample colour
//! (more than the tolerance: a sample of another triangle, or of none, counts), or whose 3x3
//! neighbourhood in the single-sample render holds more than one triangle (or none).
//! A black-edge pixel (GAMES101 A2's supersampling bug: colour or depth kept per pixel while
//! coverage is per sample) is an edge pixel both images cover whose brightness
//! `r + g + b` is below that of every covered single-sample colour in its 3x3 neighbourhood
//! by more than `3 * tolerance`.

use super::verdict::Kind;
use super::{CoverageBy, Image, Rendered, classify};

/// The single-sample render and the multisampled one, in the comparison's terms.
pub struct Sampled<'a> {
    /// barylab's render as the reference settings ask (more than one sample).
    pub ours: &'a Rendered,
    /// barylab's render with one sample at each pixel centre.
    pub single: &'a Rendered,
    /// Image width in pixels.
    pub width: usize,
}

impl Sampled<'_> {
    /// The single-sample pixels `k` and its 8 neighbours (those inside the image).
    fn neighbourhood(&self, k: usize) -> impl Iterator<Item = usize> + '_ {
        let w = self.width;
        let h = self.ours.color.len() / w.max(1);
        let (x, y) = ((k % w) as i64, (k / w) as i64);
        (-1i64..=1)
            .flat_map(move |dy| (-1i64..=1).map(move |dx| (x + dx, y + dy)))
            .filter(move |&(nx, ny)| nx >= 0 && ny >= 0 && nx < w as i64 && ny < h as i64)
            .map(move |(nx, ny)| ny as usize * w + nx as usize)
    }

    /// Whether pixel `k` is on a triangle edge (see the module's definition).
    pub fn on_edge(&self, k: usize, tolerance: u8) -> bool {
        if super::rgb_difference(self.ours.color[k], self.single.color[k]) > tolerance {
            return true;
        }
        let c = self.single.covered[k];
        let t = self.single.color[k];
        self.neighbourhood(k).any(|j| {
            self.single.covered[j] != c
                || (c && super::rgb_difference(self.single.color[j], t) > tolerance)
        })
    }

    /// Whether the other image's pixel `k`, `theirs`, is a black-edge pixel.
    pub fn black_edge(&self, k: usize, theirs: [u8; 4], tolerance: u8) -> bool {
        let bright = |p: [u8; 4]| u32::from(p[0]) + u32::from(p[1]) + u32::from(p[2]);
        if !self.ours.covered[k] || !self.on_edge(k, tolerance) {
            return false;
        }
        let darkest = self
            .neighbourhood(k)
            .filter(|&j| self.single.covered[j])
            .map(|j| bright(self.single.color[j]))
            .min();
        darkest.is_some_and(|d| bright(theirs) + 3 * u32::from(tolerance) < d)
    }

    /// Per pixel, whether the other image differs under explanation `kind` (one of this
    /// module's three).
    pub fn mask(&self, kind: Kind, theirs: &Image, by: CoverageBy, tolerance: u8) -> Vec<bool> {
        theirs
            .pixels
            .iter()
            .enumerate()
            .map(|(k, &p)| match kind {
                Kind::NoAntiAliasing => classify(p, self.single, k, by, tolerance).is_some(),
                Kind::BlackEdges => {
                    classify(p, self.ours, k, by, tolerance).is_some()
                        && !self.black_edge(k, p, tolerance)
                }
                _ => {
                    classify(p, self.ours, k, by, tolerance).is_some()
                        && !self.on_edge(k, tolerance)
                }
            })
            .collect()
    }
}
