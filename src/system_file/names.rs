//! The names of a system file: which names may be declared (`BadName`, `reserved`, a letter
//! LaTeX cannot write, a display that shows nothing), a family's indices, and how every name
//! prints, so that no two things of a system print alike (`PrintedNames`).

use std::collections::HashMap;
use std::ops::Range;

use brackets::System;
use trigpoly::{
    display_forms, is_differential_sign, is_identifier, latex_unwritable, quoted_name, shown_forms,
    unbarred, with_indices, Span, VarSet, Vars, RESERVED,
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
pub(crate) fn invisible(c: char) -> bool {
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
#[non_exhaustive]
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
        } else if let Some(why) = reserved(idx) {
            // `H` and the functions keep their meaning in the family's value: an index `H`
            // made `H` there the index, and an index `cos` refused `cos(theta)`.
            Some((ErrorKind::Name, why))
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
            "'{name}' is reserved (i, cos, sin, exp, conj, re, im, sqrt, rank)"
        ))
    } else if name == "H" {
        Some("'H' is reserved for the Hamiltonian".into())
    } else {
        None
    }
}

/// A notation a name is printed in, or the name it is read back as.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Notation {
    Text,
    Latex,
    /// The name that a thing's printed LaTeX reads back as ([`read_back`]: `o` of `o` and of
    /// omicron's `\mathit{o}`, `K_1_2_3` of `K_{1,2,3}` and `K_{1;2,3}`), or its own name,
    /// which input names it by: two things with one such name would read back as one.
    ReadBack,
}

/// The name that a printed LaTeX reads back as, word by word for a display of several words
/// (`\operatorname{Re} K` → `Re K`): what a system's LaTeX reader takes it for, `o` of both
/// `o` and omicron's `\mathit{o}`, `K_1_2_3` of `K_{1,2,3}` and of `K_{1;2,3}`; `None` where
/// it reads as no name (`x(t)`).
pub(crate) fn read_back(latex: &str) -> Option<String> {
    let words: Option<Vec<String>> = latex
        .split_whitespace()
        .map(trigpoly::syntax::latex_name)
        .collect();
    words.map(|w| w.join(" ")).filter(|s| !s.is_empty())
}

/// Whose a form is: in words (`the function Gx`), the line of a file's declaration, and for a
/// name read back, the LaTeX it is read from (`None`: the name itself).
#[derive(Clone, Debug)]
struct Owner {
    whose: String,
    line: Option<usize>,
    from: Option<String>,
}

impl Owner {
    /// Whose it is, with the line of the declaration where there is one: `the function A on
    /// line 9`.
    fn placed(&self) -> String {
        match self.line {
            Some(l) => format!("{} on line {l}", self.whose),
            None => self.whose.clone(),
        }
    }
}

/// The forms of a family's instances at every pair of indices: for each notation, what comes
/// before and after the indices, and what stands between them (`K_{` `,` `}` in text and
/// LaTeX, `K_` `_` `` read back), and the family's LaTeX, which an instance's is made from.
#[derive(Clone, Debug)]
struct Instances {
    whose: String,
    line: Option<usize>,
    latex: Option<String>,
    forms: Vec<InstanceForm>,
}

/// The form of a family's instances in one notation ([`Instances`]); `named` for the one read
/// back from the name (`K_2_3`), not from the LaTeX.
#[derive(Clone, Debug, PartialEq, Eq)]
struct InstanceForm {
    notation: Notation,
    before: String,
    between: char,
    after: String,
    named: bool,
}

impl Instances {
    /// The forms of the instances of a family `name` shown as `display`, `whose` it is.
    fn of(whose: &str, name: &str, display: &str, line: Option<usize>) -> Instances {
        // Indices that no form has, to split the forms at.
        const M: &str = "zqzqzqM";
        const N: &str = "zqzqzqN";
        let mut forms = Vec::new();
        let mut split = |notation, form: String, between: char, named: bool| {
            let indices = format!("{M}{between}{N}");
            if let Some(k) = form.rfind(&indices) {
                forms.push(InstanceForm {
                    notation,
                    before: form[..k].to_string(),
                    between,
                    after: form[k + indices.len()..].to_string(),
                    named,
                });
            }
        };
        let shown = shown_forms(display);
        let latex = shown.as_ref().map(|(_, latex)| latex.clone());
        if let Some((text, latex)) = &shown {
            split(Notation::Text, format!("{text}_{{{M},{N}}}"), ',', false);
            let instance = with_indices(latex, &format!("{M},{N}"));
            if let Some(read) = read_back(&instance) {
                split(Notation::ReadBack, read, '_', false);
            }
            split(Notation::Latex, instance, ',', false);
        }
        split(Notation::ReadBack, format!("{name}_{M}_{N}"), '_', true);
        Instances {
            whose: whose.to_string(),
            line,
            latex,
            forms,
        }
    }

    /// The instances at the indices `m, n` in LaTeX (`K_{1;m,n}` of `K1`) and the name that
    /// reads back as (`K_1_m_n`), if they have such forms.
    fn at_indices_m_n(&self) -> Option<(String, String)> {
        let instance = with_indices(self.latex.as_ref()?, "m,n");
        let read = read_back(&instance)?;
        Some((instance, read))
    }

    /// The instance whose form in `notation` is `form`, as its owner (`the family K's instance
    /// (1, 2)`, with the LaTeX its name is read back from), if one is.
    fn owning(&self, notation: Notation, form: &str) -> Option<Owner> {
        self.forms.iter().find_map(|f| {
            if f.notation != notation {
                return None;
            }
            let inner = form.strip_prefix(&f.before)?.strip_suffix(&f.after)?;
            let (m, n) = inner.split_once(f.between)?;
            let index = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
            (index(m) && index(n)).then(|| Owner {
                whose: format!("{}'s instance ({m}, {n})", self.whose),
                line: self.line,
                from: match (notation, f.named) {
                    (Notation::ReadBack, false) => self
                        .latex
                        .as_ref()
                        .map(|l| with_indices(l, &format!("{m},{n}"))),
                    _ => None,
                },
            })
        })
    }
}

/// Why [`PrintedNames::admit`] refuses a new name, in words (its `Display`).
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
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
/// function `A`), or a product would print as its name (`Mx` beside `M` and `x`). So is one
/// whose LaTeX reads back as another's name, or as what another's reads back as (a function
/// `o` beside omicron, printed `\mathit{o}`), and one that prints as an instance of a family
/// (a function shown as `K_1_2`, `K_{1,2}` in LaTeX, beside a family `K`; a parameter
/// `K_1_2_3`, `K_{1,2,3}`, beside a family `K1`, whose instance `K_{1;2,3}` reads back as
/// it). The loader checks a file's variables, functions and families so,
/// [`LoadedSystem::add_function`] a program's, and the command line its `--define`d
/// generators.
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
    forms: HashMap<(Notation, String), Owner>,
    /// The forms in the order they were taken, which a new family's instances are compared
    /// with, so that of two names printed as instances the first is named.
    order: Vec<(Notation, String)>,
    /// The forms of each family's instances.
    families: Vec<Instances>,
    /// The variables whose products the printer writes side by side, when their set was built
    /// without the new names (not a file's, whose set names its functions).
    vars: Option<Vars>,
}

/// The forms of a thing printed as `text` and `latex`, named `name`: its text, its LaTeX, and
/// the names it reads back as (from its LaTeX, and its own).
fn forms_of(
    text: String,
    latex: Option<String>,
    name: Option<&str>,
) -> Vec<(Notation, String, Option<String>)> {
    let mut forms = vec![(Notation::Text, text, None)];
    if let Some(latex) = latex {
        if let Some(read) = read_back(&latex) {
            forms.push((Notation::ReadBack, read, Some(latex.clone())));
        }
        forms.insert(1, (Notation::Latex, latex, None));
    }
    if let Some(name) = name {
        forms.push((Notation::ReadBack, name.to_string(), None));
    }
    forms
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
            // A denominator is named by what it divides by, `(x − y)`, which no name reads as.
            let named = (v.kind() != trigpoly::VarKind::Denominator).then(|| v.name());
            let forms = forms_of(v.unicode().to_string(), Some(v.latex().to_string()), named);
            for (notation, form, from) in forms {
                let owner = Owner {
                    whose: whose.clone(),
                    line,
                    from,
                };
                printed.take((notation, form), owner);
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
    /// `whose` they are (the variable `name`), given on `line`, unless a name already prints
    /// so: then why (`the parameter b would show as ω, as the parameter omega does`).
    pub(super) fn admit_variable(
        &mut self,
        whose: &str,
        name: &str,
        text: &str,
        latex: &str,
        line: usize,
    ) -> Result<(), String> {
        let forms = forms_of(text.to_string(), Some(latex.to_string()), Some(name));
        self.admit_keys(whose, forms, Some(line))
    }

    /// How the variables and the named functions of `system` print.
    pub fn of(system: &System) -> Self {
        let mut printed = PrintedNames::of_variables(system.vars());
        for f in system.functions() {
            let whose = format!("the function {}", f.name);
            // Each function was admitted beside the others: none is refused here.
            let _ = printed.admit_display(&whose, &f.name, &f.display, None);
        }
        printed.vars = Some(system.vars().clone());
        printed
    }

    /// Takes a new function `name` shown as `display`, `whose` it is (`the function Gx`, `the
    /// generator C`), unless the printer could write one of them for a product of one-letter
    /// variables ([`VarSet::juxtaposition_spells`]), or `display` prints, in text or in LaTeX,
    /// as a name already taken, or reads back as one: then why, in words (`the function B
    /// would show as A, as the function A does`), to which each caller adds what to do.
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
        self.admit_display(whose, name, display, None)
            .map_err(Refusal::Alike)
    }

    /// How the variables, the named functions and the families of `file` print.
    pub(crate) fn of_loaded(file: &LoadedSystem) -> Self {
        let mut printed = PrintedNames::of(&file.system);
        for f in &file.families {
            // Each family was admitted beside the others: none is refused here.
            let whose = format!("the family {}", f.name);
            let _ = printed.admit_family(&whose, &f.name, &f.display, None);
        }
        printed
    }

    /// Takes a family `name` shown as `display`, whose instances print as `display` with
    /// their indices (`K_{2,3}`), unless another family's print so, in text or in LaTeX, or
    /// another name prints or reads back as one of them: then why (`the family T would show
    /// its instances as K_{m,n}, as the family K does`; `the family K's instance (1, 2) would
    /// print as K_{1,2} in LaTeX, as the function F on line 7 does`).
    pub(crate) fn admit_family(
        &mut self,
        whose: &str,
        name: &str,
        display: &str,
        line: Option<usize>,
    ) -> Result<(), String> {
        let instances = Instances::of(whose, name, display, line);
        // A name printed as one of its instances, or read back as one.
        for key in &self.order {
            let (notation, form) = key;
            if let Some(instance) = instances.owning(*notation, form) {
                return Err(alike(&instance, *notation, form, &self.forms[key]));
            }
        }
        let symbolic = instances.at_indices_m_n();
        self.admit_forms(whose, display, line, "_{m,n}", symbolic)?;
        self.families.push(instances);
        Ok(())
    }

    /// Takes the forms of a function `name` shown as `display`, `whose` they are, declared on
    /// `line` if it has one, unless a name already prints so, or reads back so, or a family's
    /// instance does: then why (`the function B would show as A, as the function A on line 9
    /// does`).
    pub(super) fn admit_display(
        &mut self,
        whose: &str,
        name: &str,
        display: &str,
        line: Option<usize>,
    ) -> Result<(), String> {
        let (text, latex) = match shown_forms(display) {
            Some((text, latex)) => (text, Some(latex)),
            None => (display.to_string(), None),
        };
        let forms = forms_of(text, latex, Some(name));
        self.admit_keys(whose, forms, line)
    }

    /// Takes the forms of `display` followed by `indices` (a family's instances, `_{m,n}`; no
    /// function's display has braces, so that those forms are the families' alone), and
    /// `read`, what their LaTeX reads back as, `whose` they are, declared on `line` if it has
    /// one, unless a name already has one of them: then why, in words.
    fn admit_forms(
        &mut self,
        whose: &str,
        display: &str,
        line: Option<usize>,
        indices: &str,
        read: Option<(String, String)>,
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
        for key in &forms {
            if let Some(other) = self.forms.get(key) {
                let how = match key {
                    (Notation::Text, form) => format!("show its instances as {form}"),
                    (_, form) => format!(
                        "print its instances in LaTeX as {} with their indices",
                        form.strip_suffix(indices).unwrap_or(form)
                    ),
                };
                return Err(format!("{whose} would {how}, as {} does", other.placed()));
            }
        }
        let mut keys: Vec<(Notation, String, Option<String>)> =
            forms.into_iter().map(|(n, f)| (n, f, None)).collect();
        if let Some((latex, read)) = read {
            keys.push((Notation::ReadBack, read, Some(latex)));
        }
        self.admit_keys(whose, keys, line)
    }

    /// Takes `forms` (each in its notation, a name read back with the LaTeX it is read
    /// from), `whose` they are, declared on `line` if it has one, unless a name already has
    /// one of them, or a family's instance does: then why, in words.
    fn admit_keys(
        &mut self,
        whose: &str,
        forms: Vec<(Notation, String, Option<String>)>,
        line: Option<usize>,
    ) -> Result<(), String> {
        let owned: Vec<((Notation, String), Owner)> = (forms.into_iter())
            .map(|(notation, form, from)| {
                let whose = whose.to_string();
                ((notation, form), Owner { whose, line, from })
            })
            .collect();
        for (key, new) in &owned {
            let (notation, form) = key;
            let instance = || (self.families.iter()).find_map(|f| f.owning(*notation, form));
            if let Some(other) = self.forms.get(key).cloned().or_else(instance) {
                return Err(alike(new, *notation, form, &other));
            }
        }
        for (key, owner) in owned {
            self.take(key, owner);
        }
        Ok(())
    }

    /// Takes a form as `owner`'s, unless it has one already.
    fn take(&mut self, key: (Notation, String), owner: Owner) {
        if !self.forms.contains_key(&key) {
            self.order.push(key.clone());
            self.forms.insert(key, owner);
        }
    }
}

/// Why `new` cannot have `form` in `notation`, which `other` has: `the function B would show
/// as A, as the function A on line 9 does`; `the function o would print as o in LaTeX, and
/// the parameter omicron as \mathit{o}, which both read back as o`.
fn alike(new: &Owner, notation: Notation, form: &str, other: &Owner) -> String {
    let (whose, theirs) = (&new.whose, other.placed());
    match (notation, &new.from, &other.from) {
        (Notation::Text, ..) => format!("{whose} would show as {form}, as {theirs} does"),
        (Notation::Latex, ..) => {
            format!("{whose} would print as {form} in LaTeX, as {theirs} does")
        }
        (Notation::ReadBack, Some(mine), Some(its)) => format!(
            "{whose} would print as {mine} in LaTeX, and {theirs} as {its}, which both read \
             back as {form}"
        ),
        (Notation::ReadBack, Some(mine), None) => format!(
            "{whose} would print as {mine} in LaTeX, which reads back as {form}, the name of \
             {theirs}"
        ),
        (Notation::ReadBack, None, Some(its)) => format!(
            "{whose} would be named {form}, which the LaTeX of {theirs}, {its}, reads back as"
        ),
        (Notation::ReadBack, None, None) => {
            format!("{whose} would be named {form}, as {theirs} is")
        }
    }
}

/// The first character of `text` that shows nothing, or moves or turns the text around it
/// ([`invisible`]), with its byte offset: a line break or a tab too unless `lines` allows
/// them (a description's paragraphs and their indents, which reports print as written,
/// [`printable`](crate::render::printable)), `\r` only before `\n`.
pub(crate) fn first_invisible(text: &str, lines: bool) -> Option<(usize, char)> {
    text.char_indices().find(|&(k, c)| {
        let layout = matches!(c, '\n' | '\t') || (c == '\r' && text[k + 1..].starts_with('\n'));
        invisible(c) && !(lines && layout)
    })
}

/// Why reports could not show `text` as written, where it holds a control or invisible
/// character ([`first_invisible`]; `lines` as there): the character's byte range in `text`,
/// and the message, `{what} is shown in reports as written: U+0009 is …`, that a file's
/// texts ([`check_shown_text`]) and a claim added in code share.
pub(crate) fn unshowable(what: &str, text: &str, lines: bool) -> Option<(Span, String)> {
    let (k, c) = first_invisible(text, lines)?;
    let why = format!(
        "{what} is shown in reports as written: {}",
        invisible_named(c)
    );
    Some((Span::new(k, k + c.len_utf8()), why))
}

/// `U+0009 is an invisible or control character`, of `c`.
fn invisible_named(c: char) -> String {
    format!("U+{:04X} is an invisible or control character", c as u32)
}

/// Refuses a text that reports show as it is written (`what`: `a claim's id`, the system's
/// `name`; with `lines`, its `description` or `source`, which may run over several lines)
/// when it holds a control or invisible character ([`unshowable`]): a tab or a line break in
/// an id broke the report's layout, and an escape printed as `�`. The message points at the
/// character.
pub(crate) fn check_shown_text(
    source: &Source,
    text: &Text,
    (what, kind): (&str, ErrorKind),
    lines: bool,
) -> Result<(), FileError> {
    match unshowable(what, &text.value, lines) {
        Some((span, why)) => Err(source.error(kind, text.source_span(span), why)),
        None => Ok(()),
    }
}

/// Where the sign `c`, `∂` or `∇`, stands in a display name, for a message.
fn differential(c: char) -> String {
    format!("'{c}' stands first, right before the letter of what it applies to (∂H, ∇φ)")
}

/// Whether `c` is written as a subscript or a superscript (`₁`, `₊`, `ₐ`, `²`, `ᵃ`, `ⁿ`,
/// `ʰ`, `ª`), which Unicode counts as a digit, a sign or a letter: `subscript` or
/// `superscript`.
pub(crate) fn script(c: char) -> Option<&'static str> {
    match c {
        '\u{2080}'..='\u{209c}' | '\u{1d62}'..='\u{1d6a}' | '\u{2c7c}' => Some("subscript"),
        'ª' | 'º' | '¹' | '²' | '³' => Some("superscript"),
        '\u{2b0}'..='\u{2b8}' | '\u{2e0}'..='\u{2e4}' | '\u{1d2c}'..='\u{1d61}' => {
            Some("superscript")
        }
        '\u{1d78}' | '\u{1d9b}'..='\u{1dbf}' | '\u{2070}'..='\u{207f}' => Some("superscript"),
        '\u{a69c}' | '\u{a69d}' | '\u{a770}' | '\u{a7f8}' | '\u{a7f9}' => Some("superscript"),
        '\u{ab5c}'..='\u{ab5f}' | '\u{10780}'..='\u{107ba}' => Some("superscript"),
        _ => None,
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
    let message = |why: &str| {
        format!(
            "a display name is letters, digits, primes (G1'), a bar (Z̄), subscripts (A_x), \
             spaces and parentheses: {why}"
        )
    };
    if name.is_empty() {
        let why = "this one is empty (leave display out to show the name)";
        return Err(source.error(ErrorKind::Name, whole, message(why)));
    }
    // A refused character's place in the file is found on the way to the message only (an
    // escaped string's is read again, `Text::source_span`).
    let refuse = |at: Span, why: &str| {
        Err(source.error(ErrorKind::Name, text.source_span(at), message(why)))
    };
    let mut open: Vec<usize> = Vec::new();
    for (k, c) in name.char_indices() {
        let here = Span::new(k, k + c.len_utf8());
        match c {
            '(' => open.push(k),
            ')' if open.pop().is_none() => {
                return refuse(here, "this ')' closes no '('");
            }
            _ => {}
        }
        if MARKUP.contains(c) {
            return refuse(here, &format!("'{c}' is markup in Markdown or LaTeX"));
        }
        if invisible(c) {
            return refuse(here, &invisible_named(c));
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
        } else if k == 0 && (script(c).is_some() || is_differential_sign(c)) {
            // Said below, in the words of the rule on a display's first character.
        } else if is_differential_sign(c) {
            return refuse(here, &differential(c));
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
        // A name begins with a letter, or with `∂` or `∇` before one (`∂H`, `∇φ`): `₊`, `2`
        // or `'` alone would print as a mark, a number (`{2, H}`) or a prime of what stands
        // before it, `2x` as a product; a letter written as a subscript or a superscript,
        // `ₐx`, `ᵃx`, as one of what stands before it (a Unicode letter all the same).
        if k == 0 {
            if let Some(script) = script(c) {
                return refuse(
                    here,
                    &format!("it begins with '{c}', a {script}, not with a letter"),
                );
            }
            if is_differential_sign(c) {
                if !after.is_some_and(|a| a.is_alphabetic() && script(a).is_none()) {
                    return refuse(here, &differential(c));
                }
            } else if !c.is_alphabetic() {
                return refuse(here, &format!("it begins with '{c}', not with a letter"));
            }
        }
    }
    if let Some(&k) = open.last() {
        return refuse(Span::new(k, k + 1), "this '(' is never closed");
    }
    Ok(())
}
