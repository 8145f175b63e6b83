//! Products of short polynomials by gathering: every term product goes into one buffer, which is
//! sorted once and whose equal monomials are combined. For inputs of a handful of terms each
//! (the generators of an algebra, their squares and brackets) this costs less than shifting and
//! merging, which allocates a polynomial per term and merges them pairwise.
//!
//! Three kernels share the buffers: [`product`], [`square`] and [`jacobians`] (the short
//! Poisson bracket). Each runs with monomials of exactly the layout's width (one to
//! [`WORDS`] words, known at compile time), and first in a [`WordGather`], which keeps every
//! term product exactly in the ring's wide form (`i128` per component) when the coefficients
//! fit machine words, as they do for such inputs; [`Gather`] keeps ring elements, for
//! coefficients of any size.

use super::mul::Key;
use crate::number::IntegerRing;
use crate::varset::{Layout, Var, VarKind, VarSet};

/// Monomials of at most this many words take this path.
pub(crate) const WORDS: usize = 4;

/// Products of at most this many term pairs take this path.
pub(crate) const MAX_PAIRS: usize = 256;

/// The most pairs of variables [`jacobians`] takes (every pair of a phase space whose
/// monomials fit [`WORDS`] words, with room to spare).
pub(crate) const MAX_JACOBIAN_PAIRS: usize = 16;

/// Whether a product of `pairs` term pairs of monomials of `words` words takes this path.
pub(crate) fn fits(words: usize, pairs: usize) -> bool {
    words <= WORDS && pairs <= MAX_PAIRS
}

/// A packed monomial padded to [`WORDS`] words.
pub(crate) type Monomial = [u64; WORDS];

/// One pair of variables `(q, p)` of a sum of Jacobians, as [`jacobians`] reads it.
#[derive(Clone, Copy, Default)]
pub(crate) struct JacobianPair {
    /// The field of `q` (word, shift).
    pub(crate) q: (usize, u32),
    /// The field of `p`.
    pub(crate) p: (usize, u32),
    /// What both derivatives take off a monomial: one in the field of each variable that is
    /// not an angle.
    pub(crate) lower: Monomial,
    /// Factors `i` the derivatives bring, one per angle.
    pub(crate) turns: u32,
}

impl JacobianPair {
    /// The pair `(q, p)` of `vars`, whose monomials fit [`WORDS`] words.
    #[inline]
    pub(crate) fn new(vars: &VarSet, q: Var, p: Var) -> Self {
        let layout = vars.layout();
        let mut lower: Monomial = [0; WORDS];
        let mut turns = 0;
        for v in [q, p] {
            if vars.variable(v).kind() == VarKind::Angle {
                turns += 1;
            } else {
                let (word, shift) = layout.field(v.index());
                lower[word] = lower[word].wrapping_add(1 << shift);
            }
        }
        JacobianPair {
            q: layout.field(q.index()),
            p: layout.field(p.index()),
            lower,
            turns,
        }
    }
}

/// Calls `$f::<[u64; N], _>(args)` with `N` = `$words` (1 to [`WORDS`]).
macro_rules! by_width {
    ($words:expr, $f:ident, $($arg:expr),*) => {
        match $words {
            1 => $f::<[u64; 1], _>($($arg),*),
            2 => $f::<[u64; 2], _>($($arg),*),
            3 => $f::<[u64; 3], _>($($arg),*),
            _ => $f::<[u64; WORDS], _>($($arg),*),
        }
    };
}

/// The product of two term lists, sorted, combined, zeros dropped. The caller has checked
/// that every exponent of the product stays within its field.
pub(crate) fn product<I: IntegerRing>(
    layout: &Layout,
    a: (&[u64], &[I]),
    b: (&[u64], &[I]),
) -> (Vec<u64>, Vec<I>) {
    debug_assert!(layout.words <= WORDS);
    by_width!(layout.words, product_of_width, layout, a, b)
}

/// The square of a term list, from the `n(n + 1)/2` products `c_i²·m_i²` and `2c_ic_j·m_im_j`
/// (`i < j`), sorted, combined, zeros dropped. The caller has checked the exponents.
pub(crate) fn square<I: IntegerRing>(layout: &Layout, a: (&[u64], &[I])) -> (Vec<u64>, Vec<I>) {
    debug_assert!(layout.words <= WORDS);
    by_width!(layout.words, square_of_width, layout, a)
}

/// `Σ_k ∂(f, g)/∂(q_k, p_k)` over the `pairs`, from the term pairs: both products of
/// derivatives of the terms `c·m` and `d·n` have the monomial `m·n/(q·p)`, with the
/// coefficient `c·d·(a_q·b_p − a_p·b_q)·iᵗ`, where `a`, `b` are the exponents in `m`, `n` and
/// `t` counts the angles of the pair. `None` when a coefficient does not fit a word or an
/// angle needs `i` in a ring without it (the general path handles both). The caller has
/// checked the exponents.
pub(crate) fn jacobians<I: IntegerRing>(
    layout: &Layout,
    f: (&[u64], &[I]),
    g: (&[u64], &[I]),
    pairs: &[JacobianPair],
) -> Option<(Vec<u64>, Vec<I>)> {
    debug_assert!(layout.words <= WORDS);
    by_width!(layout.words, jacobians_of_width, layout, f, g, pairs)
}

fn product_of_width<K: Key, I: IntegerRing>(
    layout: &Layout,
    a: (&[u64], &[I]),
    b: (&[u64], &[I]),
) -> (Vec<u64>, Vec<I>) {
    let bias = K::load(layout.one());
    let n = a.1.len() * b.1.len();
    let mut words = WordGather::<K, I>::with_capacity(n);
    if product_pairs(a, b, &bias, |m, x, y, k| words.push(m, x, y, k, 0)) {
        return words.finish();
    }
    let mut exact = Gather::<K, I>::with_capacity(n);
    product_pairs(a, b, &bias, |m, x, y, k| exact.push(m, x, y, k));
    exact.finish()
}

fn square_of_width<K: Key, I: IntegerRing>(
    layout: &Layout,
    a: (&[u64], &[I]),
) -> (Vec<u64>, Vec<I>) {
    let bias = K::load(layout.one());
    let n = a.1.len() * (a.1.len() + 1) / 2;
    let mut words = WordGather::<K, I>::with_capacity(n);
    if square_pairs(a, &bias, |m, x, y, k| words.push(m, x, y, k, 0)) {
        return words.finish();
    }
    let mut exact = Gather::<K, I>::with_capacity(n);
    square_pairs(a, &bias, |m, x, y, k| exact.push(m, x, y, k));
    exact.finish()
}

fn jacobians_of_width<K: Key, I: IntegerRing>(
    layout: &Layout,
    f: (&[u64], &[I]),
    g: (&[u64], &[I]),
    pairs: &[JacobianPair],
) -> Option<(Vec<u64>, Vec<I>)> {
    let bias = K::load(layout.one());
    let mut out = WordGather::<K, I>::with_capacity(f.1.len() * g.1.len());
    let n = K::WORDS;
    for (mf, cf) in f.0.chunks_exact(n).zip(f.1) {
        let kf = K::load(mf);
        for (mg, cg) in g.0.chunks_exact(n).zip(g.1) {
            let mfg = kf.mul(&K::load(mg), &bias);
            for pair in pairs {
                let factor = layout.read(mf, pair.q) * layout.read(mg, pair.p)
                    - layout.read(mf, pair.p) * layout.read(mg, pair.q);
                if factor == 0 {
                    continue;
                }
                let m = mfg.lowered(&pair.lower[..n]);
                if !out.push(m, cf, cg, factor, pair.turns) {
                    return None;
                }
            }
        }
    }
    Some(out.finish())
}

/// Calls `emit(m_a·m_b, c_a, c_b, 1)` for every pair of terms of `a` and `b`, while it
/// returns `true`; whether every call did.
#[inline(always)]
fn product_pairs<K: Key, I>(
    a: (&[u64], &[I]),
    b: (&[u64], &[I]),
    bias: &K,
    mut emit: impl FnMut(K, &I, &I, i64) -> bool,
) -> bool {
    let n = K::WORDS;
    for (ma, ca) in a.0.chunks_exact(n).zip(a.1) {
        let ma = K::load(ma);
        for (mb, cb) in b.0.chunks_exact(n).zip(b.1) {
            if !emit(ma.mul(&K::load(mb), bias), ca, cb, 1) {
                return false;
            }
        }
    }
    true
}

/// Calls `emit(m_i², c_i, c_i, 1)` and `emit(m_i·m_j, c_i, c_j, 2)` (`i < j`) for the terms of
/// `a`, while it returns `true`; whether every call did.
#[inline(always)]
fn square_pairs<K: Key, I>(
    a: (&[u64], &[I]),
    bias: &K,
    mut emit: impl FnMut(K, &I, &I, i64) -> bool,
) -> bool {
    let n = K::WORDS;
    for (i, (mi, ci)) in a.0.chunks_exact(n).zip(a.1).enumerate() {
        let mi = K::load(mi);
        if !emit(mi.mul(&mi, bias), ci, ci, 1) {
            return false;
        }
        for (mj, cj) in a.0[(i + 1) * n..].chunks_exact(n).zip(&a.1[i + 1..]) {
            if !emit(mi.mul(&K::load(mj), bias), ci, cj, 2) {
                return false;
            }
        }
    }
    true
}

/// The most bits one term product may take in a [`WordGather`]. At most `2^12` products are
/// summed ([`MAX_PAIRS`] term pairs times [`MAX_JACOBIAN_PAIRS`]), and a Gaussian component
/// adds two real products, so every sum stays below `2^(112 + 13) < 2^127`.
const ITEM_BITS: u32 = 112;

/// Term products with word-sized coefficients, unsorted, each kept exactly in the ring's wide
/// form: no allocation, clone or drop per coefficient.
struct WordGather<K, I: IntegerRing> {
    items: Vec<(K, I::Wide)>,
}

impl<K: Key, I: IntegerRing> WordGather<K, I> {
    fn with_capacity(n: usize) -> Self {
        WordGather {
            items: Vec::with_capacity(n),
        }
    }

    /// Adds the term `a·b·k·iᵗ·m` (`k ≠ 0`, `t` = `turns`), or returns `false` and adds nothing
    /// when a component of `a` or `b` does not fit a word, the product could take more than
    /// [`ITEM_BITS`] bits, or `t > 0` in a ring without `i`.
    #[inline]
    fn push(&mut self, m: K, a: &I, b: &I, k: i64, turns: u32) -> bool {
        let (Some(a), Some(b)) = (a.to_small(), b.to_small()) else {
            return false;
        };
        let k_bits = 64 - k.unsigned_abs().leading_zeros();
        if I::small_bits(&a) + I::small_bits(&b) + k_bits > ITEM_BITS {
            return false;
        }
        let mut w = I::Wide::default();
        I::wide_add_mul(&mut w, &a, &b);
        if k != 1 {
            w = I::wide_scale(&w, k);
        }
        for _ in 0..turns {
            match I::wide_mul_i(&w) {
                Some(iw) => w = iw,
                None => return false,
            }
        }
        self.items.push((m, w));
        true
    }

    /// The terms sorted descending, equal monomials summed, zero sums dropped.
    fn finish(mut self) -> (Vec<u64>, Vec<I>) {
        let items = &mut self.items;
        items.sort_unstable_by_key(|&(m, _)| std::cmp::Reverse(m));
        let mut exps = Vec::with_capacity(items.len() * K::WORDS);
        let mut coeffs = Vec::with_capacity(items.len());
        let zero = I::Wide::default();
        let mut k = 0;
        while k < items.len() {
            let (m, mut sum) = items[k];
            k += 1;
            while k < items.len() && items[k].0 == m {
                I::wide_add(&mut sum, &items[k].1);
                k += 1;
            }
            if sum != zero {
                m.store(&mut exps, K::WORDS);
                coeffs.push(I::from_wide(sum));
            }
        }
        (exps, coeffs)
    }
}

/// Term products as ring elements, unsorted, with their monomials.
struct Gather<K, I> {
    items: Vec<(K, I)>,
}

impl<K: Key, I: IntegerRing> Gather<K, I> {
    fn with_capacity(n: usize) -> Self {
        Gather {
            items: Vec::with_capacity(n),
        }
    }

    /// Adds the term `a·b·k·m` (`k` is 1 or 2); always `true`.
    fn push(&mut self, m: K, a: &I, b: &I, k: i64) -> bool {
        debug_assert!(k == 1 || k == 2);
        let p = a.mul(b);
        self.items.push((m, if k == 2 { p.add(&p) } else { p }));
        true
    }

    /// The terms sorted descending, equal monomials summed, zero sums dropped.
    fn finish(mut self) -> (Vec<u64>, Vec<I>) {
        self.items
            .sort_unstable_by_key(|&(m, _)| std::cmp::Reverse(m));
        let mut exps = Vec::with_capacity(self.items.len() * K::WORDS);
        let mut coeffs = Vec::with_capacity(self.items.len());
        let mut items = self.items.into_iter().peekable();
        while let Some((m, mut c)) = items.next() {
            while let Some((_, d)) = items.next_if(|(n, _)| *n == m) {
                c = c.add(&d);
            }
            if !c.is_zero() {
                m.store(&mut exps, K::WORDS);
                coeffs.push(c);
            }
        }
        (exps, coeffs)
    }
}
