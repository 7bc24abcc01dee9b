// UnicornFastPath: works around Unicorn 2.0.1's slow guest stores (every RAM store takes the notdirty
// path and heap-allocates a page collection that is never used: upstream issue #1970, fixed by PR #1838
// "Ignore page_collection_lock"). The executable interposes the two functions; when the fast path is on they
// do nothing (as upstream now does), otherwise they forward to the library. On by default only for 2.0.x.
// Off (NXTMAP_EMU_SLOW_STORES), RAM stores do not stay in the translated code either (DirectStores).
#pragma once

namespace nxtmap::emu {

// Whether stores take the fast path now; set before running (affects every machine in the process).
bool unicornFastStores();
void setUnicornFastStores(bool on);

}  // namespace nxtmap::emu
