//! `Poly<C>`: exact Laurent polynomials in the variables of a `VarSet`, with each angle `θ`
//! carried as `e^{iθ}`, over Q or Q(i).
//!
//! Representation: a rational content times a primitive polynomial over the integer ring
//! (`C::Int`), terms sorted by packed exponent words in strictly descending order. This module
//! holds the type, its invariant and accessors; arithmetic, multiplication, calculus,
//! substitution, conjugation, trigonometry and printing live in the sibling files.

mod arith;
mod calculus;
mod coeffs;
mod complex;
mod denominators;
mod dense;
mod division;
mod gather;
mod hashed;
mod index;
mod kronecker;
mod mul;
mod pow;
mod power_terms;
mod radicals;
mod subst;
mod sum;
mod sum_at;
mod trig;

use std::fmt;
use std::hash::{Hash, Hasher};
use std::sync::atomic::{AtomicU8, Ordering};

use crate::error::AlgebraError;
use crate::number::{Coefficient, ExactDivisor, GaussianRational, Integer, IntegerRing, Rational};
use crate::varset::{Layout, Var, VarKind, VarSet, Vars};
use coeffs::Coeffs;

pub use division::{Division, DivisionOrder, DivisionRefusal};
pub use index::MonomialIndex;
pub use radicals::ReducedRadical;
pub use subst::Point;
pub(crate) use trig::PrintOrder;
pub use trig::{CosSinTerm, TrigMonomial};

/// The most bits a component of a coefficient of a product or a power may have (2 MiB of
/// digits): a fixed bound, which no limit raises.
pub(crate) const MAX_COEFFICIENT_BITS: u64 = 1 << 24;

/// Refuses a product or a power whose coefficients may have `bits` bits, past
/// [`MAX_COEFFICIENT_BITS`].
pub(crate) fn check_coefficient_size(bits: u64) -> Result<(), AlgebraError> {
    if bits > MAX_COEFFICIENT_BITS {
        return Err(AlgebraError::CoefficientTooLarge {
            bits,
            limit: MAX_COEFFICIENT_BITS,
        });
    }
    Ok(())
}

/// An exact Laurent polynomial over `C` in the variables of a [`VarSet`].
///
/// Invariant (kept by every operation, so equality is structural and the zero test is "no
/// terms"): terms sorted by exponent vector in strictly descending lexicographic order, no zero
/// coefficient, integer coefficients with coprime components whose leading one is positive,
/// and the rational `content` carrying the rest (zero exactly for the zero polynomial).
///
/// Angles are stored in the basis `e^{ikθ}`, `k ∈ Z`, which is a normal form of the ring
/// `Q(i)[cos θ, sin θ]/(cos²θ + sin²θ − 1)`; printing converts to the form `A(cos θ) + sin θ·B(cos θ)`.
///
/// ```
/// use trigpoly::{Poly, GaussianRational, Vars};
/// let vars = Vars::builder().coordinate("x").angle("theta").build().unwrap();
/// let c = Poly::<GaussianRational>::parse(&vars, "cos(theta)").unwrap();
/// let s = Poly::<GaussianRational>::parse(&vars, "sin(theta)").unwrap();
/// assert_eq!(&c * &c + &s * &s, Poly::one(&vars));
/// ```
#[derive(Clone)]
pub struct Poly<C: Coefficient> {
    vars: Vars,
    content: Rational,
    exps: Vec<u64>,
    coeffs: Coeffs<C::Int>,
    /// The bit length `b` of [`Poly::exponent_bound`] `= 2^b`, computed when first asked
    /// for: a polynomial that enters many products (a generator, a Hamiltonian's gradient)
    /// has its exponents read once.
    exponent_bound: Cached,
    /// [`Poly::small_bits`], computed when first asked for, likewise for its coefficients
    /// (`u8::MAX − 1` stands for `None`).
    small_bits: Cached,
    /// [`Poly::real_coefficients`], computed when first asked for (1 for true).
    real_coefficients: Cached,
}

/// A byte computed from a polynomial's terms when first asked for (plus one; 0 until then).
/// One byte of state, in the padding of the struct; relaxed atomics, since every thread that
/// computes it writes the same value.
#[derive(Default)]
struct Cached(AtomicU8);

impl Cached {
    /// The value, computed by `f` the first time (`f` must give less than `u8::MAX`).
    #[inline]
    fn get(&self, f: impl FnOnce() -> u8) -> u8 {
        match self.0.load(Ordering::Relaxed) {
            0 => {
                let value = f();
                self.0.store(value + 1, Ordering::Relaxed);
                value
            }
            known => known - 1,
        }
    }
}

impl Clone for Cached {
    fn clone(&self) -> Self {
        Cached(AtomicU8::new(self.0.load(Ordering::Relaxed)))
    }
}

/// A long polynomial's coefficients are dropped by `Coeffs::release` (in parallel, through
/// a block's counts at a time, or with no pass over them); a short one's one by one, as most
/// polynomials of a bracket or a tower are short and have no value in a slot.
impl<C: Coefficient> Drop for Poly<C> {
    #[inline]
    fn drop(&mut self) {
        if self.coeffs.len() >= coeffs::RELEASED_TERMS {
            let exps = std::mem::take(&mut self.exps);
            std::mem::take(&mut self.coeffs).release(exps);
        }
    }
}

impl<C: Coefficient> Poly<C> {
    /// The zero polynomial.
    pub fn zero(vars: &Vars) -> Self {
        Self::assemble(vars, Rational::zero(), Vec::new(), Vec::new())
    }

    /// The constant 1.
    pub fn one(vars: &Vars) -> Self {
        Self::constant(vars, C::one())
    }

    /// A constant of the variable set `vars`. A polynomial carries its set, so a number alone
    /// makes none (`Poly` has no `From<i64>`, `From<BigInt>` or `From<Rational>`, as
    /// num-rational's `Ratio` has): a constant is made in its set, here (or by [`Poly::zero`]
    /// and [`Poly::one`]), from a coefficient that each of those numbers converts into
    /// (`2.into()`), over Q and Q(i) alike.
    ///
    /// ```
    /// use trigpoly::num_bigint::BigInt;
    /// use trigpoly::{Expr, GaussianRational, Integer, Poly, Rational, Vars};
    ///
    /// let vars = Vars::builder().coordinate("x").parameter("M").build()?;
    /// let p = |s: &str| Expr::parse(&vars, s);
    /// assert_eq!(Expr::constant(&vars, 2.into()) + p("x")?, p("x + 2")?);
    /// assert_eq!(Expr::constant(&vars, Rational::new(-1, 2).into()), p("-1/2")?);
    /// assert_eq!(Expr::constant(&vars, Integer::from(7).into()), p("7")?);
    /// assert_eq!(Expr::constant(&vars, GaussianRational::i()), p("i")?);
    /// let big = BigInt::from(10).pow(30);
    /// let over_q = Poly::<Rational>::constant(&vars, big.clone().into());
    /// assert_eq!(over_q.as_constant(), Some(Rational::from(big)));
    /// assert!(Expr::constant(&vars, 0.into()).is_zero());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn constant(vars: &Vars, c: C) -> Self {
        let (content, n) = c.split();
        if content.is_zero() {
            return Self::zero(vars);
        }
        Self::assemble(vars, content, vars.layout().one().to_vec(), vec![n])
    }

    /// The variable `v` (for an angle, `e^{iθ}`).
    ///
    /// # Panics
    ///
    /// If `v` is a handle of another set ([`VarSet::owns`]), or an angle in a polynomial over
    /// Q, which has no `e^{iθ}` ([`Poly::monomial`] returns [`AlgebraError::NeedsGaussian`]
    /// there).
    pub fn var(vars: &Vars, v: Var) -> Self {
        let j = vars.index_of(v);
        let angle = vars.variable(v).kind() == VarKind::Angle;
        assert!(
            !angle || C::HAS_I,
            "the angle {} is e^{{i{}}}, which a polynomial over Q has no coefficients for: \
             take it over Q(i)",
            vars.variable(v).name(),
            vars.variable(v).unicode()
        );
        // The monomial `v` packed directly, where `monomial` checks every variable's
        // exponent and allocates twice more (a parsed expression makes one per name).
        let layout = vars.layout();
        let mut m = vec![0; layout.words];
        layout.unit(j, 1, &mut m);
        let (content, one) = C::one().split();
        Self::assemble(vars, content, m, vec![one])
    }

    /// `c · Π v^e`, for any integer exponents within the limit.
    pub fn monomial(vars: &Vars, c: C, powers: &[(Var, i64)]) -> Result<Self, AlgebraError> {
        let exps = sum_powers(vars, powers)?;
        if !C::HAS_I {
            if let Some(v) = vars.angles().find(|v| exps[v.index()] != 0) {
                return Err(AlgebraError::NeedsGaussian(format!(
                    "the angle {} (stored as e^{{iθ}})",
                    vars.variable(v).unicode()
                )));
            }
        }
        for v in vars.vars() {
            check_exponent(vars, v, exps[v.index()])?;
        }
        let (content, n) = c.split();
        if content.is_zero() {
            return Ok(Self::zero(vars));
        }
        let mut w = vec![0u64; vars.layout().words];
        vars.layout().pack(&exps, &mut w);
        Ok(Self::assemble(vars, content, w, vec![n]))
    }

    /// Builds a polynomial from terms `(coefficient, exponent vector)` in any order; equal
    /// monomials are combined.
    pub fn from_terms(
        vars: &Vars,
        terms: impl IntoIterator<Item = (C, Vec<i64>)>,
    ) -> Result<Self, AlgebraError> {
        // Pack every term, sort once, combine equal monomials, then bring the coefficients to
        // one rational content (a sum term by term would merge n times).
        let w = vars.layout().words;
        let mut packed: Vec<(Vec<u64>, GaussianRational)> = Vec::new();
        for (c, e) in terms {
            let powers: Vec<(Var, i64)> = vars.vars().zip(e).collect();
            let m = Self::monomial(vars, c.clone(), &powers)?;
            if !m.is_zero() {
                packed.push((m.into_terms().0, c.to_gaussian()));
            }
        }
        packed.sort_unstable_by(|a, b| b.0.cmp(&a.0));
        let mut combined: Vec<(Vec<u64>, GaussianRational)> = Vec::with_capacity(packed.len());
        for (key, c) in packed {
            match combined.last_mut() {
                Some(last) if last.0 == key => last.1 = &last.1 + &c,
                _ => combined.push((key, c)),
            }
        }
        combined.retain(|(_, c)| !c.is_zero());
        let parts: Vec<(Rational, C::Int)> = combined
            .iter()
            .map(|(_, c)| {
                C::from_gaussian(c)
                    .expect("a sum of field elements")
                    .split()
            })
            .collect();
        if parts.is_empty() {
            return Ok(Self::zero(vars));
        }
        let d = Rational::content_of(parts.iter().map(|(q, _)| q));
        let mut exps = Vec::with_capacity(parts.len() * w);
        let mut coeffs = Vec::with_capacity(parts.len());
        for ((key, _), (q, n)) in combined.iter().zip(parts) {
            exps.extend_from_slice(key);
            coeffs.push(n.scale(&(&q / &d).numer()));
        }
        Self::check_terms(vars, coeffs.len())?;
        Ok(Self::from_sorted(vars, d, exps, coeffs))
    }

    /// The variable set.
    pub fn vars(&self) -> &Vars {
        &self.vars
    }

    /// Number of terms.
    pub fn len(&self) -> usize {
        self.coeffs.len()
    }

    /// Whether there are no terms (the zero polynomial); the same as [`Poly::is_zero`].
    pub fn is_empty(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// Whether this is the zero polynomial (no terms): the exact zero test of a set without
    /// denominator atoms or radicals.
    ///
    /// With them, terms are not unique (`(x − y)·(x − y)⁻¹ = 1`, `r² = R` for a radical
    /// `r = √R`), and an element can be zero without being the zero polynomial: decide such
    /// an element with [`Poly::vanishes`], which clears the denominators and reduces the
    /// radicals first. `is_zero` is then only a sufficient test.
    ///
    /// ```
    /// use trigpoly::{Expr, Vars};
    /// let vars = Vars::builder().coordinate("x").radical("r", "x^2 + 1").build().unwrap();
    /// let e = Expr::parse(&vars, "r^2 - x^2 - 1").unwrap();
    /// assert!(!e.is_zero());
    /// assert!(e.vanishes().unwrap());
    /// ```
    pub fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// Whether this is a constant (no variable appears), zero included.
    pub fn is_constant(&self) -> bool {
        self.is_zero() || (self.len() == 1 && self.exps == self.vars.layout().one())
    }

    /// The constant value, if this is a constant.
    pub fn as_constant(&self) -> Option<C> {
        if self.is_zero() {
            return Some(C::zero());
        }
        self.is_constant()
            .then(|| C::from_parts(&self.content, &self.coeffs[0]))
    }

    /// Whether this is a single term (a nonzero scalar times a monomial).
    pub fn is_monomial(&self) -> bool {
        self.len() == 1
    }

    /// The terms, leading (largest exponent vector) first.
    pub fn terms(&self) -> impl ExactSizeIterator<Item = Term<'_, C>> + '_ {
        (0..self.len()).map(move |k| Term { poly: self, k })
    }

    /// The coefficient of a monomial, given as `(variable, exponent)` pairs (zero if absent).
    ///
    /// # Panics
    ///
    /// If a variable is a handle of another set ([`VarSet::owns`]).
    pub fn coeff(&self, powers: &[(Var, i64)]) -> C {
        for &(v, _) in powers {
            self.vars.index_of(v);
        }
        let Ok(exps) = sum_powers(&self.vars, powers) else {
            return C::zero();
        };
        if exps
            .iter()
            .any(|e| e.unsigned_abs() > self.vars.layout().max_exp as u64)
        {
            return C::zero();
        }
        let mut key = vec![0u64; self.words()];
        self.vars.layout().pack(&exps, &mut key);
        match self.find(&key) {
            Some(k) => C::from_parts(&self.content, &self.coeffs[k]),
            None => C::zero(),
        }
    }

    /// The largest exponent of `v` (`None` for zero).
    pub fn degree(&self, v: Var) -> Option<i64> {
        self.exponent_range(v).map(|r| r.1)
    }

    /// The smallest exponent of `v` (negative for a Laurent polynomial; `None` for zero).
    pub fn low_degree(&self, v: Var) -> Option<i64> {
        self.exponent_range(v).map(|r| r.0)
    }

    /// `(lowest, highest)` exponent of `v` (`None` for zero). For an angle this is the range of
    /// `k` in `e^{ikθ}`, so the degree in `cos θ, sin θ` is `max(|low|, |high|)`.
    ///
    /// # Panics
    ///
    /// If `v` is a handle of another set ([`VarSet::owns`]), as do [`Poly::degree`],
    /// [`Poly::low_degree`] and [`Poly::contains`].
    pub fn exponent_range(&self, v: Var) -> Option<(i64, i64)> {
        let layout = self.vars.layout();
        let j = self.vars.index_of(v);
        let mut it = self
            .exps
            .chunks_exact(self.words())
            .map(|m| layout.get(m, j));
        let first = it.next()?;
        Some(it.fold((first, first), |(lo, hi), e| (lo.min(e), hi.max(e))))
    }

    /// The total degree over the variables of the given kinds (momenta, say), largest over the
    /// terms; angles count `|k|`. `None` for zero.
    pub fn total_degree(&self, kinds: &[VarKind]) -> Option<i64> {
        let layout = self.vars.layout();
        let vars: Vec<usize> = self
            .vars
            .vars()
            .filter(|&v| kinds.contains(&self.vars.variable(v).kind()))
            .map(Var::index)
            .collect();
        self.exps
            .chunks_exact(self.words())
            .map(|m| vars.iter().map(|&j| layout.get(m, j).abs()).sum())
            .max()
    }

    /// Whether `v` appears.
    pub fn contains(&self, v: Var) -> bool {
        let layout = self.vars.layout();
        let j = self.vars.index_of(v);
        self.exps
            .chunks_exact(self.words())
            .any(|m| layout.get(m, j) != 0)
    }

    /// The content: a rational `q` such that `self/q` has coprime integer coefficients.
    pub fn content(&self) -> &Rational {
        &self.content
    }

    // ---- internals shared by the sibling modules ----

    #[inline]
    pub(crate) fn words(&self) -> usize {
        self.vars.layout().words
    }

    pub(crate) fn layout(&self) -> &Layout {
        self.vars.layout()
    }

    #[inline]
    pub(crate) fn exp(&self, k: usize) -> &[u64] {
        let w = self.words();
        &self.exps[k * w..(k + 1) * w]
    }

    pub(crate) fn find(&self, key: &[u64]) -> Option<usize> {
        let w = self.words();
        // Terms are sorted descending.
        let (mut lo, mut hi) = (0usize, self.len());
        while lo < hi {
            let mid = (lo + hi) / 2;
            match self.exps[mid * w..(mid + 1) * w].cmp(key) {
                std::cmp::Ordering::Equal => return Some(mid),
                std::cmp::Ordering::Greater => lo = mid + 1,
                std::cmp::Ordering::Less => hi = mid,
            }
        }
        None
    }

    pub(crate) fn same_vars(&self, other: &Self) -> Result<(), AlgebraError> {
        if self.vars == other.vars {
            Ok(())
        } else {
            Err(AlgebraError::VarSetMismatch)
        }
    }

    pub(crate) fn check_terms(vars: &VarSet, n: usize) -> Result<(), AlgebraError> {
        if n > vars.limits().max_terms {
            Err(AlgebraError::TooManyTerms {
                limit: vars.limits().max_terms,
            })
        } else {
            Ok(())
        }
    }

    /// The work limit's check of a product of `a` by `b` before it is formed: `n·m` term
    /// products, `n(n + 1)/2` for a square.
    pub(crate) fn check_work(a: &Self, b: &Self) -> Result<(), AlgebraError> {
        let products = Self::work(a, b);
        let limit = a.vars.limits().max_term_products;
        if products > u128::from(limit) {
            return Err(AlgebraError::TooMuchWork {
                left: a.len(),
                right: b.len(),
                products,
                limit,
            });
        }
        Ok(())
    }

    /// The term products of a product of `a` by `b`: `n·m`, `n(n + 1)/2` for a square.
    fn work(a: &Self, b: &Self) -> u128 {
        let (n, m) = (a.len() as u128, b.len() as u128);
        match std::ptr::eq(a, b) {
            true => n * (n + 1) / 2,
            false => n * m,
        }
    }

    /// The work limit's check of a sum of products `a·b` before any is formed: each product
    /// that `checked_mul` would check ([`Poly::check_work`]: neither factor of
    /// [`SMALL_SIDE`](mul::SMALL_SIDE) terms or fewer, which are shifted copies, nor so few
    /// term products that they are gathered in one table, [`gather::fits`]), and their term
    /// products together, so that a bracket of long polynomials, four products each under
    /// the limit, stops at once rather than after minutes (`{Ax^50, Ay^50}` of the Kepler
    /// problem, four products of 4·10⁹ term products, ran 200 s).
    ///
    /// Out of line (it runs once a sum): inlined into the sums, each change of its body moved
    /// the code after them, and W3, which never calls it, ran 12 % slower for where its dense
    /// product's inner loop landed (as [`summed_work_refusal`]'s `#[cold]` says).
    #[inline(never)]
    pub(crate) fn check_sum_work<'a>(
        products: impl IntoIterator<Item = (&'a Self, &'a Self)>,
    ) -> Result<(), AlgebraError>
    where
        C: 'a,
    {
        let (mut count, mut total, mut largest, mut most) = (0, 0u128, (0, 0), 0u128);
        let mut limit = u64::MAX;
        for (a, b) in products {
            let (small, big) = if a.len() <= b.len() { (a, b) } else { (b, a) };
            let gathered = gather::fits(a.words(), small.len().saturating_mul(big.len()));
            if small.len() <= mul::SMALL_SIDE || gathered {
                continue;
            }
            Self::check_work(small, big)?;
            let work = Self::work(small, big);
            (count, total, limit) = (count + 1, total + work, a.vars.limits().max_term_products);
            if work > most {
                (most, largest) = (work, (small.len(), big.len()));
            }
        }
        if total > u128::from(limit) {
            return Err(summed_work_refusal(count, largest, total, limit));
        }
        Ok(())
    }

    /// The fixed bound on the size of coefficients, checked before a product of `a` by `b`
    /// is formed: the bits of its coefficients' numerators are at most those of the two
    /// factors' added, with one more for each doubling of the terms summed into one, and of
    /// their denominators those of the two factors' contents' added (a numerator and a
    /// denominator are bounded apart, since one factor's may cancel the other's:
    /// `(c x)·(y/c)` is `x y`); past [`MAX_COEFFICIENT_BITS`] it is refused, as a power of a
    /// single term is (a chain of products `F*F*…` of a large constant multiplied for
    /// minutes, each step twice the last). Factors whose values fit machine words pass at
    /// once.
    pub(crate) fn check_coefficient_bits(a: &Self, b: &Self) -> Result<(), AlgebraError> {
        let sums = 64 - (a.len().min(b.len()) as u64).leading_zeros();
        let ((numer_a, denom_a), (numer_b, denom_b)) = (a.coefficient_bits(), b.coefficient_bits());
        check_coefficient_size((numer_a + numer_b + u64::from(sums)).max(denom_a + denom_b))
    }

    /// Bounds on the bits of any component of a coefficient's numerator, and of its
    /// denominator: those of the content's numerator and of the primitive part's largest
    /// component, added (a coefficient is their product over the content's denominator),
    /// and those of the content's denominator. One pass over the coefficients only when one
    /// of them does not fit a machine word.
    pub(crate) fn coefficient_bits(&self) -> (u64, u64) {
        let (numer, denom) = match self.content.small_parts() {
            Some((n, d)) => (
                64 - u64::from(n.unsigned_abs().leading_zeros()),
                64 - u64::from(d.unsigned_abs().leading_zeros()),
            ),
            None => (self.content.numer().bits(), self.content.denom().bits()),
        };
        let parts = match self.small_bits() {
            Some(bits) => u64::from(bits),
            None => self.coefficient_bits_of_parts(),
        };
        (numer + parts, denom)
    }

    /// The bits of the largest component of a coefficient of the primitive part.
    #[inline(never)]
    fn coefficient_bits_of_parts(&self) -> u64 {
        (self.coeffs.iter())
            .map(|c| {
                let z = c.to_gaussian_integer();
                z.re.bits().max(z.im.bits())
            })
            .max()
            .unwrap_or(0)
    }

    /// A power of two at least the largest `|e|` over every exponent of every term: one pass
    /// over the packed words, a few operations per word, no allocation. Enough to clear most
    /// exponent checks at once, since the limit is the same for every variable; a check it
    /// does not clear goes variable by variable.
    ///
    /// Inlined, so that a known bound costs a load and a shift; the pass is out of line.
    #[inline]
    pub(crate) fn exponent_bound(&self) -> i64 {
        let bits = self
            .exponent_bound
            .get(|| Self::exponent_bound_bits(&self.vars, &self.exps) as u8);
        (1u128 << bits).min(i64::MAX as u128) as i64
    }

    /// The most bits of a component of any coefficient of the primitive part, if every one
    /// fits a machine word (what the word kernels ask of a factor). Inlined like
    /// [`Poly::exponent_bound`].
    #[inline]
    pub(crate) fn small_bits(&self) -> Option<u32> {
        let bits = self.small_bits.get(|| Self::small_bits_of(&self.coeffs));
        (bits != u8::MAX - 1).then_some(u32::from(bits))
    }

    /// Whether every coefficient of the primitive part is real: always over Q; over Q(i),
    /// what lets the word kernels multiply in Z (one product where a Gaussian takes four).
    #[inline]
    pub(crate) fn real_coefficients(&self) -> bool {
        !C::Int::COMPLEX
            || self
                .real_coefficients
                .get(|| u8::from(self.coeffs.iter().all(IntegerRing::is_real)))
                == 1
    }

    /// [`Poly::small_bits`] read from the coefficients (`u8::MAX − 1` for `None`).
    #[inline(never)]
    fn small_bits_of(coeffs: &[C::Int]) -> u8 {
        gather::small_bits(coeffs).map_or(u8::MAX - 1, |b| b as u8)
    }

    /// The bit length `b` of [`Poly::exponent_bound`] `= 2^b` for the packed monomials `exps`.
    #[inline(never)]
    fn exponent_bound_bits(vars: &VarSet, exps: &[u64]) -> u32 {
        let layout = vars.layout();
        let (bits, field) = (layout.bits, layout.field_mask());
        let bias = layout.one();
        let mut acc = 0u64;
        for m in exps.chunks_exact(layout.words) {
            for (&word, &b) in m.iter().zip(bias) {
                // XOR with the bias leaves each field in two's complement (unused fields 0,
                // and `b` has the sign bit of each used field); complementing the negative
                // fields leaves `|e|` or `|e| − 1` in each.
                let x = word ^ b;
                let negative = ((x & b) >> (bits - 1)).wrapping_mul(field);
                acc |= x ^ negative;
            }
        }
        let mut r = 0u64;
        // The fields sit above the bits a word leaves over (64 mod bits of them).
        let mut s = 64 % bits;
        while s < 64 {
            r |= (acc >> s) & field;
            s += bits;
        }
        // Every |e| ≤ r + 1 ≤ 2^(bit length of r).
        64 - r.leading_zeros()
    }

    /// Checks that the exponents of a product of `self` and `other` stay within the limit:
    /// from the largest exponents when that suffices, else variable by variable.
    pub(crate) fn check_product_exponents(&self, other: &Self) -> Result<(), AlgebraError> {
        let limit = self.vars.limits().max_degree as i64;
        if self.exponent_bound() + other.exponent_bound() <= limit {
            return Ok(());
        }
        mul::check_sum_bounds(&self.vars, &self.bounds(), &other.bounds())
    }

    /// Per variable, the gcd of every exponent's distance from `bounds`' minimum (0 when the
    /// variable takes one value): the step of the lattice its exponents lie on, 2 for a
    /// polynomial in `z²`. A product's Kronecker box shrinks by each step its factors share.
    /// One pass over the packed words, which ends once every step is 1.
    pub(crate) fn exponent_steps(&self, bounds: &[(i64, i64)]) -> Vec<u64> {
        let layout = self.vars.layout();
        let mut steps = vec![0u64; bounds.len()];
        // Only the variables that take more than one value can have a step above 1.
        let open: Vec<(usize, (usize, u32))> = (0..bounds.len())
            .filter(|&j| bounds[j].0 < bounds[j].1)
            .map(|j| (j, layout.field(j)))
            .collect();
        let mut above_one = open.len();
        for m in self.exps.chunks_exact(self.words()) {
            if above_one == 0 {
                break;
            }
            for &(j, field) in &open {
                let step = steps[j];
                if step == 1 {
                    continue;
                }
                let distance = (layout.read(m, field) - bounds[j].0) as u64;
                let step = num_integer::Integer::gcd(&step, &distance);
                if step == 1 {
                    above_one -= 1;
                }
                steps[j] = step;
            }
        }
        steps
    }

    /// Per-variable `(min, max)` exponents (all zero for the zero polynomial).
    pub(crate) fn bounds(&self) -> Vec<(i64, i64)> {
        let layout = self.vars.layout();
        let n = self.vars.len();
        if self.is_zero() {
            return vec![(0, 0); n];
        }
        // Field by field on the packed words: no unpacking, no division.
        let (bits, per_word, mask) = (layout.bits, layout.per_word, layout.field_mask());
        let mut lo = vec![u64::MAX; layout.words * per_word];
        let mut hi = vec![0u64; layout.words * per_word];
        for m in self.exps.chunks_exact(self.words()) {
            for (w, &word) in m.iter().enumerate() {
                for s in 0..per_word {
                    let v = (word >> (64 - bits * (s as u32 + 1))) & mask;
                    let k = w * per_word + s;
                    lo[k] = lo[k].min(v);
                    hi[k] = hi[k].max(v);
                }
            }
        }
        let bias = 1i64 << (bits - 1);
        (0..n)
            .map(|j| (lo[j] as i64 - bias, hi[j] as i64 - bias))
            .collect()
    }

    /// Builds from sorted, distinct, nonzero terms and restores the invariant (primitive part,
    /// sign): the one place where the canonical form is enforced.
    pub(crate) fn from_sorted(
        vars: &Vars,
        content: Rational,
        exps: Vec<u64>,
        mut coeffs: Vec<C::Int>,
    ) -> Self {
        debug_assert_eq!(exps.len(), coeffs.len() * vars.layout().words);
        if coeffs.is_empty() || content.is_zero() {
            return Self::zero(vars);
        }
        // The trailing coefficient is often small: start there to reach gcd 1 early.
        let mut g = Integer::ZERO;
        for c in coeffs.iter().rev() {
            g = c.gcd_into(&g);
            if g.is_one() {
                break;
            }
        }
        let negative = coeffs[0].leading_sign() < 0;
        let mut content = content;
        if !g.is_one() || negative {
            let d = if negative { -g } else { g };
            let divisor = ExactDivisor::new(&d);
            for c in coeffs.iter_mut() {
                *c = c.div_exact(&divisor);
            }
            content *= Rational::from(d);
        }
        Self::assemble(vars, content, exps, coeffs)
    }

    /// `content ·` the terms a kernel gathered, brought to the canonical form unless the
    /// kernel did that already.
    pub(crate) fn from_gathered(
        vars: &Vars,
        content: Rational,
        terms: gather::Gathered<C::Int>,
    ) -> Self {
        let gather::Gathered {
            exps,
            coeffs,
            divisor,
        } = terms;
        match divisor {
            None => Self::from_sorted(vars, content, exps, coeffs),
            Some(_) if coeffs.is_empty() || content.is_zero() => Self::zero(vars),
            Some(d) if d.is_one() => Self::assemble(vars, content, exps, coeffs),
            Some(d) => Self::assemble(vars, content.mul_integer(&d), exps, coeffs),
        }
    }

    /// Builds from sorted, distinct, nonzero terms whose components are coprime but whose
    /// leading coefficient may be negative (the image of a canonical polynomial under a map
    /// that keeps every component's size, such as conjugation or the factor `i`): only the
    /// sign is restored, with no gcd to take.
    pub(crate) fn from_sorted_coprime(
        vars: &Vars,
        content: Rational,
        exps: Vec<u64>,
        mut coeffs: Vec<C::Int>,
    ) -> Self {
        match coeffs.first() {
            None => Self::zero(vars),
            Some(lead) if lead.leading_sign() < 0 => {
                for c in coeffs.iter_mut() {
                    *c = c.neg();
                }
                Self::assemble(vars, -content, exps, coeffs)
            }
            Some(_) => Self::assemble(vars, content, exps, coeffs),
        }
    }

    /// Builds from sorted, distinct, nonzero terms that are already primitive with a positive
    /// leading coefficient (a product of such polynomials over Z, by Gauss's lemma).
    pub(crate) fn from_sorted_primitive(
        vars: &Vars,
        content: Rational,
        exps: Vec<u64>,
        coeffs: Coeffs<C::Int>,
    ) -> Self {
        debug_assert!(C::Int::GAUSS_LEMMA);
        if coeffs.is_empty() {
            return Self::zero(vars);
        }
        debug_assert!(coeffs[0].leading_sign() > 0);
        Self::assemble_coeffs(vars, content, exps, coeffs)
    }

    /// The polynomial with these parts, as they are: the caller keeps the invariant.
    pub(crate) fn assemble(
        vars: &Vars,
        content: Rational,
        exps: Vec<u64>,
        coeffs: Vec<C::Int>,
    ) -> Self {
        Self::assemble_coeffs(vars, content, exps, Coeffs::new(coeffs))
    }

    /// [`Poly::assemble`] with coefficients that may carry their builder's note.
    pub(crate) fn assemble_coeffs(
        vars: &Vars,
        content: Rational,
        exps: Vec<u64>,
        coeffs: Coeffs<C::Int>,
    ) -> Self {
        Poly {
            vars: vars.clone(),
            content,
            exps,
            coeffs,
            exponent_bound: Cached::default(),
            small_bits: Cached::default(),
            real_coefficients: Cached::default(),
        }
    }

    /// The packed monomials and coefficients, taken out of the polynomial.
    pub(crate) fn into_terms(mut self) -> (Vec<u64>, Vec<C::Int>) {
        (
            std::mem::take(&mut self.exps),
            std::mem::take(&mut self.coeffs).into_vec(),
        )
    }

    /// The same polynomial with the content `content`.
    pub(crate) fn with_content(&self, content: Rational) -> Self {
        let mut p = self.clone();
        p.content = content;
        p
    }

    /// Sorted terms with content 1 and no normalization: an intermediate inside a kernel.
    pub(crate) fn raw(vars: &Vars, exps: Vec<u64>, coeffs: Vec<C::Int>) -> Self {
        Self::assemble(vars, Rational::one(), exps, coeffs)
    }

    /// Builds from distinct nonzero terms in any order (a bijective relabelling of monomials,
    /// such as conjugation): sorts a permutation, no combining needed.
    pub(crate) fn from_distinct_unsorted(
        vars: &Vars,
        content: Rational,
        exps: Vec<u64>,
        coeffs: Vec<C::Int>,
    ) -> Self {
        let w = vars.layout().words;
        let mut order: Vec<usize> = (0..coeffs.len()).collect();
        order.sort_unstable_by(|&a, &b| exps[b * w..(b + 1) * w].cmp(&exps[a * w..(a + 1) * w]));
        let mut e2 = Vec::with_capacity(exps.len());
        let mut coeffs: Vec<Option<C::Int>> = coeffs.into_iter().map(Some).collect();
        let mut c2 = Vec::with_capacity(coeffs.len());
        for k in order {
            e2.extend_from_slice(&exps[k * w..(k + 1) * w]);
            c2.push(coeffs[k].take().expect("each term once"));
        }
        Self::from_sorted(vars, content, e2, c2)
    }

    pub(crate) fn drop_zeros_and_normalize(
        vars: &Vars,
        content: Rational,
        exps: Vec<u64>,
        coeffs: Vec<C::Int>,
    ) -> Self {
        if coeffs.iter().all(|c| !c.is_zero()) {
            return Self::from_sorted(vars, content, exps, coeffs);
        }
        let w = vars.layout().words;
        let mut e2 = Vec::with_capacity(exps.len());
        let mut c2 = Vec::with_capacity(coeffs.len());
        for (k, c) in coeffs.into_iter().enumerate() {
            if !c.is_zero() {
                e2.extend_from_slice(&exps[k * w..(k + 1) * w]);
                c2.push(c);
            }
        }
        Self::from_sorted(vars, content, e2, c2)
    }

    pub(crate) fn raw_parts(&self) -> (&Rational, &[u64], &[C::Int]) {
        (&self.content, &self.exps, &self.coeffs)
    }

    /// The packed monomials and integer coefficients, as the kernels take them.
    #[inline]
    pub(crate) fn raw_terms(&self) -> (&[u64], &[C::Int]) {
        (&self.exps, &self.coeffs)
    }
}

/// The exponent vector of `Π v^e`, or an error if an exponent passes the limit.
fn sum_powers(vars: &VarSet, powers: &[(Var, i64)]) -> Result<Vec<i64>, AlgebraError> {
    let mut exps = vec![0i64; vars.len()];
    for &(v, e) in powers {
        let j = vars.checked_index(v)?;
        let sum = exps[j].checked_add(e).unwrap_or(i64::MAX);
        check_exponent(vars, v, sum)?;
        exps[j] = sum;
    }
    Ok(exps)
}

pub(crate) fn check_exponent(vars: &VarSet, v: Var, e: i64) -> Result<(), AlgebraError> {
    let limit = vars.limits().max_degree;
    if e.unsigned_abs() > limit as u64 {
        let variable = vars.variable(v);
        let name = variable.unicode().to_string();
        Err(match variable.kind() {
            VarKind::Angle => AlgebraError::OrderTooLarge {
                angle: name,
                order: e.unsigned_abs(),
                limit,
            },
            _ => AlgebraError::ExponentTooLarge {
                var: name,
                exponent: e,
                limit,
            },
        })
    } else {
        Ok(())
    }
}

/// One term of a polynomial: a coefficient and a monomial.
#[derive(Clone, Copy)]
pub struct Term<'a, C: Coefficient> {
    poly: &'a Poly<C>,
    k: usize,
}

impl<'a, C: Coefficient> Term<'a, C> {
    /// The coefficient.
    pub fn coeff(&self) -> C {
        C::from_parts(&self.poly.content, &self.poly.coeffs[self.k])
    }

    /// The monomial as packed words, which compare as the terms are ordered.
    pub(crate) fn packed(&self) -> &'a [u64] {
        self.poly.exp(self.k)
    }

    /// The term's coefficient in the primitive part: the coefficient is the polynomial's
    /// [`Poly::content`] times this (exact modular or integer work can take the two apart,
    /// with no rational product per term).
    pub fn primitive_coeff(&self) -> &C::Int {
        &self.poly.coeffs[self.k]
    }

    /// The exponent of `v` (for an angle, `k` in `e^{ikθ}`).
    ///
    /// # Panics
    ///
    /// If `v` is a handle of another set ([`VarSet::owns`]).
    pub fn exponent(&self, v: Var) -> i64 {
        let j = self.poly.vars.index_of(v);
        self.poly.layout().get(self.poly.exp(self.k), j)
    }

    /// All exponents, in variable order.
    pub fn exponents(&self) -> Vec<i64> {
        let m = self.poly.exp(self.k);
        (0..self.poly.vars.len())
            .map(|j| self.poly.layout().get(m, j))
            .collect()
    }
}

/// The coefficient and the exponents that are not zero, by the variables' names (an angle's
/// is `k` in `e^{ikθ}`), as a program printing a polynomial's terms with `{:?}` reads them:
///
/// ```
/// use trigpoly::{Expr, Vars};
///
/// let vars = Vars::builder().coordinate("x").momentum("p_x").angle("theta").build()?;
/// let f = Expr::parse(&vars, "3/4*x^2*p_x - i*exp(-2*i*theta)")?;
/// let terms: Vec<String> = f.terms().map(|t| format!("{t:?}")).collect();
/// assert_eq!(
///     terms,
///     [
///         "Term { coeff: 3/4, exponents: {\"x\": 2, \"p_x\": 1} }",
///         "Term { coeff: -i, exponents: {\"theta\": -2} }",
///     ]
/// );
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
impl<C: Coefficient> fmt::Debug for Term<'_, C> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let vars = &self.poly.vars;
        let exponents: Vec<(&str, i64)> = vars
            .vars()
            .zip(self.exponents())
            .filter(|&(_, e)| e != 0)
            .map(|(v, e)| (vars.variable(v).name(), e))
            .collect();
        f.debug_struct("Term")
            .field("coeff", &self.coeff())
            .field("exponents", &DebugMap(&exponents))
            .finish()
    }
}

/// Pairs shown as a map by `{:?}`.
struct DebugMap<'a>(&'a [(&'a str, i64)]);

impl fmt::Debug for DebugMap<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_map()
            .entries(self.0.iter().map(|(k, v)| (k, v)))
            .finish()
    }
}

impl<C: Coefficient> PartialEq for Poly<C> {
    fn eq(&self, other: &Self) -> bool {
        self.content == other.content
            && self.exps == other.exps
            && self.coeffs == other.coeffs
            && self.vars == other.vars
    }
}

impl<C: Coefficient> Eq for Poly<C> {}

impl<C: Coefficient> Hash for Poly<C> {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.content.hash(state);
        self.exps.hash(state);
        self.coeffs.hash(state);
    }
}

impl<C: Coefficient> fmt::Debug for Poly<C> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Poly({})", self.to_ascii())
    }
}

/// The refusal of [`Poly::check_sum_work`] ([`AlgebraError::TooMuchSummedWork`], whose
/// message `error.rs`'s `too_much_summed_work` writes). `#[cold]` for the code's layout, not
/// for this call's cost: built inline, it moved the dense product's inner loop, elsewhere, so
/// that a compare-and-branch crossed a cache line, and W3 ran 12 % slower with the same
/// instructions. A change here or in `check_sum_work` can move it again: time W3.
#[cold]
fn summed_work_refusal(
    products: usize,
    largest: (usize, usize),
    total: u128,
    limit: u64,
) -> AlgebraError {
    AlgebraError::TooMuchSummedWork {
        products,
        largest,
        total,
        limit,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rayon::prelude::*;

    /// Polynomials past the parallel-drop size, with boxed coefficients, dropped inside a
    /// pool of two threads (one at a time, and several at once from the pool's own jobs):
    /// every drop completes, and the polynomial they were cloned from is untouched.
    #[test]
    fn large_polynomials_drop_on_the_pool() {
        let vars = Vars::builder().coordinate("x").build().unwrap();
        let n = coeffs::PARALLEL_DROP_TERMS + 3;
        let exps: Vec<u64> = (0..n as u64).rev().collect();
        let coeffs: Vec<Integer> = (0..n as i128)
            .map(|k| Integer::from_i128((1 << 70) + k))
            .collect();
        let p = Poly::<Rational>::raw(&vars, exps, coeffs);
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .unwrap();
        pool.install(|| {
            let q = p.clone();
            assert!(q == p);
            drop(q);
            (0..3).into_par_iter().for_each(|_| drop(p.clone()));
        });
        assert_eq!(p.len(), n);
        assert_eq!(
            p.coeffs[n - 1],
            Integer::from_i128((1 << 70) + n as i128 - 1)
        );
    }

    /// A large dense product whose coefficients pass a word keeps its builder's counts of
    /// their slots, on one thread and on two (parts, or a writing thread), and drops by them;
    /// its copy and its negation, whose values are new, do not.
    #[test]
    fn a_large_products_coefficients_keep_their_slabs_counts() {
        let vars = Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .coordinate("z")
            .coordinate("t")
            .build()
            .unwrap();
        let f = Poly::<Rational>::parse(&vars, "(1 + 3*x + 5*y + 7*z^3 - 11*t^3)^11").unwrap();
        let g = Poly::<Rational>::parse(&vars, "(1 - 13*x^3 + 3*y^3 + 5*z + 7*t)^11").unwrap();
        for threads in [1, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let p = pool.install(|| f.checked_mul(&g).unwrap());
            assert!(p.len() >= 1 << 16, "{} terms", p.len());
            assert!(p.coeffs.iter().any(|c| c.to_i64().is_none()));
            assert!(p.coeffs.has_counts(), "on {threads} threads");
            let (copy, negated) = (p.clone(), -&p);
            assert!(!copy.coeffs.has_counts() && !negated.coeffs.has_counts());
            assert!(copy == p && negated.checked_add(&p).unwrap().is_zero());
            pool.install(|| drop(p));
        }
    }

    /// `Poly::var` packs its monomial directly: it equals the monomial `v¹` that
    /// [`Poly::monomial`] builds and checks, for every kind of variable, in both fields, and
    /// with monomials of one word and of several (40 variables).
    #[test]
    fn var_is_the_monomial_of_exponent_one() {
        let mut builder = Vars::builder()
            .coordinate("x")
            .angle("theta")
            .momentum("p_x")
            .parameter("M");
        for k in 0..36 {
            builder = builder.coordinate(&format!("q{k}"));
        }
        let small = Vars::builder()
            .coordinate("x")
            .angle("theta")
            .parameter("M");
        let (large, small) = (builder.build().unwrap(), small.build().unwrap());
        assert!(large.layout().words > 1 && small.layout().words == 1);
        for vars in [large, small] {
            for v in vars.vars() {
                let expected = Poly::<GaussianRational>::monomial(&vars, 1.into(), &[(v, 1)]);
                assert!(Poly::<GaussianRational>::var(&vars, v) == expected.unwrap());
                if vars.variable(v).kind() != VarKind::Angle {
                    let expected = Poly::<Rational>::monomial(&vars, 1.into(), &[(v, 1)]);
                    assert!(Poly::<Rational>::var(&vars, v) == expected.unwrap());
                }
            }
        }
    }
}
