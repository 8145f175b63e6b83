//! Expressions written in LaTeX: what superint prints in LaTeX reads back to the same value,
//! for every file of `systems/`, and the command line reads LaTeX as it reads the plain syntax.

use superint::render::tex::{math_with, relation};
use superint::report::Entry;
use superint::system_file::{check_report, load, ClaimForm, LimitsOverride, LoadedSystem};
use trigpoly::Style;

use crate::{scratch_text, superint_ok, superint_refused};

/// The files of `systems/`, sorted.
fn system_files() -> Vec<std::path::PathBuf> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("systems");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .expect("systems/")
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    files
}

/// Whether two values are the same: their difference is zero (a residual's normal form may
/// keep its content apart from its coefficients otherwise than a parsed one's).
fn same(a: &trigpoly::Expr, b: &trigpoly::Expr) -> bool {
    a == b || a.checked_sub(b).is_ok_and(|d| d.is_zero())
}

/// The value of `latex` in `file`, which must equal `want`: `what` says what it printed.
#[track_caller]
fn reads_back(file: &LoadedSystem, what: &str, latex: &str, want: &trigpoly::Expr) {
    let origin = file.source().origin.clone();
    match file.parse_argument(latex) {
        Ok(value) => assert!(
            same(&value, want),
            "{origin}: {what} printed as {latex} reads back as {value}, not {want}"
        ),
        Err(e) => panic!("{origin}: {what} printed as {latex} does not read back: {e}"),
    }
}

/// Every claim of every file of `systems/`, both of its sides as the LaTeX report sets them
/// (`math_with` of the statement, split at its relation), reads back to the value of the
/// side as the file writes it; so do the Hamiltonian, expanded and restated, each function's
/// printed name and value, each residual of a refuted claim and its restatement in the
/// file's functions (as its ASCII form reads), and each function of a rank claim as the
/// report names it.
#[test]
fn what_superint_prints_in_latex_reads_back_to_the_same_value() {
    let mut sides = 0;
    for path in system_files() {
        let file = load(&path, &LimitsOverride::default()).expect("the file loads");
        sides += printed_latex_reads_back(&file);
    }
    // Every file's claims were read, not none.
    assert!(sides > 400, "{sides} sides");
}

/// A file whose names a LaTeX printer could write so that they render otherwise or read back
/// as other names: Greek letters with digits after them (`theta1`, `alpha12`, `Omega1`), as a
/// subscript's piece (`p_theta1`, `omega_x1`, `L_theta1`) and before one (`theta1_x`); names
/// with subscripts (`omega_2`, `k_x`, `mu_a_b`) and their momenta; a word with digits inside
/// (`x2y`, `beta1x`); Greek letters before other letters (`alphab`); capital Greek (`Omega`,
/// `Lambda3`); omicron, which LaTeX writes as an italic o (`\mathit{o}`; a bare `o` was read as
/// no name); functions, a display and families named so; a family `K` beside a parameter
/// `K_x` (`K_{x}`) and a family `K1` (`K_{1;1,0}`), whose braces are not `K`'s; `hbar` and
/// `ell`, which print as `\hbar` and `\ell` (and `hbar2`, `\hbar_{2}`); a coordinate `u`
/// displayed `θ2`, whose momentum is `p_{\theta2}` as `p_theta1`'s is `p_{\theta1}`. What it
/// prints in LaTeX reads back to the same value, as every file's of `systems/` does.
const AWKWARD_NAMES: &str = r#"name = "names that print in LaTeX"
hamiltonian = "p_theta1^2/2 + p_omega_2^2/2 + p_k_x^2/2 + p_x2y^2/2 + p_q1^2/2 + p_phi2^2/(2*I) + p_theta1_y^2/2 + alpha12*theta1^2/2 + Omega*omega_2^2/2 + alphab*k_x^2 + beta1x*x2y^2 + mu_a_b*q1^2 + Lambda3*cos(phi2) + omega_x1*theta1*omega_2 + theta1_x*k_x + Omega1*theta1_y^2 + K_x*q1 + omicron*x2y + hbar*ell*u^2 + hbar2*p_u^2 + p_ell^2 + ell*hbar"

[phase_space]
coordinates = ["theta1", "omega_2", "k_x", "x2y", "q1", "theta1_y", "u", "ell"]
angles = ["phi2"]
parameters = ["I", "alpha12", "Omega", "Omega1", "alphab", "beta1x", "mu_a_b", "Lambda3", "omega_x1", "theta1_x", "K_x", "omicron", "hbar", "hbar2"]
display = { u = "θ2" }

[[function]]
name = "L_theta1"
value = "theta1*p_omega_2 - omega_2*p_theta1"

[[function]]
name = "Phi2"
value = "p_phi2^2/(2*I)"

[[function]]
name = "G1_x"
value = "p_k_x^2/2 + alphab*k_x^2"

[[function]]
name = "omega3"
value = "p_q1 + q1"

[[function]]
name = "psi2_a"
value = "p_theta1_y + theta1_y"

[[function]]
name = "Ab"
display = "A_theta1"
value = "p_x2y + i*x2y"

[[family]]
name = "Q_theta1"
value = "(p_q1 + i*q1)^m*exp(-i*n*phi2)"

[[family]]
name = "Omega2"
display = "Ω2"
value = "(p_q1 - i*q1)^m*exp(i*n*phi2)"

[[family]]
name = "K"
value = "(p_q1 + i*q1)^m*(p_q1 - i*q1)^n"

[[family]]
name = "K1"
value = "K_m_n*omega3"

[[claim]]
id = "k"
claim = "K1_{1,0} = K_1_0*omega3"

[[claim]]
id = "phi"
claim = "{Phi2, H} = Lambda3*sin(phi2)*p_phi2/I"

[[claim]]
id = "g"
claim = "{G1_x, H} = -theta1_x*p_k_x"

[[claim]]
id = "l"
claim = "{L_theta1, psi2_a} = 0"

[[claim]]
id = "q"
claim = "Q_theta1_1_0 = p_q1 + i*q1"

[[claim]]
id = "o"
claim = "Omega2_1_1*Q_theta1_1_1 = omega3^2"
expect = "refuted"

[[claim]]
id = "hbar"
claim = "{u, H} = 2*hbar2*p_u + hbar*ell"
expect = "refuted"

[[claim]]
id = "wrong"
claim = "{L_theta1, H} = omega_x1*theta1_x*alpha12*Ab*omega3*psi2_a*Omega1"
expect = "refuted"
"#;

/// What superint prints of a file with names that LaTeX could misread (`AWKWARD_NAMES`)
/// reads back to the same value.
#[test]
fn names_with_greek_letters_digits_and_subscripts_read_back_from_latex() {
    let path = scratch_text("latex-input", "awkward-names.toml", AWKWARD_NAMES);
    let file = load(&path, &LimitsOverride::default()).expect("the file loads");
    assert!(printed_latex_reads_back(&file) >= 14);
    // As a physicist writes them: `\theta 1_{x}` hung the subscript on the digit,
    // `p_{k,x}` read as two indices, `Q_{theta1;1,0}` spelled out t·h·e·t·a.
    let out = superint_ok(&["check", path.to_str().expect("a path"), "--format", "latex"]);
    for written in [
        r"\mathrm{\theta1}_{x}",
        r"p_{\theta1}",
        r"\theta_{1}",
        r"p_{k_{x}}",
        r"p_{\omega_{2}}",
        r"p_{\theta1_{y}}",
        r"L_{\theta1}",
        r"Q_{\theta1;1,0}",
        r"K_{1;1,0} &= K_{1,0} \omega_{3}",
        r"\mathit{o} \mathrm{x2y}",
        r"\{\theta_{2}, H\} &= 2 \hbar_{2} p_{\theta2} + \hbar\ell",
        r"p_{\ell}",
    ] {
        assert!(out.contains(written), "{written} in {out}");
    }
    for wrong in [
        r"\theta 1",
        "p_{k,x}",
        "{theta1;",
        r"p_{\theta_{2}}",
        r" {\hbar}",
        r" {\ell}",
        "mathrm{hbar",
        "mathrm{ell",
    ] {
        assert!(!out.contains(wrong), "{wrong} in {out}");
    }
}

/// Where LaTeX spells two names alike, a name written so is neither, and the error names
/// both: a system built in code, which no loader checked, with a parameter omicron (printed
/// `\mathit{o}`) beside a function `o`. A file cannot have such names: a family `K1`'s instance
/// `K_{1;2,3}` beside a parameter `K_1_2_3` (`K_{1,2,3}`), which read back alike, and a
/// family `K`'s instance `K_{1,2}` beside a function displayed `K_1_2` are refused at load
/// ([`a_name_printed_or_read_back_as_another_is_refused_at_load`]). Braces after `K` that are
/// another name's LaTeX read as that name (`K_{x}`, `K_{3}` of a function `K3`); braces that
/// are nobody's are a malformed instance, as before.
#[test]
fn a_name_that_latex_spells_as_two_is_refused_naming_both() {
    use superint::prelude::{Expr, PhaseSpace, System, Vars};
    let vars = Vars::builder()
        .coordinate("x")
        .momentum("p_x")
        .parameter("omicron")
        .build()
        .unwrap();
    let space = PhaseSpace::new(&vars, &[("x", "p_x")]).unwrap();
    let h = Expr::parse(&vars, "p_x^2/2 + omicron*x^2").unwrap();
    let mut system = System::new("unchecked", space, h).unwrap();
    system
        .define("o", "o", Expr::parse(&vars, "x + 1").unwrap())
        .unwrap();
    let unchecked = LoadedSystem::of_system(system);
    let err = unchecked.parse_argument(r"\mathit{o} x").unwrap_err();
    assert!(
        err.to_string().contains(
            "<expression>:1:1: '\\mathit{o}' names both the function o and the parameter \
             omicron in LaTeX, whose printed forms read alike: write the one meant by its name, \
             o or omicron"
        ),
        "{err}"
    );
    let file = scratch_text(
        "latex-input",
        "alike.toml",
        r#"name = "alike"
hamiltonian = "p_x^2/2 + x^2/2 + K_x*x"
[phase_space]
coordinates = ["x"]
parameters = ["K_x"]
[[function]]
name = "K3"
value = "x + 1"
[[family]]
name = "K"
value = "x^m*p_x^n"
[[family]]
name = "K2"
value = "x^m*p_x^n + 2"
"#,
    );
    let path = file.to_str().expect("a path");
    let out = superint_ok(&["expand", path, r"K_{x} + K_{3} + K_{2;3,4}"]);
    assert!(out.contains("K_x + K3 + K2_{3,4} = "), "{out}");
    let err = superint_refused(&["expand", path, r"K_{7}"]);
    assert!(
        err.contains("'K_{7}' is not an instance of the family K_m_n"),
        "{err}"
    );
}

/// A name that prints, or whose LaTeX reads back, as another name of the file does is refused
/// where it is declared, naming both: a function `o` beside a parameter omicron (`\mathit{o}`,
/// which reads back as `o`), either way round and shown otherwise too (the function's name is
/// what input names it by); a variable displayed `o` beside omicron; families `o` and omicron;
/// a family whose instance prints as a function's display (`K_{1,2}` of a display `K_1_2`), or
/// reads back as a parameter's name (`K_{1;2,3}` of a family `K1`, `K_{1,2,3}` of a parameter
/// `K_1_2_3`), or as a parameter's display; and a function a program adds so. Each loaded
/// before, and its LaTeX read back as the other name or as neither.
#[test]
fn a_name_printed_or_read_back_as_another_is_refused_at_load() {
    let head = "hamiltonian = \"p_x^2/2 + x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n";
    let function = |name: &str, display: &str| {
        format!("[[function]]\nname = \"{name}\"\ndisplay = \"{display}\"\nvalue = \"x\"\n")
    };
    let family = |name: &str| format!("[[family]]\nname = \"{name}\"\nvalue = \"x^m*p_x^n\"\n");
    let cases = [
        (
            format!("{head}parameters = [\"omicron\"]\n{}", function("o", "o")),
            "8:11: the function o would print as o in LaTeX, and the parameter omicron as \
             \\mathit{o}, which both read back as o: rename one, or give it another display",
        ),
        (
            format!("{head}parameters = [\"omicron\"]\n{}", function("o", "X")),
            "8:11: the function o would be named o, which the LaTeX of the parameter omicron, \
             \\mathit{o}, reads back as: rename one, or give it another display",
        ),
        (
            format!(
                "{head}parameters = [\"o\"]\n{}",
                function("omicron", "omicron")
            ),
            "8:11: the function omicron would print as \\mathit{o} in LaTeX, and the parameter \
             o as o, which both read back as o: rename one, or give it another display",
        ),
        (
            format!(
                "{head}{}{}",
                function("o", "o"),
                function("omicron", "omicron")
            ),
            "11:11: the function omicron would print as \\mathit{o} in LaTeX, and the function \
             o on line 7 as o, which both read back as o: rename one, or give it another display",
        ),
        (
            format!("{head}parameters = [\"a\", \"omicron\"]\ndisplay = {{ a = \"o\" }}\n"),
            "6:17: the parameter a would print as o in LaTeX, and the parameter omicron as \
             \\mathit{o}, which both read back as o: give it another display",
        ),
        (
            format!("{head}{}{}", family("o"), family("omicron")),
            "9:8: the family omicron would print as \\mathit{o}_{m,n} in LaTeX, and the family \
             o on line 6 as o_{m,n}, which both read back as o_m_n: rename one, or give it \
             another display",
        ),
        (
            format!("{head}{}{}", function("F", "K_1_2"), family("K")),
            "10:8: the family K's instance (1, 2) would print as K_{1,2} in LaTeX, as the \
             function F on line 7 does: rename one, or give it another display",
        ),
        (
            format!("{head}parameters = [\"K_1_2_3\"]\n{}", family("K1")),
            "7:8: the family K1's instance (2, 3) would print as K_{1;2,3} in LaTeX, and the \
             parameter K_1_2_3 as K_{1,2,3}, which both read back as K_1_2_3: rename one, or \
             give it another display",
        ),
        (
            format!(
                "{head}parameters = [\"a\"]\ndisplay = {{ a = \"K_1_1\" }}\n{}",
                family("K")
            ),
            "8:8: the family K's instance (1, 1) would print as K_{1,1} in LaTeX, as the \
             parameter a on line 6 does: rename one, or give it another display",
        ),
    ];
    for (k, (body, want)) in cases.iter().enumerate() {
        let text = format!("name = \"alike\"\n{body}");
        let file = scratch_text("latex-input", &format!("alike-{k}.toml"), &text);
        let err = superint_refused(&["check", file.to_str().expect("a path")]);
        assert!(
            err.contains(&format!("alike-{k}.toml:{want}")),
            "{text}\n{err}"
        );
    }
    let path = scratch_text(
        "latex-input",
        "family.toml",
        &format!("name = \"K\"\n{head}{}", family("K")),
    );
    let mut file = load(&path, &LimitsOverride::default()).expect("it loads");
    let err = file
        .add_function("F", "K_2_3", "x")
        .unwrap_err()
        .to_string();
    assert!(
        err.contains(
            "the function F would print as K_{2,3} in LaTeX, as the family K's instance (2, 3) \
             does"
        ),
        "{err}"
    );
}

/// Reads back what superint prints of `file` in LaTeX (its claims' sides, Hamiltonian,
/// functions, equations and residuals), each to its value; the number of claims' sides read.
fn printed_latex_reads_back(file: &LoadedSystem) -> usize {
    let mut sides = 0;
    let names = file.names();
    let h = file.system().hamiltonian();
    reads_back(file, "H", &h.render(Style::Latex), h);
    for f in file.system().functions() {
        reads_back(file, &f.name, &f.expr.render(Style::Latex), &f.expr);
        let name = brackets::table::latex_name(&f.display);
        reads_back(file, &f.name, &name, &f.expr);
    }
    for claim in file.claims() {
        match &claim.form {
            ClaimForm::Identity { lhs, rhs } => {
                let k = relation(&claim.statement).expect("a claim has its '='");
                let left = math_with(&claim.statement[..k], &names);
                let right = math_with(&claim.statement[k..], &names);
                let right = right.strip_prefix('=').expect("the right side follows '='");
                for (side, latex) in [(lhs, left.as_str()), (rhs, right)] {
                    let want = file.parse_argument(&side.value).expect("the side reads");
                    reads_back(file, &claim.id, latex, &want);
                    sides += 1;
                }
            }
            ClaimForm::Rank { functions, .. } => {
                for (shown, text) in functions {
                    let want = file.parse_argument(&text.value).expect("it reads");
                    reads_back(file, &claim.id, &math_with(shown, &names), &want);
                }
            }
            // A form added later fails here until this test reads its printed LaTeX back.
            other => panic!(
                "{}: a claim form this test does not read: {other:?}",
                claim.id
            ),
        }
    }
    let report = check_report(std::slice::from_ref(file)).expect("the file checks");
    for section in &report.sections {
        for entry in &section.entries {
            if let Entry::Equations(equations) = entry {
                for line in &equations.lines {
                    reads_back(file, &line.lhs, &line.rhs.render(Style::Latex), &line.rhs);
                    if let Some(restated) = line.restated(Style::Latex) {
                        reads_back(file, &line.lhs, &restated, &line.rhs);
                    }
                }
            }
        }
    }
    for claim in report.claims() {
        if let Some(residual) = &claim.residual {
            let what = format!("the residual of {}", claim.id);
            reads_back(file, &what, &residual.render(Style::Latex), residual);
            // Restated in the file's functions, the residual holds at the claim's
            // condition, where there is one: the LaTeX reads as the text does.
            if let Some(restated) = claim.residual_restated(Style::Latex) {
                let text = claim
                    .residual_restated(Style::Ascii)
                    .expect("an ASCII form");
                let want = file.parse_argument(&text).expect("the text reads back");
                reads_back(file, &what, &restated, &want);
            }
        }
    }
    sides
}

/// The command line reads an expression in LaTeX, and refuses an unknown command by name,
/// with its place, exit status 2.
#[test]
fn the_command_line_reads_latex() {
    let rotor = "systems/harmonic-rotor.toml";
    let out = superint_ok(&["expand", rotor, r"\frac{1}{2}\omega^{2} L"]);
    let plain = superint_ok(&["expand", rotor, "omega^2*L/2"]);
    let value = |out: &str| {
        let line = out
            .lines()
            .find(|l| l.contains(" = "))
            .expect("an equation");
        line.split_once(" = ").map(|(_, v)| v.trim().to_string())
    };
    assert!(out.contains("(1/2)ω² L"), "{out}");
    assert_eq!(value(&out), value(&plain), "{out}");
    // The names as they are printed: G_{1} of G1, \bar{Z} of Zbar, \bar{K}_{3,2} of an
    // instance of Kbar; the bracket \{ \}.
    let out = superint_ok(&[
        "expand",
        rotor,
        r"\{G_{1}, G_{2}\} + \omega^{2} L",
        r"\{\bar{K}_{3,2}, F_{1}\} + i(3\omega - 2\Omega) \bar{K}_{3,2}",
        r"\left\{\bar{Z}, F_{1}\right\} + i\omega\,\bar{Z}",
    ]);
    assert!(out.contains("{G1, G2} + ω² L"), "{out}");
    assert!(out.contains("{K̄_{3,2}, F1} + i(3ω − 2Ω) K̄_{3,2}"), "{out}");
    assert_eq!(out.matches("= 0\n").count(), 3, "{out}");
    let err = superint_refused(&["expand", rotor, r"\omega^{2} \foo"]);
    assert!(
        err.contains("<command line>:1:12: unknown LaTeX command '\\foo'"),
        "{err}"
    );
    // A condition in LaTeX.
    let out = superint_ok(&[
        "bracket",
        rotor,
        "P_{1,1}",
        "F_{1}",
        "--when",
        r"p_{\theta} = I\omega",
    ]);
    assert!(
        out.contains("at p_θ = Iω:\n    {P_{1,1}, F1} = 0\n"),
        "{out}"
    );
    // A name written in LaTeX that is no name of the file is an unknown name.
    let err = superint_refused(&["expand", rotor, r"G_{7}"]);
    assert!(err.contains("unknown name 'G_7'"), "{err}");
}

/// The square of a name with a prime and a subscript prints on an empty group, `P'_{1,1}{}^{2}`,
/// and reads back as the square of that name; an empty group that carries no superscript is
/// refused, and so is one that carries a second superscript, `P'_{1,1}{}^{2}{}^{3}`, which
/// LaTeX sets as `P'_{1,1}{}^{23}` (it was read as the power `2³`), at its place, exit 2.
#[test]
fn a_script_on_an_empty_group_belongs_to_the_name_before_it() {
    let rotor = "systems/gravity-rotor.toml";
    let text = "Pp_1_1^2 + 3*Lp^2";
    let out = superint_ok(&["expand", rotor, text, "--format", "latex"]);
    let printed = r"P'_{1,1}{}^{2} + 3 L'^{2}";
    assert!(out.contains(&format!("{printed} &= ")), "{out}");
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(rotor);
    let file = load(&path, &LimitsOverride::default()).expect("the file loads");
    let want = file.parse_argument(text).expect("it reads");
    reads_back(&file, text, printed, &want);
    reads_back(&file, text, r"P'_{1,1}{ } ^{2} + 3L'^2", &want);
    // The prime is the name's, not a superscript the empty group's would follow; a power is.
    reads_back(&file, text, r"P'_{1,1}{}^{2} + 3 L'{}^{2}", &want);
    let err = superint_refused(&["expand", rotor, r"L + P'_{1,1}{}^{2}{}^{3}"]);
    assert!(
        err.contains(
            "<command line>:1:19: '{}^{3}' after 'P'_{1,1}{}^{2}', which has a superscript \
             already, is ambiguous: LaTeX sets the two superscripts side by side, as one; put \
             'P'_{1,1}{}^{2}' in parentheses for a power of it, or write the exponent in one \
             group\n 1 | L + P'_{1,1}{}^{2}{}^{3}\n   |                   ^^^^^^\n"
        ),
        "{err}"
    );
    let cubed = file
        .parse_argument(r"(P'_{1,1}{}^{2}){}^{3}")
        .expect("it reads");
    assert!(same(
        &cubed,
        &file.parse_argument("Pp_1_1^6").expect("it reads")
    ));
    // A subscript on an empty group has no name to belong to (it was read as a name `_1`).
    for refused in ["L'{} + 1", "x{}_{1}"] {
        let err = file.parse_argument(refused).unwrap_err().to_string();
        assert!(
            err.contains("expected an expression after '{', found '}'"),
            "{refused}: {err}"
        );
    }
}

/// A system file may be written in LaTeX: its Hamiltonian, functions, claims and conditions,
/// its names as they print (`L_{z}` for a function `Lz` displayed so); an unknown command in
/// it is refused at its line and column.
#[test]
fn a_system_file_reads_latex() {
    let file = scratch_text(
        "latex-input",
        "oscillator.toml",
        r#"name = "oscillator in LaTeX"
hamiltonian = '\frac{p_{x}^{2} + p_{y}^{2}}{2M} + \tfrac{1}{2} M\omega^{2}\left(x^{2} + y^{2}\right)'

[phase_space]
coordinates = ["x", "y"]
parameters = ["M", "omega"]

[[function]]
name = "Lz"
display = "L_z"
value = 'x\,p_{y} - y\,p_{x}'

[[function]]
name = "A"
value = 'p_{x} + \mathrm{i} M\omega x'

[[function]]
name = "Abar"
display = "Ā"
value = '\operatorname{conj}(A)'

[[claim]]
id = "Lz"
claim = '\{L_{z}, H\} = 0'

[[claim]]
id = "ladder"
claim = '\left\{A, H\right\} = \mathrm{i}\omega A'

[[claim]]
id = "product"
claim = 'A \bar{A} = p_{x}^{2} + M^{2}\omega^{2} x^{2}'

[[claim]]
id = "at"
claim = '\{x, H\} = \frac{p_{x}}{M}'
when = 'p_{y} = M\omega x'
"#,
    );
    let path = file.to_str().expect("a path");
    let out = superint_ok(&["check", path, "--no-timings"]);
    assert!(out.contains("4 claims in 1 file: 4 proved"), "{out}");
    assert!(out.contains("A Ā = p_x² + M²ω²x²"), "{out}");
    let bad = scratch_text(
        "latex-input",
        "bad.toml",
        "hamiltonian = '\\frac{p_{x}^{2}}{2} + \\lambda x^{4}'\n[phase_space]\n\
         coordinates = [\"x\"]\nparameters = [\"lambda\"]\n[[claim]]\n\
         claim = '\\{x, H\\} = \\pdot{x}'\n",
    );
    let err = superint_refused(&["check", bad.to_str().expect("a path")]);
    assert!(
        err.contains("bad.toml:6:21: unknown LaTeX command '\\pdot'"),
        "{err}"
    );
}
