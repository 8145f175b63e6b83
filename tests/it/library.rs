//! The library as a program uses it: a system built in code with names of its own, a loaded
//! system extended in code (functions, families, claims), the reports taken as structured
//! results, and the errors a program matches on.

use superint::prelude::*;

/// A rigid rotor (angle `phi`, inertia `J`) on the oscillator of frequency `k`, in code, with
/// its ladder function `A` and `Ω = p_φ/J`: the paper's harmonic rotor in other names.
fn own_rotor() -> LoadedSystem {
    let vars = Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .angle("phi")
        .momentum("p_x")
        .momentum("p_y")
        .momentum("p_phi")
        .parameter("k")
        .parameter("J")
        .build()
        .unwrap();
    let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y"), ("phi", "p_phi")]).unwrap();
    let h = Expr::parse(
        &vars,
        "(p_x^2 + p_y^2)/2 + k^2*(x^2 + y^2)/2 + p_phi^2/(2*J)",
    )
    .unwrap();
    let mut rotor = LoadedSystem::of_system(System::new("own rotor", space, h).unwrap());
    rotor
        .add_function("A", "A", "p_x + i*p_y + i*k*(x + i*y)")
        .unwrap();
    rotor.add_function("Omega", "Ω", "p_phi/J").unwrap();
    rotor
}

/// [`own_rotor`] with the family `R_{a,b} = A^a e^{−ibφ}`, `{R_{a,b}, H} = i(ak − bΩ) R_{a,b}`.
fn own_rotor_with_tower() -> LoadedSystem {
    let mut rotor = own_rotor();
    rotor
        .add_family(
            "R",
            "R",
            ["a", "b"],
            "A^a*exp(-i*b*phi)",
            Some("i*(a*k - b*Omega)"),
        )
        .unwrap();
    rotor
}

fn harmonic_rotor_file() -> LoadedSystem {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/systems/harmonic-rotor.toml");
    load_system_file(path, &LimitsOverride::default()).unwrap()
}

/// `{R_{a,b}, H} = i(ak − bΩ) R_{a,b}` for `R_{a,b} = A^a e^{−ibφ}`, a family added in code to
/// a system built in code, in names that are not the paper's: checked for `1 ≤ a, b ≤ 3` and
/// proved for all `a, b`; with the sign of `bΩ` flipped, every bracket fails and nothing is
/// proved.
#[test]
fn family_tower_in_own_names() {
    let mut rotor = own_rotor_with_tower();
    rotor
        .add_family(
            "S",
            "S",
            ["a", "b"],
            "A^a*exp(-i*b*phi)",
            Some("i*(a*k + b*Omega)"),
        )
        .unwrap();
    let report = family_tower_report(&rotor, Some("R"), 3, None).unwrap();
    let tower = report.tower().unwrap();
    assert_eq!((tower.checked, tower.failures.len()), (9, 0));
    let proof = report.proof().unwrap();
    assert!(proof.holds(), "{proof:?}");
    assert!(report.all_proved());
    // R_{a,b} is a product of powers; its instance is A^a e^{−ibφ} itself.
    assert_eq!(
        rotor.parse("R_{2,3}").unwrap(),
        rotor.parse("A^2*exp(-3*i*phi)").unwrap()
    );

    let wrong = family_tower_report(&rotor, Some("S"), 2, None).unwrap();
    assert_eq!(
        wrong.tower().unwrap().failures,
        [(1, 1), (1, 2), (2, 1), (2, 2)]
    );
    assert!(!wrong.proof().unwrap().holds());
    assert!(!wrong.all_proved());
}

/// Without a family named, every family with an eigenvalue has its tower, in order, each in
/// its own section: of the file [`crate::TWO_TOWERS`], `K` (eigenvalue right) is proved and
/// `W` (eigenvalue wrong) refuted, its proof failing at `{p_x − ix, H}`, and `P` (none) is
/// passed over; the progress counts the eight brackets of both together. A list names them
/// in its order.
#[test]
fn family_towers_of_every_family_each_in_its_section() {
    let file = load_system_text("two.toml", crate::TWO_TOWERS, &LimitsOverride::default()).unwrap();
    let mut seen = Vec::new();
    let report =
        family_tower_report_with_progress(&file, None, 2, None, &mut |d, t| seen.push((d, t)))
            .unwrap();
    assert_eq!(seen, (1..=8).map(|d| (d, 8)).collect::<Vec<_>>());
    assert_eq!(report.sections.len(), 2);
    let towers: Vec<_> = report
        .towers()
        .map(|t| (t.claim.id.as_str(), t.checked, t.failures.len()))
        .collect();
    assert_eq!(towers, [("K-tower", 4, 0), ("W-tower", 4, 4)]);
    let proofs: Vec<bool> = report.proofs().map(|p| p.holds()).collect();
    assert_eq!(proofs, [true, false]);
    assert_eq!(
        report.proofs().nth(1).unwrap().facts[1]
            .found_statement
            .as_deref(),
        Some("{p_x − ix, H} = −i (p_x − ix)")
    );
    assert_eq!(report.tower().unwrap().claim.id, "K-tower");
    assert!(!report.all_proved());
    assert_eq!(report.claims().len(), 4);

    let listed = family_tower_report(&file, Some("W,K"), 1, None).unwrap();
    let ids: Vec<_> = listed.towers().map(|t| t.claim.id.as_str()).collect();
    assert_eq!(ids, ["W-tower", "K-tower"]);
    let err = family_tower_report(&file, Some("K,P"), 1, None).unwrap_err();
    assert_eq!(err.message, "the family 'P' declares no eigenvalue");
}

/// A tower of bound `N < 1` checks no bracket (`1 ≤ a, b ≤ N` holds no pair), and says so:
/// `N = −3` reported nine brackets checked, none of which was.
#[test]
fn a_tower_below_one_checks_nothing() {
    let rotor = own_rotor_with_tower();
    for max in [0, -3] {
        let mut calls = 0;
        let report =
            family_tower_report_with_progress(&rotor, Some("R"), max, None, &mut |_, _| calls += 1)
                .unwrap();
        let tower = report.tower().unwrap();
        assert_eq!(
            (tower.checked, tower.failures.len(), calls),
            (0, 0, 0),
            "{max}"
        );
    }
}

/// The engine's tower of the paper's rotor reports `max²` brackets to `progress` and none
/// below 1; of a bound past 3·10⁹ it stops at its first bracket's error (an unknown ladder),
/// where `max * max` overflowed first (a panic in a debug build).
#[test]
fn the_engines_tower_counts_its_pairs_without_overflow() {
    let rotor = systems::harmonic_rotor();
    let mut totals = Vec::new();
    let tower = check_tower(&rotor, "Z", 2, &mut |done, total| {
        totals.push((done, total))
    })
    .unwrap();
    assert_eq!((tower.checked, tower.failures.len()), (4, 0));
    assert_eq!(totals, [(1, 4), (2, 4), (3, 4), (4, 4)]);
    let mut calls = 0;
    let none = check_tower(&rotor, "Z", -3, &mut |_, _| calls += 1).unwrap();
    assert_eq!((none.checked, calls), (0, 0));
    for max in [i64::MAX, 1 << 32] {
        let err = check_tower(&rotor, "W", max, &mut |_, _| {}).unwrap_err();
        assert_eq!(err, EngineError::UnknownName("W".into()), "{max}");
    }
}

/// `K_{m,n} = Z^m e^{−inθ}` for any `n`: `n = −2` gives `Z e^{2iθ}`, and `n = i64::MIN`, whose
/// negation overflowed (a panic in a debug build), is refused by the limit on an angle's
/// order, as `n = i64::MAX` is.
#[test]
fn a_resonant_function_of_any_order_is_formed_or_refused() {
    let rotor = systems::harmonic_rotor();
    let k = rotor.resonant("Z", 1, -2).unwrap().k;
    assert_eq!(k, rotor.parse("Z*exp(2*i*theta)").unwrap());
    for n in [i64::MIN, i64::MAX] {
        let err = rotor.resonant("Z", 1, n).map(|_| ()).unwrap_err();
        assert!(
            matches!(
                &err,
                EngineError::Algebra(AlgebraError::OrderTooLarge { order, .. })
                    if *order == n.unsigned_abs()
            ),
            "{n}: {err:?}"
        );
        assert!(err.is_limit());
    }
}

/// The tower at a resonance: `{R_{1,1}, H} = 0` at `p_φ = Jk`, a claim added in code and
/// proved; `{R_{2,1}, H} = 0` there is refuted, as it says it expects, with the residual
/// `{R_{2,1}, H} = ik R_{2,1}` at `Ω = k`.
#[test]
fn claims_added_in_code_at_a_resonance() {
    let mut rotor = own_rotor();
    rotor
        .add_family("R", "R", ["a", "b"], "A^a*exp(-i*b*phi)", None)
        .unwrap();
    rotor
        .add_claim("resonant", "{R_{1,1}, H} = 0", Some("p_phi = J*k"))
        .unwrap();
    rotor
        .add_claim("off", "{R_{2,1}, H} = 0", Some("p_phi = J*k"))
        .unwrap()
        .expect = Expect::Refuted;
    let report = check_report([&rotor]).unwrap();
    assert!(report.all_as_expected());
    assert_eq!(
        report.claim_ids(),
        [("resonant".to_string(), true), ("off".to_string(), false)]
    );
    let off = report.claims()[1];
    assert_eq!(
        off.residual,
        Some(rotor.parse("i*k*A^2*exp(-i*phi)").unwrap())
    );
}

/// Functions, families and claims added in code to a loaded file are read like the file's own:
/// the su(2) Casimir `4G1² + G2² + ω²L² = (F1 − F2)²` (C10) as a function, the family
/// `Z^m Z̄^n` with `{N_{m,n}, H} = i(m − n)ω N_{m,n}`, its tower, and a rank claim; the file's
/// own claims still hold.
#[test]
fn a_loaded_file_extended_in_code() {
    let mut rotor = harmonic_rotor_file();
    let claims = rotor.claims().len();
    rotor
        .add_function("C", "C", "4*G1^2 + G2^2 + omega^2*L^2")
        .unwrap();
    rotor
        .add_family("N", "N", ["m", "n"], "Z^m*Zbar^n", Some("i*(m - n)*omega"))
        .unwrap();
    rotor.add_claim("casimir", "C = (F1 - F2)^2", None).unwrap();
    rotor
        .add_claim("diagonal", "{N_{2,2}, H} = 0", None)
        .unwrap();
    rotor
        .add_claim("rank", "rank(F1, F2, L, C) = 3", None)
        .unwrap();
    rotor
        .add_claim("five", "rank(F1, F2, G1, G2, P_1_1) = 5", None)
        .unwrap();
    assert_eq!(rotor.claims().len(), claims + 4);
    let report = check_report([&rotor]).unwrap();
    assert!(report.all_as_expected());
    assert_eq!(report.claims().len(), claims + 4);
    let tower = family_tower_report(&rotor, Some("N"), 3, None).unwrap();
    assert!(tower.all_proved());
    assert!(tower.proof().unwrap().holds());
}

/// An integral a search found, held as an `Expr`, becomes a function of a loaded file
/// without being written out and read back (`add_function_expr`): at the resonance `Ω = ω`
/// each integral of degree 1 of the harmonic rotor is added under a name of its own and
/// claimed conserved there, and a family built on the first one has it in its instances.
/// The search is the file's (`file_search_report`, in the prelude), and a name run together
/// with a function added so is warned of as with the file's own (`Warning`, in the prelude).
/// A name taken, a display that prints as another name, and a value of another variable set
/// are refused, and leave the system as it was.
#[test]
fn a_found_integral_becomes_a_function_of_the_file() {
    let mut rotor = harmonic_rotor_file();
    let resonance = rotor.condition("p_theta = I*omega").unwrap();
    let options = SearchOptions::new(
        SearchSpace::default()
            .momenta_degree(1)
            .positions_degree(1)
            .trig_degree(1),
    )
    .when(resonance);
    let (searched, found) = file_search_report(&rotor, &options, Caller::Program).unwrap();
    assert!(searched.all_proved());
    let integrals: Vec<Expr> = found
        .basis
        .iter()
        .map(|i| i.expr().clone())
        .filter(|e| !e.is_constant())
        .collect();
    assert!(integrals.len() >= 4, "{integrals:?}");
    let functions = rotor.system().functions().len();
    for (k, e) in integrals.iter().enumerate() {
        let name = format!("I{k}");
        rotor.add_function_expr(&name, &name, e.clone()).unwrap();
        assert_eq!(rotor.parse(&name).unwrap(), *e);
        rotor
            .add_claim(
                &name,
                &format!("{{{name}, H}} = 0"),
                Some("p_theta = I*omega"),
            )
            .unwrap();
    }
    assert_eq!(
        rotor.system().functions().len(),
        functions + integrals.len()
    );
    rotor
        .add_family("T", "T", ["m", "n"], "I0^m*exp(i*n*theta)", None)
        .unwrap();
    assert_eq!(
        rotor.parse("T_2_1").unwrap(),
        rotor.parse("I0^2*exp(i*theta)").unwrap()
    );
    // A name run together with one of them is in doubt, as with a function of the file.
    assert_eq!(rotor.parse("I0x").unwrap(), rotor.parse("I0*x").unwrap());
    let warnings: Vec<Warning> = rotor.warnings();
    assert_eq!(warnings.len(), 1);
    assert!(
        warnings[0]
            .message
            .starts_with("'I0x' is read as the product"),
        "{}",
        warnings[0]
    );
    let report = check_report([&rotor]).unwrap();
    assert!(report.all_as_expected());
    let ours = report
        .claims()
        .into_iter()
        .filter(|c| c.id.starts_with('I'));
    assert_eq!(ours.filter(|c| c.proved).count(), integrals.len());

    // Refused, each leaving the functions as they were.
    let x = rotor.parse("x").unwrap();
    let taken = rotor.add_function_expr("L", "L", x.clone()).unwrap_err();
    assert_eq!(taken.kind, ErrorKind::Name);
    assert_eq!(taken.message, "'L' is already a function of the system");
    let alike = rotor.add_function_expr("G_1", "G_1", x).unwrap_err();
    assert_eq!(alike.kind, ErrorKind::Name, "{alike}");
    assert!(alike.message.contains("as the function G1 does"), "{alike}");
    let other = Vars::builder().coordinate("x").build().unwrap();
    let foreign = Expr::parse(&other, "x").unwrap();
    let mismatch = rotor.add_function_expr("X", "X", foreign).unwrap_err();
    assert_eq!(mismatch.kind, ErrorKind::Expression);
    assert!(
        mismatch.message.contains("another variable set"),
        "{mismatch}"
    );
    assert_eq!(
        rotor.system().functions().len(),
        functions + integrals.len()
    );
    assert!(rotor.parse("X").is_err());
}

/// A family whose eigenvalue does not read is refused at its place (line 2 of `<family W>`,
/// under the misspelt name), and leaves the system as it was: another family then takes its
/// place, and its instances are its own, not the refused one's.
#[test]
fn a_refused_family_leaves_no_trace() {
    let mut rotor = harmonic_rotor_file();
    let families = rotor.families().len();
    let err = rotor
        .add_family("W", "W", ["m", "n"], "Z^m*Zbar^n", Some("i*(m - n)*omegaa"))
        .unwrap_err();
    assert_eq!(err.kind, ErrorKind::Expression);
    assert_eq!(err.origin, "<family W>");
    assert_eq!(err.line_col(), Some((2, 11)));
    assert!(
        err.to_string()
            .starts_with("<family W>:2:11: unknown name 'omegaa'"),
        "{err}"
    );
    assert_eq!(rotor.families().len(), families);
    assert!(rotor.family("W").is_none());
    rotor
        .add_family("W", "W", ["m", "n"], "Zbar^m*Z^n", None)
        .unwrap();
    assert_eq!(
        rotor.parse("W_1_1").unwrap(),
        rotor.parse("Zbar*Z").unwrap()
    );
    assert_eq!(
        rotor.parse("W_2_1").unwrap(),
        rotor.parse("Zbar^2*Z").unwrap()
    );
}

/// One rule for names: a name a variable set refuses ([`trigpoly::BadName`]) is refused by the
/// file loader, for a parameter of a file and for a function added in code, with the same
/// reason; the loader refuses `H` and `rank` besides, which a variable set takes.
#[test]
fn the_loaders_names_are_the_variable_sets_and_h_and_rank() {
    let file = |parameter: &str| {
        let text = format!(
            "name = \"oscillator\"\nhamiltonian = \"p_x^2/2 + x^2/2\"\n[phase_space]\n\
             coordinates = [\"x\"]\nparameters = [{parameter:?}]\n"
        );
        load_system_text("oscillator.toml", &text, &LimitsOverride::default())
    };
    file("k").expect("a good name loads");
    let mut rotor = harmonic_rotor_file();
    for name in ["2Q", "a b", "a_", "_a", "a__b", "θé", "x²"] {
        let why = trigpoly::BadName::of(name).expect(name).to_string();
        let vars = Vars::builder().coordinate(name).build().map(|_| ());
        assert_eq!(
            vars.unwrap_err().to_string(),
            format!("{name:?} cannot name a variable: {why}"),
            "{name:?}"
        );
        let loaded = file(name).map(|_| ()).unwrap_err().message;
        let added = rotor.add_function(name, "F", "x").unwrap_err().message;
        let (as_parameter, as_function) = match name.contains('_') {
            true => [0; 2]
                .map(|_| format!("'{name}' cannot be a name: {why}"))
                .into(),
            false => (
                format!("'{name}' cannot name a parameter: {why}"),
                format!("'{name}' cannot name a function: {why}"),
            ),
        };
        assert_eq!((loaded, added), (as_parameter, as_function), "{name:?}");
    }
    // A name past 80 characters (a line pasted where a name belongs) is refused, and shown by
    // its start and its length; one of 80 is taken.
    let long = "a".repeat(81);
    let why = "a name has at most 80 characters";
    let vars = Vars::builder().coordinate(&long).build().map(|_| ());
    let start = "a".repeat(40);
    assert_eq!(
        vars.unwrap_err().to_string(),
        format!("{start:?}…, 81 characters long, cannot name a variable: {why}")
    );
    let quoted = format!("'{start}…', 81 characters long");
    assert_eq!(
        file(&long).map(|_| ()).unwrap_err().message,
        format!("{quoted} cannot name a parameter: {why}")
    );
    assert_eq!(
        rotor.add_function(&long, "F", "x").unwrap_err().message,
        format!("{quoted} cannot name a function: {why}")
    );
    file(&"a".repeat(80)).expect("a name of 80 characters loads");
    for (name, why) in [
        (
            "cos",
            "'cos' is reserved (i, cos, sin, exp, conj, re, im, sqrt, rank)",
        ),
        (
            "rank",
            "'rank' is reserved (i, cos, sin, exp, conj, re, im, sqrt, rank)",
        ),
        ("H", "'H' is reserved for the Hamiltonian"),
    ] {
        assert_eq!(file(name).map(|_| ()).unwrap_err().message, why);
        let taken = Vars::builder().coordinate(name).build().map(|_| ());
        assert_eq!(taken.is_ok(), name != "cos", "{name}");
    }
}

/// A name the system already has, in any spelling, a reserved one, or a malformed index is
/// refused with what it is.
#[test]
fn names_already_taken_are_refused() {
    let mut rotor = harmonic_rotor_file();
    let refused = |result: Result<(), FileError>| {
        let err = result.unwrap_err();
        (err.kind, err.message)
    };
    assert_eq!(
        refused(rotor.add_function("L", "L", "x")),
        (
            ErrorKind::Name,
            "'L' is already a function of the system".into()
        )
    );
    assert_eq!(
        refused(rotor.add_function("ω", "ω", "x")),
        (
            ErrorKind::Name,
            "'ω' is already a parameter of the system".into()
        )
    );
    assert_eq!(
        refused(rotor.add_function("K", "K", "x")),
        (
            ErrorKind::Name,
            "'K' is already a family of the system".into()
        )
    );
    assert_eq!(
        refused(rotor.add_function("cos", "cos", "x")).1,
        "'cos' is reserved (i, cos, sin, exp, conj, re, im, sqrt, rank)"
    );
    assert_eq!(
        refused(rotor.add_function("F3", "F^3", "x")).1,
        "a display name is letters, digits, primes (G1'), a bar (Z̄), subscripts (A_x), spaces \
         and parentheses: '^' is markup in Markdown or LaTeX"
    );
    assert_eq!(
        refused(rotor.add_family("T", "T", ["x", "n"], "x^n", None)),
        (
            ErrorKind::Family,
            "the index 'x' is already a coordinate of the system".into()
        )
    );
    assert_eq!(
        refused(rotor.add_family("T", "T", ["m", "m"], "Z^m", None)).1,
        "the two indices are both named 'm'"
    );
}

/// A claim given in code is read at once (its form and condition) and computed when checked,
/// as a file's is; a slip in it is at line 1 of `<claim ID>`, a slip in its condition at
/// line 2, and a claim refused when read is not added.
#[test]
fn claim_errors_point_into_the_text_given() {
    let mut rotor = harmonic_rotor_file();
    let claims = rotor.claims().len();
    // Read now, refused when computed: added to a copy, which fails its check.
    let mut copy = rotor.clone();
    let spec = copy.add_claim("g3", "{L, G1} = -G3", None).unwrap().clone();
    let err = copy.check_claim(&spec).unwrap_err();
    assert_eq!(
        (err.kind, err.line_col()),
        (ErrorKind::Expression, Some((1, 12)))
    );
    assert!(
        err.to_string()
            .starts_with("<claim g3>:1:12: unknown name 'G3'"),
        "{err}"
    );
    let err = rotor
        .add_claim("c", "{K_1_1, H} = 0", Some("p_theta = I*omegaa"))
        .unwrap_err();
    assert_eq!(
        (err.kind, err.line_col()),
        (ErrorKind::Expression, Some((2, 13)))
    );
    assert_eq!(err.origin, "<claim c>");
    let err = rotor.add_claim("c", "{L, G1}", None).unwrap_err();
    assert_eq!(err.kind, ErrorKind::Claim);
    let err = rotor.add_claim(" ", "L = L", None).unwrap_err();
    assert_eq!(err.message, "a claim's id is empty");
    // A refused id does not name the text either: `<claim a\nb>` broke the message's line.
    let err = rotor.add_claim("a\nb", "L = L", None).unwrap_err();
    assert_eq!(
        (err.kind, err.origin.as_str(), err.message.as_str()),
        (
            ErrorKind::Claim,
            "<claim>",
            "a claim's id is shown in reports as written: U+000A is an invisible or control \
             character"
        )
    );
    assert_eq!(rotor.claims().len(), claims);
}

/// `?` takes an engine error into a `FileError`: a term limit is of kind `limit` (with the
/// hint to raise it), an unknown name of kind `engine`; neither has a place in a text.
#[test]
fn engine_errors_become_file_errors() {
    fn expand(rotor: &LoadedSystem, power: i64) -> Result<usize, FileError> {
        let z = rotor.system().get("Z")?;
        Ok(z.checked_pow(power).map_err(EngineError::from)?.len())
    }
    let mut rotor = harmonic_rotor_file();
    assert_eq!(expand(&rotor, 2).unwrap(), 10);
    rotor = {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/systems/harmonic-rotor.toml"
        ))
        .unwrap();
        let small = LimitsOverride::default().max_terms(50);
        load_system_text("harmonic-rotor.toml", &text, &small).unwrap()
    };
    let err = expand(&rotor, 8).unwrap_err();
    assert_eq!((err.kind, err.location), (ErrorKind::Limit, None));
    assert!(err.hint.is_some());
    let err = FileError::from(rotor.system().rank(&["F1", "nope"]).unwrap_err());
    assert_eq!(
        (err.kind, err.origin.as_str()),
        (ErrorKind::Engine, "<program>")
    );
    assert_eq!(err.kind.to_string(), "engine");
}

/// A program's tower under a condition it refuses before any bracket (a phase variable set,
/// or `J = 0` where H divides by `J`) keeps the engine's refusal (`FileError::engine`), so
/// that `condition_refusal` places it in the condition's text as a closure's is placed (it
/// had only the message, and nothing to place).
#[test]
fn a_programs_tower_keeps_a_refused_condition_to_place() {
    let towered = own_rotor_with_tower();
    for (text, var, column) in [("J = 0", "J", 5), ("p_phi = J*k", "p_phi", 9)] {
        let condition = towered.condition(text).unwrap();
        let err = family_tower_report(&towered, Some("R"), 2, Some(&condition)).unwrap_err();
        assert_eq!(
            (err.kind, err.location.is_none()),
            (ErrorKind::Condition, true)
        );
        let Some(refused @ EngineError::RefusedCondition { var: set, .. }) = err.engine.as_deref()
        else {
            panic!("the tower's error keeps the engine's refusal: {err:?}");
        };
        assert_eq!(*set, towered.system().vars().lookup(var).unwrap());
        let placed = towered.condition_refusal(text, refused);
        assert_eq!(placed.line_col(), Some((1, column)), "{placed}");
        assert_eq!(placed.message, err.message);
    }
}

/// A program's closure under a condition the engine refuses (`M = 0`, which `G1` divides
/// by) is placed in the condition's text as its search is: the closure's error keeps the
/// engine's `RefusedCondition` (`FileError::engine`), which `condition_refusal` shows at
/// `M`'s value, as it shows the search's (the closure's error had only the message, kind
/// Engine, and no variable to place).
#[test]
fn a_programs_closure_places_a_refused_condition_as_its_search_does() {
    let rotor = harmonic_rotor_file();
    let text = "omega = 1, M = 0";
    let condition = rotor.condition(text).unwrap();
    let options = ClosureOptions::new(2).when(condition.clone());
    let err =
        file_closure_report(&rotor, &["L", "G1", "G2"], &options, Caller::Program).unwrap_err();
    assert_eq!(
        (err.kind, err.location.is_none()),
        (ErrorKind::Engine, true)
    );
    let m = rotor.system().vars().lookup("M").unwrap();
    let Some(EngineError::RefusedCondition { var, .. }) = err.engine.as_deref() else {
        panic!("the closure's error keeps the engine's refusal: {err:?}");
    };
    assert_eq!(*var, m);
    let placed = rotor.condition_refusal(text, err.engine.as_deref().unwrap());
    assert_eq!(
        (placed.kind, placed.line_col()),
        (ErrorKind::Condition, Some((1, 16)))
    );
    assert!(
        placed.to_string().starts_with(
            "<condition>:1:16: the condition sets M = 0, but the generator G1 divides by M"
        ),
        "{placed}"
    );
    let space = SearchSpace::default().momenta_degree(1).positions_degree(1);
    let search = SearchOptions::new(space).when(condition);
    let Err(e) = file_search_report(&rotor, &search, Caller::Program) else {
        panic!("the search refuses M = 0");
    };
    assert!(matches!(e, EngineError::RefusedCondition { var, .. } if var == m));
    let searched = rotor.condition_refusal(text, &e);
    assert_eq!(searched.line_col(), placed.line_col());
}

/// A degree limit of 0 given to the loader is refused as such (a file's `max_degree = 0`
/// is): reading the Hamiltonian under it panicked. So are a term limit and a work limit of 0,
/// which a file's `[limits]` and the command line refuse too: the first stopped at the
/// Hamiltonian with "more than 0 terms", the second was taken and the claims checked.
#[test]
fn a_limit_out_of_its_range_is_refused_by_the_loader() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/systems/harmonic-rotor.toml"
    ))
    .unwrap();
    let zeros = [
        ("max_degree", LimitsOverride::default().max_degree(0)),
        ("max_terms", LimitsOverride::default().max_terms(0)),
        (
            "max_term_products",
            LimitsOverride::default().max_term_products(0),
        ),
    ];
    for (name, zero) in zeros {
        let err = load_system_text("harmonic-rotor.toml", &text, &zero).unwrap_err();
        assert!(err.message.contains(&format!("sets {name} to 0")), "{err}");
        assert_eq!((err.kind, err.location), (ErrorKind::Schema, None));
    }
    // A degree past the ceiling that a file and --max-degree refuse is refused too, not
    // lowered to it.
    let past = LimitsOverride::default().max_degree(32_768);
    let err = load_system_text("harmonic-rotor.toml", &text, &past).unwrap_err();
    assert_eq!(
        err.message,
        "the LimitsOverride given to the loader sets max_degree to 32768; it must be between 1 \
         and 32767"
    );
    // One is enough: the smallest of each loads.
    let ones = LimitsOverride::default()
        .max_terms(1)
        .max_degree(1)
        .max_term_products(1);
    assert_eq!(
        load_system_text("harmonic-rotor.toml", &text, &ones)
            .map_err(|e| e.kind)
            .err(),
        Some(ErrorKind::Limit)
    );
}

/// The value types a program compares can key a map or a set too: formats, styles,
/// expectations, error kinds, a report's claim outcomes and kinds, outcomes (with their
/// residuals), conditions, function names, claims and resonant functions.
#[test]
fn value_types_are_hashable() {
    use std::collections::HashSet;
    fn distinct<T: std::hash::Hash + Eq>(values: impl IntoIterator<Item = T>) -> usize {
        values.into_iter().collect::<HashSet<T>>().len()
    }
    assert_eq!(distinct(Format::ALL.into_iter().chain([Format::Json])), 4);
    assert_eq!(
        distinct([Style::Unicode, Style::Latex, Style::Ascii, Style::Latex]),
        3
    );
    assert_eq!(
        distinct([Expect::Proved, Expect::Refuted, Expect::default()]),
        2
    );
    assert_eq!(
        distinct([ErrorKind::Name, ErrorKind::Schema, ErrorKind::Name]),
        2
    );
    let claim_outcomes = [
        ClaimOutcome::Proved,
        ClaimOutcome::Refuted,
        ClaimOutcome::Undecided,
        ClaimOutcome::Refuted,
    ];
    assert_eq!(distinct(claim_outcomes), 3);
    assert_eq!(
        distinct([
            ClaimKind::Identity,
            ClaimKind::Nonvanishing,
            ClaimKind::Identity
        ]),
        2
    );
    let rotor = systems::harmonic_rotor();
    let outcome = |lhs: &str, rhs: &str| {
        let claim = Claim::new(
            "c",
            "",
            rotor.parse(lhs).unwrap(),
            rotor.parse(rhs).unwrap(),
        );
        claim.check().unwrap().outcome
    };
    let outcomes = [
        outcome("{L, G1}", "-G2"),
        outcome("{L, G2}", "4*G1"),
        outcome("{L, G1}", "G2"),
        outcome("{L, G1}", "G2"),
        outcome("{L, G1}", "0"),
    ];
    assert_eq!(distinct(outcomes), 3);
    let resonances = [(1, 1), (2, 1), (1, 1)].map(|(m, n)| rotor.resonance(m, n).unwrap());
    assert_eq!(distinct(resonances), 2);
    let name = |name: &str, display: &str| FunctionName {
        name: name.into(),
        display: display.into(),
    };
    assert_eq!(
        distinct([name("G1p", "G1'"), name("G1p", "G1'"), name("G1", "G1")]),
        2
    );
    // Claims (the same sides under another condition differ) and resonant functions.
    let claim = |lhs: &str| {
        Claim::new(
            "c",
            lhs,
            rotor.parse(lhs).unwrap(),
            rotor.parse("0").unwrap(),
        )
    };
    let at = rotor.resonance(1, 1).unwrap();
    let claims = [
        claim("{Z*exp(-i*theta), H}"),
        claim("{Z*exp(-i*theta), H}"),
        claim("{Z*exp(-i*theta), H}").when(at.clone()),
        claim("{Z*exp(-i*theta), H}").when(at),
        claim("{L, H}"),
    ];
    assert_eq!(distinct(claims), 3);
    let resonant = [(1, 1), (2, 1), (1, 1)].map(|(m, n)| rotor.resonant("Z", m, n).unwrap());
    assert_eq!(distinct(resonant), 2);
}

/// A condition belongs to one system: values and a variable of two variable sets, or a
/// condition used with another system's functions (in a claim, a flow, a search, a
/// closure), are refused as a mismatch of sets, where each panicked on a handle.
#[test]
fn a_condition_of_another_system_is_refused() {
    fn mismatch<T>(result: Result<T, EngineError>) -> bool {
        matches!(
            result,
            Err(EngineError::Algebra(AlgebraError::VarSetMismatch))
        )
    }
    let rotor = systems::harmonic_rotor();
    let gravity = systems::gravity_rotor();
    let g = gravity.var("g");
    assert!(mismatch(Condition::all(
        "g = 1",
        vec![(g, Expr::one(rotor.vars()))]
    )));
    let x = rotor.var("x");
    assert!(mismatch(Condition::all(
        "x = g",
        vec![(x, gravity.parse("g").unwrap())]
    )));
    let at_g = Condition::all("g = 1", vec![(g, Expr::one(gravity.vars()))]).unwrap();
    let x = rotor.parse("x").unwrap();
    let claim = Claim::new("c", "x = x", x.clone(), x.clone()).when(at_g.clone());
    assert!(mismatch(claim.check()));
    assert!(mismatch(rotor.flow_when(&x, &at_g)));
    let options = SearchOptions::new(SearchSpace::default().momenta_degree(1).positions_degree(1))
        .when(at_g.clone());
    assert!(mismatch(search(&rotor, &options)));
    let options = ClosureOptions::new(1).when(at_g);
    assert!(mismatch(closure(&rotor, &["L"], &options)));
}

/// The closure of generators that are not functions of the system, named by the program
/// (`closure_of`, in the prelude beside `closure` of the system's names): at the resonance
/// `Ω = ω`, `F2`, `P_{1,1}` and `Q_{1,1}` close, in the same brackets and relations as
/// `closure` finds once the system names them.
#[test]
fn a_closure_of_functions_the_system_does_not_name() {
    let rotor = systems::harmonic_rotor();
    let resonance = rotor.resonance(1, 1).unwrap();
    let z = rotor.resonant("Z", 1, 1).unwrap();
    let generators = [
        NamedFunction::new("F2", "F2", rotor.get("F2").unwrap().clone()),
        NamedFunction::new("P", "P", z.p.clone()),
        NamedFunction::new("Q", "Q", z.q.clone()),
    ];
    let options = ClosureOptions::new(2).when(resonance);
    let of = closure_of(&rotor, &generators, &options).unwrap();
    assert!(of.closes());
    let mut named = rotor.clone();
    named.define("P", "P", z.p).unwrap();
    named.define("Q", "Q", z.q).unwrap();
    let by_name = closure(&named, &["F2", "P", "Q"], &options).unwrap();
    for (a, b) in [(0, 1), (0, 2), (1, 2)] {
        assert_eq!(of.render_bracket(a, b), by_name.render_bracket(a, b));
    }
    assert_eq!(of.relations, by_name.relations);
}

/// A search's integrals, a rank's certificate, a bracket table and a tower's proof compare
/// with `==`: the same search twice finds equal bases, one of a larger space holds the
/// smaller's integrals and more, and the rank of the same functions twice has equal
/// certificates (`F1, F2, G1, G2, L`: rank 4, the Casimir ties them), of fewer functions
/// another; the su(2) table twice is one table, in another order another, and the proof for
/// all `m, n` of `K_{m,n}` twice is one proof, that of `K'` another (the table and the proof
/// had no `PartialEq`).
#[test]
fn integrals_and_rank_certificates_compare() {
    let rotor = systems::harmonic_rotor();
    let resonance = rotor.resonance(1, 1).unwrap();
    let found = |degree| {
        let space = SearchSpace::default()
            .momenta_degree(degree)
            .positions_degree(degree)
            .trig_degree(1);
        search(&rotor, &SearchOptions::new(space).when(resonance.clone()))
            .unwrap()
            .basis
    };
    let (small, again, large) = (found(1), found(1), found(2));
    assert_eq!(small, again);
    assert_eq!(small.len(), 6);
    assert!(large.len() > small.len());
    assert_ne!(small, large);
    let certify = |names: &[&str]| rotor.rank(names).unwrap();
    let five = ["F1", "F2", "G1", "G2", "L"];
    assert_eq!(certify(&five).rank, 4);
    assert_eq!(certify(&five), certify(&five));
    assert_ne!(certify(&five), certify(&five[..2]));
    let table = |names: &[&str]| BracketTable::compute(&rotor, names).unwrap();
    assert_eq!(table(&["L", "G1", "G2"]), table(&["L", "G1", "G2"]));
    assert_ne!(table(&["L", "G1", "G2"]), table(&["G1", "L", "G2"]));
    let proof = eigen_proof(&rotor, "Z").unwrap();
    assert!(proof.holds());
    assert_eq!(proof, eigen_proof(&rotor, "Z").unwrap());
    assert_ne!(proof, eigen_proof_of(&rotor, "Z", "K'").unwrap());
}

/// A bracket table computed by the engine prints as the grid a report prints, row for row
/// (the report indents it and captions it): the su(2) table, and one of `Z` and `Z̄`, whose
/// mark over the letter takes no column.
#[test]
fn a_bracket_table_prints_as_the_reports_grid() {
    let file = harmonic_rotor_file();
    for names in [&["F1", "L", "G1", "G2"][..], &["Z", "Zbar", "L"]] {
        let table = BracketTable::compute(file.system(), names).unwrap();
        let report = table_report(&file, names).unwrap();
        let text = render(&report, Format::Text, &RenderOptions::reproducible());
        let grid = table.to_string();
        assert_eq!(grid.lines().count(), names.len() + 2);
        for line in grid.lines() {
            assert!(
                text.lines().any(|l| l == format!("    {line}")),
                "{line:?} not in\n{text}"
            );
        }
    }
    // A table a program builds by hand, its fields out of step, prints what it has.
    let uneven = BracketTable {
        names: vec!["A".into(), "B".into()],
        display: vec!["A".into(), "B".into()],
        entries: vec![vec![TableEntry::Outside]],
    };
    assert_eq!(
        uneven.to_string(),
        "{·,·} │ A   B\n──────┼──────\nA     │ *\n"
    );
}

/// A residual cut to its leading part shows at least one monomial: with `shown_monomials`
/// `Some(0)`, `{G1, G2} = L` refuted printed `residual lhs − rhs = 0 + …`, which reads as
/// nearly zero; it shows its first term as `Some(1)` does.
#[test]
fn an_excerpt_shows_at_least_one_monomial() {
    let mut rotor = LoadedSystem::of_system(systems::harmonic_rotor());
    rotor.add_claim("w", "{G1, G2} = L", None).unwrap().expect = Expect::Refuted;
    let report = check_report([&rotor]).unwrap();
    let shown = |n| {
        let options = RenderOptions::reproducible().shown_monomials(Some(n));
        render(&report, Format::Text, &options)
    };
    let none = shown(0);
    assert!(!none.contains("= 0 + …"), "{none}");
    assert!(none.contains("its first 1 of 4 terms"), "{none}");
    assert_eq!(none, shown(1));
}

/// A clone is a system of its own: a function added to it is not in the original.
#[test]
fn a_clone_is_extended_alone() {
    let rotor = harmonic_rotor_file();
    let _ = rotor.parse("K_2_2").unwrap();
    let mut copy = rotor.clone();
    copy.add_function("C", "C", "4*G1^2 + G2^2 + omega^2*L^2")
        .unwrap();
    assert_eq!(copy.parse("C").unwrap(), copy.parse("(F1 - F2)^2").unwrap());
    assert!(rotor.parse("C").is_err());
    assert_eq!(copy.parse("K_2_2").unwrap(), rotor.parse("K_2_2").unwrap());
}

/// The reports take names as `&str`: the su(2) table `{G1, G2} = −ω² L`, the rank 5 of
/// `F1, F2, G1, G2, P_{1,1}` (C17) as a claim, and an expansion of the Casimir (where
/// `expand_report` took `&[String]` alone).
#[test]
fn reports_take_names_as_str() {
    let rotor = harmonic_rotor_file();
    let table = table_report(&rotor, &["L", "G1", "G2"]).unwrap();
    let text = render(&table, Format::Text, &RenderOptions::reproducible());
    assert!(text.contains("−ω² L"), "{text}");
    let rank = rank_report(&rotor, &["F1", "F2", "G1", "G2", "P_1_1"], Some(5)).unwrap();
    assert!(rank.all_proved());
    let json = render(&rank, Format::Json, &RenderOptions::reproducible());
    assert!(json.contains("\"rank\": 5"), "{json}");
    let expand = expand_report(&rotor, &["4*G1^2 + G2^2 + omega^2*L^2 - (F1 - F2)^2"], None);
    let text = render(
        &expand.unwrap(),
        Format::Text,
        &RenderOptions::reproducible(),
    );
    assert!(text.contains("(F1 − F2)² = 0"), "{text}");
    // A rank of no function is refused (nothing to expand: `report_errors_name_the_program_not_the_command_line`).
    let none = rank_report(&rotor, &[] as &[&str], None).unwrap_err();
    assert_eq!(none.message, "a rank needs at least one function");
}

/// A loaded system's `Debug` is short: its source by origin and length, its families and
/// claims by name and id, where the harmonic rotor's (a file of 7 KB) printed 443 KB, the
/// file's text in its source and again in each of its 48 claims.
#[test]
fn a_loaded_systems_debug_leaves_its_text_out() {
    let rotor = harmonic_rotor_file();
    check_report([&rotor]).expect("a report");
    let debug = format!("{rotor:?}");
    let text = std::fs::read_to_string("systems/harmonic-rotor.toml").expect("the file");
    assert!(
        !debug.contains("The harmonic rotor: a rigid rotor"),
        "{debug}"
    );
    assert!(
        debug.contains(&format!("text: <{} bytes>", text.len())),
        "{debug}"
    );
    assert!(debug.contains(r#"claims: ["C04", "C05", "C05""#), "{debug}");
    assert!(debug.len() < 2 * text.len(), "{} bytes", debug.len());
    let claim = format!("{:?}", rotor.claims()[0]);
    assert!(
        !claim.contains("The harmonic rotor: a rigid rotor"),
        "{claim}"
    );
}

/// A rank's Jacobian columns are its certificate's (`RankResult::coordinates`): a result
/// given the certificate of the level set `p_θ = Iω`, which has no column `p_θ`, prints that
/// certificate's columns, where a copy of them kept beside it still named `p_θ`.
#[test]
fn a_rank_results_coordinates_are_its_certificates() {
    use superint::report::Entry;
    let rotor = harmonic_rotor_file();
    let rank_of = |report: &Report| -> Option<RankResult> {
        report
            .sections
            .iter()
            .flat_map(|s| &s.entries)
            .find_map(|e| match e {
                Entry::Rank(r) => Some(r.clone()),
                _ => None,
            })
    };
    let mut everywhere = rank_report(&rotor, &["F1", "L"], None).unwrap();
    let level = rank_report_when(&rotor, &["F1", "L"], None, Some("p_theta = I*omega")).unwrap();
    let on_level = rank_of(&level).expect("a rank").certificate;
    let name = |r: &RankResult| -> Vec<String> {
        r.coordinates()
            .iter()
            .map(|&v| r.vars.variable(v).name().to_string())
            .collect()
    };
    let mut rank = rank_of(&everywhere).expect("a rank");
    assert_eq!(name(&rank), ["x", "y", "theta", "p_x", "p_y", "p_theta"]);
    rank.certificate = on_level;
    assert_eq!(name(&rank), ["x", "y", "theta", "p_x", "p_y"]);
    for entry in everywhere.sections.iter_mut().flat_map(|s| &mut s.entries) {
        if let Entry::Rank(r) = entry {
            *r = rank.clone();
        }
    }
    let json = render(&everywhere, Format::Json, &RenderOptions::reproducible());
    let v: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    assert_eq!(
        v["ranks"][0]["coordinates"],
        serde_json::json!(["x", "y", "theta", "p_x", "p_y"])
    );
}

/// A program's own error type takes the engine's errors by `?` through `FileError`: a slip in
/// an expression parsed by the engine keeps its line and column, a name declared twice (an
/// algebra error) is refused, and the program matches on the kinds. The harmonic oscillator
/// it builds has `{q, H} = p/m`.
#[test]
fn a_programs_error_type_matches_on_kinds() {
    #[derive(Debug, PartialEq)]
    enum Mine {
        Input { line: usize, column: usize },
        Other(ErrorKind),
    }
    impl From<FileError> for Mine {
        fn from(e: FileError) -> Self {
            match (e.kind, e.line_col()) {
                (ErrorKind::Expression, Some((line, column))) => Mine::Input { line, column },
                (kind, _) => Mine::Other(kind),
            }
        }
    }
    fn flow_of_q(h: &str, twice: bool) -> Result<String, Mine> {
        let mut builder = Vars::builder().coordinate("q").momentum("p").parameter("m");
        if twice {
            builder = builder.parameter("q");
        }
        let vars = builder.build().map_err(FileError::from)?;
        let space = PhaseSpace::new(&vars, &[("q", "p")]).map_err(FileError::from)?;
        let blank = System::new("oscillator", space, Expr::zero(&vars)).unwrap();
        let system = System::new(
            "oscillator",
            blank.space().clone(),
            blank.parse(h).map_err(FileError::from)?,
        )
        .unwrap();
        let flow = system
            .flow(&system.parse("q").map_err(FileError::from)?)
            .map_err(FileError::from)?;
        Ok(flow.to_string())
    }
    assert_eq!(flow_of_q("p^2/(2*m) + m*q^2/2", false).unwrap(), "p/m");
    assert_eq!(
        flow_of_q("p^2/(2*m)\n + m*q^^2/2", false).unwrap_err(),
        Mine::Input { line: 2, column: 8 }
    );
    assert_eq!(
        flow_of_q("p^2", true).unwrap_err(),
        Mine::Other(ErrorKind::Engine)
    );
}

/// What a program is told names the library's calls, not a file's tables: a system in code
/// without a family has no tower until `add_family`, and an unknown name in a text given in
/// code points at `add_function`. A file's messages stay the file's.
#[test]
fn messages_to_a_program_name_the_library() {
    let mut rotor = own_rotor();
    let err = family_tower_report(&rotor, None, 2, None).unwrap_err();
    assert_eq!(
        err.message,
        "the system has no family with an eigenvalue, so there is no tower to check"
    );
    assert!(err
        .hint
        .unwrap()
        .starts_with("add one with LoadedSystem::add_family"));
    let err = family_tower_report(&rotor, Some("R"), 2, None).unwrap_err();
    assert_eq!(err.message, "no family named 'R' (the system has none)");
    let err = rotor.add_function("B", "B", "p_x + i*w*x").unwrap_err();
    assert_eq!(
        (err.kind, err.line_col()),
        (ErrorKind::Expression, Some((1, 9)))
    );
    assert!(err.hint.unwrap().contains("LoadedSystem::add_function"));
    let file = harmonic_rotor_file();
    let err = family_tower_report(&file, Some("R"), 2, None).unwrap_err();
    assert_eq!(
        err.message,
        "no family named 'R' (the file declares K, Kbar, P, Q)"
    );
    let err = file.parse_argument("w").unwrap_err();
    assert!(err.hint.unwrap().contains("[[function]]"));
    // A list's empty name has no caret to stand beside in a program's message: the list is
    // quoted instead, where the command line says `missing after this comma`.
    let err = family_tower_report(&file, Some("K,,Kbar"), 2, None).unwrap_err();
    assert_eq!(
        (err.message.as_str(), err.location.is_none()),
        (
            "the list 'K,,Kbar' has an empty name: families are named separated by commas, \
             such as K,Kbar",
            true
        )
    );
    // A blank name is said to be blank, not a family's name that no family has.
    let err = family_tower_report(&file, Some("  "), 2, None).unwrap_err();
    assert_eq!(
        (err.message.as_str(), err.location.is_none()),
        (
            "the family's name '  ' is blank: name a family, such as K",
            true
        )
    );
}

/// A tower needs no progress callback: `family_tower_report` runs without one, and
/// `family_tower_report_with_progress` reports every bracket, `(done, total)`, in order, with
/// the same result.
#[test]
fn a_tower_takes_progress_only_when_asked() {
    let rotor = own_rotor_with_tower();
    let quiet = family_tower_report(&rotor, Some("R"), 2, None).unwrap();
    let mut seen = Vec::new();
    let watched = family_tower_report_with_progress(&rotor, Some("R"), 2, None, &mut |d, t| {
        seen.push((d, t));
    })
    .unwrap();
    assert_eq!(seen, [(1, 4), (2, 4), (3, 4), (4, 4)]);
    assert!(quiet.all_proved() && watched.all_proved());
    assert_eq!(
        quiet.tower().unwrap().checked,
        watched.tower().unwrap().checked
    );
    assert!(tower_report(TowerSystem::Harmonic, 2).unwrap().all_proved());
}

/// The reports' messages name the texts as a program gave them, not the command line: an
/// expression is `<expression>`, a condition `<condition>`, the table names the system and the
/// call, the tower's condition no `--when`; a file read `with_caller(Caller::CommandLine)`
/// names the command line, as `superint` does.
#[test]
fn report_errors_name_the_program_not_the_command_line() {
    let rotor = own_rotor();
    let cli_words = |err: &FileError| {
        let text = err.to_string();
        assert!(
            !text.contains("command line") && !text.contains("--") && !text.contains("superint"),
            "{text}"
        );
        text
    };
    let err = bracket_report(&rotor, "A", "B", None).unwrap_err();
    assert!(cli_words(&err).starts_with("<expression>:1:1: unknown name 'B'"));
    let err = expand_report(&rotor, &["A".to_string(), "A +".to_string()], None).unwrap_err();
    assert_eq!(
        (err.origin.as_str(), err.line_col()),
        ("<expression>", Some((1, 4)))
    );
    let err = bracket_report(&rotor, "A", "H", Some("p_phi = J*w")).unwrap_err();
    assert!(cli_words(&err).starts_with("<condition>:1:11: unknown name 'w'"));
    let err = rank_report(&rotor, &["A", "Omega", "B"], None).unwrap_err();
    assert!(cli_words(&err).starts_with("<expression>:1:1: unknown name 'B'"));
    // Nothing to expand is refused, as a table of nothing is: it was a report of no line.
    let err = expand_report(&rotor, &[] as &[&str], None).unwrap_err();
    assert_eq!(
        cli_words(&err),
        "<expression>: nothing to expand: give the expressions in the call, such as \
         expand_report(&system, &[\"H\"], None)"
    );
    let err = table_report(&rotor, &["A", "B"]).unwrap_err();
    assert_eq!(
        cli_words(&err),
        "<expression>:1:1: 'B' is not a function of the own rotor (known: H, A, Omega, x, y, p_x, \
         p_y, p_phi)\n 1 | B\n   | ^"
    );
    let vars = Vars::builder()
        .coordinate("q")
        .momentum("p")
        .build()
        .unwrap();
    let space = PhaseSpace::new(&vars, &[("q", "p")]).unwrap();
    let h = Expr::parse(&vars, "p^2/2").unwrap();
    let bare = LoadedSystem::of_system(System::new("free particle", space, h).unwrap());
    let err = table_report(&bare, &[] as &[&str]).unwrap_err();
    assert!(cli_words(&err).contains("table_report(&system"), "{err}");
    let towered = own_rotor_with_tower();
    let on_phase_space = towered.condition("p_phi = J*k").unwrap();
    let err = family_tower_report(&towered, Some("R"), 2, Some(&on_phase_space)).unwrap_err();
    assert_eq!(err.origin, "<condition>");
    assert!(cli_words(&err).contains("a tower's condition may set parameters only"));
    // Read from its text, the same refusal is shown at its value there.
    let err = towered
        .tower_condition("p_phi = J*k", Some("R"))
        .unwrap_err();
    assert!(
        cli_words(&err).starts_with("<condition>:1:9: a tower's condition may set parameters"),
        "{err}"
    );
    // At J = 0, where H divides by J, the tower was checked and proved; given without its
    // text, the refusal has no place, with its text, it is at the value.
    let at_zero = towered.condition("J = 0").unwrap();
    let err = family_tower_report(&towered, Some("R"), 2, Some(&at_zero)).unwrap_err();
    let divides = "the condition sets J = 0, but the Hamiltonian divides by J";
    assert_eq!(
        (err.origin.as_str(), err.location.is_none()),
        ("<condition>", true)
    );
    assert!(
        cli_words(&err).starts_with(&format!("<condition>: {divides}")),
        "{err}"
    );
    let err = towered.tower_condition("J = 0", Some("R")).unwrap_err();
    assert!(
        cli_words(&err).starts_with(&format!("<condition>:1:5: {divides}")),
        "{err}"
    );

    // The command line's words, when the caller says so.
    assert_eq!(rotor.caller(), Caller::Program);
    let cli = harmonic_rotor_file().with_caller(Caller::CommandLine);
    let err = table_report(&cli, &["nope"]).unwrap_err();
    assert!(err
        .to_string()
        .starts_with("<command line>:1:1: 'nope' is not a function of "));
    let err = bracket_report(&cli, "L", "H", Some("p_theta = ")).unwrap_err();
    assert_eq!(err.origin, "<command line>");
    let on_phase_space = cli.condition("p_theta = I*omega").unwrap();
    let err = family_tower_report(&cli, None, 2, Some(&on_phase_space)).unwrap_err();
    assert!(err.message.starts_with("--when: "), "{err}");
}

/// `Expr::parse`'s error says where and what wherever `?` takes it: into a `Box<dyn Error>`
/// its text has the line, column, the line and a caret; into a `FileError`, directly or
/// through an `EngineError`, it is an expression error at its line and column, shown as a
/// file's are.
#[test]
fn a_parse_error_keeps_its_place_under_question_mark() {
    let vars = Vars::builder()
        .coordinate("x")
        .momentum("p_x")
        .parameter("k")
        .build()
        .unwrap();
    let boxed = || -> Result<Expr, Box<dyn std::error::Error>> {
        Ok(Expr::parse(&vars, "p_x^2/2\n + k*x^2/2 + q")?)
    };
    assert_eq!(
        boxed().unwrap_err().to_string(),
        concat!(
            "line 2, column 14: unknown name 'q' (known: x, p_x, k)\n",
            "   + k*x^2/2 + q\n",
            "               ^"
        )
    );
    let file = || -> Result<Expr, FileError> { Ok(Expr::parse(&vars, "p_x^2/2 + k*x^^2")?) };
    let err = file().unwrap_err();
    assert_eq!(
        (err.kind, err.origin.as_str(), err.line_col()),
        (ErrorKind::Expression, "<expression>", Some((1, 15)))
    );
    assert_eq!(
        err.to_string(),
        "<expression>:1:15: expected an expression after '^', found '^'\n 1 | p_x^2/2 + k*x^^2\n   |               ^"
    );
    let engine = || -> Result<Expr, EngineError> { Ok(Expr::parse(&vars, "k*(x + ")?) };
    let err = FileError::from(engine().unwrap_err());
    assert_eq!(err.line_col(), Some((1, 7)));
    assert!(engine()
        .unwrap_err()
        .to_string()
        .starts_with("line 1, column 7: "));
}

/// A text the engine read (`System::parse`), taken into a `FileError` by `?`, keeps what kind
/// of error its parse met (`FileError::cause`), as one of the ring's own parse does: a power
/// past the term limit says the limit, an unknown name says the name; without it a program
/// told the two apart only by the message. The power past the limit is of kind `limit`, as
/// the loader says of a file's text (it was `expression` under `?`).
#[test]
fn an_engine_parse_error_taken_by_question_mark_keeps_its_cause() {
    let vars = Vars::builder()
        .coordinate("x")
        .momentum("p_x")
        .parameter("k")
        .limits(Limits::default().max_terms(30))
        .build()
        .unwrap();
    let space = PhaseSpace::new(&vars, &[("x", "p_x")]).unwrap();
    let h = Expr::parse(&vars, "p_x^2/2 + k*x^2/2").unwrap();
    let system = System::new("small", space, h).unwrap();
    let read = |text: &str| -> Result<Expr, FileError> { Ok(system.parse(text)?) };
    let ring = |text: &str| -> Result<Expr, FileError> { Ok(Expr::parse(&vars, text)?) };
    for read in [&read as &dyn Fn(&str) -> Result<Expr, FileError>, &ring] {
        let err = read("p_x^2 +\n (x + p_x + k + 1)^6").unwrap_err();
        assert_eq!((err.kind, err.line_col()), (ErrorKind::Limit, Some((2, 2))));
        assert!(err.hint.as_deref().is_some_and(|h| h.contains("max_terms")));
        assert_eq!(
            err.cause.as_deref(),
            Some(&superint::trigpoly::ParseCause::Algebra(
                AlgebraError::TooManyTerms { limit: 30 }
            )),
            "{err}"
        );
        let err = read("x + q").unwrap_err();
        assert_eq!(err.unknown_name().as_deref(), Some("q"), "{err:?}");
        assert_eq!(err.kind, ErrorKind::Expression);
        assert_eq!(read("x + (").unwrap_err().cause, None);
    }
}

/// A parse that a limit stopped is one error whichever way it reaches a program: the engine's
/// `System::parse` says which limit (`EngineError::limit`), and as a `FileError`, through `?`
/// from the engine or the ring, through the loader reading the same text in a file, and
/// through `LoadedSystem::parse`, it is of kind `limit` with the same message, and a hint that
/// names the same limit, each in the settings of its giver (a file's own text, a program's). It
/// was `expression` through `?`, `limit` through the loader. An unknown name is neither a limit
/// nor, through any of them, of kind `limit`.
#[test]
fn a_parse_stopped_at_a_limit_is_a_limit_through_question_mark_and_the_loader() {
    let file = |value: &str| {
        format!(
            "hamiltonian = \"p_x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n\
             [[function]]\nname = \"B\"\nvalue = \"{value}\"\n"
        )
    };
    let small = LimitsOverride::default().max_terms(30);
    let free = load_system_text("free.toml", &file("x"), &small).unwrap();
    let system = free.system();
    for (text, limit) in [
        ("x^5000", Some(LimitKind::Degree(5000))),
        ("(1 + x + p_x)^20", Some(LimitKind::Terms)),
        ("x + nope", None),
    ] {
        let engine = system.parse(text).unwrap_err();
        assert_eq!(engine.limit(), limit.map(EngineLimit::Ring), "{text}");
        assert_eq!(engine.is_limit(), limit.is_some(), "{text}");
        let kind = match limit {
            Some(_) => ErrorKind::Limit,
            None => ErrorKind::Expression,
        };
        let question_mark = || -> Result<Expr, FileError> { Ok(system.parse(text)?) };
        let ring = || -> Result<Expr, FileError> { Ok(Expr::parse(system.vars(), text)?) };
        let loaded = load_system_text("free.toml", &file(text), &small).unwrap_err();
        let in_code = free.parse(text).unwrap_err();
        assert_eq!(loaded.kind, kind, "{text}: {loaded}");
        for err in [question_mark().unwrap_err(), ring().unwrap_err(), in_code] {
            assert_eq!(err.kind, kind, "{text}: {err}");
            if let Some(limit) = limit {
                assert_eq!(err.message, loaded.message);
                let key = match limit {
                    LimitKind::Degree(_) => "max_degree",
                    _ => "max_terms",
                };
                for hint in [&err.hint, &loaded.hint] {
                    let hint = hint.as_deref().unwrap_or_default();
                    assert!(hint.contains(key), "{text}: {hint}");
                    assert!(hint.contains("LimitsOverride"), "{text}: {hint}");
                }
            }
        }
    }
}

/// The su(2) generators of the harmonic rotor, a closure's in the limit tests below.
const SU2: [&str; 5] = ["F1", "F2", "L", "G1", "G2"];

/// The search space of the limit tests below: degree 2 in the momenta, the coordinates and
/// the trigonometric order (300 unknowns).
fn degree_two() -> SearchSpace {
    SearchSpace::default()
        .momenta_degree(2)
        .positions_degree(2)
        .trig_degree(2)
}

/// A search for new integrals stopped past `SearchOptions::max_products` is a limit, the
/// search's products (`EngineLimit::SearchProducts`): it was `EngineError::Invalid`, no limit
/// to `is_limit`. Its message names no setting (it named `SearchOptions::max_products` and
/// `--max-products` to whoever called); taken by `?` into a `FileError` it is of kind
/// `limit`, with the hint naming the program's option, where it had none.
#[test]
fn a_search_past_its_products_says_that_limit() {
    let rotor = systems::harmonic_rotor();
    let few_products = SearchOptions::new(degree_two())
        .when(rotor.resonance(1, 1).unwrap())
        .new_only()
        .max_products(1);
    let err = search(&rotor, &few_products).unwrap_err();
    assert_eq!(err.limit(), Some(EngineLimit::SearchProducts), "{err}");
    assert!(err.is_limit());
    assert!(
        matches!(err, EngineError::PastLimit { limit: 1, .. }),
        "{err:?}"
    );
    assert_eq!(
        err.to_string(),
        "more than 1 product of integrals, the search's limit of them: search a smaller space, \
         or raise the limit"
    );
    let as_file = FileError::from(err.clone());
    assert_eq!(as_file.kind, ErrorKind::Limit);
    assert_eq!(
        as_file.hint.as_deref(),
        Some("if the machine has the time, raise the limit with SearchOptions::max_products")
    );
    assert_eq!(as_file.message, err.to_string());
}

/// A search space of more unknowns than the term limit is the term limit
/// (`EngineLimit::Ring(LimitKind::Terms)`), raised by `Limits::max_terms`: it was
/// `EngineError::Invalid`. Taken by `?` into a `FileError` it is of kind `limit` with the hint
/// to raise `max_terms`.
#[test]
fn a_search_space_past_the_term_limit_says_that_limit() {
    let small = systems::Rotor::Harmonic
        .system(Limits::default().max_terms(10))
        .unwrap();
    let err = search(&small, &SearchOptions::new(degree_two())).unwrap_err();
    assert_eq!(
        err.limit(),
        Some(EngineLimit::Ring(LimitKind::Terms)),
        "{err}"
    );
    assert!(err.is_limit());
    assert_eq!(
        err.to_string(),
        "the space has 300 unknowns, more than the term limit 10: search a smaller space, or \
         raise the limit"
    );
    let as_file = FileError::from(err);
    assert_eq!(as_file.kind, ErrorKind::Limit);
    assert!(as_file.hint.is_some_and(|h| h.contains("max_terms")));
}

/// A closure whose monomials pass `ClosureOptions::max_monomials` is a limit, the closure's
/// monomials (`EngineLimit::ClosureMonomials`), counted before any is expanded: it was
/// `EngineError::Invalid`. Its message names no setting; the hint of the error `?` makes of
/// it names the program's option.
#[test]
fn a_closure_past_its_monomials_says_that_limit() {
    let rotor = systems::harmonic_rotor();
    let few_monomials = ClosureOptions::new(2).max_monomials(20);
    let err = closure(&rotor, &SU2, &few_monomials).unwrap_err();
    assert_eq!(err.limit(), Some(EngineLimit::ClosureMonomials), "{err}");
    assert!(err.is_limit());
    assert!(
        matches!(err, EngineError::PastLimit { limit: 20, .. }),
        "{err:?}"
    );
    assert_eq!(
        err.to_string(),
        "there are 21 monomials of degree ≤ 2 in the 5 generators, more than the limit 20: \
         lower the degree, or raise the limit"
    );
    let as_file = FileError::from(err);
    assert_eq!(as_file.kind, ErrorKind::Limit);
    assert_eq!(
        as_file.hint.as_deref(),
        Some("if the machine has the time, raise the limit with ClosureOptions::max_monomials")
    );
}

/// A closure whose products of the generators pass the term limit together says the term
/// limit, which raises them (`ClosureTooManyTerms` was a limit, but no program could ask
/// which).
#[test]
fn a_closure_past_the_term_limit_says_that_limit() {
    let small = systems::Rotor::Harmonic
        .system(Limits::default().max_terms(60))
        .unwrap();
    let err = closure(&small, &SU2, &ClosureOptions::new(4)).unwrap_err();
    assert!(
        matches!(err, EngineError::ClosureTooManyTerms { limit: 60, .. }),
        "{err:?}"
    );
    assert_eq!(err.limit(), Some(EngineLimit::Ring(LimitKind::Terms)));
    assert!(err.is_limit());
}

/// A closure's report stopped at a limit says what to do about it in the library's settings,
/// as the command line says it in its options: raise the limit, or lower
/// `ClosureOptions::degree`, of a system built in code and of a file alike (a program's error
/// said the limit alone, and a file's hint how to raise it, never the degree); the error is
/// still of that limit, by type, and a file's still has its hint. A file's limits are named
/// as a program sets them, `LimitsOverride` (its advice named `Limits`, which sets a system's
/// in code), a system built in code given as a loaded one by its own, `Limits`, and an exponent past the most a file's degree limit may be is raised by the
/// degree limit of a system in code (its advice said that no limit reached it).
#[test]
fn a_closures_report_at_a_limit_advises_the_librarys_settings() {
    let terms = "the products of the generators up to degree 4 would have more than 60 terms \
                 together (the term limit); raise it with Limits::max_terms, or lower \
                 ClosureOptions::degree";
    let small = systems::Rotor::Harmonic
        .system(Limits::default().max_terms(60))
        .unwrap();
    let generators: Vec<NamedFunction> = SU2
        .iter()
        .map(|&n| NamedFunction::new(n, n, small.get(n).unwrap().clone()))
        .collect();
    let err = closure_report(
        "the harmonic rotor",
        &small,
        &generators,
        &ClosureOptions::new(4),
    )
    .unwrap_err();
    assert_eq!(err.to_string(), terms);
    assert_eq!(err.limit(), Some(EngineLimit::Ring(LimitKind::Terms)));
    // A system built in code, given as a loaded one, names its own settings, `Limits` (its
    // advice named the `LimitsOverride` of a file's loader, which it has none of).
    let in_code = LoadedSystem::of_system(small.clone());
    let err =
        file_closure_report(&in_code, &SU2, &ClosureOptions::new(4), Caller::Program).unwrap_err();
    assert_eq!(err.kind, ErrorKind::Limit);
    assert_eq!(err.message, format!("computing the closure: {terms}"));
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/systems/harmonic-rotor.toml");
    let rotor = load_system_file(path, &LimitsOverride::default().max_terms(60)).unwrap();
    let err =
        file_closure_report(&rotor, &SU2, &ClosureOptions::new(4), Caller::Program).unwrap_err();
    assert_eq!(err.kind, ErrorKind::Limit);
    let terms = terms.replace("Limits::", "LimitsOverride::");
    assert_eq!(err.message, format!("computing the closure: {terms}"));
    assert!(err.hint.is_some_and(|h| h.contains("max_terms")));
    // One operation past the work limit, and past the degree limit.
    let options = ClosureOptions::new(3);
    let few_products = LimitsOverride::default().max_term_products(1000);
    let mut work = load_system_file(path, &few_products).unwrap();
    work.add_function("X", "X", "(x+y+p_x+p_y+M+1)^8").unwrap();
    let err = file_closure_report(&work, &["L", "X"], &options, Caller::Program).unwrap_err();
    assert_eq!(err.kind, ErrorKind::Limit);
    assert_eq!(
        err.message,
        "computing the closure: the product of 495 terms by 495 would form 245025 term \
         products, past the limit of 1000 (the work limit); raise the limit with \
         LimitsOverride::max_term_products, or lower ClosureOptions::degree (the products of \
         the generators up to it are formed)"
    );
    let mut high = harmonic_rotor_file();
    high.add_function("X", "X", "p_y^300").unwrap();
    let err = file_closure_report(&high, &["L", "X"], &ClosureOptions::new(4), Caller::Program)
        .unwrap_err();
    assert_eq!(err.kind, ErrorKind::Limit);
    assert!(
        err.message.ends_with(
            "; raise the limit with LimitsOverride::max_degree, or lower ClosureOptions::degree \
             (the products of the generators up to it are formed)"
        ),
        "{err}"
    );
    // A degree limit in code may be past the most a file's may be (MAX_DEGREE_CEILING), so
    // an exponent past that is raised by it too (the advice said that no limit reached it).
    let wide = systems::Rotor::Harmonic
        .system(Limits::default().max_degree(20_000))
        .unwrap();
    let x = NamedFunction::new("X", "X", wide.parse("p_y^17000").unwrap());
    let l = NamedFunction::new("L", "L", wide.get("L").unwrap().clone());
    let err = closure_report("the rotor", &wide, &[l, x], &ClosureOptions::new(2)).unwrap_err();
    assert_eq!(
        err.limit(),
        Some(EngineLimit::Ring(LimitKind::Degree(34_000)))
    );
    assert!(
        err.to_string().ends_with(
            "; raise the limit with Limits::max_degree, or lower ClosureOptions::degree (the \
             products of the generators up to it are formed)"
        ),
        "{err}"
    );
    // The command line's, in its options.
    let cli = file_closure_report(
        &high,
        &["L", "X"],
        &ClosureOptions::new(4),
        Caller::CommandLine,
    )
    .unwrap_err();
    assert!(
        cli.message.ends_with(
            "; raise the limit with --max-degree D, or lower --degree (the \
                               products of the generators up to it are formed)"
        ),
        "{cli}"
    );
}

/// What is wrong whatever the limits is no limit: a search or a closure on a condition the
/// flow leaves, and a generator the system does not name.
#[test]
fn a_refusal_of_the_input_is_no_limit() {
    let rotor = systems::harmonic_rotor();
    let x = rotor.vars().lookup("x").unwrap();
    let on_x_zero = Condition::new("x = 0", x, Expr::zero(rotor.vars()));
    let left = SearchOptions::new(degree_two()).when(on_x_zero.clone());
    let unknown = closure(&rotor, &["F1", "nope"], &ClosureOptions::new(2));
    let flow_leaves = closure(&rotor, &SU2, &ClosureOptions::new(2).when(on_x_zero));
    for err in [
        search(&rotor, &left).unwrap_err(),
        unknown.unwrap_err(),
        flow_leaves.unwrap_err(),
    ] {
        assert_eq!((err.limit(), err.is_limit()), (None, false), "{err}");
        assert_eq!(FileError::from(err).kind, ErrorKind::Engine);
    }
}

/// The Jacobi identity of a file's `[poisson]` brackets checked under a term or degree limit
/// too small for it is a limit, as every other text of the file stopped at a limit is: of kind
/// `limit`, with the hint that raises it, at `[poisson]`. It was of kind `engine` with no hint,
/// so that a program told it from declared brackets that break the identity only by the
/// message; those stay of kind `engine`, at the last entry of their triple.
#[test]
fn a_jacobi_check_stopped_at_a_limit_is_a_limit() {
    let text = "hamiltonian = \"a\"\n[phase_space]\nvariables = [\"a\", \"b\", \"c\"]\n\
                [poisson]\n\"{a, b}\" = \"c\"\n\"{b, c}\" = \"a\"\n\
                \"{c, a}\" = \"b + a^2*c^2 + a*b*c\"\n";
    for (limits, raised) in [
        (LimitsOverride::default().max_terms(4), "max_terms"),
        (LimitsOverride::default().max_degree(2), "max_degree"),
    ] {
        let err = load_system_text("jacobi.toml", text, &limits).unwrap_err();
        assert_eq!(
            (err.kind, err.line_col()),
            (ErrorKind::Limit, Some((4, 1))),
            "{err}"
        );
        assert!(
            err.hint.as_deref().is_some_and(|h| h.contains(raised)),
            "{err}"
        );
    }
    let err = load_system_text("jacobi.toml", text, &LimitsOverride::default()).unwrap_err();
    assert_eq!(
        (err.kind, err.line_col(), err.hint.as_deref()),
        (ErrorKind::Engine, Some((7, 1)), None),
        "{err}"
    );
    assert!(err.message.contains("break the Jacobi identity"), "{err}");
}

/// A limit's hint names the setting that raises it and no other. A search of a file's space
/// of more unknowns than the term limit, reaching a program through `?` as a `FileError`, is
/// raised by `max_terms` alone (a larger `max_degree` leaves the same error), and its hint
/// named `max_degree` too; an exponent past the degree limit is raised by `max_degree` alone.
#[test]
fn a_limits_hint_names_the_setting_that_raises_it() {
    fn search(limits: &LimitsOverride) -> Result<usize, FileError> {
        let rotor = load_system_file("systems/harmonic-rotor.toml", limits)?;
        let space = SearchSpace::default()
            .momenta_degree(4)
            .positions_degree(4)
            .trig_degree(4);
        let options = SearchOptions::new(space);
        let (_, found) = file_search_report(&rotor, &options, Caller::Program)?;
        Ok(found.basis.len())
    }
    // Through `?`, from the engine: a program's settings, of a system in code or a file.
    let terms = "if the machine has the memory, raise the limit with max_terms of the Limits \
                 a system built in code was built with, or of the LimitsOverride given to the \
                 loader of a system file";
    for limits in [
        LimitsOverride::default().max_terms(100),
        LimitsOverride::default().max_terms(100).max_degree(4000),
    ] {
        let err = search(&limits).unwrap_err();
        assert_eq!(err.kind, ErrorKind::Limit, "{err}");
        assert!(
            (err.message).contains("the space has 4725 unknowns, more than the term limit 100"),
            "{err}"
        );
        assert_eq!(err.hint.as_deref(), Some(terms), "{err}");
    }
    let rotor = systems::harmonic_rotor();
    let err = FileError::from(rotor.parse("x^5000").unwrap_err());
    assert_eq!(err.kind, ErrorKind::Limit, "{err}");
    assert_eq!(
        err.hint.as_deref(),
        Some(
            "if the machine has the memory, raise the limit with max_degree of the Limits a \
             system built in code was built with, or of the LimitsOverride given to the loader \
             of a system file"
        ),
        "{err}"
    );
}

/// A limit's hint names a program's settings as the system it is about has them: a system
/// built in code (a built-in one too, as `discovery::builtin_system` builds it) the `Limits`
/// its variables were built with, where it named `max_degree under [limits] in the file`,
/// which it has not, and said that no limit reaches an exponent past 32767, which
/// `Limits::max_degree` does up to `Limits::MAX_DEGREE` (2³¹ − 1, not `u32::MAX`, as the hint
/// once had it); a file the `LimitsOverride` given to the loader, then its `[limits]`.
#[test]
fn a_programs_limit_hint_names_the_systems_settings() {
    let code = LoadedSystem::of_system(systems::harmonic_rotor());
    let (_, builtin) = superint::discovery::builtin_system("gravity", false, Limits::default())
        .unwrap()
        .unwrap();
    let builtin = LoadedSystem::of_system(builtin);
    let in_code = "if the machine has the memory, raise the limit with max_degree of the Limits \
                   the system's variables were built with";
    for system in [&code, &builtin] {
        for text in ["x^5000", "x^40000"] {
            let err = expand_report(system, &[text], None).unwrap_err();
            assert_eq!(err.kind, ErrorKind::Limit, "{err}");
            assert_eq!(err.hint.as_deref(), Some(in_code), "{err}");
        }
        let err = bracket_report(system, "L", "H", Some("x = y^5000")).unwrap_err();
        assert_eq!(err.hint.as_deref(), Some(in_code), "{err}");
    }
    // Past 2³¹ − 1 no `max_degree` takes effect (`Limits::MAX_DEGREE`), though it takes a u32.
    for text in ["x^3000000000", "x^4294967296"] {
        let err = expand_report(&code, &[text], None).unwrap_err();
        assert_eq!(
            err.hint.as_deref(),
            Some(
                "no limit reaches this exponent or order: max_degree is at most 2147483647; \
                 write the expression without so large a power or multiple"
            ),
            "{err}"
        );
    }
    let rotor =
        load_system_file("systems/harmonic-rotor.toml", &LimitsOverride::default()).unwrap();
    let err = expand_report(&rotor, &["x^5000"], None).unwrap_err();
    assert_eq!(
        err.hint.as_deref(),
        Some(
            "if the machine has the memory, raise the limit with max_degree of the \
             LimitsOverride given to the loader (or max_degree under [limits] in the file)"
        ),
        "{err}"
    );
}

/// A function added in code is checked against the names as they print, as a file's is: a
/// name the printer would write for a product of one-letter variables (`kx` for `k x`) is
/// refused, unless the variables were built knowing it, and then the product prints spaced;
/// a display that prints as a variable's or a function's does, in text or in LaTeX (`F_1` and
/// `F1`, both `F_{1}`), is refused; so is a family whose instances would print as another's.
/// Each message names the offending name, and the system is unchanged.
#[test]
fn names_added_in_code_print_apart() {
    let mut rotor = own_rotor();
    let functions = rotor.system().functions().len();
    let err = rotor.add_function("kx", "kx", "k*p_x").unwrap_err();
    assert_eq!(
        (err.kind, err.origin.as_str()),
        (ErrorKind::Name, "<function kx>")
    );
    assert_eq!(
        err.message,
        "the function kx would read back from the product k x of the variables, which prints \
         as kx: choose another name, or give it to the variables when they are built \
         (VarsBuilder::also_named), which has such products printed spaced"
    );
    // Its display alone may spell the product too.
    let err = rotor.add_function("P", "kJ", "k*J").unwrap_err();
    assert!(err
        .message
        .starts_with("the function P would read back from the product k J"));
    let err = rotor.add_function("B", "A", "p_y").unwrap_err();
    assert_eq!(
        err.message,
        "the function B would show as A, as the function A does: rename one, or give it another \
         display"
    );
    rotor.add_function("J1", "J1", "J").unwrap();
    let err = rotor.add_function("J_1", "J_1", "J").unwrap_err();
    assert_eq!(
        err.message,
        "the function J_1 would print as J_{1} in LaTeX, as the function J1 does: rename one, \
         or give it another display"
    );
    assert_eq!(rotor.system().functions().len(), functions + 1);

    // Variables built knowing the name: the function is taken, and the product spaced.
    let vars = Vars::builder()
        .coordinate("x")
        .momentum("p_x")
        .parameter("k")
        .also_named(["kx"])
        .build()
        .unwrap();
    let space = PhaseSpace::new(&vars, &[("x", "p_x")]).unwrap();
    let h = Expr::parse(&vars, "p_x^2/2 + k^2*x^2/2").unwrap();
    let mut oscillator = LoadedSystem::of_system(System::new("oscillator", space, h).unwrap());
    oscillator.add_function("kx", "kx", "k*x").unwrap();
    let report = expand_report(&oscillator, &["kx".to_string()], None).unwrap();
    let text = render(&report, Format::Text, &RenderOptions::reproducible());
    assert!(text.contains("kx = k x"), "{text}");

    // A loaded file: its own functions print spaced; a new one is told to go in the file.
    let mut file = harmonic_rotor_file();
    let err = file.add_function("Mx", "Mx", "M*x").unwrap_err();
    assert!(
        err.message
            .ends_with("declare the function in the file, whose products are then printed spaced"),
        "{err}"
    );
    let err = file.add_function("F_1", "F_1", "x").unwrap_err();
    assert_eq!(
        err.message,
        "the function F_1 would print as F_{1} in LaTeX, as the function F1 does: rename one, \
         or give it another display"
    );
    let families = file.families().len();
    let err = file
        .add_family("T", "K", ["m", "n"], "Z^m*Zbar^n", None)
        .unwrap_err();
    assert_eq!(
        (err.kind, err.origin.as_str(), err.message.as_str()),
        (
            ErrorKind::Name,
            "<family T>",
            "the family T would show its instances as K_{m,n}, as the family K does: rename \
             one, or give it another display"
        )
    );
    assert_eq!(file.families().len(), families);
}

/// A file's families are checked as those added in code are: a family whose instances would
/// print as another's (`T` shown as `K`, both `K_{m,n}`; `K1` and `K₁`, both `K_{1;m,n}` in
/// LaTeX) is refused at its display or name.
#[test]
fn a_files_families_print_apart() {
    let text = "hamiltonian = \"p_x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n\
                [[family]]\nname = \"K\"\nvalue = \"x^m*p_x^n\"\n\
                [[family]]\nname = \"T\"\ndisplay = \"K\"\nvalue = \"p_x^m*x^n\"\n";
    let err = load_system_text("two.toml", text, &LimitsOverride::default()).unwrap_err();
    assert_eq!(
        err.to_string(),
        "two.toml:9:11: the family T would show its instances as K_{m,n}, as the family K on \
         line 5 does: rename one, or give it another display\n 9 | display = \"K\"\n   |           ^^^"
    );
    let text = text
        .replace("display = \"K\"\n", "")
        .replace("\"T\"", "\"K₁\"");
    let text = text.replace("name = \"K\"", "name = \"K1\"");
    let err = load_system_text("two.toml", &text, &LimitsOverride::default()).unwrap_err();
    assert_eq!(
        err.to_string().lines().next(),
        Some(
            "two.toml:8:8: the family K₁ would print its instances in LaTeX as K_{1} with their \
             indices, as the family K1 on line 5 does: rename one, or give it another display"
        )
    );
}

/// A residual cut short in a program's report says how a program shows it all
/// (`RenderOptions::shown_monomials(None)`), not the command line's `--full-expressions`; a
/// report built for the command line names the flag, as `superint check` prints.
#[test]
fn a_programs_long_residual_names_the_render_option() {
    use superint::system_file::{check_report, load_str};

    let text = "name = \"long residuals\"\nhamiltonian = \"p_x^2/2\"\n\
                [phase_space]\ncoordinates = [\"x\"]\n\
                [[function]]\nname = \"F\"\nvalue = \"(1 + x + p_x)^3\"\n\
                [[claim]]\nid = \"long\"\nclaim = \"(1 + x + p_x)^3 = 0\"\n";
    let file = load_str("long.toml", text, &LimitsOverride::default()).unwrap();
    let options = RenderOptions::reproducible().shown_monomials(Some(2));
    let program = "shown: its first 2 of 10 terms; RenderOptions::shown_monomials(None) shows all";
    let flag = "shown: its first 2 of 10 terms; --full-expressions shows all";
    let report = check_report([&file]).unwrap();
    assert_eq!(report.caller, Caller::Program);
    for format in [Format::Text, Format::Markdown] {
        let out = render(&report, format, &options);
        let out = out.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(out.contains(program), "{format}: {out}");
        assert!(!out.contains("--full-expressions"), "{format}: {out}");
    }
    let latex = render(&report, Format::Latex, &options);
    assert!(
        latex.contains(r"RenderOptions::shown\_monomials(None)"),
        "{latex}"
    );
    assert!(!latex.contains("full-expressions"), "{latex}");
    // A program's own claims, and a table's entry, alike.
    let claim = Claim::new(
        "long",
        "(1 + x + p_x)^3 = 0",
        file.parse("(1 + x + p_x)^3").unwrap(),
        file.parse("0").unwrap(),
    );
    let own = Report::of_claims("My claims", vec![claim.check().unwrap().into()]);
    assert!(render(&own, Format::Text, &options).contains(program));
    let table = table_report(&file, &["x", "F"]).unwrap();
    let table = render(&table, Format::Markdown, &options);
    assert!(
        table.contains("RenderOptions::shown_monomials(None) shows all"),
        "{table}"
    );
    // Built for the command line, or marked so after, a report names the flag.
    let cli = check_report([&file.clone().with_caller(Caller::CommandLine)]).unwrap();
    assert_eq!(cli.caller, Caller::CommandLine);
    assert!(render(&cli, Format::Text, &options).contains(flag));
    let own = own.with_caller(Caller::CommandLine);
    assert!(render(&own, Format::Text, &options).contains(flag));
}

/// A paper's claim of kind rank is refused by its check before its sides are computed: a rank
/// has none (an `Item::Rank` is certified from its functions), where the check computed them
/// first and gave their error, here the sides' two variable sets, instead of the refusal.
#[test]
fn a_paper_claim_of_kind_rank_is_refused_before_its_sides_are_computed() {
    use superint::paper::PaperClaim;
    let one = Vars::builder().coordinate("x").build().unwrap();
    let other = Vars::builder().coordinate("y").build().unwrap();
    let claim = Claim::new(
        "R1",
        "rank(x) = 1",
        Expr::parse(&one, "x").unwrap(),
        Expr::parse(&other, "y").unwrap(),
    );
    let rank = PaperClaim {
        claim: claim.clone(),
        kind: ClaimKind::Rank,
    };
    let Err(EngineError::Invalid(why)) = rank.check() else {
        panic!("refused as no rank: {:?}", rank.check());
    };
    assert!(
        why.starts_with("R1 is a claim of two sides, not a rank"),
        "{why}"
    );
    // The same sides as an identity are computed, and their error is the answer.
    let identity = PaperClaim {
        claim,
        kind: ClaimKind::Identity,
    };
    assert!(matches!(identity.check(), Err(EngineError::Algebra(_))));
}

/// Every message of an error's chain, as a report that walks the sources prints it (anyhow's
/// `{:#}`, eyre's reports): the error's, then each source's, joined by `: `.
fn chain(error: &dyn std::error::Error) -> String {
    let mut said = vec![error.to_string()];
    let mut cause = error.source();
    while let Some(e) = cause {
        said.push(e.to_string());
        cause = e.source();
    }
    said.join(": ")
}

/// An error that says its cause in its message does not return it as its source too, so
/// that a report that walks the sources says each message once: the engine's parse error of
/// a system's expression (made by a parse, by `EngineError::parse`, named by its part, and
/// through the transparent errors that wrap an engine error), and a Gaussian rational's.
#[test]
fn walking_an_errors_chain_says_each_message_once() {
    let rotor = systems::harmonic_rotor();
    let unknown = "unknown name 'q'";
    let parse = trigpoly::ParseError::new(trigpoly::Span::new(4, 5), unknown);
    let engine = [
        rotor.parse("{L, q}").unwrap_err(),
        EngineError::parse("x + q", parse.clone()),
        EngineError::from(parse.clone()),
        EngineError::parse("x + q", parse).in_part("its Hamiltonian"),
    ];
    for error in engine {
        assert_eq!(
            chain(&error).matches(unknown).count(),
            1,
            "{}",
            chain(&error)
        );
        let workload = superint::workloads::WorkloadError::from(error.clone());
        assert_eq!(chain(&workload).matches(unknown).count(), 1);
        let trajectory = superint::trajectory::TrajectoryError::from(error);
        assert_eq!(chain(&trajectory).matches(unknown).count(), 1);
    }
    let gaussian = "1 + 2j".parse::<GaussianRational>().unwrap_err();
    let message = gaussian.reason().message();
    assert_eq!(
        chain(&gaussian).matches(message).count(),
        1,
        "{}",
        chain(&gaussian)
    );
}

/// The closure of a system file's functions named as the file names them
/// (`file_closure_report`, in the prelude): a function by its name or its display (`Ω`), a
/// family instance in either spelling (`P_{1,1}`, `Q_1_1`), each printed by the file's
/// display, is the closure `superint closure FILE NAMES` prints, whole, for the same names, in
/// every format (JSON's sections name their file, which text does not show): a program had to
/// build each `NamedFunction` by hand, instances and displays included.
#[test]
fn a_files_closure_from_a_program_is_the_command_lines() {
    let rotor = load_system_file("systems/harmonic-rotor.toml", &LimitsOverride::default())
        .unwrap()
        .with_caller(Caller::CommandLine);
    let resonance = "p_theta = I*omega";
    let closures: [(&[&str], Option<&str>); 2] = [
        (&SU2, None),
        (&["L", "Ω", "P_{1,1}", "Q_1_1"], Some(resonance)),
    ];
    for (names, when) in closures {
        let mut options = ClosureOptions::new(2);
        if let Some(w) = when {
            options = options.when(rotor.condition(w).unwrap());
        }
        let (report, algebra) =
            file_closure_report(&rotor, names, &options, Caller::CommandLine).unwrap();
        assert!(report.all_proved());
        let mut args = vec!["closure", "systems/harmonic-rotor.toml"];
        args.extend(names);
        if let Some(w) = when {
            args.extend(["--when", w]);
        }
        args.push("--no-timings");
        for format in Format::ALL {
            let printed = crate::superint_ok(&[&args[..], &["--format", format.name()]].concat());
            let rendered = render(&report, format, &RenderOptions::reproducible());
            pretty_assertions::assert_eq!(rendered, printed, "{names:?} {format:?}");
        }
        if when.is_some() {
            assert_eq!(algebra.display, ["L", "Ω", "P_{1,1}", "Q_{1,1}"]);
            assert_eq!(algebra.names[2..], ["P_1_1", "Q_1_1"]);
        }
    }
}

/// A system file's search from a program (`file_search_report`) marks its sections with the
/// file, as a file's closure does, so that a reader of several files' reports tells each one's
/// file: its JSON's sections said `"file": null`, where `superint search FILE` and a closure's
/// report said the file; with the command line's caller it is what `superint search FILE`
/// prints, whole, in every format (text, Markdown and LaTeX name no section's file).
#[test]
fn a_files_search_from_a_program_is_about_its_file_as_the_command_lines() {
    let path = "systems/fock-darwin.toml";
    let fd = load_system_file(path, &LimitsOverride::default())
        .unwrap()
        .with_caller(Caller::CommandLine);
    // The command line's space: its degrees of the kinds the file has none of are 2 and 1.
    let space = SearchSpace::default()
        .momenta_degree(2)
        .positions_degree(2)
        .trig_degree(0)
        .poisson_degree(2)
        .denominators_degree(2)
        .radicals_degree(1);
    let options = SearchOptions::new(space).when(fd.condition("a = 2*b").unwrap());
    let (report, _) = file_search_report(&fd, &options, Caller::CommandLine).unwrap();
    let (closure, _) =
        file_closure_report(&fd, &["H", "L"], &ClosureOptions::new(1), Caller::Program).unwrap();
    for sections in [&report.sections, &closure.sections] {
        assert!(sections.iter().all(|s| s.file.as_deref() == Some(path)));
    }
    let args = [
        "search",
        path,
        "--when",
        "a = 2*b",
        "--momenta-degree",
        "2",
        "--positions-degree",
        "2",
        "--trig-degree",
        "0",
        "--no-timings",
    ];
    for format in Format::ALL {
        let printed = crate::superint_ok(&[&args[..], &["--format", format.name()]].concat());
        let rendered = render(&report, format, &RenderOptions::reproducible());
        pretty_assertions::assert_eq!(rendered, printed, "{format:?}");
    }
    let json: serde_json::Value = serde_json::from_str(&render(
        &report,
        Format::Json,
        &RenderOptions::reproducible(),
    ))
    .unwrap();
    let files: Vec<&serde_json::Value> = json["sections"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| &s["file"])
        .collect();
    assert_eq!(files, [path, path]);
}

/// A name that names no generator is refused by the library as by the command line, before
/// anything is computed, typed, at its line and column in the name: a blank one, a function
/// given twice (by its name, by its name and display, an instance in two spellings), an
/// expression given as a name (its advice the library's call for a program, `--define` for
/// the command line), an unknown name and a parameter (`M`, `ω`: its advice the library's
/// option or `--symbolic`; it was refused by the engine, after the names were read, with no
/// place) and a name holding a line break or a tab, first, escaped (`'G1\nG2'`: its line
/// break was printed inside the advice to `--define 'G=G1`, `G2'`); from `<command line>` when
/// the file is the command line's, with the very message the command line prints, and a
/// built-in system's closure refuses a parameter and a line break alike.
#[test]
fn a_files_closure_refuses_a_name_as_the_command_line_does() {
    let rotor =
        load_system_file("systems/harmonic-rotor.toml", &LimitsOverride::default()).unwrap();
    let options = ClosureOptions::new(2);
    // The names, and the refusal's origin, line and column, and message's start.
    type Refused<'a> = (&'a [&'a str], &'a str, (usize, usize), &'a str);
    let parameter = "is a parameter of the system, not a function of its phase space: the \
                     brackets and relations hold the parameters in their coefficients \
                     (ClosureOptions::symbolic keeps it symbolic there)";
    let (m, omega) = (format!("'M' {parameter}"), format!("'ω' {parameter}"));
    let refused: [Refused; 11] = [
        (
            &["L", "  "],
            "<name>",
            (1, 3),
            "expected the name of a function",
        ),
        (
            &["L", "G1", " L"],
            "<expression>",
            (1, 2),
            "'L' is given twice: the closure takes each function once",
        ),
        (
            &["L", "Omega", "Ω"],
            "<expression>",
            (1, 1),
            "'Ω' is 'Omega', given before: the closure takes each function once",
        ),
        (
            &["L", "K_1_1", "K_{01,1}"],
            "<expression>",
            (1, 1),
            "'K_{01,1}' is 'K_1_1', given before",
        ),
        (
            &["L", "2*L"],
            "<expression>",
            (1, 1),
            "'2*L' is an expression, not the name of a function: name it with \
             LoadedSystem::add_function (add_function(\"G\", \"G\", \"2*L\"), then G among the \
             generators)",
        ),
        (
            &["L", "{L, G1}"],
            "<expression>",
            (1, 1),
            "'{L, G1}' is an expression",
        ),
        (
            &["L", "G1", "Foo"],
            "<expression>",
            (1, 1),
            "unknown name 'Foo'",
        ),
        (&["L", "M"], "<expression>", (1, 1), &m),
        (&["L", "ω", "G1"], "<expression>", (1, 1), &omega),
        (
            &["L", "G1\nG2"],
            "<expression>",
            (1, 3),
            "'G1\\nG2' holds a line break (U+000A), which no name does: give each generator \
             as a name of its own",
        ),
        // Before it is refused as given twice, which quotes it too.
        (
            &["L", "L\t", "L\t"],
            "<expression>",
            (1, 2),
            "'L\\t' holds a tab (U+0009)",
        ),
    ];
    for (names, origin, place, message) in refused {
        let err = file_closure_report(&rotor, names, &options, Caller::Program).unwrap_err();
        assert_eq!(err.kind, ErrorKind::Expression, "{names:?}: {err}");
        assert_eq!(err.origin, origin, "{names:?}: {err}");
        assert_eq!(err.line_col(), Some(place), "{names:?}: {err}");
        assert!(err.message.starts_with(message), "{names:?}: {err}");
        // The command line's file: the error is the command line's, byte for byte.
        let cli = rotor.clone().with_caller(Caller::CommandLine);
        let err = file_closure_report(&cli, names, &options, Caller::CommandLine).unwrap_err();
        assert_eq!(err.origin, "<command line>", "{names:?}: {err}");
        let mut args = vec!["closure", "systems/harmonic-rotor.toml", "--"];
        args.extend(names);
        let said = crate::superint_refused(&args);
        pretty_assertions::assert_eq!(said, format!("superint: error: {err}\n"), "{names:?}");
    }
    let none: [&str; 0] = [];
    let err = file_closure_report(&rotor, &none, &options, Caller::Program).unwrap_err();
    assert_eq!(err.kind, ErrorKind::Claim, "{err}");
    assert!(err.message.starts_with("give the generators"), "{err}");
    let said = crate::superint_refused(&["closure", "--system", "harmonic", "H", "G1\nG2"]);
    pretty_assertions::assert_eq!(
        said,
        "superint: error: <command line>:1:3: 'G1\\nG2' holds a line break (U+000A), which no \
         name does: give each generator as an argument of its own\n 1 | G1\n   |   ^\n"
    );
    let said = crate::superint_refused(&["closure", "--system", "harmonic", "H", "ω"]);
    pretty_assertions::assert_eq!(
        said,
        "superint: error: <command line>:1:1: 'ω' is a parameter of the system, not a function \
         of its phase space: the brackets and relations hold the parameters in their \
         coefficients (--symbolic omega keeps it symbolic there)\n 1 | ω\n   | ^\n"
    );
}

/// A name holding a line break or a tab (two names in one argument, `$'L\nG1'` in a shell) is
/// refused first, at that character, the name escaped, wherever a list of names is read: a
/// table's functions, of a file and of a built-in system, from a program too (it printed
/// `'L` and `G1' is not a function` on two lines), and the names of `--symbolic`, `--fix` and
/// `--family` (`--symbolic: 'M` and `omega' is not a parameter`), each with its own usage.
#[test]
fn a_name_holding_a_line_break_is_refused_first_in_every_list_of_names() {
    let rotor = harmonic_rotor_file();
    let err = table_report(&rotor, &["L\nG1", "G2"]).unwrap_err();
    assert_eq!(
        (err.kind, err.line_col()),
        (ErrorKind::Expression, Some((1, 2)))
    );
    assert_eq!(
        err.message,
        "'L\\nG1' holds a line break (U+000A), which no name does: give each function as a \
         name of its own"
    );
    // Before a name given twice, whose message quotes it too.
    let err = table_report(&rotor, &["L\t", "L\t"]).unwrap_err();
    assert!(
        err.message.starts_with("'L\\t' holds a tab (U+0009)"),
        "{err}"
    );
    for system in [
        &["systems/harmonic-rotor.toml"][..],
        &["--system", "harmonic"],
    ] {
        let args = [&["table"], system, &["L\nG1", "G2"]].concat();
        pretty_assertions::assert_eq!(
            crate::superint_refused(&args),
            "superint: error: <command line>:1:2: 'L\\nG1' holds a line break (U+000A), which \
             no name does: give each function as an argument of its own\n 1 | L\n   |  ^\n"
        );
    }
    let search = [
        "search",
        "systems/harmonic-rotor.toml",
        "--momenta-degree",
        "1",
    ];
    let tower = [
        "tower",
        "--system",
        "systems/harmonic-rotor.toml",
        "--max",
        "1",
    ];
    let lists: [(&[&str], &str, &str); 3] = [
        (
            &search,
            "--symbolic",
            "1:2: --symbolic: 'M\\nomega' holds a line break (U+000A), which no name does: \
             name parameters as A,B, such as M,omega\n 1 | M\n   |  ^\n",
        ),
        (
            &search,
            "--fix",
            "1:7: --fix: 'om\\tega' holds a tab (U+0009), which no name does: give a value as \
             NAME=VALUE, such as omega=1\n 1 | M=2,om\tega=1\n   |       ^\n",
        ),
        (
            &tower,
            "--family",
            "1:2: --family: 'K\\nKbar' holds a line break (U+000A), which no name does: \
             families are named separated by commas, such as K,Kbar\n 1 | K\n   |  ^\n",
        ),
    ];
    for (command, option, said) in lists {
        let list = match option {
            "--symbolic" => "M\nomega",
            "--fix" => "M=2,om\tega=1",
            _ => "K\nKbar",
        };
        let args = [command, &[option, list]].concat();
        pretty_assertions::assert_eq!(
            crate::superint_refused(&args),
            format!("superint: error: <command line>:{said}")
        );
    }
}

/// The spaces around a name are no part of it, in every list of names: a closure's generator
/// ` M` is the parameter `M`, refused as such (it was refused as an expression, with the
/// advice to `--define 'G= M'`), ` L` and `L ` are the function `L` (` L` was refused as an
/// expression, and `L ` printed as `L `, `Zbar ` as `Zbar`, not `Z̄`), of a file and of a
/// built-in system, from a program too; a table's ` M` and ` Foo` are refused at the name's
/// own column, 2, in the name as written (they were at column 1 of the name without its
/// space); and the names of `--symbolic`, `--fix` and `--family` are read so too.
#[test]
fn a_name_with_spaces_around_it_is_that_name_in_every_list_of_names() {
    let rotor = harmonic_rotor_file();
    let options = ClosureOptions::new(1);
    let m = "'M' is a parameter of the system, not a function of its phase space";
    for names in [&["H", " M"][..], &["H", "M "]] {
        let err = file_closure_report(&rotor, names, &options, Caller::Program).unwrap_err();
        assert_eq!(err.kind, ErrorKind::Expression, "{names:?}: {err}");
        let column = 1 + names[1].find('M').unwrap();
        assert_eq!(err.line_col(), Some((1, column)), "{names:?}: {err}");
        assert!(err.message.starts_with(m), "{names:?}: {err}");
    }
    for (written, shown) in [
        (" L", "L"),
        ("L ", "L"),
        ("Zbar ", "Z̄"),
        (" P_{1,1} ", "P_{1,1}"),
    ] {
        let (report, algebra) =
            file_closure_report(&rotor, &["H", written], &options, Caller::Program).unwrap();
        assert_eq!(algebra.display, ["H", shown], "{written:?}");
        assert_eq!(
            report.title,
            format!("Closure of `H`, `{shown}` for the harmonic rotor")
        );
    }
    for system in [
        &["systems/harmonic-rotor.toml"][..],
        &["--system", "harmonic"],
    ] {
        let closure =
            |name: &'static str| [&["closure"], system, &["--degree", "1", "H", name]].concat();
        pretty_assertions::assert_eq!(
            crate::superint_refused(&closure(" M")),
            format!(
                "superint: error: <command line>:1:2: {m}: the brackets and relations hold the \
                 parameters in their coefficients (--symbolic M keeps it symbolic there)\n 1 \
                 |  M\n   |  ^\n"
            )
        );
        pretty_assertions::assert_eq!(
            crate::superint_ok(&[&["--no-timings"], &closure(" Zbar ")[..]].concat()),
            crate::superint_ok(&[&["--no-timings"], &closure("Zbar")[..]].concat()),
        );
        let table = [&["table"], system, &[" M", "L"]].concat();
        let said = crate::superint_refused(&table);
        assert!(
            said.starts_with(
                "superint: error: <command line>:1:2: 'M' is a parameter, not a function"
            ),
            "{said}"
        );
        assert!(said.ends_with("\n 1 |  M\n   |  ^\n"), "{said}");
    }
    let err = table_report(&rotor, &[" Foo", "L"]).unwrap_err();
    assert_eq!(
        (err.kind, err.line_col()),
        (ErrorKind::Expression, Some((1, 2)))
    );
    assert!(err.message.starts_with("'Foo' is not a function"), "{err}");
    let shown = |names: &[&str]| {
        let report = table_report(&rotor, names).unwrap();
        render(&report, Format::Text, &RenderOptions::reproducible())
    };
    assert_eq!(shown(&[" L ", "G1"]), shown(&["L", "G1"]));
    // The lists given to an option read their names so already.
    let search = [
        "search",
        "systems/harmonic-rotor.toml",
        "--momenta-degree",
        "1",
    ];
    let tower = [
        "tower",
        "--system",
        "systems/harmonic-rotor.toml",
        "--max",
        "1",
    ];
    for args in [
        [&search[..], &["--symbolic", " M , omega"]].concat(),
        [&search[..], &["--fix", " M =2"]].concat(),
        [&tower[..], &["--family", " K "]].concat(),
    ] {
        crate::superint_ok(&args);
    }
}

/// A closure's generator with a space outside its braces (`L G1`, which the parser reads as
/// `L*G1`) is refused as the expression it is, as `L*G1` and `L+G1` are, of a file, a built-in
/// system and a program alike: the name rule took a space anywhere, so `L G1` was taken as one
/// generator named `L G1` (`the generators H, L G1`). A space inside the braces is still an
/// instance's (`P_{1, 1}`), and a table's `L G1` is no function of the file.
#[test]
fn a_space_outside_braces_makes_a_generator_an_expression() {
    let rotor = harmonic_rotor_file();
    let options = ClosureOptions::new(1);
    for written in ["L G1", " L G1 ", "L*G1"] {
        let err =
            file_closure_report(&rotor, &["H", written], &options, Caller::Program).unwrap_err();
        let name = written.trim();
        assert_eq!(err.kind, ErrorKind::Expression, "{written:?}: {err}");
        assert_eq!(
            err.line_col(),
            Some((1, 1 + written.find(name).unwrap())),
            "{written:?}: {err}"
        );
        assert!(
            err.message.starts_with(&format!(
                "'{name}' is an expression, not the name of a function: name it with \
                 LoadedSystem::add_function (add_function(\"G\", \"G\", \"{name}\")"
            )),
            "{written:?}: {err}"
        );
    }
    let (_, algebra) =
        file_closure_report(&rotor, &["H", "P_{1, 1}"], &options, Caller::Program).unwrap();
    assert_eq!(algebra.display, ["H", "P_{1, 1}"]);
    for system in [
        &["systems/harmonic-rotor.toml"][..],
        &["--system", "harmonic"],
    ] {
        let said = crate::superint_refused(&[&["closure"], system, &["H", "L G1"]].concat());
        pretty_assertions::assert_eq!(
            said,
            "superint: error: <command line>:1:1: 'L G1' is an expression, not the name of a \
             function: name it with --define (--define 'G=L G1', then G among the \
             generators)\n 1 | L G1\n   | ^^^^\n"
        );
        let said = crate::superint_refused(&[&["table"], system, &["L G1", "L"]].concat());
        assert!(
            said.starts_with("superint: error: <command line>:1:1: 'L G1' is not a function"),
            "{said}"
        );
    }
}

/// A closure's generator that is neither a name nor an expression (`P _{1,1}`, `L+`) gets the
/// parser's error, which says what is wrong with it, from a program and the command line,
/// of a file and a built-in system: it was refused as an expression, with the advice to
/// `--define 'G=P _{1,1}'`, which fails as the generator did.
#[test]
fn a_generator_that_is_no_expression_gets_the_parsers_error() {
    let rotor = harmonic_rotor_file();
    let options = ClosureOptions::new(1);
    let cases = [
        (
            "P _{1,1}",
            3,
            "'_{1,1}' is a subscript with no name before it: a subscript follows its name, \
             before a power, as in x_{1}^{2}",
            "\n 1 | P _{1,1}\n   |   ^^^^^^\n",
        ),
        (
            "L+",
            3,
            "expected an expression after '+', found end of input",
            "\n 1 | L+\n   |   ^\n",
        ),
    ];
    for (written, column, why, excerpt) in cases {
        let err =
            file_closure_report(&rotor, &["H", written], &options, Caller::Program).unwrap_err();
        assert_eq!(err.kind, ErrorKind::Expression, "{written:?}: {err}");
        assert_eq!(err.line_col(), Some((1, column)), "{written:?}: {err}");
        assert!(err.message.starts_with(why), "{written:?}: {err}");
        for system in [
            &["systems/harmonic-rotor.toml"][..],
            &["--system", "harmonic"],
        ] {
            let said = crate::superint_refused(&[&["closure"], system, &["H", written]].concat());
            pretty_assertions::assert_eq!(
                said,
                format!("superint: error: <command line>:1:{column}: {why}{excerpt}")
            );
        }
    }
}

/// A parameter named by its display as a closure's generator (`ω₊`, the parameter `a` of
/// `systems/fock-darwin.toml`, printed so) is refused as the parameter it is, as `a` is: the
/// name rule took no subscript sign, so `ω₊` was refused as an expression, with the advice to
/// `--define 'G=ω₊'`, a constant. A name whose sign no display has (`ω₋` of the harmonic
/// rotor) is an unknown name, not the parameter `ω` its letters spell.
#[test]
fn a_parameter_named_by_its_display_is_refused_as_a_parameter() {
    let fock_darwin =
        load_system_file("systems/fock-darwin.toml", &LimitsOverride::default()).unwrap();
    let options = ClosureOptions::new(2);
    let parameter = "is a parameter of the system, not a function of its phase space: the \
                     brackets and relations hold the parameters in their coefficients";
    for name in ["a", "ω₊"] {
        let names = ["H", name];
        let err = file_closure_report(&fock_darwin, &names, &options, Caller::Program);
        let err = err.unwrap_err();
        assert_eq!(
            (err.kind, err.line_col()),
            (ErrorKind::Expression, Some((1, 1)))
        );
        assert_eq!(
            err.message,
            format!("'{name}' {parameter} (ClosureOptions::symbolic keeps it symbolic there)")
        );
        let said = crate::superint_refused(&["closure", "systems/fock-darwin.toml", "H", name]);
        let caret = "^".repeat(name.chars().count());
        pretty_assertions::assert_eq!(
            said,
            format!(
                "superint: error: <command line>:1:1: '{name}' {parameter} (--symbolic a keeps \
                 it symbolic there)\n 1 | {name}\n   | {caret}\n"
            )
        );
    }
    let said = crate::superint_refused(&["closure", "systems/harmonic-rotor.toml", "H", "ω₋"]);
    assert!(
        said.starts_with("superint: error: <command line>:1:1: unknown name 'ω₋'"),
        "{said}"
    );
}

/// What the engine refuses once the names are read is an error of the file without a place:
/// the closure's products past the term limit are a limit, with the hint that raises it, and a
/// condition the flow leaves is the engine's refusal; each says it was computing the closure.
#[test]
fn a_files_closure_refused_by_the_engine_is_an_error_of_the_file() {
    let path = "systems/harmonic-rotor.toml";
    let small = load_system_file(path, &LimitsOverride::default().max_terms(60)).unwrap();
    let err =
        file_closure_report(&small, &SU2, &ClosureOptions::new(4), Caller::Program).unwrap_err();
    assert_eq!(
        (err.kind, err.location.is_none()),
        (ErrorKind::Limit, true),
        "{err}"
    );
    assert_eq!(err.origin, path);
    assert!(
        err.message.starts_with(
            "computing the closure: the products of the generators up to degree 4 would have \
             more than 60 terms together (the term limit)"
        ),
        "{err}"
    );
    assert!(
        err.hint
            .as_deref()
            .is_some_and(|h| h.contains("LimitsOverride")),
        "{err}"
    );
    let rotor = load_system_file(path, &LimitsOverride::default()).unwrap();
    let off_the_flow = ClosureOptions::new(2).when(rotor.condition("x = y").unwrap());
    let err = file_closure_report(&rotor, &["L", "H"], &off_the_flow, Caller::Program).unwrap_err();
    assert_eq!(
        (err.kind, err.location.is_none()),
        (ErrorKind::Engine, true),
        "{err}"
    );
    assert!(
        err.message
            .starts_with("computing the closure: the flow leaves the surface x = y"),
        "{err}"
    );
}

/// Generators a program gives by their values (the command line's `--define`) stand where
/// the names name them, else after them, each printed by its display; one named as the
/// system names something, one given twice, one that prints as a name of the system or one
/// built in another variable set is refused, of kind `Name`, before any name is read.
#[test]
fn a_files_closure_takes_generators_given_by_their_values() {
    let rotor = harmonic_rotor_file();
    let value = |text: &str| rotor.parse(text).unwrap();
    let casimir = NamedFunction::new("C", "C", value("4*G1^2 + G2^2 + omega^2*L^2"));
    let ladder = NamedFunction::new("R_1_1", "R_{1,1}", value("Z*exp(-i*theta)"));
    let given = [casimir.clone(), ladder];
    let generators = rotor.closure_generators(&["C", "L"], &given).unwrap();
    let shown: Vec<&str> = generators.iter().map(|g| g.display.as_str()).collect();
    assert_eq!(shown, ["C", "L", "R_{1,1}"]);
    assert_eq!(generators[0].expr, casimir.expr);
    let other = Vars::builder().coordinate("q").build().unwrap();
    let refused = [
        (
            NamedFunction::new("L", "L", value("x")),
            "L is a function of the system",
        ),
        (
            NamedFunction::new("F_1", "F_1", value("x")),
            "the generator F_1 would",
        ),
        (
            NamedFunction::new("W", "W", Expr::parse(&other, "q").unwrap()),
            "the value of W was built in another variable set",
        ),
    ];
    for (generator, message) in refused {
        let err = rotor.closure_generators(&["L"], &[generator]).unwrap_err();
        assert_eq!(err.kind, ErrorKind::Name, "{err}");
        assert!(err.message.starts_with(message), "{err}");
    }
    let twice = [casimir.clone(), casimir];
    let err = rotor.closure_generators(&["L"], &twice).unwrap_err();
    assert_eq!(err.message, "C is defined twice: give each name once");
}

/// A report's text and its LaTeX are written once, into a text of just their length: joining
/// the lines and then pushing the last newline copied the whole into twice its length, which
/// for a bracket of 635 MB printed was 0.6 GB of the peak (docs/performance.md, step 164).
#[test]
fn a_reports_text_is_written_at_its_length() {
    let file = harmonic_rotor_file();
    let report = bracket_report(&file, "P_6_6", "Q_6_5", None).unwrap();
    for format in [Format::Text, Format::Latex] {
        let text = render(&report, format, &RenderOptions::reproducible());
        assert!(text.lines().count() > 20, "{text}");
        assert!(text.ends_with('\n') && !text.ends_with("\n\n"), "{text}");
        assert_eq!(text.capacity(), text.len(), "{format:?}");
    }
}

/// A built-in system's limit error, made for limits already at or past the most the search
/// for the least that builds it may try (a degree limit above `max_degree`'s ceiling of 32767,
/// a term limit of `usize::MAX`), says the engine's message rather than panicking in that
/// search (`clamp` with its least above its most, `given + 1` past `u64::MAX`).
#[test]
fn a_built_in_systems_refusal_at_the_limits_ceiling_does_not_panic() {
    use superint::discovery::{builtin_system, builtin_system_refused};
    let degree = builtin_system("harmonic", true, Limits::default().max_degree(1)).unwrap_err();
    let terms = builtin_system("harmonic", true, Limits::default().max_terms(10)).unwrap_err();
    for (limits, e) in [
        (Limits::default().max_degree(32767), &degree),
        (Limits::default().max_degree(u32::MAX), &degree),
        (Limits::default().max_terms(usize::MAX), &terms),
    ] {
        let err = builtin_system_refused("harmonic", true, limits, e);
        assert_eq!(err.kind, superint::system_file::ErrorKind::Limit);
        assert_eq!(
            err.message,
            format!("the system does not fit the limits given: {e}")
        );
    }
}

/// Who gave a text is set where its source is made, not read from its name: a program's own
/// system file named in angle brackets (`<generated>`, as a program may name a text it wrote)
/// is still the file's own text, whose limit its `[limits]` raises first, as a file on disk's
/// is; it was told a program's text by its `<` and advised the loader's `LimitsOverride` first.
#[test]
fn a_files_own_text_named_in_angle_brackets_is_hinted_as_the_files() {
    let text = "name = \"t\"\nhamiltonian = \"(p_x^2 + x^2)/2\"\n[phase_space]\n\
                coordinates = [\"x\"]\n[limits]\nmax_degree = 100\n[[claim]]\nid = \"a\"\n\
                claim = \"{x^2000, H} = -2000*x^1999*p_x\"\n";
    let hint = |origin: &str| {
        let file = superint::system_file::load_str(origin, text, &LimitsOverride::default());
        let checked = superint::system_file::check_report([&file.unwrap()]);
        checked.unwrap_err().hint.unwrap()
    };
    let own = "if the machine has the memory, raise the limit with max_degree under [limits] in \
               the file (on the command line, --max-degree D; in a program, the LimitsOverride \
               given to the loader)";
    assert_eq!(hint("t.toml"), own);
    assert_eq!(hint("<generated>"), own);
}

/// The front page of the docs links the workspace's crates by their pages: by name
/// (`` [`trigpoly`] ``) rustdoc links a crate only when its pages exist when it starts on this
/// one, and `cargo doc` documents the crates at once, so that a fresh run showed `[trigpoly]`
/// as plain text.
#[test]
fn the_front_page_links_the_workspace_crates_by_their_pages() {
    let lib = include_str!("../../src/lib.rs");
    let front: Vec<&str> = lib
        .lines()
        .take_while(|l| l.starts_with("//"))
        .filter_map(|l| l.strip_prefix("//!"))
        .collect();
    let front = front.join("\n");
    for name in ["trigpoly", "brackets"] {
        let by_page = format!("[`{name}`][{name}-crate]");
        assert!(front.contains(&by_page), "{name}");
        assert!(!front.contains(&format!("[`{name}`] ")), "{name} by name");
        assert!(!front.contains(&format!("[`{name}`])")), "{name} by name");
        let target = format!("\n [{name}-crate]: ../{name}/index.html");
        assert!(front.contains(&target), "{name}: {front}");
    }
}
