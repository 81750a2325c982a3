//! `barylab assign --students roster.csv --number N --out DIR [--scene BASE]`: a variant of
//! the base scene per student, with its task sheet and answer key, and the roster that
//! `barylab grade --roster` reads.

use std::path::{Path, PathBuf};

use anyhow::{Result, bail};
use barylab::files::{self, shown};
use barylab::grade::assign;
use barylab::i18n::Lang;
use rayon::prelude::*;

use super::AssignArgs;
use crate::output::print;

pub(super) fn run(args: &AssignArgs) -> Result<()> {
    let students = assign::read_roster(&args.students).map_err(anyhow::Error::msg)?;
    let (base, base_dir) = match &args.scene {
        Some(p) => (
            barylab::scene::Scene::load(p)?,
            p.parent().map(Path::to_path_buf).unwrap_or_default(),
        ),
        None => (barylab::scene::Scene::default_scene(), PathBuf::new()),
    };
    let base = base.with_absolute_paths(&base_dir);
    let out = &args.out;
    match std::fs::read_dir(out) {
        Ok(mut d) => {
            if d.next().is_some() {
                bail!("{} is not empty: give a new or empty folder", shown(out));
            }
        }
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            files::check_folder(
                out.parent()
                    .filter(|p| !p.as_os_str().is_empty())
                    .unwrap_or(Path::new(".")),
            )
            .map_err(anyhow::Error::msg)?;
            std::fs::create_dir(out).map_err(|e| anyhow::anyhow!("{}: {e}", shown(out)))?;
        }
        Err(e) => bail!("{}: {e}", shown(out)),
    }
    let texture = base.load_texture(&base_dir)?;
    let number = args.number;
    students
        .par_iter()
        .map(|student| write_variant(&base, &texture, student, number, out))
        .collect::<Result<Vec<()>>>()?;
    let mut roster = String::from("student,scene\n");
    for s in &students {
        roster.push_str(&format!("{s},{s}/scene.json\n"));
    }
    let roster_path = out.join("roster.csv");
    files::write_new(&roster_path, roster.as_bytes())?;
    print(&format!(
        "{}\n",
        Lang::En.tr_with(
            "grade.assign.done",
            &[
                ("n", &students.len()),
                ("dir", &shown(out)),
                ("roster", &shown(&roster_path)),
            ],
        )
    ))
}

/// One student's folder: scene.json, task.md, answer.png, answer.md.
fn write_variant(
    base: &barylab::scene::Scene,
    texture: &barylab::raster::Texture,
    student: &str,
    number: u64,
    out: &Path,
) -> Result<()> {
    let scene = assign::variant(base, student, number).map_err(anyhow::Error::msg)?;
    let dir = out.join(student);
    std::fs::create_dir(&dir).map_err(|e| anyhow::anyhow!("{}: {e}", shown(&dir)))?;
    let settings = scene.settings();
    let render = barylab::raster::render(&scene.to_mesh(), texture, &settings)?;
    let mut png = Vec::new();
    render
        .frame
        .to_image()?
        .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)?;
    let pixels = assign::marked_pixels(&scene);
    let rows = pixels
        .iter()
        .map(|&p| assign::key_numbers(&scene, texture, p))
        .collect::<Result<Vec<String>, String>>()
        .map_err(anyhow::Error::msg)?;
    let langs = [Lang::En, Lang::Zh];
    let task = assign::task_sheet(student, &pixels, scene.size(), &langs);
    let key: Vec<String> = langs
        .iter()
        .map(|&l| assign::answer_key(student, &rows, "answer.png", l))
        .collect();
    files::write_new(&dir.join("scene.json"), scene.to_json().as_bytes())?;
    files::write_new(&dir.join("task.md"), task.as_bytes())?;
    files::write_new(&dir.join("answer.png"), &png)?;
    files::write_new(&dir.join("answer.md"), key.join("\n\n").as_bytes())?;
    Ok(())
}
