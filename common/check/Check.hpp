#pragma once
// The one check hook of the core. Its policy is set per build: on the host a failed check
// fails the test (via a handler the test harness installs); on the brick the firmware's handler
// stops the motors and shows the reason on the LCD. Checks guard invariants, never user input.
namespace nxtmap {

using CheckHandler = void (*)(const char* file, int line, const char* what);

// Installs the handler; returns the previous one. Default: spin forever (a hung brick is safe:
// the firmware watchdog and motor-silence guard stop the wheels).
CheckHandler setCheckHandler(CheckHandler handler);
[[noreturn]] void checkFailed(const char* file, int line, const char* what);

}  // namespace nxtmap

// On the brick a failed check names its file without folders and the condition's first kShownChars
// characters: all the 100-pixel screen shows of them (StatusScreen::showCheckFailed), so the image
// keeps no more of either. On the host: the whole path and condition.
namespace nxtmap::checktext {

inline constexpr int kShownChars = 25;  // 4-pixel characters across the screen

template <int N>
struct Brief {
  char text[N];
};

// The first kShownChars characters of `s` (N: its size with the terminating 0).
template <int N>
constexpr Brief<(N <= kShownChars ? N : kShownChars + 1)> brief(const char (&s)[N]) {
  Brief<(N <= kShownChars ? N : kShownChars + 1)> b{};
  for (int i = 0; i + 1 < static_cast<int>(sizeof b.text); ++i) b.text[i] = s[i];
  return b;
}

}  // namespace nxtmap::checktext

#if defined(__arm__)
#define NXTMAP_CHECK(cond)                                                                              \
  ((cond) ? static_cast<void>(0) : ::nxtmap::checkFailed(__FILE_NAME__, __LINE__, []() -> const char* { \
    static constexpr auto kBrief = ::nxtmap::checktext::brief(#cond);                                   \
    return kBrief.text;                                                                                 \
  }()))
#else
#define NXTMAP_CHECK(cond) ((cond) ? static_cast<void>(0) : ::nxtmap::checkFailed(__FILE__, __LINE__, #cond))
#endif
