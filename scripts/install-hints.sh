#!/usr/bin/env bash
# After an install under PREFIX: one line for each door the user's shell
# would not find yet, saying exactly what to add. Prints nothing when PATH
# already holds PREFIX/bin, python3 already searches SITE (the Python
# module's directory) and pkg-config (when installed) finds PREFIX's gab.pc.
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

# pkg-config searches the system's folders, not ~/.local: `pkg-config --libs
# gab` (the README's C example) needs the prefix's pkgconfig folder named.
pc_dir="$prefix/lib/pkgconfig"
if [ -f "$pc_dir/gab.pc" ] && command -v pkg-config >/dev/null 2>&1; then
  found="$(pkg-config --variable=prefix gab 2>/dev/null || true)"
  if [ "${found%/}" != "$prefix" ]; then
    echo "pkg-config does not find $pc_dir/gab.pc; add: export PKG_CONFIG_PATH=\"$(as_typed "$pc_dir")\${PKG_CONFIG_PATH:+:\$PKG_CONFIG_PATH}\"" >&2
  fi
fi
