//! Exact linear algebra for discovery: which vectors of a sequence depend on earlier ones, and
//! how. The same semi-echelon elimination runs over the prime field `F_p` (`p = 2⁶² − 57`,
//! products in `u128`) for speed and over `Q` ([`Rational`]) when exactness must not depend on
//! a reconstruction (over `Q(i)`, [`GaussianRational`], for a bracket table's combinations);
//! [`reconstruct`] lifts a residue back to a small rational.
//!
//! Nothing here is floating point, and nothing decided modulo `p` is trusted without an exact
//! check by the caller: a vector independent modulo `p` is independent over `Q` (a relation over
//! `Q` reduces to one modulo `p`), and a dependency found modulo `p` is reconstructed and then
//! verified exactly.
//!
//! ```
//! use brackets::modular::{Echelon, Fp};
//! // (1, 2), (2, 4), (0, 1): the second depends on the first.
//! let v = |a: u64, b: u64| vec![(0, Fp::new(a)), (1, Fp::new(b))];
//! let mut e = Echelon::new(2);
//! assert!(e.insert(0, &v(1, 2)).is_none());
//! assert_eq!(e.insert(1, &v(2, 4)), Some(vec![(0, Fp::new(2))]));
//! assert!(e.insert(2, &v(0, 1)).is_none());
//! assert_eq!(e.rank(), 2);
//! ```

use std::borrow::Borrow;
use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::fmt::Debug;
use std::sync::{Mutex, PoisonError};

use num_bigint::BigInt;
use num_integer::Integer as _;
use num_traits::ToPrimitive;
use trigpoly::{Coefficient, GaussianRational, Rational};

/// The prime `2⁶² − 57`.
pub const PRIME: u64 = (1 << 62) - 57;

/// The operations of a field that the elimination needs.
pub trait Field: Clone + PartialEq + Debug {
    /// Zero.
    fn zero() -> Self;
    /// One.
    fn one() -> Self;
    /// Whether this is zero.
    fn is_zero(&self) -> bool;
    /// `self + other`.
    fn add(&self, other: &Self) -> Self;
    /// `self − other`.
    fn sub(&self, other: &Self) -> Self;
    /// `self · other`.
    fn mul(&self, other: &Self) -> Self;
    /// `1/self`; panics on zero (callers only invert pivots).
    fn inv(&self) -> Self;
}

/// An element of `F_p`, `p =` [`PRIME`]. It prints as its residue in `[0, p)`.
///
/// ```
/// use brackets::modular::{Fp, PRIME};
/// assert_eq!(Fp::from_i64(-1).to_string(), (PRIME - 1).to_string());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Fp(u64);

impl std::fmt::Display for Fp {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.0)
    }
}

impl Fp {
    /// `a mod p`.
    pub fn new(a: u64) -> Self {
        Fp(a % PRIME)
    }

    /// The residue in `[0, p)`.
    pub fn value(self) -> u64 {
        self.0
    }

    /// `a mod p` for a signed integer.
    pub fn from_i64(a: i64) -> Self {
        let r = a.rem_euclid(PRIME as i64);
        Fp(r as u64)
    }

    /// `a mod p` for an integer of any size.
    pub fn from_integer(a: &trigpoly::Integer) -> Self {
        match a.to_i64() {
            Some(v) => Fp::from_i64(v),
            None => bigint_mod(&a.to_bigint()),
        }
    }

    /// `q mod p`, or `None` if `p` divides the denominator (which can be so in a machine
    /// word too: `p` is below 2⁶²).
    pub fn from_rational(q: &Rational) -> Option<Self> {
        let (n, d) = match q.small_parts() {
            Some((n, d)) => (Fp::from_i64(n), Fp::from_i64(d)),
            None => (Fp::from_integer(&q.numer()), Fp::from_integer(&q.denom())),
        };
        // An integer needs no inverse (a Euclid's algorithm of up to some 60 divisions).
        match d.0 {
            0 => None,
            1 => Some(n),
            _ => Some(n.mul(&d.inv())),
        }
    }

    /// `self^e` by repeated squaring (Fermat's `a^(p−2)` checks [`Fp::inv`] in the tests).
    #[cfg(test)]
    fn pow(self, mut e: u64) -> Self {
        let mut base = self;
        let mut acc = Fp(1);
        while e > 0 {
            if e & 1 == 1 {
                acc = acc.mul(&base);
            }
            base = base.mul(&base);
            e >>= 1;
        }
        acc
    }
}

fn bigint_mod(a: &BigInt) -> Fp {
    Fp(big_mod(a, PRIME))
}

// Residues modulo any prime below 2⁶⁴, where a computation needs several primes (the
// determinants of `search::exceptional`, by the Chinese remainder theorem); `Fp` is the
// field of the one prime `PRIME`, with its faster reduction.

/// `a` modulo the prime `p`, in `0..p`.
pub(crate) fn big_mod(a: &BigInt, p: u64) -> u64 {
    (a.mod_floor(&BigInt::from(p)))
        .to_u64()
        .expect("a residue below p fits in u64")
}

/// `a·b` modulo `p`.
pub(crate) fn mul_mod(a: u64, b: u64, p: u64) -> u64 {
    ((u128::from(a) * u128::from(b)) % u128::from(p)) as u64
}

/// A modulus `p < 2⁶²` (a prime, any one, where [`Fp`]'s is [`PRIME`]) with the constant of
/// Barrett's reduction, so that a product of residues is reduced without a division: `x mod p`
/// for `x < p²` is `x − q p` with `q = ⌊⌊x/2ⁿ⁻¹⌋ μ / 2ⁿ⁺¹⌋`, `2ⁿ⁻¹ ≤ p < 2ⁿ`, `μ = ⌊2²ⁿ/p⌋`,
/// which falls short of `⌊x/p⌋` by at most 2 (Menezes, van Oorschot and Vanstone, *Handbook
/// of Applied Cryptography*, 14.42), then at most two subtractions. The division of the
/// `u128` by `p` (`__umodti3`) and of the sums by `p` were 40 % of `--find-values` at degree 3.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Modulus {
    p: u64,
    /// `n`, the bits of `p`.
    bits: u32,
    /// `⌊2²ⁿ/p⌋`, at most `2ⁿ⁺¹` (reached when `p` is a power of two), so below `2⁶³`.
    mu: u64,
}

impl Modulus {
    /// The modulus `p`, `2 ≤ p < 2⁶²` (so that `x − q p < 3p` fits in a `u64`).
    pub(crate) fn new(p: u64) -> Self {
        assert!((2..1 << 62).contains(&p), "a modulus in [2, 2⁶²)");
        let bits = u64::BITS - p.leading_zeros();
        let mu = u64::try_from((1_u128 << (2 * bits)) / u128::from(p))
            .expect("⌊2²ⁿ/p⌋ ≤ 2ⁿ⁺¹ fits in a u64");
        Modulus { p, bits, mu }
    }

    /// `p`.
    pub(crate) fn prime(&self) -> u64 {
        self.p
    }

    /// `a·b mod p`, for residues `a, b < p`.
    #[inline]
    pub(crate) fn mul(&self, a: u64, b: u64) -> u64 {
        let x = u128::from(a) * u128::from(b);
        let q1 = (x >> (self.bits - 1)) as u64;
        let q = ((u128::from(q1) * u128::from(self.mu)) >> (self.bits + 1)) as u64;
        // The remainder is below 3p < 2⁶⁴: computed in u64, wrapping.
        let r = (x as u64).wrapping_sub(q.wrapping_mul(self.p));
        let r = if r >= self.p { r - self.p } else { r };
        if r >= self.p {
            r - self.p
        } else {
            r
        }
    }

    /// `a + b mod p`, for residues `a, b < p`.
    #[inline]
    pub(crate) fn add(&self, a: u64, b: u64) -> u64 {
        let s = a + b;
        if s >= self.p {
            s - self.p
        } else {
            s
        }
    }

    /// `a − b mod p`, for residues `a, b < p`.
    #[inline]
    pub(crate) fn sub(&self, a: u64, b: u64) -> u64 {
        if a >= b {
            a - b
        } else {
            a + self.p - b
        }
    }
}

/// `a^e` modulo `p`, by repeated squaring.
fn pow_mod(mut a: u64, mut e: u64, p: u64) -> u64 {
    let mut acc = 1;
    while e > 0 {
        if e & 1 == 1 {
            acc = mul_mod(acc, a, p);
        }
        a = mul_mod(a, a, p);
        e >>= 1;
    }
    acc
}

/// The largest prime below `n` (Miller–Rabin with the bases that decide every 64-bit number).
pub(crate) fn previous_prime(n: u64) -> u64 {
    (3..=n - 2)
        .rev()
        .step_by(2)
        .find(|&m| is_prime(m))
        .expect("a prime below n")
}

/// Whether `n` is prime.
fn is_prime(n: u64) -> bool {
    const BASES: [u64; 12] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37];
    if n < 2 {
        return false;
    }
    if let Some(&b) = BASES.iter().find(|&&b| n.is_multiple_of(b)) {
        return n == b;
    }
    let (mut d, mut s) = (n - 1, 0);
    while d % 2 == 0 {
        d /= 2;
        s += 1;
    }
    BASES.iter().all(|&a| {
        let mut x = pow_mod(a, d, n);
        if x == 1 || x == n - 1 {
            return true;
        }
        for _ in 1..s {
            x = mul_mod(x, x, n);
            if x == n - 1 {
                return true;
            }
        }
        false
    })
}

/// `x mod p` for a product `x < p²` of residues, without a division: `2⁶² ≡ 57 (mod p)`, so
/// `x = h·2⁶² + l ≡ 57h + l`, twice (below `2⁶⁸`, then below `2⁶² + 2¹²`), and one subtraction.
/// A division of the `u128` by `p` (`__umodti3`) was 30 % of a search at degree 8.
fn reduce_product(x: u128) -> u64 {
    const LOW: u128 = (1 << 62) - 1;
    let x = (x >> 62) * 57 + (x & LOW);
    let x = ((x >> 62) * 57 + (x & LOW)) as u64;
    if x >= PRIME {
        x - PRIME
    } else {
        x
    }
}

impl Field for Fp {
    fn zero() -> Self {
        Fp(0)
    }
    fn one() -> Self {
        Fp(1)
    }
    fn is_zero(&self) -> bool {
        self.0 == 0
    }
    fn add(&self, other: &Self) -> Self {
        // Both below 2⁶², so the sum fits in u64.
        let s = self.0 + other.0;
        Fp(if s >= PRIME { s - PRIME } else { s })
    }
    fn sub(&self, other: &Self) -> Self {
        Fp(if self.0 >= other.0 {
            self.0 - other.0
        } else {
            self.0 + PRIME - other.0
        })
    }
    fn mul(&self, other: &Self) -> Self {
        Fp(reduce_product(self.0 as u128 * other.0 as u128))
    }
    /// Panics on zero ("inverse of zero in F_p").
    fn inv(&self) -> Self {
        assert!(self.0 != 0, "inverse of zero in F_p");
        Fp(inverse_mod(self.0, PRIME))
    }
}

/// `a⁻¹ mod m` by the extended Euclidean algorithm, for `0 < a < m` with `gcd(a, m) = 1`
/// (every nonzero residue when `m` is prime; [`Fp::inv`] calls it with `m =` [`PRIME`], and it
/// is exact for every `m` up to `2⁶⁴ − 1`). A residue below 2³² takes a few divisions (after
/// `m mod a` the remainders are below `a`), a 62-bit one some 35 on average. Over 10⁶ random
/// 62-bit residues modulo [`PRIME`] it took 157 ms where Fermat's `a^(p−2)` (some 120
/// products), which it replaced there, took 361 ms.
///
/// Only the cofactors' magnitudes are kept, in `u64`, with no signed type and no cast. With
/// remainders `r₀ = m`, `r₁ = a`, `r_{k+1} = r_{k−1} − q_k r_k` (`q_k = ⌊r_{k−1}/r_k⌋ ≥ 1`),
/// the cofactors `t₀ = 0`, `t₁ = 1`, `t_{k+1} = t_{k−1} − q_k t_k` keep `r_k ≡ t_k a (mod m)`
/// and alternate in sign, `t_k = (−1)^{k+1} u_k` with `u₀ = 0`, `u₁ = 1`,
/// `u_{k+1} = u_{k−1} + q_k u_k` (by induction: `t_{k−1}` and `−q_k t_k` have the sign of
/// `(−1)^k`). So the `u_k` grow, and the last one, at `r_{n+1} = 0`, is `m/gcd(a, m) = m`
/// (`|t_{n+1}| = m/g` is the classical bound, reached): every `u_k ≤ m`, and `q_k u_k ≤
/// u_{k+1} ≤ m`, so no product or sum passes `m < 2⁶⁴`. At the end `r_n = 1 ≡ t_n a`: the
/// inverse is `u_n` where `t_n > 0` (`n` odd) and `m − u_n` where `t_n < 0`, and `0 < u_n <
/// m` (`u_n ≤ m/r_{n−1} ≤ m/2` for `n ≥ 2`, `u₁ = 1`).
pub(crate) fn inverse_mod(a: u64, m: u64) -> u64 {
    debug_assert!(0 < a && a < m);
    let (mut r0, mut r1) = (m, a);
    let (mut u0, mut u1) = (0u64, 1u64);
    // Whether `t` of the second slot, `u1`'s, is positive (`t₁ = 1`).
    let mut positive = true;
    while r1 != 0 {
        let q = r0 / r1;
        (r0, r1) = (r1, r0 % r1);
        (u0, u1) = (u1, u0 + q * u1);
        positive = !positive;
    }
    debug_assert_eq!(r0, 1, "a is prime to m");
    // `u0` is `u_n`, and `t_n` is positive where `t_{n+1}`, the second slot's, is not.
    if positive {
        m - u0
    } else {
        u0
    }
}

/// `Field` for a coefficient field of `trigpoly` ([`Coefficient`]: its zero, one and name) by
/// its own operators: `Q` ([`Rational`]) and `Q(i)` ([`GaussianRational`], for solves whose
/// coefficients are complex, a bracket table's combinations).
macro_rules! exact_field {
    ($t:ty) => {
        impl Field for $t {
            fn zero() -> Self {
                <$t as Coefficient>::zero()
            }
            fn one() -> Self {
                <$t as Coefficient>::one()
            }
            fn is_zero(&self) -> bool {
                <$t as Coefficient>::is_zero(self)
            }
            fn add(&self, other: &Self) -> Self {
                self + other
            }
            fn sub(&self, other: &Self) -> Self {
                self - other
            }
            fn mul(&self, other: &Self) -> Self {
                self * other
            }
            fn inv(&self) -> Self {
                (self.try_inv())
                    .unwrap_or_else(|| panic!("inverse of zero in {}", <$t as Coefficient>::NAME))
            }
        }
    };
}

exact_field!(Rational);
exact_field!(GaussianRational);

/// The rational `r/s` with `|r|, s ≤ √(p/2)` and `r ≡ a·s (mod p)`, if there is one (it is then
/// unique): Wang's rational reconstruction by the extended Euclidean algorithm.
///
/// ```
/// use brackets::modular::{reconstruct, Fp};
/// use trigpoly::Rational;
/// let q = Rational::new(-7, 12);
/// assert_eq!(reconstruct(Fp::from_rational(&q).unwrap()), Some(q));
/// ```
pub fn reconstruct(a: Fp) -> Option<Rational> {
    let bound: i128 = isqrt(PRIME / 2) as i128;
    let (mut r0, mut r1) = (PRIME as i128, a.0 as i128);
    let (mut s0, mut s1) = (0i128, 1i128);
    while r1 > bound {
        let q = r0 / r1;
        (r0, r1) = (r1, r0 - q * r1);
        (s0, s1) = (s1, s0 - q * s1);
    }
    if s1 == 0 || s1.abs() > bound {
        return None;
    }
    let (num, den) = if s1 < 0 { (-r1, -s1) } else { (r1, s1) };
    if num.gcd(&den) != 1 {
        return None;
    }
    let q = Rational::from_fraction(
        &trigpoly::Integer::from_i128(num),
        &trigpoly::Integer::from_i128(den),
    )?;
    // The reconstruction must map back to the residue.
    (Fp::from_rational(&q) == Some(a)).then_some(q)
}

/// `⌊√n⌋` by Newton's method on integers.
fn isqrt(n: u64) -> u64 {
    if n < 2 {
        return n;
    }
    let mut x = n;
    let mut y = x / 2 + 1;
    while y < x {
        x = y;
        y = (x + n / x) / 2;
    }
    x
}

/// A sparse vector: `(index, value)` with distinct indices and no zero values.
pub type SparseVec<F> = Vec<(usize, F)>;

/// One basis vector of the semi-echelon form: its pivot (a nonzero index, value 1: the first,
/// or the one [`Echelon::insert_by`] chose), the vector, and the vector as a combination of
/// the inserted vectors (by id).
#[derive(Clone, Debug)]
struct Row<F> {
    pivot: usize,
    vec: SparseVec<F>,
    combo: SparseVec<F>,
}

/// A semi-echelon basis of the span of the vectors inserted so far, each basis vector
/// remembering which combination of inserted vectors it is.
///
/// Inserting a vector either extends the basis or returns its dependency on the earlier
/// independent vectors: `v_id = Σ c_j v_j`. Inserting vectors in a chosen order gives, for each
/// dependent one, a relation with the earlier ones only, which is how the kernel of a matrix
/// comes out in reduced form (one kernel vector per dependent column). The vectors it takes
/// may also list their entries in any order, an index more than once (the entries add up).
///
/// A reduction, and the combination it makes of inserted vectors, add into dense scratch
/// vectors kept between calls and read back only the entries they touched, and it visits only
/// the rows whose pivots it meets (in a queue by row), so that an insertion costs what the rows
/// it subtracts hold, not the dimension nor the number of rows or of vectors so far: a search
/// at degree 8 inserts hundreds of thousands of short vectors into thousands of rows.
#[derive(Debug)]
pub struct Echelon<F> {
    dim: usize,
    rows: Vec<Row<F>>,
    /// For each index, the basis row whose pivot it is.
    pivot_row: Vec<Option<usize>>,
    /// What a reduction works in, kept between reductions (behind a lock, so that a basis
    /// shared between threads answers `contains` and `express`).
    scratch: Mutex<Scratch<F>>,
}

impl<F: Field> Clone for Echelon<F> {
    fn clone(&self) -> Self {
        Echelon {
            dim: self.dim,
            rows: self.rows.clone(),
            pivot_row: self.pivot_row.clone(),
            scratch: Mutex::new(Scratch::new()),
        }
    }
}

/// The working space of a reduction, empty between reductions: the residue by index, the
/// combination by identifier, and the rows still to visit, by row (duplicates allowed).
#[derive(Debug)]
struct Scratch<F> {
    residue: Accumulator<F>,
    combo: Accumulator<F>,
    queue: BinaryHeap<Reverse<usize>>,
}

impl<F: Field> Scratch<F> {
    fn new() -> Self {
        Scratch {
            residue: Accumulator::new(),
            combo: Accumulator::new(),
            queue: BinaryHeap::new(),
        }
    }
}

/// A sparse vector summed in a dense one that is zero between sums (grown as indices need),
/// with the indices touched since.
#[derive(Debug)]
struct Accumulator<F> {
    dense: Vec<F>,
    touched: Vec<usize>,
}

impl<F: Field> Accumulator<F> {
    fn new() -> Self {
        Accumulator {
            dense: Vec::new(),
            touched: Vec::new(),
        }
    }

    /// Adds `x` at `i`; whether the value there was zero.
    fn add(&mut self, i: usize, x: &F) -> bool {
        if i >= self.dense.len() {
            self.dense.resize(i + 1, F::zero());
        }
        let was_zero = self.dense[i].is_zero();
        if was_zero {
            self.touched.push(i);
        }
        self.dense[i] = self.dense[i].add(x);
        was_zero
    }

    /// The value at `i`.
    fn get(&self, i: usize) -> F {
        self.dense.get(i).cloned().unwrap_or_else(F::zero)
    }

    /// Whether every entry is zero; the accumulator is zero again.
    fn clear(&mut self) -> bool {
        let dense = &mut self.dense;
        let mut zero = true;
        for i in self.touched.drain(..) {
            zero &= std::mem::replace(&mut dense[i], F::zero()).is_zero();
        }
        zero
    }

    /// The nonzero entries by increasing index; the accumulator is zero again.
    fn take(&mut self) -> SparseVec<F> {
        // An index that cancelled and came back is listed twice, and read as zero the second
        // time.
        self.touched.sort_unstable();
        let dense = &mut self.dense;
        self.touched
            .drain(..)
            .filter_map(|i| {
                let x = std::mem::replace(&mut dense[i], F::zero());
                (!x.is_zero()).then_some((i, x))
            })
            .collect()
    }
}

impl<F: Field> Echelon<F> {
    /// An empty basis of vectors with indices below `dim`.
    pub fn new(dim: usize) -> Self {
        Echelon {
            dim,
            rows: Vec::new(),
            pivot_row: vec![None; dim],
            scratch: Mutex::new(Scratch::new()),
        }
    }

    /// Takes vectors with indices below `dim` from now on (a basis over indices numbered as
    /// they are met); a smaller `dim` changes nothing.
    pub fn grow(&mut self, dim: usize) {
        if dim > self.dim {
            self.dim = dim;
            self.pivot_row.resize(dim, None);
        }
    }

    /// The number of independent vectors inserted.
    pub fn rank(&self) -> usize {
        self.rows.len()
    }

    /// Reduces `v` by the basis: the residue (by increasing index) and, when `track`, the
    /// combination of inserted vectors that was subtracted (by increasing identifier; empty
    /// otherwise, which spares a row's combination for each row subtracted).
    fn reduce(&self, v: &SparseVec<F>, track: bool) -> (SparseVec<F>, SparseVec<F>) {
        self.reduce_then(v, track, |residue, combo| (residue.take(), combo.take()))
    }

    /// Reduces `v` by the basis into the scratch accumulators, the residue and (when `track`)
    /// the combination, and returns what `finish` reads of them; `finish` leaves both zero.
    fn reduce_then<R>(
        &self,
        v: &SparseVec<F>,
        track: bool,
        finish: impl FnOnce(&mut Accumulator<F>, &mut Accumulator<F>) -> R,
    ) -> R {
        // Checked before any is added, so that the scratch stays zero.
        if let Some((i, _)) = v.iter().find(|(i, _)| *i >= self.dim) {
            panic!("index {i} out of range {}", self.dim);
        }
        // Nothing panics while the lock is held (the indices are checked above), so a poisoned
        // lock still holds zero scratch vectors.
        let mut scratch = self.scratch.lock().unwrap_or_else(PoisonError::into_inner);
        let Scratch {
            residue: acc,
            combo,
            queue,
        } = &mut *scratch;
        // Row r holds no pivot of an earlier row (it was reduced by them when inserted), so
        // subtracting it puts entries only on pivots of later rows: visited by increasing row,
        // each row is reached after every row that changes its pivot's entry.
        let pivot_rows = &self.pivot_row;
        let meet = |queue: &mut BinaryHeap<Reverse<usize>>, i: usize| {
            if let Some(r) = pivot_rows[i] {
                queue.push(Reverse(r));
            }
        };
        for (i, x) in v {
            if acc.add(*i, x) {
                meet(queue, *i);
            }
        }
        let mut last = None;
        while let Some(Reverse(r)) = queue.pop() {
            // A pivot that cancelled and came back was queued twice.
            if last == Some(r) {
                continue;
            }
            last = Some(r);
            let row = &self.rows[r];
            let c = acc.get(row.pivot);
            if c.is_zero() {
                continue;
            }
            let minus_c = F::zero().sub(&c);
            for (i, x) in &row.vec {
                if acc.add(*i, &minus_c.mul(x)) {
                    meet(queue, *i);
                }
            }
            if track {
                for (j, x) in &row.combo {
                    combo.add(*j, &c.mul(x));
                }
            }
        }
        finish(acc, combo)
    }

    /// Inserts `v` under the identifier `id` (larger than every earlier one). `None` if it is
    /// independent of the earlier vectors (the basis grows), otherwise the coefficients `c_j`,
    /// by earlier identifiers, with `v = Σ c_j v_j`.
    pub fn insert(&mut self, id: usize, v: &SparseVec<F>) -> Option<SparseVec<F>> {
        self.insert_by(id, v, |_| 0)
    }

    /// [`Echelon::insert`], with the pivot of a new basis row chosen by `choose` among the
    /// residue's entries (by increasing index; it returns a position in that list). Any choice
    /// gives the same dependencies, since they are the unique relations with the earlier
    /// independent vectors; the choice changes only the work: a pivot that later vectors
    /// seldom hold is a row they seldom subtract.
    pub fn insert_by(
        &mut self,
        id: usize,
        v: &SparseVec<F>,
        choose: impl FnOnce(&SparseVec<F>) -> usize,
    ) -> Option<SparseVec<F>> {
        let (residue, combo) = self.reduce(v, true);
        if residue.is_empty() {
            return Some(combo);
        }
        let (pivot, lead) = &residue[choose(&residue)];
        // Row r holds no pivot of an earlier row (it was reduced by them), whichever of its
        // entries becomes its own, which is all that `reduce_then` relies on.
        // residue = v − Σ c_k row_k, in terms of inserted vectors: e_id − combo, scaled so that
        // the pivot is 1.
        let (pivot, inv) = (*pivot, lead.inv());
        let vec: SparseVec<F> = residue.iter().map(|(i, x)| (*i, x.mul(&inv))).collect();
        let minus_inv = F::zero().sub(&inv);
        let mut combo: SparseVec<F> = combo.iter().map(|(j, c)| (*j, c.mul(&minus_inv))).collect();
        combo.push((id, inv));
        self.pivot_row[pivot] = Some(self.rows.len());
        self.rows.push(Row { pivot, vec, combo });
        None
    }

    /// Inserts `v` under the identifier `id` if it is independent of the earlier vectors;
    /// whether it was. A dependent vector costs one reduction without its combination, which
    /// is what a span of many dependent vectors (products of integrals) needs.
    pub fn extend(&mut self, id: usize, v: &SparseVec<F>) -> bool {
        !self.contains(v) && self.insert(id, v).is_none()
    }

    /// `v` as a combination `Σ c_j v_j` of the inserted vectors (by identifier), if it lies in
    /// their span.
    pub fn express(&self, v: &SparseVec<F>) -> Option<SparseVec<F>> {
        let (residue, combo) = self.reduce(v, true);
        residue.is_empty().then_some(combo)
    }

    /// `v` reduced by the basis: `v` less the combination of basis rows that leaves no
    /// entry on a pivot (by increasing index; empty when `v` lies in the span).
    pub fn residue(&self, v: &SparseVec<F>) -> SparseVec<F> {
        self.reduce(v, false).0
    }

    /// Whether `v` lies in the span of the inserted vectors.
    pub fn contains(&self, v: &SparseVec<F>) -> bool {
        // Whether the residue is zero needs no sorted list of it.
        self.reduce_then(v, false, |residue, _| residue.clear())
    }

    /// The pivots of the basis rows, in insertion order.
    pub fn pivots(&self) -> Vec<usize> {
        self.rows.iter().map(|r| r.pivot).collect()
    }

    /// Whether the index is the pivot of a basis row.
    pub fn is_pivot(&self, i: usize) -> bool {
        self.pivot_row.get(i).is_some_and(|r| r.is_some())
    }
}

/// Reduces a sparse rational vector modulo `p`; `None` if a denominator is divisible by `p`.
pub fn to_fp(v: &SparseVec<Rational>) -> Option<SparseVec<Fp>> {
    let mut out = Vec::with_capacity(v.len());
    for (i, q) in v {
        let x = Fp::from_rational(q)?;
        if !x.is_zero() {
            out.push((*i, x));
        }
    }
    Some(out)
}

/// Reconstructs every entry of a vector over `F_p`; `None` if one fails.
pub fn reconstruct_vec(v: &SparseVec<Fp>) -> Option<SparseVec<Rational>> {
    v.iter()
        .map(|(i, x)| reconstruct(*x).map(|q| (*i, q)))
        .collect()
}

/// The sparse vector of entries `(j, x)` in any order, those of one index added up, zeros
/// dropped.
pub(crate) fn sum_by_index<F: Field>(mut v: SparseVec<F>) -> SparseVec<F> {
    v.sort_unstable_by_key(|x| x.0);
    v.dedup_by(|later, kept| {
        let same = later.0 == kept.0;
        if same {
            kept.1 = kept.1.add(&later.1);
        }
        same
    });
    v.retain(|x| !x.1.is_zero());
    v
}

/// The kernel of a matrix given by its columns (sparse, rows below `rows`): one kernel vector
/// per column that depends on the earlier ones, `e_j − Σ c_i e_i`, in column order. Computed
/// modulo `p`, reconstructed, and checked exactly against every column; if the check fails the
/// elimination is redone over `Q`. The result is exact either way.
pub fn kernel(columns: &[SparseVec<Rational>], rows: usize) -> Vec<SparseVec<Rational>> {
    if let Some(k) = kernel_modular(columns, rows) {
        let mut sums = CombinationSums::new();
        if k.iter().all(|v| sums.equals(columns, v, &[])) {
            return k;
        }
    }
    kernel_exact(columns, rows)
}

fn kernel_modular(
    columns: &[SparseVec<Rational>],
    rows: usize,
) -> Option<Vec<SparseVec<Rational>>> {
    kernel_mod_p(columns, rows)?
        .iter()
        .map(reconstruct_vec)
        .collect()
}

/// The kernel modulo `p`, unchecked: one vector per column that depends on the earlier
/// ones, `e_j − Σ c_i e_i`, in column order, each sorted by index; `None` if a column has a
/// denominator divisible by `p`. For a search whose every result is checked exactly.
pub fn kernel_mod_p(columns: &[SparseVec<Rational>], rows: usize) -> Option<Vec<SparseVec<Fp>>> {
    let mut e = Echelon::<Fp>::new(rows);
    let mut later = LaterColumns::new(columns, rows);
    let mut out = Vec::new();
    for (j, c) in columns.iter().enumerate() {
        later.pass(c);
        if let Some(mut v) = e.insert_by(j, &to_fp(c)?, |residue| later.pivot(residue)) {
            for x in v.iter_mut() {
                x.1 = Fp::zero().sub(&x.1);
            }
            // Every identifier in the combination is below `j`.
            v.push((j, Fp::one()));
            out.push(v);
        }
    }
    Some(out)
}

/// The same kernel, by exact elimination over `Q`.
pub fn kernel_exact(columns: &[SparseVec<Rational>], rows: usize) -> Vec<SparseVec<Rational>> {
    let mut e = Echelon::<Rational>::new(rows);
    let mut later = LaterColumns::new(columns, rows);
    let mut out = Vec::new();
    for (j, c) in columns.iter().enumerate() {
        later.pass(c);
        if let Some(mut v) = e.insert_by(j, c, |residue| later.pivot(residue)) {
            for x in v.iter_mut() {
                x.1 = -&x.1;
            }
            v.push((j, Rational::one()));
            out.push(v);
        }
    }
    out
}

/// How many of the columns not yet inserted hold each row: the kernels pivot each new basis
/// row on the entry that the fewest later columns hold (the first of those), so that later
/// columns meet few pivots and subtract few rows. Taking the first entry instead made a
/// search's eliminations subtract far more (Markowitz's rule, on one side).
struct LaterColumns(Vec<u32>);

impl LaterColumns {
    fn new<F>(columns: &[SparseVec<F>], rows: usize) -> Self {
        let mut count = vec![0u32; rows];
        for (i, _) in columns.iter().flatten() {
            count[*i] += 1;
        }
        LaterColumns(count)
    }

    /// The column about to be inserted is no longer a later one.
    fn pass<F>(&mut self, column: &SparseVec<F>) {
        for (i, _) in column {
            self.0[*i] -= 1;
        }
    }

    /// The position in `residue` of its entry that the fewest later columns hold.
    fn pivot<F>(&self, residue: &SparseVec<F>) -> usize {
        (0..residue.len())
            .min_by_key(|&k| self.0[residue[k].0])
            .unwrap_or(0)
    }
}

/// The sum in which exact checks over `Q`, `Σ v_j · column_j = target`, are made one after
/// another ([`CombinationSums::equals`]): a dense vector by row, zero again after each check,
/// which reads and clears only the rows the check's columns touch, and grows to the largest
/// row a check has touched. A sum made for each check would zero-fill and copy up to its
/// largest row every time: `--new-only`'s dependencies are thousands of checks in a space of
/// 10⁵ rows, a closure's relations at degree 8 a thousand and more, each against the multiples
/// of those before it.
///
/// ```
/// use brackets::modular::CombinationSums;
/// use trigpoly::Rational;
/// // Columns (1, 0, 1) and (0, 2, 2): their difference is (1, −2, −1).
/// let q = |n: i64| Rational::from(n);
/// let columns = vec![vec![(0, q(1)), (2, q(1))], vec![(1, q(2)), (2, q(2))]];
/// let mut sums = CombinationSums::new();
/// let difference = vec![(0, q(1)), (1, q(-1))];
/// assert!(sums.equals(&columns, &difference, &[(0, q(1)), (1, q(-2)), (2, q(-1))]));
/// assert!(!sums.equals(&columns, &difference, &[(0, q(1))]));
/// // Twice the first column less the second is not zero.
/// assert!(!sums.equals(&columns, &vec![(0, q(2)), (1, q(-1))], &[]));
/// ```
#[derive(Debug)]
pub struct CombinationSums(Accumulator<Rational>);

impl Default for CombinationSums {
    fn default() -> Self {
        Self::new()
    }
}

impl CombinationSums {
    /// A sum with no rows yet.
    pub fn new() -> Self {
        CombinationSums(Accumulator::new())
    }

    /// Whether `Σ v_j · column_j = target` exactly (the columns held or borrowed); the sum is
    /// zero again after.
    pub fn equals<C: Borrow<SparseVec<Rational>>>(
        &mut self,
        columns: &[C],
        v: &SparseVec<Rational>,
        target: &[(usize, Rational)],
    ) -> bool {
        let sum = &mut self.0;
        #[cfg(test)]
        let rows_before = sum.dense.len();
        for (j, x) in v {
            for (i, a) in columns[*j].borrow() {
                sum.add(*i, &(x * a));
            }
        }
        for (i, x) in target {
            sum.add(*i, &-x);
        }
        #[cfg(test)]
        SUMS_GROWN.with(|grown| grown.set(grown.get() + sum.dense.len() - rows_before));
        sum.clear()
    }
}

#[cfg(test)]
thread_local! {
    /// How many rows the exact checks' sums ([`CombinationSums`]) have grown by on this thread: the
    /// dense memory that checking combinations writes, which the tests bound.
    pub(crate) static SUMS_GROWN: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A xorshift generator from `seed`: the tests' repeatable pseudo-random words.
    fn xorshift(mut x: u64) -> impl FnMut() -> u64 {
        move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        }
    }

    #[test]
    fn barretts_product_is_the_remainder_of_the_division() {
        // Moduli of every size up to the largest, the primes used among them, the residues
        // at and near their ends beside pseudo-random ones.
        let mut next = xorshift(0x2545_F491_4F6C_DD1D);
        let below = previous_prime(PRIME);
        for p in [
            2,
            3,
            97,
            1_000_003,
            (1 << 32) + 15,
            (1 << 61) - 1,
            1 << 61,
            below,
            PRIME,
        ] {
            let m = Modulus::new(p);
            let mut residues = vec![0, 1 % p, p / 2, p - 1];
            residues.extend((0..40).map(|_| next() % p));
            for &a in &residues {
                for &b in &residues {
                    let exact = ((u128::from(a) * u128::from(b)) % u128::from(p)) as u64;
                    assert_eq!(m.mul(a, b), exact, "{a}·{b} mod {p}");
                    assert_eq!(
                        m.add(a, b),
                        ((u128::from(a) + u128::from(b)) % u128::from(p)) as u64
                    );
                    assert_eq!(m.add(m.sub(a, b), b), a, "({a} − {b}) + {b} mod {p}");
                }
            }
        }
    }

    fn is_prime(n: u64) -> bool {
        // Deterministic Miller–Rabin for 64-bit integers.
        if n < 2 {
            return false;
        }
        let mul = |a: u64, b: u64| ((a as u128 * b as u128) % n as u128) as u64;
        let pow = |mut b: u64, mut e: u64| {
            let mut acc = 1u64;
            while e > 0 {
                if e & 1 == 1 {
                    acc = mul(acc, b);
                }
                b = mul(b, b);
                e >>= 1;
            }
            acc
        };
        let (mut d, mut s) = (n - 1, 0);
        while d % 2 == 0 {
            d /= 2;
            s += 1;
        }
        'witness: for a in [2u64, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37] {
            if a % n == 0 {
                continue;
            }
            let mut x = pow(a, d);
            if x == 1 || x == n - 1 {
                continue;
            }
            for _ in 1..s {
                x = mul(x, x);
                if x == n - 1 {
                    continue 'witness;
                }
            }
            return false;
        }
        true
    }

    /// Over F_p, vectors that are often combinations of earlier ones (so that reductions
    /// cancel entries and touch them again): every dependency returned adds up to its vector,
    /// every independent vector raises the rank, and the span answers `contains` and
    /// `express` for combinations and for vectors outside it, the scratch vectors clean
    /// between calls, also from two threads at once.
    #[test]
    fn dependencies_add_up_and_the_span_is_the_inserted_vectors() {
        let mut next = xorshift(0x2545_F491_4F6C_DD1Du64);
        let dim = 40;
        let mut e = Echelon::<Fp>::new(dim);
        let mut inserted: Vec<SparseVec<Fp>> = Vec::new();
        let combine = |terms: &[(usize, Fp)], vectors: &[SparseVec<Fp>]| {
            let mut dense = vec![Fp(0); dim];
            for (j, c) in terms {
                for (i, v) in &vectors[*j] {
                    dense[*i] = dense[*i].add(&c.mul(v));
                }
            }
            dense
                .into_iter()
                .enumerate()
                .filter(|(_, v)| !v.is_zero())
                .collect::<SparseVec<Fp>>()
        };
        for id in 0..120 {
            let v: SparseVec<Fp> = if id % 3 == 2 && !inserted.is_empty() {
                // A combination of two earlier vectors: dependent.
                let (a, b) = (next() as usize % id, next() as usize % id);
                combine(&[(a, Fp::new(next())), (b, Fp::new(next()))], &inserted)
            } else {
                let mut idx: Vec<usize> = (0..4).map(|_| next() as usize % dim).collect();
                idx.sort_unstable();
                idx.dedup();
                idx.into_iter().map(|i| (i, Fp::new(next() | 1))).collect()
            };
            let rank = e.rank();
            inserted.push(v.clone());
            match e.insert(id, &v) {
                None => assert_eq!(e.rank(), rank + 1),
                Some(dep) => {
                    assert_eq!(e.rank(), rank);
                    assert_eq!(combine(&dep, &inserted), v, "vector {id}");
                }
            }
            let w = combine(
                &[(id, Fp(3)), (next() as usize % (id + 1), Fp(5))],
                &inserted,
            );
            assert!(e.contains(&w));
            let c = e.express(&w).expect("in the span");
            assert_eq!(combine(&c, &inserted), w);
        }
        assert_eq!(e.rank(), dim);
        // A basis shared between threads answers queries from each.
        let (first, second) = (inserted[0].clone(), inserted[1].clone());
        std::thread::scope(|s| {
            s.spawn(|| assert!(e.contains(&first)));
            s.spawn(|| assert!(e.express(&second).is_some()));
        });
        let mut small = Echelon::<Fp>::new(3);
        small.insert(0, &vec![(0, Fp(1))]);
        assert!(!small.contains(&vec![(1, Fp(1))]));
        assert_eq!(small.express(&vec![(0, Fp(1)), (2, Fp(4))]), None);
        assert_eq!(small.express(&vec![(0, Fp(7))]), Some(vec![(0, Fp(7))]));
    }

    /// A basis grown to take larger indices keeps its rows; the residue of a vector has no
    /// entry on a pivot and differs from it by a vector of the span.
    #[test]
    fn a_grown_basis_reduces_to_residues_off_its_pivots() {
        let q = |n: i64| Rational::from(n);
        let mut e = Echelon::<Rational>::new(2);
        assert!(e.insert(0, &vec![(0, q(1)), (1, q(-1))]).is_none());
        e.grow(4);
        e.grow(3);
        assert!(e.insert_by(1, &vec![(1, q(2)), (3, q(1))], |_| 1).is_none());
        assert_eq!(e.pivots(), [0, 3]);
        let v = vec![(0, q(3)), (2, q(5)), (3, q(1))];
        let residue = e.residue(&v);
        assert!(residue.iter().all(|(i, _)| !e.is_pivot(*i)), "{residue:?}");
        // v − residue = 3 (e0 − e1) + (2 e1 + e3).
        assert_eq!(residue, vec![(1, q(1)), (2, q(5))]);
        assert!(e.residue(&vec![(0, q(2)), (1, q(-2))]).is_empty());
    }

    /// The product's reduction without a division agrees with the remainder, for residues at
    /// both ends of the field and between (the largest product, `(p − 1)²`, included).
    #[test]
    fn products_reduce_like_the_remainder() {
        let mut values: Vec<u64> = vec![0, 1, 2, 56, 57, 58, 1 << 31, 1 << 61, (1 << 62) - 1];
        values.extend((1..=64).map(|k| PRIME - k));
        let mut next = xorshift(0x9E37_79B9_7F4A_7C15);
        values.extend((0..200).map(|_| next() % PRIME));
        for &a in &values {
            for &b in &values {
                let (a, b) = (a % PRIME, b % PRIME);
                let want = (a as u128 * b as u128 % PRIME as u128) as u64;
                assert_eq!(Fp(a).mul(&Fp(b)), Fp(want), "{a} * {b}");
            }
        }
    }

    /// Inverses by Euclid, checked against Fermat's `a^(p−2)`, for residues at the edges of a
    /// word and random ones.
    #[test]
    fn inverses_multiply_to_one() {
        let mut values: Vec<u64> = (1..=300).collect();
        values.extend([
            (1 << 32) - 1,
            1 << 32,
            (1 << 32) + 1,
            1 << 61,
            PRIME - 2,
            PRIME - 1,
        ]);
        let mut next = xorshift(0xD1B5_4A32_D192_ED03);
        for _ in 0..200 {
            let x = next();
            values.extend([x % PRIME, x % (1 << 32)]);
        }
        for a in values.into_iter().filter(|a| a % PRIME != 0) {
            let a = Fp::new(a);
            assert_eq!(a.mul(&a.inv()), Fp(1), "{a:?}");
            assert_eq!(a.inv(), a.pow(PRIME - 2), "{a:?}");
        }
    }

    /// Every nonzero residue of small primes (and of a composite modulus, each one prime to
    /// it) has the inverse a search over all residues finds.
    #[test]
    fn every_residue_of_a_small_modulus_has_its_inverse() {
        for m in [2u64, 3, 101, 257, 7919, 36] {
            for a in (1..m).filter(|&a| a.gcd(&m) == 1) {
                let inverse = (1..m).find(|&b| a * b % m == 1);
                assert_eq!(Some(inverse_mod(a, m)), inverse, "{a}⁻¹ mod {m}");
            }
        }
        // The last and longest cofactors: a = m − 1 and consecutive Fibonacci numbers.
        assert_eq!(inverse_mod(PRIME - 1, PRIME), PRIME - 1);
        let (f, g) = (4_660_046_610_375_530_309u64, 7_540_113_804_746_346_429u64);
        assert_eq!((inverse_mod(f, g) as u128 * f as u128) % g as u128, 1);
    }

    /// Residues near the one modulus used, [`PRIME`], and near the largest one `inverse_mod`
    /// takes, the prime `2⁶⁴ − 59` (and the largest consecutive Fibonacci numbers in a word,
    /// the longest run of quotients 1), have inverses whose product with them is 1, checked in
    /// `u128` apart from [`Fp`]'s reduction: no cofactor overflows.
    #[test]
    fn inverses_near_the_largest_moduli_are_exact() {
        let is_inverse = |a: u64, m: u64| {
            let b = inverse_mod(a, m);
            assert!(b < m, "{a}⁻¹ mod {m} = {b}");
            assert_eq!(a as u128 * b as u128 % m as u128, 1, "{a}⁻¹ mod {m} = {b}");
        };
        const LARGEST: u64 = u64::MAX - 58;
        assert!(is_prime(LARGEST));
        for m in [PRIME, LARGEST] {
            let near = (1..=2000).flat_map(|k| [k, m - k, m / 2 + k, m / 2 - k]);
            let powers = (0..64).map(|k| 1u64 << k).filter(|&x| x < m);
            for a in near.chain(powers) {
                is_inverse(a, m);
            }
            let mut next = xorshift(0x9E37_79B9_7F4A_7C15);
            for _ in 0..2000 {
                is_inverse(next() % (m - 1) + 1, m);
            }
        }
        // F₉₂ and F₉₃, the largest Fibonacci numbers below 2⁶⁴: 91 quotients of 1.
        let (f, g) = (7_540_113_804_746_346_429u64, 12_200_160_415_121_876_738u64);
        is_inverse(f, g);
        is_inverse(g - f, g);
    }

    #[test]
    fn a_residue_prints_as_its_value_below_p() {
        assert_eq!(Fp::new(0).to_string(), "0");
        assert_eq!(Fp::new(PRIME + 7).to_string(), "7");
        assert_eq!(Fp::from_i64(-1).to_string(), "4611686018427387846");
        assert_eq!(
            Fp::from_rational(&Rational::new(1, 2)).unwrap().to_string(),
            "2305843009213693924"
        );
    }

    #[test]
    #[should_panic(expected = "inverse of zero in F_p")]
    fn zero_has_no_inverse() {
        Fp::new(PRIME).inv();
    }

    #[test]
    fn the_modulus_is_a_62_bit_prime() {
        assert!(is_prime(PRIME));
        assert_eq!(64 - PRIME.leading_zeros(), 62);
    }

    #[test]
    fn reconstruction_round_trips_small_rationals() {
        for (n, d) in [
            (0, 1),
            (1, 1),
            (-1, 2),
            (355, 113),
            (-123456, 789),
            (1 << 29, 3),
        ] {
            let q = Rational::new(n, d);
            assert_eq!(reconstruct(Fp::from_rational(&q).unwrap()), Some(q));
        }
        // Whatever a residue reconstructs to maps back to it.
        let a = Fp::new(3_141_592_653_589_793_238);
        if let Some(q) = reconstruct(a) {
            assert_eq!(Fp::from_rational(&q), Some(a));
        }
        // −1/2 is (p − 1)/2.
        assert_eq!(reconstruct(Fp::new(PRIME / 2)), Some(Rational::new(-1, 2)));
    }

    #[test]
    fn rationals_map_to_their_residues() {
        // q·d ≡ n (mod p), with machine-word and big numerators and denominators alike.
        let big = |n: &str, d: &str| {
            Rational::from_fraction(
                &trigpoly::Integer::from_bigint(n.parse().unwrap()),
                &trigpoly::Integer::from_bigint(d.parse().unwrap()),
            )
            .unwrap()
        };
        let p = PRIME as i64;
        for (q, n, d) in [
            (Rational::new(-7, 3), Fp::from_i64(-7), Fp::from_i64(3)),
            (Rational::new(p + 5, 1), Fp::from_i64(5), Fp::from_i64(1)),
            (Rational::new(1, p - 1), Fp::from_i64(1), Fp::from_i64(-1)),
            (
                big("-100000000000000000000000000001", "3"),
                Fp::from_rational(&big("-100000000000000000000000000001", "1")).unwrap(),
                Fp::from_i64(3),
            ),
        ] {
            let r = Fp::from_rational(&q).unwrap();
            assert_eq!(r.mul(&d), n, "{q:?}");
        }
        // p divides the denominator: no residue, in a word or past one.
        assert_eq!(Fp::from_rational(&Rational::new(1, p)), None);
        assert_eq!(Fp::from_rational(&Rational::new(3, 2 * p)), None);
        let p_squared = (PRIME as u128 * PRIME as u128).to_string();
        assert_eq!(Fp::from_rational(&big("1", &p_squared)), None);
    }

    /// The kernels pivot each new row on the entry fewest later columns hold: their vectors
    /// are those of the first-entry pivots, over F_p and over Q, and any pivot gives the same
    /// dependencies, on columns that are often combinations of earlier ones.
    #[test]
    fn the_kernels_do_not_depend_on_the_pivots() {
        let mut next = xorshift(0x6A09_E667_F3BC_C909u64);
        let rows = 30;
        let mut columns: Vec<SparseVec<Rational>> = Vec::new();
        for j in 0..60 {
            let mut dense = vec![Rational::zero(); rows];
            if j % 3 == 2 {
                for _ in 0..2 {
                    let (k, c) = (next() as usize % j, Rational::from(next() as i64 % 7 - 3));
                    for (i, a) in &columns[k] {
                        dense[*i] += &c * a;
                    }
                }
            } else {
                for _ in 0..3 {
                    dense[next() as usize % rows] += Rational::from(next() as i64 % 9 + 1);
                }
            }
            let column = dense.into_iter().enumerate().filter(|(_, a)| !a.is_zero());
            columns.push(column.collect());
        }
        // By the first entry, as `insert` pivots.
        let by_first = |columns: &[SparseVec<Rational>]| {
            let mut e = Echelon::<Rational>::new(rows);
            let mut out = Vec::new();
            for (j, c) in columns.iter().enumerate() {
                if let Some(mut v) = e.insert(j, c) {
                    v.iter_mut().for_each(|x| x.1 = -&x.1);
                    v.push((j, Rational::one()));
                    out.push(v);
                }
            }
            out
        };
        let expected = by_first(&columns);
        assert!(expected.len() >= 20, "{} dependent columns", expected.len());
        assert_eq!(kernel_exact(&columns, rows), expected);
        let modular = kernel_mod_p(&columns, rows).expect("no denominator p");
        let expected_fp: Vec<SparseVec<Fp>> = expected.iter().filter_map(to_fp).collect();
        assert_eq!(modular, expected_fp);
        // The last entry as the pivot: the same dependencies.
        let mut e = Echelon::<Rational>::new(rows);
        let mut first = Echelon::<Rational>::new(rows);
        for (j, c) in columns.iter().enumerate() {
            let dependency = e.insert_by(j, c, |residue| residue.len() - 1);
            assert_eq!(dependency, first.insert(j, c), "column {j}");
        }
        assert_ne!(e.pivots(), first.pivots());
    }

    #[test]
    fn kernel_is_exact() {
        // Columns (1, 2, 3), (2, 4, 6), (1, 0, 1), (3, 4, 7): kernel spanned by
        // e1 − 2e0 and e3 − e0 − ... found in column order.
        let col = |v: [i64; 3]| -> SparseVec<Rational> {
            v.iter()
                .enumerate()
                .filter(|(_, x)| **x != 0)
                .map(|(i, x)| (i, Rational::from(*x)))
                .collect()
        };
        let cols = vec![
            col([1, 2, 3]),
            col([2, 4, 6]),
            col([1, 0, 1]),
            col([3, 4, 7]),
        ];
        let k = kernel(&cols, 3);
        assert_eq!(k.len(), 2);
        let mut sums = CombinationSums::new();
        for v in &k {
            assert!(sums.equals(&cols, v, &[]));
        }
        assert_eq!(kernel_exact(&cols, 3).len(), 2);
        // Column 0 minus column 2 is (0, 2, 2): its entry 0 cancels.
        let r = |x: i64| Rational::from(x);
        let diff = vec![(0, r(1)), (2, r(-1))];
        assert!(!sums.equals(&cols, &diff, &[]));
        let target = vec![(1, r(2)), (2, r(2))];
        assert!(sums.equals(&cols, &diff, &target));
        assert!(!sums.equals(&cols, &diff, &target[..1]));
        assert!(sums.equals(&cols, &vec![], &[]));
    }
}
