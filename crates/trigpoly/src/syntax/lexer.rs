//! Lexer: splits source text into spanned tokens, one at a time.
//!
//! Besides ASCII operators it accepts `−` (U+2212) as minus; `·`, `⋅`, `∗` and `×` as
//! multiplication; `÷` as division; `**` as `^`; and runs of unicode superscript digits
//! (optionally preceded by `⁻`) as a single superscript exponent token. Any unicode whitespace
//! (and a byte-order mark) separates tokens, and so does LaTeX's spacing (`\,`, `\quad`,
//! `\left`); LaTeX's commands are read by [`super::latex`].

use num_bigint::BigInt;

use super::error::{ParseCause, ParseError, Span};
use super::parser::{Reading, Unread};
use crate::varset::letter_of_char;

/// The kind of a token, with its value for literals, names and superscripts.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Tok {
    /// Non-negative decimal integer literal.
    Int(BigInt),
    /// Identifier.
    Name(String),
    /// Superscript exponent such as `²` or `⁻¹`.
    Sup {
        value: BigInt,
        negative: bool,
    },
    Plus,
    Minus,
    Star,
    Slash,
    Caret,
    LParen,
    RParen,
    LBrace,
    RBrace,
    Comma,
    /// `\frac`, `\tfrac` or `\dfrac`, whose two groups in braces follow.
    Frac,
    /// `\sqrt`, whose group in braces follows.
    Sqrt,
    /// `√`, as the text form prints a root: its radicand in parentheses, `√(x² + y²)`, or a
    /// name, `√x`.
    Root,
    Eof,
}

impl Tok {
    /// Whether this token can begin an operand (used to detect implicit multiplication).
    pub(crate) fn starts_operand(&self) -> bool {
        matches!(
            self,
            Tok::Int(_)
                | Tok::Name(_)
                | Tok::LParen
                | Tok::LBrace
                | Tok::Frac
                | Tok::Sqrt
                | Tok::Root
        )
    }
}

/// A token together with its location in the source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Token {
    pub(crate) tok: Tok,
    pub(crate) span: Span,
}

/// The ASCII digit corresponding to a superscript digit such as `²`, if `c` is one.
pub(super) fn superscript_digit(c: char) -> Option<char> {
    if c.is_ascii() {
        return None;
    }
    let value = "⁰¹²³⁴⁵⁶⁷⁸⁹".chars().position(|d| d == c)?;
    char::from_digit(value as u32, 10)
}

/// Whether a name may begin with `c`: a letter or `_`.
pub fn is_name_start(c: char) -> bool {
    c == '_' || c.is_alphabetic()
}

/// Whether a name goes on with `c`: a letter, a digit or `_`, but a superscript digit, a power
/// after the name; or a subscript sign, `₊` or `₋`, which a display name has after what it
/// stands under (the Fock–Darwin `ω₊`, as the text form prints it).
pub fn is_name_continue(c: char) -> bool {
    // Superscript digits are numeric, but `x²` must lex as `x` followed by an exponent.
    c == '_' || matches!(c, '₊' | '₋') || (c.is_alphanumeric() && superscript_digit(c).is_none())
}

/// On-demand tokenizer over a source string.
pub(crate) struct Lexer<'a> {
    pub(super) src: &'a str,
    pub(super) pos: usize,
    /// How many groups in braces of a name (`x_{a_{b}}`, `\bar{\bar{Z}}`) are open, limited
    /// to [`super::MAX_DEPTH`] as the parser's nesting is, so that reading them cannot
    /// overflow the stack.
    pub(super) groups: usize,
    /// What the names read as, for a bar's message: how the conjugate of the name under it
    /// is written ([`Reading::conjugate`]; of no names, `conj(x)` of any name).
    names: &'a dyn Reading,
}

impl<'a> Lexer<'a> {
    pub(crate) fn new(src: &'a str) -> Self {
        Lexer {
            src,
            pos: 0,
            groups: 0,
            names: &Unread,
        }
    }

    /// A lexer of `src` whose bar's message says how `names` write a name's conjugate.
    pub(crate) fn reading(src: &'a str, names: &'a dyn Reading) -> Self {
        Lexer {
            names,
            ..Lexer::new(src)
        }
    }

    fn peek(&self) -> Option<char> {
        self.src[self.pos..].chars().next()
    }

    /// Consumes characters while `pred` holds and returns them.
    fn eat_while(&mut self, pred: impl Fn(char) -> bool) -> &'a str {
        let start = self.pos;
        let rest = &self.src[start..];
        self.pos += rest.find(|c| !pred(c)).unwrap_or(rest.len());
        &self.src[start..self.pos]
    }

    /// The next token, or `Tok::Eof` once the input is exhausted. The span of `Eof` is empty and
    /// placed just after the last non-whitespace character, so that errors there point at the
    /// end of the last line of the expression rather than at trailing blank lines; in a text
    /// of blanks alone, at the end of its first line (`"   "`: column 4, past the spaces).
    pub(crate) fn next_token(&mut self) -> Result<Token, ParseError> {
        loop {
            self.eat_while(|c| c.is_whitespace() || c == '\u{feff}');
            let rest = &self.src[self.pos..];
            match Self::latex_space(rest, self.pos)?.or_else(|| Self::empty_base(rest)) {
                Some(len) => self.pos += len,
                None => break,
            }
        }
        let start = self.pos;
        let Some(c) = self.peek() else {
            let end = match self.src.trim_end().len() {
                0 => self.src.find(['\n', '\r']).unwrap_or(self.src.len()),
                end => end,
            };
            return Ok(Token {
                tok: Tok::Eof,
                span: Span::new(end, end),
            });
        };
        self.pos += c.len_utf8();
        let tok = match c {
            '0'..='9' => {
                self.pos = start;
                let digits = self.eat_while(|c| c.is_ascii_digit());
                if self.peek() == Some('.') {
                    self.pos += 1;
                    return Err(self.decimal_error(start));
                }
                if let Some(error) = self.exponent_notation(start) {
                    return Err(error);
                }
                Tok::Int(digits.parse().expect("ASCII digits form an integer"))
            }
            '.' if self.peek().is_some_and(|c| c.is_ascii_digit()) => {
                return Err(self.decimal_error(start))
            }
            c if is_name_start(c) => {
                self.eat_while(is_name_continue);
                let name = self.src[start..self.pos]
                    .chars()
                    .map(letter_of_char)
                    .collect();
                Tok::Name(self.name_rest(name, false)?)
            }
            '\\' => self.latex_token(start)?,
            '+' => Tok::Plus,
            '-' | '−' => Tok::Minus,
            '*' if self.peek() == Some('*') => {
                self.pos += 1;
                Tok::Caret
            }
            '*' | '·' | '⋅' | '×' | '∗' => Tok::Star,
            '/' | '÷' => Tok::Slash,
            '^' => Tok::Caret,
            '(' => Tok::LParen,
            ')' => Tok::RParen,
            '{' => Tok::LBrace,
            '}' => Tok::RBrace,
            ',' => Tok::Comma,
            '√' => Tok::Root,
            c if c == '⁻' || superscript_digit(c).is_some() => {
                let negative = c == '⁻';
                if !negative {
                    self.pos = start;
                }
                let digits: String = self
                    .eat_while(|c| superscript_digit(c).is_some())
                    .chars()
                    .filter_map(superscript_digit)
                    .collect();
                if digits.is_empty() {
                    let span = Span::new(start, self.pos);
                    let msg = "expected superscript digits such as '¹' after superscript minus '⁻'";
                    return Err(ParseError::new(span, msg));
                }
                let value = digits.parse().expect("digits form an integer");
                Tok::Sup { value, negative }
            }
            c => {
                let span = Span::new(start, self.pos);
                let hint = match c {
                    '½' | '⅓' | '⅔' | '¼' | '¾' | '⅕'..='⅞' => {
                        "; write a fraction such as 1/2"
                    }
                    '⁄' => "; write '/'",
                    '‐'..='―' => "; a dash is no minus sign: write '-' or '−'",
                    // Mathematica's `Sqrt[x^2 + y^2]`, `Cos[theta]`, `D[f, x]`.
                    '[' | ']' => {
                        "; a function takes its argument in parentheses, sqrt(x^2 + y^2), \
                         cos(theta), not square brackets, and the Poisson bracket is written \
                         {f, g}"
                    }
                    '=' => {
                        "; an expression has no '=' (a claim has one, a condition one per variable)"
                    }
                    // `x̄`, as a paper writes the conjugate (a function displayed with a bar is
                    // named by its caller): the conjugate of the name under the bar.
                    '\u{304}' => &self.bar_hint(start),
                    _ => "",
                };
                return Err(
                    ParseError::new(span, format!("unexpected character {c:?}{hint}"))
                        .with_cause(ParseCause::Unreadable),
                );
            }
        };
        Ok(Token {
            tok,
            span: Span::new(start, self.pos),
        })
    }

    /// What a combining bar (U+0304) at `bar` says: that it is no operation, and the call of
    /// the conjugate of the name it stands in, `conj(x)` of `x̄`, `conj(K_3_2)` of `K̄_3_2`
    /// (as a barred name's lowering says it, of `ȳ` and `\bar{y}`); of anything else, a
    /// number or parentheses, `conj(A)` of a name `A`.
    fn bar_hint(&self, bar: usize) -> String {
        let before = &self.src[..bar];
        let from = (before.char_indices().rev())
            .take_while(|&(_, c)| is_name_continue(c))
            .last()
            .map_or(bar, |(k, _)| k);
        let after = &self.src[bar + '\u{304}'.len_utf8()..];
        let to = after.find(|c| !is_name_continue(c)).unwrap_or(after.len());
        // A coefficient before the name is none of it: `2x̄` is `2·x̄`.
        let under = before[from..].trim_start_matches(|c| !is_name_start(c));
        if under.is_empty() {
            return "; a bar is no operation: the complex conjugate of A is conj(A)".to_string();
        }
        let name = format!("{under}{}", &after[..to]);
        format!("; a bar is no operation: {}", self.names.conjugate(&name))
    }

    /// Error for a number written with an exponent, `1e3` or `2E-5`, whose digits end here.
    fn exponent_notation(&mut self, start: usize) -> Option<ParseError> {
        let rest = &self.src[self.pos..];
        let after_e = rest.strip_prefix(['e', 'E'])?;
        let digits = after_e.strip_prefix(['-', '+']).unwrap_or(after_e);
        if !digits.starts_with(|c: char| c.is_ascii_digit()) {
            return None;
        }
        self.pos = self.src.len() - digits.len();
        self.eat_while(|c| c.is_ascii_digit());
        let written = &self.src[start..self.pos];
        let (number, name) = written.split_at(self.src.len() - rest.len() - start);
        let power = format!(
            "'{written}' is no number: write a power of ten as {number}*10^{}",
            &name[1..]
        );
        let message = match digits.len() < after_e.len() {
            // A sign after the e: only a power of ten was meant.
            true => power,
            false => format!("{power}, and a product with a name as {number}*{name}"),
        };
        Some(ParseError::new(Span::new(start, self.pos), message))
    }

    /// Error for a decimal number starting at `start`; consumes its remaining digits. The
    /// message names the fraction the decimal writes (`0.5 is 1/2`), as `plot` and `--fix`
    /// read it, so that it can be copied in.
    fn decimal_error(&mut self, start: usize) -> ParseError {
        self.eat_while(|c| c.is_ascii_digit());
        let written = &self.src[start..self.pos];
        let message = match decimal_fraction(written) {
            Some(fraction) => {
                format!("decimal numbers are not exact; write a fraction: {written} is {fraction}")
            }
            None => "decimal numbers are not exact; write a fraction such as 3/2".to_string(),
        };
        ParseError::new(Span::new(start, self.pos), message).with_cause(ParseCause::Decimal)
    }
}

/// The fraction in lowest terms that a decimal `1.5`, `.25` or `2.` writes (`3/2`, `1/4`,
/// `2`); `None` when it has too many digits for a machine integer.
fn decimal_fraction(written: &str) -> Option<String> {
    let (whole, fractional) = written.split_once('.')?;
    if whole.len() + fractional.len() > 36 {
        return None;
    }
    let digits = format!("{whole}{fractional}");
    let numerator: u128 = if digits.is_empty() {
        0
    } else {
        digits.parse().ok()?
    };
    let denominator = 10u128.checked_pow(u32::try_from(fractional.len()).ok()?)?;
    let (mut a, mut b) = (numerator, denominator);
    while b != 0 {
        (a, b) = (b, a % b);
    }
    let (n, d) = (numerator / a, denominator / a);
    Some(match d {
        1 => n.to_string(),
        _ => format!("{n}/{d}"),
    })
}

/// How the conjugate of `name` is written, which a bar over it is not (`x̄`, `ȳ`, `\bar{y}`):
/// `the complex conjugate of y is written conj(y)`, of the lexer's and the lowering's messages.
pub(crate) fn conjugate_written(name: &str) -> String {
    format!("the complex conjugate of {name} is written conj({name})")
}
