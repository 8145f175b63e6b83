//! The exceptional values of a parameter: the values `t0` of one parameter `t` at which the
//! space holds more integrals than at a generic value (Hietarinta's "direct method", done
//! exactly), each confirmed by the ordinary search at `t0`.
//!
//! With `t` kept as a variable and the other parameters fixed, the equations `{Σ c_j φ_j, H} = 0`
//! are `M(t) c = 0`, the entries of `M` polynomials in `t` (a row with negative powers of `t`, from
//! a negative power in `H`, multiplied by `t^k` for its largest negative exponent `−k`, which
//! changes the kernel at no `t ≠ 0`; `t = 0`, where `H` has no value, is then no candidate; so
//! for a declared denominator `d(t)` of parameters alone, each row times `d(t)^k`, its roots no
//! candidates, the unknowns `φ/d(t)^e` left out as the columns of `φ` times `1/d(t)^e`). Let
//! `r` be its generic rank: the values where the kernel is larger are those where every `r×r` minor
//! vanishes. `M` splits into blocks (unknowns sharing no equation); in each, the rank and an `r×r`
//! submatrix `S` nonsingular at a random point are found modulo a prime, and `det S(t)` is computed
//! exactly: modulo primes whose product passes twice a bound on its coefficients (Hadamard's,
//! on the unit circle: the product of the rows' Euclidean norms of their entries' sums of
//! absolute coefficients), each time from its values at `deg + 1` points (`deg` the sum of the
//! rows' largest degrees or of the columns', whichever is smaller), then by the Chinese remainder theorem. Every exceptional value is a root of `det S` of some block. Its rational
//! roots are found exactly ([`IntPoly::rational_roots`]), and each is kept only if the ordinary
//! search at that value finds more integrals than at a generic value (one that is no root).
//!
//! The other roots, those of `g`, the lcm of the determinants' square-free parts with their
//! rational factors divided out, are ruled out where they can be ([`RuledOut`]), exactly. Take
//! a prime `p` not dividing `g`'s leading coefficient, and for each block `b`, of generic rank
//! `r_b`, the gcd over `F_p` of `g mod p` with `det S_b mod p` and with `d_b = det(U M_b V) mod
//! p` for a few random small-integer `U` (`r_b × rows`) and `V` (`columns × r_b`), each
//! only modulo the gcd left so far, `c` (by elimination over `F_p[t]/(c)` with pivots that are
//! units there), or whole from its values at `deg + 1` points (`deg` bounded, by
//! Cauchy–Binet, by the largest degrees of `r_b` rows of `M_b`, or of `r_b` columns), whichever
//! costs less.
//! Where that gcd is `1`, at every root `ᾱ ∈ F̄_p` of `g mod p` some `r_b × r_b` minor of
//! `M_b(ᾱ)` is nonzero (`det(U M V)` is, by Cauchy–Binet, a combination of them). Every root
//! `α ∈ Q̄` of `g` is integral at every prime `𝔭 | p` of `Q(α)` (`p` does not divide the
//! leading coefficient) and reduces modulo `𝔭` to such an `ᾱ`; the same minor at `α`, reduced,
//! is that nonzero one, so it is nonzero: block `b` has rank `r_b` at every root of `g`. When
//! every block passes, no root of `g` holds more integrals: a proof, whatever `U` and `V` were,
//! given that `r_b`, the size of the generic minor (the rank at a point modulo a prime), is
//! the block's generic rank, as the rational roots' search assumes too (it is, unless that
//! point is a root of every larger minor).
//! A block whose gcd stays nontrivial (the roots where it truly loses rank always do) has its
//! factor named over Q: the gcd over Q of `g`, `det S_b` and the exact determinants (computed
//! as `det S_b` is) of the combinations tried, until it is no larger than modulo `p` (unless
//! `g` is square-free modulo `p` and the gcd there divides the factor named for an earlier
//! block: a factor of `g` prime to that one then reduces to one prime to the gcd, and the
//! argument above rules out its roots for this block). Outside
//! it the block keeps its rank, since one of those minors is nonzero there; at its roots every
//! minor tried vanishes, evidence of a lost rank but no proof. The lcm of these over the
//! blocks is reported as not examined ([`Determinants::unexamined`]), `g` divided by it
//! as ruled out ([`Determinants::ruled_out`]).
//!
//! The work is split in two: [`exceptional_candidates`] finds the rational roots
//! ([`Candidates`]) beside what else the determinants tell ([`Determinants`]: a generic
//! value, the other roots ruled out or not examined), and [`Candidates::confirm`] searches at
//! each with a search it is given
//! ([`exceptional_values`] gives the ordinary one; `superint search --find-values` its own,
//! whose reports it shows), so that each value is searched once. Each search's basis gets its
//! functional rank ([`basis_rank`], at most [`MAX_RANK_MINORS`] bordering minors), taken once
//! for the caller to show too: a value whose rank is larger than the generic one
//! holds functionally new integrals, not only products of those every value has.
//!
//! On a level set `P = 0` (`SearchOptions::on`), `M(t)` is that of the search there: the
//! monomials divisible by `P`'s leading monomial left out and each image its remainder on
//! division by `P`. `P` must be free of `t` and its leading coefficient, in the graded
//! lexicographic order of the phase variables, a number (at the other parameters' fixed
//! values): the division then never divides by anything holding `t`, and commutes with putting
//! in a value of it, so that `M(t0)` is the matrix of the search at `t0`. The flow of `H` must
//! keep the level set at every `t` ([`LevelSet::check_for_values_of`](super::LevelSet::check_for_values_of)).
//!
//! The generic rank is the rank at a random point modulo a prime (a larger one would need that
//! point to be a root modulo the prime of every nonzero minor of that size, a chance below
//! `deg/p < 2⁻⁵⁰`); everything else is exact.
//!
//! ```
//! use brackets::search::{exceptional_values, SearchOptions, SearchSpace};
//! use brackets::{PhaseSpace, System};
//! use trigpoly::{Expr, Vars};
//!
//! // p²/2 + (x² + a y²)/2: at a = 1 the oscillator is isotropic, and x p_y − y p_x is an
//! // integral there alone; at a = 0, y is free and p_y is one.
//! let vars = Vars::builder()
//!     .coordinate("x").coordinate("y").momentum("p_x").momentum("p_y").parameter("a")
//!     .build()?;
//! let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y")])?;
//! let h = Expr::parse(&vars, "(p_x^2 + p_y^2)/2 + (x^2 + a*y^2)/2")?;
//! let oscillator = System::new("oscillator", space, h)?;
//! let options = SearchOptions::new(SearchSpace::default().momenta_degree(2).positions_degree(2));
//! let found = exceptional_values(&oscillator, &options, vars.lookup("a").unwrap())?;
//! // 1 and the two energies, for every a.
//! assert_eq!(found.generic.basis.len(), 3);
//! let values: Vec<String> = found.values.iter().map(|v| v.value.to_string()).collect();
//! assert_eq!(values, ["0", "1"]);
//! let at_one = &found.values[1].found;
//! assert!(at_one.basis.iter().any(|i| i.expr().to_string() == "x p_y − y p_x"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::collections::BTreeMap;

use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use rayon::prelude::*;
use rustc_hash::FxHashMap;
use trigpoly::{Expr, Rational, Style, Var, VarKind, Vars};

use crate::claim::Condition;
use crate::error::{EngineError, EngineLimit};
use crate::modular::{big_mod, inverse_mod, mul_mod, previous_prime, Modulus, PRIME};
use crate::phase::PhaseSpace;
use crate::rank::{generated_rank_within, rank_within, BoundedRank};
use crate::system::System;
use crate::univariate::{gcd_mod, is_square_free_mod, IntPoly, ResidueRing};

use super::problem::{blocks, canonical, Problem};
use super::{
    fix_parameters, fixed_search_problem, refuse_beside_level_set, refuse_unvalued_denominators,
    search, FixedSearch, OnLevel, SearchOptions, SearchResult,
};

/// What [`exceptional_values`] found: what the determinants tell ([`Determinants`]), and the
/// searches at the generic value and at each of their rational roots, split into the
/// exceptional values and the spurious roots.
#[derive(Debug)]
pub struct ExceptionalValues {
    /// The parameter, a generic value, and the roots that are not rational, those ruled out
    /// apart from those not examined.
    pub determinants: Determinants,
    /// The ordinary search at [`Determinants::generic_value`].
    pub generic: SearchResult,
    /// The functional rank of [`ExceptionalValues::generic`]'s basis ([`basis_rank`]).
    pub generic_rank: BoundedRank,
    /// The rational values where the space holds more integrals, increasing, each with the
    /// ordinary search there.
    pub values: Vec<ExceptionalValue>,
    /// The rational roots of the determinants where the search found no more integrals.
    pub spurious: Vec<Rational>,
}

/// What the determinants of the blocks' generic minors tell about one parameter apart from
/// their rational roots: the parameter, a value that is no root of any, the largest minor,
/// whether `0` was left out, and their roots that are not rational, split into those ruled
/// out and those not examined (the module docs say how). [`Candidates`] holds it beside the
/// rational roots, [`ExceptionalValues`] beside the searches at them.
#[derive(Debug)]
pub struct Determinants {
    /// The parameter solved for.
    pub parameter: Var,
    /// A generic value: no root of any block's determinant.
    pub generic_value: Rational,
    /// The factor of the determinants' irrational part whose roots were not ruled out, a
    /// constant when none is left: at each of its roots every minor tried vanishes, so that
    /// they may hold more integrals, not examined since they are not rational
    /// ([`Determinants::unexamined_in`] writes it in the parameter).
    pub unexamined: IntPoly,
    /// The factor of the determinants' irrational part whose roots were ruled out: at each,
    /// every block keeps its generic rank, so that none holds more integrals in this space.
    pub ruled_out: RuledOut,
    /// The largest block's minor: its size and the degree of its determinant.
    pub largest_minor: (usize, usize),
    /// Whether `0` was a root of a determinant left out as no candidate: `H` holds a negative
    /// power of the parameter and has no value there.
    pub zero_left_out: bool,
    /// The roots of a determinant left out as no candidates because a declared denominator in
    /// the parameter (at the other parameters' fixed values) is zero there, increasing.
    pub denominator_roots_left_out: Vec<DenominatorRoot>,
}

/// A root of a determinant left out as no candidate: a declared denominator in the parameter
/// is zero there, and `H`, where it divides by it, has no value there, nor, where the space has
/// its powers ([`super::SearchSpace::denominators_degree`]), the space's functions.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DenominatorRoot {
    /// The root.
    pub root: Rational,
    /// The denominator's atom.
    pub atom: Var,
    /// Whether `H`, under the condition ([`Condition::substitution`]), divides by it; if not,
    /// the space's functions alone do.
    pub divides_h: bool,
}

impl Determinants {
    /// [`Determinants::unexamined`] as a polynomial in the parameter, in `vars` (the
    /// system's), when it is not constant: `None` when every root was rational.
    pub fn unexamined_in(&self, vars: &Vars) -> Option<Expr> {
        (self.unexamined.degree().unwrap_or(0) > 0)
            .then(|| polynomial_in(vars, self.parameter, &self.unexamined))
    }

    /// [`RuledOut::factor`] as a polynomial in the parameter, in `vars` (the system's), when
    /// any root was ruled out.
    pub fn ruled_out_in(&self, vars: &Vars) -> Option<Expr> {
        (self.ruled_out.count() > 0)
            .then(|| polynomial_in(vars, self.parameter, &self.ruled_out.factor))
    }
}

/// The irrational and complex roots of the determinants shown to hold no more integrals
/// (the module docs give the proof).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RuledOut {
    /// The factor whose roots were ruled out (primitive), a constant when none was: the
    /// determinants' irrational part is its product with [`Determinants::unexamined`].
    pub factor: IntPoly,
    /// The prime modulo which the minors were taken, when any root was examined: where a
    /// block's minors leave no common root with the irrational part modulo it, that block
    /// keeps its rank at every one of its roots; a block where they leave some had its
    /// minors' determinants computed exactly and their gcd with it taken over Q.
    pub prime: Option<u64>,
    /// How many blocks were settled so, by exact determinants over Q rather than modulo
    /// [`RuledOut::prime`] alone.
    pub exact_blocks: usize,
}

impl RuledOut {
    /// Nothing ruled out, nothing examined.
    fn none() -> Self {
        RuledOut {
            factor: IntPoly::from_i64(&[1]),
            prime: None,
            exact_blocks: 0,
        }
    }

    /// How many roots were ruled out (the factor's degree).
    pub fn count(&self) -> usize {
        self.factor.degree().unwrap_or(0)
    }
}

/// One exceptional value and the ordinary search there.
#[derive(Debug)]
pub struct ExceptionalValue {
    /// The value.
    pub value: Rational,
    /// The search at it: more integrals than [`ExceptionalValues::generic`].
    pub found: SearchResult,
    /// The functional rank of its basis ([`basis_rank`]): larger than
    /// [`ExceptionalValues::generic_rank`] where some of its integrals are functionally new,
    /// not functions of those every value has.
    pub rank: BoundedRank,
}

impl ExceptionalValue {
    /// Whether the value holds functionally new integrals: its basis is certified of larger
    /// functional rank than the generic one, whose rank is exact (a lower bound there would
    /// leave it open). Decided so off a level set, or on one [`level_set_graph_variable`]
    /// gives a variable for; elsewhere the ranks are those of remainders modulo its polynomial
    /// in the whole phase space, which functions equal on the level set do not share.
    pub fn functionally_new(&self, generic: &BoundedRank) -> bool {
        generic.is_exact() && self.rank.rank() > generic.rank()
    }
}

/// How many minors bordering the nonzero one the ranks of `--find-values` take ([`basis_rank`]
/// in [`Candidates::confirm`]) expand to certify the rank from above; past that they give the
/// lower bound alone. The harmonic rotor at `ω = 1`, 20 integrals of rank 5 in 6 phase
/// variables, takes 15 where no other bound meets it.
pub const MAX_RANK_MINORS: usize = 64;

/// How many minors bordering the nonzero one [`basis_rank`] expands, where no bound that
/// costs no symbolic minor meets the lower bound; past that it gives the lower bound alone.
/// Few, so that the rank costs a plain search little: a basis of hundreds of integrals below
/// the flow's bound has hundreds of bordering minors, each a symbolic determinant.
pub const SEARCH_RANK_MINORS: usize = 16;

/// The functional rank of a search's basis, the rank of the Jacobian of its integrals at the
/// fixed parameter values by every phase variable ([`rank_within`]), certified from above first by what costs no symbolic minor: the size (`rank ≤ N` integrals,
/// `≤ n` phase variables), and, where every integral is proved at the fixed
/// values, the flow of `H` there (`rank ≤ n − 1` where `X_H` is not identically zero, on the
/// level set of a condition that sets phase variables, `H` at the parameters it sets:
/// [`crate::integrals_rank_within`]); else the
/// bordering minors, at most `max_minors` of them ([`SEARCH_RANK_MINORS`] in a plain search),
/// else `at least` the lower bound. Where that is not exact, it is taken again bounded by the
/// rank of what [`BasisGenerators`] says generates the basis, taken the same way
/// ([`generated_rank_within`]): `--new-only`'s known and new integrals (a plain search's
/// decided by [`generation_decided`]), or the generators over the parameters kept symbolic; not on a level set, where the known integrals generate
/// modulo its polynomial alone.
/// Parameters kept symbolic are variables of the exact points like the phase variables:
/// every integral is one for every value of them (where the condition holds), so the flow's
/// bound holds at a generic value, and the rank is that over the functions of both.
/// On a level set (`--on`) the integrals are integrals modulo its polynomial: the flow bounds
/// their rank on it where it is a graph ([`level_set_graph_variable`]); elsewhere the rank is
/// that of the functions found in the whole phase space, with no bound but the bordering
/// minors.
pub fn basis_rank(
    system: &System,
    options: &SearchOptions,
    found: &SearchResult,
    max_minors: usize,
) -> Result<BoundedRank, EngineError> {
    let space = system.space();
    let functions: Vec<Expr> = found.basis.iter().map(|i| i.fixed.clone()).collect();
    let graph = level_set_graph(space, found)?;
    if found.on.is_some() && graph.is_none() {
        return rank_within(space, &functions, max_minors);
    }
    let (h, condition) = match found.basis.iter().all(|i| i.proved_fixed) {
        false => (None, None),
        true => {
            let h = fix_parameters(system.hamiltonian(), &found.parameters)?;
            let condition = match (&options.condition, graph) {
                (_, Some(graph)) => Some(graph),
                (Some(c), None) => {
                    let subs = (c.subs().iter())
                        .map(|(v, e)| Ok((*v, fix_parameters(e, &found.parameters)?)))
                        .collect::<Result<Vec<_>, EngineError>>()?;
                    Some(Condition::all(&c.to_string(), subs)?)
                }
                (None, None) => None,
            };
            (Some(h), condition)
        }
    };
    let rank_by = |generators: &[Expr]| {
        generated_rank_within(
            space,
            &functions,
            generators,
            h.as_ref(),
            condition.as_ref(),
            max_minors,
        )
    };
    // The known integrals, where they alone generate every integral, bound it at once (their
    // reason said before the minors'); other generators only where it is not otherwise exact,
    // costing nothing where the flow's bound is met.
    let none_new = found.new.as_ref().is_some_and(|n| n.new.is_empty());
    match BasisGenerators::of(found).map(|g| g.functions(found)) {
        Some(known) if none_new => rank_by(&known),
        Some(generators) => match rank_by(&[])? {
            rank if rank.is_exact() => Ok(rank),
            _ => rank_by(&generators),
        },
        None => rank_by(&[]),
    }
}

/// `found` with which of its integrals are new decided ([`SearchResult::new`]: the search
/// again with `new_only`, as `--new-only` runs it), for [`basis_rank`] to bound the rank by
/// the known and new integrals ([`BasisGenerators::KnownAndNew`]) where it is not otherwise
/// exact. `None` where it was decided already, on a level set (where the known integrals
/// generate modulo its polynomial alone), or where the search again stops at a limit or
/// finds another basis.
///
/// It runs the search again rather than reusing the first's kernel and problem: [`super::search`]
/// keeps neither in its [`SearchResult`], and keeping them (or a search that decides the new
/// integrals after the rank) would change the search's interface for a case no documented
/// search meets (each one's rank is exact at once). The second search costs about what the
/// first does: the dipole rotor at 4/4/4 (`--fix M=2,omega=3,I=5,epsilon=7`) takes 0.12 s
/// with it, 0.07 s without.
pub fn generation_decided(
    system: &System,
    options: &SearchOptions,
    found: &SearchResult,
) -> Option<SearchResult> {
    if found.new.is_some() || found.on.is_some() {
        return None;
    }
    let again = SearchOptions {
        new_only: true,
        ..options.clone()
    };
    let decided = super::search(system, &again).ok()?;
    let fixed = |r: &SearchResult| r.basis.iter().map(|i| i.fixed.clone()).collect::<Vec<_>>();
    (fixed(&decided) == fixed(found)).then_some(decided)
}

/// What generates every integral of a search's basis, so that their rank bounds the basis's
/// ([`basis_rank`], [`crate::UpperBound::Generated`]): each integral's gradient by the phase
/// variables is a combination of theirs, with coefficients rational functions of the phase
/// variables and of the parameters kept symbolic. Off a level set alone, where `--new-only`
/// decides generation modulo its polynomial.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BasisGenerators {
    /// `--new-only`'s known integrals and the new ones: every integral is a sum of known
    /// integrals, constants, products of integrals of lower grade and new ones (and with
    /// parameters kept symbolic, of parameter multiples of integrals, and quotients `K/M` of
    /// generated ones by monomials in them), so by induction on the grade a polynomial in
    /// the known and new ones, its coefficients rational functions of the parameters.
    KnownAndNew,
    /// The basis integrals that generate all of them over the polynomials in the parameters
    /// kept symbolic ([`super::ParameterModule`]), where no declared denominator of them was
    /// taken: each other basis integral `I_k` is `Σ_j r_kj I_j` (`r_kj` a parameter times a
    /// number: parameter multiples of integrals of the space) plus a combination of the
    /// generators, so `(1 − R) I = C G` with `R` vanishing where every parameter is 0:
    /// `det(1 − R)` is a polynomial with constant term 1, not zero, and `I = (1 − R)⁻¹ C G`
    /// over the rational functions of the parameters.
    Module,
}

impl BasisGenerators {
    /// What generates `found`'s basis: `--new-only`'s known and new integrals where it ran,
    /// else the parameter module's generators where they are fewer than the basis and no
    /// declared denominator was taken; `None` on a level set, and otherwise.
    pub fn of(found: &SearchResult) -> Option<Self> {
        if found.on.is_some() {
            return None;
        }
        if found.new.is_some() {
            return Some(BasisGenerators::KnownAndNew);
        }
        match &found.module {
            Some(m) if m.denominators.is_empty() && m.generators.len() < found.basis.len() => {
                Some(BasisGenerators::Module)
            }
            _ => None,
        }
    }

    /// The generators, at the fixed values (as [`super::Integral::fixed`]).
    pub fn functions(self, found: &SearchResult) -> Vec<Expr> {
        let basis = |indices: &[usize]| -> Vec<Expr> {
            (indices.iter())
                .map(|&i| found.basis[i].fixed.clone())
                .collect()
        };
        match (self, &found.new, &found.module) {
            (BasisGenerators::KnownAndNew, Some(n), _) => {
                let mut functions = n.known_integrals.clone();
                functions.extend(basis(&n.new));
                functions
            }
            (BasisGenerators::Module, _, Some(m)) => basis(&m.generators),
            _ => Vec::new(),
        }
    }
}

/// The level set of a search as the graph of its [`level_set_graph_variable`] `v` over the
/// others, a condition `v = v − P/c` (`P = c v + …`, `c` a nonzero number at the fixed
/// values), where the integrals found are integrals on it as under a `--when` setting `v`;
/// `None` off a level set, or on one that is no such graph.
fn level_set_graph(
    space: &PhaseSpace,
    found: &SearchResult,
) -> Result<Option<Condition>, EngineError> {
    let (Some(level), Some(v)) = (&found.on, level_set_graph_variable(space, found)) else {
        return Ok(None);
    };
    let p = fix_parameters(&level.polynomial, &found.parameters)?;
    let inverse = space
        .derivative(&p, v)?
        .as_constant()
        .and_then(|c| c.try_inv());
    let Some(inverse) = inverse else {
        return Ok(None);
    };
    let vars = space.vars();
    let value = Expr::var(vars, v).checked_sub(&p.scale(&inverse))?;
    Ok(Some(Condition::all(&level.level.text, vec![(v, value)])?))
}

/// The phase variable `v` the level set of a search is a graph over the others by, where
/// [`basis_rank`] is the rank on the level set: `LM(P)` is `v` itself, so that `P` is a
/// number times `v` plus terms free of it, and no integral found holds `v` (none does: the
/// monomials `LM(P)` divides are left out). Each integral is then its own restriction to the
/// level set, and its Jacobian by every phase variable is that by the variables the level
/// set leaves free beside a zero column. `None` off a level set, or where `LM(P)` is another
/// monomial (the rank is then that in the whole phase space).
pub fn level_set_graph_variable(space: &PhaseSpace, found: &SearchResult) -> Option<Var> {
    let level = found.on.as_ref()?;
    let vars = space.vars();
    space.coordinates().into_iter().find(|&v| {
        vars.variable(v).kind() != VarKind::Angle
            && level.leading_monomial == Expr::var(vars, v)
            && found.basis.iter().all(|i| !i.fixed.contains(v))
    })
}

/// The candidates for the exceptional values, before any search at them
/// ([`exceptional_candidates`]): the determinants' rational roots, beside what else they
/// tell ([`Determinants`]). [`Candidates::confirm`] searches at the generic value and at
/// each root.
#[derive(Debug)]
pub struct Candidates {
    /// The parameter, a generic value, and the roots that are not rational, those ruled out
    /// apart from those not examined.
    pub determinants: Determinants,
    /// The rational roots of the determinants, increasing (without `0` where `H` has no
    /// value there, nor the roots of a declared denominator in the parameter,
    /// [`Determinants::denominator_roots_left_out`]).
    pub roots: Vec<Rational>,
}

impl Candidates {
    /// The exceptional values among the roots: `search_at` searches at the generic value, then
    /// at each root, which is kept where its search finds more integrals than the generic
    /// one, and `rank_at` takes the functional rank of the generic search's basis and of each
    /// kept one (as [`basis_rank`] does, at most [`MAX_RANK_MINORS`] bordering minors, with
    /// the options the search had at that value). The search must be exact at the value it is
    /// given, as [`exceptional_values`]' (the options with the parameter fixed there) is; a
    /// caller that shows each search may run its own and keep what it shows, each value
    /// searched once and each rank taken once.
    ///
    /// ```
    /// use brackets::search::{
    ///     basis_rank, exceptional_candidates, search, SearchOptions, SearchSpace, MAX_RANK_MINORS,
    /// };
    /// use brackets::{PhaseSpace, System};
    /// use trigpoly::{Expr, Rational, Vars};
    ///
    /// // p²/2 + (x² + a y²)/2, isotropic at a = 1.
    /// let vars = Vars::builder()
    ///     .coordinate("x").coordinate("y").momentum("p_x").momentum("p_y").parameter("a")
    ///     .build()?;
    /// let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y")])?;
    /// let h = Expr::parse(&vars, "(p_x^2 + p_y^2)/2 + (x^2 + a*y^2)/2")?;
    /// let oscillator = System::new("oscillator", space, h)?;
    /// let options = SearchOptions::new(SearchSpace::default().momenta_degree(2).positions_degree(2));
    /// let a = vars.lookup("a").unwrap();
    /// let candidates = exceptional_candidates(&oscillator, &options, a)?;
    /// let mut searched = Vec::new();
    /// let at = |value: &Rational| options.clone().fix(a, value.clone());
    /// let found = candidates.confirm(
    ///     |value| {
    ///         searched.push(value.to_string());
    ///         search(&oscillator, &at(value))
    ///     },
    ///     |value, found| basis_rank(&oscillator, &at(value), found, MAX_RANK_MINORS),
    /// )?;
    /// // The generic value first, then each root once.
    /// assert_eq!(searched[0], found.determinants.generic_value.to_string());
    /// assert_eq!(searched.len(), 1 + found.values.len() + found.spurious.len());
    /// let values: Vec<String> = found.values.iter().map(|v| v.value.to_string()).collect();
    /// assert_eq!(values, ["0", "1"]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn confirm<E>(
        self,
        mut search_at: impl FnMut(&Rational) -> Result<SearchResult, E>,
        mut rank_at: impl FnMut(&Rational, &SearchResult) -> Result<BoundedRank, E>,
    ) -> Result<ExceptionalValues, E> {
        let generic_value = &self.determinants.generic_value;
        let generic = search_at(generic_value)?;
        let generic_rank = rank_at(generic_value, &generic)?;
        let mut values = Vec::new();
        let mut spurious = Vec::new();
        for value in self.roots {
            let found = search_at(&value)?;
            if found.basis.len() > generic.basis.len() {
                let rank = rank_at(&value, &found)?;
                values.push(ExceptionalValue { value, found, rank });
            } else {
                spurious.push(value);
            }
        }
        Ok(ExceptionalValues {
            determinants: self.determinants,
            generic,
            generic_rank,
            values,
            spurious,
        })
    }
}

/// The values of `parameter` at which the space of `options` holds more integrals than at a
/// generic value, the other parameters at `options`' fixed values (1 by default), on
/// `options`' level set if it has one: [`exceptional_candidates`], each confirmed by the
/// search with the parameter fixed at it.
pub fn exceptional_values(
    system: &System,
    options: &SearchOptions,
    parameter: Var,
) -> Result<ExceptionalValues, EngineError> {
    let at = |value: &Rational| {
        let mut options = options.clone();
        options.fixed.push((parameter, value.clone()));
        options
    };
    exceptional_candidates(system, options, parameter)?.confirm(
        |value| search(system, &at(value)),
        |value, found| basis_rank(system, &at(value), found, MAX_RANK_MINORS),
    )
}

/// The candidates for the values of `parameter` at which the space of `options` holds more
/// integrals: the rational roots of the determinants, and a generic value. Refused:
/// a parameter that is not one of `H`'s, or is fixed, kept symbolic or set by the condition;
/// parameters kept symbolic; a level set whose polynomial holds the parameter (a level set is
/// taken at the fixed values of its parameters) and what a search on a level set does not
/// take; a parameter in a declared radical, or in a declared denominator that holds a phase
/// variable too (a negative power of it in `H` is taken, and `0` is then no candidate; so is
/// a declared denominator of parameters alone that holds it, whose roots are then none);
/// and, as a limit ([`EngineLimit::MinorRows`]), a block whose minor has more rows than
/// [`SearchOptions::max_minor`].
pub fn exceptional_candidates(
    system: &System,
    options: &SearchOptions,
    parameter: Var,
) -> Result<Candidates, EngineError> {
    refuse(system, options, parameter)?;
    let problem = problem_with_parameter_kept(system, options, parameter)?;
    // The denominators that hold the parameter, in parameters alone ([`refuse`]), are cleared
    // row by row as its negative powers are ([`PolyMatrix::new`]); the others here.
    let (in_parameter, others): (Vec<_>, Vec<_>) =
        (system.space().denominator_atoms().iter().cloned())
            .partition(|(_, d): &(Var, Expr)| d.contains(parameter));
    // An unknown `φ/d(t)^e` has the column of `φ` times `1/d(t)^e`, and `φ` is a combination
    // of the unknowns free of these atoms (no such combination of their powers is `1`): it
    // changes the rank at no value of `t` where `d ≠ 0`, and is left out.
    let images = (problem.unknowns.iter().enumerate())
        .filter(|(_, u)| in_parameter.iter().all(|(v, _)| u.phase[v.index()] == 0))
        .map(|(j, _)| problem.image(&problem.expr(j, &Rational::one())?))
        .collect::<Result<Vec<Expr>, EngineError>>()?;
    crate::clearing::refuse_division_by_zero(&in_parameter, &problem.parameters, images.iter())?;
    let denominators = denominators_in(parameter, &in_parameter, &problem.parameters)?;
    let images = match crate::clearing::Clearing::new(
        &others,
        system.space().radicals(),
        &problem.parameters,
        images.iter(),
    )? {
        Some(clearing) => clearing.apply_all(&images)?,
        None => images,
    };
    let matrix = PolyMatrix::new(&images, parameter, &problem.variables.angles, &denominators);
    let mut determinants = Vec::new();
    let mut ranked_blocks = Vec::new();
    let mut largest_minor = (0, 0);
    for block in blocks(&matrix.columns, matrix.rows) {
        let minor = matrix.generic_minor(&block);
        if minor.len() > options.max_minor {
            let limit = options.max_minor;
            return Err(EngineError::PastLimit {
                which: EngineLimit::MinorRows,
                limit,
                message: format!(
                    "a block of the equations has a minor of {} rows, more than {limit}, the \
                     limit of the rows whose determinant in the parameter is computed: search \
                     a smaller space, or raise the limit",
                    minor.len()
                ),
            });
        }
        let det = determinant(&minor);
        largest_minor = largest_minor.max((minor.len(), det.degree().unwrap_or(0)));
        ranked_blocks.push((block, minor.len()));
        determinants.push(det);
    }
    let mut roots: Vec<Rational> = Vec::new();
    // Each block's square-free part with its rational factors divided out, and their lcm:
    // blocks alike share factors, and their product's square-free part took seconds.
    let mut rest = IntPoly::from_i64(&[1]);
    for det in &determinants {
        let (found, left) = det.rational_roots()?;
        roots.extend(found);
        if !left.divides(&rest) {
            rest = rest.lcm(&left);
        }
    }
    // With a negative power of `t` in H, `t = 0` is no value of H: not a candidate; nor is a
    // root of a declared denominator in `t` that H or the space's functions divide by (a
    // search there has no value for them), irrational ones divided out of the rest.
    // `H` under the condition is formed here, after the search's own checks: where the
    // condition sets to 0 a parameter `H` divides by, the substitution fails unnamed, and
    // those checks name the condition.
    let searched = searched_hamiltonian(system, options)?;
    let no_value_at_zero = (searched.terms().into_iter()).any(|term| term.exponent(parameter) < 0);
    let zero_left_out = no_value_at_zero && roots.iter().any(Rational::is_zero);
    if no_value_at_zero {
        roots.retain(|r| !r.is_zero());
    }
    let divided_by =
        |atom: Var| options.space.denominators_degree > 0 || searched.low_degree(atom) < Some(0);
    let poles: Vec<&(Var, IntPoly)> = (denominators.iter())
        .filter(|(v, _)| divided_by(*v))
        .collect();
    let zero_of = |r: &Rational| poles.iter().find(|(_, d)| d.vanishes_at(r));
    let no_value = |r: &Rational| zero_of(r).is_some();
    let mut denominator_roots_left_out: Vec<DenominatorRoot> = (roots.iter())
        .filter_map(|r| {
            zero_of(r).map(|(v, _)| DenominatorRoot {
                root: r.clone(),
                atom: *v,
                divides_h: searched.low_degree(*v) < Some(0),
            })
        })
        .collect();
    roots.retain(|r| !no_value(r));
    for (_, d) in &poles {
        let common = rest.gcd(d);
        if common.degree().unwrap_or(0) > 0 {
            rest = rest.divide_out(&common);
        }
    }
    roots.sort();
    roots.dedup();
    denominator_roots_left_out.sort_by(|a, b| a.root.cmp(&b.root));
    denominator_roots_left_out.dedup_by(|a, b| a.root == b.root);
    let generic_value = (1..)
        .map(|k| Rational::new(2 * k + 5, 1))
        .find(|v| !no_value(v) && determinants.iter().all(|d| !d.vanishes_at(v)))
        .expect("a polynomial has finitely many roots");
    let blocks: Vec<RankedBlock> = (ranked_blocks.into_iter().zip(&determinants))
        .map(|((columns, rank), determinant)| RankedBlock {
            columns,
            rank,
            determinant,
        })
        .collect();
    let (unexamined, ruled_out) = match rest.degree() {
        Some(d) if d > 0 => matrix.rule_out(&blocks, &rest),
        _ => (rest, RuledOut::none()),
    };
    Ok(Candidates {
        determinants: Determinants {
            parameter,
            generic_value,
            unexamined,
            ruled_out,
            largest_minor,
            zero_left_out,
            denominator_roots_left_out,
        },
        roots,
    })
}

/// The linear problem of `options` with `parameter` kept as a variable, the others fixed, and
/// on `options`' level set if it has one: its unknowns those the search there has, its images
/// the remainders on division by the level set's polynomial, which holds no `parameter`
/// ([`refuse`]), so that the division, and the problem, at any value of it are these at that
/// value. The level set is checked as a search checks it, here with `parameter` free: the
/// flow of `H` must keep it for every value.
fn problem_with_parameter_kept(
    system: &System,
    options: &SearchOptions,
    parameter: Var,
) -> Result<Problem, EngineError> {
    let kept = SearchOptions {
        symbolic: vec![parameter],
        space: options.space.parameters_degree(0),
        new_only: false,
        on: None,
        ..options.clone()
    };
    let FixedSearch {
        problem,
        parameters,
        ..
    } = fixed_search_problem(system, &kept)?;
    let Some(level) = &options.on else {
        return Ok(problem);
    };
    refuse_beside_level_set(options)?;
    level.check_for_values_of(system, &options.fixed, parameter, options.space.laurent)?;
    let (problem, _, _) = problem.restricted_to(OnLevel::new(level, system, &parameters)?)?;
    Ok(problem)
}

/// `H` as the search takes it: under the condition's [`Condition::substitution`], whose values
/// may hold the parameter, or divide by it or by a declared denominator in it (`κ = m − 1`
/// gives the atom of `κ + 1` the value `1/m`).
fn searched_hamiltonian(system: &System, options: &SearchOptions) -> Result<Expr, EngineError> {
    match &options.condition {
        Some(c) => Ok(system.hamiltonian().subst_many(&c.substitution())?),
        None => Ok(system.hamiltonian().clone()),
    }
}

/// Refuses what [`exceptional_values`] does not take.
fn refuse(system: &System, options: &SearchOptions, parameter: Var) -> Result<(), EngineError> {
    let vars = system.vars();
    if !vars.owns(parameter) || vars.variable(parameter).kind() != VarKind::Parameter {
        return Err(EngineError::Invalid(
            "only a parameter's exceptional values are found".into(),
        ));
    }
    // As the search at each value refuses it: `ω = 1` leaves `ω² − Ω²` at `1 − Ω²`, no value,
    // which a space without declared denominators takes where `H` does not hold it; a
    // parameter set to a number is then fixed instead, which gives it its value.
    if let Some(c) = &options.condition {
        refuse_unvalued_denominators(c, system, &options.space)
            .map_err(|e| with_fix_in_place_of(e, c, parameter))?;
    }
    let name = vars.variable(parameter).name();
    let space = system.space();
    // Held by H as written (a condition that sets the parameter is refused below, for that),
    // or by H under the condition; by a level set too, through its value's atoms
    // (`1/(κ + 1)`).
    let holds = |h: &Expr| {
        let symbol_holds = |symbols: &[(Var, Expr)]| {
            (symbols.iter()).any(|(v, e)| e.contains(parameter) && h.contains(*v))
        };
        h.contains(parameter)
            || symbol_holds(space.denominator_atoms())
            || symbol_holds(space.radicals())
    };
    let held = holds(system.hamiltonian()) || holds(&searched_hamiltonian(system, options)?);
    let refusal = if !held {
        Some(format!("{name}, which H does not hold"))
    } else if !options.symbolic.is_empty() {
        Some("parameters kept symbolic: the others are fixed".into())
    } else if let Some(level) = options
        .on
        .as_ref()
        .filter(|l| l.polynomial().is_ok_and(|p| holds(&p)))
    {
        Some(format!(
            "a level set whose polynomial holds {name}, {}: a level set is taken at the fixed \
             values of its parameters (whether it is square-free and the flow of H keeps it \
             is decided there, and each function's normal form is taken modulo it there), \
             and {name} is searched for, not fixed; write the level set without {name}",
            level.text
        ))
    } else if options.fixed.iter().any(|f| f.0 == parameter) {
        Some(format!(
            "a value fixed for {name}, the parameter solved for"
        ))
    } else if options
        .condition
        .as_ref()
        .is_some_and(|c| c.subs().iter().any(|s| s.0 == parameter))
    {
        Some(format!(
            "a condition that sets {name}, the parameter solved for"
        ))
    } else if let Some((r, _)) = (space.radicals().iter()).find(|(_, e)| e.contains(parameter)) {
        Some(format!(
            "{name} in a declared radical, {}, whose reduction depends on it",
            vars.variable(*r).unicode()
        ))
    } else if let Some((d, _)) = (space.denominator_atoms().iter()).find(|(_, e)| {
        e.contains(parameter)
            && vars
                .vars()
                .any(|v| vars.variable(v).kind() != VarKind::Parameter && e.contains(v))
    }) {
        Some(format!(
            "{name} in a declared denominator that holds a phase variable too, {}, whose \
             clearing depends on both",
            vars.variable(*d).unicode()
        ))
    } else {
        None
    };
    match refusal {
        Some(what) => Err(EngineError::Invalid(format!(
            "the search for the exceptional values of {name} does not take {what}"
        ))),
        None => Ok(()),
    }
}

/// The refusal `e` of the condition `c` with the way out for the search for the exceptional
/// values of `parameter` where `e` names a parameter `c` sets to a number: `--fix` in place of
/// the condition's value, at which the declared denominators holding `parameter` are taken
/// as polynomials in it (`--fix omega=1` makes `ω² − Ω²` the `1 − Ω²` that `ω = 1` leaves).
fn with_fix_in_place_of(e: EngineError, c: &Condition, parameter: Var) -> EngineError {
    let EngineError::RefusedCondition { var, message } = e else {
        return e;
    };
    let value = c.subs().iter().find(|(v, _)| *v == var).map(|(_, x)| x);
    let Some(value) = value.filter(|x| x.is_constant()) else {
        return EngineError::RefusedCondition { var, message };
    };
    let vars = value.vars();
    let (name, c_name) = (vars.variable(var), vars.variable(parameter).name());
    let message = format!(
        "{message}; with --find-values {c_name}, fix {} with --fix {}={} in place of the \
         condition's value",
        name.unicode(),
        name.name(),
        value.render(Style::Ascii)
    );
    EngineError::RefusedCondition { var, message }
}

/// `Σ a_i t^i` as an expression in the parameter `t`.
fn polynomial_in(vars: &Vars, t: Var, p: &IntPoly) -> Expr {
    let mut out = Expr::zero(vars);
    let mut power = Expr::constant(vars, 1.into());
    let var = Expr::var(vars, t);
    for c in p.coeffs() {
        out = &out + &(&power * &Rational::from(c.clone()));
        power = &power * &var;
    }
    out
}

/// Each atom of `atoms` (declared denominators holding `t`, in parameters alone) with its
/// polynomial `d(t)` at the other parameters' fixed values, integer coefficients (times the
/// lcm of their denominators, which changes no root). Refused: one with a coefficient that
/// is not real, which would mix a row's real and imaginary parts.
fn denominators_in(
    t: Var,
    atoms: &[(Var, Expr)],
    parameters: &[(Var, Rational)],
) -> Result<Vec<(Var, IntPoly)>, EngineError> {
    atoms
        .iter()
        .map(|(v, d)| {
            let at = fix_parameters(d, parameters)?;
            let vars = at.vars();
            if !at.is_real() {
                return Err(EngineError::Invalid(format!(
                    "the search for the exceptional values of {} does not take the declared \
                     denominator {}, whose coefficients are not real",
                    vars.variable(t).name(),
                    vars.variable(*v).unicode()
                )));
            }
            let mut coeffs: Vec<Rational> = Vec::new();
            for term in at.terms() {
                let k = usize::try_from(term.exponent(t)).expect("a denominator is a polynomial");
                if coeffs.len() <= k {
                    coeffs.resize(k + 1, Rational::zero());
                }
                coeffs[k] += &term.coeff().re;
            }
            let lcm = (coeffs.iter()).fold(BigInt::one(), |l, c| {
                num_integer::Integer::lcm(&l, &c.denom().to_bigint())
            });
            let scale = Rational::from(lcm);
            let integers = (coeffs.iter())
                .map(|c| (c * &scale).numer().to_bigint())
                .collect();
            Ok((*v, IntPoly::new(integers)))
        })
        .collect()
}

/// The equations with the parameter `t` kept: each column an unknown, each entry the
/// polynomial in `t`, integer coefficients, each row scaled by the lcm of its denominators.
/// A row with negative powers of `t` (a negative power in H) is multiplied by `t^k`, `k` the
/// largest negative exponent in it, which changes the kernel at no `t ≠ 0`; so by `d(t)^k`
/// for the atom of each declared denominator `d(t)` in `t` ([`denominators_in`]), `a^j` then
/// `d(t)^{j + k}` (`a·d = 1`), which changes it at no `t` where `d ≠ 0`.
struct PolyMatrix {
    /// By column, the rows and entries (coefficients lowest degree first).
    columns: Vec<Vec<(usize, Vec<BigInt>)>>,
    rows: usize,
}

impl PolyMatrix {
    /// The equations of the `images`: a row for the real and the imaginary part of each
    /// monomial other than `t`'s and the `denominators`' atoms' with a canonical `e^{ik·θ}`.
    fn new(images: &[Expr], t: Var, angles: &[Var], denominators: &[(Var, IntPoly)]) -> Self {
        let mut row_of: FxHashMap<(Vec<i64>, usize), usize> = FxHashMap::default();
        let mut entries: Vec<BTreeMap<usize, BTreeMap<Powers, Rational>>> = Vec::new();
        for image in images {
            let mut column: BTreeMap<usize, BTreeMap<Powers, Rational>> = BTreeMap::new();
            for term in image.terms() {
                if !canonical(angles.iter().map(|v| term.exponent(*v))) {
                    continue;
                }
                let power = Powers {
                    t: term.exponent(t),
                    atoms: denominators
                        .iter()
                        .map(|(v, _)| term.exponent(*v))
                        .collect(),
                };
                let mut key = term.exponents();
                key[t.index()] = 0;
                for (v, _) in denominators {
                    key[v.index()] = 0;
                }
                let c = term.coeff();
                for (part, x) in [c.re, c.im].into_iter().enumerate() {
                    if x.is_zero() {
                        continue;
                    }
                    let n = row_of.len();
                    let row = *row_of.entry((key.clone(), part)).or_insert(n);
                    *column
                        .entry(row)
                        .or_default()
                        .entry(power.clone())
                        .or_default() += &x;
                }
            }
            entries.push(column);
        }
        let rows = row_of.len();
        // Each row's entries made integers, times the lcm of the row's denominators, and
        // polynomials, times `t^k` for its largest negative exponent `−k` and `d^k` for each
        // atom's (`1/d` to the power `k` at most).
        let mut lcm = vec![BigInt::one(); rows];
        let mut lowest = vec![
            Powers {
                t: 0,
                atoms: vec![0; denominators.len()]
            };
            rows
        ];
        for column in &entries {
            for (row, poly) in column {
                for (power, x) in poly {
                    lcm[*row] = num_integer::Integer::lcm(&lcm[*row], &x.denom().to_bigint());
                    lowest[*row].lower_to(power);
                }
            }
        }
        // `d^k` for each atom, formed once for each `k`.
        let mut atom_powers: Vec<Vec<IntPoly>> =
            vec![vec![IntPoly::from_i64(&[1])]; denominators.len()];
        let mut power_of = |a: usize, k: usize| {
            while atom_powers[a].len() <= k {
                let next = atom_powers[a].last().expect("d^0").mul(&denominators[a].1);
                atom_powers[a].push(next);
            }
            atom_powers[a][k].clone()
        };
        let columns = entries
            .into_iter()
            .map(|column| {
                column
                    .into_iter()
                    .filter_map(|(row, poly)| {
                        let mut sum: Vec<BigInt> = Vec::new();
                        for (power, x) in poly {
                            let scaled = x * &Rational::from(lcm[row].clone());
                            let shift = power.shifted(&lowest[row]);
                            let mut coeffs = vec![BigInt::zero(); shift.t + 1];
                            coeffs[shift.t] = scaled.numer().to_bigint();
                            let mut term = IntPoly::new(coeffs);
                            for (a, &k) in shift.atoms.iter().enumerate() {
                                if k > 0 {
                                    term = term.mul(&power_of(a, k));
                                }
                            }
                            if sum.len() < term.coeffs().len() {
                                sum.resize(term.coeffs().len(), BigInt::zero());
                            }
                            for (s, c) in sum.iter_mut().zip(term.coeffs()) {
                                *s += c;
                            }
                        }
                        let p = IntPoly::new(sum);
                        (!p.is_zero()).then(|| (row, p.coeffs().to_vec()))
                    })
                    .collect()
            })
            .collect();
        PolyMatrix { columns, rows }
    }

    /// A square submatrix of the block's columns of the block's generic rank, nonsingular at
    /// a random point modulo a prime: its rows (dense, entries polynomials in `t`).
    fn generic_minor(&self, block: &[usize]) -> Vec<Vec<Vec<BigInt>>> {
        let p = Modulus::new(PRIME);
        let point = RANDOM_POINT % PRIME;
        // The block's rows, increasing, and each one's place among them: `dense[local[r]]` is
        // row `rows[local[r]] = r`, by construction.
        let (rows, local) = self.block_rows(block);
        let mut dense = vec![vec![0_u64; block.len()]; rows.len()];
        for (k, &j) in block.iter().enumerate() {
            for (row, poly) in &self.columns[j] {
                dense[local[row]][k] = evaluate_mod(poly, point, &p);
            }
        }
        // Elimination modulo p, remembering the original row of each pivot.
        let mut order: Vec<usize> = (0..rows.len()).collect();
        let (mut pivot_rows, mut pivot_columns) = (Vec::new(), Vec::new());
        let mut next = 0;
        for col in 0..block.len() {
            let Some(found) = (next..order.len()).find(|&i| dense[order[i]][col] != 0) else {
                continue;
            };
            order.swap(next, found);
            let pivot = order[next];
            let inverse = inverse_mod(dense[pivot][col], PRIME);
            let pivot_row = dense[pivot].clone();
            let support = support_after(&pivot_row, col);
            for &other in &order[next + 1..] {
                clear_entry(&mut dense[other], &pivot_row, &support, col, inverse, &p);
            }
            pivot_rows.push(rows[pivot]);
            pivot_columns.push(block[col]);
            next += 1;
        }
        let position: FxHashMap<usize, usize> = pivot_rows
            .iter()
            .enumerate()
            .map(|(i, &r)| (r, i))
            .collect();
        let mut minor = vec![vec![Vec::new(); pivot_columns.len()]; pivot_rows.len()];
        for (k, &j) in pivot_columns.iter().enumerate() {
            for (row, poly) in &self.columns[j] {
                if let Some(&i) = position.get(row) {
                    minor[i][k] = poly.clone();
                }
            }
        }
        minor
    }
}

/// The exponents of a term of an entry of [`PolyMatrix`] in the parameter `t` and in each
/// atom of a declared denominator in `t` (`1/d(t)` to the power `−k` where `k < 0`).
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Powers {
    t: i64,
    atoms: Vec<i64>,
}

impl Powers {
    /// Each exponent lowered to `other`'s where that is lower: a row's lowest.
    fn lower_to(&mut self, other: &Powers) {
        self.t = self.t.min(other.t);
        for (a, b) in self.atoms.iter_mut().zip(&other.atoms) {
            *a = (*a).min(*b);
        }
    }

    /// The exponents once the row is multiplied by `t^{−lowest.t} Π d^{−lowest.atoms}`: none
    /// negative.
    fn shifted(&self, lowest: &Powers) -> ShiftedPowers {
        let up =
            |p: i64, low: i64| usize::try_from(p - low).expect("no power below the row's lowest");
        ShiftedPowers {
            t: up(self.t, lowest.t),
            atoms: (self.atoms.iter().zip(&lowest.atoms))
                .map(|(&p, &low)| up(p, low))
                .collect(),
        }
    }
}

/// [`Powers`] of a row made polynomial ([`Powers::shifted`]).
struct ShiftedPowers {
    t: usize,
    atoms: Vec<usize>,
}

/// A block of the equations: its columns, its generic rank and the determinant of its
/// generic minor.
struct RankedBlock<'a> {
    columns: Vec<usize>,
    rank: usize,
    determinant: &'a IntPoly,
}

/// How many random combinations `U M V` of a block are tried modulo the prime before the
/// roots they leave are named over Q.
const MIXED_TRIES: usize = 3;

/// The bound on the small integers of the random combinations `U M V`.
const MIXING_BOUND: u64 = 9;

impl PolyMatrix {
    /// The roots of `g` (square-free, not constant) where every block keeps its generic rank,
    /// found as the module docs say: the factor of `g` left (whose roots are roots of every
    /// minor tried) and what was ruled out.
    fn rule_out(&self, blocks: &[RankedBlock], g: &IntPoly) -> (IntPoly, RuledOut) {
        let lead = g.coeffs().last().expect("g is not zero");
        let mut p = PRIME;
        while big_mod(lead, p) == 0 {
            p = previous_prime(p);
        }
        let g_mod = g.reduced_mod(p);
        // Square-free modulo p, g's factors over Q reduce to factors prime to each other.
        let square_free = is_square_free_mod(&g_mod, p);
        let mut seed = RANDOM_POINT;
        let mut left = IntPoly::from_i64(&[1]);
        let mut exact_blocks = 0;
        for block in blocks {
            // Modulo p: the roots of g where the minor and each combination tried vanish.
            let mut common = gcd_mod(&g_mod, &block.determinant.reduced_mod(p), p);
            let mut tried = Vec::new();
            while common.len() > 1 && tried.len() < MIXED_TRIES {
                let entries = self.block_entries(&block.columns);
                let mixed = Mixing::new(&entries, block.rank, &mut seed);
                let reduced: Vec<(usize, usize, Vec<u64>)> = (entries.iter())
                    .map(|(i, k, e)| (*i, *k, e.iter().map(|c| big_mod(c, p)).collect()))
                    .collect();
                let small = |c: i64| c.rem_euclid(p as i64) as u64;
                let combination = mixed.apply(
                    &reduced,
                    |x, c| mul_mod(*x, small(c), p),
                    |a, b| (a + b) % p,
                );
                // Only the determinant modulo `common` matters: over F_p[t]/(common) when
                // that costs less than interpolating it (about 2 deg² products an operation
                // against one at each of `degree + 1` points).
                let degree = mixed.degree_bound(&entries);
                let width = common.len() - 1;
                let det = (2 * width * width <= degree + 1)
                    .then(|| determinant_in(&ResidueRing::new(&common, p), &combination))
                    .flatten()
                    .unwrap_or_else(|| determinant_poly_mod(&combination, degree, p));
                common = gcd_mod(&common, &det, p);
                tried.push((entries, mixed));
            }
            // Nothing left, or only roots of what is left already: outside it, the block
            // keeps its rank (with g square-free modulo p, a factor of g prime to what is
            // left reduces to one prime to it, so to `common`).
            if common.len() <= 1
                || (square_free && gcd_mod(&common, &left.reduced_mod(p), p).len() == common.len())
            {
                continue;
            }
            // Left modulo p: named over Q, the gcd with the exact determinants, from the
            // minor's and those of the combinations tried until it is no larger.
            exact_blocks += 1;
            let mut named = g.gcd(block.determinant);
            for (entries, mixed) in &tried {
                if named.degree() <= Some(common.len() - 1) {
                    break;
                }
                let combination =
                    mixed.apply(entries, |x: &BigInt, c| x * BigInt::from(c), |a, b| a + b);
                let degree = mixed.degree_bound(entries);
                named = named.gcd(&determinant_of_degree(&combination, degree));
            }
            if !named.divides(&left) {
                left = left.lcm(&named);
            }
        }
        let factor = g.divide_out(&left);
        (
            left,
            RuledOut {
                factor,
                prime: Some(p),
                exact_blocks,
            },
        )
    }

    /// The block's nonzero entries: the row's place among the block's rows, the column's
    /// among its columns, the polynomial.
    fn block_entries(&self, block: &[usize]) -> Vec<(usize, usize, Vec<BigInt>)> {
        let (_, local) = self.block_rows(block);
        (block.iter().enumerate())
            .flat_map(|(k, &j)| (self.columns[j].iter()).map(move |(row, poly)| (row, k, poly)))
            .map(|(row, k, poly)| (local[row], k, poly.clone()))
            .collect()
    }

    /// The block's rows, increasing, and each one's place among them.
    fn block_rows(&self, block: &[usize]) -> (Vec<usize>, FxHashMap<usize, usize>) {
        let mut rows: Vec<usize> = (block.iter())
            .flat_map(|&j| self.columns[j].iter().map(|(row, _)| *row))
            .collect();
        rows.sort_unstable();
        rows.dedup();
        let local = rows.iter().enumerate().map(|(i, &r)| (r, i)).collect();
        (rows, local)
    }
}

/// Random small integers `U` (`rank × rows`) and `V` (`columns × rank`) combining a block's
/// matrix `M` into the square `U M V`, of the block's generic rank.
struct Mixing {
    u: Vec<Vec<i64>>,
    v: Vec<Vec<i64>>,
}

impl Mixing {
    /// Fresh `U` and `V` for the block of `entries`, drawn from `seed` (advanced).
    fn new(entries: &[(usize, usize, Vec<BigInt>)], rank: usize, seed: &mut u64) -> Self {
        let rows = entries.iter().map(|e| e.0 + 1).max().unwrap_or(0);
        let columns = entries.iter().map(|e| e.1 + 1).max().unwrap_or(0);
        let mut draw = |n: usize| -> Vec<i64> {
            (0..n)
                .map(|_| {
                    *seed = seed.wrapping_add(RANDOM_POINT);
                    let mut z = *seed;
                    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
                    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
                    z ^= z >> 31;
                    (z % (2 * MIXING_BOUND + 1)) as i64 - MIXING_BOUND as i64
                })
                .collect()
        };
        let u = (0..rank).map(|_| draw(rows)).collect();
        let v = (0..columns).map(|_| draw(rank)).collect();
        Mixing { u, v }
    }

    /// A bound on the degree of `det(U M V)`, by Cauchy–Binet a combination of `M`'s minors of
    /// its size: the sum of the largest degrees of that many rows of `M`, or of columns.
    fn degree_bound<T>(&self, entries: &[(usize, usize, Vec<T>)]) -> usize {
        let rank = self.u.len();
        let largest = |mut degrees: Vec<usize>| {
            degrees.sort_unstable_by(|a, b| b.cmp(a));
            degrees.into_iter().take(rank).sum::<usize>()
        };
        let rows = self.u.first().map_or(0, Vec::len);
        let (mut rows, mut columns) = (vec![0; rows], vec![0; self.v.len()]);
        for (i, k, poly) in entries {
            let degree = poly.len().saturating_sub(1);
            rows[*i] = rows[*i].max(degree);
            columns[*k] = columns[*k].max(degree);
        }
        largest(rows).min(largest(columns))
    }

    /// `U M V`, its entries polynomials (lowest degree first) over the ring of `scale`
    /// (an entry's coefficient times a small integer) and `add`.
    fn apply<T: Clone + Default>(
        &self,
        entries: &[(usize, usize, Vec<T>)],
        scale: impl Fn(&T, i64) -> T,
        add: impl Fn(T, T) -> T,
    ) -> Vec<Vec<Vec<T>>> {
        let rank = self.u.len();
        let rows = self.u.first().map_or(0, Vec::len);
        let accumulate = |into: &mut Vec<T>, poly: &[T], c: i64| {
            if c == 0 {
                return;
            }
            if into.len() < poly.len() {
                into.resize(poly.len(), T::default());
            }
            for (x, y) in into.iter_mut().zip(poly) {
                *x = add(std::mem::take(x), scale(y, c));
            }
        };
        // M V, then U (M V).
        let mut mv: Vec<Vec<Vec<T>>> = vec![vec![Vec::new(); rank]; rows];
        for (i, k, poly) in entries {
            for (c, &x) in self.v[*k].iter().enumerate() {
                accumulate(&mut mv[*i][c], poly, x);
            }
        }
        (self.u.iter())
            .map(|u_row| {
                (0..rank)
                    .map(|c| {
                        let mut entry = Vec::new();
                        for (i, &x) in u_row.iter().enumerate() {
                            accumulate(&mut entry, &mv[i][c], x);
                        }
                        entry
                    })
                    .collect()
            })
            .collect()
    }
}

/// The determinant modulo `p` of the square matrix of polynomials (of integers, or of
/// residues modulo `p`), of degree at most `degree`: its `degree + 1` coefficients, lowest
/// first, from its values at `0, 1, …, degree` (each point's elimination on rayon's pool).
fn determinant_poly_mod<T: Residue + Sync>(
    minor: &[Vec<Vec<T>>],
    degree: usize,
    p: u64,
) -> Vec<u64> {
    let modulus = Modulus::new(p);
    let values: Vec<u64> = (0..=degree as u64)
        .into_par_iter()
        .map(|u| {
            determinant_mod(
                entries_at(minor, |e| evaluate_mod(e, u, &modulus)),
                &modulus,
            )
        })
        .collect();
    interpolate_mod(&values, p)
}

/// The determinant of the square matrix of polynomials over `F_p`, in the ring: by
/// elimination with pivots that are units there, `None` when a column's entries left are not
/// all zero and none is a unit.
fn determinant_in(ring: &ResidueRing, minor: &[Vec<Vec<u64>>]) -> Option<Vec<u64>> {
    let mut a: Vec<Vec<Vec<u64>>> = (minor.iter())
        .map(|row| row.iter().map(|e| ring.reduce(e.clone())).collect())
        .collect();
    let r = a.len();
    let mut det = ring.reduce(vec![1]);
    for col in 0..r {
        let units = (col..r).filter(|&i| !a[i][col].is_empty());
        let Some((found, inverse)) = units
            .clone()
            .find_map(|i| ring.inverse(&a[i][col]).map(|inverse| (i, inverse)))
        else {
            // A column of zeros: the determinant is zero; of zero divisors: not found here.
            return units.count().eq(&0).then(Vec::new);
        };
        if found != col {
            a.swap(found, col);
            det = ring.sub(&[], &det);
        }
        det = ring.mul(&det, &a[col][col]);
        let (above, below) = a.split_at_mut(col + 1);
        let pivot = &above[col];
        for row in below {
            if row[col].is_empty() {
                continue;
            }
            let factor = ring.mul(&row[col], &inverse);
            for (x, y) in row[col..].iter_mut().zip(&pivot[col..]) {
                *x = ring.sub(x, &ring.mul(&factor, y));
            }
        }
    }
    Some(det)
}

/// A bound on the degree of the determinant of the square matrix of polynomials: the sum of
/// its rows' degrees, or of its columns', whichever is smaller.
fn degree_bound<T>(minor: &[Vec<Vec<T>>]) -> usize {
    let mut rows = 0;
    let mut columns = vec![0; minor.len()];
    for row in minor {
        let mut largest = 0;
        for (k, e) in row.iter().enumerate() {
            let degree = e.len().saturating_sub(1);
            largest = largest.max(degree);
            columns[k] = columns[k].max(degree);
        }
        rows += largest;
    }
    rows.min(columns.into_iter().sum())
}

/// The square of Hadamard's bound on the coefficients of the determinant of the square
/// matrix of polynomials `S`: the coefficient of `t^k` is the mean of `det S(z) z^{−k}` over
/// the unit circle `|z| = 1` (Cauchy's formula), so at most the largest `|det S(z)|` there,
/// where `|det S(z)| ≤ Π_i (Σ_j |S_ij(z)|²)^{1/2}` (Hadamard's inequality for the complex
/// matrix `S(z)`) and `|S_ij(z)| ≤ ‖S_ij‖₁` (the sum of its coefficients' absolute values);
/// so every coefficient's square is at most `Π_i Σ_j ‖S_ij‖₁²`, or the same by columns
/// (`det Sᵀ = det S`), whichever is smaller. A Hadamard matrix of constants meets it.
fn coefficient_bound_squared(minor: &[Vec<Vec<BigInt>>]) -> BigInt {
    let norms: Vec<Vec<BigInt>> = (minor.iter())
        .map(|row| {
            (row.iter())
                .map(|e| e.iter().map(BigInt::abs).sum())
                .collect()
        })
        .collect();
    let by_rows: BigInt = (norms.iter())
        .map(|row| row.iter().map(|n| n * n).sum::<BigInt>())
        .product();
    let by_columns: BigInt = (0..norms.len())
        .map(|k| norms.iter().map(|row| &row[k] * &row[k]).sum::<BigInt>())
        .product();
    by_rows.min(by_columns)
}

/// A fixed point in `F_p` standing for a random one (the golden ratio's 64 bits).
const RANDOM_POINT: u64 = 0x9E37_79B9_7F4A_7C15;

/// The determinant of the square matrix of polynomials, exactly: modulo primes whose product
/// passes twice Hadamard's bound on its coefficients ([`coefficient_bound_squared`]), each
/// from its values at `deg + 1` points ([`degree_bound`]), then by the Chinese remainder
/// theorem.
fn determinant(minor: &[Vec<Vec<BigInt>>]) -> IntPoly {
    determinant_of_degree(minor, degree_bound(minor))
}

/// [`determinant`] of a matrix whose determinant has degree at most `degree`.
fn determinant_of_degree(minor: &[Vec<Vec<BigInt>>], degree: usize) -> IntPoly {
    let r = minor.len();
    if r == 0 {
        return IntPoly::from_i64(&[1]);
    }
    let degree = degree.min(degree_bound(minor));
    // The modulus must pass twice the bound: its square four times the bound's square.
    let needed = BigInt::from(4) * coefficient_bound_squared(minor);
    let mut modulus = BigInt::one();
    let mut coeffs = vec![BigInt::zero(); degree + 1];
    let mut p = PRIME;
    while &modulus * &modulus <= needed {
        let residues = determinant_poly_mod(minor, degree, p);
        // x ≡ coeffs mod modulus, x ≡ residue mod p.
        let m_mod_p = big_mod(&modulus, p);
        let inverse = inverse_mod(m_mod_p, p);
        for (c, &residue) in coeffs.iter_mut().zip(&residues) {
            let difference = (residue + p - big_mod(c, p)) % p;
            let k = mul_mod(difference, inverse, p);
            *c += &modulus * BigInt::from(k);
        }
        modulus *= BigInt::from(p);
        p = previous_prime(p);
    }
    let half = &modulus / 2;
    for c in &mut coeffs {
        if *c > half {
            *c -= &modulus;
        }
    }
    IntPoly::new(coeffs)
}

/// The matrix of `value(entry)` for each entry.
fn entries_at<T>(minor: &[Vec<Vec<T>>], value: impl Fn(&[T]) -> u64) -> Vec<Vec<u64>> {
    (minor.iter())
        .map(|row| row.iter().map(|e| value(e)).collect())
        .collect()
}

/// The determinant of the square matrix `a` modulo `p`.
fn determinant_mod(mut a: Vec<Vec<u64>>, p: &Modulus) -> u64 {
    let r = a.len();
    let mut det = 1_u64;
    for col in 0..r {
        let Some(found) = (col..r).find(|&i| a[i][col] != 0) else {
            return 0;
        };
        if found != col {
            a.swap(found, col);
            det = p.sub(0, det);
        }
        det = p.mul(det, a[col][col]);
        let inverse = inverse_mod(a[col][col], p.prime());
        let (above, below) = a.split_at_mut(col + 1);
        let support = support_after(&above[col], col);
        for row in below {
            clear_entry(row, &above[col], &support, col, inverse, p);
        }
    }
    det
}

/// The columns after `col` where the pivot's row is not zero: the only entries that
/// clearing its column changes in another row (the equations' blocks stay sparse).
fn support_after(pivot: &[u64], col: usize) -> Vec<usize> {
    (col + 1..pivot.len()).filter(|&j| pivot[j] != 0).collect()
}

/// The coefficients, lowest degree first, of the polynomial of degree `< n` taking the
/// `values` at `0, 1, …, n − 1`, modulo `p` (Newton's divided differences).
fn interpolate_mod(values: &[u64], p: u64) -> Vec<u64> {
    let n = values.len();
    let mut d = values.to_vec();
    for k in 1..n {
        let inverse = inverse_mod(k as u64 % p, p);
        for i in (k..n).rev() {
            d[i] = mul_mod((d[i] + p - d[i - 1]) % p, inverse, p);
        }
    }
    // Σ d_k Π_{i<k} (t − i), expanded from the innermost.
    let mut coeffs = vec![0_u64; n];
    for k in (0..n).rev() {
        // coeffs = coeffs·(t − k) + d_k
        let mut shifted = vec![0_u64; n];
        for i in 0..n {
            if coeffs[i] == 0 {
                continue;
            }
            if i + 1 < n {
                shifted[i + 1] = (shifted[i + 1] + coeffs[i]) % p;
            }
            let sub = mul_mod(coeffs[i], k as u64 % p, p);
            shifted[i] = (shifted[i] + p - sub) % p;
        }
        shifted[0] = (shifted[0] + d[k]) % p;
        coeffs = shifted;
    }
    coeffs
}

/// Subtracts from `row` the multiple of `pivot` that makes its entry at `col` zero
/// (`inverse` the inverse of the pivot's there), modulo `p`: at `col`, and at the columns
/// of the pivot's `support` after it ([`support_after`]), the only others it changes.
fn clear_entry(
    row: &mut [u64],
    pivot: &[u64],
    support: &[usize],
    col: usize,
    inverse: u64,
    p: &Modulus,
) {
    let factor = p.mul(row[col], inverse);
    if factor == 0 {
        return;
    }
    row[col] = 0;
    for &j in support {
        row[j] = p.sub(row[j], p.mul(factor, pivot[j]));
    }
}

/// `poly(u)` modulo `p`.
fn evaluate_mod<T: Residue>(poly: &[T], u: u64, p: &Modulus) -> u64 {
    (poly.iter().rev()).fold(0, |acc, c| p.add(p.mul(acc, u), c.residue(p.prime())))
}

/// A coefficient of the matrices' polynomials, as a residue modulo `p`.
trait Residue {
    /// Its residue in `[0, p)`.
    fn residue(&self, p: u64) -> u64;
}

impl Residue for BigInt {
    fn residue(&self, p: u64) -> u64 {
        big_mod(self, p)
    }
}

/// A residue already reduced modulo `p`.
impl Residue for u64 {
    fn residue(&self, _p: u64) -> u64 {
        *self
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::search::SearchSpace;
    use trigpoly::VarsBuilder;

    /// The system of the Hamiltonian `h` in `x, y, p_x, p_y` and the `parameters`.
    fn planar(h: &str, parameters: &[&str]) -> System {
        crate::search::level_set::tests::on_the_plane("test", h, parameters)
    }

    fn values_of(found: &ExceptionalValues) -> Vec<String> {
        found.values.iter().map(|v| v.value.to_string()).collect()
    }

    fn space(momenta: u32, positions: u32) -> SearchOptions {
        SearchOptions::new(
            SearchSpace::default()
                .momenta_degree(momenta)
                .positions_degree(positions),
        )
    }

    #[test]
    fn the_quartic_potentials_at_b_8_have_every_irrational_root_ruled_out() {
        // x⁴ + a x²y² + 8y⁴, quadratic in the momenta, positions degree 5: the rational values
        // found, and no irrational root of the determinants left.
        let system = planar("(p_x^2 + p_y^2)/2 + x^4 + a*x^2*y^2 + 8*y^4", &["a"]);
        let found = exceptional_values(&system, &space(2, 5), system.var("a")).unwrap();
        assert_eq!(found.determinants.unexamined.degree(), Some(0));
        assert_eq!(
            found.determinants.ruled_out.count(),
            4,
            "{:?}",
            found.determinants.ruled_out
        );
        assert_eq!(values_of(&found), ["0"]);
    }

    #[test]
    fn oscillators_with_frequency_squares_a_squared_and_one_are_exceptional_at_a_equal_to_plus_or_minus_one(
    ) {
        // (x² + a² y²)/2: isotropic, with the angular momentum, at a = ±1 alone (a = 0 frees y
        // and gives p_y too).
        let system = planar("(p_x^2 + p_y^2)/2 + (x^2 + a^2*y^2)/2", &["a"]);
        let a = system.var("a");
        let found = exceptional_values(&system, &space(2, 2), a).unwrap();
        assert_eq!(values_of(&found), ["-1", "0", "1"]);
        for v in &found.values {
            assert!(v.found.basis.len() > found.generic.basis.len());
        }
    }

    #[test]
    fn henon_heiles_at_a_equal_b_equal_one_has_its_second_quadratic_integral_at_c_one_third_and_two(
    ) {
        let system = planar(
            "(p_x^2 + p_y^2)/2 + (A*x^2 + B*y^2)/2 + x^2*y + C*y^3",
            &["A", "B", "C"],
        );
        // The KdV case's integral has x⁴: degree 4 in the positions.
        let found = exceptional_values(&system, &space(2, 4), system.var("C")).unwrap();
        assert_eq!(values_of(&found), ["1/3", "2"]);
        // Generically 1 and H; one more integral at each value, proved.
        assert_eq!(found.generic.basis.len(), 2);
        for v in &found.values {
            assert_eq!(v.found.basis.len(), 3);
            assert!(v.found.basis.iter().all(|i| i.proved_fixed));
        }
    }

    /// A block whose minor has more rows than `SearchOptions::max_minor` stops the search at
    /// that limit, `EngineLimit::MinorRows`, before its determinant is computed; at as many
    /// rows as the largest minor's it runs.
    #[test]
    fn a_minor_past_max_minor_stops_at_that_limit() {
        let system = planar(
            "(p_x^2 + p_y^2)/2 + (A*x^2 + B*y^2)/2 + x^2*y + C*y^3",
            &["A", "B", "C"],
        );
        let c = system.var("C");
        let rows = exceptional_values(&system, &space(2, 4), c)
            .unwrap()
            .determinants
            .largest_minor
            .0;
        let at_most = |n| exceptional_values(&system, &space(2, 4).max_minor(n), c);
        let err = at_most(rows - 1).unwrap_err();
        assert_eq!(err.limit(), Some(EngineLimit::MinorRows), "{err}");
        assert!(
            matches!(&err, EngineError::PastLimit { limit, .. } if *limit == rows - 1),
            "{err:?}"
        );
        assert!(err.to_string().contains("raise the limit"), "{err}");
        assert_eq!(at_most(rows).unwrap().determinants.largest_minor.0, rows);
    }

    /// The generic minor is taken from the rows its elimination picked, whatever the order in
    /// which the block's columns meet its rows: here column 0 meets row 4 before column 1
    /// meets row 1, and the rank is 2 (rows 0 and 1 of columns 0 and 1), so the minor's
    /// determinant is no zero polynomial. Numbering the rows by first meeting while reading
    /// them back in increasing order took rows 0 and 1 for the pivots of rows 0 and 4, a
    /// singular minor.
    #[test]
    fn the_generic_minor_is_nonsingular_whatever_order_its_rows_are_met_in() {
        let one = || vec![BigInt::one()];
        let matrix = PolyMatrix {
            columns: vec![
                vec![(0, one()), (4, one())],
                vec![(1, one())],
                vec![(0, one()), (1, one()), (4, one())],
            ],
            rows: 5,
        };
        let block = [0, 1, 2];
        assert_eq!(blocks(&matrix.columns, matrix.rows), [block]);
        let minor = matrix.generic_minor(&block);
        assert_eq!(minor.len(), 2);
        assert!(!determinant(&minor).is_zero());
    }

    #[test]
    fn the_anisotropic_oscillator_at_degree_three_is_exceptional_at_its_resonances_one_to_two_and_one_to_three(
    ) {
        // (x² + a y²)/2 with a = (ω_y/ω_x)²: the cubic integrals of 1:2 and 2:1 (two each),
        // the one of 1:3 and 3:1 that degree 3 in the momenta and positions holds, the
        // isotropic a = 1 and the free a = 0; the other roots of the determinants are not
        // values (a = 2, say).
        let system = planar("(p_x^2 + p_y^2)/2 + (x^2 + a*y^2)/2", &["a"]);
        let found = exceptional_values(&system, &space(3, 3), system.var("a")).unwrap();
        assert_eq!(values_of(&found), ["0", "1/9", "1/4", "1", "4", "9"]);
        assert_eq!(found.determinants.unexamined.degree(), Some(0));
        assert!(found.determinants.unexamined_in(system.vars()).is_none());
        assert!(!found.spurious.is_empty());
        let generic = found.generic.basis.len();
        let more: Vec<usize> = (found.values.iter())
            .map(|v| v.found.basis.len() - generic)
            .collect();
        assert_eq!(more, [3, 1, 2, 7, 2, 1]);
    }

    #[test]
    fn a_negative_value_is_found() {
        // (x² + (a + 2) y²)/2: y free at a = −2, isotropic at a = −1.
        let system = planar("(p_x^2 + p_y^2)/2 + (x^2 + (a + 2)*y^2)/2", &["a"]);
        let found = exceptional_values(&system, &space(2, 2), system.var("a")).unwrap();
        assert_eq!(values_of(&found), ["-2", "-1"]);
    }

    #[test]
    fn a_shifted_one_to_two_oscillator_has_no_exceptional_value() {
        // The energies of x and y are integrals for every a, and nothing else of degree 2.
        let system = planar("(p_x^2 + p_y^2)/2 + (x^2 + 4*y^2)/2 + a*x", &["a"]);
        let found = exceptional_values(&system, &space(2, 2), system.var("a")).unwrap();
        assert!(found.values.is_empty(), "{:?}", values_of(&found));
        assert_eq!(found.generic.basis.len(), 3);
    }

    #[test]
    fn irrational_exceptional_values_are_reported_not_claimed() {
        // Isotropic where a² − 1 = 1, at a = ±√2: no rational value, a² − 2 left unexamined,
        // every minor vanishing there; the determinants' other irrational roots, a² = 3, 5
        // and 3/2 (frequency ratios √2, 2 and √(1/2), no quadratic integral more), ruled out.
        let system = planar("(p_x^2 + p_y^2)/2 + (x^2 + (a^2 - 1)*y^2)/2", &["a"]);
        let found = exceptional_values(&system, &space(2, 2), system.var("a")).unwrap();
        assert_eq!(
            found.determinants.unexamined,
            IntPoly::from_i64(&[-2, 0, 1])
        );
        for ruled_out in [[-3, 0, 1], [-5, 0, 1], [-3, 0, 2]] {
            assert!(IntPoly::from_i64(&ruled_out).divides(&found.determinants.ruled_out.factor));
        }
        assert_eq!(found.determinants.ruled_out.count(), 6);
        assert!(found.determinants.ruled_out.prime.is_some());
        // Written in a: the same polynomial, its value at a = 3 the IntPoly's.
        let written = found.determinants.unexamined_in(system.vars()).unwrap();
        let three = Expr::constant(system.vars(), 3.into());
        let at_three = written.subst(system.var("a"), &three).unwrap();
        let value: BigInt = (found.determinants.unexamined.coeffs().iter().rev())
            .fold(BigInt::zero(), |acc, c| acc * 3 + c);
        assert_eq!(
            at_three,
            &Expr::constant(system.vars(), 1.into()) * &Rational::from(value)
        );
        assert_eq!(values_of(&found), ["-1", "1"]);
    }

    #[test]
    fn what_the_search_for_exceptional_values_does_not_take_is_refused() {
        let system = planar(
            "(p_x^2 + p_y^2)/2 + (A*x^2 + B*y^2)/2 + x^2*y + C*y^3",
            &["A", "B", "C"],
        );
        let c = system.var("C");
        let fixed = space(2, 3).fix(c, Rational::from(2));
        let refused = exceptional_values(&system, &fixed, c)
            .unwrap_err()
            .to_string();
        assert!(refused.contains("a value fixed for C"), "{refused}");
        let symbolic = space(2, 3).symbolic(system.var("A"));
        let refused = exceptional_values(&system, &symbolic, c)
            .unwrap_err()
            .to_string();
        assert!(refused.contains("kept symbolic"), "{refused}");
        let refused = exceptional_values(&system, &space(2, 3), system.var("x"))
            .unwrap_err()
            .to_string();
        assert!(refused.contains("only a parameter"), "{refused}");
    }

    #[test]
    fn oscillators_with_frequency_squares_one_and_one_over_a_are_exceptional_at_a_equal_to_one_alone(
    ) {
        // A negative power of a in H: each row made a polynomial, a = 0 no candidate.
        let system = planar("(p_x^2 + p_y^2)/2 + (x^2 + y^2/a)/2", &["a"]);
        let found = exceptional_values(&system, &space(2, 2), system.var("a")).unwrap();
        assert!(found.determinants.zero_left_out);
        assert_eq!(values_of(&found), ["1"]);
        assert!(found.spurious.iter().all(|r| !r.is_zero()));
        let at_one = &found.values[0].found;
        assert!(at_one.basis.len() > found.generic.basis.len());
        assert!(holds_angular_momentum(at_one));
        // With a itself, a = 0 is one (y free there, p_y an integral) and no negative power.
        let direct = planar("(p_x^2 + p_y^2)/2 + (x^2 + a*y^2)/2", &["a"]);
        let found = exceptional_values(&direct, &space(2, 2), direct.var("a")).unwrap();
        assert!(!found.determinants.zero_left_out);
        assert_eq!(values_of(&found), ["0", "1"]);
    }

    /// Whether `x p_y − y p_x` is among the integrals `found`.
    fn holds_angular_momentum(found: &SearchResult) -> bool {
        (found.basis.iter()).any(|i| i.expr().to_string() == "x p_y − y p_x")
    }

    /// The plane with the parameter `a` and the declared `denominators` (in `a` alone).
    fn planar_over(h: &str, denominators: &[&str]) -> System {
        let mut builder = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .momentum("p_x")
            .momentum("p_y")
            .parameter("a");
        for d in denominators {
            builder = builder.denominator(d).unwrap();
        }
        let vars = builder.build().unwrap();
        let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y")]).unwrap();
        System::new("test", space, Expr::parse(&vars, h).unwrap()).unwrap()
    }

    #[test]
    fn oscillators_with_frequency_squares_one_and_one_over_a_plus_one_are_exceptional_at_a_zero_alone(
    ) {
        // 1/(a + 1) declared: each row times its power of a + 1; a = −1, where H has no
        // value, is no candidate, and the generic value no root of it.
        let system = planar_over("(p_x^2 + p_y^2)/2 + (x^2 + y^2/(a + 1))/2", &["a + 1"]);
        let a = system.var("a");
        let found = exceptional_values(&system, &space(2, 2), a).unwrap();
        assert_eq!(values_of(&found), ["0"]);
        let minus_one = Rational::from(-1);
        assert!(found.spurious.iter().all(|r| *r != minus_one));
        assert_ne!(found.determinants.generic_value, minus_one);
        assert!(!found.determinants.zero_left_out);
        let at_zero = &found.values[0].found;
        assert!(holds_angular_momentum(at_zero));
        // The same oscillators with b = 1/(a + 1) itself: b = 1 is a = 0, and b = 0, where y
        // is free, is no value of a.
        let direct = planar("(p_x^2 + p_y^2)/2 + (x^2 + b*y^2)/2", &["b"]);
        let by_b = exceptional_values(&direct, &space(2, 2), direct.var("b")).unwrap();
        assert_eq!(values_of(&by_b), ["0", "1"]);
        assert_eq!(by_b.values[1].found.basis.len(), at_zero.basis.len());
        assert_eq!(by_b.generic.basis.len(), found.generic.basis.len());
    }

    #[test]
    fn the_irrational_roots_of_a_declared_denominator_are_no_roots_left_to_examine() {
        // Isotropic at a² − 2 = 1, a = ±√3: the determinants' irrational part is a² − 3
        // alone, a² − 2 (no value of H) divided out of it.
        let system = planar_over("(p_x^2 + p_y^2)/2 + (x^2 + y^2/(a^2 - 2))/2", &["a^2 - 2"]);
        let found = exceptional_candidates(&system, &space(2, 2), system.var("a")).unwrap();
        let told = &found.determinants;
        assert_eq!(told.unexamined, IntPoly::from_i64(&[-3, 0, 1]));
        let d = IntPoly::from_i64(&[-2, 0, 1]);
        assert_eq!(told.ruled_out.factor.gcd(&d).degree(), Some(0));
        assert!(told.denominator_roots_left_out.is_empty());
    }

    #[test]
    fn a_parameter_in_a_declared_radical_or_in_a_denominator_beside_a_phase_variable_is_refused() {
        let refused = |h: &str, declare: &dyn Fn(VarsBuilder) -> VarsBuilder| {
            let builder = Vars::builder()
                .coordinate("x")
                .coordinate("y")
                .momentum("p_x")
                .momentum("p_y")
                .parameter("a");
            let vars = declare(builder).build().unwrap();
            let space_of = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y")]).unwrap();
            let system = System::new("test", space_of, Expr::parse(&vars, h).unwrap()).unwrap();
            exceptional_candidates(&system, &space(2, 2), system.var("a"))
                .unwrap_err()
                .to_string()
        };
        let radical = refused("(p_x^2 + p_y^2)/2 + r*x^2", &|b| b.radical("r", "a^2 + 1"));
        assert!(radical.contains("a in a declared radical, r"), "{radical}");
        let beside = refused("(p_x^2 + p_y^2)/2 + 1/(x - a*y)", &|b| {
            b.denominator("x - a*y").unwrap()
        });
        assert!(
            beside.contains("a declared denominator that holds a phase variable too"),
            "{beside}"
        );
    }

    #[test]
    fn henon_heiles_with_b_sixteen_a_has_its_quartic_integral_at_c_sixteen_thirds() {
        let system = planar(
            "(p_x^2 + p_y^2)/2 + (A*x^2 + B*y^2)/2 + x^2*y + C*y^3",
            &["A", "B", "C"],
        );
        let options = space(4, 6).fix(system.var("B"), Rational::from(16));
        let found = exceptional_values(&system, &options, system.var("C")).unwrap();
        // The KdV case's quadratic integral and its products with H, then the quartic one.
        assert_eq!(values_of(&found), ["2", "16/3"]);
        for v in &found.values {
            assert!(v.found.basis.len() > found.generic.basis.len());
            assert!(v.found.basis.iter().all(|i| i.proved_fixed));
        }
        // Roots of the determinants where the search found nothing more.
        assert!(!found.spurious.is_empty());
    }

    /// The level set `expr = value` of `system`, as `--on` reads it.
    fn level(system: &System, expr: &str, value: &str) -> crate::search::LevelSet {
        let e = |t: &str| Expr::parse(system.vars(), t).unwrap();
        crate::search::LevelSet::new(&format!("{expr} = {value}"), e(expr), e(value))
    }

    /// The heavy top with `I1 = I2 = 1` and the third moment `I3`, on e(3)*.
    fn heavy_top() -> System {
        crate::search::level_set::tests::on_e3(
            "heavy top",
            "(M1^2 + M2^2)/2 + M3^2/(2*I3) - c*gamma1",
            &["I3", "c"],
        )
    }

    #[test]
    fn the_heavy_top_on_the_area_integrals_zero_level_has_the_goryachev_chaplygin_cubic_at_i3_one_quarter(
    ) {
        let system = heavy_top();
        let area = level(&system, "M1*gamma1 + M2*gamma2 + M3*gamma3", "0");
        let options = SearchOptions::new(SearchSpace::default().poisson_degree(3)).on(area);
        let found = exceptional_values(&system, &options, system.var("I3")).unwrap();
        let values = values_of(&found);
        assert!(values.contains(&"1/4".to_string()), "{values:?}");
        // Everywhere searched on the level set, every integral proved there.
        for v in &found.values {
            assert!(v.found.basis.len() > found.generic.basis.len());
            assert!(v.found.basis.iter().all(|i| i.on_level.is_some()));
        }
        // The cubic's top part, M3(M1² + M2²), is in the space at 1/4 and not at a generic I3.
        let at_quarter = &found.values[values.iter().position(|v| v == "1/4").unwrap()].found;
        let cubic = |r: &SearchResult| {
            r.basis
                .iter()
                .any(|i| i.expr().to_string().contains("M1² M3"))
        };
        assert!(cubic(at_quarter));
        assert!(!cubic(&found.generic));
    }

    #[test]
    fn a_level_set_on_which_no_value_of_the_parameter_has_more_integrals_gives_none() {
        // The y oscillator's energy level p_y² + 4y² = 4 is kept for every a; a x only shifts
        // the x oscillator, and no a gives more there.
        let system = planar("(p_x^2 + p_y^2)/2 + (x^2 + 4*y^2)/2 + a*x", &["a"]);
        let energy = level(&system, "p_y^2 + 4*y^2", "4");
        let found = exceptional_values(&system, &space(2, 2).on(energy), system.var("a")).unwrap();
        assert!(found.values.is_empty(), "{:?}", values_of(&found));
        assert!(found.generic.on.is_some());
    }

    #[test]
    fn a_level_set_whose_polynomial_holds_the_parameter_is_refused() {
        let system = planar("(p_x^2 + p_y^2)/2 + (x^2 + a*y^2)/2", &["a"]);
        let holding_a = level(&system, "p_y^2 + a*y^2", "a");
        let refused = exceptional_values(&system, &space(2, 2).on(holding_a), system.var("a"))
            .unwrap_err()
            .to_string();
        assert!(
            refused.contains("a level set whose polynomial holds a"),
            "{refused}"
        );
    }

    #[test]
    fn a_level_set_kept_at_some_values_of_the_parameter_alone_is_refused_saying_so() {
        // {x p_y − y p_x, H} = (1 − a) x y: the flow keeps the level set at a = 1 alone.
        let system = planar("(p_x^2 + p_y^2)/2 + (x^2 + a*y^2)/2", &["a"]);
        let angular = level(&system, "x*p_y - y*p_x", "0");
        let refused = exceptional_values(&system, &space(2, 2).on(angular), system.var("a"))
            .unwrap_err()
            .to_string();
        assert!(
            refused.starts_with("the flow of H leaves the level set"),
            "{refused}"
        );
        assert!(
            refused.contains("the flow must keep the level set at every value of a"),
            "{refused}"
        );
    }

    /// [`Candidates::confirm`] searches once at the generic value and once at each root, with
    /// the caller's search, and keeps the roots where it finds more: as
    /// [`exceptional_values`] does with its own.
    #[test]
    fn confirming_the_candidates_searches_once_at_each_with_the_callers_search() {
        let system = planar("(p_x^2 + p_y^2)/2 + (x^2 + a*y^2)/2", &["a"]);
        let a = system.var("a");
        let options = space(3, 3);
        let candidates = exceptional_candidates(&system, &options, a).unwrap();
        let roots = candidates.roots.clone();
        let mut searched = Vec::new();
        let at = |value: &Rational| options.clone().fix(a, value.clone());
        let found = candidates
            .confirm(
                |value| {
                    searched.push(value.clone());
                    search(&system, &at(value))
                },
                |value, found| basis_rank(&system, &at(value), found, MAX_RANK_MINORS),
            )
            .unwrap();
        assert_eq!(searched.len(), roots.len() + 1);
        assert_eq!(searched[1..], roots[..]);
        let direct = exceptional_values(&system, &options, a).unwrap();
        assert_eq!(values_of(&found), values_of(&direct));
        assert_eq!(found.spurious, direct.spurious);
    }

    /// `0` is said to be left out only where it was a root: `x²/2 + y²/(2a)` has it (each row
    /// times `a`, those of `x²` then vanishing at `a = 0`); `H/a` has not.
    #[test]
    fn the_determinant_modulo_a_polynomial_is_the_interpolated_one_reduced() {
        let p = 1_000_003;
        let mut seed = 1_u64;
        let mut draw = |n: usize| -> Vec<u64> {
            (0..n)
                .map(|_| {
                    seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
                    (seed >> 33) % 5
                })
                .collect()
        };
        // m = (t − 1)(t − 2)(t² + 2): the roots 1 and 2 in F_p, two more outside it.
        let m = [4, p - 6, 4, p - 3, 1];
        let ring = ResidueRing::new(&m, p);
        for size in 1..6 {
            let minor: Vec<Vec<Vec<u64>>> = (0..size)
                .map(|_| (0..size).map(|_| draw(3)).collect())
                .collect();
            let interpolated = determinant_poly_mod(&minor, 2 * size, p);
            let in_ring = determinant_in(&ring, &minor).expect("entries of no common root");
            assert_eq!(in_ring, ring.reduce(interpolated), "size {size}");
        }
        // A row vanishing at t = 1: the determinant is found over F_p or not at all.
        let minor = vec![
            vec![vec![p - 1, 1], vec![p - 1, 1]],
            vec![vec![2, 1], vec![0, 0, 1]],
        ];
        let interpolated = determinant_poly_mod(&minor, 3, p);
        if let Some(in_ring) = determinant_in(&ring, &minor) {
            assert_eq!(in_ring, ring.reduce(interpolated));
        }
        // A column of zeros: zero.
        let zero = vec![vec![Vec::new(), vec![1]], vec![Vec::new(), vec![2, 1]]];
        assert_eq!(determinant_in(&ring, &zero), Some(Vec::new()));
        // Both entries of the first column dividing zero: not found.
        let stuck = vec![vec![vec![p - 1, 1], vec![1]], vec![vec![p - 2, 1], vec![3]]];
        assert_eq!(determinant_in(&ring, &stuck), None);
    }

    #[test]
    fn zero_is_left_out_only_where_it_was_a_root() {
        let at = |h: &str| {
            let system = planar(h, &["a"]);
            exceptional_candidates(&system, &space(2, 2), system.var("a")).unwrap()
        };
        let one_over_a = at("(p_x^2 + p_y^2)/2 + (x^2 + y^2/a)/2");
        assert!(one_over_a.determinants.zero_left_out);
        assert!(one_over_a.roots.iter().all(|r| !r.is_zero()));
        // H/a has H's integrals at every a ≠ 0: each row times a is constant, no root at all.
        let scaled = at("(p_x^2 + p_y^2 + x^2 + y^2)/(2*a)");
        assert!(!scaled.determinants.zero_left_out);
        assert!(scaled.roots.is_empty(), "{:?}", scaled.roots);
    }

    /// Integer polynomials, lowest degree first, for the plain expansions below.
    type Poly = Vec<BigInt>;

    fn poly_add(a: &mut Poly, b: &[BigInt], negate: bool) {
        if a.len() < b.len() {
            a.resize(b.len(), BigInt::zero());
        }
        for (x, y) in a.iter_mut().zip(b) {
            if negate {
                *x -= y;
            } else {
                *x += y;
            }
        }
    }

    /// The determinant by Laplace's expansion along the first row, over `Z[t]`: no prime,
    /// no bound, no evaluation.
    fn laplace(m: &[Vec<Poly>]) -> Poly {
        if m.is_empty() {
            return vec![BigInt::one()];
        }
        let mut det = Poly::new();
        for (k, entry) in m[0].iter().enumerate() {
            let minor: Vec<Vec<Poly>> = (m[1..].iter())
                .map(|row| {
                    (row.iter().enumerate().filter(|&(j, _)| j != k))
                        .map(|(_, e)| e.clone())
                        .collect()
                })
                .collect();
            let product = IntPoly::new(entry.clone()).mul(&IntPoly::new(laplace(&minor)));
            poly_add(&mut det, product.coeffs(), k % 2 == 1);
        }
        det
    }

    fn xorshift(mut x: u64) -> impl FnMut() -> u64 {
        move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        }
    }

    /// Random square matrices of polynomials: sizes 1 to 5, degrees up to 3, entries zero a
    /// third of the time (a sparse pivot row), coefficients small, or of 60 to 120 bits
    /// (several primes), or `±PRIME` and `±(PRIME − 1)`, the first prime and one below it.
    fn random_matrices(count: usize) -> Vec<Vec<Vec<Poly>>> {
        let mut next = xorshift(0x9E37_79B9_7F4A_7C15);
        let mut coefficient = move || {
            let sign = if next().is_multiple_of(2) { 1 } else { -1 };
            let magnitude = match next() % 6 {
                0 => BigInt::from(PRIME) - next() % 2,
                1 => BigInt::from(next()) << (next() % 60),
                _ => BigInt::from(next() % 7),
            };
            sign * magnitude
        };
        let mut shape = xorshift(0x2545_F491_4F6C_DD1D);
        (0..count)
            .map(|_| {
                let n = 1 + (shape() % 5) as usize;
                (0..n)
                    .map(|_| {
                        (0..n)
                            .map(|_| match shape() % 3 {
                                0 => Vec::new(),
                                _ => (0..=shape() % 4).map(|_| coefficient()).collect(),
                            })
                            .collect()
                    })
                    .collect()
            })
            .collect()
    }

    #[test]
    fn the_determinant_mod_primes_is_laplaces_expansion_over_the_integers() {
        for m in random_matrices(60) {
            let exact = IntPoly::new(laplace(&m));
            assert_eq!(determinant(&m), exact, "{m:?}");
            // The degree bound holds, and is used: interpolating below it would be wrong.
            assert!(exact.degree().unwrap_or(0) <= degree_bound(&m), "{m:?}");
        }
    }

    #[test]
    fn a_prime_dividing_the_leading_coefficient_loses_no_coefficient() {
        // det = PRIME·q·t² + q·t − 1, q the second prime: its leading coefficient is 0 modulo
        // both primes, its value mod each is of lower degree, the CRT still gives each one.
        let q = previous_prime(PRIME);
        let big = |n: u64| BigInt::from(n);
        let m = vec![
            vec![vec![big(1), big(PRIME)], vec![big(1)]],
            vec![vec![big(1)], vec![big(0), big(q)]],
        ];
        let exact = IntPoly::new(vec![big(0) - 1, big(q), big(PRIME) * big(q)]);
        assert_eq!(laplace(&m), exact.coeffs().to_vec());
        assert_eq!(determinant(&m), exact);
    }

    /// The Sylvester–Hadamard matrix of order `2^k`, times `c`: its determinant `±c^n n^{n/2}`
    /// meets Hadamard's bound.
    fn hadamard(k: u32, c: i64) -> Vec<Vec<Poly>> {
        let n = 1_usize << k;
        (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        let sign = if (i & j).count_ones().is_multiple_of(2) {
                            1
                        } else {
                            -1
                        };
                        vec![BigInt::from(sign * c)]
                    })
                    .collect()
            })
            .collect()
    }

    #[test]
    fn a_hadamard_matrix_meets_the_coefficient_bound_and_is_reconstructed_past_it() {
        // 4×4 times c = 20480: det = 16 c⁴ ≈ 2^61.3, between PRIME/2 and PRIME. Hadamard's bound
        // is met exactly (det² = the bound's square), so one prime, PRIME < 2·det, is not
        // enough: a modulus past the bound but not twice it would return det − PRIME.
        let c = 20480_i64;
        let m = hadamard(2, c);
        let det = BigInt::from(16) * BigInt::from(c).pow(4);
        assert!(BigInt::from(PRIME) < BigInt::from(2) * &det && det < BigInt::from(PRIME));
        assert_eq!(coefficient_bound_squared(&m), &det * &det);
        assert_eq!(laplace(&m), vec![det.clone()]);
        assert_eq!(determinant(&m), IntPoly::new(vec![det.clone()]));
        // Two rows swapped: −det, the other end of the symmetric range.
        let mut swapped = m.clone();
        swapped.swap(0, 1);
        assert_eq!(determinant(&swapped), IntPoly::new(vec![-det]));
        // Order 8, c = 1: 8⁴ = 4096.
        assert_eq!(determinant(&hadamard(3, 1)), IntPoly::from_i64(&[4096]));
    }

    #[test]
    fn the_degree_bound_takes_the_columns_when_they_are_tighter() {
        // [[t³, 1], [2t³, 1]]: rows 3 + 3, columns 3 + 0; det = −t³.
        let t3 = |c: i64| {
            vec![
                BigInt::zero(),
                BigInt::zero(),
                BigInt::zero(),
                BigInt::from(c),
            ]
        };
        let m = vec![
            vec![t3(1), vec![BigInt::one()]],
            vec![t3(2), vec![BigInt::one()]],
        ];
        assert_eq!(degree_bound(&m), 3);
        assert_eq!(determinant(&m), IntPoly::from_i64(&[0, 0, 0, -1]));
        // Transposed, the rows are the tighter.
        let transposed = vec![
            vec![t3(1), t3(2)],
            vec![vec![BigInt::one()], vec![BigInt::one()]],
        ];
        assert_eq!(degree_bound(&transposed), 3);
        assert_eq!(determinant(&transposed), IntPoly::from_i64(&[0, 0, 0, -1]));
    }

    #[test]
    fn the_determinant_is_the_same_on_one_thread_and_on_several() {
        // The points' values are collected in their order whatever order they finish in.
        let on = |threads: usize, m: &[Vec<Poly>]| {
            (rayon::ThreadPoolBuilder::new().num_threads(threads).build())
                .unwrap()
                .install(|| determinant(m))
        };
        for m in random_matrices(20) {
            let one = on(1, &m);
            assert_eq!(one, on(4, &m), "{m:?}");
            assert_eq!(one, IntPoly::new(laplace(&m)), "{m:?}");
        }
    }
}
