#!/bin/bash
# Every bad input must stop before any work with exit code 1 and one
# message that names the offending parameter or file; never a crash.
# Usage: check_bad_input.sh PNEUMA_BINARY CASE_DIRECTORY [WORK_DIRECTORY]
# The valid cases write run output (their Output/Directory is relative) into
# WORK_DIRECTORY (ctest passes build/tests/bad_input), else into a temporary
# directory removed at exit; never into the caller's directory, which may be
# the source tree.
self="$(realpath -- "$0")"
case "$1" in */*) pneuma="$(realpath -- "$1")" ;; *) pneuma="$1" ;; esac
dir="$(realpath -- "$2")"
if [ -n "$3" ]; then
  mkdir -p -- "$3" && cd -- "$3" || exit 1
else
  work="$(mktemp -d)" && cd -- "$work" || exit 1
  trap 'rm -rf -- "$work"' EXIT
fi
fail=0
# No output of any case holds a non-finite number: history.csv fields and
# summary.json values (VTU files are read back at the end).
non_finite() {
  grep -lsE '(^|[,:\[ ])-?(nan|inf|NaN|Infinity)([],} ]|$)' \
    $(find . -name history.csv -o -name summary.json 2>/dev/null)
}
check() { # case-file, expected exit code, text the message must contain
  local out code
  out=$("$pneuma" "${@:4}" "$1" 2>&1)
  code=$?
  # One message: a single line, and never deal.II's multi-line frames.
  if [ "$code" -ne "$2" ] || ! grep -qF -- "$3" <<<"$out" ||
     { [ "$2" -ne 0 ] && [ "$(wc -l <<<"$out")" -ne 1 ]; }; then
    echo "FAIL $(basename -- "$1"): exit $code, message: $out"
    fail=1
  elif [ -n "$(non_finite)" ]; then
    echo "FAIL $(basename -- "$1") $4 $5: non-finite numbers in $(non_finite)"
    fail=1
  else
    echo "ok   $(basename -- "$1"): exit $code: $(head -c 200 <<<"$out" | tr '\n' ' ')"
  fi
}
# The same on 2 MPI ranks: every rank agrees, one message, exit 1, no rank
# left waiting (mpirun's own banner about the exit code is dropped).
check_mpi() { # like check, on 2 ranks (NP=3: on 3)
  local out code
  out=$(timeout 300 mpirun -np "${NP:-2}" "$pneuma" "${@:4}" "$1" 2>&1 |
        sed '/^-\{20,\}$/,/^-\{20,\}$/d'; exit "${PIPESTATUS[0]}")
  code=$?
  if [ "$code" -ne "$2" ] || ! grep -qF -- "$3" <<<"$out" ||
     { [ "$2" -ne 0 ] && [ "$(grep -c . <<<"$out")" -ne 1 ]; }; then
    echo "FAIL (${NP:-2} ranks) $(basename "$1"): exit $code, message: $out"
    fail=1
  else
    echo "ok   (${NP:-2} ranks) $(basename "$1"): exit $code: $(head -c 200 <<<"$out" | tr '\n' ' ')"
  fi
}
check "$dir/unknown_parameter.prm"  1 "Nonexistent entry"
check "$dir/out_of_range.prm"       1 "Polynomial degree"
check "$dir/missing_mesh.prm"       1 "Geometry/gmsh/Mesh file"
check "$dir/empty_region.prm"       1 "Loads/Pressure regions"
check "$dir/empty_region.prm"       1 "Loads/Surface load regions: the mesh has no cells in region 7" --set "Loads/Pressure regions=" --set "Loads/Surface load regions=7"
check_mpi "$dir/empty_region.prm"   1 "Loads/Surface load regions" --set "Loads/Pressure regions=" --set "Loads/Surface load regions=7"
check "$dir/negative_thickness.prm" 1 "Materials/Region 0/Thickness"
check "$dir/bad_load_curve.prm"     1 "Loads/Pressure/Function expression"
check "$dir/missing_boundary.prm"   1 "Boundary conditions/Fixed boundaries"
check "$dir/bad_point.prm"          1 "Boundary conditions/Fixed points"
check "$dir/no_such_file.prm"       1 "cannot open parameter file"
# A JSON input: its layout is read like a .prm file's.
check "$dir/unused_cable.json"      1 "Cables/Cable 2: is not used: Cables/Number of cables is 1"
check "$dir/valid.json"             0 "finished"
check "$dir/valid.json"             1 "Materials/Region 0/neo-Hookean/Shear modulus: must be positive" --set "Materials/Region 0/neo-Hookean/Shear modulus=-1"
check "$dir/valid.prm"              1 "Geometry/disc/Radius" --set "Geometry/disc/Radius=abc"
check "$dir/valid.prm"              1 "Geometry/No such entry" --set "Geometry/No such entry=1"
check "$dir/valid.prm"              1 "Geometry/disc/Radius: must be positive" --set "Geometry/disc/Radius=-1"
check "$dir/valid.prm"              1 "Materials/Region 0/Law" --set "Materials/Region 0/Law=Gnt"
check "$dir/valid.prm"              1 "Materials/Region 7: no cell of the mesh has material id 7" --set "Materials/Region 0/Thickness=1e-3" --set "Materials/Region 7/Thickness=1e-3"
check "$dir/valid.prm"              1 "Materials/Region 1: the mesh has cells with material id 1 but the input has no such subsection" --set "Geometry/Type=closed cylinder"
check "$dir/valid.prm"              1 "Materials/Heating: unknown subsection" --set "Materials/Heating/Power=1"
check "$dir/valid.prm"              1 "Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio: must lie in (-1, 0.5)" --set "Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio=-1"
check "$dir/valid.prm"              1 "Materials/Region 0/Wrinkling residual stiffness: must be below 1e-2" --set "Materials/Region 0/Wrinkling=tension field" --set "Materials/Region 0/Wrinkling residual stiffness=0.5"
check "$dir/valid.prm"              1 "Materials/Region 0/Wrinkling smoothing: The string <-1e-5> does not match" --set "Materials/Region 0/Wrinkling=tension field" --set "Materials/Region 0/Wrinkling smoothing=-1e-5"
check "$dir/valid.prm"              1 "Materials/Region 0/Bending stiffness factor: must be positive" --set "Materials/Region 0/Bending=shell" --set "Materials/Region 0/Bending stiffness factor=0"
check "$dir/valid.prm"              1 "Bending/Interior penalty factor: must be positive" --set "Materials/Region 0/Bending=shell" --set "Bending/Interior penalty factor=-1"
check "$dir/valid.prm"              1 "Bending/Clamped boundaries: the mesh has no boundary 7" --set "Materials/Region 0/Bending=shell" --set "Bending/Clamped boundaries=7"
check "$dir/valid.prm"              1 "Bending/Clamped boundaries: no region is a shell" --set "Bending/Clamped boundaries=0"
check "$dir/valid.prm"              1 "Bending/Edge moment boundaries: the mesh has no boundary 7" --set "Materials/Region 0/Bending=shell" --set "Bending/Edge moment boundaries=7"
check "$dir/valid.prm"              1 "Bending/Edge moment boundaries: no region is a shell" --set "Bending/Edge moment boundaries=0"
check_mpi "$dir/valid.prm"          1 "Bending/Edge moment/Function expression" --set "Materials/Region 0/Bending=shell" --set "Bending/Edge moment boundaries=0" --set "Bending/Edge moment/Function expression=sqrt(-1-x*x)"
check_mpi "$dir/valid.prm"          1 "Materials/Region 0/Membrane strains: assumed strains need Q2 cells" --set "Materials/Region 0/Membrane strains=assumed"
check "$dir/valid.prm"              1 "Loads/Point loads" --set "Loads/Point loads=1, 2"
check_mpi "$dir/valid.prm"          1 "Loads/Point load/Function expression" --set "Loads/Point loads=0, 0, 0" --set "Loads/Point load/Function expression=0; 0; log(-1)"
check "$dir/../tensairity_friction.prm" 1 "Cables/Cable 2/Section semi-axes: a semi-axis of" --set "Cables/Cable 2/Section semi-axes=4294967297" --set "Output/Directory=out_bad"
check "$dir/valid.prm"              1 "Materials/Region 0/Warp direction: must be a non-zero vector" --set "Materials/Region 0/Warp direction=1, x, 0"
check "$dir/valid.prm"              1 "Materials/Region 0/Warp direction: the law 'orthotropic' is anisotropic" --set "Materials/Region 0/Law=orthotropic"
check "$dir/valid.prm"              1 "Materials/Region 0/Warp direction: it is within 6 degrees of the surface normal" --set "Materials/Region 0/Law=orthotropic" --set "Materials/Region 0/Warp direction=0, 0, 1"
check "$dir/valid.prm"              1 "Materials/Region 0/Prestress: must be 'n' or 'n1, n2'" --set "Materials/Region 0/Prestress=1, 2, 3"
check "$dir/valid.prm"              1 "Materials/Region 0/orthotropic/Poisson's ratio: nu12^2 must be below E1/E2" --set "Materials/Region 0/Law=orthotropic" --set "Materials/Region 0/Warp direction=1, 0, 0" --set "Materials/Region 0/orthotropic/Fill modulus=1e11"
# Form finding: a degree-1 mesh, no prestress, lambda out of range, and an
# iteration that runs out of updates (exit 2, the last shape written).
check "$dir/valid.prm"              1 "Discretisation/Polynomial degree: form finding needs degree 2" --set "Form finding/Enabled=true"
check_mpi "$dir/valid.prm"          1 "Materials/Region 0/Prestress: form finding needs a positive prestress" --set "Form finding/Enabled=true" --set "Discretisation/Polynomial degree=2"
check "$dir/valid.prm"              1 "Materials/Region 0/Bending: form finding finds the shape of a membrane" --set "Form finding/Enabled=true" --set "Discretisation/Polynomial degree=2" --set "Materials/Region 0/Prestress=100" --set "Materials/Region 0/Bending=shell"
check "$dir/valid.prm"              1 "Form finding/Homotopy factor: must be in [0, 1)" --set "Form finding/Homotopy factor=1"
check "$dir/valid.prm"              2 "the form finding did not converge in 2 updates" --set "Geometry/Type=open cylinder" --set "Boundary conditions/Fixed boundaries=0: xyz; 1: xyz" --set "Form finding/Enabled=true" --set "Discretisation/Polynomial degree=2" --set "Materials/Region 0/Prestress=100" --set "Form finding/Maximum updates=2"
# Dynamic relaxation: tolerances out of range, a mass below Gershgorin's
# limit, and a relaxation that runs out of iterations (exit 2).
check "$dir/valid.prm"              1 "Dynamic relaxation/Residual tolerance: must be in (0, 1)" --set "Load stepping/Strategy=relaxation" --set "Dynamic relaxation/Residual tolerance=2"
check "$dir/valid.prm"              1 "Mass safety factor" --set "Load stepping/Strategy=relaxation" --set "Dynamic relaxation/Mass safety factor=0.5"
check_mpi "$dir/valid.prm"          2 "the dynamic relaxation failed: no convergence in 3 iterations (Dynamic relaxation/Maximum iterations" --set "Load stepping/Strategy=relaxation" --set "Dynamic relaxation/Maximum iterations=3" --set "Loads/Pressure/Function expression=1000*t"
check "$dir/valid.prm"              1 "Load stepping/Strategy: unknown 'relaxaton'; valid: explicit, relaxation, static" --set "Load stepping/Strategy=relaxaton"
check "$dir/valid.prm"              1 "Boundary conditions/Fixed regions:" --set "Boundary conditions/Fixed regions=0: w"
# Explicit dynamics: no mass, a damping ratio on a flaccid start without its
# frequency (the lowest mode's is not defined there), a
# time step above the stable one, a stage that needs too many steps.
check "$dir/valid.prm"              1 "Load stepping/Strategy: explicit dynamics needs a mass on every free unknown; 123 have none" --set "Load stepping/Strategy=explicit"
check_mpi "$dir/valid.prm"          1 "Load stepping/Strategy: explicit dynamics needs a mass on every free unknown; 123 have none" --set "Load stepping/Strategy=explicit"
check "$dir/valid.prm"              1 "Explicit dynamics/Damping frequency: 0 takes the Damping ratio's frequency from the lowest mode of the state at t = 0, but the tangent there is singular" --set "Load stepping/Strategy=explicit" --set "Materials/Region 0/Density=1000" --set "Explicit dynamics/Damping ratio=0.1"
check_mpi "$dir/valid.prm"          1 "Explicit dynamics/Damping frequency: 0 takes the Damping ratio's frequency from the lowest mode of the state at t = 0, but the tangent there is singular" --set "Load stepping/Strategy=explicit" --set "Materials/Region 0/Density=1000" --set "Explicit dynamics/Damping ratio=0.1"
check "$dir/valid.prm"              1 "Explicit dynamics/Mass scaling time step: The string <-1e-5>" --set "Explicit dynamics/Mass scaling time step=-1e-5"
check "$dir/valid.prm"              1 "Explicit dynamics/Time step: the time step 1 s is above the stable step 6.0268e-06 s" --set "Load stepping/Strategy=explicit" --set "Materials/Region 0/Density=1000" --set "Explicit dynamics/Time step=1"
check_mpi "$dir/valid.prm"          1 "Explicit dynamics/Maximum steps: stage 1 (to t = 1) needs about 184362 steps" --set "Load stepping/Strategy=explicit" --set "Materials/Region 0/Density=1000" --set "Explicit dynamics/Maximum steps=1000"
# A probe off the membrane (on 2 ranks: every rank stops with it).
check_mpi "$dir/valid.prm"          1 "Output/Probe points: point 1 does not lie on the membrane's reference surface" --set "Output/Probe points=0, 0, 0; 0, 0, 7"
check "$dir/valid.prm"              1 "Output/Probe points:" --set "Output/Probe points=0, 0"
check "$dir/valid.prm"              1 "unknown option" --bogus
check "$dir/valid.prm"              0 "finished"
k="$dir/cable_valid.prm"
check "$k" 0 "finished"
check "$k" 1 "Cables/Cable 1/Prestress factor: stages a Prestress force, which is not given" --set "Cables/Cable 1/Prestress factor/Function expression=t"
# A prestress curve that stops being finite during the run (every rank).
check_mpi "$k" 1 "Cables/Cable 1/Prestress factor/Function expression: the prestress force f(t) F is not finite at t = 0.625" --set "Cables/Cable 1/Prestress force=100" --set "Cables/Cable 1/Prestress factor/Function expression=sqrt(0.5-t)" --set "Output/Quiet=true"
check "$dir/valid.prm" 1 "Geometry/Type: the scene has nothing to solve" --set "Geometry/Type=none"
check "$k" 1 "Cables/Cable 1: is not used: Cables/Number of cables is 0" --set "Cables/Number of cables=0"
check "$k" 1 "Cables/Cable 3: is not used: Cables/Number of cables is 1" --set "Cables/Cable 3/Density=1"
check "$k" 1 "Cables/Cable 1/gmsh/Mesh file: cannot open" --set "Cables/Cable 1/Shape=gmsh" --set "Cables/Cable 1/gmsh/Mesh file=no_such_cable.msh"
check "$k" 1 "Cables/Cable 1/gmsh/Mesh file: is empty" --set "Cables/Cable 1/Shape=gmsh"
check "$k" 1 "Cables/Cable 1/polyline/Points: points 1 and 2 coincide" --set "Cables/Cable 1/polyline/Points=0,0,0; 0,0,0"
# A point at 1e300 (found by fuzz_parameters: element lengths overflowed, SIGSEGV on 2 ranks).
check_mpi "$k" 1 "Cables/Cable 1/polyline: the cable spans inf m" --set "Cables/Cable 1/polyline/Points=0,0,0; 5,0,-3; 10,0,1e300"
check "$k" 1 "Cables/Cable 1/ring: the cable spans 2.83e-09 m" --set "Cables/Cable 1/Shape=ring" --set "Cables/Cable 1/Start support=free" --set "Cables/Cable 1/End support=free" --set "Cables/Cable 1/ring/Radius=1e-9"
check "$k" 1 "Cables/Cable 1/Start support: a ring has no ends" --set "Cables/Cable 1/Shape=ring"
check "$k" 1 "Cables/Cable 1/Distributed load/Function expression" --set "Cables/Cable 1/Distributed load/Function expression=0; sin(; 0"
check "$k" 1 "Cables/Cable 1/Unstressed length: give either" --set "Cables/Cable 1/Prestress force=10" --set "Cables/Cable 1/Unstressed length=3"
check "$k" 1 "Cables/Cable 1/Number of elements: a ring needs at least 3 elements" --set "Cables/Cable 1/Shape=ring" --set "Cables/Cable 1/Number of elements=2"
check "$k" 1 "Cables/Cable 1/End moment: Element = cable carries no moment" --set "Cables/Cable 1/End moment/Function expression=0; 0; 1"
check "$k" 1 "Cables/Cable 1/helix/Pitch: a helix needs" --set "Cables/Cable 1/Shape=helix"
check "$k" 1 "Cables/Cable 1/Element: The string <truss> does not match" --set "Cables/Cable 1/Element=truss"
check "$k" 1 "Cables/Cable 1/solid beam/Poisson's ratio: must lie in (-1, 0.5)" --set "Cables/Cable 1/Element=solid beam" --set "Cables/Cable 1/solid beam/Poisson's ratio=-1"
check "$k" 1 "Cables/Cable 1/ring/Axis: the axis must not be zero" --set "Cables/Cable 1/Shape=ring" --set "Cables/Cable 1/ring/Axis=0, 0, 0"
check "$k" 1 "Cables/Cable 1/solid beam/Section axis: is parallel to the cable" --set "Cables/Cable 1/Element=solid beam" --set "Cables/Cable 1/solid beam/Section axis=1, 0, 0"
check "$k" 1 "Cables/Cable 1/Points" --set "Cables/Cable 1/Points=0, 0, 0; 1, 0, 0"
check "$k" 1 "Contact/Number of pairs: contact needs a membrane" --set "Contact/Number of pairs=1"
check "$dir/valid.prm" 1 "Contact/Pair 1/Cable: there is no cable 1" --set "Contact/Number of pairs=1"
# Curved Gmsh regions: the vertices must lie on the declared surface.
g=(--set "Geometry/Type=gmsh" --set "Geometry/gmsh/Mesh file=$dir/../../meshes/two_spheres.msh" --set "Materials/Region 1/Thickness=1e-3")
check "$dir/valid.prm" 1 "Geometry/gmsh/Curved regions: item 1: the vertices lie between" "${g[@]}" --set "Geometry/gmsh/Curved regions=0: sphere 1,0,0"
check_mpi "$dir/valid.prm" 1 "Geometry/gmsh/Curved regions: item 2: the vertices lie between" "${g[@]}" --set "Geometry/gmsh/Curved regions=0: sphere 0,0,0; 1: cylinder 3,0,0, 1,0,0"
check "$dir/valid.prm" 1 "Geometry/gmsh/Curved regions: the mesh has no cells in the regions of item 1" "${g[@]}" --set "Geometry/gmsh/Curved regions=5: sphere 0,0,0"
check "$dir/valid.prm" 1 "Geometry/gmsh/Curved regions: '0: cone 0,0,0': give" "${g[@]}" --set "Geometry/gmsh/Curved regions=0: cone 0,0,0"
# Ties: a cable hanging from the disc's centre.
t=(--set "Cables/Number of cables=1" --set "Cables/Cable 1/polyline/Points=0, 0, 0; 0, 0, -0.1" --set "Cables/Cable 1/End support=fixed" --set "Ties/Number of ties=1")
check "$k" 1 "Ties/Number of ties: ties need a membrane" --set "Ties/Number of ties=1"
check "$dir/valid.prm" 1 "Ties/Number of ties: ties need cables" --set "Ties/Number of ties=1"
check "$dir/valid.prm" 1 "Ties/Tie 1/Cable: there is no cable 2" "${t[@]}" --set "Ties/Tie 1/Cable=2"
check "$dir/valid.prm" 1 "Ties/Tie 1/Nodes: ties a supported end of Cables/Cable 1" "${t[@]}" --set "Ties/Tie 1/Nodes=both ends"
check "$dir/valid.prm" 1 "Ties/Tie 1/Maximum distance: the node at (0 0 0.05) of Cables/Cable 1 has no membrane point within the maximum distance 0.005000 m" "${t[@]}" --set "Ties/Tie 1/Nodes=start" --set "Cables/Cable 1/polyline/Points=0, 0, 0.05; 0, 0, -0.1"
check "$dir/valid.prm" 1 "Ties/Tie 1/Nodes: Cables/Cable 1 is closed" "${t[@]}" --set "Cables/Cable 1/Shape=ring" --set "Cables/Cable 1/ring/Radius=0.05" --set "Cables/Cable 1/End support=free"
check_mpi "$dir/valid.prm" 1 "Ties/Tie 1/Membrane regions: the mesh has no cells in region 7" "${t[@]}" --set "Ties/Tie 1/Nodes=start" --set "Ties/Tie 1/Membrane regions=7"
c="$dir/chamber_valid.prm"
check "$c" 1 "Chambers/Chamber 1/Regions: the oriented walls do not close" --set "Chambers/Chamber 1/Regions=0, 1"
check "$c" 1 "flipping region 1 or 2 closes it" --set "Chambers/Chamber 1/Regions=0, -1, 2"
check "$c" 1 "walls face into the chamber" --set "Chambers/Chamber 1/Regions=-0, -1, -2"
check "$c" 1 "no cells in region 7" --set "Chambers/Chamber 1/Regions=0, 1, 2, 7"
check "$c" 1 "'x' is not a material id" --set "Chambers/Chamber 1/Regions=0, x"
# A prescribed level above a closed chamber's top (the tube reaches z = 0.23).
check "$c" 1 "Chambers/Chamber 1/Liquid/Level: the level 0.5 m at t = 0 is at or above the chamber's top" --set "Chambers/Chamber 1/Filling=liquid" --set "Chambers/Chamber 1/Liquid/Control=level" --set "Chambers/Chamber 1/Liquid/Level/Function expression=0.5"
check "$c" 1 "Chambers/Chamber 1/Connected to" --set "Chambers/Chamber 1/Filling=connected"
check "$c" 1 "Chambers/Chamber 1/Gas/Gas amount/Function expression" --set "Chambers/Chamber 1/Gas/Gas amount/Function expression=1+*t"
check "$c" 1 "Chambers/Chamber 1/Gas/Control" --set "Chambers/Chamber 1/Filling=liquid and gas" --set "Chambers/Chamber 1/Gas/Control=volume"
check "$c" 1 "Chambers/Chamber 1/Liquid/Volume: the liquid volume 1 m^3 at t = 0 does not fit" --set "Chambers/Chamber 1/Filling=liquid" --set "Chambers/Chamber 1/Liquid/Volume/Function expression=1"
check "$c" 2 "does not fit" --set "Chambers/Chamber 1/Filling=liquid" --set "Chambers/Chamber 1/Liquid/Volume/Function expression=t"
check "$c" 0 "finished"
check "$c" 0 "finished" --set "Chambers/Chamber 1/Gas/Law=isothermal"
check "$c" 1 "Chambers/Chamber 1/Gas/Law: The string <ideal> does not match" --set "Chambers/Chamber 1/Gas/Law=ideal"
check "$c" 1 "Chambers/Chamber 1/Gas/adiabatic/Exponent" --set "Chambers/Chamber 1/Gas/adiabatic/Exponent=0.5"
check "$c" 1 "Chambers/Chamber 1/Gas/Adiabatic exponent" --set "Chambers/Chamber 1/Gas/Adiabatic exponent=1.4"
check "$dir/valid.prm" 1 "Linear solver/direct/Ordering" --set "Linear solver/direct/Ordering=nested"
check "$dir/valid.prm" 1 "Linear solver/MUMPS ordering" --set "Linear solver/MUMPS ordering=amd"
g=(--set "Geometry/Type=gmsh" --set "Boundary conditions/Rigid regions=" --set "Boundary conditions/Fixed points=")
check "$dir/valid.prm" 1 "triangles.msh': holds triangles" "${g[@]}" --set "Geometry/gmsh/Mesh file=$dir/triangles.msh"
check "$dir/valid.prm" 1 "binary.msh': is a binary Gmsh file" "${g[@]}" --set "Geometry/gmsh/Mesh file=$dir/binary.msh"
check "$dir/valid.prm" 1 "version3.msh': has the unsupported MSH version" "${g[@]}" --set "Geometry/gmsh/Mesh file=$dir/version3.msh"
check "$dir/valid.prm" 1 "truncated.msh': ends before the last node" "${g[@]}" --set "Geometry/gmsh/Mesh file=$dir/truncated.msh"
check "$dir/valid.prm" 1 "not_a_mesh.msh': is not a Gmsh mesh" "${g[@]}" --set "Geometry/gmsh/Mesh file=$dir/not_a_mesh.msh"
check "$dir/valid.prm" 1 "unknown_node.msh': an element refers to the unknown node 9" "${g[@]}" --set "Geometry/gmsh/Mesh file=$dir/unknown_node.msh"
w="$dir/../../parameter_files/waterbeam_filling.prm"
# Friction that is not a number of the allowed range.
check "$dir/../../parameter_files/sheet_dragged.prm" 1 "Obstacles/Obstacle 1/Friction coefficient" --set "Obstacles/Obstacle 1/Friction coefficient=-0.3"
check "$dir/../../parameter_files/sheet_dragged.prm" 1 "Obstacles/Obstacle 1/Tangential penalty" --set "Obstacles/Obstacle 1/Tangential penalty=abc"
# An open chamber closed along gravity (a slice) whose wall faces in.
check "$dir/../../parameter_files/geotube.prm" 1 "Chambers/Chamber 1/Regions: the walls face into the chamber (the volume they close between its vertical cuts is -0.007958 m^3)" --set "Geometry/gmsh/Mesh file=$dir/../../meshes/geotube_slice.msh" --set "Chambers/Chamber 1/Regions=-1"
# Numbers that are not finite at the start are bad input.
for e in "sqrt(-1)" "1/0" "log(0)"; do
  check "$dir/valid.prm"            1 "Loads/Pressure/Function expression: is not finite at t = 0" --set "Loads/Pressure/Function expression=$e"
done
check "$dir/valid.prm"              1 "Loads/Pressure/Function constants: expected name=value" --set "Loads/Pressure/Function constants=p0" --set "Loads/Pressure/Function expression=p0*t"
check "$dir/valid.prm"              1 "Loads/Pressure/Function constants: expected name=value with a finite number" --set "Loads/Pressure/Function constants=p0=nan" --set "Loads/Pressure/Function expression=p0*t"
check "$dir/valid.prm"              1 "Loads/Gravity vector/Function expression: '0; 0; log(-t)' is not finite at t = 0" --set "Loads/Gravity=true" --set "Loads/Gravity vector/Function expression=0; 0; log(-t)"
check "$dir/valid.prm"              1 "Loads/Surface traction/Function expression: is not finite" --set "Loads/Surface load=true" --set "Loads/Surface traction/Function expression=0; 0; 1/(x-x)"
check "$c"                          1 "Chambers/Ambient pressure: must be positive" --set "Chambers/Ambient pressure=0"
check "$c"                          1 "Chambers/Chamber 1/Gas/Gas amount/Function expression: '1/t' is not finite at t = 0" --set "Chambers/Chamber 1/Gas/Gas amount/Function expression=1/t"
check_mpi "$dir/valid.prm"          1 "Loads/Pressure/Function expression: is not finite at t = 0" --set "Loads/Pressure/Function expression=sqrt(x-1)"
# Accepted silently before.
check "$c"                          1 "Boundary conditions/Rigid regions: the mesh has no cells in region 42" --set "Boundary conditions/Rigid regions=1, 2+42"
check "$dir/valid.prm"              1 "Output/Monitor points: 'nan,0,0' is not a finite point" --set "Output/Monitor points=nan,0,0"
touch empty.prm
check "empty.prm"                   1 "empty.prm: sets no parameter"
# --set alone does not make a scene: the file is still empty.
check "empty.prm"                   1 "empty.prm: sets no parameter (an empty file?)" --set "Geometry/Type=disc"
# JSON values that are not one string or number name the entry.
printf '{"Geometry": {"Type": "disc", "Global refinements": "1", "disc": {"Radius": true}},\n "Boundary conditions": {"Fixed boundaries": "0: xyz"}}\n' > wrong_type.json
check "wrong_type.json"             1 "Geometry/disc/Radius: The string <true> does not match"
printf '{"Geometry": {"Type": "disc", "Global refinements": "1", "disc": {"Radius": [0.1, 0.2]}},\n "Boundary conditions": {"Fixed boundaries": "0: xyz"}}\n' > array.json
check "array.json"                  1 "Geometry/disc/Radius: is a JSON array; give the value as one string or number"
check_mpi "array.json"              1 "Geometry/disc/Radius: is a JSON array"
printf '[{"Geometry": {"Type": "disc"}}]\n' > top_array.json
check "top_array.json"              1 "top_array.json: is a JSON array, not an object of subsections and entries"
check "$dir/valid.prm"              1 "Adaptive refinement/Refine fraction: plus Adaptive refinement/Coarsen fraction must be at most 1" --set "Adaptive refinement/Refine fraction=0.7" --set "Adaptive refinement/Coarsen fraction=0.6"
# An input error found once the run has started leaves no output of the
# run but a summary.json that records it.
only_summary() { # directory
  if [ "$(ls -A "$1")" != "summary.json" ] || ! grep -q '"exit_code": 1' "$1/summary.json"; then
    echo "FAIL input error in $1: left $(ls -A "$1" | tr '\n' ' ')"
    fail=1
  else
    echo "ok   input error in $1: only summary.json, exit_code 1"
  fi
}
check "$k"                          1 "Cables/Cable 1/Prestress factor/Function expression: the prestress force f(t) F is not finite at t = 0.625" --set "Output/Directory=input-error-1" --set "Output/Write VTU=true" --set "Cables/Cable 1/Prestress force=100" --set "Cables/Cable 1/Prestress factor/Function expression=sqrt(0.5-t)" --set "Output/Quiet=true"
only_summary input-error-1
check_mpi "$c"                      1 "walls face into the chamber" --set "Output/Directory=input-error-2" --set "Chambers/Chamber 1/Regions=-0, -1, -2"
only_summary input-error-2
check "$dir"                        1 "is a directory, not a parameter file"
check "$k"                          1 "Contact/Pair 1/Membrane regions: the mesh has no cells in region 5" --set "Geometry/Type=disc" --set "Contact/Number of pairs=1" --set "Contact/Pair 1/Membrane regions=0, 5"
check "$k"                          1 "Contact/Pair 1/Smoothed normal from: needs Master normal = smoothed" --set "Geometry/Type=disc" --set "Contact/Number of pairs=1" --set "Contact/Pair 1/Smoothed normal from=1"
# Rigid obstacles: regions, directions, penalties and a start inside one.
o=(--set "Obstacles/Number of obstacles=1" --set "Obstacles/Obstacle 1/plane/Point=0, 0, -0.01")
check "$dir/valid.prm"              1 "Obstacles/Obstacle 1/Regions: the mesh has no cells in region 5" "${o[@]}" --set "Obstacles/Obstacle 1/Regions=0, 5"
check "$dir/valid.prm"              1 "Obstacles/Obstacle 1/plane/Normal: '0, 0, 0' is not a direction" "${o[@]}" --set "Obstacles/Obstacle 1/plane/Normal=0, 0, 0"
check "$dir/valid.prm"              1 "Penalty" "${o[@]}" --set "Obstacles/Obstacle 1/Penalty=-1"
check "$dir/valid.prm"              1 "Obstacles/Obstacle 1/Penalty factor: must be positive and finite when Penalty is 0" "${o[@]}" --set "Obstacles/Obstacle 1/Penalty factor=0"
check "$dir/valid.prm"              1 "Obstacles/Obstacle 1/sphere/Radius: must be positive and finite" "${o[@]}" --set "Obstacles/Obstacle 1/Shape=sphere" --set "Obstacles/Obstacle 1/sphere/Radius=0"
check "$dir/valid.prm"              1 "Shape" "${o[@]}" --set "Obstacles/Obstacle 1/Shape=cube"
check "$dir/valid.prm"              1 "Obstacle 2" "${o[@]}" --set "Obstacles/Obstacle 2/Penalty=1"
check "$dir/valid.prm"              1 "Obstacles/Obstacle 1: the membrane starts inside the obstacle" --set "Obstacles/Number of obstacles=1"
check_mpi "$dir/valid.prm"          1 "Obstacles/Obstacle 1: the membrane starts inside the obstacle" --set "Obstacles/Number of obstacles=1"
# Rigid bodies from Gmsh: a missing file, one without surface cells, a
# surface that is not a manifold (the waterbeam's junction lines), and a
# body the membrane starts in (the slab through the square at z = 0).
g=(--set "Obstacles/Number of obstacles=1" --set "Obstacles/Obstacle 1/Shape=gmsh")
check "$dir/valid.prm"              1 "Obstacles/Obstacle 1/gmsh/Mesh file: cannot open the mesh file 'no_such.msh'" "${g[@]}" --set "Obstacles/Obstacle 1/gmsh/Mesh file=no_such.msh"
check "$dir/valid.prm"              1 "catenary_line.msh' holds no triangles or quadrilaterals" "${g[@]}" --set "Obstacles/Obstacle 1/gmsh/Mesh file=$dir/../../meshes/catenary_line.msh"
check "$dir/valid.prm"              1 "triangles; a rigid surface must be a manifold" "${g[@]}" --set "Obstacles/Obstacle 1/gmsh/Mesh file=$dir/../../meshes/waterbeam.msh"
check_mpi "$dir/valid.prm"          1 "Obstacles/Obstacle 1: the membrane starts inside the obstacle" "${g[@]}" --set "Obstacles/Obstacle 1/gmsh/Mesh file=$dir/../../meshes/obstacle_slab.msh" --set "Obstacles/Obstacle 1/Displacement/Function expression=0; 0; -0.05"
# Obstacles loaded by a force: a zero direction, a strategy without a
# matrix (their positions have no value for a given field).
f="$dir/../../parameter_files/tube_pressed_by_force.prm"
fq=(--set "Output/Quiet=true" --set "Output/Directory=out_bad")
check "$f"                          1 "Obstacles/Obstacle 1/Force direction: '0, 0, 0' is not a direction" "${fq[@]}" --set "Obstacles/Obstacle 1/Force direction=0, 0, 0"
check "$f"                          1 "Load stepping/Strategy: explicit dynamics cannot follow the border unknowns of the obstacles" "${fq[@]}" --set "Load stepping/Strategy=static, explicit"
check_mpi "$f"                      1 "Load stepping/Strategy: the relaxation cannot follow the border unknowns of the obstacles" "${fq[@]}" --set "Load stepping/Strategy=static, relaxation"
# Membrane-to-membrane contact: regions, penalties, and membranes that
# overlap at the start (meshes/two_sheets.msh: 0.5 mm apart, t = 1 mm).
surface=(--set "Surface contact/Number of pairs=1")
check "$dir/valid.prm"              1 "Surface contact/Pair 1/Opposite regions: the mesh has no cells in region 5" "${surface[@]}" --set "Surface contact/Pair 1/Regions=0" --set "Surface contact/Pair 1/Opposite regions=5"
check "$dir/valid.prm"              1 "Surface contact/Pair 1/Opposite regions: region 0 is on both sides" "${surface[@]}" --set "Surface contact/Pair 1/Regions=0" --set "Surface contact/Pair 1/Opposite regions=0"
check "$dir/valid.prm"              1 "Surface contact/Pair 1/Penalty" "${surface[@]}" --set "Surface contact/Pair 1/Penalty=-1"
check "$dir/valid.prm"              1 "Surface contact/Pair 1/Penalty factor: must be positive and finite when Penalty is 0" "${surface[@]}" --set "Surface contact/Pair 1/Penalty factor=0"
check "$dir/valid.prm"              1 "Surface contact/Pair 2" "${surface[@]}" --set "Surface contact/Pair 2/Penalty=1"
overlap=("${surface[@]}" --set "Geometry/Type=gmsh" --set "Geometry/gmsh/Mesh file=$dir/../../meshes/two_sheets.msh" --set "Materials/Region 1/Thickness=1e-3" --set "Materials/Region 2/Thickness=1e-3" --set "Surface contact/Pair 1/Regions=1" --set "Surface contact/Pair 1/Opposite regions=2")
check "$dir/valid.prm"              1 "Surface contact/Pair 1: the point" "${overlap[@]}"
check_mpi "$dir/valid.prm"          1 "the membranes overlap at the start" "${overlap[@]}"
check "$dir/valid.prm"              0 "" "${o[@]}"
# Ill-posed scenes: free rigid-body motions, named before any work.
check "$dir/valid.prm"              1 "Boundary conditions: the membrane is free to move as a rigid body (translation along x; translation along y; translation along z; rotation about x" --set "Boundary conditions/Fixed boundaries="
check "$w"                          1 "the membrane is free to move as a rigid body (translation along y" --set "Geometry/gmsh/Mesh file=$dir/../../meshes/waterbeam.msh" --set "Boundary conditions/Fixed points=0,0,0: xyz"
check "$k"                          1 "Cables/Cable 1: has no support (Start support and End support are free) and no contact pair or tie holds it" --set "Cables/Cable 1/Start support=free" --set "Cables/Cable 1/End support=free"
check "$k"                          1 "Cables/Cable 2: has no support" --set "Cables/Number of cables=2"
mkdir -p not_a_directory/history.csv
check_mpi "$dir/valid.prm"          1 "Output/Directory: cannot write into" --set "Output/Directory=not_a_directory"
check_mpi "$dir/valid.prm"          1 "Materials/Region 7: no cell of the mesh has material id 7" --set "Materials/Region 0/Thickness=1e-3" --set "Materials/Region 7/Thickness=1e-3"
check_mpi "$dir/valid.prm"          1 "Geometry/disc/Radius: must be positive" --set "Geometry/disc/Radius=-1"
check_mpi "$k"                      1 "Cables/Cable 3: is not used" --set "Cables/Cable 3/Density=1"
check_mpi "$c"                      1 "walls face into the chamber" --set "Chambers/Chamber 1/Regions=-0, -1, -2"
check_mpi "$dir/valid.prm"          0 "finished"
# Parameters: patterns, ranges, command line.
check "$dir/valid.prm"              1 "Materials/Region 0/Thickness: The string <nan> does not match" --set "Materials/Region 0/Thickness=nan"
check "$dir/valid.prm"              1 "Materials/Region 0/Thickness: The string <inf> does not match" --set "Materials/Region 0/Thickness=inf"
check "$dir/valid.prm"              1 "Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus: must be positive" --set "Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus=0"
check "$dir/valid.prm"              1 "Materials/Region 0/neo-Hookean/Shear modulus: The string <inf>" --set "Materials/Region 0/Law=neo-Hookean" --set "Materials/Region 0/neo-Hookean/Shear modulus=inf"
check "$dir/valid.prm"              1 "Load stepping/Initial increment: must be > 0" --set "Load stepping/Initial increment=0"
check "$dir/valid.prm"              1 "Load stepping/Initial increment: The string <nan>" --set "Load stepping/Initial increment=nan"
check "$dir/valid.prm"              1 "Load stepping/Minimum increment: must be > 0 and <= Initial increment" --set "Load stepping/Minimum increment=0.5" --set "Load stepping/Initial increment=0.1"
check "$dir/valid.prm"              1 "Load stepping/Stage ends: no such entry (pneuma --print-parameters lists them all)" --set "Load stepping/Stage ends=1, 0.5"
check "$dir/valid.prm"              1 "Newton/Maximum iterations: The string <0>" --set "Newton/Maximum iterations=0"
check "$dir/valid.prm"              1 "Newton/Residual tolerance: The string <-1>" --set "Newton/Residual tolerance=-1"
check "$dir/valid.prm"              1 "Output/VTU interval: The string <-1>" --set "Output/VTU interval=-1"
check "$dir/valid.prm"              1 "Output/Monitor points: '1,2' is not of the form x, y, z" --set "Output/Monitor points=1,2"
check "$dir/valid.prm"              1 "Output/Directory: must not be empty" --set "Output/Directory="
check "$dir/valid.prm"              1 "Discretisation/Polynomial degree: The string <0>" --set "Discretisation/Polynomial degree=0"
check "$dir/valid.prm"              1 "more than one parameter file given" "$dir/valid.prm"
check "$dir/valid.prm"              1 "--set Geometry: expected Path/To/Entry=value" --set "Geometry"
check "$dir/valid.prm"              1 "--set =1: empty parameter path" --set "=1"
check "$dir/valid.prm"              1 "Loads/Pressure regions: The string <x>" --set "Loads/Pressure regions=x"
check "$dir/valid.prm"              1 "Boundary conditions/Fixed boundaries: component 'w' is not one of x, y, z" --set "Boundary conditions/Fixed boundaries=0: xyw"
check "$dir/valid.prm"              1 "Boundary conditions/Fixed points: 'nan,0,0' is not a finite point" --set "Boundary conditions/Fixed points=nan,0,0: xyz"
check "$k"                          1 "Cables/Cable 1/Number of elements: The string <0>" --set "Cables/Cable 1/Number of elements=0"
check "$k"                          1 "Cables/Cable 1/Section semi-axes: The string <-0.01>" --set "Cables/Cable 1/Section semi-axes=-0.01"
check "$k"                          1 "Cables/Cable 1/Young's modulus: must be > 0" --set "Cables/Cable 1/Young's modulus=0"
check "$k"                          1 "Cables/Cable 1/Young's modulus: must be > 0 and at most 1e14 Pa" --set "Cables/Cable 1/Young's modulus=1e300"
check "$k"                          1 "Cables/Cable 1/Prestress force: The string <nan>" --set "Cables/Cable 1/Prestress force=nan"
check "$k"                          1 "Cables/Cable 1/Shape: The string <spiral>" --set "Cables/Cable 1/Shape=spiral"
check "$k"                          1 "Cables/Cable 1/Start support: The string <glued>" --set "Cables/Cable 1/Start support=glued"
check "$c"                          1 "Chambers/Chamber 1/Regions: is empty: a chamber needs walls" --set "Chambers/Chamber 1/Regions="
check "$c"                          1 "Chambers/Chamber 2/Regions: is empty: a chamber needs walls" --set "Chambers/Number of chambers=2"
check "$c"                          1 "Chambers/Chamber 1/Liquid/Density: The string <-1000>" --set "Chambers/Chamber 1/Filling=liquid" --set "Chambers/Chamber 1/Liquid/Density=-1000"
check "$c"                          1 "Chambers/Chamber 1/Filling: The string <water>" --set "Chambers/Chamber 1/Filling=water"
check "$c"                          1 "Chambers/Ambient pressure: The string <inf>" --set "Chambers/Ambient pressure=inf"
# Cable loads that are not finite at t = 0.
check "$k"                          1 "Cables/Cable 1/Distributed load/Function expression: is not finite at t = 0" --set "Cables/Cable 1/Distributed load/Function expression=0; 0; 1/t"
check "$k"                          1 "Cables/Cable 1/End force/Function expression: '0; 0; log(t)' is not finite at t = 0" --set "Cables/Cable 1/End force/Function expression=0; 0; log(t)"
check "$k"                          1 "Cables/Cable 1/Start displacement/Function expression: '0; 0; 1/t' is not finite" --set "Cables/Cable 1/Start displacement/Function expression=0; 0; 1/t"
# A load that becomes infinite later: exit 2 with the last finite state.
check "$dir/valid.prm"              2 "could not be completed at t = 0.375 even with the minimum increment 0.1 (residual is not finite). The last converged state (t = 0.375) is written." --set "Output/Directory=late" --set "Output/Write VTU=true" --set "Loads/Pressure/Function expression=100*t+1/(0.5-t)" --set "Load stepping/Growth factor=1" --set "Load stepping/Cut-back factor=0.5" --set "Load stepping/Minimum increment=0.1"
# Sizes: lengths in metres, the size guard.
check "$dir/valid.prm"              1 "Geometry/disc/Radius: is 1e+300 m; lengths are in metres (at most 1e6 m)" --set "Geometry/disc/Radius=1e300"
check "$dir/valid.prm"              1 "Geometry/disc: the membrane spans 2.83e-09 m" --set "Geometry/disc/Radius=1e-9"
check "$dir/valid.prm"              1 "Geometry/Global refinements: 12 refinements of 12 coarse cells make 2.01e+08 cells and about 6.04e+08 unknowns, which need about" --set "Geometry/Global refinements=12"
check "$dir/valid.prm"              1 "Geometry/Global refinements: 1 refinements of 12 coarse cells make 48 cells and about 144 unknowns, which need about 0.2 GB of memory; the limit is 0.001 GB" --set "Geometry/Memory limit=0.001"
check "$dir/valid.prm"              1 "Geometry/Global refinements: The string <13>" --set "Geometry/Global refinements=13"
NP=3 check_mpi "$dir/valid.prm"     1 "Geometry/Global refinements: 12 refinements" --set "Geometry/Global refinements=12"
# Path following (Load stepping/Control and Path following).
check "$dir/valid.prm"              1 "Load stepping/Control: needs one entry, or one per stage" --set "Load stepping/Control=load, arc-length"
check "$dir/valid.prm"              1 "Load stepping/Control: The string <riks> does not match" --set "Load stepping/Control=riks"
check "$dir/valid.prm"              1 "Load stepping/Maximum increment: needs one value, or one per stage (1 stages in Stage end times), not 2" --set "Load stepping/Maximum increment=0.5, 0.25"
check "$dir/valid.prm"              1 "Load stepping/Maximum increment: must be >= Minimum increment in every stage" --set "Load stepping/Stage end times=1, 2" --set "Load stepping/Maximum increment=0.5, 1e-6"
check "$dir/valid.prm"              1 "Load stepping/Path following/Target monitor value: must be a finite number or empty, not 'far'" --set "Load stepping/Control=arc-length" --set "Load stepping/Path following/Target monitor value=far"
check "$dir/valid.prm"              1 "Target monitor value: applies to the last stage, which is under load control" --set "Load stepping/Path following/Target monitor value=0.01"
check "$dir/valid.prm"              1 "Load stepping/Path following/Monitor point: displacement control needs a monitor point" --set "Load stepping/Control=displacement"
check "$dir/valid.prm"              1 "Load stepping/Path following/Monitor point: a target monitor value needs a monitor point" --set "Load stepping/Control=arc-length" --set "Load stepping/Path following/Target monitor value=0.01"
check "$dir/valid.prm"              1 "Load stepping/Path following/Monitor point: no such monitor point: it is 3, but Output/Monitor points has 1 point(s), numbered from 0" --set "Output/Monitor points=0,0,0" --set "Load stepping/Path following/Monitor point=3"
check_mpi "$dir/valid.prm"          1 "Load stepping/Path following/Monitor point: no such monitor point: it is 3" --set "Output/Monitor points=0,0,0" --set "Load stepping/Path following/Monitor point=3"
check "$dir/valid.prm"              1 "Load stepping/Control: stage 2 is path-controlled, but no load changes in it" --set "Loads/Pressure/Function expression=100*min(t,1)" --set "Load stepping/Stage end times=1, 2" --set "Load stepping/Control=load, arc-length"
check "$dir/valid.prm"              1 "Load stepping/Control: stage 1 is path-controlled, but prescribed displacements change in it" --set "Load stepping/Control=arc-length" --set "Boundary conditions/Fixed boundaries=" --set "Boundary conditions/Prescribed displacement boundaries=0" --set "Boundary conditions/Prescribed displacement/Function expression=0; 0; 0.01*t"
# A target the path never reaches: exit 2 with the last state (the run's
# monitor line comes before the message).
out=$("$pneuma" "$dir/valid.prm" --set "Output/Directory=unreached" --set "Loads/Pressure/Function expression=100*t" --set "Load stepping/Stage end times=0.5, 2" --set "Load stepping/Control=load, arc-length" --set "Load stepping/Maximum increment=0.25" --set "Load stepping/Path following/Target monitor value=1" --set "Load stepping/Path following/Maximum steps=3" --set "Output/Monitor points=0,0,0" 2>&1)
code=$?
if [ "$code" -ne 2 ] || ! grep -qF "stage 2 did not reach its end (the target monitor value 1.000000 or t = 2) in 3 steps (Load stepping/Path following/Maximum steps)" <<<"$out" || [ -n "$(non_finite)" ] || [ ! -s unreached/summary.json ]; then
  echo "FAIL unreached target: exit $code, message: $out"
  fail=1
else
  echo "ok   unreached target: exit $code: $(tail -n 1 <<<"$out" | head -c 200)"
fi
check_mpi "$dir/valid.prm"          1 "Load stepping/Control: stage 2 is path-controlled, but no load changes in it" --set "Loads/Pressure/Function expression=100*min(t,1)" --set "Load stepping/Stage end times=1, 2" --set "Load stepping/Control=load, arc-length"
# Eigen analysis: too many modes (exit 1), a failure of the analysis (exit
# 2 with the last state written, one line of message after the run's log,
# no non-finite number).
check "$k"                          1 "Eigen analysis/Number of modes: 8 modes asked of a problem with 9 free unknowns; at most 7 can be computed" --set "Eigen analysis/Type=tangent" --set "Eigen analysis/Number of modes=8"
check_mpi "$k"                      1 "Eigen analysis/Number of modes: 8 modes asked of a problem with 9 free unknowns; at most 7 can be computed" --set "Eigen analysis/Type=tangent" --set "Eigen analysis/Number of modes=8"
check "$k"                          1 "Eigen analysis/Shift: a modal analysis' shift is a frequency [Hz] and must not be negative" --set "Eigen analysis/Type=modal" --set "Eigen analysis/Shift=-1"
check "$k"                          1 "Eigen analysis/Type: The string <eigen> does not match" --set "Eigen analysis/Type=eigen"
eigen_fails() { # directory, message, settings...
  local out code
  out=$("$pneuma" "$k" --set "Output/Directory=$1" "${@:3}" 2>&1)
  code=$?
  if [ "$code" -ne 2 ] || [ "$(grep -c "pneuma: " <<<"$out")" -lt 1 ] ||
     ! grep -qF -- "$2" <<<"$(tail -n 2 <<<"$out")" || [ -n "$(non_finite)" ] ||
     [ ! -s "$1/summary.json" ]; then
    echo "FAIL eigen analysis ($1): exit $code, message: $(tail -n 3 <<<"$out")"
    fail=1
  else
    echo "ok   eigen analysis ($1): exit $code: $(tail -n 1 <<<"$out" | head -c 200)"
  fi
}
eigen_fails eigen-massless "the eigen analysis failed: the model has no mass" --set "Eigen analysis/Type=modal"
eigen_fails eigen-unconverged "the eigen analysis failed: ARPACK did not find" --set "Eigen analysis/Type=modal" --set "Cables/Cable 1/Density=7850" --set "Cables/Cable 1/Number of elements=40" --set "Eigen analysis/Maximum iterations=1" --set "Eigen analysis/Tolerance=1e-15" --set "Eigen analysis/Number of modes=10"
# Stability entries.
check "$dir/valid.prm"              1 "Stability/Locate critical points: The string <2> does not match" --set "Stability/Locate critical points=2"
check "$dir/valid.prm"              1 "Stability/Check inertia: The string <maybe> does not match" --set "Stability/Check inertia=maybe"
check "$dir/valid.prm"              1 "Stability/Branch switching: needs the located bifurcation: Stability/Check inertia = true and Stability/Locate critical points > 0" --set "Stability/Branch switching=true" --set "Stability/Locate critical points=0"
# Checkpoints: missing, damaged, of another scene, not allowed.
check --restart                     1 "--restart needs a checkpoint directory" "$dir/valid.prm"
check "$dir/valid.prm"              1 "--restart /nonexistent: cannot open '/nonexistent/state.bin' (is it a checkpoint directory?)" --restart /nonexistent
check "$dir/valid.prm"              1 "Checkpoint/Interval minutes: The string <-1>" --set "Checkpoint/Interval minutes=-1"
check "$dir/valid.prm"              1 "Checkpoint: adaptive refinement studies (Adaptive refinement/Cycles > 0) cannot be checkpointed" --set "Checkpoint/Interval steps=1" --set "Adaptive refinement/Cycles=1"
check "$dir/valid.prm"              0 "stopped after step 1 as asked" --set "Output/Directory=cp" --set "Checkpoint/Stop after step=1"
check "$dir/valid.prm"              0 "finished, 3 steps" --set "Output/Directory=cp-continued" --restart cp/checkpoint
check "$dir/valid.prm"              1 "--restart cp/checkpoint: adaptive refinement studies (Adaptive refinement/Cycles > 0) cannot be restarted" --set "Adaptive refinement/Cycles=1" --restart cp/checkpoint
check "$dir/valid.prm"              1 "Geometry/Type: is 'square' here but was 'disc' in the checkpoint's run; a restart continues the checkpoint's discrete problem" --set "Geometry/Type=square" --restart cp/checkpoint
check "$dir/valid.prm"              1 "Discretisation/Polynomial degree: is '2' here but was '1' in the checkpoint's run" --set "Discretisation/Polynomial degree=2" --restart cp/checkpoint
check "$k"                          1 "Cables/Number of cables: is '1' here but was '0' in the checkpoint's run" --set "Geometry/Type=disc" --set "Geometry/disc/Radius=0.1" --set "Boundary conditions/Fixed boundaries=0: xyz" --restart cp/checkpoint
mkdir -p broken && cp -r cp/checkpoint broken/ && head -c 40 cp/checkpoint/state.bin > broken/checkpoint/state.bin
check "$dir/valid.prm"              1 "--restart broken/checkpoint: 'broken/checkpoint/state.bin' is truncated" --restart broken/checkpoint
mkdir -p nomesh && cp -r cp/checkpoint nomesh/ && rm nomesh/checkpoint/membrane.mesh_fixed.data
check "$dir/valid.prm"              1 "--restart nomesh/checkpoint: 'nomesh/checkpoint/membrane.mesh_fixed.data' is missing (the manifest lists it)" --restart nomesh/checkpoint
echo "not a checkpoint" > broken/checkpoint/state.bin
check "$dir/valid.prm"              1 "--restart broken/checkpoint: 'broken/checkpoint/state.bin' is not a pneuma checkpoint" --restart broken/checkpoint
check_mpi "$dir/valid.prm"          1 "--restart /nonexistent: cannot open" --restart /nonexistent
check_mpi "$dir/valid.prm"          0 "finished, 3 steps" --set "Output/Directory=cp-continued-2" --restart cp/checkpoint
# Damaged checkpoints (tests/damage_checkpoint.py): every file is checked
# against the manifest's size and CRC32, every length in state.bin against
# the file, before anything is restored: exit 1 naming the file, on 1 and
# 2 ranks.
for damage in payload size flip mesh truncated manifest format-1 forged-size forged-payload; do
  /usr/bin/python3 "$dir/../damage_checkpoint.py" cp/checkpoint "damaged-$damage/checkpoint" "$damage"
done
check "$dir/valid.prm"              1 "--restart damaged-payload/checkpoint: 'damaged-payload/checkpoint/state.bin' is damaged: its CRC32 is" --restart damaged-payload/checkpoint
check_mpi "$dir/valid.prm"          1 "--restart damaged-payload/checkpoint: 'damaged-payload/checkpoint/state.bin' is damaged: its CRC32 is" --restart damaged-payload/checkpoint
check "$dir/valid.prm"              1 "--restart damaged-size/checkpoint: 'damaged-size/checkpoint/state.bin' is damaged: its CRC32 is" --restart damaged-size/checkpoint
check_mpi "$dir/valid.prm"          1 "--restart damaged-size/checkpoint: 'damaged-size/checkpoint/state.bin' is damaged: its CRC32 is" --restart damaged-size/checkpoint
check "$dir/valid.prm"              1 "--restart damaged-flip/checkpoint: 'damaged-flip/checkpoint/state.bin' is damaged: its CRC32 is" --restart damaged-flip/checkpoint
check_mpi "$dir/valid.prm"          1 "--restart damaged-flip/checkpoint: 'damaged-flip/checkpoint/state.bin' is damaged: its CRC32 is" --restart damaged-flip/checkpoint
check "$dir/valid.prm"              1 "--restart damaged-mesh/checkpoint: 'damaged-mesh/checkpoint/membrane.mesh' is damaged: its CRC32 is" --restart damaged-mesh/checkpoint
check_mpi "$dir/valid.prm"          1 "--restart damaged-mesh/checkpoint: 'damaged-mesh/checkpoint/membrane.mesh' is damaged: its CRC32 is" --restart damaged-mesh/checkpoint
check "$dir/valid.prm"              1 "--restart damaged-truncated/checkpoint: 'damaged-truncated/checkpoint/membrane.mesh_fixed.data' is truncated" --restart damaged-truncated/checkpoint
check_mpi "$dir/valid.prm"          1 "--restart damaged-truncated/checkpoint: 'damaged-truncated/checkpoint/membrane.mesh_fixed.data' is truncated" --restart damaged-truncated/checkpoint
check "$dir/valid.prm"              1 "--restart damaged-manifest/checkpoint: 'damaged-manifest/checkpoint/manifest' is missing: the checkpoint is incomplete or was written by an older pneuma" --restart damaged-manifest/checkpoint
check_mpi "$dir/valid.prm"          1 "--restart damaged-manifest/checkpoint: 'damaged-manifest/checkpoint/manifest' is missing" --restart damaged-manifest/checkpoint
check "$dir/valid.prm"              1 "--restart damaged-format-1/checkpoint: 'damaged-format-1/checkpoint/state.bin' is of checkpoint format 1 (an older pneuma), which has no checksums to verify it" --restart damaged-format-1/checkpoint
check_mpi "$dir/valid.prm"          1 "--restart damaged-format-1/checkpoint: 'damaged-format-1/checkpoint/state.bin' is of checkpoint format 1" --restart damaged-format-1/checkpoint
check "$dir/valid.prm"              1 "--restart damaged-forged-size/checkpoint: 'damaged-forged-size/checkpoint/state.bin' is damaged (section '" --restart damaged-forged-size/checkpoint
check_mpi "$dir/valid.prm"          1 "--restart damaged-forged-size/checkpoint: 'damaged-forged-size/checkpoint/state.bin' is damaged (section '" --restart damaged-forged-size/checkpoint
check "$dir/valid.prm"              1 "of 'damaged-forged-payload/checkpoint/state.bin' cannot be read" --restart damaged-forged-payload/checkpoint
check_mpi "$dir/valid.prm"          1 "of 'damaged-forged-payload/checkpoint/state.bin' cannot be read" --restart damaged-forged-payload/checkpoint
# A restart continues the checkpoint's discrete problem: a change of what
# defines it is refused naming the entry (core/restart_check.h); load
# curves, stepping, solver, output and checkpoint entries may change.
check "$dir/valid.prm"              1 "Geometry/Global refinements: is '2' here but was '1' in the checkpoint's run; a restart continues the checkpoint's discrete problem" --set "Geometry/Global refinements=2" --restart cp/checkpoint
check_mpi "$dir/valid.prm"          1 "Geometry/Global refinements: is '2' here but was '1' in the checkpoint's run" --set "Geometry/Global refinements=2" --restart cp/checkpoint
check "$dir/valid.prm"              1 "Materials/Region 0/Wrinkling smoothing: is '1e-4' here but was" --set "Materials/Region 0/Wrinkling smoothing=1e-4" --restart cp/checkpoint
check "$dir/valid.prm"              1 "Output/Monitor points: is '0,0,0' here but was '' in the checkpoint's run" --set "Output/Monitor points=0,0,0" --restart cp/checkpoint
check "$dir/valid.prm"              0 "finished, " --set "Output/Directory=cp-changed" --set "Loads/Pressure/Function expression=50*t" --set "Load stepping/Minimum increment=1e-4" --set "Newton/Residual tolerance=1e-9" --set "Output/Write VTU=true" --set "Checkpoint/Interval steps=1" --restart cp/checkpoint
NP=3 check_mpi "$dir/valid.prm"     1 "--restart nomesh/checkpoint: 'nomesh/checkpoint/membrane.mesh_fixed.data' is missing" --restart nomesh/checkpoint
NP=3 check_mpi "$c"                 1 "walls face into the chamber" --set "Chambers/Chamber 1/Regions=-0, -1, -2"
NP=3 check_mpi "$dir/valid.prm"     1 "Output/Directory: cannot write into" --set "Output/Directory=not_a_directory"
# A rerun into the same directory leaves no file of the earlier run.
"$pneuma" "$dir/valid.prm" --set "Output/Directory=rerun" --set "Output/Write VTU=true" \
  --set "Loads/Pressure/Function expression=100*t" --set "Load stepping/Initial increment=0.05" \
  --set "Load stepping/Maximum increment=0.05" > /dev/null 2>&1
touch rerun/my_notes.txt
"$pneuma" "$dir/valid.prm" --set "Output/Directory=rerun" --set "Output/Write VTU=true" \
  --set "Loads/Pressure/Function expression=100*t" > /dev/null 2>&1
if [ -e rerun/solution_0010.pvtu ] || [ ! -e rerun/my_notes.txt ] ||
   [ "$(grep -c DataSet rerun/solution.pvd)" -ne 5 ]; then
  echo "FAIL rerun: files of the earlier run left behind, or other files removed: $(ls rerun | tr '\n' ' ')"
  fail=1
else
  echo "ok   rerun: only the files of the new run (and the user's own) are left"
fi
# Every VTU any case wrote reads back finite.
for d in $(find . -name '*.pvtu' -printf '%h\n' | sort -u); do
  /usr/bin/python3 "$dir/../check_outputs_finite.py" "$d" > /dev/null || { echo "FAIL non-finite output in $d"; fail=1; }
done
n_cases=$(grep -cE '^(NP=3 )?check(_mpi)? ' "$self")
echo "$n_cases cases"
if [ $fail -eq 0 ]; then echo "all bad inputs rejected cleanly"; fi
exit $fail
