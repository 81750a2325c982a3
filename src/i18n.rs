//! Languages and the string catalogues: English and Simplified Chinese.
//!
//! The catalogues are `locales/en.yml` and `locales/zh.yml`, compiled into the crate by
//! [rust-i18n](https://docs.rs/rust-i18n) (`rust_i18n::i18n!` in `lib.rs`); a key is looked up
//! with [`tr`] (no arguments) or the crate's `rust_i18n::t!` macro with a `locale` argument
//! ([`Lang::code`]) and `%{name}` placeholders. `tests/i18n.rs` fails when a key lacks a
//! translation or a placeholder differs between the two catalogues.
//!
//! The probe's derivation, its document title, the setting names and the figure labels come
//! from the catalogues; formulas and symbols (r, s, t, W_P, a, b, c, λ) are the same in every
//! language. [`cjk_font`] finds a system font with Chinese glyphs for the figures and the app.

use std::fmt;
use std::str::FromStr;

/// A language of the user interface and the derivations.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "lowercase")]
pub enum Lang {
    /// English (the default).
    #[default]
    En,
    /// Simplified Chinese (简体中文).
    Zh,
}

impl Lang {
    /// Every language, in the order a language switch lists them.
    pub const ALL: [Lang; 2] = [Lang::En, Lang::Zh];

    /// The catalogue's locale code: `en` or `zh`.
    pub fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Zh => "zh",
        }
    }

    /// The language's own name, for a language switch: `English`, `中文`.
    pub fn native_name(self) -> &'static str {
        match self {
            Lang::En => "English",
            Lang::Zh => "中文",
        }
    }

    /// Parses a language tag: `en`, `en-US`, `zh`, `zh-CN`, `zh_CN`, `zh-Hans` (any case).
    ///
    /// ```
    /// use barylab::i18n::Lang;
    /// assert_eq!(Lang::parse("zh-CN"), Some(Lang::Zh));
    /// assert_eq!(Lang::parse("EN"), Some(Lang::En));
    /// assert_eq!(Lang::parse("fr"), None);
    /// ```
    pub fn parse(tag: &str) -> Option<Lang> {
        let tag = tag.trim().to_ascii_lowercase();
        let primary = tag.split(['-', '_', '.', '@']).next().unwrap_or("");
        match primary {
            "en" => Some(Lang::En),
            "zh" => Some(Lang::Zh),
            _ => None,
        }
    }

    /// The language of a POSIX locale value such as `zh_CN.UTF-8`: `zh*` is Chinese,
    /// anything else (`C`, `POSIX`, `en_GB.UTF-8`, `de_DE`) English.
    pub fn from_locale(locale: &str) -> Lang {
        if locale.trim().to_ascii_lowercase().starts_with("zh") {
            Lang::Zh
        } else {
            Lang::En
        }
    }

    /// The system locale's language: the first of `LC_ALL`, `LC_MESSAGES` and `LANG` that is
    /// set and not empty decides (as in POSIX); none set means English.
    pub fn detect() -> Lang {
        Lang::detect_with(|name| std::env::var(name).ok())
    }

    /// [`Lang::detect`] with the environment given as a function (for tests).
    ///
    /// ```
    /// use barylab::i18n::Lang;
    /// let env = |name: &str| (name == "LANG").then(|| "zh_CN.UTF-8".to_string());
    /// assert_eq!(Lang::detect_with(env), Lang::Zh);
    /// let env = |name: &str| match name {
    ///     "LC_ALL" => Some("C".to_string()),
    ///     "LANG" => Some("zh_CN.UTF-8".to_string()),
    ///     _ => None,
    /// };
    /// assert_eq!(Lang::detect_with(env), Lang::En);
    /// ```
    pub fn detect_with(env: impl Fn(&str) -> Option<String>) -> Lang {
        ["LC_ALL", "LC_MESSAGES", "LANG"]
            .iter()
            .filter_map(|name| env(name))
            .find(|v| !v.trim().is_empty())
            .map_or(Lang::En, |v| Lang::from_locale(&v))
    }
}

impl fmt::Display for Lang {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.code())
    }
}

impl FromStr for Lang {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Lang::parse(s).ok_or_else(|| format!("`{s}` is not a language: en or zh (zh-CN)"))
    }
}

/// The catalogue entry `key` in `lang`, without placeholders filled in. For entries with
/// `%{name}` placeholders use `rust_i18n::t!(key, locale = lang.code(), name = value)`.
pub fn tr(lang: Lang, key: &str) -> String {
    crate::_rust_i18n_translate(lang.code(), key).into_owned()
}

impl Lang {
    /// The catalogue entry `key` in this language ([`tr`] as a method).
    pub fn tr(self, key: &str) -> String {
        tr(self, key)
    }

    /// The catalogue entry `key` in this language with its `%{name}` placeholders replaced
    /// by `args`' values (a placeholder without a value stays as it is).
    ///
    /// ```
    /// use barylab::i18n::Lang;
    /// let s = Lang::Zh.tr_with("probe.title", &[("w", &800), ("h", &600), ("x", &1), ("y", &2)]);
    /// assert!(s.contains("800x600") && s.contains("(1, 2)"), "{s}");
    /// ```
    pub fn tr_with(self, key: &str, args: &[(&str, &dyn fmt::Display)]) -> String {
        let mut out = tr(self, key);
        for (name, value) in args {
            out = out.replace(&format!("%{{{name}}}"), &value.to_string());
        }
        out
    }

    /// A difference of `n` colour levels (steps of an 8-bit channel) in words, the unit in
    /// the count's number: "1 level", "64 levels" (zh "1 级").
    ///
    /// ```
    /// use barylab::i18n::Lang;
    /// assert_eq!(Lang::En.levels(1u8), "1 level");
    /// assert_eq!(Lang::En.levels(0u8), "0 levels");
    /// assert_eq!(Lang::Zh.levels(3u8), "3 级");
    /// ```
    pub fn levels(self, n: impl fmt::Display) -> String {
        let n = n.to_string();
        let key = if n == "1" {
            "count.level_one"
        } else {
            "count.level_other"
        };
        self.tr_with(key, &[("n", &n)])
    }
}

mod font;

pub use font::{
    CJK_FAMILIES, CjkFont, FontFace, SYMBOLS_FAMILY, SYMBOLS_FONT, app_font_faces, cjk_font,
};
