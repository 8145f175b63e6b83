//! JSON with a stable schema, `superint-report/1`:
//!
//! ```text
//! {
//!   "schema": "superint-report/1",
//!   "title": string, "subtitle": string,
//!   "summary": { "claims": int (distinct ids, a file's own in a check), "proved": int, "refuted": int,
//!                "undecided": int (claims whose check stopped at a limit, none refuted),
//!                "checks": int, "all_proved": bool,
//!                "as_expected": int (checks that met their expectation),
//!                "all_as_expected": bool, "seconds": number | null },
//!   "sections": [ { "number": int, "title": string,
//!                   "file": string | null   (the system file, as named on the command line) } ],
//!   "claims": [ { "id": "C09",
//!                 "section": int   (the "number" of its section in "sections"),
//!                 "statement": "{L, G1} = −G2"   (unicode, display names),
//!                 "ascii": string | null   (the claim as text superint reads back in its
//!                          system file: as the file writes it, or a found bracket, relation
//!                          or integral in the file's names; null for the paper's claims and
//!                          those a tower or a proof decides),
//!                 "condition": string | null   (unicode, as printed),
//!                 "condition_ascii": string | null   (the condition as text superint reads
//!                          back: `p_theta = I*omega`, with the fixed parameter values a
//!                          result holds at; null where "ascii" is null),
//!                 "kind": "identity" | "nonvanishing" | "rank"   (a rank claim's certificate
//!                          is in "ranks", under the same "id"),
//!                 "outcome": "proved" | "refuted" | "undecided"   (undecided: its check
//!                          stopped at a limit, which "undecided" gives, and the report's
//!                          "errors" with its place),
//!                 "expect": "proved" | "refuted"   (what the claim is meant to do),
//!                 "meets_expectation": bool,
//!                 "residual": ascii | null   (lhs − rhs of a refuted identity, or when
//!                          "residual_excerpt" is set the terms of its leading monomials),
//!                 "residual_in_functions": ascii | null   (the residual as a polynomial
//!                          of degree ≤ 3 in H and the system's named functions, proved for
//!                          every value of the parameters, where it is one: "-4*H*L/M", with
//!                          the factor its terms share as the text writes it:
//!                          "-(2*omega - 3*Omega)*Q_2_3"),
//!                 "residual_factored": ascii | null   (the residual printed whole as the
//!                          factor its terms share times the rest, where it has no form in the
//!                          functions and its terms share a factor: "2*F*(x*p_x + y*p_y)/M"),
//!                 "residual_excerpt": { "shown_monomials", "monomials" } | null   (set
//!                          when the residual had more monomials outside the angles than
//!                          `Options::shown_monomials`: "residual" is then every term of its
//!                          first "shown_monomials" of "monomials"),
//!                 "witness": ascii | null    (the nonzero value of a proved nonvanishing),
//!                 "note": string | null,
//!                 "undecided": string | null   (the limit's message),
//!                 "seconds": number | null,
//!                 "level_set": { "text" (as printed: "A = 0"), "ascii" (as the file writes
//!                          it), "polynomial" (P = EXPR − VALUE, ASCII), "quotient" (ASCII Q
//!                          with lhs − rhs = Q*P, recomputed, for a proved claim; null for a
//!                          refuted one, whose "residual" is lhs − rhs's remainder on division
//!                          by P: lhs − rhs is not a multiple of P) }   (only on a claim made
//!                          on a level set, `on` in a system file) } ],
//!   "equations": [ { "section", "caption", "lines": [ { "lhs", "text", "ascii", "latex",
//!                 "in_functions": { "text", "ascii", "latex" } | null   (the right side as a
//!                          polynomial of degree ≤ 3 in H and the named functions, proved, where
//!                          `bracket` finds it one; with the family instances at the indices
//!                          its arguments mention, and, under each integral a search of a file
//!                          shows, at those that are integrals there: "-8*Q_1_2"; under each
//!                          amplitude of its complex forms, in the functions alone: "i*Zy";
//!                          as the text writes it, with the factor its terms share:
//!                          "-(2*omega - 3*Omega)*Q_2_3"; and "holds_at": ascii, only on
//!                          the restatement of an integral a search did not lift back to
//!                          the parameters it fixed, or of its amplitude: where it is proved,
//!                          at those values alone, the `--when` condition first where there
//!                          is one, "p_theta = 1, M = 1, omega = 1, I = 1", as the integral's
//!                          claim's "condition_ascii" and `--when` read it; absent where the
//!                          restatement holds at the condition for every value, as one that
//!                          integral is lifted through does, an integral for every value with
//!                          the parameters symbolic: "2*H", the claim "{2*H, H} = 0"),
//!                 "factored": { "text", "ascii", "latex" } | null   (the right side as the
//!                          factor its terms share times the rest, where `bracket` or `expand`
//!                          finds one: "F*(x*p_x + y*p_y)/M") } ],
//!                 "kept_by_flow": bool | null, "flow_note": string | null   (only for
//!                          `bracket --when`: whether the flow of H keeps the condition's
//!                          surface, and where it does not, the note that says so: a zero there
//!                          is no conservation law; null, with a note that says why, where a
//!                          limit stopped the check) } ],
//!   "tables": [ { "section", "caption" (plain text, as every title and caption: "{A, B} for
//!                 the harmonic rotor (row A, column B)"), "functions": [ascii names],
//!                 "display": [names],
//!                 "entries": [[ { "text", "ascii", "latex" } ]]   ("ascii" null where the
//!                          entry is no expression: `*`, outside a closure's table, or `?`),
//!                 "excerpts": [ { "row", "column", "shown_monomials", "monomials" } ]   (the
//!                          entries of more monomials outside the angles than
//!                          `Options::shown_monomials`: each is then every term of its first
//!                          "shown_monomials" of "monomials"),
//!                 "undecided": [ { "row", "column", "message" } ]   (the entries above the
//!                          diagonal, and so their transposes, that a limit stopped: shown
//!                          as "?", the limit's message here) } ],
//!   "towers": [ { "section", "id", "system", "family" ("K_{m,n}", as printed), "ladder"
//!                 (the text's: "Z" in the paper, "K_{m,n} = Z^m e^{−inθ}" for a file's
//!                 family), "max", "checked", "failures": [[m, n]], "outcome", "seconds" } ],
//!   "proofs": [ { "section", "title", "facts": [ { "statement", "holds" } ],
//!                 "bases" (the names the derivation and the lemma give the two base
//!                 functions: ["A", "B"], or ["F", "G"] where the file names A or B),
//!                 "derivation" (the derivation property checked, in those names),
//!                 "leibniz_check", "lemma", "conclusion", "claims": [ids], "outcome" } ],
//!   "ranks": [ { "section", "id", "functions", "coordinates", "expected",
//!                "condition", "condition_ascii" (parameters the rank is taken at, or null), "rank",
//!                "minor": { "rows": [names], "columns": [names], "value": string },
//!                "point": [ { "variable", "value" } | { "variable", "cos", "sin" } ],
//!                "upper_bound": { "kind": "size" | "vanishing_minors", "minors": int | null
//!                                 (how many minors one larger than "minor" and containing it
//!                                 were expanded, each identically zero) },
//!                "outcome" } ],
//!   "searches": [ { "section", "space": { "momenta_degree", "positions_degree", "trig_degree",
//!                   "laurent", "coordinates", "momenta", "angles", "left_out",
//!                   "left_out_as_functions" (of "left_out", those the condition sets to a
//!                   function of the others, not to a constant), "valued_denominators" (the
//!                   declared denominators the condition gives a value, their powers left
//!                   out), "poisson_degree", "poisson_variables", "denominators_degree",
//!                   "radicals_degree" },
//!                   "parameters", "unknowns", "equations", "blocks", "largest_block",
//!                   "dimension", "functional_rank": int | null (of the basis: as for
//!                   "exceptional_values", null for no integral), "functional_rank_exact": bool
//!                   | null, "functional_rank_bound": "flow" | "size" | "vanishing_minors" |
//!                   "generated" | null (what certifies it from above; "generated": the known
//!                   integrals generate every integral, and their rank is the same), "by_momenta_degree": [int] (≤ j),
//!                   "counts": [[int]] (momenta degree exactly j, order k), "by_poisson_degree": [int] (≤ j in
//!                   the Poisson variables), "poisson_counts": [[int]] (their degree exactly
//!                   j, order k), "for_every_value": int,
//!                   "shown": [ids], "new_only": { "known", "products", "generated",
//!                          "past_degree_undecided" (only for `search --on`: a product past
//!                          the space's degree may fall back into it modulo P, and an integral
//!                          told new may be generated by one) } | null,
//!                   "level_set": { "text", "polynomial" (P = EXPR − VALUE, ASCII),
//!                          "leading_monomial" (ASCII), "left_out": int (unknowns it divides),
//!                          "normal_form_outside": { "function", "normal_form" } (ASCII: a
//!                          function of the space whose normal form modulo P leaves it; only
//!                          the integrals whose normal form lies in the space are found) | null }
//!                          (only for `search --on`; each claim then reads `{I, H} = Q P`, its
//!                          "ascii" the identity `{K, H} = (Q)*(P)`) } ],
//!   "closures": [ { "section", "generators", "degree", "monomials", "rank", "parameters",
//!                   "closes": bool, "outside": [[a, b]], "unlifted": int,
//!                   "brackets": [ids], "relations": [ids] } ],
//!   "exceptional_values": [ { "section", "parameter", "generic": { "value", "dimension",
//!                   "section", "functional_rank", "functional_rank_exact" } (the search at a
//!                   value that is no root of any determinant, shown in section "section";
//!                   "functional_rank": int, the rank of the Jacobian of its basis by every
//!                   phase variable, in the whole phase space on a level set too,
//!                   "functional_rank_exact": bool, false where it is only a lower bound, the
//!                   upper bound's bordering minors too many), "values": [ { "value",
//!                   "dimension", "section", "functional_rank", "functional_rank_exact" } ]
//!                   (the rational values with more integrals, increasing, each with the
//!                   section of the search there; a rank larger than the generic one's, that
//!                   exact, means functionally new integrals, off a level set or on one the
//!                   text says the ranks are on), "not_exceptional": [values] (the
//!                   rational roots of the determinants where the search found no more),
//!                   "unexamined": ascii | null (the polynomial in the parameter whose
//!                   roots, irrational and complex, were not ruled out: every minor tried
//!                   of some block vanishes there; not examined),
//!                   "unexamined_real_roots": int | null (how many of its roots are real),
//!                   "ruled_out": ascii | null (the polynomial whose roots, irrational and
//!                   complex, hold no more integrals: every block keeps its generic rank
//!                   there), "ruled_out_roots": int (its degree, 0 when null),
//!                   "ruled_out_real_roots": int (how many of them are real),
//!                   "ruled_out_prime": int | null (the prime modulo which the minors were
//!                   taken, null when none was ruled out),
//!                   "ruled_out_exact_blocks": int (how many blocks were shown to keep their
//!                   rank by exact determinants over Q, where a root stayed common to their
//!                   minors modulo the prime, rather than modulo it alone; 0 when none was
//!                   ruled out),
//!                   "largest_minor": { "size", "degree" }, "zero_left_out": bool (0, a root,
//!                   left out: H has a negative power of the parameter and no value there),
//!                   "denominator_roots_left_out": [string] (the roots, as fractions, left out
//!                   where a declared denominator in the parameter is zero: H has no value
//!                   there) } ]
//!                   (only for `search --find-values`)
//!   "warnings": [ { "section", "file", "line", "column", "message" } ]   (only where there
//!                   are any: a name of the section's file run together and read as a
//!                   product that may not have been meant, `Lxx` beside a function `Lx`;
//!                   "message" says the reading and what to write instead)
//! }
//!
//! where a search's or closure's "parameters" is `{ "fixed": [ { "parameter", "value" } ],
//! "symbolic": [names], "symbolic_degree": int | null, "condition": string | null }`.
//! ```
//!
//! Exact numbers (minor values, point coordinates) are strings, so that no reader rounds them;
//! expressions are given in ASCII that `superint` parses back (and in unicode and LaTeX where
//! they are shown). `seconds` is `null` under `--no-timings`, which makes the output
//! reproducible byte for byte.

use serde_json::{json, Value};
use trigpoly::{Expr, Factored, Style, VarKind};

use super::{plain, Options};
use crate::report::{
    written_in_functions, ClaimOutcome, ClaimResult, ClosureFacts, Entry, Equations,
    ExceptionalFacts, Facts, ParameterFacts, ProofResult, RankResult, Report, SearchFacts,
    TableResult, TowerResult, ValueFacts,
};
use brackets::{BoundedRank, Entry as TableEntry};

/// The schema's name and version.
pub const SCHEMA: &str = "superint-report/1";

/// Renders a report as pretty-printed JSON.
pub fn render(report: &Report, options: &Options) -> String {
    pretty(&value(report, options))
}

/// A JSON value pretty-printed, with a final newline.
pub fn pretty(value: &Value) -> String {
    let mut text = serde_json::to_string_pretty(value).expect("a JSON value always serialises");
    text.push('\n');
    text
}

/// The report as a JSON value (a [`serde_json::Value`], the crate re-exported as
/// `superint::serde_json`), for a program that reads it or puts it into a document of its own.
///
/// ```
/// use superint::prelude::*;
/// use superint::serde_json::Value;
///
/// let rotor = load_system_file("systems/harmonic-rotor.toml", &LimitsOverride::default())?;
/// let report = check_report([&rotor])?;
/// let json: Value = superint::render::json::value(&report, &RenderOptions::reproducible());
/// assert_eq!(json["schema"], "superint-report/1");
/// let claims = json["claims"].as_array().unwrap();
/// assert_eq!(claims.len(), report.claims().len());
/// assert!(claims.iter().all(|c| c["meets_expectation"] == true));
/// # Ok::<(), FileError>(())
/// ```
pub fn value(report: &Report, options: &Options) -> Value {
    let mut lists = Lists::new(options.timings);
    for s in &report.sections {
        for e in &s.entries {
            lists.add(e, s.number);
        }
    }
    lists.document(report)
}

/// A warning as the JSON gives it, `{ "section", "file", "line", "column", "message" }`: a
/// report's `warnings` with their `section`, and without one, those that `check`'s `errors`
/// give of a file that did not load.
pub fn warning(w: &crate::system_file::Warning, section: Option<u32>) -> Value {
    let mut value = serde_json::Map::new();
    if let Some(section) = section {
        value.insert("section".into(), json!(section));
    }
    value.insert("file".into(), json!(w.origin));
    value.insert("line".into(), json!(w.location.as_ref().map(|l| l.line)));
    value.insert(
        "column".into(),
        json!(w.location.as_ref().map(|l| l.column)),
    );
    value.insert("message".into(), json!(w.message));
    Value::Object(value)
}

/// The document's lists of claims, equations, tables, towers, proofs, ranks, searches and
/// closures, filled entry by entry in the order of the report.
struct Lists {
    /// Whether times are given: without them (`--no-timings`) every `seconds` is `null`, so
    /// that the output is the same on every run.
    timings: bool,
    claims: Vec<Value>,
    equations: Vec<Value>,
    tables: Vec<Value>,
    towers: Vec<Value>,
    proofs: Vec<Value>,
    ranks: Vec<Value>,
    searches: Vec<Value>,
    closures: Vec<Value>,
    exceptional_values: Vec<Value>,
    warnings: Vec<Value>,
}

impl Lists {
    /// Empty lists, with times given or not.
    fn new(timings: bool) -> Self {
        Lists {
            timings,
            claims: Vec::new(),
            equations: Vec::new(),
            tables: Vec::new(),
            towers: Vec::new(),
            proofs: Vec::new(),
            ranks: Vec::new(),
            searches: Vec::new(),
            closures: Vec::new(),
            exceptional_values: Vec::new(),
            warnings: Vec::new(),
        }
    }

    /// A time in seconds, or `null` without timings.
    fn seconds(&self, s: f64) -> Value {
        if self.timings {
            json!(s)
        } else {
            Value::Null
        }
    }

    /// A claim of section `section`, with its time.
    fn claim(&self, c: &ClaimResult, section: u32) -> Value {
        claim(c, section, self.seconds(c.seconds))
    }

    /// Adds an entry of section `section` to its list; a tower, a proof and a rank add their
    /// claims to the claims' list too, before themselves.
    fn add(&mut self, entry: &Entry, section: u32) {
        match entry {
            Entry::Heading(_) | Entry::Text(_) => {}
            Entry::Equations(eq) => self.equations.push(equations(eq, section)),
            Entry::Claim(c) => self.claims.push(self.claim(c, section)),
            Entry::Table(t) => self.tables.push(table(t, section)),
            Entry::Tower(t) => {
                self.claims.push(self.claim(&t.claim, section));
                self.towers
                    .push(tower(t, section, self.seconds(t.claim.seconds)));
            }
            Entry::Proof(p) => {
                let claims: Vec<Value> = p.claims.iter().map(|c| self.claim(c, section)).collect();
                self.claims.extend(claims);
                self.proofs.push(proof(p, section));
            }
            Entry::Rank(r) => {
                self.claims.push(self.claim(&r.claim, section));
                self.ranks.push(rank(r, section));
            }
            Entry::Data(Facts::Search(f)) => self.searches.push(search(f, section)),
            Entry::Data(Facts::Closure(f)) => self.closures.push(closure(f, section)),
            Entry::Data(Facts::ExceptionalValues(f)) => {
                self.exceptional_values.push(exceptional_values(f, section));
            }
            Entry::Warning(w) => self.warnings.push(warning(w, Some(section))),
        }
    }

    /// The whole document: the schema, the titles, the summary of the claims and the
    /// sections, then the lists.
    fn document(self, report: &Report) -> Value {
        let ids = report.claim_outcomes();
        let counted = |o: ClaimOutcome| ids.iter().filter(|(_, outcome)| *outcome == o).count();
        let mut document = json!({
            "schema": SCHEMA,
            "title": plain(&report.title),
            "subtitle": plain(&report.subtitle),
            "summary": {
                "claims": ids.len(),
                "proved": counted(ClaimOutcome::Proved),
                "refuted": counted(ClaimOutcome::Refuted),
                "undecided": counted(ClaimOutcome::Undecided),
                "checks": self.claims.len(),
                "all_proved": report.all_proved(),
                "as_expected": report.claims().iter().filter(|c| c.meets_expectation()).count(),
                "all_as_expected": report.all_as_expected(),
                "seconds": self.seconds(report.seconds),
            },
            "sections": report.sections.iter().map(|s| json!({
                "number": s.number,
                "title": plain(&s.title),
                "file": s.file,
            })).collect::<Vec<_>>(),
            "claims": self.claims,
            "equations": self.equations,
            "tables": self.tables,
            "towers": self.towers,
            "proofs": self.proofs,
            "ranks": self.ranks,
            "searches": self.searches,
            "closures": self.closures,
        });
        // Only where there are any, so that a report without them is as it always was.
        if !self.exceptional_values.is_empty() {
            document["exceptional_values"] = Value::Array(self.exceptional_values);
        }
        if !self.warnings.is_empty() {
            document["warnings"] = Value::Array(self.warnings);
        }
        document
    }
}

/// An outcome in words: `proved` or `refuted`.
fn outcome(ok: bool) -> &'static str {
    if ok {
        "proved"
    } else {
        "refuted"
    }
}

/// Displayed equations, each line's right side in the three notations with its left side and,
/// where it has one, its form in the functions.
fn equations(eq: &Equations, section: u32) -> Value {
    let mut value = json!({
        "section": section,
        "caption": plain(&eq.caption),
        "lines": eq.lines.iter().map(|l| {
            let mut v = expr(&l.rhs);
            let line = v.as_object_mut().expect("an object");
            line.insert("lhs".into(), json!(l.lhs));
            let mut restated = l.in_functions.as_ref().map_or(Value::Null, in_functions);
            // Only on a restatement at the fixed values, so that the others are as they were.
            if let (Some(at), Some(r)) = (&l.in_functions_holds_at, restated.as_object_mut()) {
                r.insert("holds_at".into(), json!(at));
            }
            line.insert("in_functions".into(), restated);
            line.insert("factored".into(), l.factored.as_ref().map_or(Value::Null, factored));
            v
        }).collect::<Vec<_>>(),
    });
    // Only where it was asked (a bracket at a condition), so that other equations are as
    // they always were.
    if let Some(flow) = &eq.flow {
        value["kept_by_flow"] = json!(flow.kept());
        value["flow_note"] = flow.note().map_or(Value::Null, |n| json!(plain(n)));
    }
    value
}

/// A table of brackets: each entry in the three notations, the entries cut short
/// (`excerpts`) and those a limit stopped (`undecided`).
fn table(t: &TableResult, section: u32) -> Value {
    json!({
        "section": section,
        "caption": plain(&t.caption),
        "functions": t.table.names,
        "display": t.table.display,
        "entries": t.table.entries.iter().enumerate().map(|(a, row)| {
            row.iter().enumerate().map(|(b, e)| json!({
                "text": t.entry(a, b, Style::Unicode),
                // Only an expression reads back: not `*` (outside) or `?` (undecided).
                "ascii": match e {
                    TableEntry::Outside | TableEntry::Undecided(_) => Value::Null,
                    _ => t.entry(a, b, Style::Ascii).into(),
                },
                "latex": t.entry(a, b, Style::Latex),
            })).collect::<Vec<_>>()
        }).collect::<Vec<_>>(),
        "excerpts": t.excerpts.iter().map(|((a, b), e)| json!({
            "row": a,
            "column": b,
            "shown_monomials": e.shown,
            "monomials": e.monomials,
        })).collect::<Vec<_>>(),
        "undecided": t.undecided().into_iter().map(|(a, b, message)| json!({
            "row": a,
            "column": b,
            "message": message,
        })).collect::<Vec<_>>(),
    })
}

/// A tower of brackets checked by expansion, with its time.
fn tower(t: &TowerResult, section: u32, seconds: Value) -> Value {
    json!({
        "section": section,
        "id": t.claim.id,
        "system": t.system,
        "family": t.family,
        "ladder": t.ladder,
        "max": t.max,
        "checked": t.checked,
        "failures": t.failures.iter().map(|&(m, n)| json!([m, n])).collect::<Vec<_>>(),
        "outcome": outcome(t.claim.proved),
        "seconds": seconds,
    })
}

/// A proof for all `m, n`: its facts, lemma and conclusion, and the ids of the claims it
/// decides.
fn proof(p: &ProofResult, section: u32) -> Value {
    json!({
        "section": section,
        "title": p.title,
        "facts": p.facts.iter().map(|f| json!({
            "statement": f.statement,
            "holds": f.holds,
            "found": f.found.as_ref().map(|e| e.render(Style::Ascii)),
            "found_statement": f.found_statement,
        })).collect::<Vec<_>>(),
        "bases": p.bases,
        "derivation": p.derivation(),
        "leibniz_check": p.leibniz_check,
        "lemma": p.lemma,
        "conclusion": p.conclusion,
        "claims": p.claims.iter().map(|c| c.id.clone()).collect::<Vec<_>>(),
        "outcome": outcome(p.holds()),
    })
}

/// A factored form in the three notations.
fn factored(f: &Factored) -> Value {
    let [text, ascii, latex] = [Style::Unicode, Style::Ascii, Style::Latex].map(|s| f.render(s));
    json!({ "text": text, "ascii": ascii, "latex": latex })
}

/// An expression in the three notations (its cos/sin normal form computed once).
fn expr(e: &Expr) -> Value {
    let [text, ascii, latex] = e.render_each([Style::Unicode, Style::Ascii, Style::Latex]);
    json!({ "text": text, "ascii": ascii, "latex": latex })
}

/// A polynomial in named functions as the text shows it, with the factor its terms share:
/// `-(2*omega - 3*Omega)*Q_2_3` ([`written_in_functions`]).
fn in_functions(e: &Expr) -> Value {
    let [text, ascii, latex] =
        [Style::Unicode, Style::Ascii, Style::Latex].map(|s| written_in_functions(e, s));
    json!({ "text": text, "ascii": ascii, "latex": latex })
}

fn claim(c: &ClaimResult, section: u32, seconds: Value) -> Value {
    let mut value = json!({
        "id": c.id,
        "section": section,
        "statement": c.statement,
        "ascii": c.written,
        "condition": c.condition,
        "condition_ascii": c.condition_ascii,
        "kind": c.kind.name(),
        "outcome": c.outcome().name(),
        "expect": c.expect.name(),
        "meets_expectation": c.meets_expectation(),
        "residual": c.residual.as_ref().map(|r| r.render(Style::Ascii)),
        "residual_in_functions": c.residual_in_functions.as_ref().map(|r| written_in_functions(r, Style::Ascii)),
        "residual_factored": c.residual_factored().map(|r| r.render(Style::Ascii)),
        "residual_excerpt": c.excerpt.map(|e| json!({
            "shown_monomials": e.shown,
            "monomials": e.monomials,
        })),
        "witness": c.witness.as_ref().map(|w| w.render(Style::Ascii)),
        "note": c.note,
        "undecided": c.undecided,
        "seconds": seconds,
    });
    // Only a claim on a level set has the key, so that no other claim's JSON changes.
    if let (Some(l), Some(map)) = (&c.on_level, value.as_object_mut()) {
        map.insert(
            "level_set".into(),
            json!({
                "text": l.text,
                "ascii": l.ascii,
                "polynomial": l.polynomial.render(Style::Ascii),
                "quotient": l.quotient.as_ref().map(|q| q.render(Style::Ascii)),
            }),
        );
    }
    value
}

fn rank(r: &RankResult, section: u32) -> Value {
    let c = &r.certificate;
    let name = |v| r.vars.variable(v).name().to_string();
    json!({
        "section": section,
        "id": r.claim.id,
        "functions": r.functions,
        "coordinates": r.coordinates().iter().map(|&v| name(v)).collect::<Vec<_>>(),
        "expected": r.expected,
        "condition": r.claim.condition,
        "condition_ascii": r.claim.condition_ascii,
        "rank": c.rank,
        "minor": {
            "rows": r.minor_functions(),
            "columns": r.minor_coordinates().iter().map(|v| v.name()).collect::<Vec<_>>(),
            "value": c.minor_value.to_string(),
        },
        "point": c.point.iter().map(|(v, value)| {
            if r.vars.variable(*v).kind() == VarKind::Angle {
                json!({"variable": name(*v), "cos": value.re.to_string(), "sin": value.im.to_string()})
            } else {
                json!({"variable": name(*v), "value": value.to_string()})
            }
        }).collect::<Vec<_>>(),
        "upper_bound": json!({"kind": c.upper.name(), "minors": c.upper.minors()}),
        "outcome": r.claim.outcome().name(),
    })
}

/// The parameters of a search or closure: `{"fixed": [{"parameter", "value"}], "symbolic",
/// "symbolic_degree", "condition"}`.
fn parameters(p: &ParameterFacts) -> Value {
    json!({
        "fixed": p.fixed.iter().map(|(name, value)| json!({"parameter": name, "value": value}))
            .collect::<Vec<_>>(),
        "symbolic": p.symbolic,
        "symbolic_degree": p.symbolic_degree,
        "condition": p.condition,
    })
}

fn search(f: &SearchFacts, section: u32) -> Value {
    let s = &f.space;
    let mut value = json!({
        "section": section,
        "space": {
            "momenta_degree": s.momenta_degree,
            "positions_degree": s.positions_degree,
            "trig_degree": s.trig_degree,
            "laurent": s.laurent,
            "coordinates": f.coordinates,
            "momenta": f.momenta,
            "angles": f.angles,
            "left_out": f.left_out,
            "left_out_as_functions": f.left_out_as_functions,
            "valued_denominators": f.valued_denominators,
            "poisson_degree": s.poisson_degree,
            "poisson_variables": f.poisson,
            "denominators_degree": s.denominators_degree,
            "radicals_degree": s.radicals_degree,
        },
        "parameters": parameters(&f.parameters),
        "unknowns": f.unknowns,
        "equations": f.equations,
        "blocks": f.blocks,
        "largest_block": f.largest_block,
        "dimension": f.dimension,
        "functional_rank": f.functional_rank.as_ref().map(BoundedRank::rank),
        "functional_rank_exact": f.functional_rank.as_ref().map(BoundedRank::is_exact),
        "functional_rank_bound": match &f.functional_rank {
            Some(BoundedRank::Exact(cert)) => Some(cert.upper.name()),
            _ => None,
        },
        "by_momenta_degree": f.by_momenta_degree,
        "counts": f.counts,
        "by_poisson_degree": f.by_poisson_degree,
        "poisson_counts": f.poisson_counts,
        "for_every_value": f.for_every_value,
        "shown": f.shown,
        "generators": f.generators,
        "new_only": f.new_only.as_ref().map(|n| json!({
            "known": n.known,
            "products": n.products,
            "generated": n.generated,
        })),
    });
    // Only a search on a level set has the keys, so that no other search's JSON changes.
    if let (Some(_), Some(n), Some(new_only)) = (
        &f.level_set,
        &f.new_only,
        value.get_mut("new_only").and_then(Value::as_object_mut),
    ) {
        new_only.insert(
            "past_degree_undecided".into(),
            n.past_degree_undecided.into(),
        );
    }
    if let (Some(l), Some(map)) = (&f.level_set, value.as_object_mut()) {
        map.insert(
            "level_set".into(),
            json!({
                "text": l.text,
                "polynomial": l.polynomial,
                "leading_monomial": l.leading_monomial,
                "left_out": l.left_out,
                "normal_form_outside": l.normal_form_outside.as_ref().map(|(function, normal_form)| {
                    json!({ "function": function, "normal_form": normal_form })
                }),
            }),
        );
    }
    value
}

/// The exceptional values of `superint search --find-values`.
fn exceptional_values(f: &ExceptionalFacts, section: u32) -> Value {
    let value = |v: &ValueFacts| {
        json!({
            "value": v.value,
            "dimension": v.dimension,
            "section": v.section,
            "functional_rank": v.functional_rank.rank(),
            "functional_rank_exact": v.functional_rank.is_exact(),
        })
    };
    json!({
        "section": section,
        "parameter": f.parameter,
        "generic": value(&f.generic),
        "values": f.values.iter().map(value).collect::<Vec<_>>(),
        "not_exceptional": f.not_exceptional,
        "unexamined": f.unexamined,
        "unexamined_real_roots": f.unexamined_real_roots,
        "ruled_out": f.ruled_out.as_ref().map(|r| &r.polynomial),
        "ruled_out_roots": f.ruled_out.as_ref().map_or(0, |r| r.roots),
        "ruled_out_real_roots": f.ruled_out.as_ref().map_or(0, |r| r.real_roots),
        "ruled_out_prime": f.ruled_out.as_ref().and_then(|r| r.prime),
        "ruled_out_exact_blocks": f.ruled_out.as_ref().map_or(0, |r| r.exact_blocks),
        "largest_minor": { "size": f.largest_minor.0, "degree": f.largest_minor.1 },
        "zero_left_out": f.zero_left_out,
        "denominator_roots_left_out": f.denominator_roots_left_out,
    })
}

fn closure(f: &ClosureFacts, section: u32) -> Value {
    json!({
        "section": section,
        "generators": f.generators,
        "degree": f.degree,
        "monomials": f.monomials,
        "rank": f.rank,
        "parameters": parameters(&f.parameters),
        "closes": f.outside.is_empty(),
        "outside": f.outside.iter().map(|(a, b)| json!([a, b])).collect::<Vec<_>>(),
        "unlifted": f.unlifted,
        "brackets": f.brackets,
        "relations": f.relations,
    })
}
