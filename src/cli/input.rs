//! System files named on the command line: a path, or `-` for standard input (read once, so
//! that `check a.toml - -` checks the piped file twice rather than an empty second one).

use std::path::Path;
use std::sync::OnceLock;

use superint::system_file::{
    load, load_bytes, read_bytes, Caller, ErrorKind, FileError, LimitsOverride, LoadedSystem,
};

/// How messages name a system file read from standard input.
const STDIN: &str = "<stdin>";

/// Loads the system file at `path`, or the one on standard input when `path` is `-`, whose
/// reports name the command line as the giver of their texts ([`Caller::CommandLine`]). A file
/// that fails to load has what its texts read in doubt before the error printed on stderr now,
/// before the error is ([`super::output::load_warnings`]), as every command prints a loaded
/// file's however its run ends.
pub fn load_system(path: &Path, limits: &LimitsOverride) -> Result<LoadedSystem, FileError> {
    load_system_keeping_warnings(path, limits).inspect_err(super::output::load_warnings)
}

/// [`load_system`] without printing a failed load's warnings: for `check`, which loads every
/// file before it prints any error, and prints each error's warnings right before it, where
/// printing them here put a later file's warnings before an earlier file's error.
pub fn load_system_keeping_warnings(
    path: &Path,
    limits: &LimitsOverride,
) -> Result<LoadedSystem, FileError> {
    load_file(path, limits).map(|file| file.with_caller(Caller::CommandLine))
}

/// Loads the system file at `path`, or the one on standard input when `path` is `-`.
fn load_file(path: &Path, limits: &LimitsOverride) -> Result<LoadedSystem, FileError> {
    if path != Path::new("-") {
        return load(path, limits);
    }
    static PIPED: OnceLock<Result<Vec<u8>, FileError>> = OnceLock::new();
    let piped = PIPED.get_or_init(|| {
        read_bytes(STDIN, std::io::stdin().lock(), |e| {
            FileError::new(
                ErrorKind::Io,
                STDIN,
                format!("cannot read standard input: {e}"),
            )
        })
    });
    match piped {
        Ok(bytes) => load_bytes(STDIN, bytes, limits),
        Err(e) => Err(e.clone()),
    }
}
