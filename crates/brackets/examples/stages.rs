//! Where W1 spends its time, stage by stage (a profiling aid).
use brackets::systems;
use std::time::Instant;
fn main() {
    let n: i64 = std::env::args()
        .nth(1)
        .map(|s| s.parse().unwrap())
        .unwrap_or(20);
    let r = systems::harmonic_rotor();
    let (mut t_pow, mut t_res, mut t_flow, mut t_subst) = (0.0, 0.0, 0.0, 0.0);
    for m in 1..=n {
        for k in 1..=n {
            let t = Instant::now();
            let zm = r.get("Z").unwrap().checked_pow(m).unwrap();
            t_pow += t.elapsed().as_secs_f64();
            let t = Instant::now();
            let res = r.resonant("Z", m, k).unwrap();
            t_res += t.elapsed().as_secs_f64();
            let cond = r.resonance(m, k).unwrap();
            for f in [&res.p, &res.q] {
                let t = Instant::now();
                let fl = r.flow(f).unwrap();
                t_flow += t.elapsed().as_secs_f64();
                let t = Instant::now();
                assert!(cond.apply(&fl).unwrap().is_zero());
                t_subst += t.elapsed().as_secs_f64();
            }
            drop(zm);
        }
    }
    println!("pow {t_pow:.3} resonant(incl. pow) {t_res:.3} flow {t_flow:.3} subst {t_subst:.3}");
}
