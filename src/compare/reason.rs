//! The words of a differing pixel's reason: [`Reason`], structured, and [`Reason::text`],
//! which words it in a language from the catalogues' `compare` section.

use serde::Serialize;

use super::verdict::Verdict;
use crate::i18n::Lang;
use crate::raster::Interpolation;
use crate::raster::setup::{EdgeKind, TieRule};

/// Why one pixel differs: structured, so that it can be worded in any language
/// ([`Reason::text`]) and written as machine data (`kind` names the variant in JSON).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Reason {
    /// The centre lies exactly on an edge of a triangle: the tie rule decided.
    OnEdge {
        /// The edge's name, e.g. `AC`.
        edge: String,
        /// Which kind of edge it is.
        edge_kind: EdgeKind,
        /// The triangle's name, e.g. `ABC`.
        triangle: String,
        /// The tie rule barylab follows.
        rule: TieRule,
        /// The triangle the rule gives the centre to (`None`: none).
        owner: Option<String>,
    },
    /// barylab's triangle covers the centre (nothing more is known).
    Covered {
        /// The triangle's name.
        triangle: String,
    },
    /// The centre lies inside barylab's triangle, `distance` pixels from its nearest edge.
    Inside {
        /// Pixels from the edge.
        distance: f64,
        /// The nearest edge's name.
        edge: String,
        /// The triangle's name.
        triangle: String,
    },
    /// The centre lies outside every triangle, `distance` pixels outside the nearest edge.
    Outside {
        /// Pixels from the edge.
        distance: f64,
        /// The edge's name.
        edge: String,
        /// The triangle's name.
        triangle: String,
    },
    /// No triangle comes near the centre.
    NothingNear,
    /// The other image's colour is barylab's in the other interpolation mode.
    OtherMode {
        /// How far apart the two modes' uv are here, in texels.
        texels: f32,
        /// The mode the other image looks like.
        looks_like: Interpolation,
    },
    /// Two triangles cover the centre; the depth test keeps the nearer.
    Depth {
        /// The triangle barylab keeps.
        front: String,
        /// The triangle behind it.
        behind: String,
        /// The front triangle's window depth.
        front_depth: f32,
        /// The hidden triangle's window depth.
        behind_depth: f32,
    },
    /// An edge pixel whose colour lies between barylab's and a neighbour's.
    AntiAliased {
        /// The neighbour `[x, y]`.
        neighbour: [u32; 2],
    },
    /// The colours differ and nothing above explains it.
    Colour {
        /// The largest channel difference in 8-bit levels.
        levels: u8,
        /// The triangle barylab draws there.
        triangle: Option<u32>,
        /// barylab's uv there.
        uv: [f32; 2],
        /// barylab's RGB there.
        colour: [u8; 3],
    },
    /// A whole-image explanation accounts for the pixel.
    Explained {
        /// The explanation.
        verdict: Verdict,
    },
}

impl Reason {
    /// The stable code of the reason's kind, as in JSON: `on_edge`, `outside`, `other_mode`…
    pub fn kind(&self) -> &'static str {
        match self {
            Reason::OnEdge { .. } => "on_edge",
            Reason::Covered { .. } => "covered",
            Reason::Inside { .. } => "inside",
            Reason::Outside { .. } => "outside",
            Reason::NothingNear => "nothing_near",
            Reason::OtherMode { .. } => "other_mode",
            Reason::Depth { .. } => "depth",
            Reason::AntiAliased { .. } => "anti_aliased",
            Reason::Colour { .. } => "colour",
            Reason::Explained { .. } => "explained",
        }
    }

    /// The reason in one line, in `lang`.
    pub fn text(&self, lang: Lang) -> String {
        match self {
            Reason::OnEdge {
                edge,
                edge_kind,
                triangle,
                rule,
                owner,
            } => {
                let kind = lang.tr(match edge_kind {
                    EdgeKind::Left => "compare.edge.left",
                    EdgeKind::Right => "compare.edge.right",
                    EdgeKind::Top => "compare.edge.top",
                    EdgeKind::Bottom => "compare.edge.bottom",
                });
                let rule = lang.tr(match rule {
                    TieRule::Llvmpipe => "compare.tie.llvmpipe",
                    TieRule::TopLeft => "compare.tie.top_left",
                    TieRule::AllEdges => "compare.tie.all_edges",
                    TieRule::NoEdges => "compare.tie.no_edges",
                });
                let args: [(&str, &dyn std::fmt::Display); 4] = [
                    ("edge", edge),
                    ("kind", &kind),
                    ("triangle", triangle),
                    ("rule", &rule),
                ];
                match owner {
                    Some(o) => {
                        let mut all = args.to_vec();
                        all.push(("owner", o));
                        lang.tr_with("compare.reason.on_edge_owned", &all)
                    }
                    None => lang.tr_with("compare.reason.on_edge_left_out", &args),
                }
            }
            Reason::Covered { triangle } => {
                lang.tr_with("compare.reason.covered", &[("triangle", triangle)])
            }
            Reason::Inside {
                distance,
                edge,
                triangle,
            } => lang.tr_with(
                "compare.reason.inside",
                &[
                    ("distance", &px(*distance)),
                    ("edge", edge),
                    ("triangle", triangle),
                    (
                        "closeness",
                        &closeness(*distance, "compare.other_leaves", lang),
                    ),
                ],
            ),
            Reason::Outside {
                distance,
                edge,
                triangle,
            } => lang.tr_with(
                "compare.reason.outside",
                &[
                    ("distance", &px(*distance)),
                    ("edge", edge),
                    ("triangle", triangle),
                    (
                        "closeness",
                        &closeness(*distance, "compare.other_covers", lang),
                    ),
                ],
            ),
            Reason::NothingNear => lang.tr("compare.reason.nothing_near"),
            Reason::OtherMode { texels, looks_like } => lang.tr_with(
                "compare.reason.other_mode",
                &[
                    ("texels", &format!("{texels:.1}")),
                    ("mode", &mode_short(*looks_like, lang)),
                ],
            ),
            Reason::Depth {
                front,
                behind,
                front_depth,
                behind_depth,
            } => lang.tr_with(
                "compare.reason.depth",
                &[
                    ("front", front),
                    ("behind", behind),
                    ("front_depth", &format!("{front_depth:.5}")),
                    ("behind_depth", &format!("{behind_depth:.5}")),
                ],
            ),
            Reason::AntiAliased { neighbour: [x, y] } => {
                lang.tr_with("compare.reason.anti_aliased", &[("x", x), ("y", y)])
            }
            Reason::Colour {
                levels,
                triangle,
                uv,
                colour,
            } => lang.tr_with(
                "compare.reason.colour",
                &[
                    ("levels", &lang.levels(*levels)),
                    (
                        "triangle",
                        &triangle.map_or_else(|| "-".to_string(), |t| t.to_string()),
                    ),
                    ("u", &format!("{:.4}", uv[0])),
                    ("v", &format!("{:.4}", uv[1])),
                    ("colour", &format!("{colour:?}")),
                ],
            ),
            Reason::Explained { verdict } => lang.tr_with(
                "compare.reason.explained",
                &[
                    ("description", &verdict.description(lang)),
                    ("verdict", &verdict.short(lang)),
                ],
            ),
        }
    }
}

/// "affine" or "perspective-correct" in `lang`: the mode in a pixel's reason.
pub fn mode_short(mode: Interpolation, lang: Lang) -> String {
    lang.tr(match mode {
        Interpolation::Affine => "compare.mode_short.affine",
        Interpolation::Perspective => "compare.mode_short.perspective",
    })
}

/// A distance in pixels, with enough digits for a hair's breadth.
fn px(d: f64) -> String {
    if d < 0.01 {
        format!("{d:.4}")
    } else {
        format!("{d:.2}")
    }
}

/// What a centre this close to an edge means, in `lang`; `other` is the catalogue key of
/// what the other image did.
fn closeness(d: f64, other: &str, lang: Lang) -> String {
    let grid = crate::raster::project::SUBPIXEL;
    let subpixel = 1.0 / grid as f64;
    let other = lang.tr(other);
    let key = if d <= subpixel {
        "compare.close.snapping"
    } else if d < 0.5 {
        "compare.close.half_pixel"
    } else {
        "compare.close.clear"
    };
    lang.tr_with(key, &[("other", &other), ("grid", &grid)])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compare::verdict::Kind;

    /// One reason of every kind (and every verdict kind in `Explained`).
    fn every_reason() -> Vec<Reason> {
        let mut all = vec![
            Reason::OnEdge {
                edge: "AC".into(),
                edge_kind: EdgeKind::Left,
                triangle: "ABC".into(),
                rule: TieRule::Llvmpipe,
                owner: Some("ACD".into()),
            },
            Reason::OnEdge {
                edge: "AC".into(),
                edge_kind: EdgeKind::Top,
                triangle: "ABC".into(),
                rule: TieRule::TopLeft,
                owner: None,
            },
            Reason::Covered {
                triangle: "ABC".into(),
            },
            Reason::NothingNear,
            Reason::OtherMode {
                texels: 3.2,
                looks_like: Interpolation::Affine,
            },
            Reason::Depth {
                front: "ABC".into(),
                behind: "DEF".into(),
                front_depth: 0.25,
                behind_depth: 0.5,
            },
            Reason::AntiAliased { neighbour: [3, 4] },
            Reason::Colour {
                levels: 40,
                triangle: Some(1),
                uv: [0.25, 0.5],
                colour: [1, 2, 3],
            },
        ];
        for distance in [0.001, 0.2, 2.0] {
            let (edge, triangle) = ("AB".to_string(), "ABC".to_string());
            all.push(Reason::Inside {
                distance,
                edge: edge.clone(),
                triangle: triangle.clone(),
            });
            all.push(Reason::Outside {
                distance,
                edge,
                triangle,
            });
        }
        for kind in [
            Kind::YFlipped,
            Kind::Rotated180,
            Kind::OtherMode,
            Kind::IntegerCentresYDown,
            Kind::OtherTieRule,
            Kind::IntegerCentresYUp,
        ] {
            all.push(Reason::Explained {
                verdict: Verdict {
                    kind,
                    differing: 7,
                    other_mode: Interpolation::Perspective,
                    other_rule: TieRule::TopLeft,
                },
            });
        }
        all
    }

    #[test]
    fn every_reason_is_worded_in_both_languages() {
        let names = [
            "barylab", "MSAA", "OpenGL", "Mesa", "llvmpipe", "Direct", "Vulkan",
        ];
        for r in every_reason() {
            let (en, zh) = (r.text(Lang::En), r.text(Lang::Zh));
            assert!(!en.contains("%{") && !zh.contains("%{"), "{en}\n{zh}");
            assert_ne!(en, zh);
            assert!(
                zh.chars().any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c)),
                "{zh}"
            );
            // No English word of three letters or more but the names (and the triangles',
            // in capitals).
            let english = zh
                .split(|c: char| !c.is_ascii_alphabetic())
                .filter(|w| !w.chars().all(|c| c.is_ascii_uppercase()))
                .find(|w| w.len() >= 3 && !names.contains(w));
            assert_eq!(english, None, "{zh}");
            assert!(!r.kind().is_empty());
        }
    }

    #[test]
    fn reasons_in_json_have_a_stable_kind() {
        let r = Reason::OtherMode {
            texels: 3.25,
            looks_like: Interpolation::Affine,
        };
        let json = serde_json::to_value(&r).expect("json");
        assert_eq!(json["kind"], "other_mode");
        assert_eq!(json["looks_like"], "affine");
        assert_eq!(r.kind(), "other_mode");
        assert!(
            r.text(Lang::En).contains("3.2 texels"),
            "{}",
            r.text(Lang::En)
        );
        assert!(
            r.text(Lang::Zh).contains("3.2 个纹素"),
            "{}",
            r.text(Lang::Zh)
        );
    }
}
