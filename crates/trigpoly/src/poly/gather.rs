//! Products of short polynomials by gathering: every term product goes into one buffer, which is
//! sorted once and whose equal monomials are combined. For inputs of a handful of terms each
//! (the generators of an algebra, their squares and brackets) this costs less than shifting and
//! merging, which allocates a polynomial per term and merges them pairwise.

use super::mul::Key;
use crate::number::IntegerRing;
use crate::varset::Layout;

/// Monomials of at most this many words take this path.
pub(crate) const WORDS: usize = 4;

/// Products of at most this many term pairs take this path.
pub(crate) const MAX_PAIRS: usize = 256;

/// Whether a product of `pairs` term pairs of monomials of `words` words takes this path.
pub(crate) fn fits(words: usize, pairs: usize) -> bool {
    words <= WORDS && pairs <= MAX_PAIRS
}

/// A packed monomial padded to [`WORDS`] words.
pub(crate) type Monomial = [u64; WORDS];

/// Term products, unsorted, with their monomials.
pub(crate) struct Gather<I> {
    items: Vec<(Monomial, I)>,
}

impl<I: IntegerRing> Gather<I> {
    /// An empty buffer with room for `n` products.
    pub(crate) fn with_capacity(n: usize) -> Self {
        Gather {
            items: Vec::with_capacity(n),
        }
    }

    /// Adds the term `c·m`.
    #[inline]
    pub(crate) fn push(&mut self, m: Monomial, c: I) {
        self.items.push((m, c));
    }

    /// The terms sorted descending, equal monomials summed, zero sums dropped; monomials of
    /// `words` words.
    pub(crate) fn finish(mut self, words: usize) -> (Vec<u64>, Vec<I>) {
        self.items
            .sort_unstable_by_key(|&(m, _)| std::cmp::Reverse(m));
        let mut exps = Vec::with_capacity(self.items.len() * words);
        let mut coeffs = Vec::with_capacity(self.items.len());
        let mut items = self.items.into_iter().peekable();
        while let Some((m, mut c)) = items.next() {
            while let Some((_, d)) = items.next_if(|(n, _)| *n == m) {
                c = c.add(&d);
            }
            if !c.is_zero() {
                m.store(&mut exps, words);
                coeffs.push(c);
            }
        }
        (exps, coeffs)
    }
}

/// The product of two term lists, sorted, combined, zeros dropped. The caller has checked
/// that every exponent of the product stays within its field.
pub(crate) fn product<I: IntegerRing>(
    layout: &Layout,
    a: (&[u64], &[I]),
    b: (&[u64], &[I]),
) -> (Vec<u64>, Vec<I>) {
    let w = layout.words;
    debug_assert!(w <= WORDS);
    let bias = Monomial::load(layout.one());
    let mut out = Gather::with_capacity(a.1.len() * b.1.len());
    for (ma, ca) in a.0.chunks_exact(w).zip(a.1) {
        let ma = Monomial::load(ma);
        for (mb, cb) in b.0.chunks_exact(w).zip(b.1) {
            out.push(ma.mul(&Monomial::load(mb), &bias), ca.mul(cb));
        }
    }
    out.finish(w)
}

/// The square of a term list, from the `n(n + 1)/2` products `c_i²·m_i²` and `2c_ic_j·m_im_j`
/// (`i < j`), sorted, combined, zeros dropped. The caller has checked the exponents.
pub(crate) fn square<I: IntegerRing>(layout: &Layout, a: (&[u64], &[I])) -> (Vec<u64>, Vec<I>) {
    let w = layout.words;
    debug_assert!(w <= WORDS);
    let bias = Monomial::load(layout.one());
    let n = a.1.len();
    let mut out = Gather::with_capacity(n * (n + 1) / 2);
    for (i, (mi, ci)) in a.0.chunks_exact(w).zip(a.1).enumerate() {
        let mi = Monomial::load(mi);
        out.push(mi.mul(&mi, &bias), ci.mul(ci));
        for (mj, cj) in a.0[(i + 1) * w..].chunks_exact(w).zip(&a.1[i + 1..]) {
            let p = ci.mul(cj);
            out.push(mi.mul(&Monomial::load(mj), &bias), p.add(&p));
        }
    }
    out.finish(w)
}
