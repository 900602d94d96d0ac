# bash completion for the toolkit's ten tools, installed once per tool name
# (bash-completion loads completions/NAME when NAME is first completed).
# Options and subcommands come from the tool's own --help (CLI11's layout:
# "  -j,--threads N ..." under a heading, subcommands under "Subcommands:"),
# so they never fall behind the tools. Anything else completes as a file.
_toolkit_complete() {
  local cur=${COMP_WORDS[COMP_CWORD]} tool=${COMP_WORDS[0]} sub="" word help
  # The first word that names one of the tool's subcommands selects its help.
  local subcommands
  subcommands=$("$tool" --help 2>/dev/null | awk '/^Subcommands:/ { on = 1; next } /^[^ ]/ { on = 0 } on && NF { print $1 }')
  for word in "${COMP_WORDS[@]:1:COMP_CWORD-1}"; do
    if grep -qxF -- "$word" <<< "$subcommands"; then sub=$word; break; fi
  done
  if [[ $cur == -* ]]; then
    help=$("$tool" $sub --help 2>/dev/null)
    COMPREPLY=($(compgen -W "$(grep -oE -- '(^|[ ,])--?[A-Za-z0-9][A-Za-z0-9-]*' <<< "$help" | tr -d ' ,' | sort -u)" -- "$cur" || true))
    return 0
  fi
  if [[ -z $sub && -n $subcommands ]]; then
    COMPREPLY=($(compgen -W "$subcommands" -- "$cur" || true))
  fi
  COMPREPLY+=($(compgen -f -- "$cur" || true))
  return 0
}
complete -o filenames -F _toolkit_complete sieve mrtest riesel gcode-pulse dxf2region fuzzyfeed smcsim tnorm-bench subtune threadcalc
