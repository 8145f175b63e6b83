//! Integration tests. `claims`: every claim of the paper (ids of `docs/claims.md`), each proved
//! exactly beside a false neighbour that the engine must refute with the exact residual.
//! `library`: the library as a program uses it, a system built or extended in code.

use brackets::{Claim, Condition, Outcome, System};

/// Checks the identity `lhs = rhs`, both sides written in the notation of `system` (named
/// functions and brackets `{f, g}` allowed), under an optional condition such as a resonance.
///
/// **Panics if** the text has no `=` or a side does not parse: a test's text is fixed.
pub fn check(system: &System, identity: &str, when: Option<&Condition>) -> Outcome {
    let (lhs, rhs) = identity
        .split_once('=')
        .unwrap_or_else(|| panic!("{identity:?} is not an identity `lhs = rhs`"));
    // Read with what the sides are computed from, as the paper's claims are.
    let mut claim = Claim::parse(system, "test", identity, lhs.trim(), rhs.trim())
        .unwrap_or_else(|e| panic!("{identity:?}: {e}"));
    if let Some(c) = when {
        claim = claim.when(c.clone());
    }
    claim
        .check()
        .unwrap_or_else(|e| panic!("{identity:?}: {e}"))
        .outcome
}

/// The one way tests state identities, in the paper's notation:
///
/// - `identity!(sys, "{L, G1} = -G2")` asserts that the engine proves it;
/// - `identity!(sys, "{P, H} = 0", when sys.resonance(1, 1)?)` proves it under a condition;
/// - `identity!(sys, "{L, G1} = G2" => refuted "-2*G2")` asserts that the engine refutes it and
///   that the residual `lhs − rhs` is exactly the expected expression (read under the same
///   condition, if any); it evaluates to the residual.
macro_rules! identity {
    ($sys:expr, $text:expr) => {
        $crate::assert_proved(&$sys, &$text, None)
    };
    ($sys:expr, $text:expr, when $cond:expr) => {
        $crate::assert_proved(&$sys, &$text, Some(&$cond))
    };
    ($sys:expr, $text:expr => refuted $residual:expr) => {
        $crate::assert_refuted(&$sys, &$text, None, &$residual)
    };
    ($sys:expr, $text:expr, when $cond:expr => refuted $residual:expr) => {
        $crate::assert_refuted(&$sys, &$text, Some(&$cond), &$residual)
    };
}

/// The brackets of so(3)* as a system file's `[poisson]` table declares them, `{M1, M2} = M3`
/// and cyclically (`{M3, M1} = M2` the table's last line), for a file whose `[phase_space]`
/// has `variables = ["M1", "M2", "M3"]`: a literal, so that a file's text built with it,
/// `concat!(…, so3_poisson!(), …)`, stays one.
macro_rules! so3_poisson {
    () => {
        "[poisson]\n\"{M1, M2}\" = \"M3\"\n\"{M2, M3}\" = \"M1\"\n\"{M3, M1}\" = \"M2\"\n"
    };
}

/// The proved arm of [`identity!`].
#[track_caller]
pub fn assert_proved(system: &System, identity: &str, when: Option<&Condition>) {
    if let Outcome::Refuted { residual } = check(system, identity, when) {
        panic!(
            "{identity}{} is refuted: residual {residual}",
            when.map_or(String::new(), |c| format!(" when {}", c.text))
        );
    }
}

/// The refuted arm of [`identity!`]: the residual, which must equal `expected` (parsed, and
/// under the same condition).
#[track_caller]
pub fn assert_refuted(
    system: &System,
    identity: &str,
    when: Option<&Condition>,
    expected: &str,
) -> trigpoly::Expr {
    let mut want = system
        .parse(expected)
        .unwrap_or_else(|e| panic!("expected residual {expected:?}: {e}"));
    if let Some(c) = when {
        want = c.apply(&want).expect("the condition applies");
    }
    assert!(!want.is_zero(), "a refutation needs a nonzero residual");
    match check(system, identity, when) {
        Outcome::Proved => panic!("{identity} was proved, but it is false"),
        Outcome::Refuted { residual } => {
            pretty_assertions::assert_eq!(
                residual.to_string(),
                want.to_string(),
                "residual of {identity}"
            );
            assert_eq!(residual, want, "residual of {identity}");
            residual
        }
        other => panic!("{identity} was neither proved nor refuted: {other}"),
    }
}

/// Runs the superint binary with `args` at the workspace root, and waits for it.
pub fn superint(args: &[&str]) -> std::process::Output {
    superint_in(std::path::Path::new(env!("CARGO_MANIFEST_DIR")), args)
}

/// Runs the superint binary with `args` and `--format json`, which must succeed, and reads
/// its output.
pub fn superint_json(args: &[&str]) -> serde_json::Value {
    serde_json::from_str(&superint_ok(&[args, &["--format", "json"]].concat())).expect("JSON")
}

/// Runs the superint binary with `args`, which must exit with `code` (its standard error
/// shown when it does not), and returns what it wrote.
#[track_caller]
pub fn superint_exits(args: &[&str], code: i32) -> std::process::Output {
    let o = superint(args);
    assert_eq!(
        o.status.code(),
        Some(code),
        "superint {args:?}\nstderr: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    o
}

/// Runs the superint binary with `args`, which must succeed (exit code 0), and returns what
/// it printed.
#[track_caller]
pub fn superint_ok(args: &[&str]) -> String {
    String::from_utf8(superint_exits(args, 0).stdout).expect("UTF-8")
}

/// Runs the superint command line `command` (its arguments as a shell writes them, single
/// quotes grouping, after the program's name), which must succeed, and returns what it wrote.
#[track_caller]
pub fn superint_ok_line(command: &str) -> String {
    let args = words(command);
    superint_ok(&args.iter().map(String::as_str).collect::<Vec<_>>())
}

/// The words of a command line, single quotes grouping.
pub fn words(command: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut word = String::new();
    let mut quoted = false;
    let mut any = false;
    for c in command.chars() {
        match c {
            '\'' => {
                quoted = !quoted;
                any = true;
            }
            ' ' if !quoted => {
                if any {
                    out.push(std::mem::take(&mut word));
                    any = false;
                }
            }
            _ => {
                word.push(c);
                any = true;
            }
        }
    }
    if any {
        out.push(word);
    }
    out
}

/// Runs the superint binary with `args`, which must be refused as bad input (exit code 2),
/// and returns its message.
#[track_caller]
pub fn superint_refused(args: &[&str]) -> String {
    String::from_utf8(superint_exits(args, 2).stderr).expect("UTF-8")
}

/// Runs the superint binary with `args` in `dir` (where a file named by a bare name, as a
/// message then names it, is found), and waits for it.
pub fn superint_in(dir: &std::path::Path, args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_superint"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the superint binary runs")
}

/// Whether the identity `lhs = rhs` of a system file is proved, both sides read through it.
///
/// **Panics if** a side does not parse: a test's text is fixed.
pub fn holds(file: &superint::system_file::LoadedSystem, lhs: &str, rhs: &str) -> bool {
    let claim = brackets::Claim::new("t", "t", file.parse(lhs).unwrap(), file.parse(rhs).unwrap());
    claim.check().unwrap().outcome.is_proved()
}

/// Whitespace runs as one space, so that wrapped and padded lines compare.
pub fn normalize(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Writes `text` to the file `name` in the scratch directory `dir` (under Cargo's temporary
/// directory for tests), and returns its path.
pub fn scratch_text(dir: &str, name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(dir);
    std::fs::create_dir_all(&dir).expect("a scratch directory");
    let file = dir.join(name);
    std::fs::write(&file, text).expect("the file is written");
    file
}

/// Two families of `(p_x + ix)^m (p_x − ix)^n` for `H = (p_x² + x²)/2`: `K` with the
/// eigenvalue `i(m − n)`, and `W` with a wrong one, `i(m + n)`; `P` has none.
pub const TWO_TOWERS: &str = "name = \"oscillator\"\nhamiltonian = \"p_x^2/2 + x^2/2\"\n\
    [phase_space]\ncoordinates = [\"x\"]\n\
    [[family]]\nname = \"K\"\nvalue = \"(p_x + i*x)^m*(p_x - i*x)^n\"\neigenvalue = \"i*(m - n)\"\n\
    [[family]]\nname = \"W\"\nvalue = \"(p_x + i*x)^m*(p_x - i*x)^n\"\neigenvalue = \"i*(m + n)\"\n\
    [[family]]\nname = \"P\"\nvalue = \"re(K_m_n)\"\n";

/// The pendulum `p_t²/2 − g cos t` as a system file: one angle, the parameter `g`.
pub const PENDULUM: &str = "name = \"pendulum\"\nhamiltonian = \"p_t^2/2 - g*cos(t)\"\n\
                            [phase_space]\nangles = [\"t\"]\nparameters = [\"g\"]\n";

mod claim_inputs;
mod claims;
mod cli;
mod closure_denominators;
mod denominators;
mod discovery;
mod exceptional_values;
mod latex_input;
mod level_set_claims;
mod level_sets_with_relations;
mod library;
mod micz_kepler;
mod poisson;
mod radicals;
mod system_files;
mod time_dependent;

/// The search space of degree 1 in the momenta and the positions and trigonometric order 1.
pub const DEGREE_ONE: [&str; 6] = [
    "--momenta-degree",
    "1",
    "--positions-degree",
    "1",
    "--trig-degree",
    "1",
];

/// The search space of degree 1 in the momenta and the positions and trigonometric order 0.
pub const DEGREE_ONE_TRIG_ZERO: [&str; 6] = [
    "--momenta-degree",
    "1",
    "--positions-degree",
    "1",
    "--trig-degree",
    "0",
];
