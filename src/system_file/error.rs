//! [`FileError`]: what is wrong with a system file (or a text given to it, by a program or on
//! the command line), where, and what to do about it, rendered as
//!
//! ```text
//! systems/mine.toml:12:21: unknown name 'G3' (known: x, y, …)
//!    12 | claim = "{L, G1} = -G3"
//!       |                     ^^
//! ```

use std::fmt;
use std::ops::Range;

use trigpoly::{Excerpt, Span};

use super::scope::{Limit, LimitSettings};
use super::text::Given;

/// What kind of problem a [`FileError`] reports.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The file could not be read.
    Io,
    /// The file is empty (or blank).
    Empty,
    /// The file is not UTF-8 text (a NUL byte, invalid UTF-8).
    NotText,
    /// The file is not valid TOML.
    Toml,
    /// A field is missing, unknown or of the wrong type.
    Schema,
    /// A declared name is invalid, reserved or declared twice.
    Name,
    /// An expression does not parse or does not mean anything (unknown name, division by a
    /// non-monomial, a bracket with a parameter, ...).
    Expression,
    /// A condition (`when`) is malformed.
    Condition,
    /// A claim is malformed (no `=`, a bad rank claim).
    Claim,
    /// A family is malformed or cannot be used as asked.
    Family,
    /// A term or degree limit was reached.
    Limit,
    /// The engine could not finish a computation (a rank it could not certify, ...).
    Engine,
}

// ALL and name() from one list, by the crate's variants_with_names (lib.rs).
variants_with_names! {
    ErrorKind;
    /// Every kind, in the order they are declared.
    ALL;
    /// The kind as one lowercase word, as JSON reports it (`limit`, `expression`).
    name;
    Io => "io",
    Empty => "empty",
    NotText => "not_text",
    Toml => "toml",
    Schema => "schema",
    Name => "name",
    Expression => "expression",
    Condition => "condition",
    Claim => "claim",
    Family => "family",
    Limit => "limit",
    Engine => "engine",
}

/// The kind as [`ErrorKind::name`] writes it (`limit`).
impl fmt::Display for ErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A kind by its [`ErrorKind::name`], as JSON reports it (`not_text`).
///
/// ```
/// use superint::system_file::{ErrorKind, UnknownErrorKind};
///
/// assert_eq!("not_text".parse(), Ok(ErrorKind::NotText));
/// assert_eq!(ErrorKind::Limit.to_string().parse::<ErrorKind>(), Ok(ErrorKind::Limit));
/// let err = "syntax".parse::<ErrorKind>().unwrap_err();
/// assert_eq!(err, UnknownErrorKind("syntax".into()));
/// assert_eq!(err.to_string(), "unknown error kind 'syntax'");
/// ```
impl std::str::FromStr for ErrorKind {
    type Err = UnknownErrorKind;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        ErrorKind::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| UnknownErrorKind(s.to_string()))
    }
}

/// A name that is no [`ErrorKind`]'s: the name.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown error kind '{0}'")]
pub struct UnknownErrorKind(pub String);

/// Where in its source an error is: 1-based line and column (in characters), the source line
/// and the caret under the offending text; where that text runs on to a later line, that line
/// and its caret too ([`Excerpt::last`]), so that both of its ends are seen.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    /// 1-based line.
    pub line: usize,
    /// 1-based column, in characters.
    pub column: usize,
    /// The source line (empty for a binary file).
    pub excerpt: String,
    /// The text before the caret: spaces, and tabs where the line has tabs.
    pad: String,
    /// How many carets.
    width: usize,
    /// The line where the offending text ends, when it is a later one.
    last: Option<Box<Location>>,
}

/// What to do about a text that divides by what reads as 0 (`1/0`), said as the hint of its
/// error.
const DIVIDED_BY_ZERO: &str =
    "what is divided by here is 0: write a divisor other than 0, or leave the division out";

/// A problem with a system file or a text given to it: kind, origin (the file's path; a text a
/// program gave, `<expression>`, `<condition>`, `<function NAME>`, ...; `<command line>` for
/// the command line's), location, message and an optional hint.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub struct FileError {
    /// What kind of problem it is.
    pub kind: ErrorKind,
    /// The file's path as given, or the name of the text at fault (`<expression>`,
    /// `<command line>`, ...).
    pub origin: String,
    /// Where, when the problem has a place in the text.
    pub location: Option<Box<Location>>,
    /// What is wrong, in one line.
    pub message: String,
    /// What to do about it.
    pub hint: Option<String>,
    /// The id of the claim whose check this is, for a claim that stopped at a limit (its
    /// location is the claim's text in the file). A boxed `str`, to keep the error small.
    pub claim: Option<Box<str>>,
    /// For a file that failed to load, what its texts read in doubt before the error, where
    /// there is any ([`LoadedSystem::warnings`](super::LoadedSystem::warnings), which the
    /// loaded file would have kept), in the order read; not part of the message. Boxed, as the
    /// location is, to keep the error small.
    pub warnings: Option<Box<Vec<Warning>>>,
    /// For an expression that did not read, what kind of error its parse met, as
    /// [`ParseError::cause`](trigpoly::ParseError::cause) says it (an unknown name with the
    /// known names, a limit, a refusal of the algebra), so that a caller tells them apart
    /// without reading the message; `None` for a mistake of syntax and for every other error.
    /// Not part of the message. Boxed, to keep the error small.
    pub cause: Option<Box<trigpoly::ParseCause>>,
    /// For an error of the engine (a computation's, or a text's the engine refused), that
    /// error as the engine gave it, so that a program tells it apart without reading the
    /// message: a refusal of the condition a computation was under
    /// ([`EngineError::RefusedCondition`](brackets::EngineError::RefusedCondition), the
    /// variable with the message) is placed in the condition's text by
    /// [`LoadedSystem::condition_refusal`](super::LoadedSystem::condition_refusal), as a
    /// search's is; `None` for every other error. Not part of the message. Boxed, to keep the
    /// error small.
    pub engine: Option<Box<brackets::EngineError>>,
}

impl FileError {
    /// An error without a place in the text (an unreadable file).
    pub fn new(kind: ErrorKind, origin: &str, message: impl Into<String>) -> Self {
        FileError {
            kind,
            origin: origin.to_string(),
            location: None,
            message: message.into(),
            hint: None,
            claim: None,
            warnings: None,
            cause: None,
            engine: None,
        }
    }

    /// An error at the byte range `span` of `text`; the caret covers the span's part of its
    /// first line (at least one character).
    pub fn at(
        kind: ErrorKind,
        origin: &str,
        text: &str,
        span: Range<usize>,
        message: impl Into<String>,
    ) -> Self {
        FileError {
            location: Some(Box::new(locate(text, span))),
            ..FileError::new(kind, origin, message)
        }
    }

    /// The same error with a hint.
    #[must_use]
    pub fn with_hint(mut self, hint: impl Into<String>) -> Self {
        self.hint = Some(hint.into());
        self
    }

    /// The same error, of an expression whose parse met `cause` ([`FileError::cause`]), and
    /// classified by it as the loader classifies a text's error:
    /// of kind [`ErrorKind::Limit`], with the hint that says how to raise the limit, where a
    /// limit stopped the parse ([`ParseCause::limit`](trigpoly::ParseCause::limit)); otherwise
    /// of its kind. By this one rule a parse that a limit stopped is a limit whether it
    /// reaches a program through the loader or through `?`, or the command line from a
    /// built-in system's text. The hint names the settings of the text's giver, `given`
    /// ([`Given`]): the command line's flag first for a text given on it (alone for a built-in
    /// system, which has no `[limits]` to set), a program's `LimitsOverride` first for a
    /// program's text to a system file (`<expression>`), the file's `[limits]` first for the
    /// file's own text, the `Limits` a system built in code was built with.
    ///
    /// ```
    /// use superint::system_file::{ErrorKind, FileError, Given};
    /// use superint::trigpoly::ParseCause;
    ///
    /// let power = ParseCause::PowerPastLimit { power: Some(5000), limit: 1000 };
    /// let err = FileError::at(ErrorKind::Expression, "<command line>", "x^5000", 2..6, "past")
    ///     .with_cause(&power, Given::CommandLineAboutFile);
    /// assert_eq!(err.kind, ErrorKind::Limit);
    /// assert_eq!(
    ///     err.hint.as_deref(),
    ///     Some("if the machine has the memory, raise the limit with --max-degree D (or \
    ///           max_degree under [limits] in the file)")
    /// );
    /// let err = FileError::at(ErrorKind::Expression, "<command line>", "x^5000", 2..6, "past")
    ///     .with_cause(&power, Given::CommandLineAboutBuiltIn);
    /// assert_eq!(
    ///     err.hint.as_deref(),
    ///     Some("if the machine has the memory, raise the limit with --max-degree D")
    /// );
    /// let err = FileError::new(ErrorKind::Expression, "<command line>", "no")
    ///     .with_cause(&ParseCause::Decimal, Given::CommandLineAboutFile);
    /// assert_eq!((err.kind, err.hint), (ErrorKind::Expression, None));
    /// ```
    #[must_use]
    pub fn with_cause(self, cause: &trigpoly::ParseCause, given: Given) -> Self {
        self.with_cause_under(cause, LimitSettings::of(given))
    }

    /// [`FileError::with_cause`], a limit's hint naming the settings `settings`.
    pub(crate) fn with_cause_under(
        mut self,
        cause: &trigpoly::ParseCause,
        settings: LimitSettings,
    ) -> Self {
        self.cause = match cause {
            trigpoly::ParseCause::Syntax => None,
            cause => Some(Box::new(cause.clone())),
        };
        self.classified_by_cause(settings)
    }

    /// The same error, of kind [`ErrorKind::Limit`] with the hint that raises the limit in
    /// `settings`, where a limit of the engine stopped what it is about, `e`
    /// ([`EngineError::limit`]); as it is otherwise: a condition whose values a limit stopped
    /// as they were resolved into each other is a limit, as its values' reading is.
    ///
    /// [`EngineError::limit`]: brackets::EngineError::limit
    #[must_use]
    pub(crate) fn limited_by(self, e: &brackets::EngineError, settings: LimitSettings) -> Self {
        match Limit::of_engine(e) {
            Some(limit) => FileError {
                kind: ErrorKind::Limit,
                hint: limit.hint(settings),
                ..self
            },
            None => self,
        }
    }

    /// The error of a computation that the command line asked of a system, `doing`
    /// (`searching for integrals`), where a limit stopped it, `e` ([`EngineError::limit`]):
    /// of kind [`ErrorKind::Limit`], from `origin` (the system file as given, or `--system
    /// NAME`), said after `doing`, with the hint that names the setting that raises it for
    /// the text's giver, `given` (the command line's flag, then a system file's `[limits]`),
    /// as a text's limit on the command line has; the engine's message names no setting,
    /// knowing not who set the limit. `None` where no limit stopped it.
    ///
    /// ```
    /// use superint::brackets::{EngineError, EngineLimit};
    /// use superint::system_file::{ErrorKind, FileError, Given};
    ///
    /// let e = EngineError::PastLimit {
    ///     which: EngineLimit::SearchProducts,
    ///     limit: 9,
    ///     message: "more than 9 products of integrals".into(),
    /// };
    /// let given = Given::CommandLineAboutFile;
    /// let err = FileError::limit_on_command_line("mine.toml", given, "searching", &e).unwrap();
    /// assert_eq!(err.kind, ErrorKind::Limit);
    /// assert_eq!(
    ///     err.to_string(),
    ///     "mine.toml: searching: more than 9 products of integrals\nhint: if the machine has \
    ///      the time, raise the limit with --max-products N"
    /// );
    /// let e = EngineError::Invalid("no".into());
    /// let given = Given::CommandLineAboutBuiltIn;
    /// assert!(FileError::limit_on_command_line("--system harmonic", given, "searching", &e)
    ///     .is_none());
    /// ```
    ///
    /// [`EngineError::limit`]: brackets::EngineError::limit
    pub fn limit_on_command_line(
        origin: &str,
        given: Given,
        doing: &str,
        e: &brackets::EngineError,
    ) -> Option<FileError> {
        Limit::of_engine(e)?;
        let message = format!("{doing}: {e}");
        Some(
            FileError::new(ErrorKind::Engine, origin, message)
                .limited_by(e, LimitSettings::of(given)),
        )
    }

    /// The same error, of kind [`ErrorKind::Limit`] with the hint in `settings` where its
    /// [`FileError::cause`] is a limit ([`FileError::with_cause`]).
    fn classified_by_cause(self, settings: LimitSettings) -> Self {
        match self.cause.as_deref().and_then(Limit::of_parse) {
            Some(limit) => FileError {
                kind: ErrorKind::Limit,
                hint: limit.hint(settings),
                ..self
            },
            // A division by what reads as 0 (`1/0`, `x/(a - a)`) says what to do, as the
            // other refusals of a text do.
            None => match self.cause.as_deref() {
                Some(trigpoly::ParseCause::Algebra(trigpoly::AlgebraError::DivisionByZero))
                    if self.hint.is_none() =>
                {
                    self.with_hint(DIVIDED_BY_ZERO)
                }
                _ => self,
            },
        }
    }

    /// The unknown name an expression's error is about ([`FileError::cause`]), if it is one,
    /// as its message shows it ([`trigpoly::shown_name`]): whole, or one past 80 characters by
    /// its start and `…`.
    pub fn unknown_name(&self) -> Option<String> {
        match self.cause.as_deref() {
            Some(trigpoly::ParseCause::UnknownName { name, .. }) => {
                Some(trigpoly::shown_name(name))
            }
            _ => None,
        }
    }

    /// The same error, as that of the claim `id`'s check.
    #[must_use]
    pub fn of_claim(mut self, id: impl Into<String>) -> Self {
        self.claim = Some(id.into().into_boxed_str());
        self
    }

    /// What the texts of a file that failed to load read in doubt before the error
    /// ([`FileError::warnings`]), in the order read; none for any other error.
    pub fn warnings_before(&self) -> &[Warning] {
        self.warnings.as_deref().map_or(&[], Vec::as_slice)
    }

    /// 1-based line and column, if the error has a place.
    pub fn line_col(&self) -> Option<(usize, usize)> {
        self.location.as_ref().map(|l| (l.line, l.column))
    }
}

impl fmt::Display for FileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.location.as_deref() {
            None => write!(f, "{}: {}", self.origin, self.message)?,
            Some(l) => {
                write!(
                    f,
                    "{}:{}:{}: {}",
                    self.origin, l.line, l.column, self.message
                )?;
                if !l.excerpt.is_empty() || l.width > 0 {
                    // The line numbers right-aligned, the last line's the widest.
                    let last = l.last.as_deref();
                    let gutter = last.unwrap_or(l).line.to_string().len();
                    l.write_excerpt(f, gutter)?;
                    if let Some(last) = last {
                        if last.line > l.line + 1 {
                            write!(f, "\n {:>gutter$} |", "…")?;
                        }
                        last.write_excerpt(f, gutter)?;
                    }
                }
            }
        }
        if let Some(h) = &self.hint {
            write!(f, "\nhint: {h}")?;
        }
        Ok(())
    }
}

impl Location {
    /// The numbered source line and the caret under it, each on a line of its own after a
    /// line break, the number right-aligned in a gutter of `gutter` characters.
    fn write_excerpt(&self, f: &mut fmt::Formatter<'_>, gutter: usize) -> fmt::Result {
        write!(f, "\n {:>gutter$} | {}", self.line, self.excerpt)?;
        let carets = "^".repeat(self.width.max(1));
        write!(f, "\n {:gutter$} | {}{carets}", "", self.pad)
    }
}

/// A text of a system file (or one given to it) that superint read, but perhaps not as it was
/// meant: a name that is not declared, read as the product of the declared names it splits
/// into where the reading is in doubt ([`trigpoly::RunTogether`]): `Lxx` beside a function
/// `Lx`. The reading stands (the claims are checked with the product); the warning says it,
/// rendered as a [`FileError`] is, with its place, the line and a caret:
///
/// ```text
/// mine.toml:12:10: 'Lxx' is read as the product L_x x, the function Lx with x after it: …
///    12 | claim = "{Lxx, H} = 0"
///       |          ^^^
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct Warning {
    /// The file's path as given, or the name of the text (`<command line>`, `<expression>`).
    pub origin: String,
    /// Where the name is written.
    pub location: Option<Box<Location>>,
    /// What was read and why it is in doubt, in one line of plain text with the system's
    /// printed names: `'Lxx' is read as the product L_x x, the function Lx with x after it:
    /// declare 'Lxx' if it is a name of its own, or write 'Lx x' for the product`.
    pub message: String,
    /// The same as a report's prose writes it (markup: the product between back quotes), its
    /// place said in words: `'Lxx' (line 12, column 10) is read as the product `L_x x`, …`.
    pub markup: String,
}

impl Warning {
    /// The warning for a name run together and read as a product in doubt, `noted`, written
    /// at `span` of `text`, a text whose name is `origin`: its place, and the reading with each
    /// piece as `shown` prints it (`L_x x`). A system file's texts and the command line's
    /// texts about a built-in system are warned of alike, but for the advice to declare the
    /// name, which only a file, where a name is `declarable`, can follow.
    pub fn run_together(
        origin: &str,
        text: &str,
        span: Range<usize>,
        noted: &trigpoly::RunTogether,
        shown: &dyn Fn(&str) -> String,
        declarable: bool,
    ) -> Warning {
        let location = locate(text, span);
        let name = trigpoly::quoted_name(&noted.name);
        let plain = noted.reading(shown, &|p: &str| p.to_string(), declarable);
        let markup = noted.reading(shown, &|p: &str| format!("`{p}`"), declarable);
        Warning {
            origin: origin.to_string(),
            markup: format!(
                "{name} (line {}, column {}) {markup}",
                location.line, location.column
            ),
            message: format!("{name} {plain}"),
            location: Some(Box::new(location)),
        }
    }

    /// 1-based line and column, if the warning has a place.
    pub fn line_col(&self) -> Option<(usize, usize)> {
        self.location.as_ref().map(|l| (l.line, l.column))
    }
}

/// The warnings of the texts read so far, in the order read, each once: a file's
/// ([`LoadedSystem::warnings`](super::LoadedSystem::warnings)) and the command line's about a
/// built-in system alike. A warning is kept once where the same is said of the same place of
/// the same text: a file's text read again (a claim checked, a family instance expanded) adds
/// none, while two command-line texts, each `<command line>:1:1:`, are two places.
#[derive(Debug, Default)]
pub struct Warnings(std::sync::Mutex<Vec<Warning>>);

impl Warnings {
    /// The warnings kept, whatever a thread that panicked left.
    fn kept(&self) -> std::sync::MutexGuard<'_, Vec<Warning>> {
        self.0
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    /// Keeps `warning` unless the same is kept already, or this thread is in an
    /// [`Warnings::unwarned`] of this store, whose closure's warnings are dropped.
    pub fn warn(&self, warning: Warning) {
        if UNWARNED.with(|u| u.borrow().contains(&self.address())) {
            return;
        }
        let mut kept = self.kept();
        if !kept.contains(&warning) {
            kept.push(warning);
        }
    }

    /// The store's address, by which a thread tells [`Warnings::warn`] that it is in an
    /// [`Warnings::unwarned`] of it.
    fn address(&self) -> usize {
        std::ptr::from_ref(self) as usize
    }

    /// The warnings kept, in the order read.
    pub fn list(&self) -> Vec<Warning> {
        self.kept().clone()
    }

    /// `f`'s result, with the warnings it adds dropped: a test of a text that is refused
    /// whatever it reads (a new name read as a product of the system's names) says nothing of
    /// how it reads. What `f` warns of on this thread is never kept, while what other threads
    /// warn of meanwhile is kept; a thread that `f` starts warns as any other.
    pub fn unwarned<T>(&self, f: impl FnOnce() -> T) -> T {
        /// Takes the store off this thread's list when `f` returns or panics.
        struct Leave(usize);
        impl Drop for Leave {
            fn drop(&mut self) {
                UNWARNED.with(|u| {
                    let mut u = u.borrow_mut();
                    if let Some(k) = u.iter().rposition(|&a| a == self.0) {
                        u.remove(k);
                    }
                });
            }
        }
        UNWARNED.with(|u| u.borrow_mut().push(self.address()));
        let _leave = Leave(self.address());
        f()
    }
}

thread_local! {
    /// The stores ([`Warnings::address`]) this thread is in an [`Warnings::unwarned`] of.
    static UNWARNED: std::cell::RefCell<Vec<usize>> = const { std::cell::RefCell::new(Vec::new()) };
}

impl Clone for Warnings {
    fn clone(&self) -> Self {
        Warnings(std::sync::Mutex::new(self.list()))
    }
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let shown = FileError {
            location: self.location.clone(),
            ..FileError::new(ErrorKind::Expression, &self.origin, self.message.clone())
        };
        shown.fmt(f)
    }
}

/// Line, column, source line and caret of a byte range; a long line is shown as a window
/// around the caret ([`Excerpt`]).
/// A byte-order mark at the start is no column of the first line.
pub(crate) fn locate(text: &str, span: Range<usize>) -> Location {
    let bom = if text.starts_with('\u{feff}') {
        '\u{feff}'.len_utf8()
    } else {
        0
    };
    let shift = |at: usize| at.saturating_sub(bom);
    Location::from(Excerpt::of(
        &text[bom..],
        Span::new(shift(span.start), shift(span.end)),
    ))
}

/// The place an excerpt shows, as a file's error shows it.
impl From<Excerpt> for Location {
    fn from(excerpt: Excerpt) -> Self {
        Location {
            line: excerpt.line,
            column: excerpt.column,
            excerpt: excerpt.text,
            pad: excerpt.pad,
            width: excerpt.width,
            last: excerpt.last.map(|last| Box::new(Location::from(*last))),
        }
    }
}

/// A parse error of the ring's own parser ([`trigpoly::Expr::parse`]), so that `?` takes it
/// into a `FileError`: of kind [`ErrorKind::Expression`], from `<expression>`, at its line and
/// column with the line and a caret when it knows its source (every error of
/// `Expr::parse` does); of kind [`ErrorKind::Limit`], with the hint, where a limit stopped the
/// parse, as the loader says of a file's text ([`FileError::cause`]).
///
/// ```
/// use superint::prelude::*;
///
/// fn energy(vars: &Vars, text: &str) -> Result<Expr, FileError> {
///     Ok(Expr::parse(vars, text)?)
/// }
/// let vars = Vars::builder().coordinate("x").momentum("p_x").build().unwrap();
/// let err = energy(&vars, "p_x^2/2 +\n x^^2").unwrap_err();
/// assert_eq!((err.kind, err.line_col()), (ErrorKind::Expression, Some((2, 4))));
/// assert!(err.to_string().starts_with("<expression>:2:4: "), "{err}");
/// assert!(err.to_string().contains("\n 2 |  x^^2\n   |    ^"), "{err}");
/// let err = energy(&vars, "x^5000").unwrap_err();
/// assert_eq!((err.kind, err.line_col()), (ErrorKind::Limit, Some((1, 3))));
/// ```
impl From<trigpoly::ParseError> for FileError {
    fn from(e: trigpoly::ParseError) -> Self {
        FileError {
            location: e.excerpt().map(|x| Box::new(Location::from(x.clone()))),
            ..FileError::new(ErrorKind::Expression, "<expression>", e.message())
        }
        .with_cause_under(e.cause(), LimitSettings::Program)
    }
}

/// Line and column of a byte offset in bytes that need not be UTF-8 (for binary files): no
/// excerpt, no caret.
pub(crate) fn locate_bytes(bytes: &[u8], offset: usize) -> Location {
    let before = &bytes[..offset.min(bytes.len())];
    let line_start = before
        .iter()
        .rposition(|&b| b == b'\n')
        .map_or(0, |i| i + 1);
    let column = String::from_utf8_lossy(&before[line_start..])
        .chars()
        .count()
        + 1;
    Location {
        line: before.iter().filter(|&&b| b == b'\n').count() + 1,
        column,
        excerpt: String::new(),
        pad: String::new(),
        width: 0,
        last: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `ALL` has every kind once, in the order they are declared (its list is `name`'s,
    /// whose match covers every kind), and each reads back from its name.
    #[test]
    fn every_kind_is_listed_in_order_and_reads_back_from_its_name() {
        for (i, kind) in ErrorKind::ALL.into_iter().enumerate() {
            assert_eq!(kind as usize, i, "{kind:?}");
            assert_eq!(kind.name().parse(), Ok(kind));
        }
    }

    /// An expression's error keeps its parse error's cause: an unknown name says the name,
    /// one past 80 characters by its start as the message shows it; a syntax error has none.
    #[test]
    fn an_expression_error_keeps_its_cause() {
        let vars = trigpoly::Vars::builder()
            .coordinate("x")
            .momentum("p_x")
            .build()
            .unwrap();
        let error = |text: &str| FileError::from(trigpoly::Expr::parse(&vars, text).unwrap_err());
        let unknown = error("x + q");
        assert_eq!(unknown.unknown_name().as_deref(), Some("q"));
        let Some(trigpoly::ParseCause::UnknownName { name, known }) = unknown.cause.as_deref()
        else {
            panic!("{unknown:?}")
        };
        assert_eq!(
            (name.as_str(), known.as_slice()),
            ("q", &["x".to_string(), "p_x".into()][..])
        );
        let long = "q".repeat(81);
        let shown = error(&long).unknown_name().unwrap();
        assert_eq!(shown, format!("{}…", "q".repeat(40)));
        assert!(error(&long)
            .message
            .starts_with(&format!("unknown name '{shown}'")));
        assert_eq!(error("x + (").cause, None);
        assert!(matches!(
            error("x^5000").cause.as_deref(),
            Some(trigpoly::ParseCause::PowerPastLimit {
                power: Some(5000),
                ..
            })
        ));
    }

    #[test]
    fn error_renders_with_file_line_column_and_caret() {
        let text = "name = \"x\"\nclaim = \"{L, G1} = -G3\"\n";
        let start = text.find("G3").unwrap();
        let e = FileError::at(
            ErrorKind::Expression,
            "a.toml",
            text,
            start..start + 2,
            "unknown name 'G3'",
        );
        assert_eq!(
            e.to_string(),
            "a.toml:2:21: unknown name 'G3'\n 2 | claim = \"{L, G1} = -G3\"\n   |                     ^^"
        );
    }

    /// A long line (here 4000 terms) shows a window of 40 characters either side of the
    /// caret, cut with `…`, and the caret stays under the offending text.
    #[test]
    fn a_long_line_is_shown_as_a_window_around_the_error() {
        let expr = format!("{}q{}", "x+".repeat(2000), "+x".repeat(2000));
        let text = format!("value = \"{expr}\"\n");
        let start = text.find('q').unwrap();
        let e = FileError::at(
            ErrorKind::Expression,
            "a.toml",
            &text,
            start..start + 1,
            "unknown name 'q'",
        );
        let side = "x+".repeat(20);
        let after = "+x".repeat(20);
        assert_eq!(
            e.to_string(),
            format!(
                "a.toml:1:{}: unknown name 'q'\n 1 | …{side}q{after}…\n   | {}^",
                start + 1,
                " ".repeat(41)
            )
        );
        // Near the start of the line nothing is cut before it.
        let e = FileError::at(ErrorKind::Expression, "a.toml", &text, 9..10, "here");
        let shown = e.to_string();
        assert!(
            shown.contains(&format!(" 1 | value = \"{}", "x+".repeat(20))),
            "{shown}"
        );
        assert!(
            shown.ends_with(&format!("…\n   | {}^", " ".repeat(9))),
            "{shown}"
        );
    }

    /// A warning of `message` at the start of the text `origin`.
    fn warning(origin: &str, message: &str) -> Warning {
        Warning {
            origin: origin.to_string(),
            location: None,
            message: message.to_string(),
            markup: message.to_string(),
        }
    }

    /// `Warnings::unwarned` drops what its closure warns of, and only that: a warning kept
    /// before it and one kept after it stay, and so does one that another thread keeps while
    /// the closure runs, which cutting the store back to its length before the closure dropped.
    #[test]
    fn unwarned_drops_the_closure_s_warnings_alone() {
        let store = Warnings::default();
        store.warn(warning("a", "before"));
        let (entered, left) = (std::sync::Barrier::new(2), std::sync::Barrier::new(2));
        std::thread::scope(|s| {
            s.spawn(|| {
                entered.wait();
                store.warn(warning("b", "from another thread"));
                left.wait();
            });
            let result = store.unwarned(|| {
                store.warn(warning("c", "in the closure"));
                entered.wait();
                left.wait();
                store.warn(warning("d", "in the closure too"));
                7
            });
            assert_eq!(result, 7);
        });
        store.warn(warning("e", "after"));
        let messages: Vec<String> = store.list().into_iter().map(|w| w.message).collect();
        assert_eq!(messages, ["before", "from another thread", "after"]);
        // A panic in the closure leaves the thread warning as before.
        let caught = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            store.unwarned(|| panic!("the closure panics"))
        }));
        assert!(caught.is_err());
        store.warn(warning("f", "after the panic"));
        assert_eq!(
            store.list().last().map(|w| w.message.as_str()),
            Some("after the panic")
        );
    }
}
