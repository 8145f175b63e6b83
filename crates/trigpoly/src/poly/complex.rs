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
        let layout = self.layout();
        let w = self.words();
        let fields: Vec<(usize, u32)> = self
            .vars
            .angles()
            .map(|v| layout.field(v.index()))
            .collect();
        // Conjugation keeps the components' sizes: the coefficients stay coprime.
        let coeffs: Vec<C::Int> = self.coeffs.iter().map(|c| c.conj()).collect();
        // e^{ikθ} ↦ e^{−ikθ}: subtract 2k in each angle's field (wrapping: exact, since −k is
        // within the limit as k is).
        let mut exps = self.exps.clone();
        if !fields.is_empty() {
            for m in exps.chunks_exact_mut(w) {
                for &field in &fields {
                    let k = layout.read(m, field);
                    m[field.0] = m[field.0].wrapping_sub(((2 * k) as u64) << field.1);
                }
            }
        }
        // Terms that share their angle exponents (a `K_{m,n}`, say) keep their order.
        if exps.chunks_exact(w).is_sorted_by(|a, b| a > b) {
            return Self::from_sorted_coprime(&self.vars, self.content.clone(), exps, coeffs);
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
