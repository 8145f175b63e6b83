//! Kronecker substitution: each monomial of a product's exponent box as one integer.
//!
//! The index of `x^e` is `Σ (e_j − lo_j)/s_j·stride_j` with the first variable most
//! significant, so index order is the term order and `idx(a·b) = idx(a) + idx(b)` when each
//! factor is indexed from its own lower corner. `s_j` is the step both factors' exponents of
//! variable `j` move by (FLINT's deflation): 2 for polynomials in `z²`, whose box then has
//! half the cells. The dense and the heap products work on these indices: one word to add and
//! compare instead of the packed exponent words.

use crate::varset::Layout;

/// The exponent box of a product `a·b`, given the per-variable bounds of `a` and `b`.
pub(crate) struct Kronecker {
    /// Lower corner of the product's box.
    lo: Vec<i64>,
    /// The step of each variable's exponents (at least 1): a digit counts steps.
    steps: Vec<u64>,
    /// Extent of the box in each variable.
    ranges: Vec<u64>,
    /// `stride_j = Π_{k > j} ranges_k`.
    strides: Vec<u64>,
    /// Number of cells of the box.
    size: u64,
}

impl Kronecker {
    /// The box of `a·b`, or `None` if its size does not fit comfortably in a `u64`, where each
    /// variable's exponents in `a` and in `b` lie `steps` apart from their minimum
    /// ([`shared_steps`]).
    pub(crate) fn new(a: &[(i64, i64)], b: &[(i64, i64)], steps: &[u64]) -> Option<Kronecker> {
        let ranges: Vec<u64> = a
            .iter()
            .zip(b)
            .zip(steps)
            .map(|((ea, eb), &s)| (ea.1 + eb.1 - ea.0 - eb.0) as u64 / s + 1)
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
            steps: steps.to_vec(),
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
                    .map(|j| {
                        let (distance, step) = ((e[j] - own[j].0) as u64, self.steps[j]);
                        // A division only where the variable has a step.
                        let digit = if step == 1 { distance } else { distance / step };
                        digit * self.strides[j]
                    })
                    .sum()
            })
            .collect()
    }

    /// A decoder from indices of this box to packed monomials, for a product that reads about
    /// `reads` indices (the table of low digits is kept no larger than that).
    pub(crate) fn decoder(&self, layout: &Layout, reads: u64) -> Decoder {
        let words = layout.words;
        let small = self.size <= 1 << 32;
        // Least significant first; a variable of extent 1 has no digit.
        let mut digits = (0..self.ranges.len())
            .rev()
            .filter(|&j| self.ranges[j] > 1)
            .map(|j| {
                let (word, shift) = layout.field(j);
                Digit {
                    divisor: Divisor::new(self.ranges[j], small),
                    step: self.steps[j],
                    word,
                    shift,
                }
            })
            .peekable();
        // The low digits whose cells fit the table.
        let cells = (TABLE_BYTES / (8 * words) as u64).min(reads.max(1));
        let mut span = 1u64;
        let mut low = Vec::new();
        while let Some(d) = digits.next_if(|d| span * d.divisor.radix <= cells) {
            span *= d.divisor.radix;
            low.push(d);
        }
        let mut corner = vec![0u64; words];
        layout.pack(&self.lo, &mut corner);
        let mut table = Vec::with_capacity(span as usize * words);
        for r in 0..span {
            let at = table.len();
            table.extend_from_slice(&corner);
            add_digits(&low, r, &mut table[at..]);
        }
        Decoder {
            words,
            table,
            split: Divisor::new(span, small),
            high: digits.collect(),
        }
    }
}

/// Per variable, the step a product's box can take (at least 1): the gcd of the factors'
/// [`Poly::exponent_steps`](super::Poly::exponent_steps), over which both factors' exponents
/// lie from their minimum.
pub(crate) fn shared_steps(a: &[u64], b: &[u64]) -> Vec<u64> {
    a.iter()
        .zip(b)
        .map(|(&sa, &sb)| num_integer::Integer::gcd(&sa, &sb).max(1))
        .collect()
}

/// Bytes of the table of low digits in a [`Decoder`]: an L1 cache's worth.
const TABLE_BYTES: u64 = 1 << 15;

/// Division by a constant: by Lemire's multiplication when every dividend fits 32 bits (and
/// the divisor is not 1), else by the hardware.
struct Divisor {
    radix: u64,
    /// `⌈2⁶⁴ / radix⌉` when the multiplication applies, else 0.
    magic: u64,
}

impl Divisor {
    fn new(radix: u64, small: bool) -> Divisor {
        Divisor {
            radix,
            magic: if small && radix > 1 {
                u64::MAX / radix + 1
            } else {
                0
            },
        }
    }

    /// `(idx / radix, idx % radix)`.
    #[inline(always)]
    fn div_rem(&self, idx: u64) -> (u64, u64) {
        let q = if self.magic != 0 {
            ((self.magic as u128 * idx as u128) >> 64) as u64
        } else {
            idx / self.radix
        };
        (q, idx - q * self.radix)
    }
}

/// One variable's digit of a Kronecker index, and the field it is packed into.
struct Digit {
    divisor: Divisor,
    /// The exponent a unit of the digit stands for.
    step: u64,
    word: usize,
    shift: u32,
}

/// Adds the digits of `idx` (least significant first) into their fields of `out`.
fn add_digits(digits: &[Digit], mut idx: u64, out: &mut [u64]) {
    for d in digits {
        let (q, r) = d.divisor.div_rem(idx);
        out[d.word] = out[d.word].wrapping_add((r * d.step) << d.shift);
        idx = q;
    }
}

/// Turns Kronecker indices into packed monomials. The packing is linear in the exponents, so a
/// monomial is the box's packed lower corner plus each digit shifted into its field. The low
/// digits are looked up in a table (the corner included), indexed by `idx % span`; the high
/// ones, `idx / span`, are decoded digit by digit only when they change, which on indices read
/// in order, as the dense product reads them, is once per `span` indices.
pub(crate) struct Decoder {
    words: usize,
    /// For each `r < span`, the packed corner plus the fields of the low digits of `r`.
    table: Vec<u64>,
    /// Division by `span`, the number of low indices.
    split: Divisor,
    /// The digits above the table, least significant first.
    high: Vec<Digit>,
}

/// A [`Decoder`]'s memory of the high part it decoded last.
pub(crate) struct Cursor {
    high: u64,
    fields: Vec<u64>,
}

impl Decoder {
    /// Words per packed monomial.
    pub(crate) fn words(&self) -> usize {
        self.words
    }

    /// A cursor that has decoded nothing yet.
    pub(crate) fn cursor(&self) -> Cursor {
        Cursor {
            high: u64::MAX,
            fields: vec![0; self.words],
        }
    }

    /// Appends the packed monomial of index `idx` to `out`.
    #[inline(always)]
    pub(crate) fn decode_onto(&self, cursor: &mut Cursor, idx: u64, out: &mut Vec<u64>) {
        // One word (most products): a push, where the general path's iterators cost more than
        // the addition.
        if self.words == 1 {
            out.push(self.decode_word(cursor, idx));
            return;
        }
        let low = self.low_part(cursor, idx);
        let at = low * self.words;
        for (l, h) in self.table[at..at + self.words].iter().zip(&cursor.fields) {
            out.push(l.wrapping_add(*h));
        }
    }

    /// The packed monomial of index `idx` in a one-word layout.
    #[inline(always)]
    pub(crate) fn decode_word(&self, cursor: &mut Cursor, idx: u64) -> u64 {
        debug_assert_eq!(self.words, 1);
        let low = self.low_part(cursor, idx);
        self.table[low].wrapping_add(cursor.fields[0])
    }

    /// The low part of `idx`, its row of the table, with the cursor moved to its high part.
    #[inline(always)]
    fn low_part(&self, cursor: &mut Cursor, idx: u64) -> usize {
        let (high, low) = self.split.div_rem(idx);
        if high != cursor.high {
            self.move_to(cursor, high);
        }
        low as usize
    }

    /// Decodes the high part `high` into the cursor (once per `span` indices read in order).
    #[inline(never)]
    fn move_to(&self, cursor: &mut Cursor, high: u64) {
        cursor.high = high;
        cursor.fields.fill(0);
        add_digits(&self.high, high, &mut cursor.fields);
    }
}

#[cfg(test)]
mod tests {
    use super::Kronecker;
    use crate::varset::Vars;

    /// Every index of a box decodes to the monomial whose index it is, read in descending
    /// order (as the dense product reads) and in a scattered order, with tables of every size
    /// from none to all the low digits, in a one-word and a three-word layout, with every
    /// step 1 and with steps of 2 and 3 (the box's monomials then lie that far apart).
    #[test]
    fn decoding_inverts_indexing() {
        let cases = [(3, 16), (5, 32)]
            .into_iter()
            .flat_map(|case| [(case, false), (case, true)]);
        for ((names, bits), stepped) in cases {
            let mut builder = Vars::builder().exponent_bits(bits);
            for k in 0..names {
                builder = builder.coordinate(&format!("v{k}"));
            }
            let vars = builder.build().unwrap();
            let layout = vars.layout();
            let n = names;
            let steps: Vec<u64> = (0..n as u64)
                .map(|j| if stepped { 1 + j % 3 } else { 1 })
                .collect();
            let s = |j: usize| steps[j] as i64;
            // The factors' bounds, a whole number of steps wide: a negative corner, and one
            // variable of extent 1 (no digit).
            let mut a: Vec<(i64, i64)> = (0..n)
                .map(|j| (-(j as i64), -(j as i64) + (2 + j as i64) * s(j)))
                .collect();
            let mut b: Vec<(i64, i64)> = (0..n).map(|j| (1, 1 + (j as i64 % 3) * s(j))).collect();
            (a[1], b[1]) = ((3, 3), (0, 0));
            let kron = Kronecker::new(&a, &b, &steps).unwrap();
            let lo: Vec<i64> = a.iter().zip(&b).map(|(x, y)| x.0 + y.0).collect();
            let hi: Vec<i64> = a.iter().zip(&b).map(|(x, y)| x.1 + y.1).collect();
            let own: Vec<(i64, i64)> = lo.iter().map(|&l| (l, l)).collect();
            // Every monomial of the box, packed, with its index from the box's corner.
            let mut expected = Vec::new();
            let mut e = lo.clone();
            loop {
                let mut packed = vec![0u64; layout.words];
                layout.pack(&e, &mut packed);
                let idx = kron.indices(layout, &packed, &own)[0];
                expected.push((idx, packed));
                let Some(j) = (0..n).rev().find(|&j| e[j] < hi[j]) else {
                    break;
                };
                e[j] += s(j);
                e[j + 1..].copy_from_slice(&lo[j + 1..]);
            }
            assert_eq!(expected.len() as u64, kron.size());
            expected.sort();
            for reads in [1, 2, 7, 30, 1 << 20] {
                let decoder = kron.decoder(layout, reads);
                let mut cursor = decoder.cursor();
                let scattered = (0..expected.len()).map(|k| (k * 7919) % expected.len());
                for k in (0..expected.len()).rev().chain(scattered) {
                    let (idx, packed) = &expected[k];
                    assert_eq!(*idx, k as u64);
                    let mut out = Vec::new();
                    decoder.decode_onto(&mut cursor, *idx, &mut out);
                    assert_eq!(&out, packed, "index {idx}, table for {reads} reads");
                }
            }
        }
    }
}
