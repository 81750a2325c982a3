//! The app's language: which one the panels show, kept in the egui context so every panel
//! (and the lessons, the windows) reads it without an extra argument.
//!
//! [`BaryApp`](crate::app::BaryApp) owns the language (saved with the state, chosen in the top bar)
//! and puts it into the context at the start of every frame with [`set_lang`]; a panel reads it
//! with [`lang`] and looks its strings up in the catalogues' `app:` section with
//! [`Lang::tr`] or [`Lang::tr_with`]. Each egui context has its own language, so tests
//! with several apps side by side do not disturb each other.

use crate::i18n::Lang;

/// Where the language is kept in the context's temporary data.
fn id() -> egui::Id {
    egui::Id::unique("barylab-lang")
}

/// The language the app shows in this context (English until the app sets one).
pub fn lang(ctx: &egui::Context) -> Lang {
    ctx.data(|d| d.get_temp::<Lang>(id())).unwrap_or_default()
}

/// Makes `lang` the language the panels of this context show.
pub fn set_lang(ctx: &egui::Context, lang: Lang) {
    ctx.data_mut(|d| d.insert_temp(id(), lang));
}

/// Whether the app's egui context has a font with Chinese glyphs: looked for once, on the
/// first frame ([`crate::i18n::cjk_font`], added as the last fallback of egui's proportional
/// and monospace families, so Latin text keeps egui's own fonts).
#[derive(Clone, Copy, Debug)]
pub struct Fonts {
    /// A font with Chinese glyphs is installed in the context.
    pub cjk: bool,
    /// Fonts were set up (on the first frame).
    pub(in crate::app) installed: bool,
    /// Pretend that the system has no such font (tests).
    pretend_none: bool,
}

impl Fonts {
    /// Not set up yet; `pretend_none` behaves as if the system had no Chinese font.
    pub fn new(pretend_none: bool) -> Self {
        Self {
            cjk: false,
            installed: false,
            pretend_none,
        }
    }

    /// Adds the system's Chinese font to the context once; returns whether there is one.
    pub(in crate::app) fn install(&mut self, ctx: &egui::Context) -> bool {
        if !self.installed {
            self.installed = true;
            add_symbols_font(ctx);
            self.cjk = !self.pretend_none && add_cjk_font(ctx);
        }
        self.cjk
    }
}

/// Adds [`crate::i18n::SYMBOLS_FONT`] to `ctx` as a fallback of the proportional and monospace
/// families, after egui's own fonts (and before the CJK font, added after it): the floor
/// brackets, arrows and other symbols that egui's Ubuntu Light lacks.
pub fn add_symbols_font(ctx: &egui::Context) {
    add_fallback_font(
        ctx,
        "barylab-symbols",
        egui::FontData::from_static(crate::i18n::SYMBOLS_FONT),
    );
}

/// Adds [`crate::i18n::cjk_font`] to `ctx` as the lowest-priority fallback of the proportional
/// and monospace families. Returns false when the system has no font with Chinese glyphs.
pub fn add_cjk_font(ctx: &egui::Context) -> bool {
    let Some(font) = crate::i18n::cjk_font() else {
        return false;
    };
    let data = egui::FontData::from_blob(font.data.clone(), font.index);
    add_fallback_font(ctx, "barylab-cjk", data);
    true
}

/// Adds `data` to `ctx` as the lowest-priority fallback (so far) of the proportional and
/// monospace families.
fn add_fallback_font(ctx: &egui::Context, name: &str, data: egui::FontData) {
    use egui::epaint::text::{FontInsert, FontPriority, InsertFontFamily};
    ctx.add_font(FontInsert::new(
        name,
        data,
        [egui::FontFamily::Proportional, egui::FontFamily::Monospace]
            .into_iter()
            .map(|family| InsertFontFamily {
                family,
                priority: FontPriority::Lowest,
            })
            .collect(),
    ));
}

/// The notice shown (in English, which needs no extra font) when Chinese was asked for but no
/// font with Chinese glyphs is installed.
pub const NO_CJK_FONT: &str = "app.lang.no_cjk_font";
