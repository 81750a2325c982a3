//! Building the derivation: [`document`] calls one function per section, each in its own
//! file, in the order the pipeline runs. Every user-facing word of the derivation is in these
//! files; every number they print is a field of the trace.

mod attribute;
mod clipping;
mod color;
mod coverage;
mod depth;
mod perspective;
mod point;
mod sample;
mod screen;
mod settings;
mod system;
mod vertices;

use super::model::*;
use super::numbers::fmt_number;
use crate::probe::{
    AttributeTrace, CoverageTest, DistanceKind, EdgeTest, PixelTrace, Position, RasterVertex,
    SceneForm, TapTrace, TriangleCoverage, TriangleTrace,
};
use crate::raster::clip::PlaneName;
use crate::raster::interpolate::Interpolation;
use crate::raster::render::TriangleStatus;
use crate::raster::setup::{EdgeKind, TieRule};
use crate::raster::shade::Shading;
use crate::raster::texture::{Filter, Wrap};

struct Builder {
    doc: Document,
}

impl Builder {
    fn section(&mut self, title: impl Into<String>) {
        let n = self.doc.sections.len() + 1;
        self.doc.sections.push(Section {
            title: format!("{n}. {}", title.into()),
            items: Vec::new(),
        });
    }

    fn push(&mut self, item: Item) {
        if self.doc.sections.is_empty() {
            self.section("");
        }
        if let Some(s) = self.doc.sections.last_mut() {
            s.items.push(item);
        }
    }

    fn para(&mut self, mut parts: Vec<Inline>) {
        for p in &mut parts {
            if let Inline::M(ms) = p {
                mark_operands(ms);
            }
        }
        self.push(Item::Para(parts));
    }

    fn text(&mut self, s: impl Into<String>) {
        self.para(vec![t(s)]);
    }

    fn eq(&mut self, mut ms: Vec<M>) {
        mark_operands(&mut ms);
        self.push(Item::Eq(ms, None));
    }

    fn eq_note(&mut self, mut ms: Vec<M>, note: impl Into<String>) {
        mark_operands(&mut ms);
        self.push(Item::Eq(ms, Some(note.into())));
    }

    fn matrix(&mut self, lhs: Vec<M>, rows: Vec<Vec<f64>>) {
        self.push(Item::Matrix {
            lhs,
            rows,
            unknowns: Vec::new(),
            rhs: Vec::new(),
        });
    }
}

/// Screen weights of the rasterized triangle's vertices, in the r, s, t / W_P notation.
const SCREEN: [&str; 3] = ["r", "s", "t"];

/// Perspective-correct weights, in the r, s, t / W_P notation.
const CORRECT: [&str; 3] = ["a", "b", "c"];

fn mode_name(mode: Interpolation) -> &'static str {
    match mode {
        Interpolation::Affine => "affine (screen-space, like GLSL noperspective)",
        Interpolation::Perspective => "perspective-correct (GLSL smooth)",
    }
}

fn shading_name(s: Shading) -> &'static str {
    match s {
        Shading::Texture => "texture",
        Shading::VertexColor => "vertex colour",
        Shading::Barycentric => "barycentric weights as colour",
        Shading::Depth => "depth as grey",
    }
}

fn filter_name(f: Filter) -> &'static str {
    match f {
        Filter::Nearest => "nearest",
        Filter::Bilinear => "bilinear",
        Filter::Trilinear => "trilinear",
    }
}

fn wrap_name(w: Wrap) -> &'static str {
    match w {
        Wrap::Repeat => "repeat",
        Wrap::ClampToEdge => "clamp to edge",
        Wrap::MirroredRepeat => "mirrored repeat",
    }
}

fn edge_kind_name(k: EdgeKind) -> &'static str {
    match k {
        EdgeKind::Left => "a left edge",
        EdgeKind::Right => "a right edge",
        EdgeKind::Top => "a top edge (horizontal, interior below it)",
        EdgeKind::Bottom => "a bottom edge (horizontal, interior above it)",
    }
}

fn plane_name(p: PlaneName) -> &'static str {
    match p {
        PlaneName::Near => "the near plane (z >= -w)",
        PlaneName::Far => "the far plane (z <= w)",
        PlaneName::PositiveW => "the plane w > 0",
        PlaneName::GuardLeft => "the left guard band",
        PlaneName::GuardRight => "the right guard band",
        PlaneName::GuardBottom => "the bottom guard band",
        PlaneName::GuardTop => "the top guard band",
    }
}

fn status_text(s: TriangleStatus) -> String {
    match s {
        TriangleStatus::Drawn => s.describe().to_string(),
        _ => format!("not drawn: {}", s.describe()),
    }
}

fn rgba(c: [u8; 4]) -> String {
    format!(
        "rgba({}, {}, {}, {}) = #{:02x}{:02x}{:02x}",
        c[0], c[1], c[2], c[3], c[0], c[1], c[2]
    )
}

fn names3(n: &[String; 3]) -> String {
    n.join(", ")
}

fn rows4(m: &[[f64; 4]; 4]) -> Vec<Vec<f64>> {
    m.iter().map(|r| r.to_vec()).collect()
}

fn raster_names(d: &TriangleTrace) -> [String; 3] {
    d.raster.vertices.clone().map(|v| v.name)
}

/// The derivation for a trace.
pub fn document(trace: &PixelTrace) -> Document {
    let [x, y] = trace.pixel;
    let [w, h] = trace.image_size;
    let mut b = Builder {
        doc: Document {
            title: format!("barylab probe: pixel ({x}, {y}) of the {w}x{h} image"),
            sections: Vec::new(),
        },
    };
    settings::settings_section(&mut b, trace);
    sample::sample_section(&mut b, trace);
    coverage::coverage_section(&mut b, trace);
    if let Some(d) = &trace.detail {
        vertices::vertices_section(&mut b, trace, d);
        if d.clipping.is_some() {
            clipping::clipping_section(&mut b, d);
        }
        screen::screen_section(&mut b, trace, d);
        perspective::perspective_section(&mut b, trace, d);
        system::system_section(&mut b, d);
        point::point_section(&mut b, trace, d);
        attribute::attribute_section(&mut b, trace, d);
        depth::depth_section(&mut b, trace, d);
    }
    color::color_section(&mut b, trace);
    b.doc
}
