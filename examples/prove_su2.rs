//! Proves the su(2) brackets of the harmonic rotor (claim C09) and prints its bracket table.
//!
//! Run with `cargo run --example prove_su2`.

use superint::prelude::*;

fn main() -> Result<(), EngineError> {
    let rotor = systems::harmonic_rotor();
    for (statement, lhs, rhs) in [
        ("{L, G1} = −G2", "{L, G1}", "-G2"),
        ("{L, G2} = 4 G1", "{L, G2}", "4*G1"),
        ("{G1, G2} = −ω² L", "{G1, G2}", "-omega^2*L"),
    ] {
        let claim = Claim::new("C09", statement, rotor.parse(lhs)?, rotor.parse(rhs)?);
        let verdict = claim.check()?;
        // The example checks what it prints: CI runs it.
        assert!(verdict.outcome.is_proved(), "{statement}");
        let outcome = match verdict.outcome {
            Outcome::Proved => "proved".to_string(),
            Outcome::Refuted { residual } => format!("refuted, residual {residual}"),
        };
        println!("{statement:<18} [C09 {outcome}]");
    }
    // The table prints with its header and aligned columns; `table.entries[a][b]` is
    // `{names[a], names[b]}` for a program that reads it, which `Entry::render` writes in
    // another notation (`Style::Latex`).
    let table = BracketTable::compute(&rotor, &["L", "G1", "G2"])?;
    print!("\n{table}");
    Ok(())
}
