//! A system font with Chinese glyphs, found at run time through `fontdb` (the font database
//! resvg uses): for the figures' Chinese labels and, later, the app's font fallback (egui's
//! built-in fonts have no Chinese glyphs).

use std::sync::{Arc, OnceLock};

use resvg::usvg::fontdb::{Database, Family, Query};

/// Font families with Simplified Chinese glyphs, most wanted first: Linux (Noto, Source
/// Han, WenQuanYi), Windows (Microsoft YaHei), macOS (PingFang). The SVG figures list them as
/// fallbacks after the overlay font.
pub const CJK_FAMILIES: [&str; 8] = [
    "Noto Sans CJK SC",
    "Source Han Sans SC",
    "Noto Sans SC",
    "WenQuanYi Micro Hei",
    "WenQuanYi Zen Hei",
    "Microsoft YaHei",
    "PingFang SC",
    "Noto Serif CJK SC",
];

/// A font face with Chinese glyphs.
#[derive(Clone, Debug)]
pub struct CjkFont {
    /// The family name, as an SVG `font-family` names it.
    pub family: String,
    /// The font file's bytes (a `.ttc` collection holds several faces: see `index`).
    pub data: Arc<Vec<u8>>,
    /// The face's index in the file (0 for a single-face file).
    pub index: u32,
}

/// The first family of [`CJK_FAMILIES`] installed on this system, searched once per process
/// (scanning the system fonts takes a moment); `None` when there is none. The app can hand
/// `data` to egui as a fallback font (`egui::FontData::from_owned(..)` with `index`).
pub fn cjk_font() -> Option<&'static CjkFont> {
    static FONT: OnceLock<Option<CjkFont>> = OnceLock::new();
    FONT.get_or_init(find).as_ref()
}

fn find() -> Option<CjkFont> {
    let mut db = Database::new();
    db.load_system_fonts();
    CJK_FAMILIES.iter().find_map(|&family| {
        let id = db.query(&Query {
            families: &[Family::Name(family)],
            ..Query::default()
        })?;
        let face = db.face(id)?;
        // Only a face that really is the family asked for (query falls back to nothing, but
        // be strict: a wrong face would draw boxes).
        if !face.families.iter().any(|(name, _)| name == family) {
            return None;
        }
        let (data, index) = db.with_face_data(id, |data, index| (data.to_vec(), index))?;
        Some(CjkFont {
            family: family.to_string(),
            data: Arc::new(data),
            index,
        })
    })
}
