# Sourced by the LibreOffice tests: a private HOME and user profile under $tmp,
# so that several soffice processes run side by side (one profile each).
lo_home=$tmp/lo-home
mkdir -p "$lo_home"
export HOME=$lo_home
lo_profile="-env:UserInstallation=file://$lo_home/profile"
# soffice FILTER OUTDIR FILE [INFILTER]: converts FILE; fails when no file comes out.
lo_convert() {
  local to=$1 outdir=$2 file=$3; shift 3
  mkdir -p "$outdir"
  timeout 300 "$soffice" "$lo_profile" --headless --norestore --nolockcheck --convert-to "$to" "$@" \
    --outdir "$outdir" "$file" > "$outdir/soffice.log" 2>&1 || { cat "$outdir/soffice.log"; return 1; }
  local out="$outdir/$(basename "${file%.*}").${to%%:*}"
  [ -s "$out" ] || { echo "LibreOffice wrote no $out"; cat "$outdir/soffice.log"; return 1; }
}
