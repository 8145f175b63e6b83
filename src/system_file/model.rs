//! The TOML model of a system file, as serde reads it: every string keeps its span in the
//! file (`toml::Spanned`), and unknown fields are errors.

use std::fmt;

use serde::de::{self, Deserializer, SeqAccess, Visitor};
use serde::Deserialize;
use toml::Spanned;

use crate::report::Expect;

/// A whole system file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct SystemModel {
    pub name: Option<Spanned<String>>,
    pub source: Option<Spanned<String>>,
    pub description: Option<Spanned<String>>,
    pub hamiltonian: Spanned<String>,
    pub phase_space: Spanned<PhaseSpaceModel>,
    pub limits: Option<Spanned<LimitsModel>>,
    #[serde(default)]
    pub function: Vec<Spanned<FunctionModel>>,
    #[serde(default)]
    pub family: Vec<Spanned<FamilyModel>>,
    #[serde(default)]
    pub claim: Vec<Spanned<ClaimModel>>,
}

/// `[phase_space]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct PhaseSpaceModel {
    #[serde(default)]
    pub coordinates: Vec<Spanned<String>>,
    #[serde(default)]
    pub angles: Vec<Spanned<String>>,
    #[serde(default)]
    pub parameters: Vec<Spanned<String>>,
}

/// `[limits]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct LimitsModel {
    pub max_terms: Option<Spanned<u64>>,
    pub max_degree: Option<Spanned<u32>>,
}

/// `[[function]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct FunctionModel {
    pub name: Spanned<String>,
    pub value: Spanned<String>,
    pub display: Option<Spanned<String>>,
}

/// `[[family]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct FamilyModel {
    pub name: Spanned<String>,
    pub value: Spanned<String>,
    pub display: Option<Spanned<String>>,
    pub indices: Option<Spanned<Vec<Spanned<String>>>>,
    pub eigenvalue: Option<Spanned<String>>,
}

/// `[[claim]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct ClaimModel {
    pub id: Option<Spanned<String>>,
    pub claim: Spanned<String>,
    pub when: Option<Spanned<When>>,
    pub expect: Option<Spanned<Expect>>,
}

/// `when = "p_theta = I*omega"` or `when = ["p_theta = I*omega", "g = 0"]`.
#[derive(Debug)]
pub(crate) enum When {
    One(String),
    Many(Vec<String>),
}

impl<'de> Deserialize<'de> for When {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = When;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a condition such as \"p_theta = I*omega\", or an array of them")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<When, E> {
                Ok(When::One(v.to_string()))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<When, A::Error> {
                let mut out = Vec::new();
                while let Some(s) = seq.next_element::<String>()? {
                    out.push(s);
                }
                Ok(When::Many(out))
            }
        }
        d.deserialize_any(V)
    }
}
