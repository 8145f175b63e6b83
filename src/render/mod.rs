//! Rendering a [`Report`] in four formats: unicode text that reads like the paper, Markdown,
//! a complete LaTeX document, and JSON with a stable schema (see [`json`]).
//!
//! Rendering is deterministic: the only nondeterministic data are timings, which appear only in
//! JSON and in the closing summary line of text and Markdown, and not at all when
//! [`Options::timings`] is off.

pub mod json;
pub mod latex;
pub mod markdown;
pub mod tex;
pub mod text;

use std::fmt;
use std::str::FromStr;

use crate::report::{ClaimResult, Expect, Report};

/// An output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Format {
    /// Unicode text that reads like the paper: `{L, G1} = −G2   [C09 proved]`.
    #[default]
    Text,
    /// Markdown, tables as Markdown tables.
    Markdown,
    /// A complete LaTeX (amsmath) document.
    Latex,
    /// JSON: one object per claim, plus tables, proofs, towers and ranks.
    Json,
}

impl Format {
    /// Every format, in the order `--help` lists them.
    pub const ALL: [Format; 4] = [Format::Text, Format::Markdown, Format::Latex, Format::Json];

    /// The format's name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Format::Text => "text",
            Format::Markdown => "markdown",
            Format::Latex => "latex",
            Format::Json => "json",
        }
    }
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A format by its name (`md` for Markdown too).
///
/// ```
/// use superint::render::{Format, UnknownFormat};
///
/// assert_eq!("json".parse(), Ok(Format::Json));
/// assert_eq!("md".parse::<Format>(), Ok(Format::Markdown));
/// let err = "pdf".parse::<Format>().unwrap_err();
/// assert_eq!(err, UnknownFormat("pdf".into()));
/// assert_eq!(err.to_string(), "unknown format 'pdf' (expected text, markdown, latex or json)");
/// ```
impl FromStr for Format {
    type Err = UnknownFormat;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Format::ALL
            .into_iter()
            .find(|f| f.name() == s || (s == "md" && *f == Format::Markdown))
            .ok_or_else(|| UnknownFormat(s.to_string()))
    }
}

/// A name that is no [`Format`]'s: the name.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown format '{0}' (expected text, markdown, latex or json)")]
pub struct UnknownFormat(pub String);

/// Rendering choices: the defaults ([`Options::default`], or [`Options::reproducible`] without
/// timings), each changed by a method of its name.
///
/// ```
/// use superint::prelude::*;
///
/// let options = RenderOptions::default().timings(false).shown_monomials(Some(10));
/// assert_eq!((options.timings, options.shown_monomials), (false, Some(10)));
/// let everything = RenderOptions::reproducible().shown_monomials(None);
/// assert_eq!(everything, RenderOptions::default().timings(false).shown_monomials(None));
/// ```
///
/// A choice may be added, so a program writes no literal of all of them:
///
/// ```compile_fail,E0639
/// let options = superint::render::Options { timings: false, shown_monomials: None };
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct Options {
    /// Whether to print timings (off makes the output byte-for-byte reproducible).
    pub timings: bool,
    /// The most monomials (outside the angles) of a refuted claim's residual or a table's entry
    /// printed whole: a longer one shows the terms of its first this many and says how many it
    /// has ([`Report::excerpted`]); `None` prints every one, and `Some(0)` is taken as
    /// `Some(1)`.
    pub shown_monomials: Option<usize>,
}

/// The monomials of a residual or a table's entry shown by default: one of a hundred terms
/// reads in full, one of millions (a gigabyte of text) by its leading terms.
pub const SHOWN_MONOMIALS: usize = 100;

impl Default for Options {
    fn default() -> Self {
        Options {
            timings: true,
            shown_monomials: Some(SHOWN_MONOMIALS),
        }
    }
}

impl Options {
    /// The defaults without timings: output that is the same on every run (`--no-timings`).
    pub fn reproducible() -> Self {
        Options::default().timings(false)
    }

    /// The same choices with timings printed or not.
    #[must_use]
    pub fn timings(mut self, timings: bool) -> Self {
        self.timings = timings;
        self
    }

    /// The same choices with at most `monomials` monomials (outside the angles) of a long
    /// expression printed, or with every one (`None`).
    #[must_use]
    pub fn shown_monomials(mut self, monomials: Option<usize>) -> Self {
        self.shown_monomials = monomials;
        self
    }
}

/// Renders a report; the result ends with a newline.
pub fn render(report: &Report, format: Format, options: &Options) -> String {
    let shortened;
    let report = match options.shown_monomials {
        Some(n) => {
            shortened = report.excerpted(n);
            &*shortened
        }
        None => report,
    };
    match format {
        Format::Text => text::render(report, options),
        Format::Markdown => markdown::render(report, options),
        Format::Latex => latex::render(report, options),
        Format::Json => json::render(report, options),
    }
}

/// Text safe to print or write: each control character but newline and tab, and each
/// bidirectional embedding, override or isolate (U+202A–U+202E, U+2066–U+2069), as `�`
/// (U+FFFD). A system file's names, descriptions and ids, and a command line's expressions,
/// may hold escapes such as `\u001b`, which on a terminal would move the cursor, clear the
/// screen or set its title, and in an SVG chart make the file no XML; an override such as
/// U+202E shows the rest of its line turned around (an error's excerpt of the file too).
pub fn printable(text: &str) -> std::borrow::Cow<'_, str> {
    let unsafe_char = |c: char| {
        (c.is_control() && c != '\n' && c != '\t')
            || matches!(c, '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}')
    };
    match text.contains(unsafe_char) {
        false => std::borrow::Cow::Borrowed(text),
        true => text
            .chars()
            .map(|c| if unsafe_char(c) { '\u{fffd}' } else { c })
            .collect::<String>()
            .into(),
    }
}

/// The lines of `out` and then of `last`, each ended by a newline, in a text of just their
/// length: a result printed whole is most of it (635 MB), where joining the lines, then
/// pushing the last newline, copied it into twice its length, and pushing the last lines
/// grew the list of some ten million lines the same way.
pub(crate) fn lines_to_text(out: &[String], last: &[&str]) -> String {
    let all = || out.iter().map(String::as_str).chain(last.iter().copied());
    let mut text = String::with_capacity(all().map(|l| l.len() + 1).sum());
    for line in all() {
        text.push_str(line);
        text.push('\n');
    }
    text
}

/// A table set as a list ([`crate::report::TableResult`] too wide for a line or page): its
/// brackets `(A, B, cell)` above the diagonal that are not zero, the others following by
/// antisymmetry.
pub(crate) fn table_list(cells: &[Vec<String>]) -> Vec<(usize, usize, &str)> {
    let brackets = cells
        .iter()
        .enumerate()
        .flat_map(|(a, row)| {
            row.iter()
                .enumerate()
                .skip(a + 1)
                .map(move |(b, c)| (a, b, c))
        })
        .filter(|(_, _, cell)| *cell != "0")
        .map(|(a, b, cell)| (a, b, cell.as_str()))
        .collect();
    brackets
}

/// Prose markup (formulas between backticks) as plain text.
pub(crate) fn plain(markup: &str) -> String {
    markup.replace('`', "")
}

/// The width of text in a terminal: characters, not counting combining marks. Counted on the
/// bytes, each that starts a character (not `0b10xx_xxxx`), with the characters read only
/// where a combining mark may be: each of U+0300 to U+036F starts with the byte 0xCC or 0xCD
/// (a long result's text is hundreds of megabytes, its lines and words measured as they wrap).
pub(crate) fn width(s: &str) -> usize {
    let bytes = s.as_bytes();
    let characters = bytes.iter().filter(|&&b| b & 0xC0 != 0x80).count();
    match bytes.iter().any(|&b| b == 0xCC || b == 0xCD) {
        false => characters,
        true => characters - s.chars().filter(|&c| tex::is_combining(c)).count(),
    }
}

/// Whether text is wider than `w` ([`width`]), read no further than its `w + 1`-th character.
pub(crate) fn wider_than(s: &str, w: usize) -> bool {
    s.len() > w
        && s.chars()
            .filter(|&c| !tex::is_combining(c))
            .nth(w)
            .is_some()
}

/// Pads to a width (in terminal columns).
pub(crate) fn pad(s: &str, w: usize) -> String {
    let n = width(s);
    if n >= w {
        s.to_string()
    } else {
        format!("{s}{}", " ".repeat(w - n))
    }
}

/// The verdict on a claim, as its tag reads: `proved`, `REFUTED`, and for a claim expected to
/// be refuted `refuted, as expected` or `PROVED, expected refuted`; `UNDECIDED` for a claim whose
/// check stopped at a limit.
pub(crate) fn verdict(c: &ClaimResult) -> &'static str {
    if c.undecided.is_some() {
        return "UNDECIDED";
    }
    match (c.proved, c.expect) {
        (true, Expect::Proved) => "proved",
        (false, Expect::Proved) => "REFUTED",
        (false, Expect::Refuted) => "refuted, as expected",
        (true, Expect::Refuted) => "PROVED, expected refuted",
    }
}

/// What an undecided claim's report says under it: `stopped at a limit: the result would have
/// more than 1000 terms (the term limit)`.
pub(crate) fn stopped(message: &str) -> String {
    format!("stopped at a limit: {message}")
}

/// ` on A = 0` after a claim made on a level set, else nothing.
pub(crate) fn level_set_suffix(c: &crate::report::ClaimResult) -> String {
    c.on_level
        .as_ref()
        .map(|l| format!(" on {}", l.text))
        .unwrap_or_default()
}

/// `p_θ = Iω` → ` at p_θ = Iω`; nothing without a condition.
pub(crate) fn condition_suffix(condition: &Option<String>) -> String {
    condition
        .as_ref()
        .map(|c| format!(" at {c}"))
        .unwrap_or_default()
}
