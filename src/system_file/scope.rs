//! Parsing expressions of a system file: a [`trigpoly::Context`] over the system that knows the
//! named functions and the family instances (`K_2_3`, expanded on first use and cached); with
//! every error mapped back to its place in the file.
//!
//! The parser and the lowering belong to `trigpoly`; this module only prepares the tree: it
//! expands family instances (so that an expansion's error has a place) and rejects a bracket
//! with a bare parameter; `conj`, `re` and `im` are the lowering's.

use std::cell::RefCell;
use std::collections::HashMap;

use brackets::{EngineError, EngineLimit, Input, Recording};

use num_bigint::BigInt;
use trigpoly::syntax::{is_name_continue, is_name_start, Expr as Tree, ExprKind, ParseError};
use trigpoly::{Context, Expr, GaussianRational, LimitKind, Limits, ParseCause, Span, VarKind};

use super::error::{ErrorKind, FileError, Warning};
use super::load::MAX_DEGREE_CEILING;
use super::text::{Given, Source, Text};
use super::LoadedSystem;

/// What a scope sees: the system's functions, the first `families` families, and names it
/// made for family instances while preparing a tree.
pub(crate) struct Scope<'a> {
    file: &'a LoadedSystem,
    families: usize,
    /// In a family's value or eigenvalue, its index names, which braces may hold (`K_{m,n}`).
    indices: &'a [String],
    /// In a family's value or eigenvalue, that family, whose instances it cannot use.
    owner: Option<usize>,
    made: RefCell<HashMap<String, Expr>>,
    /// The names run together that the lowering read as products in doubt, not yet kept as
    /// the file's warnings ([`Scope::lower`] keeps them).
    noted: RefCell<Vec<trigpoly::RunTogether>>,
    /// The names as their LaTeX spells them ([`LatexNames`]), made when a name written in
    /// LaTeX is first read.
    latex: RefCell<Option<LatexNames>>,
}

/// A system's names as their printed LaTeX spells them, read back ([`trigpoly::syntax::latex_name`]):
/// `G_1` for a function `G1` (printed `G_{1}`), `Z̄` for `Zbar` (`\bar{Z}`), `q_1` for a
/// variable `q₁`, `θ1_x` for `theta1_x` (`\mathrm{\theta1}_{x}`); a family's name, `K̄` for
/// `Kbar`, `K_1` for `K1` (`K_{1;2,3}`), with an instance's indices after it. A spelling of
/// two names is neither: reading it is an error that names both ([`Scope::latex_alias`]).
#[derive(Default)]
struct LatexNames {
    /// A spelling and the names it is, two or more where names spell it alike.
    names: HashMap<String, Vec<String>>,
    /// A family's spelling and its names, two or more where families spell it alike.
    families: HashMap<String, Vec<String>>,
    /// A function's display that is no name, as its LaTeX is written without spaces (`x(t)`,
    /// `\theta(t)`), and the functions that display so (the loader lets one).
    calls: HashMap<String, Vec<String>>,
}

/// Keeps `spelled` as a spelling of `name` in `map`, beside any other name's.
fn keep_spelling(map: &mut HashMap<String, Vec<String>>, spelled: String, name: &str) {
    let names = map.entry(spelled).or_default();
    if !names.iter().any(|n| n == name) {
        names.push(name.to_string());
    }
}

impl LatexNames {
    fn of(file: &LoadedSystem) -> LatexNames {
        let mut out = LatexNames::default();
        // A display of several words, `Re A` (`\operatorname{Re} A`), is spelled word by word.
        let keep = |map: &mut HashMap<String, Vec<String>>, latex: &str, name: &str| {
            if let Some(spelled) = super::names::read_back(latex) {
                keep_spelling(map, spelled, name);
            }
        };
        let vars = file.system.vars();
        for v in vars.vars() {
            let var = vars.variable(v);
            keep(&mut out.names, var.latex(), var.name());
        }
        for f in file.system.functions() {
            let latex = brackets::table::latex_name(&f.display);
            keep(&mut out.names, &latex, &f.name);
            if latex.contains('(') {
                let written: String = latex.split_whitespace().collect();
                keep_spelling(&mut out.calls, written, &f.name);
            }
        }
        for f in &file.families {
            if let Some((text, latex)) = trigpoly::shown_forms(&f.display) {
                keep(&mut out.families, &latex, &f.name);
                // The text an instance prints as reads back too where its LaTeX spells another
                // letter: omicron's `ο_{1,1}`, whose LaTeX is `\mathit{o}_{1,1}`.
                if !text.contains(' ') {
                    keep_spelling(&mut out.families, text, &f.name);
                }
            }
        }
        out
    }

    /// The names that `spelled` (a name written in LaTeX, read) may be: the declared names
    /// whose LaTeX spells it, and the instances of the families whose LaTeX spells its head,
    /// its indices whole numbers or `indices`; none, one, or several that print alike.
    fn names(&self, spelled: &str, indices: &[String]) -> Vec<String> {
        let mut out = self.names.get(spelled).cloned().unwrap_or_default();
        let mut parts = spelled.rsplitn(3, '_');
        if let (Some(n), Some(m), Some(head)) = (parts.next(), parts.next(), parts.next()) {
            let index = |s: &str| {
                (!s.is_empty() && s.bytes().all(|b| b.is_ascii_digit()))
                    || indices.iter().any(|i| i == s)
            };
            if index(m) && index(n) {
                let families = self.families.get(head).into_iter().flatten();
                out.extend(families.map(|family| format!("{family}_{m}_{n}")));
            }
        }
        out
    }
}

/// `K_2_3` → (family `K`, 2, 3) among `families`.
pub(crate) fn instance_of(families: &[super::Family], name: &str) -> Option<(usize, i64, i64)> {
    let (head, m, n) = instance_parts(name)?;
    let k = families.iter().position(|f| f.name == head)?;
    Some((k, index_value(m)?, index_value(n)?))
}

/// The instance of `families` under one bar in `name` (`P_3_2` of `P̄_3_2`, `Ā_1_2` with a
/// precomposed bar too), if it is one.
fn barred_instance(families: &[super::Family], name: &str) -> Option<String> {
    trigpoly::under_one_bar(name).filter(|base| instance_of(families, base).is_some())
}

/// The most digits an index of a family instance has, leading zeros aside (`K_007_1` is
/// `K_7_1`).
const INDEX_DIGITS: usize = 9;

/// An index of a family instance written in `digits`, if it has at most [`INDEX_DIGITS`]
/// digits once its leading zeros are left out.
fn index_value(digits: &str) -> Option<i64> {
    let significant = digits.trim_start_matches('0');
    match significant.is_empty() {
        true => (!digits.is_empty()).then_some(0),
        false => (significant.len() <= INDEX_DIGITS)
            .then(|| significant.parse().ok())
            .flatten(),
    }
}

/// Why `name` (`K_99999999999_1`, braces rewritten) is not an instance of `family`, if it is
/// because an index is too large: `written` is how it reads.
fn oversized_index_message(family: &super::Family, name: &str, written: &str) -> Option<String> {
    let (head, m, n) = instance_parts(name)?;
    let too_long = |i: &str| i.trim_start_matches('0').len() > INDEX_DIGITS;
    let which = match (too_long(m), too_long(n)) {
        (false, false) => return None,
        (true, false) => "its first index is",
        (false, true) => "its second index is",
        (true, true) => "both its indices are",
    };
    (head == family.name).then(|| {
        format!(
            "'{written}' is not an instance of the family {f}_{i}_{j}: {which} too large (an index has \
             at most {INDEX_DIGITS} digits, leading zeros aside: 999999999 at most)",
            f = family.name,
            i = family.indices[0],
            j = family.indices[1],
        )
    })
}

/// The parts of a name written as an instance of a family, whatever families there are:
/// `K_2_3` → (`K`, `2`, `3`), two indices of digits after a name.
pub(crate) fn instance_parts(name: &str) -> Option<(&str, &str, &str)> {
    let mut parts = name.rsplitn(3, '_');
    let (n, m, head) = (parts.next()?, parts.next()?, parts.next()?);
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    (digits(m) && digits(n) && !head.is_empty()).then_some((head, m, n))
}

/// The family whose instances a malformed name was meant to be: `P_1`, `P_` (of `P_-1_2`)
/// and `P_1_2_3` start as instances of `P` without being one.
fn meant_family<'f>(families: &'f [super::Family], name: &str) -> Option<&'f super::Family> {
    families.iter().find(|f| {
        name.strip_prefix(f.name.as_str())
            .is_some_and(|rest| rest.starts_with('_'))
    })
}

/// Whether `name` is written as an instance of `family` in a text of its own, well formed or
/// not: `K_2_3`, `K_m_n`, `K_1`, `K_1_2_3` and `K_` (of `K_{…}`) for `K` with indices `m, n`;
/// not `K_b_1_2`, which may be another family's.
fn names_own_instance(family: &super::Family, name: &str) -> bool {
    name.strip_prefix(family.name.as_str())
        .and_then(|rest| rest.strip_prefix('_'))
        .is_some_and(|rest| {
            rest.split('_').all(|piece| {
                piece.bytes().all(|b| b.is_ascii_digit())
                    || family.indices.iter().any(|i| i == piece)
            })
        })
}

/// Why a family's text cannot use the family itself, as `written` does.
fn uses_itself_message(family: &super::Family, written: &str) -> String {
    format!(
        "the family {f} uses itself here ('{written}'): a family cannot be defined by its own \
         instances; write it in the variables, the functions and the families declared before it",
        f = family.name
    )
}

/// What an instance of a family must look like, for a name or braces that are not one.
fn malformed_instance_message(family: &super::Family, written: &str) -> String {
    let [m, n] = &family.indices;
    let f = &family.name;
    format!(
        "'{written}' is not an instance of the family {f}_{m}_{n}, which takes two indices, \
         each a whole number 0, 1, 2, … of at most nine digits: write {f}_2_3 or {f}_{{2,3}} \
         (in a family's value, with index names: {f}_{m}_{n} or {f}_{{{m},{n}}})"
    )
}

/// A family instance written with braces, `K_{2, 3}`: where it is and what the braces hold.
struct BracedInstance<'f> {
    family: &'f super::Family,
    /// From the family's name to the closing brace, or to the end when it is not closed.
    span: std::ops::Range<usize>,
    /// The two indices, when the braces hold two whole numbers.
    indices: Option<(&'f str, &'f str)>,
}

/// Every `K_{…}` in `s` whose `K` is one of `families`, left to right; its indices are whole
/// numbers or, in a family's text, its `index_names`.
fn braced_instances<'f>(
    s: &'f str,
    families: &'f [super::Family],
    index_names: &'f [String],
) -> impl Iterator<Item = BracedInstance<'f>> {
    s.match_indices("_{").filter_map(move |(k, _)| {
        let head_start = s[..k]
            .char_indices()
            .rev()
            .take_while(|&(_, c)| c.is_alphanumeric() || c == '_')
            .last()
            .map_or(k, |(i, _)| i);
        // A name begins after any digits before it: `2K_{1,1}` is 2·K_{1,1}.
        let head_start = head_start + s[head_start..k].len()
            - s[head_start..k]
                .trim_start_matches(|c: char| c.is_ascii_digit())
                .len();
        let family = families.iter().find(|f| f.name == s[head_start..k])?;
        let close = s[k..].find('}').map(|c| c + k);
        let end = close.map_or(s.len(), |c| c + 1);
        let inner = &s[k + 2..close.unwrap_or(end)];
        let index = |p: &str| {
            (!p.is_empty() && p.bytes().all(|b| b.is_ascii_digit()))
                || index_names.iter().any(|i| i == p)
        };
        let indices = close
            .and_then(|_| inner.split_once(','))
            .map(|(m, n)| (m.trim(), n.trim()))
            .filter(|(m, n)| index(m) && index(n));
        Some(BracedInstance {
            family,
            span: head_start..end,
            indices,
        })
    })
}

/// The first `K_{…}` of a family `K` whose braces do not hold two whole numbers (`K_{1}`,
/// `K_{m,2}`) and that `other_name` does not take for another name's LaTeX (`K_{x}` of a
/// parameter `K_x`), with the message that says what they must hold.
fn malformed_braces(
    s: &str,
    families: &[super::Family],
    index_names: &[String],
    other_name: &dyn Fn(&super::Family, &str) -> bool,
) -> Option<(Span, String)> {
    braced_instances(s, families, index_names)
        .find(|b| b.indices.is_none() && !other_name(b.family, &s[b.span.clone()]))
        .map(|b| {
            let written = &s[b.span.clone()];
            let message = if written.ends_with('}') {
                malformed_instance_message(b.family, written)
            } else {
                format!("the braces of '{written}' are never closed")
            };
            (Span::new(b.span.start, b.span.end), message)
        })
}

/// Rewrites `K_{2,3}` into `K_2_3` (and, in a family's text, `K_{m,n}` into `K_m_n`) padded
/// with spaces to the same length, for the family names given, so that every other span stays
/// where it was.
pub(crate) fn rewrite_braces(
    s: &str,
    families: &[super::Family],
    index_names: &[String],
) -> String {
    let mut out = s.to_string();
    for b in braced_instances(s, families, index_names) {
        if let Some((m, n)) = b.indices {
            let replacement = format!("{}_{m}_{n}", b.family.name);
            let width = b.span.len();
            out.replace_range(b.span, &format!("{replacement:width$}"));
        }
    }
    out
}

/// Replaces the index names by their values in a family's tree: `m` → `2`, and inside names
/// of family instances, `K_m_n` → `K_2_3`.
pub(crate) fn substitute(
    tree: &Tree,
    indices: &[String; 2],
    values: [i64; 2],
    families: &[super::Family],
) -> Tree {
    let sub = |t: &Tree| Box::new(substitute(t, indices, values, families));
    let kind = match &tree.kind {
        ExprKind::Name(s) => {
            if let Some(k) = indices.iter().position(|i| i == s) {
                ExprKind::Integer(BigInt::from(values[k]))
            } else {
                let parts: Vec<String> = s
                    .split('_')
                    .map(|p| match indices.iter().position(|i| i == p) {
                        Some(k) => values[k].to_string(),
                        None => p.to_string(),
                    })
                    .collect();
                let renamed = parts.join("_");
                if renamed != *s && instance_of(families, &renamed).is_some() {
                    ExprKind::Name(renamed)
                } else {
                    ExprKind::Name(s.clone())
                }
            }
        }
        ExprKind::Integer(n) => ExprKind::Integer(n.clone()),
        ExprKind::Neg(a) => ExprKind::Neg(sub(a)),
        ExprKind::Add(a, b) => ExprKind::Add(sub(a), sub(b)),
        ExprKind::Sub(a, b) => ExprKind::Sub(sub(a), sub(b)),
        ExprKind::Mul(a, b) => ExprKind::Mul(sub(a), sub(b)),
        ExprKind::Div(a, b) => ExprKind::Div(sub(a), sub(b)),
        ExprKind::Pow(a, b) => ExprKind::Pow(sub(a), sub(b)),
        ExprKind::Bracket(a, b) => ExprKind::Bracket(sub(a), sub(b)),
        ExprKind::Call(f, span, args) => ExprKind::Call(
            f.clone(),
            *span,
            args.iter()
                .map(|a| substitute(a, indices, values, families))
                .collect(),
        ),
    };
    Tree {
        kind,
        span: tree.span,
    }
}

/// Which limit stopped a computation, as its hint tells how to raise it: read from the error's
/// variant and numbers, never from its message.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Limit {
    /// The work limit, of term products (`max_term_products`).
    Work,
    /// The term limit (`max_terms`), of a result, of its printing, of a closure's products
    /// together or of a search space's unknowns, which a larger one may reach.
    Terms,
    /// The degree limit (`max_degree`), of an exponent or an angle's order of this size (one
    /// too large to say is `u64::MAX`), which a larger limit reaches where the settings allow
    /// one so large ([`LimitSettings::degree_ceiling`]).
    Degree(u64),
    /// A limit of the ring this crate does not know yet, which a larger term or degree limit
    /// may reach.
    Size,
    /// A result past the machine's memory, which a larger limit only lets through.
    Memory,
    /// The products of integrals a search for new integrals forms
    /// (`SearchOptions::max_products`, `--max-products`), which no file sets.
    SearchProducts,
    /// The monomials in a closure's generators (`ClosureOptions::max_monomials`,
    /// `--max-monomials`), which no file sets.
    ClosureMonomials,
    /// The rows of a minor whose determinant `--find-values` computes
    /// (`SearchOptions::max_minor`, `--max-minor`), which no file sets.
    MinorRows,
    /// A limit of the engine's own this crate does not know yet, which no setting it knows
    /// raises: no hint.
    OfOptions,
}

/// Whose settings raise a limit, as a limit's hint names them: the input the limit stopped
/// was given by a file, the command line or a program, about a system file or a system with
/// no file (a built-in one, or one built in code). Told from who gave the text ([`Given`],
/// [`LimitSettings::of`]), its [`Source`]'s wherever the text has one, so that every caller's
/// hint is worded in one place, [`Limit::hint`], and a closure's advice at a limit names the
/// same setting ([`LimitSettings::setting`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum LimitSettings {
    /// A system file's own text, loaded by the command line or by a program: the file's
    /// `[limits]`, then the flag and the `LimitsOverride` given to the loader.
    File,
    /// A system file on the command line (a text given on it, or the file piped on standard
    /// input): the flag, then the file's `[limits]`.
    FileOnCommandLine,
    /// A text a program gave to a system file: the `LimitsOverride` given to the loader, then
    /// the file's `[limits]`.
    FileInProgram,
    /// A built-in system on the command line (`--system harmonic`), which has no file: the
    /// flag alone.
    BuiltInOnCommandLine,
    /// A system built in code (a built-in one too, `discovery::builtin_system`): the `Limits`
    /// its variables were built with.
    Code,
    /// A program's error taken by `?` from the engine or the parser, whose system may be built
    /// in code or loaded from a file: both settings.
    Program,
}

impl LimitSettings {
    /// The settings of a text `given` by the file itself, the command line or a program,
    /// about a system with a file or none ([`Given`]): a built-in system's on the command
    /// line, else one built in code's; a system file's text given on the command line (or the
    /// file piped on standard input), by a program, or the file's own, which either loaded.
    pub(crate) fn of(given: Given) -> LimitSettings {
        match given {
            Given::CommandLineAboutBuiltIn => LimitSettings::BuiltInOnCommandLine,
            Given::InCode => LimitSettings::Code,
            Given::CommandLineAboutFile => LimitSettings::FileOnCommandLine,
            Given::ProgramAboutFile | Given::ProgramAddingToFile => LimitSettings::FileInProgram,
            Given::InFile => LimitSettings::File,
        }
    }

    /// The largest degree limit these settings may set: a file's and the command line's
    /// [`MAX_DEGREE_CEILING`], a system built in code's [`Limits::MAX_DEGREE`] (past which
    /// `Limits::max_degree` takes no effect), and a program's either, so its largest.
    pub(crate) fn degree_ceiling(self) -> u64 {
        match self {
            LimitSettings::Code | LimitSettings::Program => u64::from(Limits::MAX_DEGREE),
            _ => u64::from(MAX_DEGREE_CEILING),
        }
    }

    /// The settings that raise a limit, by the file's key `keys` (`max_degree`), the command
    /// line's flag `flags` (`--max-degree D`) and the library's field `fields` of `Limits` and
    /// `LimitsOverride` (`max_degree`), the first that the input's giver would reach for
    /// first.
    fn raising(self, keys: &str, flags: &str, fields: &str) -> String {
        match self {
            LimitSettings::File => format!(
                "{keys} under [limits] in the file (on the command line, {flags}; in a \
                 program, the LimitsOverride given to the loader)"
            ),
            LimitSettings::FileOnCommandLine => {
                format!("{flags} (or {keys} under [limits] in the file)")
            }
            LimitSettings::FileInProgram => format!(
                "{fields} of the LimitsOverride given to the loader (or {keys} under [limits] \
                 in the file)"
            ),
            LimitSettings::BuiltInOnCommandLine => flags.to_string(),
            LimitSettings::Code => {
                format!("{fields} of the Limits the system's variables were built with")
            }
            LimitSettings::Program => format!(
                "{fields} of the Limits a system built in code was built with, or of the \
                 LimitsOverride given to the loader of a system file"
            ),
        }
    }

    /// The one setting that raises a limit, named short as a sentence names it beside another
    /// (a closure's `raise it with …, or lower --degree`): the command line's flag `flag`
    /// (`--max-terms N`), a program's field `field` (`max_terms`) of the `LimitsOverride` given
    /// to a system file's loader or of the `Limits` a system built in code was built with; the
    /// file's key for its own text, and both fields for a program's error of either system.
    pub(crate) fn setting(self, flag: &str, field: &str) -> String {
        match self {
            LimitSettings::FileOnCommandLine | LimitSettings::BuiltInOnCommandLine => {
                flag.to_string()
            }
            LimitSettings::FileInProgram => format!("LimitsOverride::{field}"),
            LimitSettings::Code => format!("Limits::{field}"),
            LimitSettings::File => format!("{field} under [limits] in the file"),
            LimitSettings::Program => format!("Limits::{field} or LimitsOverride::{field}"),
        }
    }

    /// Who names these settings: the command line for its own, a program for the rest.
    pub(crate) fn caller(self) -> super::Caller {
        match self {
            LimitSettings::FileOnCommandLine | LimitSettings::BuiltInOnCommandLine => {
                super::Caller::CommandLine
            }
            LimitSettings::File
            | LimitSettings::FileInProgram
            | LimitSettings::Code
            | LimitSettings::Program => super::Caller::Program,
        }
    }

    /// The setting that raises a limit of a search's or a closure's own options, which no
    /// file sets: the command line's flag `flag` (`--max-products N`), or the program's
    /// option `option` (`SearchOptions::max_products`); both for a file's own text, loaded
    /// by either.
    fn raising_option(self, flag: &str, option: &str) -> String {
        match self {
            LimitSettings::File => format!("{flag} (in a program, {option})"),
            _ => self.caller().names(flag, option).to_string(),
        }
    }
}

impl Limit {
    /// The limit of the ring that `kind` names: the term limit (of a result or of its
    /// printing), the work limit, the degree limit (an exponent, an angle's order), or the
    /// machine's memory.
    fn of_kind(kind: LimitKind) -> Limit {
        match kind {
            LimitKind::Work => Limit::Work,
            LimitKind::Terms => Limit::Terms,
            LimitKind::Degree(n) => Limit::Degree(n),
            LimitKind::Memory => Limit::Memory,
            // A kind of limit this crate does not know yet: one that a larger limit may reach.
            _ => Limit::Size,
        }
    }

    /// The limit that stopped the engine with `e`, if a limit did ([`EngineError::limit`]):
    /// the ring's (of the algebra, of a text's reading, of a closure's products or a search's
    /// unknowns), or one of the search's or the closure's options.
    pub(crate) fn of_engine(e: &EngineError) -> Option<Limit> {
        Some(match e.limit()? {
            EngineLimit::Ring(kind) => Limit::of_kind(kind),
            EngineLimit::SearchProducts => Limit::SearchProducts,
            EngineLimit::ClosureMonomials => Limit::ClosureMonomials,
            EngineLimit::MinorRows => Limit::MinorRows,
            // An option's limit this crate does not know yet.
            _ => Limit::OfOptions,
        })
    }

    /// The limit that stopped a parse with the cause `cause`, if a limit did
    /// ([`ParseCause::limit`]): the algebra's, or an exponent or multiple written past the
    /// degree limit.
    pub(crate) fn of_parse(cause: &ParseCause) -> Option<Limit> {
        cause.limit().map(Limit::of_kind)
    }

    /// The hint that goes with the limit, naming the setting that raises it in `settings`,
    /// those of the input it stopped ([`LimitSettings`]: the command line's flag first for a
    /// text given on it, and alone for a built-in system, which has no file): the work
    /// limit's, the term limit's (`max_terms` alone: a larger `max_degree` lets no more terms
    /// through, nor a search space of more unknowns), the degree limit's, or, for an exponent
    /// past the most that the settings' `max_degree` may be, that no limit reaches it; a
    /// search's products' and a closure's monomials', their option (the command line's flag,
    /// or the program's option: no file sets them); none for a limit of the engine this crate
    /// does not know.
    pub(crate) fn hint(self, settings: LimitSettings) -> Option<String> {
        let raise = |keys: &str, flags: &str, fields: &str| settings.raising(keys, flags, fields);
        Some(match self {
            Limit::OfOptions => return None,
            Limit::SearchProducts => format!(
                "if the machine has the time, raise the limit with {}",
                settings.raising_option("--max-products N", "SearchOptions::max_products")
            ),
            Limit::ClosureMonomials => format!(
                "if the machine has the time, raise the limit with {}",
                settings.raising_option("--max-monomials N", "ClosureOptions::max_monomials")
            ),
            Limit::MinorRows => format!(
                "if the machine has the time, raise the limit with {}",
                settings.raising_option("--max-minor N", "SearchOptions::max_minor")
            ),
            Limit::Degree(power) if power > settings.degree_ceiling() => {
                let most = settings.degree_ceiling();
                format!(
                    "no limit reaches this exponent or order: max_degree is at most {most}; \
                     write the expression without so large a power or multiple"
                )
            }
            Limit::Memory => {
                "no limit makes room for it: write the expression with smaller powers".to_string()
            }
            Limit::Work => format!(
                "if the machine has the time, raise the limit with {}",
                raise(
                    "max_term_products",
                    "--max-term-products N",
                    "max_term_products"
                )
            ),
            Limit::Terms => format!(
                "if the machine has the memory, raise the limit with {}",
                raise("max_terms", "--max-terms N", "max_terms")
            ),
            Limit::Degree(_) => format!(
                "if the machine has the memory, raise the limit with {}",
                raise("max_degree", "--max-degree D", "max_degree")
            ),
            Limit::Size => format!(
                "if the machine has the memory, raise the limit with {}",
                raise(
                    "max_terms or max_degree",
                    "--max-terms N or --max-degree D",
                    "max_terms or max_degree"
                )
            ),
        })
    }
}

/// The hint that goes with an unknown name: where each kind of name is declared.
const UNKNOWN_NAME_HINT: &str = "a constant such as a mass is declared under [phase_space] \
    parameters, a named function with [[function]], a family with [[family]] (used as K_2_3); \
    see docs/system-files.md";

/// The hint that goes with an unknown name in a text a program gave.
const UNKNOWN_NAME_HINT_IN_CODE: &str = "a constant such as a mass is a parameter of the \
    system's VarSet, a named function is added with LoadedSystem::add_function, a family with \
    LoadedSystem::add_family (used as K_2_3)";

/// The hint that goes with an unknown name given on the command line to a system built in code
/// (`--system harmonic`), whose user can add no name to it: the library's calls are no help
/// there.
const UNKNOWN_NAME_HINT_BUILT_IN: &str = "a built-in system knows only the names listed: write \
    a function as an expression in them (closure names one with --define NAME=EXPR), or write \
    a system file, which declares constants under [phase_space] parameters and functions with \
    [[function]]; see docs/system-files.md";

/// The hint for `unknown name 'p_1' (known: q1, p_q1, …)`, a momentum written in a name of
/// its own: each momentum is named after its coordinate, `p_q1`. `None` when the unknown
/// name is neither `p_…` nor `p` and digits (`phi` may be anything), or the system has no
/// momenta.
fn momentum_hint(unknown: &Unknown) -> Option<String> {
    let Unknown { name, momenta } = unknown;
    let numbered = name
        .strip_prefix('p')
        .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()));
    if !(name.starts_with("p_") || numbered) || momenta.is_empty() {
        return None;
    }
    Some(format!(
        "the momentum of a coordinate or an angle `q` is named `p_q`: here {}",
        momenta.join(", ")
    ))
}

/// The hint for `unknown name 'r'` in a system of two or more momenta: `r` (`rho`, `r1`, `r_12`)
/// is almost always a distance, which a file declares as a radical by name, with its
/// radicand; the hint says so before the usual one. `None` for other names, or with fewer
/// than two momenta (a distance in one coordinate is no square root).
fn distance_hint(unknown: &Unknown) -> Option<String> {
    let Unknown { name, momenta } = unknown;
    let numbered = |rest: &str| !rest.is_empty() && rest.bytes().all(|b| b.is_ascii_digit());
    let distance = matches!(name.as_str(), "r" | "rho" | "ρ")
        || name.strip_prefix('r').is_some_and(numbered)
        || name.strip_prefix("r_").is_some_and(numbered);
    if !distance || momenta.len() < 2 {
        return None;
    }
    Some(format!(
        "a distance such as {name} = √(x² + y²) is declared by name under [phase_space] with its \
         radicand, radicals = {{ {name} = \"x^2 + y^2\" }}, after which -k/{name} is exact; \
         {UNKNOWN_NAME_HINT}"
    ))
}

/// The hint for `unknown name 'p'` in a system with momenta: a bare `p` is almost always the
/// momentum, whose components are named after their coordinates (`|p|²` is `p_x^2 + p_y^2`).
/// `None` for other names, or without momenta.
fn bare_momentum_hint(unknown: &Unknown) -> Option<String> {
    let Unknown { name, momenta } = unknown;
    if name != "p" || momenta.is_empty() {
        return None;
    }
    let squares: Vec<String> = momenta.iter().map(|m| format!("{m}^2")).collect();
    Some(format!(
        "the momenta are named after their coordinates, here {} (|p|² is {}); \
         {UNKNOWN_NAME_HINT}",
        momenta.join(", "),
        squares.join(" + ")
    ))
}

/// An unknown name ([`ParseCause::UnknownName`]) as its hints read it: the name as the
/// message shows it ([`trigpoly::shown_name`]: one past 80 characters by its start), and the
/// momenta among the known names (`p_…`).
struct Unknown {
    name: String,
    momenta: Vec<String>,
}

impl Unknown {
    /// The unknown name of `cause`, if it is one.
    fn of(cause: &ParseCause) -> Option<Unknown> {
        let ParseCause::UnknownName { name, known } = cause else {
            return None;
        };
        let name = trigpoly::shown_name(name);
        let momenta = known.iter().filter(|k| k.starts_with("p_")).cloned();
        Some(Unknown {
            name,
            momenta: momenta.collect(),
        })
    }
}

/// An expression error at a span of a text, classified as a limit error when it is one (by
/// its cause, [`ParseError::cause`]; [`FileError::with_cause`], the rule by which `?`
/// classifies a parse error too), an unknown name with the hint where such a name is declared.
pub(crate) fn expression_error(source: &Source, text: &Text, e: &ParseError) -> FileError {
    let message = relocate_opener(source, text, e);
    let error = text
        .error(source, ErrorKind::Expression, e.span, message)
        .with_cause_under(e.cause(), LimitSettings::of(source.given));
    let Some(unknown) = Unknown::of(e.cause()) else {
        return error;
    };
    let hint = match (momentum_hint(&unknown), source.given) {
        (Some(hint), _) => hint,
        (None, Given::CommandLineAboutBuiltIn) => UNKNOWN_NAME_HINT_BUILT_IN.into(),
        (None, given) if given.names_library() => UNKNOWN_NAME_HINT_IN_CODE.into(),
        (None, _) => distance_hint(&unknown)
            .or_else(|| bare_momentum_hint(&unknown))
            .unwrap_or_else(|| UNKNOWN_NAME_HINT.into()),
    };
    error.with_hint(hint)
}

/// The parser's message, with where the opener it names stands (an unclosed bracket, a
/// name's braces), which the parser hands over as a byte of the text, said in the file's lines
/// and columns (`opened at line 10, column 16`) rather than the expression's own (`opened at
/// column 7`). A text of the command line is said as the parser says it of a built-in
/// system's: the column alone where the opener is on the line of the error, `opened at column
/// 5`.
fn relocate_opener(source: &Source, text: &Text, e: &ParseError) -> String {
    e.message_placing_opener(|open| {
        let at = text.source_span(Span::new(open, open + 1));
        let loc = super::error::locate(&source.text, at);
        let error_line = || super::error::locate(&source.text, text.source_span(e.span)).line;
        match source.origin == super::COMMAND_LINE && loc.line == error_line() {
            true => format!("column {}", loc.column),
            false => format!("line {}, column {}", loc.line, loc.column),
        }
    })
}

impl<'a> Scope<'a> {
    pub(crate) fn new(file: &'a LoadedSystem, families: usize) -> Self {
        Scope {
            file,
            families,
            indices: &[],
            owner: None,
            made: RefCell::new(HashMap::new()),
            noted: RefCell::new(Vec::new()),
            latex: RefCell::new(None),
        }
    }

    /// The scope of family `k`'s value and eigenvalue: the families before it, and its index
    /// names, also inside braces (`K_{m,n}` for `K_m_n`); an instance of the family itself is
    /// refused as such.
    pub(crate) fn of_family(file: &'a LoadedSystem, k: usize) -> Self {
        Scope {
            indices: &file.families[k].indices,
            owner: Some(k),
            ..Scope::new(file, k)
        }
    }

    /// A [`Recording`] of what a reading in this scope uses, each function and family
    /// instance with what its value was computed from ([`LoadedSystem::computed_from`]).
    pub(crate) fn recording(&self) -> Recording<'_, Self> {
        Recording::new(self, self.file.system.space())
            .through(|name| self.file.computed_from(name))
            .showing(|name| self.file.display_name(name))
    }

    /// Parses a text of `source` into a polynomial, with what the value was computed from
    /// ([`Scope::recording`]).
    pub(crate) fn parse_recorded(
        &self,
        source: &Source,
        text: &Text,
    ) -> Result<(Expr, Vec<Input>), FileError> {
        let recording = self.recording();
        let value = self.parse_into(source, text, &recording)?;
        Ok((value, recording.into_inputs()))
    }

    /// Parses a text of `source` into a polynomial, adding what it is computed from to
    /// `recording` (several texts into one, as a claim's sides).
    pub(crate) fn parse_into(
        &self,
        source: &Source,
        text: &Text,
        recording: &Recording<'_, Self>,
    ) -> Result<Expr, FileError> {
        let tree = self.tree(source, text)?;
        self.lower_with(source, text, &tree, recording)
    }

    /// Parses a text into a tree (family instances written `K_{2,3}` are accepted).
    pub(crate) fn tree(&self, source: &Source, text: &Text) -> Result<Tree, FileError> {
        let families = &self.file.families[..self.families];
        // `K_{m,n}` in the text of `K` itself, well formed or not.
        if let Some(owner) = self.owner {
            let family = std::slice::from_ref(&self.file.families[owner]);
            let own = braced_instances(&text.value, family, self.indices)
                .find(|b| !self.names_other(b.family, &text.value[b.span.clone()]));
            if let Some(b) = own {
                let span = Span::new(b.span.start, b.span.end);
                let message = uses_itself_message(&family[0], &text.value[b.span]);
                return Err(text.error(source, ErrorKind::Family, span, message));
            }
        }
        // `P_{1}` does not parse, and `P_{m,2}` would be an unknown `P_`: the braces are the news.
        // Braces that are another name's LaTeX (`K_{x}` of a parameter `K_x`, `K_{1;2,3}` of
        // a family `K1`'s instance) are that name's, not a malformed instance of `K`.
        let other = |f: &super::Family, written: &str| self.names_other(f, written);
        if let Some((span, message)) = malformed_braces(&text.value, families, self.indices, &other)
        {
            return Err(text.error(source, ErrorKind::Family, span, message));
        }
        let rewritten = rewrite_braces(&text.value, families, self.indices);
        let vars = self.file.system.vars();
        let mut tree = Expr::parse_tree(vars, &rewritten, self)
            .map_err(|e| self.display_error(source, text, &e))?;
        self.read_latex_names(source, text, &mut tree)?;
        Ok(tree)
    }

    /// Whether `written`, braces after the name of `family` (`K_{x}`, `K_{1}`, `K_{1;2,3}`),
    /// is the LaTeX of a name other than an instance of it: a declared name (a parameter
    /// `K_x`, a function `K1` printed `K_{1}`) or an instance of another family (`K1`'s,
    /// `K_{1;2,3}`).
    fn names_other(&self, family: &super::Family, written: &str) -> bool {
        let Some(spelled) = trigpoly::syntax::latex_name(written) else {
            return false;
        };
        self.file.declares(&spelled)
            || self
                .latex_names(|n| n.names(&spelled, self.indices))
                .iter()
                .any(|name| !names_own_instance(family, name))
    }

    /// The declared name that `name` names (a variable by any of its spellings, a function
    /// by its name or display, `i`), if any: `p_theta` of `p_θ`, `Zbar` of `Z̄`.
    fn declared_as(&self, name: &str) -> Option<String> {
        let vars = self.file.system.vars();
        if name == "i" {
            return Some(name.to_string());
        }
        if let Some(v) = vars.lookup(name) {
            return Some(vars.variable(v).name().to_string());
        }
        (self.file.system.functions().iter())
            .find(|f| f.name == name || f.display == name)
            .map(|f| f.name.clone())
    }

    /// Renames each name of `tree` written in LaTeX to the name it is ([`Scope::latex_alias`]),
    /// so that the echo and the lowering see the system's names: `G_{1}` is `G1`. A name
    /// written as two names print is refused, naming both.
    fn read_latex_names(
        &self,
        source: &Source,
        text: &Text,
        tree: &mut Tree,
    ) -> Result<(), FileError> {
        let span = tree.span;
        match &mut tree.kind {
            ExprKind::Integer(_) => {}
            ExprKind::Name(name) => *name = self.latex_alias(source, text, name, span)?,
            ExprKind::Call(f, name_span, args) => match self.display_call(text, f, span) {
                Some(name) => tree.kind = ExprKind::Name(name),
                None => {
                    *f = self.latex_alias(source, text, f, *name_span)?;
                    for a in args {
                        self.read_latex_names(source, text, a)?;
                    }
                }
            },
            ExprKind::Neg(a) => self.read_latex_names(source, text, a)?,
            ExprKind::Add(a, b)
            | ExprKind::Sub(a, b)
            | ExprKind::Mul(a, b)
            | ExprKind::Div(a, b)
            | ExprKind::Pow(a, b)
            | ExprKind::Bracket(a, b) => {
                self.read_latex_names(source, text, a)?;
                self.read_latex_names(source, text, b)?;
            }
        }
        Ok(())
    }

    /// The error for `e`, or, where it falls on a function's display name written in the text
    /// (`Z̄`, `A_x`, `G1'`, `∂H²`, as the reports print it, or its LaTeX, `\partial H`,
    /// `\nabla\varphi`, as the LaTeX output does), one that names the function to write.
    fn display_error(&self, source: &Source, text: &Text, e: &ParseError) -> FileError {
        if !matches!(
            e.cause(),
            ParseCause::UnknownName { .. }
                | ParseCause::Unreadable
                | ParseCause::FunctionWithoutParentheses { .. }
        ) {
            return expression_error(source, text, e);
        }
        // The whole of a word (a coefficient may come before it, and a power after it): `Re A`,
        // `2Re A` and `∂H²`, not the start of `Re Ax`; a LaTeX form begins with its command
        // whatever stands before it, `x\partial H`. A name begins and goes on as the lexer
        // reads it.
        let word = |c: Option<char>| c.is_some_and(is_name_continue);
        let letter = |c: Option<char>| c.is_some_and(is_name_start);
        let value = &text.value;
        let written_at = |form: &str| {
            let at = (value.match_indices(form).map(|(k, _)| k)).find(|&k| {
                let end = k + form.len();
                k <= e.span.start
                    && e.span.start < end
                    && (form.starts_with('\\') || !letter(value[..k].chars().next_back()))
                    && !word(value[end..].chars().next())
            })?;
            Some(Span::new(at, at + form.len()))
        };
        let shown = self.file.system.functions().iter().find_map(|f| {
            if f.display == f.name || f.display.is_empty() {
                return None;
            }
            let latex = brackets::table::latex_name(&f.display);
            // The LaTeX as printed, `\nabla\varphi`, or with its commands apart.
            let spaced = latex.replace('\\', " \\").trim().to_string();
            for (form, printed) in [
                (&f.display, &f.display),
                (&latex, &latex),
                (&spaced, &latex),
            ] {
                if let Some(span) = written_at(form) {
                    return Some((span, printed.clone(), f));
                }
            }
            None
        });
        match shown {
            Some((span, form, f)) => text.error(
                source,
                ErrorKind::Expression,
                span,
                format!(
                    "'{form}' is how the function {} is printed; an expression names it {}",
                    f.name, f.name
                ),
            ),
            None => expression_error(source, text, e),
        }
    }

    /// Lowers a tree whose spans are in `text`.
    pub(crate) fn lower(
        &self,
        source: &Source,
        text: &Text,
        tree: &Tree,
    ) -> Result<Expr, FileError> {
        self.lower_with(source, text, tree, self)
    }

    /// [`Scope::lower`], reading names and brackets through `context`: this scope kept by a
    /// [`brackets::Recording`] of what the value is computed from.
    pub(crate) fn lower_with(
        &self,
        source: &Source,
        text: &Text,
        tree: &Tree,
        context: &impl Context<GaussianRational>,
    ) -> Result<Expr, FileError> {
        let prepared = self.prepare(source, text, tree)?;
        let value = Expr::from_expr(self.file.system.vars(), &prepared, context)
            .map_err(|e| self.display_error(source, text, &e));
        for noted in self.noted.take() {
            self.file.warn(self.warning(source, text, &noted));
        }
        value
    }

    /// The warning for a name of `text` run together and read as a product in doubt: its
    /// place, and the reading in the system's printed names (`L_x x`), with the advice to
    /// declare the name only where the system is a file's.
    fn warning(&self, source: &Source, text: &Text, noted: &trigpoly::RunTogether) -> Warning {
        Warning::run_together(
            &source.origin,
            &source.text,
            text.source_span(noted.span),
            noted,
            &|piece: &str| self.file.display_name(piece),
            // A system that is no file (built in code, or the command line's `--system`)
            // has nowhere to declare a name.
            self.file.source.given.about_file(),
        )
    }

    /// Expands family instances, checks brackets.
    fn prepare(&self, source: &Source, text: &Text, tree: &Tree) -> Result<Tree, FileError> {
        let span = tree.span;
        let vars = self.file.system.vars();
        let rec = |t: &Tree| self.prepare(source, text, t).map(Box::new);
        let kind = match &tree.kind {
            ExprKind::Name(name) => {
                self.make_instance(source, text, name, span)?;
                ExprKind::Name(name.clone())
            }
            // A name before parentheses multiplies them: a family instance there too (`K_1_1(x)`).
            ExprKind::Call(f, name_span, args) => {
                self.make_instance(source, text, f, *name_span)?;
                ExprKind::Call(
                    f.clone(),
                    *name_span,
                    args.iter()
                        .map(|a| self.prepare(source, text, a))
                        .collect::<Result<_, _>>()?,
                )
            }
            ExprKind::Bracket(a, b) => {
                for side in [a, b] {
                    if let ExprKind::Name(n) = &side.kind {
                        let parameter = vars
                            .lookup(n)
                            .is_some_and(|v| vars.variable(v).kind() == VarKind::Parameter);
                        if parameter {
                            return Err(text.error(
                                source,
                                ErrorKind::Expression,
                                side.span,
                                format!(
                                    "'{n}' is a parameter, not a variable of the phase space, so \
                                     every bracket with it is 0; declare it under coordinates or \
                                     angles if it is meant to be canonical"
                                ),
                            ));
                        }
                    }
                }
                ExprKind::Bracket(rec(a)?, rec(b)?)
            }
            ExprKind::Integer(n) => ExprKind::Integer(n.clone()),
            ExprKind::Neg(a) => ExprKind::Neg(rec(a)?),
            ExprKind::Add(a, b) => ExprKind::Add(rec(a)?, rec(b)?),
            ExprKind::Sub(a, b) => ExprKind::Sub(rec(a)?, rec(b)?),
            ExprKind::Mul(a, b) => ExprKind::Mul(rec(a)?, rec(b)?),
            ExprKind::Div(a, b) => ExprKind::Div(rec(a)?, rec(b)?),
            ExprKind::Pow(a, b) => ExprKind::Pow(rec(a)?, rec(b)?),
        };
        Ok(Tree { kind, span })
    }

    /// The name that `name`, at `span` of `text`, is: where it is written in LaTeX (braces, a
    /// command or a prime, `G_{1}`, `\bar{Z}`, `y'`), the declared name it spells or the one
    /// whose printed LaTeX spells it the same ([`LatexNames`]); else `name`. Where two names
    /// are so (a family `K1`'s instance `K_{1;2,3}` beside a parameter `K_1_2_3`, printed
    /// `K_{1,2,3}`; two names printed apart that LaTeX spells alike), it is neither: an error
    /// that names both, not a reading of one.
    fn latex_alias(
        &self,
        source: &Source,
        text: &Text,
        name: &str,
        span: Span,
    ) -> Result<String, FileError> {
        let written = text.value.get(span.start..span.end).unwrap_or("");
        if !written.contains(['\\', '{', '\'']) {
            return Ok(name.to_string());
        }
        let declared = self.declared_as(name);
        let mut meant: Vec<String> = declared.iter().cloned().collect();
        for other in self.latex_names(|names| names.names(name, self.indices)) {
            if !meant.contains(&other) {
                meant.push(other);
            }
        }
        match meant.as_slice() {
            [] => Ok(name.to_string()),
            [one] if declared.as_ref() == Some(one) => Ok(name.to_string()),
            [one] => Ok(one.clone()),
            [..] => {
                // Braces rewritten to a name (`K_{1,2}` read as `K_1_2`) are shown whole.
                let families = &self.file.families[..self.families];
                let span = braced_instances(&text.value, families, self.indices)
                    .find(|b| b.span.start == span.start)
                    .map_or(span, |b| Span::new(b.span.start, b.span.end));
                let written = &text.value[span.start..span.end];
                let shown: Vec<String> = meant.iter().map(|m| self.described(m)).collect();
                let (last, first) = shown.split_last().expect("two or more");
                let message = format!(
                    "'{written}' names both {} and {last} in LaTeX, whose printed forms read \
                     alike: write the one meant by its name, {}",
                    first.join(", "),
                    meant.join(" or ")
                );
                Err(text.error(source, ErrorKind::Expression, span, message))
            }
        }
    }

    /// What `name` is, in words: `the parameter K_1_2_3`, `the function G1`, `the instance
    /// K1_2_3 of the family K1`.
    fn described(&self, name: &str) -> String {
        let vars = self.file.system.vars();
        if let Some(v) = vars.lookup(name) {
            let var = vars.variable(v);
            return super::names::PrintedNames::whose_variable(var.kind(), var.name());
        }
        if let Some((k, ..)) = instance_of(&self.file.families, name) {
            return format!(
                "the instance {name} of the family {}",
                self.file.families[k].name
            );
        }
        format!("the function {name}")
    }

    /// The function whose display is the call `f(…)` written at `span` of `text` in LaTeX, as
    /// its display `x(t)` or `θ(t)` prints (`x(t)`, `\theta(t)`), where `f` is no declared
    /// name (before which parentheses multiply).
    fn display_call(&self, text: &Text, f: &str, span: Span) -> Option<String> {
        if self.file.declares(f) {
            return None;
        }
        let written: String = text
            .value
            .get(span.start..span.end)?
            .split_whitespace()
            .collect();
        self.latex_names(|names| match names.calls.get(&written)?.as_slice() {
            [one] => Some(one.clone()),
            _ => None,
        })
    }

    /// `read` of the system's names as their LaTeX spells them, made the first time.
    fn latex_names<R>(&self, read: impl FnOnce(&LatexNames) -> R) -> R {
        let mut latex = self.latex.borrow_mut();
        read(latex.get_or_insert_with(|| LatexNames::of(self.file)))
    }

    /// Expands `name` (at `span`) if it is an instance of a family this scope sees, for the
    /// lowering to find; refuses the family whose text this is, a family declared later and a
    /// malformed instance. Any other
    /// name is left to the lowering.
    fn make_instance(
        &self,
        source: &Source,
        text: &Text,
        name: &str,
        span: Span,
    ) -> Result<(), FileError> {
        if self.file.declares(name) {
            return Ok(());
        }
        if let Some(family) = self.owner.map(|k| &self.file.families[k]) {
            if names_own_instance(family, name) {
                return Err(text.error(
                    source,
                    ErrorKind::Family,
                    span,
                    uses_itself_message(family, name),
                ));
            }
        }
        if let Some((k, m, n)) = instance_of(&self.file.families, name) {
            if k >= self.families {
                let f = &self.file.families[k];
                return Err(text.error(
                    source,
                    ErrorKind::Family,
                    span,
                    format!(
                        "the family '{}' cannot be used here: a family may only use families \
                         declared before it, and a function none",
                        f.name
                    ),
                ));
            }
            let e = self.expand(k, m, n, source, || text.source_span(span))?;
            self.made.borrow_mut().insert(name.to_string(), e);
        } else if let Some(base) = barred_instance(&self.file.families, name) {
            // A bar over an instance whose bar family the file does not declare
            // (`\bar{P}_{3,2}`): the instance is made, for the lowering to say that its
            // conjugate is written conj(P_3_2), as of a barred function.
            return self.make_instance(source, text, &base, span);
        } else if let Some(family) = meant_family(&self.file.families, name)
            // In a family's own text, what is no instance of it (`K_b_1_2` in `K`'s) is left
            // to the lowering: it may be one of a family declared later.
            .filter(|f| {
                self.owner
                    .is_none_or(|k| f.name != self.file.families[k].name)
            })
        {
            // Braces rewritten to a name (`K_{1,99999999999}` read as `K_1_99999999999`) are
            // shown as written, over their whole width.
            let families = &self.file.families[..self.families];
            let braced = braced_instances(&text.value, families, self.indices)
                .find(|b| b.span.start == span.start);
            let (span, written) = match braced {
                Some(b) => (Span::new(b.span.start, b.span.end), &text.value[b.span]),
                None => (span, name),
            };
            let message = oversized_index_message(family, name, written)
                .unwrap_or_else(|| malformed_instance_message(family, written));
            return Err(text.error(source, ErrorKind::Family, span, message));
        }
        Ok(())
    }

    /// The instance `(m, n)` of family `k`, expanded in a scope that sees the families before
    /// it; an error is reported at `used_at` in `source` (where the instance is used, asked
    /// only for an error), with the place of the family in the hint.
    pub(crate) fn expand(
        &self,
        k: usize,
        m: i64,
        n: i64,
        source: &Source,
        used_at: impl FnOnce() -> std::ops::Range<usize>,
    ) -> Result<Expr, FileError> {
        if let Some(e) = self.cache().get(&(k, m, n)) {
            return Ok(e.clone());
        }
        let family = &self.file.families[k];
        match self.file.compute_instance(k, m, n) {
            Ok(e) => {
                self.cache().insert((k, m, n), e.clone());
                Ok(e)
            }
            Err(inner) => {
                let used_at = used_at();
                if used_at.is_empty() {
                    return Err(inner);
                }
                let at = inner
                    .location
                    .as_ref()
                    .map(|l| format!("{}:{}:{}", inner.origin, l.line, l.column))
                    .unwrap_or_else(|| inner.origin.clone());
                let hint = match &inner.hint {
                    Some(h) => format!("{}'s value is at {at}; {h}", family.name),
                    None => format!("{}'s value is at {at}", family.name),
                };
                Err(source
                    .error(
                        inner.kind,
                        used_at,
                        format!(
                            "cannot expand {}_{{{m},{n}}}: {}",
                            family.name, inner.message
                        ),
                    )
                    .with_hint(hint))
            }
        }
    }

    fn cache(&self) -> std::sync::MutexGuard<'_, HashMap<(usize, i64, i64), Expr>> {
        self.file
            .cache
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }
}

impl LoadedSystem {
    /// The instance `(m, n)` of family `k`, computed (not cached), in a scope that sees the
    /// families before it.
    /// What it was computed from is kept ([`LoadedSystem::computed_from`]).
    pub(crate) fn compute_instance(&self, k: usize, m: i64, n: i64) -> Result<Expr, FileError> {
        let family = &self.families[k];
        let (value, inputs) = self.family_text_recorded(k, &family.value, m, n)?;
        self.keep_computed_from(format!("{}_{m}_{n}", family.name), inputs);
        Ok(value)
    }

    /// What the value of the function or family instance `name` was computed from: the
    /// functions, instances and declared brackets its text used, and what those were computed
    /// from, each of which must have a value where the function has one. Empty for a name
    /// whose value was given as an expression ([`LoadedSystem::add_function_expr`]).
    pub(crate) fn computed_from(&self, name: &str) -> Vec<Input> {
        let key = match instance_of(&self.families, name) {
            Some((k, m, n)) => format!("{}_{m}_{n}", self.families[k].name),
            None => name.to_string(),
        };
        let kept = self.computed_from.lock();
        let kept = kept.unwrap_or_else(std::sync::PoisonError::into_inner);
        kept.get(&key).cloned().unwrap_or_default()
    }

    /// Keeps what the value of `name` was computed from ([`LoadedSystem::computed_from`]).
    pub(crate) fn keep_computed_from(&self, name: String, inputs: Vec<Input>) {
        let kept = self.computed_from.lock();
        let mut kept = kept.unwrap_or_else(std::sync::PoisonError::into_inner);
        kept.insert(name, inputs);
    }

    /// A text of family `k` (its value or its eigenvalue) at `(m, n)`.
    pub(crate) fn family_text_at(
        &self,
        k: usize,
        text: &Text,
        m: i64,
        n: i64,
    ) -> Result<Expr, FileError> {
        Ok(self.family_text_recorded(k, text, m, n)?.0)
    }

    /// [`LoadedSystem::family_text_at`], with what the value was computed from
    /// ([`Scope::recording`]).
    fn family_text_recorded(
        &self,
        k: usize,
        text: &Text,
        m: i64,
        n: i64,
    ) -> Result<(Expr, Vec<Input>), FileError> {
        let family = &self.families[k];
        let scope = Scope::of_family(self, k);
        let tree = scope.tree(&family.source, text)?;
        let tree = substitute(&tree, &family.indices, [m, n], &self.families[..k]);
        let recording = scope.recording();
        let value = scope.lower_with(&family.source, text, &tree, &recording)?;
        Ok((value, recording.into_inputs()))
    }
}

impl Context<GaussianRational> for Scope<'_> {
    fn lookup(&self, name: &str) -> Option<Expr> {
        match self.file.system.get(name) {
            Ok(e) => Some(e.clone()),
            Err(_) => self.made.borrow().get(name).cloned(),
        }
    }

    fn bracket(&self, f: &Expr, g: &Expr) -> Result<Expr, trigpoly::BracketError> {
        self.file
            .system
            .bracket(f, g)
            .map_err(trigpoly::BracketError::from)
    }

    // Each place once: `LoadedSystem::warn` keeps a warning once, so a reading noted again
    // (the lowering may meet a name twice) is dropped there.
    fn run_together(&self, noted: trigpoly::RunTogether) {
        self.noted.borrow_mut().push(noted);
    }

    fn names(&self) -> Vec<String> {
        let mut names: Vec<String> = self
            .file
            .system
            .functions()
            .iter()
            .map(|f| f.name.clone())
            .collect();
        names.extend(
            self.file.families[..self.families]
                .iter()
                .map(|f| format!("{}_{}_{}", f.name, f.indices[0], f.indices[1])),
        );
        names
    }
}

/// Where `tree` has its first bracket `{f, g}`, if it has one.
pub(crate) fn first_bracket(tree: &Tree) -> Option<Span> {
    match &tree.kind {
        ExprKind::Integer(_) | ExprKind::Name(_) => None,
        ExprKind::Bracket(..) => Some(tree.span),
        ExprKind::Neg(a) => first_bracket(a),
        ExprKind::Call(_, _, args) => args.iter().find_map(first_bracket),
        ExprKind::Add(a, b)
        | ExprKind::Sub(a, b)
        | ExprKind::Mul(a, b)
        | ExprKind::Div(a, b)
        | ExprKind::Pow(a, b) => first_bracket(a).or_else(|| first_bracket(b)),
    }
}

/// The span of the first use of `name` in a tree, if any.
pub(crate) fn mention(tree: &Tree, name: &str) -> Option<Span> {
    tree.names()
        .into_iter()
        .find_map(|(n, span)| (n == name).then_some(span))
}

#[cfg(test)]
mod tests {
    use trigpoly::AlgebraError;

    use super::*;

    /// An exponent past the most `max_degree` may be set to gets no advice to raise it, and
    /// the hint names that most.
    #[test]
    fn an_exponent_past_every_limit_is_not_advised_to_raise_one() {
        let written = |power: Option<u64>| ParseCause::PowerPastLimit { power, limit: 1000 };
        let limit_hint = |cause: ParseCause| {
            Limit::of_parse(&cause)
                .and_then(|limit| limit.hint(LimitSettings::File))
                .unwrap()
        };
        let raise = limit_hint(written(Some(5000)));
        assert!(raise.contains("raise the limit with max_degree under [limits]"));
        // 32768, 99999999999999999999 (no 64-bit number), -9223372036854775808.
        for power in [Some(32768), None, Some(9_223_372_036_854_775_808)] {
            let hint = limit_hint(written(power));
            assert!(
                hint.starts_with("no limit reaches this exponent"),
                "{power:?}"
            );
            assert!(hint.contains(&MAX_DEGREE_CEILING.to_string()));
        }
        assert_eq!(limit_hint(written(Some(32767))), raise);
        // A radical's power `p/2` is bounded by its `p`: the parser gives `p` as its size.
        for (text, past) in [
            ("x^(99999999/2)", true),
            ("x^(-65535/2)", true),
            ("x^(32767/2)", false),
        ] {
            let vars = trigpoly::Vars::builder()
                .coordinate("x")
                .limits(trigpoly::Limits::default().max_degree(1000))
                .build()
                .unwrap();
            let e = Expr::parse(&vars, text).unwrap_err();
            let hint = limit_hint(e.cause().clone());
            assert_eq!(
                hint.starts_with("no limit reaches this exponent"),
                past,
                "{text}"
            );
        }
        // The other forms of the limit errors, each past every limit or not: the exponent of
        // x would reach 40000 (2000), past the limit of 32767 (1000); the multiple -32768
        // (2000) of θ, or of 1000001 bits, is past the limit of 1000; the trigonometric order
        // in θ would reach 32768 (8000), past the limit of 32767 (7999).
        let exponent = |exponent: i64| {
            ParseCause::Algebra(AlgebraError::ExponentTooLarge {
                var: "x".into(),
                exponent,
                limit: 1000,
            })
        };
        let order = |order: u64| {
            ParseCause::Algebra(AlgebraError::OrderTooLarge {
                angle: "θ".into(),
                order,
                limit: 7999,
            })
        };
        for (cause, past) in [
            (exponent(40000), true),
            (exponent(2000), false),
            (written(Some(32768)), true),
            (written(Some(2000)), false),
            (written(None), true),
            (order(32768), true),
            (order(8000), false),
        ] {
            let hint = limit_hint(cause.clone());
            assert_eq!(hint.starts_with("no limit reaches"), past, "{cause:?}");
            assert_eq!(hint == raise, !past, "{cause:?}");
        }
    }

    #[test]
    fn braces_of_family_instances_are_rewritten_in_place() {
        let fam = super::super::Family {
            name: "K".into(),
            display: "K".into(),
            indices: ["m".into(), "n".into()],
            value: Text::whole(&Source::new("t", "Z")),
            eigenvalue: None,
            span: 0..0,
            source: Source::new("t", "Z"),
        };
        let s = "{K_{2, 3}, H} + L_{1,1}";
        let r = rewrite_braces(s, std::slice::from_ref(&fam), &[]);
        assert_eq!(r, "{K_2_3   , H} + L_{1,1}");
        assert_eq!(r.len(), s.len());
        assert_eq!(instance_of(&[fam], "K_2_3"), Some((0, 2, 3)));
    }

    #[test]
    fn a_momentum_in_a_name_of_its_own_is_shown_the_momenta() {
        let unknown = |name: &str, known: &[&str]| {
            Unknown::of(&ParseCause::UnknownName {
                name: name.into(),
                known: known.iter().map(|k| k.to_string()).collect(),
            })
            .unwrap()
        };
        let known = ["q1", "q2", "p_q1", "p_q2", "H"];
        let hint = |name: &str| momentum_hint(&unknown(name, &known));
        let shown = "the momentum of a coordinate or an angle `q` is named `p_q`: here p_q1, p_q2";
        for name in ["p_1", "p_x", "p1", "p12"] {
            assert_eq!(hint(name).as_deref(), Some(shown), "{name}");
        }
        for name in ["phi", "p", "P_1", "q3", "pq1x2"] {
            assert_eq!(hint(name), None, "{name}");
        }
        // No momenta to show.
        assert_eq!(momentum_hint(&unknown("p_1", &["omega", "H"])), None);
        // A bare `p` is shown the momenta and the square of the momentum.
        assert!(
            bare_momentum_hint(&unknown("p", &known)).is_some_and(|h| h.starts_with(
                "the momenta are named after their coordinates, here p_q1, p_q2 (|p|² is \
                 p_q1^2 + p_q2^2); a constant"
            ))
        );
        assert_eq!(bare_momentum_hint(&unknown("p", &["omega", "H"])), None);
        assert_eq!(bare_momentum_hint(&unknown("q", &known)), None);
        // A distance is shown with its name, and a name past MAX_NAME_CHARS as the message
        // shows it, by its start, which is no distance.
        assert!(distance_hint(&unknown("r12", &known)).is_some_and(|h| h.contains("r12 = √")));
        let long = format!("r{}", "1".repeat(100));
        assert_eq!(distance_hint(&unknown(&long, &known)), None);
        // The cause of a real parse, whose message suggests a name before the known ones.
        let vars = trigpoly::Vars::builder()
            .coordinate("q1")
            .momentum("p_q1")
            .build()
            .unwrap();
        let e = Expr::parse(&vars, "p_1").unwrap_err();
        assert_eq!(
            e.message(),
            "unknown name 'p_1'; did you mean 'p_q1'? (known: q1, p_q1)"
        );
        let meant = Unknown::of(e.cause()).unwrap();
        assert!(momentum_hint(&meant).is_some_and(|h| h.ends_with("here p_q1")));
    }
}
