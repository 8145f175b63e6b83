//! Each basis element made primitive and real, proved at the fixed values, lifted to symbolic
//! parameters and proved again.

use trigpoly::{Expr, Rational, Var, VarKind};

use crate::claim::Condition;
use crate::error::EngineError;
use crate::modular::SparseVec;
use crate::scaling::{Lifter, Scaling};
use crate::system::System;

/// The entry of `v` at its last unknown, its lead: a kernel vector ends at its own unknown, and
/// uses only earlier ones.
pub(super) fn lead<F>(v: &SparseVec<F>) -> Option<&(usize, F)> {
    v.iter().max_by_key(|x| x.0)
}

/// The vector scaled to coprime integers, its last (leading) entry positive.
pub(super) fn primitive_vector(v: &SparseVec<Rational>) -> SparseVec<Rational> {
    let mut den = trigpoly::Integer::from(1);
    let mut num = trigpoly::Integer::from(0);
    for (_, x) in v {
        den = den.lcm(&x.denom());
        num = num.gcd(&x.numer());
    }
    let negative = lead(v).is_some_and(|l| l.1.sign() == std::cmp::Ordering::Less);
    let mut scale = Rational::from(den) / Rational::from(num);
    if negative {
        scale = -scale;
    }
    v.iter().map(|(j, x)| (*j, x * &scale)).collect()
}

/// Lifts an integral found at fixed values and proves `{F, H} = 0` symbolically (after the
/// condition); `None` if the lift does not exist or is not an integral.
pub fn lift_and_prove(
    system: &System,
    condition: Option<&Condition>,
    lifter: &Lifter,
    scaling: &Scaling,
    fixed: &Expr,
    reference: Option<&[i64]>,
) -> Result<Option<Expr>, EngineError> {
    let Some(f) = lifter.lift(scaling, fixed, reference)? else {
        return Ok(None);
    };
    // Coprime integer coefficients again (fixed values other than 1 leave a common factor).
    let f = real_primitive(&f);
    Ok(flow_vanishes(system, condition, &f)?.then_some(f))
}

/// Whether `{f, H} = 0` for every value of the parameters (after the condition).
pub(super) fn flow_vanishes(
    system: &System,
    condition: Option<&Condition>,
    f: &Expr,
) -> Result<bool, EngineError> {
    let flow = match condition {
        Some(c) => system.flow_when(f, c)?,
        None => system.flow(f)?,
    };
    Ok(flow.vanishes()?)
}

/// A real function scaled so that its coefficients in the basis `cos kθ, sin kθ` are coprime
/// integers (the sign kept): in the `e^{ikθ}` basis those are twice the coefficients of
/// `e^{±ikθ}` for `k ≠ 0`.
pub(super) fn real_primitive(f: &Expr) -> Expr {
    let vars = f.vars();
    let angles: Vec<Var> = vars.angles().collect();
    let mut g = Rational::zero();
    for t in f.terms() {
        let c = t.coeff();
        let factor = if angles.iter().any(|v| t.exponent(*v) != 0) {
            Rational::from(2)
        } else {
            Rational::one()
        };
        for x in [&c.re, &c.im] {
            if !x.is_zero() {
                g = Rational::content_gcd(&g, &(x * &factor));
            }
        }
    }
    match g.abs().try_inv() {
        Some(inv) => f.scale_rational(&inv),
        None => f.clone(),
    }
}

/// Whether `e` depends on no variable of phase space (parameters only, or a number).
pub(crate) fn is_phase_free(e: &Expr) -> bool {
    let vars = e.vars();
    vars.vars()
        .filter(|v| vars.variable(*v).kind() != VarKind::Parameter)
        .all(|v| !e.contains(v))
}
