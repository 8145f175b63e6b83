//! The linear problem: the space's unknowns, their images `{φ, H}` and the equations
//! `{F, H} = 0` numbered into rows, split into independent blocks.

use std::borrow::Cow;

use rayon::prelude::*;
use rustc_hash::FxHashMap;
use trigpoly::{
    Expr, GaussianRational, LimitKind, MonomialIndex, Rational, Term, Var, VarKind, Vars,
};

use crate::clearing::vanishes_at_values;
use crate::error::{EngineError, EngineLimit};
use crate::modular::{sum_by_index, Field, Fp, SparseVec};
use crate::system::System;

use super::independence::independent_as_functions;
use super::level_set::OnLevel;
use super::options::SearchSpace;
use super::parameters::fix_parameters;
use super::result::{NormalFormOutside, SpaceVariables};

/// How many images `{φ, H}` are formed at a time on the pool's threads before they are numbered
/// into equations: enough to share among threads, few enough to keep little in memory.
pub(super) const IMAGE_BLOCK: usize = 4096;

/// How an unknown depends on the angles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub(super) enum Trig {
    One,
    Cos,
    Sin,
}

/// One real basis function `φ · trig(k·θ)`.
#[derive(Clone, Debug)]
pub(super) struct Unknown {
    /// Exponents of the coordinates, momenta and Poisson variables and of the parameters kept
    /// symbolic (angles zero), over all variables.
    pub(super) phase: Vec<i64>,
    /// `k` over the angles, canonical (first nonzero entry positive), zero for `One`.
    pub(super) k: Vec<i64>,
    pub(super) trig: Trig,
    pub(super) momenta_degree: i64,
    pub(super) poisson_degree: i64,
    pub(super) positions_degree: i64,
    /// `Σ k_i` of its denominators `1/D_i^{k_i}`.
    pub(super) denominators_degree: i64,
    /// `Σ |j_i|` of its radicals `r_i^{j_i}`.
    pub(super) radicals_degree: i64,
    pub(super) trig_degree: i64,
    pub(super) parameters_degree: i64,
}

impl Unknown {
    /// Its degrees in the order of the unknowns, simpler first: momenta, Poisson variables,
    /// trigonometric order, radicals, positions, denominators, parameters. The radicals come
    /// before the positions so that where a power of a radical equals a polynomial
    /// (`x r² = x³ + xy² + xz²`), the polynomial's monomials are kept and the radical's left
    /// out, and integrals print with the fewest radicals.
    pub(super) fn degrees(&self) -> [i64; 7] {
        [
            self.momenta_degree,
            self.poisson_degree,
            self.trig_degree,
            self.radicals_degree,
            self.positions_degree,
            self.denominators_degree,
            self.parameters_degree,
        ]
    }
}

/// Where a monomial `φ·e^{ik·θ}` of the space sits among the unknowns.
#[derive(Clone, Copy, Debug)]
pub(super) enum Slot {
    /// `k = 0`: the unknown `φ`.
    One(usize),
    /// `k` canonical: the unknowns `φ cos k·θ` and `φ sin k·θ`.
    Canonical { cos: usize, sin: usize },
    /// `−k` for a canonical `k`: the same two unknowns, met from the conjugate side.
    Conjugate { cos: usize, sin: usize },
}

/// The search problem, with the parameters that are not kept symbolic at fixed values.
pub(super) struct Problem {
    pub(super) vars: Vars,
    /// The coordinates, momenta, Poisson variables and angles of the space.
    pub(super) variables: SpaceVariables,
    pub(super) unknowns: Vec<Unknown>,
    /// Where each monomial `φ·e^{ik·θ}` of the space sits among the unknowns.
    pub(super) slots: MonomialIndex<Slot>,
    /// The fixed Hamiltonian and condition.
    pub(super) h: Expr,
    pub(super) condition: Option<Vec<(Var, Expr)>>,
    /// The parameters at fixed values, with them.
    pub(super) parameters: Vec<(Var, Rational)>,
    /// `{φ, H} = Σ_v ∂φ/∂v · {v, H}`: for each phase variable `v` with `{v, H}` not zero after
    /// the condition, `v`, that part of `{v, H}` and whether it enters negated: `∂H/∂p` for a
    /// coordinate, `∂H/∂q` negated for a momentum, and the declared brackets' part
    /// `Σ_u {v, u} ∂H/∂u` for a variable they involve ([`crate::phase::Gradient`]), to form
    /// the images of the unknowns without differentiating `H` again each time.
    pub(super) flow_parts: Vec<(Var, Expr, bool)>,
    /// The level set the search is restricted to, if any: the images are their remainders on
    /// division by its polynomial, and the monomials its leading monomial divides are left
    /// out ([`Problem::restricted_to`]).
    pub(super) level: Option<OnLevel>,
}

/// Exponent vectors `≥ 0` (or any sign) over `n` slots with `Σ|e| ≤ max`.
pub(super) fn exponent_vectors(n: usize, max: u32, signed: bool) -> Vec<Vec<i64>> {
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

/// How many vectors [`exponent_vectors`] makes, without making them (a space of momenta degree
/// 1000 made 10⁸ of them before its count was refused), saturating at `u128::MAX`:
/// `C(n + max, n)`, and with signs `Σ_k 2^k C(n, k) C(max, k)` (`k` entries nonzero).
pub(super) fn exponent_vectors_count(n: usize, max: u32, signed: bool) -> u128 {
    let (n, max) = (n as u128, u128::from(max));
    if !signed {
        return binomial(n + max, n);
    }
    (0..=n.min(max)).fold(0, |sum: u128, k| {
        let ways = binomial(n, k).saturating_mul(binomial(max, k));
        let signs = 1u128.checked_shl(k as u32).unwrap_or(u128::MAX);
        sum.saturating_add(ways.saturating_mul(signs))
    })
}

/// `C(a, b)`, saturating at `u128::MAX`.
fn binomial(a: u128, b: u128) -> u128 {
    let b = b.min(a - b);
    // Each partial product `C(a − b + i, i)` is an integer.
    (1..=b)
        .try_fold(1u128, |acc, i| Some(acc.checked_mul(a - b + i)? / i))
        .unwrap_or(u128::MAX)
}

/// Refuses a space of `count` unknowns past the term limit of `vars`: a limit, the term
/// limit's ([`EngineLimit::Ring`] of [`LimitKind::Terms`]), said in the engine's terms: the
/// engine knows not who set the limit (a program's `Limits`, a file's `[limits]`, the command
/// line's flag), so the caller's hint names the setting that raises it.
fn too_many_unknowns(vars: &Vars, count: usize) -> Result<(), EngineError> {
    let limit = vars.limits().max_terms;
    if count > limit {
        return Err(EngineError::PastLimit {
            which: EngineLimit::Ring(LimitKind::Terms),
            limit,
            message: format!(
                "the space has {count} unknowns, more than the term limit {limit}: search a \
                 smaller space, or raise the limit"
            ),
        });
    }
    Ok(())
}

/// Whether the first nonzero entry is positive (or all are zero).
pub(super) fn canonical(k: impl IntoIterator<Item = i64>) -> bool {
    k.into_iter().find(|x| *x != 0).is_none_or(|x| x > 0)
}

/// The variables of the space: the coordinates and the angles, and the momenta and Poisson
/// variables but those that the condition fixes and the flow keeps, which are left out.
fn space_variables(system: &System, condition: Option<&[(Var, Expr)]>) -> SpaceVariables {
    let vars = system.vars();
    let pairs = system.space().pairs();
    let variables_of_kind = |kind: VarKind| -> Vec<Var> {
        pairs
            .iter()
            .filter(|p| vars.variable(p.q).kind() == kind)
            .map(|p| p.q)
            .collect()
    };
    // An angle's momentum that the condition fixes (`p_θ = mIω/n`) is a constant there:
    // every function of it is an integral, so it is left out, and so is the momentum of a
    // coordinate that `H` does not involve (the time's `p_t` in extended phase space, whose
    // `K = H + p_t` keeps it), and a Poisson variable
    // that the condition fixes (the flow keeps it, or the condition is refused). Any other
    // momentum counts. One set to a function of other phase variables (`M₃ = −(M₁γ₁ +
    // M₂γ₂)/γ₃`) is left out too, the others parametrising the surface, but is no constant.
    let value = |v: Var| {
        condition
            .into_iter()
            .flatten()
            .find_map(|(w, value)| (*w == v).then_some(value))
    };
    let fixed = |v: Var| value(v).is_some();
    let (mut momenta, mut left_out) = (Vec::new(), Vec::new());
    let hamiltonian = system.hamiltonian();
    for pair in pairs {
        let kept = vars.variable(pair.q).kind() == VarKind::Angle || !hamiltonian.contains(pair.q);
        if kept && fixed(pair.p) {
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
    let of_phase_space = |value: &Expr| {
        vars.vars()
            .any(|w| vars.variable(w).kind() != VarKind::Parameter && value.contains(w))
    };
    let left_out_as_functions = left_out
        .iter()
        .copied()
        .filter(|&v| value(v).is_some_and(of_phase_space))
        .collect();
    // A declared denominator the condition gives a value is that value in the space, which
    // its powers would only repeat.
    let valued_denominators = (vars.denominators()).filter(|&v| fixed(v)).collect();
    SpaceVariables {
        coordinates: variables_of_kind(VarKind::Coordinate),
        momenta,
        poisson,
        angles: variables_of_kind(VarKind::Angle),
        left_out,
        left_out_as_functions,
        valued_denominators,
    }
}

/// The exponent vectors that a space allows for each kind of variable, with the variables they
/// belong to: the pieces from which its unknowns are put together.
struct Exponents<'a> {
    vars: &'a Vars,
    variables: &'a SpaceVariables,
    /// The parameters kept symbolic.
    symbolic: &'a [Var],
    /// The denominator atoms `D_i`, with their polynomials.
    atoms: &'a [(Var, Expr)],
    /// The radicals `r_i`, with their radicands.
    radicals: &'a [(Var, Expr)],
    /// Over the coordinates: `Σ|a| ≤` the positions degree, of either sign in a Laurent space.
    positions: Vec<Vec<i64>>,
    momenta: Vec<Vec<i64>>,
    poisson: Vec<Vec<i64>>,
    parameters: Vec<Vec<i64>>,
    /// The powers `k_i` of the denominators `1/D_i^{k_i}`, which a monomial holds as the
    /// atoms' exponents `−k_i`.
    denominator_powers: Vec<Vec<i64>>,
    /// The powers `j_i` of the radicals, of either sign.
    radical_powers: Vec<Vec<i64>>,
    /// The angular vectors `k`, canonical.
    angular: Vec<Vec<i64>>,
    /// How many unknowns the space has, counted before the vectors were made and held to the
    /// term limit.
    count: usize,
}

impl<'a> Exponents<'a> {
    /// The exponent vectors of `space` over `variables` and the parameters kept `symbolic`;
    /// an error past the term limit, before any is formed.
    fn new(
        system: &'a System,
        space: &SearchSpace,
        variables: &'a SpaceVariables,
        symbolic: &'a [Var],
    ) -> Result<Self, EngineError> {
        let valued = &variables.valued_denominators;
        let phase = system.space();
        // The angular vectors are kept one of each ±k, each giving cos and sin (k = 0 one
        // function): as many functions as vectors of either sign.
        let count = [
            (
                variables.coordinates.len(),
                space.positions_degree,
                space.laurent,
            ),
            (variables.momenta.len(), space.momenta_degree, false),
            (variables.poisson.len(), space.poisson_degree, false),
            (symbolic.len(), space.parameters_degree, false),
            (
                phase.denominator_atoms().len() - valued.len(),
                space.denominators_degree,
                false,
            ),
            (phase.radicals().len(), space.radicals_degree, true),
            (variables.angles.len(), space.trig_degree, true),
        ]
        .into_iter()
        .fold(1u128, |product, (n, degree, signed)| {
            product.saturating_mul(exponent_vectors_count(n, degree, signed))
        });
        let count = usize::try_from(count).unwrap_or(usize::MAX);
        too_many_unknowns(system.vars(), count)?;
        let (atoms, radicals) = (
            system.space().denominator_atoms(),
            system.space().radicals(),
        );
        let vectors = |vars: &[Var], degree: u32| exponent_vectors(vars.len(), degree, false);
        Ok(Exponents {
            vars: system.vars(),
            variables,
            symbolic,
            atoms,
            radicals,
            positions: exponent_vectors(
                variables.coordinates.len(),
                space.positions_degree,
                space.laurent,
            ),
            momenta: vectors(&variables.momenta, space.momenta_degree),
            poisson: vectors(&variables.poisson, space.poisson_degree),
            parameters: vectors(symbolic, space.parameters_degree),
            denominator_powers: exponent_vectors(atoms.len(), space.denominators_degree, false)
                .into_iter()
                .filter(|k| (atoms.iter().zip(k)).all(|((a, _), k)| *k == 0 || !valued.contains(a)))
                .collect(),
            radical_powers: exponent_vectors(radicals.len(), space.radicals_degree, true),
            angular: exponent_vectors(variables.angles.len(), space.trig_degree, true)
                .into_iter()
                .filter(|k| canonical(k.iter().copied()))
                .collect(),
            count,
        })
    }

    /// How many trigonometric functions each monomial `φ` is multiplied by: each angular
    /// vector gives cos and sin, except k = 0.
    fn trig_functions(&self) -> usize {
        self.angular
            .iter()
            .map(|k| if k.iter().all(|x| *x == 0) { 1 } else { 2 })
            .sum()
    }

    /// The monomials `φ` without angles, one for each choice of an exponent vector of each
    /// kind.
    fn phases(&self) -> Vec<Unknown> {
        let variables = self.variables;
        let mut phases = Vec::with_capacity(self.count / self.trig_functions().max(1));
        let choices = itertools::iproduct!(
            &self.positions,
            &self.momenta,
            &self.poisson,
            &self.parameters,
            &self.denominator_powers,
            &self.radical_powers
        );
        for (positions, momenta, poisson, parameters, denominators, radicals) in choices {
            let mut phase = vec![0i64; self.vars.len()];
            for (v, e) in variables
                .coordinates
                .iter()
                .chain(&variables.momenta)
                .chain(&variables.poisson)
                .chain(self.symbolic)
                .zip(
                    positions
                        .iter()
                        .chain(momenta)
                        .chain(poisson)
                        .chain(parameters),
                )
            {
                phase[v.index()] = *e;
            }
            for ((v, _), e) in self.atoms.iter().zip(denominators) {
                phase[v.index()] = -e;
            }
            for ((v, _), e) in self.radicals.iter().zip(radicals) {
                phase[v.index()] = *e;
            }
            phases.push(Unknown {
                phase,
                k: vec![0; variables.angles.len()],
                trig: Trig::One,
                momenta_degree: momenta.iter().sum(),
                poisson_degree: poisson.iter().sum(),
                positions_degree: positions.iter().map(|x| x.abs()).sum(),
                denominators_degree: denominators.iter().sum(),
                radicals_degree: radicals.iter().map(|x| x.abs()).sum(),
                trig_degree: 0,
                parameters_degree: parameters.iter().sum(),
            });
        }
        phases
    }

    /// Each monomial `φ` of `phases` times each trigonometric function: the unknowns.
    fn unknowns(&self, phases: Vec<Unknown>) -> Vec<Unknown> {
        let mut unknowns = Vec::with_capacity(phases.len() * self.trig_functions());
        for phi in phases {
            for k in &self.angular {
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
        unknowns
    }
}

/// Sorts the unknowns simpler first. The order decides which basis comes out: each kernel
/// vector ends at its own unknown and uses only earlier ones, so simpler unknowns come first.
/// A total order (no two unknowns are equal), so the parallel sort is deterministic.
fn sort_simpler_first(unknowns: &mut [Unknown]) {
    unknowns.par_sort_unstable_by(|a, b| {
        a.degrees()
            .cmp(&b.degrees())
            .then_with(|| b.k.cmp(&a.k))
            .then_with(|| a.phase.cmp(&b.phase))
            .then_with(|| a.trig.cmp(&b.trig))
    });
}

impl Problem {
    /// The search of `space` for the integrals of `h` under the condition `cond`, with the
    /// parameters `symbolic` kept symbolic and the others at the values `parameters`.
    pub(super) fn new(
        system: &System,
        space: &SearchSpace,
        symbolic: &[Var],
        parameters: &[(Var, Rational)],
        h: Expr,
        cond: Option<Vec<(Var, Expr)>>,
    ) -> Result<Self, EngineError> {
        let vars = system.vars().clone();
        let variables = space_variables(system, cond.as_deref());
        let exponents = Exponents::new(system, space, &variables, symbolic)?;
        // The monomials `φ` without angles, then (with denominators) those whose functions are
        // independent of the simpler ones, then each times the trigonometric functions.
        let mut phases = exponents.phases();
        let (atoms, radicals) = (exponents.atoms, exponents.radicals);
        if !atoms.is_empty() || !radicals.is_empty() {
            phases = independent_as_functions(&vars, atoms, radicals, parameters, phases)?;
        }
        let mut unknowns = exponents.unknowns(phases);
        sort_simpler_first(&mut unknowns);
        let slots = Problem::slots(&vars, &variables.angles, &unknowns)?;
        let mut problem = Problem {
            vars,
            variables,
            unknowns,
            slots,
            h,
            condition: cond,
            parameters: parameters.to_vec(),
            flow_parts: Vec::new(),
            level: None,
        };
        problem.flow_parts = problem.nonzero_flow_parts(system)?;
        Ok(problem)
    }

    /// The parts of `{v, H}` after the condition and at the fixed values that are not zero,
    /// for [`Problem::flow_parts`]: `∂H/∂p` for each coordinate, `∂H/∂q` negated for each
    /// momentum, and the declared brackets' part for each variable they involve.
    fn nonzero_flow_parts(&self, system: &System) -> Result<Vec<(Var, Expr, bool)>, EngineError> {
        let gradient = system.space().gradient(&self.h)?;
        let canonical = system.space().pairs().iter().zip(gradient.canonical());
        let parts = canonical
            .flat_map(|(pair, (dq, dp))| [(pair.q, dp, false), (pair.p, dq, true)])
            .chain(gradient.declared().iter().map(|(v, x)| (*v, x, false)));
        let mut flow_parts = Vec::new();
        for (v, part, negated) in parts {
            // The declared brackets of an atom hold its polynomial's parameters.
            let part = self.apply_condition(fix_parameters(part, &self.parameters)?)?;
            if !part.is_zero() {
                flow_parts.push((v, part, negated));
            }
        }
        Ok(flow_parts)
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
    pub(super) fn image(&self, f: &Expr) -> Result<Expr, EngineError> {
        let products: Vec<(&Expr, Var, &Expr, bool)> = self
            .flow_parts
            .iter()
            .map(|(v, part, negated)| (f, *v, part, *negated))
            .collect();
        if products.is_empty() {
            return Ok(Expr::zero(&self.vars));
        }
        let image = Expr::sum_of_derivative_products(&products)?;
        match &self.level {
            Some(level) => level.remainder(&image),
            None => Ok(image),
        }
    }

    /// The problem on the level set `level`: the unknowns whose monomial its leading monomial
    /// divides left out (each is a combination of lower ones modulo its polynomial), and the
    /// images taken modulo the polynomial; with how many unknowns were left out, and the first
    /// of them whose normal form has a monomial the space has not ([`Problem::spans_term`]: a
    /// denominator of parameters alone, and an even power of a radical of them, is a number at
    /// the fixed values; an odd power is that radical), with that normal form (the
    /// space's degree bounds, separate for momenta and positions say, are not closed under the
    /// division, and an integral of the space whose normal form leaves it is not found).
    pub(super) fn restricted_to(
        mut self,
        level: OnLevel,
    ) -> Result<(Self, usize, Option<NormalFormOutside>), EngineError> {
        let left_out_functions: Vec<Expr> = (0..self.unknowns.len())
            .filter(|&j| level.leaves_out(&self.unknowns[j].phase))
            .map(|j| self.expr(j, &Rational::one()))
            .collect::<Result<_, _>>()?;
        self.unknowns.retain(|u| !level.leaves_out(&u.phase));
        self.slots = Problem::slots(&self.vars, &self.variables.angles, &self.unknowns)?;
        let mut outside = None;
        let numbers = self.numbers_at_fixed_values()?;
        for function in left_out_functions.iter() {
            let normal_form = level.remainder(function)?;
            if normal_form.terms().any(|t| !self.spans_term(&t, &numbers)) {
                outside = Some(NormalFormOutside {
                    function: function.clone(),
                    normal_form,
                });
                break;
            }
        }
        self.level = Some(level);
        Ok((self, left_out_functions.len(), outside))
    }

    /// The radicals and denominator atoms that are numbers at the fixed values (their radicand
    /// or denominator holds only parameters, all fixed: `r = √(κ + 3)` is 2 at `κ = 1`), each
    /// with whether it is a radical.
    fn numbers_at_fixed_values(&self) -> Result<Vec<(Var, bool)>, EngineError> {
        let mut numbers = Vec::new();
        for (is_radical, of) in [
            (true, Expr::radicals(&self.vars)?),
            (false, Expr::denominator_atoms(&self.vars)?),
        ] {
            for (v, e) in of {
                if fix_parameters(&e, &self.parameters)?.is_constant() {
                    numbers.push((v, is_radical));
                }
            }
        }
        Ok(numbers)
    }

    /// Whether the term, at the fixed values, is a multiple of a monomial of the space: its
    /// monomial is one, or is one once the factors that are `numbers` there are taken as
    /// coefficients (`1/r² = 1/(κ + 3)` times `1`; an odd power of a radical `r` keeps `r` or
    /// `1/r`, since `r^{2j+1} = (κ + 3)^j r`).
    fn spans_term(&self, t: &Term<'_, GaussianRational>, numbers: &[(Var, bool)]) -> bool {
        if self.slots.get_term(t).is_some() {
            return true;
        }
        let mut exps = t.exponents();
        let mut odd = Vec::new();
        for &(v, is_radical) in numbers {
            let e = &mut exps[v.index()];
            if is_radical && *e % 2 != 0 {
                odd.push(v.index());
            }
            *e = 0;
        }
        // Each odd power of a radical as `r` or as `1/r`.
        (0..1usize << odd.len()).any(|signs| {
            for (bit, &i) in odd.iter().enumerate() {
                exps[i] = if signs >> bit & 1 == 0 { 1 } else { -1 };
            }
            self.slots.get(&exps).is_some()
        })
    }

    /// The unknown as a function.
    pub(super) fn expr(&self, j: usize, coeff: &Rational) -> Result<Expr, EngineError> {
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
    pub(super) fn leading_exponents(&self, j: usize) -> Vec<i64> {
        let u = &self.unknowns[j];
        let mut e = u.phase.clone();
        for (v, k) in self.variables.angles.iter().zip(&u.k) {
            e[v.index()] += k;
        }
        e
    }

    /// `Σ v_j φ_j`.
    pub(super) fn combination(&self, v: &SparseVec<Rational>) -> Result<Expr, EngineError> {
        let mut terms = Vec::new();
        for (j, x) in v {
            let e = self.expr(*j, x)?;
            terms.extend(e.terms().map(|t| (t.coeff(), t.exponents())));
        }
        Ok(Expr::from_terms(&self.vars, terms)?)
    }

    pub(super) fn apply_condition(&self, e: Expr) -> Result<Expr, EngineError> {
        self.at_values().apply_condition(e)
    }

    /// `{f, H}` after the condition, at the fixed values ([`AtValues::flow`]).
    pub(super) fn flow(&self, system: &System, f: &Expr) -> Result<Expr, EngineError> {
        self.at_values().flow(system, f)
    }

    /// Whether `flow`, a function at the fixed values, is zero ([`AtValues::vanishes`]).
    pub(super) fn vanishes(&self, system: &System, flow: &Expr) -> Result<bool, EngineError> {
        self.at_values().vanishes(system, flow)
    }

    /// `f` as the space writes it: on a level set its normal form modulo the level set's
    /// polynomial (at the fixed values, as `f` is), else `f` itself.
    pub(super) fn normal_form<'f>(&self, f: &'f Expr) -> Result<Cow<'f, Expr>, EngineError> {
        match &self.level {
            Some(level) => Ok(Cow::Owned(level.remainder(f)?)),
            None => Ok(Cow::Borrowed(f)),
        }
    }

    /// Whether `f`, a function at the fixed values, is an integral where the search looks:
    /// its bracket with `H` zero after the condition, or on a level set a multiple of its
    /// polynomial (the remainder on division by it zero).
    pub(super) fn is_integral(&self, system: &System, f: &Expr) -> Result<bool, EngineError> {
        self.at_values().is_integral(system, f, self.level.as_ref())
    }

    /// The problem's fixed Hamiltonian, condition and values.
    fn at_values(&self) -> AtValues<'_> {
        AtValues {
            h: &self.h,
            condition: self.condition.as_deref(),
            parameters: &self.parameters,
        }
    }

    /// The integrals an integral `f` splits into: its `e^{ik·θ}` components `f_k e^{ik·θ}`,
    /// one per `k`, when `H` does not depend on the angles (the flow then keeps `k`, so each
    /// component is an integral); `f` itself when it does (the components of the energy of a
    /// pendulum, `p²/2` and `e^{±iψ}/2`, are none).
    pub(super) fn integral_components(&self, f: &Expr) -> Result<Vec<Expr>, EngineError> {
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
    pub(super) fn coordinates(&self, f: &Expr) -> Option<SparseVec<Rational>> {
        let (re, im) = self.coordinates_of_parts(f)?;
        im.is_empty().then_some(re)
    }

    /// The coordinates of the real and of the imaginary part of `f` in the basis, if they lie
    /// in the space (every monomial of `f` is one of the space's), in one pass over the terms
    /// of `f`.
    pub(super) fn coordinates_of_parts(
        &self,
        f: &Expr,
    ) -> Option<(SparseVec<Rational>, SparseVec<Rational>)> {
        let [re, im] = self.parts_by_slot(f, |t| {
            let c = t.coeff();
            (c.re, c.im)
        })?;
        Some((sum_by_index(re), sum_by_index(im)))
    }

    /// [`Problem::coordinates_of_parts`] modulo p, with the content of `f` applied to each
    /// coefficient of its primitive part (no rational product per term), as entries in any
    /// order with an index possibly twice (an [`Echelon`](crate::modular::Echelon) adds them up
    /// as they come): `None` when the content's denominator vanishes modulo p, `Some(None)`
    /// outside the space.
    pub(super) fn coordinates_of_parts_mod_p(
        &self,
        f: &Expr,
    ) -> Option<Option<[SparseVec<Fp>; 2]>> {
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

/// The rows of real equations by monomial: for each, the row of its real and of its
/// imaginary part, numbered as they first appear.
pub(super) type RowIndex = MonomialIndex<[Option<usize>; 2]>;

/// The real equations of an image `{φ, H}` (or, for the denominators, of a function), as a
/// column: a row for the real and for the imaginary part of each monomial with a canonical
/// `e^{ik·θ}` (`k ≥ 0`), numbered as they first appear in `rows`. Right for real functions,
/// whose other coefficients are the conjugates of these.
pub(super) fn real_rows(
    e: &Expr,
    angles: &[Var],
    rows: &mut RowIndex,
    nrows: &mut usize,
) -> SparseVec<Rational> {
    let numbered = real_entries(e, angles, |t, part| {
        let row = rows
            .get_or_insert_with_term(t, || [None, None])
            .expect("the rows have the function's variables");
        Some(*row[part].get_or_insert_with(|| {
            *nrows += 1;
            *nrows - 1
        }))
    });
    numbered.expect("every row is numbered")
}

/// The [`real_rows`] of each of `functions`, numbered in one index of rows: the rows, their
/// number and the columns.
pub(super) fn real_columns(
    functions: &[Expr],
    angles: &[Var],
    vars: &Vars,
) -> (RowIndex, usize, Vec<SparseVec<Rational>>) {
    let mut rows = MonomialIndex::new(vars);
    let mut nrows = 0;
    let columns = functions
        .iter()
        .map(|e| real_rows(e, angles, &mut rows, &mut nrows))
        .collect();
    (rows, nrows, columns)
}

/// The entries of [`real_rows`], each at the row `row(term, part)` finds for it (the real
/// part 0, the imaginary 1); `None` when it finds none.
pub(super) fn real_entries(
    e: &Expr,
    angles: &[Var],
    mut row: impl FnMut(&Term<'_, GaussianRational>, usize) -> Option<usize>,
) -> Option<SparseVec<Rational>> {
    let mut col = Vec::new();
    for t in e.terms() {
        if !canonical(angles.iter().map(|v| t.exponent(*v))) {
            continue;
        }
        let c = t.coeff();
        for (part, x) in [c.re, c.im].into_iter().enumerate() {
            if !x.is_zero() {
                col.push((row(&t, part)?, x));
            }
        }
    }
    // A search holds every column at once: no room to spare in them.
    col.shrink_to_fit();
    Some(col)
}

/// Appends `(j, x)` unless `x` is zero.
pub(super) fn push_nonzero<F: Field>(v: &mut SparseVec<F>, j: usize, x: F) {
    if !x.is_zero() {
        v.push((j, x));
    }
}

/// The columns' indices by block, those that share a row, transitively (connected
/// components): each block increasing, the blocks by their first index.
pub(super) fn blocks<T>(columns: &[Vec<(usize, T)>], nrows: usize) -> Vec<Vec<usize>> {
    let n = columns.len();
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
    groups
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

/// The Hamiltonian and the condition at the fixed values, with the values: what a bracket with
/// `H` is taken at, in the search ([`Problem`]) and before it, where the known integrals given
/// to it are checked, with no space of unknowns formed yet.
pub(super) struct AtValues<'a> {
    pub(super) h: &'a Expr,
    pub(super) condition: Option<&'a [(Var, Expr)]>,
    pub(super) parameters: &'a [(Var, Rational)],
}

impl AtValues<'_> {
    pub(super) fn apply_condition(&self, e: Expr) -> Result<Expr, EngineError> {
        match self.condition {
            Some(subs) => Ok(e.subst_many(subs)?),
            None => Ok(e),
        }
    }

    /// `{f, H}` after the condition, at the fixed values (also those that the atoms' brackets
    /// and the radicals' hold through their polynomials, `{(x − a), p_x}`).
    pub(super) fn flow(&self, system: &System, f: &Expr) -> Result<Expr, EngineError> {
        let flow = fix_parameters(&system.bracket(f, self.h)?, self.parameters)?;
        self.apply_condition(flow)
    }

    /// Whether `flow`, a function at the fixed values, is zero ([`vanishes_at_values`]).
    pub(super) fn vanishes(&self, system: &System, flow: &Expr) -> Result<bool, EngineError> {
        vanishes_at_values(system.space(), self.parameters, flow)
    }

    /// Whether `f`, a function at the fixed values, is an integral: its bracket with `H`
    /// ([`AtValues::flow`]) zero, or, on the level set `on`, a multiple of its polynomial
    /// (the remainder of its division by it zero, [`AtValues::vanishes`]; a level set takes
    /// no condition; a bracket with a negative power of a phase variable is not divided, and
    /// the function not taken).
    pub(super) fn is_integral(
        &self,
        system: &System,
        f: &Expr,
        on: Option<&OnLevel>,
    ) -> Result<bool, EngineError> {
        let flow = self.flow(system, f)?;
        match on {
            // A bracket with a negative power is not divided: such a function is not taken.
            Some(level) if level.negative_power(&flow).is_some() => Ok(false),
            // The remainder is at the fixed values: zero through their clearing.
            Some(level) => self.vanishes(system, &level.remainder(&flow)?),
            None => self.vanishes(system, &flow),
        }
    }
}
