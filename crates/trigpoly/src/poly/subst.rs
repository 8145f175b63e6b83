//! Substitution of variables by polynomials (a ring homomorphism) and exact evaluation at
//! rational points, with angles evaluated only at rational points of the unit circle.

use std::collections::HashMap;
use std::sync::Arc;

use super::Poly;
use crate::error::AlgebraError;
use crate::number::{Coefficient, GaussianRational, Rational};
use crate::varset::{Var, VarKind, VarSet};

/// Packed exponents and coefficients of a group of terms.
type Terms<C> = (Vec<u64>, Vec<<C as Coefficient>::Int>);

impl<C: Coefficient> Poly<C> {
    /// Replaces `v` by `value` (for an angle `θ`, replaces `e^{iθ}`). Where `v` appears with a
    /// negative exponent, `value` must be a single term.
    pub fn subst(&self, v: Var, value: &Self) -> Result<Self, AlgebraError> {
        self.subst_many(&[(v, value.clone())])
    }

    /// Replaces several variables at once (simultaneously: values are not substituted into
    /// each other).
    pub fn subst_many(&self, subs: &[(Var, Self)]) -> Result<Self, AlgebraError> {
        for (_, p) in subs {
            self.same_vars(p)?;
        }
        let targets: Vec<Var> = subs
            .iter()
            .map(|s| s.0)
            .filter(|&v| self.contains(v))
            .collect();
        if targets.is_empty() {
            return Ok(self.clone());
        }
        if let [v] = targets[..] {
            let value = &subs.iter().find(|s| s.0 == v).expect("a target").1;
            return self.subst_one(v, value);
        }
        // Group the terms by their exponents of the substituted variables.
        let layout = self.layout();
        let w = self.words();
        let mut groups: HashMap<Vec<i64>, Terms<C>> = HashMap::new();
        let mut order: Vec<Vec<i64>> = Vec::new();
        for k in 0..self.len() {
            let m = self.exp(k);
            let key: Vec<i64> = targets.iter().map(|v| layout.get(m, v.index())).collect();
            let mut exps: Vec<i64> = (0..self.vars.len()).map(|j| layout.get(m, j)).collect();
            for v in &targets {
                exps[v.index()] = 0;
            }
            let mut packed = vec![0u64; w];
            layout.pack(&exps, &mut packed);
            let entry = groups.entry(key.clone()).or_insert_with(|| {
                order.push(key);
                (Vec::new(), Vec::new())
            });
            entry.0.extend_from_slice(&packed);
            entry.1.push(self.coeffs[k].clone());
        }
        let value_of = |v: Var| &subs.iter().find(|s| s.0 == v).expect("a target").1;
        let mut powers: HashMap<(Var, i64), Self> = HashMap::new();
        let mut result = Self::zero(&self.vars);
        for key in order {
            let (exps, coeffs) = groups.remove(&key).expect("grouped");
            // Removing the same variables from every term of a group keeps their order.
            let mut part = Self::from_sorted(&self.vars, self.content.clone(), exps, coeffs);
            for (v, &e) in targets.iter().zip(&key) {
                if e == 0 {
                    continue;
                }
                if let std::collections::hash_map::Entry::Vacant(slot) = powers.entry((*v, e)) {
                    let p = value_of(*v).checked_pow(e).map_err(|err| match err {
                        AlgebraError::NegativePower(s) => AlgebraError::Invalid(format!(
                            "cannot substitute {s} for {}: it appears with exponent {e}, and \
                             only a single term can be raised to a negative power",
                            self.vars.variable(*v).unicode()
                        )),
                        other => other,
                    })?;
                    slot.insert(p);
                }
                part = part.checked_mul(&powers[&(*v, e)])?;
            }
            result = result.checked_add(&part)?;
        }
        Ok(result)
    }

    /// `self` with `v ↦ value`: the terms are grouped by their exponent `e` of `v`, each group
    /// translated to `e = 0` (which keeps its order) and multiplied by `value^e`.
    fn subst_one(&self, v: Var, value: &Self) -> Result<Self, AlgebraError> {
        let layout = self.layout();
        let w = self.words();
        let j = v.index();
        let mut groups: std::collections::BTreeMap<i64, Terms<C>> = Default::default();
        let mut unit = vec![0u64; w];
        for k in 0..self.len() {
            let m = self.exp(k);
            let e = layout.get(m, j);
            let group = groups.entry(e).or_default();
            let start = group.0.len();
            group.0.extend_from_slice(m);
            if e != 0 {
                layout.unit(j, -e, &mut unit);
                layout.mul_into(m, &unit, &mut group.0[start..]);
            }
            group.1.push(self.coeffs[k].clone());
        }
        let mut result = Self::zero(&self.vars);
        for (e, (exps, coeffs)) in groups {
            let part = Self::from_sorted(&self.vars, self.content.clone(), exps, coeffs);
            let power = value.checked_pow(e).map_err(|err| match err {
                AlgebraError::NegativePower(s) => AlgebraError::Invalid(format!(
                    "cannot substitute {s} for {}: it appears with exponent {e}, and only a \
                     single term can be raised to a negative power",
                    self.vars.variable(v).unicode()
                )),
                other => other,
            })?;
            result = result.checked_add(&part.checked_mul(&power)?)?;
        }
        Ok(result)
    }

    /// Replaces `v` by a constant.
    pub fn subst_value(&self, v: Var, value: &C) -> Result<Self, AlgebraError> {
        self.subst(v, &Self::constant(&self.vars, value.clone()))
    }

    /// The exact value at a point that gives every variable appearing here a value.
    pub fn eval(&self, point: &Point) -> Result<GaussianRational, AlgebraError> {
        if !Arc::ptr_eq(&self.vars, &point.vars) && *self.vars != *point.vars {
            return Err(AlgebraError::VarSetMismatch);
        }
        let layout = self.layout();
        let mut cache: HashMap<(usize, i64), GaussianRational> = HashMap::new();
        let mut total = GaussianRational::default();
        for k in 0..self.len() {
            let m = self.exp(k);
            let mut term = C::from_parts(&Rational::one(), &self.coeffs[k]).to_gaussian();
            for j in 0..self.vars.len() {
                let e = layout.get(m, j);
                if e == 0 {
                    continue;
                }
                let value = point.values[j].as_ref().ok_or_else(|| {
                    AlgebraError::MissingValue(self.vars.variable(Var(j as u16)).unicode().into())
                })?;
                if let std::collections::hash_map::Entry::Vacant(slot) = cache.entry((j, e)) {
                    slot.insert(value.pow(e).ok_or(AlgebraError::DivisionByZero)?);
                }
                term = &term * &cache[&(j, e)];
            }
            total = &total + &term;
        }
        Ok(&total * &GaussianRational::from(self.content.clone()))
    }
}

/// An exact point: a value for each variable (angles as points of the unit circle).
///
/// ```
/// use trigpoly::{Point, Rational, VarSet};
/// let vars = VarSet::builder().coordinate("x").angle("theta").build().unwrap();
/// let x = vars.lookup("x").unwrap();
/// let theta = vars.lookup("theta").unwrap();
/// let point = Point::new(&vars)
///     .with(x, Rational::new(1, 2))
///     .with_angle(theta, Rational::new(3, 5), Rational::new(4, 5))
///     .unwrap();
/// assert!(point.value(x).is_some());
/// ```
#[derive(Clone, Debug)]
pub struct Point {
    vars: Arc<VarSet>,
    values: Vec<Option<GaussianRational>>,
}

impl Point {
    /// A point with no values yet.
    pub fn new(vars: &Arc<VarSet>) -> Point {
        Point {
            vars: vars.clone(),
            values: vec![None; vars.len()],
        }
    }

    /// Sets a real value.
    pub fn with(mut self, v: Var, value: Rational) -> Point {
        self.values[v.index()] = Some(GaussianRational::from(value));
        self
    }

    /// Sets an angle by its cosine and sine, which must satisfy `cos² + sin² = 1`.
    pub fn with_angle(
        mut self,
        v: Var,
        cos: Rational,
        sin: Rational,
    ) -> Result<Point, AlgebraError> {
        let name = self.vars.variable(v).unicode().to_string();
        if self.vars.variable(v).kind() != VarKind::Angle || !(&cos * &cos + &sin * &sin).is_one() {
            return Err(AlgebraError::NotOnUnitCircle(name));
        }
        self.values[v.index()] = Some(GaussianRational::new(cos, sin));
        Ok(self)
    }

    /// The value given to `v` (for an angle, `e^{iθ} = cos θ + i sin θ`).
    pub fn value(&self, v: Var) -> Option<&GaussianRational> {
        self.values[v.index()].as_ref()
    }
}
