//! `superint search --find-values`: the values of one parameter at which the space holds more
//! integrals, in every format, and what it refuses.

use crate::cli::compile_within;
use crate::{
    normalize, scratch_text, superint_json, superint_ok, superint_ok_line, superint_refused,
};

const HENON_HEILES: &str = "systems/henon-heiles.toml";

/// The Hénon–Heiles family at A = B = 1, quadratic in the momenta, degree 4 in the positions.
const HENON_HEILES_VALUES: [&str; 9] = [
    "search",
    HENON_HEILES,
    "--find-values",
    "C",
    "--fix",
    "A=1,B=1",
    "--momenta-degree",
    "2",
    "--positions-degree",
];

/// [`HENON_HEILES_VALUES`] at positions degree 4, in `format`.
fn henon_heiles(format: &str) -> String {
    superint_ok(
        &[
            &HENON_HEILES_VALUES[..],
            &["4", "--format", format, "--no-timings"],
        ]
        .concat(),
    )
}

#[test]
fn henon_heiles_has_a_second_quadratic_integral_exactly_at_c_one_third_and_two_in_text() {
    let text = normalize(&henon_heiles("text"));
    assert!(
        text.contains("For a generic C (searched at C = 7, no root): 2 integrals (section 2), of functional rank 1."),
        "{text}"
    );
    assert!(
        text.contains(
            "More integrals at C = 1/3, 3 integrals (section 4), of functional rank 2 and at C = 2, 3 integrals (section 6), of functional rank 2."
        ),
        "{text}"
    );
    assert!(
        text.contains("Every root of the determinants is rational"),
        "{text}"
    );
    // Each value's search as --when prints it: the separable case's integral at C = 1/3, the
    // KdV case's at C = 2, each proved.
    assert!(text.contains("4 At C = 1/3: Search"), "{text}");
    assert!(text.contains("I2 = 3 p_x p_y + x³ + 3xy² + 3xy"), "{text}");
    assert!(
        text.contains("I3 = 4x p_x p_y − 4y p_x² − 3 p_y² + x⁴ + 4x²y² − 2x²y − 12y³ − 3y²"),
        "{text}"
    );
    // Each search's I1, I2, … are its own claims: 2 at the generic value, 3 at each value.
    assert!(text.contains("8 claims: 8 proved, 0 refuted"), "{text}");
}

#[test]
fn henon_heiles_exceptional_values_in_json() {
    let json = superint_json(&[&HENON_HEILES_VALUES[..], &["4"]].concat());
    let found = &json["exceptional_values"][0];
    assert_eq!(found["parameter"], "C");
    assert_eq!(found["section"], 1);
    assert_eq!(found["generic"]["value"], "7");
    assert_eq!(found["generic"]["dimension"], 2);
    let values: Vec<(&str, u64, u64)> = found["values"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| {
            let n = |k: &str| v[k].as_u64().unwrap();
            (v["value"].as_str().unwrap(), n("dimension"), n("section"))
        })
        .collect();
    assert_eq!(values, [("1/3", 3, 4), ("2", 3, 6)]);
    assert!(found["unexamined"].is_null());
    // Every root rational: nothing to rule out.
    assert_eq!(found["ruled_out_roots"], 0);
    assert!(found["ruled_out"].is_null());
    // The searches, one a value, and their claims, all proved.
    assert_eq!(json["searches"].as_array().unwrap().len(), 3);
    assert_eq!(json["summary"]["all_proved"], true);
    assert_eq!(json["summary"]["claims"], 8);
    // An ordinary search has no such list.
    let plain = superint_json(&["search", HENON_HEILES, "--momenta-degree", "1"]);
    assert!(plain.get("exceptional_values").is_none());
}

#[test]
fn henon_heiles_exceptional_values_in_markdown_and_latex() {
    let markdown = henon_heiles("markdown");
    assert!(
        markdown.contains("## 1. Values of `C` with more integrals"),
        "{markdown}"
    );
    assert!(markdown.contains("at `C = 1/3`"), "{markdown}");
    let latex = henon_heiles("latex");
    assert!(
        latex.contains("$C = 1/3$") || latex.contains("$C = \\frac{1}{3}$"),
        "{latex}"
    );
    assert!(latex.trim_end().ends_with("\\end{document}"));
    compile_within(&latex, 1.0);
}

/// A scratch system file `name`: `(p_x² + p_y²)/2 + potential` in `x, y` with the
/// parameter `a`.
fn oscillator(name: &str, potential: &str) -> std::path::PathBuf {
    let text = format!(
        "name = \"oscillator\"\nhamiltonian = \"(p_x^2 + p_y^2)/2 + {potential}\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\"]\n"
    );
    scratch_text("exceptional-values", name, &text)
}

/// `superint search FILE --find-values a` with `extra`, as arguments.
fn values_of_a<'a>(file: &'a std::path::Path, extra: &[&'a str]) -> Vec<&'a str> {
    let find = ["search", file.to_str().unwrap(), "--find-values", "a"];
    [&find[..], extra].concat()
}

#[test]
fn an_irrational_value_is_reported_with_its_polynomial_not_claimed() {
    // Isotropic where a² = 2: the value √2 is not rational.
    let file = oscillator("irrational.toml", "(x^2 + (a^2 - 1)*y^2)/2");
    let args = values_of_a(&file, &["--positions-degree", "2"]);
    let text = normalize(&superint_ok(&args));
    assert!(text.contains("More integrals at a = −1"), "{text}");
    // Short: whole, with its degree.
    assert!(
        text.contains("Other values may lie among the roots of a² − 2 (degree 2)"),
        "{text}"
    );
    // Its real roots (±√2, ±√3, ±√5 and ±√(3/2)), not rational, are counted: a real value may
    // hide there.
    // Of the determinants' roots ±√2, ±√3, ±√5 and ±√(3/2), not rational, the isotropic ±√2
    // are left, every minor vanishing there; the other six are ruled out.
    assert!(
        text.contains("Other values may lie among the roots of a² − 2 (degree 2), which are not rational (2 of them real)"),
        "{text}"
    );
    assert!(
        text.contains("The determinants' other 6 roots (not rational; 6 real) hold no more integrals in this space"),
        "{text}"
    );
    // The block where the isotropic roots stay common modulo the prime was settled by its
    // exact determinants over Q, and the text says so.
    assert!(
        text.replace('\n', " ").contains(
            "(shown modulo the prime p = 4611686018427387847 and, for 1 block, by exact \
             determinants over Q)"
        ),
        "{text}"
    );
    // JSON carries the counts beside the polynomials.
    let json = superint_json(&args);
    let found = &json["exceptional_values"][0];
    assert_eq!(found["unexamined"], "a^2 - 2");
    assert_eq!(found["unexamined_real_roots"], 2);
    assert_eq!(found["ruled_out"], "2*a^6 - 19*a^4 + 54*a^2 - 45");
    assert_eq!(found["ruled_out_roots"], 6);
    assert_eq!(found["ruled_out_real_roots"], 6);
    assert!(found["ruled_out_prime"].is_u64());
    // The one block the text says was settled by exact determinants over Q.
    assert_eq!(found["ruled_out_exact_blocks"], 1);
    assert_eq!(found["zero_left_out"], false);
}

/// Where every root of the polynomial left is complex, JSON says none is real (Hénon–Heiles at
/// B = 16: 21C² − 12C + 272); where every root is rational, it has no count.
#[test]
fn the_json_counts_the_real_roots_of_the_unexamined_polynomial() {
    let json = superint_json(&[
        "search",
        HENON_HEILES,
        "--find-values",
        "C",
        "--fix",
        "B=16",
        "--momenta-degree",
        "4",
        "--positions-degree",
        "6",
        "--trig-degree",
        "0",
    ]);
    let found = &json["exceptional_values"][0];
    // Both complex roots ruled out: nothing left unexamined.
    assert!(found["unexamined"].is_null());
    assert_eq!(found["ruled_out"], "21*C^2 - 12*C + 272");
    assert_eq!(found["ruled_out_real_roots"], 0);
    let rational = superint_json(&[&HENON_HEILES_VALUES[..], &["4"]].concat());
    assert!(rational["exceptional_values"][0]["unexamined_real_roots"].is_null());
}

/// A long polynomial whose roots were not ruled out (the oscillator isotropic at `a² = 2`, at
/// degree 5, where `a² − 1` is the square of many frequency ratios: degree 22, coefficients of
/// up to 12 digits) is shown by its first terms with its degree and the flag that shows it
/// whole, in text, Markdown and LaTeX; with --full-expressions, and in JSON, whole.
#[test]
fn a_long_unexamined_polynomial_is_shown_in_part_with_its_degree() {
    let file = oscillator("resonant.toml", "(x^2 + (a^2 - 1)*y^2)/2");
    let degree_five = [
        "search",
        file.to_str().unwrap(),
        "--find-values",
        "a",
        "--momenta-degree",
        "5",
        "--positions-degree",
        "5",
    ];
    let at = |extra: &[&str]| normalize(&superint_ok(&[&degree_five[..], extra].concat()));
    let whole = at(&["--full-expressions"]);
    let json = superint_json(&degree_five);
    let ascii = json["exceptional_values"][0]["unexamined"]
        .as_str()
        .expect("the polynomial")
        .to_string();
    // Whole: each of its 12 terms, down to the constant the JSON ends with.
    let last = ascii.rsplit(' ').next().unwrap();
    assert!(ascii.contains("a^22"), "{ascii}");
    assert!(whole.contains(&format!("{last} (degree 22)")), "{whole}");
    for format in ["text", "markdown", "latex"] {
        let part = at(&["--format", format]);
        // LaTeX writes the size as text in math and -- as -{}-.
        let size = match format {
            "latex" => "\\dots (a\\ \\text{polynomial of}\\ 12\\ \\text{terms})",
            _ => "+ … (a polynomial of 12 terms)",
        };
        for piece in [size, "(degree 22; -", "full-expressions shows it whole)"] {
            assert!(part.contains(piece), "{format}: {piece}: {part}");
        }
        assert!(!part.contains(last), "{format}: {part}");
    }
}

/// The anisotropic oscillator `(x² + a y²)/2` at degree 6: its resonances are at rational `a`
/// (squares of frequency ratios), and each of the determinants' 34 other roots, not rational,
/// is ruled out (every block keeps its rank there), in text, Markdown and LaTeX; JSON has no
/// unexamined polynomial and carries the one ruled out, whole.
#[test]
fn the_anisotropic_oscillators_irrational_roots_are_all_ruled_out() {
    let file = oscillator("anisotropic.toml", "(x^2 + a*y^2)/2");
    let degree_six = [
        "search",
        file.to_str().unwrap(),
        "--find-values",
        "a",
        "--momenta-degree",
        "6",
        "--positions-degree",
        "6",
    ];
    let at = |extra: &[&str]| normalize(&superint_ok(&[&degree_six[..], extra].concat()));
    for format in ["text", "markdown", "latex"] {
        let text = at(&["--format", format]).replace('\n', " ");
        for piece in [
            "other 34 roots (not rational; 34 real)",
            "keeps its generic rank",
        ] {
            assert!(text.contains(piece), "{format}: {piece}: {text}");
        }
        assert!(!text.contains("Other values may lie"), "{format}: {text}");
        // The prime written as the formula it is.
        let prime = match format {
            "text" => "the prime p = ",
            "markdown" => "the prime `p = ",
            _ => "the prime $p = ",
        };
        assert!(text.contains(prime), "{format}: {text}");
        // Every block settled modulo the prime: no exact determinant is claimed.
        assert!(!text.contains("exact determinants"), "{format}: {text}");
    }
    let json = superint_json(&degree_six);
    let found = &json["exceptional_values"][0];
    assert!(found["unexamined"].is_null());
    assert_eq!(found["ruled_out_roots"], 34);
    assert_eq!(found["ruled_out_real_roots"], 34);
    let ascii = found["ruled_out"].as_str().expect("the polynomial");
    assert!(ascii.contains("a^34"), "{ascii}");
    // As the text: every block modulo the prime, none by exact determinants.
    assert_eq!(found["ruled_out_exact_blocks"], 0);
}

#[test]
fn what_find_values_does_not_take_is_refused() {
    let search = |extra: &[&str]| {
        let mut args = vec!["search", HENON_HEILES, "--find-values"];
        args.extend(extra);
        superint_refused(&args)
    };
    let two = search(&["A,C"]);
    assert!(
        two.contains("--find-values solves for one parameter"),
        "{two}"
    );
    let symbolic = search(&["C", "--symbolic", "A"]);
    assert!(symbolic.contains("cannot be used with"), "{symbolic}");
    // A level set whose polynomial holds the parameter solved for: taken at fixed values.
    let top = |on: &str| {
        superint_refused(&[
            "search",
            "systems/heavy-top.toml",
            "--find-values",
            "I3",
            "--on",
            on,
        ])
    };
    let on = top("A = I3");
    assert!(
        on.contains("does not take a level set whose polynomial holds I3, A = I3"),
        "{on}"
    );
    assert!(on.contains("write the level set without I3"), "{on}");
    // Beside a level set, a condition is refused as an ordinary search refuses it.
    let when = superint_refused(&[
        "search",
        "systems/heavy-top.toml",
        "--find-values",
        "I3",
        "--on",
        "A = 0",
        "--when",
        "c = 2",
    ]);
    assert!(when.contains("--on does not take --when"), "{when}");
    let when = search(&["C", "--when", "C = 2"]);
    assert!(when.contains("a condition that sets C"), "{when}");
    let fixed = search(&["C", "--fix", "C=2"]);
    assert!(fixed.contains("a value fixed for C"), "{fixed}");
    let unknown = search(&["D"]);
    assert!(unknown.contains("--find-values"), "{unknown}");
    // A parameter in a declared denominator.
    let file = scratch_text(
        "exceptional-values",
        "denominator.toml",
        "name = \"d\"\nhamiltonian = \"(p_x^2 + p_y^2)/2 + a/(x - a*y)^2\"\n[phase_space]\n\
         coordinates = [\"x\", \"y\"]\nparameters = [\"a\"]\ndenominators = [\"x - a*y\"]\n",
    );
    let denominator = superint_refused(&["search", file.to_str().unwrap(), "--find-values", "a"]);
    assert!(
        denominator
            .contains("a in a declared denominator that holds a phase variable too, (x − ay)"),
        "{denominator}"
    );
    // A parameter in a declared radical, even one of parameters alone.
    let file = scratch_text(
        "exceptional-values",
        "radical.toml",
        "name = \"r\"\nhamiltonian = \"(p_x^2 + p_y^2)/2 + r*(x^2 + y^2)/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\"]\n\
         radicals = { r = \"a^2 + 1\" }\n",
    );
    let radical = superint_refused(&["search", file.to_str().unwrap(), "--find-values", "a"]);
    assert!(
        radical.contains("does not take a in a declared radical, r, whose reduction depends on it"),
        "{radical}"
    );
}

/// A condition that sets to 0 a parameter `H` divides by (`x²y/m` at `m = 0`) is refused as an
/// ordinary search refuses it, naming the condition, and a value fixed for the parameter solved
/// for with the refusal of `--find-values`: both said "division by zero" when `H` under the
/// condition was formed before them.
#[test]
fn a_condition_that_zeroes_a_parameter_h_divides_by_is_refused_by_name() {
    let file = scratch_text(
        "exceptional-values",
        "divides-by-m.toml",
        "name = \"m\"\nhamiltonian = \"(p_x^2 + p_y^2)/2 + a*x^2/2 + x^2*y/m\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\", \"m\"]\n",
    );
    let refused = |extra: &[&str]| superint_refused(&values_of_a(&file, extra));
    let zero = refused(&["--when", "m=0"]);
    assert!(
        zero.contains("the condition sets m = 0, but the Hamiltonian divides by m"),
        "{zero}"
    );
    let fixed = refused(&["--when", "m=0", "--fix", "a=1"]);
    assert!(fixed.contains("a value fixed for a"), "{fixed}");
}

/// A block whose minor passes `--max-minor` (the largest of Hénon–Heiles' blocks at
/// A = B = 1 has 30 rows) stops with exit code 2, the limit's message and the hint naming
/// the flag; the default lets it through.
#[test]
fn a_minor_past_max_minor_is_refused_with_the_flag_named() {
    let args = [&HENON_HEILES_VALUES[..], &["4", "--max-minor"]].concat();
    let refused = superint_refused(&[&args[..], &["29"]].concat());
    assert!(
        refused.contains("more than 29, the limit of the rows whose determinant"),
        "{refused}"
    );
    assert!(
        refused.contains("hint: if the machine has the time, raise the limit with --max-minor N"),
        "{refused}"
    );
    let at_thirty = normalize(&superint_ok(&[&args[..], &["30"]].concat()));
    assert!(at_thirty.contains("the largest has 30 rows"), "{at_thirty}");
    let without = superint_refused(&["search", HENON_HEILES, "--max-minor", "30"]);
    assert!(without.contains("--find-values"), "{without}");
}

#[test]
fn the_heavy_top_has_one_more_integral_at_the_kovalevskaya_ratio_i1_equal_i2_equal_2_i3_alone() {
    // H with k = 1/I3: k = 2 is Kovalevskaya's ratio and her quartic integral; k = 1 the
    // spherical top, where M1 is one too.
    let file = scratch_text(
        "exceptional-values",
        "heavy-top.toml",
        "name = \"top\"\nhamiltonian = \"(M1^2 + M2^2)/2 + k*M3^2/2 - c*gamma1\"\n\
         [phase_space]\nvariables = [\"M1\", \"M2\", \"M3\", \"gamma1\", \"gamma2\", \"gamma3\"]\n\
         parameters = [\"k\", \"c\"]\n[poisson]\n\"{M1, M2}\" = \"M3\"\n\"{M2, M3}\" = \"M1\"\n\
         \"{M3, M1}\" = \"M2\"\n\"{M1, gamma2}\" = \"gamma3\"\n\"{M1, gamma3}\" = \"-gamma2\"\n\
         \"{M2, gamma3}\" = \"gamma1\"\n\"{M2, gamma1}\" = \"-gamma3\"\n\
         \"{M3, gamma1}\" = \"gamma2\"\n\"{M3, gamma2}\" = \"-gamma1\"\n",
    );
    let (values, _) = top_values(file.to_str().unwrap(), "k");
    assert_eq!(values, [("1".to_string(), 10), ("2".to_string(), 1)]);
    // With I3 itself, a negative power in H: the same values, k = 1/I3, and I3 = 0 none.
    let (values, found) = top_values("systems/heavy-top.toml", "I3");
    assert_eq!(values, [("1/2".to_string(), 1), ("1".to_string(), 10)]);
    let not_exceptional = found["not_exceptional"].as_array().unwrap();
    assert!(
        not_exceptional.iter().all(|r| r != "0"),
        "{not_exceptional:?}"
    );
    // 0 was a root, left out: JSON and the text say so.
    assert_eq!(found["zero_left_out"], true);
    let text = normalize(&superint_ok(&[
        "search",
        "systems/heavy-top.toml",
        "--find-values",
        "I3",
        "--poisson-degree",
        "2",
    ]));
    assert!(
        text.contains("I3 = 0, a root of the determinants, is no value"),
        "{text}"
    );
}

/// `H/a` has the integrals of `H` at every `a ≠ 0`: each equation times `a` is constant, no
/// determinant has a root, and nothing is said of `a = 0` (JSON: not left out).
#[test]
fn zero_is_said_to_be_no_value_only_where_it_was_a_root() {
    let file = scratch_text(
        "exceptional-values",
        "scaled.toml",
        "name = \"scaled\"\nhamiltonian = \"(p_x^2 + p_y^2 + x^2 + 4*y^2)/(2*a)\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\"]\n",
    );
    let args = ["search", file.to_str().unwrap(), "--find-values", "a"];
    let text = normalize(&superint_ok(&args));
    assert!(
        text.contains("No rational value of a has more integrals."),
        "{text}"
    );
    assert!(!text.contains("a = 0"), "{text}");
    let json = superint_json(&args);
    assert_eq!(json["exceptional_values"][0]["zero_left_out"], false);
}

/// The heavy top's `H` alone, on the area integral's level `A = M·γ = 0`: the
/// Goryachev–Chaplygin top's cubic integral is found at `I3 = 1/4` (and the spherical top's
/// at `I3 = 1`), each value's dimension that of the ordinary search there, `--fix I3=VALUE
/// --on 'A = 0'`, and more than the generic value's.
#[test]
fn the_heavy_top_on_the_area_level_has_the_goryachev_chaplygin_cubic_at_i1_equal_i2_equal_4_i3() {
    let on = ["--on", "A = 0", "--poisson-degree", "3"];
    let find = [
        &["search", "systems/heavy-top.toml", "--find-values", "I3"][..],
        &on,
    ]
    .concat();
    let json = superint_json(&find);
    assert_eq!(json["summary"]["all_proved"], true);
    let found = &json["exceptional_values"][0];
    let generic = found["generic"]["dimension"].as_u64().unwrap();
    let values: Vec<(&str, u64)> = (found["values"].as_array().unwrap().iter())
        .map(|v| {
            (
                v["value"].as_str().unwrap(),
                v["dimension"].as_u64().unwrap(),
            )
        })
        .collect();
    assert!(values.iter().any(|(v, _)| *v == "1/4"), "{values:?}");
    let dimension_at = |value: &str| {
        let fix = format!("I3={value}");
        let plain = [
            &["search", "systems/heavy-top.toml", "--fix", &fix][..],
            &on,
        ]
        .concat();
        superint_json(&plain)["searches"][0]["dimension"]
            .as_u64()
            .unwrap()
    };
    assert_eq!(
        dimension_at(found["generic"]["value"].as_str().unwrap()),
        generic
    );
    for (value, dimension) in &values {
        assert!(*dimension > generic, "{value}");
        assert_eq!(dimension_at(value), *dimension, "{value}");
    }
    // The cubic, its bracket with H a multiple of M·γ, in the search at 1/4.
    let text = normalize(&superint_ok(&find));
    // The values are the level set's, as the title and the first section say.
    assert!(
        text.starts_with(
            "Values of I3 with more integrals for the heavy top on the level set M1 γ1 + M2 γ2 \
             + M3 γ3 = 0"
        ),
        "{text}"
    );
    assert!(
        text.contains("These are the values on the level set M1 γ1 + M2 γ2 + M3 γ3 = 0"),
        "{text}"
    );
    assert!(text.contains("At I3 = 1/4: Basis"), "{text}");
    assert!(
        text.contains("= Q4 (M1 γ1 + M2 γ2 + M3 γ3) at I3 = 1/4, c = 1"),
        "{text}"
    );
}

/// On a level set where no value of the parameter has more integrals (the y oscillator's
/// energy level, kept for every a; a x only shifts the x oscillator), none is found.
#[test]
fn a_level_set_where_no_value_has_more_integrals_finds_none() {
    let file = oscillator("shifted.toml", "(x^2 + 4*y^2)/2 + a*x");
    let text = normalize(&superint_ok(&[
        "search",
        file.to_str().unwrap(),
        "--find-values",
        "a",
        "--on",
        "p_y^2 + 4*y^2 = 4",
        "--positions-degree",
        "2",
    ]));
    assert!(
        text.contains("No rational value of a has more integrals."),
        "{text}"
    );
    assert!(text.contains("on the level set"), "{text}");
}

/// A level set that the flow keeps at one value of the parameter alone is refused where it
/// stands, saying that the flow must keep it at every value of the parameter:
/// `{x p_y − y p_x, H} = (1 − a) x y`.
#[test]
fn a_level_set_kept_at_one_value_of_the_parameter_alone_is_refused_saying_so() {
    let file = oscillator("kept-at-one.toml", "(x^2 + a*y^2)/2");
    let refused = superint_refused(&[
        "search",
        file.to_str().unwrap(),
        "--find-values",
        "a",
        "--on",
        "x*p_y - y*p_x = 0",
        "--positions-degree",
        "2",
    ]);
    assert!(
        refused.contains("<command line>:1:1: --on: the flow of H leaves the level set"),
        "{refused}"
    );
    assert!(
        refused.contains(
            "a is searched for, so the flow must keep the level set at every value of a, not \
             only where that remainder vanishes (search there with --fix)"
        ),
        "{refused}"
    );
}

/// Each value's search, shown as `--when 'C = VALUE'` shows it, is the engine's own, searched
/// once: its sections read as that ordinary search's.
#[test]
fn each_values_search_reads_as_the_ordinary_search_there() {
    let found = henon_heiles("text");
    let at_two = found
        .split_once("At C = 2: Search")
        .expect("the search at C = 2")
        .1;
    let plain = superint_ok(&[
        "search",
        HENON_HEILES,
        "--when",
        "C = 2",
        "--fix",
        "A=1,B=1",
        "--momenta-degree",
        "2",
        "--positions-degree",
        "4",
        "--no-timings",
    ]);
    let search = plain.split_once("1  Search").expect("its search").1;
    // Without the section titles, numbered apart, and the summaries, which count apart.
    let body = |t: &str| {
        t.lines()
            .filter(|l| !l.starts_with(|c: char| c.is_ascii_digit() || c == '═'))
            .map(str::to_string)
            .collect::<Vec<_>>()
    };
    assert!(body(search).iter().any(|l| l.contains("I3 = 4x p_x p_y")));
    assert_eq!(body(at_two), body(search));
}

/// `--find-values parameter` of the top in `file` at Poisson degree 4, every integral proved:
/// each value found with how many integrals more than the generic value has, and the JSON's
/// `exceptional_values` entry.
fn top_values(file: &str, parameter: &str) -> (Vec<(String, u64)>, serde_json::Value) {
    let json = superint_json(&[
        "search",
        file,
        "--find-values",
        parameter,
        "--poisson-degree",
        "4",
    ]);
    assert_eq!(json["summary"]["all_proved"], true);
    let found = json["exceptional_values"][0].clone();
    let generic = found["generic"]["dimension"].as_u64().unwrap();
    let values = (found["values"].as_array().unwrap().iter())
        .map(|v| {
            let more = v["dimension"].as_u64().unwrap() - generic;
            (v["value"].as_str().unwrap().to_string(), more)
        })
        .collect();
    (values, found)
}

/// An ordinary search is at the fixed values, so the flow is checked there: the level set
/// `x p_y − y p_x = 0` of `x² + a y²`, kept at `a = 1` alone, is searched with `--fix a=1`
/// (finding `p_x p_y + x y`) and refused at `a = 2`, saying at the fixed values.
#[test]
fn a_level_set_kept_at_the_fixed_value_alone_is_searched_there() {
    let file = oscillator("kept-at-the-fixed-value.toml", "(x^2 + a*y^2)/2");
    let path = file.to_str().unwrap();
    let args = |a| ["search", path, "--fix", a, "--on", "x*p_y - y*p_x = 0"];
    let found = superint_ok(&args("a=1"));
    assert!(found.contains("I3 = p_x p_y + xy"), "{found}");
    assert!(found.contains("4 proved, 0 refuted"), "{found}");
    let refused = superint_refused(&args("a=2"));
    assert!(
        refused.contains("the flow of H leaves the level set at the fixed values: {P, H} = −xy"),
        "{refused}"
    );
}

const HARMONIC_ROTOR: &str = "systems/harmonic-rotor.toml";

/// `--find-values parameter` for the harmonic rotor on the level set `p_θ = 1`, the other
/// parameters at `fix`, the space of momenta degree `momenta`, positions degree `positions`
/// and trigonometric order `order`: its `exceptional_values` entry, every integral proved,
/// each value's (and the generic value's) dimension checked by the ordinary search there,
/// `--fix parameter=VALUE --on 'p_theta = 1'`.
fn rotor_values(
    parameter: &str,
    fix: &str,
    [momenta, positions, order]: [&str; 3],
) -> serde_json::Value {
    values_checked(
        HARMONIC_ROTOR,
        ["--on", "p_theta = 1"],
        parameter,
        fix,
        [momenta, positions, order],
    )
}

/// [`rotor_values`] for the system `file`, on the level set or under the condition `level`
/// (`["--on", "p_theta = 1"]`, `["--when", "p_theta = 1"]`).
fn values_checked(
    file: &str,
    level: [&str; 2],
    parameter: &str,
    fix: &str,
    [momenta, positions, order]: [&str; 3],
) -> serde_json::Value {
    let space = [
        level[0],
        level[1],
        "--momenta-degree",
        momenta,
        "--positions-degree",
        positions,
        "--trig-degree",
        order,
    ];
    let find = [
        &["search", file, "--find-values", parameter, "--fix", fix][..],
        &space,
    ]
    .concat();
    let json = superint_json(&find);
    assert_eq!(json["summary"]["all_proved"], true);
    let found = json["exceptional_values"][0].clone();
    let dimension_at = |value: &str| {
        let fixed = format!("{fix},{parameter}={value}");
        let plain = [&["search", file, "--fix", &fixed][..], &space].concat();
        superint_json(&plain)["searches"][0]["dimension"]
            .as_u64()
            .unwrap()
    };
    let generic = found["generic"]["dimension"].as_u64().unwrap();
    assert_eq!(
        dimension_at(found["generic"]["value"].as_str().unwrap()),
        generic
    );
    for v in found["values"].as_array().unwrap() {
        let (value, dimension) = (v["value"].as_str().unwrap(), v["dimension"].as_u64());
        assert!(dimension.unwrap() > generic, "{value}");
        assert_eq!(Some(dimension_at(value)), dimension, "{value}");
    }
    found
}

/// The values of `found`, as JSON writes them.
fn values_found(found: &serde_json::Value) -> Vec<String> {
    (found["values"].as_array().unwrap().iter())
        .map(|v| v["value"].as_str().unwrap().to_string())
        .collect()
}

/// The resonant ratios `n/m` (`K_{m,n} = Z^m e^{−inθ}`, conserved where `mω = n p_θ/I`) of
/// a space that holds `Z^m` for `1 ≤ m ≤ degree` and `e^{−inθ}` for `|n| ≤ order`, increasing,
/// as JSON writes them (`−n/m` where `n < 0`: `K̄_{m,|n|}`, or `ω < 0`), with `0` (`n = 0`,
/// `Z^m` itself at `ω = 0`) when `with_zero`.
fn resonances(degree: i64, order: i64, with_zero: bool) -> Vec<String> {
    let gcd = |a: i64, b: i64| {
        (1..=a.abs().max(b))
            .rev()
            .find(|d| a % d == 0 && b % d == 0)
    };
    let mut ratios: Vec<(i64, i64)> = (1..=degree)
        .flat_map(|m| (-order..=order).map(move |n| (n, m)))
        .filter(|&(n, _)| with_zero || n != 0)
        .map(|(n, m)| {
            let d = gcd(n, m).unwrap_or(1);
            (n / d, m / d)
        })
        .collect();
    ratios.sort_by(|a, b| (a.0 * b.1).cmp(&(b.0 * a.1)));
    ratios.dedup();
    (ratios.into_iter())
        .map(|(n, m)| match m {
            1 => n.to_string(),
            _ => format!("{n}/{m}"),
        })
        .collect()
}

/// The paper's resonances asked the other way round: on `p_θ = 1` (`I = M = 1`), the values
/// of `ω` with more integrals than a generic one, quadratic in `Z` and of order 1 in `θ`,
/// are exactly `ω = n/m` for `m ≤ 2`, `|n| ≤ 1`, each confirmed by the ordinary search
/// there, and every root of the determinants is rational.
#[test]
fn harmonic_rotor_resonances_found_from_h_alone_on_p_theta_one() {
    let found = rotor_values("omega", "M=1,I=1,l=1", ["2", "2", "1"]);
    assert_eq!(values_found(&found), resonances(2, 1, true));
    assert!(found["unexamined"].is_null());
    assert_eq!(found["ruled_out_roots"], 0);
}

/// With momenta degree 1 and positions degree 2, the determinants have the irrational roots
/// `ω² = 2` and `ω² = 1/2`, ruled out: every block keeps its rank there. The same equations
/// in `w = ω²` (the Hamiltonian holds `ω²` alone) have them as the rational roots `w = 2` and
/// `w = 1/2`, where the ordinary search finds nothing more: the rule-out is right.
#[test]
fn harmonic_rotor_irrational_roots_on_p_theta_one_are_ruled_out_none_holding_more() {
    let found = rotor_values("omega", "M=1,I=1,l=1", ["1", "2", "2"]);
    assert_eq!(values_found(&found), resonances(1, 2, true));
    assert!(found["unexamined"].is_null());
    assert_eq!(found["ruled_out"], "2*omega^4 - 5*omega^2 + 2");
    assert_eq!(found["ruled_out_roots"], 4);
    assert_eq!(found["ruled_out_real_roots"], 4);
    let squared = scratch_text(
        "exceptional-values",
        "rotor-in-omega-squared.toml",
        "name = \"rotor\"\n\
         hamiltonian = \"(p_x^2 + p_y^2)/2 + w*(x^2 + y^2)/2 + p_theta^2/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nangles = [\"theta\"]\nparameters = [\"w\"]\n",
    );
    let text = normalize(&superint_ok(&[
        "search",
        squared.to_str().unwrap(),
        "--find-values",
        "w",
        "--on",
        "p_theta = 1",
        "--momenta-degree",
        "1",
        "--positions-degree",
        "2",
        "--trig-degree",
        "2",
    ]));
    assert!(
        text.contains(
            "Roots of the determinants where the search finds no more integrals: w = 1/2 and \
             w = 2."
        ),
        "{text}"
    );
}

/// On `p_θ = 1` with `ω = 1`, the moments of inertia with more integrals are `I = n/m`
/// (`m ≤ 2`, `|n| ≤ 1`, `n ≠ 0`); `I = 0`, a root once `p_θ²/(2I)` is made a polynomial, is
/// said to be no value.
#[test]
fn harmonic_rotor_resonant_moments_of_inertia_found_on_p_theta_one() {
    let found = rotor_values("I", "omega=1,M=1", ["2", "2", "1"]);
    assert_eq!(values_found(&found), resonances(2, 1, false));
    assert_eq!(found["zero_left_out"], true);
    assert!(found["unexamined"].is_null());
}

/// The harmonic rotor with `p_θ²/(2I(1 + κ))`, `1 + κ` declared: `I(1 + κ)` stands for `I`,
/// so the resonance `m ω = n p_θ/I` is `1 + κ = n p_θ/(m ω I)`, on `p_θ = 1` with `ω = I = 1`
/// `κ = n/m − 1`. At momenta and positions degree 2 and order 2, `n/m` is `±2, ±1, ±1/2`
/// (`m ≤ 2`, `0 < |n| ≤ 2`, as for `I` in section 30), so `κ = −3, −2, −3/2, −1/2, 0, 1`,
/// by hand; the same as `I − 1` for the values of `I` of the rotor without the
/// denominator, each with the same number of integrals. `κ = −1`, where `H` has no value, is
/// left out and said to be.
#[test]
fn a_parameter_in_a_declared_denominator_has_the_resonances_it_moves_found() {
    let file = scratch_text(
        "exceptional-values",
        "rotor-over-one-plus-kappa.toml",
        "name = \"rotor\"\n\
         hamiltonian = \"(p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2 + \
         p_theta^2/(2*I*(1 + kappa))\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nangles = [\"theta\"]\n\
         parameters = [\"M\", \"omega\", \"I\", \"kappa\"]\ndenominators = [\"1 + kappa\"]\n",
    );
    let file = file.to_str().unwrap();
    let when = ["--when", "p_theta = 1"];
    let space = ["2", "2", "2"];
    let found = values_checked(file, when, "kappa", "M=1,I=1,omega=1", space);
    assert_eq!(values_found(&found), ["-3", "-2", "-3/2", "-1/2", "0", "1"]);
    assert_eq!(
        found["denominator_roots_left_out"],
        serde_json::json!(["-1"])
    );
    assert!(found["unexamined"].is_null());
    // The independent route: I of the rotor without the denominator, shifted by −1.
    let by_i = values_checked(HARMONIC_ROTOR, when, "I", "omega=1,M=1,l=1", space);
    assert_eq!(values_found(&by_i), resonances(2, 2, false));
    let shifted = |v: &serde_json::Value| {
        let value = v["value"].as_str().unwrap();
        let (n, m) = value.split_once('/').unwrap_or((value, "1"));
        let (n, m): (i64, i64) = (n.parse().unwrap(), m.parse().unwrap());
        let value = match m {
            1 => (n - m).to_string(),
            _ => format!("{}/{m}", n - m),
        };
        (value, v["dimension"].as_u64())
    };
    let dimensions = |f: &serde_json::Value| {
        (f["values"].as_array().unwrap().iter())
            .map(|v| {
                (
                    v["value"].as_str().unwrap().to_string(),
                    v["dimension"].as_u64(),
                )
            })
            .collect::<Vec<_>>()
    };
    let by_i_shifted: Vec<_> = by_i["values"]
        .as_array()
        .unwrap()
        .iter()
        .map(shifted)
        .collect();
    assert_eq!(dimensions(&found), by_i_shifted);
    assert_eq!(found["generic"]["dimension"], by_i["generic"]["dimension"]);
    let text = normalize(&superint_ok(&kappa_values(
        file,
        &["--when", "p_theta = 1"],
    )));
    assert!(
        text.contains(
            "κ = −1, a root of the determinants, is no value: H divides by (κ + 1), which is \
             zero there"
        ),
        "{text}"
    );
}

/// `search FILE --find-values kappa` at `M = I = ω = 1`, then `extra`.
fn kappa_values<'a>(file: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let find = ["search", file, "--find-values", "kappa"];
    [&find[..], &["--fix", "M=1,I=1,omega=1"], extra].concat()
}

/// The gyroscopic rotor with `κ + 1` declared, which its `H` does not divide by: at
/// `--denominators-degree 0` the values of `κ` are the file's, `2κ ∈ {−2, …, 2}` (its `Q
/// e^{2iκθ}` of order 2), `κ = −1` among them; with the space's powers of `1/(κ + 1)`, which
/// have no value at `κ = −1`, that root is said not to be searched at, and the others stay.
#[test]
fn a_declared_denominator_that_h_does_not_divide_by_leaves_its_root_out_only_for_the_space() {
    let text = std::fs::read_to_string("systems/gyroscopic-rotor.toml")
        .unwrap()
        .replace(
            "parameters = [\"M\", \"omega\", \"I\", \"kappa\"]",
            "parameters = [\"M\", \"omega\", \"I\", \"kappa\"]\ndenominators = [\"kappa + 1\"]",
        );
    assert!(text.contains("denominators"));
    let file = scratch_text(
        "exceptional-values",
        "gyroscopic-over-kappa-plus-one.toml",
        &text,
    );
    let file = file.to_str().unwrap();
    let find = |extra: &[&'static str]| {
        let space = ["--momenta-degree", "2", "--positions-degree", "2"];
        kappa_values(file, &[&space[..], &["--trig-degree", "2"], extra].concat())
    };
    let run = |extra: &[&'static str]| superint_json(&find(extra))["exceptional_values"][0].clone();
    let whole = run(&["--denominators-degree", "0"]);
    assert_eq!(values_found(&whole), ["-1", "-1/2", "0", "1/2", "1"]);
    assert_eq!(whole["denominator_roots_left_out"], serde_json::json!([]));
    let with_powers = run(&[]);
    assert_eq!(values_found(&with_powers), ["-1/2", "0", "1/2", "1"]);
    assert_eq!(
        with_powers["denominator_roots_left_out"],
        serde_json::json!(["-1"])
    );
    let text = normalize(&superint_ok(&find(&[])));
    assert!(
        text.contains(
            "κ = −1, a root of the determinants, is not searched at: the space's functions \
             divide by (κ + 1), which is zero there (--denominators-degree 0 leaves them out)."
        ),
        "{text}"
    );
}

/// `search --help` says what becomes of the irrational roots: ruled out where every block
/// keeps its rank, only the polynomial of the rest printed (as `--find-values` does since
/// the rule-out, not "not examined").
#[test]
fn the_help_says_the_irrational_roots_are_ruled_out_where_they_can_be() {
    let help = normalize(&superint_ok(&["search", "--help"]));
    assert!(
        help.contains(
            "the other roots, irrational or complex, are ruled out where every block of the \
             equations keeps its rank there, and the polynomial of those that are not is printed"
        ),
        "{help}"
    );
    assert!(
        !help.contains("irrational roots were not examined"),
        "{help}"
    );
}

/// Inside a `--find-values omega` run, a value's search proposes other values of the other
/// fixed parameters alone, never of `omega`, whose values are the run's point; the ordinary
/// search at the same value still proposes one for `omega`. With no other parameter fixed
/// (the oscillator on a level set), the value's search proposes none.
#[test]
fn a_find_values_search_proposes_no_other_value_of_the_parameter_solved_for() {
    let degrees = "--momenta-degree 2 --positions-degree 2 --trig-degree 2";
    let space: Vec<&str> = (["--on", "p_theta = 1"].into_iter())
        .chain(degrees.split(' '))
        .collect();
    let run = |head: &[&str]| normalize(&superint_ok(&[head, &space[..]].concat()));
    let found = run(&[
        "search",
        HARMONIC_ROTOR,
        "--find-values",
        "omega",
        "--fix",
        "M=1,I=1,l=1",
    ]);
    assert!(
        found.contains("compare with other values (--fix M=2,I=3,l=5)"),
        "{found}"
    );
    assert!(!found.contains("omega="), "{found}");
    let plain = run(&["search", HARMONIC_ROTOR, "--fix", "M=1,I=1,l=1,omega=2"]);
    assert!(
        plain.contains("compare with other values (--fix M=2,omega=3,I=5,l=7)"),
        "{plain}"
    );
    let file = oscillator("on-a-level-set.toml", "(x^2 + a*y^2)/2");
    let args = values_of_a(
        &file,
        &["--on", "p_x^2 + x^2 = 1", "--positions-degree", "2"],
    );
    let alone = normalize(&superint_ok(&args));
    assert!(alone.contains("More integrals at a = 0"), "{alone}");
    assert!(!alone.contains("What is not lifted"), "{alone}");
}

/// The oscillator `x² + (a² + 2)y²`, isotropic at `a² = −1` and free in `y` at `a² = −2`:
/// the factor left, `a⁴ + 3a² + 2`, has no real root, and the text says so once with the
/// roots ruled out after it (`a² = 2`, `a² = −3/2`, where the frequencies are 1:2 and 2:1),
/// two of its blocks settled by exact determinants over Q, the others modulo the prime;
/// JSON counts no real root left.
#[test]
fn an_unexamined_factor_with_no_real_root_is_said_so_once_with_what_was_ruled_out() {
    let file = oscillator("complex.toml", "(x^2 + (a^2 + 2)*y^2)/2");
    let args = values_of_a(&file, &["--positions-degree", "2"]);
    let text = normalize(&superint_ok(&args)).replace('\n', " ");
    // One sentence on the roots left, then one on those ruled out.
    let said = "The determinants' other roots, those of a⁴ + 3a² + 2 (degree 4), are none of \
                them real: no other real value of a has more integrals in this space (the \
                complex ones were not examined). The remaining 4 roots (not rational; 2 real) \
                hold no more integrals in this space";
    assert!(text.contains(said), "{text}");
    assert!(
        text.contains("and, for 2 blocks, by exact determinants over Q)."),
        "{text}"
    );
    assert_eq!(text.matches("The determinants' other").count(), 1, "{text}");
    let json = superint_json(&args);
    let found = &json["exceptional_values"][0];
    assert_eq!(found["unexamined"], "a^4 + 3*a^2 + 2");
    assert_eq!(found["unexamined_real_roots"], 0);
    assert_eq!(found["ruled_out"], "2*a^4 - a^2 - 6");
    assert_eq!(found["ruled_out_real_roots"], 2);
    // The two blocks the text says were settled by exact determinants over Q.
    assert_eq!(found["ruled_out_exact_blocks"], 2);
}

/// Each value `--find-values` searches at is a `--fix`-style search, and JSON says where a
/// restatement of one not lifted holds, as its section's text does: the quartic potentials
/// with `b = 16`, whose `a = 12` restates `I3 = P` there alone; `I2 = 2 H`, restated at the
/// generic `a = 7` and at `a = 12`, is lifted through `2 H`, an integral for every value, and
/// says nothing more; at `a = 0`, `I2 = 2 H − 2 H_x`, lifted to `b`, holds at `a = 0` for
/// every `b` and says nothing more either.
#[test]
fn find_values_says_where_each_values_restatements_hold() {
    // As docs/system-files.md's JSON section runs it.
    let json: serde_json::Value = serde_json::from_str(&superint_ok_line(
        "search systems/quartic-potentials.toml --find-values a --fix b=16 \
         --momenta-degree 2 --positions-degree 5 --trig-degree 0 --format json",
    ))
    .expect("JSON");
    // Each restated line: its section's title, its label and where it holds.
    let title = |section: &serde_json::Value| {
        (json["sections"].as_array().expect("sections").iter())
            .find(|s| s["number"] == *section)
            .map_or(String::new(), |s| {
                s["title"].as_str().unwrap_or("").to_string()
            })
    };
    let restated: Vec<(String, String, Option<String>)> =
        (json["equations"].as_array().expect("equations").iter())
            .flat_map(|e| {
                let title = title(&e["section"]);
                (e["lines"].as_array().expect("lines").iter())
                    .filter(|l| !l["in_functions"].is_null())
                    .map(move |l| {
                        (
                            title.clone(),
                            l["lhs"].as_str().expect("a label").to_string(),
                            l["in_functions"]["holds_at"].as_str().map(String::from),
                        )
                    })
                    .collect::<Vec<_>>()
            })
            .collect();
    let at = |s: &str| Some(s.to_string());
    let expected = [
        ("At a = 7 (generic): Basis", "I2", None),
        ("At a = 0: Basis", "I2", None),
        ("At a = 0: Basis", "I3", None),
        ("At a = 12: Basis", "I2", None),
        ("At a = 12: Basis", "I3", at("a = 12, b = 16")),
    ]
    .map(|(t, l, h)| (t.to_string(), l.to_string(), h));
    assert_eq!(restated, expected, "{json}");
    // Each claim's statement and where it holds: `I2`, `2 H` at the fixed values, lifted
    // through `2 H`, for every `b` at each `a`; `I3 = P` at `a = 12, b = 16` alone, since
    // `{P, H} = 0` there only: its restatement stays at the fixed values.
    let claims: Vec<(String, String, String)> = (json["claims"].as_array().expect("claims"))
        .iter()
        .filter(|c| c["id"] == "I2" || c["id"] == "I3")
        .map(|c| {
            let text = |k: &str| c[k].as_str().unwrap_or("").to_string();
            (text("id"), text("ascii"), text("condition_ascii"))
        })
        .collect();
    let claim = |id: &str, ascii: &str, at: &str| (id.into(), ascii.into(), at.into());
    let expected = [
        claim("I2", "{2*H, H} = 0", "a = 7"),
        claim("I2", "{p_y^2 + 2*b*y^4, H} = 0", "a = 0"),
        claim("I3", "{p_x^2 + 2*x^4, H} = 0", "a = 0"),
        claim("I2", "{2*H, H} = 0", "a = 12"),
        claim(
            "I3",
            "{x*p_x*p_y - y*p_x^2 + 4*x^4*y + 8*x^2*y^3, H} = 0",
            "a = 12, b = 16",
        ),
    ];
    assert_eq!(claims, expected, "{json}");
}

/// Each value's `(value, functional rank)` in `found` (an `exceptional_values` entry), every
/// rank asserted exact, and the generic rank, as JSON writes them.
fn functional_ranks(found: &serde_json::Value) -> (u64, Vec<(String, u64)>) {
    let rank = |v: &serde_json::Value| {
        assert_eq!(v["functional_rank_exact"], true, "{v}");
        v["functional_rank"].as_u64().unwrap()
    };
    let values = (found["values"].as_array().unwrap().iter())
        .map(|v| (v["value"].as_str().unwrap().to_string(), rank(v)))
        .collect();
    (rank(&found["generic"]), values)
}

/// The oscillator `x² + a y²`, quadratic: at `a = 1` the isotropic `x p_y − y p_x` is
/// functionally new (rank 3 against 2 in four phase variables, the energies along `x` and `y`
/// generic); at `a = 0` the free `p_y` and `p_y²` are more integrals but no new function
/// (`p_y²/2` is the energy along `y`): rank 2, as generic.
#[test]
fn the_isotropic_oscillator_has_a_functionally_new_integral_and_the_free_one_none() {
    let file = oscillator("ranks.toml", "(x^2 + a*y^2)/2");
    let args = values_of_a(&file, &["--momenta-degree", "2", "--positions-degree", "2"]);
    let json = superint_json(&args);
    let (generic, values) = functional_ranks(&json["exceptional_values"][0]);
    assert_eq!(generic, 2);
    assert_eq!(values, [("0".to_string(), 2), ("1".to_string(), 3)]);
    let text = normalize(&superint_ok(&args)).replace('\n', " ");
    assert!(
        text.contains("no root): 3 integrals (section 2), of functional rank 2."),
        "{text}"
    );
    // Each value's rank said alone: the generic one is said once, above, and the line after
    // compares.
    assert!(
        text.contains("(section 4), of functional rank 2 and at a = 1,"),
        "{text}"
    );
    assert!(
        text.contains("(section 6), of functional rank 3."),
        "{text}"
    );
    assert!(!text.contains("at a generic"), "{text}");
    assert!(
        text.contains(
            "Functionally new integrals, a functional rank above the generic one, at a = 1."
        ),
        "{text}"
    );
}

/// Section 31's dipole rotor at momenta 3, positions 2, order 2: `ω = 0` has a fifth integral,
/// `2M H J`, which fits positions degree 2 only there, and no functionally new one: rank 2
/// (`H` and `J`), as at a generic `ω`, and the text says no value has any.
#[test]
fn dipole_rotor_at_omega_zero_has_more_integrals_but_none_functionally_new() {
    let args = [
        "search",
        "systems/dipole-rotor.toml",
        "--find-values",
        "omega",
        "--momenta-degree",
        "3",
        "--positions-degree",
        "2",
        "--trig-degree",
        "2",
    ];
    // Searched once (6 s in a debug build): the text says the ranks.
    let text = normalize(&superint_ok(&args)).replace('\n', " ");
    assert!(
        text.contains("no root): 4 integrals (section 2), of functional rank 2."),
        "{text}"
    );
    assert!(
        text.contains("More integrals at ω = 0, 5 integrals (section 4), of functional rank 2."),
        "{text}"
    );
    assert!(
        text.contains("No value of ω has functionally new integrals"),
        "{text}"
    );
}

/// On `p_θ = 1` the level set is a graph over the other phase variables, and the integrals
/// found hold no `p_θ`: the ranks are those on it, and the text says so. Of degree 1 in the
/// momenta, the positions and `θ`: for a generic `ω`, `1` and `L` (rank 1); at `ω = ±1`,
/// `(p_x ± i x)e^{∓iθ}`, `(p_y ± i y)e^{∓iθ}` too, four real functions of rank 4 (the most a
/// flow's integrals have on the five dimensions of the level set), functionally new; at
/// `ω = 0`, `p_x`, `p_y` and `L`, rank 3, new as well.
#[test]
fn harmonic_rotor_resonance_on_p_theta_one_has_functionally_new_integrals() {
    let find = [
        "search",
        HARMONIC_ROTOR,
        "--find-values",
        "omega",
        "--on",
        "p_theta = 1",
        "--fix",
        "M=1,I=1,l=1",
    ];
    let args = [&find[..], &crate::DEGREE_ONE].concat();
    let json = superint_json(&args);
    let (generic, values) = functional_ranks(&json["exceptional_values"][0]);
    assert_eq!(generic, 1);
    let expected = [("-1", 4), ("0", 3), ("1", 4)].map(|(v, r)| (v.to_string(), r));
    assert_eq!(values, expected);
    let text = normalize(&superint_ok(&args)).replace('\n', " ");
    assert!(
        text.contains(
            "The functional ranks below are those on the level set, a graph over the phase \
             variables but p_θ, which no integral found holds."
        ),
        "{text}"
    );
    assert!(
        text.contains("Functionally new integrals, a functional rank above the generic one, at ω = −1, ω = 0 and ω = 1."),
        "{text}"
    );
}

/// On `A = M·γ = 0`, whose leading monomial is no phase variable, each integral found is one
/// remainder modulo `A` of many functions equal on the level set, whose ranks in the whole
/// phase space differ (`A` itself is 0 there): the ranks shown are the remainders', said so
/// beside each rank as each search's section says it, and no value is called functionally
/// new, nor is it said that none is.
#[test]
fn on_the_area_level_the_remainders_ranks_name_no_value_functionally_new() {
    let find = "search systems/heavy-top.toml --find-values I3 --poisson-degree 3";
    let args = [&find.split(' ').collect::<Vec<_>>()[..], &["--on", "A = 0"]].concat();
    let text = normalize(&superint_ok(&args)).replace('\n', " ");
    assert!(
        text.contains(
            "The functional ranks below are those of the functions found in the whole phase \
             space, remainders modulo the level set's polynomial: they do not say which values \
             hold functionally new integrals on the level set."
        ),
        "{text}"
    );
    assert!(
        text.contains(
            "More integrals at I3 = 1/4, 4 integrals (section 4), of functional rank 3 in the \
             whole phase space, not on the level set and at I3 = 1,"
        ),
        "{text}"
    );
    assert!(
        text.contains("Functional rank: 3 in the whole phase space, not on the level set"),
        "{text}"
    );
    assert!(!text.contains("unctionally new integrals,"), "{text}");
    assert!(!text.contains("has functionally new integrals"), "{text}");
}

/// Each value's rank is taken once, as its section shows it, with the bounds a search's rank
/// has: the harmonic rotor on `p_θ = 1` at momenta, positions and order 3 has 50 integrals at
/// `ω = −1`, whose rank 4 has (50 − 4)(6 − 4) = 92 minors bordering its nonzero one; the
/// flow on the 5-dimensional level set bounds it at 4, in the summary as in the section (the
/// summary said `at least 4` when it took the rank again by the minors alone, at most 64).
#[test]
fn find_values_takes_each_values_rank_once_as_its_section_shows_it() {
    let find = "search systems/harmonic-rotor.toml --find-values omega --fix M=1,I=1,l=1 \
                --momenta-degree 3 --positions-degree 3 --trig-degree 3";
    let args = [
        &find.split_whitespace().collect::<Vec<_>>()[..],
        &["--on", "p_theta = 1"],
    ]
    .concat();
    let text = normalize(&superint_ok(&args)).replace('\n', " ");
    assert!(
        text.contains("at ω = −1, 50 integrals (section 10), of functional rank 4,"),
        "{text}"
    );
    let section = &text[text.find("10 At ω = −1: Search").expect("section 10")..];
    assert!(
        section.contains(
            "≤ 3: 50. Functional rank: 4, the most a flow on the 5-dimensional level set allows"
        ),
        "{text}"
    );
    let json = superint_json(&args);
    let minus_one = &json["exceptional_values"][0]["values"][3];
    assert_eq!(minus_one["value"], "-1");
    assert_eq!(minus_one["functional_rank"], 4);
    assert_eq!(minus_one["functional_rank_exact"], true);
}

/// Six free particles with the potential `k a b c d e f`, quadratic in the momenta and of no
/// degree in the positions: for a generic `k` the constant alone (rank 0); at `k = 0` the 28
/// polynomials in the momenta, whose rank 6 has (28 − 6)(12 − 6) = 132 minors bordering its
/// nonzero one, past `MAX_RANK_MINORS`: said to be at least 6, which is still above the
/// generic exact 0, so the value is functionally new.
#[test]
fn a_rank_past_the_bordering_minors_limit_is_a_lower_bound_and_still_decides() {
    let text = "name = \"six free\"\nhamiltonian = \"(p_a^2 + p_b^2 + p_c^2 + p_d^2 + p_e^2 \
                + p_f^2)/2 + k*a*b*c*d*e*f\"\n[phase_space]\ncoordinates = [\"a\", \"b\", \
                \"c\", \"d\", \"e\", \"f\"]\nparameters = [\"k\"]\n";
    let file = scratch_text("exceptional-values", "six-free.toml", text);
    let find = ["search", file.to_str().unwrap(), "--find-values", "k"];
    let args = [
        &find[..],
        &["--momenta-degree", "2", "--positions-degree", "0"],
    ]
    .concat();
    let json = superint_json(&args);
    let found = &json["exceptional_values"][0];
    assert_eq!(found["generic"]["functional_rank"], 0);
    assert_eq!(found["generic"]["functional_rank_exact"], true);
    let zero = &found["values"][0];
    assert_eq!(
        (&zero["value"], &zero["dimension"]),
        (&"0".into(), &28.into())
    );
    assert_eq!(zero["functional_rank"], 6);
    assert_eq!(zero["functional_rank_exact"], false);
    let text = normalize(&superint_ok(&args)).replace('\n', " ");
    for said in [
        "More integrals at k = 0, 28 integrals (section 4), of functional rank at least 6.",
        "Functionally new integrals, a functional rank above the generic one, at k = 0.",
        "said \"at least\" is certified from below alone: more than 64 minors border its \
         nonzero one.",
    ] {
        assert!(text.contains(said), "{said}\n{text}");
    }
}

/// The oscillator `(p_x² + p_y²)/2 + x²/2 + 3y²/(κ + 1)` with `κ + 1` declared, and `extra`
/// declared after it, as a scratch file.
fn oscillator_over_kappa_plus_one(name: &str, extra: &str) -> std::path::PathBuf {
    scratch_text(
        "exceptional-values",
        name,
        &format!(
            "name = \"t\"\nhamiltonian = \"(p_x^2 + p_y^2)/2 + x^2/2 + 3*y^2/(kappa + 1)\"\n\
             [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"kappa\", \"m\"]\n\
             denominators = [\"kappa + 1\"{extra}]\n"
        ),
    )
}

/// `search FILE --find-values m --when WHEN` at momenta and positions degree 3, then `extra`.
fn m_values<'a>(file: &'a str, when: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let find = ["search", file, "--find-values", "m", "--when", when];
    let degrees = ["--momenta-degree", "3", "--positions-degree", "3"];
    [&find[..], &degrees, extra].concat()
}

/// `--find-values m` under `κ = m − 1`, which gives `1/(κ + 1)` the value `1/m`: `H` holds `m`
/// through the condition, and `m = 0`, where it has no value, is no candidate. The frequency
/// of `y` is `√(6/m)` against `x`'s 1, so at degree 3 the resonances `1 : 3, 1 : 2, 1 : 1,
/// 2 : 1, 3 : 1` are `m = 6q²/p²`: `2/3, 3/2, 6, 24, 54`, by hand.
#[test]
fn find_values_under_a_condition_that_gives_a_denominator_the_parameter_takes_it() {
    let file = oscillator_over_kappa_plus_one("oscillator-kappa-m-minus-one.toml", "");
    let find = m_values(file.to_str().unwrap(), "kappa = m - 1", &[]);
    let found = superint_json(&find)["exceptional_values"][0].clone();
    assert_eq!(values_found(&found), ["2/3", "3/2", "6", "24", "54"]);
    assert_eq!(found["zero_left_out"], true);
    let text = normalize(&superint_ok(&find));
    assert!(
        text.contains("m = 0, a root of the determinants, is no value: H, with a negative power"),
        "{text}"
    );
}

/// `--find-values m` under `κ = m`, with `m + 1` declared too: the condition gives `1/(κ + 1)`
/// the value `1/(m + 1)`, so `H` divides by `m + 1` and `m = −1` is no value, even at
/// `--denominators-degree 0`, where the space has no powers of it. The frequency of `y` is
/// `√(6/(m + 1))`, so at degree 3 the values are `m = 6q²/p² − 1`: `−1/3, 1/2, 5, 23, 53`, by
/// hand.
#[test]
fn find_values_leaves_out_the_root_of_a_denominator_the_condition_makes_h_divide_by() {
    let file = oscillator_over_kappa_plus_one("oscillator-kappa-m.toml", ", \"m + 1\"");
    let file = file.to_str().unwrap();
    for degree in ["0", "2"] {
        let find = m_values(file, "kappa = m", &["--denominators-degree", degree]);
        let found = superint_json(&find)["exceptional_values"][0].clone();
        assert_eq!(values_found(&found), ["-1/3", "1/2", "5", "23", "53"]);
        assert_eq!(
            found["denominator_roots_left_out"],
            serde_json::json!(["-1"])
        );
    }
    let text = normalize(&superint_ok(&m_values(file, "kappa = m", &[])));
    assert!(
        text.contains(
            "m = −1, a root of the determinants, is no value: H divides by (m + 1), which is \
             zero there"
        ),
        "{text}"
    );
}
