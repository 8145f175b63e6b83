//! Section 4: the oscillator in a vertical plane, with gravity (claims C18–C25).

use brackets::{systems, EngineError};

use super::harmonic::{resonance, su2, with_resonant, RESONANCES};
use super::{Item, PaperOptions, Section, SectionBuilder};

pub(crate) fn section(options: &PaperOptions) -> Result<Section, EngineError> {
    let rotor = with_resonant(systems::gravity_rotor(), "Zp", "'", &RESONANCES)?;
    let mut s = SectionBuilder::new(4, "Oscillator in a vertical plane with gravity", rotor);
    s.text(
        "The same oscillator in a vertical plane: `H = … + Mgy` with `y` measured upwards. \
         Shifting to the equilibrium, `y' = y + g/ω²`, gives back the isotropic oscillator \
         plus a constant.",
    );
    s.hamilton();
    s.identity(
        "C18",
        "Mω²(x² + y²)/2 + Mgy = Mω²(x² + y'²)/2 − Mg²/(2ω²)",
        "M*omega^2*(x^2 + y^2)/2 + M*g*y",
        "M*omega^2*(x^2 + yp^2)/2 - M*g^2/(2*omega^2)",
    )?;

    s.heading("Constants of motion about the shifted centre");
    s.identity("C19", "{F1, L} = Mgx", "{F1, L}", "M*g*x")?;
    s.show(
        "",
        &[("y'", "yp"), ("L'", "Lp"), ("G1'", "G1p"), ("G2'", "G2p")],
    )?;
    s.identity("C20", "L' = x p_y − y' p_x", "Lp", "x*p_y - yp*p_x")?;
    s.identity("C20", "{F1, L'} = 0", "{F1, Lp}", "0")?;
    s.identity("C20", "{F1, F2} = 0", "{F1, F2}", "0")?;
    s.identity(
        "C21",
        "G1' = p_x p_y/(2M) + Mω²xy'/2",
        "G1p",
        "p_x*p_y/(2*M) + M*omega^2*x*yp/2",
    )?;
    s.identity(
        "C21",
        "G2' = (p_x² − p_y²)/(2M) + Mω²(x² − y'²)/2",
        "G2p",
        "(p_x^2 - p_y^2)/(2*M) + M*omega^2*(x^2 - yp^2)/2",
    )?;
    s.identity("C21", "{F1, G1'} = 0", "{F1, G1p}", "0")?;
    s.identity("C21", "{F1, G2'} = 0", "{F1, G2p}", "0")?;
    s.table("the rotor under gravity", &["F1", "F2", "Lp", "G1p", "G2p"]);
    su2(&mut s, "'")?;
    s.identity(
        "C23",
        "4 G1'² + G2'² + ω² L'² = (F1 − F2 + Mg²/(2ω²))²",
        "4*G1p^2 + G2p^2 + omega^2*Lp^2",
        "(F1 - F2 + M*g^2/(2*omega^2))^2",
    )?;

    s.heading("Shifted resonant integrals");
    s.show("", &[("Z'", "Zp")])?;
    s.identity("C24", "{Z', F1} = iω Z'", "{Zp, F1}", "i*omega*Zp")?;
    s.text("`K'_{m,n} = Z'^m e^{−inθ}`, with `P'_{m,n}`, `Q'_{m,n}` as before:");
    let sys = s.system().clone();
    s.item(Item::Tower {
        id: "C24".into(),
        statement: format!(
            "{{K'_{{m,n}}, F1}} = i(mω − nΩ) K'_{{m,n}} for 1 ≤ m, n ≤ {}",
            options.tower_max
        ),
        system: sys.clone(),
        ladder: "Zp".into(),
        family: "K'".into(),
        max: options.tower_max,
    });
    s.item(Item::Proof {
        title: "for all m, n ≥ 0, from the ladder function Z'".into(),
        settles: vec![(
            "C24".into(),
            "{K'_{m,n}, F1} = i(mω − nΩ) K'_{m,n} for all m, n ≥ 0".into(),
        )],
        system: sys,
        ladder: "Zp".into(),
        family: "K'".into(),
    });
    resonance(&mut s, "C24", "'", "p")?;

    s.heading("Functional independence");
    let base = [("F1", "F1"), ("F2", "F2"), ("G1'", "G1p"), ("G2'", "G2p")];
    let p = ("P'_{1,1}", "P11p");
    s.rank("C25", &[base[0], base[1], base[2], base[3], p], 5)?;
    s.rank("C25", &base, 4)?;
    s.rank(
        "C25",
        &[base[0], base[1], base[2], base[3], p, ("L'", "Lp")],
        5,
    )?;
    Ok(s.finish())
}
