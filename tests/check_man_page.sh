#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The manual page made by help2man: it exists, groff formats it with every warning on and
# prints none, `man -l` renders it, and it lists the products and the example of --help.
#   tests/check_man_page.sh build/lagrange.1
# Exits 77 (ctest: skipped) without groff (Debian package groff-base).
set -euo pipefail
page="$1"
if [ ! -s "$page" ]; then
  echo "error: no manual page at $page" >&2
  exit 1
fi
if ! command -v groff >/dev/null 2>&1; then
  echo "skipped: groff is not installed, so the page cannot be checked" >&2
  exit 77
fi
warnings="$(groff -man -Tutf8 -ww -z "$page" 2>&1)"
if [ -n "$warnings" ]; then
  echo "error: groff warns about $page:" >&2
  echo "$warnings" >&2
  exit 1
fi
text="$(groff -man -Tutf8 -P-c "$page" 2>/dev/null | sed 's/.\x08//g')"
if command -v man >/dev/null 2>&1; then
  text="$(MANWIDTH=80 man -l "$page" 2>&1 | sed 's/.\x08//g')"
fi
for expected in "lagrange" "SYNOPSIS" "--want" "characteristic" "workprecision" "double_pendulum.lag" "SEE ALSO"; do
  if ! grep -qF -- "$expected" <<<"$text"; then
    echo "error: the rendered page lacks \`$expected\`" >&2
    exit 1
  fi
done
echo "man page ok: $page"
