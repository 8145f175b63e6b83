//! The closure of an algebra on a system with denominator atoms: the three-body Calogero–Moser
//! integrals and the conformal functions that make it superintegrable, brackets found as
//! polynomials in the generators and proved again here as claims, relations that hold only
//! by `(x − y) · 1/(x − y) = 1` found, a false one (the same numerator over another
//! denominator) not reported, an atom of an angle, and the command line.

use brackets::closure::{closure, Bracket, Closure, ClosureOptions};
use brackets::Condition;
use superint::system_file::{load_str, LimitsOverride, LoadedSystem};

use crate::{assert_proved, normalize, scratch_text, superint, superint_ok, superint_refused};

/// Calogero–Moser with three bodies, `g = a²` for the Lax matrix `L_ij = p_i δ_ij +
/// ia/(x_i − x_j)`: `f1 = Σ x_i`, `f2 = Σ x_i p_i`, `f3 = Σ x_i p_i² + g Σ (x_i + x_j)/(x_i −
/// x_j)²` move as `{f1, H} = P`, `{f2, H} = 2H`, `{f3, H} = I3`, so `K1 = P f2 − 2H f1` and
/// `K2 = P f3 − I3 f1` are integrals. `V` is the potential over one common denominator, `T`
/// the kinetic energy; `R` is `P/(x − y)` and `S` is `P` written `(x − y) P/(x − y)`.
const CALOGERO: &str = r#"name = "Calogero–Moser three-body"
hamiltonian = "(p_x^2 + p_y^2 + p_z^2)/2 + g/(x - y)^2 + g/(x - z)^2 + g/(y - z)^2"

[phase_space]
coordinates = ["x", "y", "z"]
parameters = ["g"]
denominators = ["x - y", "x - z", "y - z"]

[[function]]
name = "P"
value = "p_x + p_y + p_z"

[[function]]
name = "I3"
value = "p_x^3 + p_y^3 + p_z^3 + 3*g*((p_x + p_y)/(x - y)^2 + (p_x + p_z)/(x - z)^2 + (p_y + p_z)/(y - z)^2)"

[[function]]
name = "f1"
value = "x + y + z"

[[function]]
name = "f2"
value = "x*p_x + y*p_y + z*p_z"

[[function]]
name = "f3"
value = "x*p_x^2 + y*p_y^2 + z*p_z^2 + g*((x + y)/(x - y)^2 + (x + z)/(x - z)^2 + (y + z)/(y - z)^2)"

[[function]]
name = "K1"
value = "P*f2 - 2*H*f1"

[[function]]
name = "K2"
value = "P*f3 - I3*f1"

[[function]]
name = "T"
value = "(p_x^2 + p_y^2 + p_z^2)/2"

[[function]]
name = "V"
value = "g*((x - z)^2*(y - z)^2 + (x - y)^2*(y - z)^2 + (x - y)^2*(x - z)^2)/((x - y)^2*(x - z)^2*(y - z)^2)"

[[function]]
name = "R"
value = "P/(x - y)"

[[function]]
name = "S"
value = "(x - y)*P/(x - y)"

[[claim]]
id = "f1"
claim = "{f1, H} = P"

[[claim]]
id = "f2"
claim = "{f2, H} = 2*H"

[[claim]]
id = "f3"
claim = "{f3, H} = I3"

[[claim]]
id = "K1"
claim = "{K1, H} = 0"

[[claim]]
id = "K2"
claim = "{K2, H} = 0"
"#;

fn calogero() -> LoadedSystem {
    load_str("calogero.toml", CALOGERO, &LimitsOverride::default()).expect("the file loads")
}

/// Every bracket the closure writes as a polynomial in the generators, proved again as the
/// claim `{A, B} = polynomial` (read back from its ASCII form); how many there were.
fn prove_each_bracket(file: &LoadedSystem, c: &Closure) -> usize {
    let mut proved = 0;
    for (a, row) in c.brackets.iter().enumerate() {
        for (b, bracket) in row.iter().enumerate() {
            if let Bracket::Polynomial { poly, symbolic } = bracket {
                assert!(*symbolic, "{{{}, {}}} = {poly}", c.names[a], c.names[b]);
                let claim = format!(
                    "{{{}, {}}} = {}",
                    c.names[a],
                    c.names[b],
                    poly.render(trigpoly::Style::Ascii)
                );
                assert_proved(file.system(), &claim, None);
                proved += 1;
            }
        }
    }
    proved
}

/// The file's claims hold: `f1, f2, f3` move as stated and `K1, K2` are integrals.
#[test]
fn closure_denominators_conformal_integrals_are_integrals() {
    let report = superint::system_file::check_report([&calogero()]).expect("checked");
    assert!(report.all_proved());
}

/// `P, H, I3, K1, K2` at degree 3: `{P, K1} = 6H − P²` (by hand: `{P, f1} = −3`,
/// `{P, f2} = −P`), `{P, K2} = 3I3 − 2PH` (`{P, f3} = −2H`), `{I3, K1} = 12H² − 3P I3`
/// (`{I3, f1} = −6H`, `{I3, f2} = −3 I3`), `H` central; `{I3, K2}` and `{K1, K2}` are no
/// polynomials of degree 3 in them, and there is no relation of degree 3. The brackets are
/// lifted from `g = 1` to every `g` and proved.
#[test]
fn closure_denominators_calogero_brackets_are_polynomials_in_the_integrals() {
    let file = calogero();
    let c = closure(
        file.system(),
        &["P", "H", "I3", "K1", "K2"],
        &ClosureOptions::new(3),
    )
    .expect("the closure is computed");
    assert_eq!(c.render_bracket(0, 3), "−P² + 6 H");
    assert_eq!(c.render_bracket(0, 4), "−2 P H + 3 I3");
    assert_eq!(c.render_bracket(2, 3), "−3 P I3 + 12 H²");
    assert_eq!(c.render_bracket(3, 0), "P² − 6 H");
    for k in 0..5 {
        assert_eq!(c.render_bracket(1, k), "0");
    }
    assert_eq!(c.outside(), [(2, 4), (3, 4)]);
    assert!(c.relations.is_empty());
    assert_eq!((c.monomials, c.rank), (56, 56));
    assert!(c.all_symbolic() && c.liftable);
    // 25 entries less the 4 outside, each proved as a claim of its own.
    assert_eq!(prove_each_bracket(&file, &c), 21);
}

/// A relation that holds only by clearing is found: `H = T + V` with `V` over one common
/// denominator, whose terms share no monomial with `H`'s; and `S = P` where `S` is
/// `(x − y) P/(x − y)`. `R = P/(x − y)` has the numerator of `P` over another denominator:
/// no relation ties it to `P` (one that compared numerators would report `R = P`).
#[test]
fn closure_denominators_relations_hold_as_elements() {
    let file = calogero();
    let system = file.system();
    let c = closure(system, &["H", "T", "V"], &ClosureOptions::new(2)).expect("computed");
    let relations: Vec<String> = c.relations.iter().map(|r| r.poly.to_string()).collect();
    assert_eq!(relations, ["H − T − V"]);
    assert!(c.relations[0].symbolic);
    // The kernel: H − T − V times 1, H, T and V.
    assert_eq!((c.monomials, c.rank), (10, 6));

    let c = closure(system, &["P", "R", "S"], &ClosureOptions::new(2)).expect("computed");
    let relations: Vec<String> = c.relations.iter().map(|r| r.poly.to_string()).collect();
    assert_eq!(relations, ["P − S"]);
    // {P, R} = 0: R depends on x − y alone besides the momenta; {R, S} = {R, P} = 0.
    assert!(c.closes());
    let c = closure(system, &["P", "R"], &ClosureOptions::new(3)).expect("computed");
    assert!(c.relations.is_empty());
    assert_eq!((c.monomials, c.rank), (10, 10));
}

/// An atom of an angle, `2 + cos θ` (real, so a real function's image is real and its
/// conjugate terms are still left out): `F + 2W = 1` and `3F² + F + 4S = 2W` for
/// `F = cos θ/(2 + cos θ)`, `W = 1/(2 + cos θ)`, `S = sin²θ/(2 + cos θ)²`.
#[test]
fn closure_denominators_an_atom_of_an_angle() {
    let text = "name = \"rotor\"\n\
                hamiltonian = \"p_theta^2/2 + 1/(2 + cos(theta))\"\n\
                [phase_space]\nangles = [\"theta\"]\ndenominators = [\"2 + cos(theta)\"]\n\
                [[function]]\nname = \"F\"\nvalue = \"cos(theta)/(2 + cos(theta))\"\n\
                [[function]]\nname = \"W\"\nvalue = \"1/(2 + cos(theta))\"\n\
                [[function]]\nname = \"S\"\nvalue = \"sin(theta)^2/(2 + cos(theta))^2\"\n";
    let file = load_str("rotor.toml", text, &LimitsOverride::default()).expect("loads");
    let c = closure(file.system(), &["F", "W", "S"], &ClosureOptions::new(2)).expect("computed");
    let relations: Vec<String> = c.relations.iter().map(|r| r.poly.to_string()).collect();
    assert_eq!(relations, ["F + 2 W − 1", "3 F² + F − 2 W + 4 S"]);
    assert!(c.closes() && c.all_symbolic());
}

/// `superint closure FILE P H K1 --degree 3` on the file: the table closes with
/// `{P, K1} = −P² + 6H`, proved, and no relation; so it does under a condition on `g`, and
/// with `K1` defined on the command line (the help's example); a condition on a
/// denominator's variable is refused with exit status 2, and only that.
#[test]
fn closure_denominators_command_line() {
    let f = scratch_text("closure-denominators", "calogero.toml", CALOGERO);
    let f = f.to_str().unwrap();
    let o = superint(&[
        "closure",
        f,
        "P",
        "H",
        "K1",
        "--degree",
        "3",
        "--no-timings",
    ]);
    let out = String::from_utf8(o.stdout).unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{out}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let flat = normalize(&out);
    assert!(flat.contains("{P, K1} = −P² + 6 H [B1 proved]"), "{out}");
    assert!(
        flat.contains("The table closes: every bracket is a polynomial of degree ≤ 3"),
        "{out}"
    );
    assert!(
        flat.contains(
            "times polynomials in the generators, as far as this degree shows), each checked by \
             expanding it; every relation up to this degree is such a combination of them. None."
        ),
        "{out}"
    );
    assert!(flat.contains("1 claim: 1 proved, 0 refuted"), "{out}");

    // Under a condition on g (no denominator's variable) the same bracket, at g = 3.
    let o = superint(&["closure", f, "P", "H", "K1", "--when", "g = 3"]);
    let out = String::from_utf8(o.stdout).unwrap();
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(normalize(&out).contains("{P, K1} = −P² + 6 H"), "{out}");

    // The help's example, and the same integral given by --define on the system file.
    let calogero = concat!(env!("CARGO_MANIFEST_DIR"), "/systems/calogero.toml");
    for (k, extra) in [
        ("K1", &[][..]),
        (
            "J",
            &["--define", "J=P*(x*p_x + y*p_y + z*p_z) - 2*H*(x + y + z)"][..],
        ),
    ] {
        let mut args = vec!["closure", calogero, "P", "H", "I3"];
        if extra.is_empty() {
            args.push(k);
        }
        args.extend(["--degree", "2"]);
        args.extend(extra);
        let o = superint(&args);
        let out = String::from_utf8(o.stdout).unwrap();
        assert_eq!(o.status.code(), Some(0), "{out}");
        let flat = normalize(&out);
        assert!(
            flat.contains(&format!("{{P, {k}}} = −P² + 6 H [B1 proved]")),
            "{out}"
        );
        assert!(
            flat.contains(&format!("{{I_3, {k}}} = −3 P I_3 + 12 H² [B2 proved]")),
            "{out}"
        );
    }

    let o = superint(&["closure", f, "P", "H", "K1", "--when", "x = 0"]);
    let err = String::from_utf8(o.stderr).unwrap();
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("the condition sets x, which the denominator (x − y) involves"),
        "{err}"
    );
}

/// A declared denominator that the default values, 1, make zero (`a − b` at `a = b = 1`):
/// the closure and the search take other values for its parameters, and say why; values
/// given that make it zero are still refused.
#[test]
fn closure_denominators_zero_at_one_moves_the_values() {
    let text = "name = \"two frequencies\"\n\
                hamiltonian = \"(p_x^2 + p_y^2)/2 + a*x^2/2 + b*y^2/2\"\n\
                [phase_space]\n\
                coordinates = [\"x\", \"y\"]\n\
                parameters = [\"a\", \"b\"]\n\
                denominators = [\"a - b\"]\n\
                [[function]]\nname = \"T\"\nvalue = \"(p_x^2/2 + a*x^2/2)/(a - b)\"\n\
                [[function]]\nname = \"X\"\nvalue = \"p_y^2/2 + b*y^2/2\"\n";
    let f = scratch_text("closure-denominators-one", "two.toml", text);
    let f = f.to_str().unwrap();
    let run = |args: &[&str]| {
        let o = superint(args);
        let (out, err) = (String::from_utf8(o.stdout).unwrap(), o.stderr);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{args:?}: {}",
            String::from_utf8_lossy(&err)
        );
        normalize(&out)
    };
    let out = run(&["closure", f, "T", "X", "H", "--no-timings"]);
    assert!(
        out.contains("at a = 7, b = 11/2 (not 1, where the denominator (a − b) is zero)"),
        "{out}"
    );
    // (a − b) T + X = H, at a − b = 3/2.
    assert!(out.contains("3 T + 2 X = 2 H at a = 7, b = 11/2"), "{out}");
    let out = run(&["search", f, "--no-timings"]);
    assert!(
        out.contains(
            "Parameters fixed for the linear algebra: a = 7, b = 11/2 (not 1, where the \
             denominator (a − b) is zero)"
        ),
        "{out}"
    );
    let o = superint(&["closure", f, "T", "X", "--fix", "a=2,b=2"]);
    let err = String::from_utf8(o.stderr).unwrap();
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("the denominator (a − b) is zero at a = 2, b = 2"),
        "{err}"
    );
}

/// The Garnier system with a coupling `c q1` and `a1 − a2` declared: a condition that sets
/// `c = 1/(a1 − a2)` has no value where `a1 = a2`. `K = c (a1 − a2) q1` is `q1` there, so no
/// vector of the linear algebra divides by `a1 − a2`; at `a1 = a2 = 1` the closure found
/// `K = 0` and exited 0. It is refused now, on the command line (exit status 2) and in the
/// library, as a search refuses such a condition; at the default values, 1, the parameters of
/// a denominator that the condition divides by move off as a generator's do, and the closure
/// finds `K = Q`.
#[test]
fn closure_denominators_refuse_a_condition_that_divides_by_a_vanishing_denominator() {
    let text = "name = \"Garnier with a coupling\"\n\
                hamiltonian = \"(p_q1^2 + p_q2^2)/2 + (a1*q1^2 + a2*q2^2)/2 + (q1^2 + q2^2)^2/4 + c*q1\"\n\
                [phase_space]\n\
                coordinates = [\"q1\", \"q2\"]\n\
                parameters = [\"a1\", \"a2\", \"c\"]\n\
                denominators = [\"a1 - a2\"]\n\
                [[function]]\nname = \"K\"\nvalue = \"c*(a1 - a2)*q1\"\n\
                [[function]]\nname = \"Q\"\nvalue = \"q1\"\n\
                [[function]]\nname = \"V\"\nvalue = \"(a1*q1^2 + a2*q2^2)/2\"\n";
    let f = scratch_text("closure-denominators-condition", "coupled.toml", text);
    let f = f.to_str().unwrap();
    let when = ["--when", "c = 1/(a1 - a2)", "--degree", "1", "--no-timings"];
    let err =
        superint_refused(&[&["closure", f, "K", "Q", "--fix", "a1=1,a2=1"][..], &when].concat());
    assert!(
        err.contains("the denominator (a1 − a2) is zero at a1 = 1, a2 = 1"),
        "{err}"
    );
    let out = normalize(&superint_ok(
        &[&["closure", f, "K", "Q"][..], &when].concat(),
    ));
    assert!(
        out.contains("K = Q at c = 1/(a1 − a2) [R1 proved]"),
        "{out}"
    );
    // Neither generator holds a1 − a2; the condition does, and the values move off 1.
    let out = normalize(&superint_ok(
        &[&["closure", f, "V", "Q"][..], &when].concat(),
    ));
    assert!(
        out.contains("at a1 = 7, a2 = 11/2 (not 1, where the denominator (a1 − a2) is zero)"),
        "{out}"
    );

    let file = load_str("coupled.toml", text, &LimitsOverride::default()).unwrap();
    let system = file.system();
    let value = system.parse("1/(a1 - a2)").unwrap();
    let condition = Condition::new("c = 1/(a1 − a2)", system.var("c"), value);
    let (a1, a2) = (system.var("a1"), system.var("a2"));
    let at = |x: i64, y: i64| {
        ClosureOptions::new(1)
            .when(condition.clone())
            .fix(a1, x)
            .fix(a2, y)
    };
    let err = closure(system, &["K", "Q"], &at(2, 2)).unwrap_err();
    assert!(
        err.to_string()
            .starts_with("the denominator (a1 − a2) is zero at a1 = 2, a2 = 2"),
        "{err}"
    );
    let c = closure(system, &["K", "Q"], &at(2, 3)).unwrap();
    assert_eq!(c.relations.len(), 1);
    assert_eq!(c.relations[0].to_string(), "K = Q");
}

/// A generator that divides by a declared denominator in terms that vanish on the condition's
/// surface: `F = p_q1² + a1 q1² + (q1 p_q2 − q2 p_q1)²/(a1 − a2)`, a Garnier-type integral's
/// form, is `p_q1² + a1 q1²` at `q2 = 0, p_q2 = 0`, so nothing the linear algebra compares
/// divides by `a1 − a2`; its brackets are formed before the condition, from `F` itself, which
/// has no value at `a1 = a2`. At `--fix a1=1,a2=1` the closure found `{F, Q} = −2 p_q1` and
/// exited 0; it is refused now (exit 2, and in the library), and found at `a1 = 2, a2 = 3`.
#[test]
fn closure_denominators_refuse_a_generator_that_divides_by_zero_off_the_condition() {
    let text = "name = \"Garnier-type\"\n\
                hamiltonian = \"(p_q1^2 + p_q2^2)/2 + (a1*q1^2 + a2*q2^2)/2 + (q1^2 + q2^2)^2/4\"\n\
                [phase_space]\n\
                coordinates = [\"q1\", \"q2\"]\n\
                parameters = [\"a1\", \"a2\"]\n\
                denominators = [\"a1 - a2\"]\n\
                [[function]]\nname = \"F\"\n\
                value = \"p_q1^2 + a1*q1^2 + (q1*p_q2 - q2*p_q1)^2/(a1 - a2)\"\n\
                [[function]]\nname = \"Q\"\nvalue = \"q1\"\n";
    let f = scratch_text("closure-denominators-formed", "garnier-type.toml", text);
    let f = f.to_str().unwrap();
    let run = [
        "closure",
        f,
        "F",
        "Q",
        "--when",
        "q2 = 0, p_q2 = 0",
        "--degree",
        "2",
    ];
    let err = superint_refused(&[&run[..], &["--fix", "a1=1,a2=1"]].concat());
    assert!(
        err.contains("the denominator (a1 − a2) is zero at a1 = 1, a2 = 1"),
        "{err}"
    );
    let out = normalize(&superint_ok(&[&run[..], &["--fix", "a1=2,a2=3"]].concat()));
    assert!(out.contains("{F, Q} = −2 p_q1"), "{out}");

    let file = load_str("garnier-type.toml", text, &LimitsOverride::default()).unwrap();
    let system = file.system();
    let (q2, p2) = (system.var("q2"), system.var("p_q2"));
    let zero = system.parse("0").unwrap();
    let condition =
        Condition::all("q2 = 0, p_q2 = 0", vec![(q2, zero.clone()), (p2, zero)]).unwrap();
    let (a1, a2) = (system.var("a1"), system.var("a2"));
    let at = |x: i64, y: i64| {
        ClosureOptions::new(2)
            .when(condition.clone())
            .fix(a1, x)
            .fix(a2, y)
    };
    let err = closure(system, &["F", "Q"], &at(1, 1)).unwrap_err();
    assert!(
        err.to_string()
            .starts_with("the denominator (a1 − a2) is zero at a1 = 1, a2 = 1"),
        "{err}"
    );
    closure(system, &["F", "Q"], &at(2, 3)).unwrap();
}
