//! With denominator atoms or radicals, the space's monomials are not independent functions
//! (`x/(x − y) − y/(x − y) = 1`, `r²/r = r`... and `x²/r + y²/r = r` for `r = √(x² + y²)`):
//! the choice of those independent of the simpler ones.

use rustc_hash::FxHashSet;

use trigpoly::{Expr, GaussianRational, Rational, Var, VarKind, Vars};

use crate::clearing::Clearing;
use crate::error::EngineError;
use crate::modular::kernel;

use super::parameters::free_parameters;
use super::problem::{real_columns, Unknown};

/// With denominator atoms or radicals the monomials of the space are not independent functions
/// (`x/(x − y) − y/(x − y) = 1`, `x²/r + y²/r = r`): the monomials `φ` (without angles) whose
/// functions are
/// independent of the simpler ones before them, in the order of [`Unknown::degrees`], decided
/// exactly on their images under one [`Clearing`], which is injective. The space they span is
/// the whole space's, and each of its functions has one set of coordinates in them. Each
/// denominator must be free of the angles (a radicand is), so that the same monomials are
/// independent times any `cos k·θ` or `sin k·θ`. When every denominator and radicand is a
/// polynomial in the coordinates and parameters, clearing and reducing commute with a factor
/// in the momenta, the Poisson variables and the symbolic parameters that no denominator or
/// radicand holds, and the monomials of each such factor are compared among themselves only:
/// the choice is made once, on the monomials in the coordinates, the radicals, the
/// denominators and the symbolic parameters they hold, in the same order.
pub(super) fn independent_as_functions(
    vars: &Vars,
    atoms: &[(Var, Expr)],
    radicals: &[(Var, Expr)],
    parameters: &[(Var, Rational)],
    mut phases: Vec<Unknown>,
) -> Result<Vec<Unknown>, EngineError> {
    check_denominators_free_of_angles(vars, atoms)?;
    let part = ChoicePart::new(vars, atoms, radicals, parameters);
    let parts: Vec<Unknown> = phases.iter().map(|u| part.of(u)).collect();
    let kept = independent_parts(vars, atoms, radicals, parameters, parts)?;
    phases.retain(|u| kept.contains(&part.of(u).phase));
    Ok(phases)
}

/// Refuses a denominator that holds an angle: the monomials independent without angles must
/// stay so times any `cos k·θ` or `sin k·θ`.
fn check_denominators_free_of_angles(
    vars: &Vars,
    atoms: &[(Var, Expr)],
) -> Result<(), EngineError> {
    if let Some((v, _)) = atoms
        .iter()
        .find(|(_, d)| vars.angles().any(|a| d.contains(a)))
    {
        return Err(EngineError::Invalid(format!(
            "the search takes denominators free of the angles, and {} has one",
            vars.variable(*v).unicode()
        )));
    }
    Ok(())
}

/// The part of a monomial that the choice is made on: when every denominator and radicand
/// is a polynomial in the coordinates and parameters, the monomial without the variables
/// that only multiply (all but the coordinates, the denominators and the radicals, and the
/// parameters too unless a denominator or radicand holds a symbolic one); otherwise the
/// whole monomial.
struct ChoicePart {
    /// Whether every denominator and radicand is a polynomial in the coordinates and
    /// parameters.
    in_coordinates: bool,
    /// The indices of the variables left out of the part.
    apart: Vec<usize>,
    /// The indices of the symbolic parameters compared with the coordinates, whose degree is
    /// the part's parameters degree.
    held: Vec<usize>,
}

impl ChoicePart {
    /// The part for the monomials over `vars`, with these denominator atoms and radicals and
    /// the parameters fixed at `parameters`.
    fn new(
        vars: &Vars,
        atoms: &[(Var, Expr)],
        radicals: &[(Var, Expr)],
        parameters: &[(Var, Rational)],
    ) -> Self {
        let kind = |v: Var| vars.variable(v).kind();
        let in_coordinates = atoms.iter().chain(radicals).all(|(_, d)| {
            vars.vars()
                .filter(|&v| d.contains(v))
                .all(|v| matches!(kind(v), VarKind::Coordinate | VarKind::Parameter))
        });
        // When a denominator or radicand holds a parameter kept symbolic, the parameters are
        // compared with the coordinates (`a² = r² − x² + 2ax − y²` for `r = √((x − a)² + y²)`),
        // all of them, since their degree is bounded together (`k·a³/r` may be past it where
        // `k·a x²/r` is not); otherwise they only multiply, like the momenta.
        let free = free_parameters(vars, atoms, radicals);
        let holds_parameters = vars.vars().any(|v| {
            kind(v) == VarKind::Parameter
                && !free.contains(&v)
                && parameters.iter().all(|p| p.0 != v)
        });
        let held = |v: Var| holds_parameters && kind(v) == VarKind::Parameter;
        let apart: Vec<usize> = match in_coordinates {
            true => vars
                .vars()
                .filter(|&v| {
                    !matches!(
                        kind(v),
                        VarKind::Coordinate | VarKind::Denominator | VarKind::Radical
                    ) && !held(v)
                })
                .map(|v| v.index())
                .collect(),
            false => Vec::new(),
        };
        let held: Vec<usize> = vars
            .vars()
            .filter(|&v| held(v))
            .map(|v| v.index())
            .collect();
        ChoicePart {
            in_coordinates,
            apart,
            held,
        }
    }

    /// The part of `u` the choice is made on.
    fn of(&self, u: &Unknown) -> Unknown {
        if !self.in_coordinates {
            return u.clone();
        }
        let mut phase = u.phase.clone();
        for &i in &self.apart {
            phase[i] = 0;
        }
        Unknown {
            parameters_degree: self.held.iter().map(|&i| phase[i]).sum(),
            phase,
            momenta_degree: 0,
            poisson_degree: 0,
            ..u.clone()
        }
    }
}

/// The monomials of `parts` (without angles) independent as functions of the simpler ones
/// before them, in the order of [`Unknown::degrees`]: decided exactly on their images under
/// one [`Clearing`].
fn independent_parts(
    vars: &Vars,
    atoms: &[(Var, Expr)],
    radicals: &[(Var, Expr)],
    parameters: &[(Var, Rational)],
    mut parts: Vec<Unknown>,
) -> Result<FxHashSet<Vec<i64>>, EngineError> {
    // Without angles, in the order of the unknowns.
    parts.sort_by(|a, b| {
        a.degrees()
            .cmp(&b.degrees())
            .then_with(|| a.phase.cmp(&b.phase))
    });
    parts.dedup_by(|a, b| a.phase == b.phase);
    let monomials = parts
        .iter()
        .map(|u| Expr::from_terms(vars, vec![(GaussianRational::from(1), u.phase.clone())]))
        .collect::<Result<Vec<Expr>, _>>()?;
    let clearing = Clearing::new(atoms, radicals, parameters, monomials.iter())?
        .expect("the space has denominator atoms or radicals");
    let (_, nrows, columns) = real_columns(&clearing.apply_all(&monomials)?, &[], vars);
    // A monomial is kept when it is no combination of those before it: the columns the exact
    // kernel leaves out, whose vectors are `e_j − Σ_{i<j} c_i e_i`, one for each column `j`
    // that depends on the earlier ones (found modulo p and checked over Q, a fifth of a search
    // with denominators where an elimination over Q took it).
    let dependent: FxHashSet<usize> = kernel(&columns, nrows)
        .iter()
        .filter_map(|v| v.iter().map(|(j, _)| *j).max())
        .collect();
    Ok(parts
        .into_iter()
        .enumerate()
        .filter(|(j, _)| !dependent.contains(j))
        .map(|(_, u)| u.phase)
        .collect())
}
