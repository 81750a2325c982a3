//! A lesson's texts: every one in English and Simplified Chinese ([`Text`]), written as
//! paragraphs separated by a blank line with `**bold**` spans ([`blocks`]); formulas are
//! plain Unicode (`W_P = 1 / (r/W_A + s/W_B + t/W_C)`), the same in both languages.

use serde::{Deserialize, Serialize};

use crate::i18n::Lang;

/// A text in both languages. In a lesson file: `{"en": "...", "zh": "..."}`; both are
/// required and neither may be empty.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(try_from = "RawText")]
pub struct Text {
    /// English.
    pub en: String,
    /// Simplified Chinese.
    pub zh: String,
}

/// A text as written, checked into a [`Text`].
#[derive(Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a text in both languages: {\"en\": ..., \"zh\": ...}"
)]
struct RawText {
    en: String,
    zh: String,
}

impl TryFrom<RawText> for Text {
    type Error = String;

    fn try_from(raw: RawText) -> Result<Self, Self::Error> {
        for (code, s) in [("en", &raw.en), ("zh", &raw.zh)] {
            if s.trim().is_empty() {
                return Err(format!("the `{code}` text is empty"));
            }
        }
        Ok(Text {
            en: raw.en,
            zh: raw.zh,
        })
    }
}

impl Text {
    /// The text in `lang`.
    pub fn get(&self, lang: Lang) -> &str {
        match lang {
            Lang::En => &self.en,
            Lang::Zh => &self.zh,
        }
    }
}

/// A run of a paragraph, bold or not.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Span {
    /// The words.
    pub text: String,
    /// Written between `**` and `**`.
    pub bold: bool,
}

/// A block of a text: a paragraph of spans, or a formula block shown line by line in a
/// monospace font.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Block {
    /// Prose: the lines of the block joined, with its bold spans.
    Paragraph(Vec<Span>),
    /// Lines that each started with four spaces (a matrix, a line of code), without them.
    Formula(Vec<String>),
}

/// Splits a text into blocks separated by blank lines. A block whose lines all start with
/// four spaces is a [`Block::Formula`], kept line by line. Otherwise its lines are joined
/// with a space (with nothing between two CJK characters) and split into plain and
/// `**bold**` spans; an unmatched `**` stays as written.
///
/// ```
/// use barylab::lesson::text::{blocks, Block, Span};
/// let b = blocks("One **two**\nthree.\n\n    [1 0]\n    [0 1]");
/// let Block::Paragraph(p) = &b[0] else { panic!() };
/// assert_eq!(p[1], Span { text: "two".into(), bold: true });
/// assert_eq!(p[2].text, " three.");
/// assert_eq!(b[1], Block::Formula(vec!["[1 0]".into(), "[0 1]".into()]));
/// ```
pub fn blocks(text: &str) -> Vec<Block> {
    let mut out = Vec::new();
    for block in text.split("\n\n") {
        let lines: Vec<&str> = block.lines().filter(|l| !l.trim().is_empty()).collect();
        if lines.is_empty() {
            continue;
        }
        if lines.iter().all(|l| l.starts_with("    ")) {
            out.push(Block::Formula(
                lines
                    .iter()
                    .map(|l| l[4..].trim_end().to_string())
                    .collect(),
            ));
            continue;
        }
        let mut joined = String::new();
        for line in lines.iter().map(|l| l.trim()) {
            let cjk_join = joined.chars().last().is_some_and(is_cjk)
                && line.chars().next().is_some_and(is_cjk);
            if !joined.is_empty() && !cjk_join {
                joined.push(' ');
            }
            joined.push_str(line);
        }
        out.push(Block::Paragraph(spans(&joined)));
    }
    out
}

/// The text without markup: paragraphs joined, bold markers dropped, formula lines kept.
pub fn plain(text: &str) -> String {
    blocks(text)
        .iter()
        .map(|b| match b {
            Block::Paragraph(p) => p.iter().map(|s| s.text.as_str()).collect::<String>(),
            Block::Formula(lines) => lines.join("\n"),
        })
        .collect::<Vec<_>>()
        .join("\n\n")
}

/// Whether `c` is a CJK ideograph or CJK punctuation (no space between two of them).
fn is_cjk(c: char) -> bool {
    matches!(c, '\u{3000}'..='\u{30ff}' | '\u{3400}'..='\u{9fff}' | '\u{ff00}'..='\u{ffef}')
}

/// The `**bold**` spans of one paragraph.
fn spans(p: &str) -> Vec<Span> {
    let parts: Vec<&str> = p.split("**").collect();
    // An odd number of markers: the last one is unmatched and stays as text.
    let pairs = (parts.len() - 1) / 2 * 2;
    let mut out: Vec<Span> = Vec::new();
    for (i, part) in parts.iter().enumerate() {
        let (text, bold) = if i > pairs {
            (format!("**{part}"), false)
        } else {
            (part.to_string(), i % 2 == 1)
        };
        if text.is_empty() {
            continue;
        }
        match out.last_mut() {
            Some(last) if last.bold == bold => last.text.push_str(&text),
            _ => out.push(Span { text, bold }),
        }
    }
    out
}

/// The text as Markdown: paragraphs separated by blank lines, bold kept as `**...**`,
/// characters Markdown would read as markup (`*` alone, `_`, `` ` ``, `[`, `<`, `$`, `#` at
/// a line start) escaped, so formulas such as `W_P` and `a*b` print as written; a formula
/// block becomes a fenced code block.
///
/// ```
/// use barylab::lesson::text::markdown;
/// assert_eq!(markdown("**W_P** = 1/w"), "**W\\_P** = 1/w\n");
/// ```
pub fn markdown(text: &str) -> String {
    blocks(text)
        .iter()
        .map(|b| match b {
            Block::Formula(lines) => format!("```\n{}\n```\n", lines.join("\n")),
            Block::Paragraph(p) => {
                let body: String = p
                    .iter()
                    .map(|s| {
                        let e = escape(&s.text);
                        if s.bold {
                            // Markdown bold must not start or end with a space.
                            let lead = &e[..e.len() - e.trim_start().len()];
                            let tail = &e[e.trim_end().len()..];
                            format!("{lead}**{}**{tail}", e.trim())
                        } else {
                            e
                        }
                    })
                    .collect();
                format!("{body}\n")
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// Escapes Markdown's markup characters in plain text.
fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for (i, c) in s.chars().enumerate() {
        match c {
            '\\' | '*' | '_' | '`' | '[' | ']' | '<' | '>' | '|' | '$' => {
                out.push('\\');
                out.push(c);
            }
            '#' if i == 0 => out.push_str("\\#"),
            _ => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chinese_lines_join_without_a_space() {
        assert_eq!(plain("重心\n坐标 r\ns"), "重心坐标 r s");
    }

    #[test]
    fn an_unmatched_marker_stays() {
        let b = blocks("a ** b **c** d");
        let Block::Paragraph(p) = &b[0] else {
            panic!("{b:?}")
        };
        assert_eq!(plain("a ** b **c** d"), "a  b c** d");
        assert!(p[1].bold, "{p:?}");
    }
}
