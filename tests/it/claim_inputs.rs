//! A claim under a condition that sets a variable to 0 is decided only where everything its
//! truth depends on has a value there: `H` and each function it names, each declared bracket
//! its brackets take. Their computed sides may have cancelled the divisor (`{A, H} = 0` of the
//! heavy top at `I3 = 0`, though `H` divides by `I3`); the file refuses such a claim at its
//! `when`, the binary exits 2, and the library's `Claim::check` refuses it too.

use superint::prelude::*;

use crate::superint_exits;

/// The heavy top's file with one more claim `id = "x"`, and the line of its `when`.
fn top_with(claim: &str, when: &str) -> (String, usize) {
    let top = std::fs::read_to_string("systems/heavy-top.toml").unwrap();
    let text = format!("{top}\n[[claim]]\nid = \"x\"\nclaim = \"{claim}\"\nwhen = \"{when}\"\n");
    let line = text.lines().count();
    (text, line)
}

/// Whether claim `x` of `text` is proved, checked as `superint check` checks it.
fn proved(text: &str) -> bool {
    let loaded = load_system_text("t.toml", text, &LimitsOverride::default()).expect("loads");
    let report = check_report([&loaded]).expect("checked");
    let x = report.claims().into_iter().find(|c| c.id == "x");
    x.expect("the claim x").proved
}

/// The refusal of `text`, asserted placed at `at` (line, column) and saying `says`.
#[track_caller]
fn refused_at(text: &str, at: (usize, usize), says: &str) {
    let err = load_system_text("t.toml", text, &LimitsOverride::default()).expect_err("refused");
    assert_eq!(err.line_col(), Some(at), "{err}");
    assert!(err.message.contains(says), "{err}");
}

/// `{A, H} = 0` at `I3 = 0` was proved, though `H = (M1² + M2²)/2 + M3²/(2 I3) − c γ1` has no
/// value there: refused at the `when`'s value, as a rank of `I3 H` is (whose value has no
/// `1/I3` left, but names `H`). A bracket that does not take `H` (`{A, Γ} = 0`) is proved at
/// `I3 = 0`; under a harmless condition the true claim is proved and a false one refuted.
#[test]
fn a_claim_whose_hamiltonian_has_no_value_at_its_condition_is_refused() {
    let h_divides = "the condition sets I3 = 0, but H divides by I3";
    let (text, line) = top_with("{A, H} = 0", "I3 = 0");
    refused_at(&text, (line, 14), h_divides);
    let (text, line) = top_with("rank(I3*H, A) = 2", "I3 = 0");
    refused_at(&text, (line, 14), h_divides);
    assert!(proved(&top_with("{A, Gamma} = 0", "I3 = 0").0));
    assert!(proved(&top_with("{A, H} = 0", "I3 = 2").0));
    assert!(proved(&top_with("{A, H} = 0", "c = 0").0));
    assert!(!proved(&top_with("{M1, H} = 0", "I3 = 2").0));
}

/// A rigid body whose declared brackets divide by `k` (`{M1, M2} = M3/k`), with its Casimir.
const SCALED_BODY: &str = r#"name = "scaled rigid body"
hamiltonian = "(M1^2 + M2^2 + M3^2)/2"
[phase_space]
variables = ["M1", "M2", "M3"]
parameters = ["k"]
[poisson]
"{M1, M2}" = "M3/k"
"{M2, M3}" = "M1/k"
"{M3, M1}" = "M2/k"
[[function]]
name = "C"
value = "M1^2 + M2^2 + M3^2"
"#;

/// A free particle with a function that divides by the coordinate `x`.
const OVER_X: &str = r#"name = "free particle"
hamiltonian = "(p_x^2 + p_y^2)/2"
[phase_space]
coordinates = ["x", "y"]
[[function]]
name = "F"
value = "p_y/x"
"#;

/// `system`'s text with one more claim `id = "x"` under `when`, and the line of its `when`.
fn with_claim(system: &str, claim: &str, when: &str) -> (String, usize) {
    let text = format!("{system}[[claim]]\nid = \"x\"\nclaim = \"{claim}\"\nwhen = \"{when}\"\n");
    let line = text.lines().count();
    (text, line)
}

/// A condition that sets to 0 a parameter a declared bracket divides by, or a phase variable
/// a named function divides by, is refused at its value: `{C, M1} = 0` (the Casimir's bracket,
/// 0 for every `k ≠ 0`) and `{F, p_y} = 0` (`F = p_y/x`) were proved there. Elsewhere the true
/// claim is proved and a false one refuted.
#[test]
fn a_condition_where_a_declared_bracket_or_a_function_divides_by_zero_is_refused() {
    let with = with_claim;
    let (text, line) = with(SCALED_BODY, "{C, M1} = 0", "k = 0");
    refused_at(
        &text,
        (line, 13),
        "the condition sets k = 0, but the bracket {M1, M2} divides by k",
    );
    assert!(proved(&with(SCALED_BODY, "{C, M1} = 0", "k = 2").0));
    assert!(!proved(&with(SCALED_BODY, "{M1, M2} = M3", "k = 2").0));
    let (text, line) = with(OVER_X, "{F, p_y} = 0", "x = 0");
    refused_at(
        &text,
        (line, 13),
        "the condition sets x = 0, but the function F divides by x",
    );
    assert!(proved(&with(OVER_X, "{F, p_y} = 0", "x = 1").0));
    assert!(!proved(&with(OVER_X, "{F, p_x} = 0", "x = 1").0));
}

/// [`OVER_X`] with `G = x F` and the family `K_{m,n} = x^m F^n`, computed from `F = p_y/x`:
/// their values (`G = p_y`, `K_{1,1} = p_y`) have no `1/x` left.
fn through_f() -> String {
    format!(
        "{OVER_X}[[function]]\nname = \"G\"\nvalue = \"x*F\"\n\
         [[family]]\nname = \"K\"\nvalue = \"x^m*F^n\"\n"
    )
}

/// A function or family instance computed from a function that divides by `x` has no value
/// at `x = 0`, though its own value has cancelled the divisor: `{G, p_y} = 0`,
/// `{K_{1,1}, p_y} = 0` and `rank(G, p_x) = 2` were proved there. Refused at the `when`'s
/// value, naming the claim's function (an instance as printed) and the function that divides;
/// at `y = 0` the claim is proved, and a false one at `x = 1` refuted.
#[test]
fn a_function_computed_from_one_that_divides_by_zero_at_the_condition_is_refused() {
    let system = through_f();
    let with = |claim: &str, when: &str| with_claim(&system, claim, when);
    let computed_from_f = |g: &str| {
        format!("x = 0, but the claim's {g} is computed from the function F, which divides by x")
    };
    for (claim, g) in [
        ("{G, p_y} = 0", "G"),
        ("{K_1_1, p_y} = 0", "K_{1,1}"),
        ("rank(G, p_x) = 2", "G"),
    ] {
        let (text, line) = with(claim, "x = 0");
        refused_at(&text, (line, 13), &computed_from_f(g));
    }
    assert!(proved(&with("{G, p_y} = 0", "y = 0").0));
    assert!(proved(&with("{K_1_1, p_y} = 0", "y = 0").0));
    assert!(!proved(&with("{G, y} = 0", "x = 1").0));
}

/// A family instance that divides by `x` itself (`K_{0,1} = F = p_y/x`) was named in ASCII by
/// the refusal, `the function K_0_1`: it is named as printed, however the claim writes it.
#[test]
fn a_refused_family_instance_is_named_as_printed() {
    let system = through_f();
    for written in ["K_0_1", "K_{0,1}"] {
        let (text, line) = with_claim(&system, &format!("{{{written}, p_y}} = 0"), "x = 0");
        refused_at(
            &text,
            (line, 13),
            "the condition sets x = 0, but the function K_{0,1} divides by x",
        );
    }
    assert!(proved(&with_claim(&system, "{K_0_1, p_y} = 0", "x = 2").0));
}

/// `superint check` of the heavy top with `{A, H} = 0` at `I3 = 0` exited 0 with the claim
/// proved: it exits 2 with the refusal at the `when`.
#[test]
fn check_exits_2_on_a_claim_whose_hamiltonian_has_no_value() {
    let dir = std::env::temp_dir().join(format!("superint-inputs-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let file = dir.join("top.toml");
    let (text, line) = top_with("{A, H} = 0", "I3 = 0");
    std::fs::write(&file, text).expect("write the file");
    let o = superint_exits(&["check", file.to_str().expect("UTF-8")], 2);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(
        stderr.contains(&format!(
            "top.toml:{line}:14: the condition sets I3 = 0, but H divides by I3"
        )),
        "{stderr}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The library's claim read in a system (`Claim::parse`) knows what its sides are computed
/// from and is refused where one has no value, as the file's is; the same sides as bare
/// expressions (`Claim::new`) are all it knows, and are proved.
#[test]
fn the_librarys_claim_is_refused_where_what_it_is_computed_from_has_no_value() {
    let (text, _) = top_with("{A, H} = 0", "I3 = 2");
    let loaded = load_system_text("t.toml", &text, &LimitsOverride::default()).expect("loads");
    let top = loaded.system();
    let i3 = top.lookup("I3").expect("I3");
    let at = |v: i64| {
        Condition::new(
            &format!("I3 = {v}"),
            i3,
            Expr::constant(top.vars(), v.into()),
        )
    };
    let read = Claim::parse(top, "x", "{A, H} = 0", "{A, H}", "0").expect("parses");
    assert!(read
        .clone()
        .when(at(2))
        .check()
        .expect("checked")
        .outcome
        .is_proved());
    let err = read.when(at(0)).check().expect_err("refused");
    assert!(
        matches!(&err, EngineError::RefusedCondition { var, .. } if *var == i3),
        "{err}"
    );
    assert!(err.to_string().contains("but H divides by I3"), "{err}");
    let bare = Claim::new(
        "x",
        "{A, H} = 0",
        top.parse("{A, H}").unwrap(),
        top.parse("0").unwrap(),
    );
    assert!(bare
        .when(at(0))
        .check()
        .expect("checked")
        .outcome
        .is_proved());
    let false_one = Claim::parse(top, "y", "{M1, H} = 0", "{M1, H}", "0").expect("parses");
    assert!(!false_one
        .when(at(2))
        .check()
        .expect("checked")
        .outcome
        .is_proved());
}
