//! Multiplication: exponent bounds are checked once up front, so the inner loops add packed
//! words without per-term overflow tests; products are accumulated without an allocation per
//! term (machine-integer accumulators, one hash slot per distinct monomial), then sorted once.

use std::hash::Hash;

use rustc_hash::FxHashMap;

use super::{check_exponent, Poly};
use crate::error::AlgebraError;
use crate::number::{Coefficient, IntegerRing};
use crate::varset::Var;

/// A packed monomial of a fixed number of words, padded with zero words.
pub(crate) trait Key: Copy + Eq + Hash + Ord {
    fn load(s: &[u64]) -> Self;
    fn store(&self, out: &mut Vec<u64>, words: usize);
    fn mul(&self, other: &Self, bias: &Self) -> Self;
}

impl<const N: usize> Key for [u64; N] {
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
}

/// Calls `$f::<[u64; N], _>(args)` with the smallest supported `N >= words`.
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
            _ => $f::<[u64; 32], _>($($arg),*),
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
        let content = &self.content * &other.content;
        let (small, big) = if self.len() <= other.len() {
            (self, other)
        } else {
            (other, self)
        };
        if small.len() <= SMALL_SIDE {
            check_sum_bounds(&self.vars, &small.bounds(), &big.bounds())?;
            let product = shift_and_merge(small, big, content);
            Self::check_terms(&self.vars, product.len())?;
            return Ok(product);
        }
        let (ba, bb) = (self.bounds(), other.bounds());
        check_sum_bounds(&self.vars, &ba, &bb)?;
        let limit = self.vars.limits().max_terms;
        if let Some(result) = super::dense::try_mul_dense(
            self.layout(),
            self.vars.len(),
            (&self.exps, &self.coeffs, &ba),
            (&other.exps, &other.coeffs, &bb),
            limit,
        ) {
            let (exps, coeffs) = result?;
            return Ok(Self::product(&self.vars, content, exps, coeffs));
        }
        let (exps, coeffs) = dispatch_words!(
            self.words(),
            mul_hash,
            self.layout().one(),
            self.words(),
            (&self.exps, &self.coeffs),
            (&other.exps, &other.coeffs),
            limit
        )?;
        Self::check_terms(&self.vars, coeffs.len())?;
        Ok(Self::product(&self.vars, content, exps, coeffs))
    }

    /// The canonical form of a product of two canonical polynomials.
    fn product(
        vars: &std::sync::Arc<crate::varset::VarSet>,
        content: crate::number::Rational,
        exps: Vec<u64>,
        coeffs: Vec<C::Int>,
    ) -> Self {
        if C::Int::GAUSS_LEMMA {
            Self::from_sorted_primitive(vars, content, exps, coeffs)
        } else {
            Self::from_sorted(vars, content, exps, coeffs)
        }
    }

    /// `self · c·m` for one term given by its packed monomial `m` and integer coefficient `c`:
    /// a translation of every exponent, which keeps the order.
    pub(crate) fn shifted(&self, m: &[u64], c: &C::Int) -> (Vec<u64>, Vec<C::Int>) {
        let w = self.words();
        let layout = self.layout();
        let mut exps = vec![0u64; self.exps.len()];
        for (out, a) in exps.chunks_exact_mut(w).zip(self.exps.chunks_exact(w)) {
            layout.mul_into(a, m, out);
        }
        let coeffs = self.coeffs.iter().map(|x| x.mul(c)).collect();
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
    let p = merge_tree(parts);
    Poly::product(&big.vars, content, p.exps, p.coeffs)
}

/// Merges sorted raw term lists (content ignored) pairwise, like the levels of a tree, so each
/// term is touched `log₂ k` times; zeros from cancellation are dropped.
pub(crate) fn merge_tree<C: Coefficient>(mut parts: Vec<Poly<C>>) -> Poly<C> {
    let one_i = crate::number::Integer::ONE;
    while parts.len() > 1 {
        let mut next = Vec::with_capacity(parts.len().div_ceil(2));
        let mut it = parts.into_iter();
        while let Some(a) = it.next() {
            match it.next() {
                Some(b) => {
                    let (exps, coeffs) = super::arith::merge(&a, &one_i, &b, &one_i);
                    let (exps, coeffs) = drop_zeros(exps, coeffs, a.words());
                    next.push(Poly::raw(&a.vars, exps, coeffs));
                }
                None => next.push(a),
            }
        }
        parts = next;
    }
    parts.pop().expect("at least one part")
}

fn drop_zeros<I: IntegerRing>(exps: Vec<u64>, coeffs: Vec<I>, w: usize) -> (Vec<u64>, Vec<I>) {
    if coeffs.iter().all(|c| !c.is_zero()) {
        return (exps, coeffs);
    }
    let mut e2 = Vec::with_capacity(exps.len());
    let mut c2 = Vec::with_capacity(coeffs.len());
    for (k, c) in coeffs.into_iter().enumerate() {
        if !c.is_zero() {
            e2.extend_from_slice(&exps[k * w..(k + 1) * w]);
            c2.push(c);
        }
    }
    (e2, c2)
}

/// Sparse product by hashing: one accumulator per distinct monomial, sorted once at the end.
fn mul_hash<K: Key, I: IntegerRing>(
    bias: &[u64],
    w: usize,
    a: (&[u64], &[I]),
    b: (&[u64], &[I]),
    max_terms: usize,
) -> Result<(Vec<u64>, Vec<I>), AlgebraError> {
    let bias = K::load(bias);
    let ak: Vec<K> = a.0.chunks_exact(w).map(K::load).collect();
    let bk: Vec<K> = b.0.chunks_exact(w).map(K::load).collect();
    let estimate = (ak.len() * bk.len()).min(1 << 20);
    let mut index: FxHashMap<K, u32> = FxHashMap::default();
    index.reserve(estimate / 4);
    let mut keys: Vec<K> = Vec::new();
    let mut accs: Vec<I::Acc> = Vec::new();
    for (ka, ca) in ak.iter().zip(a.1) {
        for (kb, cb) in bk.iter().zip(b.1) {
            let k = ka.mul(kb, &bias);
            let slot = *index.entry(k).or_insert_with(|| {
                keys.push(k);
                accs.push(I::Acc::default());
                (keys.len() - 1) as u32
            });
            I::acc_add_mul(&mut accs[slot as usize], ca, cb);
        }
        if keys.len() > max_terms {
            return Err(AlgebraError::TooManyTerms { limit: max_terms });
        }
    }
    drop(index);
    let mut order: Vec<u32> = (0..keys.len() as u32).collect();
    order.sort_unstable_by(|&x, &y| keys[y as usize].cmp(&keys[x as usize]));
    let mut exps = Vec::with_capacity(keys.len() * w);
    let mut coeffs = Vec::with_capacity(keys.len());
    for k in order {
        let c = I::acc_finish(std::mem::take(&mut accs[k as usize]));
        if !c.is_zero() {
            keys[k as usize].store(&mut exps, w);
            coeffs.push(c);
        }
    }
    Ok((exps, coeffs))
}
