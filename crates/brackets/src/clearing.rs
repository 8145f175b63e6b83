//! Clearing denominators for linear algebra: with denominator atoms (`v` standing for a
//! polynomial `D`, `v^{−k} = 1/D^k`) the monomials of a vector are not independent
//! (`v · D = 1`), so linear algebra that compares coefficients runs on the vectors' images
//! under one injective linear map onto polynomials, [`Clearing`]; so with radicals
//! (`r² = R`), whose images are reduced to each radical to the power 0 or 1. The closure's, the
//! bracket table's and the search's solves take it.

use std::sync::{Arc, Mutex, PoisonError};

use rayon::prelude::*;
use rustc_hash::FxHashMap;
use trigpoly::{Expr, GaussianRational, Rational, ReducedRadical, Var};

use crate::search::fix_parameters;
use crate::{EngineError, PhaseSpace};

/// Refuses an atom that one of `exprs` divides by (holds to a negative power) whose polynomial
/// vanishes at the fixed values: what [`Clearing::new`] refuses among its vectors, for what
/// enters them without being one, a search's `H` (`H + 1/(a1 − a2)` has the brackets of `H`,
/// but no value at `a1 = a2`) or a condition.
pub(crate) fn refuse_division_by_zero<'a>(
    atoms: &[(Var, Expr)],
    parameters: &[(Var, Rational)],
    exprs: impl Iterator<Item = &'a Expr>,
) -> Result<(), EngineError> {
    let exprs: Vec<&Expr> = exprs.collect();
    for ((v, d), n) in atoms.iter().zip(inverse_powers(atoms, &exprs)) {
        atom_at_values(*v, d, n, parameters)?;
    }
    Ok(())
}

/// For each of `symbols` (atoms or radicals), the highest power of its inverse among `exprs`,
/// 0 where none holds it to a negative power.
fn inverse_powers(symbols: &[(Var, Expr)], exprs: &[&Expr]) -> Vec<i64> {
    symbols
        .iter()
        .map(|(v, _)| {
            exprs
                .iter()
                .map(|e| -e.low_degree(*v).unwrap_or(0))
                .fold(0, i64::max)
        })
        .collect()
}

/// The polynomial `d` of the atom `v` at the fixed values, refused where it is zero and
/// something divides by it (`n`, the highest power of `1/d`, above 0).
fn atom_at_values(
    v: Var,
    d: &Expr,
    n: i64,
    parameters: &[(Var, Rational)],
) -> Result<Expr, EngineError> {
    let at = fix_parameters(d, parameters)?;
    // Only an atom divided by needs a value other than zero: one that nothing divides by (the
    // closure of `H` and `L` on a system that declares `a1 − a2`, a search at `a1 = a2` in a
    // space without `1/(a1 − a2)`) is a polynomial factor that its value, zero or not,
    // evaluates.
    if n > 0 && at.is_zero() {
        let vars = d.vars();
        let values: Vec<String> = parameters
            .iter()
            .filter(|(p, _)| d.contains(*p))
            .map(|(p, x)| format!("{} = {x}", vars.variable(*p).unicode()))
            .collect();
        return Err(EngineError::Invalid(format!(
            "the denominator {} is zero at {}, the values the linear algebra takes: give \
             other values (the options' `fix`; on the command line, --fix)",
            vars.variable(v).unicode(),
            values.join(", ")
        )));
    }
    Ok(at)
}

/// Whether `e`, a function at the fixed values `parameters`, is zero: through one
/// [`Clearing`], with the atoms' polynomials and the radicands at those values too, where the
/// ring's own zero test ([`Expr::vanishes`]) takes them with symbolic parameters and would
/// leave a residual in the parameters an atom holds (`1/(x − a)` at `a = 1`).
pub(crate) fn vanishes_at_values(
    space: &PhaseSpace,
    parameters: &[(Var, Rational)],
    e: &Expr,
) -> Result<bool, EngineError> {
    let clearing = Clearing::new(
        space.denominator_atoms(),
        space.radicals(),
        parameters,
        std::iter::once(e),
    )?;
    Ok(match clearing {
        Some(clearing) => clearing.apply(e)?.is_zero(),
        None => e.is_zero(),
    })
}

/// `e` with each declared denominator whose polynomial holds parameters alone at its value at
/// the fixed `parameters`, the number [`Clearing`] takes it at there (the atom stands for its
/// polynomial `D`, so `1/(κ + 1)` is `1/2` at `κ = 1`), refused where `D` is zero there and
/// `e` divides by it. A search's level set whose value holds one is divided by this polynomial
/// (`OnLevel`), so that the normal forms are written in the space's monomials, which hold no
/// such atom (a number at those values). A radical of parameters is left as it is: it has no
/// rational value in general, and the space holds its powers.
pub(crate) fn parameter_atoms_at_values(
    space: &PhaseSpace,
    parameters: &[(Var, Rational)],
    e: &Expr,
) -> Result<Expr, EngineError> {
    let atoms = space.denominator_atoms();
    let mut values = Vec::new();
    for ((v, d), n) in atoms.iter().zip(inverse_powers(atoms, &[e])) {
        if e.contains(*v) && fix_parameters(d, parameters)?.is_constant() {
            values.push((*v, atom_at_values(*v, d, n, parameters)?));
        }
    }
    Ok(e.subst_many(&values)?)
}

/// The injective linear map the linear algebra takes its vectors through on a system with
/// denominator atoms: `e ↦ (Π v_i^{N_i} · e)(v_i = D_i)`, each `N_i` at least the highest power
/// of `1/D_i` among the vectors, so that every image is a polynomial. It is multiplication by
/// `Π D_i^{N_i} ≠ 0` in the rational functions, hence injective, and monomials are independent
/// among polynomials: a combination of images is one of the elements, and a relation among
/// the images one among the elements, exactly. The `D_i` are taken at the parameters' fixed
/// values, where the vectors are (the closure's), or symbolic, with no values (a table's):
/// multiplication by a parameter monomial commutes with the map either way.
///
/// With radicals `r = √R` the map first multiplies by `r^M`, `M` at least the highest power of
/// `1/r` among the vectors, and reduces by `r² = R` ([`Expr::reduce_radicals`]): multiplication
/// by `r^M ≠ 0` is injective, and the reduced images, each radical to the power 0 or 1, are
/// zero exactly when the elements are.
pub(crate) struct Clearing {
    /// Each radical, its radicand at the fixed values, and its power `M`.
    radicals: Vec<ReducedRadical<GaussianRational>>,
    /// Each atom, its polynomial at the fixed values, and its power `N`.
    atoms: Vec<(Var, Expr, i64)>,
    /// Whether every atom's polynomial is real, so that a real vector's image is real.
    pub(crate) real: bool,
    /// The products `Π D_i^{k_i}` formed so far, by `k`: the images of a search share a few
    /// hundred of them, each formed once.
    products: Mutex<FxHashMap<Vec<i64>, Arc<Expr>>>,
}

impl Clearing {
    /// The map for `vectors` (every column and target), `None` without atoms or radicals.
    /// Refused: an atom that a vector divides by whose polynomial vanishes at the fixed values
    /// (`x − a` cannot, `a − b` at `a = b = 1` does).
    pub(crate) fn new<'a>(
        atoms: &[(Var, Expr)],
        radicals: &[(Var, Expr)],
        parameters: &[(Var, Rational)],
        vectors: impl Iterator<Item = &'a Expr>,
    ) -> Result<Option<Self>, EngineError> {
        if atoms.is_empty() && radicals.is_empty() {
            return Ok(None);
        }
        let vectors: Vec<&Expr> = vectors.collect();
        let radicals = radicals
            .iter()
            .zip(inverse_powers(radicals, &vectors))
            .map(|((r, radicand), m)| Ok((*r, fix_parameters(radicand, parameters)?, m)))
            .collect::<Result<Vec<_>, EngineError>>()?;
        let out = atoms
            .iter()
            .zip(inverse_powers(atoms, &vectors))
            .map(|((v, d), n)| Ok((*v, atom_at_values(*v, d, n, parameters)?, n)))
            .collect::<Result<Vec<_>, EngineError>>()?;
        let real = out.iter().all(|(_, d, _)| d.is_real());
        Ok(Some(Clearing {
            radicals,
            atoms: out,
            real,
            products: Mutex::default(),
        }))
    }

    /// The images of `es`, formed on the pool's threads; the first error in their order.
    pub(crate) fn apply_all(&self, es: &[Expr]) -> Result<Vec<Expr>, EngineError> {
        let images: Vec<Result<Expr, EngineError>> = es.par_iter().map(|e| self.apply(e)).collect();
        images.into_iter().collect()
    }

    /// The image of `e`: a polynomial with no atoms, each radical to the power 0 or 1.
    pub(crate) fn apply(&self, e: &Expr) -> Result<Expr, EngineError> {
        let vars = e.vars();
        let e = &e.reduce_radicals(&self.radicals)?;
        let powers: Vec<(Var, i64)> = self
            .atoms
            .iter()
            .filter(|a| a.2 > 0)
            .map(|(v, _, n)| (*v, *n))
            .collect();
        let out = e.checked_mul(&Expr::monomial(vars, GaussianRational::from(1), &powers)?)?;
        if self.atoms.is_empty() {
            return Ok(out);
        }
        // Every atom at once: `Σ_k c_k Π v_i^{k_i} ↦ Σ_k c_k Π D_i^{k_i}`, each product of
        // powers formed once for all the images (one atom at a time multiplied each image's
        // growing parts by each power in turn: half of a search's time with denominators).
        let atoms: Vec<Var> = self.atoms.iter().map(|a| a.0).collect();
        let parts = out
            .coefficients_in(&atoms)
            .into_iter()
            .map(|(k, c)| Ok(c.checked_mul(&*self.product(&k)?)?))
            .collect::<Result<Vec<Expr>, EngineError>>()?;
        Ok(Expr::sum_all(vars, parts)?)
    }

    /// `Π D_i^{k_i}` over the atoms, formed the first time it is asked for (the powers are not
    /// negative: the image was multiplied by `Π v_i^{N_i}` first).
    fn product(&self, k: &[i64]) -> Result<Arc<Expr>, EngineError> {
        let products = || self.products.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(p) = products().get(k) {
            return Ok(p.clone());
        }
        // Formed outside the lock (two threads may both form it; either is kept).
        let vars = self.atoms[0].1.vars();
        let mut p = Expr::one(vars);
        for ((_, d, _), &e) in self.atoms.iter().zip(k) {
            if e != 0 {
                p = p.checked_mul(&d.checked_pow(e)?)?;
            }
        }
        let mut map = products();
        let p = Arc::new(p);
        Ok(map.entry(k.to_vec()).or_insert(p).clone())
    }
}
