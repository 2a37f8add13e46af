#!/usr/bin/env bash
# The application under a real X server (Xvfb, 1280×800): it starts, the demo's
# story plays through the window (run, fit, compare, diagnose, adopt, a live rehearsal; the
# application exits with 1 when the diagnosis does not name the effect the demo
# hid), and a screenshot of every page (and the Models page's predictions) is
# written. Usage: xvfb_demo.sh DRIFTLAB OUT_DIR
set -euo pipefail
app=$1 out=$2
# Qt wants the runtime folder private (0700), as a login session makes it.
rm -rf "$out" && mkdir -p "$out/home" && chmod 700 "$out/home"
# A fresh HOME: first start, no settings or demo store from a previous run.
HOME="$out/home" XDG_RUNTIME_DIR="$out/home" timeout 300 \
    xvfb-run -a -s "-screen 0 1280x800x24" "$app" --demo --autopilot --screenshots "$out/shots"
for page in setup run models models-predictions diagnosis compensation iso230-2 iso230-3 sensor-health live; do
    png="$out/shots/gui-$page.png"
    [[ -s $png ]] || { echo "missing $png"; exit 1; }
    # A page with data is tens of kB; an empty grey window is a few.
    size=$(stat -c %s "$png")
    (( size > 40000 )) || { echo "$png is only $size bytes: an empty page?"; exit 1; }
done
