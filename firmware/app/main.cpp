// The brick's entry point and interrupt handlers (ARM code, entered through AIC_IVR; each ends
// with a write to AIC_EOICR). Everything else lives in BrickApp.
#include "common/check/Check.hpp"
#include "firmware/app/BrickApp.hpp"
#include "firmware/app/Isr.hpp"

using nxtmap::fw::BrickApp;
namespace reg = nxtmap::fw::reg;

namespace {
BrickApp g_app;  // the one application object (board singleton), constructed by the start-up code

#define NXTMAP_ISR extern "C" __attribute__((interrupt("IRQ"), target("arm"), used))
inline void endOfInterrupt() { nxtmap::fw::Mmio::write(reg::kAicEoicr, 0u); }

void onCheckFailed(const char* file, int line, const char* what) { g_app.checkFailed(file, line, what); }
}  // namespace

NXTMAP_ISR void nxtmapIsrSystem() {
  g_app.onSystem();
  endOfInterrupt();
}
NXTMAP_ISR void nxtmapIsrPio() {
  g_app.onPio();
  endOfInterrupt();
}
NXTMAP_ISR void nxtmapIsrTwi() {
  g_app.onTwi();
  endOfInterrupt();
}
NXTMAP_ISR void nxtmapIsrUsart1() {
  g_app.onUsart1();
  endOfInterrupt();
}
NXTMAP_ISR void nxtmapIsrTc0() {
  g_app.onTc0();
  endOfInterrupt();
}
NXTMAP_ISR void nxtmapIsrSsc() {
  g_app.onSsc();
  endOfInterrupt();
}
NXTMAP_ISR void nxtmapIsrSpurious() { endOfInterrupt(); }

int main() {
  nxtmap::setCheckHandler(onCheckFailed);
  g_app.init();
  g_app.run();
}
