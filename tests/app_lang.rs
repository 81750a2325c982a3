//! The app in English and Simplified Chinese: the top bar's switch changes every label and the
//! inspector's derivation without a restart, the choice is saved, a first start follows the
//! system locale, no panel keeps an English label in Chinese, and without a Chinese font the app
//! says so (in English) and stays English. Driven through egui_kittest like tests/app.rs.
//!
//! The Chinese font comes from the system (fonts-noto-cjk under CI): without one, the tests
//! that need Chinese glyphs fail under CI (CI=true) and are skipped elsewhere, as in
//! tests/figure_zh.rs.

mod common;

use std::collections::BTreeMap;
use std::path::Path;

use barylab::app::command::AppCommand;
use barylab::app::command::BenchCommand;
use barylab::app::command::ExportCommand;
use barylab::app::document::state::StateCommand;
use barylab::app::{AppOptions, BaryApp};
use barylab::i18n::{Lang, cjk_font};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

const SIZE: egui::Vec2 = egui::vec2(1920.0, 1080.0);
/// A pixel of the default scene on the quad.
const PIXEL: [u32; 2] = [400, 420];

/// Whether the CJK font is there; without it, fails under CI and skips elsewhere.
fn have_cjk_font() -> bool {
    if cjk_font().is_some() {
        return true;
    }
    assert!(
        std::env::var("CI").as_deref() != Ok("true"),
        "no CJK font found: CI needs fonts-noto-cjk"
    );
    eprintln!("no CJK font installed: Chinese app checks skipped");
    false
}

fn harness_with(app: BaryApp) -> Harness<'static, BaryApp> {
    common::app::harness_of(app, SIZE)
}

fn harness(options: AppOptions) -> Harness<'static, BaryApp> {
    common::app::harness(SIZE, options)
}

fn shows(h: &Harness<'_, BaryApp>, label: &str) -> bool {
    h.query_all_by_label(label).next().is_some()
}

/// The `app.` entries of the catalogue `locales/NAME.yml`, flattened to `app.a.b` keys.
fn app_catalogue(name: &str) -> BTreeMap<String, String> {
    fn flatten(prefix: &str, v: &serde_yaml::Value, out: &mut BTreeMap<String, String>) {
        match v {
            serde_yaml::Value::Mapping(m) => {
                for (k, v) in m {
                    let k = k.as_str().expect("string keys");
                    flatten(&format!("{prefix}.{k}"), v, out);
                }
            }
            serde_yaml::Value::String(s) => {
                out.insert(prefix.to_string(), s.clone());
            }
            other => panic!("{prefix}: not a string: {other:?}"),
        }
    }
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("locales/{name}.yml"));
    let text = std::fs::read_to_string(path).expect("catalogue");
    let value: serde_yaml::Value = serde_yaml::from_str(&text).expect("YAML");
    let mut out = BTreeMap::new();
    flatten("app", value.get("app").expect("an app: section"), &mut out);
    out
}

/// Labels that must read in Chinese (top bar, controls, inspector, status line).
const CHINESE_LABELS: [&str; 12] = [
    "文件",
    "演示",
    "控制面板",
    "检查器",
    "重置场景",
    "插值方式",
    "透视校正插值",
    "纹理过滤",
    "双线性",
    "像素网格和采样点",
    "预设场景",
    "地面（默认）",
];

#[test]
fn the_switch_changes_the_labels_without_a_restart() {
    if !have_cjk_font() {
        return;
    }
    let mut h = harness(AppOptions::default());
    assert_eq!(h.state().lang(), Lang::En);
    assert!(shows(&h, "Reset scene") && shows(&h, "Interpolation"));
    h.get_by_label("中文").click();
    h.run();
    assert_eq!(h.state().lang(), Lang::Zh);
    for label in CHINESE_LABELS {
        assert!(shows(&h, label), "`{label}` is not shown in Chinese mode");
    }
    assert!(!shows(&h, "Reset scene") && !shows(&h, "Interpolation"));
    h.get_by_label("English").click();
    h.run();
    assert_eq!(h.state().lang(), Lang::En);
    assert!(shows(&h, "Reset scene") && !shows(&h, "重置场景"));
}

/// In Chinese, no label anywhere (top bar, panels, the pinned pixel's inspector, help, Export
/// and Benchmark windows) is the English text of a catalogue entry: a string left hard-coded
/// in English, or looked up in English, would show here.
#[test]
fn chinese_mode_shows_no_english_catalogue_text() {
    if !have_cjk_font() {
        return;
    }
    let mut app = BaryApp::new(
        None,
        AppOptions {
            lang: Some(Lang::Zh),
            ..AppOptions::default()
        },
    );
    app.push(StateCommand::Pin(Some(PIXEL)));
    app.push(AppCommand::SetHelpOpen(true));
    app.push(ExportCommand::Open);
    app.push(BenchCommand::SetOpen(true));
    let h = harness_with(app);
    assert_eq!(h.state().lang(), Lang::Zh);
    assert!(shows(&h, "帮助") && shows(&h, "导出图片") && shows(&h, "性能测试"));
    assert!(shows(&h, "鼠标") && shows(&h, "本帮助"), "help rows");
    let (en, zh) = (app_catalogue("en"), app_catalogue("zh"));
    let mut english = Vec::new();
    for (key, text) in &en {
        if zh.get(key) != Some(text) && !text.contains("%{") && shows(&h, text) {
            english.push(format!("{key}: {text}"));
        }
    }
    assert!(
        english.is_empty(),
        "English labels in Chinese mode:\n{}",
        english.join("\n")
    );
    // The check itself sees an English label where there is one.
    let h_en = harness(AppOptions::default());
    assert!(shows(&h_en, &en["app.controls.interpolation"]));
}

/// A projector's narrow bar at the largest text size has room for one language button: the
/// other language's, which still switches.
#[test]
fn a_narrow_bar_offers_the_other_language() {
    if !have_cjk_font() {
        return;
    }
    let mut app = BaryApp::new(None, AppOptions::default());
    app.push(StateCommand::SetUiScale(2.5));
    let mut h = Harness::builder()
        .with_size(egui::vec2(1024.0, 768.0))
        .with_max_steps(30)
        .build_ui_state(|ui, app: &mut BaryApp| app.show(ui), app);
    for _ in 0..4 {
        h.step();
    }
    h.run();
    assert!(shows(&h, "中文") && !shows(&h, "English"));
    h.get_by_label("中文").click();
    h.run();
    assert_eq!(h.state().lang(), Lang::Zh);
    assert!(shows(&h, "English") && !shows(&h, "中文"));
    h.get_by_label("English").click();
    h.run();
    assert_eq!(h.state().lang(), Lang::En);
}

/// The inspector's derivation is written in the app's language, and follows a switch.
#[test]
fn the_derivation_follows_the_language() {
    if !have_cjk_font() {
        return;
    }
    let mut app = BaryApp::new(None, AppOptions::default());
    app.push(StateCommand::Pin(Some(PIXEL)));
    let mut h = harness_with(app);
    let report = h.state().pin_report().expect("pinned report");
    let zh = barylab::probe::format::document_in(&report.trace, Lang::Zh);
    let en = barylab::probe::format::document_in(&report.trace, Lang::En);
    assert_eq!(report.document, en);
    let (title_en, title_zh) = (&en.sections[0].title, &zh.sections[0].title);
    assert_ne!(title_en, title_zh);
    assert!(shows(&h, title_en) && !shows(&h, title_zh));
    assert!(shows(&h, "Derivation of pixel (400, 420)"));
    h.state_mut().push(AppCommand::SetLang(Lang::Zh));
    h.run();
    let report = h.state().pin_report().expect("pinned report");
    assert_eq!(report.lang, Lang::Zh);
    assert_eq!(report.document, zh);
    assert!(shows(&h, title_zh) && !shows(&h, title_en));
    assert!(shows(&h, "像素 (400, 420) 的推导"));
}

/// The choice is saved with the app's state and comes back on the next start, over the
/// system locale; `--lang` wins over both.
#[test]
fn the_language_is_saved_and_restored() {
    use eframe::App as _;
    if !have_cjk_font() {
        return;
    }
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("barylab-state.json");
    let options = |system_lang, lang| AppOptions {
        persist: true,
        system_lang,
        lang,
        ..AppOptions::default()
    };
    let app = BaryApp::new_with_state_file(None, options(Lang::En, None), Some(path.clone()));
    let mut h = harness_with(app);
    h.get_by_label("中文").click();
    h.run();
    assert_eq!(h.state().lang(), Lang::Zh);
    let mut storage = Storage::default();
    h.state_mut().save(&mut storage);
    let saved: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&path).expect("state file")).expect("JSON");
    assert_eq!(saved["lang"], "zh");
    // Restored from the file, although the system locale is English.
    let restored = harness_with(BaryApp::new_with_state_file(
        None,
        options(Lang::En, None),
        Some(path.clone()),
    ));
    assert_eq!(restored.state().lang(), Lang::Zh);
    assert!(shows(&restored, "重置场景"));
    // And from eframe's storage.
    let from_storage = BaryApp::new(Some(&storage), options(Lang::En, None));
    assert_eq!(from_storage.lang(), Lang::Zh);
    // --lang en wins over the saved Chinese.
    let asked = BaryApp::new_with_state_file(None, options(Lang::Zh, Some(Lang::En)), Some(path));
    assert_eq!(asked.lang(), Lang::En);
    // A state saved before the app had languages has none: the system locale decides.
    let old = Storage(
        [(
            barylab::app::document::persist::STORAGE_KEY.to_string(),
            "(scene_json: \"\")".to_string(),
        )]
        .into(),
    );
    assert_eq!(
        BaryApp::new(Some(&old), options(Lang::Zh, None)).lang(),
        Lang::Zh
    );
}

/// A first start (nothing saved) follows the system locale: LC_ALL, LC_MESSAGES, LANG.
#[test]
fn a_first_start_follows_the_system_locale() {
    if !have_cjk_font() {
        return;
    }
    let locale = |vars: &'static [(&'static str, &'static str)]| {
        Lang::detect_with(move |name| {
            vars.iter()
                .find(|(n, _)| *n == name)
                .map(|(_, v)| v.to_string())
        })
    };
    let zh = harness(AppOptions {
        system_lang: locale(&[("LANG", "zh_CN.UTF-8")]),
        ..AppOptions::default()
    });
    assert_eq!(zh.state().lang(), Lang::Zh);
    assert!(shows(&zh, "重置场景") && !shows(&zh, "Reset scene"));
    let en = harness(AppOptions {
        system_lang: locale(&[("LC_ALL", "en_US.UTF-8"), ("LANG", "zh_CN.UTF-8")]),
        ..AppOptions::default()
    });
    assert_eq!(en.state().lang(), Lang::En);
    assert!(shows(&en, "Reset scene") && !shows(&en, "重置场景"));
}

/// Without a Chinese font the app never draws boxes: a Chinese locale starts in English with
/// a notice in English, and the switch offers "Chinese", which says why it stays English.
#[test]
fn without_a_chinese_font_the_app_says_so_and_stays_english() {
    let mut h = harness(AppOptions {
        system_lang: Lang::Zh,
        no_cjk_font: true,
        ..AppOptions::default()
    });
    assert_eq!(h.state().lang(), Lang::En);
    let notice = h.state().banner().expect("a notice");
    assert!(
        notice[0].starts_with("No font with Chinese glyphs"),
        "{notice:?}"
    );
    assert!(shows(&h, "Reset scene") && !shows(&h, "中文"));
    h.get_by_label("Dismiss").click();
    h.run();
    assert!(h.state().banner().is_none());
    h.get_by_label("Chinese").click();
    h.run();
    assert_eq!(h.state().lang(), Lang::En);
    assert!(h.state().banner().is_some(), "the notice again");
}

/// Every `"app.…"` key the app's source looks up is in the catalogues (a missing one would
/// show as its key); tests/i18n.rs checks that both catalogues have the same keys.
#[test]
fn every_key_the_app_uses_is_in_the_catalogue() {
    let en = app_catalogue("en");
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/app");
    let mut used = 0;
    let mut missing = Vec::new();
    // Every source file under src/app, its folders included.
    let mut files = Vec::new();
    let mut dirs = vec![dir];
    while let Some(d) = dirs.pop() {
        for entry in std::fs::read_dir(&d).expect("a folder of src/app") {
            let path = entry.expect("entry").path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                files.push(path);
            }
        }
    }
    for path in files {
        let text = std::fs::read_to_string(&path).expect("source");
        for (i, _) in text.match_indices("\"app.") {
            let key: String = text[i + 1..]
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_' || *c == '.')
                .collect();
            used += 1;
            if !en.contains_key(&key) {
                missing.push(format!("{}: {key}", path.display()));
            }
        }
    }
    assert!(used > 200, "only {used} keys found");
    assert!(
        missing.is_empty(),
        "not in locales/en.yml:\n{}",
        missing.join("\n")
    );
}

/// eframe's storage in memory.
#[derive(Default)]
struct Storage(BTreeMap<String, String>);

impl eframe::Storage for Storage {
    fn get_string(&self, key: &str) -> Option<String> {
        self.0.get(key).cloned()
    }
    fn set_string(&mut self, key: &str, value: String) {
        self.0.insert(key.to_string(), value);
    }
    fn remove_string(&mut self, key: &str) {
        self.0.remove(key);
    }
    fn flush(&mut self) {}
}
