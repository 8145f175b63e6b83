//! Kronecker substitution: each monomial of a product's exponent box as one integer.
//!
//! The index of `x^e` is `Σ (e_j − lo_j)·stride_j` with the first variable most significant, so
//! index order is the term order and `idx(a·b) = idx(a) + idx(b)` when each factor is indexed
//! from its own lower corner. The dense and the heap products work on these indices: one word
//! to add and compare instead of the packed exponent words.

use crate::varset::Layout;

/// The exponent box of a product `a·b`, given the per-variable bounds of `a` and `b`.
pub(crate) struct Kronecker {
    /// Lower corner of the product's box.
    lo: Vec<i64>,
    /// Extent of the box in each variable.
    ranges: Vec<u64>,
    /// `stride_j = Π_{k > j} ranges_k`.
    strides: Vec<u64>,
    /// Number of cells of the box.
    size: u64,
}

impl Kronecker {
    /// The box of `a·b`, or `None` if its size does not fit comfortably in a `u64`.
    pub(crate) fn new(a: &[(i64, i64)], b: &[(i64, i64)]) -> Option<Kronecker> {
        let ranges: Vec<u64> = a
            .iter()
            .zip(b)
            .map(|(ea, eb)| (ea.1 + eb.1 - ea.0 - eb.0 + 1) as u64)
            .collect();
        let size = ranges.iter().try_fold(1u64, |acc, &r| acc.checked_mul(r))?;
        if size > 1 << 62 {
            return None;
        }
        let mut strides = vec![1u64; ranges.len()];
        for j in (0..ranges.len().saturating_sub(1)).rev() {
            strides[j] = strides[j + 1] * ranges[j + 1];
        }
        let lo = a.iter().zip(b).map(|(ea, eb)| ea.0 + eb.0).collect();
        Some(Kronecker {
            lo,
            ranges,
            strides,
            size,
        })
    }

    /// Number of cells of the box.
    pub(crate) fn size(&self) -> u64 {
        self.size
    }

    /// The indices of a factor's packed monomials (in their order), counted from the factor's
    /// own lower corner `own`.
    pub(crate) fn indices(&self, layout: &Layout, exps: &[u64], own: &[(i64, i64)]) -> Vec<u64> {
        let n = self.ranges.len();
        let mut e = vec![0i64; n];
        exps.chunks_exact(layout.words)
            .map(|mono| {
                layout.unpack_into(mono, &mut e);
                (0..n)
                    .map(|j| (e[j] - own[j].0) as u64 * self.strides[j])
                    .sum()
            })
            .collect()
    }

    /// The packed monomials of product indices, in the order given.
    pub(crate) fn decode(&self, layout: &Layout, indices: &[u64]) -> Vec<u64> {
        let w = layout.words;
        let mut exps = vec![0u64; indices.len() * w];
        let mut e = vec![0i64; self.ranges.len()];
        for (slot, &idx) in exps.chunks_exact_mut(w).zip(indices) {
            for (j, ej) in e.iter_mut().enumerate() {
                *ej = ((idx / self.strides[j]) % self.ranges[j]) as i64 + self.lo[j];
            }
            layout.pack(&e, slot);
        }
        exps
    }
}
