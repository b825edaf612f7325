#!/bin/bash
# A full disk is never a success: the run exits 2 with a message naming the
# file it could not write. Mounts a 200 kB tmpfs as the output directory;
# where the machine does not allow that (not root, no mount rights) the
# test is skipped (exit 77, ctest's SKIP_RETURN_CODE).
# Usage: check_disk_full.sh PNEUMA_BINARY SOURCE_DIR
pneuma="$1" src="$2"
dir="$(mktemp -d)"
trap 'umount "$dir" 2>/dev/null; rmdir "$dir"' EXIT
if ! mount -t tmpfs -o size=200k tmpfs "$dir" 2>/dev/null; then
  echo "skipped: cannot mount a small tmpfs here"
  exit 77
fi
out=$("$pneuma" "$src/parameter_files/airbeam.prm" \
        --set "Geometry/Global refinements=3" --set "Output/Quiet=true" \
        --set "Output/Directory=$dir/run" 2>&1)
code=$?
message=$(grep "^pneuma: cannot write" <<<"$out")
if [ $code -ne 2 ] || [ -z "$message" ]; then
  echo "FAIL: exit $code on a full disk, output: $out"
  exit 1
fi
echo "ok: exit 2 on a full disk: $message"
