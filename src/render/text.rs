//! Unicode text that reads like the paper: `{L, G1} = −G2   [C09 proved]`.

use brackets::UpperBound;
use rayon::prelude::*;
use std::borrow::Cow;
use trigpoly::{GaussianRational, Style, VarKind};

use super::{
    condition_suffix, level_set_suffix, pad, plain, stopped, table_list, verdict, wider_than,
    width, Options,
};
use crate::report::{
    counted, ClaimKind, ClaimResult, Entry, Equation, Equations, FlowKept, ProofResult, RankResult,
    Report, TableResult, TowerResult,
};

/// The column where claim verdicts start.
const VERDICT_COLUMN: usize = 66;
/// Prose is wrapped at this width.
const WRAP: usize = 96;

/// Renders a report as text.
pub fn render(report: &Report, options: &Options) -> String {
    let mut out = Vec::<String>::new();
    out.extend(wrap(&plain(&report.title), WRAP, ""));
    if !report.subtitle.is_empty() {
        out.extend(wrap(&report.subtitle, WRAP, ""));
    }
    for s in &report.sections {
        out.push(String::new());
        let heading = format!("{}  {}", s.number, plain(&s.title));
        out.push(heading.clone());
        out.push("═".repeat(width(&heading)));
        // Entries are blocks separated by a blank line, except that consecutive claims form
        // one block and a heading sits right on its block.
        let mut previous: Option<&Entry> = None;
        for e in s.shown_entries() {
            let joined = matches!(
                (previous, e),
                (Some(Entry::Claim(_)), Entry::Claim(_))
                    | (Some(Entry::Warning(_)), Entry::Warning(_))
                    | (Some(Entry::Heading(_)), _)
            );
            if previous.is_some() && !joined {
                out.push(String::new());
            }
            entry(&mut out, e);
            previous = Some(e);
        }
    }
    let summary = report.summary_line(options.timings);
    super::lines_to_text(&out, &["", &summary])
}

fn entry(out: &mut Vec<String>, e: &Entry) {
    match e {
        Entry::Heading(h) => {
            let h = plain(h);
            out.push("─".repeat(width(&h)));
            out.insert(out.len() - 1, h);
        }
        Entry::Text(t) => out.extend(prose(t)),
        Entry::Warning(w) => out.extend(prose(&format!("Warning: {}", w.markup))),
        Entry::Equations(eq) => equations(out, eq),
        Entry::Claim(c) => claim(out, c),
        Entry::Table(t) => table(out, t),
        Entry::Proof(p) => proof(out, p),
        Entry::Tower(t) => tower(out, t),
        Entry::Rank(r) => rank(out, r),
        Entry::Data(_) => {}
    }
}

/// Prose with formulas between backticks, wrapped at its spaces but those inside a formula's
/// parentheses or braces: `Re(Z_y e^{−iθ})` and `{L_x, A_xy}` stay on one line.
fn prose(markup: &str) -> Vec<String> {
    // Such a space is a no-break space while the text is wrapped.
    const KEPT: char = '\u{a0}';
    let (mut in_formula, mut depth) = (false, 0usize);
    let kept: String = markup
        .chars()
        .filter_map(|c| {
            match c {
                '`' => {
                    in_formula = !in_formula;
                    depth = 0;
                    return None;
                }
                '(' | '{' | '[' if in_formula => depth += 1,
                ')' | '}' | ']' if in_formula => depth = depth.saturating_sub(1),
                ' ' if in_formula && depth > 0 => return Some(KEPT),
                _ => {}
            }
            Some(c)
        })
        .collect();
    wrap_prose(&kept, WRAP, "")
        .into_iter()
        .map(|line| line.replace(KEPT, " "))
        .collect()
}

/// The words of `s` to wrap, a value kept with what it is the value of where the two fit on
/// a line of `room` columns: `I3 = 300007/300017` and `4 × 4` (a word `=` or `×` with the
/// words around it, `≤` or `≥` with the next) and `≤ 2: 3` (a bound's colon with its count).
fn wrapped_words(s: &str, room: usize) -> Vec<Cow<'_, str>> {
    let mut units: Vec<Cow<'_, str>> = Vec::new();
    let mut glue_next = false;
    for word in s.split(' ').filter(|w| !w.is_empty()) {
        let glue = glue_next || matches!(word, "=" | "×");
        glue_next = matches!(word, "=" | "≤" | "≥" | "×");
        match units.last_mut() {
            Some(last) if glue && width(last) + 1 + width(word) <= room => {
                glue_next |= word.ends_with(':') && last.starts_with(['≤', '≥']);
                let unit = last.to_mut();
                unit.push(' ');
                unit.push_str(word);
            }
            _ => units.push(Cow::Borrowed(word)),
        }
    }
    units
}

/// Greedy word wrap at spaces, keeping the leading indentation; continuation lines start
/// with `indent`.
pub(crate) fn wrap(s: &str, w: usize, indent: &str) -> Vec<String> {
    let words = s.split(' ').filter(|w| !w.is_empty()).map(Cow::Borrowed);
    wrap_words(s, words, w, indent)
}

/// [`wrap`] for sentences: a value stays with its name where the two fit on a line
/// ([`wrapped_words`]).
fn wrap_prose(s: &str, w: usize, indent: &str) -> Vec<String> {
    let room = w.saturating_sub(width(s) - width(s.trim_start_matches(' ')));
    let words = wrapped_words(s, room.min(w.saturating_sub(width(indent))));
    wrap_words(s, words.into_iter(), w, indent)
}

/// [`wrap`] of the words of `s`, given.
fn wrap_words<'a>(
    s: &str,
    words: impl Iterator<Item = Cow<'a, str>>,
    w: usize,
    indent: &str,
) -> Vec<String> {
    let lead = &s[..s.len() - s.trim_start_matches(' ').len()];
    let mut lines = Vec::new();
    let mut line = lead.to_string();
    // The line's width, counted as it grows (a long expression has millions of words).
    let mut line_width = width(lead);
    let mut empty = true;
    // Whether the line holds only a sign, which stays with the term after it (`+ 1000…0x`, a
    // term wider than a line, was a `+` on a line of its own).
    let mut sign_only = false;
    for word in words {
        let word = &*word;
        let word_width = width(word);
        if !empty && !sign_only && line_width + 1 + word_width > w {
            lines.push(std::mem::take(&mut line));
            line.push_str(indent);
            line_width = width(indent);
            empty = true;
        }
        let sign = empty && matches!(word, "+" | "−" | "-");
        if !empty {
            line.push(' ');
            line_width += 1;
        }
        line.push_str(word);
        line_width += word_width;
        empty = false;
        sign_only = sign;
    }
    if !empty {
        lines.push(line);
    }
    lines
}

/// A line of mathematics wrapped like [`wrap`], but between the terms of a sum where it can
/// (before ` + ` and ` − ` outside parentheses): a monomial such as `x² p_y⁴` stays on one line.
/// A piece wider than a line breaks between the terms of the sums inside its parentheses (a
/// fraction's numerator, `(2g p_y² − …)/((x − y)³ …)`), and a term wider than a line at its
/// spaces.
pub(crate) fn wrap_sum(s: &str, w: usize, indent: &str) -> Vec<String> {
    let mut lines = SumLines {
        lines: Vec::new(),
        line: String::new(),
        line_width: 0,
        w,
        indent,
        indent_width: width(indent),
    };
    // A piece is split when it would not fit a line after the indent. The pieces go onto the
    // lines as they are found (a result of 10⁶ terms is as many pieces; they were all listed
    // first, and the lines listed twice).
    let whole = Piece { text: s, depth: 0 };
    sum_pieces(whole, 0, w.saturating_sub(lines.indent_width), &mut lines);
    lines.finish()
}

/// The lines of [`wrap_sum`] as its pieces are laid on them, each line's width counted as it
/// grows.
struct SumLines<'i> {
    /// The lines done.
    lines: Vec<String>,
    /// The line being filled.
    line: String,
    /// Its width.
    line_width: usize,
    /// The width of a line.
    w: usize,
    /// The indent of each line after the first.
    indent: &'i str,
    /// The indent's width.
    indent_width: usize,
}

impl SumLines<'_> {
    /// Lays `piece` (of width `piece_width`) after the line's pieces, or on the next line where
    /// it does not fit.
    fn push(&mut self, piece: &str, piece_width: usize) {
        if self.line.is_empty() {
            self.line.push_str(piece);
            self.line_width = piece_width;
        } else if self.line_width + 1 + piece_width <= self.w {
            self.line.push(' ');
            self.line.push_str(piece);
            self.line_width += 1 + piece_width;
        } else {
            let next = format!("{}{piece}", self.indent);
            let done = std::mem::replace(&mut self.line, next);
            self.close(done, self.line_width);
            self.line_width = self.indent_width + piece_width;
        }
    }

    /// Adds a line of width `line_width` to those done: a line wider than a line of text (a
    /// term wider than it) is wrapped at its spaces.
    fn close(&mut self, line: String, line_width: usize) {
        match line_width <= self.w {
            true => self.lines.push(line),
            false => self.lines.extend(wrap(&line, self.w, self.indent)),
        }
    }

    /// The lines, the last one closed.
    fn finish(mut self) -> Vec<String> {
        let last = std::mem::take(&mut self.line);
        self.close(last, self.line_width);
        self.lines
    }
}

/// How wide a group in parentheses, its parentheses included, may be and still never break.
const WHOLE_GROUP: usize = 18;

/// A part of a line of mathematics, and the depth of brackets at its start in the line.
#[derive(Clone, Copy)]
struct Piece<'a> {
    text: &'a str,
    depth: i32,
}

/// The pieces of `piece` between the signs of its sums at bracket depth `level` in the line
/// (each piece after the first starts with its sign), laid onto the lines `out` as each is
/// found ([`place`]); a piece wider than `w` is split again one level deeper, down to the
/// third. One pass over the text's bytes a level (its brackets and signs are ASCII or `−`,
/// whose bytes are part of no other character); a short group in parentheses
/// ([`short_group_end`]) is read ahead from its `(`, no further than a short group's width.
/// Marking every byte inside a short group first (two more passes, and five bytes of marks a
/// byte of text) and measuring every group whole took a fifth of the time of printing a
/// result of 24 MB.
fn sum_pieces(piece: Piece<'_>, level: i32, w: usize, out: &mut SumLines<'_>) {
    const MINUS: &[u8] = "−".as_bytes();
    let s = piece.text;
    let bytes = s.as_bytes();
    let (mut depth, mut start, mut start_depth) = (piece.depth, 0, piece.depth);
    // Where the short group the scan is in closes (the byte of its `)`); a short group, a
    // factor such as `(x − y)⁴`, never breaks.
    let mut short_until = 0;
    for (k, &b) in bytes.iter().enumerate() {
        match b {
            b'(' | b'{' | b'[' => {
                depth += 1;
                if b == b'(' && k >= short_until {
                    if let Some(end) = short_group_end(&s[k..]) {
                        short_until = k + end;
                    }
                }
            }
            b')' | b'}' | b']' => depth -= 1,
            b'+' | 0xE2 if depth == level && k >= short_until && k > start => {
                let sign = match b {
                    b'+' => 1,
                    _ if bytes[k..].starts_with(MINUS) => MINUS.len(),
                    _ => continue,
                };
                if bytes[k - 1] == b' ' && bytes.get(k + sign) == Some(&b' ') {
                    // The piece ends before the space ahead of the sign.
                    let done = Piece {
                        text: &s[start..k - 1],
                        depth: start_depth,
                    };
                    place(done, level, w, out);
                    (start, start_depth) = (k, depth);
                }
            }
            _ => {}
        }
    }
    let last = Piece {
        text: &s[start..],
        depth: start_depth,
    };
    place(last, level, w, out);
}

/// Lays a piece of a sum at bracket depth `level` onto the lines, split again one level deeper
/// ([`sum_pieces`]) where it is wider than `w`, down to the third.
fn place(piece: Piece<'_>, level: i32, w: usize, out: &mut SumLines<'_>) {
    match level < 2 && wider_than(piece.text, w) {
        true => sum_pieces(piece, level + 1, w, out),
        false => out.push(piece.text, width(piece.text)),
    }
}

/// Where the group in parentheses that `t` starts with closes (the byte of its `)`), if it is
/// short: at most [`WHOLE_GROUP`] wide, its parentheses included. Read no further than that.
fn short_group_end(t: &str) -> Option<usize> {
    let (mut open, mut group_width) = (0, 0);
    for (k, c) in t.char_indices() {
        group_width += usize::from(!super::tex::is_combining(c));
        if group_width > WHOLE_GROUP {
            return None;
        }
        match c {
            '(' => open += 1,
            ')' => {
                open -= 1;
                if open == 0 {
                    return Some(k);
                }
            }
            _ => {}
        }
    }
    None
}

/// Items joined by `, `, wrapped between items only.
fn wrap_items(indent: &str, items: &[String], w: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = indent.to_string();
    for (k, item) in items.iter().enumerate() {
        let piece = if k + 1 < items.len() {
            format!("{item},")
        } else {
            item.clone()
        };
        if line.len() > indent.len() && width(&line) + 1 + width(&piece) > w {
            lines.push(std::mem::take(&mut line));
            line.push_str(indent);
        } else if line.len() > indent.len() {
            line.push(' ');
        }
        line.push_str(&piece);
    }
    lines.push(line);
    lines
}

/// The widest left side of a list of equations after which a right side too long for its line
/// wraps; past it (a long expression given to `expand`) each side of such an equation takes
/// lines of its own.
const ALIGNED_LEFT_SIDE: usize = 40;

/// The terms from which a list of equations is printed on the pool's threads.
const PARALLEL_TERMS: usize = 10_000;

fn equations(out: &mut Vec<String>, eq: &Equations) {
    if !eq.caption.is_empty() {
        out.extend(prose(&format!("{}:", eq.caption)));
    }
    let lw = eq.lines.iter().map(|l| width(&l.lhs)).max().unwrap_or(0);
    let indent = " ".repeat(4 + lw + 3);
    let print = |l: &Equation| {
        let line = format!("    {} = {}", pad(&l.lhs, lw), l.rhs);
        // Where the right side's `=` stands, for the same value in named functions below it.
        let (mut lines, equals) = if width(&line) <= WRAP {
            (vec![line], 4 + lw + 1)
        } else if lw > ALIGNED_LEFT_SIDE {
            // Too wide to wrap the right side after: each side on lines of its own.
            let mut lines = wrap_sum(&format!("    {}", l.lhs), WRAP, "      ");
            lines.extend(wrap_sum(&format!("      = {}", l.rhs), WRAP, "        "));
            (lines, 6)
        } else {
            (wrap_sum(&line, WRAP, &indent), 4 + lw + 1)
        };
        if let Some(f) = l.restated(Style::Unicode) {
            let at = " ".repeat(equals);
            lines.extend(wrap_sum(&format!("{at}= {f}"), WRAP, &format!("{at}  ")));
        }
        lines
    };
    // A long list (a search's thousands of integrals) is printed on the pool's threads; a
    // short one where it is, without starting them.
    let terms: usize = eq.lines.iter().map(|l| l.rhs.len()).sum();
    let lines: Vec<Vec<String>> = if terms >= PARALLEL_TERMS {
        eq.lines.par_iter().map(print).collect()
    } else {
        eq.lines.iter().map(print).collect()
    };
    // Reserved at once: a result printed whole is millions of lines, and the list grown line by
    // line was copied at each doubling.
    out.reserve(lines.iter().map(Vec::len).sum());
    out.extend(lines.into_iter().flatten());
    if let Some(note) = eq.flow.as_ref().and_then(FlowKept::note) {
        out.extend(prose(&format!("Note: {note}")));
    }
}

/// `  statement at condition ........ [C09 proved]`, and what was found when it failed.
fn verdict_line(out: &mut Vec<String>, c: &ClaimResult) {
    let head = format!(
        "  {}{}{}",
        c.statement,
        condition_suffix(&c.condition),
        level_set_suffix(c)
    );
    let tag = format!("[{} {}]", c.id, verdict(c));
    if width(&head) + 2 <= VERDICT_COLUMN {
        out.push(format!("{}{tag}", pad(&head, VERDICT_COLUMN)));
    } else if width(&head) + 2 + width(&tag) <= WRAP {
        out.push(format!("{head}  {tag}"));
    } else {
        // A long statement wraps between its terms, the verdict after its last line.
        let mut lines = wrap_sum(&head, WRAP, "      ");
        let last = lines.pop().expect("at least one line");
        if width(&last) + 2 + width(&tag) <= WRAP {
            lines.push(format!("{last}  {tag}"));
        } else {
            lines.extend([last, format!("      {tag}")]);
        }
        out.extend(lines);
    }
    if let Some(r) = &c.residual {
        let more = if c.excerpt.is_some() { " + …" } else { "" };
        // On a level set the residual is lhs − rhs's remainder on division by P: congruent to
        // it modulo P, not equal.
        let (relation, modulo) = match c.on_level {
            Some(_) => ("≡", " (mod P)"),
            None => ("=", ""),
        };
        out.extend(wrap_sum(
            &format!("      residual lhs − rhs {relation} {r}{more}{modulo}"),
            WRAP,
            "        ",
        ));
        if let Some(e) = &c.excerpt {
            out.extend(wrap(&format!("      ({})", e.describe()), WRAP, "       "));
        }
        if let Some(f) = c.residual_restated(Style::Unicode) {
            // Under the residual's `=`, as a derivation continues.
            let indent = " ".repeat(width("      residual lhs − rhs "));
            out.extend(wrap_sum(
                &format!("{indent}= {f}"),
                WRAP,
                &format!("{indent}  "),
            ));
        }
    }
    if let Some(n) = &c.note {
        out.extend(wrap_prose(&format!("      {n}"), WRAP, "        "));
    }
    if let Some(u) = &c.undecided {
        out.extend(wrap(&format!("      {}", stopped(u)), WRAP, "        "));
    }
}

fn claim(out: &mut Vec<String>, c: &ClaimResult) {
    verdict_line(out, c);
    // On a level set: the quotient that proves it, or what the residual is.
    if let Some(l) = &c.on_level {
        match l.proof(Style::Unicode) {
            Some((product, q)) => out.extend(wrap_sum(
                &format!("      {} = {product} with Q = {q}", l.difference),
                WRAP,
                "        ",
            )),
            // Prose after the polynomial, where a long line breaks.
            None if c.residual.is_some() => out.extend(wrap(
                &format!(
                    "      P = {} does not divide lhs − rhs: the residual is its remainder on \
                     division by P",
                    l.polynomial
                ),
                WRAP,
                "        ",
            )),
            None => {}
        }
    }
    if let (ClaimKind::Nonvanishing, Some(w)) = (c.kind, &c.witness) {
        // A term and the ` + ` before it take four columns at least: a witness of more terms
        // than that allows is not rendered to be measured.
        let terms = w.printed_terms();
        let line = (terms <= 3 * WRAP / 4).then(|| format!("      it equals {w}"));
        if let Some(line) = line.filter(|line| width(line) <= 3 * WRAP) {
            out.extend(wrap(&line, WRAP, "        "));
        } else {
            out.push(format!(
                "      it is a nonzero sum of {}",
                counted(terms, "term")
            ));
        }
    }
}

fn table(out: &mut Vec<String>, t: &TableResult) {
    table_body(out, t);
    // Why an entry is `?`.
    let names = &t.table.display;
    for (a, b, message) in t.undecided() {
        let note = format!(
            "    {{{}, {}}} = ?: {}",
            names[a],
            names[b],
            stopped(message)
        );
        out.extend(wrap(&note, WRAP, "      "));
    }
}

/// The table as a grid, or as a list when it is too wide.
fn table_body(out: &mut Vec<String>, t: &TableResult) {
    let table = &t.table;
    let corner = "{·,·}".to_string();
    let cells = t.cells(Style::Unicode);
    let first = table
        .display
        .iter()
        .map(|d| width(d))
        .chain([width(&corner)])
        .max()
        .unwrap_or(0);
    let widths: Vec<usize> = (0..table.display.len())
        .map(|j| {
            cells
                .iter()
                .map(|row| width(&row[j]))
                .chain([width(&table.display[j])])
                .max()
                .unwrap_or(0)
        })
        .collect();
    let total = 4 + first + 3 + widths.iter().sum::<usize>() + 3 * widths.len().saturating_sub(1);
    if total > WRAP {
        return table_as_list(out, t, &cells);
    }
    out.extend(prose(&t.caption));
    let row = |head: &str, items: &[String]| {
        let body: Vec<String> = items.iter().zip(&widths).map(|(c, &w)| pad(c, w)).collect();
        format!("    {} │ {}", pad(head, first), body.join("   "))
            .trim_end()
            .to_string()
    };
    out.push(row(&corner, &table.display));
    let rule: usize = widths.iter().sum::<usize>() + 3 * widths.len().saturating_sub(1) + 1;
    out.push(format!(
        "    {}┼{}",
        "─".repeat(first + 1),
        "─".repeat(rule)
    ));
    for (name, items) in table.display.iter().zip(&cells) {
        out.push(row(name, items));
    }
}

/// A table wider than a line, as the list of its brackets above the diagonal that are not
/// zero (the others follow by antisymmetry), each wrapped (a closure's bracket of two cubic
/// integrals made rows of a thousand characters).
fn table_as_list(out: &mut Vec<String>, t: &TableResult, cells: &[Vec<String>]) {
    let names = &t.table.display;
    let brackets = table_list(cells);
    let caption = plain(&t.list_caption());
    let [a, b] = &t.placeholders;
    let rows: Vec<Vec<String>> = brackets
        .into_iter()
        .map(|(a, b, cell)| {
            let row = format!("    {{{}, {}}} = {cell}", names[a], names[b]);
            let mut lines = wrap_sum(&row, WRAP, "        ");
            if let Some(e) = t.excerpts.get(&(a, b)) {
                lines.extend(wrap(
                    &format!("        ({})", e.describe()),
                    WRAP,
                    "         ",
                ));
            }
            lines
        })
        .collect();
    match rows.is_empty() {
        true => out.push(format!("{caption}: every bracket is zero.")),
        false => {
            out.extend(wrap(
                &format!(
                    "{caption}, too wide for a table: the brackets that are not zero, {a} before \
                     {b}:"
                ),
                WRAP,
                "",
            ));
            out.extend(rows.into_iter().flatten());
        }
    }
}

fn tower(out: &mut Vec<String>, t: &TowerResult) {
    verdict_line(out, &t.claim);
    out.push(format!(
        "      {} expanded for {} (ladder {}), {}",
        counted(t.checked, "bracket"),
        t.the_system,
        t.ladder,
        t.verdict()
    ));
}

fn proof(out: &mut Vec<String>, p: &ProofResult) {
    out.push(format!("  Proof {}:", p.title));
    let mark = |ok: bool| if ok { "holds" } else { "FAILS" };
    let lines: Vec<(String, bool)> = p
        .facts
        .iter()
        .map(|f| (f.statement.clone(), f.holds))
        .chain([(
            format!(
                "the derivation property {} on the base functions",
                p.derivation()
            ),
            p.leibniz_check,
        )])
        .collect();
    for (k, (st, ok)) in lines.iter().enumerate() {
        let head = format!("    {}. computed: {st}", k + 1);
        let one_line = format!("{head}  {}", mark(*ok));
        if width(&head) + 2 <= VERDICT_COLUMN {
            out.push(format!("{}{}", pad(&head, VERDICT_COLUMN), mark(*ok)));
        } else if width(&one_line) <= WRAP + 4 {
            out.push(one_line);
        } else {
            // A long fact wraps, its mark after its last line.
            out.extend(wrap(&format!("{head}: {}", mark(*ok)), WRAP, "       "));
        }
        if let Some(fact) = p.facts.get(k) {
            if let Some(found) = &fact.found {
                let so = match &fact.found_statement {
                    Some(st) => format!(", so {st}"),
                    None => String::new(),
                };
                out.extend(wrap(
                    &format!("       the bracket is {found}{so}"),
                    WRAP,
                    "       ",
                ));
            }
        }
    }
    out.extend(wrap(&format!("    Lemma: {}.", p.lemma), WRAP, "      "));
    let (label, closing) = p.closing();
    out.extend(wrap(&format!("    {label}: {closing}."), WRAP, "      "));
    for c in &p.claims {
        verdict_line(out, c);
    }
}

/// `x = 2`, `cos θ = 3/5, sin θ = 4/5`: the point of a rank certificate, in a style.
pub(crate) fn point(r: &RankResult, style: Style) -> Vec<String> {
    let name = |v| {
        let var = r.vars.variable(v);
        match style {
            Style::Unicode => var.unicode().to_string(),
            Style::Latex => var.latex().to_string(),
            Style::Ascii => var.name().to_string(),
        }
    };
    r.certificate
        .point
        .iter()
        .map(|(v, value)| {
            if r.vars.variable(*v).kind() == VarKind::Angle {
                let [c, s] = [&value.re, &value.im]
                    .map(|q| trigpoly::render_number(&GaussianRational::from(q.clone()), style));
                // `\cos\theta`, as the expression printer writes it; `\cos a`.
                let name = name(*v);
                let gap = match name.starts_with(|c: char| c.is_ascii_alphanumeric()) {
                    true => " ",
                    false => "",
                };
                match style {
                    Style::Latex => format!(r"\cos{gap}{name} = {c}, \sin{gap}{name} = {s}"),
                    Style::Ascii => format!("cos({name}) = {c}, sin({name}) = {s}"),
                    Style::Unicode => format!("cos {name} = {c}, sin {name} = {s}"),
                }
            } else {
                format!("{} = {}", name(*v), trigpoly::render_number(value, style))
            }
        })
        .collect()
}

/// `there is 1 function`, `there are 2 functions`.
fn there_are(n: usize, noun: &str) -> String {
    let verb = if n == 1 { "is" } else { "are" };
    format!("there {verb} {}", counted(n, noun))
}

/// Why the rank is at most the certified one, in words, the size of a minor between backticks
/// (a formula: `$4 \times 4$` in LaTeX, which set `4 $\times$ 4`).
pub(crate) fn upper_bound(r: &RankResult) -> String {
    let k = r.certificate.rank;
    match &r.certificate.upper {
        UpperBound::Size if r.functions.len() <= r.coordinates().len() => {
            there_are(r.functions.len(), "function")
        }
        UpperBound::Size => there_are(r.coordinates().len(), "coordinate"),
        // With no minor above, the bordering minors are every entry of the Jacobian.
        UpperBound::VanishingMinors { count } if k == 0 => format!(
            "every `1 × 1` minor ({}) vanishes identically",
            counted(*count, "minor")
        ),
        // Kronecker's bordered-minor theorem: the minors one larger that contain the nonzero
        // one all vanish, so every minor one larger does.
        UpperBound::VanishingMinors { count: 1 } => format!(
            "every `{0} × {0}` minor vanishes identically, as the one bordering the minor above does",
            k + 1
        ),
        UpperBound::VanishingMinors { count } => format!(
            "every `{0} × {0}` minor vanishes identically, as the {1} bordering the minor above do",
            k + 1,
            count
        ),
        // A kind of bound added to the engine after these words: its own clause.
        other => other.to_string(),
    }
}

fn rank(out: &mut Vec<String>, r: &RankResult) {
    verdict_line(out, &r.claim);
    let c = &r.certificate;
    let rows = r.minor_functions();
    let cols: Vec<&str> = r.minor_coordinates().iter().map(|v| v.unicode()).collect();
    if c.rank == 0 {
        // Every function has a zero gradient: no minor to show.
        out.push(format!("      ≤ 0: {}", plain(&upper_bound(r))));
        return;
    }
    let indent = "        ";
    let mut lines = wrap(
        &format!(
            "      ≥ {}: the minor ∂({})/∂({}) = {}",
            c.rank,
            rows.join(", "),
            cols.join(", "),
            trigpoly::render_number(&c.minor_value, Style::Unicode),
        ),
        WRAP,
        indent,
    );
    // `≠ 0` is one word: a long minor split it, leaving a line that began `0 at`.
    let last = lines.last_mut().expect("a line");
    if width(last) + width(" ≠ 0") <= WRAP {
        last.push_str(" ≠ 0");
    } else {
        lines.push(format!("{indent}≠ 0"));
    }
    // `at` ends the minor's last line, or else starts the point's: a long minor left it on a
    // line of its own.
    let mut at = point(r, Style::Unicode);
    let last = lines.last_mut().expect("a line");
    if width(last) + width(" at") <= WRAP || at.is_empty() {
        last.push_str(" at");
    } else {
        at[0] = format!("at {}", at[0]);
    }
    out.extend(lines);
    out.extend(wrap_items(indent, &at, WRAP));
    out.extend(wrap(
        &format!("      ≤ {}: {}", c.rank, plain(&upper_bound(r))),
        WRAP,
        "        ",
    ));
}

#[cfg(test)]
mod tests {
    use super::*;
    use trigpoly::Rational;

    /// A claim and a residual longer than a line wrap between their terms, the verdict after
    /// the claim's last line (both ran on as one line of a thousand characters).
    #[test]
    fn a_long_claim_and_its_residual_wrap() {
        let vars = trigpoly::Vars::builder()
            .coordinate("x")
            .momentum("p")
            .build()
            .unwrap();
        let sum = (1..=40)
            .map(|k| format!("{k}*x^{k}*p"))
            .collect::<Vec<_>>()
            .join(" + ");
        let residual = trigpoly::Expr::parse(&vars, &sum).unwrap();
        let mut c = ClaimResult::derived(
            "long",
            &format!("{} = 0", residual.render(Style::Unicode)),
            false,
            None,
        );
        c.residual = Some(residual.clone());
        let mut out = Vec::new();
        verdict_line(&mut out, &c);
        assert!(out.len() > 4, "{out:?}");
        assert!(out.iter().all(|l| width(l) <= WRAP), "{out:?}");
        assert!(out.iter().any(|l| l.ends_with("[long REFUTED]")), "{out:?}");
        let words = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
        let text = words(&out.join(" "));
        assert!(
            text.contains(&words(&format!(
                "residual lhs − rhs = {}",
                residual.render(Style::Unicode)
            ))),
            "{text}"
        );
    }

    /// A nonvanishing claim's witness is measured by the terms it prints as: `(x³⁷ + x³⁶ + … +
    /// x) cos θ` is 37 terms (74 monomials, `e^{±iθ}`) and prints whole; `(x + … + x²⁰⁰)
    /// cos θ` is said to be a nonzero sum of 200 terms, not of its 400 monomials.
    #[test]
    fn a_witness_is_counted_by_its_printed_terms() {
        let vars = trigpoly::Vars::builder()
            .coordinate("x")
            .angle("theta")
            .build()
            .unwrap();
        let witness = |n: usize| {
            let sum = (1..=n).map(|k| format!("x^{k}")).collect::<Vec<_>>();
            trigpoly::Expr::parse(&vars, &format!("({})*cos(theta)", sum.join(" + "))).unwrap()
        };
        let lines = |w: trigpoly::Expr| {
            let mut c = ClaimResult::derived("nonzero", "w ≠ 0", true, None);
            c.kind = ClaimKind::Nonvanishing;
            c.witness = Some(w);
            let mut out = Vec::new();
            claim(&mut out, &c);
            out.join("\n")
        };
        let short = lines(witness(37));
        assert!(short.contains("it equals (x³⁷ + x³⁶ + x³⁵"), "{short}");
        let long = lines(witness(200));
        assert!(long.contains("it is a nonzero sum of 200 terms"), "{long}");
    }

    /// A long sum breaks before its signs, not inside a monomial (`x² p_y⁴`), and not inside
    /// parentheses; a term wider than a line is wrapped at its spaces.
    #[test]
    fn a_sum_wraps_between_its_terms() {
        let line = "    {C, S} = 12Mω p_x⁶ p_y² − 18Mω p_x⁴ p_y⁴ + 144M³ω³x² p_x⁴ p_y² − (a + b)";
        let lines = wrap_sum(line, 40, "        ");
        assert_eq!(
            lines,
            [
                "    {C, S} = 12Mω p_x⁶ p_y²",
                "        − 18Mω p_x⁴ p_y⁴",
                "        + 144M³ω³x² p_x⁴ p_y² − (a + b)",
            ]
        );
        let lines = wrap_sum("x = a b c d e f + g", 6, "  ");
        assert!(lines.iter().all(|l| width(l) <= 6), "{lines:?}");
        assert_eq!(
            lines
                .join(" ")
                .split_whitespace()
                .collect::<Vec<_>>()
                .join(" "),
            "x = a b c d e f + g"
        );
    }

    /// Prose breaks at its spaces, but not inside a formula's parentheses or braces (at
    /// whatever column the formula starts), and its backticks are dropped; spaces inside
    /// prose parentheses still break.
    #[test]
    fn prose_keeps_a_formulas_parentheses_on_one_line() {
        let balanced = |l: &str| {
            l.matches('(').count() == l.matches(')').count()
                && l.matches('{').count() == l.matches('}').count()
        };
        let words = |s: &str| {
            s.replace('`', "")
                .split_whitespace()
                .collect::<Vec<_>>()
                .join(" ")
        };
        for n in 0..60 {
            let known = format!(
                "{}known: `H, A_xy, P_{{1,1}}, Re(Z_y e^{{−iθ}}), {{L_x, A_xy}}, (a + b)(c + d)`.",
                "a ".repeat(n)
            );
            let lines = prose(&known);
            assert!(lines.iter().all(|l| width(l) <= WRAP), "{lines:?}");
            assert!(lines.iter().all(|l| balanced(l)), "{lines:?}");
            assert_eq!(words(&lines.join(" ")), words(&known));
        }
        // Prose parentheses are no formula: a long one breaks inside.
        let aside = format!("({})", "word ".repeat(30).trim_end());
        assert!(prose(&aside).len() > 1);
    }

    /// A caption of equations wider than a line wraps as prose does: the caption of
    /// `search --on`'s quotients names the level set's polynomial, of any length.
    #[test]
    fn captions_wrap_as_prose() {
        let long = format!(
            "The integrals on the level set alone: `{{I, H}} = Q P`, `P = {}`, with",
            (1..=12)
                .map(|k| format!("x_{k} y_{k}"))
                .collect::<Vec<_>>()
                .join(" + ")
        );
        let eq = Equations::new(long.clone(), Vec::new());
        let mut out = Vec::new();
        equations(&mut out, &eq);
        assert!(out.len() > 1, "{out:?}");
        assert!(out.iter().all(|l| width(l) <= WRAP), "{out:?}");
        assert_eq!(out.join(" "), format!("{}:", plain(&long)));
    }

    /// A term wider than a line stays with its sign: `+ 1000…0x` was a `+` on a line of its
    /// own, the term under it (`expand` of `x² + 10¹²⁰x + y`).
    #[test]
    fn a_term_wider_than_a_line_keeps_its_sign() {
        let big = format!("1{}x", "0".repeat(60));
        let line = format!("    f = x² + {big} + y");
        let lines = wrap_sum(&line, 40, "        ");
        assert_eq!(
            lines,
            [
                "    f = x²".to_string(),
                format!("        + {big}"),
                "        + y".to_string(),
            ]
        );
    }

    /// A piece after a sign inside brackets keeps the depth it starts at, so its own sums
    /// break one level down: the Sutherland claim `{I_3 − g(… + … + …), H}` broke inside
    /// `sin(q2 − q3)`, its sum inside `g(…)` counted one level too shallow.
    #[test]
    fn a_sum_inside_brackets_breaks_between_its_terms() {
        let line = "  {I_3 − g((p_q1 + p_q2)/sin(q1 − q2)² + (p_q1 + p_q3)/sin(q1 − q3)² \
                    + (p_q2 + p_q3)/sin(q2 − q3)²), H} = 0";
        let lines = wrap_sum(line, 80, "      ");
        assert_eq!(
            lines,
            [
                "  {I_3 − g((p_q1 + p_q2)/sin(q1 − q2)² + (p_q1 + p_q3)/sin(q1 − q3)²",
                "      + (p_q2 + p_q3)/sin(q2 − q3)²), H} = 0",
            ]
        );
    }

    /// A term wider than a line breaks inside its long parentheses, one level down, but never
    /// inside a short group such as `(x − y)⁴`, wherever the group stands.
    #[test]
    fn a_short_group_never_breaks() {
        let groups = "(x − y)⁴ (aaaa + bbbb + cccc + dddd + eeee + ffff) (x + z)²";
        let line = format!("r = {groups} + {groups}");
        let lines = wrap_sum(&line, 24, "  ");
        let text = lines.join("\n");
        assert_eq!(text.matches("(x − y)⁴").count(), 2, "{text}");
        assert_eq!(text.matches("(x + z)²").count(), 2, "{text}");
        assert!(lines.len() > 4, "{text}");
        assert_eq!(
            text.split_whitespace().collect::<Vec<_>>(),
            line.split_whitespace().collect::<Vec<_>>()
        );
    }

    #[test]
    fn numbers_read_like_the_paper() {
        let q = |re: (i64, i64), im: (i64, i64)| {
            GaussianRational::new(Rational::new(re.0, re.1), Rational::new(im.0, im.1))
        };
        for (value, text) in [
            (q((0, 1), (11, 1)), "11i"),
            (q((0, 1), (-11, 7)), "−11i/7"),
            (q((0, 1), (1, 1)), "i"),
            (q((0, 1), (-1, 1)), "−i"),
            (q((3, 2), (-1, 1)), "3/2 − i"),
            (q((-5, 1), (2, 3)), "−5 + 2i/3"),
            (q((7, 4), (0, 1)), "7/4"),
        ] {
            assert_eq!(trigpoly::render_number(&value, Style::Unicode), text);
        }
    }

    /// Pieces of a printed expression: terms, signs, parentheses, braces and spaces.
    const PIECES: &[&str] = &[
        "x²", "p_y", "2M", "ω", "(", ")", "{", "}", " + ", " − ", " ", "/", "cos θ", "·", "x p_y⁴",
        "= ",
    ];

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(1000))]

        /// Wrapping keeps every word in order and breaks only at spaces, and a line is wider
        /// than the width only when it holds one word after its indent, or a sign and one.
        #[test]
        fn a_wrapped_sum_keeps_its_words_and_its_width(
            picks in proptest::collection::vec(0..PIECES.len(), 0..60),
            w in 4usize..50,
        ) {
            let s: String = picks.iter().map(|&k| PIECES[k]).collect();
            let lines = wrap_sum(&s, w, "  ");
            let words = |t: &str| t.split(' ').filter(|x| !x.is_empty()).map(str::to_string).collect::<Vec<_>>();
            let wrapped: Vec<String> = lines.iter().flat_map(|l| words(l)).collect();
            proptest::prop_assert_eq!(&wrapped, &words(&s), "{:?} at {}: {:?}", s, w, lines);
            for l in &lines {
                let signed = |ws: &[String]| ws.len() == 2 && ["+", "−"].contains(&ws[0].as_str());
                proptest::prop_assert!(
                    crate::render::width(l) <= w || words(l).len() <= 1 || signed(&words(l)),
                    "{:?} at {}: {:?}", s, w, lines
                );
            }
        }
    }

    /// The wrap as it was before it read the text in one pass a level (step 161 of
    /// docs/performance.md): every byte strictly inside a short group marked first, every
    /// piece joined to its line to be measured. The tests hold the one-pass wrap to it.
    fn wrap_sum_by_marks(s: &str, w: usize, indent: &str) -> Vec<String> {
        let mut pieces: Vec<&str> = Vec::new();
        // A piece is split when it would not fit a line after the indent.
        let whole = Piece { text: s, depth: 0 };
        sum_pieces_by_marks(whole, 0, w.saturating_sub(width(indent)), &mut pieces);
        let mut lines: Vec<String> = Vec::new();
        let mut line = String::new();
        for piece in pieces {
            let joined = match line.is_empty() {
                true => piece.to_string(),
                false => format!("{line} {piece}"),
            };
            if line.is_empty() || width(&joined) <= w {
                line = joined;
                continue;
            }
            lines.push(std::mem::replace(&mut line, format!("{indent}{piece}")));
        }
        lines.push(line);
        lines
            .into_iter()
            .flat_map(|l| match width(&l) <= w {
                true => vec![l],
                false => wrap(&l, w, indent),
            })
            .collect()
    }

    /// [`sum_pieces`] as it was, its short groups marked byte by byte.
    fn sum_pieces_by_marks<'a>(piece: Piece<'a>, level: i32, w: usize, out: &mut Vec<&'a str>) {
        let s = piece.text;
        // A short group in parentheses, a factor such as `(x − y)⁴`, never breaks. Its bytes
        // strictly inside are marked by a count that rises after its `(` and falls at its `)`: one
        // pass over the text, where asking every group at every sign took 13 s to print a
        // residual of 10⁵ terms.
        let mut open = Vec::new();
        let mut steps = vec![0i32; s.len() + 1];
        for (k, c) in s.char_indices() {
            match c {
                '(' => open.push(k),
                ')' => {
                    if let Some(o) = open.pop() {
                        if width(&s[o..=k]) <= WHOLE_GROUP {
                            steps[o + 1] += 1;
                            steps[k] -= 1;
                        }
                    }
                }
                _ => {}
            }
        }
        let mut groups = 0;
        let in_group: Vec<bool> = steps
            .iter()
            .map(|&step| {
                groups += step;
                groups > 0
            })
            .collect();
        let mut pieces: Vec<Piece> = Vec::new();
        let (mut depth, mut start, mut start_depth) = (piece.depth, 0, piece.depth);
        for (k, c) in s.char_indices() {
            match c {
                '(' | '{' | '[' => depth += 1,
                ')' | '}' | ']' => depth -= 1,
                '+' | '−'
                    if depth == level
                        && !in_group[k]
                        && k > start
                        && s[..k].ends_with(' ')
                        && s[k + c.len_utf8()..].starts_with(' ') =>
                {
                    pieces.push(Piece {
                        text: &s[start..k - 1],
                        depth: start_depth,
                    });
                    (start, start_depth) = (k, depth);
                }
                _ => {}
            }
        }
        pieces.push(Piece {
            text: &s[start..],
            depth: start_depth,
        });
        for piece in pieces {
            match width(piece.text) > w && level < 2 {
                true => sum_pieces_by_marks(piece, level + 1, w, out),
                false => out.push(piece.text),
            }
        }
    }

    /// Pieces of a printed expression for the one-pass wrap and the wrap before it: signs in
    /// and out of groups short and long, `−` beside other characters of the same first byte
    /// (`⁴`), combining marks (a bar on `A`, on `ω`), unbalanced brackets and doubled spaces.
    const MORE_PIECES: &[&str] = &[
        "x²",
        "p_y⁴",
        "2M",
        "ω̄",
        "A\u{304}",
        "(",
        ")",
        "((",
        "{",
        "}",
        "[",
        "]",
        " + ",
        " − ",
        "−",
        "+",
        " ",
        "  ",
        "/",
        "cos θ",
        "(x − y)⁴",
        "(a + b + c + d + e + f)",
        "10000000000",
        "= ",
    ];

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(3000))]

        /// The one-pass wrap gives the lines the wrap before it gave, at every width.
        #[test]
        fn the_one_pass_wrap_gives_the_same_lines(
            picks in proptest::collection::vec(0..MORE_PIECES.len(), 0..80),
            w in 1usize..60,
            indent in 0usize..6,
        ) {
            let s: String = picks.iter().map(|&k| MORE_PIECES[k]).collect();
            let indent = " ".repeat(indent);
            proptest::prop_assert_eq!(wrap_sum(&s, w, &indent), wrap_sum_by_marks(&s, w, &indent));
        }
    }

    /// The one-pass wrap, laying each piece on its lines as it finds it, gives the lines of
    /// the wrap before it where a line is exactly as wide as the width, one column wider or
    /// narrower, with combining marks that make its bytes more than its width, a term wider
    /// than the width mid-sum, and a sum of 3 000 terms; a line as wide as the width is kept
    /// whole.
    #[test]
    fn the_one_pass_wrap_keeps_a_line_at_the_width() {
        let terms = |n: usize, term: &str| {
            (1..=n)
                .map(|k| format!("{k}{term}"))
                .collect::<Vec<_>>()
                .join(" + ")
        };
        let big = format!("1{}x", "0".repeat(30));
        let lines = [
            "f = a + b − c".to_string(),
            "f = ω̄ + A\u{304} − ω̄A\u{304}".to_string(),
            format!("f = x + {big} + y − (a + b)"),
            format!("    {{C, S}} = {}", terms(40, "p_x⁴ p_y²")),
            format!("g = {}", terms(3000, "ω̄ x²")),
        ];
        for line in &lines {
            for indent in ["", "  ", "      "] {
                let whole = width(line);
                let near = (1..=whole + 2)
                    .rev()
                    .take(if whole < 1000 { 30 } else { 0 });
                for w in near.chain([8, 12, 20, 40, 80]) {
                    assert_eq!(
                        wrap_sum(line, w, indent),
                        wrap_sum_by_marks(line, w, indent),
                        "{line:?} at {w} with {indent:?}"
                    );
                }
                assert_eq!(wrap_sum(line, whole, indent), [line.as_str()]);
                assert!(wrap_sum(line, whole - 1, indent).len() > 1, "{line:?}");
            }
        }
        assert!(lines[1].len() > width(&lines[1]) + 4);
    }

    /// A report's lines are written as they were joined, each ended by a newline and the
    /// last lines after the others; no lines, no text.
    #[test]
    fn lines_to_text_ends_each_line() {
        let out = ["a".to_string(), String::new(), "ω̄ b".to_string()];
        let text = crate::render::lines_to_text(&out, &["", "end"]);
        assert_eq!(text, "a\n\nω̄ b\n\nend\n");
        assert_eq!(text.capacity(), text.len());
        assert_eq!(crate::render::lines_to_text(&out[..1], &[]), "a\n");
        assert_eq!(crate::render::lines_to_text(&[], &["x"]), "x\n");
        assert_eq!(crate::render::lines_to_text(&[], &[]), "");
    }

    /// The width counted on the bytes is that of the characters less the combining marks,
    /// for every character alone and beside the marks and the characters that share their
    /// first bytes (0xCC, 0xCD: U+0300 to U+037F); text is wider than `w` when that width is.
    #[test]
    fn the_width_counts_the_characters_but_the_combining_marks() {
        let by_characters = |t: &str| {
            t.chars()
                .filter(|&c| !super::super::tex::is_combining(c))
                .count()
        };
        for c in (0..=0x10FFFFu32).filter_map(char::from_u32) {
            let alone = c.to_string();
            assert_eq!(width(&alone), by_characters(&alone), "{c:?}");
        }
        let near: String = (0x2F0..0x380u32).filter_map(char::from_u32).collect();
        for t in [near.as_str(), "A\u{304}ω\u{303}x", "p_y⁴ − 3", ""] {
            let mixed = format!("{t}x{t}");
            assert_eq!(width(&mixed), by_characters(&mixed), "{mixed:?}");
            for w in 0..=mixed.len() + 1 {
                assert_eq!(wider_than(&mixed, w), width(&mixed) > w, "{mixed:?} at {w}");
            }
        }
    }
}
