#!/usr/bin/env bash
# Issue 5's figures for the screens, under Xvfb: time from launch to a usable main screen
# (median of 5), resident memory after 60 s of a looping program with live plots, and CPU use
# while idle with the plots running (20 s). Usage: bench/gui_figures.sh [build/release]
set -euo pipefail
cd "$(dirname "$0")/.."
app="${1:-build/release}/app/gui/trilho"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export QT_QPA_PLATFORM=xcb
Xvfb :97 -screen 0 1280x800x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null; rm -rf "$tmp"' EXIT
export DISPLAY=:97
sleep 1  # the X server's own start-up, not part of any figure

echo "launch to main screen (ms):"
for i in 1 2 3 4 5; do
  TRILHO_REPORT_STARTUP=1 "$app" --settings "$tmp/s$i.ini" --no-start-screen --size 1280x800 --quit-after 0.5 2>&1 |
    sed -n 's/.*main screen shown \([0-9]*\) ms.*/\1/p'
done | sort -n | tee "$tmp/launch" | tr '\n' ' '
echo "  median: $(sed -n 3p "$tmp/launch") ms"

ticks=$(getconf CLK_TCK)
cpu() { awk '{print $14 + $15}' "/proc/$1/stat"; }

"$app" --settings "$tmp/idle.ini" --no-start-screen --size 1280x800 --quit-after 40 >/dev/null 2>&1 &
pid=$!
sleep 10
c0=$(cpu $pid); sleep 20; c1=$(cpu $pid)
echo "idle with live plots: $(awk -v a=$c0 -v b=$c1 -v t=$ticks 'BEGIN{printf "%.1f", (b-a)/t/20*100}') % of one core (20 s, manual mode, servo thread included)"
wait $pid || true

"$app" --settings "$tmp/run.ini" --no-start-screen --size 1280x800 --program resources/programs/ciclo_continuo.G \
  --run --quit-after 75 >/dev/null 2>&1 &
pid=$!
sleep 10
c0=$(cpu $pid); sleep 60; c1=$(cpu $pid)
rss=$(awk '/VmRSS/{print $2}' /proc/$pid/status)
hwm=$(awk '/VmHWM/{print $2}' /proc/$pid/status)
echo "after 60 s of a looping program with live plots: resident $((rss / 1024)) MB (peak $((hwm / 1024)) MB), CPU $(awk -v a=$c0 -v b=$c1 -v t=$ticks 'BEGIN{printf "%.1f", (b-a)/t/60*100}') % of one core"
wait $pid || true
