#!/usr/bin/env bash
# Cross-checks superint against SymPy on random expressions (crosscheck.py: brackets, products
# and powers with radicals, denominators, angles and declared brackets, compared at exact
# points, and SymPy's results decided zero by superint). Installs SymPy into the local virtual
# environment and builds superint first.
#   benches/peers/crosscheck.sh [--cases N] [--seed S] [--verbose]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
# shellcheck source-path=SCRIPTDIR source=venv.sh
source "$here/venv.sh"
peers_python "sympy=sympy==1.14.0"
(cd "$root" && cargo build --release --quiet)
exec "$python" "$here/crosscheck.py" "$@"
