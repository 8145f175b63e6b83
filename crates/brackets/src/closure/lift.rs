//! Lifting what the closure found at fixed parameter values back to symbolic parameters
//! (`LiftContext`: each coefficient a Laurent monomial by homogeneity), and its symbolic check.

use std::collections::HashMap;

use trigpoly::{Expr, GaussianRational, Rational, Var, VarKind, Vars};

use crate::error::EngineError;
use crate::modular::SparseVec;
use crate::scaling::{Lifter, Scaling};

/// A term `c · Π p^ν · G^β` of a polynomial in the generators: coefficient, parameter
/// exponents, index of the monomial `β`.
pub(super) type LiftedTerm = (GaussianRational, Vec<(Var, i64)>, usize);

/// What lifting and printing need.
pub(super) struct LiftContext<'a> {
    pub(super) vars: Vars,
    pub(super) ring: Vars,
    pub(super) symbols: Vec<Var>,
    pub(super) param_in_ring: HashMap<Var, Var>,
    pub(super) monos: &'a [Vec<u32>],
    pub(super) col_ids: &'a [(usize, bool)],
    pub(super) g_sym: &'a [Expr],
    pub(super) sym_values: HashMap<Vec<u32>, Expr>,
    pub(super) lifter: Option<&'a Lifter>,
    pub(super) scaling: &'a Scaling,
    pub(super) gen_weights: Option<&'a [Vec<Rational>]>,
    /// Whether no parameter was fixed: then the linear algebra was done on the symbolic
    /// expansions, and what it found holds as it is, with no lift.
    pub(super) exact: bool,
}

impl LiftContext<'_> {
    /// A function of the parameters alone, in the ring.
    pub(super) fn to_ring(&self, e: &Expr) -> Result<Expr, EngineError> {
        let mut acc = Expr::zero(&self.ring);
        for t in e.terms() {
            let powers: Vec<(Var, i64)> = self
                .vars
                .vars()
                .filter(|v| t.exponent(*v) != 0)
                .map(|v| (self.param_in_ring[&v], t.exponent(v)))
                .collect();
            acc = acc.checked_add(&Expr::monomial(&self.ring, t.coeff(), &powers)?)?;
        }
        Ok(acc)
    }

    /// The symbolic value of a monomial in the generators.
    fn sym_value(&mut self, beta: &[u32]) -> Result<Expr, EngineError> {
        if let Some(v) = self.sym_values.get(beta) {
            return Ok(v.clone());
        }
        let mut acc = Expr::one(&self.vars);
        for (g, e) in self.g_sym.iter().zip(beta) {
            if *e > 0 {
                acc = acc.checked_mul(&g.checked_pow(*e as i64)?)?;
            }
        }
        self.sym_values.insert(beta.to_vec(), acc.clone());
        Ok(acc)
    }

    /// The coefficients of a solution over columns, combined per monomial (`re + i·im`).
    fn per_monomial(&self, sol: &SparseVec<Rational>) -> Vec<(usize, GaussianRational)> {
        let mut out: Vec<(usize, GaussianRational)> = Vec::new();
        for (j, x) in sol {
            let (m, imag) = self.col_ids[*j];
            let c = if imag {
                GaussianRational::new(Rational::zero(), x.clone())
            } else {
                GaussianRational::from(x.clone())
            };
            match out.iter_mut().find(|o| o.0 == m) {
                Some(o) => o.1 = &o.1 + &c,
                None => out.push((m, c)),
            }
        }
        out
    }

    fn weight_of(&self, beta: &[u32]) -> Option<Vec<Rational>> {
        let gw = self.gen_weights?;
        let mut w = vec![Rational::zero(); self.scaling.dimension()];
        for (g, e) in gw.iter().zip(beta) {
            for (wi, gi) in w.iter_mut().zip(g) {
                *wi += gi * &Rational::from(*e as i64);
            }
        }
        Some(w)
    }

    /// Terms `(coefficient, parameter exponents ν, monomial)` lifted to the weight `target`;
    /// `None` if not possible.
    fn lift_terms(
        &self,
        terms: &[(usize, GaussianRational)],
        target: &[Rational],
    ) -> Result<Option<Vec<LiftedTerm>>, EngineError> {
        let Some(lifter) = self.lifter else {
            return Ok(None);
        };
        let mut out = Vec::new();
        for (m, c) in terms {
            let Some(w) = self.weight_of(&self.monos[*m]) else {
                return Ok(None);
            };
            let delta: Vec<Rational> = target.iter().zip(&w).map(|(a, b)| a - b).collect();
            let Some(nu) = lifter.exponents(&delta) else {
                return Ok(None);
            };
            let value = lifter.value(&nu)?;
            let inv = GaussianRational::from(value.try_inv().expect("nonzero values"));
            let powers: Vec<(Var, i64)> = lifter.fixed().iter().map(|f| f.0).zip(nu).collect();
            out.push((c * &inv, powers, *m));
        }
        Ok(Some(out))
    }

    /// `Σ c ν G^β` in the ring.
    fn ring_poly(&self, terms: &[LiftedTerm]) -> Result<Expr, EngineError> {
        let mut acc = Expr::zero(&self.ring);
        for (c, nu, m) in terms {
            let mut powers: Vec<(Var, i64)> = nu
                .iter()
                .map(|(v, e)| (self.param_in_ring[v], *e))
                .collect();
            powers.extend(
                self.symbols
                    .iter()
                    .zip(&self.monos[*m])
                    .map(|(s, e)| (*s, *e as i64)),
            );
            acc = acc.checked_add(&Expr::monomial(&self.ring, c.clone(), &powers)?)?;
        }
        Ok(acc)
    }

    /// `Σ c ν G^β` expanded in phase space.
    fn expand(&mut self, terms: &[LiftedTerm]) -> Result<Expr, EngineError> {
        let mut acc = Expr::zero(&self.vars);
        for (c, nu, m) in terms {
            let monomial = Expr::monomial(&self.vars, c.clone(), nu)?;
            let beta = self.monos[*m].clone();
            acc = acc.checked_add(&monomial.checked_mul(&self.sym_value(&beta)?)?)?;
        }
        Ok(acc)
    }

    /// A relation (kernel vector), lifted and proved if possible.
    pub(super) fn relation(
        &mut self,
        rel: &SparseVec<Rational>,
    ) -> Result<(Expr, bool), EngineError> {
        let terms = self.per_monomial(rel);
        let fixed_terms: Vec<_> = terms
            .iter()
            .map(|(m, c)| (c.clone(), Vec::new(), *m))
            .collect();
        if self.exact {
            return Ok((normalize(self.ring_poly(&fixed_terms)?)?, true));
        }
        // Reference: the leading (last) monomial.
        let lead = terms
            .iter()
            .map(|t| t.0)
            .max()
            .expect("a relation has terms");
        if let Some(target) = self.weight_of(&self.monos[lead]) {
            if let Some(lifted) = self.lift_terms(&terms, &target)? {
                if self.expand(&lifted)?.vanishes()? {
                    return Ok((normalize(self.ring_poly(&lifted)?)?, true));
                }
            }
        }
        // Found at the fixed values, it may hold for every value as it stands.
        let proved = self.expand(&fixed_terms)?.vanishes()?;
        Ok((normalize(self.ring_poly(&fixed_terms)?)?, proved))
    }

    /// A bracket's expression, lifted and proved if possible.
    pub(super) fn bracket(
        &mut self,
        sol: &SparseVec<Rational>,
        target: &Expr,
    ) -> Result<(Expr, bool), EngineError> {
        let terms = self.per_monomial(sol);
        if terms.is_empty() {
            return Ok((Expr::zero(&self.ring), target.vanishes()?));
        }
        let fixed_terms: Vec<_> = terms
            .iter()
            .map(|(m, c)| (c.clone(), Vec::new(), *m))
            .collect();
        if self.exact {
            return Ok((self.ring_poly(&fixed_terms)?, true));
        }
        if let Some(w) = self.scaling.homogeneous_weight(target) {
            if let Some(lifted) = self.lift_terms(&terms, &w)? {
                if equal(&self.expand(&lifted)?, target)? {
                    return Ok((self.ring_poly(&lifted)?, true));
                }
            }
        }
        // Found at the fixed values, it may hold for every value as it stands (`C²` where
        // parameters of one weight leave homogeneity nothing to lift by).
        let proved = equal(&self.expand(&fixed_terms)?, target)?;
        Ok((self.ring_poly(&fixed_terms)?, proved))
    }
}

/// Whether `a = b` as elements: equal normal forms, or with denominator atoms or radicals a
/// difference that vanishes once cleared (`v · D` and `1` are one element, and so are `r²` and
/// `R`).
fn equal(a: &Expr, b: &Expr) -> Result<bool, EngineError> {
    if a == b {
        return Ok(true);
    }
    if !Expr::has_relations(a.vars()) {
        return Ok(false);
    }
    Ok(a.checked_sub(b)?.vanishes()?)
}

/// A relation scaled to coprime integer coefficients with a positive leading one, and, for
/// each parameter, by the power of it that leaves its least exponent 0 where that leaves it
/// in fewer terms: `c² + Q = R`, not `1 + Q/c² = R/c²`, and `A + B = 0`, not `kA + kB = 0`,
/// but `M²g⁴/ω⁴ + 4Mg² H/ω² + 4H² = 4ω² L² + …` as it is (a relation is one up to a nonzero
/// factor).
fn normalize(e: Expr) -> Result<Expr, EngineError> {
    let ring = e.vars();
    let shift: Vec<(Var, i64)> = ring
        .vars()
        .filter(|&v| ring.variable(v).kind() == VarKind::Parameter)
        .filter_map(|v| {
            let low = e.low_degree(v).filter(|&low| low != 0)?;
            let holding = |exponent: i64| e.terms().filter(|t| t.exponent(v) != exponent).count();
            (holding(low) < holding(0)).then_some((v, -low))
        })
        .collect();
    let e = match shift.is_empty() {
        true => e,
        false => e.checked_mul(&Expr::monomial(ring, GaussianRational::from(1), &shift)?)?,
    };
    Ok(match e.content().try_inv() {
        Some(inv) => e.scale_rational(&inv),
        None => e,
    })
}

#[cfg(test)]
mod tests {
    use trigpoly::{Expr, Vars};

    use super::normalize;

    fn normalized(text: &str) -> String {
        let ring = Vars::builder()
            .coordinate("Q")
            .coordinate("R")
            .coordinate("H")
            .coordinate("L")
            .parameter("c")
            .parameter("k")
            .parameter("w")
            .build()
            .expect("valid names");
        let e = Expr::parse(&ring, text).expect("reads");
        normalize(e).expect("normalizes").to_string()
    }

    /// A parameter's power comes off where that leaves it in fewer terms, and stays where it
    /// would put it in more; the content comes off too.
    #[test]
    fn a_relation_keeps_a_parameter_in_the_fewest_terms() {
        assert_eq!(normalized("1 + Q/c^2 - R/c^2"), "Q − R + c²");
        assert_eq!(normalized("2*k*Q - 4*k*R"), "Q − 2R");
        assert_eq!(
            normalized("k^2/w^4 + 4*k*H/w^2 + 4*H^2 - 4*w^2*L^2"),
            "4H² + 4kH/w² − 4w²L² + k²/w⁴"
        );
        assert_eq!(normalized("c*Q + c*R + H/c"), "c²Q + c²R + H");
    }
}
