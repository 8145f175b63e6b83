//! Dense multiplication on Kronecker indices (`kronecker.rs`), chunked over the output index
//! range. The inputs are sorted, so for each term of `a` the partners in `b` that land in an
//! output chunk form a contiguous run; a chunk of machine-word accumulators stays in cache, and
//! is scanned once, in order, for the nonzero results. Used when the box is not much larger than
//! the work and every coefficient product fits the accumulators.

use super::kronecker::Kronecker;
use crate::error::AlgebraError;
use crate::number::IntegerRing;
use crate::varset::Layout;

/// Accumulators per chunk.
const CHUNK: u64 = 1 << 15;
/// The largest box scanned, relative to the number of products.
const BOX_PER_PRODUCT: u64 = 32;

/// Packed exponents and coefficients of a product, sorted descending.
pub(crate) type Product<I> = (Vec<u64>, Vec<I>);

/// The product by the dense method, or `None` when the method does not apply (box too large
/// for the work, or coefficients too large for the accumulators).
pub(crate) fn try_mul_dense<I: IntegerRing>(
    kron: &Kronecker,
    layout: &Layout,
    a: (&[u64], &[I], &[(i64, i64)]),
    b: (&[u64], &[I], &[(i64, i64)]),
    max_terms: usize,
) -> Option<Result<Product<I>, AlgebraError>> {
    let (n, m) = (a.1.len(), b.1.len());
    let work = (n as u64).saturating_mul(m as u64);
    if kron.size() > work.saturating_mul(BOX_PER_PRODUCT) || kron.size() > 1 << 40 {
        return None;
    }
    // Coefficients must fit machine words, and sums of products the accumulators.
    let small_a: Vec<I::Small> = a.1.iter().map(|c| c.to_small()).collect::<Option<_>>()?;
    let small_b: Vec<I::Small> = b.1.iter().map(|c| c.to_small()).collect::<Option<_>>()?;
    let bits = |v: &[I::Small]| v.iter().map(I::small_bits).max().unwrap_or(0);
    let terms_bits = 64 - (n.min(m) as u64).leading_zeros();
    if bits(&small_a) + bits(&small_b) + terms_bits + I::PRODUCTS_PER_COMPONENT > 126 {
        return None;
    }
    // Kronecker indices, ascending (the inputs are sorted descending).
    let ascending = |mut v: Vec<u64>| {
        v.reverse();
        v
    };
    let fa = ascending(kron.indices(layout, a.0, a.2));
    let gb = ascending(kron.indices(layout, b.0, b.2));
    let ca: Vec<I::Small> = small_a.into_iter().rev().collect();
    let cb: Vec<I::Small> = small_b.into_iter().rev().collect();
    let zero = I::Wide::default();
    let mut acc = vec![zero; CHUNK as usize];
    let mut start = vec![0usize; n];
    let mut first = 0usize;
    let (g_min, g_max) = (gb[0], gb[m - 1]);
    let mut out_idx: Vec<u64> = Vec::new();
    let mut out_c: Vec<I> = Vec::new();
    let mut lo = fa[0] + g_min;
    let end = fa[n - 1] + g_max + 1;
    while lo < end {
        let hi = (lo + CHUNK).min(end);
        while first < n && fa[first] + g_max < lo {
            first += 1;
        }
        for i in first..n {
            let fi = fa[i];
            if fi + g_min >= hi {
                break;
            }
            let mut j = start[i];
            while j < m && fi + gb[j] < lo {
                j += 1;
            }
            let ai = &ca[i];
            while j < m {
                let k = fi + gb[j];
                if k >= hi {
                    break;
                }
                I::wide_add_mul(&mut acc[(k - lo) as usize], ai, &cb[j]);
                j += 1;
            }
            start[i] = j;
        }
        for (k, slot) in acc[..(hi - lo) as usize].iter_mut().enumerate() {
            if *slot != zero {
                out_idx.push(lo + k as u64);
                out_c.push(I::from_wide(*slot));
                *slot = zero;
            }
        }
        if out_c.len() > max_terms {
            return Some(Err(AlgebraError::TooManyTerms { limit: max_terms }));
        }
        lo = hi;
    }
    out_idx.reverse();
    out_c.reverse();
    Some(Ok((kron.decode(layout, &out_idx), out_c)))
}
