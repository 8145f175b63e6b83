//! Section 5: beyond the paper's examples: the anisotropic oscillator `ω_x : ω_y = 3 : 5`
//! coupled to the rotor (claim C26), and the planar limits `V_I`, `V_II` (claim C27).

use brackets::{systems, EngineError};
use trigpoly::Expr;

use super::{Section, SectionBuilder};
use crate::report::ClaimKind;

pub(crate) fn section() -> Result<Section, EngineError> {
    let mut rotor = systems::anisotropic_rotor(3, 5);
    // Re and Im of A_x⁵ Ā_y³ (conserved always) and of K = A_x² Ā_y e^{−iθ} (at p_θ = Iω).
    let a = rotor.parse("Ax^5*Aybar^3")?;
    let theta = rotor.var("theta");
    let k = rotor
        .parse("Ax^2*Aybar")?
        .checked_mul(&Expr::exp_i(rotor.vars(), theta, -1)?)?;
    rotor.define("ReA", "Re(A_x⁵Ā_y³)", a.re()?)?;
    rotor.define("ImA", "Im(A_x⁵Ā_y³)", a.im()?)?;
    rotor.define("K", "K", k.clone())?;
    rotor.define("ReK", "Re K", k.re()?)?;
    rotor.define("ImK", "Im K", k.im()?)?;
    let mut s = SectionBuilder::new(5, "Beyond the paper's examples", rotor);
    s.text(
        "The anisotropic oscillator `V = M(ω_x² x² + ω_y² y²)/2` with `ω_x : ω_y = 3 : 5` \
         (`ω_x = 3ω`, `ω_y = 5ω`), coupled to the rotor, which the paper only pictures. \
         Its ladder functions are `A_x = p_x + iMω_x x` and `A_y = p_y + iMω_y y`.",
    );
    s.hamilton();
    s.identity("C26", "{A_x, H} = 3iω A_x", "{Ax, H}", "3*i*omega*Ax")?;
    s.identity(
        "C26",
        "{Ā_y, H} = −5iω Ā_y",
        "{Aybar, H}",
        "-5*i*omega*Aybar",
    )?;
    s.text("The planar resonance gives a sixth-order integral, conserved for every `p_θ`:");
    s.identity("C26", "{Re(A_x⁵Ā_y³), H} = 0", "{ReA, H}", "0")?;
    s.identity("C26", "{Im(A_x⁵Ā_y³), H} = 0", "{ImA, H}", "0")?;
    s.text(
        "The resonance with the rotor `Ω = ω` (`2ω_x − ω_y = ω`) gives a third-order one, \
         `K = A_x² Ā_y e^{−iθ}`:",
    );
    s.identity(
        "C26",
        "{K, H} = i(ω − Ω) K",
        "{K, H}",
        "i*(omega - Omega)*K",
    )?;
    let sys = s.system().clone();
    for f in ["Re", "Im"] {
        s.identity_when(
            "C26",
            &format!("{{{f} K, H}} = 0"),
            &format!("{{{f}K, H}}"),
            "0",
            sys.resonance(1, 1)?,
        )?;
    }
    let off = sys.resonance(2, 1)?;
    let lhs = s.parse("{ReK, H}")?;
    s.claim(
        "C26",
        "{Re K, H} ≠ 0",
        lhs,
        Expr::zero(sys.vars()),
        Some(off),
        ClaimKind::Nonvanishing,
    );
    s.rank(
        "C26",
        &[
            ("H_x", "Hx"),
            ("H_y", "Hy"),
            ("F2", "F2"),
            ("Re(A_x⁵Ā_y³)", "ReA"),
            ("Re K", "ReK"),
        ],
        5,
    )?;
    planar_limits(&mut s)?;
    Ok(s.finish())
}

/// C27: `V_I = α(x² + y²) + β/x² + γ/y²` and `V_II = α(x² + 4y²) + β/x² + γy` (Laurent in
/// `x, y`) keep their second-order integrals when coupled to the rotor.
fn planar_limits(s: &mut SectionBuilder) -> Result<(), EngineError> {
    s.heading("The planar limits `V_I` and `V_II`");
    s.text(
        "Two of the four second-order superintegrable planar potentials, Laurent in `x, y`, \
         coupled to the rotor: each keeps its two second-order integrals.",
    );
    let greek = ["alpha", "beta", "gamma"];
    let mut v1 = systems::rotor("alpha*(x^2 + y^2) + beta/x^2 + gamma/y^2", &greek)?;
    v1.define_parsed("A", "A", "p_x^2/(2*M) + alpha*x^2 + beta/x^2")?;
    v1.define_parsed(
        "B",
        "B",
        "(x*p_y - y*p_x)^2 + 2*M*(beta*y^2/x^2 + gamma*x^2/y^2)",
    )?;
    s.use_system(v1);
    s.show("", &[("V_I", "V"), ("A", "A"), ("B", "B")])?;
    s.identity("C27", "{A, H} = 0 for V_I", "{A, H}", "0")?;
    s.identity("C27", "{B, H} = 0 for V_I", "{B, H}", "0")?;
    let mut v2 = systems::rotor("alpha*(x^2 + 4*y^2) + beta/x^2 + gamma*y", &greek)?;
    v2.define_parsed("A", "A", "p_x^2/(2*M) + alpha*x^2 + beta/x^2")?;
    v2.define_parsed(
        "B",
        "B",
        "(x*p_y - y*p_x)*p_x + M*(2*alpha*x^2*y - 2*beta*y/x^2 + gamma*x^2/2)",
    )?;
    s.use_system(v2);
    s.show("", &[("V_II", "V"), ("A", "A"), ("B", "B")])?;
    s.identity("C27", "{A, H} = 0 for V_II", "{A, H}", "0")?;
    s.identity("C27", "{B, H} = 0 for V_II", "{B, H}", "0")?;
    Ok(())
}
