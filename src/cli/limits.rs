//! `--max-terms`, `--max-degree` and `--max-term-products`, shared by the subcommands that
//! read a system file: they override the file's `[limits]`, which override the defaults. With
//! them goes the cap on memory, the machine's physical memory, read once.

use std::sync::OnceLock;

use clap::Args;
use superint::system_file::LimitsOverride;

/// The limit arguments.
#[derive(Debug, Args)]
pub struct LimitsArgs {
    /// Stop with an error when any result would have more terms than N (default: the file's
    /// [limits] max_terms, else 2000000).
    #[arg(long, allow_negative_numbers = true,
          value_name = "N", value_parser = super::Quoting(super::at_least_one))]
    max_terms: Option<u64>,
    /// Stop with an error when any exponent would exceed D (default: the file's [limits]
    /// max_degree, else 1000).
    #[arg(long, allow_negative_numbers = true,
          value_name = "D", value_parser = super::in_range::<u32>(1, 32767))]
    max_degree: Option<u32>,
    /// Stop with an error before a product of polynomials, or the products of a bracket
    /// together, that would form more than N term products (default: the file's [limits]
    /// max_term_products, else 10000000000).
    #[arg(long, allow_negative_numbers = true,
          value_name = "N", value_parser = super::Quoting(super::at_least_one))]
    max_term_products: Option<u64>,
}

impl LimitsArgs {
    /// The limits as plain data.
    pub fn settings(&self) -> LimitsOverride {
        let mut given = memory_only();
        given.max_terms = self
            .max_terms
            .map(|t| usize::try_from(t).unwrap_or(usize::MAX));
        given.max_degree = self.max_degree;
        given.max_term_products = self.max_term_products;
        given
    }

    /// Whether a limit was given.
    pub fn any(&self) -> bool {
        self.max_terms.is_some() || self.max_degree.is_some() || self.max_term_products.is_some()
    }
}

/// No limit given: the defaults, with the cap on memory.
pub fn memory_only() -> LimitsOverride {
    let mut given = LimitsOverride::default();
    given.max_reserved_bytes = physical_memory();
    given
}

/// The machine's physical memory in bytes, the cap on the room a result reserved from a
/// predicted count of terms may take (`trigpoly::Limits::max_reserved_bytes`): under Linux's
/// overcommit the allocator grants far more address space than the machine can back, and
/// `(r + p_r + p_φ + M + k + 1)^300` under a raised term limit filled memory instead of
/// stopping. Read once, from `MemTotal` in `/proc/meminfo`; `None` (no cap beyond the
/// allocator's refusal) where it cannot be read.
fn physical_memory() -> Option<u64> {
    static MEMORY: OnceLock<Option<u64>> = OnceLock::new();
    *MEMORY.get_or_init(|| {
        let text = std::fs::read_to_string("/proc/meminfo").ok()?;
        mem_total(&text)
    })
}

/// `MemTotal` of `/proc/meminfo`'s text, in bytes (the file gives kB, that is KiB).
fn mem_total(meminfo: &str) -> Option<u64> {
    let line = meminfo.lines().find_map(|l| l.strip_prefix("MemTotal:"))?;
    let kib = line.trim().strip_suffix("kB")?.trim().parse::<u64>().ok()?;
    kib.checked_mul(1024)
}

#[cfg(test)]
mod tests {
    use super::{mem_total, memory_only, physical_memory, LimitsArgs};

    /// The limits of the command line carry the machine's memory as the cap, given a limit or
    /// none, as every subcommand that reads a system file or builds a built-in system takes
    /// them (`settings`, or `memory_only` where no limit is given): nothing else sets it, and
    /// a power past the memory but within the address space the allocator grants would fill
    /// memory (an end-to-end test of it would, where the cap is lost).
    #[cfg(target_os = "linux")]
    #[test]
    fn the_command_lines_limits_carry_the_machines_memory() {
        let memory = physical_memory();
        assert!(memory.is_some_and(|m| m > 1 << 20), "{memory:?}");
        let none = LimitsArgs {
            max_terms: None,
            max_degree: None,
            max_term_products: None,
        };
        assert_eq!(none.settings().max_reserved_bytes, memory);
        let some = LimitsArgs {
            max_terms: Some(10),
            ..none
        };
        assert_eq!(some.settings().max_reserved_bytes, memory);
        assert_eq!(
            some.settings().or_defaults().max_reserved_bytes,
            memory.unwrap()
        );
        assert_eq!(memory_only().max_reserved_bytes, memory);
    }

    #[test]
    fn mem_total_reads_kib_as_bytes() {
        let text = "MemTotal:       16314716 kB\nMemFree:         1000 kB\n";
        assert_eq!(mem_total(text), Some(16_314_716 * 1024));
        assert_eq!(mem_total("MemFree: 1000 kB\n"), None);
        assert_eq!(mem_total("MemTotal: lots\n"), None);
    }
}
