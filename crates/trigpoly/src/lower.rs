//! Lowering: from a parsed expression (`syntax::Expr`) to a polynomial, checking what the
//! grammar cannot: names, integer exponents, exact divisions, angles inside `cos`, `sin`, `exp`;
//! and the complex structure's `conj`, `re`, `im`.

use crate::error::AlgebraError;
use crate::number::{Coefficient, GaussianRational, Integer, Rational};
use crate::poly::Poly;
use crate::syntax::{
    latex_name, parse_expr_reading, Expr, ExprKind, ParseCause, ParseError, Reading, Span,
};
use crate::varset::{bars_apart, long_name, under_one_bar, Var, VarKind, Vars, RESERVED};

/// What names and brackets mean beyond the variables: named functions defined elsewhere (a
/// system file's `H`, `L`) and the Poisson bracket `{f, g}` of a phase space.
pub trait Context<C: Coefficient> {
    /// The value of a name that is not a variable, if it is defined.
    fn lookup(&self, name: &str) -> Option<Poly<C>>;
    /// `{f, g}`, or why it cannot be formed: a refusal of the algebra (a limit, say) as
    /// [`BracketError::Algebra`], so that the parse error it becomes keeps it as its
    /// [`ParseCause::Algebra`].
    fn bracket(&self, f: &Poly<C>, g: &Poly<C>) -> Result<Poly<C>, BracketError>;
    /// The names this context defines (for "did you mean" messages).
    fn names(&self) -> Vec<String> {
        Vec::new()
    }
    /// How an unknown name's "did you mean" writes `name`, one of [`Context::names`], where
    /// the context reads it in a spelling it prefers (a function shown as a family instance,
    /// `P'_{1,1}`, spelt as a system file names it, `Pp_1_1`); `None` for the name itself.
    fn spelling(&self, _name: &str) -> Option<String> {
        None
    }
    /// The LaTeX that `name`, one of [`Context::names`], prints as (`G_{1}` of a function
    /// `G1`), by which the lowering reads that LaTeX back as the name where no name is so
    /// spelt; `None` where the context does not print its names.
    fn latex(&self, _name: &str) -> Option<String> {
        None
    }
    /// Told of a name that is not declared and was read as the product of the declared names
    /// it splits into, where that reading may not be what was meant ([`RunTogether`]); the
    /// lowering goes on with the product. Ignored unless a context keeps it (as
    /// [`Poly::parse_noting`] does); a name may be told more than once.
    fn run_together(&self, _: RunTogether) {}
}

/// Why a [`Context`] has no bracket `{f, g}`: the algebra refused (a limit, say), or another
/// reason, in words. Its `Display` is the algebra's message, or the words.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum BracketError {
    /// An operation of the algebra refused.
    #[error(transparent)]
    Algebra(#[from] AlgebraError),
    /// Another reason, in words.
    #[error("{0}")]
    Other(String),
}

/// A name that is not declared, read as the product of the declared names it splits into
/// ([`split_names`]), where the reading may not be what was meant: a physicist writes `Mω` for
/// `M·ω`, but `Lxx` beside a function `Lx`, `Axx` beside `A_xx`, `Hy` beside `Hx` or
/// `omegaa` beside `omega` and `a` are more likely names of their own, or slips ([`Doubt`]
/// says which rule saw it).
///
/// ```
/// use trigpoly::{Doubt, NoContext, Poly, Rational, Vars};
/// let vars = Vars::builder().coordinate("x").parameter("omega").parameter("a").build()?;
/// let read = |s: &str| Poly::<Rational>::parse_noting(&vars, s, &NoContext);
/// let (p, noted) = read("x + omegaa")?;
/// assert_eq!(p, Poly::parse(&vars, "x + omega*a")?);
/// assert_eq!((noted[0].name.as_str(), noted[0].span.start), ("omegaa", 4));
/// assert_eq!(noted[0].pieces, ["omega", "a"]);
/// assert_eq!(noted[0].doubt, Doubt::Doubled('a'));
/// assert_eq!(
///     noted[0].to_string(),
///     "'omegaa' is read as the product omega a, with its a doubled: declare 'omegaa' if it is \
///      a name of its own, or write 'omega a' for the product"
/// );
/// // The physics products are read without a word.
/// assert!(read("omega^2*ax + omegax")?.1.is_empty());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct RunTogether {
    /// The name as written (`Lxx`).
    pub name: String,
    /// Where it is written.
    pub span: Span,
    /// The declared names it is read as the product of, in order (`Lx`, `x`).
    pub pieces: Vec<String>,
    /// Why the reading is in doubt.
    pub doubt: Doubt,
}

/// Why a name run together may not be the product it is read as ([`RunTogether`]). The rules
/// are tried in this order; a split that meets none (`Mω`, `iθ`, `Mωx`, `xp_y`, `iOmega`) is
/// read without a word.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Doubt {
    /// A piece before the last is a named function (not a variable) of two characters or
    /// more, whose name the letters after it may continue: `Lxx` as `Lx·x` beside the
    /// function `Lx`, `Axy` as `Ax·y` beside `Ax`. A function last (`ωLz`, `iOmega`) is a
    /// coefficient times it.
    Continued(String),
    /// The name is one that an unknown name's "did you mean" would take for a declared name
    /// (the same letters but for case and underscores, or for a name of three characters or
    /// more one slip from exactly one such name) that is not one of its pieces: `Axx` beside
    /// `A_xx` (read `A·x·x`), `Ayx` beside `Axy`. A name that is one of the pieces (`omegax`,
    /// one letter more than `omega`) is a product as written.
    CloseTo(String),
    /// The name is two one-letter names run together, and a named function of two letters
    /// differs from it in its last letter alone: `Hy` beside a function `Hx` (read `H·y`),
    /// `Lx` beside `Ly`, likely a function of the same set that was not declared. `xy`, `Mω`,
    /// `Lx` beside a function `L` with no such function declared, and `mx` beside a parameter
    /// `mu`, are products.
    SameFirstLetter(String),
    /// A letter is doubled across two pieces, the first of two characters or more: `omegaa`
    /// as `omega·a`, `p_xx` as `p_x·x`, which may be a key struck twice (`xx`, `ωω`, of
    /// one-letter names, are products).
    Doubled(char),
}

impl RunTogether {
    /// Whether the reading of `name` as the product of `pieces` is in doubt, and why: `known`
    /// are the declared names (variables and functions), `function` says which of them are
    /// named functions.
    pub fn doubt(
        name: &str,
        pieces: &[String],
        known: &[String],
        function: &dyn Fn(&str) -> bool,
    ) -> Option<Doubt> {
        let len = |s: &str| s.chars().count();
        let before_last = &pieces[..pieces.len().saturating_sub(1)];
        if let Some(f) = before_last.iter().find(|p| len(p) >= 2 && function(p)) {
            return Some(Doubt::Continued(f.clone()));
        }
        if let Some(k) = did_you_mean(name, known).filter(|k| !pieces.iter().any(|p| p == k)) {
            return Some(Doubt::CloseTo(k.to_string()));
        }
        if let Some(k) = same_first_letter(name, known, function) {
            return Some(Doubt::SameFirstLetter(k.to_string()));
        }
        pieces.windows(2).find_map(|pair| {
            let last = pair[0].chars().next_back()?;
            let first = pair[1].chars().next()?;
            (len(&pair[0]) >= 2 && last == first && last.is_alphabetic())
                .then_some(Doubt::Doubled(last))
        })
    }

    /// What the reading is and why it is in doubt, in the words after the name (`'Lxx' is
    /// read as …`), each piece written by `shown` (a system's display names: `L_x` for `Lx`)
    /// and the product by `formula` (a report's markup puts it between back quotes): `is read
    /// as the product L_x x, the function Lx with x after it: declare 'Lxx' if it is a name of
    /// its own, or write 'Lx x' for the product`. Where no name can be `declarable` (a
    /// built-in system's names are fixed), the advice is the product's alone: `write 'Lx x'
    /// or 'Lx*x' for the product`.
    pub fn reading(
        &self,
        shown: &dyn Fn(&str) -> String,
        formula: &dyn Fn(&str) -> String,
        declarable: bool,
    ) -> String {
        let product: Vec<String> = self.pieces.iter().map(|p| shown(p)).collect();
        let why = match &self.doubt {
            Doubt::Continued(f) => {
                let at = self.pieces.iter().position(|p| p == f).unwrap_or(0);
                let after = self.pieces[at + 1..].join(" ");
                format!(", the function {f} with {after} after it")
            }
            Doubt::CloseTo(k) => format!(", though it is close to the declared name {k}"),
            Doubt::SameFirstLetter(k) => {
                format!(", though the declared name {k} differs from it in its last letter alone")
            }
            Doubt::Doubled(c) => format!(", with its {c} doubled"),
        };
        // A long run (`'abab…', 4000 characters long`) is not written out again.
        let (spaced, starred) = match long_name(&self.name) {
            None => (
                format!("'{}'", self.pieces.join(" ")),
                format!("'{}'", self.pieces.join("*")),
            ),
            Some(_) => ("it with spaces".to_string(), "with *".to_string()),
        };
        let advice = if declarable {
            format!(
                "declare {} if it is a name of its own, or write {spaced}",
                quoted_name(&self.name)
            )
        } else {
            format!("write {spaced} or {starred}")
        };
        format!(
            "is read as the product {}{why}: {advice} for the product",
            formula(&product.join(" ")),
        )
    }
}

/// The first named function of `known` that is two letters, the first of them `name`'s, where
/// `name` is two letters (read as two one-letter names, [`Doubt::SameFirstLetter`]): `Hx` for
/// `Hy`; else nothing. A variable or parameter (`mu` beside `mx`) is not such a name: a set of
/// functions (`Hx`, `Hy`; `Lx`, `Ly`) is what one forgets a member of.
fn same_first_letter<'k>(
    name: &str,
    known: &'k [String],
    function: &dyn Fn(&str) -> bool,
) -> Option<&'k str> {
    let two_letters = |s: &str| {
        let mut letters = s.chars();
        match (letters.next(), letters.next(), letters.next()) {
            (Some(a), Some(b), None) if a.is_alphabetic() && b.is_alphabetic() => Some(a),
            _ => None,
        }
    };
    let first = two_letters(name)?;
    known
        .iter()
        .map(String::as_str)
        .find(|&k| k != name && two_letters(k) == Some(first) && function(k))
}

impl std::fmt::Display for RunTogether {
    /// `'Lxx' is read as the product Lx x, the function Lx with x after it: …`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let reading = self.reading(&|p: &str| p.to_string(), &|p: &str| p.to_string(), true);
        write!(f, "{} {reading}", quoted_name(&self.name))
    }
}

/// A context that keeps what [`Context::run_together`] is told, once a place, and passes the
/// rest to the context it wraps.
struct Noting<'a, C: Coefficient> {
    ctx: &'a dyn Context<C>,
    noted: std::cell::RefCell<Vec<RunTogether>>,
}

impl<C: Coefficient> Context<C> for Noting<'_, C> {
    fn lookup(&self, name: &str) -> Option<Poly<C>> {
        self.ctx.lookup(name)
    }
    fn bracket(&self, f: &Poly<C>, g: &Poly<C>) -> Result<Poly<C>, BracketError> {
        self.ctx.bracket(f, g)
    }
    fn names(&self) -> Vec<String> {
        self.ctx.names()
    }
    fn spelling(&self, name: &str) -> Option<String> {
        self.ctx.spelling(name)
    }
    fn latex(&self, name: &str) -> Option<String> {
        self.ctx.latex(name)
    }
    fn run_together(&self, note: RunTogether) {
        let mut noted = self.noted.borrow_mut();
        if !noted
            .iter()
            .any(|n| n.span == note.span && n.name == note.name)
        {
            noted.push(note);
        }
    }
}

/// The context of a bare variable set: no named functions, no brackets.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoContext;

impl<C: Coefficient> Context<C> for NoContext {
    fn lookup(&self, _: &str) -> Option<Poly<C>> {
        None
    }
    fn bracket(&self, _: &Poly<C>, _: &Poly<C>) -> Result<Poly<C>, BracketError> {
        Err(BracketError::Other(
            "a bracket {f, g} needs a phase space; parse it through a system".into(),
        ))
    }
}

impl<C: Coefficient> Poly<C> {
    /// Parses an expression in the variables of `vars`.
    ///
    /// ```
    /// use trigpoly::{Poly, Rational, Vars};
    /// let vars = Vars::builder().coordinate("x").momentum("p_x").parameter("M").build().unwrap();
    /// let h = Poly::<Rational>::parse(&vars, "p_x^2/(2*M) + M*x^2/2").unwrap();
    /// assert_eq!(h.to_string(), "p_x²/(2M) + Mx²/2");
    /// let err = Poly::<Rational>::parse(&vars, "x/(1+x)").unwrap_err();
    /// assert_eq!(err.line_col("x/(1+x)"), (1, 3));
    /// ```
    ///
    /// What [`Poly::render`] prints in LaTeX reads back, a variable printed otherwise than
    /// it is named too (`x_{1}` of `x1`, `\theta_{2}` of `theta2`); plain text is read as
    /// written, where `x_1` names no `x1`.
    ///
    /// ```
    /// use trigpoly::{Expr, Style, Vars};
    ///
    /// let vars = Vars::builder()
    ///     .coordinate("x1").angle("theta2").momentum("p1").momentum("p_theta2")
    ///     .build()?;
    /// let e = Expr::parse(&vars, "p1^2*cos(theta2) + x1")?;
    /// let latex = e.render(Style::Latex);
    /// assert_eq!(latex, r"x_{1} + p_{1}^{2} \cos\theta_{2}");
    /// assert_eq!(Expr::parse(&vars, &latex)?, e);
    /// assert!(Expr::parse(&vars, "x_1").is_err());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn parse(vars: &Vars, src: &str) -> Result<Self, ParseError> {
        Self::parse_with(vars, src, &NoContext)
    }

    /// Parses with named functions and brackets supplied by `ctx`.
    pub fn parse_with(vars: &Vars, src: &str, ctx: &dyn Context<C>) -> Result<Self, ParseError> {
        let lower = Lower {
            vars,
            ctx,
            src: Some(src),
        };
        let expr = parse_expr_reading(src, &lower)?;
        lower.lower(&expr).map_err(|e| e.in_source(src))
    }

    /// Parses `src` into the tree that [`Poly::from_expr`] lowers, as
    /// [`parse_expr`](crate::syntax::parse_expr) does, a refusal quoting the factor a power
    /// raises as the names of `vars` and `ctx` read (`'ω^{2}'` of `Mω^{2}{}^{3}`).
    pub fn parse_tree(vars: &Vars, src: &str, ctx: &dyn Context<C>) -> Result<Expr, ParseError> {
        let lower = Lower {
            vars,
            ctx,
            src: Some(src),
        };
        parse_expr_reading(src, &lower)
    }

    /// Lowers an already parsed expression.
    pub fn from_expr(vars: &Vars, expr: &Expr, ctx: &dyn Context<C>) -> Result<Self, ParseError> {
        Lower {
            vars,
            ctx,
            src: None,
        }
        .lower(expr)
    }

    /// Parses as [`Poly::parse_with`] does, and says which names run together it read as
    /// products that may not have been meant ([`RunTogether`]), in the order it read them,
    /// each place once.
    pub fn parse_noting(
        vars: &Vars,
        src: &str,
        ctx: &dyn Context<C>,
    ) -> Result<(Self, Vec<RunTogether>), ParseError> {
        let noting = Noting {
            ctx,
            noted: std::cell::RefCell::new(Vec::new()),
        };
        let p = Self::parse_with(vars, src, &noting)?;
        Ok((p, noting.noted.into_inner()))
    }
}

/// An exponent as written: an integer, or `p/2` for an odd `p` (a power of a radical).
#[derive(Clone, Copy)]
enum Exponent {
    Integer(i64),
    Half(i64),
}

/// What takes a root: `sqrt(E)`, or the power `E^(p/2)`.
#[derive(Clone, Copy)]
enum RootOf {
    Sqrt,
    Power(i64),
}

struct Lower<'a, C: Coefficient> {
    vars: &'a Vars,
    ctx: &'a dyn Context<C>,
    /// The text parsed, where the lowering has it: what tells a name written in LaTeX
    /// ([`Lower::latex_spelled`]).
    src: Option<&'a str>,
}

/// The names as the lowering reads them, for the parser's refusals: `Re` and `Im` before
/// parentheses multiply them where the system declares them ([`Lower::is_function`]), and a
/// name that is no variable or function splits as [`Lower::lower`] splits it before a power
/// (`Mω²` is `M·ω²`).
impl<C: Coefficient> Reading for Lower<'_, C> {
    fn calls(&self, name: &str) -> bool {
        calls_function(name, &|n: &str| self.is_declared(n))
    }
    fn split(&self, name: &str) -> Option<Vec<String>> {
        if self.vars.lookup(name).is_some() || self.ctx.lookup(name).is_some() {
            return None;
        }
        self.split_name(name)
    }
    /// An angle's conjugate is no call of `conj`, which refuses it: the angle is real, and
    /// functions depend on it through its cosine, sine or exponential.
    fn conjugate(&self, name: &str) -> String {
        match self.angle_use(name) {
            Some(through) => {
                format!("{name} is an angle, real: conj does not take it, and {through}")
            }
            None => crate::syntax::conjugate_written(name),
        }
    }
}

/// A product of factors as written, each to its power: `(x + y)(x − 2y)³`, `g(x − y)²`, `−2x`.
fn written_product<C: Coefficient>(factors: &[(Poly<C>, i64)], negative: bool) -> String {
    let mut text = String::from(if negative { "−" } else { "" });
    for (p, n) in factors {
        let mut factor = match p.len() > 1 {
            true => format!("({p})"),
            false => p.to_string(),
        };
        if *n > 1 {
            factor.push_str(&crate::superscript(*n));
        }
        // Side by side as the paper writes them: `2M`, `g(x − y)²`, `(x + y)(x − y)`; a
        // number after parentheses with a dot, `(x − y)·2`; two names apart, `g x`.
        let separator = match (text.chars().last(), factor.chars().next()) {
            (None | Some('−'), _) => "",
            (Some(')'), Some(c)) if c.is_ascii_digit() => "·",
            (Some(')'), _) | (_, Some('(')) => "",
            (Some(a), Some(b)) if a.is_ascii_digit() && !b.is_ascii_digit() => "",
            _ => " ",
        };
        text.push_str(separator);
        text.push_str(&factor);
    }
    text
}

/// `|n|`, if a 64-bit number holds it.
fn size(n: &Integer) -> Option<u64> {
    n.to_i128()
        .and_then(|n| u64::try_from(n.unsigned_abs()).ok())
}

/// The parse error at `span` of a refusal of the algebra, which keeps it as its cause.
fn at(span: Span) -> impl Fn(AlgebraError) -> ParseError {
    move |e| ParseError::new(span, e.to_string()).with_cause(ParseCause::Algebra(e))
}

impl<C: Coefficient> Lower<'_, C> {
    fn lower(&self, e: &Expr) -> Result<Poly<C>, ParseError> {
        let span = e.span;
        match &e.kind {
            ExprKind::Integer(n) => Ok(Poly::constant(
                self.vars,
                C::from_rational(Rational::from(Integer::from(n.clone()))),
            )),
            ExprKind::Name(name) => self.name(name, span),
            ExprKind::Neg(a) => Ok(-self.lower(a)?),
            ExprKind::Add(a, b) => self
                .lower(a)?
                .checked_add(&self.lower(b)?)
                .map_err(at(span)),
            ExprKind::Sub(a, b) => self
                .lower(a)?
                .checked_sub(&self.lower(b)?)
                .map_err(at(span)),
            ExprKind::Mul(a, b) => self
                .lower(a)?
                .checked_mul(&self.lower(b)?)
                .map_err(at(span)),
            ExprKind::Div(a, b) => {
                let num = self.lower(a)?;
                let den = self.lower(b)?;
                num.checked_div(&den)
                    .map_err(|e| self.with_written_factors(e, b, &den))
                    .map_err(at(b.span))
            }
            ExprKind::Pow(a, b) => {
                // `M(x + y)²` as printed: the power belongs to the parentheses, not to the
                // product the name before them makes (`(M(x + y))²` squares it all).
                if let ExprKind::Call(name, name_span, args) = &a.kind {
                    if !a.in_parentheses()
                        && args.len() == 1
                        && !self.is_function(name)
                        && self.is_product_of_names(name)
                    {
                        let exp = self.integer_exponent(b)?;
                        let power = self.lower(&args[0])?.checked_pow(exp).map_err(at(span))?;
                        return self
                            .name(name, *name_span)?
                            .checked_mul(&power)
                            .map_err(at(span));
                    }
                }
                // `Mω²` as printed: the power belongs to the last name only (`(Mω)²`, in
                // parentheses, squares both).
                if let (ExprKind::Name(name), false) = (&a.kind, a.in_parentheses()) {
                    if self.vars.lookup(name).is_none() && self.ctx.lookup(name).is_none() {
                        if let Some(mut parts) = self.read_split(name, a.span) {
                            let last = parts.pop().expect("a split has two parts or more");
                            let exp = self.integer_exponent(b)?;
                            let mut acc = self
                                .name(&last, a.span)?
                                .checked_pow(exp)
                                .map_err(at(span))?;
                            for part in parts {
                                acc = acc
                                    .checked_mul(&self.name(&part, a.span)?)
                                    .map_err(at(span))?;
                            }
                            return Ok(acc);
                        }
                    }
                }
                // `Re²(L)` or `Re^2 L`: the power of a function follows its parentheses.
                let base = self.lower(a).map_err(|e| match (e.cause(), &a.kind) {
                    (ParseCause::FunctionWithoutParentheses { name }, ExprKind::Name(written))
                        if name == written && !a.in_parentheses() =>
                    {
                        let power = self.integer_exponent(b).ok();
                        function_without_parentheses(name, a.span, power)
                    }
                    _ => e,
                })?;
                match self.exponent(b)? {
                    Exponent::Integer(exp) => base
                        .checked_pow(exp)
                        .map_err(|e| self.with_written_factors(e, a, &base))
                        .map_err(at(span)),
                    // `R^(p/2)` is `√R^p`: `(x^2 + y^2)^(3/2)` is `r³` for `r = √(x² + y²)`.
                    Exponent::Half(p) => self
                        .root(&base, RootOf::Power(p), span)?
                        .checked_pow(p)
                        .map_err(at(span)),
                }
            }
            ExprKind::Call(name, name_span, args) => self.call(name, *name_span, args, span),
            ExprKind::Bracket(f, g) => {
                let f = self.lower(f)?;
                let g = self.lower(g)?;
                self.ctx.bracket(&f, &g).map_err(|e| match e {
                    BracketError::Algebra(e) => at(span)(e),
                    BracketError::Other(m) => ParseError::new(span, m),
                })
            }
        }
    }

    /// The name whose printed LaTeX spells `name` (`x_{1}` of a variable `x1`, read as `x_1`;
    /// `\theta_{2}` of `theta2`; `G_{1}` of a function `G1` of the context,
    /// [`Context::latex`]), where the text at `span` wrote it in LaTeX and no other variable's
    /// or function's LaTeX spells it alike: what [`Poly::render`] prints in LaTeX reads back.
    fn latex_spelled(&self, name: &str, span: Span) -> Option<String> {
        let written = self.src?.get(span.start..span.end)?;
        if !written.contains(['\\', '{']) {
            return None;
        }
        let spells = |latex: &str| latex_name(latex).as_deref() == Some(name);
        let variables = self
            .vars
            .vars()
            .map(|v| self.vars.variable(v))
            .filter(|v| spells(v.latex()))
            .map(|v| v.name().to_string());
        let functions = self
            .ctx
            .names()
            .into_iter()
            .filter(|f| self.ctx.latex(f).is_some_and(|latex| spells(&latex)));
        let mut found = variables.chain(functions);
        match (found.next(), found.next()) {
            (Some(n), None) => Some(n),
            _ => None,
        }
    }

    /// The variable that [`Lower::latex_spelled`] reads `name` at `span` as, if it is one.
    fn latex_variable(&self, name: &str, span: Span) -> Option<Var> {
        self.vars.lookup(&self.latex_spelled(name, span)?)
    }

    /// Of `name` an angle's (`theta`, `θ`), how functions depend on it: `functions depend on
    /// it through cos(theta), sin(theta) or exp(i*k*theta)`; of any other name, none.
    fn angle_use(&self, name: &str) -> Option<String> {
        let v = self.vars.lookup(name)?;
        let n = (self.vars.variable(v).kind() == VarKind::Angle)
            .then(|| self.vars.variable(v).name())?;
        Some(format!(
            "functions depend on it through cos({n}), sin({n}) or exp(i*k*{n})"
        ))
    }

    fn name(&self, name: &str, span: Span) -> Result<Poly<C>, ParseError> {
        if name == "i" {
            let i = C::from_gaussian(&GaussianRational::i()).ok_or_else(|| {
                ParseError::new(
                    span,
                    "the imaginary unit i needs Gaussian rational coefficients Q(i)",
                )
            })?;
            return Ok(Poly::constant(self.vars, i));
        }
        if let Some(v) = self.vars.lookup(name) {
            if let Some(through) = self.angle_use(name) {
                return Err(ParseError::new(
                    span,
                    format!("{name} is an angle: {through}"),
                ));
            }
            return Ok(Poly::var(self.vars, v));
        }
        if let Some(p) = self.ctx.lookup(name) {
            return Ok(p);
        }
        // A variable or function written in LaTeX as it prints (`x_{1}` of `x1`).
        if let Some(n) = self.latex_spelled(name, span) {
            return self.name(&n, span);
        }
        // The real or imaginary part of a name, as LaTeX sets it: `\operatorname{Re} A`.
        if let Some((part, of)) = name.split_once(' ') {
            let value = self.name(of, span)?;
            return match part {
                "Re" => value.re().map_err(at(span)),
                _ => value.im().map_err(at(span)),
            };
        }
        // The text form writes products of names side by side: `Mω` is `M·ω`.
        if let Some(parts) = self.read_split(name, span) {
            let mut acc = Poly::one(self.vars);
            for part in parts {
                acc = acc
                    .checked_mul(&self.name(&part, span)?)
                    .map_err(at(span))?;
            }
            return Ok(acc);
        }
        // A function written without its parentheses, as a paper writes `Re K` or `conj A`
        // (`cos θ` reads so; these do not): it is no unknown name, and the list of names would
        // not say what to write.
        if calls_function(name, &|n| self.is_declared(n)) {
            return Err(function_without_parentheses(name, span, None));
        }
        // A bar over a known name, as a paper writes the complex conjugate (`Ā`, LaTeX
        // `\bar{A}`, over the letter before a subscript `\bar{p}_{x}`), where no name is so
        // spelt: the conjugate is written conj(A).
        let bare = bars_apart(name);
        // Unless a variable is shown so, its bar written otherwise (`\bar{a}` or `ā` of a `c`
        // shown `ā`, a closure's generator `Zbar` shown `Z̄`): the name is that variable.
        if bare.contains('\u{304}') {
            let shown = |v: &Var| bars_apart(self.vars.variable(*v).unicode()) == bare;
            if let Some(v) = self.vars.vars().find(shown) {
                return self.name(self.vars.variable(v).name(), span);
            }
        }
        // An angle too, which conj does not take: its bar says so.
        let conjugated =
            |base: &String| self.name(base, span).is_ok() || self.angle_use(base).is_some();
        if let Some(base) = under_one_bar(name).filter(conjugated) {
            return Err(ParseError::new(
                span,
                format!(
                    "unknown name {}: {}",
                    quoted_name(name),
                    Reading::conjugate(self, &base)
                ),
            )
            .with_cause(ParseCause::Unreadable));
        }
        let known = self.known_names();
        // The name meant, as the context spells it (`Pp_1_1` for `P11` shown `P'_{1,1}`).
        let meant = did_you_mean(name, &known).map_or_else(String::new, |k| {
            meant_hint(&self.ctx.spelling(k).unwrap_or_else(|| k.to_string()))
        });
        // A set of no names (a constant's, `GaussianRational::from_str`'s) lists none.
        let listed = match known.is_empty() {
            true => " (no names are declared)".to_string(),
            false => format!(" (known: {})", known.join(", ")),
        };
        let message = format!("unknown name {}{meant}{listed}", quoted_name(name));
        Err(
            ParseError::new(span, message).with_cause(ParseCause::UnknownName {
                name: name.to_string(),
                known,
            }),
        )
    }

    /// Whether `name` is a declared name other than an angle, `i`, or a product of such names
    /// side by side (`Mω`).
    fn is_product_of_names(&self, name: &str) -> bool {
        self.is_declared(name) || self.split_name(name).is_some()
    }

    /// Whether `name` is `i` or a declared name that stands for a value (an angle does not).
    fn is_declared(&self, name: &str) -> bool {
        name == "i"
            || self
                .vars
                .lookup(name)
                .is_some_and(|v| self.vars.variable(v).kind() != VarKind::Angle)
            || self.ctx.lookup(name).is_some()
    }

    /// Whether `name` before parentheses is a function (`cos(θ)`, `Re(Z)`), not a product:
    /// `Re` and `Im` are the real and imaginary parts unless the system declares the name
    /// ([`calls_function`]); `sqrt` is read after a product of names ([`Lower::call`]).
    fn is_function(&self, name: &str) -> bool {
        name != "sqrt" && calls_function(name, &|n: &str| self.is_declared(n))
    }

    /// Splits `name`, at `span`, to be read as the product of its pieces ([`Self::split_name`]),
    /// and tells the context if that reading is in doubt ([`RunTogether::doubt`]).
    fn read_split(&self, name: &str, span: Span) -> Option<Vec<String>> {
        let pieces = self.split_name(name)?;
        let known = self.known_names();
        // A piece that is no variable is one of the context's names.
        let function = |p: &str| self.vars.lookup(p).is_none() && known.iter().any(|k| k == p);
        if let Some(doubt) = RunTogether::doubt(name, &pieces, &known, &function) {
            self.ctx.run_together(RunTogether {
                name: name.to_string(),
                span,
                pieces: pieces.clone(),
                doubt,
            });
        }
        Some(pieces)
    }

    /// The names an expression may use: the variables', then the context's.
    fn known_names(&self) -> Vec<String> {
        let mut known: Vec<String> = self
            .vars
            .vars()
            .map(|v| self.vars.variable(v).name().to_string())
            .collect();
        known.extend(self.ctx.names());
        known
    }

    /// Splits a name that is not declared into declared names (`Mω` → `M`, `ω`), longest
    /// prefix first; `None` if no split exists.
    fn split_name(&self, name: &str) -> Option<Vec<String>> {
        split_names(name, &|s: &str| self.is_declared(s))
    }

    /// Splits a name in an angle's argument into `i` and angles (`iθ`, as the echo writes
    /// `exp(i*θ)`): the angle, if any, with its coefficient (a power of `i`); `None` if the
    /// name is no such product.
    fn split_angle_name(&self, name: &str) -> Option<(Option<Var>, GaussianRational)> {
        let angle = |s: &str| {
            self.vars
                .lookup(s)
                .filter(|&v| self.vars.variable(v).kind() == VarKind::Angle)
        };
        let pieces = split_names(name, &|s: &str| s == "i" || angle(s).is_some())?;
        let mut coefficient = GaussianRational::from(1);
        let mut found = None;
        for piece in &pieces {
            match angle(piece) {
                Some(v) if found.is_none() => found = Some(v),
                Some(_) => return None,
                None => coefficient = &coefficient * &GaussianRational::i(),
            }
        }
        Some((found, coefficient))
    }

    /// A refused division by `divisor` (or negative power of it) shown and advised by its
    /// factors as written when it is a product or power of polynomials that are not all
    /// invertible: `cannot divide by (x − y)²` and the advice to declare `x − y`, `(x + y)(x −
    /// 2y)³` and `x + y`, `x − 2y`, rather than the expanded polynomial.
    fn with_written_factors(
        &self,
        e: AlgebraError,
        divisor: &Expr,
        value: &Poly<C>,
    ) -> AlgebraError {
        // Only these two are rewritten: another error (a limit, say) is given as it is, before
        // any factor is tried (`cos(16384θ)²` past the order limit took a minute to show its
        // factor in powers of `cos θ` for a message that did not use it).
        if !matches!(
            e,
            AlgebraError::NotAMonomial { .. } | AlgebraError::NegativePower { .. }
        ) {
            return e;
        }
        let mut factors = Vec::new();
        let mut negative = false;
        if self
            .written_factors(divisor, 1, &mut factors, &mut negative)
            .is_err()
        {
            return e;
        }
        let mut to_declare: Vec<String> = Vec::new();
        for (p, _) in &factors {
            match Poly::one(self.vars).checked_div(p) {
                Ok(_) => {}
                Err(AlgebraError::NotAMonomial { .. }) => match p.ascii_within(8, 80) {
                    Some(text) if !to_declare.contains(&text) => to_declare.push(text),
                    Some(_) => {}
                    None => return e,
                },
                Err(_) => return e,
            }
        }
        if to_declare.is_empty() || to_declare == [value.to_ascii()] {
            return e;
        }
        let declare = Poly::<C>::factors_declaration(&to_declare);
        let written = written_product(&factors, negative);
        let shown = |shown: String| match written.chars().count() <= 80 {
            true => written.clone(),
            false => shown,
        };
        match e {
            AlgebraError::NotAMonomial { shown: s, .. } => AlgebraError::NotAMonomial {
                shown: shown(s),
                declare,
            },
            AlgebraError::NegativePower { shown: s, .. } => AlgebraError::NegativePower {
                shown: shown(s),
                declare,
            },
            other => other,
        }
    }

    /// The factors of `e` as written, through products, negations (which flip `negative`) and
    /// positive integer powers, each lowered, with the power it is taken to times `power`;
    /// `Err` when a factor does not lower.
    fn written_factors(
        &self,
        e: &Expr,
        power: i64,
        out: &mut Vec<(Poly<C>, i64)>,
        negative: &mut bool,
    ) -> Result<(), ()> {
        match &e.kind {
            ExprKind::Mul(a, b) => {
                self.written_factors(a, power, out, negative)?;
                self.written_factors(b, power, out, negative)
            }
            ExprKind::Neg(a) => {
                *negative ^= power % 2 == 1;
                self.written_factors(a, power, out, negative)
            }
            ExprKind::Pow(a, b)
                // `M(x + y)²` and `Mω²` lower by their own rules: those are taken whole.
                if !matches!(a.kind, ExprKind::Name(_) | ExprKind::Call(..)) =>
            {
                match self.integer_exponent(b) {
                    Ok(n) if n > 0 => {
                        self.written_factors(a, power.saturating_mul(n), out, negative)
                    }
                    _ => self.written_leaf(e, power, out),
                }
            }
            _ => self.written_leaf(e, power, out),
        }
    }

    fn written_leaf(&self, e: &Expr, power: i64, out: &mut Vec<(Poly<C>, i64)>) -> Result<(), ()> {
        out.push((self.lower(e).map_err(|_| ())?, power));
        Ok(())
    }

    fn integer_exponent(&self, e: &Expr) -> Result<i64, ParseError> {
        match self.exponent(e)? {
            Exponent::Integer(n) => Ok(n),
            Exponent::Half(p) => Err(ParseError::new(
                e.span,
                format!("exponents must be integers here, found {p}/2"),
            )),
        }
    }

    /// An exponent: an integer constant, or half an odd one (a power of a radical), within
    /// the degree limit.
    fn exponent(&self, e: &Expr) -> Result<Exponent, ParseError> {
        let p: Poly<C> = self.lower(e)?;
        let value = p
            .as_constant()
            .and_then(|c| Rational::from_gaussian(&c.to_gaussian()));
        let limit = self.vars.limits().max_degree;
        let Some(q) = value else {
            return Err(ParseError::new(
                e.span,
                "exponents must be integer constants",
            ));
        };
        let twice = &q * &Rational::from(2);
        let exponent = match (q.is_integer(), twice.is_integer()) {
            (true, _) => q.numer().to_i64().map(Exponent::Integer),
            (false, true) => twice.numer().to_i64().map(Exponent::Half),
            (false, false) => {
                return Err(ParseError::new(
                    e.span,
                    format!(
                        "exponents must be integers or halves of odd integers (a power of a \
                         declared radical, (x^2 + y^2)^(3/2) for r^3), found {q} (other \
                         fractional powers are not polynomial)"
                    ),
                ))
            }
        };
        // The limit bounds the power of the radical too (`p` of `p/2`).
        match exponent {
            Some(x @ (Exponent::Integer(n) | Exponent::Half(n)))
                if n.unsigned_abs() <= u64::from(limit) =>
            {
                Ok(x)
            }
            // An exponent written as a power may be long: its size, not its digits.
            _ if q.numer().bits() > 256 => Err(ParseError::new(
                e.span,
                format!(
                    "the exponent, of {} bits, is past the limit of {limit}",
                    q.numer().bits()
                ),
            )
            .with_cause(ParseCause::PowerPastLimit { power: None, limit })),
            // The size of `p` of a half `p/2`, as the limit bounds it.
            _ => Err(ParseError::new(
                e.span,
                format!("the exponent {q} is past the limit of {limit}"),
            )
            .with_cause(ParseCause::PowerPastLimit {
                power: size(&if q.is_integer() {
                    q.numer()
                } else {
                    twice.numer()
                }),
                limit,
            })),
        }
    }

    fn call(
        &self,
        name: &str,
        name_span: Span,
        args: &[Expr],
        span: Span,
    ) -> Result<Poly<C>, ParseError> {
        let fun = match name {
            _ if FUNCTIONS.contains(&name) => name,
            // The paper's (and the echo's) real and imaginary parts.
            "Re" if self.is_function(name) => "re",
            "Im" if self.is_function(name) => "im",
            // A name before parentheses is a product, as the text form prints it:
            // `Mω(3x p_x² − …)`, `i(mω − nΩ)`.
            _ if args.len() == 1 && self.is_product_of_names(name) => {
                return self
                    .name(name, name_span)?
                    .checked_mul(&self.lower(&args[0])?)
                    .map_err(at(span));
            }
            "sqrt" if args.len() == 1 => return self.sqrt(&args[0], span),
            // Said as the others are: `sqrt takes one argument`.
            "sqrt" => name,
            _ => {
                // Every function an expression may call, as an unknown one is told: the
                // reserved names but `i` ([`FUNCTIONS`] and `sqrt`), the real and imaginary
                // parts as they are typed and printed, `Re` and `Im`, where no declared name
                // takes those spellings.
                let typed = |n: &'static str| match n {
                    "re" if self.is_function("Re") => "Re",
                    "im" if self.is_function("Im") => "Im",
                    _ => n,
                };
                let called: Vec<&str> =
                    (RESERVED.iter().copied().filter(|&n| n != "i").map(typed)).collect();
                // A declared name is no misspelled function: `Re(x, y)` where `Re` is a
                // parameter is not the real part `re`.
                let misspelled = did_you_mean(name, &called).filter(|_| !self.is_declared(name));
                let hint = match (misspelled, name) {
                    (Some(k), _) => format!("; did you mean '{k}'?"),
                    (None, "tan" | "log" | "ln" | "atan" | "arctan" | "abs") => "; expressions \
                         are polynomials in the variables, in cos and sin of angles and in \
                         negative powers of single terms"
                        .to_string(),
                    _ => String::new(),
                };
                return Err(ParseError::new(
                    name_span,
                    format!(
                        "unknown function {} (known: {}){hint}",
                        quoted_name(name),
                        called.join(", ")
                    ),
                ));
            }
        };
        if args.len() != 1 {
            // As written: `Re takes one argument`, of the real part `re`.
            return Err(ParseError::new(
                span,
                format!("{name} takes one argument, found {}", args.len()),
            ));
        }
        let arg = &args[0];
        // The complex structure: every variable is real, so conj maps e^{ikθ} to e^{−ikθ}.
        match fun {
            "conj" => return Ok(self.lower(arg)?.conj()),
            "re" => return self.lower(arg)?.re().map_err(at(span)),
            "im" => return self.lower(arg)?.im().map_err(at(span)),
            _ => {}
        }
        let multiples = self.angle_multiples(arg, fun)?;
        // A refusal of the algebra keeps its cause, a limit a limit (`cos θ` past a term
        // limit of 1).
        let wrap = &at(arg.span);
        // e^{±i Σ n_j θ_j}
        let exp_i = |sign: i64| -> Result<Poly<C>, ParseError> {
            let mut acc = Poly::one(self.vars);
            for &(v, n) in &multiples {
                acc = acc
                    .checked_mul(&Poly::exp_i(self.vars, v, sign * n).map_err(wrap)?)
                    .map_err(wrap)?;
            }
            Ok(acc)
        };
        match fun {
            "exp" => exp_i(1),
            "cos" => Ok(exp_i(1)?.checked_add(&exp_i(-1)?).map_err(wrap)? * &Rational::new(1, 2)),
            // sin φ = (e^{iφ} − e^{−iφ})/(2i)
            _ => exp_i(1)?
                .checked_sub(&exp_i(-1)?)
                .and_then(|d| d.mul_i())
                .map(|p| p * &Rational::new(-1, 2))
                .map_err(wrap),
        }
    }

    /// `sqrt(E)`: a declared radical `r` when `E` is its radicand times the square of a
    /// positive rational (`sqrt(4*x^2 + 4*y^2)` is `2r` for `r = √(x² + y²)`), or the rational
    /// root of a constant; any other root is refused with the declaration that makes it one.
    fn sqrt(&self, arg: &Expr, span: Span) -> Result<Poly<C>, ParseError> {
        self.root(&self.lower(arg)?, RootOf::Sqrt, span)
    }

    /// The root of `value` that `sqrt(value)` or a half-integer power `value^(p/2)` takes (see
    /// [`Lower::sqrt`]); a refusal names the declaration that makes it one, and what then
    /// reads as a power of the radical.
    fn root(&self, value: &Poly<C>, of: RootOf, span: Span) -> Result<Poly<C>, ParseError> {
        if let Some(root) = Poly::root_by_radicals(value).map_err(at(span))? {
            return Ok(root);
        }
        if let Some(c) = value.as_constant() {
            let message =
                format!("sqrt({c}) is not a rational number: write the root as a parameter");
            return Err(ParseError::new(span, message));
        }
        // A radical of a square, or of minus one, would be refused where it is declared: the
        // root is a polynomial, up to a sign that the writer chooses.
        let message = match value.root_up_to_sign() {
            Some((root, false)) => format!(
                "sqrt({value}) is |{root}|, whose sign is for you to choose: {}",
                root.sign_advice(false)
            ),
            Some((root, true)) => format!(
                "sqrt({value}) is i·|{root}|, whose sign is for you to choose: {}",
                root.sign_advice(true)
            ),
            None => {
                let reads = match of {
                    RootOf::Sqrt => "sqrt of it reads as r".to_string(),
                    RootOf::Power(1) => "its power 1/2 reads as r".to_string(),
                    RootOf::Power(p) => format!("its power {p}/2 reads as r^{p}"),
                };
                format!(
                    "sqrt({value}) is no declared radical: declare it (radicals = {{ r = \"{}\" }} \
                     in [phase_space], for a name r of yours), and {reads}",
                    value.to_ascii()
                )
            }
        };
        Err(ParseError::new(span, message))
    }

    /// The multiples `n_j` in `cos(Σ n_j θ_j)`, `sin(Σ n_j θ_j)` or `exp(i Σ n_j θ_j)`: the
    /// argument read as a linear form over the angles, whose coefficients must be integers for
    /// `cos` and `sin` and `i` times integers for `exp`.
    fn angle_multiples(&self, arg: &Expr, fun: &str) -> Result<Vec<(Var, i64)>, ParseError> {
        let bad = |span: Span| {
            let message = if fun == "exp" {
                "exp takes i times an integer combination of angles, such as exp(i*(2*theta - phi))"
                    .to_string()
            } else {
                format!(
                    "{fun} takes an integer combination of angles, such as {fun}(2*theta - phi)"
                )
            };
            ParseError::new(span, message)
        };
        let form = match self.linear_form(arg, &bad)? {
            LinearForm::Angles(form) => form,
            // The angle 0, a combination with no angle: `cos(0) = 1`, `sin(0) = 0`.
            LinearForm::Constant(c) if c.is_zero() => Vec::new(),
            LinearForm::Constant(_) => return Err(bad(arg.span)),
        };
        let real = form.iter().all(|(_, c)| c.im.is_zero());
        let imaginary = form.iter().all(|(_, c)| c.re.is_zero());
        let multiple: fn(&GaussianRational) -> &Rational = match fun {
            "exp" if imaginary => |c| &c.im,
            "exp" if real => {
                return Err(ParseError::new(
                    arg.span,
                    "exp takes i·n·θ with an integer n and an angle θ, such as exp(-i*2*theta)",
                ))
            }
            "exp" => return Err(bad(arg.span)),
            _ if real => |c| &c.re,
            _ if imaginary => {
                return Err(ParseError::new(
                    arg.span,
                    format!("{fun} takes a real angle n·θ; use exp for complex exponentials"),
                ))
            }
            _ => return Err(bad(arg.span)),
        };
        let limit = self.vars.limits().max_degree;
        form.iter()
            .map(|(v, c)| {
                // Only integers, i and their nonnegative powers enter the form: its
                // coefficients are Gaussian integers.
                let n = multiple(c).numer();
                let angle = self.vars.variable(*v).unicode();
                match n.to_i64() {
                    Some(k) if k.unsigned_abs() <= limit as u64 => Ok((*v, k)),
                    // A multiple written as a power may be long: its size, not its digits.
                    _ if n.bits() > 256 => Err(ParseError::new(
                        arg.span,
                        format!(
                            "the multiple of {angle}, of {} bits, is past the limit of {limit}",
                            n.bits()
                        ),
                    )
                    .with_cause(ParseCause::PowerPastLimit { power: None, limit })),
                    _ => Err(ParseError::new(
                        arg.span,
                        format!("the multiple {n} of {angle} is past the limit of {limit}"),
                    )
                    .with_cause(ParseCause::PowerPastLimit {
                        power: size(&n),
                        limit,
                    })),
                }
            })
            .collect()
    }

    /// The linear form of the product `a·b`: one side must be a constant.
    fn product_form(
        &self,
        a: &Expr,
        b: &Expr,
        bad: &dyn Fn(Span) -> ParseError,
    ) -> Result<LinearForm, ParseError> {
        use LinearForm::{Angles, Constant};
        Ok(
            match (self.linear_form(a, bad)?, self.linear_form(b, bad)?) {
                (Constant(x), Constant(y)) => Constant(&x * &y),
                (Constant(c), form) | (form, Constant(c)) => form.scale(&c),
                // A product of angles.
                (Angles(_), Angles(_)) => return Err(bad(b.span)),
            },
        )
    }

    /// Reads `e` as a linear form over the angles with Gaussian-integer coefficients: integers,
    /// `i` and angles combined by `+`, `−`, products and quotients in which one side is a
    /// constant (the constants' quotients and integer powers may be fractions, the angles'
    /// multiples not). What does not fit is refused by `bad` at its span.
    fn linear_form(
        &self,
        e: &Expr,
        bad: &dyn Fn(Span) -> ParseError,
    ) -> Result<LinearForm, ParseError> {
        use LinearForm::{Angles, Constant};
        let form = match &e.kind {
            ExprKind::Integer(n) => Constant(Rational::from(Integer::from(n.clone())).into()),
            ExprKind::Name(n) if n == "i" => Constant(GaussianRational::i()),
            ExprKind::Name(n) => match self
                .vars
                .lookup(n)
                .or_else(|| self.latex_variable(n, e.span))
            {
                Some(v) if self.vars.variable(v).kind() == VarKind::Angle => {
                    Angles(vec![(v, GaussianRational::from(1))])
                }
                // A parameter may have been meant as a multiple (`cos(k*theta)`): the message
                // says what a multiple must be.
                Some(v) if self.vars.variable(v).kind() == VarKind::Parameter => {
                    return Err(bad(e.span))
                }
                Some(v) => {
                    let kind = self.vars.variable(v).kind().described();
                    return Err(ParseError::new(
                        e.span,
                        format!(
                            "'{n}' is {kind}, not an angle: cos, sin and exp(i…) take angles, \
                             declared under `angles` in [phase_space] (of anything else they \
                             are no polynomial)"
                        ),
                    ));
                }
                None => match self.split_angle_name(n) {
                    Some((Some(v), c)) => Angles(vec![(v, c)]),
                    Some((None, c)) => Constant(c),
                    None => {
                        let message = format!("unknown angle {}", quoted_name(n));
                        return Err(ParseError::new(e.span, message));
                    }
                },
            },
            ExprKind::Neg(a) => self.linear_form(a, bad)?.scale(&GaussianRational::from(-1)),
            ExprKind::Add(a, b) | ExprKind::Sub(a, b) => {
                let sign = if matches!(e.kind, ExprKind::Sub(..)) {
                    -1
                } else {
                    1
                };
                let lhs = self.linear_form(a, bad)?;
                let rhs = self
                    .linear_form(b, bad)?
                    .scale(&GaussianRational::from(sign));
                match (lhs, rhs) {
                    (Constant(x), Constant(y)) => Constant(&x + &y),
                    (Angles(mut x), Angles(y)) => {
                        for (v, c) in y {
                            match x.iter_mut().find(|(w, _)| *w == v) {
                                Some((_, sum)) => *sum = &*sum + &c,
                                None => x.push((v, c)),
                            }
                        }
                        Angles(x)
                    }
                    // A constant phase, as in cos(θ + 1), is not a polynomial in cos θ, sin θ.
                    (Angles(x), Constant(c)) | (Constant(c), Angles(x)) if c.is_zero() => Angles(x),
                    (Angles(_), Constant(_)) => return Err(bad(b.span)),
                    (Constant(_), Angles(_)) => return Err(bad(a.span)),
                }
            }
            ExprKind::Mul(a, b) => integral(self.product_form(a, b, bad)?, e, bad)?,
            // A quotient by a constant, `4/2` in `cos(4/2*θ)` or `(4*θ)/2`; the multiples it
            // leaves must be integers (`θ/2` is refused, even inside `2*(θ/2)`).
            ExprKind::Div(a, b) => {
                let Constant(divisor) = self.linear_form(b, bad)? else {
                    return Err(bad(b.span));
                };
                let inverse = divisor
                    .try_inv()
                    .ok_or_else(|| ParseError::new(b.span, "division by zero"))?;
                integral(self.linear_form(a, bad)?.scale(&inverse), e, bad)?
            }
            // A constant written as a power, `2^3` in `cos(2^3*θ)`: a constant to an integer
            // exponent within the degree limit; its size is bounded as any power's.
            ExprKind::Pow(a, b) => {
                let Constant(base) = self.linear_form(a, bad)? else {
                    return Err(bad(e.span));
                };
                let Exponent::Integer(exp) = self.exponent(b)? else {
                    return Err(bad(e.span));
                };
                let power = Poly::constant(self.vars, base)
                    .checked_pow(exp)
                    .map_err(at(e.span))?;
                Constant(
                    power
                        .as_constant()
                        .expect("a power of a constant is a constant"),
                )
            }
            // `i(θ − φ)`: a name before parentheses multiplies them, as the echo writes it.
            ExprKind::Call(name, name_span, args) if args.len() == 1 && !self.is_function(name) => {
                let factor = Expr::new(ExprKind::Name(name.clone()), *name_span);
                integral(self.product_form(&factor, &args[0], bad)?, e, bad)?
            }
            _ => return Err(bad(e.span)),
        };
        Ok(form)
    }
}

/// `form`, the linear form of the product or quotient `e`, when its multiples of the angles
/// are Gaussian integers (its constants may be any); else refused by `bad` at `e`: `θ/2`.
fn integral(
    form: LinearForm,
    e: &Expr,
    bad: &dyn Fn(Span) -> ParseError,
) -> Result<LinearForm, ParseError> {
    match &form {
        LinearForm::Angles(multiples)
            if !multiples
                .iter()
                .all(|(_, c)| c.re.is_integer() && c.im.is_integer()) =>
        {
            Err(bad(e.span))
        }
        _ => Ok(form),
    }
}

/// A name as a message quotes it: whole, or when it is long (a name typed by mistake may be a
/// whole line: 100 KB echoed) its first characters and its length, `'aaaa…', 300 characters
/// long`.
pub fn quoted_name(name: &str) -> String {
    match long_name(name) {
        None => format!("'{name}'"),
        Some((_, n)) => format!("'{}', {n} characters long", shown_name(name)),
    }
}

/// A name as [`quoted_name`] shows it between its quotes: whole, or when it is long its first
/// characters and `…`, so that what is said of it beside a message (a hint) names it as the
/// message does.
///
/// ```
/// assert_eq!(trigpoly::shown_name("p_x"), "p_x");
/// assert_eq!(trigpoly::shown_name(&"q".repeat(81)), format!("{}…", "q".repeat(40)));
/// ```
pub fn shown_name(name: &str) -> String {
    match long_name(name) {
        None => name.to_string(),
        Some((start, _)) => format!("{start}…"),
    }
}

/// An argument of `cos`, `sin` or `exp` read as a linear form: a constant, or `Σ c_j θ_j` over
/// the angles (each angle once) with Gaussian-integer multiples.
enum LinearForm {
    Constant(GaussianRational),
    Angles(Vec<(Var, GaussianRational)>),
}

impl LinearForm {
    fn scale(self, k: &GaussianRational) -> LinearForm {
        match self {
            LinearForm::Constant(c) => LinearForm::Constant(&c * k),
            LinearForm::Angles(form) => {
                LinearForm::Angles(form.into_iter().map(|(v, c)| (v, &c * k)).collect())
            }
        }
    }
}

/// The functions an expression may call: a name before parentheses other than these (and
/// `Re`, `Im` where the system does not declare them) multiplies them.
pub const FUNCTIONS: [&str; 6] = ["cos", "sin", "exp", "conj", "re", "im"];

/// Whether `name` before parentheses calls a function rather than multiplies them: one of
/// [`FUNCTIONS`], `sqrt`, or `Re` or `Im`, the real and imaginary parts as the paper writes
/// them, unless `declared` says the system declares that name. The one list of what is called
/// that the lowering ([`Lower::is_function`]) and the parser's refusals
/// ([`Reading::calls`], by the lowering's reading or with no name declared) read.
pub(crate) fn calls_function(name: &str, declared: &dyn Fn(&str) -> bool) -> bool {
    match name {
        "Re" | "Im" => !declared(name),
        _ => FUNCTIONS.contains(&name) || name == "sqrt",
    }
}

/// The refusal of `name`, a function the parser knows ([`calls_function`]), written without
/// the parentheses of its argument (`Re K`, `conj A`), at `span`; with the power it was
/// raised to where it was (`Re²(L)`), which is written after the parentheses (`Re(…)^2`).
fn function_without_parentheses(name: &str, span: Span, power: Option<i64>) -> ParseError {
    let what = match name {
        "re" | "Re" => "the real part",
        "im" | "Im" => "the imaginary part",
        "conj" => "the complex conjugate",
        "sqrt" => "the square root",
        "exp" => "the exponential",
        "cos" => "the cosine",
        "sin" => "the sine",
        // A function added to FUNCTIONS before it is named here.
        _ => "",
    };
    let what = match what {
        "" => "a function".to_string(),
        what => format!("{what}, a function"),
    };
    let how = match power {
        Some(n) => {
            format!("write its argument in parentheses and the power after them, {name}(…)^{n}")
        }
        None => format!("write its argument in parentheses, {name}(…)"),
    };
    ParseError::new(span, format!("'{name}' is {what}: {how}")).with_cause(
        ParseCause::FunctionWithoutParentheses {
            name: name.to_string(),
        },
    )
}

/// The longest piece, in bytes, that a name run together splits into: a declared name is
/// shorter, and the bound keeps the split linear in the length of what is split (a run of
/// 16 000 `x` took 15 s and 1 GB).
const LONGEST_PIECE: usize = 256;

/// Splits `name` into names that `known` takes (`Mω` → `M`, `ω`), longest prefix first, at
/// least two of them; `None` if no split exists. This is how an expression reads names run
/// together that are not declared (`Lx` is `L·x`). Each piece is at most `LONGEST_PIECE`
/// bytes; whether the rest from each place splits is decided once, from the end.
pub fn split_names(name: &str, known: &dyn Fn(&str) -> bool) -> Option<Vec<String>> {
    if name.chars().count() < 2 {
        return None;
    }
    // The cuts after `at`: the ends of its pieces of at most LONGEST_PIECE bytes, longest
    // first.
    let cuts = |at: usize| {
        let rest = &name[at..];
        let mut ends: Vec<usize> = rest
            .char_indices()
            .map(|(k, _)| k)
            .skip(1)
            .chain([rest.len()])
            .take_while(|&k| k <= LONGEST_PIECE)
            .collect();
        ends.reverse();
        ends.into_iter().map(move |k| at + k)
    };
    // splits[at]: whether name[at..] is a sequence of known names.
    let mut splits = vec![false; name.len() + 1];
    splits[name.len()] = true;
    for (at, _) in name.char_indices().rev() {
        splits[at] = cuts(at).any(|end| splits[end] && known(&name[at..end]));
    }
    if !splits[0] {
        return None;
    }
    let mut out = Vec::new();
    let mut at = 0;
    while at < name.len() {
        let end = cuts(at)
            .find(|&end| splits[end] && known(&name[at..end]))
            .expect("a place that splits has a first piece");
        out.push(name[at..end].to_string());
        at = end;
    }
    (out.len() > 1).then_some(out)
}

/// `; did you mean 'p_x'?`, to follow a message about `name` that is none of `known`, where
/// [`did_you_mean`] finds the one meant; else nothing.
pub fn did_you_mean_hint(name: &str, known: &[impl AsRef<str>]) -> String {
    did_you_mean(name, known).map_or_else(String::new, meant_hint)
}

/// `; did you mean 'p_x'?` of the name meant.
fn meant_hint(meant: &str) -> String {
    format!("; did you mean '{meant}'?")
}

/// The known name that `name` was probably meant to be: the same letters but for case and
/// underscores (`px` for `p_x`, `Cos` for `cos`, `Omega` for `omega`), when there is one;
/// else, for a name of three characters or more, the one known name of three or more a single
/// slip away (a character changed, added or left out, or two neighbours swapped: `omegaa`,
/// `Omgea` for `omega`, `Omega`), when exactly one is (`Ayx` beside `Axy` and
/// `Ayy` could be either, and `G3` beside `G1` is a name of its own more likely than a slip).
pub fn did_you_mean<'k>(name: &str, known: &'k [impl AsRef<str>]) -> Option<&'k str> {
    let key = |s: &str| s.replace('_', "").to_lowercase();
    let wanted = key(name);
    let known = || known.iter().map(AsRef::as_ref).filter(move |&k| k != name);
    if let Some(k) = known().find(|&k| key(k) == wanted) {
        return Some(k);
    }
    let long = |s: &str| s.chars().count() >= 3;
    if !long(name) {
        return None;
    }
    let mut slips = known().filter(|&k| long(k) && one_slip(name, k));
    match (slips.next(), slips.next()) {
        (Some(k), None) => Some(k),
        _ => None,
    }
}

/// Whether `a` and `b` differ by one slip: a character changed, added or left out, or two
/// neighbouring characters swapped.
fn one_slip(a: &str, b: &str) -> bool {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let (short, long) = if a.len() <= b.len() {
        (&a, &b)
    } else {
        (&b, &a)
    };
    let start = short
        .iter()
        .zip(long.iter())
        .take_while(|(x, y)| x == y)
        .count();
    match long.len() - short.len() {
        // One left out: the rest of the longer one, past the slip, is the rest of the shorter.
        1 => short[start..] == long[start + 1..],
        0 if start < short.len() => {
            // One changed, or two neighbours swapped.
            short[start + 1..] == long[start + 1..]
                || (start + 1 < short.len()
                    && short[start] == long[start + 1]
                    && short[start + 1] == long[start]
                    && short[start + 2..] == long[start + 2..])
        }
        _ => false,
    }
}
