//! Time-dependent integrals in extended phase space: time `t` a coordinate with momentum
//! `p_t`, `K = H + p_t`, and clock angles `φ = Ωt` with `K = H + Ω p_φ`
//! (`systems/driven-oscillator.toml`, docs/system-files.md's "Time-dependent systems").

use crate::{scratch_text, superint_json, superint_ok, superint_refused};

/// Free fall in extended phase space, `K = p_x²/2 + gx + p_t`.
const FREE_FALL: &str = "name = \"free fall\"\nhamiltonian = \"p_x^2/2 + g*x + p_t\"\n\
    [phase_space]\ncoordinates = [\"x\", \"t\"]\nparameters = [\"g\"]\n";

/// `p_t = 0` fixes the momentum of a coordinate that `K` does not involve, which the flow
/// keeps, so it is left out of the space as an angle's momentum is: `p_t` is no longer found.
/// What is found is, by hand, the momentum `p_x + gt` (`d/dt = −g + g`) and the boost
/// `x − p_x t − gt²/2` (`d/dt = p_x + gt − p_x − gt = 0`), with 1: their span, of dimension 3.
#[test]
fn a_fixed_p_t_is_left_out_and_the_boost_is_found() {
    let f = scratch_text("time-dependent", "free-fall.toml", FREE_FALL);
    let out = crate::normalize(&superint_ok(&[
        "search",
        f.to_str().unwrap(),
        "--when",
        "p_t = 0",
        "--momenta-degree",
        "1",
        "--positions-degree",
        "2",
    ]));
    assert!(
        out.contains(
            "p_t is left out: the condition fixes it, and every function of it is an integral."
        ),
        "{out}"
    );
    assert!(
        out.contains("Dimension of the space of integrals: 3."),
        "{out}"
    );
    let claims = format!(
        "{FREE_FALL}[[claim]]\nid = \"momentum\"\nclaim = \"{{p_x + g*t, H}} = 0\"\n\
         [[claim]]\nid = \"boost\"\nclaim = \"{{x - p_x*t - g*t^2/2, H}} = 0\"\n\
         [[claim]]\nid = \"independent\"\nclaim = \"rank(p_x + g*t, x - p_x*t - g*t^2/2) = 2\"\n\
         [[claim]]\nid = \"false-boost\"\nclaim = \"{{x - p_x*t + g*t^2/2, H}} = 0\"\n\
         expect = \"refuted\"\n"
    );
    let f = scratch_text("time-dependent", "free-fall-claims.toml", &claims);
    let out = superint_ok(&["check", f.to_str().unwrap()]);
    assert!(
        out.contains("4 claims in 1 file: 3 proved, 1 refuted; all as expected"),
        "{out}"
    );
}

/// The driven oscillator at the resonance `Ω = ω` (`M = ω = 1`, `f = 2`): a search whose space
/// holds no denominator runs there, though the file's off-resonance integrals divide by
/// `ω² − Ω²`, and finds the resonant integral with its secular term, derived by hand in the
/// file (`P_res = 2ω p_x cos φ + 2Mω²x sin φ − f sin φ cos φ − fωt`, here
/// `2p_x cos φ + 2x sin φ − sin 2φ − 2t`); a space that holds the denominator is refused.
#[test]
fn at_the_resonance_a_search_without_denominators_finds_the_secular_integral() {
    let resonance = driven_search("M = 1, omega = 1, Omega = 1, f = 2, p_psi = 0, p_t = 0");
    let out = superint_ok(&[&resonance[..], &["--denominators-degree", "0"]].concat());
    assert!(
        out.contains("I4 = −2t + 2 p_x cos φ + 2x sin φ − sin 2φ"),
        "{out}"
    );
    let err = superint_refused(&resonance);
    assert!(
        err.contains("the denominator ω² − Ω² is 0, so what divides by it has no value there"),
        "{err}"
    );
}

/// `--find-values Omega` finds the resonance from `H` alone: at `ω = 1` (and `M = f = 1`) the
/// generic `Ω` has the four integrals of the driven oscillator, `Ω = ±1` seven (the clocks'
/// phase `cos(φ ∓ ψ)`, `sin(φ ∓ ψ)` and the secular integrals), `Ω = 0` eight (the stopped
/// clock's `cos φ`, `sin φ`), and every root of the determinants is rational. At `Ω = 1` the
/// secular integral is, by hand, `2 P_res` of the file at `M = ω = f = 1`:
/// `2(2p_x cos φ + 2x sin φ − sin φ cos φ − t) = −2t + 4p_x cos φ + 4x sin φ − sin 2φ`.
#[test]
fn find_values_finds_the_resonance_from_h_alone() {
    let search = [
        &driven_search("p_psi = 0, p_t = 0")[..],
        &["--find-values", "Omega", "--fix", "omega=1,M=1,f=1"],
        &["--denominators-degree", "0"],
    ]
    .concat();
    let json = superint_json(&search);
    let found = &json["exceptional_values"][0];
    assert_eq!(found["generic"]["dimension"], 4);
    let values: Vec<(&str, u64)> = found["values"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| {
            (
                v["value"].as_str().unwrap(),
                v["dimension"].as_u64().unwrap(),
            )
        })
        .collect();
    assert_eq!(values, [("-1", 7), ("0", 8), ("1", 7)]);
    assert_eq!(found["ruled_out_roots"], 0);
    assert!(found["unexamined"].is_null());
    let text = superint_ok(&search);
    let at_one = text
        .split("At Ω = 1: Basis")
        .nth(1)
        .expect("the search at Ω = 1");
    assert!(
        at_one.contains("= −2t + 4 p_x cos φ + 4x sin φ − sin 2φ"),
        "{text}"
    );
}

/// The values `--find-values Omega` finds, with the dimension and functional rank of the
/// search at each, and the generic dimension and rank: what two routes to the same search
/// must agree on.
fn found_values(search: &[&str]) -> (Vec<(String, u64, u64)>, u64, u64) {
    let json = superint_json(search);
    let found = &json["exceptional_values"][0];
    let at = |v: &serde_json::Value| {
        (
            v["dimension"].as_u64().unwrap(),
            v["functional_rank"].as_u64().unwrap(),
        )
    };
    let values = (found["values"].as_array().unwrap().iter())
        .map(|v| (v["value"].as_str().unwrap().to_string(), at(v).0, at(v).1))
        .collect();
    let (dimension, rank) = at(&found["generic"]);
    (values, dimension, rank)
}

/// `--when 'omega = 1, …'` is `--fix omega=1` for `--find-values Omega` in a space without
/// the declared denominator: `ω² − Ω²`, `1 − Ω²` there, divides nothing searched (`H` does
/// not hold it), so the condition is taken, and the values, their dimensions and functional
/// ranks are those the `--fix` route finds (`Ω = ±1` seven, `Ω = 0` eight, generic four, as
/// [`find_values_finds_the_resonance_from_h_alone`] checks by hand). With the denominator in
/// the space the condition is refused, saying the way out, `--fix omega=1`; and a bracket of
/// `X`, which divides by `ω² − Ω²`, stays refused at `ω = 1`: `1/(1 − Ω²)` is no division
/// the engine takes for every `Ω`.
#[test]
fn find_values_takes_a_condition_that_sets_the_denominators_other_parameter() {
    let degrees = ["--denominators-degree", "0"];
    let fixed = [
        &driven_search("p_psi = 0, p_t = 0")[..],
        &["--find-values", "Omega", "--fix", "omega=1,M=1,f=1"],
        &degrees,
    ]
    .concat();
    let when = driven_search("omega = 1, p_psi = 0, p_t = 0");
    let conditioned = [
        &when[..],
        &["--find-values", "Omega", "--fix", "M=1,f=1"],
        &degrees,
    ]
    .concat();
    let expected = |v: &str, d, r| (v.to_string(), d, r);
    let found = found_values(&conditioned);
    assert_eq!(
        found.0,
        [
            expected("-1", 7, 3),
            expected("0", 8, 4),
            expected("1", 7, 3)
        ]
    );
    assert_eq!(found, found_values(&fixed));
    let err =
        superint_refused(&[&when[..], &["--find-values", "Omega", "--fix", "M=1,f=1"]].concat());
    assert!(
        err.contains(
            "the denominator ω² − Ω² is −Ω² + 1, and cannot divide by −Ω² + 1: only division"
        ) && err.contains(
            "or leave it free; with --find-values Omega, fix ω with --fix omega=1 in place of \
             the condition's value"
        ),
        "{err}"
    );
    let err = superint_refused(&[
        "bracket",
        "systems/driven-oscillator.toml",
        "X",
        "H",
        "--when",
        "omega = 1",
    ]);
    assert!(
        err.contains("the denominator ω² − Ω² is −Ω² + 1, and cannot divide by −Ω² + 1"),
        "{err}"
    );
}

/// `check` of the file: every claim as expected, the counts those of the file's claims.
#[test]
fn the_driven_oscillator_claims_are_as_expected() {
    let out = superint_ok(&["check", "systems/driven-oscillator.toml"]);
    assert!(
        out.contains("14 claims in 1 file: 8 proved, 6 refuted; all as expected"),
        "{out}"
    );
}

/// Off the resonance (`M = 1`, `ω = 3`, `Ω = 1`, `f = 8`, so `f/(ω² − Ω²) = 1`) the search
/// finds the file's hand-derived `X` and `P` as elements (restated by them exactly), and
/// `p_t`, `p_ψ` are left out.
#[test]
fn off_the_resonance_the_search_finds_the_driven_integrals() {
    let out = superint_ok(&driven_search(
        "M = 1, omega = 3, Omega = 1, f = 8, p_psi = 0, p_t = 0",
    ));
    assert!(out.contains("p_t, p_ψ are left out"), "{out}");
    assert!(
        out.contains("Dimension of the space of integrals: 4."),
        "{out}"
    );
    // By hand: P = p_x cos ψ + 3x sin ψ + sin φ cos ψ − 3 cos φ sin ψ, and
    // sin φ cos ψ − 3 cos φ sin ψ = −sin(φ + ψ) + 2 sin(φ − ψ).
    assert!(
        out.contains("p_x cos ψ + 3x sin ψ − sin(φ + ψ) + 2 sin(φ − ψ)\n       = P"),
        "{out}"
    );
    assert!(out.contains("= −X"), "{out}");
}

/// The search of the driven oscillator's integrals of degree 1 in `p_x` and in the
/// positions, of trigonometric order 2 (products of the clocks), at the condition `when`.
fn driven_search(when: &str) -> [&str; 10] {
    [
        "search",
        "systems/driven-oscillator.toml",
        "--when",
        when,
        "--momenta-degree",
        "1",
        "--positions-degree",
        "1",
        "--trig-degree",
        "2",
    ]
}

/// An oscillator driven at `Ω` with `ω² − Ω²` declared, `F = x/(ω² − Ω²)`.
const OVER_D: &str = "name = \"d\"\n\
    hamiltonian = \"p_x^2/2 + omega^2*x^2/2 + Omega*p_phi - f*x*cos(phi)\"\n\
    [phase_space]\ncoordinates = [\"x\"]\nangles = [\"phi\"]\n\
    parameters = [\"omega\", \"Omega\", \"f\"]\ndenominators = [\"omega^2 - Omega^2\"]\n\
    [[function]]\nname = \"F\"\nvalue = \"x/(omega^2 - Omega^2)\"\n";

/// At `Ω = ω`, where `ω² − Ω²` is 0, nothing that divides by it has a value, so no claim that
/// does is proved or refuted, even where what the claim computes is free of it: `{F, p_φ}`
/// (0, but `F` divides), both sides alike (`x/D = x/D`), sides whose difference is `1`, a
/// rank whose function cancels its `F`, a bracket with an `H` over `D`, and the `bracket`
/// command of `F`. Each is refused, naming what divides by it; a claim free of `D` is checked.
#[test]
fn at_a_zero_denominator_whatever_divides_by_it_is_refused() {
    let claim =
        |c: &str| format!("[[claim]]\nid = \"c\"\nclaim = \"{c}\"\nwhen = \"Omega = omega\"\n");
    let over_h = OVER_D.replace(
        "p_x^2/2 + omega^2*x^2/2",
        "p_x^2/2 + x^2/(omega^2 - Omega^2)",
    );
    let cases = [
        (OVER_D, "{F, p_phi} = 0", "the function F divides by it"),
        (
            OVER_D,
            "x/(omega^2 - Omega^2) = x/(omega^2 - Omega^2)",
            "the claim divides by it",
        ),
        (
            OVER_D,
            "x/(omega^2 - Omega^2) + 1 = x/(omega^2 - Omega^2)",
            "the claim divides by it",
        ),
        (OVER_D, "rank(F - F + p_phi) = 1", "F divides by it"),
        (&over_h, "{p_phi, H} = 0", "divides by it"),
    ];
    for (system, c, what) in cases {
        let f = scratch_text(
            "time-dependent",
            "zero-denominator.toml",
            &format!("{system}{}", claim(c)),
        );
        let err = superint_refused(&["check", f.to_str().unwrap()]);
        assert!(
            err.contains(
                "at Ω = ω the denominator ω² − Ω² is 0, so what divides by it has no value"
            ) && err.contains(what),
            "{c}: {err}"
        );
    }
    let f = scratch_text("time-dependent", "zero-denominator.toml", OVER_D);
    let f = f.to_str().unwrap();
    let err = superint_refused(&["bracket", f, "F", "p_phi", "--when", "Omega = omega"]);
    assert!(
        err.contains("the denominator ω² − Ω² is 0") && err.contains("(F divides by it)"),
        "{err}"
    );
    let free = format!("{OVER_D}{}", claim("{x, p_x} = 1"));
    let f = scratch_text("time-dependent", "zero-denominator-free.toml", &free);
    let out = superint_ok(&["check", f.to_str().unwrap()]);
    assert!(out.contains("1 proved, 0 refuted"), "{out}");
}

/// `--new-only` at the resonance with no denominator in the space: a given known integral
/// over `ω² − Ω²` has no value there and is refused so (not as no integral, as `X` was: its
/// bracket with the atom kept is not 0, nor one that is `X_res` over it, found an integral
/// with the atom kept); the file's `X`, `P` over it are no known integrals there.
#[test]
fn at_the_resonance_a_known_integral_over_the_zero_denominator_is_refused() {
    let resonance = driven_search("M = 1, omega = 1, Omega = 1, f = 2, p_psi = 0, p_t = 0");
    let new_only = [
        &resonance[..],
        &["--denominators-degree", "0", "--new-only"],
    ]
    .concat();
    for known in ["X", "Xres/(omega^2 - Omega^2)"] {
        let err = superint_refused(&[&new_only[..], &["--known", known]].concat());
        assert!(
            err.contains("has no value where it is searched: at ")
                && err.contains("the denominator ω² − Ω² is 0"),
            "{known}: {err}"
        );
    }
    let out = superint_ok(&new_only);
    assert!(
        out.contains("Known integrals in the space: X_res, P_res."),
        "{out}"
    );
}
