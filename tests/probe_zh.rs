//! `barylab probe --lang zh`: the derivation in Simplified Chinese, with the field's standard
//! terms, the same formulas and numbers as the English one (tests/probe_arithmetic.rs checks
//! the arithmetic and the numbers of both), and English by default.

use std::process::Command;

fn barylab(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .env("LANG", "C.UTF-8")
        .output()
        .expect("run barylab")
}

fn probe(extra: &[&str]) -> String {
    let mut args = vec!["probe", "assets/scenes/default.json", "--pixel", "400,420"];
    args.extend_from_slice(extra);
    let out = barylab(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8")
}

#[test]
fn chinese_text_has_the_section_titles_and_the_standard_terms() {
    let zh = probe(&["--lang", "zh"]);
    for title in [
        "1. 设置",
        "2. 采样点",
        "3. 哪个三角形覆盖了它",
        "4. 三角形 0 的顶点在各个空间中的坐标",
        "5. A, B, C 的屏幕空间权重 r, s, t：四种算法",
        "6. 用 1/w 做透视校正（OpenGL 4.6，公式 14.9）",
        "7. 4x4 线性方程组",
        "8. 像素看到的三角形上的点",
        "9. 纹理坐标和颜色：两种插值对比",
        "10. 深度",
        "11. 写入的颜色",
    ] {
        assert!(zh.contains(title), "no title `{title}` in:\n{zh}");
    }
    for term in [
        "重心坐标",
        "透视校正插值",
        "仿射",
        "裁剪空间",
        "近平面",
        "视口变换",
        "深度缓冲",
        "双线性",
        "光栅化",
        "片元",
        "像素中心",
    ] {
        assert!(zh.contains(term), "no `{term}` in the Chinese derivation");
    }
    // The formulas and symbols are the English ones.
    for formula in [
        "1/W_P = r/W_A + s/W_B + t/W_C",
        "a = r·W_P/W_A = 0.37989·2.29136/1.74413 = 0.4991",
    ] {
        assert!(
            zh.contains(formula),
            "no `{formula}` in the Chinese derivation"
        );
    }
    // An underline as wide as its title (a Chinese character takes two columns).
    let lines: Vec<&str> = zh.lines().collect();
    let width: usize = lines[0]
        .chars()
        .map(|c| if c.is_ascii() { 1 } else { 2 })
        .sum();
    assert_eq!(lines[1], "=".repeat(width));
}

#[test]
fn english_is_the_default_and_markdown_follows_the_language() {
    let en = probe(&[]);
    assert!(en.starts_with("barylab probe: pixel (400, 420) of the 800x600 image\n"));
    assert_eq!(en, probe(&["--lang", "en"]));
    let md = probe(&["--lang", "zh-CN", "--format", "markdown"]);
    assert!(md.contains("## 1. 设置"), "{md}");
    assert!(md.contains("透视校正"));
    // LaTeX stays English (plain pdflatex), with a note on stderr.
    let out = barylab(&[
        "probe",
        "assets/scenes/default.json",
        "--pixel",
        "400,420",
        "--format",
        "latex",
        "--lang",
        "zh",
    ]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stdout).contains("Settings"));
    assert!(String::from_utf8_lossy(&out.stderr).contains("LaTeX"));
}

#[test]
fn a_bad_language_is_a_one_line_error() {
    let out = barylab(&[
        "probe",
        "assets/scenes/default.json",
        "--pixel",
        "400,420",
        "--lang",
        "fr",
    ]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("`fr` is not a language"), "{err}");
}
