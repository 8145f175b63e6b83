//! Where a thread that a product spawns may run. A new thread starts with its creator's CPU
//! affinity, so a caller whose pool pins each worker to one processor (`superint bench` does,
//! so that the kernel cannot queue a woken worker behind the one that woke it) would have the
//! product's second thread (`dense.rs`, the pipelined sparse product) share the caller's
//! processor, taking turns with it instead of running beside it. The spawned thread first
//! moves to the process's other processors: every one the process may use but its creator's,
//! when the creator is pinned to one of several (the creator cannot move, and the kernel would
//! otherwise often wake the spawned thread on its processor, where the creator wakes it); every
//! one the process may use otherwise. Elsewhere than Linux, or where the kernel refuses,
//! nothing changes, and this changes where the thread runs, never what it computes.

/// Lets the calling thread, spawned by a thread whose affinity it inherited, run beside its
/// creator (see the module's note); whether the kernel took the new affinity.
#[cfg(any(target_os = "linux", target_os = "android"))]
pub(crate) fn run_beside_creator() -> bool {
    let size = std::mem::size_of::<libc::cpu_set_t>();
    // SAFETY: `cpu_set_t` is a plain bit array, for which all zeros is a valid (empty) value;
    // every call reads or writes exactly `size` bytes of a set on this stack frame, and the
    // `CPU_*` helpers touch one bit below `CPU_SETSIZE`. The process id names the main
    // thread, whose mask is read; 0 names the calling thread.
    unsafe {
        let mut process: libc::cpu_set_t = std::mem::zeroed();
        let mut inherited: libc::cpu_set_t = std::mem::zeroed();
        if libc::sched_getaffinity(libc::getpid(), size, &mut process) != 0
            || libc::sched_getaffinity(0, size, &mut inherited) != 0
        {
            return false;
        }
        if libc::CPU_COUNT(&inherited) == 1 && libc::CPU_COUNT(&process) > 1 {
            let creators =
                (0..libc::CPU_SETSIZE as usize).find(|&c| libc::CPU_ISSET(c, &inherited));
            if let Some(c) = creators {
                libc::CPU_CLR(c, &mut process);
            }
        }
        libc::CPU_COUNT(&process) > 0 && libc::sched_setaffinity(0, size, &process) == 0
    }
}

#[cfg(not(any(target_os = "linux", target_os = "android")))]
pub(crate) fn run_beside_creator() -> bool {
    false
}

#[cfg(all(test, any(target_os = "linux", target_os = "android")))]
mod tests {
    use super::run_beside_creator;

    /// The processors the calling thread (`0`) or the main thread (the process id) may use.
    fn allowed(pid: libc::pid_t) -> Vec<usize> {
        let size = std::mem::size_of::<libc::cpu_set_t>();
        // SAFETY: as in `run_beside_creator`: a zeroed bit array of `size` bytes, written by
        // the kernel, read a bit below `CPU_SETSIZE` at a time.
        unsafe {
            let mut set: libc::cpu_set_t = std::mem::zeroed();
            assert_eq!(libc::sched_getaffinity(pid, size, &mut set), 0);
            (0..libc::CPU_SETSIZE as usize)
                .filter(|&c| libc::CPU_ISSET(c, &set))
                .collect()
        }
    }

    /// Pins the calling thread to `cpu`.
    fn pin(cpu: usize) {
        let size = std::mem::size_of::<libc::cpu_set_t>();
        // SAFETY: as in `allowed`, with one bit set below `CPU_SETSIZE`, read by the kernel.
        unsafe {
            let mut one: libc::cpu_set_t = std::mem::zeroed();
            libc::CPU_SET(cpu, &mut one);
            assert_eq!(libc::sched_setaffinity(0, size, &one), 0);
        }
    }

    /// What a thread spawned by a thread set up by `creator` may use: as it starts, and after
    /// `run_beside_creator`.
    fn spawned_by(creator: impl FnOnce() + Send + 'static) -> (Vec<usize>, Vec<usize>) {
        std::thread::spawn(move || {
            creator();
            std::thread::spawn(|| {
                let inherited = allowed(0);
                assert!(
                    run_beside_creator(),
                    "the kernel lets a thread set its own mask"
                );
                (inherited, allowed(0))
            })
            .join()
            .expect("the spawned thread ends")
        })
        .join()
        .expect("the creating thread ends")
    }

    /// A thread spawned by one pinned to a processor, as a pinned pool's worker is, starts
    /// pinned there too, and then moves to the process's other processors (to the one there
    /// is, if the process has only one); a thread spawned by an unpinned one may use every
    /// processor the process may.
    #[test]
    fn a_spawned_thread_leaves_its_creators_processor() {
        // SAFETY: `getpid` has no preconditions.
        let process = allowed(unsafe { libc::getpid() });
        let first = process[0];
        let (inherited, moved) = spawned_by(move || pin(first));
        assert_eq!(
            inherited,
            vec![first],
            "a thread starts with its creator's mask"
        );
        let others: Vec<usize> = process.iter().copied().filter(|&c| c != first).collect();
        match others.is_empty() {
            true => assert_eq!(moved, vec![first]),
            false => assert_eq!(moved, others),
        }
        let (inherited, moved) = spawned_by(|| {});
        assert_eq!((&inherited, &moved), (&process, &process));
    }
}
