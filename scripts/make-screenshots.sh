#!/bin/sh
# Regenerates the README screenshots in docs/images/ from the shipped samples:
#   gui-field.png    the tunnelmap window (xvfb-run, --screenshot --exit), field sample
#   gui-lab-side.png the window on the lab sample, side view
#   render-field.png tunnelmap-cli render (headless OSMesa), field frame nearest the manhole
#   gui-review.png   the window on a simulated three-section walk after Map tunnel, station 2 m:
#                    along view, cross-section and tunnel profile
#   gui-measure.png  the 3D view's measure tool (from tunnelmap_measure_tests)
#   render-map.png   tunnelmap-cli render --map --mesh on the same walk: station map over the fused mesh
# Usage: scripts/make-screenshots.sh [BUILD_DIR]   (default: build-gui; needs -DTUNNELMAP_BUILD_GUI=ON)
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$ROOT/build-gui}
case $BUILD in /*) ;; *) BUILD=$(pwd)/$BUILD ;; esac
OUT=$ROOT/docs/images
mkdir -p "$OUT"
# A private settings folder: the GUI restores window layout and parameters from QSettings.
CONFIG=$(mktemp -d)
WORK=$(mktemp -d)
trap 'rm -rf "$CONFIG" "$WORK"' EXIT

gui() {
  XDG_CONFIG_HOME=$CONFIG xvfb-run -a -s "-screen 0 1600x1000x24" \
    "$BUILD/app/gui/tunnelmap" "$@" --size 1280x800 --exit
}
gui "$ROOT/resources/sample/field" --params "$ROOT/resources/presets/field.json" --frame 2 \
  --view along --screenshot "$OUT/gui-field.png"
gui "$ROOT/resources/sample/lab" --params "$ROOT/resources/presets/lab.json" --frame 0 \
  --view side --screenshot "$OUT/gui-lab-side.png"
"$BUILD/app/tunnelmap-cli" render "$ROOT/resources/sample/field" \
  --params "$ROOT/resources/presets/field.json" --frame 2 --size 720x405 --view along \
  --screenshot "$OUT/render-field.png"
"$BUILD/app/tunnelmap-cli" simulate "$WORK/walk" --preset lab --frames 24 --seed 5 --quiet \
  --sections 1.5:0.84x1.30,1.5:0.80x1.28,2:0.82x1.32 --walk -1,3,10 --walk-pose 0,0.5,0
XDG_CONFIG_HOME=$CONFIG xvfb-run -a -s "-screen 0 1600x1000x24" "$BUILD/app/gui/tunnelmap" "$WORK/walk" \
  --params "$ROOT/resources/presets/lab.json" --map --station 2.0 --size 1400x880 \
  --screenshot "$OUT/gui-review.png" --exit
TUNNELMAP_GUI_SHOT_DIR=$WORK xvfb-run -a -s "-screen 0 1280x720x24" \
  "$BUILD/tests/ui/tunnelmap_measure_tests" > /dev/null
cp "$WORK/measure3d.png" "$OUT/gui-measure.png"
"$BUILD/app/tunnelmap-cli" fuse "$WORK/walk" --params "$ROOT/resources/presets/lab.json" \
  --mesh "$WORK/fused.ply" --quiet
"$BUILD/app/tunnelmap-cli" render "$WORK/walk" --params "$ROOT/resources/presets/lab.json" --map \
  --mesh "$WORK/fused.ply" --size 960x540 --screenshot "$OUT/render-map.png"
ls -l "$OUT"/*.png
