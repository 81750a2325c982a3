//! `barylab assign`: a variant of a course scene per student, so that copying a classmate's
//! image fails. The corners (in the quad's plane and across it), uv, colours and the camera
//! are moved within limits that keep the task well-posed: every corner in front of the
//! camera and inside the view, each triangle with a sizeable screen area and no sliver
//! angle (else another draw is tried). Each variant has its scene file, a task sheet in
//! English and Chinese, and the answer key: barylab's render and the probe's key numbers at
//! three marked pixels.
//!
//! The draws come from SplitMix64 seeded by the number given and the student's id
//! (FNV-1a), so the same roster and number give the same variants on every computer.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use glam::{DVec3, Vec2, Vec3};

use crate::files::shown;
use crate::i18n::Lang;
use crate::scene::Scene;

/// Largest move of a corner, as a fraction of the quad's longest side.
pub const CORNER_MOVE: f64 = 0.12;
/// Largest change of a uv coordinate.
pub const UV_MOVE: f32 = 0.15;
/// Largest move of the eye, as a fraction of its distance to the target.
pub const EYE_MOVE: f64 = 0.08;
/// Largest change of the vertical field of view, in degrees.
pub const FOV_MOVE: f64 = 5.0;
/// Smallest screen area of a triangle, as a fraction of the image.
pub const MIN_AREA: f64 = 0.02;
/// Smallest `2 area / longest side²` of a triangle on screen (no sliver).
pub const MIN_SHAPE: f64 = 0.08;
/// Draws tried per student before giving up.
pub const ATTEMPTS: usize = 200;

/// SplitMix64: a small, well-mixed generator (Steele, Lea and Flood, 2014).
struct Mix(u64);

impl Mix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [-1, 1).
    fn signed(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
}

/// FNV-1a of the id's bytes.
fn fnv(s: &str) -> u64 {
    s.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// Reads a roster: CSV, the student's id in the first column (a first line whose first field
/// is `student`, `id`, `name` or `学号` is a header). Ids must be usable as folder names:
/// no `/`, `\`, control characters or leading dot; each once. Errors name the file and line.
pub fn read_roster(path: &Path) -> Result<Vec<String>, String> {
    let bytes = crate::files::read_regular(path, crate::files::FileKind::Scene)
        .map_err(|e| e.to_string())?;
    let text = String::from_utf8_lossy(crate::files::strip_bom(&bytes)).into_owned();
    let mut out: Vec<String> = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let first = line
            .split(',')
            .next()
            .unwrap_or("")
            .trim()
            .trim_matches('"')
            .trim();
        if first.is_empty() {
            continue;
        }
        if i == 0 && ["student", "id", "name", "学号"].contains(&first.to_lowercase().as_str()) {
            continue;
        }
        let bad = first.starts_with('.')
            || first
                .chars()
                .any(|c| c == '/' || c == '\\' || c.is_control());
        if bad {
            return Err(format!(
                "{}: line {}: `{}` cannot name a folder (no /, \\, control characters or leading dot)",
                shown(path),
                i + 1,
                crate::files::escape_controls(first)
            ));
        }
        if out.iter().any(|s| s == first) {
            return Err(format!(
                "{}: line {}: student `{first}` is listed twice",
                shown(path),
                i + 1
            ));
        }
        out.push(first.to_string());
    }
    if out.is_empty() {
        return Err(format!("{}: no student listed", shown(path)));
    }
    Ok(out)
}

/// Reads the roster `barylab assign` wrote (`student,scene`, the scene relative to the
/// roster's folder): student -> scene file.
pub fn read_assigned(path: &Path) -> Result<BTreeMap<String, PathBuf>, String> {
    let bytes = crate::files::read_regular(path, crate::files::FileKind::Scene)
        .map_err(|e| e.to_string())?;
    let text = String::from_utf8_lossy(crate::files::strip_bom(&bytes)).into_owned();
    let base = path.parent().unwrap_or(Path::new("."));
    let mut out = BTreeMap::new();
    for (i, line) in text.lines().enumerate().skip(1) {
        let mut f = line.split(',').map(|s| s.trim().trim_matches('"'));
        let (Some(student), Some(scene)) = (f.next(), f.next()) else {
            continue;
        };
        if student.is_empty() {
            continue;
        }
        if scene.is_empty() {
            return Err(format!("{}: line {}: no scene", shown(path), i + 1));
        }
        out.insert(student.to_string(), base.join(scene));
    }
    if out.is_empty() {
        return Err(format!(
            "{}: no student with a scene: give grade the roster.csv that barylab assign wrote",
            shown(path)
        ));
    }
    Ok(out)
}

/// One student's variant of the base scene (a world-form scene: camera and quad).
pub fn variant(base: &Scene, student: &str, number: u64) -> Result<Scene, String> {
    let Scene::World(w) = base else {
        return Err("assign needs a scene of the world form (a camera and a quad)".into());
    };
    let mut rng = Mix(number ^ fnv(student).rotate_left(17));
    let side = (0..4)
        .map(|i| (w.quad[i].position - w.quad[(i + 1) % 4].position).length())
        .fold(0.0, f64::max);
    for _ in 0..ATTEMPTS {
        let mut v = w.clone();
        for c in &mut v.quad {
            let d = DVec3::new(rng.signed(), rng.signed() * 0.5, rng.signed());
            c.position += d * (CORNER_MOVE * side);
            c.uv += Vec2::new(rng.signed() as f32, rng.signed() as f32) * UV_MOVE;
            let tint = Vec3::new(
                rng.signed() as f32,
                rng.signed() as f32,
                rng.signed() as f32,
            );
            c.color = (c.color * 0.7 + (tint + 1.0) * 0.15).clamp(Vec3::ZERO, Vec3::ONE);
        }
        let to_eye = v.camera.eye - v.camera.target;
        let wobble = DVec3::new(rng.signed(), rng.signed(), rng.signed());
        v.camera.eye += wobble * (EYE_MOVE * to_eye.length());
        if let crate::raster::camera::Projection::Perspective { fov_y_deg, .. } =
            &mut v.camera.projection
        {
            *fov_y_deg = (*fov_y_deg + rng.signed() * FOV_MOVE).clamp(20.0, 100.0);
        }
        let scene = Scene::World(v);
        if well_posed(&scene) {
            return Ok(scene);
        }
    }
    Err(format!(
        "no well-posed variant for student `{student}` in {ATTEMPTS} draws"
    ))
}

/// Whether every corner is in front of the camera and inside the view, and each triangle
/// has at least [`MIN_AREA`] of the image and a shape of at least [`MIN_SHAPE`].
pub fn well_posed(scene: &Scene) -> bool {
    let mesh = scene.to_mesh();
    let (w, h) = scene.size();
    let (w, h) = (f64::from(w), f64::from(h));
    let mut screen = Vec::new();
    for v in &mesh.vertices {
        let c = v.clip;
        let inside = c.w > 0.0 && c.x.abs() < c.w && c.y.abs() < c.w && c.z.abs() < c.w;
        if !inside {
            return false;
        }
        screen.push(glam::DVec2::new(
            (c.x / c.w + 1.0) * w / 2.0,
            (1.0 - c.y / c.w) * h / 2.0,
        ));
    }
    mesh.triangles.iter().all(|t| {
        let [a, b, c] = t.map(|i| screen.get(i as usize).copied().unwrap_or_default());
        let area2 = (b - a).perp_dot(c - a).abs();
        let longest = [(b - a), (c - b), (a - c)]
            .iter()
            .map(|e| e.length_squared())
            .fold(0.0, f64::max);
        area2 / 2.0 >= MIN_AREA * w * h && longest > 0.0 && area2 / longest >= MIN_SHAPE
    })
}

/// The three marked pixels: the centroid of each triangle and the middle of the shared
/// diagonal moved a quarter of the way towards the second triangle's centroid, each a pixel
/// barylab covers.
pub fn marked_pixels(scene: &Scene) -> Vec<[u32; 2]> {
    let mesh = scene.to_mesh();
    let (w, h) = scene.size();
    let at = |i: u32| {
        let c = mesh
            .vertices
            .get(i as usize)
            .map(|v| v.clip)
            .unwrap_or_default();
        glam::DVec2::new(
            (c.x / c.w + 1.0) * f64::from(w) / 2.0,
            (1.0 - c.y / c.w) * f64::from(h) / 2.0,
        )
    };
    let centroid = |t: &[u32; 3]| (at(t[0]) + at(t[1]) + at(t[2])) / 3.0;
    let mut points: Vec<glam::DVec2> = mesh.triangles.iter().take(2).map(centroid).collect();
    if let (Some(t0), Some(t1)) = (mesh.triangles.first(), mesh.triangles.get(1)) {
        let mid = (at(t0[0]) + at(t0[2])) / 2.0;
        points.push(mid + (centroid(t1) - mid) * 0.25);
    }
    points
        .iter()
        .map(|p| {
            [
                (p.x.floor().max(0.0) as u32).min(w - 1),
                (p.y.floor().max(0.0) as u32).min(h - 1),
            ]
        })
        .collect()
}

/// The key numbers of one marked pixel from the probe: r s t, a b c, 1/W_P, W_P and uv, as
/// a Markdown table row (`| (x, y) | r s t | a b c | 1/W_P | W_P | uv |`).
pub fn key_numbers(
    scene: &Scene,
    texture: &crate::raster::Texture,
    pixel: [u32; 2],
) -> Result<String, String> {
    let prober =
        crate::probe::Prober::new(scene, texture, &scene.settings()).map_err(|e| e.to_string())?;
    let trace = prober
        .pixel(pixel[0], pixel[1])
        .map_err(|e| e.to_string())?;
    let d = trace
        .detail
        .as_ref()
        .filter(|d| d.writes_pixel)
        .ok_or_else(|| format!("pixel ({}, {}) is not covered", pixel[0], pixel[1]))?;
    let f = |v: [f64; 3]| format!("{:.6}, {:.6}, {:.6}", v[0], v[1], v[2]);
    let (abc, inv_w) = match &d.perspective {
        Some(p) => (f(p.renderer_weights), p.renderer_inv_w),
        None => ("-".into(), f64::NAN),
    };
    let uv = d
        .attribute
        .as_ref()
        .map(|a| format!("{:.6}, {:.6}", a.uv_perspective[0], a.uv_perspective[1]))
        .unwrap_or_else(|| "-".into());
    Ok(format!(
        "| ({}, {}) | {} | {abc} | {inv_w:.6} | {:.6} | {uv} |",
        pixel[0],
        pixel[1],
        f(d.screen.rasterizer),
        1.0 / inv_w
    ))
}

/// The task sheet in Markdown: the same task in `langs`, one section each; `pixels` are the
/// marked pixels.
pub fn task_sheet(student: &str, pixels: &[[u32; 2]], size: (u32, u32), langs: &[Lang]) -> String {
    let mut s = String::new();
    for &lang in langs {
        let list: Vec<String> = pixels
            .iter()
            .map(|p| format!("({}, {})", p[0], p[1]))
            .collect();
        let _ = writeln!(
            s,
            "{}\n",
            lang.tr_with(
                "grade.assign.task",
                &[
                    ("student", &student),
                    ("w", &size.0),
                    ("h", &size.1),
                    ("pixels", &list.join(", ")),
                ],
            )
        );
    }
    s
}

/// The answer key in Markdown: the render's file name and the marked pixels' key numbers.
pub fn answer_key(student: &str, rows: &[String], image: &str, lang: Lang) -> String {
    let mut s = lang.tr_with(
        "grade.assign.key",
        &[("student", &student), ("image", &image)],
    );
    s.push_str("\n\n| pixel | r, s, t | a, b, c | 1/W_P | W_P | uv |\n|---|---|---|---|---|---|\n");
    for r in rows {
        s.push_str(r);
        s.push('\n');
    }
    s
}
