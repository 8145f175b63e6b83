//! The one-word representation of [`Integer`] and the `unsafe` code it takes: the tagged word,
//! the boxes and the slots of a [`WideSlab`], and [`Release`] and [`SlotCounts`], which give
//! slots back a block at a time.

use std::alloc::{alloc, dealloc, handle_alloc_error, Layout};
use std::cell::Cell;
use std::num::NonZeroUsize;
use std::ptr::NonNull;
use std::sync::atomic::{fence, AtomicUsize, Ordering};

use num_bigint::BigInt;

use super::IntegerView;

/// An exact integer in one word: a 63-bit value tagged by a low bit of one, or a pointer
/// to an `i128` in a box of its own (low bits `000`) or in a slot of a `WideSlab`'s
/// block, plus four (low bits `100`), or to a boxed `BigInt`, plus two (low bits `10`);
/// the alignment of all three leaves the three low bits of their addresses zero.
///
/// Invariant: an `i128` never holds a value of 63 bits, and a boxed `BigInt` never one
/// that fits in `i128`.
///
/// ```
/// use trigpoly::Integer;
/// let big = Integer::from(i64::MAX) + Integer::from(1);
/// assert_eq!(big.to_string(), "9223372036854775808");
/// assert_eq!(big - Integer::from(1), Integer::from(i64::MAX));
/// ```
pub struct Integer {
    /// `2v + 1` for a small value `v` (an address without provenance), or the box.
    word: NonNull<u8>,
}

/// The low bit that marks a small value.
const SMALL: usize = 1;
/// The offset that marks a pointer to a `BigInt`.
const BIG: usize = 2;
/// The offset that marks a pointer to a slot of a [`WideSlab`]'s block.
const SLOT: usize = 4;

/// An `i128` where its pointer leaves the three tag bits free, on every target.
#[repr(C, align(16))]
struct Wide(i128);

const _: () = assert!(std::mem::align_of::<BigInt>() >= 4);

// SAFETY: an `Integer` owns its box, if it has one, as a `Box<i128>` or `Box<BigInt>`
// would, and never shares it (`Clone` copies it); both are `Send` and `Sync`. A slot is
// owned likewise, and its block is given back by an atomic count, from any thread.
unsafe impl Send for Integer {}
// SAFETY: as for `Send`: `&Integer` only reads the box.
unsafe impl Sync for Integer {}

impl Integer {
    /// The smallest value held in the word.
    pub(crate) const SMALL_MIN: i64 = -(1 << 62);
    /// The largest value held in the word.
    pub(crate) const SMALL_MAX: i64 = (1 << 62) - 1;

    /// `v`, which must lie in `[SMALL_MIN, SMALL_MAX]`, in the word.
    #[inline(always)]
    pub(crate) const fn small_unchecked(v: i64) -> Integer {
        debug_assert!(Integer::SMALL_MIN <= v && v <= Integer::SMALL_MAX);
        let tagged = ((v << 1) as usize) | SMALL;
        match NonZeroUsize::new(tagged) {
            // The tag bit makes it nonzero.
            Some(nonzero) => Integer {
                word: NonNull::without_provenance(nonzero),
            },
            None => unreachable!(),
        }
    }

    /// `v` in a slot of the slab this thread is [filling](WideSlab::filling), else in
    /// a box; `v` must be outside the word's range.
    #[inline(never)]
    pub(super) fn wide(v: i128) -> Integer {
        let word = match FILLING.get() {
            // SAFETY: `FILLING` points to the slab of a `filling` call on this thread,
            // which holds it mutably borrowed until it clears `FILLING` again.
            Some(mut slab) => unsafe { slab.as_mut().place(v) },
            None => NonNull::from(Box::leak(Box::new(Wide(v)))).cast::<u8>(),
        };
        Integer { word }
    }

    /// `b` in a box; `b` must be outside `i128`'s range.
    pub(super) fn big(b: BigInt) -> Integer {
        if let Some(mut slab) = FILLING.get() {
            // SAFETY: as in `wide`: the slab of a `filling` call on this thread.
            unsafe { slab.as_mut().boxed = true };
        }
        // SAFETY: a `BigInt` is larger than `BIG` bytes, so the tagged pointer stays
        // inside its allocation (and is not null).
        let word = unsafe {
            NonNull::from(Box::leak(Box::new(b)))
                .cast::<u8>()
                .byte_add(BIG)
        };
        Integer { word }
    }

    /// The value in the word, if it is held there.
    #[inline(always)]
    pub fn small(&self) -> Option<i64> {
        let w = self.word.addr().get();
        (w & SMALL != 0).then_some((w as i64) >> 1)
    }

    /// The value, read.
    #[inline(always)]
    pub fn view(&self) -> IntegerView<'_> {
        let w = self.word.addr().get();
        if w & SMALL != 0 {
            IntegerView::Small((w as i64) >> 1)
        } else if w & BIG == 0 {
            // SAFETY: the pointer from `Box::leak` of a `Wide` in `wide`, to a box this
            // `Integer` owns, or to a slot of a block plus `SLOT`, which this `Integer`
            // owns and whose block its count keeps alive; either lives as long as it does.
            IntegerView::Wide(unsafe { self.word.byte_sub(w & SLOT).cast::<Wide>().as_ref().0 })
        } else {
            // SAFETY: the pointer from `Box::leak` of a `BigInt` in `big`, plus `BIG`;
            // the box is owned by this `Integer` and lives as long as it does.
            IntegerView::Big(unsafe { self.word.byte_sub(BIG).cast::<BigInt>().as_ref() })
        }
    }

    /// Whether two values are the same word: equal small values (boxed ones never share
    /// a word, so a `false` says nothing).
    #[inline(always)]
    pub(super) fn same_word(&self, other: &Integer) -> bool {
        self.word == other.word
    }
}

impl Drop for Integer {
    #[inline]
    fn drop(&mut self) {
        let w = self.word.addr().get();
        if w & SMALL != 0 {
            return;
        }
        // SAFETY: the pointers from `Box::leak` in `wide` and `big` (less `BIG` for a `BigInt`),
        // owned by this `Integer` alone and freed once, here; or a slot, whose count in
        // its block this `Integer` holds and gives back once, here.
        unsafe {
            if w & BIG != 0 {
                drop(Box::from_raw(
                    self.word.byte_sub(BIG).cast::<BigInt>().as_ptr(),
                ));
            } else if w & SLOT != 0 {
                give_back(self.block(), 1);
            } else {
                drop(Box::from_raw(self.word.cast::<Wide>().as_ptr()));
            }
        }
    }
}

/// The slots of a block, for the tests.
#[cfg(test)]
pub(super) const SLOTS_PER_BLOCK: usize = SLOTS;

impl Integer {
    /// Whether the value lies in a slot of a slab's block.
    #[cfg(test)]
    pub(super) fn in_slot(&self) -> bool {
        self.word.addr().get() & (SMALL | BIG | SLOT) == SLOT
    }

    /// The block of a value in a slot (tagged `SLOT`): its address with the low bits of
    /// the block cleared.
    #[inline(always)]
    fn block(&self) -> NonNull<Header> {
        let w = self.word.addr().get();
        debug_assert_eq!(w & (SMALL | BIG | SLOT), SLOT);
        // SAFETY: the slot lies in its block, which starts `w mod BLOCK_BYTES` bytes
        // before the tagged address (blocks are aligned to their size).
        unsafe { self.word.byte_sub(w & (BLOCK_BYTES - 1)).cast::<Header>() }
    }
}

/// The bytes of a [`WideSlab`]'s block, which is aligned to them: a slot's block is its
/// address with the low bits cleared. 64 KiB: a block's header is one slot in 4 096, and
/// a block one of some 500 for Pearce(12)'s 2 M values past a word.
const BLOCK_BYTES: usize = 1 << 16;

/// The slots of a block, after its header (which takes the first slot's place).
const SLOTS: usize = BLOCK_BYTES / std::mem::size_of::<Wide>() - 1;

/// The start of a block: how many of its slots hold a value that is alive, plus those
/// that its slab has not handed out yet. The block is freed when that reaches zero.
#[repr(C, align(16))]
struct Header {
    live: AtomicUsize,
}

fn block_layout() -> Layout {
    match Layout::from_size_align(BLOCK_BYTES, BLOCK_BYTES) {
        Ok(layout) => layout,
        Err(_) => unreachable!("a power of two below isize::MAX"),
    }
}

/// Gives back `n` counts of the block at `header`, and frees it with the last.
///
/// # Safety
///
/// The caller holds `n` of the block's counts (values in its slots, or slots not handed
/// out), and uses none of them afterwards.
unsafe fn give_back(header: NonNull<Header>, n: usize) {
    // SAFETY: the block is alive while the caller holds a count of it.
    let live = unsafe { &header.as_ref().live };
    // Release, then acquire before the free: every use of a slot by a thread that gave its
    // count back happens before the block is freed (as `Arc` does it).
    if live.fetch_sub(n, Ordering::Release) == n {
        fence(Ordering::Acquire);
        // SAFETY: allocated in `WideSlab::refill` with this layout; no count is left.
        unsafe { dealloc(header.as_ptr().cast::<u8>(), block_layout()) };
    }
}

thread_local! {
    /// The slab this thread's wide values are placed in, during [`WideSlab::filling`].
    static FILLING: Cell<Option<NonNull<WideSlab>>> = const { Cell::new(None) };
}

/// Slots for the values past a word of a large product's coefficients, 4 095 to a block
/// of 64 KiB taken at once, where a box each cost an allocation and a free (Pearce(12):
/// 2.0 M of them, and 6–10 % of its time on one thread). A value in a slot is an
/// [`Integer`] like any other; its block is freed when the last of its values is dropped,
/// so a value kept alive keeps its block: only products large enough that a block is
/// small beside them fill a slab.
/// [`Release`] gives back the counts of a polynomial's coefficients a block at a time.
pub struct WideSlab {
    /// The block slots are taken from, if any.
    block: Option<NonNull<Header>>,
    /// Every block it has taken, each with one count that the slab holds until it is
    /// dropped or its counts are taken ([`WideSlab::into_counts`]), so that none is freed
    /// before then.
    blocks: Vec<NonNull<Header>>,
    /// Whether a value made while it was filled went to a box of its own (a `BigInt`).
    boxed: bool,
    /// The index of the next slot to hand out (the header is slot 0); `SLOTS + 1` when
    /// the block is spent.
    next: usize,
}

// SAFETY: a slab holds counts of its block, which are given back atomically from any
// thread; `FILLING` refers to it only during `filling`, which borrows it mutably.
unsafe impl Send for WideSlab {}

impl Default for WideSlab {
    fn default() -> Self {
        WideSlab::new()
    }
}

impl WideSlab {
    /// A slab with no block yet: the first value past a word takes one.
    pub fn new() -> Self {
        WideSlab {
            block: None,
            blocks: Vec::new(),
            boxed: false,
            next: SLOTS + 1,
        }
    }

    /// Runs `f` with the values past a word that this thread makes placed in this
    /// slab.
    pub fn filling<R>(&mut self, f: impl FnOnce() -> R) -> R {
        /// Puts back what `FILLING` was, on the way out (also by a panic).
        struct Restore(Option<NonNull<WideSlab>>);
        impl Drop for Restore {
            fn drop(&mut self) {
                FILLING.set(self.0);
            }
        }
        let _restore = Restore(FILLING.replace(Some(NonNull::from(self))));
        f()
    }

    /// `v`, which must lie outside the word's range, in the next slot: what
    /// [`Integer::wide`] does while this slab [fills](WideSlab::filling), for a caller that
    /// holds the slab, with no thread-local lookup and no call.
    #[inline(always)]
    pub fn place_integer(&mut self, v: i128) -> Integer {
        debug_assert!(i64::try_from(v)
            .map_or(true, |s| !(Integer::SMALL_MIN..=Integer::SMALL_MAX)
                .contains(&s)));
        Integer {
            word: self.place(v),
        }
    }

    /// `v` in the next slot, as a tagged word.
    #[inline]
    fn place(&mut self, v: i128) -> NonNull<u8> {
        let block = match self.block {
            Some(block) if self.next <= SLOTS => block,
            _ => self.refill(),
        };
        // SAFETY: slot `next` (1 to SLOTS) lies in the block and has not been handed out;
        // the value written is owned by the `Integer` that gets the word.
        unsafe {
            let slot = block.cast::<Wide>().add(self.next);
            slot.write(Wide(v));
            self.next += 1;
            slot.cast::<u8>().byte_add(SLOT)
        }
    }

    /// Gives back the slots of the block not handed out, and takes a new block.
    #[cold]
    fn refill(&mut self) -> NonNull<Header> {
        self.retire();
        let layout = block_layout();
        // SAFETY: the layout has a nonzero size.
        let Some(raw) = NonNull::new(unsafe { alloc(layout) }) else {
            handle_alloc_error(layout)
        };
        // Its pages backed in one call rather than a fault each (Pearce(12): 2–3 %).
        crate::pages::back_block(raw.as_ptr(), BLOCK_BYTES);
        let header = raw.cast::<Header>();
        // SAFETY: the block is fresh, aligned for `Header`, and larger than one.
        unsafe {
            header.write(Header {
                // Its slots, and the slab's own count.
                live: AtomicUsize::new(SLOTS + 1),
            })
        };
        self.blocks.push(header);
        self.block = Some(header);
        self.next = 1;
        header
    }

    /// Gives back the slots of the block not handed out, if there is a block.
    fn retire(&mut self) {
        if let Some(header) = self.block.take() {
            let unused = SLOTS + 1 - self.next;
            if unused > 0 {
                // SAFETY: the slab holds a count for each slot it has not handed out.
                unsafe { give_back(header, unused) };
            }
        }
    }

    /// The counts of its blocks that the values it placed hold, once it is filled: the
    /// values alive in each block, which are those of the vector it was filled for.
    ///
    /// # Safety
    ///
    /// Every value it placed and that is still alive is in one vector, whose values these
    /// counts then describe ([`SlotCounts::release`]): the slab was filled or placed in for
    /// that vector alone (`filling` around its writes or `place_integer` for them, no value
    /// made kept elsewhere), on this thread.
    pub unsafe fn into_counts(mut self) -> SlotCounts {
        self.retire();
        let mut counts = SlotCounts {
            runs: Vec::with_capacity(self.blocks.len()),
            boxed: self.boxed,
        };
        for block in std::mem::take(&mut self.blocks) {
            // SAFETY: the slab's own count keeps the block alive; no other thread holds a
            // value of it (the caller's promise), so the count is the values alive in it
            // plus the slab's.
            let live = unsafe { block.as_ref().live.load(Ordering::Acquire) };
            if live > 1 {
                counts.runs.push((block, live - 1));
            }
            // SAFETY: the slab's own count, given back once.
            unsafe { give_back(block, 1) };
        }
        counts
    }
}

impl Drop for WideSlab {
    fn drop(&mut self) {
        self.retire();
        for block in std::mem::take(&mut self.blocks) {
            // SAFETY: the slab's own count of each block it took, given back once.
            unsafe { give_back(block, 1) };
        }
    }
}

/// Drops integers, giving back the counts of the values in slots block by block: one
/// atomic operation for each run of values of one block, where a drop each takes one per
/// value. The counts of the last run are given back when it is dropped.
#[derive(Debug, Default)]
pub struct Release {
    /// The block of the current run, if any.
    block: Option<NonNull<Header>>,
    /// The values of the current run.
    count: usize,
}

// SAFETY: it holds counts of a block, which are given back atomically from any thread.
unsafe impl Send for Release {}

impl Release {
    /// Drops `i`.
    #[inline]
    pub fn take(&mut self, i: Integer) {
        let w = i.word.addr().get();
        if w & SMALL != 0 {
            return;
        }
        if w & SLOT == 0 {
            // In a box of its own.
            return drop(i);
        }
        let block = i.block();
        if self.block != Some(block) {
            self.flush();
            self.block = Some(block);
        }
        // Its count is given back with the run's.
        std::mem::forget(i);
        self.count += 1;
    }

    /// Gives back the counts of the current run.
    fn flush(&mut self) {
        if let Some(block) = self.block.take() {
            // SAFETY: the counts of the values taken from this block, whose `Integer`s
            // were forgotten.
            unsafe { give_back(block, std::mem::take(&mut self.count)) };
        }
    }
}

impl Drop for Release {
    fn drop(&mut self) {
        self.flush();
    }
}

/// The counts of [`WideSlab`] blocks that a vector of integers holds, taken from the slab
/// that a large product's builder filled ([`WideSlab::into_counts`]): the vector can then be
/// dropped a block at a time, by one atomic operation a block, with no pass over its values
/// (Pearce(12)'s pass over 5.8 M coefficients took 8 % of its time on one thread). The counts
/// are good only while the vector holds exactly the values the slab placed and that were
/// alive when it was taken, which the polynomial's coefficients (`poly::coeffs`) keep by
/// forgetting them at any change.
#[derive(Default)]
pub struct SlotCounts {
    /// Each block with the values of it the vector holds.
    runs: Vec<(NonNull<Header>, usize)>,
    /// Whether a value made while the slab was filled went to a box (a `BigInt`): it must be
    /// dropped on its own, so the counts cannot drop the vector.
    boxed: bool,
}

// SAFETY: it only names blocks, whose counts are given back atomically from any thread.
unsafe impl Send for SlotCounts {}
// SAFETY: `&SlotCounts` reads nothing of the blocks.
unsafe impl Sync for SlotCounts {}

impl SlotCounts {
    /// The blocks counted, and the counts in all.
    #[cfg(test)]
    pub(super) fn counted(&self) -> (usize, usize) {
        (self.runs.len(), self.runs.iter().map(|&(_, n)| n).sum())
    }

    /// Adds the counts of `other`, whose vector's values this one's took in (a part's).
    pub fn append(&mut self, mut other: SlotCounts) {
        self.boxed |= other.boxed;
        self.runs.append(&mut other.runs);
    }

    /// Whether the counts can drop their vector: no value had a box of its own.
    pub fn can_release(&self) -> bool {
        !self.boxed
    }

    /// Drops `values` by giving back the counts, a block at a time, and freeing the vector
    /// without a pass over its values; a vector the counts cannot drop (a value was boxed,
    /// [`SlotCounts::can_release`]) is dropped as usual.
    ///
    /// # Safety
    ///
    /// The values of `values` in slots hold exactly the counts these count, no more or fewer,
    /// and its other values are small (or the counts cannot drop it): each is an [`Integer`],
    /// or a value made of them alone.
    pub unsafe fn release<T>(self, values: Vec<T>) {
        if !self.can_release() {
            return drop(values);
        }
        for (block, n) in self.runs {
            // SAFETY: each value in a slot holds one count of its block, which goes back
            // here, where the value is forgotten below.
            unsafe { give_back(block, n) };
        }
        let mut values = std::mem::ManuallyDrop::new(values);
        // SAFETY: the values are forgotten, not dropped: those in slots have given back their
        // counts above, and small ones own nothing. The vector's buffer is then freed.
        unsafe {
            values.set_len(0);
            std::mem::ManuallyDrop::drop(&mut values);
        }
    }
}

/// Written out so that the common case, a small value, is a copy of the word inlined at
/// the call.
impl Clone for Integer {
    #[inline]
    fn clone(&self) -> Self {
        match self.small() {
            Some(_) => Integer { word: self.word },
            None => self.clone_boxed(),
        }
    }
}

impl Integer {
    #[inline(never)]
    fn clone_boxed(&self) -> Self {
        match self.view() {
            IntegerView::Small(v) => Integer::small_unchecked(v),
            IntegerView::Wide(v) => Integer::wide(v),
            IntegerView::Big(b) => Integer::big(b.clone()),
        }
    }
}
