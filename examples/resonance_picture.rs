//! The resonance `Ω = ω` twice: proved exactly (`{K_{1,1}, H} = 0` at `p_θ = Iω`), then seen
//! along trajectories computed in floating point at `M = ω = I = 1`, where `K_{1,1}` stands
//! still at `p_θ = 1` and turns at `p_θ = 2`; the chart of the first is written to
//! `resonance.svg` in the system's temporary directory.
//!
//! Run with `cargo run --example resonance_picture`.

use superint::prelude::*;
use superint::trajectory::chart::{self, Curve, Style};
use superint::trajectory::{Flow, Numeric};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let rotor = systems::harmonic_rotor();
    let k = rotor.resonant("Z", 1, 1)?.k;
    let at_resonance = Claim::new(
        "C12",
        "{K_{1,1}, H} = 0",
        rotor.flow(&k)?,
        Expr::zero(rotor.vars()),
    )
    .when(rotor.resonance(1, 1)?);
    let verdict = at_resonance.check()?;
    println!("{{K_{{1,1}}, H}} = 0 at p_θ = Iω: {:?}", verdict.outcome);
    // The example checks the exact claim it prints (CI runs it); the picture decides nothing.
    assert!(verdict.outcome.is_proved());

    // The same functions with M = ω = I = 1, rounded for the integrator.
    let one = GaussianRational::from(1);
    let at_one = |e: &Expr| -> Result<Expr, Box<dyn std::error::Error>> {
        let mut e = e.clone();
        for name in ["M", "omega", "I"] {
            e = e.subst_value(rotor.var(name), &one)?;
        }
        Ok(e)
    };
    let flow = Flow::new(rotor.space(), &at_one(rotor.hamiltonian())?)?;
    let (_, re_k, im_k) = at_one(&k)?.conj_re_im();
    let re_k = Numeric::new(&re_k, flow.phase())?;
    let im_k = Numeric::new(&im_k, flow.phase())?;
    for p_theta in [1.0, 2.0] {
        let mut start = vec![0.0; rotor.vars().len()];
        for (name, value) in [("x", 1.0), ("p_y", 0.5), ("p_theta", p_theta)] {
            start[rotor.var(name).index()] = value;
        }
        let path = flow.integrate(&start, 20.0, 10_000, 500)?;
        let moved = path
            .values(|s| (re_k.real(s) - re_k.real(&start)).hypot(im_k.real(s) - im_k.real(&start)))
            .into_iter()
            .fold(0.0, f64::max);
        println!("p_θ = {p_theta}: K_{{1,1}} moves by at most {moved:.3e} over t ∈ [0, 20]");
        if p_theta == 1.0 {
            let curve = |label: &str, f: &Numeric| {
                let values = path.values(|s| f.real(s));
                Curve::new(label, path.times.iter().copied().zip(values).collect())
            };
            let drawn = [curve("re K₁,₁", &re_k), curve("im K₁,₁", &im_k)];
            let file = std::env::temp_dir().join("resonance.svg");
            std::fs::write(
                &file,
                chart::svg("K₁,₁ at Ω = ω", "t", &drawn, Style::Lines)?,
            )?;
            println!("  its chart: {}", file.display());
        }
    }
    Ok(())
}
