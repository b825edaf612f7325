#!/bin/bash
# Every C++ file of the project follows the committed .clang-format
# (deal.II's style). Usage: check_format.sh SOURCE_DIR [CLANG_FORMAT]
# Lists the files that are not formatted and exits 1 if there are any;
# `clang-format -i FILE` fixes one.
root="$(realpath -- "$1")"
clang_format="${2:-clang-format}"
cd "$root" || exit 1
fail=0
while IFS= read -r -d '' f; do
  if ! "$clang_format" --style=file --dry-run --Werror "$f" > /dev/null 2>&1; then
    echo "not formatted: $f"
    fail=1
  fi
done < <(find app include source tests benchmarks \( -name '*.cc' -o -name '*.h' \) -print0 | sort -z)
if [ $fail -eq 0 ]; then echo "every C++ file follows .clang-format"; fi
exit $fail
