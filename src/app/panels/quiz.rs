//! The quiz: the class predicts the pinned pixel's r, s, t, a, b, c, 1/W_P or uv before
//! seeing them. A lesson step with a `quiz` starts one; Q starts or ends one on any pinned
//! pixel. Until Reveal the pixel's numbers are hidden everywhere ([`hidden_pixel`]: the
//! inspector shows a note instead; in presentation mode this panel takes the card's place);
//! Reveal shows the answer, the difference per number and the diagnosis of a wrong answer
//! ([`crate::probe::quiz`], which computes every number from the probe).

use egui::{Color32, RichText, Ui};

use crate::app::BaryApp;
use crate::app::command::{AppCommand, QuizCommand};
use crate::app::panels::canvas_layout::Framing;
use crate::app::services::pixel::PixelReport;
use crate::i18n::Lang;
use crate::probe::quiz::{self, Quantity, Question, TOLERANCE, Verdict};

/// The app's quiz part.
#[derive(Debug, Default)]
pub struct Quiz {
    /// The quiz going on.
    pub session: Option<QuizSession>,
    /// The lesson step whose quiz was ended with Q (it does not start again on that step).
    dismissed: Option<usize>,
    /// Predictions to type into the first quiz and reveal (`--quiz-answers`).
    pub answers: Option<Vec<String>>,
    /// Where the quiz's column (or window) was laid out last (for tests:
    /// `BaryApp::quiz_rect`).
    pub column: Option<egui::Rect>,
    /// This frame the quiz is a window, the canvas having no room for its column.
    floating: bool,
}

/// A quiz going on: its question, what the class typed, and whether it is revealed.
#[derive(Clone, Debug, PartialEq)]
pub struct QuizSession {
    /// The pixel and what is asked (the pixel follows the pin).
    pub question: Question,
    /// The typed text, per quantity asked, per number.
    pub fields: Vec<Vec<String>>,
    /// The answer is shown.
    pub revealed: bool,
    /// The lesson step whose quiz this is; `None`: started with Q.
    step: Option<usize>,
}

impl QuizSession {
    fn new(question: Question, step: Option<usize>) -> Self {
        let fields = question
            .ask
            .iter()
            .map(|q| vec![String::new(); q.symbols().len()])
            .collect();
        Self {
            question,
            fields,
            revealed: false,
            step,
        }
    }
}

/// What Q asks about a pinned pixel: every quantity.
const ASK_ALL: [Quantity; 4] = Quantity::ALL;

impl Quiz {
    /// The pixel whose numbers are hidden: the quiz's, until Reveal.
    pub fn hidden(&self) -> Option<[u32; 2]> {
        self.session
            .as_ref()
            .filter(|s| !s.revealed)
            .map(|s| s.question.pixel)
    }

    /// Follows the lesson and the pin, once per frame before the panels: a step with a quiz
    /// starts it (a step without one ends a step's quiz); a pin moved elsewhere moves the
    /// quiz there, with empty fields. `step`: the lesson's current step and its quiz.
    pub fn sync(&mut self, step: Option<(usize, Option<Question>)>, pinned: Option<[u32; 2]>) {
        let current = step.as_ref().map(|s| s.0);
        if self.dismissed.is_some() && self.dismissed != current {
            self.dismissed = None;
        }
        if let Some(s) = &self.session
            && s.step.is_some()
            && s.step != current
        {
            self.session = None;
        }
        if let Some((n, Some(q))) = step
            && self.session.is_none()
            && self.dismissed != Some(n)
        {
            self.session = Some(QuizSession::new(q, Some(n)));
        }
        if let (Some(s), Some(p)) = (&mut self.session, pinned)
            && s.question.pixel != p
        {
            *s = QuizSession::new(
                Question {
                    pixel: p,
                    ask: s.question.ask.clone(),
                },
                s.step,
            );
        }
        if self.answers.is_some() && self.session.is_none() && pinned.is_some() {
            self.apply(QuizCommand::Toggle, pinned, current);
        }
        if let (Some(s), Some(answers)) = (&mut self.session, self.answers.take()) {
            let mut typed = answers.into_iter();
            for f in s.fields.iter_mut().flatten() {
                *f = typed.next().unwrap_or_default();
            }
            s.revealed = true;
        }
    }

    /// Applies a quiz command; `pinned`: the pinned pixel, `step`: the lesson's step.
    pub fn apply(&mut self, c: QuizCommand, pinned: Option<[u32; 2]>, step: Option<usize>) {
        match c {
            QuizCommand::Toggle => {
                if self.session.take().is_some() {
                    self.dismissed = step;
                } else if let Some(pixel) = pinned {
                    self.dismissed = None;
                    let question = Question {
                        pixel,
                        ask: ASK_ALL.to_vec(),
                    };
                    self.session = Some(QuizSession::new(question, None));
                }
            }
            QuizCommand::Edit { part, index, text } => {
                if let Some(f) = self
                    .session
                    .as_mut()
                    .and_then(|s| s.fields.get_mut(part))
                    .and_then(|f| f.get_mut(index))
                {
                    *f = text;
                }
            }
            QuizCommand::Reveal(on) => {
                if let Some(s) = &mut self.session {
                    s.revealed = on;
                }
            }
        }
    }
}

fn id() -> egui::Id {
    egui::Id::unique("barylab-quiz-hidden")
}

/// The pixel whose numbers the panels hide this frame (set by the app before the panels).
pub fn hidden_pixel(ctx: &egui::Context) -> Option<[u32; 2]> {
    ctx.data(|d| d.get_temp::<Option<[u32; 2]>>(id())).flatten()
}

/// Makes `pixel` the one whose numbers the panels hide.
pub fn set_hidden_pixel(ctx: &egui::Context, pixel: Option<[u32; 2]>) {
    ctx.data_mut(|d| d.insert_temp(id(), pixel));
}

/// The note shown where a hidden pixel's numbers would be.
pub fn hidden_note(lang: Lang, [x, y]: [u32; 2]) -> String {
    lang.tr_with("quiz.hidden", &[("x", &x), ("y", &y)])
}

/// Width of a symbol's character (monospace, strong) in text heights, to share a row
/// between the fields.
const SYMBOL_EMS: f32 = 0.7;

/// Colours of a verdict.
const RIGHT: Color32 = Color32::from_rgb(60, 170, 90);
const WRONG: Color32 = Color32::from_rgb(220, 80, 60);

/// The quiz's contents: the question, a field per number, Reveal; once revealed, per
/// quantity the answer, the prediction, the difference and the diagnosis. `pinned`: the
/// pinned pixel's report (the answer comes from its trace).
pub fn quiz_ui(
    ui: &mut Ui,
    session: &QuizSession,
    pinned: Option<&PixelReport>,
    lang: Lang,
    closable: bool,
) -> Vec<QuizCommand> {
    let mut out = Vec::new();
    let [x, y] = session.question.pixel;
    // Larger in the presentation's column; beside the canvas, where the room is short, the
    // body size keeps it to one line.
    let prompt = RichText::new(lang.tr_with("quiz.prompt", &[("x", &x), ("y", &y)])).strong();
    ui.label(if closable {
        prompt
    } else {
        prompt.size(ui.text_style_height(&egui::TextStyle::Body) * 1.15)
    });
    let report = pinned.filter(|r| r.pixel == session.question.pixel);
    let key = report.map(|r| quiz::key(&r.trace, &session.question.ask));
    let h = ui.text_style_height(&egui::TextStyle::Body);
    // Once revealed, the table shows what was typed: the fields make room for it.
    let asking = if session.revealed {
        &[][..]
    } else {
        &session.question.ask[..]
    };
    for (part, q) in asking.iter().enumerate() {
        ui.add_space(4.0);
        let symbols = q.symbols();
        if !named_by_its_symbol(*q, lang) {
            ui.label(q.name(lang));
        }
        // One row of "symbol [field]" pairs, the fields sharing the width left.
        let n = symbols.len() as f32;
        let names: f32 = symbols
            .iter()
            .map(|s| s.len() as f32 * SYMBOL_EMS * h)
            .sum();
        let gaps = 2.0 * n * ui.spacing().item_spacing.x + n * ui.spacing().button_padding.x * 2.0;
        let field_width = ((ui.available_width() - names - gaps) / n).clamp(2.5 * h, 6.0 * h);
        ui.horizontal(|ui| {
            for (index, symbol) in symbols.iter().enumerate() {
                ui.label(RichText::new(*symbol).monospace().strong());
                let mut text = session.fields[part][index].clone();
                let edit = egui::TextEdit::singleline(&mut text)
                    .desired_width(field_width)
                    .id_salt(("quiz-field", part, index))
                    .hint_text("?");
                let r = ui.add(edit);
                if r.changed() {
                    out.push(QuizCommand::Edit { part, index, text });
                }
                // Enter in a field reveals (the field gives the keyboard back, so Page Down
                // goes on to the next step again).
                if r.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) {
                    out.push(QuizCommand::Reveal(true));
                }
            }
        });
    }
    ui.add_space(6.0);
    let label = if session.revealed {
        lang.tr("quiz.again")
    } else {
        lang.tr("quiz.reveal")
    };
    ui.horizontal_wrapped(|ui| {
        if ui.button(RichText::new(label).strong()).clicked() {
            out.push(QuizCommand::Reveal(!session.revealed));
        }
        // (A window's close button, where the quiz is not in a window.)
        if closable
            && ui
                .button(lang.tr("quiz.stop"))
                .on_hover_text(lang.tr("quiz.keys"))
                .clicked()
        {
            out.push(QuizCommand::Toggle);
        }
    });
    if !session.revealed {
        return out;
    }
    ui.separator();
    match key {
        None => {
            ui.label(lang.tr("quiz.need_pin"));
        }
        Some(Err(e)) => {
            ui.colored_label(WRONG, e.message(lang));
        }
        Some(Ok(key)) => {
            for (part, expected) in key.iter().enumerate() {
                let typed = &session.fields[part];
                let given: Option<Result<Vec<f64>, String>> =
                    (!typed.iter().all(|t| t.trim().is_empty())).then(|| {
                        typed
                            .iter()
                            .map(|t| {
                                quiz::parse_number(t).ok_or_else(|| {
                                    lang.tr_with("quiz.not_a_number", &[("text", &t.trim())])
                                })
                            })
                            .collect()
                    });
                let verdict = match &given {
                    Some(Ok(g)) => Some(expected.check(g)),
                    _ => None,
                };
                verdict_ui(
                    ui,
                    (part, expected.quantity),
                    &expected.values,
                    &verdict,
                    lang,
                );
                match given {
                    None => {
                        ui.label(lang.tr("quiz.no_answer"));
                    }
                    Some(Err(e)) => {
                        ui.colored_label(WRONG, e);
                    }
                    Some(Ok(_)) => {}
                }
                ui.add_space(6.0);
            }
        }
    }
    out
}

/// Whether `q` is one number whose name is its symbol (1/W_P): its name is written once.
fn named_by_its_symbol(q: Quantity, lang: Lang) -> bool {
    q.symbols() == [q.name(lang).as_str()]
}

/// One quantity's answer, prediction and difference as a table, then the verdict and its
/// diagnosis.
fn verdict_ui(
    ui: &mut Ui,
    (part, quantity): (usize, Quantity),
    answer: &[f64],
    verdict: &Option<Verdict>,
    lang: Lang,
) {
    ui.label(RichText::new(quantity.name(lang)).strong());
    let mono = |s: String| RichText::new(s).monospace();
    // A row per number (symbol, answer, prediction, difference): as narrow for three numbers
    // as for one.
    egui::Grid::new(("quiz-verdict", part))
        .num_columns(4)
        .min_col_width(0.0)
        .spacing([10.0, 2.0])
        .show(ui, |ui| {
            ui.label("");
            ui.label(lang.tr("quiz.answer"));
            if verdict.is_some() {
                ui.label(lang.tr("quiz.yours"));
                ui.label(lang.tr("quiz.off_by"));
            }
            ui.end_row();
            // The name above is the symbol (1/W_P): not written again, so that the table fits
            // a narrow column.
            let named = named_by_its_symbol(quantity, lang);
            for (i, (s, a)) in quantity.symbols().iter().zip(answer).enumerate() {
                ui.label(
                    mono(if named {
                        String::new()
                    } else {
                        (*s).to_string()
                    })
                    .strong(),
                );
                ui.label(mono(format!("{a:.4}")).strong());
                if let Some(v) = verdict {
                    let g = v.given.get(i).copied().unwrap_or(f64::NAN);
                    // (No "-0.0000": a difference that rounds to zero is shown as +0.0000.)
                    let d = v.differences.get(i).copied().unwrap_or(f64::NAN);
                    let d = if d.abs() < 5e-5 { 0.0 } else { d };
                    ui.label(mono(format!("{g:.4}")));
                    let colour = if d.abs() <= TOLERANCE { RIGHT } else { WRONG };
                    ui.label(mono(format!("{d:+.4}")).color(colour));
                }
                ui.end_row();
            }
        });
    let Some(v) = verdict else {
        return;
    };
    if v.correct {
        let tol = TOLERANCE.to_string();
        ui.colored_label(RIGHT, lang.tr_with("quiz.correct", &[("tol", &tol)]));
        return;
    }
    ui.colored_label(WRONG, RichText::new(lang.tr("quiz.wrong")).strong());
    match v.diagnosis {
        Some(m) => {
            ui.label(
                RichText::new(lang.tr_with("quiz.diagnosis", &[("name", &m.name(lang))])).strong(),
            );
            ui.label(m.explain(lang));
        }
        None => {
            ui.label(lang.tr("quiz.no_match"));
        }
    }
}

/// Share of the width the quiz column takes, and its least and largest width in points:
/// presenting (the card's place, the whole window's width shared) and outside presentation
/// mode (the canvas's width shared; the quiz's fields share the column's width).
const COLUMN_SHARE: f32 = 0.45;
const COLUMN_WIDTH: (f32, f32) = (270.0, 480.0);
const DOCKED_SHARE: f32 = 0.45;
const DOCKED_WIDTH: (f32, f32) = (260.0, 400.0);
/// Points: the quiz window's distance from the canvas's edges.
const WINDOW_MARGIN: f32 = 12.0;

impl BaryApp {
    /// Presentation mode during a quiz: the quiz in a column right of the picture, in the
    /// card's place (the card would show the numbers).
    pub(in crate::app) fn quiz_presenting(
        &mut self,
        ui: &mut Ui,
        texture: &std::sync::Arc<crate::raster::Texture>,
        out: &mut Vec<AppCommand>,
    ) {
        let width = (COLUMN_SHARE * ui.available_width()).clamp(COLUMN_WIDTH.0, COLUMN_WIDTH.1);
        self.quiz_column(ui, width, false, out);
        // Nothing lies over the picture (the card's corner of the last frame is gone).
        self.canvas.avoid.clear();
        let framing = Framing::presenting(self.state.view.compare);
        self.canvas_panel(ui, texture, framing, out);
    }

    /// The quiz outside presentation mode: a column at the canvas's right, beside the side
    /// panels, so that it never lies over the picture, its corners' labels or the Lessons
    /// panel (a window over the canvas had no room beside the picture at 1024x768 with text
    /// size 1.5, and covered it). With a close button, as the window had.
    /// Where the side panels leave the canvas too little room for a column
    /// ([`CANVAS_BESIDE_COLUMN`](crate::app::side_panels::CANVAS_BESIDE_COLUMN)), the quiz
    /// is a window over the canvas instead ([`Self::quiz_window`]).
    pub(in crate::app) fn quiz_docked(&mut self, ui: &mut Ui, out: &mut Vec<AppCommand>) {
        self.quiz.floating = false;
        if self.quiz.session.is_none() {
            return;
        }
        let room = ui.available_width();
        let width = (DOCKED_SHARE * room).clamp(DOCKED_WIDTH.0, DOCKED_WIDTH.1);
        if room - width < crate::app::side_panels::CANVAS_BESIDE_COLUMN {
            self.quiz.floating = true;
            return;
        }
        self.quiz_column(ui, width, true, out);
    }

    /// The quiz in a window in the canvas's top-left corner, when the side panels leave no
    /// room for its column ([`Self::quiz_docked`]): it can be moved, and it is never taller
    /// than the canvas (it scrolls), so it does not reach over the Lessons panel.
    pub(in crate::app) fn quiz_window(&mut self, ctx: &egui::Context, out: &mut Vec<AppCommand>) {
        let lang = self.lang();
        let (Some(session), true) = (&self.quiz.session, self.quiz.floating) else {
            return;
        };
        let Some(area) = self.canvas.area else {
            return;
        };
        let mut open = true;
        let shown = egui::Window::new(lang.tr("quiz.title"))
            .id(egui::Id::unique("quiz-window"))
            .open(&mut open)
            .default_pos(area.min + egui::vec2(WINDOW_MARGIN, WINDOW_MARGIN))
            .default_width(DOCKED_WIDTH.0)
            .show(ctx, |ui| {
                // Its title bar takes about one interaction height.
                let title = ui.spacing().interact_size.y + 2.0 * WINDOW_MARGIN;
                egui::ScrollArea::vertical()
                    .max_height((area.height() - 2.0 * WINDOW_MARGIN - title).max(0.0))
                    .auto_shrink([false, true])
                    .show(ui, |ui| {
                        out.extend(
                            quiz_ui(ui, session, self.reports.pin.as_ref(), lang, true)
                                .into_iter()
                                .map(Into::into),
                        );
                    });
            });
        self.quiz.column = shown.map(|s| s.response.rect);
        if !open {
            out.push(QuizCommand::Toggle.into());
        }
    }

    /// The quiz in a right-hand column `width` points wide (scrolling when taller than the
    /// room), with a close button when `closable`.
    fn quiz_column(&mut self, ui: &mut Ui, width: f32, closable: bool, out: &mut Vec<AppCommand>) {
        let lang = self.lang();
        let Some(session) = &self.quiz.session else {
            return;
        };
        let pinned = self.reports.pin.as_ref();
        let shown = egui::Panel::right(COLUMN_ID)
            .frame(
                egui::Frame::side_top_panel(ui.style())
                    .inner_margin(egui::Margin::symmetric(14, 10)),
            )
            .resizable(false)
            .exact_size(width)
            .show(ui, |ui| {
                egui::ScrollArea::vertical()
                    .auto_shrink([false, false])
                    .show(ui, |ui| {
                        // Lines wrap at the column's width; nothing widens it.
                        ui.set_max_width(ui.available_width());
                        // A room reads the quiz: its text in the strong colour (the usual
                        // grey was faint on a projector).
                        let strong = ui.visuals().strong_text_color();
                        ui.visuals_mut().override_text_color = Some(strong);
                        // Beside the canvas the room is short (a Lessons panel below): no
                        // heading (the prompt says it), the keys in End the quiz's tip.
                        if !closable {
                            ui.heading(lang.tr("quiz.title"));
                        }
                        out.extend(
                            quiz_ui(ui, session, pinned, lang, closable)
                                .into_iter()
                                .map(Into::into),
                        );
                        if !closable {
                            ui.add_space(8.0);
                            ui.label(RichText::new(lang.tr("quiz.keys")).small().weak());
                        }
                    });
            });
        self.quiz.column = Some(shown.response.rect);
    }
}

/// The quiz column's panel id.
const COLUMN_ID: &str = "quiz-column";
