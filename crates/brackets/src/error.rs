//! `EngineError`: why the engine could not form a bracket, a claim or a certificate.

use thiserror::Error;
use trigpoly::{AlgebraError, ParseError};

/// Why the bracket engine has no answer.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum EngineError {
    /// An algebraic operation failed (a limit, a division by a non-monomial, ...).
    #[error(transparent)]
    Algebra(#[from] AlgebraError),
    /// An expression did not parse; the message carries line and column.
    #[error("{}", .message)]
    Parse {
        /// The source text.
        source_text: String,
        /// The rendered message with line, column and caret.
        message: String,
        /// The parse error.
        error: ParseError,
    },
    /// A name that the system does not define.
    #[error("unknown function '{0}'")]
    UnknownName(String),
    /// A condition that sets a variable in terms of itself (`x = y, y = x`).
    #[error("{message}")]
    CircularCondition {
        /// The variable.
        var: trigpoly::Var,
        /// What is wrong, in words.
        message: String,
    },
    /// A phase space or system that is not well formed.
    #[error("{0}")]
    Invalid(String),
}

/// A parse error without its source, so that `?` works on a parse in a function that returns
/// an `EngineError`: its message says where by byte offsets (`EngineError::parse` with the
/// source gives line, column and caret).
impl From<ParseError> for EngineError {
    fn from(error: ParseError) -> Self {
        let (start, end) = (error.span.start, error.span.end);
        EngineError::Parse {
            source_text: String::new(),
            message: format!("{} (at bytes {start}..{end})", error.message),
            error,
        }
    }
}

impl EngineError {
    /// A parse error rendered against its source.
    pub fn parse(source: &str, error: ParseError) -> Self {
        EngineError::Parse {
            source_text: source.to_string(),
            message: error.render(source),
            error,
        }
    }
}
