//! The TOML model of a system file, as serde reads it: every string keeps its span in the
//! file (`toml::Spanned`), and unknown fields are errors.

use std::fmt;

use serde::de::{self, Deserializer, SeqAccess, Visitor};
use serde::Deserialize;
use toml::Spanned;

use crate::report::Expect;

/// The shape of a system file's top level, each value as TOML wrote it, for the checks that
/// serde's own reading of [`SystemModel`] does not make: serde reads a struct from an array too
/// (`phase_space = [["x"], [], []]` was accepted), and says "invalid type: map" of a date.
#[derive(Debug, Deserialize)]
pub(crate) struct ShapeModel {
    pub name: Option<Spanned<toml::Value>>,
    pub source: Option<Spanned<toml::Value>>,
    pub description: Option<Spanned<toml::Value>>,
    pub hamiltonian: Option<Spanned<toml::Value>>,
    pub phase_space: Option<Spanned<toml::Value>>,
    pub limits: Option<Spanned<toml::Value>>,
    pub poisson: Option<Spanned<toml::Value>>,
    pub function: Option<Spanned<toml::Value>>,
    pub family: Option<Spanned<toml::Value>>,
    pub claim: Option<Spanned<toml::Value>>,
}

/// The claims' `expect`, as TOML wrote it (see [`ShapeModel`]).
#[derive(Debug, Deserialize)]
pub(crate) struct ExpectShape {
    pub claim: Vec<ClaimShape>,
}

/// A claim's `expect`, as TOML wrote it.
#[derive(Debug, Deserialize)]
pub(crate) struct ClaimShape {
    pub expect: Option<Spanned<toml::Value>>,
}

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
    pub poisson: Option<Spanned<StringTable>>,
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
    #[serde(default)]
    pub variables: Vec<Spanned<String>>,
    /// Polynomials that expressions may divide by (`"x - y"`), each a denominator atom.
    #[serde(default)]
    pub denominators: Vec<Spanned<String>>,
    /// Radicals by name, each with its radicand (`r = "x^2 + y^2"`: `r = √(x² + y²)`).
    pub radicals: Option<Spanned<StringTable>>,
    /// Display names by declared name (`{ a = "ω₊" }`): how a coordinate, an angle, a
    /// Poisson variable or a parameter prints, its input keeping the name.
    pub display: Option<Spanned<StringTable>>,
}

/// A table of strings, each key and value with its span, in the order of the file: the
/// `[poisson]` table (`"{M1, M2}" = "M3"`) and `[phase_space]`'s `radicals`
/// (`{ r = "x^2 + y^2" }`) and `display` (`{ a = "ω₊" }`).
#[derive(Debug)]
pub(crate) struct StringTable {
    pub entries: Vec<(Spanned<String>, Spanned<String>)>,
}

impl<'de> Deserialize<'de> for StringTable {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = StringTable;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str(
                    "a table of strings, such as \"{M1, M2}\" = \"M3\" in [poisson] or \
                     { r = \"x^2 + y^2\" } for radicals",
                )
            }
            fn visit_map<A: de::MapAccess<'de>>(self, mut map: A) -> Result<StringTable, A::Error> {
                let mut entries = Vec::new();
                while let Some(entry) = map.next_entry::<Spanned<String>, Spanned<String>>()? {
                    entries.push(entry);
                }
                entries.sort_by_key(|(k, _): &(Spanned<String>, Spanned<String>)| k.span().start);
                Ok(StringTable { entries })
            }
        }
        d.deserialize_map(V)
    }
}

/// `[limits]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct LimitsModel {
    // Signed, as TOML's integers are, so that a negative limit gets the loader's message.
    pub max_terms: Option<Spanned<i64>>,
    pub max_degree: Option<Spanned<i64>>,
    pub max_term_products: Option<Spanned<i64>>,
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
    /// The level set the claim is made on, `EXPR = VALUE`.
    pub on: Option<Spanned<String>>,
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
