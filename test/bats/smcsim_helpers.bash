# Shared by smcsim's bats suites (loaded, not a suite itself).

# figures "LABEL ARGS..." ...: one summary per argument (a label, then
# smcsim's options), printed as one JSON object {label: summary, ...}.
figures() {
  local spec label args
  for spec in "$@"; do
    label="${spec%% *}" args=""
    [ "$spec" = "$label" ] || args="${spec#* }"
    # shellcheck disable=SC2086
    smcsim --summary $args > "figure_$label.json" || return 1
  done
  py 'import json, sys
print(json.dumps({label: json.load(open("figure_%s.json" % label)) for label in sys.argv[1:]}))' "${@%% *}"
}

# ivp ARGS...: test/oracle/feed_drive_ivp.py (SciPy's solve_ivp of the
# sampled loop); its exit status 77 means SciPy is missing: skip.
ivp() {
  run /usr/bin/python3 "$TOOLKIT_ROOT/test/oracle/feed_drive_ivp.py" "$@"
  [ "$status" -ne 77 ] || skip "$output"
  echo "$output"
}
