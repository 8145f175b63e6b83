//! `superint`: checks the Poisson-bracket identities of the rotor paper exactly.
//!
//! Exit codes: 0 when every claim is as expected (proved; or refuted, where a system file
//! expects it), 1 when one is not, 2 for bad input or usage (including every command-line
//! error clap reports).

mod cli;

use std::process::ExitCode;

/// mimalloc instead of the system allocator: the engine makes many short-lived vectors (a
/// polynomial is two), and this halves the cost of allocating them (docs/performance.md). Its
/// arenas are committed lazily (`.cargo/config.toml`), so the peak memory stays near what is used.
#[global_allocator]
static ALLOCATOR: superint::allocator::Allocator = superint::allocator::Allocator;

fn main() -> ExitCode {
    superint::allocator::configure();
    match cli::run(std::env::args_os()) {
        Ok(code) => code,
        Err(e) => {
            cli::error_line(&cli::error_message(&e));
            ExitCode::from(cli::EXIT_USAGE)
        }
    }
}
