//! Where a key of a system file belongs: the hint under an `unknown field` error, for a key
//! written in the wrong table (`radicals` at the top, `hamiltonian` below `[phase_space]`'s
//! header, which TOML reads as part of that table) or misspelt (`hamiltonain`).

/// The keys of the file itself, and of each table, with how a hint names their place.
const HOMES: [(&str, &[&str]); 6] = [
    (
        "the file itself: write it above the first [table] header, since every key below a \
         header belongs to that table",
        &["name", "source", "description", "hamiltonian"],
    ),
    (
        "[phase_space]: write it below that header",
        &[
            "coordinates",
            "angles",
            "parameters",
            "variables",
            "denominators",
            "radicals",
            "display",
        ],
    ),
    (
        "[limits]: write it below that header",
        &["max_terms", "max_degree", "max_term_products"],
    ),
    ("each [[function]] and [[family]]", &["value", "display"]),
    ("each [[family]]", &["indices", "eigenvalue"]),
    ("each [[claim]]", &["id", "when", "on", "expect"]),
];

/// Words a claim might be written with, where a claim is one equation in one string.
const CLAIM_SIDES: [&str; 6] = ["lhs", "rhs", "left", "right", "equation", "identity"];

/// The hint for serde's message `unknown field `key`, expected one of `a`, `b`, …`: the table
/// the key belongs to, when it is a key of another one; else the expected key it is one or
/// two letters from. `None` when the message is not of that form, or no hint fits.
pub(super) fn unknown_key_hint(message: &str) -> Option<String> {
    let rest = message.strip_prefix("unknown field ")?;
    let mut quoted = rest.split('`').skip(1).step_by(2);
    let key = quoted.next()?;
    let expected: Vec<&str> = quoted.collect();
    let in_claim = expected.contains(&"claim") && expected.contains(&"expect");
    if in_claim && CLAIM_SIDES.contains(&key.to_lowercase().as_str()) {
        return Some(
            "a claim is one equation in one string: claim = \"{L, H} = 0\" (see \
             docs/system-files.md)"
                .into(),
        );
    }
    if in_claim && key == "name" {
        return Some("a claim is named by its `id`".into());
    }
    if expected.contains(&"value") && key == "id" {
        return Some("a function or a family is named by its `name`".into());
    }
    // `display` is a key of [phase_space] and of each [[function]] and [[family]]: a
    // misplaced one is sent to the functions' (the last home that has it).
    if let Some((home, _)) = HOMES.iter().rev().find(|(_, keys)| keys.contains(&key)) {
        return Some(format!("`{key}` is a key of {home}"));
    }
    let nearest = expected
        .iter()
        // Insertions, deletions, substitutions and swaps of two neighbours, one edit each
        // (`hamiltonain` is one from `hamiltonian`).
        .map(|&e| (strsim::osa_distance(key, e), e))
        .filter(|&(d, e)| d <= 2 && 2 * d < e.chars().count())
        .min_by_key(|&(d, _)| d)?;
    Some(format!("did you mean `{}`?", nearest.1))
}

#[cfg(test)]
mod tests {
    use super::*;

    const TOP: &str = "unknown field `{}`, expected one of `name`, `source`, `description`, \
                       `hamiltonian`, `phase_space`, `limits`, `poisson`, `function`, `family`, \
                       `claim`";
    const PHASE: &str = "unknown field `{}`, expected one of `coordinates`, `angles`, \
                         `parameters`, `variables`, `denominators`, `radicals`";
    const CLAIM: &str = "unknown field `{}`, expected one of `id`, `claim`, `when`, `on`, `expect`";

    fn hint(form: &str, key: &str) -> Option<String> {
        unknown_key_hint(&form.replace("{}", key))
    }

    /// The keys serde expects where `zzz` stands in `text`, from its message.
    fn expected_by_the_model(text: &str) -> Vec<String> {
        let e = toml::from_str::<super::super::model::SystemModel>(text).expect_err("unknown");
        let message = e.message().to_string();
        assert!(message.starts_with("unknown field `zzz`"), "{message}");
        message
            .split('`')
            .skip(3)
            .step_by(2)
            .map(String::from)
            .collect()
    }

    /// `HOMES` is a copy of the model's fields (`model.rs`), kept from drifting: each key it
    /// homes in a table is one that table's model expects, and each key a table expects is
    /// homed (but for the tables' own names, and a function's `name` and a claim's `claim`,
    /// which the hints treat apart).
    #[test]
    fn the_homes_are_the_models_keys() {
        let tables = [
            ("zzz = 1", vec![0]),
            ("[phase_space]\nzzz = 1", vec![1]),
            ("[limits]\nzzz = 1", vec![2]),
            ("[[function]]\nzzz = 1", vec![3]),
            ("[[family]]\nzzz = 1", vec![3, 4]),
            ("[[claim]]\nzzz = 1", vec![5]),
        ];
        let apart = [
            "phase_space",
            "limits",
            "poisson",
            "function",
            "family",
            "claim",
            "name",
        ];
        for (text, homes) in tables {
            let expected = expected_by_the_model(text);
            let homed: Vec<&str> = homes
                .iter()
                .flat_map(|&h| HOMES[h].1.iter().copied())
                .collect();
            for key in &homed {
                assert!(expected.iter().any(|e| e == key), "{key} in {text:?}");
            }
            for key in &expected {
                assert!(
                    homed.contains(&key.as_str()) || apart.contains(&key.as_str()),
                    "{key} of {text:?} has no home"
                );
            }
        }
    }

    #[test]
    fn a_key_of_another_table_is_sent_there() {
        let radicals = hint(TOP, "radicals").expect("a hint");
        assert!(radicals.starts_with("`radicals` is a key of [phase_space]"));
        let h = hint(PHASE, "hamiltonian").expect("a hint");
        assert!(h.contains("above the first [table] header"), "{h}");
        assert!(hint(TOP, "max_terms").expect("a hint").contains("[limits]"));
        assert!(hint(PHASE, "eigenvalue")
            .expect("a hint")
            .contains("[[family]]"));
    }

    #[test]
    fn a_claim_written_in_two_sides_is_shown_its_one_string() {
        for side in ["lhs", "rhs", "LHS", "equation"] {
            let h = hint(CLAIM, side).expect("a hint");
            assert!(
                h.starts_with("a claim is one equation in one string"),
                "{h}"
            );
        }
        assert_eq!(
            hint(CLAIM, "name").as_deref(),
            Some("a claim is named by its `id`")
        );
        let function = "unknown field `id`, expected one of `name`, `value`, `display`";
        assert_eq!(
            unknown_key_hint(function).as_deref(),
            Some("a function or a family is named by its `name`")
        );
        // Outside a claim, `lhs` is only an unknown key.
        assert_eq!(hint(TOP, "lhs"), None);
    }

    #[test]
    fn a_misspelt_key_is_matched_to_the_nearest_expected_one() {
        assert_eq!(
            hint(TOP, "hamiltonain").as_deref(),
            Some("did you mean `hamiltonian`?")
        );
        assert_eq!(
            hint(PHASE, "coordinate").as_deref(),
            Some("did you mean `coordinates`?")
        );
        assert_eq!(
            hint(PHASE, "paramters").as_deref(),
            Some("did you mean `parameters`?")
        );
        // Too far from every expected key, or too short to say.
        assert_eq!(hint(PHASE, "momenta"), None);
        assert_eq!(hint(CLAIM, "ix"), None);
        assert_eq!(hint(CLAIM, "x"), None);
        assert_eq!(unknown_key_hint("missing field `hamiltonian`"), None);
    }
}
