//! Scaling symmetries, and lifting a result found at fixed parameter values back to symbols.
//!
//! A *weight* gives each variable a rational number; a monomial's weight is the sum over its
//! exponents. The weights that make a computation homogeneous (the flow `{·, H}` on the
//! resonance surface, or the bracket with a list of functions) form a vector space, found here
//! exactly as the kernel of a linear system. When the parameters' weights are independent (the
//! parameter part of the weights has full column rank), a function known at fixed values
//! `M = 1, ω = 1, …` determines, term by term, the unique parameter monomial that makes it
//! homogeneous: [`Lifter::lift`] puts the parameters back. The lift is then proved by the
//! engine, never assumed.

use std::collections::hash_map::Entry;

use rustc_hash::FxHashMap;
use trigpoly::{Expr, GaussianRational, Rational, Var, Vars};

use crate::claim::Condition;
use crate::error::EngineError;
use crate::linalg::Matrix;
use crate::modular::{kernel, SparseVec};
use crate::phase::PhaseSpace;

/// A basis of the weights under which a computation is homogeneous.
#[derive(Clone, Debug)]
pub struct Scaling {
    vars: Vars,
    /// Each weight vector has one entry per variable.
    basis: Vec<Vec<Rational>>,
}

/// Linear constraints on the unknowns `(w_0, …, w_{n−1}, extra)`.
struct Constraints {
    n: usize,
    rows: Vec<Vec<(usize, i64)>>,
}

impl Constraints {
    fn new(n: usize) -> Self {
        Constraints {
            n,
            rows: Vec::new(),
        }
    }

    /// `Σ_v a_v w_v + b·extra = 0` for exponents `a`.
    fn push(&mut self, a: &[i64], b: i64) {
        let mut row: Vec<(usize, i64)> = a
            .iter()
            .enumerate()
            .filter(|(_, x)| **x != 0)
            .map(|(i, x)| (i, *x))
            .collect();
        if b != 0 {
            row.push((self.n, b));
        }
        if !row.is_empty() {
            self.rows.push(row);
        }
    }

    /// The kernel, restricted to the variables.
    fn solve(&self) -> Vec<Vec<Rational>> {
        let mut columns: Vec<SparseVec<Rational>> = vec![Vec::new(); self.n + 1];
        for (r, row) in self.rows.iter().enumerate() {
            for (j, a) in row {
                columns[*j].push((r, Rational::from(*a)));
            }
        }
        kernel(&columns, self.rows.len())
            .into_iter()
            .map(|k| {
                let mut w = vec![Rational::zero(); self.n];
                for (j, x) in k {
                    if j < self.n {
                        w[j] = x;
                    }
                }
                w
            })
            .collect()
    }
}

/// An atom weighs what every term of its polynomial does, and a radical half of it, so that
/// `v ↦ D` and `r² ↦ R` keep weights and a lift is homogeneous as an element, not only as
/// written.
fn atoms_weigh_their_polynomials(c: &mut Constraints, space: &PhaseSpace) {
    let n = space.vars().len();
    let atoms = space.denominator_atoms().iter().map(|a| (a, 1));
    let radicals = space.radicals().iter().map(|r| (r, 2));
    for ((v, d), times) in atoms.chain(radicals) {
        for t in d.terms() {
            c.push(&minus(&t.exponents(), &unit(n, v.index(), times)), 0);
        }
    }
}

fn unit(n: usize, j: usize, value: i64) -> Vec<i64> {
    let mut e = vec![0; n];
    e[j] = value;
    e
}

fn minus(a: &[i64], b: &[i64]) -> Vec<i64> {
    a.iter().zip(b).map(|(x, y)| x - y).collect()
}

impl Scaling {
    /// The weights under which the flow `F ↦ {F, H} = Σ_v ∂F/∂v · {v, H}` (after the
    /// condition) maps homogeneous functions of the phase variables and the angles to
    /// homogeneous ones: every term of `{v, H}` has weight `δ + w(v)`, that is for each
    /// canonical pair `(q, p)` every term of `∂H/∂p` has weight `δ + w(q)` and every term of
    /// `∂H/∂q` weight `δ + w(p)`, and for a variable `v` of declared brackets every term of
    /// their part `Σ_u {v, u} ∂H/∂u` weight `δ + w(v)` (on so(3)*, `{M₁, H} = (1/I₂ − 1/I₃)
    /// M₂M₃` gives the moments of inertia one weight); angles have weight 0 (so `∂/∂θ` keeps a
    /// term's weight, and a potential `−g cos θ` gives `g` the weight `δ + w(p_θ)`).
    pub fn of_flow(
        space: &PhaseSpace,
        h: &Expr,
        condition: Option<&Condition>,
    ) -> Result<Self, EngineError> {
        let vars = space.vars().clone();
        let n = vars.len();
        let mut c = Constraints::new(n);
        for v in vars.angles() {
            c.push(&unit(n, v.index(), 1), 0);
        }
        let cond = |e: Expr| -> Result<Expr, EngineError> {
            match condition {
                Some(k) => k.apply(&e),
                None => Ok(e),
            }
        };
        for pair in space.pairs() {
            let dp = cond(h.derivative(pair.p)?)?;
            for t in dp.terms() {
                c.push(&minus(&t.exponents(), &unit(n, pair.q.index(), 1)), -1);
            }
            let dq = cond(h.derivative(pair.q)?)?;
            for t in dq.terms() {
                c.push(&minus(&t.exponents(), &unit(n, pair.p.index(), 1)), -1);
            }
        }
        // The declared brackets' part of the flow, the atoms' chain rule included.
        if !space.declared_brackets().is_empty()
            || !space.denominator_atoms().is_empty()
            || !space.radicals().is_empty()
        {
            for (v, part) in space.gradient(h)?.declared() {
                for t in cond(part.clone())?.terms() {
                    c.push(&minus(&t.exponents(), &unit(n, v.index(), 1)), -1);
                }
            }
        }
        atoms_weigh_their_polynomials(&mut c, space);
        Ok(Scaling {
            vars,
            basis: c.solve(),
        })
    }

    /// The weights under which the Poisson bracket is homogeneous (`w(q) + w(p)` the same for
    /// every pair, and `w(a) + w(b)` less that for every term of a declared `{a, b}`, angles of
    /// weight 0), the condition and every one of `functions` are homogeneous, and every
    /// denominator atom weighs what each term of its polynomial does.
    pub fn of_functions(
        space: &PhaseSpace,
        functions: &[Expr],
        condition: Option<&Condition>,
    ) -> Result<Self, EngineError> {
        let vars = space.vars().clone();
        let n = vars.len();
        let mut c = Constraints::new(n);
        for v in vars.angles() {
            c.push(&unit(n, v.index(), 1), 0);
        }
        for pair in space.pairs() {
            let mut e = unit(n, pair.q.index(), 1);
            e[pair.p.index()] += 1;
            c.push(&e, -1);
        }
        // A declared {a, b} = P: every term of P has weight w(a) + w(b) − δ.
        for d in space.declared_brackets() {
            let mut ab = unit(n, d.a.index(), 1);
            ab[d.b.index()] += 1;
            for t in d.value.terms() {
                c.push(&minus(&t.exponents(), &ab), 1);
            }
        }
        if let Some(k) = condition {
            for (v, value) in k.subs() {
                for t in value.terms() {
                    c.push(&minus(&t.exponents(), &unit(n, v.index(), 1)), 0);
                }
            }
        }
        atoms_weigh_their_polynomials(&mut c, space);
        for f in functions {
            let terms: Vec<Vec<i64>> = f.terms().map(|t| t.exponents()).collect();
            for t in terms.iter().skip(1) {
                c.push(&minus(t, &terms[0]), 0);
            }
        }
        Ok(Scaling {
            vars,
            basis: c.solve(),
        })
    }

    /// How many independent weights there are.
    pub fn dimension(&self) -> usize {
        self.basis.len()
    }

    /// The weight of a monomial (exponent vector) under each basis weight.
    pub fn weight(&self, exps: &[i64]) -> Vec<Rational> {
        self.basis
            .iter()
            .map(|w| {
                w.iter()
                    .zip(exps)
                    .filter(|(_, e)| **e != 0)
                    .fold(Rational::zero(), |acc, (x, e)| {
                        acc + x * &Rational::from(*e)
                    })
            })
            .collect()
    }

    /// The common weight of the terms of `e`, if `e` is homogeneous and not zero.
    pub fn homogeneous_weight(&self, e: &Expr) -> Option<Vec<Rational>> {
        let mut it = e.terms().map(|t| self.weight(&t.exponents()));
        let first = it.next()?;
        it.all(|w| w == first).then_some(first)
    }

    /// The weights of this basis under which every one of `vars` weighs zero: those that
    /// still grade a computation made with these variables fixed to values.
    #[must_use]
    pub fn with_zero_weights(&self, vars: &[Var]) -> Scaling {
        let columns: Vec<SparseVec<Rational>> = self
            .basis
            .iter()
            .map(|w| {
                vars.iter()
                    .enumerate()
                    .filter(|(_, v)| !w[v.index()].is_zero())
                    .map(|(row, v)| (row, w[v.index()].clone()))
                    .collect()
            })
            .collect();
        let basis = kernel(&columns, vars.len())
            .into_iter()
            .map(|combination| {
                let mut w = vec![Rational::zero(); self.vars.len()];
                for (i, c) in combination {
                    for (x, b) in w.iter_mut().zip(&self.basis[i]) {
                        *x += &(c.clone() * b);
                    }
                }
                w
            })
            .collect();
        Scaling {
            vars: self.vars.clone(),
            basis,
        }
    }

    /// A lifter for the given fixed parameter values, if the weights determine every one of
    /// those parameters' exponents (the parameter part of the weights has full column rank).
    /// Parameters given a value of zero cannot be lifted.
    pub fn lifter(&self, fixed: &[(Var, Rational)]) -> Option<Lifter> {
        if fixed.iter().any(|(_, v)| v.is_zero()) {
            return None;
        }
        let mut m = Matrix::zeros(self.basis.len(), fixed.len());
        for (i, w) in self.basis.iter().enumerate() {
            for (j, (v, _)) in fixed.iter().enumerate() {
                m.set(i, j, GaussianRational::from(w[v.index()].clone()));
            }
        }
        (m.rank() == fixed.len()).then(|| Lifter {
            vars: self.vars.clone(),
            fixed: fixed.to_vec(),
            matrix: m,
        })
    }
}

/// Puts parameters back into results found at fixed values, by homogeneity.
#[derive(Clone, Debug)]
pub struct Lifter {
    vars: Vars,
    fixed: Vec<(Var, Rational)>,
    matrix: Matrix,
}

impl Lifter {
    /// The parameters and the values they were fixed to.
    pub fn fixed(&self) -> &[(Var, Rational)] {
        &self.fixed
    }

    /// The integer exponents `ν` of the fixed parameters whose monomial has weight `delta`,
    /// if they exist (they are unique).
    pub fn exponents(&self, delta: &[Rational]) -> Option<Vec<i64>> {
        if self.fixed.is_empty() {
            return delta.iter().all(Rational::is_zero).then(Vec::new);
        }
        let b: Vec<GaussianRational> = delta.iter().cloned().map(GaussianRational::from).collect();
        let x = self.matrix.solve(&b)?;
        x.iter()
            .map(|q| {
                (q.is_real() && q.re.is_integer())
                    .then(|| q.re.numer().to_i64())
                    .flatten()
            })
            .collect()
    }

    /// The value of the parameter monomial `Π p^ν` at the fixed point.
    pub fn value(&self, nu: &[i64]) -> Result<Rational, EngineError> {
        let mut value = Rational::one();
        for ((_, x), e) in self.fixed.iter().zip(nu) {
            value *= x.pow(*e).ok_or(trigpoly::AlgebraError::DivisionByZero)?;
        }
        Ok(value)
    }

    /// Lifts `e`, known at the fixed values, to the homogeneous function that takes those
    /// values and keeps the term with exponents `reference` (the first term if `None`) as it
    /// is: each term `c·m` becomes `(c/π(v))·π·m`, with `π` the parameter monomial that gives
    /// it the reference's weight. `None` if some exponent is not an integer. The caller proves
    /// the result.
    pub fn lift(
        &self,
        scaling: &Scaling,
        e: &Expr,
        reference: Option<&[i64]>,
    ) -> Result<Option<Expr>, EngineError> {
        let terms: Vec<(Vec<i64>, GaussianRational)> =
            e.terms().map(|t| (t.exponents(), t.coeff())).collect();
        let Some((first, _)) = terms.first() else {
            return Ok(Some(e.clone()));
        };
        let reference = scaling.weight(reference.unwrap_or(first));
        // The terms share few weights: each weight's exponents (a linear solve) and the
        // inverse of their monomial's value, found once.
        let mut by_weight: FxHashMap<Vec<Rational>, (Vec<i64>, GaussianRational)> =
            FxHashMap::default();
        let mut out = Vec::with_capacity(terms.len());
        for (exps, c) in &terms {
            let w = scaling.weight(exps);
            let (nu, inv) = match by_weight.entry(w) {
                Entry::Occupied(found) => found.into_mut(),
                Entry::Vacant(slot) => {
                    let delta: Vec<Rational> = reference
                        .iter()
                        .zip(slot.key())
                        .map(|(a, b)| a - b)
                        .collect();
                    let Some(nu) = self.exponents(&delta) else {
                        return Ok(None);
                    };
                    let value = self.value(&nu)?;
                    let inv = value.try_inv().expect("nonzero parameter values");
                    slot.insert((nu, GaussianRational::from(inv)))
                }
            };
            let mut exps = exps.clone();
            for ((v, _), k) in self.fixed.iter().zip(nu.iter()) {
                exps[v.index()] += k;
            }
            out.push((c * &*inv, exps));
        }
        Ok(Some(Expr::from_terms(&self.vars, out)?))
    }
}
