//! `superint`: checks the Poisson-bracket identities of the rotor paper exactly.
//!
//! Exit codes: 0 when every claim is proved, 1 when a claim is refuted, 2 for bad input or
//! usage (including every command-line error clap reports).

mod cli;

use std::process::ExitCode;

fn main() -> ExitCode {
    match cli::run(std::env::args_os()) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("superint: error: {e:#}");
            ExitCode::from(cli::EXIT_USAGE)
        }
    }
}
