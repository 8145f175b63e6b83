//! A complete LaTeX document (article class and amsmath only): claims and equations in
//! `align*`, bracket tables as `array`s. Valid by construction: every string goes through
//! [`super::tex`], which escapes and balances, and the output is ASCII.

use trigpoly::Style;

use super::tex::{markup, markup_with, math, math_with, relation, sentence, text, Names};
use super::text::{point, upper_bound, wrap};
use super::{stopped, table_list, verdict, Options};
use crate::report::{
    counted, ClaimKind, ClaimResult, Entry, Equations, Excerpt, FlowKept, ProofResult, RankResult,
    Report, SummaryKind, TableResult, TowerResult,
};

/// Renders a report as a LaTeX document.
pub fn render(report: &Report, options: &Options) -> String {
    let mut out: Vec<String> = vec![
        r"\documentclass{article}".into(),
        r"\usepackage{amsmath}".into(),
        r"\allowdisplaybreaks".into(),
        r"\setlength{\emergencystretch}{3em}".into(),
        r"\begin{document}".into(),
        r"\begin{center}".into(),
        format!(r"{{\Large\bfseries {}}}", markup(&report.title)),
    ];
    if !report.subtitle.is_empty() {
        out.push(format!(r"\\[1ex] {}", text(&report.subtitle)));
    }
    out.push(r"\end{center}".into());
    for s in &report.sections {
        out.push(String::new());
        // A title may end with a file's path, which breaks after its slashes and underscores;
        // ragged right, so that a break that leaves a short line is taken rather than a path
        // set past the margin.
        let title = markup_with(&s.title, &s.names)
            .replace('/', r"/\allowbreak{}")
            .replace(r"\_", r"\_\allowbreak{}");
        out.push(format!(
            r"\section*{{\raggedright {}\quad {title}}}",
            s.number
        ));
        // Consecutive claims share one alignment, whose column is their widest left side.
        let mut run: Vec<&ClaimResult> = Vec::new();
        let claims = |out: &mut Vec<String>, run: &mut Vec<&ClaimResult>| {
            let column = claims_column(run.iter().copied(), &s.names);
            let mut rows: Vec<String> = run
                .drain(..)
                .flat_map(|c| claim_rows(c, &s.names, column))
                .collect();
            flush(out, &mut rows);
        };
        for e in s.shown_entries() {
            if let Entry::Claim(c) = e {
                run.push(c);
                continue;
            }
            claims(&mut out, &mut run);
            entry(&mut out, e, &s.names);
        }
        claims(&mut out, &mut run);
    }
    out.push(String::new());
    // A check's summary is words, numbers and the ids of claims, which are names, not
    // mathematics (`wrong_sign`, `lrl-sign`): it is set as text.
    // Another's formulas and numbers are math, set bold as its words are (`\boldmath`): in
    // `\textbf{$27$ claims: $27$ proved}` the digits were light among bold words.
    let summary = report.summary_line(options.timings);
    let summary = match report.summary {
        SummaryKind::Check { .. } => text(&summary),
        _ => format!(r"\boldmath {}", sentence(&summary)),
    };
    out.push(format!(r"\bigskip\noindent\textbf{{{summary}}}"));
    super::lines_to_text(&out, &[r"\end{document}"])
}

/// Writes pending `align*` rows.
fn flush(out: &mut Vec<String>, rows: &mut Vec<String>) {
    if rows.is_empty() {
        return;
    }
    out.push(r"\begin{align*}".into());
    let n = rows.len();
    for (k, r) in rows.drain(..).enumerate() {
        out.push(if k + 1 < n { format!(r"{r} \\") } else { r });
    }
    out.push(r"\end{align*}".into());
}

/// `lhs &= rhs`: a statement split at its relation for alignment.
fn aligned(statement: &str, names: &Names) -> String {
    let math = |s: &str| math_with(s, names);
    match relation(statement) {
        Some(k) => format!("{} &{}", math(&statement[..k]), math(&statement[k..])),
        None => format!("& {}", math(statement)),
    }
}

/// How wide a displayed equation may be, in printed characters.
const ROW: usize = 55;
/// How wide a claim's left side may be and still set the alignment column: wider, it takes
/// rows of its own.
const LONG_LHS: usize = 25;
/// How wide the formula of a claim's row may be (the verdict takes the rest of the line).
const CLAIM_ROW: usize = 30;

/// The characters of prose in a row of an aligned display: what a cut expression leaves out,
/// the limit that stopped a check.
const PROSE_ROW: usize = 50;

/// A rough width of LaTeX math as printed: characters that are not markup.
fn visual_width(s: &str) -> usize {
    let mut n = 0;
    let mut chars = s.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' => {
                // A control word prints as about one character.
                while chars.peek().is_some_and(|c| c.is_ascii_alphabetic()) {
                    chars.next();
                }
                n += 1;
            }
            '{' | '}' | '^' | '_' | ' ' => {}
            _ => n += 1,
        }
    }
    n
}

/// Splits a long LaTeX sum at the ` + ` and ` - ` outside braces into pieces about `max` wide;
/// every piece after the first starts with its sign. `\left( … \right)` becomes
/// `\bigl( … \bigr)`, which may span rows.
fn split_sum(s: &str, max: usize) -> Vec<String> {
    if visual_width(s) <= max {
        return vec![s.to_string()];
    }
    let s = &s
        .replace(r"\left(", r"\bigl(")
        .replace(r"\right)", r"\bigr)");
    pieces_at(s, &sum_cuts(s), max)
}

/// How wide a group in plain parentheses may be and still never break: a factor such as
/// `(x - y)^{3}` or `(p_{x} + p_{y})` reads as one thing.
const WHOLE_GROUP: usize = 16;

/// Where `s` may break: the spaces before ` + ` and ` - ` outside TeX's groups and outside
/// short groups in plain parentheses ([`WHOLE_GROUP`]); `\bigl( … \bigr)` may span rows.
fn sum_cuts(s: &str) -> Vec<usize> {
    // The byte ranges of the short plain groups.
    let mut open = Vec::new();
    let mut whole: Vec<(usize, usize)> = Vec::new();
    for (k, c) in s.char_indices() {
        let sized = s[..k].ends_with(r"\bigl") || s[..k].ends_with(r"\bigr");
        match c {
            '(' if !sized => open.push(k),
            ')' if !sized => {
                if let Some(o) = open.pop() {
                    if visual_width(&s[o..=k]) <= WHOLE_GROUP + 2 {
                        whole.push((o, k));
                    }
                }
            }
            _ => {}
        }
    }
    let mut cuts = Vec::new();
    let mut depth = 0i32;
    let mut escaped = false;
    for (k, c) in s.char_indices() {
        // `\{` and `\}` are a Poisson bracket's braces, printed, not TeX's groups: a sum
        // inside a bracket breaks as one outside it does.
        let after_backslash = escaped;
        escaped = c == '\\' && !escaped;
        match c {
            '{' | '}' if after_backslash => {}
            '{' => depth += 1,
            '}' => depth -= 1,
            ' ' if depth == 0
                && (s[k..].starts_with(" + ") || s[k..].starts_with(" - "))
                && !whole.iter().any(|&(o, e)| o < k && k < e) =>
            {
                cuts.push(k)
            }
            _ => {}
        }
    }
    cuts
}

/// `s` cut at some of `cuts` into pieces about `max` wide; every piece after the first starts
/// with its sign.
fn pieces_at(s: &str, cuts: &[usize], max: usize) -> Vec<String> {
    let mut pieces = Vec::new();
    let mut start = 0;
    let mut last: Option<usize> = None;
    for &k in cuts {
        if visual_width(&s[start..k]) > max {
            if let Some(l) = last.filter(|&l| l > start) {
                pieces.push(s[start..l].to_string());
                start = l + 1;
            }
        }
        last = Some(k);
    }
    if visual_width(&s[start..]) > max {
        if let Some(l) = last.filter(|&l| l > start) {
            pieces.push(s[start..l].to_string());
            start = l + 1;
        }
    }
    pieces.push(s[start..].to_string());
    pieces
}

/// `lhs &= rhs` rows for a long expression, continued on further rows.
fn long_rows(lhs: &str, rel: &str, e: &trigpoly::Expr, max: usize) -> Vec<String> {
    broken_rows(&format!("{lhs} &{rel} "), &e.render(Style::Latex), max)
}

/// `first` and the right side `rhs` broken at its sums' signs to `max` printed characters a
/// row: `first` before the first piece, `&\quad` before the others.
fn broken_rows(first: &str, rhs: &str, max: usize) -> Vec<String> {
    split_sum(rhs, max)
        .into_iter()
        .enumerate()
        .map(|(k, piece)| match k {
            0 => format!("{first}{piece}"),
            _ => format!(r"&\quad {piece}"),
        })
        .collect()
}

/// The alignment column of claims set in one `align*`: the widest of their left sides that
/// set it (one wider than [`LONG_LHS`] takes rows of its own).
fn claims_column<'a>(claims: impl IntoIterator<Item = &'a ClaimResult>, names: &Names) -> usize {
    claims
        .into_iter()
        .filter_map(|c| {
            let k = relation(&c.statement)?;
            let width = visual_width(&math_with(&c.statement[..k], names));
            (width <= LONG_LHS).then_some(width)
        })
        .max()
        .unwrap_or(0)
}

/// The rows of a claim, its right side broken to what the alignment `column` (the widest left
/// side of the claims set with it, [`claims_column`]) and its condition leave of the row.
fn claim_rows(c: &ClaimResult, names: &Names, column: usize) -> Vec<String> {
    let math = |s: &str| math_with(s, names);
    let mut cond = match &c.condition {
        Some(cond) => format!(r"\quad\text{{at }} {}", math(cond)),
        None => String::new(),
    };
    if let Some(l) = &c.on_level {
        cond.push_str(&format!(r"\quad\text{{on }} {}", math(&l.text)));
    }
    // A long statement breaks at its sums' signs, the verdict after its last line (moved
    // below it by amsmath when the line has no room). The condition follows the last piece
    // of the right side, which leaves it room (`{Y, Z} = … + 128 at ω = 1, α = 1, β = 1` of a
    // closure ran 63 pt past the margin).
    let after = visual_width(&cond);
    let mut rows: Vec<String> = match relation(&c.statement) {
        // A long left side takes rows of its own, right of the alignment column, and the
        // relation starts the next: as the column of the rows' `&`, it would push every other
        // row of the section, residuals included, past the margin.
        Some(k) if visual_width(&math(&c.statement[..k])) > LONG_LHS => {
            let room = (ROW - LONG_LHS).saturating_sub(after).max(ROW / 4);
            let mut rows = broken_rows("&", &math(&c.statement[..k]), ROW - LONG_LHS);
            rows.extend(broken_rows("&", &math(&c.statement[k..]), room));
            rows
        }
        Some(k) => {
            let lhs = math(&c.statement[..k]);
            // The right side takes what the alignment column and the condition leave of the
            // row: the column is the widest left side of the claims set together, and a short
            // left side beside a wide one (`8 P_{1,2}` under `{p_x p_y + M²a²xy, H}`) left its
            // right side 71 pt past the margin.
            let room = ROW
                .saturating_sub(visual_width(&lhs).max(column) + after)
                .max(ROW / 2);
            broken_rows(&format!("{lhs} &"), &math(&c.statement[k..]), room)
        }
        None => vec![aligned(&c.statement, names)],
    };
    let last = rows.last_mut().expect("a row");
    last.push_str(&format!(
        r"{cond} \tag*{{[{} {}]}}",
        text(&c.id),
        text(verdict(c))
    ));
    if let Some(r) = &c.residual {
        rows.extend(long_rows(r"\text{residual}", "=", r, CLAIM_ROW));
        if let Some(e) = &c.excerpt {
            rows.push(r"&\quad + \dots".into());
            rows.extend(excerpt_rows(e));
        }
        if let Some(f) = c.residual_restated(Style::Latex) {
            rows.extend(broken_rows(" &= ", &f, CLAIM_ROW));
        }
    }
    // On a level set: the quotient that proves it, or what the residual is.
    match c.on_level.as_ref().map(|l| (l, l.proof(Style::Latex))) {
        // One row where it fits right of the alignment column; else the quotient on a row of its own, and the difference on
        // one too where the product does not fit beside it (the Goryachev–Chaplygin cubic's
        // `{M3 (M1² + M2²) + c M1 γ3, H} = Q (…), Q = −c M2` of the heavy top ran 99 pt past
        // the margin).
        Some((l, Some((product, q)))) => {
            let difference = math(&l.difference);
            let equation = format!("{difference} = {product}");
            let quotient = format!(r"Q = {q}");
            // The rows start at the alignment column, the widest left side of the claims.
            let room = ROW.saturating_sub(column).max(ROW / 2);
            if visual_width(&equation) + visual_width(&quotient) <= room {
                rows.push(format!(r"&{equation}, \quad {quotient}"));
            } else {
                if visual_width(&equation) <= room {
                    rows.push(format!("&{equation},"));
                } else {
                    rows.push(format!("&{difference}"));
                    rows.push(format!(r"&\quad = {product},"));
                }
                rows.push(format!(r"&\quad {quotient}"));
            }
        }
        Some((l, None)) if c.residual.is_some() => rows.push(format!(
            r"&\quad\text{{(the remainder on division by }} P = {}\text{{: not a multiple of }} P\text{{)}}",
            l.polynomial.render(Style::Latex)
        )),
        _ => {}
    }
    if let (ClaimKind::Nonvanishing, Some(w)) = (c.kind, &c.witness) {
        // A term and the `+` before it are two columns wide at least (as the text's witness).
        let terms = w.printed_terms();
        if terms <= 3 * CLAIM_ROW / 2 && visual_width(&w.render(Style::Latex)) <= 3 * CLAIM_ROW {
            // A relation, as `=` is: spaced from what follows, and a leading minus a sign
            // (`\text{it equals}` ran into a parenthesis and set `-` as a binary minus).
            rows.extend(long_rows("", r"\mathrel{\text{it equals}}", w, CLAIM_ROW));
        } else {
            rows.push(format!(
                r"&\text{{it is a nonzero sum of {}}}",
                counted(terms, "term")
            ));
        }
    }
    // A note may name parameters and values, `proved for every A, B, at C = 2`: its formulas
    // are math, as a sentence's (they were upright text).
    if let Some(n) = &c.note {
        rows.push(format!(r"&\text{{{}}}", sentence(n)));
    }
    if let Some(u) = &c.undecided {
        rows.extend(prose_rows(&stopped(u)));
    }
    rows
}

/// What an expression cut to its leading part leaves out, in rows of prose that fit the page
/// (one row of it was set 259 pt wider than the page).
fn excerpt_rows(e: &Excerpt) -> Vec<String> {
    prose_rows(&format!("({})", e.describe()))
}

/// A sentence under a claim or table, in rows of prose that fit the page.
fn prose_rows(sentence: &str) -> Vec<String> {
    wrap(sentence, PROSE_ROW, "")
        .iter()
        .map(|line| format!(r"&\quad \text{{{}}}", text(line)))
        .collect()
}

fn entry(out: &mut Vec<String>, e: &Entry, names: &Names) {
    match e {
        Entry::Heading(h) => out.push(format!(r"\subsection*{{{}}}", markup_with(h, names))),
        Entry::Text(t) => {
            out.push(markup_with(t, names));
            out.push(String::new());
        }
        Entry::Warning(w) => {
            out.push(format!(
                r"\textbf{{Warning:}} {}",
                markup_with(&w.markup, names)
            ));
            out.push(String::new());
        }
        Entry::Equations(eq) => equations(out, eq, names),
        Entry::Claim(c) => {
            let mut rows = claim_rows(c, names, 0);
            flush(out, &mut rows);
        }
        Entry::Table(t) => table(out, t, names),
        Entry::Proof(p) => proof(out, p, names),
        Entry::Tower(t) => tower(out, t, names),
        Entry::Rank(r) => rank(out, r, names),
        Entry::Data(_) => {}
    }
}

fn equations(out: &mut Vec<String>, eq: &Equations, names: &Names) {
    if !eq.caption.is_empty() {
        out.push(format!(r"\noindent {}:", markup_with(&eq.caption, names)));
    }
    // The right sides start where the widest left side ends, and take what it leaves of the
    // row: each took the whole row, and `(1 + x + y)^2 (1/r^3 + x/s^3) = …` ran 55 pt past
    // the margin.
    let lhs: Vec<String> = eq.lines.iter().map(|l| labelled(&l.lhs, names)).collect();
    let room = rhs_room(lhs.iter().map(|l| visual_width(l)).max());
    let mut rows: Vec<String> = eq
        .lines
        .iter()
        .zip(&lhs)
        .flat_map(|(l, lhs)| {
            let mut rows = long_rows(lhs, "=", &l.rhs, room);
            if let Some(f) = l.restated(Style::Latex) {
                rows.extend(broken_rows(" &= ", &f, room));
            }
            rows
        })
        .collect();
    flush(out, &mut rows);
    if let Some(note) = eq.flow.as_ref().and_then(FlowKept::note) {
        out.push(format!(r"\noindent Note: {}", markup_with(note, names)));
        out.push(String::new());
    }
}

/// What a row of [`ROW`] leaves to a right side after a left side `lhs` wide (at least half
/// of it, where a left side is wide).
fn rhs_room(lhs: Option<usize>) -> usize {
    ROW.saturating_sub(lhs.unwrap_or(0)).max(ROW / 2)
}

/// An equation's left side, with a closing parenthetical that says what holds, a search's
/// `A3 (k = 1)`, set apart by a `\quad`: `A_{3} (k = 1)` read as `A_3` times `(k = 1)`.
fn labelled(lhs: &str, names: &Names) -> String {
    let label = lhs.strip_suffix(')').and_then(|head| {
        let mut depth = 0;
        for (k, c) in head.char_indices().rev() {
            match c {
                ')' => depth += 1,
                '(' if depth > 0 => depth -= 1,
                '(' => return Some(k),
                _ => {}
            }
        }
        None
    });
    match label {
        Some(k) if lhs[..k].ends_with(' ') && lhs[k..].contains(" = ") => format!(
            r"{}\quad {}",
            math_with(lhs[..k].trim_end(), names),
            math_with(&lhs[k..], names)
        ),
        _ => math_with(lhs, names),
    }
}

/// How wide a table may be, in the characters [`visual_width`] counts, before it is set as a
/// list of its brackets: about the width of the page.
const TABLE_ROW: usize = 70;

fn table(out: &mut Vec<String>, t: &TableResult, names: &Names) {
    table_body(out, t, names);
    let display = &t.table.display;
    for (a, b, message) in t.undecided() {
        out.push(format!(
            r"\noindent $\{{{}, {}\}} = ?$: {}\par",
            math_with(&display[a], names),
            math_with(&display[b], names),
            text(&stopped(message))
        ));
    }
}

/// The table as an array, or as a list when it is too wide for the page.
fn table_body(out: &mut Vec<String>, t: &TableResult, names: &Names) {
    let table = &t.table;
    let cells = t.cells(Style::Latex);
    let head: Vec<String> = table.display.iter().map(|d| math_with(d, names)).collect();
    let column = |k: usize| {
        let widest = cells.iter().map(|row| visual_width(&row[k])).max();
        widest.unwrap_or(0).max(visual_width(&head[k])) + 2
    };
    let width: usize = (0..head.len()).map(column).sum::<usize>() + 5;
    if width > TABLE_ROW {
        return table_as_list(out, t, &head, &cells);
    }
    out.push(r"\begin{center}".into());
    out.push(format!(r"{}\\[1ex]", markup_with(&t.caption, names)));
    out.push(r"$\begin{array}{c|".to_string() + &"c".repeat(table.display.len()) + "}");
    out.push(format!(r"\{{\cdot,\cdot\}} & {} \\", head.join(" & ")));
    out.push(r"\hline".into());
    for (name, row) in head.iter().zip(&cells) {
        out.push(format!(r"{name} & {} \\", row.join(" & ")));
    }
    out.push(r"\end{array}$".into());
    out.push(r"\end{center}".into());
}

/// A table too wide for the page, as the list of its brackets above the diagonal that are not
/// zero (the others follow by antisymmetry), each broken over lines as a long equation is.
fn table_as_list(out: &mut Vec<String>, t: &TableResult, head: &[String], cells: &[Vec<String>]) {
    let brackets = table_list(cells);
    let caption = markup(&t.list_caption());
    if brackets.is_empty() {
        // As the text says it; `\[1ex]` here opened a display that nothing closed.
        out.push(format!(r"\noindent {caption}: every bracket is zero."));
        out.push(String::new());
        return;
    }
    let [a, b] = &t.placeholders;
    out.push(format!(
        r"\noindent {caption}, the brackets that are not zero, ${}$ before ${}$:",
        math(a),
        math(b)
    ));
    // As an equation's, each right side takes what the widest bracket leaves of the row.
    let bracket = |a: usize, b: usize| format!(r"\{{{}, {}\}}", head[a], head[b]);
    let widest = brackets
        .iter()
        .map(|&(a, b, _)| visual_width(&bracket(a, b)));
    let room = rhs_room(widest.max());
    let mut rows = Vec::new();
    for (a, b, cell) in brackets {
        rows.extend(broken_rows(&format!("{} &= ", bracket(a, b)), cell, room));
        if let Some(e) = t.excerpts.get(&(a, b)) {
            rows.extend(excerpt_rows(e));
        }
    }
    flush(out, &mut rows);
}

fn tower(out: &mut Vec<String>, t: &TowerResult, names: &Names) {
    let mut rows = claim_rows(&t.claim, names, 0);
    flush(out, &mut rows);
    out.push(format!(
        r"\noindent {} expanded for {} (ladder ${}$), {}.",
        counted(t.checked, "bracket"),
        text(&t.the_system),
        math(&t.ladder),
        text(&t.verdict())
    ));
    out.push(String::new());
}

fn proof(out: &mut Vec<String>, p: &ProofResult, names: &Names) {
    // Two spaces set a formula's parenthetical apart, `e^{−iθ}  (Ω = p_θ/I)`: a `\quad`, where
    // one space read as a product, `e^{-i\theta} (\Omega = p_{\theta}/I)`.
    let math = |s: &str| {
        let parts: Vec<String> = s.split("  ").map(|part| math_with(part, names)).collect();
        parts.join(r"\quad ")
    };
    out.push(format!(r"\paragraph{{Proof}} {}:", sentence(&p.title)));
    out.push(r"\begin{enumerate}".into());
    let mark = |ok: bool| if ok { "holds" } else { "FAILS" };
    for f in &p.facts {
        let so = match &f.found_statement {
            Some(st) => format!(", so ${}$", math(st)),
            None => String::new(),
        };
        let found = match &f.found {
            Some(e) => format!(": the bracket is ${}${so}", e.render(Style::Latex)),
            None => String::new(),
        };
        // A formula, and after a colon the prose that says why (the eigenvalue's linearity),
        // set as a sentence so that it breaks between words.
        let statement = match f.statement.split_once(": ") {
            Some((formula, why)) => format!("${}$: {}", math(formula), sentence(why)),
            None => format!("${}$", math(&f.statement)),
        };
        out.push(format!(
            r"\item computed: {statement} --- {}{found}",
            mark(f.holds)
        ));
    }
    out.push(format!(
        r"\item computed: the derivation property ${}$ on the base functions --- {}",
        math(&p.derivation()),
        mark(p.leibniz_check)
    ));
    out.push(r"\end{enumerate}".into());
    out.push(format!(r"\emph{{Lemma:}} {}.", sentence(&p.lemma)));
    out.push(String::new());
    // Flush left, as the lemma is, which follows the list: it was indented under it.
    let (label, closing) = p.closing();
    out.push(format!(
        r"\noindent\emph{{{label}:}} {}.",
        sentence(&closing)
    ));
    let column = claims_column(&p.claims, names);
    let mut rows: Vec<String> = p
        .claims
        .iter()
        .flat_map(|c| claim_rows(c, names, column))
        .collect();
    flush(out, &mut rows);
}

fn rank(out: &mut Vec<String>, r: &RankResult, names: &Names) {
    let mut rows = claim_rows(&r.claim, names, 0);
    flush(out, &mut rows);
    let c = &r.certificate;
    let fns: Vec<String> = r
        .minor_functions()
        .iter()
        .map(|f| format!("${}$", math_with(f, names)))
        .collect();
    let cols: Vec<String> = r
        .minor_coordinates()
        .iter()
        .map(|v| format!("${}$", v.latex()))
        .collect();
    out.push(r"\begin{itemize}".into());
    let at: Vec<String> = point(r, Style::Latex)
        .iter()
        .map(|p| format!("${p}$"))
        .collect();
    // Rank 0: every function has a zero gradient, and there is no minor to show.
    if c.rank > 0 {
        out.push(format!(
            r"\item $\ge {}$: the minor with rows {} and columns {} is ${} \neq 0$ at {}",
            c.rank,
            fns.join(", "),
            cols.join(", "),
            trigpoly::render_number(&c.minor_value, Style::Latex),
            at.join(", ")
        ));
    }
    out.push(format!(
        r"\item $\le {}$: {}",
        c.rank,
        markup(&upper_bound(r))
    ));
    out.push(r"\end{itemize}".into());
}
