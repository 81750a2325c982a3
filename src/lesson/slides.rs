//! A lesson as a slide deck: one self-contained HTML file ([`html`]) for a projector, or the
//! Markdown that pandoc turns into a Beamer PDF ([`beamer`]).
//!
//! The HTML needs no network: the figures and row plots are PNG `data:` URIs, the formulas
//! are the lessons' own plain Unicode (a formula block is kept line by line in a monospace
//! block, as the app shows it), the style and the few lines of script are inline. A title
//! slide, then one slide per step: its title, summary, text and "try this" beside its figure
//! and row plot (the handout's pictures, [`super::handout::step_pictures`]); a step with an
//! `animation` shows it in place of the still figure, as a small looping GIF or APNG `data:` URI
//! ([`step_animation`]; the Beamer PDF keeps the still). The arrow keys,
//! Page Up / Page Down (what a presentation clicker sends), the space bar, Enter, Backspace,
//! Home and End step through it; a click on the right (left) half goes forward (back); the
//! address's `#N` is the slide shown. Printed, every slide is a page.

use base64::Engine;

use super::handout::{self, HandoutError, HandoutFile, step_pictures, step_state, texture_of};
use super::text::{self, Block};
use super::{Lesson, Step, StepAnimation, StepState};
use crate::animate;
use crate::figure::svg::escape;
use crate::i18n::{Lang, tr};
use crate::raster::Texture;

/// A lesson text as HTML: paragraphs with `<strong>` spans, formula blocks as `<pre>`.
pub fn text_html(s: &str) -> String {
    text::blocks(s)
        .iter()
        .map(|b| match b {
            Block::Formula(lines) => {
                format!(
                    "<pre class=\"formula\">{}</pre>\n",
                    escape(&lines.join("\n"))
                )
            }
            Block::Paragraph(spans) => {
                let body: String = spans
                    .iter()
                    .map(|s| match s.bold {
                        true => format!("<strong>{}</strong>", escape(&s.text)),
                        false => escape(&s.text),
                    })
                    .collect();
                format!("<p>{body}</p>\n")
            }
        })
        .collect()
}

/// A PNG as a `data:` URI.
fn png_uri(bytes: &[u8]) -> String {
    format!(
        "data:image/png;base64,{}",
        base64::engine::general_purpose::STANDARD.encode(bytes)
    )
}

/// The deck's style: one slide on the screen at a time (all of them without script, and in
/// print), text left and pictures right, sized to the window.
const STYLE: &str = r#"
html, body { margin: 0; height: 100%; background: #1e2026; color: #eceff4;
  font-family: "Noto Sans", "Noto Sans CJK SC", "Source Han Sans SC", "Microsoft YaHei", sans-serif; }
.slide { box-sizing: border-box; width: 100vw; min-height: 100vh; padding: 3vh 4vw;
  display: flex; flex-direction: column; gap: 2vh; border-bottom: 1px solid #444; }
.js .slide { display: none; height: 100vh; overflow: hidden; border: 0; }
.js .slide.current { display: flex; }
h1 { font-size: 5vh; margin: auto 0 1vh 0; }
h2 { font-size: 4vh; margin: 0; }
.title .sub { font-size: 2.6vh; color: #aab; margin-bottom: auto; }
.summary { font-size: 2.6vh; color: #ffd58a; margin: 0; }
.body { display: flex; gap: 3vw; flex: 1; min-height: 0; }
.text { flex: 1 1 40%; font-size: 2.3vh; line-height: 1.45; overflow: auto; }
.text p { margin: 0 0 1.2vh 0; }
.try { color: #9fd3ff; }
pre.formula { font-size: 2.1vh; background: #2a2d36; padding: 1vh 1vw; border-radius: 4px;
  white-space: pre-wrap; }
.pictures { flex: 1 1 60%; display: flex; flex-direction: column; gap: 1vh; min-height: 0;
  align-items: center; justify-content: center; }
.pictures img { max-width: 100%; min-height: 0; object-fit: contain; background: #fff; }
.pictures img.figure { max-height: 70vh; }
.pictures img.plot { max-height: 24vh; }
#counter { position: fixed; right: 1.5vw; bottom: 1vh; font-size: 1.8vh; color: #889; }
@media print {
  .js .slide, .slide { display: flex; height: auto; min-height: 0; page-break-after: always; }
  #counter { display: none; }
}
"#;

/// The deck's script: the keys and clicks that step through it.
const SCRIPT: &str = r#"
(function () {
  document.documentElement.classList.add('js');
  var slides = document.querySelectorAll('.slide');
  var counter = document.getElementById('counter');
  var at = 0;
  function show(n) {
    at = Math.max(0, Math.min(slides.length - 1, n));
    for (var i = 0; i < slides.length; i++) slides[i].classList.toggle('current', i === at);
    counter.textContent = (at + 1) + ' / ' + slides.length;
    if (location.hash !== '#' + (at + 1)) history.replaceState(null, '', '#' + (at + 1));
  }
  var forward = ['ArrowRight', 'ArrowDown', 'PageDown', ' ', 'Spacebar', 'Enter', 'n'];
  var back = ['ArrowLeft', 'ArrowUp', 'PageUp', 'Backspace', 'p'];
  document.addEventListener('keydown', function (e) {
    if (forward.indexOf(e.key) >= 0) { show(at + 1); e.preventDefault(); }
    else if (back.indexOf(e.key) >= 0) { show(at - 1); e.preventDefault(); }
    else if (e.key === 'Home') { show(0); e.preventDefault(); }
    else if (e.key === 'End') { show(slides.length - 1); e.preventDefault(); }
  });
  document.addEventListener('click', function (e) {
    show(e.clientX > window.innerWidth / 2 ? at + 1 : at - 1);
  });
  window.addEventListener('hashchange', function () {
    show((parseInt(location.hash.slice(1), 10) || 1) - 1);
  });
  show((parseInt(location.hash.slice(1), 10) || 1) - 1);
})();
"#;

/// Frames per second of a slide's animation.
pub const SLIDE_FPS: f64 = 5.0;

/// A step's animation as a GIF (one palette) or an APNG, looping: its sweep of the step's
/// scene, every frame drawn with the step's figure options
/// ([`crate::animate::render_frames`]).
pub fn step_animation(
    state: &StepState,
    texture: &Texture,
    animation: &StepAnimation,
    number: usize,
    lang: Lang,
) -> Result<Vec<u8>, HandoutError> {
    let error = |error| HandoutError::Animation {
        step: number,
        error,
    };
    let anim = animate::Animation {
        sweep: animation.sweep,
        frames: animation.frames,
        vertex: animation.vertex,
        options: state.figure_options(),
    };
    let frames = animate::render_frames(&state.scene, texture, &anim, lang).map_err(error)?;
    animate::encode(&frames, SLIDE_FPS, animation.format).map_err(error)
}

/// One step's slide.
fn step_slide(
    lesson: &Lesson,
    step: &Step,
    number: usize,
    lang: Lang,
) -> Result<String, HandoutError> {
    let state = step_state(lesson, number)?;
    let texture = texture_of(&state, number)?;
    let pictures = step_pictures(&state, &texture, number, lang)?;
    let title = text::plain(step.title.get(lang));
    let mut s = format!(
        "<section class=\"slide\" id=\"step-{number}\">\n<h2>{number}. {}</h2>\n",
        escape(&title)
    );
    if let Some(summary) = &step.summary {
        s.push_str(&format!(
            "<p class=\"summary\">{}</p>\n",
            escape(&text::plain(summary.get(lang)))
        ));
    }
    s.push_str("<div class=\"body\"><div class=\"text\">\n");
    s.push_str(&text_html(step.text.get(lang)));
    s.push_str(&format!(
        "<p class=\"try\"><strong>{}</strong> {}</p>\n",
        escape(&tr(lang, "lesson.try_this")),
        escape(&text::plain(step.try_this.get(lang)))
    ));
    s.push_str("</div><div class=\"pictures\">\n");
    let figure = match &step.animation {
        Some(a) => {
            let bytes = step_animation(&state, &texture, a, number, lang)?;
            let mime = match a.format {
                animate::Format::Gif => "gif",
                _ => "png",
            };
            format!(
                "data:image/{mime};base64,{}",
                base64::engine::general_purpose::STANDARD.encode(bytes)
            )
        }
        None => png_uri(&pictures.figure),
    };
    s.push_str(&format!(
        "<img class=\"figure\" alt=\"{}\" src=\"{figure}\">\n",
        escape(&title),
    ));
    if let Some((plot_title, bytes)) = &pictures.plot {
        s.push_str(&format!(
            "<img class=\"plot\" alt=\"{}\" src=\"{}\">\n",
            escape(plot_title),
            png_uri(bytes)
        ));
    }
    s.push_str("</div></div>\n</section>\n");
    Ok(s)
}

/// The lesson as one self-contained HTML slide deck in `lang` (see the module's text).
pub fn html(lesson: &Lesson, lang: Lang) -> Result<String, HandoutError> {
    let title = escape(&text::plain(lesson.title.get(lang)));
    let code = match lang {
        Lang::En => "en",
        Lang::Zh => "zh-CN",
    };
    let mut out = format!(
        "<!DOCTYPE html>\n<html lang=\"{code}\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{title}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n\
         <section class=\"slide title\" id=\"title\">\n<h1>{title}</h1>\n\
         <p class=\"sub\">{}</p>\n</section>\n",
        escape(&lang.tr_with("lesson.slides_steps", &[("n", &lesson.steps.len())]))
    );
    for (i, step) in lesson.steps.iter().enumerate() {
        out.push_str(&step_slide(lesson, step, i + 1, lang)?);
    }
    out.push_str(&format!(
        "<div id=\"counter\"></div>\n<script>{SCRIPT}</script>\n</body>\n</html>\n"
    ));
    Ok(out)
}

/// The name of the Beamer deck's Markdown file among [`beamer`]'s files.
pub const BEAMER_MARKDOWN: &str = "slides.md";

/// The lesson as Markdown for `pandoc -t beamer` (two frames a step: the text, then the
/// figure and plot), first, then the pictures it names (the handout's files).
pub fn beamer(lesson: &Lesson, lang: Lang) -> Result<Vec<HandoutFile>, HandoutError> {
    let mut md = format!(
        "---\ntitle: \"{}\"\n---\n\n",
        text::plain(lesson.title.get(lang)).replace('"', "\\\"")
    );
    let mut files = Vec::new();
    for (i, step) in lesson.steps.iter().enumerate() {
        let number = i + 1;
        let state = step_state(lesson, number)?;
        let texture = texture_of(&state, number)?;
        let pictures = step_pictures(&state, &texture, number, lang)?;
        let title = text::markdown(step.title.get(lang));
        md.push_str(&format!("## {number}. {}\n\n", title.trim()));
        if let Some(summary) = &step.summary {
            md.push_str(&format!(
                "*{}*\n\n",
                text::markdown(summary.get(lang)).trim()
            ));
        }
        md.push_str(&text::markdown(step.text.get(lang)));
        md.push_str(&format!(
            "\n**{}** {}\n\n",
            tr(lang, "lesson.try_this"),
            text::markdown(step.try_this.get(lang)).trim()
        ));
        let figure = handout::figure_name(number);
        md.push_str(&format!(
            "## {number}. {}\n\n![]({figure}){{height=70%}}\n\n",
            title.trim()
        ));
        files.push(HandoutFile {
            name: figure,
            bytes: pictures.figure,
        });
        if let Some((_, bytes)) = pictures.plot {
            let name = handout::plot_name(number);
            md.push_str(&format!("![]({name}){{height=20%}}\n\n"));
            files.push(HandoutFile { name, bytes });
        }
    }
    files.insert(
        0,
        HandoutFile {
            name: BEAMER_MARKDOWN.to_string(),
            bytes: md.into_bytes(),
        },
    );
    Ok(files)
}
