//! `System`: a phase space, a Hamiltonian and named functions, with a parser that knows the
//! names and the bracket `{f, g}`.

use trigpoly::{Context, Expr, GaussianRational, Var, Vars};

use crate::claim::Condition;
use crate::error::EngineError;
use crate::phase::PhaseSpace;

/// A named function of a system (`L`, `G1`, `Z̄`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NamedFunction {
    /// The ASCII name used in expressions (`Zbar`).
    pub name: String,
    /// The name as printed (`Z̄`).
    pub display: String,
    /// The function.
    pub expr: Expr,
}

/// A Hamiltonian system: phase space, Hamiltonian `H`, and named functions.
///
/// ```
/// use brackets::systems;
/// let rotor = systems::harmonic_rotor();
/// let table = rotor.parse("{L, G1} + G2").unwrap();
/// assert!(table.is_zero());
/// ```
#[derive(Clone, Debug)]
pub struct System {
    name: String,
    space: PhaseSpace,
    functions: Vec<NamedFunction>,
    /// The gradient of `H`, kept because every flow `{f, H}` needs it.
    dh: Vec<(Expr, Expr)>,
}

impl System {
    /// A system with Hamiltonian `h`, available under the name `H`.
    pub fn new(name: &str, space: PhaseSpace, h: Expr) -> Self {
        let mut s = System {
            name: name.to_string(),
            space,
            functions: Vec::new(),
            dh: Vec::new(),
        };
        s.define("H", "H", h);
        s
    }

    /// The system's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The phase space.
    pub fn space(&self) -> &PhaseSpace {
        &self.space
    }

    /// The variables.
    pub fn vars(&self) -> &Vars {
        self.space.vars()
    }

    /// The Hamiltonian.
    pub fn hamiltonian(&self) -> &Expr {
        &self.functions[0].expr
    }

    /// Defines (or redefines) a named function.
    pub fn define(&mut self, name: &str, display: &str, expr: Expr) {
        let f = NamedFunction {
            name: name.into(),
            display: display.into(),
            expr,
        };
        if name == "H" {
            // A gradient that cannot be formed leaves `flow` to report the error itself.
            self.dh = self.space.gradient(&f.expr).unwrap_or_default();
        }
        match self.functions.iter_mut().find(|g| g.name == name) {
            Some(g) => *g = f,
            None => self.functions.push(f),
        }
    }

    /// Defines a named function from text, which may use earlier names and brackets.
    pub fn define_parsed(
        &mut self,
        name: &str,
        display: &str,
        src: &str,
    ) -> Result<(), EngineError> {
        let e = self.parse(src)?;
        self.define(name, display, e);
        Ok(())
    }

    /// The named functions, `H` first.
    pub fn functions(&self) -> &[NamedFunction] {
        &self.functions
    }

    /// A named function.
    pub fn get(&self, name: &str) -> Result<&Expr, EngineError> {
        self.functions
            .iter()
            .find(|f| f.name == name || f.display == name)
            .map(|f| &f.expr)
            .ok_or_else(|| EngineError::UnknownName(name.to_string()))
    }

    /// The display name of a named function (the name itself if unknown).
    pub fn display_name<'a>(&'a self, name: &'a str) -> &'a str {
        self.functions
            .iter()
            .find(|f| f.name == name || f.display == name)
            .map_or(name, |f| f.display.as_str())
    }

    /// A variable by name. Panics if it is not declared (a bug in a built-in system).
    pub fn var(&self, name: &str) -> Var {
        self.vars()
            .lookup(name)
            .unwrap_or_else(|| panic!("variable {name} is not declared"))
    }

    /// Parses an expression in the system's variables, named functions and brackets, with
    /// `cos`, `sin`, `exp` of angles and the complex structure's `conj`, `re`, `im`.
    ///
    /// ```
    /// let rotor = brackets::systems::harmonic_rotor();
    /// // P_{1,1} = Re(Z e^{−iθ}) and Q_{1,1} = Im(Z e^{−iθ}), with |Z|² = P² + Q².
    /// let p = rotor.parse("re(Z*exp(-i*theta))")?;
    /// let q = rotor.parse("im(Z*exp(-i*theta))")?;
    /// assert_eq!(p.to_string(), "(p_x − Mωy) cos θ + (p_y + Mωx) sin θ");
    /// let modulus = rotor.parse("Z*conj(Z)")?;
    /// assert_eq!(modulus, &(&p * &p) + &(&q * &q));
    /// # Ok::<(), brackets::EngineError>(())
    /// ```
    pub fn parse(&self, src: &str) -> Result<Expr, EngineError> {
        Expr::parse_with(self.vars(), src, self).map_err(|e| EngineError::parse(src, e))
    }

    /// `{f, g}`.
    pub fn bracket(&self, f: &Expr, g: &Expr) -> Result<Expr, EngineError> {
        self.space.bracket(f, g)
    }

    /// `df/dt = {f, H}`, with the gradient of `H` computed once per system.
    pub fn flow(&self, f: &Expr) -> Result<Expr, EngineError> {
        if self.dh.len() == self.space.pairs().len() {
            self.space.bracket_with_gradient(f, &self.dh)
        } else {
            self.space.bracket(f, self.hamiltonian())
        }
    }

    /// `{f, H}` under a condition (a resonance `p_θ = mIω/n`, say): the flow with the
    /// condition's substitution applied, formed term by term and substituted as it is formed
    /// where the condition's values are single terms, so that the flow off the condition is
    /// never built. The same value as [`Condition::apply`] on [`System::flow`].
    pub fn flow_when(&self, f: &Expr, condition: &Condition) -> Result<Expr, EngineError> {
        if self.dh.len() == self.space.pairs().len() {
            self.space
                .bracket_with_gradient_at(f, &self.dh, condition.subs())
        } else {
            condition.apply(&self.flow(f)?)
        }
    }
}

impl Context<GaussianRational> for System {
    fn lookup(&self, name: &str) -> Option<Expr> {
        self.get(name).ok().cloned()
    }

    fn bracket(&self, f: &Expr, g: &Expr) -> Result<Expr, String> {
        self.space.bracket(f, g).map_err(|e| e.to_string())
    }

    fn names(&self) -> Vec<String> {
        self.functions.iter().map(|f| f.name.clone()).collect()
    }
}
