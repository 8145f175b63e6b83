//! Claims made on a level set, `on = "EXPR = VALUE"` in a `[[claim]]`: proved by the quotient
//! of `lhs − rhs` on division by `P = EXPR − VALUE` (recomputed here), refuted with the
//! remainder, and every refusal of the level set placed at its line and column.

use superint::prelude::*;
use superint::report::OnLevelSet;

/// The report's claim `id`, whose `k`-th it is among those of that id.
pub(crate) fn claim_of<'a>(report: &'a Report, id: &str) -> &'a ClaimResult {
    report
        .claims()
        .into_iter()
        .find(|c| c.id == id)
        .unwrap_or_else(|| panic!("no claim {id}"))
}

fn level_of(c: &ClaimResult) -> &OnLevelSet {
    c.on_level.as_ref().expect("a claim on a level set")
}

/// The Goryachev–Chaplygin integral `K` is claimed on the area integral's level set `A = 0`,
/// in the file's own names: proved, `Q = −c M2`, and `{K, H} − Q·P = 0` recomputed; the same
/// claim off the level set is refuted, as the file expects.
#[test]
fn the_goryachev_chaplygin_integral_is_proved_on_its_level_set() {
    let file = load_system_file(
        "systems/goryachev-chaplygin-top.toml",
        &LimitsOverride::default(),
    )
    .expect("loads");
    let report = check_report([&file]).expect("checked");
    assert!(report.all_as_expected());
    let on = claim_of(&report, "gc-on-level");
    assert!(on.proved && on.residual.is_none(), "{on:?}");
    let level = level_of(on);
    assert_eq!(level.text, "A = 0");
    let p = |s: &str| file.system().parse(s).expect("parses");
    assert_eq!(level.polynomial, p("M1*gamma1 + M2*gamma2 + M3*gamma3"));
    let q = level.quotient.as_ref().expect("a quotient");
    assert_eq!(q, &p("-c*M2"));
    let flow = p("{M3*(M1^2 + M2^2) + c*M1*gamma3, H}");
    let product = level.polynomial.checked_mul(q).expect("product");
    assert!(flow.checked_sub(&product).expect("difference").is_zero());
    // The text reads like the paper, a product by juxtaposition as search --on writes it.
    let text = render(&report, Format::Text, &RenderOptions::default());
    assert!(
        text.contains("{K, H} = 0 on A = 0")
            && text.contains("{K, H} = Q (M1 γ1 + M2 γ2 + M3 γ3) with Q = −c M2"),
        "{text}"
    );
    let latex = render(&report, Format::Latex, &RenderOptions::default());
    assert!(!latex.contains(r"\cdot"), "{latex}");
    let off = claim_of(&report, "gc-off-level");
    assert!(!off.proved && off.on_level.is_none());
}

/// The 1:2 oscillator `H = (p_x² + p_y²)/2 + (x² + 4y²)/2` on canonical coordinates.
const OSCILLATOR: &str = r#"name = "1:2 oscillator"
hamiltonian = "(p_x^2 + p_y^2)/2 + (x^2 + 4*y^2)/2"

[phase_space]
coordinates = ["x", "y"]

[[function]]
name = "C"
value = "(p_x^2 - x^2)*p_y + 4*x*p_x*y"
"#;

/// `OSCILLATOR` with the claims `claims` (TOML).
fn oscillator(claims: &str) -> LoadedSystem {
    load_system_text(
        "osc.toml",
        &format!("{OSCILLATOR}\n{claims}"),
        &LimitsOverride::default(),
    )
    .expect("loads")
}

/// On the energy level `H = 1`: the cubic integral `C` (everywhere, `Q = 0`), `x² = 2 − p_x² −
/// p_y² − 4y²` (there alone, `Q = 2`: refuted without `on`), and a false claim refuted with
/// its remainder, which `expect = "refuted"` takes.
#[test]
fn claims_on_an_energy_level_are_proved_or_refuted() {
    let file = oscillator(
        r#"
[[claim]]
id = "cubic"
claim = "{C, H} = 0"
on = "H = 1"

[[claim]]
id = "level"
claim = "x^2 = 2 - p_x^2 - p_y^2 - 4*y^2"
on = "H = 1"

[[claim]]
id = "off"
claim = "x^2 = 2 - p_x^2 - p_y^2 - 4*y^2"
expect = "refuted"

[[claim]]
id = "false"
claim = "{x*p_y, H} = 0"
on = "H = 1"
expect = "refuted"
"#,
    );
    let report = check_report([&file]).expect("checked");
    assert!(report.all_as_expected());
    let p = |s: &str| file.system().parse(s).expect("parses");
    let cubic = claim_of(&report, "cubic");
    assert!(cubic.proved);
    assert!(level_of(cubic).quotient.as_ref().unwrap().is_zero());
    let level = claim_of(&report, "level");
    assert!(level.proved);
    let q = level_of(level).quotient.clone().unwrap();
    assert_eq!(q, p("2"));
    let d = p("x^2 - 2 + p_x^2 + p_y^2 + 4*y^2");
    let product = level_of(level).polynomial.checked_mul(&q).unwrap();
    assert!(d.checked_sub(&product).unwrap().is_zero());
    assert!(!claim_of(&report, "off").proved);
    // {x p_y, H} = p_x p_y − 4xy, whose remainder modulo H − 1 is itself (LM(P) = x²).
    let false_claim = claim_of(&report, "false");
    assert!(!false_claim.proved && false_claim.on_level.is_some());
    assert_eq!(false_claim.residual, Some(p("p_x*p_y - 4*x*y")));
    // The same false claim expected proved fails the check.
    let file = oscillator("[[claim]]\nclaim = \"{x*p_y, H} = 0\"\non = \"H = 1\"\n");
    assert!(!check_report([&file]).unwrap().all_as_expected());
}

/// Every refusal of a claim's level set is placed at its `on` text (line and column), and
/// says what is wrong.
#[test]
fn level_sets_a_claim_cannot_take_are_refused_where_they_are_written() {
    let gc = std::fs::read_to_string("systems/goryachev-chaplygin-top.toml").unwrap();
    let refused = |claim: &str, extra: &str, on: &str| {
        let text = format!("{gc}\n[[claim]]\nclaim = \"{claim}\"\n{extra}on = \"{on}\"\n");
        let line = text.lines().count();
        let err =
            load_system_text("gc.toml", &text, &LimitsOverride::default()).expect_err("refused");
        (line, err)
    };
    let at_with = |claim: &str, extra: &str, on: &str, column_in_on: usize, message: &str| {
        let (line, err) = refused(claim, extra, on);
        // `on = "` is 6 columns.
        assert_eq!(
            err.line_col(),
            Some((line, 6 + column_in_on)),
            "{on}: {err}"
        );
        assert_eq!(err.kind, ErrorKind::Condition, "{on}: {err}");
        assert!(err.message.contains(message), "{on}: {err}");
    };
    let at = |on: &str, column_in_on: usize, message: &str| {
        at_with("{K, H} = 0", "", on, column_in_on, message)
    };
    at("A", 1, "there is no '=' here");
    at("A = 0 = 1", 7, "with one '='");
    at(" = 0", 2, "no expression before '='");
    at("A = ", 3, "no value after '='");
    at("M1/gamma3 = 0", 1, "negative power of γ3");
    at("M1 = 0", 1, "the flow of H leaves the level set");
    at("A^2 = 0", 1, "write each factor of P once");
    at("M1 + i*gamma1 = 0", 1, "is not real");
    at("M1 + i*gamma1 = 0", 1, "and `on` takes one");
    at(
        "c*A = 0",
        1,
        "has a parameter in the coefficient of its leading monomial",
    );
    at("gamma1 = M1", 10, "the level set's value holds M1");
    at("c = 1", 1, "no variable of phase space");
    at_with(
        "rank(H, K) = 2",
        "",
        "A = 0",
        1,
        "`on` takes an identity `lhs = rhs`, not a rank",
    );
    // A condition that sets a phase variable does not commute with the bracket with H.
    at_with(
        "{K, H} = 0",
        "when = \"M3 = 1\"\n",
        "A = 0",
        1,
        "a claim on a level set does not take a condition that sets a phase variable \
         (M3, a Poisson variable): its substitution does not commute with the bracket with H",
    );
    // Nor one that sets a parameter to a function of phase space.
    at_with(
        "{K, H} = 0",
        "when = \"c = gamma1\"\n",
        "A = 0",
        1,
        "sets the parameter c to a function of phase space (it holds γ1, a Poisson variable)",
    );
    // A condition that fixes the parameter to 0 leaves `c A = 0` no level set.
    at_with(
        "{K, H} = 0",
        "when = \"c = 0\"\n",
        "c*A = 0",
        1,
        "no variable of phase space",
    );
    // An angle, on the harmonic rotor.
    let rotor = std::fs::read_to_string("systems/harmonic-rotor.toml").unwrap();
    let text = format!("{rotor}\n[[claim]]\nclaim = \"{{L, H}} = 0\"\non = \"cos(theta) = 0\"\n");
    let err =
        load_system_text("rotor.toml", &text, &LimitsOverride::default()).expect_err("refused");
    assert_eq!(err.line_col(), Some((text.lines().count(), 7)), "{err}");
    assert!(err.message.contains("holds an angle, θ"), "{err}");
    // A system with radicals: a level set holding the radical, or a variable of its
    // radicand, is refused at the expression (tests/it/level_sets_with_relations.rs takes
    // one that holds neither).
    let kepler = std::fs::read_to_string("systems/kepler-3d.toml").unwrap();
    for (on, says) in [
        ("r = 1", "holds a radical, r"),
        (
            "x = 1",
            "P = x − 1 shares x with the radicand x² + y² + z² of the radical r",
        ),
    ] {
        let text = format!("{kepler}\n[[claim]]\nclaim = \"{{x, H}} = 0\"\non = \"{on}\"\n");
        let err = load_system_text("kepler.toml", &text, &LimitsOverride::default())
            .expect_err("refused");
        assert_eq!(err.line_col(), Some((text.lines().count(), 7)), "{err}");
        assert!(err.message.contains(says), "{err}");
    }
}

/// A rotation, `H = x p_y − y p_x`, with a parameter `a`, and the claims `claims` (TOML).
fn rotation(claims: &str) -> Result<LoadedSystem, FileError> {
    let header = "name = \"rotation\"\nhamiltonian = \"x*p_y - y*p_x\"\n\n[phase_space]\n\
                  coordinates = [\"x\", \"y\"]\nparameters = [\"a\"]\n\n";
    load_system_text(
        "rotation.toml",
        &format!("{header}{claims}"),
        &LimitsOverride::default(),
    )
}

/// The rotation keeps every circle `x² + y² = a`. `x = 0` on it is refuted
/// with the remainder `x`, which says only that `x` is not a multiple of `P = x² + y² − a`:
/// at `a = 0` the real level set is the origin, where `x` is zero, and at `a < 0` it is
/// empty. The report says what the remainder proves, not that `x` is nonzero on the level set.
#[test]
fn a_refutation_on_a_level_set_says_only_that_the_difference_is_no_multiple_of_p() {
    let file = rotation(
        r#"
[[claim]]
id = "on-circle"
claim = "x^2 = a - y^2"
on = "x^2 + y^2 = a"

[[claim]]
id = "axis"
claim = "x = 0"
on = "x^2 + y^2 = a"
expect = "refuted"
"#,
    )
    .expect("loads");
    let report = check_report([&file]).expect("checked");
    assert!(report.all_as_expected());
    let p = |s: &str| file.system().parse(s).expect("parses");
    let on_circle = claim_of(&report, "on-circle");
    assert_eq!(level_of(on_circle).quotient, Some(p("1")));
    let axis = claim_of(&report, "axis");
    assert_eq!(axis.residual, Some(p("x")));
    for format in [Format::Text, Format::Markdown, Format::Latex] {
        let shown = render(&report, format, &RenderOptions::default());
        let says = match format {
            Format::Text => "P = x² + y² − a does not divide lhs − rhs",
            _ => "not a multiple of",
        };
        assert!(shown.contains(says), "{shown}");
        assert!(
            !shown.contains("not zero on the level set") && !shown.contains("not zero there"),
            "{shown}"
        );
    }
    // The text's residual is the remainder, congruent to lhs − rhs modulo P, not equal to it:
    // `x² = 1` on the circle has lhs − rhs = x² − 1 and remainder −y² + a − 1.
    let file = rotation("[[claim]]\nid = \"t\"\nclaim = \"x^2 = 1\"\non = \"x^2 + y^2 = a\"\nexpect = \"refuted\"\n")
        .expect("loads");
    let report = check_report([&file]).expect("checked");
    assert_eq!(
        claim_of(&report, "t").residual,
        Some(file.system().parse("-y^2 + a - 1").unwrap())
    );
    let text = render(&report, Format::Text, &RenderOptions::default());
    assert!(
        text.contains("residual lhs − rhs ≡ −y² + a − 1 (mod P)"),
        "{text}"
    );
    assert!(!text.contains("residual lhs − rhs ="), "{text}");
}

/// A claim on a level set is decided by dividing polynomials, so a side with a negative power
/// of a phase variable is refused, not refuted: `(x² + y² − a)/x = 0` on `x² + y² = a` holds
/// where `x ≠ 0`, and its Laurent remainder `x + y²/x − a/x` was printed as a refutation.
/// Multiplied by `x`, the claim is proved.
#[test]
fn a_claim_on_a_level_set_with_a_negative_power_is_refused_not_refuted() {
    let file = rotation(
        "[[claim]]\nid = \"t\"\nclaim = \"(x^2 + y^2 - a)/x = 0\"\non = \"x^2 + y^2 = a\"\n",
    )
    .expect("loads");
    let err = check_report([&file]).unwrap_err();
    assert!(
        err.to_string()
            .contains("has a negative power of x: a claim on a level set is decided by dividing"),
        "{err}"
    );
    assert_eq!(err.line_col().map(|(line, _)| line), Some(10), "{err}");
    let file =
        rotation("[[claim]]\nid = \"t\"\nclaim = \"x^2 + y^2 - a = 0\"\non = \"x^2 + y^2 = a\"\n")
            .expect("loads");
    assert!(check_report([&file]).expect("checked").all_proved());
}

/// A program states a claim on a level set as a file does ([`LoadedSystem::add_claim_on`]):
/// proved by its quotient, refuted with its remainder, and a level set it cannot take refused
/// at line 2 of `<claim ID>`, where it is written.
#[test]
fn a_program_states_a_claim_on_a_level_set() {
    let mut gc = load_system_file(
        "systems/goryachev-chaplygin-top.toml",
        &LimitsOverride::default(),
    )
    .expect("loads");
    gc.add_claim_on("mine", "{K, H} = 0", "A = 0")
        .expect("read");
    gc.add_claim_on("off", "{M1, H} = 0", "A = 0")
        .expect("read")
        .expect = Expect::Refuted;
    let report = check_report([&gc]).expect("checked");
    assert!(report.all_as_expected());
    let p = |s: &str| gc.system().parse(s).expect("parses");
    let mine = claim_of(&report, "mine");
    assert!(mine.proved);
    assert_eq!(level_of(mine).quotient, Some(p("-c*M2")));
    let off = claim_of(&report, "off");
    assert!(!off.proved && off.residual.is_some() && off.on_level.is_some());
    let err = gc.add_claim_on("bad", "{K, H} = 0", "M1 = 0").unwrap_err();
    assert_eq!(err.origin, "<claim bad>", "{err}");
    assert_eq!(err.line_col(), Some((2, 1)), "{err}");
    assert!(
        err.message.contains("the flow of H leaves the level set"),
        "{err}"
    );
    let err = gc.add_claim_on("", "{K, H} = 0", "A = 0").unwrap_err();
    assert_eq!(err.origin, "<claim>", "{err}");
}

/// A program states a claim on a level set under a condition as a file does
/// ([`LoadedSystem::add_claim_on_when`]): the heavy top's cubic on `A = 0` is proved at
/// `I3 = 1/4` by `Q = −c M2` and refuted at `I3 = 1/2` with the remainder `2c M2 M3 γ3`, as
/// the file's claims are; a condition that sets a phase variable is refused at the level set
/// (line 2 of `<claim ID>`), and an error in the condition itself at line 3.
#[test]
fn a_program_states_a_claim_on_a_level_set_under_a_condition() {
    let mut top =
        load_system_file("systems/heavy-top.toml", &LimitsOverride::default()).expect("loads");
    let cubic = "{M3*(M1^2 + M2^2) + c*M1*gamma3, H} = 0";
    top.add_claim_on_when("mine", cubic, "A = 0", Some("I3 = 1/4"))
        .expect("read");
    top.add_claim_on_when("kov", cubic, "A = 0", Some("I3 = 1/2"))
        .expect("read")
        .expect = Expect::Refuted;
    let report = check_report([&top]).expect("checked");
    assert!(report.all_as_expected());
    let p = |s: &str| top.system().parse(s).expect("parses");
    let mine = claim_of(&report, "mine");
    assert!(
        mine.proved && mine.condition.as_deref() == Some("I3 = 1/4"),
        "{mine:?}"
    );
    assert_eq!(level_of(mine).quotient, Some(p("-c*M2")));
    let kov = claim_of(&report, "kov");
    assert_eq!(kov.residual, Some(p("2*c*M2*M3*gamma3")));
    let err = top
        .add_claim_on_when("phase", cubic, "A = 0", Some("M3 = 1"))
        .unwrap_err();
    assert_eq!(
        (err.origin.as_str(), err.line_col()),
        ("<claim phase>", Some((2, 1))),
        "{err}"
    );
    assert!(err.message.contains("sets a phase variable (M3"), "{err}");
    let err = top
        .add_claim_on_when("typo", cubic, "A = 0", Some("I3 = 1/4, I4 = 1"))
        .unwrap_err();
    assert_eq!(err.line_col(), Some((3, 11)), "{err}");
}

/// A claim holds for every value of the parameters, so its level set's polynomial need only
/// be square-free as a polynomial with them: `(x² + y²)² − (a − 1)(x² + y²)` has the repeated
/// factor `(x² + y²)²` at `a = 1`, where a search would take it, and none at `a = 2`; the
/// claim on it is read and decided. A square, `(x² + y² − a)²`, is refused at every value
/// tried, and the refusal names `P` with its parameter.
#[test]
fn a_claims_level_set_is_square_free_for_all_but_special_values_of_its_parameters() {
    let rotation = |claim: &str, on: &str| {
        rotation(&format!("[[claim]]\nclaim = \"{claim}\"\non = \"{on}\"\n"))
    };
    let file = rotation(
        "(x^2 + y^2)^2 = (a - 1)*(x^2 + y^2)",
        "(x^2 + y^2)^2 - (a - 1)*(x^2 + y^2) = 0",
    )
    .expect("square-free for a ≠ 1");
    let report = check_report([&file]).expect("checked");
    assert!(report.all_as_expected());
    let c = &report.claims()[0];
    assert_eq!(
        level_of(c).quotient,
        Some(file.system().parse("1").unwrap())
    );
    let err = rotation("x = 0", "(x^2 + y^2 - a)^2 = 0").expect_err("a square");
    assert_eq!(err.line_col(), Some((10, 7)), "{err}");
    assert!(
        err.message
            .contains("P = x⁴ + 2x²y² − 2ax² + y⁴ − 2ay² + a² is not shown square-free")
            && err
                .message
                .contains("lines tried through phase space and its parameters"),
        "{err}"
    );
    // Square-free though P is a square where b = a², a curve through every point (1, 1),
    // (k, k²) of parameter values: the lines run through the parameters too.
    let file = load_system_text(
        "circle.toml",
        "name = \"rotation\"\nhamiltonian = \"x*p_y - y*p_x\"\n\n[phase_space]\n\
         coordinates = [\"x\", \"y\"]\nparameters = [\"a\", \"b\"]\n\n[[claim]]\n\
         claim = \"x^2 + y^2 = b - a^2\"\non = \"x^2 + y^2 + a^2 = b\"\n",
        &LimitsOverride::default(),
    )
    .expect("square-free but where b = a²");
    assert!(check_report([&file]).expect("checked").all_proved());
}

/// The lines of the square-free test have directions that differ for any number of
/// variables: with 14 phase variables the 14th took the first's direction on every line, so
/// `q1² − p_q7² = 1`, square-free, was refused as a square.
#[test]
fn a_level_set_in_many_variables_is_shown_square_free() {
    let file = load_system_text(
        "seven.toml",
        "name = \"seven free\"\nhamiltonian = \"(p_q2^2 + p_q3^2)/2\"\n\n[phase_space]\n\
         coordinates = [\"q1\", \"q2\", \"q3\", \"q4\", \"q5\", \"q6\", \"q7\"]\n\n[[claim]]\n\
         claim = \"{q1, H} = 0\"\non = \"q1^2 - p_q7^2 = 1\"\n",
        &LimitsOverride::default(),
    )
    .expect("square-free");
    assert!(check_report([&file]).expect("checked").all_proved());
}

/// A level set of high degree is shown square-free, and one with a repeated factor refused,
/// at that degree: `A⁴⁰ Γ = 1` on the Goryachev–Chaplygin top (degree 82) holds the Casimirs
/// `Γ` and `A` as integrals, and `(A¹⁰ Γ − 1)²` is refused, named by its leading terms. Its
/// restriction to a line is
/// reduced modulo a prime, where Euclid over Q let the coefficients grow (37 s at degree 82).
#[test]
fn a_level_set_of_high_degree_is_shown_square_free_or_not() {
    let mut gc = load_system_file(
        "systems/goryachev-chaplygin-top.toml",
        &LimitsOverride::default(),
    )
    .expect("loads");
    gc.add_claim_on("gamma", "{Gamma, H} = 0", "A^40*Gamma = 1")
        .expect("square-free");
    let report = check_report([&gc]).expect("checked");
    assert!(report.all_as_expected() && claim_of(&report, "gamma").proved);
    let err = gc
        .add_claim_on("square", "{Gamma, H} = 0", "(A^10*Gamma - 1)^2 = 0")
        .unwrap_err();
    assert!(
        err.message.contains("is not shown square-free") && err.message.len() < 1000,
        "{err}"
    );
}

/// The heavy top with `H = (M1² + M2²)/2 + M3²/(2 I3) − c γ1` is the Goryachev–Chaplygin top
/// at `I3 = 1/4` (`I1 = I2 = 4 I3`), whose cubic `K = M3(M1² + M2²) + c M1 γ3` is conserved
/// on the area integral's level `A = 0` alone: the file's claim, `on` beside a `when` that
/// fixes `I3`, is proved by its quotient `Q = −c M2`, recomputed at `I3 = 1/4`. The `when`
/// matters: without it the claim leaves the remainder `c M2 M3 γ3 (4 − 1/I3)`, and at
/// Kovalevskaya's `I3 = 1/2` it is refuted with `2c M2 M3 γ3`. Text and JSON show both the
/// condition and the level set.
#[test]
fn the_heavy_top_at_i3_one_quarter_has_the_goryachev_chaplygin_integral_on_its_level_set() {
    let path = "systems/heavy-top.toml";
    let top = std::fs::read_to_string(path).unwrap();
    let claim = |id: &str, when: &str| {
        format!(
            "\n[[claim]]\nid = \"{id}\"\nclaim = \"{{M3*(M1^2 + M2^2) + c*M1*gamma3, H}} = 0\"\n\
             {when}on = \"A = 0\"\nexpect = \"refuted\"\n"
        )
    };
    let text = format!(
        "{top}{}{}",
        claim("free-moment", ""),
        claim("kovalevskaya-moment", "when = \"I3 = 1/2\"\n")
    );
    let file = load_system_text(path, &text, &LimitsOverride::default()).expect("loads");
    let report = check_report([&file]).expect("checked");
    assert!(report.all_as_expected());
    let p = |s: &str| file.system().parse(s).expect("parses");
    let gc = claim_of(&report, "goryachev-chaplygin");
    assert!(gc.proved && gc.residual.is_none(), "{gc:?}");
    assert_eq!(gc.condition.as_deref(), Some("I3 = 1/4"));
    let level = level_of(gc);
    assert_eq!(level.polynomial, p("M1*gamma1 + M2*gamma2 + M3*gamma3"));
    let q = level.quotient.as_ref().expect("a quotient");
    assert_eq!(q, &p("-c*M2"));
    let i3 = file.system().vars().lookup("I3").unwrap();
    let flow = p("{M3*(M1^2 + M2^2) + c*M1*gamma3, H}")
        .subst(i3, &p("1/4"))
        .unwrap();
    let product = level.polynomial.checked_mul(q).unwrap();
    assert!(flow.checked_sub(&product).unwrap().is_zero());
    let free = claim_of(&report, "free-moment");
    assert_eq!(
        free.residual,
        Some(p("4*c*M2*M3*gamma3 - c*M2*M3*gamma3/I3"))
    );
    let kovalevskaya = claim_of(&report, "kovalevskaya-moment");
    assert_eq!(kovalevskaya.residual, Some(p("2*c*M2*M3*gamma3")));
    let shown = render(&report, Format::Text, &RenderOptions::default());
    assert!(
        shown.contains("{M3 (M1² + M2²) + c M1 γ3, H} = 0 at I3 = 1/4 on A = 0"),
        "{shown}"
    );
    let json = render(&report, Format::Json, &RenderOptions::default());
    let json: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    let entry = json["claims"]
        .as_array()
        .expect("claims")
        .iter()
        .find(|c| c["id"] == "goryachev-chaplygin")
        .expect("the claim");
    assert_eq!(entry["condition_ascii"], "I3 = 1/4");
    assert_eq!(entry["level_set"]["text"], "A = 0");
    assert_eq!(entry["level_set"]["quotient"], "-c*M2");
}

/// A condition that fixes a parameter sets it in the level set too: `c A = 0` has a parameter
/// in its leading coefficient, refused for a claim for every `c`, and at `c = 2` it is `2A =
/// 0`, on which the Goryachev–Chaplygin integral is proved with `Q = −M2`.
#[test]
fn a_condition_that_fixes_a_parameter_fixes_it_in_the_level_set() {
    let gc = std::fs::read_to_string("systems/goryachev-chaplygin-top.toml").unwrap();
    let with = |when: &str| {
        let text = format!(
            "{gc}\n[[claim]]\nid = \"t\"\nclaim = \"{{K, H}} = 0\"\n{when}on = \"c*A = 0\"\n"
        );
        load_system_text("gc.toml", &text, &LimitsOverride::default())
    };
    let err = with("").expect_err("a parameter in the leading coefficient");
    assert!(
        err.message.contains("has a parameter in the coefficient"),
        "{err}"
    );
    let file = with("when = \"c = 2\"\n").expect("loads");
    let report = check_report([&file]).expect("checked");
    let t = claim_of(&report, "t");
    assert!(t.proved, "{t:?}");
    let p = |s: &str| file.system().parse(s).expect("parses");
    assert_eq!(
        level_of(t).polynomial,
        p("2*M1*gamma1 + 2*M2*gamma2 + 2*M3*gamma3")
    );
    assert_eq!(level_of(t).quotient, Some(p("-M2")));
}

/// Through the binary, a claim on a level set with a condition that sets a phase variable is
/// refused with exit status 2, placed at its `on` text.
#[test]
fn a_claim_on_a_level_set_under_a_phase_condition_is_refused_by_check() {
    let gc = std::fs::read_to_string("systems/goryachev-chaplygin-top.toml").unwrap();
    let text =
        format!("{gc}\n[[claim]]\nclaim = \"{{K, H}} = 0\"\nwhen = \"M3 = 1\"\non = \"A = 0\"\n");
    let line = text.lines().count();
    let file = crate::scratch_text("level-set-claims", "phase-when.toml", &text);
    let out = crate::superint_exits(&["check", file.to_str().unwrap()], 2);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains(&format!("phase-when.toml:{line}:7: a claim on a level set does not take a condition that sets a phase variable (M3, a Poisson variable)")),
        "{stderr}"
    );
    assert!(
        stderr.contains(" | on = \"A = 0\"") && stderr.contains('^'),
        "{stderr}"
    );
}

/// A claim's level set under a condition that fixes parameters is checked at their values, as
/// its claim is decided there: on the heavy top, the flow of `H` keeps `M3 = 0` at `c = 0`
/// alone (`{M3, H} = −c γ2`), and `M3² = c` is square-free but for `c = 0`, where it is
/// refused and the refusal says at which values `P` was taken. Where the condition sets to
/// zero a parameter that `H` or the level set divides by, neither has a value and the claim
/// is refused, placed at its `on`, not proved (`A = 0` at `I3 = 0`, though the flow of `H`,
/// which divides by `I3`, must keep `A = 0`) nor refused as a bare division by zero; a claim
/// whose sides name `H` (`{A, H} = 0`) is refused at its `when`, as one on no level set is.
#[test]
fn a_claim_on_a_level_set_is_checked_at_the_values_its_condition_fixes() {
    let top = std::fs::read_to_string("systems/heavy-top.toml").unwrap();
    let with = |claim: &str, when: &str, on: &str| {
        let text =
            format!("{top}\n[[claim]]\nid = \"t\"\nclaim = \"{claim}\"\n{when}on = \"{on}\"\n");
        let line = text.lines().count();
        (
            line,
            load_system_text("top.toml", &text, &LimitsOverride::default()),
        )
    };
    let refused = |claim: &str, when: &str, on: &str, says: &[&str]| {
        let (line, loaded) = with(claim, when, on);
        let err = loaded.expect_err("refused");
        assert_eq!(err.line_col(), Some((line, 7)), "{on}: {err}");
        for s in says {
            assert!(err.message.contains(s), "{on}: {err}");
        }
    };
    let (_, kept) = with("{M3, H} = 0", "when = \"c = 0\"\n", "M3 = 0");
    let report = check_report([&kept.expect("loads")]).expect("checked");
    assert!(claim_of(&report, "t").proved);
    refused(
        "{M3, H} = 0",
        "",
        "M3 = 0",
        &["the flow of H leaves the level set"],
    );
    refused(
        "{M3, H} = 0",
        "when = \"c = 0\"\n",
        "M3^2 = c",
        &[
            "P = M3² is not shown square-free",
            "here P is taken at c = 0, which the claim's `when` fixes",
        ],
    );
    refused(
        "A = 0",
        "when = \"I3 = 0\"\n",
        "A = 0",
        &["the condition sets I3 = 0, but H divides by I3"],
    );
    let (line, named) = with("{A, H} = 0", "when = \"I3 = 0\"\n", "A = 0");
    let err = named.expect_err("refused at the when");
    assert_eq!(err.line_col(), Some((line - 1, 14)), "{err}");
    assert!(err
        .message
        .contains("the condition sets I3 = 0, but H divides by I3"));
    refused(
        "{Gamma, H} = 0",
        "when = \"c = 0\"\n",
        "M1 + gamma1/c = 0",
        &["the condition sets c = 0, but the level set divides by c"],
    );
}
