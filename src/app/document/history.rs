//! Undo and redo of scene edits: corner drags, numeric fields, presets, tilt and field of
//! view, camera moves, opened files. A drag (everything while a pointer button is held) is
//! one step. The render options (mode, shading, filter, wireframe) and the image size are
//! view choices, not edits: undo keeps them as they are.

use std::path::PathBuf;

use crate::app::document::state::AppState;
use crate::edit;
use crate::scene::Scene;

/// Undo steps kept.
pub const DEPTH: usize = 200;

/// The part of the state undo restores.
#[derive(Clone, Debug, PartialEq)]
pub struct Snapshot {
    scene: Scene,
    dir: Option<PathBuf>,
}

impl Snapshot {
    pub fn of(state: &AppState) -> Self {
        Self {
            scene: state.scene.clone(),
            dir: state.scene_dir.clone(),
        }
    }

    /// Whether two snapshots differ in what undo restores (not in options or size).
    fn differs(&self, other: &Snapshot) -> bool {
        normalized(&self.scene) != normalized(&other.scene) || self.dir != other.dir
    }
}

/// The scene with the view choices undo does not touch set to fixed values.
fn normalized(scene: &Scene) -> Scene {
    let mut s = scene.clone();
    edit::set_options(&mut s, edit::options(&Scene::default_scene()));
    s.set_size(1, 1);
    s
}

/// The undo and redo stacks.
#[derive(Debug, Default)]
pub struct History {
    undo: Vec<Snapshot>,
    redo: Vec<Snapshot>,
    /// The state before the edit in progress (a drag not yet released).
    pending: Option<Snapshot>,
    /// The last change was an undo or redo itself: not a new step.
    restored: bool,
}

impl History {
    /// Once per frame, after the frame's commands: `before` is the state before them (`None`
    /// when there were none: nothing changed); `gesture` is whether a pointer button is still
    /// held (the edit goes on).
    pub fn track(&mut self, before: Option<Snapshot>, now: &AppState, gesture: bool) {
        if std::mem::take(&mut self.restored) {
            return;
        }
        if let Some(before) = before
            && self.pending.is_none()
            && before.differs(&Snapshot::of(now))
        {
            self.pending = Some(before);
        }
        if !gesture {
            self.commit(now);
        }
    }

    /// Ends the edit in progress, as one step (if it changed anything).
    fn commit(&mut self, now: &AppState) {
        if let Some(p) = self.pending.take()
            && p.differs(&Snapshot::of(now))
        {
            self.undo.push(p);
            if self.undo.len() > DEPTH {
                self.undo.remove(0);
            }
            self.redo.clear();
        }
    }

    pub fn can_undo(&self) -> bool {
        !self.undo.is_empty() || self.pending.is_some()
    }

    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }

    /// How many steps can be undone.
    /// This frame's change is not an edit (a lesson step was set, or the user's state came
    /// back): it becomes no undo step.
    pub fn skip_frame(&mut self) {
        self.restored = true;
        self.pending = None;
    }

    pub fn undo_steps(&self) -> usize {
        self.undo.len()
    }

    /// Undoes the last step; returns whether there was one.
    pub fn undo(&mut self, state: &mut AppState) -> bool {
        self.commit(state);
        let Some(s) = self.undo.pop() else {
            return false;
        };
        self.redo.push(Snapshot::of(state));
        restore(state, s);
        self.restored = true;
        true
    }

    /// Redoes the last undone step; returns whether there was one.
    pub fn redo(&mut self, state: &mut AppState) -> bool {
        self.commit(state);
        let Some(s) = self.redo.pop() else {
            return false;
        };
        self.undo.push(Snapshot::of(state));
        restore(state, s);
        self.restored = true;
        true
    }
}

/// Puts a snapshot back, keeping the current render options and image size.
fn restore(state: &mut AppState, s: Snapshot) {
    let options = state.options();
    let (w, h) = state.scene.size();
    state.scene = s.scene;
    edit::set_options(&mut state.scene, options);
    state.scene.set_size(w, h);
    state.scene_dir = s.dir;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::document::state::StateCommand;
    use crate::scene::Tilt;

    #[test]
    fn a_held_drag_is_one_step_and_options_are_not_undone() {
        let mut state = AppState::default();
        let mut h = History::default();
        let start = state.clone();
        // Three frames of one drag, then the release.
        for (pitch, held) in [(5.0, true), (10.0, true), (15.0, false)] {
            let before = Snapshot::of(&state);
            state
                .apply(StateCommand::SetTilt(Tilt {
                    pitch_deg: pitch,
                    yaw_deg: 0.0,
                }))
                .expect("tilt");
            h.track(Some(before), &state, held);
        }
        assert_eq!(h.undo_steps(), 1);
        // The mode is a view choice: not a step, and undo keeps it.
        let before = Snapshot::of(&state);
        state.apply(StateCommand::ToggleMode).expect("mode");
        h.track(Some(before), &state, false);
        assert_eq!(h.undo_steps(), 1);
        let mode = state.options().mode;
        assert!(h.undo(&mut state));
        assert_eq!(state.options().mode, mode);
        let mut expected = start.scene.clone();
        edit::set_options(&mut expected, state.options());
        assert_eq!(state.scene, expected);
        assert!(h.redo(&mut state));
        let Scene::World(w) = &state.scene else {
            panic!("world scene")
        };
        assert_eq!(w.tilt.pitch_deg, 15.0);
    }

    #[test]
    fn at_least_a_hundred_steps() {
        let mut state = AppState::default();
        let mut h = History::default();
        for k in 1..=150 {
            let before = Snapshot::of(&state);
            state
                .apply(StateCommand::SetFov(20.0 + f64::from(k) * 0.1))
                .expect("fov");
            h.track(Some(before), &state, false);
        }
        let mut undone = 0;
        while h.undo(&mut state) {
            undone += 1;
        }
        assert_eq!(undone, 150);
        assert_eq!(state.scene, Scene::default_scene());
    }
}
