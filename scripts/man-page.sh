#!/usr/bin/env bash
# Renders one scdoc source to troff: scdoc < SRC > PAGE, then lets every
# table column after the first share the line width ('lx'), so tables of
# long text wrap inside 80 columns instead of overflowing the terminal
# (tbl's default widths for text blocks add up to more than a line).
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 SRC.scd PAGE.1" >&2; exit 2; }
scdoc < "$1" | perl -pe 's/(?<=\s)l(?=[\s.]|$)/lx/g if /^(allbox;)?l( l)+\.?$/' > "$2.tmp"
mv "$2.tmp" "$2"
