//! Dense multiplication on Kronecker indices (`kronecker.rs`), chunked over the output index
//! range. The inputs are sorted, so for each term of `a` the partners in `b` that land in an
//! output chunk form a contiguous run. A chunk of machine-word accumulators stays in cache and
//! is read back highest first, so the terms come out in order; on a sparse box a bitmap records
//! the touched accumulators and only those are read. Used when the box is not much larger than
//! the work and every coefficient product fits the accumulators. Large products split the index
//! range into parts that rayon runs on the threads of the caller's pool.

use rayon::prelude::*;

use super::kronecker::{Decoder, Kronecker};
use crate::error::AlgebraError;
use crate::number::IntegerRing;
use crate::varset::Layout;

/// Bytes of accumulators per chunk: half the L2 cache of a typical core.
const CHUNK_BYTES: usize = 1 << 18;
/// On sparse boxes a chunk is wide enough to receive this many cache's worth of products (they
/// collide and spread out, so far fewer accumulators are touched).
const SPARSE_PRODUCTS_PER_CACHE: u64 = 1;
/// The widest chunk, in cache's worth of accumulators.
const MAX_CHUNK_CACHES: u64 = 64;
/// The largest box scanned, relative to the number of products.
const BOX_PER_PRODUCT: u64 = 32;
/// Products below this many term pairs run as one part.
const PARALLEL_WORK: u64 = 1 << 18;
/// Parts per thread, so that unequal parts balance.
const PARTS_PER_THREAD: u64 = 4;

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
    let fa = kron.indices(layout, a.0, a.2);
    let gb = kron.indices(layout, b.0, b.2);
    // Index range of the product.
    let (lo, end) = (fa[n - 1] + gb[m - 1], fa[0] + gb[0] + 1);
    // A chunk spans a cache's worth of accumulators or, on sparse boxes, more: every chunk
    // visits each term of `a` whose products reach it, so it must hold enough products.
    let cells = (CHUNK_BYTES / std::mem::size_of::<I::Wide>()) as u64;
    let chunk = (cells * SPARSE_PRODUCTS_PER_CACHE * kron.size() / work)
        .clamp(cells, cells * MAX_CHUNK_CACHES)
        .min(end - lo)
        .next_multiple_of(64);
    let factors = Factors {
        fa,
        gb,
        ca: small_a,
        cb: small_b,
    };
    let decoder = kron.decoder(layout);
    // The index range cut into parts, highest first.
    let threads = rayon::current_num_threads() as u64;
    let count = if work < PARALLEL_WORK || threads < 2 {
        1
    } else {
        (threads * PARTS_PER_THREAD).min(end - lo)
    };
    let cut = |p: u64| lo + ((end - lo) as u128 * p as u128 / count as u128) as u64;
    let ranges: Vec<(u64, u64)> = (0..count).rev().map(|p| (cut(p), cut(p + 1))).collect();
    // Marking costs a little per product, scanning a little per accumulator.
    let mark = kron.size() > work;
    let parts: Vec<Product<I>> = match ranges
        .into_par_iter()
        .map_init(
            || vec![I::Wide::default(); chunk as usize],
            |acc, (lo, hi)| {
                if mark {
                    factors.range::<I, true>(acc, lo, hi, &decoder, max_terms)
                } else {
                    factors.range::<I, false>(acc, lo, hi, &decoder, max_terms)
                }
            },
        )
        .collect()
    {
        Ok(parts) => parts,
        Err(e) => return Some(Err(e)),
    };
    // Each part kept to the term limit; the caller checks the total.
    let total: usize = parts.iter().map(|(_, c)| c.len()).sum();
    if parts.len() == 1 {
        return parts.into_iter().next().map(Ok);
    }
    let mut exps = Vec::with_capacity(total * layout.words);
    let mut coeffs = Vec::with_capacity(total);
    for (e, c) in parts {
        exps.extend_from_slice(&e);
        coeffs.extend(c);
    }
    Some(Ok((exps, coeffs)))
}

/// The two factors as Kronecker indices (descending) and machine-word coefficients.
struct Factors<S> {
    fa: Vec<u64>,
    gb: Vec<u64>,
    ca: Vec<S>,
    cb: Vec<S>,
}

impl<S: Copy + Send + Sync> Factors<S> {
    /// The terms of the product with indices in `[lo, hi)`, descending, as packed monomials.
    /// A chunk is as wide as `acc`. With `MARK`, a bitmap records the touched accumulators and
    /// only those are read back; without, every accumulator of a chunk is read back.
    fn range<I: IntegerRing<Small = S>, const MARK: bool>(
        &self,
        acc: &mut [I::Wide],
        lo: u64,
        hi: u64,
        decoder: &Decoder,
        max_terms: usize,
    ) -> Result<Product<I>, AlgebraError> {
        let (fa, gb, ca, cb) = (&self.fa, &self.gb, &self.ca, &self.cb);
        let (n, m) = (fa.len(), gb.len());
        let (g_max, g_min) = (gb[0], gb[m - 1]);
        let chunk = acc.len() as u64;
        let words = decoder.words();
        let zero = I::Wide::default();
        let mut touched = vec![0u64; if MARK { (chunk / 64) as usize } else { 0 }];
        // `next[i]`: the first partner of term `i` of `a` not yet multiplied (partners are
        // visited in descending index order, as the chunks are).
        let mut next: Vec<usize> = fa
            .iter()
            .map(|&fi| gb.partition_point(|&g| fi + g >= hi))
            .collect();
        // Terms of `a` before `first` land above every remaining chunk.
        let mut first = fa.partition_point(|&fi| fi + g_min >= hi);
        // The part has at most one term per product and per index: reserving that much up
        // front costs address space only (pages are backed when written), where growing by
        // doubling would copy and fault in the terms about twice over. If the address space
        // is refused, the vectors grow as usual.
        let products: usize = fa
            .iter()
            .zip(&next)
            .map(|(&fi, &j)| gb.partition_point(|&g| fi + g >= lo) - j)
            .sum();
        let bound = (products as u64).min(hi - lo).min(max_terms as u64 + 1) as usize;
        let (mut exps, mut coeffs) = (Vec::new(), Vec::new());
        if exps.try_reserve_exact(bound * words).is_err()
            || coeffs.try_reserve_exact(bound).is_err()
        {
            (exps, coeffs) = (Vec::new(), Vec::new());
        }
        let mut top = hi;
        while top > lo {
            let bottom = top.saturating_sub(chunk).max(lo);
            while first < n && fa[first] + g_min >= top {
                first += 1;
            }
            for i in first..n {
                let fi = fa[i];
                if fi + g_max < bottom {
                    break;
                }
                let ai = ca[i];
                let j = next[i];
                let mut run = 0;
                for (&g, c) in gb[j..].iter().zip(&cb[j..]) {
                    let k = fi + g;
                    if k < bottom {
                        break;
                    }
                    let off = (k - bottom) as usize;
                    I::wide_add_mul(&mut acc[off], &ai, c);
                    if MARK {
                        touched[off >> 6] |= 1 << (off & 63);
                    }
                    run += 1;
                }
                next[i] = j + run;
            }
            // Read the accumulators back, highest index first.
            let mut emit = |off: usize| {
                let slot = std::mem::take(&mut acc[off]);
                if slot != zero {
                    let at = exps.len();
                    exps.resize(at + words, 0);
                    decoder.decode_into(bottom + off as u64, &mut exps[at..]);
                    coeffs.push(I::from_wide(slot));
                }
            };
            if MARK {
                for (w, word) in touched.iter_mut().enumerate().rev() {
                    let mut bits = std::mem::take(word);
                    while bits != 0 {
                        let bit = 63 - bits.leading_zeros() as usize;
                        bits &= !(1 << bit);
                        emit(w * 64 + bit);
                    }
                }
            } else {
                (0..(top - bottom) as usize).rev().for_each(emit);
            }
            if coeffs.len() > max_terms {
                return Err(AlgebraError::TooManyTerms { limit: max_terms });
            }
            top = bottom;
        }
        Ok((exps, coeffs))
    }
}
