//! The help window: what the app shows and its keyboard shortcuts.

use egui::{RichText, Ui};

/// User-facing strings of the help window.
pub mod text {
    pub const TITLE: &str = "Help";
    pub const INTRO: &str = "barylab draws a textured quad (two triangles, A B C and A C D) with its own \
        CPU rasterizer, exactly as a GPU does: samples at pixel centres, one owner for every pixel on a \
        shared edge (the fill rule), clipping in clip space, perspective-correct \
        interpolation with 1/w.";
    pub const MOUSE: &str = "Mouse";
    pub const KEYS: &str = "Keys";
    pub const MOUSE_ROWS: &[(&str, &str)] = &[
        (
            "Drag a corner",
            "move it parallel to the screen (its w stays)",
        ),
        (
            "Scroll on a corner",
            "push it away / pull it closer (same place on screen, new w)",
        ),
        ("Shift + drag a corner", "the same, with the mouse"),
        (
            "Hover a pixel",
            "its derivation in the inspector, its triangle and sub-areas on the canvas",
        ),
        ("Click a pixel", "pin it (click again to unpin)"),
        (
            "Drag the wipe line",
            "move the split between affine and perspective-correct",
        ),
        (
            "Drop a file",
            "a .json scene or an .obj model opens; an image becomes the texture",
        ),
        ("Drag on a model", "orbit the camera around it"),
        ("Shift + drag or right drag on a model", "pan the camera"),
        ("Scroll on a model", "zoom in / out"),
    ];
    pub const KEY_ROWS: &[(&str, &str)] = &[
        ("P", "switch affine / perspective-correct"),
        ("1 2 3 4", "single view, side by side, wipe, difference"),
        (
            "[  ]",
            "smaller / larger image (with Fit window: smaller / larger pixels)",
        ),
        ("W", "wireframe (edges and the diagonal)"),
        ("G", "pixel grid and sample points"),
        ("H", "corner handles"),
        ("Arrow keys", "move the pinned pixel by one"),
        (
            "Esc",
            "close a menu, else this help, else leave presentation mode, else unpin",
        ),
        (
            "F5",
            "presentation mode: the canvas and the pixel's numbers in large print",
        ),
        ("Page Down / Page Up", "next / previous preset"),
        ("Ctrl + Z", "undo the last scene edit (a whole drag is one)"),
        ("Ctrl + Shift + Z or Ctrl + Y", "redo"),
        ("Ctrl + Shift + S", "save the scene as a JSON file"),
        ("Ctrl + R", "reset the scene"),
        ("Ctrl + O", "open a scene, model or image"),
        (
            "Ctrl + S",
            "export the figure (opens the Export panel; again: writes the files)",
        ),
        ("Home", "reset the view of a model"),
        ("Ctrl + / Ctrl -", "larger / smaller interface"),
        ("F1", "this help"),
    ];
}

/// The help window's contents.
pub fn help_ui(ui: &mut Ui) {
    ui.label(text::INTRO);
    ui.add_space(8.0);
    for (title, rows) in [
        (text::MOUSE, text::MOUSE_ROWS),
        (text::KEYS, text::KEY_ROWS),
    ] {
        ui.label(RichText::new(title).strong());
        egui::Grid::new(title)
            .num_columns(2)
            .striped(true)
            .spacing([16.0, 4.0])
            .show(ui, |ui| {
                for (k, what) in rows {
                    ui.label(RichText::new(*k).monospace().strong());
                    ui.label(*what);
                    ui.end_row();
                }
            });
        ui.add_space(8.0);
    }
}
