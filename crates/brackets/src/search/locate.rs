//! Where a function of the space sits among the unknowns, for `--new-only`: by its monomials
//! (on a level set, its normal form's), or, with denominator atoms or radicals (whose
//! monomials are not independent functions), by its image under a [`Clearing`] written in the
//! images of the basis integrals.

use std::cell::RefCell;
use std::rc::Rc;

use rustc_hash::FxHashMap;
use trigpoly::{Expr, Rational, Var};

use crate::clearing::Clearing;
use crate::error::EngineError;
use crate::modular::{sum_by_index, Echelon, SparseVec};

use super::parameters::free_parameters;
use super::problem::{real_columns, real_entries, Problem, RowIndex};

/// The coordinates of the real and of the imaginary part of a function.
type Parts = (SparseVec<Rational>, SparseVec<Rational>);

/// The coordinates of a function among the unknowns, if it lies in the space.
pub(super) enum Locator<'a> {
    /// By the monomials of the space, which are independent functions; on a level set, those
    /// of a function's normal form modulo its polynomial ([`Problem::normal_form`]).
    Monomials(&'a Problem),
    /// With denominator atoms or radicals, through the cleared images of the basis integrals.
    Cleared(Box<ClearedBasis>),
}

impl Locator<'_> {
    /// The coordinates of a real function `f`, if it lies in the space.
    pub(super) fn coordinates(&self, f: &Expr) -> Result<Option<SparseVec<Rational>>, EngineError> {
        match self {
            Locator::Monomials(problem) => Ok(problem.coordinates(&*problem.normal_form(f)?)),
            Locator::Cleared(basis) => basis.coordinates(f),
        }
    }

    /// The coordinates of the real and of the imaginary part of `p`, a product of integrals
    /// each written in the unknowns' monomials, if both lie in the space.
    pub(super) fn parts(&self, p: &Expr) -> Result<Option<Parts>, EngineError> {
        match self {
            Locator::Monomials(problem) => {
                Ok(problem.coordinates_of_parts(&*problem.normal_form(p)?))
            }
            Locator::Cleared(basis) if basis.past_free_degree(p) => Ok(None),
            Locator::Cleared(basis) => {
                let (_, re, im) = p.conj_re_im();
                let Some(re) = basis.coordinates(&re)? else {
                    return Ok(None);
                };
                Ok(basis.coordinates(&im)?.map(|im| (re, im)))
            }
        }
    }
}

/// The basis integrals of a search with denominator atoms or radicals, for deciding whether a
/// function
/// (a known integral, a product of integrals) lies in the space and with which coordinates.
/// The space's monomials are not independent functions, so a function written in other
/// monomials of the space, or in monomials outside it (a product's powers of `1/D` add up),
/// may still be one of its functions (so may `r · r`, which is `R`). Every function that is asked about is an integral, and
/// the basis spans the integrals of the space: a function lies in the space exactly when it
/// is a combination of the basis integrals, which is decided on the images under a
/// [`Clearing`] (injective) whose powers cover both, exactly over Q. The images of the basis
/// are formed once for each such power vector.
pub(super) struct ClearedBasis {
    atoms: Vec<(Var, Expr)>,
    radicals: Vec<(Var, Expr)>,
    parameters: Vec<(Var, Rational)>,
    angles: Vec<Var>,
    /// The basis integrals as functions, and their coordinates among the unknowns.
    integrals: Vec<Expr>,
    coordinates: Vec<SparseVec<Rational>>,
    /// The powers of `1/D_i`, then of `1/r_i`, the basis integrals have.
    powers: Vec<i64>,
    /// The parameters that no denominator or radicand holds, and the highest total degree in
    /// them of a basis integral: the relations among the monomials leave that degree as it
    /// is, so a product of higher degree is no combination of the basis, found without
    /// clearing it (with parameters kept symbolic, most products of integrals are such).
    free: Vec<Var>,
    free_degree: i64,
    /// The images of the basis integrals by the powers of the clearing.
    images: RefCell<FxHashMap<Vec<i64>, Rc<ClearedImages>>>,
}

/// The basis integrals' images under one clearing: their real equations' rows and an echelon
/// form of them, which expresses an image in them.
struct ClearedImages {
    clearing: Clearing,
    rows: RowIndex,
    echelon: Echelon<Rational>,
}

impl ClearedBasis {
    /// For the basis with coordinates `kernel` among the unknowns of `problem`, whose atoms
    /// and radicals are `atoms` and `radicals` and whose parameters are fixed at `parameters`.
    pub(super) fn new(
        problem: &Problem,
        atoms: &[(Var, Expr)],
        radicals: &[(Var, Expr)],
        parameters: &[(Var, Rational)],
        kernel: &[SparseVec<Rational>],
    ) -> Result<Self, EngineError> {
        let integrals = kernel
            .iter()
            .map(|v| problem.combination(v))
            .collect::<Result<Vec<Expr>, _>>()?;
        let mut powers = vec![0; atoms.len() + radicals.len()];
        for f in &integrals {
            raise_to(&mut powers, atoms.iter().chain(radicals), f);
        }
        let free = free_parameters(&problem.vars, atoms, radicals);
        let free_degree = integrals
            .iter()
            .map(|f| degree_in(f, &free))
            .max()
            .unwrap_or(0);
        Ok(ClearedBasis {
            atoms: atoms.to_vec(),
            radicals: radicals.to_vec(),
            parameters: parameters.to_vec(),
            angles: problem.variables.angles.clone(),
            integrals,
            coordinates: kernel.to_vec(),
            powers,
            free,
            free_degree,
            images: RefCell::default(),
        })
    }

    /// The coordinates of a real function `f` among the unknowns, if it is a combination of
    /// the basis integrals.
    fn coordinates(&self, f: &Expr) -> Result<Option<SparseVec<Rational>>, EngineError> {
        if f.is_zero() {
            return Ok(Some(Vec::new()));
        }
        let mut powers = self.powers.clone();
        raise_to(&mut powers, self.atoms.iter().chain(&self.radicals), f);
        let images = self.images_for(powers, f)?;
        let image = images.clearing.apply(f)?;
        // A monomial that no basis image has: `f` is no combination of them.
        let entries = real_entries(&image, &self.angles, |t, part| {
            images.rows.get_term(t).and_then(|row| row[part])
        });
        let Some(combination) = entries.and_then(|v| images.echelon.express(&v)) else {
            return Ok(None);
        };
        let mut out = Vec::new();
        for (k, c) in &combination {
            out.extend(self.coordinates[*k].iter().map(|(j, x)| (*j, x * c)));
        }
        Ok(Some(sum_by_index(out)))
    }

    /// Whether `p`, a product of integrals each written in the unknowns' monomials, has a
    /// higher degree in the free parameters than any basis integral, and so is no
    /// combination of them. Its terms of the highest degree are then the product of its
    /// factors', each a nonzero function (the monomials are independent), so they are no
    /// zero function written in other terms (as `k(s² − (x + a)² − y² − z²)` would be).
    fn past_free_degree(&self, p: &Expr) -> bool {
        degree_in(p, &self.free) > self.free_degree
    }

    /// The basis images under the clearing of `powers`, formed at the first call for them
    /// (`f` is the function that asks, whose powers they cover).
    fn images_for(&self, powers: Vec<i64>, f: &Expr) -> Result<Rc<ClearedImages>, EngineError> {
        if let Some(images) = self.images.borrow().get(&powers) {
            return Ok(Rc::clone(images));
        }
        let clearing = Clearing::new(
            &self.atoms,
            &self.radicals,
            &self.parameters,
            self.integrals.iter().chain([f]),
        )?
        .expect("a search with denominator atoms or radicals");
        let images = clearing.apply_all(&self.integrals)?;
        let (rows, nrows, columns) = real_columns(&images, &self.angles, f.vars());
        let mut echelon = Echelon::new(nrows);
        for (k, column) in columns.iter().enumerate() {
            let independent = echelon.extend(k, column);
            debug_assert!(independent, "the basis integrals are independent");
        }
        let images = Rc::new(ClearedImages {
            clearing,
            rows,
            echelon,
        });
        self.images.borrow_mut().insert(powers, Rc::clone(&images));
        Ok(images)
    }
}

/// Raises each of `powers` to the power of `1/D_i` (or `1/r_i`) in `f`, if higher.
fn raise_to<'a>(powers: &mut [i64], atoms: impl Iterator<Item = &'a (Var, Expr)>, f: &Expr) {
    for ((v, _), n) in atoms.zip(powers.iter_mut()) {
        *n = (*n).max(-f.low_degree(*v).unwrap_or(0));
    }
}

/// The total degree of `f` in `vars`.
fn degree_in(f: &Expr, vars: &[Var]) -> i64 {
    f.terms()
        .map(|t| vars.iter().map(|&v| t.exponent(v)).sum::<i64>())
        .max()
        .unwrap_or(0)
}
