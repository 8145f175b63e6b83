//! [`Text`]: an expression string together with where it sits in its source, so that a byte
//! span inside the string maps to a byte span of the file.
//!
//! A TOML string's value starts after its opening quote (three quotes, and a newline right
//! after them, for a multi-line string). When the raw text between the quotes is the decoded
//! value itself (no escapes), spans map one to one; otherwise, when a message asks,
//! [`escape_map`] reads the raw text again and says, for each byte of the value, which raw
//! bytes wrote it (an escape such as `\u00e9` for each byte of its character, a line-ending
//! backslash for none), so that a span maps to the raw text that wrote it.

use std::ops::Range;
use std::sync::Arc;

use trigpoly::Span;

use super::error::{ErrorKind, FileError};

/// The source an expression comes from: a file's text, a text a program gave, or the command
/// line. Its `Debug` gives the text's length, not the text, which every claim and family of a
/// file shares.
#[derive(Clone)]
pub struct Source {
    /// The file's path as given, or the name of the text (`<expression>`, `<command line>`).
    pub origin: String,
    /// The whole text.
    pub text: Arc<str>,
    /// Who gave the text, about what system: what its hints name (a file's tables or the
    /// library's calls) and whose settings raise a limit it meets
    /// ([`LimitSettings`](super::LimitSettings)).
    pub(crate) given: Given,
}

/// Who gave a text and about what system, set where its [`Source`] is made: its hints name the
/// giver's means (a file's tables, the command line's options, the library's calls), and a
/// limit the text meets is raised by the giver's settings, which its hint names. A system's
/// own source is [`Given::InFile`] for a system file and [`Given::InCode`] for one built in
/// code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Given {
    /// A system file's own text, which the command line or a program loaded.
    InFile,
    /// A text the command line gave about a system file, or the file piped on standard input,
    /// which only the command line reads.
    CommandLineAboutFile,
    /// A text the command line gave about a built-in system (`--system harmonic`), which has
    /// no file and to which its user can add no name.
    CommandLineAboutBuiltIn,
    /// A text a program gave a report about a system file (`<expression>`, `<condition>`):
    /// its hints are the file's own.
    ProgramAboutFile,
    /// A text a program added to a system file or read against it by the library's calls
    /// (`LoadedSystem::parse`, `add_function`, a display name given in code): its hints name
    /// the library's calls.
    ProgramAddingToFile,
    /// A system built in code (a built-in one too), or a text a program gave about one.
    InCode,
}

impl Given {
    /// Whether the system the text is about has a file (not one built in code, nor a built-in
    /// one, `--system harmonic`): for a system's own source, whether it is a file's.
    pub(crate) fn about_file(self) -> bool {
        match self {
            Given::InFile
            | Given::CommandLineAboutFile
            | Given::ProgramAboutFile
            | Given::ProgramAddingToFile => true,
            Given::CommandLineAboutBuiltIn | Given::InCode => false,
        }
    }

    /// Whether hints name the library's calls, not a file's tables: a text of a system built
    /// in code, or one a program added to a system (a function added in code, say).
    pub(crate) fn names_library(self) -> bool {
        match self {
            Given::ProgramAddingToFile | Given::CommandLineAboutBuiltIn | Given::InCode => true,
            Given::InFile | Given::CommandLineAboutFile | Given::ProgramAboutFile => false,
        }
    }

    /// Who gives a text `caller` gives about the system this one is about: the command line's
    /// text or a program's report's, about a file or a system with none.
    pub(crate) fn by(self, caller: super::Caller) -> Given {
        match (caller, self.about_file()) {
            (super::Caller::CommandLine, true) => Given::CommandLineAboutFile,
            (super::Caller::CommandLine, false) => Given::CommandLineAboutBuiltIn,
            (super::Caller::Program, true) => Given::ProgramAboutFile,
            (super::Caller::Program, false) => Given::InCode,
        }
    }
}

/// `Source { origin: "systems/kepler.toml", text: <4211 bytes>, given: InFile }`: a file's
/// text, shared by each of its claims and families, is printed by none of them.
impl std::fmt::Debug for Source {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Source")
            .field("origin", &self.origin)
            .field("text", &format_args!("<{} bytes>", self.text.len()))
            .field("given", &self.given)
            .finish()
    }
}

impl Source {
    /// A source with its origin, a system file's own text.
    pub fn new(origin: &str, text: &str) -> Self {
        Source::given_by(origin, text, Given::InFile)
    }

    /// A source with its origin, given by `given`.
    pub(crate) fn given_by(origin: &str, text: &str, given: Given) -> Self {
        Source {
            origin: origin.to_string(),
            text: Arc::from(text),
            given,
        }
    }

    /// A text the command line gave, named `origin` in messages, about a system file.
    pub(crate) fn on_command_line(origin: &str, text: &str) -> Self {
        Source::given_by(origin, text, Given::CommandLineAboutFile)
    }

    /// A text a program gave, named `origin` in messages, to a system file.
    pub(crate) fn program(origin: &str, text: &str) -> Self {
        Source::given_by(origin, text, Given::ProgramAddingToFile)
    }

    /// A text a program gave, named `origin` in messages, to the system of `about`: one with
    /// a file or not, as it is.
    pub(crate) fn program_about(about: &Source, origin: &str, text: &str) -> Self {
        let given = match about.given.about_file() {
            true => Given::ProgramAddingToFile,
            false => Given::InCode,
        };
        Source::given_by(origin, text, given)
    }

    /// An error at a byte range of this source.
    pub fn error(
        &self,
        kind: ErrorKind,
        span: Range<usize>,
        message: impl Into<String>,
    ) -> FileError {
        FileError::at(kind, &self.origin, &self.text, span, message)
    }
}

/// An expression (or claim, or condition) string and where it is.
#[derive(Clone, Debug)]
pub struct Text {
    /// The decoded string.
    pub value: String,
    /// The byte offset in the source of `value[0]`, when the raw text is the value itself.
    offset: Option<usize>,
    /// The basic string the value was decoded from when the raw text differs from the value
    /// (escapes), and where the value starts in that string's value.
    escaped: Option<(Arc<Escaped>, usize)>,
    /// Where errors point when the raw text is neither the value nor read again to it: the
    /// value's first byte.
    anchor: usize,
}

/// A TOML basic string written with escapes: its raw text between the quotes, where that
/// starts in the source, and its decoded value. Spans through it are mapped only when asked
/// ([`Escaped::map`]), on the way to a message, so a long string with escapes costs a copy of
/// its text, not a range for each of its bytes.
struct Escaped {
    /// The raw text between the quotes (after the newline a multi-line string's opening
    /// quotes trim).
    raw: Box<str>,
    /// The byte offset of `raw` in the source.
    start: usize,
    /// Whether the string is a multi-line one (`"""`), where a backslash may end a line.
    multiline: bool,
    /// The decoded value of the whole string.
    value: Box<str>,
}

/// `Escaped { start: 120, raw: <48 bytes>, multiline: false }`: the texts by their lengths.
impl std::fmt::Debug for Escaped {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Escaped")
            .field("start", &self.start)
            .field("raw", &format_args!("<{} bytes>", self.raw.len()))
            .field("multiline", &self.multiline)
            .finish()
    }
}

impl Escaped {
    /// For each byte of the value, the byte range in the source of what wrote it, and one
    /// more, empty range at the end ([`escape_map`]); `None` where the raw text does not read
    /// to the value.
    fn map(&self) -> Option<Vec<Range<usize>>> {
        let map = escape_map(&self.raw, self.multiline, &self.value)?;
        Some(
            map.into_iter()
                .map(|r| self.start + r.start..self.start + r.end)
                .collect(),
        )
    }
}

impl Text {
    /// The whole of a source (a command-line argument).
    pub fn whole(source: &Source) -> Self {
        Text {
            value: source.text.to_string(),
            offset: Some(0),
            escaped: None,
            anchor: 0,
        }
    }

    /// The bytes `range` of `source`, whose text is the value itself (a text given in code).
    pub(crate) fn within(source: &Source, range: Range<usize>) -> Self {
        Text {
            value: source.text[range.clone()].to_string(),
            offset: Some(range.start),
            escaped: None,
            anchor: range.start,
        }
    }

    /// A TOML string whose token (quotes included) is `span` in `file`, decoded as `value`.
    pub fn in_toml(file: &str, span: Range<usize>, value: &str) -> Self {
        let raw = file.get(span.clone()).unwrap_or("");
        let delim = ["\"\"\"", "'''", "\"", "'"]
            .into_iter()
            .find(|d| raw.starts_with(d) && raw.len() >= 2 * d.len() && raw.ends_with(d));
        let Some(d) = delim else {
            return Text {
                value: value.to_string(),
                offset: None,
                escaped: None,
                anchor: span.start,
            };
        };
        let mut start = span.start + d.len();
        let mut inner = &raw[d.len()..raw.len() - d.len()];
        if d.len() == 3 {
            for newline in ["\r\n", "\n"] {
                if let Some(rest) = inner.strip_prefix(newline) {
                    inner = rest;
                    start += newline.len();
                    break;
                }
            }
        }
        let offset = (inner == value).then_some(start);
        // Only a basic string has escapes.
        let escaped = (offset.is_none() && d.starts_with('"')).then(|| {
            let string = Escaped {
                raw: inner.into(),
                start,
                multiline: d.len() == 3,
                value: value.into(),
            };
            (Arc::new(string), 0)
        });
        Text {
            value: value.to_string(),
            offset,
            escaped,
            anchor: start,
        }
    }

    /// The part `range` of this text (byte offsets into `value`), keeping the mapping.
    #[must_use]
    pub fn slice(&self, range: Range<usize>) -> Text {
        Text {
            value: self.value[range.clone()].to_string(),
            offset: self.offset.map(|o| o + range.start),
            escaped: (self.escaped.as_ref())
                .map(|(string, shift)| (string.clone(), shift + range.start)),
            anchor: self.anchor,
        }
    }

    /// The same place with a value of the same length (a rewritten form of the value).
    pub(crate) fn rewritten(&self, value: String) -> Text {
        debug_assert_eq!(value.len(), self.value.len());
        Text {
            value,
            offset: self.offset,
            escaped: self.escaped.clone(),
            anchor: self.anchor,
        }
    }

    /// The pieces of this text between the top-level occurrences of `sep` (outside
    /// parentheses and braces), keeping the mapping.
    pub(crate) fn split(&self, sep: char) -> Vec<Text> {
        split_top_level(&self.value, sep)
            .into_iter()
            .map(|r| self.slice(r))
            .collect()
    }

    /// The span in the source of a span inside the value: through escapes, from the start of
    /// what wrote its first byte to the end of what wrote its last (an empty span at what
    /// writes the byte after it).
    pub fn source_span(&self, span: Span) -> Range<usize> {
        if let Some(o) = self.offset {
            return o + span.start..o + span.end;
        }
        let Some((map, shift)) = self.escape_map() else {
            return self.anchor..self.anchor + 1;
        };
        let start = self.written(&map, shift, span.start).start;
        match span.end > span.start {
            true => start..self.written(&map, shift, span.end - 1).end.max(start),
            false => start..start,
        }
    }

    /// The map of the string the value was decoded from ([`Escaped::map`]) and where the value
    /// starts in it; `None` where the value is the raw text, or the string does not read back.
    fn escape_map(&self) -> Option<(Vec<Range<usize>>, usize)> {
        let (string, shift) = self.escaped.as_ref()?;
        Some((string.map()?, *shift))
    }

    /// Where in the source what wrote the value's byte `k` is (an escape for each byte of its
    /// character), `k` at most the value's length (the empty range just after the value).
    fn written(&self, map: &[Range<usize>], shift: usize, k: usize) -> Range<usize> {
        let at = shift + k.min(self.value.len());
        map.get(at)
            .or(map.last())
            .cloned()
            .unwrap_or(self.anchor..self.anchor + 1)
    }

    /// The span in the source of the one-byte separator just before the value (the comma
    /// before a piece of a list; `after`: just after it), or of the whole value where the value
    /// is not found in its source as written.
    pub(crate) fn separator(&self, after: bool) -> Range<usize> {
        match (self.offset, after) {
            (Some(o), false) if o > 0 => return o - 1..o,
            (Some(o), true) => return o + self.value.len()..o + self.value.len() + 1,
            _ => {}
        }
        match (self.escape_map(), after) {
            (Some((map, shift)), false) if shift > 0 => map
                .get(shift - 1)
                .cloned()
                .unwrap_or_else(|| self.whole_span()),
            (Some((map, shift)), true) => match self.written(&map, shift, self.value.len()) {
                next if next.is_empty() => next.start..next.start + 1,
                next => next,
            },
            _ => self.whole_span(),
        }
    }

    /// The span in the source of the whole value.
    pub fn whole_span(&self) -> Range<usize> {
        self.source_span(Span::new(0, self.value.len()))
    }

    /// The span of the value without its surrounding spaces (a condition's ` 2*M`).
    pub fn trimmed_span(&self) -> Span {
        let lead = self.value.len() - self.value.trim_start().len();
        Span::new(lead, self.value.trim_end().len())
    }

    /// An error at a span inside the value.
    pub fn error(
        &self,
        source: &Source,
        kind: ErrorKind,
        span: Span,
        message: impl Into<String>,
    ) -> FileError {
        source.error(kind, self.source_span(span), message)
    }
}

/// Where each byte of a TOML basic string's value was written, read again from the raw text
/// `inner` between its quotes (after the newline a multi-line string's opening quotes trim):
/// for each byte of `value`, the byte range of `inner` that wrote it (a character as written,
/// or the whole escape, `\"`, `\u00e9`, for each byte of its character), and one more, empty
/// range at the end of the text. The escapes are TOML 1.1's (the `toml` crate's): `\b \t \n
/// \f \r \e \" \\`, `\xHH`, `\uHHHH` and `\UHHHHHHHH`. A backslash ending a line of a `multiline` string, with the
/// spaces and line breaks after it, writes nothing. `None` where the text does not read to
/// `value` (a string the TOML reader read otherwise), so that nothing is pointed at wrongly.
pub(crate) fn escape_map(inner: &str, multiline: bool, value: &str) -> Option<Vec<Range<usize>>> {
    let bytes = inner.as_bytes();
    let hex = |at: usize, digits: usize| {
        let h = inner.get(at..at + digits)?;
        match h.bytes().all(|b| b.is_ascii_hexdigit()) {
            true => char::from_u32(u32::from_str_radix(h, 16).ok()?),
            false => None,
        }
    };
    let mut decoded = String::with_capacity(value.len());
    let mut map = Vec::with_capacity(value.len() + 1);
    let mut k = 0;
    while k < bytes.len() {
        let (c, width) = match bytes[k] {
            b'\\' => match bytes.get(k + 1) {
                Some(b' ' | b'\t' | b'\r' | b'\n') if multiline => {
                    k = line_ending_backslash(bytes, k + 1)?;
                    continue;
                }
                Some(b'b') => ('\u{8}', 2),
                Some(b'e') => ('\u{1b}', 2),
                Some(b'f') => ('\u{c}', 2),
                Some(b'n') => ('\n', 2),
                Some(b'r') => ('\r', 2),
                Some(b't') => ('\t', 2),
                Some(b'"') => ('"', 2),
                Some(b'\\') => ('\\', 2),
                Some(b'x') => (hex(k + 2, 2)?, 4),
                Some(b'u') => (hex(k + 2, 4)?, 6),
                Some(b'U') => (hex(k + 2, 8)?, 10),
                _ => return None,
            },
            _ => {
                let c = inner.get(k..)?.chars().next()?;
                (c, c.len_utf8())
            }
        };
        decoded.push(c);
        map.extend(std::iter::repeat_n(k..k + width, c.len_utf8()));
        k += width;
    }
    map.push(bytes.len()..bytes.len());
    (decoded == value).then_some(map)
}

/// The end of a line-ending backslash's run in a multi-line basic string, from just after the
/// backslash at `k`: spaces and tabs, a line break, then any spaces, tabs and line breaks;
/// `None` if no line break comes first.
fn line_ending_backslash(bytes: &[u8], mut k: usize) -> Option<usize> {
    let newline = |k: usize| match bytes.get(k..) {
        Some([b'\n', ..]) => Some(1),
        Some([b'\r', b'\n', ..]) => Some(2),
        _ => None,
    };
    while matches!(bytes.get(k), Some(b' ' | b'\t')) {
        k += 1;
    }
    k += newline(k)?;
    loop {
        match bytes.get(k) {
            Some(b' ' | b'\t') => k += 1,
            _ => match newline(k) {
                Some(n) => k += n,
                None => return Some(k),
            },
        }
    }
}

/// `text` split at every comma, each piece with the byte where it begins (a list given to an
/// option, `--fix`'s or `--family`'s, whose pieces a refusal points into).
pub fn comma_pieces(text: &str) -> Vec<(usize, &str)> {
    let mut at = 0;
    text.split(',')
        .map(|piece| {
            let start = at;
            at += piece.len() + 1;
            (start, piece)
        })
        .collect()
}

/// The trimmed part of `piece`, which begins at byte `at` of its text, with its byte range
/// there (an empty range where the blanks end, for a blank piece).
pub fn trimmed(at: usize, piece: &str) -> (&str, Range<usize>) {
    let start = at + piece.len() - piece.trim_start().len();
    (piece.trim(), start..start + piece.trim().len())
}

/// Splits `s` at the top-level (outside parentheses and braces) occurrences of `sep`: the
/// byte ranges of the pieces.
pub fn split_top_level(s: &str, sep: char) -> Vec<Range<usize>> {
    let mut depth = 0i32;
    let mut pieces = Vec::new();
    let mut start = 0;
    for (k, c) in s.char_indices() {
        match c {
            '(' | '{' => depth += 1,
            ')' | '}' => depth -= 1,
            c if c == sep && depth == 0 => {
                pieces.push(start..k);
                start = k + c.len_utf8();
            }
            _ => {}
        }
    }
    pieces.push(start..s.len());
    pieces
}

/// The first bracket of `s` that does not pair up, and what is wrong with it: a closing one
/// with nothing open or of the other kind, or an opening one never closed; its byte offset.
pub(crate) fn unbalanced_bracket(s: &str) -> Option<(usize, String)> {
    let mut open = Vec::new();
    for (k, c) in s.char_indices() {
        match c {
            '(' | '{' => open.push((k, c)),
            ')' | '}' => match open.pop() {
                Some((_, o)) if (o, c) == ('(', ')') || (o, c) == ('{', '}') => {}
                Some((_, o)) => {
                    return Some((k, format!("this '{c}' does not close the '{o}' before it")))
                }
                None => return Some((k, format!("this '{c}' closes nothing"))),
            },
            _ => {}
        }
    }
    open.first()
        .map(|&(k, c)| (k, format!("this '{c}' is never closed")))
}

/// The spans of the string literals of a TOML array whose token is `span` in `file`, in
/// order (skipping comments); `None` if the array holds something else.
pub(crate) fn array_strings(file: &str, span: Range<usize>) -> Option<Vec<Range<usize>>> {
    let raw = file.get(span.clone())?;
    let bytes = raw.as_bytes();
    let mut out = Vec::new();
    let mut k = 0;
    while k < bytes.len() {
        match bytes[k] {
            b'#' => {
                while k < bytes.len() && bytes[k] != b'\n' {
                    k += 1;
                }
            }
            q @ (b'"' | b'\'') => {
                let triple = raw[k..].starts_with(if q == b'"' { "\"\"\"" } else { "'''" });
                let d = if triple { 3 } else { 1 };
                let start = k;
                k += d;
                loop {
                    if k >= bytes.len() {
                        return None;
                    }
                    if q == b'"' && bytes[k] == b'\\' {
                        k += 2;
                        continue;
                    }
                    if bytes[k] == q && (!triple || raw[k..].starts_with(&raw[start..start + 3])) {
                        k += d;
                        break;
                    }
                    k += 1;
                }
                out.push(span.start + start..span.start + k);
                continue;
            }
            b'[' | b']' | b',' | b' ' | b'\t' | b'\n' | b'\r' => {}
            _ => return None,
        }
        k += 1;
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_maps_spans_into_the_file() {
        let file = "value = \"x + y\"\n";
        let t = Text::in_toml(file, 8..15, "x + y");
        assert_eq!(t.source_span(Span::new(4, 5)), 13..14);
        let escaped = "value = \"x + \\u0079\"\n";
        let t = Text::in_toml(escaped, 8..20, "x + y");
        assert_eq!(t.source_span(Span::new(4, 5)), 13..19);
        let multi = "value = \"\"\"\nx + y\"\"\"\n";
        let t = Text::in_toml(multi, 8..multi.len() - 1, "x + y");
        assert_eq!(t.source_span(Span::new(0, 1)), 12..13);
    }

    /// The text of `v = <token>` and its mapping, the token's range and the value, or `None`
    /// where the TOML reader refuses the file.
    fn mapped(token: &str) -> Option<(Text, Range<usize>, String)> {
        let file = format!("v = {token}\n");
        let table: toml::Table = toml::from_str(&file).ok()?;
        let value = table.get("v")?.as_str()?.to_string();
        let span = 4..4 + token.len();
        Some((Text::in_toml(&file, span.clone(), &value), span, value))
    }

    #[test]
    fn escapes_map_to_where_they_are_written() {
        let at = |token: &str, from: &str| {
            let (t, span, value) = mapped(token).unwrap();
            let k = value.find(from).unwrap();
            let file = format!("v = {token}\n");
            let r = t.source_span(Span::new(k, k + from.len()));
            assert!(span.start <= r.start && r.end <= span.end, "{token}: {r:?}");
            file[r].to_string()
        };
        // After a quote written `\"`, an escaped `é`, and on the line after a line-ending
        // backslash.
        assert_eq!(at(r#""{L, G1} = \"x\" + $""#, "$"), "$");
        assert_eq!(at(r#""{L, G1} = \"x\" + $""#, "\"x"), r#"\"x"#);
        assert_eq!(at(r#""\u00e9 + $""#, "$"), "$");
        assert_eq!(at(r#""\u00e9 + $""#, "é"), r"\u00e9");
        assert_eq!(at(r#""\U0001F600 + \x41""#, "😀"), r"\U0001F600");
        assert_eq!(at(r#""\U0001F600 + \x41""#, "A"), r"\x41");
        let lines = "\"\"\"\na \\\n   \n  b\\tc\"\"\"";
        assert_eq!(at(lines, "b"), "b");
        assert_eq!(at(lines, "\tc"), "\\tc");
        let crlf = "\"\"\"\r\na \\  \r\n\r\n b\\e\r\nc\"\"\"";
        assert_eq!(at(crlf, "b\u{1b}"), "b\\e");
        assert_eq!(at(crlf, "\r\nc"), "\r\nc");
        // A span over a line-ending backslash ends at the character written last.
        assert_eq!(at("\"\"\"a \\\n b\\t\"\"\"", "a b"), "a \\\n b");
    }

    /// A piece of a basic string's raw text: characters of one, two and four bytes, and
    /// escapes; in a multi-line string also line breaks, quotes and line-ending backslashes.
    fn piece(multiline: bool) -> proptest::sample::Select<&'static str> {
        let basic = [
            "a",
            "+",
            " ",
            "é",
            "😀",
            "\\\"",
            "\\\\",
            "\\t",
            "\\n",
            "\\r",
            "\\b",
            "\\f",
            "\\e",
            "\\x41",
            "\\u00e9",
            "\\u0007",
            "\\U0001F600",
            "{",
            ",",
        ];
        let lines = ["\n", "\r\n", "\"", "\\\n", "\\ \t\r\n\n  ", "\\\n\n\t"];
        proptest::sample::select(match multiline {
            true => basic.into_iter().chain(lines).collect::<Vec<_>>(),
            false => basic.to_vec(),
        })
    }

    proptest::proptest! {
        /// Every span of an escaped value maps inside its token, on characters' boundaries;
        /// a value without escapes maps one to one, as it did.
        #[test]
        fn every_span_maps_inside_the_token(
            basic in proptest::collection::vec(piece(false), 0..12),
            multi in proptest::collection::vec(piece(true), 0..12),
            literal in "[a-z é😀\\\\\"+,]{0,12}",
            start_newline in proptest::bool::ANY,
        ) {
            let newline = if start_newline { "\n" } else { "" };
            let tokens = [
                format!("\"{}\"", basic.concat()),
                format!("\"\"\"{newline}{}\"\"\"", multi.concat()),
                format!("'{literal}'"),
                format!("'''{newline}{literal}'''"),
            ];
            for token in tokens {
                let Some((t, span, value)) = mapped(&token) else {
                    continue;
                };
                let file = format!("v = {token}\n");
                let escapes = token.starts_with('"') && token.contains('\\');
                proptest::prop_assert!(escapes || t.offset.is_some(), "{:?}", token);
                proptest::prop_assert!(t.offset.is_some() || t.escape_map().is_some(), "{:?}", token);
                for i in 0..=value.len() {
                    for j in i..=value.len() {
                        let r = t.source_span(Span::new(i, j));
                        if let (Some(o), false) = (t.offset, escapes) {
                            proptest::prop_assert_eq!(r.clone(), o + i..o + j);
                            continue;
                        }
                        proptest::prop_assert!(
                            span.start < r.start && r.start <= r.end && r.end < span.end,
                            "{:?} {}..{}: {:?}", token, i, j, r
                        );
                        proptest::prop_assert!(
                            file.is_char_boundary(r.start) && file.is_char_boundary(r.end)
                        );
                    }
                }
                for p in &t.split(',') {
                    for after in [false, true] {
                        let r = p.separator(after);
                        proptest::prop_assert!(r.start <= r.end && r.end <= file.len());
                    }
                }
            }
        }

        /// Whatever the file, span and value, mapping a span does not panic.
        #[test]
        fn any_token_maps_without_panicking(
            file in "[\"'\\\\a-z\n\r é😀ux0-9]{0,24}",
            from in 0usize..30,
            to in 0usize..30,
            value in "[\"'\\\\a-z\n é😀]{0,8}",
        ) {
            let t = Text::in_toml(&file, from..to, &value);
            let n = t.value.len();
            for i in 0..=n {
                if t.value.is_char_boundary(i) {
                    let _ = t.source_span(Span::new(i, n));
                    let _ = t.slice(i..n).separator(true);
                    let _ = t.slice(i..n).separator(false);
                }
            }
        }
    }

    #[test]
    fn arrays_of_strings_are_found() {
        let file = "when = [\"a = 1\", 'b = 2'] # c";
        let spans = array_strings(file, 7..25).unwrap();
        assert_eq!(spans, vec![8..15, 17..24]);
    }

    #[test]
    fn top_level_split_skips_brackets() {
        let s = "{f, g} = 0, x = 1";
        let parts: Vec<&str> = split_top_level(s, ',').into_iter().map(|r| &s[r]).collect();
        assert_eq!(parts, ["{f, g} = 0", " x = 1"]);
    }
}
