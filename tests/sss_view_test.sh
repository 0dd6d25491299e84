#!/usr/bin/env bash
# sss_view under the Xvfb server that xvfb-run gives this script: scripted keys on the
# procedural torus, a screenshot, a light turn's preview and refined frames, and the refusals
# (no display, bad input). Usage:
# sss_view_test.sh SSS_VIEW OUTPUT_DIR
set -euo pipefail
view=$1 out=$2
mkdir -p "$out"
shot="$out/sss_view.png"
rm -f "$shot"

fail() { echo "FAIL: $*"; exit 1; }

"$view" --help | grep -q "k / K" || fail "--help does not list the keys"

# Light left and up, next and previous material, exposure up, automatic exposure.
"$view" --size 400x300 --keys "kimMxz" --frames 12 --screenshot "$shot" 2> "$out/sss_view.log" \
  || { cat "$out/sss_view.log"; fail "scripted session exited with an error"; }
[ -s "$shot" ] || fail "no screenshot written"
grep -q "fps" "$out/sss_view.log" || fail "no status line printed"
grep -q "marble" "$out/sss_view.log" || fail "status line does not name the material"

# Refinement: the first frame and the light turn show previews, then the refined frame follows
# (after frames that refine in parts); a PNG of each of the three.
rm -f "$out"/turn-*.png
"$view" --size 400x300 --keys "k" --frames 4 --screenshots "$out/turn" 2> "$out/turn.log" \
  || { cat "$out/turn.log"; fail "refining session exited with an error"; }
for n in 00 01 02; do [ -s "$out/turn-$n.png" ] || fail "no frame $n of the light turn"; done
[ ! -e "$out/turn-03.png" ] || fail "a frame written while refining"
[ "$(grep -c "| preview, " "$out/turn.log")" -ge 2 ] || { cat "$out/turn.log"; fail "no previews"; }
tail -n 1 "$out/turn.log" | grep -q "| refined, " \
  || { cat "$out/turn.log"; fail "the last frame is not the refined one"; }
"$view" --size 400x300 --keys "k" --frames 4 --refine off 2> "$out/plain.log" \
  || { cat "$out/plain.log"; fail "--refine off exited with an error"; }
if grep -q "preview\|refined" "$out/plain.log"; then fail "--refine off showed a preview"; fi

if DISPLAY= "$view" 2> "$out/no_display.log"; then fail "ran without a display"; fi
grep -q "DISPLAY is not set" "$out/no_display.log" || fail "no display: message missing"

for bad in "$out/absent.pcd" "$out/notes.txt"; do
  [ "$bad" = "$out/notes.txt" ] && echo "1 2 3" > "$bad"
  if "$view" "$bad" 2> "$out/bad.log"; then fail "accepted $bad"; fi
  [ "$(grep -c "sss_view:" "$out/bad.log")" = 1 ] || { cat "$out/bad.log"; fail "not one message for $bad"; }
done
echo "sss_view: scripted session, screenshot, refinement, refusals all as expected"
