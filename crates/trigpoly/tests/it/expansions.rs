//! Classical expansions checked against independent integer arithmetic: Chebyshev
//! polynomials, multinomial coefficients, Laurent cancellation and the overflow of machine
//! integers into big integers.

use num_bigint::BigInt;
use trigpoly::{GaussianRational, Integer, IntegerView, Rational};

use crate::common::{big_rational, coordinates, gauss, p, phase_space, rational_i128, var, G, Q};

/// Coefficient lists (by powers of c) of T_0..=T_n or U_0..=U_n from
/// `P_{k+1} = 2c P_k − P_{k−1}` with the given `P_0 = 1`, `P_1`.
fn chebyshev(n: usize, p1: Vec<i128>) -> Vec<Vec<i128>> {
    let mut out = vec![vec![1i128], p1];
    while out.len() <= n {
        let (a, b) = (&out[out.len() - 2], &out[out.len() - 1]);
        let mut next = vec![0i128; b.len() + 1];
        for (k, &x) in b.iter().enumerate() {
            next[k + 1] += 2 * x;
        }
        for (k, &x) in a.iter().enumerate() {
            next[k] -= x;
        }
        out.push(next);
    }
    out
}

/// `Σ_k coeffs[k] · c^k` for precomputed powers `c^k`.
fn in_powers(coeffs: &[i128], powers: &[G]) -> G {
    let vars = phase_space();
    coeffs
        .iter()
        .zip(powers)
        .fold(G::zero(&vars), |acc, (&a, ck)| {
            acc + ck.scale(&GaussianRational::from(rational_i128(a)))
        })
}

#[test]
fn chebyshev_real_and_imaginary_parts_of_de_moivre() {
    const N: usize = 40;
    let vars = phase_space();
    let t = chebyshev(N, vec![0, 1]); // T_1 = c
    let u = chebyshev(N, vec![0, 2]); // U_1 = 2c
                                      // Spot checks of the recurrences themselves: T_4 = 8c⁴ − 8c² + 1, U_3 = 8c³ − 4c.
    assert_eq!(t[4], [1, 0, -8, 0, 8]);
    assert_eq!(u[3], [0, -4, 0, 8]);
    let c: G = p(&vars, "cos(theta)");
    let s: G = p(&vars, "sin(theta)");
    let mut powers = vec![G::one(&vars)];
    for k in 1..=N {
        powers.push(&powers[k - 1] * &c);
    }
    for n in 0..=N {
        let e: G = p(&vars, &format!("(cos(theta) - i*sin(theta))^{n}"));
        assert_eq!(
            e,
            p(&vars, &format!("exp(-i*{n}*theta)")),
            "(cos θ − i sin θ)^{n} = e^(−i{n}θ)"
        );
        let t_n = in_powers(&t[n], &powers);
        let u_prev = if n == 0 {
            G::zero(&vars)
        } else {
            in_powers(&u[n - 1], &powers)
        };
        assert_eq!(
            e.re().unwrap(),
            t_n,
            "Re (cos θ − i sin θ)^{n} = T_{n}(cos θ)"
        );
        assert_eq!(
            e.im().expect("over Q(i)"),
            -(&s * &u_prev),
            "Im (cos θ − i sin θ)^{n} = −sin θ U_{}(cos θ)",
            n as i64 - 1
        );
        // And in the paper's normal form, cos nθ = T_n(cos θ) is free of sin θ.
        assert_eq!(
            p::<GaussianRational>(&vars, &format!("cos({n}*theta)")),
            t_n
        );
    }
}

fn factorial(n: u64) -> u128 {
    (1..=n as u128).product()
}

#[test]
fn multinomial_coefficients_of_one_plus_x_plus_y_plus_z() {
    let vars = coordinates(&["x", "y", "z"]);
    let (x, y, z) = (var(&vars, "x"), var(&vars, "y"), var(&vars, "z"));
    for k in 0..=12u64 {
        let f: Q = p(&vars, &format!("(1 + x + y + z)^{k}"));
        let terms = (k + 1) * (k + 2) * (k + 3) / 6; // C(k+3, 3)
        assert_eq!(
            f.len() as u64,
            terms,
            "(1 + x + y + z)^{k} has C({k}+3, 3) terms"
        );
        for b in 0..=k {
            for c in 0..=k - b {
                for d in 0..=k - b - c {
                    let a = k - b - c - d;
                    let want =
                        factorial(k) / (factorial(a) * factorial(b) * factorial(c) * factorial(d));
                    let got = f.coeff(&[(x, b as i64), (y, c as i64), (z, d as i64)]);
                    assert_eq!(
                        got,
                        rational_i128(want as i128),
                        "[x^{b} y^{c} z^{d}] (1 + x + y + z)^{k}"
                    );
                }
            }
        }
        // Sum of the coefficients: f(1, 1, 1) = 4^k.
        let sum = f.terms().fold(Rational::zero(), |acc, t| acc + t.coeff());
        assert_eq!(sum, rational_i128(4i128.pow(k as u32)));
    }
}

#[test]
fn laurent_cancellation_m_plus_inverse_times_m_minus_inverse() {
    let vars = phase_space();
    for k in 0..=10 {
        identity!(vars, format!("(M + 1/M)^{k} * (M - 1/M)^{k}") => format!("(M^2 - 1/M^2)^{k}"));
        identity!(vars, format!("(M + M^-1)^{k} * (M - M⁻¹)^{k}") => format!("(M² - M⁻²)^{k}"));
    }
    // The middle terms cancel completely: (M + 1/M)(M − 1/M) has two terms, not four.
    let f: G = p(&vars, "(M + 1/M)*(M - 1/M)");
    assert_eq!(f.len(), 2);
}

fn binomial(n: u64, k: u64) -> BigInt {
    (0..k).fold(BigInt::from(1), |acc, j| {
        acc * BigInt::from(n - j) / BigInt::from(j + 1)
    })
}

#[test]
fn overflow_to_big_integers_in_a_power_of_a_binomial() {
    let vars = phase_space();
    let x = var(&vars, "x");
    let f: Q = p(&vars, "(1099511627776*x + 1)^5"); // (2^40 x + 1)^5
    assert_eq!(f.len(), 6);
    for j in 0..=5u64 {
        let want = binomial(5, j) * (BigInt::from(1) << (40 * j));
        assert_eq!(
            f.coeff(&[(x, j as i64)]),
            big_rational(&want),
            "[x^{j}] (2^40 x + 1)^5"
        );
    }
    // The same over Q(i), with i·2^40: coefficients C(5, j)·(2^40)^j·i^j.
    let g: G = p(&vars, "(1099511627776*i*x + 1)^5");
    for j in 0..=5u64 {
        let m = big_rational(&(binomial(5, j) * (BigInt::from(1) << (40 * j))));
        let want = match j % 4 {
            0 => GaussianRational::new(m, Rational::zero()),
            1 => GaussianRational::new(Rational::zero(), m),
            2 => GaussianRational::new(-m, Rational::zero()),
            _ => GaussianRational::new(Rational::zero(), -m),
        };
        assert_eq!(g.coeff(&[(x, j as i64)]), want, "[x^{j}] (2^40 i x + 1)^5");
    }
}

#[test]
fn overflow_to_big_integers_in_sums_near_i64_max() {
    let vars = phase_space();
    let x = var(&vars, "x");
    let max = BigInt::from(i64::MAX);
    identity!(vars, "9223372036854775807*x + 9223372036854775807*x" => "18446744073709551614*x");
    identity!(vars, "9223372036854775807*x + x" => "9223372036854775808*x");
    identity!(vars, "(9223372036854775807*x + 1) - 9223372036854775807*x" => "1");
    identity!(vars, "-9223372036854775808*x - 9223372036854775808*y" => "-9223372036854775808*(x + y)");
    identity!(vars, "9223372036854775807*x + 9223372036854775806*y + 9223372036854775807*x" =>
        "18446744073709551614*x + 9223372036854775806*y");
    let f: Q = p(&vars, "9223372036854775807*x + 9223372036854775806*y");
    assert_eq!((&f + &f).coeff(&[(x, 1)]), big_rational(&(&max * 2)));
    assert_eq!((&f - &f), Q::zero(&vars));
    // Back below the bound, the value is in the word again (structural equality).
    let word_max = (1i64 << 62) - 1;
    let past = Integer::from(word_max) + Integer::from(1);
    assert_eq!(past.view(), IntegerView::Wide(1 << 62));
    let back = past - Integer::from(1);
    assert_eq!(back.view(), IntegerView::Small(word_max));
    assert_eq!(Integer::from(i64::MAX).to_i64(), Some(i64::MAX));
    assert_eq!(-(-Integer::from(i64::MIN)), Integer::from(i64::MIN));
    assert!(matches!(
        (-Integer::from(i64::MIN)).view(),
        IntegerView::Wide(_)
    ));
    assert!(matches!(
        (-Integer::from_i128(i128::MIN)).view(),
        IntegerView::Big(_)
    ));
}

/// `Σ_{k<8} (MAX − k) x^k` squared: both sides have 8 terms, so the heap product runs, and
/// its `i128` accumulators overflow (each product is ~2^126) and spill to big integers.
#[test]
fn overflow_of_product_accumulators_to_big_integers() {
    let vars = phase_space();
    let x = var(&vars, "x");
    let a: Vec<i64> = (0..8).map(|k| i64::MAX - k).collect();
    let f = Q::from_terms(
        &vars,
        a.iter().enumerate().map(|(k, &c)| {
            let mut e = vec![0; vars.len()];
            e[x.index()] = k as i64;
            (Rational::from(c), e)
        }),
    )
    .unwrap();
    let square = &f * &f;
    assert_eq!(square.len(), 15);
    for j in 0..15usize {
        let want: BigInt = (0..8)
            .filter(|&k| j >= k && j - k < 8)
            .map(|k| BigInt::from(a[k]) * BigInt::from(a[j - k]))
            .sum();
        assert_eq!(
            square.coeff(&[(x, j as i64)]),
            big_rational(&want),
            "[x^{j}] f²"
        );
    }
    // Over Q(i): coefficients (MAX − k) + (MIN + k)·i, compared with (re, im) big arithmetic.
    let b: Vec<(i64, i64)> = (0..8).map(|k| (i64::MAX - k, i64::MIN + k)).collect();
    let g = G::from_terms(
        &vars,
        b.iter().enumerate().map(|(k, &(re, im))| {
            let mut e = vec![0; vars.len()];
            e[x.index()] = k as i64;
            (gauss(re, im), e)
        }),
    )
    .unwrap();
    let square = &g * &g;
    for j in 0..15usize {
        let (mut re, mut im) = (BigInt::from(0), BigInt::from(0));
        for k in (0..8).filter(|&k| j >= k && j - k < 8) {
            let ((ar, ai), (br, bi)) = (b[k], b[j - k]);
            let (ar, ai, br, bi) = (
                BigInt::from(ar),
                BigInt::from(ai),
                BigInt::from(br),
                BigInt::from(bi),
            );
            re += &ar * &br - &ai * &bi;
            im += &ar * &bi + &ai * &br;
        }
        let want = GaussianRational::new(big_rational(&re), big_rational(&im));
        assert_eq!(square.coeff(&[(x, j as i64)]), want, "[x^{j}] g²");
    }
}

#[test]
fn pythagorean_angle_expansions() {
    let vars = phase_space();
    identity!(vars, "cos(theta)^2 + sin(theta)^2" => "1");
    identity!(vars, "cos(2*theta)" => "cos(theta)^2 - sin(theta)^2");
    identity!(vars, "sin(2*theta)" => "2*sin(theta)*cos(theta)");
    identity!(vars, "cos(theta + phi)" => "cos(theta)*cos(phi) - sin(theta)*sin(phi)");
    identity!(vars, "sin(theta - phi)" => "sin(theta)*cos(phi) - cos(theta)*sin(phi)");
    identity!(vars, "exp(i*theta)*exp(-i*theta)" => "1");
    identity!(vars, "(cos(theta) + i*sin(theta))^7" => "exp(7*i*theta)");
    // Division by a single term, a trigonometric one included: e^{iθ}/e^{2iθ} = e^{−iθ}.
    identity!(vars, "exp(i*theta)/exp(2*i*theta)" => "cos(theta) - i*sin(theta)");
    let f: G = p(&vars, "exp(i*theta)");
    assert_eq!(f.checked_pow(-3), Ok(p(&vars, "exp(-3*i*theta)")));
    assert_eq!(
        G::exp_i(&vars, var(&vars, "phi"), 4),
        Ok(p(&vars, "exp(4*i*phi)"))
    );
}

/// An argument of `cos`, `sin` or `exp` is read as an integer combination of the angles however
/// it is written (nested sums, unary minus, integer factors on either side, `i` anywhere in
/// a product): each spelling has the normal form of its expanded spelling, and both that of
/// the angle-addition formula written out by hand in `cos θ, sin θ, cos φ, sin φ` alone.
#[test]
fn angle_arguments_are_integer_combinations_however_written() {
    let vars = phase_space();
    let (c, s, cp, sp) = ("cos(theta)", "sin(theta)", "cos(phi)", "sin(phi)");
    // cos 2α = cos²α − sin²α, sin 2α = 2 sin α cos α, cos 3α = 4cos³α − 3cos α,
    // sin 3α = 3 sin α − 4 sin³α.
    let cos2 = |c: &str, s: &str| format!("({c}^2 - {s}^2)");
    let sin2 = |c: &str, s: &str| format!("(2*{s}*{c})");
    let cos3 = |c: &str| format!("(4*{c}^3 - 3*{c})");
    let sin3 = |s: &str| format!("(3*{s} - 4*{s}^3)");
    let cases = [
        (
            "cos(2*(theta - phi))",
            "cos(2*theta - 2*phi)",
            // cos(a − b) = cos a cos b + sin a sin b
            format!(
                "{}*{} + {}*{}",
                cos2(c, s),
                cos2(cp, sp),
                sin2(c, s),
                sin2(cp, sp)
            ),
        ),
        (
            "sin(-(theta + 2*phi))",
            "sin(-theta - 2*phi)",
            // sin(−(a + b)) = −(sin a cos b + cos a sin b)
            format!("-({s}*{} + {c}*{})", cos2(cp, sp), sin2(cp, sp)),
        ),
        (
            "cos((theta - phi)*3)",
            "cos(3*theta - 3*phi)",
            format!("{}*{} + {}*{}", cos3(c), cos3(cp), sin3(s), sin3(sp)),
        ),
        (
            "sin((2 + 1)*theta - phi*(1 - 3))",
            "sin(3*theta + 2*phi)",
            format!(
                "{}*{} + {}*{}",
                sin3(s),
                cos2(cp, sp),
                cos3(c),
                sin2(cp, sp)
            ),
        ),
        (
            "exp(i*(theta - phi))",
            "exp(i*theta - i*phi)",
            format!("({c} + i*{s})*({cp} - i*{sp})"),
        ),
        (
            "exp((theta - phi)*i)",
            "exp(i*theta - i*phi)",
            format!("({c} + i*{s})*({cp} - i*{sp})"),
        ),
        (
            "exp(-2*i*(theta - phi))",
            "exp(-2*i*theta + 2*i*phi)",
            format!("({c} - i*{s})^2*({cp} + i*{sp})^2"),
        ),
        (
            "exp(2*i*theta - i*phi)",
            "exp(2*i*theta - i*phi)",
            format!("({c} + i*{s})^2*({cp} - i*{sp})"),
        ),
        (
            "exp(i*(2*(theta - phi) + -(-phi)))",
            "exp(2*i*theta - i*phi)",
            format!("({c} + i*{s})^2*({cp} - i*{sp})"),
        ),
        // i·i = −1 wherever the factors stand.
        (
            "exp(i*i*(theta*i))",
            "exp(-i*theta)",
            format!("{c} - i*{s}"),
        ),
        ("cos(theta - theta)", "cos(0*theta)", "1".to_string()),
    ];
    for (written, expanded, by_hand) in cases {
        identity!(vars, written => expanded);
        identity!(vars, expanded => by_hand);
    }
    // The normal forms tell the sign of a combination apart.
    assert_ne!(
        p::<GaussianRational>(&vars, "sin(2*(theta - phi))"),
        p::<GaussianRational>(&vars, "sin(2*(phi - theta))")
    );
}

/// A multiple of an angle may be an integer constant written as an expression: powers of
/// integers (and of `i`) to integer exponents, sums, products, quotients and negations, in
/// parentheses or not, on either side of the angle, so long as the angles' multiples come out
/// integers. Each has the normal form of the multiple written out.
#[test]
fn angle_multiples_written_as_integer_constants() {
    let vars = phase_space();
    let cases = [
        ("cos(2^3*theta)", "cos(8*theta)"),
        ("cos(theta*2^3)", "cos(8*theta)"),
        ("cos(theta*3)", "cos(3*theta)"),
        ("cos(-2^3*theta)", "cos(8*theta)"),
        ("sin((-2)^3*theta)", "sin(-8*theta)"),
        ("sin((1+2)*theta - phi)", "sin(3*theta - phi)"),
        ("sin((1+2)^2*(theta - 2^0*phi))", "sin(9*theta - 9*phi)"),
        ("cos((2^11 - 2040)*theta)", "cos(8*theta)"),
        ("exp(i*2^2*theta)", "exp(4*i*theta)"),
        ("exp(i^3*theta)", "exp(-i*theta)"),
        ("exp((1 + i)^2*phi)", "exp(2*i*phi)"),
        ("cos(2^(3 - 1)*theta)", "cos(4*theta)"),
        ("cos(4/2*theta)", "cos(2*theta)"),
        ("cos((4*theta)/2 - phi)", "cos(2*theta - phi)"),
        ("sin(theta*6/3)", "sin(2*theta)"),
        ("sin(2^(-1)*4*theta)", "sin(2*theta)"),
        ("exp(i*(1/2 + 1/2)*phi)", "exp(i*phi)"),
        ("exp((1 + i)^2/2*theta)", "exp(i*theta)"),
        ("cos(0)", "1"),
        ("sin(2 - 2)", "0"),
        ("exp(i*0)", "1"),
        ("cos(theta - theta + 0)", "1"),
    ];
    for (written, expanded) in cases {
        identity!(vars, written => expanded);
    }
    assert_ne!(
        p::<GaussianRational>(&vars, "cos(2^3*theta)"),
        p::<GaussianRational>(&vars, "cos(6*theta)")
    );
}

/// The Fateman product for n = 6: `f·(f + 1) = f² + f` with `f = (1 + x + y + z + t)^6`, so
/// the coefficient of `x^a y^b z^c t^d` is `12!/(e! a! b! c! d!) + 6!/(e'! a! b! c! d!)`.
#[test]
fn fateman_product_coefficients_are_multinomials() {
    const N: u64 = 6;
    let vars = coordinates(&["x", "y", "z", "t"]);
    let f: Q = p(&vars, &format!("(1 + x + y + z + t)^{N}"));
    assert_eq!(f.len(), 210); // C(10, 4)
    let product = &f * &(&f + &Q::one(&vars));
    assert_eq!(product.len(), 1820); // C(16, 4): every monomial of degree ≤ 12
    let multinomial = |k: u64, parts: [u64; 4]| -> u128 {
        let s: u64 = parts.iter().sum();
        if s > k {
            return 0;
        }
        parts
            .iter()
            .fold(factorial(k) / factorial(k - s), |acc, &e| {
                acc / factorial(e)
            })
    };
    let names = ["x", "y", "z", "t"].map(|n| var(&vars, n));
    for term in product.terms() {
        let e: Vec<u64> = names.iter().map(|&v| term.exponent(v) as u64).collect();
        let parts = [e[0], e[1], e[2], e[3]];
        let want = multinomial(2 * N, parts) + multinomial(N, parts);
        assert_eq!(
            term.coeff(),
            rational_i128(want as i128),
            "x^{} y^{} z^{} t^{}",
            e[0],
            e[1],
            e[2],
            e[3]
        );
    }
}
