//! Division by one polynomial, `f = q·p + r`, in a monomial order on chosen variables: the
//! quotient `q` and the remainder `r`, none of whose terms is divisible by the leading monomial
//! of `p`. A single polynomial is a Gröbner basis of the ideal it generates, so the remainder
//! is the normal form of `f` modulo `(p)`: `f ∈ (p)` exactly when it is zero, and it is linear
//! in `f`. The order ([`DivisionOrder`]) is graded, then lexicographic, on the exponents of the
//! variables it names, in the order named; the other variables (angles, parameters) ride along
//! in the coefficients, so the divisor's leading coefficient must be a nonzero number, one term
//! with no other variable ([`DivisionRefusal::LeadingCoefficient`]).

use std::collections::BTreeMap;

use super::Poly;
use crate::error::AlgebraError;
use crate::number::{Coefficient, GaussianRational};
use crate::varset::Var;

/// A monomial order for [`Poly::divide_by`]: total degree in `variables`, then their
/// exponents lexicographically in the order given (the first the most significant), then the
/// whole exponent vector, which orders the terms that differ only in the other variables.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DivisionOrder {
    variables: Vec<Var>,
}

impl DivisionOrder {
    /// The graded lexicographic order on `variables`, the first the most significant.
    pub fn graded_lex(variables: &[Var]) -> Self {
        DivisionOrder {
            variables: variables.to_vec(),
        }
    }

    /// The variables ordered, the first the most significant.
    pub fn variables(&self) -> &[Var] {
        &self.variables
    }

    /// The key that sorts an exponent vector in this order (greater is higher).
    fn key(&self, exponents: &[i64]) -> OrderKey {
        let ordered: Vec<i64> = self
            .variables
            .iter()
            .map(|v| exponents[v.index()])
            .collect();
        (ordered.iter().sum(), ordered, exponents.to_vec())
    }

    /// Whether the monomial `lead` (a leading monomial: nonnegative, and zero outside the
    /// ordered variables) divides the monomial `exponents`, so that the quotient is a
    /// monomial with no negative power of an ordered variable.
    pub fn divides(&self, lead: &[i64], exponents: &[i64]) -> bool {
        self.variables
            .iter()
            .all(|v| exponents[v.index()] >= lead[v.index()])
    }
}

/// A monomial's place in a [`DivisionOrder`]: its degree in the ordered variables, their
/// exponents, and the whole exponent vector.
type OrderKey = (i64, Vec<i64>, Vec<i64>);

/// Why a polynomial cannot be divided by: it is zero, or its leading term in the order has a
/// coefficient that is not a number (another term with the same monomial in the ordered
/// variables, or other variables in the term), or it has a negative power of an ordered
/// variable.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum DivisionRefusal {
    /// The divisor is zero.
    #[error("division by zero")]
    Zero,
    /// The divisor's leading monomial in the ordered variables (its exponent vector, over all
    /// the variables) has a coefficient that holds other variables, parameters say.
    #[error("the leading coefficient is not a number: it holds other variables")]
    LeadingCoefficient {
        /// The leading monomial's exponents in the ordered variables, over all the variables.
        monomial: Vec<i64>,
    },
    /// The divisor has a negative power of the ordered variable at this index.
    #[error("the divisor has a negative power of an ordered variable")]
    NegativePower(usize),
    /// The quotient or the remainder passed a limit of the ring.
    #[error(transparent)]
    Algebra(#[from] AlgebraError),
}

/// The quotient and the remainder of [`Poly::divide_by`]: `f = quotient·p + remainder`.
#[derive(Clone, Debug)]
pub struct Division<C: Coefficient> {
    /// `q`.
    pub quotient: Poly<C>,
    /// `r`, no term of which the leading monomial of `p` divides.
    pub remainder: Poly<C>,
}

impl<C: Coefficient> Poly<C> {
    /// The leading term in `order`, its coefficient and exponent vector, when it has a number
    /// as coefficient (see [`DivisionRefusal`]).
    ///
    /// ```
    /// use trigpoly::{DivisionOrder, Expr, Vars};
    ///
    /// let vars = Vars::builder().poisson("M1").poisson("g1").parameter("c").build()?;
    /// let order = DivisionOrder::graded_lex(&[vars.lookup("M1").unwrap(), vars.lookup("g1").unwrap()]);
    /// let p = Expr::parse(&vars, "M1*g1 + c*g1^2 - 1")?;
    /// assert_eq!(p.leading_term(&order)?.1, vec![1, 1, 0]);
    /// // A parameter in the leading coefficient is refused.
    /// assert!(Expr::parse(&vars, "c*M1*g1 + g1")?.leading_term(&order).is_err());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn leading_term(&self, order: &DivisionOrder) -> Result<(C, Vec<i64>), DivisionRefusal> {
        let mut best: Option<(OrderKey, C, Vec<i64>)> = None;
        for t in self.terms() {
            let e = t.exponents();
            if let Some(v) = order.variables.iter().find(|v| e[v.index()] < 0) {
                return Err(DivisionRefusal::NegativePower(v.index()));
            }
            let key = order.key(&e);
            if best.as_ref().is_none_or(|b| key > b.0) {
                best = Some((key, t.coeff(), e));
            }
        }
        let (key, c, e) = best.ok_or(DivisionRefusal::Zero)?;
        let monomial: Vec<i64> = (0..e.len())
            .map(|i| match order.variables.iter().any(|v| v.index() == i) {
                true => e[i],
                false => 0,
            })
            .collect();
        // The leading coefficient is a number: the leading term holds no other variable, and
        // no other term has the same monomial in the ordered variables.
        let shared = self
            .terms()
            .filter(|t| order.key(&t.exponents()).1 == key.1)
            .count();
        if monomial != e || shared > 1 {
            return Err(DivisionRefusal::LeadingCoefficient { monomial });
        }
        Ok((c, e))
    }

    /// `self = q·divisor + r` in `order`: the quotient and the remainder, none of whose terms
    /// the divisor's leading monomial divides. Exact (no term is dropped or rounded); the
    /// remainder is the normal form of `self` modulo the ideal `(divisor)`.
    ///
    /// ```
    /// use trigpoly::{DivisionOrder, Expr, Vars};
    ///
    /// let vars = Vars::builder().poisson("x").poisson("y").build()?;
    /// let order = DivisionOrder::graded_lex(&[vars.lookup("x").unwrap(), vars.lookup("y").unwrap()]);
    /// let p = Expr::parse(&vars, "x*y - 1")?;
    /// let f = Expr::parse(&vars, "x^2*y + y + 3")?;
    /// let d = f.divide_by(&p, &order)?;
    /// assert_eq!(d.quotient, Expr::parse(&vars, "x")?);
    /// assert_eq!(d.remainder, Expr::parse(&vars, "x + y + 3")?);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn divide_by(
        &self,
        divisor: &Self,
        order: &DivisionOrder,
    ) -> Result<Division<C>, DivisionRefusal> {
        self.same_vars(divisor)?;
        let (lead_coeff, lead) = divisor.leading_term(order)?;
        let lead_inverse = lead_coeff
            .to_gaussian()
            .try_inv()
            .ok_or(DivisionRefusal::Zero)?;
        // The divisor's other terms, subtracted at each step.
        let tail: Vec<(GaussianRational, Vec<i64>)> = divisor
            .terms()
            .map(|t| (t.coeff().to_gaussian(), t.exponents()))
            .filter(|(_, e)| *e != lead)
            .collect();
        // What is left to divide, by key in the order: the highest term is taken first, and a
        // step adds only lower ones (the tail is below the lead in the order, and
        // multiplying by a monomial keeps the order).
        let mut left: BTreeMap<OrderKey, GaussianRational> = BTreeMap::new();
        let add =
            |left: &mut BTreeMap<OrderKey, GaussianRational>, c: GaussianRational, e: &[i64]| {
                let entry = left.entry(order.key(e)).or_default();
                *entry = &*entry + &c;
            };
        for t in self.terms() {
            add(&mut left, t.coeff().to_gaussian(), &t.exponents());
        }
        let (mut quotient, mut remainder) = (Vec::new(), Vec::new());
        while let Some(((_, _, e), c)) = left.pop_last() {
            if c.is_zero() {
                continue;
            }
            if !order.divides(&lead, &e) {
                remainder.push((c, e));
                continue;
            }
            let factor = &c * &lead_inverse;
            let shift: Vec<i64> = e.iter().zip(&lead).map(|(a, b)| a - b).collect();
            for (tc, te) in &tail {
                let product: Vec<i64> = te.iter().zip(&shift).map(|(a, b)| a + b).collect();
                add(&mut left, -(&factor * tc), &product);
            }
            quotient.push((factor, shift));
        }
        let into_field = |terms: Vec<(GaussianRational, Vec<i64>)>| {
            terms.into_iter().map(|(c, e)| {
                let c = C::from_gaussian(&c).expect("quotients of the field's elements");
                (c, e)
            })
        };
        Ok(Division {
            quotient: Poly::from_terms(&self.vars, into_field(quotient))?,
            remainder: Poly::from_terms(&self.vars, into_field(remainder))?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Expr, Vars};

    fn vars() -> Vars {
        Vars::builder()
            .poisson("M1")
            .poisson("M2")
            .poisson("M3")
            .poisson("g1")
            .poisson("g2")
            .poisson("g3")
            .parameter("c")
            .angle("t")
            .build()
            .unwrap()
    }

    fn order(vars: &Vars) -> DivisionOrder {
        let phase: Vec<Var> = ["M1", "M2", "M3", "g1", "g2", "g3"]
            .iter()
            .map(|n| vars.lookup(n).unwrap())
            .collect();
        DivisionOrder::graded_lex(&phase)
    }

    /// `f = q·p + r` exactly, and no term of `r` is divisible by the leading monomial: for
    /// the Goryachev–Chaplygin top's area integral, with a parameter and an angle in the
    /// dividend riding along in the coefficients.
    #[test]
    fn division_is_exact_and_leaves_a_normal_form() {
        let vars = vars();
        let order = order(&vars);
        let p = Expr::parse(&vars, "M1*g1 + M2*g2 + M3*g3").unwrap();
        for f in [
            "-c*M2*(M1*g1 + M2*g2 + M3*g3)",
            "M1^3*g1^2 + c*M1*g1*cos(t) - M2 + 7/3",
            "M1*g1*M2*g2 + M3^4",
            "1/M2 * M1*g1",
            "0",
        ] {
            let f = Expr::parse(&vars, f).unwrap();
            let d = f.divide_by(&p, &order).unwrap();
            let back = d
                .quotient
                .checked_mul(&p)
                .unwrap()
                .checked_add(&d.remainder)
                .unwrap();
            assert_eq!(back, f, "{f}");
            let (_, lead) = p.leading_term(&order).unwrap();
            for t in d.remainder.terms() {
                assert!(
                    !order.divides(&lead, &t.exponents()),
                    "{f}: {}",
                    d.remainder
                );
            }
        }
        // In the ideal: the remainder is zero and the quotient the cofactor.
        let f = Expr::parse(&vars, "-c*M2*(M1*g1 + M2*g2 + M3*g3)").unwrap();
        let d = f.divide_by(&p, &order).unwrap();
        assert!(d.remainder.is_zero());
        assert_eq!(d.quotient, Expr::parse(&vars, "-c*M2").unwrap());
    }

    /// What is not in the ideal keeps a nonzero remainder: `M1` is not a multiple of the
    /// area integral, nor is `M1 g1` (its leading monomial, but not the whole polynomial).
    #[test]
    fn a_polynomial_outside_the_ideal_has_a_nonzero_remainder() {
        let vars = vars();
        let order = order(&vars);
        let p = Expr::parse(&vars, "M1*g1 + M2*g2 + M3*g3").unwrap();
        for f in ["M1", "M1*g1", "M1*g1 + M2*g2"] {
            let f = Expr::parse(&vars, f).unwrap();
            assert!(!f.divide_by(&p, &order).unwrap().remainder.is_zero(), "{f}");
        }
        // The remainder of M1 g1 is its normal form −M2 g2 − M3 g3.
        let f = Expr::parse(&vars, "M1*g1").unwrap();
        let r = f.divide_by(&p, &order).unwrap().remainder;
        assert_eq!(r, Expr::parse(&vars, "-M2*g2 - M3*g3").unwrap());
    }

    /// A divisor whose leading coefficient is not a number is refused, and so are zero and a
    /// negative power of an ordered variable.
    #[test]
    fn divisors_without_a_number_as_leading_coefficient_are_refused() {
        let vars = vars();
        let order = order(&vars);
        let f = Expr::parse(&vars, "M1").unwrap();
        let refused = |p: &str| f.divide_by(&Expr::parse(&vars, p).unwrap(), &order).err();
        assert!(matches!(
            refused("c*M1*g1 + M2"),
            Some(DivisionRefusal::LeadingCoefficient { .. })
        ));
        assert!(matches!(
            refused("M1*g1 + c*M1*g1 + M2"),
            Some(DivisionRefusal::LeadingCoefficient { .. })
        ));
        assert!(matches!(
            refused("M1*cos(t) + M2"),
            Some(DivisionRefusal::LeadingCoefficient { .. })
        ));
        assert_eq!(refused("0"), Some(DivisionRefusal::Zero));
        assert!(matches!(
            refused("1/M1 + M2"),
            Some(DivisionRefusal::NegativePower(_))
        ));
        // A parameter below the leading term is a coefficient like any other.
        assert!(refused("M1*g1 + c*M2").is_none());
    }
}
