//! Complex structure: conjugation (every variable is real, so `e^{ikθ} ↦ e^{−ikθ}`), real and
//! imaginary parts, and the embedding Q ⊂ Q(i).

use super::Poly;
use crate::error::AlgebraError;
use crate::number::{
    Coefficient, GaussianInteger, GaussianRational, Integer, IntegerRing, Rational,
};
use crate::varset::VarKind;

impl<C: Coefficient> Poly<C> {
    /// The complex conjugate: coefficients conjugated, every angle exponent negated.
    pub fn conj(&self) -> Self {
        let angles: Vec<usize> = self.vars.angles().map(|v| v.index()).collect();
        let layout = self.layout();
        let w = self.words();
        let coeffs: Vec<C::Int> = self.coeffs.iter().map(|c| c.conj()).collect();
        if angles.is_empty() {
            return Self::from_sorted(&self.vars, self.content.clone(), self.exps.clone(), coeffs);
        }
        // e^{ikθ} ↦ e^{−ikθ}: translate each angle field by −2k.
        let mut exps = self.exps.clone();
        let mut unit = vec![0u64; w];
        for m in exps.chunks_exact_mut(w) {
            for &j in &angles {
                let e = layout.get(m, j);
                if e != 0 {
                    layout.unit(j, -2 * e, &mut unit);
                    let old = m.to_vec();
                    layout.mul_into(&old, &unit, m);
                }
            }
        }
        Self::from_distinct_unsorted(&self.vars, self.content.clone(), exps, coeffs)
    }

    /// Whether the function is real-valued: `conj(f) = f`.
    pub fn is_real(&self) -> bool {
        self.conj() == *self
    }

    /// The real part `(f + conj f)/2`.
    pub fn re(&self) -> Self {
        (self + &self.conj()) * &Rational::new(1, 2)
    }

    /// The imaginary part `(f − conj f)/(2i)`; needs Q(i) unless `f` is real.
    pub fn im(&self) -> Result<Self, AlgebraError> {
        let d = self - &self.conj();
        // 1/(2i) = −i/2
        Ok(d.mul_i()? * &Rational::new(-1, 2))
    }

    /// Whether an angle appears.
    pub fn has_angles(&self) -> bool {
        self.vars.angles().any(|v| self.contains(v))
    }

    /// Whether no angle or non-angle variable of kind `kind` appears.
    pub fn is_free_of(&self, kind: VarKind) -> bool {
        self.vars
            .vars()
            .filter(|&v| self.vars.variable(v).kind() == kind)
            .all(|v| !self.contains(v))
    }
}

impl Poly<Rational> {
    /// The same polynomial over Q(i).
    pub fn to_gaussian(&self) -> Poly<GaussianRational> {
        let (content, exps, coeffs) = self.raw_parts();
        let coeffs = coeffs
            .iter()
            .map(|c| GaussianInteger::from_integer(c.clone()))
            .collect();
        Poly::from_sorted(self.vars(), content.clone(), exps.to_vec(), coeffs)
    }
}

impl Poly<GaussianRational> {
    /// The same polynomial over Q, if it has no angle and every coefficient is real.
    pub fn to_rational(&self) -> Option<Poly<Rational>> {
        if self.has_angles() {
            return None;
        }
        let (content, exps, coeffs) = self.raw_parts();
        let real: Option<Vec<Integer>> = coeffs
            .iter()
            .map(|c| c.im.is_zero().then(|| c.re.clone()))
            .collect();
        Some(Poly::from_sorted(
            self.vars(),
            content.clone(),
            exps.to_vec(),
            real?,
        ))
    }
}
