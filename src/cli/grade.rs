//! `barylab grade SCENE... --submissions DIR --report OUT [--csv FILE]` and `barylab assign`:
//! a class's images against barylab's renders, and a scene variant per student.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Result, bail};
use barylab::files::{self, shown};
use barylab::grade::{self, GradeScene, assign, report};
use barylab::i18n::Lang;
use rayon::prelude::*;

use super::{AssignArgs, GradeArgs};
use crate::output::{self, print};

pub(super) fn run(args: &GradeArgs) -> Result<()> {
    output::check_output(&args.report, &["html", "htm"])?;
    if let Some(c) = &args.csv {
        output::check_output(c, &["csv"])?;
    }
    let lang = args.lang;
    // The scenes: given, or each student's own from the roster `assign` wrote.
    let (paths, roster) = match &args.roster {
        Some(r) => {
            let assigned = assign::read_assigned(r).map_err(anyhow::Error::msg)?;
            let mut paths: Vec<PathBuf> = assigned.values().cloned().collect();
            paths.sort();
            paths.dedup();
            let index: BTreeMap<String, usize> = assigned
                .iter()
                .filter_map(|(s, p)| Some((s.clone(), paths.iter().position(|q| q == p)?)))
                .collect();
            (paths, Some(index))
        }
        None => (args.scenes.clone(), None),
    };
    if paths.is_empty() {
        bail!(
            "name the scenes to grade against, or give --roster (the roster.csv barylab assign wrote)"
        );
    }
    let mut scenes: Vec<GradeScene> = paths
        .par_iter()
        .map(|p| GradeScene::load(p))
        .collect::<Result<_, String>>()
        .map_err(anyhow::Error::msg)?;
    // With a roster, each scene is named after its student's folder (every variant's file is
    // scene.json); submissions are matched by the roster, not by these names.
    let names: Vec<String> = match &roster {
        Some(_) => paths
            .iter()
            .map(|p| {
                p.parent()
                    .and_then(|d| d.file_name())
                    .map(|n| n.to_string_lossy().into_owned())
                    .unwrap_or_else(|| shown(p))
            })
            .collect(),
        None => scenes.iter().map(|s| s.name.clone()).collect(),
    };
    for (s, n) in scenes.iter_mut().zip(&names) {
        s.name.clone_from(n);
    }
    let jobs = grade::find_jobs(&args.submissions, &names, roster.as_ref(), lang)
        .map_err(anyhow::Error::msg)?;
    if jobs.is_empty() {
        bail!(lang.tr_with(
            "grade.no_submissions",
            &[("dir", &shown(&args.submissions))]
        ));
    }
    let mut inputs: Vec<PathBuf> = scenes.iter().flat_map(GradeScene::inputs).collect();
    inputs.extend(jobs.iter().filter_map(|j| j.file.clone()));
    for out in std::iter::once(&args.report).chain(args.csv.as_ref()) {
        output::not_an_input(out, &inputs)?;
        let folder = out.parent().filter(|p| !p.as_os_str().is_empty());
        if files::same_file(folder.unwrap_or(Path::new(".")), &args.submissions) {
            bail!(
                "cannot write {} into the submissions folder {}: it would be graded as a \
                 submission next time; write it elsewhere",
                shown(out),
                shown(&args.submissions)
            );
        }
    }
    let start = Instant::now();
    let rows = grade::grade_all(&scenes, &jobs, args.tolerance, lang);
    let seconds = start.elapsed().as_secs_f64();
    let html = report::html(&rows, &names, lang);
    let mut staged = vec![files::stage_bytes(&args.report, html.as_bytes())?];
    if let Some(c) = &args.csv {
        staged.push(files::stage_bytes(c, report::csv(&rows).as_bytes())?);
    }
    for s in staged {
        s.commit()?;
    }
    let s = report::Summary::of(&rows);
    let mut text = lang.tr_with(
        "grade.done",
        &[
            ("submissions", &s.submissions),
            ("students", &s.students),
            ("seconds", &format!("{seconds:.1}")),
            ("pass", &s.pass),
            ("fail", &s.fail),
            ("bad", &s.bad),
            ("report", &shown(&args.report)),
        ],
    );
    if let Some(c) = &args.csv {
        text.push('\n');
        text.push_str(&lang.tr_with("grade.csv_written", &[("file", &shown(c))]));
    }
    text.push('\n');
    print(&text)
}

pub(super) fn run_assign(args: &AssignArgs) -> Result<()> {
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
