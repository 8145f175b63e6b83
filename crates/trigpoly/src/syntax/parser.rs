//! Pratt parser producing the spanned expression tree [`Expr`].
//!
//! Binding powers, loosest first: binary `+ -` (left associative), binary `* /` (left
//! associative), unary `-`/`+`, `^` and superscript exponents (right associative, binding tighter
//! than a unary minus on their left), then calls `f(a, b)`, parentheses and brackets `{f, g}`.

use num_bigint::BigInt;

use super::error::{ParseError, Span};
use super::latex::{FRACTIONS, SIZING_OPEN};
use super::lexer::{conjugate_written, Lexer, Tok, Token};
use crate::lower::calls_function;

/// Maximum nesting of parentheses, calls, brackets and operators (the operand of an operator
/// counts as nested in it, so `(a + (b))` has 2 levels and `a + b*(c^d)` has 4).
pub const MAX_DEPTH: usize = 256;

/// Maximum height of a parsed tree (a leaf has height 1). Chains such as `a + b + c` are
/// left-deep, so a product of `n` factors has height at least `n`; a sum of more than
/// [`LEFT_DEEP_SUM`] terms is balanced instead, about `log₂ n` high, so that a printed
/// polynomial of any length reads back. Consumers recursing over an [`Expr`] need stack for
/// this many levels.
pub const MAX_HEIGHT: usize = 2048;

/// The longest sum parsed as the left-deep chain it reads as (`a − b + c` is `(a − b) + c`);
/// a longer one is a balanced tree of the same terms and signs (`(a − b) + (c − d)` for
/// `a − b + c − d`), whose height grows as the logarithm of its length.
pub const LEFT_DEEP_SUM: usize = 64;

/// `items` joined pairwise, level by level, into one balanced tree about `log₂ n` high
/// (`(a b)(c d)` of `a, b, c, d`; an odd one out is carried up a level as it is), as the parser
/// joins a sum longer than [`LEFT_DEEP_SUM`]: for a consumer that builds a long chain of its
/// own and recurses over it. `None` of no items; the first error of `join`.
pub fn balanced<T, E>(
    mut items: Vec<T>,
    mut join: impl FnMut(T, T) -> Result<T, E>,
) -> Result<Option<T>, E> {
    while items.len() > 1 {
        let mut pairs = Vec::with_capacity(items.len().div_ceil(2));
        let mut rest = items.into_iter();
        while let Some(a) = rest.next() {
            pairs.push(match rest.next() {
                Some(b) => join(a, b)?,
                None => a,
            });
        }
        items = pairs;
    }
    Ok(items.pop())
}

/// Right binding power of unary `-` and `+`.
const UNARY_BP: u8 = 5;

/// Right binding power of `^`: what is parsed at it is an exponent.
const EXPONENT_BP: u8 = 6;

/// A parsed expression with its span.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Expr {
    /// What the expression is.
    pub kind: ExprKind,
    /// Where it is in the source; a parenthesized expression's span includes the parentheses.
    pub span: Span,
}

impl Expr {
    /// An expression of the given kind at `span`.
    #[must_use]
    pub fn new(kind: ExprKind, span: Span) -> Self {
        Expr { kind, span }
    }

    /// Whether the node was written in parentheses, which the tree keeps in its span (wider
    /// than a name, or starting before a call's name): `(Mω)²` and `(M(x + y))²` take their
    /// power whole, `Mω²` and `M(x + y)²` do not. A name written in LaTeX (`p_{x}`, `\omega`)
    /// is wider than its name too, and is so one name whose power is its own. Other nodes
    /// answer `false`.
    pub fn in_parentheses(&self) -> bool {
        match &self.kind {
            ExprKind::Name(n) => self.span.end - self.span.start > n.len(),
            ExprKind::Call(_, name_span, _) => self.span.start < name_span.start,
            _ => false,
        }
    }

    /// The names the expression uses, with their spans, in source order (a call's arguments'
    /// names, not the function's).
    pub fn names(&self) -> Vec<(&str, Span)> {
        self.names_with_calls(false)
    }

    /// The names the expression uses, with their spans, in source order, and the names it
    /// calls too when `calls` (`K_1_1` of `K_1_1(x)`, where a name before parentheses may
    /// multiply them).
    pub fn names_with_calls(&self, calls: bool) -> Vec<(&str, Span)> {
        fn walk<'e>(e: &'e Expr, calls: bool, out: &mut Vec<(&'e str, Span)>) {
            match &e.kind {
                ExprKind::Integer(_) => {}
                ExprKind::Name(n) => out.push((n, e.span)),
                ExprKind::Neg(a) => walk(a, calls, out),
                ExprKind::Add(a, b)
                | ExprKind::Sub(a, b)
                | ExprKind::Mul(a, b)
                | ExprKind::Div(a, b)
                | ExprKind::Pow(a, b)
                | ExprKind::Bracket(a, b) => {
                    walk(a, calls, out);
                    walk(b, calls, out);
                }
                ExprKind::Call(f, span, args) => {
                    if calls {
                        out.push((f, *span));
                    }
                    args.iter().for_each(|a| walk(a, calls, out));
                }
            }
        }
        let mut out = Vec::new();
        walk(self, calls, &mut out);
        out
    }
}

/// The node types of the expression tree.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ExprKind {
    /// Non-negative integer literal (`-2` is `Neg(Integer(2))`).
    Integer(BigInt),
    /// Identifier such as `x`, `p_θ` or `i` (the imaginary unit is decided later).
    Name(String),
    /// Unary minus.
    Neg(Box<Expr>),
    /// `a + b`.
    Add(Box<Expr>, Box<Expr>),
    /// `a - b`.
    Sub(Box<Expr>, Box<Expr>),
    /// `a * b`.
    Mul(Box<Expr>, Box<Expr>),
    /// `a / b`.
    Div(Box<Expr>, Box<Expr>),
    /// `base ^ exponent`; also `x²` and `x⁻¹`, whose exponent is `Integer` or `Neg(Integer)`.
    Pow(Box<Expr>, Box<Expr>),
    /// Function call `f(a, b, ...)`: name, span of the name, and at least one argument.
    Call(String, Span, Vec<Expr>),
    /// Bracket `{f, g}` of two expressions.
    Bracket(Box<Expr>, Box<Expr>),
}

/// Parses `src`, which must consist of exactly one expression.
///
/// # Errors
///
/// Returns the first lexical or syntax error in `src`, which knows its place in `src` (its
/// `Display` shows the line and a caret).
pub fn parse_expr(src: &str) -> Result<Expr, ParseError> {
    parse_expr_reading(src, &Unread)
}

/// Parses `src` as [`parse_expr`] does, to the same tree, a refusal quoting the factor that a
/// power raises as `names` read the names before it (`'ω^{2}'` of `Mω^{2}{}^{3}`, where `Mω`
/// reads as `M·ω`).
///
/// # Errors
///
/// Those of [`parse_expr`], in the same places.
pub(crate) fn parse_expr_reading(src: &str, names: &dyn Reading) -> Result<Expr, ParseError> {
    parse_source(src, names).map_err(|e| e.in_source(src))
}

/// What the names of an expression read as, which the parser, purely syntactic, asks only to
/// word a refusal: the lowering reads them ([`crate::Poly::parse_with`]).
pub(crate) trait Reading {
    /// Whether `name` before parentheses calls a function, `cos(θ)`, `sqrt(R)`, `Re(Z)`, rather
    /// than multiplies them, `M(x + y)`, `Re(x + y)` where the system declares `Re`.
    fn calls(&self, name: &str) -> bool;
    /// The names that `name`, written without parentheses, reads as a product of (`M`, `ω` of
    /// `Mω`), if it is one.
    fn split(&self, name: &str) -> Option<Vec<String>>;
    /// How the conjugate of `name` is written, of a bar over it (`x̄`, `\bar{y}`), which is
    /// no operation: [`conjugate_written`]'s `conj(y)` unless the name is one `conj` does not
    /// take.
    fn conjugate(&self, name: &str) -> String {
        conjugate_written(name)
    }
}

/// The reading of no names: none splits, and `Re` and `Im` are the real and imaginary parts.
pub(crate) struct Unread;

impl Reading for Unread {
    fn calls(&self, name: &str) -> bool {
        calls_function(name, &|_| false)
    }
    fn split(&self, _: &str) -> Option<Vec<String>> {
        None
    }
}

/// [`parse_expr_reading`], its error without its source.
fn parse_source(src: &str, names: &dyn Reading) -> Result<Expr, ParseError> {
    let mut lexer = Lexer::reading(src, names);
    let tok = lexer.next_token()?;
    let mut p = Parser {
        src,
        names,
        lexer,
        tok,
        prev: None,
        depth: 0,
        height: 0,
    };
    let expr = p.expr(0)?;
    match p.tok.tok {
        Tok::Eof => Ok(expr),
        ref t if t.starts_operand() => Err(p.implicit_mul()),
        _ => Err(p.error(format!("unexpected {}", p.found()))),
    }
}

/// How a `^` after a superscript character reads with it, `r²^3` or `sin²^3θ` (or after a
/// function's exponent in LaTeX, `\sin^{2}^{3}\theta`), in the
/// refusals of [`Parser::caret_after_superscript`] and [`Parser::trig_without_parens`].
const RAISES_EITHER: &str = "it may raise the power or its exponent";

/// The advice after two superscripts in doubt, `x^{2}{}^{3}`, `r²^3`, `sin² ²θ`
/// ([`Parser::superscript_already`]).
const ONE_GROUP: &str = "write the exponent in one group";

/// Parser state: the current (not yet consumed) token and the span of the previous one.
struct Parser<'a> {
    src: &'a str,
    /// What the names read as, for the factor a refusal quotes ([`Parser::powered`]).
    names: &'a dyn Reading,
    lexer: Lexer<'a>,
    tok: Token,
    prev: Option<Span>,
    depth: usize,
    /// Height of the tree most recently returned by a parsing method.
    height: usize,
}

type PResult<T> = Result<T, ParseError>;

impl Parser<'_> {
    /// Consumes the current token and returns it.
    fn bump(&mut self) -> PResult<Token> {
        let next = self.lexer.next_token()?;
        let tok = std::mem::replace(&mut self.tok, next);
        self.prev = Some(tok.span);
        Ok(tok)
    }

    /// Source text of `span`, quoted, shortened if long.
    fn quote(&self, span: Span) -> String {
        let text = &self.src[span.start..span.end];
        match text.char_indices().nth(20) {
            Some((i, _)) => format!("'{}…'", &text[..i]),
            None => format!("'{text}'"),
        }
    }

    /// Description of the current token for "found ..." messages.
    fn found(&self) -> String {
        match self.tok.tok {
            Tok::Eof => "end of input".to_string(),
            Tok::Sup { .. } => format!("superscript {}", self.quote(self.tok.span)),
            _ => self.quote(self.tok.span),
        }
    }

    /// An error located at the current token.
    fn error(&self, message: String) -> ParseError {
        ParseError::new(self.tok.span, message)
    }

    /// Error for an operand directly following another operand, e.g. `2x`.
    fn implicit_mul(&self) -> ParseError {
        let prev = self.prev.map_or_else(String::new, |s| self.quote(s));
        let found = self.quote(self.tok.span);
        self.error(format!(
            "expected an operator such as '*' between {prev} and {found}"
        ))
    }

    /// Whether the name `name` of the current token is called: parentheses follow it,
    /// `sqrt(x)`, `Re(x)`, or, after `e`, a braced exponent, `e^{iθ}`.
    fn call_follows(&self, name: &str) -> bool {
        let rest = self.src[self.tok.span.end..].trim_start();
        rest.starts_with('(')
            || (name == "e"
                && (rest.strip_prefix('^')).is_some_and(|r| r.trim_start().starts_with('{')))
    }

    /// Error for a factor written next to the divisor of a `/`, as in `p_x^2/2m`: the rules
    /// read it as `(p_x^2/2)·m`, a reader of physics as `p_x^2/(2m)`, so neither is guessed.
    /// A function before its angle or its arguments, `p²/2 cos θ`, `x/2 sqrt(x)`,
    /// `x/2 e^{iθ}`, is quoted with them, the factor it is (parsed as the juxtaposition's
    /// right side, at `right_bp`).
    #[cold]
    fn ambiguous_division(&mut self, divisor: Span, right_bp: u8) -> ParseError {
        let (next_span, quoted) = match &self.tok.tok {
            Tok::Name(name) if is_trig(name) || self.call_follows(name) => {
                let start = self.tok.span;
                match self.nested(start, |p| p.expr(right_bp)) {
                    Ok(factor) => (Span::new(start.start, factor.span.end), true),
                    Err(refused) => return refused,
                }
            }
            Tok::Name(_) | Tok::Int(_) => (self.tok.span, true),
            _ => (self.tok.span, false),
        };
        let written = &self.src[divisor.start..next_span.end];
        let divisor_text = &self.src[divisor.start..divisor.end];
        let next = match quoted {
            true => &self.src[next_span.start..next_span.end],
            false => "…",
        };
        let span = divisor.to(next_span);
        let message = if next == "…" {
            format!(
                "'/{divisor_text}(…)' is ambiguous: write '/({divisor_text}(…))' to divide by \
                 the product, or '/{divisor_text}*(…)' to divide by {divisor_text} alone"
            )
        } else {
            format!(
                "'/{written}' is ambiguous: write '/({written})' to divide by the product, or \
                 '/{divisor_text}*{next}' to divide by {divisor_text} alone"
            )
        };
        ParseError::new(span, message)
    }

    /// Error for a missing `close` delimiter matching the opener at `open`.
    fn unclosed(&self, close: char, open: Span) -> ParseError {
        if self.tok.tok.starts_operand() {
            return self.implicit_mul();
        }
        let opener = &self.src[open.start..open.end];
        ParseError::naming_opener(
            self.src,
            self.tok.span,
            open.start,
            &format!("expected '{close}' to close '{opener}' opened at "),
            &format!(", found {}", self.found()),
        )
    }

    /// Consumes the current token, which must be `tok`, or reports it as unclosed.
    fn expect_close(&mut self, tok: Tok, close: char, open: Span) -> PResult<Span> {
        if self.tok.tok == tok {
            Ok(self.bump()?.span)
        } else {
            Err(self.unclosed(close, open))
        }
    }

    /// Runs `f` one nesting level deeper, failing at `opener` beyond [`MAX_DEPTH`].
    fn nested<T>(&mut self, opener: Span, f: impl FnOnce(&mut Self) -> PResult<T>) -> PResult<T> {
        if self.depth >= MAX_DEPTH {
            return Err(too_deep(opener));
        }
        self.depth += 1;
        let result = f(self);
        self.depth -= 1;
        result
    }

    // The functions on the recursive path below (`expr`, `rhs`, `prefix`, `unary`, `paren`,
    // `atom`, `call`, `call_args`, `bracket`) keep few temporaries, with the non-recursive work
    // in helpers, so that the maximum nesting plus dropping a tree of the maximum height fits in
    // a 2 MiB thread stack even in debug builds (about 1.4 MiB in the worst case).

    /// Parses an expression whose infix operators all bind at least as tightly as `min_bp`.
    fn expr(&mut self, min_bp: u8) -> PResult<Expr> {
        let mut lhs = self.prefix(min_bp)?;
        let mut height = self.height;
        // The divisor of a `/` just parsed at this level, while nothing else followed it.
        let mut divisor: Option<Span> = None;
        while let Some(op) = self.operator(&mut lhs, &mut height, min_bp)? {
            if op.negative.is_some() {
                return self.sum(lhs, height, op, min_bp);
            }
            if let (Some(divisor), true) = (divisor, op.is_juxtaposition()) {
                // A divisor in parentheses is plainly the whole divisor: `p²/(2M) x`.
                let text = &self.src[divisor.start..divisor.end];
                let fraction = text
                    .strip_prefix('\\')
                    .is_some_and(|t| FRACTIONS.iter().any(|f| t.starts_with(f)));
                let whole = (text.starts_with('(') && text.ends_with(')')) || fraction;
                if !whole {
                    return Err(self.ambiguous_division(divisor, op.right_bp));
                }
            }
            height = self.rhs(op, &mut lhs, height)?;
            divisor = match &lhs.kind {
                ExprKind::Div(_, d) => Some(d.span),
                _ => None,
            };
        }
        self.height = height;
        Ok(lhs)
    }

    /// Parses the rest of a sum whose first term `first` (of height `height`) is followed by
    /// the `+` or `−` `op`: every later operator at this level is another `+` or `−`, since the
    /// terms take all that binds more tightly.
    fn sum(&mut self, first: Expr, height: usize, op: BinOp, min_bp: u8) -> PResult<Expr> {
        let mut terms = vec![Term {
            negative: false,
            expr: first,
            height,
            op: op.span,
        }];
        let mut op = Some(op);
        while let Some(next) = op {
            let expr = self.nested(next.span, |p| p.expr(next.right_bp))?;
            terms.push(Term {
                negative: next.negative.unwrap_or(false),
                expr,
                height: self.height,
                op: next.span,
            });
            let last = terms.last_mut().expect("a term");
            op = self.operator(&mut last.expr, &mut last.height, min_bp)?;
            debug_assert!(op.as_ref().is_none_or(|o| o.negative.is_some()));
        }
        let (tree, height) = Term::chain(terms)?;
        self.height = height;
        Ok(tree)
    }

    /// Applies any superscripts to `lhs` (of height `height`), then consumes and returns the next
    /// binary operator if it binds at least as tightly as `min_bp`.
    fn operator(
        &mut self,
        lhs: &mut Expr,
        height: &mut usize,
        min_bp: u8,
    ) -> PResult<Option<BinOp>> {
        // Superscripts bind like `^`, more tightly than any `min_bp`; but one after an exponent
        // written with `^` ends it (`x^{2}²`, `x^2²`), and one after a superscript is refused
        // below, as `x² ²` is: they stand side by side as one (`x²²`), which no reading should
        // guess.
        let mut raised = false;
        while matches!(self.tok.tok, Tok::Sup { .. }) && min_bp != EXPONENT_BP {
            if self.has_superscript(lhs) {
                return Err(self.superscript_after_superscript(lhs));
            }
            *height = grow((*height).max(2), self.tok.span)?;
            let exponent = self.superscript()?;
            map_in_place(lhs, |base| {
                let span = base.span.to(exponent.span);
                Expr::new(ExprKind::Pow(Box::new(base), Box::new(exponent)), span)
            });
            raised = true;
        }
        if self.on_empty_group() && self.has_superscript(lhs) {
            let refused = self.superscript_after_superscript(lhs);
            self.exponent_after_caret()?;
            return Err(refused);
        }
        // A `^` after a superscript character, `r²^3`, raises the power, `(r²)³`, where `r^2^3`
        // raises the exponent, `r^(2³)`: neither is guessed.
        if raised && self.tok.tok == Tok::Caret {
            return Err(self.caret_after_superscript(lhs));
        }
        self.binary_op(min_bp)
    }

    /// Whether the current token is a `^` on an empty group, `{}^{2}`, which the lexer skips
    /// (so that the superscript goes to what stands before it, as `P'_{1,1}{}^{2}` is printed):
    /// the text between it and the token before it holds a brace, which only such a group can.
    fn on_empty_group(&self) -> bool {
        self.tok.tok == Tok::Caret
            && self.prev.is_some_and(|prev| {
                self.src
                    .get(prev.end..self.tok.span.start)
                    .is_some_and(|between| between.contains('{'))
            })
    }

    /// Whether `e` was written with a superscript of its own, an exponent, outside
    /// parentheses: `x^{2}`, `x²`, `\cos^{2}\theta`, `P'_{1,1}{}^{2}`, `e^{x}`; not `(x^{2})`,
    /// `\exp(x)`, nor a name with a prime, `P'_{1,1}` (the prime, a superscript to TeX, is
    /// part of the name, and a power of it is what the empty group is printed for), nor a
    /// power of a function written before its argument in parentheses, `sin²(θ)`, whose
    /// superscript stands apart from one after the parentheses: `sin²(θ)³` is `(sin²θ)³` as
    /// `sin²(θ)^3` is (it was refused as two superscripts side by side).
    fn has_superscript(&self, e: &Expr) -> bool {
        match &e.kind {
            // In parentheses a power's span starts before its base; before the parentheses of
            // a call, `sin²(θ)`, its exponent starts before the base ends with them.
            ExprKind::Pow(base, exponent) => {
                let before_parentheses =
                    exponent.span.start < base.span.end && self.src[..base.span.end].ends_with(')');
                e.span.start == base.span.start && !before_parentheses
            }
            ExprKind::Call(f, name, _) => {
                f == "exp"
                    && !e.in_parentheses()
                    && self.src[name.end..].trim_start().starts_with('^')
            }
            _ => false,
        }
    }

    /// The error for a superscript on an empty group, or a superscript character, after
    /// `lhs`, which has one already: LaTeX sets `x^{2}{}^{3}` as `x^{23}`, and `x^{2}²` shows
    /// as `x²²`, which no reading should guess.
    #[cold]
    fn superscript_after_superscript(&self, lhs: &Expr) -> ParseError {
        let (span, set) = self.second_superscript();
        self.after_superscript(lhs, span, set)
    }

    /// Where the superscript at the current token stands, a superscript character or one on
    /// an empty group, after one already, and how the two read together.
    fn second_superscript(&self) -> (Span, &'static str) {
        // The quote starts at the empty group that carries the superscript, if one does:
        // `{}^{3}`, `{}²`.
        let after = self.prev.map_or(self.tok.span.start, |p| p.end);
        let open = self.src[after..self.tok.span.start].find('{');
        match self.tok.tok {
            Tok::Sup { .. } => (
                Span::new(
                    open.map_or(self.tok.span.start, |k| after + k),
                    self.tok.span.end,
                ),
                "the two superscripts show side by side, as one",
            ),
            _ => {
                let open = after + open.unwrap_or(0);
                let span = Span::new(open, script_end(self.src, self.tok.span.end));
                (span, "LaTeX sets the two superscripts side by side, as one")
            }
        }
    }

    /// The error for a `^` after `lhs`, which ends in a superscript character, `r²^3`: the
    /// quote holds the `^` and its exponent; one without an exponent, `r²^`, is refused as
    /// `r^` is ([`Self::exponent_after_caret`]).
    #[cold]
    fn caret_after_superscript(&mut self, lhs: &Expr) -> ParseError {
        match self.caret_and_exponent() {
            Ok(second) => self.after_superscript(lhs, second, RAISES_EITHER),
            Err(missing) => missing,
        }
    }

    /// Consumes the `^` at the current token and its exponent, after a superscript character
    /// (`r²^3`, `sin²^3θ`), returning the span the refusal quotes, from the `^` to the end of
    /// the exponent ([`Self::exponent_after_caret`], whose errors are this one's).
    fn caret_and_exponent(&mut self) -> PResult<Span> {
        let caret = self.tok.span;
        let exponent = self.exponent_after_caret()?;
        Ok(Span::new(caret.start, exponent.span.end))
    }

    /// Consumes the `^` at the current token and parses its exponent, for a refusal of the
    /// power that quotes them, returning the exponent.
    ///
    /// # Errors
    ///
    /// An exponent that is missing or does not parse, `r²^`, `r²^)`, `r²^{}`, is refused as
    /// after any other base (`r^`: `expected an expression after '^'`), since without one
    /// there is no power to be in doubt about.
    fn exponent_after_caret(&mut self) -> PResult<Expr> {
        self.bump()?;
        self.expr(EXPONENT_BP)
    }

    /// The error for what stands at `span`, a superscript, after `lhs`, which has one already,
    /// `set` saying how the two read together.
    fn after_superscript(&self, lhs: &Expr, span: Span, set: &str) -> ParseError {
        let base = self.quote(self.sized(self.powered(lhs)));
        let advice = format!("put {base} in parentheses for a power of it, or {ONE_GROUP}");
        self.superscript_already(span, &base, set, &advice)
    }

    /// The error for the superscript at `second` after `base`, the quote of what has one
    /// already, `set` saying how the two read together and `advice` what to write: the one
    /// wording of [`Self::after_superscript`] and [`Self::after_raised_function`].
    fn superscript_already(&self, second: Span, base: &str, set: &str, advice: &str) -> ParseError {
        ParseError::new(
            second,
            format!(
                "{} after {base}, which has a superscript already, is ambiguous: {set}; {advice}",
                self.quote(second)
            ),
        )
    }

    /// The span of the factor that the power `e` raises, which a message quotes: `e`'s own,
    /// but for a name before parentheses, `x(y)^{2}`, which the lowering reads as the name
    /// times the power of the parentheses, `x·(y)²`, as `M(x + y)²` is printed: `(y)^{2}`
    /// (`Re(y)^{2}` too where the system declares `Re`, [`Reading::calls`]); and
    /// for names run together, `Mω^{2}`, which it reads as the product with the power on the
    /// last name alone, `M·ω²`: `ω^{2}` (where the names are read, [`Reading::split`]). A
    /// function's call, `cos(θ)^{2}`, is raised whole.
    fn powered(&self, e: &Expr) -> Span {
        if let ExprKind::Pow(base, _) = &e.kind {
            match &base.kind {
                ExprKind::Call(name, name_span, args)
                    if !self.names.calls(name) && args.len() == 1 && !base.in_parentheses() =>
                {
                    let open = self.src[name_span.end..base.span.end].find('(');
                    if let Some(open) = open {
                        return Span::new(name_span.end + open, e.span.end);
                    }
                }
                // Not in parentheses, the name is its own text, so the last piece ends it.
                ExprKind::Name(name) if !base.in_parentheses() => {
                    let last = self
                        .names
                        .split(name)
                        .and_then(|pieces| pieces.last().cloned());
                    let written = &self.src[base.span.start..base.span.end];
                    if let Some(last) = last.filter(|last| written.ends_with(last.as_str())) {
                        return Span::new(base.span.end - last.len(), e.span.end);
                    }
                }
                _ => {}
            }
        }
        e.span
    }

    /// `span` with the sizing command before it where it opens with a delimiter that one
    /// sizes, `\left(x\right)^{2}` of `(x\right)^{2}`: a node in parentheses spans them, and the
    /// lexer skips the command as it does a space, so that a quoted node would hold half of a
    /// `\left … \right` pair.
    fn sized(&self, span: Span) -> Span {
        let text = &self.src[span.start..span.end];
        if !(text.starts_with('(') || text.starts_with("\\{")) {
            return span;
        }
        let before = self.src[..span.start].trim_end();
        let command = SIZING_OPEN.iter().find_map(|word| {
            let start = before.strip_suffix(word)?.strip_suffix('\\')?;
            Some(start.len())
        });
        command.map_or(span, |start| Span::new(start, span.end))
    }

    /// Parses the right operand of `op` and replaces `lhs` (of height `height`) by `lhs op rhs`,
    /// returning the new height.
    fn rhs(&mut self, op: BinOp, lhs: &mut Expr, height: usize) -> PResult<usize> {
        let rhs = self.nested(op.span, |p| p.expr(op.right_bp))?;
        let height = grow(height.max(self.height), op.span)?;
        map_in_place(lhs, |lhs| {
            let span = lhs.span.to(rhs.span);
            Expr::new((op.make)(Box::new(lhs), Box::new(rhs)), span)
        });
        Ok(height)
    }

    /// Consumes the current token if it is a binary operator binding at least as tightly as
    /// `min_bp`.
    fn binary_op(&mut self, min_bp: u8) -> PResult<Option<BinOp>> {
        let (left_bp, right_bp, make): (u8, u8, MakeNode) = match self.tok.tok {
            Tok::Plus => (1, 2, ExprKind::Add),
            Tok::Minus => (1, 2, ExprKind::Sub),
            Tok::Star => (3, 4, ExprKind::Mul),
            Tok::Slash => (3, 4, ExprKind::Div),
            // A superscript on an empty group after an exponent, `x^{2}{}^{3}`, is no power of
            // that exponent: it ends it, and `operator` refuses it after the power.
            Tok::Caret if min_bp == EXPONENT_BP && self.on_empty_group() => return Ok(None),
            Tok::Caret => (7, EXPONENT_BP, ExprKind::Pow),
            // Juxtaposition multiplies, as in the printed text: `2M`, `Mω²x²`, `x p_y`.
            ref t if t.starts_operand() => {
                if 3 < min_bp {
                    return Ok(None);
                }
                let at = Span::new(self.tok.span.start, self.tok.span.start);
                return Ok(Some(BinOp {
                    make: ExprKind::Mul,
                    span: at,
                    right_bp: 4,
                    negative: None,
                }));
            }
            _ => return Ok(None),
        };
        if left_bp < min_bp {
            return Ok(None);
        }
        let negative = match self.tok.tok {
            Tok::Plus => Some(false),
            Tok::Minus => Some(true),
            _ => None,
        };
        let span = self.bump()?.span;
        Ok(Some(BinOp {
            make,
            span,
            right_bp,
            negative,
        }))
    }

    /// Consumes a superscript token and returns its exponent: `Integer` or `Neg(Integer)`.
    fn superscript(&mut self) -> PResult<Expr> {
        let Token { tok, span } = self.bump()?;
        let Tok::Sup { value, negative } = tok else {
            unreachable!("current token was a superscript")
        };
        if !negative {
            return Ok(Expr::new(ExprKind::Integer(value), span));
        }
        let digits = Span::new(span.start + '⁻'.len_utf8(), span.end);
        Ok(negate(span, Expr::new(ExprKind::Integer(value), digits)))
    }

    /// Parses an operand of an expression at `min_bp`: a literal, name, call, parenthesized
    /// expression, bracket or unary operator applied to an operand.
    fn prefix(&mut self, min_bp: u8) -> PResult<Expr> {
        match self.tok.tok {
            Tok::Int(_) | Tok::Name(_) => self.atom(),
            Tok::Minus | Tok::Plus => self.unary(min_bp),
            Tok::LParen => self.paren(),
            Tok::LBrace if self.exponent_in_braces() => self.exponent_group(),
            Tok::LBrace => self.bracket(),
            Tok::Frac => self.frac(),
            Tok::Sqrt => self.sqrt(),
            Tok::Root => self.root(),
            _ => Err(self.expected_operand()),
        }
    }

    /// Parses a unary minus or plus and its operand, in an expression at `min_bp`: in an
    /// exponent (`x^-2`) the operand is one too, which a superscript on an empty group ends
    /// as it ends the exponent (`x^-2{}^{3}`, refused after the power, was `x^(−2³)`).
    fn unary(&mut self, min_bp: u8) -> PResult<Expr> {
        let op = self.bump()?;
        let bp = min_bp.max(UNARY_BP);
        let operand = self.nested(op.span, |p| p.expr(bp))?;
        if op.tok == Tok::Plus {
            return Ok(operand);
        }
        self.height = grow(self.height, op.span)?;
        Ok(negate(op.span, operand))
    }

    /// Parses a parenthesized expression.
    fn paren(&mut self) -> PResult<Expr> {
        let open = self.bump()?.span;
        let inner = self.nested(open, |p| p.expr(0))?;
        self.close_paren(open, inner)
    }

    /// Consumes the `)` closing the parenthesis opened at `open`, widening `inner`'s span.
    fn close_paren(&mut self, open: Span, mut inner: Expr) -> PResult<Expr> {
        let close = self.expect_close(Tok::RParen, ')', open)?;
        inner.span = open.to(close);
        Ok(inner)
    }

    /// Parses an integer, a name, or a call if the name is followed by `(`.
    fn atom(&mut self) -> PResult<Expr> {
        let Token { tok, span } = self.bump()?;
        self.height = 1;
        match tok {
            // No name begins with `_`: this is a subscript after something else, as LaTeX
            // writes one after a power, `x^{2}_{1}`, which read as the name `_1`.
            Tok::Name(name) if name.starts_with('_') => Err(ParseError::new(
                span,
                format!(
                    "{} is a subscript with no name before it: a subscript follows its name, \
                     before a power, as in x_{{1}}^{{2}}",
                    self.quote(span)
                ),
            )),
            Tok::Name(name) if self.tok.tok == Tok::LParen => self.call(name, span),
            Tok::Name(name) if name == "e" && self.braced_exponent_follows() => {
                self.exponential(span)
            }
            Tok::Name(name) if is_trig(&name) && !matches!(self.tok.tok, Tok::Eof) => {
                self.trig_without_parens(name, span)
            }
            // `\operatorname{Re} A`, as LaTeX sets the real part of a name, and a display name
            // of two words: one name, `Re A`.
            Tok::Name(name)
                if matches!(name.as_str(), "Re" | "Im")
                    && self.src[span.start..].starts_with('\\')
                    && matches!(self.tok.tok, Tok::Name(_)) =>
            {
                let Token {
                    tok: Tok::Name(of),
                    span: of_span,
                } = self.bump()?
                else {
                    unreachable!("the current token was a name")
                };
                Ok(Expr::new(
                    ExprKind::Name(format!("{name} {of}")),
                    span.to(of_span),
                ))
            }
            Tok::Name(name) => Ok(Expr::new(ExprKind::Name(name), span)),
            Tok::Int(n) => Ok(Expr::new(ExprKind::Integer(n), span)),
            _ => unreachable!("atom() is only called on integers and names"),
        }
    }

    /// Whether the current token is a `^` followed by `{`: after `e`, the exponential as the
    /// paper writes it, `e^{−inθ}` (a brace after any other `^` opens a bracket `{f, g}`).
    fn braced_exponent_follows(&self) -> bool {
        self.tok.tok == Tok::Caret && self.src[self.tok.span.end..].trim_start().starts_with('{')
    }

    /// Parses `^{x}` after the `e` at `span`: the exponential `exp(x)`, which the text form
    /// prints so.
    fn exponential(&mut self, span: Span) -> PResult<Expr> {
        self.bump()?;
        let open = self.bump()?.span;
        let arg = self.nested(open, |p| p.expr(0))?;
        self.height = grow(self.height, span)?;
        let close = self.expect_close(Tok::RBrace, '}', open)?;
        Ok(Expr::new(
            ExprKind::Call("exp".to_string(), span, vec![arg]),
            span.to(close),
        ))
    }

    /// Parses `cos θ` or `cos²θ` (a power written between the function and its argument), as
    /// the text form prints them.
    fn trig_without_parens(&mut self, name: String, span: Span) -> PResult<Expr> {
        let power = match self.tok.tok {
            Tok::Sup { .. } => Some(self.superscript()?),
            // `\cos^{3}\theta`, as LaTeX writes a power of it.
            Tok::Caret if self.braced_exponent_follows() => {
                self.bump()?;
                Some(self.exponent_group()?)
            }
            _ => None,
        };
        // `sin² ²θ` and `\sin^{2}{}^{3}\theta` show as one exponent, `sin²²θ`: neither is
        // guessed, as after any other power (no parentheses hold `sin²` alone).
        if let Some(exponent) = &power {
            let function = Span::new(span.start, exponent.span.end);
            let grouped = self.src[exponent.span.end..self.tok.span.start].contains('{');
            if matches!(self.tok.tok, Tok::Sup { .. }) || (self.tok.tok == Tok::Caret && grouped) {
                let (second, set) = self.second_superscript();
                return Err(self.after_raised_function(function, second, set));
            }
            // A `^` after the function's superscript, a character, `sin²^3θ`, or an exponent,
            // `\sin^{2}^{3}\theta`, may raise the power, (sin²)³, or its exponent, sin^(2³),
            // as after `r²^3`: neither is guessed.
            if self.tok.tok == Tok::Caret {
                let second = self.caret_and_exponent()?;
                return Err(self.after_raised_function(function, second, RAISES_EITHER));
            }
        }
        let call = if self.tok.tok == Tok::LParen {
            self.call(name, span)?
        } else {
            // `cos 2θ`, `\cos 2\theta`: a multiple of an angle, as the printers write one;
            // after a power too, `sin²2θ = (sin 2θ)²`, as physics writes a mixing angle's.
            let multiple = match &self.tok.tok {
                Tok::Int(n) => {
                    let k = Expr::new(ExprKind::Integer(n.clone()), self.tok.span);
                    self.bump()?;
                    Some(k)
                }
                _ => None,
            };
            let Token {
                tok: Tok::Name(arg),
                span: arg_span,
            } = self.bump()?
            else {
                let at = self.prev.unwrap_or(span);
                if let Some(k) = &multiple {
                    let written = &self.src[span.start..k.span.end];
                    return Err(ParseError::new(
                        at,
                        format!("expected an angle after '{written}', as in {name} 2θ"),
                    ));
                }
                let hint = match &self.src[at.start..at.end] {
                    "^" => format!(
                        "; a power of {name} is written {name}²θ or {name}(theta)^2, not \
                         {name}^2 theta"
                    ),
                    _ => String::new(),
                };
                return Err(ParseError::new(
                    at,
                    format!("expected an angle or '(' after '{name}'{hint}"),
                ));
            };
            // `cos θ²` could be (cos θ)² or cos(θ²), and `cos²θ^3` (cos²θ)³ or cos²(θ³), as
            // LaTeX reads `\cos^2\theta^3`: neither is guessed.
            if matches!(self.tok.tok, Tok::Sup { .. } | Tok::Caret) {
                // `sin 2θ^2`: the multiple is part of the angle that the power may raise, and
                // the square is advised only for a bare angle (`sin²θ`, `sin(θ)^2`).
                let angle = multiple.as_ref().map_or(arg_span, |k| k.span.to(arg_span));
                let unpowered = power.is_none() && multiple.is_none();
                return Err(self.power_of_bare_angle(span, angle, unpowered));
            }
            let mut arg = Expr::new(ExprKind::Name(arg), arg_span);
            if let Some(k) = multiple {
                let whole = k.span.to(arg_span);
                arg = Expr::new(ExprKind::Mul(Box::new(k), Box::new(arg)), whole);
            }
            Expr::new(ExprKind::Call(name, span, vec![arg]), span.to(arg_span))
        };
        self.height = 2;
        Ok(match power {
            None => call,
            Some(exponent) => {
                let whole = call.span.to(exponent.span);
                Expr::new(ExprKind::Pow(Box::new(call), Box::new(exponent)), whole)
            }
        })
    }

    /// The error for the superscript at `second` after the function raised at `function`,
    /// `sin²`, which has one already, `set` saying how the two read together: no parentheses
    /// hold `sin²` alone, so the advice is to write the exponent in one group.
    fn after_raised_function(&self, function: Span, second: Span, set: &str) -> ParseError {
        self.superscript_already(second, &self.quote(function), set, ONE_GROUP)
    }

    /// The error for a power of the angle at `angle` (with its multiple, `2θ`), written without
    /// parentheses after the function whose name is at `name`, or after a power of it:
    /// `sin²θ^3` could be `(sin²θ)³` or `sin²(θ³)`, as LaTeX reads `\sin^2\theta^3`, and
    /// `sin θ³` `(sin θ)³` or `sin(θ³)`; the message writes both readings in the source's own
    /// spelling (`(\sin^{2}\theta)^{3}`), but for the square of a function not raised, `unpowered`,
    /// which it writes `sin²θ` or `sin(θ)^2`, or where the function or its angle is written in
    /// LaTeX, as written, `\sin^{2}\theta` or `\sin(\theta)^{2}`. A missing exponent,
    /// `sin²θ^`, is refused as after any other base ([`Self::exponent_after_caret`]).
    #[cold]
    fn power_of_bare_angle(&mut self, name: Span, angle: Span, unpowered: bool) -> ParseError {
        // The power as written from its own `^` or superscript: an empty group or a LaTeX space
        // before it, `\theta{}^{3}`, `θ\,^3`, is no part of the power the readings write.
        let start = self.tok.span.start;
        let two = BigInt::from(2);
        let (end, square) = match &self.tok.tok {
            Tok::Sup { value, negative } => (self.tok.span.end, !negative && *value == two),
            _ => match self.exponent_after_caret() {
                Ok(e) => {
                    let square = matches!(&e.kind, ExprKind::Integer(n) if *n == two);
                    (e.span.end, square)
                }
                Err(missing) => return missing,
            },
        };
        let function = self.src[name.start..angle.start].trim_end();
        let written = &self.src[name.start..angle.end];
        let arg = &self.src[angle.start..angle.end];
        if unpowered && square {
            let function = &self.src[name.start..name.end];
            let between = &self.src[name.end..angle.start];
            // Told by the text, not by the names it reads as: `ϵ` reads as `ε`, and is no LaTeX.
            let message = if !written.contains('\\') {
                format!(
                    "'{function} {arg}' followed by a power is ambiguous: write {function}²{arg} \
                     or {function}({arg})^2 for the square of {function} {arg}"
                )
            } else {
                // Written in LaTeX, `\cos\theta`, `\cos cos`: quoted and squared as written.
                format!(
                    "'{written}' followed by a power is ambiguous: write \
                     {function}^{{2}}{between}{arg} or {function}({arg})^{{2}} for the square of \
                     {written}"
                )
            };
            return ParseError::new(Span::new(angle.start, end), message);
        }
        let power = &self.src[start..end];
        ParseError::new(
            Span::new(angle.start, end),
            format!(
                "'{written}' followed by a power is ambiguous: write ({written}){power} for a \
                 power of {written}, or {function}({arg}{power}) for {function} of {arg}{power}"
            ),
        )
    }

    /// Parses the parenthesized arguments of a call of `name` (at `span`).
    fn call(&mut self, name: String, span: Span) -> PResult<Expr> {
        let open = self.bump()?.span;
        let args = self.nested(open, Self::call_args)?;
        self.height = grow(self.height, span)?;
        let close = self.expect_close(Tok::RParen, ')', open)?;
        Ok(Expr::new(ExprKind::Call(name, span, args), span.to(close)))
    }

    /// Parses the comma-separated arguments of a call.
    fn call_args(&mut self) -> PResult<Vec<Expr>> {
        let mut args = vec![self.expr(0)?];
        let mut height = self.height;
        while self.tok.tok == Tok::Comma {
            self.bump()?;
            args.push(self.expr(0)?);
            height = height.max(self.height);
        }
        self.height = height;
        Ok(args)
    }

    /// Parses a bracket `{f, g}`.
    fn bracket(&mut self) -> PResult<Expr> {
        let open = self.bump()?.span;
        let args = self.nested(open, |p| {
            let f = p.expr(0)?;
            let height = p.height;
            p.bracket_comma()?;
            let g = p.expr(0)?;
            p.height = grow(height.max(p.height), open)?;
            Ok([f, g])
        })?;
        self.close_bracket(open, args)
    }

    /// Consumes the `,` between the two arguments of a bracket.
    fn bracket_comma(&mut self) -> PResult<()> {
        if self.tok.tok == Tok::Comma {
            return self.bump().map(drop);
        }
        let msg = "expected ',' between the two arguments of a bracket {f, g}";
        Err(self.error(format!("{msg}, found {}", self.found())))
    }

    /// Consumes the `}` closing the bracket opened at `open` and builds the bracket.
    fn close_bracket(&mut self, open: Span, [f, g]: [Expr; 2]) -> PResult<Expr> {
        if self.tok.tok == Tok::Comma {
            let msg = "a bracket {f, g} takes exactly two arguments";
            return Err(self.unclosed('}', open).prefixed(&format!("{msg}; ")));
        }
        let close = self.expect_close(Tok::RBrace, '}', open)?;
        Ok(Expr::new(
            ExprKind::Bracket(Box::new(f), Box::new(g)),
            open.to(close),
        ))
    }

    /// Whether the current token is a `{` (not a bracket's `\{`) just after `^` or `**` whose
    /// braces hold no `,` outside parentheses and inner braces: an exponent in braces, as
    /// LaTeX writes it (`x^{2}`, `x^{-2}`, `x^{2/3}`); `x^{f, g}` is `x` to the power of a
    /// bracket.
    fn exponent_in_braces(&self) -> bool {
        let after_caret = self
            .prev
            .is_some_and(|s| matches!(&self.src[s.start..s.end], "^" | "**"));
        let span = self.tok.span;
        if !after_caret || &self.src[span.start..span.end] != "{" {
            return false;
        }
        let mut depth = 0usize;
        let mut chars = self.src[span.end..].chars();
        while let Some(c) = chars.next() {
            match c {
                // A control symbol is no comma of a bracket (`x^{2\,y}`, a thin space); an
                // escaped brace, `\{f, g\}`, still counts as a brace.
                '\\' if !chars.clone().next().is_some_and(|n| matches!(n, '{' | '}')) => {
                    chars.next();
                }
                '{' | '(' => depth += 1,
                '}' | ')' if depth == 0 => return true,
                '}' | ')' => depth -= 1,
                ',' if depth == 0 => return false,
                _ => {}
            }
        }
        true
    }

    /// Parses an exponent in braces, `{2}` of `x^{2}`: the expression they hold, its span
    /// widened to them as a parenthesized one's is.
    fn exponent_group(&mut self) -> PResult<Expr> {
        let open = self.bump()?.span;
        let mut inner = self.nested(open, |p| p.expr(0))?;
        let close = self.expect_close(Tok::RBrace, '}', open)?;
        inner.span = open.to(close);
        Ok(inner)
    }

    /// Parses a group in braces that a LaTeX command at `command` takes, its `what`
    /// (`\frac{a}{b}`'s numerator and denominator, `\sqrt{x}`'s radicand): the expression,
    /// its span widened to the braces.
    fn command_group(&mut self, command: Span, what: &str) -> PResult<Expr> {
        let span = self.tok.span;
        if self.tok.tok != Tok::LBrace || &self.src[span.start..span.end] != "{" {
            let name = &self.src[command.start..command.end];
            return Err(self.error(format!(
                "expected '{{' with the {what} of '{name}', found {}; write \\frac{{1}}{{2}}, \
                 \\sqrt{{x}}",
                self.found()
            )));
        }
        self.exponent_group()
    }

    /// Parses `\frac{a}{b}` (or `\tfrac`, `\dfrac`): the quotient `a/b`.
    fn frac(&mut self) -> PResult<Expr> {
        let command = self.bump()?.span;
        let (num, den) = self.nested(command, |p| {
            let num = p.command_group(command, "numerator")?;
            let height = p.height;
            let den = p.command_group(command, "denominator")?;
            p.height = grow(height.max(p.height), command)?;
            Ok((num, den))
        })?;
        let span = command.to(den.span);
        Ok(Expr::new(ExprKind::Div(Box::new(num), Box::new(den)), span))
    }

    /// Parses `\sqrt{x}`: the call `sqrt(x)`, which reads a declared radical.
    fn sqrt(&mut self) -> PResult<Expr> {
        let command = self.bump()?.span;
        let arg = self.nested(command, |p| p.command_group(command, "radicand"))?;
        self.height = grow(self.height, command)?;
        let span = command.to(arg.span);
        Ok(Expr::new(
            ExprKind::Call("sqrt".to_string(), command, vec![arg]),
            span,
        ))
    }

    /// Parses `√(x² + y²)` or `√x`, as the text form prints a root: the call `sqrt(…)`. A
    /// power after `√x` is refused, since `√x²` could raise the root or the name, and so is
    /// a number run into what follows it, since `√4x` could be the root of `4x` (as `√xy` is
    /// the root of the names run together, `xy`) or `√4` times `x`.
    fn root(&mut self) -> PResult<Expr> {
        let root = self.bump()?.span;
        let arg = match self.tok.tok {
            Tok::LParen => self.nested(root, |p| p.paren())?,
            Tok::Name(_) | Tok::Int(_) => {
                let arg = self.nested(root, |p| p.atom())?;
                let radicand = self.src[root.end..arg.span.end].trim_start();
                if !matches!(arg.kind, ExprKind::Name(_) | ExprKind::Integer(_)) {
                    return Err(ParseError::new(
                        root.to(arg.span),
                        format!(
                            "write the radicand of {} in parentheses, √({radicand})",
                            self.quote(root.to(arg.span)),
                        ),
                    ));
                }
                if matches!(arg.kind, ExprKind::Integer(_))
                    && matches!(self.tok.tok, Tok::Name(_))
                    && self.tok.span.start == arg.span.end
                {
                    let next = &self.src[self.tok.span.start..self.tok.span.end];
                    return Err(self.error(format!(
                        "{} is ambiguous: write √({radicand}{next}) for the root of the product, \
                         or √{radicand} {next} for the root times {next}",
                        self.quote(root.to(self.tok.span))
                    )));
                }
                if matches!(self.tok.tok, Tok::Sup { .. } | Tok::Caret) {
                    return Err(self.error(format!(
                        "a power after {} is ambiguous: write (√{radicand})^2 for a power of the \
                         root, or √({radicand}^2)",
                        self.quote(root.to(arg.span))
                    )));
                }
                arg
            }
            _ => {
                return Err(self.error(format!(
                    "expected '(', a name or a number after '√', found {}; write \
                     √(x^2 + y^2) or √x",
                    self.found()
                )))
            }
        };
        self.height = grow(self.height, root)?;
        let span = root.to(arg.span);
        Ok(Expr::new(
            ExprKind::Call("sqrt".to_string(), root, vec![arg]),
            span,
        ))
    }

    /// Error for a token that cannot begin an operand.
    fn expected_operand(&self) -> ParseError {
        match self.prev {
            Some(prev) => {
                let after = self.quote(prev);
                self.error(format!(
                    "expected an expression after {after}, found {}",
                    self.found()
                ))
            }
            None if matches!(self.tok.tok, Tok::RParen | Tok::RBrace | Tok::Comma) => {
                self.error(format!("unexpected {}", self.found()))
            }
            None => self.error(format!("expected an expression, found {}", self.found())),
        }
    }
}

/// Constructor of a binary node, such as `ExprKind::Add`.
type MakeNode = fn(Box<Expr>, Box<Expr>) -> ExprKind;

/// A binary operator that has been consumed.
struct BinOp {
    make: MakeNode,
    span: Span,
    right_bp: u8,
    /// For `+` and `−`: whether it subtracts.
    negative: Option<bool>,
}

impl BinOp {
    /// Whether this is the product of two factors written side by side (`2M`), which has no
    /// token: its span is empty.
    fn is_juxtaposition(&self) -> bool {
        self.span.start == self.span.end
    }
}

/// A term of a sum: its sign, the term, its height, and the operator before it (for the first,
/// the one after it), where a height error is reported.
struct Term {
    negative: bool,
    expr: Expr,
    height: usize,
    op: Span,
}

impl Term {
    /// The tree of a sum of `terms` (the first positive) and its height: left-deep up to
    /// [`LEFT_DEEP_SUM`] terms, else balanced, terms of one sign joined by `+` and of two by
    /// `−` with the first's sign kept for the pair (`−c + d` is `−(c − d)`).
    fn chain(terms: Vec<Term>) -> PResult<(Expr, usize)> {
        let join = |a: Term, b: Term| -> PResult<Term> {
            let make = match a.negative == b.negative {
                true => ExprKind::Add,
                false => ExprKind::Sub,
            };
            let span = a.expr.span.to(b.expr.span);
            Ok(Term {
                negative: a.negative,
                height: grow(a.height.max(b.height), b.op)?,
                expr: Expr::new(make(Box::new(a.expr), Box::new(b.expr)), span),
                op: a.op,
            })
        };
        if terms.len() <= LEFT_DEEP_SUM {
            let mut rest = terms.into_iter();
            let first = rest.next().expect("a first term");
            let sum = rest.try_fold(first, join)?;
            return Ok((sum.expr, sum.height));
        }
        let sum = balanced(terms, join)?.expect("a sum");
        debug_assert!(!sum.negative, "the first term is positive");
        Ok((sum.expr, sum.height))
    }
}

/// Where the script that starts at `at` (after its `^`) ends: a group in braces, a command,
/// or one character, after any spaces.
fn script_end(src: &str, at: usize) -> usize {
    let rest = &src[at..];
    let start = at + (rest.len() - rest.trim_start().len());
    let rest = &src[start..];
    let mut depth = 0usize;
    for (k, c) in rest.char_indices() {
        match c {
            '{' => depth += 1,
            '}' if depth > 1 => depth -= 1,
            '}' if depth == 1 => return start + k + 1,
            '\\' if depth == 0 => {
                let letters = rest[1..]
                    .find(|c: char| !c.is_ascii_alphabetic())
                    .unwrap_or(rest.len() - 1);
                return start + 1 + letters.max(1).min(rest.len() - 1);
            }
            _ if depth == 0 => return start + k + c.len_utf8(),
            _ => {}
        }
    }
    src.len()
}

/// Functions that the text form writes without parentheses: `cos θ`, `sin²θ`.
fn is_trig(name: &str) -> bool {
    matches!(name, "cos" | "sin")
}

/// Replaces `e` by `f(e)`.
fn map_in_place(e: &mut Expr, f: impl FnOnce(Expr) -> Expr) {
    let placeholder = Expr::new(ExprKind::Integer(BigInt::default()), e.span);
    *e = f(std::mem::replace(e, placeholder));
}

/// The negation of `operand`, with the minus sign at `minus`.
fn negate(minus: Span, operand: Expr) -> Expr {
    let span = minus.to(operand.span);
    Expr::new(ExprKind::Neg(Box::new(operand)), span)
}

/// `child + 1`: the height of a node (at `at`) over children at most `child` high, checked
/// against [`MAX_HEIGHT`].
fn grow(child: usize, at: Span) -> PResult<usize> {
    if child < MAX_HEIGHT {
        return Ok(child + 1);
    }
    let msg = format!(
        "expression too long: more than {MAX_HEIGHT} levels of operations \
         (a chain of n terms or factors counts as n levels)"
    );
    Err(ParseError::new(at, msg))
}

/// The error for nesting deeper than [`MAX_DEPTH`] at `opener`.
pub(super) fn too_deep(opener: Span) -> ParseError {
    let msg = format!("expression nested too deeply (more than {MAX_DEPTH} levels)");
    ParseError::new(opener, msg)
}
