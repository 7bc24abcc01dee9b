#pragma once

// Attributes that win back flash on the brick (64 KiB budget, `make size`) without changing what the code does.
// NXTMAP_OUT_OF_LINE: a small helper the optimiser copies into many call sites (-Os -flto) is kept as one
// function; each use costs a call (a few instructions) instead. PoseTracker's divRound was inlined 18 times:
// 732 bytes of nxtmap.elf (measured 2026-12-05). Other compilers (none builds the brick) get a plain function.
#if defined(__GNUC__) && !defined(__clang__)
#define NXTMAP_OUT_OF_LINE __attribute__((noinline))
#else
#define NXTMAP_OUT_OF_LINE
#endif
