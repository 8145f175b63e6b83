"""The dimensions `superint search` finds on the Lie-Poisson tops (docs/results.md, section 9),
found again by SymPy on its own: the polynomial integrals of degree <= d of a Lie-Poisson
system are the solutions of the linear system {F, H} = 0 for a generic F of that degree, whose
dimension is the number of coefficients less the rank.

    python search_dimensions.py

Prints one line a case (the Euler top at I = (1, 2, 3), degrees 2 to 4: 3, 3, 6; the heavy top
with c = 1 at I3 = 1/2, the Kovalevskaya top, and at I3 = 1/3, degree 4: 11, 10). Not a
benchmark: a check by another program (some ten seconds).
"""
import itertools

import sympy as sp


def bracket(f, g, variables, table):
    """{f, g} = sum over a, b of {a, b} df/da dg/db."""
    return sp.expand(sum(table.get((a, b), 0) * sp.diff(f, a) * sp.diff(g, b)
                         for a in variables for b in variables))


def antisymmetric(pairs):
    table = {}
    for (a, b), value in pairs.items():
        table[(a, b)] = value
        table[(b, a)] = -value
    return table


def coefficient_vectors(polys, variables):
    """Each of the polynomials `polys` in `variables` as its coefficients on the monomials
    that occur in any of them. Also used by crosscheck.py."""
    table = [sp.Poly(sp.expand(p), *variables).as_dict() for p in polys]
    keys = sorted({k for t in table for k in t})
    return [[t.get(k, 0) for k in keys] for t in table]


def integrals_dimension(space, flow, variables):
    """The dimension of the combinations F of the functions `space` with real coefficients and
    flow(F) = {F, H} = 0: how many they are, less the rank of the linear map from their
    coefficients to those of flow(F), a polynomial in `variables` (its coefficients may be
    Gaussian rationals: their real and imaginary parts are equations apart). The flow is
    linear, so each function's image is a column. Also used by crosscheck.py."""
    from sympy.polys.matrices import DomainMatrix
    columns = coefficient_vectors([flow(m) for m in space], variables)
    width = len(columns[0]) if columns else 0
    rows = [[part(c[k]) for c in columns] for k in range(width) for part in (sp.re, sp.im)]
    rows = [row for row in rows if any(row)]
    if not rows:
        return len(space)
    matrix = DomainMatrix.from_list_sympy(len(rows), len(space), rows).convert_to(sp.QQ)
    return len(space) - matrix.rank()


def dimension(variables, table, h, degree):
    """The dimension of the integrals of degree <= degree."""
    monomials = [sp.Mul(*[v**e for v, e in zip(variables, exponents)])
                 for exponents in itertools.product(range(degree + 1), repeat=len(variables))
                 if sum(exponents) <= degree]
    return integrals_dimension(monomials, lambda f: bracket(f, h, variables, table), variables)


def main():
    M1, M2, M3, g1, g2, g3 = sp.symbols("M1 M2 M3 gamma1 gamma2 gamma3")
    so3 = {(M1, M2): M3, (M2, M3): M1, (M3, M1): M2}
    e3 = dict(so3)
    e3.update({(M1, g2): g3, (M1, g3): -g2, (M2, g3): g1, (M2, g1): -g3,
               (M3, g1): g2, (M3, g2): -g1})

    euler = M1**2 / 2 + M2**2 / 4 + M3**2 / 6
    for d in (2, 3, 4):
        print(f"Euler top, I = (1, 2, 3), degree <= {d}:",
              dimension([M1, M2, M3], antisymmetric(so3), euler, d))
    for i3 in (sp.Rational(1, 2), sp.Rational(1, 3)):
        heavy = (M1**2 + M2**2) / 2 + M3**2 / (2 * i3) - g1
        print(f"heavy top, I3 = {i3}, c = 1, degree <= 4:",
              dimension([M1, M2, M3, g1, g2, g3], antisymmetric(e3), heavy, 4), flush=True)


if __name__ == "__main__":
    main()
