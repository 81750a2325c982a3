//! The built-in lesson and the scenes compiled into the program, so `barylab lesson builtin`
//! and the app's Lessons menu work on a machine without the `assets/` folder.

/// The name that opens the built-in lesson (`barylab lesson builtin`).
pub const NAME: &str = "builtin";

/// A lesson's scene reference that names a built-in scene: `"builtin:default"`.
pub const SCENE_PREFIX: &str = "builtin:";

/// The built-in lesson, `assets/lessons/interpolation.json`.
pub const LESSON: &str = include_str!("../../assets/lessons/interpolation.json");

/// The scenes of `assets/scenes/` that need no other file (built-in textures only), by name.
pub const SCENES: [(&str, &str); 13] = [
    ("default", include_str!("../../assets/scenes/default.json")),
    ("front", include_str!("../../assets/scenes/front.json")),
    (
        "corner-behind",
        include_str!("../../assets/scenes/corner-behind.json"),
    ),
    (
        "near-cut",
        include_str!("../../assets/scenes/near-cut.json"),
    ),
    (
        "tetrahedron",
        include_str!("../../assets/scenes/tetrahedron.json"),
    ),
    (
        "rgbw-2x2",
        include_str!("../../assets/scenes/rgbw-2x2.json"),
    ),
    (
        "vertex-colors",
        include_str!("../../assets/scenes/vertex-colors.json"),
    ),
    (
        "orthographic",
        include_str!("../../assets/scenes/orthographic.json"),
    ),
    (
        "far-checker",
        include_str!("../../assets/scenes/far-checker.json"),
    ),
    (
        "clip-two-triangles",
        include_str!("../../assets/scenes/clip-two-triangles.json"),
    ),
    (
        "rgb-triangle",
        include_str!("../../assets/scenes/rgb-triangle.json"),
    ),
    (
        "receding-wall",
        include_str!("../../assets/scenes/receding-wall.json"),
    ),
    (
        "games101-pitfall",
        include_str!("../../assets/scenes/games101-pitfall.json"),
    ),
];

/// The built-in scene `name`'s JSON.
pub fn scene(name: &str) -> Option<&'static str> {
    SCENES.iter().find(|(n, _)| *n == name).map(|(_, t)| *t)
}

/// The built-in scenes' names.
pub fn scene_names() -> Vec<&'static str> {
    SCENES.iter().map(|(n, _)| *n).collect()
}

/// The built-in scene a relative path in the built-in lesson means: its file stem
/// (`../scenes/default.json` is `default`).
pub fn scene_name_of(path: &str) -> String {
    let file = path.rsplit(['/', '\\']).next().unwrap_or(path);
    file.strip_suffix(".json").unwrap_or(file).to_string()
}
