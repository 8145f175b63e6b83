//! Declared (Lie–Poisson) structures: the Euler top on so(3)* and the Kovalevskaya top on
//! e(3)*, proved and refuted through the library and the real binary; the bracket's laws
//! (Jacobi, Leibniz) on functions of Poisson variables; Hamilton's equations `ż = {z, H}` and
//! their picture; the commands that take such a structure, and the one that refuses it.

use std::process::{Command, Output};

use brackets::{EngineError, PhaseSpace, System};
use serde_json::Value;
use superint::system_file::{load, LimitsOverride, LoadedSystem};
use trigpoly::{Expr, VarSet};

/// A system file of `systems/`, loaded.
fn system_file(name: &str) -> LoadedSystem {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("systems")
        .join(name);
    load(&path, &LimitsOverride::default()).expect("the file loads")
}

/// The binary at the workspace root.
fn superint(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_superint"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the superint binary runs")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8(bytes.to_vec()).expect("UTF-8 output")
}

/// so(3)* with `{M1, M2} = M3` and cyclically, built in code.
fn so3() -> (trigpoly::Vars, PhaseSpace) {
    let vars = VarSet::builder()
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
    let vars = VarSet::builder()
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
    let system = System::new("spin", spin.clone(), h.clone());
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
    // The search solves over canonical monomials: refused, with why.
    let o = superint(&["search", "systems/euler-top.toml"]);
    assert_eq!(o.status.code(), Some(2));
    let err = text(&o.stderr);
    assert!(
        err.contains("M1 is a Poisson variable, whose brackets are declared")
            && !err.contains("panicked"),
        "{err}"
    );
}

/// The symmetric Euler top, `I1 = I2 = A`: `ξ = M1 + iM2` turns at the rate `(1/A − 1/C) M3`,
/// and `M3` is conserved, so `K_{m,n} = ξ^m M3^n` is an eigenfunction of the flow, for all
/// `m, n` by the tower's proof.
#[test]
fn tower_of_the_symmetric_top() {
    let file = crate::scratch_text(
        "poisson-tower",
        "symmetric.toml",
        r#"name = "symmetric top"
hamiltonian = "(M1^2 + M2^2)/(2*A) + M3^2/(2*C)"

[phase_space]
variables = ["M1", "M2", "M3"]
parameters = ["A", "C"]

[poisson]
"{M1, M2}" = "M3"
"{M2, M3}" = "M1"
"{M3, M1}" = "M2"

[[function]]
name = "xi"
value = "M1 + i*M2"

[[family]]
name = "K"
value = "xi^m*M3^n"
eigenvalue = "-i*m*(1/A - 1/C)*M3"
"#,
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
