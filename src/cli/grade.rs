//! `barylab grade SCENE... --submissions DIR --report OUT [--csv FILE]`: a class's images
//! against barylab's renders of the scenes (or each student's own variant, `--roster`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Result, bail};
use barylab::files::{self, shown};
use barylab::grade::{self, GradeScene, assign, report};
use rayon::prelude::*;

use super::GradeArgs;
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
