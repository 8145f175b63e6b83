//! Dense multiplication on Kronecker indices (`kronecker.rs`), chunked over the output index
//! range. The inputs are sorted, so for each term of `a` (a row) the partners in `b` that land
//! in an output chunk form a contiguous run. A chunk of machine-word accumulators stays in the
//! L2 cache and is read back highest first, so the terms come out in order. On a sparse box a
//! byte per accumulator marks the touched ones and only those are read, and each chunk visits
//! only the rows with a product in it: every row waits in the list of the chunk of its next
//! product (a bucket queue), where a scan would pass over every row in every chunk. Used when
//! the box is not much larger than the work and every coefficient fits two machine words per
//! component (`Cells`): with coefficients of a word, the accumulators are `i128` per component
//! when every sum fits them (`Narrow`) and 192 bits otherwise (`Broad`); with coefficients of
//! two words, 192 bits (`Double`), when every sum fits them. Over Z\[i\], factors whose
//! coefficients are each real or imaginary take one real product a term pair (`AxialNarrow`,
//! `AxialBroad`, `AxialDouble`) where a Gaussian one takes four. Such products went to the
//! hashed method before.
//!
//! A square forms each pair of terms once: the row of term `i` takes the partners after it,
//! with its coefficient doubled, and the diagonal's `a_i²` is added to its chunk apart.
//!
//! When the caller's rayon pool has more than one thread, large products use a second core: on
//! a dense box they split the index range into parts that rayon runs on the pool's threads; on
//! a sparse box, where writing the terms (and backing their pages) costs as much as the
//! additions, one thread adds and reads back while a second one, spawned for the product,
//! decodes and writes the terms, so that they are written once. A large product's vectors
//! have their pages backed a window ahead of the writes (`pages.rs`), a system call per window
//! instead of a page fault per page.

use rayon::prelude::*;

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;

use super::coeffs::Coeffs;
use super::kronecker::{Cursor, Decoder, Kronecker};
use crate::error::AlgebraError;
use crate::number::{axial_product, Integer, IntegerRing, SlotCounts, Wide192, WideSlab};
use crate::pages;
use crate::placement;
use crate::varset::Layout;

/// Bytes of accumulators per chunk: half the L2 cache of a typical core.
const CHUNK_BYTES: usize = 1 << 18;
/// The largest box scanned, relative to the number of products.
const BOX_PER_PRODUCT: u64 = 32;
/// The fewest products a row's visit to a chunk must add, on average, for a box no larger than
/// the work to be scanned unmarked, every overlapping row visiting every chunk.
const PRODUCTS_PER_VISIT: u64 = 4;
/// Products below this many term pairs run as one part.
const PARALLEL_WORK: u64 = 1 << 18;
/// Parts per thread, so that unequal parts balance.
const PARTS_PER_THREAD: u64 = 4;
/// Sparse products of at least this many term pairs build their terms on a second thread.
const PIPELINE_WORK: u64 = 1 << 20;
/// Terms handed from the accumulating thread to the building one at a time.
const BATCH: usize = 1 << 16;
/// Terms read back from the accumulators before the builder writes them together (24 KB of
/// `i128` sums: they stay in the L1 cache until it writes them).
const READ_BATCH: usize = 1 << 10;
/// Batches on their way to the building thread before the accumulating one waits.
const BATCHES_IN_FLIGHT: usize = 4;
/// A product that may have this many terms has its vectors' pages backed ahead of its writes,
/// this many terms at a time (256 KB of each vector for one-word monomials).
const BACKED_TERMS: usize = 1 << 15;
/// A product with room for this many terms or more takes its coefficients' values past a
/// word from a [`WideSlab`], whose block (4 095 values) is small beside it.
const SLAB_TERMS: usize = 1 << 16;

/// Packed exponents and coefficients of a product, sorted descending.
pub(crate) type Product<I> = (Vec<u64>, Coeffs<I>);

/// What the accumulators of a dense product hold: exact sums of products of the factors'
/// coefficients of `I`, taken as `Factor`s, in cells of `Cell`.
trait Cells<I: IntegerRing> {
    /// A coefficient of a factor, in machine words.
    type Factor: Copy + Send + Sync;
    /// One accumulator.
    type Cell: Copy + Default + PartialEq + Send + Sync;
    /// The most bits of a sum's component that a cell holds.
    const BITS: u32;
    /// `cell += a·b`; the caller guarantees no overflow.
    fn add_mul(cell: &mut Self::Cell, a: &Self::Factor, b: &Self::Factor);
    /// The sum in a cell.
    fn value(cell: Self::Cell) -> I;
    /// The sums of `cells` appended to `coeffs` as coefficients, those past a word in the
    /// slots of `slab` when there is one.
    fn extend(coeffs: &mut Vec<I>, cells: &[(u64, Self::Cell)], slab: Option<&mut WideSlab>) {
        let values = cells.iter().map(|&(_, w)| Self::value(w));
        match slab {
            Some(slab) => slab.filling(|| coeffs.extend(values)),
            None => coeffs.extend(values),
        }
    }
}

/// Coefficients of a word per component, sums in `i128` ([`IntegerRing::Wide`]).
struct Narrow;

impl<I: IntegerRing> Cells<I> for Narrow {
    type Factor = I::Small;
    type Cell = I::Wide;
    const BITS: u32 = 126;
    #[inline(always)]
    fn add_mul(cell: &mut I::Wide, a: &I::Small, b: &I::Small) {
        I::wide_add_mul(cell, a, b);
    }
    #[inline(always)]
    fn value(cell: I::Wide) -> I {
        I::from_wide(cell)
    }
    /// Each value past a word placed straight in the slab this builder holds, with no
    /// thread-local lookup or call per value (step 146).
    fn extend(coeffs: &mut Vec<I>, cells: &[(u64, I::Wide)], slab: Option<&mut WideSlab>) {
        match slab {
            Some(slab) => {
                let mut place = |v| slab.place_integer(v);
                coeffs.extend(cells.iter().map(|&(_, w)| I::from_wide_with(w, &mut place)));
            }
            None => coeffs.extend(cells.iter().map(|&(_, w)| I::from_wide(w))),
        }
    }
}

/// Coefficients of a word per component, sums in 192 bits ([`IntegerRing::Broad`]): sums
/// that could pass `i128`.
struct Broad;

impl<I: IntegerRing> Cells<I> for Broad {
    type Factor = I::Small;
    type Cell = I::Broad;
    const BITS: u32 = Wide192::BITS;
    #[inline(always)]
    fn add_mul(cell: &mut I::Broad, a: &I::Small, b: &I::Small) {
        I::broad_add_mul(cell, a, b);
    }
    #[inline(always)]
    fn value(cell: I::Broad) -> I {
        I::from_broad(cell)
    }
}

/// Coefficients of two words per component ([`IntegerRing::Double`]), sums in 192 bits.
struct Double;

impl<I: IntegerRing> Cells<I> for Double {
    type Factor = I::Double;
    type Cell = I::Broad;
    const BITS: u32 = Wide192::BITS;
    #[inline(always)]
    fn add_mul(cell: &mut I::Broad, a: &I::Double, b: &I::Double) {
        I::double_add_mul(cell, a, b);
    }
    #[inline(always)]
    fn value(cell: I::Broad) -> I {
        I::from_broad(cell)
    }
}

/// Over Z\[i\], coefficients that are each real or imaginary (`(v, false)` for `v`,
/// `(v, true)` for `i·v`), in a word, summed in `i128` per component: `(i^e x)(i^f y) =
/// i^(e+f) xy` is one real product, added to the real sum for `e = f` (negated when both are
/// imaginary) and to the imaginary one otherwise ([`axial_product`]), where a Gaussian product
/// takes four.
struct AxialNarrow;

impl<I: IntegerRing> Cells<I> for AxialNarrow {
    type Factor = (i64, bool);
    type Cell = [i128; 2];
    const BITS: u32 = 126;
    #[inline(always)]
    fn add_mul(cell: &mut [i128; 2], a: &(i64, bool), b: &(i64, bool)) {
        // The product signed, not a factor (fewer instructions): a product of words fits
        // `i128` negated too (`|xy| ≤ 2¹²⁶`).
        let (part, p) = axial_product((i128::from(a.0) * i128::from(b.0), a.1), b.1);
        cell[part] += p;
    }
    #[inline(always)]
    fn value([re, im]: [i128; 2]) -> I {
        I::from_parts(Integer::from_i128(re), Integer::from_i128(im))
    }
}

/// Axial coefficients in a word, summed in 192 bits per component.
struct AxialBroad;

impl<I: IntegerRing> Cells<I> for AxialBroad {
    type Factor = (i64, bool);
    type Cell = [Wide192; 2];
    const BITS: u32 = Wide192::BITS;
    #[inline(always)]
    fn add_mul(cell: &mut [Wide192; 2], a: &(i64, bool), b: &(i64, bool)) {
        let (part, p) = axial_product((i128::from(a.0) * i128::from(b.0), a.1), b.1);
        cell[part].add(p);
    }
    #[inline(always)]
    fn value([re, im]: [Wide192; 2]) -> I {
        I::from_parts(re.to_integer(), im.to_integer())
    }
}

/// Axial coefficients in two words (above `i128::MIN`), summed in 192 bits per component.
struct AxialDouble;

impl<I: IntegerRing> Cells<I> for AxialDouble {
    type Factor = (i128, bool);
    type Cell = [Wide192; 2];
    const BITS: u32 = Wide192::BITS;
    #[inline(always)]
    fn add_mul(cell: &mut [Wide192; 2], a: &(i128, bool), b: &(i128, bool)) {
        let (part, x) = axial_product(*a, b.1);
        cell[part].add_mul_double(x, b.0);
    }
    /// As [`AxialBroad`]'s: the same sums.
    #[inline(always)]
    fn value(cell: [Wide192; 2]) -> I {
        <AxialBroad as Cells<I>>::value(cell)
    }
}

/// The coefficients of `a` and `b` in machine words (`word`, [`IntegerRing::to_small`] or
/// [`IntegerRing::to_double`], or an axial form) and the most bits of a sum of their products
/// (`bits` of a coefficient, each component of a product the sum of `products_per_component`
/// real ones), or `None` if one does not fit.
fn in_words<I: IntegerRing, F>(
    (a, b): (&[I], &[I]),
    word: impl Fn(&I) -> Option<F>,
    bits: impl Fn(&F) -> u32,
    products_per_component: u32,
) -> Option<(Vec<F>, Vec<F>, u32)> {
    let words = |v: &[I]| v.iter().map(&word).collect::<Option<Vec<_>>>();
    let (fa, fb) = (words(a)?, words(b)?);
    let bits = |v: &[F]| v.iter().map(&bits).max().unwrap_or(0);
    // A sum has at most as many products as the shorter factor has terms.
    let terms_bits = 64 - (a.len().min(b.len()) as u64).leading_zeros();
    let sum_bits = bits(&fa) + bits(&fb) + terms_bits + products_per_component;
    Some((fa, fb, sum_bits))
}

/// The product by the dense method, or `None` when the method does not apply (box too large
/// for the work, coefficients past two machine words, or sums past 192 bits).
///
/// A square (`square`: `a` and `b` are one polynomial) forms each pair of terms once: row `i`
/// takes its partners `j > i` with the coefficient `2 a_i`, and the diagonal's `a_i²` is added
/// to its chunk apart.
pub(crate) fn try_mul_dense<I: IntegerRing>(
    kron: &Kronecker,
    layout: &Layout,
    a: Terms<'_, I>,
    b: Terms<'_, I>,
    max_terms: usize,
    square: bool,
) -> Option<Result<Product<I>, AlgebraError>> {
    let (n, m) = (a.1.len(), b.1.len());
    let work = (n as u64).saturating_mul(m as u64);
    if kron.size() > work.saturating_mul(BOX_PER_PRODUCT) || kron.size() > 1 << 40 {
        return None;
    }
    let doubled: Vec<I>;
    let a = if square {
        doubled = a.1.iter().map(|c| c.add(c)).collect();
        (a.0, &doubled[..], a.2)
    } else {
        a
    };
    // Over Z[i], coefficients that are each real or imaginary take one real product a pair
    // where a Gaussian one takes four; each component of a product is one real product.
    if I::COMPLEX {
        let word = |c: &I| {
            let (v, imaginary) = c.to_real_or_imaginary()?;
            Some((i64::try_from(v).ok()?, imaginary))
        };
        let word_bits = |c: &(i64, bool)| 64 - c.0.unsigned_abs().leading_zeros();
        // Above `i128::MIN`, so that a product of two imaginary values may negate a factor.
        let double = |c: &I| c.to_real_or_imaginary().filter(|&(v, _)| v != i128::MIN);
        let double_bits = |c: &(i128, bool)| 128 - c.0.unsigned_abs().leading_zeros();
        let axial = in_cells::<I, AxialNarrow, AxialBroad, AxialDouble>(
            (kron, layout, max_terms, square),
            (a, b),
            ((word, word_bits), (double, double_bits)),
            1,
        );
        if axial.is_some() {
            return axial;
        }
    }
    in_cells::<I, Narrow, Broad, Double>(
        (kron, layout, max_terms, square),
        (a, b),
        ((I::to_small, I::small_bits), (I::to_double, I::double_bits)),
        I::PRODUCTS_PER_COMPONENT,
    )
}

/// The terms of a factor: packed exponents, coefficients, and each variable's exponent bounds.
type Terms<'a, I> = (&'a [u64], &'a [I], &'a [(i64, i64)]);

/// The dense product in the narrowest cells that hold every sum: `N` (`i128` sums) or `B`
/// (192 bits) for coefficients that each fit a word (`word`: a coefficient as `N`'s and `B`'s
/// factor, and its bits), else `D` for coefficients in two words (`double`); `None` if no
/// cell holds them.
fn in_cells<I: IntegerRing, N, B, D>(
    (kron, layout, max_terms, square): (&Kronecker, &Layout, usize, bool),
    (a, b): (Terms<'_, I>, Terms<'_, I>),
    (word, double): (
        (impl Fn(&I) -> Option<N::Factor>, impl Fn(&N::Factor) -> u32),
        (impl Fn(&I) -> Option<D::Factor>, impl Fn(&D::Factor) -> u32),
    ),
    products_per_component: u32,
) -> Option<Result<Product<I>, AlgebraError>>
where
    N: Cells<I>,
    B: Cells<I, Factor = N::Factor>,
    D: Cells<I>,
{
    let coefficients = (a.1, b.1);
    if let Some((fa, fb, sum_bits)) = in_words(coefficients, word.0, word.1, products_per_component)
    {
        return if sum_bits <= N::BITS {
            Some(mul_dense::<I, N>(
                kron,
                layout,
                a,
                b,
                (fa, fb),
                (max_terms, square),
            ))
        } else {
            (sum_bits <= B::BITS)
                .then(|| mul_dense::<I, B>(kron, layout, a, b, (fa, fb), (max_terms, square)))
        };
    }
    let (fa, fb, sum_bits) = in_words(coefficients, double.0, double.1, products_per_component)?;
    (sum_bits <= D::BITS)
        .then(|| mul_dense::<I, D>(kron, layout, a, b, (fa, fb), (max_terms, square)))
}

/// [`try_mul_dense`] in the cells `W`, which hold every sum; `words` are the coefficients of
/// `a` and `b` as `W`'s factors (of a square, `a`'s doubled).
fn mul_dense<I: IntegerRing, W: Cells<I>>(
    kron: &Kronecker,
    layout: &Layout,
    a: Terms<'_, I>,
    b: Terms<'_, I>,
    (words_a, words_b): (Vec<W::Factor>, Vec<W::Factor>),
    (max_terms, square): (usize, bool),
) -> Result<Product<I>, AlgebraError> {
    let (n, m) = (a.1.len(), b.1.len());
    let work = (n as u64).saturating_mul(m as u64);
    let fa = kron.indices(layout, a.0, a.2);
    let gb = kron.indices(layout, b.0, b.2);
    // Index range of the product.
    let (lo, end) = (fa[n - 1] + gb[m - 1], fa[0] + gb[0] + 1);
    // A chunk spans a cache's worth of accumulators, a power of two of them (a chunk's number
    // is then a shift away, `Factors::accumulate`), and at least 64, a whole number of the
    // words of eight marks that the read-back tests at once.
    // (The cells that fit, rounded down to a power of two: 24-byte cells would round up to
    // half as many bytes again.)
    let cells = 1u64 << (CHUNK_BYTES / std::mem::size_of::<W::Cell>()).ilog2();
    let chunk = cells.min(end - lo).next_power_of_two().max(64);
    let factors = Factors {
        fa,
        ca: words_a,
        partners: gb.into_iter().zip(words_b).collect(),
        square,
    };
    let decoder = kron.decoder(layout, work);
    let budget = TermBudget::new(max_terms);
    let span = factors.partners[0].0 - factors.partners[m - 1].0;
    let mark = marks(kron.size(), work, (n as u64, span), chunk);
    let threads = rayon::current_num_threads() as u64;
    // A sparse box: the terms are few per product, and writing them costs as much as adding
    // (page faults included). A second thread writes them while this one adds, so that the
    // terms are written once, by one thread.
    if mark && threads >= 2 && work >= PIPELINE_WORK {
        let mut acc = vec![W::Cell::default(); chunk as usize];
        return factors.pipelined::<I, W>(&mut acc, (lo, end), &decoder, &budget);
    }
    // The index range cut into parts, highest first.
    let count = if work < PARALLEL_WORK || threads < 2 {
        1
    } else {
        (threads * PARTS_PER_THREAD).min(end - lo)
    };
    let cut = |p: u64| lo + ((end - lo) as u128 * p as u128 / count as u128) as u64;
    let ranges: Vec<(u64, u64)> = (0..count).rev().map(|p| (cut(p), cut(p + 1))).collect();
    let parts: Vec<Product<I>> = ranges
        .into_par_iter()
        .map_init(
            || vec![W::Cell::default(); chunk as usize],
            |acc, (lo, hi)| {
                if mark {
                    factors.range::<I, W, true>(acc, (lo, hi), &decoder, &budget)
                } else {
                    factors.range::<I, W, false>(acc, (lo, hi), &decoder, &budget)
                }
            },
        )
        .collect::<Result<_, _>>()?;
    // The parts together kept to the term limit.
    let total: usize = parts.iter().map(|(_, c)| c.len()).sum();
    if parts.len() == 1 {
        return Ok(parts.into_iter().next().expect("one part"));
    }
    let mut exps = Vec::with_capacity(total * layout.words);
    let mut coeffs = Vec::with_capacity(total);
    // The parts' counts of their slab's blocks, if every part has them.
    let mut slots = Some(SlotCounts::default());
    for (e, c) in parts {
        exps.extend_from_slice(&e);
        let (values, counts) = c.into_counted();
        coeffs.extend(values);
        slots = slots.zip(counts).map(|(mut all, part)| {
            all.append(part);
            all
        });
    }
    let coeffs = match slots {
        // SAFETY: each part's counts are exactly those of its values, all moved here, none
        // dropped.
        Some(slots) => unsafe { Coeffs::counted(coeffs, slots) },
        None => Coeffs::new(coeffs),
    };
    Ok((exps, coeffs))
}

/// Whether a product whose box has `cells` accumulators, of `work` term pairs, takes marks:
/// `rows` rows whose partners span `span` indices, in chunks of `chunk` accumulators. Marking
/// costs a little per product, scanning a little per accumulator. Unmarked, every row visits
/// every chunk its partners' span overlaps, and every accumulator is read back: a square of
/// 92 755 terms whose box (6.0·10⁹ cells) was smaller than its work (8.6·10⁹ term pairs) made
/// 6.7·10¹⁰ visits of rows to 1.5 M chunks, mostly to add nothing, and read back 6·10⁹
/// accumulators for 2.1 M terms: 100 s, where marked it took 42 s (20 s since a square forms
/// each pair once).
fn marks(cells: u64, work: u64, (rows, span): (u64, u64), chunk: u64) -> bool {
    let visits = rows.saturating_mul(span / chunk + 1);
    cells > work || visits > work / PRODUCTS_PER_VISIT
}

/// The term limit of a product, shared by its parts: each part counts the terms of every chunk
/// it reads back, so that a product split over threads stops once its parts together pass the
/// limit, not once one of them does.
struct TermBudget {
    limit: usize,
    used: AtomicUsize,
}

impl TermBudget {
    fn new(limit: usize) -> Self {
        TermBudget {
            limit,
            used: AtomicUsize::new(0),
        }
    }

    /// Counts `terms` more, or the error once the parts together hold more than the limit.
    fn count(&self, terms: usize) -> Result<(), AlgebraError> {
        let used = self
            .used
            .fetch_add(terms, Ordering::Relaxed)
            .saturating_add(terms);
        if used > self.limit {
            Err(AlgebraError::TooManyTerms { limit: self.limit })
        } else {
            Ok(())
        }
    }
}

/// The end of a list of rows.
const NONE: usize = usize::MAX;

/// The two factors as Kronecker indices (descending) and machine-word coefficients: the
/// rows of the first apart, the partners of the second each with its coefficient beside its
/// index, which the kernel's loop reads together (one stream, not two: Pearce(12) −5 %,
/// Fateman(20) −10 %, step 130).
struct Factors<S> {
    fa: Vec<u64>,
    ca: Vec<S>,
    partners: Vec<(u64, S)>,
    /// Whether the factors are one polynomial, `ca` its coefficients doubled: row `i` takes
    /// the partners after its own term, and the diagonal (each partner by itself) is added
    /// apart.
    square: bool,
}

impl<S: Copy + Send + Sync> Factors<S> {
    /// A row's products from its next partner down to `bottom`, added into the chunk's
    /// accumulators (offset from `bottom`, marked with `MARK`); moves the row on past them.
    #[inline(always)]
    fn add_row<I: IntegerRing, W: Cells<I, Factor = S>, const MARK: bool>(
        &self,
        (fi, ai, next): (u64, S, &mut usize),
        bottom: u64,
        acc: &mut [W::Cell],
        touched: &mut [u8],
    ) {
        let j = *next;
        // The accumulator of partner `g` is at `g + fi − bottom`, which wraps past the chunk's
        // width at the first partner below `bottom`: the run ends there. Every partner from
        // `j` on lies below the chunk's top, as the chunks above have taken theirs. One
        // compare per product, which also shows the compiler the index in bounds, where a
        // galloping search for the run's end before the loop cost a tenth of the kernel's
        // time on Pearce(12)'s short runs (step 120).
        let shift = fi.wrapping_sub(bottom);
        let width = acc.len() as u64;
        // A byte per accumulator: one plain store a product. A bit each (a bitmap 8 times
        // smaller to scan) needed the word's read-modify-write, or, kept in a register for
        // the run, a test and a flush at every change of word: 6 more instructions a
        // product, and Pearce(12) 4 % slower (step 133). The marks cut to the accumulators'
        // length, so that the offset tested against `width` needs no second bounds check.
        let touched = &mut touched[..if MARK { acc.len() } else { 0 }];
        let mut run = 0;
        for (g, c) in &self.partners[j..] {
            let off = g.wrapping_add(shift);
            if off >= width {
                break;
            }
            let off = off as usize;
            run += 1;
            W::add_mul(&mut acc[off], &ai, c);
            if MARK {
                touched[off] = 1;
            }
        }
        *next = j + run;
    }

    /// [`Factors::add_row`] with marks, out of line: a sparse chunk's rows (the lists of
    /// `accumulate`) call it once a row, and its loop then keeps the accumulators, the marks
    /// and the partners' end in registers, where inlined into `accumulate` all three were
    /// reloaded from the stack at every product (step 145: Pearce(12) 3–5 % faster).
    #[inline(never)]
    fn add_marked_row<I: IntegerRing, W: Cells<I, Factor = S>>(
        &self,
        row: (u64, S, &mut usize),
        bottom: u64,
        acc: &mut [W::Cell],
        touched: &mut [u8],
    ) {
        self.add_row::<I, W, true>(row, bottom, acc, touched);
    }

    /// For each row, its first partner whose product lies below `hi` (partners are visited in
    /// descending index order, as the chunks are).
    fn first_partners(&self, hi: u64) -> Vec<usize> {
        let partners = &self.partners;
        let after = |i: usize| if self.square { i + 1 } else { 0 };
        self.fa
            .iter()
            .enumerate()
            .map(|(i, &fi)| {
                partners
                    .partition_point(|&(g, _)| fi + g >= hi)
                    .max(after(i))
            })
            .collect()
    }

    /// Of a square, the first row whose diagonal product `2 f_i` lies below `hi`; the rows'
    /// number (none) otherwise.
    fn first_diagonal(&self, hi: u64) -> usize {
        match self.square {
            true => self.fa.partition_point(|&fi| 2 * fi >= hi),
            false => self.fa.len(),
        }
    }

    /// The most terms the product of the indices in `[lo, hi)` can have (one per product and
    /// one per index), and at most one more than the term limit; `next` from
    /// [`Factors::first_partners`].
    fn bound(&self, next: &[usize], (lo, hi): (u64, u64), max_terms: usize) -> usize {
        let partners = &self.partners;
        let products: usize = self
            .fa
            .iter()
            .zip(next)
            .map(|(&fi, &j)| {
                partners
                    .partition_point(|&(g, _)| fi + g >= lo)
                    .saturating_sub(j)
            })
            .sum();
        // A square's diagonal products in the range.
        let diagonal = self.first_diagonal(lo) - self.first_diagonal(hi);
        let products = products + diagonal;
        (products as u64).min(hi - lo).min(max_terms as u64 + 1) as usize
    }

    /// The terms of the product with indices in `[lo, hi)`, descending, as packed monomials,
    /// built on this thread.
    fn range<I: IntegerRing, W: Cells<I, Factor = S>, const MARK: bool>(
        &self,
        acc: &mut [W::Cell],
        (lo, hi): (u64, u64),
        decoder: &Decoder,
        budget: &TermBudget,
    ) -> Result<Product<I>, AlgebraError> {
        let next = self.first_partners(hi);
        let mut builder = Builder::<I, W>::new(decoder, self.bound(&next, (lo, hi), budget.limit));
        self.accumulate::<I, W, MARK>(acc, next, (lo, hi), budget, &mut builder)?;
        Ok(builder.finish())
    }

    /// [`Factors::range`] with the terms built on a second thread: this one adds into the
    /// accumulators and reads them back, the other turns the sums into coefficients (a box
    /// for each past a word), decodes the indices and writes the product, whose pages are
    /// backed as it writes them (page faults cost as much as the additions on a large sparse
    /// product). The boxes are freed later by another thread: the binary sets mimalloc to
    /// reclaim the pages of the ended building thread on a free, so that those frees are
    /// local (`superint::allocator::configure`); without that, converting on this thread is
    /// as fast.
    fn pipelined<I: IntegerRing, W: Cells<I, Factor = S>>(
        &self,
        acc: &mut [W::Cell],
        (lo, hi): (u64, u64),
        decoder: &Decoder,
        budget: &TermBudget,
    ) -> Result<Product<I>, AlgebraError> {
        let next = self.first_partners(hi);
        let bound = self.bound(&next, (lo, hi), budget.limit);
        let (full, batches) = mpsc::sync_channel::<Vec<(u64, W::Cell)>>(BATCHES_IN_FLIGHT);
        let (emptied, empties) = mpsc::channel::<Vec<(u64, W::Cell)>>();
        std::thread::scope(|scope| {
            let spawned = std::thread::Builder::new().spawn_scoped(scope, move || {
                // Beside this thread, not on its processor if it is pinned to one.
                placement::run_beside_creator();
                let mut builder = Builder::<I, W>::new(decoder, bound);
                for mut batch in batches {
                    builder.append(&batch);
                    batch.clear();
                    // The accumulating side may have finished; then the batch is dropped.
                    let _ = emptied.send(batch);
                }
                builder.finish()
            });
            let Ok(building) = spawned else {
                // No thread to be had: the terms are built on this one.
                return self.range::<I, W, true>(acc, (lo, hi), decoder, budget);
            };
            let mut sender = Sender {
                batch: Vec::with_capacity(BATCH),
                sent: 0,
                full,
                empties,
            };
            let added = self.accumulate::<I, W, true>(acc, next, (lo, hi), budget, &mut sender);
            if added.is_ok() && !sender.batch.is_empty() {
                sender.flush();
            }
            // The building side ends when the channel closes.
            drop(sender);
            let built = building
                .join()
                .unwrap_or_else(|panic| std::panic::resume_unwind(panic));
            added.map(|()| built)
        })
    }

    /// Adds the products with indices in `[lo, hi)` into the accumulators, chunk by chunk
    /// (a chunk is as wide as `acc`), starting each row at its partner in `next` (from
    /// [`Factors::first_partners`]), and passes each nonzero sum to `sink` with its index,
    /// highest first. With `MARK`, a byte each marks the touched accumulators and only those
    /// are read back, and each chunk visits only the rows with a product in it; without, every
    /// accumulator of a chunk is read back.
    fn accumulate<I: IntegerRing, W: Cells<I, Factor = S>, const MARK: bool>(
        &self,
        acc: &mut [W::Cell],
        mut next: Vec<usize>,
        (lo, hi): (u64, u64),
        budget: &TermBudget,
        sink: &mut impl Sink<W::Cell>,
    ) -> Result<(), AlgebraError> {
        let (fa, ca, partners) = (&self.fa, &self.ca, &self.partners);
        let (n, m) = (fa.len(), partners.len());
        let (g_max, g_min) = (partners[0].0, partners[m - 1].0);
        let chunk = acc.len() as u64;
        let zero = W::Cell::default();
        let mut touched = vec![0u8; if MARK { chunk as usize } else { 0 }];
        // `next[i]`: the first partner of row `i` not yet multiplied.
        // Sparse: `waiting[c]` starts the list of the rows whose next product falls in chunk
        // `c` (counted from the top), linked through `then`. Dense: rows before `first` land
        // above every remaining chunk, and the others are scanned in order.
        // The chunk's width is a power of two: a shift, where a division took 15 cycles a row
        // and chunk.
        debug_assert!(chunk.is_power_of_two());
        let chunk_bits = chunk.trailing_zeros();
        let chunk_of = |k: u64| ((hi - 1 - k) >> chunk_bits) as usize;
        let mut waiting = vec![
            NONE;
            if MARK {
                (hi - lo).div_ceil(chunk) as usize
            } else {
                0
            }
        ];
        let mut then = vec![NONE; if MARK { n } else { 0 }];
        // Row `i`, whose next partner is `j`, waits in the chunk of that product, if it has one
        // in the range.
        let wait = |waiting: &mut [usize], then: &mut [usize], i: usize, j: usize| {
            if let Some(k) = partners
                .get(j)
                .map(|&(g, _)| fa[i] + g)
                .filter(|&k| k >= lo)
            {
                then[i] = std::mem::replace(&mut waiting[chunk_of(k)], i);
            }
        };
        if MARK {
            for (i, &j) in next.iter().enumerate().rev() {
                wait(&mut waiting, &mut then, i, j);
            }
        }
        let mut first = fa.partition_point(|&fi| fi + g_min >= hi);
        // A square's next diagonal product, `2 f_d`, to be added in its chunk.
        let mut diagonal = self.first_diagonal(hi);
        let mut top = hi;
        let mut current = 0;
        // The terms of this range counted in the budget so far.
        let mut counted = 0;
        while top > lo {
            let bottom = top.saturating_sub(chunk).max(lo);
            // Whether a row has products in this chunk. A sparse box has many chunks that no
            // product reaches (Pearce(12): 13 045 of 19 257), whose marks need no scan.
            let mut reached = if MARK {
                let mut row = std::mem::replace(&mut waiting[current], NONE);
                let reached = row != NONE;
                while row != NONE {
                    let i = row;
                    row = then[i];
                    self.add_marked_row::<I, W>(
                        (fa[i], ca[i], &mut next[i]),
                        bottom,
                        acc,
                        &mut touched,
                    );
                    wait(&mut waiting, &mut then, i, next[i]);
                }
                reached
            } else {
                while first < n && fa[first] + g_min >= top {
                    first += 1;
                }
                for i in first..n {
                    if fa[i] + g_max < bottom {
                        break;
                    }
                    self.add_row::<I, W, MARK>(
                        (fa[i], ca[i], &mut next[i]),
                        bottom,
                        acc,
                        &mut touched,
                    );
                }
                true
            };
            // A square's diagonal products in this chunk: the partners by themselves.
            while diagonal < n && 2 * fa[diagonal] >= bottom {
                let (g, c) = &partners[diagonal];
                let off = (2 * g - bottom) as usize;
                W::add_mul(&mut acc[off], c, c);
                if MARK {
                    touched[off] = 1;
                }
                reached = true;
                diagonal += 1;
            }
            // Read the accumulators back, highest index first.
            let mut read = |off: usize| {
                let slot = std::mem::take(&mut acc[off]);
                if slot != zero {
                    sink.push(bottom + off as u64, slot);
                }
            };
            if !MARK {
                (0..(top - bottom) as usize).rev().for_each(read);
            } else if reached {
                for (w, bytes) in touched.chunks_exact_mut(8).enumerate().rev() {
                    let mut marks = u64::from_le_bytes(bytes.try_into().expect("8 bytes"));
                    if marks == 0 {
                        continue;
                    }
                    bytes.fill(0);
                    while marks != 0 {
                        let byte = (63 - marks.leading_zeros() as usize) / 8;
                        marks &= !(0xff << (8 * byte));
                        read(w * 8 + byte);
                    }
                }
            }
            sink.end_chunk();
            current += 1;
            budget.count(sink.len() - counted)?;
            counted = sink.len();
            top = bottom;
        }
        Ok(())
    }
}

/// Where the terms of a product go as the accumulators are read back. Both sinks collect
/// the terms in batches: the builder writes each batch out in two loops of known length, the
/// sender hands it to the building thread.
trait Sink<C> {
    /// The term with Kronecker index `k` and sum `w`, lower than every term before it.
    fn push(&mut self, k: u64, w: C);
    /// A chunk has been read back: [`Sink::len`] counts every term pushed so far.
    fn end_chunk(&mut self);
    /// How many terms have come.
    fn len(&self) -> usize;
}

/// The terms of a product, written as they come: indices decoded to packed monomials,
/// accumulators to coefficients.
struct Builder<'d, I: IntegerRing, W: Cells<I>> {
    decoder: &'d Decoder,
    cursor: Cursor,
    exps: Vec<u64>,
    coeffs: Vec<I>,
    /// Terms pushed as a [`Sink`] and not yet written, at most [`READ_BATCH`] of them: the
    /// monomials and the coefficients of a batch are written by a loop each, where writing
    /// each term as it was read kept the vectors' lengths and ends on the stack between the
    /// reads (Pearce(12): 1.8 % of the instructions).
    found: Vec<(u64, W::Cell)>,
    /// The number of terms at which the vectors' next [`BACKED_TERMS`] pages' worth are
    /// backed before they are written (`pages.rs`), which saves most of a page fault's cost
    /// per page; `usize::MAX` (never) unless the product is large enough that the window past
    /// its last term, backed but unused, is small beside it.
    back_at: usize,
    /// Where the coefficients' values past a word go, for a large product; its counts
    /// ([`SlotCounts`]) go with the product, which is then dropped a block at a time.
    slab: Option<WideSlab>,
}

impl<'d, I: IntegerRing, W: Cells<I>> Builder<'d, I, W> {
    /// Room for `bound` terms. A part has at most one term per product and per index:
    /// reserving that much up front costs address space only (pages are backed when
    /// written), where growing by doubling would copy and fault in the terms about twice
    /// over. If the address space is refused, the vectors grow as usual.
    fn new(decoder: &'d Decoder, bound: usize) -> Self {
        let (mut exps, mut coeffs) = (Vec::new(), Vec::new());
        if exps.try_reserve_exact(bound * decoder.words()).is_err()
            || coeffs.try_reserve_exact(bound).is_err()
        {
            (exps, coeffs) = (Vec::new(), Vec::new());
        }
        Builder {
            decoder,
            cursor: decoder.cursor(),
            back_at: if coeffs.capacity() >= 4 * BACKED_TERMS {
                0
            } else {
                usize::MAX
            },
            slab: (coeffs.capacity() >= SLAB_TERMS).then(WideSlab::new),
            exps,
            coeffs,
            found: Vec::new(),
        }
    }

    /// Appends the terms (Kronecker index and sum), descending and lower than every term so
    /// far, each window of [`BACKED_TERMS`] backed before it is written.
    fn append(&mut self, mut terms: &[(u64, W::Cell)]) {
        while !terms.is_empty() {
            if self.coeffs.len() == self.back_at {
                pages::back_spare(&mut self.exps, BACKED_TERMS * self.decoder.words());
                pages::back_spare(&mut self.coeffs, BACKED_TERMS);
                self.back_at += BACKED_TERMS;
            }
            // Up to the end of the backed window (everything, when nothing is backed).
            let room = self.back_at.saturating_sub(self.coeffs.len());
            let (now, later) = terms.split_at(room.min(terms.len()));
            let (decoder, cursor) = (self.decoder, &mut self.cursor);
            // A slice's map has a known length: each `extend` reserves once and writes
            // without a check per term.
            if decoder.words() == 1 {
                let monomial = |&(k, _): &(u64, W::Cell)| decoder.decode_word(cursor, k);
                self.exps.extend(now.iter().map(monomial));
            } else {
                for &(k, _) in now {
                    decoder.decode_onto(cursor, k, &mut self.exps);
                }
            }
            W::extend(&mut self.coeffs, now, self.slab.as_mut());
            terms = later;
        }
    }

    /// Writes the terms pushed as a [`Sink`] (their buffer kept for the next ones).
    fn write_found(&mut self) {
        let found = std::mem::take(&mut self.found);
        self.append(&found);
        self.found = found;
        self.found.clear();
    }

    fn finish(self) -> Product<I> {
        debug_assert!(self.found.is_empty(), "every chunk's terms are written");
        let coeffs = match self.slab {
            // SAFETY: the slab was filled or placed in only by the writes of `coeffs`
            // (`append`, through `Cells::extend`), on this thread, and the values made there
            // went into `coeffs` or were dropped; so its counts are those of `coeffs`' values,
            // which nothing has changed since.
            Some(slab) => unsafe { Coeffs::counted(self.coeffs, slab.into_counts()) },
            None => Coeffs::new(self.coeffs),
        };
        (self.exps, coeffs)
    }
}

impl<I: IntegerRing, W: Cells<I>> Sink<W::Cell> for Builder<'_, I, W> {
    #[inline(always)]
    fn push(&mut self, k: u64, w: W::Cell) {
        self.found.push((k, w));
        if self.found.len() == READ_BATCH {
            self.write_found();
        }
    }

    fn end_chunk(&mut self) {
        self.write_found();
    }

    fn len(&self) -> usize {
        self.coeffs.len() + self.found.len()
    }
}

/// The accumulating side of a pipelined product: sums with their indices in batches, sent to
/// the building thread, whose emptied batches come back for reuse.
struct Sender<C> {
    batch: Vec<(u64, C)>,
    sent: usize,
    full: mpsc::SyncSender<Vec<(u64, C)>>,
    empties: mpsc::Receiver<Vec<(u64, C)>>,
}

impl<C> Sender<C> {
    /// Sends the batch, and takes an emptied one (or a new one) in its place.
    fn flush(&mut self) {
        let next = self
            .empties
            .try_recv()
            .unwrap_or_else(|_| Vec::with_capacity(BATCH));
        let batch = std::mem::replace(&mut self.batch, next);
        self.sent += batch.len();
        // A send fails only if the building side has panicked, which `join` passes on.
        let _ = self.full.send(batch);
    }
}

impl<C> Sink<C> for Sender<C> {
    #[inline(always)]
    fn push(&mut self, k: u64, w: C) {
        self.batch.push((k, w));
        if self.batch.len() == BATCH {
            self.flush();
        }
    }

    fn end_chunk(&mut self) {}

    fn len(&self) -> usize {
        self.sent + self.batch.len()
    }
}

#[cfg(test)]
mod tests {
    use super::marks;

    /// The shapes the choice was measured on: Fateman(20) (a box of 2.8 M cells for 1.1·10⁸
    /// term pairs, 125 products a row's visit) is scanned; Pearce(12) (a box 8 times its work)
    /// and the square of a 92 755-term Laplace–Runge–Lenz component (a box smaller than its
    /// work, but 0.13 products a visit) are marked.
    #[test]
    fn sparse_boxes_and_scattered_rows_take_marks() {
        assert!(!marks(2_825_761, 112_911_876, (10_626, 1_378_420), 16_384));
        assert!(marks(319_873_225, 38_291_344, (6_188, 262_909_500), 16_384));
        assert!(marks(
            5_981_302_845,
            8_603_490_025,
            (92_755, 2_942_653_752),
            4_096
        ));
    }
}
