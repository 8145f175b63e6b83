//! Time-dependent integrals in extended phase space: time `t` a coordinate with momentum
//! `p_t`, `K = H + p_t`, and clock angles `φ = Ωt` with `K = H + Ω p_φ`
//! (`systems/driven-oscillator.toml`, docs/system-files.md's "Time-dependent systems").

use crate::{scratch_text, superint_ok};

/// Free fall in extended phase space, `K = p_x²/2 + gx + p_t`.
const FREE_FALL: &str = "name = \"free fall\"\nhamiltonian = \"p_x^2/2 + g*x + p_t\"\n\
    [phase_space]\ncoordinates = [\"x\", \"t\"]\nparameters = [\"g\"]\n";

/// `p_t = 0` fixes the momentum of a coordinate that `K` does not involve, which the flow
/// keeps, so it is left out of the space as an angle's momentum is: `p_t` is no longer found.
/// What is found is, by hand, the momentum `p_x + gt` (`d/dt = −g + g`) and the boost
/// `x − p_x t − gt²/2` (`d/dt = p_x + gt − p_x − gt = 0`), with 1: their span, of dimension 3.
#[test]
fn a_fixed_p_t_is_left_out_and_the_boost_is_found() {
    let f = scratch_text("time-dependent", "free-fall.toml", FREE_FALL);
    let out = crate::normalize(&superint_ok(&[
        "search",
        f.to_str().unwrap(),
        "--when",
        "p_t = 0",
        "--momenta-degree",
        "1",
        "--positions-degree",
        "2",
    ]));
    assert!(
        out.contains(
            "p_t is left out: the condition fixes it, and every function of it is an integral."
        ),
        "{out}"
    );
    assert!(
        out.contains("Dimension of the space of integrals: 3."),
        "{out}"
    );
    let claims = format!(
        "{FREE_FALL}[[claim]]\nid = \"momentum\"\nclaim = \"{{p_x + g*t, H}} = 0\"\n\
         [[claim]]\nid = \"boost\"\nclaim = \"{{x - p_x*t - g*t^2/2, H}} = 0\"\n\
         [[claim]]\nid = \"independent\"\nclaim = \"rank(p_x + g*t, x - p_x*t - g*t^2/2) = 2\"\n\
         [[claim]]\nid = \"false-boost\"\nclaim = \"{{x - p_x*t + g*t^2/2, H}} = 0\"\n\
         expect = \"refuted\"\n"
    );
    let f = scratch_text("time-dependent", "free-fall-claims.toml", &claims);
    let out = superint_ok(&["check", f.to_str().unwrap()]);
    assert!(
        out.contains("4 claims in 1 file: 3 proved, 1 refuted; all as expected"),
        "{out}"
    );
}
