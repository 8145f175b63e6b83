//! Loading a system file: bytes → text (no binary, no empty file) → the TOML model → variables
//! with their limits, phase space, Hamiltonian, functions, families and claims, each checked
//! where it is written (the names by the rules of `names.rs`).

use std::collections::HashMap;
use std::io::Read;
use std::ops::Range;
use std::path::Path;
use std::sync::Mutex;

use brackets::{EngineError, PhaseSpace, System};
use toml::Spanned;
use trigpoly::{AlgebraError, Expr, Limits, Var, VarKind, VarSet, Vars, VarsBuilder};

use super::claims::{engine_error, ClaimSpec};
use super::error::{locate_bytes, ErrorKind, FileError, Warnings};
use super::keys::unknown_key_hint;
use super::model::{
    ExpectShape, FamilyModel, FunctionModel, PhaseSpaceModel, ShapeModel, StringTable, SystemModel,
};
use super::names::{check_display, check_shown_text, index_refusal, BadName, PrintedNames};
use super::scope::{first_bracket, instance_parts, mention};
use super::text::{Source, Text};
use super::{Family, LimitsOverride, LoadedSystem};

/// The largest degree limit a file or the command line may set (what a 16-bit exponent field
/// holds; the packing widens its fields as the limit asks).
pub const MAX_DEGREE_CEILING: u32 = 32_767;

/// Reads and loads a system file (any path, as [`std::fs::read`] takes it: a `&str`, a
/// `PathBuf`, ...). Every problem is a [`FileError`] naming the file, line and column.
pub fn load(path: impl AsRef<Path>, limits: &LimitsOverride) -> Result<LoadedSystem, FileError> {
    let path = path.as_ref();
    let origin = path.display().to_string();
    let cannot = |e: std::io::Error| {
        FileError::new(ErrorKind::Io, &origin, format!("cannot read the file: {e}"))
    };
    let file = std::fs::File::open(path).map_err(cannot)?;
    let bytes = read_bytes(&origin, file, cannot)?;
    load_bytes(&origin, &bytes, limits)
}

/// The most bytes of a system file read (1 GiB): far more than any file of expressions within
/// the term limit holds, and a bound on what `check /dev/zero` or an endless pipe reads (they
/// read until memory ran out).
pub const MAX_FILE_BYTES: usize = 1 << 30;

/// The bytes of a system file from `reader` (`origin` names it), read to its end, to a NUL
/// byte (a binary file, which [`load_bytes`] then refuses at its place without the rest being
/// read), or past [`MAX_FILE_BYTES`], which is refused; an error of the reader is `cannot`'s.
pub fn read_bytes(
    origin: &str,
    mut reader: impl Read,
    cannot: impl Fn(std::io::Error) -> FileError,
) -> Result<Vec<u8>, FileError> {
    let mut bytes = Vec::new();
    let mut chunk = vec![0u8; 1 << 16];
    loop {
        let n = match reader.read(&mut chunk) {
            Ok(0) => return Ok(bytes),
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(cannot(e)),
        };
        bytes.extend_from_slice(&chunk[..n]);
        if chunk[..n].contains(&0) {
            return Ok(bytes);
        }
        if bytes.len() > MAX_FILE_BYTES {
            let message = format!(
                "the file is larger than {} GiB, far larger than a system file is: is it one?",
                MAX_FILE_BYTES >> 30
            );
            return Err(FileError::new(ErrorKind::NotText, origin, message));
        }
    }
}

/// Loads a system file from its bytes; `origin` names it in messages.
pub fn load_bytes(
    origin: &str,
    bytes: &[u8],
    limits: &LimitsOverride,
) -> Result<LoadedSystem, FileError> {
    load_str(origin, text_of(origin, bytes)?, limits)
}

/// Loads a system file piped on standard input, [`STDIN`](super::STDIN) in messages, which
/// only the command line reads: a limit its text meets is raised by the command line's flag
/// first ([`Given::CommandLineAboutFile`](super::Given::CommandLineAboutFile)).
pub fn load_piped(bytes: &[u8], limits: &LimitsOverride) -> Result<LoadedSystem, FileError> {
    let text = text_of(super::STDIN, bytes)?;
    load_source(Source::on_command_line(super::STDIN, text), limits)
}

/// The text of a system file's bytes, `origin` in messages: refused where it is binary (a NUL
/// byte) or not UTF-8.
fn text_of<'a>(origin: &str, bytes: &'a [u8]) -> Result<&'a str, FileError> {
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
    std::str::from_utf8(bytes).map_err(|e| {
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
    })
}

/// Loads a system file from its text; `origin` names it in messages.
pub fn load_str(
    origin: &str,
    text: &str,
    limits: &LimitsOverride,
) -> Result<LoadedSystem, FileError> {
    load_source(Source::new(origin, text), limits)
}

/// Loads the system file whose text is `source`.
fn load_source(source: Source, limits: &LimitsOverride) -> Result<LoadedSystem, FileError> {
    let text = source.text.clone();
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
    check_shape(&source, &text)?;
    let model: SystemModel = toml::from_str(&text).map_err(|e| toml_error(&source, &e))?;
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
    check_strings(source, &shape)?;
    check_tables(source, &shape)?;
    check_arrays_of_tables(source, &shape)?;
    check_expects(source, text)
}

/// The error for `value` at `span`, the value of `key`, which should be `wanted`.
fn wrong_at(
    source: &Source,
    span: Range<usize>,
    value: &toml::Value,
    key: &str,
    wanted: &str,
) -> FileError {
    source.error(
        ErrorKind::Schema,
        span,
        format!("{key} is {wanted}, not {}", toml_kind(value)),
    )
}

/// The error for `v`, the value of `key`, which should be `wanted`.
fn wrong(source: &Source, v: &Spanned<toml::Value>, key: &str, wanted: &str) -> FileError {
    wrong_at(source, v.span(), v.get_ref(), key, wanted)
}

/// Refuses a text key (`name`, `source`, `description`, `hamiltonian`) that is no string.
fn check_strings(source: &Source, shape: &ShapeModel) -> Result<(), FileError> {
    for (key, value) in [
        ("name", &shape.name),
        ("source", &shape.source),
        ("description", &shape.description),
        ("hamiltonian", &shape.hamiltonian),
    ] {
        if let Some(v) = value.as_ref().filter(|v| !v.get_ref().is_str()) {
            return Err(wrong(source, v, key, "a string in quotes"));
        }
    }
    Ok(())
}

/// Refuses a `[phase_space]`, `[limits]` or `[poisson]` that is no table.
fn check_tables(source: &Source, shape: &ShapeModel) -> Result<(), FileError> {
    for (key, value) in [
        ("[phase_space]", &shape.phase_space),
        ("[limits]", &shape.limits),
        ("[poisson]", &shape.poisson),
    ] {
        if let Some(v) = value.as_ref().filter(|v| !v.get_ref().is_table()) {
            return Err(
                wrong(source, v, key, "a table, written with one pair of brackets")
                    .with_hint(format!("write {key} on a line of its own, then its keys")),
            );
        }
    }
    Ok(())
}

/// Refuses a `[[function]]`, `[[family]]` or `[[claim]]` that is no array, or holds an item
/// that is no table.
fn check_arrays_of_tables(source: &Source, shape: &ShapeModel) -> Result<(), FileError> {
    for (key, value) in [
        ("[[function]]", &shape.function),
        ("[[family]]", &shape.family),
        ("[[claim]]", &shape.claim),
    ] {
        let hint = format!("write {key} on a line of its own before each one's keys");
        let Some(list) = value else { continue };
        let Some(items) = list.get_ref().as_array() else {
            return Err(wrong(
                source,
                list,
                key,
                "an array of tables, each written with two pairs of brackets",
            )
            .with_hint(hint));
        };
        if let Some(item) = items.iter().find(|v| !v.is_table()) {
            return Err(
                wrong_at(source, list.span(), item, &format!("each {key}"), "a table")
                    .with_hint(hint),
            );
        }
    }
    Ok(())
}

/// Refuses a claim's `expect` that is no string.
fn check_expects(source: &Source, text: &str) -> Result<(), FileError> {
    if let Ok(claims) = toml::from_str::<ExpectShape>(text) {
        let expects = claims.claim.iter().filter_map(|c| c.expect.as_ref());
        if let Some(v) = expects.into_iter().find(|v| !v.get_ref().is_str()) {
            return Err(wrong(source, v, "expect", "\"proved\" or \"refuted\""));
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
    if message == "duplicate key" {
        return duplicate_key(source, span);
    }
    // TOML refuses a dotted key of more than `MAX_KEY_PARTS` parts without a place.
    if message == "recursion limit" && e.span().is_none() {
        if let Some(key) = deep_key(&source.text) {
            let message = format!(
                "this dotted key has more than {MAX_KEY_PARTS} parts: TOML reads tables \
                 nested at most {MAX_KEY_PARTS} deep"
            );
            return source.error(ErrorKind::Toml, key, message);
        }
    }
    let message = if message.starts_with("missing field") {
        format!("{message} (see docs/system-files.md for every field)")
    } else if let Some(wanted) = message.strip_prefix("invalid type: map, expected ") {
        // A date is read as a map: said as a date, of its key, as at the top level.
        match date_at(&source.text, &span) {
            Some((key, false)) => format!("{key} is {}, not a date", in_words(wanted)),
            Some((key, true)) => {
                format!("each of {key} is {}, not a date", in_words(wanted))
            }
            None => serde_words(&message),
        }
    } else {
        serde_words(&message)
    };
    let hint = unknown_key_hint(&message);
    let error = source.error(kind, span, message);
    match hint {
        Some(hint) => error.with_hint(hint),
        None => error,
    }
}

/// A text that may run over several lines, as a report shows it: a file written with CRLF line
/// ends keeps them in a string of several lines, whose line breaks are the text's own (a lone
/// `\r` is refused: `Builder::check_texts`).
fn over_lines(text: &Option<Spanned<String>>) -> Option<String> {
    text.as_ref().map(|s| s.get_ref().replace("\r\n", "\n"))
}

/// The most parts a dotted key (`a.b.c`, `[a.b.c]`) may have: TOML nests tables at most this
/// deep, and says so with no place.
const MAX_KEY_PARTS: usize = 80;

/// The first dotted key of `text` with more than [`MAX_KEY_PARTS`] parts, bare or quoted (its
/// place, from its first part to its last), outside strings and comments; `None` when there is
/// none.
fn deep_key(text: &str) -> Option<Range<usize>> {
    let bytes = text.as_bytes();
    let bare = |c: &u8| c.is_ascii_alphanumeric() || matches!(c, b'_' | b'-');
    // The current run of parts: where it starts and ends, how many parts, whether a '.' is
    // open after them.
    let (mut key, mut parts, mut dot) = (0..0, 0, false);
    let mut k = 0;
    while k < bytes.len() {
        let part = match bytes[k] {
            b' ' | b'\t' => {
                k += 1;
                continue;
            }
            b'.' if parts > 0 && !dot => {
                (dot, k) = (true, k + 1);
                continue;
            }
            quote @ (b'"' | b'\'') => {
                let close = match bytes[k..].starts_with(&[quote; 3]) {
                    true => &[quote; 3][..],
                    false => &[quote][..],
                };
                let mut end = k + close.len();
                while end < bytes.len() && !bytes[end..].starts_with(close) {
                    end += if quote == b'"' && bytes[end] == b'\\' {
                        2
                    } else {
                        1
                    };
                }
                k..(end + close.len()).min(bytes.len())
            }
            c if bare(&c) => k..k + bytes[k..].iter().take_while(|c| bare(c)).count(),
            c => {
                // A comment, a newline, `=`, a bracket: the end of any key.
                if parts > MAX_KEY_PARTS {
                    return Some(key);
                }
                k = match c {
                    b'#' => text[k..].find('\n').map_or(bytes.len(), |n| k + n),
                    _ => k + 1,
                };
                (parts, dot) = (0, false);
                continue;
            }
        };
        if parts > MAX_KEY_PARTS && !dot {
            return Some(key);
        }
        (key, parts) = match dot {
            true => (key.start..part.end, parts + 1),
            false => (part.clone(), 1),
        };
        (dot, k) = (false, part.end);
    }
    (parts > MAX_KEY_PARTS).then_some(key)
}

/// TOML's `duplicate key` at `span`, in a system file's words: a `[function]`, `[family]` or
/// `[claim]` header after the array's first item (`[[claim]]`) is the array written as a table,
/// as [`check_arrays_of_tables`] says where it comes first; any other is the key or the
/// table named twice.
fn duplicate_key(source: &Source, span: Range<usize>) -> FileError {
    let text = &source.text;
    let key = text.get(span.clone()).unwrap_or("").trim();
    let line_start = text[..span.start.min(text.len())]
        .rfind('\n')
        .map_or(0, |i| i + 1);
    let before = text[line_start..span.start.min(text.len())].trim();
    // The array written as a table is the schema's error, as where it comes first.
    let array = before == "[" && ["function", "family", "claim"].contains(&key);
    let (message, hint) = match before {
        _ if array => (
            format!(
                "[[{key}]] is an array of tables, each written with two pairs of brackets, not \
                 a table"
            ),
            Some(format!(
                "write [[{key}]] on a line of its own before each one's keys"
            )),
        ),
        "[" | "[[" => (
            format!("[{key}] is given twice: one header holds all of its keys"),
            None,
        ),
        _ => {
            // The header of the table the key is in: an item of an array holds one of each
            // key, and the next item starts with the header again.
            let header = text[..line_start]
                .lines()
                .rev()
                .map(str::trim)
                .find(|l| l.starts_with('['));
            let item = header
                .and_then(|h| h.strip_prefix("[["))
                .and_then(|h| h.split("]]").next())
                .map(str::trim);
            let place = match header {
                Some(_) => " in one table",
                None => "",
            };
            (
                format!("`{key}` is given twice{place}"),
                item.map(|item| {
                    format!(
                        "each [[{item}]] holds one of each key: start the next one with \
                         [[{item}]] on a line of its own"
                    )
                }),
            )
        }
    };
    let kind = match array {
        true => ErrorKind::Schema,
        false => ErrorKind::Toml,
    };
    let error = source.error(kind, span, message);
    match hint {
        Some(hint) => error.with_hint(hint),
        None => error,
    }
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

/// A mistyped value's message in a system file's words: serde's `invalid type: string "100",
/// expected i64` (a `[limits]` value) as `expected a whole number`, `a sequence` as `an array`,
/// and a number too large for 64 bits (`integer `1e20` as i128`) as too large; any other
/// message as it is.
fn serde_words(message: &str) -> String {
    let Some((found, wanted)) = message
        .strip_prefix("invalid type: ")
        .and_then(|m| m.rsplit_once(", expected "))
    else {
        return message.to_string();
    };
    match found.strip_suffix(" as i128") {
        Some(number) => format!(
            "the number {} is too large (at most {})",
            number.trim_start_matches("integer ").trim_matches('`'),
            i64::MAX
        ),
        None => format!("invalid type: {found}, expected {}", in_words(wanted)),
    }
}

/// What serde expected, in the words of a system file's messages: `a string` is `a string in
/// quotes`, an integer `a whole number`, a sequence `an array`.
fn in_words(expected: &str) -> &str {
    match expected {
        "a string" => "a string in quotes",
        "u8" | "u16" | "u32" | "u64" | "usize" | "i64" => "a whole number",
        "a sequence" => "an array",
        other => other,
    }
}

/// The two names of a key of `[poisson]` written `{M1, M2}`, trimmed, or `None` when the
/// key is no bracket of two nonempty names.
fn bracket_names(key: &str) -> Option<Vec<&str>> {
    key.trim()
        .strip_prefix('{')
        .and_then(|k| k.strip_suffix('}'))
        .map(|k| k.split(',').map(str::trim).collect::<Vec<_>>())
        .filter(|names| names.len() == 2 && names.iter().all(|n| !n.is_empty()))
}

struct Builder<'a> {
    source: Source,
    limits: &'a LimitsOverride,
    /// Every declared name: what it is (`an angle`) and where.
    names: HashMap<String, (&'static str, Range<usize>)>,
    /// How each variable and function is printed, in text and in LaTeX.
    shown: PrintedNames,
}

/// What a name was declared as, and where.
type Declaration<'r, T> = (T, &'r Range<usize>);

/// The two declarations of a clashing name, `declared` before and `current`, in the order of
/// the file: the second there is the one refused, though the kinds are declared in turn (the
/// functions before the families).
fn in_file_order<'r, T>(
    declared: Declaration<'r, T>,
    current: Declaration<'r, T>,
) -> (Declaration<'r, T>, Declaration<'r, T>) {
    match declared.1.start > current.1.start {
        true => (current, declared),
        false => (declared, current),
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
        name: &str,
        display: &str,
        span: Range<usize>,
    ) -> Result<(), FileError> {
        let line = super::error::locate(&self.source.text, span.clone()).line;
        self.shown
            .admit_display(whose, name, display, Some(line))
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
    /// identity, checked exactly (a violation is shown at the last entry of its triple; a
    /// check stopped by a limit is a limit, with its hint, as any text's of the file is).
    fn poisson(
        &self,
        file: &LoadedSystem,
        poisson: &Spanned<StringTable>,
    ) -> Result<PhaseSpace, FileError> {
        let space = file.system.space();
        let vars = space.vars();
        let mut entries: Vec<(Var, Var, Expr, Range<usize>)> = Vec::new();
        for (key, value) in &poisson.get_ref().entries {
            let span = key.span();
            let (a, b) = self.declared_pair(key, space, &entries)?;
            let expr = self.declared_value(file, value, (a, b))?;
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
                EngineError::Jacobi(violation) => {
                    entries.get(violation.bracket).map(|e| e.3.clone())
                }
                _ => None,
            };
            engine_error(&self.source, at.unwrap_or(poisson.span()), &e)
        })
    }

    /// The two variables of a key of `[poisson]` (`{M1, M2}`), refused when the key is no
    /// bracket of two variables, names no phase variable, pairs a variable with itself or
    /// two canonical variables, or repeats an entry of `entries`.
    fn declared_pair(
        &self,
        key: &Spanned<String>,
        space: &PhaseSpace,
        entries: &[(Var, Var, Expr, Range<usize>)],
    ) -> Result<(Var, Var), FileError> {
        let span = key.span();
        let Some(names) = bracket_names(key.get_ref()) else {
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
        let a = self.declared_variable(names[0], space, &span)?;
        let b = self.declared_variable(names[1], space, &span)?;
        self.check_new_pair((a, b), space, span, entries)?;
        Ok((a, b))
    }

    /// The phase variable `name` in a key of `[poisson]` at `span`, refused when it is
    /// unknown or no variable of the phase space (a parameter has no brackets to declare).
    fn declared_variable(
        &self,
        name: &str,
        space: &PhaseSpace,
        span: &Range<usize>,
    ) -> Result<Var, FileError> {
        let vars = space.vars();
        let Some(v) = vars.lookup(name) else {
            let phase: Vec<&str> = space
                .coordinates()
                .into_iter()
                .map(|v| vars.variable(v).name())
                .collect();
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
        Ok(v)
    }

    /// Refuses a declared bracket `{a, b}` at `span` that is a variable's with itself, one of
    /// two canonical variables (fixed by their pairs), or one `entries` already give in either
    /// order.
    fn check_new_pair(
        &self,
        (a, b): (Var, Var),
        space: &PhaseSpace,
        span: Range<usize>,
        entries: &[(Var, Var, Expr, Range<usize>)],
    ) -> Result<(), FileError> {
        let vars = space.vars();
        let [ua, ub] = [a, b].map(|v| vars.variable(v).unicode());
        if a == b {
            return Err(self.error(
                ErrorKind::Name,
                span,
                format!("{{{ua}, {ua}}} is 0: a variable's bracket with itself is not declared"),
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
        Ok(())
    }

    /// The value of a declared bracket `{a, b}`: an expression in the variables (no `H`, no
    /// bracket, which it defines), real.
    fn declared_value(
        &self,
        file: &LoadedSystem,
        value: &Spanned<String>,
        (a, b): (Var, Var),
    ) -> Result<Expr, FileError> {
        let vars = file.system.space().vars();
        let [ua, ub] = [a, b].map(|v| vars.variable(v).unicode());
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
        // A negative power of a phase variable the engine would take on to the Jacobi check,
        // whose message blames the brackets, not the value: here it is shown at the value.
        if let Some((why, hint)) = negative_power(&expr) {
            return Err(text
                .error(
                    &self.source,
                    ErrorKind::Expression,
                    tree.span,
                    format!(
                        "{{{ua}, {ub}}} = {} {why}: a declared bracket divides by declared \
                         denominators and radicals alone",
                        expr.brief_excerpt()
                    ),
                )
                .with_hint(hint));
        }
        if expr.conj() != expr {
            return Err(text.error(
                &self.source,
                ErrorKind::Expression,
                tree.span,
                format!(
                    "{{{ua}, {ub}}} = {} is not real: the bracket of two real variables is \
                     real",
                    expr.brief_excerpt()
                ),
            ));
        }
        Ok(expr)
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
            let ((first, first_at), (second, second_at)) =
                in_file_order((*other, at), (what, &span));
            let line = super::error::locate(&self.source.text, first_at.clone()).line;
            return Err(self.error(
                ErrorKind::Name,
                second_at.clone(),
                format!(
                    "'{name}' is already declared as {first} on line {line}, so it cannot be \
                     {second} too"
                ),
            ));
        }
        // A name that is an instance of a family (`K_2_0` beside `K`) would stand for two
        // things, and `K_{2,0}` would read as the name: refused in either order.
        fn head(name: &str) -> Option<&str> {
            instance_parts(name).map(|(head, ..)| head)
        }
        let instance = match what {
            FAMILY => self
                .names
                .iter()
                .find(|(other, _)| head(other) == Some(name)),
            _ => head(name)
                .and_then(|family| self.names.get_key_value(family))
                .filter(|(_, (kind, _))| *kind == FAMILY),
        };
        if let Some((other, (kind, at))) = instance {
            let instance = match what {
                FAMILY => other.as_str(),
                _ => name,
            };
            let (family, m, n) = instance_parts(instance).expect("found as an instance");
            let (((first, first_kind), first_at), ((second, second_kind), second_at)) =
                in_file_order(((other.as_str(), *kind), at), ((name, what), &span));
            let line = super::error::locate(&self.source.text, first_at.clone()).line;
            return Err(self.error(
                ErrorKind::Name,
                second_at.clone(),
                format!(
                    "'{second}' cannot be {second_kind} of this file, which declares \
                     {first_kind} '{first}' on line {line}: '{instance}' is the instance \
                     {family}_{{{m},{n}}} of the family {family}; give one of them another name"
                ),
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
        mut builder: VarsBuilder,
        vars: Vars,
    ) -> Result<(VarsBuilder, Vars), FileError> {
        if declared.is_empty() {
            return Ok((builder, vars));
        }
        for (name, radicand) in declared {
            let text = self.text(radicand);
            // `r = "sqrt(x^2 + y^2)"` declares the root where the radicand is wanted.
            let root = text.value.trim().strip_prefix("sqrt(");
            if let Some(inner) = root.and_then(|t| t.strip_suffix(')')) {
                if let Ok(under) = Expr::parse(&vars, inner) {
                    let name = name.get_ref();
                    return Err(self.error(
                        ErrorKind::Expression,
                        radicand.span(),
                        format!(
                            "a radicand is what stands under the root, without sqrt: write \
                             {name} = \"{inner}\", which declares {name} = √({under})"
                        ),
                    ));
                }
            }
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
    /// a time, each read in the variables with the atoms before it and declared by
    /// [`VarsBuilder::denominator`], as a program declares one. Refused: a text that
    /// does not read (placed in it), and what [`Expr::denominator_refusal`] refuses (zero, a
    /// single term, a polynomial that is not real, one that is a product of those declared
    /// before it).
    fn denominators(
        &self,
        declared: &[Spanned<String>],
        builder: VarsBuilder,
        mut vars: Vars,
    ) -> Result<Vars, FileError> {
        let mut builder = builder;
        for d in declared {
            let text = self.text(d);
            // A text that does not read is placed in it; one that reads is checked and
            // declared as a program declares it.
            if let Err(e) = Expr::parse(&vars, &text.value) {
                return Err(super::scope::expression_error(&self.source, &text, &e));
            }
            builder = builder
                .denominator(&text.value)
                .map_err(|e| self.error(ErrorKind::Expression, d.span(), e.to_string()))?;
            vars = builder
                .clone()
                .build()
                .map_err(|e| self.error(ErrorKind::Expression, d.span(), e.to_string()))?;
        }
        Ok(vars)
    }

    /// Builds the system in the order the file is read: the names of `[phase_space]`, the
    /// limits, the variables and the phase space with its declared brackets, then the
    /// Hamiltonian, the functions, the families and the claims, each of which may use only
    /// what comes before it.
    fn build(mut self, model: SystemModel) -> Result<LoadedSystem, FileError> {
        self.check_texts(&model)?;
        self.declare_variables(&model.phase_space)?;
        let limits = self.limits(&model)?;
        let vars = self.variables(&model, limits)?;
        let space = self.phase_space(&model.phase_space, &vars)?;
        let mut file = self.unfilled(&model, space, &vars, limits)?;
        match self.fill(&mut file, &model, &vars) {
            Ok(()) => Ok(file),
            // What the file's texts read in doubt before the error is said with it
            // ([`FileError::warnings`]): the file it was kept in is not returned.
            Err(e) => {
                let warnings = file.warnings();
                Err(FileError {
                    warnings: (!warnings.is_empty()).then(|| Box::new(warnings)),
                    ..e
                })
            }
        }
    }

    /// Fills `file`, made by [`Builder::unfilled`], with the brackets of `[poisson]`, the
    /// Hamiltonian, the functions, the families and the claims.
    fn fill(
        &mut self,
        file: &mut LoadedSystem,
        model: &SystemModel,
        vars: &Vars,
    ) -> Result<(), FileError> {
        if let Some(poisson) = &model.poisson {
            let space = self.poisson(file, poisson)?;
            file.system = System::new(&file.name, space, Expr::zero(vars))?;
        }
        let h = self.hamiltonian(file, model)?;
        file.system.define("H", "H", h)?;
        self.functions(file, model)?;
        self.families(file, model)?;
        claims(file, model)
    }

    /// Declares every name of `[phase_space]`, kind by kind (coordinates, angles, Poisson
    /// variables, parameters, radicals), then each coordinate's and angle's momentum, so that
    /// a name given twice is refused at its second place. A phase space without a coordinate,
    /// an angle or a Poisson variable is refused first.
    fn declare_variables(
        &mut self,
        phase_space: &Spanned<PhaseSpaceModel>,
    ) -> Result<(), FileError> {
        let ps = phase_space.get_ref();
        if ps.coordinates.is_empty() && ps.angles.is_empty() && ps.variables.is_empty() {
            return Err(self.error(
                ErrorKind::Schema,
                phase_space.span(),
                "[phase_space] declares no coordinates, angles or variables: a phase space \
                 needs at least one canonical pair or Poisson variable",
            ));
        }
        for (names, what) in [
            (&ps.coordinates, "a coordinate"),
            (&ps.angles, "an angle"),
            (&ps.variables, "a Poisson variable"),
            (&ps.parameters, "a parameter"),
        ] {
            for name in names {
                self.declare(name.get_ref(), name.span(), what)?;
            }
        }
        for (name, _) in declared_radicals(ps) {
            self.declare(name.get_ref(), name.span(), "a radical")?;
        }
        self.declare_momenta(ps)
    }

    /// Declares the momentum `p_q` of each coordinate and angle `q`, refused at `q` when that
    /// name is already declared (a parameter `p_x` beside a coordinate `x`).
    fn declare_momenta(&mut self, ps: &PhaseSpaceModel) -> Result<(), FileError> {
        for q in canonical_coordinates(ps) {
            let p = momentum(q);
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
        Ok(())
    }

    /// The variables of `[phase_space]` held to `limits`, with the radicals and then the
    /// denominator atoms added.
    fn variables(&mut self, model: &SystemModel, limits: Limits) -> Result<Vars, FileError> {
        let ps = model.phase_space.get_ref();
        let plain = variables_builder(ps, &model.function, limits, &[]);
        let vars = self.built(model, plain.clone())?;
        let shown = self.variable_displays(model, &vars)?;
        let (with_atoms, vars) = match shown.is_empty() {
            true => (plain, vars),
            false => {
                let builder = variables_builder(ps, &model.function, limits, &shown);
                let vars = self.built(model, builder.clone())?;
                (builder, vars)
            }
        };
        let (with_atoms, vars) = self.radicals(declared_radicals(ps), with_atoms, vars)?;
        let vars = self.denominators(&ps.denominators, with_atoms, vars)?;
        // The names shown by a display, at its line: a function shown alike is refused there.
        let lines: HashMap<String, usize> =
            shown.iter().map(|s| (s.name.clone(), s.line)).collect();
        self.shown = PrintedNames::of_variables_at(&vars, &lines, &[]);
        Ok(vars)
    }

    /// The variables of `builder`, a name refused at its place in `[phase_space]`.
    fn built(&self, model: &SystemModel, builder: VarsBuilder) -> Result<Vars, FileError> {
        let ps = model.phase_space.get_ref();
        builder.build().map_err(|e| {
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
            self.error(
                ErrorKind::Name,
                at.unwrap_or(model.phase_space.span()),
                e.to_string(),
            )
        })
    }

    /// The display names of `[phase_space] display` (`{ a = "ω₊" }`), each checked against
    /// `vars`, the variables as their names print: its key a coordinate, an angle, a Poisson
    /// variable or a parameter; its value a display name of one word (`ω₊`, `A_x`, `Z̄`,
    /// `G1'`) that prints apart from every other variable, and is no other's name. A
    /// coordinate's or angle's momentum is shown with it (`p_ω₊`).
    fn variable_displays(
        &self,
        model: &SystemModel,
        vars: &VarSet,
    ) -> Result<Vec<ShownVariable>, FileError> {
        let ps = model.phase_space.get_ref();
        let Some(table) = &ps.display else {
            return Ok(Vec::new());
        };
        let entries = &table.get_ref().entries;
        let displayed: Vec<String> = entries
            .iter()
            .flat_map(|(k, _)| [k.get_ref().clone(), format!("p_{}", k.get_ref())])
            .collect();
        let mut printed = PrintedNames::of_variables_at(vars, &HashMap::new(), &displayed);
        let mut shown = Vec::new();
        for (key, value) in entries {
            let var = vars.lookup(key.get_ref()).filter(|&v| {
                matches!(
                    vars.variable(v).kind(),
                    VarKind::Coordinate | VarKind::Angle | VarKind::Poisson | VarKind::Parameter
                )
            });
            let Some(var) = var else {
                let why = self.undisplayable(model, key.get_ref());
                return Err(self.error(ErrorKind::Name, key.span(), why));
            };
            // The declared name, where the key may be its other spelling (`omega` for `ω`).
            let name = &vars.variable(var).name().to_string();
            self.check_display(value)?;
            let display = value.get_ref();
            let refuse = |why: String| Err(self.error(ErrorKind::Name, value.span(), why));
            if trigpoly::has_several_words(display) {
                return refuse(format!(
                    "a variable's display is one name (ω₊, A_x, Z̄): '{display}' is several \
                     words, which beside a factor would read as a product of its own \
                     (2 {display})"
                ));
            }
            let Some((text, latex)) = trigpoly::shown_forms(display) else {
                return refuse(format!(
                    "a variable's display is a name, with primes, a bar or subscripts (ω₊, \
                     A_x, Z̄, G1'), which reads as one factor of a product: '{display}' is not"
                ));
            };
            let kind = vars.variable(var).kind();
            let whose = PrintedNames::whose_variable(kind, name);
            let line = super::error::locate(&self.source.text, value.span()).line;
            let alike = |why: String| refuse(format!("{why}: give it another display"));
            if let Err(why) = printed.admit_variable(&whose, name, &text, &latex, line) {
                return alike(why);
            }
            // A display that another variable's name spells would read back as that one.
            for spelling in [display.as_str(), text.as_str()] {
                if let Some(other) = vars.lookup(spelling).filter(|&o| o != var) {
                    let other = vars.variable(other);
                    return alike(format!(
                        "{whose} would show as {text}, which names {}",
                        PrintedNames::whose_variable(other.kind(), other.name())
                    ));
                }
            }
            shown.push(ShownVariable {
                name: name.clone(),
                text: text.clone(),
                latex: latex.clone(),
                line,
            });
            if matches!(kind, VarKind::Coordinate | VarKind::Angle) {
                let momentum = format!("p_{name}");
                // As a momentum of a coordinate so named is written: `p_{\theta1}` of `θ1`.
                let (text, latex) = trigpoly::momentum_forms(display)
                    .unwrap_or_else(|| (format!("p_{text}"), format!("p_{{{latex}}}")));
                let whose = PrintedNames::whose_variable(VarKind::Momentum, &momentum);
                if let Err(why) = printed.admit_variable(&whose, &momentum, &text, &latex, line) {
                    return alike(why);
                }
                shown.push(ShownVariable {
                    name: momentum,
                    text,
                    latex,
                    line,
                });
            }
        }
        Ok(shown)
    }

    /// Why `name`, a key of `[phase_space] display`, has no display there: a momentum is
    /// shown with its coordinate, a function or a family by its own `display`, a radical or a
    /// name not declared has none.
    fn undisplayable(&self, model: &SystemModel, name: &str) -> String {
        let ps = model.phase_space.get_ref();
        let what = "[phase_space] display shows a coordinate, an angle, a Poisson variable or a \
                    parameter";
        let coordinate = name.strip_prefix("p_").and_then(|q| {
            canonical_coordinates(ps)
                .into_iter()
                .find(|c| c.get_ref() == q)
        });
        if let Some(q) = coordinate {
            let q = q.get_ref();
            return format!(
                "'{name}' is the momentum of {q}, which shows as {q} does ({what}; with \
                 {q} = \"ξ\", {name} shows as p_ξ)"
            );
        }
        if model
            .function
            .iter()
            .any(|f| f.get_ref().name.get_ref() == name)
        {
            return format!(
                "'{name}' is a function: give it a display in its [[function]] ({what})"
            );
        }
        if model
            .family
            .iter()
            .any(|f| f.get_ref().name.get_ref() == name)
        {
            return format!("'{name}' is a family: give it a display in its [[family]] ({what})");
        }
        if let Some((kind, _)) = self.names.get(name) {
            return format!("'{name}' is {kind}, which has no display ({what})");
        }
        format!("'{name}' is not declared ({what} declared above it)")
    }

    /// The phase space of `vars`: each coordinate and angle paired with its momentum.
    fn phase_space(
        &self,
        phase_space: &Spanned<PhaseSpaceModel>,
        vars: &Vars,
    ) -> Result<PhaseSpace, FileError> {
        let pairs: Vec<(String, String)> = canonical_coordinates(phase_space.get_ref())
            .iter()
            .map(|q| (q.get_ref().clone(), momentum(q)))
            .collect();
        let pairs: Vec<(&str, &str)> = pairs
            .iter()
            .map(|(q, p)| (q.as_str(), p.as_str()))
            .collect();
        PhaseSpace::new(vars, &pairs)
            .map_err(|e| self.error(ErrorKind::Name, phase_space.span(), e.to_string()))
    }

    /// Refuses a `name`, `source` or `description` with a control or invisible character,
    /// which reports would show as `�` or with their lines broken (a description's line
    /// breaks and tabs are its own: [`check_shown_text`]).
    fn check_texts(&self, model: &SystemModel) -> Result<(), FileError> {
        for (key, value, lines) in [
            ("the system's name", &model.name, false),
            ("the system's source", &model.source, true),
            ("the system's description", &model.description, true),
        ] {
            if let Some(v) = value {
                check_shown_text(&self.source, &self.text(v), (key, ErrorKind::Schema), lines)?;
            }
        }
        Ok(())
    }

    /// The system as its phase space alone declares it, before its declared brackets,
    /// Hamiltonian (zero until it is read), functions, families and claims.
    fn unfilled(
        &self,
        model: &SystemModel,
        space: PhaseSpace,
        vars: &Vars,
        limits: Limits,
    ) -> Result<LoadedSystem, FileError> {
        let name = self.system_name(model);
        Ok(LoadedSystem {
            source: self.source.clone(),
            name: name.clone(),
            citation: over_lines(&model.source),
            description: over_lines(&model.description),
            system: System::new(&name, space, Expr::zero(vars))?,
            families: Vec::new(),
            claims: Vec::new(),
            limits,
            caller: super::Caller::Program,
            cache: Mutex::new(HashMap::new()),
            computed_from: Mutex::new(HashMap::new()),
            warnings: Warnings::default(),
            radicands: declared_radicals(model.phase_space.get_ref())
                .iter()
                .map(|(name, radicand)| (name.get_ref().clone(), radicand.get_ref().clone()))
                .collect(),
        })
    }

    /// The system's name: the file's `name`, else the file's name without its extension
    /// (`kepler` for `systems/kepler.toml`), else `system`.
    fn system_name(&self, model: &SystemModel) -> String {
        match &model.name {
            Some(n) => n.get_ref().clone(),
            None => Path::new(&self.source.origin).file_stem().map_or_else(
                || "system".to_string(),
                |s| s.to_string_lossy().into_owned(),
            ),
        }
    }

    /// The Hamiltonian, read in the variables and parameters alone (it cannot use `H`, nor a
    /// function, which is read after it).
    fn hamiltonian(&self, file: &LoadedSystem, model: &SystemModel) -> Result<Expr, FileError> {
        let h_text = self.text(&model.hamiltonian);
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
            let e = later_function(e, &model.function, |name| {
                format!(
                    "{name} is a function, and the Hamiltonian is read before the \
                     functions: it uses only variables and parameters, so write {name}'s \
                     value out"
                )
            });
            later_family(e, &model.family, |family, name| {
                format!(
                    "{family} is a family, and the Hamiltonian is read before the families: \
                     it uses only variables and parameters, so write {name}'s value out"
                )
            })
        })
    }

    /// The file's functions, in order: each read with the functions before it, its name
    /// declared and its display checked against every name shown so far.
    fn functions(&mut self, file: &mut LoadedSystem, model: &SystemModel) -> Result<(), FileError> {
        for (k, f) in model.function.iter().enumerate() {
            let f = f.get_ref();
            self.declare(f.name.get_ref(), f.name.span(), "a function")?;
            let (value, inputs) = file
                .scope(0)
                .parse_recorded(&self.source, &self.text(&f.value))
                .map_err(|e| {
                    let e = later_function(e, &model.function[k + 1..], |name| {
                        format!(
                            "{name} is declared further down, and a function uses only the \
                             functions declared before it: move this one below {name}"
                        )
                    });
                    later_family(e, &model.family, |family, name| {
                        format!(
                            "{family} is a family, and the functions are read before the \
                             families: a function uses none, so write {name}'s value out"
                        )
                    })
                })?;
            if let Some(d) = &f.display {
                self.check_display(d)?;
            }
            let display = f.display.as_ref().unwrap_or(&f.name).get_ref();
            let whose = format!("the function {}", f.name.get_ref());
            let span = f.display.as_ref().unwrap_or(&f.name).span();
            self.check_shown_apart(&whose, f.name.get_ref(), display, span)?;
            file.system.define(f.name.get_ref(), display, value)?;
            file.keep_computed_from(f.name.get_ref().clone(), inputs);
        }
        Ok(())
    }

    /// The file's families: their indices and displays checked, each value and eigenvalue
    /// tried on the instance `(1, 1)`.
    fn families(&mut self, file: &mut LoadedSystem, model: &SystemModel) -> Result<(), FileError> {
        for (position, spanned) in model.family.iter().enumerate() {
            let f = spanned.get_ref();
            self.declare(f.name.get_ref(), f.name.span(), FAMILY)?;
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
            // Another spelling of a variable (`ω` beside `omega`) is taken too: the index
            // would print as the variable does (`K_{ω,n}`, `ωω`).
            let vars = file.system.vars().clone();
            let taken = |idx: &str| {
                self.names
                    .get(idx)
                    .map(|(other, _)| format!("declared as {other}"))
                    .or_else(|| {
                        let v = vars.variable(vars.lookup(idx)?);
                        let described = v.kind().described();
                        let kind = described.split_once(' ').map_or(described, |(_, k)| k);
                        Some(format!(
                            "a name of the {kind} '{}' (either spelling names it)",
                            v.name()
                        ))
                    })
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
            if let Err(why) =
                self.shown
                    .admit_family(&whose, f.name.get_ref(), &display, Some(line))
            {
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
            let later = |e| {
                later_family(e, &model.family[position + 1..], |family, _| {
                    format!(
                        "{family} is declared further down, and a family uses only the families \
                         declared before it: move this one ({}) below {family}",
                        f.name.get_ref()
                    )
                })
            };
            if let Err(e) = file.scope(k + 1).expand(k, 1, 1, &self.source, || 0..0) {
                // A value that fails at (1, 1) but not at (2, 2) (`(x + y)^(m - 2)`, a negative
                // power there, `x^(m/2)`, a root) fails for its indices: say which.
                let at_two = file.scope(k + 1).expand(k, 2, 2, &self.source, || 0..0);
                let e = match (&e.hint, at_two) {
                    (None, Ok(_)) => {
                        let [m, n] = &file.families[k].indices;
                        e.with_hint(format!(
                            "this is the instance {}_{{1,1}} ({m} = 1, {n} = 1), which is \
                             computed when the file is loaded: a family's value must hold for \
                             every {m}, {n} ≥ 0",
                            file.families[k].display
                        ))
                    }
                    _ => e,
                };
                return Err(later(e));
            }
            if file.families[k].eigenvalue.is_some() {
                file.eigenvalue_at(k, 1, 1).map_err(later)?;
            }
        }
        Ok(())
    }

    /// The limits: the command line's, else the file's, else the defaults.
    fn limits(&self, model: &SystemModel) -> Result<Limits, FileError> {
        let file = model.limits.as_ref().map(|l| l.get_ref());
        let terms = file.and_then(|l| l.max_terms.as_ref());
        let degree = file.and_then(|l| l.max_degree.as_ref());
        let work = file.and_then(|l| l.max_term_products.as_ref());
        for (name, given) in [("max_terms", terms), ("max_term_products", work)] {
            if let Some(t) = given.filter(|t| *t.get_ref() < 1) {
                return Err(self.error(
                    ErrorKind::Schema,
                    t.span(),
                    format!("{name} must be at least 1"),
                ));
            }
        }
        let ceiling = i64::from(MAX_DEGREE_CEILING);
        if let Some(d) = degree.filter(|d| !(1..=ceiling).contains(d.get_ref())) {
            return Err(self.error(
                ErrorKind::Schema,
                d.span(),
                format!("max_degree must be between 1 and {MAX_DEGREE_CEILING}"),
            ));
        }
        // A limit given in code out of its range is refused as the file's and the command
        // line's are: a term limit of 0 stopped at the Hamiltonian with 'more than 0 terms', a
        // work limit of 0 was taken, and a degree limit past the ceiling was lowered to it.
        let degrees = 1..=MAX_DEGREE_CEILING;
        let out_of_range = [
            self.limits
                .max_terms
                .filter(|&t| t == 0)
                .map(|t| ("max_terms", t.to_string(), "at least 1".to_string())),
            self.limits
                .max_degree
                .filter(|d| !degrees.contains(d))
                .map(|d| {
                    let range = format!("between 1 and {MAX_DEGREE_CEILING}");
                    ("max_degree", d.to_string(), range)
                }),
            self.limits
                .max_term_products
                .filter(|&w| w == 0)
                .map(|w| ("max_term_products", w.to_string(), "at least 1".to_string())),
        ];
        if let Some((name, value, range)) = out_of_range.into_iter().flatten().next() {
            return Err(FileError::new(
                ErrorKind::Schema,
                &self.source.origin,
                format!(
                    "the LimitsOverride given to the loader sets {name} to {value}; it must be \
                     {range}"
                ),
            ));
        }
        // Each is positive now, and max_degree at most the ceiling.
        let positive = |t: &Spanned<i64>| u64::try_from(*t.get_ref()).unwrap_or(u64::MAX);
        let given = LimitsOverride {
            max_terms: self
                .limits
                .max_terms
                .or(terms.map(|t| usize::try_from(positive(t)).unwrap_or(usize::MAX))),
            max_degree: self
                .limits
                .max_degree
                .or(degree.map(|d| positive(d) as u32)),
            max_term_products: self.limits.max_term_products.or(work.map(positive)),
            max_reserved_bytes: self.limits.max_reserved_bytes,
        };
        Ok(given.or_defaults())
    }
}

/// An unknown name that is one of the functions `later` (declared further down the file) gets
/// the hint `hint(name)`.
fn later_function(
    e: FileError,
    later: &[Spanned<FunctionModel>],
    hint: impl Fn(&str) -> String,
) -> FileError {
    match e
        .unknown_name()
        .filter(|n| later.iter().any(|f| f.get_ref().name.get_ref() == n))
    {
        Some(name) => e.with_hint(hint(&name)),
        None => e,
    }
}

/// An unknown name written as an instance of one of the families `later` (read after the
/// text at fault: `K_2_3`, `K_m_n`, `K_` of `K_{m,n}` for a family `K`) gets the hint
/// `hint(family, name)`.
fn later_family(
    e: FileError,
    later: &[Spanned<FamilyModel>],
    hint: impl Fn(&str, &str) -> String,
) -> FileError {
    let name = e.unknown_name();
    let family = name.as_deref().and_then(|n| {
        later.iter().map(|f| f.get_ref().name.get_ref()).find(|f| {
            n.strip_prefix(f.as_str())
                .is_some_and(|rest| rest.starts_with('_'))
        })
    });
    match (family, &name) {
        (Some(family), Some(name)) => {
            let hint = hint(family, name);
            e.with_hint(hint)
        }
        _ => e,
    }
}

/// Reads the file's claims, in order, each with every function and family of the file.
fn claims(file: &mut LoadedSystem, model: &SystemModel) -> Result<(), FileError> {
    for (k, c) in model.claim.iter().enumerate() {
        let spec = ClaimSpec::parse(file, k, c)?;
        file.claims.push(spec);
    }
    Ok(())
}

/// The coordinates and angles of `[phase_space]`, in that order: the variables that have a
/// momentum.
fn canonical_coordinates(ps: &PhaseSpaceModel) -> Vec<&Spanned<String>> {
    ps.coordinates.iter().chain(&ps.angles).collect()
}

/// The momentum of a coordinate or angle `q`: `p_q`.
fn momentum(q: &Spanned<String>) -> String {
    format!("p_{}", q.get_ref())
}

/// Why the value `e` of a declared bracket is refused, if it is, with what to do: it has a
/// negative power of a variable of phase space (`M2/M1`; a parameter's, `M2/a`, is a number's,
/// and an angle's is `e^{−iθ}`), which no declared denominator stands for (a denominator is a
/// sum of terms: a single term is refused there). Declared denominators
/// (`s/(x² + y²)`) and radicals of any power (`s z/r³`) are taken: the bracket goes through
/// them by the chain rule (`brackets::PhaseSpace`).
fn negative_power(e: &Expr) -> Option<(String, String)> {
    let vars = e.vars();
    let kind = |v: Var| vars.variable(v).kind();
    let divided_by = vars.vars().find(|&v| {
        !matches!(
            kind(v),
            VarKind::Parameter | VarKind::Angle | VarKind::Radical | VarKind::Denominator
        ) && e.low_degree(v).is_some_and(|low| low < 0)
    })?;
    let v = vars.variable(divided_by).unicode().to_string();
    let hint = format!("write it without dividing by {v}");
    Some((format!("has a negative power of {v}"), hint))
}

/// The radicals of `[phase_space]`, each name with its radicand; none when it has none.
fn declared_radicals(ps: &PhaseSpaceModel) -> &[(Spanned<String>, Spanned<String>)] {
    ps.radicals
        .as_ref()
        .map_or(&[][..], |r| &r.get_ref().entries)
}

/// The builder of the variables of `[phase_space]`, in the order of a `VarSet` (coordinates,
/// angles, their momenta, Poisson variables, parameters), held to `limits`.
fn variables_builder(
    ps: &PhaseSpaceModel,
    functions: &[Spanned<FunctionModel>],
    limits: Limits,
    shown: &[ShownVariable],
) -> VarsBuilder {
    // Each variable printed as its display shows it, if it has one.
    let show = |builder: VarsBuilder, name: &str| match shown.iter().find(|s| s.name == name) {
        Some(s) => builder.printed_as(&s.text, &s.latex),
        None => builder,
    };
    let mut builder = Vars::builder().limits(limits);
    for c in &ps.coordinates {
        builder = show(builder.coordinate(c.get_ref()), c.get_ref());
    }
    for a in &ps.angles {
        builder = show(builder.angle(a.get_ref()), a.get_ref());
    }
    for q in canonical_coordinates(ps) {
        let p = momentum(q);
        builder = show(builder.momentum(&p), &p);
    }
    for v in &ps.variables {
        builder = show(builder.poisson(v.get_ref()), v.get_ref());
    }
    for p in &ps.parameters {
        builder = show(builder.parameter(p.get_ref()), p.get_ref());
    }
    // The functions' names, which the printer must not spell with variables (`Mx`).
    builder.also_named(functions.iter().flat_map(|f| {
        let f = f.get_ref();
        [Some(&f.name), f.display.as_ref()]
            .into_iter()
            .flatten()
            .map(|n| n.get_ref().as_str())
    }))
}

/// A variable shown by `[phase_space] display`, or the momentum of one: its name, its forms
/// in text and in LaTeX, and the line of its display.
struct ShownVariable {
    name: String,
    text: String,
    latex: String,
    line: usize,
}

/// How [`Builder::declare`] calls a family.
const FAMILY: &str = "a family";
