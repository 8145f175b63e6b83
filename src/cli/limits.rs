//! `--max-terms`, `--max-degree` and `--max-term-products`, shared by the subcommands that
//! read a system file: they override the file's `[limits]`, which override the defaults.

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
    /// Stop with an error before a product of polynomials that would form more than N term
    /// products (default: the file's [limits] max_term_products, else 10000000000).
    #[arg(long, allow_negative_numbers = true,
          value_name = "N", value_parser = super::Quoting(super::at_least_one))]
    max_term_products: Option<u64>,
}

impl LimitsArgs {
    /// The limits as plain data.
    pub fn settings(&self) -> LimitsOverride {
        LimitsOverride {
            max_terms: self
                .max_terms
                .map(|t| usize::try_from(t).unwrap_or(usize::MAX)),
            max_degree: self.max_degree,
            max_term_products: self.max_term_products,
        }
    }

    /// Whether a limit was given.
    pub fn any(&self) -> bool {
        self.max_terms.is_some() || self.max_degree.is_some() || self.max_term_products.is_some()
    }
}
