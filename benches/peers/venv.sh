# shellcheck shell=bash
# Sourced by run.sh and crosscheck.sh: `peers_python MODULE=PACKAGE...` makes the local virtual
# environment `.venv` (once), installs each pinned PACKAGE whose MODULE does not import, and
# sets `python` to the environment's interpreter.
peers_python() {
  local venv here
  here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
  venv="$here/.venv"
  if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
  fi
  local wanted
  for wanted in "$@"; do
    if ! "$venv/bin/python" -c "import ${wanted%%=*}" >/dev/null 2>&1; then
      "$venv/bin/pip" install --quiet "${wanted#*=}"
    fi
  done
  # shellcheck disable=SC2034 # read by the scripts that source this file
  python="$venv/bin/python"
}
