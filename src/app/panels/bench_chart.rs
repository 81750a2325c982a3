//! The benchmark window's results: the table, the edge / scanline ratio next to a published measurement
//! claim, the bar chart and llvmpipe's reference figures. Drawing only.

use egui::{Color32, RichText, Ui};

use crate::bench::{self, BenchRecord};
use crate::i18n::Lang;

/// llvmpipe's reference median for one cell (perspective only), if quoted.
fn llvmpipe_reference(filter: &str, mode: &str, threads: usize) -> Option<f64> {
    if mode != "perspective" {
        return None;
    }
    bench::LLVMPIPE_REFERENCE_1080P
        .iter()
        .find(|(t, f, _)| *t == threads && *f == filter)
        .map(|(_, _, ms)| *ms)
}

/// The filter x mode x threads cells in table order.
fn cells(records: &[BenchRecord]) -> Vec<(String, String, usize)> {
    let mut out: Vec<(String, String, usize)> = Vec::new();
    for r in records {
        let cell = (r.filter.clone(), r.mode.clone(), r.threads);
        if !out.contains(&cell) {
            out.push(cell);
        }
    }
    out
}

/// The table: one row per filter x mode x threads cell, both rasterizers' medians.
pub fn table_ui(ui: &mut Ui, records: &[BenchRecord], reference: bool) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let ms =
        |r: Option<&BenchRecord>| r.map_or("…".to_string(), |r| format!("{:.1}", r.median_ms));
    egui::Grid::new("bench_table")
        .striped(true)
        .spacing([18.0, 4.0])
        .show(ui, |ui| {
            for h in [
                &lang.tr("app.bench_chart.filter"),
                &lang.tr("app.bench_chart.mode"),
                &lang.tr("app.bench_chart.threads"),
            ] {
                ui.label(RichText::new(h).strong());
            }
            ui.label(
                RichText::new(format!(
                    "{} {}",
                    &lang.tr("app.bench_chart.edge"),
                    &lang.tr("app.bench_chart.ms")
                ))
                .strong()
                .color(EDGE_COLOR),
            );
            ui.label(
                RichText::new(format!(
                    "{} {}",
                    &lang.tr("app.bench_chart.scanline"),
                    &lang.tr("app.bench_chart.ms")
                ))
                .strong()
                .color(SCANLINE_COLOR),
            );
            ui.label(RichText::new(lang.tr("app.bench_chart.ratio")).strong());
            ui.label(
                RichText::new(format!(
                    "{} {}",
                    &lang.tr("app.bench_chart.edge"),
                    &lang.tr("app.bench_chart.mpix")
                ))
                .strong(),
            );
            if reference {
                ui.label(
                    RichText::new(format!(
                        "{} {}",
                        &lang.tr("app.bench_chart.llvmpipe_ref"),
                        &lang.tr("app.bench_chart.ms")
                    ))
                    .strong()
                    .color(LLVMPIPE_COLOR),
                );
            }
            ui.end_row();
            for (filter, mode, threads) in cells(records) {
                let edge = bench::find(records, "edge", &filter, &mode, threads);
                let scan = bench::find(records, "scanline", &filter, &mode, threads);
                ui.label(shown(lang, &filter));
                ui.label(shown(lang, &mode));
                ui.label(threads.to_string());
                ui.monospace(ms(edge));
                ui.monospace(ms(scan));
                ui.monospace(
                    bench::edge_over_scanline(records, &filter, &mode, threads)
                        .map_or("…".to_string(), |x| format!("{x:.2}x")),
                );
                ui.monospace(edge.map_or("…".to_string(), |r| format!("{:.1}", r.mpix_per_s)));
                if reference {
                    ui.monospace(
                        llvmpipe_reference(&filter, &mode, threads)
                            .map_or("-".to_string(), |ms| format!("{ms:.1}")),
                    );
                }
                ui.end_row();
            }
        });
}

/// A filter or mode name of the records (`nearest`, `affine`, ...) in `lang`.
fn shown(lang: Lang, value: &str) -> String {
    let key = match value {
        "nearest" => "app.bench_chart.value.nearest",
        "bilinear" => "app.bench_chart.value.bilinear",
        "trilinear" => "app.bench_chart.value.trilinear",
        "affine" => "app.bench_chart.value.affine",
        "perspective" => "app.bench_chart.value.perspective",
        other => return other.to_string(),
    };
    lang.tr(key)
}

/// The median over the measured cells of edge / scanline.
fn median_ratio(records: &[BenchRecord]) -> Option<f64> {
    let ratios: Vec<f64> = cells(records)
        .iter()
        .filter_map(|(f, m, t)| bench::edge_over_scanline(records, f, m, *t))
        .collect();
    bench::median(&ratios)
}

/// The published claim and the measured edge / scanline ratio.
pub fn ratio_ui(ui: &mut Ui, records: &[BenchRecord]) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    ui.label(lang.tr("app.bench_chart.published_claim"));
    if let Some(r) = median_ratio(records) {
        ui.label(
            RichText::new(lang.tr_with(
                "app.bench_chart.measured_ratio",
                &[("ratio", &format!("{r:.2}"))],
            ))
            .strong(),
        );
    }
}

const EDGE_COLOR: Color32 = Color32::from_rgb(90, 160, 240);
const SCANLINE_COLOR: Color32 = Color32::from_rgb(240, 160, 60);
const LLVMPIPE_COLOR: Color32 = Color32::from_rgb(150, 150, 150);
/// The y range reaches this multiple of the tallest bar, leaving room for the legend.
const LEGEND_HEADROOM: f64 = 1.3;
/// Cell labels under the chart, in points (three short lines fit a cell's width).
const TICK_LABEL_SIZE: f32 = 15.0;
/// Bar width and offsets within a cell (cells are 1 apart on the x axis).
const BAR_WIDTH: f64 = 0.26;

/// The bar chart of the medians (with llvmpipe's figures for the reference scene).
pub fn chart_ui(ui: &mut Ui, records: &[BenchRecord], reference: bool) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    use egui_plot::{AxisHints, Bar, BarChart, Corner, GridMark, Legend, Plot};
    let cells = cells(records);
    let series = |name: &str,
                  offset: f64,
                  color: Color32,
                  value: &dyn Fn(&str, &str, usize) -> Option<f64>| {
        let bars: Vec<Bar> = cells
            .iter()
            .enumerate()
            .filter_map(|(i, (f, m, t))| {
                value(f, m, *t).map(|ms| {
                    Bar::new(i as f64 + offset, ms)
                        .width(BAR_WIDTH)
                        .name(format!("{f} {m} {t}"))
                })
            })
            .collect();
        BarChart::new(name, bars).color(color)
    };
    let ms_of = |name: &'static str| {
        move |f: &str, m: &str, t: usize| bench::find(records, name, f, m, t).map(|r| r.median_ms)
    };
    let edge = series(
        &lang.tr("app.bench_chart.edge"),
        -BAR_WIDTH,
        EDGE_COLOR,
        &ms_of("edge"),
    );
    let scan = series(
        &lang.tr("app.bench_chart.scanline"),
        0.0,
        SCANLINE_COLOR,
        &ms_of("scanline"),
    );
    let llvm = reference.then(|| {
        series(
            &lang.tr("app.bench_chart.llvmpipe_ref"),
            BAR_WIDTH,
            LLVMPIPE_COLOR,
            &|f, m, t| llvmpipe_reference(f, m, t),
        )
    });
    let labels: Vec<String> = cells
        .iter()
        .map(|(f, m, t)| {
            let threads = if *t == 1 {
                lang.tr("app.bench_chart.thread_1")
            } else {
                lang.tr_with("app.bench_chart.threads_n", &[("n", t)])
            };
            format!("{}\n{}\n{threads}", shown(lang, f), shown(lang, m))
        })
        .collect();
    let n = cells.len();
    let tallest = records.iter().map(|r| r.median_ms).fold(0.0, f64::max);
    Plot::new("bench_chart")
        .height(280.0)
        .legend(Legend::default().position(Corner::LeftTop))
        .y_axis_label(lang.tr("app.bench_chart.chart_y"))
        .include_y(0.0)
        .include_y(tallest * LEGEND_HEADROOM)
        .include_x(-0.6)
        .include_x(n as f64 - 0.4)
        .allow_zoom(false)
        .allow_drag(false)
        .allow_scroll(false)
        .allow_boxed_zoom(false)
        .show_x(false)
        .x_grid_spacer(move |_| {
            (0..n)
                .map(|i| GridMark {
                    value: i as f64,
                    step_size: 1.0,
                })
                .collect()
        })
        .custom_x_axes(vec![
            AxisHints::new_x()
                .min_thickness(60.0)
                .tick_label_font(egui::FontId::proportional(TICK_LABEL_SIZE))
                .formatter(move |mark, _| {
                    let i = mark.value.round();
                    if (mark.value - i).abs() < 1e-6 && i >= 0.0 {
                        labels.get(i as usize).cloned().unwrap_or_default()
                    } else {
                        String::new()
                    }
                }),
        ])
        .show(ui, |plot| {
            plot.bar_chart(edge);
            plot.bar_chart(scan);
            if let Some(l) = llvm {
                plot.bar_chart(l);
            }
        });
}

/// llvmpipe's reference figures for the 1080p scene.
pub fn reference_ui(ui: &mut Ui) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    ui.label(RichText::new(lang.tr("app.bench_chart.reference_heading")).strong());
    egui::Grid::new("llvmpipe_reference")
        .spacing([18.0, 2.0])
        .show(ui, |ui| {
            ui.label("");
            ui.label(RichText::new(shown(lang, "nearest")).strong());
            ui.label(RichText::new(shown(lang, "bilinear")).strong());
            ui.end_row();
            for threads in [1usize, 2] {
                ui.label(if threads == 1 {
                    lang.tr("app.bench_chart.thread_1")
                } else {
                    lang.tr_with("app.bench_chart.threads_n", &[("n", &threads)])
                });
                for filter in ["nearest", "bilinear"] {
                    let ms = llvmpipe_reference(filter, "perspective", threads);
                    ui.monospace(ms.map_or("-".into(), |ms| {
                        format!(
                            "{ms:.1} {} ({:.0} {})",
                            &lang.tr("app.bench_chart.ms"),
                            bench::mpix_per_s(1920, 1080, ms),
                            &lang.tr("app.bench_chart.mpix")
                        )
                    }));
                }
                ui.end_row();
            }
        });
    ui.label(RichText::new(lang.tr("app.bench_chart.reference_note")).small());
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn llvmpipe_reference_figures_are_for_perspective_only() {
        assert_eq!(llvmpipe_reference("bilinear", "perspective", 1), Some(11.8));
        assert_eq!(llvmpipe_reference("nearest", "perspective", 2), Some(2.5));
        assert_eq!(llvmpipe_reference("nearest", "affine", 2), None);
        assert_eq!(llvmpipe_reference("nearest", "perspective", 4), None);
    }
}
