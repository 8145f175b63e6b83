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

    /// A decoder from indices of this box to packed monomials.
    pub(crate) fn decoder(&self, layout: &Layout) -> Decoder {
        let mut corner = vec![0u64; layout.words];
        layout.pack(&self.lo, &mut corner);
        let small = self.size <= 1 << 32;
        let digits = (0..self.ranges.len())
            .rev()
            .filter(|&j| self.ranges[j] > 1)
            .map(|j| {
                let (word, shift) = layout.field(j);
                let radix = self.ranges[j];
                Digit {
                    radix,
                    magic: if small { u64::MAX / radix + 1 } else { 0 },
                    word,
                    shift,
                }
            })
            .collect();
        Decoder { corner, digits }
    }
}

/// One variable's digit of a Kronecker index, least significant first in [`Decoder`].
struct Digit {
    radix: u64,
    /// `⌈2⁶⁴ / radix⌉` when every index fits 32 bits (Lemire's exact division by
    /// multiplication), else 0 (hardware division).
    magic: u64,
    word: usize,
    shift: u32,
}

/// Turns Kronecker indices into packed monomials: the packing is linear in the exponents, so a
/// monomial is the box's packed lower corner plus each digit shifted into its field.
pub(crate) struct Decoder {
    corner: Vec<u64>,
    digits: Vec<Digit>,
}

impl Decoder {
    /// Words per packed monomial.
    pub(crate) fn words(&self) -> usize {
        self.corner.len()
    }

    /// Writes the packed monomial of index `idx` into `out` (`layout.words` words).
    #[inline]
    pub(crate) fn decode_into(&self, mut idx: u64, out: &mut [u64]) {
        out.copy_from_slice(&self.corner);
        for d in &self.digits {
            let q = if d.magic != 0 {
                ((d.magic as u128 * idx as u128) >> 64) as u64
            } else {
                idx / d.radix
            };
            let r = idx - q * d.radix;
            out[d.word] = out[d.word].wrapping_add(r << d.shift);
            idx = q;
        }
    }
}
