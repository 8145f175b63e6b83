//! Denominator atoms: division by declared polynomials (`[phase_space] denominators`), the
//! chain rule of their brackets, the zero test by clearing denominators, the Calogero–Moser
//! claims (maximal superintegrability among them), the rank of a Jacobian through the
//! denominators, a picture of the flow, bad declarations, and the commands that refuse such
//! systems.

use superint::prelude::*;
use superint::system_file::{load_str, LimitsOverride, LoadedSystem};

use crate::{
    holds, scratch_text, superint, superint_in, superint_json, superint_ok, superint_refused,
};

const TWO_BODY: &str = "name = \"Calogero two-body\"\n\
                        hamiltonian = \"(p_x^2 + p_y^2)/2 + g/(x - y)^2\"\n\
                        [phase_space]\n\
                        coordinates = [\"x\", \"y\"]\n\
                        parameters = [\"g\"]\n\
                        denominators = [\"x - y\", \"x^2 + y^2\"]\n\
                        [[function]]\nname = \"P\"\nvalue = \"p_x + p_y\"\n";

fn two_body() -> LoadedSystem {
    load_str("two.toml", TWO_BODY, &LimitsOverride::default()).expect("the file loads")
}

#[test]
fn denominators_chain_rule_gives_the_brackets() {
    let file = two_body();
    assert!(holds(&file, "{1/(x - y), p_x}", "-1/(x - y)^2"));
    assert!(holds(&file, "{1/(x - y), p_y}", "1/(x - y)^2"));
    assert!(holds(&file, "{1/(x - y), x}", "0"));
    assert!(holds(&file, "{p_x, g/(x - y)^2}", "2*g/(x - y)^3"));
    assert!(holds(&file, "{p_x, 1/(x^2 + y^2)}", "2*x/(x^2 + y^2)^2"));
    assert!(!holds(&file, "{1/(x - y), p_x}", "1/(x - y)^2"));
    // Total momentum commutes with a function of x − y.
    assert!(holds(&file, "{p_x + p_y, H}", "0"));
    assert!(!holds(&file, "{p_x, H}", "0"));
}

#[test]
fn denominators_zero_is_decided_by_clearing() {
    let file = two_body();
    assert!(holds(&file, "(x - y)/(x - y) - 1", "0"));
    assert!(holds(&file, "(y - x)/(x - y)", "-1"));
    assert!(holds(&file, "x^2/(x^2 + y^2) + y^2/(x^2 + y^2)", "1"));
    let refuted = Claim::new(
        "t",
        "t",
        file.parse("x/(x - y) - 1").unwrap(),
        Expr::zero(file.system().vars()),
    )
    .check()
    .unwrap();
    let Outcome::Refuted { residual } = refuted.outcome else {
        panic!("x/(x − y) − 1 is not 0")
    };
    assert_eq!(residual.to_string(), "y/(x − y)");
}

#[test]
fn denominators_calogero_claims_are_proved_and_the_wrong_coefficient_refuted() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/systems/calogero.toml");
    let file = superint::system_file::load(std::path::Path::new(path), &LimitsOverride::default())
        .expect("the file loads");
    let report = superint::system_file::check_report([&file]).expect("checked");
    assert!(report.all_as_expected());
    assert_eq!(
        report.claim_ids(),
        [
            ("momentum".to_string(), true),
            ("cubic".to_string(), true),
            ("involution".to_string(), true),
            ("f1-moves".to_string(), true),
            ("f2-moves".to_string(), true),
            ("f3-moves".to_string(), true),
            ("K1".to_string(), true),
            ("K2".to_string(), true),
            ("superintegrable".to_string(), true),
            ("f3-without-interaction".to_string(), false),
            ("dependent".to_string(), false),
            ("force".to_string(), true),
            ("wrong-coefficient".to_string(), false),
        ]
    );
    // The cubic integral's coefficient 3g, checked on its own: 2g fails.
    assert!(holds(&file, "{I3, H}", "0"));
    assert!(!holds(
        &file,
        "{p_x^3 + p_y^3 + p_z^3 + 2*g*((p_x + p_y)/(x - y)^2 + (p_x + p_z)/(x - z)^2 + (p_y + p_z)/(y - z)^2), H}",
        "0"
    ));
}

#[test]
fn denominators_bad_declarations_are_refused_at_their_place() {
    let with = |list: &str| TWO_BODY.replace("[\"x - y\", \"x^2 + y^2\"]", list);
    let cases = [
        (
            "(p_x^2 + p_y^2)/2 + g/(x + y)^2",
            "[\"x - y\"]",
            "bad.toml:2:38: cannot divide by (x + y)²: only division by a nonzero constant, a \
             single term (monomial) or a product of powers of declared denominators is exact \
             here; declare its factor as a denominator: denominators = [\"x + y\"]",
        ),
        (
            "",
            "[\"x - x\"]",
            "bad.toml:6:17: a denominator cannot be 0",
        ),
        ("", "[\"x^2\"]", "bad.toml:6:17: x² is a single term"),
        ("", "[\"3\"]", "bad.toml:6:17: 3 is a single term"),
        (
            "",
            "[\"x - y\", \"(y - x)^2\"]",
            "bad.toml:6:26: x² − 2xy + y² is a product of the denominators declared before it",
        ),
        (
            "",
            "[\"x - y\", \"x + 1/(x - y)\"]",
            "bad.toml:6:26: the denominator x + 1/(x − y) divides by (x − y), declared before it",
        ),
        ("", "[\"x - q\"]", "bad.toml:6:22: unknown name 'q'"),
        (
            "",
            "[\"i*x + y\"]",
            "bad.toml:6:17: the denominator ix + y is not real",
        ),
        // A long one is shown by its first terms and its size.
        (
            "",
            "[\"i*(x + y + 1)^20\"]",
            "bad.toml:6:17: the denominator ix²⁰ + 20ix¹⁹y + 20ix¹⁹ + 190ix¹⁸y² + 380ix¹⁸y + \
             190ix¹⁸ + 1140ix¹⁷y³ + … (a polynomial of 231 terms) is not real\n",
        ),
    ];
    for (h, list, expected) in cases {
        let mut text = with(list);
        if !h.is_empty() {
            text = text.replace("(p_x^2 + p_y^2)/2 + g/(x - y)^2", h);
        }
        let f = scratch_text("denominators-bad", "bad.toml", &text);
        let dir = f.parent().unwrap();
        let o = superint_in(dir, &["check", "bad.toml"]);
        let err = String::from_utf8(o.stderr).unwrap();
        assert_eq!(o.status.code(), Some(2), "{list}: {err}");
        assert!(
            err.starts_with(&format!("superint: error: {expected}")),
            "{list}: expected {expected:?}, got {err}"
        );
    }
}

/// A divisor written as a power of a sum is refused with its factor as written to declare,
/// not the expanded square; declared as told, the file loads and the bracket is exact.
#[test]
fn denominators_undeclared_division_names_the_fix() {
    let text = TWO_BODY.replace("denominators = [\"x - y\", \"x^2 + y^2\"]\n", "");
    assert!(!text.contains("denominators"), "{text}");
    let err = load_str("two.toml", &text, &LimitsOverride::default())
        .expect_err("refused")
        .to_string();
    assert!(
        err.starts_with(
            "two.toml:2:38: cannot divide by (x − y)²: only division by a nonzero \
             constant, a single term (monomial) or a product of powers of declared denominators \
             is exact here; declare its factor as a denominator: denominators = [\"x - y\"] in \
             [phase_space]"
        ),
        "{err}"
    );
    let told = text.replace(
        "parameters = [\"g\"]\n",
        "parameters = [\"g\"]\ndenominators = [\"x - y\"]\n",
    );
    let file = load_str("two.toml", &told, &LimitsOverride::default()).expect("loads");
    assert!(holds(&file, "{x - y, H}", "p_x - p_y"));
}

/// A condition whose value a result takes to a negative power: refused with the declaration
/// that makes it invertible, which then works.
#[test]
fn denominators_a_condition_divides_by_its_value_once_declared() {
    let text = TWO_BODY.replace("[\"g\"]", "[\"g\", \"k\"]");
    let f = scratch_text("denominators-condition", "two.toml", &text);
    let f = f.to_str().unwrap();
    // A positive power takes any value.
    let out = superint_ok(&["bracket", f, "p_x", "H", "--when", "g = k + 1"]);
    assert!(out.contains("{p_x, H} = 2(k + 1)/(x − y)³"), "{out}");
    let err = superint_refused(&["expand", f, "x/g", "--when", "g = k + 1"]);
    assert!(
        err.contains(
            "cannot substitute k + 1 for g: it appears with exponent -1, and only single terms \
             (monomials) and products of powers of declared denominators are invertible; \
             declare it (or its factors) as a denominator: denominators = [\"k + 1\"] in \
             [phase_space]"
        ),
        "{err}"
    );
    let told = text.replace("\"x^2 + y^2\"]", "\"x^2 + y^2\", \"k + 1\"]");
    let f = scratch_text("denominators-condition", "told.toml", &told);
    let out = superint_ok(&["expand", f.to_str().unwrap(), "x/g", "--when", "g = k + 1"]);
    assert!(out.contains("x/g = x/(k + 1)"), "{out}");
}

#[test]
fn denominators_bracket_expand_and_rank_work_and_a_condition_on_a_denominator_is_refused() {
    let f = scratch_text("denominators-cli", "two.toml", TWO_BODY);
    let f = f.to_str().unwrap();
    let o = superint(&["bracket", f, "1/(x - y)", "p_x"]);
    assert_eq!(o.status.code(), Some(0));
    assert!(String::from_utf8(o.stdout)
        .unwrap()
        .contains("{1/(x − y), p_x} = −1/(x − y)²"));
    let o = superint(&["expand", f, "x/(x - y) - 1", "(x - y)/(x - y) - 1"]);
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.contains("x/(x − y) − 1       = y/(x − y)"), "{out}");
    assert!(out.contains("(x − y)/(x − y) − 1 = 0"), "{out}");
    let o = superint(&["rank", f, "H", "p_x + p_y"]);
    assert_eq!(o.status.code(), Some(0));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(
        out.contains("∂(H, p_x + p_y)/∂(x, y, p_x, p_y) = 2"),
        "{out}"
    );
    let refused: [(&[&str], &str); 1] = [(
        &["bracket", f, "p_x", "H", "--when", "x = 1"],
        // At the variable, not at its value.
        "<command line>:1:1: the condition sets x, which the denominator (x − y) involves",
    )];
    for (args, message) in refused {
        let o = superint(args);
        let err = String::from_utf8(o.stderr).unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(message), "{args:?}: {err}");
    }
}

/// The search with denominators: the monomials `x^a y^b p^c/((x − y)^e (x² + y²)^f)` are not
/// independent functions, and only those independent of the simpler ones are unknowns, so
/// that no combination equal to zero is reported as an integral; what is found is lifted to
/// every `g` and proved. The two-body problem's integrals of degree ≤ 2: 1, `P`, `p_x p_y −
/// g/(x − y)²`, `H`, and two with the positions (a Galilean one and `L² + 4gxy/(x − y)²`).
#[test]
fn denominators_search_finds_integrals_that_are_functions_apart() {
    let f = scratch_text("denominators-search", "two.toml", TWO_BODY);
    let f = f.to_str().unwrap();
    // The search of degree ≤ 2 in the momenta and in the positions.
    let degree_2 = [
        "search",
        f,
        "--momenta-degree",
        "2",
        "--positions-degree",
        "2",
    ];
    let search = |more: &[&str]| superint(&[&degree_2[..], more].concat());
    let found = |denominators: &str| {
        let v = superint_json(&[&degree_2[..], &["--denominators-degree", denominators]].concat());
        let search = v["searches"][0].clone();
        assert_eq!(search["for_every_value"], search["dimension"]);
        (
            search["dimension"].as_u64().unwrap(),
            search["unknowns"].as_u64().unwrap(),
        )
    };
    // Degree 0 in the denominators: only the polynomials 1, P and P².
    assert_eq!(found("0").0, 3);
    let (dimension, unknowns) = found("2");
    assert_eq!(dimension, 6);
    // 6 · 6 · 6 monomials, 72 of them dependent on simpler ones as functions.
    assert!(unknowns < 6 * 6 * 6, "{unknowns}");
    // Higher powers of the denominators add monomials but no integral of this degree.
    assert_eq!(found("4").0, 6);
    let o = search(&[]);
    // The text as one line, whatever its wrapping.
    let out = String::from_utf8(o.stdout).unwrap();
    let out = out.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(out.contains("p_x p_y − g/(x − y)²"), "{out}");
    assert!(
        out.contains("each one equal as a function to a sum of simpler ones is left out"),
        "{out}"
    );
    // Beside H and P (the file's), two integrals are new: a Galilean one and
    // L² + 4gxy/(x − y)², which the basis writes 4gy²/(x − y)² + 4gy/(x − y) and the report
    // over its common denominator, as a physicist writes it.
    let o = search(&["--new-only", "--format", "json"]);
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let new = &v["searches"][0]["new_only"];
    assert_eq!(new["known"], serde_json::json!(["H", "P"]), "{new}");
    assert_eq!(new["generated"], 4, "{new}");
    assert_eq!(v["searches"][0]["shown"].as_array().unwrap().len(), 2);
    let out = String::from_utf8(search(&["--new-only"]).stdout).unwrap();
    let out = out.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        out.contains("I6 = x² p_y² − 2xy p_x p_y + y² p_x² + 4gxy/(x − y)²"),
        "{out}"
    );
    assert!(
        out.contains("I5 = x p_x p_y − x p_y² − y p_x² + y p_x p_y − 2g(x + y)/(x − y)²"),
        "{out}"
    );
}

/// The rank of a Jacobian with denominators: its entries through the atoms by the chain rule
/// (`1/(x − y)` depends on `x`), its larger minors decided zero by clearing, and its sample
/// points off the denominators' zeros.
#[test]
fn denominators_rank_takes_the_chain_rule_and_the_zero_test() {
    let file = two_body();
    let rank_of = |fs: &[&str]| {
        let exprs: Vec<Expr> = fs.iter().map(|f| file.parse(f).unwrap()).collect();
        rank(file.system().space(), &exprs).unwrap()
    };
    // 1/(x − y) has no x in its terms but depends on x through its atom: with the partial
    // derivatives alone its row would vanish and the rank be 1.
    let cert = rank_of(&["1/(x - y)", "x + y"]);
    assert_eq!(cert.rank, 2);
    assert!(!cert.minor_value.is_zero());
    // x/(x − y) − y/(x − y) = 1: dependent, though the 2 × 2 minor's terms do not cancel
    // until the atom is cleared.
    let cert = rank_of(&["x/(x - y)", "y/(x - y)"]);
    assert_eq!(cert.rank, 1);
    assert!(matches!(
        cert.upper,
        UpperBound::VanishingMinors { count: 3 }
    ));
    // A function of x − y alone and of x² + y² alone are independent; of x − y twice, not.
    assert_eq!(rank_of(&["g/(x - y)^2", "1/(x^2 + y^2)"]).rank, 2);
    assert_eq!(rank_of(&["g/(x - y)^2", "(x - y)^3"]).rank, 1);
    // The rank of the Calogero–Moser integrals is claimed in its file; a sample point where a
    // denominator vanishes (x = 2 at the first one, for x − 2) is passed over.
    let shifted = load_str(
        "shifted.toml",
        &TWO_BODY.replace("\"x^2 + y^2\"", "\"x - 2\""),
        &LimitsOverride::default(),
    )
    .unwrap();
    let exprs = [
        shifted.parse("1/(x - 2)").unwrap(),
        shifted.parse("y").unwrap(),
    ];
    let cert = rank(shifted.system().space(), &exprs).unwrap();
    assert_eq!(cert.rank, 2);
    let x = shifted.system().vars().lookup("x").unwrap();
    let at_x = &cert.point.iter().find(|(v, _)| *v == x).unwrap().1;
    assert_ne!(at_x, &GaussianRational::from(Rational::from(2)));
}

/// A bracket table works with denominators: a bracket equal to zero only by `v·D = 1` is 0,
/// one that is a listed function written another way shows as that function, and one that is
/// a combination whose terms share no monomial with it (`(gx + x − gy)/(x − y)²` is
/// `g/(x − y) + x/(x − y)²`) is found by solving on the cleared forms.
#[test]
fn denominators_table_decides_its_entries_exactly() {
    let text = format!(
        "{TWO_BODY}[[function]]\nname = \"X\"\nvalue = \"x\"\n\
         [[function]]\nname = \"A\"\nvalue = \"p_x/(x - y)\"\n\
         [[function]]\nname = \"U\"\nvalue = \"x/(x - y)^2 - y/(x - y)^2\"\n\
         [[function]]\nname = \"B\"\nvalue = \"p_x*(g/(x - y) + x/(x - y)^2)\"\n\
         [[function]]\nname = \"F1\"\nvalue = \"1/(x - y)\"\n\
         [[function]]\nname = \"F2\"\nvalue = \"x/(x - y)^2\"\n"
    );
    let f = scratch_text("denominators-table", "table.toml", &text);
    let f = f.to_str().unwrap();
    let o = superint(&["table", f, "H", "P", "X", "A", "U"]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let out = String::from_utf8(o.stdout).unwrap();
    // Too wide for a table, it lists the brackets that are not zero: {X, A} = ∂A/∂p_x =
    // 1/(x − y) is U; {H, P} = 0 and {P, A} = 0 (A depends on x − y only) are not listed.
    let flat = out.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(flat.contains("{X, A} = U"), "{out}");
    assert!(flat.contains("{H, U} = (p_x − p_y)/(x − y)²"), "{out}");
    assert!(
        !flat.contains("{H, P}") && !flat.contains("{P, A}"),
        "{out}"
    );
    assert!(
        !out.contains("(x\n"),
        "a factor (x − y) does not break:\n{out}"
    );
    let o = superint(&["table", f, "X", "B", "F1", "F2"]);
    let out = String::from_utf8(o.stdout).unwrap();
    assert_eq!(o.status.code(), Some(0), "{out}");
    let flat = out.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(flat.contains("{X, B} = g F1 + F2"), "{out}");
    // No combination of the four: shown over common denominators, by parameter, reduced
    // (gx/(x − y)⁴ − gy/(x − y)⁴ is g/(x − y)³).
    assert!(flat.contains("{B, F1} = x/(x − y)⁴ + g/(x − y)³"), "{out}");
}

/// A picture of the Calogero–Moser flow: Hamilton's equations through the denominators, each
/// atom evaluated as its polynomial; the five integrals stay put to rounding while the
/// particles move, and a start where two particles meet (a denominator is 0) is refused.
#[test]
fn denominators_plot_keeps_the_calogero_integrals() {
    let calogero = concat!(env!("CARGO_MANIFEST_DIR"), "/systems/calogero.toml");
    let svg = std::env::temp_dir().join(format!("superint-calogero-{}.svg", std::process::id()));
    let plot = |from: &str| {
        superint(&[
            "plot",
            calogero,
            "x",
            "P",
            "I3",
            "K1",
            "K2",
            "--at",
            "g = 1",
            "--from",
            from,
            "--time",
            "5",
            "-o",
            svg.to_str().unwrap(),
            "--format",
            "json",
        ])
    };
    let o = plot("x = -1, y = 0, z = 2, p_x = 1, p_y = 0, p_z = -1/2");
    let out = String::from_utf8(o.stdout).unwrap();
    assert_eq!(o.status.code(), Some(0), "{out}");
    let doc: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let changes: Vec<(&str, f64)> = doc["functions"]
        .as_array()
        .expect("functions")
        .iter()
        .map(|f| {
            let label = f["function"].as_str().unwrap();
            (label, f["largest_change"].as_f64().unwrap())
        })
        .collect();
    let labels: Vec<&str> = changes.iter().map(|c| c.0).collect();
    assert_eq!(labels, ["H", "x", "P", "I_3", "K1", "K2"]);
    for (label, change) in changes {
        match label {
            "x" => assert!(change > 1.0, "x moved by {change}"),
            _ => assert!(change < 1e-9, "{label} changed by {change}"),
        }
    }
    let _ = std::fs::remove_file(&svg);
    let o = plot("x = 0, y = 0, z = 2, p_x = 1, p_y = 0, p_z = -1/2");
    let err = String::from_utf8(o.stderr).unwrap();
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains(
            "H is not defined at the starting point: it divides by (x − y), which is 0 there"
        ),
        "{err}"
    );
}

/// A start on a singular line of a denominator in an angle is refused, decided exactly where the
/// angle is 0 or a rational multiple of π (`e^{iφ}` a root of unity): the TTW system's
/// `sin 3φ` at `φ = 0` and `π/3`, `cos 3φ` at `π/6` and `7π/6` (these integrated into numbers
/// of 10³² before, with exit 0); a start at `φ = 1`, which has no exact value, is drawn (it was
/// refused: 1 stood for `e^{iφ}`, that is `φ = 0`). The denominators show as written.
#[test]
fn a_start_where_a_denominator_in_an_angle_is_zero_is_refused() {
    let f = scratch_text(
        "denominators-angle-start",
        "ttw.toml",
        "hamiltonian = \"p_r^2 + p_phi^2/r^2 + r^2 + 1/(r^2*cos(3*phi)^2) + 1/(r^2*sin(3*phi)^2)\"\n\
         [phase_space]\ncoordinates = [\"r\"]\nangles = [\"phi\"]\n\
         denominators = [\"cos(3*phi)\", \"sin(3*phi)\"]\n",
    );
    let svg = std::env::temp_dir().join(format!("superint-ttw-{}.svg", std::process::id()));
    let plot = |phi: &str| {
        superint(&[
            "plot",
            f.to_str().unwrap(),
            "H",
            "--from",
            &format!("r = 1, phi = {phi}, p_r = 0, p_phi = 1"),
            "--time",
            "1/10",
            "-o",
            svg.to_str().unwrap(),
        ])
    };
    // A harmonic denominator shows as written, not as its normal form `−3 cos φ + 4 cos³φ`.
    let o = superint(&["check", f.to_str().unwrap()]);
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(
        out.contains("H = p_r² + p_φ²/r² + r² + 1/(r² (cos(3φ))²) + 1/(r² (sin(3φ))²)"),
        "{out}"
    );
    let (sin, cos) = ("(sin(3φ))", "(cos(3φ))");
    for (phi, zero) in [("0", sin), ("pi/3", sin), ("pi/6", cos), ("7*pi/6", cos)] {
        let o = plot(phi);
        let err = String::from_utf8(o.stderr).unwrap();
        assert_eq!(o.status.code(), Some(2), "{phi}: {err}");
        let refusal = format!(
            "H is not defined at the starting point: it divides by {zero}, which is 0 there"
        );
        assert!(err.contains(&refusal), "{phi}: {err}");
    }
    for phi in ["1", "pi/4"] {
        let o = plot(phi);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{phi}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
    }
    let _ = std::fs::remove_file(&svg);
}

/// A denominator in the angles is refused by the search, which keeps its monomials apart from
/// `cos k·θ` and `sin k·θ`: exit 2, with the denominator named.
#[test]
fn denominators_in_the_angles_are_refused_by_the_search() {
    let f = scratch_text(
        "denominators-angles",
        "pendulum.toml",
        "name = \"pendulum\"\n\
         hamiltonian = \"p_theta^2/2 + 1/(2 + cos(theta))\"\n\
         [phase_space]\n\
         angles = [\"theta\"]\n\
         denominators = [\"2 + cos(theta)\"]\n",
    );
    let o = superint(&["search", f.to_str().unwrap()]);
    let err = String::from_utf8(o.stderr).unwrap();
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("the search takes denominators free of the angles, and (2 + cos θ) has one"),
        "{err}"
    );
}

/// With `g` kept symbolic the two-body search finds its integrals for every `g` and shows the
/// generators over the polynomials in `g`: the multiples `g` and `g P` of `1` and `P` are
/// not among them. A parameter that a denominator holds cannot be kept symbolic: refused.
#[test]
fn denominators_search_keeps_a_parameter_symbolic_in_and_out_of_a_denominator() {
    let f = scratch_text("denominators-symbolic", "two.toml", TWO_BODY);
    let f = f.to_str().unwrap();
    let o = superint(&[
        "search",
        f,
        "--momenta-degree",
        "2",
        "--positions-degree",
        "2",
        "--symbolic",
        "g",
        "--parameters-degree",
        "1",
        "--format",
        "json",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let search = &v["searches"][0];
    assert_eq!(search["dimension"], 9);
    assert_eq!(search["for_every_value"], 9);
    // Over the polynomials in g six generate the nine: 1, P, p_x p_y − g/(x − y)², 2H and two
    // more. The ninth, g·P², is g times 2H + 2(p_x p_y − g/(x − y)²), whose g-terms cancel,
    // though g times either is past degree 1 in g.
    assert_eq!(search["shown"].as_array().unwrap().len(), 6);
    let shifted = TWO_BODY.replace("parameters = [\"g\"]", "parameters = [\"g\", \"a\"]");
    let shifted = shifted.replace("\"x^2 + y^2\"", "\"x - a\"");
    assert!(shifted.contains("x - a"), "{shifted}");
    // A parameter that a denominator holds is kept symbolic too: no integral of degree ≤ 2
    // divides by `x − a`, which `H` does not hold, so the integrals are the six generators
    // times 1, a and a², each proved for every a.
    let f = scratch_text("denominators-symbolic", "shifted.toml", &shifted);
    let v = superint_json(&["search", f.to_str().unwrap(), "--symbolic", "a"]);
    let search = &v["searches"][0];
    assert_eq!(search["dimension"], 18, "{search}");
    assert_eq!(search["for_every_value"], 18, "{search}");
    assert_eq!(search["shown"].as_array().unwrap().len(), 6, "{search}");
}

/// A parameter inside a denominator, fixed for the linear algebra: each integral found is
/// proved at the fixed values with the denominator at them too (it was refuted, the zero test
/// taking `x − a` with `a` symbolic while the integral had `a = 1`), then lifted and proved for
/// every value.
#[test]
fn denominators_search_proves_at_the_fixed_value_of_a_parameter_inside_a_denominator() {
    let text = "name = \"shifted\"\n\
                hamiltonian = \"(p_x^2 + p_y^2)/2 + g/(x - a)^2\"\n\
                [phase_space]\n\
                coordinates = [\"x\", \"y\"]\n\
                parameters = [\"g\", \"a\"]\n\
                denominators = [\"x - a\"]\n";
    let f = scratch_text("denominators-parameter", "shifted.toml", text);
    let o = superint(&[
        "search",
        f.to_str().unwrap(),
        "--momenta-degree",
        "2",
        "--positions-degree",
        "1",
        "--format",
        "json",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["searches"][0]["dimension"], 5, "{v}");
    assert_eq!(v["summary"]["refuted"], 0, "{v}");
    assert_eq!(v["searches"][0]["for_every_value"], 5, "{v}");
    let text = String::from_utf8(
        superint(&["search", f.to_str().unwrap(), "--momenta-degree", "2"]).stdout,
    )
    .unwrap();
    assert!(
        crate::normalize(&text).contains("x p_x p_y − y p_x² − a p_x p_y − 2gy/(x − a)²"),
        "{text}"
    );
}

/// `search --new-only` on the Neumann system's `file` to degree 2, its `a_i` kept symbolic
/// (of degree ≤ 1), its output normalized.
fn new_only_with_a_symbolic(file: &str) -> String {
    crate::normalize(&superint_ok(&[
        "search",
        file,
        "--poisson-degree",
        "2",
        "--new-only",
        "--symbolic",
        "a1,a2,a3",
        "--parameters-degree",
        "1",
    ]))
}

/// With its parameters kept symbolic, a multiple of an integral by a declared denominator of
/// parameters alone is a parameter multiple of it: on the Neumann system `1/(a1 − a2)` is a
/// constant and `Q/(a1 − a2)` a multiple of the Casimir `Q`, so with Uhlenbeck's integrals
/// known nothing of degree ≤ 2 is new (the constants and multiples were reported new).
#[test]
fn a_search_counts_multiples_by_a_denominator_of_parameters_as_generated() {
    let search = new_only_with_a_symbolic;
    let out = search("systems/neumann.toml");
    assert!(
        out.contains("the generated ones span the whole space (107 dimensions)"),
        "{out}"
    );
    assert!(
        out.contains("None: the known integrals generate every integral in the space."),
        "{out}"
    );
    // From `H` alone (the file cut before its functions) the Casimirs and Uhlenbeck's
    // integrals are new, the constants not.
    let out = search(&neumann_from_h_alone("denominators-of-parameters"));
    assert!(out.contains("New integrals:"), "{out}");
    assert!(!out.contains("= 1/("), "{out}");
}

/// `systems/neumann.toml` cut before its functions, so that nothing but `H` is known, written
/// in the scratch directory `dir`.
fn neumann_from_h_alone(dir: &str) -> String {
    let file = std::fs::read_to_string("systems/neumann.toml").expect("the file reads");
    let bare = &file[..file.find("[[function]]").expect("functions")];
    let f = scratch_text(dir, "neumann-bare.toml", bare);
    f.to_str().expect("a UTF-8 path").to_string()
}

/// From `H` alone, the Neumann system's new integrals of degree 2 for every `a_i` are the
/// Casimirs `Q = |x|²`, `A = L·x` and one of Uhlenbeck's, `F1 − Q`, each once and shown with
/// the least denominator: a new integral joins what is generated, with its multiples and
/// quotients by the parameters and their declared denominators, before the next one of its
/// degree is judged (`Q/((a1 − a2)(a1 − a3))` was new beside `Q/(a1 − a2)²`, 14 in all, and
/// each over two denominators).
#[test]
fn neumann_casimirs_and_one_uhlenbeck_integral_are_new_from_h_alone() {
    let out = new_only_with_a_symbolic(&neumann_from_h_alone("neumann-from-h"));
    assert!(
        out.contains("the generated ones span 104 of the 107 dimensions"),
        "{out}"
    );
    // The list, up to its first claim `{I…, H} = 0`.
    let block = out
        .split("New integrals: ")
        .nth(1)
        .and_then(|rest| rest.split(" {").next())
        .expect("a list of new integrals");
    assert_eq!(block.matches(" = ").count(), 3, "{out}");
    for form in [
        "= x1² + x2² + x3² (",
        "= L2²/(a1 − a3) + L3²/(a1 − a2) − x2² − x3² (",
        "= L1 x1 + L2 x2 + L3 x3",
    ] {
        assert!(block.contains(form), "{form}: {out}");
    }
    // Each labelled by the denominators it is multiplied by, its basis integral proved.
    assert!(block.starts_with("(a1 − a2"), "{out}");
    assert!(!block.contains("(x1² + x2² + x3²)/"), "{out}");
    assert_eq!(out.matches(", H} = 0").count(), 4, "{out}");
}

/// The rule `--new-only` prints for parameters kept symbolic names the declared denominators
/// of them alone beside the monomials, since a multiple by one counts as a parameter multiple.
#[test]
fn a_search_names_the_denominators_of_parameters_it_divides_by() {
    let out = new_only_with_a_symbolic("systems/neumann.toml");
    assert!(
        out.contains(
            "an integral whose multiple by a monomial in a1, a2, a3 or by (a1 − a2), (a1 − a3) \
             or (a2 − a3) lies in the space and is generated"
        ),
        "{out}"
    );
    assert!(
        !out.contains("numbers at the parameters' fixed values"),
        "{out}"
    );
}

/// With the parameters of its denominators fixed, a search says that those denominators are
/// numbers, whose powers add no unknown: as many unknowns as with none of them.
#[test]
fn a_search_says_denominators_of_fixed_parameters_are_numbers() {
    let unknowns = |denominators: &str| {
        crate::normalize(&superint_ok(&[
            "search",
            "systems/neumann.toml",
            "--poisson-degree",
            "2",
            "--denominators-degree",
            denominators,
        ]))
    };
    let out = unknowns("2");
    assert!(
        out.contains(
            "degree g + h + j ≤ 2 in the denominators (numbers at the parameters' fixed values \
             below, so they add no unknown): 28 unknowns"
        ),
        "{out}"
    );
    let none = unknowns("0");
    assert!(
        none.contains(" ≤ 2 in the Poisson variables: 28 unknowns"),
        "{none}"
    );
}

/// A closure whose relation cannot be lifted but whose table can says that the table holds
/// for every value, and how to find the relation for every value.
#[test]
fn a_closure_with_its_table_lifted_says_it_holds_for_every_value() {
    let out = crate::normalize(&superint_ok(&[
        "closure",
        "systems/neumann.toml",
        "F1",
        "F2",
        "F3",
        "H",
        "--degree",
        "2",
    ]));
    assert!(
        out.contains(
            "1 of the 7 brackets and relations could not be lifted, and holds at a1 = 7, a2 = \
             11/2, a3 = 13/3 only (the table holds for every value; --symbolic a1,a2,a3 keeps \
             the parameters symbolic, for every value)"
        ),
        "{out}"
    );
    assert!(
        out.contains("{F, G} for the Neumann system (row F, column G)"),
        "{out}"
    );
}

/// At values where a declared denominator vanishes, a search takes what divides by nothing
/// there: the Neumann system at `a1 = a2` (Uhlenbeck's `F3` defined, `F1` and `F2` not) finds
/// `L3`, the rotation that equal `a1, a2` add. A Hamiltonian that divides by `a1 − a2` has no
/// value there and is refused, even where the term it divides leaves no bracket: `|x|²/(a1 −
/// a2)`, a Casimir's, and `1/(a − b)`, a constant's, whose brackets are zero, so that no image
/// of the linear algebra divides by the denominator (both were searched as if `H` had a
/// value), on the command line and in the library.
#[test]
fn denominators_search_at_values_where_one_vanishes_refuses_a_hamiltonian_that_divides_by_it() {
    let neumann = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("systems/neumann.toml");
    let neumann = neumann.to_str().unwrap();
    let equal = ["--fix", "a1=2,a2=2,a3=5", "--denominators-degree", "0"];
    let found = superint_ok(&[&["search", neumann, "--new-only"][..], &equal].concat());
    assert!(found.contains("I2 = L3"), "{found}");
    assert!(found.contains("2 claims: 2 proved, 0 refuted"), "{found}");
    // A known integral that divides by a1 − a2, a constant whose bracket is zero: refused too.
    let known = ["search", neumann, "--new-only", "--known", "1/(a1 - a2)"];
    let err = superint_refused(&[&known[..], &equal].concat());
    assert!(err.contains("the denominator (a1 − a2) is zero"), "{err}");
    let text = std::fs::read_to_string(neumann).unwrap();
    let h = "hamiltonian = \"(L1^2 + L2^2 + L3^2)/2 + (a1*x1^2 + a2*x2^2 + a3*x3^2)/2";
    let casimir = text.replacen(h, &format!("{h} + (x1^2 + x2^2 + x3^2)/(a1 - a2)"), 1);
    assert_ne!(casimir, text);
    let f = scratch_text("denominators-vanishing", "casimir.toml", &casimir);
    let err = superint_refused(&[&["search", f.to_str().unwrap()][..], &equal].concat());
    assert!(
        err.contains("the denominator (a1 − a2) is zero at a1 = 2, a2 = 2"),
        "{err}"
    );
    // Other values: searched.
    let other = ["--fix", "a1=2,a2=3,a3=5", "--denominators-degree", "0"];
    superint_ok(&[&["search", f.to_str().unwrap()][..], &other].concat());

    let text = "name = \"constant\"\n\
                hamiltonian = \"(p_x^2 + p_y^2)/2 + 1/(a - b)\"\n\
                [phase_space]\n\
                coordinates = [\"x\", \"y\"]\n\
                parameters = [\"a\", \"b\"]\n\
                denominators = [\"a - b\"]\n";
    let file = load_str("constant.toml", text, &LimitsOverride::default()).unwrap();
    let system = file.system();
    let space = SearchSpace::default().denominators_degree(0);
    let at = |a: i64, b: i64| {
        SearchOptions::new(space)
            .fix(system.var("a"), Rational::from(a))
            .fix(system.var("b"), Rational::from(b))
    };
    let err = search(system, &at(1, 1)).unwrap_err();
    assert!(
        err.to_string()
            .starts_with("the denominator (a − b) is zero at a = 1, b = 1"),
        "{err}"
    );
    assert!(search(system, &at(1, 2)).is_ok());
}

/// The gyroscopic rotor with `1 + κ` declared: the paper's resonance shifted for every `κ`,
/// `p_θ = κL + Iω/(1 + κ)`, is proved and the unshifted one refuted, and the claims that fix
/// `κ` take the denominator at its value (`κ = 1/2`: `3/2`) instead of being refused.
const GYROSCOPIC_WITH_ONE_PLUS_KAPPA: &str = "name = \"gyroscopic rotor\"\n\
    hamiltonian = \"(p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2 \
    + (p_theta - kappa*(x*p_y - y*p_x))^2/(2*I)\"\n\
    [phase_space]\n\
    coordinates = [\"x\", \"y\"]\n\
    angles = [\"theta\"]\n\
    parameters = [\"M\", \"omega\", \"I\", \"kappa\"]\n\
    denominators = [\"kappa + 1\"]\n\
    [[function]]\nname = \"Z\"\nvalue = \"p_x + i*p_y + i*M*omega*(x + i*y)\"\n\
    [[function]]\nname = \"Q\"\nvalue = \"(p_x + i*p_y)^2/M + M*omega^2*(x + i*y)^2\"\n\
    [[claim]]\nid = \"resonant\"\nclaim = \"{Z*exp(-i*theta), H} = 0\"\n\
    when = \"p_theta = kappa*(x*p_y - y*p_x) + I*omega/(1 + kappa)\"\n\
    [[claim]]\nid = \"false-unshifted\"\nclaim = \"{Z*exp(-i*theta), H} = 0\"\n\
    when = \"p_theta = kappa*(x*p_y - y*p_x) + I*omega\"\nexpect = \"refuted\"\n\
    [[claim]]\nid = \"exact-half\"\nclaim = \"{Q*exp(i*theta), H} = 0\"\n\
    when = \"kappa = 1/2\"\n\
    [[claim]]\nid = \"at-half\"\nclaim = \"(2 + kappa)/(1 + kappa) = 5/3\"\n\
    when = \"kappa = 1/2\"\n\
    [[claim]]\nid = \"false-at-half\"\nclaim = \"1/(1 + kappa) = 1/2\"\n\
    when = \"kappa = 1/2\"\nexpect = \"refuted\"\n";

#[test]
fn denominators_shifted_resonance_divides_by_one_plus_kappa_for_every_kappa() {
    let f = scratch_text(
        "denominators-gyroscopic",
        "gyroscopic.toml",
        GYROSCOPIC_WITH_ONE_PLUS_KAPPA,
    );
    check_says(
        &f,
        &[
            "{Z e^{−iθ}, H} = 0 at p_θ = κ(x p_y − y p_x) + Iω/(1 + κ)",
            "[resonant proved]",
            "[false-unshifted refuted, as expected]",
            "[exact-half proved]",
            "(2 + κ)/(1 + κ) = 5/3 at κ = 1/2",
            "[false-at-half refuted, as expected]",
            "5 claims in 1 file: 3 proved, 2 refuted; all as expected",
        ],
    );
}

/// A condition where a declared denominator in parameters alone is 0 is refused where a claim
/// divides by it (`(2 + κ)/(1 + κ)`, not the claims before, free of it), naming the denominator
/// and the condition.
#[test]
fn denominators_a_condition_where_one_plus_kappa_is_zero_is_refused() {
    let at_minus_one = GYROSCOPIC_WITH_ONE_PLUS_KAPPA.replace("kappa = 1/2", "kappa = -1");
    let f = scratch_text("denominators-gyroscopic", "pole.toml", &at_minus_one);
    let err = superint_refused(&["check", f.to_str().unwrap()]);
    assert!(
        err.contains(
            "pole.toml:29:9: at κ = −1 the denominator κ + 1 is 0, so what divides by it has \
             no value there: give κ a value where κ + 1 is not 0, or leave it free"
        ),
        "{err}"
    );
    let f = scratch_text(
        "denominators-gyroscopic",
        "gyroscopic.toml",
        GYROSCOPIC_WITH_ONE_PLUS_KAPPA,
    );
    let f = f.to_str().unwrap();
    let err = superint_refused(&["bracket", f, "Z/(1 + kappa)", "H", "--when", "kappa = -1"]);
    assert!(
        err.contains("at κ = −1 the denominator κ + 1 is 0"),
        "{err}"
    );
    let out = superint_ok(&["bracket", f, "1/(1 + kappa)", "H", "--when", "kappa = 1/2"]);
    assert!(out.contains("= 0"), "{out}");
}

/// A claim that does not divide by a declared denominator takes a condition where it is 0, as
/// a resonant integral beside one that divides by `ω² − Ω²` does: at `κ = −1` the Hamiltonian
/// `p_x²/2 + (κ + 1)x + p_t` is the free particle's, whose `x − p_x t` is an integral (by hand,
/// `d/dt (x − p_x t) = p_x − p_x − ṗ_x t = (κ + 1)t`), while a claim that divides by `κ + 1` is
/// still refused there, naming the denominator.
#[test]
fn denominators_a_condition_where_one_is_zero_is_refused_only_where_held() {
    let system = "name = \"t\"\nhamiltonian = \"p_x^2/2 + (kappa + 1)*x + p_t\"\n\
        [phase_space]\ncoordinates = [\"x\", \"t\"]\nparameters = [\"kappa\"]\n\
        denominators = [\"kappa + 1\"]\n\
        [[claim]]\nid = \"free\"\nclaim = \"{x - p_x*t, H} = 0\"\nwhen = \"kappa = -1\"\n\
        [[claim]]\nid = \"falling\"\nclaim = \"{x - p_x*t, H} = (kappa + 1)*t\"\n";
    let f = scratch_text("denominators-zero-unheld", "t.toml", system);
    check_says(
        &f,
        &[
            "[free proved]",
            "[falling proved]",
            "2 claims in 1 file: 2 proved, 0 refuted",
        ],
    );
    let held = format!(
        "{system}[[claim]]\nid = \"held\"\nclaim = \"x/(kappa + 1) = 0\"\n\
         when = \"kappa = -1\"\n"
    );
    let f = scratch_text("denominators-zero-unheld", "held.toml", &held);
    let err = superint_refused(&["check", f.to_str().unwrap()]);
    assert!(
        err.contains("at κ = −1 the denominator κ + 1 is 0, so what divides by it has no value"),
        "{err}"
    );
}

/// The oscillator `(p_x² + p_y²)/2 + x²/2 + 3y²/(κ + 1)` with the denominator `κ + 1`, and the
/// degrees of its searches (3 in the momenta and the positions): at `κ = 1/2` the frequencies
/// are 1 and 2, in resonance, which brings a cubic integral that `κ = 1` has not.
const RESONANT_AT_HALF: &str = "name = \"t\"\n\
    hamiltonian = \"(p_x^2 + p_y^2)/2 + x^2/2 + 3*y^2/(kappa + 1)\"\n[phase_space]\n\
    coordinates = [\"x\", \"y\"]\nparameters = [\"kappa\", \"m\"]\n\
    denominators = [\"kappa + 1\"]\n";
const DEGREES_THREE: [&str; 4] = ["--momenta-degree", "3", "--positions-degree", "3"];

/// What a search report says it found: the dimension and rank paragraph, the counts by degree
/// and the basis, without the condition it was searched at (in the title and the proofs) and
/// without what it says of fixed values and lifts.
fn found(report: &str) -> Vec<String> {
    let from = report
        .find("Dimension of the space")
        .expect("a dimension line");
    let to = report.find("2  Basis").expect("a basis section");
    let mut lines: Vec<String> = report[from..to]
        .lines()
        .filter(|l| !l.is_empty())
        .map(str::to_string)
        .collect();
    lines.extend(
        report[to..]
            .lines()
            .filter(|l| l.starts_with("    I") && l.contains(" = "))
            .map(str::to_string),
    );
    lines
}

/// What a search's space says of [`RESONANT_AT_HALF`]'s denominator `κ + 1`: at `--fix
/// kappa=1` it is the number 2, which only multiplies, so the note that with denominators the
/// monomials are not independent (`x/(x − y) − y/(x − y) = 1`) is not true there and is not
/// said (it was), the note that it is a number is; beside a denominator of coordinates,
/// `x − y`, the note is true and stays. Under `--when kappa=1/2` the condition gives it a
/// value, its powers are left out, and the JSON names it among `valued_denominators`.
#[test]
fn denominators_a_number_at_the_fixed_values_makes_no_monomials_dependent() {
    let dependent = "with denominators the monomials are not independent";
    let space = |text: &str, options: &[&str]| -> String {
        let f = scratch_text("denominators-numbers", "t.toml", text);
        let args = [
            &["search", f.to_str().unwrap()][..],
            options,
            &["--momenta-degree", "1", "--positions-degree", "1"],
        ]
        .concat();
        let report = crate::normalize(&superint_ok(&args));
        let from = report.find("The space:").expect("a space");
        let to = from + report[from..].find("blocks").expect("its blocks");
        report[from..to].to_string()
    };
    let number = space(RESONANT_AT_HALF, &["--fix", "kappa=1"]);
    assert!(!number.contains(dependent), "{number}");
    assert!(
        number.contains("(numbers at the parameters' fixed values below, so they add no unknown)"),
        "{number}"
    );
    let mixed = RESONANT_AT_HALF.replace("[\"kappa + 1\"]", "[\"kappa + 1\", \"x - y\"]");
    let both = space(&mixed, &["--fix", "kappa=1"]);
    assert!(both.contains(dependent), "{both}");
    assert!(
        both.contains("(κ + 1) a number at the parameters' fixed values"),
        "{both}"
    );
    let f = scratch_text("denominators-numbers", "t.toml", RESONANT_AT_HALF);
    let valued = |options: &[&str]| {
        let args = [&["search", f.to_str().unwrap()][..], options].concat();
        superint_json(
            &[
                &args[..],
                &["--momenta-degree", "1", "--positions-degree", "1"],
            ]
            .concat(),
        )["searches"][0]["space"]["valued_denominators"]
            .clone()
    };
    assert_eq!(
        valued(&["--when", "kappa = 1/2"]),
        serde_json::json!(["(kappa + 1)"])
    );
    assert_eq!(valued(&["--fix", "kappa=1"]), serde_json::json!([]));
}

/// A search under a condition on a declared denominator's parameter searches at its value:
/// `1/(κ + 1)` at `κ = 1/2` finds what the same system with `2/3` written in its place finds
/// (its cubic integral of the 1 : 2 resonance among them), the same space and the same
/// numbers, and what `--fix kappa=1/2` finds; `κ = m − 1` makes `1/(κ + 1)` the `1/m` of a
/// file written with it. At `κ = −1`, where `κ + 1` is 0, it is refused.
#[test]
fn denominators_a_search_under_a_condition_on_a_denominators_parameter_takes_its_value() {
    // The file `name`, the system with each `(from, to)` of `replacements` made.
    let file_with = |name: &str, replacements: &[(&str, &str)]| {
        let text = (replacements.iter()).fold(RESONANT_AT_HALF.to_string(), |t, (from, to)| {
            t.replace(from, to)
        });
        scratch_text("denominators-search-when", name, &text)
    };
    let f = file_with("t.toml", &[]);
    let declared = "parameters = [\"kappa\", \"m\"]\ndenominators = [\"kappa + 1\"]\n";
    let by_hand = file_with(
        "by-hand.toml",
        &[("3*y^2/(kappa + 1)", "2*y^2"), (declared, "")],
    );
    let search = |file: &std::path::Path, more: &[&str]| {
        superint_ok(
            &[
                &["search", file.to_str().unwrap()][..],
                more,
                &DEGREES_THREE,
            ]
            .concat(),
        )
    };
    let at_half = search(&f, &["--when", "kappa = 1/2"]);
    let written = search(&by_hand, &[]);
    // The whole report from the search to the proofs, which name the condition: the space
    // (without powers of the number 1/(κ + 1)), the dimensions, the rank and the basis.
    let body = |r: &str| r[r.find("1  Search").unwrap()..r.find("  {I1, H}").unwrap()].to_string();
    assert_eq!(body(&at_half), body(&written));
    assert!(
        at_half.contains("5 claims: 5 proved, 0 refuted"),
        "{at_half}"
    );
    assert!(
        written.contains("    I5 = p_x² p_y − x² p_y + 4xy p_x"),
        "{written}"
    );
    assert_eq!(found(&at_half), found(&search(&f, &["--fix", "kappa=1/2"])));
    assert_ne!(found(&at_half), found(&search(&f, &[])));
    // --find-values m under the condition finds the values of m (the frequency 2√m of y)
    // that the file with 2m/3 written for m/(κ + 1) finds, and the same integrals there.
    let values = |file: &std::path::Path, more: &[&str]| {
        let out = search(file, &[more, &["--find-values", "m"]].concat());
        let summary = out[..out.find("2  At m").expect("a section per value")].to_string();
        let basis = out
            .lines()
            .filter(|l| l.starts_with("    I"))
            .map(str::to_string);
        (summary.replace("the t", "t"), basis.collect::<Vec<_>>())
    };
    let with_m = |name: &str, by: &str| file_with(name, &[("3*y^2/(kappa + 1)", by)]);
    let at_half = values(
        &with_m("m-at-half.toml", "3*m*y^2/(kappa + 1)"),
        &["--when", "kappa = 1/2"],
    );
    let written = values(&with_m("m-by-hand.toml", "2*m*y^2"), &[]);
    assert_eq!(at_half, written);
    assert!(
        at_half.0.contains("at m = 1/4, 10 integrals"),
        "{}",
        at_half.0
    );
    // κ = m − 1: κ + 1 is m, and m is 1 where the search fixes it.
    let at_m = search(&f, &["--when", "kappa = m - 1"]);
    let over_m = file_with(
        "over-m.toml",
        &[
            ("3*y^2/(kappa + 1)", "3*y^2/m"),
            (declared, "parameters = [\"m\"]\n"),
        ],
    );
    let written = search(&over_m, &[]);
    assert_eq!(found(&at_m), found(&written));
    assert!(
        at_m.contains("The space: x^a y^b p_x^c p_y^d, with"),
        "{at_m}"
    );
    let err = superint_refused(
        &[
            &["search", f.to_str().unwrap(), "--when", "kappa = -1"][..],
            &DEGREES_THREE,
        ]
        .concat(),
    );
    assert!(
        err.contains(
            "at κ = −1 the denominator κ + 1 is 0, so what divides by it has no value there: \
             give κ a value where κ + 1 is not 0, or leave it free"
        ),
        "{err}"
    );
    assert!(!err.contains("panicked"), "{err}");
}

/// A condition's value that divides by a denominator the condition gives a value takes that
/// value too: at `k = 1/2, x = 1/(k + 1)/3`, `x` is `2/9` on both sides of a claim, and at
/// `m = 1, k = 1/(m + 1)`, `k` is `1/2`, not `1/(m + 1)` beside an `m` set to 1.
#[test]
fn denominators_a_value_dividing_by_a_denominator_the_condition_sets_takes_its_value() {
    let file = |claims: &str| {
        format!(
            "name = \"t\"\nhamiltonian = \"p_x^2/2 + x^2/(2*(k + 1))\"\n[phase_space]\n\
             coordinates = [\"x\"]\nparameters = [\"k\", \"m\"]\n\
             denominators = [\"k + 1\", \"m + 1\"]\n{claims}"
        )
    };
    let claims = "[[claim]]\nid = \"both-sides\"\nclaim = \"x = 1/(3*(k + 1))\"\n\
        when = \"k = 1/2, x = 1/(k + 1)/3\"\n\
        [[claim]]\nid = \"value\"\nclaim = \"x*(k + 1) = 1/3\"\n\
        when = \"x = 1/(k + 1)/3, k = 1/2\"\n\
        [[claim]]\nid = \"false-value\"\nclaim = \"x = 1/3\"\n\
        when = \"k = 1/2, x = 1/(k + 1)/3\"\nexpect = \"refuted\"\n";
    let f = scratch_text("denominators-set-values", "t.toml", &file(claims));
    check_says(
        &f,
        &[
            "[both-sides proved]",
            "[value proved]",
            "residual lhs − rhs = −1/9",
            "3 claims in 1 file: 2 proved, 1 refuted; all as expected",
        ],
    );
    let parameter = file(
        "[[claim]]\nid = \"parameter\"\nclaim = \"k = 1/2\"\n\
         when = \"m = 1, k = 1/(m + 1)\"\n",
    )
    .replace("\"k + 1\", ", "")
    .replace("(2*(k + 1))", "2");
    let f = scratch_text("denominators-set-values", "parameter.toml", &parameter);
    let out = superint_ok(&["check", f.to_str().unwrap()]);
    assert!(out.contains("[parameter proved]"), "{out}");
}

/// A rank claim under a condition on a denominator's parameter takes the atom at its value:
/// at `k = 1/2`, `x + p_x/(k + 1)` and `x + 2p_x/3` are one function (rank 1, not 2), and
/// `x + p_x/3` another (rank 2).
#[test]
fn denominators_a_rank_under_a_condition_on_a_denominators_parameter_takes_its_value() {
    let system = "name = \"t\"\nhamiltonian = \"p_x^2/2 + x^2/(2*(k + 1))\"\n[phase_space]\n\
        coordinates = [\"x\"]\nparameters = [\"k\"]\ndenominators = [\"k + 1\"]\n\
        [[claim]]\nid = \"same\"\nclaim = \"rank(x + p_x/(k + 1), x + 2*p_x/3) = 1\"\n\
        when = \"k = 1/2\"\n\
        [[claim]]\nid = \"false-two\"\nclaim = \"rank(x + p_x/(k + 1), x + 2*p_x/3) = 2\"\n\
        when = \"k = 1/2\"\nexpect = \"refuted\"\n\
        [[claim]]\nid = \"other\"\nclaim = \"rank(x + p_x/(k + 1), x + p_x/3) = 2\"\n\
        when = \"k = 1/2\"\n";
    let f = scratch_text("denominators-rank", "t.toml", system);
    let out = superint_ok(&["check", f.to_str().unwrap()]);
    assert!(
        out.contains("3 claims in 1 file: 2 proved, 1 refuted; all as expected"),
        "{out}"
    );
}

/// `superint check file`'s output, asserted to hold each of `lines`.
fn check_says(file: &std::path::Path, lines: &[&str]) {
    let out = superint_ok(&["check", file.to_str().unwrap()]);
    for line in lines {
        assert!(out.contains(line), "no {line:?} in:\n{out}");
    }
}

/// A condition whose value of a declared denominator the engine cannot take (`k + m` is
/// `m + 1/2` at `k = 1/2`, undeclared) is refused only where what it substitutes divides by
/// that denominator: a claim on `1/(k + 1)` alone is proved, one on `1/(k + m)` or with a
/// condition's value dividing by it is refused. A value that divides by another denominator
/// (`k + 1` at `k = 1/(m + 1)`) is said to be unsupported, not given a declaration to write.
#[test]
fn denominators_a_condition_is_refused_only_where_a_denominator_it_cannot_value_is_used() {
    let system = |denominators: &str, claims: &str| {
        format!(
            "name = \"t\"\nhamiltonian = \"p_x^2/2 + x^2/2\"\n[phase_space]\n\
             coordinates = [\"x\"]\nparameters = [\"k\", \"m\"]\n\
             denominators = [{denominators}]\n{claims}"
        )
    };
    let declared = "\"k + 1\", \"k + m\"";
    let unused = "[[claim]]\nid = \"unused\"\nclaim = \"1/(k + 1) = 2/3\"\nwhen = \"k = 1/2\"\n";
    let f = scratch_text(
        "denominators-unvalued",
        "unused.toml",
        &system(declared, unused),
    );
    check_says(&f, &["[unused proved]"]);
    let used = "[[claim]]\nid = \"used\"\nclaim = \"1/(k + m) = 2/3\"\nwhen = \"k = 1/2\"\n";
    let f = scratch_text(
        "denominators-unvalued",
        "used.toml",
        &system(declared, used),
    );
    let err = superint_refused(&["check", f.to_str().unwrap()]);
    assert!(
        err.contains("used.toml:9:9: at k = 1/2 the denominator k + m is m + 1/2, and cannot"),
        "{err}"
    );
    // Beside the declaration, the two ways out a user who set `k` for a claim would take.
    assert!(
        err.contains(
            "; or give k a value where k + m is a number, a single term or a product of \
             declared denominators, or leave it free"
        ),
        "{err}"
    );
    let f = f.to_str().unwrap();
    let err = superint_refused(&["expand", f, "x", "--when", "k = 1/2, x = 1/(k + m)"]);
    assert!(err.contains("the denominator k + m is m + 1/2"), "{err}");
    let other = "[[claim]]\nid = \"free\"\nclaim = \"k*(m + 1) = 1\"\n\
        when = \"k = 1/(m + 1)\"\n\
        [[claim]]\nid = \"held\"\nclaim = \"x/(k + 1) = x\"\nwhen = \"k = 1/(m + 1)\"\n";
    let f = scratch_text(
        "denominators-unvalued",
        "other.toml",
        &system("\"k + 1\", \"m + 1\"", other),
    );
    let err = superint_refused(&["check", f.to_str().unwrap()]);
    assert!(
        err.contains(
            "other.toml:13:9: at k = 1/(m + 1) the denominator k + 1 is 1 + 1/(m + 1), which \
             divides by the denominator m + 1: a denominator's value that divides by another is \
             not supported; give k a value where k + 1 is a number, a single term or a product \
             of declared denominators, or leave it free"
        ),
        "{err}"
    );
    let free = other.split("[[claim]]\nid = \"held\"").next().unwrap();
    let f = scratch_text(
        "denominators-unvalued",
        "free.toml",
        &system("\"k + 1\", \"m + 1\"", free),
    );
    check_says(&f, &["[free proved]"]);
}
