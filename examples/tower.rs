//! Checks the resonant tower `{K_{m,n}, H} = i(mω − nΩ) K_{m,n}` for `1 ≤ m, n ≤ 4` by
//! expansion, then proves it for all `m, n` by the eigenfunction lemma.
//!
//! Run with `cargo run --example tower`.

use superint::prelude::*;

fn main() -> Result<(), EngineError> {
    let rotor = systems::harmonic_rotor();
    let tower = check_tower(&rotor, "Z", 4, &mut |_done, _total| {})?;
    println!(
        "{} brackets checked for 1 ≤ m, n ≤ {}: {}",
        tower.checked,
        tower.max,
        if tower.failures.is_empty() {
            "all hold"
        } else {
            "some fail"
        }
    );
    let proof = eigen_proof(&rotor, "Z")?;
    for fact in &proof.facts {
        println!(
            "  {}: {}",
            fact.statement,
            if fact.holds { "holds" } else { "fails" }
        );
    }
    println!("  lemma: {}", proof.lemma);
    // The example checks what it prints: CI runs it.
    assert!(tower.failures.is_empty() && proof.holds());
    println!("  so: {}", proof.conclusion);
    Ok(())
}
