//! Discovery: every statement of `docs/results.md`, asserted by running the command that
//! produced it (the same text, which `results_md_quotes_every_command` finds in the note) and
//! finding the quoted output in what it prints. Every command also exits 0, which means that
//! every integral, bracket and relation it reports was proved by the engine.

use std::path::Path;

use brackets::closure::{closure, ClosureOptions};
use brackets::search::{search, SearchOptions, SearchSpace};
use superint::system_file::{load, load_str, LimitsOverride};
use trigpoly::{Expr, Rational};

use crate::{
    normalize, superint, superint_json, superint_ok, superint_ok_line, superint_refused, words,
    DEGREE_ONE, DEGREE_ONE_TRIG_ZERO,
};

/// Every command of `docs/results.md`, by name.
const COMMANDS: &[(&str, &str)] = &[
    (
        "h11",
        "superint search systems/harmonic-rotor.toml --when 'p_theta = I*omega' \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4",
    ),
    (
        "h11-new",
        "superint search systems/harmonic-rotor.toml --when 'p_theta = I*omega' \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only",
    ),
    (
        "h11-new-8",
        "superint search systems/harmonic-rotor.toml --when 'p_theta = I*omega' \
         --momenta-degree 8 --positions-degree 8 --trig-degree 8 --new-only",
    ),
    (
        "h11-new-10",
        "superint search systems/harmonic-rotor.toml --when 'p_theta = I*omega' \
         --momenta-degree 10 --positions-degree 10 --trig-degree 10 --new-only",
    ),
    (
        "h11-new-pq",
        "superint search systems/harmonic-rotor.toml --when 'p_theta = I*omega' \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only --known P_1_1,Q_1_1",
    ),
    (
        "h11-closure",
        "superint closure systems/harmonic-rotor.toml F1 F2 L G1 G2 P_1_1 Q_1_1 \
         --when 'p_theta = I*omega' --degree 2",
    ),
    (
        "h11-closure-rs",
        "superint closure systems/harmonic-rotor.toml F1 F2 L G1 G2 P_1_1 Q_1_1 \
         --define 'R_1_1=re((p_x - i*p_y + i*M*omega*(x - i*y))*exp(-i*theta))' \
         --define 'S_1_1=im((p_x - i*p_y + i*M*omega*(x - i*y))*exp(-i*theta))' \
         --when 'p_theta = I*omega' --degree 2",
    ),
    (
        "h21-new",
        "superint search systems/harmonic-rotor.toml --when 'p_theta = 2*I*omega' \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only --known P_2_1,Q_2_1",
    ),
    (
        "h21-closure",
        "superint closure systems/harmonic-rotor.toml F1 F2 L G1 G2 P_2_1 Q_2_1 \
         --define 'R_2_1=re((p_x - i*p_y + i*M*omega*(x - i*y))^2*exp(-i*theta))' \
         --define 'S_2_1=im((p_x - i*p_y + i*M*omega*(x - i*y))^2*exp(-i*theta))' \
         --define 'T_2_1=re(Z*(p_x - i*p_y + i*M*omega*(x - i*y))*exp(-i*theta))' \
         --define 'U_2_1=im(Z*(p_x - i*p_y + i*M*omega*(x - i*y))*exp(-i*theta))' \
         --when 'p_theta = 2*I*omega' --degree 2",
    ),
    (
        "h21-new-8",
        "superint search systems/harmonic-rotor.toml --when 'p_theta = 2*I*omega' \
         --momenta-degree 8 --positions-degree 8 --trig-degree 8 --new-only --known P_2_1,Q_2_1",
    ),
    (
        "h23-new-8",
        "superint search systems/harmonic-rotor.toml --when 'p_theta = 2*I*omega/3' \
         --momenta-degree 8 --positions-degree 8 --trig-degree 8 --new-only --known P_2_3,Q_2_3",
    ),
    (
        "h12-new-8",
        "superint search systems/harmonic-rotor.toml --when 'p_theta = I*omega/2' \
         --momenta-degree 8 --positions-degree 8 --trig-degree 8 --new-only --known P_1_2,Q_1_2",
    ),
    (
        "g11-new-8",
        "superint search systems/gravity-rotor.toml --when 'p_theta = I*omega' \
         --momenta-degree 8 --positions-degree 8 --trig-degree 8 --new-only",
    ),
    (
        "h12-new",
        "superint search systems/harmonic-rotor.toml --when 'p_theta = I*omega/2' \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only --known P_1_2,Q_1_2",
    ),
    (
        "h12-closure",
        "superint closure systems/harmonic-rotor.toml F1 F2 L G1 G2 P_1_2 Q_1_2 \
         --define 'R_1_2=re((p_x - i*p_y + i*M*omega*(x - i*y))*exp(-2*i*theta))' \
         --define 'S_1_2=im((p_x - i*p_y + i*M*omega*(x - i*y))*exp(-2*i*theta))' \
         --when 'p_theta = I*omega/2' --degree 2",
    ),
    (
        "h23-new",
        "superint search systems/harmonic-rotor.toml --when 'p_theta = 2*I*omega/3' \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only --known P_2_3,Q_2_3",
    ),
    (
        "h23-closure",
        "superint closure systems/harmonic-rotor.toml F1 F2 L G1 G2 P_2_3 Q_2_3 \
         --define 'R_2_3=re((p_x - i*p_y + i*M*omega*(x - i*y))^2*exp(-3*i*theta))' \
         --define 'S_2_3=im((p_x - i*p_y + i*M*omega*(x - i*y))^2*exp(-3*i*theta))' \
         --define 'T_2_3=re(Z*(p_x - i*p_y + i*M*omega*(x - i*y))*exp(-3*i*theta))' \
         --define 'U_2_3=im(Z*(p_x - i*p_y + i*M*omega*(x - i*y))*exp(-3*i*theta))' \
         --when 'p_theta = 2*I*omega/3' --degree 2",
    ),
    (
        "g11-new",
        "superint search systems/gravity-rotor.toml --when 'p_theta = I*omega' \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only",
    ),
    (
        "g11-closure",
        "superint closure systems/gravity-rotor.toml Hp F2 Lp G1p G2p Pp_1_1 Qp_1_1 \
         --define 'Hp=F1 - F2' \
         --define 'Rp_1_1=re((p_x - i*p_y + i*M*omega*(x - i*yp))*exp(-i*theta))' \
         --define 'Sp_1_1=im((p_x - i*p_y + i*M*omega*(x - i*yp))*exp(-i*theta))' \
         --when 'p_theta = I*omega' --degree 2",
    ),
    (
        "g11-closure-f1",
        "superint closure systems/gravity-rotor.toml F1 F2 Lp G1p G2p Pp_1_1 Qp_1_1 \
         --when 'p_theta = I*omega' --degree 2",
    ),
    (
        "a35-new",
        "superint search systems/anisotropic-3-5-rotor.toml --when 'p_theta = I*omega' \
         --momenta-degree 3 --positions-degree 3 --trig-degree 5 --new-only",
    ),
    (
        "a35-closure",
        "superint closure systems/anisotropic-3-5-rotor.toml Hx Hy F2 \
         --define 'J1=re(Ax*exp(-3*i*theta))' --define 'J2=im(Ax*exp(-3*i*theta))' \
         --define 'Y1=re(Ay*exp(-5*i*theta))' --define 'Y2=im(Ay*exp(-5*i*theta))' \
         --when 'p_theta = I*omega' --degree 2",
    ),
    (
        "a35-k-and-a",
        "superint closure systems/anisotropic-3-5-rotor.toml Hx Hy ReK ImK ReA ImA \
         --when 'p_theta = I*omega' --degree 6",
    ),
    (
        "a12-new",
        "superint search --system anisotropic-1-2 --when 'p_theta = I*omega' \
         --momenta-degree 3 --positions-degree 3 --trig-degree 3 --new-only",
    ),
    (
        "sw1",
        "superint search systems/smorodinsky-winternitz-i.toml --momenta-degree 2 \
         --positions-degree 4 --trig-degree 0 --laurent",
    ),
    (
        "sw2",
        "superint search systems/smorodinsky-winternitz-ii.toml --momenta-degree 2 \
         --positions-degree 4 --trig-degree 0 --laurent",
    ),
    (
        "su2",
        "superint closure systems/harmonic-rotor.toml F1 F2 L G1 G2 --degree 2",
    ),
    (
        "hh-kdv",
        "superint search systems/henon-heiles.toml --momenta-degree 2 --positions-degree 4 \
         --trig-degree 0 --fix C=2 --symbolic A,B",
    ),
    (
        "hh-separable",
        "superint search systems/henon-heiles.toml --momenta-degree 2 --positions-degree 4 \
         --trig-degree 0 --when 'B = A, C = 1/3' --symbolic A",
    ),
    (
        "hh-quartic",
        "superint search systems/henon-heiles.toml --momenta-degree 4 --positions-degree 6 \
         --trig-degree 0 --when 'B = 16*A, C = 16/3' --symbolic A",
    ),
    (
        "hh-quartic-new",
        "superint search systems/henon-heiles.toml --momenta-degree 4 --positions-degree 6 \
         --trig-degree 0 --when 'B = 16*A, C = 16/3' --symbolic A --new-only",
    ),
    (
        "hh-values-quadratic",
        "superint search systems/henon-heiles.toml --find-values C --fix A=1,B=1 \
         --momenta-degree 2 --positions-degree 4 --trig-degree 0",
    ),
    (
        "hh-values-quartic",
        "superint search systems/henon-heiles.toml --find-values C --fix B=16 \
         --momenta-degree 4 --positions-degree 6 --trig-degree 0",
    ),
    (
        "heavy-top-values",
        "superint search systems/heavy-top.toml --find-values I3 --poisson-degree 4",
    ),
    (
        "qp-values-quadratic",
        "superint search systems/quartic-potentials.toml --find-values a --fix b=1 \
         --momenta-degree 2 --positions-degree 4 --trig-degree 0",
    ),
    (
        "qp-values-parabolic",
        "superint search systems/quartic-potentials.toml --find-values a --fix b=16 \
         --momenta-degree 2 --positions-degree 5 --trig-degree 0",
    ),
    (
        "qp-values-quartic-b1",
        "superint search systems/quartic-potentials.toml --find-values a --fix b=1 \
         --momenta-degree 4 --positions-degree 8 --trig-degree 0",
    ),
    (
        "qp-values-quartic",
        "superint search systems/quartic-potentials.toml --find-values a --fix b=8 \
         --momenta-degree 4 --positions-degree 8 --trig-degree 0",
    ),
    (
        "qp-values-b",
        "superint search systems/quartic-potentials.toml --find-values b --fix a=6 \
         --momenta-degree 4 --positions-degree 8 --trig-degree 0",
    ),
    (
        "qp-minus-six",
        "superint search systems/quartic-potentials.toml --when 'a = -6, b = 1' \
         --momenta-degree 4 --positions-degree 8 --trig-degree 0 --new-only",
    ),
    (
        "rotor-values",
        "superint search systems/harmonic-rotor.toml --find-values omega --on 'p_theta = 1' \
         --fix M=1,I=1,l=1 --momenta-degree 2 --positions-degree 2 --trig-degree 2",
    ),
    (
        "rotor-values-ruled-out",
        "superint search systems/harmonic-rotor.toml --find-values omega --on 'p_theta = 1' \
         --fix M=1,I=1,l=1 --momenta-degree 1 --positions-degree 2 --trig-degree 2",
    ),
    (
        "rotor-values-inertia",
        "superint search systems/harmonic-rotor.toml --find-values I --on 'p_theta = 1' \
         --fix omega=1,M=1 --momenta-degree 2 --positions-degree 2 --trig-degree 2",
    ),
    (
        "dipole-rotor-search",
        "superint search systems/dipole-rotor.toml --fix M=2,omega=3,I=5,epsilon=7 \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only",
    ),
    (
        "dipole-rotor-values-omega",
        "superint search systems/dipole-rotor.toml --find-values omega --fix M=1,I=1,epsilon=1 \
         --momenta-degree 2 --positions-degree 2 --trig-degree 2",
    ),
    (
        "dipole-rotor-values-epsilon",
        "superint search systems/dipole-rotor.toml --find-values epsilon --fix M=1,I=1,omega=1 \
         --momenta-degree 2 --positions-degree 2 --trig-degree 2",
    ),
    (
        "quadrupole-rotor-search",
        "superint search systems/quadrupole-rotor.toml --fix M=2,omega=3,I=5,epsilon=7 \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only",
    ),
    (
        "quadrupole-rotor-values-epsilon",
        "superint search systems/quadrupole-rotor.toml --find-values epsilon \
         --fix M=1,I=1,omega=1 --momenta-degree 2 --positions-degree 2 --trig-degree 2",
    ),
    (
        "quadrupole-rotor-vanishing-frequency",
        "superint search systems/quadrupole-rotor.toml --when 'epsilon = M*omega^2/2' \
         --fix M=1,omega=1,I=1 --momenta-degree 3 --positions-degree 3 --trig-degree 3 \
         --new-only",
    ),
    (
        "quadrupole-rotor-values-omega",
        "superint search systems/quadrupole-rotor.toml --find-values omega \
         --fix M=1,I=1,epsilon=1 --momenta-degree 2 --positions-degree 2 --trig-degree 2",
    ),
    (
        "gyroscopic-rotor-search",
        "superint search systems/gyroscopic-rotor.toml --fix M=2,omega=3,I=5,kappa=7 \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only",
    ),
    (
        "gyroscopic-rotor-values-kappa",
        "superint search systems/gyroscopic-rotor.toml --find-values kappa \
         --fix M=1,I=1,omega=1 --momenta-degree 2 --positions-degree 2 --trig-degree 2",
    ),
    (
        "gyroscopic-rotor-closure",
        "superint closure systems/gyroscopic-rotor.toml Hosc L p_theta C1 C2 \
         --when 'kappa = 1/2' --degree 2",
    ),
    (
        "gyroscopic-rotor-resonances",
        "superint search systems/gyroscopic-rotor.toml --find-values omega \
         --fix M=1,I=1,kappa=1/2 --when 'p_theta = (x*p_y - y*p_x)/2 + 1' \
         --momenta-degree 2 --positions-degree 2 --trig-degree 2",
    ),
    (
        "kepler",
        "superint search systems/kepler.toml --momenta-degree 2 --positions-degree 2 \
         --trig-degree 1 --laurent",
    ),
    (
        "kepler-new-6",
        "superint search systems/kepler.toml --momenta-degree 6 --positions-degree 6 \
         --trig-degree 3 --laurent --new-only",
    ),
    (
        "kepler-closure",
        "superint closure systems/kepler.toml H L Ax Ay --degree 3",
    ),
    (
        "hh-generic",
        "superint search systems/henon-heiles.toml --momenta-degree 2 --positions-degree 4 \
         --trig-degree 0 --symbolic A,B,C",
    ),
    (
        "euler",
        "superint search systems/euler-top.toml --poisson-degree 4 --fix I1=1,I2=2,I3=3",
    ),
    (
        "euler-symbolic",
        "superint search systems/euler-top.toml --poisson-degree 2 --symbolic I1,I2,I3",
    ),
    (
        "kovalevskaya",
        "superint search systems/kovalevskaya-top.toml --poisson-degree 4",
    ),
    (
        "kovalevskaya-new-12",
        "superint search systems/kovalevskaya-top.toml --poisson-degree 12 --new-only",
    ),
    (
        "heavy-1-3",
        "superint search systems/heavy-top.toml --poisson-degree 4 --when 'I3 = 1/3' --new-only",
    ),
    (
        "neumann",
        "superint search systems/neumann.toml --poisson-degree 6 --new-only",
    ),
    (
        "neumann-closure",
        "superint closure systems/neumann.toml F1 F2 F3 H --degree 2 --symbolic a1,a2,a3",
    ),
    (
        "calogero-rank",
        "superint rank systems/calogero.toml P H I3 K1 K2",
    ),
    (
        "calogero-closure",
        "superint closure systems/calogero.toml P H I3 K1 K2 --degree 3",
    ),
    (
        "calogero-search",
        "superint search systems/calogero.toml --momenta-degree 3 --positions-degree 1 \
         --denominators-degree 2",
    ),
    (
        "calogero-new",
        "superint search systems/calogero.toml --momenta-degree 4 --positions-degree 2 \
         --denominators-degree 2 --new-only",
    ),
    (
        "kepler3d-closure",
        "superint closure systems/kepler-3d.toml H Lx Ly Lz Ax Ay Az --degree 3",
    ),
    (
        "kepler3d-search",
        "superint search systems/kepler-3d.toml --momenta-degree 2 --positions-degree 1 --new-only",
    ),
    (
        "gkc-search",
        "superint search systems/generalized-kepler.toml --momenta-degree 2 --positions-degree 4 \
         --laurent --symbolic k,b,c --parameters-degree 1 --new-only",
    ),
    (
        "two-centres-search",
        "superint search systems/two-centres.toml --momenta-degree 2 --positions-degree 2 \
         --radicals-degree 2 --fix a=1 --new-only",
    ),
    (
        "two-centres-symbolic",
        "superint search systems/two-centres.toml --momenta-degree 2 --positions-degree 2 \
         --radicals-degree 1 --symbolic a,k,m --parameters-degree 3 --new-only",
    ),
    (
        "sw3-search",
        "superint search systems/smorodinsky-winternitz-iii.toml --momenta-degree 2 \
         --positions-degree 4 --laurent --symbolic M,alpha,beta,gamma --parameters-degree 2 \
         --new-only",
    ),
    (
        "sw3-cubic",
        "superint search systems/smorodinsky-winternitz-iii.toml --momenta-degree 3 \
         --positions-degree 4 --laurent --symbolic M,alpha,beta,gamma --parameters-degree 2 \
         --new-only",
    ),
    (
        "sw3-closure",
        "superint closure systems/smorodinsky-winternitz-iii.toml H X1 X2 R --degree 3 \
         --symbolic M,alpha,beta,gamma --parameters-degree 7",
    ),
    (
        "ttw-search",
        "superint search systems/ttw-2.toml --momenta-degree 4 --positions-degree 4 --laurent \
         --denominators-degree 4 --fix omega=2 --symbolic alpha,beta --parameters-degree 2 \
         --new-only",
    ),
    (
        "ttw-closure",
        "superint closure systems/ttw-2.toml H X Y Z --define 'Z={X, Y}' --degree 3 \
         --fix omega=2,alpha=3,beta=5",
    ),
    (
        "sw1-algebra",
        "superint closure systems/smorodinsky-winternitz-i.toml H Hx X --define 'C={Hx, X}' \
         --degree 3 --symbolic alpha,beta,gamma --parameters-degree 3",
    ),
    (
        "toda-search",
        "superint search systems/toda-lattice.toml --momenta-degree 3 --positions-degree 0 \
         --trig-degree 0 --poisson-degree 1 --new-only",
    ),
    (
        "toda-search-4",
        "superint search systems/toda-lattice.toml --momenta-degree 4 --positions-degree 0 \
         --trig-degree 0 --poisson-degree 2 --new-only",
    ),
    (
        "fl-search",
        "superint search systems/fokas-lagerstrom-1-3.toml --momenta-degree 3 \
         --positions-degree 3 --trig-degree 0 --new-only",
    ),
    (
        "fl-closure",
        "superint closure systems/fokas-lagerstrom-1-3.toml H Hx S C --degree 4",
    ),
    (
        "caged-search",
        "superint search systems/caged-oscillator-1-2.toml --momenta-degree 5 \
         --positions-degree 7 --laurent --symbolic omega,alpha,beta --parameters-degree 4 \
         --new-only",
    ),
    (
        "caged-closure",
        "superint closure systems/caged-oscillator-1-2.toml H Hx K Q --degree 4 \
         --symbolic omega,alpha,beta --parameters-degree 7",
    ),
    (
        "higgs-search",
        "superint search systems/higgs-oscillator.toml --momenta-degree 2 --positions-degree 4 \
         --symbolic lambda,omega --parameters-degree 2 --new-only",
    ),
    (
        "higgs-closure",
        "superint closure systems/higgs-oscillator.toml H L K T12 --degree 4 \
         --symbolic lambda,omega --parameters-degree 2",
    ),
    (
        "higgs-closure-tensor",
        "superint closure systems/higgs-oscillator.toml H L T11 T12 T22 --degree 2 \
         --symbolic lambda,omega --parameters-degree 2",
    ),
    (
        "stark-search",
        "superint search systems/stark.toml --momenta-degree 2 --positions-degree 2 \
         --symbolic M,k,F --parameters-degree 2 --new-only",
    ),
    (
        "stark-search-4",
        "superint search systems/stark.toml --momenta-degree 4 --positions-degree 4 \
         --radicals-degree 2 --new-only",
    ),
    (
        "fd-search",
        "superint search systems/fock-darwin.toml --when 'a = 2*b' --momenta-degree 3 \
         --positions-degree 3 --trig-degree 0 --symbolic M,b --parameters-degree 6 --new-only",
    ),
    (
        "fd-search-known",
        "superint search systems/fock-darwin.toml --when 'a = 2*b' --momenta-degree 3 \
         --positions-degree 3 --trig-degree 0 --symbolic M,b --parameters-degree 6 --new-only \
         --known P_1_2,Q_1_2",
    ),
    (
        "fd-search-4",
        "superint search systems/fock-darwin.toml --when 'a = 2*b' --momenta-degree 4 \
         --positions-degree 4 --trig-degree 0 --symbolic M,b --parameters-degree 8 --new-only",
    ),
    (
        "fd-search-1-3",
        "superint search systems/fock-darwin.toml --when 'a = 3*b' --momenta-degree 4 \
         --positions-degree 4 --trig-degree 0 --symbolic M,b --parameters-degree 8 --new-only",
    ),
    (
        "fd-search-generic",
        "superint search systems/fock-darwin.toml --momenta-degree 4 --positions-degree 4 \
         --trig-degree 0 --symbolic M,a,b --parameters-degree 8 --new-only",
    ),
    (
        "fd-search-landau",
        "superint search systems/fock-darwin.toml --when 'b = 0' --momenta-degree 2 \
         --positions-degree 2 --trig-degree 0 --symbolic M,a --parameters-degree 4 --new-only",
    ),
    (
        "fd-closure",
        "superint closure systems/fock-darwin.toml H L P_1_2 Q_1_2 --when 'a = 2*b' --degree 3 \
         --symbolic M,b --parameters-degree 6",
    ),
    (
        "fd-closure-landau",
        "superint closure systems/fock-darwin.toml H L P_0_1 Q_0_1 --when 'b = 0' --degree 2",
    ),
    (
        "fd-closure-isotropic",
        "superint closure systems/fock-darwin.toml H L P_1_1 Q_1_1 --when 'b = a' --degree 2",
    ),
    (
        "zernike-search",
        "superint search systems/zernike.toml --momenta-degree 4 --positions-degree 4 \
         --trig-degree 0 --radicals-degree 0 --symbolic g1,g2 --parameters-degree 4 --new-only",
    ),
    (
        "zernike-search-sphere",
        "superint search systems/zernike.toml --when 'g1 = 0' --momenta-degree 1 \
         --positions-degree 2 --trig-degree 0 --symbolic g2 --new-only",
    ),
    (
        "zernike-closure",
        "superint closure systems/zernike.toml H L A B --degree 4 --symbolic g1,g2 \
         --parameters-degree 4",
    ),
    (
        "zernike-closure-sphere",
        "superint closure systems/zernike.toml H L J1 J2 --when 'g1 = 0' --degree 2 \
         --symbolic g2",
    ),
    (
        "swi-rotor-search",
        "superint search systems/smorodinsky-winternitz-i-rotor.toml --when 'p_theta = 2*I*omega' \
         --momenta-degree 4 --positions-degree 4 --trig-degree 2 --laurent --new-only",
    ),
    (
        "swi-rotor-search-1-2",
        "superint search systems/smorodinsky-winternitz-i-rotor.toml --when 'p_theta = I*omega' \
         --momenta-degree 2 --positions-degree 4 --trig-degree 2 --laurent --new-only",
    ),
    (
        "swii-rotor-search",
        "superint search systems/smorodinsky-winternitz-ii-rotor.toml --when 'p_theta = 2*I*omega' \
         --momenta-degree 3 --positions-degree 3 --trig-degree 2 --laurent --new-only",
    ),
    (
        "swii-rotor-closure",
        "superint closure systems/smorodinsky-winternitz-ii-rotor.toml Hx Hy P_1_1 Q_1_1 R_1_1 S_1_1 \
         --when 'p_theta = 2*I*omega' --degree 2 --symbolic beta,gamma",
    ),
    (
        "swi-rotor-closure",
        "superint closure systems/smorodinsky-winternitz-i-rotor.toml Hx Hy X P_1_1 Q_1_1 R_1_1 \
         S_1_1 --when 'p_theta = 2*I*omega' --degree 2 --symbolic beta,gamma --parameters-degree 1",
    ),
    (
        "fd-rotor-search",
        "superint search systems/fock-darwin-rotor.toml --when 'a = 2*b, p_theta = 2*I*b' \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only",
    ),
    (
        "fd-rotor-search-6",
        "superint search systems/fock-darwin-rotor.toml --when 'a = 2*b, p_theta = 2*I*b' \
         --momenta-degree 6 --positions-degree 6 --trig-degree 6 --new-only",
    ),
    (
        "fd-rotor-search-single",
        "superint search systems/fock-darwin-rotor.toml --when 'p_theta = I*a' --momenta-degree 3 \
         --positions-degree 3 --trig-degree 2 --symbolic M,a,b --parameters-degree 4 --new-only",
    ),
    (
        "fd-rotor-search-off",
        "superint search systems/fock-darwin-rotor.toml --momenta-degree 3 --positions-degree 3 \
         --trig-degree 2 --symbolic M,a,b --parameters-degree 4 --new-only",
    ),
    (
        "fd-rotor-search-3-1",
        "superint search systems/fock-darwin-rotor.toml --when 'a = 3*b, p_theta = I*b' \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only",
    ),
    (
        "fd-rotor-closure",
        "superint closure systems/fock-darwin-rotor.toml HFD L P_2_1 Q_2_1 R_1_1 S_1_1 \
         --when 'a = 2*b, p_theta = 2*I*b' --degree 2",
    ),
    (
        "fd-rotor-closure-trap",
        "superint closure systems/fock-darwin-rotor.toml HFD L P_2_1 Q_2_1 R_1_1 S_1_1 U_1_2 V_1_2 \
         --when 'a = 2*b, p_theta = 2*I*b' --degree 2",
    ),
    (
        "iso3-rotor-search",
        "superint search systems/isotropic-rotor-3d.toml --when 'p_theta = I*omega' \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only",
    ),
    (
        "iso3-rotor-search-6",
        "superint search systems/isotropic-rotor-3d.toml --when 'p_theta = I*omega' \
         --momenta-degree 6 --positions-degree 6 --trig-degree 6 --new-only",
    ),
    (
        "iso3-rotor-search-2-1",
        "superint search systems/isotropic-rotor-3d.toml --when 'p_theta = 2*I*omega' \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only \
         --known '{Lx, Axy}, {Ly, Axy}'",
    ),
    (
        "iso3-rotor-search-1-2",
        "superint search systems/isotropic-rotor-3d.toml --when 'p_theta = I*omega/2' \
         --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only",
    ),
    (
        "iso3-rotor-search-off",
        "superint search systems/isotropic-rotor-3d.toml --momenta-degree 3 --positions-degree 3 \
         --trig-degree 2 --symbolic M,omega --parameters-degree 4 --new-only \
         --known '{Lx, Axy}, {Ly, Axy}'",
    ),
    (
        "iso3-rotor-closure",
        "superint closure systems/isotropic-rotor-3d.toml F1 Lx Ly Lz Axx Axy P_1_1 Q_1_1 R_1_1 \
         S_1_1 --define 'P_y=re(Zy*exp(-i*theta))' --define 'Q_y=im(Zy*exp(-i*theta))' \
         --when 'p_theta = I*omega' --degree 2",
    ),
    (
        "iso3-rotor-closure-2-1",
        "superint closure systems/isotropic-rotor-3d.toml Axx Azz Ly P_2_1 Q_2_1 R_2_1 S_2_1 \
         --define 'A_zx=(p_z*p_x/M + M*omega^2*z*x)/2' --define 'X=re(Zx*Zz*exp(-i*theta))' \
         --define 'Y=im(Zx*Zz*exp(-i*theta))' --when 'p_theta = 2*I*omega' --degree 1",
    ),
    (
        "iso3-rotor-closure-sp6",
        "superint closure systems/isotropic-rotor-3d.toml Lx Ly Lz Axx Ayy Azz Axy P_2_1 Q_2_1 R_2_1 \
         S_2_1 --define 'A_yz=(p_y*p_z/M + M*omega^2*y*z)/2' \
         --define 'A_zx=(p_z*p_x/M + M*omega^2*z*x)/2' --define 'T_yy=re(Zy^2*exp(-i*theta))' \
         --define 'U_yy=im(Zy^2*exp(-i*theta))' --define 'T_xy=re(Zx*Zy*exp(-i*theta))' \
         --define 'U_xy=im(Zx*Zy*exp(-i*theta))' --define 'T_yz=re(Zy*Zz*exp(-i*theta))' \
         --define 'U_yz=im(Zy*Zz*exp(-i*theta))' --define 'T_zx=re(Zz*Zx*exp(-i*theta))' \
         --define 'U_zx=im(Zz*Zx*exp(-i*theta))' --when 'p_theta = 2*I*omega' --degree 1",
    ),
    (
        "pw-search",
        "superint search systems/post-winternitz.toml --momenta-degree 4 --positions-degree 10 \
         --laurent --symbolic alpha --new-only",
    ),
    (
        "pw-search-6",
        "superint search systems/post-winternitz.toml --momenta-degree 6 --positions-degree 14 \
         --laurent --symbolic alpha --parameters-degree 3 --new-only",
    ),
    (
        "pw-closure",
        "superint closure systems/post-winternitz.toml H A B F --degree 6",
    ),
    (
        "level-set-1-1",
        "superint rank systems/harmonic-rotor.toml F1 F2 L G1 G2 P_1_1 Q_1_1 \
         --when 'p_theta = I*omega'",
    ),
    (
        "level-set-2-3",
        "superint rank systems/harmonic-rotor.toml F1 L G1 G2 P_2_3 Q_2_3 \
         --when 'p_theta = 2*I*omega/3'",
    ),
    (
        "level-set-off",
        "superint rank systems/harmonic-rotor.toml F1 L G1 G2 P_1_1 P_2_3 \
         --when 'p_theta = I*omega'",
    ),
    (
        "level-set-gravity",
        "superint rank systems/gravity-rotor.toml F1 F2 Lp G1p G2p Pp_1_1 Qp_1_1 \
         --when 'p_theta = I*omega'",
    ),
    (
        "micz-closure",
        "superint closure systems/micz-kepler-poisson.toml Jx Jy Jz Ax Ay Az H --degree 3",
    ),
    (
        "micz-search",
        "superint search systems/micz-kepler-poisson.toml --poisson-degree 3 --radicals-degree 2 \
         --new-only",
    ),
];

/// A system file of `systems/`, loaded.
fn system_file(name: &str) -> superint::system_file::LoadedSystem {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("systems")
        .join(name);
    load(&path, &LimitsOverride::default()).expect("the file loads")
}

/// Runs the named command of the note (with `--no-timings`), expects exit 0, returns stdout.
fn run(name: &str) -> String {
    let command = COMMANDS
        .iter()
        .find(|c| c.0 == name)
        .unwrap_or_else(|| panic!("no command {name}"))
        .1;
    let args = words(command);
    assert_eq!(args[0], "superint");
    let mut args: Vec<&str> = args[1..].iter().map(String::as_str).collect();
    args.push("--no-timings");
    let out = superint(&args);
    let stdout = String::from_utf8(out.stdout).expect("UTF-8");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{command}\nstdout:\n{stdout}\nstderr:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    stdout
}

/// Runs the named command on a copy of its system file cut before the first
/// `[[function]]`, so that `H` is the only integral it knows; expects exit 0, returns stdout
/// with its whitespace normalized.
fn run_on_hamiltonian_alone(name: &str) -> String {
    let command = COMMANDS
        .iter()
        .find(|c| c.0 == name)
        .unwrap_or_else(|| panic!("no command {name}"))
        .1;
    let args = words(command);
    let file = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(&args[2]))
        .expect("the file reads");
    let bare = &file[..file.find("[[function]]").expect("functions")];
    let path = crate::scratch_text("hamiltonian-alone", &format!("{name}.toml"), bare);
    let mut args: Vec<&str> = args[1..].iter().map(String::as_str).collect();
    args[1] = path.to_str().expect("a path");
    args.push("--no-timings");
    let out = superint(&args);
    let text = normalize(&String::from_utf8(out.stdout).expect("UTF-8"));
    assert_eq!(out.status.code(), Some(0), "{text}");
    text
}

/// [`run_on_hamiltonian_alone`], asserting that each expected piece of its output appears
/// (whitespace normalized); returns the normalized output.
#[track_caller]
fn expect_alone(name: &str, pieces: &[&str]) -> String {
    let text = run_on_hamiltonian_alone(name);
    for piece in pieces {
        assert!(
            text.contains(&normalize(piece)),
            "`{name}` on H alone does not print {piece:?}; it printed:\n{text}"
        );
    }
    text
}

/// Runs the named command and asserts that each expected piece of output appears.
#[track_caller]
fn expect(name: &str, pieces: &[&str]) -> String {
    let out = run(name);
    let flat = normalize(&out);
    for p in pieces {
        assert!(
            flat.contains(&normalize(p)),
            "`{name}` does not print {p:?}; it printed:\n{out}"
        );
    }
    out
}

/// How many products `H^a J^b` of an `H` quadratic and a `J` linear in the momenta have
/// momenta degree `2a + b ≤ degree`: the dimension of a space whose integrals are theirs alone.
fn products_of_h_and_j(degree: usize) -> usize {
    (0..=degree / 2).map(|a| degree - 2 * a + 1).sum()
}

/// Runs the named search (with `--new-only`, of momenta degree `degree`) and asserts that its
/// integrals are the products of `H` and `J` alone, and that it prints each of `more`.
#[track_caller]
fn expect_h_and_j_alone(name: &str, degree: usize, more: &[&str]) -> String {
    let products = products_of_h_and_j(degree);
    let dimension = format!("Dimension of the space of integrals: {products}.");
    let mut pieces = vec![
        dimension.as_str(),
        "Known integrals in the space: H, J.",
        "None: the known integrals generate every integral in the space.",
    ];
    pieces.extend_from_slice(more);
    expect(name, &pieces)
}

/// Runs the named `--find-values` search and asserts that it prints each of `pieces` and that
/// the determinants' roots it did not search at (irrational or complex) are ruled out.
#[track_caller]
fn expect_the_other_roots_ruled_out(name: &str, pieces: &[&str]) -> String {
    let ruled_out = "hold no more integrals in this space: at each, every block of the \
                     equations keeps its generic rank";
    expect(name, &[pieces, &[ruled_out]].concat())
}

/// Checks the system file and asserts that its report prints each of `pieces`.
#[track_caller]
fn check_prints(file: &str, pieces: &[&str]) {
    let out = normalize(&superint_ok(&["check", file, "--no-timings"]));
    for piece in pieces {
        assert!(out.contains(&normalize(piece)), "no {piece:?} in:\n{out}");
    }
}

#[test]
fn results_md_quotes_every_command() {
    let note = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/results.md"))
        .expect("docs/results.md exists");
    let flat = normalize(&note.replace("\\\n", " "));
    for (name, command) in COMMANDS {
        assert!(
            flat.contains(&normalize(command)),
            "docs/results.md does not show the command `{name}`: {command}"
        );
    }
}

#[test]
fn harmonic_1_1_dimensions_and_basis() {
    expect(
        "h11",
        &[
            "Dimension of the space of integrals: 105. By degree in the momenta: ≤ 0: 1, \
             ≤ 1: 6, ≤ 2: 20, ≤ 3: 50, ≤ 4: 105.",
            "Momenta degree exactly 1: 1 of order 0, 4 of order 1.",
            "J2 = x p_y − y p_x",
            "J3 = p_y cos θ + Mωy sin θ",
            "J5 = p_x cos θ + Mωx sin θ",
            "J9 = p_x² + M²ω²x²",
            "then each basis element was lifted back to symbolic parameters by homogeneity and \
             proved symbolically",
            "105 claims: 105 proved, 0 refuted",
        ],
    );
}

/// `superint search` forms what only JSON shows for JSON alone: in the other formats its
/// report holds neither the search's facts nor each integral's claim as text to read back,
/// which they leave out (a fifth of the text report's time at degree 12), and prints as the
/// whole report does; in JSON it is the whole report.
#[test]
fn a_search_forms_what_only_json_shows_for_json_alone() {
    use superint::discovery::{command_line_search_report, file_search_report};
    use superint::render::{render, Format, Options};
    use superint::report::{Entry, Report};
    use superint::system_file::Caller;

    let file = system_file("harmonic-rotor.toml");
    let space = SearchSpace::default()
        .momenta_degree(2)
        .positions_degree(2)
        .trig_degree(2);
    let options = SearchOptions::new(space).when(file.condition("p_theta = I*omega").unwrap());
    let (whole, _) = file_search_report(&file, &options, Caller::CommandLine).unwrap();
    let name = file.the_name();
    // Its sections marked with the file, as the command line marks every report.
    let report = |format| {
        command_line_search_report(Some(&file), &name, file.system(), &options, format)
            .unwrap()
            .0
            .about_file(&file.source().origin)
    };
    let for_json = |r: &Report| {
        let entries = r.sections.iter().flat_map(|s| &s.entries);
        let facts = entries.clone().any(|e| matches!(e, Entry::Data(_)));
        let written = entries.filter(|e| matches!(e, Entry::Claim(c) if c.written.is_some()));
        (facts, written.count())
    };
    let options = Options::reproducible();
    for format in [Format::Text, Format::Markdown, Format::Latex] {
        let r = report(format);
        assert_eq!(for_json(&r), (false, 0), "{format:?}");
        assert_eq!(
            render(&r, format, &options),
            render(&whole, format, &options)
        );
    }
    let json = report(Format::Json);
    assert_eq!(for_json(&json), for_json(&whole));
    assert!(for_json(&whole).0 && for_json(&whole).1 > 10);
    assert_eq!(
        render(&json, Format::Json, &options),
        render(&whole, Format::Json, &options)
    );
}

#[test]
fn euler_top_casimir_and_energy() {
    expect(
        "euler",
        &[
            "Dimension of the space of integrals: 6. By degree in the Poisson variables: ≤ 0: 1, \
             ≤ 1: 1, ≤ 2: 3, ≤ 3: 3, ≤ 4: 6.",
            "J2 = 3 M2² + 4 M3²",
            "J3 = 3 M1² − M3²",
            "the weights do not determine every parameter, so nothing is lifted",
            "6 claims: 6 proved, 0 refuted",
        ],
    );
    expect(
        "euler-symbolic",
        &[
            "Over the polynomials in I1, I2, I3, 3 of the 21 basis integrals, J1, J11 and J15, generate all of them",
            "J11 = M1² + M2² + M3²",
            "J15 = I1 I3 M2² − I2 I3 M2² + I1 I2 M3² − I2 I3 M3²",
        ],
    );
    // J15 is 2I1I2I3 H less I2I3 |M|², as the note says.
    let file = system_file("euler-top.toml");
    let parse = |t: &str| file.parse_argument(t).unwrap();
    assert_eq!(
        parse("I1*I3*M2^2 - I2*I3*M2^2 + I1*I2*M3^2 - I2*I3*M3^2"),
        parse("2*I1*I2*I3*H - I2*I3*C")
    );
}

/// The Neumann system's Uhlenbeck integrals generate every integral of degree ≤ 6 at fixed
/// distinct `a_i`, and their weighted sum is `2H` for every `a_i`.
#[test]
fn neumann_uhlenbeck_integrals_generate_every_integral_to_degree_6() {
    expect(
        "neumann",
        &[
            "Parameters fixed for the linear algebra: a1 = 7, a2 = 11/2, a3 = 13/3 (not 1, where \
             the denominator (a1 − a2) is zero)",
            "Dimension of the space of integrals: 35. By degree in the Poisson variables: ≤ 0: 1, \
             ≤ 1: 1, ≤ 2: 5, ≤ 3: 5, ≤ 4: 15, ≤ 5: 15, ≤ 6: 35.",
            "Known integrals in the space: H, Q, A, F1, F2, F3.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    expect(
        "neumann-closure",
        &[
            "The table closes",
            "a1 F1 + a2 F2 + a3 F3 = 2 H [R1 proved]",
        ],
    );
}

#[test]
fn kovalevskaya_top_quartic_integral() {
    expect(
        "kovalevskaya",
        &[
            "Dimension of the space of integrals: 11. By degree in the Poisson variables: \
             ≤ 0: 1, ≤ 1: 1, ≤ 2: 4, ≤ 3: 4, ≤ 4: 11.",
            "then each basis element was lifted back to symbolic parameters by homogeneity and \
             proved symbolically",
            "I2 = γ1² + γ2² + γ3²",
            "I3 = M1 γ1 + M2 γ2 + M3 γ3",
            "I4 = M1² + M2² + 2 M3² − 2c γ1",
            "I11 = M1⁴ + 2 M1² M2² + 4c M1² γ1 + 8c M1 M2 γ2 + M2⁴ − 4c M2² γ1 − 4c² γ3²",
            "11 claims: 11 proved, 0 refuted",
        ],
    );
    // I11 is K less 4c²Γ, as the note says.
    let file = system_file("kovalevskaya-top.toml");
    let i11 = file
        .parse_argument("M1^4 + 2*M1^2*M2^2 + 4*c*M1^2*gamma1 + 8*c*M1*M2*gamma2 + M2^4 - 4*c*M2^2*gamma1 - 4*c^2*gamma3^2")
        .unwrap();
    assert_eq!(i11, file.parse_argument("K - 4*c^2*Gamma").unwrap());
    expect(
        "kovalevskaya-new-12",
        &[
            "Dimension of the space of integrals: 130.",
            "Known integrals in the space: H, Γ, A, K.",
            "(547 products formed); the generated ones span the whole space (130 dimensions).",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    expect(
        "heavy-1-3",
        &[
            "Dimension of the space of integrals: 10.",
            "Known integrals in the space: H, Γ, A.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
}

#[test]
fn harmonic_1_1_new_integrals() {
    expect(
        "h11-new",
        &[
            "Known integrals in the space: H, L, G1, G2.",
            "the generated ones span 101 of the 105 dimensions",
            "J3 = p_y cos θ + Mωy sin θ",
            "J4 = −Mωy cos θ + p_y sin θ",
            "J5 = p_x cos θ + Mωx sin θ",
            "J6 = −Mωx cos θ + p_x sin θ",
            "A5 (k = 1) = p_x + iMωx",
        ],
    );
    expect(
        "h11-new-pq",
        &[
            "Known integrals in the space: H, L, G1, G2, P_{1,1}, Q_{1,1}.",
            "the generated ones span 103 of the 105 dimensions",
            "J3 = p_y cos θ + Mωy sin θ",
            "J4 = −Mωy cos θ + p_y sin θ",
            "3 claims: 3 proved",
        ],
    );
}

/// At 1:1 up to degrees 8 and 10, the same four linear integrals are the only new ones.
#[test]
fn harmonic_1_1_new_integrals_to_degrees_8_and_10_are_the_same_four() {
    for (name, unknowns, dimensions, filtration, span) in [
        (
            "h11-new-8",
            34425,
            825,
            "≤ 5: 196, ≤ 6: 336, ≤ 7: 540, ≤ 8: 825.",
            "(3625 products formed); the generated ones span 821 of the 825 dimensions",
        ),
        (
            "h11-new-10",
            91476,
            1716,
            "≤ 8: 825, ≤ 9: 1210, ≤ 10: 1716.",
            "the generated ones span 1712 of the 1716 dimensions",
        ),
    ] {
        expect(
            name,
            &[
                &format!("{unknowns} unknowns"),
                &format!("Dimension of the space of integrals: {dimensions}."),
                filtration,
                "Known integrals in the space: H, L, G1, G2.",
                span,
                "New integrals: J3 = p_y cos θ + Mωy sin θ J4 = −Mωy cos θ + p_y sin θ \
                 J5 = p_x cos θ + Mωx sin θ J6 = −Mωx cos θ + p_x sin θ Those",
                "5 claims: 5 proved, 0 refuted",
            ],
        );
    }
}

/// At 2:1, 2:3 and 1:2, and with gravity at 1:1, higher degrees than in §1.2–1.4 and §2 find
/// the same new integrals and no other (their names listed in order).
#[test]
fn higher_degrees_find_the_same_new_integrals() {
    for (name, dimension, generated, new, first_a) in [
        (
            "h21-new-8",
            425,
            421,
            "J7 J8 J9 J10",
            "A7 (k = 1) = p_y² + 2iMωy p_y − M²ω²y²",
        ),
        (
            "h23-new-8",
            347,
            343,
            "J7 J8 J9 J10",
            "A7 (k = 3) = p_y² + 2iMωy p_y − M²ω²y²",
        ),
        ("h12-new-8", 635, 633, "J3 J4", "A3 (k = 2) = p_y + iMωy"),
        (
            "g11-new-8",
            825,
            821,
            "J3 J4 J5 J6",
            "J3 = p_y cos θ + (Mωy + Mg/ω) sin θ",
        ),
    ] {
        let out = expect(
            name,
            &[
                &format!("Dimension of the space of integrals: {dimension}."),
                &format!("the generated ones span {generated} of the {dimension} dimensions"),
                first_a,
            ],
        );
        let listed = out
            .split("New integrals:")
            .nth(1)
            .and_then(|rest| rest.split("Those of").next())
            .expect("a list of new integrals");
        let names: Vec<&str> = listed
            .lines()
            .filter_map(|l| l.trim_start().split(' ').next())
            .filter(|w| {
                w.strip_prefix('J')
                    .is_some_and(|n| !n.is_empty() && n.chars().all(|c| c.is_ascii_digit()))
            })
            .collect();
        assert_eq!(names.join(" "), new, "`{name}`:\n{out}");
    }
}

#[test]
fn harmonic_1_1_closure() {
    expect(
        "h11-closure",
        &[
            "The brackets marked * are no polynomials of degree ≤ 2 in the generators; here \
             they are. A higher --degree, or what superint search finds added to the generators, \
             may close the table.",
            "{G1, P_{1,1}} = (ω p_x/2 + Mω²y/2) cos θ + (−ω p_y/2 + Mω²x/2) sin θ",
            "{G2, Q_{1,1}} = (−ω p_x − Mω²y) cos θ + (ω p_y − Mω²x) sin θ",
            "{F2, P_{1,1}} = −ω Q_{1,1}",
            "{L, P_{1,1}} = Q_{1,1}",
            "{P_{1,1}, Q_{1,1}} = −2Mω",
            "F2 = ω²I/2",
            "ω⁴I² + 4 F1² = 4ω²I F1 + 4ω² L² + 16 G1² + 4 G2²",
            "Mω²I + P_{1,1}² + Q_{1,1}² = 2Mω L + 2M F1",
        ],
    );
    expect(
        "h11-closure-rs",
        &[
            "The table closes",
            "{G1, P_{1,1}} = ω R_{1,1}/2",
            "{G2, P_{1,1}} = ω S_{1,1}",
            "{G1, R_{1,1}} = −ω P_{1,1}/2",
            "{R_{1,1}, S_{1,1}} = −2Mω",
            "2M G2 = P_{1,1} R_{1,1} + Q_{1,1} S_{1,1}",
            "4M G1 + P_{1,1} S_{1,1} = Q_{1,1} R_{1,1}",
            "Mω²I + 2Mω L + R_{1,1}² + S_{1,1}² = 2M F1",
            "31 claims: 31 proved, 0 refuted",
        ],
    );
    // The two circular modes commute: {P, R} = {P, S} = {Q, R} = {Q, S} = 0.
    let file = system_file("harmonic-rotor.toml");
    let parse = |s: &str| file.parse_argument(s).expect("parses");
    let w = "(p_x - i*p_y + i*M*omega*(x - i*y))*exp(-i*theta)";
    for a in ["P_1_1", "Q_1_1"] {
        for b in [format!("re({w})"), format!("im({w})")] {
            let bracket = file.system().bracket(&parse(a), &parse(&b)).unwrap();
            assert!(bracket.is_zero(), "{{{a}, {b}}} = {bracket}");
        }
    }
}

#[test]
fn harmonic_2_1() {
    expect(
        "h21-new",
        &[
            "Dimension of the space of integrals: 57. By degree in the momenta: ≤ 0: 1, \
             ≤ 1: 2, ≤ 2: 12, ≤ 3: 22, ≤ 4: 57.",
            "the generated ones span 53 of the 57 dimensions",
            "A7 (k = 1) = p_y² + 2iMωy p_y − M²ω²y²",
            "A9 (k = 1) = p_x p_y + iMωx p_y + iMωy p_x − M²ω²xy",
        ],
    );
    expect(
        "h21-closure",
        &[
            "The table closes",
            "{G1, P_{2,1}} = ω T_{2,1}",
            "{P_{2,1}, Q_{2,1}} = 16M²ω(2ω²I − ω L − F1)",
            "{T_{2,1}, U_{2,1}} = 8M²ω(2ω²I − F1)",
            "16M² G1² + P_{2,1} R_{2,1} = T_{2,1}²",
            "57 claims: 57 proved, 0 refuted",
        ],
    );
}

#[test]
fn harmonic_1_2() {
    expect(
        "h12-new",
        &[
            "Dimension of the space of integrals: 79. By degree in the momenta: ≤ 0: 1, \
             ≤ 1: 6, ≤ 2: 20, ≤ 3: 42, ≤ 4: 79.",
            "the generated ones span 77 of the 79 dimensions",
            "A3 (k = 2) = p_y + iMωy",
        ],
    );
    expect(
        "h12-closure",
        &[
            "The table closes",
            "{G1, P_{1,2}} = ω R_{1,2}/2",
            "{P_{1,2}, Q_{1,2}} = −2Mω",
            "Mω²I + 4 P_{1,2}² + 4 Q_{1,2}² = 8Mω L + 8M F1",
        ],
    );
}

#[test]
fn harmonic_2_3() {
    expect(
        "h23-new",
        &[
            "Dimension of the space of integrals: 47. By degree in the momenta: ≤ 0: 1, \
             ≤ 1: 2, ≤ 2: 12, ≤ 3: 22, ≤ 4: 47.",
            "the generated ones span 43 of the 47 dimensions",
            "A7 (k = 3) = p_y² + 2iMωy p_y − M²ω²y²",
        ],
    );
    expect(
        "h23-closure",
        &[
            "The table closes",
            "{G1, P_{2,3}} = ω T_{2,3}",
            "{P_{2,3}, Q_{2,3}} = 16M²ω(2ω²I − 9ω L − 9 F1)/9",
        ],
    );
}

#[test]
fn gravity_1_1() {
    expect(
        "g11-new",
        &[
            "Dimension of the space of integrals: 105. By degree in the momenta: ≤ 0: 1, \
             ≤ 1: 6, ≤ 2: 20, ≤ 3: 50, ≤ 4: 105.",
            "Known integrals in the space: H, L', G1', G2'.",
            "the generated ones span 101 of the 105 dimensions",
            "J3 = p_y cos θ + (Mωy + Mg/ω) sin θ",
            "J5 = p_x cos θ + Mωx sin θ",
        ],
    );
    let out = expect(
        "g11-closure",
        &[
            "The table closes",
            "M²g⁴/ω⁴ + 4Mg² Hp/ω² + 4 Hp² = 4ω² L'² + 16 G1'² + 4 G2'²",
            "M²g²/ω² + 2Mω L' + 2M Hp = P'_{1,1}² + Q'_{1,1}²",
            "2M G2' = P'_{1,1} Rp_{1,1} + Q'_{1,1} Sp_{1,1}",
            "35 claims: 35 proved, 0 refuted",
        ],
    );
    assert!(!out.contains("no symbolic lift"), "{out}");
    expect(
        "g11-closure-f1",
        &[
            "F1² = L'² + 4 G1'² + G2'² at p_θ = Iω, M = 1, ω = 1, I = 1, g = 1",
            "not lifted back to the parameters (no symbolic lift)",
        ],
    );
}

#[test]
fn anisotropic_3_5_c26() {
    expect(
        "a35-new",
        &[
            "Dimension of the space of integrals: 19. By degree in the momenta: ≤ 0: 1, \
             ≤ 1: 5, ≤ 2: 9, ≤ 3: 19.",
            "Known integrals in the space: H, H_x, H_y, Re K, Im K.",
            "the generated ones span 15 of the 19 dimensions",
            "Ψ2 (k = 3) = p_x + 3iMωx",
            "Ψ4 (k = 5) = p_y + 5iMωy",
        ],
    );
    expect(
        "a35-closure",
        &[
            "The table closes",
            "{J1, J2} = −3Mω",
            "{Y1, Y2} = −5Mω",
            "2M H_x = J1² + J2²",
            "2M H_y = Y1² + Y2²",
        ],
    );
    // C26's integrals are products of the two linear ones: with J = A_x e^{−3iθ} and
    // Y = A_y e^{−5iθ}, K = A_x² Ā_y e^{−iθ} = J² Ȳ and A_x⁵ Ā_y³ = J⁵ Ȳ³.
    let file = system_file("anisotropic-3-5-rotor.toml");
    let parse = |s: &str| file.parse_argument(s).expect("parses");
    let j = parse("Ax*exp(-3*i*theta)");
    let ybar = parse("Aybar*exp(5*i*theta)");
    let jj = j.checked_mul(&j).unwrap();
    assert_eq!(jj.checked_mul(&ybar).unwrap(), parse("K"));
    let j5 = j.checked_pow(5).unwrap();
    let y3 = ybar.checked_pow(3).unwrap();
    assert_eq!(j5.checked_mul(&y3).unwrap(), parse("A"));
}

/// A closure at `p_θ = Iω` brackets the generators on the whole phase space and sets `p_θ`
/// after: `F2 = p_θ²/(2I)` is the constant `ω²I/2` there and `{F2, J1} = −3ω J2` all the
/// same (set first, `F2` would have no bracket at all), and the report says so under its
/// method, in every prose format; a condition on the parameters alone (`b = 0`), which
/// commutes with the bracket, gets no such note; and `closure --help` says it too.
#[test]
fn a_closure_on_a_phase_variable_says_each_bracket_is_set_after_it_is_formed() {
    let note = "`p_θ` is a variable of the phase space, along which a bracket differentiates: \
                each bracket is formed from the generators on the whole phase space and only \
                then set at `p_θ = Iω`, and written in the generators set there, so a \
                generator that is a constant at `p_θ = Iω` may still have brackets that are \
                not zero.";
    let text = expect(
        "a35-closure",
        &[
            &note.replace('`', ""),
            "F2 = ω²I/2 at p_θ = Iω [R1 proved]",
            "{F2, J1} = −3ω J2 at p_θ = Iω [B5 proved]",
        ],
    );
    // Under the method's paragraph, before the table.
    let at = text.find("p_θ is a variable of the phase space");
    assert!(
        at.is_some_and(|k| k < text.find("{F, G}").unwrap()),
        "{text}"
    );
    let command = COMMANDS.iter().find(|c| c.0 == "a35-closure").unwrap().1;
    let args = words(command);
    let mut args: Vec<&str> = args[1..].iter().map(String::as_str).collect();
    args.extend(["--no-timings", "--format", "markdown"]);
    let markdown = normalize(&superint_ok(&args));
    assert!(markdown.contains(&normalize(note)), "{markdown}");
    let landau = run("fd-closure-landau");
    assert!(
        !landau.contains("along which a bracket differentiates"),
        "{landau}"
    );
    let help = normalize(&superint_ok(&["closure", "--help"]));
    for piece in [
        "Each bracket is formed from the generators on the whole phase space and only then \
         set on it (p_θ is a variable of the phase space, along which a bracket \
         differentiates, so it cannot be set to a constant first), and written in the \
         generators set there: the harmonic rotor's F2, the constant ω²I/2 at p_θ = Iω, may \
         still have brackets that are not zero",
        "With --when, each bracket is formed from the generators on the whole phase space and \
         then set on the condition",
    ] {
        assert!(help.contains(&normalize(piece)), "{help}");
    }
}

/// The 3:5 rotor's `{Re A, Im A}` reads two ways in the two closures of results.md §3, by one
/// rule (what every term shares in front, a number times a monomial): `1920M⁸ω(3 H_x −
/// 5 H_y) H_x⁴ H_y²` among `H_x, H_y, Re A, Im A`, and through `K`, with `30M²ω` alone in
/// front, at the resonance. Both are the bracket (the second there, where it is
/// `30M²ω(3 H_x − 5 H_y)|K|⁴`, as results.md restates it), and results.md quotes each as the
/// command prints it.
#[test]
fn the_3_5_rotors_re_a_im_a_reads_two_ways_by_one_rule() {
    let planar = "{Re A, Im A} = 1920M⁸ω(3 H_x − 5 H_y) H_x⁴ H_y²";
    let resonant = "{Re A, Im A} = 30M²ω(3 H_x (Re K)⁴ + 6 H_x (Re K)² (Im K)² + 3 H_x (Im K)⁴ \
                    − 5 H_y (Re K)⁴ − 10 H_y (Re K)² (Im K)² − 5 H_y (Im K)⁴)";
    let planar_run = normalize(&superint_ok_line(
        "closure systems/anisotropic-3-5-rotor.toml Hx Hy ReA ImA --degree 8 --no-timings",
    ));
    assert!(
        planar_run.contains(&format!("{planar} [B5 proved]")),
        "{planar_run}"
    );
    expect(
        "a35-k-and-a",
        &[&format!("{resonant} at p_θ = Iω [B10 proved]")],
    );
    let file = system_file("anisotropic-3-5-rotor.toml");
    let at = file.condition("p_theta = I*omega").expect("a condition");
    let system = file.system();
    crate::assert_proved(
        system,
        "{ReA, ImA} = 1920*M^8*omega*(3*Hx - 5*Hy)*Hx^4*Hy^2",
        None,
    );
    let k4 = "(ReK^2 + ImK^2)^2";
    for form in [
        "30*M^2*omega*(3*Hx*ReK^4 + 6*Hx*ReK^2*ImK^2 + 3*Hx*ImK^4 - 5*Hy*ReK^4 \
         - 10*Hy*ReK^2*ImK^2 - 5*Hy*ImK^4)"
            .to_string(),
        format!("30*M^2*omega*(3*Hx - 5*Hy)*{k4}"),
    ] {
        crate::assert_proved(system, &format!("{{ReA, ImA}} = {form}"), Some(&at));
    }
    let note = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/results.md"))
        .expect("docs/results.md exists");
    let note = normalize(&note.replace('`', ""));
    for printed in [planar, resonant] {
        assert!(
            note.contains(&normalize(printed)),
            "results.md lacks {printed}"
        );
    }
}

/// The 3:5 rotor's `K` and `A` at the resonance: at degree 6 three relations, the third
/// `2M H_x |A|² = |K|⁶`; at degree 7 it is `|K|⁴ R1 − 2M³ H_x R2`, through multiples of
/// degree 7, and only the first two are listed, not the third's multiples by each generator
/// (`H_x ·`, `H_y ·`, …), which the closure once listed in its place.
#[test]
fn anisotropic_3_5_k_and_a_relations() {
    let relations = [
        "8M³ H_x² H_y = (Re K)² + (Im K)² at p_θ = Iω [R1 proved]",
        "4 H_x H_y (Re K)⁴ + 8 H_x H_y (Re K)² (Im K)² + 4 H_x H_y (Im K)⁴ = (Re A)²/M² \
         + (Im A)²/M² at p_θ = Iω [R2 proved]",
    ];
    let third = "2M H_x (Re A)² + 2M H_x (Im A)² = (Re K)⁶ + 3 (Re K)⁴ (Im K)² \
                 + 3 (Re K)² (Im K)⁴ + (Im K)⁶ at p_θ = Iω [R3 proved]";
    let six = [
        &relations[..],
        &[
            "{Re K, Im K} = 4M³ω(5 H_x − 12 H_y) H_x at p_θ = Iω",
            third,
            "13 claims: 13 proved, 0 refuted",
        ],
    ]
    .concat();
    expect("a35-k-and-a", &six);
    let command = COMMANDS
        .iter()
        .find(|c| c.0 == "a35-k-and-a")
        .expect("the command")
        .1;
    let mut args: Vec<String> = words(command).into_iter().skip(1).collect();
    let last = args.len() - 1;
    args[last] = "7".into();
    args.push("--no-timings".into());
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = superint(&args);
    let seven = normalize(&String::from_utf8(out.stdout).expect("UTF-8"));
    assert_eq!(out.status.code(), Some(0), "{seven}");
    for piece in relations {
        assert!(seven.contains(&normalize(piece)), "{piece} not in {seven}");
    }
    assert!(!seven.contains("[R3"), "{seven}");
    assert!(seven.contains("12 claims: 12 proved, 0 refuted"), "{seven}");
}

#[test]
fn anisotropic_1_2() {
    expect(
        "a12-new",
        &[
            "Dimension of the space of integrals: 27. By degree in the momenta: ≤ 0: 1, \
             ≤ 1: 5, ≤ 2: 14, ≤ 3: 27.",
            "the generated ones span 23 of the 27 dimensions",
            "J2 = p_x cos θ + Mωx sin θ",
            "A4 (k = 2) = p_y + 2iMωy",
        ],
    );
}

#[test]
fn c27_smorodinsky_winternitz_second_order_integrals() {
    expect(
        "sw1",
        &[
            "Dimension of the space of integrals: 4.",
            "I2 = p_y² + 2Mαy² + 2Mγ/y²",
            "I3 = p_x² + 2Mαx² + 2Mβ/x²",
            "I4 = x² p_y² − 2xy p_x p_y + y² p_x² + 2Mγx²/y² + 2Mβy²/x²",
            "4 claims: 4 proved, 0 refuted",
        ],
    );
    expect(
        "sw2",
        &[
            "Dimension of the space of integrals: 4.",
            "I2 = p_y² + 8Mαy² + 2Mγy",
            "I3 = p_x² + 2Mαx² + 2Mβ/x²",
            "I4 = 2x p_x p_y − 2y p_x² + 4Mαx²y + Mγx² − 4Mβy/x²",
            "4 claims: 4 proved, 0 refuted",
        ],
    );
}

#[test]
fn su2_and_its_casimir() {
    expect(
        "su2",
        &[
            "{L, G1} = −G2",
            "{L, G2} = 4 G1",
            "{G1, G2} = −ω² L",
            "ω² L² + 2 F1 F2 + 4 G1² + G2² = F1² + F2²",
        ],
    );
}

#[test]
fn henon_heiles_kdv_integral_for_every_a_and_b() {
    expect(
        "hh-kdv",
        &[
            // No angles: no trigonometric part in the space or the counts.
            "The space: x^a y^b p_x^c p_y^d, with momenta degree c + d ≤ 2, positions degree \
             |a| + |b| ≤ 4, coefficients polynomials of degree ≤ 2 in A, B: 540 unknowns",
            "Momenta degree exactly 2: 4.",
            "Over the polynomials in A, B, 3 of the 10 basis integrals, I1, I7 and I10, generate all of them",
            "I7 = p_x² + p_y² + 2x²y + Ax² + 4y³ + By²",
            "I10 = 4x p_x p_y − 4y p_x² − 4A p_y² + B p_y² + x⁴ + 4x²y² − 4Ax²y + 2Bx²y − \
             16Ay³ + 4By³ − 4ABy² + B²y²",
            "proved for every A, B, at C = 2",
        ],
    );
    // The generator is the file's K, whose claim holds at C = 2 and is refuted elsewhere.
    let file = system_file("henon-heiles.toml");
    let var = |name: &str| file.system().vars().lookup(name).expect("a parameter");
    let options = SearchOptions::new(
        SearchSpace::default()
            .momenta_degree(2)
            .positions_degree(4)
            .parameters_degree(2),
    )
    .fix(var("C"), Rational::from(2))
    .symbolic(var("A"))
    .symbolic(var("B"));
    let r = search(file.system(), &options).expect("the search runs");
    let generators: Vec<&Expr> = r
        .module
        .as_ref()
        .expect("parameters kept symbolic")
        .generators
        .iter()
        .map(|&i| r.basis[i].expr())
        .collect();
    let k = file.parse_argument("K").expect("K parses");
    assert!(generators.contains(&&k), "{generators:?}");
    assert!(r.basis.iter().all(|f| f.proved_fixed));
}

/// The values of `C` with a second integral quadratic in the momenta, found from `H` alone
/// (results.md §7): at `A = B = 1`, the separable case `C = 1/3` and the KdV case `C = 2`,
/// every root of the determinants rational.
#[test]
fn henon_heiles_values_of_c_with_a_second_quadratic_integral_found_from_h_alone() {
    expect_alone(
        "hh-values-quadratic",
        &[
            "For a generic C (searched at C = 7, no root): 2 integrals (section 2), of functional rank 1.",
            "More integrals at C = 1/3, 3 integrals (section 4), of functional rank 2 and at C = 2, 3 integrals (section 6), of functional rank 2.",
            "Roots of the determinants where the search finds no more integrals: C = 2/15 and \
             C = 2/3.",
            "Every root of the determinants is rational: no other value of C has more integrals in \
             this space.",
            "I2 = 3 p_x p_y + x³ + 3xy² + 3xy",
            "I3 = 4x p_x p_y − 4y p_x² − 3 p_y² + x⁴ + 4x²y² − 2x²y − 12y³ − 3y²",
            // Each search's claims: 2 at the generic value, 3 at each value.
            "8 claims: 8 proved, 0 refuted",
        ],
    );
}

/// The values of `C` with an integral quartic in the momenta at `A = 1, B = 16`, from `H`
/// alone (results.md §7): the quartic case `C = 16/3` (the file's `Q`), and `C = 2`, whose
/// quadratic integral is there at every `B`; the complex roots of `21C² − 12C + 272` ruled
/// out.
#[test]
fn henon_heiles_values_of_c_with_a_quartic_integral_at_b_sixteen_found_from_h_alone() {
    expect_alone(
        "hh-values-quartic",
        &[
            "For a generic C (searched at C = 7, no root): 3 integrals (section 2), of functional rank 1.",
            "More integrals at C = 2, 4 integrals (section 4), of functional rank 2 and at C = 16/3, 4 integrals (section 6), of functional rank 2.",
            "The determinants' other 2 roots (complex, none real) hold no more integrals in \
             this space: at each, every block of the equations keeps its generic rank (shown \
             modulo the prime p = 4611686018427387847). No value of C but those above has more integrals in \
             this space.",
            "I3 = 18 p_x² p_y² + 9 p_y⁴ + 12x³ p_x p_y + 36x²y p_y² + 18x² p_y²",
            "11 claims: 11 proved, 0 refuted",
        ],
    );
}

/// The homogeneous quartic potentials `x⁴ + a x²y² + y⁴` (results.md §29), quadratic in the
/// momenta, from `H` alone: the separable `a = 0`, the rotation `a = 2` and the separable in
/// `x ± y`, `a = 6`, and no other value, every root of the determinants rational; on the file,
/// each value's integral is the file's `H_x`, `L`, `S`.
#[test]
fn quartic_potentials_cases_found_from_h() {
    expect_alone(
        "qp-values-quadratic",
        &[
            "For a generic a (searched at a = 7, no root): 2 integrals (section 2), of functional rank 1.",
            "More integrals at a = 0, 3 integrals (section 4), of functional rank 2, at a = 2, 4 integrals (section 6), of functional rank 2 and at a = 6, 3 integrals (section 8), of functional rank 2.",
            "Every root of the determinants is rational: no other value of a has more integrals \
             in this space.",
            "I3 = p_x² + 2x⁴",
            "I2 = x p_y − y p_x",
            "I2 = p_x p_y + 4x³y + 4xy³",
            "12 claims: 12 proved, 0 refuted",
        ],
    );
    expect(
        "qp-values-quadratic",
        &[
            "I3 = p_x² + 2x⁴ = 2 H_x",
            "I2 = x p_y − y p_x = L",
            "I2 = p_x p_y + 4x³y + 4xy³ = S",
        ],
    );
}

/// At `b = 16` the parabolic case `a = 12` is quadratic in the momenta and of degree 5 in the
/// positions (the literature's list calls it quartic): found from `H` alone, the file's `P`.
#[test]
fn quartic_potentials_parabolic_case_a_twelve_b_sixteen_is_quadratic_found_from_h() {
    expect_alone(
        "qp-values-parabolic",
        &[
            "More integrals at a = 0, 3 integrals (section 4), of functional rank 2 and at a = 12, 3 integrals (section 6), of functional rank 2.",
            "Every root of the determinants is rational",
            "I3 = x p_x p_y − y p_x² + 4x⁴y + 8x²y³",
            "8 claims: 8 proved, 0 refuted",
        ],
    );
    expect(
        "qp-values-parabolic",
        &["I3 = x p_x p_y − y p_x² + 4x⁴y + 8x²y³ = P"],
    );
}

/// Quartic in the momenta, at `b = 8`: `a = 6` (the file's `Q`) and the separable `a = 0`;
/// at `a = 6`, the values `b = 1` and `b = 8`; every irrational root ruled out: no other
/// value, rational or not, has more integrals in this space.
#[test]
fn quartic_potentials_quartic_case_a_six_b_eight_found_from_h() {
    expect_alone(
        "qp-values-quartic",
        &[
            "For a generic a (searched at a = 7, no root): 3 integrals (section 2), of functional rank 1.",
            "More integrals at a = 0, 6 integrals (section 4), of functional rank 2 and at a = 6, 4 integrals (section 6), of functional rank 2.",
            "The determinants' other 58 roots (not rational; 50 real) hold no more integrals \
             in this space: at each, every block of the equations keeps its generic rank",
            "No value of a but those above has more integrals in this space.",
            "I3 = 2 p_x² p_y² + p_y⁴ + 16x³y p_x p_y + 24x²y² p_y² + 32y⁴ p_x² + 32y⁴ p_y² \
             + 32x⁶y²",
            "13 claims: 13 proved, 0 refuted",
        ],
    );
    expect("qp-values-quartic", &["= Q"]);
    expect_alone(
        "qp-values-b",
        &[
            "For a generic b (searched at b = 7, no root): 3 integrals (section 2), of functional rank 1.",
            "More integrals at b = 1, 6 integrals (section 4), of functional rank 2 and at b = 8, 4 integrals (section 6), of functional rank 2.",
            "The determinants' other 28 roots (not rational; 22 real) hold no more integrals \
             in this space",
            "13 claims: 13 proved, 0 refuted",
        ],
    );
}

/// `a = −6` at `b = 1` (`Re (x + iy)⁴`) has no integral but `H` and its square to degree 4 in
/// the momenta: it is not even a root of the determinants at `b = 1`, where `a = 0, 2, 6` are.
#[test]
fn quartic_potentials_a_minus_six_has_no_second_integral() {
    let text = expect_alone(
        "qp-values-quartic-b1",
        &[
            "More integrals at a = 0, 6 integrals (section 4), of functional rank 2, at a = 2, 9 integrals (section 6), of functional rank 2 and at a = 6, 6 integrals (section 8), of functional rank 2.",
            "The determinants' other 52 roots (not rational; 46 real) hold no more integrals \
             in this space",
        ],
    );
    assert!(
        text.contains("a = −2,") && !text.contains("a = −6"),
        "{text}"
    );
    expect(
        "qp-minus-six",
        &[
            "Dimension of the space of integrals: 3.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
}

/// Section 30: on `p_θ = 1`, the frequencies with more integrals are the resonances
/// `ω = n/m` the space allows, every root rational; with momenta degree 1 and positions
/// degree 2 the irrational roots `ω² = 2, 1/2` are ruled out.
#[test]
fn harmonic_rotor_values_on_p_theta_one_are_its_resonances() {
    expect(
        "rotor-values",
        &[
            "For a generic ω (searched at ω = 7, no root): 6 integrals (section 2), of functional rank 3.",
            "More integrals at ω = −2, 14 integrals (section 4), of functional rank 4, at ω = −1, 20 integrals (section 6), of functional rank 4, at ω = −1/2, 12 integrals (section 8), of functional rank 4, at ω = 0, 10 integrals (section 10), of functional rank 3, at ω = 1/2, 12 integrals (section 12), of functional rank 4, at ω = 1, 20 integrals (section 14), of functional rank 4 and at ω = 2, 14 integrals (section 16), of functional rank 4.",
            "Every root of the determinants is rational: no other value of ω has more \
             integrals in this space.",
        ],
    );
    expect(
        "rotor-values-ruled-out",
        &[
            "More integrals at ω = −2, 6 integrals (section 4), of functional rank 4, at ω = −1, 6 integrals (section 6), of functional rank 4, at ω = 0, 4 integrals (section 8), of functional rank 3, at ω = 1, 6 integrals (section 10), of functional rank 4 and at ω = 2, 6 integrals (section 12), of functional rank 4.",
            "The determinants' other 4 roots (not rational; 4 real) hold no more integrals in \
             this space: at each, every block of the equations keeps its generic rank",
            "No value of ω but those above has more integrals in this space.",
        ],
    );
}

/// Section 30: on `p_θ = 1` with `ω = 1`, the moments of inertia with more integrals are
/// `I = n/m`; `I = 0` is said to be no value.
#[test]
fn harmonic_rotor_moments_of_inertia_on_p_theta_one_are_its_resonances() {
    expect(
        "rotor-values-inertia",
        &[
            "More integrals at I = −2, 14 integrals (section 4), of functional rank 4, at I = −1, 20 integrals (section 6), of functional rank 4, at I = −1/2, 12 integrals (section 8), of functional rank 4, at I = 1/2, 12 integrals (section 10), of functional rank 4, at I = 1, 20 integrals (section 12), of functional rank 4 and at I = 2, 14 integrals (section 14), of functional rank 4.",
            "I = 0, a root of the determinants, is no value",
        ],
    );
}

/// Section 31: the dipole rotor's `J = x p_y − y p_x + p_θ` (the rotation of `x`, `y` and `θ`
/// together) is conserved, and the orbital and the rotor's momenta, each alone, are not: the
/// dipole's torque `ε(x sin θ − y cos θ)` moves them, equal and opposite.
#[test]
fn dipole_rotor_conserves_j_and_refutes_the_orbital_momentum() {
    check_prints(
        "systems/dipole-rotor.toml",
        &[
            "{J, H} = 0 [rotation proved]",
            "{L, H} = −ε(x sin θ − y cos θ) [torque proved]",
            "{Z, H} = iω Z − ε e^{iθ} [ladder proved]",
            "{L, H} = 0 [false-orbital-momentum refuted, as expected] \
             residual lhs − rhs = εy cos θ − εx sin θ",
            "{p_θ, H} = 0 [false-rotor-momentum refuted, as expected]",
            "{Z e^{−iθ}, H} = 0 at p_θ = Iω [false-resonant refuted, as expected] \
             residual lhs − rhs = −ε",
            "16 claims in 1 file: 12 proved, 4 refuted; all as expected",
        ],
    );
}

/// Section 31: at generic values, every integral of degree ≤ 4 in the momenta and the
/// positions and of trigonometric order ≤ 4 is a polynomial in `H` and `J`: the space's
/// dimension is the number of products `H^a J^b` of momenta degree `2a + b ≤ 4`.
#[test]
fn dipole_rotor_has_no_integral_but_h_and_j_to_degree_four() {
    expect_h_and_j_alone("dipole-rotor-search", 4, &[]);
}

/// Section 31: no frequency `ω` adds an integral at degree 2 (`ω = 0`, a root, holds nothing
/// more; the complex roots are ruled out), and the report says so without pointing at values
/// "above" that it never listed.
#[test]
fn dipole_rotor_no_frequency_adds_an_integral_at_degree_two() {
    let out = expect(
        "dipole-rotor-values-omega",
        &[
            "For a generic ω (searched at ω = 7, no root): 4 integrals (section 2), of functional rank 2.",
            "No rational value of ω has more integrals.",
            "Roots of the determinants where the search finds no more integrals: ω = 0.",
            "The determinants' other 4 roots (complex, none real) hold no more integrals in \
             this space: at each, every block of the equations keeps its generic rank",
            "No value of ω has more integrals in this space.",
        ],
    );
    assert!(!out.contains("but those above"), "{out}");
}

/// Section 31: at the generic `ω = 7`, with `M = I = ε = 1` fixed, `Φ3` is `2 H` there, and
/// `2 H`, read with the file's `H` as written, is an integral for every value: `Φ3` is lifted
/// through its restatement, counted with the integrals that hold for every value, its claim
/// `{2 H, H} = 0` proved for every value, and the advice for what is not lifted not given, as
/// nothing is left; JSON's restatement has no `holds_at`.
#[test]
fn dipole_rotor_energy_at_fixed_values_is_lifted_through_two_h() {
    let out = expect(
        "dipole-rotor-values-omega",
        &[
            "3 of the 4 basis elements hold for every value as found and 1 through its \
             restatement (proved symbolically).",
            "Restated at ω = 7, M = 1, I = 1, ε = 1, where it is found, and lifted through the \
             restatement: Φ3, with the file's functions as written.",
            "{2 H, H} = 0 at ω = 7 [Φ3 proved] \
             proved for every M, I, ε; it is Φ3 at ω = 7, M = 1, I = 1, ε = 1",
        ],
    );
    for absent in [
        "What is not lifted",
        "not lifted back",
        "where it holds (not lifted)",
    ] {
        assert!(!out.contains(absent), "{absent:?} in:\n{out}");
    }
    let json: serde_json::Value = serde_json::from_str(&superint_ok_line(
        "search systems/dipole-rotor.toml --find-values omega --fix M=1,I=1,epsilon=1 \
         --momenta-degree 2 --positions-degree 2 --trig-degree 2 --format json",
    ))
    .expect("JSON");
    let line = (json["equations"].as_array().expect("equations").iter())
        .flat_map(|e| e["lines"].as_array().expect("lines"))
        .find(|l| l["lhs"] == "Φ3")
        .expect("Φ3 shown");
    assert_eq!(line["in_functions"]["ascii"], "2*H", "{line}");
    assert!(line["in_functions"].get("holds_at").is_none(), "{line}");
    let claim = (json["claims"].as_array().expect("claims").iter())
        .find(|c| c["id"] == "Φ3")
        .expect("Φ3's claim");
    assert_eq!(claim["ascii"], "{2*H, H} = 0", "{claim}");
    assert_eq!(claim["condition_ascii"], "omega = 7", "{claim}");
    assert_eq!(claim["outcome"], "proved", "{claim}");
    assert_eq!(json["searches"][0]["for_every_value"], 4, "{json}");
}

/// Section 31: the field strength `ε = 0`, the paper's harmonic rotor, is the one value of `ε`
/// with more integrals at degree 2; the other roots are complex and ruled out.
#[test]
fn dipole_rotor_only_zero_field_adds_integrals() {
    expect(
        "dipole-rotor-values-epsilon",
        &[
            "For a generic ε (searched at ε = 7, no root): 4 integrals (section 2), of functional rank 2.",
            "More integrals at ε = 0, 9 integrals (section 4), of functional rank 4.",
            "The determinants' other 2 roots (complex, none real) hold no more integrals in \
             this space",
            "No value of ε but those above has more integrals in this space.",
        ],
    );
}

/// Section 32: the quadrupole rotor's `J = x p_y − y p_x + p_θ` is conserved, the quadrupole's
/// torque `T = −∂V/∂θ = −4ε ξ1 ξ2` (in the body frame) moves `L` and `p_θ` equal and opposite,
/// and the false neighbours are refuted with their residuals: `L`, `p_θ`, the oscillator's
/// energy with the coupling, and the resonant `Z e^{−iθ}` of the harmonic rotor.
#[test]
fn quadrupole_rotor_conserves_j_and_refutes_the_orbital_momentum() {
    check_prints(
        "systems/quadrupole-rotor.toml",
        &[
            "{J, H} = 0 [rotation proved]",
            "{p_θ, H} = T [torque proved]",
            "{L, H} = −T [torque proved]",
            "T = −4ε ξ1 ξ2 [torque proved]",
            "H_osc + V = (π1² + π2²)/(2M) + (Mω² + 2ε) ξ1²/2 + (Mω² − 2ε) ξ2²/2 [body-frame proved]",
            "H = (π1² + π2²)/(2M) + (Mω² + 2ε) ξ1²/2 + (Mω² − 2ε) ξ2²/2 + (J − L)²/(2I) \
             [body-frame proved]",
            "{Z, H} = iω Z − 2ε e^{2iθ} (x − iy) [ladder proved]",
            "{L, H} = 0 [false-orbital-momentum refuted, as expected] \
             residual lhs − rhs = 4εxy cos 2θ + (−2εx² + 2εy²) sin 2θ = −T",
            "{p_θ, H} = −T [false-wrong-sign-torque refuted, as expected]",
            "{H_osc + V, H} = 0 [false-oscillator-energy refuted, as expected]",
            "{Z e^{−iθ}, H} = 0 at p_θ = Iω [false-resonant refuted, as expected]",
            "22 claims in 1 file: 16 proved, 6 refuted; all as expected",
        ],
    );
}

/// Section 32: at generic values, every integral of the quadrupole rotor of degree ≤ 4 in the
/// momenta and the positions and of trigonometric order ≤ 4 is a polynomial in `H` and `J`: the
/// space's dimension is the number of products `H^a J^b` of momenta degree `2a + b ≤ 4`.
#[test]
fn quadrupole_rotor_has_no_integral_but_h_and_j_to_degree_four() {
    expect_h_and_j_alone("quadrupole-rotor-search", 4, &[]);
}

/// Section 32: the field strengths where a co-rotating frequency `ω² ± 2ε/M` vanishes,
/// `ε = ±Mω²/2` (`±1/2` at `M = ω = 1`), are roots of the determinants at degree 2, and the
/// search there finds no more integrals; `ε = 0`, the harmonic rotor, is the one value with
/// more, functionally new, and the irrational roots are ruled out.
#[test]
fn quadrupole_rotor_vanishing_co_rotating_frequency_adds_no_integral() {
    let (mass, omega) = (1, 1);
    let vanishing = format!("{}/2", mass * omega * omega);
    let out = expect_the_other_roots_ruled_out(
        "quadrupole-rotor-values-epsilon",
        &[
            "For a generic ε (searched at ε = 7, no root): 4 integrals (section 2), of functional rank 2.",
            "More integrals at ε = 0, 9 integrals (section 4), of functional rank 4.",
            &format!(
                "Roots of the determinants where the search finds no more integrals: \
                 ε = −{vanishing} and ε = {vanishing}."
            ),
            "No value of ε but those above has more integrals in this space.",
        ],
    );
    assert!(!out.contains("More integrals at ε = 1/2"), "{out}");
}

/// Section 32: on `ε = Mω²/2`, where the frequency across the axis in the turning frame,
/// `ω² − 2ε/M`, vanishes, every integral of degree ≤ 3 (momenta, positions, order) is a
/// polynomial in `H` and `J`, lifted to every `M`, `ω`, `I`: the products `H^a J^b`,
/// `2a + b ≤ 3`, and nothing new.
#[test]
fn quadrupole_rotor_with_a_vanishing_turning_frequency_has_only_h_and_j() {
    let products = products_of_h_and_j(3);
    expect_h_and_j_alone(
        "quadrupole-rotor-vanishing-frequency",
        3,
        &[
            "Integrals of the quadrupole rotor at ε = Mω²/2",
            "each basis element was lifted back to symbolic parameters by homogeneity and \
             proved symbolically.",
            &format!("{{Φ, H}} = 0 for the {products} basis elements at ε = Mω²/2 [basis proved]"),
        ],
    );
}

/// Section 32: no frequency `ω` adds an integral to the quadrupole rotor at degree 2 (at
/// `ε = M = I = 1`): `ω = 0`, a root, holds nothing more, and the irrational roots, among them
/// `ω = ±√2` where a co-rotating frequency vanishes, are ruled out.
#[test]
fn quadrupole_rotor_no_frequency_adds_an_integral_at_degree_two() {
    let out = expect_the_other_roots_ruled_out(
        "quadrupole-rotor-values-omega",
        &[
            "For a generic ω (searched at ω = 7, no root): 4 integrals (section 2), of functional rank 2.",
            "No rational value of ω has more integrals.",
            "Roots of the determinants where the search finds no more integrals: ω = 0.",
            "No value of ω has more integrals in this space.",
        ],
    );
    assert!(!out.contains("but those above"), "{out}");
}

/// Section 33: the gyroscopic rotor conserves `L`, `p_θ` and the oscillator's energy for every
/// `κ`, its quadratic tensor turns at `2κΩ` and is locked to the angle where `2nκ` is an
/// integer; the tensor held conserved, the wrong phase, the wrong `κ` and the paper's resonance
/// unshifted are refuted with their residuals.
#[test]
fn gyroscopic_rotor_conserves_l_p_theta_and_the_oscillator_energy_for_every_kappa() {
    check_prints(
        "systems/gyroscopic-rotor.toml",
        &[
            "{L, H} = 0 [conservation proved]",
            "{p_θ, H} = 0 [conservation proved]",
            "{H_osc, H} = 0 [conservation proved]",
            "{K1, H} = 2κΩ K2 [turning proved]",
            "{Q, H} = −2iκΩ Q [turning proved]",
            "{Z, H} = i(ω − κΩ) Z [ladder proved]",
            "{Q e^{iθ}, H} = 0 at κ = 1/2 [exact-half proved]",
            "{Q² e^{iθ}, H} = 0 at κ = 1/4 [exact-quarter proved]",
            "{Q³ e^{2iθ}, H} = 0 at κ = 1/3 [exact-third proved]",
            "{Z e^{−iθ}, H} = 0 at ω = (1 + κ)(p_θ − κ(x p_y − y p_x))/I [resonant proved]",
            "{K1, H} = 0 [false-tensor-conserved refuted, as expected]",
            "= 2κ Ω K2",
            "{Q e^{−iθ}, H} = 0 at κ = 1/2 [false-wrong-phase refuted, as expected]",
            "{Q e^{iθ}, H} = 0 at κ = 1 [false-wrong-kappa refuted, as expected]",
            "{Z e^{−iθ}, H} = 0 at p_θ = Iω + κ(x p_y − y p_x) [false-unshifted-resonance refuted, as expected]",
            "{x p_x + y p_y, H} = 0 [false-dilation refuted, as expected] \
             residual lhs − rhs = p_x²/M + p_y²/M − Mω²x² − Mω²y²",
            "32 claims in 1 file: 26 proved, 6 refuted; all as expected",
        ],
    );
}

/// Section 33: at a generic `κ` every integral of the gyroscopic rotor of degree ≤ 4 in the
/// momenta and the positions and of order ≤ 4 is a polynomial in `H_osc`, `L` and `p_θ`: the
/// dimension is the number of products `H_osc^a L^b p_θ^c` of momenta degree `2a + b + c ≤ 4`.
#[test]
fn gyroscopic_rotor_has_only_h_osc_l_and_p_theta_to_degree_four() {
    let degree = 4;
    let products: usize = (0..=degree / 2)
        .map(|a| {
            let rest = degree - 2 * a;
            (rest + 1) * (rest + 2) / 2
        })
        .sum();
    expect(
        "gyroscopic-rotor-search",
        &[
            &format!("Dimension of the space of integrals: {products}."),
            "Known integrals in the space: H, H_osc, L, Ω.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
}

/// Section 33: at momenta, positions and order 2 the values of `κ` with more integrals are
/// exactly those where `Q e^{2iκθ}` lies in the space, `2κ` an integer of size ≤ 2 (`κ = 0` the
/// harmonic rotor), each with two more integrals and functional rank 4 against 3; every other
/// root is rational and holds nothing, so no other value has more.
#[test]
fn gyroscopic_rotor_exceptional_kappa_are_where_twice_kappa_is_an_integer() {
    let out = normalize(&expect(
        "gyroscopic-rotor-values-kappa",
        &[
            "For a generic κ (searched at κ = 7, no root): 7 integrals (section 2), of functional rank 3.",
            "Every root of the determinants is rational: no other value of κ has more integrals \
             in this space.",
        ],
    ));
    let order = 2;
    let values: Vec<String> = (-order..=order)
        .map(|twice| match twice {
            t if t % 2 == 0 => format!("{}", t / 2),
            t => format!("{t}/2"),
        })
        .map(|v| v.replace('-', "−"))
        .collect();
    for value in &values {
        assert!(
            out.contains(&format!("at κ = {value}, 9 integrals")),
            "no κ = {value} in:\n{out}"
        );
    }
    let listed = out.matches(", 9 integrals (section").count();
    assert_eq!(listed, values.len(), "{out}");
    assert!(
        !out.contains("Roots of the determinants where the search finds no more"),
        "{out}"
    );
}

/// Section 33: at `κ = 1/2` the parts `C1`, `C2` of `Q e^{iθ}` close with `L` in su(2), `p_θ`
/// turns them at half `L`'s rate, and `|Q|² = 4 H_osc² − 4ω² L²` is their one relation.
#[test]
fn gyroscopic_rotor_closes_su2_at_half_kappa() {
    expect(
        "gyroscopic-rotor-closure",
        &[
            "{L, C1} = 2 C2 at κ = 1/2 [B1 proved]",
            "{p_θ, C1} = C2 at κ = 1/2 [B3 proved]",
            "{C1, C2} = 8ω² L at κ = 1/2 [B5 proved]",
            "4ω² L² + C1² + C2² = 4 H_osc² at κ = 1/2 [R1 proved]",
        ],
    );
}

/// Section 33: on the level set `Ω = 1` at `κ = 1/2` the circular modes turn at `ω ∓ 1/2`
/// against the rotor's 1, and the resonant `ω` are the harmonic rotor's shifted by `±κΩ`:
/// `±1/2, ±1, ±3/2, ±5/2` at degree 2, each of rank 4 on the 5 dimensions (maximal).
#[test]
fn gyroscopic_rotor_resonances_shift_with_kappa() {
    let out = normalize(&expect(
        "gyroscopic-rotor-resonances",
        &[
            "For a generic ω (searched at ω = 7, no root): 6 integrals (section 2), of functional rank 3.",
            "Roots of the determinants where the search finds no more integrals: ω = 0.",
        ],
    ));
    for value in ["−5/2", "−3/2", "−1", "−1/2", "1/2", "1", "3/2", "5/2"] {
        assert!(
            out.contains(&format!("at ω = {value}, ")),
            "no ω = {value} in:\n{out}"
        );
    }
    assert_eq!(out.matches("of functional rank 4").count(), 8, "{out}");
}

/// The file's integrals hold at their cases and at no neighbour: each claim proved, each
/// false neighbour refuted with its residual.
#[test]
fn quartic_potentials_integrals_hold_at_their_cases_alone() {
    let out = normalize(&superint_ok(&[
        "check",
        "systems/quartic-potentials.toml",
        "--no-timings",
    ]));
    for proved in [
        "{L, H} = 0 at a = 2, b = 1 [rotation proved]",
        "{H_x, H} = 0 at a = 0 [separable-cartesian proved]",
        "{S, H} = 0 at a = 6, b = 1 [separable-diagonal proved]",
        "{P, H} = 0 at a = 12, b = 16 [parabolic proved]",
        "{Q, H} = 0 at a = 6, b = 8 [quartic proved]",
        "{L, H} = 0 at a = 2, b = 2 [false-rotation refuted, as expected] \
         residual lhs − rhs = −4xy³",
        "{P, H} = 0 at a = 12, b = 15 [false-parabolic refuted, as expected] \
         residual lhs − rhs = 4xy³ p_x",
        "[false-quartic refuted, as expected]",
        "12 claims in 1 file: 6 proved, 6 refuted; all as expected",
    ] {
        assert!(out.contains(&normalize(proved)), "{proved}: {out}");
    }
}

/// The values of `I3` of the heavy top with more integrals of degree 4, from `H`, where `I3`
/// is a negative power (results.md §9): Kovalevskaya's `I3 = 1/2` (one more, `K`) and the
/// spherical `I3 = 1` (ten more); `I3 = 0`, where `H` has no value, no candidate.
#[test]
fn the_heavy_top_has_kovalevskaya_s_integral_at_i3_one_half_found_from_h_alone() {
    expect(
        "heavy-top-values",
        &[
            "For a generic I3 (searched at I3 = 7, no root): 10 integrals (section 2), of functional rank 3.",
            "More integrals at I3 = 1/2, 11 integrals (section 4), of functional rank 4 and at I3 = 1, 20 integrals (section 6), of functional rank 4.",
            "Roots of the determinants where the search finds no more integrals: I3 = 1/4, \
             I3 = 3/2, I3 = 2 and I3 = 4.",
            "I3 = 0, a root of the determinants, is no value: H, with a negative power of I3, \
             has none there",
            "J11 = M1⁴ + 2 M1² M2² + 4c M1² γ1 + 8c M1 M2 γ2 + M2⁴ − 4c M2² γ1 − 4c² γ3²",
            "= −4c² Γ + K",
        ],
    );
}

#[test]
fn henon_heiles_with_c_symbolic_has_only_the_energy() {
    // For C symbolic nothing but 1 and H is conserved: no quadratic integral holds for every C.
    expect(
        "hh-generic",
        &[
            "Over the polynomials in A, B, C, 2 of the 14 basis integrals, I1 and I11, generate all of them",
            "I1 = 1",
            "I11 = p_x² + p_y² + 2x²y + Ax² + 2Cy³ + By²",
            "3 claims: 3 proved, 0 refuted",
        ],
    );
}

/// `--known` splits at the commas between integrals, not inside an instance's braces
/// (`P_{1,1}` was cut into `P_{1` and `1}`).
#[test]
fn known_integrals_may_be_instances_with_braces() {
    let out = superint(&[
        "search",
        "systems/harmonic-rotor.toml",
        "--when",
        "p_theta = I*omega",
        "--momenta-degree",
        "2",
        "--positions-degree",
        "2",
        "--trig-degree",
        "2",
        "--new-only",
        "--known",
        "P_{1,1}, Q_{1,1}",
        "--no-timings",
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        stdout.contains("Known integrals in the space: H, L, G1, G2, P_{1,1}, Q_{1,1}."),
        "{stdout}"
    );
}

/// The built-in harmonic rotor takes its resonant functions as `systems/harmonic-rotor.toml`
/// writes the family's instances, `P_1_1` and `P_{1,1}`, besides its own name `P11` (which
/// alone it took: `unknown name 'P_1_1'; did you mean 'P11'?`), and shows them as the file
/// does, `P_{1,1}`: the same generator, the same closure.
#[test]
fn a_builtin_closure_takes_a_resonant_function_as_the_file_writes_it() {
    let closure = |p: &str| {
        crate::superint_ok(&[
            "closure",
            "--system",
            "harmonic",
            "L",
            p,
            "--when",
            "p_theta=I*omega",
            "--no-timings",
        ])
    };
    let own = closure("P11");
    assert!(
        own.contains("{L, P_{1,1}} = (p_y + Mωx) cos θ + (−p_x + Mωy) sin θ"),
        "{own}"
    );
    for written in ["P_1_1", "P_{1,1}"] {
        assert_eq!(closure(written), own, "closure of L, {written}");
    }
}

/// The built-in rotor under gravity takes its resonant functions as
/// `systems/gravity-rotor.toml` writes the instances of its family `Pp` (shown `P'`), `Pp_1_1`
/// and `Pp_{1,1}`, besides its own name `P11` (it took `P11` and `P'_{1,1}` alone: `unknown
/// name 'Pp_1_1'`), and its closure of them reads as the file's, line by line.
#[test]
fn a_builtin_closure_under_gravity_takes_a_resonant_function_as_the_file_writes_it() {
    let closure = |system: &[&str], p: &str| {
        let generators = ["L", p, "--when", "p_theta=I*omega", "--no-timings"];
        crate::superint_ok(&[&["closure"], system, &generators[..]].concat())
    };
    let own = closure(&["--system", "gravity"], "P11");
    assert!(
        own.starts_with("Closure of L, P'_{1,1} for the rotor under gravity at p_θ = Iω\n"),
        "{own}"
    );
    for written in ["Pp_1_1", "Pp_{1,1}"] {
        assert_eq!(
            closure(&["--system", "gravity"], written),
            own,
            "closure of L, {written}"
        );
    }
    assert_eq!(closure(&["systems/gravity-rotor.toml"], "Pp_1_1"), own);
}

/// A generator written as the closure prints it, `P'_{1,1}` under gravity, is that function on
/// the built-in and on the file: the prime was taken for an expression's character, and the
/// generator refused as "an expression, not the name of a function".
#[test]
fn a_closure_takes_a_generator_as_it_prints_it_with_a_prime() {
    let closure = |system: &[&str], p: &str| {
        let generators = ["L", p, "--when", "p_theta=I*omega", "--no-timings"];
        crate::superint_ok(&[&["closure"], system, &generators[..], &["--format", "json"]].concat())
    };
    for system in [
        &["--system", "gravity"][..],
        &["systems/gravity-rotor.toml"][..],
    ] {
        assert_eq!(
            closure(system, "P'_{1,1}"),
            closure(system, "Pp_1_1"),
            "{system:?}"
        );
    }
}

/// The built-in harmonic rotor prints its condition as `systems/harmonic-rotor.toml` prints
/// it, the value as it is written, `p_θ = Iω` (it printed the normal form, `p_θ = ωI`, the
/// order of its variables), and its resonant functions as the file its instances, `P_{1,1}`:
/// the closure of the same generators at the same condition reads the same, line by line.
#[test]
fn a_builtin_closure_reads_as_the_files() {
    let closure = |system: &[&str]| {
        let generators = ["L", "P_1_1", "--when", "p_theta=I*omega", "--no-timings"];
        crate::superint_ok(&[&["closure"], system, &generators[..]].concat())
    };
    let builtin = closure(&["--system", "harmonic"]);
    assert!(
        builtin.starts_with("Closure of L, P_{1,1} for the harmonic rotor at p_θ = Iω\n"),
        "{builtin}"
    );
    assert_eq!(builtin, closure(&["systems/harmonic-rotor.toml"]));
}

/// `--fix` reads a decimal as the fraction it writes, as plot's `--at` does: `M=0.5` was
/// refused as "'0.5' is not a rational number", which it is.
#[test]
fn a_fixed_value_may_be_a_decimal() {
    let search = |fix: &str| {
        let args = [
            "search",
            "systems/fokas-lagerstrom-1-3.toml",
            "--momenta-degree",
            "3",
            "--positions-degree",
            "3",
            "--fix",
            fix,
            "--no-timings",
        ];
        let o = superint(&args);
        assert_eq!(o.status.code(), Some(0), "{fix}");
        String::from_utf8(o.stdout).expect("UTF-8")
    };
    let decimal = search("M=0.5,omega=2.5e0");
    assert!(
        normalize(&decimal).contains("Parameters fixed for the linear algebra: M = 1/2, ω = 5/2"),
        "{decimal}"
    );
    assert_eq!(decimal, search("M=1/2,omega=5/2"));
}

#[test]
fn bad_search_arguments_exit_2_with_a_message() {
    for (args, message) in [
        (
            "--symbolic A,x",
            "--symbolic: 'x' is not a parameter of the system (its parameters: A, B, C)",
        ),
        (
            "--fix c=2",
            "--fix: 'c' is not a parameter of the system; did you mean 'C'? (its parameters: \
             A, B, C)",
        ),
        (
            "--symbolic A --fix A=2",
            "A is both fixed to a value and kept symbolic",
        ),
        (
            "--fix C=two",
            "--fix: 'two' is not a number: write a fraction such as 2/3, or a decimal such as 1.5",
        ),
        (
            "--fix C=3/0",
            "--fix: '3/0' is a division by zero: a fraction's denominator is nonzero",
        ),
        ("--fix A=2,B=1,A=3", "--fix: 'A' is given two values"),
        (
            "--when C=2 --fix C=3",
            "C is set by the condition; it can be neither fixed nor kept symbolic",
        ),
        (
            "--parameters-degree 3",
            "required arguments were not provided",
        ),
        (
            "--when C=i --trig-degree 0",
            // Refused for every command, where the condition is read.
            "<command line>:1:3: the condition sets C to i, which is not real",
        ),
        (
            "--positions-degree 4 --trig-degree 0 --symbolic A,B --max-terms 500",
            "the space has 540 unknowns, more than the term limit 500",
        ),
        // A known integral that is none was left out without a word. It is named as the
        // file prints an expression, which reads back.
        (
            "--positions-degree 2 --trig-degree 0 --new-only --known x*p_y",
            "<command line>:1:1: --known: x p_y is not an integral: {x p_y, H} = ",
        ),
        (
            "--positions-degree 2 --trig-degree 0 --new-only --known x+i*p_x",
            "<command line>:1:1: --known: x + i p_x is not real: give its real and imaginary \
             parts, re(x + i p_x) and im(x + i p_x)",
        ),
    ] {
        let mut words = vec!["search", "systems/henon-heiles.toml"];
        words.extend(args.split_whitespace());
        let out = superint(&words);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args}: {stderr}");
        assert!(stderr.contains(message), "{args}: {stderr}");
    }
}

/// `--fix a=0` is refused for a parameter that a radicand holds: the two centres' radicands
/// coincide at `a = 0`, and the radicals are taken as independent.
#[test]
fn fixing_a_radicands_parameter_at_zero_is_refused() {
    let out = superint(&["search", "systems/two-centres.toml", "--fix", "a=0"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        "superint: error: <command line>:1:3: --fix: a = 0: the radicand of r = √(x² − 2ax + y² \
         + z² + a²) holds a, and at a = 0 it may be a square or another radicand, while the \
         radicals are taken as independent: give a another value\n 1 | a=0\n   |   ^\n"
    );
}

/// Zero is a value as any other for `--fix`, where `H` has one: the Goryachev–Chaplygin top's
/// `c = 0`, which `--find-values c --on 'A = 0'` reports, searched by hand as the docs say
/// each value is (`--fix c=0 --on 'A = 0'`), finds the free top's `M3` (nothing lifted back
/// to `c`); `H = … + M3²/(2 I3)` of the heavy top has no value at `I3 = 0`, which is refused.
#[test]
fn a_parameter_is_fixed_at_zero_where_h_has_a_value() {
    let found = superint_ok(&[
        "search",
        "systems/goryachev-chaplygin-top.toml",
        "--fix",
        "c=0",
        "--on",
        "A = 0",
        "--poisson-degree",
        "2",
    ]);
    assert!(
        found.contains("Parameters fixed for the linear algebra: c = 0"),
        "{found}"
    );
    assert!(found.contains("{I2, H} = 0 at c = 0"), "{found}");
    assert!(found.contains("    I2 = M3\n"), "{found}");
    let stderr = superint_refused(&["search", "systems/heavy-top.toml", "--fix", "I3=0"]);
    let why = "--fix: I3 = 0: H divides by I3, so it has no value at I3 = 0: give I3 another value";
    assert!(stderr.contains(why), "{stderr}");
}

/// A known integral that divides by a declared denominator zero at the fixed values has no
/// value there: `F1` of the Neumann system, an integral for distinct `a_i`, was refused as
/// 'not an integral: … at a1 = 1, a2 = 1', a bracket taken where it divides by zero; it is
/// refused saying so, at the values used.
#[test]
fn a_known_integral_with_no_value_at_the_fixed_values_is_refused_saying_so() {
    let neumann = "systems/neumann.toml";
    let args = |fix| {
        [
            "search",
            neumann,
            "--new-only",
            "--known",
            "F1",
            "--fix",
            fix,
        ]
    };
    let stderr = superint_refused(&args("a1=1,a2=1"));
    assert!(
        stderr.contains(
            "<command line>:1:1: --known: F1 has no value where it is searched: the denominator \
             (a1 − a2) is zero at a1 = 1, a2 = 1, the values the linear algebra takes"
        ),
        "{stderr}"
    );
    assert!(!stderr.contains("not an integral"), "{stderr}");
    // Where it has a value it is an integral, and the search runs.
    let found = superint_ok(&args("a1=1,a2=2"));
    assert!(found.contains("a1 = 1, a2 = 2"), "{found}");
}

/// A negative fixed value prints its sign as the conditions do, `M = −1` in text and markdown
/// (it was `M = -1` beside `at ω = −1`), and stays ASCII in JSON, which is read back.
#[test]
fn a_negative_fixed_value_prints_as_a_condition_does() {
    let args = [
        &[
            "search",
            "systems/harmonic-rotor.toml",
            "--fix",
            "M=-1,omega=-2/3",
        ][..],
        &DEGREE_ONE_TRIG_ZERO,
    ]
    .concat();
    let (json, text) = json_and_text(&args);
    assert!(
        normalize(&text)
            .contains("Parameters fixed for the linear algebra: M = −1, ω = −2/3, I = 1;"),
        "{text}"
    );
    assert_eq!(json["searches"][0]["parameters"]["fixed"][0]["value"], "-1");
}

/// A parameter set by the condition takes the condition's value: `--when 'C = 2'` finds what
/// `--fix C=2` finds (it was fixed to 1 first, and the search ran at `C = 1`).
#[test]
fn a_parameter_set_by_the_condition_is_not_fixed_first() {
    let file = system_file("henon-heiles.toml");
    let vars = file.system().vars();
    let var = |name: &str| vars.lookup(name).expect("a parameter");
    let space = SearchSpace::default()
        .momenta_degree(2)
        .positions_degree(4)
        .parameters_degree(2);
    let symbolic = SearchOptions::new(space)
        .symbolic(var("A"))
        .symbolic(var("B"));
    let two = || Expr::constant(vars, trigpoly::GaussianRational::from(2));
    let by_condition = search(
        file.system(),
        &symbolic
            .clone()
            .when(brackets::Condition::new("C = 2", var("C"), two())),
    )
    .expect("the search runs");
    let by_value =
        search(file.system(), &symbolic.fix(var("C"), Rational::from(2))).expect("the search runs");
    let generators = |r: &brackets::search::SearchResult| -> Vec<String> {
        let module = r.module.as_ref().expect("parameters kept symbolic");
        module
            .generators
            .iter()
            .map(|&i| r.basis[i].expr().to_string())
            .collect()
    };
    assert!(by_condition.parameters.is_empty());
    assert_eq!(generators(&by_condition), generators(&by_value));
    assert_eq!(generators(&by_condition).len(), 3);
}

#[test]
fn henon_heiles_separable_and_quartic_cases_for_every_a() {
    let file = system_file("henon-heiles.toml");
    // The command prints the integral `label` as the file states `function`.
    let prints = |command: &str, pieces: &[&str], label: &str, function: &str| {
        let out = normalize(&expect(command, pieces));
        let f = file.parse_argument(function).expect("parses").to_string();
        assert!(
            out.contains(&format!("{label} = {}", normalize(&f))),
            "{out}"
        );
    };
    prints(
        "hh-separable",
        &[
            "Over the polynomials in A, 3 of the 7 basis integrals, I1, I4 and I5, generate all of them",
            "{I4, H} = 0 at B = A, C = 1/3",
        ],
        "I4",
        "S",
    );
    prints(
        "hh-quartic",
        &[
            "Over the polynomials in A, 4 of the 7 basis integrals, I1, I4, I6 and I7, generate all of them",
            "{I6, H} = 0 at B = 16A, C = 16/3",
        ],
        "I6",
        "Q",
    );
    expect(
        "hh-quartic-new",
        &[
            "Known integrals in the space: H, Q.",
            "the generated ones span the whole space (7 dimensions).",
            "None: the known integrals generate every integral in the space.",
        ],
    );
}

/// A search with parameters kept symbolic says which of the basis integrals generate all of
/// them, by their labels, in every format and in JSON's `generators`: with `--new-only` too,
/// which shows none of them, the labels are those of the generators the same search without
/// it shows (`I1, I4, I6 and I7` of the quartic Hénon–Heiles case); a search with none kept
/// symbolic has `"generators": null`.
#[test]
fn a_symbolic_search_names_the_integrals_that_generate_the_others() {
    let labels = ["I1", "I4", "I6", "I7"];
    let command = |name: &str| {
        let c = COMMANDS.iter().find(|c| c.0 == name).unwrap().1;
        let mut args: Vec<String> = words(c).into_iter().skip(1).collect();
        args.push("--no-timings".into());
        args
    };
    let shown = |args: &[String], format: &str| {
        let mut args: Vec<&str> = args.iter().map(String::as_str).collect();
        args.extend(["--format", format]);
        normalize(&superint_ok(&args))
    };
    let all = command("hh-quartic");
    let new_only = command("hh-quartic-new");
    for args in [&all, &new_only] {
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        let json = superint_json(&refs);
        let search = &json["searches"][0];
        assert_eq!(search["generators"], serde_json::json!(labels), "{search}");
        let shown_ids = match args == &all {
            true => serde_json::json!(labels),
            false => serde_json::json!([]),
        };
        assert_eq!(search["shown"], shown_ids, "{search}");
        for (format, names) in [
            ("text", "I1, I4, I6 and I7"),
            ("markdown", "`I1`, `I4`, `I6` and `I7`"),
            ("latex", "$I_{1}$, $I_{4}$, $I_{6}$ and $I_{7}$"),
        ] {
            let out = shown(args, format);
            let said = format!("4 of the 7 basis integrals, {names}, generate all of them");
            assert!(out.contains(&said), "{format}: {out}");
        }
    }
    let plain = superint_json(
        &[
            &["search", "systems/harmonic-rotor.toml"][..],
            &DEGREE_ONE_TRIG_ZERO,
        ]
        .concat(),
    );
    assert_eq!(plain["searches"][0]["generators"], serde_json::Value::Null);
}

/// The Kepler problem in polar coordinates: the search finds the Laplace–Runge–Lenz vector
/// among the integrals quadratic in the momenta, in the file's own variables, with `p_φ` (no
/// condition fixes it) among the momenta; to degree 6 everything is generated by `H, L, A`;
/// the closure finds so(3) and the length of `A`.
#[test]
fn kepler_laplace_runge_lenz_and_nothing_else() {
    expect(
        "kepler",
        &[
            // The Kepler problem's parameter is `k`: the trigonometric order takes `j`.
            "The space: r^a p_r^b p_φ^c times 1, cos jφ, sin jφ, with momenta degree b + c ≤ 2, \
             positions degree |a| ≤ 2 (negative powers of the coordinates allowed), \
             trigonometric order j ≤ 1: 90 unknowns",
            "Dimension of the space of integrals: 6.",
            "I2 = p_φ",
            "I4 = p_r² + p_φ²/r² − 2Mk/r",
            "I5 = (p_φ²/r − Mk) cos φ + p_r p_φ sin φ",
            "I6 = −p_r p_φ cos φ + (p_φ²/r − Mk) sin φ",
            "Those of trigonometric order j > 0 as I = Re(A e^{−ijφ})",
            "6 claims: 6 proved, 0 refuted",
        ],
    );
    let new = expect(
        "kepler-new-6",
        &[
            "Dimension of the space of integrals: 44. By degree in the momenta: ≤ 0: 1, ≤ 1: 2, \
             ≤ 2: 6, ≤ 3: 10, ≤ 4: 19, ≤ 5: 28, ≤ 6: 44.",
            "Known integrals in the space: H, L, A_x, A_y.",
            "the generated ones span the whole space (44 dimensions).",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    assert!(!new.contains("left out"), "{new}");
    expect(
        "kepler-closure",
        &[
            "{L, A_x} = A_y",
            "{L, A_y} = −A_x",
            "{A_x, A_y} = −2 H L/M",
            "Mk² + 2 H L² = M A_x² + M A_y²",
        ],
    );
}

/// An angle's momentum is left out of the space only when the condition fixes it: without a
/// condition, `p_θ` is an integral of the harmonic rotor that the search finds.
#[test]
fn an_angle_momentum_is_left_out_only_when_fixed() {
    let f = "systems/harmonic-rotor.toml";
    let output = |args: &[&str]| {
        let out = superint(&[args, &DEGREE_ONE, &["--no-timings"]].concat());
        assert_eq!(out.status.code(), Some(0));
        String::from_utf8(out.stdout).expect("UTF-8")
    };
    let free = output(&["search", f]);
    assert!(
        normalize(&free).contains("with momenta degree c + d + e ≤ 1"),
        "{free}"
    );
    assert!(free.contains("\n    J2 = p_θ\n"), "{free}");
    assert!(!free.contains("left out"), "{free}");
    let fixed = output(&["search", f, "--when", "p_theta = I*omega"]);
    let flat = normalize(&fixed);
    assert!(flat.contains("with momenta degree c + d ≤ 1"), "{fixed}");
    assert!(
        flat.contains("p_θ is left out: the condition fixes it"),
        "{fixed}"
    );
    assert!(!fixed.contains("= p_θ\n"), "{fixed}");
}

/// The space is described in the file's own variables, its exponent letters none of their
/// names: two coupled rotors with angles `a`, `b` (so the exponents start at `c`) conserve the
/// total angular momentum.
#[test]
fn the_space_is_described_in_the_files_variables() {
    let file = scratch_system("two-rotors", "p_a^2/2 + p_b^2/2 + cos(a - b)", "a, b");
    let out = superint(&[
        "search",
        &file,
        "--momenta-degree",
        "1",
        "--positions-degree",
        "0",
        "--trig-degree",
        "1",
        "--no-timings",
    ]);
    assert_eq!(out.status.code(), Some(0));
    let out = String::from_utf8(out.stdout).expect("UTF-8");
    assert!(
        normalize(&out).contains(
            "The space: p_a^c p_b^d times 1, cos(k_1 a + k_2 b), sin(k_1 a + k_2 b), with \
             momenta degree c + d ≤ 1, trigonometric order |k_1| + |k_2| ≤ 1: 15 unknowns"
        ),
        "{out}"
    );
    assert!(out.contains("\n    I2 = p_a + p_b\n"), "{out}");
    assert!(
        out.contains("Dimension of the space of integrals: 2."),
        "{out}"
    );
}

/// A system file in a scratch directory, named `name`, with Hamiltonian `h` and the
/// comma-separated `angles`; its path.
fn scratch_system(name: &str, h: &str, angles: &str) -> String {
    let angles: Vec<String> = angles.split(", ").map(|a| format!("{a:?}")).collect();
    let text = format!(
        "name = {name:?}\nhamiltonian = {h:?}\n[phase_space]\nangles = [{}]\n",
        angles.join(", ")
    );
    let file = crate::scratch_text("discovery", &format!("{name}.toml"), &text);
    file.to_str().expect("a UTF-8 path").to_string()
}

/// The titles of `search` and `closure`, and the closure's table, say a system's name as
/// `check` does: `of the pendulum`, but `of my pendulum` (they said `of the my pendulum`), and
/// a file that names no system by its stem alone, `of t1` (they said `of the t1`).
#[test]
fn search_and_closure_titles_keep_a_names_own_article() {
    let pendulum = "hamiltonian = \"p_t^2/2 - cos(t)\"\n[phase_space]\nangles = [\"t\"]\n";
    let file = |stem: &str, text: &str| {
        let path = crate::scratch_text("discovery", &format!("{stem}.toml"), text);
        path.to_str().expect("a UTF-8 path").to_string()
    };
    for (file, name) in [
        (
            scratch_system("my pendulum", "p_t^2/2 - cos(t)", "t"),
            "my pendulum",
        ),
        (
            file("p1", &format!("name = \"pendulum\"\n{pendulum}")),
            "the pendulum",
        ),
        (file("t1", pendulum), "t1"),
    ] {
        for (args, title, table) in [
            (
                vec!["search", &file, "--trig-degree", "1"],
                format!("Integrals of {name}\n"),
                None,
            ),
            (
                vec!["closure", &file, "H"],
                format!("Closure of H for {name}\n"),
                Some(format!("{{A, B}} for {name} (row A, column B)\n")),
            ),
        ] {
            let out = superint(&args);
            let text = String::from_utf8(out.stdout).expect("UTF-8");
            assert_eq!(out.status.code(), Some(0), "{args:?}");
            assert!(text.starts_with(&title), "{text}");
            assert!(table.is_none_or(|t| text.contains(&t)), "{text}");
        }
    }
}

/// The search finds the real integrals of a real Hamiltonian: a complex one is refused (the
/// pendulum `p_t²/2 − e^{it}` gave `p_t² − 4 cos t` as an integral, which the proof refuted).
#[test]
fn a_complex_hamiltonian_is_refused() {
    let file = scratch_system("complex-pendulum", "p_t^2/2 - exp(i*t)", "t");
    let out = superint(&["search", &file, "--trig-degree", "1"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains(
            "the search finds the real integrals of a real Hamiltonian, and H is not real"
        ),
        "{stderr}"
    );
    // Its real part is searched as usual: the energy.
    let file = scratch_system("real-pendulum", "p_t^2/2 - cos(t)", "t");
    let out = superint(&["search", &file, "--trig-degree", "1", "--no-timings"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stdout).contains("    I2 = p_t² − 2 cos t\n"));
}

/// A closure whose results cannot be lifted back to the parameters says where they hold: at
/// the fixed values, in the statement, the table's caption and the JSON's condition. Here
/// `T = b x p_x + a y p_y` mixes the parameters so that no weights make the generators
/// homogeneous; `{U, V} = 4a³x p_x = 4a²W`, which at `a = 1` is the `4W` found, and it was
/// printed as `{U, V} = 4W` under a header that said the coefficients were lifted.
#[test]
fn a_closure_that_cannot_lift_says_where_it_holds() {
    let file = crate::scratch_text(
        "discovery",
        "unliftable.toml",
        r#"name = "unliftable"
hamiltonian = "p_x^2/2 + p_y^2/2"
[phase_space]
coordinates = ["x", "y"]
parameters = ["a", "b"]
[[function]]
name = "U"
value = "a^2*x^2"
[[function]]
name = "V"
value = "a*p_x^2"
[[function]]
name = "W"
value = "a*x*p_x"
[[function]]
name = "T"
value = "b*x*p_x + a*y*p_y"
"#,
    );
    let file = file.to_str().expect("a UTF-8 path");
    let args = ["closure", file, "U", "V", "W", "T", "--no-timings"];
    let o = superint(&args);
    assert_eq!(o.status.code(), Some(0));
    let out = String::from_utf8(o.stdout).expect("UTF-8");
    assert!(
        crate::normalize(&out).contains(
            "could not be lifted, and hold at a = 1, b = 1 only (so does the table; \
             --symbolic a,b keeps the parameters symbolic, for every value)"
        ),
        "{out}"
    );
    assert!(
        out.contains("{A, B} for unliftable at a = 1, b = 1 (row A, column B)\n"),
        "{out}"
    );
    assert!(out.contains("  {U, V} = 4 W at a = 1, b = 1 "), "{out}");
    let mut json_args = args.to_vec();
    json_args.extend(["--format", "json"]);
    let o = superint(&json_args);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let claims = v["claims"].as_array().expect("claims");
    let uv = claims
        .iter()
        .find(|c| c["statement"] == "{U, V} = 4 W")
        .expect("{U, V}");
    assert_eq!(uv["condition"], "a = 1, b = 1");
    assert_eq!(uv["condition_ascii"], "a = 1, b = 1");
    // Every bracket is its own claim, B1, B2, …, as the relations are R1, R2, …
    let ids: Vec<&str> = claims.iter().filter_map(|c| c["id"].as_str()).collect();
    assert_eq!(v["summary"]["claims"].as_u64(), Some(ids.len() as u64));
    assert!(ids.contains(&"B1") && ids.contains(&"R1"), "{ids:?}");
}

/// A potential in an angle fixes its parameter's weight: for the pendulum `p_t²/2 − g cos t`
/// the energy found at `g = 1` is lifted to `p_t² − 2g cos t` and proved for every `g` (the
/// weights left out `∂H/∂t`, so `g` had none and the energy held "at g = 1 only").
#[test]
fn a_pendulums_energy_is_lifted_to_its_parameter() {
    let file = crate::scratch_text("discovery", "pendulum.toml", crate::PENDULUM);
    let o = superint(&["search", file.to_str().expect("UTF-8"), "--no-timings"]);
    assert_eq!(o.status.code(), Some(0));
    let out = String::from_utf8(o.stdout).expect("UTF-8");
    assert!(out.contains("I2 = p_t² − 2g cos t\n"), "{out}");
    assert!(out.contains("  {I2, H} = 0  "), "{out}");
    assert!(!out.contains("no symbolic lift"), "{out}");
}

/// A search whose space cannot hold `H` says so, and why: the Smorodinsky–Winternitz
/// potential's `β/x²` needs `--laurent` (without it the search found only the constants, with
/// no hint), and the momenta degree 1 cannot hold the kinetic energy; a space that holds `H`
/// says nothing of it.
#[test]
fn a_search_says_when_h_is_outside_its_space() {
    let sw = "systems/smorodinsky-winternitz-i.toml";
    let space = [
        "--momenta-degree",
        "2",
        "--positions-degree",
        "4",
        "--trig-degree",
        "0",
    ];
    let out = superint(&[&["search", sw][..], &space].concat());
    let text = normalize(&String::from_utf8(out.stdout).expect("UTF-8"));
    assert!(
        text.contains(
            "Note: H is not in this space (negative powers of x, which a Laurent space \
             (SearchSpace::laurent; on the command line, --laurent) admits)"
        ),
        "{text}"
    );
    let out = superint(&[&["search", sw, "--laurent"][..], &space].concat());
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    assert!(!text.contains("H is not in this space"), "{text}");
    let out = superint(&[
        "search",
        "systems/harmonic-rotor.toml",
        "--when",
        "p_theta = I*omega",
        "--momenta-degree",
        "1",
        "--positions-degree",
        "2",
        "--trig-degree",
        "1",
    ]);
    let text = normalize(&String::from_utf8(out.stdout).expect("UTF-8"));
    assert!(
        text.contains("(degree 2 in the momenta, past the space's 1)"),
        "{text}"
    );
}

/// `search` and `closure` on a file read `--when` as the file's own conditions are read: as
/// written (`p_θ = Iω`; it printed the normal form `ωI`), and a mistake is located in it.
#[test]
fn search_and_closure_read_conditions_as_files_do() {
    let rotor = "systems/harmonic-rotor.toml";
    let when = ["--when", "p_theta = I*omega"];
    let out = superint(&[&["search", rotor][..], &when, &DEGREE_ONE].concat());
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    assert!(
        text.starts_with("Integrals of the harmonic rotor at p_θ = Iω\n"),
        "{text}"
    );
    let out = superint(&[&["closure", rotor, "L", "G1"][..], &when].concat());
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    assert!(
        text.starts_with("Closure of L, G1 for the harmonic rotor at p_θ = Iω\n"),
        "{text}"
    );
    let out = superint(&["search", rotor, "--when", "p_theta = I*omeg"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).expect("UTF-8");
    assert!(
        err.starts_with("superint: error: <command line>:1:13: unknown name 'omeg'"),
        "{err}"
    );
}

/// A condition must describe a surface the flow keeps: there a function whose bracket with
/// `H` vanishes is an integral. On `y = 0` of the Hénon–Heiles system the flow leaves at once
/// (`ẏ = p_y`), and the search reported `p_x² + x²` as an integral "proved at y = 0"; a rotor
/// whose coupling turns `p_θ` (`{p_θ, H} ≠ 0`) gave a false integral at `p_θ = Iω`. Both are
/// refused, by search and closure alike, at the value of the variable whose level the flow
/// leaves in --when (it was said at no place); the resonance of the harmonic rotor is kept.
#[test]
fn a_condition_the_flow_leaves_is_refused() {
    let leaves = [
        (
            vec!["systems/henon-heiles.toml", "--when", "y = 0"],
            "the flow leaves the surface y = 0: there {y, H} = p_y, not 0",
        ),
        (
            vec!["systems/harmonic-rotor.toml", "--when", "x = y"],
            "the flow leaves the surface x = y: there {x − y, H} = p_x/M − p_y/M, not 0",
        ),
    ];
    for (args, message) in leaves {
        for command in ["search", "closure"] {
            let mut words = vec![command];
            words.extend(&args);
            if command == "closure" {
                words.push("H");
            }
            let out = superint(&words);
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{words:?}: {stderr}");
            let at = format!("superint: error: <command line>:1:5: {message}");
            assert!(stderr.starts_with(&at), "{words:?}: {stderr}");
            assert!(stderr.ends_with("\n   |     ^\n"), "{words:?}: {stderr}");
        }
    }
    let coupled = scratch_system(
        "coupled-rotors",
        "p_theta^2/2 + p_phi^2/2 + cos(theta - phi)",
        "theta, phi",
    );
    let out = superint(&[
        "search",
        &coupled,
        "--when",
        "p_theta = 1",
        "--momenta-degree",
        "1",
        "--trig-degree",
        "1",
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("the flow leaves the surface p_θ = 1"),
        "{stderr}"
    );
    // Where p_θ is conserved, its level is a surface the flow keeps.
    let out = superint(
        &[
            &[
                "search",
                "systems/harmonic-rotor.toml",
                "--when",
                "p_theta = I*omega",
            ],
            &DEGREE_ONE[..],
        ]
        .concat(),
    );
    assert_eq!(out.status.code(), Some(0));
}

/// A parameter set to a function of phase space is a surface like a variable's, refused where
/// the flow leaves it: at `a = p_x` the linear potential `p_x²/2 + ax` was searched, and
/// `p_x + x`, whose bracket `p_x − a` vanishes there, was reported an integral (and `H`, which
/// is one, was missed). A parameter set to a function the flow keeps (`ω = p_θ/I`) is kept.
#[test]
fn a_parameter_set_to_a_function_the_flow_changes_is_refused() {
    let file = crate::scratch_text(
        "discovery",
        "linear-potential.toml",
        "hamiltonian = \"p_x^2/2 + a*x\"\n[phase_space]\ncoordinates = [\"x\"]\n\
         parameters = [\"a\"]\n",
    );
    let file = file.to_str().expect("a UTF-8 path");
    for command in ["search", "closure"] {
        let mut args = vec![command, file, "--when", "a = p_x"];
        if command == "closure" {
            args.push("H");
        }
        let out = superint(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.contains(
                "the flow leaves the surface a = p_x: there {a − p_x, H} = p_x, not 0, so what \
                 is conserved on it is no integral; a condition may set parameters to \
                 constants, and variables the flow keeps"
            ),
            "{args:?}: {stderr}"
        );
    }
    let out = superint(&[
        "closure",
        "systems/harmonic-rotor.toml",
        "L",
        "--when",
        "omega = p_theta/I",
    ]);
    assert_eq!(out.status.code(), Some(0));
}

/// A long value of a condition, refused as not real or as a surface the flow leaves, is shown
/// by its first terms and its size, with the flow's rate: the messages were 1.4 MB and 0.7 MB.
#[test]
fn a_long_condition_value_is_shown_by_its_first_terms() {
    let rotor = "systems/harmonic-rotor.toml";
    for (args, size) in [
        (
            vec!["expand", rotor, "p_x", "--when", "p_theta = K_40_1"],
            "… (a polynomial of 12341 terms), which is not real",
        ),
        (
            vec!["search", rotor, "--when", "p_theta = (1+y+p_x+p_y)^30"],
            "+ … (a polynomial of 5456 terms)), H} = 12180Mω²xy²⁷ p_x² + 870Mω²xy²⁸ p_x \
             + 870Mω²xy²⁸ p_y + 30Mω²xy²⁹ + 870Mω²xy²⁸ + … (a polynomial of 14880 terms), not 0",
        ),
    ] {
        let out = superint(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(stderr.len() < 1000, "{args:?}: {} bytes", stderr.len());
        assert!(stderr.contains(size), "{args:?}: {stderr}");
    }
}

/// A condition that sets to 0 a parameter that the Hamiltonian (for `search`) or a generator
/// (for `closure`) divides by is refused by saying which and by what: it said only `division
/// by zero`, without the name or the function. It is shown at the value that sets it in
/// --when, with what to do, as every other refusal of the condition is, for `expand`,
/// `bracket` and `rank` too, and for a built-in system: it was said at no place
/// (`<command line>: the condition sets γ3 = 0, but the expression divides by γ3`).
#[test]
fn a_condition_that_makes_a_divisor_zero_says_which() {
    let f = "systems/harmonic-rotor.toml";
    let refusal = |what: &str| {
        format!(
            "superint: error: <command line>:1:18: the condition sets M = 0, but {what} divides \
             by M: give M a value other than 0, or leave it free\n 1 | omega = 1/2, M = 0\n   \
             |                  ^\n"
        )
    };
    let when = ["--when", "omega = 1/2, M = 0"];
    let cases = [
        (vec!["search", f], "the Hamiltonian"),
        (vec!["search", "--system", "harmonic"], "the Hamiltonian"),
        (vec!["closure", f, "L", "G1"], "the generator G1"),
        (
            vec!["closure", "--system", "harmonic", "L", "G1"],
            "the generator G1",
        ),
        (
            vec!["closure", f, "L", "--define", "A = x/M"],
            "the generator A",
        ),
        (vec!["expand", f, "x", "x/M"], "the expression"),
        (vec!["bracket", f, "x/M", "p_x"], "the expression"),
        (vec!["rank", f, "L", "x/M"], "a function"),
    ];
    for (args, what) in cases {
        let args = [&args[..], &when[..]].concat();
        assert_eq!(superint_refused(&args), refusal(what), "{args:?}");
    }
    // A generator free of 1/M is defined there: the closure of L alone goes on.
    let out = superint(&[
        "closure",
        "systems/harmonic-rotor.toml",
        "L",
        "--when",
        "M = 0",
    ]);
    assert_eq!(out.status.code(), Some(0));
}

/// A search whose basis holds only at the fixed values says how to see the general case: the
/// Garnier system at `a = b = 1` is isotropic and has `x p_y − y p_x`, which it loses for
/// `a ≠ b`.
#[test]
fn an_unlifted_search_says_how_to_see_every_value() {
    let file = crate::scratch_text(
        "discovery",
        "garnier.toml",
        "name = \"Garnier\"\nhamiltonian = \"(p_x^2 + p_y^2)/2 + (x^2 + y^2)^2 + a*x^2 + b*y^2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\", \"b\"]\n",
    );
    let file = file.to_str().expect("a path");
    let degrees = [
        "--momenta-degree",
        "2",
        "--positions-degree",
        "4",
        "--trig-degree",
        "0",
    ];
    let search = |extra: &[&str]| {
        let out = superint(&[&["search", file][..], &degrees, extra, &["--no-timings"]].concat());
        assert_eq!(out.status.code(), Some(0));
        normalize(&String::from_utf8(out.stdout).expect("UTF-8"))
    };
    let at_one = search(&[]);
    assert!(at_one.contains("I2 = x p_y − y p_x"), "{at_one}");
    assert!(
        at_one.contains(
            "keep them symbolic (--symbolic a,b), or compare with other values (--fix a=2,b=3)"
        ),
        "{at_one}"
    );
    let general = search(&["--symbolic", "a,b"]);
    assert!(!general.contains("x p_y − y p_x"), "{general}");
    assert!(!general.contains("keep them symbolic"), "{general}");
    assert!(
        general.contains(
            "Dimension of the space of integrals over Q (a parameter's multiple of an integral \
             counts apart from it):"
        ),
        "{general}"
    );
    // Q is a formula here as in the space's sentence (`over $Q$`), not text beside it.
    let latex = search(&["--symbolic", "a,b", "--format", "latex"]);
    assert!(latex.contains("linear equations over $Q$"), "{latex}");
    assert!(
        latex.contains("integrals over $Q$ (a parameter's multiple"),
        "{latex}"
    );
}

/// A generator written as an expression is sent to `--define`, with a name the system does not
/// have: `2*L` failed as "2_L" cannot name a variable, and `L*G1` beside `L+G1` as `L_G1` named
/// twice, names the user never wrote.
#[test]
fn closure_sends_an_expression_generator_to_define() {
    for (file, generator, message) in [
        (
            "systems/harmonic-rotor.toml",
            "2*L",
            "superint: error: <command line>:1:1: '2*L' is an expression, not the name of a function: name it with \
             --define (--define 'G=2*L', then G among the generators)\n 1 | 2*L\n   | ^^^\n",
        ),
        (
            "systems/two-centres.toml",
            "Lx+G",
            "superint: error: <command line>:1:1: 'Lx+G' is an expression, not the name of a function: name it with \
             --define (--define 'X=Lx+G', then X among the generators)\n 1 | Lx+G\n   | ^^^^\n",
        ),
    ] {
        let args = ["closure", file, generator, "H"];
        assert_eq!(superint_refused(&args), message, "{args:?}");
    }
    // Names with braces, Greek letters and subscripts are names.
    let out = superint(&[
        "closure",
        "systems/harmonic-rotor.toml",
        "K_{1,1}",
        "p_θ",
        "Ω",
    ]);
    assert_eq!(out.status.code(), Some(0));
}

/// A `--define` whose value uses another defined name, or its own, says so, with the caret
/// under that name: it was refused as an unknown name with the hint to declare a
/// `[[function]]` in the file.
#[test]
fn closure_says_a_definition_cannot_use_another() {
    for (defines, message) in [
        (
            ["Y=L", "X=Y^2"],
            "superint: error: <command line>:1:3: --define: Y is given by --define, whose values \
             use only the system's names: write its value, (L), in its place\n 1 | X=Y^2\n   |   \
             ^\n",
        ),
        (
            ["X={X, L}", "Y=L"],
            "superint: error: <command line>:1:4: --define: its value uses X, the name it \
             defines\n 1 | X={X, L}\n   |    ^\n",
        ),
    ] {
        let args = [
            "closure",
            "systems/harmonic-rotor.toml",
            "L",
            "--define",
            defines[0],
            "--define",
            defines[1],
        ];
        assert_eq!(superint_refused(&args), message, "{args:?}");
    }
}

/// A parameter that the condition sets is neither fixed nor kept symbolic by `closure`, as by
/// `search`: `--fix beta=3` beside `--when 'beta = 1'` was taken, and the report said the
/// linear algebra ran at `β = 3`, a value the generators no longer have.
#[test]
fn closure_refuses_to_fix_a_parameter_the_condition_sets() {
    for option in ["--fix", "--symbolic"] {
        let value = if option == "--fix" { "beta=3" } else { "beta" };
        let args = [
            "closure",
            "systems/smorodinsky-winternitz-i.toml",
            "H",
            "Hx",
            "--when",
            "beta = 1",
            option,
            value,
        ];
        let out = superint(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert_eq!(
            String::from_utf8_lossy(&out.stderr),
            "superint: error: computing the closure: beta is set by the condition; it can be \
             neither fixed nor kept symbolic\n",
            "{args:?}"
        );
    }
}

/// A generator named twice, or a definition given twice, is a mistake on the command line; so
/// is a defined name that is reserved or that the system has, or that would print as one of
/// its names does, refused before anything is read or computed (its value may be wrong too)
/// and said as what it is.
#[test]
fn closure_refuses_a_generator_named_twice_or_a_name_the_system_has() {
    let harmonic = &["closure", "systems/harmonic-rotor.toml"][..];
    let builtin = &["closure", "--system", "harmonic"][..];
    for (command, args, message) in [
        (
            harmonic,
            vec!["L", "L"],
            "<command line>:1:1: 'L' is given twice: the closure takes each function once",
        ),
        (
            harmonic,
            vec!["L", "--define", "W=x*p_y", "--define", "W=x"],
            "<command line>:1:1: --define: W is defined twice: give each name once",
        ),
        // A defined name the system has would shadow it: `{L, P_x} = P_x` with `L = x p_x`
        // would read, in the file's names, as a claim about the angular momentum.
        (
            harmonic,
            vec!["G1", "--define", "L=x*p_x"],
            "<command line>:1:1: --define: L is a function of the system; choose another name",
        ),
        // A function by the name it is shown by (Ω for Omega), and a letter LaTeX has not.
        (
            harmonic,
            vec!["G1", "--define", "Ω=L"],
            "<command line>:1:1: --define: Ω is a function of the system; choose another name",
        ),
        (
            harmonic,
            vec!["G1", "--define", "é=L"],
            "<command line>:1:1: --define: LaTeX has no letter 'é'",
        ),
        (
            harmonic,
            vec!["L", "--define", "H=p_x"],
            "<command line>:1:1: --define: 'H' is reserved for the Hamiltonian; choose another name",
        ),
        (
            harmonic,
            vec!["L", "--define", "K_1_1=x"],
            "<command line>:1:1: --define: K_1_1 is an instance of the family K; choose another name",
        ),
        (
            harmonic,
            vec!["L", "--define", "K=x"],
            "<command line>:1:1: --define: K is a family of the system; choose another name",
        ),
        (
            harmonic,
            vec!["L", "--define", "x=p_x"],
            "<command line>:1:1: --define: x is a coordinate of the system; choose another name",
        ),
        (
            harmonic,
            vec!["L", "--define", "M=p_x"],
            "<command line>:1:1: --define: M is a parameter of the system; choose another name",
        ),
        (
            harmonic,
            vec!["L", "--define", "ω=p_x"],
            "<command line>:1:1: --define: ω is a parameter of the system; choose another name",
        ),
        (
            harmonic,
            vec!["L", "--define", "p_theta=p_x"],
            "<command line>:1:1: --define: p_theta is a momentum of the system; choose another name",
        ),
        (
            harmonic,
            vec!["L", "--define", "Mx=p_x"],
            "<command line>:1:1: --define: the system reads Mx as a product of its names; choose another name",
        ),
        (
            harmonic,
            vec!["L", "--define", "cos=)"],
            "<command line>:1:1: --define: 'cos' is reserved (i, cos, sin, exp, conj, re, im, sqrt, rank); choose \
             another name",
        ),
        (
            harmonic,
            vec!["L", "--define", "rank=x"],
            "<command line>:1:1: --define: 'rank' is reserved",
        ),
        (
            harmonic,
            vec!["L", "--define", "2Q=p_x"],
            "<command line>:1:1: --define: a name is letters, digits and '_', starting with a letter",
        ),
        (
            harmonic,
            vec!["L", "--define", "_Q=p_x"],
            "<command line>:1:1: --define: a name cannot begin or end in '_' or hold '__'; choose another name",
        ),
        (
            builtin,
            vec!["L", "--define", "P11=x"],
            "<command line>:1:1: --define: P11 is a function of the system; choose another name",
        ),
        (
            builtin,
            vec!["L", "--define", "theta=x"],
            "<command line>:1:1: --define: theta is an angle of the system; choose another name",
        ),
        // A generator printed as a function or another generator is, here in LaTeX (F_{1}),
        // whether or not that function is a generator.
        (
            harmonic,
            vec!["L", "--define", "F_1=F1"],
            "<command line>:1:1: --define: the generator F_1 would print as F_{1} in LaTeX, as the function F1 \
             does; choose another name",
        ),
        (
            builtin,
            vec!["L", "--define", "C_1=F1", "--define", "C1=F2"],
            "<command line>:1:1: --define: the generator C1 would print as C_{1} in LaTeX, as the generator C_1 \
             does; choose another name",
        ),
    ] {
        let out = superint(&[command, &args].concat());
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(
            stderr.starts_with(&format!("superint: error: {message}")),
            "{message}\n{stderr}"
        );
    }
}

/// A closure whose brackets leave the polynomials of the degree marks them `*` in the table and
/// gives them apart, and says which generator is no integral: with `L` on the
/// Smorodinsky–Winternitz system (`{L, H} ≠ 0` there), the table cannot close.
#[test]
fn a_closure_with_a_generator_that_is_no_integral_says_so() {
    let out = superint(&[
        "closure",
        "systems/smorodinsky-winternitz-i.toml",
        "H",
        "Hx",
        "L",
        "--no-timings",
    ]);
    assert_eq!(out.status.code(), Some(0));
    let out = String::from_utf8(out.stdout).expect("UTF-8");
    assert!(out.contains("    L     │ *   *     0\n"), "{out}");
    assert!(
        normalize(&out).contains(
            "L is no integral (its bracket with H is not zero), so its brackets need not close \
             among the others."
        ),
        "{out}"
    );
    assert!(out.contains("    {H, L}   = −2γx/y³ + 2βy/x³\n"), "{out}");
}

/// The quadratic algebra of the Smorodinsky–Winternitz system I with its parameters: `α`, `β`
/// and `γ` have one weight, so the lift from fixed values could not restore them, and every
/// bracket and relation held at `α = β = γ = 1` only. Kept symbolic, the coefficients are
/// found as polynomials in them (and `M` lifted): the brackets of `H_x`, `X` and
/// `C = {H_x, X}`, and the cubic relation among them, each proved for every value.
#[test]
fn smorodinsky_winternitz_quadratic_algebra_with_symbolic_parameters() {
    let out = normalize(&expect(
        "sw1-algebra",
        &[
            "{H_x, X} = C [B1 proved]",
            "{H_x, C} = 8 H H_x − 8 H_x² − 8α X/M [B2 proved]",
            "{X, C} = −32Mβ H + 32Mβ H_x + 32Mγ H_x − 8 H X + 16 H_x X [B3 proved]",
            "128Mαβγ + 64Mβ H H_x + 16 H H_x X = 32Mβ H² + 32Mβ H_x² + 32Mγ H_x² + 16 H_x² X \
             + C² + 8α X²/M [R1 proved]",
            "Parameters kept symbolic: α, β, γ.",
        ],
    ));
    assert!(!out.contains("not lifted"), "{out}");
    assert!(!out.contains("α = 1"), "{out}");
    for (args, message) in [
        (
            "--symbolic x",
            "--symbolic: 'x' is not a parameter of the system",
        ),
        (
            "--symbolic alpha --fix alpha=2",
            "alpha is both fixed to a value and kept symbolic",
        ),
    ] {
        let mut words = vec![
            "closure",
            "systems/smorodinsky-winternitz-i.toml",
            "H",
            "Hx",
        ];
        words.extend(args.split_whitespace());
        let out = superint(&words);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(stderr.contains(message), "{stderr}");
    }
}

/// Runs a command with `--format json --no-timings`, expects exit 0, returns the JSON and the
/// command's text (the same command without `--format json`).
fn json_and_text(args: &[&str]) -> (serde_json::Value, String) {
    let mut with_json = args.to_vec();
    with_json.extend(["--format", "json", "--no-timings"]);
    let o = superint(&with_json);
    assert_eq!(o.status.code(), Some(0), "{args:?}");
    let v = serde_json::from_slice(&o.stdout).expect("JSON");
    let mut with_text = args.to_vec();
    with_text.push("--no-timings");
    let o = superint(&with_text);
    assert_eq!(o.status.code(), Some(0), "{args:?}");
    (v, normalize(&String::from_utf8(o.stdout).expect("UTF-8")))
}

/// The ids of a JSON report's claims.
fn claim_ids(v: &serde_json::Value) -> Vec<String> {
    v["claims"]
        .as_array()
        .expect("claims")
        .iter()
        .map(|c| c["id"].as_str().expect("an id").to_string())
        .collect()
}

/// A script reads what a search searched and found from its JSON `searches`, the same
/// numbers the text states: the space, the linear system, the parameters fixed, the
/// dimensions, and which integrals the claims show.
#[test]
fn search_json_gives_the_space_and_dimensions_as_data() {
    let (v, text) = json_and_text(
        &[
            &[
                "search",
                "systems/harmonic-rotor.toml",
                "--when",
                "p_theta = I*omega",
            ][..],
            &crate::DEGREE_ONE,
        ]
        .concat(),
    );
    let searches = v["searches"].as_array().expect("searches");
    assert_eq!(searches.len(), 1);
    let s = &searches[0];
    let space = &s["space"];
    assert_eq!(
        (&space["momenta_degree"], &space["positions_degree"]),
        (&1.into(), &1.into())
    );
    assert_eq!(space["coordinates"], serde_json::json!(["x", "y"]));
    assert_eq!(space["momenta"], serde_json::json!(["p_x", "p_y"]));
    assert_eq!(space["left_out"], serde_json::json!(["p_theta"]));
    assert_eq!(space["left_out_as_functions"], serde_json::json!([]));
    let said = format!(
        "{} unknowns, {} linear equations over Q, in {} independent blocks (the largest has {} \
         unknowns)",
        s["unknowns"], s["equations"], s["blocks"], s["largest_block"]
    );
    assert!(text.contains(&said), "{said}\n{text}");
    let fixed: Vec<(&str, &str)> = s["parameters"]["fixed"]
        .as_array()
        .expect("fixed")
        .iter()
        .map(|p| {
            (
                p["parameter"].as_str().unwrap(),
                p["value"].as_str().unwrap(),
            )
        })
        .collect();
    assert_eq!(fixed, [("M", "1"), ("omega", "1"), ("I", "1")]);
    assert_eq!(s["parameters"]["condition"], "p_θ = Iω");
    // Six integrals, all lifted to every value; one of degree 0 and five of degree 1.
    let dimension = s["dimension"].as_u64().expect("dimension");
    assert!(
        text.contains(&format!(
            "Dimension of the space of integrals: {dimension}."
        )),
        "{text}"
    );
    assert_eq!(dimension, 6);
    assert_eq!(s["by_momenta_degree"], serde_json::json!([1, 6]));
    let counted: u64 = s["counts"]
        .as_array()
        .expect("counts")
        .iter()
        .flat_map(|row| row.as_array().expect("a row"))
        .map(|c| c.as_u64().expect("a count"))
        .sum();
    assert_eq!(counted, dimension);
    assert_eq!(s["for_every_value"], 6);
    assert_eq!(s["new_only"], serde_json::Value::Null);
    let shown: Vec<String> = serde_json::from_value(s["shown"].clone()).expect("ids");
    assert_eq!(shown, claim_ids(&v));
}

/// With `--new-only`, `shown` lists the new integrals, which are the claims, and `new_only`
/// says what generated the rest: the generated span and the new ones fill the space.
#[test]
fn search_json_new_only_accounts_for_the_whole_space() {
    let (v, text) = json_and_text(&[
        "search",
        "systems/harmonic-rotor.toml",
        "--when",
        "p_theta = I*omega",
        "--new-only",
    ]);
    let s = &v["searches"][0];
    let new = &s["new_only"];
    assert_eq!(new["known"], serde_json::json!(["H", "L", "G1", "G2"]));
    let shown: Vec<String> = serde_json::from_value(s["shown"].clone()).expect("ids");
    assert_eq!(
        new["generated"].as_u64().unwrap() + shown.len() as u64,
        s["dimension"].as_u64().unwrap()
    );
    assert!(text.contains(&format!(
        "({} products formed); the generated ones span {} of the {} dimensions",
        new["products"], new["generated"], s["dimension"]
    )));
    // The claims: one per new integral, and the one that covers the rest of the basis.
    let ids = claim_ids(&v);
    assert_eq!(ids[..shown.len()], shown[..]);
    assert_eq!(ids[shown.len()..], ["basis".to_string()]);
}

/// A closure's JSON `closures` says whether the table closes, which brackets fall outside
/// (by the generators' names), and lists the ids of the brackets and relations it proved.
#[test]
fn closure_json_says_what_closes_and_what_does_not() {
    let (v, _) = json_and_text(&[
        "closure",
        "systems/smorodinsky-winternitz-i.toml",
        "H",
        "Hx",
        "L",
    ]);
    let c = &v["closures"][0];
    assert_eq!(c["generators"], serde_json::json!(["H", "Hx", "L"]));
    assert_eq!(c["closes"], false);
    assert_eq!(c["outside"], serde_json::json!([["H", "L"], ["Hx", "L"]]));
    // Those entries, `*` in the table, have no ASCII form to read back; the rest have one.
    let entries = &v["tables"][0]["entries"];
    for (a, b) in [(0, 2), (2, 0), (1, 2), (2, 1)] {
        assert_eq!(entries[a][b]["text"], "*");
        assert_eq!(entries[a][b]["ascii"], serde_json::Value::Null);
    }
    assert_eq!(entries[0][1]["ascii"], "0");
    let (v, _) = json_and_text(&[
        "closure",
        "systems/smorodinsky-winternitz-i.toml",
        "H",
        "Hx",
        "X",
        "--define",
        "C={Hx, X}",
        "C",
        "--degree",
        "3",
        "--symbolic",
        "alpha,beta,gamma",
        "--parameters-degree",
        "3",
    ]);
    let c = &v["closures"][0];
    assert_eq!(c["closes"], true);
    assert_eq!(c["unlifted"], 0);
    let p = &c["parameters"];
    assert_eq!(p["symbolic"], serde_json::json!(["alpha", "beta", "gamma"]));
    assert_eq!(p["symbolic_degree"], 3);
    assert_eq!(
        p["fixed"],
        serde_json::json!([{"parameter": "M", "value": "1"}])
    );
    let mut ids: Vec<String> = serde_json::from_value(c["brackets"].clone()).expect("ids");
    ids.extend(serde_json::from_value::<Vec<String>>(c["relations"].clone()).expect("ids"));
    assert_eq!(ids, claim_ids(&v));
    assert_eq!(ids, ["B1", "B2", "B3", "R1"]);
}

/// With `H` depending on an angle, the `e^{ikψ}` components of an integral are no integrals
/// (the energy `p_x²/2 + p_ψ²/2 + cos ψ` of a pendulum beside a free particle has `cos ψ` as
/// one), so `--new-only` generates from whole integrals: of the nine integrals up to degree 4
/// in the momenta, only `p_x` is new. From components, the span filled up with products that
/// are no integrals, stopped early, and called `p_x(2H − p_x²)` and `(2H − p_x²)² − 2` new.
#[test]
fn new_integrals_of_an_angle_dependent_hamiltonian_are_generated_from_whole_integrals() {
    let file = crate::scratch_text(
        "discovery",
        "pendulum-free.toml",
        "name = \"pendulum and free particle\"\nhamiltonian = \"p_x^2/2 + p_psi^2/2 + cos(psi)\"\n\
         [phase_space]\ncoordinates = [\"x\"]\nangles = [\"psi\"]\n",
    );
    let file = file.to_str().expect("a UTF-8 path");
    for exact in [false, true] {
        let mut args = vec![
            "search",
            file,
            "--momenta-degree",
            "4",
            "--positions-degree",
            "0",
            "--trig-degree",
            "4",
            "--new-only",
        ];
        if exact {
            args.push("--exact-complement");
        }
        let (v, text) = json_and_text(&args);
        assert!(
            text.contains("the generated ones span 8 of the 9 dimensions"),
            "{text}"
        );
        assert!(
            text.contains("New integrals: I2 = p_x {I2, H} = 0"),
            "{text}"
        );
        assert_eq!(v["searches"][0]["shown"], serde_json::json!(["I2"]));
    }
}

/// Two rotors turning together, `H = (p_a + p_b)²/2`: every function of `a − b` and the
/// momenta is an integral, among them functions of the angles alone, of degree 0 but no
/// constants. The system file's path.
fn two_rotors() -> String {
    scratch_system("two-rotors", "(p_a + p_b)^2/2", "a, b")
}

/// The system file at `path`, loaded.
fn loaded(path: &str) -> superint::system_file::LoadedSystem {
    load(Path::new(path), &LimitsOverride::default()).expect("the file loads")
}

/// The `--new-only` search of `space`: the basis integrals, each with whether it is new.
fn new_or_generated(
    file: &superint::system_file::LoadedSystem,
    space: SearchSpace,
) -> Vec<(Expr, bool)> {
    let found = search(file.system(), &SearchOptions::new(space).new_only()).expect("searches");
    let new = found.new.expect("--new-only").new;
    (found.basis.iter().enumerate())
        .map(|(i, f)| (f.expr().clone(), new.contains(&i)))
        .collect()
}

/// Whether `f`, up to sign, is a basis integral and new; it must be a basis integral.
fn is_new(file: &superint::system_file::LoadedSystem, found: &[(Expr, bool)], f: &str) -> bool {
    let e = file.parse_argument(f).expect("parses");
    let flow = file.system().flow(&e).expect("a bracket");
    assert!(flow.is_zero(), "{f} is no integral: {{{f}, H}} = {flow}");
    let found = found.iter().find(|(g, _)| *g == e || *g == -&e);
    found
        .unwrap_or_else(|| panic!("{f} is no basis integral"))
        .1
}

/// Integrals of degree 0 that are no constants are graded by their trigonometric order:
/// `cos(a − b)` (order 2, for `k = (1, −1)`) is new, while `cos 2(a − b) = 2cos²(a − b) − 1`
/// and `p_b cos(a − b)` are products of integrals of lower grade. They were reported new, with
/// ten more: functions of the angles alone never multiplied, and stamped like constants.
#[test]
fn functions_of_the_angles_alone_generate_by_their_trigonometric_order() {
    let path = two_rotors();
    let file = loaded(&path);
    let found = new_or_generated(
        &file,
        SearchSpace::default().momenta_degree(2).trig_degree(4),
    );
    assert_eq!(found.len(), 30);
    for f in ["cos(a - b)", "sin(a - b)", "p_a", "p_b"] {
        assert!(is_new(&file, &found, f), "{f} is new");
    }
    for f in [
        "cos(2*(a - b))",
        "sin(2*(a - b))",
        "p_b*cos(a - b)",
        "p_a*sin(2*(a - b))",
        "p_a*p_b*cos(a - b)",
        "p_b^2",
    ] {
        assert!(!is_new(&file, &found, f), "{f} is generated");
    }
    assert_eq!(found.iter().filter(|f| f.1).count(), 4);
    // The command says so, by the rule it prints, modulo p and over Q alone.
    for exact in [false, true] {
        let mut args = vec![
            "search",
            &path,
            "--momenta-degree",
            "2",
            "--positions-degree",
            "0",
            "--trig-degree",
            "4",
            "--new-only",
        ];
        if exact {
            args.push("--exact-complement");
        }
        let (v, text) = json_and_text(&args);
        for expected in [
            "An integral of grade (N, k) (its degree N in the coordinates and momenta together, \
             then its trigonometric order k: the largest such pair among its terms, compared in \
             that order) is generated when it is a sum of known integrals, constants and \
             products of integrals of grade below (N, k)",
            "the generated ones span 26 of the 30 dimensions",
            // cos a cos b + sin a sin b and sin a cos b − cos a sin b, as a physicist writes them.
            "New integrals: I2 = cos(a − b) I3 = sin(a − b) I6 = p_b I7 = p_a {I2, H} = 0",
        ] {
            assert!(text.contains(expected), "{text}");
        }
        assert_eq!(
            v["searches"][0]["shown"],
            serde_json::json!(["I2", "I3", "I6", "I7"])
        );
    }
}

/// The oscillator `(p_x² + p_y²)/2 + ω²(x² + y²)/2 + gy` about its shifted centre
/// `y' = y + g/ω²`, with `H_y = p_y²/2 + ω²y'²/2` named: with `ω, g` kept symbolic it is known
/// through `ω²H_y = ω²p_y²/2 + ω⁴y²/2 + ω²gy + g²/2`, of degree 4 in them.
const SHIFTED_OSCILLATOR: &str = "name = \"shifted oscillator\"\n\
    hamiltonian = \"(p_x^2 + p_y^2)/2 + omega^2*(x^2 + y^2)/2 + g*y\"\n\
    [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"omega\", \"g\"]\n\
    [[function]]\nname = \"Hy\"\nvalue = \"p_y^2/2 + omega^2*(y + g/omega^2)^2/2\"\n";

/// The `--new-only` search of the shifted oscillator at momenta and positions `≤ 2` with
/// `ω, g` symbolic of degree `≤ parameters_degree`, over Q alone if `exact`: the basis
/// integrals, each with whether it is new.
fn shifted_oscillator_new(
    file: &superint::system_file::LoadedSystem,
    parameters_degree: u32,
    exact: bool,
) -> Vec<(Expr, bool)> {
    let var = |name: &str| file.system().vars().lookup(name).expect("a parameter");
    let space = SearchSpace::default()
        .momenta_degree(2)
        .positions_degree(2)
        .parameters_degree(parameters_degree);
    let mut options = SearchOptions::new(space)
        .symbolic(var("omega"))
        .symbolic(var("g"))
        .new_only();
    if exact {
        options = options.exact_complement();
    }
    let found = search(file.system(), &options).expect("searches");
    let new = found.new.expect("--new-only").new;
    (found.basis.iter().enumerate())
        .map(|(i, f)| (f.expr().clone(), new.contains(&i)))
        .collect()
}

/// With parameters kept symbolic, an integral whose multiple by a monomial in them is
/// generated is not new: `p_y² + ω²y² + 2gy = 2H_y − g²/ω²` and
/// `ω²L² − 2gLp_x − g²x² = ((ω²L − gp_x)² − g²(p_x² + ω²x²))/ω²` (`L = x p_y − y p_x`), whose
/// multiples by `ω²` are sums of known integrals, constants, products and their parameter
/// multiples, were reported new beside `ω²L − gp_x` and `p_x p_y + ω²xy + gx` (4 of 45, where
/// over the rational functions in `ω, g` the quadratic integrals `H_x`, `H_y`, `L'`, `G'`
/// hold two beyond `H` and `H_y`). Those two stay new. At parameters degree 2 `ω²H_y` lies
/// outside the space, which knows `H` alone, and the four are new there.
#[test]
fn integrals_generated_once_divided_by_a_parameter_are_not_new() {
    let path = crate::scratch_text("discovery", "shifted-oscillator.toml", SHIFTED_OSCILLATOR);
    let path = path.to_str().expect("a UTF-8 path");
    let file = loaded(path);
    let divided = [
        "p_y^2 + omega^2*y^2 + 2*g*y",
        "omega^2*x^2*p_y^2 - 2*omega^2*x*y*p_x*p_y - 2*g*x*p_x*p_y + omega^2*y^2*p_x^2 \
         + 2*g*y*p_x^2 - g^2*x^2",
    ];
    let genuinely_new = [
        "omega^2*x*p_y - omega^2*y*p_x - g*p_x",
        "p_x*p_y + omega^2*x*y + g*x",
    ];
    for exact in [false, true] {
        let found = shifted_oscillator_new(&file, 4, exact);
        assert_eq!(found.len(), 45);
        for f in divided {
            assert!(!is_new(&file, &found, f), "{f} is generated");
        }
        for f in genuinely_new {
            assert!(is_new(&file, &found, f), "{f} is new");
        }
        assert_eq!(found.iter().filter(|f| f.1).count(), 2);
        // Where the multiple `ω²H_y` lies outside the space nothing is divided.
        let found = shifted_oscillator_new(&file, 2, exact);
        assert_eq!(found.len(), 11);
        for f in divided.iter().chain(&genuinely_new) {
            assert!(
                is_new(&file, &found, f),
                "{f} is new at parameters degree 2"
            );
        }
        assert_eq!(found.iter().filter(|f| f.1).count(), 4);
    }
    // The command says so, and why.
    for exact in [false, true] {
        let mut args = quadratic_new_only_in_omega_and_g(path, "4");
        if exact {
            args.push("--exact-complement");
        }
        let (v, text) = json_and_text(&args);
        for expected in [
            "Below, parameter multiples of integrals count as generated, and so does an \
             integral whose multiple by a monomial in ω, g lies in the space and is generated \
             by the rule below and this one: K/ω is not new where K is generated.",
            "Known integrals in the space: H, Hy.",
            "the generated ones span 43 of the 45 dimensions",
            "New integrals: I16 = ω²x p_y − ω²y p_x − g p_x I23 = p_x p_y + ω²xy + gx \
             {I16, H} = 0",
        ] {
            assert!(text.contains(expected), "{text}");
        }
        assert_eq!(v["searches"][0]["shown"], serde_json::json!(["I16", "I23"]));
    }
}

/// The command line of `search --new-only` on `path` for integrals quadratic in the momenta and
/// the positions, without angles, with `ω, g` symbolic to `parameters_degree`.
fn quadratic_new_only_in_omega_and_g<'a>(
    path: &'a str,
    parameters_degree: &'a str,
) -> Vec<&'a str> {
    vec![
        "search",
        path,
        "--momenta-degree",
        "2",
        "--positions-degree",
        "2",
        "--trig-degree",
        "0",
        "--symbolic",
        "omega,g",
        "--parameters-degree",
        parameters_degree,
        "--new-only",
    ]
}

/// The rotor under gravity with `ω, g` symbolic (docs/results.md, "Symbolic parameters"): at
/// parameters degree 4 the known `G2' = G2 − Mgy − Mg²/(2ω²)` enters as `ω²G2'`, and
/// `p_y² + M²ω²y² + 2M²gy = M(H − F2 − G2') − M²g²/(2ω²)` and the quartic
/// `((ω²L')² − g²(p_x² + M²ω²x²))/ω²` are generated, which were reported new; at degree 2,
/// without `ω²G2'`, both stay new.
#[test]
fn gravity_rotor_integrals_divided_by_omega_squared_are_generated() {
    let search = |degree: &str| {
        json_and_text(&quadratic_new_only_in_omega_and_g(
            "systems/gravity-rotor.toml",
            degree,
        ))
    };
    let (v, text) = search("4");
    for expected in [
        "Known integrals in the space: H, F2, Ω, L', G1', G2'.",
        "the generated ones span the whole space (81 dimensions).",
        "None: the known integrals generate every integral in the space.",
    ] {
        assert!(text.contains(expected), "{text}");
    }
    assert_eq!(v["searches"][0]["shown"], serde_json::json!([]));
    let (v, text) = search("2");
    for expected in [
        "Known integrals in the space: H, F2, Ω, L', G1'.",
        "the generated ones span 22 of the 24 dimensions",
        // Each restated in the file's functions, those that are no integrals among them.
        "New integrals: J15 = p_y² + M²ω²y² + 2M²gy \
         = Mω L' + 2M H − 2M F2 − M G2' − Z' Z̄'/2 \
         J24 = ω²x² p_y² − 2ω²xy p_x p_y − 2gx p_x p_y + ω²y² p_x² + 2gy p_x² − M²g²x² \
         = −ω² L² + 2ω² L L' − 4 G1² + 8 G1 G1' − 4 G1'²",
    ] {
        assert!(text.contains(expected), "{text}");
    }
    assert_eq!(v["searches"][0]["shown"], serde_json::json!(["J15", "J24"]));
}

/// Products of integrals count only when each factor's grade is below the integral's: `p_b`
/// and `cos(a − b)` are products of integrals, but of higher grades, and stay new. Stamping a
/// product by its least factor, or by its own grade, would call them generated.
#[test]
fn an_integral_that_is_a_product_of_higher_grades_only_is_new() {
    let file = loaded(&two_rotors());
    let found = new_or_generated(
        &file,
        SearchSpace::default().momenta_degree(2).trig_degree(4),
    );
    let parse = |s: &str| file.parse_argument(s).expect("parses");
    for (f, product) in [
        (
            "cos(a - b)",
            "cos(2*(a - b))*cos(a - b) + sin(2*(a - b))*sin(a - b)",
        ),
        (
            "p_b",
            "(p_b*cos(a - b))*cos(a - b) + (p_b*sin(a - b))*sin(a - b)",
        ),
    ] {
        assert_eq!(parse(f), parse(product), "{f} = {product}");
        assert!(is_new(&file, &found, f), "{f} is new");
    }
    for factor in [
        "cos(2*(a - b))",
        "sin(2*(a - b))",
        "p_b*cos(a - b)",
        "p_b*sin(a - b)",
    ] {
        assert!(!is_new(&file, &found, factor), "{factor} is generated");
    }
}

/// With `H` depending on an angle the generators are whole integrals, and functions of the
/// angles alone multiply as well: beside a pendulum, the free rotor's `cos φ`, `sin φ` and `p_φ`
/// are new, and `cos 2φ`, `p_φ cos φ` and `H cos φ` generated.
#[test]
fn functions_of_the_angles_alone_generate_beside_an_angle_dependent_hamiltonian() {
    let file = loaded(&scratch_system(
        "pendulum beside a free rotor",
        "p_psi^2/2 + cos(psi)",
        "psi, phi",
    ));
    let found = new_or_generated(
        &file,
        SearchSpace::default().momenta_degree(2).trig_degree(2),
    );
    assert_eq!(found.len(), 18);
    for f in ["cos(phi)", "sin(phi)", "p_phi"] {
        assert!(is_new(&file, &found, f), "{f} is new");
    }
    for f in [
        "cos(2*phi)",
        "p_phi*cos(phi)",
        "(p_psi^2 + 2*cos(psi))*cos(phi)",
    ] {
        assert!(!is_new(&file, &found, f), "{f} is generated");
    }
    assert_eq!(found.iter().filter(|f| f.1).count(), 3);
}

/// The labels of a search's integrals take a letter the system does not use: two coupled
/// rotors with moments of inertia `I1`, `I2` had their integral `I2 = p_θ + p_φ` printed
/// beside the condition `at I1 = 1, I2 = 1`. And the values it suggests to compare with are
/// not those given (`--fix I1=2,I2=3` was told to compare with `--fix I1=2,I2=3,k=5`).
#[test]
fn a_searchs_labels_and_suggestions_do_not_repeat_the_systems_own() {
    let file = crate::scratch_text(
        "discovery",
        "coupled-rotors.toml",
        "name = \"two coupled rotors\"\n\
         hamiltonian = \"p_theta^2/(2*I1) + p_phi^2/(2*I2) - k*cos(theta - phi)\"\n\
         [phase_space]\nangles = [\"theta\", \"phi\"]\nparameters = [\"I1\", \"I2\", \"k\"]\n",
    );
    let file = file.to_str().expect("a UTF-8 path");
    let (v, text) = json_and_text(&["search", file, "--fix", "I1=2,I2=3"]);
    assert!(text.contains("J2 = p_θ + p_φ"), "{text}");
    assert!(!text.contains("I2 = p_θ"), "{text}");
    assert_eq!(
        claim_ids(&v),
        ["J1", "J2", "J3", "J4"].map(String::from).to_vec()
    );
    assert!(
        text.contains("or compare with other values (--fix I1=3,I2=5,k=7)"),
        "{text}"
    );
    // The weights cannot lift `I1, I2, k`, but the total momentum holds as found for every
    // value, and is proved so: it was said to hold "at I1 = 2, I2 = 3, k = 1" only; `J4`,
    // `12 H` there, is lifted through `12 H`.
    assert!(
        text.contains(
            "nothing is lifted; 2 of the 4 basis elements hold for every value as found and 1 \
             through its restatement (proved symbolically), the others at these values only"
        ),
        "{text}"
    );
    let conditions: Vec<&serde_json::Value> = v["claims"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| &c["condition"])
        .collect();
    assert_eq!(conditions[1], &serde_json::Value::Null);
    assert_eq!(conditions[2], "I1 = 2, I2 = 3, k = 1");
    assert_eq!(v["claims"][2]["condition_ascii"], "I1 = 2, I2 = 3, k = 1");
    assert_eq!(conditions[3], &serde_json::Value::Null);
    assert_eq!(v["searches"][0]["for_every_value"], 3);
}

/// With parameters kept symbolic, a search says when `H`, or the first power of it that the
/// space holds, needs a degree in them past `--parameters-degree`: the 1:3 oscillator with
/// symbolic frequency `a` showed no quartic integral at degree 2, since `H²` has degree 4
/// in `a`; at degree 4 the quartic integral is found, and there is no note.
#[test]
fn a_search_says_when_powers_of_h_need_a_larger_parameters_degree() {
    let file = crate::scratch_text(
        "discovery",
        "osc-ab.toml",
        "name = \"oscillator with two frequencies\"\n\
         hamiltonian = \"(p_x^2 + p_y^2)/2 + (a^2*x^2 + b^2*y^2)/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\", \"b\"]\n",
    );
    let file = file.to_str().expect("a UTF-8 path");
    let search = |degree: &str| {
        let out = superint(&[
            "search",
            file,
            "--momenta-degree",
            "4",
            "--positions-degree",
            "4",
            "--trig-degree",
            "0",
            "--when",
            "b = 3*a",
            "--symbolic",
            "a",
            "--parameters-degree",
            degree,
            "--no-timings",
        ]);
        assert_eq!(out.status.code(), Some(0));
        normalize(&String::from_utf8(out.stdout).expect("UTF-8"))
    };
    let two = search("2");
    assert!(
        two.contains(
            "Note: H² lies in the space but for its degree 4 in a, past the space's 2 \
             (--parameters-degree): integrals of degree 4 in the momenta may need a larger one."
        ),
        "{two}"
    );
    assert!(!two.contains("p_x³ p_y"), "{two}");
    let four = search("4");
    assert!(!four.contains("Note: H"), "{four}");
    assert!(
        four.contains("p_x³ p_y − 3a²x² p_x p_y + 9a²xy p_x² − 3a⁴x³y"),
        "{four}"
    );
    let one = superint(&[
        "search",
        file,
        "--symbolic",
        "a,b",
        "--parameters-degree",
        "1",
    ]);
    let one = normalize(&String::from_utf8(one.stdout).expect("UTF-8"));
    assert!(
        one.contains("Note: H has degree 2 in a, b, past the space's 1 (--parameters-degree)"),
        "{one}"
    );
}

/// With some parameters symbolic and the rest lifted back, the claim for the basis elements
/// not shown holds for every value: it said "proved for every α, β, γ, at M = 1" although
/// every element was lifted in `M` too.
#[test]
fn a_symbolic_search_lifted_in_the_rest_says_every_value() {
    let (v, text) = json_and_text(&[
        "search",
        "systems/smorodinsky-winternitz-i.toml",
        "--laurent",
        "--symbolic",
        "alpha,beta,gamma",
    ]);
    let dimension = v["searches"][0]["dimension"].as_u64().unwrap();
    assert_eq!(
        v["searches"][0]["for_every_value"].as_u64(),
        Some(dimension)
    );
    let rest = v["claims"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["id"] == "basis")
        .expect("the claim for the other elements");
    assert_eq!(rest["note"], serde_json::Value::Null);
    assert!(!text.contains("at M = 1"), "{text}");
}

/// The planar 3:5 resonance's integral `A = A_x⁵ Ā_y³` is of degree 8 in the phase space:
/// `{Re A, Im A}` is of degree 7 in `H_x, H_y` and the relation `|A|² = 256 M⁸ H_x⁵ H_y³` of
/// degree 8, past the degree 6 the closure was once capped at. At degree 6 the bracket stays
/// outside the table; at degree 8 the table closes with that relation.
#[test]
fn closure_past_degree_six_finds_the_3_5_oscillator_relation() {
    let args = |degree: &str| {
        superint(&[
            "closure",
            "systems/anisotropic-3-5-rotor.toml",
            "Hx",
            "Hy",
            "ReA",
            "ImA",
            "--degree",
            degree,
            "--no-timings",
        ])
    };
    let low = args("6");
    let text = normalize(&String::from_utf8(low.stdout).unwrap());
    assert_eq!(low.status.code(), Some(0), "{text}");
    assert!(
        text.contains("The brackets marked * are no polynomials of degree ≤ 6"),
        "{text}"
    );
    let high = args("8");
    let text = normalize(&String::from_utf8(high.stdout).unwrap());
    assert_eq!(high.status.code(), Some(0), "{text}");
    for line in [
        "The table closes: every bracket is a polynomial of degree ≤ 8 in the generators.",
        "{Re A, Im A} = 1920M⁸ω(3 H_x − 5 H_y) H_x⁴ H_y² [B5 proved]",
        // The relation cleared of 1/M⁸, which it has in two of its three terms.
        "256M⁸ H_x⁵ H_y³ = (Re A)² + (Im A)² [R1 proved]",
        "6 claims: 6 proved, 0 refuted",
    ] {
        assert!(text.contains(line), "{line} not in {text}");
    }
}

/// The monomials a closure would expand are counted before any is: past the limit it is an
/// error that says how many there are and which option raises it, with exit code 2.
#[test]
fn a_closure_past_its_monomial_limit_stops_before_computing() {
    // The su(2) generators and F1, F2 of the harmonic rotor, at a degree, with more options.
    let closure = |degree: &str, more: &[&str]| {
        let generators = ["F1", "F2", "L", "G1", "G2"];
        let args = [
            &["closure", "systems/harmonic-rotor.toml"][..],
            &generators[..],
        ]
        .concat();
        superint(&[&args[..], &["--degree", degree][..], more].concat())
    };
    let out = closure("64", &[]);
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains(
            "there are 11238513 monomials of degree ≤ 64 in the 5 generators, more than the \
             limit 20000"
        ) && err.contains("--max-monomials"),
        "{err}"
    );
    // Raised, the same count passes the check (at degree 4: 126 monomials, limit 126).
    let out = closure("4", &["--max-monomials", "126"]);
    assert_eq!(out.status.code(), Some(0));
    let out = closure("4", &["--max-monomials", "125"]);
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("there are 126 monomials of degree ≤ 4"),
        "{err}"
    );
}

/// The expansions of a closure's monomials are held together to the term limit, counted as
/// they are formed: `p_x` and `F1` of the rotor under gravity at degree 8 hold 6435 terms in
/// all (`F1^8`, the longest, 1287), so at `--max-terms 2000` the closure stops at the limit,
/// where it finished with every product under it; at degree 64 it held 1.3·10⁸ terms (6.2 GB)
/// before `F1^45` passed the default limit.
#[test]
fn a_closures_expansions_are_held_together_to_the_term_limit() {
    let closure = |max_terms: &str| {
        superint(&[
            "closure",
            "systems/gravity-rotor.toml",
            "p_x",
            "F1",
            "--degree",
            "8",
            "--max-terms",
            max_terms,
            "--no-timings",
        ])
    };
    let out = closure("2000");
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(out.stdout.is_empty());
    assert!(
        err.contains(
            "computing the closure: the products of the generators up to degree 8 would have \
             more than 2000 terms together (the term limit)"
        ) && err.contains("--max-terms N"),
        "{err}"
    );
    // Raised past what the expansions hold together, it finishes.
    let out = closure("6435");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The Kepler problem in space with the radical `r`: the seven integrals close into so(4)
/// with `H` central, and satisfy exactly the two relations of the reduced forms.
#[test]
fn kepler_in_space_closes_into_so4_with_two_relations() {
    let out = expect(
        "kepler3d-closure",
        &[
            "120 monomials (their span has dimension 111)",
            "{L_x, L_y} = L_z [B1 proved]",
            "{L_y, A_x} = −A_z [B6 proved]",
            "{A_x, A_y} = −2 H L_z/M [B10 proved]",
            "{A_y, A_z} = −2 H L_x/M [B12 proved]",
            "The table closes",
            "L_x A_x + L_y A_y + L_z A_z = 0 [R1 proved]",
            "Mk² + 2 H L_x² + 2 H L_y² + 2 H L_z² = M A_x² + M A_y² + M A_z² [R2 proved]",
            "14 claims: 14 proved, 0 refuted",
        ],
    );
    assert!(!out.contains("[R3"), "{out}");
}

/// The MICZ–Kepler problem without a gauge, its declared brackets holding `1/r³`: `J` and `A`
/// close into so(4) on `H`, with the two Casimirs `J · A = ks` and
/// `A · A − 2H(J · J − s²) = k²` worked out by hand (`systems/micz-kepler.toml`), and no more
/// relation to degree 3.
#[test]
fn micz_kepler_closes_into_so4_with_its_two_casimirs() {
    let out = expect(
        "micz-closure",
        &[
            "{J_x, J_y} = J_z [B1 proved]",
            "{J_y, A_x} = −A_z [B6 proved]",
            "{A_x, A_y} = −2 J_z H [B10 proved]",
            "{A_y, A_z} = −2 J_x H [B12 proved]",
            "The table closes",
            "sk = J_x A_x + J_y A_y + J_z A_z [R1 proved]",
            "2s² H + A_x² + A_y² + A_z² = k² + 2 J_x² H + 2 J_y² H + 2 J_z² H [R2 proved]",
            "14 claims: 14 proved, 0 refuted",
        ],
    );
    assert!(!out.contains("[R3"), "{out}");
}

/// The MICZ–Kepler search through the declared brackets with `1/r³`: of degree `≤ 3` in the six
/// Poisson variables and `≤ 2` in `r`, the integrals are `1`, `H` and the three components of
/// `J` and of `A` (their products are of degree 4 or more), rank 5, all of them the file's.
#[test]
fn micz_kepler_search_finds_the_poincare_and_lenz_vectors() {
    expect(
        "micz-search",
        &[
            "399 unknowns",
            "Dimension of the space of integrals: 8. By degree in the Poisson variables: ≤ 0: 1, \
             ≤ 1: 1, ≤ 2: 5, ≤ 3: 8. Functional rank: 5, the most a flow in 6 phase variables \
             allows (maximal superintegrability).",
            "Known integrals in the space: H, J_x, J_y, J_z, A_x, A_y, A_z.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
}

/// The generalized Kepler–Coulomb system: five integrals of degree 2 for every `k, b, c`, the
/// file's; with `H` alone known, the four others are new, printed as the file names them.
#[test]
fn generalized_kepler_search_finds_four_integrals() {
    expect(
        "gkc-search",
        &[
            "14320 unknowns",
            "Dimension of the space of integrals over Q (a parameter's multiple of an integral \
             counts apart from it): 9.",
            "Momenta degree exactly 2: 5.",
            "Known integrals in the space: H, A_z, J_x, J_y, J_z.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    let text = run_on_hamiltonian_alone("gkc-search");
    for integral in [
        "Known integrals in the space: H.",
        "x p_x p_z + y p_y p_z − z p_x² − z p_y² + kz/r − 2bz/x² − 2cz/y²",
        "y² p_z² − 2yz p_y p_z + z² p_y² + 2cz²/y²",
        "x² p_z² − 2xz p_x p_z + z² p_x² + 2bz²/x²",
        "x² p_y² − 2xy p_x p_y + y² p_x² + 2cx²/y² + 2by²/x²",
    ] {
        assert!(text.contains(integral), "{integral}: {text}");
    }
    assert_eq!(text.matches(" = 0 [I").count(), 4, "{text}");
}

/// The TTW system of index 2: denominators and negative powers at once, parameters symbolic.
/// The file's X and Y generate every integral of order ≤ 4; from H alone both are new, the
/// fourth-order Y found for every ω, α, β and printed as a physicist writes it, each part over
/// its common denominator (the search's own monomials give it in 19 terms).
#[test]
fn ttw_search_finds_the_fourth_order_integral_from_h_alone() {
    expect(
        "ttw-search",
        &[
            "12150 unknowns",
            "Known integrals in the space: H, X, Y.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    let text = run_on_hamiltonian_alone("ttw-search");
    for integral in [
        "Known integrals in the space: H.",
        "= 4x² p_y² − 8xy p_x p_y + 4y² p_x² + 16αx²y²/((x − y)² (x + y)²) + βx²/y² + βy²/x²",
        "= 16 p_x² p_y² + 32ω²xy p_x p_y − 8α(4xy p_x p_y + 4ω²x²y² − β)/((x − y)² (x + y)²) \
         + 4β p_x²/y² + 4β p_y²/x² + 16ω⁴x²y² + 16α²x²y²/((x − y)⁴ (x + y)⁴) + β²/(x²y²)",
    ] {
        assert!(text.contains(&normalize(integral)), "{integral}: {text}");
    }
    assert_eq!(text.matches(" = 0 [I").count(), 2, "{text}");
}

/// X, Y and their bracket Z close a polynomial algebra: {X, Z} and {Y, Z} are polynomials
/// in H, X, Y (at the fixed values; docs/results.md has {X, Z} for every value).
#[test]
fn ttw_closure_is_a_polynomial_algebra() {
    expect(
        "ttw-closure",
        &[
            "{X, Y} = Z",
            "{X, Z} = 32 H² X + 64 H² − 512 X² − 64 X Y + 1536 X",
            "{Y, Z} = −32 H² Y − 3840 H² + 1024 X Y + 40960 X + 32 Y² − 1536 Y + 10240",
            "The table closes: every bracket is a polynomial of degree ≤ 3 in the generators.",
            "3 claims: 3 proved, 0 refuted",
        ],
    );
}

/// Two radicals: the file's H, L_x and Euler's G generate the five integrals; with H alone,
/// L_x and G are new, G printed without r² or s².
#[test]
fn two_centres_search_finds_eulers_integral() {
    expect(
        "two-centres-search",
        &[
            "1130 unknowns",
            "Dimension of the space of integrals: 5.",
            "Known integrals in the space: H, L_x, G.",
            "None: the known integrals generate every integral in the space.",
            "1 claim: 1 proved, 0 refuted",
        ],
    );
    let text = run_on_hamiltonian_alone("two-centres-search");
    for piece in [
        "Known integrals in the space: H.",
        "y p_z − z p_y",
        "x² p_y² + x² p_z² − 2xy p_x p_y − 2xz p_x p_z + y² p_x² + z² p_x² − p_y² − p_z² − 2x/r \
         + 2x/s + 2/r + 2/s",
    ] {
        assert!(text.contains(piece), "{piece}: {text}");
    }
    assert!(!text.contains("REFUTED"), "{text}");
}

/// With parameters kept symbolic most basis integrals are parameter multiples of others, and
/// products with them are multiples of the others' products: left out, the rotor's complement
/// at degree 6 with `M, I` symbolic takes some ten thousand products, where forming them all
/// took over half a million (and degree 8 passed the default limit of a million). The four
/// linear integrals come out new, as over Q alone.
#[test]
fn a_symbolic_complement_leaves_parameter_multiples_out_of_the_products() {
    let o = superint(&[
        "search",
        "systems/harmonic-rotor.toml",
        "--when",
        "p_theta = I*omega",
        "--momenta-degree",
        "6",
        "--positions-degree",
        "6",
        "--trig-degree",
        "6",
        "--symbolic",
        "M,I",
        "--new-only",
        "--max-products",
        "20000",
    ]);
    let out = normalize(&String::from_utf8(o.stdout).unwrap());
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    for piece in [
        "the generated ones span 155 of the 159 dimensions",
        "= p_y cos θ + Mωy sin θ",
        "= −Mωy cos θ + p_y sin θ",
        "= p_x cos θ + Mωx sin θ",
        "= −Mωx cos θ + p_x sin θ",
        "5 claims: 5 proved, 0 refuted",
    ] {
        assert!(out.contains(piece), "{piece}: {out}");
    }
}

/// The two centres with `a`, which both radicands hold, kept symbolic with `k` and `m`: the
/// space's monomials are compared with the parameters (`a² = r² − x² + 2ax − y² − z²`), and
/// over the polynomials in `a, k, m` five integrals generate the 77 of the space, which the
/// file's `H`, `L_x` and `G` generate; from `H` alone `L_x` and Euler's `G`, exactly as the
/// file writes it, are new, proved for every value. The constants that the space writes in
/// its monomials (`−a² = x² + 2ax + y² + z² − s²`) are no generators of products.
#[test]
fn two_centres_search_keeps_the_radicands_parameter_symbolic() {
    expect(
        "two-centres-symbolic",
        &[
            "Parameters kept symbolic: a, k, m.",
            "By degree in the momenta: ≤ 0: 20, ≤ 1: 40, ≤ 2: 77.",
            "Over the polynomials in a, k, m, 5 of the 77 basis integrals, I1, I21, I41, I54 and I55, generate all of them",
            "Known integrals in the space: H, L_x, G.",
            "(10 products formed)",
            "None: the known integrals generate every integral in the space.",
            "1 claim: 1 proved, 0 refuted",
        ],
    );
    let text = normalize(&run_on_hamiltonian_alone("two-centres-symbolic"));
    for piece in [
        "Known integrals in the space: H.",
        "the generated ones span 75 of the 77 dimensions",
        "= y p_z − z p_y",
        "= x² p_y² + x² p_z² − 2xy p_x p_y − 2xz p_x p_z + y² p_x² + z² p_x² − a² p_y² − a² p_z² \
         − 2kax/r + 2max/s + 2ka²/r + 2ma²/s",
        "3 claims: 3 proved, 0 refuted",
    ] {
        assert!(text.contains(&normalize(piece)), "{piece}: {text}");
    }
}

/// Smorodinsky–Winternitz III, whose potential divides by `r + x` and `r − x`: the file's `H`,
/// `X_1`, `X_2` generate every second-order integral for every value of the parameters; from
/// `H` alone both come out new (`X_2` as the file writes it, `X_1` less the constant
/// `2M(β + γ)`), through the divisions by the conjugates.
#[test]
fn sw3_search_finds_both_integrals_through_the_conjugates() {
    expect(
        "sw3-search",
        &[
            "9450 unknowns",
            "Known integrals in the space: H, X_1, X_2.",
            "None: the known integrals generate every integral in the space.",
            "1 claim: 1 proved, 0 refuted",
        ],
    );
    let text = run_on_hamiltonian_alone("sw3-search");
    for piece in [
        "Known integrals in the space: H.",
        "x p_y² − y p_x p_y + Mαx/r + 2Mβx/y² + 2Mγx/y² − 2Mβr/y² + Mβ/r + 2Mγr/y² − Mγ/r",
        "x² p_y² − 2xy p_x p_y + y² p_x² + 2Mβx²/y² + 2Mγx²/y² − 2Mβxr/y² + 2Mγxr/y²",
        "3 claims: 3 proved, 0 refuted",
    ] {
        assert!(text.contains(piece), "{piece}: {text}");
    }
}

/// Up to third order in the momenta, the file's `H`, `X_1`, `X_2` and `R = {X_1, X_2}`
/// generate every integral, for every value of the parameters; from `H` alone the cubic one
/// comes out new beside the two quadratic ones: `−R/2`, as the file's claim `R = −2 I` checks.
#[test]
fn sw3_search_finds_the_cubic_integral_from_h_alone() {
    expect(
        "sw3-cubic",
        &[
            "15750 unknowns",
            "Known integrals in the space: H, X_1, X_2, R.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    let text = run_on_hamiltonian_alone("sw3-cubic");
    for piece in [
        "Known integrals in the space: H.",
        "x² p_x p_y² − 2xy p_x² p_y + y² p_x³ + 2Mβx² p_x/y² + 2Mγx² p_x/y² − Mαxy p_y/r \
         − 2Mβxr p_x/y² − Mβx p_x/r + 2Mγxr p_x/y² + Mγx p_x/r + Mαy² p_x/r − Mβy p_y/r \
         + Mγy p_y/r + 2Mβ p_x + 2Mγ p_x",
        "4 claims: 4 proved, 0 refuted",
    ] {
        assert!(text.contains(&crate::normalize(piece)), "{piece}: {text}");
    }
}

/// The integrals of Smorodinsky–Winternitz III and their bracket `R` close into a quadratic
/// algebra with a cubic Casimir relation, for every value of the parameters.
#[test]
fn sw3_closure_is_a_quadratic_algebra() {
    expect(
        "sw3-closure",
        &[
            "{X_1, R} = 4M²αβ − 4M²αγ − 4 X_1 X_2",
            "{X_2, R} = −2M²α² + 8M²β H + 8M²γ H − 8M H X_1 + 2 X_2²",
            "The table closes: every bracket is a polynomial of degree ≤ 3 in the generators.",
            "8M³α²β + 8M³α²γ + 16M³βγ H + 8M²αγ X_2 + 16M²β H X_1 + 16M²γ H X_1 + 4 X_1 X_2² \
             + R² = 8M³β² H + 8M³γ² H + 4M²α² X_1 + 8M²αβ X_2 + 8M H X_1²",
            "4 claims: 4 proved, 0 refuted",
        ],
    );
}

/// The search through the radical finds the Laplace–Runge–Lenz vector among eight integrals,
/// all generated by the file's seven.
#[test]
fn kepler_in_space_search_finds_eight_integrals() {
    expect(
        "kepler3d-search",
        &[
            "degree |d| ≤ 1 in the radicals: 120 unknowns",
            "Dimension of the space of integrals: 8.",
            "Known integrals in the space: H, L_x, L_y, L_z, A_x, A_y, A_z.",
            "None: the known integrals generate every integral in the space.",
            "8 of them lifted and proved symbolically",
        ],
    );
}

/// The Calogero–Moser system with its rational potential: five independent integrals (the
/// rank through the denominators), and the brackets among them that close at degree 3.
#[test]
fn calogero_moser_is_maximally_superintegrable() {
    expect(
        "calogero-rank",
        &[
            "rank ∂(P, H, I_3, K1, K2)/∂(x, y, z, p_x, p_y, p_z) = 5 [rank proved]",
            "≥ 5: the minor ∂(P, H, I_3, K1, K2)/∂(x, y, z, p_x, p_y) =",
            "1 claim in 1 file: 1 proved, 0 refuted",
        ],
    );
    let out = expect(
        "calogero-closure",
        &[
            "{P, K1} = −P² + 6 H [B1 proved]",
            "{P, K2} = −2 P H + 3 I_3 [B2 proved]",
            "{I_3, K1} = −3 P I_3 + 12 H² [B3 proved]",
            // Collected by the parameter and the momenta, each part over its own
            // denominator.
            "{I_3, K2} = −3 p_x⁴ p_y − 3 p_x⁴ p_z",
            "+ 6g²(2 p_x + 2 p_y − p_z)/(x − y)⁴",
            "{K1, K2} = −x p_x³ p_y",
            "+ 6g²(x + y + 2z)/(x − y)⁴ + 6g²(x + 2y + z)/(x − z)⁴ + 6g²(2x + y + z)/(y − z)⁴",
            "3 claims: 3 proved, 0 refuted",
        ],
    );
    let flat = normalize(&out);
    let relations = flat
        .split("2 Relations")
        .nth(1)
        .expect("a section of relations");
    assert!(relations.contains("None."), "{out}");
    // H is central: its row is all zeros.
    let row = out
        .lines()
        .find(|l| l.trim_start().starts_with("H ") && l.contains('│'))
        .expect("the row of H");
    assert_eq!(
        row.split('│')
            .nth(1)
            .unwrap()
            .split_whitespace()
            .collect::<Vec<_>>(),
        ["0"; 5],
        "{out}"
    );
}

/// The search on the Calogero–Moser system, through its denominators: the integrals of degree
/// `≤ 3` in the momenta and `≤ 1` in the positions are ten, each proved for every `g`, and
/// they span Wojciechowski's `K1` and `K2` (written in them by an exact solve, checked by the
/// zero test) but not `f₂`, which moves (`{f₂, H} = 2H`).
#[test]
fn calogero_search_finds_wojciechowski_integrals() {
    let out = run("calogero-search");
    let flat = normalize(&out);
    for line in [
        "Dimension of the space of integrals: 10.",
        "≤ 0: 1, ≤ 1: 2, ≤ 2: 5, ≤ 3: 10",
        "p_x p_y p_z − g p_x/(y − z)² − g p_y/(x − z)² − g p_z/(x − y)²",
        "10 claims: 10 proved, 0 refuted",
    ] {
        assert!(flat.contains(line), "{line}: {out}");
    }
    let file = system_file("calogero.toml");
    let space = SearchSpace::default()
        .momenta_degree(3)
        .positions_degree(1)
        .denominators_degree(2);
    let found = search(file.system(), &SearchOptions::new(space)).expect("searches");
    assert!(found.all_symbolic());
    let basis: Vec<(brackets::FunctionName, Expr)> = found
        .basis
        .iter()
        .enumerate()
        .map(|(i, f)| {
            let name = format!("J{}", i + 1);
            let label = brackets::FunctionName {
                name: name.clone(),
                display: name,
            };
            (label, f.expr().clone())
        })
        .collect();
    for (name, expected) in [("K1", true), ("K2", true), ("f2", false), ("f3", false)] {
        let target = file.parse_argument(name).expect("parses");
        let written = brackets::table::express(&target, &basis).expect("solves");
        assert_eq!(written.is_some(), expected, "{name}");
    }
    // Higher powers of the denominators add monomials, but no function that is zero.
    let wider = SearchOptions::new(
        SearchSpace::default()
            .momenta_degree(3)
            .positions_degree(1)
            .denominators_degree(4),
    );
    let more = search(file.system(), &wider).expect("searches");
    assert!(more.unknowns > found.unknowns);
    assert_eq!(more.basis.len(), 10);
}

/// `--new-only` on the Calogero–Moser system: with `H` alone known, the new integrals of
/// degree ≤ 3 in the momenta and ≤ 1 in the positions are four (the total momentum, the cubic
/// and Wojciechowski's two), and the file's five generate everything there. At degree ≤ 4 in
/// the momenta and ≤ 2 in the positions three more are new beside those five, and one of them
/// is the Casimir of the sl(2) spanned by `H`, `D = Σ x p` and `Σ x²`: `2H Σx² − D²`, which is
/// no polynomial in the five. Products of integrals are located through the cleared forms, so
/// one written in other monomials of the space counts (`x·P/(x − y) − y·P/(x − y)` is `P`).
#[test]
fn calogero_new_integrals_include_the_sl2_casimir() {
    let flat = normalize(&run("calogero-new"));
    for line in [
        "Dimension of the space of integrals: 23.",
        "Known integrals in the space: H, P, I_3, K1, K2.",
        "the generated ones span 20 of the 23 dimensions",
        // The Casimir, Σ (x_i p_j − x_j p_i)² + …, in the basis's monomials.
        "x² p_y² + x² p_z² − 2xy p_x p_y − 2xz p_x p_z + y² p_x² + y² p_z² − 2yz p_y p_z",
        "4 claims: 4 proved, 0 refuted",
    ] {
        assert!(flat.contains(line), "{line}: {flat}");
    }
    let file = system_file("calogero.toml");
    let h = file.parse_argument("H").expect("parses");
    let bare =
        brackets::System::new("Calogero–Moser, H alone", file.system().space().clone(), h).unwrap();
    let new_ones = |system: &brackets::System, options: SearchOptions| {
        let found = search(system, &options.new_only()).expect("searches");
        let new = found.new.expect("asked for");
        (new.known, new.new.len())
    };
    let small = || {
        SearchOptions::new(
            SearchSpace::default()
                .momenta_degree(3)
                .positions_degree(1)
                .denominators_degree(2),
        )
    };
    assert_eq!(new_ones(&bare, small()), (vec!["H".to_string()], 4));
    assert_eq!(new_ones(file.system(), small()).1, 0);
    let p_apart = file
        .parse_argument("x*P/(x - y) - y*P/(x - y)")
        .expect("parses");
    let (known, new) = new_ones(&bare, small().known("P'", p_apart));
    assert_eq!((known, new), (vec!["H".to_string(), "P'".to_string()], 3));
    // The Casimir known, two are new.
    let casimir = file
        .parse_argument("2*H*(x^2 + y^2 + z^2) - (x*p_x + y*p_y + z*p_z)^2")
        .expect("parses");
    assert!(file.system().flow(&casimir).unwrap().vanishes().unwrap());
    let large = SearchOptions::new(
        SearchSpace::default()
            .momenta_degree(4)
            .positions_degree(2)
            .denominators_degree(2),
    );
    assert_eq!(new_ones(file.system(), large.known("C", casimir)).1, 2);
}

/// The open Toda lattice, its exponentials `e^{q1 − q2}`, `e^{q2 − q3}` named Poisson
/// variables: up to third order in the momenta and first in them, the file's `H`, `P` and `I3`
/// generate every integral; from `H` alone the total momentum and the cubic integral come out
/// new, the cubic as the file writes it. Up to fourth order and second in the exponentials,
/// `H`, `P`, `I3` still generate all 11 dimensions.
#[test]
fn toda_search_finds_the_cubic_integral_from_h_alone() {
    expect(
        "toda-search",
        &[
            "60 unknowns",
            "Dimension of the space of integrals: 7.",
            "Known integrals in the space: H, P, I₃.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    let text = run_on_hamiltonian_alone("toda-search");
    for piece in [
        "Known integrals in the space: H.",
        "I2 = p_q1 + p_q2 + p_q3",
        "I5 = p_q1 p_q2 p_q3 − a2 p_q1 − a1 p_q3",
        "3 claims: 3 proved, 0 refuted",
    ] {
        assert!(text.contains(piece), "{piece}: {text}");
    }
    expect(
        "toda-search-4",
        &[
            "210 unknowns",
            "Dimension of the space of integrals: 11.",
            "the generated ones span the whole space (11 dimensions)",
            "None: the known integrals generate every integral in the space.",
        ],
    );
}

/// The 1 : 3 oscillator of Fokas and Lagerstrom: up to third order in the momenta the file's
/// `H`, `H_x` and `S` generate every integral, and from `H` alone the search finds the other
/// separated energy and the cubic integral, as the file writes it (`3(x p_y − y p_x) p_x² −
/// …`, expanded). With the quartic `C` they close into a cubic algebra, tied by one relation
/// of degree 4.
#[test]
fn fokas_lagerstrom_cubic_integral_and_its_cubic_algebra() {
    expect(
        "fl-search",
        &[
            "100 unknowns",
            "Dimension of the space of integrals: 4.",
            "Known integrals in the space: H, H_x, S.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    let text = run_on_hamiltonian_alone("fl-search");
    for piece in [
        "Known integrals in the space: H.",
        "I2 = p_y² + 9M²ω²y²",
        "I4 = 3x p_x² p_y − 3y p_x³ − M²ω²x³ p_y + 9M²ω²x²y p_x",
        "3 claims: 3 proved, 0 refuted",
    ] {
        assert!(text.contains(piece), "{piece}: {text}");
    }
    expect(
        "fl-closure",
        &[
            "The table closes",
            "{H_x, S} = −3 C/M [B1 proved]",
            "{H_x, C} = 3Mω² S [B2 proved]",
            "{S, C} = 24M³(3 H − 4 H_x) H_x² [B3 proved]",
            "16 H H_x³ = 16 H_x⁴ + ω² S²/M² + C²/M⁴ [R1 proved]",
        ],
    );
}

/// Checks every claim of `file`, each as expected, and the claims' ids in the file's order:
/// `proved` ones first, then the `refuted` false neighbours.
fn assert_claims_as_expected(
    file: &superint::system_file::LoadedSystem,
    proved: &[&str],
    refuted: &[&str],
) {
    let report = superint::system_file::check_report([file]).expect("checked");
    assert!(report.all_as_expected());
    let expected: Vec<(String, bool)> = (proved.iter().map(|id| (id.to_string(), true)))
        .chain(refuted.iter().map(|id| (id.to_string(), false)))
        .collect();
    assert_eq!(report.claim_ids(), expected);
}

/// The caged anisotropic oscillator 1:2 of Evans and Verrier, loaded and checked: every claim
/// of the file holds for every `ω, α, β` (the ladders, the quartic `K` and the quintic `Q`, the
/// algebra and its relation, the limits `β = 0` and `α = β = 0`, the ranks), and each of its
/// eight false neighbours is refuted: the `V_II` integral `X` with the barrier on `y`, `K` with
/// its `β` halved, the integrals of the ratios 1:1 and 1:3, the ladder without its barrier, a
/// sign in `{K, Q}`, `|B|²` with `16ω²β` for `32ω²β`, and rank 4.
#[test]
fn caged_oscillator_claims_are_proved_and_its_false_neighbours_refuted() {
    let file = system_file("caged-oscillator-1-2.toml");
    assert_claims_as_expected(
        &file,
        &[
            "ladders",
            "separable",
            "quartic",
            "quintic",
            "real-part",
            "modulus",
            "algebra",
            "relation",
            "rank",
            "limit-v-ii",
            "limit-oscillator",
        ],
        &[
            "false-v-ii-integral",
            "false-coefficient",
            "false-1-1-ratio",
            "false-1-3-ratio",
            "false-uncaged-ladder",
            "false-algebra",
            "false-modulus",
            "false-rank",
        ],
    );
}

/// The caged oscillator 1:2: up to fifth order in the momenta, for every `ω, α, β`, the file's
/// `H`, `H_x`, `K` and `Q` generate every integral, and there is none of third order beyond
/// products; from `H` alone the search finds the other separated energy, the quartic `K` and
/// the quintic `Q`, as the file writes them (expanded). They close into a polynomial algebra,
/// for every value of the parameters, tied by one relation of degree 4.
#[test]
fn caged_oscillator_quartic_and_quintic_integrals_and_their_polynomial_algebra() {
    expect(
        "caged-search",
        &[
            "83055 unknowns",
            "(a parameter's multiple of an integral counts apart from it): 60.",
            "≤ 2: 55, ≤ 3: 55, ≤ 4: 59, ≤ 5: 60.",
            "Known integrals in the space: H, H_x, K, Q.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    let text = expect_alone(
        "caged-search",
        &[
            "Known integrals in the space: H.",
            "I36 = p_y² + 4ω²y² + 2β/y²",
            "I59 = x² p_x² p_y² − 2xy p_x³ p_y + y² p_x⁴ + 2ω²x³y p_x p_y − 2ω²x²y² p_x² \
             + 2βx² p_x²/y² + 4αy² p_x²/x² − 4αy p_x p_y/x + ω⁴x⁴y² − 4ω²αy² + 4α²y²/x⁴",
            "I60 = x p_x³ p_y² − y p_x⁴ p_y − ω²x³ p_x p_y² + 6ω²x²y p_x² p_y − 4ω²xy² p_x³ \
             + 2βx p_x³/y² − 4αy p_x² p_y/x² + 2α p_x p_y²/x − ω⁴x⁴y p_y + 4ω⁴x³y² p_x \
             − 2ω²βx³ p_x/y² − 8ω²αy² p_x/x + 4ω²αy p_y − 4α²y p_y/x⁴ + 4αβ p_x/(xy²)",
            "4 claims: 4 proved, 0 refuted",
        ],
    );
    assert_eq!(text.matches(" = 0 [I").count(), 3, "{text}");
    expect(
        "caged-closure",
        &[
            "The table closes",
            "{H_x, K} = −2 Q [B1 proved]",
            "{H_x, Q} = 16ω²α H − 16ω²α H_x + 8ω² K − 8 H H_x² + 8 H_x³ [B2 proved]",
            "{K, Q} = 256ω²αβ H_x + 16ω²α K − 128β H_x³ + 16 H H_x K − 24 H_x² K [B3 proved]",
            "128ω⁴α²β + 16ω²α H K + 4ω² K² + 32β H_x⁴ + 8 H_x³ K + Q² = 128ω²αβ H_x² \
             + 16ω²α H_x K + 8 H H_x² K [R1 proved]",
        ],
    );
}

/// The Higgs oscillator, the isotropic oscillator on the sphere of curvature `λ` in gnomonic
/// coordinates, loaded and checked: every claim of the file holds for every `λ, ω` (its
/// Hamiltonian is Higgs's `(π² + λL²)/2 + ω²r²/2`, the rotations `{π_x, π_y} = λL`, `L` and the
/// Higgs tensor conserved, the tensor's quadratic algebra and the cubic Higgs algebra with its
/// Casimir, the ranks, the plane at `λ = 0`), and each of its eight false neighbours is refuted:
/// the flat Fradkin component, the tensor under the Hamiltonian without its factor `1 + λr²`,
/// `π` with its sign turned, the cubic term's sign, the term `2λHL` halved, the flat
/// `{T11, T12}`, the Casimir without its `λ` terms, and rank 4.
#[test]
fn higgs_oscillator_claims_are_proved_and_its_false_neighbours_refuted() {
    let file = system_file("higgs-oscillator.toml");
    assert_claims_as_expected(
        &file,
        &[
            "higgs-form",
            "rotations",
            "angular",
            "tensor",
            "found",
            "trace",
            "algebra",
            "higgs-algebra",
            "relation",
            "rank",
            "limit-plane",
        ],
        &[
            "false-fradkin",
            "false-conformal-factor",
            "false-momentum-sign",
            "false-cubic-sign",
            "false-cubic-coefficient",
            "false-flat-algebra",
            "false-relation",
            "false-rank",
        ],
    );
    // The factor 1 + λr² is the sphere's: without it the tensor is conserved only at λ = 0.
    let parse = |s: &str| file.parse_argument(s).expect("parses");
    let flat_metric = brackets::System::new(
        "the Higgs oscillator without 1 + λr²",
        file.system().space().clone(),
        parse("(p_x^2 + p_y^2 + lambda*(x*p_x + y*p_y)^2)/2 + omega^2*(x^2 + y^2)/2"),
    )
    .unwrap();
    for t in ["T11", "T12", "T22"] {
        assert!(file.system().flow(&parse(t)).unwrap().is_zero(), "{t}");
        assert!(!flat_metric.flow(&parse(t)).unwrap().is_zero(), "{t}");
    }
}

/// The Higgs oscillator: up to second order in the momenta and fourth in the positions, for
/// every `λ, ω`, the file's `H`, `L` and the Higgs tensor generate every integral; from `H`
/// alone the search finds `L` and the tensor's components `T22` and `T12`, which read back as
/// the file's functions. With `K = (T11 − T22)/2` they close into the cubic Higgs algebra,
/// `{K, T12} = 2ω²L + 2λHL − λ²L³`, tied by one relation of degree 4, the Casimir
/// `K² + T12² = (H − λL²/2)² − ω²L²`; in the tensor's components the brackets are quadratic,
/// with `T11 + T22 = 2H − λL²` and `T11 T22 − T12² = ω²L²` its two relations.
#[test]
fn higgs_oscillator_tensor_found_from_h_alone_and_its_cubic_higgs_algebra() {
    expect(
        "higgs-search",
        &[
            "540 unknowns",
            "(a parameter's multiple of an integral counts apart from it): 21.",
            "≤ 0: 6, ≤ 1: 12, ≤ 2: 21.",
            "Known integrals in the space: H, L, T_11, T_12, T_22, K.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    let t22 = "λ²x²y² p_x² + 2λ²xy³ p_x p_y + 2λxy p_x p_y + λ²y⁴ p_y² + 2λy² p_y² + p_y² + ω²y²";
    let t12 = "λ²x³y p_x² + 2λ²x²y² p_x p_y + λx² p_x p_y + λ²xy³ p_y² + λxy p_x² + λxy p_y² \
               + λy² p_x p_y + p_x p_y + ω²xy";
    let text = expect_alone(
        "higgs-search",
        &[
            "Known integrals in the space: H.",
            "I7 = x p_y − y p_x",
            &format!("I19 = {t22}"),
            &format!("I20 = {t12}"),
            "4 claims: 4 proved, 0 refuted",
        ],
    );
    assert_eq!(text.matches(" = 0 [I").count(), 3, "{text}");
    // The integrals found, read back as printed, are the file's T22 and T12.
    let file = system_file("higgs-oscillator.toml");
    let parse = |s: &str| file.parse_argument(s).expect("parses");
    assert_eq!(parse(t22), parse("T22"));
    assert_eq!(parse(t12), parse("T12"));
    assert_eq!(parse("T11"), parse("2*H - lambda*L^2 - T22"));
    expect(
        "higgs-closure",
        &[
            "The table closes",
            "{L, K} = 2 T_12 [B1 proved]",
            "{L, T_12} = −2 K [B2 proved]",
            "{K, T_12} = −(λ² L² − 2λ H − 2ω²) L [B3 proved]",
            "λ² L⁴ + 4 H² = 4λ H L² + 4ω² L² + 4 K² + 4 T_12² [R1 proved]",
            "4 claims: 4 proved, 0 refuted",
        ],
    );
    expect(
        "higgs-closure-tensor",
        &[
            "The table closes",
            "{L, T_11} = 2 T_12 [B1 proved]",
            "{L, T_12} = −T_11 + T_22 [B2 proved]",
            "{L, T_22} = −2 T_12 [B3 proved]",
            "{T_11, T_12} = 2(λ T_11 + ω²) L [B4 proved]",
            "{T_11, T_22} = 4λ L T_12 [B5 proved]",
            "{T_12, T_22} = 2(λ T_22 + ω²) L [B6 proved]",
            "λ L² + T_11 + T_22 = 2 H [R1 proved]",
            "ω² L² + T_12² = T_11 T_22 [R2 proved]",
            "8 claims: 8 proved, 0 refuted",
        ],
    );
}

/// The Higgs tensor's relations of degree 2 are two, the trace `T11 + T22 = 2H − λL²` and the
/// determinant `T11 T22 − T12² = ω²L²`: their combination
/// `λ T11 T22 + ω² T11 + ω² T22 = λ T12² + 2ω² H` (λ times the determinant's, ω² times the
/// trace's) is found too, and is no longer listed as a relation of its own, as it was while the
/// relations were minimal over Q with a parameter's multiple counting apart.
#[test]
fn higgs_tensor_relations_are_minimal_over_the_polynomials_in_the_parameters() {
    let file = system_file("higgs-oscillator.toml");
    let system = file.system();
    let vars = system.vars();
    let (lambda, omega) = (
        vars.lookup("lambda").unwrap(),
        vars.lookup("omega").unwrap(),
    );
    let options = ClosureOptions::new(2)
        .symbolic(lambda)
        .symbolic(omega)
        .parameters_degree(2);
    let c = closure(system, &["H", "L", "T11", "T12", "T22"], &options).expect("computed");
    assert!(c.closes() && c.all_symbolic());
    let read = |s: &str| Expr::parse(&c.ring, s).expect("parses");
    let trace = read("T11 + T22 - 2*H + lambda*L^2");
    let determinant = read("T11*T22 - T12^2 - omega^2*L^2");
    let listed: Vec<&Expr> = c.relations.iter().map(|r| &r.poly).collect();
    assert_eq!(listed.len(), 2, "{:?}", c.relations);
    for (r, e) in listed.iter().zip([&trace, &determinant]) {
        assert!(**r == *e || **r == -e, "{r} is not ±({e})");
    }
    assert!(c.relations.iter().all(|r| r.degree == 2 && r.symbolic));
    // The relation left out is the combination, an identity of the ring.
    let combination =
        read("lambda*T11*T22 + omega^2*T11 + omega^2*T22 - lambda*T12^2 - 2*omega^2*H");
    let generated = read("lambda")
        .checked_mul(&determinant)
        .unwrap()
        .checked_add(&read("omega^2").checked_mul(&trace).unwrap())
        .unwrap();
    assert_eq!(combination, generated);
    // Each listed relation holds in phase space, read back in the file's functions.
    for relation in [
        "T11 + T22 - 2*H + lambda*L^2",
        "T11*T22 - T12^2 - omega^2*L^2",
    ] {
        assert!(
            file.parse_argument(relation).expect("parses").is_zero(),
            "{relation}"
        );
    }
}

/// The Stark problem, the Kepler problem in space in a uniform field `F` along `z`, loaded and
/// checked: every claim of the file holds for every `M, k, F` (the torque on `L_x`, `L_y`, `L_z`
/// conserved, the rate `F(x p_x + y p_y)/M` of `A_z` and of the correction, Redmond's
/// `B_z = A_z − F(x² + y²)/2` conserved and in involution with `L_z`, the Kepler problem at
/// `F = 0`, rank 3), and each of its five false neighbours is refuted: `A_z` conserved, the
/// correction with its sign turned, doubled, or over `x² + y² + z²`, and `L_x` conserved.
#[test]
fn stark_problem_claims_are_proved_and_its_false_neighbours_refuted() {
    let file = system_file("stark.toml");
    assert_claims_as_expected(
        &file,
        &[
            "torque",
            "axial",
            "field-rate",
            "correction-rate",
            "redmond",
            "found",
            "involution",
            "kepler-limit",
            "rank",
        ],
        &[
            "false-lrl",
            "false-field-sign",
            "false-field-coefficient",
            "false-field-radius",
            "false-transverse",
        ],
    );
    // The correction's coefficient 1/2 is the only one: {A_z − cF(x² + y²), H} is
    // (1 − 2c) F(x p_x + y p_y)/M.
    let parse = |s: &str| file.parse_argument(s).expect("parses");
    for (c, factor) in [
        ("0", "1"),
        ("1/4", "1/2"),
        ("1/2", "0"),
        ("1", "-1"),
        ("-1/2", "2"),
    ] {
        let corrected = format!("Az - ({c})*F*(x^2 + y^2)");
        let rate = format!("({factor})*F*(x*p_x + y*p_y)/M");
        assert!(
            parse(&format!("{{{corrected}, H}} - {rate}"))
                .vanishes()
                .unwrap(),
            "c = {c}"
        );
        // With the radical, zero is decided by reducing r² (`vanishes`), not term by term.
        let conserved = file.system().flow(&parse(&corrected)).unwrap();
        let conserved = conserved.vanishes().unwrap();
        assert_eq!(conserved, c == "1/2", "c = {c}");
    }
}

/// The Stark problem: up to second order in the momenta and the positions, for every `M, k, F`,
/// the file's `H`, `L_z` and `B_z` generate every integral; from `H` alone the search finds `L_z`
/// and Redmond's integral, `−2M B_z` as the file writes it. Up to fourth order in the momenta
/// and the positions and second in `r`, nothing is new either: the field leaves no integral of
/// the Kepler problem's other four, and the system is integrable, not superintegrable, as far
/// as that space sees.
#[test]
fn stark_search_finds_the_field_corrected_runge_lenz_component_from_h_alone() {
    expect(
        "stark-search",
        &[
            "2900 unknowns",
            "(a parameter's multiple of an integral counts apart from it): 32.",
            "≤ 0: 10, ≤ 1: 20, ≤ 2: 32.",
            "Known integrals in the space: H, L_z, B_z.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    let text = expect_alone(
        "stark-search",
        &[
            "Known integrals in the space: H.",
            "I11 = x p_y − y p_x",
            "I22 = 2x p_x p_z + 2y p_y p_z − 2z p_x² − 2z p_y² + MFx² + MFy² + 2Mkz/r",
            "3 claims: 3 proved, 0 refuted",
        ],
    );
    assert_eq!(text.matches(" = 0 [I").count(), 2, "{text}");
    expect(
        "stark-search-4",
        &[
            "5075 unknowns",
            "Dimension of the space of integrals: 14. By degree in the momenta: ≤ 0: 1, ≤ 1: 2, \
             ≤ 2: 5, ≤ 3: 8, ≤ 4: 14.",
            "Known integrals in the space: H, L_z, B_z.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
}

/// A relation of the same degree that no parameter multiple of another gives is still listed:
/// with `P = a x` and `Q = a y + a² x`, `P = aU` and `Q = aV + aP` (the second with no
/// multiple of the first: it has `Q` and `V`), both of degree 1, and nothing else up to degree
/// 2 in the generators and 2 in `a` (`a²U`, `aU²`, … are multiples of the first). The
/// kernel's vector for the second is `Q = aV + a²U`, which differs from the one listed by `a`
/// times the first: the simpler, of lower parameters, is listed.
#[test]
fn an_independent_relation_of_the_same_degree_is_still_listed() {
    let text = "name = \"independent\"\n\
                hamiltonian = \"(p_x^2 + p_y^2)/2\"\n\
                [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\"]\n\
                [[function]]\nname = \"U\"\nvalue = \"x\"\n\
                [[function]]\nname = \"V\"\nvalue = \"y\"\n\
                [[function]]\nname = \"P\"\nvalue = \"a*x\"\n\
                [[function]]\nname = \"Q\"\nvalue = \"a*y + a^2*x\"\n";
    let file = load_str("independent.toml", text, &LimitsOverride::default()).expect("loads");
    let system = file.system();
    let a = system.vars().lookup("a").unwrap();
    let options = ClosureOptions::new(2).symbolic(a).parameters_degree(2);
    let c = closure(system, &["U", "V", "P", "Q"], &options).expect("computed");
    let listed: Vec<String> = c.relations.iter().map(|r| r.poly.to_string()).collect();
    assert_eq!(listed.len(), 2, "{listed:?}");
    let read = |s: &str| Expr::parse(&c.ring, s).expect("parses");
    for (r, e) in c
        .relations
        .iter()
        .zip([read("P - a*U"), read("Q - a*V - a*P")])
    {
        assert!(r.poly == e || r.poly == -&e, "{} is not ±({e})", r.poly);
        assert!(r.degree == 1 && r.symbolic);
    }
}

/// A generator with the prime `2⁶² − 57` in a denominator, `X = L/p`, has its relations'
/// span formed over Q (`L = pX` has no value modulo p), grown by the multiples of each
/// relation listed before the next is tested: at degree 3 the three listed are `L = pX` and
/// the Higgs tensor's two written in `X`, and none of their multiples (a span over Q formed
/// once and not grown lists them too).
#[test]
fn a_closure_over_the_primes_denominator_lists_only_minimal_relations() {
    let o = superint(&[
        "closure",
        "systems/higgs-oscillator.toml",
        "X",
        "H",
        "L",
        "T11",
        "T12",
        "T22",
        "--define",
        "X=L/4611686018427387847",
        "--degree",
        "3",
        "--symbolic",
        "lambda,omega",
        "--parameters-degree",
        "2",
        "--no-timings",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let text = normalize(&String::from_utf8(o.stdout).expect("UTF-8"));
    let p2 = "21267647932558653440728706863763295409";
    for piece in [
        "4611686018427387847 X = L [R1 proved]".to_string(),
        format!("{p2}λ X² + T_11 + T_22 = 2 H [R2 proved]"),
        format!("{p2}ω² X² + T_12² = T_11 T_22 [R3 proved]"),
    ] {
        assert!(text.contains(&piece), "{piece}: {text}");
    }
    assert!(!text.contains("[R4"), "{text}");
}

/// With `M` kept symbolic, `{H_x, S} = −3C/M` has a coefficient that no `--parameters-degree`
/// makes a polynomial in `M`: the advice under the table says so and what to do (it named only
/// higher degrees), and with `M` left out of `--symbolic` (fixed, then lifted) the table closes.
#[test]
fn a_closure_with_a_symbolic_divisor_says_to_leave_it_out() {
    let file = "systems/fokas-lagerstrom-1-3.toml";
    let args = [
        "closure",
        file,
        "H",
        "Hx",
        "S",
        "C",
        "--degree",
        "3",
        "--parameters-degree",
        "6",
        "--no-timings",
        "--symbolic",
    ];
    let both = superint(&[&args[..], &["M,omega"]].concat());
    assert_eq!(both.status.code(), Some(0));
    let text = normalize(&String::from_utf8(both.stdout).expect("UTF-8"));
    assert!(
        text.contains(
            "a coefficient that divides by a parameter (1/M) is no polynomial in it at any \
             degree: leave that parameter out of --symbolic, and it is fixed and lifted back by \
             homogeneity."
        ),
        "{text}"
    );
    let omega = superint(&[&args[..], &["omega"]].concat());
    assert_eq!(omega.status.code(), Some(0));
    let text = normalize(&String::from_utf8(omega.stdout).expect("UTF-8"));
    assert!(text.contains("The table closes"), "{text}");
    assert!(text.contains("{H_x, S} = −3 C/M [B1 proved]"), "{text}");
}

/// A degree above 0 for a kind of variable the system lacks would bound nothing, and the
/// search would run as if it were not given: it is refused, naming what the system lacks. A
/// degree 0 says the same as the space already does, and is accepted.
#[test]
fn a_degree_for_variables_the_system_lacks_is_refused() {
    let refused = [
        (
            vec!["systems/kepler.toml", "--poisson-degree", "4"],
            "--poisson-degree: the Kepler problem has no Poisson variables",
        ),
        (
            vec!["systems/euler-top.toml", "--trig-degree", "1"],
            "--trig-degree: the Euler top has no angles",
        ),
        (
            vec!["systems/euler-top.toml", "--momenta-degree", "3"],
            "--momenta-degree: the Euler top has no canonical momenta",
        ),
        (
            vec!["systems/kepler.toml", "--radicals-degree", "2"],
            "--radicals-degree: the Kepler problem has no radicals",
        ),
        // No coordinates at all: it said "no coordinates other than angles" of a top, which
        // has no angles either.
        (
            vec!["systems/euler-top.toml", "--laurent"],
            "--laurent: the Euler top has no coordinates, so it would bound nothing",
        ),
        (
            vec!["systems/euler-top.toml", "--positions-degree", "2"],
            "--positions-degree: the Euler top has no coordinates, so it would bound nothing",
        ),
    ];
    for (args, message) in refused {
        let out = superint(&[&["search"], &args[..]].concat());
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(message), "{args:?}: {stderr}");
    }
    let out = superint(&["search", "systems/euler-top.toml", "--trig-degree", "0"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Renders a report as text without timings, its whitespace normalized.
fn text_of(report: &superint::report::Report) -> String {
    let options = superint::render::Options::reproducible();
    normalize(&superint::render::render(
        report,
        superint::render::Format::Text,
        &options,
    ))
}

/// Whether `text` names an option of the command line (`--fix`) or a command
/// (`superint search`).
fn names_a_flag(text: &str) -> bool {
    text.contains("--") || text.contains("superint ")
}

/// A program's search report advises the library's options (`SearchOptions::symbolic`,
/// `SearchSpace::parameters_degree`), which it can set, not the command line's flags, which it
/// has none of; built for the command line, it names the flags, as `superint search` prints.
#[test]
fn a_programs_search_report_names_the_librarys_options() {
    use superint::discovery::{parse_symbolic, search_report, search_report_for};
    use superint::system_file::{load_str, Caller};

    // The Garnier system at a = b = 1 has x p_y − y p_x, which it loses for a ≠ b.
    let garnier = load_str(
        "garnier.toml",
        "name = \"Garnier\"\nhamiltonian = \"(p_x^2 + p_y^2)/2 + (x^2 + y^2)^2 + a*x^2 + b*y^2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\", \"b\"]\n",
        &LimitsOverride::default(),
    )
    .expect("the file loads");
    let options = SearchOptions::new(SearchSpace::default().momenta_degree(2).positions_degree(4));
    let (report, _) = search_report("Garnier", garnier.system(), &options).expect("searches");
    let text = text_of(&report);
    assert!(
        text.contains(
            "keep them symbolic (SearchOptions::symbolic), or compare with other values \
             (SearchOptions::fix, such as a = 2, b = 3)."
        ),
        "{text}"
    );
    assert!(!names_a_flag(&text), "{text}");
    let latex = superint::render::render(
        &report,
        superint::render::Format::Latex,
        &superint::render::Options::reproducible(),
    );
    assert!(
        latex.contains(r"(\texttt{SearchOptions::symbolic})"),
        "{latex}"
    );
    let (cli, _) = search_report_for("Garnier", garnier.system(), &options, Caller::CommandLine)
        .expect("searches");
    assert_eq!(cli.caller, Caller::CommandLine);
    assert!(
        text_of(&cli).contains(
            "keep them symbolic (--symbolic a,b), or compare with other values (--fix a=2,b=3)"
        ),
        "{}",
        text_of(&cli)
    );

    // H has degree 2 in a, b, past a space of degree 1 in them.
    let oscillator = load_str(
        "oscillator.toml",
        "name = \"oscillator\"\nhamiltonian = \"(p_x^2 + p_y^2)/2 + (a^2*x^2 + b^2*y^2)/2\"\n\
         [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\", \"b\"]\n",
        &LimitsOverride::default(),
    )
    .expect("the file loads");
    let system = oscillator.system();
    let mut options = SearchOptions::new(
        SearchSpace::default()
            .momenta_degree(2)
            .positions_degree(2)
            .parameters_degree(1),
    );
    options.symbolic = parse_symbolic(system, "a,b").expect("parameters");
    let (report, _) = search_report("the oscillator", system, &options).expect("searches");
    let text = text_of(&report);
    assert!(
        text.contains(
            "Note: H has degree 2 in a, b, past the space's 1 (SearchSpace::parameters_degree)"
        ),
        "{text}"
    );
    assert!(!names_a_flag(&text), "{text}");
}

/// A program's closure report that does not close advises `ClosureOptions::degree` (with
/// parameters kept symbolic, `ClosureOptions::parameters_degree` and `ClosureOptions::symbolic`
/// too) and `search_report`, not `--degree` and `superint search`.
#[test]
fn a_programs_closure_report_names_the_librarys_options() {
    use brackets::closure::ClosureOptions;
    use brackets::NamedFunction;
    use superint::discovery::{closure_report, closure_report_for, parse_symbolic};
    use superint::system_file::Caller;

    // {L, G1} = −G2 is no polynomial of degree 1 in L and G1, both integrals.
    let rotor = brackets::systems::harmonic_rotor();
    let generators: Vec<NamedFunction> = ["L", "G1"]
        .iter()
        .map(|&n| NamedFunction::new(n, n, rotor.get(n).expect("defined").clone()))
        .collect();
    let options = ClosureOptions::new(1);
    let (report, algebra) =
        closure_report("the harmonic rotor", &rotor, &generators, &options).expect("computes");
    assert!(!algebra.closes());
    let text = text_of(&report);
    assert!(
        text.contains(
            "A higher ClosureOptions::degree, or what discovery::search_report finds added to \
             the generators, may close the table."
        ),
        "{text}"
    );
    assert!(!names_a_flag(&text), "{text}");
    let (cli, _) = closure_report_for(
        "the harmonic rotor",
        &rotor,
        &generators,
        &options,
        Caller::CommandLine,
    )
    .expect("computes");
    assert!(
        text_of(&cli).contains(
            "A higher --degree, or what superint search finds added to the generators, may \
             close the table."
        ),
        "{}",
        text_of(&cli)
    );

    let mut options = ClosureOptions::new(1);
    options.symbolic = parse_symbolic(&rotor, "omega").expect("a parameter");
    let (report, _) =
        closure_report("the harmonic rotor", &rotor, &generators, &options).expect("computes");
    let text = text_of(&report);
    assert!(
        text.contains(
            "A higher ClosureOptions::degree or ClosureOptions::parameters_degree, or what \
             discovery::search_report finds added to the generators, may close the table;"
        ),
        "{text}"
    );
    assert!(
        text.contains("leave that parameter out of ClosureOptions::symbolic, and it is fixed"),
        "{text}"
    );
    assert!(!names_a_flag(&text), "{text}");
}

/// The Fock–Darwin system, the planar oscillator in a uniform magnetic field with the
/// normal-mode frequencies `a = ω₊`, `b = ω₋`, loaded and checked: every claim of the file holds
/// (the textbook form with `ω_c = a − b`, `ω₀² = ab`, the ladders `{Z, H} = ibZ`,
/// `{W, H} = iaW`, their Heisenberg brackets, `H` and `L` in `|Z|²` and `|W|²`, the tower and
/// the rotation of `K_{m,n} = W^m Z̄^n`, the resonances 1:2 and 1:3, the integrals the search
/// finds, the cubic algebra at 1:2 and its relation, the Landau and isotropic limits, the
/// ranks), and each of its seven false neighbours is refuted.
#[test]
fn fock_darwin_claims_are_proved_and_its_false_neighbours_refuted() {
    let file = system_file("fock-darwin.toml");
    assert_claims_as_expected(
        &file,
        &[
            "textbook",
            "ladders",
            "heisenberg",
            "modes",
            "angular",
            "tower",
            "rotation",
            "resonance",
            "found",
            "algebra",
            "relation",
            "landau",
            "isotropic",
            "rank",
        ],
        &[
            "false-eigenvalue-sign",
            "false-eigenvalues-swapped",
            "false-off-resonance",
            "false-resonance",
            "false-landau",
            "false-confinement",
            "false-relation",
        ],
    );
    // {P_{m,n}, H} = −(ma − nb) Q_{m,n}, with Q_{m,n} ≠ 0: P_{m,n} is conserved exactly on the
    // resonance ma = nb, and at a = 2b exactly when m = 2n... that is, for (1, 2) and (2, 4).
    let parse = |s: &str| file.parse_argument(s).expect("parses");
    let system = file.system();
    let vars = system.vars();
    let at_1_2 = brackets::Condition::new("a = 2b", vars.lookup("a").unwrap(), parse("2*b"));
    for m in 0..=2 {
        for n in 0..=4 {
            if m + n == 0 {
                continue;
            }
            let flow = system.flow(&parse(&format!("P_{m}_{n}"))).unwrap();
            let rate = parse(&format!("-({m}*a - {n}*b)*Q_{m}_{n}"));
            assert_eq!(flow, rate, "P_{m}_{n}");
            assert!(!parse(&format!("Q_{m}_{n}")).is_zero(), "Q_{m}_{n}");
            let resonant = at_1_2.apply(&flow).unwrap().is_zero();
            assert_eq!(resonant, 2 * m == n, "P_{m}_{n} at a = 2b");
        }
    }
}

/// The tower of the Fock–Darwin system: `{K_{m,n}, H} = i(ma − nb) K_{m,n}` expanded for
/// `1 ≤ m, n ≤ 6` and proved for all `m, n ≥ 0` from the ladders `W` and `Z̄`, for every `a, b`
/// and at the resonance `a = 2b`.
#[test]
fn fock_darwin_tower_is_proved_for_all_m_and_n() {
    for when in [None, Some("a = 2*b")] {
        let mut args = vec![
            "tower",
            "--system",
            "systems/fock-darwin.toml",
            "--max",
            "6",
            "--no-timings",
        ];
        if let Some(w) = when {
            args.extend(["--when", w]);
        }
        let out = superint(&args);
        let text = normalize(&String::from_utf8(out.stdout).expect("UTF-8"));
        assert_eq!(out.status.code(), Some(0), "{text}");
        for piece in [
            "36 brackets expanded for the Fock–Darwin system (ladder K_{m,n} = W^m Z̄^n), all hold",
            "1. computed: {W, H} = i ω₊ W holds",
            "2. computed: {Z̄, H} = −i ω₋ Z̄ holds",
            "Therefore: {K_{m,n}, H} = i(m ω₊ − n ω₋) K_{m,n} for all m, n ≥ 0.",
            // The file's display: `a` and `b` print as the normal-mode frequencies.
            "λ(m, n) = i(m ω₊ − n ω₋) equals mλ(1, 0) + nλ(0, 1)",
            "2 claims in 1 file: 2 proved, 0 refuted; all as expected",
        ] {
            assert!(text.contains(piece), "{when:?}: {piece}: {text}");
        }
    }
}

/// The Fock–Darwin system at the resonance `a = 2b`: up to third order, for every `M, b`, the
/// search finds two integrals that `H`, `L` and their products do not generate, the cubic
/// `8 P_{1,2}` and `−8 Q_{1,2}`, the parts of `W Z̄²` (the file's families, which it does not
/// know); with them known nothing is new, nor up to fourth order. At `a = 3b` the new ones are
/// quartic (`−Q_{1,3}/4` among them), at `b = 0` (the Landau problem) linear, the guiding
/// centre `2 Re Z` and `2 Im Z`, and for every `a, b` there is none beyond `H` and `L`.
#[test]
fn fock_darwin_search_finds_the_resonant_integrals() {
    // As printed, `b` shown as ω₋ (`[phase_space] display`), and as it reads back.
    let i91 = "24 p_x² p_y − 8 p_y³ + 12M ω₋ x p_x² − 12M ω₋ x p_y² − 24M ω₋ y p_x p_y \
               + 18M² ω₋² x² p_y + 36M² ω₋² xy p_x − 18M² ω₋² y² p_y + 27M³ ω₋³ x³ \
               − 81M³ ω₋³ xy²";
    let i91_ascii = "24*p_x^2*p_y - 8*p_y^3 + 12*M*b*x*p_x^2 - 12*M*b*x*p_y^2 \
                     - 24*M*b*y*p_x*p_y + 18*M^2*b^2*x^2*p_y + 36*M^2*b^2*x*y*p_x \
                     - 18*M^2*b^2*y^2*p_y + 27*M^3*b^3*x^3 - 81*M^3*b^3*x*y^2";
    let i92 = "8 p_x³ − 24 p_x p_y² − 24M ω₋ x p_x p_y − 12M ω₋ y p_x² + 12M ω₋ y p_y² \
               + 18M² ω₋² x² p_x − 36M² ω₋² xy p_y − 18M² ω₋² y² p_x − 81M³ ω₋³ x²y \
               + 27M³ ω₋³ y³";
    let i92_ascii = "8*p_x^3 - 24*p_x*p_y^2 - 24*M*b*x*p_x*p_y - 12*M*b*y*p_x^2 \
                     + 12*M*b*y*p_y^2 + 18*M^2*b^2*x^2*p_x - 36*M^2*b^2*x*y*p_y \
                     - 18*M^2*b^2*y^2*p_x - 81*M^3*b^3*x^2*y + 27*M^3*b^3*y^3";
    let text = normalize(&expect(
        "fd-search",
        &[
            "2800 unknowns",
            "(a parameter's multiple of an integral counts apart from it): 126.",
            "≤ 0: 28, ≤ 1: 56, ≤ 2: 90, ≤ 3: 126.",
            "Known integrals in the space: H, L.",
            "the generated ones span 124 of the 126 dimensions",
            // Each restated in the file's family instances, below it.
            &format!("I91 = {i91} = −8 Q_{{1,2}}"),
            &format!("I92 = {i92} = 8 P_{{1,2}}"),
            "3 claims: 3 proved, 0 refuted",
        ],
    ));
    assert_eq!(text.matches(" = 0 at ω₊ = 2 ω₋ [I").count(), 2, "{text}");
    // From H alone, the same two.
    let alone = run_on_hamiltonian_alone("fd-search");
    assert!(
        alone.contains("Known integrals in the space: H."),
        "{alone}"
    );
    assert!(alone.contains(&normalize(&format!("= {i91}"))), "{alone}");
    assert!(alone.contains(&normalize(&format!("= {i92}"))), "{alone}");
    // Read back, they are 8 P_{1,2} and −8 Q_{1,2} at a = 2b.
    let file = system_file("fock-darwin.toml");
    let parse = |s: &str| file.parse_argument(s).expect("parses");
    let vars = file.system().vars();
    let at_1_2 = brackets::Condition::new("a = 2b", vars.lookup("a").unwrap(), parse("2*b"));
    let at = |s: &str| at_1_2.apply(&parse(s)).unwrap();
    assert_eq!(parse(i92_ascii), at("8*P_1_2"));
    assert_eq!(parse(i91_ascii), at("-8*Q_1_2"));
    expect(
        "fd-search-known",
        &[
            "Known integrals in the space: H, L, P_{1,2}, Q_{1,2}.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    let four = normalize(&expect(
        "fd-search-4",
        &[
            "10125 unknowns",
            "(a parameter's multiple of an integral counts apart from it): 295.",
            "the generated ones span 293 of the 295 dimensions",
            &format!("I151 = {i91}"),
            &format!("I152 = {i92}"),
        ],
    ));
    assert_eq!(four.matches(" = 0 at ω₊ = 2 ω₋ [I").count(), 2, "{four}");
    let q13 = "p_x³ p_y − p_x p_y³ + M ω₋ x p_x³ − 3M ω₋ x p_x p_y² − 3M ω₋ y p_x² p_y \
               + M ω₋ y p_y³ + 4M³ ω₋³ x³ p_x − 12M³ ω₋³ x²y p_y − 12M³ ω₋³ xy² p_x \
               + 4M³ ω₋³ y³ p_y − 16M⁴ ω₋⁴ x³y + 16M⁴ ω₋⁴ xy³";
    let q13_ascii = "p_x^3*p_y - p_x*p_y^3 + M*b*x*p_x^3 - 3*M*b*x*p_x*p_y^2 \
                     - 3*M*b*y*p_x^2*p_y + M*b*y*p_y^3 + 4*M^3*b^3*x^3*p_x \
                     - 12*M^3*b^3*x^2*y*p_y - 12*M^3*b^3*x*y^2*p_x + 4*M^3*b^3*y^3*p_y \
                     - 16*M^4*b^4*x^3*y + 16*M^4*b^4*x*y^3";
    let third = normalize(&expect(
        "fd-search-1-3",
        &[
            "(a parameter's multiple of an integral counts apart from it): 273.",
            "the generated ones span 271 of the 273 dimensions",
            &format!("I212 = {q13} = −Q_{{1,3}}/4"),
        ],
    ));
    assert_eq!(third.matches(" = 0 at ω₊ = 3 ω₋ [I").count(), 2, "{third}");
    let at_1_3 = brackets::Condition::new("a = 3b", vars.lookup("a").unwrap(), parse("3*b"));
    assert_eq!(parse(q13_ascii), at_1_3.apply(&parse("-Q_1_3/4")).unwrap());
    expect(
        "fd-search-generic",
        &[
            "37125 unknowns",
            "(a parameter's multiple of an integral counts apart from it): 931.",
            "Known integrals in the space: H, L.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    let landau = normalize(&expect(
        "fd-search-landau",
        &[
            "I16 = 2 p_y + M ω₊ x = −2 Q_{0,1}",
            "I17 = 2 p_x − M ω₊ y = 2 P_{0,1}",
        ],
    ));
    assert_eq!(landau.matches(" = 0 at ω₋ = 0 [I").count(), 2, "{landau}");
}

/// The arguments of the named command, with `extra` after them.
fn arguments(name: &str, extra: &[&str]) -> Vec<String> {
    let command = COMMANDS
        .iter()
        .find(|c| c.0 == name)
        .unwrap_or_else(|| panic!("no command {name}"))
        .1;
    let mut args = words(command);
    args.remove(0);
    args.extend(extra.iter().map(|a| a.to_string()));
    args
}

/// A search of a system file writes each integral it shows in the file's functions and the
/// instances of its families that are integrals at its condition, where it is a polynomial in
/// them, in every format: the Fock–Darwin integrals at `a = 2b` are `−8 Q_{1,2}` and
/// `8 P_{1,2}` (what docs/results.md §21 once noted by hand), and each form read back and
/// expanded at the condition is the integral. The harmonic rotor's new integrals at 1:1, the
/// second circular mode `W e^{−iθ}`, are no polynomial in its functions and its family
/// `Z^m e^{−inθ}`, and none is printed.
#[test]
fn search_restates_its_integrals_in_functions_and_family_instances() {
    let run_as = |name: &str, format: &str| {
        let args = arguments(name, &["--no-timings", "--format", format]);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = superint(&args);
        assert_eq!(out.status.code(), Some(0));
        String::from_utf8(out.stdout).expect("UTF-8")
    };
    let markdown = run_as("fd-search", "markdown");
    for form in ["` = `−8 Q_{1,2}`\n", "` = `8 P_{1,2}`\n"] {
        assert_eq!(markdown.matches(form).count(), 1, "{form}: {markdown}");
    }
    let latex = run_as("fd-search", "latex");
    for form in ["&= -8 Q_{1,2}", "&= 8 P_{1,2}"] {
        assert_eq!(latex.matches(form).count(), 1, "{form}: {latex}");
    }
    // In JSON, the lines' `in_functions`, as `bracket` gives them; read back, each expands at
    // the condition to the integral.
    let json: serde_json::Value = serde_json::from_str(&run_as("fd-search", "json")).expect("JSON");
    let lines = |json: &serde_json::Value| -> Vec<serde_json::Value> {
        json["equations"]
            .as_array()
            .expect("equations")
            .iter()
            .filter(|e| e["caption"] == "New integrals")
            .flat_map(|e| e["lines"].as_array().expect("lines").clone())
            .collect()
    };
    let file = system_file("fock-darwin.toml");
    let when = file.condition("a = 2*b").expect("a condition");
    let found = lines(&json);
    let forms: Vec<(&str, &str)> = found
        .iter()
        .map(|l| {
            let f = &l["in_functions"];
            (
                l["lhs"].as_str().unwrap(),
                f["ascii"].as_str().expect("a form"),
            )
        })
        .collect();
    assert_eq!(forms, [("I91", "-8*Q_1_2"), ("I92", "8*P_1_2")]);
    assert_eq!(found[0]["in_functions"]["text"], "−8 Q_{1,2}");
    assert_eq!(found[1]["in_functions"]["latex"], "8 P_{1,2}");
    for l in &found {
        let integral = file.parse(l["ascii"].as_str().unwrap()).expect("parses");
        let form = file
            .parse(l["in_functions"]["ascii"].as_str().unwrap())
            .expect("parses");
        assert_eq!(when.apply(&form).unwrap(), integral, "{l}");
    }
    // The rotor's at 1:1: none, in any format.
    let rotor = run_as("h11-new", "text");
    assert!(rotor.contains("J3 = p_y cos θ + Mωy sin θ"), "{rotor}");
    assert!(
        !rotor.lines().any(|l| l.trim_start().starts_with("= ")),
        "{rotor}"
    );
    let json: serde_json::Value = serde_json::from_str(&run_as("h11-new", "json")).expect("JSON");
    let found = lines(&json);
    assert_eq!(found.len(), 4);
    assert!(found.iter().all(|l| l["in_functions"].is_null()), "{json}");
}

/// The amplitudes' letter names nothing of the file, the letter alone included: the
/// Smorodinsky–Winternitz I rotor has ladders `A` and `B`, and its search at `Ω = ω` wrote
/// `I = Re(A e^{−ikθ})` above `A7 (k = 2) = p_x² + … = A`, the amplitude and the function in
/// one letter; it now takes `Ψ`, past `B`, which the file names too, as it does past a
/// family `B`. The harmonic rotor, with no `A`, keeps it.
#[test]
fn the_amplitudes_letter_is_no_name_of_the_file() {
    let text = superint_ok_line(
        "search systems/smorodinsky-winternitz-i-rotor.toml --when 'p_theta = I*omega' \
         --momenta-degree 2 --positions-degree 4 --trig-degree 2 --laurent --new-only \
         --no-timings",
    );
    assert!(text.contains("as Φ = Re(Ψ e^{−ikθ}):"), "{text}");
    assert!(
        text.contains(
            "\n    Ψ7 (k = 2) = p_x² + 2iMωx p_x − M²ω²x² + 2Mβ/x²\n               = A\n"
        ),
        "{text}"
    );
    assert!(!text.contains("A7 (k = 2)"), "{text}");
    // The anisotropic 3:5 rotor has a function `A` and a family `B`, whose instance `B_{1,0}`
    // is the amplitude `A_x`: `Re(B e^{−ikθ})` read as the family; it takes `Ψ` too.
    let text = superint_ok_line(
        "search systems/anisotropic-3-5-rotor.toml --when 'p_theta = I*omega' \
         --momenta-degree 1 --positions-degree 1 --trig-degree 5 --new-only --no-timings",
    );
    assert!(text.contains("as J = Re(Ψ e^{−ikθ}):"), "{text}");
    assert!(text.contains("\n    Ψ2 (k = 3) = p_x + 3iMωx\n"), "{text}");
    let text = superint_ok_line(
        "search systems/harmonic-rotor.toml --when 'p_theta = I*omega' --momenta-degree 1 \
         --positions-degree 1 --trig-degree 1 --new-only --no-timings",
    );
    assert!(text.contains("as J = Re(A e^{−ikθ}):"), "{text}");
}

/// The integrals' letter names nothing of the file, the letter alone included, as the
/// amplitudes' does: a rotor's search wrote `I = Re(A e^{−ikθ})` and `{I, H} = 0 for the
/// other 23 basis elements at p_θ = Iω`, the integral and the moment of inertia in one
/// letter, over integrals `I2, I3, …`; a rotor's integrals are now `J2, …` (the
/// Fock–Darwin rotor, which names `J` too, takes `Φ`), and a system without `I` keeps it.
#[test]
fn the_integrals_letter_is_no_name_of_the_file() {
    let text = superint_ok_line(
        "search --system anisotropic-1-2 --when 'p_theta = I*omega' --momenta-degree 3 \
         --positions-degree 3 --trig-degree 3 --new-only --no-timings",
    );
    assert!(text.contains("as J = Re(A e^{−ikθ}):"), "{text}");
    assert!(
        text.contains("\n    J2 = p_x cos θ + Mωx sin θ\n"),
        "{text}"
    );
    assert!(
        text.contains("{J, H} = 0 for the other 23 basis elements at p_θ = Iω"),
        "{text}"
    );
    assert!(!text.contains("I2"), "{text}");
    assert!(!text.contains("{I, H}"), "{text}");
    let text = superint_ok_line(
        "search systems/fock-darwin-rotor.toml --when 'a = 2*b, p_theta = 2*I*b' \
         --momenta-degree 1 --positions-degree 1 --trig-degree 1 --new-only --no-timings",
    );
    assert!(text.contains("as Φ = Re("), "{text}");
    assert!(!text.contains("J1"), "{text}");
    let text = superint_ok_line(
        "search systems/fock-darwin.toml --momenta-degree 1 --positions-degree 1 --no-timings",
    );
    assert!(text.contains("\n    I1 = 1\n"), "{text}");
}

/// A search of a system file writes the amplitude `A` of each integral `Re(A e^{−ikθ})` it
/// shows in the file's functions, where it is a polynomial in them: the 3D rotor's
/// `I7 = p_y cos θ + Mωy sin θ` at `Ω = ω`, which no family names, is `Re(Z_y e^{−iθ})`
/// (`A7 = p_y + iMωy = Z_y`, `A8 = i Z_y`), and each form, read back from JSON, expands at the
/// condition to its amplitude (their difference is 0); at `Ω = 2ω` the quadratic ones are
/// products, `A19 = Z_y Z_z`. The harmonic rotor's amplitudes at 1:1, `p_y + iMωy`, are no
/// polynomial in its `Z = Z_x + iZ_y`, `Z̄` and the rest, and nothing is printed below them.
#[test]
fn search_writes_the_amplitudes_of_its_integrals_in_the_files_functions() {
    let file = "systems/isotropic-rotor-3d.toml";
    let one = "search systems/isotropic-rotor-3d.toml --when 'p_theta = I*omega' \
               --momenta-degree 2 --positions-degree 2 --trig-degree 2 --new-only --no-timings";
    let text = superint_ok_line(one);
    for form in [
        "\n    Φ7  = p_y cos θ + Mωy sin θ\n    Φ8  = ",
        "\n    A7 (k = 1)  = p_y + iMωy\n                = Z_y\n",
        "\n    A8 (k = 1)  = i p_y − Mωy\n                = i Z_y\n",
        "\n    A9 (k = 1)  = p_x + iMωx\n                = Z_x\n",
    ] {
        assert!(text.contains(form), "{form:?}: {text}");
    }
    // In JSON, each amplitude's `in_functions`; read back, the difference expands to zero.
    let json: serde_json::Value =
        serde_json::from_str(&superint_ok_line(&format!("{one} --format json"))).expect("JSON");
    let amplitudes: Vec<serde_json::Value> = json["equations"]
        .as_array()
        .expect("equations")
        .iter()
        .filter(|e| {
            e["caption"]
                .as_str()
                .unwrap()
                .starts_with("Those of trigonometric order")
        })
        .flat_map(|e| e["lines"].as_array().expect("lines").clone())
        .collect();
    let forms: Vec<(&str, &str)> = amplitudes
        .iter()
        .map(|l| {
            let lhs = l["lhs"].as_str().unwrap();
            (lhs, l["in_functions"]["ascii"].as_str().expect("a form"))
        })
        .collect();
    assert_eq!(
        forms,
        [
            ("A5 (k = 1)", "Zz"),
            ("A6 (k = 1)", "i*Zz"),
            ("A7 (k = 1)", "Zy"),
            ("A8 (k = 1)", "i*Zy"),
            ("A9 (k = 1)", "Zx"),
            ("A10 (k = 1)", "i*Zx"),
        ]
    );
    assert_eq!(amplitudes[2]["in_functions"]["latex"], "Z_{y}");
    for l in &amplitudes {
        let difference = format!(
            "({}) - ({})",
            l["ascii"].as_str().unwrap(),
            l["in_functions"]["ascii"].as_str().unwrap()
        );
        let args = ["expand", file, "--when", "p_theta = I*omega", &difference];
        let expanded: serde_json::Value = serde_json::from_str(&crate::superint_ok(
            &[&args[..], &["--format", "json"]].concat(),
        ))
        .expect("JSON");
        assert_eq!(
            expanded["equations"][0]["lines"][0]["ascii"], "0",
            "{difference}"
        );
    }
    // Not a wrong neighbour: A7's amplitude less A8's form.
    let args = [
        "expand",
        file,
        "--when",
        "p_theta = I*omega",
        "(p_y + i*M*omega*y) - (i*Zy)",
        "--format",
        "json",
    ];
    let expanded: serde_json::Value =
        serde_json::from_str(&crate::superint_ok(&args)).expect("JSON");
    assert_ne!(expanded["equations"][0]["lines"][0]["ascii"], "0");
    // At Ω = 2ω, the products of the ladders.
    let two = superint_ok_line(
        "search systems/isotropic-rotor-3d.toml --when 'p_theta = 2*I*omega' \
         --momenta-degree 2 --positions-degree 2 --trig-degree 1 --new-only --no-timings",
    );
    for form in [
        "\n    A19 (k = 1) = p_y p_z + iMωy p_z + iMωz p_y − M²ω²yz\n                = Z_y Z_z\n",
        "\n    A28 (k = 1) = i p_x² − 2Mωx p_x − iM²ω²x²\n                = i Z_x²\n",
    ] {
        assert!(two.contains(form), "{form:?}: {two}");
    }
    // The harmonic rotor's: none.
    let rotor = superint_ok_line(
        "search systems/harmonic-rotor.toml --when 'p_theta = I*omega' --momenta-degree 1 \
         --positions-degree 1 --trig-degree 1 --new-only --no-timings",
    );
    assert!(
        rotor.contains("\n    A3 (k = 1) = p_y + iMωy\n    A4 "),
        "{rotor}"
    );
    assert!(
        !rotor.lines().any(|l| l.trim_start().starts_with("= ")),
        "{rotor}"
    );
    // Under gravity, `p_x + iMωx` is `ω(ω L − ω L′ − 2i G1 + 2i G1′)/g` in the file's
    // functions (`G1′ − G1` is a multiple of `g`): proved, but it divides by `g` where the
    // amplitude does not, and is not shown.
    let gravity = superint_ok_line(
        "search systems/gravity-rotor.toml --when 'p_theta = I*omega' --momenta-degree 1 \
         --positions-degree 1 --trig-degree 1 --new-only --no-timings",
    );
    assert!(
        gravity.contains("\n    A5 (k = 1) = p_x + iMωx\n    A6 (k = 1) = i p_x − Mωx\n"),
        "{gravity}"
    );
    assert!(!gravity.contains("/g"), "{gravity}");
}

/// The Fock–Darwin system's algebras: at `a = 2b`, for every `M, b`, `H`, `L`, `P_{1,2}`,
/// `Q_{1,2}` close into a cubic algebra, `{P, Q} = 36M³b(H² − 4b²L²)`, tied by
/// `P² + Q² = 8M³(H − bL)(H + 2bL)²`; at `b = 0` the guiding centre's Heisenberg pair, with
/// `P² + Q² = 2M(H + aL)`; at `b = a` su(2) with `L`, and its Casimir.
#[test]
fn fock_darwin_closes_into_a_cubic_algebra_at_1_2() {
    expect(
        "fd-closure",
        &[
            "The table closes",
            "{L, P_{1,2}} = −3 Q_{1,2} at ω₊ = 2 ω₋ [B1 proved]",
            "{L, Q_{1,2}} = 3 P_{1,2} at ω₊ = 2 ω₋ [B2 proved]",
            "{P_{1,2}, Q_{1,2}} = −36M³ ω₋ (4 ω₋² L² − H²) at ω₊ = 2 ω₋ [B3 proved]",
            "32M³ ω₋³ L³ + P_{1,2}² + Q_{1,2}² = 24M³ ω₋ H² L + 8M³ H³ at ω₊ = 2 ω₋ [R1 proved]",
            "4 claims: 4 proved, 0 refuted",
        ],
    );
    expect(
        "fd-closure-landau",
        &[
            "The table closes",
            "{P_{0,1}, Q_{0,1}} = M ω₊ at ω₋ = 0 [B3 proved]",
            "2M ω₊ L + 2M H = P_{0,1}² + Q_{0,1}² at ω₋ = 0 [R1 proved]",
        ],
    );
    expect(
        "fd-closure-isotropic",
        &[
            "The table closes",
            "{L, P_{1,1}} = −2 Q_{1,1} at ω₋ = ω₊ [B1 proved]",
            "{P_{1,1}, Q_{1,1}} = −8M² ω₊² L at ω₋ = ω₊ [B3 proved]",
            "4M² ω₊² L² + P_{1,1}² + Q_{1,1}² = 4M² H² at ω₋ = ω₊ [R1 proved]",
        ],
    );
}

/// A Hamiltonian with negative powers of a symbolic parameter (`p²/(2M)`) is known to a search
/// through its least multiple without them (`M H`), and the note on `H` counts that multiple's
/// degree: at `a = 2b` the Fock–Darwin `M H` has degree 4 in `M, b`, so at
/// `--parameters-degree 3` `H` is left out, which nothing said (the note counted `|−1|` for
/// `1/M`, degree 3), and at 4 it is in; its square, of degree 8, is named at 4.
#[test]
fn a_search_counts_the_degree_of_h_without_its_negative_powers_of_the_parameters() {
    let search = |momenta: &str, degree: &str| {
        let out = superint(&[
            "search",
            "systems/fock-darwin.toml",
            "--when",
            "a = 2*b",
            "--momenta-degree",
            momenta,
            "--positions-degree",
            momenta,
            "--trig-degree",
            "0",
            "--symbolic",
            "M,b",
            "--parameters-degree",
            degree,
            "--new-only",
            "--no-timings",
        ]);
        assert_eq!(out.status.code(), Some(0));
        normalize(&String::from_utf8(out.stdout).expect("UTF-8"))
    };
    let three = search("3", "3");
    assert!(
        three.contains(
            "Note: M H (H without its negative powers of M, ω₋) has degree 4 in M, ω₋, past the \
             space's 3 (--parameters-degree), so H is not among the integrals found"
        ),
        "{three}"
    );
    assert!(
        three.contains("Known integrals in the space: L."),
        "{three}"
    );
    let four = search("3", "4");
    assert!(!four.contains("Note:"), "{four}");
    assert!(
        four.contains("Known integrals in the space: H, L."),
        "{four}"
    );
    let square = search("4", "4");
    assert!(
        square.contains(
            "Note: (M H)² lies in the space but for its degree 8 in M, ω₋, past the space's 4 \
             (--parameters-degree): integrals of degree 4 in the momenta may need a larger one."
        ),
        "{square}"
    );
}

/// The classical Zernike system `H = p² + γ₁D + γ₂D²`, `D = x·p` (`g1`, `g2` printed `γ₁`,
/// `γ₂`), loaded and checked: every claim of the file holds (`H` in the sphere's form, the
/// angular momentum and the tensor `T_ij = (1 + γ₂r²)p_i p_j + γ₁(x_i p_j + x_j p_i)/2`
/// conserved for every `γ₁, γ₂`, its trace and determinant, the cubic Higgs algebra of
/// `A = T11 − T22`, `B = 2T12` and its Casimir, the sphere's rotations `s p_x`, `s p_y` at
/// `γ₁ = 0`, Zernike's own values `γ₂ = −1`, `γ₁ = 2i`, the ranks), and each of its seven
/// false neighbours is refuted. The tensor needs both the factor `1 + γ₂r²` and the half in
/// its `γ₁` term: for every `γ₁, γ₂`, `{T12, H}` is zero, and with `γ₁(x p_y + y p_x)` it is
/// `2γ₁ p_x p_y`.
#[test]
fn zernike_claims_are_proved_and_its_false_neighbours_refuted() {
    let file = system_file("zernike.toml");
    assert_claims_as_expected(
        &file,
        &[
            "sphere-form",
            "angular",
            "tensor",
            "trace",
            "determinant",
            "found",
            "algebra",
            "casimir",
            "tensor-algebra",
            "sphere",
            "zernike",
            "rank",
        ],
        &[
            "false-cross-term",
            "false-conformal-sign",
            "false-algebra-sign",
            "false-casimir",
            "false-rotation",
            "false-zernike-sign",
            "false-rank",
        ],
    );
    let parse = |s: &str| file.parse_argument(s).expect("parses");
    let system = file.system();
    assert!(system.flow(&parse("T12")).unwrap().is_zero());
    let doubled = parse("(1 + g2*(x^2 + y^2))*p_x*p_y + g1*(x*p_y + y*p_x)");
    assert_eq!(system.flow(&doubled).unwrap(), parse("2*g1*p_x*p_y"));
    // The sphere's rotations are integrals at γ₁ = 0 only: {J1, H} = −γ₁ p_x/s.
    assert!(crate::holds(&file, "{J1, H}", "-g1*p_x/s"));
}

/// The classical Zernike system: to fourth order in the momenta and the positions, for every
/// `γ₁, γ₂`, the file's `H`, `L` and tensor generate every integral; from `H` alone the search
/// finds the angular momentum and the two quadratic integrals `T22 − γ₂L²` and `T12 − γ₁L/2`
/// (the file's claims `found`), and nothing cubic or quartic. At `γ₁ = 0`, with the radical,
/// it finds the two rotations of the sphere `s p_y` and `s p_x` (the file's `J2`, `J1`) beside
/// `L`. `H, L, A, B` close into the cubic
/// Higgs algebra `{A, B} = −4γ₂HL − 4γ₂²L³ − 2γ₁²L`, with the Casimir
/// `A² + B² = (H + γ₂L²)² + γ₁²L²` its one relation to degree 4; at `γ₁ = 0` the rotations
/// and `L` close into so(3) (so(2, 1) for `γ₂ > 0`), `{J_1, J_2} = −γ₂L`, with the Casimir
/// `J_1² + J_2² − γ₂L² = H`.
#[test]
fn zernike_tensor_found_from_h_alone_and_its_cubic_higgs_algebra() {
    expect(
        "zernike-search",
        &[
            "The space: x^a y^b p_x^c p_y^d, with momenta degree c + d ≤ 4",
            "3375 unknowns",
            "(a parameter's multiple of an integral counts apart from it): 195.",
            "≤ 0: 15, ≤ 1: 30, ≤ 2: 75, ≤ 3: 120, ≤ 4: 195.",
            "Known integrals in the space: H, L, T_11, T_12, T_22, A, B.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    let t22 = "2 γ₂ xy p_x p_y − γ₂ y² p_x² + γ₂ y² p_y² + p_y² + γ₁ y p_y";
    let t12 = "γ₂ x² p_x p_y + γ₂ y² p_x p_y + p_x p_y + γ₁ y p_x";
    let text = expect_alone(
        "zernike-search",
        &[
            "Known integrals in the space: H.",
            "I16 = x p_y − y p_x",
            &format!("I32 = {t22}"),
            &format!("I35 = {t12}"),
            "4 claims: 4 proved, 0 refuted",
        ],
    );
    assert_eq!(text.matches(" = 0 [I").count(), 3, "{text}");
    // The integrals found, read back as printed, are the file's tensor less multiples of L.
    let file = system_file("zernike.toml");
    let parse = |s: &str| file.parse_argument(s).expect("parses");
    assert_eq!(parse(t22), parse("T22 - g2*L^2"));
    assert_eq!(parse(t12), parse("T12 - g1*L/2"));
    expect(
        "zernike-search-sphere",
        &[
            "Known integrals in the space: L, J_1, J_2.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    expect_alone(
        "zernike-search-sphere",
        &[
            "I4 = x p_y − y p_x",
            "I7 = s p_y",
            "I8 = s p_x",
            "{I7, H} = 0 at γ₁ = 0 [I7 proved]",
            "{I8, H} = 0 at γ₁ = 0 [I8 proved]",
            "4 claims: 4 proved, 0 refuted",
        ],
    );
    expect(
        "zernike-closure",
        &[
            "The table closes",
            "{L, A} = 2 B [B1 proved]",
            "{L, B} = −2 A [B2 proved]",
            "{A, B} = −2(γ₁² + 2 γ₂² L² + 2 γ₂ H) L [B3 proved]",
            "γ₁² L² + γ₂² L⁴ + 2 γ₂ H L² + H² = A² + B² [R1 proved]",
            "4 claims: 4 proved, 0 refuted",
        ],
    );
    expect(
        "zernike-closure-sphere",
        &[
            "The table closes",
            "{L, J_1} = J_2 at γ₁ = 0 [B1 proved]",
            "{L, J_2} = −J_1 at γ₁ = 0 [B2 proved]",
            "{J_1, J_2} = −γ₂ L at γ₁ = 0 [B3 proved]",
            "γ₂ L² + H = J_1² + J_2² at γ₁ = 0 [R1 proved]",
            "4 claims: 4 proved, 0 refuted",
        ],
    );
}

/// The paper's rotor in the Smorodinsky–Winternitz potential `V_I`, loaded and checked: every
/// claim of the file holds (the separated energies and `X` conserved, the quadratic ladders
/// `{A, H} = 2iωA`, the tower's instances, the resonant integrals at `Ω = 2mω/n`, the
/// harmonic limit `β = γ = 0`, so(2,1) twice with the barriers' Casimirs, `X` as a polynomial
/// in the two copies, the ranks), and each of its five false neighbours is refuted: the
/// harmonic rotor's resonance `Ω = ω` for `P_{1,1}` and for the linear `Re(Z e^{−iθ})`, the
/// Casimir's and the bracket's signs, and rank 5 with `H = H_x + H_y + F2`. A residual that is
/// a function of the parameters alone is printed as it is, never written in the functions.
#[test]
fn sw_i_rotor_claims_are_proved_and_its_false_neighbours_refuted() {
    let file = system_file("smorodinsky-winternitz-i-rotor.toml");
    assert_claims_as_expected(
        &file,
        &[
            "separable",
            "integrals",
            "ladders",
            "tower",
            "resonance",
            "harmonic-limit",
            "so21",
            "casimir",
            "x-relation",
            "rank",
        ],
        &[
            "false-harmonic-resonance",
            "false-linear-integral",
            "false-casimir-sign",
            "false-so21-sign",
            "false-rank",
        ],
    );
    // The barriers are what breaks the linear integral: its flow at Ω = ω is theirs alone.
    let when = file.condition("p_theta = I*omega").expect("a condition");
    let parse = |s: &str| file.parse_argument(s).expect("parses");
    let flow = file.system().flow(&parse("re(Z*exp(-i*theta))")).unwrap();
    assert_eq!(
        when.apply(&flow).unwrap(),
        parse("2*beta*cos(theta)/x^3 + 2*gamma*sin(theta)/y^3")
    );
    let out = superint(&[
        "check",
        "systems/smorodinsky-winternitz-i-rotor.toml",
        "--no-timings",
    ]);
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    let lines: Vec<&str> = text.lines().collect();
    let at = lines
        .iter()
        .position(|l| l.contains("residual lhs − rhs = −16M³ω²β"))
        .unwrap_or_else(|| panic!("the Casimir's residual: {text}"));
    assert!(!lines[at + 1].trim_start().starts_with('='), "{text}");
}

/// The rotor in `V_I` at `Ω = 2ω`: to fourth order in the momenta, the four new integrals are
/// `P_{1,1}`, `Q_{1,1}`, `R_{1,1}`, `S_{1,1}` (restated so), and from `H` alone the search
/// finds `H_y` and those four and nothing else (`X` is generated); at `Ω = ω` the new ones are
/// of order 2. `H_x, H_y, X` and the four close at degree 2 into so(2,1) ⊕ so(2,1) with `X` a
/// polynomial in the rest, for every `β, γ`; the brackets written with the factor their
/// terms share in front, `{X, P_{1,1}} = −4(H_x S_{1,1} − H_y Q_{1,1})/ω`.
#[test]
fn sw_i_rotor_resonant_integrals_found_and_their_algebra() {
    expect(
        "swi-rotor-search",
        &[
            "3075 unknowns",
            "Dimension of the space of integrals: 26. By degree in the momenta: ≤ 0: 1, \
             ≤ 1: 1, ≤ 2: 8, ≤ 3: 11, ≤ 4: 26.",
            "Known integrals in the space: H, H_x, H_y, X.",
            "the generated ones span 22 of the 26 dimensions",
            "= R_{1,1}",
            "= −S_{1,1}",
            "= P_{1,1}",
            "= −Q_{1,1}",
            "5 claims: 5 proved, 0 refuted",
        ],
    );
    let alone = expect_alone(
        "swi-rotor-search",
        &[
            "Known integrals in the space: H.",
            "the generated ones span 21 of the 26 dimensions",
            "J2 = p_y² + M²ω²y² + 2Mγ/y²",
            "J7 = (p_x² − M²ω²x² + 2Mβ/x²) cos θ + 2Mωx p_x sin θ",
            "6 claims: 6 proved, 0 refuted",
        ],
    );
    assert_eq!(alone.matches(" = 0 at p_θ = 2Iω [J").count(), 5, "{alone}");
    expect(
        "swi-rotor-search-1-2",
        &[
            "Momenta degree exactly 2: 3 of order 0, 4 of order 2.",
            "= P_{1,2}",
            "= −Q_{1,2}",
            "= R_{1,2}",
            "= −S_{1,2}",
        ],
    );
    expect(
        "swi-rotor-closure",
        &[
            "The table closes",
            // The factor a bracket's terms share in front, in the table and its claim.
            "{X, P_{1,1}} = −4(H_x S_{1,1} − H_y Q_{1,1})/ω {X, Q_{1,1}}",
            "{H_x, X} = (P_{1,1} S_{1,1} − Q_{1,1} R_{1,1})/(M²ω) at p_θ = 2Iω [B1 proved]",
            "{H_x, P_{1,1}} = 2ω Q_{1,1} at p_θ = 2Iω [B2 proved]",
            "{P_{1,1}, Q_{1,1}} = −8M²ω H_x at p_θ = 2Iω [B11 proved]",
            "{R_{1,1}, S_{1,1}} = −8M²ω H_y at p_θ = 2Iω [B12 proved]",
            "2M²ω² X + P_{1,1} R_{1,1} + Q_{1,1} S_{1,1} = 4M² H_x H_y at p_θ = 2Iω [R1 proved]",
            "8M³ω²β + P_{1,1}² + Q_{1,1}² = 4M² H_x² at p_θ = 2Iω [R2 proved]",
            "15 claims: 15 proved, 0 refuted",
        ],
    );
}

/// The search restates its integrals in family instances that are integrals at the
/// condition, tried before those whose declared eigenvalue is not zero there: with the
/// conjugate families `K̄`, `J̄` added to the `V_I` rotor's six, the instances `e^{−inθ}`,
/// `A^m`, … of the lower index sums once spent the tries, and `R_{1,2}`, `S_{1,2}` (at
/// `Ω = ω`, sum 3) were never tried.
#[test]
fn search_tries_instances_with_a_zero_eigenvalue_first() {
    let file = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/systems/smorodinsky-winternitz-i-rotor.toml"
    ))
    .expect("the V_I rotor's file");
    let conjugate = |ladder: &str, base: &str, before: &str| {
        format!(
            "eigenvalue = \"i*(2*m*omega - n*Omega)\"\n\n[[family]]\nname = \"{ladder}bar\"\n\
             value = \"conj({base})^m*exp(i*n*theta)\"\n\
             eigenvalue = \"-i*(2*m*omega - n*Omega)\"\n\n[[family]]\nname = \"{before}\""
        )
    };
    let mut text = file;
    for (ladder, base, before) in [("K", "A", "P"), ("J", "B", "R")] {
        let at =
            format!("eigenvalue = \"i*(2*m*omega - n*Omega)\"\n\n[[family]]\nname = \"{before}\"");
        assert!(
            text.contains(&at),
            "the file declares {before} after {ladder}"
        );
        text = text.replace(&at, &conjugate(ladder, base, before));
    }
    assert_eq!(text.matches("[[family]]").count(), 8);
    let path = crate::scratch_text("discovery", "sw-i-rotor-eight-families.toml", &text);
    let out = superint_ok_line(&format!(
        "search {} --when 'p_theta = I*omega' --momenta-degree 4 --positions-degree 4 \
         --trig-degree 2 --laurent --new-only",
        path.display()
    ));
    for restated in ["= P_{1,2}", "= −Q_{1,2}", "= R_{1,2}", "= −S_{1,2}"] {
        assert!(out.contains(restated), "{restated} not in {out}");
    }
}

/// The paper's rotor in the Smorodinsky–Winternitz potential `V_II`, loaded and checked:
/// every claim of the file holds (the quadratic ladder `A` in `x` and the shifted linear
/// ladder `C` in `y`, both of frequency `2ω`, the resonant integrals at `Ω = 2mω/n`, `V_II`'s
/// integral `X` as `Im(A C̄)` up to `H_x` and as a product of the resonant ones, so(2,1) and
/// the canonical pair `{R, S} = −2Mω`, rank 5), and each of its four false neighbours is
/// refuted: `C` without its shift (residual `−γ`), `R_{1,1}` at `Ω = ω`, the sign of `H_x` in
/// `X`, and rank 5 with `H = H_x + H_y + F2`.
#[test]
fn sw_ii_rotor_claims_are_proved_and_its_false_neighbours_refuted() {
    let file = system_file("smorodinsky-winternitz-ii-rotor.toml");
    assert_claims_as_expected(
        &file,
        &[
            "separable",
            "integrals",
            "ladders",
            "tower",
            "resonance",
            "x-relation",
            "algebra",
            "rank",
        ],
        &[
            "false-ladder-shift",
            "false-resonance",
            "false-x-sign",
            "false-rank",
        ],
    );
    assert!(crate::holds(
        &file,
        "{p_y + 2*i*M*omega*y, H} - 2*i*omega*(p_y + 2*i*M*omega*y)",
        "-gamma"
    ));
}

/// The rotor in `V_II` at `Ω = 2ω`: to third order, the new integrals are the linear
/// `2R_{1,1}`, `−2S_{1,1}` and the quadratic `P_{1,1}`, `−Q_{1,1}`, and from `H` alone the same
/// four (they generate `H_x`, `H_y` and `X`); `H_x, H_y, P, Q, R, S` close at degree 2 into
/// so(2,1) and the oscillator algebra, for every `β, γ`.
#[test]
fn sw_ii_rotor_resonant_integrals_found_and_their_algebra() {
    expect(
        "swii-rotor-search",
        &[
            "1250 unknowns",
            "Dimension of the space of integrals: 17. By degree in the momenta: ≤ 0: 1, \
             ≤ 1: 3, ≤ 2: 10, ≤ 3: 17.",
            "Known integrals in the space: H, H_x, H_y, X.",
            "the generated ones span 13 of the 17 dimensions",
            "Φ2 = 2 p_y cos θ + (4Mωy + γ/ω) sin θ = 2 R_{1,1}",
            "= −2 S_{1,1}",
            "= P_{1,1}",
            "= −Q_{1,1}",
        ],
    );
    let alone = expect_alone(
        "swii-rotor-search",
        &[
            "Known integrals in the space: H.",
            "the generated ones span 13 of the 17 dimensions",
            "J2 = 2 p_y cos θ + (4Mωy + γ/ω) sin θ",
            "5 claims: 5 proved, 0 refuted",
        ],
    );
    assert_eq!(alone.matches(" = 0 at p_θ = 2Iω [J").count(), 4, "{alone}");
    expect(
        "swii-rotor-closure",
        &[
            "The table closes",
            "{P_{1,1}, Q_{1,1}} = −8M²ω H_x at p_θ = 2Iω",
            "{R_{1,1}, S_{1,1}} = −2Mω at p_θ = 2Iω",
            "{H_y, R_{1,1}} = 2ω S_{1,1} at p_θ = 2Iω",
            "8M H_y + γ²/ω² = 4 R_{1,1}² + 4 S_{1,1}² at p_θ = 2Iω",
            "8 claims: 8 proved, 0 refuted",
        ],
    );
}

/// The paper's rotor in the Fock–Darwin trap, loaded and checked: every claim of the file
/// holds (`H_FD`, `L`, `F2` in involution, the three ladders, the towers of `K = Z^m e^{−inθ}`,
/// `J = W^m e^{−inθ}` and the trap's `G = W^m Z̄^n`, the canonical pairs and their moduli,
/// `G_{1,2} = J_{1,1} conj(K_{2,1})`, the resonances one and two at a time, the paper's rotor at
/// `ω₊ = ω₋`, what the searches find, the algebra, rank 4 at one resonance and 5 at two), and
/// each of its seven false neighbours is refuted. The towers are proved for all `m, n`, and
/// `{P_{m,n}, H} = −(mω₋ − nΩ) Q_{m,n}`, `{R_{m,n}, H} = −(mω₊ − nΩ) S_{m,n}`,
/// `{U_{m,n}, H} = −(mω₊ − nω₋) V_{m,n}` for `m ≤ 2`, `n ≤ 3`, each conserved at the double
/// resonance `Ω = ω₊ = 2ω₋` exactly when its eigenvalue vanishes there.
#[test]
fn fd_rotor_claims_are_proved_and_its_false_neighbours_refuted() {
    let file = system_file("fock-darwin-rotor.toml");
    assert_claims_as_expected(
        &file,
        &[
            "separable",
            "integrals",
            "involution",
            "ladders",
            "modes",
            "tower",
            "rotation",
            "heisenberg",
            "modulus",
            "product",
            "resonance",
            "double-resonance",
            "paper-limit",
            "found",
            "algebra",
            "rank",
        ],
        &[
            "false-rotor-sign",
            "false-off-resonance",
            "false-other-mode",
            "false-modulus-sign",
            "false-rank",
            "false-rank-trap",
            "false-rank-energy",
        ],
    );
    let parse = |s: &str| file.parse_argument(s).expect("parses");
    let system = file.system();
    let double = file
        .condition("a = 2*b, p_theta = 2*I*b")
        .expect("a condition");
    for m in 0..=2i64 {
        for n in 0..=3i64 {
            if m + n == 0 {
                continue;
            }
            // (real part, imaginary part, the rate, conserved at Ω = ω₊ = 2ω₋)
            for (re, im, rate, resonant) in [
                ("P", "Q", format!("{m}*b - {n}*Omega"), m == 2 * n),
                ("R", "S", format!("{m}*a - {n}*Omega"), m == n),
                ("U", "V", format!("{m}*a - {n}*b"), 2 * m == n),
            ] {
                let flow = system.flow(&parse(&format!("{re}_{m}_{n}"))).unwrap();
                let expected = parse(&format!("-({rate})*{im}_{m}_{n}"));
                assert_eq!(flow, expected, "{re}_{m}_{n}");
                assert!(!parse(&format!("{im}_{m}_{n}")).is_zero(), "{im}_{m}_{n}");
                let conserved = double.apply(&flow).unwrap().is_zero();
                assert_eq!(conserved, resonant, "{re}_{m}_{n} at Ω = ω₊ = 2ω₋");
            }
        }
    }
    // The other mode's resonance leaves R_{1,1} the rate of the two modes' difference.
    let other = file.condition("p_theta = I*b").expect("a condition");
    let flow = system.flow(&parse("R_1_1")).unwrap();
    assert_eq!(
        other.apply(&flow).unwrap(),
        other.apply(&parse("-(a - b)*S_1_1")).unwrap()
    );
    let out = superint(&[
        "tower",
        "--system",
        "systems/fock-darwin-rotor.toml",
        "--max",
        "4",
        "--no-timings",
    ]);
    let text = normalize(&String::from_utf8(out.stdout).expect("UTF-8"));
    assert_eq!(out.status.code(), Some(0), "{text}");
    for piece in [
        "16 brackets expanded for the Fock–Darwin rotor (ladder K_{m,n} = Z^m e^{−inθ}), all hold",
        "Therefore: {K_{m,n}, H} = i(m ω₋ − nΩ) K_{m,n} for all m, n ≥ 0.",
        "16 brackets expanded for the Fock–Darwin rotor (ladder J_{m,n} = W^m e^{−inθ}), all hold",
        "Therefore: {J_{m,n}, H} = i(m ω₊ − nΩ) J_{m,n} for all m, n ≥ 0.",
        "16 brackets expanded for the Fock–Darwin rotor (ladder G_{m,n} = W^m Z̄^n), all hold",
        "Therefore: {G_{m,n}, H} = i(m ω₊ − n ω₋) G_{m,n} for all m, n ≥ 0.",
        "6 claims in 1 file: 6 proved, 0 refuted; all as expected",
    ] {
        assert!(text.contains(piece), "{piece}: {text}");
    }
}

/// The rotor in the Fock–Darwin trap. At the double resonance `Ω = ω₊ = 2ω₋` the four new
/// integrals, to fourth and to sixth order, are the parts of `W e^{−iθ}` and `Z² e^{−iθ}`
/// (restated `2 R_{1,1}`, `−2 S_{1,1}`, `4 P_{2,1}`, `−4 Q_{2,1}`), and from `H` alone the same
/// four and nothing else (the trap's cubic `U_{1,2}`, `H_FD` and `L` are products). At `Ω = ω₊`
/// alone, for every `M, ω₊, ω₋`, the new ones are `R_{1,1}`, `S_{1,1}`; off the resonances there
/// are none; at `Ω = ω₋`, `ω₊ = 3ω₋` the new ones are `P_{1,1}`, `Q_{1,1}` and two of order 3.
/// The resonant integrals close at degree 2, so(2,1) and the oscillator algebra, and with the
/// trap's `U_{1,2}`, `V_{1,2}` among the generators the relations make them products.
#[test]
fn fd_rotor_resonant_integrals_found_and_their_algebra() {
    let r11 = "Φ3 = (2 p_x + 3M ω₋ y) cos θ + (−2 p_y + 3M ω₋ x) sin θ = 2 R_{1,1}";
    let p21 = "+ (8 p_x p_y + 12M ω₋ x p_x − 12M ω₋ y p_y − 18M² ω₋² xy) sin θ = 4 P_{2,1}";
    expect(
        "fd-rotor-search",
        &[
            "2025 unknowns, 3104 linear equations over Q, in 89 independent blocks",
            "Dimension of the space of integrals: 57. By degree in the momenta: ≤ 0: 1, \
             ≤ 1: 4, ≤ 2: 12, ≤ 3: 28, ≤ 4: 57.",
            "Known integrals in the space: H, L, H_FD.",
            "the generated ones span 53 of the 57 dimensions",
            r11,
            "= −2 S_{1,1}",
            p21,
            "= −4 Q_{2,1}",
            "53 of them lifted and proved symbolically",
            "5 claims: 5 proved, 0 refuted",
        ],
    );
    let alone = expect_alone(
        "fd-rotor-search",
        &[
            "Known integrals in the space: H.",
            "the generated ones span 53 of the 57 dimensions",
            "J3 = (2 p_x + 3M ω₋ y) cos θ + (−2 p_y + 3M ω₋ x) sin θ",
            "5 claims: 5 proved, 0 refuted",
        ],
    );
    assert_eq!(
        alone.matches(" = 0 at ω₊ = 2 ω₋, p_θ = 2I ω₋ [J").count(),
        4,
        "{alone}"
    );
    expect(
        "fd-rotor-search-6",
        &[
            "10192 unknowns",
            "≤ 4: 57, ≤ 5: 104, ≤ 6: 176.",
            "the generated ones span 172 of the 176 dimensions",
            r11,
            "= −2 S_{1,1}",
            p21,
            "= −4 Q_{2,1}",
            "5 claims: 5 proved, 0 refuted",
        ],
    );
    let alone = expect_alone(
        "fd-rotor-search-6",
        &["the generated ones span 172 of the 176 dimensions"],
    );
    assert_eq!(
        alone.matches(" = 0 at ω₊ = 2 ω₋, p_θ = 2I ω₋ [J").count(),
        4,
        "{alone}"
    );
    expect(
        "fd-rotor-search-single",
        &[
            "17500 unknowns",
            "Dimension of the space of integrals over Q (a parameter's multiple of an integral \
             counts apart from it): 206.",
            "Over the polynomials in M, ω₊, ω₋, 16 of the 206 basis integrals, Φ1, Φ36, Φ71,",
            "the generated ones span 204 of the 206 dimensions",
            "(2 p_x + M ω₊ y + M ω₋ y) cos θ + (−2 p_y + M ω₊ x + M ω₋ x) sin θ = 2 R_{1,1}",
            "= −2 S_{1,1}",
            "3 claims: 3 proved, 0 refuted",
        ],
    );
    let off = expect(
        "fd-rotor-search-off",
        &[
            "35000 unknowns",
            "Dimension of the space of integrals over Q (a parameter's multiple of an integral \
             counts apart from it): 353.",
            "Momenta degree exactly 3: 142 of order 0.",
            "Known integrals in the space: H, L, H_FD, F2, Ω.",
            "the generated ones span the whole space (353 dimensions)",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    assert!(!off.contains("of order 1"), "{off}");
    let text = expect(
        "fd-rotor-search-3-1",
        &[
            "Dimension of the space of integrals: 71.",
            "the generated ones span 67 of the 71 dimensions",
            "Φ3 = (p_x − 2M ω₋ y) cos θ + (p_y + 2M ω₋ x) sin θ = P_{1,1}",
            "= −Q_{1,1}",
            // The parts of `W e^{−3iθ}`, though the real and imaginary parts' families,
            // which declare no eigenvalue, come before it in index order.
            // cos³θ = (3 cos θ + cos 3θ)/4, cos²θ sin θ = (sin θ + sin 3θ)/4: the parts of
            // order 1 cancel.
            "Φ5 = (p_x + 2M ω₋ y) cos 3θ + (−p_y + 2M ω₋ x) sin 3θ = R_{1,3}",
            "Φ6 = (p_y − 2M ω₋ x) cos 3θ + (p_x + 2M ω₋ y) sin 3θ = −S_{1,3}",
        ],
    );
    assert_eq!(
        normalize(&text).matches(" = 0 at ω₊ = 3 ω₋").count(),
        4,
        "{text}"
    );
    expect(
        "fd-rotor-closure",
        &[
            "The table closes",
            "{P_{2,1}, Q_{2,1}} = −24M² ω₋ (2 ω₋ L + H_FD) at ω₊ = 2 ω₋, p_θ = 2I ω₋",
            "{R_{1,1}, S_{1,1}} = −3M ω₋ at ω₊ = 2 ω₋, p_θ = 2I ω₋",
            "{H_FD, P_{2,1}} = 2 ω₋ Q_{2,1} at ω₊ = 2 ω₋, p_θ = 2I ω₋",
            "{L, R_{1,1}} = −S_{1,1} at ω₊ = 2 ω₋, p_θ = 2I ω₋",
            "16M² ω₋² L² + 16M² ω₋ H_FD L + 4M² H_FD² = P_{2,1}² + Q_{2,1}² at ω₊ = 2 ω₋, \
             p_θ = 2I ω₋ [R1 proved]",
            "2M ω₋ L + R_{1,1}² + S_{1,1}² = 2M H_FD at ω₊ = 2 ω₋, p_θ = 2I ω₋ [R2 proved]",
            "12 claims: 12 proved, 0 refuted",
        ],
    );
    expect(
        "fd-rotor-closure-trap",
        &[
            "The table closes",
            "{U_{1,2}, V_{1,2}} = −36M³ ω₋ (4 ω₋² L² − H_FD²) at ω₊ = 2 ω₋, p_θ = 2I ω₋",
            "{R_{1,1}, U_{1,2}} = −3M ω₋ Q_{2,1} at ω₊ = 2 ω₋, p_θ = 2I ω₋",
            "P_{2,1} R_{1,1} + Q_{2,1} S_{1,1} = U_{1,2} at ω₊ = 2 ω₋, p_θ = 2I ω₋ [R3 proved]",
            "P_{2,1} S_{1,1} = Q_{2,1} R_{1,1} + V_{1,2} at ω₊ = 2 ω₋, p_θ = 2I ω₋ [R2 proved]",
            "27 claims: 27 proved, 0 refuted",
        ],
    );
}

/// The paper's rotor in the three-dimensional isotropic oscillator, loaded and checked: every
/// claim of the file holds (`F1`, `F2`, `L`, the Fradkin tensor, the paper's su(2) and its
/// Casimir in the x–y plane, the four ladders, the towers of `K = Z_x^m e^{−inθ}` and
/// `J = Z_z^m e^{−inθ}`, the rotations, the canonical pairs, the resonances, the paper's rotor
/// at `z = p_z = 0`, what the searches find, the algebra, rank 6 off the resonances and 7 at
/// one), and each of its eight false neighbours is refuted. `{P_{m,n}, H} = −(mω − nΩ) Q_{m,n}`
/// and `{R_{m,n}, H} = −(mω − nΩ) S_{m,n}` for `m ≤ 2`, `n ≤ 3`, each conserved at `Ω = ω`
/// exactly when `m = n`; the towers are proved for all `m, n`, and the rank of seven integrals
/// at the resonance is 7, with its certificate.
#[test]
fn iso3_rotor_claims_are_proved_and_its_false_neighbours_refuted() {
    let file = system_file("isotropic-rotor-3d.toml");
    assert_claims_as_expected(
        &file,
        &[
            "separable",
            "trace",
            "integrals",
            "so3",
            "paper-su2",
            "ladders",
            "modes",
            "tower",
            "rotation",
            "heisenberg",
            "modulus",
            "resonance",
            "paper-limit",
            "found",
            "algebra",
            "rank",
        ],
        &[
            "false-rotor-sign",
            "false-off-resonance",
            "false-other-resonance",
            "false-heisenberg-sign",
            "false-modulus",
            "false-algebra-axis",
            "false-rank-off-resonance",
            "false-rank-8",
        ],
    );
    let parse = |s: &str| file.parse_argument(s).expect("parses");
    let system = file.system();
    let resonance = file.condition("p_theta = I*omega").expect("a condition");
    for m in 0..=2i64 {
        for n in 0..=3i64 {
            if m + n == 0 {
                continue;
            }
            for (re, im) in [("P", "Q"), ("R", "S")] {
                let flow = system.flow(&parse(&format!("{re}_{m}_{n}"))).unwrap();
                let expected = parse(&format!("-({m}*omega - {n}*Omega)*{im}_{m}_{n}"));
                assert_eq!(flow, expected, "{re}_{m}_{n}");
                assert!(!parse(&format!("{im}_{m}_{n}")).is_zero(), "{im}_{m}_{n}");
                let conserved = resonance.apply(&flow).unwrap().is_zero();
                assert_eq!(conserved, m == n, "{re}_{m}_{n} at Ω = ω");
            }
        }
    }
    let out = superint(&[
        "tower",
        "--system",
        "systems/isotropic-rotor-3d.toml",
        "--max",
        "4",
        "--no-timings",
    ]);
    let text = normalize(&String::from_utf8(out.stdout).expect("UTF-8"));
    assert_eq!(out.status.code(), Some(0), "{text}");
    for piece in [
        "16 brackets expanded for the 3D isotropic rotor (ladder K_{m,n} = Z_x^m e^{−inθ}), all hold",
        "Therefore: {K_{m,n}, H} = i(mω − nΩ) K_{m,n} for all m, n ≥ 0.",
        "16 brackets expanded for the 3D isotropic rotor (ladder J_{m,n} = Z_z^m e^{−inθ}), all hold",
        "Therefore: {J_{m,n}, H} = i(mω − nΩ) J_{m,n} for all m, n ≥ 0.",
        "4 claims in 1 file: 4 proved, 0 refuted; all as expected",
    ] {
        assert!(text.contains(piece), "{piece}: {text}");
    }
    let out = superint(&[
        "rank",
        "systems/isotropic-rotor-3d.toml",
        "F1",
        "F2",
        "Lx",
        "Ly",
        "Lz",
        "Axx",
        "P_1_1",
        "--expect",
        "7",
        "--no-timings",
    ]);
    let text = normalize(&String::from_utf8(out.stdout).expect("UTF-8"));
    assert_eq!(out.status.code(), Some(0), "{text}");
    assert!(
        text.contains(
            "rank ∂(F1, F2, L_x, L_y, L_z, A_xx, P_{1,1})/∂(x, y, z, θ, p_x, p_y, p_z, p_θ) = 7"
        ),
        "{text}"
    );
}

/// The rotor in the three-dimensional oscillator. At `Ω = ω` the six new integrals, to fourth
/// and to sixth order, are the parts of `Z_j e^{−iθ}` (those along x and z restated `P_{1,1}`,
/// `−Q_{1,1}`, `R_{1,1}`, `−S_{1,1}`), and from `H` alone the same six (the oscillator's
/// integrals are their products); at `Ω = 2ω` the twelve parts of `Z_i Z_j e^{−iθ}`, at
/// `Ω = ω/2` the six of `Z_j e^{−2iθ}`, and off the resonances, for every `M, ω`, nothing
/// beyond `F1`, `F2`, `L` and the Fradkin tensor. At `Ω = ω` the table of the linear pairs with
/// the oscillator's integrals closes at degree 2, the relations writing `F1`, `L` and the
/// tensor in the pairs; at `Ω = 2ω` the quadratic ones close linearly, sp(4, R) in the x–z
/// plane and sp(6, R) in space.
#[test]
fn iso3_rotor_resonant_integrals_found_and_their_algebra() {
    let linear = [
        "Φ5 = p_z cos θ + Mωz sin θ = R_{1,1}",
        "Φ6 = −Mωz cos θ + p_z sin θ = −S_{1,1}",
        "Φ7 = p_y cos θ + Mωy sin θ",
        "Φ8 = −Mωy cos θ + p_y sin θ",
        "Φ9 = p_x cos θ + Mωx sin θ = P_{1,1}",
        "Φ10 = −Mωx cos θ + p_x sin θ = −Q_{1,1}",
        "A7 (k = 1) = p_y + iMωy = Z_y",
        "A8 (k = 1) = i p_y − Mωy = i Z_y",
    ];
    let mut pieces = vec![
        "11025 unknowns, 18359 linear equations over Q, in 1604 independent blocks",
        "Dimension of the space of integrals: 490. By degree in the momenta: ≤ 0: 1, ≤ 1: 10, \
         ≤ 2: 50, ≤ 3: 175, ≤ 4: 490.",
        "Known integrals in the space: H, F1, L_x, L_y, L_z, A_xx, A_yy, A_zz, A_xy.",
        "the generated ones span 484 of the 490 dimensions",
        "7 claims: 7 proved, 0 refuted",
    ];
    pieces.extend(linear);
    expect("iso3-rotor-search", &pieces);
    let alone = expect_alone(
        "iso3-rotor-search",
        &[
            "Known integrals in the space: H.",
            "the generated ones span 484 of the 490 dimensions",
            "J7 = p_y cos θ + Mωy sin θ",
            "7 claims: 7 proved, 0 refuted",
        ],
    );
    assert_eq!(alone.matches(" = 0 at p_θ = Iω [J").count(), 6, "{alone}");
    let mut pieces = vec![
        "91728 unknowns",
        "≤ 4: 490, ≤ 5: 1176, ≤ 6: 2520.",
        "the generated ones span 2514 of the 2520 dimensions",
        "7 claims: 7 proved, 0 refuted",
    ];
    pieces.extend(linear);
    expect("iso3-rotor-search-6", &pieces);
    let text = expect(
        "iso3-rotor-search-2-1",
        &[
            "Dimension of the space of integrals: 254. By degree in the momenta: ≤ 0: 1, ≤ 1: 4, \
             ≤ 2: 28, ≤ 3: 83, ≤ 4: 254.",
            "Known integrals in the space: H, F1, L_x, L_y, L_z, A_xx, A_yy, A_zz, A_xy, \
             {L_x, A_xy}, {L_y, A_xy}.",
            "the generated ones span 242 of the 254 dimensions",
            "Φ17 = (p_z² − M²ω²z²) cos θ + 2Mωz p_z sin θ = R_{2,1}",
            "Φ19 = (p_y p_z − M²ω²yz) cos θ + (Mωy p_z + Mωz p_y) sin θ",
            "Φ27 = (p_x² − M²ω²x²) cos θ + 2Mωx p_x sin θ = P_{2,1}",
            "= −Q_{2,1}",
            "A19 (k = 1) = p_y p_z + iMωy p_z + iMωz p_y − M²ω²yz = Z_y Z_z",
            "13 claims: 13 proved, 0 refuted",
        ],
    );
    assert_eq!(
        normalize(&text).matches(" = 0 at p_θ = 2Iω [Φ").count(),
        12,
        "{text}"
    );
    expect(
        "iso3-rotor-search-1-2",
        &[
            "Dimension of the space of integrals: 392.",
            "the generated ones span 386 of the 392 dimensions",
            "Φ5 = p_z cos 2θ + Mωz sin 2θ = R_{1,2}",
            "Φ9 = p_x cos 2θ + Mωx sin 2θ = P_{1,2}",
            "= −Q_{1,2}",
            "7 claims: 7 proved, 0 refuted",
        ],
    );
    let off = expect(
        "iso3-rotor-search-off",
        &[
            "52500 unknowns",
            "Dimension of the space of integrals over Q (a parameter's multiple of an integral \
             counts apart from it): 552.",
            "Over the polynomials in M, ω, 62 of the 552 basis integrals, Φ1, Φ16, Φ31,",
            "the generated ones span the whole space (552 dimensions)",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    assert!(!off.contains("of order 1"), "{off}");
    expect(
        "iso3-rotor-closure",
        &[
            "The table closes",
            "{P_{1,1}, Q_{1,1}} = −Mω at p_θ = Iω",
            "{P_y, Q_y} = −Mω at p_θ = Iω",
            "{L_z, P_{1,1}} = P_y at p_θ = Iω",
            "{L_y, P_{1,1}} = −R_{1,1} at p_θ = Iω",
            "2M A_xx = P_{1,1}² + Q_{1,1}² at p_θ = Iω",
            "Mω L_z + P_{1,1} Q_y = Q_{1,1} P_y at p_θ = Iω",
            "2M A_xy = P_{1,1} P_y + Q_{1,1} Q_y at p_θ = Iω",
            "2M F1 = 2M A_xx + R_{1,1}² + S_{1,1}² + P_y² + Q_y² at p_θ = Iω",
            "46 claims: 46 proved, 0 refuted",
        ],
    );
    expect(
        "iso3-rotor-closure-2-1",
        &[
            "The table closes: every bracket is a polynomial of degree ≤ 1 in the generators.",
            "{P_{2,1}, Q_{2,1}} = −8M²ω A_xx at p_θ = 2Iω",
            "{L_y, P_{2,1}} = −2 X at p_θ = 2Iω",
            "{P_{2,1}, X} = 2M²ω² L_y at p_θ = 2Iω",
            "{X, Y} = −2M²ω(A_xx + A_zz) at p_θ = 2Iω",
            "{L_y, A_zx} = A_xx − A_zz at p_θ = 2Iω",
            "36 claims: 36 proved, 0 refuted",
        ],
    );
    expect(
        "iso3-rotor-closure-sp6",
        &[
            "by exact linear algebra on the 22 monomials (their span has dimension 22)",
            "The table closes: every bracket is a polynomial of degree ≤ 1 in the generators.",
            "{T_yy, U_yy} = −8M²ω A_yy at p_θ = 2Iω",
            "{T_xy, U_xy} = −2M²ω(A_xx + A_yy) at p_θ = 2Iω",
            "{L_z, P_{2,1}} = 2 T_xy at p_θ = 2Iω",
            "{P_{2,1}, T_xy} = −2M²ω² L_z at p_θ = 2Iω",
            "147 claims: 147 proved, 0 refuted",
        ],
    );
}

/// A known integral given to a search as an expression prints as the file's claims print
/// one, in the file's printed names (`{L_x, A_xy}` beside `L_x` and `A_xy` in the same list,
/// `L_z²`), where it printed as typed (`{Lx, Axy}`, `Lz^2`); and a bracket typed without
/// spaces is an expression, where its letters, braces and comma read as a name (`Lx_Axy`).
#[test]
fn search_prints_a_known_expression_in_the_files_names() {
    let text = normalize(&superint_ok_line(
        "search systems/isotropic-rotor-3d.toml --when 'p_theta = 2*I*omega' --momenta-degree 2 \
         --positions-degree 2 --trig-degree 1 --new-only --known '{Lx, Axy},{Ly,Axy},Lz^2' \
         --no-timings",
    ));
    assert!(
        text.contains(
            "Known integrals in the space: H, F1, L_x, L_y, L_z, A_xx, A_yy, A_zz, A_xy, \
             {L_x, A_xy}, {L_y, A_xy}, L_z²."
        ),
        "{text}"
    );
    assert!(!text.contains("Lx_Axy") && !text.contains("{Lx"), "{text}");
}

/// A closure and a search print the names given on the command line as the file and the
/// paper write them: a family instance as the file shows it, however it was spelt
/// (`Kbar_1_1` and `K_{1,1}` print `K̄_{1,1}` and `K_{1,1}`, as `check` and `rank` print
/// them), a `--define`d name with several subscripts with them in braces (`R_{1,1}`), and a
/// known integral given as an expression as it was written.
#[test]
fn closure_and_search_print_names_as_the_file_shows_them() {
    let rotor = "systems/harmonic-rotor.toml";
    let out = superint(&[
        "closure",
        rotor,
        "L",
        "Kbar_1_1",
        "K_{1,1}",
        "R_1_1",
        "--define",
        "R_1_1=re((p_x - i*p_y + i*M*omega*(x - i*y))*exp(-i*theta))",
        "--when",
        "p_theta = I*omega",
        "--no-timings",
    ]);
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    assert_eq!(out.status.code(), Some(0), "{text}");
    assert!(
        text.contains("Closure of L, K̄_{1,1}, K_{1,1}, R_{1,1} for the harmonic rotor"),
        "{text}"
    );
    assert!(
        !text.contains("Kbar_1_1") && !text.contains("R_1_1"),
        "{text}"
    );
    let text = normalize(&superint_ok_line(
        "search systems/harmonic-rotor.toml --when 'p_theta = I*omega' --momenta-degree 2 \
         --positions-degree 2 --trig-degree 1 --new-only --known P_1_1,Q_{1,1},L^2 --no-timings",
    ));
    assert!(
        text.contains("Known integrals in the space: H, L, G1, G2, P_{1,1}, Q_{1,1}, L²."),
        "{text}"
    );
}

/// The Post–Winternitz system `H = p_x² + p_y² + αy/x^{2/3}`, written in `x = s³`, loaded and
/// checked: every claim of the file holds for every `α` (the change of coordinates, the third-
/// and fourth-order integrals `A`, `B` conserved, `{A, B} = 27α³/2`, the energy of the
/// `x`-motion no integral, the sixth-order `F = (D² − B³)/α³` a polynomial conserved, its
/// brackets and relation, the ranks), and each of its six false neighbours is refuted: `A`
/// with `3α` for `9α/2`, `B` with a sign turned, `{A, B}` with its sign turned, `D² + B³`, the
/// angular momentum conserved, and rank 4.
#[test]
fn post_winternitz_claims_are_proved_and_its_false_neighbours_refuted() {
    let file = system_file("post-winternitz.toml");
    assert_claims_as_expected(
        &file,
        &[
            "canonical",
            "hamiltonian",
            "third-order",
            "fourth-order",
            "nonseparable",
            "algebra",
            "sixth-order",
            "free-limit",
            "relation",
            "rank",
        ],
        &[
            "false-coefficient",
            "false-sign",
            "false-algebra",
            "false-relation",
            "false-quadratic",
            "false-rank",
        ],
    );
}

/// The Post–Winternitz system: up to fourth order in the momenta, for every `α`, the file's
/// `H`, `A`, `B` generate every integral, and there is none of second order but `H` (it
/// separates in no coordinates); from `H` alone the search finds `6A` and `18H² − 18B`. At
/// sixth order it finds, from `H` alone, a sixth-order integral beyond products of those,
/// `144F`, which the file's `F = (D² − B³)/α³` names: the polynomial `D² − B³` in `H`, `A`,
/// `B`, of degree 12 in the momenta, divided by `α³`. With `F` the four close, `{A, B}` a
/// constant, tied by that relation.
#[test]
fn post_winternitz_third_and_fourth_order_integrals_and_a_sixth_order_one_beyond_their_products() {
    expect(
        "pw-search",
        &[
            "9945 unknowns",
            "By degree in the momenta: ≤ 0: 3, ≤ 1: 3, ≤ 2: 5, ≤ 3: 7, ≤ 4: 9.",
            "Known integrals in the space: H, A, B.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    let i6 = "2 p_s² p_y/s⁴ + 12 p_y³ + 18αy p_y/s² + 9α p_s/s";
    let i8 = "4 p_s² p_y²/s⁴ + 18 p_y⁴ + 36αy p_y²/s² + 36α p_s p_y/s + 81α²s²";
    let text = expect_alone(
        "pw-search",
        &[
            "Known integrals in the space: H.",
            &format!("I6 = {i6}"),
            &format!("I8 = {i8}"),
            "3 claims: 3 proved, 0 refuted",
        ],
    );
    assert_eq!(text.matches(" = 0 [I").count(), 2, "{text}");
    let file = system_file("post-winternitz.toml");
    let parse = |t: &str| file.parse_argument(t).unwrap();
    assert_eq!(parse(i6), parse("6*A"));
    assert_eq!(parse(i8), parse("18*H^2 - 18*B"));
    expect(
        "pw-search-6",
        &[
            "≤ 4: 14, ≤ 5: 16, ≤ 6: 21.",
            "Known integrals in the space: H, A, B, D, F.",
            "None: the known integrals generate every integral in the space.",
        ],
    );
    let text = expect_alone(
        "pw-search-6",
        &["I21 = 8y p_s⁶/s¹² + 48y p_s⁴ p_y²/s⁸ − 24 p_s⁵ p_y/s⁷"],
    );
    assert_eq!(text.matches(" = 0 [I").count(), 3, "{text}");
    let i21 = &text[text.find("I21 = ").expect("I21") + "I21 = ".len()..];
    let i21 = &i21[..i21.find(" {I").expect("its claims after it")];
    assert_eq!(parse(i21), parse("144*F"));
    expect(
        "pw-closure",
        &[
            "The table closes",
            "{A, B} = 27α³/2 [B1 proved]",
            "{A, F} = −324 H⁴ + 243 H² B + 81 H A² − 81 B²/2 [B2 proved]",
            "{B, F} = 54(4 H³ − 3 H B − A²) A [B3 proved]",
            "α³ F + 24 H⁴ B + 8 H³ A² + B³ = 16 H⁶ + 9 H² B² + 6 H A² B + A⁴ [R1 proved]",
        ],
    );
}

/// The rotor on its resonant level set `p_θ = mIω/n`, of five dimensions: `F2` is constant
/// there, the oscillator's integrals have rank 3, and `K_{m,n}` adds one (its real and
/// imaginary parts once, `P² + Q² = 2M(F1 − F2 + ωL)`): rank 4, the most that integrals of a
/// flow on five dimensions can have, at 1:1 and 2:3 and under gravity. `P_{2,3}`, no integral
/// at 1:1, takes the rank to the level set's 5. The files' claims on the level set hold, and
/// their false neighbours (C17's and C25's five functions of rank 5 there, `P, Q` with `F1, L`
/// of rank 4, the unshifted functions under gravity of rank 3) are refuted.
#[test]
fn rotor_rank_on_its_resonant_level_set_is_four() {
    expect(
        "level-set-1-1",
        &[
            "rank ∂(F1, F2, L, G1, G2, P_{1,1}, Q_{1,1})/∂(x, y, θ, p_x, p_y) = 4 at p_θ = Iω \
             [rank proved]",
            "≤ 4: every 5 × 5 minor vanishes identically, as the 3 bordering the minor above do",
        ],
    );
    expect(
        "level-set-2-3",
        &["rank ∂(F1, L, G1, G2, P_{2,3}, Q_{2,3})/∂(x, y, θ, p_x, p_y) = 4 at p_θ = 2Iω/3"],
    );
    expect(
        "level-set-off",
        &[
            "rank ∂(F1, L, G1, G2, P_{1,1}, P_{2,3})/∂(x, y, θ, p_x, p_y) = 5 at p_θ = Iω",
            "≤ 5: there are 5 coordinates",
        ],
    );
    expect(
        "level-set-gravity",
        &["rank ∂(F1, F2, L', G1', G2', P'_{1,1}, Q'_{1,1})/∂(x, y, θ, p_x, p_y) = 4 at p_θ = Iω"],
    );
    for (name, proved, refuted) in [
        (
            "harmonic-rotor.toml",
            "C17-level-set",
            &["false-C17-level-set", "false-C17-level-set-PQ"],
        ),
        (
            "gravity-rotor.toml",
            "C25-level-set",
            &["false-C25-level-set", "false-C25-level-set-unshifted"],
        ),
    ] {
        let report = superint::system_file::check_report([&system_file(name)]).expect("checked");
        assert!(report.all_as_expected(), "{name}");
        let ids = report.claim_ids();
        assert!(ids.contains(&(proved.to_string(), true)), "{name}: {ids:?}");
        for id in refuted {
            assert!(ids.contains(&(id.to_string(), false)), "{name}: {ids:?}");
        }
    }
    let count = |name: &str| {
        let out = superint_ok_line(&format!("check systems/{name} --no-timings"));
        out.lines().last().expect("a summary").to_string()
    };
    assert_eq!(
        count("harmonic-rotor.toml"),
        "48 claims in 1 file: 41 proved, 7 refuted; all as expected"
    );
    assert_eq!(
        count("gravity-rotor.toml"),
        "31 claims in 1 file: 25 proved, 6 refuted; all as expected"
    );
}

/// `search` names the file's functions as its expressions write them, `ω3`, `θ1`, `Φ_x` of
/// functions `omega3`, `theta1`, `Phi_x`, in text, Markdown, LaTeX and JSON: among the known
/// integrals of `--new-only` (text, Markdown and JSON wrote `H, omega3, theta1, Phi_x`, beside
/// a basis restated as `2 H − 2 θ1`; LaTeX `\omega_{3}`) as in the restated integrals.
#[test]
fn search_names_functions_as_its_expressions_do() {
    let file = crate::scratch_text(
        "discovery",
        "greek-search.toml",
        r#"name = "oscillator in Greek words"
hamiltonian = "(p_x^2 + p_y^2)/2 + (x^2 + y^2)/2"
[phase_space]
coordinates = ["x", "y"]
[[function]]
name = "omega3"
value = "x*p_y - y*p_x"
[[function]]
name = "theta1"
value = "p_x^2/2 + x^2/2"
[[function]]
name = "Phi_x"
value = "p_x*p_y + x*y"
"#,
    );
    let path = file.to_str().expect("a path");
    let run = |format: &str, new_only: bool| {
        let mut args = vec!["search", path, "--no-timings", "--format", format];
        if new_only {
            args.push("--new-only");
        }
        crate::superint_ok(&args)
    };
    let known = [
        ("text", "Known integrals in the space: H, ω3, θ1, Φ_x."),
        (
            "markdown",
            "Known integrals in the space: `H, ω3, θ1, Φ_x`.",
        ),
        (
            "latex",
            r"Known integrals in the space: $H, \omega_{3}, \theta_{1}, \Phi_{x}$.",
        ),
    ];
    for (format, want) in known {
        let out = run(format, true);
        assert!(out.contains(want), "{format}: {out}");
        let basis = run(format, false);
        for spelled in ["omega3", "theta1", "Phi_x"] {
            assert!(!out.contains(spelled), "{format}: {spelled} in {out}");
            assert!(!basis.contains(spelled), "{format}: {spelled} in {basis}");
        }
    }
    assert!(run("text", false).contains("    I3 = p_y² + y²\n       = 2 H − 2 θ1\n"));
    let json: String = run("json", true).split_whitespace().collect();
    assert!(json.contains(r#""known":["H","ω3","θ1","Φ_x"]"#), "{json}");
}

/// A search's labels and a table's placeholders name nothing the file shows, a function named
/// by a Greek word among them: beside functions `I1`, `J1` and `Phi1` (shown `Φ1`) the
/// integrals are `Ξ1, Ξ2, …` (they were `Φ1, Φ2`, the first of which printed as the function),
/// and beside functions `A`, `F`, `U` and `Phi` a table's rows and columns are `Ξ` and `Λ` (they
/// were `Φ` and `Ψ`).
#[test]
fn labels_and_placeholders_name_nothing_a_file_shows() {
    let file = crate::scratch_text(
        "discovery",
        "greek-labels.toml",
        r#"name = "oscillator with labels taken"
hamiltonian = "(p_x^2 + p_y^2)/2 + (x^2 + y^2)/2"
[phase_space]
coordinates = ["x", "y"]
[[function]]
name = "I1"
value = "x*p_y - y*p_x"
[[function]]
name = "J1"
value = "p_x^2/2 + x^2/2"
[[function]]
name = "Phi1"
value = "p_x*p_y + x*y"
[[function]]
name = "A"
value = "p_y^2/2 + y^2/2"
[[function]]
name = "F"
value = "p_x + y"
[[function]]
name = "U"
value = "p_y - x"
[[function]]
name = "Phi"
value = "p_x*p_y"
"#,
    );
    let path = file.to_str().expect("a path");
    let args = [
        "--momenta-degree",
        "1",
        "--positions-degree",
        "1",
        "--no-timings",
    ];
    let search = crate::superint_ok(&[&["search", path][..], &args[..]].concat());
    assert!(
        search.contains("    Ξ1 = 1\n    Ξ2 = x p_y − y p_x\n       = I1\n"),
        "{search}"
    );
    assert!(!search.contains("Φ1 ="), "{search}");
    let table = crate::superint_ok(&["table", path, "A", "F", "--no-timings"]);
    assert!(
        table.contains("{Ξ, Λ} for the oscillator with labels taken (row Ξ, column Λ)"),
        "{table}"
    );
}

/// A built-in system warns of what the command line's texts read in doubt, as a system file
/// does (`F1x` read as `F1 x` beside the function `F1`), in `--define`, `--known` and
/// `--when` alike: its parser gathered no warnings, so the same text said nothing there.
#[test]
fn a_built_in_system_warns_of_names_run_together() {
    // A built-in system's names are fixed: the advice is the product's, not to declare F1x.
    let warning = "'F1x' is read as the product F1 x, the function F1 with x after it: write \
                   'F1 x' or 'F1*x' for the product\n";
    let search = ["search", "--system", "harmonic", "--momenta-degree", "1"];
    let runs: [Vec<&str>; 4] = [
        vec![
            "closure", "--system", "harmonic", "F1", "F2", "E", "--define", "E=F1x",
        ],
        [&search[..], &["--new-only", "--known", "F1x"]].concat(),
        [&search[..], &["--when", "x = F1x"]].concat(),
        [&search[..], &["--when", "x = 1,  y =  F1x"]].concat(),
    ];
    // The column of the name in the text as typed: a condition's, not its value's.
    for (args, column) in runs.iter().zip([3, 1, 5, 14]) {
        let o = superint(args);
        let stderr = String::from_utf8(o.stderr).expect("UTF-8");
        let warning = format!("superint: warning: <command line>:1:{column}: {warning}");
        assert!(stderr.starts_with(&warning), "{args:?}: {stderr}");
        // Once, however often the text is read.
        assert_eq!(
            stderr.matches("superint: warning:").count(),
            1,
            "{args:?}: {stderr}"
        );
        // The closure goes on; F1x is no integral, and x = F1x sets x in terms of itself.
        let code = if args[0] == "closure" { 0 } else { 2 };
        assert_eq!(o.status.code(), Some(code), "{args:?}: {stderr}");
    }
}

/// A `--when` value of a built-in system that does not parse is refused at its place in the
/// condition as typed, as a system file's is, the caret and a place the message names
/// (`'(' opened at column 12`): they were counted from the value's start (column 3, opened at
/// column 1). It is written as a file's is, `<command line>:1:14:` and the numbered line.
#[test]
fn a_built_in_system_s_condition_error_points_into_the_condition() {
    let err = superint_refused(&["search", "--system", "harmonic", "--when", "ω = 1, x = (1"]);
    assert!(
        err.starts_with(
            "superint: error: <command line>:1:14: expected ')' to close '(' opened \
             at column 12, found end of input\n 1 | ω = 1, x = (1\n   |              ^\n"
        ),
        "{err}"
    );
}

/// `search --new-only` where `H` lies past the space's degrees, so that no known integral is
/// in it: the only integrals are constants, and the report said that the known integrals,
/// `no named function`, generate every one.
#[test]
fn new_only_with_no_known_integral_in_the_space_says_the_constants_are_all() {
    let path = crate::scratch_text(
        "new-only-nothing-known",
        "osc.toml",
        "name = \"oscillator\"\nhamiltonian = \"p_x^2/(2*M) + M*omega^2*x^2/2\"\n\
         [phase_space]\ncoordinates = [\"x\"]\nparameters = [\"M\", \"omega\"]\n",
    );
    let path = path.to_str().expect("a path");
    let args = [
        "search",
        path,
        "--momenta-degree",
        "1",
        "--positions-degree",
        "1",
        "--new-only",
    ];
    let text = normalize(&crate::superint_ok(&args));
    for piece in [
        "Known integrals in the space: none.",
        "None: no known integral lies in the space, and every integral in it is a constant, \
         which counts as generated.",
    ] {
        assert!(text.contains(piece), "{piece:?} not in:\n{text}");
    }
    assert!(!text.contains("the known integrals generate"), "{text}");
}

/// A closure's generator that does not read says what is wrong first, at its place, as
/// `bracket` does: the message began with the generator, `'Foo': <command line>:1:1: unknown
/// name 'Foo'`, which its excerpt shows below anyway. A built-in system's says it as a file's
/// does, with the numbered line: it said `line 1, column 1:` with an unnumbered one.
#[test]
fn a_closure_generator_that_does_not_read_says_what_is_wrong_first() {
    let file = superint_refused(&["closure", "systems/harmonic-rotor.toml", "L", "Foo"]);
    assert!(
        file.starts_with("superint: error: <command line>:1:1: unknown name 'Foo' (known:"),
        "{file}"
    );
    let bracket = superint_refused(&["bracket", "systems/harmonic-rotor.toml", "Foo", "L"]);
    assert_eq!(file.lines().next(), bracket.lines().next());
    let built_in = superint_refused(&["closure", "--system", "harmonic", "L", "Foo"]);
    assert!(
        built_in.starts_with("superint: error: <command line>:1:1: unknown name 'Foo' (known:"),
        "{built_in}"
    );
    // With the same numbered line and caret.
    assert_eq!(built_in.lines().nth(1), Some(" 1 | Foo"), "{built_in}");
    assert_eq!(built_in.lines().nth(2), file.lines().nth(2), "{built_in}");
}

/// A closure works in the system's limits: a generator of parameters alone, `A = a^1500` in a
/// file whose `[limits]` allow a degree of 32767, was refused "the exponent of a would reach
/// 1500, past the limit of 1000", with the advice to raise --max-degree, which changed
/// nothing, since the ring the closure is written in took the default limits.
#[test]
fn a_closure_takes_the_files_limits() {
    let text = "name = \"t\"\nhamiltonian = \"p_x^2\"\n[limits]\nmax_degree = 32767\n\
                [phase_space]\ncoordinates = [\"x\"]\nparameters = [\"a\"]\n\
                [[function]]\nname = \"L\"\nvalue = \"x*p_x\"\n\
                [[function]]\nname = \"A\"\nvalue = \"a^1500\"\n";
    let path = crate::scratch_text("discovery", "closure-limits.toml", text);
    let path = path.to_str().expect("UTF-8");
    let out = crate::superint_ok(&["closure", path, "L", "A", "--degree", "1", "--no-timings"]);
    assert!(out.contains("A = a¹⁵⁰⁰"), "{out}");
    // The command line's limit is the closure's too.
    let err = crate::superint_refused(&[
        "closure",
        path,
        "L",
        "A",
        "--degree",
        "1",
        "--max-degree",
        "1200",
    ]);
    assert!(err.contains("past the limit of 1200"), "{err}");
}

/// `--system NAME` of bracket, expand, table, rank and closure built the built-in system twice,
/// with its resonant functions `P11`, … and without, to keep them only where the command names
/// one; it now builds it once and adds them to a copy (`define_builtin_resonant`), which must
/// give the system built with them: the same functions, in the same order, shown alike. The
/// command line's output is the same (bracket_expand_table_and_rank_take_a_built_in_system).
#[test]
fn a_built_in_systems_resonant_functions_added_to_a_copy_are_those_it_is_built_with() {
    use superint::discovery::{builtin_system, define_builtin_resonant, BUILTIN_SYSTEMS};
    let limits = LimitsOverride::default().or_defaults();
    for name in BUILTIN_SYSTEMS {
        let (_, with) = builtin_system(name, true, limits).unwrap().unwrap();
        let (_, mut added) = builtin_system(name, false, limits).unwrap().unwrap();
        let plain = added.functions().len();
        define_builtin_resonant(name, &mut added).unwrap();
        assert_eq!(added.functions(), with.functions(), "{name}");
        let resonant = ["harmonic", "gravity"].contains(&name);
        assert_eq!(
            added.functions().len() - plain,
            if resonant { 36 } else { 0 }
        );
    }
}

/// At `--fix` values an integral not lifted back to the parameters holds there only, and is
/// restated there, `H` and the file's functions with the values put in: the parabolic
/// integral `I3` of the quartic potentials is `P` at `a = 12, b = 16`, where alone `{P, H} = 0`,
/// so it stays there; its companion `I2` is `2 H` there (it was shown with no form, as `H`
/// with `a, b` free is none of it), and `2 H` is an integral for every value, so `I2` is lifted
/// through it, counted with those that hold for every value. One lifted holds for every value
/// and is not restated at the values: under `H = p²/2 + ay`, `p_x` is `K = p_x + a p_y` at
/// `a = 0` alone, where `K` is no integral elsewhere; `x p_y − y p_x`, an integral at `a = 0`
/// only, is `M = x p_y − y p_x + ax` there.
#[test]
fn search_at_fixed_values_restates_there_only_what_is_not_lifted() {
    let quartic = normalize(&superint_ok_line(
        "search systems/quartic-potentials.toml --fix a=12,b=16 --momenta-degree 2 \
         --positions-degree 5 --trig-degree 0",
    ));
    for piece in [
        "I2 = p_x² + p_y² + 2x⁴ + 24x²y² + 32y⁴ = 2 H",
        "so nothing is lifted; 1 of the 3 basis elements holds for every value as found and 1 \
         through its restatement (proved symbolically), the others at these values only.",
        "What is not lifted holds at these values",
        "Restated at a = 12, b = 16, where it holds (not lifted): I3, with H and the file's \
         functions at these values.",
        "Restated at a = 12, b = 16, where it is found, and lifted through the restatement: I2, \
         with the file's functions as written.",
        "{2 H, H} = 0 [I2 proved] proved for every a, b; it is I2 at a = 12, b = 16",
        "{I3, H} = 0 at a = 12, b = 16 [I3 proved] not lifted back to the parameters",
    ] {
        assert!(
            quartic.contains(&normalize(piece)),
            "no {piece:?} in:\n{quartic}"
        );
    }
    let text = "name = \"fall\"\nhamiltonian = \"p_x^2/2 + p_y^2/2 + a*y\"\n\
        [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\"]\n\
        [[function]]\nname = \"K\"\nvalue = \"p_x + a*p_y\"\n\
        [[function]]\nname = \"M\"\nvalue = \"x*p_y - y*p_x + a*x\"\n";
    let file = crate::scratch_text("discovery", "fall.toml", text);
    let file = file.to_str().expect("a UTF-8 path");
    let fall = |fix: &str| {
        normalize(&superint_ok(&[
            "search",
            file,
            "--fix",
            fix,
            "--momenta-degree",
            "1",
            "--positions-degree",
            "1",
        ]))
    };
    let at_zero = fall("a=0");
    assert!(
        at_zero.contains("I3 = p_x I4 = x p_y − y p_x = M")
            && at_zero.contains("Restated at a = 0, where it holds (not lifted): I4,")
            && at_zero.contains("{I3, H} = 0 [I3 proved]"),
        "{at_zero}"
    );
    // Elsewhere `x p_y − y p_x` is no integral, and nothing is restated.
    let at_one = fall("a=1");
    assert!(
        !at_one.contains("x p_y − y p_x") && !at_one.contains("= K") && !at_one.contains("= M"),
        "{at_one}"
    );
}

/// A restatement at the fixed values whose number stands for a parameter's value is no integral
/// for every value, and the integral stays unlifted: with `a = 0` and `k = 1, w = 7, m = 1`
/// fixed, the motion along `y` gives `I2 = p_y² + 2y⁶ + 98y⁴ + 2y² = 2 T + 98 W`, where `98` is
/// `2w²`; read with `w` symbolic, `{2 T + 98 W, H} ≠ 0`. The same integral is lifted through
/// `2 Y` where the file names `Y = T + w² W`, the same at `w = 7` but an integral for every
/// value.
#[test]
fn a_restatement_whose_number_stands_for_a_value_is_not_lifted_through() {
    let text = "name = \"omega\"\n\
        hamiltonian = \"(p_x^2 + p_y^2)/2 + x^4 + a*x^2*y^2 + k*y^2 + w^2*y^4 + m*y^6\"\n\
        [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\", \"k\", \"w\", \"m\"]\n\
        [[function]]\nname = \"T\"\nvalue = \"p_y^2/2 + k*y^2 + m*y^6\"\n\
        [[function]]\nname = \"W\"\nvalue = \"y^4\"\n";
    let with_y = format!("{text}[[function]]\nname = \"Y\"\nvalue = \"T + w^2*W\"\n");
    let search = |name: &str, text: &str| {
        let file = crate::scratch_text("discovery", name, text);
        let file = file.to_str().expect("a UTF-8 path").to_string();
        normalize(&superint_ok(&[
            "search",
            &file,
            "--when",
            "a = 0",
            "--fix",
            "k=1,w=7,m=1",
            "--momenta-degree",
            "2",
            "--positions-degree",
            "6",
        ]))
    };
    let number = search("omega-number.toml", text);
    for piece in [
        "I2 = p_y² + 2y⁶ + 98y⁴ + 2y² = 2 T + 98 W",
        "Restated at a = 0, k = 1, w = 7, m = 1, where it holds (not lifted): I2,",
        "{I2, H} = 0 at a = 0, k = 1, w = 7, m = 1 [I2 proved] not lifted back to the parameters",
    ] {
        assert!(number.contains(piece), "no {piece:?} in:\n{number}");
    }
    assert!(!number.contains("lifted through"), "{number}");
    let named = search("omega-named.toml", &with_y);
    for piece in [
        "I2 = p_y² + 2y⁶ + 98y⁴ + 2y² = 2 Y",
        "{2 Y, H} = 0 at a = 0 [I2 proved]",
    ] {
        assert!(named.contains(piece), "no {piece:?} in:\n{named}");
    }
    assert!(!named.contains("(not lifted)"), "{named}");
}

/// The claim of an integral lifted through its restatement says for which parameters it is
/// proved and at which values it is the integral, wrapped as the report's other lines are
/// (it ran past the line at long fixed values): the Euler top's quadratic integrals at three
/// unequal moments.
#[test]
fn a_claim_lifted_through_its_restatement_says_where_wrapped() {
    let out = superint_ok_line(
        "search systems/euler-top.toml --poisson-degree 2 \
         --fix I1=100001/100003,I2=200003/200017,I3=300007/300017",
    );
    for label in ["J2", "J3"] {
        let note = format!(
            "[{label} proved] proved for every I1, I2, I3; it is {label} at I1 = 100001/100003, \
             I2 = 200003/200017, I3 = 300007/300017"
        );
        assert!(normalize(&out).contains(&note), "no {note:?} in:\n{out}");
    }
    let notes: Vec<&str> = (out.lines())
        .filter(|l| l.contains("proved for every I1"))
        .collect();
    assert_eq!(notes.len(), 2, "{out}");
    assert!(notes.iter().all(|l| l.chars().count() <= 96), "{out}");
}

/// The lines of a search's JSON restated in the file's functions: each line's label (`I2`,
/// `A7 (k = 1)`) with its `"in_functions"`, where it has one.
fn restated(json: &serde_json::Value) -> Vec<(String, serde_json::Value)> {
    (json["equations"].as_array().expect("equations").iter())
        .flat_map(|e| e["lines"].as_array().expect("lines").clone())
        .filter(|l| !l["in_functions"].is_null())
        .map(|l| {
            (
                l["lhs"].as_str().expect("a label").to_string(),
                l["in_functions"].clone(),
            )
        })
        .collect()
}

/// In JSON, a restatement of an integral not lifted back to the parameters fixed with `--fix`
/// says where it holds, `"holds_at"`, as the text's "Restated at … (not lifted)" does: the
/// quartic potentials' `I3 = P` at `a = 12, b = 16`, but not their `I2 = 2 H`, lifted through
/// `2 H`, an integral for every value, whose claim is `{2*H, H} = 0`; under `H = p²/2 + ay` at
/// `a = 0`, `x p_y − y p_x = M` there alone, while `p_x = L`, lifted, holds for every value
/// and carries no such field.
#[test]
fn json_says_where_a_restatement_of_an_integral_not_lifted_holds() {
    let quartic = crate::superint_json(&[
        "search",
        "systems/quartic-potentials.toml",
        "--fix",
        "a=12,b=16",
        "--momenta-degree",
        "2",
        "--positions-degree",
        "5",
        "--trig-degree",
        "0",
    ]);
    let forms = restated(&quartic);
    let labels: Vec<&str> = forms.iter().map(|(l, _)| l.as_str()).collect();
    assert_eq!(labels, ["I2", "I3"], "{quartic}");
    assert_eq!(forms[0].1["ascii"], "2*H");
    assert!(forms[0].1.get("holds_at").is_none(), "{quartic}");
    assert_eq!(forms[1].1["holds_at"], "a = 12, b = 16", "{quartic}");
    let claim = |id: &str| {
        (quartic["claims"].as_array().expect("claims").iter())
            .find(|c| c["id"] == id)
            .map(|c| (c["ascii"].clone(), c["condition_ascii"].clone()))
    };
    let null = serde_json::Value::Null;
    assert_eq!(
        claim("I2"),
        Some(("{2*H, H} = 0".into(), null)),
        "{quartic}"
    );
    assert_eq!(
        claim("I3").map(|(_, at)| at),
        Some("a = 12, b = 16".into()),
        "{quartic}"
    );
    let text = "name = \"fall\"\nhamiltonian = \"p_x^2/2 + p_y^2/2 + a*y\"\n\
        [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\"]\n\
        [[function]]\nname = \"L\"\nvalue = \"p_x\"\n\
        [[function]]\nname = \"M\"\nvalue = \"x*p_y - y*p_x + a*x\"\n";
    let file = crate::scratch_text("discovery", "fall-restated.toml", text);
    let fall = crate::superint_json(&[
        "search",
        file.to_str().expect("a UTF-8 path"),
        "--fix",
        "a=0",
        "--momenta-degree",
        "1",
        "--positions-degree",
        "1",
    ]);
    let forms = restated(&fall);
    let at: Vec<(&str, &str, Option<&str>)> = (forms.iter())
        .map(|(l, f)| {
            (
                l.as_str(),
                f["ascii"].as_str().unwrap(),
                f["holds_at"].as_str(),
            )
        })
        .collect();
    assert_eq!(
        at,
        [("I3", "L", None), ("I4", "M", Some("a = 0"))],
        "{fall}"
    );
    // The lifted one has no such field at all, not a null one.
    assert!(forms[0].1.get("holds_at").is_none(), "{fall}");
}

/// `"holds_at"` on the amplitudes of complex forms too, and as `--when` reads it back: the
/// 3D isotropic rotor at `p_θ = 1` with `M = ω = I = 1` fixed, where `Φ7 = p_y cos θ + y sin θ`
/// is an integral at the resonance `p_θ/I = ω` alone, so not lifted, and its amplitude
/// `A7 = p_y + iy` is `Z_y = p_y + iMωy` there only, as `Φ9 = P_{1,1}` is; `Φ2 = L_x`,
/// lifted, holds for every value. Searched again at `--when` that condition, nothing is fixed, and the same
/// restatements hold there with no `"holds_at"`. On the level set `p_θ = 1` (`--on`, a
/// search with no condition) the amplitudes hold at the fixed values alone.
#[test]
fn json_says_where_an_amplitude_not_lifted_is_restated_as_when_reads_it_back() {
    let rotor = |condition: &[&str]| {
        let args = [
            &["search", "systems/isotropic-rotor-3d.toml"][..],
            condition,
            &["--momenta-degree", "1", "--positions-degree", "1"],
        ]
        .concat();
        restated(&crate::superint_json(&args))
    };
    let form = |forms: &[(String, serde_json::Value)], label: &str| {
        (forms.iter().find(|(l, _)| l.starts_with(label)))
            .map(|(_, f)| (f["ascii"].clone(), f.get("holds_at").cloned()))
            .unwrap_or_else(|| panic!("no {label} in {forms:?}"))
    };
    let fixed = rotor(&["--when", "p_theta = 1", "--fix", "M=1,I=1,omega=1"]);
    let (a7, at) = form(&fixed, "A7 (k = 1)");
    assert_eq!(a7, "Zy");
    let at = at.expect("A7 restated at the fixed values only");
    let when = at.as_str().expect("a condition");
    assert_eq!(when, "p_theta = 1, M = 1, omega = 1, I = 1");
    assert_eq!(form(&fixed, "Φ9"), ("P_1_1".into(), Some(at.clone())));
    assert_eq!(form(&fixed, "Φ2"), ("Lx".into(), None));
    let read_back = rotor(&["--when", when]);
    for label in ["A7 (k = 1)", "Φ9", "Φ2"] {
        assert_eq!(form(&read_back, label).1, None, "{label}: {read_back:?}");
        assert_eq!(form(&read_back, label).0, form(&fixed, label).0, "{label}");
    }
    let on = rotor(&["--on", "p_theta = 1", "--fix", "M=1,I=1,omega=1"]);
    let (a7, at) = form(&on, "A7 (k = 1)");
    assert_eq!(
        (a7, at),
        ("Zy".into(), Some("M = 1, omega = 1, I = 1".into()))
    );
}

/// A search that finds only the powers of `H` says which positions degree would hold every
/// weighted-homogeneous integral of its momenta degree whose weight is that of its momenta
/// alone, where `H` is weighted-homogeneous: the
/// quartic potentials at `a = 6, b = 8` (positions of weight 1, momenta of weight 2) at
/// momenta and positions degree 4 find `1` and `H`, and the hint's `--positions-degree 8`
/// finds the file's quartic integral `Q`, where no hint is given. Hénon–Heiles, `H` not
/// weighted-homogeneous (`x² + y²` beside `x²y`), gets none.
#[test]
fn a_search_finding_only_powers_of_h_names_the_positions_degree_to_try() {
    let quartic = |positions| quartic_potentials_search("a=6,b=8", 4, positions);
    let hint = "those of weight ≤ 8 are held by --positions-degree 8,";
    let short = quartic(4);
    assert!(
        short.contains("Dimension of the space of integrals: 2.")
            && short.contains("(the coordinates of weight 1, the momenta of weight 2)")
            && short.contains(hint),
        "{short}"
    );
    let full = quartic(8);
    assert!(full.contains("= Q") && !full.contains(hint), "{full}");
    let henon = normalize(&superint_ok_line(
        "search systems/henon-heiles.toml --momenta-degree 2 --positions-degree 2 \
         --trig-degree 0",
    ));
    assert!(
        henon.contains("Dimension of the space of integrals: 1.") && !henon.contains("weighted"),
        "{henon}"
    );
}

/// On a level set the flow of `H` keeps only at the fixed values, the report says so, and
/// suggests no other value where the level set is refused: `p_y = 0` of
/// `p_x²/2 + p_y²/2 + xy p_y + ay` is kept at `a = 0` alone, and refused at `a = 2` (it was
/// suggested, `--fix a=2`); `H = 1` of the 1:2 oscillator, kept for every value, is said kept
/// with no such words, and other values are suggested.
#[test]
fn a_level_set_kept_at_the_fixed_values_alone_says_so_and_suggests_no_refused_value() {
    let text = "name = \"sheared\"\nhamiltonian = \"p_x^2/2 + p_y^2/2 + x*y*p_y + a*y\"\n\
        [phase_space]\ncoordinates = [\"x\", \"y\"]\nparameters = [\"a\"]\n";
    let file = crate::scratch_text("discovery", "sheared.toml", text);
    let file = file.to_str().expect("a UTF-8 path");
    let search = |fix: &str| {
        let args = ["search", file, "--fix", fix, "--on", "p_y = 0"];
        let degrees = ["--momenta-degree", "1", "--positions-degree", "1"];
        superint(&[&args[..], &degrees].concat())
    };
    let out = search("a=0");
    let at_zero = normalize(&String::from_utf8(out.stdout).expect("UTF-8"));
    assert!(
        at_zero.contains("which the flow of H keeps at the fixed values")
            && at_zero.contains("it is refused at a = 2)")
            && !at_zero.contains("--fix a=2"),
        "{at_zero}"
    );
    assert_eq!(search("a=2").status.code(), Some(2));
    let oscillator = normalize(&superint_ok_line(
        "search systems/anisotropic-oscillator-1-2.toml --on 'H = 1' --fix M=1,omega=1 \
         --momenta-degree 3 --positions-degree 3",
    ));
    assert!(
        oscillator.contains("which the flow of H keeps ({P, H} is a multiple of P)")
            && oscillator.contains("compare with other values (--fix M=2,omega=3)"),
        "{oscillator}"
    );
}

/// A known integral refused under `--symbolic` shows its bracket with `H` over common
/// denominators: of the Neumann system, `x1² + L2²/(a1 − a3)` has
/// `{·, H} = −2 L3 x1 x2` (it was shown `−2 L2 x1 x3 (a1 − a3)/(a1 − a3) + 2 L2 x1 x3 − …`,
/// the declared denominator not cancelled against its polynomial).
#[test]
fn a_refused_known_integral_shows_its_bracket_with_denominators_cancelled() {
    let refused = superint_refused(&[
        "search",
        "systems/neumann.toml",
        "--poisson-degree",
        "2",
        "--denominators-degree",
        "1",
        "--symbolic",
        "a1,a2,a3",
        "--parameters-degree",
        "1",
        "--new-only",
        "--known",
        "x1^2 + L2^2/(a1 - a3)",
    ]);
    assert!(
        refused.contains("is not an integral: {x1² + L2²/(a1 − a3), H} = −2 L3 x1 x2")
            && !refused.contains("(a1 − a3)/(a1 − a3)"),
        "{refused}"
    );
}

/// The positions-degree hint claims no more than its weights prove: at `a = 12, b = 16` the
/// quartic potentials' parabolic integral `P = x p_x p_y − y p_x² + 4x⁴y + 8x²y³` has momenta
/// degree 2 but weight 5, past the `2 · 2 = 4` of the momenta alone, so the hint at momenta
/// degree 2 and positions degree 3 names `--positions-degree 4` for the integrals of weight
/// `≤ 4` only (none there but the powers of `H`), says one of greater weight `W` needs
/// positions degree up to `W`, and says what this space rules out (weight `≤ 3`); `P` is found
/// at positions degree 5, not 4.
#[test]
fn the_positions_degree_hint_bounds_only_integrals_of_the_weight_it_names() {
    let parabolic = |positions| quartic_potentials_search("a=12,b=16", 2, positions);
    let short = parabolic(3);
    assert!(
        short.contains("no integral of momenta degree ≤ 2 and weight ≤ 3 but the powers of H")
            && short.contains("those of weight ≤ 4 are held by --positions-degree 4")
            && short.contains("one of a greater weight W needs positions degree up to W"),
        "{short}"
    );
    let four = parabolic(4);
    assert!(
        four.contains("Dimension of the space of integrals: 2.") && !four.contains("= P"),
        "{four}"
    );
    let five = parabolic(5);
    assert!(five.contains("= P"), "{five}");
}

/// The report of `superint search` on the quartic potentials at `fix`, of no angles, momenta
/// degree `momenta` and positions degree `positions`, normalized.
fn quartic_potentials_search(fix: &str, momenta: u32, positions: u32) -> String {
    normalize(&superint_ok_line(&format!(
        "search systems/quartic-potentials.toml --fix {fix} --momenta-degree {momenta} \
         --positions-degree {positions} --trig-degree 0"
    )))
}

/// Every search says the functional rank of its basis beside its dimension, in the text and
/// in JSON: the harmonic rotor at the resonance `p_θ = Iω` has 20 integrals of rank 4 where
/// the condition holds (maximal on that five-dimensional level set: with `p_θ`, 5 = 2·3 − 1
/// in the whole phase space), the same on the level set `p_θ = 1` at `ω = 1`, and off the
/// resonance 9 integrals of rank 4, a rank below the dimension and not maximal.
#[test]
fn every_search_says_the_functional_rank_of_its_basis() {
    let rotor = "systems/harmonic-rotor.toml";
    let resonance = [
        "search",
        rotor,
        "--when",
        "p_theta = I*omega",
        "--no-timings",
    ];
    let text = superint_ok(&resonance);
    assert!(
        normalize(&text).contains(
            "Dimension of the space of integrals: 20. By degree in the momenta: ≤ 0: 1, ≤ 1: 6, \
             ≤ 2: 20. Functional rank: 4, the most a flow on the 5-dimensional level set \
             allows (maximal superintegrability)."
        ),
        "{text}"
    );
    let json = superint_json(&resonance);
    let found = &json["searches"][0];
    assert_eq!(found["dimension"], 20);
    assert_eq!(found["functional_rank"], 4);
    assert_eq!(found["functional_rank_exact"], true);
    assert_eq!(found["functional_rank_bound"], "flow");
    let on = [
        "search",
        rotor,
        "--on",
        "p_theta = 1",
        "--fix",
        "omega=1",
        "--no-timings",
    ];
    let text = superint_ok(&on);
    assert!(
        normalize(&text).contains("≤ 2: 20. Functional rank: 4, the most a flow on the"),
        "{text}"
    );
    let generic = superint_json(&["search", rotor, "--no-timings"]);
    let found = &generic["searches"][0];
    assert_eq!(found["dimension"], 9);
    assert_eq!(found["functional_rank"], 4);
}

/// The prose keeps a value with what it is the value of where the two fit on a line: the
/// Euler top's `I3 = 300007/300017` in the parameters' sentence and in each claim's note,
/// and `≤ 2: 3` in the dimensions by degree; no line of the report is wider than the wrap.
#[test]
fn the_prose_keeps_a_value_with_its_name_on_one_line() {
    let fix = "I1=100001/100003,I2=200003/200017,I3=300007/300017";
    let args = [
        "search",
        "systems/euler-top.toml",
        "--poisson-degree",
        "4",
        "--fix",
        fix,
    ];
    let text = superint_ok(&[&args[..], &["--no-timings"]].concat());
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines.iter().all(|l| !l.ends_with(" =")), "{text}");
    assert!(
        lines.iter().any(|l| l.starts_with("I3 = 300007/300017;")),
        "{text}"
    );
    assert_eq!(
        lines
            .iter()
            .filter(|l| l.trim_start() == "I3 = 300007/300017")
            .count(),
        5,
        "{text}"
    );
    assert!(text.contains("≤ 2: 3, ≤ 3: 3"), "{text}");
    assert!(lines.iter().all(|l| l.chars().count() <= 96), "{text}");
}

/// Maximal superintegrability certified by the flow alone: the 3D Kepler problem's 14
/// integrals of momenta degree `≤ 2` (more than its 6 phase variables) have rank 5, the most
/// integrals of a flow can have, exact with no bordering minor (JSON's upper bound is the
/// rank's alone, `functional_rank_exact`); the harmonic rotor at the resonance `p_θ = Iω`,
/// 20 integrals, rank 4 on the five dimensions the condition leaves, the same.
#[test]
fn maximal_superintegrability_is_certified_by_the_flow_without_minors() {
    let kepler = [
        "search",
        "systems/kepler-3d.toml",
        "--momenta-degree",
        "2",
        "--positions-degree",
        "2",
        "--radicals-degree",
        "1",
        "--no-timings",
    ];
    let text = normalize(&superint_ok(&kepler));
    assert!(
        text.contains(
            "Dimension of the space of integrals: 14. By degree in the momenta: ≤ 0: 1, ≤ 1: \
             4, ≤ 2: 14. Functional rank: 5, the most a flow in 6 phase variables allows \
             (maximal superintegrability)."
        ),
        "{text}"
    );
    let json = superint_json(&kepler);
    assert_eq!(json["searches"][0]["dimension"], 14);
    assert_eq!(json["searches"][0]["functional_rank"], 5);
    assert_eq!(json["searches"][0]["functional_rank_exact"], true);
    let resonance = [
        "search",
        "systems/harmonic-rotor.toml",
        "--when",
        "p_theta = I*omega",
        "--no-timings",
    ];
    let text = normalize(&superint_ok(&resonance));
    assert!(
        text.contains("Functional rank: 4, the most a flow on the 5-dimensional level set"),
        "{text}"
    );
    assert_eq!(
        superint_json(&resonance)["searches"][0]["functional_rank_bound"],
        "flow"
    );
}

/// A rank below the dimension, where the flow does not bound it: the dipole rotor at momenta
/// degree 3, positions 2, order 2 has 4 integrals of rank 2 in 6 phase variables, certified
/// by the 8 bordering minors vanishing (few enough to expand in a plain search).
#[test]
fn dipole_rotor_search_has_rank_two_below_its_dimension() {
    let command = "search systems/dipole-rotor.toml --momenta-degree 3 --positions-degree 2 \
                   --trig-degree 2 --no-timings";
    let args: Vec<&str> = command.split_whitespace().collect();
    let text = normalize(&superint_ok(&args));
    assert!(
        text.contains("≤ 3: 4. Functional rank: 2 (certified by 8 vanishing minors)."),
        "{text}"
    );
    let json = superint_json(&args);
    assert_eq!(json["searches"][0]["dimension"], 4);
    assert_eq!(json["searches"][0]["functional_rank"], 2);
    assert_eq!(json["searches"][0]["functional_rank_exact"], true);
    assert_eq!(
        json["searches"][0]["functional_rank_bound"],
        "vanishing_minors"
    );
}

/// Where `--new-only` finds that the known integrals generate every integral, each is a
/// polynomial in them and the basis's rank is at most theirs: the dipole rotor's 9 integrals
/// at momenta, positions and order 4 have rank 2 exactly, that of `H` and `J` (the 9 × 6
/// Jacobian has 28 bordering minors, past a plain search's 16, so without `--new-only` the
/// same search decides the generation for the rank, saying so, without the new integrals'
/// section; it said `at least 2` before). Where some integral is new the bound does not apply: the
/// harmonic rotor at `p_θ = Iω` keeps the flow's bound; and where the flow's bound is the
/// same, as the 3D Kepler problem's rank 5, it is the flow's.
#[test]
fn known_integrals_that_generate_every_integral_bound_the_rank() {
    let command = "search systems/dipole-rotor.toml --fix M=2,omega=3,I=5,epsilon=7 \
                   --momenta-degree 4 --positions-degree 4 --trig-degree 4 --no-timings";
    let plain: Vec<&str> = command.split_whitespace().collect();
    let new_only = [&plain[..], &["--new-only"]].concat();
    let text = normalize(&superint_ok(&new_only));
    assert!(
        text.contains(
            "≤ 4: 9. Functional rank: 2 (the known integrals H and J generate every integral, \
             and their rank is 2)."
        ),
        "{text}"
    );
    assert!(
        text.contains("None: the known integrals generate every integral in the space."),
        "{text}"
    );
    let json = superint_json(&new_only);
    assert_eq!(json["searches"][0]["dimension"], 9);
    assert_eq!(json["searches"][0]["functional_rank"], 2);
    assert_eq!(json["searches"][0]["functional_rank_exact"], true);
    assert_eq!(json["searches"][0]["functional_rank_bound"], "generated");
    let text = normalize(&superint_ok(&plain));
    assert!(
        text.contains(
            "≤ 4: 9. Functional rank: 2 (the known integrals H and J generate every integral, \
             and their rank is 2)."
        ),
        "{text}"
    );
    assert!(
        !text.contains("the known integrals generate every integral in"),
        "{text}"
    );
    let json = superint_json(&plain);
    assert_eq!(json["searches"][0]["functional_rank_exact"], true);
    assert_eq!(json["searches"][0]["functional_rank_bound"], "generated");
    let text = normalize(&superint_ok_line(
        "search systems/harmonic-rotor.toml --when 'p_theta = I*omega' --new-only --no-timings",
    ));
    assert!(text.contains("New integrals:"), "{text}");
    assert!(
        text.contains("Functional rank: 4, the most a flow on the 5-dimensional level set"),
        "{text}"
    );
    let kepler = "search systems/kepler-3d.toml --momenta-degree 2 --positions-degree 1 \
                  --new-only --no-timings";
    let json = superint_json(&kepler.split_whitespace().collect::<Vec<_>>());
    assert_eq!(json["searches"][0]["functional_rank"], 5);
    assert_eq!(json["searches"][0]["functional_rank_bound"], "flow");
}

/// A rank that equals the number of phase variables says so as its reason: the Euler top at
/// `I1 = I2 = I3 = 1`, whose Hamiltonian is a Casimir (its flow is zero, and bounds nothing),
/// has 10 integrals of Poisson degree `≤ 2` of rank 3 in its 3 variables; JSON's bound is
/// the size.
#[test]
fn euler_top_at_equal_moments_has_the_rank_of_its_variables() {
    let args = [
        "search",
        "systems/euler-top.toml",
        "--poisson-degree",
        "2",
        "--fix",
        "I1=1,I2=1,I3=1",
        "--no-timings",
    ];
    let text = normalize(&superint_ok(&args));
    assert!(
        text.contains("≤ 2: 10. Functional rank: 3 (as many as the phase variables)."),
        "{text}"
    );
    let json = superint_json(&args);
    assert_eq!(json["searches"][0]["functional_rank"], 3);
    assert_eq!(json["searches"][0]["functional_rank_bound"], "size");
}

/// Where a `--when` sets parameters (`ω₋ = 0`, `ω₊ = 2ω₋`), the flow bounds the rank with them
/// set in `H`, as where it sets a momentum alone, and with parameters kept symbolic it holds
/// for every value of them: the Fock–Darwin system at `ω₋ = 0` with `M, ω₊` symbolic has rank
/// 3 of 4, and the Fock–Darwin rotor at `ω₊ = 2ω₋, p_θ = 2Iω₋` rank 4 on its 5-dimensional
/// level set (both said `at least` before, their bordering minors past 16).
#[test]
fn a_condition_setting_parameters_keeps_the_flows_bound_on_the_rank() {
    let fock_darwin = "search systems/fock-darwin.toml --when b=0 --momenta-degree 2 \
                       --positions-degree 2 --trig-degree 0 --symbolic M,a --parameters-degree 2 \
                       --no-timings";
    let args: Vec<&str> = fock_darwin.split_whitespace().collect();
    let text = normalize(&superint_ok(&args));
    assert!(
        text.contains(
            "Functional rank: 3, the most a flow in 4 phase variables allows (maximal \
             superintegrability)."
        ),
        "{text}"
    );
    let json = superint_json(&args);
    assert_eq!(json["searches"][0]["functional_rank_bound"], "flow");
    let rotor = "search systems/fock-darwin-rotor.toml --when a=2*b,p_theta=2*I*b \
                 --momenta-degree 4 --positions-degree 4 --trig-degree 4 --new-only --no-timings";
    let text = normalize(&superint_ok(&rotor.split_whitespace().collect::<Vec<_>>()));
    assert!(
        text.contains(
            "Functional rank: 4, the most a flow on the 5-dimensional level set allows \
             (maximal superintegrability)."
        ),
        "{text}"
    );
}

/// What generates every integral bounds the rank by its own: `--new-only`'s known and new
/// integrals (the Fock–Darwin rotor at `p_θ = Iω₊`, its integrals functions of `L`, `W
/// e^{−iθ}` and its conjugate, rank 3 below the flow's 4), and with parameters kept symbolic
/// the generators over the polynomials in them (Hénon–Heiles with `A, B, C` symbolic: 14
/// integrals, all parameter multiples of `1` and `H`, rank 1). A plain search decides the
/// known integrals' generation where its rank is not otherwise exact
/// (`known_integrals_that_generate_every_integral_bound_the_rank`); a rank stays `at least`
/// on a level set that is not a graph (no flow, no generation) past the bordering minors a
/// plain search expands, and where the generators' own rank is not exact: no documented
/// search is either.
#[test]
fn generators_of_every_integral_bound_the_rank_by_theirs() {
    let rotor = "search systems/fock-darwin-rotor.toml --when p_theta=I*a --momenta-degree 1 \
                 --positions-degree 1 --trig-degree 1 --symbolic M,a,b --parameters-degree 2 \
                 --new-only --no-timings";
    let args: Vec<&str> = rotor.split_whitespace().collect();
    let text = normalize(&superint_ok(&args));
    assert!(
        text.contains(
            "Functional rank: 3 where the condition holds (the known integral L and the new \
             integrals Φ21 and Φ22 generate every integral, and their rank is 3)."
        ),
        "{text}"
    );
    let json = superint_json(&args);
    assert_eq!(json["searches"][0]["functional_rank"], 3);
    assert_eq!(json["searches"][0]["functional_rank_exact"], true);
    assert_eq!(json["searches"][0]["functional_rank_bound"], "generated");
    let henon_heiles = "search systems/henon-heiles.toml --momenta-degree 2 --positions-degree 4 \
                        --trig-degree 0 --symbolic A,B,C --no-timings";
    let args: Vec<&str> = henon_heiles.split_whitespace().collect();
    let text = normalize(&superint_ok(&args));
    assert!(
        text.contains(
            "≤ 2: 14. Functional rank: 1 (every integral is a combination of I1 and I11 with \
             coefficients rational in A, B, C, and their rank is 1)."
        ),
        "{text}"
    );
    assert_eq!(
        superint_json(&args)["searches"][0]["functional_rank_bound"],
        "generated"
    );
}
