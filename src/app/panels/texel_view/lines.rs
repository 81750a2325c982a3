//! The texture views' numbers as text: the lines over and under the texture-space view's
//! pictures, and the line under the level-of-detail view.

use crate::i18n::Lang;
use crate::probe::LodTrace;
use crate::probe::format::fmt_number;

/// `rgba(r, g, b, a)`.
pub(super) fn rgba(c: [u8; 4]) -> String {
    format!("rgba({}, {}, {}, {})", c[0], c[1], c[2], c[3])
}

pub(super) fn n(x: f32) -> String {
    fmt_number(f64::from(x))
}

/// The lines of numbers of the texture-space view: first (over the pictures) the uv, the
/// derivatives, the footprint and level of detail, the levels and their blend; then (under
/// them) the anisotropic probes or each tap with its weight, and the colour.
pub fn texture_lines(
    lang: Lang,
    pixel: [u32; 2],
    uv: [f32; 2],
    taps: &[crate::probe::TapTrace],
    lod: Option<&LodTrace>,
    color: [u8; 4],
) -> [Vec<String>; 2] {
    let mut v = vec![lang.tr_with(
        "texel_view.uv",
        &[
            ("x", &pixel[0]),
            ("y", &pixel[1]),
            ("u", &n(uv[0])),
            ("v", &n(uv[1])),
        ],
    )];
    let mut taps = taps;
    if let Some(lt) = lod {
        v.push(lang.tr_with(
            "texel_view.derivatives",
            &[
                ("dudx", &n(lt.duv_dx[0])),
                ("dvdx", &n(lt.duv_dx[1])),
                ("dudy", &n(lt.duv_dy[0])),
                ("dvdy", &n(lt.duv_dy[1])),
            ],
        ));
        v.push(lang.tr_with(
            "texel_view.footprint",
            &[
                ("px", &n(lt.px)),
                ("py", &n(lt.py)),
                ("rho", &n(lt.rho)),
                ("lambda", &n(lt.trilinear.lambda)),
            ],
        ));
        let choice = match &lt.anisotropic {
            Some(a) => {
                v.push(lang.tr_with(
                    "texel_view.anisotropic",
                    &[
                        ("n", &a.n),
                        ("max", &a.max),
                        ("lambda", &n(a.levels.lambda)),
                    ],
                ));
                &a.levels
            }
            None => &lt.trilinear,
        };
        v.push(match choice.next {
            Some((next, f)) => lang.tr_with(
                "texel_view.two_levels",
                &[
                    ("d", &choice.level),
                    ("e", &next),
                    ("wd", &n(1.0 - f)),
                    ("we", &n(f)),
                ],
            ),
            None => lang.tr_with("texel_view.one_level", &[("d", &choice.level)]),
        });
    }
    let mut below = Vec::new();
    if let Some(lt) = lod {
        taps = &lt.taps;
        if let Some(a) = &lt.anisotropic {
            for (i, p) in a.probes.iter().enumerate() {
                below.push(lang.tr_with(
                    "texel_view.probe",
                    &[
                        ("i", &(i + 1)),
                        ("u", &n(p.uv[0])),
                        ("v", &n(p.uv[1])),
                        ("color", &rgba(p.color)),
                    ],
                ));
            }
            taps = &[];
        }
    }
    for t in taps {
        below.push(lang.tr_with(
            "texel_view.tap",
            &[
                ("level", &t.level),
                ("i", &t.i),
                ("j", &t.j),
                ("w", &n(t.weight)),
                ("color", &rgba(t.texel)),
            ],
        ));
    }
    below.push(lang.tr_with("texel_view.color", &[("color", &rgba(color))]));
    [v, below]
}

/// The line under the level-of-detail view for `pixel` with level of detail `lambda` (NaN:
/// no triangle wrote it) in a texture of `levels` levels.
pub fn lod_line(lang: Lang, pixel: [u32; 2], lambda: f32, levels: u32) -> String {
    let (x, y) = (&pixel[0], &pixel[1]);
    if lambda.is_nan() {
        return lang.tr_with("texel_view.lod_none", &[("x", x), ("y", y)]);
    }
    if lambda <= 0.0 {
        return lang.tr_with(
            "texel_view.lod_magnified",
            &[("x", x), ("y", y), ("lambda", &n(lambda))],
        );
    }
    let level = crate::figure::lod_view::level_of(lambda, levels.saturating_sub(1));
    lang.tr_with(
        "texel_view.lod_pixel",
        &[
            ("x", x),
            ("y", y),
            ("lambda", &n(lambda)),
            ("level", &level),
        ],
    )
}
