//! Discovery: a basis of *all* integrals of a system in a finite space of functions, found by
//! exact linear algebra, each basis element proved by the engine.
//!
//! The space ([`SearchSpace`]) is spanned by `x^a y^b · p_x^c p_y^d · M₁^m M₂^n · {1, cos kθ,
//! sin kθ}`: coordinates of total degree `Σ|a| ≤ e` (negative exponents too when `laurent`),
//! momenta of total degree `≤ d`, Poisson variables (whose brackets are declared, such as the
//! `M₁, M₂, M₃` of so(3)*) of total degree `≤ P`, and trigonometric order `Σ|k| ≤ K` in the
//! angles. An angle's momentum or a Poisson variable that the condition fixes is left out: on a
//! resonance surface `p_θ = mIω/n` it is a constant, and every function of it is an integral
//! ([`SpaceVariables`]). The images `{φ, H}` are the bracket's, declared brackets included: for
//! each phase variable `v`, `∂φ/∂v` times `{v, H}` (after the condition), formed once.
//!
//! The unknowns are the real coefficients of that basis, so the equations `{F, H} = 0` (after the
//! condition) are linear over `Q`: the real and imaginary parts of the coefficients of
//! `e^{ik·θ}` with `k ≥ 0`, the others being their conjugates. Parameters are fixed to rational
//! values for the linear algebra ([`SearchOptions::fixed`], 1 by default), or kept symbolic
//! ([`SearchOptions::symbolic`]): then each basis function is also multiplied by the monomials
//! of those parameters up to [`SearchSpace::parameters_degree`], the equations are the
//! coefficients of every monomial in the variables *and* those parameters, and what is found
//! holds for every value of them; [`SearchResult::module`] picks the integrals that generate
//! the others over the polynomials in the parameters. The system splits
//! into connected components (unknowns sharing an equation: for a quadratic Hamiltonian, one
//! per degree and trigonometric order), each solved modulo a 62-bit prime, reconstructed and
//! checked exactly ([`crate::modular::kernel`]). Every basis element is then proved by the
//! engine at the fixed values, lifted back to symbolic parameters by homogeneity
//! ([`crate::scaling`]) and proved again symbolically.
//!
//! On a system with denominator atoms (`1/(x − y)` exact, [`trigpoly::VarKind::Denominator`])
//! the space also has the products `1/Π D_i^{k_i}` with `Σ k_i ≤`
//! [`SearchSpace::denominators_degree`]. Its monomials are then not independent functions
//! (`x/(x − y) − y/(x − y) = 1`): the unknowns are those independent of the simpler ones, and
//! the equations and that choice are decided on images under one injective map onto
//! polynomials, the denominators cleared (`crate::clearing`), so that no function equal to
//! zero is reported and each integral has one set of coordinates. Parameters are kept
//! symbolic when no denominator holds them; which integrals are new (`new_only`) is not yet
//! offered there.
//!
//! ```
//! use brackets::search::{search, SearchOptions, SearchSpace};
//! use brackets::systems;
//!
//! // The harmonic rotor at p_θ = Iω: the integrals linear in the momenta, trig order ≤ 1.
//! let rotor = systems::harmonic_rotor();
//! let options = SearchOptions::new(SearchSpace::new(1, 1, 1)).when(rotor.resonance(1, 1)?);
//! let found = search(&rotor, &options)?;
//! // The constant, L = x p_y − y p_x, and four linear integrals: Re and Im of
//! // (p_x + iMωx)e^{−iθ} and of (p_y + iMωy)e^{−iθ}.
//! assert_eq!(found.basis.len(), 6);
//! assert!(found.basis.iter().all(|f| f.symbolic.is_some()));
//! # Ok::<(), brackets::EngineError>(())
//! ```
//!
//! On a Lie–Poisson space the same search finds the Casimirs with the integrals: for the
//! Euler top (so(3)*, `H = Σ M_i²/(2I_i)`) at generic moments, the quadratic integrals are
//! spanned by `|M|²` and `H`.
//!
//! ```
//! use brackets::search::{search, SearchOptions, SearchSpace};
//! use brackets::{PhaseSpace, System};
//! use trigpoly::{Expr, Rational, VarSet};
//!
//! let vars = VarSet::builder()
//!     .poisson("M1").poisson("M2").poisson("M3")
//!     .parameter("I1").parameter("I2").parameter("I3")
//!     .build()?;
//! let e = |s: &str| Expr::parse(&vars, s).unwrap();
//! let space = PhaseSpace::new(&vars, &[])?
//!     .with_brackets(&[("M1", "M2", e("M3")), ("M2", "M3", e("M1")), ("M3", "M1", e("M2"))])?;
//! let top = System::new("Euler top", space, e("M1^2/(2*I1) + M2^2/(2*I2) + M3^2/(2*I3)"));
//! // At I = (1, 2, 3): 1, then two quadratic integrals (|M|² and H, combined).
//! let mut options = SearchOptions::new(SearchSpace::new(0, 0, 0).poisson_degree(2));
//! for (i, name) in ["I1", "I2", "I3"].into_iter().enumerate() {
//!     options = options.fix(top.var(name), Rational::from(i as i64 + 1));
//! }
//! let found = search(&top, &options)?;
//! assert_eq!(found.dimensions_by_poisson_degree(), [1, 1, 3]);
//! assert!(found.basis.iter().all(|f| f.proved_fixed));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use rustc_hash::{FxHashMap, FxHashSet};
use std::time::Instant;

use itertools::Itertools;
use rayon::prelude::*;
use trigpoly::{
    Expr, GaussianRational, MonomialIndex, Rational, Style, Term, Var, VarKind, VarSet, Vars,
};

use crate::claim::Condition;
use crate::clearing::Clearing;
use crate::error::EngineError;
use crate::modular::{self, Echelon, Field, Fp, SparseVec};
use crate::scaling::{Lifter, Scaling};
use crate::system::System;

/// How many images `{φ, H}` are formed at a time on the pool's threads before they are numbered
/// into equations: enough to share among threads, few enough to keep little in memory.
const IMAGE_BLOCK: usize = 4096;

/// The finite space of functions searched.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SearchSpace {
    /// Total degree in the momenta ([`SpaceVariables::momenta`]).
    pub momenta_degree: u32,
    /// Total degree `Σ|a|` in the coordinates.
    pub positions_degree: u32,
    /// Trigonometric order `Σ|k|` in the angles.
    pub trig_degree: u32,
    /// Whether coordinates may carry negative exponents (Laurent potentials such as `β/x²`).
    pub laurent: bool,
    /// Total degree in the parameters kept symbolic ([`SearchOptions::symbolic`]).
    pub parameters_degree: u32,
    /// Total degree in the Poisson variables ([`SpaceVariables::poisson`]), those whose
    /// brackets are declared (0 unless set, [`SearchSpace::poisson_degree`]).
    pub poisson_degree: u32,
    /// On a system with denominator atoms, the total degree `Σ k_i` of the powers
    /// `1/D_i^{k_i}` (0 unless set, [`SearchSpace::denominators_degree`]).
    pub denominators_degree: u32,
}

impl SearchSpace {
    /// Momenta degree `d`, positions degree `e`, trigonometric order `k`, no negative powers,
    /// degree 0 in the Poisson variables ([`SearchSpace::poisson_degree`] sets another).
    pub fn new(momenta_degree: u32, positions_degree: u32, trig_degree: u32) -> Self {
        SearchSpace {
            momenta_degree,
            positions_degree,
            trig_degree,
            laurent: false,
            parameters_degree: 0,
            poisson_degree: 0,
            denominators_degree: 0,
        }
    }

    /// The same space with products of the denominators `1/D_i^{k_i}` of total degree
    /// `Σ k_i ≤ d` (on a system that declares denominator atoms; Calogero's `g/(x − y)²`
    /// has degree 2).
    pub fn denominators_degree(mut self, d: u32) -> Self {
        self.denominators_degree = d;
        self
    }

    /// The same space with polynomials of total degree `≤ d` in the Poisson variables.
    pub fn poisson_degree(mut self, d: u32) -> Self {
        self.poisson_degree = d;
        self
    }

    /// The same space with coefficients polynomial of total degree `≤ d` in the parameters
    /// kept symbolic.
    pub fn parameters_degree(mut self, d: u32) -> Self {
        self.parameters_degree = d;
        self
    }

    /// The same space with negative powers of the coordinates allowed.
    pub fn laurent(mut self) -> Self {
        self.laurent = true;
        self
    }

    /// Why `f` lies outside the space, if it does, in words: its degree in the momenta, in the
    /// coordinates, in the Poisson variables or in the angles is too high, or it has negative
    /// powers the space does not take. A search for the integrals of a system whose Hamiltonian
    /// lies outside finds neither `H` nor, often, anything else, so the report says why.
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
                why.push(format!("negative powers of {p}"));
            }
        }
        if let Some(d) = vars
            .denominators()
            .find(|&v| f.exponent_range(v).is_some_and(|(_, hi)| hi > 0))
        {
            why.push(format!(
                "a positive power of the denominator {}, which the space takes only as 1/D",
                vars.variable(d).unicode()
            ));
        }
        let over = denominators_degree(f);
        if over > i64::from(self.denominators_degree) {
            why.push(format!(
                "degree {over} in the denominators, past the space's {} \
                 (SearchSpace::denominators_degree; on the command line, --denominators-degree)",
                self.denominators_degree
            ));
        }
        if let (false, Some(x)) = (self.laurent, negative(Coordinate)) {
            why.push(format!(
                "negative powers of {x}, which a Laurent space (SearchSpace::laurent; on the \
                 command line, --laurent) admits"
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

/// The largest total degree `Σ k_i` of a term's denominators `1/D_i^{k_i}` (the negative
/// exponents of its denominator atoms).
fn denominators_degree(f: &Expr) -> i64 {
    let atoms: Vec<Var> = f.vars().denominators().collect();
    f.terms()
        .map(|t| atoms.iter().map(|&v| (-t.exponent(v)).max(0)).sum::<i64>())
        .max()
        .unwrap_or(0)
}

/// What to search for and how.
#[derive(Clone, Debug)]
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
    /// of integrals): see [`NewIntegrals`].
    pub new_only: bool,
    /// Decide that complement by elimination over Q alone. By default it is decided modulo a
    /// 62-bit prime, each dependency found there checked over Q (falling back to Q when one
    /// fails): an integral reported generated is then generated, and one reported new is new
    /// unless the prime divides a minor of the span of the known products, which this rules
    /// out at some cost in time.
    pub exact_complement: bool,
    /// The most products of integrals [`SearchOptions::new_only`] forms before it stops with
    /// an error ([`DEFAULT_MAX_PRODUCTS`] unless set).
    pub max_products: usize,
}

/// The most products of integrals `--new-only` forms unless told otherwise: some seconds'
/// work (the 1:1 resonance up to degree 12 forms some 165 000).
pub const DEFAULT_MAX_PRODUCTS: usize = 1_000_000;

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
        }
    }

    /// Under a condition.
    pub fn when(mut self, condition: Condition) -> Self {
        self.condition = Some(condition);
        self
    }

    /// With a parameter fixed to a value.
    pub fn fix(mut self, v: Var, value: Rational) -> Self {
        self.fixed.retain(|f| f.0 != v);
        self.fixed.push((v, value));
        self
    }

    /// With a parameter kept symbolic (see [`SearchSpace::parameters_degree`]).
    pub fn symbolic(mut self, v: Var) -> Self {
        self.symbolic.push(v);
        self
    }

    /// With the complement of the known integrals' products.
    pub fn new_only(mut self) -> Self {
        self.new_only = true;
        self
    }

    /// With the complement decided over Q alone ([`SearchOptions::exact_complement`]).
    pub fn exact_complement(mut self) -> Self {
        self.exact_complement = true;
        self
    }

    /// With at most `n` products of integrals for the complement.
    pub fn max_products(mut self, n: usize) -> Self {
        self.max_products = n;
        self
    }

    /// With an extra known integral.
    pub fn known(mut self, name: &str, f: Expr) -> Self {
        self.known.push((name.to_string(), f));
        self
    }
}

/// One basis element of the integrals found.
#[derive(Clone, Debug)]
pub struct Integral {
    /// The integral at the fixed parameter values, with coprime integer coefficients.
    pub fixed: Expr,
    /// Whether the engine found `{F, H} = 0` (after the condition) at the fixed values.
    pub proved_fixed: bool,
    /// The integral with its parameters, if lifting and the symbolic proof succeeded.
    pub symbolic: Option<Expr>,
    /// Degree in the momenta.
    pub momenta_degree: i64,
    /// Degree `Σ|a|` in the coordinates.
    pub positions_degree: i64,
    /// Degree in the Poisson variables.
    pub poisson_degree: i64,
    /// Trigonometric order.
    pub trig_degree: i64,
}

impl Integral {
    /// The integral as printed: symbolic if it was lifted, otherwise at the fixed values,
    /// where alone it may hold; [`SearchResult::for_every_value`] says which.
    pub fn expr(&self) -> &Expr {
        self.symbolic.as_ref().unwrap_or(&self.fixed)
    }
}

/// What `--new-only` found. Integrals are graded by their total degree in the coordinates and
/// momenta, then by their trigonometric order (the largest such pair among a function's
/// terms, compared in that order); an integral of grade `g` is generated when it is a sum of
/// known integrals, constants, products of at least two integrals of grade below `g` and, with
/// parameters kept symbolic, parameter multiples of integrals of grade `≤ g`. The grades form
/// a filtration (a product's grade is at most the sum of its factors'), so where `cos(a − b)`
/// and `p_b` are integrals, `cos 2(a − b) = 2cos²(a − b) − 1` and `p_b cos(a − b)` are
/// generated; without angles the grade is the degree.
#[derive(Clone, Debug)]
pub struct NewIntegrals {
    /// The known integrals used (named functions that are real integrals lying in the space).
    pub known: Vec<String>,
    /// The dimension of the span of the known integrals and of all products of known and found
    /// integrals that lie in the space.
    pub generated: usize,
    /// Indices into the basis of a complement: the integrals that nothing known generates,
    /// decided by increasing grade.
    pub new: Vec<usize>,
    /// How many products were formed.
    pub products: usize,
}

/// With parameters kept symbolic, the integrals found form a module over the polynomials in
/// them: `A·I` is an integral whenever `I` is.
#[derive(Clone, Debug)]
pub struct ParameterModule {
    /// The parameters kept symbolic.
    pub parameters: Vec<Var>,
    /// Indices into the basis of generators: the basis integrals that are not sums of
    /// parameter multiples `a·J` (`a` a parameter, `J` an integral of the space) and of
    /// earlier generators. Every integral of the space is a combination of them with
    /// polynomial coefficients.
    pub generators: Vec<usize>,
}

/// Seconds spent in each stage (reported, never used to decide anything).
#[derive(Clone, Debug, Default)]
pub struct SearchTimings {
    /// Building the unknowns and their images `{φ, H}`.
    pub equations: f64,
    /// The exact linear algebra.
    pub solve: f64,
    /// The engine's proofs at the fixed values, lifting and symbolic proofs.
    pub proofs: f64,
    /// The complement of known products.
    pub new_only: f64,
    /// Everything.
    pub total: f64,
}

/// The result of a search.
#[derive(Clone, Debug)]
pub struct SearchResult {
    /// The space searched.
    pub space: SearchSpace,
    /// The condition's text, if any.
    pub condition: Option<String>,
    /// The parameters as fixed for the linear algebra.
    pub parameters: Vec<(Var, Rational)>,
    /// Whether lifting back to symbolic parameters was possible at all (the weights determine
    /// every parameter).
    pub liftable: bool,
    /// The variables (for printing the parameters).
    pub vars: Vars,
    /// The variables the space's functions are formed in.
    pub variables: SpaceVariables,
    /// Number of unknowns (real basis functions).
    pub unknowns: usize,
    /// Number of (nonzero) linear equations.
    pub equations: usize,
    /// Number of connected components of the linear system.
    pub components: usize,
    /// Unknowns in the largest component.
    pub largest_component: usize,
    /// A basis of all integrals in the space, by increasing degree in the momenta, then in the
    /// Poisson variables.
    pub basis: Vec<Integral>,
    /// The complement of the known integrals' products, if asked for.
    pub new: Option<NewIntegrals>,
    /// With parameters kept symbolic, the generators over the polynomials in them.
    pub module: Option<ParameterModule>,
    /// Timings.
    pub timings: SearchTimings,
}

impl SearchResult {
    /// The number of basis integrals of momenta degree `≤ j` for each `j = 0, …, d`: the
    /// dimensions of the spaces with smaller `d` (same coordinates and trigonometric order).
    pub fn dimensions_by_momenta_degree(&self) -> Vec<usize> {
        self.dimensions_by(self.space.momenta_degree, |f| f.momenta_degree)
    }

    /// The number of basis integrals of degree `≤ j` in the Poisson variables for each
    /// `j = 0, …, P`: the dimensions of the spaces with smaller `P`.
    pub fn dimensions_by_poisson_degree(&self) -> Vec<usize> {
        self.dimensions_by(self.space.poisson_degree, |f| f.poisson_degree)
    }

    /// The number of basis integrals whose `degree` is `≤ j`, for each `j = 0, …, bound`.
    fn dimensions_by(&self, bound: u32, degree: impl Fn(&Integral) -> i64) -> Vec<usize> {
        (0..=i64::from(bound))
            .map(|j| self.basis.iter().filter(|f| degree(f) <= j).count())
            .collect()
    }

    /// `counts[j][k]`: basis integrals of momenta degree exactly `j` and trigonometric order
    /// exactly `k`.
    pub fn counts(&self) -> Vec<Vec<usize>> {
        self.counts_by(self.space.momenta_degree, |f| f.momenta_degree)
    }

    /// `poisson_counts[j][k]`: basis integrals of degree exactly `j` in the Poisson variables
    /// and trigonometric order exactly `k`.
    pub fn poisson_counts(&self) -> Vec<Vec<usize>> {
        self.counts_by(self.space.poisson_degree, |f| f.poisson_degree)
    }

    /// `c[j][k]`: basis integrals whose `degree` is `j` (`≤ bound`) and trigonometric order `k`.
    fn counts_by(&self, bound: u32, degree: impl Fn(&Integral) -> i64) -> Vec<Vec<usize>> {
        let k = self.space.trig_degree as usize;
        let mut c = vec![vec![0; k + 1]; bound as usize + 1];
        for f in &self.basis {
            c[degree(f) as usize][f.trig_degree as usize] += 1;
        }
        c
    }

    /// The `i`-th basis integral as proved for every value of the parameters: lifted and
    /// proved symbolically, or proved where no parameter was fixed. `None` when it holds at
    /// the fixed values only (`x p_y − y p_x` of `p²/2 + (x² + a²y²)/2`, at `a = 1`).
    pub fn for_every_value(&self, i: usize) -> Option<&Expr> {
        let f = &self.basis[i];
        match (&f.symbolic, f.proved_fixed && self.parameters.is_empty()) {
            (Some(e), _) => Some(e),
            (None, true) => Some(&f.fixed),
            (None, false) => None,
        }
    }

    /// Whether every basis element was proved symbolically.
    pub fn all_symbolic(&self) -> bool {
        self.basis.iter().all(|f| f.symbolic.is_some())
    }
}

/// The variables of a search's space: monomials in the coordinates, in the momenta and in the
/// Poisson variables, times `cos k·θ`, `sin k·θ` in the angles. Every momentum and Poisson
/// variable of the phase space is among them but an angle's momentum or a Poisson variable that
/// the condition fixes (`p_θ = mIω/n`, `M₃ = 1` where the flow keeps `M₃`), a constant there.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SpaceVariables {
    /// The coordinates (not the angles), whose total degree is the positions degree.
    pub coordinates: Vec<Var>,
    /// The momenta, whose total degree is the momenta degree.
    pub momenta: Vec<Var>,
    /// The Poisson variables, whose total degree is the Poisson degree.
    pub poisson: Vec<Var>,
    /// The angles, whose trigonometric order is bounded.
    pub angles: Vec<Var>,
    /// The angles' momenta and the Poisson variables that the condition fixes, left out.
    pub left_out: Vec<Var>,
}

/// How an unknown depends on the angles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
enum Trig {
    One,
    Cos,
    Sin,
}

/// One real basis function `φ · trig(k·θ)`.
#[derive(Clone, Debug)]
struct Unknown {
    /// Exponents of the coordinates, momenta and Poisson variables and of the parameters kept
    /// symbolic (angles zero), over all variables.
    phase: Vec<i64>,
    /// `k` over the angles, canonical (first nonzero entry positive), zero for `One`.
    k: Vec<i64>,
    trig: Trig,
    momenta_degree: i64,
    poisson_degree: i64,
    positions_degree: i64,
    /// `Σ k_i` of its denominators `1/D_i^{k_i}`.
    denominators_degree: i64,
    trig_degree: i64,
    parameters_degree: i64,
}

impl Unknown {
    /// Its degrees in the order of the unknowns, simpler first: momenta, Poisson variables,
    /// trigonometric order, positions, denominators, parameters.
    fn degrees(&self) -> [i64; 6] {
        [
            self.momenta_degree,
            self.poisson_degree,
            self.trig_degree,
            self.positions_degree,
            self.denominators_degree,
            self.parameters_degree,
        ]
    }
}

/// Where a monomial `φ·e^{ik·θ}` of the space sits among the unknowns.
#[derive(Clone, Copy, Debug)]
enum Slot {
    /// `k = 0`: the unknown `φ`.
    One(usize),
    /// `k` canonical: the unknowns `φ cos k·θ` and `φ sin k·θ`.
    Canonical { cos: usize, sin: usize },
    /// `−k` for a canonical `k`: the same two unknowns, met from the conjugate side.
    Conjugate { cos: usize, sin: usize },
}

/// The search problem, with the parameters that are not kept symbolic at fixed values.
struct Problem {
    vars: Vars,
    /// The coordinates, momenta, Poisson variables and angles of the space.
    variables: SpaceVariables,
    unknowns: Vec<Unknown>,
    /// Where each monomial `φ·e^{ik·θ}` of the space sits among the unknowns.
    slots: MonomialIndex<Slot>,
    /// The fixed Hamiltonian and condition.
    h: Expr,
    condition: Option<Vec<(Var, Expr)>>,
    /// `{φ, H} = Σ_v ∂φ/∂v · {v, H}`: for each phase variable `v` with `{v, H}` not zero after
    /// the condition, `v`, that part of `{v, H}` and whether it enters negated: `∂H/∂p` for a
    /// coordinate, `∂H/∂q` negated for a momentum, and the declared brackets' part
    /// `Σ_u {v, u} ∂H/∂u` for a variable they involve ([`crate::phase::Gradient`]), to form
    /// the images of the unknowns without differentiating `H` again each time.
    flow_parts: Vec<(Var, Expr, bool)>,
}

/// Exponent vectors `≥ 0` (or any sign) over `n` slots with `Σ|e| ≤ max`.
fn exponent_vectors(n: usize, max: u32, signed: bool) -> Vec<Vec<i64>> {
    let mut out = vec![Vec::new()];
    for _ in 0..n {
        let mut next = Vec::new();
        for v in &out {
            let used: i64 = v.iter().map(|x: &i64| x.abs()).sum();
            let left = max as i64 - used;
            let lo = if signed { -left } else { 0 };
            for e in lo..=left {
                let mut w = v.clone();
                w.push(e);
                next.push(w);
            }
        }
        out = next;
    }
    out
}

/// Whether the first nonzero entry is positive (or all are zero).
fn canonical(k: impl IntoIterator<Item = i64>) -> bool {
    k.into_iter().find(|x| *x != 0).is_none_or(|x| x > 0)
}

impl Problem {
    fn new(
        system: &System,
        space: &SearchSpace,
        symbolic: &[Var],
        parameters: &[(Var, Rational)],
        h: Expr,
        cond: Option<Vec<(Var, Expr)>>,
    ) -> Result<Self, EngineError> {
        let vars = system.vars().clone();
        let pairs = system.space().pairs();
        let coords: Vec<Var> = pairs
            .iter()
            .filter(|p| vars.variable(p.q).kind() == VarKind::Coordinate)
            .map(|p| p.q)
            .collect();
        // An angle's momentum that the condition fixes (`p_θ = mIω/n`) is a constant there:
        // every function of it is an integral, so it is left out, and so is a Poisson variable
        // that the condition fixes (the flow keeps it, or the condition is refused). Any other
        // momentum counts.
        let fixed = |v: Var| cond.iter().flatten().any(|(w, _)| *w == v);
        let (mut momenta, mut left_out) = (Vec::new(), Vec::new());
        for pair in pairs {
            if vars.variable(pair.q).kind() == VarKind::Angle && fixed(pair.p) {
                left_out.push(pair.p);
            } else {
                momenta.push(pair.p);
            }
        }
        let mut poisson = Vec::new();
        for &v in system.space().poisson_variables() {
            match fixed(v) {
                true => left_out.push(v),
                false => poisson.push(v),
            }
        }
        let angles: Vec<Var> = pairs
            .iter()
            .filter(|p| vars.variable(p.q).kind() == VarKind::Angle)
            .map(|p| p.q)
            .collect();
        let positions = exponent_vectors(coords.len(), space.positions_degree, space.laurent);
        let moms = exponent_vectors(momenta.len(), space.momenta_degree, false);
        let lie = exponent_vectors(poisson.len(), space.poisson_degree, false);
        let params = exponent_vectors(symbolic.len(), space.parameters_degree, false);
        // The powers `k_i` of the denominators `1/D_i^{k_i}`, stored as the atoms' exponents
        // `−k_i`.
        let atoms = system.space().denominator_atoms();
        let inverses = exponent_vectors(atoms.len(), space.denominators_degree, false);
        let ks: Vec<Vec<i64>> = exponent_vectors(angles.len(), space.trig_degree, true)
            .into_iter()
            .filter(|k| canonical(k.iter().copied()))
            .collect();
        // Each angular vector gives cos and sin, except k = 0.
        let trig_functions: usize = ks
            .iter()
            .map(|k| if k.iter().all(|x| *x == 0) { 1 } else { 2 })
            .sum();
        let count = positions
            .len()
            .saturating_mul(moms.len())
            .saturating_mul(lie.len())
            .saturating_mul(params.len())
            .saturating_mul(inverses.len())
            .saturating_mul(trig_functions);
        let limit = vars.limits().max_terms;
        if count > limit {
            return Err(EngineError::Invalid(format!(
                "the space has {count} unknowns, more than the term limit {limit}: search a \
                 smaller space, or raise the limit (`Limits::max_terms`; on the command line, --max-terms)"
            )));
        }
        // The monomials `φ` without angles, then (with denominators) those whose functions are
        // independent of the simpler ones, then each times the trigonometric functions.
        let mut phases = Vec::with_capacity(count / trig_functions.max(1));
        for (a, c, m, s, d) in itertools::iproduct!(&positions, &moms, &lie, &params, &inverses) {
            let mut phase = vec![0i64; vars.len()];
            for (v, e) in coords
                .iter()
                .chain(&momenta)
                .chain(&poisson)
                .chain(symbolic)
                .zip(a.iter().chain(c).chain(m).chain(s))
            {
                phase[v.index()] = *e;
            }
            for ((v, _), e) in atoms.iter().zip(d) {
                phase[v.index()] = -e;
            }
            phases.push(Unknown {
                phase,
                k: vec![0; angles.len()],
                trig: Trig::One,
                momenta_degree: c.iter().sum(),
                poisson_degree: m.iter().sum(),
                positions_degree: a.iter().map(|x| x.abs()).sum(),
                denominators_degree: d.iter().sum(),
                trig_degree: 0,
                parameters_degree: s.iter().sum(),
            });
        }
        if !atoms.is_empty() {
            phases = independent_as_functions(&vars, atoms, parameters, phases)?;
        }
        let mut unknowns = Vec::with_capacity(phases.len() * trig_functions);
        for phi in phases {
            for k in &ks {
                let trig_degree: i64 = k.iter().map(|x| x.abs()).sum();
                let trigs: &[Trig] = if trig_degree == 0 {
                    &[Trig::One]
                } else {
                    &[Trig::Cos, Trig::Sin]
                };
                for &trig in trigs {
                    unknowns.push(Unknown {
                        k: k.clone(),
                        trig,
                        trig_degree,
                        ..phi.clone()
                    });
                }
            }
        }
        // The order decides which basis comes out: each kernel vector ends at its own unknown
        // and uses only earlier ones, so simpler unknowns come first.
        // A total order (no two unknowns are equal), so the parallel sort is deterministic.
        unknowns.par_sort_unstable_by(|a, b| {
            a.degrees()
                .cmp(&b.degrees())
                .then_with(|| b.k.cmp(&a.k))
                .then_with(|| a.phase.cmp(&b.phase))
                .then_with(|| a.trig.cmp(&b.trig))
        });
        let slots = Problem::slots(&vars, &angles, &unknowns)?;
        let variables = SpaceVariables {
            coordinates: coords,
            momenta,
            poisson,
            angles,
            left_out,
        };
        let mut problem = Problem {
            vars,
            variables,
            unknowns,
            slots,
            h,
            condition: cond,
            flow_parts: Vec::new(),
        };
        let gradient = system.space().gradient(&problem.h)?;
        let canonical = pairs.iter().zip(gradient.canonical());
        let parts = canonical
            .flat_map(|(pair, (dq, dp))| [(pair.q, dp, false), (pair.p, dq, true)])
            .chain(gradient.declared().iter().map(|(v, x)| (*v, x, false)));
        for (v, part, negated) in parts {
            // The declared brackets of an atom hold its polynomial's parameters.
            let part = problem.apply_condition(fix_parameters(part, parameters)?)?;
            if !part.is_zero() {
                problem.flow_parts.push((v, part, negated));
            }
        }
        Ok(problem)
    }

    /// The slot of each monomial of the space: `φ` for each unknown of `k = 0`, and
    /// `φ·e^{±ik·θ}` for each pair `φ cos k·θ`, `φ sin k·θ`.
    fn slots(
        vars: &Vars,
        angles: &[Var],
        unknowns: &[Unknown],
    ) -> Result<MonomialIndex<Slot>, EngineError> {
        let with_angles = |u: &Unknown, sign: i64| {
            let mut e = u.phase.clone();
            for (v, k) in angles.iter().zip(&u.k) {
                e[v.index()] = sign * k;
            }
            e
        };
        let mut slots = MonomialIndex::new(vars);
        for (j, u) in unknowns.iter().enumerate() {
            match u.trig {
                Trig::One => {
                    slots.insert(&u.phase, Slot::One(j))?;
                }
                Trig::Cos => {}
                Trig::Sin => {
                    // The order of the unknowns ends with the trigonometric function: the
                    // cosine of the same `φ` and `k` comes right before.
                    let cos = j - 1;
                    debug_assert!(
                        unknowns[cos].trig == Trig::Cos
                            && unknowns[cos].phase == u.phase
                            && unknowns[cos].k == u.k
                    );
                    slots.insert(&with_angles(u, 1), Slot::Canonical { cos, sin: j })?;
                    slots.insert(&with_angles(u, -1), Slot::Conjugate { cos, sin: j })?;
                }
            }
        }
        Ok(slots)
    }

    /// `{f, H}` after the condition for `f` free of the variables the condition fixes (the
    /// unknowns): `Σ_v ∂f/∂v · {v, H}|_c` (`Σ ∂f/∂q · (∂H/∂p)|_c − ∂f/∂p · (∂H/∂q)|_c` for
    /// canonical pairs), the condition being a ring homomorphism that leaves `f` alone.
    fn image(&self, f: &Expr) -> Result<Expr, EngineError> {
        let products: Vec<(&Expr, Var, &Expr, bool)> = self
            .flow_parts
            .iter()
            .map(|(v, part, negated)| (f, *v, part, *negated))
            .collect();
        if products.is_empty() {
            return Ok(Expr::zero(&self.vars));
        }
        Ok(Expr::sum_of_derivative_products(&products)?)
    }

    /// The unknown as a function.
    fn expr(&self, j: usize, coeff: &Rational) -> Result<Expr, EngineError> {
        let u = &self.unknowns[j];
        let mut plus = u.phase.clone();
        let mut minus = u.phase.clone();
        for (v, k) in self.variables.angles.iter().zip(&u.k) {
            plus[v.index()] += k;
            minus[v.index()] -= k;
        }
        let half = coeff * &Rational::new(1, 2);
        let terms = match u.trig {
            Trig::One => vec![(GaussianRational::from(coeff.clone()), plus)],
            Trig::Cos => vec![
                (GaussianRational::from(half.clone()), plus),
                (GaussianRational::from(half), minus),
            ],
            // sin = (z − z̄)/(2i): coefficients −i/2 at z, i/2 at z̄.
            Trig::Sin => vec![
                (GaussianRational::new(Rational::zero(), -&half), plus),
                (GaussianRational::new(Rational::zero(), half), minus),
            ],
        };
        Ok(Expr::from_terms(&self.vars, terms)?)
    }

    /// The exponents of the `e^{ik·θ}` term of unknown `j` (`k ≥ 0`).
    fn leading_exponents(&self, j: usize) -> Vec<i64> {
        let u = &self.unknowns[j];
        let mut e = u.phase.clone();
        for (v, k) in self.variables.angles.iter().zip(&u.k) {
            e[v.index()] += k;
        }
        e
    }

    /// `Σ v_j φ_j`.
    fn combination(&self, v: &SparseVec<Rational>) -> Result<Expr, EngineError> {
        let mut terms = Vec::new();
        for (j, x) in v {
            let e = self.expr(*j, x)?;
            terms.extend(e.terms().map(|t| (t.coeff(), t.exponents())));
        }
        Ok(Expr::from_terms(&self.vars, terms)?)
    }

    fn apply_condition(&self, e: Expr) -> Result<Expr, EngineError> {
        match &self.condition {
            Some(subs) => Ok(e.subst_many(subs)?),
            None => Ok(e),
        }
    }

    /// `{f, H}` after the condition, at the fixed values.
    fn flow(&self, system: &System, f: &Expr) -> Result<Expr, EngineError> {
        self.apply_condition(system.bracket(f, &self.h)?)
    }

    /// The integrals an integral `f` splits into: its `e^{ik·θ}` components `f_k e^{ik·θ}`,
    /// one per `k`, when `H` does not depend on the angles (the flow then keeps `k`, so each
    /// component is an integral); `f` itself when it does (the components of the energy of a
    /// pendulum, `p²/2` and `e^{±iψ}/2`, are none).
    fn integral_components(&self, f: &Expr) -> Result<Vec<Expr>, EngineError> {
        if self.variables.angles.iter().any(|&a| self.h.contains(a)) {
            return Ok(vec![f.clone()]);
        }
        type Terms = Vec<(GaussianRational, Vec<i64>)>;
        let mut groups: Vec<(Vec<i64>, Terms)> = Vec::new();
        for t in f.terms() {
            let e = t.exponents();
            let k: Vec<i64> = self.variables.angles.iter().map(|v| e[v.index()]).collect();
            match groups.iter_mut().find(|g| g.0 == k) {
                Some(g) => g.1.push((t.coeff(), e)),
                None => groups.push((k, vec![(t.coeff(), e)])),
            }
        }
        groups
            .into_iter()
            .map(|(_, terms)| Ok(Expr::from_terms(&self.vars, terms)?))
            .collect()
    }

    /// The coordinates of a real function in the basis, if it lies in the space.
    fn coordinates(&self, f: &Expr) -> Option<SparseVec<Rational>> {
        let (re, im) = self.coordinates_of_parts(f)?;
        im.is_empty().then_some(re)
    }

    /// The coordinates of the real and of the imaginary part of `f` in the basis, if they lie
    /// in the space (every monomial of `f` is one of the space's), in one pass over the terms
    /// of `f`.
    fn coordinates_of_parts(&self, f: &Expr) -> Option<(SparseVec<Rational>, SparseVec<Rational>)> {
        let [re, im] = self.parts_by_slot(f, |t| {
            let c = t.coeff();
            (c.re, c.im)
        })?;
        Some((sum_by_index(re), sum_by_index(im)))
    }

    /// [`Problem::coordinates_of_parts`] modulo p, with the content of `f` applied to each
    /// coefficient of its primitive part (no rational product per term), as entries in any
    /// order with an index possibly twice (an [`Echelon`] adds them up as they come): `None`
    /// when the content's denominator vanishes modulo p, `Some(None)` outside the space.
    fn coordinates_of_parts_mod_p(&self, f: &Expr) -> Option<Option<[SparseVec<Fp>; 2]>> {
        let content = Fp::from_rational(f.content())?;
        Some(self.parts_by_slot(f, |t| {
            let c = t.primitive_coeff();
            let part = |x| content.mul(&Fp::from_integer(x));
            (part(&c.re), part(&c.im))
        }))
    }

    /// The coordinates of the real and imaginary parts of `f` in a field `F`, given each
    /// term's coefficient `(re, im)` in `F`, as entries in the order of the terms (an index
    /// twice when `f` has both `e^{±ik·θ}` of it); `None` when a monomial of `f` is outside
    /// the space. Where `f` has `a e^{ik·θ} + b e^{−ik·θ}` (times `φ`, `k` canonical), that is
    /// `(a + b) cos k·θ + i(a − b) sin k·θ`: its real part has `Re a + Re b` on the cosine
    /// and `Im b − Im a` on the sine, its imaginary part `Im a + Im b` and `Re a − Re b`.
    fn parts_by_slot<F: Field>(
        &self,
        f: &Expr,
        coeff: impl Fn(&Term<'_, GaussianRational>) -> (F, F),
    ) -> Option<[SparseVec<F>; 2]> {
        let (mut re, mut im) = (
            Vec::with_capacity(2 * f.len()),
            Vec::with_capacity(2 * f.len()),
        );
        let minus = |x: &F| F::zero().sub(x);
        for t in f.terms() {
            let slot = *self.slots.get_term(&t)?;
            let (a, b) = coeff(&t);
            let (cos, sin, conjugate) = match slot {
                Slot::One(j) => {
                    push_nonzero(&mut re, j, a);
                    push_nonzero(&mut im, j, b);
                    continue;
                }
                Slot::Canonical { cos, sin } => (cos, sin, false),
                Slot::Conjugate { cos, sin } => (cos, sin, true),
            };
            // a (canonical side) or b (conjugate side): the signs above.
            let (re_sin, im_sin) = if conjugate {
                (b.clone(), minus(&a))
            } else {
                (minus(&b), a.clone())
            };
            push_nonzero(&mut re, cos, a);
            push_nonzero(&mut re, sin, re_sin);
            push_nonzero(&mut im, cos, b);
            push_nonzero(&mut im, sin, im_sin);
        }
        Some([re, im])
    }
}

/// The real equations of an image `{φ, H}` (or, for the denominators, of a function), as a
/// column: a row for the real and for the imaginary part of each monomial with a canonical
/// `e^{ik·θ}` (`k ≥ 0`), numbered as they first appear in `rows`. Right for real functions,
/// whose other coefficients are the conjugates of these.
fn real_rows(
    e: &Expr,
    angles: &[Var],
    rows: &mut MonomialIndex<[Option<usize>; 2]>,
    nrows: &mut usize,
) -> SparseVec<Rational> {
    let mut col = Vec::new();
    for t in e.terms() {
        if !canonical(angles.iter().map(|v| t.exponent(*v))) {
            continue;
        }
        let c = t.coeff();
        let row = rows
            .get_or_insert_with_term(&t, || [None, None])
            .expect("the rows have the function's variables");
        for (part, x) in [c.re, c.im].into_iter().enumerate() {
            if x.is_zero() {
                continue;
            }
            let r = *row[part].get_or_insert_with(|| {
                *nrows += 1;
                *nrows - 1
            });
            col.push((r, x));
        }
    }
    col
}

/// With denominator atoms the monomials of the space are not independent functions
/// (`x/(x − y) − y/(x − y) = 1`): the monomials `φ` (without angles) whose functions are
/// independent of the simpler ones before them, in the order of [`Unknown::degrees`], decided
/// exactly on their images under one [`Clearing`], which is injective. The space they span is
/// the whole space's, and each of its functions has one set of coordinates in them. Each
/// denominator must be free of the angles, so that the same monomials are independent times
/// any `cos k·θ` or `sin k·θ`. When every denominator is a polynomial in the coordinates (and
/// parameters fixed for the linear algebra), clearing commutes with a factor in the momenta,
/// the Poisson variables and the symbolic parameters, and the monomials of each such factor
/// are compared among themselves only: the choice is made once, on the monomials in the
/// coordinates and the denominators alone, in the same order.
fn independent_as_functions(
    vars: &Vars,
    atoms: &[(Var, Expr)],
    parameters: &[(Var, Rational)],
    mut phases: Vec<Unknown>,
) -> Result<Vec<Unknown>, EngineError> {
    if let Some((v, _)) = atoms
        .iter()
        .find(|(_, d)| vars.angles().any(|a| d.contains(a)))
    {
        return Err(EngineError::Invalid(format!(
            "the search takes denominators free of the angles, and {} has one",
            vars.variable(*v).unicode()
        )));
    }
    let kind = |v: Var| vars.variable(v).kind();
    let in_coordinates = atoms.iter().all(|(_, d)| {
        vars.vars()
            .filter(|&v| d.contains(v))
            .all(|v| matches!(kind(v), VarKind::Coordinate | VarKind::Parameter))
    });
    // The part of a monomial that the choice is made on: without the variables listed here.
    let apart: Vec<usize> = match in_coordinates {
        true => vars
            .vars()
            .filter(|&v| !matches!(kind(v), VarKind::Coordinate | VarKind::Denominator))
            .map(|v| v.index())
            .collect(),
        false => Vec::new(),
    };
    let part = |u: &Unknown| -> Unknown {
        if !in_coordinates {
            return u.clone();
        }
        let mut phase = u.phase.clone();
        for &i in &apart {
            phase[i] = 0;
        }
        Unknown {
            phase,
            momenta_degree: 0,
            poisson_degree: 0,
            parameters_degree: 0,
            ..u.clone()
        }
    };
    let mut parts: Vec<Unknown> = phases.iter().map(part).collect();
    // Without angles, in the order of the unknowns.
    parts.sort_by(|a, b| {
        a.degrees()
            .cmp(&b.degrees())
            .then_with(|| a.phase.cmp(&b.phase))
    });
    parts.dedup_by(|a, b| a.phase == b.phase);
    let monomials = parts
        .iter()
        .map(|u| Expr::from_terms(vars, vec![(GaussianRational::from(1), u.phase.clone())]))
        .collect::<Result<Vec<Expr>, _>>()?;
    let clearing = Clearing::new(atoms, parameters, monomials.iter())?
        .expect("the space has denominator atoms");
    let mut rows = MonomialIndex::new(vars);
    let mut nrows = 0;
    let columns: Vec<SparseVec<Rational>> = clearing
        .apply_all(&monomials)?
        .iter()
        .map(|e| real_rows(e, &[], &mut rows, &mut nrows))
        .collect();
    let mut span = Echelon::<Rational>::new(nrows);
    let kept: FxHashSet<Vec<i64>> = parts
        .into_iter()
        .zip(&columns)
        .enumerate()
        .filter(|(i, (_, col))| span.extend(*i, col))
        .map(|(_, (u, _))| u.phase)
        .collect();
    phases.retain(|u| kept.contains(&part(u).phase));
    Ok(phases)
}

/// Appends `(j, x)` unless `x` is zero.
fn push_nonzero<F: Field>(v: &mut SparseVec<F>, j: usize, x: F) {
    if !x.is_zero() {
        v.push((j, x));
    }
}

/// The sparse vector of entries `(j, x)` in any order, those of one index added up, zeros
/// dropped.
fn sum_by_index<F: Field>(mut v: SparseVec<F>) -> SparseVec<F> {
    v.sort_unstable_by_key(|x| x.0);
    v.dedup_by(|later, kept| {
        let same = later.0 == kept.0;
        if same {
            kept.1 = kept.1.add(&later.1);
        }
        same
    });
    v.retain(|x| !x.1.is_zero());
    v
}

/// Union–find.
struct Components(Vec<usize>);

impl Components {
    fn find(&mut self, mut a: usize) -> usize {
        while self.0[a] != a {
            self.0[a] = self.0[self.0[a]];
            a = self.0[a];
        }
        a
    }
    fn union(&mut self, a: usize, b: usize) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            self.0[ra.max(rb)] = ra.min(rb);
        }
    }
}

/// Refuses values fixed for what is no parameter, and parameters to keep symbolic that are no
/// parameters or are also fixed to a value (a search's and a closure's `fixed`, `symbolic`).
pub(crate) fn check_parameters(
    vars: &Vars,
    symbolic: &[Var],
    fixed: &[(Var, Rational)],
) -> Result<(), EngineError> {
    if let Some((v, _)) = fixed
        .iter()
        .find(|(v, _)| vars.variable(*v).kind() != VarKind::Parameter)
    {
        return Err(EngineError::Invalid(format!(
            "only parameters are given values for the linear algebra, and {} is not one (a \
             condition sets a variable)",
            vars.variable(*v).name()
        )));
    }
    for &v in symbolic {
        let name = vars.variable(v).name();
        if vars.variable(v).kind() != VarKind::Parameter {
            return Err(EngineError::Invalid(format!(
                "only parameters can be kept symbolic, and {name} is not one"
            )));
        }
        if fixed.iter().any(|f| f.0 == v) {
            return Err(EngineError::Invalid(format!(
                "{name} is both fixed to a value and kept symbolic"
            )));
        }
    }
    Ok(())
}

/// Every parameter of `h` or of the condition that is neither kept symbolic nor set by the
/// condition, with its value (given, or 1).
fn parameter_values(
    system: &System,
    condition: Option<&Condition>,
    given: &[(Var, Rational)],
    symbolic: &[Var],
) -> Vec<(Var, Rational)> {
    let vars = system.vars();
    let mut exprs = vec![system.hamiltonian().clone()];
    // An atom's polynomial enters the bracket through its declared brackets.
    exprs.extend(
        system
            .space()
            .denominator_atoms()
            .iter()
            .map(|a| a.1.clone()),
    );
    if let Some(c) = condition {
        exprs.extend(c.subs().iter().map(|s| s.1.clone()));
    }
    let mut out: Vec<(Var, Rational)> = Vec::new();
    for v in vars.vars() {
        let set_by_condition = condition.is_some_and(|c| c.subs().iter().any(|s| s.0 == v));
        if vars.variable(v).kind() != VarKind::Parameter
            || symbolic.contains(&v)
            || set_by_condition
        {
            continue;
        }
        let value = given.iter().find(|g| g.0 == v).map(|g| g.1.clone());
        if value.is_some() || exprs.iter().any(|e| e.contains(v)) {
            out.push((v, value.unwrap_or_else(Rational::one)));
        }
    }
    out
}

/// The search's problem with the parameters at `parameters`, in `H` and in the condition.
fn fixed_problem(
    system: &System,
    options: &SearchOptions,
    parameters: &[(Var, Rational)],
) -> Result<Problem, EngineError> {
    let h = fix_parameters(system.hamiltonian(), parameters)?;
    let condition = match &options.condition {
        Some(c) => Some(
            c.subs()
                .iter()
                .map(|(v, e)| Ok((*v, fix_parameters(e, parameters)?)))
                .collect::<Result<Vec<_>, EngineError>>()?,
        ),
        None => None,
    };
    Problem::new(
        system,
        &options.space,
        &options.symbolic,
        parameters,
        h,
        condition,
    )
}

/// Substitutes parameter values.
pub fn fix_parameters(e: &Expr, values: &[(Var, Rational)]) -> Result<Expr, EngineError> {
    let vars = e.vars();
    let subs: Vec<(Var, Expr)> = values
        .iter()
        .map(|(v, x)| (*v, Expr::constant(vars, GaussianRational::from(x.clone()))))
        .collect();
    Ok(e.subst_many(&subs)?)
}

/// The entry of `v` at its last unknown, its lead: a kernel vector ends at its own unknown, and
/// uses only earlier ones.
fn lead<F>(v: &SparseVec<F>) -> Option<&(usize, F)> {
    v.iter().max_by_key(|x| x.0)
}

/// The vector scaled to coprime integers, its last (leading) entry positive.
fn primitive_vector(v: &SparseVec<Rational>) -> SparseVec<Rational> {
    let mut den = trigpoly::Integer::from(1);
    let mut num = trigpoly::Integer::from(0);
    for (_, x) in v {
        den = den.lcm(&x.denom());
        num = num.gcd(&x.numer());
    }
    let negative = lead(v).is_some_and(|l| l.1.sign() == std::cmp::Ordering::Less);
    let mut scale = Rational::from(den) / Rational::from(num);
    if negative {
        scale = -scale;
    }
    v.iter().map(|(j, x)| (*j, x * &scale)).collect()
}

/// Finds a basis of every integral of `system` in the space of `options`: each element of
/// [`SearchResult::basis`] is an [`Integral`], its function [`Integral::expr`], proved.
///
/// ```
/// use brackets::{search, systems, SearchOptions, SearchSpace};
///
/// // The harmonic rotor at the resonance p_θ = Iω: the integrals of degree ≤ 1 in the momenta
/// // and in the positions, of trigonometric order ≤ 1, are 1, L and the four components of
/// // the two linear integrals Z e^{−iθ} and W e^{−iθ} (docs/results.md, section 1.1).
/// let rotor = systems::harmonic_rotor();
/// let resonance = rotor.resonance(1, 1)?;
/// let options = SearchOptions::new(SearchSpace::new(1, 1, 1)).when(resonance.clone());
/// let found = search(&rotor, &options)?;
/// assert_eq!(found.basis.len(), 6);
/// for integral in &found.basis {
///     assert!(rotor.flow_when(integral.expr(), &resonance)?.is_zero());
/// }
/// # Ok::<(), brackets::EngineError>(())
/// ```
pub fn search(system: &System, options: &SearchOptions) -> Result<SearchResult, EngineError> {
    // The search hands blocks of work to rayon's pool (images, blocks of equations, proofs):
    // it runs on a thread of the pool, which takes its share of each and, on a pool of one
    // thread, does it in place, where any other thread would wait for the pool's at each.
    if rayon::current_thread_index().is_none() {
        return rayon::scope(|_| search(system, options));
    }
    let start = Instant::now();
    let mut timings = SearchTimings::default();
    let condition = options.condition.as_ref();
    // A parameter named twice is kept symbolic once.
    let options = &SearchOptions {
        symbolic: options.symbolic.iter().copied().unique().collect(),
        ..options.clone()
    };
    if let Some(c) = condition {
        c.kept_by_flow(system)?;
    }
    let vars = system.vars();
    check_parameters(vars, &options.symbolic, &options.fixed)?;
    let atoms = system.space().denominator_atoms();
    if !atoms.is_empty() && options.new_only {
        return Err(EngineError::Invalid(
            "on a system with denominators the search finds a basis of the integrals, but not \
             yet which of them are new (SearchOptions::new_only; --new-only): search without it"
                .into(),
        ));
    }
    // A denominator free of the parameters kept symbolic makes the choice of independent
    // monomials the same for each multiple by a parameter monomial, which the parameter
    // multiples of integrals need.
    if let Some((v, p)) = atoms.iter().find_map(|(v, d)| {
        options
            .symbolic
            .iter()
            .find(|p| d.contains(**p))
            .map(|p| (v, p))
    }) {
        return Err(EngineError::Invalid(format!(
            "the denominator {} holds {}, kept symbolic: the search keeps symbolic only \
             parameters that no denominator holds; fix it instead (--fix)",
            vars.variable(*v).unicode(),
            vars.variable(*p).unicode()
        )));
    }
    // The unknowns are the real coefficients of real functions, and the equations only the
    // coefficients of `e^{ik·θ}` with `k ≥ 0`: right when `{F, H}` is real, that is when `H`
    // and the condition's values are.
    if !system.hamiltonian().is_real() {
        return Err(EngineError::Invalid(
            "the search finds the real integrals of a real Hamiltonian, and H is not real \
             (it differs from its conjugate)"
                .into(),
        ));
    }
    if let Some(c) = &options.condition {
        if let Some((v, _)) = c.subs().iter().find(|(_, value)| !value.is_real()) {
            return Err(EngineError::Invalid(format!(
                "the search needs a real condition, and the value of {} is not real",
                vars.variable(*v).name()
            )));
        }
    }
    // A parameter the condition sets takes its value from the condition (after the bracket,
    // like a resonance): fixing it first would search at another value.
    if let Some(c) = &options.condition {
        for (v, _) in c.subs() {
            let name = vars.variable(*v).name();
            if options.fixed.iter().any(|f| f.0 == *v) || options.symbolic.contains(v) {
                return Err(EngineError::Invalid(format!(
                    "{name} is set by the condition; it can be neither fixed nor kept symbolic"
                )));
            }
        }
    }
    let parameters = parameter_values(system, condition, &options.fixed, &options.symbolic);
    let problem = fixed_problem(system, options, &parameters)?;
    let n = problem.unknowns.len();

    // The images {φ_j, H} as real equations over Q: a row for the real and for the imaginary
    // part of each monomial with a canonical `e^{ik·θ}`, numbered as they first appear. The
    // images are formed on the pool's threads, a block of unknowns at a time, and numbered in
    // the order of the unknowns.
    // With denominator atoms the images are taken through one injective `Clearing`, whose
    // powers are the highest among all the images: formed in one block.
    let block = if atoms.is_empty() {
        IMAGE_BLOCK
    } else {
        n.max(1)
    };
    let mut rows: MonomialIndex<[Option<usize>; 2]> = MonomialIndex::new(&problem.vars);
    let mut nrows = 0;
    let mut columns: Vec<SparseVec<Rational>> = Vec::with_capacity(n);
    for start in (0..n).step_by(block) {
        let images: Vec<Result<Expr, EngineError>> = (start..n.min(start + block))
            .into_par_iter()
            .map(|j| problem.image(&problem.expr(j, &Rational::one())?))
            .collect();
        let mut images = images.into_iter().collect::<Result<Vec<Expr>, _>>()?;
        if let Some(clearing) = Clearing::new(atoms, &parameters, images.iter())? {
            images = clearing.apply_all(&images)?;
        }
        for image in &images {
            columns.push(real_rows(
                image,
                &problem.variables.angles,
                &mut rows,
                &mut nrows,
            ));
        }
    }
    timings.equations = start.elapsed().as_secs_f64();

    // Connected components.
    let t = Instant::now();
    let mut uf = Components((0..n).collect());
    let mut first_col: Vec<Option<usize>> = vec![None; nrows];
    for (j, col) in columns.iter().enumerate() {
        for (r, _) in col {
            match first_col[*r] {
                Some(f) => uf.union(f, j),
                None => first_col[*r] = Some(j),
            }
        }
    }
    let mut groups: FxHashMap<usize, Vec<usize>> = FxHashMap::default();
    for j in 0..n {
        let r = uf.find(j);
        groups.entry(r).or_default().push(j);
    }
    let mut groups: Vec<Vec<usize>> = groups.into_values().collect();
    groups.sort();
    let largest_component = groups.iter().map(Vec::len).max().unwrap_or(0);
    // The blocks are independent: solved on the pool's threads, kept in the order of the blocks.
    let kernels: Vec<Vec<SparseVec<Rational>>> = groups
        .par_iter()
        .map(|g| {
            let mut local_row: FxHashMap<usize, usize> = FxHashMap::default();
            let cols: Vec<SparseVec<Rational>> = g
                .iter()
                .map(|&j| {
                    columns[j]
                        .iter()
                        .map(|(r, x)| {
                            let len = local_row.len();
                            (*local_row.entry(*r).or_insert(len), x.clone())
                        })
                        .collect()
                })
                .collect();
            modular::kernel(&cols, local_row.len())
                .into_iter()
                .map(|v| v.into_iter().map(|(i, x)| (g[i], x)).collect())
                .collect()
        })
        .collect();
    let mut kernel: Vec<SparseVec<Rational>> = kernels.into_iter().flatten().collect();
    // By leading (last) unknown, i.e. by the order of the unknowns.
    kernel.sort_by_key(|v| lead(v).map_or(0, |l| l.0));
    timings.solve = t.elapsed().as_secs_f64();

    // Proofs: at the fixed values, then lifted and proved symbolically.
    let t = Instant::now();
    let scaling = Scaling::of_flow(system.space(), system.hamiltonian(), condition)?;
    let lifter = scaling.lifter(&parameters);
    // Each basis element is proved on its own, on the pool's threads; the first error in
    // the order of the basis is the one reported.
    let proved: Vec<Result<Integral, EngineError>> = kernel
        .par_iter_mut()
        .map(|v| {
            *v = primitive_vector(v);
            let fixed = problem.combination(v)?;
            let proved_fixed = problem.flow(system, &fixed)?.vanishes()?;
            let last = lead(v).expect("a kernel vector is not zero").0;
            let reference = problem.leading_exponents(last);
            let symbolic = match &lifter {
                // Nothing was fixed: the integral found is the symbolic one.
                _ if parameters.is_empty() => proved_fixed.then(|| fixed.clone()),
                Some(l) => {
                    lift_and_prove(system, condition, l, &scaling, &fixed, Some(&reference))?
                }
                None => None,
            };
            // What the weights cannot lift may hold as found, for every value: `p_θ`, or `L`
            // of a potential whose parameter the lift cannot restore.
            let symbolic = match symbolic {
                None if proved_fixed && !parameters.is_empty() => {
                    flow_vanishes(system, condition, &fixed)?.then(|| fixed.clone())
                }
                found => found,
            };
            let deg = |kinds: &[VarKind]| fixed.total_degree(kinds).unwrap_or(0);
            Ok(Integral {
                // Every momentum of the space (an angle's momentum fixed by the condition
                // does not occur).
                momenta_degree: deg(&[VarKind::Momentum]),
                poisson_degree: deg(&[VarKind::Poisson]),
                positions_degree: deg(&[VarKind::Coordinate]),
                trig_degree: deg(&[VarKind::Angle]),
                fixed,
                proved_fixed,
                symbolic,
            })
        })
        .collect();
    let basis = proved.into_iter().collect::<Result<Vec<_>, _>>()?;
    timings.proofs = t.elapsed().as_secs_f64();

    let multiples = parameter_multiples(&problem, &options.symbolic, &basis)?;
    let t = Instant::now();
    let new = if options.new_only {
        Some(new_integrals(
            system,
            &problem,
            options,
            &parameters,
            &kernel,
            &basis,
            &multiples,
        )?)
    } else {
        None
    };
    timings.new_only = t.elapsed().as_secs_f64();
    let module = (!options.symbolic.is_empty()).then(|| ParameterModule {
        parameters: options.symbolic.clone(),
        generators: module_generators(&problem, &kernel, &multiples),
    });
    timings.total = start.elapsed().as_secs_f64();
    Ok(SearchResult {
        space: options.space,
        condition: condition.map(|c| c.text.clone()),
        parameters,
        liftable: lifter.is_some(),
        vars: system.vars().clone(),
        variables: problem.variables.clone(),
        unknowns: n,
        equations: nrows,
        components: groups.len(),
        largest_component,
        basis,
        new,
        module,
        timings,
    })
}

/// The multiples `a·I` that lie in the space, for `a` a symbolic parameter and `I` a basis
/// integral: each with the index of `I` and its coordinates. Their span is every sum of
/// parameter multiples of integrals in the space, since a product by a monomial of higher
/// degree is a product by one parameter of an integral that lies in the space.
fn parameter_multiples(
    problem: &Problem,
    symbolic: &[Var],
    basis: &[Integral],
) -> Result<Vec<(usize, SparseVec<Rational>)>, EngineError> {
    let mut out = Vec::new();
    for (i, f) in basis.iter().enumerate() {
        for &a in symbolic {
            let product = f.fixed.checked_mul(&Expr::var(&problem.vars, a))?;
            out.extend(problem.coordinates(&product).map(|v| (i, v)));
        }
    }
    Ok(out)
}

/// The basis integrals that generate the space over the polynomials in the symbolic
/// parameters: those outside the span of the parameter `multiples` and of the earlier
/// generators.
fn module_generators(
    problem: &Problem,
    kernel: &[SparseVec<Rational>],
    multiples: &[(usize, SparseVec<Rational>)],
) -> Vec<usize> {
    let mut span = Echelon::<Rational>::new(problem.unknowns.len());
    for (id, (_, v)) in multiples.iter().enumerate() {
        span.insert(id, v);
    }
    (0..kernel.len())
        .filter(|&k| span.insert(multiples.len() + k, &kernel[k]).is_none())
        .collect()
}

/// Lifts an integral found at fixed values and proves `{F, H} = 0` symbolically (after the
/// condition); `None` if the lift does not exist or is not an integral.
pub fn lift_and_prove(
    system: &System,
    condition: Option<&Condition>,
    lifter: &Lifter,
    scaling: &Scaling,
    fixed: &Expr,
    reference: Option<&[i64]>,
) -> Result<Option<Expr>, EngineError> {
    let Some(f) = lifter.lift(scaling, fixed, reference)? else {
        return Ok(None);
    };
    // Coprime integer coefficients again (fixed values other than 1 leave a common factor).
    let f = real_primitive(&f);
    Ok(flow_vanishes(system, condition, &f)?.then_some(f))
}

/// Whether `{f, H} = 0` for every value of the parameters (after the condition).
fn flow_vanishes(
    system: &System,
    condition: Option<&Condition>,
    f: &Expr,
) -> Result<bool, EngineError> {
    let flow = match condition {
        Some(c) => system.flow_when(f, c)?,
        None => system.flow(f)?,
    };
    Ok(flow.vanishes()?)
}

/// A real function scaled so that its coefficients in the basis `cos kθ, sin kθ` are coprime
/// integers (the sign kept): in the `e^{ikθ}` basis those are twice the coefficients of
/// `e^{±ikθ}` for `k ≠ 0`.
fn real_primitive(f: &Expr) -> Expr {
    let vars = f.vars();
    let angles: Vec<Var> = vars.angles().collect();
    let mut g = Rational::zero();
    for t in f.terms() {
        let c = t.coeff();
        let factor = if angles.iter().any(|v| t.exponent(*v) != 0) {
            Rational::from(2)
        } else {
            Rational::one()
        };
        for x in [&c.re, &c.im] {
            if !x.is_zero() {
                g = Rational::content_gcd(&g, &(x * &factor));
            }
        }
    }
    match g.abs().try_inv() {
        Some(inv) => f.scale_rational(&inv),
        None => f.clone(),
    }
}

/// A function times the least monomial in the `symbolic` parameters that leaves none of them
/// with a negative exponent (`G1 = p_x p_y/(2M) + …` becomes `M·G1`).
fn without_parameter_denominators(f: &Expr, symbolic: &[Var]) -> Result<Expr, EngineError> {
    let vars = f.vars();
    let mut exps = vec![0i64; vars.len()];
    for &a in symbolic {
        let lowest = f.terms().map(|t| t.exponent(a)).min().unwrap_or(0);
        exps[a.index()] = (-lowest).max(0);
    }
    if exps.iter().all(|e| *e == 0) {
        return Ok(f.clone());
    }
    let monomial = Expr::from_terms(vars, vec![(GaussianRational::from(1), exps)])?;
    Ok(f.checked_mul(&monomial)?)
}

/// Whether `e` depends on no variable of phase space (parameters only, or a number).
pub(crate) fn is_phase_free(e: &Expr) -> bool {
    let vars = e.vars();
    vars.vars()
        .filter(|v| vars.variable(*v).kind() != VarKind::Parameter)
        .all(|v| !e.contains(v))
}

fn new_integrals(
    system: &System,
    problem: &Problem,
    options: &SearchOptions,
    parameters: &[(Var, Rational)],
    kernel: &[SparseVec<Rational>],
    basis: &[Integral],
    multiples: &[(usize, SparseVec<Rational>)],
) -> Result<NewIntegrals, EngineError> {
    let (space, extra, symbolic) = (&options.space, &options.known, &options.symbolic);
    // Known integrals: named real functions that are integrals, restricted to the condition.
    let mut known_names = Vec::new();
    let mut known: Vec<(Expr, SparseVec<Rational>)> = Vec::new();
    let named = system
        .functions()
        .iter()
        .map(|f| (f.display.clone(), f.expr.clone()));
    // The system's functions that are no real integrals are left out; a known integral given
    // as one that is not is an error, not a silence.
    let named = named.map(|(name, f)| (name, f, false));
    let given = extra
        .iter()
        .map(|(name, f)| (name.clone(), f.clone(), true));
    for (name, f, given) in named.chain(given) {
        if !f.is_real() {
            if given {
                return Err(EngineError::Invalid(format!(
                    "the known integral {name} is not real: give its real and imaginary parts, \
                     re({name}) and im({name})"
                )));
            }
            continue;
        }
        let fv = fix_parameters(&f, parameters)?;
        let flow = problem.flow(system, &fv)?;
        if !flow.is_zero() {
            if given {
                return Err(not_an_integral(&name, &flow, options, parameters));
            }
            continue;
        }
        let restricted = without_parameter_denominators(&problem.apply_condition(fv)?, symbolic)?;
        // A constant on phase space (`Ω = ω` at a resonance) is no integral worth naming.
        if is_phase_free(&restricted) || known.iter().any(|k| k.0 == restricted) {
            continue;
        }
        if let Some(v) = problem.coordinates(&restricted) {
            known_names.push(name);
            known.push((restricted, v));
        }
    }
    // The filtration by grade ([`Grading`]): an integral of grade g is generated when it lies
    // in the span of the known integrals, the constants, the products of at least two
    // integrals of grade < g (known or found) and the parameter multiples of integrals of
    // grade ≤ g.
    let grading = Grading::new(&problem.variables, space.trig_degree);
    let sources = known
        .iter()
        .map(|k| &k.0)
        .chain(basis.iter().map(|b| &b.fixed));
    let gens = generators(problem, &grading, sources)?;
    let bounds = Size {
        momenta: space.momenta_degree.into(),
        coordinates: space.positions_degree.into(),
        poisson: space.poisson_degree.into(),
        angles_alone: space.trig_degree.into(),
    };
    let grades: Vec<i64> = basis.iter().map(|b| grading.grade(&b.fixed)).collect();
    let dim = problem.unknowns.len();
    let leads = Leads::of(kernel, dim);
    let generated = |exact: bool| {
        let span = Stamped::new(&leads, exact);
        // The known integrals and the constants, then the products; with parameters kept
        // symbolic, `a·I` is generated by `I`: it joins the span before the basis integrals of
        // `I`'s grade. `None` when a denominator vanishes modulo p.
        let mut vectors: Vec<(i64, SparseVec<Rational>)> =
            known.iter().map(|k| (-1, k.1.clone())).collect();
        if let Some(&Slot::One(j)) = problem.slots.get(&vec![0; problem.vars.len()]) {
            vectors.push((-1, vec![(j, Rational::one())]));
        }
        vectors.extend(multiples.iter().map(|(i, v)| (grades[*i] - 1, v.clone())));
        let limits = (kernel.len(), options.max_products);
        span_of_products(problem, &gens, vectors, bounds, space.laurent, span, limits)
    };
    // By increasing grade g: the products of factors of grade < g join the span, then each
    // basis integral of grade g is new unless it lies in the span (of those and of the new
    // ones so far).
    let mut order: Vec<usize> = (0..basis.len()).collect();
    order.sort_by_key(|&k| (grades[k], k));
    let decide = |exact: bool, spanning: &[(i64, SparseVec<Rational>)]| -> Option<Vec<usize>> {
        let mut fp = Echelon::<Fp>::new(leads.count);
        let mut q = Echelon::<Rational>::new(dim);
        // Vectors by identifier, for checking dependencies exactly.
        let mut inserted: Vec<&SparseVec<Rational>> = Vec::new();
        let mut next_span = 0;
        let mut new = Vec::new();
        for &k in &order {
            while next_span < spanning.len() && spanning[next_span].0 < grades[k] {
                let v = &spanning[next_span].1;
                if exact {
                    q.extend(inserted.len(), v);
                } else {
                    fp.extend(inserted.len(), &leads.restrict(modular::to_fp(v)?));
                }
                inserted.push(v);
                next_span += 1;
            }
            let v = &kernel[k];
            let id = inserted.len();
            inserted.push(v);
            if exact {
                if q.insert(id, v).is_none() {
                    new.push(k);
                }
                continue;
            }
            match fp.insert(id, &leads.restrict(modular::to_fp(v)?)) {
                None => new.push(k),
                Some(dep) => {
                    // A dependency is checked over Q. Independence modulo p is independence
                    // over Q unless p divides a minor of the span (its rank then drops
                    // modulo p): `exact_complement` rules that out.
                    let coeffs = modular::reconstruct_vec(&dep)?;
                    let mut acc: FxHashMap<usize, Rational> = FxHashMap::default();
                    for (id, c) in &coeffs {
                        for (i, x) in inserted[*id] {
                            *acc.entry(*i).or_insert_with(Rational::zero) += c * x;
                        }
                    }
                    for (i, x) in v {
                        *acc.entry(*i).or_insert_with(Rational::zero) -= x;
                    }
                    if acc.values().any(|x| !x.is_zero()) {
                        return None;
                    }
                }
            }
        }
        new.sort_unstable();
        Some(new)
    };
    // Modulo p first (unless asked for Q alone); over Q when a denominator vanishes modulo p
    // or a dependency found modulo p does not hold over Q.
    let modular = match options.exact_complement {
        false => generated(false)?,
        true => None,
    };
    let (new, products) = match modular.and_then(|(span, n)| Some((decide(false, &span)?, n))) {
        Some(found) => found,
        None => {
            let (span, n) = generated(true)?.expect("the span over Q always forms");
            (
                decide(true, &span).expect("exact elimination always decides"),
                n,
            )
        }
    };
    Ok(NewIntegrals {
        known: known_names,
        generated: basis.len() - new.len(),
        new,
        products,
    })
}

/// The error for a known integral `name` whose bracket with `H` is `flow`, not zero: the
/// bracket (or its size, when long) and where it was taken, under the condition and at the
/// fixed values, where it may vanish only.
fn not_an_integral(
    name: &str,
    flow: &Expr,
    options: &SearchOptions,
    parameters: &[(Var, Rational)],
) -> EngineError {
    let shown = flow.render(Style::Unicode);
    let bracket = match shown.chars().count() {
        0..=200 => format!("{{{name}, H}} = {shown}"),
        _ => format!("{{{name}, H}} ≠ 0 ({} terms)", flow.len()),
    };
    let at: Vec<String> = options
        .condition
        .iter()
        .map(|c| c.text.clone())
        .chain(
            (!parameters.is_empty())
                .then(|| parameter_text(flow.vars(), parameters, Style::Unicode)),
        )
        .collect();
    let at = match at.is_empty() {
        true => String::new(),
        false => format!(" at {}", at.join(", ")),
    };
    EngineError::Invalid(format!(
        "the known integral {name} is not an integral: {bracket}{at}"
    ))
}

/// Fixed values of parameters as they read, `M = 1, ω = 1` (in `Style::Ascii`, with the ASCII
/// names superint reads back: `M = 1, omega = 1`).
pub fn parameter_text(vars: &VarSet, values: &[(Var, Rational)], style: Style) -> String {
    values
        .iter()
        .map(|(v, x)| {
            let variable = vars.variable(*v);
            let name = match style {
                Style::Ascii => variable.name(),
                _ => variable.unicode(),
            };
            format!("{name} = {x}")
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The filtration by which `--new-only` counts an integral generated. A function's grade is
/// the largest of its terms' `(degree, order)`, lexicographically: the total degree `Σ|a|` in
/// the coordinates, momenta and Poisson variables first, then the trigonometric order `Σ|k|`. The functions of
/// grade `≤ g` form a space, and a product's grade is at most the sum of its factors' (degrees
/// add up, `|k + k'| ≤ |k| + |k'|`, and sums keep the lexicographic order): a filtration of
/// the algebra, in which a function of the angles alone has degree 0 and is told apart by its
/// order (`cos 2(a − b) = 2cos²(a − b) − 1` lies above `cos(a − b)`, and
/// `p_b cos(a − b)` above both factors).
///
/// A grade is numbered by its place in that order: in a space of trigonometric order `≤ K`,
/// `(d, t)` is `d(K + 1) + t`, and a number less one stands just below its grade. Without
/// angles the numbers order by degree alone.
struct Grading {
    /// The coordinates, the momenta and the Poisson variables, whose total degree comes first.
    degree_variables: Vec<Var>,
    angles: Vec<Var>,
    /// How many trigonometric orders the space has, `K + 1`.
    orders: i64,
}

impl Grading {
    fn new(variables: &SpaceVariables, trig_degree: u32) -> Self {
        Grading {
            degree_variables: [
                &variables.coordinates[..],
                &variables.momenta[..],
                &variables.poisson[..],
            ]
            .concat(),
            angles: variables.angles.clone(),
            orders: i64::from(trig_degree) + 1,
        }
    }

    /// The number of the grade of `f`, a function of the space (0 for a constant).
    fn grade(&self, f: &Expr) -> i64 {
        let total = |t: &Term<'_, GaussianRational>, vars: &[Var]| -> i64 {
            vars.iter().map(|&v| t.exponent(v).abs()).sum()
        };
        f.terms()
            .map(|t| total(&t, &self.degree_variables) * self.orders + total(&t, &self.angles))
            .max()
            .unwrap_or(0)
    }
}

/// What a factor takes of the space's bounds, added up over a product's factors: its degrees
/// in the momenta, in the coordinates and in the Poisson variables and, for a function of the
/// angles alone, its trigonometric order. A factor of positive degree takes no order, since the orders of such
/// factors cancel in products (`Z e^{−iθ}·W̄ e^{iθ}` has order 0), and their degrees bound how
/// many fit; the orders bound how many of the angles alone do (`cos(a − b)ⁿ`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Size {
    momenta: i64,
    coordinates: i64,
    poisson: i64,
    angles_alone: i64,
}

impl Size {
    /// Past every bound: the least size of no generator.
    const UNBOUNDED: Size = Size {
        momenta: i64::MAX,
        coordinates: i64::MAX,
        poisson: i64::MAX,
        angles_alone: i64::MAX,
    };

    fn of(f: &Expr) -> Self {
        let degree = |kind: VarKind| f.total_degree(&[kind]).unwrap_or(0);
        let (momenta, coordinates, poisson) = (
            degree(VarKind::Momentum),
            degree(VarKind::Coordinate),
            degree(VarKind::Poisson),
        );
        let angles_alone = match momenta == 0 && coordinates == 0 && poisson == 0 {
            true => degree(VarKind::Angle),
            false => 0,
        };
        Size {
            momenta,
            coordinates,
            poisson,
            angles_alone,
        }
    }

    /// Whether it has a positive degree (a factor that is no function of the angles alone).
    fn has_degree(&self) -> bool {
        self.momenta > 0 || self.coordinates > 0 || self.poisson > 0
    }

    /// The sum of each (saturating: an unbounded least size stays unbounded).
    fn plus(self, other: Size) -> Size {
        Size {
            momenta: self.momenta.saturating_add(other.momenta),
            coordinates: self.coordinates.saturating_add(other.coordinates),
            poisson: self.poisson.saturating_add(other.poisson),
            angles_alone: self.angles_alone.saturating_add(other.angles_alone),
        }
    }

    /// The least of each.
    fn min(self, other: Size) -> Size {
        Size {
            momenta: self.momenta.min(other.momenta),
            coordinates: self.coordinates.min(other.coordinates),
            poisson: self.poisson.min(other.poisson),
            angles_alone: self.angles_alone.min(other.angles_alone),
        }
    }
}

/// A generator of what is generated: an integral, or an `e^{ik·θ}` component of one when `H`
/// does not depend on the angles (each component is then an integral, since the flow keeps
/// `k`; see [`Problem::integral_components`]), made monic. Complex components multiply
/// without the cancellations of real ones (`Re(J Q̄)` lies in the space when `Re J · Re Q`
/// does not).
struct Generator {
    expr: Expr,
    /// What it takes of the space's bounds in a product.
    size: Size,
    /// The least grade ([`Grading`]) of an integral it is a component of: products count from
    /// the largest stamp of their factors on.
    stamp: i64,
}

/// The generators of the integrals `sources` (constants left out), each component once.
fn generators<'a>(
    problem: &Problem,
    grading: &Grading,
    sources: impl IntoIterator<Item = &'a Expr>,
) -> Result<Vec<Generator>, EngineError> {
    let mut gens: Vec<Generator> = Vec::new();
    for f in sources {
        let grade = grading.grade(f);
        if grade == 0 {
            continue;
        }
        for c in problem.integral_components(f)? {
            let Some(lead) = c.terms().next().map(|t| t.coeff()) else {
                continue;
            };
            let c = c.scale(&lead.try_inv().expect("nonzero"));
            match gens.iter_mut().find(|g| g.expr == c) {
                Some(g) => g.stamp = g.stamp.min(grade),
                None => gens.push(Generator {
                    size: Size::of(&c),
                    expr: c,
                    stamp: grade,
                }),
            }
        }
    }
    Ok(gens)
}

/// Vectors, each with the stamp from which it counts.
type StampedVectors = Vec<(i64, SparseVec<Rational>)>;

/// The span of `vectors` (`(stamp, coordinates)`) and of the products of `gens` whose sizes
/// fit `bounds` (the coordinates' degree only unless `laurent`), in `span`: its kept vectors by
/// increasing stamp and how many products were formed, or `None` when a denominator vanishes
/// modulo p. The products stop once the span has `dimension`, that of the integrals, and
/// fail past `max_products`.
fn span_of_products(
    problem: &Problem,
    gens: &[Generator],
    vectors: StampedVectors,
    bounds: Size,
    laurent: bool,
    mut span: Stamped,
    (dimension, max_products): (usize, usize),
) -> Result<Option<(StampedVectors, usize)>, EngineError> {
    let products = Spanning {
        problem,
        bounds,
        laurent,
        dimension,
        span: &mut span,
        formed: 0,
        max_products,
    }
    .run(gens, vectors)?;
    Ok(products.map(|n| (span.into_vectors(), n)))
}

/// The products of at least two generators whose sizes fit (degrees in the momenta and,
/// without negative powers, in the coordinates add up, and so do the orders of the functions
/// of the angles alone), each monomial once (non-decreasing indices), stamped with the largest
/// stamp of its factors, formed by increasing stamp: the real and imaginary parts of those
/// that lie in the space join the span, after the given vectors of stamps up to theirs.
/// Everything in the span is an integral of the space (products of integrals are integrals),
/// so once the span has the dimension of the integrals, every integral is generated from that
/// stamp on and no more products are formed.
struct Spanning<'a, 's> {
    problem: &'a Problem,
    bounds: Size,
    laurent: bool,
    /// The dimension of the space of integrals.
    dimension: usize,
    span: &'a mut Stamped<'s>,
    /// Products formed so far (a prefix formed again in a later stamp's round counts again).
    formed: usize,
    /// The most products to form.
    max_products: usize,
}

/// Why the products stop before the last: the span holds every integral, a denominator
/// vanishes modulo p, or an error.
enum Stop {
    Spanned,
    NotModular,
    Failed(EngineError),
}

impl From<EngineError> for Stop {
    fn from(e: EngineError) -> Self {
        Stop::Failed(e)
    }
}

impl Spanning<'_, '_> {
    /// Forms the products of `gens` and adds them and `vectors` (`(stamp, coordinates)`) to
    /// the span. How many products were formed, or `None` when a denominator vanishes modulo
    /// p (the span is then not exact).
    fn run(
        mut self,
        gens: &[Generator],
        mut vectors: StampedVectors,
    ) -> Result<Option<usize>, EngineError> {
        let mut gens: Vec<&Generator> = gens.iter().collect();
        gens.sort_by_key(|g| g.stamp);
        vectors.sort_by_key(|v| v.0);
        let mut vectors = vectors.into_iter().peekable();
        let mut all = || -> Result<(), Stop> {
            let mut lo = 0;
            while lo < gens.len() {
                let stamp = gens[lo].stamp;
                let hi = lo + gens[lo..].iter().take_while(|g| g.stamp == stamp).count();
                while let Some((at, v)) = vectors.next_if(|v| v.0 <= stamp) {
                    self.add(|span| span.add(at, v))?;
                }
                self.round(&gens[..hi], lo, stamp)?;
                lo = hi;
            }
            for (at, v) in vectors.by_ref() {
                self.add(|span| span.add(at, v))?;
            }
            Ok(())
        };
        match all() {
            Ok(()) | Err(Stop::Spanned) => Ok(Some(self.formed)),
            Err(Stop::NotModular) => Ok(None),
            Err(Stop::Failed(e)) => Err(e),
        }
    }

    /// Adds to the span; stops when a denominator vanishes modulo p or the span is full.
    fn add(&mut self, add: impl FnOnce(&mut Stamped) -> Option<()>) -> Result<(), Stop> {
        add(self.span).ok_or(Stop::NotModular)?;
        match self.span.rank() >= self.dimension {
            true => Err(Stop::Spanned),
            false => Ok(()),
        }
    }

    /// The products whose last factor is one of `gens[lo..]`, the generators of `stamp` (the
    /// others have smaller stamps), depth first and from the last generator down, so that
    /// the products of the stamp's own generators come first; a prefix of factors below `lo`
    /// only is formed again, its own stamp's round having added it. The order decides only
    /// how soon the span fills up: at the 1:1 resonance the last integrals to join it are
    /// powers such as `L^k` of the stamp's generators, which the order from the first
    /// generator up reached last (1:1 at degree 10, when the stamps were degrees: 44 185
    /// products instead of 126 086).
    fn round(&mut self, gens: &[&Generator], lo: usize, stamp: i64) -> Result<(), Stop> {
        // The least sizes from each index on.
        let mut least = vec![Size::UNBOUNDED; gens.len() + 1];
        for (i, g) in gens.iter().enumerate().rev() {
            least[i] = least[i + 1].min(g.size);
        }
        let round = Round {
            gens,
            lo,
            stamp,
            least,
            max_factors: (self.bounds.momenta + self.bounds.coordinates + self.bounds.poisson)
                .max(1) as usize
                + 1,
        };
        for (i, g) in gens.iter().enumerate().rev() {
            if round.extendable(self, i, g.size) {
                round.extend(self, (i, &g.expr, g.size), usize::from(g.size.has_degree()))?;
            }
        }
        Ok(())
    }

    fn fits(&self, size: Size) -> bool {
        size.momenta <= self.bounds.momenta
            && (self.laurent || size.coordinates <= self.bounds.coordinates)
            && size.poisson <= self.bounds.poisson
            && size.angles_alone <= self.bounds.angles_alone
    }
}

/// One stamp's depth-first walk over the products of [`Spanning::round`].
struct Round<'g> {
    gens: &'g [&'g Generator],
    lo: usize,
    stamp: i64,
    /// From each index on, the least size of a generator.
    least: Vec<Size>,
    /// The most factors of positive degree, whose coordinates' degrees may cancel in a
    /// Laurent space (those of the angles alone are bounded by their orders).
    max_factors: usize,
}

impl Round<'_> {
    /// Whether a prefix whose last index is `last`, of size `size`, can take one more factor
    /// and still fit: one from its last index on, and from `lo` on while it has none there.
    fn extendable(&self, spanning: &Spanning, last: usize, size: Size) -> bool {
        spanning.fits(size.plus(self.least[last.max(self.lo)]))
    }

    /// Extends the prefix `(last index, product, size)` with `factors` factors of positive
    /// degree by each generator from its last index on, the last first, and what fits
    /// further, depth first.
    fn extend(
        &self,
        spanning: &mut Spanning,
        (last, prefix, size): (usize, &Expr, Size),
        factors: usize,
    ) -> Result<(), Stop> {
        for (i, g) in self.gens.iter().enumerate().skip(last).rev() {
            let factors = factors + usize::from(g.size.has_degree());
            let sum = size.plus(g.size);
            if factors > self.max_factors
                || !spanning.fits(sum)
                || (i < self.lo && !self.extendable(spanning, i, sum))
            {
                continue;
            }
            let p = prefix.checked_mul(&g.expr).map_err(EngineError::from)?;
            spanning.formed += 1;
            if spanning.formed > spanning.max_products {
                let n = spanning.max_products;
                return Err(Stop::Failed(EngineError::Invalid(format!(
                    "more than {n} product{} of integrals, the limit (`SearchOptions::\
                     max_products`; on the command line, --max-products): search a smaller \
                     space, or raise the limit",
                    if n == 1 { "" } else { "s" }
                ))));
            }
            if i >= self.lo {
                let (problem, stamp) = (spanning.problem, self.stamp);
                spanning.add(|span| span.add_parts(problem, stamp, &p))?;
            }
            if self.extendable(spanning, i, sum) {
                self.extend(spanning, (i, &p, sum), factors)?;
            }
        }
        Ok(())
    }
}

/// The coordinates on which integrals of the space are compared modulo p: the leading unknown
/// of each basis integral. The basis is in echelon form by its leading unknowns, so an integral
/// `Σ c_k I_k` has at the largest lead with `c_k ≠ 0` the coefficient `c_k` times that basis
/// element's own, nonzero: an integral is zero if its coordinates there are. Modulo p that
/// holds when no lead coefficient is divisible by p, which [`Leads::of`] checks (else every
/// coordinate is kept). The complement's vectors are all integrals of the space (the known
/// ones, constants, parameter multiples, products), so their dependencies modulo p are the same
/// on the leads as on every coordinate, with a few entries where a product has tens.
struct Leads {
    /// For each unknown, its position among the leads, if it is one.
    position: Vec<Option<usize>>,
    /// How many coordinates are kept.
    count: usize,
}

impl Leads {
    /// The leads of `kernel` (sorted by leading unknown, primitive), among `dim` unknowns; every
    /// unknown when a lead coefficient vanishes modulo p.
    fn of(kernel: &[SparseVec<Rational>], dim: usize) -> Self {
        let mut position = vec![None; dim];
        for (k, v) in kernel.iter().enumerate() {
            let (last, x) = lead(v).expect("a kernel vector is not zero");
            match Fp::from_rational(x) {
                Some(x) if !x.is_zero() => position[*last] = Some(k),
                _ => return Leads::all(dim),
            }
        }
        Leads {
            position,
            count: kernel.len(),
        }
    }

    /// Every unknown.
    fn all(dim: usize) -> Self {
        Leads {
            position: (0..dim).map(Some).collect(),
            count: dim,
        }
    }

    /// `v`'s coordinates on the leads.
    fn restrict<F>(&self, v: SparseVec<F>) -> SparseVec<F> {
        v.into_iter()
            .filter_map(|(j, x)| self.position[j].map(|at| (at, x)))
            .collect()
    }
}

/// Vectors that join the span of what is generated, by non-decreasing stamp (the number of
/// the grade above which each counts, [`Grading`]), each kept only when it is independent of
/// those kept so far: modulo p, or over Q for an exact span. What is dropped lies in the span
/// of what is kept under its stamp or a smaller one, modulo p or over Q, so the pass modulo p
/// decides with the same span as with every vector, and checks its dependencies over Q with
/// vectors that are kept. At most the dimension of the integrals is kept (825 at degree 8 at
/// the 1:1 resonance).
struct Stamped<'a> {
    basis: Independent<'a>,
    /// The kept vectors over Q, with their stamps.
    kept: StampedVectors,
}

/// The vectors kept so far, as a basis modulo p (of their coordinates on the leads) or over Q.
enum Independent<'a> {
    Modular(Echelon<Fp>, &'a Leads),
    Exact(Echelon<Rational>),
}

impl<'a> Stamped<'a> {
    fn new(leads: &'a Leads, exact: bool) -> Self {
        let basis = match exact {
            true => Independent::Exact(Echelon::new(leads.position.len())),
            false => Independent::Modular(Echelon::new(leads.count), leads),
        };
        Stamped {
            basis,
            kept: Vec::new(),
        }
    }

    /// How many vectors are kept: the dimension of their span.
    fn rank(&self) -> usize {
        self.kept.len()
    }

    /// Adds `v` under `stamp`, no smaller than any stamp before it; `None` when a denominator
    /// of `v` vanishes modulo p.
    fn add(&mut self, stamp: i64, v: SparseVec<Rational>) -> Option<()> {
        debug_assert!(self.kept.last().is_none_or(|k| k.0 <= stamp));
        let id = self.kept.len();
        let independent = match &mut self.basis {
            Independent::Modular(e, leads) => e.extend(id, &leads.restrict(modular::to_fp(&v)?)),
            Independent::Exact(e) => e.extend(id, &v),
        };
        if independent {
            self.kept.push((stamp, v));
        }
        Some(())
    }

    /// Adds the coordinates of the real and imaginary parts of `p` under `stamp`, if they lie
    /// in the space; `None` when a denominator vanishes modulo p. Modulo p the coordinates are
    /// taken modulo p first, and over Q only for a part that is kept.
    fn add_parts(&mut self, problem: &Problem, stamp: i64, p: &Expr) -> Option<()> {
        let (e, leads) = match &mut self.basis {
            Independent::Modular(e, leads) => (e, *leads),
            Independent::Exact(_) => {
                if let Some((re, im)) = problem.coordinates_of_parts(p) {
                    for v in [re, im] {
                        if !v.is_empty() {
                            self.add(stamp, v)?;
                        }
                    }
                }
                return Some(());
            }
        };
        let Some(parts) = problem.coordinates_of_parts_mod_p(p)? else {
            return Some(());
        };
        debug_assert!(self.kept.last().is_none_or(|k| k.0 <= stamp));
        let mut exact_parts = None;
        for (part, v) in parts.into_iter().enumerate() {
            let v = leads.restrict(v);
            if v.is_empty() || !e.extend(self.kept.len(), &v) {
                continue;
            }
            let (re, im) = exact_parts
                .get_or_insert_with(|| problem.coordinates_of_parts(p).expect("in the space"));
            let v = std::mem::take(if part == 0 { re } else { im });
            self.kept.push((stamp, v));
        }
        Some(())
    }

    /// The kept vectors with their stamps, by increasing stamp.
    fn into_vectors(self) -> StampedVectors {
        self.kept
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::systems;

    #[test]
    fn coordinates_are_those_of_the_real_and_imaginary_parts() {
        let rotor = systems::harmonic_rotor();
        let h = rotor.hamiltonian().clone();
        let problem = Problem::new(&rotor, &SearchSpace::new(2, 1, 2), &[], &[], h, None).unwrap();
        let n = problem.unknowns.len();
        // f = Σ (a_j + i b_j) φ_j over every third unknown (the φ_j are real): Re f has the
        // coordinates a, Im f the coordinates b.
        let (mut a, mut b) = (Vec::new(), Vec::new());
        let mut f = Expr::zero(&problem.vars);
        for j in (0..n).step_by(3) {
            let (x, y) = (
                Rational::new(j as i64 % 7 - 3, 2),
                Rational::new(1, j as i64 + 1),
            );
            let c = GaussianRational::new(x.clone(), y.clone());
            f += problem.expr(j, &Rational::one()).unwrap().scale(&c);
            if !x.is_zero() {
                a.push((j, x));
            }
            b.push((j, y));
        }
        assert_eq!(
            problem.coordinates_of_parts(&f),
            Some((a.clone(), b.clone()))
        );
        assert_eq!(problem.combination(&a).unwrap(), f.re().unwrap());
        assert_eq!(problem.combination(&b).unwrap(), f.im().unwrap());
        // A real function has no imaginary part; a complex one has no real coordinates.
        assert_eq!(problem.coordinates(&f.re().unwrap()), Some(a));
        assert_eq!(problem.coordinates(&f), None);
        // Outside the space (positions degree 2 > 1): no coordinates.
        let outside = f.re().unwrap() + rotor.parse("x^2").unwrap();
        assert_eq!(problem.coordinates(&outside), None);
        assert_eq!(problem.coordinates_of_parts(&outside), None);
    }

    /// A function's grade is the largest `(degree, order)` of its terms, lexicographically, and
    /// grades form a filtration: a sum's is at most the larger of its terms', a product's at
    /// most the sum of its factors'.
    #[test]
    fn grades_are_degree_then_order_and_form_a_filtration() {
        let rotor = systems::harmonic_rotor();
        let h = rotor.hamiltonian().clone();
        let problem = Problem::new(&rotor, &SearchSpace::new(2, 2, 2), &[], &[], h, None).unwrap();
        let grading = Grading::new(&problem.variables, 8);
        let grade = |f: &Expr| {
            let n = grading.grade(f);
            (n / grading.orders, n % grading.orders)
        };
        let graded = [
            ("3", (0, 0)),
            ("cos(theta)", (0, 1)),
            ("cos(2*theta) + 1", (0, 2)),
            ("p_x*cos(theta)", (1, 1)),
            ("p_x + cos(3*theta)", (1, 0)),
            ("x*p_y - y*p_x + sin(theta)", (2, 0)),
            ("x^2*cos(theta) + p_theta*sin(2*theta) - 1", (2, 1)),
        ];
        let functions: Vec<Expr> = graded.iter().map(|g| rotor.parse(g.0).unwrap()).collect();
        for ((text, expected), f) in graded.iter().zip(&functions) {
            assert_eq!(grade(f), *expected, "{text}");
        }
        for f in &functions {
            for g in &functions {
                let (a, b) = (grade(f), grade(g));
                assert!(grade(&(f.clone() + g.clone())) <= a.max(b), "{f} + {g}");
                let product = f.checked_mul(g).unwrap();
                assert!(grade(&product) <= (a.0 + b.0, a.1 + b.1), "({f})·({g})");
            }
        }
    }

    #[test]
    fn the_complement_over_q_alone_is_the_modular_one() {
        let rotor = systems::harmonic_rotor();
        for (m, n, d) in [(1, 1, 4), (2, 1, 3)] {
            let options = SearchOptions::new(SearchSpace::new(d, d, d))
                .when(rotor.resonance(m, n).unwrap())
                .new_only();
            let modular = search(&rotor, &options).unwrap().new.unwrap();
            let exact = search(&rotor, &options.exact_complement())
                .unwrap()
                .new
                .unwrap();
            assert!(!modular.new.is_empty() && modular.generated > 0);
            assert_eq!(
                (modular.new, modular.generated, modular.products),
                (exact.new, exact.generated, exact.products)
            );
        }
    }

    #[test]
    fn a_stamp_keeps_the_parts_of_a_product_in_both_fields() {
        let rotor = systems::harmonic_rotor();
        let h = rotor.hamiltonian().clone();
        let problem = Problem::new(&rotor, &SearchSpace::new(2, 1, 2), &[], &[], h, None).unwrap();
        // f = Σ (a_j + i b_j) φ_j/3 and i·f, whose parts are those of f again.
        let mut f = Expr::zero(&problem.vars);
        for j in (0..problem.unknowns.len()).step_by(5) {
            let c = GaussianRational::new(Rational::new(j as i64 % 7 - 3, 3), Rational::new(1, 3));
            f += problem.expr(j, &Rational::one()).unwrap().scale(&c);
        }
        let i_f = f.scale(&GaussianRational::new(Rational::zero(), Rational::one()));
        let (re, im) = problem.coordinates_of_parts(&f).unwrap();
        for exact in [false, true] {
            let every = Leads::all(problem.unknowns.len());
            let mut span = Stamped::new(&every, exact);
            assert_eq!(span.add_parts(&problem, 2, &f), Some(()));
            assert_eq!(span.add_parts(&problem, 2, &i_f), Some(()));
            let outside = f.clone() + rotor.parse("x^2").unwrap();
            assert_eq!(span.add_parts(&problem, 2, &outside), Some(()));
            assert_eq!(span.into_vectors(), [(2, re.clone()), (2, im.clone())]);
        }
    }

    #[test]
    fn the_span_keeps_only_vectors_independent_of_those_before() {
        let v = |entries: &[(usize, i64)]| -> SparseVec<Rational> {
            entries
                .iter()
                .map(|&(j, x)| (j, Rational::from(x)))
                .collect()
        };
        for exact in [false, true] {
            let every = Leads::all(4);
            let mut span = Stamped::new(&every, exact);
            let a = v(&[(0, 1), (2, 3)]);
            let b = v(&[(1, 2), (2, -1)]);
            let sum = v(&[(0, 1), (1, 2), (2, 2)]);
            // b under stamp 1 spans b under stamp 3 too.
            for (stamp, x) in [
                (1, b.clone()),
                (3, a.clone()),
                (3, b.clone()),
                (3, sum),
                (3, a.clone()),
            ] {
                assert_eq!(span.add(stamp, x), Some(()));
            }
            assert_eq!(span.rank(), 2);
            // p divides a denominator: no residue, so only over Q is it kept.
            let unmappable = vec![(3, Rational::new(1, modular::PRIME as i64))];
            assert_eq!(span.add(4, unmappable.clone()).is_some(), exact);
            let mut expected = vec![(1, b.clone()), (3, a)];
            if exact {
                expected.push((4, unmappable));
            }
            assert_eq!(span.into_vectors(), expected);
        }
    }

    /// A search of `space` for integrals of `rotor` at its 1:1 resonance.
    fn at_one_to_one(rotor: &System, space: SearchSpace) -> SearchOptions {
        SearchOptions::new(space).when(rotor.resonance(1, 1).unwrap())
    }

    /// The integrals of the harmonic rotor in `space` at the 1:1 resonance, the problem at the
    /// fixed values, and the basis's coordinates there.
    fn found_at_one_to_one(space: SearchSpace) -> (SearchResult, Problem, Kernel) {
        let rotor = systems::harmonic_rotor();
        let options = at_one_to_one(&rotor, space);
        let found = search(&rotor, &options).unwrap();
        let parameters = parameter_values(&rotor, options.condition.as_ref(), &[], &[]);
        let problem = fixed_problem(&rotor, &options, &parameters).unwrap();
        let kernel = (found.basis.iter())
            .map(|b| problem.coordinates(&b.fixed).unwrap())
            .collect();
        (found, problem, kernel)
    }

    type Kernel = Vec<SparseVec<Rational>>;

    /// An integral is zero exactly when its coordinates on the leads are: a combination of the
    /// basis has, at the lead of its last basis element, that element's coefficient times its
    /// own. A lead coefficient divisible by p keeps every coordinate.
    #[test]
    fn integrals_are_told_apart_by_their_coordinates_on_the_leads() {
        let (_, problem, kernel) = found_at_one_to_one(SearchSpace::new(2, 2, 2));
        let dim = problem.unknowns.len();
        let leads = Leads::of(&kernel, dim);
        assert_eq!(leads.count, kernel.len());
        assert_eq!(leads.position.iter().flatten().count(), kernel.len());
        for last in 0..kernel.len() {
            // Σ_{k ≤ last} (k + 1)·I_k, modulo p, on the leads.
            let mut sum: FxHashMap<usize, Fp> = FxHashMap::default();
            for (k, v) in kernel[..=last].iter().enumerate() {
                for (j, x) in modular::to_fp(v).unwrap() {
                    let c = Fp::from_i64(k as i64 + 1).mul(&x);
                    let entry = sum.entry(j).or_insert(Fp::from_i64(0));
                    *entry = entry.add(&c);
                }
            }
            let v: SparseVec<Fp> = sum.into_iter().filter(|x| !x.1.is_zero()).collect();
            let on_leads = leads.restrict(v);
            let top = lead(&on_leads).unwrap();
            let own = &lead(&kernel[last]).unwrap().1;
            let expected = Fp::from_i64(last as i64 + 1).mul(&Fp::from_rational(own).unwrap());
            assert_eq!(*top, (last, expected));
        }
        let mut divisible = kernel.clone();
        let last = divisible.len() - 1;
        divisible[last].iter_mut().max_by_key(|x| x.0).unwrap().1 =
            Rational::from(modular::PRIME as i64);
        let every = Leads::of(&divisible, dim);
        assert_eq!(every.count, dim);
        assert_eq!(every.restrict(kernel[last].clone()), kernel[last]);
    }

    #[test]
    fn products_stop_once_they_span_every_integral() {
        // At the 1:1 resonance the products of the integrals up to degree 4 span what they
        // span before the last stamp's products: told that dimension, the walk stops there.
        let (found, problem, kernel) = found_at_one_to_one(SearchSpace::new(4, 4, 4));
        let grading = Grading::new(&problem.variables, 4);
        let gens = generators(&problem, &grading, found.basis.iter().map(|b| &b.fixed)).unwrap();
        let bounds = Size {
            momenta: 4,
            coordinates: 4,
            poisson: 0,
            angles_alone: 4,
        };
        let dim = problem.unknowns.len();
        let leads = Leads::of(&kernel, dim);
        assert_eq!(leads.count, found.basis.len());
        for exact in [false, true] {
            let span = |dimension| {
                let span = Stamped::new(&leads, exact);
                let limits = (dimension, DEFAULT_MAX_PRODUCTS);
                span_of_products(&problem, &gens, Vec::new(), bounds, false, span, limits)
                    .unwrap()
                    .unwrap()
            };
            let (all, formed_all) = span(usize::MAX);
            assert!(all.len() < found.basis.len());
            let (stopped, formed) = span(all.len());
            assert!(formed < formed_all, "{formed} of {formed_all}");
            // The same span: every vector of the whole walk lies in that of the stopped one.
            let mut basis = Echelon::<Rational>::new(dim);
            for (id, (_, v)) in stopped.iter().enumerate() {
                assert!(basis.insert(id, v).is_none());
            }
            assert!(all.iter().all(|(_, v)| basis.contains(v)));
            // Stamps never decrease.
            assert!(stopped.windows(2).all(|w| w[0].0 <= w[1].0));
        }
    }

    #[test]
    fn new_integrals_at_one_to_one_are_the_four_linear_ones() {
        let rotor = systems::harmonic_rotor();
        let options = at_one_to_one(&rotor, SearchSpace::new(2, 2, 2)).new_only();
        let r = search(&rotor, &options).unwrap();
        assert_eq!(r.dimensions_by_momenta_degree(), [1, 6, 20]);
        assert!(r.all_symbolic());
        let new = r.new.as_ref().unwrap();
        assert_eq!(new.new.len(), 4);
        assert_eq!(new.generated, 16);
        for &i in &new.new {
            let f = &r.basis[i];
            assert_eq!((f.momenta_degree, f.trig_degree), (1, 1));
        }
    }

    #[test]
    fn off_resonance_there_is_no_trigonometric_integral() {
        // At p_θ = 3Iω/2 nothing of trigonometric order ≤ 2 and degree ≤ 2 is conserved but
        // the planar u(2) and the constants.
        let rotor = systems::harmonic_rotor();
        let options =
            SearchOptions::new(SearchSpace::new(2, 2, 2)).when(rotor.resonance(3, 2).unwrap());
        let r = search(&rotor, &options).unwrap();
        assert!(r.basis.iter().all(|f| f.trig_degree == 0));
        // 1, L and the quadratic H_x, H_y, G1 (times 2M) and L².
        assert_eq!(r.basis.len(), 6);
    }

    /// The harmonic rotor at 1:1, integrals linear in the momenta: found at `M = ω = I = 1`
    /// and lifted by homogeneity, or found with `M, ω, I` symbolic (coefficients of degree
    /// `≤ 2` in them), the generators are the same six functions.
    #[test]
    fn symbolic_parameters_find_the_lifted_basis() {
        let rotor = systems::harmonic_rotor();
        let space = SearchSpace::new(1, 1, 1);
        let resonance = rotor.resonance(1, 1).unwrap();
        let lifted = search(&rotor, &SearchOptions::new(space).when(resonance.clone())).unwrap();
        assert!(lifted.all_symbolic() && lifted.module.is_none());
        let mut options = SearchOptions::new(space.parameters_degree(2)).when(resonance);
        for p in ["M", "omega", "I"] {
            options = options.symbolic(rotor.var(p));
        }
        let r = search(&rotor, &options).unwrap();
        assert!(r.parameters.is_empty() && r.all_symbolic());
        // 1, L and the four trigonometric ones, each also times 1, M, ω, I, M², Mω, ….
        assert_eq!(r.basis.len(), 24);
        let module = r.module.as_ref().unwrap();
        let generators: Vec<&Expr> = module
            .generators
            .iter()
            .map(|&i| r.basis[i].expr())
            .collect();
        let expected: Vec<&Expr> = lifted.basis.iter().map(Integral::expr).collect();
        assert_eq!(generators, expected);
    }

    /// The images, the blocks of equations and the proofs are shared among the pool's threads
    /// and kept in order: the same basis, proofs and new integrals on one thread or several,
    /// and from a thread outside any pool.
    #[test]
    fn the_search_is_the_same_on_any_number_of_threads() {
        let rotor = systems::harmonic_rotor();
        let options = at_one_to_one(&rotor, SearchSpace::new(3, 3, 3)).new_only();
        let on = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            pool.install(|| search(&rotor, &options).unwrap())
        };
        let summary = |r: &SearchResult| {
            let basis: Vec<(Expr, bool, Option<Expr>)> = r
                .basis
                .iter()
                .map(|b| (b.fixed.clone(), b.proved_fixed, b.symbolic.clone()))
                .collect();
            let new = r.new.as_ref().map(|n| (n.new.clone(), n.products));
            (basis, new, r.equations, r.components)
        };
        let one = summary(&on(1));
        assert_eq!(one.0.len(), 50);
        assert!(one.0.iter().all(|b| b.1 && b.2.is_some()));
        assert_eq!(summary(&on(3)), one);
        assert_eq!(summary(&search(&rotor, &options).unwrap()), one);
    }

    /// At `a = 1` the rotor in `(x² + a²y²)/2` is isotropic and `x p_y − y p_x` an integral
    /// there; the search finds it, and says it holds at the fixed values only, while the
    /// energy holds for every value.
    #[test]
    fn an_integral_of_the_fixed_values_only_is_not_for_every_value() {
        let rotor = systems::rotor("(x^2 + a^2*y^2)/2", &["a"]).unwrap();
        let r = search(&rotor, &SearchOptions::new(SearchSpace::new(2, 2, 0))).unwrap();
        let find = |text: &str| {
            let e = rotor.parse(text).unwrap();
            (0..r.basis.len())
                .find(|&i| r.basis[i].fixed == e || r.basis[i].fixed == -&e)
                .unwrap_or_else(|| panic!("{text} is found"))
        };
        let l = find("x*p_y - y*p_x");
        assert_eq!(r.for_every_value(l), None);
        let bracket = rotor.flow(&rotor.parse("x*p_y - y*p_x").unwrap()).unwrap();
        assert!(!bracket.is_zero());
        let p_theta = find("p_theta");
        assert_eq!(
            r.for_every_value(p_theta),
            Some(&rotor.parse("p_theta").unwrap())
        );
    }

    #[test]
    fn a_parameter_is_either_fixed_or_symbolic() {
        let rotor = systems::harmonic_rotor();
        let m = rotor.var("M");
        let options = SearchOptions::new(SearchSpace::new(1, 1, 0))
            .fix(m, Rational::from(2))
            .symbolic(m);
        let err = search(&rotor, &options).unwrap_err().to_string();
        assert!(
            err.contains("M is both fixed to a value and kept symbolic"),
            "{err}"
        );
        let options = SearchOptions::new(SearchSpace::new(1, 1, 0)).symbolic(rotor.var("x"));
        let err = search(&rotor, &options).unwrap_err().to_string();
        assert!(
            err.contains("only parameters can be kept symbolic"),
            "{err}"
        );
        // A value for a coordinate was ignored: the search ran as if it were not given.
        let options =
            SearchOptions::new(SearchSpace::new(1, 1, 0)).fix(rotor.var("x"), Rational::from(1));
        let err = search(&rotor, &options).unwrap_err().to_string();
        assert!(
            err.contains(
                "only parameters are given values for the linear algebra, and x is not one"
            ),
            "{err}"
        );
    }

    #[test]
    fn a_parameter_named_twice_is_kept_symbolic_once() {
        let rotor = systems::harmonic_rotor();
        let (m, omega) = (rotor.var("M"), rotor.var("omega"));
        let space = SearchSpace::new(1, 1, 0).parameters_degree(2);
        let once = search(
            &rotor,
            &SearchOptions::new(space).symbolic(m).symbolic(omega),
        )
        .unwrap();
        let mut options = SearchOptions::new(space);
        options.symbolic = vec![m, m, omega, m];
        let twice = search(&rotor, &options).unwrap();
        assert_eq!(twice.unknowns, once.unknowns);
        assert_eq!(twice.basis.len(), once.basis.len());
        assert_eq!(twice.module.unwrap().parameters, [m, omega]);
    }

    /// At 1:1 the new integrals are the four linear ones whether the parameters are fixed and
    /// lifted or kept symbolic (with them, `M·I` and the like count as generated, and the
    /// named integrals join the known ones once cleared of `1/M`, `1/I`).
    #[test]
    fn new_integrals_with_symbolic_parameters_are_the_same_four() {
        let rotor = systems::harmonic_rotor();
        let resonance = rotor.resonance(1, 1).unwrap();
        let space = SearchSpace::new(2, 2, 2);
        let fixed = search(
            &rotor,
            &SearchOptions::new(space).when(resonance.clone()).new_only(),
        )
        .unwrap();
        let mut options = SearchOptions::new(space.parameters_degree(4))
            .when(resonance)
            .new_only();
        for p in ["M", "omega", "I"] {
            options = options.symbolic(rotor.var(p));
        }
        let symbolic = search(&rotor, &options).unwrap();
        let new = |r: &SearchResult| -> Vec<Expr> {
            let new = r.new.as_ref().unwrap();
            new.new.iter().map(|&i| r.basis[i].expr().clone()).collect()
        };
        assert_eq!(new(&symbolic), new(&fixed));
        assert_eq!(new(&fixed).len(), 4);
        // The named integrals, cleared of `1/M` and `1/I`, lie in the space of degree 4 in
        // the parameters (`2M·F1` has `M²ω²x²`); F2 and Ω are constants at the resonance.
        assert_eq!(
            symbolic.new.as_ref().unwrap().known,
            fixed.new.as_ref().unwrap().known
        );
    }

    /// A Poisson variable `s` with a declared bracket with a canonical momentum, `{p_x, s} = 1`,
    /// and `H = p_x²/2 + s`: `ṗ_x = 1` comes from the declared part of `{p_x, H}` alone, so an
    /// image that took only `∂H/∂x` would find `p_x` conserved. The integrals are the
    /// polynomials in the Casimir `u = x + s` and `v = p_x² − 2x` that fit the space: `1, u, u²,
    /// v, uv` at degree `≤ 2` in each kind, each proved.
    #[test]
    fn declared_brackets_with_canonical_variables_enter_the_images() {
        let vars = VarSet::builder()
            .coordinate("x")
            .momentum("p_x")
            .poisson("s")
            .build()
            .unwrap();
        let e = |t: &str| Expr::parse(&vars, t).unwrap();
        let space = crate::PhaseSpace::new(&vars, &[("x", "p_x")])
            .unwrap()
            .with_brackets(&[("p_x", "s", e("1"))])
            .unwrap();
        let slide = System::new("slide", space, e("p_x^2/2 + s"));
        let options = SearchOptions::new(SearchSpace::new(2, 2, 0).poisson_degree(2)).new_only();
        let found = search(&slide, &options).unwrap();
        assert!(found.all_symbolic() && found.basis.iter().all(|f| f.proved_fixed));
        assert_eq!(found.variables.poisson, [slide.var("s")]);
        let parameters = parameter_values(&slide, None, &[], &[]);
        let problem = fixed_problem(&slide, &options, &parameters).unwrap();
        let mut span = Echelon::<Rational>::new(problem.unknowns.len());
        for (id, f) in found.basis.iter().enumerate() {
            assert!(span
                .insert(id, &problem.coordinates(&f.fixed).unwrap())
                .is_none());
        }
        let expected = [
            "1",
            "x + s",
            "(x + s)^2",
            "p_x^2 - 2*x",
            "(x + s)*(p_x^2 - 2*x)",
        ];
        for f in expected {
            assert!(span.contains(&problem.coordinates(&e(f)).unwrap()), "{f}");
        }
        assert_eq!(found.basis.len(), expected.len());
        assert!(problem
            .coordinates(&e("p_x"))
            .is_some_and(|v| !span.contains(&v)));
        // With H = u + v/2 known, the Casimir u alone is new: v = 2(H − u), and u², uv are
        // products.
        let new = found.new.as_ref().unwrap();
        assert_eq!(new.known, ["H"]);
        let new: Vec<&Expr> = new.new.iter().map(|&i| &found.basis[i].fixed).collect();
        assert_eq!(new, [&e("x + s")]);
    }

    /// The symmetric Euler top with the moments as parameters, on the surface `M₃ = 1`, which
    /// its flow keeps: `M₃` is left out of the space (every function of it is an integral
    /// there), and the integrals of degree `≤ 2` in `M₁, M₂` are `1` and `M₁² + M₂²`, lifted
    /// back to the moments, which have one weight, so the lift needs none of them.
    #[test]
    fn a_poisson_variable_the_condition_fixes_is_left_out() {
        let vars = VarSet::builder()
            .poisson("M1")
            .poisson("M2")
            .poisson("M3")
            .parameter("A")
            .parameter("C")
            .build()
            .unwrap();
        let e = |t: &str| Expr::parse(&vars, t).unwrap();
        let space = crate::PhaseSpace::new(&vars, &[])
            .unwrap()
            .with_brackets(&[
                ("M1", "M2", e("M3")),
                ("M2", "M3", e("M1")),
                ("M3", "M1", e("M2")),
            ])
            .unwrap();
        let top = System::new("top", space, e("(M1^2 + M2^2)/(2*A) + M3^2/(2*C)"));
        let m3 = Condition::new("M3 = 1", top.var("M3"), e("1"));
        let options = SearchOptions::new(SearchSpace::new(0, 0, 0).poisson_degree(2))
            .fix(top.var("A"), Rational::from(2))
            .when(m3);
        let found = search(&top, &options).unwrap();
        assert_eq!(found.variables.left_out, [top.var("M3")]);
        assert_eq!(found.variables.poisson, [top.var("M1"), top.var("M2")]);
        let integrals: Vec<&Expr> = found.basis.iter().map(Integral::expr).collect();
        assert_eq!(integrals, [&e("1"), &e("M1^2 + M2^2")]);
        assert!(found.basis.iter().all(|f| f.proved_fixed));
    }

    #[test]
    fn fixed_values_other_than_one_lift_the_same() {
        let rotor = systems::harmonic_rotor();
        let omega = rotor.var("omega");
        let m = rotor.var("M");
        let options = at_one_to_one(&rotor, SearchSpace::new(1, 1, 1))
            .fix(omega, Rational::new(3, 2))
            .fix(m, Rational::new(5, 7));
        let r = search(&rotor, &options).unwrap();
        let lifted: Vec<String> = r.basis.iter().map(|f| f.expr().to_string()).collect();
        assert!(
            lifted.contains(&"p_x cos θ + Mωx sin θ".to_string()),
            "{lifted:?}"
        );
    }
}
