//! Where a thread that a product spawns may run. A new thread starts with its creator's CPU
//! affinity, so a caller whose pool pins each worker to one processor (`superint bench` does,
//! so that the kernel cannot queue a woken worker behind the one that woke it) would have the
//! product's second thread (`dense.rs`, the pipelined sparse product) share the caller's
//! processor, taking turns with it instead of running beside it. The spawned thread widens its
//! affinity to the process's first: elsewhere than Linux, or where the kernel refuses, nothing
//! changes, and this changes where the thread runs, never what it computes.

/// Lets the calling thread run on every processor the process's main thread may run on;
/// whether it could.
#[cfg(any(target_os = "linux", target_os = "android"))]
pub(crate) fn run_anywhere() -> bool {
    let size = std::mem::size_of::<libc::cpu_set_t>();
    // SAFETY: `cpu_set_t` is a plain bit array, for which all zeros is a valid (empty) value;
    // both calls read or write exactly `size` bytes of `set`, which lives on this stack frame.
    // The process id names the main thread, whose mask is read; 0 names the calling thread,
    // whose mask is set.
    unsafe {
        let mut set: libc::cpu_set_t = std::mem::zeroed();
        libc::sched_getaffinity(libc::getpid(), size, &mut set) == 0
            && libc::sched_setaffinity(0, size, &set) == 0
    }
}

#[cfg(not(any(target_os = "linux", target_os = "android")))]
pub(crate) fn run_anywhere() -> bool {
    false
}

#[cfg(all(test, any(target_os = "linux", target_os = "android")))]
mod tests {
    use super::run_anywhere;

    /// The processors the calling thread (`0`) or the main thread (the process id) may use.
    fn allowed(pid: libc::pid_t) -> Vec<usize> {
        let size = std::mem::size_of::<libc::cpu_set_t>();
        // SAFETY: as in `run_anywhere`: a zeroed bit array of `size` bytes, read by the kernel.
        unsafe {
            let mut set: libc::cpu_set_t = std::mem::zeroed();
            assert_eq!(libc::sched_getaffinity(pid, size, &mut set), 0);
            (0..libc::CPU_SETSIZE as usize)
                .filter(|&c| libc::CPU_ISSET(c, &set))
                .collect()
        }
    }

    /// A thread pinned to one processor, as a pinned pool's worker is, spawns a thread: the
    /// new thread starts pinned too, and after `run_anywhere` may use every processor the
    /// process may.
    #[test]
    fn a_spawned_thread_leaves_its_creators_pin() {
        // SAFETY: `getpid` has no preconditions.
        let process = allowed(unsafe { libc::getpid() });
        let first = process[0];
        let (inherited, widened) = std::thread::spawn(move || {
            let size = std::mem::size_of::<libc::cpu_set_t>();
            // SAFETY: as in `allowed`, with one bit set, written by the kernel into this
            // thread's mask.
            unsafe {
                let mut one: libc::cpu_set_t = std::mem::zeroed();
                libc::CPU_SET(first, &mut one);
                assert_eq!(libc::sched_setaffinity(0, size, &one), 0);
            }
            std::thread::spawn(|| {
                let inherited = allowed(0);
                assert!(
                    run_anywhere(),
                    "the kernel lets a thread widen its own mask"
                );
                (inherited, allowed(0))
            })
            .join()
            .expect("the spawned thread ends")
        })
        .join()
        .expect("the pinned thread ends");
        assert_eq!(
            inherited,
            vec![first],
            "a thread starts with its creator's mask"
        );
        assert_eq!(widened, process);
    }
}
