#!/bin/sh
# Regenerates the README screenshots in docs/images/ from the shipped samples:
#   gui-field.png    the tunnelmap window (xvfb-run, --screenshot --exit), field sample
#   gui-lab-side.png the window on the lab sample, side view
#   render-field.png tunnelmap-cli render (headless OSMesa), field frame nearest the manhole
# Usage: scripts/make-screenshots.sh [BUILD_DIR]   (default: build-gui; needs -DTUNNELMAP_BUILD_GUI=ON)
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$ROOT/build-gui}
case $BUILD in /*) ;; *) BUILD=$(pwd)/$BUILD ;; esac
OUT=$ROOT/docs/images
mkdir -p "$OUT"
# A private settings folder: the GUI restores window layout and parameters from QSettings.
CONFIG=$(mktemp -d)
trap 'rm -rf "$CONFIG"' EXIT

gui() {
  XDG_CONFIG_HOME=$CONFIG xvfb-run -a -s "-screen 0 1600x1000x24" \
    "$BUILD/app/gui/tunnelmap" "$@" --size 1280x800 --exit
}
gui "$ROOT/resources/sample/field" --params "$ROOT/resources/presets/field.json" --frame 2 \
  --view along --screenshot "$OUT/gui-field.png"
gui "$ROOT/resources/sample/lab" --params "$ROOT/resources/presets/lab.json" --frame 0 \
  --view side --screenshot "$OUT/gui-lab-side.png"
"$BUILD/app/tunnelmap-cli" render "$ROOT/resources/sample/field" \
  --params "$ROOT/resources/presets/field.json" --frame 2 --size 800x450 --view along \
  --screenshot "$OUT/render-field.png"
ls -l "$OUT"/*.png
