//! What an expression read from text was computed from: the functions it names (`H` among
//! them) and the declared brackets its brackets take, so that a condition can be refused where
//! one of them has no value ([`Condition::defined_on_inputs`](crate::Condition::defined_on_inputs)),
//! though the expression computed from them has one (`{A, H} = 0` of the heavy top, whose `H`
//! divides by `I3`, at `I3 = 0`).

use std::cell::RefCell;

use trigpoly::{BracketError, Context, Expr, GaussianRational, RunTogether, Var};

use crate::PhaseSpace;

/// One thing an expression was computed from: `H`, a function, or a declared bracket's value.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Input {
    /// How a refusal names it: `H`, `the function A`, `the bracket {M1, M2}`.
    pub what: String,
    /// Its value.
    pub value: Expr,
    /// The name, as shown, of what the expression named that was computed from it (`G` for
    /// `F` where `G = x F`), or `None` where the expression used it itself.
    pub via: Option<String>,
}

/// Adds `input` to `inputs` unless one of them names the same ([`Input::what`]).
pub(crate) fn keep_once(inputs: &mut Vec<Input>, input: Input) {
    if !inputs.iter().any(|i| i.what == input.what) {
        inputs.push(input);
    }
}

/// A [`Context`] that reads as `context` does and keeps what the reading used: each name it
/// looked up (as shown where it is told, [`Recording::showing`]), what that name was itself computed from where it is told ([`Recording::through`]),
/// and each declared bracket of `space` that a bracket it took pairs (`{a, b}` where one side
/// involves `a` and the other `b`).
pub struct Recording<'a, X> {
    context: &'a X,
    space: &'a PhaseSpace,
    /// What a name's value was computed from (`F` for `G = x F`), kept beside the name.
    through: Option<ComputedFrom<'a>>,
    /// How a name is shown (`K_{1,2}` for `K_1_2`) where it is told ([`Recording::showing`]).
    shown: Option<Shown<'a>>,
    inputs: RefCell<Vec<Input>>,
}

/// What a name's value was computed from, asked by its name ([`Recording::through`]).
type ComputedFrom<'a> = Box<dyn Fn(&str) -> Vec<Input> + 'a>;

/// How a name is shown, asked by its name ([`Recording::showing`]).
type Shown<'a> = Box<dyn Fn(&str) -> String + 'a>;

impl<X> std::fmt::Debug for Recording<'_, X> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Recording")
            .field("inputs", &self.inputs)
            .finish_non_exhaustive()
    }
}

impl<'a, X: Context<GaussianRational>> Recording<'a, X> {
    /// Reads as `context`, in `space`, keeping what is used.
    pub fn new(context: &'a X, space: &'a PhaseSpace) -> Self {
        Recording {
            context,
            space,
            through: None,
            shown: None,
            inputs: RefCell::new(Vec::new()),
        }
    }

    /// The same recording, keeping beside each name looked up what `computed_from` says its
    /// value was computed from: a function defined through another that divides (`G = x F`,
    /// `F = p_y/x`, whose `G = p_y` has no `1/x` left) has no value where that one has none.
    #[must_use]
    pub fn through(mut self, computed_from: impl Fn(&str) -> Vec<Input> + 'a) -> Self {
        self.through = Some(Box::new(computed_from));
        self
    }

    /// The same recording, naming each name looked up as `shown` shows it (a family instance
    /// `K_1_2` as `K_{1,2}`), not as it was written.
    #[must_use]
    pub fn showing(mut self, shown: impl Fn(&str) -> String + 'a) -> Self {
        self.shown = Some(Box::new(shown));
        self
    }

    /// What the readings so far used, each once, in the order first used.
    pub fn into_inputs(self) -> Vec<Input> {
        self.inputs.into_inner()
    }

    fn keep(&self, input: Input) {
        keep_once(&mut self.inputs.borrow_mut(), input);
    }

    /// Whether `f` involves the phase variable `v`: holds it, or a denominator atom or a
    /// radical whose polynomial holds it (their brackets are formed from `v`'s).
    fn involves(&self, f: &Expr, v: Var) -> bool {
        let atoms = self.space.denominator_atoms().iter();
        f.contains(v)
            || atoms
                .chain(self.space.radicals())
                .any(|(atom, poly)| f.contains(*atom) && poly.contains(v))
    }
}

impl<X: Context<GaussianRational>> Context<GaussianRational> for Recording<'_, X> {
    fn lookup(&self, name: &str) -> Option<Expr> {
        let value = self.context.lookup(name)?;
        let shown = match &self.shown {
            Some(shown) => shown(name),
            None => name.to_string(),
        };
        let what = match name {
            "H" => "H".to_string(),
            _ => format!("the function {shown}"),
        };
        self.keep(Input {
            what,
            value: value.clone(),
            via: None,
        });
        if let Some(through) = &self.through {
            // What `name` was computed from, however deep, is named as computed for `name`.
            let via = |i: Input| Input {
                via: Some(shown.clone()),
                ..i
            };
            through(name).into_iter().for_each(|i| self.keep(via(i)));
        }
        Some(value)
    }

    fn bracket(&self, f: &Expr, g: &Expr) -> Result<Expr, BracketError> {
        for d in self.space.declared_brackets() {
            let (a, b) = (d.a, d.b);
            let pairs = |x: &Expr, y: &Expr| self.involves(x, a) && self.involves(y, b);
            if pairs(f, g) || pairs(g, f) {
                let vars = d.value.vars();
                let what = format!(
                    "the bracket {{{}, {}}}",
                    vars.variable(a).unicode(),
                    vars.variable(b).unicode()
                );
                self.keep(Input {
                    what,
                    value: d.value.clone(),
                    via: None,
                });
            }
        }
        self.context.bracket(f, g)
    }

    fn names(&self) -> Vec<String> {
        self.context.names()
    }

    fn spelling(&self, name: &str) -> Option<String> {
        self.context.spelling(name)
    }

    fn latex(&self, name: &str) -> Option<String> {
        self.context.latex(name)
    }

    fn run_together(&self, noted: RunTogether) {
        self.context.run_together(noted);
    }
}
