//! Discovery: a basis of *all* integrals of a system in a finite space of functions, found by
//! exact linear algebra, each basis element proved by the engine.
//!
//! The space ([`SearchSpace`]) is spanned by `x^a y^b · p_x^c p_y^d · M₁^m M₂^n · {1, cos kθ,
//! sin kθ}`: coordinates of total degree `Σ|a| ≤ e` (negative exponents too when `laurent`),
//! momenta of total degree `≤ d`, Poisson variables (whose brackets are declared, such as the
//! `M₁, M₂, M₃` of so(3)*) of total degree `≤ P`, and trigonometric order `Σ|k| ≤ K` in the
//! angles. An angle's momentum or a Poisson variable that the condition fixes is left out: on a
//! resonance surface `p_θ = mIω/n` it is a constant, and every function of it is an integral
//! ([`SpaceVariables`]); one it sets to a function of the others is left out too, and the
//! others parametrise the surface. The images `{φ, H}` are the bracket's, declared brackets
//! included: for each phase variable `v`, `∂φ/∂v` times `{v, H}` (after the condition), formed
//! once.
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
//! zero is reported and each integral has one set of coordinates. A parameter kept symbolic
//! that a denominator holds is compared with the coordinates in that choice (the parameters
//! then all are, their degree being bounded together). Which integrals are new (`new_only`) is decided
//! the same way: a known integral or a product of integrals, which may be written in other
//! monomials or in powers of `1/D` past the space's, lies in the space exactly when its
//! cleared image is a combination of the basis integrals' (`locate`); the powers of `1/D`
//! count with the coordinates in a grade, and bound only how many factors a product has.
//!
//! On a system with radicals (`r = √R`, [`trigpoly::VarKind::Radical`]) the space also has the
//! products `Π r_i^{j_i}` of either sign with `Σ |j_i| ≤` [`SearchSpace::radicals_degree`]
//! (`−k/r` and `x/r` of the Kepler problem), and the same holds with the images reduced by
//! `r² = R` (`x²/r + y²/r = r` for `R = x² + y²`): the unknowns, the equations and what is new
//! are decided on the reduced forms, and so with a parameter kept symbolic in a radicand
//! (`a² = r² − x² + 2ax − y²` for `R = (x − a)² + y²`). The parameter multiples `a·X` of
//! integrals that lie in the space are the relations `a·Σ c_j I_j = Σ d_k I_k` among the
//! basis integrals, found on the same images.
//!
//! ```
//! use brackets::search::{search, SearchOptions, SearchSpace};
//! use brackets::systems;
//!
//! // The harmonic rotor at p_θ = Iω: the integrals linear in the momenta, trig order ≤ 1.
//! let rotor = systems::harmonic_rotor();
//! let options = SearchOptions::new(SearchSpace::default().momenta_degree(1).positions_degree(1).trig_degree(1)).when(rotor.resonance(1, 1)?);
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
//! use trigpoly::{Expr, Rational, Vars};
//!
//! let vars = Vars::builder()
//!     .poisson("M1").poisson("M2").poisson("M3")
//!     .parameter("I1").parameter("I2").parameter("I3")
//!     .build()?;
//! let e = |s: &str| Expr::parse(&vars, s).unwrap();
//! let space = PhaseSpace::new(&vars, &[])?
//!     .with_brackets(&[("M1", "M2", e("M3")), ("M2", "M3", e("M1")), ("M3", "M1", e("M2"))])?;
//! let top = System::new("Euler top", space, e("M1^2/(2*I1) + M2^2/(2*I2) + M3^2/(2*I3)"))?;
//! // At I = (1, 2, 3): 1, then two quadratic integrals (|M|² and H, combined).
//! let mut options = SearchOptions::new(SearchSpace::default().poisson_degree(2));
//! for (i, name) in ["I1", "I2", "I3"].into_iter().enumerate() {
//!     options = options.fix(top.var(name), Rational::from(i as i64 + 1));
//! }
//! let found = search(&top, &options)?;
//! assert_eq!(found.dimensions_by_poisson_degree(), [1, 1, 3]);
//! assert!(found.basis.iter().all(|f| f.proved_fixed));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod exceptional;
mod independence;
mod level_set;
mod locate;
mod new_only;
mod options;
mod parameters;
mod problem;
mod proof;
mod result;
#[cfg(test)]
mod tests;

pub use exceptional::{
    basis_rank, exceptional_candidates, exceptional_values, generation_decided,
    level_set_graph_variable, BasisGenerators, Candidates, DenominatorRoot, Determinants,
    ExceptionalValue, ExceptionalValues, RuledOut, MAX_RANK_MINORS, SEARCH_RANK_MINORS,
};
pub use level_set::{
    BesideLevelSet, LevelProof, LevelReduction, LevelSet, SharedRelation, SharedVariable,
};
pub use options::{SearchOptions, SearchSpace, DEFAULT_MAX_MINOR, DEFAULT_MAX_PRODUCTS};
pub(crate) use parameters::{check_parameters, off_vanishing_denominators};
pub use parameters::{fix_parameters, GENERIC_VALUES};
pub(crate) use proof::is_phase_free;
pub use proof::lift_and_prove;
pub use result::{
    parameter_text, Integral, NewIntegrals, NormalFormOutside, ParameterModule, SearchResult,
    SearchTimings, SearchedLevel, SpaceVariables,
};

use rustc_hash::FxHashMap;
use std::borrow::Cow;
use std::time::Instant;

use itertools::Itertools;
use rayon::prelude::*;
use trigpoly::{Expr, MonomialIndex, Rational, Var, VarKind};

use crate::claim::Condition;
use crate::clearing::{refuse_division_by_zero, Clearing};
use crate::error::EngineError;
use crate::modular::{self, SparseVec};
use crate::scaling::{Lifter, Scaling};
use crate::system::System;

use level_set::OnLevel;
use new_only::new_integrals;
use parameters::{
    fixed_hamiltonian_and_condition, module_generators, parameter_denominators,
    parameter_multiples, parameter_values,
};
use problem::{real_rows, AtValues, Problem, RowIndex, IMAGE_BLOCK};
use proof::{flow_vanishes, lead, primitive_vector};

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
/// let options = SearchOptions::new(SearchSpace::default().momenta_degree(1).positions_degree(1).trig_degree(1)).when(resonance.clone());
/// let found = search(&rotor, &options)?;
/// assert_eq!(found.basis.len(), 6);
/// for integral in &found.basis {
///     assert!(rotor.flow_when(integral.expr(), &resonance)?.is_zero());
/// }
/// # Ok::<(), brackets::EngineError>(())
/// ```
///
/// The linear algebra is done with every parameter of `H` (and of the condition) fixed, to 1
/// unless [`SearchOptions::fix`] gives another value or [`SearchOptions::symbolic`] keeps it;
/// each integral found is then lifted back to the parameters where it can be. One that holds
/// at the fixed values alone is proved there only: [`SearchResult::for_every_value`] is `None`
/// for it, and a symmetry of those values (all equal) may bring many.
///
/// ```
/// use brackets::{search, PhaseSpace, SearchOptions, SearchSpace, System};
/// use trigpoly::{Expr, Rational, Vars};
///
/// // p²/2 + (x² + a²y²)/2: at a = 1 (the default) the oscillator is isotropic, and its
/// // angular momentum x p_y − y p_x is an integral there alone; at a = 2 it is none.
/// let vars = Vars::builder()
///     .coordinate("x").coordinate("y").momentum("p_x").momentum("p_y").parameter("a")
///     .build()?;
/// let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y")])?;
/// let h = Expr::parse(&vars, "(p_x^2 + p_y^2)/2 + (x^2 + a^2*y^2)/2")?;
/// let oscillator = System::new("oscillator", space, h)?;
/// let at_one = search(&oscillator, &SearchOptions::new(SearchSpace::default().momenta_degree(2).positions_degree(2)))?;
/// assert_eq!(at_one.basis.len(), 6);
/// assert_eq!(at_one.basis[1].expr().to_string(), "x p_y − y p_x");
/// assert_eq!(at_one.for_every_value(1), None);
/// let a = vars.lookup("a").unwrap();
/// let options = SearchOptions::new(SearchSpace::default().momenta_degree(2).positions_degree(2)).fix(a, Rational::from(2));
/// assert_eq!(search(&oscillator, &options)?.basis.len(), 3);
/// # Ok::<(), Box<dyn std::error::Error>>(())
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
    let FixedSearch {
        parameters,
        denominator_zero_at_one,
        problem,
        on,
    } = fixed_search_problem(system, options)?;

    // The images {φ_j, H} as real equations over Q, and their kernel, block by block.
    let (solved, nrows) = solve(system, &problem, &parameters, start, &mut timings)?;
    let Kernel {
        mut kernel,
        components,
        largest_component,
    } = solved;

    // Proofs: at the fixed values, then lifted and proved symbolically.
    let t = Instant::now();
    let prover = Prover::new(system, condition, &problem, &parameters)?;
    let basis = prover.prove_all(&mut kernel)?;
    let liftable = prover.lifter.is_some();
    timings.proofs = t.elapsed().as_secs_f64();

    let multiples = parameter_multiples(system, &problem, &options.symbolic, &kernel, &basis)?;
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
        denominators: parameter_denominators(
            &problem,
            system.space().denominator_atoms(),
            &options.symbolic,
        )
        .collect(),
    });
    timings.total = start.elapsed().as_secs_f64();
    Ok(SearchResult {
        space: options.space,
        condition: condition.map(|c| c.text.clone()),
        on,
        parameters,
        denominator_zero_at_one,
        liftable,
        vars: system.vars().clone(),
        variables: problem.variables.clone(),
        unknowns: problem.unknowns.len(),
        equations: nrows,
        components,
        largest_component,
        basis,
        new,
        module,
        timings,
    })
}

/// The search at fixed parameter values: the values, why they are not 1 if they are not, and
/// the linear problem at them.
struct FixedSearch {
    parameters: Vec<(Var, Rational)>,
    /// The declared denominator that 1 makes zero, which moved its parameters off 1.
    denominator_zero_at_one: Option<Var>,
    problem: Problem,
    /// The level set searched on, if any.
    on: Option<SearchedLevel>,
}

/// Refuses the condition `c` for a search in `space`, which substitutes the condition's values
/// of the declared denominators too, into a space that may hold any of them: one without them
/// (denominators degree 0) refuses a denominator without a value only where `H` holds it, as a
/// claim does (a driven oscillator at its resonance, beside a function over `ω² − Ω²`).
fn refuse_unvalued_denominators(
    c: &Condition,
    system: &System,
    space: &SearchSpace,
) -> Result<(), EngineError> {
    match space.denominators_degree {
        0 => c.values_denominators_of(system.hamiltonian()),
        _ => c.values_denominators(),
    }
}

/// The parameters' values for the linear algebra and the linear problem at those values,
/// once what the search cannot answer is refused: a condition that the flow leaves, fixed or
/// symbolic parameters that are no parameters of the system, what [`refuse_unreal`]
/// refuses, and, for new integrals, a known integral given that is not real or none
/// ([`new_only::refuse_given_known`]).
fn fixed_search_problem(
    system: &System,
    options: &SearchOptions,
) -> Result<FixedSearch, EngineError> {
    let condition = options.condition.as_ref();
    if let Some(level) = &options.on {
        refuse_beside_level_set(options)?;
        level.check(system, &options.fixed, options.space.laurent)?;
    }
    if let Some(c) = condition {
        refuse_unvalued_denominators(c, system, &options.space)?;
        c.kept_by_flow(system)?;
        c.defined_on(&[system.hamiltonian()], "the Hamiltonian")?;
    }
    check_parameters(system.vars(), &options.symbolic, &options.fixed)?;
    refuse_unreal(system, options)?;
    let mut parameters = parameter_values(system, condition, &options.fixed, &options.symbolic);
    if let Some(level) = &options.on {
        with_level_parameters(level, &options.fixed, &mut parameters)?;
    }
    let zero_at_one = off_vanishing_denominators(
        system.vars(),
        &mut parameters,
        &options.fixed,
        system.space().denominator_atoms().iter(),
    );
    // `H` and the condition enter every image, but a term of them that divides by an atom may
    // leave none (a constant's bracket is zero): refused where that atom vanishes too.
    refuse_division_by_zero(
        system.space().denominator_atoms(),
        &parameters,
        std::iter::once(system.hamiltonian())
            .chain(condition.into_iter().flat_map(Condition::values)),
    )?;
    let fixed = fixed_hamiltonian_and_condition(system, options, &parameters)?;
    let on_level = match &options.on {
        Some(level) => Some(OnLevel::new(level, system, &parameters)?),
        None => None,
    };
    // A known integral that is none is refused here, before the space's unknowns are formed.
    if options.new_only {
        let at = AtValues {
            h: &fixed.h,
            condition: fixed.condition.as_deref(),
            parameters: &parameters,
        };
        new_only::refuse_given_known(system, &at, on_level.as_ref(), options)?;
    }
    let problem = fixed.problem(system, options, &parameters)?;
    let (problem, on) = match (&options.on, on_level) {
        (Some(level), Some(at)) => {
            let leading_monomial = Expr::from_terms(
                system.vars(),
                [(trigpoly::GaussianRational::from(1), at.lead.clone())],
            )?;
            let kept_for_every_value = at.kept_for_every_value;
            let (problem, left_out, normal_form_outside) = problem.restricted_to(at)?;
            let searched = SearchedLevel {
                kept_for_every_value,
                level: level.clone(),
                polynomial: level.polynomial()?,
                leading_monomial,
                left_out,
                normal_form_outside,
            };
            (problem, Some(searched))
        }
        _ => (problem, None),
    };
    Ok(FixedSearch {
        parameters,
        denominator_zero_at_one: zero_at_one,
        problem,
        on,
    })
}

/// Refuses what a search on a level set does not take ([`BesideLevelSet::for_search`]).
fn refuse_beside_level_set(options: &SearchOptions) -> Result<(), EngineError> {
    match BesideLevelSet::for_search(options) {
        Some(refused) => Err(EngineError::Invalid(format!(
            "a search on a level set does not take {refused}"
        ))),
        None => Ok(()),
    }
}

/// Adds to `parameters` those of the level set's polynomial that they lack, at their value in
/// `given` or 1, in the order of their declaration.
fn with_level_parameters(
    level: &LevelSet,
    given: &[(Var, Rational)],
    parameters: &mut Vec<(Var, Rational)>,
) -> Result<(), EngineError> {
    for (v, value) in level_set::level_parameter_values(&level.polynomial()?, given) {
        if !parameters.iter().any(|(w, _)| *w == v) {
            parameters.push((v, value));
        }
    }
    parameters.sort_by_key(|(v, _)| v.index());
    Ok(())
}

/// The kernel of the problem's equations and how many equations there are: the images
/// `{φ_j, H}` as real equations over Q, one column an unknown, then their kernel, block by
/// block. The time from `start` to the equations, and the time of the kernel, go to
/// `timings`.
fn solve(
    system: &System,
    problem: &Problem,
    parameters: &[(Var, Rational)],
    start: Instant,
    timings: &mut SearchTimings,
) -> Result<(Kernel, usize), EngineError> {
    let space = system.space();
    let (atoms, radicals) = (space.denominator_atoms(), space.radicals());
    let (columns, nrows) = equations(problem, atoms, radicals, parameters)?;
    timings.equations = start.elapsed().as_secs_f64();
    let t = Instant::now();
    let kernel = kernel_by_blocks(&columns, nrows);
    timings.solve = t.elapsed().as_secs_f64();
    Ok((kernel, nrows))
}

/// What proving the kernel's vectors takes: the system, the condition, the problem and the
/// parameters' fixed values, and the lift back to symbolic parameters where there is one.
struct Prover<'a> {
    system: &'a System,
    condition: Option<&'a Condition>,
    problem: &'a Problem,
    parameters: &'a [(Var, Rational)],
    /// The weights under which the flow is homogeneous, by which the lift restores the
    /// parameters.
    scaling: Scaling,
    /// The lift from the fixed values; `None` where the weights do not determine every fixed
    /// parameter's exponent, or one is fixed to 0.
    lifter: Option<Lifter>,
}

impl<'a> Prover<'a> {
    /// The prover of a search's basis at the fixed values `parameters`, with the lift that
    /// the flow's homogeneity gives.
    fn new(
        system: &'a System,
        condition: Option<&'a Condition>,
        problem: &'a Problem,
        parameters: &'a [(Var, Rational)],
    ) -> Result<Self, EngineError> {
        let scaling = Scaling::of_flow(system.space(), system.hamiltonian(), condition)?;
        let lifter = scaling.lifter(parameters);
        Ok(Prover {
            system,
            condition,
            problem,
            parameters,
            scaling,
            lifter,
        })
    }

    /// The integral of each kernel vector, which is made primitive in place, proved.
    fn prove_all(&self, kernel: &mut [SparseVec<Rational>]) -> Result<Vec<Integral>, EngineError> {
        // Each basis element is proved on its own, on the pool's threads; the first error in
        // the order of the basis is the one reported.
        let proved: Vec<Result<Integral, EngineError>> =
            kernel.par_iter_mut().map(|v| self.prove(v)).collect();
        proved.into_iter().collect()
    }

    /// The integral of one kernel vector `v`, made primitive: proved at the fixed values, then
    /// lifted to symbolic parameters and proved again where it can be.
    fn prove(&self, v: &mut SparseVec<Rational>) -> Result<Integral, EngineError> {
        let (system, condition, problem) = (self.system, self.condition, self.problem);
        *v = primitive_vector(v);
        let fixed = problem.combination(v)?;
        let last = lead(v).expect("a kernel vector is not zero").0;
        let reference = problem.leading_exponents(last);
        if let Some(level) = &problem.level {
            return self.prove_on_level(level, fixed, &reference);
        }
        let proved_fixed = problem.vanishes(system, &problem.flow(system, &fixed)?)?;
        let symbolic = match &self.lifter {
            // Nothing was fixed: the integral found is the symbolic one.
            _ if self.parameters.is_empty() => proved_fixed.then(|| fixed.clone()),
            Some(l) => lift_and_prove(
                system,
                condition,
                l,
                &self.scaling,
                &fixed,
                Some(&reference),
            )?,
            None => None,
        };
        // What the weights cannot lift may hold as found, for every value: `p_θ`, or `L`
        // of a potential whose parameter the lift cannot restore.
        let symbolic = match symbolic {
            None if proved_fixed && !self.parameters.is_empty() => {
                flow_vanishes(system, condition, &fixed)?.then(|| fixed.clone())
            }
            found => found,
        };
        Ok(integral(fixed, proved_fixed, symbolic, None))
    }

    /// [`Prover::prove`] on a level set: `{K, H} = P·Q` at the fixed values, then, lifted to
    /// the parameters (or as found, where the lift fails), with `P`'s parameters too, where
    /// its leading coefficient is a number for every value of them.
    fn prove_on_level(
        &self,
        level: &OnLevel,
        fixed: Expr,
        reference: &[i64],
    ) -> Result<Integral, EngineError> {
        let system = self.system;
        let flow = self.problem.flow(system, &fixed)?;
        let at_fixed = level.prove(system, &flow, &level.fixed, self.parameters)?;
        let prove_symbolic = |f: &Expr| -> Result<Option<LevelProof>, EngineError> {
            match &level.symbolic {
                Some(p) => level.prove(system, &system.bracket(f, system.hamiltonian())?, p, &[]),
                None => Ok(None),
            }
        };
        let mut symbolic: Option<(Expr, LevelProof)> = None;
        if let Some(proof) = &at_fixed {
            if self.parameters.is_empty() {
                symbolic = Some((fixed.clone(), proof.clone()));
            }
            if let (None, Some(lifter)) = (&symbolic, &self.lifter) {
                if let Some(f) = lifter.lift(&self.scaling, &fixed, Some(reference))? {
                    let f = proof::real_primitive(&f);
                    symbolic = prove_symbolic(&f)?.map(|proof| (f, proof));
                }
            }
            if symbolic.is_none() {
                symbolic = prove_symbolic(&fixed)?.map(|proof| (fixed.clone(), proof));
            }
        }
        let proved_fixed = at_fixed.is_some();
        let (symbolic, on_level) = match symbolic {
            Some((f, proof)) => (Some(f), Some(proof)),
            None => (None, at_fixed),
        };
        Ok(integral(fixed, proved_fixed, symbolic, on_level))
    }
}

/// The integral `fixed` found, with its degrees, the proof's outcome at the fixed values, the
/// integral lifted and proved with its parameters, and on a level set the proof there.
fn integral(
    fixed: Expr,
    proved_fixed: bool,
    symbolic: Option<Expr>,
    on_level: Option<LevelProof>,
) -> Integral {
    let deg = |kinds: &[VarKind]| fixed.total_degree(kinds).unwrap_or(0);
    Integral {
        // Every momentum of the space (an angle's momentum fixed by the condition
        // does not occur).
        momenta_degree: deg(&[VarKind::Momentum]),
        poisson_degree: deg(&[VarKind::Poisson]),
        positions_degree: deg(&[VarKind::Coordinate]),
        trig_degree: deg(&[VarKind::Angle]),
        fixed,
        proved_fixed,
        symbolic,
        on_level,
    }
}

/// Refuses what the search cannot answer: a Hamiltonian that is not real, a condition whose
/// values are not, and a parameter the condition sets that is also fixed or kept symbolic.
fn refuse_unreal(system: &System, options: &SearchOptions) -> Result<(), EngineError> {
    let vars = system.vars();
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
    Ok(())
}

/// The images `{φ_j, H}` of the unknowns as real equations over Q, one column each: a row for
/// the real and for the imaginary part of each monomial with a canonical `e^{ik·θ}`, numbered
/// as they first appear; and how many rows there are. The images are formed on the pool's
/// threads, a block of unknowns at a time, and numbered in the order of the unknowns. With
/// denominator atoms or radicals they are taken through one injective `Clearing`, whose powers
/// are the highest among all the images: formed in one block.
fn equations(
    problem: &Problem,
    atoms: &[(Var, Expr)],
    radicals: &[(Var, Expr)],
    parameters: &[(Var, Rational)],
) -> Result<(Vec<SparseVec<Rational>>, usize), EngineError> {
    let n = problem.unknowns.len();
    let block = if atoms.is_empty() && radicals.is_empty() {
        IMAGE_BLOCK
    } else {
        n.max(1)
    };
    let mut rows: RowIndex = MonomialIndex::new(&problem.vars);
    let mut nrows = 0;
    let mut columns: Vec<SparseVec<Rational>> = Vec::with_capacity(n);
    for start in (0..n).step_by(block) {
        let images: Vec<Result<Expr, EngineError>> = (start..n.min(start + block))
            .into_par_iter()
            .map(|j| problem.image(&problem.expr(j, &Rational::one())?))
            .collect();
        let images = images.into_iter().collect::<Result<Vec<Expr>, _>>()?;
        let clearing = Clearing::new(atoms, radicals, parameters, images.iter())?;
        // The clearing's powers need every image; its images are made and numbered into
        // equations a block at a time, so that they are not all held beside the equations.
        for part in images.chunks(CLEARED_BLOCK) {
            let cleared = match &clearing {
                Some(clearing) => Cow::Owned(clearing.apply_all(part)?),
                None => Cow::Borrowed(part),
            };
            for image in cleared.iter() {
                columns.push(real_rows(
                    image,
                    &problem.variables.angles,
                    &mut rows,
                    &mut nrows,
                ));
            }
        }
    }
    Ok((columns, nrows))
}

/// How many images are cleared of denominators and radicals at a time: enough to share among
/// the pool's threads, few enough that the cleared polynomials, larger than the images, are
/// never all held beside the equations (at 6220 unknowns they were a fifth of the peak).
const CLEARED_BLOCK: usize = 256;

/// The kernel of the equations, found block by block.
struct Kernel {
    /// Its basis, by leading (last) unknown.
    kernel: Vec<SparseVec<Rational>>,
    /// How many independent blocks the unknowns fall into.
    components: usize,
    /// The unknowns of the largest block.
    largest_component: usize,
}

/// The kernel of the columns: the unknowns that share no equation fall into independent
/// blocks (connected components), solved on the pool's threads and kept in the order of the
/// blocks; the basis sorted by leading (last) unknown, i.e. in the order of the unknowns.
fn kernel_by_blocks(columns: &[SparseVec<Rational>], nrows: usize) -> Kernel {
    let groups = problem::blocks(columns, nrows);
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
    Kernel {
        kernel,
        components: groups.len(),
        largest_component,
    }
}
