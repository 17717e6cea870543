#!/usr/bin/env bash
# Builds the Debian package, installs it with dpkg, runs the installed tunnelmap-cli on the
# installed sample, and removes the package again. Needs root (CI runs it; see test.sh).
set -euo pipefail
cd "$(dirname "$0")/../build"
rm -f tunnelmap_*.deb
cpack -G DEB >/dev/null
deb=$(ls tunnelmap_*_amd64.deb)
echo "package-test: built $deb ($(du -h "$deb" | cut -f1))"
dpkg-deb --field "$deb" Depends | tr ',' '\n' | sed 's/^ */  depends: /' | head -40
dpkg -i "$deb" >/dev/null
trap 'dpkg -r tunnelmap >/dev/null 2>&1 || true' EXIT
out=$(mktemp -d)
/usr/bin/tunnelmap-cli detect /usr/share/tunnelmap/sample/lab --params /usr/share/tunnelmap/presets/lab.json \
  --json "$out/r.json" --ply "$out/map.ply"
test -s "$out/r.json" && test -s "$out/map.ply"
grep -q '"detected": 3' "$out/r.json"
# The simulated-camera driver sits where the system's OpenNI2 finds it: the installed CLI lists
# it and detects the tunnel live, with no LD_LIBRARY_PATH.
/usr/bin/tunnelmap-cli devices | grep -q '^tunnelmap-sim://lab'
/usr/bin/tunnelmap-cli detect --device 'tunnelmap-sim://lab?frames=3' --frames 5 \
  --params /usr/share/tunnelmap/presets/lab.json | grep -q 'summary: 5/5 frames detected'
# The installed GUI finds the same device and processes it live (a screenshot once the first
# live frame is shown), again with no LD_LIBRARY_PATH.
if command -v xvfb-run >/dev/null; then
  gui=(env XDG_CONFIG_HOME="$out/config" xvfb-run -a -s "-screen 0 1280x800x24" /usr/bin/tunnelmap)
  "${gui[@]}" --list-devices 2>/dev/null | grep -q '^tunnelmap-sim://lab'
  "${gui[@]}" --device 'tunnelmap-sim://lab?frames=3' --screenshot "$out/live.png" --exit >/dev/null 2>&1
  test "$(stat -c %s "$out/live.png")" -gt 20000
fi
# `evaluate` finds its presets in the installed location, not in a source tree.
/usr/bin/tunnelmap-cli evaluate --protocol ci --methods pgc --frames 1 --check --out "$out/eval" > "$out/eval.txt"
grep -qx 'presets: /usr/share/tunnelmap/presets' "$out/eval.txt" && test -s "$out/eval/table1.md"
test -x /usr/bin/tunnelmap && test -f /usr/share/applications/tunnelmap.desktop
test -f /usr/share/icons/hicolor/scalable/apps/tunnelmap.svg && test -f /usr/share/mime/packages/tunnelmap.xml
if command -v man >/dev/null; then test -f /usr/share/man/man1/tunnelmap-cli.1.gz; fi
dpkg -r tunnelmap >/dev/null
trap - EXIT
test ! -e /usr/bin/tunnelmap-cli
rm -rf "$out"
echo "package-test: installed, detected the tunnel in the installed sample, removed: ok"
