//! The linear algebra a closure stands on (`Span`): the generators after the condition, their
//! monomials of degree `≤ D` expanded at fixed parameter values and written as columns, and
//! the targets (the brackets `{G_a, G_b}`, or any expression to be written in the generators)
//! as vectors over the same rows.

use std::collections::HashMap;
use std::time::Instant;

use trigpoly::{AlgebraError, Expr, Rational, Var, VarKind, Vars};

use super::columns::{Rows, TermTable};
use super::{check_monomial_count, monomials, ClosureOptions};
use crate::claim::Condition;
use crate::clearing::{refuse_division_by_zero, Clearing};
use crate::error::EngineError;
use crate::modular::SparseVec;
use crate::scaling::Scaling;
use crate::search::{check_parameters, fix_parameters, is_phase_free, off_vanishing_denominators};
use crate::system::{NamedFunction, System};

/// An expression after the condition, if there is one.
pub(super) fn restrict(condition: Option<&Condition>, e: Expr) -> Result<Expr, EngineError> {
    match condition {
        Some(c) => c.apply(&e),
        None => Ok(e),
    }
}

/// The generators after the condition, once their names are checked to differ and the
/// condition to be kept by the flow.
pub(super) fn restricted_generators(
    system: &System,
    generators: &[NamedFunction],
    condition: Option<&Condition>,
) -> Result<Vec<Expr>, EngineError> {
    let twice = (1..generators.len())
        .find(|&k| generators[..k].iter().any(|h| h.name == generators[k].name))
        .map(|k| &generators[k]);
    if let Some(g) = twice {
        return Err(EngineError::Invalid(format!(
            "{} is named twice among the generators",
            g.name
        )));
    }
    if let Some(g) = generators.iter().find(|g| g.expr.vars() != system.vars()) {
        return Err(EngineError::Invalid(format!(
            "the generator {} is not a function of the system's variables (it was read in \
             another variable set)",
            g.name
        )));
    }
    if let Some(c) = condition {
        c.kept_by_flow(system)?;
    }
    generators
        .iter()
        .map(|g| match condition {
            Some(c) => c.apply_where_defined(&g.expr, &format!("the generator {}", g.name)),
            None => Ok(g.expr.clone()),
        })
        .collect()
}

/// The generators' monomials as columns and the targets as vectors, at fixed parameters.
pub(super) struct Span {
    /// The generators after the condition, then one per symbolic parameter (the parameter
    /// itself).
    pub(super) g_sym: Vec<Expr>,
    /// Whether each of `g_sym` is constant on the condition's surface (`F2 = Iω²/2` at
    /// `p_θ = Iω`): it enters the polynomials as its value, a relation `G − c = 0` of its own.
    pub(super) constant: Vec<bool>,
    /// The fixed parameters and their values: those of the generators and targets, each as
    /// given or 1.
    pub(super) parameters: Vec<(Var, Rational)>,
    /// The declared denominator that is zero at the default values, 1, which moved the
    /// parameters in it ([`off_vanishing_denominators`]).
    pub(super) denominator_zero_at_one: Option<Var>,
    /// Whether some generator is complex at the fixed values, or some target is: then each
    /// monomial has a column of its own and one for `i` times it.
    pub(super) complex: bool,
    /// The exponent vectors `β` (generators, then symbolic parameters) of the monomials.
    pub(super) monos: Vec<Vec<u32>>,
    /// Column `j`: its monomial's index in `monos`, and whether it is `i` times it.
    pub(super) col_ids: Vec<(usize, bool)>,
    /// The columns.
    pub(super) columns: Vec<SparseVec<Rational>>,
    /// The targets at the fixed values, in their given order.
    pub(super) targets: Vec<SparseVec<Rational>>,
    /// How many rows (terms) the vectors have.
    pub(super) nrows: usize,
    /// When the monomials had been expanded (before the columns were written).
    pub(super) expanded: Instant,
}

impl Span {
    /// The span of the monomials of degree `≤ options.degree` in `g_sym` (the generators
    /// after the condition), and the `targets` (after the condition) over the same rows;
    /// `formed` are the generators and targets as formed on the whole phase space, before the
    /// condition, whose divisions are refused as theirs are. With `graded`, the weights under
    /// which every generator and target is homogeneous, only the monomials of a target's
    /// weight are taken (see [`TargetWeights`]).
    pub(super) fn new(
        system: &System,
        g_sym: Vec<Expr>,
        targets: &[Expr],
        formed: &[&Expr],
        options: &ClosureOptions,
        graded: Option<&Scaling>,
    ) -> Result<Span, EngineError> {
        let vars = system.vars();
        let r = g_sym.len();
        let symbolic = &options.symbolic;
        // Parameters kept symbolic enter as generators of their own, `p`, each of degree at
        // most `parameters_degree` in the monomials: a coefficient `c(p)` of `G^β` is the
        // combination of the monomials `p^ν G^β`.
        check_parameters(vars, symbolic, &options.fixed)?;
        let condition = options.condition.as_ref();
        // A parameter the condition sets has its value there: fixed to another for the linear
        // algebra, the report would name that one, as search refuses too.
        let set = |v: Var| condition.is_some_and(|c| c.subs().iter().any(|(w, _)| *w == v));
        if let Some(v) = (symbolic.iter().copied())
            .chain(options.fixed.iter().map(|f| f.0))
            .find(|&v| set(v))
        {
            return Err(EngineError::Invalid(format!(
                "{} is set by the condition; it can be neither fixed nor kept symbolic",
                vars.variable(v).name()
            )));
        }
        let g_sym: Vec<Expr> = g_sym
            .into_iter()
            .chain(symbolic.iter().map(|&v| Expr::var(vars, v)))
            .collect();
        let mut parameters = fixed_parameters(system, options, g_sym.iter().chain(targets));
        let space = system.space();
        // The condition's values enter the generators and the targets, and these are formed
        // before the condition, but a term of them that divides by an atom may leave none
        // once set on it (`c (a1 − a2) x` at `c = 1/(a1 − a2)` is `x`; `(x p_y − y p_x)²/(a1 −
        // a2)` at `y = 0, p_y = 0` is 0): the atoms they hold are used too, and refused where
        // they vanish, as a search refuses them, since a function that divides by zero has
        // no value there, on the condition's surface or off it.
        let unseen =
            (condition.into_iter().flat_map(Condition::values)).chain(formed.iter().copied());
        let used_atoms = space.denominator_atoms().iter().filter(|(atom, _)| {
            (g_sym.iter().chain(targets))
                .chain(unseen.clone())
                .any(|e| e.contains(*atom))
        });
        let denominator_zero_at_one =
            off_vanishing_denominators(vars, &mut parameters, &options.fixed, used_atoms);
        refuse_division_by_zero(space.denominator_atoms(), &parameters, unseen)?;
        let fix = |e: &Expr| fix_parameters(e, &parameters);
        let g: Vec<Expr> = g_sym.iter().map(fix).collect::<Result<_, _>>()?;
        // A complex target too: in real generators it needs complex coefficients (`i L`), and
        // its terms in `e^{−ikθ}` are no conjugates of others, to be left out.
        let complex = g.iter().chain(targets).any(|e| !e.is_real());

        let constant: Vec<bool> = (0..g_sym.len())
            .map(|a| a < r && is_phase_free(&g_sym[a]))
            .collect();
        let varying = constant[..r].iter().filter(|c| !**c).count();
        check_monomial_count(varying, symbolic.len(), options)?;
        let parameter_monomials = monomials(symbolic.len(), options.parameters_degree);
        let fixed: Vec<Var> = parameters.iter().map(|(v, _)| *v).collect();
        let target_weights = graded.and_then(|s| TargetWeights::new(s, &fixed, &g_sym, targets));
        let monos: Vec<Vec<u32>> = monomials(r, options.degree)
            .into_iter()
            .filter(|b| b.iter().zip(&constant).all(|(e, c)| *e == 0 || !c))
            .flat_map(|b| {
                parameter_monomials
                    .iter()
                    .map(move |nu| b.iter().chain(nu).copied().collect::<Vec<u32>>())
            })
            .filter(|m| target_weights.as_ref().is_none_or(|g| g.admits(m)))
            .collect();
        let values = expand_monomials(vars, &g, &monos, r, options.degree)?;
        let expanded = Instant::now();

        let fixed_targets: Vec<Expr> = targets.iter().map(fix).collect::<Result<_, _>>()?;
        let mut span = Span {
            g_sym,
            constant,
            parameters,
            denominator_zero_at_one,
            complex,
            monos,
            col_ids: Vec::new(),
            columns: Vec::new(),
            targets: Vec::new(),
            nrows: 0,
            expanded,
        };
        span.write_vectors(system, &values, &fixed_targets, symbolic)?;
        Ok(span)
    }

    /// Writes the columns, each monomial `p^ν G^β` from the value of `G^β` (in `values`,
    /// at the fixed parameters) shifted by `p^ν`, and the `targets` (at the fixed
    /// parameters) as vectors over the same rows.
    fn write_vectors(
        &mut self,
        system: &System,
        values: &HashMap<Vec<u32>, Expr>,
        targets: &[Expr],
        symbolic: &[Var],
    ) -> Result<(), EngineError> {
        // With denominator atoms, every vector is cleared first (none without).
        let space = system.space();
        let clearing = Clearing::new(
            space.denominator_atoms(),
            space.radicals(),
            &self.parameters,
            values.values().chain(targets),
        )?;
        // A real function's terms in `e^{−ikθ}` are the conjugates of those in `e^{ikθ}`, so
        // they are left out; its image under the clearing is real too when every atom's
        // polynomial is.
        let conjugates_follow = !self.complex && clearing.as_ref().is_none_or(|c| c.real);
        let angles: Vec<Var> = system.vars().angles().collect();
        let table = |e: &Expr| -> Result<TermTable, EngineError> {
            let image = clearing.as_ref().map(|c| c.apply(e)).transpose()?;
            Ok(TermTable::new(
                image.as_ref().unwrap_or(e),
                &angles,
                conjugates_follow,
            ))
        };
        // Each generators' monomial cleared once (the clearing commutes with a parameter's
        // monomial, which holds no atom), and its terms read once for all the parameters'
        // monomials that shift it.
        let images: HashMap<&[u32], TermTable> = values
            .iter()
            .map(|(beta, e)| Ok((beta.as_slice(), table(e)?)))
            .collect::<Result<_, EngineError>>()?;
        let r = self.g_sym.len() - symbolic.len();
        let mut rows = Rows::default();
        for (m, beta) in self.monos.iter().enumerate() {
            let terms = &images[generators_part(beta, r).as_slice()];
            let shift: Vec<(usize, i64)> = symbolic
                .iter()
                .zip(&beta[r..])
                .filter(|(_, &k)| k > 0)
                .map(|(v, &k)| (v.index(), i64::from(k)))
                .collect();
            for times_i in [false, true] {
                if times_i && !self.complex {
                    continue;
                }
                self.col_ids.push((m, times_i));
                self.columns.push(rows.vectorize(terms, times_i, &shift));
            }
        }
        self.targets = targets
            .iter()
            .map(|e| Ok(rows.vectorize(&table(e)?, false, &[])))
            .collect::<Result<_, EngineError>>()?;
        self.nrows = rows.len();
        Ok(())
    }
}

/// The weights that still grade the linear algebra once the fixed parameters have values
/// (those under which each fixed parameter weighs zero), and the weights of the targets under
/// them. An identity `target = Σ c_{ν,β} p^ν G^β` that holds for every value of the symbolic
/// parameters `p` has, part by part, one made of the monomials of the part's weight, so the
/// others need no column: with symbolic parameters, nearly all of them (`{K, Q}` of the caged
/// oscillator in 9 functions to degree 3 and `ω, α, β` to degree 4: 111 of 7 700 monomials).
struct TargetWeights {
    /// The weight of each of `g_sym` (generators, then symbolic parameters).
    generators: Vec<Vec<Rational>>,
    /// The weights of the targets (each homogeneous, a part of one), each once.
    targets: Vec<Vec<Rational>>,
}

impl TargetWeights {
    /// The grading of `g_sym` and `targets` (homogeneous parts) under `scaling` with the
    /// `fixed` parameters weighing zero, if every one of them is homogeneous under it and some
    /// weight is left.
    fn new(scaling: &Scaling, fixed: &[Var], g_sym: &[Expr], targets: &[Expr]) -> Option<Self> {
        let scaling = scaling.with_zero_weights(fixed);
        if scaling.dimension() == 0 {
            return None;
        }
        let generators = g_sym
            .iter()
            .map(|g| scaling.homogeneous_weight(g))
            .collect::<Option<Vec<_>>>()?;
        let mut weights: Vec<Vec<Rational>> = Vec::new();
        for t in targets {
            let w = scaling.homogeneous_weight(t)?;
            if !weights.contains(&w) {
                weights.push(w);
            }
        }
        Some(TargetWeights {
            generators,
            targets: weights,
        })
    }

    /// Whether the monomial with exponents `beta` (over `g_sym`) has a target's weight.
    fn admits(&self, beta: &[u32]) -> bool {
        let mut w = vec![Rational::zero(); self.generators.first().map_or(0, Vec::len)];
        for (g, &k) in self.generators.iter().zip(beta).filter(|(_, k)| **k > 0) {
            let k = Rational::from(i64::from(k));
            for (x, y) in w.iter_mut().zip(g) {
                *x += &(k.clone() * y);
            }
        }
        self.targets.contains(&w)
    }
}

/// Whether `e` has the parameter `v`, in its terms or through an atom's polynomial
/// (`1/(x − a)`) or a radicand (`√(x² + a)`) of `system`.
pub(super) fn mentions(system: &System, e: &Expr, v: Var) -> bool {
    let space = system.space();
    e.contains(v)
        || space
            .denominator_atoms()
            .iter()
            .chain(space.radicals())
            .any(|(w, d)| d.contains(v) && e.contains(*w))
}

/// The parameters fixed for the linear algebra: each that occurs in `exprs` or is given a
/// value, at that value or 1; the symbolic ones stay.
fn fixed_parameters<'a>(
    system: &System,
    options: &ClosureOptions,
    exprs: impl Iterator<Item = &'a Expr> + Clone,
) -> Vec<(Var, Rational)> {
    let vars = system.vars();
    let mut parameters = Vec::new();
    for v in vars.vars() {
        if vars.variable(v).kind() != VarKind::Parameter || options.symbolic.contains(&v) {
            continue;
        }
        let given = options.fixed.iter().find(|f| f.0 == v).map(|f| f.1.clone());
        if given.is_some() || exprs.clone().any(|e| mentions(system, e, v)) {
            parameters.push((v, given.unwrap_or_else(Rational::one)));
        }
    }
    parameters
}

/// The generators' part of a monomial `p^ν G^β`: `β` with the symbolic parameters' exponents
/// set to zero. Only that part is expanded: a monomial of the symbolic parameters multiplies
/// it as a shift of its exponents, so the 84 monomials of degree ≤ 6 in three parameters cost
/// no product, and no copy, of their own.
fn generators_part(beta: &[u32], r: usize) -> Vec<u32> {
    let mut g = beta.to_vec();
    g[r..].fill(0);
    g
}

/// The generators' parts of `monos` expanded at the fixed values `g`, each from one of lower
/// degree times a generator (expanded too when `monos` lacks it), and the constant monomial.
///
/// The expansions are held at once (and then read into the columns), so together they are
/// held to the term limit, as one result is: each product is counted as it is formed, and
/// once their terms together pass `Limits::max_terms` the expansion stops with
/// [`EngineError::ClosureTooManyTerms`] at the closure's `degree` (as it does when one product
/// passes it alone), which says that all of them were counted. What is held is then at most
/// the limit and one product, which the limit bounds too; without the count, a product of the
/// generators of a degree reached the limit only after all those of lower degree were held
/// (`p_x`, `F1` of the rotor under gravity at degree 64: 1.3·10⁸ terms, 6.2 GB, before `F1^45`
/// passed it).
fn expand_monomials(
    vars: &Vars,
    g: &[Expr],
    monos: &[Vec<u32>],
    r: usize,
    degree: u32,
) -> Result<HashMap<Vec<u32>, Expr>, EngineError> {
    let limit = vars.limits().max_terms;
    let too_many = EngineError::ClosureTooManyTerms { degree, limit };
    let mut values: HashMap<Vec<u32>, Expr> = HashMap::new();
    values.insert(vec![0; g.len()], Expr::one(vars));
    let mut held: usize = 1;
    let mut by_degree: Vec<Vec<u32>> = monos.iter().map(|b| generators_part(b, r)).collect();
    by_degree.sort_by_key(|b| b.iter().sum::<u32>());
    by_degree.dedup();
    for beta in &by_degree {
        // The monomials below `beta`, down to one already expanded: a grading may have left
        // them out of `monos`.
        let mut chain = vec![beta.clone()];
        while !values.contains_key(chain.last().expect("one")) {
            let mut lower = chain.last().expect("one").clone();
            let a = lower.iter().position(|e| *e > 0).expect("nonconstant");
            lower[a] -= 1;
            chain.push(lower);
        }
        for pair in chain.windows(2).rev() {
            let (upper, lower) = (&pair[0], &pair[1]);
            let a = upper
                .iter()
                .zip(lower)
                .position(|(u, l)| u != l)
                .expect("one step");
            let v = values[lower].checked_mul(&g[a]).map_err(|e| match e {
                AlgebraError::TooManyTerms { .. } => too_many.clone(),
                e => e.into(),
            })?;
            held = held.saturating_add(v.len());
            if held > limit {
                return Err(too_many);
            }
            values.insert(upper.clone(), v);
        }
    }
    Ok(values)
}
