//! The grading report: a self-contained HTML page (inline CSS, the difference thumbnails as
//! `data:` URIs, one row per student linking to a section with each scene's verdict, named
//! bugs with their fixes, and regions with reasons) and a CSV with a line per submission.

use crate::figure::svg::escape;
use std::collections::BTreeMap;
use std::fmt::Write as _;

use base64::Engine as _;

use super::{Row, Verdict};
use crate::compare::bugs::Bug;
use crate::i18n::Lang;

/// Counts over the rows.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Summary {
    /// Distinct students.
    pub students: usize,
    /// Rows (a student's image for one scene).
    pub submissions: usize,
    /// Rows that pass.
    pub pass: usize,
    /// Rows that fail.
    pub fail: usize,
    /// Rows that could not be compared.
    pub bad: usize,
    /// How many rows name each bug.
    pub bugs: BTreeMap<Bug, usize>,
}

impl Summary {
    /// Counts `rows`.
    pub fn of(rows: &[Row]) -> Self {
        let mut s = Summary {
            students: students(rows).len(),
            submissions: rows.len(),
            ..Summary::default()
        };
        for r in rows {
            match r.verdict() {
                Verdict::Pass => s.pass += 1,
                Verdict::Fail => s.fail += 1,
                Verdict::Bad => s.bad += 1,
            }
            for b in bugs(r) {
                *s.bugs.entry(*b).or_default() += 1;
            }
        }
        s
    }
}

/// The students in the order they first appear, each with their rows.
fn students(rows: &[Row]) -> Vec<(&str, Vec<&Row>)> {
    let mut out: Vec<(&str, Vec<&Row>)> = Vec::new();
    for r in rows {
        match out.iter_mut().find(|(s, _)| *s == r.student) {
            Some((_, list)) => list.push(r),
            None => out.push((&r.student, vec![r])),
        }
    }
    out
}

fn bugs(r: &Row) -> &[Bug] {
    r.outcome
        .as_ref()
        .map_or(&[], |g| g.comparison.bugs.as_slice())
}

/// Pixels that differ in a row (0 when it could not be compared).
fn differing(r: &Row) -> usize {
    r.outcome.as_ref().map_or(0, |g| g.comparison.differing())
}

/// One CSV field: always quoted, quotes doubled; a field a spreadsheet would run as a
/// formula (`=`, `+`, `-`, `@` first) gets a leading apostrophe.
fn field(s: &str) -> String {
    let s = if s.starts_with(['=', '+', '-', '@']) {
        format!("'{s}")
    } else {
        s.to_string()
    };
    format!("\"{}\"", s.replace('"', "\"\""))
}

/// The CSV: `student,scene,verdict,bugs,pixels_differing,regions,file,problem`, one line per
/// row; `verdict` is `pass`, `fail` or `bad`, `bugs` the named bugs' codes separated by `;`.
pub fn csv(rows: &[Row]) -> String {
    let mut out =
        String::from("student,scene,verdict,bugs,pixels_differing,regions,file,problem\n");
    for r in rows {
        let codes: Vec<&str> = bugs(r).iter().map(|b| b.code()).collect();
        let regions = r.outcome.as_ref().map_or(0, |g| g.comparison.region_count);
        let file = r
            .file
            .as_ref()
            .map(|f| f.display().to_string())
            .unwrap_or_default();
        let problem = r.outcome.as_ref().err().cloned().unwrap_or_default();
        let line = [
            field(&r.student),
            field(&r.scene),
            field(r.verdict().code()),
            field(&codes.join(";")),
            differing(r).to_string(),
            regions.to_string(),
            field(&file),
            field(&problem),
        ]
        .join(",");
        out.push_str(&line);
        out.push('\n');
    }
    out
}

const STYLE: &str = "\
body{font-family:system-ui,'Noto Sans','Noto Sans CJK SC','PingFang SC','Microsoft YaHei',sans-serif;\
margin:2rem auto;max-width:72rem;padding:0 1rem;color:#1d2330;background:#fbfbfd;line-height:1.45}\
h1{font-size:1.7rem;margin:0 0 .3rem}h2{margin-top:2.5rem;border-bottom:2px solid #d8dce6;padding-bottom:.2rem}\
h3{margin:1.2rem 0 .4rem}.summary{font-size:1.15rem}.legend{color:#555;font-size:.9rem}\
table{border-collapse:collapse;width:100%;margin:1rem 0;background:#fff}\
th,td{border:1px solid #d8dce6;padding:.35rem .6rem;text-align:left;vertical-align:middle}\
th{background:#eef1f7}tr:nth-child(even) td{background:#f7f8fb}\
.v{font-weight:700;text-transform:uppercase;letter-spacing:.03em;white-space:nowrap}\
.pass{color:#17803d}.fail{color:#b42318}.bad{color:#8a5a00}\
.big{font-size:1.35rem}code{background:#eef1f7;padding:0 .25rem;border-radius:3px}\
img.diff{image-rendering:pixelated;border:1px solid #ccd;background:#000;max-width:160px}\
.bug{border-left:4px solid #b42318;background:#fff5f4;padding:.4rem .8rem;margin:.5rem 0}\
.problem{border-left:4px solid #8a5a00;background:#fff8e6;padding:.4rem .8rem}\
ol.regions li{margin:.3rem 0}.sample{color:#555;font-size:.9rem}a{color:#1f5fbf}";

/// The report as one HTML page in `lang`; `scenes` are the scene names graded.
pub fn html(rows: &[Row], scenes: &[String], lang: Lang) -> String {
    let s = Summary::of(rows);
    let t = |key: &str| escape(&lang.tr(&format!("grade.{key}")));
    let mut h = String::new();
    let code = match lang {
        Lang::Zh => "zh-CN",
        _ => "en",
    };
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"{code}\"><head><meta charset=\"utf-8\">\
         <meta name=\"viewport\" content=\"width=device-width,initial-scale=1\">\
         <title>{}</title><style>{STYLE}</style></head><body id=\"top\">\n",
        t("title")
    );
    let _ = writeln!(h, "<h1>{}</h1>", t("title"));
    let scene_list: Vec<String> = scenes
        .iter()
        .map(|n| format!("<code>{}</code>", escape(n)))
        .collect();
    let _ = writeln!(
        h,
        "<p>{}</p>",
        lang.tr_with("grade.scenes", &[("list", &scene_list.join(", "))])
    );
    let _ = writeln!(
        h,
        "<p class=\"summary\">{}</p>",
        escape(&lang.tr_with(
            "grade.summary",
            &[
                ("students", &s.students),
                ("submissions", &s.submissions),
                ("pass", &s.pass),
                ("fail", &s.fail),
                ("bad", &s.bad),
            ],
        ))
    );
    if !s.bugs.is_empty() {
        let _ = writeln!(
            h,
            "<h2>{}</h2><table><tr><th>{}</th><th>{}</th><th>{}</th></tr>",
            t("bugs_heading"),
            t("col_bug"),
            t("col_count"),
            t("col_fix")
        );
        for (bug, n) in &s.bugs {
            let _ = writeln!(
                h,
                "<tr><td><code>{}</code> {}</td><td>{n}</td><td>{}</td></tr>",
                bug.code(),
                escape(&bug.title(lang)),
                escape(&bug.fix(lang))
            );
        }
        h.push_str("</table>\n");
    }
    let _ = writeln!(
        h,
        "<h2>{}</h2><p class=\"legend\">{}</p>\n<table><tr><th>{}</th><th>{}</th><th>{}</th><th>{}</th><th>{}</th></tr>",
        t("class_heading"),
        t("legend"),
        t("col_student"),
        t("col_verdict"),
        t("col_bugs"),
        t("col_difference"),
        t("col_pixels"),
    );
    let groups = students(rows);
    for (i, (student, list)) in groups.iter().enumerate() {
        let worst = list
            .iter()
            .map(|r| r.verdict())
            .max()
            .unwrap_or(Verdict::Bad);
        let mut codes: Vec<Bug> = list.iter().flat_map(|r| bugs(r).iter().copied()).collect();
        codes.sort();
        codes.dedup();
        let named: Vec<String> = codes
            .iter()
            .map(|b| format!("<code>{}</code> {}", b.code(), escape(&b.title(lang))))
            .collect();
        let thumbs: String = list
            .iter()
            .filter_map(|r| r.outcome.as_ref().ok())
            .filter(|g| !g.thumbnail.is_empty())
            .map(|g| {
                format!(
                    "<a href=\"#s{i}\"><img class=\"diff\" alt=\"\" src=\"data:image/png;base64,{}\"></a>",
                    base64::engine::general_purpose::STANDARD.encode(&g.thumbnail)
                )
            })
            .collect();
        let pixels: Vec<String> = list.iter().map(|r| differing(r).to_string()).collect();
        let _ = writeln!(
            h,
            "<tr><td><a href=\"#s{i}\">{}</a></td><td class=\"v {}\">{}</td><td>{}</td><td>{thumbs}</td><td>{}</td></tr>",
            escape(student),
            worst.code(),
            escape(&worst.word(lang)),
            if named.is_empty() {
                "&ndash;".to_string()
            } else {
                named.join("<br>")
            },
            pixels.join(" / ")
        );
    }
    h.push_str("</table>\n");
    for (i, (student, list)) in groups.iter().enumerate() {
        let _ = writeln!(h, "<section id=\"s{i}\"><h2>{}</h2>", escape(student));
        for r in list {
            student_scene(&mut h, r, lang);
        }
        let _ = writeln!(h, "<p><a href=\"#top\">{}</a></p></section>", t("back"));
    }
    h.push_str("</body></html>\n");
    h
}

/// One scene of a student's section: the verdict (large), the file, the named bugs with
/// explanation and fix, then the regions with their reasons, or the problem.
fn student_scene(h: &mut String, r: &Row, lang: Lang) {
    let v = r.verdict();
    let _ = writeln!(
        h,
        "<h3>{} &mdash; <span class=\"v big {}\">{}</span></h3>",
        escape(&r.scene),
        v.code(),
        escape(&v.word(lang))
    );
    if let Some(f) = &r.file {
        let _ = writeln!(
            h,
            "<p>{}</p>",
            escape(&lang.tr_with("grade.file", &[("file", &crate::files::shown(f))]))
        );
    }
    let g = match &r.outcome {
        Ok(g) => g,
        Err(p) => {
            let _ = writeln!(h, "<p class=\"problem\">{}</p>", escape(p));
            return;
        }
    };
    let c = &g.comparison;
    if let Some(l) = &c.looks_like {
        let _ = writeln!(h, "<p><strong>{}</strong></p>", escape(&l.text(lang)));
    }
    for b in &c.bugs {
        let _ = writeln!(
            h,
            "<div class=\"bug\"><strong><code>{}</code> {}</strong>: {}<br><em>{}</em> {}</div>",
            b.code(),
            escape(&b.title(lang)),
            escape(&b.explanation(lang)),
            escape(&lang.tr("grade.fix")),
            escape(&b.fix(lang))
        );
    }
    if c.agrees() {
        return;
    }
    let _ = writeln!(
        h,
        "<p>{}</p><ol class=\"regions\">",
        escape(&lang.tr_with("compare.report.regions", &[("n", &c.region_count)]))
    );
    for (i, region) in c.regions.iter().enumerate() {
        let _ = write!(h, "<li>{}", escape(region.text(i + 1, lang).trim()));
        for p in &region.samples {
            let _ = write!(
                h,
                "<div class=\"sample\">{}</div>",
                escape(p.text(lang).trim())
            );
        }
        h.push_str("</li>\n");
    }
    h.push_str("</ol>\n");
    if c.region_count > c.regions.len() {
        let _ = writeln!(
            h,
            "<p>{}</p>",
            escape(
                lang.tr_with(
                    "compare.report.regions_more",
                    &[("n", &(c.region_count - c.regions.len()))]
                )
                .trim()
            )
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_fields_are_quoted_and_formulas_defused() {
        assert_eq!(field("a,b"), "\"a,b\"");
        assert_eq!(field("say \"hi\""), "\"say \"\"hi\"\"\"");
        assert_eq!(field("=1+1"), "\"'=1+1\"");
        // Attributes are double-quoted in the report, so `"` is escaped and `'` need not be.
        assert_eq!(
            escape("<a href=\"x\">&</a>"),
            "&lt;a href=&quot;x&quot;&gt;&amp;&lt;/a&gt;"
        );
    }
}
