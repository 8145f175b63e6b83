//! Products over Q. The Fateman benchmark: `f = (1 + x + y + z + t)^n`, the product
//! `f·(f + 1)` (dense); for n = 20 it has C(44, 4) = 135751 terms, n = 10 (10626 terms) runs
//! quickly. And a sparse square whose term pairs meet on few monomials (the hashed product):
//! `g = (x + y^7 + 2z^13 − t^23)^20`, 1771 terms, `g²` 3.1 M term pairs onto 12341 terms in a
//! box of some 10¹¹ cells; and over Q(i) with coefficients past a word, each real or
//! imaginary, `(3x + 5iy^7 + 7z^13 − 11it^23)^20` squared (the 256-bit sums).

use divan::{black_box, Bencher};
use trigpoly::{Coefficient, GaussianRational, Poly, Rational, Vars};

fn main() {
    divan::main();
}

type Q = Poly<Rational>;

/// The coordinates `x, y, z, t`.
fn xyzt() -> Vars {
    Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .coordinate("z")
        .coordinate("t")
        .build()
        .expect("valid names")
}

/// `f` and `f + 1`, with the term count of their product checked once, outside the timing.
fn fateman(n: u64) -> (Q, Q) {
    let vars = xyzt();
    let f = Q::parse(&vars, &format!("(1 + x + y + z + t)^{n}")).expect("parses");
    let g = &f + &Q::one(&vars);
    // Monomials of total degree ≤ 2n in 4 variables: C(2n + 4, 4).
    let m = 2 * n + 4;
    let terms = m * (m - 1) * (m - 2) * (m - 3) / 24;
    assert_eq!(
        f.checked_mul(&g).expect("within the limits").len() as u64,
        terms
    );
    (f, g)
}

#[divan::bench(sample_count = 10, sample_size = 1)]
fn fateman_10(bencher: Bencher) {
    let (f, g) = fateman(10);
    bencher.bench(|| {
        black_box(&f)
            .checked_mul(black_box(&g))
            .expect("within the limits")
    });
}

#[divan::bench(sample_count = 3, sample_size = 1)]
fn fateman_20(bencher: Bencher) {
    let (f, g) = fateman(20);
    assert_eq!(f.len(), 10626);
    bencher.bench(|| {
        black_box(&f)
            .checked_mul(black_box(&g))
            .expect("within the limits")
    });
}

/// The square of `(base)^20` (1771 terms), checked against the multinomial power `(base)^40`
/// once, outside the timing; `terms` of the square.
fn meeting<C: Coefficient>(bencher: Bencher, base: &str) -> usize {
    let vars = xyzt();
    let g = Poly::<C>::parse(&vars, &format!("({base})^20")).expect("parses");
    assert_eq!(g.len(), 1771);
    let square = g.checked_mul(&g).expect("within the limits");
    let power = Poly::<C>::parse(&vars, &format!("({base})^40")).expect("parses");
    assert_eq!(square, power);
    bencher.bench(|| {
        black_box(&g)
            .checked_mul(black_box(&g))
            .expect("within the limits")
    });
    square.len()
}

#[divan::bench(sample_count = 10, sample_size = 1)]
fn meeting_square(bencher: Bencher) {
    assert_eq!(
        meeting::<Rational>(bencher, "x + y^7 + 2*z^13 - t^23"),
        12341
    );
}

#[divan::bench(sample_count = 10, sample_size = 1)]
fn meeting_square_past_a_word(bencher: Bencher) {
    meeting::<GaussianRational>(bencher, "3*x + 5*i*y^7 + 7*z^13 - 11*i*t^23");
}
