//! The inspector panel: the hovered and the pinned pixel, from the probe. A summary of the
//! key numbers (coloured by vertex, negative weights in red), a comparison when a pixel is
//! pinned and another hovered, and the probe's worked example, section by section.

use crate::app::command::LessonCommand;
use egui::{Color32, RichText, Ui};

use crate::app::panels::paint::color;
use crate::app::services::pixel::PixelReport;
use crate::figure::overlay::{CLIP_POINT, NEGATIVE, vertex_color};
use crate::i18n::Lang;
use crate::lesson::InspectorSection;
use crate::probe::format::fmt_number;
use crate::probe::{Position, TriangleCoverage};
use crate::raster::Interpolation;
use crate::raster::render::TriangleStatus;

/// Sections of the probe's worked example opened at first (by position, 0-based): the
/// coverage, the screen weights, the 1/w correction and the texture coordinate.
const OPEN_SECTIONS: [usize; 4] = [2, 4, 5, 8];

/// Points: the least width of a number column.
const NUMBER_WIDTH: f32 = 64.0;
/// Points between two columns of the table of per-vertex numbers.
const COLUMN_SPACING: f32 = 8.0;
/// Points of the panel's width the table leaves spare (rounding, the panel's edge).
const TABLE_SLACK: f32 = 4.0;

mod columns;

fn weight_text(w: f64) -> RichText {
    let t = RichText::new(fmt_number(w)).monospace();
    if w < 0.0 { t.color(color(NEGATIVE)) } else { t }
}

fn pair(v: [f64; 2]) -> String {
    format!("({}, {})", fmt_number(v[0]), fmt_number(v[1]))
}

fn pair32(v: [f32; 2]) -> String {
    pair([f64::from(v[0]), f64::from(v[1])])
}

/// Why a triangle does not cover the sample, in a few words.
fn miss_reason(c: &TriangleCoverage, lang: Lang) -> String {
    match c.status {
        TriangleStatus::ClippedAway => return lang.tr("app.inspector.clipped_away"),
        TriangleStatus::Empty | TriangleStatus::BadIndex | TriangleStatus::NotFinite => {
            return lang.tr("app.inspector.empty");
        }
        TriangleStatus::Drawn => {}
    }
    match &c.test {
        Some(t) if t.position == Position::Outside => {
            let edges: Vec<&str> = t
                .edges
                .iter()
                .filter(|e| e.value < 0)
                .map(|e| e.name.as_str())
                .collect();
            lang.tr_with(
                "app.inspector.outside_edge",
                &[("edges", &edges.join(", "))],
            )
        }
        Some(t) if !t.covered => lang.tr("app.inspector.on_edge_not_owned"),
        Some(_) => lang.tr("app.inspector.hidden"),
        None => lang.tr("app.inspector.empty"),
    }
}

/// The pixel's header: position, coverage, colour.
fn header_ui(ui: &mut Ui, r: &PixelReport, role: &str) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let t = &r.trace;
    // Wrapped: in a narrow panel "pinned" goes to the next line rather than past the edge.
    ui.horizontal_wrapped(|ui| {
        let c = t.color;
        let (rect, _) = ui.allocate_exact_size(egui::vec2(28.0, 28.0), egui::Sense::hover());
        ui.painter().rect_filled(
            rect,
            4.0,
            Color32::from_rgba_unmultiplied(c[0], c[1], c[2], 255),
        );
        ui.painter().rect_stroke(
            rect,
            4.0,
            egui::Stroke::new(1.0, Color32::GRAY),
            egui::StrokeKind::Outside,
        );
        ui.label(
            RichText::new(format!(
                "{} ({}, {})",
                &lang.tr("app.inspector.pixel"),
                r.pixel[0],
                r.pixel[1]
            ))
            .strong()
            .size(22.0),
        );
        ui.label(RichText::new(role).weak());
    });
    match t.written_by {
        Some(tri) => {
            let names = t
                .triangles
                .iter()
                .find(|c| c.source == tri)
                .map(|c| c.vertices.join(""))
                .unwrap_or_default();
            ui.label(lang.tr_with("app.inspector.covered_by", &[("names", &names)]));
        }
        None => {
            ui.label(
                RichText::new(lang.tr("app.inspector.not_covered"))
                    .color(color(NEGATIVE))
                    .strong(),
            );
            for c in &t.triangles {
                ui.label(format!(
                    "  {}: {}",
                    c.vertices.join(""),
                    miss_reason(c, lang)
                ));
            }
            if t.detail.is_some() {
                ui.label(RichText::new(lang.tr("app.inspector.nearest")).weak());
            } else {
                ui.label(lang.tr("app.inspector.nothing_drawn"));
            }
        }
    }
}

/// The key numbers: per vertex r s t, 1/W, a b c; then W_P, uv both ways, depth.
fn summary_ui(ui: &mut Ui, r: &PixelReport) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let Some(d) = &r.trace.detail else {
        return;
    };
    let v = &d.raster.vertices;
    let seed = d.perspective.map(|p| p.correction);
    // The columns: r s t, 1/W, a b c, each a header (with its tooltip) and a value a vertex.
    let columns: [(String, String, Vec<RichText>); 3] = [
        (
            lang.tr("app.inspector.screen"),
            lang.tr("app.inspector.screen_tip"),
            (0..v.len())
                .map(|k| weight_text(d.screen.rasterizer[k]))
                .collect(),
        ),
        (
            lang.tr("app.inspector.inv_w"),
            lang.tr("app.inspector.inv_w_tip"),
            v.iter()
                .map(|vk| RichText::new(fmt_number(vk.inv_w)).monospace())
                .collect(),
        ),
        (
            lang.tr("app.inspector.corrected"),
            lang.tr("app.inspector.corrected_tip"),
            (0..v.len())
                .map(|k| match seed {
                    Some(s) => weight_text(s.weights[k]),
                    None => RichText::new("–"),
                })
                .collect(),
        ),
    ];
    // As many columns side by side as fit the panel; the rest in tables below.
    let width = |t: &RichText| columns::text_width(ui, t.clone());
    let vertex_header = RichText::new(lang.tr("app.inspector.vertex")).weak();
    let name_width = v
        .iter()
        .map(|vk| width(&RichText::new(&vk.name).strong()))
        .fold(width(&vertex_header), f32::max);
    let column_widths: Vec<f32> = columns
        .iter()
        .map(|(header, _, values)| {
            values
                .iter()
                .map(width)
                .fold(width(&RichText::new(header)).max(NUMBER_WIDTH), f32::max)
        })
        .collect();
    let per_table = columns::per_table(
        ui.available_width() - TABLE_SLACK,
        name_width,
        &column_widths,
        COLUMN_SPACING,
    );
    // A horizontal scroll area all the same, as in [`compare_ui`].
    egui::ScrollArea::horizontal()
        .id_salt("summary-scroll")
        .show(ui, |ui| {
            for (t, chunk) in columns.chunks(per_table).enumerate() {
                egui::Grid::new(("summary", r.pixel, t))
                    .num_columns(1 + chunk.len())
                    .spacing([COLUMN_SPACING, 4.0])
                    .min_col_width(0.0)
                    .striped(true)
                    .show(ui, |ui| {
                        ui.label(vertex_header.clone());
                        for (k, (header, tip, _)) in chunk.iter().enumerate() {
                            let w = column_widths[t * per_table + k];
                            ui.add_sized([w, 20.0], egui::Label::new(RichText::new(header).weak()))
                                .on_hover_text(tip);
                        }
                        ui.end_row();
                        for (k, vk) in v.iter().enumerate() {
                            let mesh = vk
                                .source_vertex
                                .and_then(|s| d.vertices.get(s))
                                .map(|vt| vt.index as usize);
                            let c = mesh.map_or(CLIP_POINT, vertex_color);
                            let name = ui.label(RichText::new(&vk.name).strong().color(color(c)));
                            if mesh.is_none() {
                                name.on_hover_text(lang.tr("app.inspector.clipped_vertex_tip"));
                            }
                            for (j, (_, _, values)) in chunk.iter().enumerate() {
                                let w = column_widths[t * per_table + j];
                                ui.add_sized([w, 20.0], egui::Label::new(values[k].clone()));
                            }
                            ui.end_row();
                        }
                    });
                ui.add_space(2.0);
            }
        });
    if let Some(s) = seed {
        let n = [0, 1, 2].map(|k| v[k].name.as_str());
        ui.label(
            RichText::new(format!(
                "{} = r/W_{} + s/W_{} + t/W_{} = {}",
                &lang.tr("app.inspector.inv_w_p"),
                n[0],
                n[1],
                n[2],
                fmt_number(s.inv_w_p)
            ))
            .monospace(),
        );
        ui.label(
            RichText::new(format!(
                "{} = {}",
                &lang.tr("app.inspector.w_p"),
                fmt_number(s.w_p)
            ))
            .monospace(),
        );
    }
    if let Some(a) = &d.attribute {
        let (affine, persp) = match r.mode {
            Interpolation::Affine => (true, false),
            Interpolation::Perspective => (false, true),
        };
        let line = |ui: &mut Ui, label: &str, uv: [f32; 2], shown: bool| {
            let t = RichText::new(format!("{label} = {}", pair32(uv))).monospace();
            ui.label(if shown { t.strong() } else { t });
        };
        line(ui, &lang.tr("app.inspector.uv_affine"), a.uv_affine, affine);
        line(
            ui,
            &lang.tr("app.inspector.uv_perspective"),
            a.uv_perspective,
            persp,
        );
        ui.label(lang.tr_with(
            "app.inspector.texel_gap",
            &[("n", &fmt_number(a.texel_distance))],
        ));
    }
    if let Some(dep) = &d.depth {
        ui.label(
            RichText::new(format!(
                "{} = {}",
                &lang.tr("app.inspector.depth"),
                fmt_number(dep.depth)
            ))
            .monospace(),
        );
    }
    ui.label(
        RichText::new(match r.mode {
            Interpolation::Affine => lang.tr("app.inspector.mode_affine"),
            Interpolation::Perspective => lang.tr("app.inspector.mode_perspective"),
        })
        .weak(),
    );
}

/// Pinned and hovered side by side: the numbers that differ from pixel to pixel.
fn compare_ui(ui: &mut Ui, pinned: &PixelReport, hovered: &PixelReport) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    ui.label(RichText::new(lang.tr("app.inspector.compare")).strong());
    // `split`: a pair of numbers on two lines (for a narrow panel).
    let rows = |r: &PixelReport, split: bool| -> Vec<String> {
        let d = r.trace.detail.as_ref();
        let two = |uv: [f32; 2]| {
            let p = pair32(uv);
            if split {
                p.replacen(", ", ",\n ", 1)
            } else {
                p
            }
        };
        let w3 = |w: [f64; 3]| {
            w.iter()
                .map(|x| fmt_number(*x))
                .collect::<Vec<_>>()
                .join("\n")
        };
        vec![
            format!("({}, {})", r.pixel[0], r.pixel[1]),
            d.map_or("–".into(), |d| w3(d.screen.rasterizer)),
            d.and_then(|d| d.perspective)
                .map_or("–".into(), |p| w3(p.correction.weights)),
            d.and_then(|d| d.perspective)
                .map_or("–".into(), |p| fmt_number(p.correction.w_p)),
            d.and_then(|d| d.attribute.as_ref())
                .map_or("–".into(), |a| two(a.uv_affine)),
            d.and_then(|d| d.attribute.as_ref())
                .map_or("–".into(), |a| two(a.uv_perspective)),
        ]
    };
    let names = [
        &lang.tr("app.inspector.pixel"),
        &lang.tr("app.inspector.screen"),
        &lang.tr("app.inspector.corrected"),
        &lang.tr("app.inspector.w_p"),
        &lang.tr("app.inspector.uv_affine"),
        &lang.tr("app.inspector.uv_perspective"),
    ];
    let width = |t: &str, mono: bool| {
        let t = if mono {
            RichText::new(t).monospace()
        } else {
            RichText::new(t)
        };
        columns::text_width(ui, t)
    };
    let heads = [
        lang.tr("app.inspector.pinned"),
        lang.tr("app.inspector.hovered"),
    ];
    let name_width = names.iter().map(|n| width(n, false)).fold(0.0, f32::max);
    let spacing = 12.0;
    // Pinned beside hovered when both fit the panel, else one table below the other, with
    // the uv pairs on two lines if that is still too wide.
    let fit = |split: bool| {
        let (a, b) = (rows(pinned, split), rows(hovered, split));
        let column_widths: Vec<f32> = [&a, &b]
            .iter()
            .zip(&heads)
            .map(|(col, head)| {
                col.iter()
                    .map(|x| width(x, true))
                    .fold(width(head, false), f32::max)
            })
            .collect();
        let per_table = columns::per_table(
            ui.available_width() - TABLE_SLACK,
            name_width,
            &column_widths,
            spacing,
        );
        (a, b, per_table)
    };
    let (a, b, per_table) = match fit(false) {
        (a, b, 2) => (a, b, 2),
        _ => fit(true),
    };
    let values = [&a, &b];
    // A horizontal scroll area all the same: nothing here widens the panel's content (which
    // would move the derivation below past the panel's edge).
    egui::ScrollArea::horizontal()
        .id_salt("compare-scroll")
        .show(ui, |ui| {
            for (t, chunk) in [0, 1].chunks(per_table).enumerate() {
                egui::Grid::new(("compare", t))
                    .num_columns(1 + chunk.len())
                    .spacing([spacing, 4.0])
                    .striped(true)
                    .show(ui, |ui| {
                        ui.label("");
                        for &c in chunk {
                            ui.label(RichText::new(&heads[c]).weak());
                        }
                        ui.end_row();
                        for (i, n) in names.iter().enumerate() {
                            ui.add(egui::Label::new(RichText::new(*n).weak()).extend());
                            for &c in chunk {
                                ui.add(
                                    egui::Label::new(RichText::new(&values[c][i]).monospace())
                                        .extend(),
                                );
                            }
                            ui.end_row();
                        }
                    });
                ui.add_space(2.0);
            }
        });
}

/// The probe's worked example, one collapsible section each; `open`: the sections a lesson
/// step opens (the others close), once.
fn derivation_ui(ui: &mut Ui, r: &PixelReport, open: Option<&[InspectorSection]>) {
    let detail = r.trace.detail.as_ref();
    let clipped = detail.is_some_and(|d| d.clipping.is_some());
    let wanted: Option<Vec<usize>> = open.map(|o| {
        o.iter()
            .filter_map(|s| s.index(detail.is_some(), clipped))
            .collect()
    });
    let lang = crate::app::services::locale::lang(ui.ctx());
    ui.label(
        RichText::new(lang.tr_with(
            "app.inspector.derivation",
            &[("x", &r.pixel[0]), ("y", &r.pixel[1])],
        ))
        .strong()
        .size(20.0),
    );
    for (i, section) in r.document.sections.iter().enumerate() {
        // Not a CollapsingHeader: its title never wraps, and a long one would widen the
        // panel's content so the sections below it were cut at the panel's edge.
        let id = ui.make_persistent_id(("derivation", i));
        let mut state = egui::collapsing_header::CollapsingState::load_with_default_open(
            ui.ctx(),
            id,
            OPEN_SECTIONS.contains(&i),
        );
        if let Some(w) = &wanted {
            state.set_open(w.contains(&i));
        }
        let (_, header, _) = state
            .show_header(ui, |ui| {
                ui.add(
                    egui::Label::new(RichText::new(&section.title).strong())
                        .wrap()
                        .sense(egui::Sense::click()),
                )
            })
            .body(|ui| section_ui(ui, i, &section.to_text()));
        if header.inner.clicked() {
            let mut state = egui::collapsing_header::CollapsingState::load_with_default_open(
                ui.ctx(),
                id,
                OPEN_SECTIONS.contains(&i),
            );
            state.toggle(ui);
            state.store(ui.ctx());
        }
    }
}

/// One section of the worked example: prose lines (indented by two spaces) and formula lines
/// (four spaces, monospace) both wrap at the panel's width, so nothing is cut off.
fn section_ui(ui: &mut Ui, index: usize, text: &str) {
    let mut formulas: Vec<&str> = Vec::new();
    let mut block = 0;
    let flush = |ui: &mut Ui, formulas: &mut Vec<&str>, block: &mut usize| {
        if formulas.is_empty() {
            return;
        }
        ui.push_id(("derivation-block", index, *block), |ui| {
            ui.add(
                egui::Label::new(RichText::new(formulas.join("\n")).monospace().size(15.0)).wrap(),
            );
        });
        formulas.clear();
        *block += 1;
    };
    for line in text.lines() {
        if let Some(formula) = line.strip_prefix("    ") {
            formulas.push(formula);
        } else {
            flush(ui, &mut formulas, &mut block);
            ui.label(line.trim_start());
        }
    }
    flush(ui, &mut formulas, &mut block);
}

/// The inspector panel. `open`: the derivation sections a lesson step opens; once a pixel shows
/// them it asks the lesson to forget them ([`LessonCommand::SectionsShown`]).
/// `gpu`: the GPU view when it is on (its colour at the pixel is shown beside barylab's).
pub fn inspector_ui(
    ui: &mut Ui,
    hovered: Option<&PixelReport>,
    pinned: Option<&PixelReport>,
    open: Option<&[InspectorSection]>,
    gpu: Option<&crate::app::panels::gpu_view::GpuView>,
) -> Vec<LessonCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    ui.heading(lang.tr("app.inspector.title"));
    let focus = hovered.or(pinned);
    let Some(focus) = focus else {
        ui.label(lang.tr("app.inspector.hover_hint"));
        return Vec::new();
    };
    let role = if hovered.is_some() {
        &lang.tr("app.inspector.hovered")
    } else {
        &lang.tr("app.inspector.pinned")
    };
    // A quiz hides its pixel's numbers (and its colour, which can show them) until Reveal.
    let hidden = crate::app::panels::quiz::hidden_pixel(ui.ctx());
    if hidden == Some(focus.pixel) {
        ui.label(crate::app::panels::quiz::hidden_note(lang, focus.pixel));
        return Vec::new();
    }
    header_ui(ui, focus, role);
    if let Some(g) = gpu {
        crate::app::panels::other_image::pixel_colours_ui(ui, g, focus.pixel);
    }
    ui.add_space(4.0);
    summary_ui(ui, focus);
    if let (Some(p), Some(h)) = (pinned, hovered)
        && p.pixel != h.pixel
        && hidden != Some(p.pixel)
    {
        ui.separator();
        compare_ui(ui, p, h);
    }
    ui.separator();
    derivation_ui(ui, focus, open.filter(|o| !o.is_empty()));
    if open.is_some() {
        vec![LessonCommand::SectionsShown]
    } else {
        Vec::new()
    }
}
