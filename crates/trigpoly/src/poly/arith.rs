//! Addition, subtraction, negation, scalar multiples and exact division by a term, with the
//! operator traits for all owned/borrowed combinations.

use std::ops::{Add, AddAssign, Mul, MulAssign, Neg, Sub, SubAssign};

use super::Poly;
use crate::error::AlgebraError;
use crate::number::{Coefficient, GaussianRational, Integer, IntegerRing, Rational};

impl<C: Coefficient> Poly<C> {
    // f + g with f = a·F, g = b·G: d = gcd(a, b), f + g = d·((a/d)·F + (b/d)·G).
    fn combine(&self, other: &Self, negate_other: bool) -> Result<Self, AlgebraError> {
        self.same_vars(other)?;
        if other.is_zero() {
            return Ok(self.clone());
        }
        if self.is_zero() {
            return Ok(if negate_other { -other } else { other.clone() });
        }
        // Equal term lists (as in an identity's residual `a − a`): only the contents add, so
        // nothing is merged, and a sum that cancels costs no allocation.
        if self.exps == other.exps && self.coeffs == other.coeffs {
            let content = if negate_other {
                &self.content - &other.content
            } else {
                &self.content + &other.content
            };
            if content.is_zero() {
                return Ok(Self::zero(&self.vars));
            }
            return Ok(self.with_content(content));
        }
        let (d, sa, mut sb) = Rational::content_split(&self.content, &other.content);
        if negate_other {
            sb = -sb;
        }
        let (exps, coeffs) = merge(self, &sa, other, &sb);
        Self::check_terms(&self.vars, coeffs.len())?;
        Ok(Self::drop_zeros_and_normalize(&self.vars, d, exps, coeffs))
    }

    /// `self + other`, or an error if the variable sets differ or the term limit is hit.
    pub fn checked_add(&self, other: &Self) -> Result<Self, AlgebraError> {
        self.combine(other, false)
    }

    /// `self − other`, or an error if the variable sets differ or the term limit is hit.
    pub fn checked_sub(&self, other: &Self) -> Result<Self, AlgebraError> {
        self.combine(other, true)
    }

    /// `c · self`.
    #[must_use]
    pub fn scale(&self, c: &C) -> Self {
        let (q, n) = c.split();
        if q.is_zero() || self.is_zero() {
            return Self::zero(&self.vars);
        }
        let content = &self.content * &q;
        if n.is_one() {
            return self.with_content(content);
        }
        let coeffs = self.coeffs.iter().map(|x| x.mul(&n)).collect();
        Self::from_sorted(&self.vars, content, self.exps.clone(), coeffs)
    }

    /// `q · self` for a rational `q` (a copy; `f * &q` takes `f` and copies nothing).
    #[must_use]
    pub fn scale_rational(&self, q: &Rational) -> Self {
        self.clone() * q
    }

    /// `self / d` where `d` is a nonzero constant or a single term, or (with denominator atoms
    /// declared) such a term times a product of powers of the atoms' polynomials, or (with
    /// radicals) a sum whose product with its conjugates is one of those
    /// ([`Poly::inverse_by_conjugates`]); anything else is an error (the quotient would not be
    /// in the ring).
    pub fn checked_div(&self, d: &Self) -> Result<Self, AlgebraError> {
        self.same_vars(d)?;
        if d.is_zero() {
            return Err(AlgebraError::DivisionByZero);
        }
        if !d.is_monomial() {
            if let Some(inverse) = Self::inverse_of_sum(d)? {
                return self.checked_mul(&inverse);
            }
            // `r² cos²φ` prints as one term: say why it is not one.
            return Err(if d.has_angles() && d.one_monomial_but_for_angles() {
                AlgebraError::NotAMonomialInAngles(d.brief())
            } else {
                AlgebraError::NotAMonomial {
                    shown: d.brief(),
                    declare: d.declaration(),
                }
            });
        }
        self.checked_mul(&d.checked_pow(-1)?)
    }

    /// `1/d` for a `d` of several terms: through its conjugates when a radical is in it
    /// ([`Poly::inverse_by_conjugates`]), else by the declared atoms and radicands
    /// ([`Poly::inverse_by_atoms`]); `None` when neither applies. What [`Poly::checked_div`]
    /// and negative powers divide by.
    pub(crate) fn inverse_of_sum(d: &Self) -> Result<Option<Self>, AlgebraError> {
        match d.has_radicals_in_it() {
            true => Self::inverse_by_conjugates(d),
            false => Self::inverse_by_atoms(d),
        }
    }

    /// Whether every term has the same exponents in the variables other than the angles
    /// (`r² cos²φ`: a single term times a function of the angles).
    fn one_monomial_but_for_angles(&self) -> bool {
        let others: Vec<usize> = self
            .vars
            .vars()
            .filter(|&v| self.vars.variable(v).kind() != crate::VarKind::Angle)
            .map(|v| v.index())
            .collect();
        let layout = self.layout();
        let mut monomials = self.exps.chunks_exact(self.words());
        let Some(first) = monomials.next() else {
            return true;
        };
        monomials.all(|m| {
            others
                .iter()
                .all(|&j| layout.get(m, j) == layout.get(first, j))
        })
    }

    /// Multiplies every term by `i` (needs Q(i)).
    pub fn mul_i(&self) -> Result<Self, AlgebraError> {
        let coeffs = self
            .coeffs
            .iter()
            .map(|c| c.try_mul_i())
            .collect::<Option<Vec<_>>>()
            .ok_or_else(|| AlgebraError::NeedsGaussian("multiplication by i".into()))?;
        // `i·(a + bi) = −b + ai` keeps the components' sizes, so they stay coprime.
        Ok(Self::from_sorted_coprime(
            &self.vars,
            self.content.clone(),
            self.exps.clone(),
            coeffs,
        ))
    }
}

/// Merges two sorted term lists with integer scale factors: `sa·a + sb·b` (zeros may remain).
pub(crate) fn merge<C: Coefficient>(
    a: &Poly<C>,
    sa: &Integer,
    b: &Poly<C>,
    sb: &Integer,
) -> (Vec<u64>, Vec<C::Int>) {
    // Monomials of a width known at compile time are copied in place (a runtime width is a
    // `memcpy` call per term).
    match a.words() {
        1 => merge_of_width::<C, 1>(a, sa, b, sb),
        2 => merge_of_width::<C, 2>(a, sa, b, sb),
        3 => merge_of_width::<C, 3>(a, sa, b, sb),
        4 => merge_of_width::<C, 4>(a, sa, b, sb),
        _ => merge_of_width::<C, 0>(a, sa, b, sb),
    }
}

/// [`merge`] for monomials of `W` words (`W = 0`: the polynomials' width, read at run time).
#[inline(always)]
fn merge_of_width<C: Coefficient, const W: usize>(
    a: &Poly<C>,
    sa: &Integer,
    b: &Poly<C>,
    sb: &Integer,
) -> (Vec<u64>, Vec<C::Int>) {
    let w = if W == 0 { a.words() } else { W };
    let (n, m) = (a.len(), b.len());
    let mut exps = Vec::with_capacity((n + m) * w);
    let mut coeffs = Vec::with_capacity(n + m);
    let scale = |c: &C::Int, s: &Integer| if s.is_one() { c.clone() } else { c.scale(s) };
    let (mut i, mut j) = (0, 0);
    while i < n && j < m {
        match monomial(a, i, w).cmp(monomial(b, j, w)) {
            std::cmp::Ordering::Greater => {
                exps.extend_from_slice(monomial(a, i, w));
                coeffs.push(scale(&a.coeffs[i], sa));
                i += 1;
            }
            std::cmp::Ordering::Less => {
                exps.extend_from_slice(monomial(b, j, w));
                coeffs.push(scale(&b.coeffs[j], sb));
                j += 1;
            }
            std::cmp::Ordering::Equal => {
                let c = scale(&a.coeffs[i], sa).add(&scale(&b.coeffs[j], sb));
                if !c.is_zero() {
                    exps.extend_from_slice(monomial(a, i, w));
                    coeffs.push(c);
                }
                i += 1;
                j += 1;
            }
        }
    }
    for k in i..n {
        exps.extend_from_slice(monomial(a, k, w));
        coeffs.push(scale(&a.coeffs[k], sa));
    }
    for k in j..m {
        exps.extend_from_slice(monomial(b, k, w));
        coeffs.push(scale(&b.coeffs[k], sb));
    }
    (exps, coeffs)
}

/// The monomial of term `k` of `p`, of `w` words.
#[inline(always)]
fn monomial<C: Coefficient>(p: &Poly<C>, k: usize, w: usize) -> &[u64] {
    &p.exps[k * w..(k + 1) * w]
}

/// `q · f` for a rational `q`, taking `f` (no copy of its terms, only a new content).
impl<C: Coefficient> Mul<&Rational> for Poly<C> {
    type Output = Poly<C>;
    fn mul(mut self, q: &Rational) -> Poly<C> {
        self *= q;
        self
    }
}

/// `q · f` for a rational `q`, copying `f`'s terms once with a new content
/// ([`Poly::scale_rational`]).
impl<C: Coefficient> Mul<&Rational> for &Poly<C> {
    type Output = Poly<C>;
    fn mul(self, q: &Rational) -> Poly<C> {
        if q.is_zero() || self.is_zero() {
            return Poly::zero(&self.vars);
        }
        self.with_content(&self.content * q)
    }
}

/// `q · f`, taking both.
impl<C: Coefficient> Mul<Rational> for Poly<C> {
    type Output = Poly<C>;
    fn mul(self, q: Rational) -> Poly<C> {
        self * &q
    }
}

/// `q · f`, taking `q`.
impl<C: Coefficient> Mul<Rational> for &Poly<C> {
    type Output = Poly<C>;
    fn mul(self, q: Rational) -> Poly<C> {
        self * &q
    }
}

/// `f ← q · f`, with no copy of `f`'s terms.
impl<C: Coefficient> MulAssign<&Rational> for Poly<C> {
    fn mul_assign(&mut self, q: &Rational) {
        if q.is_zero() || self.is_zero() {
            *self = Poly::zero(&self.vars);
        } else {
            self.content = &self.content * q;
        }
    }
}

/// `f ← q · f`, with no copy of `f`'s terms.
impl<C: Coefficient> MulAssign<Rational> for Poly<C> {
    fn mul_assign(&mut self, q: Rational) {
        *self *= &q;
    }
}

/// `c · f` for a Gaussian rational `c`, the coefficients' own field: `i·f`, `(2 − i)·f`
/// ([`Poly::scale`]), as `f * &q` is for a rational `q`.
///
/// ```
/// use trigpoly::{Expr, GaussianRational, Rational, Vars};
///
/// let vars = Vars::builder().coordinate("x").momentum("p_x").build()?;
/// let f = Expr::parse(&vars, "p_x + x")?;
/// let i = GaussianRational::i();
/// assert_eq!(&f * &i, Expr::parse(&vars, "i*p_x + i*x")?);
/// let half = GaussianRational::from(Rational::new(1, 2));
/// let mut g = f.clone() * half;
/// g *= &i;
/// assert_eq!(g, f.scale(&"i/2".parse()?));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
impl Mul<&GaussianRational> for &Poly<GaussianRational> {
    type Output = Poly<GaussianRational>;
    fn mul(self, c: &GaussianRational) -> Poly<GaussianRational> {
        self.scale(c)
    }
}

/// `c · f`, taking `f`: with no copy of its terms where `c` is rational.
impl Mul<&GaussianRational> for Poly<GaussianRational> {
    type Output = Poly<GaussianRational>;
    fn mul(mut self, c: &GaussianRational) -> Poly<GaussianRational> {
        self *= c;
        self
    }
}

/// `c · f`, taking `c`.
impl Mul<GaussianRational> for &Poly<GaussianRational> {
    type Output = Poly<GaussianRational>;
    fn mul(self, c: GaussianRational) -> Poly<GaussianRational> {
        self * &c
    }
}

/// `c · f`, taking both.
impl Mul<GaussianRational> for Poly<GaussianRational> {
    type Output = Poly<GaussianRational>;
    fn mul(self, c: GaussianRational) -> Poly<GaussianRational> {
        self * &c
    }
}

/// `f ← c · f`, with no copy of `f`'s terms where `c` is rational (its content changes).
impl MulAssign<&GaussianRational> for Poly<GaussianRational> {
    fn mul_assign(&mut self, c: &GaussianRational) {
        match c.is_real() {
            true => *self *= &c.re,
            false => *self = self.scale(c),
        }
    }
}

/// `f ← c · f`.
impl MulAssign<GaussianRational> for Poly<GaussianRational> {
    fn mul_assign(&mut self, c: GaussianRational) {
        *self *= &c;
    }
}

impl<C: Coefficient> Neg for &Poly<C> {
    type Output = Poly<C>;
    fn neg(self) -> Poly<C> {
        self.with_content(-&self.content)
    }
}

impl<C: Coefficient> Neg for Poly<C> {
    type Output = Poly<C>;
    fn neg(mut self) -> Poly<C> {
        self.content = -std::mem::take(&mut self.content);
        self
    }
}

macro_rules! forward_poly_binop {
    ($Trait:ident, $method:ident, $Assign:ident, $assign:ident, $checked:ident) => {
        /// Panics if the variable sets differ or a limit of the `VarSet` is exceeded; the
        /// `checked_*` method returns that as an error instead.
        impl<C: Coefficient> $Trait<&Poly<C>> for &Poly<C> {
            type Output = Poly<C>;
            fn $method(self, rhs: &Poly<C>) -> Poly<C> {
                self.$checked(rhs).unwrap_or_else(|e| panic!("{e}"))
            }
        }
        impl<C: Coefficient> $Trait<Poly<C>> for &Poly<C> {
            type Output = Poly<C>;
            fn $method(self, rhs: Poly<C>) -> Poly<C> {
                self.$method(&rhs)
            }
        }
        impl<C: Coefficient> $Trait<&Poly<C>> for Poly<C> {
            type Output = Poly<C>;
            fn $method(self, rhs: &Poly<C>) -> Poly<C> {
                (&self).$method(rhs)
            }
        }
        impl<C: Coefficient> $Trait<Poly<C>> for Poly<C> {
            type Output = Poly<C>;
            fn $method(self, rhs: Poly<C>) -> Poly<C> {
                (&self).$method(&rhs)
            }
        }
        impl<C: Coefficient> $Assign<&Poly<C>> for Poly<C> {
            fn $assign(&mut self, rhs: &Poly<C>) {
                *self = (&*self).$method(rhs);
            }
        }
        impl<C: Coefficient> $Assign<Poly<C>> for Poly<C> {
            fn $assign(&mut self, rhs: Poly<C>) {
                *self = (&*self).$method(&rhs);
            }
        }
    };
}

forward_poly_binop!(Add, add, AddAssign, add_assign, checked_add);
forward_poly_binop!(Sub, sub, SubAssign, sub_assign, checked_sub);
forward_poly_binop!(Mul, mul, MulAssign, mul_assign, checked_mul);
