#!/usr/bin/env bash
# `make size`: prints the brick image's budgets and fails when one is exceeded.
#   flash (text + read-only data + .data image) <= 64 KiB; nxtmap.bin exactly 262144 bytes, vectors first;
#   static RAM (vector copy + .data + .bss + all mode stacks) <= 24 KiB, with the 64 x 64-cell explorer;
#   RAM-run image (code + data + bss + stacks from 0x202000) <= 56 KiB;
#   no ARMv5+ instructions (the ARM7TDMI is ARMv4T); heap use is a link error (checked with a probe).
set -euo pipefail
DIR=${1:-build/firmware}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
FLASH_LIMIT=$((64 * 1024)); RAM_LIMIT=$((24 * 1024)); RAMRUN_LIMIT=$((56 * 1024))
fail=0
sym() { arm-none-eabi-nm "$1" | awk -v s="$2" '$3 == s { print $1 }'; }
hex() { printf '%d' "0x$1"; }
check() {  # name value limit
  local ok="ok"; [ "$2" -le "$3" ] || { ok="OVER"; fail=1; }
  printf '  %-44s %7d / %7d bytes  %s\n' "$1" "$2" "$3" "$ok"
}

ELF=$DIR/nxtmap.elf; RAMELF=$DIR/nxtmap-ram.elf; BIN=$DIR/nxtmap.bin
for f in "$ELF" "$RAMELF" "$BIN" "$DIR/nxtmap-ram.bin"; do [ -f "$f" ] || { echo "size: missing $f (run make firmware)"; exit 1; }; done

flash=$(( $(hex "$(sym "$ELF" __image_end)") - 0x100000 ))
ram=$(( $(hex "$(sym "$ELF" __static_ram)") ))
bss=$(( $(hex "$(sym "$ELF" _ebss)") - $(hex "$(sym "$ELF" __data_start)") ))
stacks=$(( $(hex "$(sym "$ELF" __stack_end__)") - $(hex "$(sym "$ELF" __stack_start__)") ))
ramrun=$(( $(hex "$(sym "$RAMELF" _ebss)") - 0x202000 + $(hex "$(sym "$RAMELF" __stack_end__)") - $(hex "$(sym "$RAMELF" __stack_start__)") ))
echo "nxtmap firmware (ARM7TDMI, $(arm-none-eabi-gcc -dumpversion)):"
check "flash: code + rodata + .data image" "$flash" "$FLASH_LIMIT"
check "static RAM (64x64 grid): data/bss ($bss) + stacks ($stacks)" "$ram" "$RAM_LIMIT"
check "RAM-run image at 0x202000 incl. bss + stacks" "$ramrun" "$RAMRUN_LIMIT"
SIMELF=$DIR/nxtmap-sim.elf
if [ -f "$SIMELF" ]; then
  check "static RAM of nxtmap-sim.elf (+ map export)" "$(( $(hex "$(sym "$SIMELF" __static_ram)") ))" "$RAM_LIMIT"
fi

binsize=$(stat -c %s "$BIN")
if [ "$binsize" -eq 262144 ]; then echo "  nxtmap.bin: 262144 bytes  ok"; else echo "  nxtmap.bin: $binsize bytes, must be 262144  FAIL"; fail=1; fi
# fwflash wants ARM vector instructions in the first words: ldr pc,[pc,#x] = 0xE59FF0xx.
first=$(od -An -tx4 -N24 "$BIN" | tr -s ' ' '\n' | grep -v '^$' | grep -cv '^e59ff0' || true)
if [ "$first" -eq 0 ]; then echo "  vectors: six ldr pc,[pc,#x] first  ok"; else echo "  vectors: unexpected first words  FAIL"; fail=1; fi

v5=$(arm-none-eabi-objdump -d "$ELF" "$RAMELF" $( [ -f "$SIMELF" ] && echo "$SIMELF") | grep -E $'\t(blx|clz|ldrd|strd|pld|bkpt|ldrex|strex|smulbb|smlabb|qadd|qsub|sxth|uxth|sxtb|uxtb|rev)\\b' || true)
if [ -z "$v5" ]; then echo "  ARMv4T only: no blx/clz/ldrd/strd/pld/... in any image  ok"
else echo "  ARMv5+ instructions found  FAIL"; echo "$v5" | head -5; fail=1; fi

# Heap: a probe that calls malloc must fail to link against the brick's linker script, and the same
# probe without malloc must link (so the failure is the heap rule, not something else).
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
FLAGS=(-mcpu=arm7tdmi -mthumb -mthumb-interwork -Os -ffreestanding -fno-exceptions -fno-rtti --specs=nano.specs
       -nostartfiles -L"$ROOT/firmware/board" -T nxt-flash.ld -Wl,--gc-sections -Wl,--no-warn-rwx-segments)
printf '#include <stdlib.h>\nint main(void){ void* p = malloc(16); return p != 0; }\nvoid _start(void){ main(); }\n' > "$tmp/heap.c"
printf 'int main(void){ return 0; }\nvoid _start(void){ main(); }\n' > "$tmp/noheap.c"
if arm-none-eabi-gcc "${FLAGS[@]}" "$tmp/noheap.c" -o "$tmp/noheap.elf" >"$tmp/noheap.log" 2>&1 &&
   ! arm-none-eabi-gcc "${FLAGS[@]}" "$tmp/heap.c" -o "$tmp/heap.elf" >"$tmp/heap.log" 2>&1 &&
   grep -q "heap use on the brick" "$tmp/heap.log"; then
  echo "  heap: malloc in the image is a link error  ok"
else
  echo "  heap: the malloc probe did not fail as it should  FAIL"; cat "$tmp/heap.log" "$tmp/noheap.log" | head -5; fail=1
fi
[ "$fail" -eq 0 ] && echo "size: all budgets met" || { echo "size: budget exceeded"; exit 1; }
