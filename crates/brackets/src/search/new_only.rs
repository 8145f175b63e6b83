//! Which integrals are new (`SearchOptions::new_only`): the basis modulo the span of products
//! of known and lower integrals, graded by size.

use trigpoly::{Expr, GaussianRational, Rational, Style, Term, Var, VarKind, Vars};

use crate::claim::Condition;
use crate::clearing::refuse_division_by_zero;
use crate::error::{EngineError, EngineLimit};
use crate::modular::{self, sum_by_index, CombinationSums, Echelon, Field, Fp, SparseVec};
use crate::system::System;

use super::level_set::OnLevel;
use super::locate::{ClearedBasis, Locator};
use super::options::{SearchOptions, SearchSpace};
use super::parameters::{
    fix_parameters, free_parameters, parameter_denominators, without_parameter_denominators,
    Multiple,
};
use super::problem::{AtValues, Problem, Slot};
use super::proof::{is_phase_free, lead};
use super::result::{parameter_text, Integral, NewIntegrals, SpaceVariables};

/// Which integrals of `basis` (with coordinates `kernel`) are new: those that no known
/// integral, constant, product of integrals of lower grade or parameter multiple (`multiples`)
/// generates, decided modulo p unless `options.exact_complement`, and over Q where that fails.
pub(super) fn new_integrals(
    system: &System,
    problem: &Problem,
    options: &SearchOptions,
    parameters: &[(Var, Rational)],
    kernel: &[SparseVec<Rational>],
    basis: &[Integral],
    multiples: &[Multiple],
) -> Result<NewIntegrals, EngineError> {
    let space = &options.space;
    let related = has_related_monomials(system);
    let locator = locator(system, problem, parameters, kernel)?;
    // Known integrals: named real functions that are integrals, restricted to the condition.
    let KnownIntegrals {
        names: known_names,
        integrals: known,
    } = known_integrals(system, problem, options, parameters, &locator)?;
    // The filtration by grade ([`Grading`]): an integral of grade g is generated when it lies
    // in the span of the known integrals, the constants, the products of at least two
    // integrals of grade < g (known or found) and the parameter multiples of integrals of
    // grade ≤ g.
    let grading = Grading::new(&problem.variables, space.trig_degree).with_stand_ins(&problem.vars);
    let gens = known_and_basis_generators(system, problem, &grading, &known, basis)?;
    let grades: Vec<i64> = basis.iter().map(|b| grading.grade(&b.fixed)).collect();
    let of_parameters: Vec<Var> = parameter_denominators(
        problem,
        system.space().denominator_atoms(),
        &options.symbolic,
    )
    .collect();
    let denominator_degrees: Vec<i64> = basis
        .iter()
        .map(|b| denominator_degree(&b.fixed, &of_parameters))
        .collect();
    let complement = Complement {
        locator: &locator,
        problem,
        kernel,
        known: &known,
        multiples,
        multiple_grades: multiple_grades(problem, &grading, multiples)?,
        gens,
        bounds: Size::bounds(space),
        // With atoms or radicals the degrees in the coordinates, the denominators and the
        // radicals bound only how many factors a product has, as in a Laurent space:
        // `x/(x − y) · y/(x − y)` may equal a function of the space written in fewer of them.
        laurent: space.laurent || related,
        leads: Leads::of(kernel, problem.unknowns.len()),
        order: by_grade(&grades),
        divided_order: by_grade_and_denominators(&grades, &denominator_degrees),
        grades,
        max_products: options.max_products,
    };
    let (new, products) = complement.new_and_products(options.exact_complement)?;
    let multipliers = new
        .iter()
        .map(|&k| least_denominator_multiplier(problem, &locator, &basis[k].fixed, &of_parameters))
        .collect::<Result<Vec<_>, EngineError>>()?;
    Ok(NewIntegrals {
        known: known_names,
        known_integrals: known.iter().map(|(f, _)| f.clone()).collect(),
        generated: basis.len() - new.len(),
        new,
        multipliers,
        products,
        past_degree_undecided: past_degree_undecided(problem, &complement.gens)?,
    })
}

/// On a level set, whether a product of `gens` past the space's total degree might have its
/// normal form in the space: some generator's leading form is not shown to share no factor
/// with that of `P` ([`OnLevel::top_shares_no_factor`]). Where each shares none, a product's
/// leading form is no multiple of `P`'s, so its normal form keeps its total degree.
fn past_degree_undecided(problem: &Problem, gens: &[Generator]) -> Result<bool, EngineError> {
    let Some(level) = &problem.level else {
        return Ok(false);
    };
    for g in gens {
        if !level.top_shares_no_factor(&g.expr)? {
            return Ok(true);
        }
    }
    Ok(false)
}

/// Whether the space's monomials are related as functions: with denominator atoms or
/// radicals a function of the space may be written in other monomials than the unknowns' (and
/// a product's powers of `1/D` add up, `r · r = R`).
fn has_related_monomials(system: &System) -> bool {
    !system.space().denominator_atoms().is_empty() || !system.space().radicals().is_empty()
}

/// How functions are located in the space: by their monomials, or, where the monomials are
/// related ([`has_related_monomials`]), through the cleared images of the basis integrals.
fn locator<'a>(
    system: &System,
    problem: &'a Problem,
    parameters: &[(Var, Rational)],
    kernel: &[SparseVec<Rational>],
) -> Result<Locator<'a>, EngineError> {
    let (atoms, radicals) = (
        system.space().denominator_atoms(),
        system.space().radicals(),
    );
    Ok(match has_related_monomials(system) {
        false => Locator::Monomials(problem),
        true => Locator::Cleared(Box::new(ClearedBasis::new(
            problem, atoms, radicals, parameters, kernel,
        )?)),
    })
}

/// The generators of the known integrals and of the basis integrals, but those that are
/// multiples of others by the parameters that nothing holds ([`without_parameter_multiples`]).
fn known_and_basis_generators(
    system: &System,
    problem: &Problem,
    grading: &Grading,
    known: &[(Expr, SparseVec<Rational>)],
    basis: &[Integral],
) -> Result<Vec<Generator>, EngineError> {
    let sources = known
        .iter()
        .map(|k| &k.0)
        .chain(basis.iter().map(|b| &b.fixed));
    let related = has_related_monomials(system);
    let constant = |c: &Expr| match related {
        true => is_constant(system, problem, c),
        false => Ok(false),
    };
    let gens = generators(problem, grading, sources, &constant)?;
    let (atoms, radicals) = (
        system.space().denominator_atoms(),
        system.space().radicals(),
    );
    Ok(without_parameter_multiples(
        gens,
        &free_parameters(&problem.vars, atoms, radicals),
    ))
}

/// The grade from which each parameter multiple `a·X` is generated: `a·X` is generated by
/// `X`, from `X`'s grade, or its own where that is lower: with a parameter in a radicand or a
/// denominator, the space writes `a·X` in other monomials (`a³/s = a s − a(x² + y² + z²)/s −
/// 2a²x/s` for `s = √((x + a)² + y² + z²)`).
fn multiple_grades(
    problem: &Problem,
    grading: &Grading,
    multiples: &[Multiple],
) -> Result<Vec<i64>, EngineError> {
    multiples
        .iter()
        .map(|m| {
            let grade =
                |v| -> Result<i64, EngineError> { Ok(grading.grade(&problem.combination(v)?)) };
            Ok(grade(&m.of)?.min(grade(&m.multiple)?))
        })
        .collect()
}

/// The indices of the basis integrals by increasing grade (`grades`), in their order within
/// a grade.
fn by_grade(grades: &[i64]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..grades.len()).collect();
    order.sort_by_key(|&k| (grades[k], k));
    order
}

/// The indices of the basis integrals by increasing grade, then by increasing degree in the
/// denominators of parameters (`denominator_degrees`), then in their order: of the forms
/// `Q/(a1 − a2)²`, `Q/(a1 − a2)`, `Q` of one integral, `Q` is judged first.
fn by_grade_and_denominators(grades: &[i64], denominator_degrees: &[i64]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..grades.len()).collect();
    order.sort_by_key(|&k| (grades[k], denominator_degrees[k], k));
    order
}

/// The largest degree of a term of `f` in the denominator `atoms` (`1/((a1 − a2)² (a1 − a3))`
/// has degree 3 in them).
fn denominator_degree(f: &Expr, atoms: &[Var]) -> i64 {
    f.terms()
        .map(|t| atoms.iter().map(|&v| (-t.exponent(v)).max(0)).sum())
        .max()
        .unwrap_or(0)
}

/// The product `u` of declared denominators of parameters (`atoms`), as exponents by atom, that
/// gives `u·X` the least degree in them, for an integral `X` of the space: one atom at a time,
/// while `u·X` lies in the space and its degree in them drops (`(a1 − a2)²` for `X = Q/(a1 −
/// a2)²`). Each atom is a polynomial in the parameters, nonzero, so `u·X` and `X` generate
/// each other where the parameters and these denominators may be divided by. Empty where no
/// atom lowers it.
fn least_denominator_multiplier(
    problem: &Problem,
    locator: &Locator<'_>,
    x: &Expr,
    atoms: &[Var],
) -> Result<Vec<(Var, i64)>, EngineError> {
    let mut multiplier: Vec<(Var, i64)> = Vec::new();
    let (mut current, mut degree) = (x.clone(), denominator_degree(x, atoms));
    'lower: while degree > 0 {
        for &atom in atoms {
            let times = current.checked_mul(&Expr::var(&problem.vars, atom))?;
            let Some(v) = locator.coordinates(&times)? else {
                continue;
            };
            let times = problem.combination(&v)?;
            let lower = denominator_degree(&times, atoms);
            if lower < degree {
                (current, degree) = (times, lower);
                match multiplier.iter_mut().find(|m| m.0 == atom) {
                    Some(m) => m.1 += 1,
                    None => multiplier.push((atom, 1)),
                }
                continue 'lower;
            }
        }
        break;
    }
    Ok(multiplier)
}

/// What decides which basis integrals are new: the basis, graded, and what the span of the
/// generated integrals is formed from.
struct Complement<'a> {
    locator: &'a Locator<'a>,
    problem: &'a Problem,
    /// The basis integrals' coordinates among the unknowns.
    kernel: &'a [SparseVec<Rational>],
    /// The known integrals, in the unknowns' monomials and by their coordinates.
    known: &'a [(Expr, SparseVec<Rational>)],
    /// The parameter multiples `a·X` that lie in the space, and the grade from which each is
    /// generated.
    multiples: &'a [Multiple],
    multiple_grades: Vec<i64>,
    /// The generators whose products join the span.
    gens: Vec<Generator>,
    /// The most that a product may take of the space.
    bounds: Size,
    /// Whether the coordinates' degree leaves a product's size unbounded.
    laurent: bool,
    /// The leads of the kernel, the coordinates on which the span is formed modulo p.
    leads: Leads,
    /// Each basis integral's grade, and the basis integrals by increasing grade.
    grades: Vec<i64>,
    order: Vec<usize>,
    /// The basis integrals by increasing grade and, within a grade, by increasing degree in
    /// the denominators of parameters: the order in which [`Complement::decide_divided`]
    /// judges them, so that the form with the least denominator is the one found new.
    divided_order: Vec<usize>,
    /// The most products to form.
    max_products: usize,
}

impl Complement<'_> {
    /// The new integrals and how many products were formed: modulo p first (unless
    /// `exact_complement` asks for Q alone); over Q when a denominator vanishes modulo p or a
    /// dependency found modulo p does not hold over Q.
    ///
    /// With parameters kept symbolic, when some are new this way, all are decided again with
    /// the parameters divided by ([`Complement::divided_new_and_products`]).
    fn new_and_products(&self, exact_complement: bool) -> Result<(Vec<usize>, usize), EngineError> {
        let modular = match exact_complement {
            false => self.span(false, true)?,
            true => None,
        };
        let (new, n) = match modular.and_then(|(span, n)| Some((self.decide(false, &span)?, n))) {
            Some(found) => found,
            None => {
                let (span, n) = self
                    .span(true, true)?
                    .expect("the span over Q always forms");
                (
                    self.decide(true, &span)
                        .expect("exact elimination always decides"),
                    n,
                )
            }
        };
        match new.is_empty() || self.multiples.is_empty() {
            true => Ok((new, n)),
            false => self.divided_new_and_products(exact_complement),
        }
    }

    /// With parameters kept symbolic, the new integrals when an integral `F` also counts as
    /// generated where `a·F` is, for a parameter `a` (so `μ·F` for a monomial `μ`: `K/ω²`
    /// is not new where `K` is generated): the span of the known integrals, the constants and
    /// the products (modulo p unless `exact_complement`, without the parameter multiples),
    /// then [`Complement::decide_divided`], exact. How many products were formed.
    fn divided_new_and_products(
        &self,
        exact_complement: bool,
    ) -> Result<(Vec<usize>, usize), EngineError> {
        let modular = match exact_complement {
            false => self.span(false, false)?,
            true => None,
        };
        let (span, n) = match modular {
            Some(found) => found,
            None => self
                .span(true, false)?
                .expect("the span over Q always forms"),
        };
        Ok((self.decide_divided(&span), n))
    }

    /// The span of what is generated, modulo p or over Q (`exact`), by stamp, and how many
    /// products were formed; `None` when a denominator vanishes modulo p. The parameter
    /// multiples join it when `with_multiples`.
    fn span(
        &self,
        exact: bool,
        with_multiples: bool,
    ) -> Result<Option<(StampedVectors, usize)>, EngineError> {
        let span = Stamped::new(&self.leads, exact);
        let limits = (self.kernel.len(), self.max_products);
        span_of_products(
            self.locator,
            &self.gens,
            self.vectors(with_multiples),
            self.bounds,
            self.laurent,
            span,
            limits,
        )
    }

    /// The vectors that join the span besides the products: the known integrals and the
    /// constants; with parameters kept symbolic and `with_multiples`, `a·I` is generated by
    /// `I`: it joins the span before the basis integrals of `I`'s grade.
    fn vectors(&self, with_multiples: bool) -> StampedVectors {
        let problem = self.problem;
        let mut vectors: StampedVectors = self.known.iter().map(|k| (-1, k.1.clone())).collect();
        if let Some(&Slot::One(j)) = problem.slots.get(&vec![0; problem.vars.len()]) {
            vectors.push((-1, vec![(j, Rational::one())]));
        }
        if with_multiples {
            vectors.extend(self.stamped_multiples());
        }
        vectors
    }

    /// Each parameter multiple `a·X` with the stamp below the grade from which it is
    /// generated.
    fn stamped_multiples(&self) -> impl Iterator<Item = (i64, SparseVec<Rational>)> + '_ {
        self.multiple_grades
            .iter()
            .zip(self.multiples)
            .map(|(g, m)| (g - 1, m.multiple.clone()))
    }

    /// The basis integrals that are new when parameters may be divided by, by increasing
    /// grade g (within it, by increasing degree in the denominators of parameters), over Q:
    /// the `generated` vectors (known integrals, constants, products) of stamps below g and
    /// each new integral as soon as it is found join a [`Divided`] span, which holds `X`
    /// wherever it holds `a·X` and holds `a·X` wherever it holds `X` (`a·X` in the space); the
    /// basis integral of grade g is new unless it lies in the span of that and of the
    /// parameter multiples of integrals of grade `≤ g`. So no new integral is a quotient of
    /// another of its grade (`Q/((a1 − a2)(a1 − a3))` of `Q/(a1 − a2)²`, whose multiples by
    /// `a1 − a3` and `a1 − a2` are one).
    fn decide_divided(&self, generated: &[(i64, SparseVec<Rational>)]) -> Vec<usize> {
        let rows = self.problem.unknowns.len();
        let mut divided = Divided::new(self.multiples, rows);
        let mut multiples: Vec<(i64, SparseVec<Rational>)> = self.stamped_multiples().collect();
        multiples.sort_by_key(|m| m.0);
        let mut q = Echelon::<Rational>::new(rows);
        let (mut ids, mut next_generated, mut next_multiple, mut joined) = (0, 0, 0, 0);
        let mut new: Vec<usize> = Vec::new();
        let mut grade = None;
        for &k in &self.divided_order {
            let g = self.grades[k];
            if grade != Some(g) {
                grade = Some(g);
                // The generated vectors below g, with what dividing and multiplying by the
                // parameters gives of them (the new integrals joined when they were found).
                while next_generated < generated.len() && generated[next_generated].0 < g {
                    divided.add(generated[next_generated].1.clone());
                    next_generated += 1;
                }
                divided.close();
                for v in &divided.vectors[joined..] {
                    q.extend(ids, v);
                    ids += 1;
                }
                joined = divided.vectors.len();
                while next_multiple < multiples.len() && multiples[next_multiple].0 < g {
                    q.extend(ids, &multiples[next_multiple].1);
                    ids += 1;
                    next_multiple += 1;
                }
            }
            let found_new = q.insert(ids, &self.kernel[k]).is_none();
            ids += 1;
            if found_new {
                // What it generates over the parameters and their denominators joins the span
                // before the next integral of its grade is judged: once `Q` is new,
                // `Q/(a1 − a2)` is not.
                new.push(k);
                divided.add(self.kernel[k].clone());
                divided.close();
                for v in &divided.vectors[joined..] {
                    q.extend(ids, v);
                    ids += 1;
                }
                joined = divided.vectors.len();
            }
        }
        new.sort_unstable();
        new
    }

    /// The basis integrals that are new, by increasing grade g: the span's vectors of stamps
    /// below g join the elimination, then each basis integral of grade g is new unless it lies
    /// in the span (of those and of the new ones so far). Modulo p unless `exact`; `None` when
    /// a denominator vanishes modulo p or a dependency found there does not hold over Q.
    fn decide(&self, exact: bool, spanning: &[(i64, SparseVec<Rational>)]) -> Option<Vec<usize>> {
        let leads = &self.leads;
        let mut fp = Echelon::<Fp>::new(leads.count);
        let rows = self.problem.unknowns.len();
        let mut q = Echelon::<Rational>::new(rows);
        // Vectors by identifier, for checking dependencies exactly.
        let mut inserted: Vec<&SparseVec<Rational>> = Vec::new();
        let mut sums = CombinationSums::new();
        let mut next_span = 0;
        let mut new = Vec::new();
        for &k in &self.order {
            while next_span < spanning.len() && spanning[next_span].0 < self.grades[k] {
                let v = &spanning[next_span].1;
                if exact {
                    q.extend(inserted.len(), v);
                } else {
                    fp.extend(inserted.len(), &leads.restrict(modular::to_fp(v)?));
                }
                inserted.push(v);
                next_span += 1;
            }
            let v = &self.kernel[k];
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
                Some(dependency) => {
                    if !dependency_holds(&mut sums, &dependency, &inserted, v)? {
                        return None;
                    }
                }
            }
        }
        new.sort_unstable();
        Some(new)
    }
}

/// A span of integrals of the space, over Q, closed under dividing by the parameters kept
/// symbolic and multiplying by them within the space: it holds `X` wherever it holds `a·X`,
/// and `a·X` wherever it holds `X` and `a·X` lies in the space. Each step is exact linear
/// algebra on the pairs `(X, a·X)` of the parameter multiples ([`Multiple`]), which span
/// every such pair for their parameter `a`.
struct Divided<'a> {
    /// For each parameter, the pairs that span its multiplication within the space.
    pairs: Vec<Pairs<'a>>,
    rows: usize,
    span: Echelon<Rational>,
    /// A basis of the span, in the order its vectors joined.
    vectors: Vec<SparseVec<Rational>>,
    /// For each parameter's pairs, dividing and multiplying, how many vectors the span had
    /// when that kernel was last taken: the same kernel again brings in nothing new.
    taken_at: Vec<[Option<usize>; 2]>,
}

/// The pairs `X`, `a·X` of the parameter multiples by one parameter `a`, side by side.
struct Pairs<'a> {
    by: Var,
    of: Vec<&'a SparseVec<Rational>>,
    multiple: Vec<&'a SparseVec<Rational>>,
}

impl<'a> Divided<'a> {
    fn new(multiples: &'a [Multiple], rows: usize) -> Self {
        let mut pairs: Vec<Pairs> = Vec::new();
        for m in multiples {
            match pairs.iter_mut().find(|p| p.by == m.by) {
                Some(p) => {
                    p.of.push(&m.of);
                    p.multiple.push(&m.multiple);
                }
                None => pairs.push(Pairs {
                    by: m.by,
                    of: vec![&m.of],
                    multiple: vec![&m.multiple],
                }),
            }
        }
        Divided {
            taken_at: vec![[None; 2]; pairs.len()],
            pairs,
            rows,
            span: Echelon::new(rows),
            vectors: Vec::new(),
        }
    }

    /// Adds `v`; whether it was independent of the span.
    fn add(&mut self, v: SparseVec<Rational>) -> bool {
        let independent = !v.is_empty() && self.span.extend(self.vectors.len(), &v);
        if independent {
            self.vectors.push(v);
        }
        independent
    }

    /// Adds, until none is new, each `X` whose multiple `a·X` the span holds and each `a·X`
    /// (in the space) of an `X` it holds: a combination `Σ λ_m from_m` of one side of the
    /// pairs that lies in the span (a kernel vector of those and the span's basis, exact)
    /// brings in `Σ λ_m to_m` of the other. A kernel is taken again only once the span has
    /// grown.
    fn close(&mut self) {
        loop {
            let mut grew = false;
            for p in 0..self.pairs.len() {
                for (side, divide) in [true, false].into_iter().enumerate() {
                    if self.taken_at[p][side] == Some(self.vectors.len()) {
                        continue;
                    }
                    self.taken_at[p][side] = Some(self.vectors.len());
                    let Pairs { of, multiple, .. } = &self.pairs[p];
                    let (from, to) = match divide {
                        true => (multiple, of),
                        false => (of, multiple),
                    };
                    let columns: Vec<SparseVec<Rational>> = from
                        .iter()
                        .map(|v| (*v).clone())
                        .chain(self.vectors.iter().cloned())
                        .collect();
                    let found: Vec<SparseVec<Rational>> = modular::kernel(&columns, self.rows)
                        .iter()
                        .map(|relation| {
                            sum_by_index(
                                relation
                                    .iter()
                                    .filter(|(j, _)| *j < from.len())
                                    .flat_map(|(j, x)| to[*j].iter().map(move |(i, y)| (*i, x * y)))
                                    .collect(),
                            )
                        })
                        .collect();
                    for v in found {
                        grew |= self.add(v);
                    }
                }
            }
            if !grew {
                return;
            }
        }
    }
}

/// Whether `dependency`, found modulo p, writes `v` in the `inserted` vectors over Q too,
/// summed in `sums`, which every check of one decision shares; `None` when its coefficients
/// have no rational reconstruction. Independence modulo p is independence over Q unless p
/// divides a minor of the span (its rank then drops modulo p): `exact_complement` rules that
/// out.
fn dependency_holds(
    sums: &mut CombinationSums,
    dependency: &SparseVec<Fp>,
    inserted: &[&SparseVec<Rational>],
    v: &SparseVec<Rational>,
) -> Option<bool> {
    let coeffs = modular::reconstruct_vec(dependency)?;
    Some(sums.equals(inserted, &coeffs, v))
}

/// The known integrals of a search for new ones.
struct KnownIntegrals {
    /// Each one's name (for a function of the system, its display as it prints, `ω3` of
    /// `omega3`).
    names: Vec<String>,
    /// Each one in the unknowns' monomials, and its coordinates in the space.
    integrals: Vec<(Expr, SparseVec<Rational>)>,
}

/// Refuses, before the search, the first known integral given in `options.known` that is not
/// real, divides by a declared denominator that vanishes at the fixed values (it has no value
/// there, and no bracket to test: `F1` of the Neumann system at `a1 = a2 = 1`), or is no
/// integral (under the condition, at the fixed values, `at`; on the level set
/// `on`, its bracket with `H` no multiple of the level set's polynomial), by one bracket
/// with `H` each and before the space's unknowns are formed ([`EngineError::RefusedKnown`],
/// which says which one by its place in the list).
pub(super) fn refuse_given_known(
    system: &System,
    at: &AtValues<'_>,
    on: Option<&OnLevel>,
    options: &SearchOptions,
) -> Result<(), EngineError> {
    let parameters = at.parameters;
    for (index, (name, f)) in options.known.iter().enumerate() {
        let refused = |reason: String| EngineError::RefusedKnown {
            index,
            name: name.clone(),
            reason,
        };
        if !f.is_real() {
            return Err(refused(format!(
                "is not real: give its real and imaginary parts, re({name}) and im({name})"
            )));
        }
        // Where a denominator that it divides by vanishes, it has no value to test.
        let atoms = system.space().denominator_atoms();
        match refuse_division_by_zero(atoms, parameters, std::iter::once(f)) {
            Err(EngineError::Invalid(why)) => {
                return Err(refused(format!("has no value where it is searched: {why}")))
            }
            checked => checked?,
        }
        // Nor where the condition makes one it divides by 0 (`1/(ω² − Ω²)` at `Ω = ω`).
        if let Some(c) = &options.condition {
            match c.values_denominators_of(f) {
                Err(EngineError::RefusedCondition { message, .. }) => {
                    return Err(refused(format!(
                        "has no value where it is searched: {message}"
                    )))
                }
                checked => checked?,
            }
        }
        let fixed = fix_parameters(f, parameters)?;
        if let Some(level) = on {
            let flow = at.flow(system, &fixed)?;
            if let Some(v) = level
                .negative_power(&fixed)
                .or_else(|| level.negative_power(&flow))
            {
                return Err(refused(format!(
                    "is not taken on the level set {}: it or its bracket with H has a negative \
                     power of {v}, a variable of the level set's polynomial P, and a known \
                     integral there is taken modulo P by dividing polynomials in P's \
                     variables; leave it out of --known, or take a level set of variables that \
                     it does not divide by",
                    options.on.as_ref().map_or("", |l| l.text.as_str())
                )));
            }
        }
        if !at.is_integral(system, &fixed, on)? {
            let flow = at.flow(system, &fixed)?;
            return Err(refused(not_an_integral(name, &flow, options, parameters)));
        }
    }
    Ok(())
}

/// The known integrals, named: the system's named functions that are real integrals (the
/// others left out) and those given in `options.known` (which [`refuse_given_known`] has
/// checked before the search), each restricted to the condition and located in the space; a
/// constant on phase space, or a function met twice, is left out.
fn known_integrals(
    system: &System,
    problem: &Problem,
    options: &SearchOptions,
    parameters: &[(Var, Rational)],
    locator: &Locator<'_>,
) -> Result<KnownIntegrals, EngineError> {
    let (extra, symbolic) = (&options.known, &options.symbolic);
    let mut known_names = Vec::new();
    let mut known: Vec<(Expr, SparseVec<Rational>)> = Vec::new();
    // Each named as its display prints, as the expressions write it: `ω3` of `omega3`.
    let named = system
        .functions()
        .iter()
        .map(|f| (trigpoly::shown_text(&f.display), f.expr.clone()));
    // The system's functions that are no real integrals are left out; the given ones are real
    // integrals, or the search was refused before it began.
    let named = named.map(|(name, f)| (name, f, false));
    let given = extra
        .iter()
        .map(|(name, f)| (name.clone(), f.clone(), true));
    for (name, f, given) in named.chain(given) {
        // A function of the system with no value under the condition is none of them.
        let valued = |c: &Condition| c.values_denominators_of(&f).is_ok();
        if !given && (!f.is_real() || !options.condition.iter().all(valued)) {
            continue;
        }
        let fv = fix_parameters(&f, parameters)?;
        if !given && !problem.is_integral(system, &fv)? {
            continue;
        }
        let restricted = without_parameter_denominators(&problem.apply_condition(fv)?, symbolic)?;
        let Some(v) = locator.coordinates(&restricted)? else {
            continue;
        };
        // In the unknowns' monomials, so that its generators' sizes are its own. A constant on
        // phase space (`Ω = ω` at a resonance) is no integral worth naming, and a function
        // given twice (in other monomials, with denominators) is named once.
        let canonical = problem.combination(&v)?;
        if !is_phase_free(&canonical) && !known.iter().any(|k| k.1 == v) {
            known_names.push(name);
            known.push((canonical, v));
        }
    }
    Ok(KnownIntegrals {
        names: known_names,
        integrals: known,
    })
}

/// Why a known integral `name` whose bracket with `H` is `flow`, not zero, is refused, after
/// its name: `is not an integral: ` and the bracket (or its size, when long) and where it was
/// taken, under the condition and at the fixed values, where it may vanish only; on a level
/// set, that it is none there: the bracket is no multiple of its polynomial. The bracket is
/// shown over common denominators ([`Expr::over_common_denominators`]).
fn not_an_integral(
    name: &str,
    flow: &Expr,
    options: &SearchOptions,
    parameters: &[(Var, Rational)],
) -> String {
    // Over common denominators, so that a parameter's polynomial and a declared denominator
    // of it cancel (`(a1 − a3)/(a1 − a3)` was shown so); a long one is shown by its size.
    let flow = match flow.len() <= 200 {
        true => flow
            .over_common_denominators()
            .unwrap_or_else(|_| flow.clone()),
        false => flow.clone(),
    };
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
    match &options.on {
        Some(level) => format!(
            "is not an integral on the level set {}: {bracket}{at}, which is not a multiple of \
             P = {}",
            level.text,
            level
                .polynomial()
                .map(|p| p.render(Style::Unicode))
                .unwrap_or_default()
        ),
        None => format!("is not an integral: {bracket}{at}"),
    }
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
pub(super) struct Grading {
    /// The coordinates, the momenta and the Poisson variables, whose total degree comes first.
    pub(super) degree_variables: Vec<Var>,
    pub(super) angles: Vec<Var>,
    /// How many trigonometric orders the space has, `K + 1`.
    pub(super) orders: i64,
}

impl Grading {
    pub(super) fn new(variables: &SpaceVariables, trig_degree: u32) -> Self {
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

    /// With denominator atoms and radicals, their powers count in the degree too
    /// (`1/(x − y)` and `1/r` have degree 1).
    pub(super) fn with_stand_ins(mut self, vars: &Vars) -> Self {
        self.degree_variables.extend(vars.denominators());
        self.degree_variables.extend(vars.radicals());
        self
    }

    /// The number of the grade of `f`, a function of the space (0 for a constant).
    pub(super) fn grade(&self, f: &Expr) -> i64 {
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
pub(super) struct Size {
    pub(super) momenta: i64,
    pub(super) coordinates: i64,
    pub(super) poisson: i64,
    pub(super) angles_alone: i64,
}

impl Size {
    /// Past every bound: the least size of no generator.
    const UNBOUNDED: Size = Size {
        momenta: i64::MAX,
        coordinates: i64::MAX,
        poisson: i64::MAX,
        angles_alone: i64::MAX,
    };

    /// The most that a product may take of `space`: its degrees in the momenta, the
    /// coordinates (with the powers of the denominators and radicals) and the Poisson
    /// variables, and its trigonometric order.
    fn bounds(space: &SearchSpace) -> Size {
        Size {
            momenta: space.momenta_degree.into(),
            coordinates: (space.positions_degree
                + space.denominators_degree
                + space.radicals_degree)
                .into(),
            poisson: space.poisson_degree.into(),
            angles_alone: space.trig_degree.into(),
        }
    }

    pub(super) fn of(f: &Expr) -> Self {
        let degree = |kinds: &[VarKind]| f.total_degree(kinds).unwrap_or(0);
        let (momenta, coordinates, poisson) = (
            degree(&[VarKind::Momentum]),
            // The powers of the denominator atoms and radicals count with the coordinates.
            degree(&[VarKind::Coordinate, VarKind::Denominator, VarKind::Radical]),
            degree(&[VarKind::Poisson]),
        );
        let angles_alone = match momenta == 0 && coordinates == 0 && poisson == 0 {
            true => degree(&[VarKind::Angle]),
            false => 0,
        };
        Size {
            momenta,
            coordinates,
            poisson,
            angles_alone,
        }
    }

    /// Its degree in the momenta, the coordinates and the Poisson variables together.
    fn total_degree(&self) -> i64 {
        self.momenta
            .saturating_add(self.coordinates)
            .saturating_add(self.poisson)
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
pub(super) struct Generator {
    pub(super) expr: Expr,
    /// What it takes of the space's bounds in a product.
    pub(super) size: Size,
    /// The least grade ([`Grading`]) of an integral it is a component of: products count from
    /// the largest stamp of their factors on.
    pub(super) stamp: i64,
}

/// The generators of the integrals `sources` (constants left out), each component once. A
/// constant is of grade 0, or, where the space's monomials are related, a component that
/// `constant` finds one: the space may write a constant in its monomials, where its grade is
/// not 0 (`−a²` as `x² + 2ax + y² + z² − s²` for `s² = (x + a)² + y² + z²`, where the space
/// has `a` but not `a²`).
pub(super) fn generators<'a>(
    problem: &Problem,
    grading: &Grading,
    sources: impl IntoIterator<Item = &'a Expr>,
    constant: &dyn Fn(&Expr) -> Result<bool, EngineError>,
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
                None if constant(&c)? => {}
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

/// Whether `f`, a function at the fixed values, is a constant: free of the Poisson
/// variables, and its derivative by every canonical variable, `{f, p}` and `−{f, q}` (through
/// the radicals' and denominators' declared brackets), zero.
fn is_constant(system: &System, problem: &Problem, f: &Expr) -> Result<bool, EngineError> {
    let space = system.space();
    if space.poisson_variables().iter().any(|&v| f.contains(v)) {
        return Ok(false);
    }
    for pair in space.pairs() {
        for v in [pair.q, pair.p] {
            let derivative = system.bracket(f, &Expr::var(&problem.vars, v))?;
            let derivative = fix_parameters(&derivative, &problem.parameters)?;
            if !problem.vanishes(system, &derivative)? {
                return Ok(false);
            }
        }
    }
    Ok(true)
}

/// The generators that are no multiple `μ·g` of another generator `g` by a monomial `μ ≠ 1`
/// in the parameters `free` (kept symbolic and held by no denominator or radicand). A product
/// with `μ·g` is `μ` times the product with `g`, which the parameter multiples give once that
/// product is in the span: the degree in those parameters is a grading (the relations among
/// the monomials do not hold them), so a product that lies in the space lies in it divided by
/// `μ` too. With parameters kept symbolic most basis integrals are such multiples, and the
/// products of the others are far fewer.
pub(super) fn without_parameter_multiples(
    mut gens: Vec<Generator>,
    free: &[Var],
) -> Vec<Generator> {
    let vars = match gens.first() {
        Some(g) if !free.is_empty() => g.expr.vars().clone(),
        _ => return gens,
    };
    let mut in_free = vec![false; vars.len()];
    for v in free {
        in_free[v.index()] = true;
    }
    // `c = μ·g`: the same coefficients, every exponent vector moved by the same `μ ≠ 1`.
    let multiple_of = |c: &Expr, g: &Expr| -> bool {
        if c.len() != g.len() {
            return false;
        }
        let mut shift: Option<Vec<i64>> = None;
        for (a, b) in c.terms().zip(g.terms()) {
            if a.coeff() != b.coeff() {
                return false;
            }
            let d: Vec<i64> = a
                .exponents()
                .iter()
                .zip(b.exponents())
                .map(|(x, y)| x - y)
                .collect();
            match &shift {
                Some(s) if *s != d => return false,
                Some(_) => {}
                None => {
                    let fits = d
                        .iter()
                        .zip(&in_free)
                        .all(|(e, free)| *e == 0 || (*free && *e > 0));
                    if !fits || d.iter().all(|e| *e == 0) {
                        return false;
                    }
                    shift = Some(d);
                }
            }
        }
        true
    };
    // A grade leaves the parameters out: `μ·g` and `g` have the same stamp.
    let multiples: Vec<bool> = gens
        .iter()
        .map(|c| gens.iter().any(|g| multiple_of(&c.expr, &g.expr)))
        .collect();
    let mut multiples = multiples.into_iter();
    gens.retain(|_| !multiples.next().expect("one flag a generator"));
    gens
}

/// Vectors, each with the stamp from which it counts.
pub(super) type StampedVectors = Vec<(i64, SparseVec<Rational>)>;

/// The span of `vectors` (`(stamp, coordinates)`) and of the products of `gens` whose sizes
/// fit `bounds` (the coordinates' degree only unless `laurent`; on a level set, the total
/// degree, [`Spanning::fits`]), in `span`: its kept vectors by
/// increasing stamp and how many products were formed, or `None` when a denominator vanishes
/// modulo p. The products stop once the span has `dimension`, that of the integrals, and
/// fail past `max_products`.
pub(super) fn span_of_products(
    locator: &Locator,
    gens: &[Generator],
    vectors: StampedVectors,
    bounds: Size,
    laurent: bool,
    mut span: Stamped,
    (dimension, max_products): (usize, usize),
) -> Result<Option<(StampedVectors, usize)>, EngineError> {
    let products = Spanning {
        locator,
        bounds,
        laurent,
        on_level: matches!(locator, Locator::Monomials(problem) if problem.level.is_some()),
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
pub(super) struct Spanning<'a, 's> {
    pub(super) locator: &'a Locator<'a>,
    pub(super) bounds: Size,
    pub(super) laurent: bool,
    /// Whether the products are reduced modulo a level set's polynomial, so held to the
    /// space's largest total degree rather than to each bound ([`Spanning::fits`]).
    pub(super) on_level: bool,
    /// The dimension of the space of integrals.
    pub(super) dimension: usize,
    pub(super) span: &'a mut Stamped<'s>,
    /// Products formed so far (a prefix formed again in a later stamp's round counts again).
    pub(super) formed: usize,
    /// The most products to form.
    pub(super) max_products: usize,
}

/// Why the products stop before the last: the span holds every integral, a denominator
/// vanishes modulo p, or an error.
pub(super) enum Stop {
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
                    self.add(|span| Ok(span.add(at, v)))?;
                }
                self.round(&gens[..hi], lo, stamp)?;
                lo = hi;
            }
            for (at, v) in vectors.by_ref() {
                self.add(|span| Ok(span.add(at, v)))?;
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
    fn add(
        &mut self,
        add: impl FnOnce(&mut Stamped) -> Result<Option<()>, EngineError>,
    ) -> Result<(), Stop> {
        add(self.span)?.ok_or(Stop::NotModular)?;
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

    /// Whether a product of `size` may lie in the space: within each bound (the coordinates'
    /// degree only unless `laurent`), or, on a level set, within the space's largest total
    /// degree, since a normal form modulo `P` has at most the total degree of the product it
    /// reduces (the division's order is graded) but may move it between the momenta, the
    /// coordinates and the Poisson variables (`x²` replaced through `H = E` by momenta).
    fn fits(&self, size: Size) -> bool {
        let degrees = match self.on_level {
            true => size.total_degree() <= self.bounds.total_degree(),
            false => {
                size.momenta <= self.bounds.momenta
                    && (self.laurent || size.coordinates <= self.bounds.coordinates)
                    && size.poisson <= self.bounds.poisson
            }
        };
        degrees && size.angles_alone <= self.bounds.angles_alone
    }
}

/// One stamp's depth-first walk over the products of [`Spanning::round`].
pub(super) struct Round<'g> {
    pub(super) gens: &'g [&'g Generator],
    pub(super) lo: usize,
    pub(super) stamp: i64,
    /// From each index on, the least size of a generator.
    pub(super) least: Vec<Size>,
    /// The most factors of positive degree, whose coordinates' degrees may cancel in a
    /// Laurent space (those of the angles alone are bounded by their orders).
    pub(super) max_factors: usize,
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
                return Err(Stop::Failed(EngineError::PastLimit {
                    which: EngineLimit::SearchProducts,
                    limit: n,
                    message: format!(
                        "more than {n} product{} of integrals, the search's limit of them: \
                         search a smaller space, or raise the limit",
                        if n == 1 { "" } else { "s" }
                    ),
                }));
            }
            if i >= self.lo {
                let (locator, stamp) = (spanning.locator, self.stamp);
                spanning.add(|span| span.add_parts(locator, stamp, &p))?;
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
pub(super) struct Leads {
    /// For each unknown, its position among the leads, if it is one.
    pub(super) position: Vec<Option<usize>>,
    /// How many coordinates are kept.
    pub(super) count: usize,
}

impl Leads {
    /// The leads of `kernel` (sorted by leading unknown, primitive), among `dim` unknowns; every
    /// unknown when a lead coefficient vanishes modulo p.
    pub(super) fn of(kernel: &[SparseVec<Rational>], dim: usize) -> Self {
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
    pub(super) fn all(dim: usize) -> Self {
        Leads {
            position: (0..dim).map(Some).collect(),
            count: dim,
        }
    }

    /// `v`'s coordinates on the leads.
    pub(super) fn restrict<F>(&self, v: SparseVec<F>) -> SparseVec<F> {
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
pub(super) struct Stamped<'a> {
    pub(super) basis: Independent<'a>,
    /// The kept vectors over Q, with their stamps.
    pub(super) kept: StampedVectors,
}

/// The vectors kept so far, as a basis modulo p (of their coordinates on the leads) or over Q.
pub(super) enum Independent<'a> {
    Modular(Echelon<Fp>, &'a Leads),
    Exact(Echelon<Rational>),
}

impl<'a> Stamped<'a> {
    pub(super) fn new(leads: &'a Leads, exact: bool) -> Self {
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
    pub(super) fn rank(&self) -> usize {
        self.kept.len()
    }

    /// Adds `v` under `stamp`, no smaller than any stamp before it; `None` when a denominator
    /// of `v` vanishes modulo p.
    pub(super) fn add(&mut self, stamp: i64, v: SparseVec<Rational>) -> Option<()> {
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
    pub(super) fn add_parts(
        &mut self,
        locator: &Locator,
        stamp: i64,
        p: &Expr,
    ) -> Result<Option<()>, EngineError> {
        let (e, leads) = match &mut self.basis {
            Independent::Modular(e, leads) => (e, *leads),
            Independent::Exact(_) => {
                if let Some((re, im)) = locator.parts(p)? {
                    for v in [re, im] {
                        if !v.is_empty() && self.add(stamp, v).is_none() {
                            return Ok(None);
                        }
                    }
                }
                return Ok(Some(()));
            }
        };
        // By the monomials (of the normal form, on a level set), modulo p first and over Q only
        // for a part that is kept; through the cleared basis the coordinates come over Q, once.
        let reduced = match locator {
            Locator::Monomials(problem) => Some(problem.normal_form(p)?),
            Locator::Cleared(_) => None,
        };
        let (parts, mut exact_parts) = match (locator, &reduced) {
            (Locator::Monomials(problem), Some(reduced)) => {
                (problem.coordinates_of_parts_mod_p(reduced), None)
            }
            _ => match locator.parts(p)? {
                None => (Some(None), None),
                Some((re, im)) => {
                    let fp = modular::to_fp(&re).zip(modular::to_fp(&im));
                    (fp.map(|(a, b)| Some([a, b])), Some((re, im)))
                }
            },
        };
        // `None` when a denominator vanishes modulo p, `Some(None)` outside the space.
        let Some(parts) = parts else {
            return Ok(None);
        };
        let Some(parts) = parts else {
            return Ok(Some(()));
        };
        debug_assert!(self.kept.last().is_none_or(|k| k.0 <= stamp));
        for (part, v) in parts.into_iter().enumerate() {
            let v = leads.restrict(v);
            if v.is_empty() || !e.extend(self.kept.len(), &v) {
                continue;
            }
            if exact_parts.is_none() {
                let located = match (locator, &reduced) {
                    (Locator::Monomials(problem), Some(reduced)) => {
                        problem.coordinates_of_parts(reduced)
                    }
                    _ => locator.parts(p)?,
                };
                exact_parts = Some(located.expect("in the space"));
            }
            let (re, im) = exact_parts.as_mut().expect("just formed");
            let v = std::mem::take(if part == 0 { re } else { im });
            self.kept.push((stamp, v));
        }
        Ok(Some(()))
    }

    /// The kept vectors with their stamps, by increasing stamp.
    pub(super) fn into_vectors(self) -> StampedVectors {
        self.kept
    }
}
