//! Integer powers: any power of a single term, non-negative powers of anything else.

use super::{check_exponent, Poly};
use crate::error::AlgebraError;
use crate::number::Coefficient;

impl<C: Coefficient> Poly<C> {
    /// `self^e`. Negative `e` only for a single term (`Err(NegativePower)` otherwise); `0^e`
    /// with `e < 0` is `Err(DivisionByZero)`; `f^0 = 1` for every `f`, zero included.
    pub fn checked_pow(&self, e: i64) -> Result<Self, AlgebraError> {
        if e == 0 {
            return Ok(Self::one(&self.vars));
        }
        if self.is_zero() {
            return if e < 0 {
                Err(AlgebraError::DivisionByZero)
            } else {
                Ok(self.clone())
            };
        }
        // Exponent bounds of the result, checked before any work.
        for (v, (lo, hi)) in self.vars.vars().zip(self.bounds()) {
            check_exponent(&self.vars, v, lo.saturating_mul(e))?;
            check_exponent(&self.vars, v, hi.saturating_mul(e))?;
        }
        if self.is_monomial() {
            // A single term's coefficient grows without any new term: bound its size.
            let z = C::from_parts(&self.content, &self.coeffs[0]).to_gaussian();
            let bits = [&z.re, &z.im]
                .iter()
                .map(|q| q.numer().bits().max(q.denom().bits()))
                .max()
                .unwrap_or(1);
            if bits.saturating_mul(e.unsigned_abs()) > MAX_COEFFICIENT_BITS {
                return Err(AlgebraError::Invalid(format!(
                    "the coefficient of this power would have more than {MAX_COEFFICIENT_BITS} bits"
                )));
            }
            return Ok(self.monomial_pow(e));
        }
        if e < 0 {
            return Err(AlgebraError::NegativePower(self.to_string()));
        }
        if self.len() <= 6 {
            // Repeated multiplication by a short polynomial: each step shifts and merges.
            let mut acc = self.clone();
            for _ in 1..e {
                acc = acc.checked_mul(self)?;
            }
            return Ok(acc);
        }
        let mut base = self.clone();
        let mut k = e as u64;
        let mut acc: Option<Self> = None;
        loop {
            if k & 1 == 1 {
                acc = Some(match acc {
                    None => base.clone(),
                    Some(a) => a.checked_mul(&base)?,
                });
            }
            k >>= 1;
            if k == 0 {
                break;
            }
            base = base.checked_mul(&base)?;
        }
        Ok(acc.expect("e > 0"))
    }

    /// `(c·m)^e` for a single term (bounds already checked).
    fn monomial_pow(&self, e: i64) -> Self {
        let c = C::from_parts(&self.content, &self.coeffs[0]);
        let ce = pow_field(&c, e);
        let layout = self.layout();
        let exps: Vec<i64> = (0..self.vars.len())
            .map(|j| layout.get(self.exp(0), j) * e)
            .collect();
        let mut w = vec![0u64; self.words()];
        layout.pack(&exps, &mut w);
        let (content, n) = ce.split();
        Poly {
            vars: self.vars.clone(),
            content,
            exps: w,
            coeffs: vec![n],
        }
    }
}

/// The largest coefficient a power of a single term may produce, in bits (2 MiB of digits).
const MAX_COEFFICIENT_BITS: u64 = 1 << 24;

/// `c^e` in the field (c nonzero).
pub(crate) fn pow_field<C: Coefficient>(c: &C, e: i64) -> C {
    let z = c.to_gaussian().pow(e).expect("nonzero base");
    C::from_gaussian(&z).expect("powers stay in the field")
}
