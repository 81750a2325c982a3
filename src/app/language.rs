//! The app's language: the fonts on the first frame, the top bar's switch, and the notice when
//! Chinese is asked for without a Chinese font (the catalogues and the font are in
//! [`crate::app::services::locale`]).

use crate::app::panels::banner::Banner;
use crate::app::services::locale::{NO_CJK_FONT, lang, set_lang};
use crate::i18n::Lang;

impl super::BaryApp {
    /// Once per frame, before the panels: the fonts on the first frame, then the language
    /// into the context (and the window title when it changed).
    pub(in crate::app) fn sync_lang(&mut self, ctx: &egui::Context) {
        let first = !self.fonts.installed;
        if !self.fonts.install(ctx) && self.lang == Lang::Zh {
            self.lang = Lang::En;
            self.no_cjk_notice();
        }
        if first || lang(ctx) != self.lang {
            ctx.send_viewport_cmd(egui::ViewportCommand::Title(self.lang.tr("app.title")));
        }
        set_lang(ctx, self.lang);
    }

    /// The top bar's language switch: applied from the next frame on, without a restart.
    /// Chinese without a Chinese font says so (in English) and stays English.
    pub(in crate::app) fn set_lang(&mut self, lang: Lang) {
        if lang == Lang::Zh && self.fonts.installed && !self.fonts.cjk {
            self.no_cjk_notice();
            return;
        }
        self.lang = lang;
    }

    /// The language the app shows.
    pub fn lang(&self) -> Lang {
        self.lang
    }

    fn no_cjk_notice(&mut self) {
        self.banner = Some(Banner::notice(Lang::En.tr(NO_CJK_FONT), Lang::En));
    }
}
