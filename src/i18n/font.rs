//! The fonts beside egui's own: the bundled symbols font ([`SYMBOLS_FONT`]: floor brackets,
//! arrows, sub- and superscripts, mathematical operators that egui's Ubuntu Light lacks) and a
//! system font with Chinese glyphs, found at run time through `fontdb` (the font database resvg
//! uses). The app, the figures' labels and the PNG figures use the same faces in the same
//! order ([`app_font_faces`]).

use std::sync::{Arc, OnceLock};

use resvg::usvg::fontdb::{Database, Family, Query};

/// A subset of DejaVu Sans 2.37 (`assets/fonts/`, Bitstream Vera licence with DejaVu's changes in
/// the public domain: `assets/fonts/LICENSE-DejaVu.txt`): ASCII, Latin-1, Greek, combining
/// marks, general punctuation, super- and subscripts, arrows, mathematical operators,
/// miscellaneous technical (`⌊ ⌋ ⌈ ⌉`) and geometric shapes. The fallback after egui's font
/// for the symbols it lacks.
pub const SYMBOLS_FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans-Symbols.ttf");

/// The family name of [`SYMBOLS_FONT`].
pub const SYMBOLS_FAMILY: &str = "DejaVu Sans";

/// One font face: a name, the font file's bytes and the face's index in it.
#[derive(Clone, Debug)]
pub struct FontFace {
    /// The name egui knows it by (`Ubuntu-Light`, ...), or the family for the CJK font.
    pub name: String,
    /// The font file's bytes.
    pub data: Arc<Vec<u8>>,
    /// The face's index in the file (0 for a single-face file).
    pub index: u32,
}

/// The faces of the app's proportional text, in the order egui tries them for a character:
/// egui's default `Ubuntu-Light` and `egui-icons`, then [`SYMBOLS_FONT`], then the system's
/// Chinese font ([`cjk_font`]) when there is one. (The monospace family puts `Hack` first and
/// then the same faces, so it covers at least as much.) A character none of them has shows
/// as an empty box.
pub fn app_font_faces() -> Vec<FontFace> {
    let builtin = |name: &str, data: &[u8]| FontFace {
        name: name.to_string(),
        data: Arc::new(data.to_vec()),
        index: 0,
    };
    let mut faces = vec![
        builtin("Ubuntu-Light", epaint_default_fonts::UBUNTU_LIGHT),
        builtin("egui-icons", epaint_default_fonts::EGUI_ICONS),
        builtin(SYMBOLS_FAMILY, SYMBOLS_FONT),
    ];
    if let Some(cjk) = cjk_font() {
        faces.push(FontFace {
            name: cjk.family.clone(),
            data: cjk.data.clone(),
            index: cjk.index,
        });
    }
    faces
}

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
