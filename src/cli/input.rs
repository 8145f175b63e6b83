//! System files named on the command line: a path, or `-` for standard input (read once, so
//! that `check a.toml - -` checks the piped file twice rather than an empty second one).

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use super::search::Subject;
use brackets::NamedFunction;
use superint::discovery::{builtin_system, builtin_system_refused, define_builtin_resonant};
use superint::system_file::{
    load, load_piped, name_as_identifier, read_bytes, Caller, ErrorKind, FileError, LimitsOverride,
    LoadedSystem, STDIN,
};

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
        Ok(bytes) => load_piped(bytes, limits),
        Err(e) => Err(e.clone()),
    }
}

/// `--system NAME`, a built-in system in place of the system file that begins the positional
/// arguments of `bracket`, `expand`, `table`, `rank` and `closure` ([`SystemGiven::split`]).
#[derive(Debug, clap::Args)]
pub struct BuiltinArg {
    /// A built-in system instead of a file: harmonic, gravity, anisotropic-3-5,
    /// anisotropic-1-2, planar-i, planar-ii.
    #[arg(long, value_name = "NAME")]
    pub system: Option<String>,
}

/// The system a command on expressions of a system (`bracket`, `expand`, `table`, `rank`) is
/// given: a system file, its first positional argument, or a built-in system by
/// `--system NAME`, all its positional arguments then its own (as `closure` reads them).
#[derive(Debug)]
pub struct SystemGiven {
    /// The system file; with `--system`, a first positional argument written as a file is
    /// (`-` or a name ending in `.toml`), to be refused.
    file: Option<PathBuf>,
    /// The built-in system's name.
    builtin: Option<String>,
}

impl SystemGiven {
    /// The system `builtin` or the file the first of `positionals` names, and the rest of them.
    /// With `builtin`, every positional is an expression but one written as a file is, `-` or a
    /// name ending in `.toml`, kept to be refused: whether a file of that name exists is not
    /// asked, so that an expression is not taken for a file in a directory that holds a file
    /// named `L` or `H`.
    pub fn split(builtin: Option<String>, mut positionals: Vec<String>) -> (Self, Vec<String>) {
        let first_is_file = positionals.first().is_some_and(|p| match builtin {
            None => true,
            Some(_) => p == "-" || p.ends_with(".toml"),
        });
        let file = first_is_file.then(|| PathBuf::from(positionals.remove(0)));
        (SystemGiven { file, builtin }, positionals)
    }

    /// Loads the file, or builds the built-in system held to `limits`; a file and `--system`
    /// both given are refused, as `search` refuses them. A built-in system has its resonant
    /// functions `P11`, … (as `closure` has them) where one of `texts` (the command's
    /// expressions) or `when` (its condition) names one: the 36 of them would otherwise be among the
    /// functions a result is written in, too many for `{G1, G2} = −ω² L` to be found, and
    /// among those of a table of every function.
    pub fn open(
        &self,
        texts: &[String],
        when: Option<&str>,
        limits: &LimitsOverride,
    ) -> anyhow::Result<LoadedSystem> {
        let Some(name) = &self.builtin else {
            return Ok(Subject::open(self.file.as_ref(), None, false, limits)?.into_loaded(""));
        };
        if let Some(file) = &self.file {
            anyhow::bail!(
                "the argument '{}' cannot be used with '--system {name}': give a system file \
                 or a built-in system",
                file.display()
            );
        }
        // Built once, its resonant functions added to a copy.
        let plain = Subject::open(None, Some(name), false, limits).map_err(|e| {
            // The resonant functions are built too: the least limits said are theirs.
            match builtin_system(name, true, limits.or_defaults()) {
                Err(resonant) => {
                    builtin_system_refused(name, true, limits.or_defaults(), &resonant).into()
                }
                Ok(_) => e,
            }
        })?;
        let mut resonant = plain.system().clone();
        define_builtin_resonant(name, &mut resonant)
            .map_err(|e| builtin_system_refused(name, true, limits.or_defaults(), &e))?;
        let added = |f: &&NamedFunction| plain.system().function(&f.name).is_none();
        let named = resonant.functions().iter().filter(added).any(|f| {
            let forms = [
                f.name.clone(),
                name_as_identifier(&f.display),
                f.display.clone(),
            ];
            let mut texts = texts.iter().map(String::as_str).chain(when);
            texts.any(|t| forms.iter().any(|form| mentions(t, form)))
        });
        let subject = match plain {
            Subject::Builtin(display, _, noted) if named => {
                Subject::Builtin(display, Box::new(resonant), noted)
            }
            plain => plain,
        };
        Ok(subject.into_loaded(name))
    }

    /// How a message names the system: the file as given, or `--system NAME`.
    pub fn label(&self) -> String {
        match (&self.file, &self.builtin) {
            (_, Some(name)) => format!("--system {name}"),
            (Some(file), None) => file.display().to_string(),
            (None, None) => String::new(),
        }
    }
}

/// Whether `text` has `name` in it as a whole name: neither a letter, a digit nor `_` beside it.
fn mentions(text: &str, name: &str) -> bool {
    let part_of_name = |c: char| c.is_alphanumeric() || c == '_';
    text.match_indices(name).any(|(at, _)| {
        !text[..at].chars().next_back().is_some_and(part_of_name)
            && !text[at + name.len()..]
                .chars()
                .next()
                .is_some_and(part_of_name)
    })
}
