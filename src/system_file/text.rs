//! [`Text`]: an expression string together with where it sits in its source, so that a byte
//! span inside the string maps to a byte span of the file.
//!
//! A TOML string's value starts after its opening quote (three quotes, and a newline right
//! after them, for a multi-line string). When the raw text between the quotes is the decoded
//! value itself (no escapes), spans map one to one; otherwise every span maps to the value's
//! first character.

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
    /// Whether a program gave the text (a function added in code, say): hints then name the
    /// library's calls, not a file's tables.
    pub(crate) program: bool,
}

/// `Source { origin: "systems/kepler.toml", text: <4211 bytes>, program: false }`: a file's
/// text, shared by each of its claims and families, is printed by none of them.
impl std::fmt::Debug for Source {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Source")
            .field("origin", &self.origin)
            .field("text", &format_args!("<{} bytes>", self.text.len()))
            .field("program", &self.program)
            .finish()
    }
}

impl Source {
    /// A source with its origin.
    pub fn new(origin: &str, text: &str) -> Self {
        Source {
            origin: origin.to_string(),
            text: Arc::from(text),
            program: false,
        }
    }

    /// A text a program gave, named `origin` in messages.
    pub(crate) fn program(origin: &str, text: &str) -> Self {
        Source {
            program: true,
            ..Source::new(origin, text)
        }
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
    /// Where errors point when the raw text differs from the value (escapes): the value's
    /// first byte.
    anchor: usize,
}

impl Text {
    /// The whole of a source (a command-line argument).
    pub fn whole(source: &Source) -> Self {
        Text {
            value: source.text.to_string(),
            offset: Some(0),
            anchor: 0,
        }
    }

    /// The bytes `range` of `source`, whose text is the value itself (a text given in code).
    pub(crate) fn within(source: &Source, range: Range<usize>) -> Self {
        Text {
            value: source.text[range.clone()].to_string(),
            offset: Some(range.start),
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
        Text {
            value: value.to_string(),
            offset: (inner == value).then_some(start),
            anchor: start,
        }
    }

    /// The part `range` of this text (byte offsets into `value`), keeping the mapping.
    pub fn slice(&self, range: Range<usize>) -> Text {
        Text {
            value: self.value[range.clone()].to_string(),
            offset: self.offset.map(|o| o + range.start),
            anchor: self.anchor,
        }
    }

    /// The same place with a value of the same length (a rewritten form of the value).
    pub(crate) fn rewritten(&self, value: String) -> Text {
        debug_assert_eq!(value.len(), self.value.len());
        Text {
            value,
            offset: self.offset,
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

    /// The span in the source of a span inside the value.
    pub fn source_span(&self, span: Span) -> Range<usize> {
        match self.offset {
            Some(o) => o + span.start..o + span.end,
            None => self.anchor..self.anchor + 1,
        }
    }

    /// The span in the source of the one-byte separator just before the value (the comma
    /// before a piece of a list; `after`: just after it), or of the whole value where the value
    /// is not found in its source as written.
    pub(crate) fn separator(&self, after: bool) -> Range<usize> {
        match (self.offset, after) {
            (Some(o), false) if o > 0 => o - 1..o,
            (Some(o), true) => o + self.value.len()..o + self.value.len() + 1,
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
        assert_eq!(t.source_span(Span::new(4, 5)), 9..10);
        let multi = "value = \"\"\"\nx + y\"\"\"\n";
        let t = Text::in_toml(multi, 8..multi.len() - 1, "x + y");
        assert_eq!(t.source_span(Span::new(0, 1)), 12..13);
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
