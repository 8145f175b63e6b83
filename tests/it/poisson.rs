//! Declared (Lie–Poisson) structures: the Euler top on so(3)* and the Kovalevskaya top on
//! e(3)*, proved and refuted through the library and the real binary; the bracket's laws
//! (Jacobi, Leibniz) on functions of Poisson variables; Hamilton's equations `ż = {z, H}` and
//! their picture; the commands that take such a structure; the search for every integral of
//! bounded degree in the Poisson variables, whose dimensions are checked against the span of
//! the known integrals' products, formed here.

use brackets::linalg::Matrix;
use brackets::search::{fix_parameters, search, SearchOptions, SearchResult, SearchSpace};
use brackets::{EngineError, PhaseSpace, System};
use serde_json::Value;
use std::collections::HashMap;
use superint::system_file::{load, LimitsOverride, LoadedSystem};
use trigpoly::{Expr, Rational, Vars};

use crate::superint;

/// A system file of `systems/`, loaded.
fn system_file(name: &str) -> LoadedSystem {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("systems")
        .join(name);
    load(&path, &LimitsOverride::default()).expect("the file loads")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8(bytes.to_vec()).expect("UTF-8 output")
}

/// so(3)* with `{M1, M2} = M3` and cyclically, built in code.
fn so3() -> (trigpoly::Vars, PhaseSpace) {
    let vars = Vars::builder()
        .poisson("M1")
        .poisson("M2")
        .poisson("M3")
        .parameter("a")
        .build()
        .unwrap();
    let e = |s: &str| Expr::parse(&vars, s).unwrap();
    let space = PhaseSpace::new(&vars, &[])
        .unwrap()
        .with_brackets(&[
            ("M1", "M2", e("M3")),
            ("M2", "M3", e("M1")),
            ("M3", "M1", e("M2")),
        ])
        .unwrap();
    (vars, space)
}

#[test]
fn euler_top_casimir_energy_and_euler_equations() {
    let top = system_file("euler-top.toml");
    let sys = top.system();
    for m in ["M1", "M2", "M3"] {
        identity!(sys, format!("{{C, {m}}} = 0"));
    }
    identity!(sys, "{H, H} = 0");
    identity!(sys, "{C, H} = 0");
    identity!(sys, "{M1, H} = (1/I2 - 1/I3)*M2*M3");
    identity!(sys, "{M2, H} = (1/I3 - 1/I1)*M3*M1");
    identity!(sys, "{M3, H} = (1/I1 - 1/I2)*M1*M2");
    // The other sign is the body frame's (the bracket's sign changed): refuted here, by twice
    // the right-hand side.
    identity!(sys, "{M1, H} = (1/I3 - 1/I2)*M2*M3" => refuted "2*(1/I2 - 1/I3)*M2*M3");
    identity!(sys, "{M3, H} = 0" => refuted "(1/I1 - 1/I2)*M1*M2");
    identity!(sys, "{M1^2/(2*I1), H} = 0" => refuted "(1/I2 - 1/I3)*M1*M2*M3/I1");
    let rank = sys.rank(&["H", "C"]).expect("a certificate");
    assert_eq!(rank.rank, 2);
    let functions = ["H", "C", "M1"].map(|f| sys.parse(f).unwrap());
    let rank = brackets::rank(sys.space(), &functions).expect("a certificate");
    assert_eq!(rank.rank, 3);
}

#[test]
fn kovalevskaya_integral_is_conserved_and_its_neighbours_are_not() {
    let top = system_file("kovalevskaya-top.toml");
    let sys = top.system();
    for v in ["M1", "M2", "M3", "gamma1", "gamma2", "gamma3"] {
        identity!(sys, format!("{{Gamma, {v}}} = 0"));
        identity!(sys, format!("{{A, {v}}} = 0"));
    }
    identity!(sys, "{K, H} = 0");
    identity!(sys, "{xi, H} = 2*i*M3*xi");
    identity!(
        sys,
        "{((M1 + i*M2)^2 + c*(gamma1 + i*gamma2))*((M1 - i*M2)^2 + c*(gamma1 - i*gamma2)), H} = 0"
            => refuted "2*c*M1^2*M2*gamma3 + 2*c^2*M1*gamma2*gamma3 + 2*c*M2^3*gamma3 \
                        - 2*c^2*M2*gamma1*gamma3"
    );
    // I3 = I1/3 instead of I1/2: the integral is Kovalevskaya's case alone.
    identity!(
        sys,
        "{K, H + M3^2/2} = 0"
            => refuted "4*c*M1^2*M3*gamma2 - 8*c*M1*M2*M3*gamma1 - 4*c*M2^2*M3*gamma2"
    );
    assert_eq!(sys.rank(&["H", "K", "Gamma", "A"]).unwrap().rank, 4);
    // The two Casimirs are constant on the symplectic leaves: with them, H and K, a fifth
    // function such as M3 is still independent on the six-dimensional e(3)*.
    let more = ["H", "K", "Gamma", "A", "M3"];
    let mut system = sys.clone();
    system.define_parsed("M3f", "M3f", "M3").unwrap();
    let named = more.map(|n| if n == "M3" { "M3f" } else { n });
    assert_eq!(system.rank(&named).unwrap().rank, 5);
}

#[test]
fn lie_poisson_bracket_jacobi_leibniz_and_antisymmetry() {
    let (vars, space) = so3();
    let e = |s: &str| Expr::parse(&vars, s).unwrap();
    let br = |f: &Expr, g: &Expr| space.bracket(f, g).unwrap();
    let (f, g, h) = (
        e("M1^2*M2 + a*M3"),
        e("M2*M3^3 - 2*M1"),
        e("M1*M2*M3 + M2^2/3"),
    );
    let jacobi = &(&br(&f, &br(&g, &h)) + &br(&g, &br(&h, &f))) + &br(&h, &br(&f, &g));
    assert!(jacobi.is_zero(), "Jacobi: {jacobi}");
    assert_eq!(
        br(&f, &(&g * &h)),
        &(&br(&f, &g) * &h) + &(&g * &br(&f, &h))
    );
    assert_eq!(br(&f, &g), -br(&g, &f));
    assert_eq!(br(&e("M2"), &e("M1")), e("-M3"));
    // With a kept gradient, and on a condition, the same bracket.
    let dg = space.gradient(&g).unwrap();
    assert_eq!(space.bracket_with_gradient(&f, &dg).unwrap(), br(&f, &g));
    let m3 = vars.lookup("M3").unwrap();
    let at = space
        .bracket_with_gradient_at(&f, &dg, &[(m3, e("2"))])
        .unwrap();
    assert_eq!(at, br(&f, &g).subst(m3, &e("2")).unwrap());
}

#[test]
fn library_api_refuses_what_is_not_a_poisson_structure() {
    let vars = Vars::builder()
        .coordinate("x")
        .momentum("p_x")
        .poisson("S1")
        .poisson("S2")
        .poisson("S3")
        .parameter("g")
        .build()
        .unwrap();
    let e = |s: &str| Expr::parse(&vars, s).unwrap();
    let space = || PhaseSpace::new(&vars, &[("x", "p_x")]).unwrap();
    let so3 = [
        ("S1", "S2", e("S3")),
        ("S2", "S3", e("S1")),
        ("S3", "S1", e("S2")),
    ];
    let err =
        |brackets: &[(&str, &str, Expr)]| space().with_brackets(brackets).unwrap_err().to_string();
    let mut twice = so3.to_vec();
    twice.push(("S2", "S1", e("-S3")));
    assert!(
        err(&twice).contains("{S2, S1} is given twice"),
        "{}",
        err(&twice)
    );
    assert!(err(&[("x", "p_x", e("2"))]).contains("canonical variables"));
    assert!(err(&[("S1", "g", e("1"))]).contains("is a parameter"));
    assert!(err(&[("S1", "S2", e("i*S3"))]).contains("is not real"));
    // {x, S1} = 1 with so(3): {x, {S2, S3}} = {x, S1} = 1, while the other two terms vanish.
    let mut mixed = so3.to_vec();
    mixed.push(("x", "S1", e("1")));
    let Err(EngineError::Jacobi(violation)) = space().with_brackets(&mixed) else {
        panic!("Jacobi is broken by {{x, S1}} = 1");
    };
    assert_eq!(violation.residual, e("1"));
    // A spin coupled to a particle: canonical and declared brackets side by side.
    let spin = space().with_brackets(&so3).unwrap();
    let h = e("p_x^2/2 + g*x*S3");
    let system = System::new("spin", spin.clone(), h.clone()).unwrap();
    let parse = |s: &str| system.parse(s).unwrap();
    assert!(system.flow(&parse("S1^2 + S2^2 + S3^2")).unwrap().is_zero());
    assert!(system.flow(&parse("S3")).unwrap().is_zero());
    // {S1, g x S3} = g x {S1, S3} = −g x S2.
    assert_eq!(system.flow(&parse("S1")).unwrap(), parse("-g*x*S2"));
    assert_eq!(system.flow(&parse("p_x")).unwrap(), parse("-g*S3"));
    assert_eq!(
        system.bracket(&parse("x"), &parse("S1")).unwrap(),
        parse("0")
    );
    let field = spin.hamilton_equations(&h).unwrap();
    let names: Vec<&str> = field
        .iter()
        .map(|(v, _)| vars.variable(*v).name())
        .collect();
    assert_eq!(names, ["x", "p_x", "S1", "S2", "S3"]);
    for (v, rate) in &field {
        let z = Expr::var(&vars, *v);
        assert_eq!(*rate, spin.bracket(&z, &h).unwrap(), "ż = {{z, H}}");
    }
}

/// e(3)* with one wrong bracket: one identity cannot tell which bracket is wrong, so the
/// message names every declared bracket the failing triple's identity depends on, the wrong
/// one among them wherever it stands, and, where several identities fail, which of those they
/// all depend on, showing the violation at the last of these. A wrong sign in the first
/// bracket was shown at `{M3, g1}` or `{g3, M1}`, right ones, with no word of `{M1, M2}`, and
/// then at the last of the four the first identity depends on; the two that fail share
/// `{M1, M2}` alone. A wrong `{g1, M2}` = g1, one of the triple's pairs whose leaving out
/// changes nothing (`{M1, g1}` = 0), is named too.
#[test]
fn a_jacobi_violation_names_every_bracket_its_identity_depends_on() {
    let e3 = "name = \"top\"\nhamiltonian = \"M1^2 + M2^2 + M3^2\"\n[phase_space]\n\
              variables = [\"M1\", \"M2\", \"M3\", \"g1\", \"g2\", \"g3\"]\n[poisson]\n\
              \"{M1, M2}\" = \"M3\"\n\"{M2, M3}\" = \"M1\"\n\"{M3, M1}\" = \"M2\"\n\
              \"{M1, g2}\" = \"g3\"\n\"{M2, g3}\" = \"g1\"\n\"{M3, g1}\" = \"g2\"\n\
              \"{g1, M2}\" = \"g3\"\n\"{g2, M3}\" = \"g1\"\n\"{g3, M1}\" = \"g2\"\n";
    let right = crate::scratch_text("jacobi-place", "right.toml", e3);
    let o = superint(&["check", right.to_str().expect("a UTF-8 path")]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let identity = "the declared brackets break the Jacobi identity: {M1, {M2, g1}} + \
                    {M2, {g1, M1}} + {g1, {M1, M2}} = ";
    let cases = [
        // The sign of the last one turned.
        (
            "last.toml",
            ("\"{g3, M1}\" = \"g2\"", "\"{g3, M1}\" = \"-g2\""),
            "14:1",
            "−2 g2, not 0; it depends on the declared {M1, M2}, {M3, g1}, {g1, M2} and {g3, M1}, \
             and the 3 identities that fail all depend on {g3, M1}, on no other of these: if one \
             entry alone is wrong, it is that one\
             \n 14 | \"{g3, M1}\" = \"-g2\"",
        ),
        // The sign of the first one turned.
        (
            "first.toml",
            ("\"{M1, M2}\" = \"M3\"", "\"{M1, M2}\" = \"-M3\""),
            "6:1",
            "2 g2, not 0; it depends on the declared {M1, M2}, {M3, g1}, {g1, M2} and {g3, M1}, \
             and the 2 identities that fail all depend on {M1, M2}, on no other of these: if one \
             entry alone is wrong, it is that one\
             \n 6 | \"{M1, M2}\" = \"-M3\"",
        ),
        // A pair of the triple with another value, whose leaving out keeps the residual.
        (
            "pair.toml",
            ("\"{g1, M2}\" = \"g3\"", "\"{g1, M2}\" = \"g1\""),
            "12:1",
            "−g2, not 0; it depends on the declared {M1, M2}, {M3, g1} and {g1, M2}, and the 4 \
             identities that fail all depend on {g1, M2}, on no other of these: if one entry \
             alone is wrong, it is that one\
             \n 12 | \"{g1, M2}\" = \"g1\"",
        ),
    ];
    for (name, (from, to), at, said) in cases {
        let path = crate::scratch_text("jacobi-place", name, &e3.replace(from, to));
        let o = superint(&["check", path.to_str().expect("a UTF-8 path")]);
        assert_eq!(o.status.code(), Some(2), "{name}");
        let stderr = text(&o.stderr);
        assert!(
            stderr.contains(&format!("{name}:{at}: {identity}{said}")),
            "{name}: {stderr}"
        );
    }
}

/// Long declared brackets that break the Jacobi identity: the message names the triple and
/// the entry, and shows the residual in part with its size (in full it was 1.2 MB); the
/// violation keeps the whole residual. A long value that is not real is shown so too.
#[test]
fn a_long_jacobi_violation_is_said_in_part() {
    let file = "name = \"j\"\nhamiltonian = \"M1^2 + M2^2 + M3^2\"\n[phase_space]\n\
                variables = [\"M1\", \"M2\", \"M3\"]\n[poisson]\n\
                \"{M1, M2}\" = \"(M1 + 2*M2 + 3*M3 + 1)^25\"\n\
                \"{M2, M3}\" = \"(M1 - M2 + 5*M3 + 2)^25\"\n\"{M3, M1}\" = \"M2\"\n";
    let path = crate::scratch_text("long-jacobi", "j.toml", file);
    let o = superint(&["check", path.to_str().expect("a UTF-8 path")]);
    assert_eq!(o.status.code(), Some(2));
    let stderr = text(&o.stderr);
    assert!(stderr.len() < 600, "{} bytes: {stderr}", stderr.len());
    let first = stderr.lines().next().unwrap_or_default();
    assert!(
        first.contains(
            "j.toml:8:1: the declared brackets break the Jacobi identity: {M1, {M2, M3}} + \
             {M2, {M3, M1}} + {M3, {M1, M2}} = −75 M1⁴⁹ "
        ) && first.ends_with(
            " + … (a polynomial of 22099 terms), not 0; it depends on the declared {M1, M2}, \
             {M2, M3} and {M3, M1}"
        ),
        "{stderr}"
    );
    // A long value that is not real, refused as the file is read.
    let unreal = file.replace("\"M2\"\n", "\"i*(M1 + M2 + M3 + 1)^25\"\n");
    let path = crate::scratch_text("long-jacobi", "u.toml", &unreal);
    let o = superint(&["check", path.to_str().expect("a UTF-8 path")]);
    assert_eq!(o.status.code(), Some(2));
    let stderr = text(&o.stderr);
    assert!(
        stderr.len() < 600
            && stderr.contains(
                "u.toml:8:15: {M3, M1} = i M1²⁵ + 25i M1²⁴ M2 + 25i M1²⁴ M3 + 25i M1²⁴ + 300i M1²³ \
                 M2² + 600i M1²³ M2 M3 + … (a polynomial of 3276 terms) is not real"
            ),
        "{stderr}"
    );
    // The library's violation: the whole residual, the message in part.
    let vars = Vars::builder()
        .poisson("M1")
        .poisson("M2")
        .poisson("M3")
        .build()
        .unwrap();
    let e = |s: &str| Expr::parse(&vars, s).unwrap();
    let brackets = [
        ("M1", "M2", e("(M1 + 2*M2 + 3*M3 + 1)^25")),
        ("M2", "M3", e("(M1 - M2 + 5*M3 + 2)^25")),
        ("M3", "M1", e("M2")),
    ];
    let space = PhaseSpace::new(&vars, &[]).unwrap();
    let Err(EngineError::Jacobi(violation)) = space.clone().with_brackets(&brackets) else {
        panic!("Jacobi is broken");
    };
    assert_eq!(violation.residual.len(), 22099);
    // The last bracket the identity depends on: each of the three does.
    assert_eq!(violation.bracket, 2);
    assert!(violation.message.len() < 400, "{}", violation.message);
    let unreal = [("M1", "M2", e("i*(M1 + M2 + M3 + 1)^25"))];
    let message = space.with_brackets(&unreal).unwrap_err().to_string();
    assert!(
        message.starts_with("{M1, M2} = ")
            && message.ends_with(
                " + … (a polynomial of 3276 terms) is not real: the bracket of two real \
                 variables is real"
            )
            && message.len() < 300,
        "{message}"
    );
}

#[test]
fn euler_top_hamilton_equations_and_plot() {
    let top = system_file("euler-top.toml");
    let sys = top.system();
    let field = sys.space().hamilton_equations(sys.hamiltonian()).unwrap();
    let expected = [
        "(1/I2 - 1/I3)*M2*M3",
        "(1/I3 - 1/I1)*M3*M1",
        "(1/I1 - 1/I2)*M1*M2",
    ];
    assert_eq!(field.len(), 3);
    for ((_, rate), want) in field.iter().zip(expected) {
        assert_eq!(*rate, sys.parse(want).unwrap());
    }
    // The picture: M turns about the axis it starts near, |M|² and H stay put.
    let svg = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("euler-top.svg");
    let o = superint(&[
        "plot",
        "systems/euler-top.toml",
        "M1",
        "M2",
        "C",
        "--at",
        "I1 = 1, I2 = 2, I3 = 3",
        "--from",
        "M1 = 1, M2 = 1/10, M3 = 1/2",
        "--time",
        "20",
        "--format",
        "json",
        "-o",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let doc: Value = serde_json::from_str(&text(&o.stdout)).expect("JSON");
    let change = |label: &str| {
        doc["functions"]
            .as_array()
            .unwrap()
            .iter()
            .find(|f| f["function"] == label)
            .unwrap_or_else(|| panic!("{label} is drawn"))["largest_change"]
            .as_f64()
            .unwrap()
    };
    assert!(change("C") < 1e-9, "the Casimir moved by {}", change("C"));
    assert!(change("H") < 1e-9, "H moved by {}", change("H"));
    assert!(change("M2") > 0.5, "M2 moved by {} only", change("M2"));
    let missing = superint(&[
        "plot",
        "systems/euler-top.toml",
        "M1",
        "--at",
        "I1 = 1, I2 = 2, I3 = 3",
        "--from",
        "M1 = 1, M2 = 1/10",
        "--time",
        "1",
        "-o",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(missing.status.code(), Some(2));
    assert!(
        text(&missing.stderr).contains("--from gives no value for M3"),
        "{}",
        text(&missing.stderr)
    );
}

#[test]
fn commands_take_a_declared_structure_or_refuse_it() {
    let out = superint(&["check", "--no-timings", "systems/kovalevskaya-top.toml"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    let out = text(&superint(&["rank", "systems/euler-top.toml", "H", "C"]).stdout);
    assert!(out.contains("rank ∂(H, C)/∂(M1, M2, M3) = 2"), "{out}");
    let out = text(&superint(&["expand", "systems/euler-top.toml", "{M1, M2*M3}"]).stdout);
    assert!(out.contains("{M1, M2 M3} = −M2² + M3²"), "{out}");
    // so(3) closes on its generators, with no relation of degree 2.
    let o = superint(&["closure", "systems/euler-top.toml", "M1", "M2", "M3"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    for b in ["{M1, M2} = M3", "{M1, M3} = −M2", "{M2, M3} = M1"] {
        assert!(out.contains(b), "{b} in\n{out}");
    }
    assert!(out.contains("The table closes"), "{out}");
    // The integrals of the Kovalevskaya top commute: their table is zero.
    let o = superint(&[
        "table",
        "systems/kovalevskaya-top.toml",
        "H",
        "K",
        "Gamma",
        "A",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    let rows: Vec<&str> = out.lines().filter(|l| l.contains('│')).skip(1).collect();
    assert_eq!(rows.len(), 4, "{out}");
    for row in rows {
        let entries = row.split('│').nth(1).expect("entries");
        assert!(entries.split_whitespace().all(|e| e == "0"), "{row}");
    }
    // The search solves over monomials in the Poisson variables: at I = (1, 2, 3), 1 and two
    // quadratic integrals (|M|² and H, combined), each proved.
    let o = superint(&[
        "search",
        "--no-timings",
        "systems/euler-top.toml",
        "--fix",
        "I1=1,I2=2,I3=3",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    let flat = crate::normalize(&out);
    for piece in [
        "The space: M1^a M2^b M3^c, with degree a + b + c ≤ 2 in the Poisson variables",
        "By degree in the Poisson variables: ≤ 0: 1, ≤ 1: 1, ≤ 2: 3.",
        "3 claims: 3 proved, 0 refuted",
    ] {
        assert!(flat.contains(piece), "{piece} in\n{out}");
    }
    // A space too small for H says so.
    let o = superint(&[
        "search",
        "systems/kovalevskaya-top.toml",
        "--poisson-degree",
        "1",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let flat = crate::normalize(&text(&o.stdout));
    assert!(
        flat.contains(
            "Note: H is not in this space (degree 2 in the Poisson variables, past the space's 1)"
        ),
        "{flat}"
    );
}

/// The dimension over Q of the span of `functions`: the rank of their coefficients on the
/// monomials they have.
fn span_dimension<'a>(functions: impl IntoIterator<Item = &'a Expr>) -> usize {
    let functions: Vec<&Expr> = functions.into_iter().collect();
    let mut columns: HashMap<Vec<i64>, usize> = HashMap::new();
    for f in &functions {
        for t in f.terms() {
            let next = columns.len();
            columns.entry(t.exponents()).or_insert(next);
        }
    }
    let mut m = Matrix::zeros(functions.len(), columns.len());
    for (row, f) in functions.iter().enumerate() {
        for t in f.terms() {
            m.set(row, columns[&t.exponents()], t.coeff());
        }
    }
    m.rank()
}

/// Every product of the `generators` (each with its degree) of total degree `≤ max`, the
/// empty product 1 among them.
fn products(generators: &[(Expr, u32)], max: u32) -> Vec<Expr> {
    let Some(((g, d), rest)) = generators.split_first() else {
        return Vec::new();
    };
    let one = Expr::one(g.vars());
    let mut out = Vec::new();
    let mut power = one.clone();
    let mut used = 0;
    while used <= max {
        if rest.is_empty() {
            out.push(power.clone());
        }
        for p in products(rest, max - used) {
            out.push(&power * &p);
        }
        if *d == 0 {
            break;
        }
        power = &power * g;
        used += d;
    }
    out
}

/// The search of `system` over polynomials of degree `≤ degree` in its Poisson variables,
/// with the parameters at `values` (the others 1), under `when`; every basis integral proved.
fn search_poisson(
    file: &LoadedSystem,
    degree: u32,
    values: &[(&str, i64, i64)],
    when: Option<&str>,
) -> SearchResult {
    let sys = file.system();
    let mut options = SearchOptions::new(SearchSpace::default().poisson_degree(degree));
    for &(name, num, den) in values {
        options = options.fix(sys.var(name), Rational::new(num, den));
    }
    if let Some(w) = when {
        options = options.when(file.condition(w).expect("the condition reads"));
    }
    let found = search(sys, &options).expect("the search runs");
    assert!(found.basis.iter().all(|f| f.proved_fixed));
    found
}

/// The named functions of `file`, at the parameters of `found` and under `when`, each with its
/// degree.
fn at_found_values(
    file: &LoadedSystem,
    found: &SearchResult,
    when: Option<&str>,
    names: &[&str],
) -> Vec<(Expr, u32)> {
    names
        .iter()
        .map(|&n| {
            let f = match n {
                "H" => file.system().hamiltonian(),
                _ => file.system().get(n).expect("a named function"),
            };
            let mut f = fix_parameters(f, &found.parameters).unwrap();
            if let Some(w) = when {
                f = file.condition(w).unwrap().apply(&f).unwrap();
            }
            let degree = f.total_degree(&[trigpoly::VarKind::Poisson]).unwrap();
            (f, degree as u32)
        })
        .collect()
}

/// The Euler top at generic moments: the integrals of degree `≤ 2` are 1, |M|² and H, and
/// those of degree `≤ 4` their products, no more (each found space is the span of those).
#[test]
fn euler_top_search_finds_the_casimir_and_the_energy() {
    let top = system_file("euler-top.toml");
    let moments = [("I1", 1, 1), ("I2", 2, 1), ("I3", 3, 1)];
    for degree in [2, 3, 4] {
        let found = search_poisson(&top, degree, &moments, None);
        let generated = products(&at_found_values(&top, &found, None, &["C", "H"]), degree);
        let dimension = span_dimension(&generated);
        assert_eq!(found.basis.len(), dimension, "degree {degree}");
        let fixed = found.basis.iter().map(|f| &f.fixed);
        assert_eq!(span_dimension(fixed.chain(&generated)), dimension);
    }
    assert_eq!(
        search_poisson(&top, 4, &moments, None).dimensions_by_poisson_degree(),
        [1, 1, 3, 3, 6]
    );
    // At I1 = I2 = I3 every function is conserved (H = |M|²/2, a Casimir): all 10 of degree
    // ≤ 2, M1, M2, M3 among them.
    let isotropic = search_poisson(&top, 2, &[], None);
    assert_eq!(isotropic.basis.len(), 10);
    // Kept symbolic, the moments give the integrals for every value: over the polynomials in
    // them, 1, |M|² and one combination with H generate every integral.
    let sys = top.system();
    let mut options = SearchOptions::new(
        SearchSpace::default()
            .poisson_degree(2)
            .parameters_degree(2),
    );
    for name in ["I1", "I2", "I3"] {
        options = options.symbolic(sys.var(name));
    }
    let found = search(sys, &options).unwrap();
    assert!(found.all_symbolic());
    let module = found.module.as_ref().unwrap();
    assert_eq!(module.generators.len(), 3);
    let casimir = sys.get("C").unwrap();
    assert!(module
        .generators
        .iter()
        .any(|&i| found.basis[i].expr() == casimir));
}

/// The Kovalevskaya top at degree `≤ 4`: the integrals are the products of 1, Γ, M·γ, H and K,
/// and K is none of the others' products: the search finds the quartic integral.
#[test]
fn kovalevskaya_search_finds_the_quartic_integral() {
    let top = system_file("kovalevskaya-top.toml");
    let found = search_poisson(&top, 4, &[], None);
    // Found at c = 1, lifted back to c by homogeneity and proved for every c.
    assert!(found.liftable && found.all_symbolic());
    let gens = at_found_values(&top, &found, None, &["Gamma", "A", "H"]);
    let casimirs_and_energy = products(&gens, 4);
    let lower = span_dimension(&casimirs_and_energy);
    let k = at_found_values(&top, &found, None, &["K"]).remove(0).0;
    let with_k: Vec<Expr> = casimirs_and_energy.iter().cloned().chain([k]).collect();
    let dimension = span_dimension(&with_k);
    assert_eq!(dimension, lower + 1);
    assert_eq!(found.basis.len(), dimension);
    let fixed = found.basis.iter().map(|f| &f.fixed);
    assert_eq!(span_dimension(fixed.chain(&with_k)), dimension);
    assert_eq!(found.dimensions_by_poisson_degree(), [1, 1, 4, 4, 11]);
    // The JSON report says the same, as data.
    let o = superint(&[
        "search",
        "systems/kovalevskaya-top.toml",
        "--poisson-degree",
        "4",
        "--format",
        "json",
        "--no-timings",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let v: Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let s = &v["searches"][0];
    assert_eq!(s["space"]["poisson_degree"], 4);
    assert_eq!(
        s["space"]["poisson_variables"],
        serde_json::json!(["M1", "M2", "M3", "gamma1", "gamma2", "gamma3"])
    );
    assert_eq!(s["space"]["momenta"], serde_json::json!([]));
    assert_eq!(s["dimension"], dimension);
    assert_eq!(s["by_poisson_degree"], serde_json::json!([1, 1, 4, 4, 11]));
    assert_eq!(
        s["poisson_counts"],
        serde_json::json!([[1, 0, 0], [0, 0, 0], [3, 0, 0], [0, 0, 0], [7, 0, 0]])
    );
    assert_eq!(v["summary"]["proved"], dimension);
}

/// The same family off the Kovalevskaya ratio (`I3 = 1/3` instead of 1/2): nothing quartic but
/// the products of the Casimirs and H; at 1/2 the search finds K again, with the third moment
/// set by the condition and `c` lifted back.
#[test]
fn off_the_kovalevskaya_ratio_the_search_finds_no_quartic_integral() {
    let top = system_file("heavy-top.toml");
    for (when, new) in [("I3 = 1/3", 0), ("I3 = 2/3", 0), ("I3 = 1/2", 1)] {
        let found = search_poisson(&top, 4, &[], Some(when));
        assert!(found.all_symbolic(), "{when}");
        let products = products(
            &at_found_values(&top, &found, Some(when), &["Gamma", "A", "H"]),
            4,
        );
        let generated = span_dimension(&products);
        assert_eq!(found.basis.len(), generated + new, "{when}");
        let fixed = found.basis.iter().map(|f| &f.fixed);
        assert_eq!(
            span_dimension(fixed.chain(&products)),
            generated + new,
            "{when}"
        );
    }
    // Through the binary, with --new-only and the file's Casimirs alone known (the file cut
    // before ξ and K): nothing is new at 1/3, and at 1/2 one quartic integral is.
    let whole = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("systems/heavy-top.toml"),
    )
    .unwrap();
    let casimirs_only = &whole[..whole.find("[[function]]\nname = \"xi\"").expect("ξ")];
    let file = crate::scratch_text("poisson-search", "casimirs.toml", casimirs_only);
    for (when, new) in [("I3 = 1/3", false), ("I3 = 1/2", true)] {
        let o = superint(&[
            "search",
            file.to_str().unwrap(),
            "--poisson-degree",
            "4",
            "--when",
            when,
            "--new-only",
            "--no-timings",
        ]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
        let out = text(&o.stdout);
        assert!(
            out.contains("Known integrals in the space: H, Γ, A."),
            "{out}"
        );
        if !new {
            assert!(
                out.contains("None: the known integrals generate every integral in the space."),
                "{out}"
            );
            continue;
        }
        let flat = crate::normalize(&out);
        assert!(
            flat.contains("the generated ones span 10 of the 11 dimensions"),
            "{out}"
        );
        // One new integral, proved (the rest in one line, `[basis proved]`).
        let proved = out.lines().filter(|l| l.ends_with(" proved]"));
        assert_eq!(proved.filter(|l| !l.contains("[basis")).count(), 1, "{out}");
    }
}

/// The symmetric Euler top, `I1 = I2 = A`: `ξ = M1 + iM2` turns at the rate `(1/A − 1/C) M3`,
/// and `M3` is conserved, so `K_{m,n} = ξ^m M3^n` is an eigenfunction of the flow, for all
/// `m, n` by the tower's proof.
#[test]
fn tower_of_the_symmetric_top() {
    let file = crate::scratch_text(
        "poisson-tower",
        "symmetric.toml",
        concat!(
            r#"name = "symmetric top"
hamiltonian = "(M1^2 + M2^2)/(2*A) + M3^2/(2*C)"

[phase_space]
variables = ["M1", "M2", "M3"]
parameters = ["A", "C"]

"#,
            so3_poisson!(),
            r#"
[[function]]
name = "xi"
value = "M1 + i*M2"

[[family]]
name = "K"
value = "xi^m*M3^n"
eigenvalue = "-i*m*(1/A - 1/C)*M3"
"#
        ),
    );
    let o = superint(&["tower", "--system", file.to_str().unwrap(), "--max", "3"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert!(
        out.contains("{K_{m,n}, H} = (−im)(1/A − 1/C) M3 K_{m,n} for all m, n ≥ 0"),
        "{out}"
    );
    // The rate itself, and its opposite sign refuted by twice the rate.
    let sys = load(&file, &LimitsOverride::default())
        .unwrap()
        .system()
        .clone();
    identity!(sys, "{xi, H} = -i*(1/A - 1/C)*M3*xi");
    identity!(
        sys,
        "{xi, H} = i*(1/A - 1/C)*M3*xi" => refuted "-2*i*(1/A - 1/C)*M3*xi"
    );
}

/// A condition that sets a Poisson variable to a function of the others, here the
/// Kovalevskaya top on the level set `M·γ = 0` of its area integral, leaves it out of the
/// search's space as the surface's graph, not as a constant: the report said "every function
/// of it is an integral", which `M3 = −(M1 γ1 + M2 γ2)/γ3` is not; JSON's space names it under
/// `left_out_as_functions` as well as `left_out`, where it named it as a constant's.
#[test]
fn a_poisson_variable_set_to_a_function_is_left_out_as_no_constant() {
    let out = superint(&[
        "search",
        "systems/kovalevskaya-top.toml",
        "--poisson-degree",
        "2",
        "--when",
        "M3 = -(M1*gamma1 + M2*gamma2)/gamma3",
        "--no-timings",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let flat = text(&out.stdout)
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    assert!(
        flat.contains(
            "M3 is left out: the condition sets it to a function of the other variables, and \
             the space's functions are functions of those, on the surface it describes."
        ) && !flat.contains("every function of it is an integral"),
        "{flat}"
    );
    // JSON tells it from a constant too.
    let json = superint(&[
        "search",
        "systems/kovalevskaya-top.toml",
        "--poisson-degree",
        "2",
        "--when",
        "M3 = -(M1*gamma1 + M2*gamma2)/gamma3",
        "--format",
        "json",
    ]);
    assert_eq!(json.status.code(), Some(0), "{}", text(&json.stderr));
    let v: Value = serde_json::from_slice(&json.stdout).expect("JSON");
    let space = &v["searches"][0]["space"];
    assert_eq!(space["left_out"], serde_json::json!(["M3"]));
    assert_eq!(space["left_out_as_functions"], serde_json::json!(["M3"]));
}

/// A condition's or a starting point's left side that names no variable lists the kinds it may
/// name, with the Poisson variables on a top, which has nothing else to set: it listed "a
/// coordinate, a momentum or a parameter" (for `--from`, "a coordinate, an angle or a
/// momentum"), none of which a top on e(3)* has but its parameter.
#[test]
fn a_left_side_that_names_no_variable_lists_the_poisson_variables_on_a_top() {
    let f = "systems/kovalevskaya-top.toml";
    for (args, message) in [
        (
            vec!["bracket", f, "M1", "H", "--when", "gama3 = 0"],
            "<command line>:1:1: the left side of a condition is one declared variable (a \
             coordinate, a momentum, a Poisson variable or a parameter), found 'gama3'; did \
             you mean 'gamma3'?",
        ),
        (
            vec![
                "plot",
                f,
                "M1",
                "--at",
                "c = 1",
                "--time",
                "1",
                "-o",
                "-",
                "--from",
                "M1 = 1, M2 = 0, M3 = 0, gamma1 = 0, gamma2 = 0, gama3 = 1",
            ],
            "<command line>:1:49: the left side of a value of --from is one declared variable \
             (a coordinate, an angle, a momentum or a Poisson variable), found 'gama3'; did you \
             mean 'gamma3'?",
        ),
    ] {
        let out = superint(&args);
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(message), "{args:?}: {stderr}");
    }
}

/// `search --on`: on the Goryachev–Chaplygin top's area level set `M·γ = 0` the cubic
/// integral `K` is found, lifted to `c`, with its proof `{K, H} = Q·P`, `Q = −c M2`, which
/// JSON writes as an identity to read back and checks here by `bracket`; the level set is in
/// JSON's search facts. Without `--on` no cubic integral is found.
#[test]
fn a_search_on_a_level_set_finds_the_goryachev_chaplygin_integral() {
    let f = "systems/goryachev-chaplygin-top.toml";
    let on = "M1*gamma1 + M2*gamma2 + M3*gamma3 = 0";
    let args = [
        "search",
        f,
        "--on",
        on,
        "--poisson-degree",
        "3",
        "--no-timings",
    ];
    let out = superint(&args);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    for line in [
        "Integrals of the Goryachev–Chaplygin top on the level set M1 γ1 + M2 γ2 + M3 γ3 = 0",
        "I4 = M1² M3 + c M1 γ3 + M2² M3",
        "= K",
        "Q4 = −c M2",
        "{I4, H} = Q4 (M1 γ1 + M2 γ2 + M3 γ3)",
        "4 claims: 4 proved, 0 refuted",
    ] {
        assert!(stdout.contains(line), "{line}: {stdout}");
    }
    let json = superint(&[&args[..], &["--format", "json"]].concat());
    assert_eq!(json.status.code(), Some(0), "{}", text(&json.stderr));
    let v: Value = serde_json::from_slice(&json.stdout).expect("JSON");
    let level = &v["searches"][0]["level_set"];
    assert_eq!(level["text"], on);
    assert_eq!(level["polynomial"], "M1*gamma1 + M2*gamma2 + M3*gamma3");
    assert_eq!(level["leading_monomial"], "M1*gamma1");
    assert_eq!(level["left_out"], 7);
    let claims = v["claims"].as_array().expect("claims");
    let written = claims
        .iter()
        .find_map(|c| c["ascii"].as_str().filter(|a| a.contains("-c*M2")))
        .expect("the proof of K");
    assert_eq!(
        written,
        "{M1^2*M3 + c*M1*gamma3 + M2^2*M3, H} = (-c*M2)*(M1*gamma1 + M2*gamma2 + M3*gamma3)"
    );
    // The identity, read back and proved for every c.
    let (lhs, rhs) = written.split_once(" = ").unwrap();
    let k = &lhs[1..lhs.len() - 4];
    let bracket = superint(&["bracket", f, k, "H"]);
    let shown = text(&bracket.stdout);
    assert!(
        shown.contains("= −c M2 (M1 γ1 + M2 γ2 + M3 γ3)"),
        "{shown} vs {rhs}"
    );
    // A search of the same space without the level set has no cubic integral.
    let everywhere = superint(&["search", f, "--poisson-degree", "3", "--no-timings"]);
    let everywhere = text(&everywhere.stdout);
    assert!(
        everywhere.contains("Dimension of the space of integrals: 4.")
            && !everywhere.contains("M1² M3"),
        "{everywhere}"
    );
}

/// `search --on` on canonical coordinates: the 1:2 oscillator on its energy level `H = 1`
/// finds again the real and imaginary parts of its cubic integral `a² b̄`, in normal form,
/// each with its quotient.
#[test]
fn a_search_on_an_energy_level_finds_the_cubic_integrals_of_the_oscillator() {
    let out = superint(&[
        "search",
        "systems/anisotropic-oscillator-1-2.toml",
        "--on",
        "H = 1",
        "--fix",
        "M=1,omega=1",
        "--momenta-degree",
        "3",
        "--positions-degree",
        "3",
        "--no-timings",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    for line in [
        "I3 = x p_x p_y − 2y p_x² − y p_y² − 4y³ + 2y",
        "I4 = 2 p_x² p_y + p_y³ + 4xy p_x + 4y² p_y − 2 p_y",
        "Q3 = −2 p_y",
        "Q4 = −8y",
        "4 claims: 4 proved, 0 refuted",
    ] {
        assert!(stdout.contains(line), "{line}: {stdout}");
    }
}

/// `search --on` refuses what it cannot take, each refusal placed in the `--on` text with a
/// caret (exit 2, no panic): an angle, a non-polynomial, a level set the flow leaves, a text
/// with no `=`, a value of phase space, a parameter in the leading coefficient; and the
/// options it does not take beside it (`--new-only` it takes).
#[test]
fn a_level_set_the_search_cannot_take_is_refused_in_place() {
    let rotor = "systems/harmonic-rotor.toml";
    let top = "systems/goryachev-chaplygin-top.toml";
    for (file, on, expected) in [
        (
            rotor,
            "cos(theta) + x = 0",
            "<command line>:1:1: --on: the level set's expression holds an angle, θ",
        ),
        (
            rotor,
            "x/y = 1",
            "<command line>:1:1: --on: the level set's expression has a negative power of y",
        ),
        (
            rotor,
            "x = 1",
            "<command line>:1:1: --on: the flow of H leaves the level set: {P, H} = p_x/M for P = x − 1",
        ),
        (rotor, "x^2 + y^2", "<command line>:1:1: --on: no '='"),
        (
            rotor,
            "x = y = 1",
            "<command line>:1:7: --on: a second '=': a level set is one equation",
        ),
        (
            top,
            "gamma1 = M1",
            "<command line>:1:10: --on: the level set's value holds M1: it must be a constant",
        ),
        (
            top,
            "c*A = 0",
            "<command line>:1:1: --on: the level set's polynomial P = c M1 γ1 + c M2 γ2 + c M3 γ3 has at its leading monomial M1 γ1 a coefficient that holds a parameter",
        ),
    ] {
        let out = superint(&["search", file, "--on", on]);
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{on}: {stderr}");
        assert!(stderr.contains(expected), "{on}: {stderr}");
        assert!(stderr.contains(&format!(" 1 | {on}")) && stderr.contains('^'), "{stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
    // Each in the engine's words, with the option named: a condition that fixes parameters
    // alone points to --fix, which fixes them for the search and lifts back.
    for (extra, says) in [
        (
            vec!["--when", "c = 2"],
            "--on does not take --when, a condition that fixes parameters: a search on a level \
             set fixes its parameters itself: give their values with --fix",
        ),
        (
            vec!["--when", "M3 = 1"],
            "--on does not take --when, a condition that sets a phase variable (M3, a Poisson \
             variable): its substitution does not commute with the bracket with H",
        ),
        (
            vec!["--symbolic", "c"],
            "--on does not take --symbolic, parameters kept symbolic: the parameters are fixed \
             (1 unless --fix gives other values)",
        ),
    ] {
        let args = [&["search", top, "--on", "A = 0"][..], &extra[..]].concat();
        let out = superint(&args);
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(stderr.contains(says), "{stderr}");
    }
    // A Laurent space is taken where the level set holds no coordinate: H holds x.
    let oscillator = "systems/anisotropic-oscillator-1-2.toml";
    let out = superint(&["search", oscillator, "--on", "H = 1", "--laurent"]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("--on:")
            && stderr.contains("shares x with the negative powers of x that a Laurent space"),
        "{stderr}"
    );
    let out = superint(&["search", top, "--on", "A = 0", "--new-only"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // On a system with radicals, the options beside the level set first, then the level
    // set's own refusals: r is a radical; x = 1 shares x with the radicand (before the flow,
    // which leaves it).
    let kepler = "systems/kepler-3d.toml";
    for (extra, says) in [
        (&["--on", "r = 1"][..], "holds a radical, r"),
        (
            &["--on", "x = 1"],
            "P = x − 1 shares x with the radicand x² + y² + z² of the radical r",
        ),
        (
            &["--on", "x = 1", "--when", "k = 2"],
            "--on does not take --when",
        ),
    ] {
        let args = [&["search", kepler, "--momenta-degree", "1"][..], extra].concat();
        let out = superint(&args);
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(stderr.contains(says), "{stderr}");
    }
}

/// `search --on --new-only` on the Goryachev–Chaplygin top at Poisson degree 6: with the
/// file's functions known (`H`, `Γ` and `K`, whose bracket is a multiple of `P`; `A` is 0
/// there) nothing is new; with the file cut before `K`, `K` alone is, and the 13 other
/// dimensions (`Γ²`, `Γ K`, `K²`, ... in normal form modulo `P`) are generated; JSON has both
/// the level set and the new integrals. A known integral that is none on the level set is
/// refused in place.
#[test]
fn new_integrals_on_a_level_set_are_told_modulo_its_polynomial() {
    let f = "systems/goryachev-chaplygin-top.toml";
    let on = ["--on", "M1*gamma1 + M2*gamma2 + M3*gamma3 = 0"];
    let rest = ["--poisson-degree", "6", "--new-only", "--no-timings"];
    let run = |file: &str, extra: &[&str]| {
        superint(&[&["search", file][..], &on[..], &rest[..], extra].concat())
    };
    let o = run(f, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = crate::normalize(&text(&o.stdout));
    for line in [
        "Known integrals in the space: H, Γ, K.",
        "every known integral and product taken in normal form modulo P and not counted where \
         that leaves the space",
        "None: the known integrals generate every integral in the space.",
    ] {
        assert!(out.contains(line), "{line}: {out}");
    }
    let whole =
        std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(f)).unwrap();
    let without_k = &whole[..whole.find("[[function]]\nname = \"K\"").expect("K")];
    let file = crate::scratch_text("level-set-new-only", "gc.toml", without_k);
    let file = file.to_str().unwrap();
    let o = run(file, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = crate::normalize(&text(&o.stdout));
    for line in [
        "Known integrals in the space: H, Γ.",
        "the generated ones span 13 of the 14 dimensions",
        "New integrals: I4 = M1² M3 + c M1 γ3 + M2² M3",
        "{I4, H} = Q4 (M1 γ1 + M2 γ2 + M3 γ3)",
    ] {
        assert!(out.contains(line), "{line}: {out}");
    }
    let json = run(file, &["--format", "json"]);
    assert_eq!(json.status.code(), Some(0), "{}", text(&json.stderr));
    let v: Value = serde_json::from_slice(&json.stdout).expect("JSON");
    let search = &v["searches"][0];
    assert_eq!(search["level_set"]["leading_monomial"], "M1*gamma1");
    assert_eq!(search["new_only"]["generated"], 13);
    assert_eq!(search["new_only"]["known"], serde_json::json!(["H", "Γ"]));
    let o = run(file, &["--known", "Gamma,M1"]);
    let stderr = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains(
            "<command line>:1:7: --known: M1 is not an integral on the level set \
             M1*gamma1 + M2*gamma2 + M3*gamma3 = 0"
        ) && stderr.contains("not a multiple of P = M1 γ1 + M2 γ2 + M3 γ3"),
        "{stderr}"
    );
}

/// Division by a level set's polynomial takes polynomials, so a search refuses what it would
/// have divided with a negative power, rather than say something false of it: `K + A/γ1`
/// given as known on the Goryachev–Chaplygin area level set (an integral there, whose bracket
/// is `A` times a Laurent polynomial) was refused as "not an integral", and with
/// `H = p_x²/2 + 1/x²` the level set of `P = 2x²(H − 1)`, which the flow keeps (`{P, H} =
/// (2p_x/x) P`), was refused as one the flow leaves. It is now refused before its flow, for
/// sharing `x` with `H`'s negative power: in the Laurent ring `P` and `H − 1` span the same
/// ideal, whose normal forms are not the remainders on division by `P`.
#[test]
fn a_search_on_a_level_set_refuses_negative_powers_rather_than_misjudge_them() {
    let o = superint(&[
        "search",
        "systems/goryachev-chaplygin-top.toml",
        "--on",
        "M1*gamma1 + M2*gamma2 + M3*gamma3 = 0",
        "--poisson-degree",
        "3",
        "--new-only",
        "--known",
        "K + A/gamma1",
    ]);
    let stderr = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("<command line>:1:1: --known: K + A/γ1 is not taken on the level set")
            && stderr.contains("negative power of γ1, a variable of the level set's polynomial P")
            && stderr.contains("leave it out of --known, or take a level set of variables")
            && !stderr.contains("is not an integral"),
        "{stderr}"
    );
    let inverse = crate::scratch_text(
        "level-set-laurent",
        "inverse.toml",
        "name = \"inverse square\"\nhamiltonian = \"p_x^2/2 + 1/x^2\"\n\n\
         [phase_space]\ncoordinates = [\"x\"]\n",
    );
    let o = superint(&[
        "search",
        inverse.to_str().unwrap(),
        "--on",
        "x^2*p_x^2 + 2 - 2*x^2 = 0",
        "--momenta-degree",
        "2",
        "--positions-degree",
        "2",
    ]);
    let stderr = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("P = x² p_x² − 2x² + 2 shares x with the negative power 1/x² of H")
            && !stderr.contains("leaves"),
        "{stderr}"
    );
}

/// `search --on --new-only` says, in its text and its JSON, when a product past the space's
/// degree might fall back into it modulo `P`: for the free particle on `p_x p_y = 1`, where
/// `p_x · p_y` is 1 there, an integral told new may be generated by such a product; on the
/// Goryachev–Chaplygin top's area level set nothing is said and JSON has `false`.
#[test]
fn a_level_set_whose_leading_form_factors_says_what_is_new_is_undecided() {
    let free = crate::scratch_text(
        "level-set-undecided",
        "free.toml",
        "name = \"free particle\"\nhamiltonian = \"(p_x^2 + p_y^2)/2\"\n\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\n",
    );
    let free = free.to_str().unwrap();
    let args = [
        "search",
        free,
        "--on",
        "p_x*p_y = 1",
        "--momenta-degree",
        "2",
        "--positions-degree",
        "1",
        "--new-only",
        "--no-timings",
    ];
    let o = superint(&args);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = crate::normalize(&text(&o.stdout));
    let said = "the part of top degree of P is not shown to share no factor with each \
                integral's, so a product past the space's degree (not formed) may fall back \
                into it modulo P, and an integral told new may be generated by one";
    assert!(out.contains(said), "{out}");
    let json = superint(&[&args[..], &["--format", "json"]].concat());
    let v: Value = serde_json::from_slice(&json.stdout).expect("JSON");
    assert_eq!(v["searches"][0]["new_only"]["past_degree_undecided"], true);

    let top = "systems/goryachev-chaplygin-top.toml";
    let on = "M1*gamma1 + M2*gamma2 + M3*gamma3 = 0";
    let rest = ["--poisson-degree", "4", "--new-only", "--no-timings"];
    let o = superint(&[&["search", top, "--on", on][..], &rest[..]].concat());
    assert!(!crate::normalize(&text(&o.stdout)).contains("not shown to share"));
    let json = superint(
        &[
            &["search", top, "--on", on][..],
            &rest[..],
            &["--format", "json"],
        ]
        .concat(),
    );
    let v: Value = serde_json::from_slice(&json.stdout).expect("JSON");
    assert_eq!(v["searches"][0]["new_only"]["past_degree_undecided"], false);
}

/// On a level set the products of `--new-only` are held to the space's largest total degree,
/// not to each of its bounds: a normal form modulo `P` has at most its product's total degree
/// but may move it between the momenta and the positions (`x² = 2 − p_x² − p_y² − y²` on the
/// 1:1 oscillator's `H = 1`). With momenta and positions of degree `≤ 2` each, the products of
/// total degree `≤ 4` are formed, 15 (1 where each bound held them), and `L` and
/// `x y + p_x p_y` stay new beside the known `H_x`.
#[test]
fn products_on_a_level_set_are_held_to_the_total_degree() {
    let oscillator = crate::scratch_text(
        "level-set-total-degree",
        "oscillator.toml",
        "name = \"1:1 oscillator\"\nhamiltonian = \"(p_x^2 + p_y^2 + x^2 + y^2)/2\"\n\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\n\n\
         [[function]]\nname = \"Hx\"\nvalue = \"(p_x^2 + x^2)/2\"\n",
    );
    let o = superint(&[
        "search",
        oscillator.to_str().unwrap(),
        "--on",
        "H = 1",
        "--momenta-degree",
        "2",
        "--positions-degree",
        "2",
        "--new-only",
        "--no-timings",
        "--format",
        "json",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let v: Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let search = &v["searches"][0];
    assert_eq!(search["new_only"]["products"], 15);
    assert_eq!(search["new_only"]["known"], serde_json::json!(["Hx"]));
    assert_eq!(search["shown"].as_array().map(Vec::len), Some(2));
}
