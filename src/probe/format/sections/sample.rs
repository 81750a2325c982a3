//! The sample point: the pixel centre in window coordinates, NDC and fixed point.

use super::*;

pub(super) fn sample_section(b: &mut Builder, trace: &PixelTrace) {
    let [x, y] = trace.pixel;
    let [w, h] = trace.image_size;
    let s = &trace.sample;
    b.section("The sample point");
    b.text(
        "A pixel is sampled at its centre. Window coordinates are in pixels, x to the right, \
         y down from the top row:",
    );
    b.eq(vec![
        sym("x_P"),
        EQ,
        int(x.into()),
        PLUS,
        num(0.5),
        EQ,
        num(s.window[0]),
        SEP,
        sym("y_P"),
        EQ,
        int(y.into()),
        PLUS,
        num(0.5),
        EQ,
        num(s.window[1]),
    ]);
    b.text("In normalized device coordinates (NDC y = +1 is the top row):");
    b.eq(vec![
        sym("x_ndc"),
        EQ,
        frac(vec![int(2), MUL, num(s.window[0])], int(w.into())),
        MINUS,
        int(1),
        EQ,
        num(s.ndc[0]),
        SEP,
        sym("y_ndc"),
        EQ,
        int(1),
        MINUS,
        frac(vec![int(2), MUL, num(s.window[1])], int(h.into())),
        EQ,
        num(s.ndc[1]),
    ]);
    b.para(vec![
        t(format!(
            "The rasterizer works in exact integers of 1/{} pixel: ",
            s.subpixel
        )),
        m(vec![
            sym("P"),
            EQ,
            M::Tuple(vec![vec![int(s.fixed[0])], vec![int(s.fixed[1])]]),
        ]),
        t("."),
    ]);
}
