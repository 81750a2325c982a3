//! The catalogues `locales/en.yml` and `locales/zh.yml`: every key in one is in the other,
//! with the same `%{name}` (and `{name}`) placeholders, and no entry is empty; the language
//! type parses tags and follows the system locale; every character that the catalogues, the
//! built-in lesson and the probe show has a glyph in the app's fonts.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use barylab::i18n::{Lang, tr};

/// The catalogue `locales/NAME.yml` as flattened `a.b.c` keys and their strings.
fn catalogue(name: &str) -> BTreeMap<String, String> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("locales/{name}.yml"));
    let text = std::fs::read_to_string(&path).expect("catalogue");
    let value: serde_yaml::Value = serde_yaml::from_str(&text).expect("YAML");
    let mut out = BTreeMap::new();
    flatten("", &value, &mut out);
    out.remove("_version");
    out
}

fn flatten(prefix: &str, v: &serde_yaml::Value, out: &mut BTreeMap<String, String>) {
    match v {
        serde_yaml::Value::Mapping(m) => {
            for (k, v) in m {
                let k = k.as_str().expect("string keys");
                let key = if prefix.is_empty() {
                    k.to_string()
                } else {
                    format!("{prefix}.{k}")
                };
                flatten(&key, v, out);
            }
        }
        serde_yaml::Value::String(s) => {
            out.insert(prefix.to_string(), s.clone());
        }
        other => {
            out.insert(prefix.to_string(), format!("{other:?}"));
        }
    }
}

/// The placeholders of an entry: `%{name}` (rust-i18n) and `{name}` (format-style).
fn placeholders(s: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut rest = s;
    while let Some(open) = rest.find('{') {
        let after = &rest[open + 1..];
        let Some(close) = after.find('}') else { break };
        let name = &after[..close];
        if !name.is_empty() && name.chars().all(|c| c.is_alphanumeric() || c == '_') {
            let percent = rest[..open].ends_with('%');
            out.insert(format!("{}{{{name}}}", if percent { "%" } else { "" }));
        }
        rest = &after[close + 1..];
    }
    out
}

/// The check itself, on two catalogues: the problems found, one line each.
fn problems(en: &BTreeMap<String, String>, zh: &BTreeMap<String, String>) -> Vec<String> {
    let mut out = Vec::new();
    for k in en.keys().filter(|k| !zh.contains_key(*k)) {
        out.push(format!("`{k}` has no Chinese translation (locales/zh.yml)"));
    }
    for k in zh.keys().filter(|k| !en.contains_key(*k)) {
        out.push(format!("`{k}` has no English entry (locales/en.yml)"));
    }
    for (k, e) in en {
        if let Some(z) = zh.get(k) {
            let (pe, pz) = (placeholders(e), placeholders(z));
            if pe != pz {
                out.push(format!("`{k}`: placeholders differ: en {pe:?}, zh {pz:?}"));
            }
            if z.trim().is_empty() && !e.trim().is_empty() {
                out.push(format!("`{k}`: the Chinese entry is empty"));
            }
        }
    }
    out
}

#[test]
fn every_key_is_translated_with_the_same_placeholders() {
    let (en, zh) = (catalogue("en"), catalogue("zh"));
    assert!(en.len() > 100, "only {} English entries", en.len());
    let found = problems(&en, &zh);
    assert!(
        found.is_empty(),
        "catalogue problems:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_check_catches_a_missing_key_and_a_renamed_placeholder() {
    let en: BTreeMap<String, String> = [
        ("a".to_string(), "pixel (%{x}, %{y})".to_string()),
        ("b".to_string(), "two".to_string()),
    ]
    .into();
    let zh: BTreeMap<String, String> = [("a".to_string(), "像素 (%{x}, %{z})".to_string())].into();
    let found = problems(&en, &zh);
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(found[0].contains("`b` has no Chinese"));
    assert!(found[1].contains("placeholders differ"));
    assert_eq!(
        placeholders("a %{x} {y} {not a name}"),
        ["%{x}".to_string(), "{y}".to_string()].into()
    );
}

/// The compiled-in catalogues are the files: a lookup gives the file's entry in each language.
#[test]
fn lookups_use_the_catalogues() {
    let (en, zh) = (catalogue("en"), catalogue("zh"));
    for key in [
        "probe.settings.title",
        "probe.filter.bilinear",
        "figure.texels",
    ] {
        assert_eq!(tr(Lang::En, key), en[key]);
        assert_eq!(tr(Lang::Zh, key), zh[key]);
    }
    assert_eq!(tr(Lang::Zh, "probe.filter.bilinear"), "双线性");
}

#[test]
fn languages_parse_and_follow_the_system_locale() {
    for (tag, lang) in [
        ("en", Lang::En),
        ("en-US", Lang::En),
        ("zh", Lang::Zh),
        ("zh-CN", Lang::Zh),
        ("zh_CN", Lang::Zh),
        ("ZH-cn", Lang::Zh),
        ("zh-Hans", Lang::Zh),
    ] {
        assert_eq!(tag.parse::<Lang>(), Ok(lang), "{tag}");
    }
    assert!("fr".parse::<Lang>().is_err());
    assert!("".parse::<Lang>().is_err());
    let env = |vars: &'static [(&'static str, &'static str)]| {
        move |name: &str| {
            vars.iter()
                .find(|(n, _)| *n == name)
                .map(|(_, v)| v.to_string())
        }
    };
    assert_eq!(Lang::detect_with(env(&[])), Lang::En);
    assert_eq!(Lang::detect_with(env(&[("LANG", "zh_CN.UTF-8")])), Lang::Zh);
    assert_eq!(Lang::detect_with(env(&[("LANG", "en_US.UTF-8")])), Lang::En);
    // LC_ALL wins over LC_MESSAGES, which wins over LANG; empty values are skipped.
    assert_eq!(
        Lang::detect_with(env(&[("LC_ALL", "C"), ("LANG", "zh_CN.UTF-8")])),
        Lang::En
    );
    assert_eq!(
        Lang::detect_with(env(&[("LC_MESSAGES", "zh_TW.UTF-8"), ("LANG", "en_GB")])),
        Lang::Zh
    );
    assert_eq!(
        Lang::detect_with(env(&[("LC_ALL", ""), ("LANG", "zh_CN.UTF-8")])),
        Lang::Zh
    );
}

/// The overlay's English labels (constants the app uses directly) are the catalogue's English
/// entries, and the Chinese ones come from the catalogue.
#[test]
fn figure_labels_match_the_catalogue() {
    use barylab::figure::overlay::{
        HandleMark, OverlayInput, Shape, behind_camera_note, build, build_in, mode_label,
        mode_label_in,
    };
    use barylab::raster::Interpolation;
    assert_eq!(
        mode_label(Interpolation::Affine),
        tr(Lang::En, "figure.affine")
    );
    assert_eq!(
        mode_label(Interpolation::Perspective),
        tr(Lang::En, "figure.perspective")
    );
    assert_eq!(
        mode_label_in(Interpolation::Perspective, Lang::Zh),
        "透视校正插值"
    );
    let handles = vec![HandleMark {
        index: 1,
        window: None,
        w: -1.0,
        active: false,
    }];
    let note = behind_camera_note(&handles).expect("a note");
    assert!(note.starts_with(&tr(Lang::En, "figure.behind")), "{note}");
    let input = OverlayInput {
        size: [100, 80],
        pixel_size: 1,
        pixels_per_point: 1.0,
        mode: None,
        show_grid: false,
        handles,
        hover: None,
        pin: None,
        clipped: None,
        sub_areas: false,
        sub_area_fill: true,
        wipe: None,
        color_bar: Some(10.0),
    };
    let texts = |lang: Lang| -> Vec<String> {
        let overlay = if lang == Lang::En {
            build(&input)
        } else {
            build_in(&input, lang)
        };
        overlay
            .shapes
            .iter()
            .filter_map(|s| match s {
                Shape::Text { text, .. } => Some(text.clone()),
                Shape::ColorBar { title, .. } => Some(title.clone()),
                _ => None,
            })
            .collect()
    };
    for lang in Lang::ALL {
        let texts = texts(lang);
        for key in ["figure.difference", "figure.texels"] {
            assert!(texts.contains(&tr(lang, key)), "{lang}: {key} in {texts:?}");
        }
        assert!(
            texts
                .iter()
                .any(|t| t.starts_with(&tr(lang, "figure.behind"))),
            "{lang}: {texts:?}"
        );
    }
}

/// Every text the app shows that this test can reach, with where it comes from: the built-in
/// lesson's strings in both languages, every catalogue entry, and the probe's text for the
/// default scene's pixel (400, 420) in both languages (line by line).
fn shown_texts() -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut both = |place: String, t: &barylab::lesson::text::Text| {
        out.push((format!("{place} (en)"), t.en.clone()));
        out.push((format!("{place} (zh)"), t.zh.clone()));
    };
    // Every built-in lesson.
    for b in &barylab::lesson::builtin::LESSONS {
        let lesson = barylab::lesson::Lesson::open(Path::new(b.name)).expect("built-in lesson");
        let name = b.name;
        both(format!("the {name} lesson's title"), &lesson.title);
        for (k, step) in lesson.steps.iter().enumerate() {
            let n = k + 1;
            both(format!("{name} lesson step {n}, title"), &step.title);
            if let Some(summary) = &step.summary {
                both(format!("{name} lesson step {n}, summary"), summary);
            }
            both(format!("{name} lesson step {n}, text"), &step.text);
            both(format!("{name} lesson step {n}, try"), &step.try_this);
        }
    }
    for name in ["en", "zh"] {
        for (key, text) in catalogue(name) {
            out.push((format!("locales/{name}.yml, {key}"), text));
        }
    }
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let scene = barylab::Scene::load(&dir.join("default.json")).expect("scene");
    let texture = scene.load_texture(&dir).expect("texture");
    let trace =
        barylab::probe::probe(&scene, &texture, &scene.settings(), (400, 420)).expect("probe");
    for lang in [Lang::En, Lang::Zh] {
        let text =
            barylab::probe::format::write_in(&trace, barylab::probe::format::Format::Text, lang);
        for (k, line) in text.lines().enumerate() {
            out.push((
                format!("the probe's text ({}), line {}", lang.code(), k + 1),
                line.to_string(),
            ));
        }
    }
    out
}

/// The characters of `texts` that no face of `faces` has, each with the places it occurs in
/// (control characters such as line breaks are not drawn and are skipped).
fn missing_glyphs(
    texts: &[(String, String)],
    faces: &[barylab::i18n::FontFace],
) -> BTreeMap<char, Vec<String>> {
    let parsed: Vec<ttf_parser::Face> = faces
        .iter()
        .map(|f| ttf_parser::Face::parse(f.data.as_slice(), f.index).expect("a font the app uses"))
        .collect();
    let mut missing: BTreeMap<char, Vec<String>> = BTreeMap::new();
    for (place, text) in texts {
        for c in text.chars() {
            if c.is_control() || parsed.iter().any(|f| f.glyph_index(c).is_some()) {
                continue;
            }
            let places = missing.entry(c).or_default();
            if !places.contains(place) {
                places.push(place.clone());
            }
        }
    }
    missing
}

#[test]
fn every_character_shown_has_a_glyph_in_the_apps_fonts() {
    let faces = barylab::i18n::app_font_faces();
    if barylab::i18n::cjk_font().is_none() {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "no CJK font found: CI needs fonts-noto-cjk"
        );
        eprintln!("no CJK font installed: the glyph check is skipped");
        return;
    }
    let missing = missing_glyphs(&shown_texts(), &faces);
    let names: Vec<&str> = faces.iter().map(|f| f.name.as_str()).collect();
    let report: Vec<String> = missing
        .iter()
        .map(|(c, places)| {
            format!(
                "{c:?} (U+{:04X}) is in none of the app's fonts {names:?}: {}",
                u32::from(*c),
                places.join("; ")
            )
        })
        .collect();
    assert!(report.is_empty(), "{}", report.join("\n"));
}

#[test]
fn the_glyph_check_names_the_character_and_where_it_is() {
    let texts = vec![
        ("step 7".to_string(), "texel (⌊u·W⌋, ⌊v·H⌋)".to_string()),
        ("a label".to_string(), "a clef 𝄞".to_string()),
    ];
    // Without the symbols font egui's Ubuntu Light has no floor brackets.
    let without_symbols: Vec<_> = barylab::i18n::app_font_faces()
        .into_iter()
        .filter(|f| f.name != barylab::i18n::SYMBOLS_FAMILY)
        .collect();
    let missing = missing_glyphs(&texts, &without_symbols);
    assert_eq!(missing.get(&'⌊'), Some(&vec!["step 7".to_string()]));
    assert_eq!(missing.get(&'⌋'), Some(&vec!["step 7".to_string()]));
    // With it, only the clef (in no font) is left.
    let missing = missing_glyphs(&texts, &barylab::i18n::app_font_faces());
    assert_eq!(
        missing.into_iter().collect::<Vec<_>>(),
        [('𝄞', vec!["a label".to_string()])]
    );
}
