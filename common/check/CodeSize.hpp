#pragma once

// Attributes that win back flash on the brick (64 KiB budget, `make size`) without changing what the code does.
// NXTMAP_OUT_OF_LINE: a small helper the optimiser copies into many call sites (-Os -flto) is kept as one
// function; each use costs a call (a few instructions) instead. PoseTracker's divRound was inlined 18 times:
// 732 bytes of nxtmap.elf (measured 2026-12-05).
// NXTMAP_RUN_ONCE: a constructor or start-up routine the brick runs once (or once a run). Without it the link-time
// optimiser specialises it for its one object (this = &g_app) and loads every member's address from a literal
// pool; with it `this` stays in a register: about 700 bytes over the eight of them. Never on a hot path.
// Other compilers (none builds the brick) get plain functions.
#if defined(__GNUC__) && !defined(__clang__)
#define NXTMAP_OUT_OF_LINE __attribute__((noinline))
#define NXTMAP_RUN_ONCE __attribute__((noipa))
#else
#define NXTMAP_OUT_OF_LINE
#define NXTMAP_RUN_ONCE
#endif
