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
    let table = BracketTable::compute(&rotor, &["L", "G1", "G2"])?;
    for (name, row) in table.display.iter().zip(&table.entries) {
        let cells: Vec<String> = row.iter().map(|e| e.render(Style::Unicode)).collect();
        println!("{name:>3} │ {}", cells.join("  "));
    }
    Ok(())
}
