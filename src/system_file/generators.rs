//! The generators of a closure named as a system file names them
//! ([`LoadedSystem::closure_generators`], behind `superint closure FILE NAMES` and
//! [`file_closure_report`](crate::discovery::file_closure_report)): each name a function by
//! its name or its display (`Omega`, `Ω`), a family instance (`P_1_1`, `P_{1,1}`), a phase
//! variable, or a generator the caller gives by its value (`--define`), with the name it
//! prints by; a blank name, one holding a line break, one given twice, an expression and a
//! parameter given as a name refused at their places. Beside it what the command line's
//! built-in systems share with a file: how a name given as a generator prints
//! ([`display_as_given`]), its identifier ([`name_as_identifier`]), why a new name is refused
//! ([`new_name_refusal`]) and the refusals of a name holding a line break (a generator's or a
//! table's, [`refuse_unshowable_name`]), and of an expression and a parameter given as a
//! generator ([`refuse_expression_as_generator`], [`refuse_parameter_as_generator`]).

use brackets::NamedFunction;

use super::error::{ErrorKind, FileError};
use super::names::{first_invisible, invisible, script, BadName, PrintedNames};
use super::text::trimmed;
use super::{Caller, LoadedSystem, COMMAND_LINE};

impl LoadedSystem {
    /// The generators of a closure named by `names`, as `superint closure FILE NAMES` reads
    /// them: a function by its name or its display (`Omega` or `Ω`), a family instance
    /// (`P_1_1` or `P_{1,1}`) or a phase variable (`p_x`), each with the name it prints by
    /// (`P_{1,1}`, `K̄_{1,1}` for `Kbar_1_1`); and after them each of `given` that `names` does
    /// not name, a generator given by its value (the command line's `--define NAME=EXPR`),
    /// which a name among `names` may name too, where it stands. The spaces around a name are
    /// no part of it (` L` and `L ` are `L`, ` M` the parameter `M`). A blank name, one holding a
    /// line break or a tab ([`refuse_unshowable_name`]), a function given twice (by one
    /// name or by its name and its display, or one instance written two ways:
    /// [`LoadedSystem::refuse_repeated`]), an expression given as a name (`2*L`, which
    /// has no name for the table and the relations), a parameter (`M`, a constant:
    /// [`refuse_parameter_as_generator`]), or one the file does not know is refused,
    /// of kind [`ErrorKind::Expression`], at its place in the name as given (`<expression>`,
    /// a blank one `<name>`, or `<command line>` as the [`Caller`] says); a generator of `given` whose name the
    /// system has already, or that would print as one of its names, given twice, or built in
    /// another variable set, of kind [`ErrorKind::Name`]; no generator at all, of kind
    /// [`ErrorKind::Claim`].
    ///
    /// ```
    /// use superint::prelude::*;
    ///
    /// let rotor = load_system_file("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
    /// let casimir = NamedFunction::new("C", "C", rotor.parse("4*G1^2 + G2^2 + omega^2*L^2")?);
    /// let generators = rotor.closure_generators(&["L", "Ω", "P_{1,1}", "C"], &[casimir])?;
    /// let shown: Vec<&str> = generators.iter().map(|g| g.display.as_str()).collect();
    /// assert_eq!(shown, ["L", "Ω", "P_{1,1}", "C"]);
    /// assert_eq!(generators[2].name, "P_1_1");
    ///
    /// let err = rotor.closure_generators(&["L", "2*L"], &[]).unwrap_err();
    /// assert_eq!((err.kind, err.line_col()), (ErrorKind::Expression, Some((1, 1))));
    /// assert!(err.message.starts_with("'2*L' is an expression, not the name of a function"));
    /// # Ok::<(), FileError>(())
    /// ```
    pub fn closure_generators(
        &self,
        names: &[impl AsRef<str>],
        given: &[NamedFunction],
    ) -> Result<Vec<NamedFunction>, FileError> {
        // How the system's names print, and then each generator given by its value.
        let mut printed = self.admit_given(given)?;
        let mut all: Vec<&str> = names.iter().map(AsRef::as_ref).collect();
        for g in given {
            if !all.iter().any(|n| n.trim() == g.name) {
                all.push(&g.name);
            }
        }
        if all.is_empty() {
            let message = match self.caller {
                Caller::CommandLine => {
                    "give the generators: names of functions of the system, or --define NAME=EXPR"
                }
                Caller::Program => {
                    "give the generators: names of functions of the system, of family instances \
                     or of phase variables, or generators given by their values"
                }
            };
            return Err(FileError::new(
                ErrorKind::Claim,
                &self.source.origin,
                message,
            ));
        }
        self.refuse_blank(&all)?;
        for name in &all {
            refuse_unshowable_name(name, self.caller, "generator")?;
        }
        self.refuse_repeated(&all, "the closure")?;
        let mut generators = Vec::with_capacity(all.len());
        for written in all {
            // The name without the spaces around it (` L`, `L `), which are no part of it;
            // each refusal is placed in the name as written.
            let name = written.trim();
            let (expr, display) = match given.iter().find(|g| g.name == name) {
                Some(g) => (g.expr.clone(), g.display.clone()),
                None => {
                    refuse_expression_as_generator(
                        written,
                        self.caller,
                        |n| {
                            self.refuses_new_name(n).is_none()
                                && printed.admit("the generator", n, n).is_ok()
                        },
                        || {
                            self.kept_warnings().unwarned(|| {
                                self.parse_argument_within(written, 0..written.len())
                                    .map(drop)
                            })
                        },
                    )?;
                    refuse_parameter_as_generator(written, self.caller, self.system.vars())?;
                    // The parse error with its place: its excerpt shows the generator.
                    let expr = self.parse_argument_within(written, 0..written.len())?;
                    (expr, display_as_given(name, |n| self.display_name(n)))
                }
            };
            generators.push(NamedFunction::new(
                &name_as_identifier(name),
                &display,
                expr,
            ));
        }
        Ok(generators)
    }

    /// How the system's names print, with each generator of `given` admitted beside them
    /// (`the generator C`), in order; a generator refused as [`LoadedSystem::closure_generators`]
    /// says, at the first.
    fn admit_given(&self, given: &[NamedFunction]) -> Result<PrintedNames, FileError> {
        let mut printed = PrintedNames::of(&self.system);
        for (k, g) in given.iter().enumerate() {
            let name = g.name.as_str();
            let refused = |message: String| {
                FileError::new(ErrorKind::Name, &format!("<generator {name}>"), message)
            };
            if let Some(why) = self.refuses_new_name(name) {
                return Err(refused(why));
            }
            if given[..k].iter().any(|before| before.name == name) {
                return Err(refused(format!(
                    "{name} is defined twice: give each name once"
                )));
            }
            if let Err(why) = printed.admit(&format!("the generator {name}"), name, name) {
                return Err(refused(format!("{why}; choose another name")));
            }
            if g.expr.vars() != self.system.vars() {
                return Err(refused(format!(
                    "the value of {name} was built in another variable set than the system's: \
                     build it from system().vars(), or read it with parse"
                )));
            }
        }
        Ok(printed)
    }

    /// Why `name` is refused as a new name of this system ([`new_name_refusal`]), what it
    /// reads as tested without a warning of how it reads.
    fn refuses_new_name(&self, name: &str) -> Option<String> {
        new_name_refusal(
            name,
            || self.what_is(name),
            || {
                self.kept_warnings()
                    .unwarned(|| self.parse_argument_within(name, 0..name.len()).is_ok())
            },
        )
    }
}

/// Why `name` is refused as a new name (a generator `--define` gives, a name offered in an
/// example), if it is, before anything is computed: one that is not an identifier, is
/// reserved, or names something of the system already (`what_is`: which it would shadow, so
/// that what is found about it would read, in the system's names, as a claim about the
/// system's own), or that the system reads as a product of its names (`Mx`; `reads`: whether
/// it parses), each said as such, for the caller to place.
///
/// ```
/// use superint::system_file::{new_name_refusal, what_is};
///
/// let rotor = superint::brackets::systems::harmonic_rotor();
/// let refusal = |name| new_name_refusal(name, || what_is(&rotor, &[], name), || false);
/// assert_eq!(refusal("C"), None);
/// assert_eq!(
///     refusal("L").as_deref(),
///     Some("L is a function of the system; choose another name")
/// );
/// ```
pub fn new_name_refusal(
    name: &str,
    what_is: impl FnOnce() -> Option<String>,
    reads: impl FnOnce() -> bool,
) -> Option<String> {
    match BadName::of(name) {
        Some(bad @ BadName::Unnamed(trigpoly::BadName::Malformed | trigpoly::BadName::TooLong)) => {
            return Some(bad.why())
        }
        Some(bad) => return Some(format!("{}; choose another name", bad.why())),
        None => {}
    }
    if let Some(what) = what_is() {
        return Some(format!("{name} is {what}; choose another name"));
    }
    // Names run together that read as a product of the system's (`Mx`), refused without
    // the warning of how they read, which the refusal says.
    if reads() {
        return Some(format!(
            "the system reads {name} as a product of its names; choose another name"
        ));
    }
    None
}

/// Refuses `name`, given as a closure's generator, where it is an expression rather than a
/// name (`2*L`, `L+G1`, `L G1`, `{L, G1}`): it has no name of its own for the table and the relations
/// (`2*L` was named `2_L`, which no relation can hold, and `L*G1` and `L+G1` were both
/// `L_G1`). The spaces around a name are no part of it (` M` is the name `M`, which
/// [`refuse_parameter_as_generator`] then refuses). The error is at the whole of it, its
/// surrounding spaces left out, as a name given twice is, and says how to name it
/// (`--define 'G=2*L'` for [`Caller::CommandLine`], `LoadedSystem::add_function` for a
/// program), with the first name of `G`, `X`, `Y`, `W` that `free` takes (a name the system
/// does not have), else `Gen`. Text that is no expression either (`L+`, `P _{1,1}`) gets the
/// parser's error instead, from `parse`, which says what is wrong with it, where the advice
/// would name it as written and fail again; a parse that a limit stopped is an expression
/// still.
///
/// ```
/// use superint::system_file::{refuse_expression_as_generator, Caller, ErrorKind};
///
/// let refused = |name, free: fn(&str) -> bool| {
///     refuse_expression_as_generator(name, Caller::Program, free, || Ok(()))
/// };
/// assert!(refused("P_{1,1}", |_| true).is_ok());
/// assert!(refused(" L ", |_| true).is_ok());
/// assert!(refused("P_{1, 1}", |_| true).is_ok());
/// assert!(refused("L G1", |_| true).is_err());
/// let err = refused("L+G1", |n| n != "G").unwrap_err();
/// assert_eq!((err.kind, err.line_col()), (ErrorKind::Expression, Some((1, 1))));
/// assert!(err.message.ends_with(
///     "name it with LoadedSystem::add_function (add_function(\"X\", \"X\", \"L+G1\"), \
///      then X among the generators)"
/// ));
/// ```
pub fn refuse_expression_as_generator(
    name: &str,
    caller: Caller,
    mut free: impl FnMut(&str) -> bool,
    parse: impl FnOnce() -> Result<(), FileError>,
) -> Result<(), FileError> {
    let written = name.trim();
    if reads_as_a_generator_name(written) {
        return Ok(());
    }
    match parse() {
        Err(unread) if unread.kind != ErrorKind::Limit => return Err(unread),
        _ => {}
    }
    // A name the system does not have, for the example.
    let free = ["G", "X", "Y", "W", "Gen"]
        .into_iter()
        .find(|n| free(n))
        .unwrap_or("Gen");
    // A long expression is shown by its start, and left out of the example.
    let example = match written.chars().count() > trigpoly::MAX_NAME_CHARS {
        true => "…",
        false => written,
    };
    let (origin, how) = match caller {
        Caller::CommandLine => (
            COMMAND_LINE,
            format!("--define (--define '{free}={example}', then {free} among the generators)"),
        ),
        Caller::Program => (
            "<expression>",
            format!(
                "LoadedSystem::add_function (add_function(\"{free}\", \"{free}\", \
                 \"{example}\"), then {free} among the generators)"
            ),
        ),
    };
    // Refused as a whole, the caret under all of it, as a name given twice is.
    Err(refused_whole(
        origin,
        name,
        format!(
            "{} is an expression, not the name of a function: name it with {how}",
            trigpoly::quoted_name(written)
        ),
    ))
}

/// Refuses `name`, given as one of several names (a closure's generator, a table's
/// function: `each` says which), where it holds a character that shows nothing or moves the
/// text around it (a line break, a tab, a zero-width space: `$'H\nL'` in a shell, two names
/// in one argument), at that character, with the name written with each such character
/// escaped (`'H\nL'`). It comes before every other refusal of a name, each of which quotes
/// it: the advice under an expression given as a generator printed the line break inside
/// `--define 'G=H` and `L'`, and a table's unknown name inside its quotes.
///
/// ```
/// use superint::system_file::{refuse_unshowable_name, Caller, ErrorKind};
///
/// assert!(refuse_unshowable_name("P_{1, 1}", Caller::CommandLine, "generator").is_ok());
/// let err = refuse_unshowable_name("H\nL", Caller::CommandLine, "generator").unwrap_err();
/// assert_eq!((err.kind, err.line_col()), (ErrorKind::Expression, Some((1, 2))));
/// assert_eq!(
///     err.message,
///     "'H\\nL' holds a line break (U+000A), which no name does: give each generator as an \
///      argument of its own"
/// );
/// let err = refuse_unshowable_name("L\tG1", Caller::Program, "function").unwrap_err();
/// assert!(err.message.ends_with("give each function as a name of its own"));
/// ```
pub fn refuse_unshowable_name(name: &str, caller: Caller, each: &str) -> Result<(), FileError> {
    let Some((span, why)) = unshowable_in_name(name) else {
        return Ok(());
    };
    let (origin, how) = match caller {
        Caller::CommandLine => (COMMAND_LINE, "as an argument of its own"),
        Caller::Program => ("<expression>", "as a name of its own"),
    };
    Err(FileError::at(
        ErrorKind::Expression,
        origin,
        name,
        span,
        format!("{why}: give each {each} {how}"),
    ))
}

/// Where `name` holds a character that shows nothing or moves the text around it
/// ([`first_invisible`], a line break and a tab too), that character's byte range and why
/// no name holds it, the name quoted with each such character escaped: `'H\nL' holds a line
/// break (U+000A), which no name does`. The one rule of every name given on the command line
/// or by a program as a list of names ([`refuse_unshowable_name`]; `--symbolic`, `--fix` and
/// a tower's `--family` put it before their usage).
pub(crate) fn unshowable_in_name(name: &str) -> Option<(std::ops::Range<usize>, String)> {
    let (k, c) = first_invisible(name, false)?;
    let escaped: String = name
        .chars()
        .map(|c| match invisible(c) {
            true => c.escape_debug().to_string(),
            false => c.to_string(),
        })
        .collect();
    let code = format!("U+{:04X}", c as u32);
    let what = match c {
        '\n' | '\r' | '\u{2028}' => format!("a line break ({code})"),
        '\t' => format!("a tab ({code})"),
        _ => format!("{code}, an invisible or control character"),
    };
    let why = format!(
        "{} holds {what}, which no name does",
        trigpoly::quoted_name(&escaped)
    );
    Some((k..k + c.len_utf8(), why))
}

/// Refuses `name`, given as a closure's generator, where it names a parameter of the system
/// (`M`, or `ω` for `omega`, by any spelling `vars` reads): a constant, no function of the
/// phase space, whose brackets are all 0, and which the brackets and relations hold in their
/// coefficients already. The engine refused it too, but after the other generators had been
/// read and with no place (`computing the closure: the generator 'M' has the name of a
/// parameter`); the error is at the whole of it, as an expression given as a name is, and
/// says how to keep the parameter in the coefficients (`--symbolic M` for
/// [`Caller::CommandLine`], `ClosureOptions::symbolic` for a program).
///
/// ```
/// use superint::system_file::{refuse_parameter_as_generator, Caller, ErrorKind};
///
/// let rotor = superint::brackets::systems::harmonic_rotor();
/// assert!(refuse_parameter_as_generator("x", Caller::CommandLine, rotor.vars()).is_ok());
/// let err = refuse_parameter_as_generator("ω", Caller::CommandLine, rotor.vars()).unwrap_err();
/// assert_eq!((err.kind, err.line_col()), (ErrorKind::Expression, Some((1, 1))));
/// assert!(err.message.starts_with("'ω' is a parameter of the system, not a function"));
/// assert!(err.message.ends_with("(--symbolic omega keeps it symbolic there)"));
/// ```
pub fn refuse_parameter_as_generator(
    name: &str,
    caller: Caller,
    vars: &trigpoly::Vars,
) -> Result<(), FileError> {
    // As written (`ω`, `ω₊` of a display), or in braces (`a_{1}`), but not by the identifier
    // of a name whose marks it drops: `ω₋` is no spelling of `ω`.
    let written = name.trim();
    let braced = written
        .chars()
        .all(|c| c.is_alphanumeric() || "_{}, '".contains(c));
    let identifier = braced.then(|| name_as_identifier(written));
    let parameter = std::iter::once(written)
        .chain(identifier.as_deref())
        .find_map(|n| vars.lookup(n))
        .filter(|&v| vars.variable(v).kind() == trigpoly::VarKind::Parameter);
    let Some(v) = parameter else {
        return Ok(());
    };
    let ascii = vars.variable(v).name();
    let (origin, keep) = match caller {
        Caller::CommandLine => (COMMAND_LINE, format!("--symbolic {ascii}")),
        Caller::Program => ("<expression>", "ClosureOptions::symbolic".to_string()),
    };
    Err(refused_whole(
        origin,
        name,
        format!(
            "{} is a parameter of the system, not a function of its phase space: the \
             brackets and relations hold the parameters in their coefficients ({keep} keeps \
             it symbolic there)",
            trigpoly::quoted_name(written)
        ),
    ))
}

/// Whether `name`, given as a closure's generator, is a name rather than an expression: a
/// letter first, then letters, digits, `_`, an instance's braces, primes (`P'`), the macron
/// of a display (`Z̄`) and a display's subscripts and superscripts, signs too (`ω₊`, which
/// Unicode counts as no letter or digit), commas (`P_{1,1}`; one elsewhere is the parser's to
/// refuse), and spaces inside the braces (`P_{1, 1}`), so that a generator such as `Z̄`, `P'_{1,1}` or `ω₊` is resolved by its name,
/// or refused as the parameter it names, and not refused as an expression. A space outside
/// the braces parts two names, which the parser reads as their product: `L G1` is the
/// expression `L*G1` is, not a name. Not [`looks_like_name`]'s rule (for `--known` and for
/// displays), which takes a digit first but neither primes, spaces nor marks.
fn reads_as_a_generator_name(name: &str) -> bool {
    let mut braces = 0usize;
    name.chars().next().is_some_and(char::is_alphabetic)
        && name.chars().all(|c| match c {
            '{' => {
                braces += 1;
                true
            }
            '}' => {
                braces = braces.saturating_sub(1);
                true
            }
            ' ' => braces > 0,
            c => c.is_alphanumeric() || "_,'".contains(c) || c == '\u{304}' || script(c).is_some(),
        })
}

/// `P_{1,1}` → `P_1_1`: a name given as a generator or a known integral as the generators'
/// ring takes it, a prime spelt `p` (`P'_{1,1}` is `Pp_1_1`, as `y'` is `yp`).
///
/// ```
/// use superint::system_file::name_as_identifier;
///
/// assert_eq!(name_as_identifier("P_{1,1}"), "P_1_1");
/// assert_eq!(name_as_identifier("P'_{1,1}"), "Pp_1_1");
/// ```
pub fn name_as_identifier(name: &str) -> String {
    let mut out = String::new();
    for c in name.chars() {
        if c.is_alphanumeric() {
            out.push(c);
        } else if c == '\'' && !out.is_empty() {
            // A prime as a name spells it (`P'_{1,1}` is `Pp_1_1`, as `y'` is `yp`).
            out.push('p');
        } else if !out.ends_with('_') && !out.is_empty() {
            out.push('_');
        }
    }
    out.trim_end_matches('_').to_string()
}

/// Whether `text` given on the command line is a name (`Zbar`, `K_{1,2}`, `Kbar_1_2`) rather
/// than an expression (`x*p_y`, `L^2`, or a bracket `{Lx,Axy}`, which the characters of an
/// instance's braces would otherwise let through as the name `Lx_Axy`).
pub fn looks_like_name(text: &str) -> bool {
    text.chars().next().is_some_and(char::is_alphanumeric)
        && text
            .chars()
            .all(|c| c.is_alphanumeric() || "_{},".contains(c))
}

/// How a name given as a generator or a known integral prints, `shown` being how the system
/// prints a name of its own (`name` itself for one it does not have): a function or family
/// instance as the system shows it (`Z̄` for `Zbar`, `K̄_{1,2}` for `Kbar_1_2` or
/// `Kbar_{1,2}`), any other name of an instance's shape as an instance is shown, as the paper
/// writes it and the LaTeX prints it (`R_{1,1}` for a `--define R_1_1`), and an expression
/// (`x*p_y`) as it is written.
///
/// ```
/// use superint::system_file::{display_as_given, load, LimitsOverride};
///
/// let rotor = load("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
/// let shown = |name| display_as_given(name, |n| rotor.display_name(n));
/// assert_eq!(shown("Kbar_{1,2}"), "K̄_{1,2}");
/// assert_eq!(shown("R_1_1"), "R_{1,1}");
/// assert_eq!(shown("x*p_y"), "x*p_y");
/// # Ok::<(), superint::system_file::FileError>(())
/// ```
pub fn display_as_given(name: &str, shown: impl Fn(&str) -> String) -> String {
    // An expression (`--known 'x*p_y'`) as it is written.
    if !looks_like_name(name) {
        return name.to_string();
    }
    // As given, then as an identifier (`Kbar_{1,2}` is `Kbar_1_2`).
    let key = name_as_identifier(name);
    let found = [name, key.as_str()]
        .into_iter()
        .map(|n| (n, shown(n)))
        .find(|(n, s)| s != n)
        .map(|(_, s)| s);
    found.unwrap_or_else(|| braced_indices(&key))
}

/// `R_1_1` → `R_{1,1}`: a name of a family instance's shape, two numeric indices, shown as an
/// instance is (which `trigpoly::shown_forms` reads); any other name as it is, so that its
/// own forms (`W_x_θ`, `W_{x,\theta}` for `W_x_theta`) stand.
fn braced_indices(name: &str) -> String {
    let numeric = |s: &str| !s.is_empty() && s.chars().all(|c| c.is_ascii_digit());
    match name
        .split_once('_')
        .map(|(head, tail)| (head, tail.split_once('_')))
    {
        Some((head, Some((m, n)))) if !head.is_empty() && numeric(m) && numeric(n) => {
            format!("{head}_{{{m},{n}}}")
        }
        _ => name.to_string(),
    }
}

/// A generator's name refused as a whole, the caret under all of it (its surrounding spaces
/// left out), as an error of kind `expression` from `origin`.
fn refused_whole(origin: &str, name: &str, message: String) -> FileError {
    FileError::at(
        ErrorKind::Expression,
        origin,
        name,
        trimmed(0, name).1,
        message,
    )
}
