//! Markdown: formulas as code spans in the paper's unicode notation, bracket tables as Markdown
//! tables, claims as lists.

use trigpoly::Style;

use super::tex::{set_sentence, Piece};
use super::text::{point, upper_bound};
use super::{stopped, verdict, Options, SHOWN_MONOMIALS};
use crate::report::{
    counted, ClaimKind, ClaimResult, Entry, Equations, FlowKept, ProofResult, RankResult, Report,
    SummaryKind, TableResult, TowerResult,
};

/// Renders a report as Markdown.
pub fn render(report: &Report, options: &Options) -> String {
    let mut blocks: Vec<String> = vec![format!("# {}", prose(&report.title))];
    if !report.subtitle.is_empty() {
        blocks.push(format!("*{}*", prose(&report.subtitle)));
    }
    for s in &report.sections {
        blocks.push(format!("## {}. {}", s.number, prose(&s.title)));
        let mut list: Vec<String> = Vec::new();
        for e in s.shown_entries() {
            if let Entry::Claim(c) = e {
                list.push(claim(c));
                continue;
            }
            if !list.is_empty() {
                blocks.push(std::mem::take(&mut list).join("\n"));
            }
            blocks.push(entry(e));
        }
        if !list.is_empty() {
            blocks.push(list.join("\n"));
        }
    }
    // A check's summary is words, numbers and ids, as in LaTeX; another's formulas are code.
    let summary = report.summary_line(options.timings);
    let summary = match report.summary {
        SummaryKind::Check { .. } => prose(&summary),
        _ => sentence(&summary),
    };
    blocks.push(format!("**{summary}**"));
    let mut out = blocks.join("\n\n");
    out.push('\n');
    out
}

fn code(s: &str) -> String {
    format!("`{s}`")
}

/// A sentence that mixes prose and formulas (a proof's title, lemma and closing), each
/// formula a code span, as LaTeX sets it in math ([`super::tex::sentence`]): `for all
/// `m, n ≥ 0`, from the ladder function `Z`` (the formulas were bare prose).
fn sentence(s: &str) -> String {
    set_sentence(s, |piece| match piece {
        Piece::Prose(p) => prose(p),
        // A number alone reads as prose: `12 claims`, not a code span.
        Piece::Formula(f) if f.chars().all(|c| c.is_ascii_digit() || c == '.') => prose(f),
        Piece::Formula(f) => code(f),
    })
}

/// Prose for Markdown: `<`, `>` and `&` outside code spans written as entities, so that a
/// name such as `<stdin>` is not read as an HTML tag and dropped.
fn prose(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut in_code = false;
    for c in s.chars() {
        match (c, in_code, entity(c)) {
            ('`', _, _) => {
                in_code = !in_code;
                out.push(c);
            }
            (_, false, Some(e)) => out.push_str(e),
            _ => out.push(c),
        }
    }
    out
}

/// The entity Markdown prose writes `c` as, where `c` would read as HTML: `<`, `>`, `&`.
fn entity(c: char) -> Option<&'static str> {
    match c {
        '<' => Some("&lt;"),
        '>' => Some("&gt;"),
        '&' => Some("&amp;"),
        _ => None,
    }
}

/// A name of the user's (a claim's id) as Markdown shows it literally: the punctuation that
/// Markdown reads as markup escaped by a backslash, so that the id `__x__` is not emphasis
/// inside the bold verdict, and `<`, `>`, `&` as [`prose`] writes them.
fn literal(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match (c, entity(c)) {
            ('\\' | '`' | '*' | '_' | '[' | ']' | '|' | '~' | '#', _) => {
                out.push('\\');
                out.push(c);
            }
            (_, Some(e)) => out.push_str(e),
            _ => out.push(c),
        }
    }
    out
}

fn entry(e: &Entry) -> String {
    match e {
        Entry::Heading(h) => format!("### {}", prose(h)),
        Entry::Text(t) => prose(t),
        Entry::Warning(w) => format!("**Warning:** {}", prose(&w.markup)),
        Entry::Equations(eq) => equations(eq),
        Entry::Claim(c) => claim(c),
        Entry::Table(t) => table(t),
        Entry::Proof(p) => proof(p),
        Entry::Tower(t) => tower(t),
        Entry::Rank(r) => rank(r),
        Entry::Data(_) => String::new(),
    }
}

fn equations(eq: &Equations) -> String {
    let mut lines = Vec::new();
    if !eq.caption.is_empty() {
        lines.push(format!("{}:", prose(&eq.caption)));
        lines.push(String::new());
    }
    for l in &eq.lines {
        let mut line = format!("- {}", code(&format!("{} = {}", l.lhs, l.rhs)));
        if let Some(f) = l.restated(Style::Unicode) {
            line.push_str(&format!(" = {}", code(&f)));
        }
        lines.push(line);
    }
    if let Some(note) = eq.flow.as_ref().and_then(FlowKept::note) {
        lines.push(String::new());
        lines.push(format!("Note: {}", prose(note)));
    }
    lines.join("\n")
}

fn claim(c: &ClaimResult) -> String {
    let mut cond = match &c.condition {
        Some(cond) => format!(" at {}", code(cond)),
        None => String::new(),
    };
    if let Some(l) = &c.on_level {
        cond.push_str(&format!(" on {}", code(&l.text)));
    }
    let mut line = format!(
        "- {}{cond} — **{} {}**",
        code(&c.statement),
        literal(&c.id),
        verdict(c)
    );
    // On a level set: the quotient that proves it (the residual says the rest).
    if let Some((l, (product, q))) =
        (c.on_level.as_ref()).and_then(|l| Some((l, l.proof(Style::Unicode)?)))
    {
        line.push_str(&format!(
            ", {} with {}",
            code(&format!("{} = {product}", l.difference)),
            code(&format!("Q = {q}"))
        ));
    }
    if let Some(r) = &c.residual {
        line.push_str(&format!(", residual {}", code(&r.to_string())));
        if let Some(e) = &c.excerpt {
            line.push_str(&format!(" + … ({})", e.describe()));
        }
        if let Some(f) = c.residual_restated(Style::Unicode) {
            line.push_str(&format!(" = {}", code(&f)));
        }
        if let Some(l) = &c.on_level {
            line.push_str(&format!(
                " (the remainder on division by {}: not a multiple of P)",
                code(&format!("P = {}", l.polynomial))
            ));
        }
    }
    if let (ClaimKind::Nonvanishing, Some(w)) = (c.kind, &c.witness) {
        match w.printed_terms() {
            terms if terms <= SHOWN_MONOMIALS => {
                line.push_str(&format!(" (it equals {})", code(&w.to_string())));
            }
            terms => line.push_str(&format!(
                " (it is a nonzero sum of {})",
                counted(terms, "term")
            )),
        }
    }
    // A note's formulas are code, as LaTeX sets them in math: `proved for every `A, B`, at
    // `C = 2``.
    if let Some(n) = &c.note {
        line.push_str(&format!(" ({})", sentence(n)));
    }
    if let Some(u) = &c.undecided {
        line.push_str(&format!(" ({})", stopped(u)));
    }
    line
}

fn table(t: &TableResult) -> String {
    let table = &t.table;
    let mut lines = vec![format!("*{}*", t.caption), String::new()];
    let head: Vec<String> = table.display.iter().map(|d| code(d)).collect();
    lines.push(format!("| {} | {} |", code("{·,·}"), head.join(" | ")));
    lines.push(format!("|---|{}", "---|".repeat(head.len())));
    for (name, row) in table.display.iter().zip(t.cells(Style::Unicode)) {
        let cells: Vec<String> = row.iter().map(|c| code(c)).collect();
        lines.push(format!("| {} | {} |", code(name), cells.join(" | ")));
    }
    // What an entry cut to its leading part leaves out, once for each pair, and why an entry
    // is `?`.
    let bracket =
        |a: usize, b: usize| code(&format!("{{{}, {}}}", table.display[a], table.display[b]));
    let cut = t.excerpts.iter().filter(|((a, b), _)| a < b);
    let mut notes: Vec<String> = cut
        .map(|((a, b), e)| format!("- {}: {}", bracket(*a, *b), e.describe()))
        .collect();
    notes.extend(
        (t.undecided().into_iter())
            .map(|(a, b, message)| format!("- {} = ?: {}", bracket(a, b), stopped(message))),
    );
    if !notes.is_empty() {
        lines.push(String::new());
        lines.extend(notes);
    }
    lines.join("\n")
}

fn tower(t: &TowerResult) -> String {
    format!(
        "{}: {} expanded for {} (ladder {}), {}",
        claim(&t.claim),
        counted(t.checked, "bracket"),
        t.the_system,
        code(&t.ladder),
        t.verdict()
    )
}

fn proof(p: &ProofResult) -> String {
    let mut lines = vec![format!("**Proof** {}:", sentence(&p.title)), String::new()];
    let mark = |ok: bool| if ok { "holds" } else { "FAILS" };
    for (k, f) in p.facts.iter().enumerate() {
        let so = match &f.found_statement {
            Some(st) => format!(", so {}", code(st)),
            None => String::new(),
        };
        let found = match &f.found {
            Some(e) => format!(": the bracket is {}{so}", code(&e.to_string())),
            None => String::new(),
        };
        lines.push(format!(
            "{}. computed: {} — {}{found}",
            k + 1,
            fact(&f.statement),
            mark(f.holds)
        ));
    }
    lines.push(format!(
        "{}. computed: the derivation property {} on the base functions — {}",
        p.facts.len() + 1,
        code(&p.derivation()),
        mark(p.leibniz_check)
    ));
    lines.push(String::new());
    lines.push(format!("*Lemma:* {}.", sentence(&p.lemma)));
    lines.push(String::new());
    let (label, closing) = p.closing();
    lines.push(format!("*{label}:* {}.", sentence(&closing)));
    lines.push(String::new());
    lines.extend(p.claims.iter().map(claim));
    lines.join("\n")
}

/// A proof's fact as LaTeX sets it: its formula a code span, a parenthetical after two
/// spaces one of its own (`` `{e^{−iθ}, H} = −iΩ e^{−iθ}` (`Ω = p_θ/I`) ``: in one span the
/// spaces collapse, and it read as a product), and after a colon the prose that says why as a
/// sentence (`both are polynomials of degree at most 1 in m, n` was code).
fn fact(statement: &str) -> String {
    let (formula, why) = match statement.split_once(": ") {
        Some((formula, why)) => (formula, format!(": {}", sentence(why))),
        None => (statement, String::new()),
    };
    let parts: Vec<String> = formula
        .split("  ")
        .map(
            |part| match part.strip_prefix('(').and_then(|p| p.strip_suffix(')')) {
                Some(inner) => format!("({})", code(inner)),
                None => code(part),
            },
        )
        .collect();
    format!("{}{why}", parts.join(" "))
}

fn rank(r: &RankResult) -> String {
    let c = &r.certificate;
    let rows = r.minor_functions();
    let cols: Vec<&str> = r.minor_coordinates().iter().map(|v| v.unicode()).collect();
    let point: Vec<String> = point(r, Style::Unicode).iter().map(|p| code(p)).collect();
    if c.rank == 0 {
        // Every function has a zero gradient: no minor to show.
        return [claim(&r.claim), format!("  - ≤ 0: {}", upper_bound(r))].join("\n");
    }
    [
        claim(&r.claim),
        format!(
            "  - ≥ {}: the minor {} = {} ≠ 0 at {}",
            c.rank,
            code(&format!("∂({})/∂({})", rows.join(", "), cols.join(", "))),
            code(&trigpoly::render_number(&c.minor_value, Style::Unicode)),
            point.join(", ")
        ),
        format!("  - ≤ {}: {}", c.rank, upper_bound(r)),
    ]
    .join("\n")
}
