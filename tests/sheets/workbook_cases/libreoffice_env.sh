# Sourced by the LibreOffice tests: a private HOME and user profile under $tmp,
# so that several soffice processes run side by side (one profile each).
lo_home=$tmp/lo-home
mkdir -p "$lo_home"
export HOME=$lo_home
lo_profile="-env:UserInstallation=file://$lo_home/profile"
# lo_convert FILTER OUTDIR FILE...: converts every FILE in one soffice run (one
# start-up); fails when one of them does not come out. $lo_infilter, when
# set, is the import filter (e.g. CSV options).
lo_convert() {
  local to=$1 outdir=$2; shift 2
  local extra=()
  [ -n "${lo_infilter:-}" ] && extra=(--infilter="$lo_infilter")
  mkdir -p "$outdir"
  timeout 300 "$soffice" "$lo_profile" --headless --norestore --nolockcheck --convert-to "$to" "${extra[@]}" \
    --outdir "$outdir" "$@" > "$outdir/soffice.log" 2>&1 || { cat "$outdir/soffice.log"; return 1; }
  local file out
  for file in "$@"; do
    out="$outdir/$(basename "${file%.*}").${to%%:*}"
    [ -s "$out" ] || { echo "LibreOffice wrote no $out"; cat "$outdir/soffice.log"; return 1; }
  done
}
