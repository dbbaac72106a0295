#!/usr/bin/env bash
# run_pytest.sh PYTHON TESTS_DIR: the Python module's tests; exit 77 (skipped) when pytest or
# numpy is missing, so that a machine without them says so rather than failing.
set -u
python=$1
tests=$2
if ! "$python" -c "import pytest, numpy" 2>/dev/null; then
  echo "SKIPPED: $python has no pytest or numpy (apt-get install python3-pytest python3-numpy)"
  exit 77
fi
exec "$python" -m pytest -q -s -p no:cacheprovider "$tests"
