//! Phase spaces: canonical pairs `(q, p)`, planar or angular, and the Poisson bracket
//! `{f, g} = Σ_i (∂f/∂q_i ∂g/∂p_i − ∂f/∂p_i ∂g/∂q_i)`, so `{q, p} = 1` and `{f, H} = df/dt`.

use trigpoly::{Expr, Var, VarKind, Vars};

use crate::error::EngineError;

/// A canonical pair: a coordinate (or angle) and its momentum.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CanonicalPair {
    /// The coordinate `q` (an angle for an angular pair).
    pub q: Var,
    /// The momentum `p`.
    pub p: Var,
}

/// A phase space: variables and the canonical pairs among them; the other variables are
/// parameters (constants under the flow).
///
/// ```
/// use brackets::PhaseSpace;
/// use trigpoly::{Expr, VarSet};
/// let vars = VarSet::builder().coordinate("x").momentum("p_x").build().unwrap();
/// let space = PhaseSpace::new(&vars, &[("x", "p_x")]).unwrap();
/// let x = Expr::parse(&vars, "x").unwrap();
/// let p = Expr::parse(&vars, "p_x").unwrap();
/// assert_eq!(space.bracket(&x, &p).unwrap(), Expr::one(&vars));
/// ```
#[derive(Clone, Debug)]
pub struct PhaseSpace {
    vars: Vars,
    pairs: Vec<CanonicalPair>,
    /// The pairs as `(q, p)` variables, the form the kernels take.
    var_pairs: Vec<(Var, Var)>,
}

impl PhaseSpace {
    /// A phase space from pairs of names `(q, p)`. A `q` declared as an angle makes an angular
    /// pair; `p` must be a momentum.
    pub fn new(vars: &Vars, pairs: &[(&str, &str)]) -> Result<Self, EngineError> {
        let find = |n: &str| {
            vars.lookup(n).ok_or_else(|| {
                EngineError::Invalid(format!("unknown variable '{n}' in a canonical pair"))
            })
        };
        let mut out = Vec::new();
        for &(q, p) in pairs {
            let (qv, pv) = (find(q)?, find(p)?);
            let qk = vars.variable(qv).kind();
            if !matches!(qk, VarKind::Coordinate | VarKind::Angle) {
                return Err(EngineError::Invalid(format!(
                    "'{q}' must be a coordinate or an angle"
                )));
            }
            if vars.variable(pv).kind() != VarKind::Momentum {
                return Err(EngineError::Invalid(format!("'{p}' must be a momentum")));
            }
            if out
                .iter()
                .any(|c: &CanonicalPair| [c.q, c.p].iter().any(|&v| v == qv || v == pv))
            {
                return Err(EngineError::Invalid(format!(
                    "'{q}' or '{p}' is in two canonical pairs"
                )));
            }
            out.push(CanonicalPair { q: qv, p: pv });
        }
        Ok(PhaseSpace {
            vars: vars.clone(),
            var_pairs: out.iter().map(|c| (c.q, c.p)).collect(),
            pairs: out,
        })
    }

    /// The variables.
    pub fn vars(&self) -> &Vars {
        &self.vars
    }

    /// The canonical pairs.
    pub fn pairs(&self) -> &[CanonicalPair] {
        &self.pairs
    }

    /// The phase-space coordinates in the order `q_1, …, q_n, p_1, …, p_n`.
    pub fn coordinates(&self) -> Vec<Var> {
        self.pairs
            .iter()
            .map(|c| c.q)
            .chain(self.pairs.iter().map(|c| c.p))
            .collect()
    }

    /// Whether `v` is a phase-space variable (not a parameter).
    pub fn is_phase_variable(&self, v: Var) -> bool {
        self.pairs.iter().any(|c| c.q == v || c.p == v)
    }

    // {f, g} = Σ_i (∂f/∂q_i ∂g/∂p_i − ∂f/∂p_i ∂g/∂q_i)
    /// The Poisson bracket `{f, g}`.
    pub fn bracket(&self, f: &Expr, g: &Expr) -> Result<Expr, EngineError> {
        Ok(Expr::sum_of_jacobians(f, g, self.var_pairs())?)
    }

    /// The canonical pairs as `(q, p)` variables, the form the kernels take.
    fn var_pairs(&self) -> &[(Var, Var)] {
        &self.var_pairs
    }

    /// `(∂g/∂q_i, ∂g/∂p_i)` for each pair: what a bracket with `g` needs of `g`, worth keeping
    /// when `g` (a Hamiltonian, say) enters many brackets.
    pub fn gradient(&self, g: &Expr) -> Result<Vec<(Expr, Expr)>, EngineError> {
        self.pairs
            .iter()
            .map(|c| Ok((g.derivative(c.q)?, g.derivative(c.p)?)))
            .collect()
    }

    /// `{f, g}` given the gradient of `g` from [`PhaseSpace::gradient`]: one fused sum of
    /// products of the derivatives of `f` (never built on their own) with it, normalised once.
    pub fn bracket_with_gradient(
        &self,
        f: &Expr,
        dg: &[(Expr, Expr)],
    ) -> Result<Expr, EngineError> {
        Ok(Expr::sum_of_jacobians_with_gradient(
            f,
            self.var_pairs(),
            dg,
        )?)
    }

    /// `{f, g}` given the gradient of `g`, with the substitution `subs` applied (a condition
    /// such as a resonance): the bracket's term products are formed, substituted and added in
    /// one table when the values are single terms, so the bracket before the condition is
    /// never built.
    pub fn bracket_with_gradient_at(
        &self,
        f: &Expr,
        dg: &[(Expr, Expr)],
        subs: &[(Var, Expr)],
    ) -> Result<Expr, EngineError> {
        Ok(Expr::sum_of_jacobians_with_gradient_at(
            f,
            self.var_pairs(),
            dg,
            subs,
        )?)
    }

    /// Hamilton's vector field of `h`: `(q̇_i, ṗ_i) = (∂h/∂p_i, −∂h/∂q_i)` for each pair, in the
    /// order of [`PhaseSpace::coordinates`].
    pub fn hamilton_equations(&self, h: &Expr) -> Result<Vec<(Var, Expr)>, EngineError> {
        let mut out = Vec::new();
        for c in &self.pairs {
            out.push((c.q, h.derivative(c.p)?));
        }
        for c in &self.pairs {
            out.push((c.p, -h.derivative(c.q)?));
        }
        Ok(out)
    }
}
