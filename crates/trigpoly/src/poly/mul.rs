//! Multiplication: exponent bounds are checked once up front, so the inner loops add packed
//! words without per-term overflow tests. The method goes by shape: a single term translates
//! the other factor; a few term pairs are gathered into one table and combined (`gather/`,
//! which also squares); a short factor shifts and merges copies of the long one; a product
//! whose exponent box is not much larger than the work goes dense (`dense.rs`); anything
//! sparser goes through a heap (Johnson's method with Monagan and Pearce's lazy rows), which
//! produces the terms in order, one machine-integer accumulator at a time, with a working set
//! of one heap entry per term of the shorter factor.

use super::coeffs::Coeffs;
use super::dense::try_mul_dense;
use super::gather;
use super::hashed;
use super::kronecker::{shared_steps, Kronecker};
use super::{check_exponent, Poly};
use crate::error::AlgebraError;
use crate::number::{Coefficient, IntegerRing};
use crate::varset::{Layout, Var};

/// A packed monomial of a fixed number of words, padded with zero words.
pub(crate) trait Key: Copy + Eq + Ord + AsRef<[u64]> + AsMut<[u64]> {
    /// The key of all zero words.
    const ZERO: Self;
    /// The words of a key.
    const WORDS: usize;
    fn load(s: &[u64]) -> Self;
    fn store(&self, out: &mut Vec<u64>, words: usize);
    fn mul(&self, other: &Self, bias: &Self) -> Self;
    /// The monomial divided by the one whose packed fields are `by` (no bias: `by` holds the
    /// exponents themselves, word by word).
    fn lowered(&self, by: &[u64]) -> Self;
    /// The monomial multiplied by the one whose packed fields are `by`, less the bias (a
    /// translation, as [`crate::varset::Layout::translation`] gives).
    fn translated(&self, by: &[u64]) -> Self;
    /// A hash of the monomial whose top bits are well mixed (a multiplicative hash).
    fn hash(&self) -> u64;
}

impl<const N: usize> Key for [u64; N] {
    const ZERO: Self = [0; N];
    const WORDS: usize = N;
    #[inline]
    fn load(s: &[u64]) -> Self {
        let mut k = [0u64; N];
        k[..s.len()].copy_from_slice(s);
        k
    }
    #[inline]
    fn store(&self, out: &mut Vec<u64>, words: usize) {
        out.extend_from_slice(&self[..words]);
    }
    #[inline]
    fn mul(&self, other: &Self, bias: &Self) -> Self {
        let mut r = [0u64; N];
        for w in 0..N {
            r[w] = self[w].wrapping_add(other[w]).wrapping_sub(bias[w]);
        }
        r
    }
    #[inline]
    fn translated(&self, by: &[u64]) -> Self {
        let mut r = *self;
        for (word, by) in r.iter_mut().zip(by) {
            *word = word.wrapping_add(*by);
        }
        r
    }
    #[inline]
    fn hash(&self) -> u64 {
        // Fibonacci hashing, word by word.
        self.iter()
            .fold(0u64, |h, &w| (h ^ w).wrapping_mul(0x9E37_79B9_7F4A_7C15))
    }
    #[inline]
    fn lowered(&self, by: &[u64]) -> Self {
        let mut r = *self;
        for (word, by) in r.iter_mut().zip(by) {
            *word = word.wrapping_sub(*by);
        }
        r
    }
}

/// The widest monomial, in words, that [`dispatch_words!`] has a key for.
pub(crate) const MAX_KEY_WORDS: usize = 32;

/// Calls `$f::<[u64; N], _>(args)` with the smallest supported `N >= words` (at most
/// [`MAX_KEY_WORDS`]; wider monomials must not get here).
macro_rules! dispatch_words {
    ($words:expr, $f:ident, $($arg:expr),*) => {
        match $words {
            1 => $f::<[u64; 1], _>($($arg),*),
            2 => $f::<[u64; 2], _>($($arg),*),
            3 => $f::<[u64; 3], _>($($arg),*),
            4 => $f::<[u64; 4], _>($($arg),*),
            5..=6 => $f::<[u64; 6], _>($($arg),*),
            7..=8 => $f::<[u64; 8], _>($($arg),*),
            9..=12 => $f::<[u64; 12], _>($($arg),*),
            13..=16 => $f::<[u64; 16], _>($($arg),*),
            _ => $f::<[u64; MAX_KEY_WORDS], _>($($arg),*),
        }
    };
}

/// Inputs with at most this many terms on one side are multiplied by shifting and merging.
pub(crate) const SMALL_SIDE: usize = 6;

impl<C: Coefficient> Poly<C> {
    /// `self · other`, or an error if the variable sets differ, an exponent would pass the
    /// limit, or the product would have more terms than the limit.
    pub fn checked_mul(&self, other: &Self) -> Result<Self, AlgebraError> {
        self.same_vars(other)?;
        if self.is_zero() || other.is_zero() {
            return Ok(Self::zero(&self.vars));
        }
        Self::check_coefficient_bits(self, other)?;
        let content = &self.content * &other.content;
        let (small, big) = if self.len() <= other.len() {
            (self, other)
        } else {
            (other, self)
        };
        // A single term translates every exponent, which keeps the order; a coefficient 1 (a
        // monomial such as ω²) keeps the coefficients too, and with them the normal form.
        if small.len() == 1 {
            small.check_product_exponents(big)?;
            let c = &small.coeffs[0];
            let (exps, coeffs) = big.shifted(&small.exps, c);
            return Ok(if c.is_one() {
                Self::assemble(&self.vars, content, exps, coeffs)
            } else {
                Self::product(&self.vars, content, exps, Coeffs::new(coeffs))
            });
        }
        if gather::fits(self.words(), small.len().saturating_mul(big.len())) {
            small.check_product_exponents(big)?;
            let terms = gather::product(
                self.layout(),
                (&small.exps, &small.coeffs),
                (&big.exps, &big.coeffs),
                small.real_coefficients() && big.real_coefficients(),
            );
            Self::check_terms(&self.vars, terms.coeffs.len())?;
            return Ok(Self::from_gathered(&self.vars, content, terms));
        }
        if small.len() > SMALL_SIDE {
            Self::check_work(small, big)?;
        }
        // Monomials wider than the heap's keys also shift and merge, whatever the lengths.
        if small.len() <= SMALL_SIDE || self.words() > MAX_KEY_WORDS {
            small.check_product_exponents(big)?;
            let product = shift_and_merge(small, big, content);
            Self::check_terms(&self.vars, product.len())?;
            return Ok(product);
        }
        let (bs, bb) = (small.bounds(), big.bounds());
        check_sum_bounds(&self.vars, &bs, &bb)?;
        let limit = self.vars.limits().max_terms;
        let layout = self.layout();
        let steps = shared_steps(&small.exponent_steps(&bs), &big.exponent_steps(&bb));
        let (exps, coeffs) = match Kronecker::new(&bs, &bb, &steps) {
            Some(kron) => match try_mul_dense(
                &kron,
                layout,
                (&small.exps, &small.coeffs, &bs),
                (&big.exps, &big.coeffs, &bb),
                limit,
                std::ptr::eq(small, big),
            ) {
                Some(result) => result?,
                None => {
                    let ka = kron.indices(layout, &small.exps, &bs);
                    // A square's factors are one list (the hashed product takes each pair once).
                    let kb =
                        (!std::ptr::eq(small, big)).then(|| kron.indices(layout, &big.exps, &bb));
                    let kb = kb.as_deref().unwrap_or(&ka);
                    let (a, b) = ((&ka[..], &small.coeffs[..]), (kb, &big.coeffs[..]));
                    let hashed = hashed::plan(a.0, b.0)
                        .and_then(|lows| hashed::hashed_product(a, b, &lows, limit));
                    let (pairs, coeffs) = match hashed {
                        Some(product) => product?,
                        None => heap_product(a, b, |x, y| x + y, limit)?,
                    };
                    let exps = pair_monomials(layout, &small.exps, &big.exps, &pairs);
                    (exps, Coeffs::new(coeffs))
                }
            },
            None => dispatch_words!(
                self.words(),
                mul_heap_packed,
                self.layout().one(),
                self.words(),
                (&small.exps, &small.coeffs),
                (&big.exps, &big.coeffs),
                limit
            )
            .map(|(exps, coeffs)| (exps, Coeffs::new(coeffs)))?,
        };
        Self::check_terms(&self.vars, coeffs.len())?;
        Ok(Self::product(&self.vars, content, exps, coeffs))
    }

    /// `self²`: a short polynomial gathers each pair of terms once (the multinomial walk's
    /// tables cost more than they save at `e = 2`); anything longer is the product by itself.
    pub(crate) fn checked_square(&self) -> Result<Self, AlgebraError> {
        if !gather::fits(self.words(), self.len().saturating_mul(self.len())) {
            return self.checked_mul(self);
        }
        Self::check_coefficient_bits(self, self)?;
        self.check_product_exponents(self)?;
        let terms = gather::square(
            self.layout(),
            (&self.exps, &self.coeffs),
            self.real_coefficients(),
        );
        Self::check_terms(&self.vars, terms.coeffs.len())?;
        Ok(Self::from_gathered(
            &self.vars,
            &self.content * &self.content,
            terms,
        ))
    }

    /// Whether [`Poly::checked_square`] refuses `self²` by the work limit before it forms a
    /// term product: a square too long to gather, past [`SMALL_SIDE`] terms, whose
    /// `n(n + 1)/2` term products pass the limit ([`Poly::check_work`], as `checked_mul`
    /// asks it).
    pub(crate) fn square_passes_the_work_limit(&self) -> bool {
        let n = self.len();
        !gather::fits(self.words(), n.saturating_mul(n))
            && n > SMALL_SIDE
            && Self::check_work(self, self).is_err()
    }

    /// The canonical form of a product of two canonical polynomials.
    fn product(
        vars: &crate::varset::Vars,
        content: crate::number::Rational,
        exps: Vec<u64>,
        coeffs: Coeffs<C::Int>,
    ) -> Self {
        if C::Int::GAUSS_LEMMA {
            Self::from_sorted_primitive(vars, content, exps, coeffs)
        } else {
            Self::from_sorted(vars, content, exps, coeffs.into_vec())
        }
    }

    /// `self · c·m` for one term given by its packed monomial `m` and integer coefficient `c`:
    /// a translation of every exponent, which keeps the order (and the coefficients, when `c`
    /// is 1).
    pub(crate) fn shifted(&self, m: &[u64], c: &C::Int) -> (Vec<u64>, Vec<C::Int>) {
        let by = self.layout().translation(m);
        let mut exps = Vec::with_capacity(self.exps.len());
        for a in self.exps.chunks_exact(self.words()) {
            Layout::push_translated(&mut exps, a, &by);
        }
        let coeffs = if c.is_one() {
            self.coeffs.to_vec()
        } else {
            self.coeffs.iter().map(|x| x.mul(c)).collect()
        };
        (exps, coeffs)
    }

    /// `self · v^e` (a translation; exponents are checked).
    pub fn mul_var_power(&self, v: Var, e: i64) -> Result<Self, AlgebraError> {
        let m = Self::monomial(&self.vars, C::one(), &[(v, e)])?;
        self.checked_mul(&m)
    }
}

/// Checks that exponents `a + b` stay within the limit, given per-variable bounds.
pub(crate) fn check_sum_bounds(
    vars: &crate::varset::VarSet,
    a: &[(i64, i64)],
    b: &[(i64, i64)],
) -> Result<(), AlgebraError> {
    for v in vars.vars() {
        let j = v.index();
        check_exponent(vars, v, a[j].0 + b[j].0)?;
        check_exponent(vars, v, a[j].1 + b[j].1)?;
    }
    Ok(())
}

/// `small · big` as a sum of shifted copies of `big`, merged pairwise.
fn shift_and_merge<C: Coefficient>(
    small: &Poly<C>,
    big: &Poly<C>,
    content: crate::number::Rational,
) -> Poly<C> {
    let parts: Vec<Poly<C>> = (0..small.len())
        .map(|k| {
            let (exps, coeffs) = big.shifted(small.exp(k), &small.coeffs[k]);
            Poly::raw(&big.vars, exps, coeffs)
        })
        .collect();
    let (exps, coeffs) = merge_tree(parts).into_terms();
    Poly::product(&big.vars, content, exps, Coeffs::new(coeffs))
}

/// Merges sorted raw term lists (content ignored) pairwise, like the levels of a tree, so each
/// term is touched `log₂ k` times; zeros from cancellation are dropped.
pub(crate) fn merge_tree<C: Coefficient>(mut parts: Vec<Poly<C>>) -> Poly<C> {
    while parts.len() > 1 {
        let mut next = Vec::with_capacity(parts.len().div_ceil(2));
        let mut it = parts.into_iter();
        while let Some(a) = it.next() {
            match it.next() {
                Some(b) => next.push(merge_owned(a, b)),
                None => next.push(a),
            }
        }
        parts = next;
    }
    parts.pop().expect("at least one part")
}

/// `a + b` for sorted raw term lists (content ignored), moving the coefficients rather than
/// copying them; sums that cancel are dropped.
fn merge_owned<C: Coefficient>(a: Poly<C>, b: Poly<C>) -> Poly<C> {
    let w = a.words();
    let vars = a.vars.clone();
    let (n, m) = (a.len(), b.len());
    let mut exps = Vec::with_capacity((n + m) * w);
    let mut coeffs = Vec::with_capacity(n + m);
    let (ea, ca) = a.into_terms();
    let (eb, cb) = b.into_terms();
    let (mut ca, mut cb) = (ca.into_iter(), cb.into_iter());
    let (mut i, mut j) = (0, 0);
    while i < n && j < m {
        let (x, y) = (&ea[i * w..(i + 1) * w], &eb[j * w..(j + 1) * w]);
        match x.cmp(y) {
            std::cmp::Ordering::Greater => {
                exps.extend_from_slice(x);
                coeffs.push(ca.next().expect("n terms"));
                i += 1;
            }
            std::cmp::Ordering::Less => {
                exps.extend_from_slice(y);
                coeffs.push(cb.next().expect("m terms"));
                j += 1;
            }
            std::cmp::Ordering::Equal => {
                let c = ca
                    .next()
                    .expect("n terms")
                    .add(&cb.next().expect("m terms"));
                if !c.is_zero() {
                    exps.extend_from_slice(x);
                    coeffs.push(c);
                }
                i += 1;
                j += 1;
            }
        }
    }
    exps.extend_from_slice(&ea[i * w..]);
    coeffs.extend(ca);
    exps.extend_from_slice(&eb[j * w..]);
    coeffs.extend(cb);
    Poly::raw(&vars, exps, coeffs)
}

/// The heap product on packed monomials, for a box too large for Kronecker indices.
fn mul_heap_packed<K: Key, I: IntegerRing>(
    bias: &[u64],
    w: usize,
    a: (&[u64], &[I]),
    b: (&[u64], &[I]),
    max_terms: usize,
) -> Result<(Vec<u64>, Vec<I>), AlgebraError> {
    let bias = K::load(bias);
    let ak: Vec<K> = a.0.chunks_exact(w).map(K::load).collect();
    let bk: Vec<K> = b.0.chunks_exact(w).map(K::load).collect();
    let (pairs, coeffs) = heap_product((&ak, a.1), (&bk, b.1), |x, y| x.mul(y, &bias), max_terms)?;
    let mut exps = Vec::with_capacity(pairs.len() * w);
    for &(i, j) in &pairs {
        ak[i as usize]
            .mul(&bk[j as usize], &bias)
            .store(&mut exps, w);
    }
    Ok((exps, coeffs))
}

/// One row of the heap product: the next unmerged product `a_i·b_j` and its monomial.
#[derive(Clone, Copy)]
struct Entry<K> {
    key: K,
    i: u32,
    j: u32,
}

/// A binary max-heap on `Entry::key` alone, whose top is replaced in place (the next product
/// of the same row) and sifted down.
struct RowHeap<K> {
    v: Vec<Entry<K>>,
}

impl<K: Copy + Ord> RowHeap<K> {
    fn top(&self) -> Option<&Entry<K>> {
        self.v.first()
    }

    fn push(&mut self, e: Entry<K>) {
        self.v.push(e);
        let mut pos = self.v.len() - 1;
        while pos > 0 {
            let parent = (pos - 1) / 2;
            if e.key <= self.v[parent].key {
                break;
            }
            self.v[pos] = self.v[parent];
            pos = parent;
        }
        self.v[pos] = e;
    }

    fn replace_top(&mut self, e: Entry<K>) {
        let v = &mut self.v[..];
        let end = v.len();
        let mut pos = 0;
        let mut child = 1;
        while child < end {
            if child + 1 < end && v[child].key < v[child + 1].key {
                child += 1;
            }
            if e.key >= v[child].key {
                break;
            }
            v[pos] = v[child];
            pos = child;
            child = 2 * pos + 1;
        }
        v[pos] = e;
    }

    fn pop_top(&mut self) {
        let last = self.v.pop().expect("a nonempty heap");
        if !self.v.is_empty() {
            self.replace_top(last);
        }
    }
}

/// The terms of a heap product: for each, a pair `(i, j)` of factor terms whose product is its
/// monomial, and its coefficient.
pub(super) type PairProduct<I> = (Vec<(u32, u32)>, Vec<I>);

/// Sparse product by a heap over the rows of the shorter factor `a` (keys sorted descending,
/// `mul` the monomial product): row `i` holds the next unmerged product `a_i·b_j`; the largest
/// is taken, equal monomials are summed in one accumulator, and row `i + 1` enters only when
/// `a_i·b_0` leaves (it is smaller than every product still to come from the rows before), so
/// the heap never holds more than `len(a)` entries and the terms come out sorted. Returns, for
/// each term, one pair `(i, j)` whose product is its monomial, and the coefficient.
fn heap_product<K: Copy + Ord, I: IntegerRing>(
    a: (&[K], &[I]),
    b: (&[K], &[I]),
    mul: impl Fn(&K, &K) -> K,
    max_terms: usize,
) -> Result<PairProduct<I>, AlgebraError> {
    let (ak, bk) = (a.0, b.0);
    let (n, m) = (ak.len(), bk.len());
    let entry = |i: usize, j: usize| Entry {
        key: mul(&ak[i], &bk[j]),
        i: i as u32,
        j: j as u32,
    };
    let mut heap = RowHeap {
        v: Vec::with_capacity(n),
    };
    heap.push(entry(0, 0));
    let mut pairs = Vec::new();
    let mut coeffs = Vec::new();
    while let Some(&Entry { key, .. }) = heap.top() {
        let mut acc = I::Acc::default();
        let mut last = (0, 0);
        while let Some(&Entry { key: k, i, j }) = heap.top() {
            if k != key {
                break;
            }
            last = (i, j);
            let (i, j) = (i as usize, j as usize);
            I::acc_add_mul(&mut acc, &a.1[i], &b.1[j]);
            if j + 1 < m {
                heap.replace_top(entry(i, j + 1));
            } else {
                heap.pop_top();
            }
            if j == 0 && i + 1 < n {
                // a_{i+1}·b_0 < a_i·b_0 = key: it cannot join this monomial's sum.
                heap.push(entry(i + 1, 0));
            }
        }
        let c = I::acc_finish(acc);
        if !c.is_zero() {
            pairs.push(last);
            coeffs.push(c);
            if coeffs.len() > max_terms {
                return Err(AlgebraError::TooManyTerms { limit: max_terms });
            }
        }
    }
    Ok((pairs, coeffs))
}

/// The packed monomials `a_i·b_j` of the given pairs.
fn pair_monomials(layout: &Layout, a: &[u64], b: &[u64], pairs: &[(u32, u32)]) -> Vec<u64> {
    let w = layout.words;
    let mut exps = vec![0u64; pairs.len() * w];
    for (out, &(i, j)) in exps.chunks_exact_mut(w).zip(pairs) {
        let (i, j) = (i as usize, j as usize);
        layout.mul_into(&a[i * w..(i + 1) * w], &b[j * w..(j + 1) * w], out);
    }
    exps
}
