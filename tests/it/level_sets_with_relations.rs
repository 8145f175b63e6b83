//! Level sets (`on` in a claim, `search --on`) on systems with relations: declared
//! denominators, radicals, negative powers of `H` and Laurent spaces. Taken where the level
//! set's polynomial `P` shares no variable with them (the ring is then `A ⊗ k[V(P)]`, and the
//! remainders on division by `P` are its normal forms), refused naming the variable shared
//! where it does.

use superint::prelude::*;

use crate::level_set_claims::claim_of;
use crate::{normalize, scratch_text, superint_json, superint_ok, superint_refused, DEGREE_ONE};

/// A rotor beside a Calogero pair in a harmonic trap, the denominator `x − y` declared:
/// with `u = x − y`, `q = p_x − p_y` (`{u, q} = 2`), `A = (q + 2iu)² + 4g/u²` has
/// `{A, H} = 4iA` (by hand: `{u, H} = q`, `{q, H} = 4g/u³ − 4u`), so `K = A e^{−iθ}` has
/// `{K, H} = −i(p_θ − 4)K`: conserved on `p_θ = 4` alone.
const CALOGERO_ROTOR: &str = r#"name = "Calogero pair rotor"
hamiltonian = "(p_x^2 + p_y^2)/2 + g/(x - y)^2 + (x - y)^2 + p_theta^2/2"

[phase_space]
coordinates = ["x", "y"]
angles = ["theta"]
parameters = ["g"]
denominators = ["x - y"]

[[function]]
name = "ReK"
value = "((p_x - p_y)^2 - 4*(x - y)^2 + 4*g/(x - y)^2)*cos(theta) + 4*(x - y)*(p_x - p_y)*sin(theta)"

[[function]]
name = "ImK"
value = "4*(x - y)*(p_x - p_y)*cos(theta) - ((p_x - p_y)^2 - 4*(x - y)^2 + 4*g/(x - y)^2)*sin(theta)"
"#;

/// A planar Kepler problem beside a free motion in `z`, the radical `r = √(x² + y²)`
/// declared: `p_z` is conserved and no relation holds it.
const KEPLER_AND_FREE_Z: &str = r#"name = "planar Kepler and a free z"
hamiltonian = "(p_x^2 + p_y^2 + p_z^2)/2 - k/r"

[phase_space]
coordinates = ["x", "y", "z"]
parameters = ["k", "c"]
radicals = { r = "x^2 + y^2" }
"#;

/// `H` with the negative power `b/x²`, whose flow keeps `x p_y = 0`: `{x p_y, H} = x p_y`.
const BARRIER: &str = r#"name = "barrier"
hamiltonian = "x*p_x + b/x^2 + p_y^2/2"

[phase_space]
coordinates = ["x", "y"]
parameters = ["b"]
"#;

fn load(name: &str, text: &str) -> Result<LoadedSystem, FileError> {
    load_system_text(name, text, &LimitsOverride::default())
}

/// `text`, whose last line is a claim's `on = "…"`, refused there (at its expression) with
/// `message`.
fn refused_at_the_on(name: &str, text: &str, message: &str) {
    let err = load(name, text).expect_err("refused");
    assert_eq!(err.line_col(), Some((text.lines().count(), 7)), "{err}");
    assert!(err.message.contains(message), "{err}");
}

/// `a − b` is zero as a function (modulo the relations of the radicals and denominators).
fn same(a: &trigpoly::Expr, b: &trigpoly::Expr) -> bool {
    a.checked_sub(b).unwrap().vanishes().unwrap()
}

/// Before, a claim on `x p_y = 0` of `H = x p_x + b/x² + p_y²/2` was divided by `x p_y` as a
/// polynomial, and the true `p_y = 0` (where `H` is defined, `x ≠ 0`, so `x p_y = 0` is
/// `p_y = 0`) was refuted with the remainder `p_y`: in the Laurent ring `x p_y` and `p_y` span
/// the same ideal. `P` shares `x` with the negative power of `H`: refused, in place.
#[test]
fn a_claim_on_a_level_set_sharing_a_variable_with_a_negative_power_is_refused() {
    let text =
        format!("{BARRIER}\n[[claim]]\nid = \"t\"\nclaim = \"p_y = 0\"\non = \"x*p_y = 0\"\n");
    refused_at_the_on(
        "barrier.toml",
        &text,
        "P = x p_y shares x with the negative power 1/x² of H",
    );
    // A level set of p_y alone, which no relation holds, is taken: p_y = 0 there, Q = 1.
    let text = format!("{BARRIER}\n[[claim]]\nid = \"t\"\nclaim = \"p_y = 0\"\non = \"p_y = 0\"\n");
    let file = load("barrier.toml", &text).expect("loads");
    let report = check_report([&file]).expect("checked");
    let t = claim_of(&report, "t");
    assert!(t.proved, "{t:?}");
    let quotient = t.on_level.as_ref().unwrap().quotient.clone();
    assert_eq!(quotient, Some(file.system().parse("1").unwrap()));
}

/// On the Smorodinsky–Winternitz I rotor (`β/x²`, `γ/y²` in `H`), its file's `P_{1,1} = Re K`
/// on `p_θ = 2Iω`: `{K, H} = i(2ω − p_θ/I)K` (the family's eigenvalue at `m = n = 1`), so
/// `{P_{1,1}, H} = (p_θ − 2Iω) Q_{1,1}/I`, proved with that quotient; on `p_θ = Iω` it is
/// refuted with the remainder `(Iω − 2Iω) Q_{1,1}/I = −ω Q_{1,1}`. Before, `lhs − rhs`, which
/// holds `1/x²`, was refused for its negative power, though `P` holds no `x`.
#[test]
fn claims_on_a_level_set_free_of_the_negative_powers_of_h_are_decided() {
    let rotor = std::fs::read_to_string("systems/smorodinsky-winternitz-i-rotor.toml").unwrap();
    let claims = "\n[[claim]]\nid = \"on\"\nclaim = \"{P_1_1, H} = 0\"\n\
                  on = \"p_theta = 2*I*omega\"\n\
                  \n[[claim]]\nid = \"other\"\nclaim = \"{P_1_1, H} = 0\"\n\
                  on = \"p_theta = I*omega\"\nexpect = \"refuted\"\n";
    let file = load("sw-rotor.toml", &format!("{rotor}{claims}")).expect("loads");
    let report = check_report([&file]).expect("checked");
    assert!(report.all_as_expected());
    let p = |s: &str| file.system().parse(s).expect("parses");
    // Q_{1,1} = Im(A e^{−iθ}) with A = (p_x + iMωx)² + 2Mβ/x².
    let q11 = "(2*M*omega*x*p_x*cos(theta) - (p_x^2 - M^2*omega^2*x^2 + 2*M*beta/x^2)*sin(theta))";
    let on = claim_of(&report, "on");
    let q = on.on_level.as_ref().unwrap().quotient.as_ref().expect("Q");
    assert!(same(q, &p(&format!("{q11}/I"))), "{q}");
    let r = claim_of(&report, "other")
        .residual
        .clone()
        .expect("a remainder");
    assert!(same(&r, &p(&format!("-omega*{q11}"))), "{r}");
}

/// On the Calogero pair rotor (a declared denominator `x − y`): `{Re K, H} = 0` on
/// `p_θ = 4`, proved with the quotient `Im K` derived by hand (`{Re K, H} = (p_θ − 4) Im K`),
/// and refuted on `p_θ = 2` with the remainder `−2 Im K`, and off the level set.
#[test]
fn claims_on_a_level_set_beside_a_declared_denominator_are_proved_and_refuted() {
    let claims = "\n[[claim]]\nid = \"on\"\nclaim = \"{ReK, H} = 0\"\non = \"p_theta = 4\"\n\
                  \n[[claim]]\nid = \"other\"\nclaim = \"{ReK, H} = 0\"\non = \"p_theta = 2\"\n\
                  expect = \"refuted\"\n\
                  \n[[claim]]\nid = \"off\"\nclaim = \"{ReK, H} = 0\"\nexpect = \"refuted\"\n";
    let file = load("calogero-rotor.toml", &format!("{CALOGERO_ROTOR}{claims}")).expect("loads");
    let report = check_report([&file]).expect("checked");
    assert!(report.all_as_expected(), "{report:?}");
    let p = |s: &str| file.system().parse(s).expect("parses");
    let on = claim_of(&report, "on");
    let q = on.on_level.as_ref().unwrap().quotient.as_ref().expect("Q");
    assert!(same(q, &p("ImK")), "{q}");
    let other = claim_of(&report, "other");
    let r = other.residual.as_ref().expect("a remainder");
    assert!(same(r, &p("-2*ImK")), "{r}");
}

/// On a system with a radical, `r = √(x² + y²)`, and a free `z`: claims on `p_z = c`. One
/// holds by the relation `r² = x² + y²` alone (its remainder `c r² − c(x² + y²)` is zero as
/// a function), with `Q = r²`; `{z, H} k/r = k/r` is refuted with the remainder `(c − 1)k/r`.
#[test]
fn claims_on_a_level_set_beside_a_radical_are_proved_and_refuted() {
    let claims = "\n[[claim]]\nid = \"bracket\"\nclaim = \"{z, H}*k/r = c*k/r\"\n\
                  on = \"p_z = c\"\n\
                  \n[[claim]]\nid = \"relation\"\nclaim = \"p_z*r^2 = c*(x^2 + y^2)\"\n\
                  on = \"p_z = c\"\n\
                  \n[[claim]]\nid = \"false\"\nclaim = \"{z, H}*k/r = k/r\"\non = \"p_z = c\"\n\
                  expect = \"refuted\"\n";
    let file = load("kepler-z.toml", &format!("{KEPLER_AND_FREE_Z}{claims}")).expect("loads");
    let report = check_report([&file]).expect("checked");
    assert!(report.all_as_expected(), "{report:?}");
    let p = |s: &str| file.system().parse(s).expect("parses");
    let quotient = |id: &str| {
        let c = claim_of(&report, id);
        c.on_level.as_ref().unwrap().quotient.clone().expect("Q")
    };
    assert!(same(&quotient("bracket"), &p("k/r")));
    assert!(same(&quotient("relation"), &p("x^2 + y^2")));
    let r = claim_of(&report, "false")
        .residual
        .clone()
        .expect("a remainder");
    assert!(same(&r, &p("(c - 1)*k/r")), "{r}");
    // The level x = 1 shares x with the radicand: refused where it is written.
    let text =
        format!("{KEPLER_AND_FREE_Z}\n[[claim]]\nclaim = \"{{z, H}} = 0\"\non = \"x = 1\"\n");
    refused_at_the_on(
        "kepler-z.toml",
        &text,
        "P = x − 1 shares x with the radicand x² + y² of the radical r",
    );
}

/// The arguments of a search of the Calogero pair rotor at momenta and positions degree 2,
/// denominators degree 2, order 1, with `extra`.
fn calogero_rotor_search(extra: &[&str]) -> Vec<String> {
    let path = scratch_text(
        "level-sets-relations",
        "calogero-rotor.toml",
        CALOGERO_ROTOR,
    );
    let mut args: Vec<String> = ["search", path.to_str().unwrap()]
        .into_iter()
        .chain(["--momenta-degree", "2", "--positions-degree", "2"])
        .chain(["--denominators-degree", "2", "--trig-degree", "1"])
        .map(String::from)
        .collect();
    args.extend(extra.iter().map(|s| s.to_string()));
    args
}

/// `search --on 'p_theta = 4'` on the Calogero pair rotor finds `Re K` and `Im K`, each proved
/// on the level set alone with the quotient derived by hand (`{Re K, H} = (p_θ − 4) Im K`,
/// `{Im K, H} = −(p_θ − 4) Re K`), among as many integrals as the search with
/// `--when 'p_theta = 4'` finds (an independent route: the condition substitutes `p_θ`).
#[test]
fn a_search_on_a_level_set_beside_a_declared_denominator_finds_its_resonant_integrals() {
    let run = |extra: &[&str]| {
        let args = calogero_rotor_search(extra);
        superint_json(&args.iter().map(String::as_str).collect::<Vec<_>>())
    };
    let on = run(&["--on", "p_theta = 4"]);
    let when = run(&["--when", "p_theta = 4"]);
    let dimension = |json: &serde_json::Value| json["searches"][0]["dimension"].clone();
    assert_eq!(dimension(&on), 6);
    assert_eq!(dimension(&on), dimension(&when));
    let file = load("calogero-rotor.toml", CALOGERO_ROTOR).expect("loads");
    let p = |s: &str| file.system().parse(s).expect("parses");
    // Each integral proved on the level set alone reads `{F, H} = (Q)*(p_theta - 4)`.
    let mut found = Vec::new();
    for claim in on["claims"].as_array().unwrap() {
        let ascii = claim["ascii"].as_str().unwrap();
        let Some(shown) = ascii.strip_suffix("*(p_theta - 4)") else {
            continue;
        };
        let (f, q) = shown.split_once(", H} = ").unwrap();
        found.push((p(&f[1..]), p(&q[1..q.len() - 1])));
    }
    assert_eq!(found.len(), 2, "{on}");
    let (re, im) = (p("ReK"), p("ImK"));
    let minus = |e: &trigpoly::Expr| e.checked_mul(&p("-1")).unwrap();
    for (f, q) in &found {
        let expected = match same(f, &re) {
            true => im.clone(),
            false if same(f, &minus(&im)) => re.clone(),
            false => panic!("{f} is neither Re K nor −Im K"),
        };
        assert!(same(q, &expected), "{f}: {q}");
    }
}

/// `--find-values` on a level set beside a declared denominator follows from the same
/// criterion: with the trap `w (x − y)²`, `A = (q + 2√w i u)² + 4g/u²` has `{A, H} = 4√w i A`
/// (the derivation of [`CALOGERO_ROTOR`] with `2w` for 2), so `A e^{−iθ}` is conserved on
/// `p_θ = 4` where `w = 1`, which the search for `w`'s exceptional values finds.
#[test]
fn the_values_of_a_parameter_with_more_integrals_on_a_level_set_beside_a_denominator() {
    let text = CALOGERO_ROTOR
        .replace("+ (x - y)^2 +", "+ w*(x - y)^2 +")
        .replace("parameters = [\"g\"]", "parameters = [\"g\", \"w\"]");
    let path = scratch_text("level-sets-relations", "calogero-rotor-w.toml", &text);
    let args = [
        &[
            "search",
            path.to_str().unwrap(),
            "--on",
            "p_theta = 4",
            "--find-values",
            "w",
        ][..],
        &["--momenta-degree", "2", "--positions-degree", "2"],
        &[
            "--denominators-degree",
            "2",
            "--trig-degree",
            "1",
            "--no-timings",
        ],
    ]
    .concat();
    let found = normalize(&superint_ok(&args));
    assert!(
        found.contains("For a generic w (searched at w = 7, no root): 4 integrals")
            && found.contains("at w = 1, 6 integrals"),
        "{found}"
    );
}

/// The Smorodinsky–Winternitz I rotor, a Laurent search (`β/x²`, `γ/y²`) on `p_θ = 2Iω`,
/// finds what the documented `--when 'p_theta = 2*I*omega'` search finds: 8 integrals, and
/// the same four new ones (`Re`, `Im` of `A e^{−iθ}` and `B e^{−iθ}`), those now proved on
/// the level set alone.
#[test]
fn a_laurent_search_on_a_level_set_finds_the_resonant_integrals_of_the_barrier_rotor() {
    let rotor = "systems/smorodinsky-winternitz-i-rotor.toml";
    let search = |level: &[&str]| {
        let args = [
            &["search", rotor][..],
            level,
            &[
                "--momenta-degree",
                "2",
                "--positions-degree",
                "4",
                "--trig-degree",
                "2",
            ],
            &["--laurent", "--new-only", "--no-timings"],
        ]
        .concat();
        normalize(&superint_ok(&args))
    };
    let on = search(&["--on", "p_theta = 2*I*omega"]);
    let when = search(&["--when", "p_theta = 2*I*omega"]);
    let new = |text: &str| -> Vec<String> {
        let from = text.find("New integrals: Φ").expect("new integrals");
        let to = text[from..].find("Those of").expect("amplitudes") + from;
        (text[from..to].split(" Φ").skip(1))
            .map(|s| {
                s.split(" = R_")
                    .next()
                    .unwrap()
                    .split(" = −S_")
                    .next()
                    .unwrap()
            })
            .map(|s| {
                s.split(" = P_")
                    .next()
                    .unwrap()
                    .split(" = −Q_")
                    .next()
                    .unwrap()
            })
            .map(|s| s.trim().to_string())
            .collect()
    };
    assert!(
        on.contains("Dimension of the space of integrals: 8."),
        "{on}"
    );
    assert!(
        when.contains("Dimension of the space of integrals: 8."),
        "{when}"
    );
    assert_eq!(new(&on), new(&when));
    assert_eq!(new(&on).len(), 4);
    assert!(new(&on).iter().all(|f| f.contains("cos θ")), "{on}");
    assert!(on.contains("{Φ7, H} = Π7 (p_θ − 2ωI)"), "{on}");
}

/// A level set that shares a variable with a relation is refused, naming the variable and
/// the relation, exit 2: a declared denominator, a radicand, the negative powers of a
/// Laurent space (with the two ways out: a level set of momenta, or no `--laurent`); and on
/// the command line at the level set's expression.
#[test]
fn a_search_on_a_level_set_sharing_a_variable_with_a_relation_is_refused() {
    let calogero = calogero_rotor_search(&["--on", "p_x + p_y + x = 0"]);
    let stderr = superint_refused(&calogero.iter().map(String::as_str).collect::<Vec<_>>());
    assert!(
        stderr.contains("P = p_x + p_y + x shares x with the denominator x − y"),
        "{stderr}"
    );
    let stderr = superint_refused(&[
        "search",
        "systems/kepler-3d.toml",
        "--momenta-degree",
        "1",
        "--on",
        "x = 1",
    ]);
    assert!(
        stderr.contains("--on:") && stderr.contains("P = x − 1 shares x with the radicand"),
        "{stderr}"
    );
    let stderr = superint_refused(&[
        "search",
        "systems/anisotropic-oscillator-1-2.toml",
        "--on",
        "H = 1",
        "--laurent",
    ]);
    assert!(
        stderr.contains("shares x with the negative powers of x that a Laurent space admits")
            && stderr.contains(
                "take a level set of variables that no negative power involves (a Laurent \
                 space admits them of every coordinate), or search without --laurent"
            ),
        "{stderr}"
    );
}

/// A claim whose side, or a function it names, divides by a variable of `P` is refused at
/// the claim, though `H` holds no negative power: `F = p_y + 1/x` has no value where `x = 0`,
/// so `F = 1/x` on `x p_y = 0` is a claim where `x ≠ 0`, that is on `p_y = 0`, where it holds
/// (`F − 1/x = p_y`); before, `lhs − rhs = p_y`, whose `1/x` cancelled, was divided by `x p_y`
/// and the true claim refuted with the remainder `p_y`. So for `{F, y} = 1 − p_y` (the
/// bracket, `−1`, has cancelled `1/x` too, and `F`, which it is computed from, divides by `x`).
#[test]
fn a_claim_dividing_by_a_variable_of_the_level_set_is_refused() {
    let system = "name = \"free\"\nhamiltonian = \"x*p_x + p_y^2/2\"\n\
                  [phase_space]\ncoordinates = [\"x\", \"y\"]\n\
                  [[function]]\nname = \"F\"\nvalue = \"p_y + 1/x\"\n";
    for (claim, what) in [
        ("F = 1/x", "the side p_y + 1/x has a negative power of x: a claim on a level set"),
        ("{F, y} = p_y - 1", "the function F has a negative power of x, a variable of the level set's polynomial P = x p_y"),
    ] {
        let text =
            format!("{system}[[claim]]\nid = \"t\"\nclaim = \"{claim}\"\non = \"x*p_y = 0\"\n");
        let file = scratch_text("dividing-claim", "free.toml", &text);
        let stderr = superint_refused(&["check", file.to_str().unwrap()]);
        assert!(stderr.contains(what), "{stderr}");
        // On p_y = 0, which the claim does not divide by, it is proved.
        let text = text.replace("x*p_y = 0", "p_y = 0");
        let file = scratch_text("dividing-claim", "free.toml", &text);
        let stdout = superint_ok(&["check", file.to_str().unwrap()]);
        assert!(stdout.contains("1 proved"), "{stdout}");
    }
}

/// A free pair with the denominator `x − a` declared and `H`'s `y x/(x − a) − a y/(x − a) − y`,
/// zero by the atom's relation.
const FREE_PAIR: &str = "name = \"free pair\"\n\
    hamiltonian = \"(p_x^2 + p_y^2)/2 + y*x/(x - a) - a*y/(x - a) - y\"\n\
    [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\"]\n\
    denominators = [\"x - a\"]\n";

/// `superint search` of [`FREE_PAIR`] (written in the scratch directory `dir`) with `options`,
/// at momenta and positions degree 1 and no denominator: its output, exit 0.
fn free_pair_search(dir: &str, options: &[&str]) -> String {
    let file = scratch_text(dir, "pair.toml", FREE_PAIR);
    let mut args = vec!["search", file.to_str().unwrap()];
    args.extend(options);
    args.extend([
        "--momenta-degree",
        "1",
        "--positions-degree",
        "1",
        "--denominators-degree",
        "0",
    ]);
    superint_ok(&args)
}

/// [`FREE_PAIR`], where `H`'s
/// `y x/(x − a) − a y/(x − a) − y` is zero and `p_x x/(x − a) − a p_x/(x − a)` is `p_x`: at
/// `a = 1` a remainder holding `1/(x − a)` is zero only with the atom's polynomial at that
/// value too. Before, the flow's `{p_y, H} = −(x − 1)/(x − a) + 1` (zero, by hand) refused
/// `p_y = 0` as left by the flow, and the known integral, whose bracket
/// `−p_x²(a − 1)/(x − a)²` is zero at `a = 1`, was refused as no integral on `p_y = 0`, and
/// the basis's `p_x` was refuted at `a = 1`.
#[test]
fn a_remainder_at_the_fixed_values_is_zero_with_the_atoms_at_them() {
    let stdout = free_pair_search("remainder-at-values", &["--on", "p_y = 0", "--fix", "a=1"]);
    assert!(stdout.contains("on the level set p_y = 0"), "{stdout}");
    // p_x among the basis, whose {p_x, H} = y/(x − a) − (x − a)y/(x − a)² is zero by hand.
    assert!(
        stdout.contains("I3 = p_x") && stdout.contains("4 claims: 4 proved"),
        "{stdout}"
    );
    let known = "p_x*x/(x - a) - a*p_x/(x - a)";
    let with_known = ["--on", "p_y = 0", "--new-only", "--known", known];
    let stdout = free_pair_search("remainder-at-values", &with_known);
    assert!(stdout.contains("0 refuted"), "{stdout}");
}

/// On [`FREE_PAIR`], `a p_y = 0` is kept by the flow for every value of `a`: `{a p_y, H}` is
/// `a(1 − (x − a)/(x − a))`, zero by the atom's relation though not as written. Before, the
/// search, which divides by `P` at the fixed values only where its leading coefficient `a` is
/// a parameter, said it kept at the fixed values alone.
#[test]
fn a_level_set_whose_flow_is_zero_by_the_relations_is_kept_for_every_value() {
    let on = ["--on", "a*p_y = 0", "--fix", "a=2"];
    let stdout = free_pair_search("kept-for-every-value", &on);
    assert!(
        normalize(&stdout).contains("which the flow of H keeps ({P, H} is a multiple of P)"),
        "{stdout}"
    );
}

/// An oscillator beside a rotor whose speed holds the parameter `κ`, the denominator `κ + 1`
/// declared: with `K = (x + i p_x) e^{iθ}`, `R = Re K`, `C = Im K`, by hand
/// `{x + i p_x, H} = −i(x + i p_x)` and `{e^{iθ}, H} = i(κ + 1) p_θ e^{iθ}`, so
/// `{K, H} = iK((κ + 1) p_θ − 1)`, and `{C, H} = R((κ + 1) p_θ − 1)`: conserved on
/// `p_θ = 1/(κ + 1)`, where `{C, H} = (κ + 1) R (p_θ − 1/(κ + 1))`.
const KAPPA_ROTOR: &str = r#"name = "kappa rotor"
hamiltonian = "(p_x^2 + x^2)/2 + (kappa + 1)*p_theta^2/2"

[phase_space]
coordinates = ["x"]
angles = ["theta"]
parameters = ["kappa"]
denominators = ["kappa + 1"]

[[function]]
name = "R"
value = "x*cos(theta) - p_x*sin(theta)"

[[function]]
name = "C"
value = "x*sin(theta) + p_x*cos(theta)"
"#;

/// A level set's value may hold a declared denominator of parameters alone: `P = p_θ − D`,
/// `D = 1/(κ + 1)` one of its coefficients, `LM(P) = p_θ` with 1 for coefficient. Before, it
/// was refused as no constant. `{C, H} = 0` on `p_θ = 1/(κ + 1)` is proved for every `κ` with
/// the quotient `(κ + 1) R` derived by hand ([`KAPPA_ROTOR`]); as the claim on `p_θ = 1/2` at
/// `κ = 1`, with the quotient `2R`; and on `p_θ = 1/2` for every `κ` it is refuted with the
/// remainder `R((κ + 1)/2 − 1) = (κ − 1) R/2`.
#[test]
fn a_claim_on_a_level_set_whose_value_holds_a_denominator_of_parameters_is_decided() {
    let claims = "\n[[claim]]\nid = \"on\"\nclaim = \"{C, H} = 0\"\n\
                  on = \"p_theta = 1/(kappa + 1)\"\n\
                  \n[[claim]]\nid = \"at\"\nclaim = \"{C, H} = 0\"\nwhen = \"kappa = 1\"\n\
                  on = \"p_theta = 1/(kappa + 1)\"\n\
                  \n[[claim]]\nid = \"written\"\nclaim = \"{C, H} = 0\"\nwhen = \"kappa = 1\"\n\
                  on = \"p_theta = 1/2\"\n\
                  \n[[claim]]\nid = \"other\"\nclaim = \"{C, H} = 0\"\n\
                  on = \"p_theta = 1/2\"\nexpect = \"refuted\"\n";
    let file = load("kappa-rotor.toml", &format!("{KAPPA_ROTOR}{claims}")).expect("loads");
    let report = check_report([&file]).expect("checked");
    assert!(report.all_as_expected());
    let p = |s: &str| file.system().parse(s).expect("parses");
    let quotient = |id: &str| {
        let claim = claim_of(&report, id);
        assert!(claim.proved, "{claim:?}");
        claim
            .on_level
            .as_ref()
            .unwrap()
            .quotient
            .clone()
            .expect("Q")
    };
    assert!(same(&quotient("on"), &p("(kappa + 1)*R")));
    assert!(same(&quotient("at"), &p("2*R")));
    assert!(same(&quotient("written"), &p("2*R")));
    let r = claim_of(&report, "other")
        .residual
        .clone()
        .expect("a remainder");
    assert!(same(&r, &p("(kappa - 1)*R/2")), "{r}");
}

/// `search --on 'p_theta = 1/(kappa + 1)' --fix kappa=1` finds what `--on 'p_theta = 1/2'`
/// finds at `κ = 1`: `1`, `R` and `C` ([`KAPPA_ROTOR`]), each proved on the level set, with
/// no note that a normal form leaves the space.
#[test]
fn a_search_on_a_level_set_whose_value_holds_a_denominator_of_parameters() {
    let path = scratch_text("level-sets-relations", "kappa-rotor.toml", KAPPA_ROTOR);
    let run = |value: &str| {
        let on = format!("p_theta = {value}");
        let mut args = vec![
            "search",
            path.to_str().unwrap(),
            "--on",
            &on,
            "--fix",
            "kappa=1",
        ];
        args.extend(DEGREE_ONE);
        superint_json(&args)
    };
    let (symbolic, written) = (run("1/(kappa + 1)"), run("1/2"));
    let dimension = |json: &serde_json::Value| json["searches"][0]["dimension"].clone();
    assert_eq!(dimension(&symbolic), 3, "{symbolic}");
    assert_eq!(dimension(&symbolic), dimension(&written));
    let proved = |json: &serde_json::Value| {
        json["claims"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["outcome"] == "proved")
            .count()
    };
    assert_eq!(proved(&symbolic), 3, "{symbolic}");
    // `P` is divided at κ = 1 with the atom at its value, `p_θ − 1/2`: the normal form of
    // `p_θ` is `1/2`, a number of the space, where it was the atom `1/(κ + 1)`, said outside it.
    let level_set = |json: &serde_json::Value| json["searches"][0]["level_set"].clone();
    assert!(
        level_set(&symbolic)["normal_form_outside"].is_null(),
        "{}",
        level_set(&symbolic)
    );
    // The same integrals, term for term: `1`, `C` and `−R` (on `p_θ = 1/2` at `κ = 1`, θ turns
    // at `(κ + 1) p_θ = 1`, as `(x, p_x)` does under `H`).
    let basis = |json: &serde_json::Value| -> Vec<(String, String)> {
        let equations = json["equations"].as_array().unwrap();
        let lines = equations
            .iter()
            .find(|e| e["caption"] == "A basis of the integrals")
            .expect("a basis")["lines"]
            .as_array()
            .unwrap();
        let text = |v: &serde_json::Value| v.as_str().unwrap_or_default().to_string();
        (lines.iter())
            .map(|l| (text(&l["ascii"]), text(&l["in_functions"]["ascii"])))
            .collect()
    };
    assert_eq!(basis(&symbolic), basis(&written));
    let in_functions: Vec<String> = basis(&written).into_iter().map(|l| l.1).collect();
    assert_eq!(in_functions, ["", "C", "-R"], "{written}");
    // Its polynomial holds κ through the atom: the values of κ are not searched on it.
    let stderr = superint_refused(&[
        "search",
        path.to_str().unwrap(),
        "--on",
        "p_theta = 1/(kappa + 1)",
        "--find-values",
        "kappa",
    ]);
    assert!(
        stderr.contains("a level set whose polynomial holds kappa"),
        "{stderr}"
    );
}

/// A rotor whose radical `r = √(κ + 3)` holds a parameter alone: a number at fixed values.
const RADICAL_ROTOR: &str = r#"name = "rotor with a radical of parameters"
hamiltonian = "(p_x^2 + p_y^2)/2 + (x^2 + y^2)/2 + p_theta^2/2"
[phase_space]
coordinates = ["x", "y"]
angles = ["theta"]
parameters = ["kappa"]
radicals = { r = "kappa + 3" }
"#;

/// A normal form is in the space when each of its monomials is one of the space's, a radical
/// of parameters alone taken as a coefficient: on `p_θ = 1/r` at `κ = 1` the normal form of
/// `p_θ/r` is `1/r² = 1/(κ + 3) = 1/4` (by hand), the constant `1` of the space, and no note
/// says it leaves the space (it did). On `x² + y² + p_x² + p_y² = 1/r`, whose leading monomial
/// is `x²`, the normal form of `x²` is `1/r − y² − p_x² − p_y²` (by hand), of momenta degree 2
/// past the space's 1: that note stays. An odd power is the radical, not a number: on
/// `p_θ = r³` the normal form of `p_θ` is `r³ = (κ + 3) r` (by hand), in the space that holds
/// `r` and outside the one of `--radicals-degree 0`, which the note says.
#[test]
fn a_normal_form_with_a_radical_of_parameters_lies_in_the_space() {
    let path = scratch_text("level-sets-relations", "radical-rotor.toml", RADICAL_ROTOR);
    let run_with = |on: &str, positions: &str, extra: &[&str]| {
        let args = [
            "search",
            path.to_str().unwrap(),
            "--on",
            on,
            "--fix",
            "kappa=1",
            "--momenta-degree",
            "1",
            "--positions-degree",
            positions,
            "--trig-degree",
            "1",
        ];
        superint_json(&[&args[..], extra].concat())
    };
    let run = |on: &str, positions: &str| run_with(on, positions, &[]);
    let outside =
        |json: &serde_json::Value| json["searches"][0]["level_set"]["normal_form_outside"].clone();
    let inside = run("p_theta = 1/r", "1");
    assert!(outside(&inside).is_null(), "{}", outside(&inside));
    let energy = run("x^2 + y^2 + p_x^2 + p_y^2 = 1/r", "2");
    assert_eq!(
        outside(&energy),
        serde_json::json!({"function": "x^2", "normal_form": "-p_x^2 - p_y^2 - y^2 + 1/r"})
    );
    let cube = run("p_theta = r^3", "1");
    assert!(outside(&cube).is_null(), "{}", outside(&cube));
    let without_r = run_with("p_theta = r^3", "1", &["--radicals-degree", "0"]);
    assert_eq!(
        outside(&without_r),
        serde_json::json!({"function": "p_theta", "normal_form": "r^3"})
    );
}
