//! Building the derivation: [`document`] calls one function per section, each in its own
//! file, in the order the pipeline runs. Every user-facing word of the derivation comes from
//! the catalogues `locales/*.yml` (keys `probe.*`, looked up with [`tr!`]); every number they
//! print is a field of the trace.

mod attribute;
mod clipping;
mod color;
mod coverage;
mod depth;
mod lod;
mod perspective;
mod point;
mod sample;
mod samples;
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

pub(crate) use crate::i18n::Lang;

/// A catalogue entry in the builder's language, with `%{name}` placeholders filled in:
/// `tr!(b, "probe.sample.title")`, `tr!(b, "probe.coverage.shows", k = 3)`.
macro_rules! tr {
    ($b:expr, $key:expr) => {
        rust_i18n::t!($key, locale = $b.lang.code()).into_owned()
    };
    ($b:expr, $key:expr, $($name:ident = $value:expr),+ $(,)?) => {
        rust_i18n::t!($key, locale = $b.lang.code(), $($name = $value),+).into_owned()
    };
}
use tr;

struct Builder {
    doc: Document,
    lang: Lang,
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

/// The interpolation mode's name in `lang` (the probe's settings line).
pub fn mode_name(lang: Lang, mode: Interpolation) -> String {
    crate::i18n::tr(
        lang,
        match mode {
            Interpolation::Affine => "probe.mode.affine",
            Interpolation::Perspective => "probe.mode.perspective",
        },
    )
}

/// The shading mode's name in `lang`.
pub fn shading_name(lang: Lang, s: Shading) -> String {
    crate::i18n::tr(
        lang,
        match s {
            Shading::Texture => "probe.shading.texture",
            Shading::VertexColor => "probe.shading.vertex_color",
            Shading::Barycentric => "probe.shading.barycentric",
            Shading::Depth => "probe.shading.depth",
            Shading::Normal => "probe.shading.normal",
            Shading::Lambert => "probe.shading.lambert",
        },
    )
}

/// The texture filter's name in `lang`.
pub fn filter_name(lang: Lang, f: Filter) -> String {
    crate::i18n::tr(
        lang,
        match f {
            Filter::Nearest => "probe.filter.nearest",
            Filter::Bilinear => "probe.filter.bilinear",
            Filter::Trilinear => "probe.filter.trilinear",
        },
    )
}

/// The sampler in `lang`: the filter's name, with the largest anisotropy when trilinear
/// filtering is anisotropic.
fn sampler_name(lang: Lang, f: Filter, max_anisotropy: u32) -> String {
    if f == Filter::Trilinear && max_anisotropy > 1 {
        lang.tr_with("probe.filter.anisotropic", &[("n", &max_anisotropy)])
    } else {
        filter_name(lang, f)
    }
}

/// The wrap mode's name in `lang`.
pub fn wrap_name(lang: Lang, w: Wrap) -> String {
    crate::i18n::tr(
        lang,
        match w {
            Wrap::Repeat => "probe.wrap.repeat",
            Wrap::ClampToEdge => "probe.wrap.clamp_to_edge",
            Wrap::MirroredRepeat => "probe.wrap.mirrored_repeat",
        },
    )
}

fn edge_kind_name(b: &Builder, k: EdgeKind) -> String {
    match k {
        EdgeKind::Left => tr!(b, "probe.edge.left"),
        EdgeKind::Right => tr!(b, "probe.edge.right"),
        EdgeKind::Top => tr!(b, "probe.edge.top"),
        EdgeKind::Bottom => tr!(b, "probe.edge.bottom"),
    }
}

fn plane_name(b: &Builder, p: PlaneName) -> String {
    match p {
        PlaneName::Near => tr!(b, "probe.plane.near"),
        PlaneName::Far => tr!(b, "probe.plane.far"),
        PlaneName::PositiveW => tr!(b, "probe.plane.positive_w"),
        PlaneName::GuardLeft => tr!(b, "probe.plane.guard_left"),
        PlaneName::GuardRight => tr!(b, "probe.plane.guard_right"),
        PlaneName::GuardBottom => tr!(b, "probe.plane.guard_bottom"),
        PlaneName::GuardTop => tr!(b, "probe.plane.guard_top"),
    }
}

/// A triangle's status in words (the English entries are `TriangleStatus::describe`).
fn status_text(b: &Builder, s: TriangleStatus) -> String {
    let reason = match s {
        TriangleStatus::Drawn => return tr!(b, "probe.status.drawn"),
        TriangleStatus::BadIndex => tr!(b, "probe.status.bad_index"),
        TriangleStatus::NotFinite => tr!(b, "probe.status.not_finite"),
        TriangleStatus::ClippedAway => tr!(b, "probe.status.clipped_away"),
        TriangleStatus::Empty => tr!(b, "probe.status.empty"),
    };
    tr!(b, "probe.status.not_drawn", reason = reason)
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

/// The derivation for a trace, in English.
pub fn document(trace: &PixelTrace) -> Document {
    document_in(trace, Lang::En)
}

/// The derivation for a trace with its prose in `lang`; the formulas, symbols and numbers are
/// the same in every language.
pub fn document_in(trace: &PixelTrace, lang: Lang) -> Document {
    let [x, y] = trace.pixel;
    let [w, h] = trace.image_size;
    let mut b = Builder {
        doc: Document {
            title: String::new(),
            sections: Vec::new(),
        },
        lang,
    };
    b.doc.title = tr!(b, "probe.title", x = x, y = y, w = w, h = h);
    settings::settings_section(&mut b, trace);
    sample::sample_section(&mut b, trace);
    coverage::coverage_section(&mut b, trace);
    samples::samples_section(&mut b, trace);
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
        if let Some(lt) = d.attribute.as_ref().and_then(|a| a.lod.as_ref()) {
            lod::lod_section(&mut b, trace, lt);
        }
        depth::depth_section(&mut b, trace, d);
    }
    color::color_section(&mut b, trace);
    b.doc
}
