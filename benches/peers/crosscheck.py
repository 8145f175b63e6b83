"""Cross-checks superint against SymPy on random expressions: an independent oracle for the engine.

    python crosscheck.py [--cases 400] [--seed 1] [--jobs N] [--superint PATH] [--verbose]

For each case the script draws two random expressions F and G in one of four small systems (two
radicals; declared denominators; two angles with complex exponentials; Poisson variables of
e(3)* beside a canonical pair), picks an operation ({F, G}, {F, G} at a condition such as
`p_θ = 2Mω/3` (`--when`, the path of the brackets at a resonance), F·G or F^k), and asks
superint for the result (`bracket` or `expand`, JSON output; or the rank of two to four of
them and their products, whose certificate SymPy checks: below). SymPy computes the same result
from the definitions: the bracket as the sum over the canonical pairs and the declared brackets
of derivatives, with each radical as `sqrt(R)`, `cos`, `sin` and `exp(i nθ)` as SymPy's own
functions, then the condition substituted. Then four things must hold:

1. **The printed result is right.** superint's ASCII form, read back by SymPy, equals SymPy's
   result at exact points: rational points where every radicand is a square (so that every
   radical is rational) and every declared denominator nonzero, and rational points on the unit
   circle (cos θ = 3/5, sin θ = 4/5, ...) for the angles. Every value is an exact rational.
2. **SymPy's result is a zero difference in superint.** `expand "(superint's input) − (SymPy's
   result as text)"` prints `0`: SymPy's form (its own radicals, unexpanded denominators,
   `cos(θ − φ)`) is read by superint and decided zero exactly.
3. **A wrong result is refuted.** The same difference plus a small nonzero term is not `0`.
4. **As a user states it.** A system file with F and G as its functions and the claims
   `{F, G} = (SymPy's result)` and the wrong one (`expect = "refuted"`, at the condition where
   there is one): `superint check` finds every claim as expected.

A rank (`superint rank`) is right when the certificate's minor, recomputed by SymPy at the
certificate's point, is the nonzero value it states, and SymPy's rank of the Jacobian there and
at two other exact points is at most the rank (and at the certificate's point, equal to it).

A search (`superint search`) of a random potential `V(x, y)` (generic, separable, an oscillator
in resonance or rotationally invariant; or `a V₁ + b V₂` with `a`, `b` kept `--symbolic`; or
with negative powers, `--laurent`) is complete when its unknowns and dimension are SymPy's:
the polynomials of degree at most m in the momenta and n in the positions (times the
monomials in `a`, `b` up to their degree), less the rank of the linear map that takes their
coefficients to those of `{F, H}`.

A search of a random rotor (`H` with an angle θ, its potential coupling x, y and θ through
`cos kθ`, `sin kθ`, or not at all; or an oscillator at a value of p_θ, `--when`, as at the
resonances) is complete when its count of unknowns and the dimension it reports are SymPy's,
found with `E = e^{iθ}`: `{F, H}` is then a Laurent polynomial in `E`, whose coefficients' real
and imaginary parts are the equations.

A search of a random potential with the radical `r = √(x² + y²)` (`1/r`, `r`, `r²`, `x/r³`, `y/r`
and an oscillator's `x²`) is complete when its unknowns (the space's functions `p^a x^c y^d r^j`
that are independent as functions) and dimension are SymPy's, each function written `A + B r`.

A search of two particles on a line with the declared denominator `x − y` (`1/(x − y)²`,
`1/(x − y)`, oscillators) is complete in the same way, each function times a power of `x − y`.

A search of a random top (a quadratic form in M on so(3)*, or on e(3)* with a linear and
sometimes a quadratic term in γ) is complete when its dimension at a degree in the Poisson
variables is the one `search_dimensions.py` finds for it.

A closure (`superint closure`) of two to five random generators in the plane (quadratic forms
mostly, or combinations of u(2)'s; with parameters `a`, `b` in their coefficients, left at
superint's values and lifted back, fixed by `--fix`, or kept `--symbolic`) is right when every
bracket its table writes as a polynomial in the generators expands to the bracket SymPy
computes, every bracket it marks `*` is outside the span of the monomials in the generators up
to the degree (SymPy's rank), and the relations it prints vanish and, with their multiples up
to the degree, span the nullspace of those monomials' expansions (SymPy's dimension). What
superint states for every value of the parameters must hold for every value; what it states at
its values, there. Closures of the rotor's generators (quadratic forms, `p_θ`, the resonant
`(p_x + i w x)^m e^{−inθ}`, its conjugate and real parts, `cos θ`) at the resonance
`p_θ = w m/n` (`--when`) are checked the same way, every function written in `E = e^{iθ}`.

A case that superint refuses with a message (exit code 2: dividing by a sum that is no declared
denominator, say) is counted and skipped, as is a result too long for SymPy's parser even term
by term; any other exit code is a failure. The script prints a
summary line and exits nonzero if any case failed. It needs only SymPy (`run.sh` installs it
into `.venv`: `benches/peers/crosscheck.sh` does that and builds superint first).
"""
import argparse
import functools
import itertools
import json
import math
import multiprocessing
import os
import random
import re
import subprocess
import sys
import tempfile
from fractions import Fraction

import sympy as sp

from search_dimensions import (antisymmetric, coefficient_vectors, dimension,
                               integrals_dimension)

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# ---------------------------------------------------------------------------------------------
# The systems: a file for superint, the same definitions for SymPy, random atoms, exact points.


class System:
    """One system: its file text, SymPy symbols, canonical pairs, declared brackets, atoms."""

    def __init__(self, name, toml, symbols, pairs, declared, atoms, points, conditions,
                 extra_locals=None):
        self.name = name
        self.toml = toml
        self.locals = dict(symbols)
        self.locals.update(extra_locals or {})
        self.pairs = [(self.locals[q], self.locals[p]) for q, p in pairs]
        self.declared = [(self.locals[a], self.locals[b], sp.sympify(v, locals=self.locals))
                         for a, b, v in declared]
        self.atoms = atoms
        self.points = points
        # Substitutions after a bracket (`--when`): a single term (the fused path of the
        # brackets at a resonance) or a sum.
        self.conditions = conditions
        self.file = None

    def read(self, text):
        """An expression in superint's language (or SymPy's printing of one), read by SymPy: a
        long sum term by term, since Python's compiler nests a sum one level a term."""
        terms = top_level_terms(text) if len(text) > 10000 else [text]
        return sp.Add(*[sp.sympify(t.replace("^", "**"), locals=self.locals) for t in terms])

    def bracket(self, f, g):
        """{f, g}: the canonical pairs' Jacobians plus the declared brackets' part."""
        out = sp.Integer(0)
        for q, p in self.pairs:
            out += sp.diff(f, q) * sp.diff(g, p) - sp.diff(f, p) * sp.diff(g, q)
        for a, b, value in self.declared:
            out += value * (sp.diff(f, a) * sp.diff(g, b) - sp.diff(f, b) * sp.diff(g, a))
        return out


def top_level_terms(text):
    """`text` cut before each ` + ` and ` - ` outside parentheses: terms whose sum it is."""
    terms, depth, start = [], 0, 0
    for k, ch in enumerate(text):
        depth += {"(": 1, ")": -1}.get(ch, 0)
        if depth == 0 and text.startswith((" + ", " - "), k) and k > start:
            terms.append(text[start:k])
            start = k
    terms.append(text[start:])
    return terms


def symbols(names):
    return {n: sp.Symbol(n, real=True) for n in names.split()}


def radicals_system():
    s = symbols("x y z p_x p_y p_z k a")
    x, y, z, a = s["x"], s["y"], s["z"], s["a"]
    extra = {"r": sp.sqrt(x**2 + y**2 + z**2), "s": sp.sqrt((x - a)**2 + y**2 + z**2),
             "sqrt": sp.sqrt}
    # Integer points where both radicands are squares: both radicals are rational there.
    points = []
    for px in range(-6, 7):
        for py in range(1, 7):
            for pz in range(-6, 7):
                for pa in (-4, -3, -2, -1, 1, 2, 3, 4):
                    r2, s2 = px * px + py * py + pz * pz, (px - pa) ** 2 + py * py + pz * pz
                    if is_square(r2) and is_square(s2):
                        points.append({"x": px, "y": py, "z": pz, "a": pa})
    atoms = ["x", "y", "z", "p_x", "p_y", "p_z", "k", "a", "r", "s", "1/r", "1/s", "r^-3",
             "r^2", "s^3", "(x - y + 2*p_z)^2", "(r - z)", "sqrt(x^2 + y^2 + z^2)",
             "sqrt(4*(x - a)^2 + 4*y^2 + 4*z^2)", "(r*s + x)", "1/(r*s)", "1/(r + z)",
             "(x^2 + y^2 + z^2)^(-3/2)", "1/(x^2 + y^2)"]
    return System(
        "radicals",
        """name = "two radicals and a denominator"
hamiltonian = "(p_x^2 + p_y^2 + p_z^2)/2 - k/r - k/s"
[phase_space]
coordinates = ["x", "y", "z"]
parameters = ["k", "a"]
radicals = { r = "x^2 + y^2 + z^2", s = "(x - a)^2 + y^2 + z^2" }
denominators = ["x^2 + y^2"]
""",
        s, [("x", "p_x"), ("y", "p_y"), ("z", "p_z")], [], atoms, points,
        [("p_z", "2*k"), ("p_x", "-p_y/3"), ("k", "p_y + 1"), ("p_y", "k*p_z")], extra)


def denominators_system(rng):
    s = symbols("x y z p_x p_y p_z g")
    points = []
    while len(points) < 40:
        p = {"x": Fraction(rng.randint(-9, 9), rng.randint(1, 4)),
             "y": Fraction(rng.randint(-9, 9), rng.randint(1, 5)),
             "z": Fraction(rng.randint(-9, 9), 3)}
        if p["x"] != p["y"] and p["y"] + 2 * p["z"] != 0 and p["x"] != 0 and p["y"] != 0:
            points.append(p)
    atoms = ["x", "y", "z", "p_x", "p_y", "p_z", "g", "1/(x - y)", "1/(y - x)^2",
             "1/(x - y)^3", "1/(x^2 + z^2 + 1)", "(x^2 + z^2 + 1)^-2", "1/((x - y)*(y + 2*z))",
             "(2*y + 4*z)^-2", "(x + p_y)^2", "1/x", "y^-2", "(x - y)^2"]
    return System(
        "denominators",
        """name = "declared denominators"
hamiltonian = "(p_x^2 + p_y^2 + p_z^2)/2 + g/(x - y)^2 + g/(x^2 + z^2 + 1)"
[phase_space]
coordinates = ["x", "y", "z"]
parameters = ["g"]
denominators = ["x - y", "x^2 + z^2 + 1", "y + 2*z"]
""",
        s, [("x", "p_x"), ("y", "p_y"), ("z", "p_z")], [], atoms, points,
        [("p_z", "3*g"), ("g", "p_x*p_y"), ("p_x", "p_y - 2"), ("p_y", "-1/2")])


CIRCLE = [(Fraction(3, 5), Fraction(4, 5)), (Fraction(-5, 13), Fraction(12, 13)),
          (Fraction(8, 17), Fraction(-15, 17)), (Fraction(7, 25), Fraction(-24, 25))]


def angles_system(rng):
    s = symbols("x y theta phi p_x p_y p_theta p_phi M omega")
    extra = {"i": sp.I, "I": sp.I, "cos": sp.cos, "sin": sp.sin, "exp": sp.exp,
             "conj": sp.conjugate, "re": sp.re, "im": sp.im}
    points = []
    for _ in range(40):
        (c1, s1), (c2, s2) = rng.choice(CIRCLE), rng.choice(CIRCLE)
        points.append({"x": Fraction(rng.randint(-5, 5), 2), "y": Fraction(rng.randint(-5, 5), 3),
                       "angles": (c1, s1, c2, s2)})
    atoms = ["x", "y", "p_x", "p_y", "p_theta", "p_phi", "M", "omega", "i", "1/M",
             "cos(theta)", "cos(2*theta)", "sin(theta - phi)", "sin(theta + 2*phi)",
             "exp(i*theta)", "exp(-2*i*phi)", "exp(i*(theta - phi))", "(x + i*y)^2",
             "cos(phi)^2", "conj(x + i*p_y)", "re(exp(i*theta))"]
    return System(
        "angles",
        """name = "two angles"
hamiltonian = "(p_x^2 + p_y^2)/(2*M) + M*omega^2*(x^2 + y^2)/2 + p_theta^2/2 + p_phi^2/2"
[phase_space]
coordinates = ["x", "y"]
angles = ["theta", "phi"]
parameters = ["M", "omega"]
""",
        s, [("x", "p_x"), ("y", "p_y"), ("theta", "p_theta"), ("phi", "p_phi")], [], atoms,
        points, [("p_theta", "2*M*omega/3"), ("p_phi", "p_theta - omega"), ("M", "omega^2"),
                 ("p_x", "-p_y")], extra)


def poisson_system():
    s = symbols("x p_x M1 M2 M3 g1 g2 g3 I1 I2")
    declared = []
    for i, j, k in ((1, 2, 3), (2, 3, 1), (3, 1, 2)):
        declared += [(f"M{i}", f"M{j}", f"M{k}"), (f"M{i}", f"g{j}", f"g{k}"),
                     (f"g{i}", f"M{j}", f"g{k}")]
    brackets = "\n".join(f'"{{{a}, {b}}}" = "{v}"' for a, b, v in declared)
    atoms = ["x", "p_x", "M1", "M2", "M3", "g1", "g2", "g3", "I1", "(M1 - g2)^2", "1/x", "1/I2",
             "x*M3"]
    return System(
        "poisson",
        f"""name = "e(3) beside a canonical pair"
hamiltonian = "M1^2/(2*I1) + M2^2/(2*I2) + M3^2/2 + x*p_x"
[phase_space]
coordinates = ["x"]
variables = ["M1", "M2", "M3", "g1", "g2", "g3"]
parameters = ["I1", "I2"]
[poisson]
{brackets}
""",
        s, [("x", "p_x")], declared, atoms, [{} for _ in range(10)],
        [("p_x", "I1*M3"), ("I2", "I1 + 1"), ("M3", "2"), ("g3", "M1 - g1")])


def monomials(variables, degree):
    """The monomials in `variables` of total degree at most `degree`, by degree."""
    return [sp.Mul(*[v**k for v, k in zip(variables, exps)])
            for total in range(degree + 1)
            for exps in itertools.product(range(total + 1), repeat=len(variables))
            if sum(exps) == total]


def is_square(n):
    return n >= 0 and math.isqrt(n) ** 2 == n


# ---------------------------------------------------------------------------------------------
# Random expressions and exact evaluation.


def random_rational(rng):
    n = rng.choice([1, 1, 1, 2, 3, 5, 7, 12, -1, -2, -3])
    d = rng.choice([1, 1, 1, 2, 3, 4])
    return str(n) if d == 1 else f"{n}/{d}"


def random_expression(rng, system):
    terms = []
    for _ in range(rng.randint(1, 4)):
        factors = [random_rational(rng)] + [rng.choice(system.atoms)
                                            for _ in range(rng.randint(0, 3))]
        terms.append("*".join(f"({f})" for f in factors))
    return " + ".join(terms)


def value_at(expr, system, point):
    """`expr` at `point`, exactly: the point's coordinates, a value for every other symbol
    fixed by its name and the point (so that two expressions get the same values), and the
    angles at the point's rational points of the circle."""
    seed = repr(sorted((k, str(v)) for k, v in point.items()))
    angles = point.get("angles")
    theta, phi = system.locals.get("theta"), system.locals.get("phi")
    subs = {}
    for sym in expr.free_symbols:
        name = str(sym)
        if name in point:
            subs[sym] = sp.Rational(point[name].numerator, point[name].denominator) \
                if isinstance(point[name], Fraction) else sp.Integer(point[name])
        elif sym not in (theta, phi):
            r = random.Random(seed + name)
            subs[sym] = sp.Rational(r.randint(-7, 7) or 1, r.randint(1, 4))
    e = expr.subs(subs)
    if angles is not None and e.free_symbols:
        c1, s1, c2, s2 = (sp.Rational(v.numerator, v.denominator) for v in angles)
        e = sp.expand_trig(sp.expand(e.rewrite(sp.cos)))
        e = e.subs({sp.cos(theta): c1, sp.sin(theta): s1, sp.cos(phi): c2, sp.sin(phi): s2})
    # A number now; a symbol left over makes the comparison fail, as it should.
    return sp.expand(e)


def superint_text(expr):
    """SymPy's printing of an expression, in superint's language."""
    text = sp.sstr(expr, order="none")
    return re.sub(r"\bI\b", "i", text.replace("**", "^"))


# ---------------------------------------------------------------------------------------------


def phase_variables(system):
    """The variables the rank's Jacobian takes: the canonical pairs, then the Poisson ones."""
    return [q for q, _ in system.pairs] + [p for _, p in system.pairs] + \
        [a for a in system.locals.values()
         if isinstance(a, sp.Symbol) and str(a) in {"M1", "M2", "M3", "g1", "g2", "g3"}]


def sympy_rank(functions, system, point):
    """The rank of the Jacobian of `functions` at `point`, by SymPy: at most the generic rank,
    and equal to it at a point off a proper subvariety."""
    variables = phase_variables(system)
    jacobian = sp.Matrix([[value_at(sp.diff(f, v), system, point) for v in variables]
                          for f in functions])
    return jacobian.rank()


def rank_case(binary, system, texts, rng):
    """`superint rank` of the functions `texts`: its certificate's minor recomputed by SymPy at
    its point (the lower bound), and SymPy's rank at that point and two random ones no larger
    (the upper bound). Returns (status, message)."""
    status, doc = run_json(binary, ["rank", system.file] + texts)
    if status != "ok":
        return status, doc
    found = doc["ranks"][0]
    functions = [system.read(t) for t in texts]
    point = {}
    angles = {}
    for entry in found["point"]:
        if "cos" in entry:
            angles[entry["variable"]] = (Fraction(entry["cos"]), Fraction(entry["sin"]))
        else:
            point[entry["variable"]] = Fraction(entry["value"])
    if angles:
        point["angles"] = angles["theta"] + angles["phi"]
    rank = found["rank"]
    if rank > 0:
        minor = found["minor"]
        rows = [functions[found["functions"].index(row)] for row in minor["rows"]]
        columns = [system.locals[c] for c in minor["columns"]]
        matrix = sp.Matrix([[value_at(sp.diff(f, v), system, point) for v in columns]
                            for f in rows])
        value = matrix.det()
        if value == 0 or value != sp.sympify(minor["value"], locals={"i": sp.I}):
            return "failed", (f"rank {rank}: the minor {minor} is {value} at the point by "
                              f"SymPy")
    ranks = [sympy_rank(functions, system, p)
             for p in [point] + rng.sample(system.points, min(2, len(system.points)))]
    if max(ranks) != rank:
        return "failed", f"superint's rank {rank}, SymPy's at three points {ranks}"
    return "ok", f"rank {rank}"


POTENTIALS = ["generic", "separable", "resonant", "central"]


def random_potential(rng, kind=None):
    """A polynomial potential in x, y of the kind given or drawn from `POTENTIALS`: generic,
    separable, an oscillator in resonance, or rotationally invariant (the last three with
    integrals beside H)."""
    c = lambda: random_rational(rng)
    kind = kind or rng.choice(POTENTIALS)
    if kind == "generic":
        terms = [f"({c()})*x^{a}*y^{b}" for a in range(4) for b in range(4 - a)
                 if a + b >= 2 and rng.random() < 0.4]
        return " + ".join(terms or ["x^2*y"])
    if kind == "separable":
        return f"({c()})*x^2 + ({c()})*x^{rng.randint(3, 4)} + ({c()})*y^{rng.randint(2, 4)}"
    if kind == "resonant":
        k = rng.randint(1, 3)
        return f"({c()})*(x^2 + {k * k}*y^2)"
    return f"({c()})*(x^2 + y^2) + ({c()})*(x^2 + y^2)^2"


class Plane:
    """The plane, x, y, p_x, p_y with parameters a, b: every expression a polynomial, no
    condition. With `Rotor`, the model of the functions a closure or a search is checked in."""

    def __init__(self):
        self.variables = list(sp.symbols("x y p_x p_y", real=True))
        self.parameters = dict(zip("ab", sp.symbols("a b", real=True)))
        self.locals = dict(zip(["x", "y", "p_x", "p_y"], self.variables), **self.parameters)
        x, y, px, py = self.variables
        self.pairs = [(x, px), (y, py)]

    def read(self, text):
        return sp.sympify(text.replace("^", "**"), locals=self.locals)

    def bracket(self, f, g):
        return sp.expand(sum(sp.diff(f, q) * sp.diff(g, p) - sp.diff(f, p) * sp.diff(g, q)
                             for q, p in self.pairs))

    def at(self, e):
        """`e` on the condition's surface."""
        return e

    def poly(self, e):
        """`e` as a polynomial in `variables` (one form for equal functions)."""
        return sp.expand(e)


class Rotor(Plane):
    """The plane and an angle θ with its momentum, each function written in `E = e^{iθ}` (a
    Laurent polynomial, times `E^shift` for a polynomial), at the condition `p_θ = value`."""

    def __init__(self, value, shift):
        """At `p_θ = value` (anywhere when None), polynomials times `E^shift`."""
        super().__init__()
        self.theta, self.p_theta, self.e = sp.symbols("theta p_theta E")
        self.variables += [self.p_theta, self.e]
        self.locals.update(theta=self.theta, p_theta=self.p_theta, i=sp.I, exp=sp.exp,
                           cos=sp.cos, sin=sp.sin)
        self.value = None if value is None else sp.Rational(value)
        self.shift = shift

    def read(self, text):
        e = super().read(text).rewrite(sp.exp)
        return sp.expand(e.subs(self.theta, -sp.I * sp.log(self.e)))

    def bracket(self, f, g):
        d_theta = lambda h: sp.I * self.e * sp.diff(h, self.e)
        return sp.expand(super().bracket(f, g) + d_theta(f) * sp.diff(g, self.p_theta)
                         - sp.diff(f, self.p_theta) * d_theta(g))

    def at(self, e):
        return e if self.value is None else sp.expand(e.subs(self.p_theta, self.value))

    def poly(self, e):
        return sp.expand(e * self.e**self.shift)


def search_found(binary, tmp, text, options):
    """`superint search` of the system file `text` with `options`: ("ok", (its unknowns, its
    dimension)), or ("refused" or "crashed", why)."""
    file = os.path.join(tmp, "search.toml")
    with open(file, "w") as out:
        out.write(text)
    status, doc = run_json(binary, ["search", file] + options, timeout=300)
    if status != "ok":
        return status, doc
    return "ok", (doc["searches"][0]["unknowns"], doc["searches"][0]["dimension"])


def search_verdict(found, expected, case):
    """("ok", …) when superint's (unknowns, dimension) `found` are SymPy's `expected`, else
    ("failed", …), `case` saying what was searched."""
    if found != expected:
        return "failed", (f"{case}: superint has {found[0]} unknowns and {found[1]} integrals, "
                          f"SymPy {expected[0]} and {expected[1]}")
    return "ok", f"{case}: {found[1]} integrals"


def plane_search(binary, tmp, potential, declaration, degrees, options):
    """`search_found` for `H = (p_x² + p_y²)/2 + potential` in the plane, the phase space
    declaring `declaration` (parameters, denominators, radicals) too, over the functions of
    `degrees` (in the momenta, in the positions), with `options` besides."""
    text = (f'name = "a particle in the plane"\n'
            f'hamiltonian = "(p_x^2 + p_y^2)/2 + {potential}"\n'
            f'[phase_space]\ncoordinates = ["x", "y"]\n{declaration}\n')
    return search_found(binary, tmp, text, ["--momenta-degree", str(degrees[0]),
                                            "--positions-degree", str(degrees[1])] + options)


def plane_hamiltonian(potential, symbols):
    """`(p_x² + p_y²)/2 + potential` read by SymPy in `symbols` (x, y, p_x, p_y and others)."""
    return sp.sympify(f"(p_x**2 + p_y**2)/2 + {potential.replace('^', '**')}", locals=symbols)


def sympy_search_dimension(h, momenta_degree, positions_degree, symbolic=(), s_degree=0,
                           laurent=False):
    """The dimension of the integrals of `h` among the polynomials of degree at most
    `momenta_degree` in p_x, p_y and `positions_degree` in x, y, by SymPy alone; with
    `symbolic` parameters, their coefficients polynomials of degree at most `s_degree` in
    them, and {F, H} zero for every value of them (a parameter's multiple counts apart); with
    `laurent`, `x^c y^d` for any integers with `|c| + |d|` at most `positions_degree`."""
    x, y, px, py = sp.symbols("x y p_x p_y", real=True)
    if laurent:
        n = positions_degree
        positions = [x**c * y**d for c in range(-n, n + 1) for d in range(-n, n + 1)
                     if abs(c) + abs(d) <= n]
    else:
        positions = monomials([x, y], positions_degree)
    space = [m * q * nu for m in monomials([px, py], momenta_degree) for q in positions
             for nu in monomials(list(symbolic), s_degree)]
    # A Laurent polynomial times x^k y^k, with k past every negative power, is a polynomial.
    k = positions_degree + 4 if laurent else 0
    def flow(f):
        return (sp.diff(f, x) * sp.diff(h, px) - sp.diff(f, px) * sp.diff(h, x)
                + sp.diff(f, y) * sp.diff(h, py) - sp.diff(f, py) * sp.diff(h, y)) * (x * y)**k
    return len(space), integrals_dimension(space, flow, [x, y, px, py] + list(symbolic))


def search_case(binary, tmp, rng):
    """`superint search` of a random potential, some of the time with parameters `a`, `b`
    in it kept symbolic: the dimension it reports, against SymPy's nullspace of {F, H} = 0
    over the same space. Returns (status, message)."""
    plane = Plane()
    potential = random_potential(rng)
    momenta_degree, positions_degree = rng.randint(1, 3), rng.randint(0, 3)
    options, symbolic, s_degree, laurent = [], (), 0, False
    draw = rng.random()
    if draw < 0.2:
        # Negative powers (`--laurent`): Smorodinsky–Winternitz I's β/x² + γ/y² beside an
        # oscillator (separable: each coordinate's energy is an integral), or random terms.
        laurent = True
        c = lambda: random_rational(rng)
        potential = rng.choice([f"({c()})*(x^2 + y^2) + ({c()})/x^2 + ({c()})/y^2",
                                f"({c()})*x^2 + ({c()})*x^-2 + ({c()})*y^2",
                                f"({c()})*x^-1*y + ({c()})*x^2*y^-2 + ({c()})*y^2"])
        momenta_degree, positions_degree = rng.randint(1, 2), rng.choice([1, 2, 2])
        options = ["--laurent"]
    elif draw < 0.45:
        # a·V₁ + b·V₂ of one kind: integrals for every a and b (L for central ones, the
        # energies of x and y for separable ones), their coefficients polynomials in them.
        kind = rng.choice(POTENTIALS)
        potential = f"a*({random_potential(rng, kind)}) + b*({random_potential(rng, kind)})"
        momenta_degree, positions_degree = rng.randint(1, 2), rng.randint(0, 4)
        s_degree = rng.randint(1, 2)
        symbolic = tuple(plane.parameters.values())
        options = ["--symbolic", "a,b", "--parameters-degree", str(s_degree)]
    status, found = plane_search(binary, tmp, potential, 'parameters = ["a", "b"]',
                                 (momenta_degree, positions_degree), options)
    if status != "ok":
        return status, found
    h = plane_hamiltonian(potential, plane.locals)
    expected = sympy_search_dimension(h, momenta_degree, positions_degree, symbolic, s_degree,
                                      laurent)
    return search_verdict(found, expected, f"V = {potential}, momenta degree {momenta_degree}, "
                          f"positions degree {positions_degree} {' '.join(options)}")


def functions_dimension(space, flow, canonical, variables):
    """For functions `space` that may be dependent, each written as a polynomial in `variables`
    by `canonical` (one form for equal functions), and `flow` giving that form of {F, H}: how
    many are independent, and the dimension of the integrals in their span (the combinations
    with {F, H} = 0, less those that are zero as functions)."""
    independent = rank_of([canonical(f) for f in space], variables)
    dependent = len(space) - independent
    return independent, integrals_dimension(space, flow, variables) - dependent


def denominator_search_case(binary, tmp, rng):
    """`superint search` of two particles on a line with a declared denominator `x − y`
    (Calogero's `g/(x − y)²`, a Coulomb `g/(x − y)`, with or without an oscillator): the
    unknowns (the functions `p^a x^c y^d/(x − y)^k` independent as functions) and dimension it
    reports, against SymPy's, which multiplies every function by a power of `x − y`. Returns
    (status, message)."""
    c = lambda: random_rational(rng)
    potential = " + ".join(rng.sample([f"({c()})/(x - y)^2", f"({c()})/(x - y)",
                                       f"({c()})*(x^2 + y^2)", f"({c()})*(x - y)^2"],
                                      rng.randint(1, 2)))
    degrees = rng.randint(1, 2), rng.randint(0, 2), rng.randint(1, 2)
    status, found = plane_search(binary, tmp, potential, 'denominators = ["x - y"]',
                                 degrees[:2], ["--denominators-degree", str(degrees[2])])
    if status != "ok":
        return status, found
    x, y, px, py = sp.symbols("x y p_x p_y")
    h = plane_hamiltonian(potential, {"x": x, "y": y, "p_x": px, "p_y": py})
    clear = (x - y)**(degrees[2] + 4)  # past the force's 1/(x − y)³ times f's lowest power
    canonical = lambda f: sp.expand(sp.cancel(f * clear))
    flow = lambda f: canonical(sp.diff(f, x) * sp.diff(h, px) - sp.diff(f, px) * sp.diff(h, x)
                               + sp.diff(f, y) * sp.diff(h, py) - sp.diff(f, py) * sp.diff(h, y))
    space = [m * q / (x - y)**k for m in monomials([px, py], degrees[0])
             for q in monomials([x, y], degrees[1]) for k in range(degrees[2] + 1)]
    expected = functions_dimension(space, flow, canonical, [x, y, px, py])
    return search_verdict(found, expected, f"V = {potential}, degrees (momenta, positions, "
                          f"denominators) {degrees}")


def radical_search_case(binary, tmp, rng):
    """`superint search` of a random central or near-central potential in the plane with the
    radical `r = √(x² + y²)` (Kepler's `−k/r`, `r`, `r²`, a dipole `x/r³`, an oscillator): the
    unknowns (the space's functions `p^a x^c y^d r^j` independent as functions) and the
    dimension it reports, against SymPy's, which writes every function as `A + B r` with
    polynomials `A`, `B` (times a power of `r` that clears the negative ones, `r²` reduced
    to `x² + y²`). Returns (status, message)."""
    c = lambda: random_rational(rng)
    terms = rng.sample([f"({c()})/r", f"({c()})*r", f"({c()})*r^2", f"({c()})*x/r^3",
                        f"({c()})*x^2", f"({c()})*y/r"], rng.randint(1, 2))
    potential = " + ".join(terms)
    degrees = rng.randint(1, 2), rng.randint(0, 2), rng.randint(1, 2)
    status, found = plane_search(binary, tmp, potential, 'radicals = { r = "x^2 + y^2" }',
                                 degrees[:2], ["--radicals-degree", str(degrees[2])])
    if status != "ok":
        return status, found
    x, y, px, py, r = sp.symbols("x y p_x p_y r", positive=True)
    h = plane_hamiltonian(potential, {"x": x, "y": y, "p_x": px, "p_y": py, "r": r})
    top = degrees[2] + 8  # past r^(−j−5): f's lowest power times a dipole force's
    def canonical(f):
        """`f·r^top` as `A + B r`: a polynomial of degree at most 1 in `r`."""
        f = sp.expand(f * r**top)
        return sp.rem(sp.Poly(f, r), sp.Poly(r**2 - x**2 - y**2, r)).as_expr()
    d = lambda f, v: sp.diff(f, v) + sp.diff(f, r) * v / r  # r depends on x and y
    flow = lambda f: canonical(d(f, x) * sp.diff(h, px) - sp.diff(f, px) * d(h, x)
                               + d(f, y) * sp.diff(h, py) - sp.diff(f, py) * d(h, y))
    space = [m * q * r**j for m in monomials([px, py], degrees[0])
             for q in monomials([x, y], degrees[1])
             for j in range(-degrees[2], degrees[2] + 1)]
    expected = functions_dimension(space, flow, canonical, [x, y, px, py, r])
    return search_verdict(found, expected, f"V = {potential}, degrees (momenta, positions, "
                          f"radicals) {degrees}")


PLANE = """name = "the plane"
hamiltonian = "(p_x^2 + p_y^2)/2 + a*(x^2 + y^2)/2"
[phase_space]
coordinates = ["x", "y"]
parameters = ["a", "b"]
"""


def random_generator(rng, parameters):
    """A polynomial in x, y, p_x, p_y of one to three terms, mostly quadratic (quadratic forms
    close under the bracket: sp(4)), sometimes with a linear, constant or cubic term; with
    `parameters`, some coefficients carry `a`, `b` or `a*b`."""
    quadratic = [f"{a}*{b}" for i, a in enumerate(["x", "y", "p_x", "p_y"])
                 for b in ["x", "y", "p_x", "p_y"][i:]]
    others = ["x", "y", "p_x", "p_y", "1", "x^2*p_y", "p_x^3", "x*y*p_y"]
    terms = [rng.choice(quadratic if rng.random() < 0.8 else others)
             for _ in range(rng.randint(1, 3))]
    return " + ".join(f"{random_coefficient(rng, parameters)}*{t}" for t in terms)


def random_coefficient(rng, parameters):
    """A rational, times a parameter monomial some of the time when `parameters`."""
    factor = rng.choice(["", "", "*a", "*b", "*a*b"]) if parameters else ""
    return f"({random_rational(rng)}{factor})"


def closure_case(binary, tmp, rng):
    """`superint closure` of two to five random generators, in the plane with parameters `a`,
    `b` (left at superint's values and lifted back, fixed, or kept symbolic) or without: every
    bracket its table writes as a polynomial in them is that bracket (SymPy expands both;
    for all values of the parameters unless superint says it holds at its values only), every
    bracket it marks `*` lies outside the span of the monomials in them (SymPy's rank), every
    relation it prints vanishes, and with their multiples (by polynomials in the generators
    within the degree, and in the symbolic parameters of degree at most theirs) they generate
    every relation up to the degrees (SymPy's nullspace). Returns (status, message)."""
    count, degree = rng.randint(2, 5), rng.randint(1, 3)
    names = [f"G{k + 1}" for k in range(count)]
    mode = rng.choice(["plain", "plain", "lifted", "fixed", "symbolic"])
    parameters = mode != "plain"
    if rng.random() < 0.3:
        # Combinations of u(2)'s quadratic forms: a Lie algebra (the table closes at degree 1)
        # with a Casimir (a relation at degree 2).
        u2 = ["x^2 + p_x^2", "y^2 + p_y^2", "x*y + p_x*p_y", "x*p_y - y*p_x"]
        texts = [" + ".join(f"{random_coefficient(rng, parameters)}*({f})"
                            for f in rng.sample(u2, rng.randint(1, 2))) for _ in names]
    else:
        texts = [random_generator(rng, parameters) for _ in names]
    file = os.path.join(tmp, "plane.toml")
    with open(file, "w") as out:
        out.write(PLANE)
    options = ["--degree", str(degree)]
    if mode == "fixed":
        options += ["--fix", f"a={rng.choice(['2', '-3', '1/2'])},b={rng.choice(['3', '-1/3'])}"]
    elif mode == "symbolic":
        degree = rng.randint(1, 2)
        options = ["--degree", str(degree), "--symbolic", "a,b", "--parameters-degree",
                   str(rng.randint(1, 2))]
    defines = [a for n, t in zip(names, texts) for a in ("--define", f"{n}={t}")]
    status, doc = run_json(binary, ["closure", file] + names + defines + options)
    if status != "ok":
        return status, doc
    case = f"generators {dict(zip(names, texts))}, {' '.join(options)}"
    failure = check_closure(doc, names, texts, degree, Plane())
    if failure:
        return "failed", f"{case}: {failure}"
    return "ok", f"{case}: agreed"


def rotor_closure_case(binary, tmp, rng):
    """`superint closure` of two to four generators of the rotor coupled to an oscillator of
    frequency w, at a resonance `p_θ = w·m/n` (`--when`): quadratic forms, `p_θ`, the
    resonant `K = (p_x + i w x)^m e^{−inθ}`, its conjugate and real parts, `cos θ`; checked as
    the plane's closures are (`check_closure`), on the surface. Returns (status, message)."""
    w = rng.choice(["1", "2"])
    m, n = rng.choice([(1, 1), (2, 1), (1, 2)])
    value = sp.Rational(w) * m / n
    pool = ["x*p_y - y*p_x", f"p_x^2 + {w}^2*x^2", f"p_y^2 + {w}^2*y^2",
            f"p_x*p_y + {w}^2*x*y", "p_theta", f"(p_x + i*{w}*x)^{m}*exp(-{n}*i*theta)",
            f"(p_x - i*{w}*x)^{m}*exp({n}*i*theta)", f"p_x*cos(theta) - {w}*x*sin(theta)",
            f"p_y*sin(theta) + {w}*y*cos(theta)", "cos(theta)"]
    count, degree = rng.randint(2, 4), rng.randint(1, 2)
    names = [f"G{k + 1}" for k in range(count)]
    texts = [f"({random_rational(rng)})*({t})" for t in rng.sample(pool, count)]
    file = os.path.join(tmp, "rotor-closure.toml")
    with open(file, "w") as out:
        out.write(f'name = "the rotor"\n'
                  f'hamiltonian = "(p_x^2 + p_y^2 + p_theta^2)/2 + ({w})^2*(x^2 + y^2)/2"\n'
                  f'[phase_space]\ncoordinates = ["x", "y"]\nangles = ["theta"]\n')
    defines = [a for name, t in zip(names, texts) for a in ("--define", f"{name}={t}")]
    options = ["--degree", str(degree), "--when", f"p_theta = {value}"]
    status, doc = run_json(binary, ["closure", file] + names + defines + options)
    if status != "ok":
        return status, doc
    case = f"generators {dict(zip(names, texts))}, {' '.join(options)}"
    failure = check_closure(doc, names, texts, degree, Rotor(value, 2 * degree + 6))
    if failure:
        return "failed", f"{case}: {failure}"
    return "ok", f"{case}: agreed"


def check_closure(doc, names, texts, degree, model):
    """What is wrong with superint's closure `doc` of the generators `names` = `texts` up to
    `degree`, in `model` (`Plane` or `Rotor`), by SymPy, or None."""
    gens = sp.symbols(" ".join(names))
    defined = [model.read(t) for t in texts]
    found = doc["closures"][0]
    fixed = {model.parameters[f["parameter"]]: sp.Rational(f["value"])
             for f in found["parameters"]["fixed"]}
    symbolic = [model.parameters[n] for n in found["parameters"]["symbolic"]]
    s_degree = found["parameters"]["symbolic_degree"] or 0
    # On the surface, at superint's values of the parameters, as a polynomial.
    at_values = lambda e: model.poly(model.at(sp.expand(e.subs(fixed))))
    in_gens = lambda text: sp.sympify(text.replace("^", "**"),
                                      locals=dict(zip(names, gens), i=sp.I, **model.parameters))
    # The condition applies to the generators, and after each bracket of them.
    on_surface = [model.at(d) for d in defined]
    expand = lambda e: sp.expand(e.subs(dict(zip(gens, on_surface))))
    gen_degree = lambda e: sp.Poly(e, *gens).total_degree()
    par_degree = lambda e: sp.Poly(e, *symbolic).total_degree() if symbolic else 0

    # The columns: monomials up to the degree in the generators that are not constants, times
    # monomials in the symbolic parameters up to theirs, expanded at superint's values of the
    # others. A generator that is constant on the surface enters as its value, and `G = c` is
    # a relation of its own.
    constants = [g for g, d in zip(gens, on_surface) if not d.free_symbols & set(model.variables)]
    varying = [g for g in gens if g not in constants]
    columns = [m * nu for m in monomials(varying, degree)
               for nu in monomials(symbolic, s_degree)]
    expanded = [at_values(expand(c)) for c in columns]
    space = model.variables + symbolic
    span = rank_of(expanded, space)
    if (found["monomials"], found["rank"]) != (len(columns), span):
        return (f"superint has {found['monomials']} monomials of rank {found['rank']}, SymPy "
                f"{len(columns)} of rank {span}")

    # The table, and the claims (a claim with a condition holds at superint's values only).
    claims = {c["id"]: c for c in doc["claims"]}
    general = {}
    for c in doc["claims"]:
        if c["ascii"].startswith("{"):
            general[c["ascii"].split(" = ")[0]] = c["condition_ascii"] is None
    lifted_table = found["unlifted"] == 0
    entries = doc["tables"][0]["entries"]
    outside = 0
    for i, j in itertools.product(range(len(names)), repeat=2):
        text = entries[i][j]["ascii"]
        theirs = model.at(model.bracket(defined[i], defined[j]))
        pair = f"{{{names[i]}, {names[j]}}}"
        if text is None:  # `*`: no expression, so one of the brackets said to be outside
            if [names[i], names[j]] not in found["outside"] and \
                    [names[j], names[i]] not in found["outside"]:
                return f"{pair} has no expression in the table, and is not said to be outside"
            outside += 1
            if rank_of(expanded + [at_values(theirs)], space) == span:
                return f"{pair} is marked outside, but SymPy writes it in the monomials"
            continue
        difference = expand(in_gens(text)) - theirs
        if at_values(difference) != 0:
            return f"{pair} = {text} is wrong" + (f" at {fixed}" if fixed else "")
        if general.get(pair, lifted_table) and sp.expand(difference) != 0:
            return f"{pair} = {text} is said for every value of the parameters, and is wrong"
    if found["closes"] != (outside == 0):
        return f"'closes' is {found['closes']} with {outside} brackets outside"

    # The relations: each vanishes (for every value of the parameters, unless it has a
    # condition) and is no zero polynomial. Those of the constants are one `G = c` each; the
    # others, with their multiples by monomials in the generators that stay within the degree
    # and in the symbolic parameters up to their degree (a product may pass it: `λ·R` and
    # `ω²·R'` may add up to a relation within it), span the nullspace of the columns'
    # expansions.
    multiples, of_constants = [], 0
    for rid in found["relations"]:
        claim = claims[rid]
        left, right = claim["ascii"].split(" = ")
        relation = in_gens(left) - in_gens(right)
        value = expand(relation)
        if relation == 0 or at_values(value) != 0 or \
                (claim["condition_ascii"] is None and sp.expand(value) != 0):
            return f"the relation {claim['ascii']} does not hold"
        if relation.free_symbols & set(constants):
            of_constants += 1
            continue
        relation = sp.expand(relation.subs(fixed))
        multiples += [sp.expand(m * nu * relation)
                      for m in monomials(varying, degree - gen_degree(relation))
                      for nu in monomials(symbolic, s_degree)]
    if of_constants != (len(constants) if degree >= 1 else 0):
        return f"{of_constants} relations of the constants {constants}"
    kernel = len(columns) - span
    # The nullspace as polynomials in the generators and the symbolic parameters.
    null = sp.Matrix(coefficient_vectors(expanded, space)).T.nullspace() if kernel else []
    relations = [sp.expand(sum(c * m for c, m in zip(v, columns))) for v in null]
    if len(relations) != kernel:
        return f"SymPy finds {len(relations)} dimensions of relations, not {kernel}"
    variables = varying + symbolic
    spanned = rank_of(multiples, variables) if multiples else 0
    if relations and rank_of(multiples + relations, variables) != spanned:
        return (f"the relations printed and their multiples do not generate the {kernel} "
                f"dimensions of relations")
    return None


def rank_of(polys, variables):
    """The rank of the polynomials `polys` in `variables`, as vectors of coefficients (over
    Q(i) when they have `i`)."""
    return sp.Matrix(coefficient_vectors(polys, variables)).rank()


def random_coupling(rng):
    """A potential of x, y and an angle θ: none, the rotation-invariant `x cos θ + y sin θ`
    (with H's oscillator, `L + p_θ` is an integral), or random terms `c x^a y^b cos kθ`
    and `sin kθ`."""
    kind = rng.choice(["none", "invariant", "random", "random"])
    if kind == "none":
        return "0"
    if kind == "invariant":
        c = random_rational(rng)
        return f"({c})*(x*cos(theta) + y*sin(theta))"
    terms = []
    for _ in range(rng.randint(1, 2)):
        a, b = rng.randint(0, 2), rng.randint(0, 1)
        trig = rng.choice(["cos", "sin"])
        terms.append(f"({random_rational(rng)})*x^{a}*y^{b}*{trig}({rng.randint(1, 2)}*theta)")
    return " + ".join(terms)


def sympy_angle_search_dimension(h_text, momenta_degree, positions_degree, trig_degree,
                                 when=None):
    """The dimension of the integrals of `h_text` (in x, y, θ and their momenta) among the
    functions `p^a x^b cos kθ` and `p^a x^b sin kθ` of degree at most `momenta_degree` in
    the momenta, `positions_degree` in x, y and `k <= trig_degree`, by SymPy alone: with
    `E = e^{iθ}`, `{F, H}` is a Laurent polynomial in `E` whose coefficients, real and
    imaginary parts apart, are linear equations over Q in the real unknowns. With `when`, a
    value of p_θ: the functions are free of p_θ, and `{F, H}` vanishes at that value."""
    model = Rotor(when, trig_degree + 3)  # Laurent in E: shifted to a polynomial
    x, y, px, py, pt, e = model.variables
    h = model.read(h_text)
    waves = [sp.Integer(1)] + [w for k in range(1, trig_degree + 1)
                               for w in ((e**k + e**-k) / 2, (e**k - e**-k) / (2 * sp.I))]
    momenta = [px, py] if when is not None else [px, py, pt]
    space = [m * q * w for m in monomials(momenta, momenta_degree)
             for q in monomials([x, y], positions_degree) for w in waves]
    flow = lambda f: model.poly(model.at(model.bracket(f, h)))
    return len(space), integrals_dimension(space, flow, model.variables)


def angle_search_case(binary, tmp, rng):
    """`superint search` of a random H with an angle: the number of unknowns and the dimension
    it reports, against SymPy's count of the space and nullspace of {F, H} = 0 over it.
    Returns (status, message)."""
    potential, coupling = random_potential(rng), random_coupling(rng)
    when = None
    if rng.random() < 0.4:
        # At a value of p_θ (`--when`, the path of the resonances): for the oscillator of
        # frequency w, at p_θ = w·m/n the integrals Z^m e^{−inθ} appear.
        w = rng.choice(["1", "2", "1/2"])
        potential = f"({w})^2*(x^2 + y^2)/2"
        coupling = rng.choice(["0", "0", "0", "0", coupling])  # else refused: p_θ moves
        when = str(sp.Rational(w) * sp.Rational(rng.choice(["1", "2", "1/2", "3/2", "1/3"])))
    h = f"(p_x^2 + p_y^2 + p_theta^2)/2 + {potential} + {coupling}"
    degrees = rng.randint(1, 2), rng.randint(0, 2), rng.randint(0, 2)
    text = (f'name = "random rotor"\nhamiltonian = "{h}"\n'
            f'[phase_space]\ncoordinates = ["x", "y"]\nangles = ["theta"]\n')
    status, found = search_found(binary, tmp, text, [
        "--momenta-degree", str(degrees[0]), "--positions-degree", str(degrees[1]),
        "--trig-degree", str(degrees[2])] + (["--when", f"p_theta = {when}"] if when else []))
    if status != "ok":
        return status, found
    expected = sympy_angle_search_dimension(h, *degrees, when)
    at = f" at p_θ = {when}" if when else ""
    return search_verdict(found, expected, f"H = {h}{at}, degrees (momenta, positions, trig) "
                          f"{degrees}")


E3 = {("M1", "M2"): "M3", ("M2", "M3"): "M1", ("M3", "M1"): "M2",
      ("M1", "g2"): "g3", ("M1", "g3"): "-g2", ("M2", "g3"): "g1", ("M2", "g1"): "-g3",
      ("M3", "g1"): "g2", ("M3", "g2"): "-g1"}


def top_search_case(binary, tmp, rng):
    """`superint search` of a random top on so(3)* or e(3)* (a quadratic form in M, plus a
    linear and sometimes a quadratic one in γ on e(3)*, some with symmetry): the dimension of its
    polynomial integrals of degree at most d in the Poisson variables, against SymPy's
    (`search_dimensions.dimension`). Returns (status, message)."""
    e3 = rng.random() < 0.7
    names = ["M1", "M2", "M3"] + (["g1", "g2", "g3"] if e3 else [])
    pairs = {k: v for k, v in E3.items() if all(n in names for n in k)}
    c = lambda: random_rational(rng)
    inertia = [c() for _ in range(3)]
    if rng.random() < 0.4:
        inertia[1] = inertia[0]  # symmetric: M3 is an integral (with γ along the axis)
    terms = [f"({i})*M{k + 1}^2" for k, i in enumerate(inertia)]
    if rng.random() < 0.3:
        terms.append(f"({c()})*M1*M2")
    if e3:
        terms.append(rng.choice([f"({c()})*g3", f"({c()})*g1", f"({c()})*g1 + ({c()})*g2"]))
        if rng.random() < 0.3:
            terms.append(f"({c()})*g3^2")
    h = " + ".join(terms)
    degree = rng.randint(1, 4 if not e3 else 3)
    brackets = "\n".join(f'"{{{a}, {b}}}" = "{v}"' for (a, b), v in pairs.items())
    text = (f'name = "random top"\nhamiltonian = "{h}"\n[phase_space]\n'
            f'variables = {json.dumps(names)}\n[poisson]\n{brackets}\n')
    status, found = search_found(binary, tmp, text, ["--poisson-degree", str(degree)])
    if status != "ok":
        return status, found
    variables = sp.symbols(" ".join(names))
    local = dict(zip(names, variables))
    table = antisymmetric({(local[a], local[b]): sp.sympify(v, locals=local)
                           for (a, b), v in pairs.items()})
    expected = (len(monomials(variables, degree)),
                dimension(variables, table, sp.sympify(h.replace("^", "**"), locals=local),
                          degree))
    return search_verdict(found, expected, f"H = {h} on {'e(3)*' if e3 else 'so(3)*'}, "
                          f"degree {degree}")


def run_json(binary, args, timeout=120):
    """superint's JSON report for `args`: ("ok", the report), ("refused", its message) on exit
    code 2 without a panic, or ("crashed", what happened)."""
    r = subprocess.run([binary] + args + ["--format", "json", "--no-timings"],
                       capture_output=True, text=True, timeout=timeout)
    if r.returncode == 0:
        return "ok", json.loads(r.stdout)
    if r.returncode == 2 and "panicked" not in r.stderr:
        return "refused", r.stderr.strip().splitlines()[0] if r.stderr.strip() else ""
    return "crashed", f"exit code {r.returncode}: {r.stderr.strip()[:400]}"


def run_superint(binary, args):
    """The ASCII form of the first equation `args` prints (or why there is none)."""
    status, doc = run_json(binary, args)
    return (status, doc["equations"][0]["lines"][0]["ascii"]) if status == "ok" else (status, doc)


# The operations that draw their own system: each case's function and the name it is counted
# under.
ALONE = {
    "search": (search_case, "searches of random potentials"),
    "search with an angle": (angle_search_case, "searches of rotors"),
    "search of a top": (top_search_case, "searches of tops"),
    "search with a radical": (radical_search_case, "searches with a radical"),
    "search with a denominator": (denominator_search_case, "searches with a denominator"),
    "closure": (closure_case, "closures of random generators"),
    "closure at a resonance": (rotor_closure_case, "closures at a resonance"),
}


class Outcome:
    """What one case came to: its count ("compared", "refused", "too long for SymPy" or
    "failed"), the kind it is counted under when compared, and the lines it prints."""

    def __init__(self):
        self.count, self.kind, self.lines = None, None, []

    def end(self, count, kind=None, line=None):
        self.count, self.kind = count, kind
        if line is not None:
            self.lines.append(line)
        return self


def run_case(n, seed, superint, systems, tmp, verbose):
    """Case `n`: its own random generator (from the seed and `n`, so that a case is the same
    whatever the number of jobs) and its own directory for the files it writes."""
    rng = random.Random(f"{seed}:{n}")
    case_dir = os.path.join(tmp, f"case-{n}")
    os.mkdir(case_dir)
    outcome = Outcome()

    def fail(case, why):
        return outcome.end("failed", line=f"FAILED ({case}): {why}")

    def tally(status, message, case, kind):
        """A rank's or a search's outcome, `kind` the system's name or `searches`."""
        line = f"{status} ({case}): {message}" if verbose else None
        if status == "ok":
            return outcome.end("compared", kind, line)
        if status == "refused":
            return outcome.end("refused", line=line)
        return fail(case, message)

    system = rng.choice(systems)
    f_text, g_text = random_expression(rng, system), random_expression(rng, system)
    op = rng.choice(["bracket", "bracket", "bracket at a condition", "product", "power",
                     "rank", "search", "search with an angle", "search of a top",
                     "search with a radical", "search with a denominator", "closure",
                     "closure at a resonance"])
    if op in ALONE:
        run, kind = ALONE[op]
        status, message = run(superint, case_dir, rng)
        return tally(status, message, f"case {n}: a {op}", kind)
    if op == "rank":
        # Two to four functions, some of them functions of the others.
        texts = [f_text, g_text] + rng.sample(
            [f"({f_text})*({g_text})", f"({f_text})^2 - 3*({g_text})",
             random_expression(rng, system)], rng.randint(0, 2))
        status, message = rank_case(superint, system, texts, rng)
        return tally(status, message, f"case {n}, {system.name}: the rank of {texts}",
                     system.name)
    when = []
    if op.startswith("bracket"):
        given = f"{{{f_text}, {g_text}}}"
        if op == "bracket at a condition":
            variable, value = rng.choice(system.conditions)
            when = ["--when", f"{variable} = {value}"]
        status, out = run_superint(superint, ["bracket", system.file, f_text, g_text] + when)
    elif op == "product":
        given = f"({f_text})*({g_text})"
        status, out = run_superint(superint, ["expand", system.file, given])
    else:
        power = rng.randint(2, 3)
        given = f"({f_text})^{power}"
        status, out = run_superint(superint, ["expand", system.file, given])
    case = f"case {n}, {system.name}: {given}"
    if status == "crashed":
        return fail(case, out)
    if status == "refused":
        return outcome.end("refused", line=f"refused ({case}): {out}" if verbose else None)
    try:
        ours = system.read(out)
    except RecursionError:
        # Python's compiler nests a long sum one level a term: SymPy cannot read it.
        return outcome.end("too long for SymPy", line=(
            f"too long for SymPy ({case}): {len(out)} characters" if verbose else None))
    f, g = system.read(f_text), system.read(g_text)
    if op.startswith("bracket"):
        theirs = system.bracket(f, g)
        if when:
            variable, value = when[1].split(" = ")
            theirs = theirs.subs(system.read(variable), system.read(value))
    else:
        theirs = system.read(given)
    # 1. superint's printed result equals SymPy's at exact points.
    points = rng.sample(system.points, min(3, len(system.points)))
    for point in points:
        a, b = value_at(ours, system, point), value_at(theirs, system, point)
        if a != b:
            return fail(case, f"superint printed {out}\n  at {point}: {a}, SymPy {b}")
    # 2. SymPy's result, as text, is a zero difference for superint; 3. a wrong one is
    # refuted.
    reference = superint_text(theirs)
    difference = f"{given} - ({reference})"
    status, zero = run_superint(superint, ["expand", system.file, difference] + when)
    if status != "ok" or zero != "0":
        return fail(case, f"{given} − (SymPy's {reference}) is {zero} ({status}), not 0")
    # A wrong term of the system's atoms, or a constant where the condition cannot be
    # substituted into that atom (`1/I2` at `I2 = I1 + 1`).
    for extra in (f"({rng.choice(system.atoms)})", "1"):
        wrong = f"{difference} + {rng.choice(['1/7', '2', '-3/2'])}*{extra}"
        status, residual = run_superint(superint, ["expand", system.file, wrong] + when)
        if status != "refused":
            break
    if status != "ok" or residual == "0":
        return fail(case, f"a wrong result was not refuted: {wrong} gave {residual} ({status})")
    # 4. The same as a user states it: F and G as functions of the file, the right claim
    # proved and the wrong one refuted, as expected.
    named = {"bracket": "{F, G}", "bracket at a condition": "{F, G}",
             "product": "F*G", "power": f"F^{power}" if op == "power" else ""}[op]
    condition = f'when = "{when[1]}"\n' if when else ""
    claims = (f'{system.toml}\n[[function]]\nname = "F"\nvalue = "{f_text}"\n'
              f'[[function]]\nname = "G"\nvalue = "{g_text}"\n'
              f'[[claim]]\nid = "right"\nclaim = "{named} = {reference}"\n{condition}'
              f'[[claim]]\nid = "wrong"\nclaim = "{named} = {reference} + '
              f'{wrong[len(difference) + 3:]}"\n{condition}expect = "refuted"\n')
    claims_file = os.path.join(case_dir, "claims.toml")
    with open(claims_file, "w") as f_out:
        f_out.write(claims)
    r = subprocess.run([superint, "check", claims_file, "--no-timings"],
                       capture_output=True, text=True, timeout=120)
    if r.returncode != 0 or "all as expected" not in r.stdout:
        return fail(case, f"the claims were not as expected (exit code {r.returncode}):\n"
                          f"{claims}\n{r.stdout[-800:]}{r.stderr[:800]}")
    return outcome.end("compared", system.name, f"agreed ({case})" if verbose else None)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cases", type=int, default=400)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--superint", default=os.environ.get(
        "SUPERINT_BIN", os.path.join(ROOT, "target", "release", "superint")))
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                    help="cases run at once, each in its own process (default: the cores)")
    ap.add_argument("--verbose", action="store_true")
    args = ap.parse_args()
    rng = random.Random(args.seed)  # the systems; each case has its own
    systems = [radicals_system(), denominators_system(rng), angles_system(rng), poisson_system()]
    tmp = tempfile.mkdtemp(prefix="superint-crosscheck-")
    for system in systems:
        system.file = os.path.join(tmp, f"{system.name}.toml")
        with open(system.file, "w") as f:
            f.write(system.toml)

    counts = {"compared": 0, "refused": 0, "failed": 0, "too long for SymPy": 0}
    by_kind = {s.name: 0 for s in systems}
    by_kind.update((kind, 0) for _, kind in ALONE.values())

    # Forked workers inherit the systems; each case draws from its own generator, so the
    # cases and the summary are the same for any number of jobs, printed in case order.
    work = functools.partial(run_case, seed=args.seed, superint=args.superint,
                             systems=systems, tmp=tmp, verbose=args.verbose)
    with multiprocessing.get_context("fork").Pool(args.jobs) as pool:
        for outcome in pool.imap(work, range(args.cases)):
            counts[outcome.count] += 1
            if outcome.count == "compared":
                by_kind[outcome.kind] += 1
            for line in outcome.lines:
                print(line, flush=True)
    systems_line = ", ".join(f"{k} {v}" for k, v in by_kind.items())
    print(f"crosscheck against SymPy {sp.__version__}: {args.cases} cases (seed {args.seed}): "
          f"{counts['compared']} agreed ({systems_line}), {counts['refused']} refused with a "
          f"message, {counts['too long for SymPy']} results too long for SymPy to read, "
          f"{counts['failed']} failed")
    sys.exit(1 if counts["failed"] else 0)


if __name__ == "__main__":
    main()
