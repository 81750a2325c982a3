//! A scene's samples and interpolation qualifiers (`samples`, `sample_pattern`,
//! `shading_rate`, `location`, `flat`, `provoking_vertex`): read into
//! [`SampleSettings`], set from the command line, checked; and the sampler's
//! `max_anisotropy`.

use super::{Scene, SceneError, invalid};
use crate::raster::sample::SampleSettings;
use crate::raster::texture::MaxAnisotropy;

/// The same six fields of every form, read or written.
macro_rules! each_form {
    ($scene:expr, $s:ident => $body:expr) => {
        match $scene {
            Scene::World($s) => $body,
            Scene::Clip($s) => $body,
            Scene::Model($s) => $body,
        }
    };
}

impl Scene {
    /// The samples and qualifiers the scene asks for.
    pub fn samples(&self) -> SampleSettings {
        each_form!(self, s => SampleSettings {
            count: s.samples,
            pattern: s.sample_pattern,
            rate: s.shading_rate,
            location: s.location,
            flat: s.flat,
            provoking: s.provoking_vertex,
        })
    }

    /// Sets the samples and qualifiers.
    pub fn set_samples(&mut self, v: SampleSettings) {
        each_form!(self, s => {
            s.samples = v.count;
            s.sample_pattern = v.pattern;
            s.shading_rate = v.rate;
            s.location = v.location;
            s.flat = v.flat;
            s.provoking_vertex = v.provoking;
        })
    }

    /// The largest anisotropy of texture lookups (`max_anisotropy`).
    pub fn max_anisotropy(&self) -> MaxAnisotropy {
        each_form!(self, s => s.max_anisotropy)
    }

    /// Sets the largest anisotropy of texture lookups.
    pub fn set_max_anisotropy(&mut self, max: MaxAnisotropy) {
        each_form!(self, s => s.max_anisotropy = max)
    }

    /// Refuses a sample pattern the count has no positions for, naming the fields.
    pub(super) fn check_samples(&self, path: &str) -> Result<(), SceneError> {
        self.samples()
            .check()
            .map_err(|e| invalid(path, &format!("fields `samples` and `sample_pattern`: {e}")))
    }
}
