//! Where threads run: the processors a thread may use (its CPU affinity), read and set. A
//! caller may pin each worker of its pool to a processor of its own (`superint bench` does, so
//! that the kernel cannot wake a sleeping worker on the processor of the one that woke it,
//! queued behind it); a product's own thread (`poly/dense.rs`, the pipelined sparse product)
//! then moves off its creator's processor ([`run_beside_creator`]), since a new thread starts
//! with its creator's affinity and would otherwise take turns with it instead of running
//! beside it. Linux only: elsewhere nothing is known ([`allowed`] is empty) and nothing is set.
//! Affinity changes where a thread runs, never what it computes.

/// The processors the calling thread may use, in order (empty where that is not known).
pub fn allowed() -> Vec<usize> {
    read(0)
}

/// The processors the process's main thread may use, in order (empty where that is not known):
/// the set a thread of the process may run on unless it was narrowed.
pub fn process_allowed() -> Vec<usize> {
    // SAFETY: `getpid` has no preconditions.
    #[cfg(any(target_os = "linux", target_os = "android"))]
    let main = unsafe { libc::getpid() };
    #[cfg(not(any(target_os = "linux", target_os = "android")))]
    let main = 0;
    read(main)
}

/// Lets the calling thread run on the processors `cpus` only; whether the kernel took them
/// (never for an empty set).
pub fn allow(cpus: &[usize]) -> bool {
    !cpus.is_empty() && write(cpus)
}

/// Lets the calling thread, spawned by a thread whose affinity it inherited, run beside its
/// creator: on every processor the process may use but its creator's, when the creator is
/// pinned to one of several (the creator cannot move, and the kernel would often wake this
/// thread on the creator's processor, where the creator wakes it); on every one the process
/// may use otherwise. Whether the kernel took the new affinity.
pub fn run_beside_creator() -> bool {
    let mut process = process_allowed();
    if let [creator] = allowed()[..] {
        if process.len() > 1 {
            process.retain(|&c| c != creator);
        }
    }
    allow(&process)
}

/// The processors thread `tid` (0: the calling thread) may use.
#[cfg(any(target_os = "linux", target_os = "android"))]
fn read(tid: libc::pid_t) -> Vec<usize> {
    let size = std::mem::size_of::<libc::cpu_set_t>();
    // SAFETY: `cpu_set_t` is a plain bit array, for which all zeros is a valid (empty) value;
    // the kernel writes at most `size` bytes of it, and `CPU_ISSET` reads one bit below
    // `CPU_SETSIZE`.
    unsafe {
        let mut set: libc::cpu_set_t = std::mem::zeroed();
        if libc::sched_getaffinity(tid, size, &mut set) != 0 {
            return Vec::new();
        }
        (0..libc::CPU_SETSIZE as usize)
            .filter(|&cpu| libc::CPU_ISSET(cpu, &set))
            .collect()
    }
}

/// Sets the calling thread's processors to `cpus`; whether the kernel took them.
#[cfg(any(target_os = "linux", target_os = "android"))]
fn write(cpus: &[usize]) -> bool {
    let size = std::mem::size_of::<libc::cpu_set_t>();
    if cpus.iter().any(|&cpu| cpu >= libc::CPU_SETSIZE as usize) {
        return false;
    }
    // SAFETY: as in `read`; `CPU_SET` writes one bit below `CPU_SETSIZE` (checked above), and
    // the kernel reads `size` bytes.
    unsafe {
        let mut set: libc::cpu_set_t = std::mem::zeroed();
        for &cpu in cpus {
            libc::CPU_SET(cpu, &mut set);
        }
        libc::sched_setaffinity(0, size, &set) == 0
    }
}

#[cfg(not(any(target_os = "linux", target_os = "android")))]
fn read(_tid: i32) -> Vec<usize> {
    Vec::new()
}

#[cfg(not(any(target_os = "linux", target_os = "android")))]
fn write(_cpus: &[usize]) -> bool {
    false
}

#[cfg(all(test, any(target_os = "linux", target_os = "android")))]
mod tests {
    use super::{allow, allowed, process_allowed, run_beside_creator};

    /// What a thread spawned by a thread set up by `creator` may use: as it starts, and after
    /// `run_beside_creator`.
    fn spawned_by(creator: impl FnOnce() + Send + 'static) -> (Vec<usize>, Vec<usize>) {
        std::thread::spawn(move || {
            creator();
            std::thread::spawn(|| {
                let inherited = allowed();
                assert!(
                    run_beside_creator(),
                    "the kernel lets a thread set its own mask"
                );
                (inherited, allowed())
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
        let process = process_allowed();
        let first = process[0];
        let (inherited, moved) = spawned_by(move || assert!(allow(&[first])));
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
