#!/usr/bin/env bash
# make demo: the whole product on one PC. The real firmware image runs in the emulated brick in a HouseExpo
# house (two rooms); the console connects to it over the (emulated) Bluetooth link and maps the whole house by itself
# (explore house: room by room through every exit, no button pressed), drives back across the rooms to the
# start (route near start), saves the house (houses format: a ROS map per room + house.yaml), exports a PNG
# and the merged ROS map, then sums up.
set -euo pipefail
BUILD=${BUILD:-build}
NXTMAP="$BUILD/host/host/cli/nxtmap"
FIRMWARE="$BUILD/firmware/nxtmap-sim.elf"   # the published experiments' geometry: 10 cm cells, 1 m range
WORLD=${WORLD:-worlds/houseexpo/1f99717550c31ae321ca2313edceedcc.json}
OUT=${OUT:-$BUILD/demo}
mkdir -p "$OUT"
for f in "$NXTMAP" "$FIRMWARE"; do
  [ -x "$f" ] || [ -f "$f" ] || { echo "demo: $f is missing (make host firmware)" >&2; exit 1; }
done

# A free TCP port on the loopback for the brick's radio.
PORT=""
for p in $(seq 5560 5599); do
  if ! (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null; then PORT=$p; break; fi
done
[ -n "$PORT" ] || { echo "demo: no free port in 5560-5599" >&2; exit 1; }

echo "== nxtmap demo: $WORLD (its default start), firmware $FIRMWARE"
echo "== 1. the emulated brick boots the firmware and listens on tcp:127.0.0.1:$PORT"
"$NXTMAP" emulate "$WORLD" --firmware "$FIRMWARE" --listen "tcp:127.0.0.1:$PORT" \
  --enter-at -1 --seconds 3600 --lcd "$OUT/lcd.png" > "$OUT/brick.log" 2>&1 &
BRICK=$!
trap 'kill $BRICK 2>/dev/null || true' EXIT
for _ in $(seq 1 100); do grep -q "^link:" "$OUT/brick.log" 2>/dev/null && break; sleep 0.1; done
grep "^link:" "$OUT/brick.log" || { cat "$OUT/brick.log" >&2; exit 1; }

echo "== 2. the console connects and maps the house room by room, then drives back to the start"
T0=$(date +%s)
"$NXTMAP" connect "tcp:127.0.0.1:$PORT" --no-live <<SCRIPT
explore house
wait house 600
rooms
route near start
wait goal 300
status
battery
save $OUT/house
export $OUT/room.png
quit
SCRIPT
RC=$?
if [ "$RC" -eq 0 ]; then
  echo "== the saved house, exported as one ROS map and a picture"
  "$NXTMAP" export "$OUT/house" --png "$OUT/house.png" --ros "$OUT/ros" || RC=$?
fi
wait $BRICK || true
trap - EXIT
T1=$(date +%s)

echo "== 3. the brick's own report"
sed -n '/^end/,$p' "$OUT/brick.log"
echo "== summary"
echo "console exit code $RC; wall time $((T1 - T0)) s"
echo "house: $OUT/house (house.yaml + a ROS map per room); merged ROS map $OUT/ros; pictures $OUT/room.png, $OUT/house.png; brick LCD $OUT/lcd.png"
exit $RC
