//! The built-in lessons and the scenes compiled into the program, so `barylab lesson
//! interpolation` (or `builtin`), `barylab lesson texture`, `barylab lesson samples` and the app's Lessons menu work on
//! a machine without the `assets/` folder. [`LESSONS`] is the registry: a lesson added there
//! is opened by name everywhere.

/// The name that opens the first built-in lesson, interpolation (`barylab lesson builtin`).
pub const NAME: &str = "builtin";

/// A lesson compiled into the program.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BuiltinLesson {
    /// The name that opens it (`barylab lesson NAME`).
    pub name: &'static str,
    /// Other names that open it.
    pub aliases: &'static [&'static str],
    /// Its JSON.
    pub text: &'static str,
}

/// The built-in lessons, in the order the Lessons menu lists them.
pub const LESSONS: [BuiltinLesson; 3] = [
    BuiltinLesson {
        name: "interpolation",
        aliases: &[NAME],
        text: LESSON,
    },
    BuiltinLesson {
        name: "texture",
        aliases: &[],
        text: TEXTURE_LESSON,
    },
    BuiltinLesson {
        name: "samples",
        aliases: &[],
        text: SAMPLES_LESSON,
    },
];

/// The built-in lesson a name (or alias) opens.
///
/// ```
/// use barylab::lesson::builtin::lesson;
/// assert_eq!(lesson("builtin").map(|l| l.name), Some("interpolation"));
/// assert_eq!(lesson("texture").map(|l| l.name), Some("texture"));
/// assert_eq!(lesson("samples").map(|l| l.name), Some("samples"));
/// assert!(lesson("lessons/my.json").is_none());
/// ```
pub fn lesson(name: &str) -> Option<&'static BuiltinLesson> {
    LESSONS
        .iter()
        .find(|l| l.name == name || l.aliases.contains(&name))
}

/// The second built-in lesson, `assets/lessons/texture.json`: from uv to texel.
pub const TEXTURE_LESSON: &str = include_str!("../../assets/lessons/texture.json");

/// The third built-in lesson, `assets/lessons/samples.json`: samples per pixel, the resolve,
/// the black-edge bug, MSAA and supersampling (its scenes are the clip-space copies of
/// GAMES101 A2's, `games101-a2-clip*.json`, which need no model file).
pub const SAMPLES_LESSON: &str = include_str!("../../assets/lessons/samples.json");

/// A lesson's scene reference that names a built-in scene: `"builtin:default"`.
pub const SCENE_PREFIX: &str = "builtin:";

/// The built-in lesson, `assets/lessons/interpolation.json`.
pub const LESSON: &str = include_str!("../../assets/lessons/interpolation.json");

/// The scenes of `assets/scenes/` that need no other file (built-in textures only), by name.
pub const SCENES: [(&str, &str); 17] = [
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
        "far-checker-anisotropic",
        include_str!("../../assets/scenes/far-checker-anisotropic.json"),
    ),
    (
        "checker-closeup",
        include_str!("../../assets/scenes/checker-closeup.json"),
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
    (
        "games101-a2-clip",
        include_str!("../../assets/scenes/games101-a2-clip.json"),
    ),
    (
        "games101-a2-clip-ssaa",
        include_str!("../../assets/scenes/games101-a2-clip-ssaa.json"),
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
