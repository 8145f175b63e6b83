//! Closure: the algebra a list of functions generates under the Poisson bracket.
//!
//! For generators `G_1, …, G_r` and a degree `D`, every bracket `{G_a, G_b}` is written as a
//! polynomial `Σ c_β G^β` of degree `≤ D` in the generators when one exists, and the polynomial
//! relations among the generators up to degree `D` (syzygies, such as the Casimir
//! `4 G1² + G2² + ω² L² = (F1 − F2)²`) are found, each relation minimal: not a combination of
//! the relations before it times polynomials in the generators and in the symbolic parameters
//! (`closure/minimal.rs`). Both are exact linear algebra over `Q` on the monomials `G^β`
//! expanded at fixed parameter values (modulo a 62-bit prime, reconstructed, checked exactly);
//! coefficients are then lifted to Laurent monomials in the parameters by homogeneity
//! ([`crate::scaling`]) and every bracket and relation is checked by expanding it symbolically.
//! A condition such as a resonance is applied to each bracket after it is formed from the
//! generators on the whole phase space, and to the generators the bracket is written in, so
//! the identities hold on the condition's surface. A condition that sets a phase variable
//! (`p_θ = Iω`) cannot be applied first: a bracket differentiates along that variable, so a
//! generator constant on the surface (`F2 = Iω²/2`) may still have brackets that are not zero.
//!
//! With denominator atoms (`v` standing for a polynomial `D`, `v^{−k} = 1/D^k`) the monomials
//! are not independent (`v · D = 1`), so the linear algebra runs on the images of every column
//! and target under one injective linear map, `Clearing` (`clearing.rs`): multiplied by a
//! common `Π v^N` and `v = D` substituted, polynomials on which monomials are independent. A combination or
//! relation of the images is one of the elements, and none is missed; the symbolic checks
//! decide zero by [`Expr::vanishes`].
//!
//! ```
//! use brackets::closure::{closure, ClosureOptions};
//! use brackets::systems;
//!
//! // su(2) of the harmonic rotor, and its Casimir.
//! let rotor = systems::harmonic_rotor();
//! let c = closure(&rotor, &["F1", "F2", "L", "G1", "G2"], &ClosureOptions::new(2))?;
//! assert_eq!(c.render_bracket(3, 4), "−ω² L"); // {G1, G2}
//! assert_eq!(c.relations.len(), 1);
//! assert!(c.relations[0].symbolic);
//! # Ok::<(), brackets::EngineError>(())
//! ```

use itertools::Itertools;
use std::collections::HashMap;
use std::time::Instant;

use trigpoly::{AlgebraError, Expr, GaussianRational, Rational, Style, Var, VarKind, Vars};

use crate::claim::Condition;
use crate::error::{EngineError, EngineLimit};
use crate::modular::{self, CombinationSums, Echelon, Fp, SparseVec};
use crate::scaling::{Lifter, Scaling};
use crate::system::{NamedFunction, System};
use crate::table::{BracketTable, Entry};

mod columns;
mod fewest;
mod lift;
mod minimal;
mod span;

use fewest::Relations;
use lift::LiftContext;
use span::Span;

/// What to compute: a degree ([`ClosureOptions::new`]), then each other choice by a method,
/// the condition by [`ClosureOptions::when`], a parameter's value by [`ClosureOptions::fix`],
/// every other field by the method of its name (`symbolic` adds one more each call).
///
/// ```
/// use brackets::{systems, ClosureOptions};
///
/// let rotor = systems::harmonic_rotor();
/// let omega = rotor.vars().lookup("omega").unwrap();
/// let options = ClosureOptions::new(2).symbolic(omega).parameters_degree(1).max_monomials(500);
/// assert_eq!((options.degree, options.parameters_degree, options.max_monomials), (2, 1, 500));
/// assert_eq!(options.symbolic, vec![omega]);
/// assert_eq!(ClosureOptions::new(2).max_monomials, ClosureOptions::DEFAULT_MAX_MONOMIALS);
/// ```
///
/// A choice may be added, so another crate writes no literal of all of them:
///
/// ```compile_fail,E0639
/// let options = brackets::ClosureOptions { degree: 2, condition: None, fixed: vec![],
///     symbolic: vec![], parameters_degree: 2, max_monomials: 100 };
/// ```
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct ClosureOptions {
    /// The largest degree of the polynomials in the generators.
    pub degree: u32,
    /// The condition (a resonance): applied to each bracket after it is formed from the
    /// generators on the whole phase space, and to the generators it is written in.
    pub condition: Option<Condition>,
    /// Parameter values for the linear algebra (every other parameter is fixed to 1).
    pub fixed: Vec<(Var, Rational)>,
    /// Parameters kept symbolic: the coefficients are polynomials in them, of total degree at
    /// most [`ClosureOptions::parameters_degree`], and what is found holds for every value of
    /// them (where the lift by homogeneity cannot tell apart parameters of one weight).
    pub symbolic: Vec<Var>,
    /// The total degree of the coefficients in the symbolic parameters.
    pub parameters_degree: u32,
    /// The most monomials `p^ν G^β` the linear algebra may take: each is expanded, and each
    /// is a column of the system (5 generators at degree 12 are 6188 monomials, 2 s and
    /// 200 MB; at degree 14, 11628, 8 s and 570 MB). More are refused before any is expanded,
    /// a limit: [`EngineError::PastLimit`] of [`EngineLimit::ClosureMonomials`].
    pub max_monomials: usize,
}

impl ClosureOptions {
    /// Degree `D`, no condition.
    pub fn new(degree: u32) -> Self {
        ClosureOptions {
            degree,
            condition: None,
            fixed: Vec::new(),
            symbolic: Vec::new(),
            parameters_degree: 2,
            max_monomials: ClosureOptions::DEFAULT_MAX_MONOMIALS,
        }
    }

    /// The default of [`ClosureOptions::max_monomials`].
    pub const DEFAULT_MAX_MONOMIALS: usize = 20_000;

    /// Under a condition.
    #[must_use]
    pub fn when(mut self, condition: Condition) -> Self {
        self.condition = Some(condition);
        self
    }

    /// With a parameter fixed to a value for the linear algebra: a [`Rational`], or an
    /// integer.
    ///
    /// ```
    /// use brackets::{systems, ClosureOptions};
    /// use trigpoly::Rational;
    ///
    /// let rotor = systems::harmonic_rotor();
    /// let omega = rotor.vars().lookup("omega").unwrap();
    /// let options = ClosureOptions::new(2).fix(omega, 3);
    /// assert_eq!(options.fixed, [(omega, Rational::from(3))]);
    /// ```
    #[must_use]
    pub fn fix(mut self, v: Var, value: impl Into<Rational>) -> Self {
        self.fixed.retain(|f| f.0 != v);
        self.fixed.push((v, value.into()));
        self
    }

    /// With a parameter kept symbolic (see [`ClosureOptions::parameters_degree`]).
    #[must_use]
    pub fn symbolic(mut self, v: Var) -> Self {
        if !self.symbolic.contains(&v) {
            self.symbolic.push(v);
        }
        self
    }

    /// With coefficients polynomial of total degree `≤ d` in the parameters kept symbolic,
    /// all of them together (2 unless set).
    #[must_use]
    pub fn parameters_degree(mut self, d: u32) -> Self {
        self.parameters_degree = d;
        self
    }

    /// With at most `n` monomials `p^ν G^β` for the linear algebra
    /// ([`ClosureOptions::DEFAULT_MAX_MONOMIALS`] unless set).
    #[must_use]
    pub fn max_monomials(mut self, n: usize) -> Self {
        self.max_monomials = n;
        self
    }
}

/// One bracket of the structure table.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Bracket {
    /// `{G_a, G_b}` as a polynomial in the generators (in [`Closure::ring`]), checked by
    /// expanding it: for all parameter values when `symbolic`, else at the fixed values.
    Polynomial {
        /// The polynomial.
        poly: Expr,
        /// Whether it was proved with symbolic parameters.
        symbolic: bool,
    },
    /// No polynomial of degree `≤ D` in the generators: the bracket itself.
    Outside {
        /// `{G_a, G_b}` (after the condition), over its common denominator on a system with
        /// denominator atoms.
        bracket: Expr,
    },
}

/// A relation `R = 0` as `positive terms = negated negative terms`, in the paper's notation:
/// `P11² + Q11² = 2MωL + 2M F1 − Mω²I`; one with a coefficient that is not real as
/// `R = 0`.
pub fn relation_text(poly: &Expr) -> String {
    let vars = poly.vars();
    let mut left = Vec::new();
    let mut right = Vec::new();
    for t in poly.terms() {
        let c = t.coeff();
        if !c.is_real() {
            return format!("{} = 0", poly.render(Style::Unicode));
        }
        let e = t.exponents();
        if c.re.is_negative() {
            right.push((-&c, e));
        } else {
            left.push((c, e));
        }
    }
    let side = |terms: Vec<(GaussianRational, Vec<i64>)>| -> String {
        if terms.is_empty() {
            return "0".into();
        }
        Expr::from_terms(vars, terms)
            .map(|e| e.render(Style::Unicode))
            .unwrap_or_else(|_| "?".into())
    };
    format!("{} = {}", side(left), side(right))
}

/// A polynomial relation among the generators. Its `Display` is [`relation_text`], the
/// positive terms on the left.
///
/// ```
/// use brackets::{closure, systems, ClosureOptions};
///
/// // The Casimir of su(2) (C10): 4 G1² + G2² + ω² L² = (F1 − F2)².
/// let rotor = systems::harmonic_rotor();
/// let c = closure(&rotor, &["F1", "F2", "L", "G1", "G2"], &ClosureOptions::new(2))?;
/// assert_eq!(c.relations.len(), 1);
/// assert_eq!(
///     c.relations[0].to_string(),
///     "ω² L² + 2 F1 F2 + 4 G1² + G2² = F1² + F2²"
/// );
/// # Ok::<(), brackets::EngineError>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct Relation {
    /// `R(G) = 0`, a polynomial in [`Closure::ring`].
    pub poly: Expr,
    /// Its degree in the generators.
    pub degree: u32,
    /// Whether it was proved with symbolic parameters (else only at the fixed values).
    pub symbolic: bool,
}

impl std::fmt::Display for Relation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&relation_text(&self.poly))
    }
}

/// Seconds spent (reported, never used to decide anything).
#[derive(Clone, Debug, Default)]
#[non_exhaustive]
pub struct ClosureTimings {
    /// Expanding the monomials at the fixed values.
    pub monomials: f64,
    /// Linear algebra and reconstruction.
    pub solve: f64,
    /// Symbolic lifting and proofs.
    pub proofs: f64,
    /// Everything.
    pub total: f64,
}

/// The closure of a list of generators.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Closure {
    /// The generators' names, as given.
    pub names: Vec<String>,
    /// Their display names.
    pub display: Vec<String>,
    /// The ring the polynomials live in: the parameters and one symbol per generator.
    pub ring: Vars,
    /// The generators' symbols in [`Closure::ring`].
    pub symbols: Vec<Var>,
    /// The degree bound.
    pub degree: u32,
    /// The condition's text, if any.
    pub condition: Option<String>,
    /// The parameter values used for the linear algebra.
    pub parameters: Vec<(Var, Rational)>,
    /// The declared denominator that is zero when the parameters are 1, their default: those
    /// in it that were not given values took
    /// [`GENERIC_VALUES`](crate::search::GENERIC_VALUES) instead.
    pub denominator_zero_at_one: Option<Var>,
    /// Whether the weights determine every parameter (so that results can be lifted).
    pub liftable: bool,
    /// `brackets[a][b] = {G_a, G_b}`.
    pub brackets: Vec<Vec<Bracket>>,
    /// The minimal relations, by degree and simplest first: none is a combination of those
    /// before it times polynomials in the generators and the symbolic parameters (within the
    /// degrees: `m R` of degree `≤ D` in the generators, the parameters' coefficients of
    /// degree `≤ S`).
    pub relations: Vec<Relation>,
    /// How many monomials of degree `≤ D` there are.
    pub monomials: usize,
    /// The dimension of their span (monomials minus independent relations).
    pub rank: usize,
    /// Timings.
    pub timings: ClosureTimings,
}

impl Closure {
    /// The bracket `{G_a, G_b}` as text: `−ω² L`, `0`, or the expression itself.
    ///
    /// # Panics
    ///
    /// Panics if `a` or `b` is not the index of a generator (`names.len()` or more).
    pub fn render_bracket(&self, a: usize, b: usize) -> String {
        match &self.brackets[a][b] {
            Bracket::Polynomial { poly, .. } => poly.render(Style::Unicode),
            Bracket::Outside { bracket } => bracket.render(Style::Unicode),
        }
    }

    /// The structure table as a [`BracketTable`], for printing: a bracket outside the
    /// polynomials of the degree is [`Entry::Outside`], given apart by [`Closure::outside`].
    pub fn table(&self) -> BracketTable {
        BracketTable {
            names: self.names.clone(),
            display: self.display.clone(),
            entries: self
                .brackets
                .iter()
                .map(|row| {
                    row.iter()
                        .map(|b| match b {
                            Bracket::Polynomial { poly, .. } if poly.is_zero() => {
                                Entry::Combination(Vec::new())
                            }
                            Bracket::Polynomial { poly, .. } => Entry::Expression(poly.clone()),
                            Bracket::Outside { .. } => Entry::Outside,
                        })
                        .collect()
                })
                .collect(),
        }
    }

    /// The pairs `(a, b)`, `a < b`, whose bracket is not a polynomial of degree `≤ D`.
    pub fn outside(&self) -> Vec<(usize, usize)> {
        let r = self.names.len();
        (0..r)
            .flat_map(|a| (a + 1..r).map(move |b| (a, b)))
            .filter(|&(a, b)| matches!(self.brackets[a][b], Bracket::Outside { .. }))
            .collect()
    }

    /// Whether the table closes: every bracket is a polynomial in the generators.
    pub fn closes(&self) -> bool {
        self.outside().is_empty()
    }

    /// Whether every polynomial bracket and relation was proved symbolically.
    pub fn all_symbolic(&self) -> bool {
        self.relations.iter().all(|r| r.symbolic)
            && self.brackets.iter().flatten().all(|b| match b {
                Bracket::Polynomial { symbolic, .. } => *symbolic,
                Bracket::Outside { .. } => true,
            })
    }
}

/// Exponent vectors over `r` generators of degree `≤ d`, ordered: degree 1, then the constant,
/// then degrees 2, 3, … (so that a generator is preferred over a constant it equals), each
/// degree in lexicographic order.
fn monomials(r: usize, d: u32) -> Vec<Vec<u32>> {
    fn of_degree(r: usize, d: u32) -> Vec<Vec<u32>> {
        if r == 0 {
            return if d == 0 { vec![Vec::new()] } else { Vec::new() };
        }
        let mut out = Vec::new();
        for e in (0..=d).rev() {
            for mut rest in of_degree(r - 1, d - e) {
                rest.insert(0, e);
                out.push(rest);
            }
        }
        out
    }
    let mut order = vec![1, 0];
    order.extend(2..=d);
    order
        .into_iter()
        .filter(|&k| k <= d)
        .flat_map(|k| of_degree(r, k))
        .collect()
}

/// How many exponent vectors over `r` variables have degree `≤ d`: `C(r + d, d)`, or
/// `u128::MAX` past it.
fn monomial_count(r: usize, d: u32) -> u128 {
    // C(r + d, d) = Π_{k=1..r} (d + k)/k, each partial product an integer.
    (1..=r as u128)
        .try_fold(1u128, |acc, k| {
            Some(acc.checked_mul(u128::from(d) + k)? / k)
        })
        .unwrap_or(u128::MAX)
}

/// The closure of the named generators of `system`: each bracket of two of them as a
/// polynomial in them ([`Closure::brackets`]), and their relations ([`Closure::relations`]).
///
/// ```
/// use brackets::{closure, systems, ClosureBracket, ClosureOptions};
///
/// // su(2) and its Casimir (C09, C10): {G1, G2} = −ω² L, and a relation of degree 2.
/// let rotor = systems::harmonic_rotor();
/// let c = closure(&rotor, &["F1", "F2", "L", "G1", "G2"], &ClosureOptions::new(2))?;
/// let ClosureBracket::Polynomial { poly, symbolic } = &c.brackets[3][4] else {
///     panic!("{{G1, G2}} is a polynomial in the generators");
/// };
/// assert!(*symbolic);
/// assert_eq!(poly.to_string(), "−ω² L");
/// assert!(c.relations.iter().any(|r| r.degree == 2 && r.symbolic));
/// # Ok::<(), brackets::EngineError>(())
/// ```
pub fn closure(
    system: &System,
    names: &[impl AsRef<str>],
    options: &ClosureOptions,
) -> Result<Closure, EngineError> {
    let gens: Vec<NamedFunction> = names
        .iter()
        .map(|n| {
            let n = n.as_ref();
            Ok(NamedFunction::new(
                n,
                system.display_name(n),
                system.get(n)?.clone(),
            ))
        })
        .collect::<Result<_, EngineError>>()?;
    closure_of(system, &gens, options)
}

/// The closure of generators given as named functions (name, display name, function), which
/// need not be functions of the system.
pub fn closure_of(
    system: &System,
    generators: &[NamedFunction],
    options: &ClosureOptions,
) -> Result<Closure, EngineError> {
    let start = Instant::now();
    let mut timings = ClosureTimings::default();
    // A parameter named twice (in the public field) is kept symbolic once, as a search's is:
    // twice, it stood for two generators, and the closure found the relations 0 = 0.
    let options = &ClosureOptions {
        symbolic: options.symbolic.iter().copied().unique().collect(),
        ..options.clone()
    };
    let r = generators.len();
    let condition = options.condition.as_ref();
    let g_sym = span::restricted_generators(system, generators, condition)?;
    // The brackets `{G_a, G_b}`, `a < b`, formed on the whole phase space, then after the
    // condition: the targets.
    let pairs: Vec<(usize, usize)> = (0..r)
        .flat_map(|a| (a + 1..r).map(move |b| (a, b)))
        .collect();
    let brackets: Vec<Expr> = pairs
        .iter()
        .map(|&(a, b)| system.bracket(&generators[a].expr, &generators[b].expr))
        .collect::<Result<_, _>>()?;
    let formed: Vec<&Expr> = (generators.iter().map(|g| &g.expr))
        .chain(&brackets)
        .collect();
    let b_sym: Vec<Expr> = (brackets.iter())
        .map(|bracket| span::restrict(condition, bracket.clone()))
        .collect::<Result<_, _>>()?;
    let span = Span::new(system, g_sym, &b_sym, &formed, options, None)?;
    timings.monomials = (span.expanded - start).as_secs_f64();

    // Relations: the kernel, in column order (exact).
    let kernel = modular::kernel(&span.columns, span.nrows);
    // With complex generators the columns are each monomial and i times it: their span over
    // Q is a space over Q(i), of half its dimension, which is the monomials' span.
    let rank = (span.columns.len() - kernel.len()) / if span.complex { 2 } else { 1 };
    // Brackets: each target in the span of the columns.
    let solutions = express_targets(&span.columns, span.nrows, &span.targets);
    timings.solve = span.expanded.elapsed().as_secs_f64();

    let t = Instant::now();
    let scaling = scaling_of(system, generators, condition)?;
    let lifting = Lifting::new(system, generators, &span, &b_sym, options, scaling)?;
    let mut lift_ctx = lifting.context(system, &span);
    let bounds = minimal::Bounds {
        generators: r,
        degree: options.degree,
        parameters_degree: options.parameters_degree,
    };
    let relations =
        minimal::minimal_relations(&mut lift_ctx, &kernel, bounds, span.complex, &span.constant)?;
    let brackets = structure_table(r, &pairs, &solutions, &b_sym, &mut lift_ctx)?;
    timings.proofs = t.elapsed().as_secs_f64();
    timings.total = start.elapsed().as_secs_f64();
    Ok(Closure {
        names: generators.iter().map(|g| g.name.clone()).collect(),
        display: generators.iter().map(|g| g.display.clone()).collect(),
        ring: lifting.printing.ring.clone(),
        symbols: lifting.printing.symbols[..r].to_vec(),
        degree: options.degree,
        condition: condition.map(|c| c.text.clone()),
        liftable: lifting.liftable(),
        parameters: span.parameters,
        denominator_zero_at_one: span.denominator_zero_at_one,
        brackets,
        relations,
        monomials: span.monos.len(),
        rank,
        timings,
    })
}

/// What lifting a result from the fixed values back to symbolic parameters needs: the
/// printing ring, and the system's scaling with its lifter and the generators' weights.
struct Lifting {
    /// The ring the results are written in (with the symbolic parameters' symbols after the
    /// generators').
    printing: PrintingRing,
    /// The system's scaling symmetries, restricted to the generators and the condition.
    scaling: Scaling,
    /// The lifter of the parameters the results must restore, if the weights determine
    /// them.
    lifter: Option<Lifter>,
    /// Each of the span's generators' weights, if each is homogeneous.
    gen_weights: Option<Vec<Vec<Rational>>>,
}

impl Lifting {
    /// The lifting of results about `targets` in the span of `generators`, under the
    /// weights of [`scaling_of`].
    fn new(
        system: &System,
        generators: &[NamedFunction],
        span: &Span,
        targets: &[Expr],
        options: &ClosureOptions,
        scaling: Scaling,
    ) -> Result<Lifting, EngineError> {
        let vars = system.vars();
        let mut printing = printing_ring(vars, generators)?;
        // The symbolic parameters' symbols are the ring's parameters.
        printing
            .symbols
            .extend(options.symbolic.iter().map(|v| printing.param_in_ring[v]));
        // The parameters that the lift must restore: those of the generators that are not
        // constant on the surface and of the targets (a surface constant such as
        // `F2 = Iω²/2` is a relation of its own, kept symbolic).
        let varying = span
            .g_sym
            .iter()
            .zip(&span.constant)
            .filter(|(_, c)| !**c)
            .map(|(e, _)| e);
        let lifted_parameters: Vec<(Var, Rational)> = span
            .parameters
            .iter()
            .filter(|(v, _)| {
                varying
                    .clone()
                    .chain(targets)
                    .any(|e| span::mentions(system, e, *v))
            })
            .cloned()
            .collect();
        let lifter = scaling.lifter(&lifted_parameters);
        let gen_weights = span
            .g_sym
            .iter()
            .map(|e| scaling.homogeneous_weight(e))
            .collect();
        Ok(Lifting {
            printing,
            scaling,
            lifter,
            gen_weights,
        })
    }

    /// Whether the weights determine every parameter, so that results can be lifted.
    fn liftable(&self) -> bool {
        self.lifter.is_some() && self.gen_weights.is_some()
    }

    /// The context that lifts and proves the span's results.
    fn context<'a>(&'a self, system: &System, span: &'a Span) -> LiftContext<'a> {
        LiftContext {
            vars: system.vars().clone(),
            ring: self.printing.ring.clone(),
            symbols: self.printing.symbols.clone(),
            param_in_ring: self.printing.param_in_ring.clone(),
            monos: &span.monos,
            col_ids: &span.col_ids,
            g_sym: &span.g_sym,
            sym_values: HashMap::new(),
            lifter: self.lifter.as_ref(),
            scaling: &self.scaling,
            gen_weights: self.gen_weights.as_deref(),
            exact: span.parameters.is_empty(),
        }
    }
}

/// An expression written as a polynomial in named functions ([`expressed_in`]).
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct Expressed {
    /// The polynomial, in [`Expressed::ring`]: the parameters and one symbol per function.
    pub poly: Expr,
    /// Whether it was proved with symbolic parameters (else only at the fixed values).
    pub symbolic: bool,
    /// The ring of the polynomial.
    pub ring: Vars,
}

/// `target` as a polynomial of degree `≤ options.degree` in the `generators`, found and
/// proved as a closure's brackets are (after `options.condition`), or `None` when there is
/// none. The polynomial is one of several when the generators have relations of that degree;
/// the one with the fewest monomials that a greedy walk over the relations finds is given.
/// A target that is not homogeneous under the system's scalings (a claim off by a factor of
/// a parameter) is written part by part, each homogeneous part lifted on its own.
///
/// ```
/// use brackets::closure::{expressed_in, ClosureOptions};
/// use brackets::{systems, NamedFunction};
///
/// // {G1, G2} = −ω² L, found from the bracket's expansion alone.
/// let rotor = systems::harmonic_rotor();
/// let generators: Vec<NamedFunction> = ["F1", "L", "G1"]
///     .iter()
///     .map(|n| NamedFunction::new(n, n, rotor.get(n).unwrap().clone()))
///     .collect();
/// let bracket = rotor.bracket(rotor.get("G1")?, rotor.get("G2")?)?;
/// let found = expressed_in(&rotor, &generators, &bracket, &ClosureOptions::new(2))?;
/// let found = found.expect("a polynomial in the generators");
/// assert!(found.symbolic);
/// assert_eq!(found.poly.to_string(), "−ω² L");
/// # Ok::<(), brackets::EngineError>(())
/// ```
///
/// A target at fixed values of the parameters (a search's [`Integral::fixed`](crate::Integral::fixed),
/// found there) is written in the generators taken at the same values
/// ([`fix_parameters`](crate::search::fix_parameters)), with those values fixed in the
/// options: in the generators as they are, with their parameters, the scalings weigh the
/// parameters, which the target no longer has, and no polynomial is found.
///
/// ```
/// use brackets::closure::{expressed_in, ClosureOptions};
/// use brackets::search::fix_parameters;
/// use brackets::{systems, NamedFunction};
/// use trigpoly::Rational;
///
/// let rotor = systems::harmonic_rotor();
/// let values = [(rotor.var("M"), Rational::from(2)), (rotor.var("omega"), Rational::from(3))];
/// let mut options = ClosureOptions::new(2);
/// for (v, x) in &values {
///     options = options.fix(*v, x.clone());
/// }
/// // 4 G1² + G2² + ω² L², the Casimir of C10, at M = 2, ω = 3.
/// let target = fix_parameters(&rotor.parse("4*G1^2 + G2^2 + omega^2*L^2")?, &values)?;
/// let names = ["F1", "F2", "L", "G1", "G2"];
/// let symbolic: Vec<NamedFunction> = names
///     .iter()
///     .map(|n| Ok(NamedFunction::new(n, n, rotor.get(n)?.clone())))
///     .collect::<Result<_, brackets::EngineError>>()?;
/// assert!(expressed_in(&rotor, &symbolic, &target, &options)?.is_none());
/// let at_values: Vec<NamedFunction> = symbolic
///     .iter()
///     .map(|f| Ok(NamedFunction::new(&f.name, &f.display, fix_parameters(&f.expr, &values)?)))
///     .collect::<Result<_, brackets::EngineError>>()?;
/// let found = expressed_in(&rotor, &at_values, &target, &options)?.expect("(F1 − F2)²");
/// assert_eq!(found.poly.to_string(), "F1² − 2 F1 F2 + F2²");
/// # Ok::<(), brackets::EngineError>(())
/// ```
pub fn expressed_in(
    system: &System,
    generators: &[NamedFunction],
    target: &Expr,
    options: &ClosureOptions,
) -> Result<Option<Expressed>, EngineError> {
    let condition = options.condition.as_ref();
    let g_sym = span::restricted_generators(system, generators, condition)?;
    if target.vars() != system.vars() {
        return Err(AlgebraError::VarSetMismatch.into());
    }
    let formed: Vec<&Expr> = (generators.iter().map(|g| &g.expr))
        .chain(std::iter::once(target))
        .collect();
    let target = span::restrict(condition, target.clone())?;
    let scaling = scaling_of(system, generators, condition)?;
    let parts = homogeneous_parts(&scaling, &target)?;
    let span = Span::new(system, g_sym, &parts, &formed, options, Some(&scaling))?;
    let Some(solutions) = express_targets(&span.columns, span.nrows, &span.targets)
        .into_iter()
        .collect::<Option<Vec<_>>>()
    else {
        return Ok(None);
    };
    // Where the generators have relations, the shortest of the solutions reads best (one
    // of a single column is as short as any).
    let mut relations = solutions
        .iter()
        .any(|s| s.len() > 1)
        .then(|| Relations::new(&span.columns, span.nrows))
        .flatten();
    let lifting = Lifting::new(system, generators, &span, &parts, options, scaling)?;
    let mut lift_ctx = lifting.context(system, &span);
    let mut poly = Expr::zero(&lifting.printing.ring);
    let mut symbolic = true;
    for ((solution, target), part) in solutions.into_iter().zip(&span.targets).zip(&parts) {
        let shorter = relations
            .as_mut()
            .and_then(|r| r.shorter(&span.columns, &solution, target));
        // A shorter solution that does not lift (it holds at the fixed values only) gives
        // way to the echelon's.
        let lifted = shorter.map(|s| lift_ctx.bracket(&s, part)).transpose()?;
        let (p, proved) = match lifted {
            Some((p, true)) => (p, true),
            _ => lift_ctx.bracket(&solution, part)?,
        };
        poly = poly.checked_add(&p)?;
        symbolic &= proved;
    }
    Ok(Some(Expressed {
        poly,
        symbolic,
        ring: lifting.printing.ring.clone(),
    }))
}

/// The weights under which the bracket, the condition and every generator are homogeneous.
fn scaling_of(
    system: &System,
    generators: &[NamedFunction],
    condition: Option<&Condition>,
) -> Result<Scaling, EngineError> {
    let exprs: Vec<Expr> = generators.iter().map(|g| g.expr.clone()).collect();
    Scaling::of_functions(system.space(), &exprs, condition)
}

/// `e` split into its homogeneous parts under `scaling`, in the order of their first terms.
fn homogeneous_parts(scaling: &Scaling, e: &Expr) -> Result<Vec<Expr>, EngineError> {
    /// A weight, and the terms `(coefficient, exponents)` of that weight.
    type Part = (Vec<Rational>, Vec<(GaussianRational, Vec<i64>)>);
    let mut parts: Vec<Part> = Vec::new();
    for t in e.terms() {
        let exps = t.exponents();
        let weight = scaling.weight(&exps);
        match parts.iter_mut().find(|p| p.0 == weight) {
            Some(part) => part.1.push((t.coeff(), exps)),
            None => parts.push((weight, vec![(t.coeff(), exps)])),
        }
    }
    parts
        .into_iter()
        .map(|(_, terms)| Ok(Expr::from_terms(e.vars(), terms)?))
        .collect()
}

/// Refuses, before any is expanded, a closure whose monomials (of degree `≤ options.degree`
/// in the `varying` generators, times those of the `symbolic` parameters) would pass
/// `options.max_monomials`: a limit, [`EngineLimit::ClosureMonomials`], which a program tells
/// by [`EngineError::limit`].
fn check_monomial_count(
    varying: usize,
    symbolic: usize,
    options: &ClosureOptions,
) -> Result<(), EngineError> {
    let count = monomial_count(varying, options.degree)
        .saturating_mul(monomial_count(symbolic, options.parameters_degree));
    if count <= options.max_monomials as u128 {
        return Ok(());
    }
    let with_parameters = match symbolic {
        0 => String::new(),
        n => format!(
            " (times those of degree ≤ {} in the {n} symbolic parameter{})",
            options.parameters_degree,
            if n == 1 { "" } else { "s" }
        ),
    };
    let count = if count == u128::MAX {
        "more than 2^128".to_string()
    } else {
        count.to_string()
    };
    Err(EngineError::PastLimit {
        which: EngineLimit::ClosureMonomials,
        limit: options.max_monomials,
        message: format!(
            "there are {count} monomials of degree ≤ {} in the {}{with_parameters}, \
             more than the limit {}: lower the degree, or raise the limit",
            options.degree,
            if varying == 1 {
                "generator".to_string()
            } else {
                format!("{varying} generators")
            },
            options.max_monomials
        ),
    })
}

/// Each target (a bracket `{G_a, G_b}` at the fixed values) as a combination of the columns,
/// or `None` when it is outside their span: modulo a prime first (independent there, it is
/// certainly outside; a solution there is reconstructed and checked exactly), and over Q
/// where that does not decide.
fn express_targets(
    columns: &[SparseVec<Rational>],
    nrows: usize,
    targets: &[SparseVec<Rational>],
) -> Vec<Option<SparseVec<Rational>>> {
    let mut echelon = Echelon::<Fp>::new(nrows);
    let mut exact: Option<Echelon<Rational>> = None;
    let mut fp_ok = true;
    for (j, c) in columns.iter().enumerate() {
        match modular::to_fp(c) {
            Some(v) => {
                echelon.insert(j, &v);
            }
            None => fp_ok = false,
        }
    }
    let mut sums = CombinationSums::new();
    let mut solutions = Vec::with_capacity(targets.len());
    for target in targets {
        let mut found = None;
        let mut decided = false;
        if fp_ok {
            if let Some(tf) = modular::to_fp(target) {
                match echelon.express(&tf) {
                    None => decided = true, // independent modulo p: certainly outside
                    Some(dep) => {
                        if let Some(sol) = modular::reconstruct_vec(&dep) {
                            if sums.equals(columns, &sol, target) {
                                found = Some(sol);
                                decided = true;
                            }
                        }
                    }
                }
            }
        }
        if !decided {
            let e = exact.get_or_insert_with(|| {
                let mut e = Echelon::<Rational>::new(nrows);
                for (j, c) in columns.iter().enumerate() {
                    e.insert(j, c);
                }
                e
            });
            found = e.express(target);
        }
        solutions.push(found);
    }
    solutions
}

/// The ring a closure is printed in, and the symbols of the generators and parameters there.
struct PrintingRing {
    /// The system's parameters and one symbol per generator.
    ring: Vars,
    /// Each generator's symbol.
    symbols: Vec<Var>,
    /// Each parameter of the system's variables, as a symbol of the ring.
    param_in_ring: HashMap<Var, Var>,
}

/// The ring a closure is printed in: the system's parameters and one symbol per generator,
/// shown by its display name (`A_x` for `Ax`) unless two would then print alike.
fn printing_ring(vars: &Vars, generators: &[NamedFunction]) -> Result<PrintingRing, EngineError> {
    // The system's limits, which the command line and the file set: the ring's own default
    // refused a generator `a^1500` at a degree limit of 1000 that no --max-degree raised.
    let mut builder = Vars::builder().limits(vars.limits());
    for v in vars.vars() {
        let p = vars.variable(v);
        if p.kind() == VarKind::Parameter {
            // Printed as the system prints it (a file's display, `ω₊` for `a`).
            builder = builder
                .parameter(p.name())
                .printed_as(p.unicode(), p.latex());
        }
    }
    let mut shown = builder.clone();
    for NamedFunction { name, display, .. } in generators {
        if vars
            .lookup(name)
            .is_some_and(|v| vars.variable(v).kind() == VarKind::Parameter)
        {
            return Err(EngineError::Invalid(format!(
                "the generator {} has the name of a parameter",
                trigpoly::quoted_name(name)
            )));
        }
        builder = builder.coordinate(name).word();
        // A display that is no name, `x(t)` or `∂H`, prints as it is, as the rest of a report
        // writes it (in LaTeX as a table writes it, `\partial H`); its ASCII form stays the
        // name, which reads back.
        shown = match trigpoly::shown_forms(display) {
            Some(_) => shown.coordinate(name).shown_as(display),
            None => shown
                .coordinate(name)
                .printed_as(display, &crate::table::latex_name(display)),
        }
        .word();
    }
    // What `build` refuses here is a name (not one, declared twice, printed alike) or more
    // variables than a set holds, a range no limit raises (`AlgebraError::limit` is `None` for
    // each): never a limit, so the words lose none that `EngineError::limit` would say.
    let ring = shown
        .build()
        .or_else(|_| builder.build())
        .map_err(|e| EngineError::Invalid(format!("cannot name the generators: {e}")))?;
    let symbols: Vec<Var> = generators
        .iter()
        .map(|g| ring.lookup(&g.name).expect("declared"))
        .collect();
    let param_in_ring: HashMap<Var, Var> = vars
        .vars()
        .filter(|v| vars.variable(*v).kind() == VarKind::Parameter)
        .map(|v| (v, ring.lookup(vars.variable(v).name()).expect("declared")))
        .collect();
    Ok(PrintingRing {
        ring,
        symbols,
        param_in_ring,
    })
}

/// The structure table: `{G_a, G_b}` as a polynomial in the generators, lifted and proved, or
/// outside their span over its common denominator; antisymmetric, zero on the diagonal.
/// `solutions[k]` and `b_sym[k]` are the solution and the bracket of `pairs[k]`.
fn structure_table(
    r: usize,
    pairs: &[(usize, usize)],
    solutions: &[Option<SparseVec<Rational>>],
    b_sym: &[Expr],
    lift_ctx: &mut LiftContext<'_>,
) -> Result<Vec<Vec<Bracket>>, EngineError> {
    let ring = lift_ctx.ring.clone();
    let mut brackets = vec![
        vec![
            Bracket::Polynomial {
                poly: Expr::zero(&ring),
                symbolic: true
            };
            r
        ];
        r
    ];
    for ((&(a, b), solution), bracket) in pairs.iter().zip(solutions).zip(b_sym) {
        let entry = match solution {
            Some(sol) => {
                let (poly, symbolic) = lift_ctx.bracket(sol, bracket)?;
                Bracket::Polynomial { poly, symbolic }
            }
            // Over its common denominator, as a table shows brackets (the same element; as
            // it is without atoms).
            None => Bracket::Outside {
                bracket: bracket.over_common_denominators()?,
            },
        };
        let negated = match &entry {
            Bracket::Polynomial { poly, symbolic } => Bracket::Polynomial {
                poly: -poly,
                symbolic: *symbolic,
            },
            Bracket::Outside { bracket } => Bracket::Outside { bracket: -bracket },
        };
        brackets[a][b] = entry;
        brackets[b][a] = negated;
    }
    Ok(brackets)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::systems;

    /// The count the limit is checked against is the number of exponent vectors the closure
    /// then builds, and saturates instead of overflowing.
    #[test]
    fn monomial_count_is_the_number_of_monomials() {
        for r in 0..5 {
            for d in 0..7 {
                assert_eq!(
                    monomial_count(r, d),
                    monomials(r, d).len() as u128,
                    "r {r}, d {d}"
                );
            }
        }
        assert_eq!(monomial_count(5, 64), 11_238_513);
        assert_eq!(monomial_count(60, u32::MAX), u128::MAX);
    }

    #[test]
    fn complex_generators_close_with_one_relation() {
        let rotor = systems::harmonic_rotor();
        let c = closure(
            &rotor,
            &["Z", "Zbar", "F1", "F2", "L"],
            &ClosureOptions::new(2),
        )
        .unwrap();
        assert!(c.closes());
        assert!(c.all_symbolic());
        // {Z, Z̄} = 4iMω, {Z, F1} = iω Z (C11).
        assert_eq!(c.render_bracket(0, 1), "4iMω");
        assert_eq!(c.render_bracket(0, 2), "iω Z");
        // Z Z̄ = 2M(F1 − F2) + 2MωL, once (not again times i).
        assert_eq!(c.relations.len(), 1);
        // The 21 monomials of degree ≤ 2 in five generators span 20 dimensions over Q(i)
        // (it read 40, the dimension over Q of the monomials and i times them).
        assert_eq!((c.monomials, c.rank), (21, 20));
    }

    /// A target outside the generators' polynomials is `None`; one that is not homogeneous
    /// (off by a factor of a parameter) is written part by part, each part lifted and
    /// proved.
    #[test]
    fn a_target_is_expressed_part_by_part_or_not_at_all() {
        let rotor = systems::harmonic_rotor();
        let generators: Vec<NamedFunction> = ["F1", "L", "G1"]
            .iter()
            .map(|n| NamedFunction::new(n, n, rotor.get(n).unwrap().clone()))
            .collect();
        let options = ClosureOptions::new(2);
        let g2 = rotor.get("G2").unwrap();
        assert_eq!(
            expressed_in(&rotor, &generators, g2, &options).unwrap(),
            None
        );
        // {G1, G2} + M L = −ω² L + M L: two weights.
        let bracket = rotor.bracket(rotor.get("G1").unwrap(), g2).unwrap();
        let target = bracket.checked_add(&rotor.parse("M*L").unwrap()).unwrap();
        let found = expressed_in(&rotor, &generators, &target, &options)
            .unwrap()
            .expect("a polynomial in the generators");
        assert!(found.symbolic);
        assert_eq!(found.poly.to_string(), "M L − ω² L");
    }

    /// A complex target is written in real generators with Gaussian coefficients: `i L`,
    /// `iωL + G1`, and `L e^{−iθ} = L C − i L S` in `C = cos θ`, `S = sin θ` (the columns `i`
    /// times each monomial are formed where a target is complex, not only where a generator
    /// is); the real `L C` is written as before, and `e^{−iθ}` times `G2` not at all.
    #[test]
    fn a_complex_target_is_written_in_real_generators_over_the_gaussian_rationals() {
        let rotor = systems::harmonic_rotor();
        let mut generators: Vec<NamedFunction> = ["F1", "L", "G1"]
            .iter()
            .map(|n| NamedFunction::new(n, n, rotor.get(n).unwrap().clone()))
            .collect();
        for (name, value) in [("C", "cos(theta)"), ("S", "sin(theta)")] {
            generators.push(NamedFunction::new(name, name, rotor.parse(value).unwrap()));
        }
        let options = ClosureOptions::new(2);
        for (target, written) in [
            ("i*L", Some("i L")),
            ("G1 + i*omega*L", Some("iω L + G1")),
            ("L*exp(-i*theta)", Some("L C − i L S")),
            ("L*cos(theta)", Some("L C")),
            ("G2*exp(-i*theta)", None),
        ] {
            let target = rotor.parse(target).unwrap();
            let found = expressed_in(&rotor, &generators, &target, &options).unwrap();
            let found = found.map(|f| {
                assert!(f.symbolic, "{target}");
                f.poly.to_string()
            });
            assert_eq!(found.as_deref(), written, "{target}");
        }
    }

    /// With symbolic parameters, a target is sought among the monomials of its own weight
    /// only (the weights under which the fixed parameters weigh zero): `{G1, G2} = −ω² L`
    /// of the rotor with `M, ω` symbolic to degree 4 takes a fraction of the columns, and
    /// is found as before; with `M` fixed (weighing zero), the weights left still grade.
    #[test]
    fn a_target_is_sought_among_the_monomials_of_its_weight() {
        let rotor = systems::harmonic_rotor();
        let generators: Vec<NamedFunction> = ["F1", "F2", "L", "G1"]
            .iter()
            .map(|n| NamedFunction::new(n, n, rotor.get(n).unwrap().clone()))
            .collect();
        let target = rotor
            .bracket(rotor.get("G1").unwrap(), rotor.get("G2").unwrap())
            .unwrap();
        let columns = |options: &ClosureOptions, graded: bool| {
            let g_sym = span::restricted_generators(&rotor, &generators, None).unwrap();
            let scaling = scaling_of(&rotor, &generators, None).unwrap();
            let parts = homogeneous_parts(&scaling, &target).unwrap();
            let span = Span::new(
                &rotor,
                g_sym,
                &parts,
                &[],
                options,
                graded.then_some(&scaling),
            );
            span.unwrap().monos.len()
        };
        let symbolic = ClosureOptions::new(2)
            .symbolic(rotor.var("M"))
            .symbolic(rotor.var("omega"))
            .parameters_degree(4);
        let all = columns(&symbolic, false);
        let graded = columns(&symbolic, true);
        assert_eq!(all, 15 * 15);
        assert!(graded * 10 < all, "{graded} of {all}");
        let m_fixed = ClosureOptions::new(2)
            .symbolic(rotor.var("omega"))
            .parameters_degree(4);
        let graded_m_fixed = columns(&m_fixed, true);
        assert!(
            graded_m_fixed * 5 < 15 * 5,
            "{graded_m_fixed} of {}",
            15 * 5
        );
        for options in [symbolic, m_fixed] {
            let found = expressed_in(&rotor, &generators, &target, &options)
                .unwrap()
                .expect("a polynomial in the generators");
            assert!(found.symbolic);
            assert_eq!(found.poly.to_string(), "−ω² L");
        }
    }

    /// A generator named twice is refused in those words (the ring of generators said
    /// 'variable "L" is declared twice').
    #[test]
    fn a_generator_named_twice_is_refused() {
        let rotor = systems::harmonic_rotor();
        let err = closure(&rotor, &["L", "G1", "L"], &ClosureOptions::new(2)).unwrap_err();
        assert_eq!(err.to_string(), "L is named twice among the generators");
    }

    /// A generator or a target read in another variable set is refused, in a closure and in
    /// `expressed_in` (each panicked on the first variable of the system it looked up).
    #[test]
    fn functions_of_another_variable_set_are_refused() {
        let rotor = systems::harmonic_rotor();
        let vars = Vars::builder().coordinate("q").build().unwrap();
        let q = Expr::parse(&vars, "q").unwrap();
        let l = NamedFunction::new("L", "L", rotor.get("L").unwrap().clone());
        let foreign = [l.clone(), NamedFunction::new("Q", "Q", q.clone())];
        let options = ClosureOptions::new(1);
        let err = closure_of(&rotor, &foreign, &options).unwrap_err();
        assert_eq!(
            err.to_string(),
            "the generator Q is not a function of the system's variables (it was read in \
             another variable set)"
        );
        let err = expressed_in(&rotor, &foreign, &q, &options).unwrap_err();
        assert!(err.to_string().contains("the generator Q"), "{err}");
        let err = expressed_in(&rotor, &[l], &q, &options).unwrap_err();
        assert!(
            matches!(err, EngineError::Algebra(AlgebraError::VarSetMismatch)),
            "{err}"
        );
    }

    /// A parameter named twice is kept symbolic once, and the degree in the parameters is
    /// set apart from them, as a search's options take them.
    #[test]
    fn options_keep_a_parameter_symbolic_once() {
        let rotor = systems::harmonic_rotor();
        let (m, omega) = (rotor.var("M"), rotor.var("omega"));
        let options = ClosureOptions::new(2)
            .symbolic(m)
            .symbolic(omega)
            .symbolic(m)
            .parameters_degree(3);
        assert_eq!(
            (options.symbolic, options.parameters_degree),
            (vec![m, omega], 3)
        );
        let search = crate::search::SearchOptions::new(
            crate::search::SearchSpace::default()
                .momenta_degree(1)
                .positions_degree(1),
        )
        .symbolic(omega)
        .symbolic(omega);
        assert_eq!(search.symbolic, [omega]);
    }

    /// Options whose public field names a parameter twice give the closure of naming it once,
    /// as the builder does, not a second generator ω with the relation ω − ω = 0.
    #[test]
    fn a_parameter_named_twice_in_the_options_is_kept_symbolic_once() {
        let rotor = systems::harmonic_rotor();
        let omega = rotor.var("omega");
        let gens = ["F1", "F2", "L", "G1", "G2"];
        let once = closure(&rotor, &gens, &ClosureOptions::new(2).symbolic(omega)).unwrap();
        let twice = ClosureOptions {
            symbolic: vec![omega, omega],
            ..ClosureOptions::new(2)
        };
        let twice = closure(&rotor, &gens, &twice).unwrap();
        let relations = |c: &Closure| {
            (c.relations.iter())
                .map(|r| (r.degree, r.poly.to_string()))
                .collect::<Vec<_>>()
        };
        assert_eq!(relations(&twice), relations(&once));
        assert_eq!(twice.render_bracket(3, 4), once.render_bracket(3, 4));
    }

    /// With every parameter symbolic, the linear algebra runs on the symbolic expansions and
    /// its results hold as found: su(2) and its Casimir with `M, ω, I` as they are.
    #[test]
    fn every_parameter_symbolic() {
        let rotor = systems::harmonic_rotor();
        let mut options = ClosureOptions::new(2);
        for name in ["M", "omega", "I"] {
            options = options.symbolic(rotor.var(name));
        }
        let c = closure(&rotor, &["F1", "F2", "L", "G1", "G2"], &options).unwrap();
        assert!(c.parameters.is_empty() && c.all_symbolic());
        assert_eq!(c.render_bracket(3, 4), "−ω² L");
        assert_eq!(c.relations.len(), 1);
        assert_eq!(c.relations[0].degree, 2);
        // The relation, expanded in phase space, vanishes.
        let r = &c.relations[0].poly;
        let mut sum = Expr::zero(rotor.vars());
        for t in r.terms() {
            let mut term = Expr::constant(rotor.vars(), t.coeff());
            for (v, e) in c.ring.vars().zip(t.exponents()) {
                if e == 0 {
                    continue;
                }
                let name = c.ring.variable(v).name();
                let value = match c.names.iter().position(|n| n == name) {
                    Some(k) => rotor.get(&c.names[k]).unwrap().clone(),
                    None => Expr::var(rotor.vars(), rotor.var(name)),
                };
                term = term.checked_mul(&value.checked_pow(e).unwrap()).unwrap();
            }
            sum = sum.checked_add(&term).unwrap();
        }
        assert!(sum.is_zero(), "{r}");
    }

    /// `x, y` with their momenta, the parameters `a, b` and the atoms `x − y`, `x − a` and
    /// `a − b`; `H = (p_x² + p_y²)/2 + 1/(x − y)²` and the functions `(name, value)`.
    fn with_atoms(functions: &[(&str, &str)]) -> System {
        let vars = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .momentum("p_x")
            .momentum("p_y")
            .parameter("a")
            .parameter("b")
            .denominator("x - y")
            .unwrap()
            .denominator("x - a")
            .unwrap()
            .denominator("a - b")
            .unwrap()
            .build()
            .unwrap();
        let space = crate::PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y")]).unwrap();
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        let mut system = System::new("atoms", space, e("(p_x^2 + p_y^2)/2 + 1/(x - y)^2")).unwrap();
        for (name, value) in functions {
            system.define(name, name, e(value)).unwrap();
        }
        system
    }

    /// `x/(x − y) − y/(x − y) = 1` holds only by `v · D = 1`: the terms of the two sides
    /// share no monomial, so linear algebra on the monomials as written misses it; on the
    /// cleared images it is found, and proved.
    #[test]
    fn a_relation_by_clearing_is_found() {
        let system = with_atoms(&[("A", "x/(x - y)"), ("B", "y/(x - y)")]);
        let c = closure(&system, &["A", "B"], &ClosureOptions::new(2)).unwrap();
        assert_eq!(c.relations.len(), 1);
        assert_eq!(c.relations[0].poly.to_string(), "A − B − 1");
        assert!(c.relations[0].symbolic);
        // {A, B} = 0: the brackets of functions of x and y alone.
        assert_eq!(c.render_bracket(0, 1), "0");
        assert_eq!((c.monomials, c.rank), (6, 3));
    }

    /// One power of each `D` clears every vector: clearing each by its own power would send
    /// `p_x/(x − y)` and `p_x` to `p_x` both and report `U = V`, which is false.
    #[test]
    fn no_relation_by_clearing_vectors_apart() {
        let system = with_atoms(&[("U", "p_x/(x - y)"), ("V", "p_x")]);
        let c = closure(&system, &["U", "V"], &ClosureOptions::new(3)).unwrap();
        assert!(c.relations.is_empty(), "{:?}", c.relations);
        assert_eq!((c.monomials, c.rank), (10, 10));
        // {U, V} = −p_x/(x − y)² is no polynomial in U and V (U² = p_x²/(x − y)² has p_x²),
        // shown over its common denominator.
        assert_eq!(c.outside(), [(0, 1)]);
        assert_eq!(c.render_bracket(0, 1), "−p_x/(x − y)²");
    }

    /// A parameter that occurs only through an atom, `a` in `1/(x − a)`, is fixed for the
    /// linear algebra (the atom's polynomial at that value) and lifted back: `a W + 1 = X`.
    #[test]
    fn a_parameter_in_an_atom_is_lifted() {
        let system = with_atoms(&[("W", "1/(x - a)"), ("X", "x/(x - a)")]);
        let c = closure(&system, &["W", "X"], &ClosureOptions::new(2)).unwrap();
        assert_eq!(c.parameters, [(system.var("a"), Rational::one())]);
        assert_eq!(c.relations.len(), 1);
        assert_eq!(c.relations[0].poly.to_string(), "a W − X + 1");
        assert!(c.relations[0].symbolic);
        // Kept symbolic, the same relation is found from the symbolic expansions.
        let options = ClosureOptions::new(2)
            .symbolic(system.var("a"))
            .parameters_degree(1);
        let c = closure(&system, &["W", "X"], &options).unwrap();
        assert!(c.parameters.is_empty() && c.all_symbolic());
        assert_eq!(c.relations[0].poly.to_string(), "a W − X + 1");
    }

    /// An atom that no generator divides by needs no value other than zero: the closure of
    /// functions free of `1/(a − b)` on a system that declares `a − b` is found at `a = b`
    /// (it was refused, "the denominator (a − b) is zero at a = 1, b = 1", for a denominator
    /// nothing divided by), and so at the default values; one that divides by it still is.
    #[test]
    fn an_atom_no_generator_divides_by_may_vanish_at_the_fixed_values() {
        let system = with_atoms(&[("P", "p_x + p_y"), ("X", "(a - b)*x"), ("T", "x/(a - b)")]);
        let (a, b) = (system.var("a"), system.var("b"));
        let equal = ClosureOptions::new(1)
            .fix(a, Rational::from(3))
            .fix(b, Rational::from(3));
        let c = closure(&system, &["H", "P"], &equal).unwrap();
        assert!(c.closes());
        assert_eq!(c.render_bracket(0, 1), "0");
        // (a − b) x is 0 at a = b: the relation X = 0 holds there.
        let c = closure(&system, &["P", "X"], &equal).unwrap();
        assert_eq!(c.relations.len(), 1);
        assert_eq!(c.relations[0].poly.to_string(), "X");
        assert!(closure(&system, &["H", "P"], &ClosureOptions::new(1)).is_ok());
        let err = closure(&system, &["P", "T"], &equal).unwrap_err();
        assert!(err
            .to_string()
            .starts_with("the denominator (a − b) is zero at a = 3, b = 3"));
    }

    /// An atom whose polynomial vanishes at the given values has no value there: refused,
    /// with the values to change; other values work. When it vanishes at the default values,
    /// 1, the parameters in it take generic values instead.
    #[test]
    fn an_atom_zero_at_the_fixed_values_is_refused() {
        let system = with_atoms(&[("T", "x/(a - b)"), ("X", "x")]);
        let (a, b) = (system.var("a"), system.var("b"));
        let c = closure(&system, &["T", "X"], &ClosureOptions::new(1)).unwrap();
        let generic = |(n, d): (i64, i64)| Rational::new(n, d);
        let (va, vb) = (
            generic(crate::search::GENERIC_VALUES[0]),
            generic(crate::search::GENERIC_VALUES[1]),
        );
        assert_eq!((&va, &vb), (&Rational::from(7), &Rational::new(11, 2)));
        assert_eq!(c.parameters, [(a, va), (b, vb)]);
        let atom = c
            .denominator_zero_at_one
            .expect("a − b is zero at a = b = 1");
        assert_eq!(system.vars().variable(atom).unicode(), "(a − b)");
        // (a − b) T = X, at these values: (7 − 11/2) T = X.
        assert_eq!(c.relations.len(), 1);
        assert_eq!(c.relations[0].poly.to_string(), "3 T − 2 X");
        assert!(!c.relations[0].symbolic);
        let options = ClosureOptions::new(1)
            .fix(a, Rational::one())
            .fix(b, Rational::one());
        let err = closure(&system, &["T", "X"], &options).unwrap_err();
        assert_eq!(
            err.to_string(),
            "the denominator (a − b) is zero at a = 1, b = 1, the values the linear algebra \
             takes: give other values (the options' `fix`; on the command line, --fix)"
        );
        let options = ClosureOptions::new(1).fix(system.var("b"), Rational::from(2));
        let c = closure(&system, &["T", "X"], &options).unwrap();
        assert_eq!(c.relations.len(), 1);
        // (a − b) T = X holds at a = 1, b = 2 as T + X = 0; its coefficient a − b is no
        // monomial, so homogeneity cannot lift it, and it is not claimed for other values.
        assert_eq!(c.relations[0].poly.to_string(), "T + X");
        assert!(!c.relations[0].symbolic);
    }

    #[test]
    fn surface_constants_are_relations_of_their_own() {
        let mut rotor = systems::harmonic_rotor();
        let k = rotor.resonant("Z", 1, 1).unwrap();
        rotor.define("P", "P", k.p).unwrap();
        rotor.define("Q", "Q", k.q).unwrap();
        let options = ClosureOptions::new(2).when(rotor.resonance(1, 1).unwrap());
        let c = closure(&rotor, &["F1", "F2", "L", "P", "Q"], &options).unwrap();
        assert_eq!(c.render_bracket(3, 4), "−2Mω");
        let first = c.relations[0].poly.to_string();
        assert_eq!(first, "−ω²I/2 + F2");
        assert!(c.relations.iter().all(|r| r.symbolic));
    }

    /// A relation left out as a combination of those listed keeps its multiples in the span:
    /// with `h = x², y = p², k = x²p, a = x⁵p³`, `h a² = k⁶` (degree 6) is
    /// `k⁴(h² y − k²) − h(h y k⁴ − a²)`, through multiples of degree 7. Degree 6 lists it;
    /// degree 7 leaves it out, and its multiples `h² a² = h k⁶`, `h y a² = y k⁶`, …, which the
    /// multiples of degree `≤ 7` of the two listed do not reach, were listed in its place.
    #[test]
    fn the_multiples_of_a_relation_left_out_are_not_listed() {
        let vars = Vars::builder()
            .coordinate("x")
            .momentum("p_x")
            .build()
            .unwrap();
        let space = crate::PhaseSpace::new(&vars, &[("x", "p_x")]).unwrap();
        let mut system =
            System::new("x, p", space, Expr::parse(&vars, "p_x^2/2").unwrap()).unwrap();
        for (name, value) in [
            ("h", "x^2"),
            ("y", "p_x^2"),
            ("k", "x^2*p_x"),
            ("a", "x^5*p_x^3"),
        ] {
            system.define_parsed(name, name, value).unwrap();
        }
        let relations = |degree| {
            let c = closure(&system, &["h", "y", "k", "a"], &ClosureOptions::new(degree)).unwrap();
            c.relations
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
        };
        assert_eq!(relations(6), ["h² y = k²", "h y k⁴ = a²", "h a² = k⁶"]);
        assert_eq!(relations(7), ["h² y = k²", "h y k⁴ = a²"]);
    }

    /// A closure checks over Q, in one sum a phase, each combination found modulo p: the
    /// kernel's vectors, the brackets' solutions, and each relation found in the span of the
    /// multiples of those before it (`closure/minimal.rs`). The sums grow by at most the span's
    /// rows each, and the relations' by at most one row a monomial; a sum for each check grew
    /// to its largest row every time (at degree 5, 55 relations checked in sums of up to 228
    /// rows, 7 428 rows in all, where the span has 984 rows and 252 monomials).
    #[test]
    fn a_closure_checks_its_combinations_in_one_sum_a_phase() {
        let rotor = systems::harmonic_rotor();
        let names = ["F1", "F2", "L", "G1", "G2"];
        let options = ClosureOptions::new(5);
        let before = modular::SUMS_GROWN.get();
        let c = closure(&rotor, &names, &options).unwrap();
        let grown = modular::SUMS_GROWN.get() - before;
        assert_eq!(c.relations.len(), 1);
        // The span's rows, formed as `closure_of` forms them.
        let generators: Vec<NamedFunction> = (names.iter())
            .map(|n| NamedFunction::new(n, n, rotor.get(n).unwrap().clone()))
            .collect();
        let g_sym = span::restricted_generators(&rotor, &generators, None).unwrap();
        let brackets: Vec<Expr> = (0..names.len())
            .flat_map(|a| (a + 1..names.len()).map(move |b| (a, b)))
            .map(|(a, b)| rotor.bracket(&generators[a].expr, &generators[b].expr))
            .collect::<Result<_, _>>()
            .unwrap();
        let span = Span::new(&rotor, g_sym, &brackets, &[], &options, None).unwrap();
        let bound = 2 * span.nrows + c.monomials;
        assert!(
            grown <= bound,
            "the checks grew their sums by {grown} rows, more than the {} rows twice and the \
             {} monomials",
            span.nrows,
            c.monomials
        );
    }

    /// The brackets' solutions are checked in one sum: ten targets, each a multiple of a
    /// column with an entry on the last of 300 rows, grow it by 300 rows (a sum for each grew
    /// by 3 000).
    #[test]
    fn the_targets_are_checked_in_one_sum() {
        let rows = 300;
        let q = Rational::from;
        let mut columns: Vec<SparseVec<Rational>> = vec![vec![(0, q(1)), (rows - 1, q(1))]];
        columns.extend((1..rows - 1).map(|i| vec![(i, q(1))]));
        let targets: Vec<SparseVec<Rational>> = (1..=10)
            .map(|k| vec![(0, q(k)), (rows - 1, q(k))])
            .collect();
        let before = modular::SUMS_GROWN.get();
        let solutions = express_targets(&columns, rows, &targets);
        let grown = modular::SUMS_GROWN.get() - before;
        for (k, solution) in (1..=10).zip(&solutions) {
            assert_eq!(solution.as_ref(), Some(&vec![(0, q(k))]));
        }
        assert!(grown <= rows, "10 checks grew their sums by {grown} rows");
    }
}
