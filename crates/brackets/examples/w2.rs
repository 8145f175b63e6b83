//! W2 single(m) timing sketch: P, Q for m = n, bracket with H, restrict to resonance.
use brackets::{systems, Claim};
use trigpoly::Expr;
fn main() {
    let m: i64 = std::env::args()
        .nth(1)
        .map(|s| s.parse().unwrap())
        .unwrap_or(40);
    let r = systems::harmonic_rotor();
    let t0 = std::time::Instant::now();
    let res = r.resonant("Z", m, m).unwrap();
    let t1 = t0.elapsed().as_secs_f64();
    let mut terms = 0;
    for f in [&res.p, &res.q] {
        terms += f.len();
        let c = Claim::new("w2", "", r.flow(f).unwrap(), Expr::zero(r.vars()))
            .when(r.resonance(m, m).unwrap());
        assert!(c.check().unwrap().outcome.is_proved());
    }
    eprintln!("expand {t1:.3}");
    println!(
        "seconds: {:.3}\nterms: {}",
        t0.elapsed().as_secs_f64(),
        terms
    );
}
