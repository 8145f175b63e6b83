//! The hashed product: every term product added into a hash table keyed by its monomial's
//! Kronecker index, for products too sparse for the dense accumulators whose term products
//! nonetheless meet on few monomials (the minors of a rank's upper bound: 9.5 M term products,
//! each monomial met by hundreds of them). The heap product pays `log₂ n` comparisons a term
//! product to bring equal monomials together; the table pays one probe, and a sort of the
//! result. [`plan`] decides between them from a sample of rows, and cuts the range of the
//! product's indices into chunks of about [`CHUNK_SUMS`] monomials each, so that the table of
//! the chunk at hand stays in cache (the square of a polynomial of 24 682 terms has 229 723:
//! one table of them all spent most of its time waiting for memory).

use rustc_hash::FxHashSet;

use super::mul::PairProduct;
use crate::error::AlgebraError;
use crate::number::{axial_product, IntegerRing, Wide256};

/// The share of the term products [`plan`] samples, at most: one in 64 (whole rows of the
/// longer factor, 2 to 32 of them, or 32 rows of a share of its columns).
const SAMPLE_SHARE: usize = 64;

/// The most term products [`plan`] samples.
const MAX_SAMPLE: usize = 1 << 18;

/// Products of fewer term pairs than this stay with the heap: both ways are quick, and the
/// sample would cost a tenth of the product.
const MIN_PAIRS: usize = 1 << 16;

/// The least number of term products per monomial, estimated, for which the hashed product
/// is taken: it then adds into a table that many times smaller than the work, where the heap
/// pays `log₂ n` comparisons a term product.
const MIN_MULTIPLICITY: usize = 8;

/// The monomials a chunk is planned to hold: its sums (48 bytes each in words over Z\[i\],
/// up to 144 in the accumulators) and slots stay in the L2 cache. Of 2^9 to 2^15, 2^10 took
/// the least time for both the rank's minors (2^13: a third more) and the closure's square.
const CHUNK_SUMS: usize = 1 << 10;

/// Whether to take the hashed product of `a·b` (Kronecker indices, sorted descending, a
/// term's index the sum of its factors'), and if so the lowest index of each chunk of the
/// product, descending, the last 0: chunk `c` holds the indices from `lows[c]` up to the
/// chunk before it.
///
/// A sample of `s` rows of `a` spread over it, each times all of `b`, shows `e` products that
/// land on an index another sampled product has. When each monomial of the product is met by
/// `μ` products from as many rows, a sample of `s` of the `n` rows meets it about `λ = μs/n`
/// times, and `e/(sm) ≈ λ/2` while `λ` is small (less beyond), so `μ ≈ 2en/(s²m)`, an
/// underestimate for large `λ`. The sample is a 64th of the products, at most [`MAX_SAMPLE`]:
/// 2 to 32 whole rows, or, when fewer than two fit, 32 rows of a share `t/m` of the columns
/// (a product finds its partner only when that column is sampled too, so `μ ≈ 2enm/(s²t²)`).
/// Two rows alone, far apart, can miss each other's monomials altogether (the products of a
/// bracket of `{K_{26,25}, F1}` with `P_{24,24}`: `μ` 0 from two rows, 230 from 32, and 5.5 s
/// on the heap against 0.8 s hashed). The minors of a rank's upper
/// bound give `μ` over a hundred; Pearce's sparse products (truly 1.9 and 2.8 at sizes 6 and
/// 8, where the heap was the faster) under one. Below [`MIN_MULTIPLICITY`] the product stays
/// with the heap, whose memory is the product's own, where a table would hold a sum for
/// nearly each term product. The chunks are cut at quantiles of the sampled indices, as many
/// as the product's estimated monomials `nm/μ` fill at [`CHUNK_SUMS`] each.
pub(super) fn plan(a: &[u64], b: &[u64]) -> Option<Vec<u64>> {
    let (n, m) = (a.len(), b.len());
    if n < 2 || n.saturating_mul(m) < MIN_PAIRS {
        return None;
    }
    let budget = (n.saturating_mul(m) / SAMPLE_SHARE).min(MAX_SAMPLE);
    // Whole rows while two of them fit the budget; past that, 32 rows of a share of the
    // columns, picked by a hash of their position (the same ones in every row).
    let rows = match budget / m {
        0 | 1 => n.min(32),
        r => r.min(32).min(n),
    };
    let wanted = (budget / rows).min(m) as u64;
    let threshold = (wanted << 32) / m as u64;
    let cols: Vec<u64> = (0u64..)
        .zip(b)
        .filter(|&(j, _)| wanted == m as u64 || mix(j) >> 32 < threshold)
        .map(|(_, &bj)| bj)
        .collect();
    let t = cols.len();
    if t == 0 {
        return None;
    }
    // The sample's distinct indices (sorted below only for a product that is hashed:
    // sorting them all cost a tenth of a product of 1287² pairs that the heap then took).
    let mut seen = FxHashSet::with_capacity_and_hasher(rows * t, Default::default());
    for k in 0..rows {
        // Row midpoints of `rows` equal parts: the extreme rows, the least alike, are left.
        let ai = a[(2 * k + 1) * n / (2 * rows)];
        seen.extend(cols.iter().map(|&bj| ai + bj));
    }
    let distinct = seen.len();
    // With a share `t/m` of the columns, a sampled product finds its partner only when that
    // column is sampled too: `e/(st) ≈ (λ/2)(t/m)`, so `μ ≈ 2enm/(s²t²)`.
    let excess = (rows * t - distinct) as u128;
    let (n, m, s, t) = (n as u128, m as u128, rows as u128, t as u128);
    // `s²t²`, the sampled products squared.
    let sampled_squared = (s * t).pow(2);
    if 2 * excess * n * m < MIN_MULTIPLICITY as u128 * sampled_squared {
        return None;
    }
    // The estimated monomials, `nm/μ = s²t²/(2e)`, in chunks.
    let monomials = (sampled_squared / (2 * excess)).min(usize::MAX as u128) as usize;
    let chunks = monomials.div_ceil(CHUNK_SUMS).clamp(1, distinct);
    let mut sample: Vec<u64> = seen.into_iter().collect();
    sample.sort_unstable_by(|x, y| y.cmp(x));
    let mut lows: Vec<u64> = (1..chunks)
        .map(|c| sample[c * sample.len() / chunks])
        .collect();
    lows.dedup();
    lows.push(0);
    Some(lows)
}

/// A well-mixed hash of a column's position (SplitMix64's finaliser): the columns it picks
/// must look random, since a collision needs two picked columns at a given distance (a
/// multiplicative hash picks them on a lattice whose distances miss most others).
fn mix(j: u64) -> u64 {
    let mut z = j.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// One monomial of the table as it is drained: its index, one pair of factor terms whose
/// product it is, and its sum.
struct Sum<A> {
    key: u64,
    pair: (u32, u32),
    acc: A,
}

/// The sums, in the order their monomials came, and the slots that find them by linear
/// probing (an index into the sums plus one, or 0 when empty; more than twice the sums). An
/// `FxHashMap` of the same sums took 5 % more time for the rank's minors and 13 % more for the
/// closure's square.
struct Table<A> {
    /// The sums' monomials, apart from the sums themselves, so that a probe compares in a
    /// small array that stays in the L1 cache (8 bytes a monomial, where a sum is 32 to 144).
    keys: Vec<u64>,
    pairs: Vec<(u32, u32)>,
    accs: Vec<A>,
    slots: Vec<u32>,
    shift: u32,
}

impl<A: Default> Table<A> {
    fn with_slots(slots: usize) -> Self {
        debug_assert!(slots.is_power_of_two());
        Table {
            keys: Vec::with_capacity(slots / 2),
            pairs: Vec::with_capacity(slots / 2),
            accs: Vec::with_capacity(slots / 2),
            slots: vec![0; slots],
            shift: 64 - slots.trailing_zeros(),
        }
    }

    fn slot_of(&self, key: u64) -> usize {
        (key.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> self.shift) as usize
    }

    /// How many monomials the table holds.
    fn len(&self) -> usize {
        self.keys.len()
    }

    /// The sum of `key`, new (from `pair`) when the key has none yet.
    #[inline(always)]
    fn sum(&mut self, key: u64, pair: (u32, u32)) -> &mut A {
        let mask = self.slots.len() - 1;
        let mut slot = self.slot_of(key);
        loop {
            match self.slots[slot] {
                0 => {
                    if 2 * (self.len() + 1) >= self.slots.len() {
                        self.grow();
                        return self.sum(key, pair);
                    }
                    self.keys.push(key);
                    self.pairs.push(pair);
                    self.accs.push(A::default());
                    self.slots[slot] = self.len() as u32;
                    let last = self.len() - 1;
                    return &mut self.accs[last];
                }
                k => {
                    let k = k as usize - 1;
                    if self.keys[k] == key {
                        return &mut self.accs[k];
                    }
                }
            }
            slot = (slot + 1) & mask;
        }
    }

    /// Twice the slots, every sum found again.
    #[cold]
    fn grow(&mut self) {
        let slots = 2 * self.slots.len();
        self.slots = vec![0; slots];
        self.shift = 64 - slots.trailing_zeros();
        let mask = slots - 1;
        for (k, &key) in self.keys.iter().enumerate() {
            let mut slot = self.slot_of(key);
            while self.slots[slot] != 0 {
                slot = (slot + 1) & mask;
            }
            self.slots[slot] = k as u32 + 1;
        }
    }

    /// The sums, the table emptied for the next chunk.
    fn drain(&mut self) -> impl Iterator<Item = Sum<A>> + '_ {
        self.slots.fill(0);
        let keys = self.keys.drain(..).zip(self.pairs.drain(..));
        keys.zip(self.accs.drain(..))
            .map(|((key, pair), acc)| Sum { key, pair, acc })
    }
}

/// `a·b` on Kronecker indices (each factor's sorted descending), chunk by chunk of the
/// indices (`lows` from [`plan`]), every term product added to its monomial's sum in a hash
/// table; a square (`a` and `b` the same terms) takes each pair of distinct terms once,
/// doubled. The terms come out sorted descending, each with one pair of factor terms whose
/// product is its monomial, like the heap product's. `None` when the terms and the table
/// would hold more than `max_terms` monomials (sums that cancel included): the heap product
/// then decides whether the product itself has too many terms.
///
/// The sums are the narrowest that hold them. When every coefficient fits a word and no sum
/// can pass an `i128` component (a monomial gathers at most one product per row), they are
/// machine words: a table entry is 32 bytes over Z and 48 over Z\[i\], and a product one
/// multiply-add. When every coefficient is real or imaginary and fits an `i128` (each of
/// `Z^m e^{−inθ}`'s is), and no sum can pass 255 bits, a product is one real product, added
/// to the real or the imaginary part (chosen without a branch) of a pair of 256-bit sums: the squares
/// of the closure's resonant integrals, whose 70-bit coefficients spilled the accumulators to
/// their 256-bit tier a product at a time. Otherwise each sum is the ring's accumulator,
/// which spills past 256 bits when it must.
pub(super) fn hashed_product<I: IntegerRing>(
    a: (&[u64], &[I]),
    b: (&[u64], &[I]),
    lows: &[u64],
    max_terms: usize,
) -> Option<Result<PairProduct<I>, AlgebraError>> {
    let square = std::ptr::eq(a.0, b.0) && std::ptr::eq(a.1, b.1);
    let pairs = (a.0, b.0, square);
    // Bits a sum can gain over the largest product: one product a row, each component the sum
    // of `products` real ones, and doubled off a square's diagonal.
    let fan_in = |products: u32| {
        let rows = a.1.len().min(b.1.len()) as u64;
        64 - rows.leading_zeros() + products + u32::from(square)
    };
    let words = Converted::new(a.1, b.1, square, I::to_small, I::small_bits, |c| {
        I::small_checked_scale(c, 2)
    });
    if let Some(words) = words.filter(|w| w.bits + fan_in(I::PRODUCTS_PER_COMPONENT) <= 126) {
        return words.product(pairs, lows, max_terms, I::wide_add_mul, I::from_wide);
    }
    let bits = |c: &(i128, bool)| 128 - c.0.unsigned_abs().leading_zeros();
    let parts = Converted::new(a.1, b.1, square, I::to_real_or_imaginary, bits, |c| {
        (bits(c) < 126).then(|| (2 * c.0, c.1))
    });
    if let Some(parts) = parts.filter(|p| p.max_bits <= 126 && p.bits + fan_in(1) <= 254) {
        // (i^e x)(i^f y) = i^(e+f) xy: real for e = f, negated when both are imaginary.
        let add_mul = |sum: &mut [Wide256; 2], x: &(i128, bool), y: &(i128, bool)| {
            let (part, x) = axial_product(*x, y.1);
            sum[part].add_mul(x, y.0);
        };
        let finish = |[re, im]: [Wide256; 2]| I::from_parts(re.to_integer(), im.to_integer());
        return parts.product(pairs, lows, max_terms, add_mul, finish);
    }
    let doubled: Vec<I> = match square {
        true => b.1.iter().map(|c| c.add(c)).collect(),
        false => Vec::new(),
    };
    let add = |acc: &mut I::Acc, i: usize, j: usize, twice: bool| {
        I::acc_add_mul(acc, &a.1[i], if twice { &doubled[j] } else { &b.1[j] })
    };
    let drain = |table: &mut Table<I::Acc>, out: &mut Product<I>| {
        let sums = table.drain().map(|s| (s.key, s.pair, I::acc_finish(s.acc)));
        out.append(sums.filter(|t| !t.2.is_zero()));
    };
    chunked(pairs, lows, max_terms, add, drain).map(Ok)
}

/// The factors' coefficients in a fixed-width form `W` (machine words, or real and imaginary
/// `i128`s), the second's doubled for a square, with the bits their products can take.
struct Converted<W> {
    a: Vec<W>,
    b: Vec<W>,
    /// The second factor's coefficients doubled (a square's pairs off the diagonal), or none.
    doubled: Vec<W>,
    /// Bits of the largest coefficient of `a` plus those of the largest of `b`.
    bits: u32,
    /// Bits of the largest coefficient of either factor, doubled ones included.
    max_bits: u32,
}

impl<W: Copy> Converted<W> {
    /// Both factors' coefficients in the form `W`, if every one converts (and doubles, for
    /// a square).
    fn new<I>(
        a: &[I],
        b: &[I],
        square: bool,
        convert: impl Fn(&I) -> Option<W>,
        bits_of: impl Fn(&W) -> u32,
        double: impl Fn(&W) -> Option<W>,
    ) -> Option<Self> {
        let all = |c: &[I]| c.iter().map(&convert).collect::<Option<Vec<_>>>();
        let (a, b) = (all(a)?, all(b)?);
        let doubled: Vec<W> = match square {
            true => b.iter().map(&double).collect::<Option<_>>()?,
            false => Vec::new(),
        };
        let max = |s: &[W]| s.iter().map(&bits_of).max().unwrap_or(0);
        let (bits_a, bits_b) = (max(&a), max(&b));
        Some(Converted {
            bits: bits_a + bits_b,
            max_bits: bits_a.max(bits_b).max(max(&doubled)),
            a,
            b,
            doubled,
        })
    }

    /// The product with sums `A` (`add_mul` adds a product of coefficients, `finish` reads a
    /// sum back), which the caller has checked cannot overflow.
    fn product<A: Default + PartialEq, I>(
        &self,
        pairs: (&[u64], &[u64], bool),
        lows: &[u64],
        max_terms: usize,
        add_mul: impl Fn(&mut A, &W, &W),
        finish: impl Fn(A) -> I,
    ) -> Option<Result<PairProduct<I>, AlgebraError>> {
        let add = |acc: &mut A, i: usize, j: usize, twice: bool| {
            let partner = if twice { &self.doubled[j] } else { &self.b[j] };
            add_mul(acc, &self.a[i], partner)
        };
        let drain = |table: &mut Table<A>, out: &mut Product<I>| {
            let zero = A::default();
            let sums = table.drain().filter(|s| s.acc != zero);
            out.append(sums.map(|s| (s.key, s.pair, finish(s.acc))));
        };
        chunked(pairs, lows, max_terms, add, drain).map(Ok)
    }
}

/// The terms of a product as they come, chunk by chunk, highest first.
struct Product<I> {
    pairs: Vec<(u32, u32)>,
    coeffs: Vec<I>,
}

impl<I> Default for Product<I> {
    fn default() -> Self {
        Product {
            pairs: Vec::new(),
            coeffs: Vec::new(),
        }
    }
}

impl<I> Product<I> {
    /// Appends the terms of a chunk, below every term so far, sorted descending.
    fn append(&mut self, terms: impl Iterator<Item = (u64, (u32, u32), I)>) {
        let mut terms: Vec<_> = terms.collect();
        terms.sort_unstable_by_key(|t| std::cmp::Reverse(t.0));
        for (_, pair, c) in terms {
            self.pairs.push(pair);
            self.coeffs.push(c);
        }
    }
}

/// Adds every term product `a_i·b_j` (for a square, `j ≥ i`, those off the diagonal twice,
/// which `add`'s last argument asks for) to its index's sum in a table of sums `A`, a chunk of
/// indices at a time (`lows`), and hands each chunk's sums to `drain`, which writes them as
/// terms; `None` once the terms and the table hold more than `max_terms`.
#[inline(always)]
fn chunked<A: Default, I>(
    (a, b, square): (&[u64], &[u64], bool),
    lows: &[u64],
    max_terms: usize,
    mut add: impl FnMut(&mut A, usize, usize, bool),
    mut drain: impl FnMut(&mut Table<A>, &mut Product<I>),
) -> Option<PairProduct<I>> {
    let mut table = Table::<A>::with_slots(4 * CHUNK_SUMS);
    let mut out = Product::default();
    // `next[i]`: the first partner of row `i` not yet multiplied (products of a row descend).
    let mut next: Vec<usize> = (0..a.len()).map(|i| if square { i } else { 0 }).collect();
    for &low in lows {
        for (i, (&ka, next)) in a.iter().zip(next.iter_mut()).enumerate() {
            // The row's products in the chunk: a run from `next` on, found first, so that the
            // loop only adds.
            let start = *next;
            let run = b[start..].partition_point(|&kb| ka + kb >= low);
            for (j, &kb) in (start..).zip(&b[start..start + run]) {
                add(
                    table.sum(ka + kb, (i as u32, j as u32)),
                    i,
                    j,
                    square && j > i,
                );
            }
            *next = start + run;
        }
        if out.coeffs.len() + table.len() > max_terms {
            return None;
        }
        drain(&mut table, &mut out);
    }
    Some((out.pairs, out.coeffs))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::{GaussianInteger, Integer};

    /// Kronecker indices of a two-variable polynomial `Σ c x^i y^j` with `i, j < 100`.
    fn index(i: u64, j: u64) -> u64 {
        100 * i + j
    }

    /// The terms `c x^i y^j` sorted by index, descending.
    fn sorted<I: IntegerRing>(terms: Vec<(u64, u64, I)>) -> (Vec<u64>, Vec<I>) {
        let mut t: Vec<(u64, I)> = terms
            .into_iter()
            .map(|(i, j, c)| (index(i, j), c))
            .collect();
        t.sort_unstable_by_key(|x| std::cmp::Reverse(x.0));
        t.into_iter().unzip()
    }

    fn dense(terms: &[(u64, u64, i64)]) -> (Vec<u64>, Vec<Integer>) {
        sorted(
            terms
                .iter()
                .map(|&(i, j, c)| (i, j, Integer::from(c)))
                .collect(),
        )
    }

    /// The product by the definition: every pair, summed per index by the ring's own
    /// arithmetic, zeros dropped.
    fn naive<I: IntegerRing>(a: &(Vec<u64>, Vec<I>), b: &(Vec<u64>, Vec<I>)) -> Vec<(u64, I)> {
        let mut sums = std::collections::BTreeMap::<u64, I>::new();
        for (ka, ca) in a.0.iter().zip(&a.1) {
            for (kb, cb) in b.0.iter().zip(&b.1) {
                let sum = sums.entry(ka + kb).or_default();
                *sum = sum.add(&ca.mul(cb));
            }
        }
        sums.into_iter()
            .rev()
            .filter(|(_, c)| !c.is_zero())
            .collect()
    }

    /// The hashed product as one chunk, checked against the same in chunks that cut it
    /// anywhere (a chunk with no monomial included).
    fn hashed<I: IntegerRing>(a: &(Vec<u64>, Vec<I>), b: &(Vec<u64>, Vec<I>)) -> Vec<(u64, I)> {
        let run = |lows: &[u64]| {
            let (pairs, coeffs) = hashed_product((&a.0, &a.1), (&b.0, &b.1), lows, usize::MAX)
                .expect("no limit")
                .expect("no error");
            pairs
                .iter()
                .map(|&(i, j)| a.0[i as usize] + b.0[j as usize])
                .zip(coeffs)
                .collect::<Vec<_>>()
        };
        let whole = run(&[0]);
        assert_eq!(run(&[5000, 4999, 2500, 1000, 150, 0]), whole);
        whole
    }

    #[test]
    fn sums_products_squares_and_cancellations_like_the_definition() {
        // (x + y)^k-like rows: many products per monomial, a cancellation, a wide coefficient
        // and more monomials than the first table's slots (it grows).
        let mut f = vec![
            (3, 0, 1),
            (2, 1, -3),
            (1, 2, 3),
            (0, 3, -1),
            (5, 5, i64::MAX),
        ];
        let g: Vec<(u64, u64, i64)> = (0..40)
            .flat_map(|i| (0..40).map(move |j| (i, j, (i * 7 + j * 3) as i64 % 11 - 5)))
            .filter(|t| t.2 != 0)
            .collect();
        let (fa, gb) = (dense(&f), dense(&g));
        assert_eq!(hashed(&fa, &gb), naive(&fa, &gb));
        assert_eq!(hashed(&gb, &gb), naive(&gb, &gb));
        // Words whose sums could pass an `i128` (63 + 63 bits, 40 rows), and a coefficient past
        // a word: 256-bit sums.
        let wide: Vec<(u64, u64, i64)> = g
            .iter()
            .map(|&(i, j, c)| (i, j, i64::MAX - 5 - c))
            .collect();
        let wide = dense(&wide);
        assert_eq!(hashed(&wide, &wide), naive(&wide, &wide));
        // The same, as a product of two lists (a square doubles past a word, which alone
        // would leave the words).
        let other = wide.clone();
        assert_eq!(hashed(&wide, &other), naive(&wide, &other));
        // A coefficient of 102 bits (256-bit sums), and one past an `i128` (the accumulators).
        let mut long = dense(&f);
        for bits in [100, 130] {
            long.1[0] = Integer::from_bigint(num_bigint::BigInt::from(3) << bits);
            assert_eq!(hashed(&long, &gb), naive(&long, &gb));
            assert_eq!(hashed(&long, &long), naive(&long, &long));
        }
        // x − y times x + y: x² − y², the xy terms cancel.
        f = vec![(1, 0, 1), (0, 1, -1)];
        let h = dense(&[(1, 0, 1), (0, 1, 1)]);
        assert_eq!(
            hashed(&dense(&f), &h),
            vec![
                (index(2, 0), Integer::from(1)),
                (index(0, 2), Integer::from(-1))
            ]
        );
    }

    /// Over Z\[i\]: real and imaginary coefficients of 70 bits (the 256-bit sums of real
    /// products, where two imaginary factors make a negative real product, and a monomial
    /// gathers real and imaginary products both), squares among them; a coefficient with
    /// both parts (the accumulators); and words (48-byte sums).
    #[test]
    fn gaussian_products_of_real_and_imaginary_coefficients_like_the_definition() {
        let gaussian = |re: i128, im: i128| {
            GaussianInteger::new(Integer::from_i128(re), Integer::from_i128(im))
        };
        let big = 1i128 << 69;
        let part = |i: u64, j: u64| {
            let v = big - (i * 31 + j * 17) as i128 % 97 + 48;
            match (i * j + i) % 4 {
                0 => gaussian(v, 0),
                1 => gaussian(0, v),
                2 => gaussian(-v, 0),
                _ => gaussian(0, -v),
            }
        };
        let grid = |n: u64| -> Vec<(u64, u64, GaussianInteger)> {
            (0..n)
                .flat_map(|i| (0..n).map(move |j| (i, j, part(i, j))))
                .collect()
        };
        let (f, g) = (sorted(grid(7)), sorted(grid(20)));
        for (a, b) in [(&f, &g), (&g, &g), (&f, &f)] {
            let want = naive(a, b);
            assert!(want.iter().any(|(_, c)| !c.re.is_zero() && !c.im.is_zero()));
            assert_eq!(hashed(a, b), want);
        }
        let mut mixed = f.clone();
        mixed.1[3] = gaussian(big, -big);
        assert_eq!(hashed(&mixed, &g), naive(&mixed, &g));
        assert_eq!(hashed(&mixed, &mixed), naive(&mixed, &mixed));
        let small: Vec<(u64, u64, GaussianInteger)> = grid(12)
            .into_iter()
            .map(|(i, j, c)| {
                (
                    i,
                    j,
                    gaussian(c.re.to_i128().unwrap() >> 40, c.im.to_i128().unwrap() >> 40),
                )
            })
            .collect();
        let small = sorted(small);
        assert_eq!(hashed(&small, &small), naive(&small, &small));
        assert_eq!(hashed(&small, &g), naive(&small, &g));
    }

    #[test]
    fn a_table_past_the_limit_is_left_to_the_heap() {
        let g = dense(&[(1, 0, 1), (0, 1, 1), (0, 0, 1)]);
        let h = dense(&[(9, 0, 1), (0, 9, 1), (3, 3, 1)]);
        for lows in [&[0][..], &[600, 0]] {
            assert!(hashed_product((&g.0, &g.1), (&h.0, &h.1), lows, 8).is_none());
            assert!(hashed_product((&g.0, &g.1), (&h.0, &h.1), lows, 9).is_some());
        }
    }

    #[test]
    fn only_products_whose_monomials_meet_are_hashed_in_chunks_down_to_zero() {
        // Chunks cut descending, down to 0.
        let chunked =
            |lows: &[u64]| lows.windows(2).all(|w| w[0] > w[1]) && lows.last() == Some(&0);
        // (1 + x + … + x^299)²: every monomial is met by many products (599 monomials,
        // estimated at 4368 since a sample meets each one many times: a few small chunks).
        let line: Vec<u64> = (0..300).rev().collect();
        assert!(plan(&line, &line).is_some_and(|lows| chunked(&lows)));
        // x^(300 i) · y^j: every product a monomial of its own.
        let spread: Vec<u64> = (0..300).rev().map(|i| 300 * i).collect();
        assert_eq!(plan(&spread, &line), None);
        // A longer factor than the sample holds whole rows of: 32 rows of a share of its
        // columns, which still meet.
        let wide: Vec<u64> = (0..1u64 << 20).rev().collect();
        assert!(plan(&line, &wide).is_some_and(|lows| chunked(&lows)));
        let far: Vec<u64> = (0..1u64 << 20).rev().map(|j| j << 20).collect();
        assert_eq!(plan(&line, &far), None);
        // Too few pairs to be worth a sample.
        assert_eq!(plan(&line[..200], &line[..200]), None);
        // (1 + … + x^19999)²: 39 999 monomials, estimated from 13 rows at about 150 000 (the
        // estimate errs high where a sample meets each monomial many times): at least as many
        // chunks as the true monomials fill, and at most four times that, descending to 0.
        let long: Vec<u64> = (0..20_000).rev().collect();
        let lows = plan(&long, &long).expect("hashed");
        let least = 39_999usize.div_ceil(CHUNK_SUMS);
        assert!(
            (least..=4 * least).contains(&lows.len()),
            "{} chunks",
            lows.len()
        );
        assert!(chunked(&lows));
    }
}
