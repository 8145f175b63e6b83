//! Backing memory's pages before it is written: a vector's next pages, or a block fresh from
//! the allocator. A large product writes its terms once, into memory fresh from the system,
//! and each page of it would fault on its first write (1.6–1.8 µs a page on the virtual
//! machines measured); asking the kernel to back a window of pages at once
//! (`madvise(MADV_POPULATE_WRITE)`, Linux 5.14 and later) does the same work in one system
//! call. Elsewhere, or where the kernel refuses, nothing happens and the pages fault as before:
//! this changes when memory is backed, never what it holds.

/// The size of a page, as the ranges backed are aligned (a larger page only backs more).
const PAGE: usize = 4096;

/// Backs the pages wholly inside the first `n` elements of `v`'s spare capacity; whether the
/// kernel did (false where it cannot, or when no whole page lies in the range).
pub(crate) fn back_spare<T>(v: &mut Vec<T>, n: usize) -> bool {
    let spare = v.spare_capacity_mut();
    let bytes = n.min(spare.len()) * std::mem::size_of::<T>();
    back_block(spare.as_mut_ptr().cast::<u8>(), bytes)
}

/// Backs the pages wholly inside the `len` bytes from `start`, which the caller owns; whether
/// the kernel did.
pub(crate) fn back_block(start: *mut u8, len: usize) -> bool {
    let start = start as usize;
    let (first, last) = (start.div_ceil(PAGE) * PAGE, (start + len) / PAGE * PAGE);
    last > first && back(first, last - first)
}

#[cfg(all(any(target_os = "linux", target_os = "android"), not(miri)))]
fn back(first: usize, len: usize) -> bool {
    // SAFETY: the range lies inside an allocation this process owns (a vector's spare capacity, or
    // a block the caller allocated), and MADV_POPULATE_WRITE only backs its pages as a write would,
    // without writing: it changes no byte of memory, so no Rust value can observe it. A refusal (an
    // older kernel says EINVAL) leaves the pages to fault as before.
    unsafe { libc::madvise(first as *mut libc::c_void, len, libc::MADV_POPULATE_WRITE) == 0 }
}

/// Elsewhere, and under Miri (which has no `madvise`), pages fault as they are written.
#[cfg(not(all(any(target_os = "linux", target_os = "android"), not(miri))))]
fn back(_first: usize, _len: usize) -> bool {
    false
}

#[cfg(all(test, any(target_os = "linux", target_os = "android"), not(miri)))]
mod tests {
    use super::{back_spare, PAGE};

    /// Which of the pages from `start` (page-aligned) are resident, by `mincore`.
    fn resident(start: usize, pages: usize) -> Vec<bool> {
        let mut flags = vec![0u8; pages];
        // SAFETY: the range is inside the test's own allocation and `flags` has one byte per
        // page, as `mincore` requires.
        let ok = unsafe {
            libc::mincore(start as *mut libc::c_void, pages * PAGE, flags.as_mut_ptr()) == 0
        };
        assert!(ok, "mincore failed");
        flags.iter().map(|f| f & 1 == 1).collect()
    }

    /// The pages of the window are backed and those past it are not; the values written
    /// before and after are kept. (A kernel without `MADV_POPULATE_WRITE` backs nothing, and
    /// then only the values are checked.)
    #[test]
    fn backs_the_window_and_keeps_values() {
        // 64 MiB from the system allocator: a fresh mapping, not yet backed (above glibc's
        // largest threshold for serving a block from its heap, 32 MiB, which could hand back
        // memory another test touched).
        let mut v: Vec<u64> = Vec::with_capacity(8 << 20);
        v.extend(0..1000);
        let window = 256 * PAGE / 8;
        let backed = back_spare(&mut v, window);
        let start = (v.spare_capacity_mut().as_ptr() as usize).div_ceil(PAGE) * PAGE;
        let pages = resident(start, 1536);
        if backed {
            assert!(pages[..255].iter().all(|&r| r), "the window is backed");
            // Where the kernel backs anonymous memory with 2 MiB pages unasked, the page that
            // holds the window's end comes whole: only 3 MiB past the start is certain.
            let huge = std::fs::read_to_string("/sys/kernel/mm/transparent_hugepage/enabled")
                .is_ok_and(|mode| mode.contains("[always]"));
            let past = if huge { 768 } else { 256 };
            assert!(pages[past..].iter().all(|&r| !r), "nothing past it");
        }
        v.extend(1000..1000 + window as u64);
        assert!(v.iter().enumerate().all(|(i, &x)| x == i as u64));
        assert!(!back_spare(&mut v, 0), "an empty window backs nothing");
    }
}
