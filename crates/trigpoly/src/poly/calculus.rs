//! Partial derivatives. For a variable, `∂(c·v^e·m)/∂v = e·c·v^(e−1)·m`; for an angle, with
//! `cos θ = (e^{iθ} + e^{−iθ})/2` and `sin θ = (e^{iθ} − e^{−iθ})/(2i)`,
//! `∂e^{ikθ}/∂θ = ik·e^{ikθ}`, which is `−sin θ ∂/∂cos θ + cos θ ∂/∂sin θ` on the normal form.

use super::{check_exponent, Poly};
use crate::error::AlgebraError;
use crate::number::{Coefficient, Integer, IntegerRing};
use crate::varset::{Var, VarKind};

/// The terms of a derivative before normalisation (see [`Poly::derivative_terms`]).
pub(crate) struct DerivativeTerms<I> {
    /// The indices of the terms that contain the variable.
    pub rows: Vec<usize>,
    /// Their coefficients times the exponent (times `i` for an angle).
    pub coeffs: Vec<I>,
    /// The word holding the variable's field.
    pub word: usize,
    /// What to subtract from that word: one in the variable's field, or zero for an angle
    /// (`e^{ikθ}` keeps its exponent).
    pub lower: u64,
}

impl<C: Coefficient> Poly<C> {
    /// `∂self/∂v`. For an angle `θ` this is `∂/∂θ`, which needs Q(i) coefficients.
    pub fn derivative(&self, v: Var) -> Result<Self, AlgebraError> {
        let d = self.derivative_terms(v)?;
        let mut exps = Vec::with_capacity(d.rows.len() * self.words());
        for &k in &d.rows {
            let start = exps.len();
            exps.extend_from_slice(self.exp(k));
            exps[start + d.word] = exps[start + d.word].wrapping_sub(d.lower);
        }
        Ok(Self::from_sorted(
            &self.vars,
            self.content.clone(),
            exps,
            d.coeffs,
        ))
    }

    /// The terms of `∂self/∂v` over the integer ring, with the content of `self`: which terms
    /// contain `v`, their new coefficients, and how their monomials change. The derivative
    /// and the bracket's fused kernel (`sum.rs`) both build on this.
    pub(crate) fn derivative_terms(&self, v: Var) -> Result<DerivativeTerms<C::Int>, AlgebraError> {
        let j = self.vars.checked_index(v)?;
        let layout = self.layout();
        let angle = self.vars.variable(v).kind() == VarKind::Angle;
        let limit = self.vars.limits().max_degree as i64;
        let field = layout.field(j);
        // Sized exactly: the bracket's kernel keeps these coefficients as a stream.
        let count = self
            .exps
            .chunks_exact(layout.words)
            .filter(|m| layout.read(m, field) != 0)
            .count();
        let mut rows = Vec::with_capacity(count);
        let mut coeffs = Vec::with_capacity(count);
        for (k, m) in self.exps.chunks_exact(layout.words).enumerate() {
            let e = layout.read(m, field);
            if e == 0 {
                continue;
            }
            let c = self.coeffs[k].scale(&Integer::from(e));
            if angle {
                coeffs.push(c.try_mul_i().ok_or_else(|| {
                    AlgebraError::NeedsGaussian(format!(
                        "the derivative by the angle {}",
                        self.vars.variable(v).unicode()
                    ))
                })?);
            } else {
                if (e - 1).abs() > limit {
                    check_exponent(&self.vars, v, e - 1)?;
                }
                coeffs.push(c);
            }
            rows.push(k);
        }
        // Lowering the exponent of v by one is a subtraction in one field of one word.
        let (word, shift) = field;
        Ok(DerivativeTerms {
            rows,
            coeffs,
            word,
            lower: if angle { 0 } else { 1u64 << shift },
        })
    }
}
