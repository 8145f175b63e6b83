//! Large products through the dense kernel: split into parts over two threads or run as one
//! part, with the touched accumulators marked (a sparse box) or all of them scanned (a dense
//! box), over Q and over Q(i), the product is the same canonical polynomial, and takes the
//! value of `f(p)·g(p)` at an integer point.

use trigpoly::{Coefficient, Point, Poly, Rational};

use crate::common::{coordinates, p, var, G, Q};

/// `f · g` computed on a rayon pool of `threads` threads.
fn product_on<C: Coefficient>(threads: usize, f: &Poly<C>, g: &Poly<C>) -> Poly<C> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
        .install(|| f * g)
}

#[test]
fn dense_products_split_over_threads_agree_with_one_thread() {
    let vars = coordinates(&["x", "y", "z", "t"]);
    let point = [("x", 2), ("y", -1), ("z", 1), ("t", -1)]
        .iter()
        .fold(Point::new(&vars), |pt, &(name, v)| {
            pt.with(var(&vars, name), Rational::from(v))
        });
    for (f, g) in [
        // 715² ≈ 511k products into a box of 19⁴ ≈ 130k cells: every accumulator is scanned.
        ("(1 + x + y + z + t)^9", "(1 + 2*x - y + 3*z + t)^9"),
        // 715² products into a box of 37⁴ ≈ 1.9M cells: the touched ones are marked.
        ("(1 + x + y + 2*z^3 - t^3)^9", "(1 - x^3 + 3*y^3 + z + t)^9"),
    ] {
        let (f, g): (Q, Q) = (p(&vars, f), p(&vars, g));
        let one = product_on(1, &f, &g);
        let two = product_on(2, &f, &g);
        assert_eq!(one, two);
        // The terms are in canonical order: rebuilding from them (which sorts) changes nothing.
        let rebuilt = Q::from_terms(&vars, one.terms().map(|t| (t.coeff(), t.exponents())));
        assert_eq!(rebuilt.as_ref(), Ok(&one));
        let value = f.eval(&point).unwrap() * g.eval(&point).unwrap();
        assert_eq!(one.eval(&point), Ok(value));
    }
    // Over Q(i) on a sparse box: the accumulators hold both components.
    let (f, g): (G, G) = (
        p(&vars, "(1 + i*x + y + 2*z^3 - t^3)^9"),
        p(&vars, "(1 - x^3 + 3*i*y^3 + z + t)^9"),
    );
    let one = product_on(1, &f, &g);
    assert_eq!(one, product_on(2, &f, &g));
    let value = f.eval(&point).unwrap() * g.eval(&point).unwrap();
    assert_eq!(one.eval(&point), Ok(value));
    assert!(one.terms().any(|t| !t.coeff().is_real()));
}

/// 140 variables pack into 35 words, wider than the heap product's fixed-width keys: a sparse
/// product of two 8-term polynomials shifts and merges instead, and equals the sum of the
/// products by each term.
#[test]
fn products_of_monomials_wider_than_the_heap_keys() {
    let names: Vec<String> = (0..140).map(|k| format!("v{k}")).collect();
    let refs: Vec<&str> = names.iter().map(String::as_str).collect();
    let vars = coordinates(&refs);
    let sum = |terms: Vec<String>| terms.join(" + ");
    let f: Q = p(
        &vars,
        &sum((0..8)
            .map(|k| format!("{} v{}^{}", k + 1, k * 17, 900 + k))
            .collect()),
    );
    let g: Q = p(
        &vars,
        &sum((0..8)
            .map(|k| format!("v{}^{}", k * 13 + 1, 700 + k))
            .collect()),
    );
    let product = f.checked_mul(&g).expect("a product within the limits");
    let by_terms = g
        .terms()
        .map(|t| Q::from_terms(&vars, [(t.coeff(), t.exponents())]).expect("one term"))
        .fold(Q::zero(&vars), |acc, term| &acc + &(&f * &term));
    assert_eq!(product.len(), 64);
    assert_eq!(product, by_terms);
}
