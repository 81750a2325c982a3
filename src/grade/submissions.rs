//! Which image of which student goes with which scene: the submissions folder holds a file
//! per student (one scene: any name; several: the file name contains the scene's name,
//! e.g. `alice-games101-a2.png`) or a folder per student with an image per scene (its name
//! contains the scene's name; with one scene, a folder's only image). With a roster, each
//! student's image goes with their own variant. Nothing is opened here: what is not a
//! regular file or folder (a FIFO, a device) becomes a job with its problem.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use crate::files::shown;
use crate::i18n::Lang;

/// One submission to grade.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Job {
    /// The student.
    pub student: String,
    /// The scene's index in the list graded.
    pub scene: usize,
    /// The image file (`None`: missing).
    pub file: Option<PathBuf>,
    /// Why it cannot be compared, found before opening it.
    pub problem: Option<String>,
}

/// A folder entry: its name, path and what it is.
struct Entry {
    name: String,
    path: PathBuf,
    kind: EntryKind,
}

#[derive(PartialEq)]
enum EntryKind {
    File,
    Folder,
    /// Anything else, in words (from [`crate::files::describe`]).
    Other(&'static str),
}

/// The entries of `dir`, sorted by name, hidden ones (a leading dot) left out; links are
/// followed.
fn entries(dir: &Path) -> Result<Vec<Entry>, String> {
    let read = std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", shown(dir)))?;
    let mut out = Vec::new();
    for e in read {
        let e = e.map_err(|e| format!("{}: {e}", shown(dir)))?;
        let name = e.file_name().to_string_lossy().into_owned();
        if name.starts_with('.') {
            continue;
        }
        let path = e.path();
        let kind = match std::fs::metadata(&path) {
            Ok(m) if m.is_file() => EntryKind::File,
            Ok(m) if m.is_dir() => EntryKind::Folder,
            Ok(m) => EntryKind::Other(crate::files::describe(&m)),
            Err(_) => EntryKind::Other("a broken link"),
        };
        out.push(Entry { name, path, kind });
    }
    out.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(out)
}

/// The name without its extension.
fn stem(name: &str) -> &str {
    match name.rfind('.') {
        Some(i) if i > 0 => &name[..i],
        _ => name,
    }
}

/// The scene whose name the file name contains (the longest such name; case ignored).
fn scene_of(name: &str, scenes: &[String]) -> Option<usize> {
    let lower = name.to_lowercase();
    scenes
        .iter()
        .enumerate()
        .filter(|(_, s)| !s.is_empty() && lower.contains(&s.to_lowercase()))
        .max_by_key(|(_, s)| s.len())
        .map(|(i, _)| i)
}

/// The student's name in a file named after the student and the scene: the scene's name and
/// the separators around it taken out (`alice-games101-a2` -> `alice`).
fn student_of(file_stem: &str, scene: &str) -> String {
    let lower = file_stem.to_lowercase();
    let Some(i) = lower.find(&scene.to_lowercase()) else {
        return file_stem.to_string();
    };
    let rest = format!("{}{}", &file_stem[..i], &file_stem[i + scene.len()..]);
    let trimmed = rest.trim_matches(|c: char| c == '-' || c == '_' || c == '.' || c == ' ');
    if trimmed.is_empty() {
        file_stem.to_string()
    } else {
        trimmed.to_string()
    }
}

/// The jobs of the submissions folder `dir` for the scenes named `scenes`. With `roster`
/// (student -> scene index), a student's file or folder is named after the student and goes
/// with their scene; roster students without one are missing, and others are refused with
/// a problem. Fails only when `dir` cannot be read.
pub fn find_jobs(
    dir: &Path,
    scenes: &[String],
    roster: Option<&BTreeMap<String, usize>>,
    lang: Lang,
) -> Result<Vec<Job>, String> {
    let mut jobs = Vec::new();
    let problem = |student: &str, scene: usize, file: &Path, p: String| Job {
        student: student.to_string(),
        scene,
        file: Some(file.to_path_buf()),
        problem: Some(p),
    };
    let other = |what: &str| lang.tr_with("grade.not_a_file", &[("what", &what)]);
    for e in entries(dir)? {
        let file_stem = if e.kind == EntryKind::Folder {
            e.name.as_str()
        } else {
            stem(&e.name)
        };
        // Which scene, and whose.
        let (student, scene) = match roster {
            Some(r) => match r.get(file_stem) {
                Some(&i) => (file_stem.to_string(), Some(i)),
                None => {
                    let p = lang.tr("grade.not_on_roster");
                    jobs.push(problem(file_stem, 0, &e.path, p));
                    continue;
                }
            },
            None if e.kind == EntryKind::Folder => (e.name.clone(), None),
            None if scenes.len() == 1 => (file_stem.to_string(), Some(0)),
            None => match scene_of(file_stem, scenes) {
                Some(i) => (student_of(file_stem, &scenes[i]), Some(i)),
                None => {
                    let p = lang.tr("grade.no_scene");
                    jobs.push(problem(file_stem, 0, &e.path, p));
                    continue;
                }
            },
        };
        match e.kind {
            EntryKind::File => jobs.push(Job {
                student,
                scene: scene.unwrap_or(0),
                file: Some(e.path),
                problem: None,
            }),
            EntryKind::Other(what) => {
                jobs.push(problem(&student, scene.unwrap_or(0), &e.path, other(what)));
            }
            EntryKind::Folder => {
                let inside = entries(&e.path)?;
                let wanted: Vec<usize> = match scene {
                    Some(i) => vec![i],
                    None => (0..scenes.len()).collect(),
                };
                for i in wanted {
                    let only = inside.len() == 1 && (scenes.len() == 1 || roster.is_some());
                    let found = inside
                        .iter()
                        .find(|f| only || scene_of(stem(&f.name), scenes) == Some(i));
                    jobs.push(match found {
                        Some(f) => Job {
                            student: student.clone(),
                            scene: i,
                            file: Some(f.path.clone()),
                            problem: match f.kind {
                                EntryKind::File => None,
                                EntryKind::Folder => Some(other("a folder")),
                                EntryKind::Other(what) => Some(other(what)),
                            },
                        },
                        None => Job {
                            student: student.clone(),
                            scene: i,
                            file: None,
                            problem: None,
                        },
                    });
                }
            }
        }
    }
    if let Some(r) = roster {
        for (student, &scene) in r {
            if !jobs.iter().any(|j| &j.student == student) {
                jobs.push(Job {
                    student: student.clone(),
                    scene,
                    file: None,
                    problem: None,
                });
            }
        }
    }
    Ok(jobs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_names_pick_the_scene_and_the_student() {
        let scenes = ["games101-a2".to_string(), "games101-a2-ssaa".to_string()];
        assert_eq!(scene_of("alice-games101-a2", &scenes), Some(0));
        assert_eq!(scene_of("bob_GAMES101-A2-SSAA", &scenes), Some(1));
        assert_eq!(scene_of("carol", &scenes), None);
        assert_eq!(student_of("alice-games101-a2", "games101-a2"), "alice");
        assert_eq!(student_of("games101-a2", "games101-a2"), "games101-a2");
        assert_eq!(stem("a.b.png"), "a.b");
        assert_eq!(stem(".png"), ".png");
    }
}
