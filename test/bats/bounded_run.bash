# bounded CMD [ARGS...]: runs CMD as bats' `run` does, under a 20 s timeout, a
# 2 GB address-space limit and a 200 MB file-size limit, so that a check that
# regresses (a run that was to be refused at once) fails fast instead of
# eating the machine. AddressSanitizer reserves terabytes of address space,
# so the sanitized pass (TOOLKIT_SANITIZED=1) keeps the timeout and the file
# limit only.
bounded() {
  local memory_limit='ulimit -v 2000000;'
  [ -n "${TOOLKIT_SANITIZED:-}" ] && memory_limit=''
  run bash -c "$memory_limit ulimit -f 204800; exec timeout 20 \"\$@\"" bounded "$@"
}
