//! The sample point: the pixel centre in window coordinates, NDC and fixed point.

use super::*;

pub(super) fn sample_section(b: &mut Builder, trace: &PixelTrace) {
    let [x, y] = trace.pixel;
    let [w, h] = trace.image_size;
    let s = &trace.sample;
    b.section(tr!(b, "probe.sample.title"));
    b.text(tr!(b, "probe.sample.intro"));
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
    b.text(tr!(b, "probe.sample.ndc"));
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
        t(tr!(b, "probe.sample.fixed", subpixel = s.subpixel)),
        m(vec![
            sym("P"),
            EQ,
            M::Tuple(vec![vec![int(s.fixed[0])], vec![int(s.fixed[1])]]),
        ]),
        t(tr!(b, "probe.period")),
    ]);
}
