//! A loaded system extended in code: functions, families and claims added by a program, each
//! read and checked as a file's own are, with errors located in the text the program gave
//! (`<family K>:2:7: unknown name 'Omegaa'`, the line and a caret).

use std::ops::Range;

use trigpoly::Expr;

use super::claims::ClaimSpec;
use super::error::{ErrorKind, FileError};
use super::names::{check_display, index_refusal, BadName, PrintedNames, Refusal};
use super::text::{Source, Text};
use super::{Family, LoadedSystem};
use crate::report::Expect;

impl LoadedSystem {
    /// Parses an expression in the system's variables, named functions, family instances
    /// (`K_2_3` or `K_{2,3}`) and brackets, as a claim's side is read; an error names the
    /// `<expression>` with line, column and caret.
    ///
    /// ```
    /// use superint::system_file::{load, LimitsOverride};
    ///
    /// let rotor = load("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
    /// // K_{1,1} = Z e^{−iθ}, and P_{1,1} its real part.
    /// let k = rotor.parse("K_{1,1}")?;
    /// assert_eq!(rotor.parse("(K_1_1 + Kbar_1_1)/2")?, rotor.parse("P_1_1")?);
    /// assert_eq!(k, rotor.parse("Z*exp(-i*theta)")?);
    /// let err = rotor.parse("K_1_1 + G3").unwrap_err();
    /// assert_eq!(err.line_col(), Some((1, 9)));
    /// # Ok::<(), superint::system_file::FileError>(())
    /// ```
    pub fn parse(&self, src: &str) -> Result<Expr, FileError> {
        self.value(&self.argument_in(Source::program_about(&self.source, "<expression>", src))?)
    }

    /// Adds a named function, as a `[[function]]` of the file declares one; `value` may use
    /// the variables, `H`, the functions and the family instances. A name that the system
    /// already has (a variable in any spelling, a function, a family), a reserved or malformed
    /// name, a display name that would not print, or one that would print as another name of
    /// the system does, in text or in LaTeX (`F_1` beside `F1`, both `F_{1}`), or as a product
    /// of its variables (`Mx` beside `M` and `x`) is refused ([`PrintedNames`]), and the system
    /// is unchanged.
    ///
    /// ```
    /// use superint::system_file::{load, ErrorKind, LimitsOverride};
    ///
    /// let mut rotor = load("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
    /// rotor.add_function("Casimir", "C", "4*G1^2 + G2^2 + omega^2*L^2")?;
    /// assert_eq!(rotor.parse("Casimir")?, rotor.parse("(F1 - F2)^2")?);
    /// let err = rotor.add_function("L", "L", "x").unwrap_err();
    /// assert_eq!(err.kind, ErrorKind::Name);
    /// assert_eq!(err.message, "'L' is already a function of the system");
    /// # Ok::<(), superint::system_file::FileError>(())
    /// ```
    pub fn add_function(
        &mut self,
        name: &str,
        display: &str,
        value: &str,
    ) -> Result<(), FileError> {
        let origin = format!("<function {name}>");
        self.check_new_name(&origin, name, "a function")?;
        check_display_in(&origin, display)?;
        self.check_printed_apart(&origin, name, display)?;
        let source = Source::program_about(&self.source, &origin, value);
        let (value, inputs) = self
            .scope(self.families.len())
            .parse_recorded(&source, &Text::whole(&source))?;
        self.system.define(name, display, value)?;
        self.keep_computed_from(name.to_string(), inputs);
        Ok(())
    }

    /// Adds a named function whose value the program already holds as an [`Expr`] (an
    /// integral a search found, a product or a real part formed in code), under the same rules
    /// for its name and display as [`LoadedSystem::add_function`]; it is then read in claims,
    /// families, tables and ranks as a function the file declares is. A value built in
    /// another variable set than the system's (`system().vars()`) is refused, of kind
    /// [`ErrorKind::Expression`], and so is a name already taken; either leaves the system
    /// unchanged.
    ///
    /// ```
    /// use superint::prelude::*;
    ///
    /// let mut rotor = load_system_file("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
    /// // P_{1,1}² + Q_{1,1}² = |Z|², formed in code, as a function of the file.
    /// let (p, q) = (rotor.parse("P_1_1")?, rotor.parse("Q_1_1")?);
    /// rotor.add_function_expr("N", "N", &(&p * &p) + &(&q * &q))?;
    /// rotor.add_claim("modulus", "N = Z*Zbar", None)?;
    /// rotor.add_claim("conserved", "{N, H} = 0", None)?;
    /// assert!(check_report([&rotor])?.all_as_expected());
    /// // A value of another variable set names no variable of this one.
    /// let other = Vars::builder().coordinate("q").build()?;
    /// let err = rotor.add_function_expr("W", "W", Expr::parse(&other, "q")?).unwrap_err();
    /// assert_eq!(err.kind, ErrorKind::Expression);
    /// # Ok::<(), FileError>(())
    /// ```
    pub fn add_function_expr(
        &mut self,
        name: &str,
        display: &str,
        value: Expr,
    ) -> Result<(), FileError> {
        let origin = format!("<function {name}>");
        self.check_new_name(&origin, name, "a function")?;
        check_display_in(&origin, display)?;
        self.check_printed_apart(&origin, name, display)?;
        if value.vars() != self.system.vars() {
            let message = format!(
                "the value of {name} was built in another variable set than the system's: \
                 build it from system().vars(), or read it with parse"
            );
            return Err(FileError::new(ErrorKind::Expression, &origin, message));
        }
        self.system.define(name, display, value)?;
        Ok(())
    }

    /// Adds a family with two integer indices, as a `[[family]]` of the file declares one:
    /// its instances `name_i_j` (or `name_{i,j}`) are `value` with `i, j` for the indices, and
    /// `eigenvalue`, if given, is `λ` in `{name_{m,n}, H} = λ(m, n) name_{m,n}`, which
    /// [`family_tower_report`](super::family_tower_report) checks for `1 ≤ m, n ≤ N` and proves
    /// for all `m, n`. The value and the eigenvalue are read at `(1, 1)` at once; an error there,
    /// or a name already taken, leaves the system unchanged; so does a display whose instances
    /// would print as another family's do (`T` shown as `K` beside a family `K`: both
    /// `K_{1,1}`). Errors in the value are at line 1 of `<family NAME>`, in the eigenvalue at
    /// line 2.
    ///
    /// ```
    /// use superint::prelude::*;
    ///
    /// // The 2-d isotropic oscillator with its ladder functions, in code, with names of our own.
    /// let vars = Vars::builder()
    ///     .coordinate("x").coordinate("y").momentum("p_x").momentum("p_y").parameter("k")
    ///     .build()?;
    /// let space = PhaseSpace::new(&vars, &[("x", "p_x"), ("y", "p_y")])?;
    /// let h = Expr::parse(&vars, "(p_x^2 + p_y^2)/2 + k^2*(x^2 + y^2)/2")?;
    /// let mut oscillator = LoadedSystem::of_system(System::new("oscillator", space, h)?);
    /// oscillator.add_function("A", "A", "p_x + i*k*x")?;
    /// oscillator.add_function("B", "B", "p_y - i*k*y")?;
    /// // {A^a B^b, H} = i(a − b)k A^a B^b: conserved on the diagonal a = b.
    /// oscillator.add_family("T", "T", ["a", "b"], "A^a*B^b", Some("i*(a - b)*k"))?;
    /// let report = family_tower_report(&oscillator, Some("T"), 3, None)?;
    /// assert!(report.all_proved());
    /// assert_eq!(report.tower().map(|t| t.checked), Some(9));
    /// assert!(report.proof().is_some_and(|p| p.holds()));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn add_family(
        &mut self,
        name: &str,
        display: &str,
        indices: [&str; 2],
        value: &str,
        eigenvalue: Option<&str>,
    ) -> Result<(), FileError> {
        let origin = format!("<family {name}>");
        self.check_new_name(&origin, name, "a family")?;
        check_display_in(&origin, display)?;
        let whose = format!("the family {name}");
        if let Err(why) = PrintedNames::of_loaded(self).admit_family(&whose, name, display, None) {
            let message = format!("{why}: rename one, or give it another display");
            return Err(FileError::new(ErrorKind::Name, &origin, message));
        }
        if let Some((_, kind, message)) = index_refusal(indices, |idx| self.what_is(idx)) {
            return Err(FileError::new(kind, &origin, message));
        }
        let (source, value_at, [eigenvalue_at]) = lines(&origin, value, [eigenvalue]);
        self.families.push(Family {
            name: name.to_string(),
            display: display.to_string(),
            indices: indices.map(str::to_string),
            value: Text::within(&source, value_at.clone()),
            eigenvalue: eigenvalue_at.map(|at| Text::within(&source, at)),
            span: value_at,
            source: source.clone(),
        });
        // Read at (1, 1), as a file's family is when it loads.
        let k = self.families.len() - 1;
        let checked = self
            .scope(k + 1)
            .expand(k, 1, 1, &source, || 0..0)
            .and_then(|_| match eigenvalue {
                Some(_) => self.eigenvalue_at(k, 1, 1).map(drop),
                None => Ok(()),
            });
        if let Err(e) = checked {
            self.families.pop();
            self.forget_instances(k);
            return Err(e);
        }
        Ok(())
    }

    /// Adds a claim, as a `[[claim]]` of the file declares one: `lhs = rhs` (brackets, family
    /// instances) or `rank(F, G, …) = r`, under the condition `when` if given
    /// (`"p_theta = I*omega"`, several separated by commas). It is read at once and checked by
    /// [`LoadedSystem::check_claim`] or with the others by
    /// [`check_report`](super::check_report); it is expected to be proved, unless its `expect`
    /// is set to [`Expect::Refuted`]. Errors in the claim are at line 1 of `<claim ID>`, in
    /// the condition at line 2; an id that is refused (empty, or with a control character) is
    /// reported of `<claim>`.
    ///
    /// ```
    /// use superint::prelude::*;
    ///
    /// let mut rotor = load_system_file("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
    /// rotor.add_claim("mine", "{K_2_1, H} = 0", Some("p_theta = 2*I*omega"))?;
    /// rotor.add_claim("off", "{K_2_1, H} = 0", Some("p_theta = I*omega"))?.expect = Expect::Refuted;
    /// let report = check_report([&rotor])?;
    /// assert!(report.all_as_expected());
    /// assert_eq!(report.claim_ids().last(), Some(&("off".to_string(), false)));
    /// # Ok::<(), FileError>(())
    /// ```
    pub fn add_claim(
        &mut self,
        id: &str,
        claim: &str,
        when: Option<&str>,
    ) -> Result<&mut ClaimSpec, FileError> {
        let origin = claim_origin(id)?;
        let (source, claim_at, [when_at]) = lines(&origin, claim, [when]);
        let text = Text::within(&source, claim_at.clone());
        let when = when_at.map(|at| Text::within(&source, at).split(','));
        let spec = ClaimSpec::read(
            self,
            &source,
            id.to_string(),
            text,
            when,
            Expect::Proved,
            claim_at,
        )?;
        self.claims.push(spec);
        Ok(self.claims.last_mut().expect("just pushed"))
    }

    /// Adds a claim made on a level set, as a `[[claim]]` with `on = "EXPR = VALUE"` declares
    /// one: `lhs = rhs` (brackets, family instances, the file's functions in `EXPR`), proved
    /// where `lhs − rhs` is a multiple of `P = EXPR − VALUE`, by its quotient `Q`
    /// ([`ClaimResult::on_level`](crate::report::ClaimResult::on_level)), and refuted with
    /// its remainder on division by `P` otherwise. The level set is read and checked at once,
    /// as the file's are (real, square-free, kept by the flow of `H`, a number as its leading
    /// coefficient). Errors in the claim are at line 1 of `<claim ID>`, in the level set at
    /// line 2; an id that is refused is reported of `<claim>`.
    ///
    /// ```
    /// use superint::prelude::*;
    ///
    /// let mut gc = load_system_file(
    ///     "systems/goryachev-chaplygin-top.toml",
    ///     &LimitsOverride::default(),
    /// )?;
    /// gc.add_claim_on("mine", "{K, H} = 0", "A = 0")?;
    /// let report = check_report([&gc])?;
    /// let mine = report.claims().into_iter().find(|c| c.id == "mine").unwrap();
    /// assert!(mine.proved);
    /// let q = mine.on_level.as_ref().and_then(|l| l.quotient.clone());
    /// assert_eq!(q, Some(gc.system().parse("-c*M2")?));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn add_claim_on(
        &mut self,
        id: &str,
        claim: &str,
        on: &str,
    ) -> Result<&mut ClaimSpec, FileError> {
        self.add_claim_on_when(id, claim, on, None)
    }

    /// [`LoadedSystem::add_claim_on`] under the condition `when` if given, as a `[[claim]]`
    /// with both `on` and `when` declares one: a condition that fixes parameters alone
    /// (`"I3 = 1/4"`, several separated by commas, as [`LoadedSystem::add_claim`] takes them),
    /// whose values are substituted into `H`, the claim's sides and the level set, which is
    /// read and checked at them; one that sets a phase variable is refused beside a level
    /// set. Errors in the claim are at line 1 of `<claim ID>`, in the level set at line 2,
    /// in the condition at line 3.
    ///
    /// ```
    /// use superint::prelude::*;
    ///
    /// let mut top = load_system_file("systems/heavy-top.toml", &LimitsOverride::default())?;
    /// let cubic = "{M3*(M1^2 + M2^2) + c*M1*gamma3, H} = 0";
    /// top.add_claim_on_when("gc", cubic, "A = 0", Some("I3 = 1/4"))?;
    /// top.add_claim_on_when("kovalevskaya", cubic, "A = 0", Some("I3 = 1/2"))?.expect =
    ///     Expect::Refuted;
    /// let report = check_report([&top])?;
    /// assert!(report.all_as_expected());
    /// let gc = report.claims().into_iter().find(|c| c.id == "gc").unwrap();
    /// let q = gc.on_level.as_ref().and_then(|l| l.quotient.clone());
    /// assert_eq!(q, Some(top.system().parse("-c*M2")?));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn add_claim_on_when(
        &mut self,
        id: &str,
        claim: &str,
        on: &str,
        when: Option<&str>,
    ) -> Result<&mut ClaimSpec, FileError> {
        let origin = claim_origin(id)?;
        let (source, claim_at, [on_at, when_at]) = lines(&origin, claim, [Some(on), when]);
        let text = Text::within(&source, claim_at.clone());
        let on = on_at.map(|at| Text::within(&source, at));
        let when = when_at.map(|at| Text::within(&source, at).split(','));
        let spec = ClaimSpec::read(
            self,
            &source,
            id.to_string(),
            text,
            when,
            Expect::Proved,
            claim_at,
        )?
        .on_level_set(self, on)?;
        self.claims.push(spec);
        Ok(self.claims.last_mut().expect("just pushed"))
    }

    /// Refuses `name` for a new function or family (`what`) when it is malformed, reserved,
    /// or already names something of the system.
    fn check_new_name(&self, origin: &str, name: &str, what: &str) -> Result<(), FileError> {
        let message = if let Some(bad) = BadName::of(name) {
            bad.declaring(name, what)
        } else if let Some(other) = self.what_is(name) {
            format!("'{name}' is already {other}")
        } else {
            return Ok(());
        };
        Err(FileError::new(ErrorKind::Name, origin, message))
    }

    /// Refuses a new function `name` shown as `display` that would print as something else of
    /// the system ([`PrintedNames::admit`]), as a file's function is refused.
    fn check_printed_apart(
        &self,
        origin: &str,
        name: &str,
        display: &str,
    ) -> Result<(), FileError> {
        let whose = format!("the function {name}");
        let advice = match PrintedNames::of_loaded(self).admit(&whose, name, display) {
            Ok(()) => return Ok(()),
            Err(Refusal::Alike(why)) => format!("{why}: rename one, or give it another display"),
            Err(Refusal::Product(why)) if !self.source.given.about_file() => format!(
                "{why}: choose another name, or give it to the variables when they are built \
                 (VarsBuilder::also_named), which has such products printed spaced"
            ),
            Err(Refusal::Product(why)) => format!(
                "{why}: choose another name, or declare the function in the file, whose \
                 products are then printed spaced"
            ),
        };
        Err(FileError::new(ErrorKind::Name, origin, advice))
    }

    /// Drops the cached instances of family `k` (a family that was refused).
    fn forget_instances(&self, k: usize) {
        self.cache
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .retain(|&(family, _, _), _| family != k);
    }
}

/// Refuses a display name that would not print as written, at its character in a source of
/// its own.
fn check_display_in(origin: &str, display: &str) -> Result<(), FileError> {
    let source = Source::program(origin, display);
    check_display(&source, &Text::whole(&source), 0..display.len())
}

/// The origin of a claim added by a program, `<claim ID>`, once its id is shown refused or
/// not: an id that is refused is no name for the text, and its errors are of `<claim>`.
fn claim_origin(id: &str) -> Result<String, FileError> {
    if id.trim().is_empty() {
        return Err(FileError::new(
            ErrorKind::Claim,
            "<claim>",
            "a claim's id is empty",
        ));
    }
    if let Some((_, why)) = super::names::unshowable("a claim's id", id, false) {
        return Err(FileError::new(ErrorKind::Claim, "<claim>", why));
    }
    Ok(format!("<claim {id}>"))
}

/// One source for a text and the optional ones after it, each given on a line of its own
/// after those before it: the source and where each text is in it.
fn lines<const N: usize>(
    origin: &str,
    first: &str,
    rest: [Option<&str>; N],
) -> (Source, Range<usize>, [Option<Range<usize>>; N]) {
    let mut text = first.to_string();
    let at = rest.map(|line| {
        line.map(|s| {
            text.push('\n');
            let start = text.len();
            text.push_str(s);
            start..text.len()
        })
    });
    (Source::program(origin, &text), 0..first.len(), at)
}
