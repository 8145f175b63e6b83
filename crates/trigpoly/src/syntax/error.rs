//! Source spans and parse errors, with line/column lookup and caret rendering.

use crate::error::{AlgebraError, LimitKind};

/// Byte range `start..end` in the source text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Span {
    /// Byte offset of the first byte of the range.
    pub start: usize,
    /// Byte offset one past the last byte of the range.
    pub end: usize,
}

impl Span {
    /// The span `start..end`.
    #[must_use]
    pub fn new(start: usize, end: usize) -> Self {
        Span { start, end }
    }

    /// The smallest span covering both `self` and `other`.
    #[must_use]
    pub fn to(self, other: Span) -> Span {
        Span::new(self.start.min(other.start), self.end.max(other.end))
    }
}

/// A syntax error: what was expected and what was found, at a location in the source.
///
/// An error of a parse that had its text ([`Poly::parse`](crate::Poly::parse),
/// [`parse_expr`](crate::syntax::parse_expr)) keeps the line it is in, so that it says where on
/// its own, wherever `?` takes it (a `Box<dyn Error>`, an `anyhow::Error`): its `Display` is
/// [`ParseError::render`]'s, `line L, column C: message`, the line and a caret under the
/// offending text. One made without its text ([`ParseError::new`]) shows its message alone.
///
/// ```
/// use trigpoly::{Expr, Vars};
///
/// let vars = Vars::builder().coordinate("x").momentum("p_x").build().unwrap();
/// let err = Expr::parse(&vars, "p_x^2/2 + q*x").unwrap_err();
/// assert_eq!(err.message(), "unknown name 'q' (known: x, p_x)");
/// assert_eq!(
///     err.to_string(),
///     "line 1, column 11: unknown name 'q' (known: x, p_x)\n  p_x^2/2 + q*x\n            ^"
/// );
/// let boxed: Box<dyn std::error::Error> = err.into();
/// assert!(boxed.to_string().ends_with("^"));
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParseError {
    /// The offending part of the source (empty at the end of the input).
    pub span: Span,
    /// Human-readable description, without location information ([`ParseError::message`]).
    message: String,
    /// The place of `span` in the source and its line, when the error knows its source.
    excerpt: Option<Box<Excerpt>>,
    /// The opener whose place the message says, when it says one.
    opener: Option<Box<Opener>>,
    /// What kind of error it is ([`ParseError::cause`]); `None` for [`ParseCause::Syntax`].
    cause: Option<Box<ParseCause>>,
}

/// What kind of error a [`ParseError`] is, beyond its message: set where the error is made,
/// so that a caller tells a limit or an unknown name from a mistake of syntax (and gives its
/// hint) without reading the message's text.
///
/// New kinds come as new variants, so a `match` on it needs a `_` arm.
///
/// ```
/// use trigpoly::{AlgebraError, Expr, ParseCause, Vars};
///
/// let vars = Vars::builder().coordinate("x").momentum("p_x").build().unwrap();
/// let err = Expr::parse(&vars, "p_x^2/2 + q*x").unwrap_err();
/// let ParseCause::UnknownName { name, known } = err.cause() else { panic!() };
/// assert_eq!((name.as_str(), known.as_slice()), ("q", &["x".to_string(), "p_x".into()][..]));
/// let err = Expr::parse(&vars, "x^5000").unwrap_err();
/// assert!(matches!(err.cause(), ParseCause::PowerPastLimit { power: Some(5000), .. }));
/// let err = Expr::parse(&vars, "x/(1 + x)").unwrap_err();
/// assert!(matches!(err.cause(), ParseCause::Algebra(AlgebraError::NotAMonomial { .. })));
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ParseCause {
    /// The text does not read, or reads as nothing the ring has: what the message says.
    Syntax,
    /// Text that no token is made of where it stands, as a name printed otherwise than it is
    /// written may be (`Z̄`, `G1'`, `\nabla\varphi`): a character no token begins with, a
    /// LaTeX command the reader does not know, or what is no part of a name in a name's
    /// braces (`p_{x$}`), or a known name under a bar (`ȳ`, `\bar{y}`), as a paper writes
    /// the conjugate.
    Unreadable,
    /// A decimal number (`0.5`), which is not exact: the message names the fraction it writes.
    Decimal,
    /// A name that is neither declared nor defined by the context.
    UnknownName {
        /// The name, as written.
        name: String,
        /// The names that are known (variables and the context's names), as the message
        /// lists them; empty where none are declared.
        known: Vec<String>,
    },
    /// A function that takes its argument in parentheses written without them, as a paper
    /// writes the real part, `Re K` or `conj A` (`cos θ` reads so; these do not), where no
    /// declared name takes that spelling: the message says what to write, `Re(…)`, and where
    /// it was raised to a power before the parentheses (`Re²(L)`), that the power follows
    /// them, `Re(…)^2`.
    FunctionWithoutParentheses {
        /// The function's name, as written (`Re`, `conj`).
        name: String,
    },
    /// An operation of the algebra refused while the expression was formed: a limit
    /// ([`AlgebraError::TooManyTerms`], [`AlgebraError::ExponentTooLarge`], …), a division
    /// that is not exact, and the rest of [`AlgebraError`].
    Algebra(AlgebraError),
    /// An exponent or an angle's multiple, written in the text, past the degree limit
    /// ([`Limits::max_degree`](crate::Limits)): `x^5000`, `cos(5000*θ)`.
    PowerPastLimit {
        /// Its size `|n|` (of a radical's power `p/2`, `|p|`), or `None` for one that no
        /// 64-bit number holds.
        power: Option<u64>,
        /// The limit in force.
        limit: u32,
    },
}

impl ParseCause {
    /// Whether a limit stopped the text's reading: an operation of the algebra refused at a
    /// limit ([`AlgebraError::limit`]), or an exponent or multiple written past the degree
    /// limit. It asks [`ParseCause::limit`].
    ///
    /// ```
    /// use trigpoly::{AlgebraError, ParseCause};
    ///
    /// assert!(ParseCause::PowerPastLimit { power: Some(5000), limit: 1000 }.is_limit());
    /// assert!(ParseCause::Algebra(AlgebraError::TooManyTerms { limit: 30 }).is_limit());
    /// assert!(!ParseCause::Algebra(AlgebraError::DivisionByZero).is_limit());
    /// assert!(!ParseCause::Syntax.is_limit());
    /// ```
    #[must_use]
    pub fn is_limit(&self) -> bool {
        self.limit().is_some()
    }

    /// The limit that stopped the text's reading, if one did: the algebra's
    /// ([`AlgebraError::limit`]), or the degree limit for an exponent or multiple written past
    /// it, of its size (`u64::MAX` for one that no 64-bit number holds, past every limit).
    ///
    /// ```
    /// use trigpoly::{AlgebraError, LimitKind, ParseCause};
    ///
    /// let power = ParseCause::PowerPastLimit { power: Some(5000), limit: 1000 };
    /// assert_eq!(power.limit(), Some(LimitKind::Degree(5000)));
    /// let terms = ParseCause::Algebra(AlgebraError::TooManyTerms { limit: 30 });
    /// assert_eq!(terms.limit(), Some(LimitKind::Terms));
    /// assert_eq!(ParseCause::Algebra(AlgebraError::DivisionByZero).limit(), None);
    /// assert_eq!(ParseCause::Syntax.limit(), None);
    /// ```
    #[must_use]
    pub fn limit(&self) -> Option<LimitKind> {
        match self {
            ParseCause::Algebra(e) => e.limit(),
            ParseCause::PowerPastLimit { power, .. } => {
                Some(LimitKind::Degree(power.unwrap_or(u64::MAX)))
            }
            _ => None,
        }
    }
}

/// The cause of an error made without one.
const SYNTAX: ParseCause = ParseCause::Syntax;

/// An opener named by an error's message (`expected ')' to close '(' opened at column 5,
/// found end of input`): its byte offset in the parsed text, and the message before
/// and after the place the parser wrote (`column 5`), so that a caller that places the text
/// in lines of its own (a file's) writes the message with its own place once
/// ([`ParseError::message_placing_opener`]).
#[derive(Clone, Debug, PartialEq, Eq)]
struct Opener {
    at: usize,
    before: String,
    after: String,
}

impl ParseError {
    /// An error at `span` with the given message.
    pub fn new(span: Span, message: impl Into<String>) -> Self {
        ParseError {
            span,
            message: message.into(),
            excerpt: None,
            opener: None,
            cause: None,
        }
    }

    /// The same error, of the kind `cause` ([`ParseError::cause`]).
    #[must_use]
    pub fn with_cause(mut self, cause: ParseCause) -> Self {
        self.cause = match cause {
            ParseCause::Syntax => None,
            cause => Some(Box::new(cause)),
        };
        self
    }

    /// What kind of error it is: an unknown name, a refusal of the algebra (a limit among
    /// them), a power past the degree limit, text no token is made of
    /// ([`ParseCause::Unreadable`]), a decimal number ([`ParseCause::Decimal`]), or else
    /// [`ParseCause::Syntax`]. It is set where the error is made, and kept by the methods that
    /// change its message or its source.
    #[must_use]
    pub fn cause(&self) -> &ParseCause {
        self.cause.as_deref().unwrap_or(&SYNTAX)
    }

    /// The description, without the place: what its `Display` writes after `line L, column C: `.
    /// It is set where the error is made, and changed only by methods that keep the opener it
    /// names, if it names one, in step ([`ParseError::message_placing_opener`]).
    #[must_use]
    pub fn message(&self) -> &str {
        &self.message
    }

    /// An error at `span` of `src` saying where the opener at byte `open` of what it refuses
    /// stands (the braces of a name, a parenthesis never closed):
    /// `before`, the place ([`opened_at`]: the column where the opener is on the error's line,
    /// else its line and column), `after`.
    pub(crate) fn naming_opener(
        src: &str,
        span: Span,
        open: usize,
        before: &str,
        after: &str,
    ) -> Self {
        let at = opened_at(src, open, span.start);
        ParseError {
            opener: Some(Box::new(Opener {
                at: open,
                before: before.to_string(),
                after: after.to_string(),
            })),
            ..ParseError::new(span, format!("{before}{at}{after}"))
        }
    }

    /// The same error with `prefix` before its message (`a bracket {f, g} takes exactly two
    /// arguments; `), still naming its opener.
    #[must_use]
    pub(crate) fn prefixed(mut self, prefix: &str) -> Self {
        self.message.insert_str(0, prefix);
        if let Some(opener) = &mut self.opener {
            opener.before.insert_str(0, prefix);
        }
        self
    }

    /// The message, with the place of the opener it names, if it names one, written
    /// by `place` from the opener's byte offset in the parsed text: for a caller whose lines
    /// are not the parsed text's (a file's, where the text is a value among others).
    pub fn message_placing_opener(&self, place: impl FnOnce(usize) -> String) -> String {
        match &self.opener {
            Some(o) => format!("{}{}{}", o.before, place(o.at), o.after),
            None => self.message.clone(),
        }
    }

    /// The same error, knowing its source `src`: its line, column and the line it is in, which
    /// its `Display` then shows. An error that knows its source already keeps it (the text of
    /// an inner parse is the text that was parsed).
    #[must_use]
    pub fn in_source(mut self, src: &str) -> Self {
        if self.excerpt.is_none() {
            self.excerpt = Some(Box::new(Excerpt::of(src, self.span)));
        }
        self
    }

    /// The same error, not knowing its source: its `Display` is then its message alone, for
    /// a text whose line and column would place it in nothing a reader sees. It still names
    /// its opener, if it names one.
    #[must_use]
    pub fn without_source(mut self) -> Self {
        self.excerpt = None;
        self
    }

    /// The line, column and source line of the error, if it knows its source
    /// ([`ParseError::in_source`]).
    pub fn excerpt(&self) -> Option<&Excerpt> {
        self.excerpt.as_deref()
    }

    /// 1-based line and column (column counted in characters, not bytes) of `span.start` in `src`.
    #[must_use]
    pub fn line_col(&self, src: &str) -> (usize, usize) {
        line_col(src, self.span.start)
    }

    /// Multi-line rendering: `"line L, column C: message"`, then the source line, then a line of
    /// carets under the offending span (as wide as the span in characters, at least one); a
    /// long line is shown as a window around the caret ([`Excerpt`]).
    #[must_use]
    pub fn render(&self, src: &str) -> String {
        rendered(&self.message, &Excerpt::of(src, self.span))
    }

    /// [`ParseError::render`] with `place` where the line and column stand, `its Hamiltonian:
    /// message`, for a text nobody typed (a built-in system's), whose line and column would
    /// place it in nothing a reader sees.
    #[must_use]
    pub fn render_as(&self, src: &str, place: &str) -> String {
        rendered_at(place, &self.message, &Excerpt::of(src, self.span))
    }
}

/// `line L, column C: message`, the line and the caret.
fn rendered(message: &str, excerpt: &Excerpt) -> String {
    let place = format!("line {}, column {}", excerpt.line, excerpt.column);
    rendered_at(&place, message, excerpt)
}

/// `place: message`, the line and the caret; for a span that ends on a later line, that line
/// and its caret too, after `…` where lines lie between them.
fn rendered_at(place: &str, message: &str, excerpt: &Excerpt) -> String {
    let shown = |e: &Excerpt| format!("\n  {}\n  {}{}", e.text, e.pad, "^".repeat(e.width));
    let mut out = format!("{place}: {message}{}", shown(excerpt));
    if let Some(last) = &excerpt.last {
        if last.line > excerpt.line + 1 {
            out.push_str("\n  …");
        }
        out.push_str(&shown(last));
    }
    out
}

/// The message with its place, line and caret when the error knows its source
/// ([`ParseError::render`]); else the message alone.
impl std::fmt::Display for ParseError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.excerpt {
            Some(excerpt) => f.write_str(&rendered(&self.message, excerpt)),
            None => f.write_str(&self.message),
        }
    }
}

impl std::error::Error for ParseError {}

/// A source line longer than this many characters is shown as a window around the error.
const EXCERPT_CHARS: usize = 100;

/// Characters of context a window keeps on each side of the caret.
const EXCERPT_CONTEXT: usize = 40;

/// The part of a source line shown under an error, and the caret under the offending span:
/// the whole line, or for a line past 100 characters (a generated expression pasted into a
/// file) a window of 40 characters either side of the caret, cut with `…`; and where the span
/// runs on past that line (`x/(x +` then `y)`), the line where it ends, [`Excerpt::last`], so
/// that both ends of what is refused are seen. Made by [`Excerpt::of`] and read. A field may
/// be added, so a pattern of one names the fields it reads and `..`:
///
/// ```compile_fail,E0638
/// fn line(excerpt: trigpoly::syntax::Excerpt) -> usize {
///     let trigpoly::syntax::Excerpt { line, column, text, pad, width, last } = excerpt;
///     line
/// }
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct Excerpt {
    /// 1-based line of the span's start.
    pub line: usize,
    /// 1-based column of the span's start, in characters.
    pub column: usize,
    /// The line, or its window.
    pub text: String,
    /// What goes before the caret: spaces, and tabs where the line has tabs.
    pub pad: String,
    /// How many carets (at least one).
    pub width: usize,
    /// Where the span ends on a later line than it starts (past the blanks it ends with), that
    /// line's excerpt, its caret under the span's part of it from the line's first character
    /// that is not blank (its `line` and `column` that character's; of a long line, the window
    /// around the span's end), with no `last` of its own.
    pub last: Option<Box<Excerpt>>,
}

impl Excerpt {
    /// The place and excerpt of the line of `src` where `span` starts; the caret covers the
    /// span's part of that line. Where the span runs on to a later line, [`Excerpt::last`] is
    /// the line where it ends, and the first line's caret stops at its last character that is
    /// not blank (`x/(x + ` then `y)`: under `(x +`).
    ///
    /// ```
    /// use trigpoly::{Excerpt, Span};
    ///
    /// let src = "x/(x +\n  y) + 1";
    /// let excerpt = Excerpt::of(src, Span::new(2, 12));
    /// assert_eq!((excerpt.line, excerpt.column, excerpt.width), (1, 3, 4));
    /// let last = excerpt.last.expect("the span ends on line 2");
    /// assert_eq!((last.line, last.column, last.width), (2, 3, 2));
    /// assert_eq!((last.text.as_str(), last.pad.as_str()), ("  y) + 1", "  "));
    /// ```
    #[must_use]
    pub fn of(src: &str, span: Span) -> Excerpt {
        let start = char_floor(src, span.start);
        let line_end = src[start..].find('\n').map_or(src.len(), |i| start + i);
        let end = char_floor(src, span.end).max(start);
        // The span's end past the blanks it ends with (a line break after its text).
        let last_end = start + src[start..end].trim_end().len();
        if last_end <= line_end {
            return Excerpt::on_line(src, start, end.min(line_end), false);
        }
        // On a later line: the first line to its last character that is not blank, and the
        // line where the span ends from its first character that is not blank, so that each
        // caret is under text.
        let first_end = start + src[start..line_end].trim_end().len();
        let mut excerpt = Excerpt::on_line(src, start, first_end, false);
        let last_line = src[..last_end].rfind('\n').map_or(0, |i| i + 1);
        let text = &src[last_line..last_end];
        let from = last_line + text.len() - text.trim_start().len();
        excerpt.last = Some(Box::new(Excerpt::on_line(src, from, last_end, true)));
        excerpt
    }

    /// The excerpt of the line of `src` where byte `start` stands, the caret under
    /// `start..end` (which that line holds); of a long line, the window around the span's
    /// start, or, `at_end`, around its end (the line where a span over several lines ends,
    /// whose end is what it shows).
    fn on_line(src: &str, start: usize, end: usize, at_end: bool) -> Excerpt {
        let line_start = src[..start].rfind('\n').map_or(0, |i| i + 1);
        let line_end = src[start..].find('\n').map_or(src.len(), |i| start + i);
        let end = end.clamp(start, line_end);
        let line: Vec<char> = src[line_start..line_end]
            .trim_end_matches('\r')
            .chars()
            .collect();
        let column = src[line_start..start].chars().count();
        let width = src[start..end].chars().count().max(1);
        let (from, to) = if line.len() <= EXCERPT_CHARS {
            (0, line.len())
        } else if at_end {
            let end_column = column + width;
            let from = end_column.saturating_sub(width.min(EXCERPT_CONTEXT) + EXCERPT_CONTEXT);
            (from, (end_column + EXCERPT_CONTEXT).min(line.len()))
        } else {
            let to = column + width.min(EXCERPT_CONTEXT) + EXCERPT_CONTEXT;
            (column.saturating_sub(EXCERPT_CONTEXT), to.min(line.len()))
        };
        // Where the caret begins in the window: at the span's start, or at the window's
        // start where the window begins past it (the end of a long span).
        let caret = column.clamp(from, line.len());
        let cut_before = if from > 0 { "…" } else { "" };
        let cut_after = if to < line.len() { "…" } else { "" };
        let window: String = line[from..to].iter().collect();
        let pad: String = line[from..caret]
            .iter()
            .map(|&c| if c == '\t' { '\t' } else { ' ' })
            .collect();
        Excerpt {
            line: src[..start].matches('\n').count() + 1,
            column: column + 1,
            text: format!("{cut_before}{window}{cut_after}"),
            pad: " ".repeat(cut_before.chars().count()) + &pad,
            width: (column + width).min(to).saturating_sub(caret).max(1),
            last: None,
        }
    }
}

/// 1-based line and character column of byte `offset` in `src` (clamped to the source).
pub(crate) fn line_col(src: &str, offset: usize) -> (usize, usize) {
    let before = &src[..char_floor(src, offset)];
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (
        before.matches('\n').count() + 1,
        before[line_start..].chars().count() + 1,
    )
}

/// Where an opener at byte `open` of `src` stands, for a refusal at byte `here` of what it
/// opens: `column C` where both are on one line, else `line L, column C`.
fn opened_at(src: &str, open: usize, here: usize) -> String {
    let (line, col) = line_col(src, open);
    if line == line_col(src, here).0 {
        format!("column {col}")
    } else {
        format!("line {line}, column {col}")
    }
}

/// The largest char boundary of `src` that is at most `offset`.
fn char_floor(src: &str, offset: usize) -> usize {
    let mut i = offset.min(src.len());
    while !src.is_char_boundary(i) {
        i -= 1;
    }
    i
}
