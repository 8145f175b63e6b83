//! Where the gathering kernels add their term products: `WordGather`, exact sums in machine
//! words found by open addressing, and `Gather`, ring elements for coefficients of any size;
//! `Gathered`, the sorted terms either gives back; and `Smalls`, a factor's coefficients as
//! machine words, converted once for all its term products.

use std::marker::PhantomData;

use arrayvec::ArrayVec;

use super::MonomialMap;
use crate::number::{Integer, IntegerRing};
use crate::poly::mul::Key;
use crate::varset::Layout;

/// The terms a kernel gathered: sorted, distinct, nonzero.
pub(crate) struct Gathered<I> {
    pub(crate) exps: Vec<u64>,
    pub(crate) coeffs: Vec<I>,
    /// `Some(d)` when the sums were divided by `d` (their gcd, with the sign of the leading
    /// one), which leaves them primitive with a positive lead; `None` when they are as they
    /// came, and still to be normalised.
    pub(crate) divisor: Option<Integer>,
}

/// The bits of the `i128` sums: a term product whose real products each take at most `b`
/// bits has components below `2^(b + 1)` (a Gaussian component adds two), so that `n` of them
/// sum below `2^(b + 1 + ⌈log₂ n⌉)`, which must stay below `2^127`.
const SUM_BITS: u32 = 126;

/// The most bits of a component of any of the coefficients, if every one fits a word.
pub(crate) fn small_bits<I: IntegerRing>(coeffs: &[I]) -> Option<u32> {
    let mut bits = 0;
    for c in coeffs {
        bits = bits.max(I::small_bits(&c.to_small()?));
    }
    Some(bits)
}

/// Coefficients as machine words ([`IntegerRing::Small`]), converted once per factor rather
/// than once per term product: held inline for the short polynomials these kernels mostly see,
/// on the heap past [`INLINE_SMALLS`] terms. Filled where it stays (its inline part is up to
/// half a kilobyte, which a move would copy: returned by value, it cost W4 a tenth more).
pub(super) struct Smalls<S> {
    inline: ArrayVec<S, INLINE_SMALLS>,
    heap: Vec<S>,
}

/// The most coefficients [`Smalls`] holds inline.
const INLINE_SMALLS: usize = 32;

impl<S: Copy> Smalls<S> {
    #[inline(always)]
    pub(super) fn new() -> Self {
        Smalls {
            inline: ArrayVec::new(),
            heap: Vec::new(),
        }
    }

    /// The coefficients as words, or `None` if one does not fit.
    #[inline(always)]
    pub(super) fn fill<I: IntegerRing<Small = S>>(&mut self, coeffs: &[I]) -> Option<&[S]> {
        self.fill_with(coeffs, I::to_small)
    }

    /// The coefficients each as `word`, or `None` if one has none.
    #[inline(always)]
    fn fill_with<I>(&mut self, coeffs: &[I], word: impl Fn(&I) -> Option<S>) -> Option<&[S]> {
        if coeffs.len() <= INLINE_SMALLS {
            self.inline.clear();
            for c in coeffs {
                self.inline.push(word(c)?);
            }
            Some(&self.inline)
        } else {
            // The vector's room is kept from one factor to the next.
            self.heap.clear();
            for c in coeffs {
                self.heap.push(word(c)?);
            }
            Some(&self.heap)
        }
    }
}

impl Smalls<i64> {
    /// The coefficients as words of Z, or `None` if one is not real or does not fit: the
    /// factors of a real gathering ([`IntegerRing::COMPLEX`]).
    #[inline(always)]
    pub(super) fn fill_real<I: IntegerRing>(&mut self, coeffs: &[I]) -> Option<&[i64]> {
        self.fill_with(coeffs, I::to_real_i64)
    }
}

/// Term products with word-sized coefficients, each kept exactly in the ring's wide form (no
/// allocation, clone or drop per coefficient) and added at once to the running sum of its
/// monomial, which an open-addressing table (`T`) finds: only the distinct monomials are
/// sorted at the end, and only those whose sums did not cancel (none, for an identity's
/// residual).
pub(super) struct WordGather<K, I: IntegerRing, T = Heap<K, <I as IntegerRing>::Wide>> {
    /// The distinct monomials in the order they came, with their sums, and the slots that
    /// find them.
    table: T,
    /// `64 − log₂(slots)`: a hash's top bits pick the slot.
    shift: u32,
    /// `slots − 1`, kept rather than derived from `shift`: every probe reads it.
    mask: usize,
    /// The bits left for the multiplier `k` of a product `a·b·k`: [`SUM_BITS`] less the
    /// bits of the most term products one monomial can gather and the most bits of `a` and
    /// `b` together (from [`small_bits`]).
    k_budget: u32,
    ring: PhantomData<(K, I)>,
}

/// A gathering of fewer term products than this can be held [`Inline`]: its slots, `2n + 1`
/// rounded up to a power of two, are then at most `2·INLINE`. A bracket of two generators of
/// an algebra gathers 8 to 16 term products, the Casimir of su(2) 27.
pub(super) const INLINE: usize = 32;

/// The sums of a [`WordGather`] and the slots that find them, by linear probing: a slot holds
/// an index into the sums plus one, or 0 when empty; a power of two, more than twice the sums.
pub(super) trait Table<K, W>: Sized {
    /// Room for `n` sums in `slots` slots.
    fn new(n: usize, slots: usize) -> Self;
    /// What slot `slot` holds: the index of a sum plus one, or 0.
    fn slot(&self, slot: usize) -> usize;
    /// The monomial and sum of index `k`, which a slot holds.
    fn sum(&mut self, k: usize) -> &mut (K, W);
    /// A new sum, found from the empty slot `slot`.
    fn insert(&mut self, slot: usize, m: K, w: W);
    /// Drops the sums equal to `zero` and gives the rest, in the order they came.
    fn nonzero(&mut self, zero: W) -> &mut [(K, W)];
}

/// A [`Table`] on the heap, of any size.
pub(super) struct Heap<K, W> {
    items: Vec<(K, W)>,
    slots: Vec<u32>,
}

/// A [`Table`] held inline, for fewer than [`INLINE`] sums: no allocation (the two of a
/// [`Heap`] table and their frees were a tenth of a short bracket). Its indices are masked by
/// the arrays' lengths, which changes none of them and spares the bounds checks.
pub(super) struct Inline<K, W> {
    items: ArrayVec<(K, W), INLINE>,
    slots: [u8; 2 * INLINE],
}

impl<K: Key, W: Copy + PartialEq> Table<K, W> for Heap<K, W> {
    #[inline(always)]
    fn new(n: usize, slots: usize) -> Self {
        Heap {
            items: Vec::with_capacity(n),
            slots: vec![0; slots],
        }
    }

    #[inline(always)]
    fn slot(&self, slot: usize) -> usize {
        self.slots[slot] as usize
    }

    #[inline(always)]
    fn sum(&mut self, k: usize) -> &mut (K, W) {
        &mut self.items[k]
    }

    #[inline(always)]
    fn insert(&mut self, slot: usize, m: K, w: W) {
        debug_assert!(
            2 * self.items.len() < self.slots.len(),
            "more sums than promised"
        );
        self.items.push((m, w));
        self.slots[slot] = self.items.len() as u32;
    }

    fn nonzero(&mut self, zero: W) -> &mut [(K, W)] {
        self.items.retain(|(_, sum)| *sum != zero);
        &mut self.items
    }
}

impl<K: Key, W: Copy + PartialEq> Table<K, W> for Inline<K, W> {
    #[inline(always)]
    fn new(n: usize, slots: usize) -> Self {
        debug_assert!(n < INLINE && slots <= 2 * INLINE);
        Inline {
            items: ArrayVec::new(),
            slots: [0; 2 * INLINE],
        }
    }

    #[inline(always)]
    fn slot(&self, slot: usize) -> usize {
        usize::from(self.slots[slot & (2 * INLINE - 1)])
    }

    #[inline(always)]
    fn sum(&mut self, k: usize) -> &mut (K, W) {
        &mut self.items[k & (INLINE - 1)]
    }

    #[inline(always)]
    fn insert(&mut self, slot: usize, m: K, w: W) {
        self.items.push((m, w));
        self.slots[slot & (2 * INLINE - 1)] = self.items.len() as u8;
    }

    fn nonzero(&mut self, zero: W) -> &mut [(K, W)] {
        self.items.retain(|(_, sum)| *sum != zero);
        &mut self.items
    }
}

impl<K: Key, I: IntegerRing> WordGather<K, I> {
    /// The bits a multiplier may take in the sums of term products whose coefficients fit
    /// words and take at most `ab_bits` bits together, and of which at most `per_monomial`
    /// share a monomial; `None` when no multiplier would leave room in the sums.
    #[inline(always)]
    pub(super) fn budget(ab_bits: u32, per_monomial: usize) -> Option<u32> {
        let fan_in_bits = usize::BITS - per_monomial.max(1).saturating_sub(1).leading_zeros();
        SUM_BITS.checked_sub(fan_in_bits + ab_bits)
    }
}

impl<K: Key, I: IntegerRing, T: Table<K, I::Wide>> WordGather<K, I, T> {
    /// Room for at most `n` term products, with the [`WordGather::budget`] of their
    /// coefficients. (Not an `Option`: an [`Inline`] table is built where it stays, never
    /// moved out of one, which would copy its 1.5 KB.)
    #[inline(always)]
    pub(super) fn new(n: usize, k_budget: u32) -> Self {
        let slots = (2 * n + 1).next_power_of_two().max(8);
        WordGather {
            table: T::new(n, slots),
            shift: 64 - slots.trailing_zeros(),
            mask: slots - 1,
            k_budget,
            ring: PhantomData,
        }
    }

    /// Adds the term `a·b·k·iᵗ·m` (`k ≠ 0`, `t` = `turns`; `a`, `b` from [`Smalls`]), or
    /// returns `false` and adds nothing when `k` takes more bits than the sums leave it, or
    /// `t > 0` in a ring without `i`. Tests for `k = 1`, the multiplier of most term products
    /// of products, squares and brackets, first.
    #[inline(always)]
    pub(super) fn push(&mut self, m: K, a: &I::Small, b: &I::Small, k: i64, turns: u32) -> bool {
        // `k = 1` takes one bit of the budget, like any other multiplier.
        let w = if k == 1 && turns == 0 && self.k_budget >= 1 {
            let mut w = I::Wide::default();
            I::wide_add_mul(&mut w, a, b);
            w
        } else {
            match self.term(a, b, k, turns) {
                Some(w) => w,
                None => return false,
            }
        };
        self.add(m, w);
        true
    }

    /// [`WordGather::push`] of ring elements, converted to words here: for walks that form
    /// each term product once and skip terms (a derivative's), or have one long factor (a flow
    /// on a condition), where converting every coefficient of a factor beforehand would be
    /// wasted, and whose multipliers are seldom 1.
    #[inline(always)]
    pub(super) fn push_ring(&mut self, m: K, a: &I, b: &I, k: i64, turns: u32) -> bool {
        let (Some(a), Some(b)) = (a.to_small(), b.to_small()) else {
            return false;
        };
        match self.term(&a, &b, k, turns) {
            Some(w) => {
                self.add(m, w);
                true
            }
            None => false,
        }
    }

    /// `a·b·k·iᵗ` in the wide form, or `None` when `k` takes more bits than the sums leave
    /// it, or `t > 0` in a ring without `i`.
    #[inline(always)]
    fn term(&self, a: &I::Small, b: &I::Small, k: i64, turns: u32) -> Option<I::Wide> {
        let k_bits = 64 - k.unsigned_abs().leading_zeros();
        if k_bits > self.k_budget {
            return None;
        }
        let mut w = I::Wide::default();
        // The multiplier goes into a word-sized factor when it fits, else into the product.
        match (k, I::small_checked_scale(a, k)) {
            (1, _) => I::wide_add_mul(&mut w, a, b),
            (_, Some(ak)) => I::wide_add_mul(&mut w, &ak, b),
            (_, None) => {
                I::wide_add_mul(&mut w, a, b);
                w = I::wide_scale(&w, k);
            }
        }
        for _ in 0..turns {
            w = I::wide_mul_i(&w)?;
        }
        Some(w)
    }

    /// [`WordGather::push`] of the image of the term under `map`, when given; `false` when
    /// the image's factor passes a word.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    pub(super) fn push_mapped(
        &mut self,
        layout: &Layout,
        map: Option<&MonomialMap>,
        m: K,
        a: &I::Small,
        b: &I::Small,
        k: i64,
        turns: u32,
    ) -> bool {
        match map {
            None => self.push(m, a, b, k, turns),
            Some(map) => match map.apply(layout, m, k) {
                Some((m, k)) => self.push(m, a, b, k, turns),
                None => false,
            },
        }
    }

    /// `sum(m) += w`.
    #[inline(always)]
    pub(super) fn add(&mut self, m: K, w: I::Wide) {
        let mut slot = (m.hash() >> self.shift) as usize;
        loop {
            match self.table.slot(slot) {
                0 => return self.table.insert(slot, m, w),
                k => {
                    let item = self.table.sum(k - 1);
                    if item.0 == m {
                        return I::wide_add(&mut item.1, &w);
                    }
                }
            }
            slot = (slot + 1) & self.mask;
        }
    }

    /// The terms sorted descending, zero sums dropped, divided by the gcd of the sums and the
    /// sign of the leading one (on machine words, while they are converted), so that they are
    /// primitive. Takes `&mut self` so that an [`Inline`] table is not moved (copied) into
    /// the call; the table is spent afterwards.
    pub(super) fn finish(&mut self) -> Gathered<I> {
        self.finish_as(I::from_wide)
    }

    /// [`WordGather::finish`] with each sum, divided, made an element of the ring `O` by
    /// `element`: a real gathering for Z\[i\] ([`IntegerRing::from_real_wide`]).
    pub(super) fn finish_as<O>(&mut self, element: impl Fn(I::Wide) -> O) -> Gathered<O> {
        let zero = I::Wide::default();
        let items = self.table.nonzero(zero);
        items.sort_unstable_by_key(|&(m, _)| std::cmp::Reverse(m));
        let mut g = 0u128;
        for (_, sum) in items.iter() {
            g = I::wide_gcd(g, sum);
            if g == 1 {
                break;
            }
        }
        // Every sum is below 2^127 in size, and so is their gcd.
        let mut divisor = (g as i128).max(1);
        if items
            .first()
            .is_some_and(|(_, sum)| I::wide_leading_sign(sum) < 0)
        {
            divisor = -divisor;
        }
        let mut exps = Vec::with_capacity(items.len() * K::WORDS);
        let mut coeffs = Vec::with_capacity(items.len());
        for &(m, sum) in items.iter() {
            m.store(&mut exps, K::WORDS);
            coeffs.push(element(match divisor {
                1 => sum,
                -1 => I::wide_scale(&sum, -1),
                d => I::wide_div_exact(&sum, d),
            }));
        }
        Gathered {
            exps,
            coeffs,
            divisor: Some(Integer::from_i128(divisor)),
        }
    }
}

/// Term products as ring elements, unsorted, with their monomials.
pub(super) struct Gather<K, I> {
    items: Vec<(K, I)>,
}

impl<K: Key, I: IntegerRing> Gather<K, I> {
    pub(super) fn with_capacity(n: usize) -> Self {
        Gather {
            items: Vec::with_capacity(n),
        }
    }

    /// Adds the term `a·b·k·m` (`k` is 1 or 2); always `true`.
    pub(super) fn push(&mut self, m: K, a: &I, b: &I, k: i64) -> bool {
        debug_assert!(k == 1 || k == 2);
        let p = a.mul(b);
        self.items.push((m, if k == 2 { p.add(&p) } else { p }));
        true
    }

    /// The terms sorted descending, equal monomials summed, zero sums dropped.
    pub(super) fn finish(mut self) -> Gathered<I> {
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
        Gathered {
            exps,
            coeffs,
            divisor: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Gathered, Heap, Inline, Smalls, Table, WordGather, INLINE, INLINE_SMALLS};
    use crate::number::{GaussianInteger, Integer, IntegerRing};

    type Sums = <Integer as IntegerRing>::Wide;

    /// `Σ c·m` over `terms`, gathered in a table of type `T`.
    fn gather<T: Table<[u64; 1], Sums>>(terms: &[(u64, i64)]) -> Gathered<Integer> {
        let budget = WordGather::<[u64; 1], Integer>::budget(64, terms.len()).expect("room");
        let mut sums = WordGather::<[u64; 1], Integer, T>::new(terms.len(), budget);
        for &(m, c) in terms {
            assert!(sums.push([m], &c, &1, 1, 0));
        }
        sums.finish()
    }

    fn parts(g: &Gathered<Integer>) -> (Vec<u64>, Vec<Integer>, Option<Integer>) {
        (g.exps.clone(), g.coeffs.clone(), g.divisor.clone())
    }

    #[test]
    fn inline_and_heap_tables_gather_the_same_sums() {
        // The most term products an inline table takes, on monomials that collide in its
        // slots (every one a multiple of 8), with sums that cancel and a common factor 2.
        let terms: Vec<(u64, i64)> = (0..INLINE as i64 - 1)
            .map(|i| {
                let c = match i {
                    4 => 3,
                    13 => -1,
                    22 => -2,
                    _ => 2 * i,
                };
                (8 * (i % 9) as u64, c)
            })
            .collect();
        let inline = gather::<Inline<_, _>>(&terms);
        let heap = gather::<Heap<_, _>>(&terms);
        assert_eq!(parts(&inline), parts(&heap));
        // Monomial 32 gathers 3 − 1 − 2 = 0 and is dropped; the others are divided by 2
        // and sorted descending.
        assert!(!inline.exps.contains(&32));
        assert_eq!(inline.exps, vec![64, 56, 48, 40, 24, 16, 8, 0]);
        assert_eq!(inline.divisor, Some(Integer::from(2)));
        // Monomial 0 gathers 2·(0 + 9 + 18 + 27) = 108, halved.
        assert_eq!(inline.coeffs.last(), Some(&Integer::from(54)));
    }

    #[test]
    fn a_multiplier_of_one_takes_a_bit_of_the_budget() {
        // No bit left for a multiplier: even 1 is refused (its product could pass the sums),
        // as 2 and −1 are; one bit left takes 1 and −1 but not 2.
        for (budget, k, fits) in [
            (0, 1, false),
            (0, -1, false),
            (0, 2, false),
            (1, 1, true),
            (1, -1, true),
            (1, 2, false),
        ] {
            let mut sums = WordGather::<[u64; 1], Integer, Heap<_, _>>::new(1, budget);
            assert_eq!(sums.push([7], &3, &5, k, 0), fits, "budget {budget}, k {k}");
            let expected = if fits { vec![7] } else { vec![] };
            assert_eq!(sums.finish().exps, expected, "budget {budget}, k {k}");
        }
    }

    #[test]
    fn smalls_hold_word_coefficients_inline_or_on_the_heap_and_refuse_wider_ones() {
        let ints = |n: i64| {
            (1..=n)
                .map(|k| Integer::from(k * (1 - 2 * (k % 2))))
                .collect::<Vec<_>>()
        };
        let mut smalls = Smalls::new();
        for n in [0, 1, INLINE_SMALLS as i64, INLINE_SMALLS as i64 + 1, 100] {
            let words: Vec<i64> = (1..=n).map(|k| k * (1 - 2 * (k % 2))).collect();
            assert_eq!(smalls.fill(&ints(n)), Some(&words[..]), "{n} coefficients");
        }
        // Past a word, inline and on the heap.
        let wide = Integer::from_i128(1 << 70);
        let mut short = ints(3);
        short.push(wide.clone());
        assert_eq!(smalls.fill(&short), None);
        let mut long = ints(40);
        long.push(wide);
        assert_eq!(smalls.fill(&long), None);
        // A Gaussian coefficient is two words.
        let z = GaussianInteger::new(Integer::from(2), Integer::from(-3));
        assert_eq!(Smalls::new().fill(&[z]), Some(&[(2, -3)][..]));
    }
}
