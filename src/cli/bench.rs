//! `superint bench W SIZE`: runs one performance workload once; the last two lines are
//! `seconds: X` and `terms: T`, which the peer comparison (`benches/peers/compare.py`) reads
//! (`--format json`: one object with the same fields).

use std::time::Instant;

use anyhow::{bail, Context};
use clap::Args;
use superint::render::Format;
use superint::workloads::Workload;

use trigpoly::placement;

use super::output::Output;

pub const EXAMPLES: &str = "\
Examples:
  superint bench W1 24        the tower: {P, H}, {Q, H} at resonance for 1 ≤ m, n ≤ 24
  superint bench W2 80        one pair m = n = 80
  superint bench fateman 20   the Fateman product f·(f + 1), f = (1 + x + y + z + t)^20
  superint bench pearce 12    the sparse Pearce product
  superint bench W4 1000      the su(2) table and the Casimir, 1000 times
  superint bench W1 24 --threads 2   the pairs spread over two threads, one to a processor";

/// Arguments of `superint bench`.
#[derive(Debug, Args)]
pub struct BenchArgs {
    /// The workload: W1|tower, W2|single, W3a|fateman, W3b|pearce, W4|algebra.
    workload: String,
    /// Its size (N for W1, m for W2, the exponent for W3, repetitions for W4).
    #[arg(value_parser = super::in_range::<i64>(1, 100_000))]
    size: i64,
    /// Threads for the workloads that have independent parts (W1 pairs, W2 brackets, the index
    /// range of a large dense product in W3, W4 repetitions); 1 runs everything on the calling
    /// thread.
    #[arg(long, allow_negative_numbers = true,
          default_value_t = 1,
          value_parser = super::in_range::<u16>(1, super::MAX_THREADS))]
    threads: u16,
    /// Leave the pool's threads where the kernel puts them. By default each of two or more
    /// threads is pinned to a processor of its own (when the process may use that many), so
    /// that the kernel cannot queue a woken thread behind the one that woke it.
    #[arg(long)]
    no_pin: bool,
}

impl BenchArgs {
    pub fn job(self, output: Output) -> BenchJob {
        BenchJob { args: self, output }
    }
}

/// The bench job, as plain data.
#[derive(Debug)]
pub struct BenchJob {
    pub args: BenchArgs,
    pub output: Output,
}

/// Runs the workload once and prints what it computed and how long it took.
pub fn run(job: &BenchJob) -> anyhow::Result<bool> {
    let args = &job.args;
    match job.output.format {
        Format::Text | Format::Json => {}
        other => bail!("bench prints text or json, not {other}"),
    }
    if !job.output.options.timings {
        bail!("bench measures a time: --no-timings does not apply to it");
    }
    let workload = Workload::new(&args.workload, args.size)?;
    let pool = pool(args.threads as usize, !args.no_pin)?;
    // The pool's threads start before the clock does, heaps included: their start is not
    // the workload's. Each tells whether it runs pinned.
    let alone = pool.broadcast(|_| {
        warm_heap();
        placement::allowed().len() == 1
    });
    // The program's code is loaded before the clock, as the peers' is by `import`.
    map_program();
    // This thread may use every processor the process may: each pool thread that may use
    // one only, of two or more, was pinned.
    let pinned = args.threads > 1 && placement::allowed().len() > 1 && alone.iter().all(|&a| a);
    // The clock runs on the pool's thread, from the workload's first step to its last: not
    // the hand-over of the job from this thread to the pool and back, which a program that
    // runs in its pool does not make.
    let (outcome, elapsed) = pool.install(|| {
        let start = Instant::now();
        let outcome = workload.run();
        (outcome, start.elapsed())
    });
    let outcome = outcome.with_context(|| format!("workload {workload}"))?;
    // Wall-clock time is reported, never used to decide anything.
    let seconds = elapsed.as_secs_f64();
    if job.output.format == Format::Json {
        let doc = serde_json::json!({
            "schema": "superint-bench/1",
            "workload": workload.to_string(),
            "threads": args.threads,
            "pinned": pinned,
            "zeros": outcome.zeros,
            "seconds": seconds,
            "terms": outcome.terms,
        });
        println!("{doc:#}");
        return Ok(true);
    }
    println!("workload: {workload}");
    println!(
        "threads: {}{}",
        args.threads,
        if pinned { ", pinned" } else { "" }
    );
    println!("zeros: {}", outcome.zeros);
    println!("seconds: {seconds:.6}");
    println!("terms: {}", outcome.terms);
    Ok(true)
}

/// Allocates and frees blocks of the sizes from a word to 64 KiB, so that this thread's heap
/// exists and has its first pages before the clock starts, as the calling thread's has from
/// parsing the arguments: mimalloc makes a thread's heap at its first allocation and takes
/// fresh pages (page faults) for each size class it then meets. Without this, W4(1) took
/// 0.32 ms on two threads and 0.18 ms on one (medians of 21 alternating runs in a slow quarter
/// hour); with it, 0.20 ms and 0.14 ms.
fn warm_heap() {
    let sizes = (1..=64).chain((7..=13).map(|b| 1 << b));
    let blocks: Vec<Vec<u64>> = sizes.map(Vec::with_capacity).collect();
    drop(std::hint::black_box(blocks));
}

/// Maps the program's own pages (its code, constants and data) before the clock starts, as
/// the peers' interpreters have loaded SymPy's and python-flint's code with `import` before
/// theirs. The kernel maps a program's pages as they are first run, a page fault each, and a
/// workload's first steps run code nothing before them has: W4(1) had 28 page faults in its
/// 0.23 ms, and 0.11 ms without them (the clock's work is the same). One
/// `madvise(MADV_POPULATE_READ)` per mapping of the executable (Linux 5.14 and later); where
/// the kernel refuses, or elsewhere, the pages fault as before. Whether every mapping was
/// mapped.
#[cfg(any(target_os = "linux", target_os = "android"))]
fn map_program() -> bool {
    let (Ok(maps), Ok(exe)) = (
        std::fs::read_to_string("/proc/self/maps"),
        std::fs::read_link("/proc/self/exe"),
    ) else {
        return false;
    };
    let mut all = true;
    let mut any = false;
    // A line: `start-end perms offset device inode path`.
    for line in maps.lines() {
        let mut fields = line.split_whitespace();
        let (Some(range), Some(path)) = (fields.next(), fields.nth(4)) else {
            continue;
        };
        if std::path::Path::new(path) != exe {
            continue;
        }
        let Some((start, end)) = range.split_once('-').and_then(|(a, b)| {
            Some((
                usize::from_str_radix(a, 16).ok()?,
                usize::from_str_radix(b, 16).ok()?,
            ))
        }) else {
            continue;
        };
        // SAFETY: the range is a mapping of this process, as the kernel lists it, and
        // MADV_POPULATE_READ only fills its page tables as reads of it would, without
        // reading into or writing any memory: no Rust value can observe it. A refusal (an
        // older kernel says EINVAL) leaves the pages to fault as before.
        let mapped = unsafe {
            libc::madvise(
                start as *mut libc::c_void,
                end - start,
                libc::MADV_POPULATE_READ,
            )
        } == 0;
        all &= mapped;
        any = true;
    }
    any && all
}

#[cfg(not(any(target_os = "linux", target_os = "android")))]
fn map_program() -> bool {
    false
}

/// The pool the workload runs in. One thread is the calling one, whose heap is already in use:
/// started on a fresh pool thread, W4(1) took 0.24 ms instead of 0.08 (median of 41), most of
/// it that thread's first allocations (page faults) and its wake-up. Such a pool holds the
/// calling thread for the rest of the process; a calling thread that is already some pool's
/// gets a thread of its own. More threads are all the pool's own: with the calling thread as
/// one of two, W4(1000) took 1.37 ms instead of 0.89 ms (median of 31 alternating runs).
///
/// With `pin`, each of two or more threads is pinned to a processor of its own, if the process
/// may use as many. A rayon worker with nothing to do sleeps, and the kernel tends to wake a
/// thread on the processor of the thread that wakes it: the second worker of W4(1000) on two
/// threads was queued behind the first for the whole run in a third of the runs (1.2 ms
/// against 0.7 ms, `docs/performance.md`, step 123). A pinned worker is woken on its own.
fn pool(threads: usize, pin: bool) -> Result<rayon::ThreadPool, rayon::ThreadPoolBuildError> {
    let builder = || rayon::ThreadPoolBuilder::new().num_threads(threads);
    if threads == 1 {
        if let Ok(pool) = builder().use_current_thread().build() {
            return Ok(pool);
        }
    }
    let cpus = placement::allowed();
    if pin && cpus.len() >= threads {
        return builder()
            .start_handler(move |i| {
                // Unpinned if the kernel refuses; the bench reports which it was.
                placement::allow(&cpus[i..=i]);
            })
            .build();
    }
    builder().build()
}

#[cfg(test)]
mod tests {
    use super::{map_program, pool};
    use trigpoly::placement;

    /// Once the program is mapped, every page of its code is in its page tables: the resident
    /// size of its executable mapping is the mapping's size. (A kernel without
    /// `MADV_POPULATE_READ` maps nothing, and then nothing is checked.)
    #[test]
    #[cfg(any(target_os = "linux", target_os = "android"))]
    fn mapping_the_program_maps_all_its_code() {
        if !map_program() {
            return;
        }
        let exe = std::fs::read_link("/proc/self/exe").expect("the executable");
        let smaps = std::fs::read_to_string("/proc/self/smaps").expect("smaps");
        let lines: Vec<&str> = smaps.lines().collect();
        let code = lines
            .iter()
            .position(|l| {
                let f: Vec<&str> = l.split_whitespace().collect();
                f.len() == 6 && f[1] == "r-xp" && std::path::Path::new(f[5]) == exe
            })
            .expect("the executable's code mapping");
        let kib = |key: &str| -> u64 {
            let line = lines[code + 1..]
                .iter()
                .find(|l| l.starts_with(key))
                .expect(key);
            line[key.len()..]
                .trim()
                .trim_end_matches("kB")
                .trim()
                .parse()
                .expect("a size in kB")
        };
        assert_eq!(kib("Rss:"), kib("Size:"));
    }

    #[test]
    fn one_thread_is_the_calling_one_once_and_then_a_thread_of_its_own() {
        let here = std::thread::current().id();
        let first = pool(1, true).expect("a pool on this thread");
        let second = pool(1, true).expect("a pool on a thread of its own");
        assert_eq!(first.install(|| std::thread::current().id()), here);
        assert_ne!(second.install(|| std::thread::current().id()), here);
        assert_eq!(second.current_num_threads(), 1);
    }

    /// With two or more processors, a pinned pool of two runs each thread on a processor of
    /// its own, the first two the process may use; unpinned, each may use them all.
    #[test]
    fn two_threads_are_pinned_one_to_a_processor() {
        let cpus = placement::allowed();
        if cpus.len() < 2 {
            // Nothing to pin to: the pool is built unpinned, which the next lines check.
            let masks = pool(2, true)
                .expect("a pool")
                .broadcast(|_| placement::allowed());
            assert!(masks.iter().all(|m| *m == cpus));
            return;
        }
        let masks = pool(2, true)
            .expect("a pool")
            .broadcast(|_| placement::allowed());
        assert_eq!(masks, vec![vec![cpus[0]], vec![cpus[1]]]);
        let masks = pool(2, false)
            .expect("a pool")
            .broadcast(|_| placement::allowed());
        assert_eq!(masks, vec![cpus.clone(), cpus]);
    }
}
