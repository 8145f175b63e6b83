//! `System`: a phase space, a Hamiltonian and named functions, with a parser that knows the
//! names and the bracket `{f, g}`.

use trigpoly::{AlgebraError, BracketError, Context, Expr, GaussianRational, Var, Vars};

use crate::claim::Condition;
use crate::error::EngineError;
use crate::inputs::{Input, Recording};
use crate::phase::{Gradient, PhaseSpace};

/// A named function of a system (`L`, `G1`, `Z̄`), or a generator of a closure.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct NamedFunction {
    /// The ASCII name used in expressions (`Zbar`).
    pub name: String,
    /// The name as printed (`Z̄`).
    pub display: String,
    /// The function.
    pub expr: Expr,
}

impl NamedFunction {
    /// A function with its name and the name it is printed by.
    pub fn new(name: &str, display: &str, expr: Expr) -> Self {
        NamedFunction {
            name: name.to_string(),
            display: display.to_string(),
            expr,
        }
    }
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
    dh: Option<Gradient>,
}

impl System {
    /// A system with Hamiltonian `h`, available under the name `H` (unless a variable is named
    /// `H`, which then wins in [`System::parse`]; system files reserve the name).
    ///
    /// # Errors
    ///
    /// [`AlgebraError::VarSetMismatch`](trigpoly::AlgebraError::VarSetMismatch) if `h` is
    /// not over the space's variables ([`System::define`]).
    pub fn new(name: &str, space: PhaseSpace, h: Expr) -> Result<Self, EngineError> {
        let mut s = System {
            name: name.to_string(),
            space,
            functions: Vec::new(),
            dh: None,
        };
        s.define("H", "H", h)?;
        Ok(s)
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

    /// Defines (or redefines) a named function. A variable of the same name (in any of its
    /// spellings) wins in [`System::parse`], so such a function could not be named there:
    /// [`System::define_parsed`] refuses the name.
    ///
    /// # Errors
    ///
    /// [`AlgebraError::VarSetMismatch`](trigpoly::AlgebraError::VarSetMismatch) if `expr` is
    /// over other variables than the system's (another system's): its variables would be
    /// read by their places in this system's, so it is refused here rather than in every
    /// later use of its name.
    ///
    /// ```
    /// use brackets::{systems, EngineError};
    /// use trigpoly::{AlgebraError, Expr, Vars};
    ///
    /// let mut rotor = systems::harmonic_rotor();
    /// let own = rotor.parse("x*p_y - y*p_x")?;
    /// rotor.define("Lz", "L_z", own)?;
    /// let elsewhere = Vars::builder().coordinate("x").momentum("p_x").build()?;
    /// let foreign = Expr::parse(&elsewhere, "x*p_x")?;
    /// let refused = rotor.define("D", "D", foreign).unwrap_err();
    /// assert_eq!(refused, EngineError::Algebra(AlgebraError::VarSetMismatch));
    /// assert!(rotor.get("D").is_err());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn define(&mut self, name: &str, display: &str, expr: Expr) -> Result<(), EngineError> {
        if expr.vars() != self.vars() {
            return Err(AlgebraError::VarSetMismatch.into());
        }
        let f = NamedFunction {
            name: name.into(),
            display: display.into(),
            expr,
        };
        if name == "H" {
            // A gradient that cannot be formed leaves `flow` to report the error itself.
            self.dh = self.space.gradient(&f.expr).ok();
        }
        match self.functions.iter_mut().find(|g| g.name == name) {
            Some(g) => *g = f,
            None => self.functions.push(f),
        }
        Ok(())
    }

    /// [`System::define_parsed`] for a built-in system's own function, whose text nobody typed:
    /// an error (a text that does not fit the limits) names the function, `its function W'`,
    /// with the text and a caret ([`EngineError::in_part`]), not a line and column.
    pub fn define_builtin(
        &mut self,
        name: &str,
        display: &str,
        src: &str,
    ) -> Result<(), EngineError> {
        self.define_parsed(name, display, src)
            .map_err(|e| e.in_part(&format!("its function {display}")))
    }

    /// Defines a named function from text, which may use earlier names and brackets; the name
    /// of a variable is refused (a variable wins in [`System::parse`]).
    pub fn define_parsed(
        &mut self,
        name: &str,
        display: &str,
        src: &str,
    ) -> Result<(), EngineError> {
        if self.vars().lookup(name).is_some() {
            return Err(EngineError::Invalid(format!(
                "'{name}' is a variable of the system, so a function of that name could never \
                 be used; choose another name"
            )));
        }
        let e = self.parse(src)?;
        self.define(name, display, e)
    }

    /// Certifies the rank of the Jacobian of the named functions (or family instances the
    /// system defines) by the phase-space coordinates: [`rank`](crate::rank()) by names, as
    /// [`closure`](crate::closure()) and [`BracketTable::compute`](crate::BracketTable::compute)
    /// take them.
    pub fn rank(&self, names: &[impl AsRef<str>]) -> Result<crate::RankCertificate, EngineError> {
        let functions = names
            .iter()
            .map(|name| self.get(name.as_ref()).cloned())
            .collect::<Result<Vec<_>, _>>()?;
        crate::rank(&self.space, &functions)
    }

    /// The named functions, `H` first.
    pub fn functions(&self) -> &[NamedFunction] {
        &self.functions
    }

    /// The named function that `name` spells, by its name or its display (`Omega` or `Ω`), or
    /// else by its display as an expression reads it ([`trigpoly::syntax::latex_name`]: a
    /// function shown `P_{1,1}` is read as `P_1_1`, whether written so or with the braces), or
    /// as a name spells it, a prime as `p` (a function shown `P'_{1,1}` is read as `Pp_1_1`, as
    /// a system file names the instances of its family `Pp` shown `P'`, and as `y'` is named
    /// `yp`; a display read as `name` itself is taken first), if any: the one lookup of a
    /// function by a name, through which [`System::get`] and [`System::display_name`] find it.
    ///
    /// ```
    /// let mut rotor = brackets::systems::harmonic_rotor();
    /// let p = rotor.parse("re(Z*exp(-i*theta))")?;
    /// rotor.define("P11", "P_{1,1}", p.clone())?;
    /// assert_eq!(rotor.get("P_1_1")?, &p);
    /// assert_eq!(rotor.parse("P_{1,1}")?, p);
    /// rotor.define("P11p", "P'_{1,1}", p.clone())?;
    /// assert_eq!(rotor.get("Pp_1_1")?, &p);
    /// assert_eq!(rotor.parse("Pp_{1,1}")?, p);
    /// // A display that reads as the name itself comes first, whatever the order.
    /// let q = rotor.parse("im(Z*exp(-i*theta))")?;
    /// rotor.define("Q", "Pp_{1,1}", q.clone())?;
    /// assert_eq!(rotor.get("Pp_1_1")?, &q);
    /// # Ok::<(), brackets::EngineError>(())
    /// ```
    pub fn function(&self, name: &str) -> Option<&NamedFunction> {
        let functions = &self.functions;
        // Each reading in turn over every function, so that a display that reads as `name`
        // itself is taken before another whose primes spelt as `p` would (`Pp_{1,1}` before
        // `P'_{1,1}` for `Pp_1_1`).
        functions
            .iter()
            .find(|f| f.name == name || f.display == name)
            .or_else(|| {
                functions
                    .iter()
                    .find(|f| display_read(f).is_some_and(|r| r == name))
            })
            .or_else(|| {
                functions.iter().find(|f| {
                    display_read(f)
                        .is_some_and(|r| r.contains('\'') && r.replace('\'', "p") == name)
                })
            })
    }

    /// A named function.
    pub fn get(&self, name: &str) -> Result<&Expr, EngineError> {
        self.function(name)
            .map(|f| &f.expr)
            .ok_or_else(|| EngineError::UnknownName(name.to_string()))
    }

    /// The display name of a named function (the name itself if unknown).
    pub fn display_name<'a>(&'a self, name: &'a str) -> &'a str {
        self.function(name).map_or(name, |f| f.display.as_str())
    }

    /// A variable by name, or `None` if `name` is not a variable of the system.
    ///
    /// ```
    /// let rotor = brackets::systems::harmonic_rotor();
    /// assert!(rotor.lookup("omega").is_some());
    /// assert_eq!(rotor.lookup("nope"), None);
    /// ```
    pub fn lookup(&self, name: &str) -> Option<Var> {
        self.vars().lookup(name)
    }

    /// A variable by name.
    ///
    /// # Panics
    ///
    /// If it is not declared (a bug in a built-in system); a name read from input goes
    /// through [`System::lookup`].
    pub fn var(&self, name: &str) -> Var {
        self.lookup(name)
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
    ///
    /// A function's name as LaTeX prints it reads back as the function (`G_{1}` of `G1`,
    /// [`table::latex_name`](crate::table::latex_name)), a bracket of functions so printed
    /// too; plain text is read as written, where `G_1` names no `G1`.
    ///
    /// ```
    /// use brackets::table::latex_name;
    ///
    /// let rotor = brackets::systems::harmonic_rotor();
    /// assert_eq!(latex_name(rotor.display_name("G1")), "G_{1}");
    /// assert_eq!(&rotor.parse("G_{1}")?, rotor.get("G1")?);
    /// let bracket = format!(r"\{{L, {}\}} - {}", latex_name("G1"), latex_name("G2"));
    /// assert_eq!(bracket, r"\{L, G_{1}\} - G_{2}");
    /// assert_eq!(rotor.parse(&bracket)?, rotor.parse("-2*G2")?);
    /// assert!(rotor.parse("G_1").is_err());
    /// # Ok::<(), brackets::EngineError>(())
    /// ```
    pub fn parse(&self, src: &str) -> Result<Expr, EngineError> {
        Expr::parse_with(self.vars(), src, self).map_err(|e| EngineError::parse(src, e))
    }

    /// [`System::parse`], with what the expression was computed from: the functions it names
    /// (`H` among them) and the declared brackets its brackets take ([`Recording`]), each of
    /// which must have a value where a condition puts the expression
    /// ([`Claim::computed_from`](crate::Claim::computed_from)).
    ///
    /// ```
    /// let rotor = brackets::systems::harmonic_rotor();
    /// let (bracket, inputs) = rotor.parse_recording("{F2, L} + H")?;
    /// assert_eq!(bracket, rotor.parse("H")?);
    /// let what: Vec<&str> = inputs.iter().map(|i| i.what.as_str()).collect();
    /// assert_eq!(what, ["the function F2", "the function L", "H"]);
    /// # Ok::<(), brackets::EngineError>(())
    /// ```
    pub fn parse_recording(&self, src: &str) -> Result<(Expr, Vec<Input>), EngineError> {
        let recording = Recording::new(self, &self.space);
        let e = Expr::parse_with(self.vars(), src, &recording)
            .map_err(|e| EngineError::parse(src, e))?;
        Ok((e, recording.into_inputs()))
    }

    /// `{f, g}`.
    pub fn bracket(&self, f: &Expr, g: &Expr) -> Result<Expr, EngineError> {
        self.space.bracket(f, g)
    }

    /// `df/dt = {f, H}`, with the gradient of `H` computed once per system. Whether it is
    /// zero is [`Expr::vanishes`] (or [`System::conserves`]), not [`Expr::is_zero`]: with
    /// radicals or denominator atoms a zero can have terms (`r² − x² − y²`).
    pub fn flow(&self, f: &Expr) -> Result<Expr, EngineError> {
        match &self.dh {
            Some(dh) => self.space.bracket_with_gradient(f, dh),
            None => self.space.bracket(f, self.hamiltonian()),
        }
    }

    /// Whether `f` is an integral of the motion, `{f, H} = 0`, by the exact zero test of the
    /// ring ([`Expr::vanishes`]): the flow cleared of its denominator atoms and reduced by
    /// `r² = R` for each radical, where a bare [`Expr::is_zero`] on [`System::flow`] would miss
    /// a zero that has terms.
    ///
    /// ```
    /// use brackets::{PhaseSpace, System};
    /// use trigpoly::{Expr, Vars};
    ///
    /// // The Kepler problem in the plane, with r = √(x² + y²).
    /// let vars = Vars::builder()
    ///     .coordinate("x").coordinate("y").momentum("p_x").momentum("p_y")
    ///     .parameter("k").radical("r", "x^2 + y^2")
    ///     .build()?;
    /// let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y")])?;
    /// let h = Expr::parse(&vars, "(p_x^2 + p_y^2)/2 - k/r")?;
    /// let kepler = System::new("Kepler", space, h)?;
    /// let runge_lenz = Expr::parse(&vars, "p_y*(x*p_y - y*p_x) - k*x/r")?;
    /// assert!(!kepler.flow(&runge_lenz)?.is_zero()); // terms that cancel only by r² = x² + y²
    /// assert!(kepler.conserves(&runge_lenz)?);
    /// assert!(!kepler.conserves(&Expr::parse(&vars, "x*p_y")?)?);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn conserves(&self, f: &Expr) -> Result<bool, EngineError> {
        Ok(self.flow(f)?.vanishes()?)
    }

    /// `{f, H}` under a condition (a resonance `p_θ = mIω/n`, say): the flow with the
    /// condition's substitution applied, formed term by term and substituted as it is formed
    /// where the condition's values are single terms, so that the flow off the condition is
    /// never built. The same value as [`Condition::apply`] on [`System::flow`].
    pub fn flow_when(&self, f: &Expr, condition: &Condition) -> Result<Expr, EngineError> {
        match &self.dh {
            // The fast path substitutes the condition's own variables alone: it is taken where
            // the condition sets no parameter of a declared denominator (nor a radicand's).
            Some(dh) if condition.substitutes_its_variables_alone() => {
                self.space.bracket_with_gradient_at(f, dh, condition.subs())
            }
            _ => condition.apply(&self.flow(f)?),
        }
    }
}

impl Context<GaussianRational> for System {
    fn lookup(&self, name: &str) -> Option<Expr> {
        self.get(name).ok().cloned()
    }

    fn bracket(&self, f: &Expr, g: &Expr) -> Result<Expr, BracketError> {
        self.space.bracket(f, g).map_err(BracketError::from)
    }

    fn names(&self) -> Vec<String> {
        self.functions.iter().map(|f| f.name.clone()).collect()
    }

    /// A function's display as LaTeX prints it ([`crate::table::latex_name`]: `G_{1}` of `G1`),
    /// which [`System::parse`] reads back as the function.
    fn latex(&self, name: &str) -> Option<String> {
        let f = self.functions.iter().find(|f| f.name == name)?;
        Some(crate::table::latex_name(&f.display))
    }

    /// A function shown as a family instance (`P'_{1,1}`, the built-in gravity rotor's `P11`)
    /// is spelt as a system file names the instance, and as [`System::function`] reads it too:
    /// its display as an expression reads it, a prime as `p` (`Pp_1_1`), when that is ASCII
    /// and names the same function.
    fn spelling(&self, name: &str) -> Option<String> {
        let f = self.functions.iter().find(|f| f.name == name)?;
        let read = display_read(f)?.replace('\'', "p");
        let same = self.function(&read).is_some_and(|g| g.name == f.name);
        (read != f.name && read.is_ascii() && same).then_some(read)
    }
}

/// The name that a function's display reads as, as an expression reads it, for a display
/// written in LaTeX alone (`P'_{1,1}` → `P'_1_1`): how [`System::function`] finds a function
/// by its display, and [`System`]'s `Context::spelling` spells it.
fn display_read(f: &NamedFunction) -> Option<String> {
    match f.display.contains(['{', '\\']) {
        true => trigpoly::syntax::latex_name(&f.display),
        false => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::systems::harmonic_rotor;

    /// `System::rank` by names certifies what `rank` does on the same functions, and an
    /// unknown name is an error.
    #[test]
    fn rank_by_names() {
        let rotor = harmonic_rotor();
        let by_names = rotor.rank(&["H", "L", "F2"]).expect("a certificate");
        let functions: Vec<Expr> = ["H", "L", "F2"]
            .iter()
            .map(|n| rotor.get(n).unwrap().clone())
            .collect();
        let direct = crate::rank(rotor.space(), &functions).expect("a certificate");
        assert_eq!((by_names.rank, direct.rank), (3, 3));
        assert_eq!(
            rotor.rank(&["H", "nope"]).unwrap_err(),
            EngineError::UnknownName("nope".into())
        );
    }

    /// The functions of a rank, a bracket table and a closure are named by `&str`s or by
    /// `String`s a program holds (read from its input, say), where they took `&[&str]` alone
    /// and a `Vec<String>` had to be borrowed name by name into another vector first.
    #[test]
    fn functions_are_named_by_strs_or_strings() {
        let rotor = harmonic_rotor();
        let owned: Vec<String> = ["L", "G1", "G2"].map(String::from).to_vec();
        let rank = rotor.rank(&owned).unwrap();
        assert_eq!(rank, rotor.rank(&["L", "G1", "G2"]).unwrap());
        assert_eq!(rank.rank, 3);
        let table = crate::BracketTable::compute(&rotor, &owned).unwrap();
        assert_eq!(
            table,
            crate::BracketTable::compute(&rotor, &["L", "G1", "G2"]).unwrap()
        );
        let options = crate::ClosureOptions::new(2);
        let closed = crate::closure(&rotor, &owned, &options).unwrap();
        assert_eq!(closed.names, owned);
        let by_strs = crate::closure(&rotor, &["L", "G1", "G2"], &options).unwrap();
        assert_eq!(closed.relations.len(), by_strs.relations.len());
    }

    /// A function named like a variable could never be used: `define_parsed` refuses it.
    #[test]
    fn a_function_may_not_take_a_variables_name() {
        let mut rotor = harmonic_rotor();
        for name in ["x", "omega", "ω", "p_theta"] {
            let err = rotor.define_parsed(name, name, "x^2").unwrap_err();
            assert!(err.to_string().contains("is a variable"), "{name}: {err}");
        }
        rotor
            .define_parsed("X2", "X₂", "x^2")
            .expect("a fresh name");
        assert_eq!(rotor.parse("X2").unwrap(), rotor.parse("x^2").unwrap());
    }

    /// A function over another system's variables is refused where it is defined, and so is
    /// a Hamiltonian over other variables than the phase space's: `parse("F")` returned it
    /// over the other set, and `F + L` failed later as a parse error at column 1 of a text
    /// that had none. The system is left as it was.
    #[test]
    fn a_function_over_another_systems_variables_is_refused() {
        let mut rotor = harmonic_rotor();
        let oscillator = crate::systems::rotor("x^2 + y^2", &[]).expect("a rotor");
        // Of the same names, but another set: the rotor's declares omega and l.
        assert_ne!(oscillator.vars(), rotor.vars());
        let foreign = oscillator.parse("x*p_y").unwrap();
        let mismatch = EngineError::Algebra(AlgebraError::VarSetMismatch);
        assert_eq!(
            rotor.define("F", "F", foreign.clone()),
            Err(mismatch.clone())
        );
        assert_eq!(rotor.get("F"), Err(EngineError::UnknownName("F".into())));
        let h = rotor.hamiltonian().clone();
        assert_eq!(
            rotor.define("H", "H", foreign.clone()),
            Err(mismatch.clone())
        );
        assert_eq!(rotor.hamiltonian(), &h);
        let space = rotor.space().clone();
        assert_eq!(
            System::new("mixed", space.clone(), foreign).unwrap_err(),
            mismatch
        );
        // Its own expressions are taken, by define and by new.
        rotor
            .define("F", "F", rotor.parse("x*p_y").unwrap())
            .unwrap();
        assert_eq!(rotor.parse("F - x*p_y").unwrap(), Expr::zero(rotor.vars()));
        assert!(System::new("same", space, h).is_ok());
    }

    /// `?` turns a parse error into an `EngineError` that says where: by line, column and
    /// caret when the error knows its source, as `Expr::parse`'s do; by bytes when not.
    #[test]
    fn parse_errors_convert_with_their_place() {
        fn parse(rotor: &System, src: &str) -> Result<Expr, EngineError> {
            Ok(Expr::parse(rotor.vars(), src)?)
        }
        let err = parse(&harmonic_rotor(), "x +").unwrap_err();
        assert!(matches!(err, EngineError::Parse { .. }));
        assert_eq!(
            err.to_string(),
            "line 1, column 4: expected an expression after '+', found end of input\n  x +\n     ^"
        );
        let bare = trigpoly::ParseError::new(trigpoly::Span::new(3, 3), "expected an expression");
        let err = EngineError::from(bare);
        assert!(err.to_string().contains("(at bytes 3..3)"), "{err}");
    }

    /// A condition prints as it reads.
    #[test]
    fn a_condition_prints_its_text() {
        let rotor = harmonic_rotor();
        let value = rotor.parse("2*I*omega").unwrap();
        let condition = crate::Condition::new("p_θ = 2Iω", rotor.var("p_theta"), value);
        assert_eq!(condition.to_string(), "p_θ = 2Iω");
        assert_eq!(condition.to_string(), condition.text);
    }

    /// A condition whose value mentions its variable is an equation, refused in every build
    /// (a `debug_assert` let it through in release).
    #[test]
    #[should_panic(expected = "a condition's value mentions its variable")]
    fn a_condition_may_not_set_a_variable_in_terms_of_itself() {
        let rotor = harmonic_rotor();
        let x = rotor.var("x");
        let value = rotor.parse("2*x").unwrap();
        let _ = crate::Condition::new("x = 2x", x, value);
    }

    /// An angle enters functions through `e^{iθ}`, so a condition on it sets `e^{iθ}`: "θ = 0"
    /// written as the value 0 made `e^{2iθ} = 0` proved. `Condition::all` refuses a constant
    /// of modulus other than 1 with an error, `new` panics; 1 (`θ = 0`) and `i` are values.
    #[test]
    fn a_condition_sets_an_angle_on_the_unit_circle_only() {
        let rotor = harmonic_rotor();
        let theta = rotor.var("theta");
        let zero = Expr::zero(rotor.vars());
        let err = crate::Condition::all("theta = 0", vec![(theta, zero.clone())]).unwrap_err();
        assert!(
            err.to_string().contains(
                "a condition on the angle θ sets e^{iθ}, and 0 is no value of it (its modulus is 1"
            ),
            "{err}"
        );
        let two = rotor.parse("3/5 + 4*i/5 + 1").unwrap();
        assert!(crate::Condition::all("", vec![(theta, two)]).is_err());
        let set = std::panic::catch_unwind(|| crate::Condition::new("theta = 0", theta, zero));
        assert!(set.is_err());
        // On the circle: e^{2iθ} at e^{iθ} = i is −1, and 3/5 + 4i/5 is a value too.
        let i = rotor.parse("i").unwrap();
        let at = crate::Condition::all("θ = π/2", vec![(theta, i)]).expect("a value of e^{iθ}");
        let e2 = rotor.parse("exp(2*i*theta)").unwrap();
        assert_eq!(at.apply(&e2).unwrap(), rotor.parse("-1").unwrap());
        let unit = rotor.parse("3/5 + 4*i/5").unwrap();
        assert!(crate::Condition::all("", vec![(theta, unit)]).is_ok());
    }

    /// Phase space and the parameters are real, so a value that is not sets no point of them
    /// (at `p_x = ix`, `p_x² + x² = 0` was proved): `Condition::all` refuses it, naming the
    /// variable, whether the value is written so or only resolves so through another
    /// assignment; `new` panics. A real value with `i` in it is kept.
    #[test]
    fn a_condition_sets_a_real_variable_to_a_real_value_only() {
        let rotor = harmonic_rotor();
        let (p_x, omega) = (rotor.var("p_x"), rotor.var("omega"));
        let e = |s: &str| rotor.parse(s).unwrap();
        let err = crate::Condition::all("p_x = ix", vec![(p_x, e("i*x"))]).unwrap_err();
        assert_eq!(
            err,
            EngineError::RefusedCondition {
                var: p_x,
                message: "the condition sets p_x to ix, which is not real: the variables and \
                          parameters take real values"
                    .into()
            }
        );
        let through = vec![(p_x, e("omega*x")), (omega, e("2*i"))];
        let err = crate::Condition::all("", through).unwrap_err();
        assert!(
            matches!(err, EngineError::RefusedCondition { var, .. } if var == omega),
            "{err}"
        );
        let real = crate::Condition::all("", vec![(p_x, e("i*(x - i*y) - i*x"))]).unwrap();
        assert_eq!(real.apply(&e("p_x^2")).unwrap(), e("y^2"));
        let set = std::panic::catch_unwind(|| crate::Condition::new("p_x = ix", p_x, e("i*x")));
        assert!(set.is_err());
    }
}
