//! Partial derivatives. For a variable, `∂(c·v^e·m)/∂v = e·c·v^(e−1)·m`; for an angle, with
//! `cos θ = (e^{iθ} + e^{−iθ})/2` and `sin θ = (e^{iθ} − e^{−iθ})/(2i)`,
//! `∂e^{ikθ}/∂θ = ik·e^{ikθ}`, which is `−sin θ ∂/∂cos θ + cos θ ∂/∂sin θ` on the normal form.

use super::{check_exponent, Poly};
use crate::error::AlgebraError;
use crate::number::{Coefficient, Integer, IntegerRing};
use crate::varset::{Var, VarKind};

impl<C: Coefficient> Poly<C> {
    /// `∂self/∂v`. For an angle `θ` this is `∂/∂θ`, which needs Q(i) coefficients.
    pub fn derivative(&self, v: Var) -> Result<Self, AlgebraError> {
        let j = v.index();
        let layout = self.layout();
        let angle = self.vars.variable(v).kind() == VarKind::Angle;
        let limit = self.vars.limits().max_degree as i64;
        let mut exps = Vec::with_capacity(self.exps.len());
        let mut coeffs = Vec::with_capacity(self.len());
        // Lowering the exponent of v by one is a subtraction in one field of one word.
        let (word, shift) = layout.field(j);
        for k in 0..self.len() {
            let m = self.exp(k);
            let e = layout.get(m, j);
            if e == 0 {
                continue;
            }
            let c = self.coeffs[k].scale(&Integer::from(e));
            if angle {
                let ci = c.try_mul_i().ok_or_else(|| {
                    AlgebraError::NeedsGaussian(format!(
                        "the derivative by the angle {}",
                        self.vars.variable(v).unicode()
                    ))
                })?;
                exps.extend_from_slice(m);
                coeffs.push(ci);
            } else {
                if (e - 1).abs() > limit {
                    check_exponent(&self.vars, v, e - 1)?;
                }
                let start = exps.len();
                exps.extend_from_slice(m);
                exps[start + word] = exps[start + word].wrapping_sub(1u64 << shift);
                coeffs.push(c);
            }
        }
        Ok(Self::from_sorted(
            &self.vars,
            self.content.clone(),
            exps,
            coeffs,
        ))
    }
}
