//! Loading a system file: bytes → text (no binary, no empty file) → the TOML model → variables
//! with their limits, phase space, Hamiltonian, functions, families and claims, each checked
//! where it is written.

use std::collections::HashMap;
use std::ops::Range;
use std::path::Path;
use std::sync::Mutex;

use brackets::{EngineError, PhaseSpace, System};
use toml::Spanned;
use trigpoly::{
    display_forms, is_identifier, latex_unwritable, unbarred, AlgebraError, Expr, Limits, Span,
    Var, VarSet, VarSetBuilder, Vars, LATEX_LETTERS, RESERVED,
};

use super::claims::ClaimSpec;
use super::error::{locate_bytes, ErrorKind, FileError};
use super::model::{ExpectShape, FunctionModel, ShapeModel, StringTable, SystemModel};
use super::scope::{first_bracket, mention};
use super::text::{Source, Text};
use super::{Family, LimitsOverride, LoadedSystem};

/// The largest degree limit a file or the command line may set (what a 16-bit exponent field
/// holds; the packing widens its fields as the limit asks).
const MAX_DEGREE_CEILING: u32 = 32_767;

/// Why a letter cannot be in a name or a display name, when LaTeX output could not write it
/// ([`latex_unwritable`]): `LaTeX has no letter 'é' (…)`; a character other than a letter (a
/// mark over a letter, a sign, one that prints nothing) is said by its code point.
pub fn unwritable_letter(c: char) -> Option<String> {
    latex_unwritable(c.encode_utf8(&mut [0; 4]))?;
    Some(match c.is_alphabetic() {
        true => format!("LaTeX has no letter '{c}' ({LATEX_LETTERS})"),
        false => format!("LaTeX has no letter U+{:04X} ({LATEX_LETTERS})", c as u32),
    })
}

/// Whether `c` shows nothing, or moves or turns the text around it: a control character
/// (a tab), white space other than the space (no-break, line separator), or a format character
/// (zero width, the bidirectional marks and overrides, a byte-order mark, variation selectors).
fn invisible(c: char) -> bool {
    c.is_control()
        || (c.is_whitespace() && c != ' ')
        || matches!(
            c,
            '\u{ad}'
                | '\u{34f}'
                | '\u{61c}'
                | '\u{115f}'
                | '\u{1160}'
                | '\u{17b4}'
                | '\u{17b5}'
                | '\u{180b}'..='\u{180f}'
                | '\u{200b}'..='\u{200f}'
                | '\u{202a}'..='\u{202e}'
                | '\u{2060}'..='\u{206f}'
                | '\u{3164}'
                | '\u{fe00}'..='\u{fe0f}'
                | '\u{feff}'
                | '\u{ffa0}'
                | '\u{fff0}'..='\u{fffb}'
                | '\u{1bca0}'..='\u{1bca3}'
                | '\u{1d173}'..='\u{1d17a}'
                | '\u{e0000}'..='\u{e0fff}'
        )
}

/// Why a name cannot name anything new, whatever the system has: each caller says it in its
/// own words (`'2Q' cannot name a function: …`, `--define '2Q': …`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BadName {
    /// Not letters, digits and `_` starting with a letter or `_`.
    Malformed,
    /// A letter LaTeX output could not write, and why ([`unwritable_letter`]).
    Unwritable(String),
    /// A reserved name, and why ([`reserved`]).
    Reserved(String),
}

impl BadName {
    /// The first reason `name` is refused, if any: malformed, unwritable, reserved.
    pub fn of(name: &str) -> Option<BadName> {
        if !is_identifier(name) {
            Some(BadName::Malformed)
        } else if let Some(why) = latex_unwritable(name).and_then(unwritable_letter) {
            Some(BadName::Unwritable(why))
        } else {
            reserved(name).map(BadName::Reserved)
        }
    }

    /// The message for declaring `name` as `what` (`a function`): `'2Q' cannot name a
    /// function: a name is …`; a reserved name's reason says it alone.
    pub fn declaring(&self, name: &str, what: &str) -> String {
        match self {
            BadName::Reserved(why) => why.clone(),
            _ => format!("'{name}' cannot name {what}: {}", self.why()),
        }
    }

    /// The reason in words: `a name is letters, …`, `LaTeX has no letter 'é' (…)`, `'H' is
    /// reserved for the Hamiltonian`.
    pub fn why(&self) -> &str {
        match self {
            BadName::Malformed => {
                "a name is letters, digits and '_', starting with a letter or '_'"
            }
            BadName::Unwritable(why) | BadName::Reserved(why) => why,
        }
    }
}

/// Why a family's two indices are refused, if they are: the index at fault, the kind of error
/// and the message. `taken` says what already has a name, in the words after "is already"
/// (`declared as a coordinate`).
pub(super) fn index_refusal(
    indices: [&str; 2],
    taken: impl Fn(&str) -> Option<String>,
) -> Option<(usize, ErrorKind, String)> {
    for (k, idx) in indices.into_iter().enumerate() {
        let refusal = if !is_identifier(idx) || idx.contains('_') || idx == "i" {
            Some((
                ErrorKind::Family,
                format!("'{idx}' cannot name an index: use a plain name such as m or n"),
            ))
        } else if let Some(why) = latex_unwritable(idx).and_then(unwritable_letter) {
            Some((
                ErrorKind::Name,
                format!("'{idx}' cannot name an index: {why}"),
            ))
        } else if let Some(other) = taken(idx) {
            Some((
                ErrorKind::Family,
                format!("the index '{idx}' is already {other}"),
            ))
        } else if k == 1 && indices[0] == idx {
            Some((
                ErrorKind::Family,
                format!("the two indices are both named '{idx}'"),
            ))
        } else {
            None
        };
        if let Some((kind, message)) = refusal {
            return Some((k, kind, message));
        }
    }
    None
}

/// Why `name` cannot be declared whatever the system: `'cos' is reserved (i, cos, …)`,
/// `'H' is reserved for the Hamiltonian`; `None` for a name that is free of meaning.
pub fn reserved(name: &str) -> Option<String> {
    if RESERVED.contains(&name) || name == "rank" {
        Some(format!(
            "'{name}' is reserved (i, cos, sin, exp, conj, re, im, rank)"
        ))
    } else if name == "H" {
        Some("'H' is reserved for the Hamiltonian".into())
    } else {
        None
    }
}

/// Reads and loads a system file. Every problem is a [`FileError`] naming the file, line and
/// column.
pub fn load(path: &Path, limits: &LimitsOverride) -> Result<LoadedSystem, FileError> {
    let origin = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| {
        FileError::new(ErrorKind::Io, &origin, format!("cannot read the file: {e}"))
    })?;
    load_bytes(&origin, &bytes, limits)
}

/// Loads a system file from its bytes; `origin` names it in messages.
pub fn load_bytes(
    origin: &str,
    bytes: &[u8],
    limits: &LimitsOverride,
) -> Result<LoadedSystem, FileError> {
    if let Some(k) = bytes.iter().position(|&b| b == 0) {
        return Err(FileError {
            location: Some(Box::new(locate_bytes(bytes, k))),
            ..FileError::new(
                ErrorKind::NotText,
                origin,
                "this is a binary file (it contains a NUL byte), not a TOML system file",
            )
        });
    }
    let text = std::str::from_utf8(bytes).map_err(|e| {
        let k = e.valid_up_to();
        FileError {
            location: Some(Box::new(locate_bytes(bytes, k))),
            ..FileError::new(
                ErrorKind::NotText,
                origin,
                format!(
                    "the file is not UTF-8 text (byte 0x{:02X} is not valid UTF-8); a system \
                     file is a UTF-8 TOML file",
                    bytes[k]
                ),
            )
        }
    })?;
    load_str(origin, text, limits)
}

/// Loads a system file from its text; `origin` names it in messages.
pub fn load_str(
    origin: &str,
    text: &str,
    limits: &LimitsOverride,
) -> Result<LoadedSystem, FileError> {
    let source = Source::new(origin, text);
    if text.trim_start_matches('\u{feff}').trim().is_empty() {
        return Err(source
            .error(
                ErrorKind::Empty,
                0..0,
                "the file is empty: a system file declares at least `hamiltonian` and \
                 [phase_space]",
            )
            .with_hint("see docs/system-files.md for a complete example"));
    }
    check_shape(&source, text)?;
    let model: SystemModel = toml::from_str(text).map_err(|e| toml_error(&source, &e))?;
    Builder::new(source, limits).build(model)
}

/// The kind of a TOML value, in words.
fn toml_kind(v: &toml::Value) -> &'static str {
    match v {
        toml::Value::String(_) => "a string",
        toml::Value::Integer(_) => "an integer",
        toml::Value::Float(_) => "a decimal number",
        toml::Value::Boolean(_) => "true or false",
        toml::Value::Datetime(_) => "a date",
        toml::Value::Array(_) => "an array",
        toml::Value::Table(_) => "a table",
    }
}

/// Refuses top-level values of the wrong shape, where serde would read them anyway or say so
/// in its own words: the text keys are strings, `[phase_space]` and `[limits]` tables,
/// `[[function]]`, `[[family]]` and `[[claim]]` arrays of tables.
fn check_shape(source: &Source, text: &str) -> Result<(), FileError> {
    // A file that does not parse as TOML, or misses a key, is left to the reading proper,
    // which says where.
    let Ok(shape) = toml::from_str::<ShapeModel>(text) else {
        return Ok(());
    };
    let wrong_at = |span: Range<usize>, value: &toml::Value, key: &str, wanted: &str| {
        source.error(
            ErrorKind::Schema,
            span,
            format!("{key} is {wanted}, not {}", toml_kind(value)),
        )
    };
    let wrong = |v: &Spanned<toml::Value>, key: &str, wanted: &str| {
        wrong_at(v.span(), v.get_ref(), key, wanted)
    };
    for (key, value) in [
        ("name", &shape.name),
        ("source", &shape.source),
        ("description", &shape.description),
        ("hamiltonian", &shape.hamiltonian),
    ] {
        if let Some(v) = value.as_ref().filter(|v| !v.get_ref().is_str()) {
            return Err(wrong(v, key, "a string in quotes"));
        }
    }
    for (key, value) in [
        ("[phase_space]", &shape.phase_space),
        ("[limits]", &shape.limits),
        ("[poisson]", &shape.poisson),
    ] {
        if let Some(v) = value.as_ref().filter(|v| !v.get_ref().is_table()) {
            return Err(wrong(v, key, "a table, written with one pair of brackets")
                .with_hint(format!("write {key} on a line of its own, then its keys")));
        }
    }
    for (key, value) in [
        ("[[function]]", &shape.function),
        ("[[family]]", &shape.family),
        ("[[claim]]", &shape.claim),
    ] {
        let hint = format!("write {key} on a line of its own before each one's keys");
        let Some(list) = value else { continue };
        let Some(items) = list.get_ref().as_array() else {
            return Err(wrong(
                list,
                key,
                "an array of tables, each written with two pairs of brackets",
            )
            .with_hint(hint));
        };
        if let Some(item) = items.iter().find(|v| !v.is_table()) {
            return Err(
                wrong_at(list.span(), item, &format!("each {key}"), "a table").with_hint(hint),
            );
        }
    }
    if let Ok(claims) = toml::from_str::<ExpectShape>(text) {
        let expects = claims.claim.iter().filter_map(|c| c.expect.as_ref());
        if let Some(v) = expects.into_iter().find(|v| !v.get_ref().is_str()) {
            return Err(wrong(v, "expect", "\"proved\" or \"refuted\""));
        }
    }
    Ok(())
}

/// A TOML error (syntax, or a missing, unknown or mistyped field) at its place.
fn toml_error(source: &Source, e: &toml::de::Error) -> FileError {
    let message = e
        .message()
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("; ");
    let schema = [
        "missing field",
        "unknown field",
        "invalid type",
        "invalid value",
        "unknown variant",
        "invalid length",
    ]
    .iter()
    .any(|p| message.starts_with(p));
    let kind = if schema {
        ErrorKind::Schema
    } else {
        ErrorKind::Toml
    };
    let span = e.span().unwrap_or(0..0);
    let message = if message.starts_with("missing field") {
        format!("{message} (see docs/system-files.md for every field)")
    } else if let Some(wanted) = message.strip_prefix("invalid type: map, expected ") {
        // A date is read as a map: said as a date, of its key, as at the top level.
        match date_at(&source.text, &span) {
            Some((key, false)) => format!("{key} is {}, not a date", in_words(wanted)),
            Some((key, true)) => {
                format!("each of {key} is {}, not a date", in_words(wanted))
            }
            None => message,
        }
    } else {
        message
    };
    source.error(kind, span, message)
}

/// The key of the date at `span` in the TOML document `text`, and whether it is an element of
/// that key's array (`coordinates = [1979-05-27]`); `None` where no date is.
fn date_at(text: &str, span: &Range<usize>) -> Option<(String, bool)> {
    fn find(
        key: &str,
        value: &Spanned<toml::de::DeValue<'_>>,
        span: &Range<usize>,
        in_array: bool,
    ) -> Option<(String, bool)> {
        match value.get_ref() {
            toml::de::DeValue::Datetime(_) if value.span() == *span => {
                Some((key.to_string(), in_array))
            }
            toml::de::DeValue::Array(items) => {
                items.iter().find_map(|item| find(key, item, span, true))
            }
            toml::de::DeValue::Table(table) => table
                .iter()
                .find_map(|(k, v)| find(k.get_ref(), v, span, false)),
            _ => None,
        }
    }
    let document = toml::de::DeTable::parse(text).ok()?;
    document
        .get_ref()
        .iter()
        .find_map(|(k, v)| find(k.get_ref(), v, span, false))
}

/// What serde expected, in the words of a system file's messages: `a string` is `a string in
/// quotes`, an unsigned integer `a whole number`, a sequence `an array`.
fn in_words(expected: &str) -> &str {
    match expected {
        "a string" => "a string in quotes",
        "u8" | "u16" | "u32" | "u64" | "usize" => "a whole number",
        "a sequence" => "an array",
        other => other,
    }
}

struct Builder<'a> {
    source: Source,
    limits: &'a LimitsOverride,
    /// Every declared name: what it is (`an angle`) and where.
    names: HashMap<String, (&'static str, Range<usize>)>,
    /// How each variable and function is printed, in text and in LaTeX.
    shown: PrintedNames,
}

/// A notation a name is printed in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Notation {
    Text,
    Latex,
}

/// Why [`PrintedNames::admit`] refuses a new name, in words (its `Display`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Refusal {
    /// The printer writes a product of one-letter variables as the name (`Mx` for `M x`),
    /// which would read back as the function.
    Product(String),
    /// The name's display prints, in text or in LaTeX, as another name of the system does.
    Alike(String),
}

impl std::fmt::Display for Refusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Refusal::Product(why) | Refusal::Alike(why) => f.write_str(why),
        }
    }
}

/// How the names of a system print, in text and in LaTeX, so that a new function (of a file,
/// of a program, or a generator given on the command line) that would print as one of them
/// is refused ([`PrintedNames::admit`]): its tables and equations would show two things alike
/// (`G_1` and a parameter `G1`, both `G_{1}` in LaTeX; a function `B` shown as `A` beside a
/// function `A`), or a product would print as its name (`Mx` beside `M` and `x`). The loader
/// checks a file's functions so, [`LoadedSystem::add_function`] a program's, and the command
/// line its `--define`d generators.
///
/// ```
/// use superint::system_file::{PrintedNames, Refusal};
///
/// let rotor = superint::brackets::systems::harmonic_rotor();
/// let mut printed = PrintedNames::of(&rotor);
/// assert_eq!(
///     printed.admit("the function F_1", "F_1", "F_1").unwrap_err().to_string(),
///     "the function F_1 would print as F_{1} in LaTeX, as the function F1 does"
/// );
/// let product = printed.admit("the function Mx", "Mx", "Mx").unwrap_err();
/// assert!(matches!(product, Refusal::Product(_)), "{product}");
/// assert!(printed.admit("the function C", "C", "C").is_ok());
/// assert!(matches!(printed.admit("the function D", "D", "C"), Err(Refusal::Alike(_))));
/// ```
#[derive(Clone, Debug, Default)]
pub struct PrintedNames {
    /// For each form, whose it is (`the parameter M1`, `the function Gx`) and, for a file's
    /// function, the line of its name or display.
    forms: HashMap<(Notation, String), (String, Option<usize>)>,
    /// The variables whose products the printer writes side by side, when their set was built
    /// without the new names (not a file's, whose set names its functions).
    vars: Option<Vars>,
}

impl PrintedNames {
    /// The forms of the variables of `vars`.
    fn of_variables(vars: &VarSet) -> Self {
        let mut printed = PrintedNames::default();
        for v in vars.vars() {
            let v = vars.variable(v);
            // `a coordinate` → `the coordinate x1`.
            let kind = v.kind().described().split_once(' ').map_or("", |k| k.1);
            let whose = format!("the {kind} {}", v.name());
            for form in [(Notation::Text, v.unicode()), (Notation::Latex, v.latex())] {
                printed
                    .forms
                    .insert((form.0, form.1.to_string()), (whose.clone(), None));
            }
        }
        printed
    }

    /// How the variables and the named functions of `system` print.
    pub fn of(system: &System) -> Self {
        let mut printed = PrintedNames::of_variables(system.vars());
        for f in system.functions() {
            let whose = format!("the function {}", f.name);
            // Each function was admitted beside the others: none is refused here.
            let _ = printed.admit_display(&whose, &f.display, None);
        }
        printed.vars = Some(system.vars().clone());
        printed
    }

    /// Takes a new function `name` shown as `display`, `whose` it is (`the function Gx`, `the
    /// generator C`), unless the printer could write one of them for a product of one-letter
    /// variables ([`VarSet::juxtaposition_spells`]), or `display` prints, in text or in LaTeX,
    /// as a name already taken: then why, in words (`the function B would show as A, as the
    /// function A does`), to which each caller adds what to do.
    pub fn admit(&mut self, whose: &str, name: &str, display: &str) -> Result<(), Refusal> {
        if let Some(vars) = &self.vars {
            for written in [name, display] {
                let text = display_forms(written).map_or_else(|| written.to_string(), |f| f.0);
                if vars.juxtaposition_spells(&text) {
                    let letters: Vec<String> = text.chars().map(String::from).collect();
                    return Err(Refusal::Product(format!(
                        "{whose} would read back from the product {} of the variables, which \
                         prints as {text}",
                        letters.join(" ")
                    )));
                }
            }
        }
        self.admit_display(whose, display, None)
            .map_err(Refusal::Alike)
    }

    /// How the variables, the named functions and the families of `file` print.
    pub(crate) fn of_loaded(file: &LoadedSystem) -> Self {
        let mut printed = PrintedNames::of(&file.system);
        for f in &file.families {
            // Each family was admitted beside the others: none is refused here.
            let _ = printed.admit_family(&format!("the family {}", f.name), &f.display, None);
        }
        printed
    }

    /// Takes a family shown as `display`, whose instances print as `display` with their
    /// indices (`K_{2,3}`), unless another family's print so, in text or in LaTeX: then why
    /// (`the family T would show its instances as K_{m,n}, as the family K does`).
    pub(crate) fn admit_family(
        &mut self,
        whose: &str,
        display: &str,
        line: Option<usize>,
    ) -> Result<(), String> {
        self.admit_forms(whose, display, line, "_{m,n}")
    }

    /// Takes the forms of `display`, `whose` they are, declared on `line` if it has one, unless
    /// a name already prints so: then why (`the function B would show as A, as the function A
    /// on line 9 does`). A display without such forms (refused elsewhere) is taken as it is.
    fn admit_display(
        &mut self,
        whose: &str,
        display: &str,
        line: Option<usize>,
    ) -> Result<(), String> {
        self.admit_forms(whose, display, line, "")
    }

    /// Takes the forms of `display` followed by `indices` (a family's instances; no
    /// function's display has braces, so that those forms are the families' alone), `whose`
    /// they are, declared on `line` if it has one, unless a name already has one of them: then
    /// why, in words.
    fn admit_forms(
        &mut self,
        whose: &str,
        display: &str,
        line: Option<usize>,
        indices: &str,
    ) -> Result<(), String> {
        let Some((text, latex)) = display_forms(display) else {
            return Ok(());
        };
        let forms = [
            (Notation::Text, format!("{text}{indices}")),
            (Notation::Latex, format!("{latex}{indices}")),
        ];
        for key in &forms {
            if let Some((other, at)) = self.forms.get(key) {
                let place = at.map(|l| format!(" on line {l}")).unwrap_or_default();
                let how = match (key, indices.is_empty()) {
                    ((Notation::Text, form), true) => format!("show as {form}"),
                    ((Notation::Latex, form), true) => format!("print as {form} in LaTeX"),
                    ((Notation::Text, form), false) => format!("show its instances as {form}"),
                    ((Notation::Latex, _), false) => {
                        format!("print its instances in LaTeX as {latex} with their indices")
                    }
                };
                return Err(format!("{whose} would {how}, as {other}{place} does"));
            }
        }
        for key in forms {
            self.forms.insert(key, (whose.to_string(), line));
        }
        Ok(())
    }
}

impl<'a> Builder<'a> {
    /// Refuses a display name that would not show as written: empty, beginning or ending with
    /// a space, with a character that is markup in Markdown or LaTeX (`a^b^c` stopped pdflatex,
    /// `L|x` split a Markdown table's cells), one that is invisible or a control (a tab, the
    /// right-to-left override U+202E, which turns the text after it around), or a subscript
    /// `_` of nothing (`a_`, `a__b`: LaTeX `a__{b}` stops pdflatex). The message points at
    /// the character.
    fn check_display(&self, display: &Spanned<String>) -> Result<(), FileError> {
        check_display(&self.source, &self.text(display), display.span())
    }

    fn new(source: Source, limits: &'a LimitsOverride) -> Self {
        Builder {
            source,
            limits,
            names: HashMap::new(),
            shown: PrintedNames::default(),
        }
    }

    /// Refuses a function printed as a variable or an earlier function is, in text or in
    /// LaTeX (`Gx` shown as `G_x` and a function `G_x`; `G1` and `G_1`, both `G_{1}`): its
    /// tables and equations would show two things alike ([`PrintedNames`]).
    fn check_shown_apart(
        &mut self,
        whose: &str,
        display: &str,
        span: Range<usize>,
    ) -> Result<(), FileError> {
        let line = super::error::locate(&self.source.text, span.clone()).line;
        self.shown
            .admit_display(whose, display, Some(line))
            .map_err(|why| {
                self.error(
                    ErrorKind::Name,
                    span,
                    format!("{why}: rename one, or give it another display"),
                )
            })
    }

    /// The phase space with the brackets of `[poisson]` declared: each key `"{a, b}"` names
    /// two phase variables, one at least a Poisson variable, once; each value is a real
    /// polynomial in the variables and parameters; and the brackets satisfy the Jacobi
    /// identity, checked exactly (a violation is shown at the last entry of its triple).
    fn poisson(
        &self,
        file: &LoadedSystem,
        poisson: &Spanned<StringTable>,
    ) -> Result<PhaseSpace, FileError> {
        let space = file.system.space();
        let vars = space.vars();
        let phase: Vec<&str> = space
            .coordinates()
            .into_iter()
            .map(|v| vars.variable(v).name())
            .collect();
        let mut entries: Vec<(Var, Var, Expr, Range<usize>)> = Vec::new();
        for (key, value) in &poisson.get_ref().entries {
            let span = key.span();
            let names = key
                .get_ref()
                .trim()
                .strip_prefix('{')
                .and_then(|k| k.strip_suffix('}'))
                .map(|k| k.split(',').map(str::trim).collect::<Vec<_>>())
                .filter(|names| names.len() == 2 && names.iter().all(|n| !n.is_empty()));
            let Some(names) = names else {
                return Err(self.error(
                    ErrorKind::Schema,
                    span,
                    format!(
                        "a key of [poisson] is a bracket of two variables, such as \
                         \"{{M1, M2}}\", not \"{}\"",
                        key.get_ref()
                    ),
                ));
            };
            let mut pair = Vec::new();
            for name in names {
                let Some(v) = vars.lookup(name) else {
                    return Err(self.error(
                        ErrorKind::Name,
                        span.clone(),
                        format!(
                            "unknown name '{name}' in a bracket of [poisson] (the phase \
                             variables: {})",
                            phase.join(", ")
                        ),
                    ));
                };
                if !space.is_phase_variable(v) {
                    return Err(self.error(
                        ErrorKind::Name,
                        span.clone(),
                        format!(
                            "'{name}' is {}, not a variable of the phase space, so every \
                             bracket with it is 0; declare it under variables to give it \
                             brackets",
                            vars.variable(v).kind().described()
                        ),
                    ));
                }
                pair.push(v);
            }
            let (a, b) = (pair[0], pair[1]);
            let [ua, ub] = [a, b].map(|v| vars.variable(v).unicode());
            if a == b {
                return Err(self.error(
                    ErrorKind::Name,
                    span,
                    format!(
                        "{{{ua}, {ua}}} is 0: a variable's bracket with itself is not declared"
                    ),
                ));
            }
            let poisson_vars = space.poisson_variables();
            if !poisson_vars.contains(&a) && !poisson_vars.contains(&b) {
                return Err(self.error(
                    ErrorKind::Name,
                    span,
                    format!(
                        "{{{ua}, {ub}}} is a bracket of canonical variables, already fixed by \
                         their pairs ({{q, p_q}} = 1, every other 0): [poisson] gives the \
                         brackets of the Poisson variables (under variables)"
                    ),
                ));
            }
            if let Some((.., first)) = entries
                .iter()
                .find(|e| (e.0, e.1) == (a, b) || (e.0, e.1) == (b, a))
            {
                let line = super::error::locate(&self.source.text, first.clone()).line;
                return Err(self.error(
                    ErrorKind::Name,
                    span,
                    format!(
                        "{{{ua}, {ub}}} is given twice: line {line} gives it already (a \
                         bracket in one order gives the other, {{{ub}, {ua}}} = −{{{ua}, {ub}}})"
                    ),
                ));
            }
            let text = self.text(value);
            let scope = file.scope(0);
            let tree = scope.tree(&self.source, &text)?;
            let refused = mention(&tree, "H")
                .map(|at| {
                    (
                        at,
                        "a declared bracket cannot use H: write it in the variables",
                    )
                })
                .or_else(|| {
                    first_bracket(&tree).map(|at| {
                        (
                            at,
                            "a declared bracket's value cannot be a bracket: it is what \
                             defines them; write it in the variables",
                        )
                    })
                });
            if let Some((at, message)) = refused {
                return Err(text.error(&self.source, ErrorKind::Expression, at, message));
            }
            let expr = scope.lower(&self.source, &text, &tree)?;
            if expr.conj() != expr {
                return Err(text.error(
                    &self.source,
                    ErrorKind::Expression,
                    tree.span,
                    format!(
                        "{{{ua}, {ub}}} = {expr} is not real: the bracket of two real \
                         variables is real"
                    ),
                ));
            }
            entries.push((a, b, expr, span));
        }
        let named: Vec<(&str, &str, Expr)> = entries
            .iter()
            .map(|(a, b, e, _)| {
                (
                    vars.variable(*a).name(),
                    vars.variable(*b).name(),
                    e.clone(),
                )
            })
            .collect();
        space.clone().with_brackets(&named).map_err(|e| {
            let at = match &e {
                EngineError::Jacobi(violation) => entries
                    .iter()
                    .rev()
                    .find(|(a, b, ..)| violation.triple.contains(a) && violation.triple.contains(b))
                    .map(|e| e.3.clone()),
                _ => None,
            };
            self.error(
                ErrorKind::Engine,
                at.unwrap_or(poisson.span()),
                e.to_string(),
            )
        })
    }

    fn text(&self, s: &Spanned<String>) -> Text {
        Text::in_toml(&self.source.text, s.span(), s.get_ref())
    }

    fn error(&self, kind: ErrorKind, span: Range<usize>, message: impl Into<String>) -> FileError {
        self.source.error(kind, span, message)
    }

    /// Declares a name of the given kind (`a coordinate`), checking that it is an identifier, not reserved,
    /// and new.
    fn declare(
        &mut self,
        name: &str,
        span: Range<usize>,
        what: &'static str,
    ) -> Result<(), FileError> {
        if let Some(bad) = BadName::of(name) {
            return Err(self.error(ErrorKind::Name, span, bad.declaring(name, what)));
        }
        if let Some((other, at)) = self.names.get(name) {
            let line = super::error::locate(&self.source.text, at.clone()).line;
            return Err(self.error(
                ErrorKind::Name,
                span,
                format!("'{name}' is already declared as {other} on line {line}"),
            ));
        }
        self.names.insert(name.to_string(), (what, span));
        Ok(())
    }

    /// The variables with the radicals of `[phase_space] radicals` added (`r = "x^2 + y^2"`),
    /// each radicand read in the variables without radicals and written back in ASCII, and the
    /// builder that declares them. Refused: a radicand that does not read, is constant, is not
    /// real, and radicals that are not independent (a radicand, or a product of them, that is
    /// a square), each at the text in the file.
    fn radicals(
        &self,
        declared: &[(Spanned<String>, Spanned<String>)],
        mut builder: VarSetBuilder,
        vars: Vars,
    ) -> Result<(VarSetBuilder, Vars), FileError> {
        if declared.is_empty() {
            return Ok((builder, vars));
        }
        for (name, radicand) in declared {
            let text = self.text(radicand);
            let value = Expr::parse(&vars, &text.value)
                .map_err(|e| super::scope::expression_error(&self.source, &text, &e))?;
            if let Some(why) = Expr::radicand_refusal(name.get_ref(), &value) {
                return Err(self.error(ErrorKind::Expression, radicand.span(), why));
            }
            builder = builder.radical(name.get_ref(), &value.to_ascii());
        }
        let vars = builder
            .clone()
            .build()
            .map_err(|e| self.error(ErrorKind::Name, declared[0].0.span(), e.to_string()))?;
        Expr::check_radicals(&vars).map_err(|e| {
            let first = declared.first().map(|(k, _)| k.span().start).unwrap_or(0);
            let last = declared.last().map(|(_, v)| v.span().end).unwrap_or(0);
            self.error(ErrorKind::Expression, first..last, e.to_string())
        })?;
        Ok((builder, vars))
    }

    /// The variables with the denominator atoms of `[phase_space] denominators` added, one at
    /// a time, each read in the variables with the atoms before it. Refused: a text that does
    /// not read, zero, a single term (division by one is exact already), a polynomial that is
    /// not real, and one that is a product of those declared before it (times a term).
    fn denominators(
        &self,
        declared: &[Spanned<String>],
        builder: VarSetBuilder,
        mut vars: Vars,
    ) -> Result<Vars, FileError> {
        let mut builder = builder;
        for d in declared {
            let text = self.text(d);
            let value = Expr::parse(&vars, &text.value)
                .map_err(|e| super::scope::expression_error(&self.source, &text, &e))?;
            let refuse = |why: String| Err(self.error(ErrorKind::Expression, d.span(), why));
            if value.is_zero() {
                return refuse("a denominator cannot be 0".into());
            }
            if value.is_monomial() {
                return refuse(format!(
                    "{value} is a single term: division by it is exact already, so declare \
                     only sums (such as \"x - y\") as denominators"
                ));
            }
            if value.conj() != value {
                return refuse(format!("the denominator {value} is not real"));
            }
            if vars.radicals().any(|r| value.contains(r)) {
                return refuse(format!(
                    "the denominator {value} has a radical in it: a denominator is a polynomial \
                     in the coordinates, momenta and parameters; divide by {value} where it \
                     stands instead, which superint does through its conjugates"
                ));
            }
            if Expr::one(&vars).checked_div(&value).is_ok() {
                return refuse(format!(
                    "{value} is a product of the denominators declared before it and the \
                     radicands (times a term): division by it is exact already"
                ));
            }
            builder = builder.denominator(&value.to_ascii(), &value.to_string(), &value.to_latex());
            vars = builder
                .clone()
                .build()
                .map_err(|e| self.error(ErrorKind::Expression, d.span(), e.to_string()))?;
        }
        Ok(vars)
    }

    fn build(mut self, model: SystemModel) -> Result<LoadedSystem, FileError> {
        let ps = model.phase_space.get_ref();
        if ps.coordinates.is_empty() && ps.angles.is_empty() && ps.variables.is_empty() {
            return Err(self.error(
                ErrorKind::Schema,
                model.phase_space.span(),
                "[phase_space] declares no coordinates, angles or variables: a phase space \
                 needs at least one canonical pair or Poisson variable",
            ));
        }
        for c in &ps.coordinates {
            self.declare(c.get_ref(), c.span(), "a coordinate")?;
        }
        for a in &ps.angles {
            self.declare(a.get_ref(), a.span(), "an angle")?;
        }
        for v in &ps.variables {
            self.declare(v.get_ref(), v.span(), "a Poisson variable")?;
        }
        for p in &ps.parameters {
            self.declare(p.get_ref(), p.span(), "a parameter")?;
        }
        let radicals = ps
            .radicals
            .as_ref()
            .map_or(&[][..], |r| &r.get_ref().entries);
        for (name, _) in radicals {
            self.declare(name.get_ref(), name.span(), "a radical")?;
        }
        let qs: Vec<&Spanned<String>> = ps.coordinates.iter().chain(&ps.angles).collect();
        for q in &qs {
            let p = format!("p_{}", q.get_ref());
            if let Some((other, _)) = self.names.get(&p) {
                return Err(self.error(
                    ErrorKind::Name,
                    q.span(),
                    format!(
                        "the momentum of '{}' is '{p}', which is already declared as {other}",
                        q.get_ref()
                    ),
                ));
            }
            self.names.insert(p, ("a momentum", q.span()));
        }
        let limits = self.limits(&model)?;
        let mut builder = VarSet::builder().limits(limits);
        for c in &ps.coordinates {
            builder = builder.coordinate(c.get_ref());
        }
        for a in &ps.angles {
            builder = builder.angle(a.get_ref());
        }
        for q in &qs {
            builder = builder.momentum(&format!("p_{}", q.get_ref()));
        }
        for v in &ps.variables {
            builder = builder.poisson(v.get_ref());
        }
        for p in &ps.parameters {
            builder = builder.parameter(p.get_ref());
        }
        // The functions' names, which the printer must not spell with variables (`Mx`).
        builder = builder.also_named(model.function.iter().flat_map(|f| {
            let f = f.get_ref();
            [Some(&f.name), f.display.as_ref()]
                .into_iter()
                .flatten()
                .map(|n| n.get_ref().as_str())
        }));
        let span = model.phase_space.span();
        let with_atoms = builder.clone();
        let vars = builder.build().map_err(|e| {
            // Two names that one spelling finds (`omega` and `ω`), or that LaTeX prints
            // alike (`x1` and `x₁`): shown at the second.
            let at = match &e {
                AlgebraError::DeclaredTwice { name, .. }
                | AlgebraError::PrintedAlike { name, .. } => ps
                    .coordinates
                    .iter()
                    .chain(&ps.angles)
                    .chain(&ps.variables)
                    .chain(&ps.parameters)
                    .find(|n| n.get_ref() == name)
                    .map(|n| n.span()),
                _ => None,
            };
            self.error(ErrorKind::Name, at.unwrap_or(span.clone()), e.to_string())
        })?;
        let (with_atoms, vars) = self.radicals(radicals, with_atoms, vars)?;
        let vars = self.denominators(&ps.denominators, with_atoms, vars)?;
        let pairs: Vec<(String, String)> = qs
            .iter()
            .map(|q| (q.get_ref().clone(), format!("p_{}", q.get_ref())))
            .collect();
        let pairs: Vec<(&str, &str)> = pairs
            .iter()
            .map(|(q, p)| (q.as_str(), p.as_str()))
            .collect();
        let space = PhaseSpace::new(&vars, &pairs)
            .map_err(|e| self.error(ErrorKind::Name, span.clone(), e.to_string()))?;
        self.shown = PrintedNames::of_variables(&vars);
        let name = match &model.name {
            Some(n) => n.get_ref().clone(),
            None => Path::new(&self.source.origin).file_stem().map_or_else(
                || "system".to_string(),
                |s| s.to_string_lossy().into_owned(),
            ),
        };
        let mut file = LoadedSystem {
            source: self.source.clone(),
            name: name.clone(),
            citation: model.source.as_ref().map(|s| s.get_ref().clone()),
            description: model.description.as_ref().map(|s| s.get_ref().clone()),
            system: System::new(&name, space, Expr::zero(&vars)),
            families: Vec::new(),
            claims: Vec::new(),
            limits,
            caller: super::Caller::Program,
            cache: Mutex::new(HashMap::new()),
        };

        if let Some(poisson) = &model.poisson {
            let space = self.poisson(&file, poisson)?;
            file.system = System::new(&name, space, Expr::zero(&vars));
        }

        // H may use the variables only.
        let h_text = self.text(&model.hamiltonian);
        let h = {
            let scope = file.scope(0);
            let tree = scope.tree(&self.source, &h_text)?;
            if let Some(at) = mention(&tree, "H") {
                return Err(h_text.error(
                    &self.source,
                    ErrorKind::Expression,
                    at,
                    "the Hamiltonian cannot use H itself",
                ));
            }
            scope.lower(&self.source, &h_text, &tree).map_err(|e| {
                later_function(e, &model.function, |name| {
                    format!(
                        "{name} is a function, and the Hamiltonian is read before the \
                         functions: it uses only variables and parameters, so write {name}'s \
                         value out"
                    )
                })
            })?
        };
        file.system.define("H", "H", h);

        for (k, f) in model.function.iter().enumerate() {
            let f = f.get_ref();
            self.declare(f.name.get_ref(), f.name.span(), "a function")?;
            let value = file
                .scope(0)
                .parse(&self.source, &self.text(&f.value))
                .map_err(|e| {
                    later_function(e, &model.function[k + 1..], |name| {
                        format!(
                            "{name} is declared further down, and a function uses only the \
                             functions declared before it: move this one below {name}"
                        )
                    })
                })?;
            if let Some(d) = &f.display {
                self.check_display(d)?;
            }
            let display = f.display.as_ref().unwrap_or(&f.name).get_ref();
            let whose = format!("the function {}", f.name.get_ref());
            let span = f.display.as_ref().unwrap_or(&f.name).span();
            self.check_shown_apart(&whose, display, span)?;
            file.system.define(f.name.get_ref(), display, value);
        }

        for spanned in &model.family {
            let f = spanned.get_ref();
            self.declare(f.name.get_ref(), f.name.span(), "a family")?;
            let indices = match &f.indices {
                None => ["m".to_string(), "n".to_string()],
                Some(list) => {
                    let items = list.get_ref();
                    if items.len() != 2 {
                        return Err(self.error(
                            ErrorKind::Family,
                            list.span(),
                            format!(
                                "a family has two indices, such as [\"m\", \"n\"]; found {}",
                                items.len()
                            ),
                        ));
                    }
                    [items[0].get_ref().clone(), items[1].get_ref().clone()]
                }
            };
            let index_span = f.indices.as_ref().map_or(f.name.span(), |l| l.span());
            let taken = |idx: &str| {
                self.names
                    .get(idx)
                    .map(|(other, _)| format!("declared as {other}"))
            };
            if let Some((k, kind, message)) = index_refusal([&indices[0], &indices[1]], taken) {
                // An unwritable letter is shown at its index; the rest at the list.
                let list = f.indices.as_ref().map(|l| l.get_ref());
                let span = match kind {
                    ErrorKind::Name => list.map_or(index_span.clone(), |l| l[k].span()),
                    _ => index_span,
                };
                return Err(self.error(kind, span, message));
            }
            if let Some(d) = &f.display {
                self.check_display(d)?;
            }
            let display = f.display.as_ref().unwrap_or(&f.name).get_ref().clone();
            let span = f.display.as_ref().unwrap_or(&f.name).span();
            let line = super::error::locate(&self.source.text, span.clone()).line;
            let whose = format!("the family {}", f.name.get_ref());
            if let Err(why) = self.shown.admit_family(&whose, &display, Some(line)) {
                return Err(self.error(
                    ErrorKind::Name,
                    span,
                    format!("{why}: rename one, or give it another display"),
                ));
            }
            file.families.push(Family {
                name: f.name.get_ref().clone(),
                display,
                indices,
                value: self.text(&f.value),
                eigenvalue: f.eigenvalue.as_ref().map(|e| self.text(e)),
                span: f.name.span(),
                source: self.source.clone(),
            });
            // Check the value and the eigenvalue on the instance (1, 1).
            let k = file.families.len() - 1;
            file.scope(k + 1).expand(k, 1, 1, &self.source, 0..0)?;
            if file.families[k].eigenvalue.is_some() {
                file.eigenvalue_at(k, 1, 1)?;
            }
        }

        for (k, c) in model.claim.iter().enumerate() {
            let spec = ClaimSpec::parse(&file, k, c)?;
            file.claims.push(spec);
        }
        Ok(file)
    }

    /// The limits: the command line's, else the file's, else the defaults.
    fn limits(&self, model: &SystemModel) -> Result<Limits, FileError> {
        let file = model.limits.as_ref().map(|l| l.get_ref());
        let terms = file.and_then(|l| l.max_terms.as_ref());
        let degree = file.and_then(|l| l.max_degree.as_ref());
        let work = file.and_then(|l| l.max_term_products.as_ref());
        for (name, given) in [("max_terms", terms), ("max_term_products", work)] {
            if let Some(t) = given.filter(|t| *t.get_ref() == 0) {
                return Err(self.error(
                    ErrorKind::Schema,
                    t.span(),
                    format!("{name} must be at least 1"),
                ));
            }
        }
        if let Some(d) = degree {
            if *d.get_ref() == 0 || *d.get_ref() > MAX_DEGREE_CEILING {
                return Err(self.error(
                    ErrorKind::Schema,
                    d.span(),
                    format!("max_degree must be between 1 and {MAX_DEGREE_CEILING}"),
                ));
            }
        }
        let given = LimitsOverride {
            max_terms: self
                .limits
                .max_terms
                .or(terms.map(|t| usize::try_from(*t.get_ref()).unwrap_or(usize::MAX))),
            max_degree: self.limits.max_degree.or(degree.map(|d| *d.get_ref())),
            max_term_products: self.limits.max_term_products.or(work.map(|w| *w.get_ref())),
        };
        let limits = given.or_defaults();
        Ok(Limits {
            max_degree: limits.max_degree.min(MAX_DEGREE_CEILING),
            ..limits
        })
    }
}

/// An unknown name that is one of the functions `later` (declared further down the file) gets
/// the hint `hint(name)`.
fn later_function(
    e: FileError,
    later: &[Spanned<FunctionModel>],
    hint: impl Fn(&str) -> String,
) -> FileError {
    let name = e
        .message
        .strip_prefix("unknown name '")
        .and_then(|rest| rest.split('\'').next())
        .map(str::to_string);
    match name.filter(|n| later.iter().any(|f| f.get_ref().name.get_ref() == n)) {
        Some(name) => e.with_hint(hint(&name)),
        None => e,
    }
}

/// Refuses a display name (`text`, written at `whole` in `source`) that would not show as
/// written ([`Builder::check_display`] says how); the message points at the character.
pub(crate) fn check_display(
    source: &Source,
    text: &Text,
    whole: Range<usize>,
) -> Result<(), FileError> {
    const MARKUP: &str = "^`|\\$%&#{}~*<>\"";
    let name = &text.value;
    let refuse = |span: Range<usize>, why: &str| {
        Err(source.error(
            ErrorKind::Name,
            span,
            format!(
                "a display name is letters, digits, primes (G1'), a bar (Z̄), subscripts \
                 (A_x), spaces and parentheses: {why}"
            ),
        ))
    };
    if name.is_empty() {
        return refuse(
            whole.clone(),
            "this one is empty (leave display out to show the name)",
        );
    }
    for (k, c) in name.char_indices() {
        let here = text.source_span(Span::new(k, k + c.len_utf8()));
        if MARKUP.contains(c) {
            return refuse(here, &format!("'{c}' is markup in Markdown or LaTeX"));
        }
        if invisible(c) {
            let code = c as u32;
            return refuse(
                here,
                &format!("U+{code:04X} is an invisible or control character"),
            );
        }
        let before = name[..k].chars().next_back();
        let after = name[k + c.len_utf8()..].chars().next();
        if c == ' ' && (before.is_none() || after.is_none()) {
            return refuse(here, "it begins or ends with a space");
        }
        if c == '\u{304}' || unbarred(c).is_some() {
            let letter = c != '\u{304}' || before.is_some_and(|b| b.is_alphanumeric());
            if !letter || after.is_some_and(|a| !matches!(a, '_' | '\'' | ' ' | '(' | ')')) {
                return refuse(
                    here,
                    "a bar (U+0304) stands right after the letter or digit it is drawn over, \
                     at the end of the name or before its '_', a prime, a space or a \
                     parenthesis (Z̄, Z̄_x)",
                );
            }
        } else if let Some(why) = unwritable_letter(c) {
            return refuse(here, &why);
        }
        let stands = |c: Option<char>| c.is_some_and(|c| c != '_' && c != ' ');
        if c == '_' && !(stands(before) && stands(after)) {
            return refuse(
                here,
                "a subscript '_' stands between a name and its subscript (A_x), not at an \
                 end or beside another '_' or a space",
            );
        }
    }
    Ok(())
}
