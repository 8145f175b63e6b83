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
        let terms: Vec<(Vec<u64>, C::Int)> = (0..self.len())
            .map(|k| {
                let m = self.exp(k);
                let key = if angles.is_empty() {
                    m.to_vec()
                } else {
                    let mut e: Vec<i64> = (0..self.vars.len()).map(|j| layout.get(m, j)).collect();
                    for &j in &angles {
                        e[j] = -e[j];
                    }
                    let mut packed = vec![0u64; w];
                    layout.pack(&e, &mut packed);
                    packed
                };
                (key, self.coeffs[k].conj())
            })
            .collect();
        Self::from_unsorted(&self.vars, self.content.clone(), terms)
    }

    /// Whether the function is real-valued: `conj(f) = f`.
    pub fn is_real(&self) -> bool {
        self.conj() == *self
    }

    /// The real part `(f + conj f)/2`.
    pub fn re(&self) -> Self {
        (self + &self.conj()).scale_rational(&Rational::new(1, 2))
    }

    /// The imaginary part `(f − conj f)/(2i)`; needs Q(i) unless `f` is real.
    pub fn im(&self) -> Result<Self, AlgebraError> {
        let d = self - &self.conj();
        // 1/(2i) = −i/2
        Ok(d.mul_i()?.scale_rational(&Rational::new(-1, 2)))
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
    /// The same polynomial over Q, if every coefficient (in the `e^{ikθ}` basis) is real.
    pub fn to_rational(&self) -> Option<Poly<Rational>> {
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
