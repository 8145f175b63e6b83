//! System files, through the real binary: every file of `systems/` checks as expected, the
//! example of `docs/system-files.md` works as documented, every output format holds together,
//! and every kind of bad input gets its message (file, line, column, caret) and exit status 2.
//!
//! The messages of bad inputs are compared whole with `tests/it/snapshots/bad-inputs.txt`;
//! after an intended change, rewrite it with
//! `SUPERINT_UPDATE_SNAPSHOTS=1 cargo test --test it system_files`, and read the diff.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use pretty_assertions::assert_eq;
use serde_json::Value;

use crate::superint_in;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8(bytes.to_vec()).expect("UTF-8 output")
}

/// Runs the binary at the workspace root and expects exit status `code`; returns stdout.
#[track_caller]
fn run(args: &[&str], code: i32) -> String {
    let o = superint_in(root(), args);
    assert_eq!(
        o.status.code(),
        Some(code),
        "superint {args:?}\nstdout: {}\nstderr: {}",
        text(&o.stdout),
        text(&o.stderr)
    );
    text(&o.stdout)
}

/// A fresh directory for one test's files.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("system-files")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a scratch directory");
    dir
}

/// Compares with a snapshot, or rewrites it when `SUPERINT_UPDATE_SNAPSHOTS` is set.
#[track_caller]
fn assert_snapshot(name: &str, actual: &str) {
    let path = root().join("tests/it/snapshots").join(name);
    if std::env::var_os("SUPERINT_UPDATE_SNAPSHOTS").is_some() {
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

/// Every file of `systems/`, sorted.
fn system_files() -> Vec<String> {
    let mut files: Vec<String> = std::fs::read_dir(root().join("systems"))
        .expect("systems/ exists")
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| format!("systems/{}", p.file_name().unwrap().to_string_lossy()))
        .collect();
    files.sort();
    files
}

#[test]
fn systems_every_file_checks_as_expected() {
    let files = system_files();
    assert!(files.len() >= 7, "systems/ has only {files:?}");
    let mut args = vec!["check", "--no-timings"];
    args.extend(files.iter().map(String::as_str));
    let out = run(&args, 0);
    let last = out.lines().last().expect("a summary line");
    assert!(last.ends_with("; all as expected"), "{last}");
    assert!(!out.contains("REFUTED") && !out.contains("PROVED"), "{out}");
    // No name of theirs run together is read in doubt (their products, written with `*`, and
    // those the echo reads back, `Mω²x`, `iMωx`, are read without a word).
    assert!(!out.contains("Warning:"), "{out}");
    // Each file declares deliberately false claims, and they are refuted.
    for f in &files {
        let json = run(&["check", f, "--format", "json", "--no-timings"], 0);
        let v: Value = serde_json::from_str(&json).expect("JSON");
        assert_eq!(v.get("warnings"), None, "{f}");
        let refuted = v["claims"]
            .as_array()
            .expect("claims")
            .iter()
            .filter(|c| c["expect"] == "refuted" && c["outcome"] == "refuted")
            .count();
        assert!(refuted >= 1, "{f} has no deliberately false claim");
    }
}

/// A system whose texts run names together: the function `Lz` with `x` after it (in a
/// function's value, `Lzx^2`), `omegaa` (its `a` doubled) and `Axx` beside `A_xx`, each read
/// as the product, and the physics products `aLz`, `xp_y`, `omegax`, read without a word.
const RUN_TOGETHER: &str = r#"name = "run together"
hamiltonian = "p_x^2/2 + p_y^2/2 + omega^2*(x^2 + y^2)/2"

[phase_space]
coordinates = ["x", "y"]
parameters = ["omega", "a", "A"]

[[function]]
name = "Lz"
display = "L_z"
value = "x*p_y - y*p_x"

[[function]]
name = "A_xx"
value = "p_x^2/2 + omega^2*x^2/2"

[[function]]
name = "B"
value = "Lzx^2"

[[claim]]
id = "physics"
claim = "aLz + xp_y*omegax = a*Lz + x*p_y*omega*x"

[[claim]]
id = "doubled"
claim = "omegaa = a*omega"

[[claim]]
id = "close"
claim = "{Axx, H} = 2*A*x*p_x"
"#;

/// The line and column of the first `name` after `after` in `text`, 1-based, in characters.
fn line_column(text: &str, after: &str, name: &str) -> (usize, usize) {
    let at = text.find(after).expect("the text")
        + text[text.find(after).unwrap()..]
            .find(name)
            .expect("the name");
    let line_start = text[..at].rfind('\n').map_or(0, |k| k + 1);
    (
        text[..at].matches('\n').count() + 1,
        text[line_start..at].chars().count() + 1,
    )
}

/// A name that is not declared and splits into declared names is read as their product, and
/// where that reading is in doubt, check says so in its report, with the place in the file,
/// in every format (a paragraph before the claims; the JSON's `warnings`): the claims are
/// checked with the product (all proved), and the exit status is 0.
#[test]
fn names_run_together_in_doubt_are_warned_with_their_place() {
    let dir = scratch("run-together-check");
    std::fs::write(dir.join("rt.toml"), RUN_TOGETHER).expect("written");
    let o = superint_in(&dir, &["check", "rt.toml", "--no-timings"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert_eq!(text(&o.stderr), "");
    let out = text(&o.stdout);
    let place = |after: &str, name: &str| {
        let (line, column) = line_column(RUN_TOGETHER, after, name);
        format!("(line {line}, column {column})")
    };
    let expected = [
        format!(
            "Warning: 'Lzx' {} is read as the product L_z x, the function Lz with x after it: \
             declare 'Lzx' if it is a name of its own, or write 'Lz x' for the product",
            place("value = \"Lzx", "Lzx")
        ),
        format!(
            "Warning: 'omegaa' {} is read as the product ω a, with its a doubled: declare \
             'omegaa' if it is a name of its own, or write 'omega a' for the product",
            place("claim = \"omegaa", "omegaa")
        ),
        format!(
            "Warning: 'Axx' {} is read as the product A x x, though it is close to the declared \
             name A_xx: declare 'Axx' if it is a name of its own, or write 'A x x' for the \
             product",
            place("claim = \"{Axx", "Axx")
        ),
    ];
    assert!(
        crate::normalize(&out).contains(&expected.join(" ")),
        "{out}"
    );
    assert!(
        out.ends_with("3 claims in 1 file: 3 proved, 0 refuted; all as expected\n"),
        "{out}"
    );
    // Before the claims, after the Hamiltonian.
    assert!(out.find("Warning:") < out.find("[physics proved]"), "{out}");
    // In JSON, each with its file, line and column.
    let json = superint_in(
        &dir,
        &["check", "rt.toml", "--format", "json", "--no-timings"],
    );
    let v: Value = serde_json::from_str(&text(&json.stdout)).expect("JSON");
    let warnings = v["warnings"].as_array().expect("warnings");
    let places: Vec<(usize, usize)> = warnings
        .iter()
        .map(|w| {
            assert_eq!(
                (&w["file"], &w["section"]),
                (&Value::from("rt.toml"), &Value::from(1))
            );
            (
                w["line"].as_u64().unwrap() as usize,
                w["column"].as_u64().unwrap() as usize,
            )
        })
        .collect();
    assert_eq!(
        places,
        [
            line_column(RUN_TOGETHER, "value = \"Lzx", "Lzx"),
            line_column(RUN_TOGETHER, "claim = \"omegaa", "omegaa"),
            line_column(RUN_TOGETHER, "claim = \"{Axx", "Axx"),
        ]
    );
    assert!(warnings[2]["message"].as_str().unwrap().starts_with(
        "'Axx' is read as the product A x x, though it is close to the declared name A_xx"
    ));
    // Markdown and LaTeX carry them too, the product as a formula.
    let md = superint_in(
        &dir,
        &["check", "rt.toml", "--format", "markdown", "--no-timings"],
    );
    assert!(
        text(&md.stdout).contains("**Warning:** 'Lzx' ("),
        "{}",
        text(&md.stdout)
    );
    assert!(text(&md.stdout).contains("is read as the product `L_z x`"));
    let tex = superint_in(
        &dir,
        &["check", "rt.toml", "--format", "latex", "--no-timings"],
    );
    assert!(
        text(&tex.stdout).contains(r"\textbf{Warning:} 'Lzx' ("),
        "{}",
        text(&tex.stdout)
    );
    assert!(text(&tex.stdout).contains("is read as the product $L_{z} x$"));
}

/// A long run of names, 30 000 of them, is echoed as the product it reads as: the echo's
/// tree of the product was left-deep, one level a name, and its printing overflowed the stack
/// (`claim = "abab…ab = a^15000*b^15000"` aborted the process), where the parser's tree of
/// any sum is about `log₂ n` high.
#[test]
fn a_long_run_of_names_is_echoed_without_overflowing_the_stack() {
    let dir = scratch("long-run");
    let run = "ab".repeat(15_000);
    std::fs::write(
        dir.join("long.toml"),
        format!(
            "name = \"long run\"\nhamiltonian = \"p_x^2\"\n[limits]\nmax_degree = 32767\n\
             [phase_space]\ncoordinates = [\"x\"]\nparameters = [\"a\", \"b\"]\n\
             [[claim]]\nclaim = \"{run} = a^15000*b^15000\"\n"
        ),
    )
    .expect("written");
    let o = superint_in(&dir, &["check", "long.toml", "--no-timings"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert!(out.contains(&format!("  {run}\n")), "{out}");
    assert!(out.contains("= a¹⁵⁰⁰⁰b¹⁵⁰⁰⁰  [#1 proved]"), "{out}");
}

/// The other commands say on standard error what their file's texts and the expressions given
/// on the command line read in doubt, each with its place, line and caret, and go on with
/// the product; the physics products of the command line are read without a word.
#[test]
fn other_commands_warn_of_names_run_together_on_standard_error() {
    let dir = scratch("run-together-commands");
    std::fs::write(dir.join("rt.toml"), RUN_TOGETHER).expect("written");
    let o = superint_in(&dir, &["bracket", "rt.toml", "x + Lzy", "H"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(
        text(&o.stdout).contains("{x + L_z y, H}"),
        "{}",
        text(&o.stdout)
    );
    let (line, column) = line_column(RUN_TOGETHER, "value = \"Lzx", "Lzx");
    assert_eq!(
        text(&o.stderr),
        format!(
            "superint: warning: rt.toml:{line}:{column}: 'Lzx' is read as the product L_z x, the \
             function Lz with x after it: declare 'Lzx' if it is a name of its own, or write 'Lz \
             x' for the product\n {line} | value = \"Lzx^2\"\n    |          ^^^\n\
             superint: warning: <command line>:1:5: 'Lzy' is read as the product L_z y, the \
             function Lz with y after it: declare 'Lzy' if it is a name of its own, or write 'Lz \
             y' for the product\n 1 | x + Lzy\n   |     ^^^\n"
        )
    );
    // A run that ends with an error says them too, before the error: they were left out.
    let file_warning = format!("superint: warning: rt.toml:{line}:{column}: 'Lzx'");
    for args in [
        vec!["expand", "rt.toml", "Lzy + 1/(x + 1)"],
        vec!["bracket", "rt.toml", "Lzy", "x^2000", "--max-degree", "10"],
        vec!["rank", "rt.toml", "Lzy", "1/(x + 1)"],
        vec!["closure", "rt.toml", "Lz", "--define", "Q=Lzy/(x + 1)"],
        vec!["search", "rt.toml", "--new-only", "--known", "Lzy/(x + 1)"],
    ] {
        let o = superint_in(&dir, &args);
        let stderr = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {stderr}");
        // The name's column in the text as typed: after `Q=` in --define's.
        let column = if args[0] == "closure" { 3 } else { 1 };
        let warned = stderr.find(&format!(
            "superint: warning: <command line>:1:{column}: 'Lzy'"
        ));
        let failed = stderr.find("superint: error:");
        assert!(
            stderr.starts_with(&file_warning) && warned.is_some() && warned < failed,
            "{args:?}: {stderr}"
        );
    }
    // Products a physicist writes, and the file's own: nothing said.
    let plain = "name = \"plain\"\nhamiltonian = \"p_x^2/(2*M) + M*omega^2*x^2/2\"\n\
                 [phase_space]\ncoordinates = [\"x\"]\nangles = [\"theta\"]\n\
                 parameters = [\"M\", \"omega\", \"I\"]\n";
    std::fs::write(dir.join("plain.toml"), plain).expect("written");
    for (f, g) in [("Mω²x", "Iω p_theta"), ("iMωx + 2Mω", "exp(iθ)*p_x")] {
        let o = superint_in(&dir, &["bracket", "plain.toml", f, g]);
        assert_eq!(
            (o.status.code(), text(&o.stderr)),
            (Some(0), String::new()),
            "{f}, {g}"
        );
    }
}

/// Two one-letter names run together where a declared name of two letters differs in the
/// last alone are warned of, the product read (`Hy` beside a function `Hx` is `H·y`, where
/// `Hy` was likely left undeclared; `Lx` beside `L` and `Ly` is `L·x`); `xy`, `Mω` and `Lx`
/// beside a function `L` alone are products without a word.
#[test]
fn two_letters_beside_a_declared_name_of_the_same_first_are_warned_of() {
    let dir = scratch("run-together-same-first");
    let file = |name: &str, functions: &[(&str, &str)]| {
        let declared: String = functions
            .iter()
            .map(|(f, value)| format!("\n[[function]]\nname = \"{f}\"\nvalue = \"{value}\"\n"))
            .collect();
        let text = format!(
            "name = \"{name}\"\nhamiltonian = \"(p_x^2 + p_y^2)/2\"\n\n[phase_space]\n\
             coordinates = [\"x\", \"y\"]\nparameters = [\"M\", \"omega\"]\n{declared}"
        );
        std::fs::write(dir.join(format!("{name}.toml")), text).expect("written");
    };
    file("trap", &[("Hx", "p_x^2/2")]);
    file("noise", &[("L", "x*p_y - y*p_x"), ("Ly", "y*p_x")]);
    file("alone", &[("L", "x*p_y - y*p_x")]);
    let warned = |args: &[&str]| {
        let o = superint_in(&dir, args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", text(&o.stderr));
        (text(&o.stdout), text(&o.stderr))
    };
    let (out, err) = warned(&["bracket", "trap.toml", "Hy", "x"]);
    assert!(out.contains("{H y, x}"), "{out}");
    assert_eq!(
        err,
        "superint: warning: <command line>:1:1: 'Hy' is read as the product H y, though the \
         declared name Hx differs from it in its last letter alone: declare 'Hy' if it is a name \
         of its own, or write 'H y' for the product\n 1 | Hy\n   | ^^\n"
    );
    let (_, err) = warned(&["bracket", "noise.toml", "Lx", "x"]);
    assert!(
        err.starts_with(
            "superint: warning: <command line>:1:1: 'Lx' is read as the product L x, though the \
             declared name Ly differs from it in its last letter alone: declare 'Lx' if it is a \
             name of its own, or write 'L x' for the product\n"
        ),
        "{err}"
    );
    for file in ["trap.toml", "noise.toml", "alone.toml"] {
        assert_eq!(warned(&["bracket", file, "xy + Mω", "x"]).1, "", "{file}");
    }
    assert_eq!(warned(&["bracket", "alone.toml", "Lx", "Mω"]).1, "");
}

/// [`RUN_TOGETHER`] with a function after `Lzx` that names an unknown `q`: the load fails
/// after the warning of `Lzx`.
fn failing_run_together() -> String {
    RUN_TOGETHER.replacen(
        "[[claim]]",
        "[[function]]\nname = \"C\"\nvalue = \"q + 1\"\n\n[[claim]]",
        1,
    )
}

/// A file that fails to load says what its texts read in doubt before the error, as a run that
/// fails after loading does: the warning of `Lzx`, read before the unknown name of a later
/// function stopped the load, was left out, as the file that kept it was not returned.
#[test]
fn a_file_that_fails_to_load_says_its_warnings_before_the_error() {
    let dir = scratch("run-together-failed-load");
    let failing = failing_run_together();
    std::fs::write(dir.join("rt.toml"), &failing).expect("written");
    let (line, column) = line_column(&failing, "value = \"Lzx", "Lzx");
    let warning = format!(
        "superint: warning: rt.toml:{line}:{column}: 'Lzx' is read as the product L_z x, the \
         function Lz with x after it: declare 'Lzx' if it is a name of its own, or write 'Lz x' \
         for the product\n {line} | value = \"Lzx^2\"\n    |          ^^^\n"
    );
    let (line, column) = line_column(&failing, "value = \"q", "q");
    let error = format!("superint: error: rt.toml:{line}:{column}: unknown name 'q'");
    for args in [
        vec!["check", "rt.toml", "--no-timings"],
        vec!["expand", "rt.toml", "x"],
        vec!["bracket", "rt.toml", "x", "H"],
    ] {
        let o = superint_in(&dir, &args);
        let stderr = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.starts_with(&format!("{warning}{error}")),
            "{args:?}: {stderr}"
        );
    }
}

/// `check` of several files that fail to load says each file's warnings right before its
/// error: it loads them all before it prints any error, and the warnings printed at the load
/// put the second file's before the first file's error.
#[test]
fn check_says_each_failed_file_s_warnings_before_its_own_error() {
    let dir = scratch("run-together-failed-loads");
    let failing = failing_run_together();
    std::fs::write(dir.join("a.toml"), &failing).expect("written");
    std::fs::write(dir.join("b.toml"), &failing).expect("written");
    let o = superint_in(&dir, &["check", "a.toml", "b.toml", "--no-timings"]);
    let stderr = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    let said: Vec<&str> = stderr
        .lines()
        .filter(|l| l.starts_with("superint: "))
        .map(|l| &l[..l.find(".toml").map_or(l.len(), |k| k + 5)])
        .collect();
    assert_eq!(
        said,
        [
            "superint: warning: a.toml",
            "superint: error: a.toml",
            "superint: warning: b.toml",
            "superint: error: b.toml",
        ],
        "{stderr}"
    );
}

/// The JSON report of `check` gives a failed file's warnings in its error, as stderr says them
/// before it: a script that reads the JSON saw the error alone.
#[test]
fn check_json_errors_carry_the_failed_file_s_warnings() {
    let dir = scratch("run-together-failed-load-json");
    let failing = failing_run_together();
    std::fs::write(dir.join("rt.toml"), &failing).expect("written");
    std::fs::write(dir.join("ok.toml"), RUN_TOGETHER).expect("written");
    let o = superint_in(
        &dir,
        &[
            "check",
            "ok.toml",
            "rt.toml",
            "--format",
            "json",
            "--no-timings",
        ],
    );
    assert_eq!(o.status.code(), Some(2), "{}", text(&o.stderr));
    let v: Value = serde_json::from_slice(&o.stdout).expect("one JSON document");
    let (line, column) = line_column(&failing, "value = \"Lzx", "Lzx");
    let error = &v["errors"][0];
    assert_eq!(error["file"], "rt.toml", "{error}");
    let warnings = error["warnings"].as_array().expect("the error's warnings");
    assert_eq!(warnings.len(), 1, "{error}");
    let w = &warnings[0];
    assert_eq!(
        (&w["file"], &w["line"], &w["column"]),
        (
            &serde_json::json!("rt.toml"),
            &serde_json::json!(line),
            &serde_json::json!(column)
        ),
        "{w}"
    );
    assert!(
        w["message"]
            .as_str()
            .is_some_and(|m| m.starts_with("'Lzx' is read as the product")),
        "{w}"
    );
    // The loaded file's own warnings are the same shape, with their section.
    let loaded = &v["warnings"][0];
    assert_eq!(loaded["file"], "ok.toml", "{loaded}");
    assert_eq!(loaded["message"], w["message"], "{loaded}");
}

#[test]
fn systems_paper_claims_are_all_there() {
    let mut ids = Vec::new();
    for f in system_files() {
        let v: Value =
            serde_json::from_str(&run(&["check", &f, "--format", "json", "--no-timings"], 0))
                .expect("JSON");
        for c in v["claims"].as_array().expect("claims") {
            ids.push(c["id"].as_str().expect("an id").to_string());
        }
    }
    for k in 4..=26 {
        let id = format!("C{k:02}");
        assert!(ids.contains(&id), "{id} is in no system file");
    }
}

/// The complete example of `docs/system-files.md` checks as the document shows.
#[test]
fn docs_example_checks_as_documented() {
    let doc = std::fs::read_to_string(root().join("docs/system-files.md")).expect("the doc");
    let start = doc.find("```toml\n").expect("a TOML example") + "```toml\n".len();
    let example = &doc[start..start + doc[start..].find("```").expect("its end")];
    let dir = scratch("docs-example");
    std::fs::write(dir.join("rotor.toml"), example).expect("write the example");
    let o = superint_in(&dir, &["check", "rotor.toml", "--no-timings"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert_snapshot("system-file-example.txt", &out);
    // The document shows the same output (with the timing).
    let shown = doc
        .split("```console\n$ superint check rotor.toml\n")
        .nth(1)
        .expect("the output in the doc");
    let shown = &shown[..shown.find("```").expect("its end")];
    let body = |s: &str| s.lines().rev().skip(1).collect::<Vec<_>>().join("\n");
    assert_eq!(body(shown), body(&out));
}

/// The error examples of `docs/system-files.md` are what `check` prints for the document's
/// example file with, in turn, each of these appended (they had drifted: a missing hint, the
/// carets, a limit the file did not set, line numbers of another file).
#[test]
fn docs_error_examples_are_what_check_prints() {
    let doc = std::fs::read_to_string(root().join("docs/system-files.md")).expect("the doc");
    let start = doc.find("```toml\n").expect("a TOML example") + "```toml\n".len();
    let example = &doc[start..start + doc[start..].find("```").expect("its end")];
    let appended = [
        "\n[[claim]]\nclaim = \"{L, G1} = -G3\"\n",
        "\n[[function]]\nname = \"D\"\nvalue = \"x/(1+y)\"\n",
        "\n[[claim]]\nclaim = \"{L, omega} = -G2\"\n",
        "\n[[claim]]\nclam = \"{L, G1} = -G2\"\n",
        "\n[limits]\nmax_terms = 10000\n\n[[claim]]\n\
         claim = \"(x + y + p_x + p_y + M + omega)^400 = 0\"\n",
    ];
    let shown: Vec<&str> = doc
        .split("```text\n")
        .skip(1)
        .map(|b| &b[..b.find("```").expect("the block's end")])
        .filter(|b| b.starts_with("superint: error: rotor.toml:"))
        .collect();
    assert_eq!(shown.len(), appended.len(), "one example for each");
    let dir = scratch("docs-errors");
    for (tail, shown) in appended.iter().zip(shown) {
        std::fs::write(dir.join("rotor.toml"), format!("{example}{tail}")).expect("write");
        let o = superint_in(&dir, &["check", "rotor.toml"]);
        assert_eq!(o.status.code(), Some(2), "{tail}");
        assert_eq!(text(&o.stderr), shown, "{tail}");
    }
}

/// The warnings of `docs/system-files.md` for names run together are what `check` prints for
/// the document's example file with a claim appended, and what `bracket` prints on standard
/// error for an expression of the command line.
#[test]
fn docs_run_together_examples_are_what_superint_prints() {
    let doc = std::fs::read_to_string(root().join("docs/system-files.md")).expect("the doc");
    let start = doc.find("```toml\n").expect("a TOML example") + "```toml\n".len();
    let example = &doc[start..start + doc[start..].find("```").expect("its end")];
    let shown = |starting: &str| {
        let blocks = doc.split("```text\n").skip(1);
        let mut found = blocks
            .map(|b| &b[..b.find("```").expect("the block's end")])
            .filter(|b| b.starts_with(starting));
        let block = found.next().expect("the example");
        assert_eq!(found.next(), None, "one example");
        block.to_string()
    };
    let dir = scratch("docs-run-together");
    let appended = "\n[[claim]]\nclaim = \"{L, G1x} = G1*y - G2*x\"\n";
    assert!(doc.contains("`claim = \"{L, G1x} = G1*y - G2*x\"`"));
    std::fs::write(dir.join("rotor.toml"), format!("{example}{appended}")).expect("write");
    let o = superint_in(&dir, &["check", "rotor.toml", "--no-timings"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stdout));
    let out = text(&o.stdout);
    let warning = shown("Warning: 'G1x'");
    assert!(out.contains(&format!("\n\n{warning}\n")), "{out}");
    let o = superint_in(&dir, &["bracket", "rotor.toml", "x + G1y", "H"]);
    assert_eq!(o.status.code(), Some(0));
    assert!(doc.contains("`superint bracket rotor.toml 'x + G1y' H` prints\n`{x + G1 y, H}`"));
    assert!(
        text(&o.stdout).contains("{x + G1 y, H}"),
        "{}",
        text(&o.stdout)
    );
    assert_eq!(
        text(&o.stderr),
        shown("superint: warning: <command line>:1:5: 'G1y'")
    );
}

/// The declared brackets' example of `docs/system-files.md` checks, and its error examples are
/// what `check` prints for it with, in turn, its last bracket replaced by each of these.
#[test]
fn docs_poisson_error_examples_are_what_check_prints() {
    let doc = std::fs::read_to_string(root().join("docs/system-files.md")).expect("the doc");
    let start = doc
        .find("```toml\n# The free rigid body on so(3)*.")
        .expect("the declared brackets' example")
        + "```toml\n".len();
    let example = &doc[start..start + doc[start..].find("```").expect("its end")];
    let dir = scratch("docs-poisson");
    std::fs::write(dir.join("top.toml"), example).expect("write");
    let o = superint_in(&dir, &["check", "top.toml", "--no-timings"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stdout));
    assert!(text(&o.stdout).contains("2 claims in 1 file: 2 proved"));
    let last = "\"{M3, M1}\" = \"M2\"";
    let replaced = [
        "\"{M3, M1}\" = \"M1\"",
        "\"{M2, M1}\" = \"-M3\"",
        "\"{M3, N}\" = \"M2\"",
        "\"{M3, I1}\" = \"M2\"",
    ];
    let shown: Vec<&str> = doc
        .split("```text\n")
        .skip(1)
        .map(|b| &b[..b.find("```").expect("the block's end")])
        .filter(|b| b.starts_with("superint: error: top.toml:"))
        .collect();
    assert_eq!(shown.len(), replaced.len(), "one example for each");
    for (line, shown) in replaced.iter().zip(shown) {
        assert!(example.contains(last));
        std::fs::write(dir.join("top.toml"), example.replacen(last, line, 1)).expect("write");
        let o = superint_in(&dir, &["check", "top.toml"]);
        assert_eq!(o.status.code(), Some(2), "{line}");
        assert_eq!(text(&o.stderr), shown, "{line}");
    }
}

const BASE: &str = r#"name = "oscillator"
hamiltonian = "p_x^2/(2*M) + M*omega^2*x^2/2"

[phase_space]
coordinates = ["x"]
parameters = ["M", "omega"]

[[function]]
name = "A"
value = "p_x + i*M*omega*x"

[[claim]]
id = "ladder"
claim = "{A, H} = i*omega*A"
"#;

/// so(3)* beside a canonical pair: the Poisson variables' bad inputs replace line 12, the
/// last of its brackets (`{M3, M1} = M2`).
const TOP: &str = concat!(
    r#"name = "top"
hamiltonian = "M1^2/2 + M2^2/2 + M3^2 + p_x^2/2"

[phase_space]
coordinates = ["x"]
variables = ["M1", "M2", "M3"]
parameters = ["a"]

"#,
    so3_poisson!(),
    r#"
[[claim]]
claim = "{M1^2 + M2^2 + M3^2, H} = 0"
"#
);

fn top_with(line_12: &str) -> Vec<u8> {
    TOP.replacen("\"{M3, M1}\" = \"M2\"", line_12, 1)
        .into_bytes()
}

/// The rotor's variables and a power that no machine can expand: C(405, 5) ≈ 9·10¹⁰ terms.
const HUGE: &str = r#"name = "runaway"
hamiltonian = "(p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2 + p_theta^2/(2*I)"

[phase_space]
coordinates = ["x", "y"]
angles = ["theta"]
parameters = ["M", "omega", "I"]

[limits]
max_terms = 10000

[[claim]]
id = "runaway"
claim = "(x + y + p_x + p_y + M + omega)^400 = 0"
"#;

/// `HUGE` with a work limit of 1000 term products, and a claim whose product forms 35 · 35.
fn work() -> Vec<u8> {
    HUGE.replace("max_terms = 10000", "max_term_products = 1000")
        .replace(
            "(x + y + p_x + p_y + M + omega)^400",
            "(1 + x + y + p_x)^4*(1 - x + y - p_y)^4",
        )
        .into_bytes()
}

/// `BASE` with `from` replaced by `to` (which must occur).
fn base_with(from: &str, to: &str) -> Vec<u8> {
    assert!(BASE.contains(from), "{from:?}");
    BASE.replacen(from, to, 1).into_bytes()
}

/// The display names a file may not give, on `BASE`'s function `A` (line 10): the case, the
/// display as the file writes it, the column the message points at, and why.
const BAD_DISPLAY_NAMES: [(&str, &str, usize, &str); 25] = [
    (
        "display name with markup",
        "a^b^c",
        13,
        "'^' is markup in Markdown or LaTeX",
    ),
    (
        "display name empty",
        "",
        11,
        "this one is empty (leave display out to show the name)",
    ),
    (
        "display name with a subscript of a subscript",
        "a__b",
        13,
        SUBSCRIPT_OF_NOTHING,
    ),
    (
        "display name ending in a subscript of nothing",
        "A_x_",
        15,
        SUBSCRIPT_OF_NOTHING,
    ),
    (
        "display name with a tab",
        "A\t1",
        13,
        "U+0009 is an invisible or control character",
    ),
    // The right-to-left override turns the text after it around: the label `A2` would show
    // as another; the excerpt shows it as U+FFFD.
    (
        "display name with a right-to-left override",
        "A\u{202e}2",
        13,
        "U+202E is an invisible or control character",
    ),
    (
        "display name escaping a zero-width space",
        "A\\u200B",
        13,
        "U+200B is an invisible or control character",
    ),
    (
        "display name beginning with a space",
        " A",
        12,
        "it begins or ends with a space",
    ),
    (
        "display name with a Cyrillic letter",
        "Lщ",
        13,
        "LaTeX has no letter 'щ' ",
    ),
    (
        "display name with an accented letter",
        "Lé",
        13,
        "LaTeX has no letter 'é' ",
    ),
    (
        "display name with an emoji",
        "😀",
        12,
        "LaTeX has no letter U+1F600 ",
    ),
    (
        "display name with an arrow over a letter",
        "L\u{20d7}",
        13,
        "LaTeX has no letter U+20D7 ",
    ),
    (
        "display name with a blank braille pattern",
        "a\u{2800}b",
        13,
        "LaTeX has no letter U+2800 ",
    ),
    // A display that begins with no letter printed as a mark (`{₊, H}`), a number (`{2, H}`,
    // the bracket of 2) or a product (`2x`); one with a parenthesis unclosed as a piece of an
    // expression's (`{x(, H}`).
    (
        "display name a subscript sign alone",
        "₊",
        12,
        "it begins with '₊', a subscript, not with a letter",
    ),
    // A letter written as a subscript or superscript is a Unicode letter, but prints under or
    // over what stands before it: it was refused as no letter LaTeX has, and `₁x` as no letter.
    (
        "display name beginning with a subscript letter",
        "ₐx",
        12,
        "it begins with 'ₐ', a subscript, not with a letter",
    ),
    (
        "display name beginning with a superscript letter",
        "ᵃx",
        12,
        "it begins with 'ᵃ', a superscript, not with a letter",
    ),
    (
        "display name beginning with a subscript digit",
        "₁x",
        12,
        "it begins with '₁', a subscript, not with a letter",
    ),
    // `∂` and `∇` begin a display, right before a letter (`∂H`, `∇φ`), and nowhere else.
    (
        "display name a partial sign alone",
        "∂",
        12,
        "'∂' stands first, right before the letter of what it applies to (∂H, ∇φ)",
    ),
    (
        "display name with a nabla after a letter",
        "x∇",
        13,
        "'∇' stands first, right before the letter of what it applies to (∂H, ∇φ)",
    ),
    (
        "display name a number",
        "2",
        12,
        "it begins with '2', not with a letter",
    ),
    (
        "display name with a parenthesis never closed",
        "x(t",
        13,
        "this '(' is never closed",
    ),
    (
        "display name with a parenthesis never opened",
        "x)",
        13,
        "this ')' closes no '('",
    ),
    ("display name a lone bar", "\u{304}", 12, BAR),
    (
        "display name with a bar over a subscript",
        "a_\u{304}",
        14,
        BAR,
    ),
    (
        "display name with a bar inside a word",
        "Z\u{304}x",
        13,
        BAR,
    ),
];

/// A display that is a derivative or a gradient, `∂H`, `∇φ`, takes a power in parentheses,
/// `(∂H)²`, in an echo and in a result, in text and in LaTeX: `∂H²` and `\partial H^{2}` read
/// as the derivative of `H²`.
#[test]
fn a_power_of_a_derivative_display_is_set_in_parentheses() {
    let dir = scratch("display-differential-powers");
    let file = "name = \"signs\"\nhamiltonian = \"p_x^2/2 + p_y^2/2\"\n\n[phase_space]\n\
                coordinates = [\"x\", \"y\"]\n\n[[function]]\nname = \"G\"\n\
                display = \"∇φ\"\nvalue = \"x*p_x\"\n\n[[function]]\nname = \"dH\"\n\
                display = \"∂H\"\nvalue = \"p_x\"\n";
    std::fs::write(dir.join("signs.toml"), file).expect("written");
    let run = |args: &[&str]| {
        let o = superint_in(&dir, args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", text(&o.stderr));
        text(&o.stdout)
    };
    let echo = run(&["expand", "signs.toml", "dH^2*G", "--no-timings"]);
    assert!(echo.contains("    (∂H)² ∇φ = x p_x³\n"), "{echo}");
    let bracket = run(&["bracket", "signs.toml", "G", "H", "--no-timings"]);
    assert!(bracket.contains("            = (∂H)²\n"), "{bracket}");
    let latex = run(&[
        "bracket",
        "signs.toml",
        "G",
        "H",
        "--no-timings",
        "--format",
        "latex",
    ]);
    assert!(latex.contains(r" &= (\partial H)^{2}"), "{latex}");
}

/// A display may begin with `∂` or `∇` before a letter, as a derivative or a gradient is
/// written: `∂H`, `∇φ` print as written, and in LaTeX as `\partial H`, `\nabla\varphi`; they
/// were refused as no letter LaTeX has, while a display beginning with a subscript or
/// superscript letter was refused in those words rather than as beginning with no letter.
#[test]
fn a_display_may_begin_with_a_partial_or_a_nabla_sign() {
    let dir = scratch("display-differentials");
    let file = "name = \"signs\"\nhamiltonian = \"p_x^2/2 + p_y^2/2\"\n\n[phase_space]\n\
                coordinates = [\"x\", \"y\"]\n\n[[function]]\nname = \"G\"\n\
                display = \"∇φ\"\nvalue = \"x*p_x\"\n\n[[function]]\nname = \"dH\"\n\
                display = \"∂H\"\nvalue = \"p_x\"\n\n[[claim]]\nid = \"c1\"\n\
                claim = \"{G, dH} = dH\"\n";
    std::fs::write(dir.join("signs.toml"), file).expect("written");
    let o = superint_in(&dir, &["check", "signs.toml", "--no-timings"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(
        text(&o.stdout).contains("{∇φ, ∂H} = ∂H"),
        "{}",
        text(&o.stdout)
    );
    let o = superint_in(
        &dir,
        &["check", "signs.toml", "--no-timings", "--format", "latex"],
    );
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(
        text(&o.stdout).contains(r"\{\nabla\varphi, \partial H\} &= \partial H"),
        "{}",
        text(&o.stdout)
    );
}

/// Why a bar stands where it does.
const BAR: &str = "a bar (U+0304) stands right after the letter or digit it is drawn over, at \
                   the end of the name or before its '_', a prime, a space or a parenthesis \
                   (Z̄, Z̄_x)";

/// Why `a__b` and `A_x_` are no display names.
const SUBSCRIPT_OF_NOTHING: &str = "a subscript '_' stands between a name and its subscript \
                                    (A_x), not at an end or beside another '_' or a space";

/// Every kind of bad input: its file, where the message must point, and the command line
/// ([`BAD_DISPLAY_NAMES`] among them).
fn every_bad_input() -> Vec<(&'static str, Vec<u8>, String, Vec<&'static str>)> {
    let displays = BAD_DISPLAY_NAMES.map(|(case, display, column, why)| {
        (
            case,
            base_with(
                "name = \"A\"",
                &format!("name = \"A\"\ndisplay = \"{display}\""),
            ),
            format!(
                "bad.toml:10:{column}: a display name is letters, digits, primes (G1'), a bar \
                 (Z̄), subscripts (A_x), spaces and parentheses: {why}"
            ),
            vec!["check", "bad.toml"],
        )
    });
    (bad_inputs().into_iter())
        .map(|(case, file, message, args)| (case, file, message.to_string(), args))
        .chain(displays)
        .collect()
}

/// Every kind of bad input but display names: its file, where the message must point, and the
/// command line.
fn bad_inputs() -> Vec<(&'static str, Vec<u8>, &'static str, Vec<&'static str>)> {
    let check = vec!["check", "bad.toml"];
    vec![
        (
            "unknown name",
            base_with("i*omega*A\"", "i*omega*B\""),
            "bad.toml:14:27: unknown name 'B'",
            check.clone(),
        ),
        (
            "malformed expression",
            base_with("p_x + i*M", "p_x + (i*M"),
            "bad.toml:10:28: expected ')' to close '(' opened at line 10, column 16",
            check.clone(),
        ),
        (
            "division by a non-monomial",
            base_with("p_x + i*M*omega*x", "p_x/(1 + x)"),
            "bad.toml:10:14: cannot divide by x + 1",
            check.clone(),
        ),
        (
            "a letter LaTeX has not",
            base_with("parameters = [\"M\", ", "parameters = [\"M\", \"é\", "),
            "bad.toml:6:20: 'é' cannot name a parameter: LaTeX has no letter 'é'",
            check.clone(),
        ),
        (
            "a letter LaTeX has not after a Greek letter",
            base_with("parameters = [\"M\", ", "parameters = [\"M\", \"θé\", "),
            "bad.toml:6:20: 'θé' cannot name a parameter: LaTeX has no letter 'é'",
            check.clone(),
        ),
        (
            "family index with a letter LaTeX has not",
            base_with(
                "[[claim]]",
                "[[family]]\nname = \"K\"\nindices = [\"m\", \"щ\"]\nvalue = \"A^m*x^щ\"\n\n[[claim]]",
            ),
            "bad.toml:14:17: 'щ' cannot name an index: LaTeX has no letter 'щ'",
            check.clone(),
        ),
        // `H` and the functions are no indices: an index `H` made the `H` of the family's value
        // the index, not the Hamiltonian, and an index `cos` refused its `cos(theta)`.
        (
            "family index named H",
            base_with(
                "[[claim]]",
                "[[family]]\nname = \"K\"\nindices = [\"m\", \"H\"]\nvalue = \"A^m*H^2\"\n\n[[claim]]",
            ),
            "bad.toml:14:17: 'H' is reserved for the Hamiltonian",
            check.clone(),
        ),
        (
            "family index named cos",
            base_with(
                "[[claim]]",
                "[[family]]\nname = \"K\"\nindices = [\"cos\", \"n\"]\nvalue = \"A^cos*x^n\"\n\n[[claim]]",
            ),
            "bad.toml:14:12: 'cos' is reserved (i, cos, sin, exp, conj, re, im, sqrt, rank)",
            check.clone(),
        ),
        // Each `_` starts a subscript: a name ending in one, or with two in a row, has an empty
        // subscript, which LaTeX wrote as `x_{,} H` or `\mathrm{a_}` (every kind of name).
        (
            "coordinate ending in '_'",
            base_with("coordinates = [\"x\"]", "coordinates = [\"x\", \"x_\"]"),
            "bad.toml:5:21: 'x_' cannot be a name: a name cannot begin or end in '_' or hold '__'",
            check.clone(),
        ),
        (
            "parameter named '_'",
            base_with("parameters = [\"M\", ", "parameters = [\"M\", \"_\", "),
            "bad.toml:6:20: '_' cannot be a name: a name cannot begin or end in '_' or hold '__'",
            check.clone(),
        ),
        // A '_' at the start is a subscript of nothing: `_a` was written `\mathrm{_a}`, a lone
        // subscript, and `_q`'s momentum `p__q` as `p_{,q}`.
        (
            "coordinate beginning with '_'",
            base_with("coordinates = [\"x\"]", "coordinates = [\"x\", \"_q\"]"),
            "bad.toml:5:21: '_q' cannot be a name: a name cannot begin or end in '_' or hold '__'",
            check.clone(),
        ),
        (
            "parameter beginning with '_'",
            base_with("parameters = [\"M\", ", "parameters = [\"M\", \"_a\", "),
            "bad.toml:6:20: '_a' cannot be a name: a name cannot begin or end in '_' or hold '__'",
            check.clone(),
        ),
        // TOML refuses a key of more than 80 parts with no place, which was said as 1:1.
        (
            "dotted key of 81 parts",
            base_with(
                "[[claim]]",
                &format!("{}b = 1\n\n[[claim]]", "a.".repeat(80)),
            ),
            "bad.toml:12:1: this dotted key has more than 80 parts: TOML reads tables nested at \
             most 80 deep",
            check.clone(),
        ),
        // `sqrt` is a function: a parameter so named made `sqrt(x^2 + y^2)`, and LaTeX's
        // `\sqrt{x^2 + y^2}`, the product `sqrt·(x² + y²)`, echoed as the root.
        (
            "parameter named sqrt",
            base_with("parameters = [\"M\", ", "parameters = [\"M\", \"sqrt\", "),
            "bad.toml:6:20: 'sqrt' is reserved (i, cos, sin, exp, conj, re, im, sqrt, rank)",
            check.clone(),
        ),
        (
            "function beginning with '_'",
            base_with("name = \"A\"", "name = \"_A\""),
            "bad.toml:9:8: '_A' cannot be a name: a name cannot begin or end in '_' or hold '__'",
            check.clone(),
        ),
        (
            "function with '__'",
            base_with("name = \"A\"", "name = \"a__b\""),
            "bad.toml:9:8: 'a__b' cannot be a name: a name cannot begin or end in '_' or hold '__'",
            check.clone(),
        ),
        (
            "family ending in '_'",
            base_with(
                "[[claim]]",
                "[[family]]\nname = \"K_\"\nvalue = \"A^m*x^n\"\n\n[[claim]]",
            ),
            "bad.toml:13:8: 'K_' cannot be a name: a name cannot begin or end in '_' or hold '__'",
            check.clone(),
        ),
        (
            "radical ending in '_'",
            base_with(
                "parameters = [\"M\", \"omega\"]",
                "parameters = [\"M\", \"omega\"]\nradicals = { r_ = \"x^2 + 1\" }",
            ),
            "bad.toml:7:14: 'r_' cannot be a name: a name cannot begin or end in '_' or hold '__'",
            check.clone(),
        ),
        (
            "bracket with a parameter",
            base_with("{A, H}", "{A, omega}"),
            "bad.toml:14:14: 'omega' is a parameter, not a variable of the phase space",
            check.clone(),
        ),
        (
            "bracket with an angle",
            BASE.replacen(
                "coordinates = [\"x\"]",
                "coordinates = [\"x\"]\nangles = [\"theta\"]",
                1,
            )
            .replacen("{A, H}", "{theta, H}", 1)
            .into_bytes(),
            "bad.toml:15:11: theta is an angle",
            check.clone(),
        ),
        (
            "misspelt field",
            base_with("hamiltonian = ", "hamiltonien = "),
            "bad.toml:2:1: unknown field `hamiltonien`",
            check.clone(),
        ),
        (
            "the Hamiltonian below a table's header",
            BASE.replacen("hamiltonian = \"p_x^2/(2*M) + M*omega^2*x^2/2\"\n", "", 1)
                .replacen(
                    "parameters = [\"M\", \"omega\"]\n",
                    "parameters = [\"M\", \"omega\"]\nhamiltonian = \"p_x^2/(2*M)\"\n",
                    1,
                )
                .into_bytes(),
            "bad.toml:6:1: unknown field `hamiltonian`, expected one of `coordinates`, `angles`, \
             `parameters`, `variables`, `denominators`, `radicals`, `display`\n 6 | hamiltonian = \
             \"p_x^2/(2*M)\"\n   | ^^^^^^^^^^^\nhint: `hamiltonian` is a key of the file itself: \
             write it above the first [table] header",
            check.clone(),
        ),
        (
            "a momentum in a name of its own",
            base_with("value = \"p_x + i", "value = \"p_1 + i"),
            "bad.toml:10:10: unknown name 'p_1'",
            check.clone(),
        ),
        (
            "a claim in two sides",
            base_with(
                "claim = \"{A, H} = i*omega*A\"",
                "lhs = \"{A, H}\"\nrhs = \"i*omega*A\"",
            ),
            "bad.toml:14:1: unknown field `lhs`, expected one of `id`, `claim`, `when`, \
             `on`, `expect`\n 14 | lhs = \"{A, H}\"\n    | ^^^\nhint: a claim is one equation in one \
             string: claim = \"{L, H} = 0\"",
            check.clone(),
        ),
        (
            "missing hamiltonian",
            base_with("hamiltonian = \"p_x^2/(2*M) + M*omega^2*x^2/2\"\n", ""),
            "bad.toml:1:1: missing field `hamiltonian`",
            check.clone(),
        ),
        (
            "missing value of a function",
            base_with("value = \"p_x + i*M*omega*x\"\n", ""),
            "bad.toml:8:1: missing field `value`",
            check.clone(),
        ),
        (
            "mistyped field",
            base_with("coordinates = [\"x\"]", "coordinates = \"x\""),
            "bad.toml:5:15: invalid type: string \"x\", expected an array",
            check.clone(),
        ),
        (
            "mistyped expectation",
            base_with("claim = \"{A, H}", "expect = \"false\"\nclaim = \"{A, H}"),
            "bad.toml:14:10: unknown variant `false`, expected `proved` or `refuted`",
            check.clone(),
        ),
        // serde read a table from an array, and said "invalid type: map" of a date.
        (
            "phase space as an array of tables",
            base_with("[phase_space]", "[[phase_space]]"),
            "bad.toml:4:1: [phase_space] is a table, written with one pair of brackets, not an \
             array",
            check.clone(),
        ),
        (
            "phase space as an array",
            base_with(
                "[phase_space]\ncoordinates = [\"x\"]\nparameters = [\"M\", \"omega\"]",
                "phase_space = [[\"x\"], [], [\"M\", \"omega\"]]",
            ),
            "bad.toml:4:15: [phase_space] is a table, written with one pair of brackets, not an \
             array",
            check.clone(),
        ),
        (
            "a claim as an array",
            format!(
                "claim = [[\"ladder\", \"{{A, H}} = i*omega*A\"]]\n{}",
                &BASE[..BASE.find("[[claim]]").unwrap()]
            )
            .into_bytes(),
            "bad.toml:1:9: each [[claim]] is a table, not an array",
            check.clone(),
        ),
        (
            "a function as a table",
            base_with("[[function]]", "[function]"),
            "bad.toml:8:1: [[function]] is an array of tables, each written with two pairs of \
             brackets, not a table",
            check.clone(),
        ),
        // A byte-order mark is no column (the caret was one to the right of the name).
        (
            "unknown name after a byte-order mark",
            format!(
                "\u{feff}hamiltonian = \"q\"\n{}",
                &BASE[BASE.find("\n[phase_space]").unwrap()..]
            )
            .into_bytes(),
            "bad.toml:1:16: unknown name 'q'",
            check.clone(),
        ),
        (
            "hamiltonian as a date",
            base_with("\"p_x^2/(2*M) + M*omega^2*x^2/2\"", "1979-05-27"),
            "bad.toml:2:15: hamiltonian is a string in quotes, not a date",
            check.clone(),
        ),
        // A date inside an array or a table is said as a date too (serde said "invalid type:
        // map"), of its key.
        (
            "a coordinate as a date",
            base_with("coordinates = [\"x\"]", "coordinates = [1979-05-27]"),
            "bad.toml:5:16: each of coordinates is a string in quotes, not a date",
            check.clone(),
        ),
        (
            "a claim's id as a date",
            base_with("id = \"ladder\"", "id = 1979-05-27"),
            "bad.toml:13:6: id is a string in quotes, not a date",
            check.clone(),
        ),
        // A report shows an id, and the system's name, source and description, as written: a
        // tab or line break broke its layout, and an escape printed as U+FFFD.
        (
            "a claim's id with a tab",
            base_with("id = \"ladder\"", "id = \"lad\tder\""),
            "bad.toml:13:10: a claim's id is shown in reports as written: U+0009 is an \
             invisible or control character",
            check.clone(),
        ),
        (
            "a claim's id with an escaped line break",
            base_with("id = \"ladder\"", "id = \"lad\\nder\""),
            "bad.toml:13:10: a claim's id is shown in reports as written: U+000A is an \
             invisible or control character",
            check.clone(),
        ),
        (
            "a claim's id over two lines",
            base_with("id = \"ladder\"", "id = \"\"\"lad\nder\"\"\""),
            "bad.toml:13:12: a claim's id is shown in reports as written: U+000A is an \
             invisible or control character",
            check.clone(),
        ),
        (
            "a system's name with an escape",
            base_with("name = \"oscillator\"", "name = \"osc\\u001b[31m\""),
            "bad.toml:1:12: the system's name is shown in reports as written: U+001B is an \
             invisible or control character",
            check.clone(),
        ),
        (
            "a system's description with a bell",
            base_with(
                "name = \"oscillator\"",
                "name = \"oscillator\"\ndescription = \"\"\"\nOne line,\nanother\\u0007.\"\"\"",
            ),
            "bad.toml:4:8: the system's description is shown in reports as written: U+0007 is \
             an invisible or control character",
            check.clone(),
        ),
        // A string's escapes are found where they are written, and what comes after them: the
        // caret went under the string's first character.
        (
            "a claim with an escaped quote",
            base_with("\"{A, H} = i*omega*A\"", r#""{A, H} = \"x\" + $""#),
            "bad.toml:14:19: unexpected character '\"'",
            check.clone(),
        ),
        (
            "a claim after an escaped backslash",
            base_with("\"{A, H} = i*omega*A\"", r#""{A, H} = \\frac{i}{1}*omega*A + $""#),
            "bad.toml:14:42: unexpected character '$'",
            check.clone(),
        ),
        (
            "a claim after an escaped letter",
            base_with("\"{A, H} = i*omega*A\"", r#""{A, H} = i*\u00e9*A + $""#),
            "bad.toml:14:32: unexpected character '$'",
            check.clone(),
        ),
        (
            "a claim after a line-ending backslash",
            base_with(
                "\"{A, H} = i*omega*A\"",
                "\"\"\"\n{A, H} = \\\n    i*omega*A + $\"\"\"",
            ),
            "bad.toml:16:17: unexpected character '$'",
            check.clone(),
        ),
        (
            "a system's source with a right-to-left override",
            base_with(
                "name = \"oscillator\"",
                "name = \"oscillator\"\nsource = \"A. Author\u{202e}, 1979\"",
            ),
            "bad.toml:2:20: the system's source is shown in reports as written: U+202E is an \
             invisible or control character",
            check.clone(),
        ),
        (
            "a limit as a time",
            base_with(
                "[[function]]",
                "[limits]\nmax_terms = 07:32:00\n\n[[function]]",
            ),
            "bad.toml:9:13: max_terms is a whole number, not a date",
            check.clone(),
        ),
        (
            "expectation as a boolean",
            base_with("claim = \"{A, H}", "expect = true\nclaim = \"{A, H}"),
            "bad.toml:14:10: expect is \"proved\" or \"refuted\", not true or false",
            check.clone(),
        ),
        (
            "unknown field",
            base_with("claim = \"{A", "clam = \"{A"),
            "bad.toml:14:1: unknown field `clam`",
            check.clone(),
        ),
        (
            "bad condition",
            base_with("claim = \"{A, H}", "when = \"omega 2\"\nclaim = \"{A, H}"),
            "bad.toml:14:9: a condition reads `variable = value`",
            check.clone(),
        ),
        (
            "condition on a function",
            base_with(
                "claim = \"{A, H}",
                "when = \"M = 1, A = 0\"\nclaim = \"{A, H}",
            ),
            "bad.toml:14:16: the left side of a condition is one declared variable",
            check.clone(),
        ),
        (
            "an array of tables written as a table after its first item",
            base_with("[[claim]]", "[function]\nname = \"B\"\nvalue = \"x\"\n\n[[claim]]"),
            "bad.toml:12:2: [[function]] is an array of tables, each written with two pairs of \
             brackets, not a table",
            check.clone(),
        ),
        (
            "a key given twice in a claim",
            base_with("claim = \"{A, H}", "claim = \"{A, A} = 0\"\nclaim = \"{A, H}"),
            "bad.toml:15:1: `claim` is given twice in one table",
            check.clone(),
        ),
        (
            "a key given twice at the top",
            base_with("hamiltonian", "name = \"twice\"\nhamiltonian"),
            "bad.toml:2:1: `name` is given twice",
            check.clone(),
        ),
        (
            "condition on a mistyped parameter",
            base_with("claim = \"{A, H}", "when = \"omgea = 1\"\nclaim = \"{A, H}"),
            "bad.toml:14:9: the left side of a condition is one declared variable (a coordinate, \
             a momentum or a parameter), found 'omgea'; did you mean 'omega'?",
            check.clone(),
        ),
        (
            "condition that sets a variable in terms of itself",
            base_with("claim = \"{A, H}", "when = \"M = 2*M\"\nclaim = \"{A, H}"),
            "bad.toml:14:13: the condition sets M in terms of itself",
            check.clone(),
        ),
        (
            "circular condition",
            base_with(
                "claim = \"{A, H}",
                "when = \"M = omega, omega = 2*M\"\nclaim = \"{A, H}",
            ),
            "bad.toml:14:13: the condition sets M in terms of itself",
            check.clone(),
        ),
        (
            "condition with a value that is not real",
            base_with(
                "claim = \"{A, H}",
                "when = \"M = 1, p_x = i*x\"\nclaim = \"{A, H}",
            ),
            "bad.toml:14:22: the condition sets p_x to ix, which is not real",
            check.clone(),
        ),
        // These two said what but not what to do.
        (
            "condition that fixes a variable twice",
            base_with(
                "claim = \"{A, H}",
                "when = \"M = 1, M = 2\"\nclaim = \"{A, H}",
            ),
            "bad.toml:14:16: 'M' is fixed twice\n 14 | when = \"M = 1, M = 2\"\n    |                ^\n\
             hint: keep one of its values: a list of values sets each name once",
            check.clone(),
        ),
        (
            "condition with a value that divides by zero",
            base_with(
                "claim = \"{A, H}",
                "when = \"M = 1, x = 1/0\"\nclaim = \"{A, H}",
            ),
            concat!(
                "bad.toml:14:22: division by zero\n 14 | when = \"M = 1, x = 1/0\"\n",
                "    |                      ^\n",
                "hint: what is divided by here is 0: write a divisor other than 0, or leave the \
                 division out",
            ),
            check.clone(),
        ),
        (
            "claim without =",
            base_with("{A, H} = i*omega*A", "{A, H}"),
            "bad.toml:14:10: a claim reads `lhs = rhs`",
            check.clone(),
        ),
        // A rank on a level set: each phase variable set once, to a value free of itself.
        (
            "rank claim on a level set that sets a variable in terms of itself",
            base_with(
                "claim = \"{A, H} = i*omega*A\"",
                "claim = \"rank(A, H) = 1\"\nwhen = \"x = p_x, p_x = 1 - x\"",
            ),
            "bad.toml:15:13: the condition sets x in terms of itself",
            check.clone(),
        ),
        (
            "rank claim on a level set that sets a variable twice",
            base_with(
                "claim = \"{A, H} = i*omega*A\"",
                "claim = \"rank(A, H) = 1\"\nwhen = [\"p_x = M\", \"p_x = omega\"]",
            ),
            "bad.toml:15:21: 'p_x' is fixed twice",
            check.clone(),
        ),
        (
            "rank claim with a parameter set to a momentum",
            base_with(
                "claim = \"{A, H} = i*omega*A\"",
                "claim = \"rank(A, H) = 1\"\nwhen = \"omega = p_x\"",
            ),
            "bad.toml:15:17: the condition sets the parameter ω to a function of phase space \
             (it holds p_x, a momentum): a rank's condition sets parameters to numbers or other \
             parameters, and a phase variable to a value in them and the other phase variables",
            check.clone(),
        ),
        (
            "rank claim with a parameter set to zero where it divides",
            base_with(
                "claim = \"{A, H} = i*omega*A\"",
                "claim = \"rank(A, H) = 1\"\nwhen = \"M = 0\"",
            ),
            "bad.toml:14:9: the condition sets M = 0, but a function divides by M",
            check.clone(),
        ),
        (
            "rank claim with a rank past any dimension",
            base_with("{A, H} = i*omega*A", "rank(A, H) = 99999999999999999999999"),
            "bad.toml:14:23: the right side of a rank claim is a whole number, and this one is \
             too large to be a rank",
            check.clone(),
        ),
        (
            "rank claim with a non-integer rank",
            base_with("{A, H} = i*omega*A", "rank(A, H) = two"),
            "bad.toml:14:23: the right side of a rank claim is a whole number",
            check.clone(),
        ),
        (
            "name declared twice",
            base_with(
                "parameters = [\"M\", \"omega\"]",
                "parameters = [\"M\", \"x\"]",
            ),
            "bad.toml:6:20: 'x' is already declared as a coordinate on line 5",
            check.clone(),
        ),
        (
            "parameter named as an angle",
            base_with(
                "parameters = [\"M\", \"omega\"]",
                "angles = [\"phi\"]\nparameters = [\"M\", \"phi\"]",
            ),
            "bad.toml:7:20: 'phi' is already declared as an angle on line 6",
            check.clone(),
        ),
        (
            "family with an unknown name",
            base_with(
                "[[claim]]",
                "[[family]]\nname = \"K\"\nvalue = \"Q^m*A^n\"\n\n[[claim]]",
            ),
            "bad.toml:14:10: unknown name 'Q'",
            check.clone(),
        ),
        (
            "family whose value fails at its instance (1, 1) only (the hint says it is that \
             instance, which the loader computes)",
            base_with(
                "[[claim]]",
                "[[family]]\nname = \"K\"\nvalue = \"(x + A)^(m - 2)*A^n\"\n\n[[claim]]",
            ),
            "bad.toml:14:10: cannot raise ",
            check.clone(),
        ),
        (
            "family using itself",
            base_with(
                "[[claim]]",
                "[[family]]\nname = \"K\"\nvalue = \"A^m*K_m_n\"\n\n[[claim]]",
            ),
            "bad.toml:14:14: the family K uses itself here ('K_m_n'): a family cannot be \
             defined by its own instances",
            check.clone(),
        ),
        (
            "family using itself at indices",
            base_with(
                "[[claim]]",
                "[[family]]\nname = \"K\"\nvalue = \"K_1_2*A^m\"\n\n[[claim]]",
            ),
            "bad.toml:14:10: the family K uses itself here ('K_1_2'): a family cannot be \
             defined by its own instances",
            check.clone(),
        ),
        (
            "condition that divides by zero",
            base_with(
                "claim = \"{A, H} = i*omega*A\"",
                "when = \"M = 0\"\nclaim = \"{x, H} = p_x/M\"",
            ),
            "bad.toml:15:9: the condition sets M = 0, but the claim divides by M",
            check.clone(),
        ),
        (
            // One value divides by what another sets to 0: it was "division by zero" at the
            // other's value, saying neither what nor where.
            "condition whose value divides by zero",
            base_with(
                "claim = \"{A, H} = i*omega*A\"",
                "when = \"M = 0, omega = 1/M\"\nclaim = \"{x, H} = p_x\"",
            ),
            "bad.toml:14:24: the condition sets M = 0, but the value of ω divides by M: give ω \
             a value defined there, or leave M free",
            check.clone(),
        ),
        (
            "claim with an unclosed brace",
            base_with("{A, H} = i*omega*A", "{A, H = i*omega*A"),
            "bad.toml:14:10: this '{' is never closed",
            check.clone(),
        ),
        (
            "claim with a bracket that closes nothing",
            base_with("{A, H} = i*omega*A", "A, H} = i*omega*A"),
            "bad.toml:14:14: this '}' closes nothing",
            check.clone(),
        ),
        (
            "TOML syntax error",
            base_with(
                "claim = \"{A, H} = i*omega*A\"",
                "claim = \"{A, H} = i*omega*A",
            ),
            "bad.toml:14:",
            check.clone(),
        ),
        (
            "empty file",
            b"\n  \n".to_vec(),
            "bad.toml:1:1: the file is empty",
            check.clone(),
        ),
        (
            "binary file",
            b"\x7fELF\x02\x01\x01\x00\x00\x00".to_vec(),
            "bad.toml:1:8: this is a binary file",
            check.clone(),
        ),
        (
            "invalid UTF-8",
            b"name = \"caf\xe9\"\n".to_vec(),
            "bad.toml:1:12: the file is not UTF-8 text (byte 0xE9",
            check.clone(),
        ),
        (
            "degree limit",
            base_with("{A, H} = i*omega*A", "x^5000 = 0"),
            "bad.toml:14:12: the exponent 5000 is past the limit of 1000",
            check.clone(),
        ),
        (
            "term limit from the file",
            HUGE.as_bytes().to_vec(),
            "bad.toml:14:10: the result would have more than 10000 terms (the term limit)",
            check.clone(),
        ),
        (
            "term limit from the command line",
            HUGE.as_bytes().to_vec(),
            "bad.toml:14:10: the result would have more than 3000 terms (the term limit)",
            vec!["check", "bad.toml", "--max-terms", "3000"],
        ),
        (
            "work limit from the file",
            work(),
            "bad.toml:14:10: the product of 35 terms by 35 would form 1225 term products, past \
             the limit of 1000 (the work limit)",
            check.clone(),
        ),
        (
            "work limit from the command line",
            work(),
            "bad.toml:14:10: the product of 35 terms by 35 would form 1225 term products, past \
             the limit of 600 (the work limit)",
            vec!["check", "bad.toml", "--max-term-products", "600"],
        ),
        (
            "a work limit of zero",
            base_with("[[claim]]", "[limits]\nmax_term_products = 0\n\n[[claim]]"),
            "bad.toml:13:21: max_term_products must be at least 1",
            check.clone(),
        ),
        (
            "a negative term limit (it was serde's `expected u64`)",
            base_with("[[claim]]", "[limits]\nmax_terms = -5\n\n[[claim]]"),
            "bad.toml:13:13: max_terms must be at least 1",
            check.clone(),
        ),
        (
            "a term limit in quotes (it was serde's `expected i64`)",
            base_with("[[claim]]", "[limits]\nmax_terms = \"100\"\n\n[[claim]]"),
            "bad.toml:13:13: invalid type: string \"100\", expected a whole number",
            check.clone(),
        ),
        (
            "a term limit past 64 bits (it was serde's `as i128, expected i64`)",
            base_with(
                "[[claim]]",
                "[limits]\nmax_terms = 99999999999999999999\n\n[[claim]]",
            ),
            "bad.toml:13:13: the number 99999999999999999999 is too large (at most \
             9223372036854775807)",
            check.clone(),
        ),
        (
            "a negative degree limit",
            base_with("[[claim]]", "[limits]\nmax_degree = -5\n\n[[claim]]"),
            "bad.toml:13:14: max_degree must be between 1 and 32767",
            check.clone(),
        ),
        (
            "unknown name on the command line",
            BASE.as_bytes().to_vec(),
            "<command line>:1:5: unknown name 'B'",
            vec!["bracket", "bad.toml", "A", "H + B"],
        ),
        (
            "two spellings of one parameter",
            base_with(
                "parameters = [\"M\", \"omega\"]",
                "parameters = [\"M\", \"omega\", \"ω\"]",
            ),
            "bad.toml:6:29: variable \"ω\" is declared twice (as \"omega\"",
            check.clone(),
        ),
        // Names that read apart in text print alike in LaTeX: `M1` and `M₁` are both `M_{1}`.
        (
            "two parameters alike in LaTeX",
            base_with(
                "parameters = [\"M\", \"omega\"]",
                "parameters = [\"M\", \"omega\", \"M1\", \"M₁\"]",
            ),
            "bad.toml:6:35: \"M1\" and \"M₁\" would print alike in LaTeX, as M_{1}: rename one",
            check.clone(),
        ),
        (
            "a function printed as a parameter is in LaTeX",
            base_with(
                "parameters = [\"M\", \"omega\"]\n\n[[function]]\nname = \"A\"",
                "parameters = [\"M\", \"omega\", \"M1\"]\n\n[[function]]\nname = \"M_1\"",
            ),
            "bad.toml:9:8: the function M_1 would print as M_{1} in LaTeX, as the parameter M1 \
             does: rename one, or give it another display",
            check.clone(),
        ),
        (
            "a function shown as another is",
            base_with(
                "[[claim]]",
                "[[function]]\nname = \"B\"\ndisplay = \"A\"\nvalue = \"x\"\n\n[[claim]]",
            ),
            "bad.toml:14:11: the function B would show as A, as the function A on line 9 does",
            check.clone(),
        ),
        // Names of several words, and displays that are no name (`x(t)`), are compared too.
        (
            "two functions shown alike in words",
            base_with(
                "[[claim]]",
                "[[function]]\nname = \"B\"\ndisplay = \"Re A\"\nvalue = \"x\"\n\n[[function]]\n\
                 name = \"C\"\ndisplay = \"Re A\"\nvalue = \"p_x\"\n\n[[claim]]",
            ),
            "bad.toml:19:11: the function C would show as Re A, as the function B on line 14 does",
            check.clone(),
        ),
        (
            "two functions shown alike as no name",
            base_with(
                "[[claim]]",
                "[[function]]\nname = \"B\"\ndisplay = \"x(t)\"\nvalue = \"x\"\n\n[[function]]\n\
                 name = \"C\"\ndisplay = \"x(t)\"\nvalue = \"p_x\"\n\n[[claim]]",
            ),
            "bad.toml:19:11: the function C would show as x(t), as the function B on line 14 does",
            check.clone(),
        ),
        // `[phase_space] display` (`{ a = "ω₊" }`): a variable's display name, refused at its
        // key or its value.
        (
            "display of an undeclared name",
            base_with("parameters = [\"M\", \"omega\"]", "parameters = [\"M\", \"omega\"]\ndisplay = { c = \"γ\" }"),
            "bad.toml:7:13: 'c' is not declared ([phase_space] display shows a coordinate, an angle, a Poisson variable or a parameter declared above it)",
            check.clone(),
        ),
        (
            "display of a momentum",
            base_with("parameters = [\"M\", \"omega\"]", "parameters = [\"M\", \"omega\"]\ndisplay = { p_x = \"π\" }"),
            "bad.toml:7:13: 'p_x' is the momentum of x, which shows as x does ([phase_space] display shows a coordinate, an angle, a Poisson variable or a parameter; with x = \"ξ\", p_x shows as p_ξ)",
            check.clone(),
        ),
        (
            "display of a function",
            base_with("parameters = [\"M\", \"omega\"]", "parameters = [\"M\", \"omega\"]\ndisplay = { A = \"α\" }"),
            "bad.toml:7:13: 'A' is a function: give it a display in its [[function]] ([phase_space] display shows a coordinate, an angle, a Poisson variable or a parameter)",
            check.clone(),
        ),
        (
            "display of a parameter empty",
            base_with("parameters = [\"M\", \"omega\"]", "parameters = [\"M\", \"omega\"]\ndisplay = { omega = \"\" }"),
            "bad.toml:7:21: a display name is letters, digits, primes (G1'), a bar (Z̄), subscripts (A_x), spaces and parentheses: this one is empty (leave display out to show the name)",
            check.clone(),
        ),
        (
            "display of a parameter in two words",
            base_with("parameters = [\"M\", \"omega\"]", "parameters = [\"M\", \"omega\"]\ndisplay = { omega = \"w t\" }"),
            "bad.toml:7:21: a variable's display is one name (ω₊, A_x, Z̄): 'w t' is several words, which beside a factor would read as a product of its own (2 w t)",
            check.clone(),
        ),
        (
            "display of a parameter that is no name",
            base_with("parameters = [\"M\", \"omega\"]", "parameters = [\"M\", \"omega\"]\ndisplay = { omega = \"w(t)\" }"),
            "bad.toml:7:21: a variable's display is a name, with primes, a bar or subscripts (ω₊, A_x, Z̄, G1'), which reads as one factor of a product: 'w(t)' is not",
            check.clone(),
        ),
        (
            "display of a parameter shown as another parameter",
            base_with("parameters = [\"M\", \"omega\"]", "parameters = [\"M\", \"omega\"]\ndisplay = { omega = \"M\" }"),
            "bad.toml:7:21: the parameter omega would show as M, as the parameter M does: give it another display",
            check.clone(),
        ),
        (
            "display of a parameter printed as another is in LaTeX",
            base_with("parameters = [\"M\", \"omega\"]", "parameters = [\"M\", \"omega\"]\ndisplay = { M = \"x_1\", omega = \"x₁\" }"),
            "bad.toml:7:32: the parameter omega would print as x_{1} in LaTeX, as the parameter M on line 7 does: give it another display",
            check.clone(),
        ),
        (
            "display of a parameter that names another",
            base_with("parameters = [\"M\", \"omega\"]", "parameters = [\"M\", \"omega\"]\ndisplay = { M = \"omega\", omega = \"Ω\" }"),
            "bad.toml:7:17: the parameter M would show as ω, which names the parameter omega: give it another display",
            check.clone(),
        ),
        (
            "display of a parameter shown as a function",
            base_with("parameters = [\"M\", \"omega\"]", "parameters = [\"M\", \"omega\"]\ndisplay = { omega = \"A\" }"),
            "bad.toml:10:8: the function A would show as A, as the parameter omega on line 7 does: rename one, or give it another display",
            check.clone(),
        ),
        (
            "family instance with one index",
            base_with(
                "[[claim]]",
                "[[family]]\nname = \"K\"\nvalue = \"A^m*x^n\"\n\n[[claim]]",
            ),
            "<command line>:1:5: 'K_1' is not an instance of the family K_m_n, which takes two \
             indices, each a whole number",
            vec!["bracket", "bad.toml", "A", "H + K_1"],
        ),
        (
            "family instance with a negative index",
            base_with(
                "[[claim]]",
                "[[family]]\nname = \"K\"\nvalue = \"A^m*x^n\"\n\n[[claim]]",
            ),
            "<command line>:1:1: 'K_{-1,2}' is not an instance of the family K_m_n",
            vec!["expand", "bad.toml", "K_{-1,2}"],
        ),
        (
            // Shown as written, over its whole width: it was 'K_1_9999999999', two characters
            // short, as the braces were read.
            "family instance with an index of ten digits in braces",
            base_with(
                "[[claim]]",
                "[[family]]\nname = \"K\"\nvalue = \"A^m*x^n\"\n\n[[claim]]",
            ),
            "<command line>:1:5: 'K_{1,9999999999}' is not an instance of the family K_m_n: its \
             second index is too large (an index has at most 9 digits, leading zeros aside: \
             999999999 at most)\n 1 | x + K_{1,9999999999}\n   |     ^^^^^^^^^^^^^^^^",
            vec!["expand", "bad.toml", "x + K_{1,9999999999}"],
        ),
        (
            "family instance with an index of eleven digits",
            base_with(
                "[[claim]]",
                "[[family]]\nname = \"K\"\nvalue = \"A^m*x^n\"\n\n[[claim]]",
            ),
            "<command line>:1:1: 'K_99999999999_1' is not an instance of the family K_m_n: its \
             first index is too large (an index has at most 9 digits",
            vec!["expand", "bad.toml", "K_99999999999_1"],
        ),
        (
            "family instance with unclosed braces",
            base_with(
                "[[claim]]",
                "[[family]]\nname = \"K\"\nvalue = \"A^m*x^n\"\n\n[[claim]]",
            ),
            "<command line>:1:3: the braces of 'K_{1,2' are never closed",
            vec!["expand", "bad.toml", "2*K_{1,2"],
        ),
        (
            "tower without a family",
            BASE.as_bytes().to_vec(),
            "bad.toml: the file declares no [[family]] with an eigenvalue",
            vec!["tower", "--system", "bad.toml", "--max", "2"],
        ),
        (
            "declared brackets that break the Jacobi identity",
            top_with("\"{M3, M1}\" = \"M1\""),
            "bad.toml:12:1: the declared brackets break the Jacobi identity: {M1, {M2, M3}} + \
             {M2, {M3, M1}} + {M3, {M1, M2}} = −M3, not 0; it depends on the declared {M1, M2}, \
             {M2, M3} and {M3, M1}",
            check.clone(),
        ),
        (
            "a declared bracket that breaks Jacobi with a canonical pair",
            top_with("\"{M3, M1}\" = \"M2*x\""),
            "bad.toml:12:1: the declared brackets break the Jacobi identity: {p_x, {M1, M3}} + \
             {M1, {M3, p_x}} + {M3, {p_x, M1}} = M2, not 0",
            check.clone(),
        ),
        (
            "a declared bracket given twice",
            top_with("\"{M2, M1}\" = \"-M3\""),
            "bad.toml:12:1: {M2, M1} is given twice: line 10 gives it already",
            check.clone(),
        ),
        (
            "a declared bracket of an unknown name",
            top_with("\"{M3, N}\" = \"M2\""),
            "bad.toml:12:1: unknown name 'N' in a bracket of [poisson] (the phase variables: \
             x, p_x, M1, M2, M3)",
            check.clone(),
        ),
        (
            "a declared bracket of a parameter",
            top_with("\"{M3, a}\" = \"M2\""),
            "bad.toml:12:1: 'a' is a parameter, not a variable of the phase space",
            check.clone(),
        ),
        (
            "a declared bracket of canonical variables",
            top_with("\"{x, p_x}\" = \"2\""),
            "bad.toml:12:1: {x, p_x} is a bracket of canonical variables, already fixed by \
             their pairs",
            check.clone(),
        ),
        (
            "a declared bracket of a variable with itself",
            top_with("\"{M3, M3}\" = \"M2\""),
            "bad.toml:12:1: {M3, M3} is 0",
            check.clone(),
        ),
        (
            "a declared bracket's key without braces",
            top_with("\"M3, M1\" = \"M2\""),
            "bad.toml:12:1: a key of [poisson] is a bracket of two variables, such as \
             \"{M1, M2}\", not \"M3, M1\"",
            check.clone(),
        ),
        (
            "a declared bracket that is not a string",
            top_with("\"{M3, M1}\" = 2"),
            "bad.toml:12:14: invalid type: integer `2`, expected a string in quotes",
            check.clone(),
        ),
        (
            "a declared bracket that is not real",
            top_with("\"{M3, M1}\" = \"i*M2\""),
            "bad.toml:12:15: {M3, M1} = i M2 is not real",
            check.clone(),
        ),
        // A declared denominator and a radical are taken in a declared bracket (the bracket goes
        // through them by the chain rule), and the Jacobi identity is checked with them:
        // {M2, M2/(M1 − M2)} = −M3 ∂(M2/(M1 − M2))/∂M1 = M2 M3/(M1 − M2)², and
        // {p_x, −M2 r} = M2 x/r for r = √(x² + 1).
        (
            "a declared bracket with a denominator that breaks the Jacobi identity",
            TOP.replacen(
                "parameters = [\"a\"]\n",
                "parameters = [\"a\"]\ndenominators = [\"M1 - M2\"]\n",
                1,
            )
            .replacen("\"{M3, M1}\" = \"M2\"", "\"{M3, M1}\" = \"M2/(M1 - M2)\"", 1)
            .into_bytes(),
            "bad.toml:13:1: the declared brackets break the Jacobi identity: {M1, {M2, M3}} + \
             {M2, {M3, M1}} + {M3, {M1, M2}} = M2 M3/(M1 − M2)², not 0",
            check.clone(),
        ),
        // A negative power of a phase variable went on to the Jacobi check, whose message
        // blamed the brackets at the key, not the value.
        (
            "a declared bracket with a negative power of a Poisson variable",
            top_with("\"{M3, M1}\" = \"M2/M1\""),
            "bad.toml:12:15: {M3, M1} = M2/M1 has a negative power of M1: a declared bracket \
             divides by declared denominators and radicals alone\n 12 | \"{M3, M1}\" = \"M2/M1\"\n    |               ^^^^^\nhint: write \
             it without dividing by M1",
            check.clone(),
        ),
        (
            "a declared bracket with a radical that breaks the Jacobi identity",
            TOP.replacen(
                "parameters = [\"a\"]\n",
                "parameters = [\"a\"]\nradicals = { r = \"x^2 + 1\" }\n",
                1,
            )
            .replacen("\"{M3, M1}\" = \"M2\"", "\"{M3, M1}\" = \"M2*r\"", 1)
            .into_bytes(),
            "bad.toml:13:1: the declared brackets break the Jacobi identity: {p_x, {M1, M3}} + \
             {M1, {M3, p_x}} + {M3, {p_x, M1}} = x M2/r, not 0; it depends on the declared \
             {M3, M1}",
            check.clone(),
        ),
        (
            "a declared bracket that is a bracket",
            top_with("\"{M3, M1}\" = \"{M1, M2}\""),
            "bad.toml:12:15: a declared bracket's value cannot be a bracket",
            check.clone(),
        ),
        (
            "a declared bracket with an unknown name",
            top_with("\"{M3, M1}\" = \"M2 + b\""),
            "bad.toml:12:20: unknown name 'b'",
            check.clone(),
        ),
        (
            "a search on a surface of Poisson variables that the flow leaves",
            TOP.as_bytes().to_vec(),
            "<command line>:1:6: the flow leaves the surface M1 = 0: there {M1, H} = −M2 M3, \
             not 0",
            vec!["search", "bad.toml", "--when", "M1 = 0"],
        ),
        (
            "missing file",
            Vec::new(),
            "missing.toml: cannot read the file",
            vec!["check", "missing.toml"],
        ),
    ]
}

#[test]
fn bad_inputs_get_file_line_column_and_exit_2() {
    let dir = scratch("bad-inputs");
    let mut all = String::new();
    let mut wrong = Vec::new();
    for (name, content, expected, args) in every_bad_input() {
        std::fs::write(dir.join("bad.toml"), &content).expect("write the file");
        let o = superint_in(&dir, &args);
        let stderr = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{name}: {stderr}");
        // A claim past a limit is reported undecided, beside the file's other claims; any
        // other bad input prints nothing.
        let stdout = text(&o.stdout);
        let undecided = args[0] == "check" && expected.contains("limit");
        match undecided {
            true => assert!(stdout.contains("UNDECIDED]"), "{name}: {stdout}"),
            false => assert!(stdout.is_empty(), "{name} printed to stdout"),
        }
        assert!(!stderr.contains("panicked"), "{name}: {stderr}");
        if !stderr.starts_with(&format!("superint: error: {expected}")) {
            wrong.push(format!("{name}: expected {expected:?}, got\n{stderr}"));
        }
        all.push_str(&format!(
            "== {name}: superint {}\n{stderr}\n",
            args.join(" ")
        ));
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert_snapshot("bad-inputs.txt", &all);
}

#[test]
fn limits_flag_overrides_the_file() {
    let dir = scratch("limits");
    std::fs::write(dir.join("huge.toml"), HUGE).expect("write");
    // A larger limit on the command line wins over the file's 10000 and still stops it.
    let o = superint_in(&dir, &["check", "huge.toml", "--max-terms", "20000"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("more than 20000 terms"));
    // A degree limit from the command line stops a modest power.
    let o = superint_in(
        root(),
        &["check", "systems/harmonic-rotor.toml", "--max-degree", "3"],
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(
        text(&o.stderr).contains("past the limit of 3"),
        "{}",
        text(&o.stderr)
    );
}

/// A rank claim's condition sets parameters: the rank is that of the functions at those values,
/// and the certificate's point leaves out what the condition sets.
#[test]
fn rank_claims_under_a_parameter_condition() {
    let dir = scratch("rank-condition");
    let file = "hamiltonian = \"(p_x^2 + p_y^2)/2 + (x^2 + a*y^2)/2\"\n\
                [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\"]\n\
                [[claim]]\nid = \"isotropic\"\n\
                claim = \"rank(H, (p_x^2 + x^2 + p_y^2 + y^2)/2) = 1\"\nwhen = \"a = 1\"\n\
                [[claim]]\nid = \"anisotropic\"\n\
                claim = \"rank(H, (p_x^2 + x^2 + p_y^2 + y^2)/2) = 1\"\nwhen = \"a = 4\"\n\
                expect = \"refuted\"\n";
    std::fs::write(dir.join("rank.toml"), file).expect("write");
    let o = superint_in(&dir, &["check", "rank.toml", "--no-timings"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert!(out.contains("= 1 at a = 1"), "{out}");
    assert!(out.contains("[isotropic proved]"), "{out}");
    assert!(out.contains("[anisotropic refuted, as expected]"), "{out}");
    assert!(out.contains("the rank is 2"), "{out}");
    assert!(!out.contains("a = 11/2"), "the point leaves out a: {out}");
    let o = superint_in(&dir, &["check", "rank.toml", "--format", "json"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let isotropic = &v["ranks"][0];
    assert_eq!(isotropic["condition"], "a = 1");
    assert_eq!(isotropic["condition_ascii"], "a = 1");
    assert_eq!(isotropic["rank"], 1);
}

/// A rank claim's condition may set a phase variable: the rank is then that of the functions
/// restricted to its level set, the condition substituted and the Jacobian taken by the other
/// phase variables. On `p_y = x` the function `p_y − x` vanishes, so that `H` and it have rank
/// 1 there (2 on the whole plane); four functions have rank 3 on the three-dimensional level
/// set, which the number of its coordinates bounds. Each format says so: the Jacobian by
/// `(x, y, p_x)` at `p_y = x`, with a point that leaves out `p_y`.
#[test]
fn rank_claims_on_a_level_set() {
    let dir = scratch("rank-level-set");
    let file = "hamiltonian = \"(p_x^2 + p_y^2)/2 + (x^2 + y^2)/2\"\n\
                [phase_space]\ncoordinates = [\"x\", \"y\"]\n\
                [[claim]]\nid = \"whole\"\nclaim = \"rank(H, p_y - x) = 2\"\n\
                [[claim]]\nid = \"level\"\nclaim = \"rank(H, p_y - x) = 1\"\nwhen = \"p_y = x\"\n\
                [[claim]]\nid = \"level-false\"\nclaim = \"rank(H, p_y - x) = 2\"\n\
                when = \"p_y = x\"\nexpect = \"refuted\"\n\
                [[claim]]\nid = \"columns\"\nclaim = \"rank(x, y, p_x, p_y) = 3\"\n\
                when = \"p_y = x\"\n";
    std::fs::write(dir.join("level.toml"), file).expect("write");
    let run = |format: &str| {
        let o = superint_in(
            &dir,
            &["check", "level.toml", "--format", format, "--no-timings"],
        );
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
        text(&o.stdout)
    };
    let out = run("text");
    for line in [
        "rank ∂(H, p_y − x)/∂(x, y, p_x, p_y) = 2",
        "rank ∂(H, p_y − x)/∂(x, y, p_x) = 1 at p_y = x",
        "[level proved]",
        "rank ∂(H, p_y − x)/∂(x, y, p_x) = 2 at p_y = x",
        "[level-false refuted, as expected]",
        "the rank is 1",
        "rank ∂(x, y, p_x, p_y)/∂(x, y, p_x) = 3 at p_y = x",
        "[columns proved]",
        "≤ 3: there are 3 coordinates",
    ] {
        assert!(out.contains(line), "{line}: {out}");
    }
    // The points of the claims on the level set leave out p_y, which the condition sets.
    assert_eq!(out.matches("p_y = ").count(), 1 + 3, "{out}");
    let markdown = run("markdown");
    assert!(
        markdown.contains("`rank ∂(H, p_y − x)/∂(x, y, p_x) = 1` at `p_y = x`"),
        "{markdown}"
    );
    let latex = run("latex");
    assert!(
        latex.contains(r"\partial(H, p_{y} - x)/\partial(x, y, p_{x})"),
        "{latex}"
    );
    assert!(latex.contains(r"\text{at } p_{y} = x"), "{latex}");
    let v: serde_json::Value = serde_json::from_str(&run("json")).expect("JSON");
    let level = &v["ranks"][1];
    assert_eq!(level["id"], "level");
    assert_eq!(level["coordinates"], serde_json::json!(["x", "y", "p_x"]));
    assert_eq!(level["condition"], "p_y = x");
    assert_eq!(level["rank"], 1);
    let point: Vec<&str> = level["point"]
        .as_array()
        .expect("a point")
        .iter()
        .map(|p| p["variable"].as_str().expect("a name"))
        .collect();
    assert_eq!(point, ["x", "y", "p_x"]);
    assert_eq!(v["ranks"][2]["outcome"], "refuted");
    assert_eq!(v["ranks"][3]["upper_bound"]["kind"], "size");
}

/// A proof's computed fact parenthesizes a base function that is a sum: `i p_x + ix` would
/// read as a sum of two terms, where the bracket is `i(p_x + ix)`.
#[test]
fn tower_proof_facts_parenthesize_a_sum() {
    let dir = scratch("tower-sum");
    let file = "hamiltonian = \"p_x^2/2 + x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n\
                [[family]]\nname = \"K\"\nvalue = \"(p_x + i*x)^m*(p_x - i*x)^n\"\n\
                eigenvalue = \"i*(m - n)\"\n";
    std::fs::write(dir.join("sum.toml"), file).expect("write");
    let o = superint_in(&dir, &["tower", "--system", "sum.toml", "--max", "2"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert!(out.contains("{p_x + ix, H} = i (p_x + ix)"), "{out}");
    assert!(out.contains("{p_x − ix, H} = −i (p_x − ix)"), "{out}");
}

/// A tower's proof names its two base functions otherwise than the file's functions: where a
/// file has ladders `A` and `B` and a family `J = B^m e^{−inθ}`, the proof said
/// `{A, H} = λ_A A and {B, H} = λ_B B give {A^m B^n, H} = …` of the bases `B` and `e^{−iθ}`, so
/// that the file's `A` stood for `B` and its `B` for `e^{−iθ}`; it now takes the first pair the
/// file does not name, `F`, `G`, in every format, and keeps `A`, `B` where it can.
#[test]
fn a_tower_proof_names_its_bases_apart_from_the_files_functions() {
    let dir = scratch("tower-bases");
    let file = "hamiltonian = \"(p_x^2 + p_y^2)/2 + (x^2 + 4*y^2)/2 + p_theta^2/2\"\n\
                [phase_space]\ncoordinates = [\"x\", \"y\"]\nangles = [\"theta\"]\n\
                [[function]]\nname = \"A\"\nvalue = \"p_x + i*x\"\n\
                [[function]]\nname = \"B\"\nvalue = \"p_y + 2*i*y\"\n\
                [[family]]\nname = \"J\"\nvalue = \"B^m*exp(-i*n*theta)\"\n\
                eigenvalue = \"i*(2*m - n*p_theta)\"\n";
    std::fs::write(dir.join("ab.toml"), file).expect("write");
    for (format, said) in [
        (
            "text",
            [
                "{FG, H} = F{G, H} + G{F, H}",
                "so {F, H} = λ_F F and {G, H} = λ_G G",
            ],
        ),
        (
            "markdown",
            [
                "`{FG, H} = F{G, H} + G{F, H}`",
                "`{F, H} = λ_F F` and `{G, H} = λ_G G`",
            ],
        ),
        (
            "latex",
            [
                r"$\{FG, H\} = F\{G, H\} + G\{F, H\}$",
                r"$\{F, H\} = \lambda_{F} F$ and $\{G, H\} = \lambda_{G} G$",
            ],
        ),
    ] {
        let o = superint_in(
            &dir,
            &[
                "tower", "--system", "ab.toml", "--max", "2", "--format", format,
            ],
        );
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
        let out = text(&o.stdout);
        for s in said {
            assert!(out.contains(s), "{format}: {s}\n{out}");
        }
        assert!(!out.contains("λ_A") && !out.contains("lambda_{A}"), "{out}");
    }
    // Without functions so named, the proof keeps A and B.
    let free = file
        .replace("name = \"A\"", "name = \"U1\"")
        .replace("name = \"B\"", "name = \"V1\"")
        .replace("\"B^m", "\"V1^m");
    std::fs::write(dir.join("free.toml"), free).expect("write");
    let o = superint_in(&dir, &["tower", "--system", "free.toml", "--max", "2"]);
    let out = text(&o.stdout);
    assert!(out.contains("{AB, H} = A{B, H} + B{A, H}"), "{out}");
    assert!(
        out.contains("so {A, H} = λ_A A and {B, H} = λ_B B"),
        "{out}"
    );
}

/// A tower's proof names its bases apart from the file's families too: beside functions `A`,
/// `B` and a family `F = A^m B^n`, the proof of `J` said `{F, H} = λ_F F` of its base `B`, so
/// that the family's letter stood for a base; it now takes `U`, `V`, in both proofs.
#[test]
fn a_tower_proof_names_its_bases_apart_from_the_files_families() {
    let dir = scratch("tower-bases-families");
    let file = "hamiltonian = \"(p_x^2 + p_y^2)/2 + (x^2 + 4*y^2)/2 + p_theta^2/2\"\n\
                [phase_space]\ncoordinates = [\"x\", \"y\"]\nangles = [\"theta\"]\n\
                [[function]]\nname = \"A\"\nvalue = \"p_x + i*x\"\n\
                [[function]]\nname = \"B\"\nvalue = \"p_y + 2*i*y\"\n\
                [[family]]\nname = \"J\"\nvalue = \"B^m*exp(-i*n*theta)\"\n\
                eigenvalue = \"i*(2*m - n*p_theta)\"\n\
                [[family]]\nname = \"F\"\nvalue = \"A^m*B^n\"\n\
                eigenvalue = \"i*(m + 2*n)\"\n";
    std::fs::write(dir.join("abf.toml"), file).expect("write");
    let o = superint_in(&dir, &["tower", "--system", "abf.toml", "--max", "1"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert_eq!(
        out.matches("{UV, H} = U{V, H} + V{U, H}").count(),
        2,
        "{out}"
    );
    assert_eq!(
        out.matches("so {U, H} = λ_U U and {V, H} = λ_V V").count(),
        2,
        "{out}"
    );
    assert!(!out.contains("λ_F") && !out.contains("{FG, H}"), "{out}");
    // JSON carries the names its lemma uses, and the derivation checked in them.
    let o = superint_in(
        &dir,
        &[
            "tower", "--system", "abf.toml", "--max", "1", "--format", "json",
        ],
    );
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
    let proofs = json["proofs"].as_array().expect("proofs");
    assert_eq!(proofs.len(), 2, "{json}");
    for p in proofs {
        assert_eq!(p["bases"], serde_json::json!(["U", "V"]), "{json}");
        assert_eq!(p["derivation"], "{UV, H} = U{V, H} + V{U, H}", "{json}");
        assert!(p["lemma"].as_str().unwrap().contains("λ_U"), "{json}");
    }
}

/// A tower says its system's name as the titles do: `for my oscillator`, in every format (it
/// said `for the my oscillator`), the harmonic rotor's `for the harmonic rotor`, and a file
/// that names no system by its stem.
#[test]
fn tower_lines_keep_a_names_own_article() {
    let dir = scratch("tower-article");
    let file = "name = \"my oscillator\"\nhamiltonian = \"p_x^2/2 + x^2/2\"\n\
                [phase_space]\ncoordinates = [\"x\"]\n\
                [[family]]\nname = \"K\"\nvalue = \"(p_x + i*x)^m*(p_x - i*x)^n\"\n\
                eigenvalue = \"i*(m - n)\"\n";
    std::fs::write(dir.join("mine.toml"), file).expect("write");
    for (format, said) in [
        ("text", "expanded for my oscillator (ladder"),
        ("markdown", "expanded for my oscillator (ladder"),
        ("latex", r"expanded for my oscillator (ladder"),
    ] {
        let args = [
            "tower",
            "--system",
            "mine.toml",
            "--max",
            "2",
            "--format",
            format,
        ];
        let o = superint_in(&dir, &args);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
        let out = text(&o.stdout);
        assert!(out.contains(said), "{format}: {out}");
        assert!(out.contains("of my oscillator"), "{format}: {out}");
    }
    let out = run(&["tower", "--max", "1", "--no-timings"], 0);
    assert!(out.contains("expanded for the harmonic rotor"), "{out}");
    // A file that names no system is its stem, in the title and the line alike (the line
    // said `for the t1`).
    let unnamed = file.replacen("name = \"my oscillator\"\n", "", 1);
    std::fs::write(dir.join("t1.toml"), unnamed).expect("write");
    let o = superint_in(&dir, &["tower", "--system", "t1.toml", "--max", "2"]);
    let out = text(&o.stdout);
    assert!(out.contains("expanded for t1 (ladder"), "{out}");
    assert!(out.contains("{K_{m,n}, H} for t1"), "{out}");
}

/// Rank 0 has no minor to show: its certificate is the vanishing gradients alone (it read
/// "the minor ∂()/∂() = 1 ≠ 0").
#[test]
fn rank_zero_shows_no_empty_minor() {
    for format in ["text", "markdown", "latex"] {
        let out = run(
            &[
                "rank",
                "systems/harmonic-rotor.toml",
                "M*omega",
                "--format",
                format,
                "--no-timings",
            ],
            0,
        );
        assert!(!out.contains("∂()") && !out.contains("rows  and"), "{out}");
        let one_by_one = ["every 1 × 1", "every `1 × 1`", r"every $1 \times 1$"];
        assert!(
            one_by_one.iter().any(|m| out.contains(m)) && out.contains("vanishes identically"),
            "{out}"
        );
        assert!(!out.contains("≥ 0") && !out.contains(r"\ge 0"), "{out}");
    }
}

/// `tower --when` checks a family at values of parameters: `K = (p_x + ix)^m (p_x − ix)^n`
/// has the eigenvalue `i(m − n)` at `a = 1` only, where the tower and the proof hold; without
/// the condition both are refuted, and a condition on phase space is refused.
#[test]
fn tower_at_values_of_parameters() {
    let dir = scratch("tower-when");
    let file = "hamiltonian = \"p_x^2/2 + a*x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n\
                parameters = [\"a\"]\n[[family]]\nname = \"K\"\n\
                value = \"(p_x + i*x)^m*(p_x - i*x)^n\"\neigenvalue = \"i*(m - n)\"\n";
    std::fs::write(dir.join("a.toml"), file).expect("write");
    let tower = |extra: &[&str]| {
        let mut args = vec!["tower", "--system", "a.toml", "--max", "2", "--no-timings"];
        args.extend(extra);
        superint_in(&dir, &args)
    };
    let out = text(&tower(&["--when", "a = 1"]).stdout);
    assert!(out.contains("at a = 1       [K-tower proved]"), "{out}");
    assert!(out.contains("at a = 1       [K-all proved]"), "{out}");
    let everywhere = text(&tower(&[]).stdout);
    assert!(everywhere.contains("[K-tower REFUTED]"), "{everywhere}");
    assert!(everywhere.contains("[K-all REFUTED]"), "{everywhere}");
    let o = tower(&["--when", "a = x"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        text(&o.stderr).contains("a tower's condition may set parameters only"),
        "{}",
        text(&o.stderr)
    );
}

/// `tower --when` refuses a condition at the value in `--when` that makes it fail: one that
/// sets a phase variable, or a parameter to one (it had no place), one that sets to 0 a
/// parameter `H` divides by (it was checked at `M = 0` and exited 0, the tower's brackets
/// holding no `1/M`), and one that sets to 0 a parameter a family divides by (it was shown at
/// the family's `name = "K"` in the file).
#[test]
fn tower_refuses_a_condition_at_its_value_in_when() {
    let dir = scratch("tower-when-placed");
    let file = "hamiltonian = \"p_x^2/(2*M) + a*x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n\
                parameters = [\"a\", \"M\", \"c\"]\n[[family]]\nname = \"K\"\n\
                value = \"(p_x + i*x)^m*(p_x - i*x)^n/c\"\neigenvalue = \"i*(m - n)\"\n";
    std::fs::write(dir.join("a.toml"), file).expect("write");
    let phase = "a tower's condition may set parameters only, to numbers or other parameters, \
                 and it holds";
    for (when, message) in [
        (
            "x = 0",
            format!("<command line>:1:5: --when: {phase} x, a coordinate"),
        ),
        (
            "a = 1, M = p_x",
            format!("<command line>:1:12: --when: {phase} p_x, a momentum"),
        ),
        (
            "a = 1, M = 0",
            "<command line>:1:12: the condition sets M = 0, but the Hamiltonian divides by M: \
             give M a value other than 0, or leave it free\n 1 | a = 1, M = 0\n   |            ^"
                .to_string(),
        ),
        (
            "c = 0, a = 1",
            "<command line>:1:5: the condition sets c = 0, but the tower divides by c: give c a \
             value other than 0, or leave it free\n 1 | c = 0, a = 1\n   |     ^"
                .to_string(),
        ),
    ] {
        let o = superint_in(
            &dir,
            &["tower", "--system", "a.toml", "--max", "2", "--when", when],
        );
        assert_eq!(o.status.code(), Some(2), "{when}: {}", text(&o.stdout));
        assert!(
            text(&o.stderr).contains(&message),
            "{when}: {}",
            text(&o.stderr)
        );
        assert!(!text(&o.stderr).contains("panicked"), "{}", text(&o.stderr));
    }
    // A family that divides by c only past K_{1,1} (c^(m − 1)): the tower met it at K_{2,1}
    // and it was shown at the family's name = "K" in the file (b.toml:6:8).
    let later = file.replace("/c\"", "/c^(m - 1)\"");
    std::fs::write(dir.join("b.toml"), later).expect("write");
    let o = superint_in(
        &dir,
        &[
            "tower",
            "--system",
            "b.toml",
            "--max",
            "2",
            "--when",
            "c = 0, a = 1",
        ],
    );
    assert_eq!(o.status.code(), Some(2), "{}", text(&o.stdout));
    assert!(
        text(&o.stderr).starts_with(
            "superint: error: <command line>:1:5: the condition sets c = 0, but the tower \
             divides by c: give c a value other than 0, or leave it free\n 1 | c = 0, a = 1\n   \
             |     ^"
        ),
        "{}",
        text(&o.stderr)
    );
}

/// Every family of a file with an eigenvalue has its tower checked, each in its own section:
/// the harmonic rotor's `K_{m,n}` and `K̄_{m,n}` (it checked `K` alone), both expanded and
/// proved for all `m, n`, four claims in all; `P` and `Q`, which declare no eigenvalue, are
/// passed over. The JSON has the two sections, towers and proofs.
#[test]
fn tower_checks_every_family_with_an_eigenvalue() {
    let args = [
        "tower",
        "--system",
        "systems/harmonic-rotor.toml",
        "--max",
        "2",
        "--no-timings",
    ];
    let out = run(&args, 0);
    assert!(
        out.starts_with("The towers of K_{m,n} and K̄_{m,n}, 1 ≤ m, n ≤ 2\n"),
        "{out}"
    );
    let sections: Vec<&str> = out
        .lines()
        .filter(|l| l.contains("} for the harmonic rotor"))
        .collect();
    assert_eq!(
        sections,
        [
            "1  {K_{m,n}, H} for the harmonic rotor",
            "2  {K̄_{m,n}, H} for the harmonic rotor"
        ]
    );
    let verdicts = [
        "[K-tower proved]",
        "[K-all proved]",
        "[Kbar-tower proved]",
        "[Kbar-all proved]",
    ];
    let places: Vec<Option<usize>> = verdicts.iter().map(|v| out.find(v)).collect();
    assert!(places.iter().all(Option::is_some), "{out}");
    assert!(places.is_sorted(), "{out}");
    assert!(
        out.contains("Therefore: {K̄_{m,n}, H} = −i(mω − nΩ) K̄_{m,n} for all m, n ≥ 0."),
        "{out}"
    );
    // The rotor's eigenvalue in the file's functions, as the family's eigenvalue writes it.
    assert!(
        out.contains("2. computed: {e^{−iθ}, H} = −i Ω e^{−iθ}")
            && out.contains("2. computed: {e^{iθ}, H} = i Ω e^{iθ}"),
        "{out}"
    );
    assert!(
        !out.contains("P-tower") && !out.contains("{P_{m,n}, H}"),
        "{out}"
    );
    assert!(
        out.ends_with("\n4 claims in 1 file: 4 proved, 0 refuted; all as expected\n"),
        "{out}"
    );

    let json: Value =
        serde_json::from_str(&run(&[&args[..], &["--format", "json"]].concat(), 0)).expect("JSON");
    assert_eq!(
        json["title"],
        "The towers of K_{m,n} and K̄_{m,n}, 1 ≤ m, n ≤ 2"
    );
    assert_eq!(json["sections"].as_array().map(Vec::len), Some(2));
    let towers: Vec<Value> = (json["towers"].as_array().expect("towers").iter())
        .map(|t| serde_json::json!([t["section"], t["id"], t["family"], t["outcome"]]))
        .collect();
    assert_eq!(
        towers,
        [
            serde_json::json!([1, "K-tower", "K_{m,n}", "proved"]),
            serde_json::json!([2, "Kbar-tower", "K̄_{m,n}", "proved"])
        ]
    );
    assert_eq!(json["proofs"].as_array().map(Vec::len), Some(2));
    let summary = &json["summary"];
    assert_eq!(
        (summary["claims"].as_u64(), summary["proved"].as_u64()),
        (Some(4), Some(4))
    );
}

/// `superint tower --system systems/harmonic-rotor.toml --family FAMILY --max 1
/// --no-timings`, run at the workspace root.
fn harmonic_rotor_towers(family: &str) -> Output {
    let args = [
        "tower",
        "--system",
        "systems/harmonic-rotor.toml",
        "--family",
        family,
    ];
    superint_in(
        root(),
        &[&args[..], &["--max", "1", "--no-timings"]].concat(),
    )
}

/// `--family` names the towers to check: one name checks that family alone, under today's
/// title; a list separated by commas checks each in its own section, in the order given.
#[test]
fn tower_family_takes_one_name_or_a_list_in_order() {
    let tower = |family: &str| {
        let o = harmonic_rotor_towers(family);
        assert_eq!(o.status.code(), Some(0), "{family}: {}", text(&o.stderr));
        text(&o.stdout)
    };
    let one = tower("K");
    assert!(
        one.starts_with("The tower of K_{m,n}, 1 ≤ m, n ≤ 1\n"),
        "{one}"
    );
    assert!(
        one.contains("[K-tower proved]") && one.contains("[K-all proved]"),
        "{one}"
    );
    assert!(!one.contains("Kbar") && !one.contains("\n2  "), "{one}");
    assert!(
        one.ends_with("\n2 claims in 1 file: 2 proved, 0 refuted; all as expected\n"),
        "{one}"
    );

    for (list, first, second) in [("K,Kbar", "K", "Kbar"), ("Kbar, K", "Kbar", "K")] {
        let both = tower(list);
        let place = |family: &str| both.find(&format!("[{family}-tower proved]"));
        assert!(
            place(first).is_some() && place(first) < place(second),
            "{list}: {both}"
        );
        assert!(both.contains("\n2  {"), "{list}: {both}");
        assert!(
            both.ends_with("\n4 claims in 1 file: 4 proved, 0 refuted; all as expected\n"),
            "{both}"
        );
    }
    assert!(tower("Kbar,K").starts_with("The towers of K̄_{m,n} and K_{m,n}, 1 ≤ m, n ≤ 1\n"));
}

/// A file whose second family declares a wrong eigenvalue, `i(m + n)` for
/// `(p_x + ix)^m (p_x − ix)^n`: its tower and proof are refuted in its own section, while the
/// first family's, in the same file and run, are proved; the run exits 1.
#[test]
fn tower_refutes_a_wrong_eigenvalue_in_its_own_section() {
    let dir = scratch("tower-two-families");
    std::fs::write(dir.join("two.toml"), crate::TWO_TOWERS).expect("write");
    let o = superint_in(
        &dir,
        &[
            "tower",
            "--system",
            "two.toml",
            "--max",
            "2",
            "--no-timings",
        ],
    );
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}{}", text(&o.stderr));
    let second = out
        .find("\n2  {W_{m,n}, H} for the oscillator\n")
        .expect("a section of W");
    let (first, second) = out.split_at(second);
    assert!(
        first.contains("[K-tower proved]") && first.contains("[K-all proved]"),
        "{out}"
    );
    assert!(
        second.contains("[W-tower REFUTED]") && second.contains("[W-all REFUTED]"),
        "{out}"
    );
    assert!(
        second.contains("fails for (m, n) in [(1, 1), (1, 2), (2, 1), (2, 2)]"),
        "{out}"
    );
    assert!(
        out.ends_with(
            "\n4 claims in 1 file: 2 proved, 2 refuted; 2 NOT as expected: W-tower, W-all\n"
        ),
        "{out}"
    );
}

/// `--family` refuses a list with an unknown name (exit 2, naming it and the declared
/// families), a family with no eigenvalue, a name given twice and an empty name, before any
/// bracket is formed: nothing is printed. A name, or the comma beside an empty one, is placed in
/// the list (`<command line>:1:C: --family:`).
#[test]
fn tower_family_list_refuses_bad_names() {
    for (family, message) in [
        (
            "K,Nope",
            "superint: error: <command line>:1:3: --family: no family named 'Nope' (the file \
             declares K, Kbar, P, Q)",
        ),
        (
            "K,P",
            "superint: error: systems/harmonic-rotor.toml:68:8: the family 'P' declares no \
             eigenvalue",
        ),
        (
            "K,Kbar,K",
            "superint: error: <command line>:1:8: --family: the family 'K' is named twice: each \
             tower is checked once",
        ),
        (
            "K,,Kbar",
            "superint: error: <command line>:1:2: --family: a family's name is missing after \
             this comma: families are named separated by commas, such as K,Kbar",
        ),
    ] {
        let o = harmonic_rotor_towers(family);
        assert_eq!(o.status.code(), Some(2), "{family}");
        assert_eq!(text(&o.stderr).lines().next(), Some(message), "{family}");
        assert!(o.stdout.is_empty(), "{family}");
    }
}

/// Every refusal of `--family` that is about a place in its list is said as `--fix`'s are,
/// `<command line>:1:C: --family:`, then the list and a caret under the place: a name that no
/// family has, a family named twice, the comma beside an empty name, because the refusals named
/// the file alone (`systems/harmonic-rotor.toml: no family named 'zz'`) with no place, and
/// quoted the whole list for an empty name. That comma is the one before the empty name
/// (`after this comma`), or after it for the first (`before this comma`), as every other list
/// says (`blank_beside_comma`); it was the comma after it, or before it for the last, `missing
/// beside this comma`.
#[test]
fn tower_family_list_refuses_at_its_place_as_fix_does() {
    for (family, message) in [
        (
            "K, zz",
            "superint: error: <command line>:1:4: --family: no family named 'zz' (the file \
             declares K, Kbar, P, Q)\n 1 | K, zz\n   |    ^^\n",
        ),
        (
            "Kbar,K,Kbar",
            "superint: error: <command line>:1:8: --family: the family 'Kbar' is named twice: \
             each tower is checked once\n 1 | Kbar,K,Kbar\n   |        ^^^^\n",
        ),
        (
            "K, ,Kbar",
            "superint: error: <command line>:1:2: --family: a family's name is missing after \
             this comma: families are named separated by commas, such as K,Kbar\n\
             \x201 | K, ,Kbar\n\x20\x20\x20|  ^\n",
        ),
        (
            "K,",
            "superint: error: <command line>:1:2: --family: a family's name is missing after \
             this comma: families are named separated by commas, such as K,Kbar\n\
             \x201 | K,\n\x20\x20\x20|  ^\n",
        ),
        (
            ",K",
            "superint: error: <command line>:1:1: --family: a family's name is missing before \
             this comma: families are named separated by commas, such as K,Kbar\n\
             \x201 | ,K\n\x20\x20\x20| ^\n",
        ),
    ] {
        let o = harmonic_rotor_towers(family);
        assert_eq!(o.status.code(), Some(2), "{family}");
        assert_eq!(text(&o.stderr), message, "{family}");
        assert!(o.stdout.is_empty(), "{family}");
    }
}

/// A blank `--family` (`''`, `'  '`) is said to be blank, where it ends, as a blank function
/// name is (`expected the name of a family, found end of input`): it said `no family named ''`,
/// as if a family could be called so.
#[test]
fn tower_a_blank_family_is_said_to_be_blank() {
    for (family, column, line) in [("", 1, " 1 | \n   | ^\n"), ("  ", 3, " 1 |   \n   |   ^\n")] {
        let o = harmonic_rotor_towers(family);
        assert_eq!(o.status.code(), Some(2), "{family:?}");
        assert_eq!(
            text(&o.stderr),
            format!(
                "superint: error: <command line>:1:{column}: --family: expected the name of a \
                 family, found end of input\n{line}"
            ),
            "{family:?}"
        );
        assert!(o.stdout.is_empty(), "{family:?}");
    }
}

#[test]
fn check_exit_status_follows_expectations() {
    let dir = scratch("expectations");
    let wrong = BASE.replace("i*omega*A\"", "-i*omega*A\"");
    std::fs::write(dir.join("wrong.toml"), &wrong).expect("write");
    let o = superint_in(&dir, &["check", "wrong.toml", "--no-timings"]);
    assert_eq!(o.status.code(), Some(1));
    let out = text(&o.stdout);
    assert!(out.contains("[ladder REFUTED]"), "{out}");
    assert!(
        out.contains("residual lhs − rhs = 2iω p_x − 2Mω²x"),
        "{out}"
    );
    assert!(out.ends_with("1 claim in 1 file: 0 proved, 1 refuted; 1 NOT as expected: ladder\n"));
    // Marked as deliberately false, the same claim meets its expectation.
    let marked = wrong.replace("id = \"ladder\"", "id = \"ladder\"\nexpect = \"refuted\"");
    std::fs::write(dir.join("marked.toml"), &marked).expect("write");
    let out = text(&superint_in(&dir, &["check", "marked.toml"]).stdout);
    assert!(out.contains("[ladder refuted, as expected]"), "{out}");
    // A true claim marked as false does not.
    let proved = BASE.replace("id = \"ladder\"", "id = \"ladder\"\nexpect = \"refuted\"");
    std::fs::write(dir.join("proved.toml"), &proved).expect("write");
    let o = superint_in(&dir, &["check", "proved.toml"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o.stdout).contains("[ladder PROVED, expected refuted]"));
}

/// A rank claim is of kind `rank` in JSON, with its certificate under the same id in
/// `ranks`: it compares no two sides and has no residual, where it was of kind `identity`.
#[test]
fn a_rank_claims_kind_is_rank_in_json() {
    let claims_of = |file: &str| {
        let v = crate::superint_json(&["check", file, "--no-timings"]);
        let claims = v["claims"].as_array().expect("claims").clone();
        (claims, v["ranks"].as_array().expect("ranks").len())
    };
    // `rank(H, Hx, C) = 3` and `rank(H, Hx, C, S) = 3`, beside identities.
    let (claims, ranks) = claims_of("systems/anisotropic-oscillator-1-2.toml");
    let kind = |c: &Value| (c["id"].as_str().unwrap().to_string(), c["kind"].clone());
    let kinds: Vec<_> = claims
        .iter()
        .map(kind)
        .filter(|(id, _)| id.starts_with('r'))
        .collect();
    let expected = [("relation", "identity"), ("rank", "rank"), ("rank", "rank")];
    assert_eq!(
        kinds,
        expected.map(|(id, k)| (id.to_string(), Value::from(k)))
    );
    assert_eq!(ranks, 2);
    // A refuted rank has no residual: its note says the rank found.
    let (claims, _) = claims_of("systems/harmonic-rotor.toml");
    let refuted = claims
        .iter()
        .find(|c| c["id"] == "false-C17-rank")
        .expect("a rank");
    assert_eq!(refuted["kind"], "rank");
    assert_eq!(refuted["outcome"], "refuted");
    assert_eq!(refuted["note"], "the rank is 4");
    assert!(refuted["residual"].is_null());
}

#[test]
fn check_json_is_one_object_per_claim() {
    let out = run(
        &[
            "check",
            "systems/harmonic-rotor.toml",
            "--format",
            "json",
            "--no-timings",
        ],
        0,
    );
    let v: Value = serde_json::from_str(&out).expect("JSON");
    assert_eq!(v["schema"], "superint-report/1");
    assert_eq!(v["summary"]["all_as_expected"], true);
    assert_eq!(
        v["sections"][0]["title"],
        "harmonic rotor (systems/harmonic-rotor.toml)"
    );
    let claims = v["claims"].as_array().expect("claims");
    assert_eq!(v["summary"]["checks"], claims.len());
    for c in claims {
        for key in [
            "id",
            "statement",
            "condition",
            "expect",
            "outcome",
            "meets_expectation",
            "residual",
            "seconds",
        ] {
            assert!(c.get(key).is_some(), "{key} missing in {c}");
        }
        assert_eq!(c["meets_expectation"], true, "{c}");
        assert!(c["seconds"].is_null(), "{c}");
        match c["outcome"].as_str() {
            Some("proved") => assert!(c["residual"].is_null(), "{c}"),
            // An identity has its residual; a rank, the rank found.
            Some("refuted") => assert!(c["residual"].is_string() || c["note"].is_string(), "{c}"),
            other => panic!("outcome {other:?}"),
        }
    }
    let c16 = claims
        .iter()
        .find(|c| c["id"] == "C16-off")
        .expect("C16-off");
    assert_eq!(c16["expect"], "refuted");
    assert_eq!(c16["condition"], "p_θ = Iω");
    // The condition as superint reads it back: the same surface, read again by `--when`.
    assert_eq!(c16["condition_ascii"], "p_theta = omega*I");
    let read_back = run(
        &[
            "expand",
            "systems/harmonic-rotor.toml",
            "p_theta",
            "--when",
            c16["condition_ascii"].as_str().expect("a string"),
            "--no-timings",
        ],
        0,
    );
    assert!(read_back.contains("    p_θ = ωI\n"), "{read_back}");
    assert!(c16["residual"]
        .as_str()
        .expect("a residual")
        .contains("cos(3*theta)"));
    let sw = run(
        &[
            "check",
            "systems/smorodinsky-winternitz-i.toml",
            "--format",
            "json",
        ],
        0,
    );
    let v: Value = serde_json::from_str(&sw).expect("JSON");
    assert!(v["claims"][0]["seconds"].is_number());
    assert!(v["summary"]["seconds"].is_number());
}

#[test]
fn check_every_format_renders() {
    let file = "systems/anisotropic-oscillator-1-2.toml";
    let md = run(&["check", file, "--format", "markdown", "--no-timings"], 0);
    assert!(
        md.contains("- `{a, H} = iω a` — **ladders proved**"),
        "{md}"
    );
    assert!(md.contains("**false-sign refuted, as expected**"), "{md}");
    let tex = run(&["check", file, "--format", "latex", "--no-timings"], 0);
    assert!(tex.starts_with("\\documentclass{article}") && tex.is_ascii());
    assert!(
        tex.contains(r"\tag*{[false-sign refuted, as expected]}"),
        "{tex}"
    );
    let txt = run(&["check", file, "--no-timings"], 0);
    assert!(txt.contains("Source: J. M. Jauch, E. L. Hill"));
}

#[test]
fn bracket_prints_the_normal_form() {
    let f = "systems/harmonic-rotor.toml";
    let out = run(&["bracket", f, "G1", "G2", "--no-timings"], 0);
    assert!(
        out.contains("\n    {G1, G2} = −ω²x p_y + ω²y p_x\n"),
        "{out}"
    );
    let v: Value = serde_json::from_str(&run(&["bracket", f, "L", "G1", "--format", "json"], 0))
        .expect("JSON");
    let line = &v["equations"][0]["lines"][0];
    assert_eq!(line["lhs"], "{L, G1}");
    assert_eq!(
        line["ascii"],
        "-p_x^2/(2*M) + p_y^2/(2*M) - M*omega^2*x^2/2 + M*omega^2*y^2/2"
    );
    // Off resonance P_{2,3} moves; on it, it does not.
    let on = run(
        &[
            "bracket",
            f,
            "P_{2,3}",
            "H",
            "--when",
            "p_theta = 2*I*omega/3",
            "--no-timings",
        ],
        0,
    );
    assert!(on.contains("{P_{2,3}, H} = 0"), "{on}");
    assert!(on.contains("at p_θ = 2Iω/3"), "{on}");
}

/// The output of a command on a system but the heading that names where the system came
/// from (`harmonic rotor (systems/harmonic-rotor.toml)`, `… (--system harmonic)`).
fn without_origin(out: &str) -> String {
    out.lines()
        .filter(|l| !l.contains("harmonic rotor (") && !l.chars().all(|c| c == '═'))
        .collect::<Vec<_>>()
        .join("\n")
}

/// `bracket`, `expand`, `table` and `rank` take a built-in system by --system, as `search`
/// and `closure` do, with its functions and its resonant ones (`P_1_1`, `P11`), and give what
/// they give with the file of the same system: they took only a FILE, and `--system` was
/// refused as an unexpected argument.
#[test]
fn bracket_expand_table_and_rank_take_a_built_in_system() {
    let f = "systems/harmonic-rotor.toml";
    let when = "p_theta = I*omega";
    let commands: [&[&str]; 6] = [
        &["bracket", "G1", "G2"],
        &["bracket", "P_1_1", "H", "--when", when],
        &["expand", "{G1, G2}", "Z^2", "{P_1_1, H}", "--when", when],
        &["table", "F1", "F2", "L", "G1", "G2"],
        &["rank", "F1", "F2", "G1", "G2", "P_1_1", "--expect", "5"],
        &["rank", "F1", "G1", "G2", "P_1_1", "--when", when],
    ];
    for command in commands {
        let (name, rest) = command.split_first().expect("a command");
        let with_file = run(&[&[*name, f], rest, &["--no-timings"]].concat(), 0);
        let args = [&[*name, "--system", "harmonic"], rest, &["--no-timings"]].concat();
        let built_in = run(&args, 0);
        assert!(
            built_in.contains("harmonic rotor (--system harmonic)"),
            "{built_in}"
        );
        // (The file has a parameter l more, at which a rank's point is written too.)
        let kept = |out: &str| match *name {
            "rank" => out.lines().filter(|l| l.starts_with("  rank ")).collect(),
            _ => without_origin(out),
        };
        assert_eq!(kept(&built_in), kept(&with_file), "{args:?}");
    }
    let out = run(
        &[
            "bracket",
            "--system",
            "harmonic",
            "G1",
            "G2",
            "--no-timings",
        ],
        0,
    );
    assert!(out.contains("\n             = −ω² L\n"), "{out}");
    // A built-in system is named as `search --system` titles it, not by its engine's name
    // (`the gravity rotor`, `the planar limit V_I with rotor`).
    for (system, title) in [
        ("gravity", "{L, H} for the rotor under gravity\n"),
        ("planar-i", "{L, H} for the rotor with V_I\n"),
    ] {
        let out = run(
            &["bracket", "--system", system, "L", "H", "--no-timings"],
            0,
        );
        assert!(out.starts_with(title), "{out}");
        let search = [
            &["search", "--system", system][..],
            &crate::DEGREE_ONE_TRIG_ZERO,
            &["--laurent", "--no-timings"],
        ]
        .concat();
        let search = run(&search, 0);
        let name = title.trim_end().trim_start_matches("{L, H} for the ");
        assert!(
            search.starts_with(&format!("Integrals of the {name}\n")),
            "{search}"
        );
    }
    // A resonant function by its built-in name, and a table of every function without them.
    let out = run(
        &[
            "rank", "--system", "harmonic", "F1", "F2", "G1", "G2", "P11",
        ],
        0,
    );
    assert!(
        out.contains("P_{1,1})/∂(x, y, θ, p_x, p_y, p_θ) = 5"),
        "{out}"
    );
    // A name run together is warned of as `search --system` warns of it: a built-in system
    // has no file to declare a name in.
    let together = crate::superint(&[
        "bracket",
        "--system",
        "harmonic",
        "G1y",
        "H",
        "--no-timings",
    ]);
    let warned = String::from_utf8(together.stderr).expect("UTF-8");
    assert!(
        warned.contains("is read as the product G1 y, the function G1 with y after it: write"),
        "{warned}"
    );
    assert!(!warned.contains("declare"), "{warned}");
    // No file to count: `1 claim: …`, not `1 claim in 1 file: …`, which a file's rank says.
    assert!(
        out.contains("\n1 claim: 1 proved, 0 refuted; all as expected"),
        "{out}"
    );
    let v: Value = serde_json::from_str(&run(
        &["table", "--system", "harmonic", "--format", "json"],
        0,
    ))
    .expect("JSON");
    let functions = &v["tables"][0]["functions"];
    assert_eq!(functions[0], "F1", "{functions}");
    assert!(!functions.to_string().contains("P11"), "{functions}");
}

/// `--system` is refused as `search` refuses it: an unknown name with the list of the
/// built-in systems, and beside a FILE; and a FILE that is no file but a built-in system's
/// name says that a built-in system is given with --system.
#[test]
fn bracket_expand_table_and_rank_refuse_a_built_in_system_as_search_does() {
    let f = "systems/harmonic-rotor.toml";
    let commands: [&[&str]; 4] = [
        &["bracket", "L", "H"],
        &["expand", "L"],
        &["table", "L", "G1"],
        &["rank", "L", "G1"],
    ];
    let stderr = |args: &[&str]| {
        let o = superint_in(root(), args);
        assert_eq!(o.status.code(), Some(2), "superint {args:?}");
        text(&o.stderr)
    };
    for command in commands {
        let (name, rest) = command.split_first().expect("a command");
        let unknown = stderr(&[&[*name, "--system", "harmonc"], rest].concat());
        assert!(
            unknown.contains(
                "unknown system 'harmonc' (built-in: harmonic, gravity, anisotropic-3-5, \
                 anisotropic-1-2, planar-i, planar-ii)"
            ),
            "{unknown}"
        );
        let both = stderr(&[&[*name, "--system", "harmonic", f], rest].concat());
        assert!(
            both.contains(&format!("'{f}' cannot be used with '--system harmonic'")),
            "{both}"
        );
        let named = stderr(&[&[*name, "harmonic"], rest].concat());
        assert!(named.contains("harmonic: cannot read the file"), "{named}");
        assert!(
            named.contains("hint: harmonic is a built-in system: give it with --system harmonic"),
            "{named}"
        );
    }
}

/// A left side too wide to align on takes lines of its own, its right side below it after
/// `=`: aligned after a left side of 160 characters, the right side was written one word a
/// line at column 160. Here the sl(2) Casimir of the Calogero–Moser system, `2H Σx² − D²`,
/// less its expansion, is zero.
#[test]
fn expand_writes_a_long_left_side_on_lines_of_its_own() {
    let long = "2*H*(x^2 + y^2 + z^2) - (x*p_x + y*p_y + z*p_z)^2 - ((x*p_y - y*p_x)^2 \
                + (x*p_z - z*p_x)^2 + (y*p_z - z*p_y)^2 \
                + 2*g*(x^2 + y^2 + z^2)*(1/(x - y)^2 + 1/(x - z)^2 + 1/(y - z)^2))";
    let f = "systems/calogero.toml";
    let out = run(&["expand", f, long, "(x + y)^2", "--no-timings"], 0);
    assert!(out.lines().all(|l| l.chars().count() <= 96), "{out}");
    assert!(out.contains("1/(y − z)²))\n      = 0\n"), "{out}");
    assert!(
        out.contains("\n    (x + y)²\n      = x² + 2xy + y²\n"),
        "{out}"
    );
}

/// Two rotors coupled by `ε cos(θ − φ)` (`systems/coupled-rotors.toml`): every claim holds
/// as marked, the total momentum's conservation proved and `{p_θ, H} = 0` refuted; the
/// coupling prints as a physicist writes it, `ε cos(θ − φ)`, in text, LaTeX and the JSON's
/// ASCII, and the torque `{p_θ, H} = −∂H/∂θ = ε sin(θ − φ)` (by hand); with `--angles
/// powers`, as the product of the two rotors' directions, as before.
#[test]
fn coupled_rotors_print_their_coupling_as_cos_of_the_difference() {
    let f = "systems/coupled-rotors.toml";
    let out = run(&["check", f], 0);
    assert!(
        out.contains("7 claims in 1 file: 6 proved, 1 refuted; all as expected"),
        "{out}"
    );
    assert!(out.contains("residual lhs − rhs = ε sin(θ − φ)\n"), "{out}");
    let out = run(&["expand", f, "H", "V", "{p_theta, H}", "--no-timings"], 0);
    // The moments of inertia print as the header writes them, `I₁`, `I₂`.
    assert!(
        out.contains("\n    H        = p_θ²/(2 I₁) + p_φ²/(2 I₂) + ε cos(θ − φ)\n"),
        "{out}"
    );
    assert!(out.contains("\n    V        = ε cos(θ − φ)\n"), "{out}");
    assert!(out.contains("\n    {p_θ, H} = ε sin(θ − φ)\n"), "{out}");
    let latex = run(&["expand", f, "V", "--format", "latex"], 0);
    assert!(
        latex.contains(r"\varepsilon \cos(\theta - \varphi)"),
        "{latex}"
    );
    let v: Value =
        serde_json::from_str(&run(&["expand", f, "V", "--format", "json"], 0)).expect("JSON");
    assert_eq!(
        v["equations"][0]["lines"][0]["ascii"],
        "epsilon*cos(theta - phi)"
    );
    let powers = run(&["expand", f, "V", "--no-timings", "--angles", "powers"], 0);
    assert!(
        powers.contains("= ε cos θ cos φ + ε sin θ sin φ\n"),
        "{powers}"
    );
}

/// `expand` prints expressions in the normal form the claims are decided in: the Casimir
/// relation C10 expands to zero, and so does not a wrong neighbour of it; a condition applies
/// after the expansion.
#[test]
fn expand_prints_the_normal_form() {
    let f = "systems/harmonic-rotor.toml";
    let out = run(&["expand", f, "K_1_1", "sin(theta)^2", "--no-timings"], 0);
    assert!(
        out.contains(
            "\n    K_{1,1} = (p_x + i p_y + iMωx − Mωy) cos θ + (−i p_x + p_y + Mωx + iMωy) sin θ\n"
        ),
        "{out}"
    );
    assert!(out.contains("\n    sin²θ   = 1/2 − (cos 2θ)/2\n"), "{out}");
    // P_{1,2} = (p_x − Mωy) cos 2θ + (p_y + Mωx) sin 2θ by default, and with `--angles
    // powers` in the normal form's powers: A cos 2θ + B sin 2θ = −A + 2A cos²θ + 2B cos θ sin θ.
    let harmonics = run(&["expand", f, "P_1_2", "--no-timings"], 0);
    let shown = "\n    P_{1,2} = (p_x − Mωy) cos 2θ + (p_y + Mωx) sin 2θ\n";
    assert!(harmonics.contains(shown), "{harmonics}");
    let powers = run(
        &["expand", f, "P_1_2", "--no-timings", "--angles", "powers"],
        0,
    );
    let shown = "\n    P_{1,2} = −p_x + Mωy + (2 p_x − 2Mωy) cos²θ + (2 p_y + 2Mωx) cos θ sin θ\n";
    assert!(powers.contains(shown), "{powers}");
    let latex = run(
        &[
            "expand", f, "P_1_2", "--format", "latex", "--angles", "powers",
        ],
        0,
    );
    assert!(latex.contains(r"\cos^{2}\theta"), "{latex}");
    let latex = run(&["expand", f, "P_1_2", "--format", "latex"], 0);
    assert!(latex.contains(r"\right) \cos 2\theta + "), "{latex}");
    let casimir = "4*G1^2 + G2^2 + omega^2*L^2 - (F1 - F2)^2";
    let wrong = "4*G1^2 + G2^2 + omega^2*L^2 - F1^2";
    let v: Value =
        serde_json::from_str(&run(&["expand", f, casimir, wrong, "--format", "json"], 0))
            .expect("JSON");
    let lines = &v["equations"][0]["lines"];
    assert_eq!(lines[0]["ascii"], "0");
    // 4G1² + G2² + ω²L² − F1² = −2F1F2 + F2², worked out by hand from F1 = H, F2 = p_θ²/(2I).
    assert_eq!(
        lines[1]["ascii"],
        "-p_x^2*p_theta^2/(2*M*I) - p_y^2*p_theta^2/(2*M*I) - p_theta^4/(4*I^2) \
         - M*omega^2*x^2*p_theta^2/(2*I) - M*omega^2*y^2*p_theta^2/(2*I)"
    );
    // {P_{1,1}, H} vanishes at the resonance p_θ = Iω and not off it.
    let on = run(
        &[
            "expand",
            f,
            "{P_1_1, H}",
            "--when",
            "p_theta = I*omega",
            "--no-timings",
        ],
        0,
    );
    assert!(on.contains("at p_θ = Iω:\n    {P_{1,1}, H} = 0\n"), "{on}");
    let off = run(
        &[
            "expand",
            f,
            "{P_1_1, H}",
            "--when",
            "p_theta = 2*I*omega",
            "--no-timings",
        ],
        0,
    );
    assert!(!off.contains("{P_{1,1}, H} = 0\n"), "{off}");
    assert!(off.contains("at p_θ = 2Iω:\n    {P_{1,1}, H} = "), "{off}");
}

/// A condition whose values use the variables it sets is resolved before it applies: at
/// `p_θ = Iω, ω = 1/2` (in either order) `K = Z e^{−iθ}` is conserved, and at
/// `p_θ = 2Iω, ω = 1/2` it is not, with a residual in which ω is 1/2. They were refuted, and
/// the residual kept ω, when the values were substituted once, all at the same time.
#[test]
fn chained_conditions_are_resolved() {
    let dir = scratch("chained-conditions");
    let file = r#"name = "rotor"
hamiltonian = "(p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2 + p_theta^2/(2*I)"

[phase_space]
coordinates = ["x", "y"]
angles = ["theta"]
parameters = ["M", "omega", "I"]

[[function]]
name = "K"
value = "(p_x + i*p_y + i*M*omega*(x + i*y))*exp(-i*theta)"

[[claim]]
id = "resonance"
claim = "{K, H} = 0"
when = "p_theta = I*omega, omega = 1/2"

[[claim]]
id = "resonance, the other order"
claim = "{K, H} = 0"
when = ["omega = 1/2", "p_theta = I*omega"]

[[claim]]
id = "off resonance"
claim = "{K, H} = 0"
when = "p_theta = 2*I*omega, omega = 1/2"
expect = "refuted"

[[claim]]
id = "a chain to zero"
claim = "x*M = x*I"
when = "M = I, I = 0"
"#;
    std::fs::write(dir.join("chain.toml"), file).expect("write the file");
    let o = superint_in(&dir, &["check", "chain.toml", "--format", "json"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let v: Value = serde_json::from_str(&text(&o.stdout)).expect("JSON");
    let claims = v["claims"].as_array().expect("claims");
    let outcome = |id: &str| {
        let c = claims.iter().find(|c| c["id"] == id).expect(id);
        (
            c["outcome"].as_str().unwrap().to_string(),
            c.get("residual").cloned(),
        )
    };
    assert_eq!(outcome("resonance").0, "proved");
    assert_eq!(outcome("resonance, the other order").0, "proved");
    assert_eq!(outcome("a chain to zero").0, "proved");
    // {K, H} = i(ω − Ω)K = −(i/2)K at Ω = 2ω = 1: no ω left in the residual.
    let (off, residual) = outcome("off resonance");
    assert_eq!(off, "refuted");
    let residual = residual.expect("a residual").to_string();
    assert!(
        !residual.contains("omega") && !residual.contains('ω'),
        "{residual}"
    );
    // The search counts the integrals at the resolved point: the same space as `p_θ = I, ω = 1`.
    let f = "systems/harmonic-rotor.toml";
    let space = [
        "--momenta-degree",
        "2",
        "--positions-degree",
        "2",
        "--trig-degree",
        "1",
    ];
    let dimension = |when: &str| {
        let mut args = vec!["search", f, "--when", when, "--no-timings"];
        args.extend(space);
        let out = run(&args, 0);
        out.lines()
            .find(|l| l.starts_with("Dimension of the space of integrals"))
            .expect("the dimension")
            .to_string()
    };
    assert_eq!(
        dimension("p_theta = I*omega, omega = 1"),
        dimension("p_theta = I, omega = 1")
    );
}

/// `re(…)` and `im(…)` print as the paper's `Re` and `Im` (upright in LaTeX), and take the
/// parts of `Z = (p_x − Mωy) + i(p_y + Mωx)`.
#[test]
fn real_and_imaginary_parts_print_as_re_and_im() {
    let f = "systems/harmonic-rotor.toml";
    let parts = "re(Z)*im(Z)";
    let text = run(&["expand", f, parts, "--no-timings"], 0);
    assert!(
        text.contains("\n    Re(Z) Im(Z) = p_x p_y + Mωx p_x − Mωy p_y − M²ω²xy\n"),
        "{text}"
    );
    let latex = run(
        &["expand", f, parts, "--format", "latex", "--no-timings"],
        0,
    );
    assert!(
        latex.contains(r"\operatorname{Re}(Z) \operatorname{Im}(Z) &= p_{x} p_{y}"),
        "{latex}"
    );
}

/// A command reads all its arguments before it expands any: with a term limit that the first
/// expression's expansion passes, a slip in a later argument is still what is reported.
/// The inputs echoed in the paper's notation: a quotient that is a factor of a product is in
/// parentheses (`x/2y` and `5/7i` would read as `x/(2y)` and `5/(7i)`), and a sum's or a
/// minus sign's quotient is not; the result writes `i` on the numerator.
#[test]
fn echoed_quotients_inside_products_are_parenthesised() {
    let out = run(
        &[
            "bracket",
            "systems/harmonic-rotor.toml",
            "x/2*y + 3/2*i*x - x/2/3 - (x/2)",
            "p_x/(2*M)*y",
            "--no-timings",
        ],
        0,
    );
    assert!(
        out.contains(
            "{(x/2)y + (3/2)ix − x/2/3 − x/2, (p_x/(2M))y} = y²/(4M) + (−1/3 + 3i/4) y/M\n"
        ),
        "{out}"
    );
    // The trajectory's claim of the harmonic rotor's solution: `(p_x_0/M) cos φ`.
    let solution = run(
        &[
            "check",
            "systems/harmonic-rotor-solution.toml",
            "--no-timings",
        ],
        0,
    );
    assert!(
        solution.contains("ω {x(t), p_φ} = −ω x_0 sin φ + (p_x_0/M) cos φ"),
        "{solution}"
    );
}

#[test]
fn arguments_are_read_before_any_is_expanded() {
    let f = "systems/harmonic-rotor.toml";
    let (big, limit) = ("(P_{3,2})^6", "1000");
    // The limit is real: alone, the expansion stops at it.
    let alone = superint_in(root(), &["bracket", f, big, "H", "--max-terms", limit]);
    assert_eq!(alone.status.code(), Some(2));
    assert!(
        text(&alone.stderr).contains("more than 1000 terms"),
        "{}",
        text(&alone.stderr)
    );
    for (args, message) in [
        (
            vec!["bracket", f, big, "L - , G1"],
            "1:5: expected an expression after '-'",
        ),
        (
            vec!["bracket", f, big, "L", "--when", "p_theta ="],
            "one side is empty",
        ),
        (
            vec!["rank", f, big, "F1", "G1 +"],
            "1:5: expected an expression after '+'",
        ),
        (vec!["table", f, "K_30_1", "Foo"], "'Foo' is not a function"),
        // As a claim's condition in a file is: "division by zero" said neither what nor where.
        (
            vec!["expand", f, "x/M", "--when", "M = 0"],
            "the condition sets M = 0, but the expression divides by M",
        ),
        // And so is one whose own value divides by what another value sets to 0.
        (
            vec!["expand", f, "x", "--when", "M = 0, omega = 1/M"],
            "<command line>:1:16: the condition sets M = 0, but the value of ω divides by M",
        ),
        // Set to 0 through another variable, the divisor is named as the value writes it:
        // it was "sets I = 0, but the value of ω divides by I", of a value 1/M.
        (
            vec!["expand", f, "x", "--when", "M = I, I = 0, omega = 1/M"],
            "<command line>:1:23: the condition sets M = 0, but the value of ω divides by M",
        ),
        (
            vec!["expand", f, big, "L - "],
            "1:4: expected an expression after '-'",
        ),
        (
            vec!["expand", f, big, "--when", "theta = 0"],
            "a condition cannot fix an angle",
        ),
    ] {
        let args = [args, vec!["--max-terms", limit]].concat();
        let o = superint_in(root(), &args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(
            text(&o.stderr).contains(message),
            "{args:?}: {}",
            text(&o.stderr)
        );
    }
}

#[test]
fn table_is_the_su2_table() {
    let out = run(
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
    assert!(out.contains("    L     │ 0       −G2    4 G1\n"), "{out}");
    assert!(out.contains("    G1    │ G2      0      −ω² L\n"), "{out}");
    let v: Value = serde_json::from_str(&run(
        &[
            "table",
            "systems/gravity-rotor.toml",
            "Lp",
            "G1p",
            "G2p",
            "--format",
            "json",
        ],
        0,
    ))
    .expect("JSON");
    assert_eq!(v["tables"][0]["display"][0], "L'");
    // The text shows display names; the ASCII form, the file's names, which read back.
    assert_eq!(v["tables"][0]["entries"][0][1]["text"], "−G2'");
    assert_eq!(v["tables"][0]["entries"][0][1]["ascii"], "-G2p");
    assert_eq!(v["tables"][0]["entries"][1][2]["ascii"], "-omega^2*Lp");
    assert_eq!(v["sections"][0]["file"], "systems/gravity-rotor.toml");
    let expanded = run(
        &[
            "expand",
            "systems/gravity-rotor.toml",
            "omega^2*Lp",
            "--no-timings",
        ],
        0,
    );
    assert!(expanded.contains("ω² L' = "), "{expanded}");
}

#[test]
fn rank_prints_its_certificate() {
    let f = "systems/harmonic-rotor.toml";
    let out = run(
        &["rank", f, "F1", "F2", "G1", "G2", "P_1_1", "--no-timings"],
        0,
    );
    assert!(out.contains("= 5   [rank proved]"), "{out}");
    assert!(out.contains("≥ 5: the minor"), "{out}");
    run(
        &["rank", f, "F1", "F2", "G1", "G2", "L", "--expect", "4"],
        0,
    );
    let out = run(
        &["rank", f, "F1", "F2", "G1", "G2", "L", "--expect", "5"],
        1,
    );
    assert!(out.contains("the rank is 4"), "{out}");
    // The upper bound: five functions in six coordinates, rank 4, so (5 − 4)(6 − 4) = 2
    // minors border the nonzero one.
    assert!(
        out.contains("≤ 4: every 5 × 5 minor vanishes identically, as the 2 bordering"),
        "{out}"
    );
}

#[test]
fn tower_of_a_file_family_with_its_proof() {
    let out = run(
        &[
            "tower",
            "--system",
            "systems/gravity-rotor.toml",
            "--max",
            "2",
            "--no-timings",
        ],
        0,
    );
    assert!(out.contains("[Kp-tower proved]"), "{out}");
    assert!(out.contains("[Kp-all proved]"), "{out}");
    // The eigenvalue bare, as the paper writes it, where it is one term.
    assert!(out.contains("computed: {Z', H} = iω Z'"), "{out}");
    let out = run(
        &[
            "tower",
            "--system",
            "systems/anisotropic-oscillator-1-2.toml",
            "--max",
            "2",
            "--no-timings",
        ],
        0,
    );
    assert!(out.contains("[W-all proved]"), "{out}");
    assert!(
        out.contains("computed: {conj(b), H} = −2iω conj(b)"),
        "{out}"
    );
    assert!(out.contains("    Therefore: {W_{m,n}, H} = "), "{out}");
    // With a wrong eigenvalue a base fact fails, and the proof says that nothing follows.
    let dir = scratch("tower-wrong");
    let file = std::fs::read_to_string(root().join("systems/anisotropic-oscillator-1-2.toml"))
        .expect("the file");
    let wrong = file.replace("i*(m - 2*n)*omega", "i*(m + 2*n)*omega");
    assert_ne!(wrong, file);
    std::fs::write(dir.join("w.toml"), wrong).expect("write");
    let o = superint_in(&dir, &["tower", "--system", "w.toml", "--max", "1"]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert!(out.contains("[W-all REFUTED]"), "{out}");
    assert!(
        out.contains("    Not proved: a step above fails, so the lemma does not give"),
        "{out}"
    );
    assert!(!out.contains("Therefore"), "{out}");
    // A family that is not a product of powers A^m B^n: the bounded check only.
    let dir = scratch("tower");
    let family = "[[family]]\nname = \"S\"\nvalue = \"A^(m + n)\"\n\
                  eigenvalue = \"i*(m + n)*omega\"\n\n[[claim]]";
    std::fs::write(dir.join("s.toml"), BASE.replacen("[[claim]]", family, 1)).expect("write");
    let o = superint_in(&dir, &["tower", "--system", "s.toml", "--max", "2"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert!(out.contains("[S-tower proved]"), "{out}");
    assert!(out.contains("No proof for all m, n"), "{out}");
    let out = run(
        &[
            "tower",
            "--system",
            "systems/harmonic-rotor.toml",
            "--family",
            "P",
            "--max",
            "1",
        ],
        2,
    );
    assert!(out.is_empty());
}

/// The all-`m, n` proof decides `λ(m, n) = mλ(1, 0) + nλ(0, 1)` from the eigenvalue's values on
/// a grid as large as its degree, not from how it is written: `iω(m − n)^1 + mn − mn` is
/// proved (it was refuted as "not affine"), a term `m(m − 1)(m − 2)(m − 3)` that the bounded
/// check to 3 cannot see is refuted at `(4, 0)`, its verdict naming that step, and `1^n` gives
/// no proof, not a refutation.
#[test]
fn tower_decides_the_eigenvalue_by_its_values() {
    let dir = scratch("tower-eigenvalue");
    let tower = |eigenvalue: &str, code: i32| {
        let family = format!(
            "[[family]]\nname = \"W\"\nvalue = \"A^m*conj(A)^n\"\n\
             eigenvalue = \"{eigenvalue}\"\n\n[[claim]]"
        );
        std::fs::write(dir.join("w.toml"), BASE.replacen("[[claim]]", &family, 1)).expect("write");
        let args = ["tower", "--system", "w.toml", "--max", "3", "--no-timings"];
        let o = superint_in(&dir, &args);
        assert_eq!(
            o.status.code(),
            Some(code),
            "{eigenvalue}: {}",
            text(&o.stderr)
        );
        let out = text(&o.stdout);
        assert!(out.contains("[W-tower proved]"), "{out}");
        out
    };
    let out = tower("i*omega*(m - n)^1 + m*n - m*n", 0);
    assert!(out.contains("[W-all proved]"), "{out}");
    // The fact wraps: compare its words.
    let words = crate::normalize(&out);
    assert!(
        words.contains(
            "both are polynomials of degree at most 2 in m, n, and they agree at the 9 points"
        ),
        "{out}"
    );
    assert!(
        out.contains("{W_{m,n}, H} = (iω(m − n)¹ + mn − mn) W_{m,n} for all m, n ≥ 0"),
        "{out}"
    );
    let out = tower("i*omega*(m - n) + m*(m - 1)*(m - 2)*(m - 3)", 1);
    assert!(out.contains("[W-all REFUTED]"), "{out}");
    let words = crate::normalize(&out);
    assert!(words.contains("they differ at (m, n) = (4, 0)"), "{out}");
    // The verdict names the step that fails (it said "a base fact or the derivation check").
    assert!(
        out.contains("[W-all REFUTED]\n      step 3 fails\n"),
        "{out}"
    );
    let out = tower("i*omega*(m - n)*1^n", 0);
    assert!(out.contains("No proof for all m, n"), "{out}");
    assert!(!out.contains("W-all"), "{out}");
}

#[test]
fn every_new_help_shows_an_example() {
    for cmd in ["check", "bracket", "expand", "table", "rank", "tower"] {
        let out = run(&[cmd, "--help"], 0);
        assert!(out.contains("Examples:\n  superint"), "{cmd}");
        assert!(out.contains("--max-terms"), "{cmd}");
    }
}

/// An id that several claims of a file share names the claim that did not meet its
/// expectation with its statement: the summary said `2 NOT as expected: ladder, ladder`, of no
/// help to tell them apart. An id of one claim is named alone.
#[test]
fn a_shared_id_is_named_with_its_statement() {
    let dir = scratch("shared-id");
    let file = format!(
        "{BASE}\n[[claim]]\nid = \"ladder\"\nclaim = \"{{A, H}} = -i*omega*A\"\n\n[[claim]]\n\
         id = \"ladder\"\nclaim = \"{{conj(A), H}} = i*omega*conj(A)\"\n\n[[claim]]\n\
         id = \"alone\"\nclaim = \"{{A, H}} = 0\"\n"
    );
    std::fs::write(dir.join("shared.toml"), file).expect("write");
    let o = superint_in(&dir, &["check", "shared.toml", "--no-timings"]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert!(
        out.ends_with(
            "4 claims in 1 file: 1 proved, 3 refuted; 3 NOT as expected: ladder ({A, H} = −iω \
             A), ladder ({conj(A), H} = iω conj(A)), alone\n"
        ),
        "{out}"
    );
    let o = superint_in(
        &dir,
        &["check", "shared.toml", "shared.toml", "--no-timings"],
    );
    let out = text(&o.stdout);
    assert!(out.contains("ladder ({A, H} = −iω A; section 2)"), "{out}");
}

/// Ids are a file's own: the same id in two files is two claims, in the text's summary and in
/// the JSON's (which counted one, refuted, and lost the proved one), and the claim that did
/// not meet its expectation is named with its section.
#[test]
fn the_same_id_in_two_files_is_two_claims() {
    let dir = scratch("id-in-two-files");
    std::fs::write(
        dir.join("one.toml"),
        BASE.replace("id = \"ladder\"", "id = \"main\""),
    )
    .expect("write");
    let wrong = BASE
        .replace("id = \"ladder\"", "id = \"main\"")
        .replace("{A, H} = i*omega*A", "{A, H} = -i*omega*A");
    std::fs::write(dir.join("two.toml"), wrong).expect("write");
    let o = superint_in(&dir, &["check", "one.toml", "two.toml", "--no-timings"]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert!(
        out.contains(
            "2 claims in 2 files: 1 proved, 1 refuted; 1 NOT as expected: main (section 2)"
        ),
        "{out}"
    );
    let o = superint_in(&dir, &["check", "one.toml", "two.toml", "--format", "json"]);
    let v: Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let summary = &v["summary"];
    assert_eq!(
        (&summary["claims"], &summary["proved"], &summary["refuted"]),
        (&Value::from(2), &Value::from(1), &Value::from(1)),
        "{summary}"
    );
}

/// A claim is echoed so that it reads back: where one-letter names side by side spell another
/// name of the system (a coordinate `xy`, a function `Mx`), they are spaced.
#[test]
fn echoed_products_do_not_spell_another_name() {
    let dir = scratch("names-side-by-side");
    let coordinate = "name = \"xy\"\nhamiltonian = \"(p_x^2 + p_y^2 + p_xy^2)/2\"\n\
                      [phase_space]\ncoordinates = [\"x\", \"y\", \"xy\"]\n\
                      [[claim]]\nid = \"product\"\nclaim = \"{x*y, p_xy} = 0\"\n";
    let function = "name = \"Mx\"\nhamiltonian = \"p_x^2/2 + M*x\"\n\
                    [phase_space]\ncoordinates = [\"x\"]\nparameters = [\"M\"]\n\
                    [[function]]\nname = \"Mx\"\nvalue = \"M*p_x\"\n\
                    [[claim]]\nid = \"function\"\nclaim = \"{Mx, M*x} = -M^2\"\n";
    std::fs::write(dir.join("coordinate.toml"), coordinate).expect("write");
    std::fs::write(dir.join("function.toml"), function).expect("write");
    let o = superint_in(&dir, &["check", "coordinate.toml", "function.toml"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert!(out.contains("{x y, p_xy} = 0 "), "{out}");
    assert!(out.contains("{Mx, M x} = −M² "), "{out}");
    // The normal form too: M·x printed `Mx` read back as the function.
    let o = superint_in(&dir, &["expand", "function.toml", "M*x", "Mx"]);
    let out = text(&o.stdout);
    assert!(
        out.contains("M x = M x\n") && out.contains("Mx  = M p_x\n"),
        "{out}"
    );
    // Where nothing is spelled that way, factors stay side by side, as in the paper.
    let plain = superint_in(
        root(),
        &[
            "expand",
            "systems/harmonic-rotor.toml",
            "M*x*y",
            "--no-timings",
        ],
    );
    assert!(
        text(&plain.stdout).contains("Mxy = Mxy"),
        "{}",
        text(&plain.stdout)
    );
}

/// A product is spaced only where its letters would run into another name: in the V_II rotor,
/// which declares `Hx` and `Hy`, the false ladder `p_y + 2iMωy` is echoed as the paper writes
/// it (it was `p_y + 2i M ω y`, since `H` and `y` are written in the claim, though never side
/// by side), as the normal form prints it on the right; beside functions `xy` and `My`, the run
/// `2i M x y` is spaced, and the other products of the same claim are not (`Max`, `ax`, `2iMx`);
/// `H` beside `Hy` is a function's name, set apart as ever (`H y`); and letters run together
/// before parentheses that spell a function, `i·m·(x + y)`, still take their own, `(im)(x + y)`,
/// not the call `im(x + y)`.
#[test]
fn echoed_products_are_spaced_only_where_their_letters_spell_another_name() {
    let o = superint_in(
        root(),
        &[
            "check",
            "systems/smorodinsky-winternitz-ii-rotor.toml",
            "--no-timings",
        ],
    );
    let out = text(&o.stdout);
    assert!(
        out.contains("  {p_y + 2iMωy, H} = 2iω(p_y + 2iMωy) "),
        "{out}"
    );

    let dir = scratch("runs-side-by-side");
    let file = "name = \"runs\"\nhamiltonian = \"(p_x^2 + p_y^2)/2 + a*x\"\n\
                [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"M\", \"a\", \"m\"]\n\
                [[function]]\nname = \"xy\"\nvalue = \"x*p_y\"\n\
                [[function]]\nname = \"My\"\nvalue = \"M*p_y\"\n\
                [[function]]\nname = \"Hy\"\nvalue = \"p_y^2/2\"\n\
                [[claim]]\nclaim = \"{2*i*M*x*y + M*a*x, p_y} = 2*i*M*x\"\n\
                [[claim]]\nclaim = \"{M*y + a*x, p_y} = M\"\n\
                [[claim]]\nclaim = \"{H*y, y} = -y*p_y\"\n\
                [[claim]]\nclaim = \"{i*m*(x + y), p_x} = i*m\"\n";
    std::fs::write(dir.join("runs.toml"), file).expect("write the file");
    let o = superint_in(&dir, &["check", "runs.toml", "--no-timings"]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}{}", text(&o.stderr));
    for statement in [
        "  {2i M x y + Max, p_y} = 2iMx ",
        "  {M y + ax, p_y} = M ",
        "  {H y, y} = −y p_y ",
        "  {(im)(x + y), p_x} = im ",
    ] {
        assert!(out.contains(statement), "{statement:?} in\n{out}");
    }
}

/// An endless input is read only so far: to its first NUL byte, the binary file being refused
/// there (`check /dev/zero` read until memory ran out), and no further than
/// `MAX_FILE_BYTES` of text.
#[test]
fn an_endless_input_is_read_only_so_far() {
    use superint::system_file::{read_bytes, ErrorKind, FileError, MAX_FILE_BYTES};
    let cannot = |e: std::io::Error| FileError::new(ErrorKind::Io, "<zeros>", e.to_string());
    let zeros = read_bytes("<zeros>", std::io::repeat(0), cannot).expect("read");
    assert!(
        zeros.len() <= 1 << 16 && zeros.ends_with(&[0]),
        "{}",
        zeros.len()
    );
    assert_eq!(MAX_FILE_BYTES, 1 << 30);
    if Path::new("/dev/zero").exists() {
        let o = superint_in(root(), &["check", "/dev/zero"]);
        assert_eq!(o.status.code(), Some(2));
        assert!(
            text(&o.stderr).starts_with(
                "superint: error: /dev/zero:1:1: this is a binary file (it contains a NUL byte)"
            ),
            "{}",
            text(&o.stderr)
        );
    }
}

/// Runs the binary at the workspace root with `input` on its standard input.
fn superint_piped(args: &[&str], input: &str) -> Output {
    use std::io::Write;
    let mut child = Command::new(env!("CARGO_BIN_EXE_superint"))
        .args(args)
        .current_dir(root())
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("the superint binary runs");
    let mut stdin = child.stdin.take().expect("a pipe");
    stdin
        .write_all(input.as_bytes())
        .expect("the input is written");
    drop(stdin);
    child.wait_with_output().expect("the binary ends")
}

/// `-` names a system file on standard input, for scripts that write systems on the fly: it
/// checks as the file does, may be named twice (read once), and its errors say `<stdin>`.
#[test]
fn a_system_file_on_standard_input() {
    let kepler = std::fs::read_to_string(root().join("systems/kepler.toml")).expect("read");
    let from_file = run(&["check", "systems/kepler.toml", "--no-timings"], 0);
    let o = superint_piped(&["check", "-", "--no-timings"], &kepler);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    // The same report but for the file's name (and the rule under it, as long as the name).
    let without_rules = |out: &str| {
        out.lines()
            .filter(|l| !l.starts_with('═'))
            .collect::<Vec<_>>()
            .join("\n")
    };
    assert_eq!(
        without_rules(&text(&o.stdout).replace("(<stdin>)", "(systems/kepler.toml)")),
        without_rules(&from_file)
    );
    let o = superint_piped(&["check", "-", "-", "--no-timings"], &kepler);
    assert!(
        text(&o.stdout).contains("20 claims in 2 files: 14 proved, 6 refuted; all as expected"),
        "{}",
        text(&o.stdout)
    );
    let o = superint_piped(
        &["expand", "-", "x*p_x"],
        "name = \"broken\"\nhamiltonian = \"p_x^2/2 +\"\n[phase_space]\ncoordinates = [\"x\"]\n",
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(
        text(&o.stderr).starts_with(
            "superint: error: <stdin>:2:25: expected an expression after '+', found end of input"
        ),
        "{}",
        text(&o.stderr)
    );
}

/// A family instance before parentheses multiplies them, as any name there does (it was
/// "unknown function 'K_1_1'"), and the echo writes it `K_{1,1}(x)`; the functions of a bare
/// angle echo as the paper writes them, `cos θ` and `cos²θ`, and read back.
#[test]
fn family_instances_before_parentheses_and_trigonometric_echoes() {
    let dir = scratch("instance-before-parentheses");
    std::fs::write(
        dir.join("k.toml"),
        "hamiltonian = \"p_x^2/2 + p_theta^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n\
         angles = [\"theta\"]\n[[family]]\nname = \"K\"\nvalue = \"(x+i*p_x)^m*exp(-i*n*theta)\"\n",
    )
    .expect("write");
    let exprs = [
        "K_1_1 (x) - x*K_1_1",
        "K_{1,1}(x) - K_1_1*x",
        "cos(theta)^2 + sin(theta)*x - cos²θ - x sin θ",
        "sin(theta)^3^2 - sin(theta)^9",
    ];
    let o = superint_in(
        &dir,
        &[&["expand", "k.toml"][..], &exprs, &["--no-timings"]].concat(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    for echo in [
        "K_{1,1}(x) − x K_{1,1} ",
        "K_{1,1}(x) − K_{1,1} x ",
        // A factor after a sine sets it apart: `sin θ x` would read as the sine of `θx`.
        "cos²θ + (sin θ) x − cos²θ − x sin θ = 0",
        // Another power takes the angle in parentheses: `sin θ^(3²)` reads as ambiguous.
        "sin(θ)^(3²) − sin⁹θ ",
    ] {
        assert!(out.contains(echo), "{echo:?} in {out}");
    }
    assert_eq!(out.matches("= 0\n").count(), 4, "{out}");
    let echo = "sin(θ)^(3²) − sin⁹θ";
    let o = superint_in(&dir, &["expand", "k.toml", echo, "--no-timings"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
}

/// A sine or cosine of an integer multiple of a bare angle echoes as the paper and the normal
/// form write it, `sin 2θ` (it echoed `sin(2θ)`), and is set apart as `sin θ` is: `cos²3θ` for
/// its square (which reads as `(cos 3θ)²`), `(sin 2θ) x` and `(sin 2θ)/2` before a factor or a
/// denominator, where `sin 2θ x` and `sin 2θ/2` would read as the sine of `2θx` and of
/// `2θ/2`; a sum of angles, a negative multiple and any other power keep their parentheses.
/// Each echo reads back: the expression minus its echo expands to 0, in text and in LaTeX.
#[test]
fn a_multiple_of_a_bare_angle_echoes_as_the_paper_writes_it() {
    let dir = scratch("multiple-angle-echo");
    std::fs::write(
        dir.join("rotors.toml"),
        "hamiltonian = \"p_x^2/2 + p_theta^2/2 + p_phi^2/2\"\n[phase_space]\n\
         coordinates = [\"x\"]\nangles = [\"theta\", \"phi\"]\n",
    )
    .expect("write");
    let cases = [
        ("sin(2*theta)", "sin 2θ"),
        ("cos(3*theta)^2", "cos²3θ"),
        ("x*sin(2*theta)", "x sin 2θ"),
        ("sin(2*theta)*x", "(sin 2θ) x"),
        ("sin(2 theta)/2", "(sin 2θ)/2"),
        ("x*cos(3*phi)/2", "(x cos 3φ)/2"),
        ("sin(2*theta)*cos(3*phi)", "sin 2θ cos 3φ"),
        ("cos(2*theta)*sin(theta)*x", "(cos 2θ sin θ) x"),
        ("cos(2*theta - phi)", "cos(2θ − φ)"),
        ("sin(-2*theta)", "sin(−2θ)"),
        ("sin(2*theta)^(2^2)", "sin(2θ)^(2²)"),
    ];
    let exprs: Vec<&str> = cases.iter().map(|(e, _)| *e).collect();
    let o = superint_in(
        &dir,
        &[&["expand", "rotors.toml"][..], &exprs, &["--no-timings"]].concat(),
    );
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}{}", text(&o.stderr));
    let statements: Vec<&str> = out
        .lines()
        .filter_map(|l| l.split_once(" = "))
        .map(|(lhs, _)| lhs.trim())
        .filter(|lhs| !lhs.is_empty())
        .collect();
    let echoes: Vec<&str> = cases.iter().map(|(_, echo)| *echo).collect();
    assert_eq!(statements, echoes, "{out}");
    let differences: Vec<String> = cases
        .iter()
        .map(|(e, echo)| format!("{e} - ({echo})"))
        .collect();
    let differences: Vec<&str> = differences.iter().map(String::as_str).collect();
    let o = superint_in(
        &dir,
        &[&["expand", "rotors.toml", "--"][..], &differences].concat(),
    );
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}{}", text(&o.stderr));
    assert_eq!(out.matches(" = 0\n").count(), cases.len(), "{out}");
    // LaTeX writes them so too, and reads them back.
    let o = superint_in(
        &dir,
        &[
            "expand",
            "rotors.toml",
            "cos(3*theta)^2 + sin(2*theta)*x",
            "--format",
            "latex",
        ],
    );
    let latex = text(&o.stdout);
    let echo = r"\cos^{2}3\theta + (\sin 2\theta) x";
    assert!(latex.contains(&format!("{echo} &=")), "{latex}");
    let difference = format!("cos(3*theta)^2 + sin(2*theta)*x - ({echo})");
    let o = superint_in(
        &dir,
        &["expand", "rotors.toml", &difference, "--no-timings"],
    );
    assert!(
        text(&o.stdout).contains(" = 0\n"),
        "{}{}",
        text(&o.stdout),
        text(&o.stderr)
    );
}

/// `bracket` takes expressions that begin with a minus sign as they are (they were refused as
/// unknown options), and the options after them still count; `expand` takes them after `--`.
#[test]
fn expressions_may_begin_with_a_minus_sign() {
    let out = run(
        &[
            "bracket",
            "systems/kepler.toml",
            "-r",
            "-p_r",
            "--no-timings",
        ],
        0,
    );
    assert!(out.contains("{−r, −p_r} = 1\n"), "{out}");
    let out = run(
        &["expand", "systems/kepler.toml", "--no-timings", "--", "-r"],
        0,
    );
    assert!(out.contains("−r = −r\n"), "{out}");
}

/// A family's value may write an earlier family's instance with braces and its own index names,
/// `K_{m,n}` or `K_{a, 2}`, as claims write `K_{2,3}` (only `K_m_n` was taken there).
#[test]
fn family_values_write_instances_with_braces() {
    let dir = scratch("braces-in-family-values");
    std::fs::write(
        dir.join("f.toml"),
        "hamiltonian = \"p_x^2/2 + p_theta^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n\
         angles = [\"theta\"]\n[[family]]\nname = \"K\"\nvalue = \"(x+i*p_x)^m*exp(-i*n*theta)\"\n\
         [[family]]\nname = \"P\"\nvalue = \"re(K_{m,n})\"\n\
         [[family]]\nname = \"Q\"\nindices = [\"a\", \"b\"]\nvalue = \"K_{a, 2}*K_{1,b}\"\n",
    )
    .expect("write");
    let o = superint_in(
        &dir,
        &[
            "expand",
            "f.toml",
            "P_2_3 - re(K_2_3)",
            "Q_3_1 - K_3_2*K_1_1",
            "P_2_3",
        ],
    );
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert_eq!(out.matches(" = 0\n").count(), 2, "{out}");
    assert!(!out.contains("P_{2,3} = 0"), "P_{{2,3}} is not zero: {out}");
}

/// The rank's upper bound reads as English for one function too ("there are 1 function").
#[test]
fn rank_of_one_function_reads_there_is() {
    let out = run(&["rank", "systems/kepler.toml", "L", "--no-timings"], 0);
    assert!(out.contains("≤ 1: there is 1 function\n"), "{out}");
}

/// Every operation an expression can reach stops at the term limit with exit status 2, never a
/// panic: `re`, `im`, `cos`, `sin` and `conj` formed their sums with the panicking operators
/// (exit 134 at `--max-terms 1`, and at the default limits for `re` of a long power).
#[test]
fn the_term_limit_stops_every_function_with_an_error() {
    let dir = scratch("term-limit-functions");
    std::fs::write(
        dir.join("t.toml"),
        "hamiltonian = \"p_t^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\nangles = [\"t\"]\n",
    )
    .expect("write");
    for e in [
        "re(exp(i*t))",
        "im(x*exp(i*t))",
        "cos(t)",
        "sin(t)",
        "conj(x + exp(i*t))",
        "{cos(t), p_t}",
    ] {
        let o = superint_in(&dir, &["expand", "t.toml", e, "--max-terms", "1"]);
        let err = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{e}: {err}");
        assert!(
            err.contains("the result would have more than 1 term (the term limit)"),
            "{e}: {err}"
        );
    }
}

/// A file without a `name` is named by its file name, without an article ("The claims of the
/// t1" read oddly), and so is a name with an article or possessive of its own ("of the my
/// oscillator" did); any other name takes "the".
#[test]
fn a_system_named_by_its_file_takes_no_article() {
    let dir = scratch("unnamed");
    std::fs::write(
        dir.join("t1.toml"),
        "hamiltonian = \"p_x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n",
    )
    .expect("write");
    let out = text(&superint_in(&dir, &["check", "t1.toml"]).stdout);
    assert!(
        out.starts_with("The claims of t1, checked exactly\n"),
        "{out}"
    );
    let out = run(&["check", "systems/kepler.toml"], 0);
    assert!(out.starts_with("The claims of the Kepler problem, checked exactly\n"));
    for (name, title) in [
        ("my oscillator", "The claims of my oscillator"),
        ("The oscillator", "The claims of The oscillator"),
        ("an oscillator", "The claims of an oscillator"),
        (
            "anisotropic oscillator",
            "The claims of the anisotropic oscillator",
        ),
        ("mystery", "The claims of the mystery"),
    ] {
        let file = dir.join("named.toml");
        let body = format!(
            "name = \"{name}\"\nhamiltonian = \"p_x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n"
        );
        std::fs::write(&file, body).expect("write");
        let out = text(&superint_in(&dir, &["check", "named.toml"]).stdout);
        assert!(
            out.starts_with(&format!("{title}, checked exactly\n")),
            "{out}"
        );
    }
}

/// What `expand` echoes of an expression reads back to the same normal form (a fuzzer of
/// round trips found each of these echoes wrong or unreadable: `2−xy` for 2·(−xy), `−1/x(x + y)`,
/// `2K_{1,1}`, `Re(x)`, `exp(iθ)`, `exp(i(θ − φ))`; and `M(x + y)²`, `(xy)²` read with the
/// power on the whole product, or on the last name only).
#[test]
fn echoes_read_back_to_the_same_normal_form() {
    let dir = scratch("echo-round-trips");
    std::fs::write(
        dir.join("xy.toml"),
        "hamiltonian = \"p_x^2/2 + p_y^2/2\"\n[phase_space]\ncoordinates = [\"x\", \"y\"]\n\
         angles = [\"theta\", \"phi\"]\nparameters = [\"M\"]\n[[family]]\nname = \"K\"\n\
         value = \"x^m*exp(-i*n*theta)\"\n",
    )
    .expect("write");
    let expand = |e: &str| -> (String, String) {
        let o = superint_in(&dir, &["expand", "xy.toml", "--format", "json", "--", e]);
        assert_eq!(o.status.code(), Some(0), "{e}: {}", text(&o.stderr));
        let v: Value = serde_json::from_slice(&o.stdout).expect("JSON");
        let line = &v["equations"][0]["lines"][0];
        let field = |k: &str| line[k].as_str().expect("a string").to_string();
        (field("lhs"), field("ascii"))
    };
    for input in [
        "2*(-x*y)",
        "x*(-2*y)",
        "(-(1/x))*(x + y)",
        "2*K_1_1",
        "re(x*exp(i*theta))",
        "im(x*exp(i*theta))",
        "exp(i*theta)",
        "exp(3*i*theta)",
        "exp(i*(theta - phi))",
        "e^{-i*theta}*x^2",
        "exp(-i*theta)^2",
        "re(e^{2*i*theta - i*phi})",
        "M*(x + y)^2",
        "x*(-x)^2",
        "(x*y)^2",
        "(M*x)^-1",
        "M*x^2",
    ] {
        let (echo, value) = expand(input);
        let (_, again) = expand(&echo);
        assert_eq!(again, value, "{input} echoed as {echo}");
    }
    // A name before parentheses with a power after them, and the same in parentheses.
    for input in [
        "M(x + y)^(2)",
        "(M(x + y))^2",
        "(p_x (3/4*i))^2",
        "x(cos(theta)^2)^2",
    ] {
        let (echo, value) = expand(input);
        let (_, again) = expand(&echo);
        assert_eq!(again, value, "{input} echoed as {echo}");
    }
    // The paper's way of writing: a name before parentheses multiplies them, the power on the
    // parentheses; in parentheses, a power takes names run together whole.
    assert_eq!(expand("2M(x + y)²").1, expand("2*M*(x + y)^2").1);
    assert_eq!(expand("(Mx)²").1, "M^2*x^2");
    assert_eq!(expand("Mx²").1, "M*x^2");
    // The exponential echoes as the paper writes it; a power of it takes parentheses.
    assert_eq!(expand("x^2*exp(-i*theta)").0, "x² e^{−iθ}");
    assert_eq!(expand("exp(-i*theta)^2").0, "(e^{−iθ})²");
}

/// A family named by a Greek letter prints its instances with that letter, `ο_{1,1}` of a family
/// `omicron`, which reads back as the instance, as `θ_{1,1}` of a family `theta` did; omicron's
/// was an unknown name, its LaTeX `\mathit{o}_{1,1}` spelling the Latin `o`. A function `o`
/// beside it stays apart (`o`, with no indices, in text and LaTeX alike).
#[test]
fn a_greek_familys_instance_reads_back_as_printed() {
    let dir = scratch("greek-family");
    std::fs::write(
        dir.join("omicron.toml"),
        "hamiltonian = \"p_x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n\
         [[function]]\nname = \"o\"\nvalue = \"x\"\n\
         [[family]]\nname = \"omicron\"\nvalue = \"x^m*p_x^n\"\n\
         [[family]]\nname = \"theta\"\nvalue = \"x^m*p_x^(2*n)\"\n",
    )
    .expect("write");
    let expand = |e: &str| -> (String, String) {
        let o = superint_in(
            &dir,
            &["expand", "omicron.toml", "--format", "json", "--", e],
        );
        assert_eq!(o.status.code(), Some(0), "{e}: {}", text(&o.stderr));
        let v: Value = serde_json::from_slice(&o.stdout).expect("JSON");
        let line = &v["equations"][0]["lines"][0];
        let field = |k: &str| line[k].as_str().expect("a string").to_string();
        (field("lhs"), field("ascii"))
    };
    let (echo, value) = expand("omicron_1_2 + 2*theta_2_1 + o");
    assert_eq!(echo, "ο_{1,2} + 2 θ_{2,1} + o");
    assert_eq!(expand(&echo).1, value, "{echo}");
    for written in ["ο_{1,2}", "o_{1,2}", r"\mathit{o}_{1,2}", "omicron_1_2"] {
        assert_eq!(expand(written).1, "x*p_x^2", "{written}");
    }
    assert_eq!(expand(r"\mathit{o}").1, "x");
}

/// The exponential is `e^{…}` (with braces) in what superint reads and prints, unless the
/// system declares a name `e`: then `e^2` is its square, and the exponential echoes as
/// `exp(…)`, which reads back.
#[test]
fn the_exponential_is_written_e_unless_the_system_declares_e() {
    let dir = scratch("a-name-e");
    std::fs::write(
        dir.join("e.toml"),
        "hamiltonian = \"p_x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n\
         angles = [\"theta\"]\nparameters = [\"e\"]\n",
    )
    .expect("write");
    let o = superint_in(
        &dir,
        &[
            "expand",
            "e.toml",
            "e^2*exp(i*theta) - e^2*e^{i*theta}",
            "e^2*exp(i*theta)",
        ],
    );
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(out.contains("e² exp(iθ) − e² exp(iθ) = 0\n"), "{out}");
    assert!(
        out.contains("e² exp(iθ)              = e² cos θ + ie² sin θ\n"),
        "{out}"
    );
}

/// `Re` and `Im` are the real and imaginary parts unless the system declares the name: a
/// function `Re` before parentheses multiplies them, and the echo of a real part is then `re`.
#[test]
fn a_function_named_re_is_the_systems() {
    let dir = scratch("function-named-re");
    std::fs::write(
        dir.join("re.toml"),
        "hamiltonian = \"p_x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\nparameters = [\"E\"]\n\
         [[function]]\nname = \"Re\"\nvalue = \"x^2 + 1\"\n",
    )
    .expect("write");
    let o = superint_in(
        &dir,
        &["expand", "re.toml", "Re (E) - Re*E", "re(i*x) + Re"],
    );
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(out.contains("Re(E) − Re E = 0\n"), "{out}");
    assert!(out.contains("re(ix) + Re  = x² + 1\n"), "{out}");
}

/// A file that does not load does not stop a check of several: the others are checked and
/// printed, each error goes to stderr (and into the JSON's `errors`, with its place and kind),
/// and the run exits 2. A file whose check stops at a limit counts as one that failed.
#[test]
fn check_goes_on_past_a_bad_file() {
    let dir = scratch("past-a-bad-file");
    let good = "systems/kepler.toml";
    let bad = dir.join("bad.toml");
    std::fs::write(
        &bad,
        "name = \"bad\"\nhamiltonian = \"p_x^2/2m\"\n[phase_space]\ncoordinates = [\"x\"]\n\
         parameters = [\"m\"]\n",
    )
    .expect("write bad.toml");
    let big = dir.join("big.toml");
    std::fs::write(
        &big,
        "name = \"big\"\nhamiltonian = \"p_x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n\
         [limits]\nmax_terms = 10\n[[claim]]\nclaim = \"(x + p_x)^20 = 0\"\n",
    )
    .expect("write big.toml");
    let (bad, big) = (bad.to_str().expect("a path"), big.to_str().expect("a path"));
    let o = superint_in(root(), &["check", good, bad, big, "--no-timings"]);
    let (stdout, stderr) = (text(&o.stdout), text(&o.stderr));
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(
        stdout.contains("Kepler problem (systems/kepler.toml)"),
        "{stdout}"
    );
    // The claim past the limit is undecided; the file's section is reported.
    assert!(
        stdout.ends_with(
            "11 claims in 2 files: 7 proved, 3 refuted, 1 undecided; the decided ones as \
             expected; undecided: #1 (section 2)\n"
        ),
        "{stdout}"
    );
    assert!(stdout.contains("[#1 UNDECIDED]"), "{stdout}");
    assert!(
        stderr.contains("bad.toml:2:22: '/2m' is ambiguous"),
        "{stderr}"
    );
    assert!(
        stderr.contains("big.toml:8:10: the result would have more than 10 terms"),
        "{stderr}"
    );
    assert!(
        stderr.ends_with(
            "superint: error: 1 of 3 files not checked, 1 claim undecided, stopped at a limit \
             (the errors above)\n"
        ),
        "{stderr}"
    );
    let o = superint_in(
        root(),
        &["check", bad, good, "--format", "json", "--no-timings"],
    );
    assert_eq!(o.status.code(), Some(2));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("one JSON document");
    assert_eq!(v["sections"][0]["file"], good);
    let error = &v["errors"][0];
    assert_eq!(
        (
            &error["file"],
            &error["line"],
            &error["column"],
            &error["kind"]
        ),
        (
            &serde_json::json!(bad),
            &serde_json::json!(2),
            &serde_json::json!(22),
            &serde_json::json!("expression")
        )
    );
    // An error of the file itself belongs to no claim.
    assert_eq!(
        error.get("claim"),
        Some(&serde_json::Value::Null),
        "{error}"
    );
    // Each claim as the file writes it, which reads back there.
    let claim = &v["claims"][0];
    assert_eq!(
        (&claim["statement"], &claim["ascii"]),
        (
            &serde_json::json!("{A_x, H} = 0"),
            &serde_json::json!("{Ax, H} = 0")
        )
    );
    // Only bad files: nothing on stdout, the last error is the run's.
    let o = superint_in(root(), &["check", bad]);
    assert_eq!((o.status.code(), o.stdout.is_empty()), (Some(2), true));
}

/// A claim whose check reaches a limit is reported undecided, in every format, and the
/// file's other claims are still checked: proved, refuted, and a rank. The run ends with the
/// limit's error (exit 2), which says where the claim is. With the limit raised, the same
/// claim is decided (refuted: the bracket is not zero), so the limit alone left it open.
#[test]
fn check_reports_a_claim_past_a_limit_undecided() {
    let dir = scratch("claim-past-a-limit");
    let file = dir.join("limit.toml");
    std::fs::write(
        &file,
        "name = \"limit test\"\n\
         hamiltonian = \"(p_x^2 + p_y^2)/2 + omega^2*(x^2 + y^2)/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"omega\"]\n\
         [[function]]\nname = \"L\"\nvalue = \"x*p_y - y*p_x\"\n\
         [[claim]]\nid = \"big\"\nclaim = \"{L, (1 + x + y + p_x + p_y)^20} = 0\"\n\
         [[claim]]\nid = \"su2\"\nclaim = \"{L, H} = 0\"\n\
         [[claim]]\nid = \"false\"\nclaim = \"{x, H} = 0\"\nexpect = \"refuted\"\n\
         [[claim]]\nid = \"rank\"\nclaim = \"rank(H, L) = 2\"\n",
    )
    .expect("write limit.toml");
    let file = file.to_str().expect("a path");
    let check = |extra: &[&str]| {
        let args = [
            &["check", file, "--no-timings", "--max-terms", "1000"],
            extra,
        ]
        .concat();
        superint_in(root(), &args)
    };
    let o = check(&[]);
    let (stdout, stderr) = (text(&o.stdout), text(&o.stderr));
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    for said in [
        "[big UNDECIDED]",
        "      stopped at a limit: the result would have more than 1000 terms (the term limit)",
        "[su2 proved]",
        "[false refuted, as expected]",
        "[rank proved]",
        "4 claims in 1 file: 2 proved, 1 refuted, 1 undecided; the decided ones as expected; \
         undecided: big\n",
    ] {
        assert!(stdout.contains(said), "{said}\n{stdout}");
    }
    assert!(
        stderr.starts_with(&format!(
            "superint: error: {file}:11:14: the result would have more than 1000 terms"
        )),
        "{stderr}"
    );
    assert!(
        stderr.ends_with(
            "superint: error: 1 claim undecided, stopped at a limit (the error above)\n"
        ),
        "{stderr}"
    );
    // JSON: the outcome, the limit's message, the summary's count and the error's place.
    let o = check(&["--format", "json"]);
    assert_eq!(o.status.code(), Some(2));
    let v: Value = serde_json::from_slice(&o.stdout).expect("one JSON document");
    let outcomes: Vec<(&str, &str)> = (v["claims"].as_array().expect("claims").iter())
        .map(|c| (c["id"].as_str().unwrap(), c["outcome"].as_str().unwrap()))
        .collect();
    assert_eq!(
        outcomes,
        [
            ("big", "undecided"),
            ("su2", "proved"),
            ("false", "refuted"),
            ("rank", "proved")
        ]
    );
    let big = &v["claims"][0];
    assert_eq!(big["meets_expectation"], false);
    assert!(
        (big["undecided"].as_str().unwrap()).starts_with("the result would have more than 1000"),
        "{big}"
    );
    assert_eq!(v["claims"][1]["undecided"], Value::Null);
    let summary = &v["summary"];
    assert_eq!(
        (
            &summary["proved"],
            &summary["refuted"],
            &summary["undecided"]
        ),
        (&Value::from(2), &Value::from(1), &Value::from(1))
    );
    let error = &v["errors"][0];
    assert_eq!(
        (
            &error["line"],
            &error["column"],
            &error["kind"],
            &error["claim"]
        ),
        (
            &Value::from(11),
            &Value::from(14),
            &Value::from("limit"),
            &Value::from("big")
        )
    );
    // Markdown and LaTeX give the verdict and the limit too.
    for format in ["markdown", "latex"] {
        let o = check(&["--format", format]);
        let out = text(&o.stdout);
        assert_eq!(o.status.code(), Some(2), "{format}");
        assert!(out.contains("big UNDECIDED"), "{out}");
        assert!(
            out.contains("stopped at a limit: the result would have"),
            "{out}"
        );
        if format == "latex" {
            crate::cli::compile_within(&out, 1.0);
        }
    }
    // Raised, the limit leaves the claim decided: refuted, since {L, ·} of that power is not
    // zero, and so not as expected (exit 1).
    let o = superint_in(root(), &["check", file, "--no-timings"]);
    let stdout = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o.stderr));
    assert!(stdout.contains("[big REFUTED]"), "{stdout}");
    assert!(!stdout.contains("UNDECIDED"), "{stdout}");
}

/// The summary names a claim a limit stopped apart from one that is decided against its
/// expectation: the first may hold, the second is wrong as written.
#[test]
fn the_summary_names_undecided_claims_apart_from_unexpected_ones() {
    let dir = scratch("undecided-and-unexpected");
    let file = dir.join("both.toml");
    std::fs::write(
        &file,
        "hamiltonian = \"(p_x^2 + p_y^2)/2 + (x^2 + y^2)/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\n\
         [[claim]]\nid = \"big\"\nclaim = \"{x*p_y - y*p_x, (1 + x + y + p_x + p_y)^20} = 0\"\n\
         [[claim]]\nid = \"wrong\"\nclaim = \"{x, H} = 0\"\n\
         [[claim]]\nid = \"right\"\nclaim = \"{x*p_y - y*p_x, H} = 0\"\n",
    )
    .expect("write both.toml");
    let file = file.to_str().expect("a path");
    let o = superint_in(
        root(),
        &["check", file, "--no-timings", "--max-terms", "1000"],
    );
    assert_eq!(o.status.code(), Some(2), "{}", text(&o.stderr));
    let stdout = text(&o.stdout);
    assert!(
        stdout.ends_with(
            "3 claims in 1 file: 1 proved, 1 refuted, 1 undecided; 1 NOT as expected: wrong; \
             undecided: big\n"
        ),
        "{stdout}"
    );
}

/// A LaTeX report's section heading holds the file's path, which fits the page wherever the
/// file lies: the heading breaks after a path's slashes and underscores, and is set ragged
/// right (justified, a break after `tmp/` left the line too loose, and TeX set the path 23 pt
/// past the margin instead).
#[test]
fn latex_headings_fit_the_page_at_any_path() {
    let claim = "name = \"limit test\"\nhamiltonian = \"p_x^2/2 + x^2/2\"\n\
                 [phase_space]\ncoordinates = [\"x\"]\n\
                 [[claim]]\nid = \"free\"\nclaim = \"{x, H} = p_x\"\n";
    for dir in [
        "system_files/claim-past-a-limit",
        "a_directory_whose_name_is_longer_than_the_line_of_a_section_heading_can_hold_at_all",
    ] {
        let file = crate::scratch_text(dir, "limit.toml", claim);
        let file = file.to_str().expect("a path");
        let o = superint_in(
            root(),
            &["check", file, "--no-timings", "--format", "latex"],
        );
        let out = text(&o.stdout);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
        assert!(out.contains(r"\section*{"), "{out}");
        crate::cli::compile_within(&out, 1.0);
    }
}

/// `check_report`, the library's strict check, answers with the first limit a claim reaches.
#[test]
fn check_report_answers_with_a_claims_limit() {
    let text = "name = \"free\"\nhamiltonian = \"p_x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n\
                [[claim]]\nclaim = \"{p_x, H} = 0\"\n[[claim]]\nclaim = \"(x + p_x)^20 = 0\"\n";
    let limits = superint::system_file::LimitsOverride::default().max_terms(10);
    let file = superint::system_file::load_str("free.toml", text, &limits).expect("loads");
    let err = superint::system_file::check_report([&file]).expect_err("a limit");
    assert_eq!(
        (err.kind, err.line_col()),
        (superint::system_file::ErrorKind::Limit, Some((8, 10)))
    );
}

/// `table` takes a family instance written with braces, as every other command does.
#[test]
fn table_takes_family_instances_in_braces() {
    let f = "systems/anisotropic-3-5-rotor.toml";
    let braces = run(&["table", f, "B_{1,1}", "H", "--no-timings"], 0);
    let plain = run(&["table", f, "B_1_1", "H", "--no-timings"], 0);
    assert_eq!(braces, plain);
    assert!(
        braces.contains("B_{1,1} │ 0             −2iω B_{1,1}"),
        "{braces}"
    );
}

/// A base fact of a tower's proof that fails shows what the bracket is, so that the mistake
/// (here a sign: `{Ā, H} = −iω₁Ā`) can be read off, and, where it is another multiple of the
/// base, the eigenvalue it has.
#[test]
fn a_failed_base_fact_shows_the_bracket() {
    let dir = scratch("failed-fact");
    std::fs::write(
        dir.join("sign.toml"),
        "name = \"oscillator\"\nhamiltonian = \"(p_x^2 + p_y^2)/2 + (w1^2*x^2 + w2^2*y^2)/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"w1\", \"w2\"]\n\
         [[function]]\nname = \"A\"\nvalue = \"p_x + i*w1*x\"\n\
         [[function]]\nname = \"B\"\nvalue = \"p_y + i*w2*y\"\n\
         [[family]]\nname = \"T\"\nvalue = \"conj(A)^m*B^n\"\neigenvalue = \"i*(n*w2 + m*w1)\"\n",
    )
    .expect("write sign.toml");
    let o = superint_in(
        &dir,
        &[
            "tower",
            "--system",
            "sign.toml",
            "--max",
            "1",
            "--no-timings",
        ],
    );
    assert_eq!(o.status.code(), Some(1));
    let out = text(&o.stdout);
    assert!(
        out.contains(
            "    1. computed: {conj(A), H} = i w1 conj(A)                      FAILS\n       \
             the bracket is −i w1 p_x − w1² x, so {conj(A), H} = −i w1 conj(A)\n"
        ),
        "{out}"
    );
    let o = superint_in(
        &dir,
        &[
            "tower",
            "--system",
            "sign.toml",
            "--max",
            "1",
            "--format",
            "json",
        ],
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(v["proofs"][0]["facts"][0]["found"], "-i*w1*p_x - w1^2*x");
    assert_eq!(
        v["proofs"][0]["facts"][0]["found_statement"],
        "{conj(A), H} = −i w1 conj(A)"
    );
    assert_eq!(v["proofs"][0]["facts"][1]["found"], serde_json::Value::Null);
    assert_eq!(
        v["proofs"][0]["facts"][1]["found_statement"],
        serde_json::Value::Null
    );
    // A bracket that is no multiple of its base shows no eigenvalue.
    let not_a_ladder = std::fs::read_to_string(dir.join("sign.toml"))
        .unwrap()
        .replace("p_x + i*w1*x", "p_x + i*w1*x + y");
    std::fs::write(dir.join("not.toml"), not_a_ladder).expect("write not.toml");
    let o = superint_in(&dir, &["tower", "--system", "not.toml", "--max", "1"]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}");
    assert!(
        out.contains("the bracket is ") && !out.contains(", so {conj(A), H}"),
        "{out}"
    );
}

/// A name or function misspelled only in case or underscores is pointed to the known one.
#[test]
fn misspelled_names_point_to_the_known_ones() {
    let f = "systems/harmonic-rotor.toml";
    for (expr, message) in [
        (
            "px*x",
            "unknown name 'px'; did you mean 'p_x'? (known: x, y, theta, p_x,",
        ),
        ("OMEGA", "unknown name 'OMEGA'; did you mean 'omega'?"),
        (
            "Sin(theta)",
            "unknown function 'Sin' (known: cos, sin, exp, conj, Re, Im, sqrt); did you mean 'sin'?",
        ),
        (
            "sqrt(x^2 + y^2)",
            "sqrt(x² + y²) is no declared radical: declare it (radicals = { r = \"x^2 + y^2\" } \
             in [phase_space], for a name r of yours), and sqrt of it reads as r",
        ),
    ] {
        let o = superint_in(root(), &["expand", f, expr]);
        let stderr = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{stderr}");
        assert!(stderr.contains(message), "{expr}: {stderr}");
    }
}

/// A physicist's first try at the Kepler problem in space writes `-k/r` without declaring the
/// distance: the hint says how to declare it as a radical (for `r`, `rho`, `r1`, `r_12` in a
/// system of two momenta or more), where it said only where parameters, functions and families
/// go. With one coordinate, where a distance is no square root, and for another name, the
/// usual hint stays.
#[test]
fn an_undeclared_distance_is_pointed_to_radicals() {
    let dir = scratch("undeclared-distance");
    let space = "coordinates = [\"x\", \"y\", \"z\"]";
    let line = "coordinates = [\"x\"]";
    let file = |coordinates: &str, name: &str| {
        let kinetic = match coordinates == line {
            true => "p_x^2/2",
            false => "(p_x^2 + p_y^2 + p_z^2)/2",
        };
        format!(
            "hamiltonian = \"{kinetic} - k/{name}\"\n[phase_space]\n{coordinates}\n\
             parameters = [\"k\"]\n"
        )
    };
    for (coordinates, name, radical_hint) in [
        (space, "r", true),
        (space, "rho", true),
        (space, "r_12", true),
        (space, "s", false),
        (line, "r", false),
    ] {
        std::fs::write(dir.join("kepler.toml"), file(coordinates, name)).expect("write");
        let o = superint_in(&dir, &["check", "kepler.toml"]);
        let stderr = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert!(
            stderr.starts_with("superint: error: kepler.toml:1:")
                && stderr.contains(&format!("unknown name '{name}'")),
            "{stderr}"
        );
        let declare =
            format!("radicals = {{ {name} = \"x^2 + y^2\" }}, after which -k/{name} is exact");
        assert_eq!(stderr.contains(&declare), radical_hint, "{name}: {stderr}");
        // The usual hint follows either way.
        assert!(
            stderr.contains("a constant such as a mass is declared under [phase_space] parameters"),
            "{stderr}"
        );
    }
}

/// A radical declared with its root, `r = "sqrt(x^2 + y^2 + z^2)"`, where the radicand alone
/// is wanted, is refused at its place with what to write, not with `sqrt(…) is no declared
/// radical: declare it`, which read as if the declaration being written were missing.
#[test]
fn a_radicand_written_as_a_root_is_refused_with_the_radicand_to_write() {
    let dir = scratch("radicand-as-root");
    let file = "hamiltonian = \"(p_x^2 + p_y^2 + p_z^2)/2 - k/r\"\n[phase_space]\n\
                coordinates = [\"x\", \"y\", \"z\"]\nparameters = [\"k\"]\n\
                radicals = { r = \"sqrt(x^2 + y^2 + z^2)\" }\n";
    std::fs::write(dir.join("kepler.toml"), file).expect("write");
    let o = superint_in(&dir, &["check", "kepler.toml"]);
    let stderr = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.starts_with(
            "superint: error: kepler.toml:5:18: a radicand is what stands under the root, \
             without sqrt: write r = \"x^2 + y^2 + z^2\", which declares r = √(x² + y² + z²)"
        ),
        "{stderr}"
    );
    // Written as the radicand, the file loads.
    let fixed = file.replace("\"sqrt(x^2 + y^2 + z^2)\"", "\"x^2 + y^2 + z^2\"");
    std::fs::write(dir.join("kepler.toml"), fixed).expect("write");
    assert_eq!(
        superint_in(&dir, &["check", "kepler.toml"]).status.code(),
        Some(0)
    );
}

/// A decimal in an expression is refused (it is no exact number) with the fraction it writes,
/// which can be copied in: `0.5 is 1/2`, `.25 is 1/4`, `2. is 2`; it said only "such as 3/2".
#[test]
fn a_decimal_is_refused_with_the_fraction_it_writes() {
    for (expr, place, fraction) in [
        ("x + 0.5*F*z", "1:5", "0.5 is 1/2"),
        ("x + .25", "1:5", ".25 is 1/4"),
        ("x + 2.", "1:5", "2. is 2"),
        ("1.125*k", "1:1", "1.125 is 9/8"),
    ] {
        let o = superint_in(root(), &["expand", "systems/stark.toml", "--", expr]);
        let stderr = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{stderr}");
        let message = format!(
            "superint: error: <command line>:{place}: decimal numbers are not exact; write a \
             fraction: {fraction}\n"
        );
        assert!(stderr.starts_with(&message), "{expr}: {stderr}");
    }
}

/// A function used before it is declared, or by the Hamiltonian, is named in the hint.
#[test]
fn a_function_used_too_early_is_explained() {
    let dir = scratch("too-early");
    let head = "name = \"t\"\n[phase_space]\ncoordinates = [\"x\"]\n";
    for (h, functions, hint) in [
        (
            "p_x^2/2",
            "[[function]]\nname = \"A\"\nvalue = \"B + 1\"\n[[function]]\nname = \"B\"\nvalue = \"x\"\n",
            "hint: B is declared further down, and a function uses only the functions declared \
             before it: move this one below B\n",
        ),
        (
            "T + x^2",
            "[[function]]\nname = \"T\"\nvalue = \"p_x^2/2\"\n",
            "hint: T is a function, and the Hamiltonian is read before the functions: it uses \
             only variables and parameters, so write T's value out\n",
        ),
    ] {
        let file = format!("hamiltonian = \"{h}\"\n{head}{functions}");
        std::fs::write(dir.join("early.toml"), file).expect("write early.toml");
        let o = superint_in(&dir, &["check", "early.toml"]);
        let stderr = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{stderr}");
        assert!(stderr.contains("unknown name"), "{stderr}");
        assert!(stderr.ends_with(hint), "{stderr}");
    }
}

/// A family whose value or eigenvalue uses the family itself is refused at that use, however
/// the instance is written; one that uses a family declared after it, or a function that uses
/// a family, is told so in the hint (it said the family took two indices, or to declare it).
#[test]
fn a_family_used_by_itself_or_too_early_is_explained() {
    let dir = scratch("family-too-early");
    let head = "name = \"t\"\nhamiltonian = \"p_x^2/2 + x^2/2\"\n[phase_space]\n\
                coordinates = [\"x\"]\n";
    let itself = |written: &str| {
        format!(
            "the family K uses itself here ('{written}'): a family cannot be defined by its own \
             instances; write it in the variables, the functions and the families declared \
             before it\n"
        )
    };
    let later = "hint: J is declared further down, and a family uses only the families declared \
                 before it: move this one (K) below J\n";
    for (body, place, message, hint) in [
        (
            "[[family]]\nname = \"K\"\nvalue = \"K_m_n*x\"\n".to_string(),
            "7:10",
            itself("K_m_n"),
            None,
        ),
        (
            "[[family]]\nname = \"K\"\nvalue = \"x + K_1_2\"\n".to_string(),
            "7:14",
            itself("K_1_2"),
            None,
        ),
        (
            "[[family]]\nname = \"K\"\nindices = [\"a\", \"b\"]\nvalue = \"K_{a, b}\"\n"
                .to_string(),
            "8:10",
            itself("K_{a, b}"),
            None,
        ),
        (
            "[[family]]\nname = \"K\"\nvalue = \"x^m\"\neigenvalue = \"m*K_m\"\n".to_string(),
            "8:17",
            itself("K_m"),
            None,
        ),
        (
            "[[family]]\nname = \"K\"\nvalue = \"J_m_n*x\"\n\
             [[family]]\nname = \"J\"\nvalue = \"x^m*p_x^n\"\n"
                .to_string(),
            "7:10",
            "unknown name 'J_m_n' (known: x, p_x, H)\n".to_string(),
            Some(later),
        ),
        (
            "[[family]]\nname = \"K\"\nvalue = \"x*J_1_2\"\n\
             [[family]]\nname = \"J\"\nvalue = \"x^m*p_x^n\"\n"
                .to_string(),
            "7:12",
            "unknown name 'J_1_2' (known: x, p_x, H)\n".to_string(),
            Some(later),
        ),
        (
            "[[function]]\nname = \"F\"\nvalue = \"K_1_2*x\"\n\
             [[family]]\nname = \"K\"\nvalue = \"x^m*p_x^n\"\n"
                .to_string(),
            "7:10",
            "unknown name 'K_1_2' (known: x, p_x, H)\n".to_string(),
            Some(
                "hint: K is a family, and the functions are read before the families: a \
                 function uses none, so write K_1_2's value out\n",
            ),
        ),
    ] {
        std::fs::write(dir.join("k.toml"), format!("{head}{body}")).expect("write k.toml");
        let o = superint_in(&dir, &["check", "k.toml"]);
        let stderr = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{stderr}");
        assert!(
            stderr.starts_with(&format!("superint: error: k.toml:{place}: {message}")),
            "{body}: {stderr}"
        );
        match hint {
            Some(hint) => assert!(stderr.ends_with(hint), "{body}: {stderr}"),
            None => assert!(!stderr.contains("hint:"), "{body}: {stderr}"),
        }
    }
    // The Hamiltonian is read before the families too.
    let h = head.replace("x^2/2\"", "K_1_1\"");
    let family = "[[family]]\nname = \"K\"\nvalue = \"x^m*p_x^n\"\n";
    std::fs::write(dir.join("h.toml"), format!("{h}{family}")).expect("write h.toml");
    let o = superint_in(&dir, &["check", "h.toml"]);
    let stderr = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.starts_with("superint: error: h.toml:2:26: unknown name 'K_1_1'")
            && stderr.ends_with(
                "hint: K is a family, and the Hamiltonian is read before the families: it uses \
                 only variables and parameters, so write K_1_1's value out\n"
            ),
        "{stderr}"
    );
    // A family may use the families declared before it, with the same head (`K` in `K_b`).
    let fine = "[[family]]\nname = \"K\"\nvalue = \"x^m*p_x^n\"\n\
                [[family]]\nname = \"K_b\"\nvalue = \"K_m_n + K_{n,m}\"\n";
    std::fs::write(dir.join("ok.toml"), format!("{head}{fine}")).expect("write ok.toml");
    let o = superint_in(&dir, &["check", "ok.toml"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
}

/// Letters before parentheses that spell a function (`i·m` before `(−m)` as `im(−m)`, the
/// imaginary part) are echoed in parentheses of their own, so the echo reads back as the
/// product it is (it read back as 0).
#[test]
fn an_echo_does_not_spell_a_function_before_parentheses() {
    let dir = scratch("im-echo");
    std::fs::write(
        dir.join("m.toml"),
        "hamiltonian = \"p_m^2/2\"\n[phase_space]\ncoordinates = [\"m\"]\n",
    )
    .expect("write m.toml");
    let expand = |e: &str| {
        let o = superint_in(
            &dir,
            &["expand", "m.toml", e, "--format", "json", "--no-timings"],
        );
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
        let line = &v["equations"][0]["lines"][0];
        (
            line["lhs"].as_str().unwrap().to_string(),
            line["ascii"].as_str().unwrap().to_string(),
        )
    };
    let (echo, value) = expand("((5/7*i) m)*(-m)");
    assert_eq!(echo, "((5/7)im)(−m)");
    assert_eq!(value, "-5*i*m^2/7");
    assert_eq!(expand(&echo).1, value);
}

/// A table that a limit stops names the file and the bracket it computed: it said
/// `<command line>: the exponent of x would reach 1999` for `table FILE` with no names given.
/// The entry is `?` in the table printed.
#[test]
fn a_table_past_a_limit_names_the_file_and_the_brackets() {
    let file = crate::scratch_text(
        "system_files",
        "table-limit.toml",
        "hamiltonian = \"p_x^2/2\"\n[phase_space]\ncoordinates = [\"x\"]\n\
         [[function]]\nname = \"A\"\nvalue = \"x^1000\"\n\
         [[function]]\nname = \"B\"\nvalue = \"x^1000*p_x\"\n",
    );
    let path = file.to_str().expect("a UTF-8 path");
    let out = superint_in(root(), &["table", path]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains(&format!(
            "superint: error: {path}: 1 entry of the table undecided (shown as ?), stopped at a \
             limit, the first {{A, B}}: the exponent of x would reach 1999"
        )),
        "{stderr}"
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("    A     │ 0   ?"), "{stdout}");
}

/// A refuted identity's residual is also written in `H` and the file's functions where it is
/// a polynomial of degree ≤ 3 in them for every value of the parameters, and only there: not
/// when it is a constant, nor when it is no such polynomial. The wrong sign of Pauli's
/// `{A_x, A_y} = −2 H L/M` leaves `−4 H L/M`; `{L, H_x}² = 4 H_x H_y − ω² L²` times `H`
/// without its last term leaves `−ω² H L²`, of degree 3.
#[test]
fn a_refuted_residual_is_written_in_the_files_functions() {
    let dir = scratch("residual-in-functions");
    std::fs::write(
        dir.join("planar.toml"),
        r#"name = "planar oscillator"
hamiltonian = "(p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2"

[phase_space]
coordinates = ["x", "y"]
parameters = ["M", "omega"]

[[function]]
name = "L"
value = "x*p_y - y*p_x"

[[function]]
name = "Hx"
display = "H_x"
value = "p_x^2/(2*M) + M*omega^2*x^2/2"

[[claim]]
id = "times-h"
claim = "{L, H} = 3*M*H*L - Hx^2"
expect = "refuted"

[[claim]]
id = "at-omega"
claim = "{L, H} = omega*Hx"
when = "omega = 2"
expect = "refuted"

[[claim]]
id = "cubic"
claim = "{L, Hx}^2*H = 4*Hx*(H - Hx)*H"
expect = "refuted"

[[claim]]
id = "constant"
claim = "{L, H} = 1/M"
expect = "refuted"

[[claim]]
id = "outside"
claim = "{L, Hx} = 2*H"
expect = "refuted"
"#,
    )
    .expect("write the file");
    let o = superint_in(&dir, &["check", "planar.toml", "--format", "json"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let v: Value = serde_json::from_str(&text(&o.stdout)).expect("JSON");
    let found: Vec<(String, Value)> = v["claims"]
        .as_array()
        .expect("claims")
        .iter()
        .map(|c| {
            (
                c["id"].as_str().unwrap().into(),
                c["residual_in_functions"].clone(),
            )
        })
        .collect();
    // {L, H} = 0; {L, H_x} = p_x p_y/M + Mω²xy, which is no polynomial in H, L and H_x.
    assert_eq!(
        found,
        vec![
            ("times-h".into(), Value::from("-3*M*H*L + Hx^2")),
            ("at-omega".into(), Value::from("-2*Hx")),
            ("cubic".into(), Value::from("-omega^2*H*L^2")),
            ("constant".into(), Value::Null),
            ("outside".into(), Value::Null),
        ]
    );
    let kepler = run(&["check", "systems/kepler.toml"], 0);
    assert!(
        kepler.contains(
            "      residual lhs − rhs = −2 p_r² p_φ/M² − 2 p_φ³/(M²r²) + 4k p_φ/(Mr)\n\
             \x20                        = −4 H L/M\n"
        ),
        "{kepler}"
    );
}

/// A bracket or a residual whose coefficients are of degree 4 in the parameters is written in
/// the functions too, where α and β of one weight keep the fit at fixed values from lifting:
/// the caged oscillator's `{K, Q}` (its algebra's claim), the residual of a false `{K, Q}`
/// (`512ω²αβ H_x`, twice the sign-turned term), and that of `{W_{3,1}, H} = 0` (`2iω
/// W_{3,1}`, the instance the claim mentions, where in the functions alone it is `2iω A³B̄ =
/// 2iω A (C + 4iω Q)`). At degree 2 in the parameters, all three were long polynomials in the
/// phase variables.
#[test]
fn coefficients_of_degree_four_in_the_parameters_are_written() {
    let file = "systems/caged-oscillator-1-2.toml";
    let bracket = run(&["bracket", file, "K", "Q"], 0);
    assert!(
        bracket.contains("= 256ω²αβ H_x + 16ω²α K − 128β H_x³ + 16 H H_x K − 24 H_x² K\n"),
        "{bracket}"
    );
    let v: Value =
        serde_json::from_str(&run(&["check", file, "--format", "json"], 0)).expect("JSON");
    let written: Vec<(&str, &str)> = v["claims"]
        .as_array()
        .expect("claims")
        .iter()
        .filter_map(|c| Some((c["id"].as_str()?, c["residual_in_functions"].as_str()?)))
        .collect();
    assert_eq!(
        written,
        vec![
            ("false-1-3-ratio", "2*i*omega*W_3_1"),
            ("false-algebra", "512*omega^2*alpha*beta*Hx"),
        ]
    );
}

/// Where the functions have relations, a residual has several polynomials in them; the one
/// with the fewest monomials is written. Kepler's `A_x² + A_y² = k² + 2 H L²/M` would
/// otherwise turn the missing `/M`'s `2 H L²/M − 2 H L²` into `M k² − M A_x² − …`, and the
/// 3-5 rotor's off-resonance residual `ω Im K` into `−iω K + iω Re K`; a bracket likewise.
#[test]
fn a_residual_is_written_with_the_fewest_monomials_the_relations_allow() {
    let dir = scratch("fewest-monomials");
    let kepler = std::fs::read_to_string("systems/kepler.toml").expect("read");
    let functions = &kepler[..kepler.find("[[claim]]").expect("claims")];
    std::fs::write(
        dir.join("kepler.toml"),
        format!(
            "{functions}[[claim]]\nclaim = \"Ax^2 + Ay^2 = k^2 + 2*H*L^2\"\nexpect = \"refuted\"\n"
        ),
    )
    .expect("write the file");
    let o = superint_in(&dir, &["check", "kepler.toml", "--format", "json"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let v: Value = serde_json::from_str(&text(&o.stdout)).expect("JSON");
    assert_eq!(
        v["claims"][0]["residual_in_functions"],
        "-2*H*L^2 + 2*H*L^2/M"
    );
    let rotor = run(&["check", "systems/anisotropic-3-5-rotor.toml"], 0);
    assert!(
        rotor.contains(
            "        + (−ω p_x² p_y + 9M²ω³x² p_y − 30M²ω³xy p_x) sin θ\n\
             \x20                        = ω Im K\n"
        ),
        "{rotor}"
    );
    let bracket = run(
        &[
            "bracket",
            "systems/anisotropic-3-5-rotor.toml",
            "Ax",
            "H*F2",
        ],
        0,
    );
    assert!(bracket.contains("= 3iω F2 A_x\n"), "{bracket}");
}

/// `bracket` writes the bracket in `H` and the file's functions too, where it is a polynomial
/// of degree ≤ 2 in them (Pauli's `{A_x, A_y} = −2 H L/M`), under the `=` of the expansion, in
/// every format; where it is none, or zero, nothing is added.
#[test]
fn bracket_writes_the_bracket_in_the_files_functions() {
    let text = run(&["bracket", "systems/kepler.toml", "Ax", "Ay"], 0);
    assert!(
        text.contains(
            "    {A_x, A_y} = −p_r² p_φ/M² − p_φ³/(M²r²) + 2k p_φ/(Mr)\n\
             \x20              = −2 H L/M\n"
        ),
        "{text}"
    );
    let json = |f: &str, g: &str| -> Value {
        let out = run(
            &["bracket", "systems/kepler.toml", f, g, "--format", "json"],
            0,
        );
        let v: Value = serde_json::from_str(&out).expect("JSON");
        v["equations"][0]["lines"][0]["in_functions"].clone()
    };
    assert_eq!(json("Ax", "Ay")["ascii"], "-2*H*L/M");
    assert_eq!(json("Ax", "Ay")["latex"], r"-\frac{2 H L}{M}");
    // {L, A_x} = A_y; {A_x, H} = 0; {r, p_r} = 1 has no function in it; {cos φ, A_x} is none.
    assert_eq!(json("L", "Ax")["ascii"], "Ay");
    assert_eq!(json("Ax", "H"), Value::Null);
    assert_eq!(json("r", "p_r"), Value::Null);
    assert_eq!(json("cos(phi)", "Ax"), Value::Null);
    let markdown = run(
        &[
            "bracket",
            "systems/kepler.toml",
            "Ax",
            "Ay",
            "--format",
            "markdown",
        ],
        0,
    );
    assert!(markdown.contains("` = `−2 H L/M`"), "{markdown}");
}

/// Where `bracket`'s arguments mention family instances, the instances of every family at
/// their indices are functions too, printed as instances in every format and in ASCII that
/// reads back: the Fock–Darwin `{L, P_{1,2}} = −3 Q_{1,2}` (in `Z`, `W` alone, `−3i Z² W̄/2 +
/// 3i Z̄² W/2`), the rotor's `{P_{2,3}, H}` off resonance, `{L, K̄_{1,2}} = i K̄_{1,2}` with
/// its display's bar, and `{L, P_{5,5}} = −10 Q_{5,5}`, an instance too long for its square to
/// be sought, as a multiple. A bracket that is no polynomial in them gets nothing (`{xy,
/// P_{1,2}}`), and one in the functions alone is still written so (`{Z, P_{1,2}}`).
#[test]
fn bracket_writes_the_bracket_in_the_family_instances_it_mentions() {
    let fd = "systems/fock-darwin.toml";
    let text = run(&["bracket", fd, "L", "P_1_2"], 0);
    assert!(
        text.contains("− 9M³ ω₋³ xy²/8\n                 = −3 Q_{1,2}\n"),
        "{text}"
    );
    let json = |file: &str, f: &str, g: &str| -> Value {
        let out = run(&["bracket", file, f, g, "--format", "json"], 0);
        let v: Value = serde_json::from_str(&out).expect("JSON");
        v["equations"][0]["lines"][0].clone()
    };
    let line = json(fd, "L", "P_{1,2}");
    let written = &line["in_functions"];
    assert_eq!(written["text"], "−3 Q_{1,2}");
    assert_eq!(written["latex"], "-3 Q_{1,2}");
    assert_eq!(written["ascii"], "-3*Q_1_2");
    // The ASCII reads back in the file, to the bracket's normal form.
    let ascii = written["ascii"].as_str().expect("ASCII");
    let out = run(&["expand", fd, "--format", "json", "--", ascii], 0);
    let v: Value = serde_json::from_str(&out).expect("JSON");
    assert_eq!(v["equations"][0]["lines"][0]["ascii"], line["ascii"]);
    let rotor = "systems/harmonic-rotor.toml";
    let written = |file: &str, f: &str, g: &str| json(file, f, g)["in_functions"].clone();
    // Off the resonance, the instance's coefficient collected as the paper writes it
    // (`{P_{2,3}, F1} = −(2ω − 3Ω) Q_{2,3}`), in a form that reads back.
    let off = written(rotor, "P_2_3", "H");
    assert_eq!(off["text"], "−(2ω − 3 Ω) Q_{2,3}");
    assert_eq!(off["latex"], r"-\left(2 \omega - 3 \Omega\right) Q_{2,3}");
    assert_eq!(off["ascii"], "-(2*omega - 3*Omega)*Q_2_3");
    let ascii = off["ascii"].as_str().expect("ASCII");
    let out = run(&["expand", rotor, "--format", "json", "--", ascii], 0);
    let v: Value = serde_json::from_str(&out).expect("JSON");
    assert_eq!(
        v["equations"][0]["lines"][0]["ascii"],
        json(rotor, "P_2_3", "H")["ascii"]
    );
    let bar = written(rotor, "L", "Kbar_1_2");
    assert_eq!(bar["text"], "i K̄_{1,2}");
    assert_eq!(bar["latex"], r"i \bar{K}_{1,2}");
    assert_eq!(bar["ascii"], "i*Kbar_1_2");
    assert_eq!(written(fd, "L", "P_5_5")["ascii"], "-10*Q_5_5");
    assert_eq!(written(fd, "x*y", "P_1_2"), Value::Null);
    assert_eq!(written(fd, "Z", "P_1_2")["text"], "2iM(ω₊ + ω₋) Z̄ W");
}

/// `check FILE --format json`'s claims, looked up by id (a panic names an id not there).
fn checked_claims(file: &str) -> impl Fn(&str) -> Value {
    let v: Value =
        serde_json::from_str(&run(&["check", file, "--format", "json"], 0)).expect("JSON");
    let claims = v["claims"].as_array().expect("claims").clone();
    move |id| {
        claims
            .iter()
            .find(|c| c["id"] == id)
            .unwrap_or_else(|| panic!("no claim {id}"))
            .clone()
    }
}

/// A refuted claim that mentions family instances has its residual written in the instances
/// of every family at their indices too, where it is a polynomial in them and the functions:
/// the Fock–Darwin `P_{1,2}` conserved off the resonance (`−(ω₊ − 2 ω₋) Q_{1,2}`) or at the other
/// one, `ω₋ = 2 ω₊` (`3 ω₊ Q_{1,2}`, which was `3i ω₊ Z² W̄/2 − …`); each reads back, under
/// the claim's condition, to the residual. A residual that is none is written as before.
#[test]
fn a_refuted_residual_is_written_in_the_instances_the_claim_mentions() {
    let fd = "systems/fock-darwin.toml";
    let claim = checked_claims(fd);
    for (id, written) in [
        ("false-off-resonance", "-(a - 2*b)*Q_1_2"),
        ("false-resonance", "3*a*Q_1_2"),
    ] {
        let c = claim(id);
        assert_eq!(c["residual_in_functions"], written, "{c}");
        let difference = format!(
            "({}) - ({written})",
            c["residual"].as_str().expect("residual")
        );
        let mut args = vec!["expand", fd, "--format", "json", difference.as_str()];
        if let Some(when) = c["condition_ascii"].as_str() {
            args.extend(["--when", when]);
        }
        let out: Value = serde_json::from_str(&run(&args, 0)).expect("JSON");
        assert_eq!(out["equations"][0]["lines"][0]["ascii"], "0", "{id}");
    }
    // W conserved at b = 0 is ia W, in the functions, as before.
    assert_eq!(claim("false-landau")["residual_in_functions"], "i*a*W");
    let text = run(&["check", fd], 0);
    assert!(text.contains("= 3 ω₊ Q_{1,2}\n"), "{text}");
}

/// The text form reads back where a variable's display has a subscript sign: the Fock–Darwin
/// parameters `a`, `b` print as `ω₊`, `ω₋`, and a bracket's text, `… + i ω₊ x p_x/2 + …`, was
/// refused as "unexpected character '₊'", while its LaTeX, `\omega_{+}`, read back. Each form
/// of the bracket now reads back to its ASCII result.
#[test]
fn a_display_with_a_subscript_sign_reads_back_in_the_text_form() {
    let fd = "systems/fock-darwin.toml";
    let out: Value =
        serde_json::from_str(&run(&["bracket", fd, "Z*x", "H", "--format", "json"], 0))
            .expect("JSON");
    let line = &out["equations"][0]["lines"][0];
    let text = line["text"].as_str().expect("text");
    assert!(text.contains("i ω₊ x p_x/2"), "{text}");
    for form in ["text", "latex"] {
        let difference = format!(
            "({}) - ({})",
            line[form].as_str().expect("form"),
            line["ascii"].as_str().expect("ascii")
        );
        let back: Value = serde_json::from_str(&run(
            &["expand", fd, "--format", "json", difference.as_str()],
            0,
        ))
        .expect("JSON");
        assert_eq!(back["equations"][0]["lines"][0]["ascii"], "0", "{form}");
    }
    let back: Value =
        serde_json::from_str(&run(&["expand", fd, "--format", "json", "M ω₊² x − ω₋"], 0))
            .expect("JSON");
    assert_eq!(back["equations"][0]["lines"][0]["ascii"], "M*a^2*x - b");
}

/// Where the parameters of one weight leave homogeneity nothing to lift by, and all of them
/// kept symbolic would pass the monomial limits, only those the lift cannot restore are kept
/// symbolic, the others fixed and lifted: the Fock–Darwin rotor's `ω₊, ω₋` share a weight, and
/// with its nineteen functions and instances `M, ω₊, ω₋, I` symbolic (3150 monomials at degree
/// 2) were refused, so that `{P_{1,1}, H}` and the residual of `R_{1,1}` conserved off the
/// resonance had no form; `ω₋` alone symbolic writes them `−(ω₋ − Ω) Q_{1,1}` and
/// `−(ω₊ − Ω) S_{1,1}`, each proved for every value of the parameters and reading back to the
/// expansion. A form found with every parameter symbolic is kept as it was: the Fock–Darwin
/// `{P_{1,2}, Q_{1,2}}`, written in the functions alone with `Z Z̄`.
#[test]
fn a_form_is_found_with_only_the_parameters_the_lift_cannot_restore_symbolic() {
    let rotor = "systems/fock-darwin-rotor.toml";
    for (f, written) in [
        ("P_1_1", "-(b - Omega)*Q_1_1"),
        ("Q_1_1", "(b - Omega)*P_1_1"),
        ("R_1_3", "-(a - 3*Omega)*S_1_3"),
        ("K_1_1", "i*(b - Omega)*K_1_1"),
    ] {
        let json = crate::superint_json(&["bracket", rotor, f, "H"]);
        let line = &json["equations"][0]["lines"][0];
        assert_eq!(line["in_functions"]["ascii"], written, "{f}: {json}");
        // The form reads back to the bracket.
        let difference = format!("{{{f}, H}} - ({written})");
        let out: Value =
            serde_json::from_str(&run(&["expand", rotor, "--format", "json", &difference], 0))
                .expect("JSON");
        assert_eq!(out["equations"][0]["lines"][0]["ascii"], "0", "{f}");
    }
    let text = run(&["bracket", rotor, "P_1_1", "H", "--no-timings"], 0);
    assert!(
        text.contains("\n                 = −(ω₋ − Ω) Q_{1,1}\n"),
        "{text}"
    );
    let claim = checked_claims(rotor);
    assert_eq!(
        claim("false-off-resonance")["residual_in_functions"],
        "-(a - Omega)*S_1_1"
    );
    assert_eq!(
        claim("false-other-mode")["residual_in_functions"],
        "-(a - b)*S_1_1"
    );
    let fd = crate::superint_json(&["bracket", "systems/fock-darwin.toml", "P_1_2", "Q_1_2"]);
    assert_eq!(
        fd["equations"][0]["lines"][0]["in_functions"]["ascii"],
        "-2*M^2*(a^2*L + 5*a*b*L - 3*a*H + 4*b^2*L - 3*b*H)*Z*Zbar",
        "{fd}"
    );
}

/// A residual is written in the functions where the parameters at 1, the values the linear
/// algebra takes first, are a special point: the Euler top with symbolic moments has `H = C/2`
/// at `I1 = I2 = I3 = 1`, where `C²` was found as `4 H²`, which holds there only, and no line
/// was written; the search is made again at values that are not special, and a combination
/// found there is proved by expanding it as it stands (the moments, of one weight, leave
/// homogeneity nothing to lift by). A declared denominator zero at 1 (`a1 − a2`) likewise;
/// and where the combination found at other values does not lift, it is sought with the
/// residual's parameters kept symbolic.
#[test]
fn a_residual_is_written_in_the_functions_where_the_parameters_at_one_are_special() {
    let dir = scratch("special-parameters");
    std::fs::write(
        dir.join("top.toml"),
        concat!(
            "hamiltonian = \"M1^2/(2*I1) + M2^2/(2*I2) + M3^2/(2*I3)\"\n\
             [phase_space]\nvariables = [\"M1\", \"M2\", \"M3\"]\nparameters = [\"I1\", \"I2\", \"I3\"]\n",
            so3_poisson!(),
            "[[function]]\nname = \"C\"\nvalue = \"M1^2 + M2^2 + M3^2\"\n\
             [[claim]]\nclaim = \"C^2 = 0\"\nexpect = \"refuted\"\n\
             [[claim]]\nclaim = \"C + H = 0\"\nexpect = \"refuted\"\n",
        ),
    )
    .expect("write the file");
    std::fs::write(
        dir.join("split.toml"),
        "hamiltonian = \"p_x^2/2 + p_y^2/2 + x^2/(a1 - a2)\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a1\", \"a2\"]\n\
         denominators = [\"a1 - a2\"]\n\
         [[function]]\nname = \"Hx\"\nvalue = \"p_x^2/2 + x^2/(a1 - a2)\"\n\
         [[claim]]\nclaim = \"{Hx, H} + Hx^2 = 0\"\nexpect = \"refuted\"\n",
    )
    .expect("write the file");
    let written = |file: &str| {
        let o = superint_in(&dir, &["check", file, "--format", "json"]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
        let v: Value = serde_json::from_str(&text(&o.stdout)).expect("JSON");
        let claims = v["claims"].as_array().expect("claims").clone();
        claims
            .iter()
            .map(|c| {
                c["residual_in_functions"]
                    .as_str()
                    .unwrap_or("")
                    .to_string()
            })
            .collect::<Vec<_>>()
    };
    std::fs::write(
        dir.join("weights.toml"),
        "hamiltonian = \"(p_x^2 + p_y^2)/2 + a*x^2/2 + b*y^2/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\", \"b\"]\n\
         [[function]]\nname = \"L\"\nvalue = \"x*p_y - y*p_x\"\n\
         [[function]]\nname = \"F\"\nvalue = \"x*y\"\n\
         [[claim]]\nclaim = \"{L, H} = 0\"\nexpect = \"refuted\"\n",
    )
    .expect("write the file");
    assert_eq!(written("top.toml"), ["C^2", "H + C"]);
    assert_eq!(written("split.toml"), ["Hx^2"]);
    // `{L, H} = (a − b) xy`: zero at a = b = 1, and at other values a multiple of F that
    // homogeneity cannot lift (a and b have one weight), found with a and b kept symbolic.
    assert_eq!(written("weights.toml"), ["(a - b)*F"]);
}

/// Names run together that are not declared read as the product of the declared names they
/// split into, and the claim's echo shows that product: `{Lx, H}`, a misspelt `L_x` beside a
/// declared `L`, echoes as `{L x, H}` (it echoed `{Lx, H}`, so that the reading could not be
/// seen), while variables run together stay together, a power on the last of them (`Mω²x`) or,
/// in parentheses, on all (`(Mω)²`).
#[test]
fn names_run_together_echo_as_the_product_they_read_as() {
    let dir = scratch("run-together");
    std::fs::write(
        dir.join("osc.toml"),
        "hamiltonian = \"(p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"M\", \"omega\"]\n\
         [[function]]\nname = \"L\"\nvalue = \"x*p_y - y*p_x\"\n\
         [[claim]]\nclaim = \"{Lx, H} = 1\"\nexpect = \"refuted\"\n\
         [[claim]]\nclaim = \"{p_x, H} = -Momega^2x\"\n\
         [[claim]]\nclaim = \"(Momega)^2 = M^2*omega^2\"\n",
    )
    .expect("write the file");
    let o = superint_in(&dir, &["check", "osc.toml", "--no-timings"]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(out.contains("  {L x, H} = 1 "), "{out}");
    assert!(out.contains("  {p_x, H} = −Mω²x "), "{out}");
    assert!(out.contains("  (Mω)² = M²ω² "), "{out}");
}

/// A tower whose base is zero at the condition: `(ωZ)^m e^{−inθ}` at `ω = 0` is 0 for every
/// `m ≥ 1`, so `{K, H} = λK` holds there for any `λ`, and the eigenvalue's `m(m − 1)M`, which
/// is no multiple of `m`, refutes nothing: the comparison is made on the line `m = 0`, where
/// `λ(0, n) = −inΩ` is `nλ(0, 1)`, and the identity is proved for all `m, n`. With `ω` free
/// the same eigenvalue is wrong at `(2, 0)` and the proof refutes it. An eigenvalue written
/// `i(mω − nΩ)`, a name before parentheses, is a polynomial of degree 1 in the indices.
#[test]
fn a_tower_with_a_zero_base_is_proved_where_its_instances_are_zero() {
    let dir = scratch("zero-base");
    let rotor = "name = \"rotor\"\n\
         hamiltonian = \"(p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2 + p_theta^2/(2*I)\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nangles = [\"theta\"]\n\
         parameters = [\"M\", \"omega\", \"I\"]\n\
         [[function]]\nname = \"Z\"\nvalue = \"p_x + i*p_y + i*M*omega*(x + i*y)\"\n\
         [[function]]\nname = \"Omega\"\ndisplay = \"Ω\"\nvalue = \"p_theta/I\"\n";
    std::fs::write(
        dir.join("zero.toml"),
        format!(
            "{rotor}[[family]]\nname = \"K\"\nvalue = \"(omega*Z)^m*exp(-i*n*theta)\"\n\
             eigenvalue = \"i*(m*omega - n*Omega) + m*(m - 1)*M\"\n"
        ),
    )
    .expect("write zero.toml");
    let tower = |when: &[&str]| {
        let mut args = vec![
            "tower",
            "--system",
            "zero.toml",
            "--max",
            "2",
            "--no-timings",
        ];
        args.extend_from_slice(when);
        superint_in(&dir, &args)
    };
    let o = tower(&["--when", "omega = 0"]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(out.contains("[K-all proved]"), "{out}");
    let words = out.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        words.contains(
            "equals mλ(1, 0) + nλ(0, 1) where K_{m,n} is not 0 (the first base is 0, so K_{m,n} \
             is 0 for m ≥ 1): both are polynomials of degree at most 2 in m, n, and they agree \
             at the 3 points m = 0, 0 ≤ n ≤ 2: holds"
        ),
        "{out}"
    );
    let o = tower(&[]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}");
    let words = out.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        words.contains("they differ at (m, n) = (2, 0): FAILS"),
        "{out}"
    );
    assert!(out.contains("[K-all REFUTED]"), "{out}");
    std::fs::write(
        dir.join("written.toml"),
        format!(
            "{rotor}[[family]]\nname = \"K\"\nvalue = \"Z^m*exp(-i*n*theta)\"\n\
             eigenvalue = \"i(m*omega - n*Omega)\"\n"
        ),
    )
    .expect("write written.toml");
    let o = superint_in(
        &dir,
        &[
            "tower",
            "--system",
            "written.toml",
            "--max",
            "2",
            "--no-timings",
        ],
    );
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(out.contains("[K-all proved]"), "{out}");
}

/// A name of the file written as an instance of one of its families (`K_2_0` beside `K`)
/// would make `K_{2,0}` stand for two things (it read as the function, so that the true
/// `K_{2,0} = x²` was refuted): refused with line and column, at the family, which is read
/// after the functions and parameters.
#[test]
fn a_name_written_as_a_family_instance_is_refused() {
    let dir = scratch("instance-name");
    let head = "hamiltonian = \"p_x^2/2 + p_theta^2/2\"\n\
         [phase_space]\ncoordinates = [\"x\"]\nangles = [\"theta\"]\n";
    let family = "[[family]]\nname = \"K\"\nvalue = \"x^m*exp(i*n*theta)\"\n";
    let function = "[[function]]\nname = \"K_2_0\"\nvalue = \"p_x\"\n";
    std::fs::write(dir.join("f.toml"), format!("{head}{family}{function}")).expect("write");
    let o = superint_in(&dir, &["check", "f.toml"]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(
        text(&o.stderr).lines().next().unwrap_or_default(),
        "superint: error: f.toml:9:8: 'K_2_0' cannot be a function of this file, which \
         declares a family 'K' on line 6: 'K_2_0' is the instance K_{2,0} of the family K; give \
         one of them another name"
    );
    // The second in the file is refused, though the functions are declared before the
    // families: a function named as a family below it.
    let same = "[[function]]\nname = \"K\"\nvalue = \"p_x\"\n";
    std::fs::write(dir.join("s.toml"), format!("{head}{family}{same}")).expect("write");
    let o = superint_in(&dir, &["check", "s.toml"]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(
        text(&o.stderr).lines().next().unwrap_or_default(),
        "superint: error: s.toml:9:8: 'K' is already declared as a family on line 6, so it \
         cannot be a function too"
    );
    let parameter = head.replace("angles", "parameters = [\"K_1_1\"]\nangles");
    std::fs::write(dir.join("p.toml"), format!("{parameter}{family}")).expect("write");
    let o = superint_in(&dir, &["check", "p.toml"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        text(&o.stderr).contains(
            "'K' cannot be a family of this file, which declares a \
             parameter 'K_1_1' on line 4"
        ),
        "{}",
        text(&o.stderr)
    );
    // Not an instance: `K_2` (one index), `K_a_b`, and the family's own name elsewhere.
    let fine = "[[function]]\nname = \"K_2\"\nvalue = \"p_x\"\n[[function]]\nname = \"K_a_b\"\nvalue = \"x\"\n";
    std::fs::write(dir.join("ok.toml"), format!("{head}{family}{fine}")).expect("write");
    let o = superint_in(&dir, &["check", "ok.toml"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
}

/// A family's index that is another spelling of a variable (`ω` beside the parameter
/// `omega`, `theta` beside the angle `θ`) would print as the variable does (`K_{ω,n}`,
/// `i(ωω − nΩ)`): refused at the indices, as a name declared in the file is.
#[test]
fn an_index_spelled_as_a_variable_is_refused() {
    let dir = scratch("index-spelling");
    let file = |angle: &str, index: &str| {
        format!(
            "hamiltonian = \"p_x^2/2 + omega^2*x^2/2\"\n\
             [phase_space]\ncoordinates = [\"x\"]\nangles = [\"{angle}\"]\n\
             parameters = [\"omega\"]\n\
             [[family]]\nname = \"K\"\nindices = [\"{index}\", \"n\"]\n\
             value = \"x^{index}*exp(i*n*{angle})\"\n"
        )
    };
    let refused = [
        (
            "theta",
            "ω",
            "the index 'ω' is already a name of the parameter 'omega'",
        ),
        (
            "θ",
            "theta",
            "the index 'theta' is already a name of the angle 'θ'",
        ),
    ];
    for (k, (angle, index, message)) in refused.into_iter().enumerate() {
        let name = format!("f{k}.toml");
        std::fs::write(dir.join(&name), file(angle, index)).expect("write");
        let o = superint_in(&dir, &["check", &name]);
        assert_eq!(o.status.code(), Some(2));
        let err = text(&o.stderr);
        assert!(
            err.starts_with(&format!("superint: error: {name}:8:11: {message}")),
            "{err}"
        );
    }
    std::fs::write(dir.join("ok.toml"), file("theta", "m")).expect("write");
    let o = superint_in(&dir, &["expand", "ok.toml", "K_2_1"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
}

/// An oscillator whose frequency `a` and coordinate `x` are shown as `ω₊` and `ξ`
/// (`[phase_space] display`), with one claim refuted for its residual.
const SHOWN: &str = r#"name = "shown"
hamiltonian = "p_x^2/(2*M) + M*a^2*x^2/2"

[phase_space]
coordinates = ["x"]
parameters = ["M", "a"]
display = { a = "ω₊", x = "ξ" }

[[function]]
name = "A"
value = "p_x + i*M*a*x"

[[claim]]
id = "ladder"
claim = "{A, H} = i*a*p_x - M*a^2*x"

[[claim]]
id = "false-ladder"
claim = "{A, H} = 0"
expect = "refuted"
"#;

/// A display of `[phase_space]` prints wherever the name would: text (`ω₊`, the momentum
/// `p_ξ`, spaced as its own letters ask), LaTeX (`\omega_{+}`, `p_{\xi}`), JSON's `statement`; the input and JSON's `ascii`
/// and `residual` keep the declared names, and the residual reads back in the file.
#[test]
fn a_variable_display_prints_in_every_output_and_its_ascii_reads_back() {
    let dir = scratch("variable-display");
    std::fs::write(dir.join("shown.toml"), SHOWN).expect("write");
    let o = superint_in(&dir, &["check", "shown.toml", "--no-timings"]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}{}", text(&o.stderr));
    for piece in [
        "{A, H} = i ω₊ p_ξ − M ω₊² ξ",
        // `2M`, not `2 M`: the text writes `ξ`, never the `x` that beside `i` would spell
        // `xi`, one of ξ's input spellings.
        "H = p_ξ²/(2M) + M ω₊² ξ²/2",
        "residual lhs − rhs = i ω₊ p_ξ − M ω₊² ξ",
        "{A, H} = 0",
    ] {
        assert!(out.contains(piece), "{piece}: {out}");
    }
    assert!(!out.contains("p_x") && !out.contains("ω₊ = a"), "{out}");
    let o = superint_in(&dir, &["check", "shown.toml", "--format", "latex"]);
    let latex = text(&o.stdout);
    assert!(latex.contains(r"\omega_{+}"), "{latex}");
    assert!(latex.contains(r"p_{\xi}"), "{latex}");
    assert!(!latex.contains('ω') && !latex.contains('₊'), "{latex}");
    let o = superint_in(&dir, &["check", "shown.toml", "--format", "json"]);
    let v: Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let claims = v["claims"].as_array().expect("claims");
    assert_eq!(claims[0]["statement"], "{A, H} = i ω₊ p_ξ − M ω₊² ξ");
    assert_eq!(claims[0]["ascii"], "{A, H} = i*a*p_x - M*a^2*x");
    let residual = claims[1]["residual"].as_str().expect("a residual");
    assert!(
        residual.contains("a") && !residual.contains('ω'),
        "{residual}"
    );
    // The residual, in the file's names, reads back: {A, H} equals it.
    let again =
        format!("{SHOWN}\n[[claim]]\nid = \"residual\"\nclaim = \"{{A, H}} = {residual}\"\n");
    std::fs::write(dir.join("again.toml"), again).expect("write");
    let o = superint_in(&dir, &["check", "again.toml", "--no-timings"]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}{}", text(&o.stderr));
    assert!(out.contains("[residual proved]"), "{out}");
}

/// Functions and a family named with Greek letters spelled out, and `hbar`, `ell`: see
/// [`a_claims_echo_writes_names_as_its_expressions_do`].
const GREEK_NAMES: &str = r#"name = "greek names"
hamiltonian = "p_x^2/2 + omega^2*x^2/2 + p_theta1^2/2 + hbar*ell"

[phase_space]
coordinates = ["x"]
angles = ["theta1"]
parameters = ["omega", "hbar", "ell"]

[[function]]
name = "omega3"
value = "p_x^2 + x^2"

[[family]]
name = "Q_theta1"
value = "(p_x + i*x)^m*exp(i*n*theta1)"

[[claim]]
id = "square"
claim = "{omega3^2, H} = 0"
expect = "refuted"

[[claim]]
id = "q"
claim = "{Q_theta1_1_1, omega3} = hbar*ell*Q_theta1_1_1"
expect = "refuted"
"#;

/// A claim's echo writes a function's or a family's name as the expressions of the same
/// report write it, its Greek letters as letters (`ω3²`, `Q_θ1_{1,1}` beside the residual's
/// `−(ħℓ − 2i) Q_θ1_{1,1}`; it echoed `omega3²` and `Q_theta1_{1,1}`), and `hbar`, `ell` as `ħ`, `ℓ`
/// as `omega` is `ω` (it echoed `hbar ell`), in text, Markdown, JSON's `statement` and LaTeX
/// (`\omega_{3}`, `Q_{\theta1;1,1}`, `\hbar\ell`), while JSON's `ascii` keeps the names; and
/// so does a bracket table.
#[test]
fn a_claims_echo_writes_names_as_its_expressions_do() {
    let dir = scratch("greek-echo");
    std::fs::write(dir.join("greek.toml"), GREEK_NAMES).expect("write");
    let check = |format: &str| {
        let o = superint_in(
            &dir,
            &["check", "greek.toml", "--no-timings", "--format", format],
        );
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
        text(&o.stdout)
    };
    let out = check("text");
    for piece in [
        "{ω3², H} = 0",
        "{Q_θ1_{1,1}, ω3} = ħℓ Q_θ1_{1,1}",
        "= −(ħℓ − 2i) Q_θ1_{1,1}",
        "+ ħℓ",
    ] {
        assert!(out.contains(piece), "{piece}: {out}");
    }
    for wrong in ["omega3", "theta1", "hbar", "ell"] {
        assert!(!out.contains(wrong), "{wrong}: {out}");
    }
    let markdown = check("markdown");
    assert!(
        markdown.contains("`{Q_θ1_{1,1}, ω3} = ħℓ Q_θ1_{1,1}`"),
        "{markdown}"
    );
    let latex = check("latex");
    for piece in [
        r"\{\omega_{3}^{2}, H\}",
        r"\{Q_{\theta1;1,1}, \omega_{3}\} &= \hbar\ell Q_{\theta1;1,1}",
    ] {
        assert!(latex.contains(piece), "{piece}: {latex}");
    }
    assert!(
        !latex.contains("hbar}") && !latex.contains("mathrm"),
        "{latex}"
    );
    let v: Value = serde_json::from_str(&check("json")).expect("JSON");
    let claims = v["claims"].as_array().expect("claims");
    assert_eq!(claims[1]["statement"], "{Q_θ1_{1,1}, ω3} = ħℓ Q_θ1_{1,1}");
    assert_eq!(
        claims[1]["ascii"],
        "{Q_theta1_1_1, omega3} = hbar*ell*Q_theta1_1_1"
    );
    // A bracket table names them so too, in its headers and its entries (it wrote `omega3`,
    // `−2i Q_theta1_{1,1}`).
    let o = superint_in(
        &dir,
        &[
            "table",
            "greek.toml",
            "omega3",
            "Q_theta1_1_1",
            "--no-timings",
        ],
    );
    let table = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(
        table.contains("    ω3         │ 0               −2i Q_θ1_{1,1}\n"),
        "{table}"
    );
    assert!(
        !table.contains("omega3") && !table.contains("theta1"),
        "{table}"
    );
}

/// A description and a source may run over several lines (a TOML string of several lines, its
/// line breaks `\r\n` in a file written so, which printed as `�` and a line break), which the
/// reports keep as line breaks, and indent them with tabs, which the reports print as written
/// (a tab was refused as a control character); an id or the system's name may not ("a claim's
/// id with an escaped line break" in [`bad_inputs`]).
#[test]
fn a_description_may_run_over_lines() {
    let dir = scratch("description-lines");
    let file = BASE.replace(
        "name = \"oscillator\"",
        "name = \"oscillator\"\ndescription = \"\"\"\nOne line,\n\tand another.\"\"\"\n\
         source = \"A. Author,\\r\\nsome journal\"",
    );
    std::fs::write(dir.join("lines.toml"), file).expect("write");
    let o = superint_in(&dir, &["check", "lines.toml", "--no-timings"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert!(out.contains("One line,\n\tand another."), "{out}");
    assert!(out.contains("Source: A. Author,\nsome journal"), "{out}");
}

/// A fresh directory `name` holding `osc.toml`, the oscillator `p_x²/(2M) + Mω²x²/2` with the
/// parameters `M` and `ω` (`BASE` without its function and claim).
fn oscillator_in(name: &str) -> PathBuf {
    let dir = scratch(name);
    std::fs::write(
        dir.join("osc.toml"),
        "name = \"oscillator\"\nhamiltonian = \"p_x^2/(2*M) + M*omega^2*x^2/2\"\n\
         [phase_space]\ncoordinates = [\"x\"]\nparameters = [\"M\", \"omega\"]\n",
    )
    .expect("written");
    dir
}

/// `bracket --when` says where the flow of `H` does not keep the condition: `{x, H}` of an
/// oscillator at `x = 0` has a value there, but a bracket that vanishes on a surface the flow
/// leaves is no conservation law, and nothing said so. A resonance the flow keeps gets no note.
#[test]
fn bracket_at_a_condition_the_flow_leaves_says_so() {
    let dir = oscillator_in("bracket-flow-note");
    // A sentence, as the report's other notes are.
    let note = "Note: x = 0 is not kept by the flow of H ({x, H} = p_x/M there): a zero is no \
                conservation law.\n";
    let o = superint_in(
        &dir,
        &["bracket", "osc.toml", "x^2", "H", "--when", "x = 0"],
    );
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert!(out.contains(&format!("    {{x², H}} = 0\n{note}")), "{out}");
    let o = superint_in(
        &dir,
        &[
            "bracket", "osc.toml", "x^2", "H", "--when", "x = 0", "--format", "json",
        ],
    );
    let v: Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let eq = &v["equations"][0];
    assert_eq!(eq["kept_by_flow"], false, "{eq}");
    assert_eq!(
        eq["flow_note"],
        "x = 0 is not kept by the flow of H ({x, H} = p_x/M there): a zero is no conservation \
         law.",
        "{eq}"
    );
    // A condition the flow keeps: no note; without one, no key.
    let args = ["bracket", "systems/harmonic-rotor.toml", "P_1_1", "H"];
    let o = superint_in(
        root(),
        &[&args[..], &["--when", "p_theta = I*omega"]].concat(),
    );
    assert!(!text(&o.stdout).contains("Note:"), "{}", text(&o.stdout));
    let o = superint_in(
        root(),
        &[
            &args[..],
            &["--when", "p_theta = I*omega", "--format", "json"],
        ]
        .concat(),
    );
    let v: Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(v["equations"][0]["kept_by_flow"], true);
    assert_eq!(v["equations"][0]["flow_note"], Value::Null);
    let o = superint_in(root(), &[&args[..], &["--format", "json"]].concat());
    let v: Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(v["equations"][0].get("kept_by_flow"), None);
}

/// Where the bracket printed is not zero on a surface the flow leaves, the note says only that
/// the flow leaves it: `{x, H} = p_x/M` at `x = 0` is no zero, and the note ended with a zero is
/// no conservation law, which said nothing of it.
#[test]
fn bracket_that_is_no_zero_at_a_condition_the_flow_leaves_says_no_more() {
    let dir = oscillator_in("bracket-flow-note-no-zero");
    let note = "x = 0 is not kept by the flow of H ({x, H} = p_x/M there).";
    let o = superint_in(&dir, &["bracket", "osc.toml", "x", "H", "--when", "x = 0"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert!(
        out.contains(&format!("    {{x, H}} = p_x/M\nNote: {note}\n")),
        "{out}"
    );
    let o = superint_in(
        &dir,
        &[
            "bracket", "osc.toml", "x", "H", "--when", "x = 0", "--format", "json",
        ],
    );
    let v: Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let eq = &v["equations"][0];
    assert_eq!(eq["kept_by_flow"], false, "{eq}");
    assert_eq!(eq["flow_note"], note, "{eq}");
}

/// Where a limit stops the check whether the flow of `H` keeps a `bracket --when` condition,
/// a note says so with the limit's message, and JSON's `kept_by_flow` is null: nothing was said
/// and no note appeared. Here the bracket fits 4 terms, but `{x − (y p_y + y + p_y), H}` has 5.
#[test]
fn bracket_at_a_condition_whose_flow_check_passes_a_limit_says_so() {
    let dir = scratch("bracket-flow-note-limit");
    std::fs::write(
        dir.join("osc.toml"),
        "name = \"oscillator\"\nhamiltonian = \"p_x^2/2 + p_y^2/2 + x^2/2 + y^2/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\n",
    )
    .expect("written");
    let args = [
        "bracket",
        "osc.toml",
        "x",
        "y",
        "--when",
        "x = y*p_y + y + p_y",
        "--max-terms",
        "4",
    ];
    let note = "whether x = y p_y + y + p_y is kept by the flow of H was not checked: the result \
                would have more than 4 terms (the term limit); raise the limit or simplify the \
                input.";
    let o = superint_in(&dir, &args);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let out = text(&o.stdout);
    assert!(out.contains("    {x, y} = 0\nNote: whether x = y p_y + y + p_y is kept by the flow of H was not checked: the result would\nhave more than 4 terms"), "{out}");
    let o = superint_in(&dir, &[&args[..], &["--format", "json"]].concat());
    let v: Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let eq = &v["equations"][0];
    assert_eq!(eq["kept_by_flow"], Value::Null, "{eq}");
    assert_eq!(eq["flow_note"], note, "{eq}");
    // With room for the check, it is decided.
    let o = superint_in(&dir, &args[..6]);
    assert!(
        text(&o.stdout).contains("is not kept by the flow of H"),
        "{}",
        text(&o.stdout)
    );
}

/// A parameter named epsilon prints in LaTeX as `\varepsilon`, the letter `ε` its text prints
/// (it printed `\epsilon`, which LaTeX sets as the lunate `ϵ`), as `φ` prints `\varphi`; and
/// each spelling of it still reads as the one parameter.
#[test]
fn epsilon_prints_in_latex_as_the_letter_its_text_prints() {
    let dir = scratch("epsilon-latex");
    std::fs::write(
        dir.join("eps.toml"),
        "name = \"oscillator\"\nhamiltonian = \"p_x^2/2 + epsilon*x^2/2\"\n\
         [phase_space]\ncoordinates = [\"x\"]\nparameters = [\"epsilon\"]\n",
    )
    .expect("written");
    for spelling in ["epsilon", "ε", "ϵ", r"\epsilon", r"\varepsilon"] {
        let bracket = |format: &str| {
            let o = superint_in(
                &dir,
                &[
                    "bracket",
                    "eps.toml",
                    "p_x",
                    &format!("{spelling}*x"),
                    "--format",
                    format,
                ],
            );
            assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
            text(&o.stdout)
        };
        let latex = bracket("latex");
        assert!(latex.contains(r"\varepsilon"), "{spelling}: {latex}");
        assert!(!latex.contains(r"\epsilon"), "{spelling}: {latex}");
        let plain = bracket("text");
        assert!(plain.contains("ε"), "{spelling}: {plain}");
        assert!(!plain.contains("ϵ"), "{spelling}: {plain}");
    }
}

/// The Kepler problem in the plane with a root written out in a claim: see
/// [`a_claims_echo_writes_a_root_as_the_paper_does`].
const ROOT_WRITTEN: &str = r#"name = "planar Kepler"
hamiltonian = "(p_x^2 + p_y^2)/2 - k/r"

[phase_space]
coordinates = ["x", "y"]
parameters = ["k"]
radicals = { r = "x^2 + y^2" }

[[claim]]
id = "root"
claim = "{r, p_x} = x/sqrt(x^2 + y^2)"
"#;

/// A claim's echo writes `sqrt(…)` as a function, `x/√(x² + y²)` in text and
/// `x/\sqrt{x^{2} + y^{2}}` in LaTeX, as the report's `r = √(x² + y²)` is set: it echoed
/// `x/(sqrt(x² + y²))` and `x/(\operatorname{sqrt}(x^{2} + y^{2}))`, the root taken for a
/// name multiplying its parentheses, and then `x/sqrt(x² + y²)` in text. The text and the
/// LaTeX each read back to the same claim (the parser refused `√`).
#[test]
fn a_claims_echo_writes_a_root_as_the_paper_does() {
    let dir = scratch("root-echo");
    std::fs::write(dir.join("kepler.toml"), ROOT_WRITTEN).expect("write");
    let o = superint_in(&dir, &["check", "kepler.toml", "--no-timings"]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}{}", text(&o.stderr));
    let text_echo = "{r, p_x} = x/√(x² + y²)";
    assert!(out.contains(text_echo), "{out}");
    assert!(!out.contains("sqrt"), "{out}");
    let o = superint_in(&dir, &["check", "kepler.toml", "--format", "latex"]);
    let latex = text(&o.stdout);
    let echo = r"\{r, p_{x}\} &= x/\sqrt{x^{2} + y^{2}}";
    assert!(latex.contains(echo), "{latex}");
    assert!(!latex.contains("operatorname{sqrt}"), "{latex}");
    let again = format!(
        "{ROOT_WRITTEN}\n[[claim]]\nid = \"again\"\nclaim = '{}'\n\
         \n[[claim]]\nid = \"again-text\"\nclaim = '{text_echo}'\n",
        echo.replace(" &=", " =")
    );
    std::fs::write(dir.join("again.toml"), again).expect("write");
    let o = superint_in(&dir, &["check", "again.toml", "--no-timings"]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}{}", text(&o.stderr));
    assert!(out.contains("[again proved]"), "{out}");
    assert!(out.contains("[again-text proved]"), "{out}");
    // The text reads back to the same expression, and prints as it did.
    let line = out.lines().find(|l| l.contains("[again-text proved]"));
    assert!(
        line.is_some_and(|l| l.trim().starts_with(text_echo)),
        "{out}"
    );
}

/// A rotor with claims whose products put a factor after a sine or cosine of a bare angle:
/// see [`a_claims_echo_sets_a_sine_or_cosine_apart_from_a_factor_after_it`].
const TRIG_BEFORE_FACTOR: &str = r#"name = "rotor and oscillator"
hamiltonian = "p_theta^2/(2*I) + (p_x^2 + x^2)/2"

[phase_space]
coordinates = ["x"]
angles = ["theta"]
parameters = ["I"]

[[claim]]
id = "cos"
claim = "{cos(theta), H} = -sin(theta)*p_theta/I"

[[claim]]
id = "product"
claim = "cos(theta)*x = x*cos(theta)"

[[claim]]
id = "square"
claim = "cos(theta)^2*x*p_x = x*p_x*cos(theta)^2"

[[claim]]
id = "both"
claim = "sin(theta)*cos(theta) = sin(2*theta)/2"

[[claim]]
id = "nested"
claim = "cos(theta)*(sin(theta)*x) = x*sin(theta)*cos(theta)"
"#;

/// A claim's echo sets a sine or cosine of a bare angle apart from a factor after it,
/// `(cos θ) x`, `(−sin θ) p_θ/I` as `(x sin θ)/2` is set apart from a denominator, because it
/// echoed `cos θ x` and `−sin θ p_θ/I`, which read as the cosine of `θx` and the sine of
/// `θ p_θ` (LaTeX `\cos\theta x`); a sine or cosine after it needs no parentheses
/// (`sin θ cos θ`), but a factor that begins with one set apart does (`(cos θ) (sin θ) x`).
/// What it prints reads back to the same value.
#[test]
fn a_claims_echo_sets_a_sine_or_cosine_apart_from_a_factor_after_it() {
    let dir = scratch("trig-before-factor");
    std::fs::write(dir.join("rotor.toml"), TRIG_BEFORE_FACTOR).expect("write");
    let o = superint_in(&dir, &["check", "rotor.toml", "--no-timings"]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}{}", text(&o.stderr));
    for piece in [
        "{cos θ, H} = (−sin θ) p_θ/I",
        "(cos θ) x = x cos θ",
        "(cos²θ) x p_x = x p_x cos²θ",
        "sin θ cos θ = (sin 2θ)/2",
        // The factor after it begins with a sine set apart, not with the sine.
        "(cos θ) (sin θ) x = x sin θ cos θ",
    ] {
        assert!(out.contains(piece), "{piece}: {out}");
    }
    let o = superint_in(&dir, &["check", "rotor.toml", "--format", "latex"]);
    let latex = text(&o.stdout);
    assert!(latex.contains(r"(\cos\theta) x &= x \cos\theta"), "{latex}");
    assert!(!latex.contains(r"\cos\theta x"), "{latex}");
    assert!(!latex.contains(r"\cos\theta (\sin"), "{latex}");
    // The echo reads back: each left side expands as its right side does.
    for (echo, expanded) in [
        ("(−sin θ) p_θ/I", "−(p_θ sin θ)/I"),
        ("(cos θ) x", "x cos θ"),
        // cos²θ = (1 + cos 2θ)/2, cos θ sin θ = (sin 2θ)/2.
        ("(cos²θ) x p_x", "x p_x/2 + (x p_x cos 2θ)/2"),
        ("(cos θ) (sin θ) x", "(x sin 2θ)/2"),
    ] {
        let o = superint_in(&dir, &["expand", "rotor.toml", "--", echo]);
        let out = text(&o.stdout);
        assert_eq!(o.status.code(), Some(0), "{out}{}", text(&o.stderr));
        assert!(out.contains(&format!("= {expanded}")), "{echo}: {out}");
    }
}

/// A claim whose sine or cosine passes the term limit as it is expanded is undecided at the
/// limit, with the hint to raise it, as one whose power passes it is: the expansion's refusal
/// lost its cause, so that the file was refused as a mistake of its expression, with no hint.
#[test]
fn a_sine_past_the_term_limit_is_a_limit_with_its_hint() {
    let dir = scratch("sine-past-the-term-limit");
    std::fs::write(
        dir.join("rotor.toml"),
        "name = \"rotor\"\nhamiltonian = \"p_theta^2\"\n[phase_space]\nangles = [\"theta\"]\n\
         [limits]\nmax_terms = 1\n[[claim]]\nid = \"cos\"\nclaim = \"cos(theta) = cos(theta)\"\n",
    )
    .expect("write");
    let o = superint_in(&dir, &["check", "rotor.toml", "--no-timings"]);
    let (stdout, stderr) = (text(&o.stdout), text(&o.stderr));
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stdout.contains("[cos UNDECIDED]"), "{stdout}{stderr}");
    assert!(
        stderr.contains("rotor.toml:9:14: the result would have more than 1 term (the term limit)")
            && stderr
                .contains("hint: if the machine has the memory, raise the limit with max_terms"),
        "{stderr}"
    );
}

/// With `--system NAME`, a first positional that named an existing file was taken for a system
/// file and refused beside `--system`, so that in a directory holding a file named `L` or `G1`
/// `bracket --system harmonic L H` said "the argument 'L' cannot be used with '--system
/// harmonic'". Every positional is now an expression but `-` and a name ending in `.toml`,
/// which are still refused as files.
#[test]
fn a_built_in_systems_expressions_are_not_taken_for_files_of_their_names() {
    let dir = crate::scratch_text("names-as-files", "L", "")
        .parent()
        .expect("a directory")
        .to_path_buf();
    for name in ["H", "G1", "x.toml"] {
        std::fs::write(dir.join(name), "").expect("the file is written");
    }
    let ok = |args: &[&str]| {
        let o = superint_in(&dir, args);
        assert_eq!(
            o.status.code(),
            Some(0),
            "superint {args:?}: {}",
            text(&o.stderr)
        );
        text(&o.stdout)
    };
    let h = "--system";
    let out = ok(&["bracket", h, "harmonic", "L", "H", "--no-timings"]);
    assert!(out.contains("{L, H} = 0"), "{out}");
    let out = ok(&["bracket", h, "harmonic", "G1", "G2", "--no-timings"]);
    assert!(out.contains("= −ω² L"), "{out}");
    ok(&["expand", h, "harmonic", "G1", "--no-timings"]);
    ok(&["table", h, "harmonic", "L", "G1", "--no-timings"]);
    ok(&["rank", h, "harmonic", "L", "H", "--no-timings"]);
    for file in ["x.toml", "-"] {
        let o = superint_in(&dir, &["bracket", h, "harmonic", file, "H"]);
        assert_eq!(o.status.code(), Some(2), "{file}");
        assert!(
            text(&o.stderr).contains(&format!("'{file}' cannot be used with '--system harmonic'")),
            "{}",
            text(&o.stderr)
        );
    }
}

/// A refused text that runs on past its first line shows the line where it ends too, in a
/// system file's multi-line string (the Hamiltonian's divisor, a claim's, with `…` for the
/// lines between) and on the command line (a `--when` and an expression given over two
/// lines), the line numbers right-aligned: the excerpt showed the first line alone, `x/(x +`,
/// whose divisor the reader could not see closed.
#[test]
fn a_refusal_over_several_lines_shows_both_its_ends() {
    let declare = |d: &str| {
        format!(
            "only division by a nonzero constant, a single term (monomial) or a product of \
             powers of declared denominators is exact here; declare it (or its factors) as a \
             denominator: denominators = [\"{d}\"] in [phase_space]"
        )
    };
    let files = [
        (
            "hamiltonian = \"\"\"\np_x^2/2 +\n  x^2/(1 +\n  x)\"\"\"\n",
            format!(
                "h.toml:4:7: cannot divide by x + 1: {}\n 4 |   x^2/(1 +\n   |       ^^^^\n \
                 5 |   x)\"\"\"\n   |   ^^",
                declare("x + 1")
            ),
        ),
        (
            "hamiltonian = \"p_x^2/2\"\n# a\n# b\n[[claim]]\nid = \"a\"\n\
             claim = \"\"\"{x, H} = x/(x +\n\n\n  1 +\n  p_x) + 1\"\"\"\n",
            format!(
                "h.toml:7:23: cannot divide by p_x + x + 1: {}\n  7 | claim = \"\"\"{{x, H}} = \
                 x/(x +\n    |                       ^^^^\n  … |\n 11 |   p_x) + 1\"\"\"\n    \
                 |   ^^^^",
                declare("p_x + x + 1")
            ),
        ),
    ];
    for (body, said) in files {
        let text = format!("name = \"oscillator\"\n{body}[phase_space]\ncoordinates = [\"x\"]\n");
        let limits = superint::system_file::LimitsOverride::default();
        let err = match superint::system_file::load_str("h.toml", &text, &limits) {
            Err(e) => e,
            Ok(file) => superint::system_file::check_report([&file]).unwrap_err(),
        };
        assert_eq!(err.to_string(), said, "{text}");
    }
    let refused = |args: &[&str]| {
        let o = superint_in(root(), args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        String::from_utf8(o.stderr).expect("UTF-8")
    };
    let rotor = "systems/harmonic-rotor.toml";
    let when = ["--when", "x = 1/(y +\n p_y)"];
    assert_eq!(
        refused(&[&["bracket", rotor, "x", "H"][..], &when].concat()),
        format!(
            "superint: error: <command line>:1:7: cannot divide by p_y + y: {}\n 1 | x = 1/(y \
             +\n   |       ^^^^\n 2 |  p_y)\n   |  ^^^^\n",
            declare("p_y + y")
        )
    );
    assert_eq!(
        refused(&[&["search", "--system", "harmonic"][..], &when].concat()),
        refused(&[&["bracket", rotor, "x", "H"][..], &when].concat()),
    );
    assert_eq!(
        refused(&["expand", rotor, "x/(x +\n y)"]),
        format!(
            "superint: error: <command line>:1:3: cannot divide by x + y: {}\n 1 | x/(x +\n   |   \
             ^^^^\n 2 |  y)\n   |  ^^\n",
            declare("x + y")
        )
    );
}
