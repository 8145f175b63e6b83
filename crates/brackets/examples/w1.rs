//! W1 tower(N) timing sketch: expand P, Q for all m, n ≤ N, bracket with H, restrict to resonance.
use brackets::{systems, Claim};
use trigpoly::Expr;
fn main() {
    let n: i64 = std::env::args()
        .nth(1)
        .map(|s| s.parse().unwrap())
        .unwrap_or(8);
    let r = systems::harmonic_rotor();
    let t0 = std::time::Instant::now();
    let mut terms = 0;
    for m in 1..=n {
        for k in 1..=n {
            let res = r.resonant("Z", m, k).unwrap();
            for f in [&res.p, &res.q] {
                terms += f.len();
                let c = Claim::new("w1", "", r.flow(f).unwrap(), Expr::zero(r.vars()))
                    .when(r.resonance(m, k).unwrap());
                assert!(c.check().unwrap().outcome.is_proved());
            }
        }
    }
    println!(
        "seconds: {:.3}\nterms: {}",
        t0.elapsed().as_secs_f64(),
        terms
    );
}
