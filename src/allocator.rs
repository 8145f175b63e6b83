//! The allocator of the `superint` binary and its benchmarks: mimalloc, called the way its
//! fast path expects.
//!
//! The engine makes many short-lived vectors (a polynomial is two), so the allocator's fast
//! path matters. The `mimalloc` crate's own `GlobalAlloc` calls `mi_malloc_aligned` for every
//! request, whose fast path only holds while the size class's current page has a free block:
//! otherwise a size that is not a power of two is served by over-allocating, at three times
//! the instructions, into a larger size class (43 % of W4's allocations took that path). Every
//! mimalloc block is aligned to a machine word, and every block of at least 16 bytes to 16
//! (`MI_MAX_ALIGN_SIZE`, the alignment of C's `max_align_t`, which `malloc` guarantees), so
//! requests that those alignments satisfy go to plain `mi_malloc` (the rule of Rust's own
//! `System` allocator), and only the others to the aligned entry points. An `i128` asks for
//! 16: its boxes and vectors took the aligned path's slow branch, 163 instructions per
//! bracket of W4. Freeing is `mi_free` for both.

use std::alloc::{GlobalAlloc, Layout};
use std::ffi::c_void;

use libmimalloc_sys as ffi;

/// The alignment every mimalloc block has: block sizes are multiples of a machine word and
/// pages start at word boundaries.
const WORD: usize = std::mem::size_of::<usize>();

/// The alignment of every mimalloc block of at least this many bytes (`MI_MAX_ALIGN_SIZE`).
const MAX_ALIGN: usize = 16;

/// Whether a plain (unaligned) mimalloc block of `size` bytes has alignment `align`.
#[inline]
fn plain_block_fits(size: usize, align: usize) -> bool {
    align <= WORD || (align <= MAX_ALIGN && size >= MAX_ALIGN)
}

/// mimalloc's `mi_option_page_reclaim_on_free` (its place in `mi_option_e` of mimalloc 3,
/// which `libmimalloc-sys` 0.1.49 builds but does not name; a test pins the place).
const OPTION_PAGE_RECLAIM_ON_FREE: ffi::mi_option_t = 35;

/// Sets the options the engine's allocation pattern wants; call it first thing in `main`.
///
/// A large product built on two threads (`trigpoly`'s dense pipeline) has its coefficients
/// made on the building thread, which ends with the product; they are freed later by another
/// thread. By default mimalloc frees each such block across threads (an atomic operation per
/// block, 1.7 million of them for Pearce(12)); reclaiming on free lets the freeing thread take
/// over each page of the ended thread at its first free, after which its frees are local.
pub fn configure() {
    // SAFETY: `mi_option_set` only stores the value of an option, for any option and value.
    unsafe { ffi::mi_option_set(OPTION_PAGE_RECLAIM_ON_FREE, 1) };
}

/// mimalloc as the global allocator: `#[global_allocator] static A: Allocator = Allocator;`.
#[derive(Clone, Copy, Debug, Default)]
pub struct Allocator;

// SAFETY: every method forwards to mimalloc, which returns blocks of at least the requested
// size that stay valid until `mi_free`. A request whose alignment every plain block of its
// size has (`plain_block_fits`: see `WORD` and `MAX_ALIGN`) goes to an entry point without an
// alignment argument; any other goes to the `_aligned` entry point with that alignment.
// `realloc` keeps the layout's alignment the same way, and `mi_free` takes blocks from every
// entry point.
unsafe impl GlobalAlloc for Allocator {
    #[inline]
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if plain_block_fits(layout.size(), layout.align()) {
            ffi::mi_malloc(layout.size()).cast()
        } else {
            ffi::mi_malloc_aligned(layout.size(), layout.align()).cast()
        }
    }

    #[inline]
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        if plain_block_fits(layout.size(), layout.align()) {
            ffi::mi_zalloc(layout.size()).cast()
        } else {
            ffi::mi_zalloc_aligned(layout.size(), layout.align()).cast()
        }
    }

    #[inline]
    unsafe fn dealloc(&self, ptr: *mut u8, _layout: Layout) {
        ffi::mi_free(ptr.cast::<c_void>());
    }

    #[inline]
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if plain_block_fits(new_size, layout.align()) {
            ffi::mi_realloc(ptr.cast::<c_void>(), new_size).cast()
        } else {
            ffi::mi_realloc_aligned(ptr.cast::<c_void>(), new_size, layout.align()).cast()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The option `configure` sets is mimalloc's page reclaim on free: its place in the
    /// options' enum is after `generic_collect` (default 10000) and before `page_full_retain`
    /// and `page_max_candidates` (defaults 2 and 4). Moving the enum makes this fail.
    #[test]
    fn the_reclaim_option_is_where_configure_sets_it() {
        // SAFETY: reading options has no precondition.
        let get = |option| unsafe { ffi::mi_option_get(option) };
        let neighbours = [-1, 1, 2].map(|d| get(OPTION_PAGE_RECLAIM_ON_FREE + d));
        assert_eq!(neighbours, [10_000, 2, 4]);
        configure();
        assert_eq!(get(OPTION_PAGE_RECLAIM_ON_FREE), 1);
    }

    /// Every alignment from 1 to 64 over sizes that fall in many size classes: the block is
    /// aligned, holds what is written to it, and keeps it through a `realloc` that grows it.
    #[test]
    fn blocks_are_aligned_and_keep_their_contents_through_realloc() {
        let allocator = Allocator;
        for align in (0..7).map(|k| 1usize << k) {
            for size in (1..=200).chain([1000, 4096, 70_000]) {
                let layout = Layout::from_size_align(size, align).unwrap();
                // SAFETY: `layout` has a nonzero size; the block is written within its size,
                // grown with the layout it was allocated with, and freed with the new size.
                unsafe {
                    for zeroed in [false, true] {
                        let p = if zeroed {
                            allocator.alloc_zeroed(layout)
                        } else {
                            allocator.alloc(layout)
                        };
                        assert!(!p.is_null());
                        assert_eq!(p as usize % align, 0, "size {size}, align {align}");
                        if zeroed {
                            assert!((0..size).all(|i| *p.add(i) == 0));
                        }
                        for i in 0..size {
                            *p.add(i) = i as u8;
                        }
                        let q = allocator.realloc(p, layout, 3 * size);
                        assert_eq!(q as usize % align, 0, "realloc {size}, align {align}");
                        assert!((0..size).all(|i| *q.add(i) == i as u8));
                        let grown = Layout::from_size_align(3 * size, align).unwrap();
                        allocator.dealloc(q, grown);
                    }
                }
            }
        }
    }
}
