//! The samples control in the controls: samples per pixel (1, 4, 8, 16), their pattern
//! (the GL's standard positions or GAMES101's grid), the shading rate (MSAA or supersampling)
//! and where MSAA evaluates values (centre, centroid, sample). The settings are the scene's
//! (saved with it, undone like any edit); the magnifier draws every sample and the inspector
//! lists the pinned pixel's (see [`crate::raster::sample`]).

use egui::Ui;

use crate::app::document::state::StateCommand;
use crate::raster::sample::{Location, SampleCount, SamplePattern, SampleSettings, ShadingRate};

/// One row of choices: the label, then a selectable button per value; returns the value
/// clicked when it differs from `current`.
fn choices<T: Copy + PartialEq>(
    ui: &mut Ui,
    label: &str,
    tip: &str,
    current: T,
    options: &[(T, String, bool)],
) -> Option<T> {
    let mut picked = None;
    ui.horizontal_wrapped(|ui| {
        ui.label(label).on_hover_text(tip);
        for (value, text, enabled) in options {
            let button = egui::Button::selectable(current == *value, text.as_str());
            if ui.add_enabled(*enabled, button).clicked() && current != *value {
                picked = Some(*value);
            }
        }
    });
    picked
}

/// The samples control for the scene's `samples`; returns the changed settings as a command.
pub fn samples_ui(ui: &mut Ui, samples: SampleSettings) -> Vec<StateCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut next = samples;
    let counts = [
        SampleCount::One,
        SampleCount::Four,
        SampleCount::Eight,
        SampleCount::Sixteen,
    ]
    .map(|c| {
        // The grid has no 8-sample pattern.
        let ok = !(c == SampleCount::Eight && samples.pattern == SamplePattern::Grid);
        (c, c.get().to_string(), ok)
    });
    if let Some(c) = choices(
        ui,
        &lang.tr("app.samples.count"),
        &lang.tr("app.samples.count_tip"),
        samples.count,
        &counts,
    ) {
        next.count = c;
    }
    let many = samples.count != SampleCount::One;
    let patterns = [
        (
            SamplePattern::Standard,
            lang.tr("app.samples.standard"),
            many,
        ),
        (
            SamplePattern::Grid,
            lang.tr("app.samples.grid"),
            many && samples.count != SampleCount::Eight,
        ),
    ];
    if let Some(p) = choices(
        ui,
        &lang.tr("app.samples.pattern"),
        &lang.tr("app.samples.pattern_tip"),
        samples.pattern,
        &patterns,
    ) {
        next.pattern = p;
    }
    let rates = [
        (ShadingRate::Msaa, lang.tr("app.samples.msaa"), many),
        (ShadingRate::Ssaa, lang.tr("app.samples.ssaa"), many),
    ];
    if let Some(r) = choices(
        ui,
        &lang.tr("app.samples.rate"),
        &lang.tr("app.samples.rate_tip"),
        samples.rate,
        &rates,
    ) {
        next.rate = r;
    }
    let msaa = many && samples.rate == ShadingRate::Msaa;
    let locations = [
        (Location::Center, lang.tr("app.samples.center"), msaa),
        (Location::Centroid, lang.tr("app.samples.centroid"), msaa),
        (Location::Sample, lang.tr("app.samples.sample"), msaa),
    ];
    if let Some(l) = choices(
        ui,
        &lang.tr("app.samples.location"),
        &lang.tr("app.samples.location_tip"),
        samples.location,
        &locations,
    ) {
        next.location = l;
    }
    if next == samples {
        Vec::new()
    } else {
        vec![StateCommand::SetSamples(next)]
    }
}
