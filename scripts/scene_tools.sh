# Shared by the scene scripts (scripts/airbeam_figure7.sh,
# scripts/waterbeam_filling.sh, scripts/waterbeam_bending.sh,
# scripts/waterbeam_cables.sh, scripts/tensairity_beam.sh): source it after
# setting root (the project) and out (the scene's output directory).

# The water variant of parameter_files/waterbeam_bending.prm: chamber 2
# (chamber 3 of the file) filled with 5 litres of water in stage 2, its gas
# sealed at the end of the filling (as in Figure 10).
waterbeam_water=(
  --set "Chambers/Chamber 3/Filling=liquid and gas"
  --set "Chambers/Chamber 3/Gas/Seal time=2"
  --set "Chambers/Chamber 3/Liquid/Volume/Function expression=0.005*min(max(t-1,0),1)")

# scene_run NAME FILE [ARGUMENTS...]: runs pneuma on FILE into $out/NAME,
# logs to $out/NAME.log and prints its last line. Exit 2 is a curve that
# ends where the structure gives way (its last converged state is
# written); any other failure stops the script.
scene_run() {
  local name=$1 file=$2 code=0
  shift 2
  echo "$name: running"
  "$root/build/pneuma" "$file" --set "Output/Directory=$out/$name" "$@" \
    > "$out/$name.log" 2>&1 || code=$?
  tail -n 1 "$out/$name.log"
  if [ "$code" -ne 0 ] && [ "$code" -ne 2 ]; then
    echo "$name failed (exit $code), see $out/$name.log" >&2
    exit "$code"
  fi
}

# scene_pictures NAME...: renders the last state of each run $out/NAME to
# $out/NAME.png with scripts/render_state.py where ParaView's pvbatch is
# installed (under xvfb-run without a display).
scene_pictures() {
  if ! command -v pvbatch > /dev/null; then
    echo "pvbatch not found: scripts/install_dependencies.sh --pictures installs ParaView for pictures of the deformed beams"
    return
  fi
  local render=(pvbatch) name
  [ -z "${DISPLAY:-}" ] && command -v xvfb-run > /dev/null &&
    render=(xvfb-run -a -s "-screen 0 1920x1080x24" pvbatch)
  for name in "$@"; do
    if "${render[@]}" "$root/scripts/render_state.py" "$out/$name" "$out/$name.png" \
         --title "$name, last converged state" > "$out/$name.render.log" 2>&1; then
      grep written "$out/$name.render.log"
    else
      echo "$name: no picture: $(grep -v '^$' "$out/$name.render.log" | tail -n 1)"
      grep -q "No module named 'paraview'" "$out/$name.render.log" &&
        echo "  (pvbatch needs python3-paraview: scripts/install_dependencies.sh --pictures)"
    fi
  done
}
