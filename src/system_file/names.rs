//! The names of a system file: which names may be declared (`BadName`, `reserved`, a letter
//! LaTeX cannot write, a display that shows nothing), a family's indices, and how every name
//! prints, so that no two things of a system print alike (`PrintedNames`).

use std::collections::HashMap;
use std::ops::Range;

use brackets::System;
use trigpoly::{
    display_forms, is_identifier, latex_unwritable, quoted_name, shown_forms, unbarred, Span,
    VarSet, Vars, RESERVED,
};

use super::error::{ErrorKind, FileError};
use super::text::{Source, Text};
use super::LoadedSystem;

/// Why a letter cannot be in a name or a display name, when LaTeX output could not write it
/// ([`latex_unwritable`]): `LaTeX has no letter 'é' (…)`; a character other than a letter (a
/// mark over a letter, a sign, one that prints nothing) is said by its code point. The words
/// are [`trigpoly::BadName::Unwritable`]'s.
pub fn unwritable_letter(c: char) -> Option<String> {
    latex_unwritable(c.encode_utf8(&mut [0; 4]))?;
    Some(trigpoly::BadName::Unwritable(c).to_string())
}

/// Whether `c` shows nothing, or moves or turns the text around it: a control character
/// (a tab), white space other than the space (no-break, line separator), or a format character
/// (zero width, the bidirectional marks and overrides, a byte-order mark, variation selectors).
fn invisible(c: char) -> bool {
    c.is_control()
        || (c.is_whitespace() && c != ' ')
        || matches!(
            c,
            '\u{ad}'
                | '\u{34f}'
                | '\u{61c}'
                | '\u{115f}'
                | '\u{1160}'
                | '\u{17b4}'
                | '\u{17b5}'
                | '\u{180b}'..='\u{180f}'
                | '\u{200b}'..='\u{200f}'
                | '\u{202a}'..='\u{202e}'
                | '\u{2060}'..='\u{206f}'
                | '\u{3164}'
                | '\u{fe00}'..='\u{fe0f}'
                | '\u{feff}'
                | '\u{ffa0}'
                | '\u{fff0}'..='\u{fffb}'
                | '\u{1bca0}'..='\u{1bca3}'
                | '\u{1d173}'..='\u{1d17a}'
                | '\u{e0000}'..='\u{e0fff}'
        )
}

/// Why a name cannot name anything new in a system file, whatever the system has: each caller
/// says it in its own words (`'2Q' cannot name a function: …`, `--define '2Q': …`).
///
/// The rule is the variable sets' one ([`trigpoly::BadName`]: an identifier, no empty
/// subscript, letters LaTeX can write, not `i` or a function), which the file format widens
/// by the names it gives a meaning of its own ([`reserved`]: `H`, `rank`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BadName {
    /// A name no variable set takes, and why ([`trigpoly::BadName`]).
    Unnamed(trigpoly::BadName),
    /// A name the file format reserves, and why ([`reserved`]): `i` and the functions, which
    /// [`trigpoly::BadName::Reserved`] refuses too, said with the file's own `rank` and `H`.
    Reserved(String),
}

impl BadName {
    /// The first reason `name` is refused, if any: malformed, an empty subscript, unwritable,
    /// reserved.
    pub fn of(name: &str) -> Option<BadName> {
        match trigpoly::BadName::of(name) {
            // The file's words for i and the functions, which list its own reserved names.
            Some(trigpoly::BadName::Reserved) | None => reserved(name).map(BadName::Reserved),
            Some(bad) => Some(BadName::Unnamed(bad)),
        }
    }

    /// The message for declaring `name` as `what` (`a function`): `'2Q' cannot name a
    /// function: a name is …`, `'a_' cannot be a name: …` (a long name by its start and its
    /// length, [`quoted_name`]); a reserved name's reason says it alone.
    pub fn declaring(&self, name: &str, what: &str) -> String {
        match self {
            BadName::Reserved(why) => why.clone(),
            BadName::Unnamed(trigpoly::BadName::EmptySubscript) => {
                format!("{} cannot be a name: {}", quoted_name(name), self.why())
            }
            BadName::Unnamed(_) => {
                format!("{} cannot name {what}: {}", quoted_name(name), self.why())
            }
        }
    }

    /// The reason in words: `a name is letters, …`, `LaTeX has no letter 'é' (…)`, `'H' is
    /// reserved for the Hamiltonian`.
    pub fn why(&self) -> String {
        match self {
            BadName::Unnamed(bad) => bad.to_string(),
            BadName::Reserved(why) => why.clone(),
        }
    }
}

/// Why a family's two indices are refused, if they are: the index at fault, the kind of error
/// and the message. `taken` says what already has a name, in the words after "is already"
/// (`declared as a coordinate`).
pub(super) fn index_refusal(
    indices: [&str; 2],
    taken: impl Fn(&str) -> Option<String>,
) -> Option<(usize, ErrorKind, String)> {
    for (k, idx) in indices.into_iter().enumerate() {
        let refusal = if !is_identifier(idx) || idx.contains('_') || idx == "i" {
            Some((
                ErrorKind::Family,
                format!("'{idx}' cannot name an index: use a plain name such as m or n"),
            ))
        } else if let Some(why) = latex_unwritable(idx).and_then(unwritable_letter) {
            Some((
                ErrorKind::Name,
                format!("'{idx}' cannot name an index: {why}"),
            ))
        } else if let Some(other) = taken(idx) {
            Some((
                ErrorKind::Family,
                format!("the index '{idx}' is already {other}"),
            ))
        } else if k == 1 && indices[0] == idx {
            Some((
                ErrorKind::Family,
                format!("the two indices are both named '{idx}'"),
            ))
        } else {
            None
        };
        if let Some((kind, message)) = refusal {
            return Some((k, kind, message));
        }
    }
    None
}

/// Why `name` cannot be declared whatever the system: `'cos' is reserved (i, cos, …)`,
/// `'H' is reserved for the Hamiltonian`; `None` for a name that is free of meaning.
pub fn reserved(name: &str) -> Option<String> {
    if RESERVED.contains(&name) || name == "rank" {
        Some(format!(
            "'{name}' is reserved (i, cos, sin, exp, conj, re, im, rank)"
        ))
    } else if name == "H" {
        Some("'H' is reserved for the Hamiltonian".into())
    } else {
        None
    }
}

/// A notation a name is printed in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Notation {
    Text,
    Latex,
}

/// Why [`PrintedNames::admit`] refuses a new name, in words (its `Display`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Refusal {
    /// The printer writes a product of one-letter variables as the name (`Mx` for `M x`),
    /// which would read back as the function.
    Product(String),
    /// The name's display prints, in text or in LaTeX, as another name of the system does.
    Alike(String),
}

impl std::fmt::Display for Refusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Refusal::Product(why) | Refusal::Alike(why) => f.write_str(why),
        }
    }
}

/// How the names of a system print, in text and in LaTeX, so that a new function (of a file,
/// of a program, or a generator given on the command line) that would print as one of them
/// is refused ([`PrintedNames::admit`]): its tables and equations would show two things alike
/// (`G_1` and a parameter `G1`, both `G_{1}` in LaTeX; a function `B` shown as `A` beside a
/// function `A`), or a product would print as its name (`Mx` beside `M` and `x`). The loader
/// checks a file's functions so, [`LoadedSystem::add_function`] a program's, and the command
/// line its `--define`d generators.
///
/// ```
/// use superint::system_file::{PrintedNames, Refusal};
///
/// let rotor = superint::brackets::systems::harmonic_rotor();
/// let mut printed = PrintedNames::of(&rotor);
/// assert_eq!(
///     printed.admit("the function F_1", "F_1", "F_1").unwrap_err().to_string(),
///     "the function F_1 would print as F_{1} in LaTeX, as the function F1 does"
/// );
/// let product = printed.admit("the function Mx", "Mx", "Mx").unwrap_err();
/// assert!(matches!(product, Refusal::Product(_)), "{product}");
/// assert!(printed.admit("the function C", "C", "C").is_ok());
/// assert!(matches!(printed.admit("the function D", "D", "C"), Err(Refusal::Alike(_))));
/// ```
#[derive(Clone, Debug, Default)]
pub struct PrintedNames {
    /// For each form, whose it is (`the parameter M1`, `the function Gx`) and, for a file's
    /// function, the line of its name or display.
    forms: HashMap<(Notation, String), (String, Option<usize>)>,
    /// The variables whose products the printer writes side by side, when their set was built
    /// without the new names (not a file's, whose set names its functions).
    vars: Option<Vars>,
}

impl PrintedNames {
    /// The forms of the variables of `vars`.
    pub(super) fn of_variables(vars: &VarSet) -> Self {
        PrintedNames::of_variables_at(vars, &HashMap::new(), &[])
    }

    /// The forms of the variables of `vars` but those named in `except`, each of those of
    /// `lines` (by name) given on that line of a file (its display, `[phase_space] display`).
    pub(super) fn of_variables_at(
        vars: &VarSet,
        lines: &HashMap<String, usize>,
        except: &[String],
    ) -> Self {
        let mut printed = PrintedNames::default();
        for v in vars.vars() {
            let v = vars.variable(v);
            if except.iter().any(|e| e == v.name()) {
                continue;
            }
            let whose = PrintedNames::whose_variable(v.kind(), v.name());
            let line = lines.get(v.name()).copied();
            for form in [(Notation::Text, v.unicode()), (Notation::Latex, v.latex())] {
                printed
                    .forms
                    .insert((form.0, form.1.to_string()), (whose.clone(), line));
            }
        }
        printed
    }

    /// Whose a variable is in messages: `the coordinate x1`, `the parameter a`.
    pub(super) fn whose_variable(kind: trigpoly::VarKind, name: &str) -> String {
        // `a coordinate` → `the coordinate x1`.
        let kind = kind.described().split_once(' ').map_or("", |k| k.1);
        format!("the {kind} {name}")
    }

    /// Takes a variable's forms, `text` and `latex` (a display's, `[phase_space] display`),
    /// `whose` they are, given on `line`, unless a name already prints so: then why (`the
    /// parameter b would show as ω, as the parameter omega does`).
    pub(super) fn admit_variable(
        &mut self,
        whose: &str,
        text: &str,
        latex: &str,
        line: usize,
    ) -> Result<(), String> {
        let forms = [
            (Notation::Text, text.to_string()),
            (Notation::Latex, latex.to_string()),
        ];
        self.admit_keys(whose, forms.to_vec(), Some(line), "")
    }

    /// How the variables and the named functions of `system` print.
    pub fn of(system: &System) -> Self {
        let mut printed = PrintedNames::of_variables(system.vars());
        for f in system.functions() {
            let whose = format!("the function {}", f.name);
            // Each function was admitted beside the others: none is refused here.
            let _ = printed.admit_display(&whose, &f.display, None);
        }
        printed.vars = Some(system.vars().clone());
        printed
    }

    /// Takes a new function `name` shown as `display`, `whose` it is (`the function Gx`, `the
    /// generator C`), unless the printer could write one of them for a product of one-letter
    /// variables ([`VarSet::juxtaposition_spells`]), or `display` prints, in text or in LaTeX,
    /// as a name already taken: then why, in words (`the function B would show as A, as the
    /// function A does`), to which each caller adds what to do.
    pub fn admit(&mut self, whose: &str, name: &str, display: &str) -> Result<(), Refusal> {
        if let Some(vars) = &self.vars {
            for written in [name, display] {
                let text = display_forms(written).map_or_else(|| written.to_string(), |f| f.0);
                if vars.juxtaposition_spells(&text) {
                    let letters: Vec<String> = text.chars().map(String::from).collect();
                    return Err(Refusal::Product(format!(
                        "{whose} would read back from the product {} of the variables, which \
                         prints as {text}",
                        letters.join(" ")
                    )));
                }
            }
        }
        self.admit_display(whose, display, None)
            .map_err(Refusal::Alike)
    }

    /// How the variables, the named functions and the families of `file` print.
    pub(crate) fn of_loaded(file: &LoadedSystem) -> Self {
        let mut printed = PrintedNames::of(&file.system);
        for f in &file.families {
            // Each family was admitted beside the others: none is refused here.
            let _ = printed.admit_family(&format!("the family {}", f.name), &f.display, None);
        }
        printed
    }

    /// Takes a family shown as `display`, whose instances print as `display` with their
    /// indices (`K_{2,3}`), unless another family's print so, in text or in LaTeX: then why
    /// (`the family T would show its instances as K_{m,n}, as the family K does`).
    pub(crate) fn admit_family(
        &mut self,
        whose: &str,
        display: &str,
        line: Option<usize>,
    ) -> Result<(), String> {
        self.admit_forms(whose, display, line, "_{m,n}")
    }

    /// Takes the forms of `display`, `whose` they are, declared on `line` if it has one, unless
    /// a name already prints so: then why (`the function B would show as A, as the function A
    /// on line 9 does`).
    pub(super) fn admit_display(
        &mut self,
        whose: &str,
        display: &str,
        line: Option<usize>,
    ) -> Result<(), String> {
        self.admit_forms(whose, display, line, "")
    }

    /// Takes the forms of `display` followed by `indices` (a family's instances; no
    /// function's display has braces, so that those forms are the families' alone), `whose`
    /// they are, declared on `line` if it has one, unless a name already has one of them: then
    /// why, in words.
    fn admit_forms(
        &mut self,
        whose: &str,
        display: &str,
        line: Option<usize>,
        indices: &str,
    ) -> Result<(), String> {
        // A display of several words (`Re K`) has forms too; one of neither (`x(t)`) is
        // compared as it is written, in text.
        let (text, latex) = match shown_forms(display) {
            Some((text, latex)) => (text, Some(latex)),
            None => (display.to_string(), None),
        };
        let mut forms = vec![(Notation::Text, format!("{text}{indices}"))];
        if let Some(latex) = &latex {
            forms.push((Notation::Latex, format!("{latex}{indices}")));
        }
        self.admit_keys(whose, forms, line, indices)
    }

    /// Takes `forms` (with `indices` after them for a family's), `whose` they are, declared
    /// on `line` if it has one, unless a name already has one of them: then why, in words.
    fn admit_keys(
        &mut self,
        whose: &str,
        forms: Vec<(Notation, String)>,
        line: Option<usize>,
        indices: &str,
    ) -> Result<(), String> {
        for key in &forms {
            if let Some((other, at)) = self.forms.get(key) {
                let place = at.map(|l| format!(" on line {l}")).unwrap_or_default();
                let how = match (key, indices.is_empty()) {
                    ((Notation::Text, form), true) => format!("show as {form}"),
                    ((Notation::Latex, form), true) => format!("print as {form} in LaTeX"),
                    ((Notation::Text, form), false) => format!("show its instances as {form}"),
                    ((Notation::Latex, form), false) => format!(
                        "print its instances in LaTeX as {} with their indices",
                        form.strip_suffix(indices).unwrap_or(form)
                    ),
                };
                return Err(format!("{whose} would {how}, as {other}{place} does"));
            }
        }
        for key in forms {
            self.forms.insert(key, (whose.to_string(), line));
        }
        Ok(())
    }
}

/// Refuses a display name (`text`, written at `whole` in `source`) that would not show as
/// written ([`Builder::check_display`] says how); the message points at the character.
pub(crate) fn check_display(
    source: &Source,
    text: &Text,
    whole: Range<usize>,
) -> Result<(), FileError> {
    const MARKUP: &str = "^`|\\$%&#{}~*<>\"";
    let name = &text.value;
    let refuse = |span: Range<usize>, why: &str| {
        Err(source.error(
            ErrorKind::Name,
            span,
            format!(
                "a display name is letters, digits, primes (G1'), a bar (Z̄), subscripts \
                 (A_x), spaces and parentheses: {why}"
            ),
        ))
    };
    if name.is_empty() {
        return refuse(
            whole.clone(),
            "this one is empty (leave display out to show the name)",
        );
    }
    for (k, c) in name.char_indices() {
        let here = text.source_span(Span::new(k, k + c.len_utf8()));
        if MARKUP.contains(c) {
            return refuse(here, &format!("'{c}' is markup in Markdown or LaTeX"));
        }
        if invisible(c) {
            let code = c as u32;
            return refuse(
                here,
                &format!("U+{code:04X} is an invisible or control character"),
            );
        }
        let before = name[..k].chars().next_back();
        let after = name[k + c.len_utf8()..].chars().next();
        if c == ' ' && (before.is_none() || after.is_none()) {
            return refuse(here, "it begins or ends with a space");
        }
        if c == '\u{304}' || unbarred(c).is_some() {
            let letter = c != '\u{304}' || before.is_some_and(|b| b.is_alphanumeric());
            if !letter || after.is_some_and(|a| !matches!(a, '_' | '\'' | ' ' | '(' | ')')) {
                return refuse(
                    here,
                    "a bar (U+0304) stands right after the letter or digit it is drawn over, \
                     at the end of the name or before its '_', a prime, a space or a \
                     parenthesis (Z̄, Z̄_x)",
                );
            }
        } else if let Some(why) = unwritable_letter(c) {
            return refuse(here, &why);
        }
        let stands = |c: Option<char>| c.is_some_and(|c| c != '_' && c != ' ');
        if c == '_' && !(stands(before) && stands(after)) {
            return refuse(
                here,
                "a subscript '_' stands between a name and its subscript (A_x), not at an \
                 end or beside another '_' or a space",
            );
        }
    }
    Ok(())
}
