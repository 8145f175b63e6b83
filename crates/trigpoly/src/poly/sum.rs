//! Sums of products `Σ ± a_k·b_k` in one accumulation: the kernel of the Poisson bracket.
//!
//! Each product with a short factor becomes sorted streams (shifted copies of the long factor);
//! all streams are brought to one rational content, merged pairwise like the levels of a tree,
//! and normalised once, instead of normalising every product and every partial sum.

use super::mul::{merge_tree, SMALL_SIDE};
use super::Poly;
use crate::error::AlgebraError;
use crate::number::{Coefficient, IntegerRing, Rational};

impl<C: Coefficient> Poly<C> {
    /// `Σ_k ± a_k · b_k` (minus where the flag is `true`), exactly as the sum of the products,
    /// computed with one accumulation and one normalization.
    ///
    /// ```
    /// use trigpoly::{Poly, Rational, VarSet};
    /// let vars = VarSet::builder().coordinate("x").momentum("p").build().unwrap();
    /// let p = |s: &str| Poly::<Rational>::parse(&vars, s).unwrap();
    /// let (x, px) = (p("x + 1"), p("p^2 - x"));
    /// let sum = Poly::sum_of_products(&[(&x, &px, false), (&px, &px, true)]).unwrap();
    /// assert_eq!(sum, &(&x * &px) - &(&px * &px));
    /// ```
    pub fn sum_of_products(terms: &[(&Self, &Self, bool)]) -> Result<Self, AlgebraError> {
        let Some(first) = terms.first() else {
            return Err(AlgebraError::Invalid(
                "an empty sum of products has no variable set".into(),
            ));
        };
        let vars = first.0.vars.clone();
        let mut streams: Vec<(Rational, Self)> = Vec::new();
        for &(a, b, negate) in terms {
            a.same_vars(b)?;
            first.0.same_vars(a)?;
            if a.is_zero() || b.is_zero() {
                continue;
            }
            let (small, big) = if a.len() <= b.len() { (a, b) } else { (b, a) };
            if small.len() <= SMALL_SIDE {
                small.check_product_exponents(big)?;
                let mut q = &a.content * &b.content;
                if negate {
                    q = -q;
                }
                for k in 0..small.len() {
                    let (exps, coeffs) = big.shifted(small.exp(k), &small.coeffs[k]);
                    streams.push((q.clone(), Self::raw(&vars, exps, coeffs)));
                }
            } else {
                let p = a.checked_mul(b)?;
                let q = if negate {
                    -p.content.clone()
                } else {
                    p.content.clone()
                };
                streams.push((q, Self::raw(&vars, p.exps, p.coeffs)));
            }
        }
        if streams.is_empty() {
            return Ok(Self::zero(&vars));
        }
        let d = streams
            .iter()
            .skip(1)
            .fold(streams[0].0.abs(), |g, (q, _)| Rational::content_gcd(&g, q));
        let parts: Vec<Self> = streams
            .into_iter()
            .map(|(q, mut s)| {
                let scale = (&q / &d).numer();
                if !scale.is_one() {
                    s.coeffs.iter_mut().for_each(|c| *c = c.scale(&scale));
                }
                s
            })
            .collect();
        let total = merge_tree(parts);
        Self::check_terms(&vars, total.len())?;
        Ok(Self::drop_zeros_and_normalize(
            &vars,
            d,
            total.exps,
            total.coeffs,
        ))
    }
}
