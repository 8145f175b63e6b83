//! The performance workloads W1–W4 (`superint::workloads`) under divan: the same code the
//! `bench` subcommand and the peer comparison run. `cargo bench --bench workloads`.
//!
//! For repeatable figures on a noisy machine, count instructions instead:
//! `valgrind --tool=callgrind target/release/superint bench W1 8`.

use divan::Bencher;
use superint::workloads::Workload;

/// The allocator of the `superint` binary, so that these figures match `superint bench`.
#[global_allocator]
static ALLOCATOR: superint::allocator::Allocator = superint::allocator::Allocator;

fn main() {
    superint::allocator::configure();
    divan::main();
}

fn run(bencher: Bencher, workload: Workload) {
    // Check once, outside the timing, that the workload's identities hold.
    let outcome = workload.run().expect("the workload's identities hold");
    assert!(outcome.terms > 0);
    bencher.bench(|| divan::black_box(workload.run().expect("holds")));
}

/// W1: {P, H} and {Q, H} at resonance for all 1 ≤ m, n ≤ N.
#[divan::bench(args = [8, 16], sample_count = 5)]
fn w1_tower(bencher: Bencher, n: i64) {
    run(bencher, Workload::Tower(n));
}

/// W2: one pair m = n.
#[divan::bench(args = [40, 80], sample_count = 3)]
fn w2_single(bencher: Bencher, m: i64) {
    run(bencher, Workload::Single(m));
}

/// W3a: the Fateman product f·(f + 1), f = (1 + x + y + z + t)^N.
#[divan::bench(args = [12, 20], sample_count = 5)]
fn w3a_fateman(bencher: Bencher, n: i64) {
    run(bencher, Workload::Fateman(n));
}

/// W3b: the sparse Pearce product.
#[divan::bench(args = [8, 12], sample_count = 3)]
fn w3b_pearce(bencher: Bencher, n: i64) {
    run(bencher, Workload::Pearce(n));
}

/// W4: the su(2) brackets and the Casimir, N times.
#[divan::bench(args = [100, 1000], sample_count = 5)]
fn w4_algebra(bencher: Bencher, n: i64) {
    run(bencher, Workload::Algebra(n));
}
