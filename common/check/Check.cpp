#include "common/check/Check.hpp"

namespace nxtmap {
namespace {
CheckHandler g_handler = nullptr;  // owned by the build's start-up code; the only mutable global
}

CheckHandler setCheckHandler(CheckHandler handler) {
  CheckHandler previous = g_handler;
  g_handler = handler;
  return previous;
}

void checkFailed(const char* file, int line, const char* what) {
  if (g_handler != nullptr) g_handler(file, line, what);
  for (;;) {}
}

}  // namespace nxtmap
