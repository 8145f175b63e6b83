//! The space searched and the options of a search.

use trigpoly::{Expr, Rational, Var};

use crate::claim::Condition;

use super::level_set::LevelSet;

/// The finite space of functions searched, each degree named as it is set: the default is
/// the constants (every degree 0), and each method widens one degree.
///
/// ```
/// use brackets::search::SearchSpace;
///
/// // Quadratic in the momenta, linear in the coordinates, first order in the angles.
/// let space = SearchSpace::default().momenta_degree(2).positions_degree(1).trig_degree(1);
/// assert_eq!((space.momenta_degree, space.positions_degree, space.trig_degree), (2, 1, 1));
/// assert_eq!(space.poisson_degree, 0);
/// assert!(!space.laurent);
/// ```
///
/// A degree may be added, so another crate writes no literal of all of them:
///
/// ```compile_fail,E0639
/// let space = brackets::search::SearchSpace { momenta_degree: 2, ..Default::default() };
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct SearchSpace {
    /// Total degree in the momenta ([`SpaceVariables::momenta`](super::SpaceVariables::momenta)).
    pub momenta_degree: u32,
    /// Total degree `Σ|a|` in the coordinates.
    pub positions_degree: u32,
    /// Trigonometric order `Σ|k|` in the angles.
    pub trig_degree: u32,
    /// Whether coordinates may carry negative exponents (Laurent potentials such as `β/x²`).
    pub laurent: bool,
    /// Total degree in the parameters kept symbolic ([`SearchOptions::symbolic`]).
    pub parameters_degree: u32,
    /// Total degree in the Poisson variables
    /// ([`SpaceVariables::poisson`](super::SpaceVariables::poisson)), those whose brackets are
    /// declared (0 unless set, [`SearchSpace::poisson_degree`]).
    pub poisson_degree: u32,
    /// On a system with denominator atoms, the total degree `Σ k_i` of the powers
    /// `1/D_i^{k_i}` (0 unless set, [`SearchSpace::denominators_degree`]).
    pub denominators_degree: u32,
    /// On a system with radicals, the total degree `Σ |j_i|` of the powers `r_i^{j_i}`, of
    /// either sign (0 unless set, [`SearchSpace::radicals_degree`]).
    pub radicals_degree: u32,
}

impl SearchSpace {
    /// The same space with polynomials of total degree `≤ d` in the momenta.
    #[must_use]
    pub fn momenta_degree(mut self, d: u32) -> Self {
        self.momenta_degree = d;
        self
    }

    /// The same space with polynomials of total degree `≤ d` in the coordinates (`Σ|a| ≤ d`
    /// with negative powers, [`SearchSpace::laurent`]).
    #[must_use]
    pub fn positions_degree(mut self, d: u32) -> Self {
        self.positions_degree = d;
        self
    }

    /// The same space with trigonometric polynomials of order `Σ|k| ≤ d` in the angles.
    #[must_use]
    pub fn trig_degree(mut self, d: u32) -> Self {
        self.trig_degree = d;
        self
    }

    /// The same space with products of powers of the radicals `r_i^{j_i}` of total degree
    /// `Σ |j_i| ≤ d`, negative powers included (on a system that declares radicals; the
    /// Kepler problem's `−k/r` and `x/r` have degree 1).
    #[must_use]
    pub fn radicals_degree(mut self, d: u32) -> Self {
        self.radicals_degree = d;
        self
    }

    /// The same space with products of the denominators `1/D_i^{k_i}` of total degree
    /// `Σ k_i ≤ d` (on a system that declares denominator atoms; Calogero's `g/(x − y)²`
    /// has degree 2).
    #[must_use]
    pub fn denominators_degree(mut self, d: u32) -> Self {
        self.denominators_degree = d;
        self
    }

    /// The same space with polynomials of total degree `≤ d` in the Poisson variables.
    #[must_use]
    pub fn poisson_degree(mut self, d: u32) -> Self {
        self.poisson_degree = d;
        self
    }

    /// The same space with coefficients polynomial of total degree `≤ d` in the parameters
    /// kept symbolic.
    #[must_use]
    pub fn parameters_degree(mut self, d: u32) -> Self {
        self.parameters_degree = d;
        self
    }

    /// The same space with negative powers of the coordinates allowed.
    #[must_use]
    pub fn laurent(mut self) -> Self {
        self.laurent = true;
        self
    }

    /// Why `f` lies outside the space, if it does, in words: its degree in the momenta, in the
    /// coordinates, in the Poisson variables or in the angles is too high, or it has negative
    /// powers the space does not take. A search for the integrals of a system whose Hamiltonian
    /// lies outside finds neither `H` nor, often, anything else, so the report says why. Its
    /// names and settings are between backticks, as a report's prose marks its formulas
    /// (``negative powers of `x` ``).
    pub fn why_outside(&self, f: &Expr) -> Option<String> {
        use trigpoly::VarKind::{Angle, Coordinate, Momentum, Poisson};
        let vars = f.vars();
        // The first variable of `kind` with a negative power in `f`, by name.
        let negative = |kind| {
            vars.vars()
                .filter(|&v| vars.variable(v).kind() == kind)
                .find(|&v| f.exponent_range(v).is_some_and(|(lo, _)| lo < 0))
                .map(|v| vars.variable(v).unicode().to_string())
        };
        let mut why = Vec::new();
        for kind in [Momentum, Poisson] {
            if let Some(p) = negative(kind) {
                why.push(format!("negative powers of `{p}`"));
            }
        }
        if let Some(d) = vars
            .denominators()
            .find(|&v| f.exponent_range(v).is_some_and(|(_, hi)| hi > 0))
        {
            why.push(format!(
                "a positive power of the denominator `{}`, which the space takes only as `1/D`",
                vars.variable(d).unicode()
            ));
        }
        // The degrees that a setting of their own bounds, named as the API and the command line
        // name it.
        for (what, d, bound, setting) in [
            (
                "radicals",
                radicals_degree(f),
                self.radicals_degree,
                "radicals_degree",
            ),
            (
                "denominators",
                denominators_degree(f),
                self.denominators_degree,
                "denominators_degree",
            ),
        ] {
            if d > i64::from(bound) {
                why.push(format!(
                    "degree {d} in the {what}, past the space's {bound} (`SearchSpace::{setting}`; \
                     on the command line, `--{}`)",
                    setting.replace('_', "-")
                ));
            }
        }
        if let (false, Some(x)) = (self.laurent, negative(Coordinate)) {
            why.push(format!(
                "negative powers of `{x}`, which a Laurent space (`SearchSpace::laurent`; on the \
                 command line, `--laurent`) admits"
            ));
        }
        for (what, kind, bound) in [
            ("momenta", Momentum, self.momenta_degree),
            ("coordinates", Coordinate, self.positions_degree),
            ("Poisson variables", Poisson, self.poisson_degree),
            ("angles (trigonometric order)", Angle, self.trig_degree),
        ] {
            let d = f.total_degree(&[kind]).unwrap_or(0);
            if d > i64::from(bound) {
                why.push(format!(
                    "degree {d} in the {what}, past the space's {bound}"
                ));
            }
        }
        (!why.is_empty()).then(|| why.join("; "))
    }
}

/// The largest total degree `Σ |j_i|` of a term's radicals `r_i^{j_i}`.
pub(super) fn radicals_degree(f: &Expr) -> i64 {
    let radicals: Vec<Var> = f.vars().radicals().collect();
    f.terms()
        .map(|t| radicals.iter().map(|&v| t.exponent(v).abs()).sum::<i64>())
        .max()
        .unwrap_or(0)
}

/// The largest total degree `Σ k_i` of a term's denominators `1/D_i^{k_i}` (the negative
/// exponents of its denominator atoms).
pub(super) fn denominators_degree(f: &Expr) -> i64 {
    let atoms: Vec<Var> = f.vars().denominators().collect();
    f.terms()
        .map(|t| atoms.iter().map(|&v| (-t.exponent(v)).max(0)).sum::<i64>())
        .max()
        .unwrap_or(0)
}

/// What to search for and how: a space ([`SearchOptions::new`]), then each other choice by a
/// method, the condition by [`SearchOptions::when`], a parameter's value by
/// [`SearchOptions::fix`], every other field by the method of its name (`symbolic` and `known`
/// add one more each call).
///
/// ```
/// use brackets::search::{SearchOptions, SearchSpace, DEFAULT_MAX_PRODUCTS};
/// use brackets::systems;
///
/// let rotor = systems::harmonic_rotor();
/// let omega = rotor.vars().lookup("omega").unwrap();
/// let space = SearchSpace::default().momenta_degree(2).positions_degree(2).trig_degree(1);
/// let options = SearchOptions::new(space).symbolic(omega).new_only().max_products(1000);
/// assert_eq!((options.symbolic, options.new_only, options.max_products), (vec![omega], true, 1000));
/// assert!(!options.exact_complement && options.condition.is_none());
/// assert_eq!(SearchOptions::new(space).max_products, DEFAULT_MAX_PRODUCTS);
/// ```
///
/// A choice may be added, so another crate writes no literal of all of them:
///
/// ```compile_fail,E0639
/// use brackets::search::{SearchOptions, SearchSpace};
/// let options = SearchOptions { space: SearchSpace::default(), condition: None, fixed: vec![],
///     symbolic: vec![], known: vec![], new_only: false, exact_complement: false,
///     max_products: 10 };
/// ```
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct SearchOptions {
    /// The space.
    pub space: SearchSpace,
    /// The condition (a resonance), applied after the bracket.
    pub condition: Option<Condition>,
    /// Values for parameters; every parameter of `H` or of the condition that is neither
    /// listed here nor kept symbolic is fixed to 1.
    pub fixed: Vec<(Var, Rational)>,
    /// Parameters kept symbolic: the coefficients of the integrals are polynomials in them.
    pub symbolic: Vec<Var>,
    /// Known integrals (symbolic) for [`SearchOptions::new_only`]; the system's named
    /// functions that are real integrals are always used.
    pub known: Vec<(String, Expr)>,
    /// Also find a complement of what sums of known integrals, constants and products of
    /// integrals of lower grade give (and, with parameters kept symbolic, parameter multiples
    /// of integrals, and an integral `F` whose multiple `μ·F` by a monomial in the parameters,
    /// or by a declared denominator of them alone, lies in the space and is generated): see
    /// [`NewIntegrals`](super::NewIntegrals).
    pub new_only: bool,
    /// Decide that complement by elimination over Q alone. By default it is decided modulo a
    /// 62-bit prime, each dependency found there checked over Q (falling back to Q when one
    /// fails): an integral reported generated is then generated, and one reported new is new
    /// unless the prime divides a minor of the span of the known products, which this rules
    /// out at some cost in time.
    pub exact_complement: bool,
    /// The most products of integrals [`SearchOptions::new_only`] forms before it stops with
    /// an error ([`DEFAULT_MAX_PRODUCTS`] unless set): a limit,
    /// [`EngineError::PastLimit`](crate::EngineError::PastLimit) of
    /// [`EngineLimit::SearchProducts`](crate::EngineLimit::SearchProducts).
    pub max_products: usize,
    /// The most rows of a block's generic minor whose determinant
    /// [`exceptional_values`](super::exceptional_values) computes before it stops with an error
    /// ([`DEFAULT_MAX_MINOR`] unless set): a limit,
    /// [`EngineError::PastLimit`](crate::EngineError::PastLimit) of
    /// [`EngineLimit::MinorRows`](crate::EngineLimit::MinorRows).
    pub max_minor: usize,
    /// The level set the search is restricted to ([`SearchOptions::on`]): the integrals
    /// found are those whose bracket with `H` vanishes there, in normal form modulo its
    /// polynomial. It takes no condition and no parameters kept symbolic; with `new_only`,
    /// every integral, known or a product, is taken in normal form modulo that polynomial
    /// (see [`NewIntegrals`](super::NewIntegrals)).
    pub on: Option<LevelSet>,
}

/// The most products of integrals `--new-only` forms unless told otherwise: some seconds'
/// work (the 1:1 resonance up to degree 12 forms some 165 000).
pub const DEFAULT_MAX_PRODUCTS: usize = 1_000_000;

/// The most rows of a minor whose determinant in the parameter
/// [`exceptional_values`](super::exceptional_values) computes unless told otherwise: some
/// seconds' work (release: 206 rows take 4.6 s, 302 rows 22 s, the time growing about as the fourth power of the rows; 250 rows some 10 s).
pub const DEFAULT_MAX_MINOR: usize = 250;

impl SearchOptions {
    /// Searches a space with parameters fixed to 1 and no condition.
    pub fn new(space: SearchSpace) -> Self {
        SearchOptions {
            space,
            condition: None,
            fixed: Vec::new(),
            symbolic: Vec::new(),
            known: Vec::new(),
            new_only: false,
            exact_complement: false,
            max_products: DEFAULT_MAX_PRODUCTS,
            max_minor: DEFAULT_MAX_MINOR,
            on: None,
        }
    }

    /// On the level set `level` of a polynomial that the flow of `H` keeps
    /// ([`LevelSet`]): the integrals there, `{K, H} = P·Q`.
    #[must_use]
    pub fn on(mut self, level: LevelSet) -> Self {
        self.on = Some(level);
        self
    }

    /// Under a condition.
    #[must_use]
    pub fn when(mut self, condition: Condition) -> Self {
        self.condition = Some(condition);
        self
    }

    /// With a parameter fixed to a value: a [`Rational`], or an integer.
    ///
    /// ```
    /// use brackets::{systems, SearchOptions, SearchSpace};
    /// use trigpoly::Rational;
    ///
    /// let rotor = systems::harmonic_rotor();
    /// let omega = rotor.vars().lookup("omega").unwrap();
    /// let options = SearchOptions::new(SearchSpace::default()).fix(omega, 2);
    /// assert_eq!(options.fixed, [(omega, Rational::from(2))]);
    /// let options = options.fix(omega, Rational::new(1, 3));
    /// assert_eq!(options.fixed, [(omega, Rational::new(1, 3))]);
    /// ```
    #[must_use]
    pub fn fix(mut self, v: Var, value: impl Into<Rational>) -> Self {
        self.fixed.retain(|f| f.0 != v);
        self.fixed.push((v, value.into()));
        self
    }

    /// With a parameter kept symbolic (see [`SearchSpace::parameters_degree`]).
    #[must_use]
    pub fn symbolic(mut self, v: Var) -> Self {
        if !self.symbolic.contains(&v) {
            self.symbolic.push(v);
        }
        self
    }

    /// With the complement of the known integrals' products.
    #[must_use]
    pub fn new_only(mut self) -> Self {
        self.new_only = true;
        self
    }

    /// With the complement decided over Q alone ([`SearchOptions::exact_complement`]).
    #[must_use]
    pub fn exact_complement(mut self) -> Self {
        self.exact_complement = true;
        self
    }

    /// With at most `n` products of integrals for the complement.
    #[must_use]
    pub fn max_products(mut self, n: usize) -> Self {
        self.max_products = n;
        self
    }

    /// With at most `n` rows in a minor whose determinant
    /// [`exceptional_values`](super::exceptional_values) computes.
    ///
    /// ```
    /// use brackets::search::{SearchOptions, SearchSpace, DEFAULT_MAX_MINOR};
    ///
    /// assert_eq!(SearchOptions::new(SearchSpace::default()).max_minor, DEFAULT_MAX_MINOR);
    /// assert_eq!(SearchOptions::new(SearchSpace::default()).max_minor(30).max_minor, 30);
    /// ```
    #[must_use]
    pub fn max_minor(mut self, n: usize) -> Self {
        self.max_minor = n;
        self
    }

    /// With an extra known integral.
    #[must_use]
    pub fn known(mut self, name: &str, f: Expr) -> Self {
        self.known.push((name.to_string(), f));
        self
    }
}
