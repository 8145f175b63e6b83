//! Rejected inputs: each with its exact message, its (line, column) and the caret rendering.

use pretty_assertions::assert_eq;
use trigpoly::{Coefficient, GaussianRational, Poly, Rational, Vars};

use crate::common::phase_space;

/// Over which field an input is parsed.
#[derive(Clone, Copy, Debug)]
enum Field {
    Q,
    Qi,
}

struct Case {
    field: Field,
    src: &'static str,
    message: &'static str,
    line_col: (usize, usize),
    /// The whole rendering: location, message, source line, carets.
    render: &'static str,
}

const KNOWN: &str = "x, y, p_x, p_y, theta, phi, M, omega";

fn cases() -> Vec<Case> {
    use Field::{Qi, Q};
    let case = |field, src, message, line_col, render| Case {
        field,
        src,
        message,
        line_col,
        render,
    };
    vec![
        case(Qi, "1/0", "division by zero", (1, 3), "line 1, column 3: division by zero\n  1/0\n    ^"),
        case(
            Qi,
            "x^",
            "expected an expression after '^', found end of input",
            (1, 3),
            "line 1, column 3: expected an expression after '^', found end of input\n  x^\n    ^",
        ),
        case(
            Qi,
            "cos(x",
            "expected ')' to close '(' opened at column 4, found end of input",
            (1, 6),
            "line 1, column 6: expected ')' to close '(' opened at column 4, found end of input\n  cos(x\n       ^",
        ),
        case(
            Q,
            "x/(1+x)",
            "cannot divide by x + 1: only division by a nonzero constant, a single term (monomial) or a product of powers of declared denominators is exact here; declare it (or its factors) as a denominator: denominators = [\"x + 1\"] in [phase_space]",
            (1, 3),
            "line 1, column 3: cannot divide by x + 1: only division by a nonzero constant, a single \
             term (monomial) or a product of powers of declared denominators is exact here; \
             declare it (or its factors) as a denominator: denominators = [\"x + 1\"] in \
             [phase_space]\n  x/(1+x)\n    ^^^^^",
        ),
        // A divisor that is not real cannot be declared: the message names its real norm.
        case(
            Qi,
            "x/(p_x + i*x)",
            "cannot divide by p_x + ix: only division by a nonzero constant, a single term \
             (monomial) or a product of powers of declared denominators is exact here; it is not \
             real, so it cannot be declared (a denominator is real): write 1/D as \
             conj(D)/(D conj(D)) and declare the real D conj(D): denominators = \
             [\"p_x^2 + x^2\"] in [phase_space]",
            (1, 3),
            "line 1, column 3: cannot divide by p_x + ix: only division by a nonzero constant, a \
             single term (monomial) or a product of powers of declared denominators is exact \
             here; it is not real, so it cannot be declared (a denominator is real): write 1/D \
             as conj(D)/(D conj(D)) and declare the real D conj(D): denominators = \
             [\"p_x^2 + x^2\"] in [phase_space]\n  x/(p_x + i*x)\n    ^^^^^^^^^^^",
        ),
        case(
            Q,
            "2^(1/3)",
            "exponents must be integers or halves of odd integers (a power of a declared radical, \
             (x^2 + y^2)^(3/2) for r^3), found 1/3 (other fractional powers are not polynomial)",
            (1, 3),
            "line 1, column 3: exponents must be integers or halves of odd integers (a power of a \
             declared radical, (x^2 + y^2)^(3/2) for r^3), found 1/3 (other fractional powers are \
             not polynomial)\n  2^(1/3)\n    ^^^^^",
        ),
        case(
            Q,
            "2^(1/2)",
            "sqrt(2) is not a rational number: write the root as a parameter",
            (1, 1),
            "line 1, column 1: sqrt(2) is not a rational number: write the root as a parameter\n  \
             2^(1/2)\n  ^^^^^^^",
        ),
        case(
            Qi,
            "exp(i*theta/2)",
            "exp takes i times an integer combination of angles, such as exp(i*(2*theta - phi))",
            (1, 5),
            "line 1, column 5: exp takes i times an integer combination of angles, such as \
             exp(i*(2*theta - phi))\n  exp(i*theta/2)\n      ^^^^^^^^^",
        ),
        case(
            Qi,
            "x + q*y",
            "unknown name 'q' (known: x, y, p_x, p_y, theta, phi, M, omega)",
            (1, 5),
            "line 1, column 5: unknown name 'q' (known: x, y, p_x, p_y, theta, phi, M, omega)\n  \
             x + q*y\n      ^",
        ),
        // One slip away from one known name: two neighbours swapped, a letter added.
        case(
            Qi,
            "M*omgea^2",
            "unknown name 'omgea'; did you mean 'omega'? (known: x, y, p_x, p_y, theta, phi, M, \
             omega)",
            (1, 3),
            "line 1, column 3: unknown name 'omgea'; did you mean 'omega'? (known: x, y, p_x, \
             p_y, theta, phi, M, omega)\n  M*omgea^2\n    ^^^^^",
        ),
        case(
            Qi,
            "thetta + x",
            "unknown name 'thetta'; did you mean 'theta'? (known: x, y, p_x, p_y, theta, phi, M, \
             omega)",
            (1, 1),
            "line 1, column 1: unknown name 'thetta'; did you mean 'theta'? (known: x, y, p_x, \
             p_y, theta, phi, M, omega)\n  thetta + x\n  ^^^^^^",
        ),
        // One slip away from two, p_x and p_y: no guess.
        case(
            Qi,
            "p_z",
            "unknown name 'p_z' (known: x, y, p_x, p_y, theta, phi, M, omega)",
            (1, 1),
            "line 1, column 1: unknown name 'p_z' (known: x, y, p_x, p_y, theta, phi, M, omega)\n  \
             p_z\n  ^^^",
        ),
        case(
            Qi,
            "sni(theta)",
            "unknown function 'sni' (known: cos, sin, exp, conj, Re, Im, sqrt); did you mean 'sin'?",
            (1, 1),
            "line 1, column 1: unknown function 'sni' (known: cos, sin, exp, conj, Re, Im, sqrt); did \
             you mean 'sin'?\n  sni(theta)\n  ^^^",
        ),
        // A function written without its parentheses, as a paper writes the real part, is
        // told so, not listed among unknown names ('Re' was "unknown name 'Re' (known: …)").
        case(
            Qi,
            "Re M + 1",
            "'Re' is the real part, a function: write its argument in parentheses, Re(…)",
            (1, 1),
            "line 1, column 1: 'Re' is the real part, a function: write its argument in \
             parentheses, Re(…)\n  Re M + 1\n  ^^",
        ),
        // Raised to a power before its parentheses, as `cos²(θ)` is written, it is told where
        // the power goes ('Re²(x)' was told to write the parentheses it had).
        case(
            Qi,
            "2 + Re²(x)",
            "'Re' is the real part, a function: write its argument in parentheses and the power \
             after them, Re(…)^2",
            (1, 5),
            "line 1, column 5: 'Re' is the real part, a function: write its argument in \
             parentheses and the power after them, Re(…)^2\n  2 + Re²(x)\n      ^^",
        ),
        case(
            Qi,
            "conj^3 x",
            "'conj' is the complex conjugate, a function: write its argument in parentheses and \
             the power after them, conj(…)^3",
            (1, 1),
            "line 1, column 1: 'conj' is the complex conjugate, a function: write its argument \
             in parentheses and the power after them, conj(…)^3\n  conj^3 x\n  ^^^^",
        ),
        // A bar over a known name, as a paper writes the conjugate, is told how to write it
        // ('ȳ' was "unknown name 'ȳ' (known: …)", 'x̄' "unexpected character '\u{304}'").
        case(
            Qi,
            "x*ȳ",
            "unknown name 'ȳ': the complex conjugate of y is written conj(y)",
            (1, 3),
            "line 1, column 3: unknown name 'ȳ': the complex conjugate of y is written \
             conj(y)\n  x*ȳ\n    ^",
        ),
        case(
            Qi,
            "\\bar{y} + 1",
            "unknown name 'y\u{304}': the complex conjugate of y is written conj(y)",
            (1, 1),
            "line 1, column 1: unknown name 'y\u{304}': the complex conjugate of y is written \
             conj(y)\n  \\bar{y} + 1\n  ^^^^^^^",
        ),
        // A combining bar says the call of the name it stands in, as a barred name does ('M̄'
        // said "the complex conjugate of A is conj(A)", of a name A never written); its column
        // counts characters, past a multi-byte one; over a number or parentheses, `conj(A)`.
        // A bar over the letter before a subscript, as LaTeX writes it, names the name too
        // ('p̄_x' was "unknown name 'p̄_x' (known: …)").
        case(
            Qi,
            "\\bar{p}_{x} + 1",
            "unknown name 'p\u{304}_x': the complex conjugate of p_x is written conj(p_x)",
            (1, 1),
            "line 1, column 1: unknown name 'p\u{304}_x': the complex conjugate of p_x is \
             written conj(p_x)\n  \\bar{p}_{x} + 1\n  ^^^^^^^^^^^",
        ),
        case(
            Qi,
            "M\u{304}",
            "unexpected character '\\u{304}'; a bar is no operation: the complex conjugate of M \
             is written conj(M)",
            (1, 2),
            "line 1, column 2: unexpected character '\\u{304}'; a bar is no operation: the \
             complex conjugate of M is written conj(M)\n  M\u{304}\n   ^",
        ),
        case(
            Qi,
            "ω*2x\u{304}_1",
            "unexpected character '\\u{304}'; a bar is no operation: the complex conjugate of \
             x_1 is written conj(x_1)",
            (1, 5),
            "line 1, column 5: unexpected character '\\u{304}'; a bar is no operation: the \
             complex conjugate of x_1 is written conj(x_1)\n  ω*2x\u{304}_1\n      ^",
        ),
        case(
            Qi,
            "(x + y)\u{304}",
            "unexpected character '\\u{304}'; a bar is no operation: the complex conjugate of A \
             is conj(A)",
            (1, 8),
            "line 1, column 8: unexpected character '\\u{304}'; a bar is no operation: the \
             complex conjugate of A is conj(A)\n  (x + y)\u{304}\n         ^",
        ),
        case(
            Qi,
            "x*conj y",
            "'conj' is the complex conjugate, a function: write its argument in parentheses, \
             conj(…)",
            (1, 3),
            "line 1, column 3: 'conj' is the complex conjugate, a function: write its argument \
             in parentheses, conj(…)\n  x*conj y\n    ^^^^",
        ),
        case(
            Q,
            "x^100000",
            "the exponent 100000 is past the limit of 1000",
            (1, 3),
            "line 1, column 3: the exponent 100000 is past the limit of 1000\n  x^100000\n    ^^^^^^",
        ),
        case(
            Qi,
            "theta",
            "theta is an angle: functions depend on it through cos(theta), sin(theta) or exp(i*k*theta)",
            (1, 1),
            "line 1, column 1: theta is an angle: functions depend on it through cos(theta), \
             sin(theta) or exp(i*k*theta)\n  theta\n  ^^^^^",
        ),
        case(
            Qi,
            "2*θ",
            "θ is an angle: functions depend on it through cos(theta), sin(theta) or exp(i*k*theta)",
            (1, 3),
            "line 1, column 3: θ is an angle: functions depend on it through cos(theta), sin(theta) \
             or exp(i*k*theta)\n  2*θ\n    ^",
        ),
        case(
            Qi,
            "sin(x)",
            "'x' is a coordinate, not an angle: cos, sin and exp(i…) take angles, declared \
             under `angles` in [phase_space] (of anything else they are no polynomial)",
            (1, 5),
            "line 1, column 5: 'x' is a coordinate, not an angle: cos, sin and exp(i…) take \
             angles, declared under `angles` in [phase_space] (of anything else they are no \
             polynomial)\n  sin(x)\n      ^",
        ),
        case(
            Q,
            "x + i*y",
            "the imaginary unit i needs Gaussian rational coefficients Q(i)",
            (1, 5),
            "line 1, column 5: the imaginary unit i needs Gaussian rational coefficients Q(i)\n  \
             x + i*y\n      ^",
        ),
        case(
            Q,
            "1.5",
            "decimal numbers are not exact; write a fraction: 1.5 is 3/2",
            (1, 1),
            "line 1, column 1: decimal numbers are not exact; write a fraction: 1.5 is 3/2\n  1.5\n  ^^^",
        ),
        case(
            Q,
            "cos(theta)",
            "the angle θ (stored as e^{iθ}) needs Gaussian rational coefficients Q(i), but this polynomial is over Q",
            (1, 5),
            "line 1, column 5: the angle θ (stored as e^{iθ}) needs Gaussian rational coefficients \
             Q(i), but this polynomial is over Q\n  cos(theta)\n      ^^^^^",
        ),
        case(
            Qi,
            "(x + y)^-1",
            "cannot raise x + y to a negative power: only single terms (monomials) and products of powers of declared denominators are invertible; declare it (or its factors) as a denominator: denominators = [\"x + y\"] in [phase_space]",
            (1, 1),
            "line 1, column 1: cannot raise x + y to a negative power: only single terms (monomials) \
             and products of powers of declared denominators are invertible; declare it (or its \
             factors) as a denominator: denominators = [\"x + y\"] in [phase_space]\n  \
             (x + y)^-1\n  ^^^^^^^^^^",
        ),
        // A divisor written as a product of powers: shown so, and its factors as written are
        // to declare.
        case(
            Qi,
            "1/((x - y)^2*(x + 2*y))",
            "cannot divide by (x − y)²(x + 2y): only division by a nonzero constant, a single term (monomial) or a product of powers of declared denominators is exact here; declare its factors as denominators: denominators = [\"x - y\", \"x + 2*y\"] in [phase_space]",
            (1, 3),
            "line 1, column 3: cannot divide by (x − y)²(x + 2y): only division by a nonzero \
             constant, a single term (monomial) or a product of powers of declared denominators \
             is exact here; declare its factors as denominators: denominators = [\"x - y\", \
             \"x + 2*y\"] in [phase_space]\n  1/((x - y)^2*(x + 2*y))\n    ^^^^^^^^^^^^^^^^^^^^^",
        ),
        case(
            Qi,
            "((x - y)^3)^-1",
            "cannot raise (x − y)³ to a negative power: only single terms (monomials) and products of powers of declared denominators are invertible; declare its factor as a denominator: denominators = [\"x - y\"] in [phase_space]",
            (1, 1),
            "line 1, column 1: cannot raise (x − y)³ to a negative power: only single terms \
             (monomials) and products of powers of declared denominators are invertible; declare \
             its factor as a denominator: denominators = [\"x - y\"] in [phase_space]\n  \
             ((x - y)^3)^-1\n  ^^^^^^^^^^^^^^",
        ),
        case(
            Qi,
            "exp(theta)",
            "exp takes i·n·θ with an integer n and an angle θ, such as exp(-i*2*theta)",
            (1, 5),
            "line 1, column 5: exp takes i·n·θ with an integer n and an angle θ, such as \
             exp(-i*2*theta)\n  exp(theta)\n      ^^^^^",
        ),
        case(
            Qi,
            "cos(i*theta)",
            "cos takes a real angle n·θ; use exp for complex exponentials",
            (1, 5),
            "line 1, column 5: cos takes a real angle n·θ; use exp for complex exponentials\n  \
             cos(i*theta)\n      ^^^^^^^",
        ),
        case(
            Qi,
            "tan(theta)",
            "unknown function 'tan' (known: cos, sin, exp, conj, Re, Im, sqrt); expressions are \
             polynomials in the variables, in cos and sin of angles and in negative powers of \
             single terms",
            (1, 1),
            "line 1, column 1: unknown function 'tan' (known: cos, sin, exp, conj, Re, Im, sqrt); \
             expressions are polynomials in the variables, in cos and sin of angles and in \
             negative powers of single terms\n  tan(theta)\n  ^^^",
        ),
        case(
            Qi,
            "Cos(theta)",
            "unknown function 'Cos' (known: cos, sin, exp, conj, Re, Im, sqrt); did you mean 'cos'?",
            (1, 1),
            "line 1, column 1: unknown function 'Cos' (known: cos, sin, exp, conj, Re, Im, sqrt); did \
             you mean 'cos'?\n  Cos(theta)\n  ^^^",
        ),
        case(
            Qi,
            "cos(theta, phi)",
            "cos takes one argument, found 2",
            (1, 1),
            "line 1, column 1: cos takes one argument, found 2\n  cos(theta, phi)\n  ^^^^^^^^^^^^^^^",
        ),
        // The real part is named as written, Re as re.
        case(
            Qi,
            "Re(x, y)",
            "Re takes one argument, found 2",
            (1, 1),
            "line 1, column 1: Re takes one argument, found 2\n  Re(x, y)\n  ^^^^^^^^",
        ),
        // sqrt is a function too: with two arguments it was an unknown one.
        case(
            Q,
            "sqrt(x, 4)",
            "sqrt takes one argument, found 2",
            (1, 1),
            "line 1, column 1: sqrt takes one argument, found 2\n  sqrt(x, 4)\n  ^^^^^^^^^^",
        ),
        case(
            Q,
            "sqr(4)",
            "unknown function 'sqr' (known: cos, sin, exp, conj, Re, Im, sqrt); did you mean \
             'sqrt'?",
            (1, 1),
            "line 1, column 1: unknown function 'sqr' (known: cos, sin, exp, conj, Re, Im, sqrt); \
             did you mean 'sqrt'?\n  sqr(4)\n  ^^^",
        ),
        case(
            Qi,
            "x^y",
            "exponents must be integer constants",
            (1, 3),
            "line 1, column 3: exponents must be integer constants\n  x^y\n    ^",
        ),
        // A thin space `\\,` in braces after `^` is no bracket's comma: they are an exponent.
        case(
            Qi,
            r"x^{2\,y}",
            "exponents must be integer constants",
            (1, 3),
            "line 1, column 3: exponents must be integer constants\n  x^{2\\,y}\n    ^^^^^^",
        ),
        // A sizing command with no delimiter after it, which LaTeX refuses, was skipped.
        case(
            Qi,
            r"\left x + y",
            "'\\left' takes a delimiter after it, as in LaTeX ('\\left(', '\\left\\{'), found \
             'x'; leave it out where none is meant",
            (1, 1),
            "line 1, column 1: '\\left' takes a delimiter after it, as in LaTeX ('\\left(', \
             '\\left\\{'), found 'x'; leave it out where none is meant\n  \\left x + y\n  \
             ^^^^^",
        ),
        // A closing one is shown with a closing delimiter, `\bigr)` (it was `\bigr(`).
        case(
            Qi,
            r"\bigl(x + y\bigr",
            "'\\bigr' takes a delimiter after it, as in LaTeX ('\\bigr)', '\\bigr\\}'), found \
             end of input; leave it out where none is meant",
            (1, 12),
            "line 1, column 12: '\\bigr' takes a delimiter after it, as in LaTeX ('\\bigr)', \
             '\\bigr\\}'), found end of input; leave it out where none is meant\n  \
             \\bigl(x + y\\bigr\n             ^^^^^",
        ),
        case(
            Qi,
            r"\Big(x\Big",
            "'\\Big' takes a delimiter after it, as in LaTeX ('\\Big(', '\\Big\\{'), found end \
             of input; leave it out where none is meant",
            (1, 7),
            "line 1, column 7: '\\Big' takes a delimiter after it, as in LaTeX ('\\Big(', \
             '\\Big\\{'), found end of input; leave it out where none is meant\n  \
             \\Big(x\\Big\n        ^^^^",
        ),
        // A superscript on an empty group after one, `x^{2}{}^{3}`, which LaTeX sets as
        // `x^{23}`, was read as `x^(2³)`; after a power written otherwise, as `(x²)³`.
        case(
            Qi,
            "x^{2}{}^{3}",
            "'{}^{3}' after 'x^{2}', which has a superscript already, is ambiguous: LaTeX sets \
             the two superscripts side by side, as one; put 'x^{2}' in parentheses for a power \
             of it, or write the exponent in one group",
            (1, 6),
            "line 1, column 6: '{}^{3}' after 'x^{2}', which has a superscript already, is \
             ambiguous: LaTeX sets the two superscripts side by side, as one; put 'x^{2}' in \
             parentheses for a power of it, or write the exponent in one group\n  \
             x^{2}{}^{3}\n       ^^^^^^",
        ),
        // After a negative exponent written without braces it was read as the exponent's
        // power, `x^(−2³)`.
        case(
            Qi,
            "x^-2{}^{3}",
            "'{}^{3}' after 'x^-2', which has a superscript already, is ambiguous: LaTeX sets \
             the two superscripts side by side, as one; put 'x^-2' in parentheses for a power \
             of it, or write the exponent in one group",
            (1, 5),
            "line 1, column 5: '{}^{3}' after 'x^-2', which has a superscript already, is \
             ambiguous: LaTeX sets the two superscripts side by side, as one; put 'x^-2' in \
             parentheses for a power of it, or write the exponent in one group\n  \
             x^-2{}^{3}\n      ^^^^^^",
        ),
        case(
            Qi,
            "x^-(2){}^3",
            "'{}^3' after 'x^-(2)', which has a superscript already, is ambiguous: LaTeX sets \
             the two superscripts side by side, as one; put 'x^-(2)' in parentheses for a power \
             of it, or write the exponent in one group",
            (1, 7),
            "line 1, column 7: '{}^3' after 'x^-(2)', which has a superscript already, is \
             ambiguous: LaTeX sets the two superscripts side by side, as one; put 'x^-(2)' in \
             parentheses for a power of it, or write the exponent in one group\n  \
             x^-(2){}^3\n        ^^^^",
        ),
        // A power in `\left( … \right)` is quoted whole, where the quote began at its `(`.
        case(
            Qi,
            r"\left(x\right)^{2}{}^{3}",
            "'{}^{3}' after '\\left(x\\right)^{2}', which has a superscript already, is \
             ambiguous: LaTeX sets the two superscripts side by side, as one; put \
             '\\left(x\\right)^{2}' in parentheses for a power of it, or write the exponent in \
             one group",
            (1, 19),
            "line 1, column 19: '{}^{3}' after '\\left(x\\right)^{2}', which has a superscript \
             already, is ambiguous: LaTeX sets the two superscripts side by side, as one; put \
             '\\left(x\\right)^{2}' in parentheses for a power of it, or write the exponent in \
             one group\n  \\left(x\\right)^{2}{}^{3}\n                    ^^^^^^",
        ),
        case(
            Qi,
            r"y \Bigl\{x, y\Bigr\}^2²",
            "'²' after '\\Bigl\\{x, y\\Bigr\\}^2', which has a superscript already, is \
             ambiguous: the two superscripts show side by side, as one; put \
             '\\Bigl\\{x, y\\Bigr\\}^2' in parentheses for a power of it, or write the exponent \
             in one group",
            (1, 23),
            "line 1, column 23: '²' after '\\Bigl\\{x, y\\Bigr\\}^2', which has a superscript \
             already, is ambiguous: the two superscripts show side by side, as one; put \
             '\\Bigl\\{x, y\\Bigr\\}^2' in parentheses for a power of it, or write the exponent \
             in one group\n  y \\Bigl\\{x, y\\Bigr\\}^2²\n                        ^",
        ),
        // A superscript character after a superscript shows beside it as one, `x²²`: it was
        // read as a power of the exponent, `x^(2²)`, or of the power, `(x²)²`.
        case(
            Qi,
            "x^{2}²",
            "'²' after 'x^{2}', which has a superscript already, is ambiguous: the two \
             superscripts show side by side, as one; put 'x^{2}' in parentheses for a power of \
             it, or write the exponent in one group",
            (1, 6),
            "line 1, column 6: '²' after 'x^{2}', which has a superscript already, is \
             ambiguous: the two superscripts show side by side, as one; put 'x^{2}' in \
             parentheses for a power of it, or write the exponent in one group\n  \
             x^{2}²\n       ^",
        ),
        case(
            Qi,
            "y + x^-2³",
            "'³' after 'x^-2', which has a superscript already, is ambiguous: the two \
             superscripts show side by side, as one; put 'x^-2' in parentheses for a power of \
             it, or write the exponent in one group",
            (1, 9),
            "line 1, column 9: '³' after 'x^-2', which has a superscript already, is \
             ambiguous: the two superscripts show side by side, as one; put 'x^-2' in \
             parentheses for a power of it, or write the exponent in one group\n  \
             y + x^-2³\n          ^",
        ),
        case(
            Qi,
            "x² ⁻¹",
            "'⁻¹' after 'x²', which has a superscript already, is ambiguous: the two \
             superscripts show side by side, as one; put 'x²' in parentheses for a power of it, \
             or write the exponent in one group",
            (1, 4),
            "line 1, column 4: '⁻¹' after 'x²', which has a superscript already, is \
             ambiguous: the two superscripts show side by side, as one; put 'x²' in \
             parentheses for a power of it, or write the exponent in one group\n  \
             x² ⁻¹\n     ^^",
        ),
        case(
            Qi,
            r"y + x^2 \, { } ^3",
            "'{ } ^3' after 'x^2', which has a superscript already, is ambiguous: LaTeX sets \
             the two superscripts side by side, as one; put 'x^2' in parentheses for a power \
             of it, or write the exponent in one group",
            (1, 12),
            "line 1, column 12: '{ } ^3' after 'x^2', which has a superscript already, is \
             ambiguous: LaTeX sets the two superscripts side by side, as one; put 'x^2' in \
             parentheses for a power of it, or write the exponent in one group\n  \
             y + x^2 \\, { } ^3\n             ^^^^^^",
        ),
        case(
            Qi,
            r"x{}^{2}{}^{\theta}",
            "'{}^{\\theta}' after 'x{}^{2}', which has a superscript already, is ambiguous: \
             LaTeX sets the two superscripts side by side, as one; put 'x{}^{2}' in parentheses \
             for a power of it, or write the exponent in one group",
            (1, 8),
            "line 1, column 8: '{}^{\\theta}' after 'x{}^{2}', which has a superscript \
             already, is ambiguous: LaTeX sets the two superscripts side by side, as one; put \
             'x{}^{2}' in parentheses for a power of it, or write the exponent in one \
             group\n  x{}^{2}{}^{\\theta}\n         ^^^^^^^^^^^",
        ),
        case(
            Qi,
            "-x²{}^3",
            "'{}^3' after 'x²', which has a superscript already, is ambiguous: LaTeX sets the \
             two superscripts side by side, as one; put 'x²' in parentheses for a power of it, \
             or write the exponent in one group",
            (1, 4),
            "line 1, column 4: '{}^3' after 'x²', which has a superscript already, is \
             ambiguous: LaTeX sets the two superscripts side by side, as one; put 'x²' in \
             parentheses for a power of it, or write the exponent in one group\n  \
             -x²{}^3\n     ^^^^",
        ),
        case(
            Qi,
            r"e^{i\theta}{}^{2}",
            "'{}^{2}' after 'e^{i\\theta}', which has a superscript already, is ambiguous: \
             LaTeX sets the two superscripts side by side, as one; put 'e^{i\\theta}' in \
             parentheses for a power of it, or write the exponent in one group",
            (1, 12),
            "line 1, column 12: '{}^{2}' after 'e^{i\\theta}', which has a superscript \
             already, is ambiguous: LaTeX sets the two superscripts side by side, as one; put \
             'e^{i\\theta}' in parentheses for a power of it, or write the exponent in one \
             group\n  e^{i\\theta}{}^{2}\n             ^^^^^^",
        ),
        case(
            Qi,
            "(x - x)^-2",
            "division by zero",
            (1, 1),
            "line 1, column 1: division by zero\n  (x - x)^-2\n  ^^^^^^^^^^",
        ),
        case(
            Qi,
            "{x, y}",
            "a bracket {f, g} needs a phase space; parse it through a system",
            (1, 1),
            "line 1, column 1: a bracket {f, g} needs a phase space; parse it through a system\n  \
             {x, y}\n  ^^^^^^",
        ),
        case(
            Qi,
            "x +\n  1/(x + y)",
            "cannot divide by x + y: only division by a nonzero constant, a single term (monomial) or a product of powers of declared denominators is exact here; declare it (or its factors) as a denominator: denominators = [\"x + y\"] in [phase_space]",
            (2, 5),
            "line 2, column 5: cannot divide by x + y: only division by a nonzero constant, a single \
             term (monomial) or a product of powers of declared denominators is exact here; \
             declare it (or its factors) as a denominator: denominators = [\"x + y\"] in \
             [phase_space]\n    1/(x + y)\n      ^^^^^^^",
        ),
        case(
            Qi,
            "(x^500)^3",
            "the exponent of x would reach 1500, past the limit of 1000",
            (1, 1),
            "line 1, column 1: the exponent of x would reach 1500, past the limit of 1000\n  \
             (x^500)^3\n  ^^^^^^^^^",
        ),
        // An angle is stored as e^{iθ}, but its order is said as cos kθ, sin kθ say it.
        case(
            Qi,
            "sin(theta)^800*cos(theta)^800",
            "the trigonometric order in θ would reach 1600 (terms in cos 1600θ, sin 1600θ), past \
             the limit of 1000",
            (1, 1),
            "line 1, column 1: the trigonometric order in θ would reach 1600 (terms in cos 1600θ, \
             sin 1600θ), past the limit of 1000\n  sin(theta)^800*cos(theta)^800\n  \
             ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^",
        ),
        // A rational multiple that is not an integer.
        case(
            Qi,
            "cos(theta/2)",
            "cos takes an integer combination of angles, such as cos(2*theta - phi)",
            (1, 5),
            "line 1, column 5: cos takes an integer combination of angles, such as cos(2*theta - phi)\n  \
             cos(theta/2)\n      ^^^^^^^",
        ),
        case(
            Qi,
            "sin(1/2*theta)",
            "sin takes an integer combination of angles, such as sin(2*theta - phi)",
            (1, 5),
            "line 1, column 5: sin takes an integer combination of angles, such as sin(2*theta - phi)\n  \
             sin(1/2*theta)\n      ^^^^^^^^^",
        ),
        // A quotient in a multiple: by zero, and of an angle that the product after it
        // would make whole again (each quotient must leave integer multiples).
        case(
            Qi,
            "cos(theta/(2 - 2))",
            "division by zero",
            (1, 11),
            "line 1, column 11: division by zero\n  cos(theta/(2 - 2))\n            ^^^^^^^",
        ),
        case(
            Qi,
            "cos(2*(theta/2))",
            "cos takes an integer combination of angles, such as cos(2*theta - phi)",
            (1, 7),
            "line 1, column 7: cos takes an integer combination of angles, such as cos(2*theta - phi)\n  \
             cos(2*(theta/2))\n        ^^^^^^^^^",
        ),
        // A power in a multiple: of an integer to a negative exponent (not an integer), of
        // an angle, past the degree limit, and one whose value is past it.
        case(
            Qi,
            "cos(2^(-1)*theta)",
            "cos takes an integer combination of angles, such as cos(2*theta - phi)",
            (1, 5),
            "line 1, column 5: cos takes an integer combination of angles, such as cos(2*theta - phi)\n  \
             cos(2^(-1)*theta)\n      ^^^^^^^^^^^^",
        ),
        case(
            Qi,
            "cos(theta^2)",
            "cos takes an integer combination of angles, such as cos(2*theta - phi)",
            (1, 5),
            "line 1, column 5: cos takes an integer combination of angles, such as cos(2*theta - phi)\n  \
             cos(theta^2)\n      ^^^^^^^",
        ),
        case(
            Qi,
            "exp(i*2^2000*theta)",
            "the exponent 2000 is past the limit of 1000",
            (1, 9),
            "line 1, column 9: the exponent 2000 is past the limit of 1000\n  \
             exp(i*2^2000*theta)\n          ^^^^",
        ),
        case(
            Qi,
            "cos(10^30*theta)",
            "the multiple 1000000000000000000000000000000 of θ is past the limit of 1000",
            (1, 5),
            "line 1, column 5: the multiple 1000000000000000000000000000000 of θ is past the \
             limit of 1000\n  cos(10^30*theta)\n      ^^^^^^^^^^^",
        ),
        // An exponent too long to write, likewise.
        case(
            Qi,
            "x^(2^1000)",
            "the exponent, of 1001 bits, is past the limit of 1000",
            (1, 3),
            "line 1, column 3: the exponent, of 1001 bits, is past the limit of 1000\n  \
             x^(2^1000)\n    ^^^^^^^^",
        ),
        // A multiple too long to write is said by its size.
        case(
            Qi,
            "sin(phi - (2^1000)^1000*theta)",
            "the multiple of θ, of 1000001 bits, is past the limit of 1000",
            (1, 5),
            "line 1, column 5: the multiple of θ, of 1000001 bits, is past the limit of 1000\n  \
             sin(phi - (2^1000)^1000*theta)\n      ^^^^^^^^^^^^^^^^^^^^^^^^^",
        ),
        // A product of angles, at the second.
        case(
            Qi,
            "cos(theta*(phi - theta))",
            "cos takes an integer combination of angles, such as cos(2*theta - phi)",
            (1, 11),
            "line 1, column 11: cos takes an integer combination of angles, such as cos(2*theta - phi)\n  \
             cos(theta*(phi - theta))\n            ^^^^^^^^^^^^^",
        ),
        // A coordinate or a parameter in the combination.
        case(
            Qi,
            "cos(2*(theta - x))",
            "'x' is a coordinate, not an angle: cos, sin and exp(i…) take angles, declared \
             under `angles` in [phase_space] (of anything else they are no polynomial)",
            (1, 16),
            "line 1, column 16: 'x' is a coordinate, not an angle: cos, sin and exp(i…) take \
             angles, declared under `angles` in [phase_space] (of anything else they are no \
             polynomial)\n  cos(2*(theta - x))\n                 ^",
        ),
        case(
            Qi,
            "cos(M*theta)",
            "cos takes an integer combination of angles, such as cos(2*theta - phi)",
            (1, 5),
            "line 1, column 5: cos takes an integer combination of angles, such as cos(2*theta - phi)\n  \
             cos(M*theta)\n      ^",
        ),
        case(
            Qi,
            "cos(k*theta)",
            "unknown angle 'k'",
            (1, 5),
            "line 1, column 5: unknown angle 'k'\n  \
             cos(k*theta)\n      ^",
        ),
        // A constant phase.
        case(
            Qi,
            "cos(theta + 1)",
            "cos takes an integer combination of angles, such as cos(2*theta - phi)",
            (1, 13),
            "line 1, column 13: cos takes an integer combination of angles, such as cos(2*theta - phi)\n  \
             cos(theta + 1)\n              ^",
        ),
        // A constant angle other than 0 (`cos(0)` is 1).
        case(
            Qi,
            "sin(2/3)",
            "sin takes an integer combination of angles, such as sin(2*theta - phi)",
            (1, 5),
            "line 1, column 5: sin takes an integer combination of angles, such as sin(2*theta - phi)\n  \
             sin(2/3)\n      ^^^",
        ),
        // A combination without i, and one that is partly real and partly imaginary.
        case(
            Qi,
            "exp(2*(theta - phi))",
            "exp takes i·n·θ with an integer n and an angle θ, such as exp(-i*2*theta)",
            (1, 5),
            "line 1, column 5: exp takes i·n·θ with an integer n and an angle θ, such as exp(-i*2*theta)\n  \
             exp(2*(theta - phi))\n      ^^^^^^^^^^^^^^^",
        ),
        case(
            Qi,
            "exp(i*theta + phi)",
            "exp takes i times an integer combination of angles, such as exp(i*(2*theta - phi))",
            (1, 5),
            "line 1, column 5: exp takes i times an integer combination of angles, such as exp(i*(2*theta - phi))\n  \
             exp(i*theta + phi)\n      ^^^^^^^^^^^^^",
        ),
        case(
            Qi,
            "M/(x^2*cos(phi)^2)",
            "cannot divide by x²/2 + (x² cos 2φ)/2: cos and sin of an angle are sums of exponentials, which \
             are not invertible here; only division by a nonzero constant, a single term in the \
             other variables, or exp(i*k*angle) is exact",
            (1, 3),
            "line 1, column 3: cannot divide by x²/2 + (x² cos 2φ)/2: cos and sin of an angle are sums of \
             exponentials, which are not invertible here; only division by a nonzero constant, a \
             single term in the other variables, or exp(i*k*angle) is exact\n  \
             M/(x^2*cos(phi)^2)\n    ^^^^^^^^^^^^^^^^",
        ),
    ]
}

#[test]
fn rejected_inputs_have_exact_messages_locations_and_carets() {
    let vars = phase_space();
    let unknown = cases().into_iter().find(|c| c.src == "x + q*y");
    assert!(unknown.is_some_and(|c| c.message.ends_with(&format!("(known: {KNOWN})"))));
    for case in cases() {
        let err = match case.field {
            Field::Q => Poly::<Rational>::parse(&vars, case.src).map(|f| f.to_string()),
            Field::Qi => Poly::<GaussianRational>::parse(&vars, case.src).map(|f| f.to_string()),
        }
        .map(|f| {
            panic!(
                "{:?} over {:?} parsed to {f}, but must be rejected",
                case.src, case.field
            )
        })
        .unwrap_err();
        assert_eq!(
            (err.message(), err.line_col(case.src)),
            (case.message, case.line_col),
            "{:?}",
            case.src
        );
        assert_eq!(err.render(case.src), case.render, "{:?}", case.src);
    }
}

/// Every function the parser knows, written without its parentheses, is told as what it is
/// (`'cos' is the cosine, a function: …`), not as "a function" alone, the message kept for a
/// function added to `FUNCTIONS` before its description is.
#[test]
fn every_function_without_parentheses_is_named_for_what_it_is() {
    let vars = phase_space();
    for name in trigpoly::FUNCTIONS.into_iter().chain(["sqrt", "Re", "Im"]) {
        let src = name.to_string();
        let err = Poly::<GaussianRational>::parse(&vars, &src).unwrap_err();
        let message = err.message();
        let named = message
            .strip_prefix(&format!("'{name}' is the "))
            .and_then(|rest| rest.split_once(", a function: write its argument in parentheses, "));
        assert!(
            named.is_some_and(|(what, call)| !what.is_empty() && call == format!("{name}(…)")),
            "{src:?}: {message}"
        );
    }
}

/// The same source is fine over Q(i) where Q rejects it, and vice versa nothing else changes.
#[test]
fn rejected_over_q_accepted_over_gaussian_rationals() {
    let vars = phase_space();
    for src in ["x + i*y", "cos(theta)", "exp(2*i*phi)"] {
        assert!(Poly::<Rational>::parse(&vars, src).is_err(), "{src} over Q");
        assert!(
            Poly::<GaussianRational>::parse(&vars, src).is_ok(),
            "{src} over Q(i)"
        );
    }
}

/// An angle over Q has no polynomial: `Poly::monomial` says so, and `Poly::var`, which
/// returns no error, panics saying so (it said "exponent 1 is within every limit").
#[test]
#[should_panic(expected = "the angle theta is e^{iθ}, which a polynomial over Q has no")]
fn an_angle_is_no_variable_over_q() {
    let vars = phase_space();
    let theta = vars.lookup("theta").unwrap();
    assert!(Poly::<Rational>::monomial(&vars, Rational::one(), &[(theta, 1)]).is_err());
    assert!(!Poly::<GaussianRational>::var(&vars, theta).is_real());
    Poly::<Rational>::var(&vars, theta);
}

/// `coefficients_in` of a handle of another set panics saying so, as `coeff` and `degree` do,
/// where it collected in whatever variable stood at the handle's index here: `y` of `{y}`
/// gave `x²p + 3x² + p` in `x`, `(2, p + 3)` and `(0, p)`.
#[test]
#[should_panic(expected = "a variable handle of another variable set was used")]
fn coefficients_in_a_variable_of_another_set_panic() {
    let vars = trigpoly::Vars::builder()
        .coordinate("x")
        .momentum("p")
        .build()
        .unwrap();
    let other = trigpoly::Vars::builder().coordinate("y").build().unwrap();
    let f = Poly::<Rational>::parse(&vars, "x^2*p + 3*x^2 + p").unwrap();
    let x = vars.lookup("x").unwrap();
    assert_eq!(f.coefficients_in(&[x]).len(), 2);
    f.coefficients_in(&[other.lookup("y").unwrap()]);
}

/// A long line (a generated expression) is rendered as a window of 40 characters either side
/// of the caret, cut with `…`, with the caret under the offending character.
#[test]
fn a_long_line_renders_as_a_window_around_the_error() {
    let src = format!("{}@{}", "x + ".repeat(500), " + y".repeat(500));
    let err = Poly::<Rational>::parse(&phase_space(), &src).expect_err("@ is not an operator");
    let rendered = err.render(&src);
    let column = 4 * 500 + 1;
    assert_eq!(
        rendered,
        format!(
            "line 1, column {column}: {}\n  …{}@{}…\n  {}^",
            err.message(),
            &"x + ".repeat(10),
            &" + y".repeat(10),
            " ".repeat(41)
        )
    );
}

/// A refused span that runs on past its first line (a divisor opened on one line and closed
/// on another) shows the line where it ends too, its caret from that line's first character
/// that is not blank, so that both of its ends are seen (the excerpt showed `x/(x +` alone),
/// with `…` for the lines between, and the first line's caret to its last character that is
/// not blank (it ran on under the blanks at the line's end); a span that ends with a line
/// break after its text is on one line.
#[test]
fn a_span_over_several_lines_shows_both_its_ends() {
    let vars = phase_space();
    let message = "cannot divide by x + y: only division by a nonzero constant, a single term \
                   (monomial) or a product of powers of declared denominators is exact here; \
                   declare it (or its factors) as a denominator: denominators = [\"x + y\"] in \
                   [phase_space]";
    let rendered = [
        (
            "x/(x +\n  y) + 1",
            "\n  x/(x +\n    ^^^^\n    y) + 1\n    ^^",
        ),
        ("x/(x\n\n +\n\ty)", "\n  x/(x\n    ^^\n  …\n  \ty)\n  \t^^"),
        (
            "x/(x + \t\n  y) + 1",
            "\n  x/(x + \t\n    ^^^^\n    y) + 1\n    ^^",
        ),
    ];
    for (src, excerpt) in rendered {
        let err = Poly::<Rational>::parse(&vars, src).expect_err("not a monomial");
        assert_eq!(err.message(), message);
        assert_eq!(
            err.to_string(),
            format!("line 1, column 3: {message}{excerpt}")
        );
        assert_eq!(err.render(src), err.to_string());
    }
    // A long line where the span ends is shown by its window around the span's end, which
    // is what it is there to show (the window was around the line's first character, and
    // cut away `y)`).
    let src = format!("x/(x +\n  {}y) + 1", "x*".repeat(60));
    let err = Poly::<Rational>::parse(&vars, &src).expect_err("not a monomial");
    let last = err
        .excerpt()
        .unwrap()
        .last
        .clone()
        .expect("the span ends on line 2");
    assert_eq!((last.line, last.column), (2, 3));
    assert_eq!(last.text, format!("…{}y) + 1", "x*".repeat(39)));
    assert_eq!((last.pad.as_str(), last.width), (" ", 80));
    let excerpt = trigpoly::Excerpt::of("x/(x +\n", trigpoly::Span::new(2, 7));
    assert_eq!((excerpt.line, excerpt.column, excerpt.width), (1, 3, 4));
    assert_eq!(excerpt.last, None);
}

/// A refused division or negative power names a long polynomial by its size, not its text (a
/// divisor of 24 k terms once made a 270 MB message); a short one is still shown in full.
#[test]
fn a_long_divisor_is_named_by_its_size() {
    let vars = phase_space();
    // Written as a power, it is shown as written (not as its 21 terms), and its factor is
    // what to declare.
    let long = Poly::<Rational>::parse(&vars, "x/(1 + x)^20").expect_err("not a monomial");
    assert_eq!(
        long.message(),
        "cannot divide by (x + 1)²⁰: only division by a nonzero constant, a single term \
         (monomial) or a product of powers of declared denominators is exact here; declare its \
         factor as a denominator: denominators = [\"x + 1\"] in [phase_space]"
    );
    let long = Poly::<Rational>::parse(
        &vars,
        "x/(1 + x + y^2 + y^3 + x*y + x^2*y + x^3 + y^4 + x^5)",
    )
    .expect_err("not a monomial");
    assert_eq!(
        long.message(),
        "cannot divide by a polynomial of 9 terms: only division by a nonzero constant, a \
         single term (monomial) or a product of powers of declared denominators is exact here; \
         declare its factors as denominators in [phase_space]"
    );
    let power = Poly::<Rational>::parse(&vars, "(1 + x + y)^(-1)").expect_err("not invertible");
    assert_eq!(
        power.message(),
        "cannot raise x + y + 1 to a negative power: only single terms (monomials) and products \
         of powers of declared denominators are invertible; declare it (or its factors) as a \
         denominator: denominators = [\"x + y + 1\"] in [phase_space]"
    );
}

/// Names run together split into declared ones whatever their length, and a long run that
/// does not split is refused as an unknown name: the split tried every cut at every place
/// (a run of 16 000 `x` took 15 s and 1 GB before the exponent limit stopped it).
#[test]
fn long_runs_of_names_split_or_are_refused() {
    let vars = phase_space();
    let run = "xy".repeat(400);
    let product = Poly::<Rational>::parse(&vars, &run).expect("x·y·x·y…");
    assert_eq!(product, Poly::parse(&vars, "x^400*y^400").unwrap());
    let err = Poly::<Rational>::parse(&vars, &"x".repeat(20_000)).expect_err("past the degree");
    assert!(
        err.message().contains("the exponent of x would reach"),
        "{}",
        err.message()
    );
    // A run that ends in an undeclared letter: no split, from any place.
    let err = Poly::<Rational>::parse(&vars, &format!("{}q", "xy".repeat(5_000)))
        .expect_err("q is not declared");
    assert!(
        err.message().starts_with("unknown name"),
        "{}",
        err.message()
    );
    // Quoted by its first characters and its length, not echoed whole (10 001 characters).
    assert!(
        err.message().starts_with(&format!(
            "unknown name '{}…', 10001 characters long (known: ",
            "xy".repeat(20)
        )) && err.message().len() < 200,
        "{}",
        err.message()
    );
}

/// A `^` after a superscript character, `x²^3`, could raise the power, `(x²)³`, as it was
/// read, or the exponent, `x^(2³)`, as `x^2^3` is: it is refused as a superscript character
/// after an exponent is, quoting the `^` with its exponent; in parentheses either reads.
#[test]
fn a_caret_after_a_superscript_character_is_ambiguous() {
    let vars = phase_space();
    let refused = [
        ("x²^3", "'^3'", "'x²'", (1, 3)),
        ("x²^{3}", "'^{3}'", "'x²'", (1, 3)),
        ("x² ^3", "'^3'", "'x²'", (1, 4)),
        ("y + x⁻¹^(2)", "'^(2)'", "'x⁻¹'", (1, 8)),
        ("x^{y²^3}", "'^3'", "'y²'", (1, 6)),
    ];
    let set = "it may raise the power or its exponent";
    for (src, quote, base, line_col) in refused {
        refused_after_a_superscript::<Rational>(&vars, src, (quote, base, set), line_col);
    }
    for (src, value) in [
        ("(x²)^3", "x^6"),
        ("x^(2²)", "x^4"),
        ("x^{2²}", "x^4"),
        ("x^2^3", "x^8"),
    ] {
        reads_as::<Rational>(&vars, src, value);
    }
}

/// Asserts that `src`, read with `vars`, is refused for the superscript `quote` after `base`,
/// which has one already, `set` saying how the two read together, at `line_col`.
#[track_caller]
fn refused_after_a_superscript<C: Coefficient>(
    vars: &trigpoly::Vars,
    src: &str,
    (quote, base, set): (&str, &str, &str),
    line_col: (usize, usize),
) {
    let err = Poly::<C>::parse(vars, src).expect_err(src);
    assert_eq!(
        (err.message().to_string(), err.line_col(src)),
        (
            format!(
                "{quote} after {base}, which has a superscript already, is ambiguous: {set}; put \
                 {base} in parentheses for a power of it, or write the exponent in one group"
            ),
            line_col
        ),
        "{src}"
    );
}

/// Asserts that `src` and `value`, read with `vars`, are the same element.
#[track_caller]
fn reads_as<C: Coefficient>(vars: &trigpoly::Vars, src: &str, value: &str) {
    assert_eq!(
        Poly::<C>::parse(vars, src).expect(src),
        Poly::<C>::parse(vars, value).unwrap(),
        "{src}"
    );
}

/// A superscript refused after a power quotes the factor that the power raises: after a name
/// before parentheses, `x(y)^{2}`, read as `x·(y)²` as `M(x + y)²` is printed, the
/// parentheses and their power, where it quoted `x(y)^{2}` as if the power were the product's;
/// a function's call, a product's last factor and a fraction are quoted whole.
#[test]
fn a_superscript_after_a_power_quotes_the_factor_raised() {
    let vars = phase_space();
    for (src, base) in [
        ("x(y)^{2}{}^{3}", "'(y)^{2}'"),
        ("x(y)^{2}²", "'(y)^{2}'"),
        ("x(y)²^3", "'(y)²'"),
        ("M (x + y)^2²", "'(x + y)^2'"),
        (r"M\left(x\right)^{2}{}^{3}", r"'\left(x\right)^{2}'"),
        ("(M(x))^{2}{}^{3}", "'(M(x))^{2}'"),
        ("cos(theta)^{2}{}^{3}", "'cos(theta)^{2}'"),
        ("2x^{2}{}^{3}", "'x^{2}'"),
        ("x y^{2}{}^{3}", "'y^{2}'"),
        (r"\frac{1}{M}^{2}{}^{3}", r"'\frac{1}{M}^{2}'"),
        // Names run together, read as their product with the power on the last alone.
        ("Mω^{2}{}^{3}", "'ω^{2}'"),
        ("Mω²^3", "'ω²'"),
        ("Mωx^2²", "'x^2'"),
        ("p_xy^{2}{}^{3}", "'y^{2}'"),
        ("(Mω)^{2}{}^{3}", "'(Mω)^{2}'"),
    ] {
        refused_quoting_the_power(&vars, src, base);
    }
}

/// Asserts that `src`, read with `vars`, is refused for a superscript after a power, quoting
/// `base` as the factor the power raises.
#[track_caller]
fn refused_quoting_the_power(vars: &trigpoly::Vars, src: &str, base: &str) {
    let err = Poly::<GaussianRational>::parse(vars, src).expect_err(src);
    assert!(
        err.message().contains(&format!(
            " after {base}, which has a superscript already, is ambiguous: "
        )) && err
            .message()
            .contains(&format!("; put {base} in parentheses for a power of it")),
        "{src}: {}",
        err.message()
    );
}

/// A power of a function written before its argument in parentheses, `sin²(θ)`, takes a
/// superscript after them as it takes `^`, `sin²(θ)³` being `(sin²θ)³`; a second superscript
/// or a `^` after that one is refused as after any other, quoting the power it raises.
#[test]
fn a_superscript_after_a_call_raised_before_its_parentheses_is_refused_as_after_any_power() {
    let vars = phase_space();
    let side_by_side = "the two superscripts show side by side, as one";
    for (src, quote, base, set, line_col) in [
        ("sin²(θ)³ ²", "'²'", "'sin²(θ)³'", side_by_side, (1, 10)),
        (
            "sin²(θ)³{}^{2}",
            "'{}^{2}'",
            "'sin²(θ)³'",
            "LaTeX sets the two superscripts side by side, as one",
            (1, 9),
        ),
        (
            "sin²(θ)³^2",
            "'^2'",
            "'sin²(θ)³'",
            "it may raise the power or its exponent",
            (1, 9),
        ),
        ("sin²(θ)^3²", "'²'", "'sin²(θ)^3'", side_by_side, (1, 10)),
    ] {
        refused_after_a_superscript::<GaussianRational>(&vars, src, (quote, base, set), line_col);
    }
}

/// A `^` after a superscript character with no exponent after it, `x²^`, is refused as it is
/// after any other base, `x^`: there is no power to be in doubt about.
#[test]
fn a_caret_without_an_exponent_after_a_superscript_is_missing_its_exponent() {
    let vars = phase_space();
    for (src, alone, line_col) in [
        ("x²^", "x^", (1, 4)),
        ("x² ^", "x ^", (1, 5)),
        ("(x²^)", "(x^)", (1, 5)),
        ("x²^{}", "x^{}", (1, 5)),
        ("x²^(2", "x ^(2", (1, 6)),
        ("x²^$", "x^$", (1, 4)),
        ("x²{}^", "x{}^", (1, 6)),
        ("x^{2}{}^", "x{}^", (1, 9)),
        ("cos²θ^", "x^", (1, 7)),
        ("cos θ^", "x^", (1, 7)),
    ] {
        let err = Poly::<Rational>::parse(&vars, src).expect_err(src);
        let want = Poly::<Rational>::parse(&vars, alone).expect_err(alone);
        assert_eq!(
            (err.message(), err.line_col(src)),
            (want.message(), line_col),
            "{src}"
        );
    }
}

/// A power of an angle written without parentheses after a power of its function,
/// `sin²θ^3`, could raise `sin²θ`, as it was read, or the angle, as LaTeX reads
/// `\sin^2\theta^3`: it is refused, with both readings written as the input writes them. With
/// the angle in parentheses the power raises the call, as `sin(θ)^3` does.
#[test]
fn a_power_of_a_bare_angle_after_a_powered_function_is_ambiguous() {
    let vars = phase_space();
    let refused = [
        ("sin²θ^3", "sin²θ", "^3", "sin²", "θ", (1, 5)),
        ("sin²θ^{3}", "sin²θ", "^{3}", "sin²", "θ", (1, 5)),
        ("sin²θ³", "sin²θ", "³", "sin²", "θ", (1, 5)),
        ("cos⁻¹θ⁻¹", "cos⁻¹θ", "⁻¹", "cos⁻¹", "θ", (1, 6)),
        (
            "x + sin² theta ^2",
            "sin² theta",
            "^2",
            "sin²",
            "theta",
            (1, 10),
        ),
        (
            "\\sin^{2}\\theta^{3}",
            "\\sin^{2}\\theta",
            "^{3}",
            "\\sin^{2}",
            "\\theta",
            (1, 9),
        ),
        (
            "\\sin^{2}\\theta{}^{3}",
            "\\sin^{2}\\theta",
            "^{3}",
            "\\sin^{2}",
            "\\theta",
            (1, 9),
        ),
        ("x^{cos²θ^-2}", "cos²θ", "^-2", "cos²", "θ", (1, 8)),
    ];
    for (src, written, power, function, angle, line_col) in refused {
        let err = Poly::<GaussianRational>::parse(&vars, src).expect_err(src);
        assert_eq!(
            (err.message().to_string(), err.line_col(src)),
            (
                format!(
                    "'{written}' followed by a power is ambiguous: write ({written}){power} \
                     for a power of {written}, or {function}({angle}{power}) for {function} of \
                     {angle}{power}"
                ),
                line_col
            ),
            "{src}"
        );
        // Both readings the message writes parse (the power of the angle is no polynomial,
        // and is refused as one).
        let (whole, inner) = (
            format!("({written}){power}"),
            format!("{function}({angle}{power})"),
        );
        for reading in [whole, inner] {
            trigpoly::syntax::parse_expr(&reading).expect(&reading);
        }
    }
    for (src, value) in [
        ("sin²θ", "sin(theta)^2"),
        ("sin²θ x^3", "x^3 sin(theta)^2"),
        ("cos²θ sin³θ", "cos(theta)^2 sin(theta)^3"),
        ("sin(θ)^3", "sin(theta)^3"),
        ("sin²(θ)^3", "sin(theta)^6"),
        ("\\sin^{2}(\\theta)^{3}", "sin(theta)^6"),
        ("(sin²θ)^3", "sin(theta)^6"),
        // A superscript character after the parentheses raises the call as `^` does: the
        // function's own stands before them, not beside it (`sin²(θ)³` was refused as two
        // superscripts side by side), and so does a superscript on an empty group.
        ("sin²(θ)³", "sin(theta)^6"),
        ("sin²(θ) ³ x", "x sin(theta)^6"),
        ("cos³(θ)²", "cos(theta)^6"),
        ("\\sin^{2}(\\theta)³", "sin(theta)^6"),
        ("\\sin^{2}\\left(\\theta\\right)³", "sin(theta)^6"),
        ("\\sin^{2}(\\theta){}^{3}", "sin(theta)^6"),
    ] {
        reads_as::<GaussianRational>(&vars, src, value);
    }
}

/// A superscript refused after a power of `Re(…)` or `Im(…)` quotes the power of the
/// parentheses, `'(y)^{2}'`, where the system declares `Re` and `Im` as names, which multiply
/// them as `x(y)^{2}` does; where it does not, the real and imaginary parts are raised whole.
#[test]
fn a_superscript_after_a_power_of_a_declared_re_quotes_the_parentheses() {
    let declared = Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .parameter("Re")
        .parameter("Im")
        .build()
        .expect("valid variable names");
    let parts = Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .build()
        .expect("valid variable names");
    for (src, product, part) in [
        ("Re(y)^{2}{}^{3}", "'(y)^{2}'", "'Re(y)^{2}'"),
        ("Im(x + y)²^3", "'(x + y)²'", "'Im(x + y)²'"),
        ("Re(y)^2²", "'(y)^2'", "'Re(y)^2'"),
    ] {
        for (vars, base) in [(&declared, product), (&parts, part)] {
            refused_quoting_the_power(vars, src, base);
        }
    }
}

/// A name the system declares, before parentheses with two arguments, is refused as a name
/// that is no function, as `M(x, y)` is, with no guess at a function it misspells: `Re(x, y)`
/// where `Re` is a parameter was asked whether it meant the real part `re`.
#[test]
fn a_declared_re_with_two_arguments_is_no_misspelled_part() {
    let declared = Vars::builder()
        .coordinate("x")
        .coordinate("y")
        .parameter("Re")
        .parameter("Cos")
        .build()
        .expect("valid variable names");
    let known = "(known: cos, sin, exp, conj, re, Im, sqrt)";
    for name in ["Re", "Cos"] {
        let src = format!("{name}(x, y)");
        let err = Poly::<GaussianRational>::parse(&declared, &src).expect_err(&src);
        assert_eq!(err.message(), format!("unknown function '{name}' {known}"));
    }
    let err = Poly::<GaussianRational>::parse(&declared, "Sin(x, y)").expect_err("Sin");
    assert_eq!(
        err.message(),
        format!("unknown function 'Sin' {known}; did you mean 'sin'?")
    );
}

/// A multiple of an angle written without parentheses, `cos 2θ`, as the printers write one,
/// reads as `cos(2θ)`; what it cannot be read as is refused naming the multiple: a power after
/// it (`sin 2θ^2` is not the square of `sin θ`, which the message for `sin θ^2` advises), and a
/// multiple that is not one integer (`cos 2/3θ`).
#[test]
fn a_multiple_angle_without_parentheses_is_read_or_refused_as_written() {
    let vars = phase_space();
    let read = |src: &str| Poly::<GaussianRational>::parse(&vars, src);
    for src in ["cos 2θ", "cos 2 theta", "\\cos 2\\theta", "cos 2 θ"] {
        assert_eq!(read(src), read("cos(2*theta)"), "{src}");
    }
    let refused = [
        (
            "sin 2θ^2",
            "'sin 2θ' followed by a power is ambiguous: write (sin 2θ)^2 for a power of sin 2θ, \
             or sin(2θ^2) for sin of 2θ^2",
            (1, 5),
        ),
        (
            "x + cos 2 theta³",
            "'cos 2 theta' followed by a power is ambiguous: write (cos 2 theta)³ for a power of \
             cos 2 theta, or cos(2 theta³) for cos of 2 theta³",
            (1, 9),
        ),
        (
            "cos 2/3θ",
            "expected an angle after 'cos 2', as in cos 2θ",
            (1, 6),
        ),
        (
            "sin 2(θ)",
            "expected an angle after 'sin 2', as in sin 2θ",
            (1, 6),
        ),
    ];
    for (src, message, line_col) in refused {
        let err = read(src).expect_err(src);
        assert_eq!(
            (err.message().to_string(), err.line_col(src)),
            (message.to_string(), line_col),
            "{src}"
        );
    }
    // The power the message writes first parses, to the square of `sin 2θ`.
    assert_eq!(read("(sin 2θ)^2"), read("sin(2*theta)^2"));
}

/// A power written between the function and a multiple of an angle, `sin²2θ`, as physics writes
/// a mixing angle's, reads as the power of `sin 2θ` (it was refused as "expected an angle or
/// '('"): `sin²2θ = (1 − cos 4θ)/2`, by hand; a power after it is still refused as ambiguous.
#[test]
fn a_power_of_a_multiple_angle_reads_as_physics_writes_it() {
    let vars = phase_space();
    let read = |src: &str| Poly::<GaussianRational>::parse(&vars, src);
    for src in ["sin²2θ", "sin² 2θ", "sin² 2 theta", "\\sin^{2} 2\\theta"] {
        assert_eq!(read(src), read("sin(2*theta)^2"), "{src}");
        assert_eq!(read(src), read("(1 - cos(4*theta))/2"), "{src}");
    }
    assert_eq!(read("cos³3θ"), read("cos(3*theta)^3"));
    let err = read("sin²2θ^3").expect_err("sin²2θ^3");
    assert!(err.message().contains("ambiguous"), "{}", err.message());
    let err = read("cos² 2/3θ").expect_err("cos² 2/3θ");
    assert_eq!(
        err.message(),
        "expected an angle after 'cos² 2', as in cos 2θ"
    );
}
