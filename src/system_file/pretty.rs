//! Statements in the paper's notation: a parsed expression printed back as written, with
//! unicode names (`p_θ`, `ω`, `Z̄`, `K_{2,3}`), superscript exponents and implicit products:
//! `{L, G1} = -G2` reads `{L, G1} = −G2`, `4*G1^2 + omega^2*L^2` reads `4 G1² + ω² L²`.

use std::convert::Infallible;

use num_bigint::{BigInt, Sign};

use trigpoly::superscript;
use trigpoly::syntax::{Expr as Tree, ExprKind, LEFT_DEEP_SUM};

use super::scope::instance_of;
use super::LoadedSystem;

/// A printed subexpression: its text, how tightly it binds, whether its first and last atoms
/// are names longer than one character (which products separate by a space), and where a name
/// of several words that ends it starts (`Re K` in `6ω Re K`), which takes parentheses when a
/// factor, a power or a denominator follows it.
struct Printed {
    text: String,
    prec: u8,
    first_long: bool,
    last_long: bool,
    trailing_words: Option<usize>,
}

const SUM: u8 = 1;
/// A quotient: a factor of a product only in parentheses, since `x/2y` and `5/7i` read as
/// `x/(2y)` and `5/(7i)` (written `(x/2)y`, `x(5/7)i`).
const QUOTIENT: u8 = 2;
const PRODUCT: u8 = 3;
const NEG: u8 = 4;
const POWER: u8 = 5;
const ATOM: u8 = 6;

/// Where a product writes two one-letter names side by side (`M` and `ω` of `Mω`) while it is
/// printed: once the whole expression is, the run of letters each stands in becomes spaced or
/// not ([`LoadedSystem::settle_runs`]). An invisible times, which no name has.
const JUXTAPOSED: &str = "\u{2062}";

impl Printed {
    fn atom(text: String) -> Self {
        let long = text
            .chars()
            .filter(|c| !crate::render::tex::is_combining(*c))
            .count()
            > 1
            && !text.chars().all(|c| c.is_ascii_digit());
        Printed {
            text,
            prec: ATOM,
            first_long: long,
            last_long: long,
            trailing_words: None,
        }
    }

    /// The text with its trailing name of several words, or derivative or gradient, in
    /// parentheses, if it has one: `6ω (Re K)`, `2(∂H)`, before a factor, a power or a
    /// denominator.
    fn words_closed(mut self) -> Self {
        if let Some(at) = self.trailing_words.take() {
            self.text.insert(at, '(');
            self.text.push(')');
            if at == 0 {
                self.prec = ATOM;
            }
        }
        self
    }

    /// Whether the name that ends the text and takes parentheses before a factor, a power or
    /// a denominator is a derivative or a gradient, `∂H` (not a name of several words).
    fn differential_last(&self) -> bool {
        self.trailing_words
            .is_some_and(|at| trigpoly::is_differential(&self.text[at..]))
    }

    fn wrapped(self, min: u8) -> Self {
        if self.prec >= min {
            self
        } else {
            Printed {
                text: format!("({})", self.text),
                prec: ATOM,
                first_long: false,
                last_long: false,
                trailing_words: None,
            }
        }
    }
}

impl LoadedSystem {
    /// The name of a variable, function or family instance as printed, `name` itself for
    /// anything else. A function's or family's display is written as the expressions write
    /// it ([`trigpoly::shown_text`], as a variable's name is): a Greek letter spelled out
    /// becomes the letter, `omega3` → `ω3`, `Q_theta1_1_2` → `Q_θ1_{1,2}`.
    ///
    /// ```
    /// use superint::system_file::{load, LimitsOverride};
    ///
    /// let rotor = load("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
    /// assert_eq!(rotor.display_name("Zbar"), "Z̄");
    /// assert_eq!(rotor.display_name("Kbar_1_2"), "K̄_{1,2}");
    /// assert_eq!(rotor.display_name("omega"), "ω");
    /// assert_eq!(rotor.display_name("W"), "W");
    /// # Ok::<(), superint::system_file::FileError>(())
    /// ```
    pub fn display_name(&self, name: &str) -> String {
        let vars = self.system.vars();
        if let Some(v) = vars.lookup(name) {
            return vars.variable(v).unicode().to_string();
        }
        if self.system.get(name).is_ok() {
            return trigpoly::shown_text(self.system.display_name(name));
        }
        if let Some((k, m, n)) = instance_of(&self.families, name) {
            return format!(
                "{}_{{{m},{n}}}",
                trigpoly::shown_text(&self.families[k].display)
            );
        }
        for f in &self.families {
            let pattern = format!("{}_{}_{}", f.name, f.indices[0], f.indices[1]);
            if name == pattern {
                let (m, n) = (&f.indices[0], &f.indices[1]);
                return format!("{}_{{{m},{n}}}", trigpoly::shown_text(&f.display));
            }
        }
        name.to_string()
    }

    /// Whether `name` is one name of the system (a variable, function, family instance or
    /// `i`), not names run together.
    fn is_declared_name(&self, name: &str) -> bool {
        self.declares(name) || instance_of(&self.families, name).is_some()
    }

    /// An expression tree in the paper's notation.
    pub(crate) fn pretty(&self, tree: &Tree) -> String {
        self.settle_runs(&self.print(tree).text)
    }

    /// An expression tree in the paper's notation as the left factor of a product: a sum or a
    /// quotient in parentheses (`(iωm − 3iωn) W_{m,n}`).
    pub(crate) fn pretty_factor(&self, tree: &Tree) -> String {
        self.settle_runs(&self.print(tree).wrapped(PRODUCT).text)
    }

    /// `text` with each run of one-letter names side by side ([`JUXTAPOSED`] between each two)
    /// written with a space between each two where two or more of them in a row spell another
    /// name of the system, a variable or a function (`x y` beside a function `xy`,
    /// `VarSet::juxtaposition_is_ambiguous`), which it would read back as; run together
    /// elsewhere, as the paper writes them (`2iMωy` beside functions `Hx` and `Hy`).
    fn settle_runs(&self, text: &str) -> String {
        let in_run = |c: char| JUXTAPOSED.contains(c) || is_letter(c);
        let mut out = String::with_capacity(text.len());
        let mut rest = text;
        while let Some(at) = rest.find(JUXTAPOSED) {
            let start = rest[..at].trim_end_matches(in_run).len();
            let end = rest[at..]
                .find(|c: char| !in_run(c))
                .map_or(rest.len(), |k| at + k);
            let run: Vec<&str> = rest[start..end].split(JUXTAPOSED).collect();
            // The file's variables know its functions' names too (`VarsBuilder::also_named`).
            let ambiguous = self.system.vars().juxtaposition_is_ambiguous(&run);
            out.push_str(&rest[..start]);
            out.push_str(&run.join(if ambiguous { " " } else { "" }));
            rest = &rest[end..];
        }
        out.push_str(rest);
        out
    }

    /// `tree` printed, its one-letter names side by side with [`JUXTAPOSED`] between them.
    fn print(&self, tree: &Tree) -> Printed {
        match &tree.kind {
            ExprKind::Integer(n) => Printed::atom(n.to_string()),
            ExprKind::Name(n) => match self.run_together(tree, n, None) {
                Some(product) => self.print(&product),
                None => self.print_name(n),
            },
            ExprKind::Pow(a, b)
                if let (ExprKind::Name(n), false) = (&a.kind, a.in_parentheses()) =>
            {
                match self.run_together(tree, n, Some(b)) {
                    Some(product) => self.print(&product),
                    None => self.print_power(a, b),
                }
            }
            ExprKind::Neg(a) => self.print_neg(a),
            ExprKind::Add(a, b) => self.print_sum(a, "+", b),
            ExprKind::Sub(a, b) => self.print_sum(a, "−", b),
            ExprKind::Mul(a, b) => self.print_product(a, b),
            ExprKind::Div(a, b) => self.print_quotient(a, b),
            ExprKind::Pow(a, b) => self.print_power(a, b),
            ExprKind::Call(f, _, args) => self.print_call(f, args),
            ExprKind::Bracket(a, b) => self.print_bracket(a, b),
        }
    }

    /// A name `n` that is not declared, at `tree`, as the product of the declared names it
    /// reads as, run together (`Lx` is `L·x`, printed `L x` as the product is, so that a
    /// misspelt `L_x` shows how it was read), with the `power` on it taken by the last one
    /// (`Mω²` is `M·ω²`); `None` for a declared name.
    fn run_together(&self, tree: &Tree, n: &str, power: Option<&Tree>) -> Option<Tree> {
        if self.is_declared_name(n) {
            return None;
        }
        let pieces = trigpoly::split_names(n, &|s: &str| self.is_declared_name(s))?;
        let at = |kind: ExprKind| Tree::new(kind, tree.span);
        let count = pieces.len();
        let factors: Vec<Tree> = pieces
            .into_iter()
            .enumerate()
            .map(|(k, piece)| match power {
                Some(e) if k + 1 == count => at(ExprKind::Pow(
                    Box::new(at(ExprKind::Name(piece))),
                    Box::new(e.clone()),
                )),
                _ => at(ExprKind::Name(piece)),
            })
            .collect();
        // Left-deep as the parser reads a product, in runs of `LEFT_DEEP_SUM` factors, and
        // those runs joined as a balanced tree, so that a run of any length (a name of
        // 100 000 letters) is a tree about `log₂ n` high, which `print` walks without
        // overflowing the stack, as the parser's sums are.
        let mul = |a: Tree, b: Tree| at(ExprKind::Mul(Box::new(a), Box::new(b)));
        let mut runs: Vec<Tree> = Vec::with_capacity(count.div_ceil(LEFT_DEEP_SUM));
        let mut factors = factors.into_iter();
        while let Some(first) = factors.next() {
            runs.push(factors.by_ref().take(LEFT_DEEP_SUM - 1).fold(first, mul));
        }
        let joined = trigpoly::syntax::balanced(runs, |a, b| Ok::<_, Infallible>(mul(a, b)));
        joined.unwrap_or_else(|never| match never {})
    }

    /// A name: a function's is a word in a product.
    fn print_name(&self, n: &str) -> Printed {
        let mut p = Printed::atom(self.display_name(n));
        // A function (`L`, `H`, `K_{1,1}`) is a word in a product, `−ω² L`, as the
        // paper sets its generators apart; variables run together, `Mω²x`, and so
        // does a function named by one Greek letter, a frequency `Ω` as `ω` is.
        let greek_letter = {
            let mut chars = p.text.chars();
            chars.next().is_some_and(|c| !c.is_ascii()) && chars.next().is_none()
        };
        let function = self.system.get(n).is_ok()
            || instance_of(&self.families, n).is_some()
            || self.families.iter().any(|f| f.name == *n);
        if function && !greek_letter {
            p.first_long = true;
            p.last_long = true;
        }
        if trigpoly::has_several_words(&p.text) {
            p.trailing_words = Some(0);
        }
        // A derivative or a gradient, `∂H`, `∇φ`, takes a power in parentheses, `(∂H)²`, and
        // so a factor or a denominator after it, `(∂H) x`, `(∂H)/2`, where `∂H²`, `∂H x`
        // and `∂H/2` would read as `∂(H²)`, `∂(Hx)` and `∂(H/2)`; alone, or the last factor
        // of a product, `x ∂H`, it takes none.
        if trigpoly::is_differential(&p.text) {
            p.prec = POWER;
            p.trailing_words = Some(0);
        }
        p
    }

    /// `−a`.
    fn print_neg(&self, a: &Tree) -> Printed {
        let a = self.print(a).wrapped(QUOTIENT);
        // `−1/x` is a quotient: as a left factor it takes parentheses like `1/x`.
        let prec = if a.prec == QUOTIENT { QUOTIENT } else { NEG };
        Printed {
            text: format!("−{}", a.text),
            prec,
            first_long: false,
            last_long: a.last_long,
            trailing_words: a.trailing_words.map(|at| at + '−'.len_utf8()),
        }
    }

    /// `a + b` or `a − b`.
    fn print_sum(&self, a: &Tree, op: &str, b: &Tree) -> Printed {
        let a = self.print(a);
        let b = self.print(b).wrapped(QUOTIENT);
        let b = if b.prec == NEG { b.wrapped(ATOM) } else { b };
        Printed {
            text: format!("{} {op} {}", a.text, b.text),
            prec: SUM,
            first_long: a.first_long,
            last_long: b.last_long,
            trailing_words: None,
        }
    }

    /// `a b`: run together (one-letter names with [`JUXTAPOSED`] between them), spaced, or
    /// with a dot between numbers.
    fn print_product(&self, a: &Tree, b: &Tree) -> Printed {
        // `(cos θ) x` and `(x sin θ) p_θ`, not `cos θ x`, which reads as the cosine of `θx`,
        // as `(x sin θ)/2` is written for `x sin θ/2`; a sine or cosine after it needs none
        // (`sin θ cos θ`).
        let trig_before = sets_trig_apart(a, b);
        let a = self.print(a);
        let a = match trig_before {
            true => Printed {
                last_long: true,
                ..a.wrapped(ATOM + 1)
            },
            false => a,
        };
        // `(Re K) (Im K)`: beside a name of several words in parentheses, another takes them
        // too (not a derivative, which takes them only before a factor: `(∂H) ∂G`).
        let words_before = a.trailing_words.is_some() && !a.differential_last();
        let a = a.words_closed().wrapped(PRODUCT);
        let b = self.print(b);
        let b = match words_before && b.trailing_words == Some(0) && !b.differential_last() {
            true => b.words_closed(),
            false => b,
        };
        // A right factor that begins with a minus sign (`−x y`, a product whose first
        // factor is negated) takes parentheses: `2(−xy)`, not `2−xy`.
        let b = if b.prec < PRODUCT || b.prec == NEG || b.text.starts_with('−') {
            b.wrapped(ATOM)
        } else {
            b
        };
        let number_left = a.text.ends_with(|c: char| c.is_ascii_digit());
        let digit_right = b.text.starts_with(|c: char| c.is_ascii_digit());
        // Letters before parentheses that spell a function, `i·m·(x)`, would read as
        // its call `im(x)`: the left factor takes parentheses, `(im)(x)`.
        let run = a
            .text
            .trim_end_matches(|c: char| c.is_alphanumeric() || c == '_' || JUXTAPOSED.contains(c));
        let written = a.text[run.len()..].replace(JUXTAPOSED, "");
        let call = b.text.starts_with('(')
            && trigpoly::FUNCTIONS
                .iter()
                .chain(&["Re", "Im"])
                .any(|f| written == *f);
        let a = if call { a.wrapped(ATOM) } else { a };
        let sep = if digit_right {
            "·"
        } else if number_left && !a.text.contains(|c: char| c.is_alphabetic()) && !b.first_long {
            ""
        } else if a.last_long || b.first_long {
            " "
        } else if a.text.ends_with(is_letter) && b.text.starts_with(is_letter) {
            JUXTAPOSED
        } else {
            ""
        };
        Printed {
            trailing_words: b.trailing_words.map(|at| at + a.text.len() + sep.len()),
            text: format!("{}{sep}{}", a.text, b.text),
            prec: PRODUCT,
            first_long: a.first_long,
            last_long: b.last_long,
        }
    }

    /// `a/b`.
    fn print_quotient(&self, a: &Tree, b: &Tree) -> Printed {
        // `(x sin θ)/2`, not `x sin θ/2`, which reads as the sine of `θ/2`.
        let at_least = match ends_in_bare_trig(a) {
            true => ATOM + 1,
            false => QUOTIENT,
        };
        // `(Re K)/2` and `x/(Re K)`, not `Re K/2`, which reads as the real part of `K/2`.
        let a = self.print(a).words_closed().wrapped(at_least);
        // `x/∂H`: nothing follows a derivative in the denominator.
        let b = self.print(b);
        let b = match b.differential_last() {
            true => b,
            false => b.words_closed(),
        };
        let b = b.wrapped(POWER);
        Printed {
            text: format!("{}/{}", a.text, b.text),
            prec: QUOTIENT,
            first_long: a.first_long,
            last_long: false,
            trailing_words: None,
        }
    }

    /// `a^b`: a superscript exponent where it is an integer, `cos²θ` on a function of an angle.
    fn print_power(&self, a: &Tree, b: &Tree) -> Printed {
        // Names run together are a product, which a power in parentheses takes whole
        // (`(xy)²`) and one without takes at its last name (`xy²` is x·y²): the tree
        // keeps the parentheses in the name's span.
        let run_together = match &a.kind {
            ExprKind::Name(n) => {
                a.in_parentheses() && n.chars().count() > 1 && !self.is_declared_name(n)
            }
            _ => false,
        };
        // A name before parentheses with a power after them, `M(x + y)²`, is read with
        // the power on the parentheses: printed as it was written, it reads back so.
        let power_on_parentheses = match &a.kind {
            ExprKind::Call(f, _, args) => {
                !a.in_parentheses() && args.len() == 1 && !trigpoly::FUNCTIONS.contains(&f.as_str())
            }
            _ => false,
        };
        // `(Re K)²`, not `Re K²`, the real part of `K²`.
        let base = self.print(a);
        let base = match base.trailing_words {
            Some(0) => base.words_closed(),
            _ => base,
        };
        let base = if run_together {
            base.wrapped(ATOM + 1)
        } else if power_on_parentheses {
            base
        } else {
            base.wrapped(ATOM)
        };
        let small = |n: &num_bigint::BigInt| i64::try_from(n.clone()).ok();
        let exponent = match &b.kind {
            ExprKind::Integer(n) => small(n).map(superscript),
            ExprKind::Neg(inner) => match &inner.kind {
                ExprKind::Integer(n) => small(n).map(|k| superscript(-k)),
                _ => None,
            },
            _ => None,
        };
        // `cos²θ`, `sin²2θ`: the exponent on the function of a bare angle, as the paper
        // writes it (and the parser reads `sin²2θ` as `(sin 2θ)²`).
        let trig_of_angle = match &a.kind {
            ExprKind::Call(f, _, args) if bare_angle(f, args).is_some() => {
                base.text.split_once(' ')
            }
            _ => None,
        };
        // Any other power of it takes the angle in parentheses: `cos θ⁻¹` and
        // `cos θ^(3²)` would read as ambiguous, and so would `sin 2θ⁻¹`.
        let base_text = match trig_of_angle {
            Some((f, angle)) => format!("{f}({angle})"),
            None => base.text.clone(),
        };
        let text = match (exponent, trig_of_angle) {
            (Some(e), Some((f, angle))) if !e.starts_with('⁻') => {
                format!("{f}{e}{angle}")
            }
            (Some(e), _) => format!("{base_text}{e}"),
            (None, _) => {
                format!("{base_text}^{}", self.print(b).wrapped(ATOM).text)
            }
        };
        Printed {
            text,
            prec: POWER,
            first_long: base.first_long,
            last_long: base.last_long,
            trailing_words: None,
        }
    }

    /// `f(args)`: `cos θ` of a bare angle, `Re` and `Im`, or a name that multiplies its parentheses.
    fn print_call(&self, f: &str, args: &[Tree]) -> Printed {
        // `cos θ` and `sin 2θ` of a bare angle, as the paper (and the normal form) writes them.
        if let Some((multiple, angle)) = bare_angle(f, args) {
            let multiple = multiple.map_or(String::new(), |k| k.to_string());
            let mut p = Printed::atom(format!("{f} {multiple}{}", self.display_name(angle)));
            p.first_long = true;
            p.last_long = true;
            return p;
        }
        // `e^{−inθ}`, as the paper writes the exponential (`exp(…)` where the system
        // declares a name `e`): a power, which another power or `Re` takes in parentheses.
        if let ([arg], "exp") = (args, f) {
            if !self.is_declared_name("e") {
                let mut p = Printed::atom(format!("e^{{{}}}", self.print(arg).text));
                p.prec = POWER;
                p.first_long = true;
                p.last_long = true;
                return p;
            }
        }
        let args: Vec<String> = args.iter().map(|a| self.print(a).text).collect();
        // The paper's (and LaTeX's) real and imaginary parts are `Re` and `Im` (`re`
        // and `im` where the system declares `Re` or `Im` itself); any other name
        // before parentheses multiplies them (`K_{1,1}(x)`).
        let (name, function) = match f {
            "re" if !self.is_declared_name("Re") => ("Re".to_string(), true),
            "im" if !self.is_declared_name("Im") => ("Im".to_string(), true),
            other if trigpoly::FUNCTIONS.contains(&other) => (f.to_string(), true),
            // A root is a function, not a name that multiplies its parentheses, and prints as
            // the paper writes it (and the parser reads it): `x/√(x² + y²)`, not
            // `x/(sqrt(x² + y²))`.
            "sqrt" => ("√".to_string(), true),
            // `(Re K)(x + y)`: a name of several words multiplies in parentheses.
            other => match self.display_name(other) {
                shown if trigpoly::has_several_words(&shown) => (format!("({shown})"), false),
                shown => (shown, false),
            },
        };
        let mut p = Printed::atom(format!("{name}({})", args.join(", ")));
        p.first_long = true;
        p.last_long = true;
        if !function {
            // A product: a power after it takes parentheses, `(p_x(x + y))²`.
            p.prec = PRODUCT;
        }
        p
    }

    /// `{a, b}`.
    fn print_bracket(&self, a: &Tree, b: &Tree) -> Printed {
        let mut p = Printed::atom(format!(
            "{{{}, {}}}",
            self.print(a).text,
            self.print(b).text
        ));
        p.first_long = true;
        p.last_long = true;
        p
    }
}

/// Whether `c` is part of a letter: a letter, or a mark drawn over one (`Z̄`).
fn is_letter(c: char) -> bool {
    c.is_alphabetic() || crate::render::tex::is_combining(c)
}

/// The angle of `cos θ`, `sin 2θ`: of a sine or cosine `f` of `args` that is printed without
/// parentheses, as the paper writes it and the parser reads it back, its one argument a name
/// or an integer multiple of one (`2*theta`), as its multiple (if any) and name.
fn bare_angle<'t>(f: &str, args: &'t [Tree]) -> Option<(Option<&'t BigInt>, &'t str)> {
    if !matches!(f, "cos" | "sin") {
        return None;
    }
    match args {
        [arg] => match &arg.kind {
            ExprKind::Name(angle) => Some((None, angle)),
            // Not `−2θ`, which the parser reads after `sin` only in parentheses.
            ExprKind::Mul(k, angle) => match (&k.kind, &angle.kind) {
                (ExprKind::Integer(k), ExprKind::Name(angle)) if k.sign() != Sign::Minus => {
                    Some((Some(k), angle))
                }
                _ => None,
            },
            _ => None,
        },
        _ => None,
    }
}

/// Whether `tree` is printed ending in `cos θ` or `sin 2θ` of a bare angle ([`bare_angle`]:
/// `x cos θ`, `cos²θ`), which a `/` after it would seem to divide the angle of.
fn ends_in_bare_trig(tree: &Tree) -> bool {
    match &tree.kind {
        ExprKind::Call(f, _, args) => bare_angle(f, args).is_some(),
        ExprKind::Pow(a, b) => {
            matches!(b.kind, ExprKind::Integer(_))
                && matches!(a.kind, ExprKind::Call(..))
                && ends_in_bare_trig(a)
        }
        ExprKind::Mul(_, b) | ExprKind::Neg(b) => ends_in_bare_trig(b),
        _ => false,
    }
}

/// Whether `tree` is printed beginning with a sine or cosine (`cos θ`, `sin²θ`, `sin θ cos θ`),
/// which reads as a factor of its own after another one. A power of a product is printed in
/// parentheses, `(x sin θ)²`, and so is a product whose sine or cosine [`print_product`]
/// sets apart from a factor after it, `(sin θ) x`: neither begins with a sine.
///
/// [`print_product`]: LoadedSystem::print_product
fn begins_with_trig(tree: &Tree) -> bool {
    match &tree.kind {
        ExprKind::Call(f, _, _) => matches!(f.as_str(), "cos" | "sin"),
        ExprKind::Pow(a, _) => matches!(a.kind, ExprKind::Call(..)) && begins_with_trig(a),
        ExprKind::Mul(a, b) => begins_with_trig(a) && !sets_trig_apart(a, b),
        _ => false,
    }
}

/// Whether the product `a b` is printed with `a` in parentheses, as a sine or cosine of a bare
/// angle at its end is set apart from a factor after it that does not begin with one: `(cos θ)
/// x`, not `cos θ x`, which reads as the cosine of `θx`.
fn sets_trig_apart(a: &Tree, b: &Tree) -> bool {
    ends_in_bare_trig(a) && !begins_with_trig(b)
}
