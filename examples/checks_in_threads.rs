//! A system file given as a string, its claims checked on several threads and read as data;
//! a function formed in code from the file's own and added as an `Expr`; identities of code's
//! own checked in parallel and reported in LaTeX; and a bad file's error carried out of its
//! thread, with its line and column.
//!
//! Systems, loaded systems and their errors are `Send + Sync + 'static`: a `LoadedSystem` is
//! shared by reference with scoped threads, and a `FileError` goes into a
//! `Box<dyn Error + Send + Sync>`.
//!
//! Run with `cargo run --example checks_in_threads`.

use std::error::Error;
use std::thread;

use superint::prelude::*;

/// The planar oscillator with frequencies 1 : 3: `a = p_x + iωx`, `b = p_y + 3iωy` have
/// `{a, H} = iωa`, `{b, H} = 3iωb`, so `a³ b̄` is conserved.
const OSCILLATOR: &str = r#"
name = "anisotropic oscillator 1:3"
hamiltonian = "(p_x^2 + p_y^2)/2 + omega^2*(x^2 + 9*y^2)/2"

[phase_space]
coordinates = ["x", "y"]
parameters = ["omega"]

[[function]]
name = "Hx"
display = "H_x"
value = "p_x^2/2 + omega^2*x^2/2"

[[function]]
name = "a"
value = "p_x + i*omega*x"

[[function]]
name = "b"
value = "p_y + 3*i*omega*y"

[[function]]
name = "C"
value = "re(a^3*conj(b))"

[[claim]]
id = "quartic"
claim = "{C, H} = 0"

[[claim]]
id = "ladder"
claim = "{b, H} = 3*i*omega*b"

[[claim]]
id = "wrong-resonance"
claim = "{re(a^2*conj(b)), H} = 0"
expect = "refuted"
"#;

fn main() -> Result<(), Box<dyn Error + Send + Sync>> {
    let mut oscillator =
        load_system_text("oscillator.toml", OSCILLATOR, &LimitsOverride::default())?;

    // S = Im(a³ b̄), formed in code from the file's functions, and |a³ b̄|² = C² + S² with it.
    let (a, b) = (oscillator.parse("a")?, oscillator.parse("b")?);
    let s = a.checked_pow(3)?.checked_mul(&b.conj())?.im()?;
    oscillator.add_function_expr("S", "S", s)?;
    oscillator.add_claim("quartic", "{S, H} = 0", None)?;
    oscillator.add_claim("modulus", "C^2 + S^2 = (2*Hx)^3*(2*(H - Hx))", None)?;

    // Each claim on a thread of its own; the system is shared, not copied.
    let checked: Vec<(String, ClaimOutcome, Option<Expr>)> = thread::scope(|scope| {
        let handles: Vec<_> = oscillator
            .claims()
            .iter()
            .map(|spec| scope.spawn(|| oscillator.check_claim(spec)))
            .collect();
        handles
            .into_iter()
            .map(|h| {
                let checked = h.join().expect("a check does not panic")?;
                let result = checked.result();
                Ok((result.id.clone(), result.outcome(), result.residual.clone()))
            })
            .collect::<Result<_, FileError>>()
    })?;
    for (id, outcome, residual) in &checked {
        match residual {
            Some(r) => println!("{id:>16}: {outcome}, residual {r}"),
            None => println!("{id:>16}: {outcome}"),
        }
    }
    // The example checks what it prints: CI runs it. The threads find what one thread does.
    let report = check_report([&oscillator])?;
    assert!(report.all_as_expected());
    let sequential: Vec<ClaimOutcome> = report.claims().iter().map(|c| c.outcome()).collect();
    let parallel: Vec<ClaimOutcome> = checked.iter().map(|c| c.1).collect();
    assert_eq!(parallel, sequential);
    assert_eq!(checked[2].1, ClaimOutcome::Refuted);

    // Identities in code, one thread each, gathered into a report and printed as LaTeX.
    let system = oscillator.system();
    let identities = [
        ("Hx", "{H_x, H} = 0", "{Hx, H}", "0"),
        ("a", "{a, H} = iωa", "{a, H}", "i*omega*a"),
        ("ab", "{a b̄, H} = 0", "{a*conj(b), H}", "0"),
    ];
    let verdicts: Vec<Verdict> = thread::scope(|scope| {
        let handles: Vec<_> = identities
            .iter()
            .map(|&(id, statement, lhs, rhs)| {
                scope.spawn(move || {
                    Claim::new(id, statement, system.parse(lhs)?, system.parse(rhs)?).check()
                })
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("a check does not panic"))
            .collect::<Result<_, EngineError>>()
    })?;
    let proved: Vec<bool> = verdicts.iter().map(|v| v.outcome.is_proved()).collect();
    assert_eq!(proved, [true, true, false]);
    let report = Report::of_claims(
        "The 1:3 oscillator",
        verdicts.into_iter().map(ClaimResult::from).collect(),
    );
    let latex = render(&report, Format::Latex, &RenderOptions::reproducible());
    let refuted = latex.lines().find(|l| l.contains("[ab REFUTED]"));
    println!(
        "as LaTeX, {} lines; the refuted one:\n  {}",
        latex.lines().count(),
        refuted.unwrap_or("?")
    );
    assert!(refuted.is_some());

    // A bad file loaded on another thread: the error comes back whole, with its place.
    let bad = OSCILLATOR.replace("re(a^3*conj(b))", "re(a^3*conj(B))");
    let err = thread::spawn(move || -> Result<(), Box<dyn Error + Send + Sync>> {
        load_system_text("bad.toml", &bad, &LimitsOverride::default())?;
        Ok(())
    })
    .join()
    .expect("loading does not panic")
    .unwrap_err();
    let file_error = err.downcast_ref::<FileError>().expect("a FileError");
    println!("{err}");
    assert_eq!(file_error.kind, ErrorKind::Expression);
    assert!(file_error.line_col().is_some());
    Ok(())
}
