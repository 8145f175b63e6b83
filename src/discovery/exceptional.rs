//! The report of `superint search --find-values`: the values of one parameter at which the
//! space holds more integrals than at a generic value
//! ([`brackets::search::exceptional_values`]), then the search at the generic value and at
//! each of those values, as `--when` shows it (on a level set, as `--fix` does).

use brackets::search::{level_set_graph_variable, ExceptionalValues, MAX_RANK_MINORS};
use brackets::BoundedRank;
use brackets::System;
use trigpoly::Style;

use crate::report::{counted, listed};
use crate::report::{
    Entry, ExceptionalFacts, Facts, Report, RuledOutFacts, Section, SummaryKind, ValueFacts,
};
use crate::system_file::Caller;

use super::search::level_set_shown;

/// The report of what [`brackets::search::exceptional_values`] `found` for `name`, `system`:
/// a section that says which values have more integrals (and, with `facts`, the JSON's data),
/// then the sections of `searches`, the reports of the search at the generic value and at each
/// exceptional value in order, numbered on and titled by their value. The polynomial whose
/// roots were not examined is shown whole with `whole` (`--full-expressions`), else, when
/// long, in part ([`trigpoly::Poly::brief_excerpt`]), its degree said either way; the JSON's
/// data hold it whole.
pub fn exceptional_values_report(
    name: &str,
    system: &System,
    found: &ExceptionalValues,
    searches: Vec<Report>,
    caller: Caller,
    (facts, whole): (bool, bool),
) -> Report {
    let vars = system.vars();
    let told = &found.determinants;
    // A value as the prose prints numbers, with a minus sign.
    let shown = |v: &trigpoly::Rational| v.to_string().replace('-', "−");
    let t = vars.variable(told.parameter).unicode().to_string();
    let mut entries = vec![Entry::Text(format!(
        "The equations `{{Σ c_j φ_j, H}} = 0` with `{t}` kept are `M({t}) c = 0`, each entry of \
         `M` a polynomial in `{t}`; their rank drops, and the space holds more integrals, only \
         at a root of the determinant of a generic minor of each block of `M` (the largest has {}, \
         its determinant of degree {} in `{t}`). Each rational root was searched at exactly.",
        counted(told.largest_minor.0, "row"),
        told.largest_minor.1
    ))];
    // On a level set, the values are its own: say so before them, as the title does.
    let on = (found.generic.on.as_ref())
        .map(|on| format!(" on the level set `{}`", level_set_shown(on)))
        .unwrap_or_default();
    // The ranks are those on the level set where it is a graph over the variables the
    // integrals hold, else those in the whole phase space: said which.
    let searches_found =
        std::iter::once(&found.generic).chain(found.values.iter().map(|v| &v.found));
    let graph_over = searches_found
        .map(|r| level_set_graph_variable(system.space(), r))
        .collect::<Option<Vec<_>>>();
    // Elsewhere each integral found is one remainder modulo `P` of many functions equal on the
    // level set (`P` itself is 0 there), whose ranks in the whole phase space differ: those
    // of the remainders are shown, and no value is said to hold functionally new integrals.
    let ranks_on_level_set = found.generic.on.is_none() || graph_over.is_some();
    let ranks_where = match graph_over.as_ref().and_then(|v| v.first()) {
        Some(&v) => format!(
            "The functional ranks below are those on the level set, a graph over the phase \
             variables but `{}`, which no integral found holds.",
            vars.variable(v).unicode()
        ),
        None => "The functional ranks below are those of the functions found in the whole \
                 phase space, remainders modulo the level set's polynomial: they do not say \
                 which values hold functionally new integrals on the level set."
            .to_string(),
    };
    if !on.is_empty() {
        entries.push(Entry::Text(format!(
            "These are the values{on}: the equations are those of the search there (section 2), \
             each bracket taken modulo its polynomial, which does not hold `{t}`; off the level \
             set they may have no more integrals. {ranks_where}"
        )));
    }
    // The sections of the searches begin after this one, each search's after the last's.
    let starts: Vec<u32> = searches
        .iter()
        .scan(2, |next, r| {
            let start = *next;
            *next += u32::try_from(r.sections.len()).unwrap_or(u32::MAX);
            Some(start)
        })
        .collect();
    let section_of = |k: usize| starts.get(k).copied().unwrap_or_default();
    let dimension = |k: usize, r: &brackets::search::SearchResult| {
        format!(
            "{} (section {})",
            counted(r.basis.len(), "integral"),
            section_of(k)
        )
    };
    // Where the level set is no graph, the rank is said where it is taken, as each section
    // says it.
    let rank_said = |r: &brackets::search::SearchResult, rank: &BoundedRank| {
        let whole = r.on.is_some() && level_set_graph_variable(system.space(), r).is_none();
        match whole {
            true => format!("{rank} in the whole phase space, not on the level set"),
            false => rank.to_string(),
        }
    };
    let generic_rank = &found.generic_rank;
    entries.push(Entry::Text(format!(
        "For a generic `{t}` (searched at `{t} = {}`, no root): {}, of functional rank {}.",
        shown(&told.generic_value),
        dimension(0, &found.generic),
        rank_said(&found.generic, generic_rank)
    )));
    // The generic rank said once, above: the line after these compares each value's with it.
    let values: Vec<String> = (found.values.iter().enumerate())
        .map(|(k, v)| {
            format!(
                "at `{t} = {}`, {}, of functional rank {}",
                shown(&v.value),
                dimension(k + 1, &v.found),
                rank_said(&v.found, &v.rank)
            )
        })
        .collect();
    entries.push(Entry::Text(match values.is_empty() {
        true => format!("No rational value of `{t}` has more integrals."),
        false => format!("More integrals {}.", listed(&values)),
    }));
    // The values a physicist asks for: those whose integrals are not all functions of the
    // generic ones.
    let new: Vec<String> = (found.values.iter())
        .filter(|v| ranks_on_level_set && v.functionally_new(generic_rank))
        .map(|v| format!("`{t} = {}`", shown(&v.value)))
        .collect();
    let ranks = std::iter::once(generic_rank).chain(found.values.iter().map(|v| &v.rank));
    if !new.is_empty() {
        entries.push(Entry::Text(format!(
            "Functionally new integrals, a functional rank above the generic one, at {}.",
            listed(&new)
        )));
    } else if ranks_on_level_set
        && !found.values.is_empty()
        && ranks.clone().all(BoundedRank::is_exact)
    {
        entries.push(Entry::Text(format!(
            "No value of `{t}` has functionally new integrals: none has a functional rank above \
             the generic one."
        )));
    }
    if ranks.clone().any(|r| !r.is_exact()) {
        entries.push(Entry::Text(format!(
            "A functional rank (of the Jacobian of the integrals by every phase variable) said \
             \"at least\" is certified from below alone: more than {MAX_RANK_MINORS} minors \
             border its nonzero one."
        )));
    }
    if !found.spurious.is_empty() {
        let roots: Vec<String> = (found.spurious.iter())
            .map(|r| format!("`{t} = {}`", shown(r)))
            .collect();
        entries.push(Entry::Text(format!(
            "Roots of the determinants where the search finds no more integrals: {}.",
            listed(&roots)
        )));
    }
    // Said only where 0 was a root: elsewhere it would explain a value nobody was shown.
    if told.zero_left_out {
        entries.push(Entry::Text(format!(
            "`{t} = 0`, a root of the determinants, is no value: H, with a negative power of \
             `{t}`, has none there (each equation was multiplied by the power of `{t}` that \
             makes it a polynomial, which changes its solutions at no other value)."
        )));
    }
    // As for 0: each root of a declared denominator in the parameter that was a root of a
    // determinant, said where it was left out.
    for left_out in &told.denominator_roots_left_out {
        let (root, d) = (&left_out.root, vars.variable(left_out.atom).unicode());
        entries.push(Entry::Text(match left_out.divides_h {
            true => format!(
                "`{t} = {}`, a root of the determinants, is no value: H divides by `{d}`, \
                 which is zero there (each equation was multiplied by the power of `{d}` \
                 that makes it a polynomial, which changes its solutions at no other value).",
                shown(root)
            ),
            false => format!(
                "`{t} = {}`, a root of the determinants, is not searched at: the space's \
                 functions divide by `{d}`, which is zero there (--denominators-degree 0 \
                 leaves them out).",
                shown(root)
            ),
        }));
    }
    let unexamined = told.unexamined_in(vars);
    let real_roots = unexamined
        .as_ref()
        .map(|_| told.unexamined.real_root_count());
    let ruled_out = &told.ruled_out;
    let ruled_out_real = (ruled_out.count() > 0).then(|| ruled_out.factor.real_root_count());
    // How the blocks were shown to keep their rank: modulo the prime, and some, where a root
    // stayed common modulo it, by exact determinants.
    let prime = ruled_out
        .prime
        .map_or(String::new(), |p| format!(" `p = {p}`"));
    let shown_how = match ruled_out.exact_blocks {
        0 => format!("shown modulo the prime{prime}"),
        k => format!(
            "shown modulo the prime{prime} and, for {}, by exact determinants over Q",
            counted(k, "block")
        ),
    };
    // The roots ruled out, as a clause: "58 roots (not rational; 50 real)", "2 roots
    // (complex, none real)".
    let ruled_out_roots = ruled_out_real.map(|real| {
        let roots = counted(ruled_out.count(), "root");
        match real {
            0 => format!("{roots} (complex, none real)"),
            real => format!("{roots} (not rational; {real} real)"),
        }
    });
    entries.push(Entry::Text(match (&unexamined, real_roots) {
        (Some(p), Some(real)) => {
            let shown = unexamined_shown(p, told.unexamined.degree().unwrap_or(0), whole, caller);
            // "The determinants' other" said once: the left part says it where none is real.
            let (left, rest) = match real {
                0 => (
                    format!(
                        "The determinants' other roots, those of {shown}, are none of them real: \
                         no other real value of `{t}` has more integrals in this space (the \
                         complex ones were not examined)."
                    ),
                    "The remaining",
                ),
                real => (
                    format!(
                        "Other values may lie among the roots of {shown}, which are not rational \
                         ({real} of them real): at each, every minor tried of some block \
                         vanishes, so that it may hold more integrals (not examined: they are \
                         not rational)."
                    ),
                    "The determinants' other",
                ),
            };
            match &ruled_out_roots {
                Some(roots) => format!(
                    "{left} {rest} {roots} hold no more integrals in this space: at each, every \
                     block of the equations keeps its generic rank ({shown_how})."
                ),
                None => left,
            }
        }
        _ => match &ruled_out_roots {
            // "But those above" only where values above have more integrals: where none has,
            // it would point at the roots that hold nothing more.
            Some(roots) => format!(
                "The determinants' other {roots} hold no more integrals in this space: at each, \
                 every block of the equations keeps its generic rank ({shown_how}). No value of \
                 `{t}`{} has more integrals in this space.",
                if values.is_empty() { "" } else { " but those above" }
            ),
            None => format!("Every root of the determinants is rational: no other value of `{t}` has more integrals in this space."),
        },
    }));
    if facts {
        let value = |k: usize,
                     v: &trigpoly::Rational,
                     r: &brackets::search::SearchResult,
                     rank: &brackets::BoundedRank| {
            ValueFacts::new(v.to_string(), r.basis.len(), section_of(k), rank.clone())
        };
        entries.push(Entry::Data(Facts::ExceptionalValues(Box::new(
            ExceptionalFacts::new(
                vars.variable(told.parameter).name().to_string(),
                value(0, &told.generic_value, &found.generic, generic_rank),
                (found.values.iter().enumerate())
                    .map(|(k, v)| value(k + 1, &v.value, &v.found, &v.rank))
                    .collect(),
                found.spurious.iter().map(ToString::to_string).collect(),
                (unexamined.as_ref().zip(real_roots))
                    .map(|(p, real)| (p.render(Style::Ascii), real)),
                told.largest_minor,
                told.zero_left_out,
            )
            .with_denominator_roots_left_out(
                (told.denominator_roots_left_out.iter())
                    .map(|r| r.root.to_string())
                    .collect(),
            )
            .with_ruled_out(ruled_out_real.map(|real| RuledOutFacts {
                polynomial:
                    (told.ruled_out_in(vars)).map_or(String::new(), |p| p.render(Style::Ascii)),
                roots: ruled_out.count(),
                real_roots: real,
                prime: ruled_out.prime,
                exact_blocks: ruled_out.exact_blocks,
            })),
        ))));
    }
    let first = searches
        .first()
        .and_then(|r| r.sections.first())
        .map(|s| s.names.clone())
        .unwrap_or_else(|| crate::render::tex::Names::of_system(system));
    let mut sections = vec![Section {
        number: 1,
        title: format!("Values of `{t}` with more integrals"),
        file: None,
        entries,
        names: first,
    }];
    let mut seconds = 0.0;
    let at_values = std::iter::once(format!("`{t} = {}` (generic)", shown(&told.generic_value)))
        .chain(
            found
                .values
                .iter()
                .map(|v| format!("`{t} = {}`", shown(&v.value))),
        );
    for (report, at) in searches.into_iter().zip(at_values) {
        seconds += report.seconds;
        for mut section in report.sections {
            section.number = u32::try_from(sections.len() + 1).unwrap_or(u32::MAX);
            section.title = format!("At {at}: {}", section.title);
            sections.push(section);
        }
    }
    Report {
        title: format!("Values of `{t}` with more integrals for {name}{on}"),
        subtitle: String::new(),
        sections,
        summary: SummaryKind::Searches,
        seconds,
        caller,
    }
}

/// The polynomial `p` of degree `degree` whose roots were not examined, as the prose says it:
/// whole with `whole` or when short (`` `21C² − 12C + 272` (degree 2) ``), else its first
/// terms and how to show it all (`` `4618108208206766407680a³⁴ + … (a polynomial of 35
/// terms)` (degree 34; --full-expressions shows it whole) ``).
fn unexamined_shown(p: &trigpoly::Expr, degree: usize, whole: bool, caller: Caller) -> String {
    let all = p.to_string();
    let shown = if whole {
        all.clone()
    } else {
        p.brief_excerpt()
    };
    match shown == all {
        true => format!("`{all}` (degree {degree})"),
        false => format!(
            "`{shown}` (degree {degree}; {} shows it whole)",
            caller.names("--full-expressions", "RenderOptions::shown_monomials(None)")
        ),
    }
}
