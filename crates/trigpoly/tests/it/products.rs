//! Large products through the dense kernel: split into parts over two threads, written by a
//! second thread as the first adds, or run as one part, with the touched accumulators marked
//! (a sparse box) or all of them scanned (a dense box), over Q and over Q(i), the product is
//! the same canonical polynomial, and takes the value of `f(p)·g(p)` at an integer point.

use trigpoly::{
    AlgebraError, Coefficient, GaussianRational, Limits, Point, Poly, Rational, Var, Vars,
};

use crate::common::{coordinates, p, var, G, Q};

/// `f · g` computed on a rayon pool of `threads` threads.
fn product_on<C: Coefficient>(threads: usize, f: &Poly<C>, g: &Poly<C>) -> Poly<C> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
        .install(|| f * g)
}

/// The point of `vars` with the given integer values.
fn point(vars: &Vars, values: &[(&str, i64)]) -> Point {
    values.iter().fold(Point::new(vars), |pt, &(name, v)| {
        pt.with(var(vars, name), Rational::from(v))
    })
}

/// `f · g` on one thread, checked against the same product on two threads, against the
/// canonical order (rebuilding from its terms, which sorts, changes nothing) and against
/// `f(pt)·g(pt)`.
fn checked_product<C: Coefficient>(f: &str, g: &str, pt: &[(&str, i64)]) -> Poly<C> {
    let vars = coordinates(&["x", "y", "z", "t"]);
    let (f, g): (Poly<C>, Poly<C>) = (p(&vars, f), p(&vars, g));
    let one = product_on(1, &f, &g);
    assert_eq!(one, product_on(2, &f, &g));
    let rebuilt = Poly::<C>::from_terms(&vars, one.terms().map(|t| (t.coeff(), t.exponents())));
    assert_eq!(rebuilt.as_ref(), Ok(&one));
    let pt = point(&vars, pt);
    let value = f.eval(&pt).unwrap() * g.eval(&pt).unwrap();
    assert_eq!(one.eval(&pt), Ok(value));
    one
}

#[test]
fn dense_products_split_over_threads_agree_with_one_thread() {
    let pt = [("x", 2), ("y", -1), ("z", 1), ("t", -1)];
    // 715² ≈ 511k products into a box of 19⁴ ≈ 130k cells: every accumulator is scanned.
    checked_product::<Rational>("(1 + x + y + z + t)^9", "(1 + 2*x - y + 3*z + t)^9", &pt);
    // 715² products into a box of 37⁴ ≈ 1.9M cells: the touched ones are marked.
    checked_product::<Rational>(
        "(1 + x + y + 2*z^3 - t^3)^9",
        "(1 - x^3 + 3*y^3 + z + t)^9",
        &pt,
    );
    // Over Q(i) on a sparse box: the accumulators hold both components. Every coefficient
    // of these factors is real or imaginary (`i^k` times a real one), so each term pair is one
    // real product (the axial cells); with coefficients such as `2 + i` it is a Gaussian one.
    for (f, g) in [
        (
            "(1 + i*x + y + 2*z^3 - t^3)^9",
            "(1 - x^3 + 3*i*y^3 + z + t)^9",
        ),
        (
            "(1 + (2+i)*x + y + 2*z^3 - t^3)^9",
            "(1 - x^3 + (3-i)*y^3 + z + t)^9",
        ),
    ] {
        let product: G = checked_product(f, g, &pt);
        assert!(product.terms().any(|t| !t.coeff().is_real()));
    }
}

/// A square through the dense kernel forms each pair of terms once (the row of term `i` takes
/// the terms after it with `2 a_i`, the diagonal `a_i²` apart) and is the product of the
/// polynomial by a copy of itself, which forms every pair: on a scanned box (split into parts
/// on two threads), a marked one (pipelined on two threads when large), over Q(i) with axial
/// and Gaussian cells, and with a coefficient whose double passes a word (two-word cells).
#[test]
fn squares_through_the_dense_kernel_form_each_pair_once() {
    let vars = coordinates(&["x", "y", "z", "t"]);
    let pt = point(&vars, &[("x", 2), ("y", -1), ("z", 1), ("t", -3)]);
    fn check<C: Coefficient>(f: &Poly<C>, pt: &Point) {
        let copy = f + &Poly::zero(f.vars());
        assert!(!std::ptr::eq(f, &copy));
        for threads in [1, 2] {
            let square = product_on(threads, f, f);
            assert_eq!(square, product_on(threads, f, &copy), "{threads} threads");
            let value = f.eval(pt).unwrap();
            assert_eq!(square.eval(pt), Ok(&value * &value));
        }
    }
    for f in [
        // 715 terms, 715² pairs in a box of 19⁴ cells: scanned.
        "(1 + x + y + z + t)^9",
        // The same in a box of 55⁴ cells: marked; 1820 terms: pipelined on two threads.
        "(1 + x + y + 2*z^3 - t^3)^9",
        "(1 + x + y + 2*z^3 - t^3)^12",
        // 2⁶² + 1, whose double passes an `i64`.
        "(1 + x + y + z + t)^9 + 4611686018427387905*x^9*y^9",
    ] {
        check::<Rational>(&p(&vars, f), &pt);
    }
    for f in [
        "(1 + i*x + y + 2*z^3 - t^3)^9",
        "(1 + (2+i)*x + y + 2*z^3 - t^3)^9",
    ] {
        check::<GaussianRational>(&p(&vars, f), &pt);
    }
}

/// Factors whose exponents of a variable lie a step apart from their least (`x³`, `z²` and
/// `t⁻²` in one, `x⁶`, `z²` and `t⁴` in the other) multiply in a box with the shared steps (3,
/// 2, 2) taken out: indices count steps, and the decoder puts them back. The product is the
/// product of the factors with every step 1 (`x`, `z`, `t⁻¹` ...), with `x³`, `z²` and `t²`
/// put for `x`, `z` and `t` afterwards, and takes the value of `f(p)·g(p)` at a point, on one
/// thread and on two, over Q and over Q(i).
#[test]
fn products_of_factors_in_powers_of_a_variable_take_the_steps_out_of_the_box() {
    let pt = [("x", 2), ("y", -1), ("z", 1), ("t", -1)];
    let stepped = [
        "(1 + x^3 + 2*z^2 - 3*z^4*t^-2 + y)^6",
        "(2 - x^6 + z^2*y + 5*t^4 + z^6)^6",
    ];
    let product: Q = checked_product(stepped[0], stepped[1], &pt);
    let vars = coordinates(&["x", "y", "z", "t"]);
    let unstepped: Q =
        p(&vars, "(1 + x + 2*z - 3*z^2*t^-1 + y)^6") * p(&vars, "(2 - x^2 + z*y + 5*t^2 + z^3)^6");
    let powers =
        [("x", "x^3"), ("z", "z^2"), ("t", "t^2")].map(|(v, e)| (var(&vars, v), p(&vars, e)));
    assert_eq!(unstepped.subst_many(&powers), Ok(product));
    checked_product::<GaussianRational>(
        "(1 + i*x^3 + 2*z^2 - 3*z^4*t^-2 + y)^6",
        "(2 - x^6 + i*z^2*y + 5*t^4 + z^6)^6",
        &pt,
    );
}

/// A sparse product of 1365² ≈ 1.9M term pairs (a box of 67⁴ ≈ 20M cells): on two threads
/// one adds into the accumulators while the other writes the terms, in batches. The product
/// is the one computed on one thread, over Q and over Q(i).
#[test]
fn sparse_products_written_by_a_second_thread_agree_with_one_thread() {
    let pt = [("x", 1), ("y", -1), ("z", 2), ("t", 1)];
    let product: Q = checked_product(
        "(1 + x + y + 2*z^3 - t^3)^11",
        "(1 - x^3 + 3*y^3 + z + t)^11",
        &pt,
    );
    // More terms than one batch carries.
    assert!(product.len() > 1 << 16, "{} terms", product.len());
    checked_product::<GaussianRational>(
        "(1 + i*x + y + 2*z^3 - t^3)^11",
        "(1 - x^3 + 3*i*y^3 + z + t)^11",
        &pt,
    );
}

/// `(P + Q)(P − Q)` in a sparse box (1 430² term pairs in 55⁴ ≈ 9.2M cells): the cross terms
/// `PQ` meet in accumulators that the kernel marks and whose sums cancel, so the product is
/// `P² − Q²`, with only the marked accumulators of nonzero sum read back, on one thread and on
/// two. It is checked against the same product taken through the heap: each factor's terms
/// put in a box far too sparse for the accumulators by a term `x⁶⁰⁰`, whose product is taken
/// back off.
#[test]
fn a_sparse_products_cancelling_sums_leave_no_term() {
    let vars = coordinates(&["x", "y", "z", "t"]);
    let (p_, q_): (Q, Q) = (
        p(&vars, "(1 + x + y + 2*z^3 - t^3)^9"),
        p(&vars, "(1 - x^3 + 3*y^3 + z + t)^9"),
    );
    let (f, g) = (&p_ + &q_, &p_ - &q_);
    let far: Q = p(&vars, "x^600");
    let heap = &(&(&f + &far) * &g) - &(&far * &g);
    let (p2, q2) = (&p_ * &p_, &q_ * &q_);
    for threads in [1, 2] {
        let product = product_on(threads, &f, &g);
        assert_eq!(product, heap);
        assert_eq!(product, &p2 - &q2);
        // Fewer terms than the products of the squares together: the cross terms are gone.
        assert!(product.len() < p2.len() + q2.len());
    }
}

/// A product of more than a million terms, a third of whose coefficients pass a word: the
/// product builds those values in blocks of slots rather than a box each, on one thread and on
/// the writing thread of two. Either product is the other and takes the value `f(p)·g(p)`;
/// each is dropped, the one on a pool of two threads (its coefficients given back in parts,
/// block by block), the other on one, after its clone (whose values are boxed) was checked
/// against it; the clone outlives it.
#[test]
fn a_large_products_values_past_a_word_are_built_in_blocks_and_given_back() {
    let pt = [("x", 1), ("y", -1), ("z", 2), ("t", 1)];
    let vars = coordinates(&["x", "y", "z", "t"]);
    let (f, g): (Q, Q) = (
        p(&vars, "(1 + 3*x + 5*y + 7*z^3 - 11*t^3)^15"),
        p(&vars, "(1 - 13*x^3 + 3*y^3 + 5*z + 7*t)^15"),
    );
    let one = product_on(1, &f, &g);
    assert!(one.len() > 1 << 20, "{} terms", one.len());
    let wide = one.terms().filter(|t| t.coeff().numer().to_i64().is_none());
    assert!(wide.count() > one.len() / 4);
    let two = product_on(2, &f, &g);
    assert_eq!(one, two);
    let value = f.eval(&point(&vars, &pt)).unwrap() * g.eval(&point(&vars, &pt)).unwrap();
    assert_eq!(two.eval(&point(&vars, &pt)), Ok(value.clone()));
    rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .expect("a thread pool")
        .install(move || drop(two));
    let copy = one.clone();
    assert_eq!(&copy - &one, Poly::zero(&vars));
    drop(one);
    assert_eq!(copy.eval(&point(&vars, &pt)), Ok(value));
}

/// Factors with coefficients of 60 and 61 bits: sums of their products could pass `i128`, so
/// the dense kernel adds them in 192-bit accumulators (a product of 715² term pairs in a
/// scanned box, and one of 1365² in a sparse box, written by a second thread on two), over Q
/// and over Q(i). Each is the product on one thread and on two, and takes the value
/// `f(p)·g(p)`.
#[test]
fn products_whose_sums_could_pass_i128_take_broad_accumulators() {
    let pt = [("x", 2), ("y", -1), ("z", 1), ("t", -1)];
    let product: Q = checked_product(
        "(1 + 43*x + 41*y + 37*z + 31*t)^9",
        "(1 - 31*x + 37*y - 41*z + 43*t)^9",
        &pt,
    );
    // Some coefficient takes more than 64 bits.
    assert!(product
        .terms()
        .any(|t| t.coeff().numer().to_i64().is_none()));
    checked_product::<Rational>(
        "(1 + 19*x^3 + 17*y + 13*z^3 + 11*t)^11",
        "(1 + 11*x + 13*y^3 - 17*z + 19*t^3)^11",
        &pt,
    );
    // Over Q(i), with coefficients each real or imaginary, and with general ones.
    for (f, g) in [
        (
            "(1 + 43*i*x + 41*y + 37*z + 31*t)^9",
            "(1 - 31*x + 37*i*y - 41*z + 43*t)^9",
        ),
        (
            "(1 + (43+2*i)*x + 41*y + 37*z + 31*t)^9",
            "(1 - 31*x + (37-3*i)*y - 41*z + 43*t)^9",
        ),
    ] {
        let product: G = checked_product(f, g, &pt);
        assert!(product.terms().any(|t| !t.coeff().is_real()));
    }
}

/// Factors with coefficients of 84 and 71 bits, past a word: the dense kernel takes them in
/// two words and adds their products in 192-bit accumulators, in a scanned box and in a
/// sparse one written by a second thread, over Q and over Q(i).
#[test]
fn products_of_coefficients_past_a_word_take_two_words() {
    let pt = [("x", 2), ("y", -1), ("z", 1), ("t", -1)];
    let product: Q = checked_product(
        "(1 + 233*x + 229*y + 227*z + 223*t)^9",
        "(1 - 223*x + 227*y - 229*z + 233*t)^9",
        &pt,
    );
    // Some coefficient takes more than 128 bits.
    assert!(product
        .terms()
        .any(|t| t.coeff().numer().to_i128().is_none()));
    checked_product::<Rational>(
        "(1 + 37*x^3 + 31*y + 29*z^3 + 23*t)^11",
        "(1 + 23*x + 29*y^3 - 31*z + 37*t^3)^11",
        &pt,
    );
    for (f, g) in [
        (
            "(1 + 233*i*x + 229*y + 227*z + 223*t)^9",
            "(1 - 223*x + 227*i*y - 229*z + 233*t)^9",
        ),
        (
            "(1 + (233+i)*x + 229*y + 227*z + 223*t)^9",
            "(1 - 223*x + (227-2*i)*y - 229*z + 233*t)^9",
        ),
    ] {
        let product: G = checked_product(f, g, &pt);
        assert!(product.terms().any(|t| !t.coeff().is_real()));
    }
}

/// Over Q(i), factors whose coefficients are each real or imaginary, as those of a ladder
/// function `A = p_x + iMωx·(…)` and of `Z^m e^{−inθ}` are, with both kinds in each factor
/// and products of two imaginary coefficients (`i·i = −1`): sums that fit `i128`, sums that
/// could pass it, and coefficients past a word. Each product is the one on two threads, takes
/// the value `f(p)·g(p)`, and equals the product computed through a general Gaussian
/// coefficient: `f·g = f·(g + (1 + i)·m) − (1 + i)·m·f` for a monomial `m`.
#[test]
fn products_of_real_or_imaginary_coefficients_take_one_real_product_a_pair() {
    let pt = [("x", 2), ("y", -1), ("z", 1), ("t", -1)];
    let vars = coordinates(&["x", "y", "z", "t"]);
    let m: G = p(&vars, "(1+i)*x^20*y^20");
    for k in [1, 43, 233] {
        let (a, b, c, d) = (k, k + 2, k + 4, k + 6);
        let f = format!("i*x*(1 + {a}*x + {b}*y + {c}*z + {d}*t)^9 + y^12 - 3*i*z^12");
        let g = format!("(1 - {d}*x + {c}*y - {b}*z + {a}*t)^9 + 5*i*t^12 - 7*i*x^11");
        let product: G = checked_product(&f, &g, &pt);
        assert!(product.terms().any(|t| !t.coeff().is_real()));
        let (f, g): (G, G) = (p(&vars, &f), p(&vars, &g));
        let axial = |h: &G| {
            h.terms()
                .all(|t| t.coeff().is_real() || t.coeff().re.is_zero())
        };
        assert!(axial(&f) && axial(&g));
        assert_eq!(f.clone() * (g + m.clone()) - m.clone() * f, product);
    }
}

/// Products too sparse for the dense accumulators (a box of 21·141·261·581 ≈ 449M cells for
/// 286² ≈ 82k term pairs) whose term pairs meet on few monomials (1771 of them): the hashed
/// product. A square equals the power by the multinomial walk, and a product the one on two
/// threads and its value at a point, over Q and over Q(i).
#[test]
fn sparse_products_whose_term_pairs_meet_are_hashed_exactly() {
    let vars = coordinates(&["x", "y", "z", "t"]);
    let f: Q = p(&vars, "(x + y^7 + 2*z^13 - t^29)^10");
    let square = &f * &f;
    assert_eq!(square, p(&vars, "(x + y^7 + 2*z^13 - t^29)^20"));
    assert_eq!(square.len(), 1771);
    let g: G = p(&vars, "(x + i*y^7 + 2*z^13 - t^29)^10");
    assert_eq!(&g * &g, p(&vars, "(x + i*y^7 + 2*z^13 - t^29)^20"));
    // Coefficients past a word: the sums are the ring's accumulators.
    let h: G = p(&vars, "(x + i*y^7 + 2^40*z^13 - t^29)^10");
    assert_eq!(&h * &h, p(&vars, "(x + i*y^7 + 2^40*z^13 - t^29)^20"));
    let pt = [("x", 1), ("y", -1), ("z", 2), ("t", 1)];
    checked_product::<Rational>(
        "(x + y^7 + 2*z^13 - t^29)^10",
        "(3*x - y^7 + z^13 + t^29)^10",
        &pt,
    );
    checked_product::<GaussianRational>(
        "(x + i*y^7 + 2*z^13 - t^29)^10",
        "(3*x - y^7 + i*z^13 + t^29)^10",
        &pt,
    );
}

/// The same sparse product under a term limit it exceeds: on two threads as on one, the adding
/// side stops at the limit with an error, and the writing side lets go of what it wrote.
#[test]
fn a_sparse_product_written_by_a_second_thread_stops_at_the_term_limit() {
    let vars = ["x", "y", "z", "t"]
        .iter()
        .fold(Vars::builder(), |b, name| b.coordinate(name))
        .limits(Limits::default().max_terms(100_000))
        .build()
        .expect("valid variable names");
    let (f, g): (Q, Q) = (
        p(&vars, "(1 + x + y + 2*z^3 - t^3)^11"),
        p(&vars, "(1 - x^3 + 3*y^3 + z + t)^11"),
    );
    for threads in [1, 2] {
        let product = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a thread pool")
            .install(|| f.checked_mul(&g));
        assert_eq!(
            product.map(|h| h.len()),
            Err(AlgebraError::TooManyTerms { limit: 100_000 })
        );
    }
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

/// The space `x, y, p, θ` of the word-boundary tests, its variables, the point `x = 3,
/// y = −2, p = 5`, and the constant `e^{iθ} = (3 + 4i)/5` (`cos θ = 3/5`, `sin θ = 4/5`) to
/// put for `θ` before evaluating there.
fn word_boundary_space() -> (Vars, [Var; 4], Point, G) {
    let vars = Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .momentum("p")
        .angle("theta")
        .build()
        .unwrap();
    let names = ["x", "y", "p", "theta"].map(|v| var(&vars, v));
    let pt = point(&vars, &[("x", 3), ("y", -2), ("p", 5)]);
    let on_circle = G::constant(
        &vars,
        GaussianRational::new(Rational::new(3, 5), Rational::new(4, 5)),
    );
    (vars, names, pt, on_circle)
}

/// Short products, squares, sums of products and brackets gather their term products in
/// `i128` when the coefficients fit machine words, and as exact integers past a word or past
/// the bits an `i128` sum holds. On both sides of each boundary, over Q and over Q(i): the
/// product, the square and the sum `(3/2)·f·g + f² − g²` take the values of `f(p)·g(p)`,
/// `f(p)²` and the sum of those, and the bracket equals the one built from the derivatives,
/// each taken and multiplied on its own.
#[test]
fn short_products_squares_sums_and_brackets_on_both_sides_of_the_word_boundary() {
    let (vars, [x, y, pm, theta], pt, on_circle) = word_boundary_space();
    let coefficients = [
        "3", "2^31", "2^55", "2^56 + 1", "2^62", "2^63 - 1", "-2^63", "2^63", "2^64 + 7", "2^100",
    ];
    for c in coefficients {
        for unit in ["1", "(2 - 3*i)"] {
            let f: G = p(
                &vars,
                &format!("{unit}*({c})*x*y*p - 5*x^2 + ({c})*y^2*cos(theta) + {unit}"),
            );
            let g: G = p(&vars, &format!("x*p^2 - ({c})*y^3 + 7*{unit}*sin(theta)"));
            let at = |h: &G| h.subst(theta, &on_circle).and_then(|h| h.eval(&pt));
            let (fp, gp) = (at(&f).unwrap(), at(&g).unwrap());
            assert_eq!(at(&(&f * &g)), Ok(&fp * &gp), "f·g with c = {c}");
            assert_eq!(
                at(&f.checked_pow(2).unwrap()),
                Ok(&fp * &fp),
                "f² with c = {c}"
            );
            let three_halves = GaussianRational::from(Rational::new(3, 2));
            let sum = G::sum_of_products(&[
                (&f.scale(&three_halves), &g, false),
                (&f, &f, false),
                (&g, &g, true),
            ]);
            let expected = &(&(&three_halves * &(&fp * &gp)) + &(&fp * &fp)) - &(&gp * &gp);
            assert_eq!(
                sum.and_then(|s| at(&s)),
                Ok(expected),
                "(3/2)·f·g + f² − g² with c = {c}"
            );
            let pairs = [(x, pm), (theta, y)];
            let direct = pairs.iter().fold(G::zero(&vars), |sum, &(q, m)| {
                let d = |h: &G, v| h.derivative(v).unwrap();
                &(&sum + &(&d(&f, q) * &d(&g, m))) - &(&d(&f, m) * &d(&g, q))
            });
            assert_eq!(
                G::sum_of_jacobians(&f, &g, &pairs),
                Ok(direct),
                "{{f, g}} with c = {c}"
            );
        }
        // Over Q, where the gather's word path has no `i` to multiply by.
        let f: Q = p(&vars, &format!("({c})*x*y*p - 5*x^2 + ({c})*y^2 + 1"));
        let g: Q = p(&vars, &format!("x*p^2 - ({c})*y^3 + 7"));
        let (fp, gp) = (f.eval(&pt).unwrap(), g.eval(&pt).unwrap());
        assert_eq!(
            (&f * &g).eval(&pt),
            Ok(&fp * &gp),
            "f·g over Q with c = {c}"
        );
        assert_eq!(f.checked_pow(2).unwrap().eval(&pt), Ok(&fp * &fp));
        let sum = Q::sum_of_products(&[(&f, &g, true), (&g, &g, false), (&f, &f, false)]);
        assert_eq!(
            sum.and_then(|s| s.eval(&pt)),
            Ok(&(&(&gp * &gp) + &(&fp * &fp)) - &(&fp * &gp)),
            "f² + g² − f·g over Q with c = {c}"
        );
        let direct = &(&f.derivative(x).unwrap() * &g.derivative(pm).unwrap())
            - &(&f.derivative(pm).unwrap() * &g.derivative(x).unwrap());
        assert_eq!(Q::sum_of_jacobians(&f, &g, &[(x, pm)]), Ok(direct));
    }
}

/// Over Q(i), factors whose coefficients are all real gather in Z's words, with one product
/// per term pair where a Gaussian takes four; a bracket on a pair with an angle, whose
/// derivative brings `i`, does not. On both sides of the word boundary: the product, the
/// square, the sum `(3/2)·f·g + f² − g²` and the brackets on `(x, p)` alone and with
/// `(θ, y)` take the values that the factors and their derivatives give at a point.
#[test]
fn real_factors_over_q_i_gather_in_integer_words() {
    let (vars, [x, y, pm, theta], pt, on_circle) = word_boundary_space();
    let at = |h: &G| {
        h.subst(theta, &on_circle)
            .and_then(|h| h.eval(&pt))
            .unwrap()
    };
    for c in ["3", "2^31", "2^62", "2^63 - 1", "2^63", "2^100"] {
        // cos θ = (e^{iθ} + e^{−iθ})/2 and cos 2θ have real coefficients.
        let f: G = p(
            &vars,
            &format!("({c})*x*y*p - 5*x^2 + ({c})*y^2*cos(theta) + 1"),
        );
        let g: G = p(&vars, &format!("x*p^2 - ({c})*y^3 + 7*cos(2*theta)"));
        assert!(f.is_real() && g.is_real());
        let (fp, gp) = (at(&f), at(&g));
        assert_eq!(at(&(&f * &g)), &fp * &gp, "f·g with c = {c}");
        assert_eq!(at(&f.checked_pow(2).unwrap()), &fp * &fp, "f² with c = {c}");
        let three_halves = GaussianRational::from(Rational::new(3, 2));
        let sum = G::sum_of_products(&[
            (&f.scale(&three_halves), &g, false),
            (&f, &f, false),
            (&g, &g, true),
        ])
        .unwrap();
        let expected = &(&(&three_halves * &(&fp * &gp)) + &(&fp * &fp)) - &(&gp * &gp);
        assert_eq!(at(&sum), expected, "(3/2)·f·g + f² − g² with c = {c}");
        let d = |h: &G, v| at(&h.derivative(v).unwrap());
        let jacobian = |q, m| &(&d(&f, q) * &d(&g, m)) - &(&d(&f, m) * &d(&g, q));
        let flat = G::sum_of_jacobians(&f, &g, &[(x, pm)]).unwrap();
        assert_eq!(
            at(&flat),
            jacobian(x, pm),
            "{{f, g}} on (x, p) with c = {c}"
        );
        let angled = G::sum_of_jacobians(&f, &g, &[(x, pm), (theta, y)]).unwrap();
        assert_eq!(
            at(&angled),
            &jacobian(x, pm) + &jacobian(theta, y),
            "{{f, g}} on (x, p), (θ, y) with c = {c}"
        );
    }
}
