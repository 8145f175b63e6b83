#!/usr/bin/env bash
# One command: installs the peers (python-flint and SymPy, with gmpy2 for SymPy's other ground
# types, in a local virtual environment; Singular from Debian's packages), builds superint, and
# runs the side-by-side comparison.
#   benches/peers/run.sh [--quick] [--repeats N] [--markdown]
#   benches/peers/run.sh --sympy-goal [--repeats N] [--max-cap SECONDS] [--markdown]   (SymPy at the goal sizes, capped at 300x superint)
#   ... [--sympy-ground flint,gmpy]   (SymPy's ground types to run; its figure is the fastest)
#   benches/peers/run.sh --pgo ...   (superint built profile-guided by scripts/pgo.sh, five minutes more)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
# shellcheck source-path=SCRIPTDIR source=venv.sh
source "$here/venv.sh"
peers_python "flint=python-flint==0.9.0" "sympy=sympy==1.14.0" "gmpy2=gmpy2==2.3.2"
if ! command -v Singular >/dev/null 2>&1; then
  if [ "$(id -u)" = 0 ]; then
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq singular >/dev/null
  else
    sudo apt-get update -qq && sudo DEBIAN_FRONTEND=noninteractive apt-get install -y -qq singular >/dev/null
  fi
fi
pgo=no
args=()
for a in "$@"; do
  if [ "$a" = --pgo ]; then pgo=yes; else args+=("$a"); fi
done
if [ "$pgo" = yes ]; then
  SUPERINT_BIN="$("$root/scripts/pgo.sh" | tail -n 1)"
  export SUPERINT_BIN SUPERINT_BUILD="profile-guided, scripts/pgo.sh"
else
  (cd "$root" && cargo build --release --quiet)
fi
PEERS_PYTHON="$python" exec "$python" "$here/compare.py" ${args[@]+"${args[@]}"}
