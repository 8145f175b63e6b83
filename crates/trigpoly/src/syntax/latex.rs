//! LaTeX math in expressions, as a paper writes them and as superint prints them: commands
//! (`\omega`, `\frac`, `\cdot`, `\cos`), names with subscripts in braces (`p_{x}`,
//! `p_{\theta}`, `\omega_{x,2}`, `\bar{K}_{3,2}`), the bracket `\{f, g\}`, and spacing
//! (`\,`, `\quad`, `\left(`), which the lexer reads beside the plain syntax.
//!
//! A name written in LaTeX becomes the name the plain syntax reads: each letter command its
//! letter (`\omega` is `ω`, which names `omega` too), a subscript after `_`, its pieces
//! apart by `_` (`\omega_{x,2}` is `ω_x_2`, `K_{1,1}` is `K_1_1`), a bar `\bar{Z}` or
//! `\overline{Z}` the letter with a combining macron (`Z̄`, as a display name writes it).
//! A name that is printed otherwise than it is named (`G_{1}` of a function `G1`, `\bar{Z}`
//! of `Zbar`) is told by the system's names, where its LaTeX spells it
//! ([`latex_name`] of the LaTeX it prints).

use super::error::{ParseCause, ParseError, Span};
use super::lexer::{superscript_digit, Lexer, Tok};
use super::parser::{too_deep, MAX_DEPTH};
use crate::varset::{letter_of_char, letter_of_command};

/// Commands that space or set a style and mean nothing to an expression: `\quad`,
/// `\displaystyle`; the sizing commands, [`SIZING_OPEN`] and [`SIZING_CLOSE`], mean nothing
/// either but take a delimiter.
const IGNORED: &[&str] = &["quad", "qquad", "displaystyle", "textstyle"];

/// The sizing commands that open a pair or size a delimiter either way, which LaTeX requires
/// a delimiter after (`\left(`, `\bigl\{`, `\big(`, never `\left x`), and which a quote of
/// the parenthesis they size starts at (`Parser::sized`).
pub(super) const SIZING_OPEN: &[&str] = &[
    "left", "big", "Big", "bigg", "Bigg", "bigl", "Bigl", "biggl", "Biggl",
];

/// The sizing commands that close a pair, which likewise take a delimiter: `\right)`,
/// `\bigr\}`.
const SIZING_CLOSE: &[&str] = &["right", "bigr", "Bigr", "biggr", "Biggr"];

/// How the refusal of what is no part of a name in a name's braces begins, `p_{\left(}`,
/// `p_{x$}`, which the system file's scope reads for a display written there (`x_{ω̄}`).
pub const NOT_IN_NAME: &str = "expected a letter, a digit or '}' in the name's braces";

/// Whether `word` is a sizing command, [`SIZING_OPEN`] or [`SIZING_CLOSE`].
fn is_sizing(word: &str) -> bool {
    SIZING_OPEN.contains(&word) || SIZING_CLOSE.contains(&word)
}

/// What LaTeX takes for a delimiter after a sizing command: a character (`.` is the empty
/// one, `\left.`) or a command; superint reads `(`, `)`, `\{` and `\}`, and refuses the
/// others where they stand, as the characters and commands they are.
fn is_delimiter(rest: &str) -> bool {
    const COMMANDS: &[&str] = &[
        "{",
        "}",
        "|",
        "langle",
        "rangle",
        "lbrace",
        "rbrace",
        "lbrack",
        "rbrack",
        "vert",
        "Vert",
        "lvert",
        "rvert",
        "lVert",
        "rVert",
        "lfloor",
        "rfloor",
        "lceil",
        "rceil",
        "backslash",
        "uparrow",
        "downarrow",
        "updownarrow",
        "Uparrow",
        "Downarrow",
        "Updownarrow",
        "lgroup",
        "rgroup",
    ];
    match command(rest) {
        Some((word, _)) => COMMANDS.contains(&word),
        None => rest.starts_with(['(', ')', '[', ']', '|', '.', '/', '<', '>']),
    }
}

/// The commands of a fraction, `\frac{a}{b}` ([`Tok::Frac`]), which the parser takes for a
/// whole divisor as it does one in parentheses.
pub(super) const FRACTIONS: &[&str] = &["frac", "tfrac", "dfrac"];

/// Commands whose braces hold a name set upright: `\mathrm{i}`, `\operatorname{Re}`.
const UPRIGHT: &[&str] = &["mathrm", "operatorname", "mathit", "text"];

/// The name a text of LaTeX writes, when the whole text is one name: `p_{\theta}` → `p_θ`,
/// `G_{1}` → `G_1`, `\bar{K}` → `K̄`, `\omega_{x,2}` → `ω_x_2`; `None` for anything else
/// (`x y`, `\frac{1}{2}`). A system reads a name written in LaTeX as the name whose printed
/// LaTeX this spells the same.
///
/// ```
/// use trigpoly::syntax::latex_name;
///
/// assert_eq!(latex_name(r"p_{\theta}").as_deref(), Some("p_θ"));
/// assert_eq!(latex_name(r"\bar{K}_{3,2}").as_deref(), Some("K̄_3_2"));
/// assert_eq!(latex_name("G_{1}'").as_deref(), Some("G_1'"));
/// assert_eq!(latex_name(r"x \cdot y"), None);
/// ```
pub fn latex_name(src: &str) -> Option<String> {
    let mut lexer = Lexer::new(src);
    let Ok(token) = lexer.next_token() else {
        return None;
    };
    match (token.tok, lexer.next_token().map(|t| t.tok)) {
        (Tok::Name(name), Ok(Tok::Eof)) => Some(name),
        _ => None,
    }
}

/// The control word at the start of `rest` (after its backslash), and its length with the
/// backslash: `\omega x` → (`omega`, 6); a control symbol, `\,`, is its one character.
fn command(rest: &str) -> Option<(&str, usize)> {
    let after = rest.strip_prefix('\\')?;
    let letters = after
        .find(|c: char| !c.is_ascii_alphabetic())
        .unwrap_or(after.len());
    if letters > 0 {
        return Some((&after[..letters], letters + 1));
    }
    let c = after.chars().next()?;
    Some((&after[..c.len_utf8()], c.len_utf8() + 1))
}

/// The token of a command that an expression reads as no name: an operator (`\cdot`), `\frac`,
/// `\sqrt`, a brace of a bracket `\{ \}`, or a function (`\cos`, whose name it is); `None`
/// for any other, a name's command (`\omega`, `\bar`) or an unknown one.
fn command_token(word: &str) -> Option<Tok> {
    Some(match word {
        "{" => Tok::LBrace,
        "}" => Tok::RBrace,
        "cdot" | "times" | "ast" => Tok::Star,
        "div" => Tok::Slash,
        _ if FRACTIONS.contains(&word) => Tok::Frac,
        "sqrt" => Tok::Sqrt,
        "cos" | "sin" | "exp" | "Re" | "Im" => Tok::Name(word.to_string()),
        _ => return None,
    })
}

/// The error for a backslash at the end of the text, at `span`.
fn no_command(span: Span) -> ParseError {
    ParseError::new(
        span,
        "expected a LaTeX command after '\\', found end of input",
    )
}

impl Lexer<'_> {
    /// The length of the spacing or sizing command at the start of `rest` (`\,`, `\quad`,
    /// `\left`), which is skipped as a space is; `None` for any other text. A sizing command
    /// with no delimiter after it (`\left x`, which LaTeX refuses) is an error, at the
    /// command, which stands at byte `at` of the source.
    pub(crate) fn latex_space(rest: &str, at: usize) -> Result<Option<usize>, ParseError> {
        let Some((word, len)) = command(rest) else {
            return Ok(None);
        };
        let closing = SIZING_CLOSE.contains(&word);
        let sizing = is_sizing(word);
        let space = matches!(word, "," | ";" | ":" | "!" | " ") || IGNORED.contains(&word);
        if !space && !sizing {
            return Ok(None);
        }
        let after = rest[len..].trim_start();
        if sizing && !is_delimiter(after) {
            let found = match after.chars().next() {
                None => "end of input".to_string(),
                Some('\\') => match command(after) {
                    Some((next, _)) => format!("'\\{next}'"),
                    None => "'\\'".to_string(),
                },
                Some(c) => format!("'{c}'"),
            };
            let (paren, brace) = match closing {
                true => (")", "\\}"),
                false => ("(", "\\{"),
            };
            return Err(ParseError::new(
                Span::new(at, at + len),
                format!(
                    "'\\{word}' takes a delimiter after it, as in LaTeX ('\\{word}{paren}', \
                     '\\{word}{brace}'), found {found}; leave it out where none is meant"
                ),
            ));
        }
        Ok(Some(len))
    }

    /// The length of the empty group at the start of `rest` that carries a superscript
    /// (`{}^{2}`, as superint prints the square of `P'_{1,1}`, or a superscript character,
    /// `{}²`, which a Unicode LaTeX sets as `{}^{2}`), which is skipped as a space is, the
    /// power going to what stands before it (which the parser refuses where that has an
    /// exponent already, `x^{2}{}^{3}`, `x^{2}{}²`, or is a bare angle after a function,
    /// `sin²θ{}²`); `None` for any other text, an empty group elsewhere being refused by the
    /// parser (a subscript on one, `x{}_{1}`, too: a subscript is part of a name, and the
    /// group would leave it none).
    pub(crate) fn empty_base(rest: &str) -> Option<usize> {
        let inside = rest.strip_prefix('{')?.trim_start();
        let after = inside.strip_prefix('}')?;
        let script = |c: char| c == '^' || c == '⁻' || superscript_digit(c).is_some();
        after
            .trim_start()
            .starts_with(script)
            .then_some(rest.len() - after.len())
    }

    /// The token of the command whose backslash is at `start` (already consumed): an
    /// operator, `\frac`, `\sqrt`, a brace of a bracket `\{ \}`, or a name.
    pub(crate) fn latex_token(&mut self, start: usize) -> Result<Tok, ParseError> {
        let Some((word, len)) = command(&self.src[start..]) else {
            return Err(no_command(Span::new(start, self.pos)));
        };
        let Some(tok) = command_token(word) else {
            self.pos = start;
            let name = self.latex_base()?;
            return Ok(Tok::Name(self.name_rest(name, true)?));
        };
        self.pos = start + len;
        Ok(tok)
    }

    /// A name that starts with a command at the current position: a letter (`\omega`), a bar
    /// over a name (`\bar{Z}`), or an upright name (`\mathrm{i}`, `\operatorname{Re}`).
    fn latex_base(&mut self) -> Result<String, ParseError> {
        let start = self.pos;
        let Some((word, len)) = command(&self.src[start..]) else {
            return Err(no_command(Span::new(start, self.src.len())));
        };
        self.pos = start + len;
        if let Some(letter) = letter_of_command(word) {
            return Ok(letter.to_string());
        }
        let barred = matches!(word, "bar" | "overline");
        if !barred && !UPRIGHT.contains(&word) {
            return Err(self.unknown_command(start, word));
        }
        let inner = self.group(start, word)?;
        match (inner.is_empty(), barred) {
            (true, _) => Err(self.empty_group(start, word)),
            (false, true) => Ok(format!("{inner}\u{304}")),
            (false, false) => Ok(inner),
        }
    }

    /// The error for an unknown command `\word` at `start`.
    fn unknown_command(&self, start: usize, word: &str) -> ParseError {
        let len = word.len() + 1;
        let span = Span::new(start, start + len);
        ParseError::new(
            span,
            format!(
                "unknown LaTeX command '\\{word}': an expression reads Greek letters (\\omega), \
                 \\frac, \\sqrt, \\cdot, \\times, \\cos, \\sin, \\exp, \\bar, \\mathrm, \\{{ \\}} \
                 and spacing"
            ),
        )
        .with_cause(ParseCause::Unreadable)
    }

    /// The error for `\word{}` with nothing in its braces.
    fn empty_group(&self, start: usize, word: &str) -> ParseError {
        let span = Span::new(start, self.pos);
        ParseError::new(span, format!("'\\{word}{{}}' holds no name"))
    }

    /// The name after a name `name` (a plain name's letters, or a command's): a subscript
    /// after `_` (for a plain name, one in braces or a command, `p_{x}` and `p_\theta`, the
    /// plain `p_x` being the plain name's own) and the primes after a name written in LaTeX
    /// (`G_{1}'`).
    pub(crate) fn name_rest(&mut self, name: String, latex: bool) -> Result<String, ParseError> {
        // Primes, `y'`, as LaTeX writes a display name `y'`, and before a subscript, `K'_{2,3}`.
        let primed = !name.ends_with('_') && self.src[self.pos..].starts_with('\'');
        let mut name = self.primes(name);
        let latex = latex || primed;
        let rest = &self.src[self.pos..];
        let subscript = match name.ends_with('_') {
            // The plain name took the `_`.
            true => rest.starts_with(['{', '\\']),
            false if latex && rest.starts_with('_') => {
                self.pos += 1;
                name.push('_');
                true
            }
            false => false,
        };
        if !subscript {
            return Ok(name);
        }
        let piece = self.script()?;
        name.push_str(&piece);
        Ok(self.primes(name))
    }

    /// `name` with the primes after it (`G_{1}'`, `y'`).
    fn primes(&mut self, mut name: String) -> String {
        while self.src[self.pos..].starts_with('\'') {
            self.pos += 1;
            name.push('\'');
        }
        name
    }

    /// A subscript after its `_`: a group in braces, a command of a name, or one letter or
    /// digit; a command that is no name's, `p_\frac`, `p_\,`, is refused as a character
    /// that begins none is (a backslash alone, `p_\`, as after any other text).
    fn script(&mut self) -> Result<String, ParseError> {
        let start = self.pos;
        let rest = &self.src[start..];
        let named = |(word, _): (&str, usize)| command_token(word).is_none();
        let name_command = command(rest).is_none_or(named)
            && Self::latex_space(rest, start).is_ok_and(|space| space.is_none());
        match rest.chars().next() {
            Some('{') => self.group_at(start),
            Some('\\') if name_command => self.latex_base(),
            Some(c) if c.is_alphanumeric() => {
                self.pos += c.len_utf8();
                Ok(letter_of_char(c).to_string())
            }
            _ => {
                let end = match command(rest) {
                    Some((_, len)) => len,
                    None => rest.chars().next().map_or(0, char::len_utf8),
                };
                let span = Span::new(start.saturating_sub(1), start + end);
                Err(ParseError::new(
                    span,
                    "expected a subscript after '_': a letter, a digit, or a name in braces, \
                     p_{x}",
                ))
            }
        }
    }

    /// The braces after `\word` (at `start`), which must follow it, and the name they hold.
    fn group(&mut self, start: usize, word: &str) -> Result<String, ParseError> {
        let at = self.pos;
        if !self.src[at..].starts_with('{') {
            let span = Span::new(start, at);
            return Err(ParseError::new(
                span,
                format!("expected '{{' after '\\{word}', as in \\{word}{{Z}}"),
            ));
        }
        self.group_at(at)
    }

    /// The name a group in braces at `open` holds, its pieces apart by `_` (a `,` or `;`
    /// between them, as family indices are written) and its letters' commands as letters:
    /// `{x,2}` → `x_2`, `{\theta}` → `θ`.
    fn group_at(&mut self, open: usize) -> Result<String, ParseError> {
        if self.groups >= MAX_DEPTH {
            return Err(too_deep(Span::new(open, open + 1)));
        }
        self.groups += 1;
        let name = self.group_name(open);
        self.groups -= 1;
        name
    }

    /// [`Self::group_at`]'s reading of the group, one level deeper.
    fn group_name(&mut self, open: usize) -> Result<String, ParseError> {
        self.pos = open + 1;
        let mut out = String::new();
        loop {
            let rest = &self.src[self.pos..];
            let Some(c) = rest.chars().next() else {
                let span = Span::new(open, open + 1);
                return Err(ParseError::new(
                    span,
                    "the '{' of this name is never closed: expected '}'",
                ));
            };
            match c {
                '}' => {
                    self.pos += 1;
                    return Ok(out);
                }
                c if c.is_whitespace() => self.pos += c.len_utf8(),
                ',' | ';' | '_' => {
                    self.pos += 1;
                    out.push('_');
                }
                '{' => out.push_str(&self.group_at(self.pos)?),
                '\\' => match (Self::latex_space(rest, self.pos)?, command(rest)) {
                    // A sizing command and its delimiter, `\left(`: no part of a name, as `(`
                    // is none; it was skipped as a space, and the delimiter quoted alone.
                    (Some(len), Some((word, _))) if is_sizing(word) => {
                        let after = &rest[len..];
                        let delimiter = after.trim_start();
                        let spaces = after.len() - delimiter.len();
                        let width = command(delimiter).map_or_else(
                            || delimiter.chars().next().map_or(0, char::len_utf8),
                            |(_, width)| width,
                        );
                        let span = Span::new(self.pos, self.pos + len + spaces + width);
                        return Err(self.not_in_name(open, span));
                    }
                    (Some(len), _) => self.pos += len,
                    // An operator, `\frac`, `\{`: no part of a name, as `/` is none.
                    (None, Some((word, len))) if command_token(word).is_some() => {
                        let span = Span::new(self.pos, self.pos + len);
                        return Err(self.not_in_name(open, span));
                    }
                    (None, _) => out.push_str(&self.latex_base()?),
                },
                '+' | '-' | '\'' => {
                    self.pos += 1;
                    out.push(c);
                }
                c if c.is_alphanumeric() => {
                    self.pos += c.len_utf8();
                    out.push(letter_of_char(c));
                }
                c => {
                    let span = Span::new(self.pos, self.pos + c.len_utf8());
                    return Err(self.not_in_name(open, span));
                }
            }
        }
    }

    /// The error for the text at `span`, no part of a name, in the braces of a name opened at
    /// byte `open`: what they hold, and where they open.
    fn not_in_name(&self, open: usize, span: Span) -> ParseError {
        let found = &self.src[span.start..span.end];
        ParseError::naming_opener(
            self.src,
            span,
            open,
            &format!("{NOT_IN_NAME} opened at "),
            &format!(", found '{found}'"),
        )
        .with_cause(ParseCause::Unreadable)
    }
}
