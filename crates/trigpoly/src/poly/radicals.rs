//! Radicals ([`VarKind::Radical`]): a variable `r` declared with a radicand `R`, a polynomial
//! in the other variables, stands for `√R`, so that the ring is `Q[vars][r, 1/r]` with
//! `r² = R`. Here: the radicals' radicands ([`Poly::radicals`]), the check that they are
//! independent ([`Poly::check_radicals`]: no product of radicands is a square, so that the
//! products of distinct radicals are independent over the rational functions), and the
//! reduction by `r² = R` that the exact zero test and the clearing of denominators begin with
//! ([`Poly::reduce_radicals`]): `r^M · P` with `M` at least the highest power of `1/r` in `P`
//! has no negative power of `r`, and `r^k ↦ R^{⌊k/2⌋} r^{k mod 2}` leaves each radical to the
//! power 0 or 1. Multiplying by `r^M ≠ 0` is injective, and an element `Σ_s P_s Π r_i^{s_i}`
//! with the `P_s` free of radicals is zero exactly when every `P_s` is, so the reduced element
//! is the zero polynomial exactly when `P` is zero.

use std::collections::BTreeMap;

use super::Poly;
use crate::error::{AlgebraError, Misuse, Setting};
use crate::number::{Coefficient, Rational};
use crate::varset::{Var, VarKind, Vars, MAX_RADICALS};
use crate::Point;

thread_local! {
    /// Whether this thread is reading a radicand.
    static READING: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// A radical, its radicand, and the power of the radical an element was multiplied by.
pub type ReducedRadical<C> = (Var, Poly<C>, i64);

/// The most terms of a norm that a refused division writes out (a longer one by its size):
/// the norm is what to declare, and the user has not seen it.
const NORM_TERMS: usize = 64;
/// The most characters of a norm that a refused division writes out.
const NORM_CHARS: usize = 1200;
/// How many points the independence check tries for each product of radicands before it
/// takes the product for a square.
const SQUARE_POINTS: i64 = 48;
/// The most terms of a radicand that is a square whose root a refusal finds and says.
const MAX_ROOT_TERMS: usize = 200;

impl<C: Coefficient> Poly<C> {
    /// The radicals of `vars` with their radicands, in declaration order (none for a set
    /// without them). Refused: a radicand that does not read, is a constant, is not real, or
    /// has a radical, a denominator atom or an angle in it (a radicand is a polynomial, or a
    /// Laurent polynomial, in the coordinates, momenta and parameters).
    pub fn radicals(vars: &Vars) -> Result<Vec<(Var, Self)>, AlgebraError> {
        vars.radicals()
            .map(|v| {
                let variable = vars.variable(v);
                let text = variable.radicand().unwrap_or_default();
                let invalid = |why: &str| AlgebraError::RadicalRefused {
                    radicals: vec![variable.unicode().to_string()],
                    message: format!("the radicand {text} of {} {why}", variable.unicode()),
                };
                // A radicand that divides by a polynomial would be read again by the division
                // (`Poly::inverse_by_atoms` takes radicands): refused at the second reading.
                if READING.with(|r| r.replace(true)) {
                    return Err(invalid("divides by a polynomial"));
                }
                let r = Self::parse(vars, text);
                READING.with(|r| r.set(false));
                let r = r.map_err(|e| invalid(&format!("does not read: {e}")))?;
                match Self::radicand_refusal(variable.unicode(), &r) {
                    Some(why) => Err(AlgebraError::RadicalRefused {
                        radicals: vec![variable.unicode().to_string()],
                        message: why,
                    }),
                    None => Ok((v, r)),
                }
            })
            .collect()
    }

    /// Why `radicand` cannot stand under the root of the radical shown as `name`, if it
    /// cannot: it is a constant, it holds a radical, a denominator atom or an angle (a radicand
    /// is a polynomial, or a Laurent polynomial, in the coordinates, momenta and parameters),
    /// it is not real, or it is nowhere positive, every term a negative number times even
    /// powers (`−x² − y² − 1`), so that its root is real nowhere.
    pub fn radicand_refusal(name: &str, radicand: &Self) -> Option<String> {
        let vars = &radicand.vars;
        let kind = |w: Var| vars.variable(w).kind();
        if radicand.is_constant() {
            Some(format!(
                "the radicand of {name} is the constant {radicand}: a radical stands for the root \
                 of a function of the variables (write a constant root as a parameter)"
            ))
        } else if vars.vars().any(|w| {
            radicand.contains(w)
                && matches!(
                    kind(w),
                    VarKind::Radical | VarKind::Denominator | VarKind::Angle
                )
        }) {
            Some(format!(
                "the radicand {} has a radical, a denominator or an angle in it: a \
                 radicand is a polynomial in the coordinates, momenta and parameters",
                radicand.brief()
            ))
        } else if radicand.conj() != *radicand {
            Some(format!("the radicand {} is not real", radicand.brief()))
        } else if radicand.is_nowhere_positive() {
            Some(format!(
                "the radicand {} is nowhere positive (each term is a negative number times even \
                 powers), so {name} is real nowhere: a radical stands for the positive root of \
                 its radicand where that is positive",
                radicand.brief()
            ))
        } else {
            None
        }
    }

    /// Whether every term is a negative real number times even powers of the variables, so
    /// that the polynomial is at most 0 at every real point where it is defined (`−x² − y² −
    /// 1`): a sufficient condition, not a decision.
    fn is_nowhere_positive(&self) -> bool {
        self.terms().all(|t| {
            let c = t.coeff().to_gaussian();
            c.is_real() && c.re.is_negative() && t.exponents().iter().all(|e| e % 2 == 0)
        })
    }

    /// How the radical `r` with its radicand reads in messages and reports:
    /// `r = √(x² + y² + z²)`.
    pub fn radical_definition(r: Var, radicand: &Self) -> String {
        format!("{} = √({radicand})", radicand.vars.variable(r).unicode())
    }

    /// Whether the set declares radicals.
    pub fn has_radicals(vars: &Vars) -> bool {
        vars.radicals().next().is_some()
    }

    /// Whether a declared radical occurs in `self` (read from the variables, no radicand
    /// parsed).
    pub(crate) fn has_radicals_in_it(&self) -> bool {
        self.vars.radicals().any(|r| self.contains(r))
    }

    /// Whether the set declares denominator atoms or radicals: variables that stand for
    /// functions of the others, so that equal elements may have different terms (`v · D` and
    /// `1`, `r²` and `R`) and zero is decided by [`Poly::vanishes`], not by the terms.
    pub fn has_relations(vars: &Vars) -> bool {
        Self::has_denominator_atoms(vars) || Self::has_radicals(vars)
    }

    /// Checks that the radicals of `vars` are independent: that no product of their radicands
    /// (one radicand alone included) is the square of a rational function, where the radicals'
    /// products would satisfy relations that [`Poly::vanishes`] does not know (`√(x²)` is
    /// `±x`). Coefficients are in Q(i), where `−S²` is the square `(iS)²`, so a product is
    /// shown not to be a square by a point of small integers where its value is a nonzero
    /// rational whose absolute value is not a rational square; one that is a square up to sign
    /// at every point tried is refused as one.
    ///
    /// ```
    /// use trigpoly::{Expr, Vars};
    /// let builder = Vars::builder().coordinate("x").coordinate("y");
    /// let vars = builder.clone().radical("r", "x^2 + y^2").build().unwrap();
    /// assert!(Expr::check_radicals(&vars).is_ok());
    /// let square = builder.radical("r", "x^2 + 2*x*y + y^2").build().unwrap();
    /// assert!(Expr::check_radicals(&square).is_err());
    /// ```
    pub fn check_radicals(vars: &Vars) -> Result<(), AlgebraError> {
        let radicals = Self::radicals(vars)?;
        if radicals.is_empty() {
            return Ok(());
        }
        if radicals.len() > MAX_RADICALS {
            return Err(AlgebraError::SettingOutOfRange {
                setting: Setting::Radicals,
                value: radicals.len() as u64,
            });
        }
        let used: Vec<Var> = vars
            .vars()
            .filter(|&w| radicals.iter().any(|(_, r)| r.contains(w)))
            .collect();
        let points: Vec<Vec<Rational>> = (0..SQUARE_POINTS)
            .filter_map(|s| {
                let mut point = Point::new(vars);
                for (k, &w) in used.iter().enumerate() {
                    point = point.with(w, small_value(k as i64, s));
                }
                // A point where every radicand has a real, nonzero value.
                radicals
                    .iter()
                    .map(|(_, r)| match r.eval(&point) {
                        Ok(value) if value.is_real() && !value.re.is_zero() => Some(value.re),
                        _ => None,
                    })
                    .collect()
            })
            .collect();
        for subset in 1u32..1 << radicals.len() {
            let chosen = |i: usize| subset & (1 << i) != 0;
            let not_square = points.iter().any(|values| {
                let product = values
                    .iter()
                    .enumerate()
                    .filter(|&(i, _)| chosen(i))
                    .fold(Rational::one(), |acc, (_, v)| &acc * v);
                product.abs().sqrt().is_none()
            });
            if !not_square {
                let names: Vec<String> = radicals
                    .iter()
                    .enumerate()
                    .filter(|&(i, _)| chosen(i))
                    .map(|(_, (v, r))| {
                        format!("{} = √({})", vars.variable(*v).unicode(), r.brief())
                    })
                    .collect();
                // One radicand that is a square, or minus one, of a polynomial: its root,
                // where the radicand is short enough for the root to be found at once and
                // said in a message (`(x² + y² + 1)^500`, 125 751 terms, took minutes).
                let one = (names.len() == 1).then(|| {
                    let radicand = &radicals[subset.trailing_zeros() as usize].1;
                    match radicand.len() <= MAX_ROOT_TERMS {
                        true => radicand.root_up_to_sign(),
                        false => None,
                    }
                });
                let message = match one {
                    // The radicand is the square of a polynomial: the root is known exactly.
                    Some(Some((root, false))) => format!(
                        "the radicand of {} is the square of {root}, so the radical is {root} \
                         up to its sign, which is for you to choose: {}",
                        names[0],
                        root.sign_advice(false)
                    ),
                    Some(Some((root, true))) => format!(
                        "the radicand of {} is minus the square of {root}, so the radical is \
                         i({root}) up to its sign, which is for you to choose: {}",
                        names[0],
                        root.sign_advice(true)
                    ),
                    Some(None) => format!(
                        "the radicand of {} is a square (it is one at every point tried), so \
                         the radical is a rational function of the variables: write it as one",
                        names[0]
                    ),
                    _ => format!(
                        "the product of the radicands of {} is a square (it is one at every \
                         point tried), so one radical is a rational function times the others: \
                         declare only the others",
                        names.join(", ")
                    ),
                };
                let radicals = radicals
                    .iter()
                    .enumerate()
                    .filter(|&(i, _)| chosen(i))
                    .map(|(_, (v, _))| vars.variable(*v).unicode().to_string())
                    .collect();
                return Err(AlgebraError::RadicalRefused { radicals, message });
            }
        }
        Ok(())
    }

    /// The root of `e` by a declared radical: `c·r` when `e = c²·R` for a radical `r` with
    /// radicand `R` and a positive rational `c`, or the positive rational root of a constant
    /// that is a rational square; `None` otherwise (the root of `x²` is `|x|`, no polynomial).
    pub(crate) fn root_by_radicals(e: &Self) -> Result<Option<Self>, AlgebraError> {
        if let Some(c) = e.as_constant() {
            let c = c.to_gaussian();
            let root = match c.is_real() {
                true => c.re.sqrt(),
                false => None,
            };
            return Ok(root.map(|q| Self::constant(&e.vars, C::from_rational(q))));
        }
        for (r, radicand) in Self::radicals(&e.vars)? {
            let (Some(lead_e), Some(lead_r)) = (e.terms().next(), radicand.terms().next()) else {
                continue;
            };
            if lead_e.exponents() != lead_r.exponents() {
                continue;
            }
            // A radicand is real: its leading coefficient is a nonzero rational.
            let (ce, cr) = (lead_e.coeff().to_gaussian(), lead_r.coeff().to_gaussian());
            if !ce.is_real() {
                continue;
            }
            let q = &ce.re / &cr.re;
            if radicand.scale_rational(&q) != *e {
                continue;
            }
            if let Some(c) = q.sqrt() {
                return Ok(Some(Self::var(&e.vars, r).scale_rational(&c)));
            }
        }
        Ok(None)
    }

    /// The root of `self` when it is the square of a polynomial, `(s, false)`, or minus one,
    /// `(s, true)` (then the root is `i·s`), with `s` as [`Poly::square_root`] gives it: what
    /// a radical of `self` would be, up to a sign that the writer chooses.
    pub(crate) fn root_up_to_sign(&self) -> Option<(Self, bool)> {
        let negated = || (-self).square_root().map(|root| (root, true));
        self.square_root()
            .map(|root| (root, false))
            .or_else(negated)
    }

    /// How a message asks for the root `self` (times `i` when `imaginary`) of a square, whose
    /// sign the writer chooses: `write x + y where it is not negative, and its negative
    /// where it is`, or `write i*(x + y) where x + y is not negative, …`.
    pub(crate) fn sign_advice(&self, imaginary: bool) -> String {
        match imaginary {
            false => either_sign(&self.to_ascii(), "it"),
            true => either_sign(&format!("i*({})", self.to_ascii()), &self.to_string()),
        }
    }

    /// The polynomial `s` with a positive leading coefficient whose square is `self`, if
    /// there is one (`x + y` for `x² + 2xy + y²`, `cos θ` for `cos² θ`): what `sqrt` of a
    /// square is, up to its sign, which no polynomial chooses. The schoolbook root: the root
    /// of the leading term, then each next term from the leading term of the remainder
    /// divided by twice the root's leading term. Every term of `s` lies in the half of
    /// `self`'s exponent box (the Newton polytope of `s²` is twice that of `s`), and the terms
    /// come in descending order, so the walk ends; it stops early, after as many terms as
    /// `self` has and a few more, with `None`: also for the rare square whose root has more
    /// terms than that, and when an operation meets a limit (this serves messages, not normal
    /// forms).
    pub(crate) fn square_root(&self) -> Option<Self> {
        let vars = &self.vars;
        let handles: Vec<Var> = vars.vars().collect();
        let ranges = self.bounds();
        // A monomial of `s`: each exponent in half of `self`'s range.
        let half = |e: &[i64]| -> Option<Vec<(Var, i64)>> {
            e.iter()
                .zip(&ranges)
                .zip(&handles)
                .map(|((&x, &(lo, hi)), &v)| (2 * x >= lo && 2 * x <= hi).then_some((v, x)))
                .collect()
        };
        let lead = self.terms().next()?;
        let c = lead.coeff().to_gaussian();
        let root_c = if c.is_real() {
            c.re.sqrt()?
        } else {
            return None;
        };
        let lead_e = lead.exponents();
        if lead_e.iter().any(|e| e % 2 != 0) {
            return None;
        }
        let half_lead: Vec<i64> = lead_e.iter().map(|e| e / 2).collect();
        let mut root =
            Self::monomial(vars, C::from_rational(root_c.clone()), &half(&half_lead)?).ok()?;
        let over_twice_lead = &Rational::one() / &(&Rational::from(2) * &root_c);
        let mut rest = self.checked_sub(&root.checked_mul(&root).ok()?).ok()?;
        for _ in 0..self.len() + 8 {
            let Some(next) = rest.terms().next() else {
                return Some(root);
            };
            let e: Vec<i64> = next
                .exponents()
                .iter()
                .zip(&half_lead)
                .map(|(a, b)| a - b)
                .collect();
            let term = Self::monomial(vars, next.coeff(), &half(&e)?)
                .ok()?
                .scale_rational(&over_twice_lead);
            // (s + t)² = s² + t·(2s + t)
            let twice_plus = root
                .scale_rational(&Rational::from(2))
                .checked_add(&term)
                .ok()?;
            rest = rest
                .checked_sub(&term.checked_mul(&twice_plus).ok()?)
                .ok()?;
            root = root.checked_add(&term).ok()?;
        }
        None
    }

    /// For each radical of the set, the power of it that clears `self` of its negative
    /// powers (`max(0, −lowest exponent)`), with its radicand: what
    /// [`Poly::reduce_radicals`] takes to reduce `self`.
    pub fn radical_powers(&self) -> Result<Vec<ReducedRadical<C>>, AlgebraError> {
        Ok(Self::radicals(&self.vars)?
            .into_iter()
            .map(|(v, r)| {
                let m = -self.low_degree(v).unwrap_or(0).min(0);
                (v, r, m)
            })
            .collect())
    }

    /// `Π r^M · self` reduced by `r² = R`, for each radical `(r, R, M)` in turn: every power
    /// `r^k` (`k ≥ 0` once multiplied) becomes `R^{⌊k/2⌋} r^{k mod 2}`. Each `M` must be at
    /// least the highest power of `1/r` in `self` ([`Poly::radical_powers`] gives the least);
    /// a fixed `M` for many elements makes the map linear, and injective.
    ///
    /// ```
    /// use trigpoly::{Expr, Vars};
    /// let vars = Vars::builder()
    ///     .coordinate("x")
    ///     .coordinate("y")
    ///     .radical("r", "x^2 + y^2")
    ///     .build()
    ///     .unwrap();
    /// let e = |s: &str| Expr::parse(&vars, s).unwrap();
    /// let f = e("x^2/r^3 + y^2/r^3 - 1/r");
    /// let powers = f.radical_powers().unwrap();
    /// assert_eq!(powers[0].2, 3);
    /// assert!(f.reduce_radicals(&powers).unwrap().is_zero());
    /// assert_eq!(e("r^3").reduce_radicals(&e("r^3").radical_powers().unwrap()).unwrap(),
    ///     e("x^2*r + y^2*r"));
    /// ```
    pub fn reduce_radicals(&self, radicals: &[ReducedRadical<C>]) -> Result<Self, AlgebraError> {
        let mut p = self.clone();
        for (r, radicand, m) in radicals {
            p = p.reduce_radical(*r, radicand, *m)?;
        }
        Ok(p)
    }

    /// [`Poly::reduce_radicals`] for one radical.
    fn reduce_radical(&self, r: Var, radicand: &Self, m: i64) -> Result<Self, AlgebraError> {
        let j = self.vars.checked_index(r)?;
        if !self.contains(r) && m == 0 {
            return Ok(self.clone());
        }
        // The terms by the power of R they take, each with r to the power 0 or 1.
        let mut by_power: BTreeMap<i64, Vec<(C, Vec<i64>)>> = BTreeMap::new();
        for t in self.terms() {
            let mut e = t.exponents();
            let k = e[j] + m;
            if k < 0 {
                return Err(AlgebraError::Misuse(Misuse::RadicalPower {
                    radical: self.vars.variable(r).unicode().to_string(),
                    multiplier: m,
                    power: e[j],
                }));
            }
            e[j] = k % 2;
            by_power.entry(k / 2).or_default().push((t.coeff(), e));
        }
        let mut out = Self::zero(&self.vars);
        let (mut power, mut at) = (Self::one(&self.vars), 0);
        for (q, terms) in by_power {
            while at < q {
                power = power.checked_mul(radicand)?;
                at += 1;
            }
            let part = Self::from_terms(&self.vars, terms)?.checked_mul(&power)?;
            out = out.checked_add(&part)?;
        }
        Ok(out)
    }

    /// `1/d` for a `d` with radicals in it, through its conjugates; `None` when `d` has no
    /// radical. For each radical `r = √R` of `d` in turn, `d = r^k (A + B r)` with `A`, `B`
    /// free of `r` (`k` the lowest power of `r` in `d`, the rest reduced by `r² = R`), and
    /// `1/(A + B r) = (A − B r)/(A² − B² R)`, whose denominator has one radical less; when all
    /// are gone the denominator, the norm of `d`, is inverted as [`Poly::checked_div`] inverts
    /// a divisor without radicals: a constant times a single term times powers of declared
    /// denominators and radicands. So `1/(r − x)` is `(r + x)/y²` for `r = √(x² + y²)`, and
    /// `1/(r(r + x))`, the parabolic term of Smorodinsky–Winternitz III, is
    /// `(r − x)/(r y²)`. A norm that is none of those is an error that names it.
    ///
    /// ```
    /// use trigpoly::{Expr, Vars};
    /// let vars = Vars::builder()
    ///     .coordinate("x")
    ///     .coordinate("y")
    ///     .radical("r", "x^2 + y^2")
    ///     .build()
    ///     .unwrap();
    /// let e = |s: &str| Expr::parse(&vars, s).unwrap();
    /// assert_eq!(e("1/(r - x)"), e("(r + x)/y^2"));
    /// assert!((&e("1/(r*(r + x))") * &e("r^2 + x*r") - e("1")).vanishes().unwrap());
    /// let refused = Expr::parse(&vars, "1/(r - 1)").unwrap_err().to_string();
    /// assert!(refused.contains("x^2 + y^2 - 1"), "{refused}");
    /// ```
    pub fn inverse_by_conjugates(d: &Self) -> Result<Option<Self>, AlgebraError> {
        if !d.has_radicals_in_it() {
            return Ok(None);
        }
        let radicals: Vec<(Var, Self)> = Self::radicals(&d.vars)?
            .into_iter()
            .filter(|(r, _)| d.contains(*r))
            .collect();
        let vars = &d.vars;
        let (mut numerator, mut norm) = (Self::one(vars), d.clone());
        for (r, radicand) in &radicals {
            let Some(low) = norm.low_degree(*r) else {
                // Gone with an earlier radical's conjugate.
                continue;
            };
            let rv = Self::var(vars, *r);
            // norm = r^low · (A + B r)
            let reduced = norm.reduce_radical(*r, radicand, -low)?;
            let b = reduced.derivative(*r)?;
            let a = reduced.checked_sub(&b.checked_mul(&rv)?)?;
            numerator = numerator.checked_mul(&rv.checked_pow(-low)?)?;
            norm = match (a.is_zero(), b.is_zero()) {
                (true, true) => {
                    return Err(AlgebraError::DivisorVanishes {
                        shown: d.brief(),
                        definition: Self::radical_definition(*r, radicand),
                    })
                }
                (false, true) => a,
                (true, false) => {
                    numerator = numerator.checked_mul(&rv.checked_pow(-1)?)?;
                    b
                }
                (false, false) => {
                    numerator = numerator.checked_mul(&a.checked_sub(&b.checked_mul(&rv)?)?)?;
                    a.checked_square()?
                        .checked_sub(&b.checked_square()?.checked_mul(radicand)?)?
                }
            };
        }
        if norm.is_zero() {
            return Err(AlgebraError::DivisionByZero);
        }
        let inverse = match norm.is_monomial() {
            true => Some(norm.checked_pow(-1)?),
            false => Self::inverse_by_atoms(&norm)?,
        };
        let Some(inverse) = inverse else {
            // Shown with a positive leading coefficient, as a physicist declares it (the
            // primitive part's lead is positive: the content carries the sign).
            if norm.content().is_negative() {
                norm = -norm;
            }
            // The norm in full where a divisor is brief: the user has not seen it.
            return Err(AlgebraError::NormNotInvertible {
                shown: d.brief(),
                norm: norm.brief_within(NORM_TERMS, NORM_CHARS),
                declare: norm.declaration_within(NORM_TERMS, NORM_CHARS),
            });
        };
        Ok(Some(numerator.checked_mul(&inverse)?))
    }

    /// The same element written with the least powers of its radicals, as results are shown:
    /// for each radical `r` in turn, the terms with the same powers of the other radicals
    /// (`s^{−3}`) are taken together, multiplied by the `r^M` that clears their `1/r`, reduced
    /// by `r² = R` to `A + B r`, and while `R` divides `A`,
    /// `(A + B r)/r^M = (B + (A/R) r)/r^{M−1}`; so `x²/r³ + y²/r³` is `1/r` for `R = x² + y²`,
    /// `r³` is `x²r + y²r`, and `k/r³ + m/s³` stays as it is. A group whose terms are fewer
    /// than that and have no power of `r` above 1 is kept as it is (`1/r + x/r³`): the form is
    /// one of the element's, chosen to read short, not a normal form.
    pub fn with_least_radical_powers(&self) -> Result<Self, AlgebraError> {
        let vars = self.vars.clone();
        let radicals = Self::radicals(&vars)?;
        let mut p = self.clone();
        for (k, (r, radicand)) in radicals.iter().enumerate() {
            let others: Vec<usize> = radicals
                .iter()
                .enumerate()
                .filter(|&(j, _)| j != k)
                .map(|(_, (s, _))| s.index())
                .collect();
            let mut groups: BTreeMap<Vec<i64>, Vec<(C, Vec<i64>)>> = BTreeMap::new();
            for t in p.terms() {
                let e = t.exponents();
                let key = others.iter().map(|&j| e[j]).collect();
                groups.entry(key).or_default().push((t.coeff(), e));
            }
            let mut out = Self::zero(&vars);
            for terms in groups.into_values() {
                let group = Self::from_terms(&vars, terms)?;
                out = out.checked_add(&group.least_powers_of(*r, radicand)?)?;
            }
            p = out;
        }
        Ok(p)
    }

    /// [`Poly::with_least_radical_powers`] for one radical `r` with radicand `R`.
    fn least_powers_of(&self, r: Var, radicand: &Self) -> Result<Self, AlgebraError> {
        let mut m = -self.low_degree(r).unwrap_or(0).min(0);
        let mut p = self.reduce_radical(r, radicand, m)?;
        let rv = Self::var(&self.vars, r);
        while m > 0 {
            let b = p.derivative(r)?;
            let a = p.checked_sub(&b.checked_mul(&rv)?)?;
            match a.laurent_quotient_by(radicand)? {
                Some(a) => {
                    p = b.checked_add(&a.checked_mul(&rv)?)?;
                    m -= 1;
                }
                None => break,
            }
        }
        if m > 0 && !p.is_zero() {
            p = p.checked_mul(&rv.checked_pow(-m)?)?;
        }
        // The terms as they were when they are fewer and no power of `r` in them could be
        // lowered (`1/r + x/r³`, not `x²/r³ + x/r³ + y²/r³ + z²/r³`).
        let lowered = self.degree(r).is_none_or(|d| d <= 1);
        if lowered && self.len() < p.len() {
            return Ok(self.clone());
        }
        Ok(p)
    }

    /// `self / d` when `d` divides `self` exactly, negative powers allowed in `self` (`c/x³` and
    /// a radicand in `x`): the division runs on `self` times the monomial that clears them, a
    /// unit, whose inverse then multiplies the quotient.
    fn laurent_quotient_by(&self, d: &Self) -> Result<Option<Self>, AlgebraError> {
        let unit: Vec<(Var, i64)> = self
            .vars
            .vars()
            .filter_map(|v| {
                self.low_degree(v)
                    .filter(|&low| low < 0)
                    .map(|low| (v, -low))
            })
            .collect();
        if unit.is_empty() {
            return self.quotient_by(d);
        }
        let unit = Self::monomial(&self.vars, C::one(), &unit)?;
        let Some(q) = self.checked_mul(&unit)?.quotient_by(d)? else {
            return Ok(None);
        };
        Ok(Some(q.checked_mul(&unit.checked_pow(-1)?)?))
    }
}

/// How a message asks for the root of a square, whose sign is for you to choose:
/// `write x + y where it is not negative, and its negative where it is`, for `written` the
/// root as the user writes it and `subject` what its sign is the sign of.
fn either_sign(written: &str, subject: &str) -> String {
    format!("write {written} where {subject} is not negative, and its negative where it is")
}

/// The `k`-th variable's value at the `s`-th point of the independence check: small integers,
/// positive and negative, that vary with both.
fn small_value(k: i64, s: i64) -> Rational {
    let v = (7 * k + 3) * (s + 1) + s * s;
    Rational::new(v % 23 - 11, 1)
}

#[cfg(test)]
mod tests {
    use crate::{Expr, Vars};

    fn kepler() -> crate::Vars {
        Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .coordinate("z")
            .parameter("k")
            .radical("r", "x^2 + y^2 + z^2")
            .build()
            .unwrap()
    }

    #[test]
    fn an_element_is_zero_exactly_when_it_reduces_to_zero() {
        let vars = kepler();
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        assert!(e("r^2 - x^2 - y^2 - z^2").vanishes().unwrap());
        assert!(e("x^2/r^3 + y^2/r^3 + z^2/r^3 - 1/r").vanishes().unwrap());
        assert!(e("r^4 - (x^2 + y^2 + z^2)*r^2").vanishes().unwrap());
        // r is not a polynomial: r − x, r² − x² are not zero.
        assert!(!e("r - x").vanishes().unwrap());
        assert!(!e("r^2 - x^2").vanishes().unwrap());
        assert!(!e("x/r^3 - x/r").vanishes().unwrap());
    }

    #[test]
    fn over_a_common_denominator_a_radical_keeps_its_least_powers() {
        let vars = kepler();
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        let reduced = |s: &str| e(s).over_common_denominators().unwrap();
        assert_eq!(reduced("x^2/r^3 + y^2/r^3 + z^2/r^3"), e("1/r"));
        assert_eq!(reduced("-k*x/r^3"), e("-k*x/r^3"));
        assert_eq!(reduced("r^2"), e("x^2 + y^2 + z^2"));
        assert_eq!(reduced("(x^2 + y^2 + z^2)/r - r"), e("0"));
        assert_eq!(reduced("x*r^3"), e("x*(x^2 + y^2 + z^2)*r"));
        // A radicand divides a numerator with negative powers too.
        assert_eq!(reduced("k*(x^2 + y^2 + z^2)/(x^3*r^2)"), e("k/x^3"));
        assert_eq!(
            reduced("k*x^2/(y*r^3) + k*(y^2 + z^2)/(y*r^3)"),
            e("k/(y*r)")
        );
        // Shorter as written: kept.
        assert_eq!(reduced("1/r + x/r^3"), e("1/r + x/r^3"));
    }

    /// With two radicals, each is written with its least powers among the terms that share
    /// the other's: `k/r³ + m/s³` is not brought to one power of both.
    #[test]
    fn two_radicals_keep_their_own_powers() {
        let vars = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .parameter("k")
            .parameter("m")
            .radical("r", "(x - 1)^2 + y^2")
            .radical("s", "(x + 1)^2 + y^2")
            .build()
            .unwrap();
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        let reduced = |s: &str| e(s).over_common_denominators().unwrap();
        assert_eq!(reduced("k/r^3 + m/s^3"), e("k/r^3 + m/s^3"));
        assert_eq!(reduced("r^2/s - (x - 1)^2/s - y^2/s + m/s"), e("m/s"));
        assert_eq!(reduced("r*s/r"), e("s"));
        assert!(e("r^2*s^2 - ((x - 1)^2 + y^2)*((x + 1)^2 + y^2)")
            .vanishes()
            .unwrap());
        assert!(!e("r*s - (x^2 + y^2 + 1)").vanishes().unwrap());
    }

    /// A divisor with radicals is inverted through its conjugates: the inverse is exact (its
    /// product with the divisor is 1), written without the radicals in its denominator, over
    /// one radical or two; a divisor that is zero once reduced is a division by zero, and one
    /// whose norm is not invertible is refused with the norm to declare, after which it
    /// divides.
    #[test]
    fn division_by_a_sum_with_radicals_goes_through_its_conjugates() {
        let builder = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .parameter("k")
            .radical("r", "x^2 + y^2")
            .radical("s", "x^2 + y^2 + 1");
        let vars = builder.clone().build().unwrap();
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        // (r − x)(r + x) = r² − x² = y².
        assert_eq!(e("1/(r - x)"), e("(r + x)/y^2"));
        assert_eq!(e("k/(r + x)"), e("k*(r - x)/y^2"));
        assert_eq!(e("(r - x)^-2"), e("(r + x)^2/y^4"));
        // (r + s)(s − r) = s² − r² = 1.
        assert_eq!(e("1/(r + s)"), e("s - r"));
        for divisor in [
            "r - x",
            "r*(r + x)",
            "r + s",
            "r + s + 1",
            "k*r + k*x",
            "x/r - 1",
        ] {
            let d = e(divisor);
            let product = e(&format!("1/({divisor})")).checked_mul(&d).unwrap();
            assert!((product - e("1")).vanishes().unwrap(), "{divisor}");
        }
        let err = |s: &str| Expr::parse(&vars, s).unwrap_err().to_string();
        assert_eq!(
            err("1/(r^2 - x^2 - y^2)"),
            "line 1, column 3: division by zero: −x² − y² + r² is 0, as r = √(x² + y²)\n  \
             1/(r^2 - x^2 - y^2)\n    ^^^^^^^^^^^^^^^^^"
        );
        let refused = err("1/(r - 1)");
        assert!(
            refused.contains("cannot divide by r − 1")
                && refused.contains("a division by its norm, ±(x² + y² − 1), and that is not")
                && refused.contains("denominators = [\"x^2 + y^2 - 1\"]"),
            "{refused}"
        );
        let declared = builder
            .denominator("x^2 + y^2 - 1")
            .unwrap()
            .build()
            .unwrap();
        let e = |s: &str| Expr::parse(&declared, s).unwrap();
        let product = e("1/(r - 1)").checked_mul(&e("r - 1")).unwrap();
        assert!((product - e("1")).vanishes().unwrap());
    }

    /// The square root of a square is the polynomial with a positive leading coefficient whose
    /// square it is, with rational and Gaussian coefficients, negative powers and angles; a
    /// polynomial that is no square (an odd power, a coefficient that is no rational square, a
    /// term too many, a negative leading coefficient) has none.
    #[test]
    fn square_roots_of_squares_and_of_nothing_else() {
        let vars = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .momentum("p")
            .angle("theta")
            .parameter("k")
            .build()
            .unwrap();
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        for root in [
            "x",
            "x + y",
            "2*x - 3*y + 1/2",
            "x^3*y - k*p^2 + 7",
            "x/y + y/x",
            "k^-2 + p",
            "cos(theta)",
            "p*sin(theta) + x*cos(2*theta)",
            "x + i*y",
            "(1 + x + y + p)^4",
        ] {
            let s = e(root);
            let square = s.checked_mul(&s).unwrap();
            // The root whose leading coefficient is positive: `s` or `−s`.
            let lead = s.terms().next().unwrap().coeff();
            let expected = if lead.re.is_negative() { -&s } else { s };
            assert_eq!(square.square_root(), Some(expected), "{root}");
        }
        for not_square in [
            "x",
            "x^3",
            "2*x^2",
            "x^2 + 1",
            "x^2 + x",
            "x^2 + 2*x*y",
            "-x^2",
            "x^2*y^2 + 1",
            "cos(theta)^2 + 1",
            "(1 + x + y + p)^4 + x",
        ] {
            assert_eq!(e(not_square).square_root(), None, "{not_square}");
        }
    }

    #[test]
    fn dependent_radicals_are_refused() {
        let build = |radicals: &[(&str, &str)]| {
            let mut b = Vars::builder().coordinate("x").coordinate("y");
            for (name, radicand) in radicals {
                b = b.radical(name, radicand);
            }
            b.build().unwrap()
        };
        let ok = build(&[("r", "(x - 1)^2 + y^2"), ("s", "(x + 1)^2 + y^2")]);
        assert!(Expr::check_radicals(&ok).is_ok());
        let square = build(&[("r", "4*x^2")]);
        let err = Expr::check_radicals(&square).unwrap_err().to_string();
        assert!(
            err.contains("the radicand of r = √(4x²) is the square of 2x, so the radical is 2x"),
            "{err}"
        );
        // √(x² + y²) · √(4x² + 4y²) = 2(x² + y²).
        let product = build(&[("r", "x^2 + y^2"), ("s", "4*x^2 + 4*y^2")]);
        let err = Expr::check_radicals(&product).unwrap_err().to_string();
        assert!(err.contains("the product of the radicands of r"), "{err}");
        // Over Q(i), −(x + y)² is the square of i(x + y).
        let imaginary = build(&[("r", "-x^2 - 2*x*y - y^2")]);
        let err = Expr::check_radicals(&imaginary).unwrap_err().to_string();
        assert!(
            err.contains(
                "the radicand of r = √(−x² − 2xy − y²) is minus the square of x + y, so the \
                 radical is i(x + y) up to its sign, which is for you to choose: write \
                 i*(x + y) where x + y is not negative, and its negative where it is"
            ),
            "{err}"
        );
        // Not a square over Q(i), but nowhere positive: real nowhere. One that changes sign
        // is real where it is positive.
        let negative = build(&[("r", "-x^2 - y^2")]);
        let err = Expr::check_radicals(&negative).unwrap_err().to_string();
        assert!(err.contains("is nowhere positive"), "{err}");
        assert!(Expr::check_radicals(&build(&[("r", "y^2 - x^2")])).is_ok());
        let constant = build(&[("r", "2")]);
        assert!(Expr::check_radicals(&constant).is_err());
        let inside = build(&[("r", "x^2 + y^2"), ("s", "r + x")]);
        let err = Expr::check_radicals(&inside).unwrap_err().to_string();
        assert!(err.contains("has a radical"), "{err}");
        let fraction = build(&[("r", "1/(x + y)")]);
        let err = Expr::check_radicals(&fraction).unwrap_err().to_string();
        assert!(err.contains("divides by a polynomial"), "{err}");
    }
}
