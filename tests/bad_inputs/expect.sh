# Sourced by this folder's shell tests: one run of demcal checked for its exit code and message.
#   expect_exit CODE NAME FRAGMENT -- DEMCAL ARGUMENTS...
# runs demcal through `launch` (a test may redefine it, e.g. to set a ulimit) under a 60 s
# timeout, prints the command and the output, and sets fail=1 unless the exit code is CODE and
# the output holds FRAGMENT. A run the timeout killed is reported as a hang. Needs $demcal.
launch() { timeout 60 "$demcal" "$@"; }
fail=0
expect_exit() {
  local code=$1 name=$2 fragment=$3
  shift 4
  local output rc
  # Through a pipe, not a file: a ulimit set in `launch` would hold a file to its limit too.
  output=$(launch "$@" 2>&1 </dev/null)
  rc=$?
  echo "[$name] demcal $* -> exit $rc"
  echo "$output"
  if ((rc == 124)); then echo "FAIL [$name]: hung (killed after 60 s)"; fail=1; return; fi
  [[ $rc == "$code" ]] || { echo "FAIL [$name]: exit $rc, expected $code"; fail=1; }
  grep -qF -- "$fragment" <<<"$output" || { echo "FAIL [$name]: missing: $fragment"; fail=1; }
}
