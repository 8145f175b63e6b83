//! Parameters: checked, fixed to values for the linear algebra, or kept symbolic (their
//! multiples and the module they generate).

use trigpoly::{AlgebraError, Expr, GaussianRational, Rational, Var, VarKind, Vars};

use crate::claim::Condition;
use crate::clearing::Clearing;
use crate::error::EngineError;
use crate::modular::{self, sum_by_index, Echelon, SparseVec};
use crate::system::System;

use super::options::SearchOptions;
use super::problem::{real_columns, Problem};
use super::result::Integral;

/// Refuses values fixed for what is no parameter, and parameters to keep symbolic that are no
/// parameters or are also fixed to a value (a search's and a closure's `fixed`, `symbolic`).
pub(crate) fn check_parameters(
    vars: &Vars,
    symbolic: &[Var],
    fixed: &[(Var, Rational)],
) -> Result<(), EngineError> {
    // A handle of another set would name whatever variable stands at its index here.
    let mut given = fixed.iter().map(|f| f.0).chain(symbolic.iter().copied());
    if given.any(|v| !vars.owns(v)) {
        return Err(AlgebraError::VarSetMismatch.into());
    }
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

/// Every parameter of `h`, of a declared bracket, denominator or radical, or of the condition
/// that is neither kept symbolic nor set by the condition, with its value (given, or 1).
pub(super) fn parameter_values(
    system: &System,
    condition: Option<&Condition>,
    given: &[(Var, Rational)],
    symbolic: &[Var],
) -> Vec<(Var, Rational)> {
    let vars = system.vars();
    let mut exprs = vec![system.hamiltonian().clone()];
    // An atom's polynomial and a radicand enter the bracket through their declared brackets,
    // and a declared bracket's value through every bracket (`{M1, M2} = kM3` makes the
    // Casimir `M1² + M2² + kM3²`, an integral whose coefficients hold `k`).
    let space = system.space();
    exprs.extend(
        space
            .denominator_atoms()
            .iter()
            .chain(space.radicals())
            .map(|a| a.1.clone())
            .chain(space.declared_brackets().iter().map(|b| b.value.clone())),
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

/// Values of the parameters, in the order of their declaration, that the linear algebra takes
/// instead of 1 where 1 is a special point (a declared denominator zero there, for the search
/// and the closure, and the second search for a function written in others, superint's
/// `written_in_functions`): primes over 1, 2 and 3, so that no small
/// relation (equal values, one the sum of two others) holds among them. Parameters past the
/// list keep the value 1.
pub const GENERIC_VALUES: [(i64, i64); 12] = [
    (7, 1),
    (11, 2),
    (13, 3),
    (17, 1),
    (19, 2),
    (23, 3),
    (29, 1),
    (31, 2),
    (37, 3),
    (41, 1),
    (43, 2),
    (47, 3),
];

/// Moves the parameters that took the value 1 by default (those not in `given`) off a
/// declared denominator that 1 makes zero: `a − b` has no value at `a = b = 1`, where the
/// linear algebra would refuse it. Each such parameter of each of the `atoms` that is zero at
/// `values` takes its [`GENERIC_VALUES`] entry. Returns the first atom that was zero, for the
/// report; `None` when none was, or when none that was has a parameter to move (the clearing
/// then refuses it, naming the values).
pub(crate) fn off_vanishing_denominators<'a>(
    vars: &Vars,
    values: &mut [(Var, Rational)],
    given: &[(Var, Rational)],
    atoms: impl Iterator<Item = &'a (Var, Expr)>,
) -> Option<Var> {
    let vanishing: Vec<&(Var, Expr)> = atoms
        .filter(|(_, d)| fix_parameters(d, values).is_ok_and(|at| at.is_zero()))
        .collect();
    let mut moved = None;
    for (atom, d) in vanishing {
        for (v, value) in values.iter_mut() {
            if d.contains(*v) && !given.iter().any(|g| g.0 == *v) {
                let index = vars
                    .vars()
                    .filter(|&w| vars.variable(w).kind() == VarKind::Parameter)
                    .position(|p| p == *v);
                if let Some(&(n, m)) = index.and_then(|k| GENERIC_VALUES.get(k)) {
                    *value = Rational::new(n, m);
                    moved.get_or_insert(*atom);
                }
            }
        }
    }
    moved
}

/// The search's problem with the parameters at `parameters`, in `H` and in the condition.
#[cfg(test)]
pub(super) fn fixed_problem(
    system: &System,
    options: &SearchOptions,
    parameters: &[(Var, Rational)],
) -> Result<Problem, EngineError> {
    fixed_hamiltonian_and_condition(system, options, parameters)?
        .problem(system, options, parameters)
}

/// The Hamiltonian and the condition's substitution ([`Condition::substitution`], with the
/// values it gives the declared denominators) at the fixed `parameters`.
pub(super) fn fixed_hamiltonian_and_condition(
    system: &System,
    options: &SearchOptions,
    parameters: &[(Var, Rational)],
) -> Result<FixedHamiltonianAndCondition, EngineError> {
    let h = fix_parameters(system.hamiltonian(), parameters)?;
    let condition = match &options.condition {
        Some(c) => Some(
            c.substitution()
                .iter()
                .map(|(v, e)| Ok((*v, fix_parameters(e, parameters)?)))
                .collect::<Result<Vec<_>, EngineError>>()?,
        ),
        None => None,
    };
    Ok(FixedHamiltonianAndCondition { h, condition })
}

/// A Hamiltonian and a condition's substitutions, at fixed values.
pub(super) struct FixedHamiltonianAndCondition {
    /// The Hamiltonian.
    pub(super) h: Expr,
    /// The condition's substitutions, where there is a condition.
    pub(super) condition: Option<Vec<(Var, Expr)>>,
}

impl FixedHamiltonianAndCondition {
    /// The search's linear problem in the space of `options`, with this Hamiltonian and
    /// condition at the fixed `parameters`.
    pub(super) fn problem(
        self,
        system: &System,
        options: &SearchOptions,
        parameters: &[(Var, Rational)],
    ) -> Result<Problem, EngineError> {
        Problem::new(
            system,
            &options.space,
            &options.symbolic,
            parameters,
            self.h,
            self.condition,
        )
    }
}

/// Substitutes parameter values; refuses, naming it, a parameter given zero that `e` divides
/// by (`p_x/a` at `a = 0`), where `e` has no value.
pub fn fix_parameters(e: &Expr, values: &[(Var, Rational)]) -> Result<Expr, EngineError> {
    let vars = e.vars();
    let divided_by_zero = values
        .iter()
        .find(|(v, x)| x.is_zero() && e.low_degree(*v).unwrap_or(0) < 0);
    if let Some((v, _)) = divided_by_zero {
        let name = vars.variable(*v).unicode();
        return Err(EngineError::Invalid(format!(
            "{} divides by {name}, so it has no value at {name} = 0, the value the linear \
             algebra takes: give {name} another value (the options' `fix`; on the command \
             line, --fix)",
            e.brief_excerpt()
        )));
    }
    let subs: Vec<(Var, Expr)> = values
        .iter()
        .map(|(v, x)| (*v, Expr::constant(vars, GaussianRational::from(x.clone()))))
        .collect();
    Ok(e.subst_many(&subs)?)
}

/// The parameters that no denominator atom or radicand holds: the relations among the
/// monomials of a search's space do not hold them, so the degree in them is a grading of
/// its functions.
pub(super) fn free_parameters(
    vars: &Vars,
    atoms: &[(Var, Expr)],
    radicals: &[(Var, Expr)],
) -> Vec<Var> {
    vars.vars()
        .filter(|&v| {
            vars.variable(v).kind() == VarKind::Parameter
                && !atoms.iter().chain(radicals).any(|(_, d)| d.contains(v))
        })
        .collect()
}

/// The denominator atoms whose polynomial holds the `symbolic` parameters alone, such as
/// `a1 − a2`: a polynomial in the parameters, by which a multiple is a parameter multiple too
/// (`Q/(a1 − a2)` is one of `Q`, and `1/(a1 − a2)` a constant's).
pub(super) fn parameter_denominators<'a>(
    problem: &'a Problem,
    atoms: &'a [(Var, Expr)],
    symbolic: &'a [Var],
) -> impl Iterator<Item = Var> + 'a {
    atoms
        .iter()
        .filter(move |(_, d)| {
            problem
                .vars
                .vars()
                .all(|v| !d.contains(v) || symbolic.contains(&v))
        })
        .map(|(atom, _)| *atom)
}

/// A parameter multiple `a·X` of an integral `X` of the space that lies in the space.
pub(super) struct Multiple {
    /// The parameter `a`, or a denominator atom of parameters alone (`a1 − a2`).
    pub(super) by: Var,
    /// The coordinates of `X` among the unknowns.
    pub(super) of: SparseVec<Rational>,
    /// The coordinates of `a·X`.
    pub(super) multiple: SparseVec<Rational>,
}

/// The multiples `a·X` that lie in the space, for `a` a symbolic parameter and `X` an integral
/// of the space: for each `a`, a basis of the relations `a·Σ c_j I_j = Σ d_k I_k` among the
/// basis integrals `I_j` (with coordinates `kernel`), found as the kernel of their images
/// (through one [`Clearing`] with denominator atoms or radicals, whose functions are not
/// independent monomials). A combination may lie in the space where none of its terms does:
/// `a·(G + 2a²H)` is of degree 3 in the parameters while `a·G` and `a³H` are of degree 4.
/// Their span is every sum of parameter multiples of integrals in the space, since a product
/// by a monomial of higher degree is a product by one parameter of an integral that lies in
/// the space.
pub(super) fn parameter_multiples(
    system: &System,
    problem: &Problem,
    symbolic: &[Var],
    kernel: &[SparseVec<Rational>],
    basis: &[Integral],
) -> Result<Vec<Multiple>, EngineError> {
    let space = system.space();
    let n = basis.len();
    let mut out = Vec::new();
    for a in symbolic.iter().copied().chain(parameter_denominators(
        problem,
        space.denominator_atoms(),
        symbolic,
    )) {
        let a_times = Expr::var(&problem.vars, a);
        let mut functions = basis
            .iter()
            .map(|f| f.fixed.checked_mul(&a_times))
            .collect::<Result<Vec<Expr>, _>>()?;
        functions.extend(basis.iter().map(|f| f.fixed.clone()));
        let clearing = Clearing::new(
            space.denominator_atoms(),
            space.radicals(),
            &problem.parameters,
            functions.iter(),
        )?;
        if let Some(clearing) = clearing {
            functions = clearing.apply_all(&functions)?;
        }
        let (_, nrows, columns) =
            real_columns(&functions, &problem.variables.angles, &problem.vars);
        // `Σ c_j a·I_j + Σ d_k I_k = 0`: `X = Σ c_j I_j` and `a·X = −Σ d_k I_k`.
        for relation in modular::kernel(&columns, nrows) {
            let (mut of, mut multiple) = (Vec::new(), Vec::new());
            for (j, x) in &relation {
                match j.checked_sub(n) {
                    None => of.extend(kernel[*j].iter().map(|(i, y)| (*i, x * y))),
                    Some(k) => multiple.extend(kernel[k].iter().map(|(i, y)| (*i, -(x * y)))),
                }
            }
            out.push(Multiple {
                by: a,
                of: sum_by_index(of),
                multiple: sum_by_index(multiple),
            });
        }
    }
    Ok(out)
}

/// The basis integrals that generate the space over the rational functions of the symbolic
/// parameters ([`ParameterModule::generators`](super::ParameterModule::generators)): those
/// outside the span of the parameter `multiples` and of the earlier generators.
pub(super) fn module_generators(
    problem: &Problem,
    kernel: &[SparseVec<Rational>],
    multiples: &[Multiple],
) -> Vec<usize> {
    let mut span = Echelon::<Rational>::new(problem.unknowns.len());
    for (id, m) in multiples.iter().enumerate() {
        span.insert(id, &m.multiple);
    }
    (0..kernel.len())
        .filter(|&k| span.insert(multiples.len() + k, &kernel[k]).is_none())
        .collect()
}

/// A function times the least monomial in the `symbolic` parameters that leaves none of them
/// with a negative exponent (`G1 = p_x p_y/(2M) + …` becomes `M·G1`).
pub(super) fn without_parameter_denominators(
    f: &Expr,
    symbolic: &[Var],
) -> Result<Expr, EngineError> {
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
