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
    #[must_use]
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

    /// The conjugate, the real part `(f + conj f)/2` and the imaginary part
    /// `(f − conj f)/(2i)` at once: one conjugation and one pass over both term lists, which
    /// gives the monomials of both parts. When `f` and its conjugate share no monomial (a
    /// `K_{m,n} = Z^m e^{−inθ}`, whose angle exponent is `−n ≠ 0` in every term), the parts
    /// keep the coefficients of `f` up to sign and `i`, and need no gcd.
    pub fn conj_re_im(&self) -> (Self, Self, Self) {
        let conj = self.conj();
        if !C::HAS_I || self.is_zero() {
            // Over Q every function is real.
            return (conj, self.clone(), Self::zero(&self.vars));
        }
        let w = self.words();
        let (n, m) = (self.len(), conj.len());
        let (d, sa, sb) = Rational::content_split(&self.content, &conj.content);
        let scale = |c: &C::Int, s: &Integer| if s.is_one() { c.clone() } else { c.scale(s) };
        // −i·c (over Q(i), where every coefficient has a product by i).
        let minus_i = |c: &C::Int| c.try_mul_i().expect("over Q(i)").neg();
        let (mut re_e, mut im_e) = (
            Vec::with_capacity((n + m) * w),
            Vec::with_capacity((n + m) * w),
        );
        let (mut re_c, mut im_c) = (Vec::with_capacity(n + m), Vec::with_capacity(n + m));
        let mut overlap = false;
        let (mut i, mut j) = (0, 0);
        while i < n || j < m {
            let order = match (i < n, j < m) {
                (true, true) => self.exp(i).cmp(conj.exp(j)),
                (true, false) => std::cmp::Ordering::Greater,
                _ => std::cmp::Ordering::Less,
            };
            // re: sa·F + sb·F̄; im: −i·(sa·F − sb·F̄).
            let (monomial, re, im) = match order {
                std::cmp::Ordering::Greater => {
                    let a = scale(&self.coeffs[i], &sa);
                    i += 1;
                    let im = minus_i(&a);
                    (self.exp(i - 1), a, im)
                }
                std::cmp::Ordering::Less => {
                    let b = scale(&conj.coeffs[j], &sb);
                    j += 1;
                    let im = minus_i(&b.neg());
                    (conj.exp(j - 1), b, im)
                }
                std::cmp::Ordering::Equal => {
                    overlap = true;
                    let (a, b) = (scale(&self.coeffs[i], &sa), scale(&conj.coeffs[j], &sb));
                    i += 1;
                    j += 1;
                    (self.exp(i - 1), a.add(&b), minus_i(&a.sub(&b)))
                }
            };
            if !re.is_zero() {
                re_e.extend_from_slice(monomial);
                re_c.push(re);
            }
            if !im.is_zero() {
                im_e.extend_from_slice(monomial);
                im_c.push(im);
            }
        }
        let half = &d * &Rational::new(1, 2);
        let build = |exps, coeffs| {
            if overlap {
                Self::from_sorted(&self.vars, half.clone(), exps, coeffs)
            } else {
                Self::from_sorted_coprime(&self.vars, half.clone(), exps, coeffs)
            }
        };
        (conj, build(re_e, re_c), build(im_e, im_c))
    }

    /// Whether the function is real-valued: `conj(f) = f`.
    pub fn is_real(&self) -> bool {
        self.conj() == *self
    }

    /// The real part `(f + conj f)/2`, or an error if it passes the term limit (`re e^{iθ}`
    /// has two terms).
    pub fn re(&self) -> Result<Self, AlgebraError> {
        Ok(self.checked_add(&self.conj())? * &Rational::new(1, 2))
    }

    /// The imaginary part `(f − conj f)/(2i)`; needs Q(i) unless `f` is real, and is an error
    /// if it passes the term limit.
    pub fn im(&self) -> Result<Self, AlgebraError> {
        let d = self.checked_sub(&self.conj())?;
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

/// A polynomial over Q as the same one over Q(i), in the same variable set
/// ([`Poly::to_gaussian`]): Q lies in Q(i), so every one converts, as a `Rational` into a
/// `GaussianRational`.
///
/// ```
/// use trigpoly::{Expr, Poly, Rational, Vars};
///
/// let vars = Vars::builder().coordinate("x").momentum("p_x").build()?;
/// let over_q = Poly::<Rational>::parse(&vars, "p_x^2/2 + x/3")?;
/// assert_eq!(Expr::from(&over_q), Expr::parse(&vars, "p_x^2/2 + x/3")?);
/// assert_eq!(Expr::from(over_q.clone()), over_q.to_gaussian());
/// assert_eq!(Expr::from(over_q).vars(), &vars);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
impl From<&Poly<Rational>> for Poly<GaussianRational> {
    fn from(p: &Poly<Rational>) -> Self {
        p.to_gaussian()
    }
}

/// As `From<&Poly<Rational>>`, taking the polynomial.
impl From<Poly<Rational>> for Poly<GaussianRational> {
    fn from(p: Poly<Rational>) -> Self {
        p.to_gaussian()
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
