#!/usr/bin/env bash
# After an install under PREFIX: one line for each door the user's shell
# would not find yet, saying exactly what to add. Prints nothing when PATH
# already holds PREFIX/bin and python3 already searches SITE (the Python
# module's directory).
#   install-hints.sh PREFIX [SITE]   (no SITE: no Python module was installed)
set -euo pipefail
prefix="${1%/}"
site="${2:-}"
site="${site%/}"

# ~/.local/bin reads better (and stays right for the profile) as $HOME/.local/bin.
as_typed() {
  case "$1" in
    "$HOME"/*) printf '$HOME%s' "${1#"$HOME"}" ;;
    *) printf '%s' "$1" ;;
  esac
}

case ":$PATH:" in
  *":$prefix/bin:"*) ;;
  *) echo "gab is in $prefix/bin, not on PATH; add: export PATH=\"$(as_typed "$prefix/bin"):\$PATH\"" >&2 ;;
esac

if [ -n "$site" ] && command -v python3 >/dev/null 2>&1 &&
   ! python3 -c 'import os, sys; sys.exit(os.path.realpath(sys.argv[1]) not in [os.path.realpath(p) for p in sys.path])' \
       "$site" 2>/dev/null; then
  echo "python3 does not search $site (the gab module); add: export PYTHONPATH=\"$(as_typed "$site")\${PYTHONPATH:+:\$PYTHONPATH}\"" >&2
fi
