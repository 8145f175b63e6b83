//! Source spans and parse errors, with line/column lookup and caret rendering.

/// Byte range `start..end` in the source text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Span {
    /// Byte offset of the first byte of the range.
    pub start: usize,
    /// Byte offset one past the last byte of the range.
    pub end: usize,
}

impl Span {
    /// The span `start..end`.
    #[must_use]
    pub fn new(start: usize, end: usize) -> Self {
        Span { start, end }
    }

    /// The smallest span covering both `self` and `other`.
    #[must_use]
    pub fn to(self, other: Span) -> Span {
        Span::new(self.start.min(other.start), self.end.max(other.end))
    }
}

/// A syntax error: what was expected and what was found, at a location in the source.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct ParseError {
    /// The offending part of the source (empty at the end of the input).
    pub span: Span,
    /// Human-readable description, without location information.
    pub message: String,
}

impl ParseError {
    /// An error at `span` with the given message.
    pub fn new(span: Span, message: impl Into<String>) -> Self {
        ParseError {
            span,
            message: message.into(),
        }
    }

    /// 1-based line and column (column counted in characters, not bytes) of `span.start` in `src`.
    #[must_use]
    pub fn line_col(&self, src: &str) -> (usize, usize) {
        line_col(src, self.span.start)
    }

    /// Multi-line rendering: `"line L, column C: message"`, then the source line, then a line of
    /// carets under the offending span (as wide as the span in characters, at least one).
    #[must_use]
    pub fn render(&self, src: &str) -> String {
        let start = char_floor(src, self.span.start);
        let (line, col) = line_col(src, start);
        let line_start = src[..start].rfind('\n').map_or(0, |i| i + 1);
        let line_end = src[start..].find('\n').map_or(src.len(), |i| start + i);
        let end = char_floor(src, self.span.end).clamp(start, line_end);
        let width = src[start..end].chars().count().max(1);
        // Keep tabs so that the carets line up with the source line.
        let pad: String = src[line_start..start]
            .chars()
            .map(|c| if c == '\t' { '\t' } else { ' ' })
            .collect();
        let text = src[line_start..line_end].trim_end_matches('\r');
        format!(
            "line {line}, column {col}: {}\n  {text}\n  {pad}{}",
            self.message,
            "^".repeat(width)
        )
    }
}

/// 1-based line and character column of byte `offset` in `src` (clamped to the source).
pub(crate) fn line_col(src: &str, offset: usize) -> (usize, usize) {
    let before = &src[..char_floor(src, offset)];
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (
        before.matches('\n').count() + 1,
        before[line_start..].chars().count() + 1,
    )
}

/// The largest char boundary of `src` that is at most `offset`.
fn char_floor(src: &str, offset: usize) -> usize {
    let mut i = offset.min(src.len());
    while !src.is_char_boundary(i) {
        i -= 1;
    }
    i
}
