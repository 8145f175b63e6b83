//! The `superint` binary, run for real: whole outputs compared with snapshot files in
//! `tests/it/snapshots/`, every format parsed or checked for structure, exit codes.
//!
//! After an intended change of output, rewrite the snapshots with
//! `SUPERINT_UPDATE_SNAPSHOTS=1 cargo test --test it cli`, and read the diff.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use pretty_assertions::assert_eq;
use serde_json::Value;

use crate::{superint, superint_exits, superint_json, DEGREE_ONE_TRIG_ZERO};

fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).expect("stdout is UTF-8")
}

fn stderr(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).expect("stderr is UTF-8")
}

/// Runs the binary and expects exit code `code`; returns stdout.
#[track_caller]
fn run(args: &[&str], code: i32) -> String {
    stdout(&superint_exits(args, code))
}

fn snapshot_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/it/snapshots")
        .join(name)
}

/// Compares a whole output with its snapshot (or rewrites the snapshot when
/// `SUPERINT_UPDATE_SNAPSHOTS` is set).
#[track_caller]
fn assert_snapshot(name: &str, actual: &str) {
    let path = snapshot_path(name);
    if std::env::var_os("SUPERINT_UPDATE_SNAPSHOTS").is_some() {
        std::fs::create_dir_all(path.parent().expect("a parent")).expect("create snapshots/");
        std::fs::write(&path, actual).expect("write the snapshot");
        return;
    }
    let expected = std::fs::read_to_string(&path).unwrap_or_else(|e| {
        panic!(
            "{}: {e}; run with SUPERINT_UPDATE_SNAPSHOTS=1 to create it",
            path.display()
        )
    });
    assert_eq!(expected, actual, "output differs from {}", path.display());
}

#[test]
fn cli_default_job_text_matches_snapshot() {
    let out = run(&["--no-timings"], 0);
    assert_snapshot("paper.txt", &out);
    for claim in ["{L, G1} = −G2", "{L, G2} = 4 G1", "{G1, G2} = −ω² L"] {
        assert!(
            out.lines()
                .any(|l| l.trim_start().starts_with(claim) && l.ends_with("[C09 proved]")),
            "{claim} is not printed as proved"
        );
    }
}

#[test]
fn cli_paper_subcommand_is_the_default_job() {
    let default = run(&["--no-timings", "--format", "markdown"], 0);
    let paper = run(&["paper", "--format", "markdown", "--no-timings"], 0);
    assert_eq!(default, paper);
}

#[test]
fn cli_summary_line_has_the_count_and_the_seconds() {
    let out = run(&[], 0);
    let last = out.lines().last().expect("a summary line");
    assert!(
        last.starts_with("27 claims: 27 proved, 0 refuted (") && last.ends_with(" s)"),
        "{last}"
    );
    // Timings appear in the summary line only.
    let without = run(&["--no-timings"], 0);
    let body = |s: &str| s.lines().rev().skip(1).collect::<Vec<_>>().join("\n");
    assert_eq!(body(&out), body(&without));
    assert!(!without
        .lines()
        .last()
        .expect("a summary line")
        .contains(" s)"));
}

#[test]
fn cli_json_has_every_claim_proved() {
    let out = run(&["--format", "json", "--no-timings"], 0);
    let v: Value = serde_json::from_str(&out).expect("the output is JSON");
    assert_eq!(v["schema"], "superint-report/1");
    let claims = v["claims"].as_array().expect("a list of claims");
    assert!(claims.len() >= 25, "only {} claims", claims.len());
    for c in claims {
        assert_eq!(c["outcome"], "proved", "{c}");
        assert!(c["residual"].is_null(), "{c}");
        assert!(
            c["seconds"].is_null(),
            "--no-timings leaves seconds out: {c}"
        );
        for key in ["id", "statement", "condition", "kind", "witness", "note"] {
            assert!(c.get(key).is_some(), "{key} missing in {c}");
        }
    }
    for k in 1..=25 {
        let id = format!("C{k:02}");
        assert!(
            claims.iter().any(|c| c["id"] == id.as_str()),
            "{id} is missing"
        );
    }
    let summary = &v["summary"];
    assert_eq!(summary["all_proved"], true);
    assert_eq!(summary["refuted"], 0);
    assert!(summary["claims"].as_u64().expect("a count") >= 25);
    // Tables, proofs, towers and ranks come along; exact numbers are strings.
    assert_eq!(v["tables"][0]["entries"][2][3]["ascii"], "-G2");
    // Captions are plain text, without the markup's backticks.
    assert_eq!(
        v["tables"][0]["caption"],
        "{A, B} for the harmonic rotor (row A, column B)"
    );
    assert_eq!(v["tables"][0]["entries"][3][4]["text"], "−ω² L");
    assert!(!v["proofs"].as_array().expect("proofs").is_empty());
    assert_eq!(v["towers"][0]["checked"], 64);
    assert_eq!(
        (&v["towers"][0]["family"], &v["towers"][0]["ladder"]),
        (&serde_json::json!("K_{m,n}"), &serde_json::json!("Z"))
    );
    let rank = &v["ranks"][0];
    assert_eq!(rank["rank"], 5);
    assert!(rank["minor"]["value"].is_string());
}

#[test]
fn cli_json_timings_are_numbers() {
    let out = run(&["--format", "json", "tower", "--max", "2"], 0);
    let v: Value = serde_json::from_str(&out).expect("the output is JSON");
    assert!(v["summary"]["seconds"].is_number());
    assert!(v["claims"][0]["seconds"].is_number());
}

/// `\begin{…}`/`\end{…}` pairs nest, braces balance (ignoring `\{`, `\}`), and `$` pair up.
fn assert_balanced_latex(doc: &str) {
    let mut envs: Vec<&str> = Vec::new();
    let mut rest = doc;
    while let Some(k) = rest.find(['\\']) {
        rest = &rest[k + 1..];
        for (kw, open) in [("begin{", true), ("end{", false)] {
            if let Some(tail) = rest.strip_prefix(kw) {
                let name = &tail[..tail.find('}').expect("a closing brace")];
                if open {
                    envs.push(name);
                } else {
                    assert_eq!(envs.pop(), Some(name), "\\end{{{name}}} closes nothing");
                }
            }
        }
    }
    assert!(envs.is_empty(), "unclosed environments {envs:?}");
    let mut depth = 0i64;
    let mut dollars = 0;
    let mut escaped = false;
    for c in doc.chars() {
        match (escaped, c) {
            (true, _) => escaped = false,
            (false, '\\') => escaped = true,
            (false, '{') => depth += 1,
            (false, '}') => depth -= 1,
            (false, '$') => dollars += 1,
            _ => {}
        }
        assert!(depth >= 0, "a brace closes nothing");
    }
    assert_eq!(depth, 0, "unbalanced braces");
    assert_eq!(dollars % 2, 0, "unpaired $");
}

#[test]
fn cli_latex_is_a_complete_valid_document() {
    let doc = run(&["--format", "latex", "--no-timings"], 0);
    assert!(doc.starts_with("\\documentclass{article}\n"));
    assert!(doc.contains("\\usepackage{amsmath}"));
    assert!(doc.contains("\\begin{document}"));
    assert!(doc.trim_end().ends_with("\\end{document}"));
    assert!(doc.contains("\\begin{align*}") && doc.contains("\\begin{array}"));
    assert!(doc.contains(r"\{L, G_{1}\} &= -G_{2} \tag*{[C09 proved]}"));
    assert!(doc.is_ascii(), "LaTeX output is ASCII");
    assert_balanced_latex(&doc);
    compile_within(&doc, 1.0);
}

/// Whether `pdflatex` is installed; CI installs it and sets `SUPERINT_REQUIRE_PDFLATEX`, so that
/// there the LaTeX tests cannot pass by skipping.
fn pdflatex_available() -> bool {
    let found = Command::new("pdflatex")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    assert!(
        found || std::env::var_os("SUPERINT_REQUIRE_PDFLATEX").is_none(),
        "SUPERINT_REQUIRE_PDFLATEX is set, but pdflatex is not installed"
    );
    found
}

/// Compiles with `pdflatex` when it is installed (CI installs it), and fails on an error or on
/// a line set wider than the page by more than `slack_pt` points.
pub(crate) fn compile_within(doc: &str, slack_pt: f64) {
    if !pdflatex_available() {
        return;
    }
    static COUNT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = COUNT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("superint-latex-{}-{n}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    std::fs::write(dir.join("paper.tex"), doc).expect("write paper.tex");
    let o = Command::new("pdflatex")
        .args(["-interaction=nonstopmode", "-halt-on-error", "paper.tex"])
        .current_dir(&dir)
        .output()
        .expect("pdflatex runs");
    let log = String::from_utf8_lossy(&o.stdout).to_string();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(o.status.success(), "pdflatex failed:\n{log}");
    for line in log.lines().filter(|l| l.starts_with("Overfull \\hbox (")) {
        let points: f64 = line["Overfull \\hbox (".len()..]
            .split("pt")
            .next()
            .and_then(|p| p.parse().ok())
            .expect("an overfull box's width");
        assert!(points <= slack_pt, "{line}\n{log}");
    }
}

/// A description's formulas, between backticks, compile whatever characters they hold: 60
/// formulas of up to 30 characters of the notation (script signs and digits, accents, braces,
/// primes, TeX's special characters, and two that LaTeX has no letter for, written by their
/// code points), and 160 of up to 8 scripts, groups and names, drawn by a fixed linear
/// congruential generator. Before, 13 of 140 such formulas made pdflatex fail (a double
/// superscript, a script sign at the end, `$$`, a backslash that escaped the closing `$`).
#[test]
fn a_description_of_any_characters_compiles() {
    let alphabet: Vec<char> = "xpG12 _^{}()/'ωθħℓ²⁻¹₁₂\u{304}\u{307}−=,Zacosein$%&~#|<>中🙂"
        .chars()
        .collect();
    let mut state: u64 = 0x5eed;
    let mut next = |n: usize| {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 33) as usize % n
    };
    let mut description = String::new();
    for _ in 0..60 {
        let length = 1 + next(30);
        let formula: String = (0..length)
            .map(|_| alphabet[next(alphabet.len())])
            .collect();
        description.push_str(&format!("and `{formula}` then {formula} "));
    }
    // Runs of whole scripts and groups, which characters drawn one by one seldom make: before,
    // 2 of these 160 failed (`²_{_{²_{1,2}^{a}_{b}`, a script's group forgot the scripts its
    // base had, and `x^{a}_{b}^{c}` was a double superscript).
    let pieces = [
        "x", "G1", "p_x", "^{a}", "_{b}", "^a", "_b", "²", "₁", "'", " ", "{", "}", "^{", "_{",
        "K₁", "_{1,2}", "^", "_", "θ",
    ];
    for _ in 0..160 {
        let length = 1 + next(8);
        let formula: String = (0..length).map(|_| pieces[next(pieces.len())]).collect();
        description.push_str(&format!("and `{formula}` then "));
    }
    let file = crate::scratch_text(
        "latex-descriptions",
        "random.toml",
        &format!(
            "name = \"random formulas\"\nhamiltonian = \"p_x^2/2\"\n\
             description = \"{description}\"\n[phase_space]\ncoordinates = [\"x\"]\n\
             [[claim]]\nclaim = \"{{x, H}} = p_x\"\n"
        ),
    );
    let doc = run(
        &["check", &file.display().to_string(), "--format", "latex"],
        0,
    );
    assert_balanced_latex(&doc);
    // Random formulas may run past the line; only errors count.
    compile_within(&doc, f64::INFINITY);
}

/// Names in the statements, headers and titles of LaTeX output are written as the expression
/// printer writes them (`alpha1` was `alpha_{1}` in a statement and `\alpha_{1}` in its
/// bracket's value; the coordinate `ωx` was `\omega x`, ω·x), an exponent of more than one
/// piece is braced whole (`x^(1 + 1)` was `x^{(}1 + 1)`), names run together in the paper's
/// C06 are a product (`p_θt` was `p_{\theta t}`), and a command line is typewriter text
/// (`$--symbolic I_{1},I_{2},I_{3}$` read −−symbolicI₁,I₂,I₃).
#[test]
fn latex_writes_names_exponents_and_command_lines_as_they_read() {
    let file = crate::scratch_text(
        "latex-names",
        "names.toml",
        "name = \"names\"\ndescription = \"formulas `x^-1`, `x^(n+1)`, `e^(iθ)`, `x^2^3`\"\n\
         hamiltonian = \"p_x^2/2 + omega^2*x^2/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"ωx\"]\nparameters = [\"omega\", \"ln\"]\n\
         [[function]]\nname = \"alpha1\"\nvalue = \"x\"\n\
         [[function]]\nname = \"beta\"\nvalue = \"p_x^2\"\n\
         [[function]]\nname = \"Lambda3x\"\nvalue = \"x^3\"\n\
         [[claim]]\nclaim = \"{alpha1, H} = p_x\"\n\
         [[claim]]\nclaim = \"{beta, Lambda3x} = -6*x^2*p_x\"\n\
         [[claim]]\nclaim = \"{ωx, p_ωx} = 1\"\n\
         [[claim]]\nclaim = \"ln*x^(1+1)*x^2^3 = ln*x^10\"\n",
    );
    let file = file.to_str().expect("a path");
    let check = run(&["check", file, "--format", "latex", "--no-timings"], 0);
    for expected in [
        r"\{\alpha_{1}, H\} &= p_{x}",
        r"\{\beta, \mathrm{Lambda3x}\} &= -6x^{2} p_{x}",
        r"\{\mathrm{{\omega}x}, p_{{\omega}x}\} &= 1",
        r"\mathrm{ln} x^{1 + 1}x^{2^{3}} &= \mathrm{ln} x^{10}",
        r"formulas $x^{-1}$, $x^{n+1}$, $e^{i\theta}$, $x^{2^{3}}$",
    ] {
        assert!(check.contains(expected), "{expected} in\n{check}");
    }
    let table = run(
        &[
            "table",
            file,
            "alpha1",
            "Lambda3x",
            "--format",
            "latex",
            "--no-timings",
        ],
        0,
    );
    assert!(
        table.contains(r"\{\cdot,\cdot\} & \alpha_{1} & \mathrm{Lambda3x} \\"),
        "{table}"
    );
    let paper = run(&["--format", "latex", "--no-timings"], 0);
    assert!(
        paper.contains(r"\theta(t) &= \theta_{0} + p_{\theta}t/I"),
        "{paper}"
    );
    let search = run(
        &[
            "search",
            "systems/euler-top.toml",
            "--format",
            "latex",
            "--no-timings",
        ],
        0,
    );
    assert!(
        search.contains(r"(\texttt{-{}-symbolic I1,I2,I3})"),
        "{search}"
    );
    assert!(
        search.contains(r"(\texttt{-{}-fix I1=2,I2=3,I3=5})"),
        "{search}"
    );
    for doc in [&check, &table, &search] {
        assert_balanced_latex(doc);
        compile_within(doc, 60.0);
    }
}

/// A caption and a sentence that hold formulas set them as formulas: a condition's caption
/// (`at p\_$\theta$ = I$\omega$` was text with the Greek letters alone in math), a search's
/// complex form (`e\^{}\{$-$ik$\theta$\}`), the parameters a closure keeps symbolic (`in M,
/// $\alpha$`), each a code span in Markdown and the text as it was.
#[test]
fn captions_and_prose_set_their_formulas_as_formulas() {
    let when = ["--when", "p_theta = I*omega", "--no-timings"];
    let expand = |format: &str| {
        let mut args = vec![
            "expand",
            "systems/harmonic-rotor.toml",
            "G1",
            "--format",
            format,
        ];
        args.extend(when);
        run(&args, 0)
    };
    assert!(expand("latex").contains(r"\noindent at $p_{\theta} = I\omega$:"));
    assert!(expand("markdown").contains("\nat `p_θ = Iω`:\n"));
    assert!(expand("text").contains("\nat p_θ = Iω:\n"));
    let search = run(
        &[
            "search",
            "--system",
            "harmonic",
            "--when",
            "p_theta = 2*I*omega",
            "--format",
            "latex",
            "--no-timings",
        ],
        0,
    );
    assert!(
        search.contains(
            r"Those of trigonometric order $k > 0$ as $J = \operatorname{Re}(A e^{-ik\theta})$:"
        ),
        "{search}"
    );
    let closure = run(
        &[
            "closure",
            "systems/smorodinsky-winternitz-i.toml",
            "H",
            "Hx",
            "X",
            "--define",
            "C={Hx, X}",
            "--degree",
            "3",
            "--symbolic",
            "M,alpha,beta,gamma",
            "--format",
            "latex",
            "--no-timings",
        ],
        0,
    );
    assert!(
        closure.contains(r"of degree $\le 2$ in $M, \alpha, \beta, \gamma$; here they are"),
        "{closure}"
    );
}

/// A rank certificate's point writes an angle's cosine and sine as the expressions do,
/// `\cos\varphi` (it was `\cos \varphi`).
#[test]
fn a_rank_point_writes_cos_as_expressions_do() {
    let rank = run(
        &[
            "rank",
            "systems/kepler.toml",
            "H",
            "L",
            "Ax",
            "--format",
            "latex",
            "--no-timings",
        ],
        0,
    );
    assert!(
        rank.contains(r"$\cos\varphi = \frac{5}{13}, \sin\varphi = \frac{12}{13}$"),
        "{rank}"
    );
}

/// A minor whose `≠ 0` leaves no room for `at` on its line puts `at` before the point, where it
/// stood on a line of its own; a minor that leaves room for it ends its line with it, as
/// before, and where `≠ 0` went to the next line, `at` follows it there. `≠ 0` is never split:
/// a minor with room for `≠` but not for `0` wraps before `≠`, where a line began `0 at`.
#[test]
fn a_long_minor_keeps_at_with_the_point() {
    let point = "r = 2, cos φ = 5/13, sin φ = 12/13, p_r = 5/3, p_φ = 7, M = 11/2, k = 13/3";
    let minor = |power: usize| {
        let a = format!("Ax*10^{power}");
        let out = run(
            &["rank", "systems/kepler.toml", "H", "L", &a, "--no-timings"],
            0,
        );
        let start = out.find("      ≥ 3").expect("the minor");
        let end = out.find("      ≤ 3").expect("the bound");
        let lines: Vec<&str> = out[start..end].lines().collect();
        assert!(lines.iter().all(|l| l.chars().count() <= 96), "{out}");
        let value = format!("302{}/14157", "0".repeat(power));
        (lines.join("\n"), value)
    };
    let head = |power: &str| format!("      ≥ 3: the minor ∂(H, L, A_x·10{power})/∂(r, φ, p_φ) =");
    let (lines, value) = minor(26);
    assert_eq!(
        lines,
        format!("{} {value} ≠ 0 at\n        {point}", head("²⁶"))
    );
    let (lines, value) = minor(27);
    assert_eq!(
        lines,
        format!("{} {value} ≠ 0\n        at {point}", head("²⁷"))
    );
    let (lines, value) = minor(30);
    assert_eq!(
        lines,
        format!("{} {value}\n        ≠ 0 at\n        {point}", head("³⁰"))
    );
    let (lines, value) = minor(32);
    assert_eq!(
        lines,
        format!("{} {value}\n        ≠ 0 at\n        {point}", head("³²"))
    );
    let (lines, value) = minor(74);
    assert_eq!(
        lines,
        format!("{}\n        {value} ≠ 0\n        at {point}", head("⁷⁴"))
    );
}

/// The size of the minors that bound a rank is a formula: `$4 \times 4$` in LaTeX (it was
/// `4 $\times$ 4`), a code span in Markdown, and the text as it was.
#[test]
fn a_rank_bounds_minors_of_a_size_written_as_a_formula() {
    let rank = |format: &str| {
        let args = [
            "rank",
            "systems/kepler.toml",
            "H",
            "L",
            "Ax",
            "Ay",
            "--format",
            format,
        ];
        run(&args, 0)
    };
    let bound = "minor vanishes identically, as the one bordering the minor above does";
    assert!(rank("latex").contains(&format!(r"every $4 \times 4$ {bound}")));
    assert!(rank("markdown").contains(&format!("every `4 × 4` {bound}")));
    assert!(rank("text").contains(&format!("every 4 × 4 {bound}")));
}

/// A proof's fact sets its parenthetical apart by a `\quad`, as the text does by two spaces
/// (`-i\Omega e^{-i\theta} (\Omega = p_{\theta}/I)` read as a product); a sentence's
/// punctuation follows its formula (`$1 \le m, n \le 2,$` was inside it).
#[test]
fn a_proofs_parenthetical_and_punctuation_read_as_text_does() {
    let tower = run(
        &["tower", "--max", "2", "--format", "latex", "--no-timings"],
        0,
    );
    assert!(
        tower.contains(
            r"$\{e^{-i\theta}, H\} = -i\Omega e^{-i\theta}\quad (\Omega = p_{\theta}/I)$"
        ),
        "{tower}"
    );
    assert!(
        tower.contains(r"for all $m, n \ge 0$, from the ladder function $Z$:"),
        "{tower}"
    );
    assert!(
        tower.contains(r"checked for $1 \le m, n \le 2$, all hold"),
        "{tower}"
    );
    // The closing's parenthetical is a formula of its own, not a product with `0`.
    assert!(
        tower.contains(r"for all $m, n \ge 0$ $(K_{m,n} = Z^{m} e^{-in\theta})$: conserved"),
        "{tower}"
    );
}

/// Markdown sets a proof's formulas as code spans, as LaTeX sets them in math (they were bare
/// prose: `for all m, n ≥ 0, from the ladder function Z`), a number alone as prose.
#[test]
fn markdown_proofs_mark_their_formulas() {
    let tower = run(
        &[
            "tower",
            "--max",
            "2",
            "--format",
            "markdown",
            "--no-timings",
        ],
        0,
    );
    for expected in [
        "**Proof** for all `m, n ≥ 0`, from the ladder function `Z`:",
        "so `{A, H} = λ_A A` and `{B, H} = λ_B B` give",
        "for all `m, n ≥ 0` `(K_{m,n} = Z^m e^{−inθ})`: conserved exactly when `Ω/ω = m/n`.",
        "**tower: 4 brackets `{K_{m,n}, H} = i(mω − nΩ) K_{m,n}` checked for `1 ≤ m, n ≤ 2`, \
         all hold**",
        // A fact's parenthetical is a code span of its own, as LaTeX sets it apart.
        "2. computed: `{e^{−iθ}, H} = −iΩ e^{−iθ}` (`Ω = p_θ/I`) — holds",
    ] {
        assert!(tower.contains(expected), "{expected} in\n{tower}");
    }
    let text = run(&["tower", "--max", "2", "--no-timings"], 0);
    assert!(text.contains("from the ladder function Z:"), "{text}");
    // A fact's reason, after its colon, is prose with its formulas marked, as in LaTeX: it
    // was part of the fact's code span.
    let family = run(
        &[
            "tower",
            "--system",
            "systems/harmonic-rotor.toml",
            "--family",
            "K",
            "--max",
            "1",
            "--format",
            "markdown",
            "--no-timings",
        ],
        0,
    );
    assert!(
        family.contains(
            "3. computed: `λ(m, n) = i(mω − nΩ) equals mλ(1, 0) + nλ(0, 1)`: both are \
             polynomials of degree at most 1 in `m, n`, and they agree at the 4 points \
             `0 ≤ m, n ≤ 1` — holds"
        ),
        "{family}"
    );
}

/// A system whose names LaTeX writes only with care: see [`cli_latex_of_every_command_compiles`].
const LATEX_NAMES: &str = r#"name = "LaTeX names"
hamiltonian = "(p_a + p_b)^2/2 + p_ω₁₂^2/2 + ω₁₂^2/2 + p_ℓ₁*ħ₁ + p_θ₁₂*θ₁₂ + ωx*x₁y"
[phase_space]
coordinates = ["ω₁₂", "ℓ₁", "ħ₁", "θ₁₂", "ωx", "x₁y"]
angles = ["a", "b"]
[[function]]
name = "L"
value = "p_a + p_b"
[[function]]
name = "A"
display = "Z̄_x"
value = "p_a*cos(a - b)"
[[family]]
name = "K₁"
value = "(p_ω₁₂ + i*ω₁₂)^m*(p_ω₁₂ - i*ω₁₂)^n"
eigenvalue = "i*(m - n)"
[[family]]
name = "K_a"
value = "(p_ω₁₂ + i*ω₁₂)^m*(p_ω₁₂ - i*ω₁₂)^n*sin(a - b)"
[[family]]
name = "K2"
value = "K_a_{m,n}*x₁y"
[[claim]]
claim = "{ω₁₂, p_ω₁₂} = 1"
[[claim]]
claim = "{cos(a)*ωx, p_a + p_ωx} = -sin(a)*ωx + cos(a)"
[[claim]]
claim = "{K₁_1_2, H} = -i*K₁_1_2"
"#;

/// Every command that writes LaTeX writes a document that compiles, for every system file and
/// for names with several subscripts (`p_x_0`, `P_1_1`) or subscript digits (`q₁`, `p_q₁`), `ħ`,
/// accented names (`Hénon`) and claim ids that LaTeX would read as mathematics (`wrong_sign`).
#[test]
fn cli_latex_of_every_command_compiles() {
    let systems: Vec<String> =
        std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("systems"))
            .expect("systems/")
            .map(|e| e.expect("an entry").path().display().to_string())
            .filter(|p| p.ends_with(".toml"))
            .collect();
    let mut docs = Vec::new();
    for file in &systems {
        docs.push(run(
            &["check", file, "--format", "latex", "--no-timings"],
            0,
        ));
    }
    let rotor = "systems/harmonic-rotor.toml";
    for args in [
        vec![
            "closure",
            rotor,
            "F1",
            "L",
            "G1",
            "P_1_1",
            "Q_1_1",
            "--when",
            "p_theta = I*omega",
        ],
        vec!["tower", "--max", "2", "--system", rotor, "--family", "K"],
        vec!["table", "systems/gravity-rotor.toml", "Lp", "G1p", "G2p"],
        vec!["table", "systems/gravity-rotor.toml"],
        vec!["bracket", rotor, "K_1_2", "H"],
        // A half-integer power of a radicand, echoed as written (`^(3/2)` was `^{(}3/2)`).
        vec![
            "expand",
            "systems/kepler-3d.toml",
            "k*x/(x^2 + y^2 + z^2)^(3/2) + (x^2 + y^2 + z^2)^(-1/2)",
        ],
        [
            &["search", rotor, "--when", "p_theta = I*omega"][..],
            &crate::DEGREE_ONE,
        ]
        .concat(),
        vec![
            "search",
            "systems/kovalevskaya-top.toml",
            "--poisson-degree",
            "4",
            "--new-only",
        ],
    ] {
        let mut args = args;
        args.extend(["--format", "latex", "--no-timings"]);
        docs.push(run(&args, 0));
    }
    let dir = std::env::temp_dir().join(format!("superint-ids-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let file = dir.join("ids.toml");
    std::fs::write(
        &file,
        "name = \"Hénon's test\"\nhamiltonian = \"p_x_0^2/2 + ħ*q₁ + p_q₁^2/2\"\n\
         [phase_space]\ncoordinates = [\"x_0\", \"q₁\"]\nparameters = [\"ħ\"]\n\
         [[claim]]\nid = \"wrong_sign_#1\"\nclaim = \"{x_0, H} = -p_x_0\"\n\
         [[claim]]\nclaim = \"{q₁, H} = p_q₁\"\n",
    )
    .expect("write ids.toml");
    let out = superint(&["check", file.to_str().expect("a path"), "--format", "latex"]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    docs.push(stdout(&out));
    // Angles with Latin names (`\cosa` was one undefined command), Greek letters, ħ and ℓ with
    // subscript digits and inside a word (`p_{\omega }_{12}` was a double subscript), families
    // named with a subscript of their own (`K_{1}_{1,2}`), a bar before a subscript (`Z̄_x` was
    // written as it is in a table's entries).
    let names = dir.join("names.toml");
    std::fs::write(&names, LATEX_NAMES).expect("write names.toml");
    let names = names.to_str().expect("a path");
    for args in [
        &["check", names][..],
        &[
            "expand",
            names,
            "K₁_1_2",
            "K_a_1_1",
            "K2_2_1",
            "cos(a)*sin(b)",
        ],
        &["bracket", names, "cos(a)", "p_a"],
        &["table", names, "L", "A", "K₁_1_2"],
        // A rank certificate's point at the angles (`\cosa = 3/5` was undefined).
        &["rank", names, "A", "L"],
        &[&["search", names][..], &crate::DEGREE_ONE].concat(),
        // The proof's linearity line: its prose breaks between words (it ran 296 pt wide).
        &["tower", "--system", names, "--family", "K₁", "--max", "2"],
    ] {
        docs.push(run(
            &[args, &["--format", "latex", "--no-timings"]].concat(),
            0,
        ));
    }
    let _ = std::fs::remove_dir_all(&dir);
    // Nothing runs far off the page: a wide table is a list, a long claim breaks and its
    // verdict moves below it (a table ran 980 pt too wide).
    for doc in &docs {
        assert!(doc.is_ascii(), "LaTeX output is ASCII");
        assert_balanced_latex(doc);
        compile_within(doc, 60.0);
    }
}

/// A table too wide for the page whose brackets all vanish says so in a sentence, as the text
/// does: it wrote `\[1ex] every bracket is zero.`, which opened a display that nothing closed,
/// and pdflatex stopped at `Missing $ inserted`. The ladder functions `K_{m,n} = Z^m e^{−inθ}`
/// commute with one another and with `Z`.
#[test]
fn latex_wide_table_of_zero_brackets_is_a_sentence() {
    let mut args = vec!["table", "systems/harmonic-rotor.toml", "Z"];
    args.extend([
        "K_1_1", "K_1_2", "K_2_1", "K_2_2", "K_1_3", "K_3_1", "K_3_3", "K_2_3", "K_3_2", "K_4_1",
        "K_4_2", "K_4_3", "K_4_4",
    ]);
    let text = run(&[&args[..], &["--no-timings"]].concat(), 0);
    assert!(
        text.contains("{A, B} for the harmonic rotor: every bracket is zero."),
        "{text}"
    );
    let doc = run(
        &[&args[..], &["--format", "latex", "--no-timings"]].concat(),
        0,
    );
    assert!(
        doc.contains(r"\noindent $\{A, B\}$ for the harmonic rotor: every bracket is zero."),
        "{doc}"
    );
    assert!(!doc.contains(r"\["), "{doc}");
    assert_balanced_latex(&doc);
    compile_within(&doc, 1.0);
}

/// A nonvanishing claim's value follows `it equals` as the right side of a relation: the words
/// ran into the value's parenthesis (`it equals(2ωp_x p_y`) and made its leading minus a binary
/// one (`it equals − ωp_y`).
#[test]
fn latex_it_equals_is_a_relation() {
    let paper = run(&["--format", "latex", "--no-timings"], 0);
    for expected in [
        r" &\mathrel{\text{it equals}} \left(\omega p_{y} + M \omega^{2} x\right) \cos\theta",
        r" &\mathrel{\text{it equals}} \bigl(2 \omega p_{x} p_{y} + 2 M \omega^{2} x p_{x}",
        // −A + 2A cos²θ + 2B cos θ sin θ = A cos 2θ + B sin 2θ.
        r" &\mathrel{\text{it equals}} \bigl(\omega p_{y} + M \omega^{2} x\bigr) \cos 2\theta",
    ] {
        assert!(paper.contains(expected), "{expected} in\n{paper}");
    }
    assert!(!paper.contains(r"\text{it equals} "), "{paper}");
}

/// A closing line whose numbers and formulas are math sets them bold, as its words are
/// (`\textbf{$27$ claims: $27$ proved}` had light digits among bold words); a check's, which is
/// text, is as it was.
#[test]
fn latex_summary_sets_its_math_bold() {
    let tower = run(
        &["tower", "--max", "2", "--format", "latex", "--no-timings"],
        0,
    );
    assert!(
        tower.contains(
            r"\bigskip\noindent\textbf{\boldmath tower: $4$ brackets $\{K_{m,n}, H\} = i(m\omega - n\Omega) K_{m,n}$ checked for $1 \le m, n \le 2$, all hold}"
        ),
        "{tower}"
    );
    let paper = run(&["--format", "latex", "--no-timings"], 0);
    assert!(
        paper.contains(r"\bigskip\noindent\textbf{\boldmath $"),
        "{paper}"
    );
    let check = run(
        &[
            "check",
            "systems/kepler.toml",
            "--format",
            "latex",
            "--no-timings",
        ],
        0,
    );
    assert!(
        check.contains(
            r"\bigskip\noindent\textbf{10 claims in 1 file: 7 proved, 3 refuted; all as expected}"
        ),
        "{check}"
    );
    compile_within(&tower, 1.0);
}

/// A search's complex form labels its left side with its order, `A3 (k = 1)`, set apart by a
/// `\quad`: `A_{3} (k = 1)` read as `A_3` times `(k = 1)`.
#[test]
fn latex_labels_an_equation_apart_from_its_name() {
    let search = run(
        &[
            &[
                "search",
                "systems/harmonic-rotor.toml",
                "--when",
                "p_theta = I*omega",
                "--format",
                "latex",
                "--no-timings",
            ][..],
            &crate::DEGREE_ONE,
        ]
        .concat(),
        0,
    );
    assert!(
        search.contains(r"A_{3}\quad (k = 1) &= p_{y} + i M \omega y \\"),
        "{search}"
    );
    compile_within(&search, 1.0);
}

/// A claim's condition follows the last row of its right side, which leaves it room: a
/// closure's `{Y, Z} = −32 H² Y − … + 128 at ω = 1, α = 1, β = 1` was one row, 63 pt past the
/// margin.
#[test]
fn latex_claim_leaves_room_for_its_condition() {
    let doc = run(
        &[
            "closure",
            "systems/ttw-2.toml",
            "H",
            "X",
            "Y",
            "Z",
            "--define",
            "Z={X, Y}",
            "--degree",
            "3",
            "--format",
            "latex",
            "--no-timings",
        ],
        0,
    );
    let expected = concat!(
        r"\{Y, Z\} &= -32 H^{2} Y - 192 H^{2} + 256 X Y + 512 X + 32 Y^{2} - 128 Y \\",
        "\n",
        r"&\quad + 128\quad\text{at } \omega = 1, \alpha = 1, \beta = 1 \tag*{[B3 proved]}",
    );
    assert!(doc.contains(expected), "{doc}");
    compile_within(&doc, 1.0);
}

/// The right sides of equations and of a wide table's list start where the widest left side
/// ends, and are broken to what it leaves of the row: each took the whole row, and an expanded
/// product ran 55 pt past the margin, a bracket of Fokas–Lagerstrom's table 18 pt.
#[test]
fn latex_right_sides_take_what_the_left_sides_leave() {
    let expand = run(
        &[
            "expand",
            "systems/two-centres.toml",
            "(1 + x + y)^2*(1/r^3 + x/s^3)",
            "G",
            "--format",
            "latex",
            "--no-timings",
        ],
        0,
    );
    let table = run(
        &[
            "table",
            "systems/fokas-lagerstrom-1-3.toml",
            "--format",
            "latex",
            "--no-timings",
        ],
        0,
    );
    assert!(
        table.contains(r"\{S, C\} &= -3 p_{x}^{6} + 9 p_{x}^{4} p_{y}^{2} - 9 M^{2} \omega^{2} x^{2} p_{x}^{4} + 18 M^{2} \omega^{2} x^{2} p_{x}^{2} p_{y}^{2} \\"),
        "{table}"
    );
    for doc in [&expand, &table] {
        compile_within(doc, 1.0);
    }
}

/// A claim's note sets its formulas as formulas, in LaTeX and in Markdown: a search's
/// `proved for every A, B, at C = 2` was upright text in LaTeX and bare prose in Markdown.
#[test]
fn notes_set_their_formulas_as_formulas() {
    let search = |format: &str| {
        run(
            &[
                "search",
                "systems/henon-heiles.toml",
                "--momenta-degree",
                "2",
                "--positions-degree",
                "4",
                "--trig-degree",
                "0",
                "--fix",
                "C=2",
                "--symbolic",
                "A,B",
                "--format",
                format,
                "--no-timings",
            ],
            0,
        )
    };
    let latex = search("latex");
    assert!(
        latex.contains(r"&\text{proved for every $A, B$, at $C = 2$}"),
        "{latex}"
    );
    let markdown = search("markdown");
    assert!(
        markdown.contains("— **basis proved** (proved for every `A, B`, at `C = 2`)"),
        "{markdown}"
    );
    let text = search("text");
    assert!(
        text.contains("      proved for every A, B, at C = 2\n"),
        "{text}"
    );
    compile_within(&latex, 60.0);
}

/// A proof's closing paragraph is flush left, as its lemma is (it was indented below it).
#[test]
fn latex_proof_closing_is_flush_left() {
    let tower = run(
        &["tower", "--max", "1", "--format", "latex", "--no-timings"],
        0,
    );
    assert!(
        tower.contains("\n\\noindent\\emph{Therefore:} $\\{K_{m,n}, H\\} = "),
        "{tower}"
    );
    assert!(
        tower.contains("\\end{enumerate}\n\\emph{Lemma:} "),
        "{tower}"
    );
}

/// A family's tower proof closes its lemma with `mλ_A + nλ_B = mλ(1, 0) + nλ(0, 1) =
/// λ(m, n)`, one formula: the numbers that close its parentheses cut it into pieces, in LaTeX
/// (`$m\lambda(1$, $0$) $+ n\lambda(0$, $1$)`) and in Markdown's code spans alike.
#[test]
fn a_towers_lemma_keeps_its_formula_whole() {
    let tower = |format: &str| {
        let args = [
            "tower",
            "--system",
            "systems/harmonic-rotor.toml",
            "--family",
            "K",
            "--max",
            "1",
            "--format",
            format,
            "--no-timings",
        ];
        run(&args, 0)
    };
    let latex = tower("latex");
    assert!(
        latex.contains(
            r"and $m\lambda_{A} + n\lambda_{B} = m\lambda(1, 0) + n\lambda(0, 1) = \lambda(m, n)$."
        ),
        "{latex}"
    );
    let markdown = tower("markdown");
    assert!(
        markdown.contains("and `mλ_A + nλ_B = mλ(1, 0) + nλ(0, 1) = λ(m, n)`."),
        "{markdown}"
    );
}

/// A search's note that `H` lies outside the space marks its formulas and settings, as the
/// notes beside it do: `H`, `r` and `SearchSpace::laurent` were upright prose in LaTeX and
/// bare in Markdown. The text reads as it did.
#[test]
fn a_search_note_on_h_marks_its_formulas() {
    let search = |format: &str| {
        let args = [
            "search",
            "systems/kepler.toml",
            "--momenta-degree",
            "2",
            "--positions-degree",
            "2",
            "--format",
            format,
            "--no-timings",
        ];
        run(&args, 0)
    };
    let latex = search("latex");
    assert!(
        latex.contains(
            r"Note: $H$ is not in this space (negative powers of $r$, which a Laurent space (\texttt{SearchSpace::laurent}; on the command line, \texttt{-{}-laurent}) admits), so $H$ is not"
        ),
        "{latex}"
    );
    let markdown = search("markdown");
    assert!(
        markdown.contains(
            "Note: `H` is not in this space (negative powers of `r`, which a Laurent space \
             (`SearchSpace::laurent`; on the command line, `--laurent`) admits), so `H` is not"
        ),
        "{markdown}"
    );
    let text = crate::normalize(&search("text"));
    assert!(
        text.contains(
            "Note: H is not in this space (negative powers of r, which a Laurent space \
             (SearchSpace::laurent; on the command line, --laurent) admits), so H is not"
        ),
        "{text}"
    );
    compile_within(&latex, 1.0);
}

/// A claim whose left side is long takes rows of its own, so that it does not set the
/// alignment column of its section: that pushed every row beside it, residuals included, 120 pt
/// past the margin.
#[test]
fn cli_latex_long_left_side_takes_rows_of_its_own() {
    let dir = std::env::temp_dir().join(format!("superint-long-lhs-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let file = dir.join("long.toml");
    std::fs::write(
        &file,
        r#"name = "A long left side"
hamiltonian = "(p_x^2 + p_y^2)/2 + (x^2 + y^2)/2"
[phase_space]
coordinates = ["x", "y"]
[[claim]]
claim = "{x^3*p_y^2 + 3*x^2*y*p_x*p_y - 7*y^3*p_x^2 + 5*x*y*p_x^2*p_y^2 + x^4 + y^4 + 11*x^2*y^2 + p_x^4, H} = 0"
[[claim]]
claim = "{x*p_y - y*p_x, H} = 0"
[[claim]]
claim = "{x*p_y + y*p_x, H} = 0"
"#,
    )
    .expect("write long.toml");
    let out = superint(&[
        "check",
        file.to_str().expect("a path"),
        "--format",
        "latex",
        "--no-timings",
    ]);
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    let doc = stdout(&out);
    // The long bracket breaks inside its braces, the relation opens the next row, and the
    // short claims keep their left sides at the column.
    assert!(
        doc.contains(
            "&\\{x^{3} p_{y}^{2} + 3x^{2}y p_{x} p_{y} - 7y^{3} p_{x}^{2} \\\\\n\
             &\\quad + 5xy p_{x}^{2} p_{y}^{2} + x^{4} + y^{4} + 11x^{2}y^{2} + p_{x}^{4}, H\\} \\\\\n\
             &= 0 \\tag*{[\\#1 REFUTED]}"
        ),
        "{doc}"
    );
    assert!(doc.contains("\\{x p_{y} - y p_{x}, H\\} &= 0 \\tag*{[\\#2 proved]}"));
    assert!(doc.contains("\\text{residual} &= 2 p_{x} p_{y} - 2 x y"));
    assert_balanced_latex(&doc);
    compile_within(&doc, 0.0);
}

#[test]
fn cli_markdown_has_tables() {
    let md = run(&["--format", "markdown", "--no-timings"], 0);
    assert!(md.starts_with("# "));
    assert!(md.contains("| `{·,·}` | `F1` | `F2` | `L` | `G1` | `G2` |\n|---|---|---|---|---|---|"));
    assert!(md.contains("| `L` | `0` | `0` | `0` | `−G2` | `4 G1` |"));
    assert!(md.contains("- `{L, G1} = −G2` — **C09 proved**"));
    let rules = md.lines().filter(|l| l.starts_with("|---|")).count();
    assert_eq!(rules, 2, "two bracket tables");
}

#[test]
fn cli_tower_small_matches_snapshot() {
    let out = run(&["tower", "--max", "3", "--no-timings"], 0);
    assert_snapshot("tower-3.txt", &out);
    assert_eq!(
        out.lines().last(),
        Some(
            "tower: 9 brackets {K_{m,n}, H} = i(mω − nΩ) K_{m,n} checked for 1 ≤ m, n ≤ 3, \
             all hold"
        )
    );
    let timed = run(&["tower", "--max", "3"], 0);
    let last = timed.lines().last().expect("a summary line");
    assert!(
        last.starts_with("tower: 9 brackets") && last.ends_with(" s)"),
        "{last}"
    );
}

#[test]
fn cli_tower_gravity_and_formats() {
    let out = run(
        &["tower", "--max", "2", "--system", "gravity", "--no-timings"],
        0,
    );
    assert!(out.contains("[C24 proved]"));
    // The shifted family K' is named as such in the proof's conclusion and the closing line
    // (both said K_{m,n}, the harmonic rotor's family).
    assert!(
        out.contains("(K'_{m,n} = Z'^m e^{−inθ}): conserved exactly when Ω/ω = m/n"),
        "{out}"
    );
    assert_eq!(
        out.lines().last(),
        Some("tower: 4 brackets {K'_{m,n}, H} = i(mω − nΩ) K'_{m,n} checked for 1 ≤ m, n ≤ 2, all hold")
    );
    let v: Value = serde_json::from_str(&run(
        &["tower", "--max", "2", "--format", "json", "--no-timings"],
        0,
    ))
    .expect("JSON");
    assert_eq!(v["towers"][0]["checked"], 4);
    assert_eq!(v["towers"][0]["outcome"], "proved");
    assert_eq!(v["proofs"][0]["outcome"], "proved");
}

#[test]
fn cli_bad_usage_exits_2_with_a_message() {
    for (args, message) in [
        (
            &["tower", "--max", "x"][..],
            "invalid value 'x' for '--max <N>'",
        ),
        (
            &["tower", "--max", "0"][..],
            "invalid value '0' for '--max <N>'",
        ),
        (
            &["--format", "pdf"][..],
            "invalid value 'pdf' for '--format <FORMAT>'",
        ),
        (&["frobnicate"][..], "unrecognized subcommand 'frobnicate'"),
        (
            &[
                "search",
                "systems/harmonic-rotor.toml",
                "--exact-complement",
            ][..],
            "the following required arguments were not provided",
        ),
        (
            &[
                "search",
                "systems/harmonic-rotor.toml",
                "--max-products",
                "9",
            ][..],
            "the following required arguments were not provided",
        ),
        (
            &[
                "search",
                "systems/harmonic-rotor.toml",
                "--new-only",
                "--max-products",
                "0",
            ][..],
            "invalid value '0' for '--max-products <N>'",
        ),
        (
            &[
                "search",
                "systems/harmonic-rotor.toml",
                "--trig-degree",
                "21",
            ][..],
            "invalid value '21' for '--trig-degree <K>': 21 is not in 0..=20",
        ),
        (
            &["search", "systems/harmonic-rotor.toml", "--threads", "0"][..],
            "invalid value '0' for '--threads <N>': 0 is not in 1..=256",
        ),
        (
            &[
                "search",
                "systems/harmonic-rotor.toml",
                "--threads",
                "65535",
            ][..],
            "invalid value '65535' for '--threads <N>': 65535 is not in 1..=256",
        ),
        (&["paper", "--bogus"][..], "unexpected argument '--bogus'"),
        (
            &["expand", "systems/harmonic-rotor.toml"][..],
            "give the expressions to expand after the system",
        ),
    ] {
        assert_bad_usage(args, message);
    }
    // The products of integrals up to degree 2 at p_θ = Iω are more than nine.
    for (limit, message) in [
        (
            "9",
            "more than 9 products of integrals, the search's limit of them: search a smaller \
             space, or raise the limit\nhint: if the machine has the time, raise the limit with \
             --max-products N\n",
        ),
        (
            "1",
            "more than 1 product of integrals, the search's limit of them",
        ),
    ] {
        let search = ["search", "systems/harmonic-rotor.toml", "--new-only"];
        let options = ["--when", "p_theta = I*omega", "--max-products", limit];
        assert_bad_usage(&[&search[..], &options[..]].concat(), message);
    }
}

/// A function's display name typed in an expression, as the reports print it (`Z̄`, `Re A`), is
/// said to be one, with the name to write: it was `unexpected character '\u{304}'` and `unknown
/// name 'Re'`. A word that only begins like one (`Re Ax`) is told what `Re` is, a function that
/// takes parentheses.
#[test]
fn cli_a_display_name_in_an_expression_names_the_function() {
    let rotor = "systems/harmonic-rotor.toml";
    let a35 = "systems/anisotropic-3-5-rotor.toml";
    for (args, message) in [
        (
            vec!["bracket", rotor, "Z̄", "Z"],
            "superint: error: <command line>:1:1: 'Z̄' is how the function Zbar is printed; an \
             expression names it Zbar\n 1 | Z̄\n   | ^^\n",
        ),
        (
            vec!["expand", a35, "--", "x/(2Re A)"],
            "superint: error: <command line>:1:5: 'Re A' is how the function ReA is printed; an \
             expression names it ReA\n 1 | x/(2Re A)\n   |     ^^^^\n",
        ),
    ] {
        let o = superint(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert_eq!(stderr(&o), message, "{args:?}");
    }
    let o = superint(&["expand", a35, "Re Ax"]);
    let want = "'Re' is the real part, a function: write its argument in parentheses, Re(…)";
    assert!(stderr(&o).contains(want), "{}", stderr(&o));
}

/// A bar over an angle, `θ̄` or `\bar{\theta}`, says that the angle is real and that `conj`
/// does not take it, with how functions depend on it: it said "the complex conjugate of θ is
/// written conj(θ)" (and `\bar{\theta}` "unknown name 'θ̄' (known: …)"), and `conj(θ)` is
/// refused. A bar over a variable conj takes keeps its `conj(x)`.
#[test]
fn cli_a_bar_over_an_angle_says_that_conj_does_not_take_it() {
    let rotor = "systems/harmonic-rotor.toml";
    let angle = "θ is an angle, real: conj does not take it, and functions depend on it through \
                 cos(theta), sin(theta) or exp(i*k*theta)";
    for (expr, message) in [
        (
            "θ\u{304}",
            format!(
                "superint: error: <command line>:1:2: unexpected character '\\u{{304}}'; a bar \
                 is no operation: {angle}\n 1 | θ\u{304}\n   |  ^\n"
            ),
        ),
        (
            "\\bar{\\theta}",
            format!(
                "superint: error: <command line>:1:1: unknown name 'θ\u{304}': {angle}\n \
                 1 | \\bar{{\\theta}}\n   | ^^^^^^^^^^^^\n"
            ),
        ),
        (
            "x\u{304}",
            "superint: error: <command line>:1:2: unexpected character '\\u{304}'; a bar is no \
             operation: the complex conjugate of x is written conj(x)\n 1 | x\u{304}\n   |  ^\n"
                .to_string(),
        ),
    ] {
        let o = superint(&["expand", rotor, "--", expr]);
        assert_eq!(o.status.code(), Some(2), "{expr}");
        assert_eq!(stderr(&o), message, "{expr}");
    }
}

/// A bar over a family's instance whose bar family the file does not declare,
/// `\bar{P}_{3,2}`, says that its conjugate is written conj(P_3_2), as a bar over a function
/// (`\bar{L}`) says conj(L): it said "unknown name 'P̄_3_2' (known: …)" with the generic hint.
/// `\bar{K}_{3,2}` is the file's family Kbar's instance still.
#[test]
fn cli_a_bar_over_a_family_instance_says_how_its_conjugate_is_written() {
    let rotor = "systems/harmonic-rotor.toml";
    let o = superint(&["expand", rotor, "--", "x + \\bar{P}_{3,2}"]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(
        stderr(&o),
        "superint: error: <command line>:1:5: unknown name 'P\u{304}_3_2': the complex \
         conjugate of P_3_2 is written conj(P_3_2)\n 1 | x + \\bar{P}_{3,2}\n   |     \
         ^^^^^^^^^^^^^\n"
    );
    run(&["expand", rotor, "conj(P_3_2)", "--no-timings"], 0);
    run(&["expand", rotor, "\\bar{K}_{3,2}", "--no-timings"], 0);
}

/// A system whose functions display as no name, `∂H` and `∇φ` (in LaTeX `\partial H` and
/// `\nabla\varphi`), for the refusals of a display typed in an expression.
fn differential_displays() -> std::path::PathBuf {
    crate::scratch_text(
        "differential-displays",
        "d.toml",
        "name = \"oscillator\"\nhamiltonian = \"(p_x^2 + p_y^2)/2 + (x^2 + y^2)/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\n\
         [[function]]\nname = \"dH\"\ndisplay = \"∂H\"\nvalue = \"x*p_x + y*p_y\"\n\
         [[function]]\nname = \"nf\"\ndisplay = \"∇φ\"\nvalue = \"x\"\n",
    )
}

/// A function's display typed in LaTeX, as the LaTeX output prints it (`\partial H`,
/// `\nabla\varphi`), is said to be one, with the name to write, as its text form `∂H` is: it
/// was an unknown LaTeX command '\partial'. It is not read as the function. A command that
/// only begins one (`\partial Hx`) keeps its own message.
#[test]
fn cli_a_display_in_latex_in_an_expression_names_the_function() {
    let file = differential_displays();
    let file = file.to_str().expect("a UTF-8 path");
    for (expr, column, printed, name, caret) in [
        (r"\partial H", 1, r"\partial H", "dH", "^^^^^^^^^^"),
        (r"2\partial H^2", 2, r"\partial H", "dH", " ^^^^^^^^^^"),
        (r"\nabla\varphi", 1, r"\nabla\varphi", "nf", "^^^^^^^^^^^^^"),
        (
            r"\nabla \varphi",
            1,
            r"\nabla\varphi",
            "nf",
            "^^^^^^^^^^^^^^",
        ),
    ] {
        let o = superint(&["expand", file, "--", expr]);
        assert_eq!(o.status.code(), Some(2), "{expr}");
        assert_eq!(
            stderr(&o),
            format!(
                "superint: error: <command line>:1:{column}: '{printed}' is how the function \
                 {name} is printed; an expression names it {name}\n 1 | {expr}\n   | {caret}\n"
            ),
            "{expr}"
        );
    }
    let o = superint(&["expand", file, r"\partial Hx"]);
    assert!(
        stderr(&o).contains(r"unknown LaTeX command '\partial'"),
        "{}",
        stderr(&o)
    );
}

/// A function's display with a power after it, `∂H²`, is said to be one, as `∂H^2` is: it was
/// an unexpected character '∂', the superscript taken for a letter of a longer word.
#[test]
fn cli_a_display_raised_by_a_superscript_names_the_function() {
    let file = differential_displays();
    let file = file.to_str().expect("a UTF-8 path");
    for expr in ["∂H²", "x + ∂H³ y", "∂H^2"] {
        let o = superint(&["expand", file, "--", expr]);
        assert_eq!(o.status.code(), Some(2), "{expr}");
        assert!(
            stderr(&o)
                .contains("'∂H' is how the function dH is printed; an expression names it dH"),
            "{expr}: {}",
            stderr(&o)
        );
    }
}

/// A display written in a name's braces, `x_{ω̄}`, names its function as one written apart
/// does, while other text there, `p_{\left(}`, is refused with what the braces hold and where
/// they open (it was an unexpected character '(' at the parenthesis, past its `\left`).
#[test]
fn cli_a_name_s_braces_say_what_they_hold_and_a_display_in_them_names_the_function() {
    let file = "systems/fock-darwin-rotor.toml";
    let o = superint(&["expand", file, "--", "x_{ω̄}"]);
    assert_eq!(o.status.code(), Some(2));
    let wanted = "'ω̄' is how the function omegabar is printed; an expression names it omegabar";
    assert!(stderr(&o).contains(wanted), "{}", stderr(&o));
    let o = superint(&["expand", file, "--", r"p_{\left(}"]);
    assert_eq!(o.status.code(), Some(2));
    let wanted = "<command line>:1:4: expected a letter, a digit or '}' in the name's braces \
                  opened at column 3, found '\\left('";
    assert!(stderr(&o).contains(wanted), "{}", stderr(&o));
}

/// A family's index may be written with leading zeros, which do not count toward its nine
/// digits: `K_{0000000000001,1}` is `K_{1,1}` (it was refused as an index too long).
#[test]
fn cli_leading_zeros_of_a_family_index_are_not_digits_of_it() {
    let rotor = "systems/harmonic-rotor.toml";
    let plain = run(&["expand", rotor, "K_1_1", "--no-timings"], 0);
    for written in [
        "K_{0000000000001,1}",
        "K_0000000000001_00000000001",
        "K_01_1",
    ] {
        assert_eq!(
            run(&["expand", rotor, written, "--no-timings"], 0),
            plain,
            "{written}"
        );
    }
}

/// A table's entry that is no combination of the listed functions but a polynomial in `H`
/// and the file's functions is written so below the table, as `bracket` writes it: the cubic
/// algebra of the Fokas–Lagerstrom integrals showed `{S, C}` only as ten monomials. One of
/// degree 1 in the listed functions is not (the table chose the bracket over it), and the
/// gravity rotor's table, all such, has no such lines.
#[test]
fn cli_table_writes_an_entry_in_the_functions_where_it_can() {
    let fl = "systems/fokas-lagerstrom-1-3.toml";
    let out = run(&["table", fl, "H", "Hx", "S", "C", "--no-timings"], 0);
    // Expanded, then with the factor its terms share, as `bracket` writes it.
    assert!(
        out.contains(
            "\n    {S, C} = 72M³ H H_x² − 96M³ H_x³\n           = 24M³(3 H − 4 H_x) H_x²\n"
        ),
        "{out}"
    );
    let below = out
        .split("as polynomials in H")
        .nth(1)
        .expect("lines below the table");
    assert!(!below.contains("{H_x,"), "{below}");
    let v: Value =
        serde_json::from_str(&run(&["table", fl, "S", "C", "--format", "json"], 0)).expect("JSON");
    let line = &v["equations"][0]["lines"][0];
    assert_eq!(line["lhs"], "{S, C}");
    assert_eq!(line["ascii"], "72*M^3*H*Hx^2 - 96*M^3*Hx^3");
    assert_eq!(line["in_functions"]["ascii"], "24*M^3*(3*H - 4*Hx)*Hx^2");
    let tex = run(&["table", fl, "S", "C", "--format", "latex"], 0);
    assert!(
        tex.contains(r"\{S, C\} &= 72 M^{3} H H_{x}^{2} - 96 M^{3} H_{x}^{3}"),
        "{tex}"
    );
    let gravity = run(&["table", "systems/gravity-rotor.toml", "--no-timings"], 0);
    assert!(!gravity.contains("as polynomials in H"), "{gravity}");
}

/// `rank --when` sets parameters as a rank claim's `when` does: the two energies of the planar
/// oscillator are dependent at `a = 1` only, where the report is as it was before a condition
/// could set a phase variable, byte for byte. A parameter set to a function of phase space is
/// refused. `rank` had no `--when`, though a file's rank claim takes one.
#[test]
fn cli_rank_takes_a_condition_on_parameters() {
    let file = crate::scratch_text(
        "rank-when",
        "oscillator.toml",
        "hamiltonian = \"(p_x^2 + p_y^2)/2 + (x^2 + a*y^2)/2\"\n[phase_space]\n\
         coordinates = [\"x\", \"y\"]\nparameters = [\"a\"]\n",
    );
    let file = file.to_str().expect("a path");
    let both = "(p_x^2 + x^2 + p_y^2 + y^2)/2";
    let at = |when: &str, code: i32| {
        let args = [
            "rank",
            file,
            "H",
            both,
            "--when",
            when,
            "--expect",
            "1",
            "--no-timings",
        ];
        let o = superint_exits(&args, code);
        (stdout(&o), stderr(&o))
    };
    let (isotropic, _) = at("a = 1", 0);
    let body = isotropic.split_once("══\n").expect("a section").1;
    assert_eq!(
        body,
        "  rank ∂(H, (p_x² + x² + p_y² + y²)/2)/∂(x, y, p_x, p_y) = 1 at a = 1  [rank proved]\n\
         \x20     ≥ 1: the minor ∂(H)/∂(x) = 2 ≠ 0 at\n\
         \x20       x = 2, y = 3/2, p_x = 5/3, p_y = 7\n\
         \x20     ≤ 1: every 2 × 2 minor vanishes identically, as the 3 bordering the minor \
         above do\n\
         \n\
         1 claim in 1 file: 1 proved, 0 refuted; all as expected\n"
    );
    let (anisotropic, _) = at("a = 4", 1);
    assert!(anisotropic.contains("the rank is 2"), "{anisotropic}");
    let (_, refused) = at("a = x", 2);
    assert_eq!(
        refused,
        "superint: error: <command line>:1:5: the condition sets the parameter a to a function \
         of phase space (it holds x, a coordinate): a rank's condition sets parameters to \
         numbers or other parameters, and a phase variable to a value in them and the other \
         phase variables, the rank being that on its level set\n \
         1 | a = x\n   |     ^\n"
    );
}

/// `rank --when` on a level set: the rotor's functions restricted to the resonance
/// `p_θ = Iω`, where `F2 = p_θ²/(2I)` is constant, so that C17's five functions have rank 4,
/// by the five phase variables but `p_θ`; the value of a condition may use another's variable
/// (`p_θ = Iω, ω = 2`, read as `p_θ = 2I`), as in every `when`. A condition that is no level
/// set is refused at its place, with exit status 2: a variable set twice or in terms of
/// itself, directly or in a cycle, an angle or its cosine, a parameter set to a function of
/// phase space.
#[test]
fn cli_rank_on_a_level_set() {
    let rotor = "systems/harmonic-rotor.toml";
    let c17 = ["F1", "F2", "G1", "G2", "P_1_1"];
    let rank = |when: &str, expect: &str, code: i32| {
        let mut args = vec!["rank", rotor];
        args.extend(c17);
        args.extend(["--when", when, "--expect", expect, "--no-timings"]);
        let o = superint_exits(&args, code);
        (stdout(&o), stderr(&o))
    };
    let (four, _) = rank("p_theta = I*omega", "4", 0);
    assert!(
        four.contains(
            "rank ∂(F1, F2, G1, G2, P_{1,1})/∂(x, y, θ, p_x, p_y) = 4 at p_θ = Iω  [rank proved]"
        ),
        "{four}"
    );
    assert!(
        !four.contains("p_θ = 13/3"),
        "the point leaves p_θ out: {four}"
    );
    assert!(
        four.contains("≤ 4: every 5 × 5 minor vanishes identically"),
        "{four}"
    );
    let (five, _) = rank("p_theta = I*omega", "5", 1);
    assert!(five.contains("[rank REFUTED]"), "{five}");
    assert!(five.contains("the rank is 4"), "{five}");
    let (resolved, _) = rank("p_theta = I*omega, omega = 2", "4", 0);
    assert!(resolved.contains("= 4 at p_θ = Iω, ω = 2"), "{resolved}");
    assert!(!resolved.contains("ω = 19/2"), "{resolved}");
    for (when, message) in [
        (
            "x = p_x, x = 2",
            "1:10: 'x' is fixed twice\n 1 | x = p_x, x = 2\n   |          ^\nhint: keep one of \
             its values: a list of values sets each name once",
        ),
        // It said what but not what to do.
        (
            "x = 1/0",
            "1:7: division by zero\n 1 | x = 1/0\n   |       ^\nhint: what is divided by here is \
             0: write a divisor other than 0, or leave the division out",
        ),
        (
            "p_x = 2*p_x",
            "1:7: the condition sets p_x in terms of itself",
        ),
        (
            "x = p_y, p_y = x",
            "1:5: the condition sets x in terms of itself",
        ),
        (
            "theta = 0",
            "1:1: a condition cannot fix an angle: functions depend on it through cos, sin, exp",
        ),
        (
            "cos(theta) = 1/2",
            "1:1: the left side of a condition is one declared variable",
        ),
        (
            "p_theta = I*omega, I = x",
            "1:24: the condition sets the parameter I to a function of phase space (it holds x, \
             a coordinate)",
        ),
    ] {
        let (out, err) = rank(when, "4", 2);
        assert!(out.is_empty(), "{when}: {out}");
        assert!(
            err.starts_with(&format!("superint: error: <command line>:{message}")),
            "{when}: {err}"
        );
    }
}

/// A negative number given to a numeric option is refused by the option's own check, not as an
/// unexpected argument with clap's tip to write `-- -5`, which would make it a positional
/// argument and fail again; a count or a limit says in words what it takes, where `u64`'s
/// parser said "invalid digit found in string".
#[test]
fn cli_a_negative_number_for_an_option_gets_its_range() {
    let fl = "systems/fokas-lagerstrom-1-3.toml";
    let start = "x = 1, y = 0, p_x = 0, p_y = 1";
    for (args, message) in [
        (
            vec![
                "plot",
                fl,
                "S",
                "--at",
                "M = 1, omega = 1",
                "--from",
                start,
                "--time",
                "-5",
            ],
            "invalid value '-5' for '--time <T>': not a positive number of time units",
        ),
        (
            vec!["search", fl, "--momenta-degree", "-1"],
            "invalid value '-1' for '--momenta-degree <D>': -1 is not in 0..=20",
        ),
        (
            vec!["tower", "--system", fl, "--max", "-3"],
            "invalid value '-3' for '--max <N>': -3 is not in 1..=64",
        ),
        (
            vec!["closure", fl, "H", "--degree", "-2"],
            "invalid value '-2' for '--degree <D>': -2 is not in 0..=64",
        ),
        (
            vec!["rank", fl, "H", "--expect", "-1"],
            "invalid value '-1' for '--expect <R>': a negative number, where a whole number (a \
             rank) is expected",
        ),
        (
            vec!["check", fl, "--max-terms", "-5"],
            "invalid value '-5' for '--max-terms <N>': a negative number, where a whole number \
             (at least 1) is expected",
        ),
        (
            vec!["closure", fl, "H", "--max-monomials", "0"],
            "invalid value '0' for '--max-monomials <N>': 0, where the least is 1",
        ),
        (
            vec!["check", fl, "--max-term-products", "1.5"],
            "invalid value '1.5' for '--max-term-products <N>': not a whole number (at least 1)",
        ),
        (
            vec!["check", fl, "--max-degree", "-4"],
            "invalid value '-4' for '--max-degree <D>': -4 is not in 1..=32767",
        ),
    ] {
        let o = superint_exits(&args, 2);
        let err = stderr(&o);
        assert!(err.contains(message), "{args:?}: {err}");
        assert!(!err.contains("tip:"), "{args:?}: {err}");
    }
}

/// A ranged option (`--degree`, `--max`, `--max-degree`, a bench's size) refuses a whole
/// number past 64 bits as out of its range, as it does a smaller one, and text that is no whole
/// number in words: clap's integer parser said "number too large to fit in target type",
/// "invalid digit found in string" and "cannot parse integer from empty string".
#[test]
fn cli_a_ranged_option_refuses_any_number_or_text_in_words() {
    let fl = "systems/fokas-lagerstrom-1-3.toml";
    for (args, message) in [
        (
            vec!["closure", fl, "H", "--degree", "99999999999999999999"],
            "invalid value '99999999999999999999' for '--degree <D>': 99999999999999999999 is \
             not in 0..=64",
        ),
        (
            vec!["tower", "--system", fl, "--max", "-99999999999999999999"],
            "invalid value '-99999999999999999999' for '--max <N>': -99999999999999999999 is \
             not in 1..=64",
        ),
        (
            vec!["check", fl, "--max-degree", "1.5"],
            "invalid value '1.5' for '--max-degree <D>': not a whole number (from 1 to 32767)",
        ),
        (
            vec!["search", fl, "--trig-degree", ""],
            "invalid value '' for '--trig-degree <K>': not a whole number (from 0 to 20)",
        ),
        (
            vec!["bench", "W1", "x"],
            "invalid value 'x' for '<SIZE>': not a whole number (from 1 to 100000)",
        ),
    ] {
        let o = superint_exits(&args, 2);
        let err = stderr(&o);
        assert!(err.contains(message), "{args:?}: {err}");
    }
    // A number too long to echo is shown as its quotation shows it, not written out whole.
    let long = "9".repeat(120);
    let o = superint_exits(&["closure", fl, "H", "--degree", &long], 2);
    let err = stderr(&o);
    let shown = format!("{}… is not in 0..=64", "9".repeat(40));
    assert!(err.contains(&shown), "{err}");
    assert!(!err.contains(&long), "{err}");
    // Just past the range, refused as it was.
    let o = superint_exits(&["closure", fl, "H", "--degree", "65"], 2);
    assert!(stderr(&o).contains("65 is not in 0..=64"), "{}", stderr(&o));
    // At either end of the range, and with a sign, read as it was.
    superint_exits(&["check", fl, "--max-degree", "32767", "--no-timings"], 0);
    superint_exits(&["check", fl, "--max-degree", "+32767", "--no-timings"], 0);
    let o = superint_exits(&["closure", fl, "H", "--degree", "0", "--no-timings"], 0);
    assert!(stdout(&o).starts_with("Closure of H"), "{}", stdout(&o));
}

/// A table takes the phase variables as `closure` does: the Euclidean algebra e(2) of a free
/// particle is `table FILE p_x p_y L` with no `[[function]]` for the momenta, and so(3) is the
/// Euler top's `M1 M2 M3`. Both were refused as "not a function"; an angle and a parameter
/// still are, each said to be what it is.
#[test]
fn cli_table_takes_phase_variables() {
    let free = crate::scratch_text(
        "table-variables",
        "free.toml",
        "hamiltonian = \"(p_x^2 + p_y^2)/(2*m)\"\n[phase_space]\ncoordinates = [\"x\", \"y\"]\n\
         angles = [\"theta\"]\nparameters = [\"m\"]\n[[function]]\nname = \"L\"\n\
         value = \"x*p_y - y*p_x\"\n",
    );
    let free = free.to_str().expect("a path");
    let out = run(&["table", free, "p_x", "p_y", "L", "--no-timings"], 0);
    assert!(out.contains("    p_x   │ 0     0      −p_y\n"), "{out}");
    assert!(out.contains("    L     │ p_y   −p_x   0\n"), "{out}");
    let out = run(&["table", free, "p_theta", "x", "--no-timings"], 0);
    assert!(out.contains("    p_θ   │ 0     0\n"), "{out}");
    let top = run(
        &[
            "table",
            "systems/euler-top.toml",
            "M1",
            "M2",
            "M3",
            "--no-timings",
        ],
        0,
    );
    assert!(top.contains("    M1    │ 0     M3    −M2\n"), "{top}");
    for (name, message) in [
        (
            "theta",
            "'theta' is an angle, not a function of FILE: a [[function]] can name its cosine \
             or sine (value = \"cos(theta)\") (known: H, L, x, y, p_x, p_y, p_theta)",
        ),
        (
            "m",
            "'m' is a parameter, not a function of FILE: every bracket with it is 0 (known: H, \
             L, x, y, p_x, p_y, p_theta)",
        ),
        (
            "z",
            "'z' is not a function of FILE (known: H, L, x, y, p_x, p_y, p_theta)",
        ),
        (
            "px",
            "'px' is not a function of FILE; did you mean 'p_x'? (known: H, L, x, y, p_x, p_y, \
             p_theta)",
        ),
    ] {
        let o = superint(&["table", free, "L", name]);
        assert_eq!(o.status.code(), Some(2), "{name}");
        assert_eq!(
            stderr(&o),
            format!(
                "superint: error: <command line>:1:1: {}\n 1 | {name}\n   | {}\n",
                message.replace("FILE", free),
                "^".repeat(name.len())
            )
        );
    }
}

/// A function given twice to a table, a rank or a closure is refused at its second mention,
/// however it is spelt (`K_{01,1}` is `K_1_1`): a table showed its row twice, a rank counted
/// it twice, and a closure of `K_1_1 K_01_1` found the relation `K_1_1 = K_01_1`. A bracket
/// `{L, L}` is a bracket like another (0).
#[test]
fn cli_a_function_given_twice_is_refused_where_it_repeats() {
    let rotor = "systems/harmonic-rotor.toml";
    for (args, message) in [
        (
            vec!["table", rotor, "L", "G1", "L"],
            "superint: error: <command line>:1:1: 'L' is given twice: a table takes each \
             function once\n 1 | L\n   | ^\n",
        ),
        (
            vec!["table", rotor, "K_1_1", "L", "K_{1,1}"],
            "superint: error: <command line>:1:1: 'K_{1,1}' is 'K_1_1', given before: a table \
             takes each function once\n 1 | K_{1,1}\n   | ^^^^^^^\n",
        ),
        (
            vec!["rank", rotor, "F2 + L", "G1", "F2+L"],
            "superint: error: <command line>:1:1: 'F2+L' is 'F2 + L', given before: a rank \
             takes each function once\n 1 | F2+L\n   | ^^^^\n",
        ),
        (
            vec!["closure", rotor, "L", "G1", "L"],
            "superint: error: <command line>:1:1: 'L' is given twice: the closure takes each \
             function once\n 1 | L\n   | ^\n",
        ),
        (
            vec!["closure", rotor, "L", "K_1_1", "K_{01,1}"],
            "superint: error: <command line>:1:1: 'K_{01,1}' is 'K_1_1', given before: the \
             closure takes each function once\n 1 | K_{01,1}\n   | ^^^^^^^^\n",
        ),
        (
            vec!["closure", "--system", "harmonic", "L", "G1", "L"],
            "superint: error: <command line>:1:1: 'L' is given twice: the closure takes each \
             function once\n 1 | L\n   | ^\n",
        ),
    ] {
        let o = superint(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(stdout(&o).is_empty(), "{args:?}");
        assert_eq!(stderr(&o), message, "{args:?}");
    }
    let out = run(&["bracket", rotor, "L", "L", "--no-timings"], 0);
    assert!(out.contains("{L, L} = 0"), "{out}");
}

/// A function given twice by its name and by its display (`Omega` and `Ω`) is refused at the
/// second as one family instance written two ways is, for a file's closure, table and rank and
/// for a built-in system's closure: a closure of `L Omega Ω` stopped at naming its generators,
/// "variable \"Ω\" is declared twice", and a table and a rank took `Ω` twice.
#[test]
fn cli_a_function_given_by_its_name_and_its_display_is_refused_where_it_repeats() {
    let rotor = "systems/harmonic-rotor.toml";
    let refusal = |given: &str, before: &str, what: &str| {
        let caret = "^".repeat(given.chars().count());
        format!(
            "superint: error: <command line>:1:1: '{given}' is '{before}', given before: {what} \
             takes each function once\n 1 | {given}\n   | {caret}\n"
        )
    };
    for (args, message) in [
        (
            vec!["closure", rotor, "L", "Omega", "Ω"],
            refusal("Ω", "Omega", "the closure"),
        ),
        (
            vec!["closure", "--system", "harmonic", "L", "Omega", "Ω"],
            refusal("Ω", "Omega", "the closure"),
        ),
        (
            vec!["table", rotor, "L", "Ω", "Omega"],
            refusal("Omega", "Ω", "a table"),
        ),
        (
            vec!["rank", rotor, "L", "Omega", "Ω"],
            refusal("Ω", "Omega", "a rank"),
        ),
    ] {
        let o = superint(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(stdout(&o).is_empty(), "{args:?}");
        assert_eq!(stderr(&o), message, "{args:?}");
    }
}

/// A comma with no assignment after it (or before it) is said to be one, the caret under the
/// comma: the caret stood past the end of the text, under nothing, with only the form of a
/// condition as the message.
#[test]
fn cli_a_comma_with_no_assignment_after_it_is_underlined() {
    let rotor = "systems/harmonic-rotor.toml";
    let full = "x = 1, y = 0, theta = 0, p_x = 0, p_y = 1/2, p_theta = 1";
    let plot = |at: &str, from: &str| {
        let (at, from) = (at.to_string(), from.to_string());
        let args = [
            "plot", rotor, "L", "--at", &at, "--from", &from, "--time", "1",
        ];
        let mut args: Vec<String> = args.iter().map(|a| a.to_string()).collect();
        args.extend(["-o".into(), "-".into()]);
        args
    };
    for (args, message) in [
        (
            ["expand", rotor, "H", "--when", "M = 1,"]
                .map(String::from)
                .to_vec(),
            "superint: error: <command line>:1:6: a condition is missing after this comma: a \
             condition reads `variable = value`, such as \"p_theta = 2*I*omega/3\"\n 1 | M = \
             1,\n   |      ^\n",
        ),
        (
            ["bracket", rotor, "L", "H", "--when", ", M = 1"]
                .map(String::from)
                .to_vec(),
            "superint: error: <command line>:1:1: a condition is missing before this comma: a \
             condition reads `variable = value`, such as \"p_theta = 2*I*omega/3\"\n 1 | , M \
             = 1\n   | ^\n",
        ),
        (
            plot("M = 1, omega = 1, I = 1, ", full),
            "superint: error: <command line>:1:24: a value of --at is missing after this comma: \
             --at reads `parameter = number, …`, such as \"M = 1, omega = 3/2\"\n 1 | M = 1, \
             omega = 1, I = 1, \n   |                        ^\n",
        ),
        (
            [
                "closure",
                "--system",
                "harmonic",
                "L",
                "G1",
                "--when",
                "M = 1,,omega = 2",
            ]
            .map(String::from)
            .to_vec(),
            "superint: error: <command line>:1:6: a condition is missing after this comma: a \
             condition reads `variable = value`, such as \"p_theta = 2*I*omega/3\"\n 1 | M = \
             1,,omega = 2\n   |      ^\n",
        ),
    ] {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = superint(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert_eq!(stderr(&o), message, "{args:?}");
    }
}

/// A rank refused for one function (a limit its derivatives reach) underlines that function,
/// on the command line and in a file's claim: the caret underlined the whole list.
#[test]
fn cli_a_rank_refused_for_one_function_underlines_it() {
    let o = superint(&["rank", "systems/calogero.toml", "x", "1/(x-y)^1000", "y"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).starts_with(
            "superint: error: <command line>:1:3: the exponent of (x − y) would reach -1001, past \
             the limit of 1000\n 1 | x 1/(x-y)^1000 y\n   |   ^^^^^^^^^^^^\n"
        ),
        "{}",
        stderr(&o)
    );
    let file = scratch_file("rank-one-function.toml");
    let text = "hamiltonian = \"p_x^2/2\"\n[phase_space]\ncoordinates = [\"x\", \"y\"]\n\
                denominators = [\"x - y\"]\n[[claim]]\nclaim = \"rank(x, 1/(x-y)^1000) = 2\"\n";
    std::fs::write(&file, text).expect("write the file");
    let o = superint(&["check", file.to_str().expect("a path")]);
    assert_eq!(o.status.code(), Some(2));
    let caret = format!("   | {}{}\n", " ".repeat(17), "^".repeat(12));
    let message = "rank-one-function.toml:6:18: the exponent of (x − y) would reach -1001, past \
                   the limit of 1000\n 6 | claim = \"rank(x, 1/(x-y)^1000) = 2\"\n";
    assert!(
        stderr(&o).contains(&format!("{message}{caret}")),
        "{}",
        stderr(&o)
    );
}

/// A name the command line echoes is quoted as the lowering quotes an unknown name, whole or,
/// past 80 characters, by its first 40 and its length: a name typed by mistake was echoed
/// whole (300 characters here, or a whole file pasted). `--define` refuses a name past 80
/// characters, which every message and the report would print.
#[test]
fn cli_echoed_names_are_quoted_and_shortened_alike() {
    let long = "a".repeat(300);
    let quoted = format!("'{}…', 300 characters long", "a".repeat(40));
    let rotor = "systems/harmonic-rotor.toml";
    let define = format!("{long}=x");
    let fix = format!("{long}=1");
    let (angle, function) = (format!("cos({long})"), format!("{long}(x)"));
    for (args, message) in [
        (
            vec!["table", rotor, &long],
            format!("{quoted} is not a function of systems/harmonic-rotor.toml"),
        ),
        (
            vec!["closure", rotor, "L", "--define", &define],
            "<command line>:1:1: --define: a name has at most 80 characters".to_string(),
        ),
        (
            vec!["closure", rotor, "L", "--fix", &fix],
            format!("--fix: {quoted} is not a parameter of the system"),
        ),
        (
            vec!["closure", rotor, "L", "--symbolic", &long],
            format!("--symbolic: {quoted} is not a parameter of the system"),
        ),
        (
            vec!["closure", "--system", &long, "L"],
            format!("unknown system {quoted} (built-in: harmonic"),
        ),
        (
            vec![
                "plot",
                rotor,
                "L",
                "--at",
                "M = 1, omega = 1, I = 1",
                "--from",
                "x = 1, y = 0, theta = 0, p_x = 0, p_y = 1, p_theta = 1",
                "--time",
                &long,
                "-o",
                "-",
            ],
            format!("invalid value {quoted} for '--time <T>': not a positive number of time units"),
        ),
        (
            vec!["tower", "--system", &long],
            format!(
                "error: invalid value {quoted} for '--system \
                 <harmonic|gravity|FILE>': no built-in system {quoted} (harmonic, gravity), and \
                 no file of that name\n\nFor more information, try '--help'.\n"
            ),
        ),
        (
            vec!["closure", "--system", "harmonic", "L", "--when", &fix],
            format!(
                "the left side of a condition is one declared variable (a coordinate, a momentum \
                 or a parameter), found {quoted}"
            ),
        ),
        (
            vec!["expand", rotor, "x", "--when", &fix],
            format!(
                "one declared variable (a coordinate, a momentum or a parameter), found {quoted}"
            ),
        ),
        (
            vec!["expand", rotor, &angle],
            format!("<command line>:1:5: unknown angle {quoted}\n"),
        ),
        (
            vec!["expand", rotor, &function],
            format!("<command line>:1:1: unknown function {quoted} (known: cos, sin"),
        ),
        (
            vec!["closure", rotor, "L", &long],
            format!("superint: error: <command line>:1:1: unknown name {quoted}"),
        ),
    ] {
        let o = superint(&args);
        assert_eq!(o.status.code(), Some(2), "{message}");
        let err = stderr(&o);
        assert!(err.contains(&message), "{err}");
        assert!(!err.contains(&"a".repeat(81)), "{err}");
    }
    // A name of 80 characters is still one.
    let eighty = "b".repeat(80);
    let out = run(
        &[
            "closure",
            rotor,
            "L",
            &eighty,
            "--define",
            &format!("{eighty}=x"),
            "--degree",
            "1",
        ],
        0,
    );
    assert!(out.contains(&eighty), "{out}");
}

/// A comma with no value after it (or before it) in --fix is refused at the comma, as one in
/// --when is: --fix 'M=1,' was read as 'M=1', where --when 'M = 1,' is refused.
#[test]
fn cli_a_comma_with_no_value_beside_it_is_refused_by_fix() {
    let rotor = "systems/harmonic-rotor.toml";
    for (fix, column) in [("M=1,", 4), ("M=1, ,omega=2", 4), (" ,M=1", 2)] {
        let side = if column == 2 { "before" } else { "after" };
        let message = refused_at(
            fix,
            column,
            "^",
            &format!(
                "--fix: a value is missing {side} this comma: give a value as NAME=VALUE, such \
                 as omega=1"
            ),
        );
        for args in [
            vec!["closure", rotor, "L", "--fix", fix],
            vec!["search", "--system", "harmonic", "--fix", fix],
        ] {
            let o = superint(&args);
            assert_eq!(o.status.code(), Some(2), "{args:?}");
            assert_eq!(stderr(&o), message, "{args:?}");
        }
    }
}

/// A refusal of a command-line text at column `column`, underlined by `caret`, as a --when
/// condition's is: `<command line>:1:C: message`, the numbered line and the caret.
fn refused_at(text: &str, column: usize, caret: &str, message: &str) -> String {
    format!(
        "superint: error: <command line>:1:{column}: {message}\n 1 | {text}\n   | {}{caret}\n",
        " ".repeat(column - 1)
    )
}

/// `--fix` takes zero, so a known integral or a generator that divides by the parameter has
/// no value where the linear algebra is: refused naming the parameter (exit 2), for search
/// and closure alike; it read `division by zero`, naming nothing.
#[test]
fn cli_fix_to_zero_of_a_parameter_divided_by_names_it() {
    let says = "p_θ/ω divides by ω, so it has no value at ω = 0, the value the linear algebra \
                takes: give ω another value";
    let known = [
        "search",
        "--system",
        "harmonic",
        "--fix",
        "omega=0",
        "--new-only",
    ];
    let closure = [
        "closure", "--system", "harmonic", "L", "K", "--fix", "omega=0",
    ];
    for args in [
        [&known[..], &["--known", "p_theta/omega"]].concat(),
        [&closure[..], &["--define", "K=p_theta/omega"]].concat(),
    ] {
        let refused = String::from_utf8(superint_exits(&args, 2).stderr).unwrap();
        assert!(refused.contains(says), "{args:?}: {refused}");
    }
}

/// Every refusal of --fix and --symbolic that is about a place in its text says it as --when
/// does, `<command line>:1:C:` with the option named, the text and a caret under the place
/// (the comma with nothing beside it, the value with no `=`, the name that is no parameter or
/// comes twice, the value that is no number or a zero where H has none), for a file and a built-in system,
/// for search and closure alike: the comma's place was said in words, `after the comma at
/// column 4`, and the others had no place at all.
#[test]
fn cli_fix_and_symbolic_refuse_at_their_place_as_when_does() {
    let rotor = "systems/harmonic-rotor.toml";
    let usage = "give a value as NAME=VALUE, such as omega=1";
    let cases: Vec<(&str, &str, usize, &str, String)> = vec![
        (
            "--fix",
            "M=1,",
            4,
            "^",
            format!("a value is missing after this comma: {usage}"),
        ),
        (
            "--fix",
            "M=1,,omega=2",
            4,
            "^",
            format!("a value is missing after this comma: {usage}"),
        ),
        (
            "--fix",
            ",M=1",
            1,
            "^",
            format!("a value is missing before this comma: {usage}"),
        ),
        (
            "--fix",
            "M=1,omega",
            5,
            "^^^^^",
            format!("'omega' has no '=': {usage}"),
        ),
        (
            "--fix",
            "M=1, =2",
            6,
            "^",
            format!("a name is missing before this '=': {usage}"),
        ),
        (
            "--fix",
            "M= ",
            2,
            "^",
            format!("a value is missing after this '=': {usage}"),
        ),
        (
            "--fix",
            "M=1, m=2",
            6,
            "^",
            "'m' is not a parameter of the system; did you mean 'M'? (its parameters: M, omega, \
             I"
            .into(),
        ),
        (
            "--fix",
            "M = two",
            5,
            "^^^",
            "'two' is not a number: write a fraction such as 2/3, or a decimal such as 1.5".into(),
        ),
        (
            "--fix",
            "M=3/0",
            3,
            "^^^",
            "'3/0' is a division by zero: a fraction's denominator is nonzero".into(),
        ),
        (
            "--fix",
            "ω=1, omega=2",
            6,
            "^^^^^",
            "'omega' is given two values".into(),
        ),
        (
            "--fix",
            "omega=1,M=0",
            11,
            "^",
            "M = 0: H divides by M, so it has no value at M = 0: give M another value".into(),
        ),
        (
            "--symbolic",
            "omega,",
            6,
            "^",
            "a parameter is missing after this comma: name parameters as A,B, such as M,omega"
                .into(),
        ),
        (
            "--symbolic",
            "M, Q",
            4,
            "^",
            "'Q' is not a parameter of the system (its parameters: M, omega, I".into(),
        ),
        (
            "--symbolic",
            "omega, ω",
            8,
            "^",
            "'ω' is named twice".into(),
        ),
    ];
    for (option, text, column, caret, message) in &cases {
        let expected = refused_at(text, *column, caret, &format!("{option}: {message}"));
        // The built-in system's parameters are the file's but for its l, listed last.
        let (head, tail) = expected.split_at(expected.find("\n").expect("a line"));
        for system in [&["--system", "harmonic"][..], &[rotor][..]] {
            for command in [
                [&["search"], system, &DEGREE_ONE_TRIG_ZERO[..]].concat(),
                [&["closure"], system, &["G1", "G2"][..]].concat(),
            ] {
                let args = [&command[..], &[*option, *text]].concat();
                let o = superint(&args);
                assert_eq!(o.status.code(), Some(2), "{args:?}");
                let got = stderr(&o);
                let (got_head, got_tail) = got.split_at(got.find('\n').expect("a line"));
                assert!(got_head.starts_with(head), "{args:?}\n{got}\n{expected}");
                assert_eq!(got_tail, tail, "{args:?}");
            }
        }
    }
}

/// --fix and --symbolic read a parameter's name as --when reads a variable's, by the parser:
/// `\omega` names omega there as in --when '\omega = 1', where it was refused as no parameter
/// of the system (did you mean 'omega'?); and named beside `omega` it is named twice.
#[test]
fn cli_fix_and_symbolic_read_a_parameter_written_in_latex() {
    let rotor = "systems/harmonic-rotor.toml";
    for system in [&["--system", "harmonic"][..], &[rotor][..]] {
        for (command, option, latex, plain) in [
            (&["search"][..], "--fix", r"\omega=2, M=1", "omega=2, M=1"),
            (&["closure"][..], "--symbolic", r"M, \omega", "M, omega"),
        ] {
            let run = |list: &str| {
                let tail: &[&str] = match command[0] {
                    "search" => &DEGREE_ONE_TRIG_ZERO,
                    _ => &["G1", "G2"],
                };
                let args = [command, system, tail, &["--no-timings", option, list]].concat();
                let o = superint(&args);
                assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
                stdout(&o)
            };
            assert_eq!(run(latex), run(plain), "{system:?} {option} {latex}");
        }
        for (option, list, column, message) in [
            (
                "--fix",
                r"omega=1, \omega=2",
                10,
                r"'\omega' is given two values",
            ),
            (
                "--symbolic",
                r"omega, \omega",
                8,
                r"'\omega' is named twice",
            ),
        ] {
            let args = [&["closure"][..], system, &["G1", "G2", option, list]].concat();
            let o = superint(&args);
            assert_eq!(o.status.code(), Some(2), "{args:?}");
            assert_eq!(
                stderr(&o),
                refused_at(list, column, "^^^^^^", &format!("{option}: {message}")),
                "{args:?}"
            );
        }
    }
}

/// An expression of spaces alone has the caret past them, where its input ends, as an empty
/// one has it where it ends: the caret stood at column 1, under the first space.
#[test]
fn cli_an_expression_of_spaces_is_underlined_where_it_ends() {
    let rotor = "systems/harmonic-rotor.toml";
    for (args, message) in [
        (
            vec!["expand", rotor, ""],
            "superint: error: <command line>:1:1: expected an expression, found end of input\n \
             1 | \n   | ^\n",
        ),
        (
            vec!["expand", rotor, "   "],
            "superint: error: <command line>:1:4: expected an expression, found end of input\n \
             1 |    \n   |    ^\n",
        ),
        (
            vec!["rank", rotor, "L", "  "],
            "superint: error: <command line>:1:3: expected an expression, found end of input\n \
             1 |   \n   |   ^\n",
        ),
    ] {
        let o = superint(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert_eq!(stderr(&o), message, "{args:?}");
    }
}

/// A condition with an empty side (`M =   `) has the caret under that side, as a claim has:
/// it underlined the whole condition.
#[test]
fn cli_a_condition_with_an_empty_side_underlines_that_side() {
    let rotor = "systems/harmonic-rotor.toml";
    for (when, message) in [
        (
            "M =   ",
            "superint: error: <command line>:1:4: a condition reads `variable = value`, such as \
             \"p_theta = 2*I*omega/3\"; one side is empty\n 1 | M =   \n   |    ^^^\n",
        ),
        (
            "M = 1, omega =",
            "superint: error: <command line>:1:15: a condition reads `variable = value`, such as \
             \"p_theta = 2*I*omega/3\"; one side is empty\n 1 | M = 1, omega =\n   |        \
             \x20      ^\n",
        ),
    ] {
        let o = superint(&["expand", rotor, "H", "--when", when]);
        assert_eq!(o.status.code(), Some(2), "{when}");
        assert_eq!(stderr(&o), message, "{when}");
    }
}

/// A name past 80 characters in a file is refused where it is declared, shown by its start
/// and its length (it was taken, and echoed whole by every message that named it); a family
/// the command line names that the file does not declare is quoted alike.
#[test]
fn cli_names_from_a_file_are_quoted_and_shortened_alike() {
    let long = "a".repeat(300);
    let quoted = format!("'{}…', 300 characters long", "a".repeat(40));
    let text = format!(
        "name = \"long\"\nhamiltonian = \"p_x^2/2 + {long}*x\"\n[phase_space]\n\
         coordinates = [\"x\"]\nparameters = [\"{long}\"]\n"
    );
    let file = crate::scratch_text("long-names", "long.toml", &text);
    let file = file.to_str().expect("UTF-8");
    for (args, message) in [
        (
            vec!["closure", file, "x", &long],
            format!(
                "superint: error: {file}:5:15: {quoted} cannot name a parameter: a name has at \
                 most 80 characters"
            ),
        ),
        (
            vec![
                "tower",
                "--system",
                "systems/harmonic-rotor.toml",
                "--family",
                &long,
            ],
            format!(
                "superint: error: <command line>:1:1: --family: no family named {quoted} (the \
                 file declares K, Kbar, P, Q)"
            ),
        ),
    ] {
        let o = superint(&args);
        assert_eq!(o.status.code(), Some(2), "{message}");
        assert_eq!(stderr(&o).lines().next(), Some(message.as_str()));
    }
}

/// A built-in system's --when of blanks alone, or with an empty side, is refused as a file's
/// is, where the value's parser reported an end of input at line 1, column 1 of nothing shown:
/// at `<command line>:1:C:`, the numbered line and a caret under the blank.
#[test]
fn cli_a_builtin_systems_blank_condition_is_said_to_be_empty() {
    let usage = "a condition reads `variable = value`, such as \"p_theta = 2*I*omega/3\"";
    for (when, message) in [
        ("", format!("1:1: {usage}\n 1 | \n   | ^")),
        ("   ", format!("1:1: {usage}\n 1 |    \n   | ^^^")),
        (
            "M = ",
            format!("1:4: {usage}; one side is empty\n 1 | M = \n   |    ^"),
        ),
        (
            "M = 1,  = 2",
            format!("1:7: {usage}; one side is empty\n 1 | M = 1,  = 2\n   |       ^^"),
        ),
    ] {
        let o = superint(&["closure", "--system", "harmonic", "L", "--when", when]);
        assert_eq!(o.status.code(), Some(2), "{when:?}");
        assert_eq!(
            stderr(&o),
            format!("superint: error: <command line>:{message}\n")
        );
    }
}

/// A built-in system's --when refuses a condition on an angle as a file's does, at the angle's
/// name: it said that `theta = 0` sets e^{iθ} to 0, no value of it, and took `theta = 1`, to
/// refuse the search later because the flow leaves the surface.
#[test]
fn cli_a_builtin_systems_condition_on_an_angle_is_refused_as_a_files() {
    let refusal = "a condition cannot fix an angle: functions depend on it through cos, sin, exp";
    for (when, column, caret) in [
        ("theta = 1", 1, "^^^^^"),
        ("theta = 0", 1, "^^^^^"),
        ("p_theta = 1, theta = 1", 14, "^^^^^"),
        (r"\theta = 1", 1, "^^^^^^"),
        (" θ = 1", 2, "^"),
        ("ω = 1, θ = 1", 8, "^"),
    ] {
        let builtin = search_when_refused(&["--system", "harmonic"], when);
        assert_eq!(
            builtin,
            refused_at(when, column, caret, refusal),
            "{when:?}"
        );
        let file = search_when_refused(&["systems/harmonic-rotor.toml"], when);
        assert_eq!(builtin, file, "{when:?}");
    }
}

/// The stderr of a search of `system` (a file or `--system NAME`) whose `--when when` is
/// refused.
fn search_when_refused(system: &[&str], when: &str) -> String {
    let o = superint(
        &[
            &["search"],
            system,
            &["--when", when],
            &DEGREE_ONE_TRIG_ZERO,
        ]
        .concat(),
    );
    assert_eq!(o.status.code(), Some(2), "{when:?}: {}", stderr(&o));
    stderr(&o)
}

/// A malformed --when of a built-in system is refused in the words and the form of a file's,
/// `<command line>:1:C:` with the numbered line and a caret: it was `--when: 'omega 1': a
/// condition reads …` with no place, the variable set twice `the condition sets x twice`, and
/// an unknown left side `'q' is not a variable of the system`, each other words than a file's.
#[test]
fn cli_a_builtin_systems_malformed_condition_reads_as_a_files() {
    for when in [
        "omega 1",
        "omega == 1",
        "q = 1",
        "omga = 1",
        "x = 1, x = 2",
        ", omega = 1",
        "p_theta = x, x = p_theta",
        // An `=` inside parentheses or braces splits no condition, as in a file's.
        "(x = 1",
        "x_{ = 1",
    ] {
        let builtin = search_when_refused(&["--system", "harmonic"], when);
        let file = search_when_refused(&["systems/harmonic-rotor.toml"], when);
        assert_eq!(builtin, file, "{when:?}");
        assert!(
            builtin.starts_with("superint: error: <command line>:1:"),
            "{builtin}"
        );
    }
    let o = superint(&["search", "--system", "harmonic", "--when", "omega 1"]);
    assert_eq!(
        stderr(&o),
        "superint: error: <command line>:1:1: a condition reads `variable = value`, such as \
         \"p_theta = 2*I*omega/3\"\n 1 | omega 1\n   | ^^^^^^^\n"
    );
}

/// A built-in system's --when reads its left side as a file's does, by the parser: a variable
/// written in LaTeX, `\omega`, `p_{\theta}`, names it (it was refused as no variable of the
/// system, with did you mean 'omega'?).
#[test]
fn cli_a_builtin_systems_condition_names_a_variable_written_in_latex() {
    for (latex, plain) in [
        (r"\omega = 1", "omega = 1"),
        (r"p_{\theta} = I*omega", "p_theta = I*omega"),
    ] {
        let run = |when: &str| {
            let o = superint(
                &[
                    &["search", "--system", "harmonic", "--when", when][..],
                    &DEGREE_ONE_TRIG_ZERO,
                    &["--no-timings"],
                ]
                .concat(),
            );
            assert_eq!(o.status.code(), Some(0), "{when:?}: {}", stderr(&o));
            String::from_utf8(o.stdout).expect("UTF-8")
        };
        assert_eq!(run(latex), run(plain), "{latex:?}");
    }
}

/// An unknown name given on the command line to a built-in system is hinted at with what the
/// command line can do, not with the library's calls: `rank --system harmonic L Foo` said that
/// a named function is added with LoadedSystem::add_function, which no command-line user can
/// call. A file's unknown name keeps the file's hint.
#[test]
fn cli_a_built_in_systems_unknown_name_is_hinted_at_for_the_command_line() {
    for args in [
        &["rank", "--system", "harmonic", "L", "Foo"][..],
        &["bracket", "--system", "gravity", "L", "Foo"][..],
        &["expand", "--system", "harmonic", "Foo"][..],
    ] {
        let o = superint(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = stderr(&o);
        let hint = err.lines().find(|l| l.starts_with("hint: "));
        assert_eq!(
            hint,
            Some(
                "hint: a built-in system knows only the names listed: write a function as an \
                 expression in them (closure names one with --define NAME=EXPR), or write a \
                 system file, which declares constants under [phase_space] parameters and \
                 functions with [[function]]; see docs/system-files.md"
            ),
            "{args:?}: {err}"
        );
        assert!(!err.contains("LoadedSystem"), "{args:?}: {err}");
    }
    let o = superint(&["rank", "systems/harmonic-rotor.toml", "L", "Foo"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("hint: a constant such as a mass is declared under [phase_space]"),
        "{}",
        stderr(&o)
    );
}

/// A blank function name given to a table or a closure is refused as a blank expression is,
/// at its end of input: a table said '' is not a function, and a closure that '   ' is an
/// expression, to be named with --define.
#[test]
fn cli_a_blank_function_name_is_refused_where_it_ends() {
    let rotor = "systems/harmonic-rotor.toml";
    let end = |column: usize, text: &str| {
        format!(
            "superint: error: <command line>:1:{column}: expected the name of a function, found \
             end of input\n 1 | {text}\n   | {}^\n",
            " ".repeat(column - 1)
        )
    };
    for (args, message) in [
        (vec!["table", rotor, "L", "   ", "   "], end(4, "   ")),
        (vec!["table", rotor, ""], end(1, "")),
        (vec!["closure", rotor, "L", "  "], end(3, "  ")),
        (
            vec!["closure", "--system", "harmonic", "L", "  "],
            end(3, "  "),
        ),
    ] {
        let o = superint(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert_eq!(stderr(&o), message, "{args:?}");
    }
}

/// A built-in system's closure refuses a generator given twice, or a blank one, as a file's
/// does, at its place in the generator as given (`<command line>:1:C:`, the text and a caret),
/// because it said `'L' is given twice` and `a generator is blank` with no place at all.
#[test]
fn cli_a_built_in_systems_closure_refuses_a_generator_at_its_place_as_a_files() {
    for (generators, message) in [
        (
            &["L", "G1", " L "][..],
            "superint: error: <command line>:1:2: 'L' is given twice: the closure takes each \
             function once\n 1 |  L \n   |  ^\n",
        ),
        (
            &["L", ""][..],
            "superint: error: <command line>:1:1: expected the name of a function, found end of \
             input\n 1 | \n   | ^\n",
        ),
    ] {
        for system in [
            &["systems/harmonic-rotor.toml"][..],
            &["--system", "harmonic"][..],
        ] {
            let o = superint(&[&["closure"][..], system, &["--"][..], generators].concat());
            assert_eq!(o.status.code(), Some(2), "{system:?} {generators:?}");
            assert!(stdout(&o).is_empty(), "{system:?} {generators:?}");
            assert_eq!(stderr(&o), message, "{system:?} {generators:?}");
        }
    }
}

/// A comma with no parameter after it (or before it) in --symbolic is refused at the comma,
/// as one in --fix and --when is: --symbolic 'M,' was read as 'M'.
#[test]
fn cli_a_comma_with_no_parameter_beside_it_is_refused_by_symbolic() {
    let rotor = "systems/harmonic-rotor.toml";
    for (symbolic, side, column) in [
        ("M,", "after", 2),
        ("M,,omega", "after", 2),
        (",M", "before", 1),
    ] {
        let o = superint(&["closure", rotor, "L", "--symbolic", symbolic]);
        assert_eq!(o.status.code(), Some(2), "{symbolic}");
        let message = refused_at(
            symbolic,
            column,
            "^",
            &format!(
                "--symbolic: a parameter is missing {side} this comma: name parameters as A,B, \
                 such as M,omega"
            ),
        );
        assert_eq!(stderr(&o), message, "{symbolic}");
    }
}

/// A parameter named twice in --symbolic is refused, as one given two values by --fix is: it
/// was kept symbolic twice, the closure finding the relations 0 = 0 and the search losing `H`
/// to a degree in `M, M` past the space's.
#[test]
fn cli_a_parameter_named_twice_is_refused_by_symbolic() {
    let rotor = "systems/harmonic-rotor.toml";
    for (command, symbolic, twice, column) in [
        (vec!["closure", rotor, "L", "G1", "G2"], "omega,ω", "ω", 7),
        (vec!["search", rotor], "M, M", "M", 4),
    ] {
        let o = superint(&[&command[..], &["--symbolic", symbolic]].concat());
        assert_eq!(o.status.code(), Some(2), "{symbolic}");
        let message = refused_at(
            symbolic,
            column,
            "^",
            &format!("--symbolic: '{twice}' is named twice"),
        );
        assert_eq!(stderr(&o), message, "{symbolic}");
    }
}

/// Every refusal of --known about a place in its text says it as --fix and --when do,
/// `<command line>:1:C: --known:`, the whole list and a caret under the place, for a file and a
/// built-in system: a comma with no expression beside it (a comma inside an instance's braces
/// is the instance's), which was said in words, `missing after the comma at column 2`, and an
/// expression that does not parse, which was placed in that expression alone, as if it were
/// the whole text (`<command line>:1:1: unknown name 'zz'` under `zz` for `p_theta, zz`).
#[test]
fn cli_known_refuses_at_its_place_as_fix_does() {
    let usage = "expressions or family instances separated by commas, such as L,P_1_1";
    let cases: Vec<(&str, usize, &str, String)> = vec![
        (
            "L,",
            2,
            "^",
            format!("an expression is missing after this comma: {usage}"),
        ),
        (
            "K_{1,1}, ,L",
            8,
            "^",
            format!("an expression is missing after this comma: {usage}"),
        ),
        (
            ",L",
            1,
            "^",
            format!("an expression is missing before this comma: {usage}"),
        ),
        (
            "p_theta,x+",
            11,
            "^",
            "expected an expression after '+', found end of input".into(),
        ),
        (
            "ω, (x",
            6,
            "^",
            "expected ')' to close '(' opened at column 4, found end of input".into(),
        ),
        (
            "p_theta, zz",
            10,
            "^^",
            "unknown name 'zz' (known: x, y, theta".into(),
        ),
    ];
    for system in [
        &["systems/harmonic-rotor.toml"][..],
        &["--system", "harmonic"],
    ] {
        for (known, column, caret, message) in &cases {
            let mut args = vec!["search"];
            args.extend_from_slice(system);
            args.extend(["--new-only", "--known", known]);
            let o = superint(&args);
            assert_eq!(o.status.code(), Some(2), "{system:?} {known}");
            let err = stderr(&o);
            let expected = refused_at(known, *column, caret, &format!("--known: {message}"));
            // The first line up to the message, then the text and the caret.
            let (head, tail) = expected.split_once('\n').unwrap();
            let first = err.lines().next().unwrap_or("");
            assert!(first.starts_with(head), "{system:?} {known}: {err}");
            let shown: Vec<&str> = err.lines().skip(1).take(2).collect();
            let wanted: Vec<&str> = tail.lines().collect();
            assert_eq!(shown, wanted, "{system:?} {known}: {err}");
        }
    }
}

/// A known integral that is none, or not real, is refused at its place in --known, as a name
/// it does not know is, for a file and a built-in system: it was said after `searching for
/// integrals:` with no place, `the known integral x is not an integral: {x, H} = p_x at M = 1,
/// ω = 1, I = 1`, and only once the whole search had run. The bracket and the values it was
/// taken at are kept; the condition comes before them. An expression is named as it prints
/// (`x p_x`), for a file and a built-in system alike.
#[test]
fn cli_known_refuses_a_known_integral_that_is_none_at_its_place() {
    let fixed = "M = 1, ω = 1, I = 1";
    let cases: Vec<(&str, &[&str], usize, &str, String)> = vec![
        (
            "p_theta, x",
            &[],
            10,
            "^",
            format!("x is not an integral: {{x, H}} = p_x at {fixed}"),
        ),
        (
            "x*p_x ,p_theta",
            &[],
            1,
            "^^^^^",
            format!("NAME is not an integral: {{NAME, H}} = p_x² − x² at {fixed}"),
        ),
        (
            "p_theta, y",
            &["--when", "p_theta = omega"],
            10,
            "^",
            format!("y is not an integral: {{y, H}} = p_y at p_θ = ω, {fixed}"),
        ),
        (
            "p_theta, i*p_theta",
            &[],
            10,
            "^^^^^^^^^",
            "NAME is not real: give its real and imaginary parts, re(NAME) and im(NAME)".into(),
        ),
    ];
    for system in [
        &["systems/harmonic-rotor.toml"][..],
        &["--system", "harmonic"],
    ] {
        for (known, more, column, caret, message) in &cases {
            let mut args = vec!["search"];
            args.extend_from_slice(system);
            args.extend_from_slice(more);
            args.extend(["--momenta-degree", "1", "--positions-degree", "1"]);
            args.extend(["--trig-degree", "0", "--new-only", "--known", known]);
            let o = superint(&args);
            assert_eq!(o.status.code(), Some(2), "{system:?} {known}");
            let name = match known.starts_with('x') {
                true => "x p_x",
                false => "i p_θ",
            };
            let message = message.replace("NAME", name);
            let expected = refused_at(known, *column, caret, &format!("--known: {message}"));
            assert_eq!(stderr(&o), expected, "{system:?} {known}");
        }
    }
}

/// A known integral given as an expression is named as it prints, for a built-in system as
/// for a file (`2 p_θ²`): a built-in system named it as typed (`2*p_theta^2`).
#[test]
fn cli_a_known_expression_is_named_as_it_prints_for_a_built_in_system_as_for_a_file() {
    for system in [
        &["systems/harmonic-rotor.toml"][..],
        &["--system", "harmonic"][..],
    ] {
        let mut args = vec!["search"];
        args.extend_from_slice(system);
        args.extend(["--momenta-degree", "2", "--positions-degree", "2"]);
        args.extend(["--trig-degree", "0", "--new-only", "--known", "2*p_theta^2"]);
        let o = superint(&args);
        assert_eq!(o.status.code(), Some(0), "{system:?}: {}", stderr(&o));
        let out = stdout(&o).replace('\n', " ");
        let known = out
            .split("Known integrals in the space: ")
            .nth(1)
            .and_then(|rest| rest.split(". ").next())
            .unwrap_or_default();
        assert!(known.ends_with(", 2 p_θ²"), "{system:?}: {out}");
    }
}

/// A known integral that is none is refused before the search forms its space: a space past
/// the term limit, which the search refuses as soon as it counts its unknowns, is not reached.
#[test]
fn cli_known_integral_that_is_none_is_refused_before_the_search() {
    let args = |known: Option<&'static str>| {
        let space = "--momenta-degree 6 --positions-degree 6 --trig-degree 6 --max-terms 500";
        let mut args = vec!["search", "systems/harmonic-rotor.toml", "--new-only"];
        args.extend(space.split_whitespace());
        args.extend(known.map(|k| ["--known", k]).into_iter().flatten());
        args
    };
    let o = superint(&args(None));
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("unknowns, more than the term limit 500"),
        "{}",
        stderr(&o)
    );
    let o = superint(&args(Some("p_theta, x")));
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).starts_with(
            "superint: error: <command line>:1:10: --known: x is not an integral: {x, H} = p_x"
        ),
        "{}",
        stderr(&o)
    );
}

/// Runs the binary and expects exit code 2, nothing on stdout and `message` on stderr.
#[track_caller]
fn assert_bad_usage(args: &[&str], message: &str) {
    let o = superint(args);
    assert_eq!(
        o.status.code(),
        Some(2),
        "superint {args:?}: {}",
        stderr(&o)
    );
    assert!(stdout(&o).is_empty(), "superint {args:?} printed to stdout");
    assert!(
        stderr(&o).contains(message),
        "superint {args:?}: {}",
        stderr(&o)
    );
}

/// A built-in system's condition that fixes a name twice or divides by zero says what to do,
/// as a file's does: both said only what was wrong.
#[test]
fn cli_a_builtin_systems_condition_says_what_to_do() {
    for (when, message) in [
        (
            "M = 1, M = 2",
            "<command line>:1:8: 'M' is fixed twice\n 1 | M = 1, M = 2\n   |        ^\nhint: \
             keep one of its values: a list of values sets each name once",
        ),
        (
            "x = 1/0",
            "<command line>:1:7: division by zero\n 1 | x = 1/0\n   |       ^\nhint: what is \
             divided by here is 0: write a divisor other than 0, or leave the division out",
        ),
    ] {
        assert_bad_usage(&["search", "--system", "harmonic", "--when", when], message);
    }
}

/// A built-in system (`--system`) is held to `--max-terms` and `--max-degree`, and by default
/// to a system file's limits, as the help says: the limits were not passed to it, so that
/// `--max-terms` did nothing there and a search of 2.4 M unknowns ran (the library's default
/// is 20 M terms). Limits too small for the system's own functions are an error that says so.
#[test]
fn cli_a_builtin_system_keeps_the_limits_given() {
    let degrees = |d: &'static str| {
        [
            "--momenta-degree",
            d,
            "--positions-degree",
            d,
            "--trig-degree",
            d,
        ]
    };
    let search = ["search", "--system", "harmonic"];
    assert_bad_usage(
        &[&search[..], &degrees("2"), &["--max-terms", "10"]].concat(),
        "the space has 300 unknowns, more than the term limit 10",
    );
    assert_bad_usage(
        &[&search[..], &degrees("14")].concat(),
        "the space has 2366400 unknowns, more than the term limit 2000000",
    );
    // A built-in system that does not fit is a limit, with the least that builds it and the
    // flag that raises it; no line and column of a text nobody typed (line 1, column 1:).
    assert_bad_usage(
        &[&search[..], &["--max-terms", "4"]].concat(),
        "superint: error: --system harmonic: the system does not fit the limits given: building \
         it needs a term limit of at least 5 (the limit is 4)\nhint: if the machine has the \
         memory, raise the limit with --max-terms N\n",
    );
    let o = superint(&[&search[..], &["--max-terms", "4"]].concat());
    assert!(!stderr(&o).contains("line 1"), "{}", stderr(&o));
    assert_bad_usage(
        &[
            "closure",
            "--system",
            "gravity",
            "--max-degree",
            "1",
            "L",
            "G1",
        ],
        "--system gravity: the system does not fit the limits given: building it needs a \
         degree limit of at least 3 (the limit is 1)\n",
    );
    // Within the limits, the search runs as before.
    let out = run(
        &[&search[..], &degrees("2"), &["--max-terms", "300"]].concat(),
        0,
    );
    assert!(out.contains("300 unknowns"), "{out}");
}

#[test]
fn cli_search_complement_over_q_alone_prints_the_same() {
    let args = [
        "search",
        "systems/harmonic-rotor.toml",
        "--when",
        "p_theta = 2*I*omega",
        "--momenta-degree",
        "3",
        "--positions-degree",
        "3",
        "--trig-degree",
        "3",
        "--new-only",
        "--no-timings",
    ];
    let modular = run(&args, 0);
    assert!(modular.contains("products formed"), "{modular}");
    let exact = run(&[&args[..], &["--exact-complement"]].concat(), 0);
    assert_eq!(modular, exact);
}

/// The equations, their blocks, the proofs and the printing are shared among threads; what
/// comes out is in the order of the unknowns, whatever the number of threads.
#[test]
fn cli_search_prints_the_same_on_any_number_of_threads() {
    let args = [
        "search",
        "systems/harmonic-rotor.toml",
        "--when",
        "p_theta = I*omega",
        "--momenta-degree",
        "4",
        "--positions-degree",
        "4",
        "--trig-degree",
        "4",
        "--no-timings",
    ];
    let one = run(&[&args[..], &["--threads", "1"]].concat(), 0);
    assert!(
        one.contains("Dimension of the space of integrals: 105."),
        "{one}"
    );
    for threads in ["2", "3"] {
        let many = run(&[&args[..], &["--threads", threads]].concat(), 0);
        assert_eq!(one, many, "--threads {threads}");
    }
}

#[test]
fn cli_every_help_shows_an_example() {
    for args in [
        &["--help"][..],
        &["paper", "--help"],
        &["tower", "--help"],
        &["plot", "--help"],
    ] {
        let out = run(args, 0);
        assert!(out.contains("Examples:\n  superint"), "superint {args:?}");
    }
    assert!(run(&["--version"], 0).starts_with("superint "));
}

/// `superint bench W SIZE` runs a workload once; the last two lines are `seconds:` and
/// `terms:`, which the peer comparison reads. The term counts are exact facts: W3a(4) is
/// `f·(f + 1)` with `C(12, 4) = 495` terms, and one or two threads find the same W1.
#[test]
fn cli_bench_prints_seconds_and_terms_last() {
    let out = run(&["bench", "fateman", "4"], 0);
    let lines: Vec<&str> = out.lines().collect();
    let n = lines.len();
    assert!(lines[n - 2].starts_with("seconds: "), "{out}");
    assert_eq!(lines[n - 1], "terms: 495");
    let one = run(&["bench", "W1", "3"], 0);
    let two = run(&["bench", "W1", "3", "--threads", "2"], 0);
    let terms = |s: &str| s.lines().last().map(str::to_string);
    assert_eq!(terms(&one), terms(&two));
    assert!(one.contains("zeros: 18"), "{one}");
    run(&["bench", "W9", "3"], 2);
    // The largest W1 stops at its first pair past the limit on θ's order, where it listed its
    // 10¹⁰ pairs first (160 GB).
    let largest = superint(&["bench", "W1", "100000"]);
    assert_eq!(largest.status.code(), Some(2));
    assert_eq!(
        stderr(&largest),
        "superint: error: workload tower 100000: the trigonometric order in θ would reach \
         1001 (terms in cos 1001θ, sin 1001θ), past the limit of 1000\n"
    );
    // The formats it does not print are refused, as its help says.
    let latex = superint(&["bench", "W1", "3", "--format", "latex"]);
    assert_eq!(latex.status.code(), Some(2));
    assert!(stderr(&latex).contains("bench prints text or json, not latex"));
    assert!(run(&["bench", "--help"], 0).contains("and `bench` text or JSON"));
}

/// The harmonic rotor at `M = ω = I = 1` from `(x, y) = (1, 0)` with momentum `(0, 1/2)`:
/// `x = cos t`, `y = sin(t)/2`, and `Ω = p_θ`, so that `p_θ = 1` is the resonance 1 : 1.
/// `rest` follows its `--from`, so that a further `--from` in it is the second orbit.
fn plot_args(p_theta: &str, rest: &[&str]) -> Vec<String> {
    let first = format!("x = 1, y = 0, theta = 0, p_x = 0, p_y = 1/2, p_theta = {p_theta}");
    let fixed = [
        "plot",
        "systems/harmonic-rotor.toml",
        "--at",
        "M = 1, omega = 1, I = 1",
    ];
    (fixed.iter().copied())
        .chain(["--from", &first])
        .chain(rest.iter().copied())
        .map(String::from)
        .collect()
}

/// Runs `superint` with [`plot_args`] and expects exit code `code`; returns stdout.
fn run_plot(p_theta: &str, rest: &[&str], code: i32) -> String {
    let args = plot_args(p_theta, rest);
    run(&args.iter().map(String::as_str).collect::<Vec<_>>(), code)
}

/// Runs `superint` with [`plot_args`].
fn plot_output(p_theta: &str, rest: &[&str]) -> Output {
    let args = plot_args(p_theta, rest);
    superint(&args.iter().map(String::as_str).collect::<Vec<_>>())
}

/// A scratch file for a test's output.
fn scratch_file(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("plot");
    std::fs::create_dir_all(&dir).expect("a scratch directory");
    dir.join(name)
}

/// The header and the rows of numbers of a plot's CSV file.
fn csv_rows(path: &Path) -> (String, Vec<Vec<f64>>) {
    let data = std::fs::read_to_string(path).expect("the data was written");
    let mut lines = data.lines();
    let header = lines.next().expect("a header").to_string();
    let rows = lines
        .map(|l| l.split(',').map(|v| v.parse().expect("a number")).collect())
        .collect();
    (header, rows)
}

/// `largest_change` of each function of a plot's JSON table, by label.
fn changes(json: &str) -> Vec<(String, f64)> {
    let doc: Value = serde_json::from_str(json).expect("plot --format json is JSON");
    doc["functions"]
        .as_array()
        .expect("a list of functions")
        .iter()
        .map(|f| {
            let label = f["function"].as_str().expect("a label").to_string();
            (label, f["largest_change"].as_f64().expect("a number"))
        })
        .collect()
}

/// The paper's resonance in a picture: `K_{1,1}` stands still when `Ω = ω` (numerically, to
/// rounding) and turns when `Ω = 2ω`, while `H` and `L` stay put in both.
#[test]
fn cli_plot_shows_k_still_at_resonance_and_turning_off_it() {
    let svg = scratch_file("resonance.svg");
    let svg_arg = svg.to_str().unwrap();
    for (p_theta, k_moves) in [("I*omega", false), ("2", true)] {
        let rest = [
            "re(K_1_1)",
            "im(K_1_1)",
            "L",
            "--time",
            "20",
            "-o",
            svg_arg,
            "--format",
            "json",
        ];
        let table = changes(&run_plot(p_theta, &rest, 0));
        let labels: Vec<&str> = table.iter().map(|(l, _)| l.as_str()).collect();
        assert_eq!(labels, ["H", "Re(K_{1,1})", "Im(K_{1,1})", "L"]);
        for (label, change) in &table {
            let moves = label.contains('K') && k_moves;
            assert_eq!(
                *change > 0.5,
                moves,
                "{label} changed by {change} at p_θ = {p_theta}"
            );
            if !moves {
                assert!(
                    *change < 1e-9,
                    "{label} changed by {change} at p_θ = {p_theta}"
                );
            }
        }
        let drawn = std::fs::read_to_string(&svg).expect("the chart was written");
        assert!(drawn.starts_with("<svg") && drawn.contains("Re(K_{1,1})"));
    }
}

/// A complex curve is drawn as its real and imaginary parts, labelled as `re(…)` and `im(…)`
/// given as curves print (`Re(K_{1,1})`): they were `re(K_{1,1})`, so that one table could
/// show `re(K_{1,1})` beside `Re(K_{1,1})` for the same function.
#[test]
fn cli_plot_labels_the_parts_of_a_complex_curve_as_re_and_im_print() {
    let svg = scratch_file("parts.svg");
    let rest = [
        "K_1_1",
        "--time",
        "1",
        "-o",
        svg.to_str().unwrap(),
        "--format",
        "json",
    ];
    let table = changes(&run_plot("I*omega", &rest, 0));
    let labels: Vec<&str> = table.iter().map(|(l, _)| l.as_str()).collect();
    assert_eq!(labels, ["H", "Re(K_{1,1})", "Im(K_{1,1})"]);
}

/// `y` against `x` is the orbit, the ellipse `x² + 4y² = 1`; the CSV holds every sample.
#[test]
fn cli_plot_draws_the_orbit_and_writes_its_samples() {
    let (svg, csv) = (scratch_file("orbit.svg"), scratch_file("orbit.csv"));
    let (svg_arg, csv_arg) = (svg.to_str().unwrap(), csv.to_str().unwrap());
    let rest = [
        "y",
        "--against",
        "x",
        "--time",
        "7",
        "--samples",
        "70",
        "-o",
        svg_arg,
        "--data",
        csv_arg,
    ];
    let table = run_plot("2", &rest, 0);
    assert!(
        table.starts_with("harmonic rotor at M = 1, ω = 1, I = 1\n"),
        "{table}"
    );
    let (header, rows) = csv_rows(&csv);
    assert_eq!(header, r#"orbit,t,"x","y""#);
    assert_eq!(rows.len(), 71);
    assert_eq!((rows[0][1], rows[70][1]), (0.0, 7.0));
    for row in &rows {
        let (orbit, t, x, y) = (row[0], row[1], row[2], row[3]);
        assert_eq!(orbit, 1.0);
        assert!(
            (x - t.cos()).abs() < 1e-9 && (x * x + 4.0 * y * y - 1.0).abs() < 1e-9,
            "{row:?}"
        );
    }
}

/// `-o -` writes the chart to standard output and the table to standard error.
#[test]
fn cli_plot_to_stdout_is_the_svg_alone() {
    let o = plot_output("1", &["L", "--time", "1", "--steps", "100", "-o", "-"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).starts_with("<svg") && stdout(&o).trim_end().ends_with("</svg>"));
    assert!(stderr(&o).contains("largest change"), "{}", stderr(&o));
}

/// Every mistake in a plot's arguments is exit 2 with a message that says what to do, and
/// where in the argument when it has a place there.
#[test]
fn cli_plot_bad_arguments_exit_2_with_a_message() {
    let full = "x = 1, y = 0, theta = 0, p_x = 0, p_y = 1/2, p_theta = 1";
    let out = scratch_file("bad.svg");
    let out = out.to_str().unwrap();
    // The same file spelled otherwise, and not written yet.
    let dotted = out.replace("/bad.svg", "/./bad.svg");
    let at = "M = 1, omega = 1, I = 1";
    for (args, message) in [
        (
            vec!["L", "--at", at, "--from", "x = 1, y = 0, p_x = 0, p_y = 1"],
            "--from gives no value for θ, p_θ: every coordinate, angle and momentum needs one",
        ),
        (
            vec!["L", "--at", "M = 1, x = 1", "--from", full],
            "<command line>:1:8: --at gives the parameters their values; x is a coordinate \
             (give it with --from)",
        ),
        (
            vec!["L", "--at", at, "--from", &format!("{full}, M = 2")],
            "M is a parameter: give its value with --at",
        ),
        (
            vec!["L", "--at", "M = 1, omega = x", "--from", full],
            "<command line>:1:16: the value of a parameter is a real number, such as 3/2",
        ),
        (
            vec!["L", "--at", "M = 1, omega = 1", "--from", full],
            "H holds I, which has no value: give it with --at, such as --at 'I = 1'",
        ),
        (
            vec!["L*l", "--at", at, "--from", full],
            "<command line>:1:1: 'L*l' holds l, which has no value: give it with --at, such as \
             --at 'l = 1'",
        ),
        (
            vec!["L + Q3", "--at", at, "--from", full],
            "<command line>:1:5: unknown name 'Q3'",
        ),
        (
            vec!["L", "--against", "K_1_1", "--at", at, "--from", full],
            "--against takes a real function; K_{1,1} is not: take re(…) or im(…)",
        ),
        (
            vec![
                "L",
                "--at",
                at,
                "--from",
                "x = 1, y = 0, theta = i, p_x = 0, p_y = 0, p_theta = 0",
            ],
            "the starting value of θ must be a real number once the parameters have their values",
        ),
        (
            vec![
                "L",
                "--at",
                at,
                "--from",
                "x = 10^400, y = 0, theta = 0, p_x = 0, p_y = 0, p_theta = 0",
            ],
            "the starting value of x: the number 100000000000000000000000… (401 characters) is \
             too large for floating point",
        ),
        (
            vec!["L", "--at", at, "--from", full, "--time", "0"],
            "invalid value '0' for '--time <T>': not a positive number of time units",
        ),
        (
            vec!["L", "--at", at, "--from", full, "--time", "1/0"],
            "invalid value '1/0' for '--time <T>': not a positive number of time units",
        ),
        (
            vec!["L", "--at", "M = 1, theta = 1", "--from", full],
            "<command line>:1:8: --at gives the parameters their values; θ is an angle (give it \
             with --from)",
        ),
        (
            vec!["L", "--at", at, "--from", &format!("{full}, H = 2")],
            "the left side of a value of --from is one declared variable (a coordinate, an angle \
             or a momentum), found 'H'",
        ),
        // A parameter set to 0 that H, a curve or a starting value divides by is named, as
        // --when's condition names it; it was 'H at the values of --at: division by zero'. H's
        // divisor and a curve's (which had no place) are underlined in --at, a starting
        // value's in --from, each with what to do.
        (
            vec!["L", "--at", "M = 0, omega = 1, I = 1", "--from", full],
            "<command line>:1:5: --at sets M = 0, but H divides by M\n 1 | M = 0, omega = 1, \
             I = 1\n   |     ^\nhint: give M a value other than 0 with --at",
        ),
        (
            vec![
                "L",
                "--at",
                "M = 1, omega = 0, I = 1",
                "--from",
                &full.replace("x = 1", "x = 1/omega"),
            ],
            "<command line>:1:5: --at sets ω = 0, but the starting value of x divides by ω\n \
             1 | x = 1/omega, y = 0,",
        ),
        (
            vec!["L/omega", "--at", "M = 1, omega = 0, I = 1", "--from", full],
            "<command line>:1:16: --at sets ω = 0, but 'L/omega' divides by ω\n 1 | M = 1, \
             omega = 0, I = 1\n   |                ^\nhint: give ω a value other than 0 with --at",
        ),
        (
            vec![
                "x^309/10",
                "--at",
                at,
                "--from",
                &full.replace("x = 1", "x = 10"),
            ],
            "x³⁰⁹/10 is not a finite floating-point number at t = 0 of the orbit",
        ),
        (
            vec!["L", "--section", "x", "--at", at, "--from", full],
            "the following required arguments were not provided:\n  --against <F>",
        ),
        (
            vec!["L", "--at", at, "--from", full, "--format", "latex"],
            "plot prints its table as text, markdown or json, not latex",
        ),
        // Outputs that would overwrite one another, or the system file: `--data -` wrote a
        // file named `-`, and the data replaced the chart of the same name.
        (
            vec!["L", "--at", at, "--from", full, "--data", "-"],
            "--data writes a file: give its name (only -o takes - for standard output)",
        ),
        (
            vec!["L", "--at", at, "--from", full, "--data", out],
            "-o and --data name the same file",
        ),
        (
            vec!["L", "--at", at, "--from", full, "--data", &dotted],
            "-o and --data name the same file",
        ),
        (
            vec![
                "L",
                "--at",
                at,
                "--from",
                full,
                "--data",
                "systems/harmonic-rotor.toml",
            ],
            "systems/harmonic-rotor.toml is the system file: an output would overwrite it",
        ),
    ] {
        let mut all = vec!["plot", "systems/harmonic-rotor.toml"];
        all.extend(&args);
        if !all.contains(&"--time") {
            all.extend(["--time", "1"]);
        }
        all.extend(["-o", out]);
        assert_bad_usage(&all, message);
    }
    // A chart named as another format is refused: SVG was written into `orbit.png` silently.
    let png = scratch_file("orbit.PNG");
    let _ = std::fs::remove_file(&png);
    let png = png.to_str().unwrap();
    assert_bad_usage(
        &[
            "plot",
            "systems/harmonic-rotor.toml",
            "L",
            "--at",
            at,
            "--from",
            full,
            "--time",
            "1",
            "-o",
            png,
        ],
        &format!(
            "-o {png}: plot writes SVG, which a .png file would hold under another format's \
             name; name it {} (rsvg-convert or inkscape turn an SVG into PNG)",
            png.replace("orbit.PNG", "orbit.svg")
        ),
    );
    assert!(!std::path::Path::new(png).exists());
    // A start where H or a curve divides by zero is said as such; the flow ran off at once and
    // floating point said it 'left the finite numbers near t = 0.001'.
    let on_axis = "x = 0, y = 1, theta = 0, p_x = 0, p_y = 1/2, p_theta = 1";
    assert_bad_usage(
        &[
            "plot",
            "systems/harmonic-rotor.toml",
            "L/x",
            "--at",
            at,
            "--from",
            on_axis,
            "--time",
            "1",
            "-o",
            out,
        ],
        "<command line>:1:5: L/x is not defined at the starting point: it divides by x, which \
         starts at 0 (--from)\n 1 | x = 0, y = 1, theta = 0, p_x = 0, p_y = 1/2, p_theta = 1\n   \
         |     ^\nhint: start x at a value other than 0",
    );
    assert_bad_usage(
        &[
            "plot",
            "systems/smorodinsky-winternitz-i.toml",
            "H",
            "--at",
            "M = 1, alpha = 1, beta = 1, gamma = 1",
            "--from",
            "x = 1, y = 0, p_x = 0, p_y = 1",
            "--time",
            "1",
            "-o",
            out,
        ],
        "<command line>:1:12: H is not defined at the starting point: it divides by y, which \
         starts at 0 (--from)\n 1 | x = 1, y = 0, p_x = 0, p_y = 1\n   |            ^\nhint: \
         start y at a value other than 0",
    );
}

/// A denominator or a radicand that the parameters' values alone make 0 or negative is the
/// fault of --at, not of the starting point: `--at 'a = 2, b = 2'` with a denominator `a − b`
/// was said to be undefined 'at the starting point (--from)'.
#[test]
fn cli_plot_blames_at_for_what_the_parameters_decide() {
    let out = scratch_file("blame.svg");
    let out = out.to_str().unwrap();
    let system = |name: &str, text: &str| {
        let path = scratch_file(name);
        std::fs::write(&path, text).expect("write the file");
        path
    };
    let header = "hamiltonian = \"p_x^2/2 + x^2*D\"\n[phase_space]\ncoordinates = [\"x\"]\n\
                  parameters = [\"a\", \"b\"]\n";
    let denominator = system(
        "blame-denominator.toml",
        &format!("{header}denominators = [\"a - b\"]\n").replace("x^2*D", "x^2/(a - b)"),
    );
    let radical = system(
        "blame-radical.toml",
        &format!("{header}radicals = {{ r = \"a - b - 1\" }}\n").replace("x^2*D", "x^2*r"),
    );
    let on_x = system(
        "blame-from.toml",
        &format!("{header}denominators = [\"x - a\"]\n").replace("x^2*D", "1/(x - a)"),
    );
    // Each is shown at the value that makes it so, in --at (b's, which completes a − b) or in
    // --from (x's), with what to do; they had no place.
    for (file, message) in [
        (
            &denominator,
            "<command line>:1:12: H is not defined at the values of --at: it divides by (a − b), \
             which is 0 there (--at)\n 1 | a = 2, b = 2\n   |            ^\nhint: give --at \
             values at which (a − b) is not 0",
        ),
        (
            &radical,
            "<command line>:1:12: H is not defined at the values of --at: r = √(a − b − 1) is \
             the root of -1 there (--at)\n 1 | a = 2, b = 2\n   |            ^\nhint: give --at \
             values at which a − b − 1 is not negative",
        ),
        (
            &on_x,
            "<command line>:1:5: H is not defined at the starting point: it divides by (x − a), \
             which is 0 there (--from)\n 1 | x = 2, p_x = 0\n   |     ^\nhint: give --from \
             values at which (x − a) is not 0",
        ),
    ] {
        let file = file.to_str().unwrap();
        let args = [
            "plot",
            file,
            "x",
            "--at",
            "a = 2, b = 2",
            "--from",
            "x = 2, p_x = 0",
        ];
        assert_bad_usage(&[&args[..], &["--time", "1", "-o", out]].concat(), message);
    }
}

/// A Poincaré section of the oscillator's ellipse at `x = 0` (upward): every crossing is at
/// `y = −1/2`, `p_y = 0`, once a period `2π`; one that is never crossed is an error.
#[test]
fn cli_plot_section_keeps_the_upward_crossings() {
    let (svg, csv) = (scratch_file("section.svg"), scratch_file("section.csv"));
    let (svg_arg, csv_arg) = (svg.to_str().unwrap(), csv.to_str().unwrap());
    let section = [
        "p_y",
        "--against",
        "y",
        "--section",
        "x",
        "--time",
        "20",
        "-o",
        svg_arg,
    ];
    let rest = [&section[..], &["--data", csv_arg, "--format", "json"]].concat();
    let doc: Value = serde_json::from_str(&run_plot("1", &rest, 0)).expect("JSON");
    assert_eq!(doc["section"], "x");
    assert_eq!(doc["points"], serde_json::json!([3]));
    let (_, rows) = csv_rows(&csv);
    let period = 2.0 * std::f64::consts::PI;
    for (k, row) in rows.iter().enumerate() {
        let (t, y, p_y) = (row[1], row[2], row[3]);
        assert!((t - (0.75 + k as f64) * period).abs() < 1e-9, "{row:?}");
        assert!((y + 0.5).abs() < 1e-9 && p_y.abs() < 1e-9, "{row:?}");
    }
    assert_eq!(rows.len(), 3);
    let drawn = std::fs::read_to_string(&svg).expect("the chart was written");
    assert_eq!(
        drawn.matches("<circle").count(),
        3 + 1,
        "three dots and the legend's"
    );

    let never = section.map(|a| if a == "x" { "x - 2" } else { a });
    let o = plot_output("1", &never);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("x − 2 does not cross zero upward from t = 0 to 20"),
        "{}",
        stderr(&o)
    );
}

/// Several starting points are several orbits in one chart: a section of two ellipses of the
/// oscillator, `x = cos t`, `y = b sin t` for `b = 1/2` and `b = 1/4`, crossed at `y = −b`.
#[test]
fn cli_plot_draws_an_orbit_from_each_starting_point() {
    let svg = scratch_file("orbits.svg");
    let rest = [
        "p_y",
        "--against",
        "y",
        "--section",
        "x",
        "--time",
        "20",
        "--from",
        "x = 1, y = 0, theta = 0, p_x = 0, p_y = 1/4, p_theta = 1",
        "-o",
        svg.to_str().unwrap(),
        "--format",
        "json",
    ];
    let doc: Value = serde_json::from_str(&run_plot("1", &rest, 0)).expect("JSON");
    assert_eq!(doc["points"], serde_json::json!([3, 3]));
    let rows: Vec<(String, i64, f64)> = doc["functions"]
        .as_array()
        .expect("rows")
        .iter()
        .map(|f| {
            let label = f["function"].as_str().expect("a label").to_string();
            (
                label,
                f["orbit"].as_i64().expect("an orbit"),
                f["first"].as_f64().expect("a value"),
            )
        })
        .collect();
    let labels: Vec<(&str, i64)> = rows.iter().map(|(l, k, _)| (l.as_str(), *k)).collect();
    assert_eq!(
        labels,
        [("H [1]", 1), ("p_y [1]", 1), ("H [2]", 2), ("p_y [2]", 2)]
    );
    // H = (p_y² + x²)/2 + p_θ²/2 at the start: 1/8 + 1/2 + 1/2 and 1/32 + 1/2 + 1/2.
    assert!((rows[0].2 - 1.125).abs() < 1e-12 && (rows[2].2 - 1.03125).abs() < 1e-12);
    let drawn = std::fs::read_to_string(&svg).expect("the chart was written");
    assert_eq!(
        drawn.matches("<circle").count(),
        2 * 3 + 2,
        "six dots and two in the legend"
    );
}

/// `--method gauss` steps symplectically: over a long Hénon–Heiles run at steps of 1/4, `H`
/// stays within 1e-5 where Runge–Kutta's drifts by far more.
#[test]
fn cli_plot_gauss_keeps_the_energy_over_long_times() {
    let svg = scratch_file("gauss.svg");
    let change_of_h = |method: &str| {
        let args = [
            "plot",
            "systems/henon-heiles.toml",
            "p_y",
            "--against",
            "y",
            "--section",
            "x",
            "--at",
            "A = 1, B = 1, C = -1/3",
            "--from",
            "x = 0, y = 1/10, p_x = 2/5, p_y = 0",
            "--time",
            "5000",
            "--steps",
            "20000",
            "--method",
            method,
            "-o",
            svg.to_str().unwrap(),
            "--format",
            "json",
        ];
        let doc: Value = serde_json::from_str(&run(&args, 0)).expect("JSON");
        assert!(doc["method"].as_str().unwrap().contains(match method {
            "gauss" => "Gauss–Legendre",
            _ => "Runge–Kutta",
        }));
        changes(&doc.to_string())[0].1
    };
    let (gauss, rk) = (change_of_h("gauss"), change_of_h("rk4"));
    assert!(
        gauss < 1e-5 && rk > 100.0 * gauss,
        "Gauss {gauss}, Runge–Kutta {rk}"
    );
}

/// `plot` warns when H moves by more than a thousandth of its size along an orbit (the
/// integration's error, since H is conserved), and says nothing when the steps are fine
/// enough. The rotor's orbit at 200 steps of 1/2 loses far more than that with RK4.
#[test]
fn cli_plot_warns_when_the_energy_drifts() {
    let svg = scratch_file("drift.svg");
    let svg = svg.to_str().unwrap();
    let stderr = |steps: &str, method: &str| {
        let rest = [
            "--time", "100", "--steps", steps, "--method", method, "-o", svg,
        ];
        let o = plot_output("1", &[&["L"][..], &rest].concat());
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        String::from_utf8(o.stderr).expect("UTF-8")
    };
    let coarse = stderr("200", "rk4");
    assert!(
        coarse.starts_with("superint: warning: H moved by ")
            && coarse.contains("% of its size along the orbit: the integration is not accurate at 200 steps; raise --steps or use --method gauss"),
        "{coarse}"
    );
    assert_eq!(stderr("10000", "rk4"), "");
}

/// `--against` an angle draws a phase portrait, the angle reduced to `[−π, π)`: the pendulum
/// `p_t²/2 − g cos t` at `g = 1` librates between `±π/3` from `p_t = 1` (`H = −1/2`, so
/// `cos t ≥ 1/2`), and from `p_t = 3` (`H = 7/2`, so `p_t ≥ √5`) goes round, leaving at `π` and
/// coming back at `−π`, its line broken there (no line across the chart). With `--unreduced`
/// the angle is as the integration carries it, past `2π` within `t = 10`. An angle axis was
/// refused; then it was drawn unreduced only.
#[test]
fn cli_plot_against_an_angle_draws_a_phase_portrait() {
    use std::f64::consts::{FRAC_PI_3, PI};
    let file = crate::scratch_text("plot", "pendulum.toml", crate::PENDULUM);
    let (svg, data) = (scratch_file("pendulum.svg"), scratch_file("pendulum.csv"));
    let plot = |extra: &[&str]| {
        let args = [
            "plot",
            file.to_str().unwrap(),
            "p_t",
            "--against",
            "t",
            "--at",
            "g = 1",
            "--from",
            "t = 0, p_t = 1",
            "--from",
            "t = 0, p_t = 3",
            "--time",
            "10",
            "-o",
            svg.to_str().unwrap(),
            "--data",
            data.to_str().unwrap(),
        ];
        run(&[&args[..], extra].concat(), 0);
        let drawn = std::fs::read_to_string(&svg).expect("the chart was written");
        (drawn, csv_rows(&data))
    };
    let (drawn, (header, rows)) = plot(&[]);
    assert!(drawn.contains("t (mod 2π)"), "the axis says what it shows");
    assert_eq!(header, "orbit,t,\"t (mod 2π)\",\"p_t\"");
    let angles = |orbit: f64| {
        rows.iter()
            .filter(move |r| r[0] == orbit)
            .map(|r| r[2])
            .collect::<Vec<_>>()
    };
    let turning = FRAC_PI_3 + 1e-3;
    assert!(
        angles(1.0).iter().all(|a| a.abs() <= turning),
        "the first orbit librates"
    );
    assert!(angles(1.0).iter().any(|&a| a > 1.0) && angles(1.0).iter().any(|&a| a < -1.0));
    let going_round = angles(2.0);
    assert!(going_round.iter().all(|a| (-PI..PI).contains(a)));
    let wraps = going_round.windows(2).filter(|w| w[1] < w[0] - PI).count();
    assert!(wraps >= 3, "the second orbit goes round, {wraps} times");
    // The second curve's colour (Tableau's red); the legend's mark is one line more.
    let lines = |svg: &str| {
        svg.matches(r##"stroke="#D62728" stroke-width="2""##)
            .count()
    };
    let reduced_lines = lines(&drawn);

    let (drawn, (header, rows)) = plot(&["--unreduced"]);
    assert!(drawn.contains("t (not reduced mod 2π)"));
    assert_eq!(header, "orbit,t,\"t (not reduced mod 2π)\",\"p_t\"");
    // Reduced, the rotation's line is broken once a turn; unreduced, it is one line.
    assert_eq!(lines(&drawn), 1 + 1, "the rotation in one line");
    assert_eq!(reduced_lines, 1 + 1 + wraps);
    let last = rows
        .iter()
        .rev()
        .find(|r| r[0] == 2.0)
        .expect("the second orbit")[2];
    assert!(last > 2.0 * PI, "the second orbit goes round: {last}");
}

/// `bench --format json` prints one object with the text's fields; the formats and options it
/// cannot honour are refused (they were accepted and ignored).
#[test]
fn cli_bench_prints_json_and_refuses_what_it_cannot_honour() {
    let out = run(&["bench", "W4", "3", "--format", "json"], 0);
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    assert_eq!(v["schema"], "superint-bench/1");
    assert_eq!((&v["zeros"], &v["terms"]), (&3.into(), &24.into()), "{v}");
    assert!(v["seconds"].is_number());
    // One thread, or two left unpinned, run unpinned; two are pinned where the machine has
    // two processors for them (the pool's own test checks the pins).
    assert_eq!(v["pinned"], false);
    let json =
        |args: &[&str]| -> serde_json::Value { serde_json::from_str(&run(args, 0)).expect("JSON") };
    let unpinned = json(&[
        "bench",
        "W4",
        "3",
        "--threads",
        "2",
        "--no-pin",
        "--format",
        "json",
    ]);
    assert_eq!(unpinned["pinned"], false);
    let two = json(&["bench", "W4", "3", "--threads", "2", "--format", "json"]);
    let processors = std::thread::available_parallelism().map_or(1, usize::from);
    if processors >= 2 {
        assert_eq!(two["pinned"], true, "{two}");
    }
    for args in [
        &["bench", "W4", "3", "--format", "latex"][..],
        &["bench", "W4", "3", "--no-timings"],
    ] {
        let o = superint(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
    }
}

/// The README's worked example is an excerpt of what the default job prints (it had been
/// written by hand, and differed).
#[test]
fn cli_readme_excerpt_is_the_default_jobs_output() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md"))
        .expect("the README");
    let start = readme.find("```text\n").expect("an excerpt") + "```text\n".len();
    let excerpt = &readme[start..start + readme[start..].find("```").expect("its end")];
    let out = run(&["--no-timings"], 0);
    assert!(out.contains(excerpt), "{excerpt}\nnot in\n{out}");
}

/// `--time` takes a fraction as `--at` and `--from` take numbers, and a decimal: the same.
#[test]
fn cli_plot_time_takes_a_fraction() {
    let svg = scratch_file("half.svg");
    let json = |time: &str| {
        let args = [
            "plot",
            "systems/henon-heiles.toml",
            "p_y",
            "--at",
            "A = 1, B = 1, C = -1/3",
            "--from",
            "x = 0, y = 1/10, p_x = 2/5, p_y = 0",
            "--time",
            time,
            "--steps",
            "50",
            "-o",
            svg.to_str().unwrap(),
            "--format",
            "json",
        ];
        serde_json::from_str::<Value>(&run(&args, 0)).expect("JSON")
    };
    let half = json("1/2");
    assert_eq!(half, json("0.5"));
    assert_eq!(half["time"], 0.5);
    // What was asked, as given, and whether the integration kept H.
    assert_eq!(half["at"], "A = 1, B = 1, C = -1/3");
    assert_eq!(half["from"][0], "x = 0, y = 1/10, p_x = 2/5, p_y = 0");
    assert_eq!(half["method_id"], "runge-kutta");
    assert_eq!(half["accurate"], true);
    assert!(half["energy_drift"][0].as_f64().is_some_and(|d| d < 1e-3));
}

/// `plot` reads a decimal value as the fraction it writes, so that the same orbit follows
/// from `y = 0.1` and `y = 1/10`; a decimal inside an expression is refused with a hint, and
/// `H` asked for as a curve is listed once.
#[test]
fn cli_plot_values_may_be_decimals() {
    let svg = scratch_file("decimals.svg");
    let json = |at: &str, from: &str, curves: &[&str]| {
        let mut args = vec!["plot", "systems/henon-heiles.toml"];
        args.extend(curves);
        args.extend([
            "--at",
            at,
            "--from",
            from,
            "--time",
            "1",
            "--steps",
            "50",
            "-o",
            svg.to_str().unwrap(),
            "--format",
            "json",
        ]);
        serde_json::from_str::<Value>(&run(&args, 0)).expect("JSON")
    };
    let fractions = json(
        "A = 1, B = 1, C = -1/4",
        "x = 0, y = 1/10, p_x = 2/5, p_y = -1/1000",
        &["p_y"],
    );
    let decimals = json(
        "A = 1.0, B = 1, C = −0.25",
        "x = 0, y = .1, p_x = 4e-1, p_y = -1E-3",
        &["p_y"],
    );
    assert_eq!(fractions["functions"], decimals["functions"]);
    assert_eq!(decimals["at"], "A = 1.0, B = 1, C = −0.25");
    let with_h = json(
        "A = 1, B = 1, C = -1/4",
        "x = 0, y = 1/10, p_x = 2/5, p_y = 0",
        &["H", "p_y"],
    );
    let labels: Vec<&str> = with_h["functions"]
        .as_array()
        .expect("functions")
        .iter()
        .map(|f| f["function"].as_str().expect("a label"))
        .collect();
    assert_eq!(labels, ["H", "p_y"]);
    let out = superint(&[
        "plot",
        "systems/henon-heiles.toml",
        "p_y",
        "--at",
        "A = 1, B = 1, C = 2*0.5",
        "--from",
        "x = 0, y = 1/10, p_x = 2/5, p_y = 0",
        "--time",
        "1",
        "-o",
        svg.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("<command line>:1:21: decimal numbers are not exact")
            && stderr.contains("hint: a value alone may be a decimal number (x = 0.5)"),
        "{stderr}"
    );
}

/// A bracket table wider than a line is printed as the list of its brackets above the
/// diagonal that are not zero, each sum wrapped between its terms: the full table of the
/// rotor under gravity was over a hundred characters wide, and a closure of cubic integrals
/// made rows of a thousand. A table that fits stays a table.
#[test]
fn cli_text_table_too_wide_is_a_list() {
    let out = run(&["table", "systems/gravity-rotor.toml", "--no-timings"], 0);
    assert!(
        out.contains("too wide for a table: the brackets that are not zero"),
        "{out}"
    );
    assert!(out.lines().all(|l| l.chars().count() <= 96), "{out}");
    assert!(out.contains("\n    {L, G1} = −G2\n"), "{out}");
    assert!(out.contains("\n    {G1, G2} = −ω² L\n"), "{out}");
    // Antisymmetry gives the rest: {G1, L} is not listed, nor a zero {F1, F2}.
    assert!(
        !out.contains("{G1, L}") && !out.contains("{F1, F2}"),
        "{out}"
    );
    let narrow = run(
        &[
            "table",
            "systems/gravity-rotor.toml",
            "Lp",
            "G1p",
            "G2p",
            "--no-timings",
        ],
        0,
    );
    assert!(narrow.contains("{·,·} │"), "{narrow}");
    assert!(!narrow.contains("too wide"), "{narrow}");
}

/// Control characters that a system file's escapes (`\u001b`) put in its name, description or
/// a claim's id are refused at their place (on a terminal they would set its title or clear
/// it, and they made an SVG chart no XML); those a command line puts in an expression are
/// printed as `�` in the error's excerpt.
#[test]
fn cli_prints_no_control_characters() {
    let clean = |text: &str| !text.contains(|c: char| c.is_control() && c != '\n' && c != '\t');
    let header = "name = \"t\"\n";
    let body = "hamiltonian = \"p_x^2/2\"\n\
                [phase_space]\ncoordinates = [\"x\"]\n\
                [[function]]\nname = \"L\"\nvalue = \"x*p_x\"\n\
                [[claim]]\nid = \"c\"\nclaim = \"{L, H} = p_x^2\"\n";
    for (case, from, to, refusal) in [
        (
            "name",
            "name = \"t\"",
            "name = \"t\\u001b]0;title\\u0007\"",
            "control.toml:1:10: the system's name is shown in reports as written: U+001B",
        ),
        (
            "description",
            "name = \"t\"",
            "name = \"t\"\ndescription = \"a\\bb\\rc\"",
            "control.toml:2:17: the system's description is shown in reports as written: U+0008",
        ),
        (
            "id",
            "id = \"c\"",
            "id = \"c\\u0000\"",
            "control.toml:9:8: a claim's id is shown in reports as written: U+0000",
        ),
    ] {
        let text = format!("{header}{body}").replacen(from, to, 1);
        let file = crate::scratch_text("cli", "control.toml", &text);
        let file = file.to_str().expect("a UTF-8 path");
        for format in ["text", "json"] {
            let out = superint(&["check", file, "--format", format]);
            assert_eq!(out.status.code(), Some(2), "{case}: {}", stdout(&out));
            let err = stderr(&out);
            assert!(clean(&err) && err.contains(refusal), "{case}: {err:?}");
        }
    }
    let file = crate::scratch_text("cli", "control.toml", &format!("{header}{body}"));
    let file = file.to_str().expect("a UTF-8 path");
    let out = superint(&["expand", file, "\u{1b}[31mx"]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(clean(&err) && err.contains("\u{fffd}[31mx"), "{err:?}");
    // A right-to-left override would turn the rest of an error's line around on a terminal.
    let out = superint(&["expand", file, "x\u{202e} + y"]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(
        !err.contains('\u{202e}') && err.contains("x\u{fffd} + y"),
        "{err:?}"
    );
}

/// A misspelt built-in system is named as such, with the built-in ones, where "cannot read
/// the file" suggested a missing file.
#[test]
fn cli_tower_names_a_misspelt_builtin_system() {
    assert_bad_usage(
        &["tower", "--system", "harmonics"],
        "no built-in system 'harmonics' (harmonic, gravity), and no file of that name",
    );
}

/// A starting angle may be a multiple of π alone (`theta = 3*pi/4`), which floating point
/// then rounds; in an expression `pi` is refused with a hint.
#[test]
fn cli_plot_starting_angles_may_be_multiples_of_pi() {
    let svg = scratch_file("pi.svg");
    let args = |theta: &str| {
        vec![
            "plot".to_string(),
            "systems/harmonic-rotor.toml".into(),
            "cos(theta)".into(),
            "sin(theta)".into(),
            "--at".into(),
            "M = 1, omega = 1, I = 1".into(),
            "--from".into(),
            format!("x = 1, y = 0, theta = {theta}, p_x = 0, p_y = 1/2, p_theta = 0"),
            "--time".into(),
            "1".into(),
            "--steps".into(),
            "10".into(),
            "-o".into(),
            svg.to_str().unwrap().into(),
            "--format".into(),
            "json".into(),
        ]
    };
    let run_with = |theta: &str| {
        let a = args(theta);
        let doc: Value =
            serde_json::from_str(&run(&a.iter().map(String::as_str).collect::<Vec<_>>(), 0))
                .expect("JSON");
        let first = |k: usize| doc["functions"][k]["first"].as_f64().expect("a number");
        (first(1), first(2))
    };
    let half = std::f64::consts::FRAC_1_SQRT_2;
    for theta in ["3*pi/4", "3π/4", "0.75*pi", "pi*3/4", "pi/4*3", "3pi/4"] {
        let (c, s) = run_with(theta);
        assert!(
            (c + half).abs() < 1e-12 && (s - half).abs() < 1e-12,
            "{theta}: {c}, {s}"
        );
    }
    let (c, s) = run_with("-pi/2");
    assert!(
        c.abs() < 1e-12 && (s + 1.0).abs() < 1e-12,
        "-pi/2: {c}, {s}"
    );
    let a = args("2*pi + 1");
    let out = superint(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(
        err.contains("unknown name 'pi'")
            && err.contains("hint: a value may be a multiple of π alone (theta = 3*pi/4"),
        "{err}"
    );
}

/// A count of one takes its noun in the singular wherever a count is printed in words: the
/// products a search forms, its unknowns and blocks, the rest of its basis, the brackets a
/// tower expands, the steps of a plot, the files `check` could not read.
#[test]
fn cli_counts_of_one_are_singular() {
    let file = scratch_file("oscillator.toml");
    std::fs::write(
        &file,
        "hamiltonian = \"p_x^2/2 + x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n",
    )
    .expect("write the system");
    let file = file.to_str().expect("a UTF-8 path");
    let search = |degree: &str| {
        let args = ["search", file, "--new-only", "--format", "markdown"];
        let degrees = ["--momenta-degree", degree, "--positions-degree", degree];
        run(&[&args[..], &degrees[..]].concat(), 0)
    };
    let four = search("4");
    assert!(four.contains("(1 product formed)"), "{four}");
    let zero = search("0");
    for said in [
        "1 unknown, 0 linear equations over `Q`, in 1 independent block (the largest has 1 \
         unknown).",
        "(0 products formed); the generated ones span the whole space (1 dimension).",
        "`{I, H} = 0 for the 1 basis element`",
    ] {
        assert!(zero.contains(said), "{said}\n{zero}");
    }
    let tower = run(&["tower", "--max", "1", "--no-timings"], 0);
    for said in [
        "1 bracket expanded for the harmonic rotor",
        "tower: 1 bracket {K_{m,n}, H}",
    ] {
        assert!(tower.contains(said), "{said}\n{tower}");
    }
    let svg = scratch_file("one-step.svg");
    let plot = run_plot(
        "1",
        &[
            "H",
            "--time",
            "1",
            "--steps",
            "1",
            "--samples",
            "1",
            "-o",
            svg.to_str().unwrap(),
        ],
        0,
    );
    assert!(plot.contains(" in 1 step of "), "{plot}");
    let missing = superint(&["check", "systems/kepler.toml", "no-such-file.toml"]);
    assert_eq!(missing.status.code(), Some(2));
    let err = stderr(&missing);
    assert!(
        err.contains("1 of 2 files not checked (the error above)"),
        "{err}"
    );
}

/// A table's caption names a row and a column by letters the system does not use: the
/// Hénon–Heiles family's parameters are `A`, `B`, `C`, so its tables (and a closure's) say
/// `{F, G}`, in every format, and so do its generators' names where they are `F`, `G`.
#[test]
fn cli_table_placeholders_are_names_the_system_does_not_use() {
    let henon = "systems/henon-heiles.toml";
    let text = run(&["table", henon, "K", "S", "--no-timings"], 0);
    assert!(
        text.contains(
            "{F, G} for the Hénon–Heiles family, too wide for a table: the brackets \
                       that are not zero, F\nbefore G:"
        ),
        "{text}"
    );
    assert!(!text.contains("{A, B}"), "{text}");
    let latex = run(&["table", henon, "--no-timings", "--format", "latex"], 0);
    assert!(
        latex.contains(
            "$\\{F, G\\}$ for the H\\'{e}non--Heiles family, the brackets that are not \
             zero, $F$ before $G$:"
        ),
        "{latex}"
    );
    let markdown = run(
        &[
            "table",
            henon,
            "K",
            "S",
            "--no-timings",
            "--format",
            "markdown",
        ],
        0,
    );
    assert!(
        markdown.contains("*`{F, G}` for the Hénon–Heiles family (row `F`, column `G`)*"),
        "{markdown}"
    );
    let json = run(&["table", henon, "K", "S", "--format", "json"], 0);
    let json: Value = serde_json::from_str(&json).expect("JSON");
    assert_eq!(
        json["tables"][0]["caption"],
        "{F, G} for the Hénon–Heiles family (row F, column G)"
    );
    let closure = run(
        &[
            "closure",
            henon,
            "H",
            "K",
            "--when",
            "C = 2",
            "--no-timings",
        ],
        0,
    );
    assert!(
        closure.contains("{F, G} for the Hénon–Heiles family at C = 2 (row F, column G)\n"),
        "{closure}"
    );
    // Where the generators take F and G too, the next pair.
    let args = [
        "closure", henon, "F", "G", "--define", "F=p_x", "--define", "G=p_y",
    ];
    let closure = run(&[&args[..], &["--no-timings"]].concat(), 0);
    assert!(
        closure.contains("{U, V} for the Hénon–Heiles family (row U, column V)\n"),
        "{closure}"
    );
    // Where nothing is taken, the paper's letters.
    let rotor = run(
        &[
            "table",
            "systems/harmonic-rotor.toml",
            "L",
            "G1",
            "G2",
            "--no-timings",
        ],
        0,
    );
    assert!(
        rotor.contains("{A, B} for the harmonic rotor (row A, column B)\n"),
        "{rotor}"
    );
}

/// A refuted claim's residual of more than a hundred monomials prints the terms of its first
/// hundred and its size, in every format, and whole with `--full-expressions` (also spelled
/// `--full-residuals`, the option's first name): one of two
/// million terms printed 1.5 GB of text in two minutes and 9.5 GB of memory (found by the
/// fuzzer, seed 1202).
#[test]
fn cli_long_residual_shows_its_leading_terms() {
    let file = crate::scratch_text(
        "cli",
        "long-residual.toml",
        "name = \"long residuals\"\n\
         hamiltonian = \"(p_x^2 + p_y^2)/2 + p_theta^2/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nangles = [\"theta\"]\n\
         [[claim]]\nid = \"flat\"\nclaim = \"(1 + x + y + p_x + p_y)^10 = 0\"\n\
         [[claim]]\nid = \"angles\"\nclaim = \"(1 + x + y)^14*(cos(theta) + sin(2*theta)) = 0\"\n",
    );
    let file = file.to_str().expect("a UTF-8 path");
    let out = superint_exits(&["check", file, "--no-timings"], 1);
    let text = stdout(&out);
    // (1 + x + y + p_x + p_y)^10 has C(14, 4) = 1001 terms; (1 + x + y)^14 has C(16, 2) = 120
    // monomials, each with cos θ and sin 2θ = 2 sin θ cos θ.
    assert!(
        crate::normalize(&text)
            .contains("(shown: its first 100 of 1001 terms; --full-expressions shows all)"),
        "{text}"
    );
    assert!(
        crate::normalize(&text).contains(
            "(shown: the terms of its first 100 of 120 monomials outside the angles; \
             --full-expressions shows all)"
        ),
        "{text}"
    );
    assert_eq!(text.matches(" + …").count(), 2, "{text}");
    // In LaTeX, what is left out is said in rows of prose that fit the page (one row of it
    // was set 259 pt wider).
    let latex = stdout(&superint_exits(
        &["check", file, "--no-timings", "--format", "latex"],
        1,
    ));
    assert_eq!(latex.matches(r"&\quad + \dots").count(), 2, "{latex}");
    assert!(latex.contains("its first 100 of 1001 terms"), "{latex}");
    compile_within(&latex, 1.0);
    let json = |extra: &[&str]| -> Value {
        let args = [&["check", file, "--format", "json"], extra].concat();
        serde_json::from_str(&stdout(&superint_exits(&args, 1))).expect("JSON")
    };
    let json_part = json(&[]);
    let claims = json_part["claims"].as_array().expect("claims");
    let system = superint::system_file::load(
        Path::new(file),
        &superint::system_file::LimitsOverride::default(),
    )
    .expect("the file loads");
    let whole = [
        "(1 + x + y + p_x + p_y)^10",
        "(1 + x + y)^14*(cos(theta) + sin(2*theta))",
    ];
    for (claim, whole) in claims.iter().zip(whole) {
        assert_eq!(claim["residual_excerpt"]["shown_monomials"], 100, "{claim}");
        // The part is the leading part of the residual, and parses back to it.
        let whole = system.parse(whole).expect("the residual");
        let part = system
            .parse(claim["residual"].as_str().expect("ascii"))
            .expect("the part parses");
        let (want, monomials) = whole.leading_part(100);
        assert_eq!(part, want);
        assert_eq!(claim["residual_excerpt"]["monomials"], monomials, "{claim}");
    }
    // --full-expressions prints every term, and so does its first name.
    for flag in ["--full-expressions", "--full-residuals"] {
        let full = superint_exits(&["check", file, "--no-timings", flag], 1);
        let full = stdout(&full);
        assert!(!full.contains("shown:") && !full.contains('…'), "{full}");
    }
    let json_full = json(&["--full-expressions"]);
    let residual = json_full["claims"][0]["residual"].as_str().expect("ascii");
    let residual = system.parse(residual).expect("the residual parses");
    assert_eq!(residual.len(), 1001);
    assert_eq!(json_full["claims"][0]["residual_excerpt"], Value::Null);
}

/// The columns a table's combination is sought in are held at once, and together within the
/// term limit: a bracket of 10⁶ terms spanning a function of 7·10⁵ took 24 columns of
/// 1.7·10⁷ terms, 46 s, before the limit stopped the table (found by the fuzzer, seed 1205).
/// The entry past the limit is `?`, the limit said under the table in every format, and the
/// run exits 2.
#[test]
fn cli_table_columns_are_held_to_the_term_limit() {
    // {F, D} = Σ (a − b)·(terms x^a p_x^b of F): the 11 monomials of F, each with the
    // parameter parts 1 and M that F has too; so ν runs over 1/M, 1, M, three columns of
    // F's 22 terms, 66 in all, while no result has more than 22.
    let file = crate::scratch_text(
        "cli",
        "table-columns.toml",
        "name = \"column limit\"\n\
         hamiltonian = \"p_x^2/2\"\n\
         [phase_space]\ncoordinates = [\"x\"]\nparameters = [\"M\"]\n\
         [[function]]\nname = \"F\"\nvalue = \"(1 + M)*(x^2 + p_x)^10\"\n\
         [[function]]\nname = \"D\"\nvalue = \"x*p_x\"\n",
    );
    let file = file.to_str().expect("a UTF-8 path");
    let out = superint_exits(&["table", file, "--no-timings", "--max-terms", "65"], 2);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains(
            "1 entry of the table undecided (shown as ?), stopped at a limit, the first {F, D}: \
             the result would have more than 65 terms (the term limit)"
        ),
        "{err}"
    );
    // The entry is `?`, with the limit under the table; the others are computed.
    let text = stdout(&out);
    for said in [
        "    F     │ 0   ?",
        "    D     │ ?   0",
        "    {F, D} = ?: stopped at a limit: the result would have more than 65 terms",
        "computed exactly, but for 1 entry stopped at a limit",
    ] {
        assert!(text.contains(said), "{said}\n{text}");
    }
    let undecided = |format: &str| {
        let args = [
            "table",
            file,
            "--no-timings",
            "--max-terms",
            "65",
            "--format",
            format,
        ];
        stdout(&superint_exits(&args, 2))
    };
    let markdown = undecided("markdown");
    assert!(
        markdown.contains("- `{F, D}` = ?: stopped at a limit: the result would have"),
        "{markdown}"
    );
    let latex = undecided("latex");
    assert!(
        latex.contains(r"\noindent $\{F, D\} = ?$: stopped at a limit"),
        "{latex}"
    );
    compile_within(&latex, 1.0);
    let json: Value = serde_json::from_str(&undecided("json")).expect("JSON");
    let table = &json["tables"][0];
    // Shown as `?`, with no ASCII form to read back.
    assert_eq!(table["entries"][0][1]["text"], "?");
    assert_eq!(table["entries"][0][1]["ascii"], Value::Null);
    assert_eq!(
        (
            &table["undecided"][0]["row"],
            &table["undecided"][0]["column"]
        ),
        (&Value::from(0), &Value::from(1))
    );
    assert!(
        (table["undecided"][0]["message"]
            .as_str()
            .expect("a message"))
        .starts_with("the result would have more than 65 terms"),
        "{table}"
    );
    let out = superint_exits(&["table", file, "--no-timings", "--max-terms", "66"], 0);
    assert!(stdout(&out).contains("{F, D} = "), "{}", stdout(&out));
    assert!(!stdout(&out).contains('?'), "{}", stdout(&out));
}

/// A table's entry of more than a hundred monomials that is no combination of the listed
/// functions prints the terms of its first hundred and its size, in every format, and whole
/// with `--full-expressions`: a table with one function of 10⁵ terms printed 190 MB in 50 s
/// (found by the fuzzer, seed 1205).
#[test]
fn cli_long_table_entry_shows_its_leading_terms() {
    let file = crate::scratch_text(
        "cli",
        "long-table-entry.toml",
        "name = \"long entries\"\n\
         hamiltonian = \"(p_x^2 + p_y^2)/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\n\
         [[function]]\nname = \"X\"\nvalue = \"x\"\n\
         [[function]]\nname = \"B\"\nvalue = \"(1 + y + p_x + p_y)^12\"\n",
    );
    let file = file.to_str().expect("a UTF-8 path");
    // {X, B} = ∂B/∂p_x = 12(1 + y + p_x + p_y)^11, of C(14, 3) = 364 terms, and no
    // combination of X and B.
    let text = stdout(&superint_exits(&["table", file, "--no-timings"], 0));
    let normal = crate::normalize(&text);
    assert!(
        normal.contains("(shown: its first 100 of 364 terms; --full-expressions shows all)"),
        "{text}"
    );
    assert_eq!(text.matches(" + …").count(), 1, "{text}");
    let markdown = stdout(&superint_exits(
        &["table", file, "--no-timings", "--format", "markdown"],
        0,
    ));
    assert!(
        markdown.contains("- `{X, B}`: shown: its first 100 of 364 terms;"),
        "{markdown}"
    );
    assert_eq!(markdown.matches(" + …").count(), 2, "{markdown}");
    let latex = stdout(&superint_exits(
        &["table", file, "--no-timings", "--format", "latex"],
        0,
    ));
    assert!(latex.contains(r"+ \dots"), "{latex}");
    assert!(latex.contains("its first 100 of 364 terms"), "{latex}");
    compile_within(&latex, 1.0);
    // JSON: the entries are the leading parts, which parse back, and say so.
    let json = |extra: &[&str]| crate::superint_json(&[&["table", file], extra].concat());
    let system = superint::system_file::load(
        Path::new(file),
        &superint::system_file::LimitsOverride::default(),
    )
    .expect("the file loads");
    let whole = system.parse("{X, B}").expect("the bracket");
    let (want, monomials) = whole.leading_part(100);
    assert_eq!(monomials, 364);
    let part = json(&[]);
    let table = &part["tables"][0];
    assert_eq!(
        table["excerpts"],
        serde_json::json!([
            { "row": 0, "column": 1, "shown_monomials": 100, "monomials": 364 },
            { "row": 1, "column": 0, "shown_monomials": 100, "monomials": 364 },
        ])
    );
    let entry = |t: &Value, a: usize, b: usize| {
        let ascii = t["entries"][a][b]["ascii"].as_str().expect("ascii");
        system.parse(ascii).expect("the entry parses")
    };
    assert_eq!(entry(table, 0, 1), want);
    assert_eq!(entry(table, 1, 0), -&want);
    // Whole with --full-expressions.
    let full = json(&["--full-expressions"]);
    assert_eq!(full["tables"][0]["excerpts"], serde_json::json!([]));
    assert_eq!(entry(&full["tables"][0], 0, 1), whole);
    let text = stdout(&superint_exits(
        &["table", file, "--no-timings", "--full-expressions"],
        0,
    ));
    assert!(!text.contains("shown:") && !text.contains('…'), "{text}");
}

/// A closure's table and equations write a generator by its display name of several words
/// (`Re A`), in parentheses where a power or a factor follows it: `(Re A)² + (Im A)²`, not
/// `Re A² + Im A²`, which reads as the real part of `A²`, nor the names `ReA`, `ImA`. A display
/// name that is no name (`x(t)`) is written as it is, as the rest of the report writes it (it
/// was written by the generator's name, with a note on which stands for which).
#[test]
fn closure_writes_display_names_of_several_words_in_parentheses_before_a_power() {
    let out = run(
        &[
            "closure",
            "systems/anisotropic-3-5-rotor.toml",
            "Hx",
            "Hy",
            "ReA",
            "ImA",
            "--degree",
            "8",
            "--no-timings",
        ],
        0,
    );
    assert!(out.contains("{H_x, Re A} = 15ω Im A "), "{out}");
    assert!(
        out.contains("256M⁸ H_x⁵ H_y³ = (Re A)² + (Im A)² "),
        "{out}"
    );
    assert!(!out.contains("stands for") && !out.contains("ReA"), "{out}");
    let solution = run(
        &[
            "closure",
            "systems/harmonic-rotor-solution.toml",
            "X",
            "Y",
            "--no-timings",
        ],
        0,
    );
    assert!(
        solution.contains("  x(t) = y(t) at x_0 = 1, ") && !solution.contains("stands for"),
        "{solution}"
    );
    let plain = run(
        &["closure", "systems/harmonic-rotor.toml", "L", "G1", "G2"],
        0,
    );
    assert!(!plain.contains("stands for"), "{plain}");
}

/// A name of several words (`Re K`) is set in parentheses where a power, a factor or a
/// denominator follows it, in the statement as the user wrote it and in the bracket written in
/// the functions; at the end of a term it is bare (`6ω Im K`).
#[test]
fn display_names_of_several_words_take_parentheses_only_where_they_would_read_otherwise() {
    let out = run(
        &[
            "expand",
            "systems/anisotropic-3-5-rotor.toml",
            "ReK^2*Hx",
            "ReK/2",
            "omega*ImK",
            "ReK*ImK*x",
            "--no-timings",
        ],
        0,
    );
    let first = out.lines().next().expect("a title");
    assert!(
        first.starts_with("(Re K)² H_x, (Re K)/2, ω Im K, (Re K) (Im K) x in normal form"),
        "{out}"
    );
    let bracket = run(
        &[
            "bracket",
            "systems/anisotropic-3-5-rotor.toml",
            "Hx",
            "ReK*ImK",
            "--no-timings",
        ],
        0,
    );
    assert!(
        bracket.contains("= −6ω(K² − 2i (Re K) (Im K))\n"),
        "{bracket}"
    );
    let table = run(
        &[
            "table",
            "systems/anisotropic-3-5-rotor.toml",
            "Hx",
            "ReK",
            "ImK",
            "Omega",
            "--no-timings",
        ],
        0,
    );
    assert!(table.contains("{H_x, Re K} = 6ω Im K\n"), "{table}");
    assert!(table.contains("{Re K, Ω} = (Im K)/I\n"), "{table}");
}

/// An expansion that would print past the term limit stops at once with the limit's message
/// (`K_{60,60}` printed 2.4 million terms in powers of cos θ and sin θ, 240 MB, in nine
/// seconds, past `--max-terms 40000`), and prints below it. The terms are counted in the form
/// printed: `K_{60,60} = Z⁶⁰e^{−60iθ}` is, in multiple angles, `cos 60θ` and `sin 60θ` times
/// each of the C(63, 3) = 39711 monomials of `Z⁶⁰` (`Z = p_x − Mωy + i(p_y + Mωx)`), 79422 terms.
#[test]
fn an_expansion_that_would_print_past_the_term_limit_is_refused() {
    let file = "systems/harmonic-rotor.toml";
    for (angles, said) in [
        (
            "powers",
            "printed in powers of cos and sin, the result could have up to 2422371 terms",
        ),
        (
            "harmonics",
            "printed in multiple angles, the result could have up to 79422 terms",
        ),
    ] {
        let err = crate::superint_refused(&[
            "expand",
            file,
            "K_{60,60}",
            "--max-terms",
            "40000",
            "--angles",
            angles,
        ]);
        assert!(
            err.contains(&format!("<command line>: {said}"))
                && err.contains("past the limit of 40000 (the term limit)"),
            "{err}"
        );
    }
    let out = run(&["expand", file, "K_{2,2}", "--max-terms", "40"], 0);
    assert!(out.contains("K_{2,2} ="), "{out}");
}

/// A family instance that `table` cannot expand is an error of the command line that names
/// it, with the family's place in the hint, as `bracket` says it (it was placed at the
/// family's value in the file).
#[test]
fn a_table_instance_past_a_limit_is_an_error_of_the_command_line() {
    let file = "systems/harmonic-rotor.toml";
    for command in ["table", "bracket"] {
        let err = crate::superint_refused(&[command, file, "K_{30,30}", "L", "--max-terms", "100"]);
        assert!(
            err.starts_with("superint: error: <command line>:1:1: cannot expand K_{30,30}: the result would have more than 100 terms")
                && err.contains("hint: K's value is at systems/harmonic-rotor.toml:58:10"),
            "{command}: {err}"
        );
    }
}

/// An instance of a family whose value uses another family's instance is refused with both
/// places in the hint, each named by its family: the Fock–Darwin `P_{m,n} = re(K_m_n)` at
/// `P`'s value, then `K`'s (both hints once read "the family's value is at", twice).
#[test]
fn a_nested_family_instance_past_a_limit_names_each_family_at_its_place() {
    let err = crate::superint_refused(&["expand", "systems/fock-darwin.toml", "P_99_1"]);
    assert!(
        err.contains(
            "hint: P's value is at systems/fock-darwin.toml:79:13; \
             K's value is at systems/fock-darwin.toml:74:10; "
        ),
        "{err}"
    );
}

/// A family instance whose power is known to pass the term limit is refused before it is
/// multiplied out, with the limit's message, by every command that forms it: the Fock–Darwin
/// `P_{99,1} = Re(W^99 Z̄)`, whose `W^99` has 8 670 850 terms, was refused only after 20 s of
/// multiplying by `W` one factor at a time up to `W^68`, the first power past the default
/// limit of 2 000 000 (the terms of a power of `W` meet on one relation and cannot cancel, so
/// their count is known from `W`'s monomials). Under a configured limit the instance at the
/// limit is formed and refused one below it: `K_{20,0} = W^20`, of 19 481 terms.
#[test]
fn a_power_known_to_pass_the_term_limit_is_refused_before_it_is_formed() {
    let file = "systems/fock-darwin.toml";
    for args in [
        &["expand", file, "P_99_1"][..],
        &["bracket", file, "P_99_1", "H"],
        &["table", file, "P_99_1", "L"],
        &["rank", file, "H", "P_99_1"],
        &["closure", file, "H", "P_99_1"],
    ] {
        let err = crate::superint_refused(args);
        assert!(
            err.starts_with(
                "superint: error: <command line>:1:1: cannot expand P_{99,1}: cannot expand \
                 K_{99,1}: the result would have more than 2000000 terms (the term limit); \
                 raise the limit or simplify the input\n"
            ) && err.contains("on the command line, --max-terms N"),
            "{args:?}: {err}"
        );
    }
    let expand = ["expand", file, "K_20_0", "--no-timings", "--max-terms"];
    let at = |limit| [&expand[..], &[limit]].concat();
    let err = crate::superint_refused(&at("19480"));
    assert!(
        err.contains("cannot expand K_{20,0}: the result would have more than 19480 terms"),
        "{err}"
    );
    let report = crate::superint_json(&at("19481"));
    let ascii = report["equations"][0]["lines"][0]["ascii"]
        .as_str()
        .expect("the expansion");
    let terms = 1 + ascii.matches(" + ").count() + ascii.matches(" - ").count();
    assert_eq!(terms, 19_481, "{}", &ascii[..200]);
}

/// Markdown headings and prose write `<`, `>` and `&` as entities outside code spans: a file
/// read from standard input is `<stdin>`, which a Markdown viewer took for an HTML tag and
/// dropped (`## 1. Kepler problem ()`).
#[test]
fn markdown_prose_escapes_what_reads_as_html() {
    let text = std::fs::read("systems/kepler.toml").expect("the file");
    let mut child = Command::new(env!("CARGO_BIN_EXE_superint"))
        .args(["check", "-", "--format", "markdown"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .expect("superint runs");
    std::io::Write::write_all(&mut child.stdin.take().expect("stdin"), &text).expect("write");
    let out = child.wait_with_output().expect("superint ends");
    let md = stdout(&out);
    assert!(md.contains("## 1. Kepler problem (&lt;stdin&gt;)"), "{md}");
    assert!(md.contains("`−k/r`"), "{md}");
}

/// A claim's id is shown literally in Markdown: `__x__` and `a*b*c` were emphasis inside the
/// bold verdict (`**__x__ proved**`), their underscores and stars lost; an id of letters and
/// digits reads as it did.
#[test]
fn markdown_shows_claim_ids_literally() {
    let file = scratch_file("ids.toml");
    std::fs::write(
        &file,
        "hamiltonian = \"(p_x^2 + p_y^2)/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\n\
         [[claim]]\nid = \"__x__\"\nclaim = \"{p_x, H} = 0\"\n\
         [[claim]]\nid = \"a*b*c\"\nclaim = \"{p_y, H} = 0\"\n\
         [[claim]]\nid = \"C09\"\nclaim = \"{x*p_y - y*p_x, H} = 0\"\n",
    )
    .expect("write the file");
    let md = run(
        &[
            "check",
            file.to_str().expect("a path"),
            "--format",
            "markdown",
        ],
        0,
    );
    for shown in [
        r"**\_\_x\_\_ proved**",
        r"**a\*b\*c proved**",
        "**C09 proved**",
    ] {
        assert!(md.contains(shown), "{shown}: {md}");
    }
}

/// The closure help's example of a cubic algebra runs as shown, and finds it.
#[test]
fn the_closure_help_example_of_a_cubic_algebra_runs() {
    let help = run(&["closure", "--help"], 0);
    let example = "superint closure systems/fokas-lagerstrom-1-3.toml H Hx S C --degree 4";
    assert!(help.contains(example), "{help}");
    let args: Vec<&str> = example.split(' ').skip(1).collect();
    let out = run(&args, 0);
    assert!(out.contains("{S, C} = 24M³(3 H − 4 H_x) H_x²"), "{out}");
    // The table's entry in JSON as the text writes it, and it reads back as the bracket.
    let v: Value =
        serde_json::from_str(&run(&[&args[..], &["--format", "json"]].concat(), 0)).expect("JSON");
    let entry = &v["tables"][0]["entries"][2][3];
    assert_eq!(entry["text"], "24M³(3 H − 4 H_x) H_x²");
    let file = superint::system_file::load(
        Path::new("systems/fokas-lagerstrom-1-3.toml"),
        &superint::system_file::LimitsOverride::default(),
    )
    .expect("the file loads");
    let read = |text: &str| file.parse(text).expect("it parses");
    let ascii = entry["ascii"].as_str().expect("ascii");
    assert_eq!(read(ascii), read("{S, C}"), "{ascii}");
}

/// The example of `--define` in `closure --help` runs (its `Hx` read as `H·x` and was
/// refused), and finds the relation of the defined generator.
#[test]
fn the_closure_help_example_of_define_runs() {
    let help = run(&["closure", "--help"], 0);
    let example = "--system harmonic Hp L G1 G2 Ex --define 'Ex=p_x^2/(2*M) + M*omega^2*x^2/2'";
    assert!(help.contains(example), "{help}");
    let out = run(
        &[
            "closure",
            "--system",
            "harmonic",
            "Hp",
            "L",
            "G1",
            "G2",
            "Ex",
            "--define",
            "Ex=p_x^2/(2*M) + M*omega^2*x^2/2",
        ],
        0,
    );
    assert!(out.contains("Hp + G2 = 2 Ex"), "{out}");
}

/// A closure of generators in involution has no bracket to write and, here, no relation: its
/// closing line says the table was computed exactly, not `0 claims: 0 proved, 0 refuted (0
/// exact checks)`, which read as if nothing had been checked.
#[test]
fn a_closure_without_claims_closes_with_what_was_computed() {
    let out = run(
        &[
            "closure",
            "systems/stark.toml",
            "H",
            "Lz",
            "Bz",
            "--no-timings",
        ],
        0,
    );
    assert!(out.contains("    B_z   │ 0   0     0\n"), "{out}");
    assert!(out.ends_with("\ncomputed exactly\n"), "{out}");
    assert!(!out.contains("0 claims"), "{out}");
}

/// A built-in system's text that a limit stops while it is read (a `--when` value, a
/// `--define`, a `--known` integral: `x^5000` past the degree limit, a power past the term
/// limit) is of kind `limit`, with the hint that raises it, as the same text given with a
/// system file is (it was of kind `expression`, without the hint); the hint names the flag
/// alone, a built-in system having no file.
#[test]
fn a_builtin_systems_text_at_a_limit_is_a_limit() {
    let hint = "\nhint: if the machine has the memory, raise the limit with --max-degree D\n";
    let file_hint = |flag: &str, key: &str| format!("{flag} (or {key} under [limits] in the file)");
    let texts: [&[&str]; 4] = [
        &["search", "--when", "p_theta = x^5000"],
        &["closure", "H", "L", "--define", "G=x^5000"],
        &["search", "--new-only", "--known", "L, x^5000"],
        &[
            "search",
            "--new-only",
            "--known",
            "L, (x+p_x+y+p_y+1)^40",
            "--max-terms",
            "1000",
        ],
    ];
    for args in texts {
        let (command, rest) = args.split_first().unwrap();
        let builtin = stderr(&superint_exits(
            &[&[*command, "--system", "harmonic"][..], rest].concat(),
            2,
        ));
        let file = stderr(&superint_exits(
            &[&[*command, "systems/harmonic-rotor.toml"][..], rest].concat(),
            2,
        ));
        let (flag, key) = match args.contains(&"--max-terms") {
            true => ("--max-terms N", "max_terms"),
            false => ("--max-degree D", "max_degree"),
        };
        assert_eq!(
            builtin.replace(flag, &file_hint(flag, key)),
            file,
            "{args:?}"
        );
        assert!(
            builtin.ends_with(&format!(
                "\nhint: if the machine has the memory, raise the limit with {flag}\n"
            )),
            "{builtin}"
        );
    }
    let said = stderr(&superint_exits(
        &[
            "search",
            "--system",
            "harmonic",
            "--when",
            "p_theta = x^5000",
        ],
        2,
    ));
    assert_eq!(
        said,
        format!(
            "superint: error: <command line>:1:13: the exponent 5000 is past the limit of 1000\n \
             1 | p_theta = x^5000\n   |             ^^^^{hint}"
        )
    );
}

/// A condition whose values a limit stops as they are resolved into each other (`x` in `y`,
/// `y` past the term limit) is of kind `limit`, with the hint that raises it, as its values'
/// reading is: `discovery::parse_condition` (a built-in system's `--when`) said it as a string,
/// and a file's condition said it of kind `condition`, without the hint, and so in the JSON
/// report's `errors` of `check`.
#[test]
fn a_condition_at_a_limit_is_a_limit() {
    let when = "x = (y + p_y + 1)^4, y = (p_x + p_theta + 1)^4";
    let said = |raise: &str| {
        format!(
            "superint: error: <command line>:1:5: the result would have more than 100 terms \
             (the term limit); raise the limit or simplify the input\n 1 | {when}\n   |     \
             ^^^^^^^^^^^^^^^\nhint: if the machine has the memory, raise the limit with \
             {raise}\n"
        )
    };
    for (system, said) in [
        (&["--system", "harmonic"][..], said("--max-terms N")),
        (
            &["systems/harmonic-rotor.toml"],
            said("--max-terms N (or max_terms under [limits] in the file)"),
        ),
    ] {
        let args = [&["search"], system, &["--when", when, "--max-terms", "100"]].concat();
        assert_eq!(stderr(&superint_exits(&args, 2)), said, "{system:?}");
    }
    let file = crate::scratch_text(
        "condition-at-a-limit",
        "limited.toml",
        "name = \"oscillator\"\nhamiltonian = \"p_x^2/2 + p_y^2/2 + x^2/2 + y^2/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\n[limits]\nmax_terms = 100\n\
         [[claim]]\nid = \"a\"\nclaim = \"{x, H} = p_x\"\n\
         when = \"x = (y + p_y + 1)^4, y = (p_x + x + 1)^6\"\n",
    );
    let file = file.to_str().unwrap();
    let o = superint_exits(
        &["check", file, "systems/kepler.toml", "--format", "json"],
        2,
    );
    let report: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let errors = report["errors"].as_array().unwrap();
    assert_eq!(errors.len(), 1, "{report}");
    assert_eq!(errors[0]["kind"], "limit", "{report}");
    assert_eq!(
        (&errors[0]["line"], &errors[0]["column"]),
        (&10.into(), &13.into())
    );
    assert!(
        errors[0]["hint"].as_str().unwrap().contains("max_terms"),
        "{report}"
    );
}

/// A limit's hint speaks to the input it was given: for a built-in system (`--system
/// harmonic`, which has no file) the command line's flag alone, where it named `max_degree
/// under [limits] in the file`, then the flag and a program's `LimitsOverride`; for a text
/// given on the command line to a file, and for a file piped on standard input, the flag
/// first, then the file's `[limits]`; for a file's own text, loaded by whoever, the file's
/// `[limits]`, then the flag and the `LimitsOverride`, as before. The degree, term and work
/// limits alike, each from one place.
#[test]
fn a_limits_hint_speaks_to_the_input_it_was_given() {
    let hint = |args: &[&str]| {
        let err = stderr(&superint_exits(args, 2));
        let hint = err.lines().find_map(|l| l.strip_prefix("hint: "));
        hint.unwrap_or_else(|| panic!("{args:?}: {err}"))
            .to_string()
    };
    let memory = "if the machine has the memory, raise the limit with";
    let time = "if the machine has the time, raise the limit with";
    let big = "(x + p_x + y + p_y + 1)^20";
    let work = "(1 + x + y + p_x)^4*(1 - x + y - p_y)^4";
    for (args, said) in [
        (
            &[
                "expand",
                "--system",
                "harmonic",
                "x^2000",
                "--max-degree",
                "100",
            ][..],
            format!("{memory} --max-degree D"),
        ),
        (
            &[
                "bracket",
                "--system",
                "harmonic",
                big,
                "H",
                "--max-terms",
                "1000",
            ],
            format!("{memory} --max-terms N"),
        ),
        (
            &[
                "expand",
                "--system",
                "gravity",
                work,
                "--max-term-products",
                "600",
            ],
            format!("{time} --max-term-products N"),
        ),
        (
            &[
                "rank",
                "--system",
                "harmonic",
                "L",
                "x^2000",
                "--max-degree",
                "100",
            ],
            format!("{memory} --max-degree D"),
        ),
        (
            &[
                "expand",
                "systems/harmonic-rotor.toml",
                "x^2000",
                "--max-degree",
                "100",
            ],
            format!("{memory} --max-degree D (or max_degree under [limits] in the file)"),
        ),
        (
            &[
                "bracket",
                "systems/harmonic-rotor.toml",
                "L",
                "H",
                "--when",
                "x = y^2000",
            ],
            format!("{memory} --max-degree D (or max_degree under [limits] in the file)"),
        ),
        (
            &[
                "expand",
                "systems/harmonic-rotor.toml",
                work,
                "--max-term-products",
                "600",
            ],
            format!(
                "{time} --max-term-products N (or max_term_products under [limits] in the file)"
            ),
        ),
    ] {
        assert_eq!(hint(args), said, "{args:?}");
    }
    // A file's own claim past the limit: whoever loaded it may raise it, the file first.
    let file = crate::scratch_text(
        "limit-hint-of-a-file",
        "limited.toml",
        "name = \"oscillator\"\nhamiltonian = \"p_x^2/2 + x^2/2\"\n\
         [phase_space]\ncoordinates = [\"x\"]\n\
         [[claim]]\nid = \"a\"\nclaim = \"x^5000 = 0\"\n",
    );
    let own = format!(
        "{memory} max_degree under [limits] in the file (on the command line, --max-degree D; \
         in a program, the LimitsOverride given to the loader)"
    );
    assert_eq!(hint(&["check", file.to_str().unwrap()]), own);
    // The same file piped on standard input: only the command line reads it.
    let mut child = Command::new(env!("CARGO_BIN_EXE_superint"))
        .args(["check", "-"])
        .stdin(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("superint runs");
    let text = std::fs::read(&file).expect("the file");
    std::io::Write::write_all(&mut child.stdin.take().expect("stdin"), &text).expect("write");
    let out = child.wait_with_output().expect("superint ends");
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains(&format!(
            "\nhint: {memory} --max-degree D (or max_degree under [limits] in the file)\n"
        )),
        "{}",
        stderr(&out)
    );
}

/// A built-in system that the limits given do not let be built (`--max-terms 10`, which its
/// functions' expansions pass) is a limit as every other is: exit code 2, the limit and how
/// far it must be raised in the message, and the hint naming the flag, where it said only
/// `the built-in system harmonic does not fit the limits given: the result would have more
/// than 10 terms (the term limit); raise the limit or simplify the input`, with no flag;
/// under a degree limit the least said is that of the resonant functions too, which
/// `expand` builds (the Hamiltonian's exponent 2 is not enough), and that limit builds it.
#[test]
fn a_built_in_system_past_the_limits_given_is_a_limit_with_its_flag() {
    let memory = "if the machine has the memory, raise the limit with";
    for (args, needs) in [
        (
            &["expand", "--system", "harmonic", "x", "--max-terms", "10"][..],
            "a term limit of at least 20 (the limit is 10)\nhint: {memory} --max-terms N",
        ),
        (
            &["expand", "--system", "harmonic", "x", "--max-degree", "1"],
            "a degree limit of at least 3 (the limit is 1)\nhint: {memory} --max-degree D",
        ),
        (
            &["search", "--system", "gravity", "--max-terms", "2"],
            "a term limit of at least 6 (the limit is 2)\nhint: {memory} --max-terms N",
        ),
    ] {
        let system = args[2];
        let expected = format!(
            "superint: error: --system {system}: the system does not fit the limits given: \
             building it needs {}\n",
            needs.replace("{memory}", memory)
        );
        assert_eq!(stderr(&superint_exits(args, 2)), expected, "{args:?}");
    }
    run(
        &["expand", "--system", "harmonic", "x", "--max-degree", "3"],
        0,
    );
    run(
        &["expand", "--system", "harmonic", "x", "--max-terms", "20"],
        0,
    );
}

/// A search's or a closure's limit met on the command line says what happened in the engine's
/// terms, naming no setting (the search's term limit named `Limits::max_terms`, a program's,
/// for a system file, whose limit the flag or its `[limits]` sets), and the hint names what
/// raises it for the input: the flag, then the file's `[limits]` for a file; the flag alone
/// for a built-in system and for an option no file sets (`--max-products`, `--max-monomials`),
/// where there was no hint.
#[test]
fn a_search_or_closure_limit_hints_the_setting_for_its_input() {
    let memory = "if the machine has the memory, raise the limit with";
    let time = "if the machine has the time, raise the limit with";
    let unknowns = "the space has 300 unknowns, more than the term limit 10: search a smaller \
                    space, or raise the limit";
    for (args, said) in [
        (
            &["search", "systems/harmonic-rotor.toml", "--max-terms", "10"][..],
            format!(
                "systems/harmonic-rotor.toml: searching for integrals: {unknowns}\nhint: \
                 {memory} --max-terms N (or max_terms under [limits] in the file)"
            ),
        ),
        (
            &["search", "--system", "harmonic", "--max-terms", "10"],
            format!("--system harmonic: searching for integrals: {unknowns}\nhint: {memory} --max-terms N"),
        ),
        (
            &["search", "--system", "harmonic", "--new-only", "--max-products", "1"],
            format!(
                "--system harmonic: searching for integrals: more than 1 product of integrals, \
                 the search's limit of them: search a smaller space, or raise the limit\nhint: \
                 {time} --max-products N"
            ),
        ),
        (
            &["closure", "systems/harmonic-rotor.toml", "L", "H", "--max-monomials", "3"],
            format!(
                "systems/harmonic-rotor.toml: computing the closure: there are 6 monomials of \
                 degree ≤ 2 in the 2 generators, more than the limit 3: lower the degree, or \
                 raise the limit\nhint: {time} --max-monomials N"
            ),
        ),
    ] {
        let err = stderr(&superint_exits(args, 2));
        assert_eq!(err, format!("superint: error: {said}\n"), "{args:?}");
    }
}

/// A closure that passes a limit while forming the products of its generators stops with exit
/// code 2 and says how to go on: raise the limit, named by the option of the one it passed
/// (the degree limit's, not the term or work limit's, which it named too), or lower the
/// degree.
#[test]
fn a_closure_at_a_limit_says_how_to_go_on() {
    let closure = [
        "closure",
        "systems/stark.toml",
        "H",
        "Lz",
        "X",
        "--define",
        "X=p_y^300",
        "--degree",
        "4",
    ];
    closure_stops_with(
        &closure,
        "the exponent of p_y would reach 1200, past the limit of 1000; raise the limit with \
         --max-degree D, or lower --degree",
    );
    run(&[&closure[..], &["--max-degree", "1200"]].concat(), 0);
}

/// That `closure` stops with exit code 2 and says `computing the closure: {said} (the
/// products of the generators up to it are formed)`.
fn closure_stops_with(closure: &[&str], said: &str) {
    let o = superint_exits(closure, 2);
    assert_eq!(
        stderr(&o),
        format!(
            "superint: error: computing the closure: {said} (the products of the generators \
             up to it are formed)\n"
        )
    );
}

/// A closure whose products pass the degree limit with an exponent past the most that
/// --max-degree may be (32767) says that no limit reaches it, and only that a lower degree
/// helps: it said to raise the limit with --max-degree D, which refuses any D past 32767.
#[test]
fn a_closure_past_the_largest_degree_limit_names_no_option() {
    let closure = [
        "closure",
        "systems/stark.toml",
        "X",
        "--define",
        "X=p_y^20000",
        "--degree",
        "2",
        "--max-degree",
        "20000",
    ];
    closure_stops_with(
        &closure,
        "the exponent of p_y would reach 40000, past the limit of 20000; no limit reaches this \
         exponent (--max-degree is at most 32767): lower --degree",
    );
    let mut lower = closure;
    lower[6] = "1";
    run(&lower, 0);
}

/// An unknown name one slip from a resonant instance of the built-in rotor under gravity is
/// told the instance as systems/gravity-rotor.toml names it, `Pp_1_1` (the family `Pp`, shown
/// `P'`), which the built-in reads too: it was told `P11`, the built-in's own name for
/// `P'_{1,1}`, which no file of the rotor spells so. Without gravity, `P_1_1`.
#[test]
fn an_unknown_name_is_told_a_resonant_instance_as_the_file_spells_it() {
    for (system, typed, meant) in [
        ("gravity", "P_1_1", "Pp_1_1"),
        ("harmonic", "p_1_1", "P_1_1"),
    ] {
        let o = superint_exits(&["closure", "--system", system, "L", typed], 2);
        let expected = format!(
            "superint: error: <command line>:1:1: unknown name '{typed}'; did you mean \
             '{meant}'? (known: "
        );
        assert!(stderr(&o).starts_with(&expected), "{}", stderr(&o));
        run(&["closure", "--system", system, "L", meant], 0);
    }
}

/// A --define value that uses a name another --define gives (or its own) is refused with the
/// caret under that name where the value first uses it, as an unknown name's is, on a built-in
/// system and on a file alike: it stood under the whole value, `A+zz`.
#[test]
fn a_define_using_a_defined_name_is_refused_at_the_name() {
    // `G` is first a name of its own after `2` (a coefficient), not the start of `G1`.
    for system in [
        &["--system", "harmonic"][..],
        &["systems/harmonic-rotor.toml"],
    ] {
        let given = [
            &["closure"],
            system,
            &["L", "G", "B", "--define", "G=L*x", "--define", "B= G1+2G*G"],
        ]
        .concat();
        assert_eq!(
            stderr(&superint_exits(&given, 2)),
            "superint: error: <command line>:1:8: --define: G is given by --define, whose values \
             use only the system's names: write its value, (L*x), in its place\n \
             1 | B= G1+2G*G\n   |        ^\n"
        );
        let own = [&["closure"], system, &["L", "G", "--define", "G=G1+x*G"]].concat();
        assert_eq!(
            stderr(&superint_exits(&own, 2)),
            "superint: error: <command line>:1:8: --define: its value uses G, the name it \
             defines\n 1 | G=G1+x*G\n   |        ^\n"
        );
    }
}

/// A closure whose products of the generators pass the term limit together says so, what was
/// counted and the degree, and how to go on once: it said `the result would have more than
/// 2000000 terms`, though no one result had, and `raise the limit` twice, the engine's advice
/// and then the command line's. A built-in system and a file read alike; another limit that
/// carries the algebra's own advice (the work limit) says `raise` once too, and names its
/// own option alone (it named all three limits' options).
#[test]
fn a_closures_products_at_the_term_limit_say_what_was_counted() {
    let expected = "superint: error: computing the closure: the products of the generators up \
                    to degree 32 would have more than 2000000 terms together (the term limit); \
                    raise it with --max-terms N, or lower --degree\n";
    for system in [
        &["--system", "gravity"][..],
        &["systems/gravity-rotor.toml"],
    ] {
        let closure = [&["closure"], system, &["p_x", "F1", "--degree", "32"]].concat();
        let o = superint_exits(&closure, 2);
        assert_eq!(stderr(&o), expected);
    }
    let work = [
        "closure",
        "--system",
        "harmonic",
        "L",
        "X",
        "--define",
        "X=(x+y+p_x+p_y+M+1)^8",
        "--degree",
        "3",
        "--max-term-products",
        "1000",
    ];
    let o = superint_exits(&work, 2);
    assert_eq!(
        stderr(&o),
        "superint: error: computing the closure: the product of 495 terms by 495 would form \
         245025 term products, past the limit of 1000 (the work limit); raise the limit with \
         --max-term-products N, or lower --degree (the products of the generators up to it \
         are formed)\n"
    );
}

/// The work limit bounds a bracket's products together, not each alone: `{Ax^50, Ay^50}` of
/// the Kepler problem formed four products of 4·10⁹ term products each, every one under the
/// default limit of 10¹⁰, and answered after 200 s. The bracket counts them all before it
/// forms any, stops with the limit's message and the option that raises it, and a limit
/// above the total lets it through.
#[test]
fn a_brackets_products_count_against_the_work_limit_together() {
    let bracket = |limit: &'static str| {
        let args = [
            "bracket",
            "systems/kepler.toml",
            "Ax^8",
            "Ay^8",
            "--no-timings",
        ];
        [&args[..], &["--max-term-products", limit]].concat()
    };
    // Each product is at most 340 terms by 356, 121 040 term products; all four, 407 936.
    let o = superint_exits(&bracket("400000"), 2);
    let err = stderr(&o);
    assert!(
        err.starts_with(
            "superint: error: <command line>: a sum of 4 products (as a bracket is) would form \
             407936 term products in all (the largest, 340 terms by 356), past the limit of \
             400000 (the work limit)"
        ),
        "{err}"
    );
    assert!(err.contains("--max-term-products N"), "{err}");
    let out = run(&bracket("410000"), 0);
    assert!(out.contains("{A_x⁸, A_y⁸} = "), "{out}");
}

/// A bracket, an expansion and a refuted claim's residual whose terms share a factor are
/// also written as that factor times the rest, as the paper writes them
/// (`{A_z, H} = F(x p_x + y p_y)/M`), in every format; a result in the named functions
/// (`2iω Z²`) or with no shared factor (a Hamiltonian) is not.
#[test]
fn results_whose_terms_share_a_factor_are_also_written_factored() {
    let out = run(
        &["bracket", "systems/stark.toml", "Az", "H", "--no-timings"],
        0,
    );
    assert!(
        out.contains("    {A_z, H} = Fx p_x/M + Fy p_y/M\n             = F(x p_x + y p_y)/M\n"),
        "{out}"
    );
    let json = superint_json(&["bracket", "systems/stark.toml", "Az", "H"]);
    let line = &json["equations"][0]["lines"][0];
    assert_eq!(line["factored"]["ascii"], "F*(x*p_x + y*p_y)/M", "{json}");
    assert_eq!(
        line["factored"]["latex"], r"\frac{F \left(x p_{x} + y p_{y}\right)}{M}",
        "{json}"
    );
    let latex = run(
        &[
            "bracket",
            "systems/stark.toml",
            "Az",
            "H",
            "--format",
            "latex",
        ],
        0,
    );
    assert!(
        latex.contains(r"&= \frac{F \left(x p_{x} + y p_{y}\right)}{M}"),
        "{latex}"
    );
    let markdown = run(
        &["bracket", "systems/stark.toml", "Az", "H", "--format", "md"],
        0,
    );
    assert!(markdown.contains(" = `F(x p_x + y p_y)/M`"), "{markdown}");

    // In the named functions, it is not factored as well.
    let z2 = run(
        &[
            "bracket",
            "systems/harmonic-rotor.toml",
            "Z^2",
            "H",
            "--no-timings",
        ],
        0,
    );
    assert!(z2.contains("= 2iω Z²\n"), "{z2}");
    assert!(!z2.contains("= 2ω("), "{z2}");
    // A Hamiltonian's terms share no factor that leaves a polynomial.
    let h = run(&["expand", "systems/stark.toml", "H", "--no-timings"], 0);
    assert_eq!(h.matches(" = ").count(), 1, "{h}");

    let check = run(&["check", "systems/stark.toml", "--no-timings"], 0);
    assert!(
        check.contains(
            "      residual lhs − rhs = 2Fx p_x/M + 2Fy p_y/M\n\
             \x20                        = 2F(x p_x + y p_y)/M\n"
        ),
        "{check}"
    );
    // A single term is not restated.
    assert!(
        check.contains("      residual lhs − rhs = −Fz p_z/M\n  {L_x, H} = 0"),
        "{check}"
    );
    let json = superint_json(&["check", "systems/stark.toml"]);
    let claims = json["claims"].as_array().expect("claims");
    let sign = claims
        .iter()
        .find(|c| c["id"] == "false-field-sign")
        .expect("the claim");
    assert_eq!(sign["residual_factored"], "2*F*(x*p_x + y*p_y)/M", "{sign}");
    let radius = claims
        .iter()
        .find(|c| c["id"] == "false-field-radius")
        .expect("the claim");
    assert_eq!(radius["residual_factored"], Value::Null, "{radius}");
}

/// Claims set in one alignment share its column, the widest of their left sides: a claim with
/// a short left side breaks its right side to what that column leaves of the row, not its own
/// left side (the Fock–Darwin file's `8 P_{1,2} = 8 p_x³ − …` under
/// `{p_x p_y + M²a²xy, H} = 0` was set 71 pt past the margin).
#[test]
fn a_short_left_side_beside_a_wide_one_breaks_to_the_alignment_column() {
    let file = crate::scratch_text(
        "latex",
        "column.toml",
        "name = \"column\"\n\
         hamiltonian = \"(p_x^2 + p_y^2)/2 + (x^2 + y^2)/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\n\
         [[function]]\nname = \"S\"\n\
         value = \"x^3 + y^3 + p_x^3 + p_y^3 + x^2*y + x*y^2 + p_x^2*p_y + p_x*p_y^2 \
         + x*p_x^2 + y*p_y^2 + x^2*p_y + y^2*p_x\"\n\
         [[claim]]\nclaim = \"{p_x*p_y + x*y + p_x^2 + x^2, H} = 0\"\n\
         [[claim]]\nclaim = \"S = x^3 + y^3 + p_x^3 + p_y^3 + x^2*y + x*y^2 + p_x^2*p_y \
         + p_x*p_y^2 + x*p_x^2 + y*p_y^2 + x^2*p_y + y^2*p_x\"\n\
         [[claim]]\nclaim = \"{x, H} = 0\"\nexpect = \"refuted\"\n",
    );
    let doc = run(
        &[
            "check",
            file.to_str().expect("a UTF-8 path"),
            "--format",
            "latex",
            "--no-timings",
        ],
        0,
    );
    assert!(doc.contains(r"S &= x^{3}"), "{doc}");
    compile_within(&doc, 1.0);
}

/// A search at a condition on the parameters shows H as it searches it, the condition applied
/// (the title says `at a = 2b`, and H had kept its `a`); one at a momentum's value shows H
/// whole, since the condition is applied to the brackets. Where no integral is listed, the
/// closing claim is for "the" basis elements, not "the other" ones.
#[test]
fn a_search_at_a_condition_shows_h_as_it_searches_it() {
    let out = run(
        &[
            "search",
            "systems/fock-darwin.toml",
            "--momenta-degree",
            "2",
            "--positions-degree",
            "2",
            "--when",
            "a = 2*b",
            "--new-only",
            "--no-timings",
        ],
        0,
    );
    assert!(
        out.contains(
            "    H = p_x²/(2M) + p_y²/(2M) − ω₋ x p_y/2 + ω₋ y p_x/2 + 9M ω₋² x²/8 + 9M ω₋² y²/8\n"
        ),
        "{out}"
    );
    assert!(
        out.contains("{I, H} = 0 for the 4 basis elements at ω₊ = 2 ω₋"),
        "{out}"
    );
    assert!(!out.contains("the other"), "{out}");
    let search = ["search", "systems/harmonic-rotor.toml"];
    let at = ["--when", "p_theta = I*omega", "--no-timings"];
    let rotor = run(&[&search[..], &crate::DEGREE_ONE, &at].concat(), 0);
    assert!(
        rotor.contains("    H = p_x²/(2M) + p_y²/(2M) + p_θ²/(2I) + Mω²x²/2 + Mω²y²/2\n"),
        "{rotor}"
    );
}

/// A function whose display is no name, `∂H` or `x(t)`, is printed by its display where a
/// result is written in the functions, as everywhere else in a report: `bracket`'s line below
/// the normal form, `table`'s brackets that are no combination of the listed functions and
/// (in LaTeX) its combinations, `search`'s integrals and `closure`'s table, in text, LaTeX
/// (`\partial H`, as the statement writes it) and JSON; the ASCII form keeps the name, which
/// reads back. They printed the name (`= dH`, `\mathrm{dH}`), and a table's LaTeX cell `∂H`
/// raw.
#[test]
fn results_in_the_functions_print_a_display_that_is_no_name() {
    let file = crate::scratch_text(
        "display-no-name",
        "d.toml",
        "name = \"oscillator\"\nhamiltonian = \"(p_x^2 + p_y^2)/2 + (x^2 + y^2)/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\n\
         [[function]]\nname = \"dH\"\ndisplay = \"∂H\"\nvalue = \"x*p_x + y*p_y\"\n\
         [[function]]\nname = \"xt\"\ndisplay = \"x(t)\"\nvalue = \"x\"\n\
         [[function]]\nname = \"R\"\nvalue = \"(x^2 + y^2)/2\"\n\
         [[function]]\nname = \"E\"\nvalue = \"H\"\n\
         [[function]]\nname = \"B\"\ndisplay = \"b(t)\"\nvalue = \"p_x*p_y + x*y\"\n\
         [[function]]\nname = \"A\"\nvalue = \"p_x^2 + x^2 - p_y^2 - y^2\"\n",
    );
    let file = file.to_str().expect("a UTF-8 path");
    let bracket = |f: &str, g: &str, format: &str| {
        run(
            &["bracket", file, f, g, "--no-timings", "--format", format],
            0,
        )
    };
    let text = bracket("R", "H", "text");
    assert!(
        text.contains("    {R, H} = x p_x + y p_y\n           = ∂H\n"),
        "{text}"
    );
    let text = bracket("H", "p_x", "text");
    assert!(text.contains("= x(t)\n"), "{text}");
    let latex = bracket("R", "H", "latex");
    assert!(latex.contains(r" &= \partial H"), "{latex}");
    assert!(!latex.contains("dH"), "{latex}");
    let json: Value = serde_json::from_str(&bracket("R", "H", "json")).expect("JSON");
    let written = &json["equations"][0]["lines"][0]["in_functions"];
    assert_eq!(
        [&written["text"], &written["ascii"], &written["latex"]],
        ["∂H", "dH", r"\partial H"]
    );
    let table = run(&["table", file, "R", "E", "dH", "xt", "--no-timings"], 0);
    assert!(
        crate::normalize(&table).contains("R │ 0 ∂H 2 R 0"),
        "{table}"
    );
    let latex = run(
        &[
            "table",
            file,
            "R",
            "E",
            "dH",
            "--no-timings",
            "--format",
            "latex",
        ],
        0,
    );
    assert!(latex.contains(r"R & 0 & \partial H & 2 R \\"), "{latex}");
    let apart = run(&["table", file, "dH", "A", "R", "xt", "--no-timings"], 0);
    assert!(
        apart.contains("{∂H, A} = −8 x(t)² + 8 R + 2 A\n"),
        "{apart}"
    );
    let search = run(
        &[
            "search",
            file,
            "--momenta-degree",
            "2",
            "--positions-degree",
            "2",
            "--no-timings",
        ],
        0,
    );
    assert!(search.contains("= b(t)\n"), "{search}");
    let closure = run(&["closure", file, "dH", "xt", "--no-timings"], 0);
    assert!(
        closure.contains("{∂H, x(t)} = −x(t) ") && !closure.contains("stands for"),
        "{closure}"
    );
}

/// A display that holds its function's own name after a differential sign, `∂L` of `L` or
/// `∇H2` of `H2`, is written in LaTeX once, `\partial L^{2}` as the text's `∂L²`, in
/// `expand`'s, `bracket`'s and `check`'s echo of the expressions and in a table's header: the
/// name after the sign was read as the function again, `\partial\partial L^{2}`.
#[test]
fn a_display_holding_its_own_name_is_written_in_latex_once() {
    let file = crate::scratch_text(
        "display-own-name",
        "l.toml",
        "name = \"rotor\"\nhamiltonian = \"p_r^2/2 + p_phi^2/(2*r^2)\"\n\
         [phase_space]\ncoordinates = [\"r\"]\nangles = [\"phi\"]\n\
         [[function]]\nname = \"L\"\ndisplay = \"∂L\"\nvalue = \"p_phi\"\n\
         [[function]]\nname = \"H2\"\ndisplay = \"∇H2\"\nvalue = \"p_r^2 + p_phi\"\n\
         [[claim]]\nclaim = \"{L^2, H} = 0\"\n\
         [[claim]]\nclaim = \"{H2^2, L} = 0\"\n",
    );
    let file = file.to_str().expect("a UTF-8 path");
    let latex = |command: &str, exprs: &[&str]| {
        let mut args = vec![command, file, "--no-timings", "--format", "latex", "--"];
        args.extend(exprs);
        let out = run(&args, 0);
        assert!(
            !out.contains(r"\partial\partial") && !out.contains(r"\nabla\nabla"),
            "{out}"
        );
        out
    };
    let expand = latex("expand", &["L^2", "2*L*H2"]);
    assert!(
        expand.contains(r"(\partial L)^{2} &= p_{\varphi}^{2} \\"),
        "{expand}"
    );
    assert!(
        expand.contains(r"2 (\partial L) \nabla H_{2} &= "),
        "{expand}"
    );
    let bracket = latex("bracket", &["L^2", "H2^2"]);
    assert!(
        bracket.contains(r"\{(\partial L)^{2}, (\nabla H_{2})^{2}\} &= 0"),
        "{bracket}"
    );
    let check = latex("check", &[]);
    assert!(
        check.contains(r"\{(\nabla H_{2})^{2}, \partial L\} &= 0"),
        "{check}"
    );
    let table = latex("table", &["L", "H2"]);
    assert!(table.contains(r"\partial L & 0 & 0 \\"), "{table}");
    // The text and Markdown print the display as written, in parentheses under a power.
    let text = run(&["expand", file, "L^2", "--no-timings"], 0);
    assert!(text.contains("    (∂L)² = p_φ²\n"), "{text}");
    let markdown = run(&["check", file, "--no-timings", "--format", "markdown"], 0);
    assert!(markdown.contains("- `{(∂L)², H} = 0`"), "{markdown}");
}

/// A superscript refused after a power of names run together, `Mω^{2}{}^{3}` of a system
/// file, quotes the factor the power raises, `ω^{2}`, as the lowering reads `M·ω²`: the file's
/// names are read for the message as for the value.
#[test]
fn a_second_superscript_on_names_run_together_quotes_the_last_name_raised() {
    let file = "systems/harmonic-rotor.toml";
    for (src, base) in [("Mω^{2}{}^{3}", "'ω^{2}'"), ("Mω²^3", "'ω²'")] {
        let err = crate::superint_refused(&["expand", file, src]);
        assert!(
            err.contains(&format!(
                " after {base}, which has a superscript already, is ambiguous: "
            )) && err.contains(&format!("; put {base} in parentheses for a power of it")),
            "{src}: {err}"
        );
    }
}

/// A display that begins with `∂` or `∇` takes parentheses where anything follows it in its
/// product, as under a power: `(∂H) x`, `(\partial H) x`, `(∂H)/2`, in an echo and in a
/// result written in the functions (`2 (∂H) R`), where `∂H x` read as `∂(Hx)`; alone or as the
/// last factor, `x ∂H`, it takes none.
#[test]
fn a_differential_display_takes_parentheses_before_a_factor() {
    let file = crate::scratch_text(
        "display-differential-product",
        "d.toml",
        "name = \"oscillator\"\nhamiltonian = \"(p_x^2 + p_y^2)/2 + (x^2 + y^2)/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\n\
         [[function]]\nname = \"dH\"\ndisplay = \"∂H\"\nvalue = \"x*p_x + y*p_y\"\n\
         [[function]]\nname = \"G\"\ndisplay = \"∇G\"\nvalue = \"x*p_y\"\n\
         [[function]]\nname = \"R\"\nvalue = \"(x^2 + y^2)/2\"\n",
    );
    let file = file.to_str().expect("a UTF-8 path");
    let exprs = ["dH*x", "x*dH", "dH", "dH/2", "-dH*G", "G^2*dH"];
    let text = run(
        &[&["expand", file, "--no-timings", "--"][..], &exprs].concat(),
        0,
    );
    for echo in [
        "(∂H) x ",
        "x ∂H ",
        "∂H ",
        "(∂H)/2 ",
        "−(∂H) ∇G ",
        "(∇G)² ∂H ",
    ] {
        assert!(text.contains(&format!("\n    {echo}")), "{echo}: {text}");
    }
    let latex = run(
        &[
            &["expand", file, "--no-timings", "--format", "latex", "--"][..],
            &exprs,
        ]
        .concat(),
        0,
    );
    for echo in [
        r"(\partial H) x &=",
        r"x \partial H &=",
        r"(\partial H)/2 &=",
    ] {
        assert!(latex.contains(echo), "{echo}: {latex}");
    }
    let bracket = |format: &str| {
        run(
            &[
                "bracket",
                file,
                "R^2",
                "H",
                "--no-timings",
                "--format",
                format,
            ],
            0,
        )
    };
    let text = bracket("text");
    assert!(text.contains("= 2 (∂H) R\n"), "{text}");
    let latex = bracket("latex");
    assert!(latex.contains(r"&= 2 (\partial H) R"), "{latex}");
    let last = run(&["bracket", file, "dH^2*R", "H", "--no-timings"], 0);
    assert!(last.contains("= (4 H R + (∂H)² − 8 R²) ∂H\n"), "{last}");
}

/// A --define name that the system reads as a product of its names is refused without the
/// warning of how it reads, which the refusal says: `G1x` was first warned of as the product
/// G1 x, then refused. A text that is accepted (the value `G1x` of another name) still warns.
#[test]
fn cli_a_refused_define_name_is_not_warned_of_first() {
    let refusal = "superint: error: <command line>:1:1: --define: the system reads G1x as a \
                   product of its names; choose another name\n 1 | G1x=x\n   | ^^^\n";
    for system in [
        &["--system", "harmonic"][..],
        &["systems/harmonic-rotor.toml"][..],
    ] {
        let o = superint(&[&["closure"], system, &["G1x", "--define", "G1x=x"]].concat());
        assert_eq!(o.status.code(), Some(2), "{system:?}");
        assert_eq!(stderr(&o), refusal, "{system:?}");
        let o = superint(&[&["closure"], system, &["L", "G1", "--define", "N=G1x"]].concat());
        assert!(
            stderr(&o).starts_with(
                "superint: warning: <command line>:1:3: 'G1x' is read as the product G1 x"
            ),
            "{system:?}: {}",
            stderr(&o)
        );
    }
}

/// Every refusal of `--define` is placed in its text as `--fix`'s and `--known`'s are,
/// `<command line>:1:C: --define:`, then the whole text and a caret under the place: the name
/// that is refused, the expression that does not parse, where it stands after the `=`, and the
/// whole text where it has no `=`, because the name's refusals had no place (`--define x: x is
/// a coordinate of the system`) and the expression was parsed alone, so that its caret stood
/// under the expression as if it were the whole text (`zz` of `C=zz` at column 1, not 3).
#[test]
fn cli_define_refuses_at_its_place_as_fix_does() {
    let cases = [
        (
            "x=p_x",
            "<command line>:1:1: --define: x is a coordinate of the system; choose another \
             name\n 1 | x=p_x\n   | ^\n",
        ),
        (
            " 2Q = L",
            "<command line>:1:2: --define: a name is letters, digits and '_', starting with a \
             letter\n 1 |  2Q = L\n   |  ^^\n",
        ),
        (
            "C= L + zz",
            "<command line>:1:8: --define: unknown name 'zz'",
        ),
        (
            "E=x + (1",
            "<command line>:1:9: --define: expected ')' to close '(' opened at column 7, found \
             end of input\n 1 | E=x + (1\n   |         ^\n",
        ),
        (
            "Ex",
            "<command line>:1:1: --define: give NAME=EXPR, such as C={L, G1}\n 1 | Ex\n   | ^^\n",
        ),
        (
            "=L",
            "<command line>:1:1: --define: a name is missing before this =\n 1 | =L\n   | ^\n",
        ),
        (
            "C= ",
            "<command line>:1:2: --define: an expression is missing after this =\n 1 | C= \n   \
             |  ^\n",
        ),
    ];
    for (define, message) in cases {
        for system in [
            &["systems/harmonic-rotor.toml"][..],
            &["--system", "harmonic"][..],
        ] {
            let o = superint(&[&["closure"], system, &["L", "--define", define]].concat());
            assert_eq!(o.status.code(), Some(2), "{define} {system:?}");
            let got = stderr(&o);
            assert!(
                got.starts_with(&format!("superint: error: {message}")),
                "{define} {system:?}\n{got}"
            );
            assert!(!got.contains("panicked"), "{got}");
        }
    }
}

/// A file and a built-in system keep the command line's warnings by one rule
/// (`system_file::Warnings`): the same said of the same place of the same text once, and two
/// texts, each `<command line>:1:3:`, as two places. A file kept one warning of `G1x` and
/// `G1x + 1`, whose places were both the same, where a built-in system kept two.
#[test]
fn cli_a_file_and_a_built_in_system_keep_the_command_line_s_warnings_alike() {
    for system in [
        &["--system", "harmonic"][..],
        &["systems/harmonic-rotor.toml"][..],
    ] {
        let args = ["L", "G1", "--define", "N=G1x", "--define", "Y=G1x + 1"];
        let o = superint(&[&["closure"], system, &args[..]].concat());
        assert_eq!(o.status.code(), Some(0), "{system:?}: {}", stderr(&o));
        let err = stderr(&o);
        let warnings: Vec<&str> = err.split("superint: warning: ").skip(1).collect();
        assert_eq!(warnings.len(), 2, "{system:?}: {err}");
        for (warning, line) in warnings.iter().zip(["N=G1x", "Y=G1x + 1"]) {
            assert!(
                warning.starts_with("<command line>:1:3: 'G1x' is read as the product G1 x, "),
                "{system:?}: {err}"
            );
            assert!(
                warning.ends_with(&format!(" for the product\n 1 | {line}\n   |   ^^^\n")),
                "{system:?}: {err}"
            );
        }
    }
}

/// A closure's generator shown by a display with a precomposed bar (`Ā_x`, U+0100) prints in
/// the equations as the display is written, as the table and the claims write it, and no
/// note says that it stands for itself: its symbol was `A` and a combining bar, which the note
/// compared with the display and found different, and which the equations printed.
#[test]
fn cli_closure_prints_a_precomposed_bar_as_its_display_writes_it() {
    let file = "systems/anisotropic-3-5-rotor.toml";
    for args in [
        vec!["closure", file, "Ax", "Axbar", "Hx", "--no-timings"],
        vec![
            "closure",
            "--system",
            "anisotropic-3-5",
            "Ax",
            "Axbar",
            "Hx",
            "--no-timings",
        ],
    ] {
        let out = run(&args, 0);
        assert!(!out.contains("stands for"), "{args:?}\n{out}");
        assert!(!out.contains("A\u{304}"), "{args:?}\n{out}");
        for line in [
            "    Ā_x   │ −6iMω      0         −3iω Ā_x\n",
            "    H_x   │ −3iω A_x   3iω Ā_x   0\n",
            "  {Ā_x, H_x} = −3iω Ā_x ",
            "  2M H_x = A_x Ā_x ",
        ] {
            assert!(out.contains(line), "{args:?}: {line}\n{out}");
        }
    }
}

/// Where an unclosed parenthesis of a text given on the command line opens is said alike for
/// a system file and a built-in system, as the parser says it: the column alone on the line of
/// the error, `opened at column 5`, else its line too (a file's text said `opened at line 1,
/// column 5` where a built-in system's said `opened at column 5`).
#[test]
fn cli_an_unclosed_parenthesis_opens_at_the_same_place_for_a_file_and_a_built_in_system() {
    let cases: [(&[&str], &[&str], &str); 4] = [
        (
            &["search"],
            &["--when", "x = (1"],
            "<command line>:1:7: expected ')' to close '(' opened at column 5, found end of \
             input\n 1 | x = (1\n   |       ^\n",
        ),
        (
            &["search"],
            &["--when", "x = 1, M = (2"],
            "<command line>:1:14: expected ')' to close '(' opened at column 12, found end of \
             input\n 1 | x = 1, M = (2\n   |              ^\n",
        ),
        (
            &["closure"],
            &["L", "--define", "E=x + (1"],
            "<command line>:1:9: --define: expected ')' to close '(' opened at column 7, found \
             end of input\n 1 | E=x + (1\n   |         ^\n",
        ),
        (
            &["closure"],
            &["L", "--when", "x = (1\n+ 2"],
            "<command line>:2:4: expected ')' to close '(' opened at line 1, column 5, found \
             end of input\n 2 | + 2\n   |    ^\n",
        ),
    ];
    for (command, rest, message) in cases {
        for system in [
            &["systems/harmonic-rotor.toml"][..],
            &["--system", "harmonic"][..],
        ] {
            let mut args: Vec<&str> = command.to_vec();
            args.extend(system);
            args.extend(rest);
            if command == ["search"] {
                args.extend(DEGREE_ONE_TRIG_ZERO);
            }
            let o = superint(&args);
            assert_eq!(o.status.code(), Some(2), "{args:?}");
            assert_eq!(
                stderr(&o),
                format!("superint: error: {message}"),
                "{args:?}"
            );
        }
    }
}

/// A power whose terms the term limit lets through but the machine cannot hold stops with
/// exit 2 and says so: `(r + p_r + p_phi + M + k + 1)^300` under `--max-terms 10^12`, of
/// 21 281 794 436 terms, reserved room for all of them up front and aborted the process
/// (exit 134, "memory allocation of 340508710976 bytes failed"). The power here has
/// C(12 005, 5) ≈ 2.1·10¹⁸ terms, whose room passes `isize::MAX` bytes, so that the
/// reservation is refused before the allocator is asked and nothing is allocated, whatever
/// the machine's overcommit.
#[test]
fn a_power_too_large_for_memory_stops_with_exit_2() {
    let out = superint_exits(
        &[
            "expand",
            "systems/kepler.toml",
            "(r + p_r + p_phi + M + k + 1)^12000",
            "--max-terms",
            "18000000000000000000",
            "--max-degree",
            "32767",
            "--no-timings",
        ],
        2,
    );
    let err = stderr(&out);
    assert!(
        err.contains(
            "the result would have 2076193224270027401 terms, about 129.7 EiB of memory, more \
             than this machine can hold"
        ),
        "{err}"
    );
    // No larger limit makes room for it: the hint does not say to raise one.
    assert!(
        err.contains("hint: no limit makes room for it: write the expression with smaller powers"),
        "{err}"
    );
    assert!(!err.contains("raise the limit"), "{err}");
}

/// A power whose room is within `isize::MAX` bytes but past the machine's physical memory
/// stops before any work, as one past `isize::MAX` does: the allocator under Linux's
/// overcommit granted `(r + p_r + p_phi + M + k + 1)^300` its 634 GiB of address space, and
/// the power filled memory. The command line caps the room at `MemTotal`; the power here,
/// C(2005, 5) ≈ 2.7·10¹⁴ terms and 17.2 PiB held at once, is past any machine's memory, and
/// past the 128 TiB of address space that x86-64 gives a process too, so that the allocator
/// would refuse it without the cap: this test shows the message and the hint, not that the cap
/// is set (a power within the address space would fill memory where it is lost);
/// `limits::tests::the_command_lines_limits_carry_the_machines_memory` shows that.
#[cfg(target_os = "linux")]
#[test]
fn a_power_past_the_machines_memory_stops_before_any_work() {
    let out = superint_exits(
        &[
            "expand",
            "systems/kepler.toml",
            "(r + p_r + p_phi + M + k + 1)^2000",
            "--max-terms",
            "1000000000000000",
            "--max-degree",
            "2000",
            "--no-timings",
        ],
        2,
    );
    let err = stderr(&out);
    assert!(
        err.contains(
            "the result would have 268672340837901 terms, about 17.2 PiB of memory, more than \
             this machine can hold"
        ),
        "{err}"
    );
    assert!(
        err.contains("hint: no limit makes room for it: write the expression with smaller powers"),
        "{err}"
    );
}

/// A claim whose power is past the machine's memory is undecided, stopped at a limit, with
/// the hint that no limit makes room for it; the file is checked, not refused.
#[test]
fn a_claim_too_large_for_memory_is_undecided_with_its_hint() {
    let file = crate::scratch_text(
        "memory",
        "big.toml",
        "name = \"big\"\nhamiltonian = \"p_x^2/2\"\n[phase_space]\ncoordinates = [\"x\", \"y\", \"z\"]\n\
         [[claim]]\nid = \"big\"\nclaim = \"(x + y + z + p_x + p_y + 1)^12000 = 0\"\n\
         [limits]\nmax_terms = 9000000000000000000\nmax_degree = 32767\n",
    );
    let out = superint_exits(&["check", file.to_str().unwrap(), "--no-timings"], 2);
    let (stdout, err) = (String::from_utf8_lossy(&out.stdout), stderr(&out));
    assert!(stdout.contains("[big UNDECIDED]"), "{stdout}");
    assert!(
        stdout.contains("0 proved, 0 refuted, 1 undecided"),
        "{stdout}"
    );
    assert!(
        err.contains("hint: no limit makes room for it: write the expression with smaller powers"),
        "{err}"
    );
}

/// Checks that `args` stop before anything is loaded, exit 2, saying that `option` stands
/// after `--` and goes before it.
fn stops_with_the_option_after_the_double_dash(args: &[&str], option: &str) {
    let o = superint_exits(args, 2);
    assert_eq!(
        stderr(&o),
        format!(
            "superint: error: '{option}' follows '--', after which every word is read as an \
             expression; put the options before '--'\n"
        ),
        "{args:?}"
    );
}

/// An option written after the `--` that a list of expressions needs (`expand FILE -- -x
/// --no-timings`, as a user appends options) was read as an expression, `−(−(no − timings))`,
/// and refused as "unknown name 'no'", with a caret under the option; it is now said to stand
/// after `--`, with what to do. A word after `--` that is no option of the command (`--x`,
/// minus minus x) is still an expression.
#[test]
fn an_option_after_the_double_dash_is_told_to_go_before_it() {
    let rotor = "systems/harmonic-rotor.toml";
    for (args, option) in [
        (
            vec!["expand", rotor, "--", "-x", "--no-timings"],
            "--no-timings",
        ),
        (
            vec!["expand", rotor, "--", "L", "--format=json"],
            "--format=json",
        ),
        (
            vec!["closure", rotor, "L", "--", "G1", "--degree", "2"],
            "--degree",
        ),
    ] {
        stops_with_the_option_after_the_double_dash(&args, option);
    }
    let o = superint_exits(&["expand", rotor, "--no-timings", "--", "--x"], 0);
    assert!(String::from_utf8_lossy(&o.stdout).contains("−−x = x"));
}

/// The options after `--` that are told to go before it are all those the command takes, as
/// clap builds it: an alias (`--full-residuals` of `--full-expressions`) and `--help` were
/// read as expressions, "unknown name 'full'" and "unknown name 'help'". `--version`, which
/// `expand` does not take, is still an expression there.
#[test]
fn an_alias_or_help_after_the_double_dash_is_told_to_go_before_it() {
    let rotor = "systems/harmonic-rotor.toml";
    for (args, option) in [
        (
            vec!["expand", rotor, "--", "L", "--full-residuals"],
            "--full-residuals",
        ),
        (vec!["rank", rotor, "--", "L", "H", "--help"], "--help"),
    ] {
        stops_with_the_option_after_the_double_dash(&args, option);
    }
    let o = superint_exits(&["expand", rotor, "--", "L", "--version"], 2);
    assert!(
        stderr(&o).contains("unknown name 'version'"),
        "{}",
        stderr(&o)
    );
}

/// `bracket` takes two expressions, so that an option after the `--` before them (`bracket
/// FILE -- L H --no-timings`) made the arguments too many, and clap refused it with its bare
/// "unexpected argument '--no-timings' found"; it is now said to stand after `--`, as
/// `expand`'s is. Expressions after `--` that begin with a minus sign are still expressions.
#[test]
fn an_option_after_the_double_dash_of_bracket_is_told_to_go_before_it() {
    let rotor = "systems/harmonic-rotor.toml";
    for (args, option) in [
        (
            vec!["bracket", rotor, "--", "L", "H", "--no-timings"],
            "--no-timings",
        ),
        (
            vec![
                "bracket",
                rotor,
                "L",
                "--",
                "H",
                "--when",
                "p_theta = I*omega",
            ],
            "--when",
        ),
        (
            vec![
                "bracket",
                "--system",
                "harmonic",
                "--",
                "L",
                "H",
                "--format=json",
            ],
            "--format=json",
        ),
    ] {
        stops_with_the_option_after_the_double_dash(&args, option);
    }
    for args in [
        vec!["bracket", "--no-timings", rotor, "--", "-L", "H"],
        vec!["bracket", "--no-timings", rotor, "-L", "--", "-H"],
        vec![
            "bracket",
            "--no-timings",
            "--system",
            "harmonic",
            "--",
            "-L",
            "H",
        ],
    ] {
        let out = run(&args, 0);
        assert!(out.contains("= 0"), "{args:?}: {out}");
    }
}

/// A command-line argument refused as a whole, rather than at one of its characters, is
/// placed as a refusal at one character is, `<command line>:1:C:` with the argument and a
/// caret under all of it: a name that is no function of a table's file, an expression given
/// to closure as a generator, and a `--from` that leaves a variable without its value were
/// said with no place (`<command line>: 'z' is not a function of …`).
#[test]
fn an_argument_refused_as_a_whole_is_underlined_whole() {
    let rotor = "systems/harmonic-rotor.toml";
    let out = scratch_file("whole.svg");
    let from = "x = 1, y = 0, p_x = 0, p_y = 1";
    for (args, message, excerpt, caret) in [
        (
            vec!["table", rotor, "L", "zz"],
            "<command line>:1:1: 'zz' is not a function of systems/harmonic-rotor.toml",
            "zz",
            "^^",
        ),
        (
            vec!["table", "--system", "harmonic", "L+H"],
            "<command line>:1:1: 'L+H' is not a function of --system harmonic",
            "L+H",
            "^^^",
        ),
        (
            vec!["closure", rotor, "L", "2*L", "--degree", "2"],
            "<command line>:1:1: '2*L' is an expression, not the name of a function",
            "2*L",
            "^^^",
        ),
        (
            vec![
                "plot",
                rotor,
                "L",
                "--at",
                "M = 1, omega = 1, I = 1",
                "--time",
                "1",
                "-o",
                out.to_str().unwrap(),
                "--from",
                from,
            ],
            "<command line>:1:1: --from gives no value for θ, p_θ",
            from,
            "^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^",
        ),
    ] {
        let err = stderr(&superint_exits(&args, 2));
        let lines: Vec<&str> = err.lines().collect();
        assert!(
            lines[0].starts_with(&format!("superint: error: {message}")),
            "{args:?}: {err}"
        );
        assert_eq!(lines[1], format!(" 1 | {excerpt}"), "{args:?}: {err}");
        assert_eq!(lines[2], format!("   | {caret}"), "{args:?}: {err}");
    }
}
