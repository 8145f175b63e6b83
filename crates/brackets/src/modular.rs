//! Exact linear algebra for discovery: which vectors of a sequence depend on earlier ones, and
//! how. The same semi-echelon elimination runs over the prime field `F_p` (`p = 2⁶² − 57`,
//! products in `u128`) for speed and over `Q` ([`Rational`]) when exactness must not depend on
//! a reconstruction; [`reconstruct`] lifts a residue back to a small rational.
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

use std::fmt::Debug;

use num_bigint::BigInt;
use num_integer::Integer as _;
use num_traits::ToPrimitive;
use trigpoly::Rational;

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

/// An element of `F_p`, `p =` [`PRIME`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Fp(u64);

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

    /// `q mod p`, or `None` if `p` divides the denominator.
    pub fn from_rational(q: &Rational) -> Option<Self> {
        let n = integer_mod(&q.numer());
        let d = integer_mod(&q.denom());
        (!d.is_zero()).then(|| n.mul(&d.inv()))
    }

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

fn integer_mod(a: &trigpoly::Integer) -> Fp {
    match a.to_i64() {
        Some(v) => Fp::from_i64(v),
        None => bigint_mod(&a.to_bigint()),
    }
}

fn bigint_mod(a: &BigInt) -> Fp {
    let p = BigInt::from(PRIME);
    let r = a.mod_floor(&p);
    Fp(r.to_u64().expect("a residue below p fits in u64"))
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
        Fp(((self.0 as u128 * other.0 as u128) % PRIME as u128) as u64)
    }
    fn inv(&self) -> Self {
        assert!(self.0 != 0, "inverse of zero in F_p");
        self.pow(PRIME - 2)
    }
}

impl Field for Rational {
    fn zero() -> Self {
        Rational::zero()
    }
    fn one() -> Self {
        Rational::one()
    }
    fn is_zero(&self) -> bool {
        Rational::is_zero(self)
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
        self.try_inv().expect("inverse of zero in Q")
    }
}

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

/// One basis vector of the semi-echelon form: its pivot (first nonzero index, value 1), the
/// vector, and the vector as a combination of the inserted vectors (by id).
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
/// comes out in reduced form (one kernel vector per dependent column).
#[derive(Clone, Debug)]
pub struct Echelon<F> {
    dim: usize,
    rows: Vec<Row<F>>,
    /// For each index, the basis row whose pivot it is.
    pivot_row: Vec<Option<usize>>,
}

impl<F: Field> Echelon<F> {
    /// An empty basis of vectors with indices below `dim`.
    pub fn new(dim: usize) -> Self {
        Echelon {
            dim,
            rows: Vec::new(),
            pivot_row: vec![None; dim],
        }
    }

    /// The number of independent vectors inserted.
    pub fn rank(&self) -> usize {
        self.rows.len()
    }

    /// Reduces `v` by the basis: the residue (dense) and the combination of inserted vectors
    /// that was subtracted.
    fn reduce(&self, v: &SparseVec<F>) -> (Vec<F>, Vec<(usize, F)>) {
        let mut acc = vec![F::zero(); self.dim];
        for (i, x) in v {
            assert!(*i < self.dim, "index {i} out of range {}", self.dim);
            acc[*i] = acc[*i].add(x);
        }
        let mut used: Vec<(usize, F)> = Vec::new();
        // Rows were reduced by all earlier rows when inserted, so reducing in insertion order
        // clears every pivot.
        for (k, row) in self.rows.iter().enumerate() {
            let c = acc[row.pivot].clone();
            if c.is_zero() {
                continue;
            }
            for (i, x) in &row.vec {
                acc[*i] = acc[*i].sub(&c.mul(x));
            }
            used.push((k, c));
        }
        (acc, used)
    }

    /// The combination of inserted vectors that the basis rows `used` (with coefficients) add up
    /// to.
    fn combine(&self, used: &[(usize, F)], ids: usize) -> Vec<F> {
        let mut combo = vec![F::zero(); ids];
        for (k, c) in used {
            for (j, x) in &self.rows[*k].combo {
                if *j >= combo.len() {
                    combo.resize(*j + 1, F::zero());
                }
                combo[*j] = combo[*j].add(&c.mul(x));
            }
        }
        combo
    }

    fn max_id(&self) -> usize {
        self.rows
            .iter()
            .flat_map(|r| r.combo.iter().map(|c| c.0 + 1))
            .max()
            .unwrap_or(0)
    }

    /// Inserts `v` under the identifier `id` (larger than every earlier one). `None` if it is
    /// independent of the earlier vectors (the basis grows), otherwise the coefficients `c_j`,
    /// by earlier identifiers, with `v = Σ c_j v_j`.
    pub fn insert(&mut self, id: usize, v: &SparseVec<F>) -> Option<SparseVec<F>> {
        let (acc, used) = self.reduce(v);
        let ids = self.max_id().max(id + 1);
        let combo = self.combine(&used, ids);
        let Some(pivot) = acc.iter().position(|x| !x.is_zero()) else {
            return Some(sparse(combo));
        };
        // residue = v − Σ c_k row_k, in terms of inserted vectors: e_id − combo.
        let inv = acc[pivot].inv();
        let vec: SparseVec<F> = acc
            .iter()
            .enumerate()
            .filter(|(_, x)| !x.is_zero())
            .map(|(i, x)| (i, x.mul(&inv)))
            .collect();
        let mut residue_combo: Vec<F> = combo.iter().map(|c| F::zero().sub(c)).collect();
        if residue_combo.len() <= id {
            residue_combo.resize(id + 1, F::zero());
        }
        residue_combo[id] = residue_combo[id].add(&F::one());
        let combo = sparse(residue_combo.iter().map(|c| c.mul(&inv)).collect());
        self.pivot_row[pivot] = Some(self.rows.len());
        self.rows.push(Row { pivot, vec, combo });
        None
    }

    /// `v` as a combination `Σ c_j v_j` of the inserted vectors (by identifier), if it lies in
    /// their span.
    pub fn express(&self, v: &SparseVec<F>) -> Option<SparseVec<F>> {
        let (acc, used) = self.reduce(v);
        if acc.iter().any(|x| !x.is_zero()) {
            return None;
        }
        Some(sparse(self.combine(&used, self.max_id())))
    }

    /// Whether `v` lies in the span of the inserted vectors.
    pub fn contains(&self, v: &SparseVec<F>) -> bool {
        self.reduce(v).0.iter().all(|x| x.is_zero())
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

fn sparse<F: Field>(dense: Vec<F>) -> SparseVec<F> {
    dense
        .into_iter()
        .enumerate()
        .filter(|(_, x)| !x.is_zero())
        .collect()
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

/// The kernel of a matrix given by its columns (sparse, rows below `rows`): one kernel vector
/// per column that depends on the earlier ones, `e_j − Σ c_i e_i`, in column order. Computed
/// modulo `p`, reconstructed, and checked exactly against every column; if the check fails the
/// elimination is redone over `Q`. The result is exact either way.
pub fn kernel(columns: &[SparseVec<Rational>], rows: usize) -> Vec<SparseVec<Rational>> {
    if let Some(k) = kernel_modular(columns, rows) {
        if k.iter().all(|v| in_kernel(columns, rows, v)) {
            return k;
        }
    }
    kernel_exact(columns, rows)
}

fn kernel_modular(
    columns: &[SparseVec<Rational>],
    rows: usize,
) -> Option<Vec<SparseVec<Rational>>> {
    let mut e = Echelon::<Fp>::new(rows);
    let mut out = Vec::new();
    for (j, c) in columns.iter().enumerate() {
        if let Some(dep) = e.insert(j, &to_fp(c)?) {
            let mut v = reconstruct_vec(&dep)?;
            for x in v.iter_mut() {
                x.1 = -&x.1;
            }
            v.push((j, Rational::one()));
            out.push(v);
        }
    }
    Some(out)
}

/// The same kernel, by exact elimination over `Q`.
pub fn kernel_exact(columns: &[SparseVec<Rational>], rows: usize) -> Vec<SparseVec<Rational>> {
    let mut e = Echelon::<Rational>::new(rows);
    let mut out = Vec::new();
    for (j, c) in columns.iter().enumerate() {
        if let Some(mut v) = e.insert(j, c) {
            for x in v.iter_mut() {
                x.1 = -&x.1;
            }
            v.push((j, Rational::one()));
            out.push(v);
        }
    }
    out
}

/// Whether `Σ v_j · column_j = 0` exactly.
pub fn in_kernel(columns: &[SparseVec<Rational>], rows: usize, v: &SparseVec<Rational>) -> bool {
    let mut acc = vec![Rational::zero(); rows];
    for (j, x) in v {
        for (i, a) in &columns[*j] {
            acc[*i] += x * a;
        }
    }
    acc.iter().all(Rational::is_zero)
}

#[cfg(test)]
mod tests {
    use super::*;

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
        for v in &k {
            assert!(in_kernel(&cols, 3, v));
        }
        assert_eq!(kernel_exact(&cols, 3).len(), 2);
    }
}
