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
            // `Outcome` may gain kinds: one this program does not know, in the engine's words.
            other => other.to_string(),
        };
        println!("{statement:<18} [C09 {outcome}]");
    }
    // The table prints with its header and aligned columns; a program reads its entries,
    // `table.entries[a][b]` being `{names[a], names[b]}`, written by `Entry::render` in a
    // notation of its choice (`Style::Latex` too): above the diagonal, the three claims.
    let table = BracketTable::compute(&rotor, &["L", "G1", "G2"])?;
    let entry = |a: usize, b: usize| table.entries[a][b].render(Style::Unicode);
    assert_eq!(
        [entry(0, 1), entry(0, 2), entry(1, 2)],
        ["−G2", "4 G1", "−ω² L"]
    );
    print!("\n{table}");
    Ok(())
}
