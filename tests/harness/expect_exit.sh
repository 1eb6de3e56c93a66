#!/usr/bin/env bash
# expect_exit.sh EXPECTED -- COMMAND...: passes iff COMMAND exits with EXPECTED.
expected=$1
shift 2
"$@"
rc=$?
if [[ $rc != "$expected" ]]; then
  echo "expect_exit: '$*' exited $rc, expected $expected" >&2
  exit 1
fi
echo "expect_exit: exit status $rc as expected"
