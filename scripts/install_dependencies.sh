#!/bin/bash
# Installs what pneuma needs on Debian 12 (deal.II 9.4 with Trilinos, p4est,
# MPI and MUMPS; nlohmann's JSON library for summary.json; numdiff for the tests; Gmsh for meshes; ccache;
# matplotlib for the chamber plots; OpenBLAS, which makes the MUMPS factorizations 5x faster than the
# reference BLAS Debian selects otherwise).
# Does nothing when everything is already there. VTK's Python module (for
# the tests' output checks) comes from python3-vtk9, or from
# python3-paraview where ParaView is installed for pictures
# (scripts/render_state.py): Debian's two packages conflict, so the one
# present is kept.
#
# --pictures also installs ParaView's pvbatch with its Python module and
# xvfb, for the pictures of the scene scripts (about 1 GB; replaces
# python3-vtk9 by python3-paraview).
set -euo pipefail
packages=(build-essential cmake ccache libdeal.ii-dev libmumps-dev libmetis-dev numdiff
          nlohmann-json3-dev
          libopenblas0-pthread
          gmsh openmpi-bin time python3 python3-matplotlib
          clang-format)
case "${1:-}" in
  "") ;;
  --pictures) packages+=(paraview python3-paraview xvfb xauth) ;;
  *) echo "install_dependencies.sh: unknown argument '$1' (known: --pictures)" >&2
     exit 1 ;;
esac
if [ "${1:-}" != --pictures ] &&
   ! dpkg-query -W -f='${Status}' python3-paraview 2>/dev/null |
     grep -q "install ok installed"; then
  packages+=(python3-vtk9)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "Installing: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO=sudo; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
