// LEGO's own firmware 1.29 (Debian's nxt-firmware package: a raw 262144-byte flash image), unmodified, in the
// emulated brick: it loads as a .bin, formats its file system through the flash controller, shows its main
// menu as the real brick does (the picture in tests/emu/lego/), keeps the AVR link, follows the buttons.
// The long run is named EndToEnd: it runs in the Release build (too slow under ASan: LEGO never idles).
#include "EmuTestSupport.hpp"
#include "../support/TempDir.hpp"

#include <fstream>
#include <sstream>

namespace nxtmap::emu::test {
namespace {

const std::string kLegoImage = "/usr/share/nxt-firmware/nxt_firmware.bin";
const std::string kMenuPicture = std::string(NXTMAP_SOURCE_DIR) + "/tests/emu/lego/main-menu-1.29.pbm";
constexpr uint16_t kRight = 0x17F, kEnter = 0x7FF, kExit = 0x3FF;  // raw button ladder values

bool legoPresent() { return std::ifstream(kLegoImage).good(); }

// The LCD as plain PBM rows ('1' dark).
std::string lcdRows(const Lcd& lcd) {
  std::string s;
  for (int y = 0; y < Lcd::kHeight; ++y) {
    for (int x = 0; x < Lcd::kWidth; ++x) s += lcd.pixel(x, y) ? '1' : '0';
    s += '\n';
  }
  return s;
}

// A plain PBM's rows, comment lines skipped; empty if it is not P1 of the LCD's size.
std::string readPbmRows(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  const std::string size = std::to_string(Lcd::kWidth) + " " + std::to_string(Lcd::kHeight);
  if (lines.size() < 2 || lines[0] != "P1" || lines[1] != size) return "";
  std::string rows;
  for (size_t i = 2; i < lines.size(); ++i) rows += lines[i] + "\n";
  return rows;
}

TEST(LegoFirmware, RawImageLoadsAtTheFlashBase) {
  if (!legoPresent()) GTEST_SKIP() << kLegoImage << " is absent (Debian package nxt-firmware, make deps)";
  const ElfLoad l = ElfImage::load(kLegoImage);
  ASSERT_TRUE(l.image) << l.error;
  EXPECT_TRUE(l.image->rawFlash());
  EXPECT_EQ(l.image->flashUsed(), kFlashSize);
  EXPECT_EQ(l.image->entry(), kFlashBase);
  EXPECT_FALSE(l.image->symbol("g_explorerDone"));
  std::ifstream in(kLegoImage, std::ios::binary);
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(std::equal(bytes.begin(), bytes.end(), l.image->flash().begin()));
}

TEST(LegoFirmware, RawImageLargerThanTheFlashIsRefused) {
  nxtmap::test::TempDir dir("rawbin");
  const std::string big = dir.path("big.bin");
  std::ofstream(big, std::ios::binary) << std::string(kFlashSize + 1, '\xff');
  const ElfLoad l = ElfImage::load(big);
  EXPECT_FALSE(l.image);
  EXPECT_NE(l.error.find("raw flash image must hold 1..262144 bytes"), std::string::npos) << l.error;
}

struct LegoBrick {
  ElfImage image;
  sim::World world = smallRoom();
  std::unique_ptr<Brick> brick;
  explicit LegoBrick(ElfImage img) : image(std::move(img)) {
    BrickConfig c;
    c.startCol = 3;
    c.startRow = 3;
    brick = std::make_unique<Brick>(image, world, c);
  }
  bool runTo(double s) { return brick->runFor(s); }
  // Holds a button for 0.3 s from now, then lets go and waits 0.7 s.
  bool press(uint16_t raw) {
    brick->avr().setButtons(raw);
    const double t = brick->seconds();
    if (!runTo(t + 0.3)) return false;
    brick->avr().setButtons(0);
    return runTo(t + 1.0);
  }
};

// Why LEGO's firmware is not booted here (empty: it is).
std::string whyNotBooted() {
#if defined(__SANITIZE_ADDRESS__)
  return "LEGO's firmware never idles (0.4 x real time under ASan): make test runs this from the Release build";
#else
  return legoPresent() ? std::string()
                       : std::string(kLegoImage) + " is absent (Debian package nxt-firmware, make deps)";
#endif
}

TEST(LegoFirmwareEndToEnd, BootsToItsMainMenuKeepsTheAvrLinkAndFollowsTheButtons) {
  if (const std::string why = whyNotBooted(); !why.empty()) GTEST_SKIP() << why;
  ElfLoad l = ElfImage::load(kLegoImage);
  ASSERT_TRUE(l.image) << l.error;
  LegoBrick b(std::move(*l.image));
  ASSERT_TRUE(b.runTo(5.0)) << b.brick->machine().fault().describe();
  const std::string menu = lcdRows(b.brick->lcd());
  if (const char* out = std::getenv("NXTMAP_WRITE_LEGO_MENU")) {
    std::ofstream(out) << "P1\n# LEGO NXT firmware 1.29 (Debian nxt-firmware), main menu 5 s after reset, "
                          "as nxtmap's emulated brick shows it\n"
                       << Lcd::kWidth << " " << Lcd::kHeight << "\n"
                       << menu;
  }
  EXPECT_TRUE(b.brick->lcd().displayOn());
  EXPECT_EQ(menu, readPbmRows(kMenuPicture)) << "the main menu differs from " << kMenuPicture;
  EXPECT_GT(b.brick->machine().flash().pagesWritten(), 0u);  // its file system, formatted on first boot

  ASSERT_TRUE(b.press(kRight)) << b.brick->machine().fault().describe();
  const std::string right = lcdRows(b.brick->lcd());
  EXPECT_NE(right, menu) << "Right did not move the menu";
  ASSERT_TRUE(b.press(kEnter)) << b.brick->machine().fault().describe();
  const std::string entered = lcdRows(b.brick->lcd());
  EXPECT_NE(entered, right) << "Enter did not open the item";
  ASSERT_TRUE(b.press(kExit)) << b.brick->machine().fault().describe();
  EXPECT_NE(lcdRows(b.brick->lcd()), entered) << "Exit did not go back";

  ASSERT_TRUE(b.runTo(60.0)) << b.brick->machine().fault().describe();
  const AvrModel& avr = b.brick->avr();
  EXPECT_GT(avr.goodFrames(), 60u * 100u);  // a command frame every few ms
  EXPECT_EQ(avr.badFrames(), 0u);
}

// LEGO enables TXRDY's interrupt, reloads its buffer pointer and writes the first byte: the interrupt comes one
// instruction after the enable (the ARM7's latency), the handler sends byte 0 and steps the pointer, and the main
// line's THR write repeats byte 0 (the register it loaded) while the address goes out. Taken at the block's
// end the handler sent byte 0 twice; taken at once the main line sent byte 1 first.
TEST(LegoFirmwareEndToEnd, CompletesTheAvrHandshakeWithoutABadFrame) {
  if (const std::string why = whyNotBooted(); !why.empty()) GTEST_SKIP() << why;
  ElfLoad l = ElfImage::load(kLegoImage);
  ASSERT_TRUE(l.image) << l.error;
  LegoBrick b(std::move(*l.image));
  ASSERT_TRUE(b.runTo(3.0)) << b.brick->machine().fault().describe();  // the handshake starts at 2.35 s
  EXPECT_TRUE(b.brick->avr().handshakeDone());
  EXPECT_EQ(b.brick->avr().badFrames(), 0u);
}

}  // namespace
}  // namespace nxtmap::emu::test
