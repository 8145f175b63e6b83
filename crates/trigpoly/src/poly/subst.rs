//! Substitution of variables by polynomials (a ring homomorphism) and exact evaluation at
//! rational points, with angles evaluated only at rational points of the unit circle.

use std::collections::HashMap;
use std::fmt;

use super::Poly;
use crate::error::{AlgebraError, AngleUse};
use crate::number::{
    Coefficient, GaussianAcc, GaussianInteger, GaussianRational, Integer, IntegerRing, Rational,
};
use crate::varset::{Layout, Var, VarKind, Vars};

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
        for (v, p) in subs {
            self.same_vars(p)?;
            self.vars.checked_index(*v)?;
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
        let value_of = |v: Var| &subs.iter().find(|s| s.0 == v).expect("a target").1;
        let mut powers: HashMap<(Var, i64), Self> = HashMap::new();
        let mut products = Vec::new();
        for (key, mut part) in self.coefficients_in(&targets) {
            for (v, &e) in targets.iter().zip(&key) {
                if e == 0 {
                    continue;
                }
                if let std::collections::hash_map::Entry::Vacant(slot) = powers.entry((*v, e)) {
                    let p = value_of(*v)
                        .checked_pow(e)
                        .map_err(|err| self.uninvertible_value(err, *v, e))?;
                    slot.insert(p);
                }
                part = part.checked_mul(&powers[&(*v, e)])?;
            }
            products.push(part);
        }
        Self::sum_all(&self.vars, products)
    }

    /// `self` as `Σ_k c_k · Π v_i^{k_i}` in the variables `vs`: each exponent vector `k` of
    /// theirs that occurs (in the order of the terms where each first occurs) with its
    /// coefficient `c_k`, free of them. Collecting with respect to `vs`, as substituting them
    /// needs: `x²y + 3x² + y` in `x` is `(2, y + 3)`, `(0, y)`.
    ///
    /// # Panics
    ///
    /// If a variable is a handle of another set ([`VarSet::owns`](crate::VarSet::owns)), as
    /// [`Poly::coeff`] and [`Poly::degree`] do: such a handle would name whatever variable
    /// stands at its index here.
    #[track_caller]
    pub fn coefficients_in(&self, vs: &[Var]) -> Vec<(Vec<i64>, Self)> {
        let indices: Vec<usize> = vs.iter().map(|&v| self.vars.index_of(v)).collect();
        let layout = self.layout();
        let w = self.words();
        let mut groups: HashMap<Vec<i64>, Terms<C>> = HashMap::new();
        let mut order: Vec<Vec<i64>> = Vec::new();
        let mut exps = vec![0i64; self.vars.len()];
        for k in 0..self.len() {
            let m = self.exp(k);
            let key: Vec<i64> = indices.iter().map(|&j| layout.get(m, j)).collect();
            for (j, e) in exps.iter_mut().enumerate() {
                *e = layout.get(m, j);
            }
            for &j in &indices {
                exps[j] = 0;
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
        order
            .into_iter()
            .map(|key| {
                let (exps, coeffs) = groups.remove(&key).expect("grouped");
                // Removing the same variables from every term of a group keeps their order.
                let part = Self::from_sorted(&self.vars, self.content.clone(), exps, coeffs);
                (key, part)
            })
            .collect()
    }

    /// The sum of `parts` (all in `vars`; zero when there are none), added pairwise like the
    /// levels of a tree, so that each term is merged `log₂ n` times, not once per part after it.
    pub fn sum_all(vars: &Vars, mut parts: Vec<Self>) -> Result<Self, AlgebraError> {
        while parts.len() > 1 {
            let mut next = Vec::with_capacity(parts.len().div_ceil(2));
            let mut it = parts.into_iter();
            while let Some(a) = it.next() {
                next.push(match it.next() {
                    Some(b) => a.checked_add(&b)?,
                    None => a,
                });
            }
            parts = next;
        }
        Ok(parts.pop().unwrap_or_else(|| Self::zero(vars)))
    }

    /// The refusal of a substituted value that `self` takes to the negative power `e` of `v`
    /// and that is not invertible: the value, and what to declare to make it so.
    fn uninvertible_value(&self, err: AlgebraError, v: Var, e: i64) -> AlgebraError {
        match err {
            AlgebraError::NegativePower { shown, declare } => {
                AlgebraError::UninvertibleSubstitution {
                    shown,
                    var: self.vars.variable(v).unicode().to_string(),
                    exponent: e,
                    declare,
                }
            }
            other => other,
        }
    }

    /// `self` with `v ↦ value`: the terms are grouped by their exponent `e` of `v`, each group
    /// translated to `e = 0` (which keeps its order) and multiplied by `value^e`.
    fn subst_one(&self, v: Var, value: &Self) -> Result<Self, AlgebraError> {
        if value.is_monomial() {
            if let Some(result) = self.subst_term(v, value) {
                return result;
            }
        }
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
            let power = value
                .checked_pow(e)
                .map_err(|err| self.uninvertible_value(err, v, e))?;
            result = result.checked_add(&part.checked_mul(&power)?)?;
        }
        Ok(result)
    }

    /// `self` with `v ↦ c·m` for a single term, in one pass: a term with exponent `e` of `v` is
    /// translated by `e·(m − v)` and scaled by `c^e`; the groups of equal `e` stay sorted, so
    /// they are merged once and normalised once. `None` when this path does not apply (a
    /// non-unit integer part raised to a negative power, or exponents near the limit), and
    /// the general path decides.
    fn subst_term(&self, v: Var, value: &Self) -> Option<Result<Self, AlgebraError>> {
        let layout = self.layout();
        let w = self.words();
        let j = v.index();
        let one = C::Int::from_integer(crate::number::Integer::ONE);
        let (q, n) = (&value.content, &value.coeffs[0]);
        // The exponent of v in each term, and the distinct ones, ascending (they span at most
        // twice the degree limit); n^e must stay integral (n a unit, or e ≥ 0).
        let field = layout.field(j);
        let term_exps: Vec<i64> = self
            .exps
            .chunks_exact(w)
            .map(|m| layout.read(m, field))
            .collect();
        let lowest = *term_exps.iter().min()?;
        let highest = *term_exps.iter().max()?;
        // The exponents present, by their offset from the lowest; the group of a present one
        // is the number of present ones below it.
        let mut present = vec![false; usize::try_from(highest - lowest).ok()? + 1];
        for &e in &term_exps {
            present[(e - lowest) as usize] = true;
        }
        let mut exps_v = Vec::new();
        let mut group_of = Vec::with_capacity(present.len());
        for (offset, &here) in present.iter().enumerate() {
            group_of.push(exps_v.len());
            if here {
                exps_v.push(lowest + offset as i64);
            }
        }
        let unit_n = *n == one || *n == one.neg();
        if !unit_n && exps_v.iter().any(|&e| e < 0) {
            return None;
        }
        // Conservative exponent check from the overall bounds; near the limit, the general path.
        let mv: Vec<i64> = (0..self.vars.len())
            .map(|k| layout.get(value.exp(0), k))
            .collect();
        let largest_shift = exps_v
            .iter()
            .map(|e| e.unsigned_abs())
            .max()
            .unwrap_or(0)
            .checked_mul(mv.iter().map(|m| m.unsigned_abs()).max().unwrap_or(0))?;
        let clear = (self.exponent_bound() as u64).checked_add(largest_shift)?
            <= self.vars.limits().max_degree as u64;
        if !clear {
            let bounds = self.bounds();
            for &e in &exps_v {
                for (k, var) in self.vars.vars().enumerate() {
                    let (lo, hi) = if k == j { (0, 0) } else { bounds[k] };
                    let shift = e.checked_mul(mv[k])?;
                    for x in [lo.checked_add(shift)?, hi.checked_add(shift)?] {
                        if super::check_exponent(&self.vars, var, x).is_err() {
                            return None;
                        }
                    }
                }
            }
        }
        // One rational content for every group: q^e = d · s_e with s_e an integer.
        let powers: Vec<(i64, Rational)> = exps_v
            .iter()
            .map(|&e| Some((e, q.pow(e)?)))
            .collect::<Option<_>>()?;
        let d = Rational::content_of(powers.iter().map(|(_, p)| p));
        // Per group: the translation e·(m − v) and the integer factor of the coefficients.
        let mut unit = vec![0u64; w];
        layout.unit(j, 1, &mut unit);
        let groups: Vec<(Vec<u64>, C::Int)> = powers
            .iter()
            .map(|(e, qe)| {
                // Word by word (wrapping, exact because the fields stay in range).
                let delta = value
                    .exp(0)
                    .iter()
                    .zip(&unit)
                    .map(|(mw, uw)| mw.wrapping_sub(*uw).wrapping_mul(*e as u64))
                    .collect();
                let scale = (qe / &d).numer();
                // n^e; for e < 0 only n = ±1 gets here, and (±1)^e = (±1)^{|e|}.
                let mut ne = one.clone();
                for _ in 0..e.unsigned_abs() {
                    ne = ne.mul(n);
                }
                (delta, ne.scale(&scale))
            })
            .collect();
        // One pass over the terms, each to its group (groups stay sorted), into vectors sized
        // by a count first (growing them by doubling copied every group about twice).
        let mut sizes = vec![0usize; groups.len()];
        for &e in &term_exps {
            sizes[group_of[(e - lowest) as usize]] += 1;
        }
        let mut parts: Vec<(Vec<u64>, Vec<C::Int>)> = sizes
            .iter()
            .map(|&n| (Vec::with_capacity(n * w), Vec::with_capacity(n)))
            .collect();
        for (k, &e) in term_exps.iter().enumerate() {
            let m = self.exp(k);
            let g = group_of[(e - lowest) as usize];
            let (delta, factor) = &groups[g];
            let (exps, coeffs) = &mut parts[g];
            Layout::push_translated(exps, m, delta);
            coeffs.push(self.coeffs[k].mul(factor));
        }
        let parts = parts
            .into_iter()
            .map(|(exps, coeffs)| Self::raw(&self.vars, exps, coeffs))
            .collect();
        let total = super::mul::merge_tree(parts);
        if let Err(err) = Self::check_terms(&self.vars, total.len()) {
            return Some(Err(err));
        }
        let content = &self.content * &d;
        let (exps, coeffs) = total.into_terms();
        Some(Ok(Self::drop_zeros_and_normalize(
            &self.vars, content, exps, coeffs,
        )))
    }

    /// Replaces `v` by a constant.
    pub fn subst_value(&self, v: Var, value: &C) -> Result<Self, AlgebraError> {
        self.subst(v, &Self::constant(&self.vars, value.clone()))
    }

    /// The exact value at a point that gives every variable appearing here a value.
    ///
    /// The terms are summed in Z\[i\] over one common denominator: adding them as fractions
    /// took a gcd of ever longer numbers per term, minutes for a Jacobian whose entries have
    /// 10 000 terms of degree 40. Consecutive terms share the leading exponents, so each term
    /// reuses the product of the factors of its common prefix with the term before.
    pub fn eval(&self, point: &Point) -> Result<GaussianRational, AlgebraError> {
        Ok(self.eval_with_partials(point, &[])?.0)
    }

    /// The partial derivatives by `vars` at a point ([`Poly::eval`] of each
    /// [`Poly::derivative`]), from the terms in one pass and without building a derivative:
    /// a term `t = c·x^e` adds `e_k·t/x_k` to `∂/∂x_k`, and `i·e_k·t` for an angle (`x_k` the
    /// point `e^{iθ}` of the circle). `None` where a variable of `vars` that appears here is
    /// zero at the point, for the caller to differentiate instead.
    ///
    /// ```
    /// use trigpoly::{Expr, Point, Rational, Vars};
    /// let vars = Vars::builder().coordinate("x").coordinate("y").angle("theta").build().unwrap();
    /// let [x, y, theta] = ["x", "y", "theta"].map(|name| vars.lookup(name).unwrap());
    /// let f = Expr::parse(&vars, "x^3*y*cos(theta) - 2*y^2/3 + sin(2*theta)/x").unwrap();
    /// let point = Point::new(&vars).with(x, Rational::new(1, 2)).with(y, Rational::from(3));
    /// let point = point.with_angle(theta, Rational::new(3, 5), Rational::new(4, 5)).unwrap();
    /// let gradient = f.eval_gradient(&point, &[x, y, theta]).unwrap().unwrap();
    /// assert!(gradient.iter().all(|value| !value.is_zero()));
    /// for (value, v) in gradient.iter().zip([x, y, theta]) {
    ///     assert_eq!(*value, f.derivative(v).unwrap().eval(&point).unwrap());
    /// }
    /// ```
    pub fn eval_gradient(
        &self,
        point: &Point,
        vars: &[Var],
    ) -> Result<Option<Vec<GaussianRational>>, AlgebraError> {
        for &v in vars {
            let j = self.vars.checked_index(v)?;
            let appears = self.bounds()[j] != (0, 0);
            if appears
                && point.values[j]
                    .as_ref()
                    .is_some_and(GaussianRational::is_zero)
            {
                return Ok(None);
            }
        }
        let (_, sums) = self.eval_with_partials(point, vars)?;
        let mut gradient = Vec::with_capacity(vars.len());
        for (&v, sum) in vars.iter().zip(sums) {
            let j = self.vars.checked_index(v)?;
            let value = match (sum.is_zero(), &point.values[j]) {
                (true, _) | (false, None) => sum,
                (false, Some(_)) if self.vars.variable(v).kind() == VarKind::Angle => {
                    GaussianRational::new(-&sum.im, sum.re.clone())
                }
                (false, Some(x)) => &sum / x,
            };
            gradient.push(value);
        }
        Ok(Some(gradient))
    }

    /// The value at a point, and for each of `partials` the sum of `e_k·t` over the terms `t`
    /// (their values there) with `e_k` the exponent of that variable: [`Poly::eval`] and
    /// [`Poly::eval_gradient`] in one pass.
    fn eval_with_partials(
        &self,
        point: &Point,
        partials: &[Var],
    ) -> Result<(GaussianRational, Vec<GaussianRational>), AlgebraError> {
        if self.vars != point.vars {
            return Err(AlgebraError::VarSetMismatch);
        }
        if let Some(e) = &point.invalid {
            return Err(e.clone());
        }
        let mut scaled = Vec::new();
        for (j, (lo, hi)) in self.bounds().into_iter().enumerate() {
            if (lo, hi) == (0, 0) {
                continue;
            }
            let value = point.values[j].as_ref().ok_or_else(|| {
                AlgebraError::MissingValue(self.vars.variable(self.vars.var_at(j)).unicode().into())
            })?;
            scaled.push((j, ScaledValue::new(value, lo, hi)?));
        }
        let denominator = scaled
            .iter()
            .fold(Integer::ONE, |acc, (_, s)| &acc * &s.denominator());
        let layout = self.layout();
        // The partials' positions among `scaled` (`None`: the variable does not appear).
        let partials: Vec<Option<usize>> = partials
            .iter()
            .map(|&v| {
                let j = self.vars.checked_index(v)?;
                Ok(scaled.iter().position(|(i, _)| *i == j))
            })
            .collect::<Result<_, AlgebraError>>()?;
        let mut partial_sums = vec![GaussianAcc::default(); partials.len()];
        let mut factors: HashMap<(usize, i64), GaussianInteger> = HashMap::new();
        // `prefix[i]`: the product of the first `i` factors of the last term, whose exponents
        // are `last`.
        let one = GaussianInteger::new(Integer::ONE, Integer::ZERO);
        let mut prefix = vec![one; scaled.len() + 1];
        let mut last: Vec<Option<i64>> = vec![None; scaled.len()];
        let mut total = GaussianInteger::default();
        for k in 0..self.len() {
            let m = self.exp(k);
            let mut same = true;
            for (i, (j, s)) in scaled.iter().enumerate() {
                let e = layout.get(m, *j);
                if same && last[i] == Some(e) {
                    continue;
                }
                same = false;
                last[i] = Some(e);
                let factor = factors.entry((i, e)).or_insert_with(|| s.factor(e));
                prefix[i + 1] = prefix[i].mul(factor);
            }
            let c = C::from_parts(&Rational::one(), &self.coeffs[k]).to_gaussian();
            let c = GaussianInteger::new(c.re.numer(), c.im.numer());
            let term = prefix[scaled.len()].mul(&c);
            for (sum, at) in partial_sums.iter_mut().zip(&partials) {
                if let Some(e) = at.and_then(|i| last[i]).filter(|&e| e != 0) {
                    sum.add_mul(&GaussianInteger::from(e), &term);
                }
            }
            total = total.add(&term);
        }
        let content = GaussianRational::from(self.content.clone());
        let part = |x: &Integer| Rational::from_fraction(x, &denominator).expect("nonzero");
        let value =
            |g: &GaussianInteger| &GaussianRational::new(part(&g.re), part(&g.im)) * &content;
        let partial_values = partial_sums
            .into_iter()
            .map(|s| value(&s.finish()))
            .collect();
        Ok((value(&total), partial_values))
    }
}

/// A variable's value `v` scaled for a sum over one denominator, its exponents lying in
/// `[lo, hi]`: with `v = g/d` (`g ∈ Z[i]`, `d > 0`) and `N = g·ḡ = d²·|v|²`, every power `v^e`
/// times `scale = d^{hi⁺}·N^{lo⁻}` (`hi⁺ = max(hi, 0)`, `lo⁻ = max(−lo, 0)`) is a Gaussian
/// integer: `g^e·d^{hi⁺−e}·N^{lo⁻}` for `e ≥ 0`, `ḡ^{−e}·d^{hi⁺−e}·N^{lo⁻+e}` for `e < 0`.
struct ScaledValue<'a> {
    value: &'a GaussianRational,
    scale: Rational,
}

impl<'a> ScaledValue<'a> {
    fn new(value: &'a GaussianRational, lo: i64, hi: i64) -> Result<Self, AlgebraError> {
        if lo < 0 && value.is_zero() {
            return Err(AlgebraError::DivisionByZero);
        }
        let d = Rational::from(value.re.denom().lcm(&value.im.denom()));
        let norm = &(&d * &d) * &value.norm();
        let scale = &d.pow(hi.max(0)).expect("d > 0")
            * &norm.pow(lo.min(0).abs()).expect("N ≠ 0 when lo < 0");
        Ok(ScaledValue { value, scale })
    }

    /// `d^{hi⁺}·N^{lo⁻}`, by which the sum is scaled (an integer).
    fn denominator(&self) -> Integer {
        self.scale.numer()
    }

    /// `v^e·d^{hi⁺}·N^{lo⁻}`, a Gaussian integer for `e` in `[lo, hi]`.
    fn factor(&self, e: i64) -> GaussianInteger {
        let power = self.value.pow(e).expect("v ≠ 0 when e < 0");
        let f = &power * &GaussianRational::from(self.scale.clone());
        debug_assert!(f.re.is_integer() && f.im.is_integer());
        GaussianInteger::new(f.re.numer(), f.im.numer())
    }
}

/// An exact point: a value for each variable (angles as points of the unit circle).
///
/// ```
/// use trigpoly::{Point, Rational, Vars};
/// let vars = Vars::builder().coordinate("x").angle("theta").build().unwrap();
/// let x = vars.lookup("x").unwrap();
/// let theta = vars.lookup("theta").unwrap();
/// let point = Point::new(&vars)
///     .with(x, Rational::new(1, 2))
///     .with_angle(theta, Rational::new(3, 5), Rational::new(4, 5))
///     .unwrap();
/// assert!(point.value(x).is_some());
/// assert_eq!(point.to_string(), "x = 1/2, cos θ = 3/5, sin θ = 4/5");
/// ```
///
/// Two points are equal when they give the same values to the variables of the same set (and
/// are both valid, or invalid for the same reason).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Point {
    vars: Vars,
    values: Vec<Option<GaussianRational>>,
    /// Why the point cannot be used, if a value was given wrongly ([`Point::with`] of a
    /// handle of another set, or of a real value off the unit circle for an angle): the
    /// evaluation says so.
    invalid: Option<AlgebraError>,
}

impl Point {
    /// A point with no values yet.
    pub fn new(vars: &Vars) -> Point {
        Point {
            vars: vars.clone(),
            values: vec![None; vars.len()],
            invalid: None,
        }
    }

    /// Sets a real value. An angle takes its value as `e^{iθ}`, so only `1` or `−1` (θ = 0
    /// or π; others through [`Point::with_angle`]); any other value for an angle, or a
    /// variable of another set, makes [`Poly::eval`] at the point an error.
    #[must_use]
    pub fn with(mut self, v: Var, value: Rational) -> Point {
        let Ok(j) = self.vars.checked_index(v) else {
            self.invalid.get_or_insert(AlgebraError::VarSetMismatch);
            return self;
        };
        let variable = self.vars.variable(v);
        if variable.kind() == VarKind::Angle && value.abs() != Rational::one() {
            let name = variable.unicode().to_string();
            self.invalid
                .get_or_insert(AlgebraError::NotOnUnitCircle(name));
        }
        self.values[j] = Some(GaussianRational::from(value));
        self
    }

    /// Sets an angle by its cosine and sine, which must satisfy `cos² + sin² = 1`. A variable
    /// that is no angle is refused as such (it was refused as a point off the unit circle),
    /// and a handle of another set as a mismatch of sets.
    ///
    /// ```
    /// use trigpoly::{AlgebraError, Expr, Point, Rational, Vars};
    ///
    /// let vars = Vars::builder().coordinate("x").angle("theta").build()?;
    /// let (x, theta) = (vars.lookup("x").unwrap(), vars.lookup("theta").unwrap());
    /// // x cos θ + sin 2θ at x = 2, (cos θ, sin θ) = (3/5, 4/5): 6/5 + 2·(4/5)(3/5) = 54/25.
    /// let f = Expr::parse(&vars, "x*cos(theta) + sin(2*theta)")?;
    /// let point = Point::new(&vars)
    ///     .with(x, Rational::from(2))
    ///     .with_angle(theta, Rational::new(3, 5), Rational::new(4, 5))?;
    /// assert_eq!(f.eval(&point)?.to_string(), "54/25");
    /// // Off the circle, and not an angle.
    /// let off = Point::new(&vars).with_angle(theta, Rational::one(), Rational::one());
    /// assert_eq!(off, Err(AlgebraError::NotOnUnitCircle("θ".into())));
    /// let coordinate = Point::new(&vars).with_angle(x, Rational::new(3, 5), Rational::new(4, 5));
    /// assert_eq!(
    ///     coordinate.unwrap_err().to_string(),
    ///     "Point::with_angle sets an angle, and x is a coordinate"
    /// );
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_angle(
        mut self,
        v: Var,
        cos: Rational,
        sin: Rational,
    ) -> Result<Point, AlgebraError> {
        let j = self.vars.checked_index(v)?;
        let variable = self.vars.variable(v);
        let name = variable.unicode().to_string();
        if variable.kind() != VarKind::Angle {
            return Err(AlgebraError::NotAnAngle {
                needed_by: AngleUse::PointWithAngle,
                var: name,
                kind: variable.kind(),
            });
        }
        if !(&cos * &cos + &sin * &sin).is_one() {
            return Err(AlgebraError::NotOnUnitCircle(name));
        }
        self.values[j] = Some(GaussianRational::new(cos, sin));
        Ok(self)
    }

    /// Sets each denominator atom `(D)` to `D` evaluated at the point (its other variables
    /// given), so that its negative powers evaluate as `1/D^k`; `None` when some `D` is zero
    /// there, where the elements with atoms are not defined. `atoms` are the set's atoms with
    /// their polynomials, as [`Poly::denominator_atoms`] gives them.
    ///
    /// ```
    /// use trigpoly::{Expr, Point, Rational, Vars};
    /// let vars = Vars::builder()
    ///     .coordinate("x")
    ///     .coordinate("y")
    ///     .denominator("x - y").unwrap()
    ///     .build()
    ///     .unwrap();
    /// let atoms = Expr::denominator_atoms(&vars).unwrap();
    /// let (x, y) = (vars.lookup("x").unwrap(), vars.lookup("y").unwrap());
    /// let f = Expr::parse(&vars, "x/(x - y)^2").unwrap();
    /// let at = |a: i64, b: i64| Point::new(&vars).with(x, a.into()).with(y, b.into());
    /// let point = at(3, 1).with_atoms(&atoms).unwrap().unwrap();
    /// assert_eq!(f.eval(&point).unwrap(), Rational::new(3, 4).into());
    /// assert!(at(2, 2).with_atoms(&atoms).unwrap().is_none());
    /// ```
    pub fn with_atoms<C: Coefficient>(
        mut self,
        atoms: &[(Var, Poly<C>)],
    ) -> Result<Option<Point>, AlgebraError> {
        for (v, d) in atoms {
            let value = d.eval(&self)?;
            if value.is_zero() {
                return Ok(None);
            }
            let j = self.vars.checked_index(*v)?;
            self.values[j] = Some(value);
        }
        Ok(Some(self))
    }

    /// Sets each radical `r = √R` to the positive rational root of `R` at the point (its other
    /// variables given); `None` when some `R` is not the square of a nonzero rational there,
    /// where the radical has no exact rational value (the point `x = 3, y = 4` gives
    /// `√(x² + y²)` the value 5, `x = y = 1` none). `radicals` are the set's radicals with their
    /// radicands, as [`Poly::radicals`] gives them.
    ///
    /// ```
    /// use trigpoly::{Expr, Point, Rational, Vars};
    /// let vars = Vars::builder()
    ///     .coordinate("x")
    ///     .coordinate("y")
    ///     .radical("r", "x^2 + y^2")
    ///     .build()
    ///     .unwrap();
    /// let radicals = Expr::radicals(&vars).unwrap();
    /// let (x, y) = (vars.lookup("x").unwrap(), vars.lookup("y").unwrap());
    /// let at = |a: i64, b: i64| Point::new(&vars).with(x, a.into()).with(y, b.into());
    /// let point = at(3, 4).with_radicals(&radicals).unwrap().unwrap();
    /// let f = Expr::parse(&vars, "x/r^3").unwrap();
    /// assert_eq!(f.eval(&point).unwrap(), Rational::new(3, 125).into());
    /// assert!(at(1, 1).with_radicals(&radicals).unwrap().is_none());
    /// ```
    pub fn with_radicals<C: Coefficient>(
        mut self,
        radicals: &[(Var, Poly<C>)],
    ) -> Result<Option<Point>, AlgebraError> {
        for (r, radicand) in radicals {
            let value = radicand.eval(&self)?;
            let root = match value.is_real() && !value.is_zero() {
                true => value.re.sqrt(),
                false => None,
            };
            let Some(root) = root else {
                return Ok(None);
            };
            let j = self.vars.checked_index(*r)?;
            self.values[j] = Some(GaussianRational::from(root));
        }
        Ok(Some(self))
    }

    /// The value given to `v` (for an angle, `e^{iθ} = cos θ + i sin θ`).
    ///
    /// ```
    /// use trigpoly::{Point, Vars};
    /// let vars = Vars::builder().coordinate("x").coordinate("y").build().unwrap();
    /// let x = vars.lookup("x").unwrap();
    /// assert_eq!(Point::new(&vars).with(x, 2.into()).to_string(), "x = 2");
    /// ```
    ///
    /// # Panics
    ///
    /// If `v` is a handle of another set ([`VarSet::owns`](crate::VarSet::owns)).
    pub fn value(&self, v: Var) -> Option<&GaussianRational> {
        self.values[self.vars.index_of(v)].as_ref()
    }
}

impl fmt::Display for Point {
    /// The values given, in the set's order and Unicode names: `x = 1/2, cos θ = 3/5,
    /// sin θ = 4/5` (an angle by its cosine and sine); a variable without a value is left out,
    /// and a point with none is `no values`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let number = |q: &Rational| {
            crate::print::render_number(&GaussianRational::from(q.clone()), crate::Style::Unicode)
        };
        let mut first = true;
        for (v, value) in self.vars.vars().zip(&self.values) {
            let Some(value) = value else { continue };
            if !std::mem::take(&mut first) {
                f.write_str(", ")?;
            }
            let variable = self.vars.variable(v);
            let name = variable.unicode();
            match variable.kind() {
                VarKind::Angle => write!(
                    f,
                    "cos {name} = {}, sin {name} = {}",
                    number(&value.re),
                    number(&value.im)
                )?,
                _ => write!(
                    f,
                    "{name} = {}",
                    crate::print::render_number(value, crate::Style::Unicode)
                )?,
            }
        }
        if first {
            f.write_str("no values")?;
        }
        Ok(())
    }
}
