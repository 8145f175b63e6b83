//! Pinning the benchmark pool's threads, one to a processor. A rayon worker with nothing to do
//! sleeps, and the kernel tends to wake a thread on the processor of the thread that wakes it
//! (when that one has just been running there): on this project's two-processor machines the
//! second worker of `superint bench W4 1000 --threads 2` was queued behind the first for the
//! whole run in a third of the runs (1.2 ms against 0.7 ms, `docs/performance.md`). A worker
//! pinned to a processor of its own is woken there. Elsewhere than Linux, or where the kernel
//! refuses, the threads stay where the kernel puts them: pinning changes where the work runs,
//! never what it computes.

/// The processors the calling thread may run on, in order (empty where that is not known).
#[cfg(target_os = "linux")]
pub fn allowed() -> Vec<usize> {
    let size = std::mem::size_of::<libc::cpu_set_t>();
    // SAFETY: `cpu_set_t` is a plain bit array, for which all zeros is a valid (empty) value;
    // the kernel writes at most `size` bytes of it, and `CPU_ISSET` reads one bit below
    // `CPU_SETSIZE`.
    unsafe {
        let mut set: libc::cpu_set_t = std::mem::zeroed();
        if libc::sched_getaffinity(0, size, &mut set) != 0 {
            return Vec::new();
        }
        (0..libc::CPU_SETSIZE as usize)
            .filter(|&cpu| libc::CPU_ISSET(cpu, &set))
            .collect()
    }
}

#[cfg(not(target_os = "linux"))]
pub fn allowed() -> Vec<usize> {
    Vec::new()
}

/// Pins the calling thread to processor `cpu`; whether the kernel did.
#[cfg(target_os = "linux")]
pub fn pin_to(cpu: usize) -> bool {
    let size = std::mem::size_of::<libc::cpu_set_t>();
    if cpu >= libc::CPU_SETSIZE as usize {
        return false;
    }
    // SAFETY: as in `allowed`; `CPU_SET` writes one bit below `CPU_SETSIZE` (checked above),
    // and the kernel reads `size` bytes.
    unsafe {
        let mut set: libc::cpu_set_t = std::mem::zeroed();
        libc::CPU_SET(cpu, &mut set);
        libc::sched_setaffinity(0, size, &set) == 0
    }
}

#[cfg(not(target_os = "linux"))]
pub fn pin_to(_cpu: usize) -> bool {
    false
}
