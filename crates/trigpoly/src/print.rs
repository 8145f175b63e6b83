//! Printing like the paper: unicode text (`p_x²/(2M) − ω² L`), LaTeX (`\frac{p_{x}^{2}}{2 M}`),
//! and an ASCII form (`p_x^2/(2*M)`) that parses back to the same element.
//!
//! The terms print in one order in every notation (and in what the command line writes as
//! Markdown and JSON), that of [`Poly::cos_sin_terms`]: by trigonometric monomial, then the
//! momenta's degree, highest first, then the exponents in descending lexicographic order
//! (`x² + xy + y²`). A parameter's negative power is part of the coefficient and keeps its
//! place in that comparison (`p_x²/(2M) + Mω²x²/2`); a negative power of any other variable (a
//! coordinate, a momentum, a Poisson variable, a declared denominator or a radical) is left out
//! of it, and the terms it leaves equal are ordered by that denominator: none first, then the
//! least total degree, then in the variables' order (`β/x² + γ/y²`, `g/(x − y)² + g/(x − z)²`,
//! `x² + x/y + y² + y/x + 1 + 1/x² + 1/y²`). Without such a denominator the order is the
//! exponents' alone. The storage order of a polynomial is not this one and is never changed
//! by printing.

use std::collections::hash_map::{Entry, HashMap};
use std::fmt;
use std::sync::atomic::{AtomicBool, Ordering};

use crate::number::{Coefficient, GaussianRational, Magnitude, Rational};
use crate::poly::{CosSinTerm, Poly, TrigMonomial};
use crate::varset::{
    has_several_words, juxtaposition_is_ambiguous, spelled_by, unparenthesized, VarKind, VarSet,
};

mod factored;

pub use factored::Factored;

/// An output notation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Style {
    /// Unicode text: `p_x²/(2M)`, `−ω² L`, `cos θ`.
    Unicode,
    /// LaTeX math: `\frac{p_{x}^{2}}{2 M}`, `\cos\theta`.
    Latex,
    /// ASCII that parses back: `p_x^2/(2*M)`, `cos(theta)`.
    Ascii,
}

/// [`Style::ALL`] and [`Style::name`] from one list of the notations with their names, as
/// superint's `ErrorKind` and `Expect` are made: `name`'s match must cover every notation, so
/// that one left out of the list, and so out of `ALL`, does not compile.
macro_rules! styles_with_names {
    ($($style:ident => $name:literal,)*) => {
        impl Style {
            /// Every notation, in the order they are declared.
            pub const ALL: [Style; [$($name),*].len()] = [$(Style::$style),*];

            /// The notation's name: `unicode`, `latex` or `ascii`.
            pub fn name(self) -> &'static str {
                match self {
                    $(Style::$style => $name,)*
                }
            }
        }
    };
}

styles_with_names! {
    Unicode => "unicode",
    Latex => "latex",
    Ascii => "ascii",
}

/// The notation's [`Style::name`].
impl fmt::Display for Style {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A notation by its name (`text` for Unicode too, as a report's JSON names that form).
///
/// ```
/// use trigpoly::{Style, UnknownStyle};
///
/// assert_eq!("latex".parse(), Ok(Style::Latex));
/// assert_eq!("text".parse::<Style>(), Ok(Style::Unicode));
/// assert_eq!(Style::Ascii.to_string().parse::<Style>(), Ok(Style::Ascii));
/// let err = "html".parse::<Style>().unwrap_err();
/// assert_eq!(err, UnknownStyle("html".into()));
/// assert_eq!(err.to_string(), "unknown style 'html' (expected unicode or text, latex or ascii)");
/// ```
impl std::str::FromStr for Style {
    type Err = UnknownStyle;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Style::ALL
            .into_iter()
            .find(|style| style.name() == s || (s == "text" && *style == Style::Unicode))
            .ok_or_else(|| UnknownStyle(s.to_string()))
    }
}

/// A name that is no [`Style`]'s: the name.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown style '{0}' (expected unicode or text, latex or ascii)")]
pub struct UnknownStyle(pub String);

/// How the printers write an angle's part: in multiple angles (`A cos 2θ + B sin 2θ`, as the
/// paper does) or in powers of `cos θ` and `sin θ` (`A cos²θ + B cos θ sin θ`, the normal form
/// the engine decides in). Only the text differs: either form parses back to the same element.
///
/// [`Poly::render`], `Poly`'s `Display` (`to_string`) and the other printers write the process's form
/// ([`Angles::current`], harmonics unless [`Angles::set_current`] chose powers, as the command
/// line's `--angles powers` does); [`Poly::render_with`] and [`Poly::with_angles`] name one.
///
/// ```
/// use trigpoly::{Angles, Expr, Style, Vars};
/// let vars = Vars::builder().coordinate("x").angle("theta").build().unwrap();
/// let f = Expr::parse(&vars, "x*cos(theta)^2").unwrap();
/// assert_eq!(f.render_with(Style::Unicode, Angles::Harmonics), "x/2 + (x cos 2θ)/2");
/// assert_eq!(f.with_angles(Angles::Powers).to_string(), "x cos²θ");
/// assert_eq!(f.render_with(Style::Ascii, Angles::Harmonics), "x/2 + x*cos(2*theta)/2");
/// assert_eq!("powers".parse(), Ok(Angles::Powers));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Angles {
    /// Multiple angles: `cos kθ`, `sin kθ`, each angle's part grouped by harmonic.
    #[default]
    Harmonics,
    /// Powers: `cos^a θ sin^b θ` with `b ≤ 1` (`sin²θ` written `1 − cos²θ`).
    Powers,
}

/// Whether the process prints angles in [`Angles::Powers`] ([`Angles::current`]).
static POWERS: AtomicBool = AtomicBool::new(false);

impl Angles {
    /// Both forms, the default first.
    pub const ALL: [Angles; 2] = [Angles::Harmonics, Angles::Powers];

    /// The form's name: `harmonics` or `powers`.
    pub fn name(self) -> &'static str {
        match self {
            Angles::Harmonics => "harmonics",
            Angles::Powers => "powers",
        }
    }

    /// The form the printers of this process write where none is named.
    pub fn current() -> Angles {
        match POWERS.load(Ordering::Relaxed) {
            true => Angles::Powers,
            false => Angles::Harmonics,
        }
    }

    /// Makes this form the one the printers of this process write where none is named (a
    /// program's setting, as `--angles` is the command line's: every thread prints in it).
    ///
    /// A process-wide setting, not an argument, because [`fmt::Display`] takes none and over a
    /// hundred places print an element by it or by [`Poly::render`] (reports, messages, errors):
    /// passing the form as `--full-expressions` is passed, in the renderer's options, would
    /// reach only the reports. Set it once, before any thread prints, as the command line does;
    /// a library or a test that wants one form names it ([`Poly::render_with`],
    /// [`Poly::with_angles`]): setting it in a test changes what tests running beside it print.
    pub fn set_current(self) {
        POWERS.store(self == Angles::Powers, Ordering::Relaxed);
    }

    /// The terms of `p` in this form, in printing order.
    fn terms<C: Coefficient>(self, p: &Poly<C>) -> Vec<CosSinTerm> {
        match self {
            Angles::Harmonics => p.harmonic_terms(),
            Angles::Powers => p.cos_sin_terms(),
        }
    }
}

/// A form by its name ([`Angles::name`]).
impl std::str::FromStr for Angles {
    type Err = UnknownAngles;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        (Angles::ALL.into_iter())
            .find(|a| a.name() == s)
            .ok_or_else(|| UnknownAngles(s.to_string()))
    }
}

/// A name that is no [`Angles`]'s: the name.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown form of angles '{0}' (expected harmonics or powers)")]
pub struct UnknownAngles(pub String);

/// An element shown as text with its angles in a named form ([`Poly::with_angles`]).
#[derive(Debug)]
pub struct WithAngles<'a, C: Coefficient> {
    poly: &'a Poly<C>,
    angles: Angles,
}

impl<C: Coefficient> fmt::Display for WithAngles<'_, C> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.poly.render_with(Style::Unicode, self.angles))
    }
}

impl<C: Coefficient> Poly<C> {
    /// The element in a given notation, its angles in the process's form ([`Angles::current`]).
    pub fn render(&self, style: Style) -> String {
        self.render_with(style, Angles::current())
    }

    /// The element in a given notation with its angles in a given form.
    pub fn render_with(&self, style: Style, angles: Angles) -> String {
        render_terms(self.vars(), &angles.terms(self), style, angles)
    }

    /// The number of terms the element prints as, its angles in the process's form
    /// ([`Angles::current`]): fewer than its monomials ([`Poly::len`]) in harmonics, where
    /// `e^{2iθ}` and `e^{−2iθ}` print together as `cos 2θ` and `sin 2θ` terms, more or fewer
    /// in powers.
    pub fn printed_terms(&self) -> usize {
        Angles::current().terms(self).len()
    }

    /// The element as text ([`fmt::Display`]) with its angles in a given form.
    pub fn with_angles(&self, angles: Angles) -> WithAngles<'_, C> {
        WithAngles { poly: self, angles }
    }

    /// The element in several notations, its terms in the process's form of the angles
    /// ([`Poly::harmonic_terms`] or [`Poly::cos_sin_terms`]) computed once for all of them.
    ///
    /// ```
    /// use trigpoly::{Poly, Rational, Style, Vars};
    /// let vars = Vars::builder().coordinate("x").momentum("p_x").parameter("M").build().unwrap();
    /// let h = Poly::<Rational>::parse(&vars, "p_x^2/(2*M)").unwrap();
    /// let [text, latex] = h.render_each([Style::Unicode, Style::Latex]);
    /// assert_eq!((text, latex), (h.to_string(), h.to_latex()));
    /// ```
    pub fn render_each<const N: usize>(&self, styles: [Style; N]) -> [String; N] {
        let angles = Angles::current();
        let terms = angles.terms(self);
        styles.map(|style| render_terms(self.vars(), &terms, style, angles))
    }

    /// The element's text for a message: in full when it is short, else only its size (`a
    /// polynomial of 24310 terms`), which a one-line message has no room for and an error no
    /// time to print (a refused division once printed a 270 MB divisor).
    pub(crate) fn brief(&self) -> String {
        self.brief_within(8, 80)
    }

    /// [`Poly::brief`] with room for at most `terms` terms and `chars` characters.
    pub(crate) fn brief_within(&self, terms: usize, chars: usize) -> String {
        if self.len() <= terms {
            let text = self.to_string();
            if text.chars().count() <= chars {
                return text;
            }
        }
        format!("a polynomial of {} terms", self.len())
    }

    /// The element's text for a message that should show a part of a long one: in full
    /// when `brief` would show it whole, else the terms of its first monomials outside
    /// the angles ([`Poly::leading_part`], each a printed term of the whole) that fit in as
    /// many characters, then `+ …` and its size (`−75 M1⁴⁹ − 1800 M1⁴⁸ M2 + … (a polynomial
    /// of 1326 terms)`); its size alone when not even its first terms fit.
    pub fn brief_excerpt(&self) -> String {
        const TERMS: usize = 8;
        const CHARS: usize = 80;
        if self.len() <= TERMS {
            let text = self.to_string();
            if text.chars().count() <= CHARS {
                return text;
            }
        }
        let size = format!("a polynomial of {} terms", self.len());
        (1..=TERMS)
            .rev()
            .map(|k| self.leading_part(k).0)
            .filter(|part| part.len() < self.len())
            .map(|part| part.to_string())
            .find(|text| text.chars().count() <= CHARS)
            .map_or(size.clone(), |text| format!("{text} + … ({size})"))
    }

    /// LaTeX math (no surrounding `$`).
    pub fn to_latex(&self) -> String {
        self.render(Style::Latex)
    }

    /// ASCII text that [`Poly::parse`] reads back to the same element.
    pub fn to_ascii(&self) -> String {
        self.render(Style::Ascii)
    }
}

impl<C: Coefficient> fmt::Display for Poly<C> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.render(Style::Unicode))
    }
}

/// Renders a sum of normal-form terms, grouping terms by their trigonometric factor:
/// `(p_x − Mωy) cos θ + (p_y + Mωx) sin θ`.
pub(crate) fn render_terms(
    vars: &VarSet,
    terms: &[CosSinTerm],
    style: Style,
    angles: Angles,
) -> String {
    if terms.is_empty() {
        return "0".into();
    }
    if let Some(fractions) = render_fractions(vars, terms, style, angles) {
        return fractions;
    }
    let names = Names::new(vars, terms, style, angles);
    let mut out = String::new();
    let mut k = 0;
    while k < terms.len() {
        let trig = &terms[k].trig;
        let end = k + terms[k..].iter().take_while(|t| &t.trig == trig).count();
        let group = &terms[k..end];
        if trig.is_one() || group.len() == 1 {
            for t in group {
                write_term(&mut out, 0, &names, t, Some(&t.trig), None, style);
            }
        } else {
            // `(inner) factor`, written in place: the inner sum can run to megabytes.
            push_sign(&mut out, 0, false, style);
            out.push_str(if style == Style::Latex {
                r"\left("
            } else {
                "("
            });
            let start = out.len();
            for t in group {
                write_term(&mut out, start, &names, t, None, None, style);
            }
            out.push_str(match style {
                Style::Ascii => ")*",
                Style::Latex => r"\right) ",
                Style::Unicode => ") ",
            });
            write_trig_factors(&mut out, &mut Product::new(style), &names, trig);
        }
        k = end;
    }
    out
}

/// A sum with denominator atoms, with the terms that have the same denominator (the same
/// powers of atoms, some negative, and the same negative powers of the other variables)
/// written as one fraction: `3g(p_x + p_y)/(x − y)²`, `p_x(p_x − p_y)/(x − y)²`, the factors
/// and the rational content they share in front; the other terms as they are, in order of
/// first appearance. `None` when no two terms share a denominator (then nothing changes).
fn render_fractions(
    vars: &VarSet,
    terms: &[CosSinTerm],
    style: Style,
    angles: Angles,
) -> Option<String> {
    vars.denominators().next()?;
    let is_atom: Vec<bool> = vars
        .vars()
        .map(|v| vars.variable(v).kind() == VarKind::Denominator)
        .collect();
    let divides = |t: &CosSinTerm| t.exps.iter().zip(&is_atom).any(|(&e, &atom)| atom && e < 0);
    let denominator = |t: &CosSinTerm| -> Vec<i64> {
        (t.exps.iter().zip(&is_atom))
            .map(|(&e, &atom)| if atom || e < 0 { e } else { 0 })
            .collect()
    };
    let mut groups: Vec<Vec<&CosSinTerm>> = Vec::new();
    let mut group_of: HashMap<(Vec<i64>, &TrigMonomial), usize> = HashMap::new();
    for t in terms {
        if !divides(t) {
            groups.push(vec![t]);
            continue;
        }
        match group_of.entry((denominator(t), &t.trig)) {
            Entry::Occupied(g) => groups[*g.get()].push(t),
            Entry::Vacant(v) => {
                v.insert(groups.len());
                groups.push(vec![t]);
            }
        }
    }
    if groups.len() == terms.len() {
        return None;
    }
    let names = Names::new(vars, terms, style, angles);
    let mut out = String::new();
    for group in groups {
        if let [t] = group[..] {
            write_term(&mut out, 0, &names, t, Some(&t.trig), None, style);
            continue;
        }
        let (outer, numerator) = fraction(&group, &is_atom);
        let inner = render_terms(vars, &numerator, style, angles);
        let inner = Inner {
            text: &inner,
            terms: numerator.len(),
        };
        write_term(
            &mut out,
            0,
            &names,
            &outer,
            Some(&outer.trig),
            Some(inner),
            style,
        );
    }
    Some(out)
}

/// Terms with one denominator as `outer · (numerator)`: the outer term holds the
/// denominator, the factors every term has (the least power of each variable among them)
/// and the rational content (signed as the first term, so that the numerator starts
/// positive); the numerator the rest.
fn fraction(group: &[&CosSinTerm], is_atom: &[bool]) -> (CosSinTerm, Vec<CosSinTerm>) {
    let first = group[0];
    let n = first.exps.len();
    // The power of each variable in front: its denominator's (the same in every term), or
    // the least among the terms.
    let front: Vec<i64> = (0..n)
        .map(|j| match is_atom[j] || first.exps[j] < 0 {
            true => first.exps[j],
            false => group.iter().map(|t| t.exps[j]).min().unwrap_or(0),
        })
        .collect();
    let content = match group.iter().all(|t| t.coeff.im.is_zero()) {
        true => {
            let c = Rational::content_of(group.iter().map(|t| &t.coeff.re));
            match first.coeff.re.is_negative() {
                true => -&c,
                false => c,
            }
        }
        false => Rational::one(),
    };
    let numerator = group
        .iter()
        .map(|t| CosSinTerm {
            coeff: match content.is_one() {
                true => t.coeff.clone(),
                false => GaussianRational::from(&t.coeff.re / &content),
            },
            exps: (0..n).map(|j| t.exps[j] - front[j]).collect(),
            trig: TrigMonomial::one(first.trig.powers.len()),
        })
        .collect();
    let outer = CosSinTerm {
        coeff: GaussianRational::from(content),
        exps: front,
        trig: first.trig.clone(),
    };
    (outer, numerator)
}

fn minus(style: Style) -> &'static str {
    match style {
        Style::Unicode => "−",
        _ => "-",
    }
}

/// The sign of the next term of a sum written into `out` from byte `start` on: `−` before a
/// negative first term, ` + ` or ` − ` between terms.
fn push_sign(out: &mut String, start: usize, negative: bool, style: Style) {
    match (out.len() == start, negative) {
        (true, false) => {}
        (true, true) => out.push_str(minus(style)),
        (false, false) => out.push_str(" + "),
        (false, true) => {
            out.push(' ');
            out.push_str(minus(style));
            out.push(' ');
        }
    }
}

/// A product written factor by factor: `*` between factors in ASCII, a space in LaTeX, and in
/// text a space where either neighbour is "wide" (a word, a name of several letters:
/// `2 cos θ`, `Mω²x`).
struct Product {
    style: Style,
    factors: usize,
    wide: bool,
}

impl Product {
    fn new(style: Style) -> Self {
        Product {
            style,
            factors: 0,
            wide: false,
        }
    }

    /// Writes what separates the next factor (`wide` or not) from the one before, if any.
    fn next(&mut self, out: &mut String, wide: bool) {
        self.next_apart(out, wide, false);
    }

    /// [`Product::next`], with a space in text also where `apart` (`x y` beside a variable
    /// `xy`, though both are one letter).
    fn next_apart(&mut self, out: &mut String, wide: bool, apart: bool) {
        if self.factors > 0 {
            match self.style {
                Style::Ascii => out.push('*'),
                Style::Latex => out.push(' '),
                Style::Unicode if wide || apart || self.wide => out.push(' '),
                Style::Unicode => {}
            }
        }
        self.factors += 1;
        self.wide = wide;
    }
}

/// `base^e` (`e ≥ 1`) in the notation of `style`.
fn write_power(out: &mut String, base: &str, e: i64, style: Style) {
    out.push_str(base);
    write_exponent(out, e, style);
}

/// The exponent `e ≥ 1` of a power, nothing for 1: `²`, `^{2}`, `^2`.
fn write_exponent(out: &mut String, e: i64, style: Style) {
    if e == 1 {
        return;
    }
    match style {
        Style::Unicode => out.push_str(&superscript(e)),
        Style::Latex => write_display(out, format_args!("^{{{e}}}")),
        Style::Ascii => write_display(out, format_args!("^{e}")),
    }
}

/// Appends formatted text (writing to a `String` cannot fail).
pub(crate) fn write_display(out: &mut String, args: fmt::Arguments<'_>) {
    let _ = fmt::Write::write_fmt(out, args);
}

/// The signs a display name may begin with, right before a letter, as a derivative or a
/// gradient is written (`∂H`, `∇φ`), and their LaTeX commands.
pub const DIFFERENTIALS: [(char, &str); 2] = [('∂', r"\partial"), ('∇', r"\nabla")];

/// The LaTeX command of `c` where it is one of the [`DIFFERENTIALS`] (`∂` → `\partial`).
pub fn differential_latex(c: char) -> Option<&'static str> {
    DIFFERENTIALS.iter().find(|d| d.0 == c).map(|d| d.1)
}

/// Whether `c` is one of the [`DIFFERENTIALS`], `∂` or `∇`.
pub fn is_differential_sign(c: char) -> bool {
    differential_latex(c).is_some()
}

/// Whether the name `shown` begins with one of the [`DIFFERENTIALS`], a derivative or a
/// gradient: a power of it is set in parentheses, `(∂H)²`, where `∂H²` would read as `∂(H²)`.
pub fn is_differential(shown: &str) -> bool {
    shown.chars().next().is_some_and(is_differential_sign)
}

/// `-12` → `⁻¹²`.
pub fn superscript(e: i64) -> String {
    e.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            _ => '⁹',
        })
        .collect()
}

/// The variables' names in one notation, and the order in which a term's factors are
/// written, worked out once for all the terms of an element.
struct Names {
    /// The name of each variable, by index.
    names: Vec<String>,
    /// Whether text sets each variable apart as a word, by index ([`crate::VarsBuilder::word`]).
    words: Vec<bool>,
    /// Whether each variable's name is several words (`Re K`), by index: with a power or a
    /// factor after it, it is set in parentheses, `(Re K)² H_x`, where `Re K² H_x` would read
    /// as `Re(K²) H_x`.
    several_words: Vec<bool>,
    /// Whether each variable's name is a derivative or a gradient (`∂H`, `∇φ`), by index: with
    /// a power, or a factor or a denominator after it, it is set in parentheses, `(∂H)²`,
    /// `(∂H) x`, where `∂H²` and `∂H x` would read as `∂(H²)` and `∂(Hx)`.
    differential: Vec<bool>,
    /// The variables as the paper orders a term's factors: parameters, then coordinates,
    /// then momenta (then angles), each kind in declaration order.
    order: Vec<usize>,
    /// The angles' indices, in declaration order.
    angles: Vec<usize>,
    /// The form of the terms' trigonometric parts ([`CosSinTerm::trig`]): powers, or harmonics.
    angle_form: Angles,
    /// The declared names of several letters that one-letter names of the element, side by
    /// side, could spell (`xy` where `x` and `y` are written), in text; most often none, and
    /// then no term need look at its runs ([`Names::apart_in_runs`]).
    spellable: Vec<String>,
}

impl Names {
    /// Whether `trig` is a harmonic of several angles jointly, `cos(θ − φ)`, written with its
    /// argument in parentheses.
    fn is_joint_harmonic(&self, trig: &TrigMonomial) -> bool {
        self.angle_form == Angles::Harmonics
            && trig
                .powers
                .iter()
                .filter(|&&(a, b)| a + b != 0)
                .nth(1)
                .is_some()
    }

    fn new(vars: &VarSet, terms: &[CosSinTerm], style: Style, angle_form: Angles) -> Self {
        let names = vars
            .vars()
            .map(|v| {
                let var = vars.variable(v);
                match style {
                    Style::Unicode => var.unicode().to_string(),
                    Style::Latex => var.latex().to_string(),
                    Style::Ascii => var.ascii().to_string(),
                }
            })
            .collect();
        let rank = |v: &crate::varset::Var| match vars.variable(*v).kind() {
            VarKind::Parameter => 0,
            VarKind::Coordinate | VarKind::Poisson | VarKind::Radical => 1,
            VarKind::Momentum => 2,
            VarKind::Angle => 3,
            VarKind::Denominator => 4,
        };
        let mut order: Vec<crate::varset::Var> = vars.vars().collect();
        order.sort_by_key(rank);
        Names {
            names,
            words: vars.vars().map(|v| vars.variable(v).is_word()).collect(),
            several_words: vars
                .vars()
                .map(|v| style != Style::Ascii && has_several_words(vars.variable(v).unicode()))
                .collect(),
            differential: vars
                .vars()
                .map(|v| style != Style::Ascii && is_differential(vars.variable(v).unicode()))
                .collect(),
            order: order.iter().map(|v| v.index()).collect(),
            angles: vars.angles().map(|v| v.index()).collect(),
            angle_form,
            spellable: match style {
                Style::Unicode => spellable(vars, terms),
                _ => Vec::new(),
            },
        }
    }

    /// Which of a product's `factors` (variables by index, each to the power `exps[j]`, the
    /// first written after the imaginary unit where `after_i`) a space sets apart from the one
    /// before in text, though both are one letter: each of a run of one-letter names side by
    /// side of which two or more in a row spell another name ([`juxtaposition_is_ambiguous`]:
    /// `2i x y`, `Mω²x y` beside a variable `xy`; `2iMωy` beside `Hy`). A wider factor ends a
    /// run, and a power ends it after its name. Empty where no run of the element can spell
    /// one ([`Names::spellable`]), as is usual.
    fn apart_in_runs(
        &self,
        factors: impl Iterator<Item = usize>,
        exps: &[i64],
        after_i: bool,
    ) -> Vec<bool> {
        let mut apart = Vec::new();
        if self.spellable.is_empty() {
            return apart;
        }
        let spellable = || self.spellable.iter().map(String::as_str);
        // The run so far, and the index in `apart` of its second letter (of its first, where
        // the run begins with `i`): the first that a spaced run sets apart.
        let mut run: Vec<&str> = Vec::new();
        let mut joined = 0;
        let close = |run: &mut Vec<&str>, apart: &mut Vec<bool>, joined: usize| {
            if juxtaposition_is_ambiguous(spellable(), run) {
                apart[joined..].fill(true);
            }
            run.clear();
        };
        if after_i {
            run.push("i");
        }
        for j in factors {
            let name = self.names[j].as_str();
            if self.words[j] || name.chars().count() > 1 {
                close(&mut run, &mut apart, joined);
                apart.push(false);
                continue;
            }
            if run.is_empty() {
                joined = apart.len() + 1;
            }
            run.push(name);
            apart.push(false);
            if exps[j].abs() != 1 {
                close(&mut run, &mut apart, joined);
            }
        }
        close(&mut run, &mut apart, joined);
        apart
    }
}

/// The declared names of several letters that one-letter names of the element (its variables
/// written in one letter, in text, and the imaginary unit) could spell side by side: `xy` where
/// `x` and `y` are written, `omega` where `o`, `m`, `e`, `g` and `a` are.
fn spellable(vars: &VarSet, terms: &[CosSinTerm]) -> Vec<String> {
    // What text writes is each variable's unicode form (`ξ` for a coordinate `x` shown
    // so): its other spellings (`x`, `xi`) never stand side by side in it.
    let letters: Vec<char> = vars
        .vars()
        .filter(|v| terms.iter().any(|t| t.exps[v.index()] != 0))
        .filter_map(|v| {
            let mut chars = vars.variable(v).unicode().chars();
            chars.next().filter(|_| chars.next().is_none())
        })
        .chain(['i'])
        .collect();
    vars.declared_names()
        .filter(|name| spelled_by(name, |c| letters.contains(&c)))
        .map(str::to_string)
        .collect()
}

/// The factors of a trigonometric monomial, each wide, into `product`: `cos^a θ sin^b θ`, or
/// in harmonics `cos kθ` or `sin kθ`, `cos(kθ − lφ)` over several angles
/// ([`Poly::harmonic_terms`]).
fn write_trig_factors(out: &mut String, product: &mut Product, names: &Names, trig: &TrigMonomial) {
    let style = product.style;
    if names.is_joint_harmonic(trig) {
        let fun = match trig.powers.iter().any(|&(_, b)| b != 0) {
            true => "sin",
            false => "cos",
        };
        let multiples = (names.angles.iter().zip(&trig.powers).enumerate())
            .filter(|(_, (_, &(a, b)))| a + b != 0)
            .map(|(place, (&j, &(a, b)))| {
                let k = i64::from(a + b);
                let k = if trig.minus.contains(&place) { -k } else { k };
                (names.names[j].as_str(), k)
            });
        product.next(out, true);
        if style == Style::Latex {
            out.push('\\');
        }
        out.push_str(fun);
        out.push('(');
        write_angle_sum(out, multiples, style);
        out.push(')');
        return;
    }
    for (&j, &(a, b)) in names.angles.iter().zip(&trig.powers) {
        let name = &names.names[j];
        for (fun, e) in [("cos", a), ("sin", b)] {
            if e == 0 {
                continue;
            }
            product.next(out, true);
            if names.angle_form == Angles::Harmonics && e > 1 {
                write_multiple_angle(out, fun, e, name, style);
                continue;
            }
            // `cos²θ`, `cos θ`, `\cos^{2}\theta`; `cos(theta)^2`.
            if style == Style::Ascii {
                write_display(out, format_args!("{fun}({name})"));
                write_exponent(out, e.into(), style);
                continue;
            }
            if style == Style::Latex {
                out.push('\\');
            }
            out.push_str(fun);
            write_exponent(out, e.into(), style);
            // `cos θ`; `\cos a`, where `\cosa` would be one undefined command.
            let letter = name.starts_with(|c: char| c.is_ascii_alphanumeric());
            if e == 1 && (style == Style::Unicode || letter) {
                out.push(' ');
            }
            out.push_str(name);
        }
    }
}

/// `kθ − lφ` (`k`, `l` nonzero, the first of them positive): `2θ − 3φ`, `2\theta -
/// 3\varphi`, `2*theta - 3*phi`, which parse back.
pub(crate) fn write_angle_sum<'n>(
    out: &mut String,
    multiples: impl Iterator<Item = (&'n str, i64)>,
    style: Style,
) {
    let start = out.len();
    for (name, k) in multiples {
        let first = out.len() == start;
        match (first, k < 0) {
            (true, false) => {}
            (true, true) => out.push_str(minus(style)),
            (false, false) => out.push_str(" + "),
            (false, true) => write_display(out, format_args!(" {} ", minus(style))),
        }
        match (k.unsigned_abs(), style) {
            (1, _) => {}
            (n, Style::Ascii) => write_display(out, format_args!("{n}*")),
            (n, _) => write_display(out, format_args!("{n}")),
        }
        out.push_str(name);
    }
}

/// `cos kθ` for `k ≥ 2`: `cos 2θ`, `\cos 2\theta`; `cos(2*theta)`, which parses back.
fn write_multiple_angle(out: &mut String, fun: &str, k: u32, name: &str, style: Style) {
    match style {
        Style::Ascii => write_display(out, format_args!("{fun}({k}*{name})")),
        Style::Latex => write_display(out, format_args!("\\{fun} {k}{name}")),
        Style::Unicode => write_display(out, format_args!("{fun} {k}{name}")),
    }
}

/// A sum written inside a term, `α(x² + y²)/(…)`: its text and its number of terms.
#[derive(Clone, Copy)]
struct Inner<'a> {
    text: &'a str,
    terms: usize,
}

/// Writes the term `coeff · Π v^e · (inner) · trig` of a sum written from byte `start` of
/// `out` on: its sign or the ` + ` before it, then its text, factor by factor, with no string
/// of its own.
fn write_term(
    out: &mut String,
    start: usize,
    names: &Names,
    term: &CosSinTerm,
    trig: Option<&TrigMonomial>,
    inner: Option<Inner<'_>>,
    style: Style,
) {
    let (coeff, exps) = (&term.coeff, &term.exps);
    let (negative, num_int, den_int, complex) = split_coeff(coeff, style);
    push_sign(out, start, negative, style);
    let denominators =
        usize::from(!den_int.is_one()) + names.order.iter().filter(|&&j| exps[j] < 0).count();
    // A long sum over a denominator in `\left( … \right) / \left( … \right)`, where a display
    // may break it between terms (a `\frac` is one box, which ran 2950 pt past the margin).
    let frac = style == Style::Latex && denominators > 0 && inner.is_none_or(|i| i.terms <= 4);
    if frac {
        out.push_str(r"\frac{");
    }
    // `(p_x sin φ)/(Mω)`, not `p_x sin φ/(Mω)`, which reads as the sine of `φ/(Mω)`: text
    // sets a numerator that ends in a bare `cos θ` or `sin θ` apart from its denominator
    // (`cos(θ − φ)/2` ends in its own parenthesis).
    let enclosed = style == Style::Unicode
        && denominators > 0
        && trig.is_some_and(|t| !TrigMonomial::is_one(t) && !names.is_joint_harmonic(t));
    if enclosed {
        out.push('(');
    }
    // A name of several words that has a power, or a factor or a denominator after it, is set
    // in parentheses, and so is every other in the term: `(Re K)² H_x`, `(Re K) (Im K)`,
    // `(Re K)/M`, but `6ω Im K` and `\frac{\operatorname{Re} K}{M}`.
    let last_factor = names.order.iter().rev().find(|&&j| exps[j] > 0);
    let words_in_parentheses = names.order.iter().any(|&j| {
        names.several_words[j]
            && exps[j] != 0
            && (exps[j] != 1
                || Some(&j) != last_factor
                || inner.is_some()
                || trig.is_some_and(|t| !TrigMonomial::is_one(t))
                || (denominators > 0 && !frac))
    });
    let mut numerator = Product::new(style);
    let after_i = complex.is_none() && !coeff.im.is_zero();
    if let Some(c) = complex {
        numerator.next(out, true);
        out.push_str(&c);
    } else {
        if !num_int.is_one() {
            numerator.next(out, false);
            write_display(out, format_args!("{num_int}"));
        }
        if !coeff.im.is_zero() {
            numerator.next(out, false);
            out.push('i');
        }
    }
    // What the numerator writes after its variables: a sum in parentheses, cosines and sines,
    // and in text a denominator after a `/`.
    let after_numerator = inner.is_some()
        || trig.is_some_and(|t| !TrigMonomial::is_one(t))
        || (denominators > 0 && !frac);
    let variables = |out: &mut String, product: &mut Product, positive: bool, after_i: bool| {
        let factors =
            || (names.order.iter().copied()).filter(|&j| exps[j] != 0 && (exps[j] > 0) == positive);
        let apart = names.apart_in_runs(factors(), exps, after_i);
        let count = factors().count();
        for (k, j) in factors().enumerate() {
            let name = &names.names[j];
            let wide = style == Style::Unicode && (names.words[j] || name.chars().count() > 1);
            product.next_apart(out, wide, apart.get(k) == Some(&true));
            // A derivative or a gradient with a power, or anything after it in its product
            // (another factor, a sum, a cosine, a denominator), is set in parentheses, where
            // it would take them as its argument: `(∂H)²`, `(∂H) x`, `(∂H)/M`, not `∂H²`,
            // `∂H x`, `∂H/M`, which read as `∂(H²)`, `∂(Hx)`, `∂(H/M)`; alone or last, as
            // `x ∂H`, it needs none.
            let followed = k + 1 < count || (positive && after_numerator);
            if (names.several_words[j] && words_in_parentheses)
                || (names.differential[j] && (exps[j].abs() != 1 || followed))
            {
                write_power(out, &format!("({name})"), exps[j].abs(), style);
            } else {
                write_power(out, name, exps[j].abs(), style);
            }
        }
    };
    variables(out, &mut numerator, true, after_i);
    if let Some(i) = inner {
        // `α(x² + y²)`: the parenthesis sets the sum apart, so no space is needed before it
        // (nor `*` in ASCII, which still parses); `\frac{x + y}{…}` needs none.
        let alone = numerator.factors == 0 && trig.is_none_or(TrigMonomial::is_one);
        numerator.next(out, false);
        match style {
            Style::Latex if frac && alone => out.push_str(i.text),
            Style::Latex => write_display(out, format_args!(r"\left({}\right)", i.text)),
            _ => write_display(out, format_args!("({})", i.text)),
        }
    }
    if let Some(t) = trig {
        write_trig_factors(out, &mut numerator, names, t);
    }
    if numerator.factors == 0 {
        out.push('1');
    }
    if enclosed {
        out.push(')');
    }
    if denominators == 0 {
        return;
    }
    match style {
        Style::Latex if frac => out.push_str("}{"),
        Style::Latex => out.push_str(r" / \left("),
        _ if denominators == 1 => out.push('/'),
        _ => out.push_str("/("),
    }
    let mut denominator = Product::new(style);
    if !den_int.is_one() {
        denominator.next(out, false);
        write_display(out, format_args!("{den_int}"));
    }
    // A denominator that is one atom to the first power needs no parentheses of its own in
    // LaTeX, where the fraction sets it apart: `\frac{1}{x - y}` (it was `\frac{1}{(x - y)}`).
    let mut below = names.order.iter().filter(|&&j| exps[j] < 0);
    let lone = match (below.next(), below.next()) {
        (Some(&j), None) if style == Style::Latex && den_int.is_one() && exps[j] == -1 => {
            unparenthesized(&names.names[j])
        }
        _ => None,
    };
    match lone {
        Some(bare) => out.push_str(bare),
        None => variables(out, &mut denominator, false, false),
    }
    match style {
        Style::Latex if frac => out.push('}'),
        Style::Latex => out.push_str(r"\right)"),
        _ if denominators > 1 => out.push(')'),
        _ => {}
    }
}

/// `(negative, |numerator|, denominator, general complex text)` of a coefficient, the two
/// magnitudes borrowed from it (one for a complex coefficient, written whole in the text).
fn split_coeff(
    c: &GaussianRational,
    style: Style,
) -> (bool, Magnitude<'_>, Magnitude<'_>, Option<String>) {
    let (part, complex) = match (c.re.is_zero(), c.im.is_zero()) {
        (_, true) => (&c.re, false),
        (true, false) => (&c.im, false),
        _ => (&c.re, true),
    };
    if complex {
        let text = match style {
            Style::Ascii => format!("({c})"),
            Style::Latex => {
                let sign = if c.im.is_negative() { "-" } else { "+" };
                let re = render_term_free(&c.re, style);
                let re = if re.0 { format!("-{}", re.1) } else { re.1 };
                format!(r"\left({re} {sign} {}\right)", imaginary(&c.im, style))
            }
            Style::Unicode => {
                let sign = if c.im.is_negative() { "−" } else { "+" };
                let re = render_term_free(&c.re, style);
                let re = if re.0 { format!("−{}", re.1) } else { re.1 };
                format!("({re} {sign} {})", imaginary(&c.im, style))
            }
        };
        return (false, Magnitude::Word(1), Magnitude::Word(1), Some(text));
    }
    let (numerator, denominator) = part.magnitudes();
    (part.is_negative(), numerator, denominator, None)
}

/// A number alone, as the notation writes it: `-3/2`, `11i`, `-11i/7` (the `i` on the
/// numerator, where `11/7i` would read as `11/(7i)`), `3/2 - i`, with the style's minus sign.
pub fn render_number(q: &GaussianRational, style: Style) -> String {
    let signed = |negative: bool, text: String| match negative {
        true => format!("{}{text}", minus(style)),
        false => text,
    };
    let (negative, re) = render_term_free(&q.re, style);
    let re = signed(negative, re);
    match (q.re.is_zero(), q.im.is_zero(), q.im.is_negative()) {
        (_, true, _) => re,
        (true, false, negative) => signed(negative, imaginary(&q.im, style)),
        (false, false, true) => format!("{re} {} {}", minus(style), imaginary(&q.im, style)),
        (false, false, false) => format!("{re} + {}", imaginary(&q.im, style)),
    }
}

/// `|q|·i` beside a real part: `i` alone for `±1`, the `i` on the numerator in text (`5i/7`,
/// where `5/7i` reads as `5/(7i)`), after the fraction in LaTeX (`\frac{5}{7} i`).
fn imaginary(q: &Rational, style: Style) -> String {
    let (numerator, denominator) = q.magnitudes();
    let latex = style == Style::Latex;
    match (latex, numerator.is_one(), denominator.is_one()) {
        (_, true, true) => "i".to_string(),
        (true, false, true) => format!("{numerator} i"),
        (false, false, true) => format!("{numerator}i"),
        (true, _, false) => format!(r"\frac{{{numerator}}}{{{denominator}}} i"),
        (false, true, false) => format!("i/{denominator}"),
        (false, false, false) => format!("{numerator}i/{denominator}"),
    }
}

fn render_term_free(q: &Rational, style: Style) -> (bool, String) {
    let abs = q.abs();
    let text = match style {
        Style::Latex if !abs.is_integer() => {
            format!(r"\frac{{{}}}{{{}}}", abs.numer(), abs.denom())
        }
        _ => abs.to_string(),
    };
    (q.is_negative(), text)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `ALL` has every notation once, in the order they are declared (its list is `name`'s,
    /// whose match covers every notation), and each reads back from its name.
    #[test]
    fn every_style_is_listed_in_order_and_reads_back_from_its_name() {
        for (i, style) in Style::ALL.into_iter().enumerate() {
            assert_eq!(style as usize, i, "{style:?}");
            assert_eq!(style.name().parse(), Ok(style));
        }
    }
}
