//! Limits: runaway expansions and exponents end in an error value, never in an allocation
//! blow-up, a wrapped exponent or a panic.

use trigpoly::{AlgebraError, Limits, Poly, Rational, Setting, VarSet, Vars};

use crate::common::{coordinates, p, phase_space, var, G, Q};

fn small_vars() -> Vars {
    Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .coordinate("z")
        .coordinate("t")
        .coordinate("u")
        .coordinate("v")
        .coordinate("w")
        // Exponents up to 39² below: a degree limit above the default.
        .limits(Limits::default().max_terms(1000).max_degree(10_000))
        .build()
        .unwrap()
}

/// `x, y, z, t` with a work limit of `products` term products a product.
fn work_vars(products: u64) -> Vars {
    Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .coordinate("z")
        .coordinate("t")
        .limits(Limits::default().max_term_products(products))
        .build()
        .unwrap()
}

/// A product is refused before it starts when it would form more term products than the
/// work limit: `n·m`, or `n(n + 1)/2` for a square; at the limit it is formed. A power of a
/// long polynomial stops at its first product past the limit, where it used to multiply for
/// a quarter of an hour before the term limit stopped it (found by the fuzzer, seed 1202:
/// `Z̄^3` with a `Z̄` of 46 379 terms, 3.2·10¹⁰ term products).
#[test]
fn work_limit_refuses_a_product_before_it_starts() {
    // (1 + x + y + z + t)^4 has C(8, 4) = 70 terms, (1 + x + y + z + t)^3 has 35.
    let (f4, f3) = ("(1 + x + y + z + t)^4", "(1 + x + y + z + t)^3");
    let at = |limit: u64| -> (Q, Q) { (p(&work_vars(limit), f4), p(&work_vars(limit), f3)) };
    let (f, g) = at(70 * 35);
    assert_eq!(f.checked_mul(&g).map(|h| h.len()), Ok(C(11, 4)));
    let (f, g) = at(70 * 35 - 1);
    assert_eq!(
        f.checked_mul(&g).map(|h| h.len()),
        Err(AlgebraError::TooMuchWork {
            left: 35,
            right: 70,
            products: 70 * 35,
            limit: 70 * 35 - 1,
        })
    );
    // A square takes each pair of terms once: 70·71/2 = 2485.
    let (f, _) = at(2485);
    assert_eq!(f.checked_pow(2).map(|h| h.len()), Ok(C(12, 4)));
    let (f, _) = at(2484);
    let err = f.checked_pow(2).unwrap_err();
    assert!(
        matches!(err, AlgebraError::TooMuchWork { products: 2485, .. }),
        "{err}"
    );
    assert_eq!(
        err.to_string(),
        "the product of 70 terms by 70 would form 2485 term products, past the limit of 2484 \
         (the work limit); raise the limit or simplify the input"
    );
    // f^3 = f²·f: 495 · 70 = 34650 term products for its second product.
    let (f, _) = at(34_650);
    assert_eq!(f.checked_pow(3).map(|h| h.len()), Ok(C(16, 4)));
    let (f, _) = at(34_649);
    assert!(matches!(
        f.checked_pow(3),
        Err(AlgebraError::TooMuchWork {
            products: 34_650,
            ..
        })
    ));
    // A short factor shifts and merges, linear work, whatever the limit.
    let product = |limit| {
        let vars = work_vars(limit);
        let (f, short): (Q, Q) = (p(&vars, f4), p(&vars, "x + y - 2"));
        f.checked_mul(&short).map(|h| h.to_string())
    };
    assert_eq!(product(1), product(u64::MAX));
    assert!(product(1).is_ok());
}

/// A sum of products counts their term products together against the work limit, before it
/// forms any (a bracket's four products of 4·10⁹ each passed the limit of 10¹⁰ one by one and
/// ran 200 s): at the total it is formed, one below it is refused, and a product past the
/// limit alone is refused as a product is.
#[test]
fn work_limit_counts_a_sums_products_together() {
    let (f4, f3) = ("(1 + x + y + z + t)^4", "(1 + x + y + z + t)^3");
    // f4·f3 − f3·f4: two products of 70·35 = 2450 term products, 4900 together.
    let sum = |limit: u64| {
        let vars = work_vars(limit);
        let (f, g): (Q, Q) = (p(&vars, f4), p(&vars, f3));
        Poly::sum_of_products(&[(&f, &g, false), (&g, &f, true)]).map(|h| h.len())
    };
    assert_eq!(sum(4900), Ok(0));
    let err = sum(4899).unwrap_err();
    assert_eq!(
        err,
        AlgebraError::TooMuchSummedWork {
            products: 2,
            largest: (35, 70),
            total: 4900,
            limit: 4899,
        }
    );
    assert_eq!(err.limit(), Some(trigpoly::LimitKind::Work));
    assert_eq!(
        err.to_string(),
        "a sum of 2 products (as a bracket is) would form 4900 term products in all (the \
         largest, 35 terms by 70), past the limit of 4899 (the work limit); raise the limit or \
         simplify the input"
    );
    assert!(matches!(
        sum(2449),
        Err(AlgebraError::TooMuchWork { products: 2450, .. })
    ));
}

/// A sum of products checks and counts only the products that a product alone would check:
/// one of few enough term products to be gathered in one table (7 terms by 7, 49) is formed
/// whatever the work limit, alone and in a sum too long to be gathered as a whole (six such
/// products, 294 term products), as it was before sums were counted; it was refused as "the
/// product of 7 terms by 7 would form 49 term products, past the limit of 48".
#[test]
fn work_limit_lets_a_sums_gathered_products_through() {
    let vars = work_vars(48);
    let f: Q = p(&vars, "1 + x + y + z + t + x^2 + y^2");
    let gs: Vec<Q> = (1..=6)
        .map(|k| {
            p(
                &vars,
                &format!("{k} + x*y + y*z + z*t + t*x + x*z^{k} + y*t"),
            )
        })
        .collect();
    assert!(gs.iter().all(|g| (f.len(), g.len()) == (7, 7)));
    // Alone, each product is formed past the limit; their sum is theirs.
    let mut expected = Poly::zero(&vars);
    for g in &gs {
        expected = &expected + &f.checked_mul(g).unwrap();
    }
    let terms: Vec<(&Q, &Q, bool)> = gs.iter().map(|g| (&f, g, false)).collect();
    assert_eq!(Poly::sum_of_products(&terms), Ok(expected));
}

/// The binomial coefficient `C(n, k)`: the terms of `(1 + x_1 + … + x_k)^(n − k)`.
#[allow(non_snake_case)]
fn C(n: usize, k: usize) -> usize {
    (0..k).fold(1, |c, j| c * (n - j) / (j + 1))
}

/// `(1 + x + y + z)^30` has C(33, 3) = 5456 terms, past the limit of 1000.
#[test]
fn term_limit_stops_a_power_of_a_short_polynomial() {
    let vars = small_vars();
    let f: Q = p(&vars, "1 + x + y + z");
    assert_eq!(
        f.checked_pow(30).map(|g| g.len()),
        Err(AlgebraError::TooManyTerms { limit: 1000 })
    );
    // Just below the limit it works: (1 + x + y + z)^15 has C(18, 3) = 816 terms.
    assert_eq!(f.checked_pow(15).map(|g| g.len()), Ok(816));
}

/// `x, y, z, t, u` with a term limit of 10¹² and the memory cap `max_reserved_bytes`.
fn capped_vars(max_reserved_bytes: u64) -> Vars {
    ["x", "y", "z", "t", "u"]
        .into_iter()
        .fold(Vars::builder(), |b, name| b.coordinate(name))
        .limits(
            Limits::default()
                .max_terms(1_000_000_000_000)
                .max_reserved_bytes(max_reserved_bytes),
        )
        .build()
        .unwrap()
}

/// A power whose room, reserved from its predicted count of terms, would pass the cap on
/// memory (`Limits::max_reserved_bytes`) is `TooLargeForMemory` before any work, as when the
/// allocator
/// refuses it: `(1 + x + y + z + t + u)^300`, of C(305, 5) = 21 281 794 436 terms (about
/// 340 GB), was granted its room by an allocator under Linux's overcommit and filled the
/// machine's memory; under a cap of a mebibyte it stops at once, with nothing allocated (its
/// walk would form the terms). The cap alone refuses: `(1 + x + y + z + t + u)^30`, of
/// C(35, 5) = 324 632 terms, a few megabytes, is refused under the cap and formed without it.
#[test]
fn a_power_past_the_memory_cap_is_refused_before_any_work() {
    let capped = capped_vars(1 << 20);
    let f: Q = p(&capped, "1 + x + y + z + t + u");
    let err = f.checked_pow(300).map(|g| g.len()).unwrap_err();
    let AlgebraError::TooLargeForMemory { terms, bytes } = err else {
        panic!("{err:?}");
    };
    assert_eq!(terms, C(305, 5) as u128);
    assert!(
        bytes > 300_000_000_000 && bytes < isize::MAX as u128,
        "{bytes}"
    );
    assert_eq!(err.limit(), Some(trigpoly::LimitKind::Memory));
    match f.checked_pow(30) {
        Err(AlgebraError::TooLargeForMemory { terms, bytes }) => {
            assert_eq!(terms, C(35, 5) as u128);
            assert!(bytes > 1 << 20, "{bytes}");
        }
        other => panic!("{:?}", other.map(|g| g.len())),
    }
    let uncapped = capped_vars(Limits::NO_MEMORY_CAP);
    let g: Q = p(&uncapped, "1 + x + y + z + t + u");
    assert_eq!(g.checked_pow(30).map(|g| g.len()), Ok(C(35, 5)));
    assert_eq!(Limits::default().max_reserved_bytes, Limits::NO_MEMORY_CAP);
}

/// The cap on memory counts all that a power by the multinomial theorem holds at once, not its
/// terms as formed alone: `(1 + x + y + z + t + u)^30`, C(35, 5) = 324 632 terms of one word
/// and a one-word coefficient (16 bytes each), holds them (5 194 112 bytes), their order for
/// the sort (8 bytes a term, 2 597 056) and the terms combined, as many since each composition
/// is a monomial of its own (5 194 112): 12 985 280 bytes. Under a cap of the first two alone
/// it was let through, and the room for the terms combined was compared to the cap alone, as
/// though nothing else were held; it is refused before any work now, and formed under a cap
/// of all three. Where compositions share a monomial, `(1 + x + … + x⁵)^30` of 151 terms, only
/// the room for the distinct terms is counted (and reserved): the cap refuses nothing that
/// fits.
#[test]
fn the_memory_cap_counts_what_a_power_holds_at_once() {
    let n = C(35, 5) as u64;
    let (formed, order) = (16 * n, 8 * n);
    let at_once = formed + order + formed;
    let f: Q = p(&capped_vars(formed + order), "1 + x + y + z + t + u");
    match f.checked_pow(30) {
        Err(AlgebraError::TooLargeForMemory { terms, bytes }) => {
            assert_eq!((terms, bytes), (u128::from(n), u128::from(at_once)));
        }
        other => panic!("{:?}", other.map(|g| g.len())),
    }
    let g: Q = p(&capped_vars(at_once), "1 + x + y + z + t + u");
    assert_eq!(g.checked_pow(30).map(|g| g.len()), Ok(C(35, 5)));
    let shared: Q = p(
        &capped_vars(formed + order + 151 * 16),
        "1 + x + x^2 + x^3 + x^4 + x^5",
    );
    assert_eq!(shared.checked_pow(30).map(|g| g.len()), Ok(151));
}

/// The same through the general (dense or heap) product: `(1 + x + … + w)^6` has C(13, 6) =
/// 1716 terms.
#[test]
fn term_limit_stops_a_power_of_a_long_polynomial() {
    let vars = small_vars();
    let f: Q = p(&vars, "1 + x + y + z + t + u + v + w");
    assert_eq!(
        f.checked_pow(6).map(|g| g.len()),
        Err(AlgebraError::TooManyTerms { limit: 1000 })
    );
    let g: Q = p(&vars, "1 + x + y + z + t + u + v");
    assert_eq!(g.checked_mul(&g).map(|h| h.len()), Ok(28));
}

/// A sparse product (the heap method: the box of `Σ x^{k²} · Σ y^{k²}` is thousands of times
/// larger than the work) stops at the limit: 40 × 40 distinct terms against 1000, while
/// 30 × 30 = 900 fit.
#[test]
fn term_limit_stops_a_sparse_heap_product() {
    let vars = small_vars();
    let squares = |v: &str, n: i64| -> Q {
        let src: Vec<String> = (0..n).map(|k| format!("{v}^{}", k * k)).collect();
        p(&vars, &src.join(" + "))
    };
    let (f, g) = (squares("x", 40), squares("y", 40));
    assert_eq!(
        f.checked_mul(&g).map(|h| h.len()),
        Err(AlgebraError::TooManyTerms { limit: 1000 })
    );
    assert_eq!(
        squares("x", 30)
            .checked_mul(&squares("y", 30))
            .map(|h| h.len()),
        Ok(900)
    );
}

/// A product of a short polynomial (at most 6 terms) by a long one, past the limit.
#[test]
fn term_limit_stops_a_short_times_long_product() {
    let vars = small_vars();
    let long: Q = p(&vars, "(1 + x + y + z + t + u + v)^4"); // C(10, 4) = 210 terms
    assert_eq!(long.len(), 210);
    let short: Q = p(&vars, "1 + w + w^2 + w^3 + w^4 + w^5");
    // 210 · 6 = 1260 distinct terms.
    assert_eq!(
        long.checked_mul(&short).map(|h| h.len()),
        Err(AlgebraError::TooManyTerms { limit: 1000 })
    );
    let shorter: Q = p(&vars, "1 + w + w^2 + w^3");
    assert_eq!(long.checked_mul(&shorter).map(|h| h.len()), Ok(840));
}

#[test]
fn term_limit_stops_a_sum() {
    let vars = small_vars();
    let f: Q = p(&vars, "(1 + x + y)^30"); // C(32, 2) = 496 terms
    let g: Q = p(&vars, "(1 + z + t)^30");
    assert_eq!(f.len(), 496);
    // 496 + 496 − 1 (the shared constant 1) = 991 terms: within the limit.
    assert_eq!(f.checked_add(&g).map(|h| h.len()), Ok(991));
    let h: Q = p(&vars, "(1 + u + v)^30");
    assert_eq!(
        f.checked_add(&g)
            .and_then(|fg| fg.checked_add(&h))
            .map(|s| s.len()),
        Err(AlgebraError::TooManyTerms { limit: 1000 })
    );
}

#[test]
fn exponent_overflow_in_products_and_powers_is_an_error() {
    let vars = phase_space();
    let x = var(&vars, "x");
    let too_large = |exponent: i64| AlgebraError::ExponentTooLarge {
        var: "x".into(),
        exponent,
        limit: 1000,
    };
    let big: G = p(&vars, "x^1000");
    let xv: G = p(&vars, "x");
    assert_eq!(big.checked_mul(&xv), Err(too_large(1001)));
    assert_eq!(big.checked_mul(&big), Err(too_large(2000)));
    let half: G = p(&vars, "x^500 + 1");
    assert_eq!(half.checked_pow(3), Err(too_large(1500)));
    assert_eq!(half.checked_pow(2).map(|f| f.degree(x)), Ok(Some(1000)));
    assert_eq!(xv.checked_pow(i64::MAX), Err(too_large(i64::MAX)));
    assert_eq!(xv.checked_pow(i64::MIN), Err(too_large(i64::MIN)));
    let low: G = p(&vars, "x^-1000");
    assert_eq!(low.derivative(x), Err(too_large(-1001)));
    assert_eq!(
        Poly::<Rational>::monomial(&vars, Rational::one(), &[(x, 1001)]),
        Err(too_large(1001))
    );
    assert_eq!(
        G::exp_i(&vars, var(&vars, "theta"), -1001).map(|f| f.len()),
        Err(AlgebraError::OrderTooLarge {
            angle: "θ".into(),
            order: 1001,
            limit: 1000
        })
    );
}

#[test]
fn exponent_overflow_with_narrow_exponent_fields() {
    let vars = Vars::builder()
        .coordinate("x")
        .angle("theta")
        .exponent_bits(8)
        .build()
        .unwrap();
    assert_eq!(vars.limits().max_degree, 127);
    let x = var(&vars, "x");
    let f: G = p(&vars, "x^100");
    assert_eq!(
        f.checked_mul(&f),
        Err(AlgebraError::ExponentTooLarge {
            var: "x".into(),
            exponent: 200,
            limit: 127
        })
    );
    let e: G = p(&vars, "exp(i*100*theta)");
    assert_eq!(
        e.checked_pow(-2),
        Err(AlgebraError::OrderTooLarge {
            angle: "θ".into(),
            order: 200,
            limit: 127
        })
    );
    // At the limit the packed field is exact, both signs.
    let top: G = p(&vars, "x^127 + x^-127");
    assert_eq!(top.exponent_range(x), Some((-127, 127)));
    assert_eq!(&top * &G::one(&vars), top);
}

/// Without a requested width the packing follows the degree limit: the fewest words whose
/// fields hold it, and a new limit packs anew (a requested width stays).
#[test]
fn exponent_fields_follow_the_degree_limit() {
    let five = coordinates(&["x", "y", "z", "t", "u"]);
    assert_eq!((five.exponent_bits(), five.monomial_words()), (12, 1));
    let phase = phase_space();
    assert_eq!((phase.len(), phase.monomial_words()), (8, 2));
    let with_degree = |vars: &VarSet, max_degree| {
        let limits = vars.limits().max_degree(max_degree);
        let v = vars.with_limits(limits).unwrap();
        (v.exponent_bits(), v.monomial_words(), v.limits().max_degree)
    };
    assert_eq!(with_degree(&five, 10_000), (21, 2, 10_000));
    assert_eq!(with_degree(&five, 100), (12, 1, 100));
    let asked = Vars::builder()
        .coordinate("x")
        .exponent_bits(16)
        .build()
        .unwrap();
    assert_eq!(with_degree(&asked, 100_000), (16, 1, 32_767));
    // Asking for the width the limit would choose declares the same ring.
    let chosen = coordinates(&["x"]);
    let named = Vars::builder()
        .coordinate("x")
        .exponent_bits(chosen.exponent_bits())
        .build()
        .unwrap();
    assert_eq!(named, chosen);
    let thirteen = Vars::builder()
        .coordinate("x")
        .exponent_bits(13)
        .build()
        .map(|v| v.len());
    assert_eq!(
        thirteen,
        Err(AlgebraError::SettingOutOfRange {
            setting: Setting::ExponentBits,
            value: 13
        })
    );
    assert_eq!(
        thirteen.unwrap_err().to_string(),
        "exponent bits must be one of [8, 10, 12, 16, 21, 32], not 13"
    );
}

/// A degree limit of 0 is refused where the set is built: under it even `x` was past the
/// limit, and reading `x` panicked.
#[test]
fn a_degree_limit_of_zero_is_refused() {
    let zero = Limits::default().max_degree(0);
    let refused = Err(AlgebraError::SettingOutOfRange {
        setting: Setting::MaxDegree,
        value: 0,
    });
    let built = Vars::builder().coordinate("x").limits(zero).build();
    let built = built.map(|v| v.len());
    assert_eq!(built, refused);
    assert_eq!(
        built.unwrap_err().to_string(),
        "the degree limit (max_degree) must be at least 1: at 0 no variable could be written, \
         not even x itself"
    );
    let x = coordinates(&["x"]);
    assert_eq!(x.with_limits(zero).map(|v| v.len()), refused);
    let one = x.with_limits(Limits::default().max_degree(1)).unwrap();
    assert_eq!(Poly::<Rational>::parse(&one, "x").unwrap().to_string(), "x");
    let err = Poly::<Rational>::parse(&one, "x^2").unwrap_err();
    assert!(err.to_string().contains("past the limit of 1"), "{err}");
}

/// Twelve-bit fields leave four bits over at the bottom of each word: the last variable's
/// field sits above them, and its exponents are as exact and as checked as the first's.
#[test]
fn twelve_bit_fields_are_exact_up_to_the_limit() {
    let vars = coordinates(&["x", "y", "z", "t", "u"]);
    assert_eq!(vars.exponent_bits(), 12);
    for name in ["x", "u"] {
        let v = var(&vars, name);
        let top: Q = p(&vars, &format!("{name}^1000 + {name}^-1000 + x*u"));
        assert_eq!(top.exponent_range(v), Some((-1000, 1000)));
        assert_eq!(&top * &Q::one(&vars), top);
        let too_large = |exponent: i64| AlgebraError::ExponentTooLarge {
            var: name.into(),
            exponent,
            limit: 1000,
        };
        let (one, inverse): (Q, Q) = (p(&vars, name), p(&vars, &format!("{name}^-1")));
        assert_eq!(top.checked_mul(&one), Err(too_large(1001)));
        assert_eq!(top.checked_mul(&inverse), Err(too_large(-1001)));
        // 512 is one bit of the field: its product with itself passes the limit.
        let power: Q = p(&vars, &format!("{name}^512"));
        assert_eq!(power.checked_mul(&power), Err(too_large(1024)));
        let square: Q = p(&vars, &format!("{name}^500 - {name}^-500"));
        assert_eq!(
            square.checked_mul(&square),
            Ok(p(&vars, &format!("{name}^1000 - 2 + {name}^-1000")))
        );
    }
}

/// Exponents and angle multiples written in the source that overflow `i64` while being
/// combined must be reported, not wrap around or panic.
#[test]
fn angle_multiples_that_overflow_i64_are_rejected() {
    let vars = phase_space();
    let mut failures = Vec::new();
    for src in [
        // The multiples are summed: 2·(2^63 − 1) + 2 wraps to 0 in i64.
        "exp(i*9223372036854775807*theta + i*9223372036854775807*theta + i*2*theta)",
        "cos(9223372036854775807*theta + 9223372036854775807*theta)",
        // −2 · 2^62 = −2^63 = i64::MIN, then negated by the minus of −θ.
        "cos(-2*4611686018427387904*-theta)",
    ] {
        let result =
            std::panic::catch_unwind(|| G::parse(&vars, src).map_err(|e| e.message().to_string()));
        match result {
            Ok(Err(message)) if message.contains("past the limit") => {}
            Ok(Err(message)) => failures.push(format!("{src}: unexpected message {message}")),
            Ok(Ok(f)) => failures.push(format!("{src} parsed to {f}")),
            Err(_) => failures.push(format!("{src}: panicked (integer overflow)")),
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// `Poly::monomial` and `Poly::coeff` add up repeated variables; overflow must be an error
/// (or, for `coeff`, the coefficient 0 of a monomial that cannot occur).
#[test]
fn repeated_variable_exponents_that_overflow_i64_are_rejected() {
    let vars = phase_space();
    let x = var(&vars, "x");
    let powers = [(x, i64::MAX), (x, i64::MAX), (x, 2)];
    let monomial =
        std::panic::catch_unwind(|| Poly::<Rational>::monomial(&vars, Rational::one(), &powers));
    assert!(
        matches!(monomial, Ok(Err(AlgebraError::ExponentTooLarge { .. }))),
        "Poly::monomial on x^MAX · x^MAX · x²: {}",
        if monomial.is_err() {
            "panicked (integer overflow)"
        } else {
            "no ExponentTooLarge"
        }
    );
    let f: Q = p(&vars, "1 + x");
    let coeff = std::panic::catch_unwind(|| f.coeff(&powers));
    assert!(
        matches!(&coeff, Ok(c) if c.is_zero()),
        "Poly::coeff on x^MAX · x^MAX · x²: {}",
        if coeff.is_err() {
            "panicked (integer overflow)"
        } else {
            "nonzero"
        }
    );
}

/// A power of a polynomial of seven or eight terms in general position (every composition
/// `60 = a_1 + … + a_t` its own monomial) is refused before any product, at the library's
/// default limit: `(x + y + z + t + u + v + w)^60` has C(66, 6) ≈ 9·10⁷ terms, and repeated
/// multiplication ran for 38 s and 2.3 GB before it met the limit. Terms that share a
/// direction are multiplied as before: `(1 + x + … + x⁶)^60` has 361 terms.
#[test]
fn term_limit_refuses_a_power_in_general_position_up_front() {
    let vars = coordinates(&["x", "y", "z", "t", "u", "v", "w"]);
    let limit = Limits::default().max_terms;
    for f in ["x + y + z + t + u + v + w", "1 + x + y + z + t + u + v + w"] {
        let f: Q = p(&vars, f);
        assert_eq!(
            f.checked_pow(60).map(|g| g.len()),
            Err(AlgebraError::TooManyTerms { limit })
        );
    }
    let f: Q = p(&vars, "1 + x + x^2 + x^3 + x^4 + x^5 + x^6");
    assert_eq!(f.checked_pow(60).map(|g| g.len()), Ok(361));
    // Eight terms in seven variables that are not in general position: no early refusal.
    let g: Q = p(&vars, "1 + x + y + z + t + u + v + x*y");
    assert_eq!(g.checked_pow(2).map(|h| h.len()), Ok(35));
}

/// `x, y, z, t, u` with a term limit of `terms` and a work limit of `products`.
fn terms_and_work_vars(terms: usize, products: u64) -> Vars {
    ["x", "y", "z", "t", "u"]
        .into_iter()
        .fold(Vars::builder(), |b, name| b.coordinate(name))
        .limits(
            Limits::default()
                .max_terms(terms)
                .max_term_products(products),
        )
        .build()
        .unwrap()
}

/// A power whose terms meet on a relation that keeps their phase is refused by its count
/// before any of its products, as one in general position is: `f = 1 + x + y + xy + z + t +
/// u`, whose monomials meet on `1 · xy = x · y`, has `f^12` of C(18, 6) − C(16, 6) = 10 556
/// terms. Under a term limit one below that it is `TooManyTerms`, even with a work limit one
/// below the 7 371 × 7 term products of the last product, `f^11 · f` (multiplied one factor
/// at a time, it met that work limit first: the count was known only of the power formed);
/// under a term limit of 10 556 that work limit decides, and without it the power is formed,
/// of 10 556 terms, as are the powers below it.
#[test]
fn term_limit_refuses_a_power_whose_terms_meet_but_cannot_cancel_up_front() {
    let f = "1 + x + y + x*y + z + t + u";
    let power = |terms, products, e| {
        let f: Q = p(&terms_and_work_vars(terms, products), f);
        f.checked_pow(e).map(|g| g.len())
    };
    let last_product = 7371 * 7;
    assert_eq!(
        power(10_555, last_product - 1, 12),
        Err(AlgebraError::TooManyTerms { limit: 10_555 })
    );
    assert_eq!(
        power(10_556, last_product - 1, 12),
        Err(AlgebraError::TooMuchWork {
            left: 7,
            right: 7371,
            products: last_product as u128,
            limit: last_product - 1,
        })
    );
    let unlimited = Limits::default().max_term_products;
    assert_eq!(power(10_556, unlimited, 12), Ok(10_556));
    assert_eq!(power(10_555, unlimited, 11), Ok(7371));
}

/// A power whose square the work limit refuses before it starts is refused so, at once,
/// without first finding the relations among its monomials, whose elimination takes time
/// in the terms (a power of 200 000 terms in 12 variables waited a second for it, and was
/// refused in microseconds without it): `f = (1 + x)(1 + y)(1 + z)(1 + t)(1 + u)`, of 32
/// terms, whose `f^7` has at least 1 688 terms by its relations, is refused by its square's
/// 32 · 33/2 = 528 term products under a work limit of 527, and by its count of terms under
/// one of 528.
#[test]
fn a_power_whose_square_passes_the_work_limit_is_refused_by_it() {
    let f = "(1 + x)*(1 + y)*(1 + z)*(1 + t)*(1 + u)";
    let power = |products| {
        let f: Q = p(&terms_and_work_vars(1687, products), f);
        f.checked_pow(7).map(|g| g.len())
    };
    assert_eq!(
        power(527),
        Err(AlgebraError::TooMuchWork {
            left: 32,
            right: 32,
            products: 528,
            limit: 527,
        })
    );
    assert_eq!(power(528), Err(AlgebraError::TooManyTerms { limit: 1687 }));
}

/// `f · g` on a pool of two threads, in variables `x, y, z, t, u` whose term limit is `limit`.
fn product_with_limit(f: &str, g: &str, limit: usize) -> Result<usize, AlgebraError> {
    let vars = Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .coordinate("z")
        .coordinate("t")
        .coordinate("u")
        .limits(Limits::default().max_terms(limit))
        .build()
        .unwrap();
    let (f, g): (Q, Q) = (p(&vars, f), p(&vars, g));
    rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .expect("a thread pool")
        .install(|| f.checked_mul(&g))
        .map(|h| h.len())
}

/// A large product on two threads is held to the limit by all its parts together: the dense
/// product `(1 + x + y + z)^20 · ((1 + x + y + z)^20 + 1)`, whose box is split into parts,
/// has C(43, 3) = 12341 terms; the sparse `(1 + x + y + 2z² + 3t³ + 5u⁵)^8 · (1 + u + t +
/// 2z² + 3y³ + 5x⁵)^8`, whose terms a second thread writes as the first adds, has 591235.
/// Each is refused one term below its size, and computed at it.
#[test]
fn term_limit_holds_a_product_split_over_threads_to_its_total() {
    let f = "(1 + x + y + z)^20";
    let dense = |limit| product_with_limit(f, &format!("{f} + 1"), limit);
    assert_eq!(dense(12341), Ok(12341));
    assert_eq!(
        dense(12340),
        Err(AlgebraError::TooManyTerms { limit: 12340 })
    );
    // Below the size of any one part.
    assert_eq!(dense(1800), Err(AlgebraError::TooManyTerms { limit: 1800 }));
    let sparse = |limit| {
        product_with_limit(
            "(1 + x + y + 2*z^2 + 3*t^3 + 5*u^5)^8",
            "(1 + u + t + 2*z^2 + 3*y^3 + 5*x^5)^8",
            limit,
        )
    };
    let terms = sparse(1 << 20).expect("within the limit");
    assert_eq!(sparse(terms), Ok(terms));
    assert_eq!(
        sparse(terms - 1),
        Err(AlgebraError::TooManyTerms { limit: terms - 1 })
    );
}

/// A parse whose expansion passes a limit says which, as its cause: the algebra's refusal,
/// with its numbers, or the exponent or multiple written past the degree limit, with its size;
/// an unknown name says the name and the known ones.
#[test]
fn a_parse_error_keeps_its_cause() {
    use trigpoly::{BracketError, Context, ParseCause};
    let vars = small_vars();
    let err = Poly::<Rational>::parse(&vars, "(x + y + z + t + u + v + w)^9").unwrap_err();
    assert_eq!(
        err.cause(),
        &ParseCause::Algebra(AlgebraError::TooManyTerms { limit: 1000 })
    );
    let work = work_vars(70 * 35 - 1);
    let err =
        Poly::<Rational>::parse(&work, "(1 + x + y + z + t)^4*(1 + x + y + z + t)^3").unwrap_err();
    assert!(matches!(
        err.cause(),
        ParseCause::Algebra(AlgebraError::TooMuchWork { limit: 2449, .. })
    ));
    let err = Poly::<Rational>::parse(&vars, "x^5000*x^5001").unwrap_err();
    assert!(matches!(
        err.cause(),
        ParseCause::Algebra(AlgebraError::ExponentTooLarge {
            exponent: 10001,
            limit: 10_000,
            ..
        })
    ));
    for (text, power) in [
        ("x^20000", Some(20000)),
        ("x^(-40001/2)", Some(40001)),
        ("x^99999999999999999999", None),
        ("x^(2^300)", None),
    ] {
        let err = Poly::<Rational>::parse(&vars, text).unwrap_err();
        assert_eq!(
            err.cause(),
            &ParseCause::PowerPastLimit {
                power,
                limit: 10_000
            },
            "{text}"
        );
    }
    let angles = Vars::builder().angle("theta").build().unwrap();
    let err = Poly::<Rational>::parse(&angles, "cos(5000*theta)").unwrap_err();
    assert_eq!(
        err.cause(),
        &ParseCause::PowerPastLimit {
            power: Some(5000),
            limit: 1000
        }
    );
    // The expansion of a sine or cosine, `(e^{iθ} + e^{−iθ})/2`, past the term limit.
    let one_term = Vars::builder()
        .angle("theta")
        .limits(Limits::default().max_terms(1))
        .build()
        .unwrap();
    for text in ["cos(theta)", "sin(theta)"] {
        let err = Poly::<trigpoly::GaussianRational>::parse(&one_term, text).unwrap_err();
        assert_eq!(
            err.cause(),
            &ParseCause::Algebra(AlgebraError::TooManyTerms { limit: 1 }),
            "{text}"
        );
    }
    let err = Poly::<Rational>::parse(&vars, "x + q").unwrap_err();
    let ParseCause::UnknownName { name, known } = err.cause() else {
        panic!("{err:?}")
    };
    assert_eq!(name, "q");
    assert_eq!(known, &["x", "y", "z", "t", "u", "v", "w"]);
    let err = Poly::<Rational>::parse(&vars, "x + (y").unwrap_err();
    assert_eq!(err.cause(), &ParseCause::Syntax);
    // What no token is made of, and a decimal number.
    for text in ["x $ y", "\\nabla x", "p_{x$}"] {
        let err = Poly::<Rational>::parse(&vars, text).unwrap_err();
        assert_eq!(err.cause(), &ParseCause::Unreadable, "{text}: {err}");
    }
    let err = Poly::<Rational>::parse(&vars, "0.5*x").unwrap_err();
    assert_eq!(err.cause(), &ParseCause::Decimal);

    /// A context whose bracket passes the term limit.
    struct Limited;
    impl Context<Rational> for Limited {
        fn lookup(&self, _: &str) -> Option<Q> {
            None
        }
        fn bracket(&self, _: &Q, _: &Q) -> Result<Q, BracketError> {
            Err(AlgebraError::TooManyTerms { limit: 7 }.into())
        }
    }
    let err = Poly::<Rational>::parse_with(&vars, "{x, y}", &Limited).unwrap_err();
    assert_eq!(
        err.cause(),
        &ParseCause::Algebra(AlgebraError::TooManyTerms { limit: 7 })
    );
}

/// A limit's message is what happened and then the advice; `without_advice` is the first
/// alone, and every other message is whole.
#[test]
fn a_limit_says_what_happened_without_its_advice() {
    for (e, advice) in [
        (
            AlgebraError::TooManyTerms { limit: 1 },
            "raise the limit or simplify the input",
        ),
        (
            AlgebraError::TooManyPrintedTerms {
                terms: 12,
                limit: 10,
                angles: trigpoly::Angles::Powers,
            },
            "raise the limit or print less of it",
        ),
        (
            AlgebraError::TooMuchWork {
                left: 3,
                right: 4,
                products: 12,
                limit: 10,
            },
            "raise the limit or simplify the input",
        ),
    ] {
        let said = e.without_advice();
        assert_eq!(e.to_string(), format!("{said}; {advice}"));
        assert!(said.ends_with(" limit)"), "{said}");
    }
    assert_eq!(
        AlgebraError::TooManyTerms { limit: 1 }.without_advice(),
        "the result would have more than 1 term (the term limit)"
    );
    let exponent = AlgebraError::ExponentTooLarge {
        var: "x".into(),
        exponent: 2000,
        limit: 1000,
    };
    assert_eq!(exponent.without_advice(), exponent.to_string());
}
