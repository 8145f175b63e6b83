//! The MICZ–Kepler problem, a charge about a magnetic monopole, stated two ways: in a gauge
//! (`systems/micz-kepler.toml`, canonical momenta and the vector potential
//! `A = s(−y, x, 0)/(r(r + z))`) and without one (`systems/micz-kepler-poisson.toml`, the kinetic
//! momenta `π` as Poisson variables whose declared brackets `{π_i, π_j} = ε_ijk s x_k/r³` hold a
//! radical). The expected brackets are worked out by hand (the files' comments): `J = x × π − s x/r`
//! and `A = π × J − k x/r` close into so(4) on `H`, with `J · A = ks` and
//! `A · A − 2H(J · J − s²) = k²`.

use brackets::{EngineError, PhaseSpace};
use superint::system_file::{load, LimitsOverride, LoadedSystem};
use trigpoly::{Expr, Vars, VarsBuilder};

use crate::{holds, superint_json, superint_refused};

const GAUGE: &str = "systems/micz-kepler.toml";
const GAUGE_FREE: &str = "systems/micz-kepler-poisson.toml";

/// The integrals both files name: the energy, the Poincaré vector and the Laplace–Runge–Lenz
/// vector.
const INTEGRALS: [&str; 7] = ["H", "Jx", "Jy", "Jz", "Ax", "Ay", "Az"];

fn system_file(path: &str) -> LoadedSystem {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(path);
    load(&path, &LimitsOverride::default()).expect("the file loads")
}

/// `{F, G}` for two of [`INTEGRALS`], as worked out by hand: so(3) of `J`, `A` a vector under
/// it, `{A_i, A_j} = −2H ε_ijk J_k`, and `H` commuting with all.
fn expected_bracket(f: &str, g: &str) -> String {
    let index = |n: &str| "xyz".find(&n[1..]).expect("an axis");
    let (kind_f, kind_g) = (&f[..1], &g[..1]);
    if kind_f == "H" || kind_g == "H" {
        return "0".into();
    }
    let (i, j) = (index(f), index(g));
    if i == j {
        return "0".into();
    }
    let k = 3 - i - j;
    // ε_ijk: +1 for a cyclic (i, j, k), −1 otherwise.
    let sign = if (j + 3 - i) % 3 == 1 { "" } else { "-" };
    let axis = &"xyz"[k..=k];
    match (kind_f, kind_g) {
        ("J", "J") => format!("{sign}J{axis}"),
        ("J", "A") | ("A", "J") => format!("{sign}A{axis}"),
        _ => format!("{sign}(-2*H*J{axis})"),
    }
}

/// Every claim of both files holds as the file expects: the gauge's brackets of `π`, the
/// Lorentz force, the conservation of `J` and `A`, so(4), the Casimirs and the rank, with the
/// deliberately false neighbours refuted.
#[test]
fn micz_kepler_files_prove_their_claims_both_ways() {
    // The claims checked, and the refuted ids among them (a summary counts claims by id).
    for (file, checks, refuted) in [(GAUGE, 31, 2), (GAUGE_FREE, 22, 3)] {
        let json = superint_json(&["check", file, "--no-timings"]);
        let summary = &json["summary"];
        assert_eq!(summary["checks"], checks, "{file}: {summary}");
        assert_eq!(summary["as_expected"], checks, "{file}: {summary}");
        assert_eq!(summary["refuted"], refuted, "{file}: {summary}");
        assert_eq!(summary["all_as_expected"], true, "{file}: {summary}");
    }
}

/// The table of `H, J, A` is the same computed both ways: each bracket formed in the gauge-free
/// file, through its declared brackets with `1/r³`, is read into the gauge's file, where `π_x`
/// names the function `p_x + sy/(r(r + z))`, and proved equal there to the bracket formed with
/// the canonical momenta; and each is the bracket worked out by hand, in both files.
#[test]
fn micz_kepler_bracket_tables_agree_in_the_gauge_and_without_it() {
    let (gauge, free) = (system_file(GAUGE), system_file(GAUGE_FREE));
    for (a, f) in INTEGRALS.iter().enumerate() {
        for g in &INTEGRALS[a + 1..] {
            let lhs = format!("{{{f}, {g}}}");
            let json = superint_json(&["bracket", GAUGE_FREE, f, g, "--no-timings"]);
            let line = &json["equations"][0]["lines"][0];
            let without_gauge = line["ascii"].as_str().expect("the bracket's text");
            assert!(
                holds(&gauge, &lhs, without_gauge),
                "{lhs} = {without_gauge} of the gauge-free file fails in the gauge"
            );
            let expected = expected_bracket(f, g);
            for (name, file) in [(GAUGE, &gauge), (GAUGE_FREE, &free)] {
                assert!(holds(file, &lhs, &expected), "{name}: {lhs} = {expected}");
            }
        }
    }
}

/// False claims are refuted with the residual worked out by hand: `J · A = −ks` by `2ks`, and
/// `{A_x, A_y} = 2H J_z` by `−4H J_z`; `J` with the sign of its monopole term turned is not
/// conserved, by `2s d(x/r)/dt = 2s(r²π_x − x(x · π))/r³`.
#[test]
fn micz_kepler_false_claims_are_refuted() {
    for file in [GAUGE, GAUGE_FREE] {
        let sys = system_file(file);
        let wrong_sign = "Jx*Ax + Jy*Ay + Jz*Az + k*s";
        assert!(!holds(&sys, wrong_sign, "0"), "{file}");
        assert!(holds(&sys, wrong_sign, "2*k*s"), "{file}");
        assert!(!holds(&sys, "{Ax, Ay}", "2*H*Jz"), "{file}");
        assert!(holds(&sys, "{Ax, Ay} - 2*H*Jz", "-4*H*Jz"), "{file}");
        let turned = "{y*pi_z - z*pi_y + s*x/r, H}";
        let rate = "2*s*((x^2 + y^2 + z^2)*pi_x - x*(x*pi_x + y*pi_y + z*pi_z))/r^3";
        assert!(!holds(&sys, turned, "0"), "{file}");
        assert!(holds(&sys, turned, rate), "{file}");
    }
}

/// The position `x, y, z` and the kinetic momenta `π` as six Poisson variables, and the
/// parameter `s`.
fn kinetic_variables() -> VarsBuilder {
    ["x", "y", "z", "pi_x", "pi_y", "pi_z"]
        .iter()
        .fold(Vars::builder(), |b, n| b.poisson(n))
        .parameter("s")
}

/// The kinetic momenta's brackets in the field `B` (its components as text):
/// `{x_i, π_j} = δ_ij` and `{π_i, π_j} = ε_ijk B_k`.
fn kinetic_space(vars: &Vars, field: [&str; 3]) -> Result<PhaseSpace, EngineError> {
    let e = |s: &str| Expr::parse(vars, s).unwrap();
    PhaseSpace::new(vars, &[])?.with_brackets(&[
        ("x", "pi_x", e("1")),
        ("y", "pi_y", e("1")),
        ("z", "pi_z", e("1")),
        ("pi_x", "pi_y", e(field[2])),
        ("pi_y", "pi_z", e(field[0])),
        ("pi_z", "pi_x", e(field[1])),
    ])
}

/// The monopole's brackets in code: six Poisson variables and the radical `r`, `{π_x, π_y} =
/// s z/r³` and cyclically, accepted (the Jacobi identity of `π_x, π_y, π_z` is `−div B`, zero
/// off the origin); the field `s x/r²`, whose divergence is `s/r²`, refused with the residual
/// `−s/r²`. And a declared denominator: the field of a line of monopoles, `s(x, y, 0)/(x² + y²)`,
/// divergence-free, accepted; with the power 2, divergence `−2s/(x² + y²)²`, refused.
#[test]
fn a_declared_bracket_with_a_radical_or_denominator_keeps_the_jacobi_identity() {
    let builder = kinetic_variables();
    let refused_by = |vars: &Vars, field: [&str; 3]| match kinetic_space(vars, field) {
        Err(EngineError::Jacobi(violation)) => violation.residual,
        other => panic!("{field:?} breaks the Jacobi identity: {other:?}"),
    };
    let vars = builder
        .clone()
        .radical("r", "x^2 + y^2 + z^2")
        .build()
        .unwrap();
    let e = |s: &str| Expr::parse(&vars, s).unwrap();
    let monopole = kinetic_space(&vars, ["s*x/r^3", "s*y/r^3", "s*z/r^3"]).expect("Jacobi holds");
    let bracket = monopole.bracket(&e("pi_x"), &e("pi_y")).unwrap();
    assert!((&bracket - &e("s*z/r^3")).vanishes().unwrap());
    // Its identity of π_x, π_y, π_z holds through r² = x² + y² + z² alone: its terms,
    // −3s/r³ + 3s(x² + y² + z²)/r⁵ as formed, cancel only by it.
    let [px, py, pz] = ["pi_x", "pi_y", "pi_z"].map(e);
    let nested = |a: &Expr, b: &Expr, c: &Expr| {
        let inner = monopole.bracket(b, c).unwrap();
        monopole.bracket(a, &inner).unwrap()
    };
    let jacobiator = &(&nested(&px, &py, &pz) + &nested(&py, &pz, &px)) + &nested(&pz, &px, &py);
    assert!(!jacobiator.is_zero(), "{jacobiator}");
    assert!(jacobiator.vanishes().unwrap(), "{jacobiator}");
    // {r, π_x} = x/r through the radical, for a Poisson variable as for a canonical one.
    let rate = monopole.bracket(&e("r"), &e("pi_x")).unwrap();
    assert!((&rate - &e("x/r")).vanishes().unwrap());
    let residual = refused_by(&vars, ["s*x/r^2", "s*y/r^2", "s*z/r^2"]);
    assert!((&residual + &e("s/r^2")).vanishes().unwrap(), "{residual}");

    let vars = builder.denominator("x^2 + y^2").unwrap().build().unwrap();
    let e = |s: &str| Expr::parse(&vars, s).unwrap();
    let line = ["s*x/(x^2 + y^2)", "s*y/(x^2 + y^2)", "0"];
    kinetic_space(&vars, line).expect("Jacobi holds");
    let residual = refused_by(&vars, ["s*x/(x^2 + y^2)^2", "s*y/(x^2 + y^2)^2", "0"]);
    assert!(
        (&residual - &e("2*s/(x^2 + y^2)^2")).vanishes().unwrap(),
        "{residual}"
    );
}

/// Brackets through the radical, a declared denominator and their powers, each worked out by
/// hand: with `{x_i, π_j} = δ_ij` and the positions commuting, `{f(x), π_j} = ∂f/∂x_j`, the
/// total derivative (`{1/r, π_x} = −x/r³`, `{x/(x² + y²), π_y} = −2xy/(x² + y²)²`,
/// `{1/(x² + y²)², π_x} = −4x/(x² + y²)³`), and a momentum in `f` brings the declared value
/// in: `{π_x/r, π_y} = π_x ∂(1/r)/∂y + {π_x, π_y}/r = −yπ_x/r³ + sz/r⁴`, and for the line of
/// monopoles `{π_x/(x² + y²), π_z} = −{π_z, π_x}/(x² + y²) = −sy/(x² + y²)²`.
#[test]
fn brackets_through_a_radical_and_a_declared_denominator_are_the_hand_ones() {
    let builder = kinetic_variables();
    let space = |vars: &Vars, field: [&str; 3]| {
        kinetic_space(vars, field).expect("the Jacobi identity holds")
    };
    let agrees = |space: &PhaseSpace, f: &str, g: &str, by_hand: &str| {
        let e = |s: &str| Expr::parse(space.vars(), s).unwrap();
        let bracket = space.bracket(&e(f), &e(g)).unwrap();
        let difference = &bracket - &e(by_hand);
        assert!(difference.vanishes().unwrap(), "{{{f}, {g}}} = {bracket}");
    };
    let vars = builder
        .clone()
        .radical("r", "x^2 + y^2 + z^2")
        .build()
        .unwrap();
    let monopole = space(&vars, ["s*x/r^3", "s*y/r^3", "s*z/r^3"]);
    agrees(&monopole, "1/r", "pi_x", "-x/r^3");
    agrees(&monopole, "pi_x/r", "pi_y", "-y*pi_x/r^3 + s*z/r^4");
    agrees(&monopole, "x", "pi_x/r", "1/r");
    let vars = builder.denominator("x^2 + y^2").unwrap().build().unwrap();
    let line = space(&vars, ["s*x/(x^2 + y^2)", "s*y/(x^2 + y^2)", "0"]);
    agrees(&line, "x/(x^2 + y^2)", "pi_y", "-2*x*y/(x^2 + y^2)^2");
    agrees(&line, "1/(x^2 + y^2)^2", "pi_x", "-4*x/(x^2 + y^2)^3");
    agrees(&line, "pi_x/(x^2 + y^2)", "pi_z", "-s*y/(x^2 + y^2)^2");
}

/// The file with the wrong power, `s x_k/r²`, is refused at load: exit 2, the identity of
/// `π_x, π_y, π_z` and its residual `−s/r²`, reduced by `r² = x² + y² + z²` as `expand` prints
/// it (it was printed `2sx²/r⁴ + 2sy²/r⁴ + 2sz²/r⁴ − 3s/r²`).
#[test]
fn a_monopole_table_with_the_wrong_power_is_refused() {
    let text =
        std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(GAUGE_FREE))
            .expect("the file");
    let wrong = text.replace("/r^3\"", "/r^2\"");
    assert_eq!(wrong.matches("/r^2\"").count(), 3);
    let file = crate::scratch_text("micz-kepler", "wrong-power.toml", &wrong);
    let message = superint_refused(&["check", file.to_str().expect("a path")]);
    assert!(
        message.contains(
            "the declared brackets break the Jacobi identity: {π_x, {π_y, π_z}} + \
             {π_y, {π_z, π_x}} + {π_z, {π_x, π_y}} = −s/r², not 0"
        ),
        "{message}"
    );
    assert!(!message.contains("panicked"), "{message}");
}

/// `check` heads the gauge's file with its `H` reduced as `expand` prints it: the term
/// `s²z²/(2r² (x² + y²))` of `|π|²/2`, by hand `(s y/(r(r + z)))²/2 + (s x/(r(r + z)))²/2 =
/// s²/(2r²) · (r − z)²/(x² + y²)`, whose `z²` part it is, not over `(x² + y²)²` with a factor
/// `x² + y²` above as it was printed.
#[test]
fn micz_kepler_check_prints_h_reduced() {
    let out = crate::superint_ok(&["check", GAUGE, "--no-timings"]);
    let header = out.split("with r = ").next().expect("the header");
    assert!(header.contains("s²z²/(2r² (x² + y²))"), "{header}");
    assert!(!header.contains("(x² + y²)²"), "{header}");
}

/// `tower` refuses the gauge-free system, as any with radicals (its evaluation takes `r²` and
/// `x² + y² + z²` for different functions), with exit 2 and no panic; the other commands take
/// it (`closure` and `search`: `tests/it/discovery.rs`).
#[test]
fn micz_kepler_gauge_free_tower_is_refused() {
    let refused = superint_refused(&["tower", "--system", GAUGE_FREE]);
    assert!(
        refused.contains("not supported on a system with radicals"),
        "{refused}"
    );
    assert!(!refused.contains("panicked"), "{refused}");
}

/// A plot of the gauge-free flow, whose Hamilton's equations go through the declared brackets
/// with `1/r³`: from `x = (1, 0, 0)`, `π = (0, 4/5, 0)` at `s = k = 1`, `J = (−1, 0, 4/5)`,
/// `A = π × J − x/r = (−9/25, 0, 4/5)` and `sA − kJ = (16/25, 0, 0)`, so by the file's claim
/// `plane` the orbit stays on `x = 1` (to the integrator's error), while `z` moves.
#[test]
fn micz_kepler_gauge_free_orbit_stays_in_its_plane() {
    let json = superint_json(&[
        "plot",
        GAUGE_FREE,
        "x",
        "z",
        "--against",
        "y",
        "--at",
        "s = 1, k = 1",
        "--from",
        "x = 1, y = 0, z = 0, pi_x = 0, pi_y = 4/5, pi_z = 0",
        "--time",
        "30",
        "-o",
        crate::scratch_text("micz-kepler", "orbit.svg", "")
            .to_str()
            .expect("a path"),
    ]);
    let row = |name: &str| {
        json["functions"]
            .as_array()
            .expect("functions")
            .iter()
            .find(|f| f["function"] == name)
            .unwrap_or_else(|| panic!("no {name} in {json}"))
            .clone()
    };
    let span = |name: &str| {
        let f = row(name);
        f["greatest"].as_f64().expect("a number") - f["least"].as_f64().expect("a number")
    };
    assert!(span("x") < 1e-9, "{}", row("x"));
    assert!(span("z") > 1.0, "{}", row("z"));
    assert!(span("H") < 1e-9, "{}", row("H"));
}
