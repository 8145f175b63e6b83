//! A polynomial's integer coefficients, and how a long polynomial's are dropped: through a
//! [`Release`] (a run of one slab block's values gives its counts back at once), or a large
//! product's by the [`SlotCounts`] its builder took, with no pass over the values at all.

use std::hash::{Hash, Hasher};
use std::ops::Deref;

use crate::number::{IntegerRing, Release, SlotCounts};

/// Polynomials of at least this many terms drop their coefficients on the threads of the
/// caller's rayon pool.
pub(super) const PARALLEL_DROP_TERMS: usize = 1 << 20;

/// A polynomial of this many terms or more drops its coefficients through a [`Release`]:
/// those of a large product may lie in a [`WideSlab`](crate::number::WideSlab)'s blocks. A
/// shorter one drops them one by one, as most polynomials of a bracket or a tower are short
/// and have no value in a slot (W2(30) ran 0.8 % more instructions with `1 << 12`); a value
/// in a slot dropped alone gives its count back alone.
pub(super) const RELEASED_TERMS: usize = 1 << 14;

/// The coefficients of a polynomial's terms, read as a vector (`Deref`), changed only through
/// [`Coeffs::make_mut`] or taken out with [`Coeffs::into_vec`]. Each of those forgets the
/// [`SlotCounts`] a large product's builder took from its slab, which are good only while the
/// vector holds the values they count.
pub(crate) struct Coeffs<I: IntegerRing> {
    values: Vec<I>,
    /// Only for a vector of [`RELEASED_TERMS`] values or more, which the polynomial's drop
    /// gives to [`Coeffs::release`]: a short one is dropped one by one.
    slots: Option<Box<SlotCounts>>,
}

impl<I: IntegerRing> Coeffs<I> {
    /// `values`, dropped as any vector of their length is.
    pub(crate) fn new(values: Vec<I>) -> Self {
        Coeffs {
            values,
            slots: None,
        }
    }

    /// `values`, whose values in slots hold exactly the counts `slots` counts (a large
    /// product's builder filled a slab for them).
    ///
    /// # Safety
    ///
    /// The values of `values` in slots hold exactly the counts of `slots`, no more or fewer.
    pub(crate) unsafe fn counted(values: Vec<I>, slots: SlotCounts) -> Self {
        let keep = slots.can_release() && values.len() >= RELEASED_TERMS;
        Coeffs {
            values,
            slots: keep.then(|| Box::new(slots)),
        }
    }

    /// Whether it has its builder's counts, and will be dropped by them.
    #[cfg(test)]
    pub(crate) fn has_counts(&self) -> bool {
        self.slots.is_some()
    }

    /// The vector, to change: its counts are forgotten.
    pub(crate) fn make_mut(&mut self) -> &mut Vec<I> {
        drop(self.slots.take());
        &mut self.values
    }

    /// The vector, taken out.
    pub(crate) fn into_vec(mut self) -> Vec<I> {
        drop(self.slots.take());
        std::mem::take(&mut self.values)
    }

    /// The vector taken out, with its counts if it has them (to be given to
    /// [`Coeffs::counted`] with these values and others).
    pub(crate) fn into_counted(mut self) -> (Vec<I>, Option<SlotCounts>) {
        let slots = self.slots.take().map(|b| *b);
        (std::mem::take(&mut self.values), slots)
    }

    /// Drops the values of a vector of [`RELEASED_TERMS`] or more, on the pool's threads when
    /// there are millions; `exps`, the polynomial's monomials, goes back to the system on one
    /// thread meanwhile. Dropping a coefficient reads it and frees it if boxed: for a product of
    /// millions of terms (Pearce(12): 5.8 M coefficients, 2.0 M of them past a word) that is
    /// several milliseconds on one thread. The values in a slab's slots are given back a block
    /// at a time ([`Release`]), or with no pass at all by the builder's counts
    /// ([`SlotCounts`]).
    #[inline(never)]
    pub(crate) fn release(mut self, exps: Vec<u64>) {
        let values = std::mem::take(&mut self.values);
        if let Some(slots) = self.slots.take() {
            drop(exps);
            // SAFETY: the counts are exactly those of these values (`counted`), which
            // nothing has changed since (`make_mut` and `into_vec` forget the counts).
            return unsafe { slots.release(values) };
        }
        if values.len() >= PARALLEL_DROP_TERMS
            && rayon::current_thread_index().is_some()
            && rayon::current_num_threads() > 1
        {
            use rayon::prelude::*;
            rayon::join(
                || drop(exps),
                || {
                    values
                        .into_par_iter()
                        .with_min_len(PARALLEL_DROP_TERMS / 4)
                        .fold(Release::default, |mut release, c| {
                            c.release_into(&mut release);
                            release
                        })
                        .for_each(drop)
                },
            );
        } else {
            drop(exps);
            let mut release = Release::default();
            for c in values {
                c.release_into(&mut release);
            }
        }
    }
}

impl<I: IntegerRing> Default for Coeffs<I> {
    fn default() -> Self {
        Coeffs::new(Vec::new())
    }
}

impl<I: IntegerRing> Deref for Coeffs<I> {
    type Target = Vec<I>;
    fn deref(&self) -> &Vec<I> {
        &self.values
    }
}

/// A copy has no counts: a value in a slot is copied into a box of its own.
impl<I: IntegerRing> Clone for Coeffs<I> {
    fn clone(&self) -> Self {
        Coeffs::new(self.values.clone())
    }
}

impl<I: IntegerRing> PartialEq for Coeffs<I> {
    fn eq(&self, other: &Self) -> bool {
        self.values == other.values
    }
}

impl<I: IntegerRing + Hash> Hash for Coeffs<I> {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.values.hash(state);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::{Integer, WideSlab};

    /// Values past a word in a slab's slots, every third small, as a product's builder
    /// writes them, with the slab's counts.
    fn counted(n: i128) -> Coeffs<Integer> {
        let mut slab = WideSlab::new();
        let values = slab.filling(|| {
            (0..n)
                .map(|k| match k % 3 {
                    0 => Integer::from(k as i64),
                    _ => Integer::from_i128((1 << 64) + k),
                })
                .collect()
        });
        // SAFETY: the slab was filled for `values` alone, on this thread.
        unsafe { Coeffs::counted(values, slab.into_counts()) }
    }

    /// Coefficients with their builder's counts keep them only as they were written: a copy
    /// has none (its values are boxed), a change forgets them, and a vector taken out with
    /// them gives them to the next, as the parts of a product do. Every drop frees each
    /// block once: under Miri (`cargo +nightly miri test -p trigpoly --lib poly::coeffs`), a
    /// count given back twice is a read after a free, and one never given back a leak.
    #[test]
    fn counts_go_with_the_values_as_written() {
        let n = 20_000;
        let c = counted(n);
        assert!(c.slots.is_some());
        let copy = c.clone();
        assert!(copy.slots.is_none() && copy == c);
        c.release(Vec::new());
        assert_eq!(copy[n as usize - 1], Integer::from_i128((1 << 64) + n - 1));

        let mut changed = counted(n);
        let last = changed.make_mut().pop();
        assert!(changed.slots.is_none());
        assert_eq!(last, Some(Integer::from_i128((1 << 64) + n - 1)));
        drop(changed);
        drop(last);

        let (values, slots) = counted(n).into_counted();
        let (more, more_slots) = counted(n).into_counted();
        let mut all = slots.expect("counted");
        all.append(more_slots.expect("counted"));
        let mut both = values;
        both.extend(more);
        // SAFETY: the two parts' counts, of their values, all moved here.
        let both = unsafe { Coeffs::counted(both, all) };
        assert!(both.slots.is_some() && both.len() == 2 * n as usize);
        both.release(Vec::new());
        // Dropped without a release, its values give back their counts one by one.
        drop(counted(n));

        let taken = counted(n).into_vec();
        assert_eq!(taken.len(), n as usize);
    }
}
