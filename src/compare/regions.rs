//! Differing pixels grouped into regions: the connected components (8-neighbourhood) of the
//! pixels that differ, each with its bounding box, its size, what kind of difference its
//! pixels are, how many of them the whole-image explanation accounts for, and the reason that
//! explains most of it (from a few sample pixels).

use serde::Serialize;

use super::Difference;

/// Regions listed with reasons and samples (all are counted).
pub const REGIONS_LISTED: usize = 8;

/// Sample pixels kept per listed region, each with its reason.
pub const SAMPLES_PER_REGION: usize = 3;

/// A connected group of differing pixels.
#[derive(Clone, Debug, Serialize)]
pub struct Region {
    /// `[x0, y0, x1, y1]`, inclusive, row 0 at the top.
    pub bbox: [u32; 4],
    /// Pixels in the region.
    pub pixels: usize,
    /// Of them, covered only in the other image.
    pub only_theirs: usize,
    /// Covered only by barylab.
    pub only_ours: usize,
    /// Covered by both, colours apart.
    pub color: usize,
    /// Of them, the pixels the whole-image verdict (if any) accounts for.
    pub explained: usize,
    /// The reason that explains most of the region: the verdict's when it accounts for more
    /// than half of it, else the commonest kind of reason among the samples (in JSON:
    /// `reason` in English, `why` structured).
    #[serde(flatten, serialize_with = "reason_json")]
    pub reason: Option<super::reason::Reason>,
    /// A few of its pixels (the first in row order, one in the middle, the last), with
    /// their reasons.
    pub samples: Vec<super::PixelDifference>,
}

impl Region {
    /// The region in one line, numbered `i`, with its reason, in `lang` (indented as in
    /// `barylab compare`'s report).
    pub fn text(&self, i: usize, lang: crate::i18n::Lang) -> String {
        let reason = self
            .reason
            .as_ref()
            .map(|r| r.text(lang))
            .unwrap_or_default();
        lang.tr_with(
            "compare.report.region",
            &[
                ("i", &i),
                ("n", &self.pixels),
                ("x0", &self.bbox[0]),
                ("y0", &self.bbox[1]),
                ("x1", &self.bbox[2]),
                ("y1", &self.bbox[3]),
                ("only_image", &self.only_theirs),
                ("only_barylab", &self.only_ours),
                ("colour", &self.color),
                ("reason", &reason),
            ],
        )
    }
}

fn reason_json<S: serde::Serializer>(
    reason: &Option<super::reason::Reason>,
    serializer: S,
) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeMap;
    let mut m = serializer.serialize_map(Some(2))?;
    m.serialize_entry(
        "reason",
        &reason.as_ref().map(|r| r.text(crate::i18n::Lang::En)),
    )?;
    m.serialize_entry("why", reason)?;
    m.end()
}

/// One region's pixels before reasons: its indices in row order and counts.
#[derive(Clone, Debug)]
pub struct Component {
    /// Pixel indices `y * width + x`, in row order.
    pub indices: Vec<usize>,
    /// `[x0, y0, x1, y1]`, inclusive.
    pub bbox: [u32; 4],
}

impl Component {
    /// The sample pixels: the first in row order, the middle one, the last (distinct, at
    /// most [`SAMPLES_PER_REGION`]).
    pub fn samples(&self) -> Vec<usize> {
        let n = self.indices.len();
        let mut picks: Vec<usize> = [0, n / 2, n.saturating_sub(1)]
            .into_iter()
            .filter(|&i| i < n)
            .map(|i| self.indices[i])
            .collect();
        picks.dedup();
        picks.truncate(SAMPLES_PER_REGION);
        picks
    }
}

/// The connected components of the pixels where `differs[k]` is set (8-neighbourhood), in
/// an image `width` wide; largest first, among equal sizes the first in row order first.
pub fn components(differs: &[Option<Difference>], width: usize) -> Vec<Component> {
    const UNSEEN: u32 = u32::MAX;
    let width = width.max(1);
    let height = differs.len() / width;
    let mut label = vec![UNSEEN; differs.len()];
    let mut out = Vec::new();
    let mut stack = Vec::new();
    for start in 0..differs.len() {
        if differs[start].is_none() || label[start] != UNSEEN {
            continue;
        }
        let id = out.len() as u32;
        label[start] = id;
        stack.push(start);
        let mut indices = Vec::new();
        let (sx, sy) = ((start % width) as u32, (start / width) as u32);
        let mut bbox = [sx, sy, sx, sy];
        while let Some(k) = stack.pop() {
            indices.push(k);
            let (x, y) = (k % width, k / width);
            bbox = [
                bbox[0].min(x as u32),
                bbox[1].min(y as u32),
                bbox[2].max(x as u32),
                bbox[3].max(y as u32),
            ];
            for ny in y.saturating_sub(1)..=(y + 1).min(height.saturating_sub(1)) {
                for nx in x.saturating_sub(1)..=(x + 1).min(width - 1) {
                    let j = ny * width + nx;
                    if differs[j].is_some() && label[j] == UNSEEN {
                        label[j] = id;
                        stack.push(j);
                    }
                }
            }
        }
        indices.sort_unstable();
        out.push(Component { indices, bbox });
    }
    out.sort_by(|a, b| {
        b.indices
            .len()
            .cmp(&a.indices.len())
            .then(a.indices[0].cmp(&b.indices[0]))
    });
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn diagonal_neighbours_join_and_separate_groups_stay_apart() {
        // 5x4: an L of four pixels joined diagonally, and one pixel apart.
        let d = Some(Difference::Color);
        let mut m = vec![None; 20];
        for k in [0, 6, 12, 13, 4] {
            m[k] = d;
        }
        let c = components(&m, 5);
        assert_eq!(c.len(), 2);
        assert_eq!(c[0].indices, vec![0, 6, 12, 13]);
        assert_eq!(c[0].bbox, [0, 0, 3, 2]);
        assert_eq!(c[1].indices, vec![4]);
        assert_eq!(c[1].bbox, [4, 0, 4, 0]);
        assert_eq!(c[0].samples(), vec![0, 12, 13]);
        assert_eq!(c[1].samples(), vec![4]);
    }
}
