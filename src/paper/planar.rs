//! Section 2: a rigid rotor coupled to a planar system (claims C01–C03).

use brackets::{systems, Condition, EngineError};
use trigpoly::Expr;

use super::{Section, SectionBuilder};
use crate::report::ClaimKind;

/// The monomials `x^i y^j` with `1 ≤ i + j ≤ 4`: a general quartic potential.
fn quartic() -> (String, Vec<String>) {
    let mut terms = Vec::new();
    let mut params = Vec::new();
    for d in 1..=4 {
        for j in 0..=d {
            let i = d - j;
            let a = format!("a_{i}{j}");
            let power = |v: &str, e: usize| match e {
                0 => String::new(),
                1 => format!("*{v}"),
                _ => format!("*{v}^{e}"),
            };
            terms.push(format!("{a}{}{}", power("x", i), power("y", j)));
            params.push(a);
        }
    }
    (terms.join(" + "), params)
}

pub(crate) fn section() -> Result<Section, EngineError> {
    let (v, params) = quartic();
    let params: Vec<&str> = params.iter().map(String::as_str).collect();
    let rotor = systems::rotor(&v, &params)?;
    let mut s = SectionBuilder::new(2, "The rigid rotor coupled to planar systems", rotor);
    s.text(
        "A rigid body of mass `M` and moment of inertia `I` whose centre of mass moves in the \
         plane under a potential `V(x, y)`: the rotor adds `p_θ²/(2I)` to the planar \
         Hamiltonian, `H = (p_x² + p_y²)/(2M) + V(x, y) + p_θ²/(2I)`. Here `V` is a general \
         quartic with symbolic coefficients `a_ij`:",
    );
    s.show("", &[("V", "V")])?;

    s.heading("Hamilton's equations");
    let sys = s.system().clone();
    // The engine's vector field: (q̇, ṗ) = (∂H/∂p, −∂H/∂q) for each canonical pair.
    let field = sys.space().hamilton_equations(sys.hamiltonian())?;
    let rate = |v: &str| -> Expr {
        let var = sys.var(v);
        field
            .iter()
            .find(|(w, _)| *w == var)
            .map(|(_, e)| e.clone())
            .expect("every phase-space variable has an equation")
    };
    let minus_grad =
        |v: &str| -> Result<Expr, EngineError> { Ok(-sys.get("V")?.derivative(sys.var(v))?) };
    for (v, statement, rhs) in [
        ("x", "ẋ = p_x/M", s.parse("p_x/M")?),
        ("y", "ẏ = p_y/M", s.parse("p_y/M")?),
        ("theta", "θ̇ = p_θ/I", s.parse("p_theta/I")?),
        ("p_x", "ṗ_x = −V_x", minus_grad("x")?),
        ("p_y", "ṗ_y = −V_y", minus_grad("y")?),
        ("p_theta", "ṗ_θ = 0", Expr::zero(sys.vars())),
    ] {
        s.claim("C01", statement, rate(v), rhs, None, ClaimKind::Identity);
    }

    s.heading("Central potentials");
    let r2 = "(x^2 + y^2)";
    let mut central = systems::rotor(
        &format!("k_1*{r2} + k_2*{r2}^2 + k_3*{r2}^3"),
        &["k_1", "k_2", "k_3"],
    )?;
    central.define_parsed("F1", "F1", "H")?;
    central.define_parsed("F2", "F2", "x*p_y - y*p_x")?;
    central.define_parsed("F3", "F3", "p_theta")?;
    s.use_system(central);
    s.text(
        "For a central potential `V = k_1 r² + k_2 r⁴ + k_3 r⁶` (`r² = x² + y²`), \
         `F1 = H`, `F2 = x p_y − y p_x` and `F3 = p_θ` are in involution:",
    );
    for (a, b) in [("F1", "F2"), ("F1", "F3"), ("F2", "F3")] {
        s.identity(
            "C02",
            &format!("{{{a}, {b}}} = 0"),
            &format!("{{{a}, {b}}}"),
            "0",
        )?;
    }

    s.heading("No rotation");
    let rotor = s.use_system(sys.as_ref().clone());
    let p_theta = rotor.var("p_theta");
    let zero = Condition::new("p_θ = 0", p_theta, Expr::zero(rotor.vars()));
    s.text("Without rotation the rotor is a particle of mass `M` in the plane:");
    s.identity_when(
        "C03",
        "H = (p_x² + p_y²)/(2M) + V(x, y)",
        "H",
        "(p_x^2 + p_y^2)/(2*M) + V",
        zero,
    )?;
    Ok(s.finish())
}
