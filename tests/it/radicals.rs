//! Radicals: variables standing for square roots (`[phase_space] radicals`, `r = √(x² + y²)`),
//! the chain rule of their brackets, the zero test by reducing `r² = R`, the Kepler problem in
//! Cartesian coordinates (its Laplace–Runge–Lenz vector, so(4), maximal superintegrability),
//! the rank at points where the radical is rational, the closure, the search that finds the
//! Laplace–Runge–Lenz vector, a picture of the flow, and bad declarations.

use superint::prelude::*;
use superint::system_file::{load, load_str, LimitsOverride, LoadedSystem};

use crate::{
    holds, scratch_text, superint, superint_in, superint_json, superint_ok, superint_refused,
};

const PLANAR: &str = "name = \"planar Kepler\"\n\
                      hamiltonian = \"(p_x^2 + p_y^2)/2 - k/r\"\n\
                      [phase_space]\n\
                      coordinates = [\"x\", \"y\"]\n\
                      parameters = [\"k\"]\n\
                      radicals = { r = \"x^2 + y^2\" }\n";

fn planar() -> LoadedSystem {
    load_str("planar.toml", PLANAR, &LimitsOverride::default()).expect("the file loads")
}

fn kepler() -> LoadedSystem {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/systems/kepler-3d.toml");
    load(std::path::Path::new(path), &LimitsOverride::default()).expect("the file loads")
}

#[test]
fn radicals_chain_rule_gives_the_brackets() {
    let file = planar();
    assert!(holds(&file, "{r, p_x}", "x/r"));
    assert!(holds(&file, "{r, p_y}", "y/r"));
    assert!(holds(&file, "{r, x}", "0"));
    assert!(holds(&file, "{p_x, 1/r}", "x/r^3"));
    assert!(holds(&file, "{r^2, p_x}", "2*x"));
    assert!(!holds(&file, "{r, p_x}", "x"));
    assert!(!holds(&file, "{r, p_x}", "-x/r"));
    // The force of −k/r, and the angular momentum is conserved; the linear one is not.
    assert!(holds(&file, "{p_x, H}", "-k*x/r^3"));
    assert!(holds(&file, "{x*p_y - y*p_x, H}", "0"));
    assert!(!holds(&file, "{p_x, H}", "0"));
}

#[test]
fn radicals_zero_is_decided_by_reducing() {
    let file = planar();
    assert!(holds(&file, "r^2", "x^2 + y^2"));
    assert!(holds(&file, "x^2/r^3 + y^2/r^3", "1/r"));
    assert!(holds(&file, "r^3", "(x^2 + y^2)*r"));
    // Division by the radicand is by r², and sqrt of it (times a rational square) is r.
    assert!(holds(&file, "x/(x^2 + y^2)", "x/r^2"));
    assert!(holds(&file, "sqrt(x^2 + y^2)", "r"));
    assert!(holds(&file, "k/sqrt(9*x^2 + 9*y^2)^3", "k/(27*r^3)"));
    assert!(holds(&file, "sqrt(9/4)", "3/2"));
    // `√`, as the text form prints a root: of parentheses or of a name or number.
    assert!(holds(&file, "√(x^2 + y^2)", "r"));
    assert!(holds(&file, "k/√(9x² + 9y²)³", "k/(27*r^3)"));
    assert!(holds(&file, "√4 x", "2*x"));
    assert!(!holds(&file, "sqrt(4*x^2 + 4*y^2)", "r"));
    for (root, message) in [
        ("sqrt(2)", "sqrt(2) is not a rational number"),
        (
            "sqrt(2*x^2 + 2*y^2)",
            "sqrt(2x² + 2y²) is no declared radical",
        ),
        ("sqrt(x^2 + 2*y^2)", "radicals = { r = \"x^2 + 2*y^2\" }"),
        // The root of a square is a polynomial up to its sign: no radical to declare.
        (
            "sqrt(x^2)",
            "sqrt(x²) is |x|, whose sign is for you to choose: write x where it is not \
             negative, and its negative where it is",
        ),
        (
            "sqrt(-4*x^2 - 4*y^2 - 8*x*y)",
            "sqrt(−4x² − 8xy − 4y²) is i·|2x + 2y|, whose sign is for you to choose: write \
             i*(2*x + 2*y) where 2x + 2y is not negative, and its negative where it is",
        ),
        (
            "sqrt(x^2/4 - x*y + y^2)",
            "sqrt(x²/4 − xy + y²) is |x/2 − y|, whose sign is for you to choose: write \
             x/2 - y where it is not negative",
        ),
    ] {
        let err = file.parse(root).expect_err(root).to_string();
        assert!(err.contains(message), "{root}: {err}");
    }
    // r is no polynomial: neither x nor −x, and r² is not x².
    assert!(!holds(&file, "r", "x"));
    assert!(!holds(&file, "r^2", "x^2"));
    let refuted = Claim::new(
        "t",
        "t",
        file.parse("x^2/r^3 + y^2/r^3 + r").unwrap(),
        file.parse("1/r").unwrap(),
    )
    .check()
    .unwrap();
    let Outcome::Refuted { residual } = refuted.outcome else {
        panic!("x²/r³ + y²/r³ + r is not 1/r")
    };
    // The residual is reduced: r, not x²/r³ + y²/r³ − 1/r + r.
    assert_eq!(residual.to_string(), "r");
}

#[test]
fn radicals_half_integer_powers_of_a_radicand_are_powers_of_its_radical() {
    let file = planar();
    // The force as physicists write it: R^(p/2) is r^p, for every odd p of either sign.
    assert!(holds(&file, "{p_x, H}", "-k*x/(x^2 + y^2)^(3/2)"));
    assert!(holds(&file, "(x^2 + y^2)^(1/2)", "r"));
    assert!(holds(&file, "(x^2 + y^2)^(-1/2)", "1/r"));
    assert!(holds(&file, "(x^2 + y^2)^(5/2)", "r^5"));
    assert!(holds(&file, "(4*x^2 + 4*y^2)^(3/2)", "8*r^3"));
    assert!(holds(&file, "(9/4)^(-3/2)", "8/27"));
    // Integer and half-integer powers agree where both apply.
    assert!(holds(&file, "(x^2 + y^2)^(4/2)", "(x^2 + y^2)^2"));
    assert!(!holds(&file, "(x^2 + y^2)^(3/2)", "r^2"));
    assert!(!holds(&file, "(x^2 + y^2)^(-3/2)", "r^3"));
    for (power, message) in [
        (
            "(x^2 + 2*y^2)^(3/2)",
            "sqrt(x² + 2y²) is no declared radical: declare it (radicals = { r = \"x^2 + 2*y^2\" } \
             in [phase_space], for a name r of yours), and its power 3/2 reads as r^3",
        ),
        (
            "x^(1/2)",
            "sqrt(x) is no declared radical: declare it (radicals = { r = \"x\" } in \
             [phase_space], for a name r of yours), and its power 1/2 reads as r",
        ),
        ("2^(3/2)", "sqrt(2) is not a rational number"),
        ("(x^2 + 2*x*y + y^2)^(1/2)", "sqrt(x² + 2xy + y²) is |x + y|"),
        (
            "(x^2 + y^2)^(1/3)",
            "exponents must be integers or halves of odd integers (a power of a declared \
             radical, (x^2 + y^2)^(3/2) for r^3), found 1/3",
        ),
        ("(x^2 + y^2)^(2001/2)", "the exponent 2001/2 is past the limit of 1000"),
    ] {
        let err = file.parse(power).expect_err(power).to_string();
        assert!(err.contains(message), "{power}: {err}");
    }
}

#[test]
fn radicals_kepler_claims_are_proved_and_the_wrong_signs_refuted() {
    let file = kepler();
    let report = superint::system_file::check_report([&file]).expect("checked");
    assert!(report.all_as_expected());
    let ids: Vec<(String, bool)> = report.claim_ids();
    let expect = |id: &str, proved: bool| {
        assert!(
            ids.iter().any(|c| c.0 == id && c.1 == proved),
            "{id} {proved}: {ids:?}"
        );
    };
    for id in [
        "radius",
        "radial-velocity",
        "angular-momentum",
        "lrl",
        "so3",
        "vector",
        "so4",
        "orthogonal",
        "length",
        "rank",
    ] {
        expect(id, true);
    }
    for id in ["lrl-sign", "so4-sign", "rank-six"] {
        expect(id, false);
    }
    // The Laplace–Runge–Lenz vector needs the potential's term with its sign, and its
    // brackets close on −2HL/M, not 2HL/M.
    assert!(holds(&file, "{Az, H}", "0"));
    assert!(!holds(&file, "{Az + 2*k*z/r, H}", "0"));
    assert!(holds(&file, "{Ay, Az}", "-2*H*Lx/M"));
    assert!(!holds(&file, "{Ay, Az}", "-H*Lx/M"));
}

/// The rank of the Kepler integrals: the Jacobian through `r` by the chain rule, certified at a
/// point of small integers where `x² + y² + z²` is a square, so that `r` is rational there.
#[test]
fn radicals_rank_is_certified_where_the_radical_is_rational() {
    let file = kepler();
    let exprs: Vec<Expr> = ["H", "Lx", "Ly", "Lz", "Ax", "Ay", "Az"]
        .iter()
        .map(|f| file.parse(f).unwrap())
        .collect();
    let cert = rank(file.system().space(), &exprs).unwrap();
    assert_eq!(cert.rank, 5);
    assert!(matches!(cert.upper, UpperBound::VanishingMinors { .. }));
    let vars = file.system().vars();
    let value = |name: &str| {
        let v = vars.lookup(name).unwrap();
        let value = &cert.point.iter().find(|(w, _)| *w == v).unwrap().1;
        value.re.clone()
    };
    let (x, y, z, r) = (value("x"), value("y"), value("z"), value("r"));
    assert_eq!(&r * &r, &(&x * &x + &y * &y) + &z * &z);
    assert!(!r.is_negative());
    // Without the chain rule through r, −k/r would not depend on x: H, L_z and A_x would
    // still be independent, and x/r and y/r are not (their ratio is y/x).
    let two: Vec<Expr> = ["x/r", "y/r", "x/y"]
        .iter()
        .map(|f| file.parse(f).unwrap())
        .collect();
    assert_eq!(rank(file.system().space(), &two).unwrap().rank, 2);
}

/// Two radicands that small integers rarely make squares together, `x² + y² + z²` and `(x −
/// a)² + y² + z²` (the sample points once took a sequence of 72 tuples, none of them such a
/// point, and the rank was refused): the certificate's point makes both exact, and the rank
/// sees that `s² = r² − 2ax + a²` ties `x`, `r`, `s` while `y` is free of them. A radicand
/// that only fractions make squares is taken at one; one that nothing makes a square is
/// refused.
#[test]
fn radicals_rank_finds_a_point_where_two_radicands_are_squares() {
    let text = "name = \"two radicals\"\n\
                hamiltonian = \"(p_x^2 + p_y^2 + p_z^2)/2 - k/r - k/s\"\n\
                [phase_space]\n\
                coordinates = [\"x\", \"y\", \"z\"]\n\
                parameters = [\"k\", \"a\"]\n\
                radicals = { r = \"x^2 + y^2 + z^2\", s = \"(x - a)^2 + y^2 + z^2\" }\n";
    let file = load_str("two.toml", text, &LimitsOverride::default()).expect("the file loads");
    let parse = |fs: &[&str]| -> Vec<Expr> { fs.iter().map(|f| file.parse(f).unwrap()).collect() };
    let tied = rank(file.system().space(), &parse(&["x", "r", "s"])).unwrap();
    assert_eq!(tied.rank, 2);
    assert!(matches!(tied.upper, UpperBound::VanishingMinors { .. }));
    let vars = file.system().vars();
    let value = |name: &str| {
        let v = vars.lookup(name).unwrap();
        tied.point
            .iter()
            .find(|(w, _)| *w == v)
            .unwrap()
            .1
            .re
            .clone()
    };
    let (x, y, z, a) = (value("x"), value("y"), value("z"), value("a"));
    let (r, s) = (value("r"), value("s"));
    assert_eq!(&r * &r, &(&x * &x + &y * &y) + &z * &z);
    let shifted = &x - &a;
    assert_eq!(&s * &s, &(&shifted * &shifted + &y * &y) + &z * &z);
    assert!(!r.is_negative() && !s.is_negative());
    assert_eq!(
        rank(file.system().space(), &parse(&["x", "y", "r", "s"]))
            .unwrap()
            .rank,
        3
    );
    // A radicand that no integer makes a square, x² + 2, is one at x = 1/2 (9/4).
    let half = scratch_text(
        "radicals-rank",
        "half.toml",
        &text.replace("x^2 + y^2 + z^2\"", "x^2 + 2\""),
    );
    let out = superint_ok(&["rank", half.to_str().unwrap(), "x", "y", "r"]);
    assert!(
        out.contains("rank ∂(x, y, r)/∂(x, y, z, p_x, p_y, p_z) = 2") && out.contains("r = 3/2"),
        "{out}"
    );
    // One that no rational makes a square (3x² + 2 = y² has no rational solution, as 2 is no
    // square modulo 3): refused, about all the functions given, with the radicands, and
    // without the denominators the file does not have (it said that one might vanish).
    let never = scratch_text(
        "radicals-rank",
        "never.toml",
        &text.replace("x^2 + y^2 + z^2\"", "3*x^2 + 2\""),
    );
    let err = superint_refused(&["rank", never.to_str().unwrap(), "x", "r", "s"]);
    assert!(
        err.contains(
            "superint: error: <command line>:1:1: no point of small integers or fractions of \
             them makes every radicand (r = √(3x² + 2), s = √(x² − 2ax + y² + z² + a²)) the \
             square of a rational, where the radicals have exact values: the rank is certified \
             at exact points, and there is none\n 1 | x r s\n   | ^^^^^"
        ),
        "{err}"
    );
}

/// The closure of the seven integrals: so(4) with `{A_x, A_y} = −2 H L_z/M`, and at degree 3
/// the two relations `A · L = 0` and `M|A|² = Mk² + 2H|L|²`.
#[test]
fn radicals_closure_finds_so4_and_the_relations() {
    let f = concat!(env!("CARGO_MANIFEST_DIR"), "/systems/kepler-3d.toml");
    let o = superint(&[
        "closure",
        f,
        "H",
        "Lx",
        "Ly",
        "Lz",
        "Ax",
        "Ay",
        "Az",
        "--degree",
        "3",
        "--no-timings",
    ]);
    let out = String::from_utf8(o.stdout).unwrap();
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(out.contains("{A_x, A_y} = −2 H L_z/M"), "{out}");
    assert!(out.contains("{L_y, A_x} = −A_z"), "{out}");
    assert!(out.contains("L_x A_x + L_y A_y + L_z A_z = 0"), "{out}");
    assert!(
        out.contains("Mk² + 2 H L_x² + 2 H L_y² + 2 H L_z² = M A_x² + M A_y² + M A_z²"),
        "{out}"
    );
    assert!(out.contains("The table closes"), "{out}");
}

/// Bracket and expand print the reduced forms, over the least power of `r`.
#[test]
fn radicals_commands_print_reduced_forms() {
    let f = scratch_text("radicals-cli", "planar.toml", PLANAR);
    let f = f.to_str().unwrap();
    let o = superint(&["bracket", f, "r", "p_x"]);
    assert_eq!(o.status.code(), Some(0));
    assert!(String::from_utf8(o.stdout)
        .unwrap()
        .contains("{r, p_x} = x/r"));
    let o = superint(&["expand", f, "x^2/r^3 + y^2/r^3", "r^2"]);
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.contains("x²/r³ + y²/r³ = 1/r"), "{out}");
    assert!(out.contains("r²            = x² + y²"), "{out}");
}

/// The search through a radical: from `H` alone it finds the angular momentum and the
/// Laplace–Runge–Lenz vector of the Kepler problem in space as new integrals, the monomials
/// equal as functions to simpler ones (`r² = x² + y² + z²`) left out of the unknowns; a
/// radicand may hold a parameter kept symbolic.
#[test]
fn radicals_search_finds_the_laplace_runge_lenz_vector() {
    let bare = "name = \"Kepler, H alone\"\n\
                hamiltonian = \"(p_x^2 + p_y^2 + p_z^2)/(2*M) - k/r\"\n\
                [phase_space]\n\
                coordinates = [\"x\", \"y\", \"z\"]\n\
                parameters = [\"M\", \"k\"]\n\
                radicals = { r = \"x^2 + y^2 + z^2\" }\n";
    let f = scratch_text("radicals-search", "bare.toml", bare);
    let f = f.to_str().unwrap();
    let search = |more: &[&str]| {
        let mut args = vec!["search", f, "--no-timings"];
        args.extend(more);
        let o = superint(&args);
        let out = String::from_utf8(o.stdout).unwrap();
        assert_eq!(
            o.status.code(),
            Some(0),
            "{out}{}",
            String::from_utf8_lossy(&o.stderr)
        );
        out
    };
    let json = |more: &[&str]| -> serde_json::Value {
        let mut args = more.to_vec();
        args.extend(["--format", "json"]);
        serde_json::from_str(&search(&args)).expect("JSON")
    };
    let degree_2 = ["--momenta-degree", "2", "--positions-degree", "1"];
    let v = json(&[&degree_2[..], &["--new-only"]].concat());
    let found = &v["searches"][0];
    assert_eq!(found["dimension"], 8, "{found}");
    assert_eq!(found["for_every_value"], 8, "{found}");
    assert_eq!(
        found["new_only"]["known"],
        serde_json::json!(["H"]),
        "{found}"
    );
    assert_eq!(found["shown"].as_array().unwrap().len(), 6, "{found}");
    let out = search(&[&degree_2[..], &["--new-only"]].concat());
    let flat = out.split_whitespace().collect::<Vec<_>>().join(" ");
    for integral in [
        "x p_y − y p_x",
        "x p_y² + x p_z² − y p_x p_y − z p_x p_z − Mkx/r",
        "x p_x p_y − y p_x² − y p_z² + z p_y p_z + Mky/r",
        "r and 1/r of degree 1",
    ] {
        assert!(flat.contains(integral), "{integral}: {out}");
    }
    // Without the radical's powers the vector is not in the space, and H is outside it.
    let v = json(&[&degree_2[..], &["--radicals-degree", "0"]].concat());
    assert_eq!(v["searches"][0]["dimension"], 4, "{v}");
    let out = search(&[&degree_2[..], &["--radicals-degree", "0"]].concat());
    assert!(
        crate::normalize(&out).contains(
            "H is not in this space (degree 1 in the radicals, past the space's 0 \
             (SearchSpace::radicals_degree; on the command line, --radicals-degree))"
        ),
        "{out}"
    );
    // Of the 10 · 5 monomials of degree ≤ 2 in x, y, z times r^j, |j| ≤ 2, three equal sums
    // of others and are left out, one for each of r² = x² + y² + z², x²/r + y²/r + z²/r = r
    // and x²/r² + y²/r² + z²/r² = 1.
    let v = json(&[
        "--momenta-degree",
        "0",
        "--positions-degree",
        "2",
        "--radicals-degree",
        "2",
    ]);
    assert_eq!(v["searches"][0]["unknowns"], 47, "{v}");
    assert_eq!(v["searches"][0]["dimension"], 1, "{v}");
    // A parameter inside a radicand is kept symbolic too. With `r² = x² + y² + z² + k` the
    // potential `−k/r` is still central, and the integrals of degree ≤ 2 are generated over the
    // polynomials in k by 1, L_x, L_y, L_z, H and the six products L_i L_j: over Q, 1, L_i and
    // L_i L_j times 1, k, k², and H times 1, k and k², where `k²H` holds `k³/r`, which is
    // `k²r − k²(x² + y² + z²)/r` since k itself equals `r² − x² − y² − z²` there.
    let shifted = bare.replace("\"x^2 + y^2 + z^2\"", "\"x^2 + y^2 + z^2 + k\"");
    let g = scratch_text("radicals-search", "shifted.toml", &shifted);
    let v = superint_json(&["search", g.to_str().unwrap(), "--symbolic", "k"]);
    let search = &v["searches"][0];
    assert_eq!(search["dimension"], 3 + 3 * 3 + 3 + 6 * 3, "{search}");
    assert_eq!(search["for_every_value"], 33, "{search}");
    assert_eq!(search["shown"].as_array().unwrap().len(), 11, "{search}");
}

#[test]
fn radicals_bad_declarations_are_refused_at_their_place() {
    let with = |radicals: &str| PLANAR.replace("{ r = \"x^2 + y^2\" }", radicals);
    let cases = [
        (
            "{ r = \"x^2 + 2*x*y + y^2\" }",
            "bad.toml:6:14: the radicand of r = √(x² + 2xy + y²) is the square of x + y, so the \
             radical is x + y up to its sign, which is for you to choose: write x + y where it \
             is not negative, and its negative where it is",
        ),
        (
            "{ r = \"4\" }",
            "bad.toml:6:18: the radicand of r is the constant 4",
        ),
        ("{ r = \"x^2 + q\" }", "bad.toml:6:25: unknown name 'q'"),
        (
            "{ r = \"i*x + y\" }",
            "bad.toml:6:18: the radicand ix + y is not real",
        ),
        (
            "{ r = \"-x^2 - y^2 - 1\" }",
            "bad.toml:6:18: the radicand −x² − y² − 1 is nowhere positive (each term is a \
             negative number times even powers), so r is real nowhere",
        ),
        (
            // A long square: said by its size, its root not sought (`^500` took minutes).
            "{ r = \"(x^2 + y^2 + 1)^40\" }",
            "bad.toml:6:14: the radicand of r = √(a polynomial of 861 terms) is a square (it is \
             one at every point tried)",
        ),
        (
            "{ x = \"x^2 + y^2\" }",
            "bad.toml:6:14: 'x' is already declared as a coordinate",
        ),
        (
            "{ r = \"x^2 + y^2\", s = \"4*x^2 + 4*y^2\" }",
            "bad.toml:6:14: the product of the radicands of r = √(x² + y²), s = √(4x² + 4y²) is \
             a square",
        ),
        (
            "{ r = \"1/(1 + x^2)\" }",
            "bad.toml:6:21: cannot divide by x² + 1",
        ),
        ("[\"x^2 + y^2\"]", "bad.toml:6:12: invalid type: sequence"),
    ];
    for (radicals, expected) in cases {
        let f = scratch_text("radicals-bad", "bad.toml", &with(radicals));
        let dir = f.parent().unwrap();
        let o = superint_in(dir, &["check", "bad.toml"]);
        let err = String::from_utf8(o.stderr).unwrap();
        assert_eq!(o.status.code(), Some(2), "{radicals}: {err}");
        assert!(
            err.starts_with(&format!("superint: error: {expected}")),
            "{radicals}: expected {expected:?}, got {err}"
        );
    }
    // A denominator with a radical in it.
    let text = format!("{PLANAR}denominators = [\"r - x\"]\n");
    let err = load_str("bad.toml", &text, &LimitsOverride::default())
        .expect_err("refused")
        .to_string();
    assert!(
        err.starts_with("bad.toml:7:17: the denominator −x + r has a radical in it"),
        "{err}"
    );
}

/// A picture of the Kepler flow: Hamilton's equations through `r`, evaluated as the root of
/// its radicand; H, L_z and A_x stay put to rounding while the body moves, and a start at the
/// origin, where `1/r` has no value, is refused.
#[test]
fn radicals_plot_keeps_the_kepler_integrals() {
    let f = concat!(env!("CARGO_MANIFEST_DIR"), "/systems/kepler-3d.toml");
    let svg = std::env::temp_dir().join(format!("superint-kepler-{}.svg", std::process::id()));
    let plot = |from: &str| {
        superint(&[
            "plot",
            f,
            "x",
            "Lz",
            "Ax",
            "Ay",
            "--at",
            "M = 1, k = 1",
            "--from",
            from,
            "--time",
            "10",
            "--method",
            "gauss",
            "-o",
            svg.to_str().unwrap(),
            "--format",
            "json",
        ])
    };
    let o = plot("x = 1, y = 0, z = 0, p_x = 0, p_y = 4/5, p_z = 0");
    let out = String::from_utf8(o.stdout).unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{out}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let doc: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    for f in doc["functions"].as_array().expect("functions") {
        let label = f["function"].as_str().unwrap();
        let change = f["largest_change"].as_f64().unwrap();
        match label {
            "x" => assert!(change > 1.0, "x moved by {change}"),
            _ => assert!(change < 1e-6, "{label} changed by {change}"),
        }
    }
    let _ = std::fs::remove_file(&svg);
    let o = plot("x = 0, y = 0, z = 0, p_x = 1, p_y = 0, p_z = 0");
    let err = String::from_utf8(o.stderr).unwrap();
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("is not defined at the starting point: r = √(x² + y² + z²) is the root of 0"),
        "{err}"
    );
}

/// A condition that sets a variable of a radicand is refused, at the variable, by every
/// command: the radical would keep its radicand, so `r² = x² + y² + z²` at `z = 0` would
/// refute `r² = x² + y²`, and a rank at `a = 0` of `t = √(x² + ay²)` would be certified at
/// a point of another `a`. A condition on other variables stays.
#[test]
fn a_condition_on_a_radicands_variable_is_refused() {
    let text = "name = \"radicand\"\n\
                hamiltonian = \"(p_x^2 + p_y^2)/2 - k/t\"\n\
                [phase_space]\n\
                coordinates = [\"x\", \"y\"]\n\
                parameters = [\"k\", \"a\"]\n\
                radicals = { t = \"x^2 + a*y^2\" }\n";
    let claim = "[[claim]]\nclaim = \"rank(t, x) = 2\"\nwhen = \"a = 0\"\n";
    let f = scratch_text(
        "radicals-condition",
        "claim.toml",
        &format!("{text}{claim}"),
    );
    let o = superint_in(f.parent().unwrap(), &["check", "claim.toml"]);
    let err = String::from_utf8(o.stderr).unwrap();
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.starts_with(
            "superint: error: claim.toml:9:9: the condition sets a, which the radicand of t = \
             √(x² + ay²) involves: a condition on a radicand's variables is not supported"
        ),
        "{err}"
    );
    let f = scratch_text("radicals-condition", "plain.toml", text);
    let f = f.to_str().unwrap();
    let commands: [&[&str]; 4] = [
        &["expand", f, "t^2", "--when", "a = 1"],
        &["bracket", f, "t", "p_y", "--when", "y = 0"],
        &["search", f, "--when", "a = 1"],
        &["closure", f, "H", "--define", "T=t^2", "--when", "a = 0"],
    ];
    for args in commands {
        let o = superint(args);
        let err = String::from_utf8(o.stderr).unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            err.contains("<command line>:1:1: the condition sets ")
                && err.contains("which the radicand of t = √(x² + ay²) involves"),
            "{args:?}: {err}"
        );
    }
    // The library refuses the condition when it is made.
    let file = load_str("plain.toml", text, &LimitsOverride::default()).expect("the file loads");
    let vars = file.system().vars();
    let zero = Expr::constant(vars, GaussianRational::from(0));
    let err = Condition::all("x = 0", vec![(file.system().var("x"), zero)])
        .expect_err("x is in the radicand");
    assert!(err.to_string().starts_with("the condition sets x"), "{err}");
    // A parameter outside the radicand may be set.
    let out = superint_ok(&["expand", f, "k/t", "--when", "k = 2"]);
    assert!(out.contains("k/t = 2/t"), "{out}");
}

/// A radical stands for a function of the coordinates: a condition that sets it alone
/// (`r = 1`) contradicts `r² = x² + y²`, and refuted the true `r² = x² + y²` there. It is
/// refused, in a file's claim at its place and on the command line, the caret under the
/// radical (it stood under the value).
#[test]
fn a_condition_on_a_radical_is_refused() {
    let claim = format!("{PLANAR}[[claim]]\nclaim = \"r^2 = x^2 + y^2\"\nwhen = \"r = 1\"\n");
    let file = scratch_text("radicals-condition", "on-r.toml", &claim);
    let err = superint_refused(&["check", file.to_str().expect("a path")]);
    assert!(
        err.contains(
            "on-r.toml:9:9: the condition sets r, which is a radical, a function of \
                      the other variables"
        ),
        "{err}"
    );
    let planar = scratch_text("radicals-condition", "planar.toml", PLANAR);
    let planar = planar.to_str().expect("a path");
    let err = superint_refused(&["bracket", planar, "r", "H", "--when", "k = 1, r = 2"]);
    assert!(
        err.contains(
            "<command line>:1:8: the condition sets r, which is a radical, a function of the \
             other variables: a condition sets coordinates, momenta, angles or parameters; set \
             those it is made of\n 1 | k = 1, r = 2\n   |        ^\n"
        ),
        "{err}"
    );
}

/// A search at `--radicals-degree 0` has no power of a radical in its space, and says so: its
/// monomials are `x^a y^b p_x^c p_y^d` (they were written `x^a y^b s^c p_x^d p_y^e` with
/// `|c| ≤ 0`), independent (the note that `s² = …` leaves some out is gone), and a grade
/// counts the coordinates and momenta alone; at degree 1 the radical is back in all three. So
/// for the denominators at `--denominators-degree 0`.
#[test]
fn a_search_without_powers_of_the_radicals_describes_a_space_without_them() {
    let search = |degree: &str| {
        crate::normalize(&crate::superint_ok_line(&format!(
            "search systems/zernike.toml --momenta-degree 1 --positions-degree 1 \
             --trig-degree 0 --radicals-degree {degree} --new-only --no-timings"
        )))
    };
    let none = search("0");
    for piece in [
        "The space: x^a y^b p_x^c p_y^d, with momenta degree c + d ≤ 1, positions degree \
         |a| + |b| ≤ 1:",
        "An integral of degree N (in the coordinates and momenta together) is generated",
    ] {
        assert!(none.contains(piece), "{piece}: {none}");
    }
    assert!(!none.contains("s^") && !none.contains("s² ="), "{none}");
    let one = search("1");
    for piece in [
        "The space: x^a y^b s^c p_x^d p_y^e, with momenta degree d + e ≤ 1, positions degree \
         |a| + |b| ≤ 1, degree |c| ≤ 1 in the radicals:",
        "(with radicals the monomials are not independent, s² = γ₂ x² + γ₂ y² + 1:",
        "(in the coordinates, momenta and radicals together, s and 1/s of degree 1)",
    ] {
        assert!(one.contains(piece), "{piece}: {one}");
    }
    // So for a denominator at `--denominators-degree 0`: no `(x − y)^g` in the monomial.
    let calogero = crate::normalize(&crate::superint_ok_line(
        "search systems/calogero.toml --momenta-degree 1 --positions-degree 1 --trig-degree 0 \
         --denominators-degree 0 --no-timings",
    ));
    assert!(
        calogero.contains(
            "The space: x^a y^b z^c p_x^d p_y^e p_z^f, with momenta degree d + e + f ≤ 1, \
             positions degree |a| + |b| + |c| ≤ 1: 16 unknowns,"
        ),
        "{calogero}"
    );
}

/// A report's line on what each radical stands for writes the radicand as the file declares
/// it, in the paper's notation: the two centres' distances `√((x − a)² + y² + z²)` (they were
/// written in normal form, `√(x² − 2ax + y² + z² + a²)`, which hid the centre at `x = a`), and
/// the Zernike file's `√(1 + γ₂ (x² + y²))` with its display names.
#[test]
fn a_report_writes_each_radicand_as_declared() {
    let check = |file: &str| crate::normalize(&superint_ok(&["check", file, "--no-timings"]));
    let centres = check("systems/two-centres.toml");
    assert!(
        centres.contains("with r = √((x − a)² + y² + z²), s = √((x + a)² + y² + z²)."),
        "{centres}"
    );
    let zernike = check("systems/zernike.toml");
    assert!(
        zernike.contains("with s = √(1 + γ₂ (x² + y²))."),
        "{zernike}"
    );
}
