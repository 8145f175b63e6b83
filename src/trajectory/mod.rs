//! Trajectories of a Hamiltonian flow in floating point, for pictures (`superint plot`).
//!
//! This is the one place where superint computes with `f64`, and nothing here decides whether
//! an identity holds. Hamilton's equations are formed exactly
//! ([`PhaseSpace::hamilton_equations`]) from a Hamiltonian whose parameters the caller has
//! already replaced by exact rationals; only then are they rounded to floating-point term
//! lists ([`Numeric`]) and integrated at a fixed step, by the classical fourth-order
//! Runge–Kutta method or the symplectic Gauss–Legendre one ([`Method`]), and sampled at equal
//! times ([`Flow::integrate`]) or where a function crosses zero, a Poincaré section
//! ([`Flow::section`]). How far `H` moves along the computed trajectory tells how far the
//! picture can be trusted.
//!
//! ```
//! use superint::prelude::*;
//! use superint::trajectory::{Flow, Numeric};
//!
//! // A harmonic oscillator, M = ω = 1: a circle in the phase plane.
//! let vars = Vars::builder().coordinate("x").momentum("p_x").build()?;
//! let space = PhaseSpace::new(&vars, &[("x", "p_x")])?;
//! let h = Expr::parse(&vars, "(p_x^2 + x^2)/2")?;
//! let flow = Flow::new(&space, &h)?;
//! let mut start = vec![0.0; vars.len()];
//! start[vars.lookup("x").unwrap().index()] = 1.0;
//! let path = flow.integrate(&start, 3.0, 3000, 4)?;
//! assert_eq!(path.times, [0.0, 0.75, 1.5, 2.25, 3.0]);
//! let x = Numeric::new(&Expr::parse(&vars, "x")?, flow.phase())?;
//! assert!((x.real(path.states.last().unwrap()) - 3.0f64.cos()).abs() < 1e-9);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod chart;

use std::ops::ControlFlow;

use brackets::{EngineError, PhaseSpace};
use num_traits::ToPrimitive;
use trigpoly::{Expr, Rational, Var, VarKind};

/// Why a trajectory could not be computed. Errors compare (`assert_eq!` in a program's tests),
/// as the engine's do.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum TrajectoryError {
    /// The engine refused (a limit, say) while forming Hamilton's equations.
    #[error(transparent)]
    Engine(#[from] EngineError),
    /// A variable that is not a coordinate, angle or momentum (a parameter) is still there.
    #[error("{0} has no value")]
    Unbound(String),
    /// A number does not fit a floating-point number.
    #[error("the number {0} is too large for floating point")]
    Overflow(String),
    /// The Hamiltonian is not real, so its flow is not a motion in phase space.
    #[error("H is not real, so its flow has no picture")]
    NotReal,
    /// An implicit step did not converge.
    #[error(
        "the implicit step near t = {} did not converge: the step is too long for this motion \
         (more steps may help)",
        short(*.time)
    )]
    NoConvergence {
        /// The time at the step's end.
        time: f64,
    },
    /// A state of the trajectory is not a finite number.
    #[error(
        "the trajectory left the finite numbers near t = {}: the motion runs off to \
         infinity or into a singularity of H (a shorter time or more steps may help)",
        short(*.time)
    )]
    NotFinite {
        /// The time of the first state that is not finite.
        time: f64,
    },
}

/// A function of the ring rounded for evaluation in floating point: its terms, each a
/// complex coefficient and the powers of the phase variables it holds (for an angle `θ`,
/// `k` stands for `e^{ikθ}`), and the denominator atoms and radicals it holds, whose values
/// are computed first at each evaluation (an atom `v = (D)` to the power `k` is `D^k`, a
/// radical `r = √R` to the power `k` is `√R^k`).
#[derive(Clone, Debug)]
pub struct Numeric {
    terms: Vec<NumericTerm>,
    /// The atoms and radicals the terms hold, rounded, in the order `over` counts.
    stand_ins: Vec<StandIn>,
}

/// A variable that stands for a function of the phase variables, rounded: its value follows
/// from the state's.
#[derive(Clone, Debug)]
pub enum StandIn {
    /// A denominator atom `(D)`: the value of `D`.
    Atom(Numeric),
    /// A radical `√R`: the root of `R`'s value (not a number where `R < 0`).
    Root(Numeric),
}

impl StandIn {
    /// The value at `state`.
    fn value(&self, state: &[f64]) -> f64 {
        match self {
            StandIn::Atom(d) => d.real(state),
            StandIn::Root(radicand) => radicand.real(state).sqrt(),
        }
    }
}

#[derive(Clone, Debug)]
struct NumericTerm {
    re: f64,
    im: f64,
    /// `(variable index, exponent)` of the coordinates and momenta.
    powers: Vec<(usize, i32)>,
    /// `(variable index, k)` of the angles: `e^{ikθ}`.
    turns: Vec<(usize, i32)>,
    /// `(index into stand_ins, exponent)` of the atoms and radicals.
    over: Vec<(usize, i32)>,
}

impl Numeric {
    /// Rounds `e`, which may hold only the variables of `phase`; `Unbound` names any other
    /// (a denominator atom among them: [`Flow::numeric`] rounds a function with its atoms).
    pub fn new(e: &Expr, phase: &[Var]) -> Result<Numeric, TrajectoryError> {
        Numeric::with_atoms(e, phase, &[])
    }

    /// Rounds `e`, which may hold the variables of `phase` and the denominator atoms and
    /// radicals of `atoms` (each with its polynomial, rounded).
    fn with_atoms(
        e: &Expr,
        phase: &[Var],
        atoms: &[(Var, StandIn)],
    ) -> Result<Numeric, TrajectoryError> {
        let vars = e.vars();
        let mut terms = Vec::with_capacity(e.len());
        // The positions in `atoms` of the atoms the terms hold, in the order `over` counts.
        let mut used: Vec<usize> = Vec::new();
        for term in e.terms() {
            let c = term.coeff();
            let (mut powers, mut turns, mut over) = (Vec::new(), Vec::new(), Vec::new());
            for (v, &k) in vars.vars().zip(&term.exponents()) {
                if k == 0 {
                    continue;
                }
                let j = v.index();
                let variable = vars.variable(v);
                // Exponents are bounded by the degree limit (at most 32 767).
                let k = i32::try_from(k).expect("exponents fit 32 bits");
                if let Some(atom) = atoms.iter().position(|(a, _)| *a == v) {
                    let slot = match used.iter().position(|&u| u == atom) {
                        Some(slot) => slot,
                        None => {
                            used.push(atom);
                            used.len() - 1
                        }
                    };
                    over.push((slot, k));
                    continue;
                }
                if !phase.contains(&v) {
                    return Err(TrajectoryError::Unbound(variable.unicode().to_string()));
                }
                match variable.kind() {
                    VarKind::Angle => turns.push((j, k)),
                    _ => powers.push((j, k)),
                }
            }
            terms.push(NumericTerm {
                re: nearest_f64(&c.re)?,
                im: nearest_f64(&c.im)?,
                powers,
                turns,
                over,
            });
        }
        let stand_ins = used.iter().map(|&i| atoms[i].1.clone()).collect();
        Ok(Numeric { terms, stand_ins })
    }

    /// The value at `state` (indexed by variable; an angle's entry is the angle itself), as
    /// `(re, im)`.
    ///
    /// # Panics
    ///
    /// Panics if `state` has no entry for a variable the function holds (a state shorter
    /// than its variable set).
    pub fn eval(&self, state: &[f64]) -> (f64, f64) {
        let atoms: Vec<f64> = self.stand_ins.iter().map(|d| d.value(state)).collect();
        let (mut re, mut im) = (0.0, 0.0);
        for t in &self.terms {
            let magnitude: f64 = t.powers.iter().map(|&(j, e)| state[j].powi(e)).product();
            let magnitude = magnitude
                * t.over
                    .iter()
                    .map(|&(a, e)| atoms[a].powi(e))
                    .product::<f64>();
            let phase: f64 = t.turns.iter().map(|&(j, k)| f64::from(k) * state[j]).sum();
            let (s, c) = phase.sin_cos();
            // (re + i·im)·(c + i·s)·magnitude
            re += magnitude * (t.re * c - t.im * s);
            im += magnitude * (t.re * s + t.im * c);
        }
        (re, im)
    }

    /// The real part of the value at `state`.
    ///
    /// # Panics
    ///
    /// As [`Numeric::eval`]: if `state` has no entry for a variable the function holds.
    pub fn real(&self, state: &[f64]) -> f64 {
        self.eval(state).0
    }
}

/// The nearest `f64` to an exact rational, or `Overflow` (naming the number by its first
/// digits when it is long).
pub fn nearest_f64(q: &Rational) -> Result<f64, TrajectoryError> {
    match q.to_big_rational().to_f64() {
        Some(v) if v.is_finite() => Ok(v),
        _ => {
            let digits = q.to_string();
            let shown = match digits.char_indices().nth(24) {
                Some((cut, _)) => format!("{}… ({} characters)", &digits[..cut], digits.len()),
                None => digits,
            };
            Err(TrajectoryError::Overflow(shown))
        }
    }
}

/// A floating-point value to read: six significant digits, in scientific notation when it is
/// very small or large.
pub fn short(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 || !v.is_finite() {
        v.to_string()
    } else if (1e-3..1e6).contains(&a) {
        let decimals = (5 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{v:.decimals$}");
        match s.contains('.') {
            true => s.trim_end_matches('0').trim_end_matches('.').to_string(),
            false => s,
        }
    } else {
        format!("{v:.3e}")
    }
}

/// How a [`Flow`] steps.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Method {
    /// The classical fourth-order Runge–Kutta method: explicit, four evaluations a step; its
    /// error in `H` grows with the time.
    #[default]
    RungeKutta,
    /// The two-stage Gauss–Legendre method: implicit (its stages solved by fixed-point
    /// iteration to rounding), of order four and symplectic, so that its error in `H` stays
    /// bounded over long times.
    Gauss,
}

/// Hamilton's equations of a real Hamiltonian with no parameters left, rounded for
/// integration.
#[derive(Clone, Debug)]
pub struct Flow {
    /// The phase variables, coordinates and angles first, then their momenta.
    phase: Vec<Var>,
    /// `d/dt` of each, in the same order.
    rates: Vec<Numeric>,
    /// The space's denominator atoms and radicals, each with its polynomial rounded: no state
    /// variables, their values follow from the state's.
    atoms: Vec<(Var, StandIn)>,
    /// How many variables a state holds (every variable of the ring, parameters included).
    width: usize,
    /// How it steps.
    method: Method,
}

impl Flow {
    /// The flow of `h` on `space`: `h` must be real and hold only phase variables (and the
    /// space's denominator atoms, whose polynomials must too).
    pub fn new(space: &PhaseSpace, h: &Expr) -> Result<Flow, TrajectoryError> {
        Flow::at(space, h, &[])
    }

    /// The flow of `h` on `space` with the parameters given their `values` (exact constants)
    /// after Hamilton's equations are formed: in `h`, and in the denominators' polynomials
    /// and brackets, which the equations take through the chain rule.
    pub fn at(
        space: &PhaseSpace,
        h: &Expr,
        values: &[(Var, Expr)],
    ) -> Result<Flow, TrajectoryError> {
        if !h.is_real() {
            return Err(TrajectoryError::NotReal);
        }
        let at = |e: &Expr| -> Result<Expr, TrajectoryError> {
            e.subst_many(values)
                .map_err(|err| EngineError::from(err).into())
        };
        let equations = space.hamilton_equations(h)?;
        let phase: Vec<Var> = equations.iter().map(|(v, _)| *v).collect();
        let atoms = space
            .denominator_atoms()
            .iter()
            .map(|(v, d)| Ok((*v, StandIn::Atom(Numeric::new(&at(d)?, &phase)?))))
            .chain(space.radicals().iter().map(|(r, radicand)| {
                Ok((*r, StandIn::Root(Numeric::new(&at(radicand)?, &phase)?)))
            }))
            .collect::<Result<Vec<_>, TrajectoryError>>()?;
        let rates = equations
            .iter()
            .map(|(_, rate)| Numeric::with_atoms(&at(rate)?, &phase, &atoms))
            .collect::<Result<_, _>>()?;
        Ok(Flow {
            phase,
            rates,
            atoms,
            width: space.vars().len(),
            method: Method::default(),
        })
    }

    /// `e` rounded for evaluation along this flow: it may hold the phase variables and the
    /// denominator atoms.
    pub fn numeric(&self, e: &Expr) -> Result<Numeric, TrajectoryError> {
        Numeric::with_atoms(e, &self.phase, &self.atoms)
    }

    /// The same flow, stepped by `method`.
    #[must_use]
    pub fn with_method(self, method: Method) -> Flow {
        Flow { method, ..self }
    }

    /// The phase variables, coordinates and angles first, then their momenta.
    pub fn phase(&self) -> &[Var] {
        &self.phase
    }

    /// `d/dt` of every variable at `state` (zero for the parameters).
    fn velocity(&self, state: &[f64], out: &mut [f64]) {
        for (v, rate) in self.phase.iter().zip(&self.rates) {
            out[v.index()] = rate.real(state);
        }
    }

    /// Integrates from `start` (a value for every variable, by index; parameters' entries are
    /// not read) over `time` in `steps` equal steps of classical fourth-order Runge–Kutta, and
    /// keeps the state at `t = 0` and `samples` more (`steps` if there are fewer steps), at
    /// steps as evenly spaced as the steps allow (equally when `samples` divides `steps`), the
    /// last step included.
    ///
    /// # Panics
    ///
    /// Panics if `start` does not hold one value for each variable of the space, or if
    /// `steps` or `samples` is 0.
    pub fn integrate(
        &self,
        start: &[f64],
        time: f64,
        steps: usize,
        samples: usize,
    ) -> Result<Trajectory, TrajectoryError> {
        assert!(samples > 0, "at least one sample");
        // The step `n` is kept when `n·samples/steps` reaches a new integer.
        let kept = |n: usize| n * samples / steps > (n - 1) * samples / steps;
        let mut path = Trajectory {
            times: vec![0.0],
            states: vec![start.to_vec()],
        };
        self.walk(start, time, steps, |step| {
            if kept(step.number) {
                path.times.push(step.t1);
                path.states.push(step.y1.to_vec());
            }
            ControlFlow::Continue(())
        })?;
        Ok(path)
    }

    /// Integrates as [`Flow::integrate`] does and keeps the states where `section` crosses
    /// zero upward (from below zero to zero or above), at most `points` of them: a Poincaré
    /// section. Each crossing is found within its step on the cubic that matches the states
    /// and velocities at both ends (Hermite's, accurate to the order of the method), by
    /// regula falsi on `section` along it.
    ///
    /// # Panics
    ///
    /// Panics if `start` does not hold one value for each variable of the space, or if
    /// `steps` is 0.
    pub fn section(
        &self,
        start: &[f64],
        time: f64,
        steps: usize,
        section: &Numeric,
        points: usize,
    ) -> Result<Trajectory, TrajectoryError> {
        let mut path = Trajectory {
            times: Vec::new(),
            states: Vec::new(),
        };
        let mut end_velocity = vec![0.0; self.width];
        // The section's value at the start of each step, carried from the end of the last.
        let mut f0 = section.real(start);
        self.walk(start, time, steps, |step| {
            let f1 = section.real(step.y1);
            if f0 < 0.0 && f1 >= 0.0 {
                self.velocity(step.y1, &mut end_velocity);
                let (s, y) = crossing(step, &end_velocity, |y| section.real(y), (f0, f1));
                path.times.push(step.t0 + s * (step.t1 - step.t0));
                path.states.push(y);
            }
            f0 = f1;
            match path.times.len() < points {
                true => ControlFlow::Continue(()),
                false => ControlFlow::Break(()),
            }
        })?;
        Ok(path)
    }

    /// Takes `steps` equal steps of classical Runge–Kutta from `start` over `time`, handing
    /// each to `visit`, until the last or until `visit` breaks; stops with
    /// `NotFinite` at a state that is not finite.
    fn walk(
        &self,
        start: &[f64],
        time: f64,
        steps: usize,
        mut visit: impl FnMut(&Step<'_>) -> ControlFlow<()>,
    ) -> Result<(), TrajectoryError> {
        assert_eq!(start.len(), self.width, "a state holds every variable");
        assert!(steps > 0, "at least one step");
        let dt = time / steps as f64;
        let (mut y0, mut y1) = (start.to_vec(), start.to_vec());
        let mut k1 = vec![0.0; self.width];
        let mut scratch = Scratch::new(self.width);
        let mut t0 = 0.0;
        for number in 1..=steps {
            self.velocity(&y0, &mut k1);
            let converged = match self.method {
                Method::RungeKutta => {
                    self.runge_kutta(&y0, &k1, dt, &mut scratch, &mut y1);
                    true
                }
                Method::Gauss => self.gauss(&y0, &k1, dt, &mut scratch, &mut y1),
            };
            let t1 = time * number as f64 / steps as f64;
            if self.phase.iter().any(|v| !y1[v.index()].is_finite()) {
                return Err(TrajectoryError::NotFinite { time: t1 });
            }
            if !converged {
                return Err(TrajectoryError::NoConvergence { time: t1 });
            }
            let step = Step {
                number,
                t0,
                t1,
                y0: &y0,
                y1: &y1,
                velocity: &k1,
            };
            if visit(&step).is_break() {
                break;
            }
            std::mem::swap(&mut y0, &mut y1);
            t0 = t1;
        }
        Ok(())
    }

    /// One step of classical Runge–Kutta from `y0`, whose velocity is `k1`, into `y1`.
    fn runge_kutta(&self, y0: &[f64], k1: &[f64], dt: f64, s: &mut Scratch, y1: &mut [f64]) {
        stage(y0, &[(k1, dt / 2.0)], &mut s.y);
        self.velocity(&s.y, &mut s.k[0]);
        stage(y0, &[(&s.k[0], dt / 2.0)], &mut s.y);
        self.velocity(&s.y, &mut s.k[1]);
        stage(y0, &[(&s.k[1], dt)], &mut s.y);
        self.velocity(&s.y, &mut s.k[2]);
        let (k2, k3, k4) = (&s.k[0], &s.k[1], &s.k[2]);
        for j in 0..y1.len() {
            y1[j] = y0[j] + dt / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
        }
    }

    /// One step of the two-stage Gauss–Legendre method from `y0`, whose velocity is `k1`, into
    /// `y1`: the stages' velocities `K_i = f(y0 + dt·Σ_j a_ij K_j)` by fixed-point iteration
    /// from `k1` until an iteration moves the stages by no more than rounding. Whether it
    /// converged.
    fn gauss(&self, y0: &[f64], k1: &[f64], dt: f64, s: &mut Scratch, y1: &mut [f64]) -> bool {
        let r = 3f64.sqrt() / 6.0;
        let a = [[0.25, 0.25 - r], [0.25 + r, 0.25]];
        let scale = 1.0
            + self
                .phase
                .iter()
                .map(|v| y0[v.index()].abs())
                .fold(0.0, f64::max);
        let [k_1, k_2, n_1, n_2] = &mut s.k;
        k_1.copy_from_slice(k1);
        k_2.copy_from_slice(k1);
        let mut converged = false;
        for iteration in 0..100 {
            stage(y0, &[(k_1, dt * a[0][0]), (k_2, dt * a[0][1])], &mut s.y);
            self.velocity(&s.y, n_1);
            stage(y0, &[(k_1, dt * a[1][0]), (k_2, dt * a[1][1])], &mut s.y);
            self.velocity(&s.y, n_2);
            let moved = self
                .phase
                .iter()
                .map(|v| {
                    dt.abs()
                        * ((n_1[v.index()] - k_1[v.index()]).abs()
                            + (n_2[v.index()] - k_2[v.index()]).abs())
                })
                .fold(0.0, f64::max);
            std::mem::swap(k_1, n_1);
            std::mem::swap(k_2, n_2);
            // Rounding, or (after many iterations that circle at the last bits) near it.
            if moved <= 4.0 * f64::EPSILON * scale || (iteration >= 50 && moved <= 1e-12 * scale) {
                converged = true;
                break;
            }
        }
        for j in 0..y1.len() {
            y1[j] = y0[j] + dt / 2.0 * (k_1[j] + k_2[j]);
        }
        converged
    }
}

/// `out = y + Σ h·k` over the pairs `(k, h)`.
fn stage(y: &[f64], terms: &[(&[f64], f64)], out: &mut [f64]) {
    out.copy_from_slice(y);
    for (k, h) in terms {
        for (o, &x) in out.iter_mut().zip(*k) {
            *o += h * x;
        }
    }
}

/// The working vectors of a step: a state and four velocities.
struct Scratch {
    y: Vec<f64>,
    k: [Vec<f64>; 4],
}

impl Scratch {
    fn new(width: usize) -> Scratch {
        Scratch {
            y: vec![0.0; width],
            k: std::array::from_fn(|_| vec![0.0; width]),
        }
    }
}

/// One step of a walk: its number (from 1), its times and states, and the velocity at its
/// start.
struct Step<'a> {
    number: usize,
    t0: f64,
    t1: f64,
    y0: &'a [f64],
    y1: &'a [f64],
    velocity: &'a [f64],
}

/// Where in `step` the function `f`, with the values `(f0 < 0, f1 ≥ 0)` at its ends, is zero:
/// the fraction `s` of the step and the state there, on Hermite's cubic through both ends'
/// states and velocities (`end_velocity` at the end), by regula falsi with the Illinois
/// rule.
fn crossing(
    step: &Step<'_>,
    end_velocity: &[f64],
    f: impl Fn(&[f64]) -> f64,
    (f0, f1): (f64, f64),
) -> (f64, Vec<f64>) {
    let h = step.t1 - step.t0;
    let at = |s: f64| -> Vec<f64> {
        let (s2, s3) = (s * s, s * s * s);
        let (h00, h10, h01, h11) = (
            2.0 * s3 - 3.0 * s2 + 1.0,
            s3 - 2.0 * s2 + s,
            3.0 * s2 - 2.0 * s3,
            s3 - s2,
        );
        (0..step.y0.len())
            .map(|j| {
                h00 * step.y0[j]
                    + h10 * h * step.velocity[j]
                    + h01 * step.y1[j]
                    + h11 * h * end_velocity[j]
            })
            .collect()
    };
    let (mut a, mut fa, mut b, mut fb) = (0.0, f0, 1.0, f1);
    let mut side = 0;
    for _ in 0..40 {
        let s = a - fa * (b - a) / (fb - fa);
        let fs = f(&at(s));
        if fs == 0.0 || b - a < 1e-15 {
            return (s, at(s));
        }
        if fs < 0.0 {
            (a, fa) = (s, fs);
            if side == -1 {
                fb /= 2.0;
            }
            side = -1;
        } else {
            (b, fb) = (s, fs);
            if side == 1 {
                fa /= 2.0;
            }
            side = 1;
        }
    }
    let s = a - fa * (b - a) / (fb - fa);
    (s, at(s))
}

/// States of a flow at increasing times, the first at `t = 0`.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Trajectory {
    /// The times.
    pub times: Vec<f64>,
    /// The state at each time, indexed by variable.
    pub states: Vec<Vec<f64>>,
}

impl Trajectory {
    /// The values of `f` along the trajectory.
    pub fn values(&self, f: impl Fn(&[f64]) -> f64) -> Vec<f64> {
        self.states.iter().map(|s| f(s)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use brackets::systems;
    use std::f64::consts::PI;

    /// The harmonic rotor at M = ω = I = 1.
    fn unit_rotor() -> (brackets::System, Expr) {
        let rotor = systems::harmonic_rotor();
        let mut h = rotor.hamiltonian().clone();
        for name in ["M", "omega", "I"] {
            let one = trigpoly::GaussianRational::from(1);
            h = h.subst_value(rotor.var(name), &one).unwrap();
        }
        (rotor, h)
    }

    #[test]
    fn the_oscillator_moves_on_its_exact_solution() {
        // x(t) = cos t, y(t) = sin t from (1, 0) with momentum (0, 1); θ(t) = θ0 + p_θ t.
        let (rotor, h) = unit_rotor();
        let flow = Flow::new(rotor.space(), &h).unwrap();
        let mut start = vec![0.0; rotor.vars().len()];
        for (name, value) in [("x", 1.0), ("p_y", 1.0), ("theta", 0.5), ("p_theta", 2.0)] {
            start[rotor.var(name).index()] = value;
        }
        let path = flow.integrate(&start, 2.0, 2000, 8).unwrap();
        assert_eq!(path.times.len(), 9);
        let spaced: Vec<f64> = (0..=8).map(|k| f64::from(k) / 4.0).collect();
        for (t, want) in path.times.iter().zip(&spaced) {
            assert!((t - want).abs() < 1e-12, "{:?}", path.times);
        }
        // As evenly as the steps allow, and never more samples than steps.
        let times = |steps, samples| flow.integrate(&start, 10.0, steps, samples).unwrap().times;
        assert_eq!(times(10, 4), [0.0, 3.0, 5.0, 8.0, 10.0]);
        assert_eq!(times(10_000, 3000).len(), 3001);
        assert_eq!(times(10, 6000).len(), 11);
        let end = path.states.last().unwrap();
        let at = |name: &str| end[rotor.var(name).index()];
        assert!((at("x") - 2f64.cos()).abs() < 1e-10);
        assert!((at("y") - 2f64.sin()).abs() < 1e-10);
        assert!((at("theta") - 4.5).abs() < 1e-10);
        assert!((at("p_theta") - 2.0).abs() < 1e-12);
    }

    #[test]
    fn a_section_finds_each_upward_crossing_on_the_exact_solution() {
        // x = cos t, y = sin(t)/2: x crosses 0 upward at t = 3π/2 + 2πk, where y = −1/2.
        let (rotor, h) = unit_rotor();
        let flow = Flow::new(rotor.space(), &h).unwrap();
        let mut start = vec![0.0; rotor.vars().len()];
        for (name, value) in [("x", 1.0), ("p_y", 0.5), ("p_theta", 1.0)] {
            start[rotor.var(name).index()] = value;
        }
        let x = Numeric::new(&rotor.parse("x").unwrap(), flow.phase()).unwrap();
        let path = flow.section(&start, 20.0, 2000, &x, 100).unwrap();
        let expected: Vec<f64> = (0..3).map(|k| 1.5 * PI + 2.0 * PI * f64::from(k)).collect();
        assert_eq!(path.times.len(), expected.len());
        for (t, state) in path.times.iter().zip(&path.states) {
            let nearest = expected
                .iter()
                .map(|e| (e - t).abs())
                .fold(f64::MAX, f64::min);
            // Steps of 0.01: the crossing to the method's accuracy, where a straight line
            // between the steps' ends would be off by about 1e-5.
            assert!(nearest < 1e-8, "a crossing at {t}");
            assert!(state[rotor.var("x").index()].abs() < 1e-8);
            assert!((state[rotor.var("y").index()] + 0.5).abs() < 1e-8);
        }
        // At most `points` of them: the walk stops at the second.
        assert_eq!(
            flow.section(&start, 20.0, 200, &x, 2).unwrap().times.len(),
            2
        );
    }

    /// The flow of `h` on the phase plane `(x, p)`.
    fn one_degree_of_freedom(h: &str) -> Flow {
        let vars = trigpoly::Vars::builder()
            .coordinate("x")
            .momentum("p")
            .build()
            .unwrap();
        let space = PhaseSpace::new(&vars, &[("x", "p")]).unwrap();
        Flow::new(&space, &Expr::parse(&vars, h).unwrap()).unwrap()
    }

    /// Hénon–Heiles (`A = B = 1`, `C = −1/3`) from a bounded orbit: the largest change of
    /// `H` over `time` in `steps` steps of `method`.
    fn henon_heiles_drift(method: Method, time: f64, steps: usize) -> f64 {
        let vars = trigpoly::Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .momentum("p_x")
            .momentum("p_y")
            .build()
            .unwrap();
        let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y")]).unwrap();
        let h = Expr::parse(&vars, "(p_x^2 + p_y^2 + x^2 + y^2)/2 + x^2*y - y^3/3").unwrap();
        let flow = Flow::new(&space, &h).unwrap().with_method(method);
        let energy = Numeric::new(&h, flow.phase()).unwrap();
        let path = flow
            .integrate(&[0.0, 0.1, 0.4, 0.0], time, steps, 1000)
            .unwrap();
        let first = energy.real(&path.states[0]);
        path.values(|s| (energy.real(s) - first).abs())
            .into_iter()
            .fold(0.0, f64::max)
    }

    #[test]
    fn gauss_keeps_the_energy_where_runge_kutta_lets_it_drift() {
        // Steps of 0.25 over 5000 time units: Runge–Kutta's error in H grows with the time,
        // the symplectic method's stays at its size after one orbit.
        let (rk, gauss) = (
            henon_heiles_drift(Method::RungeKutta, 5000.0, 20_000),
            henon_heiles_drift(Method::Gauss, 5000.0, 20_000),
        );
        let gauss_short = henon_heiles_drift(Method::Gauss, 50.0, 200);
        assert!(
            gauss < 1e-5 && gauss < 3.0 * gauss_short,
            "{gauss} after {gauss_short}"
        );
        assert!(rk > 100.0 * gauss, "Runge–Kutta {rk}, Gauss {gauss}");
    }

    #[test]
    fn gauss_follows_the_exact_solution_to_fourth_order() {
        let (rotor, h) = unit_rotor();
        let flow = Flow::new(rotor.space(), &h)
            .unwrap()
            .with_method(Method::Gauss);
        let mut start = vec![0.0; rotor.vars().len()];
        for (name, value) in [("x", 1.0), ("p_y", 1.0), ("theta", 0.5), ("p_theta", 2.0)] {
            start[rotor.var(name).index()] = value;
        }
        let error = |steps: usize| {
            let path = flow.integrate(&start, 2.0, steps, 1).unwrap();
            let end = path.states.last().unwrap();
            (end[rotor.var("x").index()] - 2f64.cos()).abs()
        };
        // Halving the step divides the error by about 2⁴ = 16.
        let ratio = error(50) / error(100);
        assert!((12.0..20.0).contains(&ratio), "{ratio}");
        assert!(error(2000) < 1e-12);
    }

    /// Two bodies repelling by `1/(x − y − c)²` with the denominator `x − y − c` declared and
    /// `c` a parameter given its value after the equations are formed: from rest at
    /// `r = x − y − c = 1`, `r(t)² = 1 + 4t²` (`d²(r²)/dt² = 8H`); a function of the atom
    /// is evaluated through its polynomial, and without the atoms it has no value.
    #[test]
    fn a_flow_through_a_denominator_follows_the_exact_solution() {
        let vars = trigpoly::Vars::builder()
            .coordinate("x")
            .coordinate("y")
            .momentum("p_x")
            .momentum("p_y")
            .parameter("c")
            .denominator("x - y - c")
            .unwrap()
            .build()
            .unwrap();
        let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y")]).unwrap();
        let e = |s: &str| Expr::parse(&vars, s).unwrap();
        let c = vars.lookup("c").unwrap();
        let c_is_1 = [(c, e("1"))];
        let h = e("(p_x^2 + p_y^2)/2 + 1/(x - y - c)^2")
            .subst_many(&c_is_1)
            .unwrap();
        let flow = Flow::at(&space, &h, &c_is_1).unwrap();
        let mut start = vec![0.0; vars.len()];
        start[vars.lookup("x").unwrap().index()] = 2.0;
        let path = flow.integrate(&start, 3.0, 3000, 6).unwrap();
        let r = flow.numeric(&e("x - y - 1")).unwrap();
        let energy = flow.numeric(&h).unwrap();
        for (t, state) in path.times.iter().zip(&path.states) {
            let exact = (1.0 + 4.0 * t * t).sqrt();
            assert!((r.real(state) - exact).abs() < 1e-9, "r({t})");
            assert!((energy.real(state) - 1.0).abs() < 1e-9, "H({t})");
        }
        let err = Numeric::new(&h, flow.phase()).unwrap_err();
        assert!(
            matches!(&err, TrajectoryError::Unbound(v) if v == "(x − y − c)"),
            "{err}"
        );
        // Without its value c is left in the atom's bracket, and named.
        let err = Flow::new(&space, &h).unwrap_err();
        assert!(
            matches!(&err, TrajectoryError::Unbound(v) if v == "c"),
            "{err}"
        );
    }

    #[test]
    fn a_step_too_long_for_the_implicit_method_is_an_error() {
        let flow = one_degree_of_freedom("(p^2 + 10000*x^2)/2").with_method(Method::Gauss);
        let err = flow.integrate(&[1.0, 0.0], 10.0, 10, 10).unwrap_err();
        assert!(
            matches!(err, TrajectoryError::NoConvergence { time } if time == 1.0),
            "{err}"
        );
    }

    #[test]
    fn an_angle_is_evaluated_through_its_exponentials() {
        let (rotor, _) = unit_rotor();
        let e = rotor.parse("cos(theta)^2*x - sin(theta)").unwrap();
        let phase = [rotor.var("x"), rotor.var("theta")];
        let f = Numeric::new(&e, &phase).unwrap();
        let mut state = vec![0.0; rotor.vars().len()];
        state[rotor.var("x").index()] = 3.0;
        state[rotor.var("theta").index()] = 0.7;
        let (re, im) = f.eval(&state);
        assert!((re - (0.7f64.cos().powi(2) * 3.0 - 0.7f64.sin())).abs() < 1e-12);
        assert!(im.abs() < 1e-12);
    }

    #[test]
    fn numbers_read_short_and_long_ones_are_cut() {
        assert_eq!(short(1.125), "1.125");
        assert_eq!(short(-2.111083), "-2.11108");
        assert_eq!(short(6.2e-15), "6.200e-15");
        assert_eq!(short(0.0), "0");
        let huge: Rational = format!("1{}", "0".repeat(400)).parse().unwrap();
        let err = nearest_f64(&huge).unwrap_err().to_string();
        assert_eq!(
            err,
            "the number 100000000000000000000000… (401 characters) is too large for floating point"
        );
    }

    #[test]
    fn a_parameter_left_in_is_named() {
        let rotor = systems::harmonic_rotor();
        let err = Flow::new(rotor.space(), rotor.hamiltonian()).unwrap_err();
        assert!(
            matches!(err, TrajectoryError::Unbound(ref v) if v == "M"),
            "{err}"
        );
    }

    #[test]
    fn a_complex_hamiltonian_has_no_flow() {
        let rotor = systems::harmonic_rotor();
        let h = rotor.parse("i*x*p_x").unwrap();
        assert!(matches!(
            Flow::new(rotor.space(), &h),
            Err(TrajectoryError::NotReal)
        ));
        // The error compares and clones, as the engine's do.
        let err = Flow::new(rotor.space(), &h).map(|_| ()).unwrap_err();
        assert_eq!(err.clone(), TrajectoryError::NotReal);
        assert_ne!(err, TrajectoryError::Unbound("M".into()));
    }

    #[test]
    fn a_run_to_infinity_stops_with_its_time() {
        // ẋ = p, ṗ = 3x²/... : H = p²/2 − x³ blows up in finite time from x = 1.
        let flow = one_degree_of_freedom("p^2/2 - x^3");
        let err = flow.integrate(&[1.0, 0.0], 10.0, 1000, 10).unwrap_err();
        let TrajectoryError::NotFinite { time } = err else {
            panic!("{err}")
        };
        assert!(time > 0.5 && time < 10.0, "{time}");
    }
}
