#!/usr/bin/env bash
# Fails, naming the files, if a C++ source differs from what .clang-format
# makes of it (run by .ci/run; fix with clang-format -i FILE).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang-format >/dev/null; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends clang-format >/dev/null
fi
bad=$(git ls-files '*.cc' '*.h' | while read -r f; do
  clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || echo "$f"
done)
if [ -n "$bad" ]; then
  echo "check_format: not formatted with .clang-format:"; echo "$bad" | sed 's/^/  /'
  exit 1
fi
echo "check_format: every C++ file is formatted"
