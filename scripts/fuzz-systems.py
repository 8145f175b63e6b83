#!/usr/bin/env python3
"""Mutation fuzzing of superint's system files.

Each case takes a file of systems/, changes one to three of its expressions (a value, a claim,
the Hamiltonian; the TOML around them stays valid) by deleting a few characters, inserting a
token (an operator, a bracket, a huge power, a division by zero, a family index, a radical, a
large power of a sum, a superscript, a LaTeX command, an empty group), copying a piece of
another expression, changing a digit or multiplying a side by a well-formed factor, and runs
a command of superint on it. Every run must end with exit code 0 (proved), 1 (refuted) or 2
(an error, reported), never with a panic, and within the timeout: a hang is a failure too (it
found a quadratic exact division and a quadratic line breaker, each minutes long on a result
of 10^5 terms).

    scripts/fuzz-systems.py --cases 300 --seed 1              # check, in every output format
    scripts/fuzz-systems.py --cases 300 --seed 1 --commands table,search,expand,bracket,rank,closure,tower

A failing case is written to --keep (default /tmp/superint-fuzz) with the command that failed.
Standard library only; superint is built in release mode first unless --binary is given.
"""

import argparse
import os
import random
import re
import subprocess
import sys
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

TOKENS = [
    "^", "^-1", "^-2", "^9999", "^100000000000000000000", "*", "/", "(", ")", "{", "}", ",", "=",
    "sqrt(", "conj(", "re(", "im(", "0", "1/0", "0^0", "0^-1", "i", "theta", "cos(theta)",
    "sin(2*theta)", "p_theta", "rank(", "e^(i*theta)", "x", "y", "99999999999999999999999999999",
    "-", "+", "/(x-y)", "_{1,2}", "_{0,0}", "_{-1,2}", "_{100,100}", "  ", "é", "∂", "H", "{H, x}",
    "{x, {x, H}}", "(x+y)^200", "(1+x+y+p_x+p_y)^30", "sqrt(x)", "1/x", "x^(1/2)", "2/3", "ω", "θ",
    "|", "!", "..", "'",
    # Superscripts, empty groups and LaTeX, which the parser reads beside the plain syntax (a
    # backslash is escaped where a token goes into the file's string, `\\sin`).
    "²", "³", "⁻¹", "⁻", "¹", "⁰", "²³", "⁻²", "{}", "{}^", "{}²", "{}^{2}", "{ }^{3}", "^{2}",
    "^{-1}", "^{", "^2²", "²^3", r"\sin", r"\cos", r"\exp", r"\theta", r"\omega", r"\varphi",
    r"\frac{1}{2}", r"\frac{", r"\tfrac", r"\sqrt{x}", r"\sqrt", r"\partial", r"\nabla", "∇",
    r"\partial H", "(∂H)", "Re(", "Im(", r"\Re", r"\operatorname{Re}", r"\mathrm{i}", r"\bar{Z}",
    r"\bar{}", "sin²", "cos³θ", "sin²θ", "sin²(θ)", r"\sin^{2}", r"\sin^{2}\theta", "x^{2}{}^{3}",
    "Mω^{2}", "Mω^{2}{}^{3}", "e^{", "e^{iθ}", "_{", "_", r"p_{\theta}", r"\,", r"\;", r"\quad",
    r"\left(", r"\right)", r"\left.", r"\left", r"\big(", r"\bigr)", r"\{", r"\}", r"\cdot",
    r"\times", "·", "−", "÷", "**", "\\", r"\unknown", "₁", "1e3", "0.5", "√", "½",
]

# Each command with the arguments it takes after the file.
COMMANDS = {
    "check": [],
    "check-json": [],
    "check-latex": [],
    "check-markdown": [],
    "table": [],
    "search": ["--momenta-degree", "1", "--positions-degree", "1"],
    "expand": ["H"],
    "bracket": ["H", "x"],
    "rank": ["H"],
    "closure": ["H"],
    "tower": ["--max", "2"],
}

# The option before the file, for a command that takes it so (`tower --system FILE`).
FILE_OPTION = {"tower": ["--system"]}

# A line `key = "expression"` of a system file (keys whose strings are prose are left alone).
EXPRESSION = re.compile(
    r'^(\s*(?:value|claim|hamiltonian|eigenvalue|\{[^}]*\})\s*=\s*")([^"\n]*)(".*)$'
)


def mutate(rng, text):
    lines = text.split("\n")
    places = [i for i, line in enumerate(lines) if EXPRESSION.match(line)]
    for _ in range(rng.randint(1, 3)):
        i = rng.choice(places)
        head, s, tail = EXPRESSION.match(lines[i]).groups()
        at = rng.randrange(len(s) + 1)
        op = rng.random()
        digits = [k for k, c in enumerate(s) if c.isdigit()]
        if op < 0.25 and s:
            s = s[:at] + s[at + rng.randint(1, 6):]
        elif op < 0.6:
            s = s[:at] + rng.choice(TOKENS).replace("\\", "\\\\") + s[at:]
        elif op < 0.75:
            other = EXPRESSION.match(lines[rng.choice(places)]).group(2)
            start = rng.randrange(len(other) + 1)
            s = s[:at] + other[start:start + rng.randint(1, 20)] + s[at:]
        elif op < 0.9 and digits:
            # Another number where one stood: the text stays well formed.
            k = rng.choice(digits)
            s = s[:k] + str(rng.randrange(10)) + s[k + 1:]
        else:
            # A well-formed factor on one side: `lhs = rhs` stays a claim.
            side = s.split("=")
            j = rng.randrange(len(side))
            factor = rng.choice(["(1 + x)", "(x - y)^2", "p_x", "2/3", "(1 + x + p_x)^4"])
            side[j] = f"({side[j].strip()})*{factor}" if side[j].strip() else side[j]
            s = " = ".join(x.strip() for x in side)
        lines[i] = head + s + tail
    return "\n".join(lines)


def command_line(binary, command, path):
    name, _, form = command.partition("-")
    line = [binary, name, "--no-timings"]
    if form:
        line += ["--format", form]
    return line + FILE_OPTION.get(name, []) + [path] + COMMANDS[command]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", type=int, default=300)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=60, help="seconds a case may take")
    parser.add_argument("--commands", default="check,check-json,check-latex,check-markdown",
                        help=f"a comma-separated choice of {', '.join(COMMANDS)}")
    parser.add_argument("--binary", help="superint to run (default: build target/release/superint)")
    parser.add_argument("--keep", default="/tmp/superint-fuzz", help="where failing cases go")
    args = parser.parse_args()
    commands = args.commands.split(",")
    unknown = [c for c in commands if c not in COMMANDS]
    if unknown:
        parser.error(f"unknown command {unknown[0]!r}: one of {', '.join(COMMANDS)}")
    binary = args.binary
    if binary is None:
        subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
        binary = str(ROOT / "target" / "release" / "superint")

    rng = random.Random(args.seed)
    seeds = sorted((ROOT / "systems").glob("*.toml"))
    texts = [p.read_text() for p in seeds]
    if os.path.exists(args.keep) and not os.path.isdir(args.keep):
        parser.error(f"--keep {args.keep}: a file is there, not a directory")
    os.makedirs(args.keep, exist_ok=True)
    case = os.path.join(args.keep, "case.toml")
    codes, failures = Counter(), 0
    for n in range(args.cases):
        k = rng.randrange(len(texts))
        command = rng.choice(commands)
        source = mutate(rng, texts[k])
        with open(case, "w") as f:
            f.write(source)
        line = command_line(binary, command, case)
        try:
            run = subprocess.run(line, capture_output=True, text=True, errors="replace",
                                 timeout=args.timeout)
            codes[run.returncode] += 1
            failed = run.returncode not in (0, 1, 2) or "panicked" in run.stderr
            why = f"exit code {run.returncode}: {run.stderr[-500:].strip()}"
        except subprocess.TimeoutExpired:
            codes["timeout"] += 1
            failed, why = True, f"no end within {args.timeout:g} s"
        if failed:
            failures += 1
            kept = os.path.join(args.keep, f"failed-{args.seed}-{n}-{seeds[k].name}")
            with open(kept, "w") as f:
                f.write(source)
            shown = " ".join(line[1:-1 - len(COMMANDS[command])] + [kept] + COMMANDS[command])
            print(f"case {n} ({seeds[k].name}): superint {shown}\n  {why}", flush=True)
    summary = ", ".join(f"{count} exit {code}" for code, count in sorted(codes.items(), key=str))
    print(f"{args.cases} mutated system files (seed {args.seed}): {failures} failed; {summary}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
