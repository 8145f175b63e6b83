//! What one operation on short polynomials costs, from a one-term input to the generators of
//! su(2): the fixed part of each operation (checks, set-up, the result's two vectors, the
//! drop) against its work. W4 is made of such operations, and about half of a repetition is
//! their fixed parts (docs/performance.md, forty-fourth session): these are the figures a
//! representation of short polynomials must bring down. `cargo bench --bench operations`.
//!
//! Every result is dropped inside the timing, as in a workload ([`time`]). For repeatable
//! counts, `valgrind --tool=callgrind` on a loop of one operation.

use brackets::{systems, System};
use divan::{black_box, Bencher};
use trigpoly::{Expr, GaussianRational};

/// The allocator of the `superint` binary, so that these figures match `superint bench`.
#[global_allocator]
static ALLOCATOR: superint::allocator::Allocator = superint::allocator::Allocator;

fn main() {
    superint::allocator::configure();
    divan::main();
}

/// A function of the harmonic rotor, by name or expression.
fn parse(rotor: &System, src: &str) -> Expr {
    rotor.parse(src).expect("parses")
}

/// Times `op` with the drop of its result: divan drops what a benchmark returns after the
/// sample, so the benchmark itself returns nothing.
fn time<T>(bencher: Bencher, op: impl Fn() -> T + Sync) {
    bencher.bench(|| drop(black_box(op())));
}

#[divan::bench]
fn clone_one_term(bencher: Bencher) {
    let rotor = systems::harmonic_rotor();
    let x = parse(&rotor, "x");
    time(bencher, || black_box(&x).clone());
}

#[divan::bench]
fn product_one_term(bencher: Bencher) {
    let rotor = systems::harmonic_rotor();
    let (x, y) = (parse(&rotor, "x"), parse(&rotor, "y"));
    assert_eq!(x.checked_mul(&y).expect("fits"), parse(&rotor, "x*y"));
    time(bencher, || {
        black_box(&x).checked_mul(black_box(&y)).expect("fits")
    });
}

#[divan::bench]
fn sum_one_term(bencher: Bencher) {
    let rotor = systems::harmonic_rotor();
    let (x, y) = (parse(&rotor, "x"), parse(&rotor, "y"));
    time(bencher, || {
        black_box(&x).checked_add(black_box(&y)).expect("fits")
    });
}

#[divan::bench]
fn scale_one_term(bencher: Bencher) {
    let rotor = systems::harmonic_rotor();
    let x = parse(&rotor, "x");
    let four = GaussianRational::from(4);
    time(bencher, || black_box(&x).scale(black_box(&four)));
}

/// Times `{f, g}` of the rotor, after checking that it is `expected`.
fn time_bracket(bencher: Bencher, f: &str, g: &str, expected: &str) {
    let rotor = systems::harmonic_rotor();
    let (f, g) = (parse(&rotor, f), parse(&rotor, g));
    assert_eq!(
        rotor.bracket(&f, &g).expect("forms"),
        parse(&rotor, expected)
    );
    time(bencher, || {
        rotor.bracket(black_box(&f), black_box(&g)).expect("forms")
    });
}

/// `{x, p_x} = 1`: one term pair.
#[divan::bench]
fn bracket_one_term(bencher: Bencher) {
    time_bracket(bencher, "x", "p_x", "1");
}

/// `{L, G1} = −G2`: 2 × 2 terms, 8 term pairs.
#[divan::bench]
fn bracket_of_generators(bencher: Bencher) {
    time_bracket(bencher, "L", "G1", "-G2");
}

/// `G2²`: 4 × 4 terms, onto 10 (the squares of the four and their six cross products).
#[divan::bench]
fn square_of_a_generator(bencher: Bencher) {
    let rotor = systems::harmonic_rotor();
    let g2 = parse(&rotor, "G2");
    assert_eq!(g2.checked_mul(&g2).expect("fits").len(), 10);
    time(bencher, || {
        black_box(&g2).checked_mul(black_box(&g2)).expect("fits")
    });
}
